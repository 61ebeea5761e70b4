"""Tests of the chapter-28 exercise checkers and of the Boehm project checker.  Right answers are
worked by hand from the problem constants (so a bug in goldman_lib.knot_insertion cannot make a
checker accept a wrong answer); the generic checks of every checker are in tests/exercises/test_exercises.py
and tests/exercises/test_solutions.py."""

import numpy as np
import pytest
from scipy.interpolate import BSpline

from goldman_lib.exercises import Result, ch28

# Quadratic, P = (0,0),(2,4),(4,4),(6,0), knots 0,0,0,1,2,2,2; labels P0=b(0,0), P1=b(0,1), P2=b(1,2), P3=b(2,2).
# Boehm, u = 0.5 in [t2, t3) = [0, 1): a1 = (0.5-0)/(1-0) = 1/2, a2 = (0.5-0)/(2-0) = 1/4
# Q1 = P0/2 + P1/2 = (1, 2); Q2 = 3/4 P1 + 1/4 P2 = (2.5, 4)
BOEHM = [[0, 0], [1, 2], [2.5, 4], [4, 4], [6, 0]]
# Oslo, new knots 0,0,0,.5,1,1.5,2,2,2: b(0,0), b(0,.5), b(.5,1), b(1,1.5), b(1.5,2), b(2,2)
# b(0,.5) = (P0+P1)/2 = (1,2); b(.5,1) = 3/4 P1 + 1/4 P2 = (2.5,4); b(1,1.5) = 1/4 P1 + 3/4 P2 = (3.5,4);
# b(1.5,2) = (P2+P3)/2 = (5,2)
OSLO = [[0, 0], [1, 2], [2.5, 4], [3.5, 4], [5, 2], [6, 0]]
# pieces: [b(0,0), b(0,1), b(1,1)] and [b(1,1), b(1,2), b(2,2)], b(1,1) = (P1+P2)/2 = (3,4)
PIECES = [[[0, 0], [2, 4], [3, 4]], [[3, 4], [4, 4], [6, 0]]]
# Chaikin on the open polygon (0,0),(2,6),(10,6),(10,0): 1/4 and 3/4 of each leg
CHAIKIN = [[0.5, 1.5], [1.5, 4.5], [4, 6], [8, 6], [10, 4.5], [10, 1.5]]
# Schaefer, P = (0,0),(3,6),(9,6),(12,0), knots 0,0,0,1,3,3,3 -> new knots 0,0,0,0.5,1,2,3,3,3:
# b(0,0); b(0,.5) = (P0+P1)/2 = (1.5,3); b(.5,1) = 5/6 P1 + 1/6 P2 = (4,6); b(1,2) = 1/3 P1 + 2/3 P2 = (7,6);
# b(2,3) = (P2+P3)/2 = (10.5,3); b(3,3) = (12,0)
SCHAEFER = [[0, 0], [1.5, 3], [4, 6], [7, 6], [10.5, 3], [12, 0]]
# 0.5/4^4 = 0.00195 >= 0.001, 0.5/4^5 = 0.00049 < 0.001
LEVELS = 5

CHECKERS = [
    (ch28.check_boehm_insert, BOEHM),
    (ch28.check_oslo, OSLO),
    (ch28.check_bezier_pieces, PIECES),
    (ch28.check_chaikin, CHAIKIN),
    (ch28.check_schaefer, SCHAEFER),
    (ch28.check_convergence_levels, LEVELS),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch28.QUAD_CTRL.tolist() == [[0, 0], [2, 4], [4, 4], [6, 0]]
    assert ch28.QUAD_KNOTS.tolist() == [0, 0, 0, 1, 2, 2, 2] and ch28.QUAD_DEGREE == 2 and ch28.BOEHM_U == 0.5
    assert ch28.OSLO_NEW_KNOTS.tolist() == [0, 0, 0, 0.5, 1, 1.5, 2, 2, 2]
    assert ch28.CHAIKIN_CTRL.tolist() == [[0, 0], [2, 6], [10, 6], [10, 0]]
    assert ch28.SCHAEFER_CTRL.tolist() == [[0, 0], [3, 6], [9, 6], [12, 0]]
    assert ch28.SCHAEFER_KNOTS.tolist() == [0, 0, 0, 1, 3, 3, 3]
    assert (ch28.CONV_DISTANCE, ch28.CONV_TOL) == (0.5, 0.001)


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_hand_answers_describe_the_same_curves():
    u = np.linspace(0, 2, 41)
    old = BSpline(ch28.QUAD_KNOTS, ch28.QUAD_CTRL, 2)(u)
    assert np.allclose(BSpline([0, 0, 0, 0.5, 1, 2, 2, 2], BOEHM, 2)(u), old)
    assert np.allclose(BSpline(ch28.OSLO_NEW_KNOTS, OSLO, 2)(u), old)
    u = np.linspace(0, 3, 61)
    assert np.allclose(BSpline([0, 0, 0, 0.5, 1, 2, 3, 3, 3], SCHAEFER, 2)(u),
                       BSpline(ch28.SCHAEFER_KNOTS, ch28.SCHAEFER_CTRL, 2)(u))


def test_boehm_messages():
    assert "weights are swapped" in ch28.check_boehm_insert([[0, 0], [1, 2], [3.5, 4], [4, 4], [6, 0]]).message
    assert "old polygon" in ch28.check_boehm_insert(ch28.QUAD_CTRL.tolist()).message
    # a_1 with t_(i+p+1): (0.5 - 0)/(2 - 0) = 1/4 -> Q1 = (0.5, 1)
    assert "wrong knot interval" in ch28.check_boehm_insert([[0, 0], [0.5, 1], [2.5, 4], [4, 4], [6, 0]]).message
    # the range k-p+1..k moved to 2..3: Q3 = P2 - 1/2 (P3 - P2) = (3, 6)
    assert "replaced the wrong points" in ch28.check_boehm_insert([[0, 0], [2, 4], [2.5, 4], [3, 6], [6, 0]]).message
    assert "same ratio" in ch28.check_boehm_insert([[0, 0], [1, 2], [3, 4], [4, 4], [6, 0]]).message
    assert "should be 5 points" in ch28.check_boehm_insert([[0, 0], [1, 2], [6, 0]]).message
    r = ch28.check_boehm_insert([[0, 0], [1, 2], [2.5, 3.5], [4, 4], [6, 0]])
    assert not r and "point 2" in r.message


def test_oslo_messages():
    assert "inserting 0.5 alone" in ch28.check_oslo(BOEHM).message
    # 1.5 alone: in [1, 2): a2 = (1.5-0)/(2-0) = 3/4, a3 = (1.5-1)/(2-1) = 1/2
    assert "inserting 1.5 alone" in ch28.check_oslo([[0, 0], [2, 4], [3.5, 4], [5, 2], [6, 0]]).message
    assert "midpoints of the old legs" in ch28.check_oslo([[0, 0], [1, 2], [3, 4], [5, 2], [6, 0]]).message
    r = ch28.check_oslo([[0, 0], [1, 2], [3, 4], [3, 4], [5, 2], [6, 0]])
    assert not r and "point 2" in r.message and "blossom" in r.message


def test_bezier_pieces_messages():
    r = ch28.check_bezier_pieces([[[0, 0], [2, 4], [4, 4]], [[2, 4], [4, 4], [6, 0]]])
    assert "meet at one point" in r.message
    r = ch28.check_bezier_pieces([[[0, 0], [2, 4], [4, 4]], [[4, 4], [4, 4], [6, 0]]])
    assert "share an end point, but it is not the curve point" in r.message
    assert "shape (2, 3, 2)" in ch28.check_bezier_pieces([[0, 0], [2, 4], [3, 4], [4, 4], [6, 0]]).message
    r = ch28.check_bezier_pieces([[[0, 0], [2, 3], [3, 4]], [[3, 4], [4, 4], [6, 0]]])
    assert not r and "point 1" in r.message


def test_chaikin_messages():
    midpoints = [[0, 0], [1, 3], [2, 6], [6, 6], [10, 6], [10, 3], [10, 0]]
    assert "one averaging round" in ch28.check_chaikin(midpoints).message
    closed = CHAIKIN + [[7.5, 0], [2.5, 0]]
    assert "closed" in ch28.check_chaikin(closed).message
    doubled = [[0, 0], [0, 0], [2, 6], [2, 6], [10, 6], [10, 6], [10, 0], [10, 0]]
    assert "doubled polygon only" in ch28.check_chaikin(doubled).message
    thirds = [[2 / 3, 2], [4 / 3, 4], [14 / 3, 6], [22 / 3, 6], [10, 4], [10, 2]]
    assert "in thirds" in ch28.check_chaikin(thirds).message
    r = ch28.check_chaikin([[0.5, 1.5], [1.5, 4.5], [4, 6], [8, 6], [10, 4.5], [10, 2]])
    assert not r and "point 5" in r.message


def test_schaefer_messages():
    # Lane-Riesenfeld (Chaikin) on the same polygon: 3/4, 1/4 along each leg
    lr = [[0.75, 1.5], [2.25, 4.5], [4.5, 6], [7.5, 6], [9.75, 4.5], [11.25, 1.5]]
    assert "Lane-Riesenfeld's answer" in ch28.check_schaefer(lr).message
    round1 = [[0, 0], [0, 0], [3, 6], [4, 6], [9, 6], [10.5, 3], [12, 0]]
    assert "after round 1" in ch28.check_schaefer(round1).message
    plain = [[0, 0], [1.5, 3], [3, 6], [6, 6], [9, 6], [10.5, 3], [12, 0]]
    assert "one round of plain averages" in ch28.check_schaefer(plain).message
    r = ch28.check_schaefer([[0, 0], [1.5, 3], [4.5, 6], [7, 6], [10.5, 3], [12, 0]])
    assert not r and "point 2" in r.message
    assert "should be 6 points" in ch28.check_schaefer([[0, 0], [12, 0]]).message


def test_convergence_levels_messages():
    assert "halved per level" in ch28.check_convergence_levels(9).message
    assert "factor 8" in ch28.check_convergence_levels(3).message
    assert "one level short" in ch28.check_convergence_levels(4).message
    assert "more than needed" in ch28.check_convergence_levels(7).message
    assert "too few levels" in ch28.check_convergence_levels(1).message
    assert "whole number" in ch28.check_convergence_levels("five").message


def test_slips_are_all_recognised_as_wrong():
    for name, slips in ch28.SLIPS.items():
        for slip in slips:
            r = getattr(ch28, name)(slip)
            assert r.answered and not r.correct, (name, slip, r)


# -- the programming project: Boehm's knot insertion ------------------------------------------------

def _boehm_by_hand(ctrl, knots, degree, u):
    """A correct learner solution, written out independently of the library."""
    P = np.asarray(ctrl, dtype=float)
    t = np.asarray(knots, dtype=float)
    p, n = degree, len(P) - 1
    k = min(int(np.searchsorted(t, u, side="right")) - 1, n)
    Q = np.empty((n + 2, P.shape[1]))
    Q[:k - p + 1] = P[:k - p + 1]
    Q[k + 1:] = P[k:]
    for i in range(k - p + 1, k + 1):
        a = (u - t[i]) / (t[i + p] - t[i])
        Q[i] = (1 - a) * P[i - 1] + a * P[i]
    return Q


def _boehm_off_by_one(ctrl, knots, degree, u):
    """Subtly wrong: the new points are Q_(k-p+2)..Q_(k+1) (the affected range shifted one place)."""
    P = np.asarray(ctrl, dtype=float)
    t = np.asarray(knots, dtype=float)
    p, n = degree, len(P) - 1
    k = min(int(np.searchsorted(t, u, side="right")) - 1, n)
    Q = np.empty((n + 2, P.shape[1]))
    Q[:k - p + 2] = P[:k - p + 2]
    Q[k + 2:] = P[k + 1:]
    for i in range(k - p + 2, min(k + 2, n + 1)):
        a = (u - t[i]) / (t[i + p] - t[i])
        Q[i] = (1 - a) * P[i - 1] + a * P[i]
    if k + 1 == n + 1:
        Q[n + 1] = P[n]
    return Q


def _boehm_wrong_knot(ctrl, knots, degree, u):
    """Subtly wrong: a_i = (u - t_i)/(t_(i+p+1) - t_i), one knot too far."""
    P = np.asarray(ctrl, dtype=float)
    t = np.asarray(knots, dtype=float)
    p, n = degree, len(P) - 1
    k = min(int(np.searchsorted(t, u, side="right")) - 1, n)
    Q = np.empty((n + 2, P.shape[1]))
    Q[:k - p + 1] = P[:k - p + 1]
    Q[k + 1:] = P[k:]
    for i in range(k - p + 1, k + 1):
        a = (u - t[i]) / (t[i + p + 1] - t[i])
        Q[i] = (1 - a) * P[i - 1] + a * P[i]
    return Q


def _boehm_crashes(ctrl, knots, degree, u):
    k = knots.index(u)  # numpy arrays have no .index
    return ctrl


def test_boehm_cases_cover_degrees_dimensions_and_kinds():
    cases = ch28.boehm_project_cases()
    assert {c.args[2] for c in cases} == {1, 2, 3, 4}
    assert {np.asarray(c.args[0]).shape[1] for c in cases} == {2, 3}
    assert {"u at an existing knot", "u in the first span", "u in the last span", "u inside a span",
            "unclamped non-uniform knots", "degenerate: u already of multiplicity p"} <= {c.kind for c in cases}
    for c in cases:                                   # each kind is what it says
        P, t, p, u = c.args
        n = len(P) - 1
        if c.kind == "u at an existing knot":
            assert u in t[p + 1:n + 1]
        if c.kind == "u in the first span":
            assert t[p] < u < t[p + 1]
        if c.kind == "u in the last span":
            assert t[n] < u < t[n + 1]
        if c.kind.startswith("unclamped"):
            assert t[0] < t[p] and t[n + 1] < t[-1]
    again = ch28.boehm_project_cases()                # a fixed seed: the same cases every time
    assert [c.label for c in again] == [c.label for c in cases]
    assert all(np.array_equal(a.args[0], b.args[0]) for a, b in zip(again, cases))


def test_boehm_project_accepts_a_correct_function():
    r = ch28.check_boehm_project(_boehm_by_hand)
    assert r.correct and "passes all 41 cases" in r.message and "u at an existing knot" in r.message


def test_boehm_project_names_the_case_of_an_off_by_one():
    r = ch28.check_boehm_project(_boehm_off_by_one)
    assert not r.correct and r.answered
    assert r.message.startswith("case 1 of 41 (inserting u = ")
    assert "your new control point 1 is" in r.message and "from where it should be" in r.message
    assert "Hint: with t_k <= u < t_(k+1)" in r.message


def test_boehm_project_names_the_case_of_a_wrong_knot_in_alpha():
    r = ch28.check_boehm_project(_boehm_wrong_knot)
    assert not r.correct and r.answered
    assert "case 1 of 41 (inserting u = 0.08 into the linear B-spline with 5 control points in 2D" in r.message
    assert "your new control point" in r.message


def test_boehm_project_reports_a_crash_with_the_learners_line():
    r = ch28.check_boehm_project(_boehm_crashes)
    assert not r.correct and r.answered
    assert "raised AttributeError" in r.message and "k = knots.index(u)" in r.message


def test_boehm_project_too_few_points_and_unanswered():
    r = ch28.check_boehm_project(lambda ctrl, knots, degree, u: ctrl)
    assert "as many as before" in r.message

    def starter(ctrl, knots, degree, u):
        ...

    assert not ch28.check_boehm_project(starter).answered
    assert not ch28.check_boehm_project(None).answered


# -- dealt instances (issue 17 §3): every dealt answer leaves the curve unchanged (scipy) -------------

SEEDS = range(1, 41)


def _dealt(name, seed):
    return ch28.DECK.exercises[name].instance(seed), ch28.DECK.exercises[name].answer


def _same_curve(ctrl, knots, new_ctrl, new_knots):
    a, b = knots[2], knots[-3]
    u = np.linspace(a, b, 23)
    return np.allclose(BSpline(knots, np.asarray(ctrl, float), 2)(u), BSpline(new_knots, new_ctrl, 2)(u), atol=1e-12)


def test_dealt_boehm_oslo_and_schaefer_keep_the_curve():
    for seed in SEEDS:
        p, answer = _dealt("check_boehm_insert", seed)
        assert _same_curve(p["ctrl"], p["knots"], answer(p), np.sort(list(p["knots"]) + [p["u"]]))
        p, answer = _dealt("check_oslo", seed)
        assert _same_curve(p["ctrl"], p["knots"], answer(p), np.sort(list(p["knots"]) + list(p["new"])))
        p, answer = _dealt("check_schaefer", seed)
        t = p["knots"]
        refined = np.sort(list(t) + [t[3] / 2, (t[3] + t[-1]) / 2])
        assert _same_curve(p["ctrl"], t, answer(p), refined)


def test_dealt_bezier_pieces_are_the_curve_on_each_span():
    for seed in SEEDS:
        p, answer = _dealt("check_bezier_pieces", seed)
        t, pieces = p["knots"], np.asarray(answer(p))
        curve = BSpline(t, np.asarray(p["ctrl"], float), 2)
        for (a, b), piece in zip(((0, t[3]), (t[3], t[-1])), pieces):
            s = np.linspace(0, 1, 9)[:, None]
            bern = (1 - s) ** 2 * piece[0] + 2 * s * (1 - s) * piece[1] + s ** 2 * piece[2]
            assert np.allclose(bern, curve(a + (b - a) * s[:, 0]), atol=1e-12)


def test_dealt_chaikin_cuts_each_leg_at_a_quarter():
    for seed in SEEDS:
        p, answer = _dealt("check_chaikin", seed)
        P = np.asarray(p["ctrl"], float)
        expected = [w * a + (1 - w) * b for a, b in zip(P[:-1], P[1:]) for w in (0.75, 0.25)]
        assert np.allclose(answer(p), expected)


def test_dealt_convergence_levels_are_the_smallest_power_of_four():
    for seed in SEEDS:
        p, answer = _dealt("check_convergence_levels", seed)
        L = answer(p)
        assert p["distance"] / 4 ** L < p["tol"] <= p["distance"] / 4 ** (L - 1)

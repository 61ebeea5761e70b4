"""Exercise checkers for chapter 28, knot insertion (Goldman §28.3-28.4), and the checker of its
programming project (Boehm's knot insertion).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers of the kinds each checker recognises.  The data differ from the
chapter's worked examples (its cubic with knots 1/4, 1/2, 3/4, the square, the quadratic with the
knot 0.4).  The crossing-count drill of variation diminishing lives in chapter 25.

>>> print(PROBLEMS["check_convergence_levels"])  # doctest: +ELLIPSIS
After some levels of subdivision ... (Goldman §28.4.3).
"""

from __future__ import annotations

import numpy as np

from goldman_lib import knot_insertion as ki
from goldman_lib.exercises import guard_checkers
from goldman_lib.exercises import (Result, check_points, correct, fmt, fmt_points, read_number,
                                   read_points, wrong)
from goldman_lib.exercises.projects import Case, check_project, compare_points

__all__ = ["PROBLEMS", "SLIPS", "QUAD_CTRL", "QUAD_KNOTS", "QUAD_DEGREE", "BOEHM_U", "OSLO_NEW_KNOTS",
           "CHAIKIN_CTRL", "SCHAEFER_CTRL", "SCHAEFER_KNOTS", "CONV_DISTANCE", "CONV_TOL",
           "check_boehm_insert", "check_oslo", "check_bezier_pieces", "check_chaikin", "check_schaefer",
           "check_convergence_levels", "boehm_project_cases", "check_boehm_project"]

#: Exercises 1-3: the quadratic B-spline with knots 0, 0, 0, 1, 2, 2, 2 (two polynomial pieces).
QUAD_CTRL = np.array([[0.0, 0.0], [2.0, 4.0], [4.0, 4.0], [6.0, 0.0]])
QUAD_KNOTS = np.array([0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])
QUAD_DEGREE = 2
#: Exercise 1: the knot inserted once by Boehm's algorithm.
BOEHM_U = 0.5
#: Exercise 2: the refined knot vector of the Oslo algorithm (0.5 and 1.5 inserted at once).
OSLO_NEW_KNOTS = np.array([0.0, 0.0, 0.0, 0.5, 1.0, 1.5, 2.0, 2.0, 2.0])
#: Exercise 4: the open polygon refined by one level of Lane-Riesenfeld of degree 2 (Chaikin).
CHAIKIN_CTRL = np.array([[0.0, 0.0], [2.0, 6.0], [10.0, 6.0], [10.0, 0.0]])
#: Exercise 5: a quadratic on non-uniform knots (intervals 1 and 2), one level of Schaefer's algorithm.
SCHAEFER_CTRL = np.array([[0.0, 0.0], [3.0, 6.0], [9.0, 6.0], [12.0, 0.0]])
SCHAEFER_KNOTS = np.array([0.0, 0.0, 0.0, 1.0, 3.0, 3.0, 3.0])
#: Exercise 6: the polygon-to-curve distance now, and the tolerance to reach.
CONV_DISTANCE, CONV_TOL = 0.5, 0.001


def _knots(t) -> str:
    return ", ".join(fmt(x) for x in np.asarray(t))


PROBLEMS = {
    "check_boehm_insert": (
        f"The quadratic B-spline with control points {fmt_points(QUAD_CTRL)} and knots {_knots(QUAD_KNOTS)}: insert the "
        f"knot u = {fmt(BOEHM_U)} once by Boehm's algorithm and give the five new control points (Goldman §28.3.1)."),
    "check_oslo": (
        f"For the same quadratic B-spline ({fmt_points(QUAD_CTRL)}; knots {_knots(QUAD_KNOTS)}), give the control points over the refined knot vector "
        f"{_knots(OSLO_NEW_KNOTS)} (the knots 0.5 and 1.5 inserted at once): each new control point is the blossom "
        f"at two consecutive new knots (Goldman §28.3.2)."),
    "check_bezier_pieces": (
        f"Convert the same quadratic B-spline ({fmt_points(QUAD_CTRL)}; knots {_knots(QUAD_KNOTS)}) to piecewise "
        f"Bezier form: give the two Bezier control polygons, [[piece 1: 3 points], [piece 2: 3 points]] "
        f"(Goldman §28.3.3)."),
    "check_chaikin": (
        f"Apply one level of the Lane-Riesenfeld algorithm of degree 2 (Chaikin's corner cutting: double every "
        f"point, then average neighbours twice) to the open polygon {fmt_points(CHAIKIN_CTRL)}: give the refined "
        f"polygon (Goldman §28.4.1)."),
    "check_schaefer": (
        f"The quadratic B-spline with control points {fmt_points(SCHAEFER_CTRL)} has the non-uniform knots "
        f"{_knots(SCHAEFER_KNOTS)}. Run one level of Schaefer's algorithm (double every point, then two rounds of "
        f"averaging neighbours with the weights that blossoming gives), which inserts the midpoints 0.5 and 2 of "
        f"the knot intervals: give the six new control points (Goldman §28.4.2)."),
    "check_convergence_levels": (
        f"After some levels of subdivision the control polygon of a smooth cubic B-spline is "
        f"{fmt(CONV_DISTANCE)} from the curve (max |Q_i - C(xi_i)|). How many more levels of subdivision make "
        f"this distance smaller than {fmt(CONV_TOL)}, if each level shrinks it as the rate of convergence "
        f"predicts? (Goldman §28.4.3)."),
}


def _near(a, b, tol: float = 1e-6) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= tol))


# -- Boehm's algorithm and its usual slips (the exercise and the project's tests use them) ----------

def _boehm_variant(ctrl, knots, degree, u, *, shift: int = 0, alpha_knot: int = 0, swap: bool = False):
    """Boehm's insertion of one knot as a learner might write it, right by default (Goldman §28.3.1).

    ``shift`` moves the affected index range ``k-p+1 .. k`` by that many places (an off-by-one),
    ``alpha_knot`` reads the right-hand knot of ``a_i`` as ``t_(i+p+alpha_knot)`` (``alpha_knot=1``:
    the wrong knot ``t_(i+p+1)``), ``swap`` swaps ``a_i`` and ``1 - a_i``.  The checkers use the
    variants to recognise slips; the library's :func:`goldman_lib.knot_insertion.boehm_insert` is
    the reference.

    >>> _boehm_variant([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5).tolist()
    [[0.0, 0.0], [0.5, 1.0], [1.5, 1.0], [2.0, 0.0]]
    """
    P = np.asarray(ctrl, dtype=float)
    t = np.asarray(knots, dtype=float)
    p = int(degree)
    n = len(P) - 1
    k = int(np.searchsorted(t, u, side="right")) - 1
    k = min(max(k, p), n) + shift
    Q = np.empty((n + 2, P.shape[1]))
    lo = max(k - p + 1, 1)
    hi = min(k, n)
    Q[:lo] = P[:lo]
    Q[hi + 1:] = P[hi:]
    with np.errstate(divide="ignore", invalid="ignore"):
        for i in range(lo, hi + 1):
            right = t[min(i + p + alpha_knot, len(t) - 1)]
            a = (u - t[i]) / (right - t[i]) if right != t[i] else 0.0
            if swap:
                a = 1 - a
            Q[i] = (1 - a) * P[i - 1] + a * P[i]
    return Q


def check_boehm_insert(answer) -> Result:
    """Check the five control points after inserting ``BOEHM_U`` into the quadratic (Goldman §28.3.1).

    >>> check_boehm_insert([[0, 0], [1, 2], [3.5, 4], [4, 4], [6, 0]])
    Not yet: the weights are swapped: Q_i = (1 - a_i) P_(i-1) + a_i P_i, so a_i, which grows with u, goes with P_i.
    """
    what = "the new control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P, t, p, u = QUAD_CTRL, QUAD_KNOTS, QUAD_DEGREE, BOEHM_U
    expected, _ = ki.boehm_insert(P, t, p, u)
    if _near(got, P):
        return wrong("that is the old polygon: inserting a knot adds one control point and replaces p - 1 old "
                     "points by p new ones on the legs (here one by two).")
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points (one more than the {len(P)} old ones); "
                     f"yours has shape {got.shape}.")
    if _near(got, expected):
        return correct(f"{what} match: P0 kept, two new points on the legs P0P1 and P1P2, P2 and P3 kept "
                       f"(shifted one place).")
    if _near(got, _boehm_variant(P, t, p, u, swap=True)):
        return wrong("the weights are swapped: Q_i = (1 - a_i) P_(i-1) + a_i P_i, so a_i, which grows with u, "
                     "goes with P_i.")
    if _near(got, _boehm_variant(P, t, p, u, alpha_knot=1)):
        return wrong("a_i divides by the wrong knot interval: a_i = (u - t_i)/(t_(i+p) - t_i), the interval of "
                     "p knots that the label of P_i spans, not t_(i+p+1) - t_i.")
    if _near(got, _boehm_variant(P, t, p, u, shift=1)):
        return wrong("you replaced the wrong points: with t_k <= u < t_(k+1) the new points are Q_(k-p+1)..Q_k, "
                     "and the span k here has t_k <= 0.5 < t_(k+1).")
    s = (u - t[2]) / (t[3] - t[2])
    if _near(got[2], (1 - s) * P[1] + s * P[2]) and not _near(got[2], expected[2]):
        return wrong("you cut every leg at the same ratio (u - t_k)/(t_(k+1) - t_k); in Boehm's algorithm each new "
                     "point has its own a_i = (u - t_i)/(t_(i+p) - t_i).")
    return check_points(got, expected, what=what,
                        hint="u = 0.5 lies in [t_2, t_3) = [0, 1); a_1 = (0.5 - t_1)/(t_3 - t_1), a_2 = (0.5 - t_2)/(t_4 - t_2)")


def check_oslo(answer) -> Result:
    """Check the six control points over ``OSLO_NEW_KNOTS`` (Goldman §28.3.2).
    """
    what = "the refined control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    expected = ki.oslo(QUAD_CTRL, QUAD_KNOTS, QUAD_DEGREE, OSLO_NEW_KNOTS)
    for u in (0.5, 1.5):
        one, _ = ki.boehm_insert(QUAD_CTRL, QUAD_KNOTS, QUAD_DEGREE, u)
        if _near(got, one):
            return wrong(f"these are the points after inserting {fmt(u)} alone; the Oslo algorithm inserts 0.5 and "
                         f"1.5 together, giving {len(expected)} points.")
    mids = np.vstack([QUAD_CTRL[:1], (QUAD_CTRL[:-1] + QUAD_CTRL[1:]) / 2, QUAD_CTRL[-1:]])
    if _near(got, mids):
        return wrong("those are the old end points and the midpoints of the old legs (uniform subdivision of degree "
                     "one); the new points are blossom values at two consecutive new knots, one new point per "
                     "inserted knot.")
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points (two knots inserted into {len(QUAD_CTRL)} points); "
                     f"yours has shape {got.shape}.")
    return check_points(got, expected, what=what,
                        hint="each new point is the blossom at two consecutive new knots; the blossom is symmetric "
                             "and affine in each argument, so b(x, 1) moves along the leg P_1 P_2 in proportion to x")


def check_bezier_pieces(answer) -> Result:
    """Check the two Bezier polygons of the quadratic (Goldman §28.3.3).

    >>> check_bezier_pieces([[[0, 0], [2, 4], [4, 4]], [[2, 4], [4, 4], [6, 0]]])
    Not yet: the pieces must meet at one point, the curve point C(1) = b(1, 1): insert the knot 1 once more, so that it has multiplicity p = 2, and both pieces share that new control point.
    """
    what = "the Bezier pieces"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    expected, _ = ki.to_piecewise_bezier(QUAD_CTRL, QUAD_KNOTS, QUAD_DEGREE)
    if got.shape != expected.shape:
        return wrong(f"{what} should be 2 quadratic Bezier polygons of 3 points each, shape (2, 3, 2); yours has "
                     f"shape {got.shape}.")
    junction = expected[0, -1]
    if not (_near(got[0, -1], junction) and _near(got[1, 0], junction)):
        if _near(got[0, -1], got[1, 0]):
            return wrong("the two pieces share an end point, but it is not the curve point C(1) = b(1, 1); b(x, 1) "
                         "runs from P_1 = b(0, 1) to P_2 = b(2, 1) as x goes from 0 to 2.")
        return wrong("the pieces must meet at one point, the curve point C(1) = b(1, 1): insert the knot 1 once "
                     "more, so that it has multiplicity p = 2, and both pieces share that new control point.")
    return check_points(got.reshape(-1, 2), expected.reshape(-1, 2), what=what,
                        hint="the Bezier points of the piece over [a, b] are b(a, a), b(a, b), b(b, b)")


def check_chaikin(answer) -> Result:
    """Check one Lane-Riesenfeld level of degree 2 on ``CHAIKIN_CTRL`` (Goldman §28.4.1).

    >>> check_chaikin([[0, 0], [1, 3], [2, 6], [6, 6], [10, 6], [10, 3], [10, 0]])
    Not yet: that is one averaging round (degree 1: the midpoints inserted); degree 2 averages twice.
    """
    what = "the points of the refined polygon"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P = CHAIKIN_CTRL
    expected = ki.lane_riesenfeld(P, 2, 1)
    if _near(got, expected):
        return correct(f"{what} match: 1/4 and 3/4 along each leg.")
    if _near(got, ki.lane_riesenfeld(P, 1, 1)):
        return wrong("that is one averaging round (degree 1: the midpoints inserted); degree 2 averages twice.")
    closed = ki.lane_riesenfeld(P, 2, 1, closed=True)
    if got.shape == closed.shape and all(np.any(np.linalg.norm(closed - g, axis=1) < 1e-6) for g in got):
        return wrong("that treats the polygon as closed (the leg from the last point back to the first is cut too); "
                     "the polygon is open, so the refined one has two points per leg of the old polygon.")
    if _near(got, np.repeat(P, 2, axis=0)):
        return wrong("that is the doubled polygon only; now average neighbours twice.")
    thirds = np.array([w * a + (1 - w) * b for a, b in zip(P[:-1], P[1:]) for w in (2 / 3, 1 / 3)])
    if _near(got, thirds):
        return wrong("you cut the legs in thirds; two rounds of averaging after doubling cut each leg a quarter "
                     "and three quarters of the way along.")
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points: doubling gives 8, and each of the 2 averaging "
                     f"rounds drops one; yours has shape {got.shape}.")
    return check_points(got, expected, what=what, hint="each leg P_i P_(i+1) gives the points a quarter and "
                                                        "three quarters of the way along it")


def check_schaefer(answer) -> Result:
    """Check one level of Schaefer's algorithm on the non-uniform quadratic (Goldman §28.4.2).
    """
    what = "the new control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P, t = SCHAEFER_CTRL, SCHAEFER_KNOTS
    steps = ki.schaefer_steps(P, t, 2)
    expected = steps["rounds"][-1]
    if _near(got, expected):
        return correct(f"the six new control points match: they are the blossoms at consecutive knots of "
                       f"{_knots(steps['knots'])}.")
    if _near(got, ki.lane_riesenfeld(P, 2, 1)):
        return wrong("that is Lane-Riesenfeld's answer (plain averages, Chaikin's quarter and three-quarter points): right for uniform "
                     "knots only. With knot intervals of different lengths the weights come from the blossom labels, and "
                     "the clamped ends keep P0 and P3.")
    if _near(got, steps["rounds"][1]):
        return wrong("that is the polygon after round 1; a quadratic needs two rounds of averaging after the "
                     "doubling.")
    lr_rounds = ki.lane_riesenfeld_steps(P, 2, 1)[0]
    if _near(got, lr_rounds[1]):
        return wrong("that is one round of plain averages (the midpoints of the legs); Schaefer's rounds use "
                     "blossom weights, and a quadratic needs two rounds.")
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points: doubling gives {2 * len(P)}, and each of the "
                     f"two rounds drops one; yours has shape {got.shape}.")
    return check_points(got, expected, what=what,
                        hint="after the last round, new point j is the blossom at two consecutive knots of the refined "
                             "knot vector (the old knots with the midpoints inserted); each round trades one old knot "
                             "of every label for a midpoint")


def check_convergence_levels(answer) -> Result:
    """Check the number of subdivision levels to bring the polygon within ``CONV_TOL`` (Goldman §28.4.3).

    >>> check_convergence_levels(9)
    Not yet: that would be right if the distance halved per level, like the knot spacing h; but a control point is O(h^2) from the curve, so each level divides the distance by about 4.
    """
    what = "the number of levels"
    value, err = read_number(answer, what, unit="whole number")
    if err is not None:
        return err

    def levels(factor):
        n, d = 0, CONV_DISTANCE
        while d >= CONV_TOL:
            d, n = d / factor, n + 1
        return n

    expected = levels(4)
    if value == expected:
        return correct(f"{fmt(CONV_DISTANCE)} / 4^{expected} is below {fmt(CONV_TOL)} and {fmt(CONV_DISTANCE)} / "
                       f"4^{expected - 1} is not: five more levels.")
    if value == levels(2):
        return wrong("that would be right if the distance halved per level, like the knot spacing h; but a control "
                     "point is O(h^2) from the curve, so each level divides the distance by about 4.")
    if value == levels(8):
        return wrong("that assumes the distance falls like h^3 (a factor 8 per level); the rate of §28.4.3 is O(h^2) "
                     "for every degree >= 2.")
    if value == expected - 1:
        return wrong(f"one level short: after {fmt(value)} levels the distance is {fmt(CONV_DISTANCE / 4 ** value, 3)}, "
                     f"still not below {fmt(CONV_TOL)}.")
    if value > expected:
        return wrong(f"more than needed: fewer levels already bring the distance below {fmt(CONV_TOL)}; find the "
                     f"smallest L with {fmt(CONV_DISTANCE)} / 4^L < {fmt(CONV_TOL)}.")
    return wrong(f"too few levels: each level divides the distance by about 4, so after L levels it is "
                 f"{fmt(CONV_DISTANCE)} / 4^L; find the smallest L that brings it below {fmt(CONV_TOL)}.")


#: Wrong answers of the kinds each checker recognises (tests/test_solutions.py feeds them in).
SLIPS = {
    "check_boehm_insert": [QUAD_CTRL.tolist(), [[0, 0], [1, 2], [3.5, 4], [4, 4], [6, 0]],
                           [[0, 0], [0.5, 1], [2.5, 4], [4, 4], [6, 0]], [[0, 0], [2, 4], [2.5, 4], [3, 6], [6, 0]],
                           [[0, 0], [1, 2], [3, 4], [4, 4], [6, 0]]],
    "check_oslo": [[[0, 0], [1, 2], [2.5, 4], [4, 4], [6, 0]], [[0, 0], [2, 4], [3.5, 4], [5, 2], [6, 0]],
                   [[0, 0], [1, 2], [3, 4], [5, 2], [6, 0]]],
    "check_bezier_pieces": [[[[0, 0], [2, 4], [4, 4]], [[2, 4], [4, 4], [6, 0]]],
                            [[[0, 0], [2, 4], [4, 4]], [[4, 4], [4, 4], [6, 0]]],
                            [[[0, 0], [2, 3], [3, 4]], [[3, 4], [4, 4], [6, 0]]]],
    "check_chaikin": [[[0, 0], [1, 3], [2, 6], [6, 6], [10, 6], [10, 3], [10, 0]],
                      [[0.5, 1.5], [1.5, 4.5], [4, 6], [8, 6], [10, 4.5], [10, 1.5], [7.5, 0], [2.5, 0]],
                      [[0, 0], [0, 0], [2, 6], [2, 6], [10, 6], [10, 6], [10, 0], [10, 0]],
                      [[2 / 3, 2], [4 / 3, 4], [14 / 3, 6], [22 / 3, 6], [10, 4], [10, 2]]],
    "check_schaefer": [[[0.75, 1.5], [2.25, 4.5], [4.5, 6], [7.5, 6], [9.75, 4.5], [11.25, 1.5]],
                       [[0, 0], [0, 0], [3, 6], [4, 6], [9, 6], [10.5, 3], [12, 0]],
                       [[0, 0], [1.5, 3], [3, 6], [6, 6], [9, 6], [10.5, 3], [12, 0]],
                       [[0, 0], [1.5, 3], [4.5, 6], [7, 6], [10.5, 3], [12, 0]]],
    "check_convergence_levels": [9, 3, 4, 7, 1],
}


# -- the programming project: Boehm's knot insertion ----------------------------------------------

_DEGREE_NAMES = {1: "linear B-spline", 2: "quadratic B-spline", 3: "cubic B-spline", 4: "quartic B-spline"}


def _interior(rng, m: int) -> np.ndarray:
    """m distinct interior knots in (0, 1), two decimals, sorted."""
    return np.sort(rng.choice(np.arange(5, 96), size=m, replace=False)) / 100.0


def boehm_project_cases(seed: int = 28) -> list[Case]:
    """The generated cases of the Boehm project: degrees 1..4, 2D and 3D, clamped and unclamped
    non-uniform knots; u inside a span, at an existing knot (raising its multiplicity), in the first
    and the last span of the domain, and at a knot that already has multiplicity p (degenerate)."""
    rng = np.random.default_rng(seed)
    cases = []
    for p in (1, 2, 3, 4):
        for d in (2, 3):
            m = int(rng.integers(2, 5))                       # interior knots
            inner = _interior(rng, m)
            clamped = np.concatenate([np.zeros(p + 1), inner, np.ones(p + 1)])
            n1 = len(clamped) - p - 1
            ctrl = np.round(rng.uniform(-5, 5, size=(n1, d)), 1)
            lo, hi = clamped[p], clamped[p + 1]
            choices = [
                ("u inside a span", float(np.round(rng.uniform(0.01, 0.99), 2)), clamped, ctrl),
                ("u at an existing knot", float(inner[int(rng.integers(0, m))]), clamped, ctrl),
                ("u in the first span", float(np.round((lo + hi) / 2, 3)), clamped, ctrl),
                ("u in the last span", float(np.round((clamped[n1 - 1] + clamped[n1]) / 2, 3)), clamped, ctrl),
            ]
            # unclamped, non-uniform knots: the domain is [t_p, t_(n+1)]
            free = np.sort(rng.choice(np.arange(0, 100), size=n1 + p + 1, replace=False)) / 10.0
            uf = float(np.round(rng.uniform(free[p] + 0.01, free[n1] - 0.01), 2))
            choices.append(("unclamped non-uniform knots", uf, free, ctrl))
            for kind, u, knots, P in choices:
                label = (f"inserting u = {fmt(u)} into the {_DEGREE_NAMES[p]} with {len(P)} control points in {d}D "
                         f"and knots [{_knots(knots)}]")
                cases.append(Case(label, (P.copy(), knots.copy(), p, u), kind=kind))
    # degenerate: u already of multiplicity p (the new point repeats an old one)
    p = 3
    knots = np.array([0, 0, 0, 0, 0.3, 0.6, 0.6, 0.6, 1, 1, 1, 1], dtype=float)
    P = np.round(np.random.default_rng(seed + 1).uniform(-5, 5, size=(len(knots) - p - 1, 2)), 1)
    cases.append(Case(f"inserting u = 0.6 into the cubic B-spline with {len(P)} control points in 2D and knots "
                      f"[{_knots(knots)}] (0.6 already has multiplicity 3)", (P, knots, p, 0.6),
                      kind="degenerate: u already of multiplicity p"))
    return cases


def _boehm_reference(ctrl, knots, degree, u):
    return ki.boehm_insert(ctrl, knots, degree, u)[0]


def _boehm_compare(got, expected, case):
    arr = np.asarray(got, dtype=float)
    if arr.shape == (expected.shape[0] - 1, expected.shape[1]):
        return (f"it has {arr.shape[0]} points, as many as before: inserting one knot adds one control point "
                f"(expected {expected.shape[0]})")
    problem = compare_points(tol=1e-8, what="your new control point")(got, expected, case)
    if problem is None or arr.shape != expected.shape:
        return problem
    slips = [
        (dict(swap=True), "the weights are swapped: Q_i = (1 - a_i) P_(i-1) + a_i P_i, so a_i = 1 keeps P_i"),
        (dict(alpha_knot=1), "a_i divides by the wrong knot gap: a_i = (u - t_i) / (t_(i+p) - t_i), with t_(i+p), "
                             "not t_(i+p+1)"),
        (dict(shift=1), "the new points sit one index too late: the span k has t_k <= u < t_(k+1), and the "
                        "new points are Q_(k-p+1) .. Q_k"),
        (dict(shift=-1), "the new points sit one index too early: the span k has t_k <= u < t_(k+1), and the "
                         "new points are Q_(k-p+1) .. Q_k"),
    ]
    for kwargs, why in slips:
        try:
            alt = _boehm_variant(*case.args, **kwargs)
        except (ValueError, IndexError):
            continue
        if alt.shape == arr.shape and np.all(np.isfinite(alt)) and np.allclose(arr, alt, atol=1e-8) \
                and not np.allclose(alt, expected, atol=1e-8):
            return problem + "; " + why
    return problem


def check_boehm_project(function) -> Result:
    """Check the learner's Boehm insertion ``function(ctrl, knots, degree, u) -> new ctrl`` on the
    generated cases of :func:`boehm_project_cases` against :func:`goldman_lib.knot_insertion.boehm_insert`
    (Goldman §28.3.1).

    >>> def swapped(ctrl, knots, degree, u):
    ...     return _boehm_variant(ctrl, knots, degree, u, swap=True)
    >>> print(check_boehm_project(swapped).message)   # doctest: +ELLIPSIS
    case ...: ...; the weights are swapped: ... Hint: ...
    """
    return check_project(function, boehm_project_cases(), reference=_boehm_reference, compare=_boehm_compare,
                         what="Boehm's knot insertion",
                         hint=("with t_k <= u < t_(k+1), keep P_0..P_(k-p) and P_k..P_n; for k-p+1 <= i <= k put "
                               "Q_i = (1 - a_i) P_(i-1) + a_i P_i with a_i = (u - t_i)/(t_(i+p) - t_i)"))


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

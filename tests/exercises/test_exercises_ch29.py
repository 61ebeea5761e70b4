"""Tests of the chapter-29 exercise checkers and of the programming-project checker.  Right answers
are worked by hand from the problem constants (so a bug in goldman_lib.subdivision_matrices cannot
make a checker accept a wrong answer)."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch29

# t = 1/3: rows (1, 0, 0); (2/3, 1/3, 0); ((2/3)^2, 2 (1/3)(2/3), (1/3)^2)
LEFT = [[1, 0, 0], [2 / 3, 1 / 3, 0], [4 / 9, 4 / 9, 1 / 9]]
# 8R = [[1,6,1,0],[0,4,4,0],[0,1,6,1],[0,0,4,4]] on (0,0),(2,6),(6,6),(8,2)
BSPLINE_RIGHT = [[18 / 8, 42 / 8], [4, 6], [46 / 8, 44 / 8], [7, 4]]
# C(t) -> C(t/2) -> C(1/2 + t/4): t = 2/3; C(2/3) = 4/9 (3, 6) + 4/9 (9, 0)
FIXED = [16 / 3, 8 / 3]
# B_k^4(1/3) = C(4, k) 2^(4-k) / 81, k = 1..4
NORMAL = [32 / 81, 24 / 81, 8 / 81, 1 / 81]
# v = -1/2, u = 3/4: 3/4 (0,0) - 1/2 (2,4) + 3/4 (4,0) = (3 - 1, -2)
JOINT = [2.0, -2.0]
# L P = (0,0), (1,2), (2,-2); 3/4 (0,0) - 1/2 (1,2) + 3/4 (2,-2) = (1, -2.5)
QUARTER = [1.0, -2.5]

CHECKERS = [
    (ch29.check_left_matrix_at_t, LEFT),
    (ch29.check_bspline_right_half, BSPLINE_RIGHT),
    (ch29.check_composed_fixed_point, FIXED),
    (ch29.check_normal_curve_point, NORMAL),
    (ch29.check_fractal_joint, JOINT),
    (ch29.check_fractal_quarter_joint, QUARTER),
]
IDS = [c.__name__ for c, _ in CHECKERS]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch29.SPLIT_T == 1 / 3
    assert ch29.BSPLINE_CTRL.tolist() == [[0, 0], [2, 6], [6, 6], [8, 2]]
    assert ch29.COMPOSED_CTRL.tolist() == [[0, 0], [3, 6], [9, 0]]
    assert (ch29.NORMAL_DEGREE, ch29.NORMAL_T) == (4, 1 / 3)
    assert ch29.FRACTAL_CTRL.tolist() == [[0, 0], [2, 4], [4, 0]] and ch29.FRACTAL_MIDDLE == -0.5


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=IDS)
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_hand_decimals_are_accepted():
    assert ch29.check_left_matrix_at_t([[1, 0, 0], [0.6667, 0.3333, 0], [0.4444, 0.4444, 0.1111]]).correct
    assert ch29.check_composed_fixed_point([5.3333, 2.6667]).correct
    assert ch29.check_normal_curve_point([0.3951, 0.2963, 0.09877, 0.01235]).correct
    assert not ch29.check_normal_curve_point([0.395, 0.296, 0.099, 0.012]).correct


def test_left_matrix_messages():
    assert "transpose" in ch29.check_left_matrix_at_t(np.array(LEFT).T.tolist()).message
    assert "that is R" in ch29.check_left_matrix_at_t([[4 / 9, 4 / 9, 1 / 9], [0, 2 / 3, 1 / 3], [0, 0, 1]]).message
    assert "swapped" in ch29.check_left_matrix_at_t([[1, 0, 0], [1 / 3, 2 / 3, 0], [1 / 9, 4 / 9, 4 / 9]]).message
    assert "t = 1/2" in ch29.check_left_matrix_at_t([[1, 0, 0], [0.5, 0.5, 0], [0.25, 0.5, 0.25]]).message
    r = ch29.check_left_matrix_at_t([[1, 0, 0], [2 / 3, 1 / 3, 0], [4 / 9, 2 / 9, 1 / 9]])
    assert "row 2 sums to 0.7778" in r.message
    r = ch29.check_left_matrix_at_t([[1, 0, 0], [2 / 3, 1 / 3, 0], [4 / 9, 3 / 9, 2 / 9]])
    assert "row 2, column 1 of L" in r.message and "too small;" in r.message
    assert "shape (3, 3)" in ch29.check_left_matrix_at_t([[1, 0], [0.5, 0.5]]).message


def test_bspline_right_half_messages():
    assert "that is L @ P" in ch29.check_bspline_right_half([[1, 3], [2.25, 5.25], [4, 6], [5.75, 5.5]]).message
    assert "Bezier R @ P" in ch29.check_bspline_right_half([[4, 4.75], [5.5, 5], [7, 4], [8, 2]]).message
    assert "transposed" in ch29.check_bspline_right_half([[0, 0], [1.75, 3.75], [9.5, 8.5], [4.75, 1.75]]).message
    assert "five points" in ch29.check_bspline_right_half(
        [[1, 3], [2.25, 5.25], [4, 6], [5.75, 5.5], [7, 4]]).message
    r = ch29.check_bspline_right_half([[2.25, 5.25], [4, 6.5], [5.75, 5.5], [7, 4]])
    assert "point 1 of R @ P is off from where it should be" in r.message and "the only point that is off" in r.message


def test_composed_fixed_point_messages():
    # M_R then M_L: C(t) -> C((1 + t)/4), fixed at t = 1/3: 4/9 (3, 6) + 1/9 (9, 0)
    assert "M_R followed by M_L" in ch29.check_composed_fixed_point([7 / 3, 8 / 3]).message
    assert "M_L alone" in ch29.check_composed_fixed_point([0, 0]).message
    assert "M_R alone" in ch29.check_composed_fixed_point([9, 0]).message
    # C(1/2) = 1/2 (3, 6) + 1/4 (9, 0)
    assert "where the two halves meet" in ch29.check_composed_fixed_point([3.75, 3]).message
    assert "not a parameter" in ch29.check_composed_fixed_point(2 / 3).message
    assert "is off from where it should be" in ch29.check_composed_fixed_point([5, 3]).message


def test_normal_curve_messages():
    assert "B_0 is the weight of the origin" in ch29.check_normal_curve_point(
        [16 / 81, 32 / 81, 24 / 81, 8 / 81, 1 / 81]).message
    assert "N(2/3)" in ch29.check_normal_curve_point([8 / 81, 24 / 81, 32 / 81, 16 / 81]).message
    assert "binomial coefficients" in ch29.check_normal_curve_point([8 / 81, 4 / 81, 2 / 81, 1 / 81]).message
    assert "coordinate x2 of N(1/3)" in ch29.check_normal_curve_point([32 / 81, 0.3, 8 / 81, 1 / 81]).message


def test_joint_messages():
    assert "Bezier midpoint" in ch29.check_fractal_joint([2, 2]).message
    assert "sum to one" in ch29.check_fractal_joint([1, -2]).message    # u = 1/2: (0 - 1 + 2, -2)
    assert "sum to one" in ch29.check_fractal_joint([0, -2]).message    # u = 1/4: (0 - 1 + 1, -2)


def test_quarter_joint_messages():
    # R P = (2,-2), (3,2), (4,0); its joint 3/4 (2,-2) - 1/2 (3,2) + 3/4 (4,0) = (3, -2.5)
    assert "third and fourth quarters" in ch29.check_fractal_quarter_joint([3, -2.5]).message
    assert "joint of the two halves" in ch29.check_fractal_quarter_joint([2, -2]).message
    # Bezier C(1/4) = 6/16 (2, 4) + 1/16 (4, 0)
    assert "Bezier point C(1/4)" in ch29.check_fractal_quarter_joint([1, 1.5]).message
    assert "midpoint of P0 and the joint" in ch29.check_fractal_quarter_joint([1, -1]).message


# -- the programming project --------------------------------------------------------------------------

from math import comb  # noqa: E402


def hand_matrices(n, t=0.5):
    """The Bernstein formulas of §29.2, written out here (not the library)."""
    L = np.zeros((n + 1, n + 1))
    R = np.zeros((n + 1, n + 1))
    for i in range(n + 1):
        for j in range(i + 1):
            L[i, j] = comb(i, j) * t ** j * (1 - t) ** (i - j)
        for j in range(i, n + 1):
            R[i, j] = comb(n - i, j - i) * t ** (j - i) * (1 - t) ** (n - j)
    return L, R


def test_project_accepts_a_correct_function():
    r = ch29.check_subdivision_matrices_project(hand_matrices)
    assert r.correct, r
    assert "12 cases" in r.message and "degree 1 (a segment)" in r.message and "random t" in r.message


def test_project_names_swapped_matrices():
    def swapped(n, t=0.5):
        L, R = hand_matrices(n, t)
        return R, L

    r = ch29.check_subdivision_matrices_project(swapped)
    assert not r.correct and r.answered
    assert "case 1 of 12 (degree 1, a segment, at t = 1/2)" in r.message and "L and R are swapped" in r.message
    assert "two 2 x 2 matrices" in r.message


def test_project_names_a_transposed_matrix_and_a_wrong_entry_without_printing_the_matrix():
    def transposed_r(n, t=0.5):
        L, R = hand_matrices(n, t)
        return L, R.T

    r = ch29.check_subdivision_matrices_project(transposed_r)
    assert "case 1 of 12" in r.message and "R is transposed" in r.message

    def off_from_degree_4(n, t=0.5):        # the binomial coefficient dropped in L's row 3 for n >= 4
        L, R = hand_matrices(n, t)
        if n >= 4:
            L[3, 1] = t * (1 - t) ** 2
        return L, R

    r = ch29.check_subdivision_matrices_project(off_from_degree_4)
    assert "case 4 of 12 (degree 4 at t = 1/2)" in r.message
    assert "L[3, 1] (row 3, column 1) is 0.125, expected 0.375" in r.message
    assert "two 5 x 5 matrices" in r.message and "[[" not in r.message


def test_project_reports_a_crash_with_the_learners_line():
    def crashing(n, t=0.5):
        L = np.zeros((n + 1, n + 1))
        L[n + 1, 0] = 1.0
        return L, L

    r = ch29.check_subdivision_matrices_project(crashing)
    assert not r.correct and r.answered
    assert "case 1 of 12" in r.message and "raised IndexError" in r.message
    assert "`L[n + 1, 0] = 1.0`" in r.message


def test_project_unanswered_and_wrong_shapes():
    def starter(n, t=0.5):
        """Return (L, R)."""
        ...

    assert not ch29.check_subdivision_matrices_project(starter).answered
    assert not ch29.check_subdivision_matrices_project(None).answered
    r = ch29.check_subdivision_matrices_project(lambda n, t=0.5: hand_matrices(n, t)[0])
    assert "a pair (L, R)" in r.message
    r = ch29.check_subdivision_matrices_project(lambda n, t=0.5: tuple(m[:-1] for m in hand_matrices(n, t)))
    assert "should have shape (2, 2)" in r.message


# -- dealt instances (issue 17 §3): the dealt answers against closed forms ----------------------------

SEEDS = range(1, 41)


def _dealt(name, seed):
    return ch29.DECK.exercises[name].instance(seed), ch29.DECK.exercises[name].answer


def _bern(n, k, t):
    return math.comb(n, k) * t ** k * (1 - t) ** (n - k)


def test_dealt_left_matrix_and_normal_point_are_bernstein_values():
    for seed in SEEDS:
        p, answer = _dealt("check_left_matrix_at_t", seed)
        t = p["t"]
        assert np.allclose(answer(p), [[_bern(i, j, t) if j <= i else 0 for j in range(3)] for i in range(3)])
        p, answer = _dealt("check_normal_curve_point", seed)
        assert np.allclose(answer(p), [_bern(4, k, p["t"]) for k in range(1, 5)])


def test_dealt_right_half_uses_the_cubic_mask():
    rows = np.array([[1, 6, 1, 0], [0, 4, 4, 0], [0, 1, 6, 1], [0, 0, 4, 4]]) / 8
    for seed in SEEDS:
        p, answer = _dealt("check_bspline_right_half", seed)
        assert np.allclose(answer(p), rows @ np.array(p["ctrl"]))


def test_dealt_fixed_point_and_joints():
    for seed in SEEDS:
        p, answer = _dealt("check_composed_fixed_point", seed)
        P = np.array(p["ctrl"])
        assert np.allclose(answer(p), (P[0] + 4 * P[1] + 4 * P[2]) / 9)       # C(2/3)
        p, answer = _dealt("check_fractal_joint", seed)
        P, v = np.array(p["ctrl"]), p["v"]
        u = (1 - v) / 2
        joint = u * P[0] + v * P[1] + u * P[2]
        assert np.allclose(answer(p), joint)
        p, answer = _dealt("check_fractal_quarter_joint", seed)
        P, v = np.array(p["ctrl"]), p["v"]
        u = (1 - v) / 2
        left = [P[0], (P[0] + P[1]) / 2, u * P[0] + v * P[1] + u * P[2]]
        assert np.allclose(answer(p), u * left[0] + v * left[1] + u * left[2])

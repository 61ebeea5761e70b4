"""Tests of the chapter-24 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.bezier cannot make a checker accept a wrong answer), and each
recognised slip gets its own message."""

import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch24

# -- hand-worked answers ---------------------------------------------------------------------------
# cubic (0,0),(4,8),(8,8),(12,0) at t = 1/4:
#   level 1 (1,2),(5,8),(9,6); level 2 (2,3.5),(6,7.5); level 3 (3,4.5)
DC_POINT = [3.0, 4.5]
# B_k^4(0.2) = C(4,k) 0.2^k 0.8^(4-k): 0.4096, 4*0.2*0.512, 6*0.04*0.64, 4*0.008*0.8, 0.0016
BERN = [0.4096, 0.4096, 0.1536, 0.0256, 0.0016]
# P0 = (1,1); P1 = P0 + (6,3)/3 = (3,2); P2 = P3 - (3,-6)/3 = (6,3); P3 = (7,1)
ENDS = [[1, 1], [3, 2], [6, 3], [7, 1]]
# 3 * differences of (1,0),(2,3),(5,4),(6,1): 3*(1,3), 3*(3,1), 3*(1,-3)
HODO = [[3, 9], [9, 3], [3, -9]]
# (0,0),(6,3),(3,9): Q1 = 1/3 P0 + 2/3 P1 = (4,2); Q2 = 2/3 P1 + 1/3 P2 = (4+1, 2+3)
ELEV = [[0, 0], [4, 2], [5, 5], [3, 9]]
# P3 = (6,3), P3 - P2 = (2,-1), interval ratio 2: Q1 = (6,3) + 2*(2,-1)
JOIN = [[6, 3], [10, 1]]
# net (2j, 2i, z_ij), z = [[0,2,0],[2,4,2],[0,2,4]], u = 1/2 (1/4,1/2,1/4), v = 1/4 (9/16,6/16,1/16):
#   x = 4v = 1, y = 4u = 2; rows at v: z = 12/16, 44/16, 16/16; at u: 3/16 + 22/16 + 4/16 = 29/16
PATCH = [1.0, 2.0, 29 / 16]

CHECKERS = [
    (ch24.check_de_casteljau_point, DC_POINT),
    (ch24.check_bernstein_weights, BERN),
    (ch24.check_end_conditions, ENDS),
    (ch24.check_hodograph, HODO),
    (ch24.check_degree_elevation, ELEV),
    (ch24.check_c1_join_unequal, JOIN),
    (ch24.check_patch_point, PATCH),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch24.DE_CASTELJAU_CTRL.tolist() == [[0, 0], [4, 8], [8, 8], [12, 0]] and ch24.DE_CASTELJAU_T == 0.25
    assert (ch24.BERNSTEIN_N, ch24.BERNSTEIN_T) == (4, 0.2)
    assert [p.tolist() for p in (ch24.END_P0, ch24.END_D0, ch24.END_P3, ch24.END_D1)] == [[1, 1], [6, 3], [7, 1], [3, -6]]
    assert ch24.HODOGRAPH_CTRL.tolist() == [[1, 0], [2, 3], [5, 4], [6, 1]]
    assert ch24.ELEVATION_CTRL.tolist() == [[0, 0], [6, 3], [3, 9]]
    assert ch24.JOIN_CTRL.tolist() == [[0, 0], [1, 3], [4, 4], [6, 3]] and ch24.JOIN_RATIO == 2
    assert ch24.PATCH_NET[:, :, 2].tolist() == [[0, 2, 0], [2, 4, 2], [0, 2, 4]]
    assert ch24.PATCH_NET[1, 2, :2].tolist() == [4, 2] and (ch24.PATCH_U, ch24.PATCH_V) == (0.5, 0.25)


def test_exercises_use_fresh_data_not_the_chapters_worked_examples():
    worked = [[0, 0], [1, 2.5], [3, 2.5], [4, 0.5]]
    for ctrl in (ch24.DE_CASTELJAU_CTRL, ch24.HODOGRAPH_CTRL, ch24.JOIN_CTRL):
        assert ctrl.tolist() != worked
    assert ch24.DE_CASTELJAU_T != 0.5 and ch24.BERNSTEIN_T != 0.4 and ch24.JOIN_RATIO != 1


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_hand_decimals_are_accepted():
    assert ch24.check_patch_point([1, 2, 1.8125]).correct
    assert ch24.check_bernstein_weights([0.4096, 0.4096, 0.15360001, 0.0256, 0.0016]).correct


def test_de_casteljau_messages():
    assert "a little off from the curve at t=0.25" in ch24.check_de_casteljau_point([3.0, 4.53]).message
    assert "level 1" in ch24.check_de_casteljau_point([5, 8]).message
    assert "level 2" in ch24.check_de_casteljau_point([2, 3.5]).message
    assert "point at t = 0.75" in ch24.check_de_casteljau_point([9, 4.5]).message
    assert "average of the control points" in ch24.check_de_casteljau_point([6, 4]).message
    assert "shape" in ch24.check_de_casteljau_point([[3, 4.5]]).message


def test_bernstein_messages():
    assert "binomial coefficient C(4, k)" in ch24.check_bernstein_weights([0.4096, 0.1024, 0.0256, 0.0064, 0.0016]).message
    assert "reversed" in ch24.check_bernstein_weights(BERN[::-1]).message
    assert "list of 5 numbers" in ch24.check_bernstein_weights([0.4, 0.4, 0.15, 0.03]).message
    r = ch24.check_bernstein_weights([0.4096, 0.4096, 0.2, 0.0256, 0.0016])
    assert "weight 2 (B_2^4) is too large" in r.message and "sum to one" in r.message


def test_end_condition_messages():
    assert "three times too far" in ch24.check_end_conditions([[1, 1], [7, 4], [4, 7], [7, 1]]).message
    assert "wrong side of P3" in ch24.check_end_conditions([[1, 1], [3, 2], [8, -1], [7, 1]]).message
    assert "interpolates its end control points" in ch24.check_end_conditions([[0, 0], [3, 2], [6, 3], [7, 1]]).message
    r = ch24.check_end_conditions([[1, 1], [3, 2.5], [6, 3], [7, 1]])
    assert not r and "point 1" in r.message


def test_hodograph_messages():
    assert "multiplies them by the degree n = 3" in ch24.check_hodograph([[1, 3], [3, 1], [1, -3]]).message
    assert "point backwards" in ch24.check_hodograph([[-3, -9], [-9, -3], [-3, 9]]).message
    assert "degree 2" in ch24.check_hodograph([[3, 9], [9, 3]]).message
    r = ch24.check_hodograph([[3, 9], [9, 4], [3, -9]])
    assert not r and "point 1" in r.message


def test_degree_elevation_messages():
    assert "swapped" in ch24.check_degree_elevation([[0, 0], [2, 1], [4, 7], [3, 9]]).message
    assert "should be four points" in ch24.check_degree_elevation([[0, 0], [6, 3], [3, 9]]).message
    assert "keeps its end points" in ch24.check_degree_elevation([[0, 0], [4, 2], [5, 5], [3, 8]]).message
    r = ch24.check_degree_elevation([[0, 0], [4, 2], [5, 5.5], [3, 9]])
    assert not r and "point 2" in r.message


def test_c1_join_messages():
    assert "gap at the join" in ch24.check_c1_join_unequal([[6, 4], [10, 1]]).message
    assert "C1 for equal parameter intervals" in ch24.check_c1_join_unequal([[6, 3], [8, 2]]).message
    assert "inverted" in ch24.check_c1_join_unequal([[6, 3], [7, 2.5]]).message
    assert "wrong side" in ch24.check_c1_join_unequal([[6, 3], [2, 5]]).message
    assert "length of Q1 - Q0" in ch24.check_c1_join_unequal([[6, 3], [12, 0]]).message
    r = ch24.check_c1_join_unequal([[6, 3], [10, 2]])
    assert "Q1 is off from where it should be" in r.message and "10" not in r.message.replace("[10, 2]", "")


def test_patch_messages():
    assert "exchanged" in ch24.check_patch_point([2, 1, 29 / 16]).message
    assert "bilinear interpolation of the four corner" in ch24.check_patch_point([1, 2, 0.5]).message
    assert "plain average" in ch24.check_patch_point([2, 2, 16 / 9]).message
    assert "shape" in ch24.check_patch_point([1, 2]).message
    r = ch24.check_patch_point([1, 2, 2])
    assert "off from the patch point" in r.message


# -- Exercise 8 (§24.1), worked by hand: nodes 0, 1/2, 1 at t = 1/4 give level 1 (2, 2) and (2, 6),
#    level 2 3/4 (2, 2) + 1/4 (2, 6) = (2, 3); the parabola is x = 8t, y = 16 t (1 - t)
def test_neville_exercise_by_hand_and_its_slips():
    assert ch24.NEVILLE_POINTS.tolist() == [[0, 0], [4, 4], [8, 0]] and ch24.NEVILLE_NODES.tolist() == [0, 0.5, 1]
    assert ch24.NEVILLE_T == 0.25
    assert ch24.check_neville_point([2, 3]).correct
    assert "Bezier" in ch24.check_neville_point([2, 1.5]).message         # the approximation, not the interpolant
    assert "first level" in ch24.check_neville_point([2, 6]).message
    assert "data points" in ch24.check_neville_point([4, 4]).message

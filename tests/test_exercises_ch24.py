"""Tests of the chapter-24 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.bezier cannot make a checker accept a wrong answer)."""

import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch24

# hand-worked answers
# cubic (0,0),(1,3),(3,3),(4,0) at 1/2: (P0 + 3P1 + 3P2 + P3)/8 = (16/8, 18/8)
DC_POINT = [2.0, 2.25]
# 3 * differences of (0,0),(1,2),(3,2),(4,0)
HODO = [[3, 6], [6, 0], [3, -6]]
# (0,0),(3,3),(6,0): Q1 = 1/3 P0 + 2/3 P1 = (2,2); Q2 = 2/3 P1 + 1/3 P2 = (4,2)
ELEV = [[0, 0], [2, 2], [4, 2], [6, 0]]
# P3 = (4,2), P3 - P2 = (1,-1)
JOIN = [[4, 2], [5, 1]]
BERN = 6 / 16

CHECKERS = [
    (ch24.check_de_casteljau_point, DC_POINT),
    (ch24.check_hodograph, HODO),
    (ch24.check_degree_elevation, ELEV),
    (ch24.check_c1_join, JOIN),
    (ch24.check_bernstein_value, BERN),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch24.DE_CASTELJAU_CTRL.tolist() == [[0, 0], [1, 3], [3, 3], [4, 0]] and ch24.DE_CASTELJAU_T == 0.5
    assert ch24.HODOGRAPH_CTRL.tolist() == [[0, 0], [1, 2], [3, 2], [4, 0]]
    assert ch24.ELEVATION_CTRL.tolist() == [[0, 0], [3, 3], [6, 0]]
    assert ch24.JOIN_CTRL.tolist() == [[0, 0], [1, 2], [3, 3], [4, 2]]
    assert (ch24.BERNSTEIN_N, ch24.BERNSTEIN_K, ch24.BERNSTEIN_T) == (4, 2, 0.5)


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_de_casteljau_messages():
    assert "0.03 from the curve at t=0.5" in ch24.check_de_casteljau_point([2.0, 2.28]).message
    # level-1 point (2, 3) and level-2 point (2.75, 2.25)
    assert "level 1" in ch24.check_de_casteljau_point([2, 3]).message
    assert "level 2" in ch24.check_de_casteljau_point([2.75, 2.25]).message
    assert "average of the control points" in ch24.check_de_casteljau_point([2, 1.5]).message
    assert "shape" in ch24.check_de_casteljau_point([[2, 2.25]]).message


def test_hodograph_messages():
    assert "multiplies them by the degree n = 3" in ch24.check_hodograph([[1, 2], [2, 0], [1, -2]]).message
    assert "degree 2" in ch24.check_hodograph([[3, 6], [6, 0]]).message
    r = ch24.check_hodograph([[3, 6], [6, 1], [3, -6]])
    assert not r and "point 1" in r.message


def test_degree_elevation_messages():
    assert "swapped" in ch24.check_degree_elevation([[0, 0], [1, 1], [5, 1], [6, 0]]).message
    assert "should be 4 points" in ch24.check_degree_elevation([[0, 0], [3, 3], [6, 0]]).message
    r = ch24.check_degree_elevation([[0, 0], [2, 2], [4, 2.5], [6, 0]])
    assert not r and "point 2" in r.message


def test_c1_join_messages():
    assert "meet (C0)" in ch24.check_c1_join([[4, 3], [5, 1]]).message
    assert "G1, but not C1" in ch24.check_c1_join([[4, 2], [4.5, 1.5]]).message
    assert "wrong side" in ch24.check_c1_join([[4, 2], [3, 3]]).message
    assert "Q1 should be (5, 1)" in ch24.check_c1_join([[4, 2], [5, 2]]).message


def test_bernstein_messages():
    assert "binomial coefficient C(4, 2) = 6" in ch24.check_bernstein_value(1 / 16).message
    r = ch24.check_bernstein_value(0.4)
    assert not r and "should be 0.375" in r.message

"""Tests of the chapter-10 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.vectors cannot make a checker accept a wrong answer); the
generic checks of every checker are in tests/exercises/test_exercises.py and tests/exercises/test_solutions.py."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import Result, ch10

# 2*4 + (-1)*5 + 3*(-2) = 8 - 5 - 6 = -3
DOT = -3
# (3*4 - (-2)(-1), (-2)*2 - 1*4, 1*(-1) - 3*2) = (12 - 2, -4 - 4, -1 - 6)
CROSS = [10, -8, -7]
# 2((-1)(1) - 2*0) - 1(1*1 - 2*4) + 3(1*0 - (-1)*4) = -2 + 7 + 12
DET = 17
# u.v = 3 + 0 + 8 = 11, |u| = 5, |v| = 3: acos(11/15)
ANGLE = 42.83
# Q - P = (2, 1, 0), R - P = (1, 3, 2): cross (1*2 - 0*3, 0*1 - 2*2, 2*3 - 1*1) = (2, -4, 5), sqrt(4 + 16 + 25)
AREA = 6.708
# v x w = (0*7 - 1*4, 1*k - 2*7, 2*4 - 0*k) = (-4, k - 14, 8); u.(v x w) = -4 + 2k - 28 + 24 = 2k - 8 = 0
K = 4

CHECKERS = [
    (ch10.check_dot_product, DOT),
    (ch10.check_cross_product, CROSS),
    (ch10.check_determinant, DET),
    (ch10.check_angle, ANGLE),
    (ch10.check_parallelogram_area, AREA),
    (ch10.check_coplanar_k, K),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch10.DOT_U.tolist() == [2, -1, 3] and ch10.DOT_V.tolist() == [4, 5, -2]
    assert ch10.CROSS_U.tolist() == [1, 3, -2] and ch10.CROSS_V.tolist() == [2, -1, 4]
    assert ch10.DET_ROWS.tolist() == [[2, 1, 3], [1, -1, 2], [4, 0, 1]]
    assert ch10.ANGLE_U.tolist() == [3, 0, 4] and ch10.ANGLE_V.tolist() == [1, 2, 2]
    assert ch10.AREA_POINTS.tolist() == [[1, 0, 2], [3, 1, 2], [2, 3, 4]]
    assert ch10.COPLANAR_U.tolist() == [1, 2, 3] and ch10.COPLANAR_V.tolist() == [2, 0, 1]
    assert ch10.COPLANAR_W == (4, 7)


def test_hand_answers_against_numpy():
    assert np.dot(ch10.DOT_U, ch10.DOT_V) == DOT
    assert np.cross(ch10.CROSS_U, ch10.CROSS_V).tolist() == CROSS
    assert round(np.linalg.det(ch10.DET_ROWS), 9) == DET
    assert abs(math.degrees(math.acos(11 / 15)) - ANGLE) < 0.005
    assert abs(math.sqrt(45) - AREA) < 5e-4
    assert abs(np.linalg.det([ch10.COPLANAR_U, ch10.COPLANAR_V, [K, 4, 7]])) < 1e-12


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def message(checker, answer):
    r = checker(answer)
    assert not r.correct and r.answered, r
    return r.message


def test_dot_slips():
    assert "vector of products" in message(ch10.check_dot_product, [8, -5, -6])
    assert "sizes of the products" in message(ch10.check_dot_product, 19)
    assert "u_2 v_2" in message(ch10.check_dot_product, 7)


def test_cross_slips():
    assert "v × u" in message(ch10.check_cross_product, [-10, 8, 7])
    assert "difference, not a sum" in message(ch10.check_cross_product, [14, 0, 5])
    assert "middle coordinate" in message(ch10.check_cross_product, [10, 8, -7])
    assert "vector of products" in message(ch10.check_cross_product, [2, -3, -8])
    assert "coordinate 3 is too large" in message(ch10.check_cross_product, [10, -8, -6])


def test_determinant_slips():
    assert "alternate + - +" in message(ch10.check_determinant, 3)
    assert "sign is reversed" in message(ch10.check_determinant, -17)
    assert "Sarrus" in message(ch10.check_determinant, 6)


def test_angle_slips():
    assert "radians" in message(ch10.check_angle, 0.7476)
    assert "cos θ" in message(ch10.check_angle, 0.7333)
    assert "square roots" in message(ch10.check_angle, 87.2)
    assert "supplementary" in message(ch10.check_angle, 137.17)


def test_area_slips():
    assert "half the area" in message(ch10.check_parallelogram_area, 3.354)
    assert "square root" in message(ch10.check_parallelogram_area, 45)
    assert "added the coordinates" in message(ch10.check_parallelogram_area, 3)
    assert "points' own coordinates" in message(ch10.check_parallelogram_area, 10.8167)


def test_coplanar_slips():
    assert "middle term" in message(ch10.check_coplanar_k, 24)
    assert "differences" in message(ch10.check_coplanar_k, 0)
    assert "negative" in message(ch10.check_coplanar_k, -4) and "positive" in message(ch10.check_coplanar_k, 5)

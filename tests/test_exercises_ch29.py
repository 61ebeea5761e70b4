"""Tests of the chapter-29 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.subdivision_matrices cannot make a checker accept a wrong answer)."""

import numpy as np
import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch29

# de Casteljau triangle at 1/2, left edge: P0; (P0+P1)/2; (P0+2P1+P2)/4
LEFT = [[1, 0, 0], [0.5, 0.5, 0], [0.25, 0.5, 0.25]]
# Chaikin: the segment's right half uses the cuts 1/4 P0 + 3/4 P1, 3/4 P1 + 1/4 P2, 1/4 P1 + 3/4 P2
RIGHT = [[0.25, 0.75, 0], [0, 0.75, 0.25], [0, 0.25, 0.75]]
# B_k^3(1/2) = 3/8, 3/8, 1/8 for k = 1, 2, 3
NORMAL = [3 / 8, 3 / 8, 1 / 8]
# the right map fixes P2
FIXED = [6, 2]
# v = -1/2, u = 3/4: 3/4 (0,0) - 1/2 (2,4) + 3/4 (4,0) = (3 - 1, -2)
JOINT = [2.0, -2.0]

CHECKERS = [
    (ch29.check_quadratic_left_matrix, LEFT),
    (ch29.check_chaikin_right_matrix, RIGHT),
    (ch29.check_normal_curve_point, NORMAL),
    (ch29.check_right_map_fixed_point, FIXED),
    (ch29.check_fractal_joint, JOINT),
]
IDS = [c.__name__ for c, _ in CHECKERS]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch29.FIXED_CTRL.tolist() == [[0, 0], [2, 4], [6, 2]]
    assert ch29.FRACTAL_CTRL.tolist() == [[0, 0], [2, 4], [4, 0]] and ch29.FRACTAL_MIDDLE == -0.5


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=IDS)
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_left_matrix_messages():
    assert "transpose" in ch29.check_quadratic_left_matrix(np.array(LEFT).T.tolist()).message
    assert "that is R" in ch29.check_quadratic_left_matrix([[0.25, 0.5, 0.25], [0, 0.5, 0.5], [0, 0, 1]]).message
    assert "row 2 sums to 0.9" in ch29.check_quadratic_left_matrix([[1, 0, 0], [0.5, 0.5, 0], [0.25, 0.5, 0.15]]).message


def test_right_matrix_messages():
    assert "that is L" in ch29.check_chaikin_right_matrix([[0.75, 0.25, 0], [0.25, 0.75, 0], [0, 0.75, 0.25]]).message
    assert "Bezier R" in ch29.check_chaikin_right_matrix([[0.25, 0.5, 0.25], [0, 0.5, 0.5], [0, 0, 1]]).message


def test_normal_curve_messages():
    assert "B_0 is the weight of the origin" in ch29.check_normal_curve_point([1 / 8, 3 / 8, 3 / 8, 1 / 8]).message
    assert "point 0" in ch29.check_normal_curve_point([0.5, 0.375, 0.125]).message


def test_fixed_point_messages():
    assert "left map" in ch29.check_right_map_fixed_point([0, 0]).message
    assert "C(3/4)" in ch29.check_right_map_fixed_point([2.5, 2.5]).message


def test_joint_messages():
    assert "Bezier midpoint" in ch29.check_fractal_joint([2, 2]).message
    assert "sum to one" in ch29.check_fractal_joint([1, -2]).message  # u = 1/2: (0 - 1 + 2, -2)

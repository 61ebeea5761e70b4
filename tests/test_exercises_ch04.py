"""Chapter 4 checkers: right for the worked solutions (also computed here by hand), wrong with the
reason for typical slips, "not answered" for None and ...."""

import math

import numpy as np

from goldman_lib.exercises import ch04


def _assert_wrong(result, *fragments):
    assert result.answered and not result.correct, result
    for f in fragments:
        assert f in result.message, (f, result.message)


CHECKERS = [ch04.exercise_rotate_point, ch04.exercise_compose_matrix, ch04.exercise_three_points,
            ch04.exercise_vector_image, ch04.exercise_nonuniform_scaling]


def test_problems_listed():
    assert set(ch04.PROBLEMS) == {c.__name__ for c in CHECKERS}


def test_rotate_point():
    assert ch04.exercise_rotate_point((1, 3)).correct
    assert ch04.exercise_rotate_point(np.array([1.0, 3.0 + 1e-9])).correct
    _assert_wrong(ch04.exercise_rotate_point((-1, 3)), "about the origin")
    _assert_wrong(ch04.exercise_rotate_point((1, -1)), "clockwise")
    _assert_wrong(ch04.exercise_rotate_point((0, 2)), "translate back by Q")
    _assert_wrong(ch04.exercise_rotate_point((2, 2)), "should be (1, 3); you gave (2, 2)")
    _assert_wrong(ch04.exercise_rotate_point((1, 2, 3)), "two numbers")
    _assert_wrong(ch04.exercise_rotate_point("up"), "should be numbers")


def test_compose_matrix():
    # T(2, -1) then S(2): (x, y) -> (2(x + 2), 2(y - 1)) = (2x + 4, 2y - 2)
    assert ch04.exercise_compose_matrix([[2, 0, 0], [0, 2, 0], [4, -2, 1]]).correct
    _assert_wrong(ch04.exercise_compose_matrix([[2, 0, 0], [0, 2, 0], [2, -1, 1]]), "scale, then translate")
    _assert_wrong(ch04.exercise_compose_matrix([[2, 0, 4], [0, 2, -2], [0, 0, 1]]), "column-vector form")
    _assert_wrong(ch04.exercise_compose_matrix([[1, 0, 0], [0, 1, 0], [2, -1, 1]]), "scaling by 2 is missing")
    _assert_wrong(ch04.exercise_compose_matrix([[2, 0, 1], [0, 2, 0], [4, -2, 1]]), "last column")
    _assert_wrong(ch04.exercise_compose_matrix([[2, 0, 0], [0, 2, 0], [4, 2, 1]]), "third row, the translation")
    _assert_wrong(ch04.exercise_compose_matrix([[2, 0], [0, 2]]), "3x3 matrix")


def test_three_points():
    # rows: Q2 - Q1 = (2, 1), Q3 - Q1 = (-1, 2), Q1 = (1, 1)
    assert ch04.exercise_three_points([[2, 1, 0], [-1, 2, 0], [1, 1, 1]]).correct
    _assert_wrong(ch04.exercise_three_points([[3, 2, 0], [0, 3, 0], [1, 1, 1]]), "Q2 - Q1 and Q3 - Q1")
    _assert_wrong(ch04.exercise_three_points([[2, -1, 1], [1, 2, 1], [0, 0, 1]]), "transpose")
    _assert_wrong(ch04.exercise_three_points([[2, 1, 0], [-1, 2, 0], [0, 0, 1]]), "image of the origin")
    _assert_wrong(ch04.exercise_three_points([[2, 1, 0], [1, 2, 0], [1, 1, 1]]), "second row, the image of the vector e2")


def test_vector_image():
    assert ch04.exercise_vector_image((-1, 1)).correct
    _assert_wrong(ch04.exercise_vector_image((-3, 6)), "translations do not move it")
    _assert_wrong(ch04.exercise_vector_image((1, 1)), "the rotation does turn it")
    _assert_wrong(ch04.exercise_vector_image((1, -1)), "clockwise")


def test_nonuniform_scaling():
    # w = (1, 1)/sqrt(2): I + 2 w w^T = [[2, 1], [1, 2]]
    assert ch04.exercise_nonuniform_scaling([[2, 1, 0], [1, 2, 0], [0, 0, 1]]).correct
    r = 1 / math.sqrt(2)
    assert ch04.exercise_nonuniform_scaling(np.eye(3) + np.pad(2 * np.outer([r, r], [r, r]), ((0, 1), (0, 1)))).correct
    _assert_wrong(ch04.exercise_nonuniform_scaling([[3, 2, 0], [2, 3, 0], [0, 0, 1]]), "unit vector")
    _assert_wrong(ch04.exercise_nonuniform_scaling([[3, 0, 0], [0, 3, 0], [0, 0, 1]]), "uniform scaling")
    _assert_wrong(ch04.exercise_nonuniform_scaling([[3, 0, 0], [0, 1, 0], [0, 0, 1]]), "x-axis")

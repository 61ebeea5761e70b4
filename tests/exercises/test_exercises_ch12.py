"""Tests of the chapter-12 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.transforms cannot make a checker accept a wrong answer)."""

import numpy as np
import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch12

# 120 degrees about (1, 1, 1) sends (x, y, z) to (z, x, y): v = P - Q = (2, 1, -1) -> (-1, 2, 1); + Q
ROTATED = [0, 2, 3]
# n = (1, 2, 2)/3; (P - Q)·n = (3, 1, 2)·(1, 2, 2)/3 = 3; P - 6 n = (4, 1, 3) - (2, 4, 4)
MIRRORED = [2, -3, -1]
# w = (0, 0.6, 0.8); (P - Q)·w = (1, 2, 1)·w = 2; P + (3 - 1)·2 w = (2, 3, 2) + (0, 2.4, 3.2)
SCALED = [2, 5.4, 5.2]
# n = (2, -1, 2)/3; (P - Q)·n = (3, -1, 4)·n = 5; P - 5 n = (4, -1, 4) - (10, -5, 10)/3
ORTHO = [2 / 3, 2 / 3, 2 / 3]
# t = (Q - E)·N / (P - E)·N = (3, 1, -1)·(1, 1, 0) / (4, 2, 2)·(1, 1, 0) = 4/6; E + t (4, 2, 2)
PERSP = [5 / 3, 1 / 3, 7 / 3]

CHECKERS = [
    (ch12.check_rotation_about_point, ROTATED),
    (ch12.check_mirror_point, MIRRORED),
    (ch12.check_scale_along, SCALED),
    (ch12.check_orthogonal_projection, ORTHO),
    (ch12.check_perspective_projection, PERSP),
]
IDS = [c.__name__ for c, _ in CHECKERS]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch12.ROTATE_POINT.tolist() == [3, 1, 1] and ch12.ROTATE_THROUGH.tolist() == [1, 0, 2]
    assert ch12.ROTATE_AXIS.tolist() == [1, 1, 1] and ch12.ROTATE_ANGLE == 120
    assert (ch12.MIRROR_POINT.tolist(), ch12.MIRROR_PLANE_POINT.tolist(), ch12.MIRROR_NORMAL.tolist()) == (
        [4, 1, 3], [1, 0, 1], [1, 2, 2])
    assert (ch12.SCALE_POINT.tolist(), ch12.SCALE_FACTOR, ch12.SCALE_DIRECTION.tolist(), ch12.SCALE_CENTER.tolist()) == (
        [2, 3, 2], 3, [0, 3, 4], [1, 1, 1])
    assert (ch12.ORTHO_POINT.tolist(), ch12.ORTHO_PLANE_POINT.tolist(), ch12.ORTHO_NORMAL.tolist()) == (
        [4, -1, 4], [1, 0, 0], [2, -1, 2])
    assert (ch12.PERSP_POINT.tolist(), ch12.PERSP_EYE.tolist(), ch12.PERSP_PLANE_POINT.tolist(),
            ch12.PERSP_NORMAL.tolist()) == ([3, 1, 3], [-1, -1, 1], [2, 0, 0], [1, 1, 0])


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=IDS)
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_hand_decimals_are_accepted_and_sloppy_ones_not():
    assert ch12.check_orthogonal_projection([0.6667, 0.6667, 0.6667]).correct
    assert ch12.check_perspective_projection([1.6667, 0.3333, 2.3333]).correct
    assert not ch12.check_perspective_projection([1.67, 0.33, 2.33]).correct


def test_rotation_slips():
    m = lambda a: ch12.check_rotation_about_point(a).message  # noqa: E731
    assert "parallel axis through the origin" in m([1, 3, 1])
    assert "the other way" in m([2, -1, 4])
    assert "rotated vector" in m([-1, 2, 1])
    s3 = 3 ** 0.5
    assert "not normalised" in m([3 - s3, 2.5 + 1.5 * s3, 5.5 - s3 / 2])


def test_mirror_slips():
    m = lambda a: ch12.check_mirror_point(a).message  # noqa: E731
    assert "factor 1" in m([3, -1, 1])
    assert "length 3, not 1" in m([-14, -35, -33])
    assert "plane through the origin" in m([4 / 3, -13 / 3, -7 / 3])
    assert "sign is wrong" in m([6, 5, 7])


def test_scaling_slips():
    m = lambda a: ch12.check_scale_along(a).message  # noqa: E731
    assert "uniform scaling" in m([4, 7, 4])
    assert "about the origin" in m([2, 7.08, 7.44])
    assert "length 5" in m([2, 63, 82])
    assert "(s - 1)" in m([2, 6.6, 6.8])


def test_projection_slips():
    m = lambda a: ch12.check_orthogonal_projection(a).message  # noqa: E731
    assert "mirror image" in m([-8 / 3, 7 / 3, -8 / 3])
    assert "length 3, not 1" in m([-26, 14, -26]) and "not on the plane" in m([-26, 14, -26])
    assert "through the origin" in m([4 - 34 / 9, -1 + 17 / 9, 4 - 34 / 9])
    p = lambda a: ch12.check_perspective_projection(a).message  # noqa: E731
    assert "upside down" in p([5, 2, 4])
    assert "orthogonal projection" in p([2, 0, 3])
    assert "perspective from the origin" in p([1.5, 0.5, 1.5])
    assert "E + t (P - E)" in p([2, 2 / 3, 2])


def test_other_wrong_answers_say_how_far_and_never_the_answer():
    r = ch12.check_mirror_point([2, -3, 0])
    assert not r.correct and "off" in r.message
    r = ch12.check_rotation_about_point([0, 2])
    assert not r.correct and "shape (2,)" in r.message

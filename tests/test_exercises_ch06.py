"""Chapter 6 exercise checkers: hand-worked right answers pass, typical slips fail with the reason,
None is 'not answered'."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import ch06

# hand-worked: P = P/2 + (1, 0.5) -> P/2 = (1, 0.5) -> P = (2, 1)
FIXED = [2.0, 1.0]
# scale 1/2, turn 90 ccw ((x, y) -> (-y, x)), add (1, 0)
SQUARE = [[1, 0], [1, 0.5], [0.5, 0.5], [0.5, 0]]
CORNERS = [(0, 0), (2, 0), (0, 2)]


def half_about(c):
    return np.array([[0.5, 0, 0], [0, 0.5, 0], [c[0] / 2, c[1] / 2, 1]])


CASES = [
    (ch06.check_fixed_point, FIXED, [1, 0.5], "one step from the origin"),
    (ch06.check_gasket_count, 3 ** 5, 15, "multiplies by 3"),
    (ch06.check_tree_branches, 31, 16, "newest"),
    (ch06.check_square_image, SQUARE, [[1, 0], [1, -0.5], [1.5, -0.5], [1.5, 0]], "clockwise"),
    (ch06.check_gasket_maps, [half_about(c) for c in CORNERS], [half_about(c) for c in [(0, 0), (1, 0), (0, 1)]],
     "unit triangle"),
]


@pytest.mark.parametrize("checker,right,wrong_answer,reason", CASES, ids=[c[0].__name__ for c in CASES])
def test_right_wrong_and_unanswered(checker, right, wrong_answer, reason):
    r = checker(right)
    assert r.correct and r.answered, r
    w = checker(wrong_answer)
    assert not w.correct and w.answered and reason in w.message, w
    n = checker(None)
    assert not n.answered and "Not answered yet" in repr(n)


def test_gasket_maps_accepts_any_order_and_symmetric_maps():
    maps = [half_about(c) for c in reversed(CORNERS)]
    assert ch06.check_gasket_maps(maps).correct
    # the gasket is symmetric in the line y = x: a map that also reflects in it draws the same set
    swap = np.array([[0, 1, 0], [1, 0, 0], [0, 0, 1.0]])
    assert ch06.check_gasket_maps([swap @ half_about(CORNERS[0])] + [half_about(c) for c in CORNERS[1:]]).correct
    assert "does not shrink" in ch06.check_gasket_maps([np.eye(3)]).message
    assert "3x3" in ch06.check_gasket_maps([[1, 2]]).message


def test_other_slips_are_explained():
    assert "counts every level" in ch06.check_gasket_count(sum(3 ** j for j in range(6))).message
    assert "off by one level" in ch06.check_tree_branches(15).message
    assert "translated before rotating" in ch06.check_square_image([[0, 1], [0, 1.5], [-0.5, 1.5], [-0.5, 1]]).message
    assert "not the same point" in ch06.check_fixed_point([0, 0]).message
    assert not ch06.check_gasket_count("many").correct
    assert math.isclose(ch06.FIXED_POINT_MAP[0, 0], 0.5)

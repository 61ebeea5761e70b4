"""Chapter 4 checkers: right answers worked by hand here pass (also within hand-computed decimals),
each recognised slip gets its own reason, other wrong answers say how far off and where to look,
and no message gives the answer away."""

import numpy as np
import pytest

from goldman_lib.exercises import ch04


def _assert_wrong(result, *fragments):
    assert result.answered and not result.correct, result
    for f in fragments:
        assert f in result.message, (f, result.message)


def test_problems_and_slips_listed():
    names = {"check_rotate_about_point", "check_composite_matrix", "check_commuting_pairs",
             "check_point_and_vector_image", "check_point_and_vectors_map", "check_directional_scaling",
             "check_three_points_map"}
    assert set(ch04.PROBLEMS) == names == set(ch04.SLIPS)
    assert all(len(v) >= 2 for v in ch04.SLIPS.values())


def test_rotate_about_point():
    # P - Q = (4, 2) - (2, -1) = (2, 3); rotated by 90: (-3, 2); plus Q: (-1, 1)
    assert ch04.check_rotate_about_point([-1, 1]).correct
    assert ch04.check_rotate_about_point(np.array([-1.00001, 0.99999])).correct
    _assert_wrong(ch04.check_rotate_about_point([-2, 4]), "rotated about the origin")      # R(90) P
    _assert_wrong(ch04.check_rotate_about_point([5, -3]), "clockwise")                     # Q + R(-90)(P - Q)
    _assert_wrong(ch04.check_rotate_about_point([-3, 2]), "add Q back")                    # R(90)(P - Q)
    _assert_wrong(ch04.check_rotate_about_point([-3, 7]), "subtract Q before rotating")   # R(90)(P + Q) - Q
    r = ch04.check_rotate_about_point([0, 1])
    _assert_wrong(r, "off")
    _assert_wrong(ch04.check_rotate_about_point([1, 2, 3]), "two numbers")


def test_composite_matrix():
    # R(90) rows (0,1,0), (-1,0,0), (0,0,1); S(3, (1,0)): P -> 3P - (2, 0); R S:
    right = [[0, 3, 0], [-3, 0, 0], [-2, 0, 1]]
    assert ch04.check_composite_matrix(right).correct
    _assert_wrong(ch04.check_composite_matrix([[0, 3, 0], [-3, 0, 0], [0, -2, 1]]), "scale, then rotate")  # S R
    _assert_wrong(ch04.check_composite_matrix([[0, 3, 0], [-3, 0, 0], [0, 0, 1]]), "scales about the origin")
    _assert_wrong(ch04.check_composite_matrix(np.array(right).T.tolist()), "column-vector form")
    _assert_wrong(ch04.check_composite_matrix([[0, -3, 0], [3, 0, 0], [-2, 0, 1]]), "clockwise")
    _assert_wrong(ch04.check_composite_matrix([[0, 3, 1], [-3, 0, 0], [-2, 0, 1]]), "last column")
    _assert_wrong(ch04.check_composite_matrix([[0, 3, 0], [-3, 0, 0], [-2, 1, 1]]),
                  "third row of your matrix, the translation", "is off.")
    _assert_wrong(ch04.check_composite_matrix([[0, 3], [-3, 0]]), "3x3 matrix")


RIGHT_PAIRS = {"a": False, "b": True, "c": False, "d": True, "e": False}


def test_commuting_pairs():
    assert ch04.check_commuting_pairs(RIGHT_PAIRS).correct
    assert ch04.check_commuting_pairs({"a": "no", "b": "yes", "c": "No", "d": "True", "e": False}).correct
    _assert_wrong(ch04.check_commuting_pairs({**RIGHT_PAIRS, "a": True}), "pair (a)", "scales the translation")
    _assert_wrong(ch04.check_commuting_pairs({**RIGHT_PAIRS, "b": False}), "pair (b)", "SAME point")
    _assert_wrong(ch04.check_commuting_pairs({**RIGHT_PAIRS, "c": True}), "pair (c)", "different centres")
    _assert_wrong(ch04.check_commuting_pairs({**RIGHT_PAIRS, "d": False}), "pair (d)", "diagonal")
    _assert_wrong(ch04.check_commuting_pairs({**RIGHT_PAIRS, "e": True}), "pair (e)", "nonuniform")
    _assert_wrong(ch04.check_commuting_pairs({"a": False}), "pair (b) is missing")
    _assert_wrong(ch04.check_commuting_pairs({**RIGHT_PAIRS, "c": "maybe"}), "True or False")
    _assert_wrong(ch04.check_commuting_pairs([False, True]), "should be a dict")


def test_point_and_vector_image():
    # (1, 2, 1) M = (2 + 3, 1 + 2 - 1, 1) = (5, 2, 1); (1, 2, 0) M = (2, 3, 0)
    assert ch04.check_point_and_vector_image([[5, 2], [2, 3]]).correct
    _assert_wrong(ch04.check_point_and_vector_image([[5, 2], [5, 2]]), "translates the vector")
    _assert_wrong(ch04.check_point_and_vector_image([[5, 2], [1, 2]]), "leaves the vector unchanged")
    # M (1, 2, 1)^T = (4, 2, 2), M (1, 2, 0)^T = (4, 2, 1)
    _assert_wrong(ch04.check_point_and_vector_image([[4, 2], [4, 2]]), "multiplies M by a column")
    _assert_wrong(ch04.check_point_and_vector_image([[2, 3], [5, 2]]), "swapped")
    _assert_wrong(ch04.check_point_and_vector_image([[5, 2], [2, 4]]), "image of the vector v", "is off;")
    _assert_wrong(ch04.check_point_and_vector_image([5, 2]), "two points")


def test_point_and_vectors_map():
    # v1 = e1 -> (0, 2); e2 = v2 - v1 -> (1, 1) - (0, 2) = (1, -1); t = (2, 3) - (1, 1) L = (2, 3) - (1, 1)
    right = [[0, 2, 0], [1, -1, 0], [1, 2, 1]]
    assert ch04.check_point_and_vectors_map(right).correct
    # W as the rows, t = (2, 3) - (1, 1) W = (1, 0)
    _assert_wrong(ch04.check_point_and_vectors_map([[0, 2, 0], [1, 1, 0], [1, 0, 1]]), "as if v1, v2 were")
    _assert_wrong(ch04.check_point_and_vectors_map([[0, 2, 0], [1, -1, 0], [2, 3, 1]]), "image of the ORIGIN")
    _assert_wrong(ch04.check_point_and_vectors_map(np.array(right).T), "transpose")
    _assert_wrong(ch04.check_point_and_vectors_map([[0, 2, 0], [1, -1, 0], [1, 3, 1]]), "third row")


def test_directional_scaling():
    # w = (0.6, 0.8): L = I + w^T w = [[1.36, 0.48], [0.48, 1.64]]; t = (1, 0) - (1, 0) L = (-0.36, -0.48)
    right = [[1.36, 0.48, 0], [0.48, 1.64, 0], [-0.36, -0.48, 1]]
    assert ch04.check_directional_scaling(right).correct
    nudged = np.array(right)
    nudged[:, :2] += 3e-5
    assert ch04.check_directional_scaling(nudged).correct  # four decimals are enough
    nudged[:, :2] += 3e-3
    _assert_wrong(ch04.check_directional_scaling(nudged), "first row of your matrix", "also off: row 2, row 3")
    # w = (3, 4) as it is: L = I + [[9, 12], [12, 16]], t = (1, 0) - (10, 12)
    _assert_wrong(ch04.check_directional_scaling([[10, 12, 0], [12, 17, 0], [-9, -12, 1]]), "UNIT vector")
    _assert_wrong(ch04.check_directional_scaling([[1.36, 0.48, 0], [0.48, 1.64, 0], [0, 0, 1]]), "about the origin")
    _assert_wrong(ch04.check_directional_scaling([[2, 0, 0], [0, 2, 0], [-1, 0, 1]]), "uniform scaling")


def test_three_points_map():
    # P2 - P1 = (1, 0) -> (2, 2); P3 - P1 = (0, 2) -> (-2, 2), so (0, 1) -> (-1, 1); t = -(1, 1) L = (-1, -3)
    right = [[2, 2, 0], [-1, 1, 0], [-1, -3, 1]]
    assert ch04.check_three_points_map(right).correct
    _assert_wrong(ch04.check_three_points_map([[2, 2, 0], [-2, 2, 0], [0, 0, 1]]), "points Q2 and Q3 as rows")
    # Q2 - Q1, Q3 - Q1 as rows; t = Q1 - P1 L = -(0, 4)
    _assert_wrong(ch04.check_three_points_map([[2, 2, 0], [-2, 2, 0], [0, -4, 1]]), "P3 - P1 is not (0, 1)")
    _assert_wrong(ch04.check_three_points_map([[2, 2, 0], [-1, 1, 0], [0, 0, 1]]), "puts Q1 in the last row")
    _assert_wrong(ch04.check_three_points_map([[2, 2, 0], [-1, 2, 0], [-1, -3, 1]]), "second row", "e2")


@pytest.mark.parametrize("name", sorted(ch04.PROBLEMS))
def test_messages_never_state_the_expected_matrix(name):
    for slip in ch04.SLIPS[name]:
        r = getattr(ch04, name)(slip)
        assert not r.correct and "should be" not in r.message, r

"""Tests of the chapter-9 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.vectors cannot make a checker accept a wrong answer); the
generic checks of every checker are in tests/exercises/test_exercises.py and tests/exercises/test_solutions.py."""

import numpy as np
import pytest

from goldman_lib.exercises import Result, ch09

# (a) Q - P: weights -1, 1 -> 0, a vector; (b) P + Q: 2, undefined; (c) 2P - Q: 1, a point;
# (d) (P + Q)/2: 1, a point; (e) P - 2Q + R: 0, a vector; (f) P + Q - R: 1, a point.
KINDS = ["vector", "undefined", "point", "point", "vector", "point"]
# a = 1 - 0.3 - 0.45 = 0.25: 0.25 (1, 4) + 0.3 (5, 0) + 0.45 (-1, -2) = (0.25 + 1.5 - 0.45, 1 - 0.9) = (1.3, 0.1)
AFFINE = [1.3, 0.1]
# (16 + 25 - 49) / 2 = -4
DOT = -4
# |u x v| = 4 * 2.5 * sin 150 = 5, up (+z): u along +x, v counterclockwise
CROSS = [0, 0, 5]
# swap: -5; cyclic: 5; factors 2 and -1: -10; u + v in the plane of u, v: 0
DETS = [-5, 5, -10, 0]
# (u.v) w - (v.w) u = 3 (0, 1, 1) + 2 (1, 0, 2) = (2, 3, 7)
ASSOC = [2, 3, 7]

CHECKERS = [
    (ch09.check_expression_types, KINDS),
    (ch09.check_affine_point, AFFINE),
    (ch09.check_dot_from_lengths, DOT),
    (ch09.check_cross_from_angle, CROSS),
    (ch09.check_orientation, DETS),
    (ch09.check_associator, ASSOC),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert [e for e, _ in ch09.EXPRESSIONS] == ["Q - P", "P + Q", "2P - Q", "(P + Q)/2", "P - 2Q + R", "P + Q - R"]
    assert ch09.AFFINE_POINTS.tolist() == [[1, 4], [5, 0], [-1, -2]] and ch09.AFFINE_WEIGHTS == (0.3, 0.45)
    assert ch09.DOT_LENGTHS == (4, 5, 7)
    assert ch09.CROSS_U.tolist() == [4, 0, 0] and (ch09.CROSS_V_LENGTH, ch09.CROSS_ANGLE) == (2.5, 150)
    assert ch09.DET_GIVEN == 5 and [n for n, _ in ch09.DET_ASKED] == ["det(v, u, w)", "det(w, u, v)",
                                                                      "det(2u, v, -w)", "det(u, v, u + v)"]
    assert ch09.ASSOC_U.tolist() == [1, 0, 2] and ch09.ASSOC_W.tolist() == [0, 1, 1]
    assert (ch09.ASSOC_UV, ch09.ASSOC_VW) == (3, -2)


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_answers_typed_to_a_few_digits_are_accepted():
    assert ch09.check_cross_from_angle([0, 0, 5.0001]).correct
    assert ch09.check_expression_types("vector, illegal, a point, point, Vector, point").correct


def test_the_associator_hand_answer_holds_for_an_actual_v():
    # v = (1, 0, 1) has u.v = 1 + 2 = 3 and v.w = 0 + 0 + 1 = 1, not -2; v = (3, -2, 0): u.v = 3, v.w = -2
    u, v, w = ch09.ASSOC_U, np.array([3.0, -2.0, 0.0]), ch09.ASSOC_W
    assert np.dot(u, v) == 3 and np.dot(v, w) == -2
    assoc = np.cross(np.cross(u, v), w) - np.cross(u, np.cross(v, w))
    assert assoc.tolist() == ASSOC


def message(checker, answer):
    r = checker(answer)
    assert not r.correct and r.answered
    return r.message


def test_expression_slips_are_named():
    assert "2P - Q is not undefined" in message(ch09.check_expression_types,
                                                ["vector", "undefined", "undefined", "point", "vector", "point"])
    assert "(P + Q)/2 is not undefined" in message(ch09.check_expression_types,
                                                   ["vector", "undefined", "point", "undefined", "vector", "point"])
    assert "P + Q is undefined" in message(ch09.check_expression_types,
                                           ["vector", "point", "point", "point", "vector", "point"])
    assert "Q - P is not a point" in message(ch09.check_expression_types,
                                             ["point", "undefined", "point", "point", "vector", "point"])
    assert "not one of point, vector, undefined" in message(ch09.check_expression_types, ["a", "b", "c", "d", "e", "f"])


def test_affine_slips_are_named():
    assert "weights sum to 1.75, not 1" in message(ch09.check_affine_point, [2.05, 3.1])
    assert "weights sum to 0.75, not 1" in message(ch09.check_affine_point, [1.05, -0.9])
    assert "centroid" in message(ch09.check_affine_point, [5 / 3, 2 / 3])
    assert "wrong points" in message(ch09.check_affine_point, [2.2, 0.4])


def test_dot_slips_are_named():
    assert "forgot to halve" in message(ch09.check_dot_from_lengths, -8)
    assert "sign is reversed" in message(ch09.check_dot_from_lengths, 4)
    assert "squared lengths" in message(ch09.check_dot_from_lengths, 1)
    assert "too large" in message(ch09.check_dot_from_lengths, -3)


def test_cross_slips_are_named():
    assert "v × u" in message(ch09.check_cross_from_angle, [0, 0, -5])
    assert "uses cos θ" in message(ch09.check_cross_from_angle, [0, 0, 8.66025])
    assert "radians" in message(ch09.check_cross_from_angle, [0, 0, -7.14876])
    assert "triangle" in message(ch09.check_cross_from_angle, [0, 0, 2.5])
    assert "perpendicular" in message(ch09.check_cross_from_angle, [0, 5, 0])


def test_orientation_slips_are_named():
    assert "without their signs" in message(ch09.check_orientation, [5, 5, 10, 0])
    assert "cyclic shift" in message(ch09.check_orientation, [-5, -5, -10, 0])
    assert "factor in a slot" in message(ch09.check_orientation, [-5, 5, -5, 0])
    assert "plane of the first two" in message(ch09.check_orientation, [-5, 5, -10, 5])


def test_associator_slips_are_named():
    assert "associative" in message(ch09.check_associator, [0, 0, 0])
    assert "sign is reversed" in message(ch09.check_associator, [-2, -3, -7])
    assert "wrong vectors" in message(ch09.check_associator, [-3, -2, -8])

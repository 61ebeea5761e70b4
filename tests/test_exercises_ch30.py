"""Tests of the chapter-30 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.subdivision_surfaces cannot make a checker accept a wrong answer)."""

import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch30

# cube: V' = 8 + 12 + 6, F' = 4 * 6, E' = 2 * 12 + 4 * 6
COUNTS = [26, 48, 24]
# valence 5: 9/16, 3/(8*5), 1/(16*5)
STENCIL = [9 / 16, 3 / 40, 1 / 80]
# 9/16 (1,1,1) + 1/8 (1,1,1) + 1/48 (-1,-1,-1) = 32/48 = 2/3
CUBE_VERTEX = [2 / 3, 2 / 3, 2 / 3]
# 3/8 ((0,0,0) + (4,0,0)) + 1/8 ((2,3,1) + (2,-3,3)) = (1.5, 0, 0) + (0.5, 0, 0.5)
EDGE = [2.0, 0.0, 0.5]
# Chaikin: (0,0)(4,0)(4,4) -> 3/4, 1/4 corner cuts
CHAIKIN = [[1, 0], [3, 0], [4, 1], [4, 3]]

CHECKERS = [
    (ch30.check_cube_counts, COUNTS),
    (ch30.check_quad_vertex_stencil, STENCIL),
    (ch30.check_cube_vertex_point, CUBE_VERTEX),
    (ch30.check_triangle_edge_point, EDGE),
    (ch30.check_chaikin, CHAIKIN),
]
IDS = [c.__name__ for c, _ in CHECKERS]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch30.STENCIL_VALENCE == 5
    assert ch30.EDGE_POINTS.tolist() == [[0, 0, 0], [4, 0, 0], [2, 3, 1], [2, -3, 3]]
    assert ch30.CHAIKIN_CTRL.tolist() == [[0, 0], [4, 0], [4, 4]]


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=IDS)
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


def test_counts_messages():
    assert "left out the face points" in ch30.check_cube_counts([20, 48, 24]).message
    assert "triangle scheme" in ch30.check_cube_counts([26, 72, 48]).message
    r = ch30.check_cube_counts([26, 50, 24])
    assert not r and "V - E + F = 0" in r.message and "12 edges" in r.message


def test_stencil_messages():
    assert "regular vertex (n = 4)" in ch30.check_quad_vertex_stencil([9 / 16, 3 / 32, 1 / 64]).message
    assert "sum to one" in ch30.check_quad_vertex_stencil([0.5, 0.1, 0.1]).message
    assert "should be" in ch30.check_quad_vertex_stencil([0.5, 0.08, 0.02]).message


def test_vertex_point_messages():
    assert "Catmull-Clark" in ch30.check_cube_vertex_point([5 / 9] * 3).message
    assert "valence-4 weights" in ch30.check_cube_vertex_point([41 / 64] * 3).message
    assert "away" in ch30.check_cube_vertex_point([0.7, 0.7, 0.7]).message


def test_edge_point_messages():
    assert "midpoint of the edge" in ch30.check_triangle_edge_point([2, 0, 0]).message
    # plain centroids: 7/18 (v + w) + 1/9 (x + y) = (14/9 + 4/9, 0, 4/9)
    assert "7/18, 1/9" in ch30.check_triangle_edge_point([2, 0, 4 / 9]).message


def test_chaikin_messages():
    assert "averaged once" in ch30.check_chaikin([[0, 0], [2, 0], [4, 0], [4, 2], [4, 4]]).message
    assert "split alone" in ch30.check_chaikin([[0, 0], [0, 0], [4, 0], [4, 0], [4, 4], [4, 4]]).message
    assert "there should be 4 points" in ch30.check_chaikin([[1, 0], [3, 0], [4, 1]]).message
    assert "point 1" in ch30.check_chaikin([[1, 0], [3.5, 0], [4, 1], [4, 3]]).message

"""Tests of the chapter-25 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.bezier cannot make a checker accept a wrong answer)."""

import numpy as np
import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch25

# hand-worked answers
# (0,0),(2,4),(6,4),(8,0) at 1/2: level 1 (1,2),(4,4),(7,2); level 2 (2.5,3),(5.5,3); level 3 (4,3)
LEFT = [[0, 0], [1, 2], [2.5, 3], [4, 3]]
RIGHT = [[4, 3], [5.5, 3], [7, 2], [8, 0]]
REPARAM = 0.25 + 0.75 * 0.5
FLAT = 1.0                       # |(3,0) - (2,0)|
CROSS = 3                        # y - 0.5 along the polygon: -0.5, 2.5, -3.5, 0.5
C2 = [[4, 2], [5, 1], [5, -2]]   # Q1 = 2P3 - P2, Q2 = P1 - 4P2 + 4P3

CHECKERS = [
    (ch25.check_subdivision_left, LEFT),
    (ch25.check_reparametrised_parameter, REPARAM),
    (ch25.check_flatness, FLAT),
    (ch25.check_crossing_bound, CROSS),
    (ch25.check_c2_continuation, C2),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch25.SUBDIVIDE_CTRL.tolist() == [[0, 0], [2, 4], [6, 4], [8, 0]]
    assert (ch25.REPARAM_T, ch25.REPARAM_S) == (0.25, 0.5)
    assert ch25.FLATNESS_CTRL.tolist() == [[0, 0], [3, 0], [4, 0]]
    assert ch25.CROSSING_CTRL.tolist() == [[0, 0], [1, 3], [2, -3], [3, 1]] and ch25.CROSSING_LINE_Y == 0.5
    assert ch25.C2_CTRL.tolist() == [[0, 0], [1, 2], [3, 3], [4, 2]]


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r
    assert "Correct" in repr(r) and "Correct" in r._repr_html_()


@pytest.mark.parametrize("answer,reason", [
    (RIGHT, "right piece"),
    (LEFT[::-1], "reverse order"),
    ([[0, 0], [1, 2], [4, 4], [7, 2]], "midpoints of the control polygon"),
    ([[0, 0], [1, 2], [2.5, 3]], "four points"),
    ([[0, 0], [1, 2], [2.5, 3], [4, 3.5]], "point 3"),
])
def test_subdivision_wrong_answers_say_why(answer, reason):
    r = ch25.check_subdivision_left(answer)
    assert not r.correct and reason in r.message, r


@pytest.mark.parametrize("answer,reason", [(0.125, "LEFT piece"), (0.5, "t + (1 - t) s")])
def test_reparametrised_wrong_answers_say_why(answer, reason):
    r = ch25.check_reparametrised_parameter(answer)
    assert not r.correct and reason in r.message, r


@pytest.mark.parametrize("answer,reason", [(0, "not evenly spaced"), (2.0, "midpoint of P0 and P2")])
def test_flatness_wrong_answers_say_why(answer, reason):
    r = ch25.check_flatness(answer)
    assert not r.correct and reason in r.message, r


@pytest.mark.parametrize("answer,reason", [(4, "number of control points"), (3.5, "should be 3"),
                                           (2, "opposite sides")])
def test_crossing_wrong_answers_say_why(answer, reason):
    r = ch25.check_crossing_bound(answer)
    assert not r.correct and reason in r.message, r


def test_crossing_bound_degree_answer():
    # the degree equals the bound here, so 3 is right; the degree message needs a different count
    assert ch25.check_crossing_bound(3).correct


@pytest.mark.parametrize("answer,reason", [
    ([[4, 2], [5, 1], [7, 2]], "C1 but not C2"),
    ([[4, 2], [5, 1], [7, 2]], "Reflecting P1 through P3"),
    ([[4, 2], [6, 0], [5, -2]], "tangents differ"),
    ([[4, 3], [5, 1], [5, -2]], "do not even meet"),
    ([[4, 2], [5, 1]], "three points"),
])
def test_c2_wrong_answers_say_why(answer, reason):
    r = ch25.check_c2_continuation(answer)
    assert not r.correct and reason in r.message, r


def test_every_checker_has_a_problem_statement():
    assert set(ch25.PROBLEMS) == {c.__name__ for c, _ in CHECKERS}
    assert all("Goldman §25." in text for text in ch25.PROBLEMS.values())
    np.testing.assert_allclose(LEFT[-1], RIGHT[0])

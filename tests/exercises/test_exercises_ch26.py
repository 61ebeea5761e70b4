"""Tests of the chapter-26 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.blossom cannot make a checker accept a wrong answer), and each
recognised slip gets its own message."""

import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch26

# -- hand-worked answers ---------------------------------------------------------------------------
# P(t) = 2t^3 + 3t^2 - 6t + 1: p = 2 u1u2u3 + (u1u2 + u1u3 + u2u3) - 2 (u1 + u2 + u3) + 1;
# at (1, 2, 3): 2*6 + 11 - 2*6 + 1
POLAR = 12.0
# (0,0),(2,6),(6,6),(8,0) with u = 1/2, 1/2, 2: level 1 (1,3),(4,6),(7,3); level 2 (2.5,4.5),(5.5,4.5);
# level 3 -(2.5,4.5) + 2 (5.5,4.5)
BLOSSOM = [8.5, 4.5]
# (0,2),(2,0),(4,4) over [-1, 1]: p(-1,-1): level 1 at -1 (-2,4),(0,-4), level 2 at -1 (-4,12);
# p(-1,1) = (0,-4) (level 2 at 1); p(1,1) = P2
INTERVAL = [[-4, 12], [0, -4], [4, 4]]
# (0,0),(1,3),(4,4),(6,0): differences (1,3),(3,1),(2,-4); second differences (2,-2),(-1,-5);
# at t = 1/4: (1.25,-2.75); times n(n-1) = 6
SECOND = [7.5, -16.5]
# 2 - 3t + 6t^2 + t^3: P0 = 2, P1 = 2 - 3/3, P2 = 2 - 2*3/3 + 6/3, P3 = 2 - 3 + 6 + 1
TO_BEZIER = [2, 1, 2, 6]
# Bezier 1, 0, 0, 2: differences -1, 0, 2 / 1, 2 / 1; a = 1, 3*(-1), 3*1, 1*1
TO_MONOMIAL = [1, -3, 3, 1]

CHECKERS = [
    (ch26.check_polar_form, POLAR),
    (ch26.check_blossom_value, BLOSSOM),
    (ch26.check_interval_points, INTERVAL),
    (ch26.check_second_derivative, SECOND),
    (ch26.check_monomial_to_bezier, TO_BEZIER),
    (ch26.check_bezier_to_monomial, TO_MONOMIAL),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch26.POLAR_COEFFS.tolist() == [1, -6, 3, 2] and ch26.POLAR_ARGS == (1, 2, 3)
    assert ch26.BLOSSOM_CTRL.tolist() == [[0, 0], [2, 6], [6, 6], [8, 0]] and ch26.BLOSSOM_ARGS == (0.5, 0.5, 2)
    assert ch26.INTERVAL_CTRL.tolist() == [[0, 2], [2, 0], [4, 4]] and ch26.INTERVAL == (-1, 1)
    assert ch26.SECOND_CTRL.tolist() == [[0, 0], [1, 3], [4, 4], [6, 0]] and ch26.SECOND_T == 0.25
    assert ch26.MONOMIAL_COEFFS.tolist() == [2, -3, 6, 1]
    assert ch26.BEZIER_COEFFS.tolist() == [1, 0, 0, 2]


def test_statements_print_the_polynomials_as_written_in_the_hand_work():
    assert "P(t) = 2t^3 + 3t^2 - 6t + 1" in ch26.PROBLEMS["check_polar_form"]
    assert "t^3 + 6t^2 - 3t + 2" in ch26.PROBLEMS["check_monomial_to_bezier"]


def test_exercises_use_fresh_data_not_the_chapters_worked_examples():
    assert ch26.MONOMIAL_COEFFS.tolist() != [1, 3, -3, 2] and ch26.POLAR_COEFFS.tolist() != [1, 3, -3, 2]
    worked = [[0, 0], [1, 2.5], [3, 2.5], [4, 0.5]]
    assert ch26.BLOSSOM_CTRL.tolist() != worked and ch26.SECOND_CTRL.tolist() != worked


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


@pytest.mark.parametrize("checker,answer,reason", [
    (ch26.check_polar_form, 17, "average of the arguments"),
    (ch26.check_polar_form, 10, "without dividing by C(3, j)"),
    (ch26.check_polar_form, 13, "not symmetric"),
    (ch26.check_polar_form, 11, "too small"),
    (ch26.check_blossom_value, [8, 0], "average of the arguments"),
    (ch26.check_blossom_value, [4, 4.5], "curve point P(u1)"),
    (ch26.check_blossom_value, [-0.5, 4.5], "weights are exchanged"),
    (ch26.check_blossom_value, [5.5, 4.5], "level 2"),
    (ch26.check_blossom_value, [8.5, 4.5, 1], "one point"),
    (ch26.check_blossom_value, [8.5, 5.5], "off from p(0.5, 0.5, 2)"),
    (ch26.check_interval_points, [[-4, 12], [0, 2], [4, 4]], "points ON the curve"),
    (ch26.check_interval_points, [[4, 4], [0, -4], [-4, 12]], "reverse order"),
    (ch26.check_interval_points, [[-4, 12], [4, 4]], "three points"),
    (ch26.check_interval_points, [[-4, 12], [0, -3], [4, 4]], "point 1"),
    (ch26.check_second_derivative, [1.25, -2.75], "n(n-1) = 6 times it"),
    (ch26.check_second_derivative, [3.75, -8.25], "multiplied by n = 3"),
    (ch26.check_second_derivative, [7.5, -16], "a little off from P''(t)"),
    (ch26.check_monomial_to_bezier, [2, -3, 6, 1], "monomial coefficients"),
    (ch26.check_monomial_to_bezier, [2, -1, 2, 12], "divide by C(3, j)"),
    (ch26.check_monomial_to_bezier, [2, 1, 2, 7], "P3 is too large"),
    (ch26.check_monomial_to_bezier, [2, 1, 2], "four numbers"),
    (ch26.check_bezier_to_monomial, [1, -1, 1, 1], "forward differences"),
    (ch26.check_bezier_to_monomial, [1, 3, -3, 1], "reverse order"),
    (ch26.check_bezier_to_monomial, [1, -3, 2, 1], "a2 is too small"),
])
def test_wrong_answers_say_why(checker, answer, reason):
    r = checker(answer)
    assert not r.correct and r.answered and reason in r.message, r


def test_first_derivative_is_recognised():
    # P'(1/4) = 3 sum_k B_k^2(1/4) (P_k+1 - P_k), B^2(1/4) = (9, 6, 1)/16, differences (1,3),(3,1),(2,-4):
    # x = 3 (9 + 18 + 2)/16 = 87/16, y = 3 (27 + 6 - 4)/16 = 87/16
    r = ch26.check_second_derivative([87 / 16, 87 / 16])
    assert "first derivative" in r.message


def test_every_checker_has_a_problem_statement_and_slips():
    assert set(ch26.PROBLEMS) == {c.__name__ for c, _ in CHECKERS} == set(ch26.SLIPS)
    assert all("Goldman §26." in text for text in ch26.PROBLEMS.values())

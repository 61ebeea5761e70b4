"""Tests of the chapter-26 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.blossom cannot make a checker accept a wrong answer)."""

import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch26

# hand-worked answers
# p(1/4, 3/4) of (0,0),(2,4),(4,0): level 1 at 1/4: (0.5, 1), (2.5, 3); level 2 at 3/4: (2, 2.5)
BLOSSOM = [2, 2.5]
# 1 + 3t - 3t^2 + 2t^3: P_k = sum_j C(k,j)/C(3,j) a_j = 1, 1 + 1, 1 + 2 - 1, 1 + 3 - 3 + 2
MONO = [1, 2, 2, 3]
# over [1/2, 1]: p(1/2,1/2) = (2, 2), p(1/2, 1) = (3, 2), p(1, 1) = (4, 0)
INTERVAL = [[2, 2], [3, 2], [4, 0]]
# hodograph 3(P1-P0), 3(P2-P1), 3(P3-P2) = (3,9), (6,0), (3,-9); at 1/2: ((3+12+3)/4, (9-9)/4)
DERIV = [4.5, 0]
# 0, 1, 3: a0 = 0, a1 = 2(1 - 0) = 2, a2 = 3 - 2 + 0 = 1
COEFFS = [0, 2, 1]

CHECKERS = [
    (ch26.check_blossom_value, BLOSSOM),
    (ch26.check_monomial_to_bezier, MONO),
    (ch26.check_interval_points, INTERVAL),
    (ch26.check_derivative, DERIV),
    (ch26.check_bezier_to_monomial, COEFFS),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch26.BLOSSOM_CTRL.tolist() == [[0, 0], [2, 4], [4, 0]] and ch26.BLOSSOM_ARGS == (0.25, 0.75)
    assert ch26.MONOMIAL_COEFFS.tolist() == [1, 3, -3, 2]
    assert ch26.INTERVAL_CTRL.tolist() == [[0, 0], [2, 4], [4, 0]] and ch26.INTERVAL == (0.5, 1.0)
    assert ch26.DERIVATIVE_CTRL.tolist() == [[0, 0], [1, 3], [3, 3], [4, 0]] and ch26.DERIVATIVE_T == 0.5
    assert ch26.BEZIER_COEFFS.tolist() == [0, 1, 3]


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct and r.answered, r


@pytest.mark.parametrize("checker,answer,reason", [
    (ch26.check_blossom_value, [2, 2], "average"),
    (ch26.check_blossom_value, [1, 1.5], "same parameter at both levels"),       # P(1/4)
    (ch26.check_blossom_value, [2, 2.4], "point 0"),
    (ch26.check_blossom_value, [[2, 2.5]], "one point"),
    (ch26.check_monomial_to_bezier, [1, 3, -3, 2], "monomial coefficients themselves"),
    (ch26.check_monomial_to_bezier, [1, 4, 1, 3], "partial sums"),
    (ch26.check_monomial_to_bezier, [1, 2, 2], "four"),
    (ch26.check_interval_points, [[4, 0], [3, 2], [2, 2]], "reversed"),
    (ch26.check_interval_points, [[0, 0], [1, 2], [2, 2]], "[0, 0.5]"),
    (ch26.check_derivative, [1.5, 0], "n = 3 times"),
    (ch26.check_derivative, [2, 2.25], "the point P(0.5)"),
    (ch26.check_bezier_to_monomial, [0, 1, 1], "binomials"),
    (ch26.check_bezier_to_monomial, [0, 1, 3], "Bezier coefficients themselves"),
])
def test_wrong_answers_say_why(checker, answer, reason):
    r = checker(answer)
    assert not r.correct and reason in r.message, r


def test_every_checker_has_a_problem_statement():
    assert set(ch26.PROBLEMS) == {c.__name__ for c, _ in CHECKERS}
    assert all("Goldman §26." in text for text in ch26.PROBLEMS.values())

"""Tests of the chapter-3 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.fractals cannot make a checker accept a wrong answer)."""

import math

import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch03

TENT = [("TURN", 60), ("FORWARD", 1), ("TURN", -120), ("FORWARD", 1), ("TURN", 60)]
# hand-worked: 5 copies at 1/3 -> log 5 / log 3; scales 1/2, 1/4, 1/4: x + 2x^2 = 1, x = 1/2 -> D = 1;
# 3 (4/3)^10; K(4^-5) = (3^-5, 0) -> (4/3)^5
CHECKERS = [
    (ch03.check_equal_scales_dimension, math.log(5) / math.log(3)),
    (ch03.check_program_dimension, 1.0),
    (ch03.check_koch_length, 3 * (4 / 3) ** 10),
    (ch03.check_difference_quotient, (4 / 3) ** 5),
    (ch03.check_koch_base_case, TENT),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert (ch03.KOCH_LEVEL, ch03.KOCH_SIDE, ch03.QUOTIENT_POWER) == (10, 3.0, 5)
    assert ch03.UNEQUAL_PROGRAM.body == (("RESIZE", 0.5), ("RECURSE", None), ("MOVE", 1.0), ("RESIZE", 0.5),
                                         ("RECURSE", None), ("MOVE", 1.0), ("RECURSE", None), ("RESIZE", 4.0))
    assert set(ch03.PROBLEMS) == {c.__name__ for c, _ in CHECKERS}


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct, r.message


def test_other_good_base_cases_are_accepted():
    square_bump = [("FORWARD", 1 / 3), ("TURN", 90), ("FORWARD", 1 / 3), ("TURN", -90), ("FORWARD", 1 / 3),
                   ("TURN", -90), ("FORWARD", 1 / 3), ("TURN", 90), ("FORWARD", 1 / 3)]
    assert ch03.check_koch_base_case(square_bump).correct
    assert ch03.check_koch_base_case([("FORWARD", 0.5), ("FORWARD", 0.5)]).correct


@pytest.mark.parametrize("checker, answer, why", [
    (ch03.check_equal_scales_dimension, math.log(3) / math.log(5), "upside down"),
    (ch03.check_equal_scales_dimension, 5 / 3, "logarithms"),
    (ch03.check_equal_scales_dimension, 2, "9 copies"),
    (ch03.check_equal_scales_dimension, 1.2, "solves 5 (1/3)^D = 1"),
    (ch03.check_equal_scales_dimension, "D", "should be a number"),
    (ch03.check_program_dimension, math.log(3) / math.log(2), "scale 1/4"),
    (ch03.check_program_dimension, math.log(3) / math.log(4), "scale 1/2"),
    (ch03.check_program_dimension, 1.3, "product of the RESIZEs"),
    (ch03.check_koch_length, (4 / 3) ** 10, "unit segment"),
    (ch03.check_koch_length, 3 * (4 / 3) ** 9, "level 9"),
    (ch03.check_koch_length, 3 * (1 + 10 / 3), "geometrically"),
    (ch03.check_difference_quotient, (3 / 4) ** 5, "upside down"),
    (ch03.check_difference_quotient, 1, "straight segment"),
    (ch03.check_koch_base_case, TENT[:-1], "heading -60 degrees"),
    (ch03.check_koch_base_case, [("FORWARD", 2)], "ends at (2, 0)"),
    (ch03.check_koch_base_case, [("FORWARD", 1), ("RESIZE", 2)], "factor 2"),
    (ch03.check_koch_base_case, [("MOVE", 1)], "draws nothing"),
    (ch03.check_koch_base_case, [("FORWARD", 1)], "the book's base case"),
    (ch03.check_koch_base_case, [("RECURSE", None)], "not a base case"),
])
def test_typical_wrong_answers_are_explained(checker, answer, why):
    r = checker(answer)
    assert not r.correct and r.answered
    assert why in r.message, r.message

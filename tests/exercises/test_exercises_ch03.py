"""Tests of the chapter-3 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.fractals cannot make a checker accept a wrong answer); each
recognised slip gets its own reason."""

import math

import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch03

# Hand-worked answers:
# 3.1  8 copies at 1/4: 8 * 4^-D = 1, 4^D = 8, D = 3/2.
# 3.2  scales 1/4, 1/2, 1/2, 1/4: 2x + 2x^2 = 1 with x = 2^-D, x = (sqrt 3 - 1)/2, D = log2(1 + sqrt 3).
# 3.3  C(2^-j) at direction 45 j: 225 degrees (= -135) for j = 5.
# 3.4  the dip: TURN -45, FORWARD sqrt(1/2) to (1/2, -1/2), TURN 90, FORWARD sqrt(1/2) to (1, 0), TURN -45.
# 3.5  0.3 (1/sqrt 2)^6 = 0.3 / 8 = 0.0375.
DIP = [("TURN", -45), ("FORWARD", math.sqrt(0.5)), ("TURN", 90), ("FORWARD", math.sqrt(0.5)), ("TURN", -45)]
CHECKERS = [
    (ch03.check_equal_scales_dimension, 1.5),
    (ch03.check_program_dimension, math.log2(1 + math.sqrt(3))),
    (ch03.check_c_curve_chord, 225),
    (ch03.check_c_curve_base_case, DIP),
    (ch03.check_attraction_bound, 0.0375),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert (ch03.EQUAL_COPIES, ch03.EQUAL_SCALE) == (8, 0.25)
    assert ch03.TENT_PROGRAM.body == (("RESIZE", 0.25), ("RECURSE", None), ("TURN", 60.0), ("RESIZE", 2.0),
                                      ("RECURSE", None), ("TURN", -120.0), ("RECURSE", None), ("TURN", 60.0),
                                      ("RESIZE", 0.5), ("RECURSE", None), ("RESIZE", 4.0))
    assert ch03.TENT_PROGRAM.base == (("FORWARD", 1.0),)
    assert (ch03.CHORD_LEVEL, ch03.BOUND_START, ch03.BOUND_LEVEL) == (5, 0.3, 6)
    assert set(ch03.PROBLEMS) == {c.__name__ for c, _ in CHECKERS} == set(ch03.SLIPS)


def test_the_tent_program_is_well_posed():
    """The exercise's program moves the turtle as FORWARD 1 does (1/4 + 1/2 cos 60 + 1/2 cos 60 + 1/4 = 1),
    so its levels converge: every level ends at (1, 0) heading (1, 0)."""
    for level in range(4):
        t = ch03.TENT_PROGRAM.trace(level)
        assert t.point == pytest.approx([1, 0], abs=1e-12) and t.direction == pytest.approx([1, 0], abs=1e-12)


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct, r.message


def test_equivalent_and_rounded_answers_are_accepted():
    assert ch03.check_program_dimension(1.4500).correct       # 4 decimals
    assert not ch03.check_program_dimension(1.4498).correct
    assert ch03.check_c_curve_chord(-135).correct and ch03.check_c_curve_chord(585).correct
    square_bump = [("FORWARD", 1 / 3), ("TURN", 90), ("FORWARD", 1 / 3), ("TURN", -90), ("FORWARD", 1 / 3),
                   ("TURN", -90), ("FORWARD", 1 / 3), ("TURN", 90), ("FORWARD", 1 / 3)]
    assert ch03.check_c_curve_base_case(square_bump).correct
    assert ch03.check_c_curve_base_case([("FORWARD", 0.5), ("FORWARD", 0.5)]).correct
    assert ch03.check_attraction_bound(0.03750).correct


@pytest.mark.parametrize("checker, answer, why", [
    (ch03.check_equal_scales_dimension, math.log(4) / math.log(8), "upside down"),
    (ch03.check_equal_scales_dimension, 2, "divides the counts"),
    (ch03.check_equal_scales_dimension, math.log(8) / math.log(3), "Sierpinski carpet"),
    (ch03.check_equal_scales_dimension, 1.3, "too small"),
    (ch03.check_equal_scales_dimension, "D", "should be a number"),
    (ch03.check_program_dimension, 1.0, "all four copies as a quarter"),
    (ch03.check_program_dimension, 2.0, "all four copies as half"),
    (ch03.check_program_dimension, math.log(4) / math.log(3), "Koch curve's dimension"),
    (ch03.check_program_dimension, math.log(4) / math.log(8 / 3), "mean scale"),
    (ch03.check_program_dimension, math.log2(1 + math.sqrt(2)), "counts three copies"),
    (ch03.check_program_dimension, math.log2((1 + math.sqrt(5)) / 2), "each different scale once"),
    (ch03.check_program_dimension, 1.3, "too small"),
    (ch03.check_c_curve_chord, 45, "chord to C(1/2) only"),
    (ch03.check_c_curve_chord, 180, "chord to C(2^-4)"),
    (ch03.check_c_curve_chord, 270, "chord to C(2^-6)"),
    (ch03.check_c_curve_chord, 135, "turns clockwise"),
    (ch03.check_c_curve_chord, 0, "Koch curve"),
    (ch03.check_c_curve_chord, 200, "too small (mod 360)"),
    (ch03.check_c_curve_base_case, [("TURN", 45), ("FORWARD", 1)], "heading 45 degrees"),
    (ch03.check_c_curve_base_case, [("RESIZE", 2), ("FORWARD", 0.5)], "step by a factor 2"),
    (ch03.check_c_curve_base_case, [("FORWARD", 2)], "ends at (2, 0)"),
    (ch03.check_c_curve_base_case, [("MOVE", 1)], "draws nothing"),
    (ch03.check_c_curve_base_case, [("FORWARD", 1)], "the book's base case"),
    (ch03.check_c_curve_base_case, [("RECURSE", None)], "not a base case"),
    (ch03.check_c_curve_base_case, "FORWARD 1", "not a base case"),
    (ch03.check_attraction_bound, 0.3 / 3 ** 6, "a third per level"),
    (ch03.check_attraction_bound, 0.3 / 2 ** 6, "a half per level"),
    (ch03.check_attraction_bound, 0.3 / 2 ** 2.5, "one level fewer"),
    (ch03.check_attraction_bound, 0.3 / 2 ** 3.5, "one level more"),
    (ch03.check_attraction_bound, 2.4, "do not add up"),
    (ch03.check_attraction_bound, 0.3, "does shrink"),
    (ch03.check_attraction_bound, 0.05, "too large"),
])
def test_typical_wrong_answers_are_explained(checker, answer, why):
    r = checker(answer)
    assert not r.correct and r.answered
    assert why in r.message, r.message

"""Tests of the chapter-2 exercise checkers.  Right answers are worked by hand from the problem
constants (so a bug in goldman_lib.fractals cannot make a checker accept a wrong answer)."""

import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch02

R = ("RECURSE", None)
# hand-worked: 100 = 360 * 5/18 -> period 18; a star closing after exactly 9: 360 p / 9, gcd(p, 9) = 1,
# p not 1 or 8 -> 80, 160, 200, 280; snowflake 3 * 4**5; tree 2**6 - 1
SQUARE_KOCH = [("RESIZE", 1 / 3), R, ("TURN", 90), R, ("TURN", -90), R, ("TURN", -90), R, ("TURN", 90), R,
               ("RESIZE", 3)]
CHECKERS = [
    (ch02.check_loop_period, 18),
    (ch02.check_star_angle, 160),
    (ch02.check_snowflake_segments, 3072),
    (ch02.check_tree_branches, 63),
    (ch02.check_square_koch_body, SQUARE_KOCH),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert (ch02.LOOP_ANGLE, ch02.STAR_PASSES, ch02.SNOWFLAKE_LEVEL, ch02.TREE_LEVEL) == (100, 9, 5, 5)
    assert set(ch02.PROBLEMS) == {c.__name__ for c, _ in CHECKERS}


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct, r.message


@pytest.mark.parametrize("a", [80, 200, 280, 80.004])
def test_every_star_angle_is_accepted(a):
    assert ch02.check_star_angle(a).correct


@pytest.mark.parametrize("checker, answer, why", [
    (ch02.check_loop_period, 36, "already back after fewer"),
    (ch02.check_loop_period, 3.6, "not a whole number"),
    (ch02.check_loop_period, 5, "winding number"),
    (ch02.check_loop_period, 7, "not a multiple of 360"),
    (ch02.check_loop_period, "many", "should be a whole number"),
    (ch02.check_star_angle, 120, "only 3 passes"),
    (ch02.check_star_angle, 40, "convex regular 9-gon"),
    (ch02.check_star_angle, 100, "does not close after 9"),
    (ch02.check_snowflake_segments, 1024, "one side"),
    (ch02.check_snowflake_segments, 768, "level 4"),
    (ch02.check_snowflake_segments, 3 * 5**5, "not 5"),
    (ch02.check_tree_branches, 32, "tips only"),
    (ch02.check_tree_branches, 64, "one too many"),
    (ch02.check_tree_branches, 31, "level 4"),
    (ch02.check_square_koch_body, SQUARE_KOCH[:-1], "must end with RESIZE 3"),
    (ch02.check_square_koch_body, SQUARE_KOCH[:3] + SQUARE_KOCH[5:], "makes 4 recursive calls"),
    (ch02.check_square_koch_body, [(c, -v if c == "TURN" else v) for c, v in SQUARE_KOCH], "points down"),
    (ch02.check_square_koch_body, [("RESIZE", 0.5)] + SQUARE_KOCH[1:-1] + [("RESIZE", 2)], "should end at (1, 0)"),
    (ch02.check_square_koch_body, [("FORWARD", 1)], "not a program body"),
    (ch02.check_square_koch_body, "RESIZE 1/3", "not a program body"),
])
def test_typical_wrong_answers_are_explained(checker, answer, why):
    r = checker(answer)
    assert not r.correct and r.answered
    assert why in r.message, r.message

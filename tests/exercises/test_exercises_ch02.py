"""Tests of the chapter-2 exercise checkers and the programming-project checker.  Right answers are
worked by hand from the problem constants (so a bug in goldman_lib.fractals cannot make a checker
accept a wrong answer); each recognised slip gets its own reason."""

import math

import pytest

from goldman_lib.exercises import Result
from goldman_lib.exercises import ch02

# Hand-worked answers:
# 2.1  one pass turns 60 + 24 = 84 = 360 * 7/30 (gcd(84, 360) = 12): period 30, winding 7.
# 2.2  a star closing after exactly 9 passes: 360 p / 9 with gcd(p, 9) = 1, p not 1 or 8: 80, 160, 200, 280.
# 2.3  one pass: FORWARD 1 to (1, 0), TURN 90, FORWARD 1 to (1, 1), TURN -30: d = 1 + i, T = 60.
#      1 - e^(i60) = 1/2 - i sqrt(3)/2 = e^(-i60), so c = (1 + i) e^(i60) = ((1 - sqrt 3)/2, (1 + sqrt 3)/2).
# 2.4  along a side each copy reaches r + r cos 45 from its corner; two copies meet mid-side:
#      2 r (1 + sqrt(2)/2) = 1, r = 1 / (2 + sqrt 2) = 0.2928932...
# 2.5  c(0) = 1, c(n) = 5 + 2 c(n-1): 1, 7, 19, 43, 91, 187, 379.
CENTRE = ((1 - math.sqrt(3)) / 2, (1 + math.sqrt(3)) / 2)
CHECKERS = [
    (ch02.check_loop_period, 30),
    (ch02.check_star_angle, 160),
    (ch02.check_loop_centre, CENTRE),
    (ch02.check_gasket_scale, 1 / (2 + math.sqrt(2))),
    (ch02.check_c_curve_commands, 379),
]


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch02.LOOP_PASS == "FORWARD 1 TURN 60 FORWARD 2 TURN 24"
    assert ch02.CENTRE_PASS == "FORWARD 1 TURN 90 FORWARD 1 TURN -30"
    assert (ch02.STAR_PASSES, ch02.GASKET_SIDES, ch02.C_CURVE_LEVEL) == (9, 8, 6)
    assert set(ch02.PROBLEMS) == {c.__name__ for c, _ in CHECKERS} == set(ch02.SLIPS)


@pytest.mark.parametrize("checker,answer", CHECKERS, ids=[c.__name__ for c, _ in CHECKERS])
def test_right_answer_is_correct(checker, answer):
    r = checker(answer)
    assert isinstance(r, Result) and r.correct, r.message


@pytest.mark.parametrize("a", [80, 200, 280, 80.004])
def test_every_star_angle_is_accepted(a):
    assert ch02.check_star_angle(a).correct


def test_rounded_answers_are_accepted():
    assert ch02.check_loop_centre((-0.3660, 1.3660)).correct
    assert ch02.check_gasket_scale(0.2929).correct


@pytest.mark.parametrize("checker, answer, why", [
    (ch02.check_loop_period, 6, "period of TURN 60 alone"),
    (ch02.check_loop_period, 15, "period of TURN 24 alone"),
    (ch02.check_loop_period, 60, "already back after fewer"),
    (ch02.check_loop_period, 360 / 84, "not a whole number"),
    (ch02.check_loop_period, 7, "winding number"),
    (ch02.check_loop_period, 11, "not a multiple of 360"),
    (ch02.check_loop_period, "many", "should be a whole number"),
    (ch02.check_star_angle, 120, "only 3 passes"),
    (ch02.check_star_angle, 40, "convex regular 9-gon"),
    (ch02.check_star_angle, 320, "convex regular 9-gon"),
    (ch02.check_star_angle, 100, "does not close after 9"),
    (ch02.check_loop_centre, ((1 + math.sqrt(3)) / 2, (1 - math.sqrt(3)) / 2), "turned clockwise"),
    (ch02.check_loop_centre, (0.5, 0.5), "midpoint"),
    (ch02.check_loop_centre, (1, 1), "where the first pass ends"),
    (ch02.check_loop_centre, ((1 - math.sqrt(3)) / 2, -(1 + math.sqrt(3)) / 2), "mirror image"),
    (ch02.check_loop_centre, (0, 1), "off"),
    (ch02.check_loop_centre, (1, 2, 3), "one point (x, y)"),
    (ch02.check_gasket_scale, 0.5, "Sierpinski gasket"),
    (ch02.check_gasket_scale, 1 / 3, "hexagonal gasket"),
    (ch02.check_gasket_scale, 1 / (1 + math.sqrt(2) / 2), "two copies on each side"),
    (ch02.check_gasket_scale, 1 / (1 + math.sqrt(2)), "whole width of a copy"),
    (ch02.check_gasket_scale, 1 / (2 + 2 * math.sqrt(2)), "whole width of a copy"),
    (ch02.check_gasket_scale, 0.3, "a little too large"),
    (ch02.check_c_curve_commands, 64, "FORWARDs only"),
    (ch02.check_c_curve_commands, 315, "TURNs and RESIZEs only"),
    (ch02.check_c_curve_commands, 187, "level 5"),
    (ch02.check_c_curve_commands, 763, "level 7"),
    (ch02.check_c_curve_commands, 31, "doubles"),
    (ch02.check_c_curve_commands, 400, "too large"),
])
def test_typical_wrong_answers_are_explained(checker, answer, why):
    r = checker(answer)
    assert not r.correct and r.answered
    assert why in r.message, r.message


# -- the programming project -----------------------------------------------------------------------

def _body(copy):
    return ([("RESIZE", 1 / 3)] + copy + [("TURN", 90)] + copy + [("TURN", -90)] + copy + [("TURN", -90)] + copy
            + [("TURN", 90)] + copy + [("RESIZE", 3)])


def quadratic_koch(level):
    if level == 0:
        return [("FORWARD", 1)]
    return _body(quadratic_koch(level - 1))


def test_project_accepts_the_recursive_program():
    r = ch02.check_quadratic_koch_project(quadratic_koch)
    assert r.correct, r
    assert "all 7 cases" in r.message and "the base case (level 0)" in r.message


def test_project_hand_worked_level_one():
    """Level 1 by hand: thirds forward, up, forward, down, forward (the bump on the left)."""
    assert quadratic_koch(1) == [("RESIZE", 1 / 3), ("FORWARD", 1), ("TURN", 90), ("FORWARD", 1), ("TURN", -90),
                                 ("FORWARD", 1), ("TURN", -90), ("FORWARD", 1), ("TURN", 90), ("FORWARD", 1),
                                 ("RESIZE", 3)]
    assert ch02.check_quadratic_koch_project(lambda n: quadratic_koch(1) if n == 1 else quadratic_koch(n)).correct


def test_project_names_the_level_a_function_off_by_one_level_fails():
    def off_by_one(level):           # the base case one level too low: level n draws level n + 1
        if level < 0:
            return [("FORWARD", 1)]
        return _body(off_by_one(level - 1))

    r = ch02.check_quadratic_koch_project(off_by_one)
    assert r.answered and not r.correct
    assert "case 1 of 7 (level 0 (the base case))" in r.message
    assert "at level 0 your curve has 5 segments, expected 1" in r.message


def test_project_off_by_one_from_level_two_on():
    def late(level):                  # level 1 right, then each level draws the one below it
        if level <= 1:
            return _body([("FORWARD", 1)]) if level == 1 else [("FORWARD", 1)]
        return _body(late(level - 2))

    r = ch02.check_quadratic_koch_project(late)
    assert "case 3 of 7 (level 2)" in r.message and "at level 2 your curve has 5 segments, expected 25" in r.message


def test_project_explains_a_missing_resize_and_a_mirrored_bump():
    def no_restore(level):
        return [("FORWARD", 1)] if level == 0 else _body(no_restore(level - 1))[:-1]

    r = ch02.check_quadratic_koch_project(no_restore)
    assert "case 2 of 7 (level 1)" in r.message and "restore the step with RESIZE 3" in r.message

    def mirrored(level):
        return [(c, -v if c == "TURN" else v) for c, v in quadratic_koch(level)]

    r = ch02.check_quadratic_koch_project(mirrored)
    assert "case 2 of 7 (level 1)" in r.message and "bumps point to the turtle's right" in r.message


def test_project_reports_the_first_vertex_off_and_wrong_kinds():
    def wrong_scale(level):
        return [(c, 0.5 if c == "RESIZE" and v < 1 else (2 if c == "RESIZE" else v)) for c, v in quadratic_koch(level)]

    r = ch02.check_quadratic_koch_project(wrong_scale)
    assert "case 2 of 7 (level 1)" in r.message and "vertex 1 of your curve is" in r.message

    r = ch02.check_quadratic_koch_project(lambda n: [("RESIZE", 1 / 3), ("RECURSE", None), ("RESIZE", 3)])
    assert "entry 1 is a RECURSE" in r.message
    r = ch02.check_quadratic_koch_project(lambda n: "FORWARD 1")
    assert "list of (command, value) pairs" in r.message
    r = ch02.check_quadratic_koch_project(lambda n: [("JUMP", 1)])
    assert "use FORWARD, MOVE, TURN or RESIZE" in r.message
    r = ch02.check_quadratic_koch_project(lambda n: [("MOVE", 1)])
    assert "draw nothing" in r.message


def test_project_reports_a_crash_with_the_learners_line():
    def crashing(level):
        if level == 0:
            return [("FORWARD", 1)]
        return crashing(level - 1)[7]

    r = ch02.check_quadratic_koch_project(crashing)
    assert r.answered and not r.correct
    assert "case 2 of 7 (level 1): your function raised IndexError" in r.message
    assert "return crashing(level - 1)[7]" in r.message


def test_project_unanswered():
    def starter(level):
        ...

    assert not ch02.check_quadratic_koch_project(starter).answered
    assert not ch02.check_quadratic_koch_project(None).answered

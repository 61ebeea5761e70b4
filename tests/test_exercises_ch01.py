"""Chapter 1 checkers: right for the worked solutions, wrong with the reason for typical slips,
"not answered" for None and ...."""

import pytest

from goldman_lib.exercises import ch01


def _assert_wrong(result, *fragments):
    assert result.answered and not result.correct, result
    for f in fragments:
        assert f in result.message, (f, result.message)


@pytest.mark.parametrize("program", ["REPEAT 6 [FORWARD 2 TURN 60]", "REPEAT 6 [FORWARD 2 TURN -60]",
                                     "repeat 6 [forward 1 forward 1 turn 60]",
                                     "TURN 30 REPEAT 6 [FORWARD 2 TURN 60]",
                                     "RESIZE 2 REPEAT 6 [FORWARD 1 TURN 60]"])
def test_hexagon_worked_solutions(program):
    result = ch01.exercise_hexagon(program)
    assert result.correct, result
    assert "6 sides" in result.message


def test_hexagon_typical_mistakes():
    _assert_wrong(ch01.exercise_hexagon("REPEAT 5 [FORWARD 2 TURN 60]"),
                  "your path ends 2 away from where it started: it does not close")
    _assert_wrong(ch01.exercise_hexagon("REPEAT 6 [FORWARD 2 TURN 72]"), "it does not close")
    _assert_wrong(ch01.exercise_hexagon("REPEAT 5 [FORWARD 2 TURN 72]"), "you drew 5 sides, a hexagon needs 6")
    _assert_wrong(ch01.exercise_hexagon("REPEAT 6 [FORWARD 1 TURN 60]"),
                  "side 1 has length 1; every side should be 2")
    _assert_wrong(ch01.exercise_hexagon("REPEAT 12 [FORWARD 2 TURN 60]"), "you drew 12 sides", "round 2 times")
    _assert_wrong(ch01.exercise_hexagon("REPEAT 3 [FORWARD 2 TURN 90 FORWARD 2 TURN 30]"),
                  "turns by the same 60 degrees")
    _assert_wrong(ch01.exercise_hexagon("REPEAT 6 [FORWARD 2 TURN 60"),
                  "the program does not run: line 1, column 28: expected ']'")
    _assert_wrong(ch01.exercise_hexagon("REPEAT 6 [MOVE 2 TURN 60]"), "draws nothing")
    _assert_wrong(ch01.exercise_hexagon("REPEAT 3 [FORWARD 2 TURN 60 MOVE 2 TURN 60]"), "separate strokes")
    _assert_wrong(ch01.exercise_hexagon(6), "should be a turtle program in quotes")


def test_five_pointed_star():
    assert ch01.exercise_five_pointed_star("REPEAT 5 [FORWARD 1 TURN 144]").correct
    assert ch01.exercise_five_pointed_star("REPEAT 5 [FORWARD 1 TURN -144]").correct
    _assert_wrong(ch01.exercise_five_pointed_star("REPEAT 5 [FORWARD 1 TURN 72]"),
                  "turns by 72, 72, 72, 72, 72 degrees", "144")
    _assert_wrong(ch01.exercise_five_pointed_star("REPEAT 5 [FORWARD 1 TURN 36]"), "does not close")
    _assert_wrong(ch01.exercise_five_pointed_star("REPEAT 10 [FORWARD 1 TURN 144]"), "round 2 times")


def test_star_angle():
    assert ch01.exercise_star_angle(360 * 3 / 7).correct
    assert ch01.exercise_star_angle(154.29).correct           # within 0.01 degree
    assert ch01.exercise_star_angle(-360 * 3 / 7).correct     # clockwise: the mirror image, same star
    assert ch01.exercise_star_angle(360 * 3 / 7 + 360).correct
    assert ch01.exercise_star_angle(144, n=5, k=2).correct
    _assert_wrong(ch01.exercise_star_angle(360 / 7), "draws the regular 7-gon {7/1}", "every 3rd point")
    _assert_wrong(ch01.exercise_star_angle(180 - 360 * 3 / 7), "angle inside each point", "180 minus")
    _assert_wrong(ch01.exercise_star_angle(100), "should be 154.3, you gave 100")
    _assert_wrong(ch01.exercise_star_angle("wide"), "should be a number of degrees")


def test_final_position():
    assert ch01.exercise_final_position((-1, 3)).correct
    assert ch01.exercise_final_position([-1.0, 3.0]).correct
    _assert_wrong(ch01.exercise_final_position((-1, 2)), "RESIZE 2 doubles w")
    _assert_wrong(ch01.exercise_final_position((-1, -3)), "counterclockwise")
    _assert_wrong(ch01.exercise_final_position((2, 3)), "MOVE 3 moves the turtle")
    _assert_wrong(ch01.exercise_final_position((0, 0)), "should be (-1, 3), you gave (0, 0)")
    _assert_wrong(ch01.exercise_final_position((1, 2, 3)), "two numbers")


def test_total_turning():
    assert ch01.exercise_total_turning(1080).correct
    _assert_wrong(ch01.exercise_total_turning(360), "simple polygon", "3 * 360 = 1080")
    _assert_wrong(ch01.exercise_total_turning(360 * 3 / 7), "the turn at one corner")
    _assert_wrong(ch01.exercise_total_turning(720), "should be 1080, you gave 720")

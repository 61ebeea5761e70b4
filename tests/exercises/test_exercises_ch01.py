"""Chapter 1 checkers: right for answers worked by hand, wrong with the specific reason for each
recognised slip.  (None / ... / garbage are checked for every chapter in tests/exercises/test_exercises.py.)"""

import math

import pytest

from goldman_lib.exercises import ch01


def _assert_wrong(result, *fragments):
    assert result.answered and not result.correct, result
    for f in fragments:
        assert f in result.message, (f, result.message)


def test_problem_constants_are_what_the_hand_answers_assume():
    assert ch01.STATE_PROGRAM == "FORWARD 2 TURN 90 FORWARD 1 TURN 90 MOVE 3 RESIZE 2 TURN -90 FORWARD 1"
    assert (ch01.POLYGON_INTERIOR, ch01.POLYGON_SIDE) == (140, 1.5)
    assert (ch01.STAR_N, ch01.STAR_K, ch01.STAR_SIDE) == (10, 3, 2)
    assert (ch01.CIRCLE_RADIUS, ch01.CIRCLE_SIDES) == (2, 20)
    assert ch01.SPIRAL_PROGRAM == "REPEAT 8 [FORWARD 1 TURN 45 RESIZE 1.5]"
    assert ch01.ROSETTE_COPIES == 8
    assert set(ch01.PROBLEMS) == set(ch01.SLIPS)


# -- 1.1 the state ---------------------------------------------------------------------------------
# By hand: (0,0),(1,0) -F2-> (2,0) -T90-> w=(0,1) -F1-> (2,1) -T90-> w=(-1,0) -M3-> (-1,1)
# -R2-> w=(-2,0) -T-90-> w=(0,2) -F1-> (-1,3).

def test_final_state():
    assert ch01.check_final_state([[-1, 3], [0, 2]]).correct
    assert ch01.check_final_state(((-1.0, 3.0), (0.0, 2.0))).correct
    _assert_wrong(ch01.check_final_state([[-1, 2], [0, 1]]), "without RESIZE 2", "multiplies w by s")
    _assert_wrong(ch01.check_final_state([[-1, -3], [0, -2]]), "every TURN the other way", "counterclockwise")
    _assert_wrong(ch01.check_final_state([[2, 3], [0, 2]]), "MOVE 3 left out", "without drawing")
    _assert_wrong(ch01.check_final_state([[-1, 3], [0, 1]]), "P is right, but w is not")
    _assert_wrong(ch01.check_final_state([[0, 3], [0, 2]]), "w is right, but P is off")
    _assert_wrong(ch01.check_final_state([-1, 3]), "give both parts of the state")
    _assert_wrong(ch01.check_final_state([[5, 5], [5, 5]]), "both P and w are off")
    _assert_wrong(ch01.check_final_state([1, 2, 3]), "shape (3,)")


# -- 1.2 polygon from its interior angle: 360 / (180 - 140) = 9 sides, turn 40 ----------------------

@pytest.mark.parametrize("program", ["REPEAT 9 [FORWARD 1.5 TURN 40]", "REPEAT 9 [FORWARD 1.5 TURN -40]",
                                     "resize 1.5 repeat 9 [forward 1 turn 40]",
                                     "REPEAT 9 [FORWARD 0.75 FORWARD 0.75 TURN 40]"])
def test_polygon_right(program):
    r = ch01.check_polygon_program(program)
    assert r.correct, r
    assert "9-gon" in r.message


def test_polygon_slips():
    _assert_wrong(ch01.check_polygon_program("REPEAT 9 [FORWARD 1.5 TURN 140]"), "the interior angle",
                  "exterior angle")
    _assert_wrong(ch01.check_polygon_program("REPEAT 8 [FORWARD 1.5 TURN 45]"), "regular 8-gon", "135 degrees")
    _assert_wrong(ch01.check_polygon_program("REPEAT 9 [FORWARD 1 TURN 40]"), "side 1 has length 1")
    _assert_wrong(ch01.check_polygon_program("REPEAT 8 [FORWARD 1.5 TURN 40]"), "does not close")
    _assert_wrong(ch01.check_polygon_program("REPEAT 9 [FORWARD 1.5 TURN 80]"), "winds round 2 times", "a star")
    _assert_wrong(ch01.check_polygon_program("REPEAT 9 [MOVE 1.5 TURN 40]"), "draws nothing")
    _assert_wrong(ch01.check_polygon_program("REPEAT 9 [FORWARD 1.5 TURN 40"), "does not run", "line 1")
    _assert_wrong(ch01.check_polygon_program(9), "a turtle program in quotes")


# -- 1.3 the star {10/3}: turn 360 * 3 / 10 = 108 ---------------------------------------------------

def test_star_right():
    assert ch01.check_star_program("REPEAT 10 [FORWARD 2 TURN 108]").correct
    assert ch01.check_star_program("REPEAT 10 [FORWARD 2 TURN -108]").correct
    assert ch01.check_star_program("REPEAT 5 [FORWARD 2 TURN 108 FORWARD 2 TURN 108]").correct


def test_star_slips():
    _assert_wrong(ch01.check_star_program("REPEAT 10 [FORWARD 2 TURN 36]"), "regular decagon {10/1}",
                  "3 times as large")
    _assert_wrong(ch01.check_star_program("REPEAT 10 [FORWARD 2 TURN 72]"), "angle inside each point",
                  "pentagon {5/1} twice")
    _assert_wrong(ch01.check_star_program("REPEAT 20 [FORWARD 2 TURN 108]"), "20 sides", "round 2 times")
    _assert_wrong(ch01.check_star_program("REPEAT 10 [FORWARD 1 TURN 108]"), "side 1 has length 1")
    _assert_wrong(ch01.check_star_program("REPEAT 7 [FORWARD 2 TURN 108]"), "does not close")
    _assert_wrong(ch01.check_star_program("REPEAT 10 [FORWARD 2 TURN 144]"), "winds round its centre 4 times")
    _assert_wrong(ch01.check_star_program("REPEAT 5 [FORWARD 2 TURN 144]"), "5 sides")
    _assert_wrong(ch01.check_star_program("REPEAT 2 [FORWARD 2 TURN 108 MOVE 2]"), "separate strokes")


# -- 1.4 the circle's step: d = 2 r sin(180/20) = 4 sin 9 deg = 0.6257378... -----------------------

def test_circle_step():
    assert ch01.check_circle_step(0.625738).correct
    assert ch01.check_circle_step(0.6257).correct          # 4 decimals
    _assert_wrong(ch01.check_circle_step(2 * math.pi * 2 / 20), "arc length", "chord")
    _assert_wrong(ch01.check_circle_step(0.312869), "half the chord")
    _assert_wrong(ch01.check_circle_step(1.236068), "sine of the whole central angle")
    _assert_wrong(ch01.check_circle_step(4 * math.sin(9)), "radians")
    _assert_wrong(ch01.check_circle_step(0.6), "a little too small", "chord")


# -- 1.5 the spiral's ink: 1 + 1.5 + ... + 1.5^7 = (1.5^8 - 1) / 0.5 = 49.2578125 --------------------

def test_spiral_ink():
    assert ch01.check_spiral_ink(49.2578125).correct
    assert ch01.check_spiral_ink(49.258).correct
    _assert_wrong(ch01.check_spiral_ink(8), "8 sides of length 1")
    _assert_wrong(ch01.check_spiral_ink(74.88671875), "9th side")
    _assert_wrong(ch01.check_spiral_ink(17.0859375), "last side alone")
    _assert_wrong(ch01.check_spiral_ink(25.62890625), "step after the loop")
    _assert_wrong(ch01.check_spiral_ink(22), "does not add 0.5")
    _assert_wrong(ch01.check_spiral_ink(50), "a little too large", "geometric series")


# -- 1.6 the rosette: REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90] TURN 45] --------------------------------

@pytest.mark.parametrize("program", ["REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90] TURN 45]",
                                     "REPEAT 8 [TURN 45 REPEAT 4 [FORWARD 1 TURN 90]]",
                                     "REPEAT 8 [REPEAT 4 [FORWARD 1 TURN -90] TURN -45]",
                                     "REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90] TURN 225]"])
def test_rosette_right(program):
    r = ch01.check_rosette_program(program)
    assert r.correct, r


def test_rosette_slips():
    _assert_wrong(ch01.check_rosette_program("REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90]] TURN 45"),
                  "one square, 8 times over", "inside the outer REPEAT")
    _assert_wrong(ch01.check_rosette_program("REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90] TURN 90]"),
                  "only 4 different squares")
    _assert_wrong(ch01.check_rosette_program("REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90] TURN 45] TURN 10"),
                  "the drawing is right", "not in its initial state")
    _assert_wrong(ch01.check_rosette_program("REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90] TURN 40]"),
                  "away from the rosette")
    _assert_wrong(ch01.check_rosette_program("REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90] TURN 45"),
                  "does not run", "expected ']'")
    _assert_wrong(ch01.check_rosette_program("TURN 90"), "draws nothing")


def test_sides_of_merges_collinear_steps_across_the_start():
    lengths, turns = ch01.sides_of([[1, 0], [2, 0], [2, 2], [0, 2], [0, 0], [1, 0]])
    assert lengths.tolist() == [2.0, 2.0, 2.0, 2.0] and turns.tolist() == [90.0, 90.0, 90.0, 90.0]

"""Chapter 5 checkers: right for the worked solutions and for other correct programs, wrong with
the reason for typical slips (the interpreter's own message for programs that do not run),
"not answered" for None and ...."""

import pytest

from goldman_lib import codo
from goldman_lib.exercises import ch05


def _assert_wrong(result, *fragments):
    assert result.answered and not result.correct, result
    for f in fragments:
        assert f in result.message, (f, result.message)


CHECKERS = [ch05.exercise_hexagon_program, ch05.exercise_one_third, ch05.exercise_expression_types,
            ch05.exercise_image_program, ch05.exercise_sheared_turn]


def test_problems_listed():
    assert set(ch05.PROBLEMS) == {c.__name__ for c in CHECKERS}


HEXAGON = """C = point(0, 0)
P = point(1, 0)
R = rotate(C, 60)
REPEAT 6 [ CONNECT P, R(P); P = R(P) ]"""


@pytest.mark.parametrize("program", [
    HEXAGON,
    HEXAGON.replace("60", "-60"),
    "C = point(0, 0)\nF = polyline(point(1, 0), point(0.5, sqrt(3)/2))\nREPEAT 6 [ DRAW F; F = rotate(C, 60)(F) ]",
    "CONNECT point(1,0), point(cos(60), sin(60)), point(cos(120), sin(120)), point(-1, 0), point(cos(240), sin(240)),"
    " point(cos(300), sin(300)), point(1, 0)",
])
def test_hexagon_program_right(program):
    result = ch05.exercise_hexagon_program(program)
    assert result.correct, result


def test_hexagon_program_wrong():
    _assert_wrong(ch05.exercise_hexagon_program(HEXAGON.replace("60", "72").replace("6 [", "5 [")),
                  "5 different segments, 0 of them sides")
    _assert_wrong(ch05.exercise_hexagon_program(HEXAGON.replace("6 [", "5 [")), "1 of the 6 sides is missing")
    _assert_wrong(ch05.exercise_hexagon_program(HEXAGON.replace("point(1, 0)", "point(2, 0)")),
                  "none of them is a side", "position and size")
    _assert_wrong(ch05.exercise_hexagon_program("P = point(0, 0)\nCONNECT P, P + P"),
                  "does not run: line 2, column 14, at '+'", "weights add up to 2")
    _assert_wrong(ch05.exercise_hexagon_program("P = point(0, 0)"), "draws nothing")
    _assert_wrong(ch05.exercise_hexagon_program(6), "CODO program in quotes")


@pytest.mark.parametrize("expr", ["P + (Q - P)/3", "(2*P + Q)/3", "2/3*P + 1/3*Q", "Q - 2*(Q - P)/3",
                                  "P + 1/3*(Q - P)"])
def test_one_third_right(expr):
    assert ch05.exercise_one_third(expr).correct


def test_one_third_wrong():
    _assert_wrong(ch05.exercise_one_third("P + Q/3"), "does not run: line 1, column 3, at '+'", "1.33333")
    _assert_wrong(ch05.exercise_one_third("(P + Q)/3"), "at '/'", "0.666667")
    _assert_wrong(ch05.exercise_one_third("(Q - P)/3"), "is a vector, not a point")
    _assert_wrong(ch05.exercise_one_third("P + 2*(Q - P)/3"), "two thirds of the way")
    _assert_wrong(ch05.exercise_one_third("point(3, 3)"), "write it in terms of P and Q")
    _assert_wrong(ch05.exercise_one_third("(P + Q)/2"), "one third of the way is (3, 3)")
    _assert_wrong(ch05.exercise_one_third(1 / 3), "CODO expression in quotes")


RIGHT_TYPES = {"P - Q": "vector", "P + v": "point", "P + Q": "illegal", "(P + Q + R)/3": "point",
               "P - 2*Q + R": "vector", "2*P - Q": "point", "3*v - P": "illegal"}


def test_expression_types():
    assert ch05.exercise_expression_types(RIGHT_TYPES).correct
    assert ch05.exercise_expression_types({k: v.upper() for k, v in RIGHT_TYPES.items()}).correct
    _assert_wrong(ch05.exercise_expression_types({**RIGHT_TYPES, "P + Q": "point"}), "P + Q is illegal",
                  "weights add up to 2")
    _assert_wrong(ch05.exercise_expression_types({**RIGHT_TYPES, "P - 2*Q + R": "illegal"}),
                  "P - 2*Q + R is a vector: the weights of its points add up to 0")
    _assert_wrong(ch05.exercise_expression_types({**RIGHT_TYPES, "2*P - Q": "illegal"}), "is a point")
    _assert_wrong(ch05.exercise_expression_types({**RIGHT_TYPES, "3*v - P": "vector"}), "weights add up to -1")
    _assert_wrong(ch05.exercise_expression_types({"P - Q": "vector"}), "is missing")
    _assert_wrong(ch05.exercise_expression_types({**RIGHT_TYPES, "P - Q": "arrow"}), "'point', 'vector' or 'illegal'")
    _assert_wrong(ch05.exercise_expression_types(["vector"]), "should be a dict")


IMAGE = """M = affine(point(0, 0), point(1, 0), point(0, 1), point(1, 0), point(3, 1), point(2, 2))
DRAW M(polygon(point(0, 0), point(1, 0), point(1, 1), point(0, 1)))"""


def test_image_program():
    assert ch05.exercise_image_program(IMAGE).correct
    assert ch05.exercise_image_program("CONNECT point(1,0), point(3,1), point(4,3), point(2,2), point(1,0)").correct
    _assert_wrong(ch05.exercise_image_program("CONNECT point(0,0), point(1,0), point(1,1), point(0,1), point(0,0)"),
                  "the square itself")
    _assert_wrong(ch05.exercise_image_program("CONNECT point(1,0), point(3,1), point(3,3), point(2,2), point(1,0)"),
                  "(4, 3)")
    _assert_wrong(ch05.exercise_image_program("CONNECT point(1,0), point(3,1), point(4,3), point(2,2)"),
                  "1 of the 4 sides is missing")
    _assert_wrong(ch05.exercise_image_program("M = affine(point(0, 0), point(1, 0), point(2, 0), point(1, 0), "
                                              "point(3, 1), point(2, 2))"), "line 1, column 5, at 'affine'",
                  "collinear")


def test_sheared_turn():
    assert ch05.exercise_sheared_turn(45).correct
    assert ch05.exercise_sheared_turn(405).correct
    _assert_wrong(ch05.exercise_sheared_turn(90), "the shear changes the angles")
    _assert_wrong(ch05.exercise_sheared_turn(135), "interior angle")
    _assert_wrong(ch05.exercise_sheared_turn(-45), "clockwise")
    _assert_wrong(ch05.exercise_sheared_turn(30), "should be 45 degrees")
    _assert_wrong(ch05.exercise_sheared_turn("left"), "number of degrees")


def test_segments_of_forgets_order_and_direction():
    a = ch05.segments_of(codo.run(HEXAGON))
    b = ch05.segments_of(codo.run(HEXAGON.replace("60", "-60")))
    assert a == b and len(a) == 6

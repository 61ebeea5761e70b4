"""Chapter 5 checkers: right for the worked solutions and other correct programs (decimals to four
places included), wrong with the reason for each recognised slip (the interpreter's own message for
programs that do not run), never stating the expected numbers."""

import math

import numpy as np
import pytest

from goldman_lib import codo
from goldman_lib.exercises import ch05


def _assert_wrong(result, *fragments):
    assert result.answered and not result.correct, result
    for f in fragments:
        assert f in result.message, (f, result.message)


def test_problems_and_slips_listed():
    names = {"check_hexagon_program", "check_parallelogram_vertex", "check_expression_types",
             "check_image_program", "check_sheared_turn", "check_turtle_through_dots"}
    assert set(ch05.PROBLEMS) == names == set(ch05.SLIPS)
    assert all(len(v) >= 2 for v in ch05.SLIPS.values())


HEXAGON = """C = point(0, 0)
P = point(1, 0)
R = rotate(C, 60)
REPEAT 6 [ CONNECT P, R(P); P = R(P) ]"""
# the vertices (cos 60k, sin 60k): (1, 0), (1/2, sqrt(3)/2), (-1/2, sqrt(3)/2), (-1, 0), ...
TYPED = ("CONNECT point(1, 0), point(0.5, {h}), point(-0.5, {h}), point(-1, 0), point(-0.5, -{h}), "
         "point(0.5, -{h}), point(1, 0)")


@pytest.mark.parametrize("program", [
    HEXAGON,
    HEXAGON.replace("60", "-60"),
    "C = point(0, 0)\nF = polyline(point(1, 0), point(0.5, sqrt(3)/2))\nREPEAT 6 [ DRAW F; F = rotate(C, 60)(F) ]",
    TYPED.format(h="sqrt(3)/2"),
    TYPED.format(h="0.86603"),   # the hexagon: five digits typed by hand
    TYPED.format(h="0.8660"),
    HEXAGON + "\nCONNECT point(1, 0), point(0.5, 0.86603)",   # a side drawn twice is still one side
])
def test_hexagon_program_right(program):
    result = ch05.check_hexagon_program(program)
    assert result.correct, result


def test_hexagon_program_wrong():
    _assert_wrong(ch05.check_hexagon_program(codo.SAMPLES["regular pentagon"]), "none of your 5 segments",
                  "360/6")
    _assert_wrong(ch05.check_hexagon_program(HEXAGON.replace("6 [", "5 [")), "1 of the 6 sides", "missing")
    _assert_wrong(ch05.check_hexagon_program(TYPED.format(h="0.87")), "nearly a side", "off",
                  "sqrt(3)/2")
    r = ch05.check_hexagon_program(TYPED.format(h="0.87"))
    assert "0.866" not in r.message
    _assert_wrong(ch05.check_hexagon_program(HEXAGON.replace("point(1, 0)", "point(2, 0)")), "none of your")
    _assert_wrong(ch05.check_hexagon_program(HEXAGON + "\nCONNECT C, P"), "(0, 0) to (1, 0) is not a side")
    _assert_wrong(ch05.check_hexagon_program("P = point(0, 0)\nCONNECT P, P + P"),
                  "does not run: line 2, column 14, at '+'", "weights add up to 2")
    _assert_wrong(ch05.check_hexagon_program("P = point(0, 0)"), "draws nothing")
    _assert_wrong(ch05.check_hexagon_program(6), "CODO program in quotes")
    _assert_wrong(ch05.check_hexagon_program("REPEAT 100000 [ CONNECT point(0, 0), point(1, 0) ]"), "does not run")


@pytest.mark.parametrize("expr", ["A + C - B", "C + (A - B)", "A + (C - B)", "(A + C) - B", "2*((A + C)/2) - B"])
def test_parallelogram_vertex_right(expr):
    # D - A = C - B: for A, B, C = (1, 2), (4, 1), (6, 5), D = (3, 6)
    assert ch05.check_parallelogram_vertex(expr).correct


def test_parallelogram_vertex_wrong():
    _assert_wrong(ch05.check_parallelogram_vertex("B + C - A"), "opposite A")
    _assert_wrong(ch05.check_parallelogram_vertex("A + B - C"), "opposite C")
    _assert_wrong(ch05.check_parallelogram_vertex("(A + C)/2"), "the centre")
    _assert_wrong(ch05.check_parallelogram_vertex("C - B"), "is a vector")
    _assert_wrong(ch05.check_parallelogram_vertex("A + C"), "does not run: line 1, column 3, at '+'",
                  "weights add up to 2")
    _assert_wrong(ch05.check_parallelogram_vertex("point(3, 6)"), "not numbers")
    # (A + B + C)/3 at A, B, C = (1, 2), (4, 1), (6, 5) is (11/3, 8/3); D = (3, 6): distance sqrt(4/9 + 100/9)
    _assert_wrong(ch05.check_parallelogram_vertex("(A + B + C)/3"), "is well off from D")
    _assert_wrong(ch05.check_parallelogram_vertex("A; CONNECT A, B"), "one expression")
    _assert_wrong(ch05.check_parallelogram_vertex(3.0), "CODO expression in quotes")


RIGHT_TYPES = {"Q - 2*P": "illegal", "P + v": "point", "(P + Q + R)/3": "point", "P - 2*Q + R": "vector",
               "2*P - Q": "point", "3*v - P": "illegal", "(P - Q)/2 + R": "point", "0.5*P + 0.5*v": "illegal"}


def test_expression_types():
    assert ch05.check_expression_types(RIGHT_TYPES).correct
    assert ch05.check_expression_types({k: v.upper() for k, v in RIGHT_TYPES.items()}).correct
    _assert_wrong(ch05.check_expression_types({**RIGHT_TYPES, "Q - 2*P": "vector"}), "Q - 2*P is illegal",
                  "weights add up to -1")
    _assert_wrong(ch05.check_expression_types({**RIGHT_TYPES, "P + v": "illegal"}), "does not count in the weights")
    _assert_wrong(ch05.check_expression_types({**RIGHT_TYPES, "P - 2*Q + R": "illegal"}),
                  "P - 2*Q + R is a vector: the weights of its points add up to 0")
    _assert_wrong(ch05.check_expression_types({**RIGHT_TYPES, "(P - Q)/2 + R": "vector"}), "is a point")
    _assert_wrong(ch05.check_expression_types({**RIGHT_TYPES, "0.5*P + 0.5*v": "point"}), "weights add up to 0.5")
    _assert_wrong(ch05.check_expression_types({"P + v": "point"}), "is missing")
    _assert_wrong(ch05.check_expression_types({**RIGHT_TYPES, "P + v": "arrow"}), "'point', 'vector' or 'illegal'")
    _assert_wrong(ch05.check_expression_types(["vector"]), "should be a dict")


IMAGE = """M = affine(point(0, 0), point(1, 0), point(0, 1), point(1, 0), point(3, 1), point(2, 2))
DRAW M(polygon(point(0, 0), point(1, 0), point(1, 1), point(0, 1)))"""


def test_image_program():
    # (1, 1) = (1, 0) + (0, 1) - (0, 0) goes to (3, 1) + (2, 2) - (1, 0) = (4, 3)
    assert ch05.check_image_program(IMAGE).correct
    assert ch05.check_image_program("CONNECT point(1,0), point(3,1), point(4,3), point(2,2), point(1,0)").correct
    _assert_wrong(ch05.check_image_program("CONNECT point(0,0), point(1,0), point(1,1), point(0,1), point(0,0)"),
                  "the square itself")
    _assert_wrong(ch05.check_image_program("CONNECT point(1,0), point(3,1), point(2,2), point(1,0)"),
                  "image of the triangle")
    _assert_wrong(ch05.check_image_program("CONNECT point(1,0), point(3,1), point(3,2), point(2,2), point(1,0)"),
                  "not a corner you can read off")
    _assert_wrong(ch05.check_image_program("CONNECT point(1,0), point(3,1), point(4,3), point(2,2)"),
                  "1 of the 4 sides", "missing")
    _assert_wrong(ch05.check_image_program("M = affine(point(0, 0), point(1, 0), point(2, 0), point(1, 0), "
                                           "point(3, 1), point(2, 2))"), "line 1, column 5, at 'affine'", "collinear")


def test_sheared_turn():
    # the side (1, 0) -> (2, 1) has direction (1, 1): heading 45 degrees
    assert ch05.check_sheared_turn(45).correct
    assert ch05.check_sheared_turn(405).correct
    _assert_wrong(ch05.check_sheared_turn(90), "the shear changes the angles")
    _assert_wrong(ch05.check_sheared_turn(135), "interior angle")
    _assert_wrong(ch05.check_sheared_turn(-45), "clockwise")
    _assert_wrong(ch05.check_sheared_turn(math.pi / 4), "radians")
    _assert_wrong(ch05.check_sheared_turn(30), "too small")
    _assert_wrong(ch05.check_sheared_turn("left"), "number of degrees")


def test_turtle_through_dots():
    # (1, 1) -> (-3, 4): (-4, 3), length 5, heading 180 - atan(3/4) = 143.1301 degrees;
    # (-3, 4) -> (-3, 0): (0, -4), length 4, heading -90, turn -90 - 143.1301 + 360 = 126.8699
    assert ch05.check_turtle_through_dots([143.1301, 5, 126.8699, 4]).correct
    assert ch05.check_turtle_through_dots([143.13, 5, -233.13, 4]).correct  # turns modulo 360
    _assert_wrong(ch05.check_turtle_through_dots([36.87, 5, 126.87, 4]), "without its quadrant")
    _assert_wrong(ch05.check_turtle_through_dots([-36.87, 5, 126.87, 4]), "atan(dy/dx)")
    _assert_wrong(ch05.check_turtle_through_dots([2.4981, 5, 126.87, 4]), "radians")
    _assert_wrong(ch05.check_turtle_through_dots([143.13, 7, 126.87, 4]), "|dx| + |dy|")
    _assert_wrong(ch05.check_turtle_through_dots([143.13, 25, 126.87, 4]), "squared length")
    _assert_wrong(ch05.check_turtle_through_dots([143.13, 5, 270, 4]), "TURN is relative")
    _assert_wrong(ch05.check_turtle_through_dots([143.13, 5, -126.87, 4]), "wrong way")
    _assert_wrong(ch05.check_turtle_through_dots([143.13, 5, 126.87, 3]), "forward 2", "too small")
    _assert_wrong(ch05.check_turtle_through_dots([143.13, 5, 126.87]), "four numbers")


def test_segments_of_forgets_order_and_direction():
    a = ch05.segments_of(codo.run(HEXAGON))
    b = ch05.segments_of(codo.run(HEXAGON.replace("60", "-60")))
    assert a == b and len(a) == 6

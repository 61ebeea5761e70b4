"""goldman_lib.turtle: the four commands of Goldman §1.2, the programs of §1.3, the language.

Expected values come from closed forms (regular polygons, rotations by 90 degrees), never from
the code under test."""

import math
import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from goldman_lib import turtle
from goldman_lib.turtle import TurtleSyntaxError


# -- commands -----------------------------------------------------------------------------------

def test_turn_is_counterclockwise():
    (path,) = turtle.run("FORWARD 1 TURN 90 FORWARD 1")
    np.testing.assert_allclose(path, [[0, 0], [1, 0], [1, 1]], atol=1e-15)


def test_negative_turn_is_clockwise():
    (path,) = turtle.run("FORWARD 1 TURN -90 FORWARD 1")
    np.testing.assert_allclose(path, [[0, 0], [1, 0], [1, -1]], atol=1e-15)


def test_move_starts_a_new_stroke():
    polys = turtle.run("FORWARD 1 MOVE 1 FORWARD 2 TURN 90 FORWARD 1 MOVE 5")
    assert len(polys) == 2
    np.testing.assert_allclose(polys[0], [[0, 0], [1, 0]])
    np.testing.assert_allclose(polys[1], [[2, 0], [4, 0], [4, 1]])


def test_resize_scales_later_steps_and_keeps_heading():
    polys = turtle.run("FORWARD 1 RESIZE 3 FORWARD 1 RESIZE 0.5 TURN 90 FORWARD 2")
    np.testing.assert_allclose(polys[0], [[0, 0], [1, 0], [4, 0], [4, 3]])
    p, w = turtle.final_state("RESIZE 3 TURN 90")
    np.testing.assert_allclose(w, [0, 3], atol=1e-15)
    np.testing.assert_allclose(p, [0, 0])


def test_direction_length_is_the_step_size_and_point_is_the_start():
    (path,) = turtle.run("FORWARD 1 TURN 90 FORWARD 1", point=(2, 3), direction=(0, 2))
    np.testing.assert_allclose(path, [[2, 3], [2, 5], [0, 5]], atol=1e-14)


def test_no_drawing_gives_no_polylines_and_polylines_are_float_k_by_2():
    assert turtle.run("") == []
    assert turtle.run("MOVE 1 TURN 30 RESIZE 2") == []
    for p in turtle.run("REPEAT 3 [FORWARD 1 MOVE 1]"):
        assert p.dtype == float and p.shape == (2, 2)


def test_turtle_object_matches_the_language():
    t = turtle.Turtle()
    t.forward(1).turn(90).forward(1).move(1).resize(2).forward(1)
    np.testing.assert_allclose(t.point, [1, 4], atol=1e-15)
    assert t.heading == 90.0 and t.step == 2.0 and t.total_turning == 90.0
    expected = turtle.run("FORWARD 1 TURN 90 FORWARD 1 MOVE 1 RESIZE 2 FORWARD 1")
    got = t.polylines()
    assert len(got) == len(expected) == 2
    for a, b in zip(got, expected):
        np.testing.assert_allclose(a, b)
    t.run("FORWARD 1")  # continues the open stroke
    assert len(t.polylines()) == 2 and t.polylines()[-1].shape == (3, 2)
    with pytest.raises(TypeError, match="distance must be a real number"):
        t.forward("1")
    with pytest.raises(ValueError, match="angle must be finite"):
        t.turn(float("inf"))


# -- programs of §1.3 ---------------------------------------------------------------------------

@pytest.mark.parametrize("n", [3, 4, 5, 6, 8, 12, 36])
@pytest.mark.parametrize("step", [0.5, 1.0, 2.5])
def test_regular_polygon_closes_with_perimeter_n_step(n, step):
    (path,) = turtle.run(turtle.polygon(n, step))
    assert path.shape == (n + 1, 2)
    assert turtle.closes(path, 1e-9)
    assert turtle.perimeter(path) == pytest.approx(n * step, rel=1e-12)
    # every vertex on the circumscribed circle of radius step / (2 sin(pi/n))
    radius = step / (2 * math.sin(math.pi / n))
    centre = path[:-1].mean(axis=0)
    np.testing.assert_allclose(np.hypot(*(path[:-1] - centre).T), radius, rtol=1e-9)
    assert turtle.total_turning(turtle.polygon(n, step)) == pytest.approx(360.0)


def test_five_two_star_closes_after_five_steps_with_total_turning_720():
    (path,) = turtle.run("REPEAT 5 [FORWARD 1 TURN 144]")
    assert path.shape == (6, 2)
    assert turtle.closes(path, 1e-12)
    assert not any(turtle.closes(path[: j + 1], 1e-6) for j in range(1, 5))
    assert turtle.total_turning(turtle.star(5, 2)) == pytest.approx(720.0)
    # the five points lie on the circle through them: chord 1 subtends 144 degrees
    radius = 1 / (2 * math.sin(math.radians(72)))
    centre = path[:-1].mean(axis=0)
    np.testing.assert_allclose(np.hypot(*(path[:-1] - centre).T), radius, rtol=1e-12)


@pytest.mark.parametrize("n,k", [(5, 2), (7, 2), (7, 3), (8, 3), (9, 4), (6, 1)])
def test_star_total_turning_is_360k(n, k):
    (path,) = turtle.run(turtle.star(n, k))
    assert turtle.closes(path, 1e-9)
    assert turtle.total_turning(turtle.star(n, k)) == pytest.approx(360.0 * k)
    assert turtle.turning_angles(path) == pytest.approx(np.full(n - 1, 360.0 * k / n - 360.0 * (k / n > 0.5)))


def test_circle_vertices_lie_on_the_circle_and_the_state_returns():
    r, n = 2.0, 36
    t = turtle.trace(turtle.circle(r, n))
    (path,) = t.polylines
    np.testing.assert_allclose(np.hypot(path[:, 0], path[:, 1] - r), r, rtol=1e-12)
    np.testing.assert_allclose(t.point, [0, 0], atol=1e-12)
    np.testing.assert_allclose(t.direction, [1, 0], atol=1e-12)
    assert turtle.length(path) == pytest.approx(2 * n * r * math.sin(math.pi / n))


def test_spiral_with_resize_has_geometric_steps():
    (path,) = turtle.run(turtle.spiral(5, 90, 1, factor=2))
    steps = np.hypot(*np.diff(path, axis=0).T)
    np.testing.assert_allclose(steps, [1, 2, 4, 8, 16])
    (path,) = turtle.run(turtle.spiral(4, 90, 1, increment=0.5))
    np.testing.assert_allclose(np.hypot(*np.diff(path, axis=0).T), [1, 1.5, 2, 2.5])
    with pytest.raises(ValueError, match="factor or increment, not both"):
        turtle.spiral(3, factor=2, increment=1)


def test_rosette_is_the_polygon_rotated():
    polys = turtle.run(turtle.rosette(4, 4, 1))
    (path,) = polys
    assert path.shape == (17, 2)
    assert turtle.length(path) == pytest.approx(16.0)
    assert turtle.total_turning(turtle.rosette(4, 4)) == pytest.approx(4 * 360 + 360)


# -- the language --------------------------------------------------------------------------------

def test_nested_repeat_case_comments_decimals_negatives():
    program = """
    # two squares, side 0.5, the second turned by -90
    repeat 2 [
        Repeat 4 [ forward .5  TURN 90 ]   # a square
        TURN -90
    ]
    """
    codes, values = turtle.expand(program)
    assert codes.tolist() == ([0, 2] * 4 + [2]) * 2
    assert values.tolist() == ([0.5, 90.0] * 4 + [-90.0]) * 2
    assert turtle.parse("FORWARD 1e-1").items[0].value == 0.1
    assert turtle.parse("REPEAT 3.0 [FORWARD 1]").items[0].count == 3
    assert turtle.expand("REPEAT 0 [FORWARD 1] REPEAT 2 []")[0].size == 0


@pytest.mark.parametrize("program,message", [
    ("REPEAT 5 [\n FORWARD", "line 2, column 9: expected a number after FORWARD, found end of program"),
    ("REPEAT 5 [FORWARD 1\n  TURN 72",
     "line 2, column 10: expected ']' to close REPEAT opened at line 1, column 1, found end of program"),
    ("FORWARD abc", "line 1, column 9: expected a number after FORWARD, found 'abc'"),
    ("FORWRD 1", "line 1, column 1: expected a command (FORWARD, MOVE, TURN, RESIZE or REPEAT), found 'FORWRD' "
                 "(did you mean FORWARD?)"),
    ("FORWARD 1 ]", "line 1, column 11: found ']' with no REPEAT [ to close"),
    ("REPEAT 3 FORWARD 1", "line 1, column 10: expected '[' after REPEAT 3, found 'FORWARD'"),
    ("REPEAT 2.5 [FORWARD 1]", "line 1, column 8: the REPEAT count must be a non-negative whole number, found 2.5"),
    ("REPEAT -1 [FORWARD 1]", "line 1, column 8: the REPEAT count must be a non-negative whole number, found -1"),
    ("TURN 1e400", "line 1, column 6: the number after TURN must be finite; 1e400 is too large"),
    ("TURN nan", "line 1, column 6: expected a number after TURN, found 'nan'"),
    ("FORWARD 1 @", "line 1, column 11: expected a command (FORWARD, MOVE, TURN, RESIZE or REPEAT), found '@'"),
    ("# comment only\nMOVE", "line 2, column 5: expected a number after MOVE, found end of program"),
])
def test_syntax_errors_name_line_column_and_expected_token(program, message):
    with pytest.raises(TurtleSyntaxError) as info:
        turtle.run(program)
    assert str(info.value) == message
    assert isinstance(info.value, ValueError)
    line, col = (int(s) for s in message.split(":")[0].replace("line ", "").split(", column "))
    assert (info.value.line, info.value.column) == (line, col)


def test_command_cap_fails_fast_naming_the_repeat():
    start = time.process_time()     # CPU time: the suite runs beside two browsers
    with pytest.raises(ValueError, match=r"line 1, column 1: this program would execute 1,000,000 commands, "
                                         r"more than the limit of 200,000"):
        turtle.run("REPEAT 1000 [REPEAT 1000 [FORWARD 1 ]]")
    with pytest.raises(ValueError, match="limit"):
        turtle.run("REPEAT 1e300 [REPEAT 1e300 [FORWARD 1 TURN 1]]")
    assert time.process_time() - start < 0.5
    assert len(turtle.run("REPEAT 1000000 []")) == 0
    with pytest.raises(ValueError, match="REPEAT count must be at most 1,000,000"):
        turtle.run("REPEAT 1e300 []")
    assert turtle.expand("REPEAT 100000 [FORWARD 1 TURN 1]")[0].size == 200_000


def test_deep_nesting_is_an_error_not_a_recursion_crash():
    with pytest.raises(TurtleSyntaxError, match="nested more than"):
        turtle.parse("REPEAT 1 [" * 500 + "FORWARD 1" + "]" * 500)


def test_overflow_is_a_clear_error():
    with pytest.raises(ValueError, match="overflowed"):
        turtle.run("REPEAT 100 [FORWARD 1 RESIZE 1e5]")


# -- bad input at the boundary --------------------------------------------------------------------

def test_bad_arguments_name_the_parameter():
    with pytest.raises(TypeError, match="program must be a turtle program"):
        turtle.run(42)
    with pytest.raises(TypeError, match="program must be a string"):
        turtle.parse(None)
    with pytest.raises(ValueError, match="point must hold 2-dimensional points"):
        turtle.run("FORWARD 1", point=(0, 0, 0))
    with pytest.raises(ValueError, match="direction must be finite"):
        turtle.run("FORWARD 1", direction=(1, float("nan")))
    with pytest.raises(TypeError, match="direction must be numeric"):
        turtle.run("FORWARD 1", direction="east")
    with pytest.raises(ValueError, match="n must be >= 3"):
        turtle.polygon(2)
    with pytest.raises(ValueError, match="k must be <= 4"):
        turtle.star(5, 5)
    with pytest.raises(ValueError, match="step must be positive"):
        turtle.polygon(5, 0)
    with pytest.raises(ValueError, match="radius must be positive"):
        turtle.circle(-1)
    with pytest.raises(ValueError, match="tol must be >= 0"):
        turtle.closes([[0, 0], [1, 1]], -1)
    with pytest.raises(ValueError, match="polyline must be closed to have a perimeter; its ends are 1 apart"):
        turtle.perimeter([[0, 0], [1, 0]])
    with pytest.raises(ValueError, match="polyline must have shape"):
        turtle.closes([0, 0])


def test_measures():
    assert turtle.length([[0, 0], [3, 4]]) == 5.0
    assert turtle.length([np.array([[0, 0], [3, 4]]), np.array([[0, 0], [0, 1]])]) == 6.0
    assert turtle.closing_gap([[0, 0], [3, 0], [3, 4]]) == 5.0
    np.testing.assert_allclose(turtle.turning_angles([[0, 0], [1, 0], [1, -1], [1, -1], [2, -1]]), [-90, 90])


# -- properties (hypothesis) --------------------------------------------------------------------

commands = st.lists(st.tuples(st.sampled_from(["FORWARD", "MOVE", "TURN", "RESIZE"]),
                              st.floats(-3, 3, allow_nan=False).map(lambda x: round(x, 3))),
                    min_size=0, max_size=25)


def _program(cmds):
    return " ".join(f"{c} {v if c != 'RESIZE' else (abs(v) % 1.5) + 0.25}" for c, v in cmds)


@settings(max_examples=150, deadline=None)
@given(cmds=commands, px=st.floats(-5, 5), py=st.floats(-5, 5), angle=st.floats(-360, 360),
       size=st.floats(0.25, 4))
def test_rigid_motion_and_scaling_invariance(cmds, px, py, angle, size):
    """Starting from P and w = size * (cos a, sin a) draws the standard drawing rotated by a,
    scaled by size and translated by P (the turtle is intrinsic: Goldman §1.2)."""
    program = _program(cmds)
    base = turtle.run(program)
    a = math.radians(angle)
    rot = size * np.array([[math.cos(a), math.sin(a)], [-math.sin(a), math.cos(a)]])  # row vectors
    moved = turtle.run(program, point=(px, py), direction=(size * math.cos(a), size * math.sin(a)))
    assert len(moved) == len(base)
    for b, m in zip(base, moved):
        np.testing.assert_allclose(m, b @ rot + [px, py], atol=1e-9 * (1 + np.abs(b).max()) * size)


@settings(max_examples=60, deadline=None)
@given(n=st.integers(3, 400), step=st.floats(0.01, 100))
def test_repeat_n_forward_turn_360_over_n_closes(n, step):
    (path,) = turtle.run(f"REPEAT {n} [FORWARD {step!r} TURN {360 / n!r}]")
    assert turtle.closes(path, 1e-9 * n * step)
    assert turtle.length(path) == pytest.approx(n * step, rel=1e-9)


@settings(max_examples=60, deadline=None)
@given(cmds=commands, reps=st.integers(0, 4))
def test_repeat_is_concatenation(cmds, reps):
    body = _program(cmds)
    a = turtle.expand(f"REPEAT {reps} [{body}]")
    b = turtle.expand(" ".join([body] * reps))
    assert a[0].tolist() == b[0].tolist() and a[1].tolist() == b[1].tolist()


@settings(max_examples=60, deadline=None)
@given(cmds=commands)
def test_total_turning_is_the_heading_change_mod_360(cmds):
    program = _program(cmds)
    _, w = turtle.final_state(program)
    turn = turtle.total_turning(program)
    expected = math.radians(turn)
    assert math.cos(math.atan2(w[1], w[0]) - expected) == pytest.approx(1.0, abs=1e-9)

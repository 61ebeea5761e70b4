"""Chapter 8 checkers: right for answers worked by hand here, wrong with the reason for each
recognised slip, "not answered" for None and ...; the Ron's-algorithm project checker passes a
correct function and names the failing case of subtly wrong and crashing ones."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import ch08

R2 = math.sqrt(2)
TAO_RIGHT = "RESIZE 1/2 RECURSE RESIZE 2 MOVE 1 TURN 90 RESIZE 1/2 RECURSE RESIZE 2 TURN -90 MOVE -1"


def _wrong(result, *fragments):
    assert result.answered and not result.correct, result
    for f in fragments:
        assert f in result.message, (f, result.message)


def test_every_checker_has_a_problem_statement_and_slips():
    names = {"check_moved_point", "check_level_end", "check_ron_map", "check_tao_body", "check_bump_from_ifs"}
    assert set(ch08.PROBLEMS) == names == set(ch08.SLIPS)
    for name in names:
        assert not getattr(ch08, name)(None).answered


def test_moved_point():
    # P = (-1, 2), w = (1, 1), w_perp = (-1, 1): (x, y) -> (-1 + x - y, 2 + x + y); (1/2, 1/2) -> (-1, 3)
    assert ch08.check_moved_point([-1, 3]).correct
    _wrong(ch08.check_moved_point([-0.5, 2.5]), "did not turn or scale")            # P + (1/2, 1/2)
    _wrong(ch08.check_moved_point([0, 2]), "clockwise")                           # w_perp taken as (1, -1)
    _wrong(ch08.check_moved_point([0, 1]), "forgot to move it")                   # (x - y, x + y)
    _wrong(ch08.check_moved_point([-1, 2 + R2 / 2]), "kept the size")             # rotate 45, no scaling
    _wrong(ch08.check_moved_point([1, 1]), "from where it is drawn")
    _wrong(ch08.check_moved_point([1, 2, 3]), "one point")
    _wrong(ch08.check_moved_point("here"), "should be numbers")


def test_level_end():
    # RESIZE 1/2; call -> (1/2, 0); TURN 90; call -> (1/2, 1/2); base case FORWARD 1 ends at (1, 0)
    r = ch08.check_level_end([0.5, 0.5])
    assert r.correct and "breaks the hypothesis" in r.message
    _wrong(ch08.check_level_end([1, 0]), "where level 0, FORWARD 1, ends")
    _wrong(ch08.check_level_end([0, 0]), "did not move the turtle")
    _wrong(ch08.check_level_end([1, 1]), "left out RESIZE 1/2")
    _wrong(ch08.check_level_end([0.5, -0.5]), "turned clockwise")
    _wrong(ch08.check_level_end([2, 2]), "command by command")


def test_ron_map():
    # call 3 at P = (1/2, 1/4), w = (1/4, -1/4)
    right = [[0.25, -0.25, 0], [0.25, 0.25, 0], [0.5, 0.25, 1]]
    assert ch08.check_ron_map(right).correct
    assert ch08.check_ron_map(np.array(right) + 4e-5).correct
    _wrong(ch08.check_ron_map(np.array(right).T.tolist()), "transposed")
    _wrong(ch08.check_ron_map([[0.25, 0.25, 0], [-0.25, 0.25, 0], [0.25, 0, 1]]), "the map of call 2")
    _wrong(ch08.check_ron_map([[0.25, -0.25, 0], [0.25, 0.25, 0], [0, 0, 1]]), "each earlier RECURSE moves")
    _wrong(ch08.check_ron_map([[0.25, 0.25, 0], [-0.25, 0.25, 0], [0.5, -0.25, 1]]), "clockwise")
    _wrong(ch08.check_ron_map([[0.25, -0.25, 0], [-0.25, -0.25, 0], [0.5, 0.25, 1]]), "reflects")
    _wrong(ch08.check_ron_map([[0.25, -0.25, 0], [0.25, 0.25, 0], [0.5, 0.5, 1]]), "the point P (last row) is off")
    _wrong(ch08.check_ron_map([[0.25, -0.25, 1], [0.25, 0.25, 0], [0.5, 0.25, 1]]), "last column (0, 0, 1)")
    _wrong(ch08.check_ron_map([[1, 2], [3, 4]]), "3x3 matrix")


@pytest.mark.parametrize("body", [TAO_RIGHT,
                                  "resize 0.5, recurse, resize 2, move 1, turn 90, resize 0.5, recurse, "
                                  "resize 2, turn -90, move -1",
                                  # the other order of the maps, and a TURN-MOVE-TURN route to (1, 0)
                                  "MOVE 1 TURN 90 RESIZE 1/2 RECURSE RESIZE 2 TURN -90 MOVE -1 RESIZE 1/2 "
                                  "RECURSE RESIZE 2"])
def test_tao_body_right(body):
    assert ch08.check_tao_body(body).correct


def test_tao_body_slips():
    _wrong(ch08.check_tao_body("RESIZE 1/2 RECURSE RESIZE 2 MOVE 1 TURN 90 RESIZE 1/2 RECURSE RESIZE 2 MOVE -1"),
           "does not bring the turtle back", "heading not restored")
    _wrong(ch08.check_tao_body("RESIZE 1/2 RECURSE RESIZE 2 TURN 90 MOVE 1 RESIZE 1/2 RECURSE RESIZE 2 MOVE -1 "
                               "TURN -90"), "at P = (0, 1)", "MOVE 1 first, then TURN 90")
    _wrong(ch08.check_tao_body("RESIZE 1/2 RECURSE MOVE 1 TURN 90 RECURSE TURN -90 MOVE -1 RESIZE 2"),
           "at P = (0.5, 0)", "undo the RESIZE before you move")
    _wrong(ch08.check_tao_body("RESIZE 1/2 RECURSE RESIZE 2 MOVE 1 TURN -90 RESIZE 1/2 RECURSE RESIZE 2 TURN 90 "
                               "MOVE -1"), "heading -90 degrees", "wrong way")
    _wrong(ch08.check_tao_body("RECURSE MOVE 1 TURN 90 RECURSE TURN -90 MOVE -1"), "step 1,", "RESIZE 1/2")
    _wrong(ch08.check_tao_body("RESIZE 1/2 RECURSE RESIZE 2"), "calls itself 1 times")
    _wrong(ch08.check_tao_body("RESIZE half RECURSE"), "is not a number")
    _wrong(ch08.check_tao_body("JUMP 1 RECURSE"), "is not a command")
    _wrong(ch08.check_tao_body("MOVE 1"), "does not read")
    _wrong(ch08.check_tao_body(42), "as a string")


def test_bump_from_ifs():
    # T1: (0,0)->(0,0), (1,0)->(0.3,0.4); T2: (0,0)->(0.6,0), (1,0)->(0.6,0)+(-0.3,0.4) = (0.3,0.4), backwards;
    # T3: (0,0)->(0.6,0), (1,0)->(1,0)
    right = [[0, 0], [0.3, 0.4], [0.6, 0], [1, 0]]
    r = ch08.check_bump_from_ifs(right)
    assert r.correct and "T2" in r.message and "backwards" in r.message
    _wrong(ch08.check_bump_from_ifs(right[:3]), "3 maps has 4 points")
    _wrong(ch08.check_bump_from_ifs(right[::-1]), "in reverse")
    _wrong(ch08.check_bump_from_ifs([[0, 0], [0.6, 0], [0.6, 0], [1, 0]]), "last row as the start", "backwards")
    _wrong(ch08.check_bump_from_ifs([[0, 0], [0.3, 0.4], [-0.3, 0.4], [0.4, 0]]), "a direction, not a point")
    _wrong(ch08.check_bump_from_ifs([[0, 0], [0.3, 0.5], [0.6, 0], [1, 0]]), "point 1 of your bump is off")
    _wrong(ch08.check_bump_from_ifs(right + [[2, 0]]), "yours has 5")
    _wrong(ch08.check_bump_from_ifs([0, 0]), "list of points")


def test_parse_body_reads_fractions_and_sqrt2():
    assert ch08.parse_body("TURN 45 RESIZE sqrt2 RESIZE 1/sqrt2, RECURSE") == [
        ("TURN", 45.0), ("RESIZE", R2), ("RESIZE", 1 / R2), ("RECURSE", None)]
    with pytest.raises(ValueError, match="needs a number"):
        ch08.parse_body("TURN")


# -- the programming project ---------------------------------------------------------------------

def rons_maps(body):
    P, w, maps = np.zeros(2), np.array([1.0, 0.0]), []
    for c, v in body:
        if c in ("FORWARD", "MOVE"):
            P = P + v * w
        elif c == "TURN":
            co, si = math.cos(math.radians(v)), math.sin(math.radians(v))
            w = np.array([co * w[0] - si * w[1], si * w[0] + co * w[1]])
        elif c == "RESIZE":
            w = v * w
        else:
            maps.append([[w[0], w[1], 0], [-w[1], w[0], 0], [P[0], P[1], 1]])
            P = P + w
    return np.array(maps)


def calls_do_not_move(body):
    P, w, maps = np.zeros(2), np.array([1.0, 0.0]), []
    for c, v in body:
        if c in ("FORWARD", "MOVE"):
            P = P + v * w
        elif c == "TURN":
            co, si = math.cos(math.radians(v)), math.sin(math.radians(v))
            w = np.array([co * w[0] - si * w[1], si * w[0] + co * w[1]])
        elif c == "RESIZE":
            w = v * w
        else:
            maps.append([[w[0], w[1], 0], [-w[1], w[0], 0], [P[0], P[1], 1]])
    return np.array(maps)


def transposed(body):
    return rons_maps(body).transpose(0, 2, 1)


def clockwise(body):
    return rons_maps([(c, -v if c == "TURN" else v) for c, v in body])


def composed_in_the_wrong_order(body):
    """Turns applied on the wrong side (about the world origin instead of the turtle)."""
    F, maps = np.eye(3), []
    for c, v in body:
        if c == "TURN":
            co, si = math.cos(math.radians(v)), math.sin(math.radians(v))
            F = F @ np.array([[co, si, 0], [-si, co, 0], [0, 0, 1]])
        elif c == "RESIZE":
            F = F @ np.diag([v, v, 1.0])
        elif c in ("FORWARD", "MOVE", "RECURSE"):
            if c == "RECURSE":
                maps.append(F.copy())
            T = np.eye(3)
            T[2, 0] = 1.0 if c == "RECURSE" else v
            F = T @ F
    return np.array(maps)


def crashing(body):
    return [value for command, value in body if value > 0]


def test_project_accepts_a_correct_function():
    r = ch08.check_rons_algorithm_project(rons_maps)
    assert r.correct, r
    assert "a single call (the identity map)" in r.message and "two calls in the same state" in r.message


@pytest.mark.parametrize("function,fragment", [
    (transposed, "transposed (column-vector convention)"),
    (calls_do_not_move, "your calls do not move the turtle"),
    (clockwise, "your turns go clockwise"),
    (composed_in_the_wrong_order, "map 2 (call 2) is off by 0.29 in an entry: yours is the state at P = (0.1667, 0.2887)"),
])
def test_project_names_the_failing_case_and_the_slip(function, fragment):
    r = ch08.check_rons_algorithm_project(function)
    assert not r.correct and r.answered
    assert r.message.startswith("case 1 of 12 (body RESIZE 0.3333 RECURSE TURN 60 RECURSE"), r
    assert fragment in r.message, r


def test_project_reports_a_crash_with_the_learners_line():
    r = ch08.check_rons_algorithm_project(crashing)
    assert not r.correct and "raised TypeError" in r.message and "value > 0" in r.message, r


def test_project_wrong_count_and_unanswered():
    r = ch08.check_rons_algorithm_project(lambda body: rons_maps(body)[:1])
    assert "it has 1 maps; the body has 4 RECURSEs" in r.message, r

    def starter(body):
        """docstring only"""
        ...
    assert not ch08.check_rons_algorithm_project(starter).answered


def test_project_cases_are_fixed_consistent_and_cover_degenerate_kinds():
    a, b = ch08.rons_project_cases(), ch08.rons_project_cases()
    assert [c.label for c in a] == [c.label for c in b]
    kinds = {c.kind for c in a}
    assert {"random bodies", "a single call (the identity map)", "two calls in the same state",
            "a body ending with its call", "full turns"} <= kinds
    for case in a:   # every body ends where FORWARD 1 does, so Ron's algorithm accepts it
        (body,) = case.args
        assert len(rons_maps(body)) == sum(c == "RECURSE" for c, _ in body)
        _, (P, w) = ch08.call_states(body)
        assert np.allclose(P, [1, 0]) and np.allclose(w, [1, 0])

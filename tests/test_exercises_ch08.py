"""Chapter 8 checkers: right for the worked solutions, wrong with the reason for typical slips,
"not answered" for None and ...; expected values worked out by hand here."""

import math

import pytest

from goldman_lib.exercises import ch08

CHECKERS = [ch08.check_moved_apex, ch08.check_call_state, ch08.check_tao_body, ch08.check_bump_dimension,
            ch08.check_conformal_maps]
H = math.sqrt(3) / 6


def _wrong(result, *fragments):
    assert result.answered and not result.correct, result
    for f in fragments:
        assert f in result.message, (f, result.message)


def test_every_checker_has_a_problem_statement():
    assert set(ch08.PROBLEMS) == {c.__name__ for c in CHECKERS}


def test_moved_apex():
    # P = (2, 1), w = (0, 1): (x, y) -> (2 - y, 1 + x)
    assert ch08.check_moved_apex([2 - H, 1.5]).correct
    _wrong(ch08.check_moved_apex([2.5, 1 + H]), "did not turn")
    _wrong(ch08.check_moved_apex([2 + H, 0.5]), "clockwise")
    _wrong(ch08.check_moved_apex([-H, 0.5]), "forgot to move it")
    _wrong(ch08.check_moved_apex([0, 0]), "from the apex")
    _wrong(ch08.check_moved_apex([1, 2, 3]), "one point")
    _wrong(ch08.check_moved_apex("here"), "should be numbers")


def test_call_state():
    assert ch08.check_call_state([[0.5, 0.5], [0.5, -0.5]]).correct
    _wrong(ch08.check_call_state([[0, 0], [0.5, -0.5]]), "where the first call started")
    r = 1 / math.sqrt(2)
    _wrong(ch08.check_call_state([[0.5, 0.5], [r, -r]]), "too long")
    _wrong(ch08.check_call_state([[0.5, 0.5], [0.5, 0.5]]), "heading 45 - 90 = -45")
    _wrong(ch08.check_call_state([[0.5, 0.5]]), "[[Px, Py], [wx, wy]]")


@pytest.mark.parametrize("body", ["RESIZE 1/2 RECURSE RECURSE RESIZE 2",
                                  "resize 0.5, recurse, recurse, resize 2",
                                  "RESIZE 0.5 RECURSE MOVE -1 MOVE 1 RECURSE RESIZE 2"])
def test_tao_body_right(body):
    assert ch08.check_tao_body(body).correct


def test_tao_body_typical_mistakes():
    _wrong(ch08.check_tao_body("RESIZE 1/2 RECURSE RECURSE"), "not consistent", "Undo the RESIZE")
    _wrong(ch08.check_tao_body("RESIZE 1/2 RECURSE RESIZE 2"), "not consistent", "must end where FORWARD 1 ends")
    _wrong(ch08.check_tao_body("RESIZE 1/2 RECURSE MOVE 1 RESIZE 2"), "calls itself 1 times")
    _wrong(ch08.check_tao_body("RECURSE RECURSE MOVE -1"), "scales 1, 1")
    _wrong(ch08.check_tao_body("RESIZE 1/2 RECURSE TURN 90 RECURSE TURN -90 RESIZE 2"), "not consistent")
    _wrong(ch08.check_tao_body("RESIZE 1/2 RECURSE MOVE 1 RECURSE MOVE -1 RESIZE 2"), "should start at (0, 0) and (0.5, 0)")
    _wrong(ch08.check_tao_body("RESIZE half RECURSE"), "is not a number")
    _wrong(ch08.check_tao_body("JUMP 1 RECURSE"), "is not a command")
    _wrong(ch08.check_tao_body(42), "as a string")


def test_bump_dimension():
    assert ch08.check_bump_dimension(math.log(5) / math.log(3)).correct
    _wrong(ch08.check_bump_dimension(math.log(4) / math.log(3)), "Koch curve's dimension")
    _wrong(ch08.check_bump_dimension(1.0), "should be 1.465")


def test_conformal_maps():
    assert ch08.check_conformal_maps({"A", "D"}).correct
    assert ch08.check_conformal_maps(["a", "d"]).correct
    _wrong(ch08.check_conformal_maps({"A", "D", "C"}), "reverses orientation")
    _wrong(ch08.check_conformal_maps({"A", "B", "D"}), "B is not conformal")
    _wrong(ch08.check_conformal_maps({"A", "D", "E"}), "E is not conformal")
    _wrong(ch08.check_conformal_maps({"A"}), "D can be followed too")
    _wrong(ch08.check_conformal_maps({"A", "Z"}), "Z is not one of the maps")

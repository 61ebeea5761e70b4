"""Corpus of the chapter-2 project (the quadratic Koch curve as turtle commands): correct programs
written from the statement alone (recursion with RESIZE, an explicit step length with no RESIZE,
string rewriting F -> F+F-F-F+F, turns written as -270/270, lowercase names and list pairs) must be
accepted; realistic wrong ones must be rejected with the slip named."""

import pytest

from goldman_lib.exercises import ch02


# -- accepted ------------------------------------------------------------------------------------------

def recursive(level):
    if level == 0:
        return [("FORWARD", 1)]
    c = recursive(level - 1)
    return ([("RESIZE", 1 / 3)] + c + [("TURN", 90)] + c + [("TURN", -90)] + c + [("TURN", -90)] + c
            + [("TURN", 90)] + c + [("RESIZE", 3)])


def explicit_step(level, step=1.0):
    """No RESIZE: each segment is FORWARD 3^-level; turns as 270 / -270, pairs as lists."""
    if level == 0:
        return [["FORWARD", step]]
    c = explicit_step(level - 1, step / 3)
    return c + [["TURN", -270]] + c + [["TURN", 270]] + c + [["TURN", 270]] + c + [["TURN", -270]] + c


def rewriting(level):
    """An L-system: F -> F+F-F-F+F, then read the string (lowercase command names)."""
    s = "F"
    for _ in range(level):
        s = s.replace("F", "F+F-F-F+F")
    step = 3.0 ** -level
    out = []
    for ch in s:
        out.append(("forward", step) if ch == "F" else ("turn", 90 if ch == "+" else -90))
    return out


ACCEPTED = [recursive, explicit_step, rewriting]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch02.check_quadratic_koch_project(solution)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def off_by_one_level(level):                   # the base case one level too low
    if level < 0:
        return [("FORWARD", 1)]
    c = off_by_one_level(level - 1)
    return ([("RESIZE", 1 / 3)] + c + [("TURN", 90)] + c + [("TURN", -90)] + c + [("TURN", -90)] + c
            + [("TURN", 90)] + c + [("RESIZE", 3)])


def bumps_on_the_right(level):                 # the turns' signs swapped
    if level == 0:
        return [("FORWARD", 1)]
    c = bumps_on_the_right(level - 1)
    return ([("RESIZE", 1 / 3)] + c + [("TURN", -90)] + c + [("TURN", 90)] + c + [("TURN", 90)] + c
            + [("TURN", -90)] + c + [("RESIZE", 3)])


def step_not_restored(level):                  # no RESIZE 3 at the end
    if level == 0:
        return [("FORWARD", 1)]
    c = step_not_restored(level - 1)
    return [("RESIZE", 1 / 3)] + c + [("TURN", 90)] + c + [("TURN", -90)] + c + [("TURN", -90)] + c + [
        ("TURN", 90)] + c


def recurse_left_in(level):                    # the program, not its expansion
    if level == 0:
        return [("FORWARD", 1)]
    return [("RESIZE", 1 / 3), ("RECURSE", level - 1), ("TURN", 90), ("RECURSE", level - 1), ("RESIZE", 3)]


def pen_up_across(level):                      # MOVE for the copy across the top of the bump
    if level == 0:
        return [("FORWARD", 1)]
    c = pen_up_across(level - 1)
    across = [("MOVE", 1)] if level == 1 else c
    return ([("RESIZE", 1 / 3)] + c + [("TURN", 90)] + c + [("TURN", -90)] + across + [("TURN", -90)] + c
            + [("TURN", 90)] + c + [("RESIZE", 3)])


def four_copies(level):                        # one copy forgotten
    if level == 0:
        return [("FORWARD", 1)]
    c = four_copies(level - 1)
    return [("RESIZE", 1 / 3)] + c + [("TURN", 90)] + c + [("TURN", -90)] + c + [("TURN", -90)] + c + [
        ("TURN", 90), ("RESIZE", 3)]


REJECTED = [
    (off_by_one_level, "at level 0 your curve has 5 segments, expected 1"),
    (bumps_on_the_right, "bumps point to the turtle's right"),
    (step_not_restored, "restore the step with RESIZE 3"),
    (recurse_left_in, "is a RECURSE"),
    (pen_up_across, "separate strokes"),
    (four_copies, "segments, expected 5"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch02.check_quadratic_koch_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message

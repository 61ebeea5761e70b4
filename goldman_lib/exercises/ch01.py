"""Exercise checkers for chapter 1, turtle graphics (Goldman §1.1-1.3).

Each checker takes the learner's answer (a turtle program as a string, or a number, or a point)
and returns a :class:`~goldman_lib.exercises.Result` that says why a wrong answer is wrong.
``None`` or ``...`` means "not answered yet".

>>> exercise_hexagon("REPEAT 6 [FORWARD 2 TURN 60]")
Correct: a regular hexagon with side 2 that closes: 6 sides, each turn 60 degrees, total turning 360.
>>> exercise_hexagon("REPEAT 5 [FORWARD 2 TURN 60]")
Not yet: your path ends 2 away from where it started: it does not close.
"""

from __future__ import annotations

import numpy as np

from goldman_lib import turtle
from goldman_lib.exercises import (Result, read_number, check_number, check_points, correct, fmt, is_unanswered,
                                   unanswered, wrong)

__all__ = ["PROBLEMS", "exercise_hexagon", "exercise_star_angle", "exercise_five_pointed_star",
           "exercise_final_position", "exercise_total_turning", "sides_of", "FINAL_POSITION_PROGRAM"]


#: The problem statement of each exercise (its checker's name -> the text), as in chapters 2-30.
PROBLEMS = {
    "exercise_hexagon": "Write a turtle program that draws a regular hexagon with side 2 and closes (Goldman §1.3).",
    "exercise_star_angle": ("Give the TURN angle a for which REPEAT 7 [FORWARD 1 TURN a] draws the star polygon {7/3} "
                            "(Goldman §1.3)."),
    "exercise_five_pointed_star": "Write a turtle program for the five-pointed star {5/2} with side 1 (Goldman §1.3).",
    "exercise_final_position": ("Where does the turtle end after FINAL_POSITION_PROGRAM, starting at (0, 0) heading "
                                "(1, 0)? Give the point (x, y) (Goldman §1.2)."),
    "exercise_total_turning": ("The total turning, in degrees, of the turtle drawing the star {7/3} with "
                               "REPEAT 7 [FORWARD 1 TURN 360*3/7] (Goldman §1.3)."),
}


def sides_of(polyline, tol: float = 1e-9) -> tuple[np.ndarray, np.ndarray]:
    """The sides of a closed turtle path: ``(lengths (s,), turns (s,))`` in degrees.

    Zero-length steps are dropped and consecutive collinear steps (``FORWARD 1 FORWARD 1``) merge
    into one side, also across the start, so the count is the number of sides a reader sees.
    turns[i] is the turn at the end of side i.

    >>> lengths, turns = sides_of(turtle.run("REPEAT 4 [FORWARD 1 FORWARD 1 TURN 90]")[0])
    >>> lengths.tolist(), turns.tolist()
    ([2.0, 2.0, 2.0, 2.0], [90.0, 90.0, 90.0, 90.0])
    """
    p = np.asarray(polyline, dtype=float)
    seg = np.diff(p, axis=0)
    lens = np.hypot(seg[:, 0], seg[:, 1])
    keep = lens > tol
    seg, lens = seg[keep], lens[keep]
    if len(seg) == 0:
        return np.zeros(0), np.zeros(0)
    nxt = np.roll(seg, -1, axis=0)
    cross = seg[:, 0] * nxt[:, 1] - seg[:, 1] * nxt[:, 0]
    dot = (seg * nxt).sum(axis=1)
    turns = np.degrees(np.arctan2(cross, dot))
    straight = np.abs(turns) < 1e-7
    if straight.all():
        return np.array([lens.sum()]), np.array([0.0])
    # rotate so that the last segment ends a side (a turn follows it), then merge straight runs
    last = int(np.flatnonzero(~straight)[-1])
    order = np.roll(np.arange(len(seg)), -(last + 1))
    lens, straight, turns = lens[order], straight[order], turns[order]
    side_id = np.concatenate(([0], np.cumsum(~straight[:-1])))
    merged = np.bincount(side_id, weights=lens)
    return merged, turns[~straight]


def _run(answer) -> tuple[list | None, Result | None]:
    if not isinstance(answer, str):
        return None, wrong(f"the answer should be a turtle program in quotes, like \"REPEAT 3 [FORWARD 1 TURN 120]\"; "
                           f"you gave {type(answer).__name__} {answer!r}.")
    try:
        return turtle.run(answer), None
    except ValueError as exc:
        return None, wrong(f"the program does not run: {exc}.")


def _check_closed_figure(answer, *, name, sides, side, turn, total, what) -> Result:
    if is_unanswered(answer):
        return unanswered(f"a turtle program (in quotes) for a {what}")
    polys, err = _run(answer)
    if err is not None:
        return err
    if not polys:
        return wrong("your program draws nothing: use FORWARD (MOVE does not draw).")
    if len(polys) > 1:
        return wrong(f"your drawing has {len(polys)} separate strokes (MOVE lifts the pen); "
                     f"draw the {name} in one stroke.")
    path = polys[0]
    gap = float(np.hypot(*(path[-1] - path[0])))
    if gap > 1e-6:
        return wrong(f"your path ends {fmt(gap, 3)} away from where it started: it does not close.")
    lengths, turns = sides_of(path)
    if len(lengths) < 2:
        return wrong("your path goes out and back along one line; it encloses nothing.")
    winding = float(turns.sum())
    if abs(abs(winding) - total) > 1e-6 and len(lengths) % sides == 0 and len(lengths) > sides:
        return wrong(f"you drew {len(lengths)} sides: the path goes round {len(lengths) // sides} times; "
                     f"a {name} needs {sides} sides, drawn once.")
    if len(lengths) != sides:
        return wrong(f"you drew {len(lengths)} sides, a {name} needs {sides}.")
    bad = np.flatnonzero(np.abs(lengths - side) > 1e-6)
    if bad.size:
        k = int(bad[0])
        return wrong(f"side {k + 1} has length {fmt(lengths[k])}; every side should be {fmt(side)}.")
    if not (np.allclose(turns, turn, atol=1e-6) or np.allclose(turns, -turn, atol=1e-6)):
        return wrong(f"your turtle turns by {', '.join(fmt(t) for t in turns)} degrees at its corners; "
                     f"a {name} turns by the same {fmt(turn)} degrees at every corner.")
    return correct(f"a {what} that closes: {sides} sides, each turn {fmt(turn)} degrees, "
                   f"total turning {fmt(abs(winding))}.")


def exercise_hexagon(answer) -> Result:
    """Exercise 1.1: write a turtle program that draws a regular hexagon with side 2 and closes
    (Goldman §1.3).

    answer: a program string.  Checks that it draws one stroke that closes, with 6 sides of
    length 2 and equal turns of 60 degrees (either way round).

    >>> exercise_hexagon("REPEAT 6 [FORWARD 1 TURN 60]")
    Not yet: side 1 has length 1; every side should be 2.
    """
    return _check_closed_figure(answer, name="hexagon", sides=6, side=2.0, turn=60.0, total=360.0,
                                what="regular hexagon with side 2")


def exercise_five_pointed_star(answer) -> Result:
    """Exercise 1.3: write a turtle program for the five-pointed star {5/2} with side 1
    (Goldman §1.3).

    answer: a program string.  Checks one closed stroke of 5 sides of length 1, each turn 144
    degrees (either way round), total turning 720.

    >>> exercise_five_pointed_star("REPEAT 5 [FORWARD 1 TURN 72]")
    Not yet: your turtle turns by 72, 72, 72, 72, 72 degrees at its corners; a five-pointed star turns by the same 144 degrees at every corner.
    """
    return _check_closed_figure(answer, name="five-pointed star", sides=5, side=1.0, turn=144.0, total=720.0,
                                what="five-pointed star {5/2} with side 1")


def exercise_star_angle(answer, n: int = 7, k: int = 3) -> Result:
    """Exercise 1.2: the TURN angle ``a`` for which ``REPEAT n [FORWARD 1 TURN a]`` draws the
    star polygon {n/k} (Goldman §1.3); by default {7/3}.

    answer: a number of degrees.  Accepts ``360k/n`` (or its clockwise twin ``-360k/n``, or any
    angle equal to these mod 360) within 0.01 degrees.

    >>> exercise_star_angle(360 * 3 / 7)
    Correct: the turning angle of the {7/3} star is 154.3 degrees (360k/n = 360*3/7).
    >>> exercise_star_angle(360 / 7)
    Not yet: 51.43 degrees draws the regular 7-gon {7/1}. The star {7/3} joins every 3rd point, so the turtle turns 3 times as far: 360*3/7.
    """
    what = f"the turning angle of the {{{n}/{k}}} star"
    a, problem = read_number(answer, what, "number of degrees")
    if problem is not None:
        return problem
    expected = 360.0 * k / n
    r = a % 360.0
    for target in (expected, 360.0 - expected):
        if min(abs(r - target), 360.0 - abs(r - target)) <= 0.01:
            return correct(f"{what} is {fmt(expected)} degrees (360k/n = 360*{k}/{n}).")
    if abs(r - 360.0 / n) <= 0.01 or abs(r - (360.0 - 360.0 / n)) <= 0.01:
        return wrong(f"{fmt(a)} degrees draws the regular {n}-gon {{{n}/1}}. The star {{{n}/{k}}} joins every "
                     f"{k}rd point, so the turtle turns {k} times as far: 360*{k}/{n}.".replace("1rd", "1st")
                     .replace("2rd", "2nd"))
    if abs(a - (180.0 - expected)) <= 0.01:
        return wrong(f"{fmt(a)} degrees is the angle inside each point of the star; the turtle turns by the "
                     f"exterior angle, 180 minus that.")
    return check_number(a, expected, what=what, tol=0.01,
                        hint=f"after n = {n} steps the turtle must have turned k = {k} full turns")


#: The program whose final state exercise 1.4 asks for.
FINAL_POSITION_PROGRAM = "FORWARD 2 TURN 90 FORWARD 1 TURN 90 MOVE 3 RESIZE 2 TURN -90 FORWARD 1"


def exercise_final_position(answer) -> Result:
    """Exercise 1.4: where does the turtle end after :data:`FINAL_POSITION_PROGRAM`, starting at
    (0, 0) heading (1, 0)?  (Goldman §1.2.)

    answer: the point ``(x, y)``.  Recognises the usual slips: turning clockwise for positive
    angles, forgetting RESIZE, treating MOVE as "no movement".

    >>> exercise_final_position((-1, 3))
    Correct: the turtle's final position matches.
    >>> exercise_final_position((-1, 2))
    Not yet: the turtle ends at (-1, 3), not (-1, 2): RESIZE 2 doubles w, so the last FORWARD 1 goes 2 units.
    """
    what = "the turtle's final position"
    if is_unanswered(answer):
        return unanswered(what)
    expected, _ = turtle.final_state(FINAL_POSITION_PROGRAM)
    try:
        got = np.asarray(answer, dtype=float)
    except (TypeError, ValueError):
        return wrong(f"{what} should be a point (x, y); you gave {answer!r}.")
    if got.shape != (2,):
        return wrong(f"{what} should be a point (x, y) with two numbers; you gave shape {got.shape}.")
    if np.all(np.abs(got - expected) <= 1e-6):
        return correct(f"{what} matches.")
    slips = {
        "RESIZE 2 doubles w, so the last FORWARD 1 goes 2 units":
            FINAL_POSITION_PROGRAM.replace("RESIZE 2", "RESIZE 1"),
        "TURN with a positive angle turns counterclockwise (to the left)":
            "FORWARD 2 TURN -90 FORWARD 1 TURN -90 MOVE 3 RESIZE 2 TURN 90 FORWARD 1",
        "MOVE 3 moves the turtle 3 steps without drawing":
            FINAL_POSITION_PROGRAM.replace("MOVE 3", "MOVE 0"),
    }
    for why, program in slips.items():
        if np.all(np.abs(got - turtle.final_state(program)[0]) <= 1e-6):
            return wrong(f"the turtle ends at {fmt(expected)}, not {fmt(got)}: {why}.")
    return check_points(got[None], expected[None], what=what,
                        hint="follow P and w command by command; TURN rotates w, RESIZE scales it")


def exercise_total_turning(answer) -> Result:
    """Exercise 1.5: the total turning, in degrees, of the turtle drawing the star {7/3} with
    ``REPEAT 7 [FORWARD 1 TURN 360*3/7]`` (Goldman §1.3).

    answer: a number.  The turtle returns to its initial state, so it turns a whole number of
    full turns: 3 * 360 = 1080.

    >>> exercise_total_turning(1080)
    Correct: the total turning is 1080 degrees: the turtle turns 3 full turns.
    >>> exercise_total_turning(360)
    Not yet: 360 is the total turning around a simple polygon; the {7/3} star winds round its centre 3 times, so the turtle turns 3 * 360 = 1080 degrees.
    """
    what = "the total turning"
    expected = turtle.total_turning(turtle.star(7, 3))
    a, problem = read_number(answer, what, "number of degrees")
    if problem is not None:
        return problem
    if abs(a - 360.0) <= 1e-6:
        return wrong("360 is the total turning around a simple polygon; the {7/3} star winds round its centre "
                     "3 times, so the turtle turns 3 * 360 = 1080 degrees.")
    if abs(a - 360.0 * 3 / 7) <= 0.01:
        return wrong(f"{fmt(a)} is the turn at one corner; the turtle makes 7 such turns.")
    if abs(a - expected) <= 1e-3:
        return correct(f"{what} is {fmt(expected)} degrees: the turtle turns 3 full turns.")
    return wrong(f"{what} should be {fmt(expected)}, you gave {fmt(a)}. Hint: add up the 7 turns; a turtle that "
                 f"returns to its initial state turns a whole number of times 360 degrees.")

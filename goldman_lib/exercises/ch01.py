"""Exercise checkers for chapter 1, turtle graphics (Goldman §1.2-1.3).

Each checker takes the learner's answer (a turtle program as a string, a number, or the turtle's
state) and returns a :class:`~goldman_lib.exercises.Result` that says why a wrong answer is wrong,
without giving the answer away.  ``None`` or ``...`` means "not answered yet".  ``PROBLEMS`` holds
the statements by checker name (built from the constants below, so statement and checker agree);
``SLIPS`` holds wrong answers of the kinds each checker recognises.

>>> check_star_program("REPEAT 10 [FORWARD 2 TURN 36]")
Not yet: that is the regular decagon {10/1}: every turn is 36 degrees. The star {10/3} joins every 3rd of the 10 points, so each turn is 3 times as large.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import fractals, turtle
from goldman_lib.exercises import far_off, guard_checkers, quote, clip
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, off_by, read_number, read_points, unanswered, wrong
from goldman_lib.fixed_point import hausdorff_distance

__all__ = ["PROBLEMS", "SLIPS", "STATE_PROGRAM", "POLYGON_INTERIOR", "POLYGON_SIDE", "STAR_N", "STAR_K",
           "STAR_SIDE", "CIRCLE_RADIUS", "CIRCLE_SIDES", "SPIRAL_PROGRAM", "ROSETTE_COPIES",
           "check_final_state", "check_polygon_program", "check_star_program", "check_circle_step",
           "check_spiral_ink", "check_rosette_program", "sides_of"]

#: Exercise 1.1 (§1.2): the program whose final state is asked for.
STATE_PROGRAM = "FORWARD 2 TURN 90 FORWARD 1 TURN 90 MOVE 3 RESIZE 2 TURN -90 FORWARD 1"
#: Exercise 1.2 (§1.3): the interior angle (degrees) and side of the regular polygon to draw.
POLYGON_INTERIOR, POLYGON_SIDE = 140, 1.5
#: Exercise 1.3 (§1.3): the star polygon {STAR_N/STAR_K} with side STAR_SIDE.
STAR_N, STAR_K, STAR_SIDE = 10, 3, 2
#: Exercise 1.4 (§1.3): REPEAT CIRCLE_SIDES [FORWARD d TURN 360/CIRCLE_SIDES] inscribed in a circle of CIRCLE_RADIUS.
CIRCLE_RADIUS, CIRCLE_SIDES = 2, 20
#: Exercise 1.5 (§1.3): the spiral whose ink (total length drawn) is asked for.
SPIRAL_PROGRAM = "REPEAT 8 [FORWARD 1 TURN 45 RESIZE 1.5]"
#: Exercise 1.6 (§1.3): the rosette of ROSETTE_COPIES unit squares.
ROSETTE_COPIES = 8

_STAR_TURN = 360 * STAR_K / STAR_N
_POLYGON_SIDES = round(360 / (180 - POLYGON_INTERIOR))

PROBLEMS = {
    "check_final_state": (
        f"The turtle starts at P = (0, 0) heading w = (1, 0) and runs {STATE_PROGRAM}. Give its final state "
        f"[P, w] = [[x, y], [w1, w2]]: where it is, and its direction vector (whose length is its step) "
        f"(Goldman §1.2)."),
    "check_polygon_program": (
        f"Write a turtle program that draws, in one closed stroke, the regular polygon whose interior angles "
        f"are all {POLYGON_INTERIOR} degrees, with sides of length {POLYGON_SIDE} (Goldman §1.3)."),
    "check_star_program": (
        f"Write a turtle program that draws the star polygon {{{STAR_N}/{STAR_K}}} with sides of length "
        f"{STAR_SIDE}, in one closed stroke (Goldman §1.3)."),
    "check_circle_step": (
        f"REPEAT {CIRCLE_SIDES} [FORWARD d TURN {fmt(360 / CIRCLE_SIDES)}] approximates a circle by a regular "
        f"{CIRCLE_SIDES}-gon. For which step d are its vertices on a circle of radius {CIRCLE_RADIUS}? "
        f"Give d to 4 decimals (Goldman §1.3)."),
    "check_spiral_ink": (
        f"How much ink does the spiral {SPIRAL_PROGRAM} use: the total length of the lines it draws, "
        f"starting with step |w| = 1? Give it to 3 decimals (Goldman §1.2-1.3)."),
    "check_rosette_program": (
        f"Write a turtle program with nested REPEATs for a rosette of {ROSETTE_COPIES} squares with side 1 "
        f"that all have one corner at the turtle's start, each square turned {fmt(360 / ROSETTE_COPIES)} "
        f"degrees from the one before, the turtle ending in its initial state (Goldman §1.3)."),
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


def _program(answer, what: str) -> tuple[str | None, Result | None]:
    if is_unanswered(answer):
        return None, unanswered(f"a turtle program (in quotes) for {what}")
    if not isinstance(answer, str):
        return None, wrong(f"the answer should be a turtle program in quotes, like \"REPEAT 3 [FORWARD 1 TURN 120]\"; "
                           f"you gave {type(answer).__name__} {quote(answer)}.")
    try:
        turtle.expand(answer)
    except ValueError as exc:
        return None, wrong(f"the program does not run: {clip(exc, 200)}.")
    return answer, None


def _turns(program: str) -> np.ndarray:
    """The TURN angles a program executes, in order."""
    codes, values = turtle.expand(program)
    return values[codes == turtle.TURN]


def _all_turns_are(program: str, angle: float) -> bool:
    turns = _turns(program)
    return turns.size > 0 and bool(np.all(np.abs(np.abs(turns) - angle) < 1e-6))


def _closed_figure(program: str, *, name: str, side: float, turn: float) -> tuple[np.ndarray | None, Result | None]:
    """Checks common to a polygon or star drawn in one closed stroke: one stroke that closes, equal
    sides of length ``side``.  Returns the side turns, or the verdict to return."""
    polys = turtle.run(program)
    if not polys:
        return None, wrong("your program draws nothing: use FORWARD (MOVE does not draw).")
    if len(polys) > 1:
        return None, wrong(f"your drawing has {len(polys)} separate strokes (MOVE lifts the pen); draw the {name} in "
                           f"one stroke.")
    path = polys[0]
    gap = turtle.closing_gap(path)
    if gap > 1e-6:
        return None, wrong(f"your path ends {fmt(gap, 3)} away from where it started: it does not close. The turns "
                           f"of a closed path add up to a whole number of full turns.")
    lengths, turns = sides_of(path)
    if len(lengths) < 2:
        return None, wrong("your path goes out and back along one line; it encloses nothing.")
    bad = np.flatnonzero(np.abs(lengths - side) > 1e-6)
    if bad.size:
        k = int(bad[0])
        return None, wrong(f"side {k + 1} has length {fmt(lengths[k])}; every side should be {fmt(side)} "
                           f"(FORWARD d goes d steps of |w|).")
    if not (np.allclose(turns, turns[0], atol=1e-6)):
        return None, wrong(f"your turtle turns by {', '.join(fmt(t) for t in turns)} degrees at its corners; a "
                           f"regular {name} turns by the same angle at every corner.")
    return turns, None


def check_final_state(answer) -> Result:
    """Exercise 1.1: the turtle's final state ``[P, w]`` after :data:`STATE_PROGRAM` (Goldman §1.2).

    answer: ``[[x, y], [w1, w2]]``.  Recognises the usual slips: TURN taken clockwise, RESIZE
    forgotten, MOVE taken as "no movement", the position alone.

    >>> check_final_state([[-1, 2], [0, 1]])
    Not yet: that is the state of the program without RESIZE 2: RESIZE s multiplies w by s, so every later step is s times as long.
    """
    what = "the final state [P, w]"
    got, problem = read_points(answer, what)
    if problem is not None:
        return problem
    if got.shape == (2,):
        return wrong("give both parts of the state, [[x, y], [w1, w2]]: the point P and the direction vector w.")
    if got.shape != (2, 2):
        return wrong(f"{what} should be two pairs [[x, y], [w1, w2]]; yours has shape {got.shape}.")
    p, w = turtle.final_state(STATE_PROGRAM)
    expected = np.array([p, w])
    if np.all(np.abs(got - expected) <= 1e-6):
        return correct(f"the turtle ends at P = {fmt(p)} heading w = {fmt(w)} (its step is now {fmt(np.hypot(*w))}).")
    slips = {
        "RESIZE s multiplies w by s, so every later step is s times as long":
            ("the program without RESIZE 2", STATE_PROGRAM.replace("RESIZE 2", "RESIZE 1")),
        "TURN a with a > 0 turns counterclockwise (to the left)":
            ("the program with every TURN clockwise",
             STATE_PROGRAM.replace("TURN 90", "TURN @").replace("TURN -90", "TURN 90").replace("@", "-90")),
        "MOVE d moves the turtle d steps like FORWARD, only without drawing":
            ("the program with MOVE 3 left out", STATE_PROGRAM.replace("MOVE 3", "MOVE 0")),
    }
    for why, (name, program) in slips.items():
        sp, sw = turtle.final_state(program)
        if np.all(np.abs(got - np.array([sp, sw])) <= 1e-6):
            return wrong(f"that is the state of {name}: {why}.")
    if np.all(np.abs(got[1] - w) <= 1e-6):
        return wrong(f"w is right, but P is {far_off(got[0], p)}; follow P command by "
                     f"command: FORWARD and MOVE add d*w to P.")
    if np.all(np.abs(got[0] - p) <= 1e-6):
        return wrong("P is right, but w is not: TURN rotates w, RESIZE scales it, and FORWARD and MOVE leave it "
                     "alone.")
    return wrong("both P and w are off; write down (P, w) after each command: FORWARD d and MOVE d add d*w to P, "
                 "TURN a rotates w by a degrees counterclockwise, RESIZE s multiplies w by s.")


def check_polygon_program(answer) -> Result:
    """Exercise 1.2: a program for the regular polygon with interior angles
    :data:`POLYGON_INTERIOR` and side :data:`POLYGON_SIDE` (Goldman §1.3), checked by running it and
    comparing the drawing.

    Recognises turning by the interior angle instead of the exterior one, another number of
    sides (naming that polygon's interior angle), wrong side lengths, an open path.
    """
    program, problem = _program(answer, f"the regular polygon with interior angles {POLYGON_INTERIOR}")
    if problem is not None:
        return problem
    if _all_turns_are(program, POLYGON_INTERIOR):
        return wrong(f"your turtle turns by the interior angle, {POLYGON_INTERIOR} degrees; at each corner it turns by "
                     f"the exterior angle, 180 minus the interior angle.")
    turns, problem = _closed_figure(program, name="polygon", side=POLYGON_SIDE, turn=180 - POLYGON_INTERIOR)
    if problem is not None:
        return problem
    n = len(turns)
    if abs(abs(float(turns.sum())) - 360) > 1e-6:
        return wrong(f"your path winds round {fmt(abs(turns.sum()) / 360)} times: that is a star, not a convex "
                     f"polygon; a convex polygon's turns add up to one full turn.")
    if n != _POLYGON_SIDES:
        return wrong(f"you drew a regular {n}-gon, whose interior angles are 180 - 360/{n} = "
                     f"{fmt(180 - 360 / n)} degrees, not {POLYGON_INTERIOR}: the exterior angles add up to 360, "
                     f"so 360 / (180 - interior) is the number of sides.")
    return correct(f"a regular {n}-gon with side {fmt(POLYGON_SIDE)}: the turtle turns by the exterior angle "
                   f"180 - {POLYGON_INTERIOR} = {fmt(180 - POLYGON_INTERIOR)} at each of its {n} corners.")


def check_star_program(answer) -> Result:
    """Exercise 1.3: a program for the star polygon {10/3} with side 2 (Goldman §1.3).

    Recognises the regular 10-gon (turn 360/n), the angle inside a point of the star (180 - 360k/n,
    which here draws a pentagon twice), and paths that retrace another polygon.

    >>> check_star_program("REPEAT 10 [FORWARD 2 TURN 72]")
    Not yet: 72 degrees is the angle inside each point of the star; the turtle turns by 180 minus that. (Turning 72 draws the pentagon {5/1} twice over.)
    """
    n, k = STAR_N, STAR_K
    program, problem = _program(answer, f"the star {{{n}/{k}}}")
    if problem is not None:
        return problem
    inside = 180 - _STAR_TURN
    if _all_turns_are(program, inside):
        extra = ""
        q = fractals.loop_period(inside)
        if q is not None and q < n:
            p = round(q * inside / 360)
            extra = f" (Turning {fmt(inside)} draws the {'pentagon' if q == 5 else 'polygon'} {{{q}/{p}}} {'twice' if n // q == 2 else f'{n // q} times'} over.)"
        return wrong(f"{fmt(inside)} degrees is the angle inside each point of the star; the turtle turns by 180 minus "
                     f"that.{extra}")
    if _all_turns_are(program, 360 / n):
        return wrong(f"that is the regular decagon {{{n}/1}}: every turn is {fmt(360 / n)} degrees. The star "
                     f"{{{n}/{k}}} joins every {k}rd of the {n} points, so each turn is {k} times as large.")
    turns, problem = _closed_figure(program, name="star", side=STAR_SIDE, turn=_STAR_TURN)
    if problem is not None:
        return problem
    winding = abs(float(turns.sum())) / 360
    if len(turns) % n == 0 and len(turns) > n:
        return wrong(f"you drew {len(turns)} sides: the path goes round {len(turns) // n} times; the star has {n} "
                     f"sides, drawn once.")
    if len(turns) != n:
        return wrong(f"you drew {len(turns)} sides; the star {{{n}/{k}}} has {n} points and {n} sides.")
    if abs(winding - k) > 1e-6:
        return wrong(f"your {n}-sided path winds round its centre {fmt(winding)} times; the star {{{n}/{k}}} winds "
                     f"{k} times (its turns add up to {k} full turns).")
    return correct(f"the star {{{n}/{k}}} with side {fmt(STAR_SIDE)}: {n} turns of 360*{k}/{n} = {fmt(_STAR_TURN)} "
                   f"degrees, {k} full turns in all.")


def check_circle_step(answer) -> Result:
    """Exercise 1.4: the step ``d`` of the regular 20-gon inscribed in a circle of radius 2
    (Goldman §1.3): the chord ``2 r sin(180/n)``.  Accepts 1e-4.

    Recognises the arc length ``2 pi r / n``, the half chord ``r sin(180/n)``, the sine of the full
    central angle, and the sine taken in radians.

    >>> check_circle_step(2 * math.pi * 2 / 20)
    Not yet: that is the arc length 2 pi r / n of one 20th of the circle; the turtle walks the chord, which is a little shorter (the chord of a central angle t is 2 r sin(t/2)).
    """
    what = "the step d"
    d, problem = read_number(answer, what)
    if problem is not None:
        return problem
    r, n = CIRCLE_RADIUS, CIRCLE_SIDES
    (path,) = turtle.run(turtle.circle(r, n))
    expected = float(np.hypot(*(path[1] - path[0])))
    if abs(d - expected) <= 1e-4:
        return correct(f"{what} is the chord 2 r sin(180/n) = {fmt(expected, 6)}, a little shorter than the arc "
                       f"2 pi r / n = {fmt(2 * math.pi * r / n, 6)}.")
    half = math.pi / n
    slips = [
        (2 * math.pi * r / n, f"that is the arc length 2 pi r / n of one {n}th of the circle; the turtle walks the "
                              f"chord, which is a little shorter (the chord of a central angle t is 2 r sin(t/2))"),
        (r * math.sin(half), "that is half the chord, r sin(t/2) (the distance from the chord's midpoint to its "
                             "end); the whole chord is twice as long"),
        (2 * r * math.sin(2 * half), "you took the sine of the whole central angle; the chord of a central angle t "
                                     "is 2 r sin(t/2)"),
        (2 * r * math.sin(math.degrees(half)), "your calculator took the angle in radians; set it to degrees"),
    ]
    for value, why in slips:
        if abs(d - value) <= 1e-4:
            return wrong(f"{why}.")
    return wrong(f"{what} is {off_by(d, expected)}. Hint: the {n} vertices split the circle into {n} equal central "
                 f"angles; each side is the chord of one of them.")


def check_spiral_ink(answer) -> Result:
    """Exercise 1.5: the ink of :data:`SPIRAL_PROGRAM` (Goldman §1.2-1.3): the geometric sum
    ``1 + 1.5 + ... + 1.5**7``.  Accepts 1e-3.

    Recognises RESIZE ignored, a ninth side counted, the last side alone, RESIZE taken as adding
    0.5 rather than multiplying by 1.5.

    >>> check_spiral_ink(8)
    Not yet: 8 is the ink of 8 sides of length 1: RESIZE 1.5 multiplies the step after every side.
    """
    what = "the ink"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    expected = turtle.length(turtle.run(SPIRAL_PROGRAM))
    if abs(value - expected) <= 1e-3:
        return correct(f"{what} is 1 + 1.5 + ... + 1.5^7 = (1.5^8 - 1) / (1.5 - 1) = {fmt(expected, 7)}.")
    slips = [
        (8.0, "8 is the ink of 8 sides of length 1: RESIZE 1.5 multiplies the step after every side"),
        ((1.5 ** 9 - 1) / 0.5, "you added a 9th side: the last RESIZE comes after the last FORWARD, so it lengthens "
                               "no side; the sides are 1, 1.5, ..., up to the 8th"),
        (1.5 ** 7, "that is the last side alone; the ink is the sum of all 8 sides"),
        (1.5 ** 8, "that is the step after the loop, not the ink; add up the 8 sides"),
        (sum(1 + 0.5 * i for i in range(8)), "RESIZE 1.5 multiplies the step by 1.5; it does not add 0.5 to it"),
    ]
    for v, why in slips:
        if abs(value - v) <= 1e-3:
            return wrong(f"{why}.")
    return wrong(f"{what} is {off_by(value, expected)}. Hint: side i (i = 0..7) has length 1.5^i; sum the geometric "
                 f"series.")


def _rosette_drawing(program: str) -> np.ndarray:
    return fractals.points_on(turtle.run(program), 8)


def check_rosette_program(answer) -> Result:
    """Exercise 1.6: a nested-REPEAT program for the rosette of 8 unit squares turned 45 degrees
    apart, ending in the initial state (Goldman §1.3).

    Compares the drawing (as a point set, so any order of drawing counts; the mirror image, with
    the squares turned clockwise, too) with :func:`goldman_lib.turtle.rosette`.  Recognises the
    TURN between copies left outside the outer REPEAT (one square), a turn of 90 between copies
    (4 squares), and a right drawing that leaves the turtle turned or moved.

    >>> check_rosette_program("REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90]] TURN 45")
    Not yet: your program draws one square, 8 times over: the TURN between copies must be inside the outer REPEAT's brackets.
    """
    m = ROSETTE_COPIES
    program, problem = _program(answer, f"the rosette of {m} squares")
    if problem is not None:
        return problem
    polys = turtle.run(program)
    if not polys:
        return wrong("your program draws nothing: use FORWARD (MOVE does not draw).")
    mine = _rosette_drawing(program)
    ref = _rosette_drawing(turtle.rosette(m, 4, 1))
    mirror = ref * np.array([1.0, -1.0])
    dist = min(hausdorff_distance(mine, ref), hausdorff_distance(mine, mirror))
    if dist > 1e-6:
        for slip, why in [
            ("REPEAT 4 [FORWARD 1 TURN 90]",
             f"your program draws one square, {m} times over: the TURN between copies must be inside the outer "
             f"REPEAT's brackets"),
            (turtle.rosette(4, 4, 1),
             f"your rosette has only 4 different squares: turning 90 degrees between copies brings copy 5 back onto "
             f"copy 1; {m} copies spread round a full turn are 360/{m} degrees apart"),
        ]:
            d = min(hausdorff_distance(mine, _rosette_drawing(slip)),
                    hausdorff_distance(mine, _rosette_drawing(slip) * np.array([1.0, -1.0])))
            if d <= 1e-6:
                return wrong(f"{why}.")
        return wrong(f"your drawing is {fmt(dist, 2)} away from the rosette (the farthest point of one drawing from "
                     f"the other). Hint: one copy is REPEAT 4 [FORWARD 1 TURN 90]; repeat it {m} times with a turn "
                     f"between copies.")
    p, w = turtle.final_state(program)
    if np.hypot(*p) > 1e-6 or np.hypot(*(w - [1.0, 0.0])) > 1e-6:
        p, w = np.round(p, 9) + 0.0, np.round(w, 9) + 0.0
        return wrong(f"the drawing is right, but the turtle ends at {fmt(p)} heading {fmt(w)}, not in its initial state "
                     f"(0, 0), (1, 0): the turns between copies should add up to full turns and end where they began.")
    return correct(f"a rosette of {m} squares, {fmt(360 / m)} degrees apart; the turtle turned "
                   f"{fmt(abs(turtle.total_turning(program)))} degrees in all and is back in its initial state.")


#: Wrong answers of the kinds each checker recognises (tests feed them in and check the reason).
SLIPS = {
    "check_final_state": [[[-1, 2], [0, 1]], [[-1, -3], [0, -2]], [[2, 3], [0, 2]], [[-1, 3], [0, 1]],
                          [[0, 3], [0, 2]], [-1, 3]],
    "check_polygon_program": ["REPEAT 9 [FORWARD 1.5 TURN 140]", "REPEAT 8 [FORWARD 1.5 TURN 45]",
                              "REPEAT 9 [FORWARD 1 TURN 40]", "REPEAT 8 [FORWARD 1.5 TURN 40]",
                              "REPEAT 9 [FORWARD 1.5 TURN 80]"],
    "check_star_program": ["REPEAT 10 [FORWARD 2 TURN 36]", "REPEAT 10 [FORWARD 2 TURN 72]",
                           "REPEAT 20 [FORWARD 2 TURN 108]", "REPEAT 10 [FORWARD 1 TURN 108]",
                           "REPEAT 7 [FORWARD 2 TURN 108]"],
    "check_circle_step": [2 * math.pi * 2 / 20, 2 * math.sin(math.radians(9)), 4 * math.sin(math.radians(18)),
                          4 * math.sin(9), 0.6],
    "check_spiral_ink": [8, (1.5 ** 9 - 1) / 0.5, 1.5 ** 7, 1.5 ** 8, 22, 50],
    "check_rosette_program": ["REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90]] TURN 45",
                              "REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90] TURN 90]",
                              "REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90] TURN 45] TURN 10",
                              "REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90] TURN 40]",
                              "REPEAT 8 [REPEAT 4 [FORWARD 1 TURN 90] TURN 45"],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

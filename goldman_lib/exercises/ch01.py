"""Exercise checkers for chapter 1, turtle graphics (Goldman §1.2-1.3).

Each checker takes the learner's answer (a turtle program as a string, a number, or the turtle's
state) and returns a :class:`~goldman_lib.exercises.Result` that says why a wrong answer is wrong,
without giving the answer away.  ``None`` or ``...`` means "not answered yet".  ``PROBLEMS`` holds
the statements by checker name (built from the constants below, so statement and checker agree);
``SLIPS`` holds wrong answers of the kinds each checker recognises (for the stored instances).

The numeric exercises (1.1 the final state, 1.4 a circle's step, 1.5 a spiral's ink) deal new
instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0 is the module constants
below, which the stored notebook shows; ``deal("check_...")`` (or the button beside the exercise)
deals another, and the checker, ``PROBLEMS`` and ``steps("check_...")`` follow the current
instance.  Exercises 1.2, 1.3 and 1.6 ask for a program (many programs are right, each checked by
running it), so they do not deal.

>>> check_star_program("REPEAT 10 [FORWARD 2 TURN 36]")
Not yet: that is the regular decagon {10/1}: every turn is 36 degrees. The star {10/3} joins every 3rd of the 10 points, so each turn is 3 times as large.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import fractals, turtle
from goldman_lib.exercises import far_off, guard_checkers, quote, clip
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, off_by, read_number, read_points, unanswered, wrong
from goldman_lib.exercises.deal import Deck, within
from goldman_lib.fixed_point import hausdorff_distance

__all__ = ["PROBLEMS", "SLIPS", "STATE_PROGRAM", "POLYGON_INTERIOR", "POLYGON_SIDE", "STAR_N", "STAR_K",
           "STAR_SIDE", "CIRCLE_RADIUS", "CIRCLE_SIDES", "SPIRAL_PROGRAM", "ROSETTE_COPIES",
           "check_final_state", "check_polygon_program", "check_star_program", "check_circle_step",
           "check_spiral_ink", "check_rosette_program", "sides_of", "DECK", "deal", "steps", "current",
           "deal_button"]

#: Exercise 1.1 (§1.2): the program whose final state is asked for.
STATE_PROGRAM = "FORWARD 2 TURN 90 FORWARD 1 TURN 90 MOVE 3 RESIZE 2 TURN -90 FORWARD 1"
#: Exercise 1.2 (§1.3): the interior angle (degrees) and side of the regular polygon to draw.
POLYGON_INTERIOR, POLYGON_SIDE = 140, 1.5
#: Exercise 1.3 (§1.3): the star polygon {STAR_N/STAR_K} with side STAR_SIDE.
STAR_N, STAR_K, STAR_SIDE = 10, 3, 2
#: Exercise 1.4 (§1.3): REPEAT CIRCLE_SIDES [FORWARD d TURN 360/CIRCLE_SIDES] inscribed in a circle of CIRCLE_RADIUS.
CIRCLE_RADIUS, CIRCLE_SIDES = 2, 20
#: Exercise 1.5 (§1.3): the spiral whose ink (total length drawn) is asked for: REPEAT SPIRAL_SIDES
#: [FORWARD 1 TURN SPIRAL_TURN RESIZE SPIRAL_FACTOR].
SPIRAL_SIDES, SPIRAL_TURN, SPIRAL_FACTOR = 8, 45, 1.5
SPIRAL_PROGRAM = f"REPEAT {SPIRAL_SIDES} [FORWARD 1 TURN {SPIRAL_TURN} RESIZE {SPIRAL_FACTOR}]"
#: Exercise 1.6 (§1.3): the rosette of ROSETTE_COPIES unit squares.
ROSETTE_COPIES = 8

_STAR_TURN = 360 * STAR_K / STAR_N
_POLYGON_SIDES = round(360 / (180 - POLYGON_INTERIOR))

_FIXED_PROBLEMS = {
    "check_polygon_program": (
        f"Write a turtle program that draws, in one closed stroke, the regular polygon whose interior angles "
        f"are all {POLYGON_INTERIOR} degrees, with sides of length {POLYGON_SIDE} (Goldman §1.3)."),
    "check_star_program": (
        f"Write a turtle program that draws the star polygon {{{STAR_N}/{STAR_K}}} with sides of length "
        f"{STAR_SIDE}, in one closed stroke (Goldman §1.3)."),
    "check_rosette_program": (
        f"Write a turtle program with nested REPEATs for a rosette of {ROSETTE_COPIES} squares with side 1 "
        f"that all have one corner at the turtle's start, each square turned {fmt(360 / ROSETTE_COPIES)} "
        f"degrees from the one before, the turtle ending in its initial state (Goldman §1.3)."),
}

DECK = Deck("ch01")


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


# -- exercise 1.1: the final state ------------------------------------------------------------------

def _commands(program: str) -> list[str]:
    """The commands of a flat program, as "NAME value" strings."""
    words = program.split()
    return [f"{words[i]} {words[i + 1]}" for i in range(0, len(words), 2)]


def _state_generate(rng) -> dict:
    a, b, c, d = (int(v) for v in rng.integers(1, 4, size=4))
    t1, t2, t3 = (int(v) for v in rng.choice([90, -90], size=3))
    s = [2, 3, 0.5][int(rng.integers(0, 3))]
    return {"program": f"FORWARD {a} TURN {t1} FORWARD {b} TURN {t2} MOVE {c} RESIZE {fmt(s)} TURN {t3} FORWARD {d}"}


def _state(program: str) -> np.ndarray:
    p, w = turtle.final_state(program)
    return np.array([p, w]) + 0.0


def _state_variants(program: str) -> dict:
    """The programs of the slips: RESIZE forgotten, every TURN clockwise, MOVE left out."""
    cmds = _commands(program)
    no_resize = [("RESIZE 1" if c.startswith("RESIZE") else c) for c in cmds]
    clockwise = [(f"TURN {fmt(-float(c.split()[1]))}" if c.startswith("TURN") else c) for c in cmds]
    no_move = [("MOVE 0" if c.startswith("MOVE") else c) for c in cmds]
    return {"resize": " ".join(no_resize), "clockwise": " ".join(clockwise), "move": " ".join(no_move)}


def _state_answer(p) -> np.ndarray:
    return _state(p["program"])


def _state_slips(p) -> dict:
    v = _state_variants(p["program"])
    return {"RESIZE forgotten": _state(v["resize"]), "TURN clockwise": _state(v["clockwise"]),
            "MOVE left out": _state(v["move"])}


def _state_ok(p):
    answer = _state_answer(p)
    if np.abs(answer).max() > 12:
        return "the turtle goes too far for a hand exercise"
    if np.allclose(answer[0], 0):
        return "the turtle ends where it began: P says nothing"
    return None


def _state_statement(p) -> str:
    return (f"The turtle starts at P = (0, 0) heading w = (1, 0) and runs {p['program']}. Give its final state "
            f"[P, w] = [[x, y], [w1, w2]]: where it is, and its direction vector (whose length is its step) "
            f"(Goldman §1.2).")


def _state_steps(p) -> str:
    cmds = _commands(p["program"])
    lines = ["Write down (P, w) after every command (FORWARD d and MOVE d add d w to P; TURN a rotates w by "
             "a degrees counterclockwise; RESIZE s multiplies w by s):", "",
             "| after | P | w |", "|---|---|---|", "| start | (0, 0) | (1, 0) |"]
    for k in range(1, len(cmds) + 1):
        P, w = turtle.final_state(" ".join(cmds[:k]))
        lines.append(f"| {cmds[k - 1]} | {fmt(np.round(P, 9) + 0.0)} | {fmt(np.round(w, 9) + 0.0)} |")
    return "\n".join(lines)


@DECK.exercise(stored={"program": STATE_PROGRAM}, generate=_state_generate, answer=_state_answer,
               slips=_state_slips, statement=_state_statement, steps=_state_steps, same=within(1e-6),
               well_posed=_state_ok)
def check_final_state(answer, p) -> Result:
    """Exercise 1.1: the turtle's final state ``[P, w]`` after the program of the statement (Goldman §1.2).

    answer: ``[[x, y], [w1, w2]]``.  Recognises the usual slips: TURN taken clockwise, RESIZE
    forgotten, MOVE taken as "no movement", the position alone.
    """
    what = "the final state [P, w]"
    got, problem = read_points(answer, what)
    if problem is not None:
        return problem
    if got.shape == (2,):
        return wrong("give both parts of the state, [[x, y], [w1, w2]]: the point P and the direction vector w.")
    if got.shape != (2, 2):
        return wrong(f"{what} should be two pairs [[x, y], [w1, w2]]; yours has shape {got.shape}.")
    expected = _state(p["program"])
    P, w = expected
    if np.all(np.abs(got - expected) <= 1e-6):
        return correct(f"the turtle ends at P = {fmt(P)} heading w = {fmt(w)} (its step is now {fmt(np.hypot(*w))}).")
    variants = _state_variants(p["program"])
    resize = next(c for c in _commands(p["program"]) if c.startswith("RESIZE"))
    move = next(c for c in _commands(p["program"]) if c.startswith("MOVE"))
    slips = {
        "RESIZE s multiplies w by s, so every later step is s times as long":
            (f"the program without {resize}", variants["resize"]),
        "TURN a with a > 0 turns counterclockwise (to the left)":
            ("the program with every TURN the other way", variants["clockwise"]),
        "MOVE d moves the turtle d steps like FORWARD, only without drawing":
            (f"the program with {move} left out", variants["move"]),
    }
    for why, (name, program) in slips.items():
        if np.all(np.abs(got - _state(program)) <= 1e-6):
            return wrong(f"that is the state of {name}: {why}.")
    if np.all(np.abs(got[1] - w) <= 1e-6):
        return wrong(f"w is right, but P is {far_off(got[0], P)}; follow P command by "
                     f"command: FORWARD and MOVE add d*w to P.")
    if np.all(np.abs(got[0] - P) <= 1e-6):
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


# -- exercise 1.4: a circle's step ---------------------------------------------------------------------

def _circle_generate(rng) -> dict:
    return {"r": int(rng.integers(1, 6)), "n": int(rng.choice([8, 9, 10, 12, 15, 18, 20, 24, 30, 36]))}


def _circle_answer(p) -> float:
    (path,) = turtle.run(turtle.circle(p["r"], p["n"]))
    return float(np.hypot(*(path[1] - path[0])))


def _circle_slips(p) -> dict:
    r, n = p["r"], p["n"]
    half = math.pi / n
    return {"the arc": 2 * math.pi * r / n, "the half chord": r * math.sin(half),
            "the sine of the whole angle": 2 * r * math.sin(2 * half),
            "radians": 2 * r * math.sin(math.degrees(half))}


def _circle_statement(p) -> str:
    r, n = p["r"], p["n"]
    return (f"REPEAT {n} [FORWARD d TURN {fmt(360 / n)}] approximates a circle by a regular "
            f"{n}-gon. For which step d are its vertices on a circle of radius {r}? "
            f"Give d to 4 decimals (Goldman §1.3).")


def _circle_steps(p) -> str:
    r, n = p["r"], p["n"]
    return (f"1. The {n} vertices cut the circle into {n} central angles of 360°/{n} = {fmt(360 / n)}°.\n"
            f"2. Each side is the chord of one of them; the chord of a central angle t in a circle of radius r "
            f"is 2 r sin(t/2).\n"
            f"3. d = 2 · {r} · sin({fmt(180 / n)}°) = {fmt(_circle_answer(p), 6)} (the arc 2 π r / n = "
            f"{fmt(2 * math.pi * r / n, 6)} is a little longer).")


@DECK.exercise(stored={"r": CIRCLE_RADIUS, "n": CIRCLE_SIDES}, generate=_circle_generate, answer=_circle_answer,
               slips=_circle_slips, statement=_circle_statement, steps=_circle_steps, same=within(1e-4))
def check_circle_step(answer, p) -> Result:
    """Exercise 1.4: the step ``d`` of the regular n-gon inscribed in a circle of radius r
    (Goldman §1.3): the chord of one central angle.  Accepts 1e-4.

    Recognises the arc length ``2 pi r / n``, the half chord, the sine of the full central angle,
    and the sine taken in radians.
    """
    what = "the step d"
    d, problem = read_number(answer, what)
    if problem is not None:
        return problem
    r, n = p["r"], p["n"]
    expected = _circle_answer(p)
    if abs(d - expected) <= 1e-4:
        return correct(f"{what} is the chord 2 r sin(180/n) = {fmt(expected, 6)}, a little shorter than the arc "
                       f"2 pi r / n = {fmt(2 * math.pi * r / n, 6)}.")
    slip = _circle_slips(p)
    why = {
        "the arc": f"that is the arc length 2 pi r / n of one {n}th of the circle; the turtle walks the "
                   f"chord, which is a little shorter (the chord of a central angle t is 2 r sin(t/2))",
        "the half chord": "that is half the chord, r sin(t/2) (the distance from the chord's midpoint to its "
                          "end); the whole chord is twice as long",
        "the sine of the whole angle": "you took the sine of the whole central angle; the chord of a central "
                                       "angle t is 2 r sin(t/2)",
        "radians": "your calculator took the angle in radians; set it to degrees",
    }
    for name, value in slip.items():
        if abs(d - value) <= 1e-4:
            return wrong(f"{why[name]}.")
    return wrong(f"{what} is {off_by(d, expected)}. Hint: the {n} vertices split the circle into {n} equal central "
                 f"angles; each side is the chord of one of them.")


# -- exercise 1.5: the ink of a spiral ------------------------------------------------------------------

def _spiral_program(p) -> str:
    return f"REPEAT {p['n']} [FORWARD 1 TURN {p['turn']} RESIZE {fmt(p['s'])}]"


def _spiral_generate(rng) -> dict:
    return {"n": int(rng.integers(4, 10)), "turn": int(rng.choice([30, 40, 45, 60, 72, 90, 120])),
            "s": float(rng.choice([1.25, 1.5, 2.0, 3.0]))}


def _spiral_answer(p) -> float:
    return turtle.length(turtle.run(_spiral_program(p)))


def _spiral_slips(p) -> dict:
    n, s = p["n"], p["s"]
    return {"RESIZE ignored": float(n), "one side too many": (s ** (n + 1) - 1) / (s - 1),
            "the last side": s ** (n - 1), "the step after the loop": s ** n,
            "RESIZE as adding": sum(1 + (s - 1) * i for i in range(n))}


def _spiral_ok(p):
    return "too much ink to add by hand" if _spiral_answer(p) > 2000 else None


def _spiral_statement(p) -> str:
    return (f"How much ink does the spiral {_spiral_program(p)} use: the total length of the lines it draws, "
            f"starting with step |w| = 1? Give it to 3 decimals (Goldman §1.2-1.3).")


def _spiral_steps(p) -> str:
    n, s = p["n"], fmt(p["s"])
    return (f"1. RESIZE {s} comes after each FORWARD, so the sides are 1, {s}, {s}^2, ..., {s}^{n - 1}: {n} sides "
            f"(the last RESIZE lengthens no side).\n"
            f"2. Their sum is the geometric series ({s}^{n} - 1) / ({s} - 1) = {fmt(_spiral_answer(p), 7)}.")


@DECK.exercise(stored={"n": SPIRAL_SIDES, "turn": SPIRAL_TURN, "s": SPIRAL_FACTOR}, generate=_spiral_generate,
               answer=_spiral_answer, slips=_spiral_slips, statement=_spiral_statement, steps=_spiral_steps,
               same=within(1e-3), well_posed=_spiral_ok)
def check_spiral_ink(answer, p) -> Result:
    """Exercise 1.5: the ink of the spiral of the statement (Goldman §1.2-1.3): a geometric sum of
    side lengths.  Accepts 1e-3.

    Recognises RESIZE ignored, one side too many, the last side alone, the step after the loop,
    RESIZE s taken as adding s - 1 rather than multiplying by s.
    """
    what = "the ink"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    n, s = p["n"], fmt(p["s"])
    expected = _spiral_answer(p)
    if abs(value - expected) <= 1e-3:
        return correct(f"{what} is 1 + {s} + ... + {s}^{n - 1} = ({s}^{n} - 1) / ({s} - 1) = {fmt(expected, 7)}.")
    why = {
        "RESIZE ignored": f"{n} is the ink of {n} sides of length 1: RESIZE {s} multiplies the step after every side",
        "one side too many": f"you added a {n + 1}th side: the last RESIZE comes after the last FORWARD, so it lengthens "
                             f"no side; there are {n} sides",
        "the last side": f"that is the last side alone; the ink is the sum of all {n} sides",
        "the step after the loop": "that is the step after the loop, not the ink; add up the sides",
        "RESIZE as adding": f"RESIZE {s} multiplies the step by {s}; it does not add {fmt(p['s'] - 1)} to it",
    }
    for name, v in _spiral_slips(p).items():
        if abs(value - v) <= 1e-3:
            return wrong(f"{why[name]}.")
    return wrong(f"{what} is {off_by(value, expected)}. Hint: side i (i = 0..{n - 1}) has length {s}^i; sum the "
                 f"geometric series.")


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


deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems(_FIXED_PROBLEMS)

# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

"""Exercise checkers for chapter 8, recursive turtle programs and conformal IFS (Goldman §8.2-8.5).

Each exercise's data are module constants (instance 0), so the notebook prints the problem from here and
the checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers each checker recognises.  ``None`` or ``...`` means "not answered yet".
Every exercise uses other states, programs and maps than the chapter's worked examples.  The
programming project, :func:`check_rons_algorithm_project`, runs the learner's Ron's algorithm
against :func:`goldman_lib.conformal_ifs.rons_algorithm` on generated programs.

Exercises 1, 2, 3 and 5 deal new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
``deal("check_moved_point")`` (or ``deal_button``) puts an exercise on a new seed, ``steps(...)`` shows
the library's worked steps of the current instance, and seed 0 is the instance the module constants
describe.  The rules for a well-posed instance sit beside each generator (points and directions a
learner computes with by hand; bodies consistent with their base case, so Ron's algorithm accepts
them; bumps of one-decimal points with one segment backwards).  Exercise 4 (Tao's algorithm) does not
deal: its answer is a program, and many bodies are right; nor does the programming project.

"Conformal" here means what the turtle can do: translation, rotation and uniform scaling, no mirror.

>>> print(PROBLEMS["check_moved_point"])
A turtle program drawn from the standard state ((0, 0), (1, 0)) passes through the point (1/2, 1/2). The same program is started at P = (-1, 2) with w = (1, 1). Where is that point drawn now? Give [x, y] (Goldman §8.2).
>>> check_moved_point([-0.5, 2.5])
Not yet: you translated by P but did not turn or scale: w = (1, 1) is turned 45 degrees and is sqrt(2) long, so the drawing turns and grows before it moves to P.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from goldman_lib import affine, fractals
from goldman_lib import conformal_ifs as cf
from goldman_lib.exercises import far_off, guard_checkers, quote, clip
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, read_points, unanswered, wrong
from goldman_lib.exercises.deal import Deck, memo
from goldman_lib.exercises.projects import Case, check_project
from goldman_lib.turtle import Turtle

__all__ = ["PROBLEMS", "SLIPS", "MOVED_POINT", "STATE_POINT", "STATE_DIRECTION", "LEVEL_BODY", "RON_BODY",
           "RON_CALL", "TAO_MAPS", "TAO_BASE", "BUMP_MAPS", "DECK", "deal", "steps", "current", "deal_button",
           "check_moved_point", "check_level_end", "check_ron_map",
           "check_tao_body", "check_bump_from_ifs", "check_rons_algorithm_project", "rons_project_cases",
           "parse_body", "call_states"]

R2 = math.sqrt(2.0)

#: Exercise 1 (§8.2): a point of the drawing from the standard state, and the new initial state.
MOVED_POINT = (0.5, 0.5)
STATE_POINT = (-1.0, 2.0)
STATE_DIRECTION = (1.0, 1.0)
#: Exercise 2 (§8.3): a body (base case FORWARD 1) whose level 1 ends elsewhere than its base case.
LEVEL_BODY = "RESIZE 1/2 RECURSE TURN 90 RECURSE TURN -90 RESIZE 2"
#: Exercise 3 (§8.4, Ron's algorithm): a body with base case FORWARD 1, and the call asked for (1-based).
RON_BODY = "RESIZE 1/4 RECURSE TURN 45 RESIZE sqrt2 RECURSE TURN -90 RECURSE TURN 45 RESIZE 1/sqrt2 RECURSE RESIZE 4"
RON_CALL = 3
#: Exercise 4 (§8.4, Tao's algorithm): the IFS to write a body for, and the base case (draws the unit
#: segment and comes home, as Tao's base cases do).
TAO_MAPS = (affine.similarity(0.5, 0), affine.similarity(0.5, 90, (1.0, 0.0)))
TAO_BASE = (("FORWARD", 1.0), ("MOVE", -1.0))
#: Exercise 5 (§8.5): the maps of a bump fractal (the second draws its segment backwards).
BUMP_MAPS = (cf.state_map((0.0, 0.0), (0.3, 0.4)), cf.state_map((0.6, 0.0), (-0.3, 0.4)),
             cf.state_map((0.6, 0.0), (0.4, 0.0)))


def _matrix_text(M) -> str:
    return "[" + ", ".join("[" + ", ".join(fmt(v + 0.0) for v in row) + "]" for row in np.asarray(M)) + "]"


# -- reading answers ---------------------------------------------------------------------------------

def _read_point(answer, what: str):
    got, err = read_points(answer, "your point", ask=what + " as [x, y]")
    if err is not None:
        return None, err
    if got.shape != (2,):
        return None, wrong(f"{what} should be one point [x, y]; yours has shape {got.shape}.")
    return got, None


def parse_body(text: str) -> list[tuple[str, float | None]]:
    """Read a body written as text: commands ``FORWARD d``, ``MOVE d``, ``TURN a``, ``RESIZE s`` and
    ``RECURSE``, separated by spaces, commas or line breaks; numbers may be fractions like 1/2 and
    may use ``sqrt2`` (``1/sqrt2``, ``sqrt2/2``).  Raises ValueError naming the token that is not
    understood.

    >>> parse_body("RESIZE 1/2 RECURSE MOVE 1")
    [('RESIZE', 0.5), ('RECURSE', None), ('MOVE', 1.0)]
    >>> parse_body("RESIZE 1/sqrt2")[0][1] == 1 / math.sqrt(2)
    True
    """
    def number(tok: str) -> float:
        tok = tok.lower()
        parts = tok.split("/")
        if len(parts) > 2:
            raise ValueError
        vals = [R2 if p in ("sqrt2", "sqrt(2)", "√2") else (-R2 if p in ("-sqrt2", "-sqrt(2)") else float(p))
                for p in parts]
        return vals[0] / vals[1] if len(vals) == 2 else vals[0]

    tokens = text.replace(",", " ").split()
    out, i = [], 0
    while i < len(tokens):
        word = tokens[i].upper()
        if word == "RECURSE":
            out.append(("RECURSE", None))
            i += 1
            continue
        if word not in ("FORWARD", "MOVE", "TURN", "RESIZE"):
            raise ValueError(f"{quote(tokens[i])} is not a command (FORWARD, MOVE, TURN, RESIZE, RECURSE)")
        if i + 1 >= len(tokens):
            raise ValueError(f"{word} needs a number after it")
        try:
            value = number(tokens[i + 1])
        except (ValueError, ZeroDivisionError):
            raise ValueError(f"{quote(tokens[i + 1])} after {word} is not a number") from None
        out.append((word, value))
        i += 2
    return out


def call_states(body, *, base_moves: float = 1.0, turn_sign: float = 1.0, resize: bool = True):
    """Run a body once from the standard state with the library's turtle, each RECURSE changing the
    state as a base case ``MOVE base_moves`` would; return the similarities ``state_map(P, w)`` of the
    states at the RECURSEs, and the final ``(P, w)``.  With ``turn_sign=-1`` every TURN is negated,
    with ``resize=False`` RESIZE is ignored: the states a learner who made those slips computes.

    >>> maps, (P, w) = call_states(parse_body("RESIZE 1/2 RECURSE RECURSE RESIZE 2"))
    >>> [M[2, :2].tolist() for M in maps], P.tolist(), w.tolist()
    ([[0.0, 0.0], [0.5, 0.0]], [1.0, 0.0], [1.0, 0.0])
    """
    t = Turtle()
    maps = []
    for cmd, value in body:
        if cmd == "RECURSE":
            maps.append(cf.state_map(t.point, t.direction))
            if base_moves:
                t.move(base_moves)
        elif cmd == "TURN":
            t.turn(turn_sign * value)
        elif cmd == "RESIZE":
            if resize:
                t.resize(value)
        elif cmd == "FORWARD":
            t.forward(value)
        elif cmd == "MOVE":
            t.move(value)
    return maps, (t.point.copy(), t.direction.copy())


def _program(body, base=(("FORWARD", 1.0),)):
    return fractals.RecursiveTurtleProgram(body, list(base))


DECK = Deck("ch08")


def _frac(x: float) -> str:
    """A coordinate as the fraction a learner reads (1/2, -3/2, 2)."""
    f = Fraction(float(x)).limit_denominator(12)
    return str(f.numerator) if f.denominator == 1 else f"{f.numerator}/{f.denominator}"


def _close(got, expected, tol: float = 1e-4) -> bool:
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    return got.shape == expected.shape and bool(np.allclose(got, expected, rtol=0, atol=tol))


def _point_close(a, b) -> bool:
    """The point checkers' tolerance: within 1e-4 (Euclidean)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and float(np.linalg.norm(a - b)) <= 1e-4


def _walk(text: str) -> str:
    """The turtle's state after each command of the body ``text`` (each RECURSE run as FORWARD 1):
    worked steps."""
    t = Turtle()
    tokens, lines = text.split(), []
    for cmd, value in parse_body(text):
        if cmd == "RECURSE":
            start = _pt(t.point)
            t.move(1.0)
            lines.append(f"RECURSE (as FORWARD 1) from P = {start} with w = {_pt(t.direction)}: P = {_pt(t.point)}")
            tokens = tokens[1:]
            continue
        written, tokens = tokens[1], tokens[2:]
        {"TURN": t.turn, "RESIZE": t.resize, "FORWARD": t.forward, "MOVE": t.move}[cmd](value)
        lines.append(f"{cmd} {written}: P = {_pt(t.point)}, w = {_pt(t.direction)}")
    return "\n".join(f"   - {line}" for line in lines)


def _pt(v) -> str:
    return fmt(np.round(np.asarray(v, dtype=float), 9) + 0.0, 6)


def _decimals(answer) -> str:
    """" Decimals to 4 places are fine." for an instance whose answer is not a short decimal (the
    checker's tolerance, 1e-4, takes a 4-place rounding); nothing for one that is (instance 0)."""
    values = np.ravel(np.asarray(answer, dtype=float))
    return "" if np.allclose(values, np.round(values, 3), rtol=0, atol=1e-9) else " Decimals to 4 places are fine."


# -- §8.2 ----------------------------------------------------------------------------------------------

#: Directions w of exercise 1: (w, its angle in degrees, its length as a learner writes it).
_MOVED_DIRECTIONS = {(1.0, 1.0): ("45", "sqrt(2)"), (2.0, 2.0): ("45", "2 sqrt(2)"), (0.0, 2.0): ("90", "2"),
                     (-1.0, 1.0): ("135", "sqrt(2)"), (-2.0, 2.0): ("135", "2 sqrt(2)"), (0.0, 3.0): ("90", "3"),
                     (-2.0, 0.0): ("180", "2")}
_STORED_MOVED = {"q": MOVED_POINT, "P": STATE_POINT, "w": STATE_DIRECTION}


@memo
def _moved_answers(p):
    q, P, w = np.array(p["q"]), np.array(p["P"]), np.array(p["w"])
    expected = affine.apply(q[None], cf.state_map(P, w))[0]
    angle = float(_MOVED_DIRECTIONS[tuple(p["w"])][0])
    slips = {"translated only": q + P, "clockwise": P + q[0] * w + q[1] * np.array([w[1], -w[0]]),
             "not moved": expected - P,
             "not scaled": affine.apply(q[None], affine.rotation(angle) @ affine.translation(P))[0]}
    return expected, slips


def _moved_generate(rng) -> dict:
    halves = (-1.0, -0.5, 0.5, 1.0, 1.5)
    dirs = list(_MOVED_DIRECTIONS)
    return {"q": (float(rng.choice(halves)), float(rng.choice(halves))),
            "P": tuple(float(v) for v in rng.integers(-3, 4, size=2)), "w": dirs[int(rng.integers(len(dirs)))]}


def _moved_ok(p):
    if not any(p["P"]):
        return "P is the origin (the translation could not be told)"
    return None


def _moved_statement(p) -> str:
    q = "(" + ", ".join(_frac(v) for v in p["q"]) + ")"
    return (f"A turtle program drawn from the standard state ((0, 0), (1, 0)) passes through the point {q}. "
            f"The same program is started at P = {fmt(p['P'])} with w = {fmt(p['w'])}. Where is that "
            f"point drawn now? Give [x, y] (Goldman §8.2).")


def _moved_steps(p) -> str:
    q, P, w = np.array(p["q"]), np.array(p["P"]), np.array(p["w"])
    perp = np.array([-w[1], w[0]])
    return (f"1. The map of the new state sends (0, 0) to P = {fmt(P)}, (1, 0) to P + w and (0, 1) to P + w_perp, "
            f"with w_perp = w turned 90 degrees counterclockwise = {fmt(perp)}.\n"
            f"2. So (x, y) goes to P + x w + y w_perp = {fmt(P)} + {fmt(q[0])} {fmt(w)} + {fmt(q[1])} {fmt(perp)}.\n"
            f"3. = {_pt(_moved_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_MOVED, generate=_moved_generate, answer=lambda p: _moved_answers(p)[0],
               slips=lambda p: _moved_answers(p)[1], statement=_moved_statement, steps=_moved_steps,
               same=_point_close, well_posed=_moved_ok)
def check_moved_point(answer, p) -> Result:
    """Check where the statement's point is drawn from the turtle state (P, w) it gives: the map
    sends (x, y) to P + x w + y w_perp (Goldman §8.2).

    Recognises a translation only, a clockwise turn, a turn without the scaling, a turn and scaling
    without the translation.
    """
    what = "the moved point"
    got, err = _read_point(answer, what)
    if err is not None:
        return err
    expected, slips = _moved_answers(p)
    w = np.array(p["w"])
    angle, length = _MOVED_DIRECTIONS[tuple(p["w"])]
    perp = fmt((-w[1], w[0]))
    tol = 1e-4
    if np.linalg.norm(got - expected) <= tol:
        return correct(f"the point is drawn at {fmt(expected)}: (x, y) goes to P + x w + y w_perp with "
                       f"w_perp = {perp}.")
    if np.linalg.norm(got - slips["translated only"]) <= tol:
        return wrong(f"you translated by P but did not turn or scale: w = {fmt(w)} is turned {angle} degrees and is "
                     f"{length} long, so the drawing turns and grows before it moves to P.")
    if np.linalg.norm(got - slips["clockwise"]) <= tol:
        return wrong(f"you turned the drawing clockwise: the heading turns from (1, 0) to w = {fmt(w)}, "
                     f"counterclockwise, so (0, 1) goes to the perpendicular {perp}, not {fmt((w[1], -w[0]))}.")
    if np.linalg.norm(got - slips["not moved"]) <= tol:
        return wrong("you turned and scaled the drawing but forgot to move it: the start (0, 0) goes to P.")
    if np.linalg.norm(got - slips["not scaled"]) <= tol:
        return wrong(f"you turned by {angle} degrees but kept the size: the step |w| = {length} scales the whole "
                     f"drawing.")
    return wrong(f"your point is {far_off(got, expected)} from where "
                 f"it is drawn; send (0, 0) to P and (1, 0) to P + w, and (0, 1) to P plus w turned 90 degrees "
                 f"counterclockwise.")


# -- §8.3 ----------------------------------------------------------------------------------------------

#: Exercise 2's resizes: the factor as written, its inverse as written, and the word for the step.
_LEVEL_RESIZES = {"1/2": ("2", "halved"), "1/3": ("3", "resized"), "1/4": ("4", "resized"), "2": ("1/2", "doubled")}
_STORED_LEVEL = {"resize": "1/2", "turn": 90.0}


def _level_body_text(p) -> str:
    back, _ = _LEVEL_RESIZES[p["resize"]]
    a = fmt(p["turn"])
    return f"RESIZE {p['resize']} RECURSE TURN {a} RECURSE TURN -{a} RESIZE {back}"


@memo
def _level_answers(p):
    body = parse_body(_level_body_text(p))
    expected = _program(body).trace(1).point
    slips = {"level 0": _program(body).trace(0).point, "calls that do not move": call_states(body, base_moves=0.0)[1][0],
             "no RESIZE": call_states(body, resize=False)[1][0], "clockwise": call_states(body, turn_sign=-1.0)[1][0]}
    return expected, slips


def _level_generate(rng) -> dict:
    return {"resize": str(rng.choice(list(_LEVEL_RESIZES))), "turn": float(rng.choice([90.0, 60.0, 45.0, 120.0]))}


def _level_statement(p) -> str:
    return (f"A recursive turtle program has base case FORWARD 1 and body {_level_body_text(p)}. From the standard "
            f"state ((0, 0), (1, 0)), where is the turtle at the end of level 1? Give P as [x, y], and compare it "
            f"with where level 0 ends (Goldman §8.3).{_decimals(_level_answers(p)[0])}")


def _level_steps(p) -> str:
    return (f"1. Level 1 runs the body once, each RECURSE running level 0, FORWARD 1, with the step and heading in "
            f"force at the call:\n{_walk(_level_body_text(p))}\n"
            f"2. Level 1 ends at P = {_pt(_level_answers(p)[0])}; level 0 ends at (1, 0).")


@DECK.exercise(stored=_STORED_LEVEL, generate=_level_generate, answer=lambda p: _level_answers(p)[0],
               slips=lambda p: _level_answers(p)[1], statement=_level_statement, steps=_level_steps,
               same=_point_close)
def check_level_end(answer, p) -> Result:
    """Check where level 1 of the statement's body ends: each call moves the turtle as FORWARD 1
    does, with the step and heading in force at the call (Goldman §8.3).

    Recognises the base case's end, calls that do not move the turtle, a forgotten RESIZE and a
    clockwise turn.
    """
    what = "the end of level 1"
    got, err = _read_point(answer, what)
    if err is not None:
        return err
    expected, slips = _level_answers(p)
    base_end = slips["level 0"]
    tol = 1e-4
    if np.linalg.norm(got - expected) <= tol:
        return correct(f"level 1 ends at {fmt(expected)}, but level 0 ends at {fmt(base_end)}: the levels change "
                       f"the turtle's state differently, so this program breaks the hypothesis of the equivalence "
                       f"theorem and Ron's algorithm refuses it (each call would be drawn from a state the maps "
                       f"cannot predict).")
    if np.linalg.norm(got - base_end) <= tol:
        return wrong(f"{fmt(base_end)} is where level 0, FORWARD 1, ends; level 1 runs the body, and each of its "
                     f"calls moves the turtle as FORWARD 1 does, with the step and heading in force at the call.")
    if np.linalg.norm(got - slips["calls that do not move"]) <= tol:
        return wrong("your calls did not move the turtle: at level 1 each RECURSE runs the base case FORWARD 1, "
                     "which moves it one (resized) step.")
    if np.linalg.norm(got - slips["no RESIZE"]) <= tol:
        return wrong(f"you left out RESIZE {p['resize']}: each call moves the turtle by the "
                     f"{_LEVEL_RESIZES[p['resize']][1]} step.")
    if np.linalg.norm(got - slips["clockwise"]) <= tol:
        return wrong(f"you turned clockwise: TURN {fmt(p['turn'])} turns the heading counterclockwise, from (1, 0) "
                     f"towards (0, 1).")
    return wrong(f"your point is {far_off(got, expected)} from the end "
                 f"of level 1; follow the body command by command, each RECURSE acting like FORWARD 1.")


# -- §8.4 ----------------------------------------------------------------------------------------------

#: Exercise 3's bodies: each is consistent with its base case FORWARD 1 (every level ends at
#: ((1, 0), (1, 0))), so Ron's algorithm accepts it; each is dealt as written or mirrored.
_RON_BODIES = (
    RON_BODY,
    "RESIZE 1/4 RECURSE TURN 60 RESIZE 2 RECURSE TURN -120 RECURSE TURN 60 RESIZE 1/2 RECURSE RESIZE 4",
    "RESIZE 1/3 RECURSE TURN 60 RECURSE TURN -120 RECURSE TURN 60 RECURSE RESIZE 3",
    "RESIZE 1/3 RECURSE TURN 90 RECURSE TURN -90 RECURSE TURN -90 RECURSE TURN 90 RECURSE RESIZE 3",
    "TURN 45 RESIZE 1/sqrt2 RECURSE TURN -90 RECURSE TURN 45 RESIZE sqrt2",
    "RESIZE 1/4 RECURSE TURN 90 RESIZE 2 RECURSE TURN -90 RECURSE TURN -90 RECURSE TURN 90 RESIZE 1/2 RECURSE RESIZE 4",
)
_STORED_RON = {"body": RON_BODY, "call": RON_CALL}


def _mirror(body_text: str) -> str:
    out, tokens = [], body_text.split()
    for i, tok in enumerate(tokens):
        if i > 0 and tokens[i - 1] == "TURN":
            tok = tok[1:] if tok.startswith("-") else "-" + tok
        out.append(tok)
    return " ".join(out)


@memo
def _ron_answers(p):
    body, c = parse_body(p["body"]), p["call"]
    expected = cf.rons_algorithm(_program(body)).maps[c - 1]
    maps, _ = call_states(body)
    slips = {"transposed": expected.T}
    for k, M in enumerate(maps, start=1):
        if k != c:
            slips[f"call {k}"] = M
    mirrored = expected.copy()
    mirrored[1, :2] = -mirrored[1, :2]
    slips.update({"calls that do not move": call_states(body, base_moves=0.0)[0][c - 1],
                  "clockwise": call_states(body, turn_sign=-1.0)[0][c - 1], "a reflection": mirrored})
    return expected, slips


def _ron_generate(rng) -> dict:
    text = _RON_BODIES[int(rng.integers(len(_RON_BODIES)))]
    if rng.integers(2):
        text = _mirror(text)
    return {"body": text, "call": int(rng.integers(2, text.count("RECURSE") + 1))}


def _ron_statement(p) -> str:
    c = p["call"]
    root = " (sqrt2 = 1.41421...)" if "sqrt2" in p["body"] else ""
    return (f"A recursive turtle program has base case FORWARD 1 and body {p['body']}{root}. By Ron's "
            f"algorithm, call number {c} gives the map T{c} sending the standard state ((0, 0), (1, 0)) "
            f"to the turtle's state at that call. Give T{c} as a 3x3 matrix in the row-vector convention "
            f"(Q = [x, y, 1] T, translation in the last row) (Goldman §8.4).{_decimals(_ron_answers(p)[0])}")


def _ron_steps(p) -> str:
    M = _ron_answers(p)[0]
    rows = "; ".join(_pt(r) for r in M)
    return (f"1. Walk the body, each RECURSE moving the turtle as FORWARD 1 does:\n{_walk(p['body'])}\n"
            f"2. At call {p['call']} the turtle is at P = {_pt(M[2, :2])} with w = {_pt(M[0, :2])}.\n"
            f"3. T{p['call']} has rows (w, 0), (w turned 90 degrees counterclockwise, 0), (P, 1): {rows}.")


@DECK.exercise(stored=_STORED_RON, generate=_ron_generate, answer=lambda p: _ron_answers(p)[0],
               slips=lambda p: _ron_answers(p)[1], statement=_ron_statement, steps=_ron_steps, same=_close)
def check_ron_map(answer, p) -> Result:
    """Check the matrix of the map of the statement's call of its body, in the row convention: the
    turtle's direction w, w turned 90 degrees and its position P as rows (Goldman §8.4).

    Recognises the transposed (column-vector) matrix, the map of another call, calls that do not
    move the turtle, clockwise turns, and a second row that reflects.
    """
    c = p["call"]
    what = f"T{c}"
    got, err = read_points(answer, "your matrix", ask=f"{what} as a 3x3 matrix [[.., .., 0], [.., .., 0], [.., .., 1]]")
    if err is not None:
        return err
    if got.shape != (3, 3):
        return wrong(f"{what} is a 3x3 matrix; yours has shape {got.shape}.")
    expected, slips = _ron_answers(p)
    tol = 1e-4
    if np.allclose(got, expected, atol=tol):
        P, w = expected[2, :2], expected[0, :2]
        return correct(f"{what} has last row (P, 1) with P = {fmt(P)} and first row (w, 0) with w = {fmt(w)}: the "
                       f"turtle's state at call {c}.")
    if np.allclose(got, expected.T, atol=tol):
        return wrong("that is the transposed matrix, for column vectors; here points are rows, Q = [x, y, 1] T, so "
                     "the translation is the last row and the first row is the image of (1, 0), the direction w.")
    body = parse_body(p["body"])
    maps, _ = call_states(body)
    for k, M in enumerate(maps, start=1):
        if k != c and np.allclose(got, M, atol=tol):
            return wrong(f"that is the map of call {k}; count the RECURSEs: call {c} comes after "
                         f"{c - 1} others, each moving the turtle one step.")
    if np.allclose(got, slips["calls that do not move"], atol=tol):
        return wrong("the direction is right but the point is not: each earlier RECURSE moves the turtle as the "
                     "base case FORWARD 1 does, one (resized) step along w.")
    if np.allclose(got, slips["clockwise"], atol=tol):
        turns = [v for cmd, v in body if cmd == "TURN"]
        pos = next((fmt(v) for v in turns if v > 0), None)
        neg = next((fmt(v) for v in turns if v < 0), None)
        told = ", and ".join(filter(None, [f"TURN {pos} turns w counterclockwise" if pos else "",
                                          f"TURN {neg} clockwise" if neg else ""]))
        return wrong(f"your turns go clockwise: {told}." if pos else f"your turns go the wrong way: {told}.")
    if np.allclose(got, slips["a reflection"], atol=tol):
        return wrong("your second row is (w_y, -w_x): that map reflects. The image of (0, 1) is w turned 90 degrees "
                     "counterclockwise, (-w_y, w_x).")
    if not np.allclose(got[:, 2], [0, 0, 1], atol=tol):
        return wrong("an affine matrix in the row-vector convention has last column (0, 0, 1); put P in the last "
                     "row, w in the first.")
    bad_p = np.linalg.norm(got[2, :2] - expected[2, :2]) > tol
    bad_w = np.linalg.norm(got[0, :2] - expected[0, :2]) > tol
    parts = []
    if bad_p:
        parts.append(f"the point P (last row) is {far_off(got[2, :2], expected[2, :2])}")
    if bad_w:
        parts.append(f"the direction w (first row) is {far_off(got[0, :2], expected[0, :2])}")
    if not parts:
        parts.append("the second row should be w turned 90 degrees counterclockwise")
    return wrong("; ".join(parts) + f". Follow the body to call {c}, each RECURSE acting like FORWARD 1.")



def _describe_map(M) -> str:
    P, w = M[2, :2], M[0, :2]
    heading = math.degrees(math.atan2(w[1], w[0])) + 0.0
    return f"at P = {fmt(P + 0.0)}, heading {fmt(round(heading, 6))} degrees, step {fmt(math.hypot(*w))}"


def check_tao_body(answer) -> Result:
    """Check a body whose IFS (base case FORWARD 1 MOVE -1) is ``TAO_MAPS`` (Goldman §8.4): any body
    whose calls are made at the two maps' states and that leaves the turtle where it started.

    >>> check_tao_body("RESIZE 1/2 RECURSE RESIZE 2 MOVE 1 TURN 90 RESIZE 1/2 RECURSE RESIZE 2 MOVE -1")
    Not yet: your body does not bring the turtle back: it ends at P = (1, -1), heading 90 degrees, step 1, but the base case ends where it started, at P = (0, 0), heading 0 degrees, step 1. Undo every TURN, MOVE and RESIZE after the last RECURSE, in reverse order (a heading not restored is the usual slip).
    """
    if is_unanswered(answer):
        return unanswered("a body in quotes, such as \"RESIZE 1/2 RECURSE ...\"")
    if not isinstance(answer, str):
        return wrong(f"give the body as a string of commands; you gave {type(answer).__name__}.")
    try:
        body = parse_body(answer)
        program = _program(body, TAO_BASE)
    except (TypeError, ValueError) as exc:
        return wrong(f"the body does not read: {clip(exc, 200)}.")
    maps, (P, w) = call_states(body, base_moves=0.0)
    home = cf.state_map((0, 0), (1, 0))
    if not np.allclose(cf.state_map(P, w), home, atol=1e-9):
        return wrong(f"your body does not bring the turtle back: it ends {_describe_map(cf.state_map(P, w))}, but "
                     f"the base case ends where it started, {_describe_map(home)}. Undo every TURN, MOVE and "
                     f"RESIZE after the last RECURSE, in reverse order (a heading not restored is the usual slip).")
    conv = cf.rons_algorithm(program)
    got = list(conv.maps)
    if len(got) != len(TAO_MAPS):
        return wrong(f"your body calls itself {len(got)} times; the IFS has {len(TAO_MAPS)} maps, one RECURSE each.")
    left = list(TAO_MAPS)
    unmatched = []
    for M in got:
        k = next((j for j, T in enumerate(left) if np.allclose(M, T, atol=1e-6)), None)
        if k is None:
            unmatched.append(M)
        else:
            del left[k]
    if not unmatched:
        return correct("Ron's algorithm reads T1 and T2 back from your body, and it leaves the turtle where it "
                       "started, like the base case.")
    M = unmatched[0]
    i = next(j for j, G in enumerate(got) if G is M) + 1
    hint = ""
    if abs(math.hypot(*M[0, :2]) - 0.5) > 1e-6:
        hint = " Both maps scale by 1/2: RESIZE 1/2 just before each RECURSE, RESIZE 2 just after."
    elif np.linalg.norm(M[2, :2] - [0.5, 0.0]) < 1e-6:
        hint = " A MOVE 1 made after RESIZE 1/2 goes only half as far: undo the RESIZE before you move."
    elif np.linalg.norm(M[2, :2] - [0.0, 1.0]) < 1e-6:
        hint = " MOVE goes along the current heading: MOVE 1 first, then TURN 90."
    elif np.linalg.norm(M[0, :2] - [0.0, -0.5]) < 1e-6:
        hint = " TURN 90 turns counterclockwise; a negative angle turns the wrong way."
    return wrong(f"call {i} of your body is made {_describe_map(M)}, which is neither T1 (at P = (0, 0), heading 0, "
                 f"step 1/2) nor T2 (at P = (1, 0), heading 90, step 1/2).{hint}")


# -- §8.5 ----------------------------------------------------------------------------------------------

def _bump_maps_of(points, backward: int) -> tuple:
    """The IFS of a bump: map i sends the unit segment onto segment i, segment ``backward`` reversed."""
    pts = np.asarray(points, dtype=float)
    maps = []
    for i in range(len(pts) - 1):
        A, B = pts[i], pts[i + 1]
        maps.append(cf.state_map(B, A - B) if i == backward else cf.state_map(A, B - A))
    return tuple(maps)


_STORED_BUMP = {"points": ((0.0, 0.0), (0.3, 0.4), (0.6, 0.0), (1.0, 0.0)), "backward": 1}
assert all(np.allclose(M, T) for M, T in zip(_bump_maps_of(_STORED_BUMP["points"], 1), BUMP_MAPS))


@memo
def _bump_answers(p):
    maps = _bump_maps_of(p["points"], p["backward"])
    expected, _ = cf.bump_of(list(maps))
    slips = {"in reverse": expected[::-1], "last rows as starts": np.array([M[2, :2] for M in maps] + [[1.0, 0.0]]),
             "first rows as points": np.array([[0.0, 0.0]] + [M[0, :2] for M in maps]),
             "no end point": expected[:-1]}
    return expected, slips


def _bump_generate(rng) -> dict:
    k = int(rng.integers(1, 3))          # interior points: a bump of 2 or 3 segments
    xs = np.sort(rng.choice(np.arange(1, 10), size=k, replace=False)) / 10
    ys = rng.choice([-0.4, -0.3, -0.2, 0.2, 0.3, 0.4, 0.5], size=k)
    pts = ((0.0, 0.0),) + tuple((float(x), float(y)) for x, y in zip(xs, ys)) + ((1.0, 0.0),)
    return {"points": pts, "backward": int(rng.integers(0, k + 1))}


def _bump_statement(p) -> str:
    maps = _bump_maps_of(p["points"], p["backward"])
    return ("This IFS draws a bump fractal: each map sends the unit segment from (0, 0) to (1, 0) onto one segment of "
            "the bump, one of them backwards (as in the dragon). "
            + "; ".join(f"T{i + 1} = {_matrix_text(M)}" for i, M in enumerate(maps))
            + " (row-vector convention, translation in the last row). Give the bump as its list of points "
              "[[x0, y0], [x1, y1], ...], from (0, 0) to (1, 0) (Goldman §8.5).")


def _bump_steps(p) -> str:
    maps = _bump_maps_of(p["points"], p["backward"])
    lines = [f"   - T{i + 1}: (0, 0) goes to P = {_pt(M[2, :2])}, (1, 0) to P + w = {_pt(M[2, :2] + M[0, :2])}"
             for i, M in enumerate(maps)]
    expected = _bump_answers(p)[0]
    return ("1. Each map sends (0, 0) to its last row P and (1, 0) to P + w (last row plus first row):\n"
            + "\n".join(lines) + "\n"
            f"2. Chain the segments from (0, 0): T{p['backward'] + 1} runs backwards (its P is where its segment "
            f"ends).\n3. The bump: {', '.join(_pt(q) for q in expected)}.")


@DECK.exercise(stored=_STORED_BUMP, generate=_bump_generate, answer=lambda p: _bump_answers(p)[0],
               slips=lambda p: _bump_answers(p)[1], statement=_bump_statement, steps=_bump_steps, same=_close)
def check_bump_from_ifs(answer, p) -> Result:
    """Check the bump read back from the statement's maps (Goldman §8.5): T_i sends (0, 0) to its last
    row P and (1, 0) to P + w (first row), so each map is one segment of the bump.

    Recognises the last rows taken as the segments' starts (missing the backward segment), the first
    rows taken as points, a missing end point and the bump in reverse.
    """
    got, err = read_points(answer, "your bump", ask="the bump as a list of points [[x0, y0], ...]")
    if err is not None:
        return err
    maps = _bump_maps_of(p["points"], p["backward"])
    expected, reverse = cf.bump_of(list(maps))
    n = len(expected)
    tol = 1e-4
    if got.ndim != 2 or got.shape[1:] != (2,):
        return wrong(f"give the bump as a list of points [[x0, y0], [x1, y1], ...]; yours has shape {got.shape}.")
    if got.shape == expected.shape and np.allclose(got, expected, atol=tol):
        return correct(f"the bump has {n} points; T{reverse[0] + 1} sends (0, 0) to the END of its segment, so "
                       f"it draws it backwards.")
    if got.shape[0] == n - 1:
        return wrong(f"a bump with {n - 1} maps has {n} points, one more than segments: from (0, 0) through the "
                     f"segments' joints to (1, 0).")
    if got.shape[0] != n:
        return wrong(f"a bump with {n - 1} maps has {n} points; yours has {got.shape[0]}.")
    if np.allclose(got, expected[::-1], atol=tol):
        return wrong("that is the bump in reverse; it runs from (0, 0), where T1 starts, to (1, 0).")
    starts = np.array([M[2, :2] for M in maps] + [[1.0, 0.0]])
    if np.allclose(got, starts, atol=tol):
        return wrong(f"you took each map's last row as the start of its segment; it is the image of (0, 0), and "
                     f"T{reverse[0] + 1} draws its segment backwards, so its last row is where its segment ENDS. "
                     f"Chain the segments: each begins where the one before ended.")
    rows = np.array([[0.0, 0.0]] + [M[0, :2] for M in maps])
    if np.allclose(got, rows, atol=tol):
        return wrong("the first row of a map is w, a direction, not a point: the image of (1, 0) is P + w, the "
                     "last row plus the first.")
    bad = [k for k in range(n) if np.linalg.norm(got[k] - expected[k]) > tol]
    k = bad[0]
    return wrong(f"point {k} of your bump is {far_off(got[k], expected[k])} from where it "
                 f"should be ({len(bad)} of {n} points are off). Each map sends (0, 0) to its last row P and "
                 f"(1, 0) to P + w; one of them runs backwards.")


#: Deal another instance of an exercise (``deal("check_moved_point")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
#: Exercise 4 asks for a program (a body for a given IFS; many bodies are right): it does not deal.
PROBLEMS = DECK.problems({"check_tao_body": (
    "Write the body of a recursive turtle program with base case FORWARD 1 MOVE -1 (it draws the unit segment "
    "and comes home) whose IFS is {T1: scale by 1/2; T2: scale by 1/2, rotate by 90 degrees, then translate "
    "by (1, 0)}, as Tao's algorithm does: for each map move the turtle (pen up) to the map's state, RECURSE, "
    "and move back. Give it as a string such as \"RESIZE 2 RECURSE TURN 90\" (Goldman §8.4).")})



# -- the programming project: Ron's algorithm (§8.4) -------------------------------------------------

_TURNS = (-150.0, -120.0, -90.0, -60.0, -45.0, -30.0, 30.0, 45.0, 60.0, 90.0, 120.0, 135.0, 180.0)
_RESIZES = (0.5, 0.25, 2.0, 0.75, 1.5)
_STEPS = (1.0, 0.5, -1.0, 2.0, 0.25)


def _closing(body) -> list:
    """Commands that take the turtle from where ``body`` leaves it (each RECURSE moving it as
    FORWARD 1) back to ``((1, 0), (1, 0))``, so the program is consistent with base case FORWARD 1."""
    _, (P, w) = call_states(body)
    return [(c, float(v)) for c, v in cf.move_commands(P, w, (1.0, 0.0), (1.0, 0.0))]


def _label(body) -> str:
    parts = []
    for c, v in body:
        parts.append(c if c == "RECURSE" else f"{c} {fmt(v)}")
    text = " ".join(parts)
    return text if len(text) <= 160 else text[:157] + "..."


def rons_project_cases() -> list[Case]:
    """The project's cases from a fixed seed: random bodies with 1 to 4 calls among TURN, RESIZE,
    FORWARD and MOVE, closed so that every level ends where FORWARD 1 does; plus the Koch curve and
    C-curve bodies, a single call (the identity map), two calls in the same state, a body that ends
    with its call, and a body with a full turn."""
    rng = np.random.default_rng(8)
    cases: list[Case] = []

    def add(body, kind=""):
        body = [(c, None if c == "RECURSE" else float(v)) for c, v in body]
        cases.append(Case(f"body {_label(body)}", (body,), kind=kind))

    add(fractals.koch_curve_program().body, "the Koch curve")
    add(fractals.c_curve_program().body, "the C-curve")
    for _ in range(6):
        body = []
        calls = int(rng.integers(1, 5))
        for _k in range(calls):
            for _j in range(int(rng.integers(1, 4))):
                kind = rng.choice(["TURN", "RESIZE", "FORWARD", "MOVE"])
                pool = _TURNS if kind == "TURN" else _RESIZES if kind == "RESIZE" else _STEPS
                body.append((str(kind), float(pool[int(rng.integers(len(pool)))])))
            body.append(("RECURSE", None))
        add(body + _closing(body), "random bodies")
    add([("RECURSE", None)], "a single call (the identity map)")
    add([("RESIZE", 0.5), ("RECURSE", None), ("MOVE", -1.0), ("RECURSE", None), ("MOVE", 1.0), ("RESIZE", 2.0)],
        "two calls in the same state")
    add([("FORWARD", 1.0), ("TURN", 90.0), ("FORWARD", 0.5), ("TURN", 180.0), ("MOVE", 0.5), ("TURN", 90.0),
         ("MOVE", -1.0), ("RECURSE", None)], "a body ending with its call")
    add([("TURN", 360.0), ("RESIZE", 0.5), ("RECURSE", None), ("TURN", -720.0), ("RECURSE", None), ("RESIZE", 2.0)],
        "full turns")
    return cases


def _rons_reference(body) -> np.ndarray:
    return cf.rons_algorithm(_program(body)).maps


def _compare_rons(got, expected, case) -> str | None:
    (body,) = case.args
    try:
        arr = np.asarray(got, dtype=float)
    except (TypeError, ValueError):
        return "it should be an array of 3x3 matrices, one per RECURSE"
    k = len(expected)
    if arr.shape != expected.shape:
        if arr.ndim == 3 and arr.shape[1:] == (3, 3):
            return f"it has {arr.shape[0]} maps; the body has {k} RECURSE{'s' if k != 1 else ''}, one map each"
        return f"it should have shape ({k}, 3, 3), one 3x3 matrix per RECURSE; yours has shape {arr.shape}"
    if not np.all(np.isfinite(arr)):
        return "it contains NaN or infinite values"
    err = np.abs(arr - expected).reshape(k, -1).max(axis=1)
    if err.max() <= 1e-8:
        return None
    if np.allclose(arr, expected.transpose(0, 2, 1), atol=1e-8):
        return ("your matrices are transposed (column-vector convention): here points are rows, Q = [x, y, 1] M, "
                "so the translation P goes in the last row and the direction w in the first")
    slips = [
        (dict(base_moves=0.0), "your calls do not move the turtle: each RECURSE changes the state as the base "
                               "case FORWARD 1 does, P <- P + w"),
        (dict(turn_sign=-1.0), "your turns go clockwise: TURN a turns w counterclockwise by a degrees"),
        (dict(resize=False), "you ignored RESIZE: it multiplies w, the turtle's step, by its factor"),
    ]
    for kwargs, text in slips:
        alt = np.array(call_states(body, **kwargs)[0])
        if alt.shape == expected.shape and np.allclose(arr, alt, atol=1e-8):
            return text
    i = int(np.argmax(err > 1e-8))
    M, E = arr[i], expected[i]
    mirror = E.copy()
    mirror[1, :2] = -mirror[1, :2]
    if np.allclose(M, mirror, atol=1e-8):
        return (f"map {i + 1} reflects: its second row should be w turned 90 degrees counterclockwise, "
                f"(-w_y, w_x), as in [[w_x, w_y, 0], [-w_y, w_x, 0], [P_x, P_y, 1]]")
    return (f"map {i + 1} (call {i + 1}) is off by {fmt(float(err[i]), 2)} in an entry: yours is the state "
            f"{_describe_map(M)}, but at that call the turtle is {_describe_map(E)}")


def check_rons_algorithm_project(function) -> Result:
    """Check the learner's ``rons_maps(body)`` against :func:`goldman_lib.conformal_ifs.rons_algorithm`
    on :func:`rons_project_cases` (base case FORWARD 1): one 3x3 map per RECURSE, in order (Goldman §8.4).

    >>> def at_origin(body):
    ...     return np.array([np.eye(3) for c, v in body if c == "RECURSE"])
    >>> print(check_rons_algorithm_project(at_origin).message)   # doctest: +ELLIPSIS
    case 1 of 12 (body RESIZE 0.3333 RECURSE TURN 60 ...): your function returned ...; map 1 (call 1) is off by 0.67 in an entry: ...
    """
    return check_project(function, rons_project_cases(), reference=_rons_reference, compare=_compare_rons,
                         what="rons_maps",
                         hint="walk the body once with the turtle; at each RECURSE record [[w_x, w_y, 0], "
                              "[-w_y, w_x, 0], [P_x, P_y, 1]], then move P by w as FORWARD 1 would")


SLIPS = {
    "check_moved_point": [[-0.5, 2.5], [0.0, 2.0], [0.0, 1.0], [-1.0, 2 + R2 / 2]],
    "check_level_end": [[1, 0], [0, 0], [1, 1], [0.5, -0.5]],
    "check_ron_map": [
        [[0.25, 0.25, 0.5], [-0.25, 0.25, 0.25], [0, 0, 1]],
        [[0.25, 0.25, 0], [-0.25, 0.25, 0], [0.25, 0, 1]],
        [[0.25, -0.25, 0], [0.25, 0.25, 0], [0, 0, 1]],
        [[0.25, 0.25, 0], [-0.25, 0.25, 0], [0.5, -0.25, 1]],
        [[0.25, -0.25, 0], [-0.25, -0.25, 0], [0.5, 0.25, 1]],
    ],
    "check_tao_body": [
        "RESIZE 1/2 RECURSE RESIZE 2 MOVE 1 TURN 90 RESIZE 1/2 RECURSE RESIZE 2 MOVE -1",
        "RESIZE 1/2 RECURSE RESIZE 2 TURN 90 MOVE 1 RESIZE 1/2 RECURSE RESIZE 2 MOVE -1 TURN -90",
        "RESIZE 1/2 RECURSE MOVE 1 TURN 90 RECURSE TURN -90 MOVE -1 RESIZE 2",
        "RESIZE 1/2 RECURSE RESIZE 2 MOVE 1 TURN -90 RESIZE 1/2 RECURSE RESIZE 2 TURN 90 MOVE -1",
    ],
    "check_bump_from_ifs": [
        [[0, 0], [0.3, 0.4], [0.6, 0]],
        [[1, 0], [0.6, 0], [0.3, 0.4], [0, 0]],
        [[0, 0], [0.6, 0], [0.6, 0], [1, 0]],
        [[0, 0], [0.3, 0.4], [-0.3, 0.4], [0.4, 0]],
    ],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

"""Exercise checkers for chapter 8, recursive turtle programs and conformal IFS (Goldman §8.2-8.5).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name.
``None`` or ``...`` means "not answered yet".

>>> print(PROBLEMS["check_bump_dimension"])
The square Koch curve replaces a segment by the bump (0, 0), (1/3, 0), (1/3, 1/3), (2/3, 1/3), (2/3, 0), (1, 0). Its IFS has one map per segment of the bump. What is the similarity dimension of the curve (Goldman §8.5, §3.2)?
>>> check_bump_dimension(math.log(5) / math.log(3))
Correct: the similarity dimension is 1.465: 5 maps of scale 1/3, so D = log 5 / log 3.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import affine, fractals
from goldman_lib import conformal_ifs as cf
from goldman_lib.exercises import (Result, check_number, correct, fmt, is_unanswered, read_points, unanswered,
                                   wrong)

__all__ = ["PROBLEMS", "STATE_POINT", "STATE_DIRECTION", "APEX", "TARGET_MAPS", "CANDIDATE_MAPS",
           "check_moved_apex", "check_call_state", "check_tao_body", "check_bump_dimension",
           "check_conformal_maps", "parse_body"]

#: Exercise 1: the new initial state of the Koch curve, and the apex of its level 1.
STATE_POINT = (2.0, 1.0)
STATE_DIRECTION = (0.0, 1.0)
APEX = (0.5, math.sqrt(3) / 6)
#: Exercise 3: the IFS whose turtle program is asked for (the two halves of the unit segment).
TARGET_MAPS = (affine.similarity(0.5, 0), affine.similarity(0.5, 0, (0.5, 0.0)))
#: Exercise 5: maps to sort into those a turtle can follow and those it cannot.
CANDIDATE_MAPS = {
    "A": ("scaling(1/2) about the origin", affine.scaling(0.5)),
    "B": ("scaling by 1/2 along x and 1/4 along y", affine.scaling([0.5, 0.25])),
    "C": ("similarity(1/2, 30°) with a reflection", affine.similarity(0.5, 30, reflect=True)),
    "D": ("rotation by 90° then translation by (1, 0)", affine.rotation(90) @ affine.translation([1, 0])),
    "E": ("the shear (x, y) -> (x + y/2, y)", affine.shear(0.5)),
}

PROBLEMS = {
    "check_moved_apex": (
        f"Level 1 of the Koch curve drawn from the standard state ((0, 0), (1, 0)) has its apex at "
        f"(1/2, sqrt(3)/6). The turtle now starts at P = {fmt(STATE_POINT)} heading w = {fmt(STATE_DIRECTION)}. "
        f"Where is the apex drawn? Give (x, y) (Goldman §8.2)."),
    "check_call_state": (
        "The C-curve's body is TURN 45 RESIZE 1/sqrt2 C TURN -90 C TURN 45 RESIZE sqrt2, and its base case "
        "FORWARD 1. Starting from ((0, 0), (1, 0)), what is the turtle's state (P, w) at the second recursive "
        "call C? Give [P, w] as [[Px, Py], [wx, wy]] (Goldman §8.4, Ron's algorithm)."),
    "check_tao_body": (
        "Write the body of a recursive turtle program with base case FORWARD 1 whose IFS (by Ron's "
        "algorithm) is {scale by 1/2 about (0, 0), scale by 1/2 then translate by (1/2, 0)}: the two halves "
        "of the unit segment. Give it as a string such as \"RESIZE 2 RECURSE TURN 90\" "
        "(Goldman §8.4, Tao's algorithm)."),
    "check_bump_dimension": (
        "The square Koch curve replaces a segment by the bump (0, 0), (1/3, 0), (1/3, 1/3), (2/3, 1/3), "
        "(2/3, 0), (1, 0). Its IFS has one map per segment of the bump. What is the similarity dimension of "
        "the curve (Goldman §8.5, §3.2)?"),
    "check_conformal_maps": (
        "Which of these maps can Tao's algorithm turn into turtle commands? "
        + "; ".join(f"{k}: {d}" for k, (d, _) in CANDIDATE_MAPS.items())
        + ". Answer with the set of letters, e.g. {\"A\", \"B\"} (Goldman §8.3-8.4)."),
}


def _moved(point) -> np.ndarray:
    return affine.apply(np.asarray(point, float)[None], cf.state_map(STATE_POINT, STATE_DIRECTION))[0]


def check_moved_apex(answer) -> Result:
    """Check where the Koch apex lands when the initial state changes (Goldman §8.2).

    >>> check_moved_apex([2 - math.sqrt(3) / 6, 1.5])
    Correct: the apex is drawn at (1.711, 1.5): the map sends (x, y) to (2 - y, 1 + x), a quarter turn then a translation by P.
    >>> check_moved_apex([2.5, 1 + math.sqrt(3) / 6])
    Not yet: you translated by P but did not turn: w = (0, 1) points up, so the whole drawing turns by 90 degrees (x, y) -> (-y, x) before it moves to P.
    """
    what = "the apex"
    got, err = read_points(answer, "your point", ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} should be one point [x, y]; yours has shape {got.shape}.")
    expected = _moved(APEX)
    if np.linalg.norm(got - expected) <= 1e-6:
        return correct(f"the apex is drawn at {fmt(expected)}: the map sends (x, y) to (2 - y, 1 + x), a quarter "
                       f"turn then a translation by P.")
    apex = np.array(APEX)
    if np.linalg.norm(got - (apex + STATE_POINT)) <= 1e-6:
        return wrong("you translated by P but did not turn: w = (0, 1) points up, so the whole drawing turns by "
                     "90 degrees (x, y) -> (-y, x) before it moves to P.")
    if np.linalg.norm(got - (np.array([apex[1], -apex[0]]) + STATE_POINT)) <= 1e-6:
        return wrong("you turned the drawing clockwise: the heading turns from (1, 0) to (0, 1), a counterclockwise "
                     "quarter turn (x, y) -> (-y, x).")
    if np.linalg.norm(got - np.array([-apex[1], apex[0]])) <= 1e-6:
        return wrong("you turned the drawing but forgot to move it: the start (0, 0) goes to P = (2, 1).")
    return wrong(f"your point is {fmt(np.linalg.norm(got - expected), 2)} from the apex; map the apex by the "
                 f"similarity sending (0, 0) to P and (1, 0) to P + w.")


def check_call_state(answer) -> Result:
    """Check the state at the C-curve's second recursive call (Goldman §8.4).

    >>> check_call_state([[0.5, 0.5], [0.5, -0.5]])
    Correct: at the second call P = (0.5, 0.5), w = (0.5, -0.5): the first call moved the turtle one (resized) step along w, and TURN -90 turned it.
    >>> check_call_state([[0, 0], [0.5, -0.5]])
    Not yet: your P is where the first call started: a recursive call moves the turtle, as its base case FORWARD 1 does, so the second call starts one step further along.
    """
    got, err = read_points(answer, "your state", ask="the state [[Px, Py], [wx, wy]]")
    if err is not None:
        return err
    if got.shape != (2, 2):
        return wrong(f"give the state as [[Px, Py], [wx, wy]]; yours has shape {got.shape}.")
    conv = cf.rons_algorithm(fractals.c_curve_program())
    T = conv.maps[1]
    P, w = T[2, :2], T[0, :2]
    if np.allclose(got, [P, w], atol=1e-6):
        return correct(f"at the second call P = {fmt(P)}, w = {fmt(w)}: the first call moved the turtle one "
                       f"(resized) step along w, and TURN -90 turned it.")
    if np.allclose(got[0], [0, 0], atol=1e-6):
        return wrong("your P is where the first call started: a recursive call moves the turtle, as its base case "
                     "FORWARD 1 does, so the second call starts one step further along.")
    if np.allclose(got[0], P, atol=1e-6) and np.allclose(np.hypot(*got[1]), 1.0, atol=1e-6):
        return wrong("P is right, but w is too long: RESIZE 1/sqrt2 shrank the step, so |w| = 1/sqrt2.")
    if np.allclose(got[0], P, atol=1e-6):
        return wrong(f"P is right, but w should be {fmt(w)}: heading 45 - 90 = -45 degrees, length 1/sqrt2.")
    return wrong(f"follow the body command by command from P = (0, 0), w = (1, 0); the first call ends at "
                 f"P + w, like FORWARD 1.")


def parse_body(text: str) -> list[tuple[str, float | None]]:
    """Read a body written as text: commands ``FORWARD d``, ``MOVE d``, ``TURN a``, ``RESIZE s`` and
    ``RECURSE``, separated by spaces, commas or line breaks; numbers may be fractions like 1/2.
    Raises ValueError naming the token that is not understood.

    >>> parse_body("RESIZE 1/2 RECURSE MOVE 1")
    [('RESIZE', 0.5), ('RECURSE', None), ('MOVE', 1.0)]
    """
    tokens = text.replace(",", " ").split()
    out, i = [], 0
    while i < len(tokens):
        word = tokens[i].upper()
        if word == "RECURSE":
            out.append(("RECURSE", None))
            i += 1
            continue
        if word not in ("FORWARD", "MOVE", "TURN", "RESIZE"):
            raise ValueError(f"{tokens[i]!r} is not a command (FORWARD, MOVE, TURN, RESIZE, RECURSE)")
        if i + 1 >= len(tokens):
            raise ValueError(f"{word} needs a number after it")
        num = tokens[i + 1]
        try:
            if "/" in num:
                a, b = num.split("/")
                value = float(a) / float(b)
            else:
                value = float(num)
        except (ValueError, ZeroDivisionError):
            raise ValueError(f"{num!r} after {word} is not a number") from None
        out.append((word, value))
        i += 2
    return out


def check_tao_body(answer) -> Result:
    """Check a body whose IFS is the two halves of the unit segment (Goldman §8.4).

    >>> check_tao_body("RESIZE 1/2 RECURSE RECURSE RESIZE 2")
    Correct: Ron's algorithm finds the maps scale 1/2 at (0, 0) and scale 1/2 at (0.5, 0): the first call ends where the second begins.
    >>> check_tao_body("RESIZE 1/2 RECURSE RECURSE")
    Not yet: the program is not consistent: the base case leaves the turtle at point (1, 0), direction (1, 0) but level 1 leaves it at point (1, 0), direction (0.5, 0) (from the standard state); Ron's algorithm needs every level to change the turtle's state the same way (Goldman §8.3). Undo the RESIZE and TURN commands at the end of the body.
    """
    if is_unanswered(answer):
        return unanswered("a body in quotes, such as \"RESIZE 1/2 RECURSE ...\"")
    if not isinstance(answer, str):
        return wrong(f"give the body as a string of commands; you gave {type(answer).__name__}.")
    try:
        body = parse_body(answer)
        program = fractals.RecursiveTurtleProgram(body, [("FORWARD", 1.0)])
    except (TypeError, ValueError) as exc:
        return wrong(f"the body does not read: {exc}.")
    try:
        conv = cf.rons_algorithm(program)
    except ValueError as exc:
        message = str(exc).replace("the program: ", "")
        end = program.trace(1, max_commands=10_000)
        if not (abs(end.direction[0] - 1) < 1e-9 and abs(end.direction[1]) < 1e-9):
            hint = " Undo the RESIZE and TURN commands at the end of the body."
        else:
            hint = " The body must end where FORWARD 1 ends, at (1, 0)."
        return wrong(f"the program is not consistent: {message}.{hint}")
    maps = list(conv.maps)
    if len(maps) != len(TARGET_MAPS):
        return wrong(f"your body calls itself {len(maps)} times; the IFS has {len(TARGET_MAPS)} maps, one RECURSE each.")
    if cf._maps_match(maps, list(TARGET_MAPS), 1e-6):
        return correct("Ron's algorithm finds the maps scale 1/2 at (0, 0) and scale 1/2 at (0.5, 0): the first "
                       "call ends where the second begins.")
    scales = [math.sqrt(abs(np.linalg.det(M[:2, :2]))) for M in maps]
    if any(abs(s - 0.5) > 1e-6 for s in scales):
        return wrong(f"your calls are drawn at scales {', '.join(fmt(s) for s in scales)}; both halves need RESIZE 1/2.")
    starts = [fmt(M[2, :2]) for M in maps]
    return wrong(f"your calls start at {', '.join(starts)} with headings "
                 f"{', '.join(fmt(round(affine.to_parameters(M)['angle'], 6)) for M in maps)} degrees; they should "
                 f"start at (0, 0) and (0.5, 0), both heading along the x-axis.")


def check_bump_dimension(answer) -> Result:
    """Check the similarity dimension of the square Koch curve (Goldman §8.5).

    >>> check_bump_dimension(math.log(4) / math.log(3))
    Not yet: log 4 / log 3 is the Koch curve's dimension (4 segments); this bump has 5 segments of length 1/3. Hint: count the segments of the bump: each is a map of scale 1/3.
    """
    poly, rev = cf.BUMPS["square Koch curve"]
    system = cf.bump_ifs(poly, rev)
    scales = np.sqrt(np.abs(np.linalg.det(system.maps[:, :2, :2])))
    expected = fractals.similarity_dimension(scales)
    if not is_unanswered(answer):
        try:
            v = float(answer)
        except (TypeError, ValueError):
            v = None
        if v is not None and abs(v - math.log(4) / math.log(3)) <= 1e-6:
            return wrong("log 4 / log 3 is the Koch curve's dimension (4 segments); this bump has 5 segments of "
                         "length 1/3. Hint: count the segments of the bump: each is a map of scale 1/3.")
        if v is not None and abs(v - expected) <= 1e-6:
            return correct(f"the similarity dimension is {fmt(expected)}: {len(scales)} maps of scale 1/3, so "
                           f"D = log 5 / log 3.")
    return check_number(answer, expected, what="the similarity dimension",
                        hint="solve 5 (1/3)^D = 1")


def check_conformal_maps(answer) -> Result:
    """Check which maps a turtle can follow (Goldman §8.3-8.4): orientation-preserving similarities.

    >>> check_conformal_maps({"A", "D"})
    Correct: A and D are similarities that keep orientation: a MOVE, a TURN and a RESIZE reach their states.
    >>> check_conformal_maps({"A", "C", "D"})
    Not yet: C is conformal but reverses orientation (a reflection): a turtle's MOVE, TURN and RESIZE never mirror the drawing.
    """
    if is_unanswered(answer):
        return unanswered("a set of letters, such as {\"A\", \"B\"}")
    if isinstance(answer, str):
        answer = set(answer.replace(",", " ").split()) if len(answer) > 1 else {answer}
    try:
        chosen = {str(a).strip().upper() for a in answer}
    except TypeError:
        return wrong(f"give a set of letters such as {{\"A\", \"B\"}}; you gave {answer!r}.")
    unknown = chosen - set(CANDIDATE_MAPS)
    if unknown:
        return wrong(f"{', '.join(sorted(unknown))} is not one of the maps {', '.join(CANDIDATE_MAPS)}.")
    ok = set()
    reasons = {}
    for k, (_, M) in CANDIDATE_MAPS.items():
        if not affine.is_conformal(M):
            reasons[k] = (f"{k} is not conformal: it stretches one direction more than another (or shears), "
                          f"which no RESIZE can do")
        elif np.linalg.det(M[:2, :2]) < 0:
            reasons[k] = (f"{k} is conformal but reverses orientation (a reflection): a turtle's MOVE, TURN and "
                          f"RESIZE never mirror the drawing")
        else:
            ok.add(k)
    if chosen == ok:
        return correct(f"{' and '.join(sorted(ok))} are similarities that keep orientation: a MOVE, a TURN and a "
                       f"RESIZE reach their states.")
    extra = sorted(chosen - ok)
    if extra:
        return wrong(reasons[extra[0]] + ".")
    missing = sorted(ok - chosen)
    return wrong(f"{missing[0]} can be followed too: it is a rotation, a uniform scaling and a translation, "
                 f"which are TURN, RESIZE and MOVE.")

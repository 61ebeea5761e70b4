"""Exercise checkers for chapter 2, recursive turtle programs (Goldman §2.2-2.3), and the
chapter's programming project.

Each checker takes the learner's answer and returns a :class:`~goldman_lib.exercises.Result`
saying right or wrong and why, never what the answer is; ``None`` or ``...`` means "not answered
yet".  ``PROBLEMS`` holds the statements by checker name (built from the constants below);
``SLIPS`` the wrong answers of the kinds each checker recognises.  The project checker
:func:`check_quadratic_koch_project` runs the learner's recursive function against
:func:`goldman_lib.fractals.quadratic_koch_program` at levels 0-4.

>>> check_loop_period(6)
Not yet: 6 is the period of TURN 60 alone; one pass turns the turtle by the sum of its TURNs, and that total decides when it is back.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import fractals, turtle
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "LOOP_PASS", "STAR_PASSES", "CENTRE_PASS", "GASKET_SIDES", "C_CURVE_LEVEL",
           "PROJECT_SEED", "check_loop_period", "check_star_angle", "check_loop_centre", "check_gasket_scale",
           "check_c_curve_commands", "check_quadratic_koch_project"]

#: Exercise 2.1 (§2.2): the pass whose period is asked for (total turning 84 = 360 * 7/30).
LOOP_PASS = "FORWARD 1 TURN 60 FORWARD 2 TURN 24"
#: Exercise 2.2 (§2.2): the number of passes after which the star must close.
STAR_PASSES = 9
#: Exercise 2.3 (§2.2): the pass whose centre of rotation is asked for.
CENTRE_PASS = "FORWARD 1 TURN 90 FORWARD 1 TURN -30"
#: Exercise 2.4 (§2.3): the polygon gasket whose scale is asked for (the octagonal gasket).
GASKET_SIDES = 8
#: Exercise 2.5 (§2.3): the level of the C-curve whose commands are counted.
C_CURVE_LEVEL = 6
#: The programming project's cases come from this seed (the turtle's other starting states).
PROJECT_SEED = 2024

_LOOP_TURNS = [float(v) for v in LOOP_PASS.split()[3::4]]

PROBLEMS = {
    "check_loop_period": (
        f"After how many repetitions does REPEAT k [{LOOP_PASS}] first bring the turtle back to its initial "
        f"state (position and heading)? (Goldman §2.2)"),
    "check_star_angle": (
        f"Give a TURN angle a (degrees, between 0 and 360) for which REPEAT {STAR_PASSES} [FORWARD 1 TURN a] "
        f"returns to its initial state after exactly {STAR_PASSES} passes (not fewer) and draws a star, "
        f"not a convex polygon (Goldman §2.2)."),
    "check_loop_centre": (
        f"The turtle starts at (0, 0) heading (1, 0) and repeats the pass {CENTRE_PASS}. Every pass is the "
        f"one before rotated about one centre c. Give c = (x, y) to 4 decimals (Goldman §2.2)."),
    "check_gasket_scale": (
        f"The octagonal gasket: level 0 is a regular octagon with side 1; level n is REPEAT {GASKET_SIDES} "
        f"[RESIZE r, RECURSE, RESIZE 1/r, MOVE 1, TURN {fmt(360 / GASKET_SIDES)}], a copy scaled by r at each "
        f"corner. For which r do neighbouring copies just touch? Give r to 4 decimals (Goldman §2.3)."),
    "check_c_curve_commands": (
        f"The C-curve: level 0 is FORWARD 1; level n is TURN 45, RESIZE 1/sqrt(2), C, TURN -90, C, TURN 45, "
        f"RESIZE sqrt(2), where C runs level n-1. How many turtle commands (FORWARD, TURN and RESIZE each "
        f"count one) does level {C_CURVE_LEVEL} execute? (Goldman §2.3)"),
}


def check_loop_period(answer) -> Result:
    """Exercise 2.1: the period of ``REPEAT k [FORWARD 1 TURN 60 FORWARD 2 TURN 24]`` (Goldman §2.2,
    looping lemma): the least number of passes whose total turning is a multiple of 360.

    answer: a whole number.  Recognises the period of one TURN alone, 360/T (not whole), a later
    multiple, the winding number given instead of the period.
    """
    what = "the number of repetitions"
    k, problem = read_number(answer, what, "whole number")
    if problem is not None:
        return problem
    loop = fractals.loop_analysis(LOOP_PASS)
    T = round(loop.total_turning)
    q, p = loop.period, loop.winding
    if k > 1e6:
        return wrong(f"{fmt(k)} passes is far too many; the looping lemma gives a period below 360.")
    if k != int(k) or k < 1:
        return wrong(f"{fmt(k)} is not a whole number of repetitions: 360/{T} is not whole, so one full turn of the "
                     f"heading is not enough; find the least k with k * {T} a multiple of 360.")
    k = int(k)
    if k == q:
        return correct(f"one pass turns {' + '.join(fmt(t) for t in _LOOP_TURNS)} = {T} degrees = 360 * {p}/{q}: "
                       f"the turtle is first back after {q} passes, having wound {p} times round the centre.")
    for t in _LOOP_TURNS:
        if k == fractals.loop_period(t):
            return wrong(f"{k} is the period of TURN {fmt(t)} alone; one pass turns the turtle by the sum of its "
                         f"TURNs, and that total decides when it is back.")
    if (k * T) % 360 == 0:
        return wrong(f"after {k} passes the turtle is indeed back ({k} * {T} = {k * T} = {k * T // 360} * 360), but "
                     f"it was already back after fewer: look for the least k with k * {T} a multiple of 360.")
    if k == p:
        return wrong(f"{k} is how many full turns the turtle makes before it is back (the winding number); the "
                     f"question asks for the number of passes.")
    return wrong(f"after {k} passes the turtle has turned {k} * {T} = {k * T} degrees, not a multiple of 360, so it "
                 f"is not back: by the looping lemma it returns exactly when k * {T} is a multiple of 360.")


def check_star_angle(answer) -> Result:
    """Exercise 2.2: an angle ``a`` for which ``REPEAT 9 [FORWARD 1 TURN a]`` closes after exactly 9
    passes and draws a star (Goldman §2.2).  Every such angle is accepted, within 0.01 degrees."""
    what = "the TURN angle"
    a, problem = read_number(answer, what, "number of degrees")
    if problem is not None:
        return problem
    if abs(a) > 1e6:
        return wrong(f"{fmt(a)} degrees turns the turtle round thousands of times in one TURN; give an angle "
                     f"between -360 and 360.")
    n = STAR_PASSES
    near = round(n * a / 360)
    if abs(a - 360 * near / n) <= 0.01:
        a = 360 * near / n  # within 0.01 degrees of a multiple of 360/n: take that angle
    q = fractals.loop_period(a)
    if q is None or n % q != 0:
        return wrong(f"{fmt(a)} degrees does not close after {n} passes: {n} * {fmt(a)} = {fmt(n * a)} is not a "
                     f"multiple of 360. Try a = 360 p / {n} for a whole number p.")
    if q < n:
        return wrong(f"{fmt(a)} degrees closes after only {q} passes ({q} * {fmt(a)} = {fmt(q * a)}): the {n} passes "
                     f"would draw the same {'triangle' if q == 3 else 'figure'} {n // q} times.")
    p = round(n * a / 360) % n
    if p in (1, n - 1):
        return wrong(f"{fmt(a)} degrees closes after {n} passes, but it draws the convex regular {n}-gon (it winds "
                     f"once around); a star winds around more than once: p = {fmt(a * n / 360)} must be between 2 "
                     f"and {n - 2}.")
    return correct(f"{n} * {fmt(a)} = {fmt(n * a)} = {round(n * a / 360)} * 360 and no fewer passes close: the "
                   f"turtle draws the {{{n}/{min(p, n - p)}}} star.")




def check_loop_centre(answer) -> Result:
    """Exercise 2.3: the centre of rotation of the pass ``FORWARD 1 TURN 90 FORWARD 1 TURN -30``
    (Goldman §2.2): ``c = d / (1 - e^{iT})`` with ``d = (1, 1)``, ``T = 60``.  Accepts 1e-4.

    Recognises the rotation taken clockwise (``1 - e^{-iT}``), the midpoint of one pass, the end
    point of one pass, the mirror image.

    >>> check_loop_centre((0.5, 0.5))
    Not yet: that is the midpoint of the first pass's start and end; the centre is the point that one pass leaves fixed: c = d + e^(iT) c, with d the displacement and T the total turning of one pass.
    """
    what = "the centre c"
    got, problem = read_points(answer, what)
    if problem is not None:
        return problem
    if got.shape != (2,):
        return wrong(f"{what} should be one point (x, y); yours has shape {got.shape}.")
    loop = fractals.loop_analysis(CENTRE_PASS)
    c, d, T = loop.center, loop.displacement, loop.total_turning
    if np.all(np.abs(got - c) <= 1e-4):
        return correct(f"c = d / (1 - e^(iT)) = {fmt(c, 5)}: one pass moves the turtle by d = {fmt(d)} and turns "
                       f"it by T = {fmt(T)}, and the {loop.period} passes go round c.")
    dz = complex(*d)
    clockwise = dz / (1 - complex(math.cos(math.radians(-T)), math.sin(math.radians(-T))))
    slips = [
        ((clockwise.real, clockwise.imag), "you turned clockwise: TURN with a positive angle turns counterclockwise, "
                                           "so one pass rotates by e^(iT), and c solves c = d + e^(iT) c"),
        (d / 2, "that is the midpoint of the first pass's start and end; the centre is the point that one pass leaves "
                "fixed: c = d + e^(iT) c, with d the displacement and T the total turning of one pass"),
        (d, "that is where the first pass ends (its displacement d); the centre is the fixed point of the "
            "rotation by T that carries each pass to the next"),
        (c * np.array([1.0, -1.0]), "that is the mirror image of the centre in the x-axis: check the sign of the "
                                    "imaginary part when you solve c = d + e^(iT) c"),
    ]
    for value, why in slips:
        if np.all(np.abs(got - np.asarray(value)) <= 1e-4):
            return wrong(f"{why}.")
    return wrong(f"your point is {far_off(got, c)} from the centre. Hint: with points "
                 f"as complex numbers, find d and T of one pass and solve c = d + e^(iT) c.")


def check_gasket_scale(answer) -> Result:
    """Exercise 2.4: the scale ``r`` of the octagonal gasket's copies (Goldman §2.3, fractal gaskets):
    along a side of the big octagon, the copies at its two corners just touch.  Accepts 1e-4.

    Recognises the Sierpinski and hexagonal scales (1/2, 1/3), one copy's reach taken as the whole
    side, and the copy's full width used on both sides.
    """
    what = "the scale r"
    r, problem = read_number(answer, what)
    if problem is not None:
        return problem
    prog = fractals.polygon_gasket_program(GASKET_SIDES)
    expected = float(fractals.recursion_scales(prog)[0])
    if abs(r - expected) <= 1e-4:
        return correct(f"2 r (1 + cos 45) = 1 gives r = 1 / (2 + sqrt 2) = {fmt(expected, 6)}: the copies at the two "
                       f"ends of a side meet at its midpoint.")
    c45 = math.cos(math.radians(45))
    slips = [
        (1 / 2, "1/2 is the scale of the Sierpinski gasket, whose triangles meet at a point; the octagon's copies "
                "reach out sideways too, so they must be smaller"),
        (1 / 3, "1/3 is the scale of the hexagonal gasket (and the carpet); the octagon's copies reach further "
                "along a side, because of its 45 degree corners"),
        (1 / (1 + c45), "along a side one copy reaches r + r cos 45 from its corner, and there are two copies on "
                        "each side, one at each end: their reaches add up to the side"),
        (1 / (1 + 2 * c45), "r (1 + 2 cos 45) is the whole width of a copy; along the big octagon's side each copy "
                            "reaches only r + r cos 45 from its corner, and the two copies at its ends share the side"),
        (1 / (2 * (1 + 2 * c45)), "r (1 + 2 cos 45) is the whole width of a copy, but along the side each copy reaches "
                                  "only r + r cos 45 from its corner (its other slanted side points back)"),
    ]
    for value, why in slips:
        if abs(r - value) <= 1e-4:
            return wrong(f"{why}.")
    return wrong(f"{what} is {off_by(r, expected)}. Hint: follow one side of the big octagon from a corner: how far "
                 f"along it does the copy at that corner reach, and where does it meet the copy at the other end?")


def check_c_curve_commands(answer) -> Result:
    """Exercise 2.5: the commands executed by level 6 of the C-curve (Goldman §2.3), from the
    recurrence of the command count c(n) of level n.

    Recognises the FORWARDs alone, the other commands alone, a neighbouring level, and the
    recursion added instead of doubled.
    """
    n = C_CURVE_LEVEL
    what = "the number of commands"
    value, problem = read_number(answer, what, "whole number")
    if problem is not None:
        return problem
    prog = fractals.c_curve_program()
    expected = prog.count(n)
    if value == expected:
        return correct(f"c(0) = 1 and c(n) = 5 + 2 c(n-1) (five commands of the body plus two copies of level n-1), "
                       f"so c({n}) = 6 * 2^{n} - 5 = {expected}.")
    segments = 2 ** n
    slips = [
        (segments, f"{segments} counts the FORWARDs only (the segments drawn); every level also runs the TURNs and "
                   f"RESIZEs of its body"),
        (expected - segments, "that counts the TURNs and RESIZEs only; the FORWARDs of level 0, one per segment, "
                              "are commands too"),
        (prog.count(n - 1), f"that is the count of level {n - 1}; level 0 is already one command, FORWARD 1"),
        (prog.count(n + 1), f"that is the count of level {n + 1}; level 0 is FORWARD 1, and level 1 the body with "
                            f"two FORWARDs"),
        (1 + 5 * n, "each level runs level n-1 twice, so the count doubles (and adds the body's five commands); "
                    "it does not just grow by five"),
    ]
    for v, why in slips:
        if value == v:
            return wrong(f"{why}.")
    return wrong(f"{what} is {off_by(value, expected)}. Hint: write c(n) for the commands of level n; the body runs "
                 f"5 commands of its own and calls level n-1 twice.")


# ---------------------------------------------------------------------------------------------
# Programming project: a recursive turtle program for the quadratic Koch curve (§2.3)
# ---------------------------------------------------------------------------------------------

_START = ((0.0, 0.0), (1.0, 0.0))


def _project_cases() -> tuple[list, dict]:
    """Levels 0-4 from the usual start, then levels 2 and 3 from starting states drawn from
    :data:`PROJECT_SEED` (a turtle program is intrinsic: it draws the same curve moved, turned and
    scaled).  Returns the cases and their starting states by label."""
    rng = np.random.default_rng(PROJECT_SEED)
    cases, starts = [], {}
    for n in range(5):
        label = "level 0 (the base case)" if n == 0 else f"level {n}"
        cases.append(Case(label, (n,), kind="the base case (level 0)" if n == 0 else ""))
        starts[label] = _START
    for n in (2, 3):
        p = rng.uniform(-2, 2, 2).round(2)
        angle, step = float(round(rng.uniform(0, 360))), round(float(rng.uniform(0.5, 2)), 1)
        w = (step * math.cos(math.radians(angle)), step * math.sin(math.radians(angle)))
        label = f"level {n}, the turtle starting at {fmt(p)} heading {fmt(angle)} degrees with step {fmt(step)}"
        cases.append(Case(label, (n,), kind="other starting states"))
        starts[label] = (tuple(p), w)
    return cases, starts


def _as_codes(commands) -> tuple[np.ndarray, np.ndarray]:
    """The learner's list of (command, value) pairs as turtle codes and values; ValueError says what
    is wrong with it, in words."""
    if isinstance(commands, (str, bytes, dict)) or not hasattr(commands, "__iter__"):
        raise ValueError("it should be a list of (command, value) pairs, like [('FORWARD', 1)]")
    codes, values = [], []
    for i, item in enumerate(commands):
        if not isinstance(item, (tuple, list)) or len(item) != 2:
            raise ValueError(f"entry {i} should be a (command, value) pair, like ('TURN', 90); it is {item!r}")
        cmd, value = item
        name = cmd.upper() if isinstance(cmd, str) else None
        if name == "RECURSE":
            raise ValueError(f"entry {i} is a RECURSE: return the flat list of commands the level executes, with "
                             f"the list of level n-1 spliced in where each copy goes")
        if name not in turtle.COMMANDS:
            raise ValueError(f"entry {i} has the command {cmd!r}; use FORWARD, MOVE, TURN or RESIZE")
        try:
            v = float(value)
        except (TypeError, ValueError):
            raise ValueError(f"entry {i}: the value of {name} should be a number; it is {value!r}") from None
        if not math.isfinite(v):
            raise ValueError(f"entry {i}: the value of {name} is not finite")
        codes.append(turtle.COMMANDS.index(name))
        values.append(v)
    return np.array(codes, dtype=np.int8), np.array(values, dtype=float)


def _compare_project(starts):
    def compare(got, expected, case):
        (level,) = case.args
        try:
            codes, values = _as_codes(got)
        except ValueError as exc:
            return str(exc)
        p0, w0 = (np.array(v, dtype=float) for v in starts[case.label])
        try:
            mine = turtle.trace_arrays(codes, values, p0, w0)
        except ValueError as exc:
            return f"its commands cannot be run ({exc})"
        ref = turtle.trace_arrays(expected[0], expected[1], p0, w0)
        ref_line = ref.polylines[0]
        if not mine.polylines:
            return "its commands draw nothing (no FORWARD)"
        if len(mine.polylines) > 1:
            return f"it draws {len(mine.polylines)} separate strokes (MOVE lifts the pen); the curve is one stroke"
        line = mine.polylines[0]
        if len(line) != len(ref_line):
            return (f"at level {level} your curve has {len(line) - 1} segments, expected {len(ref_line) - 1} "
                    f"(5^{level})")
        err = np.hypot(*(line - ref_line).T)
        bad = np.flatnonzero(err > 1e-9)
        if bad.size:
            if case.args and starts[case.label] == _START:
                mirrored = ref_line * np.array([1.0, -1.0])
                if np.allclose(line, mirrored, atol=1e-9):
                    return ("its bumps point to the turtle's right; TURN with a positive angle turns left, so the "
                            "bump goes up with TURN 90 first")
            k = int(bad[0])
            return (f"vertex {k} of your curve is {fmt(err[k], 2)} from where it should be, expected "
                    f"{fmt(np.round(ref_line[k], 9) + 0.0)} ({bad.size} of {len(err)} vertices are off)")
        if not (np.allclose(mine.point, ref.point, atol=1e-9) and np.allclose(mine.direction, ref.direction, atol=1e-9)):
            ratio = float(np.hypot(*mine.direction) / np.hypot(*ref.direction))
            return (f"it draws the right curve but leaves the turtle with {fmt(ratio, 6)} times the step and heading "
                    f"{fmt(np.degrees(np.arctan2(mine.direction[1], mine.direction[0])) + 0.0, 4)} degrees; a copy "
                    f"must leave the turtle as FORWARD 1 does (restore the step with RESIZE 3 at the end)")
        return None
    return compare


def _reference_commands(level):
    return fractals.quadratic_koch_program().expand(level)


def check_quadratic_koch_project(function) -> Result:
    """The programming project of chapter 2 (Goldman §2.3): the learner's recursive
    ``function(level)`` returns the list of ``(command, value)`` pairs that the quadratic Koch
    curve executes at ``level``; it is run with the turtle at levels 0-4 (and from two other
    starting states drawn from :data:`PROJECT_SEED`) and compared with
    :func:`goldman_lib.fractals.quadratic_koch_program`: the number of segments, the first vertex
    that is off, the bumps' side, and the turtle's final state.

    >>> def off_by_one(level):
    ...     if level < 0:
    ...         return [("FORWARD", 1)]
    ...     c = off_by_one(level - 1)
    ...     return [("RESIZE", 1 / 3)] + c + [("TURN", 90)] + c + [("TURN", -90)] + c + [("TURN", -90)] + c + \\
    ...         [("TURN", 90)] + c + [("RESIZE", 3)]
    >>> print(check_quadratic_koch_project(off_by_one).message)  # doctest: +ELLIPSIS
    case 1 of 7 (level 0 (the base case)): your function returned ...; at level 0 your curve has 5 segments, expected 1 (5^0). Hint: ...
    """
    cases, starts = _project_cases()
    return check_project(function, cases, reference=_reference_commands, compare=_compare_project(starts),
                         what="the quadratic Koch curve",
                         hint="level 0 is the base case, one FORWARD 1; level n splices in five copies of the list "
                              "of level n-1, drawn at a third of the step, with the bump's turns between them, and "
                              "restores the step at the end")


#: Wrong answers of the kinds each checker recognises (tests feed them in and check the reason).
SLIPS = {
    "check_loop_period": [6, 15, 60, 7, 360 / 84, 11],
    "check_star_angle": [120, 40, 100, 320],
    "check_loop_centre": [(1.36603, -0.36603), (0.5, 0.5), (1, 1), (-0.36603, -1.36603), (0, 1)],
    "check_gasket_scale": [0.5, 1 / 3, 1 / (1 + math.sqrt(0.5)), 1 / (1 + math.sqrt(2)), 1 / (2 + 2 * math.sqrt(2)),
                           0.3],
    "check_c_curve_commands": [64, 315, 187, 763, 31, 400],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

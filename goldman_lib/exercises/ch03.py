"""Exercise checkers for chapter 3, fractal strangeness (Goldman §3.2-3.4).

Each checker takes the learner's answer and returns a :class:`~goldman_lib.exercises.Result`
saying right or wrong and why, never what the answer is; ``None`` or ``...`` means "not answered
yet".  ``PROBLEMS`` holds the statements by checker name (built from the constants below);
``SLIPS`` the wrong answers of the kinds each checker recognises.

>>> check_equal_scales_dimension(math.log(4) / math.log(8))
Not yet: that is log 4 / log 8, the ratio upside down: N s^D = 1 gives D = log N / log(1/s).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import fractals
from goldman_lib.exercises import guard_checkers, clip
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, off_by, read_number, unanswered, wrong

__all__ = ["PROBLEMS", "SLIPS", "EQUAL_COPIES", "EQUAL_SCALE", "TENT_PROGRAM", "CHORD_LEVEL", "BOUND_START",
           "BOUND_LEVEL", "check_equal_scales_dimension", "check_program_dimension", "check_c_curve_chord",
           "check_c_curve_base_case", "check_attraction_bound"]

#: Exercise 3.1 (§3.2): a curve made of EQUAL_COPIES copies of itself at scale EQUAL_SCALE (the Minkowski sausage).
EQUAL_COPIES, EQUAL_SCALE = 8, 1 / 4
#: Exercise 3.2 (§3.2.2): a Koch-like curve whose tent is two half-size copies between two quarter-size ones.
#: It moves the turtle exactly as FORWARD 1 does (to (1, 0), same heading and step), so its levels converge.
TENT_PROGRAM = fractals.RecursiveTurtleProgram(
    [("RESIZE", 0.25), ("RECURSE", None), ("TURN", 60), ("RESIZE", 2), ("RECURSE", None), ("TURN", -120),
     ("RECURSE", None), ("TURN", 60), ("RESIZE", 0.5), ("RECURSE", None), ("RESIZE", 4)], [("FORWARD", 1)],
    "wide-tent curve")
#: Exercise 3.3 (§3.3): the chord of the C-curve from C(0) to C(2**-CHORD_LEVEL).
CHORD_LEVEL = 5
#: Exercise 3.5 (§3.4): the Hausdorff distance of two C-curve base cases at level 0, and the level asked about.
BOUND_START, BOUND_LEVEL = 0.3, 6

PROBLEMS = {
    "check_equal_scales_dimension": (
        f"The Minkowski sausage replaces a segment by {EQUAL_COPIES} segments a quarter as long (forward, up, "
        f"forward, down, down, forward, up, forward), again and again: its limit is made of {EQUAL_COPIES} copies "
        f"of itself, each scaled by 1/4. What is its similarity dimension? (Goldman §3.2)"),
    "check_program_dimension": (
        "A recursive turtle program: level 0 is FORWARD 1; level n is RESIZE 1/4, R, TURN 60, RESIZE 2, R, "
        "TURN -120, R, TURN 60, RESIZE 1/2, R, RESIZE 4, where R runs level n-1. Like FORWARD 1 it moves the "
        "turtle to (1, 0) with its heading and step unchanged, so its levels converge to a fractal. What is the "
        "fractal's similarity dimension? Give it to 4 decimals (Goldman §3.2.2)."),
    "check_c_curve_chord": (
        f"Let C(t) be the C-curve from (0, 0) to (1, 0) (level 0: FORWARD 1; level n: TURN 45, RESIZE "
        f"1/sqrt(2), C, TURN -90, C, TURN 45, RESIZE sqrt(2)), t the fraction of its length. In which direction "
        f"(degrees from the x-axis) does the chord from C(0) to C(h) point for h = 2^-{CHORD_LEVEL}? (Goldman §3.3)"),
    "check_c_curve_base_case": (
        "Give a base case for the C-curve program (a list of (command, value) pairs) that draws something other "
        "than FORWARD 1 at level 0, yet whose levels converge to the same C-curve (Goldman §3.4)."),
    "check_attraction_bound": (
        f"Two base cases for the C-curve both move the turtle as FORWARD 1 does, and their level-0 drawings are "
        f"at Hausdorff distance {fmt(BOUND_START)}. What upper bound does the attraction argument give for the "
        f"distance between their level-{BOUND_LEVEL} drawings? (Goldman §3.4)"),
}


def _near(value: float, target: float, tol: float) -> bool:
    return abs(value - target) <= tol


def check_equal_scales_dimension(answer) -> Result:
    """Exercise 3.1: the dimension of 8 copies at scale 1/4 (Goldman §3.2), from N s^D = 1.
    Accepts 1e-3.

    Recognises the ratio upside down, the counts divided instead of their logarithms, the scale
    taken as 1/3 (the carpet's log 8 / log 3).
    """
    value, problem = read_number(answer, "the dimension")
    if problem is not None:
        return problem
    n, s = EQUAL_COPIES, EQUAL_SCALE
    expected = fractals.similarity_dimension([s] * n)
    if _near(value, expected, 1e-3):
        return correct(f"N s^D = 1 with N = {n}, s = 1/4 gives D = log {n} / log 4 = {fmt(expected)}: more than a "
                       f"curve (D = 1), less than an area (D = 2).")
    slips = [
        (math.log(1 / s) / math.log(n), f"that is log 4 / log {n}, the ratio upside down: N s^D = 1 gives "
                                        f"D = log N / log(1/s)"),
        (n * s, f"that divides the counts ({n} / 4); the dimension divides their logarithms: D = log N / log(1/s)"),
        (math.log(n) / math.log(3), f"that is log {n} / log 3, the Sierpinski carpet's dimension; here each copy is "
                                    f"scaled by a quarter, not a third"),
    ]
    for v, why in slips:
        if _near(value, v, 1e-3):
            return wrong(f"{why}.")
    return wrong(f"the dimension is {off_by(value, expected)}. Hint: D solves N s^D = 1 with N = {n} copies "
                 f"at scale s = 1/4.")


def check_program_dimension(answer) -> Result:
    """Exercise 3.2: the dimension of :data:`TENT_PROGRAM` (Goldman §3.2.2), from the scales of its
    RECURSE calls (the RESIZE factors multiply) and the equation sum s_i^D = 1.  Accepts 1e-4.

    Recognises all scales taken as a quarter, or as a half, the Koch curve's 4 copies at 1/3, the
    mean scale, and three copies counted instead of four.
    """
    value, problem = read_number(answer, "the dimension")
    if problem is not None:
        return problem
    scales = fractals.recursion_scales(TENT_PROGRAM)
    expected = fractals.program_dimension(TENT_PROGRAM)
    if _near(value, expected, 1e-4):
        return correct(f"the copies are drawn at the scales {', '.join(fmt(s) for s in scales)} (the RESIZE factors "
                       f"multiply); with x = 2^-D, 2x + 2x^2 = 1 gives x = (sqrt 3 - 1)/2 and D = log2(1 + sqrt 3) "
                       f"= {fmt(expected, 6)}.")
    quarter, half = 0.25, 0.5
    slips = [
        (fractals.similarity_dimension([quarter] * 4),
         "that treats all four copies as a quarter of the size; the RESIZE 2 after the first copy makes the middle "
         "two copies half the size"),
        (fractals.similarity_dimension([half] * 4),
         "that treats all four copies as half the size; the first and the last copy are drawn at a quarter"),
        (math.log(4) / math.log(3),
         "that is the Koch curve's dimension, four copies at a third; here the RESIZE factors give each copy its "
         "own scale"),
        (fractals.similarity_dimension([float(np.mean(scales))] * 4),
         "that uses the mean scale for all four copies; with unequal scales solve the sum of s_i^D equal to one, "
         "each copy with its own s_i"),
        (fractals.similarity_dimension([quarter, half, half]),
         "that counts three copies; the program calls R four times"),
        (fractals.similarity_dimension([quarter, half]),
         "that counts each different scale once; every call of R is a copy, so a scale used twice counts twice"),
    ]
    for v, why in slips:
        if _near(value, v, 1e-4):
            return wrong(f"{why}.")
    return wrong(f"the dimension is {off_by(value, expected)}. Hint: write down the step in force at each R (the "
                 f"product of the RESIZEs before it), then solve the sum of s_i^D equal to one, with x = 2^-D.")


def _angle_mod(a: float) -> float:
    """An angle in degrees reduced to [0, 360)."""
    return a % 360.0


def check_c_curve_chord(answer) -> Result:
    """Exercise 3.3: the direction of the chord from C(0) to C(2^-5) on the C-curve (Goldman §3.3), in
    degrees.  Any angle equal mod 360 is right (0.01).

    Recognises one turn of 45 only, a neighbouring level, the turns taken clockwise, and the chord
    taken along the x-axis as for the Koch curve.
    """
    what = "the chord's direction"
    value, problem = read_number(answer, what, "number of degrees")
    if problem is not None:
        return problem
    j = CHORD_LEVEL
    level = j + 5
    (curve,) = fractals.c_curve(level)
    expected = float(fractals.chord_angles(curve, 0, [2 ** (level - j)])[0])
    r = _angle_mod(value)

    def same(a, b):
        d = abs(_angle_mod(a) - _angle_mod(b))
        return min(d, 360 - d) <= 0.01

    if same(r, expected):
        return correct(f"C(2^-j) is the end of j nested first halves, each turned 45 degrees and scaled by 1/sqrt 2: "
                       f"the chord points at 45 j = {45 * j} degrees (= {fmt(expected)}), and turns by another 45 "
                       f"with every halving of h, so it never settles: C has no tangent at 0.")
    if same(r, 45):
        return wrong(f"{fmt(value)} degrees is the chord to C(1/2) only; each halving of h nests one more copy, and "
                     f"each copy turns the chord by another 45 degrees.")
    for m in (j - 1, j + 1):
        if same(r, 45 * m):
            return wrong(f"{fmt(value)} degrees is the chord to C(2^-{m}): count the halvings again, one 45 degree turn "
                         f"for each.")
    if same(r, -expected):
        return wrong("your chord turns clockwise; the C-curve's body starts with TURN 45, a turn to the left "
                     "(counterclockwise), so the nested copies turn counterclockwise.")
    if same(r, 0):
        return wrong("the chord along the x-axis is what the Koch curve gives at h = 4^-j; the C-curve's first half is "
                     "turned 45 degrees, so its chords turn with every halving.")
    e = _angle_mod(expected)
    return wrong(f"{what} is {off_by(e + (r - e + 180) % 360 - 180, e)} "
                 f"(mod 360). Hint: C(2^-j) is the end of the first half of the first half of ... (j times), "
                 f"and each first half is turned 45 degrees.")


def check_c_curve_base_case(answer) -> Result:
    """Exercise 3.4: a base case for the C-curve, other than FORWARD 1, whose levels converge to the
    C-curve (Goldman §3.4).  Right: it draws, it differs from ``FORWARD 1``, and it moves the turtle
    from ``(0, 0)`` heading ``(1, 0)`` to ``(1, 0)`` heading ``(1, 0)`` with its step unchanged.

    Recognises a base that changes the heading, the step, or the end point, one that draws
    nothing, and the book's own base case.

    >>> check_c_curve_base_case([("TURN", 45), ("FORWARD", 1)])
    Not yet: your base case leaves the turtle heading 45 degrees instead of 0, so every copy after the first starts off in the wrong direction and the pieces no longer join into the C-curve.
    """
    if is_unanswered(answer):
        return unanswered("a base case, a list of (command, value) pairs")
    c_curve = fractals.c_curve_program()
    try:
        prog = c_curve.with_base(answer)
    except (TypeError, ValueError) as exc:
        return wrong(f"that is not a base case: {clip(exc, 200)}.")
    if not prog.polylines(0):
        return wrong("your base case draws nothing (only MOVE and TURN): then every level draws nothing either.")
    if prog.base == c_curve.base:
        return wrong("that is the book's base case; the exercise asks for a different one.")
    T, S, d = fractals.state_change(prog.base)
    heading = ((T + 180) % 360) - 180
    if abs(heading) > 1e-9:
        return wrong(f"your base case leaves the turtle heading {fmt(heading)} degrees instead of 0, so every copy "
                     f"after the first starts off in the wrong direction and the pieces no longer join into the "
                     f"C-curve.")
    if abs(S - 1) > 1e-9:
        return wrong(f"your base case changes the turtle's step by a factor {fmt(S)}; it must leave the step as it "
                     f"found it, or the later copies are drawn at the wrong size.")
    if not np.allclose(d, [1, 0], atol=1e-9):
        return wrong(f"your base case ends at {fmt(np.round(d, 9) + 0.0)} instead of (1, 0), so the limit is a "
                     f"different set (FORWARD 2, for example, gives a C-curve twice as large).")
    dist = fractals.base_case_distances(c_curve, [prog.base], [0])[0, 0]
    return correct(f"it changes the turtle's state exactly as FORWARD 1 does, so the copies join as before and level "
                   f"n differs from the C-curve by at most (1/sqrt 2)^n times the level-0 distance (yours starts "
                   f"{fmt(dist, 3)} from FORWARD 1).")


def check_attraction_bound(answer) -> Result:
    """Exercise 3.5: the bound on the Hausdorff distance at level 6 between two C-curve drawings 0.3
    apart at level 0 (Goldman §3.4), from the contraction factor of the C-curve's maps.  Accepts 1e-5.

    Recognises the Koch curve's factor 1/3, a factor 1/2, a neighbouring level, the copies' distances
    added up (times 2 per level), and no shrinking at all.
    """
    what = "the bound"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    d0, n = BOUND_START, BOUND_LEVEL
    s = float(fractals.recursion_scales(fractals.c_curve_program()).max())
    expected = d0 * s ** n
    if _near(value, expected, 1e-5):
        return correct(f"each level shrinks the distance at least by the copies' scale 1/sqrt 2, so level {n} is "
                       f"within {fmt(d0)} (1/sqrt 2)^{n} = {fmt(expected)}.")
    slips = [
        (d0 / 3 ** n, "that shrinks by a third per level, the Koch curve's scale; the C-curve's copies are scaled by "
                      "1/sqrt 2"),
        (d0 / 2 ** n, "that shrinks by a half per level; the C-curve's copies are scaled by 1/sqrt 2, the square root "
                      "of a half"),
        (d0 * s ** (n - 1), "that is the bound for one level fewer: level 0 is the given distance, and each of the "
                            "levels after it multiplies by the scale"),
        (d0 * s ** (n + 1), "that is the bound for one level more: level 0 is the given distance, and each of the "
                            "levels after it multiplies by the scale"),
        (d0 * (2 * s) ** n, "the distances of the copies do not add up: the Hausdorff distance of two unions is at "
                            "most the largest distance between matching copies, so only the scale counts"),
        (d0, "the distance does shrink: each level is made of copies at a smaller scale, and corresponding copies "
             "are closer by that scale"),
    ]
    for v, why in slips:
        if _near(value, v, 1e-5):
            return wrong(f"{why}.")
    return wrong(f"{what} is {off_by(value, expected)}. Hint: each level multiplies the largest distance by the "
                 f"scale of the copies.")


#: Wrong answers of the kinds each checker recognises (tests feed them in and check the reason).
SLIPS = {
    "check_equal_scales_dimension": [math.log(4) / math.log(8), 2.0, math.log(8) / math.log(3), 1.3],
    "check_program_dimension": [1.0, 2.0, math.log(4) / math.log(3), math.log(4) / math.log(8 / 3),
                                math.log(1 + math.sqrt(2)) / math.log(2), 0.6942419136, 1.3],
    "check_c_curve_chord": [45, 180, 270, 135, 0, 200],
    "check_c_curve_base_case": [[("TURN", 45), ("FORWARD", 1)], [("RESIZE", 2), ("FORWARD", 0.5)],
                                [("FORWARD", 2)], [("MOVE", 1)], [("FORWARD", 1)], [("JUMP", 1)]],
    "check_attraction_bound": [0.3 / 3 ** 6, 0.3 / 2 ** 6, 0.3 * 0.5 ** 2.5, 0.3 * 0.5 ** 3.5, 2.4, 0.3, 0.05],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

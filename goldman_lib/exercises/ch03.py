"""Exercise checkers for chapter 3, fractal strangeness (Goldman §3.2-3.4).

Each checker takes the learner's answer and returns a :class:`~goldman_lib.exercises.Result`
saying right or wrong and why; ``None`` or ``...`` means "not answered yet".  ``PROBLEMS``
holds the statements by checker name.

>>> print(PROBLEMS["check_equal_scales_dimension"])
A fractal is made of 5 copies of itself, each scaled by 1/3 (the Vicsek cross). What is its similarity dimension? (Goldman §3.2.1)
>>> check_equal_scales_dimension(1.465)
Correct: N s^D = 1 gives D = log 5 / log 3 = 1.465.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import fractals
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, read_number, unanswered, wrong

__all__ = ["PROBLEMS", "UNEQUAL_PROGRAM", "KOCH_LEVEL", "KOCH_SIDE", "QUOTIENT_POWER",
           "check_equal_scales_dimension", "check_program_dimension", "check_koch_length",
           "check_difference_quotient", "check_koch_base_case"]

#: Exercise 2: a recursive turtle program with unequal scales 1/2, 1/4, 1/4 (read cumulatively).
UNEQUAL_PROGRAM = fractals.RecursiveTurtleProgram(
    [("RESIZE", 0.5), ("RECURSE", None), ("MOVE", 1), ("RESIZE", 0.5), ("RECURSE", None), ("MOVE", 1),
     ("RECURSE", None), ("RESIZE", 4)], [("FORWARD", 1)], "three pieces")
#: Exercise 3: the level and the length of the segment the Koch curve starts from.
KOCH_LEVEL, KOCH_SIDE = 10, 3.0
#: Exercise 4: the difference quotient at the start of the Koch curve with h = 4**-QUOTIENT_POWER.
QUOTIENT_POWER = 5

PROBLEMS = {
    "check_equal_scales_dimension": (
        "A fractal is made of 5 copies of itself, each scaled by 1/3 (the Vicsek cross). What is its "
        "similarity dimension? (Goldman §3.2.1)"),
    "check_program_dimension": (
        "What is the similarity dimension of the fractal drawn by the recursive turtle program UNEQUAL_PROGRAM: "
        "level 0 FORWARD 1; level n RESIZE 1/2, RECURSE, MOVE 1, RESIZE 1/2, RECURSE, MOVE 1, RECURSE, "
        "RESIZE 4? (Goldman §3.2.2)"),
    "check_koch_length": (
        f"The Koch curve is drawn over a segment of length {fmt(KOCH_SIDE)}. How long is the curve at level "
        f"{KOCH_LEVEL}? (Goldman §3.2)"),
    "check_difference_quotient": (
        f"Let K(t) be the level-8 Koch curve from (0, 0) to (1, 0), parametrised by the fraction t of its "
        f"length. Compute the difference quotient |K(h) - K(0)| / h for h = 4^-{QUOTIENT_POWER}. (Goldman §3.3)"),
    "check_koch_base_case": (
        "Replace the base case FORWARD 1 of the Koch curve program by another base case (a list of "
        "(command, value) pairs) that draws something different at level 0 but converges to the same Koch "
        "curve. (Goldman §3.4)"),
}


def check_equal_scales_dimension(answer) -> Result:
    """Exercise 3.1: the dimension of 5 copies at scale 1/3: ``log 5 / log 3 = 1.465`` (Goldman §3.2.1).

    Accepts within 0.001.  Recognises the ratio upside down, 5/3, and log 9 / log 3 = 2.

    >>> check_equal_scales_dimension(math.log(3) / math.log(5))
    Not yet: 0.6826 is log 3 / log 5, the ratio upside down: N s^D = 1 gives D = log N / log(1/s) = log 5 / log 3.
    """
    value, problem = read_number(answer, "the dimension")
    if problem is not None:
        return problem
    expected = math.log(5) / math.log(3)
    if abs(value - expected) <= 1e-3:
        return correct(f"N s^D = 1 gives D = log 5 / log 3 = {fmt(expected)}.")
    if abs(value - math.log(3) / math.log(5)) <= 1e-3:
        return wrong(f"{fmt(value)} is log 3 / log 5, the ratio upside down: N s^D = 1 gives D = log N / log(1/s) = "
                     f"log 5 / log 3.")
    if abs(value - 5 / 3) <= 1e-3:
        return wrong("5/3 divides the counts; the dimension divides their logarithms: D = log 5 / log 3.")
    if abs(value - 2) <= 1e-3:
        return wrong("2 would be 9 copies at scale 1/3 (the whole square); with 5 copies D = log 5 / log 3 < 2.")
    return wrong(f"the dimension D solves 5 (1/3)^D = 1; you gave {fmt(value)}.")


def check_program_dimension(answer) -> Result:
    """Exercise 3.2: the dimension of :data:`UNEQUAL_PROGRAM`, scales 1/2, 1/4, 1/4: ``D = 1``
    (``x + 2x^2 = 1`` with ``x = 2^-D`` gives ``x = 1/2``) (Goldman §3.2.2).

    >>> check_program_dimension(1)
    Correct: the scales are 1/2, 1/4, 1/4 (RESIZE factors multiply); (1/2)^D + 2 (1/4)^D = 1 at D = 1.
    >>> check_program_dimension(math.log(3) / math.log(2))
    Not yet: 1.585 = log 3 / log 2 treats all three copies as scale 1/2; the second RESIZE 1/2 acts on a step already halved, so the last two copies have scale 1/4.
    """
    value, problem = read_number(answer, "the dimension")
    if problem is not None:
        return problem
    if abs(value - 1.0) <= 1e-3:
        return correct("the scales are 1/2, 1/4, 1/4 (RESIZE factors multiply); (1/2)^D + 2 (1/4)^D = 1 at D = 1.")
    if abs(value - math.log(3) / math.log(2)) <= 1e-3:
        return wrong(f"{fmt(value)} = log 3 / log 2 treats all three copies as scale 1/2; the second RESIZE 1/2 acts "
                     f"on a step already halved, so the last two copies have scale 1/4.")
    if abs(value - math.log(3) / math.log(4)) <= 1e-3:
        return wrong(f"{fmt(value)} = log 3 / log 4 treats all three copies as scale 1/4; the first copy is drawn "
                     f"at scale 1/2.")
    return wrong(f"read the scale of each RECURSE (the product of the RESIZEs before it), then solve "
                 f"sum s_i^D = 1; you gave {fmt(value)}.")


def check_koch_length(answer) -> Result:
    """Exercise 3.3: the length of the level-10 Koch curve over a segment of length 3:
    ``3 (4/3)^10 = 53.27`` (Goldman §3.2).  Accepts within 0.01.

    >>> check_koch_length(3 * (4 / 3) ** 10)
    Correct: every level multiplies the length by 4/3: 3 (4/3)^10 = 53.27.
    >>> check_koch_length((4 / 3) ** 10)
    Not yet: 17.76 = (4/3)^10 is the length over a unit segment; this curve starts from a segment of length 3.
    """
    value, problem = read_number(answer, "the length")
    if problem is not None:
        return problem
    n, L = KOCH_LEVEL, KOCH_SIDE
    expected = L * (4 / 3) ** n
    if abs(value - expected) <= 1e-2:
        return correct(f"every level multiplies the length by 4/3: {fmt(L)} (4/3)^{n} = {fmt(expected)}.")
    if abs(value - (4 / 3) ** n) <= 1e-2:
        return wrong(f"{fmt(value)} = (4/3)^{n} is the length over a unit segment; this curve starts from a segment "
                     f"of length {fmt(L)}.")
    for m in (n - 1, n + 1):
        if abs(value - L * (4 / 3) ** m) <= 1e-2:
            return wrong(f"{fmt(value)} is the length at level {m}: level 0 is the segment itself, length {fmt(L)}.")
    if abs(value - L * (1 + n / 3)) <= 1e-2:
        return wrong("the length is multiplied by 4/3 at every level, not increased by a third of the segment: it "
                     "grows geometrically, (4/3)^n.")
    return wrong(f"each segment becomes 4 segments one third as long, so each level multiplies the length by 4/3; "
                 f"you gave {fmt(value)}.")


def check_difference_quotient(answer) -> Result:
    """Exercise 3.4: ``|K(h) - K(0)| / h`` at ``h = 4^-5`` on the Koch curve: ``K(h) = (3^-5, 0)`` so
    the quotient is ``(4/3)^5 = 4.214`` (Goldman §3.3).  Accepts within 0.001.

    >>> check_difference_quotient((4 / 3) ** 5)
    Correct: the first 4^-5 of the curve is a copy scaled by 3^-5 ending at (3^-5, 0): the quotient is (4/3)^5 = 4.214, and it grows without bound as h -> 0, so K has no derivative at 0.
    >>> check_difference_quotient((3 / 4) ** 5)
    Not yet: 0.2373 = (3/4)^5 is h / |K(h) - K(0)|, the quotient upside down.
    """
    value, problem = read_number(answer, "the difference quotient")
    if problem is not None:
        return problem
    j = QUOTIENT_POWER
    expected = (4 / 3) ** j
    if abs(value - expected) <= 1e-3:
        return correct(f"the first 4^-{j} of the curve is a copy scaled by 3^-{j} ending at (3^-{j}, 0): the quotient "
                       f"is (4/3)^{j} = {fmt(expected)}, and it grows without bound as h -> 0, so K has no "
                       f"derivative at 0.")
    if abs(value - (3 / 4) ** j) <= 1e-4:
        return wrong(f"{fmt(value)} = (3/4)^{j} is h / |K(h) - K(0)|, the quotient upside down.")
    if abs(value - 1) <= 1e-3:
        return wrong("1 would be the quotient of a straight segment of length 1 traversed at unit speed; the "
                     "Koch curve is (4/3)^8 times longer, so at parameter h it has gone much less far.")
    return wrong(f"the first quarter of the curve is a copy scaled by 1/3, so K(4^-j) = (3^-j, 0); you gave "
                 f"{fmt(value)}.")


def check_koch_base_case(answer) -> Result:
    """Exercise 3.5: a different base case for the Koch program that converges to the same curve
    (Goldman §3.4).  Right: it draws, differs from ``FORWARD 1``, and moves the turtle from
    ``(0, 0)`` heading ``(1, 0)`` to ``(1, 0)`` heading ``(1, 0)`` with its step unchanged (as
    ``FORWARD 1`` does), so the copies join as before.

    >>> check_koch_base_case([("TURN", 60), ("FORWARD", 1), ("TURN", -120), ("FORWARD", 1), ("TURN", 60)])
    Correct: it changes the turtle's state exactly as FORWARD 1 does, so level n differs from the Koch curve by at most 1/3^n of the level-0 difference (level 5: 0.00356).
    >>> check_koch_base_case([("TURN", 60), ("FORWARD", 1), ("TURN", -120), ("FORWARD", 1)])
    Not yet: your base case leaves the turtle heading -60 degrees instead of 0, so every copy after the first starts off in the wrong direction and the pieces no longer join into the Koch curve.
    """
    if is_unanswered(answer):
        return unanswered("a base case, a list of (command, value) pairs")
    koch = fractals.koch_curve_program()
    try:
        prog = koch.with_base(answer)
    except (TypeError, ValueError) as exc:
        return wrong(f"that is not a base case: {exc}.")
    if not prog.polylines(0):
        return wrong("your base case draws nothing (only MOVE and TURN): then every level draws nothing either.")
    if prog.polylines(0) and len(prog.base) == 1 and prog.base[0] == ("FORWARD", 1.0):
        return wrong("that is the book's base case; the exercise asks for a different one.")
    T, S, d = fractals.state_change(prog.base)
    heading = ((T + 180) % 360) - 180
    if abs(heading) > 1e-9:
        return wrong(f"your base case leaves the turtle heading {fmt(heading)} degrees instead of 0, so every copy "
                     f"after the first starts off in the wrong direction and the pieces no longer join into the "
                     f"Koch curve.")
    if abs(S - 1) > 1e-9:
        return wrong(f"your base case changes the turtle's step by a factor {fmt(S)}; it must leave the step as it "
                     f"found it, or the later copies are drawn at the wrong size.")
    if not np.allclose(d, [1, 0], atol=1e-9):
        return wrong(f"your base case ends at {fmt(d)} instead of (1, 0), so the limit is a different set (FORWARD 2, "
                     f"for example, gives a Koch curve twice as large; a sideways end breaks the copies apart).")
    dist = fractals.base_case_distances(koch, [prog.base], [5])[0, 0]
    return correct(f"it changes the turtle's state exactly as FORWARD 1 does, so level n differs from the Koch curve "
                   f"by at most 1/3^n of the level-0 difference (level 5: {fmt(dist, 3)}).")

"""Exercise checkers for chapter 2, recursive turtle programs (Goldman §2.2-2.3).

Each checker takes the learner's answer and returns a :class:`~goldman_lib.exercises.Result`
saying right or wrong and why; ``None`` or ``...`` means "not answered yet".  ``PROBLEMS``
holds the statements by checker name.

>>> print(PROBLEMS["check_loop_period"])
After how many repetitions does REPEAT k [FORWARD 1 TURN 100] first bring the turtle back to its initial state? (Goldman §2.2)
>>> check_loop_period(18)
Correct: 18 * 100 = 1800 = 5 * 360 is the first multiple of 360: the turtle is back after 18 passes, having drawn the {18/5} star.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import fractals, turtle
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, read_number, unanswered, wrong

__all__ = ["PROBLEMS", "LOOP_ANGLE", "STAR_PASSES", "SNOWFLAKE_LEVEL", "TREE_LEVEL",
           "check_loop_period", "check_star_angle", "check_snowflake_segments", "check_tree_branches",
           "check_square_koch_body"]

#: Exercise 1: the TURN angle of the loop whose period is asked for.
LOOP_ANGLE = 100
#: Exercise 2: the number of passes after which the star must close.
STAR_PASSES = 9
#: Exercise 3: the level of the Koch snowflake whose segments are counted.
SNOWFLAKE_LEVEL = 5
#: Exercise 4: the level of the binary fractal tree whose branches are counted.
TREE_LEVEL = 5

PROBLEMS = {
    "check_loop_period": (
        f"After how many repetitions does REPEAT k [FORWARD 1 TURN {LOOP_ANGLE}] first bring the turtle back "
        f"to its initial state? (Goldman §2.2)"),
    "check_star_angle": (
        f"Give a TURN angle a (degrees, between 0 and 360) for which REPEAT {STAR_PASSES} [FORWARD 1 TURN a] "
        f"returns to its initial state after exactly {STAR_PASSES} passes (not fewer) and draws a star, "
        f"not a convex polygon (Goldman §2.2)."),
    "check_snowflake_segments": (
        f"How many line segments does level {SNOWFLAKE_LEVEL} of the Koch snowflake draw? (Goldman §2.3)"),
    "check_tree_branches": (
        f"How many branches (segments drawn by FORWARD) does level {TREE_LEVEL} of the binary fractal tree "
        f"draw? Level 0 is one stick; level n is a trunk with two level n-1 trees on top. (Goldman §2.3)"),
    "check_square_koch_body": (
        "Write the body of a recursive turtle program, as a list of (command, value) pairs, for the "
        "quadratic Koch curve: base case FORWARD 1; at each level the segment is replaced by five segments "
        "one third as long - forward, up, forward, down, forward - with the square bump on the turtle's "
        "left. Use ('RECURSE', None) for the recursive call. (Goldman §2.3)"),
}


def check_loop_period(answer) -> Result:
    """Exercise 2.1: the period of ``REPEAT k [FORWARD 1 TURN 100]`` (Goldman §2.2, looping lemma).

    answer: a whole number.  Recognises 360/100 (not whole), a later multiple (36), and the
    winding number (5) given instead of the period.

    >>> check_loop_period(36)
    Not yet: after 36 passes the turtle is indeed back (36 * 100 = 3600 = 10 * 360), but it was already back after fewer: look for the least k with k * 100 a multiple of 360.
    """
    what = "the number of repetitions"
    k, problem = read_number(answer, what, "whole number")
    if problem is not None:
        return problem
    a = LOOP_ANGLE
    q = 360 // math.gcd(a, 360)
    p = a // math.gcd(a, 360)
    if k != int(k) or k < 1:
        return wrong(f"{fmt(k)} is not a whole number of repetitions: 360/{a} = {fmt(360 / a)} is not whole, so "
                     f"one lap of 360 degrees is not enough; find the least k with k * {a} a multiple of 360.")
    k = int(k)
    if k == q:
        return correct(f"{q} * {a} = {q * a} = {p} * 360 is the first multiple of 360: the turtle is back after "
                       f"{q} passes, having drawn the {{{q}/{p}}} star.")
    if (k * a) % 360 == 0:
        return wrong(f"after {k} passes the turtle is indeed back ({k} * {a} = {k * a} = {k * a // 360} * 360), but "
                     f"it was already back after fewer: look for the least k with k * {a} a multiple of 360.")
    if k == p:
        return wrong(f"{p} is how many full turns the turtle makes before it is back (the winding number); the "
                     f"question asks for the number of passes.")
    return wrong(f"after {k} passes the turtle has turned {k * a} degrees, not a multiple of 360, so it is not "
                 f"back: by the looping lemma it returns exactly when k * {a} is a multiple of 360.")


def check_star_angle(answer) -> Result:
    """Exercise 2.2: an angle ``a`` for which ``REPEAT 9 [FORWARD 1 TURN a]`` closes after exactly 9
    passes and draws a star (Goldman §2.2).  Right answers: ``360 p / 9`` with ``gcd(p, 9) = 1`` and
    ``p`` not 1 or 8 (80, 160, 200, 280), within 0.01 degrees.

    >>> check_star_angle(160)
    Correct: 9 * 160 = 1440 = 4 * 360 and no fewer passes close: the turtle draws the {9/4} star.
    >>> check_star_angle(120)
    Not yet: 120 degrees closes after only 3 passes (3 * 120 = 360): the 9 passes would draw the same triangle 3 times.
    """
    what = "the TURN angle"
    a, problem = read_number(answer, what, "number of degrees")
    if problem is not None:
        return problem
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


def check_snowflake_segments(answer) -> Result:
    """Exercise 2.3: the number of segments of level 5 of the Koch snowflake: ``3 * 4**5 = 3072``
    (Goldman §2.3).  Recognises one side only (1024) and an off-by-one level.

    >>> check_snowflake_segments(3072)
    Correct: 3 sides, each a Koch curve of 4**5 = 1024 segments: 3072.
    >>> check_snowflake_segments(1024)
    Not yet: 1024 = 4**5 is one side; the snowflake has three Koch curves.
    """
    n = SNOWFLAKE_LEVEL
    value, problem = read_number(answer, "the number of segments", "whole number")
    if problem is not None:
        return problem
    if value == 3 * 4**n:
        return correct(f"3 sides, each a Koch curve of 4**{n} = {4**n} segments: {3 * 4**n}.")
    if value == 4**n:
        return wrong(f"{4**n} = 4**{n} is one side; the snowflake has three Koch curves.")
    if value in (3 * 4 ** (n - 1), 3 * 4 ** (n + 1)):
        return wrong(f"{fmt(value)} is the count of level {n - 1 if value < 3 * 4**n else n + 1}: level 0 is the "
                     f"triangle of 3 segments and every level multiplies the count by 4.")
    if value == 3 * 5**n or value == 5**n:
        return wrong("each segment becomes 4 segments (the middle third is replaced by two sides of a bump), "
                     "not 5.")
    return wrong(f"level 0 draws 3 segments and every level replaces each segment by 4: the answer is 3 * 4**{n}.")


def check_tree_branches(answer) -> Result:
    """Exercise 2.4: the branches of level 5 of the binary tree: ``2**6 - 1 = 63`` (Goldman §2.3).

    >>> check_tree_branches(63)
    Correct: b(n) = 1 + 2 b(n-1) with b(0) = 1 gives b(5) = 2**6 - 1 = 63.
    >>> check_tree_branches(32)
    Not yet: 32 = 2**5 counts the tips only; the trunks of every level are branches too.
    """
    n = TREE_LEVEL
    value, problem = read_number(answer, "the number of branches", "whole number")
    if problem is not None:
        return problem
    expected = 2 ** (n + 1) - 1
    if value == expected:
        return correct(f"b(n) = 1 + 2 b(n-1) with b(0) = 1 gives b({n}) = 2**{n + 1} - 1 = {expected}.")
    if value == 2**n:
        return wrong(f"{2**n} = 2**{n} counts the tips only; the trunks of every level are branches too.")
    if value == 2 ** (n + 1):
        return wrong(f"{2 ** (n + 1)} is one too many: 1 + 2 + 4 + ... + 2**{n} = 2**{n + 1} - 1.")
    if value == 2**n - 1:
        return wrong(f"{2**n - 1} counts the branches of level {n - 1}; level 0 is already one stick.")
    return wrong(f"count level by level: b(0) = 1 and b(n) = 1 (the trunk) + 2 b(n-1) (the two subtrees).")


_SQUARE_KOCH = fractals.RecursiveTurtleProgram(
    [("RESIZE", 1 / 3), ("RECURSE", None), ("TURN", 90), ("RECURSE", None), ("TURN", -90), ("RECURSE", None),
     ("TURN", -90), ("RECURSE", None), ("TURN", 90), ("RECURSE", None), ("RESIZE", 3)], [("FORWARD", 1)],
    "quadratic Koch curve")


def check_square_koch_body(answer) -> Result:
    """Exercise 2.5: the body of the quadratic Koch curve (Goldman §2.3).

    answer: a list of ``(command, value)`` pairs.  Runs it with base ``FORWARD 1`` at levels 1
    and 2 and compares the drawings with the quadratic Koch curve; explains a missing ``RESIZE 3``
    at the end, a wrong number of recursive calls, a bump on the wrong side, wrong scale.

    >>> R = ("RECURSE", None)
    >>> check_square_koch_body([("RESIZE", 1/3), R, ("TURN", 90), R, ("TURN", -90), R, ("TURN", -90), R,
    ...                         ("TURN", 90), R, ("RESIZE", 3)])
    Correct: your program draws the quadratic Koch curve: 5 copies at scale 1/3, level 2 has 25 segments.
    >>> check_square_koch_body([("RESIZE", 1/3), R, ("TURN", 90), R, ("TURN", -90), R, ("TURN", -90), R,
    ...                         ("TURN", 90), R])
    Not yet: level 1 is right, but level 2 is not: the body must end with RESIZE 3 so that the turtle's step is restored after it (otherwise the next copies are drawn too small).
    """
    if is_unanswered(answer):
        return unanswered("the body, a list of (command, value) pairs")
    try:
        prog = fractals.RecursiveTurtleProgram(answer, [("FORWARD", 1)])
    except (TypeError, ValueError) as exc:
        return wrong(f"that is not a program body: {exc}.")
    try:
        mine = [prog.polylines(n) for n in (1, 2)]
    except ValueError as exc:
        return wrong(f"your program does not run: {exc}.")
    ref = [_SQUARE_KOCH.polylines(n) for n in (1, 2)]

    def same(a, b):
        return len(a) == len(b) and all(p.shape == q.shape and np.allclose(p, q, atol=1e-9) for p, q in zip(a, b))

    if same(mine[0], ref[0]) and same(mine[1], ref[1]):
        return correct("your program draws the quadratic Koch curve: 5 copies at scale 1/3, level 2 has 25 "
                       "segments.")
    calls = sum(1 for c, _ in prog.body if c == "RECURSE")
    if calls != 5:
        return wrong(f"your body makes {calls} recursive call{'s' * (calls != 1)}; the curve has five pieces, so "
                     f"it needs five RECURSE entries.")
    if same(mine[0], ref[0]):
        return wrong("level 1 is right, but level 2 is not: the body must end with RESIZE 3 so that the turtle's "
                     "step is restored after it (otherwise the next copies are drawn too small).")
    if len(mine[0]) == 1:
        flipped = mine[0][0] * np.array([1.0, -1.0])
        if flipped.shape == ref[0][0].shape and np.allclose(flipped, ref[0][0], atol=1e-9):
            return wrong("your bump points down (to the turtle's right): TURN with a positive angle turns left, "
                         "so go up with TURN 90 first.")
        end = mine[0][0][-1]
        if not np.allclose(end, [1, 0], atol=1e-9):
            return wrong(f"level 1 should end at (1, 0), yours ends at {fmt(end)}: check the RESIZE (each piece is 1/3 "
                         f"long) and that the turns cancel out.")
    return wrong("level 1 should be forward 1/3, up 1/3, forward 1/3, down 1/3, forward 1/3 with the bump on the "
                 "left; compare your drawing with that.")

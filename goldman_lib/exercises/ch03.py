"""Exercise checkers for chapter 3, fractal strangeness (Goldman §3.2-3.4).

Each checker takes the learner's answer and returns a :class:`~goldman_lib.exercises.Result`
saying right or wrong and why, never what the answer is; ``None`` or ``...`` means "not answered
yet".  ``PROBLEMS`` holds the statements by checker name (built from the constants below);
``SLIPS`` the wrong answers of the kinds each checker recognises.

>>> check_equal_scales_dimension(math.log(4) / math.log(8))
Not yet: that is log 4 / log 8, the ratio upside down: N s^D = 1 gives D = log N / log(1/s).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from goldman_lib import fractals
from goldman_lib.exercises import guard_checkers, clip
from goldman_lib.exercises.deal import Deck, within
from goldman_lib.exercises import Result, correct, fmt, is_unanswered, off_by, read_number, unanswered, wrong

__all__ = ["PROBLEMS", "SLIPS", "EQUAL_COPIES", "EQUAL_SCALE", "TENT_PROGRAM", "CHORD_LEVEL", "BOUND_START",
           "BOUND_LEVEL", "DECK", "deal", "steps", "current", "deal_button", "tent_program", "check_equal_scales_dimension", "check_program_dimension", "check_c_curve_chord",
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

DECK = Deck("ch03")

_WORDS = {2: "a half", 3: "a third", 4: "a quarter", 5: "a fifth", 6: "a sixth", 7: "a seventh"}


def _near(value: float, target: float, tol: float) -> bool:
    return abs(value - target) <= tol


# -- exercise 3.1: N copies at scale 1/k -------------------------------------------------------

_STORED_EQUAL = {"copies": EQUAL_COPIES, "k": round(1 / EQUAL_SCALE)}


def _equal_generate(rng) -> dict:
    k = int(rng.integers(2, 7))
    return {"copies": int(rng.integers(k + 1, k * k)), "k": k}


def _equal_answer(p) -> float:
    return float(fractals.similarity_dimension([1 / p["k"]] * p["copies"]))


def _equal_slips(p) -> dict:
    n, k = p["copies"], p["k"]
    return {"the ratio upside down": math.log(k) / math.log(n), "the counts divided": n / k,
            "the carpet's scale": math.log(n) / math.log(3)}


def _equal_statement(p) -> str:
    n, k = p["copies"], p["k"]
    if p == _STORED_EQUAL:
        return (f"The Minkowski sausage replaces a segment by {n} segments a quarter as long (forward, up, "
                f"forward, down, down, forward, up, forward), again and again: its limit is made of {n} copies "
                f"of itself, each scaled by 1/4. What is its similarity dimension? (Goldman §3.2)")
    return (f"A curve is the limit of replacing every segment by {n} segments 1/{k} as long, again and again: it is "
            f"made of {n} copies of itself, each scaled by 1/{k}. What is its similarity dimension? (Goldman §3.2)")


def _equal_steps(p) -> str:
    n, k = p["copies"], p["k"]
    return (f"1. A set made of N copies of itself at scale s has similarity dimension D with N s^D = 1.\n"
            f"2. Here N = {n}, s = 1/{k}: {n} (1/{k})^D = 1, so {k}^D = {n}.\n"
            f"3. D = log {n} / log {k} = {fmt(_equal_answer(p), 6)}.")


@DECK.exercise(stored=_STORED_EQUAL, generate=_equal_generate, answer=_equal_answer, slips=_equal_slips,
               statement=_equal_statement, steps=_equal_steps, same=within(1e-3),
               well_posed=lambda p: None if 1.05 < _equal_answer(p) < 1.95 else "the dimension is too near 1 or 2")
def check_equal_scales_dimension(answer, p) -> Result:
    """Exercise 3.1: the dimension of N copies at scale 1/k (Goldman §3.2), from N s^D = 1.
    Accepts 1e-3.

    Recognises the ratio upside down, the counts divided instead of their logarithms, the scale
    taken as 1/3 (the carpet's log N / log 3).
    """
    value, problem = read_number(answer, "the dimension")
    if problem is not None:
        return problem
    n, k = p["copies"], p["k"]
    expected = _equal_answer(p)
    if _near(value, expected, 1e-3):
        return correct(f"N s^D = 1 with N = {n}, s = 1/{k} gives D = log {n} / log {k} = {fmt(expected)}: more than "
                       f"a curve (D = 1), less than an area (D = 2).")
    s = _equal_slips(p)
    slips = [
        (s["the ratio upside down"], f"that is log {k} / log {n}, the ratio upside down: N s^D = 1 gives "
                                     f"D = log N / log(1/s)"),
        (s["the counts divided"], f"that divides the counts ({n} / {k}); the dimension divides their logarithms: "
                                  f"D = log N / log(1/s)"),
        (s["the carpet's scale"], f"that is log {n} / log 3, the Sierpinski carpet's dimension; here each copy is "
                                  f"scaled by {_WORDS[k]}, not a third"),
    ]
    for v, why in slips:
        if _near(value, v, 1e-3):
            return wrong(f"{why}.")
    return wrong(f"the dimension is {off_by(value, expected)}. Hint: D solves N s^D = 1 with N = {n} copies "
                 f"at scale s = 1/{k}.")


# -- exercise 3.2: the dimension of a wide-tent program -----------------------------------------

def _frac(x: float) -> str:
    """1/4, 2, 3/5: a RESIZE factor as the statement writes it."""
    from fractions import Fraction
    f = Fraction(x).limit_denominator(100)
    return str(f.numerator) if f.denominator == 1 else f"{f.numerator}/{f.denominator}"


def tent_program(k: int) -> fractals.RecursiveTurtleProgram:
    """The wide tent of exercise 3.2 with end copies at scale 1/k and middle copies at (k-2)/k, so
    that 2/k + 2 (k-2)/k cos 60 = 1: it moves the turtle as FORWARD 1 does."""
    a, b = 1 / k, (k - 2) / k
    return fractals.RecursiveTurtleProgram(
        [("RESIZE", a), ("RECURSE", None), ("TURN", 60), ("RESIZE", b / a), ("RECURSE", None), ("TURN", -120),
         ("RECURSE", None), ("TURN", 60), ("RESIZE", a / b), ("RECURSE", None), ("RESIZE", 1 / a)],
        [("FORWARD", 1)], "wide-tent curve")


def _tent_generate(rng) -> dict:
    return {"k": int(rng.integers(4, 9))}


@functools.lru_cache(maxsize=64)
def _tent(k):
    prog = TENT_PROGRAM if k == 4 else tent_program(k)
    return prog, fractals.recursion_scales(prog), float(fractals.program_dimension(prog))


def _tent_answer(p) -> float:
    return _tent(p["k"])[2]


def _tent_slips(p) -> dict:
    k = p["k"]
    a, b = 1 / k, (k - 2) / k
    _, scales, _ = _tent(k)
    return {"all at the end scale": fractals.similarity_dimension([a] * 4),
            "all at the middle scale": fractals.similarity_dimension([b] * 4),
            "the Koch curve": math.log(4) / math.log(3),
            "the mean scale": fractals.similarity_dimension([float(np.mean(scales))] * 4),
            "three copies": fractals.similarity_dimension([a, b, b]),
            "each scale once": fractals.similarity_dimension([a, b])}


def _tent_statement(p) -> str:
    k = p["k"]
    a, b = 1 / k, (k - 2) / k
    return (f"A recursive turtle program: level 0 is FORWARD 1; level n is RESIZE {_frac(a)}, R, TURN 60, RESIZE "
            f"{_frac(b / a)}, R, TURN -120, R, TURN 60, RESIZE {_frac(a / b)}, R, RESIZE {_frac(1 / a)}, where R runs "
            f"level n-1. Like FORWARD 1 it moves the turtle to (1, 0) with its heading and step unchanged, so its "
            f"levels converge to a fractal. What is the fractal's similarity dimension? Give it to 4 decimals "
            f"(Goldman §3.2.2).")


def _tent_steps(p) -> str:
    k = p["k"]
    _, scales, D = _tent(k)
    return (f"1. The step in force at each R is the product of the RESIZEs before it: "
            f"{', '.join(_frac(s) for s in scales)}.\n"
            f"2. The dimension D solves the sum of s_i^D equal to one: "
            f"{' + '.join(f'({_frac(s)})^D' for s in scales)} = 1.\n"
            f"3. The left side falls as D grows; solving numerically (bisection) gives D = {fmt(D, 6)}.")


@DECK.exercise(stored={"k": 4}, generate=_tent_generate, answer=_tent_answer, slips=_tent_slips,
               statement=_tent_statement, steps=_tent_steps, same=within(1e-4))
def check_program_dimension(answer, p) -> Result:
    """Exercise 3.2: the dimension of the wide-tent program of the statement (Goldman §3.2.2),
    from the scales of its RECURSE calls (the RESIZE factors multiply) and the equation
    sum s_i^D = 1.  Accepts 1e-4.

    Recognises all scales taken as the end copies' or as the middle copies', the Koch curve's 4
    copies at 1/3, the mean scale, three copies counted instead of four, each scale counted once.
    """
    value, problem = read_number(answer, "the dimension")
    if problem is not None:
        return problem
    k = p["k"]
    _, scales, expected = _tent(k)
    if _near(value, expected, 1e-4):
        how = ("with x = 2^-D, 2x + 2x^2 = 1 gives x = (sqrt 3 - 1)/2 and D = log2(1 + sqrt 3)" if k == 4 else
               "the sum of s_i^D equal to one gives D")
        return correct(f"the copies are drawn at the scales {', '.join(fmt(s) for s in scales)} (the RESIZE factors "
                       f"multiply); {how} = {fmt(expected, 6)}.")
    s = _tent_slips(p)
    end, middle = ("a quarter", "half") if k == 4 else (f"{_frac(1 / k)}", f"{_frac((k - 2) / k)}")
    slips = [
        (s["all at the end scale"],
         f"that treats all four copies as {end} of the size; the RESIZE {_frac(k - 2)} after the first copy makes "
         f"the middle two copies {middle} the size"),
        (s["all at the middle scale"],
         f"that treats all four copies as {middle} the size; the first and the last copy are drawn at {end}"),
        (s["the Koch curve"],
         "that is the Koch curve's dimension, four copies at a third; here the RESIZE factors give each copy its "
         "own scale"),
        (s["the mean scale"],
         "that uses the mean scale for all four copies; with unequal scales solve the sum of s_i^D equal to one, "
         "each copy with its own s_i"),
        (s["three copies"], "that counts three copies; the program calls R four times"),
        (s["each scale once"],
         "that counts each different scale once; every call of R is a copy, so a scale used twice counts twice"),
    ]
    for v, why in slips:
        if _near(value, v, 1e-4):
            return wrong(f"{why}.")
    x = ", with x = 2^-D" if k == 4 else ""
    return wrong(f"the dimension is {off_by(value, expected)}. Hint: write down the step in force at each R (the "
                 f"product of the RESIZEs before it), then solve the sum of s_i^D equal to one{x}.")


# -- exercise 3.3: the direction of a chord of the C-curve ----------------------------------------

def _angle_mod(a: float) -> float:
    """An angle in degrees reduced to [0, 360)."""
    return a % 360.0


def _same_angle(a, b) -> bool:
    d = abs(_angle_mod(float(a)) - _angle_mod(float(b)))
    return min(d, 360 - d) <= 0.01


@functools.lru_cache(maxsize=16)
def _chord(j: int) -> float:
    level = j + 5
    (curve,) = fractals.c_curve(level)
    return float(fractals.chord_angles(curve, 0, [2 ** (level - j)])[0])


def _chord_slips(p) -> dict:
    j = p["level"]
    e = _chord(j)
    return {"one turn of 45": 45.0, "one halving fewer": 45.0 * (j - 1), "one halving more": 45.0 * (j + 1),
            "clockwise": -e, "along the x-axis": 0.0}


def _chord_statement(p) -> str:
    return (f"Let C(t) be the C-curve from (0, 0) to (1, 0) (level 0: FORWARD 1; level n: TURN 45, RESIZE "
            f"1/sqrt(2), C, TURN -90, C, TURN 45, RESIZE sqrt(2)), t the fraction of its length. In which direction "
            f"(degrees from the x-axis) does the chord from C(0) to C(h) point for h = 2^-{p['level']}? "
            f"(Goldman §3.3)")


def _chord_steps(p) -> str:
    j = p["level"]
    return (f"1. C(1/2) is the end of the first half, a copy turned by 45 degrees and scaled by 1/sqrt 2.\n"
            f"2. C(2^-j) is the end of the first half of the first half of ... ({j} times): {j} nested copies, "
            f"each turned by another 45 degrees.\n"
            f"3. The chord points at 45 * {j} = {45 * j} degrees, that is {fmt(_angle_mod(_chord(j)))} mod 360 "
            f"(measured on level {j + 5}: {fmt(_chord(j))}).")


@DECK.exercise(stored={"level": CHORD_LEVEL}, generate=lambda rng: {"level": int(rng.integers(2, 10))},
               answer=lambda p: _chord(p["level"]), slips=_chord_slips, statement=_chord_statement,
               steps=_chord_steps, same=_same_angle)
def check_c_curve_chord(answer, p) -> Result:
    """Exercise 3.3: the direction of the chord from C(0) to C(2^-j) on the C-curve (Goldman §3.3),
    in degrees.  Any angle equal mod 360 is right (0.01).

    Recognises one turn of 45 only, a neighbouring level, the turns taken clockwise, and the chord
    taken along the x-axis as for the Koch curve.
    """
    what = "the chord's direction"
    value, problem = read_number(answer, what, "number of degrees")
    if problem is not None:
        return problem
    j = p["level"]
    expected = _chord(j)
    r = _angle_mod(value)
    same = _same_angle

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


# -- exercise 3.5: the attraction bound ---------------------------------------------------------

_C_SCALE = float(fractals.recursion_scales(fractals.c_curve_program()).max())


def _bound_generate(rng) -> dict:
    return {"start": round(float(rng.integers(2, 19)) * 0.05, 2), "level": int(rng.integers(3, 10))}


def _bound_answer(p) -> float:
    return p["start"] * _C_SCALE ** p["level"]


def _bound_slips(p) -> dict:
    d0, n, s = p["start"], p["level"], _C_SCALE
    return {"the Koch curve's third": d0 / 3 ** n, "a half": d0 / 2 ** n, "one level fewer": d0 * s ** (n - 1),
            "one level more": d0 * s ** (n + 1), "the copies added up": d0 * (2 * s) ** n, "no shrinking": d0}


def _bound_statement(p) -> str:
    return (f"Two base cases for the C-curve both move the turtle as FORWARD 1 does, and their level-0 drawings are "
            f"at Hausdorff distance {fmt(p['start'])}. What upper bound does the attraction argument give for the "
            f"distance between their level-{p['level']} drawings? (Goldman §3.4)")


def _bound_steps(p) -> str:
    d0, n = p["start"], p["level"]
    return (f"1. Level n of either drawing is two copies of level n-1, each scaled by 1/sqrt 2 (the C-curve's "
            f"maps).\n"
            f"2. The Hausdorff distance of two unions is at most the largest distance of matching copies, so each "
            f"level multiplies the bound by 1/sqrt 2.\n"
            f"3. Level {n}: {fmt(d0)} (1/sqrt 2)^{n} = {fmt(_bound_answer(p), 6)}.")


@DECK.exercise(stored={"start": BOUND_START, "level": BOUND_LEVEL}, generate=_bound_generate, answer=_bound_answer,
               slips=_bound_slips, statement=_bound_statement, steps=_bound_steps, same=within(1e-5))
def check_attraction_bound(answer, p) -> Result:
    """Exercise 3.5: the bound on the Hausdorff distance at a level between two C-curve drawings a given
    distance apart at level 0 (Goldman §3.4), from the contraction factor of the C-curve's maps.  Accepts 1e-5.

    Recognises the Koch curve's factor 1/3, a factor 1/2, a neighbouring level, the copies' distances
    added up (times 2 per level), and no shrinking at all.
    """
    what = "the bound"
    value, problem = read_number(answer, what)
    if problem is not None:
        return problem
    d0, n = p["start"], p["level"]
    s = _C_SCALE
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



#: Deal another instance of an exercise (``deal("check_program_dimension")``, or with ``seed=``; 0
#: is the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
#: Exercise 3.4 asks for a program (any base case that moves the turtle as FORWARD 1 does): it
#: does not deal.
PROBLEMS = DECK.problems({"check_c_curve_base_case": (
    "Give a base case for the C-curve program (a list of (command, value) pairs) that draws something other "
    "than FORWARD 1 at level 0, yet whose levels converge to the same C-curve (Goldman §3.4).")})


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

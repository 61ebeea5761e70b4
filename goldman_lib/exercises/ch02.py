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

import functools
import math

import numpy as np

from goldman_lib import fractals, turtle
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises.deal import Deck, within
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "LOOP_PASS", "STAR_PASSES", "CENTRE_PASS", "GASKET_SIDES", "C_CURVE_LEVEL",
           "PROJECT_SEED", "DECK", "deal", "steps", "current", "deal_button", "check_loop_period", "check_star_angle", "check_loop_centre", "check_gasket_scale",
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

DECK = Deck("ch02")

#: One loop analysis per pass (the checker, its slips and its steps ask for it many times).
_analysis = functools.lru_cache(maxsize=1024)(fractals.loop_analysis)


def _turns(pass_: str) -> list[float]:
    return [float(v) for v in pass_.split()[3::4]]


def _num(x) -> str:
    return fmt(x)


# -- exercise 2.1: the period of a loop ---------------------------------------------------------

_TURN_CHOICES = (30, 36, 40, 45, 60, 72, 90, 120, 135, 144, 150)


def _loop_generate(rng) -> dict:
    a, b = (int(v) for v in rng.integers(1, 4, size=2))
    t1 = int(rng.choice(_TURN_CHOICES))
    t2 = int(rng.integers(5, 86)) * 2
    return {"pass": f"FORWARD {a} TURN {t1} FORWARD {b} TURN {t2}"}


def _loop_numbers(p):
    loop = _analysis(p["pass"])
    return loop, round(loop.total_turning)


def _loop_answer(p) -> int:
    return int(_analysis(p["pass"]).period)


def _loop_slips(p) -> dict:
    loop, T = _loop_numbers(p)
    out = {f"the period of TURN {_num(t)} alone": fractals.loop_period(t) for t in _turns(p["pass"])}
    out.update({"360/T, not whole": 360 / T, "a later multiple of the period": 2 * loop.period,
                "the winding number": loop.winding})
    return out


def _loop_ok(p):
    loop, T = _loop_numbers(p)
    if T % 360 == 0 or 360 % T == 0:
        return "one pass turns by a divisor of 360: no looping lemma to use"
    if loop.period > 180:
        return "the period is too long to be a hand exercise"
    if any(fractals.loop_period(t) is None for t in _turns(p["pass"])):
        return "a TURN alone has no period"
    return None


def _loop_statement(p) -> str:
    return (f"After how many repetitions does REPEAT k [{p['pass']}] first bring the turtle back to its initial "
            f"state (position and heading)? (Goldman §2.2)")


def _loop_steps(p) -> str:
    loop, T = _loop_numbers(p)
    turns = _turns(p["pass"])
    g = math.gcd(T, 360)
    return (f"1. One pass turns the turtle by T = {' + '.join(_num(t) for t in turns)} = {T} degrees.\n"
            f"2. By the looping lemma the turtle is back after k passes exactly when k T is a multiple of 360.\n"
            f"3. gcd({T}, 360) = {g}, so T / 360 = {T // g}/{360 // g} in lowest terms.\n"
            f"4. The least k is the denominator: k = {loop.period} (the turtle winds {loop.winding} times round "
            f"the centre on the way).")


@DECK.exercise(stored={"pass": LOOP_PASS}, generate=_loop_generate, answer=_loop_answer, slips=_loop_slips,
               statement=_loop_statement, steps=_loop_steps, same=within(0), well_posed=_loop_ok)
def check_loop_period(answer, p) -> Result:
    """Exercise 2.1: the period of ``REPEAT k [pass]`` for the pass of the statement (Goldman §2.2,
    looping lemma): the least number of passes whose total turning is a multiple of 360.

    answer: a whole number.  Recognises the period of one TURN alone, 360/T (not whole), a later
    multiple, the winding number given instead of the period.
    """
    what = "the number of repetitions"
    k, problem = read_number(answer, what, "whole number")
    if problem is not None:
        return problem
    loop, T = _loop_numbers(p)
    turns = _turns(p["pass"])
    q, w = loop.period, loop.winding
    if k > 1e6:
        return wrong(f"{fmt(k)} passes is far too many; the looping lemma gives a period below 360.")
    if k != int(k) or k < 1:
        return wrong(f"{fmt(k)} is not a whole number of repetitions: 360/{T} is not whole, so one full turn of the "
                     f"heading is not enough; find the least k with k * {T} a multiple of 360.")
    k = int(k)
    if k == q:
        return correct(f"one pass turns {' + '.join(fmt(t) for t in turns)} = {T} degrees = 360 * {w}/{q}: "
                       f"the turtle is first back after {q} passes, having wound {w} times round the centre.")
    for t in turns:
        if k == fractals.loop_period(t):
            return wrong(f"{k} is the period of TURN {fmt(t)} alone; one pass turns the turtle by the sum of its "
                         f"TURNs, and that total decides when it is back.")
    if (k * T) % 360 == 0:
        return wrong(f"after {k} passes the turtle is indeed back ({k} * {T} = {k * T} = {k * T // 360} * 360), but "
                     f"it was already back after fewer: look for the least k with k * {T} a multiple of 360.")
    if k == w:
        return wrong(f"{k} is how many full turns the turtle makes before it is back (the winding number); the "
                     f"question asks for the number of passes.")
    return wrong(f"after {k} passes the turtle has turned {k} * {T} = {k * T} degrees, not a multiple of 360, so it "
                 f"is not back: by the looping lemma it returns exactly when k * {T} is a multiple of 360.")


# -- exercise 2.2: a star that closes after n passes -------------------------------------------

def _star_generate(rng) -> dict:
    return {"n": int(rng.choice([5, 7, 8, 9, 10, 11, 12]))}


def _star_answer(p) -> float:
    n = p["n"]
    w = next(k for k in range(2, n - 1) if math.gcd(k, n) == 1)
    return 360 * w / n


def _star_slips(p) -> dict:
    n = p["n"]
    out = {"the convex polygon": 360 / n, "an angle that does not close": 540 / n}
    d = next((d for d in range(2, n) if n % d == 0), None)
    if d is not None:
        out["an angle that closes after fewer passes"] = 360 / d
    return out


def _star_statement(p) -> str:
    n = p["n"]
    return (f"Give a TURN angle a (degrees, between 0 and 360) for which REPEAT {n} [FORWARD 1 TURN a] "
            f"returns to its initial state after exactly {n} passes (not fewer) and draws a star, "
            f"not a convex polygon (Goldman §2.2).")


def _star_steps(p) -> str:
    n = p["n"]
    stars = [k for k in range(2, n - 1) if math.gcd(k, n) == 1]
    return (f"1. REPEAT {n} [FORWARD 1 TURN a] closes after {n} passes when {n} a = 360 p for a whole p: "
            f"a = 360 p / {n}.\n"
            f"2. It closes after no fewer passes when gcd(p, {n}) = 1, and winds p times round.\n"
            f"3. p = 1 or {n - 1} gives the convex {n}-gon; a star needs 2 <= p <= {n - 2}.\n"
            f"4. So p in {stars}: a = " + ", ".join(fmt(360 * k / n) for k in stars) + " degrees.")


@DECK.exercise(stored={"n": STAR_PASSES}, generate=_star_generate, answer=_star_answer, slips=_star_slips,
               statement=_star_statement, steps=_star_steps, same=within(0.01))
def check_star_angle(answer, p) -> Result:
    """Exercise 2.2: an angle ``a`` for which ``REPEAT n [FORWARD 1 TURN a]`` closes after exactly n
    passes and draws a star (Goldman §2.2).  Every such angle is accepted, within 0.01 degrees."""
    what = "the TURN angle"
    a, problem = read_number(answer, what, "number of degrees")
    if problem is not None:
        return problem
    if abs(a) > 1e6:
        return wrong(f"{fmt(a)} degrees turns the turtle round thousands of times in one TURN; give an angle "
                     f"between -360 and 360.")
    n = p["n"]
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
    w = round(n * a / 360) % n
    if w in (1, n - 1):
        return wrong(f"{fmt(a)} degrees closes after {n} passes, but it draws the convex regular {n}-gon (it winds "
                     f"once around); a star winds around more than once: p = {fmt(a * n / 360)} must be between 2 "
                     f"and {n - 2}.")
    return correct(f"{n} * {fmt(a)} = {fmt(n * a)} = {round(n * a / 360)} * 360 and no fewer passes close: the "
                   f"turtle draws the {{{n}/{min(w, n - w)}}} star.")


# -- exercise 2.3: the centre of a loop --------------------------------------------------------

def _centre_generate(rng) -> dict:
    a, b = (int(v) for v in rng.integers(1, 4, size=2))
    t1 = int(rng.choice([30, 45, 60, 90, 120]))
    t2 = int(rng.choice([-60, -45, -30, 30, 45, 60]))
    return {"pass": f"FORWARD {a} TURN {t1} FORWARD {b} TURN {t2}"}


def _centre_parts(p):
    loop = _analysis(p["pass"])
    return loop, loop.center, loop.displacement, loop.total_turning


def _centre_answer(p):
    return _centre_parts(p)[1]


def _centre_slips(p) -> dict:
    loop, c, d, T = _centre_parts(p)
    dz = complex(*d)
    cw = dz / (1 - complex(math.cos(math.radians(-T)), math.sin(math.radians(-T))))
    return {"clockwise": np.array([cw.real, cw.imag]), "midpoint": d / 2, "end of a pass": np.asarray(d),
            "mirror image": c * np.array([1.0, -1.0])}


def _centre_ok(p):
    loop, c, d, T = _centre_parts(p)
    if loop.center is None or abs(((T + 180) % 360) - 180) < 20 or abs(abs(((T + 180) % 360) - 180) - 180) < 1e-9:
        return "the pass turns by too little (or by 180): the centre is ill-conditioned or a midpoint"
    if np.linalg.norm(c) > 10:
        return "the centre is far away"
    return None


def _centre_statement(p) -> str:
    return (f"The turtle starts at (0, 0) heading (1, 0) and repeats the pass {p['pass']}. Every pass is the "
            f"one before rotated about one centre c. Give c = (x, y) to 4 decimals (Goldman §2.2).")


def _centre_steps(p) -> str:
    loop, c, d, T = _centre_parts(p)
    return (f"1. Run one pass: the turtle ends at d = {fmt(d, 5)} and has turned by T = {fmt(T)} degrees.\n"
            f"2. With points as complex numbers, a pass maps z to d + e^(iT) z; its fixed point c solves "
            f"c = d + e^(iT) c.\n"
            f"3. c = d / (1 - e^(iT)) = {fmt(c, 5)}.")


@DECK.exercise(stored={"pass": CENTRE_PASS}, generate=_centre_generate, answer=_centre_answer,
               slips=_centre_slips, statement=_centre_statement, steps=_centre_steps, same=within(1e-4),
               well_posed=_centre_ok)
def check_loop_centre(answer, p) -> Result:
    """Exercise 2.3: the centre of rotation of the pass of the statement (Goldman §2.2):
    ``c = d / (1 - e^{iT})`` with ``d`` the displacement and ``T`` the turning of one pass.
    Accepts 1e-4.

    Recognises the rotation taken clockwise (``1 - e^{-iT}``), the midpoint of one pass, the end
    point of one pass, the mirror image.
    """
    what = "the centre c"
    got, problem = read_points(answer, what)
    if problem is not None:
        return problem
    if got.shape != (2,):
        return wrong(f"{what} should be one point (x, y); yours has shape {got.shape}.")
    loop, c, d, T = _centre_parts(p)
    if np.all(np.abs(got - c) <= 1e-4):
        return correct(f"c = d / (1 - e^(iT)) = {fmt(c, 5)}: one pass moves the turtle by d = {fmt(d)} and turns "
                       f"it by T = {fmt(T)}, and the {loop.period} passes go round c.")
    s = _centre_slips(p)
    slips = [
        (s["clockwise"], "you turned clockwise: TURN with a positive angle turns counterclockwise, "
                         "so one pass rotates by e^(iT), and c solves c = d + e^(iT) c"),
        (s["midpoint"], "that is the midpoint of the first pass's start and end; the centre is the point that one "
                        "pass leaves fixed: c = d + e^(iT) c, with d the displacement and T the total turning of one "
                        "pass"),
        (s["end of a pass"], "that is where the first pass ends (its displacement d); the centre is the fixed point "
                             "of the rotation by T that carries each pass to the next"),
        (s["mirror image"], "that is the mirror image of the centre in the x-axis: check the sign of the "
                            "imaginary part when you solve c = d + e^(iT) c"),
    ]
    for value, why in slips:
        if np.all(np.abs(got - np.asarray(value)) <= 1e-4):
            return wrong(f"{why}.")
    return wrong(f"your point is {far_off(got, c)} from the centre. Hint: with points "
                 f"as complex numbers, find d and T of one pass and solve c = d + e^(iT) c.")


# -- exercise 2.4: the scale of a polygon gasket -----------------------------------------------

_POLYGONS = {5: "pentagon", 6: "hexagon", 7: "heptagon", 8: "octagon", 9: "nonagon", 10: "decagon",
             12: "dodecagon"}
_GASKETS = {5: "pentagonal", 6: "hexagonal", 7: "heptagonal", 8: "octagonal", 9: "nonagonal", 10: "decagonal",
            12: "dodecagonal"}


def _gasket_reach(n) -> tuple[float, list[float]]:
    """S = the sum of cos(k e) over the slanted sides a copy turns back along (k e < 90), e = 360/n."""
    e = 360 / n
    angles = [k * e for k in range(1, n) if k * e < 90 - 1e-9]
    return sum(math.cos(math.radians(a)) for a in angles), angles


def _gasket_generate(rng) -> dict:
    return {"sides": int(rng.choice([5, 7, 8, 9, 10, 12]))}


def _gasket_answer(p) -> float:
    return float(fractals.recursion_scales(fractals.polygon_gasket_program(p["sides"]))[0])


def _gasket_slips(p) -> dict:
    S, _ = _gasket_reach(p["sides"])
    return {"the Sierpinski scale": 1 / 2, "the hexagonal scale": 1 / 3, "one copy's reach as the side": 1 / (1 + S),
            "a copy's width as the side": 1 / (1 + 2 * S), "a copy's width on both sides": 1 / (2 * (1 + 2 * S))}


def _cos_text(angles) -> str:
    return " + ".join(f"cos {fmt(a)}" for a in angles)


def _gasket_statement(p) -> str:
    n = p["sides"]
    return (f"The {_GASKETS[n]} gasket: level 0 is a regular {_POLYGONS[n]} with side 1; level n is REPEAT {n} "
            f"[RESIZE r, RECURSE, RESIZE 1/r, MOVE 1, TURN {fmt(360 / n)}], a copy scaled by r at each "
            f"corner. For which r do neighbouring copies just touch? Give r to 4 decimals (Goldman §2.3).")


def _gasket_steps(p) -> str:
    n = p["sides"]
    S, angles = _gasket_reach(n)
    r = _gasket_answer(p)
    return (f"1. Follow one side of the big {_POLYGONS[n]} from a corner. The copy at that corner has side r; its "
            f"sides turn by {fmt(360 / n)} degrees at each corner.\n"
            f"2. Along the big side the copy reaches r (its own first side) plus the projections of its slanted "
            f"sides that still go forward: r ({_cos_text(angles)}).\n"
            f"3. The copies at the two ends of the side meet at its midpoint: 2 r (1 + {_cos_text(angles)}) = 1.\n"
            f"4. r = {fmt(r, 6)}.")


@DECK.exercise(stored={"sides": GASKET_SIDES}, generate=_gasket_generate, answer=_gasket_answer,
               slips=_gasket_slips, statement=_gasket_statement, steps=_gasket_steps, same=within(1e-4))
def check_gasket_scale(answer, p) -> Result:
    """Exercise 2.4: the scale ``r`` of a polygon gasket's copies (Goldman §2.3, fractal gaskets):
    along a side of the big polygon, the copies at its two corners just touch.  Accepts 1e-4.

    Recognises the Sierpinski and hexagonal scales (1/2, 1/3), one copy's reach taken as the whole
    side, and the copy's full width used on both sides.
    """
    what = "the scale r"
    r, problem = read_number(answer, what)
    if problem is not None:
        return problem
    n = p["sides"]
    name = _POLYGONS[n]
    S, angles = _gasket_reach(n)
    cos_text = _cos_text(angles)
    expected = _gasket_answer(p)
    if abs(r - expected) <= 1e-4:
        formula = ("2 r (1 + cos 45) = 1 gives r = 1 / (2 + sqrt 2)" if n == 8 else
                   f"2 r (1 + {cos_text}) = 1 gives r")
        return correct(f"{formula} = {fmt(expected, 6)}: the copies at the two "
                       f"ends of a side meet at its midpoint.")
    s = _gasket_slips(p)
    corners = f"{fmt(360 / n)} degree corners" if n != 8 else "45 degree corners"
    slips = [
        (s["the Sierpinski scale"], f"1/2 is the scale of the Sierpinski gasket, whose triangles meet at a point; "
                                    f"the {name}'s copies reach out sideways too, so they must be smaller"),
        (s["the hexagonal scale"], f"1/3 is the scale of the hexagonal gasket (and the carpet); the {name}'s copies "
                                   f"reach {'further' if S > 0.5 else 'less far'} along a side, because of its "
                                   f"{corners}"),
        (s["one copy's reach as the side"], f"along a side one copy reaches r + r {' + r '.join(cos_text.split(' + '))} "
                                            f"from its corner, and there are two copies on each side, one at each "
                                            f"end: their reaches add up to the side"),
        (s["a copy's width as the side"], f"r (1 + 2 {'(' + cos_text + ')' if len(angles) > 1 else cos_text}) is the "
                                          f"whole width of a copy; along the big {name}'s side each copy reaches only "
                                          f"r + r {' + r '.join(cos_text.split(' + '))} from its corner, and the two "
                                          f"copies at its ends share the side"),
        (s["a copy's width on both sides"], f"r (1 + 2 {'(' + cos_text + ')' if len(angles) > 1 else cos_text}) is "
                                            f"the whole width of a copy, but along the side each copy reaches only "
                                            f"r + r {' + r '.join(cos_text.split(' + '))} from its corner (its other "
                                            f"slanted side points back)"),
    ]
    for value, why in slips:
        if abs(r - value) <= 1e-4:
            return wrong(f"{why}.")
    return wrong(f"{what} is {off_by(r, expected)}. Hint: follow one side of the big {name} from a corner: how far "
                 f"along it does the copy at that corner reach, and where does it meet the copy at the other end?")


# -- exercise 2.5: the commands of the C-curve -------------------------------------------------

def _commands_generate(rng) -> dict:
    return {"level": int(rng.integers(3, 11))}


def _commands_answer(p) -> int:
    return int(fractals.c_curve_program().count(p["level"]))


def _commands_slips(p) -> dict:
    n = p["level"]
    prog = fractals.c_curve_program()
    expected = prog.count(n)
    return {"the FORWARDs only": 2 ** n, "the other commands only": expected - 2 ** n,
            "one level fewer": prog.count(n - 1), "one level more": prog.count(n + 1),
            "added, not doubled": 1 + 5 * n}


def _commands_statement(p) -> str:
    return (f"The C-curve: level 0 is FORWARD 1; level n is TURN 45, RESIZE 1/sqrt(2), C, TURN -90, C, TURN 45, "
            f"RESIZE sqrt(2), where C runs level n-1. How many turtle commands (FORWARD, TURN and RESIZE each "
            f"count one) does level {p['level']} execute? (Goldman §2.3)")


def _commands_steps(p) -> str:
    n = p["level"]
    prog = fractals.c_curve_program()
    counts = ", ".join(f"c({k}) = {prog.count(k)}" for k in range(n + 1))
    return (f"1. Let c(n) be the commands level n executes. Level 0 is FORWARD 1: c(0) = 1.\n"
            f"2. The body runs 5 commands of its own and level n-1 twice: c(n) = 5 + 2 c(n-1).\n"
            f"3. {counts}.\n"
            f"4. In closed form c(n) = 6 * 2^n - 5, so c({n}) = {prog.count(n)}.")


@DECK.exercise(stored={"level": C_CURVE_LEVEL}, generate=_commands_generate, answer=_commands_answer,
               slips=_commands_slips, statement=_commands_statement, steps=_commands_steps, same=within(0))
def check_c_curve_commands(answer, p) -> Result:
    """Exercise 2.5: the commands executed by a level of the C-curve (Goldman §2.3), from the
    recurrence of the command count c(n) of level n.

    Recognises the FORWARDs alone, the other commands alone, a neighbouring level, and the
    recursion added instead of doubled.
    """
    n = p["level"]
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


#: Deal another instance of an exercise (``deal("check_loop_period")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a "Deal another" button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems()


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

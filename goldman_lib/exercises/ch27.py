"""Exercise checkers for chapter 27, B-spline curves and surfaces (Goldman §27.2-27.9).

Every exercise deals new numbers (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0 is
the module constants below (the stored notebook), ``deal("check_...")`` or
``deal_button("check_...")`` deals another, each checker checks the current instance,
``PROBLEMS`` states it and ``steps("check_...")`` shows its worked steps, computed by the library.
The chapter's "show that" exercises (in :mod:`goldman_lib.exercises.proofs`) ask for an
expression, not a number, so they do not deal.  ``SLIPS`` holds the wrong answers of the kinds each
checker recognises, for the stored instances.  The data differ from the chapter's worked examples
(its cubic on clamped uniform knots, the quadratic u^2 spline, the circle and the sphere).

>>> print(PROBLEMS["check_continuity_orders"])  # doctest: +ELLIPSIS
A quartic B-spline (degree 4) has the knots ... (Goldman §27.4).
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from goldman_lib import bspline
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, fmt_points, off_by, read_points, wrong
from goldman_lib.exercises.deal import Deck, memo, plain as _tup, steps_number as _f, within

__all__ = ["PROBLEMS", "SLIPS",
           "CURVE_CTRL", "CURVE_KNOTS", "CURVE_DEGREE", "DE_BOOR_U", "BASIS_U",
           "CONT_DEGREE", "CONT_KNOTS", "CONT_AT",
           "SPLINE_PIECES", "SPLINE_BREAKS", "SPLINE_CONTINUITY",
           "SURF_HEIGHTS", "SURF_KNOTS_U", "SURF_KNOTS_V", "SURF_DEGREES", "SURF_UV",
           "NURBS_CTRL", "NURBS_WEIGHTS", "NURBS_KNOTS", "NURBS_U", "PYRAMID_KNOTS", "PYRAMID_DEGREE", "PYRAMID_NODE",
           "DECK", "deal", "steps", "current", "deal_button",
           "check_local_de_boor", "check_basis_values", "check_continuity_orders",
           "check_spline_control_points", "check_surface_point", "check_nurbs_point", "check_pyramid_node_interval"]

#: Exercises 1-2: a quadratic B-spline on non-uniform knots (interior knots 1 and 3).
CURVE_CTRL = np.array([[0.0, 0.0], [1.0, 3.0], [4.0, 6.0], [7.0, 0.0], [9.0, 2.0]])
CURVE_KNOTS = np.array([0.0, 0, 0, 1, 3, 4, 4, 4])
CURVE_DEGREE = 2
#: Exercise 1: the parameter of the local de Boor algorithm.
DE_BOOR_U = 2.0
#: Exercise 2: the parameter of the basis values.
BASIS_U = 2.5
#: Exercise 3: a quartic whose interior knots 1, 2, 3, 4 have multiplicities 1, 2, 3, 4.
CONT_DEGREE = 4
CONT_KNOTS = np.array([0.0] * 5 + [1.0] + [2.0] * 2 + [3.0] * 3 + [4.0] * 4 + [5.0] * 5)
CONT_AT = np.array([1.0, 2.0, 3.0, 4.0])
#: Exercise 4: a C^1 quadratic spline given piece by piece (power coefficients, lowest first).
SPLINE_PIECES = np.array([[[0.0], [2.0], [-1.0]],        # 2u - u^2 on [0, 1]
                          [[0.5], [1.0], [-0.5]]])       # 0.5 + u - u^2/2 on [1, 3]
SPLINE_BREAKS = np.array([0.0, 1.0, 3.0])
SPLINE_CONTINUITY = 1
#: Exercise 5: a surface of degree 1 in u and 2 in v over the net P_ij = (i, j, SURF_HEIGHTS[i][j]).
SURF_HEIGHTS = np.array([[0.0, 2.0, 0.0], [2.0, 4.0, 2.0], [4.0, 0.0, 6.0]])
SURF_KNOTS_U = np.array([0.0, 0, 1, 2, 2])
SURF_KNOTS_V = np.array([0.0, 0, 0, 1, 1, 1])
SURF_DEGREES = (1, 2)
SURF_UV = (1.5, 0.5)
#: Exercise 6: a quadratic NURBS curve with three different weights.
NURBS_CTRL = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
NURBS_WEIGHTS = np.array([1.0, 2.0, 1.0, 3.0])
NURBS_KNOTS = np.array([0.0, 0, 0, 1, 2, 2, 2])
NURBS_U = 1.5
#: Exercise 7 (§27.5): a node (level r, index i) of the global de Boor pyramid of a quadratic.
PYRAMID_KNOTS = np.array([0.0, 0, 0, 1, 2, 4, 5, 5, 5])
PYRAMID_DEGREE = 2
PYRAMID_NODE = (1, 3)

DECK = Deck("ch27")

_DEGREE_NAMES = {1: "linear", 2: "quadratic", 3: "cubic", 4: "quartic", 5: "quintic"}


def _knots(t) -> str:
    return "[" + ", ".join(fmt(x) for x in t) + "]"


def _arr(v):
    return np.asarray(v, dtype=float)


def _frac(x) -> str:
    """A weight as a learner writes it: a fraction with a small denominator (2/3, 1/2), else a decimal."""
    q = Fraction(float(x)).limit_denominator(24)
    if abs(float(q) - float(x)) < 1e-12:
        return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"
    return fmt(x)


def _read_point(answer, what: str, dim: int):
    got, err = read_points(answer, what, ask=f"{what} as [{', '.join('xyz'[:dim])}]")
    if err is not None:
        return None, err
    if got.shape != (dim,):
        return None, wrong(f"{what} should be one point [{', '.join('xyz'[:dim])}]; yours has shape {got.shape}.")
    return got, None


def _near(a, b, tol) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= tol))


def _terminating(x, places: int = 4) -> bool:
    """Whether every entry of x is a decimal of at most ``places`` places (a learner can type it
    exactly: the checker's tolerance 1e-6 does not forgive a rounded third)."""
    scaled = np.asarray(x, dtype=float) * 10 ** places
    return bool(np.all(np.abs(scaled - np.round(scaled)) < 1e-6))


def _hand_exact(answer):
    """The ``well_posed`` rule of the exercises checked to 1e-6: an answer of short decimals."""
    def ok(p):
        return None if _terminating(answer(p)) else "the answer is not a short decimal (a hand answer would be rounded)"
    return ok


def _quadratic_knots(rng) -> tuple:
    """Clamped quadratic knots 0, 0, 0, a, b, c, c, c with whole a < b < c (the middle span [a, b) at least 2 long)."""
    a = int(rng.integers(1, 3))
    b = a + int(rng.integers(2, 5))
    c = b + int(rng.integers(1, 3))
    return (0.0, 0.0, 0.0, float(a), float(b), float(c), float(c), float(c))


# -- Exercise 1 -----------------------------------------------------------------------------------

def _span_curve(P, t, p, k: int, u: float) -> np.ndarray:
    """C(u) computed with the pyramid of span k (right for k = the span of u, a slip otherwise)."""
    pts = np.array(P[k - p:k + 1], dtype=float)
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            i = k - p + j
            a = (u - t[i]) / (t[i + p + 1 - r] - t[i])
            pts[j] = (1 - a) * pts[j - 1] + a * pts[j]
    return pts[p]


_STORED_DE_BOOR = {"ctrl": _tup(CURVE_CTRL), "knots": _tup(CURVE_KNOTS), "u": DE_BOOR_U}


@memo
def _de_boor_answers(p):
    P, t, u, deg = _arr(p["ctrl"]), _arr(p["knots"]), p["u"], CURVE_DEGREE
    k = int(bspline.find_span(t, deg, u))
    levels = bspline.de_boor_steps(P, t, deg, u)
    s = (u - t[k]) / (t[k + 1] - t[k])
    Q = P[k - deg:k + 1]
    slips = {f"level 1, node {k - 1 + j}": levels[1][j] for j in range(len(levels[1]))}
    slips["de Casteljau's weight"] = (1 - s) ** 2 * Q[0] + 2 * s * (1 - s) * Q[1] + s ** 2 * Q[2]
    for other in (k - 1, k + 1):
        if deg <= other <= len(P) - 1:
            slips[f"span {other}"] = _span_curve(P, t, deg, other, u)
    return levels[-1][0], slips


def _de_boor_generate(rng) -> dict:
    t = _quadratic_knots(rng)
    u = t[3] + float(rng.integers(1, int(t[4] - t[3])))
    return {"ctrl": _tup(rng.integers(0, 10, size=(5, 2))), "knots": t, "u": u}


def _de_boor_statement(p) -> str:
    return (f"The quadratic B-spline with control points {fmt_points(p['ctrl'])} and knots {_knots(p['knots'])}: "
            f"evaluate C({fmt(p['u'])}) by the local de Boor algorithm (find the span, then two levels of "
            f"affine combinations, each with the knots of its own node). Give C(u) as [x, y] (Goldman §27.2).")


def _de_boor_steps(p) -> str:
    P, t, u, deg = _arr(p["ctrl"]), _arr(p["knots"]), p["u"], CURVE_DEGREE
    k = int(bspline.find_span(t, deg, u))
    levels = bspline.de_boor_steps(P, t, deg, u)
    lines = [f"1. The span: t{k} = {fmt(t[k])} <= u = {fmt(u)} < t{k + 1} = {fmt(t[k + 1])}, so k = {k} and "
             f"P{k - deg}, ..., P{k} act: {fmt_points(levels[0])}."]
    for r in range(1, deg + 1):
        parts = []
        for j, point in enumerate(levels[r]):
            i = k - deg + r + j
            a = (u - t[i]) / (t[i + deg + 1 - r] - t[i])
            parts.append(f"node {i}: a = (u - t{i})/(t{i + deg + 1 - r} - t{i}) = ({fmt(u)} - {fmt(t[i])})/"
                         f"({fmt(t[i + deg + 1 - r])} - {fmt(t[i])}) = {_f(a)}, point {_f(point)}")
        lines.append(f"{r + 1}. Level {r}: " + "; ".join(parts) + ".")
    lines.append(f"{deg + 2}. C({fmt(u)}) = {_f(levels[-1][0])}.")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_DE_BOOR, generate=_de_boor_generate, answer=lambda p: _de_boor_answers(p)[0],
               slips=lambda p: _de_boor_answers(p)[1], statement=_de_boor_statement, steps=_de_boor_steps,
               same=within(1e-6), well_posed=_hand_exact(lambda p: _de_boor_answers(p)[0]))
def check_local_de_boor(answer, p) -> Result:
    """Check C(u) of the statement's quadratic B-spline by local de Boor (Goldman §27.2); recognises a
    point of level 1, de Casteljau's weights over the span, and the pyramid of a neighbouring span.

    >>> check_local_de_boor([4, 3.75])
    Not yet: you used de Casteljau's weight (u - t_k)/(t_(k+1) - t_k) on every level, as if P1..P3 were a Bezier polygon over the span; de Boor's weight at node i of level r is (u - t_i)/(t_(i+p+1-r) - t_i), with the knots of that node.
    """
    P, t, u, deg = _arr(p["ctrl"]), _arr(p["knots"]), p["u"], CURVE_DEGREE
    what = f"C({fmt(u)})"
    got, err = _read_point(answer, what, 2)
    if err is not None:
        return err
    k = int(bspline.find_span(t, deg, u))
    levels = bspline.de_boor_steps(P, t, deg, u)
    expected = levels[-1][0]
    if _near(got, expected, 1e-6):
        weights = [(u - t[i]) / (t[i + deg] - t[i]) for i in (k - 1, k)]
        return correct(f"{what} = {fmt(expected)}: the span [t{k}, t{k + 1}) = [{fmt(t[k])}, {fmt(t[k + 1])}), "
                       f"points P{k - deg}..P{k}, weights {_frac(weights[0])} and {_frac(weights[1])} on level 1, "
                       f"{_frac((u - t[k]) / (t[k + 1] - t[k]))} on level 2.")
    for j, q in enumerate(levels[1]):
        if _near(got, q, 1e-6):
            return wrong(f"that is the point of node {k - 1 + j} on level 1 of the pyramid; a quadratic needs 2 "
                         f"levels: combine the two level-1 points once more, with the weight "
                         f"(u - t_i)/(t_(i+1) - t_i).")
    s = (u - t[k]) / (t[k + 1] - t[k])
    Q = P[k - deg:k + 1]
    if _near(got, (1 - s) ** 2 * Q[0] + 2 * s * (1 - s) * Q[1] + s ** 2 * Q[2], 1e-6):
        return wrong(f"you used de Casteljau's weight (u - t_k)/(t_(k+1) - t_k) on every level, as if "
                     f"P{k - deg}..P{k} were a Bezier polygon over the span; de Boor's weight at node i of level r is "
                     f"(u - t_i)/(t_(i+p+1-r) - t_i), with the knots of that node.")
    for other in (k - 1, k + 1):
        if deg <= other <= len(P) - 1 and _near(got, _span_curve(P, t, deg, other, u), 1e-6):
            return wrong(f"you ran the pyramid on P{other - deg}..P{other}, the points of another span; u = {fmt(u)} "
                         f"lies in [t{k}, t{k + 1}) = [{fmt(t[k])}, {fmt(t[k + 1])}), so P_(k-p)..P_k act.")
    return wrong(f"your point is {far_off(got, expected)} from {what}. Find the span "
                 f"t_k <= u < t_(k+1) first; on level r the weight of node i is (u - t_i)/(t_(i+p+1-r) - t_i).")


# -- Exercise 2 -----------------------------------------------------------------------------------

_STORED_BASIS = {"knots": _tup(CURVE_KNOTS), "u": BASIS_U}


@memo
def _basis_answers(p):
    t, u, deg = _arr(p["knots"]), p["u"], CURVE_DEGREE
    expected = bspline.basis(t, deg, u)[1:4]
    k = int(bspline.find_span(t, deg, u))
    s = (u - t[k]) / (t[k + 1] - t[k])
    return expected, {"Bernstein": np.array([(1 - s) ** 2, 2 * s * (1 - s), s ** 2]), "reverse order": expected[::-1]}


def _basis_generate(rng) -> dict:
    t = _quadratic_knots(rng)
    return {"knots": t, "u": t[3] + float(rng.integers(1, 2 * int(t[4] - t[3]))) / 2}


def _basis_statement(p) -> str:
    same = "the same knots" if p == _STORED_BASIS else "the knots"
    return (f"On {same} {_knots(p['knots'])}, three quadratic B-splines are non-zero at u = {fmt(p['u'])}. "
            f"Compute them with the recurrence of the global de Boor algorithm, from the degree-0 functions up, and "
            f"give [N_1,2(u), N_2,2(u), N_3,2(u)] to 4 decimals (Goldman §27.3).")


def _basis_steps(p) -> str:
    t, u = _arr(p["knots"]), p["u"]
    k = int(bspline.find_span(t, CURVE_DEGREE, u))
    lines = [f"1. u = {fmt(u)} lies in [t{k}, t{k + 1}) = [{fmt(t[k])}, {fmt(t[k + 1])}): N_{k},0 = 1, the other "
             f"degree-0 functions vanish."]
    for r in (1, 2):
        d = CURVE_DEGREE - r     # the degree-r functions live on the knots without d end knots each side
        N = bspline.basis(t[d:t.size - d], r, u)
        nz = ", ".join(f"N_{i},{r} = {_f(N[i - d])}" for i in range(k - r, k + 1))
        lines.append(f"{r + 1}. Degree {r}, N_k,{r} = (u - t_k)/(t_(k+{r}) - t_k) N_k,{r - 1} + "
                     f"(t_(k+{r + 1}) - u)/(t_(k+{r + 1}) - t_(k+1)) N_k+1,{r - 1}: {nz}.")
    lines.append("4. They sum to 1 (partition of unity).")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_BASIS, generate=_basis_generate, answer=lambda p: _basis_answers(p)[0],
               slips=lambda p: _basis_answers(p)[1], statement=_basis_statement, steps=_basis_steps,
               same=within(1e-4))
def check_basis_values(answer, p) -> Result:
    """Check the three quadratic B-splines non-zero at the statement's u (Goldman §27.3); recognises the
    Bernstein values of the span's local parameter and the values in reverse order.
    """
    t, u, deg = _arr(p["knots"]), p["u"], CURVE_DEGREE
    what = f"[N_1,2, N_2,2, N_3,2] at u = {fmt(u)}"
    got, err = read_points(answer, "your basis values", ask=what + " as a list of three numbers")
    if err is not None:
        return err
    got = got.reshape(-1)
    if got.size != 3:
        return wrong(f"give the three basis functions that are non-zero at u = {fmt(u)}, "
                     f"[N_1,2, N_2,2, N_3,2]; you gave {got.size} numbers.")
    expected = bspline.basis(t, deg, u)[1:4]
    if _near(got, expected, 1e-4):
        return correct(f"N_1,2, N_2,2, N_3,2 at u = {fmt(u)} match, and they sum to 1 (partition of unity).")
    k = int(bspline.find_span(t, deg, u))
    s = (u - t[k]) / (t[k + 1] - t[k])
    if _near(got, [(1 - s) ** 2, 2 * s * (1 - s), s ** 2], 1e-4):
        return wrong(f"those are the Bernstein values of the span's local parameter (u - {fmt(t[k])})/"
                     f"({fmt(t[k + 1])} - {fmt(t[k])}); on non-uniform knots the B-splines are not Bernstein "
                     f"polynomials: each level of the recurrence divides by its own knot difference, t_(k+r) - t_k.")
    if _near(got, expected[::-1], 1e-4):
        return wrong("your values are in reverse order: N_1,2 is the one whose support [t1, t4] ends soonest.")
    if abs(got.sum() - 1) > 1e-3:
        return wrong(f"your values sum to {fmt(got.sum())}, but the B-splines of a degree sum to 1 at every u "
                     f"(partition of unity); check the two terms of N_2,2 and the single terms of N_1,2 and N_3,2.")
    bad = int(np.flatnonzero(np.abs(got - expected) > 1e-4)[0])
    return wrong(f"N_{bad + 1},2 is {off_by(got[bad], expected[bad])}. Start from N_{k},0 = 1 on [t{k}, t{k + 1}), "
                 f"then N_k,r = (u - t_k)/(t_(k+r) - t_k) N_k,r-1 + (t_(k+r+1) - u)/(t_(k+r+1) - t_(k+1)) N_k+1,r-1.")


# -- Exercise 3 -----------------------------------------------------------------------------------

_STORED_CONT = {"degree": CONT_DEGREE, "knots": _tup(CONT_KNOTS), "at": _tup(CONT_AT)}


def _mults(p) -> np.ndarray:
    return np.array([bspline.multiplicity(_arr(p["knots"]), x) for x in p["at"]])


@memo
def _cont_answers(p):
    deg, mult = p["degree"], _mults(p)
    expected = deg - mult
    return expected, {"the multiplicities": mult, "one too low": expected - 1,
                      "C^(p - 1) everywhere": np.full(mult.size, deg - 1)}


def _cont_generate(rng) -> dict:
    deg = int(rng.integers(2, 6))
    mult = rng.integers(1, deg + 1, size=4)
    knots = [0.0] * (deg + 1) + [float(x) for x, m in zip((1, 2, 3, 4), mult) for _ in range(m)] + [5.0] * (deg + 1)
    return {"degree": deg, "knots": tuple(knots), "at": (1.0, 2.0, 3.0, 4.0)}


def _cont_statement(p) -> str:
    deg = p["degree"]
    return (f"A {_DEGREE_NAMES[deg]} B-spline (degree {deg}) has the knots {_knots(p['knots'])}. How smooth is it "
            f"at each interior knot? Give [k1, k2, k3, k4] for C^k at u = {', '.join(fmt(x) for x in p['at'])} "
            f"(Goldman §27.4).")


def _cont_steps(p) -> str:
    deg, mult = p["degree"], _mults(p)
    rows = "; ".join(f"u = {fmt(x)}: m = {m}, C^{deg - m}" for x, m in zip(p["at"], mult))
    return (f"1. Count how often each interior knot appears (its multiplicity m).\n"
            f"2. At a knot of multiplicity m a spline of degree p = {deg} is C^(p - m): {rows}.\n"
            f"3. The answer is {fmt(deg - mult)} (the library: "
            f"{fmt([bspline.continuity_at(_arr(p['knots']), deg, x) for x in p['at']])}).")


@DECK.exercise(stored=_STORED_CONT, generate=_cont_generate, answer=lambda p: _cont_answers(p)[0],
               slips=lambda p: _cont_answers(p)[1], statement=_cont_statement, steps=_cont_steps,
               same=within(1e-9))
def check_continuity_orders(answer, p) -> Result:
    """Check the order of continuity at each interior knot of the statement's knot vector (Goldman §27.4);
    recognises the multiplicities themselves, every order one too low, and C^(p - 1) everywhere.

    >>> check_continuity_orders([1, 2, 3, 4])
    Not yet: those are the multiplicities of the knots; the smoothness goes the other way: each repetition of a knot removes one order of continuity, C^(p - m).
    """
    what = "[k1, k2, k3, k4]"
    got, err = read_points(answer, "your orders", ask=what + " for C^k at the four interior knots")
    if err is not None:
        return err
    got = got.reshape(-1)
    deg = p["degree"]
    mult = _mults(p)
    if got.size != mult.size:
        return wrong(f"give one order for each of the {mult.size} interior knots; you gave {got.size}.")
    expected = deg - mult
    if np.array_equal(got, expected):
        orders = ", ".join(f"C^{k}" for k in expected)
        return correct(f"at a knot of multiplicity m a {_DEGREE_NAMES[deg]} is C^({deg} - m): {orders} at the knots "
                       f"{', '.join(fmt(x) for x in p['at'])}.")
    if np.array_equal(got, mult):
        return wrong("those are the multiplicities of the knots; the smoothness goes the other way: each "
                     "repetition of a knot removes one order of continuity, C^(p - m).")
    if np.array_equal(got, expected - 1):
        return wrong(f"every order is one too low: a simple knot of a degree-{deg} spline leaves C^(p - 1), so the "
                     f"rule is C^(p - m), and only multiplicity p + 1 lets the curve jump.")
    if np.all(got == got[0]) and got[0] == deg - 1:
        return wrong("C^(p - 1) holds at a simple knot only; count how often each knot is repeated: C^(p - m).")
    bad = int(np.flatnonzero(got != expected)[0])
    return wrong(f"the order at u = {fmt(p['at'][bad])} is not right: count how often that knot appears in the "
                 f"knot vector (m) and use C^(p - m) with p = {deg}.")


# -- Exercise 4 -----------------------------------------------------------------------------------

_STORED_SPLINE = {"pieces": _tup(SPLINE_PIECES[:, :, 0]), "breaks": _tup(SPLINE_BREAKS)}


def _poly(c) -> str:
    """a + b u + c u^2 as a learner writes it (2u - u^2, 0.5 + u - u^2/2)."""
    text = ""
    for coef, mono in zip(c, ("", "u", "u^2")):
        if coef == 0:
            continue
        m = abs(coef)
        term = (mono if m == 1 else f"{mono}/2" if m == 0.5 else f"{fmt(m)}{mono}") if mono else fmt(m)
        text += (" - " if coef < 0 else " + ") + term if text else ("-" if coef < 0 else "") + term
    return text or "0"


@memo
def _spline(p):
    pieces = _arr(p["pieces"])[:, :, None]
    ctrl, knots, _ = bspline.spline_to_bspline(pieces, _arr(p["breaks"]), SPLINE_CONTINUITY)
    return ctrl.reshape(-1), knots


def _piece_value(p, i: int, x) -> float:
    c = _arr(p["pieces"])[i]
    return float(c[0] + c[1] * x + c[2] * x * x)


def _spline_forms(p):
    """The spline's values at the midpoints of the labels, and the first piece's blossoms everywhere."""
    _, knots = _spline(p)
    breaks = _arr(p["breaks"])
    greville = (knots[1:-2] + knots[2:-1]) / 2
    pieces = np.searchsorted(breaks, greville, side="right") - 1
    values = np.array([_piece_value(p, min(i, len(breaks) - 2), x) for i, x in zip(pieces, greville)])
    c0 = _arr(p["pieces"])[0]
    first = np.array([c0[0] + c0[1] * (a + b) / 2 + c0[2] * a * b for a, b in zip(knots[1:-2], knots[2:-1])])
    return values, first


def _spline_generate(rng) -> dict:
    b = float(rng.integers(1, 3))
    e = b + float(rng.integers(1, 3))
    c0 = np.array([rng.integers(-2, 3), rng.integers(-3, 4), rng.choice([-2, -1, 1, 2])], dtype=float)
    dc = float(rng.choice([-2, -1, -0.5, 0.5, 1, 2]))
    c1 = c0 + dc * np.array([b * b, -2 * b, 1.0])     # s2 = s1 + dc (u - b)^2: C^1 at b
    return {"pieces": (_tup(c0), _tup(c1)), "breaks": (0.0, b, e)}


def _spline_statement(p) -> str:
    (c0, c1), (a, b, e) = p["pieces"], p["breaks"]
    return (f"The quadratic spline s(u) = {_poly(c0)} on [{fmt(a)}, {fmt(b)}] and s(u) = {_poly(c1)} on "
            f"[{fmt(b)}, {fmt(e)}] is C^1 at u = {fmt(b)}. "
            f"As a B-spline on the knots {_knots(_spline(p)[1])} "
            "its control points are the blossoms of the pieces at consecutive knots: give the four (numbers) "
            "[P0, P1, P2, P3] (Goldman §27.6).")


def _spline_steps(p) -> str:
    ctrl, knots = _spline(p)
    (c0, c1), b = p["pieces"], p["breaks"][1]
    labels = [(knots[i + 1], knots[i + 2]) for i in range(len(ctrl))]
    rows = "; ".join(f"P{i} = b_{1 if hi <= b else 2}({fmt(lo)}, {fmt(hi)}) = {_f(v)}"
                     for i, ((lo, hi), v) in enumerate(zip(labels, ctrl)))
    return (f"1. The blossom of a + b u + c u^2 is a + b (u1 + u2)/2 + c u1 u2: b_1 for {_poly(c0)}, b_2 for "
            f"{_poly(c1)}.\n"
            f"2. The knots {_knots(knots)}: the labels of the control points are consecutive pairs of the "
            f"inner knots.\n"
            f"3. Each label lies in one piece's span (the label ({fmt(labels[2][0])}, {fmt(labels[2][1])}) in both: "
            f"the spline is C^1 there): {rows}.")


@DECK.exercise(stored=_STORED_SPLINE, generate=_spline_generate, answer=lambda p: _spline(p)[0],
               slips=lambda p: dict(zip(("values of the spline", "first piece beyond its span"), _spline_forms(p))),
               statement=_spline_statement, steps=_spline_steps, same=within(1e-6),
               well_posed=_hand_exact(lambda p: _spline(p)[0]))
def check_spline_control_points(answer, p) -> Result:
    """Check the B-spline control points of the statement's piecewise quadratic (Goldman §27.6); recognises
    values of the spline in place of blossoms and the first piece's blossom used beyond its span.

    >>> check_spline_control_points([0, 1, 1, -3])
    Not yet: P3 = b(3, 3) has a label in the span [1, 3]: use the blossom of the second piece there (you used the first piece's blossom beyond its span).
    """
    what = "[P0, P1, P2, P3]"
    got, err = read_points(answer, "your control points", ask=what + " as a list of four numbers")
    if err is not None:
        return err
    got = got.reshape(-1)
    expected, knots = _spline(p)
    b, e = p["breaks"][1], p["breaks"][2]
    if got.size != expected.size:
        return wrong(f"a quadratic with the knots {_knots(knots)} has {expected.size} control points "
                     f"(number of knots - p - 1); you gave {got.size}.")
    if _near(got, expected, 1e-6):
        labels = ", ".join(f"b({fmt(knots[i + 1])}, {fmt(knots[i + 2])})" for i in range(expected.size))
        return correct(f"the control points are the blossoms {labels}; P2 comes out the "
                       f"same from either piece because the spline is C^1 at u = {fmt(b)}.")
    values, first = _spline_forms(p)
    if _near(got, values, 1e-6):
        return wrong("those are values of the spline (at the midpoints of the labels); a control point is not a "
                     "point of the curve but the blossom: replace u^2 by u1 u2 and u by (u1 + u2)/2, then put in "
                     "the two knots of the label.")
    if _near(got, first, 1e-6):
        return wrong(f"P3 = b({fmt(e)}, {fmt(e)}) has a label in the span [{fmt(b)}, {fmt(e)}]: use the blossom of "
                     f"the second piece there (you used the first piece's blossom beyond its span).")
    bad = int(np.flatnonzero(np.abs(got - expected) > 1e-6)[0])
    label = (knots[bad + 1], knots[bad + 2])
    return wrong(f"P{bad} is {off_by(got[bad], expected[bad])}. Its label is ({fmt(label[0])}, {fmt(label[1])}); the "
                 f"blossom of a + b u + c u^2 is a + b (u1 + u2)/2 + c u1 u2.")


# -- Exercise 5 -----------------------------------------------------------------------------------

_STORED_SURFACE = {"heights": _tup(SURF_HEIGHTS), "uv": tuple(float(x) for x in SURF_UV)}


def _surface_net(heights) -> np.ndarray:
    heights = _arr(heights)
    m, n = heights.shape
    i, j = np.meshgrid(np.arange(m, dtype=float), np.arange(n, dtype=float), indexing="ij")
    return np.stack([i, j, heights], axis=-1)


@memo
def _surface_answers(p):
    net = _surface_net(p["heights"])
    (dp, dq), (u, v) = SURF_DEGREES, p["uv"]
    expected = bspline.surface_de_boor(net, SURF_KNOTS_U, SURF_KNOTS_V, dp, dq, u, v)
    Nu, Nv = bspline.basis(SURF_KNOTS_U, dp, u), bspline.basis(SURF_KNOTS_V, dq, v)
    slips = {"knots swapped": np.einsum("j,i,ijd->d", Nu, Nv, net)}
    rows = np.einsum("j,ijd->id", Nv, net)
    for i in np.flatnonzero(Nu > 0):
        slips[f"row {i} alone"] = rows[i]
    return expected, slips


def _surface_generate(rng) -> dict:
    return {"heights": _tup(rng.integers(0, 7, size=(3, 3))),
            "uv": (float(rng.choice([0.25, 0.5, 0.75, 1.25, 1.5, 1.75])), float(rng.choice([0.25, 0.5, 0.75])))}


def _surface_statement(p) -> str:
    h, (u, v) = _arr(p["heights"]), p["uv"]
    return (f"A B-spline surface has degree {SURF_DEGREES[0]} in u with knots {_knots(SURF_KNOTS_U)} and degree "
            f"{SURF_DEGREES[1]} in v with knots {_knots(SURF_KNOTS_V)}. Its control net is P_ij = (i, j, z_ij), "
            f"i, j = 0, 1, 2 (i goes with u, j with v), with heights z_0j = {fmt(h[0])}, "
            f"z_1j = {fmt(h[1])}, z_2j = {fmt(h[2])}. Give S({fmt(u)}, "
            f"{fmt(v)}) as [x, y, z] (Goldman §27.8).")


def _surface_steps(p) -> str:
    net = _surface_net(p["heights"])
    (dp, dq), (u, v) = SURF_DEGREES, p["uv"]
    Nu, Nv = bspline.basis(SURF_KNOTS_U, dp, u), bspline.basis(SURF_KNOTS_V, dq, v)
    rows = np.einsum("j,ijd->id", Nv, net)
    active = np.flatnonzero(Nu > 0)
    return (f"1. In v (degree {dq}, knots {_knots(SURF_KNOTS_V)}): N_0,2, N_1,2, N_2,2 at v = {fmt(v)} are "
            f"{_f(Nv)}.\n"
            f"2. Each active row's v-point, sum_j N_j,2(v) P_ij: "
            + "; ".join(f"row {i}: {_f(rows[i])}" for i in active) + ".\n"
            f"3. In u (degree {dp}, knots {_knots(SURF_KNOTS_U)}): u = {fmt(u)} gives "
            + ", ".join(f"N_{i},1 = {_f(Nu[i])}" for i in active) + ".\n"
            f"4. S({fmt(u)}, {fmt(v)}) = {_f(_surface_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_SURFACE, generate=_surface_generate, answer=lambda p: _surface_answers(p)[0],
               slips=lambda p: _surface_answers(p)[1], statement=_surface_statement, steps=_surface_steps,
               same=within(1e-6), well_posed=_hand_exact(lambda p: _surface_answers(p)[0]))
def check_surface_point(answer, p) -> Result:
    """Check S(u, v) of the statement's degree (1, 2) surface (Goldman §27.8); recognises the knot vectors
    swapped between the directions and the v-curve of one row alone.

    >>> check_surface_point([1, 1.5, 2.5])
    Not yet: you used the u knots along j and the v knots along i; i goes with u (the first knot vector), j with v.
    """
    (u, v) = p["uv"]
    what = f"S({fmt(u)}, {fmt(v)})"
    got, err = _read_point(answer, what, 3)
    if err is not None:
        return err
    net = _surface_net(p["heights"])
    dp, dq = SURF_DEGREES
    expected = bspline.surface_de_boor(net, SURF_KNOTS_U, SURF_KNOTS_V, dp, dq, u, v)
    Nu, Nv = bspline.basis(SURF_KNOTS_U, dp, u), bspline.basis(SURF_KNOTS_V, dq, v)
    active = np.flatnonzero(Nu > 0)
    if _near(got, expected, 1e-6):
        a, b = Nu[active[0]], Nu[active[-1]]
        weigh = f"{_frac(a)} each" if a == b else f"{_frac(a)} and {_frac(b)}"
        return correct(f"{what} = {fmt(expected)}: rows {active[0]} and {active[-1]} weigh {weigh} in u, the "
                       f"Bernstein weights {', '.join(_frac(x) for x in Nv)} act in v.")
    swapped = np.einsum("j,i,ijd->d", Nu, Nv, net)
    if _near(got, swapped, 1e-6):
        return wrong("you used the u knots along j and the v knots along i; i goes with u (the first knot vector), "
                     "j with v.")
    rows = np.einsum("j,ijd->id", Nv, net)
    k = int(bspline.find_span(SURF_KNOTS_U, dp, u))
    for i in active:
        if _near(got, rows[i], 1e-6):
            return wrong(f"that is the v-curve of row {i} alone; u = {fmt(u)} lies in the span "
                         f"[{fmt(SURF_KNOTS_U[k])}, {fmt(SURF_KNOTS_U[k + 1])}) of the linear u direction, so two "
                         f"rows take part: combine their v-points with the weights N_i,1(u).")
    if _near(got[:2], expected[:2], 1e-6):
        return wrong(f"x and y are right, the height is {off_by(got[2], expected[2])}; run the v direction on the "
                     f"heights of each active row, then combine the rows in u.")
    return wrong(f"your point is {far_off(got, expected)} from {what}. Find u's span in the "
                 f"u knots and v's in the v knots; S = sum_i sum_j N_i,1(u) N_j,2(v) P_ij.")


# -- Exercise 6 -----------------------------------------------------------------------------------

_STORED_NURBS = {"ctrl": _tup(NURBS_CTRL), "weights": _tup(NURBS_WEIGHTS), "u": NURBS_U}


@memo
def _nurbs_answers(p):
    P, w, u = _arr(p["ctrl"]), _arr(p["weights"]), p["u"]
    N = bspline.basis(NURBS_KNOTS, 2, u)
    numerator = (w * N) @ P
    slips = {"polynomial": N @ P, "numerator only": numerator, "sum of the weights": numerator / w.sum(),
             "weights divided": bspline.nurbs_curve(P, 1 / w, NURBS_KNOTS, 2, u)}
    return bspline.nurbs_curve(P, w, NURBS_KNOTS, 2, u), slips


def _nurbs_generate(rng) -> dict:
    return {"ctrl": _tup(rng.integers(0, 7, size=(4, 2))), "weights": _tup(rng.integers(1, 5, size=4)),
            "u": float(rng.choice([0.5, 1.5]))}


def _nurbs_ok(p):
    if len(set(p["weights"])) < 3:
        return "fewer than three different weights"
    return None


def _nurbs_statement(p) -> str:
    return (f"The quadratic NURBS curve with control points {fmt_points(p['ctrl'])}, weights "
            f"{', '.join(fmt(w) for w in p['weights'])} and knots {_knots(NURBS_KNOTS)}: compute C({fmt(p['u'])}) "
            f"= sum w_k N_k,2(u) P_k / sum w_k N_k,2(u). Give [x, y] to 3 decimals (Goldman §27.9).")


def _nurbs_steps(p) -> str:
    P, w, u = _arr(p["ctrl"]), _arr(p["weights"]), p["u"]
    N = bspline.basis(NURBS_KNOTS, 2, u)
    return (f"1. The basis values at u = {fmt(u)}: N_k,2 = {_f(N)} (k = 0..3).\n"
            f"2. Weighted: w_k N_k,2 = {_f(w * N)}, their sum {_f((w * N).sum())}.\n"
            f"3. The numerator sum w_k N_k,2 P_k = {_f((w * N) @ P)}.\n"
            f"4. C({fmt(u)}) = numerator / sum = {_f(_nurbs_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_NURBS, generate=_nurbs_generate, answer=lambda p: _nurbs_answers(p)[0],
               slips=lambda p: _nurbs_answers(p)[1], statement=_nurbs_statement, steps=_nurbs_steps,
               same=within(1e-3), well_posed=_nurbs_ok)
def check_nurbs_point(answer, p) -> Result:
    """Check C(u) of the statement's rational quadratic (Goldman §27.9); recognises the polynomial
    B-spline, the numerator alone, the division by the sum of the weights, and the weights divided.

    >>> check_nurbs_point([3, 1.5])
    Not yet: that is the polynomial B-spline (every weight equal); multiply each N_k,2(u) by its weight w_k, and divide by the sum of the weighted basis values.
    """
    P, w, t, u = _arr(p["ctrl"]), _arr(p["weights"]), NURBS_KNOTS, p["u"]
    what = f"C({fmt(u)})"
    got, err = _read_point(answer, what, 2)
    if err is not None:
        return err
    expected = bspline.nurbs_curve(P, w, t, 2, u)
    if _near(got, expected, 1e-3):
        heavy = [k for k in range(len(w)) if w[k] > w.min()]
        return correct(f"{what} matches: the weights {' and '.join(fmt(w[k]) for k in heavy)} pull the point towards "
                       f"{' and '.join(f'P{k}' for k in heavy)} compared with the polynomial B-spline.")
    N = bspline.basis(t, 2, u)
    numerator = (w * N) @ P
    if _near(got, N @ P, 1e-3):
        return wrong("that is the polynomial B-spline (every weight equal); multiply each N_k,2(u) by its weight w_k, "
                     "and divide by the sum of the weighted basis values.")
    if _near(got, numerator, 1e-3):
        return wrong("you forgot to divide: sum w_k N_k P_k is the numerator only; divide by sum w_k N_k(u) (the "
                     "homogeneous coordinate), which is not constant when the weights differ.")
    if _near(got, numerator / w.sum(), 1e-3):
        return wrong("you divided by the sum of the weights; the denominator is sum w_k N_k,2(u), each weight "
                     "times its basis value at u.")
    if _near(got, bspline.nurbs_curve(P, 1 / w, t, 2, u), 1e-3):
        return wrong("you divided by the weights instead of multiplying: a larger weight pulls the curve towards "
                     "its control point, so w_k multiplies N_k,2(u).")
    active = [k for k in range(len(N)) if N[k] > 0]
    return wrong(f"your point is {far_off(got, expected)} from {what}. Compute "
                 f"{', '.join(f'N_{k},2' for k in active)} at u = {fmt(u)}, then C = sum w_k N_k P_k / sum w_k N_k.")


# -- Exercise 7 -----------------------------------------------------------------------------------

_STORED_PYRAMID = {"knots": _tup(PYRAMID_KNOTS), "degree": PYRAMID_DEGREE, "node": PYRAMID_NODE}


@memo
def _pyramid_answers(p):
    (r, i), deg, t = p["node"], p["degree"], _arr(p["knots"])
    info = bspline.global_pyramid_labels(t, deg)[r][i - r]
    slips = {"support of N_i,p": np.array([t[i], t[i + deg + 1]]), "one span": np.array([t[i], t[i + 1]])}
    for shift, name in ((-1, "one knot early"), (1, "one knot late")):
        j = i + shift
        if 0 <= j and j + deg + 1 - r < t.size:
            slips[name] = np.array([t[j], t[j + deg + 1 - r]])
    return np.array(info["interval"]), slips


def _pyramid_generate(rng) -> dict:
    deg = int(rng.integers(2, 4))
    inner = np.sort(rng.choice(np.arange(1, 8), size=int(rng.integers(3, 5)), replace=False)).astype(float)
    end = float(inner[-1] + rng.integers(1, 3))
    knots = (0.0,) * (deg + 1) + tuple(float(x) for x in inner) + (end,) * (deg + 1)
    n = len(knots) - deg - 2
    r = int(rng.integers(1, deg))
    return {"knots": knots, "degree": deg, "node": (r, int(rng.integers(r, n + 1)))}


def _pyramid_ok(p):
    (r, i), deg, t = p["node"], p["degree"], _arr(p["knots"])
    info = bspline.global_pyramid_labels(t, deg)[r][i - r]
    a, b = info["interval"]
    if not info["defined"] or not b > a:
        return "the node serves no span of the curve"
    return None


def _pyramid_statement(p) -> str:
    (r, i), deg = p["node"], p["degree"]
    return (f"In the global de Boor pyramid of a {_DEGREE_NAMES[deg]} B-spline (degree {deg}) on the knots "
            f"{_knots(p['knots'])}, take the node P_{i}^{r} (level {r}, "
            f"index {i}). On which interval [a, b] of u is this node a blossom value of the curve's "
            f"polynomial pieces (the union of the spans whose local pyramids use it)? Give [a, b] (Goldman §27.5).")


def _pyramid_steps(p) -> str:
    (r, i), deg, t = p["node"], p["degree"], _arr(p["knots"])
    info = bspline.global_pyramid_labels(t, deg)[r][i - r]
    label = ", ".join(["u"] * r + [fmt(x) for x in info["knots"]])
    spans = ", ".join(f"[{fmt(t[k])}, {fmt(t[k + 1])})" for k in info["spans"])
    return (f"1. The knots t_0, ..., t_{t.size - 1} = {', '.join(fmt(x) for x in t)}; p = {deg}.\n"
            f"2. Node i = {i} of level r = {r} keeps the knots t_(i+1), ..., t_(i+p-r) of its parents: its label is "
            f"({label}).\n"
            f"3. It is a blossom value of the piece on span k when those knots are among that span's, "
            f"i <= k <= i + p - r: the spans {spans}.\n"
            f"4. Their union is [t_i, t_(i+p+1-r)] = [{fmt(info['interval'][0])}, {fmt(info['interval'][1])}].")


@DECK.exercise(stored=_STORED_PYRAMID, generate=_pyramid_generate, answer=lambda p: _pyramid_answers(p)[0],
               slips=lambda p: _pyramid_answers(p)[1], statement=_pyramid_statement, steps=_pyramid_steps,
               same=within(1e-9), well_posed=_pyramid_ok)
def check_pyramid_node_interval(answer, p) -> Result:
    """Check the locality interval ``[t_i, t_(i+p+1-r)]`` of the statement's node (Goldman §27.5).

    answer: [a, b].  Recognises the support of the basis function N_i,p (the level ignored), the one
    span [t_i, t_(i+1)] (the node is shared by several spans), and a knot index shifted by one.
    """
    (r, i), deg, t = p["node"], p["degree"], _arr(p["knots"])
    got, err = read_points(answer, "your interval", ask="the interval as [a, b]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"the interval should be two numbers [a, b]; yours has shape {got.shape}.")
    info = bspline.global_pyramid_labels(t, deg)[r][i - r]
    expected = np.array(info["interval"])
    if _near(got, expected, 1e-9):
        label = ", ".join(["u"] * r + [fmt(x) for x in info["knots"]])
        pieces = " and ".join(f"[{fmt(t[k])}, {fmt(t[k + 1])})" for k in info["spans"])
        return correct(f"the node P_{i}^{r} is labelled ({label}) and is a blossom value of the pieces on {pieces}: "
                       f"u in [{fmt(expected[0])}, {fmt(expected[1])}].")
    if _near(got, [t[i], t[i + deg + 1]], 1e-9):
        return wrong(f"that is the support of the basis function N_{i},{deg}, the reach of a control point at level "
                     f"0; a node of level {r} has its parents' common knots, one fewer per level, so it reaches fewer "
                     f"spans.")
    if _near(got, [t[i], t[i + 1]], 1e-9):
        return wrong("that is a single knot span; a node below the apex is shared by the local pyramids of several "
                     "neighbouring spans: count the knots in its label.")
    for shift, way in ((-1, "one knot too early"), (1, "one knot too late")):
        j = i + shift
        if 0 <= j and j + deg + 1 - r < t.size and _near(got, [t[j], t[j + deg + 1 - r]], 1e-9):
            return wrong(f"your interval has the right length in knots but starts at the wrong knot ({way}): node i "
                         f"of level r combines with the weight (u - t_i) / (t_(i+p+1-r) - t_i), so its interval "
                         f"starts at t_i.")
    return wrong("your interval is not one the node's label gives; the node's label is (u^r, t_(i+1), ..., t_(i+p-r)) "
                 "and it serves the spans k with i <= k <= i+p-r.")


#: Deal another instance of an exercise (``deal("check_nurbs_point")``, or with ``seed=``; 0 is
#: the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


#: Wrong answers of the kinds each checker recognises (tests/exercises/test_solutions.py feeds them in).
SLIPS = {
    "check_local_de_boor": [[4.0, 3.75], [3.0, 5.0], [5.0, 4.0], [4.0, 4.0], [5.0, 10.0], [0.0, 0.0]],
    "check_basis_values": [[0.0625, 0.375, 0.5625], [0.375, 7 / 12, 1 / 24], [0.1, 0.5, 0.3], [0.05, 0.575, 0.375]],
    "check_continuity_orders": [[1, 2, 3, 4], [2, 1, 0, -1], [3, 3, 3, 3], [3, 2, 0, 0]],
    "check_spline_control_points": [[0.0, 0.75, 0.5, -1.0], [0.0, 1.0, 1.0, -3.0], [0.0, 1.0, 2.0, -1.0]],
    "check_surface_point": [[1.0, 1.5, 2.5], [1.0, 1.0, 3.0], [2.0, 1.0, 2.5], [1.5, 1.0, 3.0]],
    "check_nurbs_point": [[3.0, 1.5], [5.125, 1.75], [5.125 / 7, 0.25], [2.9459, 1.7838], [3.0, 1.0]],
    "check_pyramid_node_interval": [[1.0, 5.0], [1.0, 2.0], [0.0, 2.0], [2.0, 5.0], [0.0, 1.0]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

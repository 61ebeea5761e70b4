"""Exercise checkers for chapter 28, knot insertion (Goldman §28.3-28.4), and the checker of its
programming project (Boehm's knot insertion).

Every numeric exercise deals new numbers (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
instance 0 is the module constants below (the stored notebook), ``deal("check_...")`` or
``deal_button("check_...")`` deals another, each checker checks the current instance,
``PROBLEMS`` states it and ``steps("check_...")`` shows its worked steps, computed by the library.
The "show that" exercises (in :mod:`goldman_lib.exercises.proofs`) and the programming project
do not deal.  ``SLIPS`` holds the wrong answers of the kinds each checker recognises, for the
stored instances.  The data differ from the chapter's worked examples (its cubic with knots 1/4,
1/2, 3/4, the square, the quadratic with the knot 0.4).  The crossing-count drill of variation
diminishing lives in chapter 25.

>>> print(PROBLEMS["check_convergence_levels"])  # doctest: +ELLIPSIS
After some levels of subdivision ... (Goldman §28.4.3).
"""

from __future__ import annotations

import numpy as np

from goldman_lib import knot_insertion as ki
from goldman_lib.exercises import guard_checkers
from goldman_lib.exercises import (Result, check_points, correct, fmt, fmt_points, read_number,
                                   read_points, wrong)
from goldman_lib.exercises.deal import Deck, memo, plain as _tup, within
from goldman_lib.exercises.projects import Case, check_project, compare_points

__all__ = ["PROBLEMS", "SLIPS", "QUAD_CTRL", "QUAD_KNOTS", "QUAD_DEGREE", "BOEHM_U", "OSLO_NEW_KNOTS",
           "CHAIKIN_CTRL", "SCHAEFER_CTRL", "SCHAEFER_KNOTS", "CONV_DISTANCE", "CONV_TOL",
           "DECK", "deal", "steps", "current", "deal_button",
           "check_boehm_insert", "check_oslo", "check_bezier_pieces", "check_chaikin", "check_schaefer",
           "check_convergence_levels", "boehm_project_cases", "check_boehm_project"]

#: Exercises 1-3: the quadratic B-spline with knots 0, 0, 0, 1, 2, 2, 2 (two polynomial pieces).
QUAD_CTRL = np.array([[0.0, 0.0], [2.0, 4.0], [4.0, 4.0], [6.0, 0.0]])
QUAD_KNOTS = np.array([0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])
QUAD_DEGREE = 2
#: Exercise 1: the knot inserted once by Boehm's algorithm.
BOEHM_U = 0.5
#: Exercise 2: the refined knot vector of the Oslo algorithm (0.5 and 1.5 inserted at once).
OSLO_NEW_KNOTS = np.array([0.0, 0.0, 0.0, 0.5, 1.0, 1.5, 2.0, 2.0, 2.0])
#: Exercise 4: the open polygon refined by one level of Lane-Riesenfeld of degree 2 (Chaikin).
CHAIKIN_CTRL = np.array([[0.0, 0.0], [2.0, 6.0], [10.0, 6.0], [10.0, 0.0]])
#: Exercise 5: a quadratic on non-uniform knots (intervals 1 and 2), one level of Schaefer's algorithm.
SCHAEFER_CTRL = np.array([[0.0, 0.0], [3.0, 6.0], [9.0, 6.0], [12.0, 0.0]])
SCHAEFER_KNOTS = np.array([0.0, 0.0, 0.0, 1.0, 3.0, 3.0, 3.0])
#: Exercise 6: the polygon-to-curve distance now, and the tolerance to reach.
CONV_DISTANCE, CONV_TOL = 0.5, 0.001

DECK = Deck("ch28")

_WORDS = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six", 7: "seven", 8: "eight", 9: "nine",
          10: "ten", 11: "eleven", 12: "twelve"}


def _knots(t) -> str:
    return ", ".join(fmt(x) for x in np.asarray(t))


def _arr(v):
    return np.asarray(v, dtype=float)


def _f(x) -> str:
    """Points of the worked steps, rounded to 6 digits (no floating-point noise)."""
    x = np.round(np.asarray(x, dtype=float), 6) + 0.0
    return fmt_points(x, 6) if x.ndim > 1 else fmt(x, 6)


def _near(a, b, tol: float = 1e-6) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= tol))


def _same_points(a, b) -> bool:
    """The checkers' tolerance, 1e-6 per coordinate; arrays of other shapes are different answers."""
    return _near(a, b)


def _terminating(x, places: int = 4) -> bool:
    """Whether every entry of x is a decimal of at most ``places`` places (a learner can type it
    exactly: the checkers' tolerance 1e-6 does not forgive a rounded third)."""
    scaled = np.asarray(x, dtype=float) * 10 ** places
    return bool(np.all(np.abs(scaled - np.round(scaled)) < 1e-6))


_NOT_EXACT = "the answer is not a short decimal (a hand answer would be rounded)"


def _quad_generate(rng) -> tuple:
    """Four whole control points and clamped knots 0, 0, 0, a, c, c, c (a, c - a in 1..2)."""
    a = float(rng.integers(1, 3))
    c = a + float(rng.integers(1, 3))
    return _tup(rng.integers(0, 9, size=(4, 2))), (0.0, 0.0, 0.0, a, c, c, c)


def _half_in(rng, lo, hi) -> float:
    """A multiple of 1/2 strictly between lo and hi."""
    return lo + float(rng.integers(1, int(2 * (hi - lo)))) / 2


def _same_curve(p, stored) -> str:
    return "the same quadratic B-spline" if p == stored else "the quadratic B-spline"


# -- Boehm's algorithm and its usual slips (the exercise and the project's tests use them) ----------

def _boehm_variant(ctrl, knots, degree, u, *, shift: int = 0, alpha_knot: int = 0, swap: bool = False):
    """Boehm's insertion of one knot as a learner might write it, right by default (Goldman §28.3.1).

    ``shift`` moves the affected index range ``k-p+1 .. k`` by that many places (an off-by-one),
    ``alpha_knot`` reads the right-hand knot of ``a_i`` as ``t_(i+p+alpha_knot)`` (``alpha_knot=1``:
    the wrong knot ``t_(i+p+1)``), ``swap`` swaps ``a_i`` and ``1 - a_i``.  The checkers use the
    variants to recognise slips; the library's :func:`goldman_lib.knot_insertion.boehm_insert` is
    the reference.

    >>> _boehm_variant([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5).tolist()
    [[0.0, 0.0], [0.5, 1.0], [1.5, 1.0], [2.0, 0.0]]
    """
    P = np.asarray(ctrl, dtype=float)
    t = np.asarray(knots, dtype=float)
    p = int(degree)
    n = len(P) - 1
    k = int(np.searchsorted(t, u, side="right")) - 1
    k = min(max(k, p), n) + shift
    Q = np.empty((n + 2, P.shape[1]))
    lo = max(k - p + 1, 1)
    hi = min(k, n)
    Q[:lo] = P[:lo]
    Q[hi + 1:] = P[hi:]
    with np.errstate(divide="ignore", invalid="ignore"):
        for i in range(lo, hi + 1):
            right = t[min(i + p + alpha_knot, len(t) - 1)]
            a = (u - t[i]) / (right - t[i]) if right != t[i] else 0.0
            if swap:
                a = 1 - a
            Q[i] = (1 - a) * P[i - 1] + a * P[i]
    return Q


def _span(t, p, n, u) -> int:
    return min(max(int(np.searchsorted(t, u, side="right")) - 1, p), n)


def _one_ratio(P, t, p, u):
    """Every affected leg cut at the span's own ratio (u - t_k)/(t_(k+1) - t_k) (a slip)."""
    k = _span(t, p, len(P) - 1, u)
    s = (u - t[k]) / (t[k + 1] - t[k])
    Q = np.vstack([P[:1], P])
    for i in range(k - p + 1, k + 1):
        Q[i] = (1 - s) * P[i - 1] + s * P[i]
    Q[k + 1:] = P[k:]
    Q[:k - p + 1] = P[:k - p + 1]
    return Q


_STORED_BOEHM = {"ctrl": _tup(QUAD_CTRL), "knots": _tup(QUAD_KNOTS), "u": BOEHM_U}


@memo
def _boehm_answers(p):
    P, t, u = _arr(p["ctrl"]), _arr(p["knots"]), p["u"]
    d = QUAD_DEGREE
    slips = {"the old polygon": P, "weights swapped": _boehm_variant(P, t, d, u, swap=True),
             "wrong knot in a_i": _boehm_variant(P, t, d, u, alpha_knot=1),
             "wrong points replaced": _boehm_variant(P, t, d, u, shift=1), "one ratio": _one_ratio(P, t, d, u)}
    return ki.boehm_insert(P, t, d, u)[0], slips


def _boehm_generate(rng) -> dict:
    ctrl, t = _quad_generate(rng)
    u = _half_in(rng, 0, t[-1])
    return {"ctrl": ctrl, "knots": t, "u": u}


def _boehm_ok(p):
    if p["u"] in p["knots"]:
        return "u is already a knot"
    return None if _terminating(_boehm_answers(p)[0]) else _NOT_EXACT


def _boehm_statement(p) -> str:
    return (f"The quadratic B-spline with control points {fmt_points(p['ctrl'])} and knots {_knots(p['knots'])}: "
            f"insert the knot u = {fmt(p['u'])} once by Boehm's algorithm and give the five new control points "
            f"(Goldman §28.3.1).")


def _boehm_steps(p) -> str:
    P, t, u, d = _arr(p["ctrl"]), _arr(p["knots"]), p["u"], QUAD_DEGREE
    k = _span(t, d, len(P) - 1, u)
    new, knots = ki.boehm_insert(P, t, d, u)
    rows = "; ".join(f"a_{i} = ({fmt(u)} - t_{i})/(t_{i + d} - t_{i}) = ({fmt(u)} - {fmt(t[i])})/({fmt(t[i + d])} - "
                     f"{fmt(t[i])}) = {_f((u - t[i]) / (t[i + d] - t[i]))}, Q_{i} = {_f(new[i])}"
                     for i in range(k - d + 1, k + 1))
    return (f"1. The span: t_{k} = {fmt(t[k])} <= {fmt(u)} < t_{k + 1} = {fmt(t[k + 1])}, so k = {k}; P_0..P_{k - d} "
            f"and P_{k}..P_{len(P) - 1} are kept (the latter shifted one place).\n"
            f"2. Q_i = (1 - a_i) P_(i-1) + a_i P_i for {k - d + 1} <= i <= {k}: {rows}.\n"
            f"3. The new control points {_f(new)} over the knots {_knots(knots)}.")


@DECK.exercise(stored=_STORED_BOEHM, generate=_boehm_generate, answer=lambda p: _boehm_answers(p)[0],
               slips=lambda p: _boehm_answers(p)[1], statement=_boehm_statement, steps=_boehm_steps,
               same=_same_points, well_posed=_boehm_ok)
def check_boehm_insert(answer, p) -> Result:
    """Check the five control points after inserting the statement's knot into the quadratic (Goldman
    §28.3.1); recognises the old polygon, the weights swapped, the wrong knot in a_i, the wrong points
    replaced and one ratio for every leg.

    >>> check_boehm_insert([[0, 0], [1, 2], [3.5, 4], [4, 4], [6, 0]])
    Not yet: the weights are swapped: Q_i = (1 - a_i) P_(i-1) + a_i P_i, so a_i, which grows with u, goes with P_i.
    """
    what = "the new control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P, t, d, u = _arr(p["ctrl"]), _arr(p["knots"]), QUAD_DEGREE, p["u"]
    expected, _ = ki.boehm_insert(P, t, d, u)
    k = _span(t, d, len(P) - 1, u)
    if _near(got, P):
        return wrong("that is the old polygon: inserting a knot adds one control point and replaces p - 1 old "
                     "points by p new ones on the legs (here one by two).")
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points (one more than the {len(P)} old ones); "
                     f"yours has shape {got.shape}.")
    if _near(got, expected):
        before = " and ".join(f"P{i}" for i in range(k - d + 1))
        after = " and ".join(f"P{i}" for i in range(k, len(P)))
        return correct(f"{what} match: {before} kept, two new points on the legs P{k - 2}P{k - 1} and "
                       f"P{k - 1}P{k}, {after} kept (shifted one place).")
    if _near(got, _boehm_variant(P, t, d, u, swap=True)):
        return wrong("the weights are swapped: Q_i = (1 - a_i) P_(i-1) + a_i P_i, so a_i, which grows with u, "
                     "goes with P_i.")
    if _near(got, _boehm_variant(P, t, d, u, alpha_knot=1)):
        return wrong("a_i divides by the wrong knot interval: a_i = (u - t_i)/(t_(i+p) - t_i), the interval of "
                     "p knots that the label of P_i spans, not t_(i+p+1) - t_i.")
    if _near(got, _boehm_variant(P, t, d, u, shift=1)):
        return wrong(f"you replaced the wrong points: with t_k <= u < t_(k+1) the new points are Q_(k-p+1)..Q_k, "
                     f"and the span k here has t_k <= {fmt(u)} < t_(k+1).")
    if _near(got, _one_ratio(P, t, d, u)):
        return wrong("you cut every leg at the same ratio (u - t_k)/(t_(k+1) - t_k); in Boehm's algorithm each new "
                     "point has its own a_i = (u - t_i)/(t_(i+p) - t_i).")
    i0 = k - d + 1
    return check_points(got, expected, what=what,
                        hint=f"u = {fmt(u)} lies in [t_{k}, t_{k + 1}) = [{fmt(t[k])}, {fmt(t[k + 1])}); "
                             f"a_{i0} = ({fmt(u)} - t_{i0})/(t_{i0 + d} - t_{i0}), "
                             f"a_{i0 + 1} = ({fmt(u)} - t_{i0 + 1})/(t_{i0 + 1 + d} - t_{i0 + 1})")


# -- Oslo -------------------------------------------------------------------------------------------

_STORED_OSLO = {"ctrl": _tup(QUAD_CTRL), "knots": _tup(QUAD_KNOTS), "new": (0.5, 1.5)}


def _refined(p) -> np.ndarray:
    return np.sort(np.concatenate([_arr(p["knots"]), _arr(p["new"])]))


@memo
def _oslo_answers(p):
    P, t = _arr(p["ctrl"]), _arr(p["knots"])
    slips = {f"{fmt(u)} alone": ki.boehm_insert(P, t, QUAD_DEGREE, u)[0] for u in p["new"]}
    slips["midpoints"] = np.vstack([P[:1], (P[:-1] + P[1:]) / 2, P[-1:]])
    return ki.oslo(P, t, QUAD_DEGREE, _refined(p)), slips


def _oslo_generate(rng) -> dict:
    """New control points and two new knots, one in each span, on the stored knots (the notebook's
    hint names their labels b(0, 0), b(0, 1), b(1, 2), b(2, 2))."""
    ctrl, _ = _quad_generate(rng)
    return {"ctrl": ctrl, "knots": _tup(QUAD_KNOTS),
            "new": (float(rng.integers(1, 4)) / 4, 1 + float(rng.integers(1, 4)) / 4)}


def _oslo_ok(p):
    return None if _terminating(_oslo_answers(p)[0]) else _NOT_EXACT


def _oslo_statement(p) -> str:
    u1, u2 = p["new"]
    return (f"For {_same_curve(p, _STORED_OSLO)} ({fmt_points(p['ctrl'])}; knots {_knots(p['knots'])}), give the "
            f"control points over the refined knot vector "
            f"{_knots(_refined(p))} (the knots {fmt(u1)} and {fmt(u2)} inserted at once): each new control point is "
            f"the blossom at two consecutive new knots (Goldman §28.3.2).")


def _oslo_steps(p) -> str:
    P, t = _arr(p["ctrl"]), _arr(p["knots"])
    rows = "\n".join(f"   Q_{j} = b({', '.join(fmt(x) for x in s['label'])}) = {_f(s['point'])} "
                     f"(from P_{s['span'] - QUAD_DEGREE}..P_{s['span']}, the span {s['span']})"
                     for j, s in enumerate(ki.oslo_steps(P, t, QUAD_DEGREE, _refined(p))))
    return (f"1. The refined knots {_knots(_refined(p))}: the labels of the new control points are consecutive "
            f"pairs of the inner knots.\n"
            f"2. Each is a blossom value, computed by de Boor's pyramid with the label as arguments:\n{rows}")


@DECK.exercise(stored=_STORED_OSLO, generate=_oslo_generate, answer=lambda p: _oslo_answers(p)[0],
               slips=lambda p: _oslo_answers(p)[1], statement=_oslo_statement, steps=_oslo_steps,
               same=_same_points, well_posed=_oslo_ok)
def check_oslo(answer, p) -> Result:
    """Check the six control points over the statement's refined knot vector (Goldman §28.3.2);
    recognises one knot inserted alone and the midpoints of the old legs.
    """
    what = "the refined control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P, t = _arr(p["ctrl"]), _arr(p["knots"])
    expected = ki.oslo(P, t, QUAD_DEGREE, _refined(p))
    u1, u2 = p["new"]
    for u in (u1, u2):
        one, _ = ki.boehm_insert(P, t, QUAD_DEGREE, u)
        if _near(got, one):
            return wrong(f"these are the points after inserting {fmt(u)} alone; the Oslo algorithm inserts "
                         f"{fmt(u1)} and {fmt(u2)} together, giving {len(expected)} points.")
    mids = np.vstack([P[:1], (P[:-1] + P[1:]) / 2, P[-1:]])
    if _near(got, mids):
        return wrong("those are the old end points and the midpoints of the old legs (uniform subdivision of degree "
                     "one); the new points are blossom values at two consecutive new knots, one new point per "
                     "inserted knot.")
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points (two knots inserted into {len(P)} points); "
                     f"yours has shape {got.shape}.")
    return check_points(got, expected, what=what,
                        hint="each new point is the blossom at two consecutive new knots; the blossom is symmetric "
                             "and affine in each argument, so b(x, 1) moves along the leg P_1 P_2 in proportion to x"
                        if p == _STORED_OSLO else
                        "each new point is the blossom at two consecutive new knots; the blossom is symmetric "
                        "and affine in each argument, so b(x, y) moves along a leg in proportion to x")


# -- piecewise Bezier -------------------------------------------------------------------------------

_STORED_BEZIER = {"ctrl": _tup(QUAD_CTRL), "knots": _tup(QUAD_KNOTS)}


@memo
def _bezier_answers(p):
    P, t = _arr(p["ctrl"]), _arr(p["knots"])
    slips = {"knot not inserted": np.array([P[:3], P[1:]]), "junction at an old point": np.array(
        [[P[0], P[1], P[2]], [P[2], P[2], P[3]]])}
    return ki.to_piecewise_bezier(P, t, QUAD_DEGREE)[0], slips


def _bezier_generate(rng) -> dict:
    ctrl, t = _quad_generate(rng)
    return {"ctrl": ctrl, "knots": t}


def _bezier_statement(p) -> str:
    return (f"Convert {_same_curve(p, _STORED_BEZIER)} ({fmt_points(p['ctrl'])}; knots {_knots(p['knots'])}) to "
            f"piecewise Bezier form: give the two Bezier control polygons, [[piece 1: 3 points], [piece 2: 3 points]] "
            f"(Goldman §28.3.3).")


def _bezier_steps(p) -> str:
    P, t = _arr(p["ctrl"]), _arr(p["knots"])
    a, c = t[3], t[-1]
    pieces, _ = ki.to_piecewise_bezier(P, t, QUAD_DEGREE)
    return (f"1. The control points are the blossoms b(0, 0), b(0, {fmt(a)}), b({fmt(a)}, {fmt(c)}), "
            f"b({fmt(c)}, {fmt(c)}).\n"
            f"2. Insert the knot {fmt(a)} once more (multiplicity p = 2): the new point "
            f"b({fmt(a)}, {fmt(a)}) = C({fmt(a)}) "
            f"lies on the leg P_1 P_2, {fmt(a)}/{fmt(c)} of the way along: {_f(pieces[0][-1])}.\n"
            f"3. The pieces: over [0, {fmt(a)}] b(0, 0), b(0, {fmt(a)}), b({fmt(a)}, {fmt(a)}) = {_f(pieces[0])}; over "
            f"[{fmt(a)}, {fmt(c)}] b({fmt(a)}, {fmt(a)}), b({fmt(a)}, {fmt(c)}), b({fmt(c)}, {fmt(c)}) = "
            f"{_f(pieces[1])}.")


@DECK.exercise(stored=_STORED_BEZIER, generate=_bezier_generate, answer=lambda p: _bezier_answers(p)[0],
               slips=lambda p: _bezier_answers(p)[1], statement=_bezier_statement, steps=_bezier_steps,
               same=_same_points, well_posed=lambda p: None if _terminating(_bezier_answers(p)[0]) else _NOT_EXACT)
def check_bezier_pieces(answer, p) -> Result:
    """Check the two Bezier polygons of the statement's quadratic (Goldman §28.3.3); recognises the knot
    not inserted (the pieces do not meet) and a junction that is not the curve point.

    >>> check_bezier_pieces([[[0, 0], [2, 4], [4, 4]], [[2, 4], [4, 4], [6, 0]]])
    Not yet: the pieces must meet at one point, the curve point C(1) = b(1, 1): insert the knot 1 once more, so that it has multiplicity p = 2, and both pieces share that new control point.
    """
    what = "the Bezier pieces"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P, t = _arr(p["ctrl"]), _arr(p["knots"])
    a, c = fmt(t[3]), fmt(t[-1])
    expected, _ = ki.to_piecewise_bezier(P, t, QUAD_DEGREE)
    if got.shape != expected.shape:
        return wrong(f"{what} should be 2 quadratic Bezier polygons of 3 points each, shape (2, 3, 2); yours has "
                     f"shape {got.shape}.")
    junction = expected[0, -1]
    if not (_near(got[0, -1], junction) and _near(got[1, 0], junction)):
        if _near(got[0, -1], got[1, 0]):
            return wrong(f"the two pieces share an end point, but it is not the curve point C({a}) = b({a}, {a}); "
                         f"b(x, {a}) runs from P_1 = b(0, {a}) to P_2 = b({c}, {a}) as x goes from 0 to {c}.")
        return wrong(f"the pieces must meet at one point, the curve point C({a}) = b({a}, {a}): insert the knot {a} "
                     f"once more, so that it has multiplicity p = 2, and both pieces share that new control point.")
    return check_points(got.reshape(-1, 2), expected.reshape(-1, 2), what=what,
                        hint="the Bezier points of the piece over [a, b] are b(a, a), b(a, b), b(b, b)")


# -- Chaikin ----------------------------------------------------------------------------------------

_STORED_CHAIKIN = {"ctrl": _tup(CHAIKIN_CTRL)}


def _thirds(P):
    return np.array([w * a + (1 - w) * b for a, b in zip(P[:-1], P[1:]) for w in (2 / 3, 1 / 3)])


@memo
def _chaikin_answers(p):
    P = _arr(p["ctrl"])
    slips = {"degree 1": ki.lane_riesenfeld(P, 1, 1), "closed": ki.lane_riesenfeld(P, 2, 1, closed=True),
             "doubled only": np.repeat(P, 2, axis=0), "thirds": _thirds(P)}
    return ki.lane_riesenfeld(P, 2, 1), slips


def _chaikin_generate(rng) -> dict:
    return {"ctrl": _tup(4 * rng.integers(0, 4, size=(4, 2)) + 2 * rng.integers(0, 2, size=(4, 2)))}


def _chaikin_ok(p):
    P = _arr(p["ctrl"])
    if np.any(np.all(P[1:] == P[:-1], axis=1)):
        return "two consecutive points coincide"
    closed = ki.lane_riesenfeld(P, 2, 1, closed=True)
    if all(np.any(np.linalg.norm(closed - g, axis=1) < 1e-6) for g in np.repeat(P, 2, axis=0)):
        return "the doubled polygon's points are the closed polygon's"
    return None if _terminating(_chaikin_answers(p)[0]) else _NOT_EXACT


def _chaikin_statement(p) -> str:
    return (f"Apply one level of the Lane-Riesenfeld algorithm of degree 2 (Chaikin's corner cutting: double every "
            f"point, then average neighbours twice) to the open polygon {fmt_points(p['ctrl'])}: give the refined "
            f"polygon (Goldman §28.4.1).")


def _chaikin_steps(p) -> str:
    P = _arr(p["ctrl"])
    (rounds,) = ki.lane_riesenfeld_steps(P, 2, 1)[:1]
    return (f"1. Double every point: {_f(rounds[0])}.\n"
            f"2. Average neighbours (round 1): {_f(rounds[1])}.\n"
            f"3. Average again (round 2): {_f(rounds[2])}; each leg P_i P_(i+1) gives its points 1/4 and 3/4 "
            f"of the way along.")


@DECK.exercise(stored=_STORED_CHAIKIN, generate=_chaikin_generate, answer=lambda p: _chaikin_answers(p)[0],
               slips=lambda p: _chaikin_answers(p)[1], statement=_chaikin_statement, steps=_chaikin_steps,
               same=_same_points, well_posed=_chaikin_ok)
def check_chaikin(answer, p) -> Result:
    """Check one Lane-Riesenfeld level of degree 2 on the statement's polygon (Goldman §28.4.1);
    recognises degree 1, the polygon taken as closed, the doubled polygon and legs cut in thirds.

    >>> check_chaikin([[0, 0], [1, 3], [2, 6], [6, 6], [10, 6], [10, 3], [10, 0]])
    Not yet: that is one averaging round (degree 1: the midpoints inserted); degree 2 averages twice.
    """
    what = "the points of the refined polygon"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P = _arr(p["ctrl"])
    expected = ki.lane_riesenfeld(P, 2, 1)
    if _near(got, expected):
        return correct(f"{what} match: 1/4 and 3/4 along each leg.")
    if _near(got, ki.lane_riesenfeld(P, 1, 1)):
        return wrong("that is one averaging round (degree 1: the midpoints inserted); degree 2 averages twice.")
    closed = ki.lane_riesenfeld(P, 2, 1, closed=True)
    if got.shape == closed.shape and all(np.any(np.linalg.norm(closed - g, axis=1) < 1e-6) for g in got):
        return wrong("that treats the polygon as closed (the leg from the last point back to the first is cut too); "
                     "the polygon is open, so the refined one has two points per leg of the old polygon.")
    if _near(got, np.repeat(P, 2, axis=0)):
        return wrong("that is the doubled polygon only; now average neighbours twice.")
    if _near(got, _thirds(P)):
        return wrong("you cut the legs in thirds; two rounds of averaging after doubling cut each leg a quarter "
                     "and three quarters of the way along.")
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points: doubling gives {2 * len(P)}, and each of the 2 "
                     f"averaging rounds drops one; yours has shape {got.shape}.")
    return check_points(got, expected, what=what, hint="each leg P_i P_(i+1) gives the points a quarter and "
                                                        "three quarters of the way along it")


# -- Schaefer ---------------------------------------------------------------------------------------

_STORED_SCHAEFER = {"ctrl": _tup(SCHAEFER_CTRL), "knots": _tup(SCHAEFER_KNOTS)}


@memo
def _schaefer_answers(p):
    P, t = _arr(p["ctrl"]), _arr(p["knots"])
    steps = ki.schaefer_steps(P, t, 2)
    slips = {"Lane-Riesenfeld": ki.lane_riesenfeld(P, 2, 1), "round 1": steps["rounds"][1],
             "plain averages, one round": ki.lane_riesenfeld_steps(P, 2, 1)[0][1]}
    return steps["rounds"][-1], slips


def _schaefer_generate(rng) -> dict:
    a = float(rng.integers(1, 4))
    c = a + float(rng.integers(1, 4))
    return {"ctrl": _tup(rng.integers(0, 13, size=(4, 2))), "knots": (0.0, 0.0, 0.0, a, c, c, c)}


def _schaefer_ok(p):
    t = p["knots"]
    if t[3] == t[-1] - t[3]:
        return "uniform knots: Schaefer's weights are Lane-Riesenfeld's"
    return None if _terminating(_schaefer_answers(p)[0]) else _NOT_EXACT


def _schaefer_statement(p) -> str:
    t = p["knots"]
    return (f"The quadratic B-spline with control points {fmt_points(p['ctrl'])} has the non-uniform knots "
            f"{_knots(t)}. Run one level of Schaefer's algorithm (double every point, then two rounds of "
            f"averaging neighbours with the weights that blossoming gives), which inserts the midpoints "
            f"{fmt(t[3] / 2)} and {fmt((t[3] + t[-1]) / 2)} of "
            f"the knot intervals: give the six new control points (Goldman §28.4.2).")


def _schaefer_steps(p) -> str:
    P, t = _arr(p["ctrl"]), _arr(p["knots"])
    s = ki.schaefer_steps(P, t, 2)
    lines = [f"1. The refined knots {_knots(s['knots'])}; double every point: {_f(s['rounds'][0])}."]
    for r in (1, 2):
        labels = ", ".join("(" + ", ".join(fmt(x) for x in lab) + ")" for lab in s["labels"][r])
        lines.append(f"{r + 1}. Round {r}: the labels {labels}; each point is the affine combination of its two "
                     f"neighbours that blossoming gives: {_f(s['rounds'][r])}.")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_SCHAEFER, generate=_schaefer_generate, answer=lambda p: _schaefer_answers(p)[0],
               slips=lambda p: _schaefer_answers(p)[1], statement=_schaefer_statement, steps=_schaefer_steps,
               same=_same_points, well_posed=_schaefer_ok)
def check_schaefer(answer, p) -> Result:
    """Check one level of Schaefer's algorithm on the statement's non-uniform quadratic (Goldman §28.4.2);
    recognises Lane-Riesenfeld's uniform answer, the polygon after round 1, and one round of plain averages.
    """
    what = "the new control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P, t = _arr(p["ctrl"]), _arr(p["knots"])
    steps = ki.schaefer_steps(P, t, 2)
    expected = steps["rounds"][-1]
    if _near(got, expected):
        return correct(f"the six new control points match: they are the blossoms at consecutive knots of "
                       f"{_knots(steps['knots'])}.")
    if _near(got, ki.lane_riesenfeld(P, 2, 1)):
        return wrong("that is Lane-Riesenfeld's answer (plain averages, Chaikin's quarter and three-quarter points): right for uniform "
                     "knots only. With knot intervals of different lengths the weights come from the blossom labels, and "
                     "the clamped ends keep P0 and P3.")
    if _near(got, steps["rounds"][1]):
        return wrong("that is the polygon after round 1; a quadratic needs two rounds of averaging after the "
                     "doubling.")
    lr_rounds = ki.lane_riesenfeld_steps(P, 2, 1)[0]
    if _near(got, lr_rounds[1]):
        return wrong("that is one round of plain averages (the midpoints of the legs); Schaefer's rounds use "
                     "blossom weights, and a quadratic needs two rounds.")
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points: doubling gives {2 * len(P)}, and each of the "
                     f"two rounds drops one; yours has shape {got.shape}.")
    return check_points(got, expected, what=what,
                        hint="after the last round, new point j is the blossom at two consecutive knots of the refined "
                             "knot vector (the old knots with the midpoints inserted); each round trades one old knot "
                             "of every label for a midpoint")


# -- convergence ------------------------------------------------------------------------------------

_STORED_CONV = {"distance": CONV_DISTANCE, "tol": CONV_TOL}


def _levels(p, factor) -> int:
    n, d = 0, p["distance"]
    while d >= p["tol"]:
        d, n = d / factor, n + 1
    return n


@memo
def _conv_answers(p):
    expected = _levels(p, 4)
    return expected, {"halving": _levels(p, 2), "h^3": _levels(p, 8), "one short": expected - 1}


def _conv_generate(rng) -> dict:
    return {"distance": float(rng.choice([0.2, 0.3, 0.5, 0.8, 1.0, 2.0, 3.0, 5.0])),
            "tol": float(rng.choice([0.01, 0.005, 0.002, 0.001, 0.0005, 0.0001]))}


def _conv_ok(p):
    for factor in (2, 4, 8):
        ratios = [p["distance"] / factor ** L / p["tol"] for L in range(40)]
        if any(abs(r - 1) < 0.01 for r in ratios):
            return "the distance lands within 1% of the tolerance after a whole number of levels"
    if _levels(p, 4) < 2:
        return "fewer than two levels"
    return None


def _conv_statement(p) -> str:
    return (f"After some levels of subdivision the control polygon of a smooth cubic B-spline is "
            f"{fmt(p['distance'])} from the curve (max |Q_i - C(xi_i)|). How many more levels of subdivision make "
            f"this distance smaller than {fmt(p['tol'])}, if each level shrinks it as the rate of convergence "
            f"predicts? (Goldman §28.4.3).")


def _conv_steps(p) -> str:
    d, tol, L = p["distance"], p["tol"], _levels(p, 4)
    return (f"1. A control point is O(h^2) from the curve, and each level halves h: the distance falls by about 4 "
            f"per level (§28.4.3).\n"
            f"2. After L levels it is {fmt(d)} / 4^L; we need {fmt(d)} / 4^L < {fmt(tol)}, i.e. 4^L > "
            f"{fmt(d / tol, 6)}.\n"
            f"3. 4^{L - 1} = {4 ** (L - 1)} is not enough, 4^{L} = {4 ** L} is: L = {L}.")


@DECK.exercise(stored=_STORED_CONV, generate=_conv_generate, answer=lambda p: _conv_answers(p)[0],
               slips=lambda p: _conv_answers(p)[1], statement=_conv_statement, steps=_conv_steps,
               same=within(1e-9), well_posed=_conv_ok)
def check_convergence_levels(answer, p) -> Result:
    """Check the number of subdivision levels to bring the polygon within the statement's tolerance
    (Goldman §28.4.3); recognises the distance halved per level, divided by 8 per level, and one level short.

    >>> check_convergence_levels(9)
    Not yet: that would be right if the distance halved per level, like the knot spacing h; but a control point is O(h^2) from the curve, so each level divides the distance by about 4.
    """
    what = "the number of levels"
    value, err = read_number(answer, what, unit="whole number")
    if err is not None:
        return err
    d, tol = p["distance"], p["tol"]
    expected = _levels(p, 4)
    if value == expected:
        return correct(f"{fmt(d)} / 4^{expected} is below {fmt(tol)} and {fmt(d)} / "
                       f"4^{expected - 1} is not: {_WORDS.get(expected, str(expected))} more levels.")
    if value == _levels(p, 2):
        return wrong("that would be right if the distance halved per level, like the knot spacing h; but a control "
                     "point is O(h^2) from the curve, so each level divides the distance by about 4.")
    if value == _levels(p, 8):
        return wrong("that assumes the distance falls like h^3 (a factor 8 per level); the rate of §28.4.3 is O(h^2) "
                     "for every degree >= 2.")
    if value == expected - 1:
        return wrong(f"one level short: after {fmt(value)} levels the distance is {fmt(d / 4 ** value, 3)}, "
                     f"still not below {fmt(tol)}.")
    if value > expected:
        return wrong(f"more than needed: fewer levels already bring the distance below {fmt(tol)}; find the "
                     f"smallest L with {fmt(d)} / 4^L < {fmt(tol)}.")
    return wrong(f"too few levels: each level divides the distance by about 4, so after L levels it is "
                 f"{fmt(d)} / 4^L; find the smallest L that brings it below {fmt(tol)}.")


#: Deal another instance of an exercise (``deal("check_chaikin")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


#: Wrong answers of the kinds each checker recognises (tests/exercises/test_solutions.py feeds them in).
SLIPS = {
    "check_boehm_insert": [QUAD_CTRL.tolist(), [[0, 0], [1, 2], [3.5, 4], [4, 4], [6, 0]],
                           [[0, 0], [0.5, 1], [2.5, 4], [4, 4], [6, 0]], [[0, 0], [2, 4], [2.5, 4], [3, 6], [6, 0]],
                           [[0, 0], [1, 2], [3, 4], [4, 4], [6, 0]]],
    "check_oslo": [[[0, 0], [1, 2], [2.5, 4], [4, 4], [6, 0]], [[0, 0], [2, 4], [3.5, 4], [5, 2], [6, 0]],
                   [[0, 0], [1, 2], [3, 4], [5, 2], [6, 0]]],
    "check_bezier_pieces": [[[[0, 0], [2, 4], [4, 4]], [[2, 4], [4, 4], [6, 0]]],
                            [[[0, 0], [2, 4], [4, 4]], [[4, 4], [4, 4], [6, 0]]],
                            [[[0, 0], [2, 3], [3, 4]], [[3, 4], [4, 4], [6, 0]]]],
    "check_chaikin": [[[0, 0], [1, 3], [2, 6], [6, 6], [10, 6], [10, 3], [10, 0]],
                      [[0.5, 1.5], [1.5, 4.5], [4, 6], [8, 6], [10, 4.5], [10, 1.5], [7.5, 0], [2.5, 0]],
                      [[0, 0], [0, 0], [2, 6], [2, 6], [10, 6], [10, 6], [10, 0], [10, 0]],
                      [[2 / 3, 2], [4 / 3, 4], [14 / 3, 6], [22 / 3, 6], [10, 4], [10, 2]]],
    "check_schaefer": [[[0.75, 1.5], [2.25, 4.5], [4.5, 6], [7.5, 6], [9.75, 4.5], [11.25, 1.5]],
                       [[0, 0], [0, 0], [3, 6], [4, 6], [9, 6], [10.5, 3], [12, 0]],
                       [[0, 0], [1.5, 3], [3, 6], [6, 6], [9, 6], [10.5, 3], [12, 0]],
                       [[0, 0], [1.5, 3], [4.5, 6], [7, 6], [10.5, 3], [12, 0]]],
    "check_convergence_levels": [9, 3, 4, 7, 1],
}


# -- the programming project: Boehm's knot insertion ----------------------------------------------

_DEGREE_NAMES = {1: "linear B-spline", 2: "quadratic B-spline", 3: "cubic B-spline", 4: "quartic B-spline"}


def _interior(rng, m: int) -> np.ndarray:
    """m distinct interior knots in (0, 1), two decimals, sorted."""
    return np.sort(rng.choice(np.arange(5, 96), size=m, replace=False)) / 100.0


def boehm_project_cases(seed: int = 28) -> list[Case]:
    """The generated cases of the Boehm project: degrees 1..4, 2D and 3D, clamped and unclamped
    non-uniform knots; u inside a span, at an existing knot (raising its multiplicity), in the first
    and the last span of the domain, and at a knot that already has multiplicity p (degenerate)."""
    rng = np.random.default_rng(seed)
    cases = []
    for p in (1, 2, 3, 4):
        for d in (2, 3):
            m = int(rng.integers(2, 5))                       # interior knots
            inner = _interior(rng, m)
            clamped = np.concatenate([np.zeros(p + 1), inner, np.ones(p + 1)])
            n1 = len(clamped) - p - 1
            ctrl = np.round(rng.uniform(-5, 5, size=(n1, d)), 1)
            lo, hi = clamped[p], clamped[p + 1]
            choices = [
                ("u inside a span", float(np.round(rng.uniform(0.01, 0.99), 2)), clamped, ctrl),
                ("u at an existing knot", float(inner[int(rng.integers(0, m))]), clamped, ctrl),
                ("u in the first span", float(np.round((lo + hi) / 2, 3)), clamped, ctrl),
                ("u in the last span", float(np.round((clamped[n1 - 1] + clamped[n1]) / 2, 3)), clamped, ctrl),
            ]
            # unclamped, non-uniform knots: the domain is [t_p, t_(n+1)]
            free = np.sort(rng.choice(np.arange(0, 100), size=n1 + p + 1, replace=False)) / 10.0
            uf = float(np.round(rng.uniform(free[p] + 0.01, free[n1] - 0.01), 2))
            choices.append(("unclamped non-uniform knots", uf, free, ctrl))
            for kind, u, knots, P in choices:
                label = (f"inserting u = {fmt(u)} into the {_DEGREE_NAMES[p]} with {len(P)} control points in {d}D "
                         f"and knots [{_knots(knots)}]")
                cases.append(Case(label, (P.copy(), knots.copy(), p, u), kind=kind))
    # degenerate: u already of multiplicity p (the new point repeats an old one)
    p = 3
    knots = np.array([0, 0, 0, 0, 0.3, 0.6, 0.6, 0.6, 1, 1, 1, 1], dtype=float)
    P = np.round(np.random.default_rng(seed + 1).uniform(-5, 5, size=(len(knots) - p - 1, 2)), 1)
    cases.append(Case(f"inserting u = 0.6 into the cubic B-spline with {len(P)} control points in 2D and knots "
                      f"[{_knots(knots)}] (0.6 already has multiplicity 3)", (P, knots, p, 0.6),
                      kind="degenerate: u already of multiplicity p"))
    return cases


def _boehm_reference(ctrl, knots, degree, u):
    return ki.boehm_insert(ctrl, knots, degree, u)[0]


def _boehm_compare(got, expected, case):
    arr = np.asarray(got, dtype=float)
    if arr.shape == (expected.shape[0] - 1, expected.shape[1]):
        return (f"it has {arr.shape[0]} points, as many as before: inserting one knot adds one control point "
                f"(expected {expected.shape[0]})")
    problem = compare_points(tol=1e-8, what="your new control point")(got, expected, case)
    if problem is None or arr.shape != expected.shape:
        return problem
    slips = [
        (dict(swap=True), "the weights are swapped: Q_i = (1 - a_i) P_(i-1) + a_i P_i, so a_i = 1 keeps P_i"),
        (dict(alpha_knot=1), "a_i divides by the wrong knot gap: a_i = (u - t_i) / (t_(i+p) - t_i), with t_(i+p), "
                             "not t_(i+p+1)"),
        (dict(shift=1), "the new points sit one index too late: the span k has t_k <= u < t_(k+1), and the "
                        "new points are Q_(k-p+1) .. Q_k"),
        (dict(shift=-1), "the new points sit one index too early: the span k has t_k <= u < t_(k+1), and the "
                         "new points are Q_(k-p+1) .. Q_k"),
    ]
    for kwargs, why in slips:
        try:
            alt = _boehm_variant(*case.args, **kwargs)
        except (ValueError, IndexError):
            continue
        if alt.shape == arr.shape and np.all(np.isfinite(alt)) and np.allclose(arr, alt, atol=1e-8) \
                and not np.allclose(alt, expected, atol=1e-8):
            return problem + "; " + why
    return problem


def check_boehm_project(function) -> Result:
    """Check the learner's Boehm insertion ``function(ctrl, knots, degree, u) -> new ctrl`` on the
    generated cases of :func:`boehm_project_cases` against :func:`goldman_lib.knot_insertion.boehm_insert`
    (Goldman §28.3.1).

    >>> def swapped(ctrl, knots, degree, u):
    ...     return _boehm_variant(ctrl, knots, degree, u, swap=True)
    >>> print(check_boehm_project(swapped).message)   # doctest: +ELLIPSIS
    case ...: ...; the weights are swapped: ... Hint: ...
    """
    return check_project(function, boehm_project_cases(), reference=_boehm_reference, compare=_boehm_compare,
                         what="Boehm's knot insertion",
                         hint=("with t_k <= u < t_(k+1), keep P_0..P_(k-p) and P_k..P_n; for k-p+1 <= i <= k put "
                               "Q_i = (1 - a_i) P_(i-1) + a_i P_i with a_i = (u - t_i)/(t_(i+p) - t_i)"))


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

"""Exercise checkers for chapter 24, Bezier curves and surfaces (Goldman §24.2-24.6).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0
is the module constants below, which the stored notebook shows; ``deal("check_...")`` (or the button
beside the exercise) deals another, and the checker, ``PROBLEMS`` and ``steps("check_...")`` follow the
current instance.  The chapter's "show that" exercises (in :mod:`goldman_lib.exercises.proofs`) ask for
an identity, not a number, so they do not deal.  ``SLIPS`` holds the wrong answers of the kinds each
checker recognises, for the stored instance (``tests/exercises/test_solutions.py`` feeds them to the checkers and
fails a message that gives the answer away).  The data differ from the chapter's worked examples (the
cubic (0, 0), (1, 2.5), (3, 2.5), (4, 0.5) and the bicubic patch of §24.6), so no exercise asks for a
number the chapter printed.

>>> print(PROBLEMS["check_bernstein_weights"])
Give the 5 Bernstein weights B_0^4(0.2), ..., B_4^4(0.2) that the quartic Bezier curve gives its control points at t = 0.2, as a list (Goldman §24.3).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import bezier
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, check_points, correct, fmt, fmt_points, off_by, read_points, wrong
from goldman_lib.exercises.deal import Deck, integers as _ints, plain as _tup, steps_number as _f, within

__all__ = ["PROBLEMS", "SLIPS", "DE_CASTELJAU_CTRL", "DE_CASTELJAU_T", "BERNSTEIN_N", "BERNSTEIN_T",
           "END_P0", "END_D0", "END_P3", "END_D1", "HODOGRAPH_CTRL", "ELEVATION_CTRL", "JOIN_CTRL",
           "JOIN_RATIO", "PATCH_NET", "PATCH_U", "PATCH_V", "NEVILLE_POINTS", "NEVILLE_NODES", "NEVILLE_T",
           "DECK", "deal", "steps", "current", "deal_button",
           "check_de_casteljau_point", "check_bernstein_weights", "check_end_conditions", "check_hodograph",
           "check_degree_elevation", "check_c1_join_unequal", "check_patch_point", "check_neville_point"]

#: Exercise 1 (§24.2): the cubic whose point at t = 1/4 is computed by hand with de Casteljau.
DE_CASTELJAU_CTRL = np.array([[0.0, 0.0], [4.0, 8.0], [8.0, 8.0], [12.0, 0.0]])
DE_CASTELJAU_T = 0.25
#: Exercise 2 (§24.3): the weights B_k^N(T), k = 0..N.
BERNSTEIN_N, BERNSTEIN_T = 4, 0.2
#: Exercise 3 (§24.4): a cubic given by its end points and end derivatives (Hermite data).
END_P0, END_D0 = np.array([1.0, 1.0]), np.array([6.0, 3.0])
END_P3, END_D1 = np.array([7.0, 1.0]), np.array([3.0, -6.0])
#: Exercise 4 (§24.5): the cubic whose hodograph (derivative curve) is asked for.
HODOGRAPH_CTRL = np.array([[1.0, 0.0], [2.0, 3.0], [5.0, 4.0], [6.0, 1.0]])
#: Exercise 5 (§24.5): the quadratic to elevate to degree 3.
ELEVATION_CTRL = np.array([[0.0, 0.0], [6.0, 3.0], [3.0, 9.0]])
#: Exercise 6 (§24.5.1): the cubic P over [0, 1] that a cubic Q over [1, 1 + JOIN_RATIO] continues.
JOIN_CTRL = np.array([[0.0, 0.0], [1.0, 3.0], [4.0, 4.0], [6.0, 3.0]])
JOIN_RATIO = 2.0
#: Exercise 7 (§24.6): a biquadratic net P_ij = (2j, 2i, z_ij) (row index i goes with u) and (u, v).
_Z = np.array([[0.0, 2.0, 0.0], [2.0, 4.0, 2.0], [0.0, 2.0, 4.0]])
PATCH_NET = np.array([[[2.0 * j, 2.0 * i, _Z[i, j]] for j in range(3)] for i in range(3)])
PATCH_U, PATCH_V = 0.5, 0.25
#: Exercise 8 (§24.1): three points interpolated at the nodes 0, 1/2, 1; the parameter of Neville's pyramid.
NEVILLE_POINTS = np.array([[0.0, 0.0], [4.0, 4.0], [8.0, 0.0]])
NEVILLE_NODES = np.array([0.0, 0.5, 1.0])
NEVILLE_T = 0.25


DECK = Deck("ch24")

_DEGREE_WORDS = {2: "quadratic", 3: "cubic", 4: "quartic", 5: "quintic"}


def _net_text(net) -> str:
    return "; ".join(f"row {i}: " + fmt_points(row) for i, row in enumerate(net))


def _arr(x):
    return np.asarray(x, dtype=float)


def _apart(forms, tol=1e-3) -> bool:
    """Whether the forms a checker recognises (arrays of one shape) are pairwise further apart than
    ``tol`` in some coordinate, so that each gets its own message."""
    forms = [_arr(f) for f in forms]
    return not any(u.shape == v.shape and np.all(np.abs(u - v) <= tol)
                   for i, u in enumerate(forms) for v in forms[i + 1:])


_SAME = within(1e-3)
_QUARTERS = (0.25, 0.75)


# -- §24.2: de Casteljau ------------------------------------------------------------------------------------

_STORED_DC = {"ctrl": _tup(DE_CASTELJAU_CTRL), "t": DE_CASTELJAU_T}


def _steps(ctrl, t):
    return bezier.de_casteljau_steps(ctrl, t)


def _dc_answer(p):
    return _steps(_arr(p["ctrl"]), p["t"])[-1][0]


def _dc_slips(p):
    P, t = _arr(p["ctrl"]), p["t"]
    return {"stopped at level 2": _steps(P, t)[-2][0], "at 1 - t": bezier.de_casteljau(P, 1 - t),
            "centroid": P.mean(axis=0)}


def _dc_generate(rng) -> dict:
    return {"ctrl": _ints(rng, 0, 12, (4, 2)), "t": float(rng.choice(_QUARTERS))}


def _dc_ok(p):
    P, t = _arr(p["ctrl"]), p["t"]
    inner = [q for level in _steps(P, t)[1:-1] for q in level]
    if not _apart([_dc_answer(p), bezier.de_casteljau(P, 1 - t), P.mean(axis=0)] + inner):
        return "two points the checker recognises coincide (the intermediate levels included)"
    return None


def _dc_statement(p) -> str:
    return (f"Run de Casteljau's algorithm by hand on the cubic with control points {fmt_points(_arr(p['ctrl']))} "
            f"at t = {fmt(p['t'])}: give the point on the curve as [x, y] (Goldman §24.2).")


def _dc_steps(p) -> str:
    t = p["t"]
    levels = _steps(_arr(p["ctrl"]), t)
    lines = [f"Each new point is (1 - t) P_j + t P_(j+1) = {fmt(1 - t)} P_j + {fmt(t)} P_(j+1)."]
    lines += [f"{r}. Level {r}: " + ", ".join(_f(q) for q in level) for r, level in enumerate(levels[1:], start=1)]
    lines.append(f"The apex {_f(levels[-1][0])} is the point C({fmt(t)}).")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_DC, generate=_dc_generate, answer=_dc_answer, slips=_dc_slips,
               statement=_dc_statement, steps=_dc_steps, same=_SAME, well_posed=_dc_ok)
def check_de_casteljau_point(answer, p) -> Result:
    """Check the point of the statement's cubic at its parameter t (Goldman §24.2).

    answer: [x, y].  Recognises a point of an intermediate level of the construction (stopped too
    early), the point at 1 - t (t and 1 - t exchanged in (1-t) P_j + t P_{j+1}) and the centroid of
    the control points (equal weights instead of the Bernstein weights).
    """
    P, t = _arr(p["ctrl"]), p["t"]
    what = f"the point at t={fmt(t)}"
    got, err = read_points(answer, "your point", ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} should be one point [x, y]; yours has shape {got.shape}.")
    steps = _steps(P, t)
    expected = steps[-1][0]
    dist = float(np.linalg.norm(got - expected))
    if dist <= 1e-4:
        return correct(f"{what} is {fmt(expected)}.")
    for level, pts in enumerate(steps[1:-1], start=1):
        if np.any(np.linalg.norm(pts - got, axis=1) <= 1e-4):
            return wrong(f"your point is a point of level {level} of the construction, not the end: "
                         "a cubic needs three levels of affine combinations.")
    if np.linalg.norm(got - bezier.de_casteljau(P, 1 - t)) <= 1e-4:
        return wrong(f"that is the point at t = {fmt(1 - t)}: each step must move a fraction t = {fmt(t)} of the way "
                     f"from P_j towards P_(j+1), (1-t) P_j + t P_(j+1), not a fraction 1 - t.")
    if np.linalg.norm(got - P.mean(axis=0)) <= 1e-4:
        return wrong(f"your point is the average of the control points; the curve weights them by the "
                     f"Bernstein values at t, which are not equal.")
    return wrong(f"your point is {far_off(got, expected)} from the curve at t={fmt(t)}; the curve point is a repeated "
                 f"affine combination (1-t) P_j + t P_(j+1), three levels deep for a cubic.")


# -- §24.3: Bernstein weights ---------------------------------------------------------------------------------

_STORED_BERNSTEIN = {"n": BERNSTEIN_N, "t": BERNSTEIN_T}


def _bernstein_answer(p):
    return bezier.bernstein(p["n"], p["t"])


def _bernstein_slips(p):
    n, t = p["n"], p["t"]
    k = np.arange(n + 1)
    return {"no binomial coefficients": t ** k * (1 - t) ** (n - k), "reversed": _bernstein_answer(p)[::-1]}


def _bernstein_generate(rng) -> dict:
    return {"n": int(rng.integers(2, 6)), "t": float(rng.choice([0.1, 0.2, 0.25, 0.3, 0.6, 0.7, 0.75, 0.8, 0.9]))}


def _bernstein_statement(p) -> str:
    n, t = p["n"], p["t"]
    return (f"Give the {n + 1} Bernstein weights B_0^{n}({fmt(t)}), ..., "
            f"B_{n}^{n}({fmt(t)}) that the {_DEGREE_WORDS[n]} Bezier curve gives its control points "
            f"at t = {fmt(t)}, as a list (Goldman §24.3).")


def _bernstein_steps(p) -> str:
    n, t = p["n"], p["t"]
    w = _bernstein_answer(p)
    rows = [f"- B_{k}^{n}({fmt(t)}) = C({n}, {k}) {fmt(t)}^{k} {fmt(1 - t)}^{n - k} = {math.comb(n, k)}·"
            f"{_f(t ** k)}·{_f((1 - t) ** (n - k))} = {_f(w[k])}" for k in range(n + 1)]
    return (f"B_k^{n}(t) = C({n}, k) t^k (1 - t)^({n} - k) with t = {fmt(t)}, 1 - t = {fmt(1 - t)}:\n\n" + "\n".join(rows)
            + f"\n\nThey sum to 1 ({_f(w.sum())}).")


@DECK.exercise(stored=_STORED_BERNSTEIN, generate=_bernstein_generate, answer=_bernstein_answer,
               slips=_bernstein_slips, statement=_bernstein_statement, steps=_bernstein_steps, same=_SAME)
def check_bernstein_weights(answer, p) -> Result:
    """Check the list B_k^N(T), k = 0..N, of the statement's degree N and parameter T (Goldman §24.3).

    Recognises the weights without the binomial coefficients, the list in reverse order (t and
    1 - t exchanged) and a wrong number of weights; otherwise names the first weight that is off.
    Tolerance 1e-4 per weight.
    """
    n, t = p["n"], p["t"]
    what = "the weights"
    got, err = read_points(answer, what, ask=f"the {n + 1} weights as a list")
    if err is not None:
        return err
    expected = bezier.bernstein(n, t)
    if got.shape != expected.shape:
        return wrong(f"{what} should be a list of {n + 1} numbers, one per control point of a degree-{n} "
                     f"curve; yours has shape {got.shape}.")
    if np.allclose(got, expected, atol=1e-4):
        return correct(f"the {n + 1} weights match, and they sum to one.")
    k = np.arange(n + 1)
    if np.allclose(got, t ** k * (1 - t) ** (n - k), atol=1e-4):
        binom = ", ".join(str(math.comb(n, j)) for j in k)
        return wrong(f"these are t^k (1-t)^({n}-k) alone: B_k^{n} also has the binomial coefficient C({n}, k) "
                     f"({binom}), the number of paths down the de Casteljau pyramid.")
    if np.allclose(got, expected[::-1], atol=1e-4):
        return wrong(f"the list is reversed: B_k^{n}(t) = C({n}, k) t^k (1-t)^({n}-k) puts the power t^k on P_k, so "
                     f"near t = 0 the first weight is the largest; you exchanged t and 1 - t.")
    bad = int(np.flatnonzero(np.abs(got - expected) > 1e-4)[0])
    hint = "" if abs(got.sum() - 1) <= 1e-4 else " Your weights do not sum to one, as Bernstein weights must."
    return wrong(f"weight {bad} (B_{bad}^{n}) is {off_by(got[bad], expected[bad])}.{hint} "
                 f"Check B_k^n(t) = C(n, k) t^k (1-t)^(n-k).")


# -- §24.4: end conditions ------------------------------------------------------------------------------------

_STORED_ENDS = {"P0": _tup(END_P0), "D0": _tup(END_D0), "P3": _tup(END_P3), "D1": _tup(END_D1)}


def _ends(p):
    return _arr(p["P0"]), _arr(p["D0"]), _arr(p["P3"]), _arr(p["D1"])


def _ends_answer(p):
    P0, D0, P3, D1 = _ends(p)
    return np.array([P0, P0 + D0 / 3, P3 - D1 / 3, P3])


def _ends_slips(p):
    P0, D0, P3, D1 = _ends(p)
    return {"no factor 1/3": np.array([P0, P0 + D0, P3 - D1, P3]),
            "P2 on the wrong side": np.array([P0, P0 + D0 / 3, P3 + D1 / 3, P3])}


def _ends_generate(rng) -> dict:
    nonzero = lambda: _tup(3 * np.array([v if v else 1 for v in rng.integers(-3, 4, size=2)]))  # noqa: E731
    return {"P0": _ints(rng, -2, 8, 2), "D0": nonzero(), "P3": _ints(rng, -2, 8, 2), "D1": nonzero()}


def _ends_ok(p):
    if np.allclose(_arr(p["P0"]), _arr(p["P3"])):
        return "the curve would be closed (P0 = P3)"
    return None


def _ends_statement(p) -> str:
    return (f"A cubic Bezier curve starts at C(0) = {fmt(p['P0'])} with velocity C'(0) = {fmt(p['D0'])} and ends at "
            f"C(1) = {fmt(p['P3'])} with velocity C'(1) = {fmt(p['D1'])}. Use endpoint interpolation and the end "
            f"tangents of §24.4 to give its four control points P0, P1, P2, P3 (Goldman §24.4).")


def _ends_steps(p) -> str:
    P0, D0, P3, D1 = _ends(p)
    Q = _ends_answer(p)
    return (f"1. The curve interpolates its end control points: P0 = C(0) = {fmt(P0)}, P3 = C(1) = {fmt(P3)}.\n"
            f"2. C'(0) = 3 (P1 - P0), so P1 = P0 + C'(0)/3 = {fmt(P0)} + {_f(D0 / 3)} = {_f(Q[1])}.\n"
            f"3. C'(1) = 3 (P3 - P2), so P2 = P3 - C'(1)/3 = {fmt(P3)} - {_f(D1 / 3)} = {_f(Q[2])}.")


@DECK.exercise(stored=_STORED_ENDS, generate=_ends_generate, answer=_ends_answer, slips=_ends_slips,
               statement=_ends_statement, steps=_ends_steps, same=_SAME, well_posed=_ends_ok)
def check_end_conditions(answer, p) -> Result:
    """Check the control points of the cubic with the statement's end points and end velocities (Goldman §24.4).

    answer: (4, 2).  Recognises end points that are not interpolated, inner points without the
    factor 1/3 (C'(0) = 3 (P1 - P0)), and P2 on the wrong side of P3 (P3 + C'(1)/3).

    >>> check_end_conditions([[1, 1], [7, 4], [4, 7], [7, 1]])
    Not yet: the inner points are the right direction but three times too far: C'(0) = 3 (P1 - P0) for a cubic, so P1 - P0 is a third of C'(0) (and likewise at the other end).
    """
    what = "the control points"
    got, err = read_points(answer, what, ask="the four control points as [[x0, y0], ..., [x3, y3]]")
    if err is not None:
        return err
    if got.shape != (4, 2):
        return wrong(f"{what} should be four points [x, y] (a cubic); yours has shape {got.shape}.")
    P0, D0, P3, D1 = _ends(p)
    n = 3
    expected = np.array([P0, P0 + D0 / n, P3 - D1 / n, P3])
    if np.allclose(got, expected, atol=1e-4):
        return correct("the control points match: P1 = P0 + C'(0)/3 and P2 = P3 - C'(1)/3.")
    if np.linalg.norm(got[0] - P0) > 1e-4 or np.linalg.norm(got[3] - P3) > 1e-4:
        return wrong("a Bezier curve interpolates its end control points: P0 must be C(0) and P3 must be C(1).")
    no_third = np.array([P0, P0 + D0, P3 - D1, P3])
    if np.allclose(got, no_third, atol=1e-4):
        return wrong("the inner points are the right direction but three times too far: C'(0) = 3 (P1 - P0) for a "
                     "cubic, so P1 - P0 is a third of C'(0) (and likewise at the other end).")
    if np.linalg.norm(got[2] - (P3 + D1 / n)) <= 1e-4:
        return wrong("P2 is on the wrong side of P3: the curve arrives at P3 from the direction of P2, "
                     "C'(1) = 3 (P3 - P2), so P2 = P3 - C'(1)/3.")
    return check_points(got, expected, what=what,
                        hint="C'(0) = 3 (P1 - P0) and C'(1) = 3 (P3 - P2) for a cubic")


# -- §24.5: hodograph -----------------------------------------------------------------------------------------

_STORED_HODOGRAPH = {"ctrl": _tup(HODOGRAPH_CTRL)}


def _hodograph_answer(p):
    return bezier.hodograph(_arr(p["ctrl"]))


def _hodograph_slips(p):
    H = _hodograph_answer(p)
    return {"no factor n": H / (len(H)), "backwards": -H}


def _hodograph_generate(rng) -> dict:
    return {"ctrl": _ints(rng, -2, 8, (int(rng.choice([3, 4, 5])), 2))}


def _hodograph_ok(p):
    H = _hodograph_answer(p)
    if np.any(np.all(np.abs(H) < 0.5, axis=1)):
        return "two consecutive control points coincide"
    return None


def _hodograph_statement(p) -> str:
    P = _arr(p["ctrl"])
    return (f"Give the control points of the hodograph (the derivative curve) of the {_DEGREE_WORDS[len(P) - 1]} with "
            f"control points {fmt_points(P)} (Goldman §24.5).")


def _hodograph_steps(p) -> str:
    P = _arr(p["ctrl"])
    n = len(P) - 1
    return (f"1. The degree is n = {n}; the differences P_(k+1) - P_k are {', '.join(_f(d) for d in np.diff(P, axis=0))}.\n"
            f"2. The hodograph's control points are n (P_(k+1) - P_k): "
            f"{', '.join(_f(h) for h in _hodograph_answer(p))} (degree {n - 1}).")


@DECK.exercise(stored=_STORED_HODOGRAPH, generate=_hodograph_generate, answer=_hodograph_answer,
               slips=_hodograph_slips, statement=_hodograph_statement, steps=_hodograph_steps, same=_SAME,
               well_posed=_hodograph_ok)
def check_hodograph(answer, p) -> Result:
    """Check the control points of the hodograph of the statement's curve (Goldman §24.5).

    answer: (n, 2), the points ``n (P_{k+1} - P_k)``.  Recognises the differences without the
    factor n, the differences taken the other way (P_k - P_{k+1}) and a wrong number of points.

    >>> check_hodograph([[1, 3], [3, 1], [1, -3]])
    Not yet: these are the differences P_(k+1) - P_k; the hodograph multiplies them by the degree n = 3.
    """
    what = "the hodograph's control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P = _arr(p["ctrl"])
    n = len(P) - 1
    expected = bezier.hodograph(P)
    if got.shape != expected.shape:
        return wrong(f"{what} should be {n} points of shape {expected.shape}: the derivative of a degree-{n} "
                     f"curve has degree {n - 1}; yours has shape {got.shape}.")
    if np.allclose(got, expected / n, atol=1e-6):
        return wrong(f"these are the differences P_(k+1) - P_k; the hodograph multiplies them by the degree n = {n}.")
    if np.allclose(got, -expected, atol=1e-6) or np.allclose(got, -expected / n, atol=1e-6):
        return wrong("the differences point backwards: the derivative follows the curve's direction, "
                     "n (P_(k+1) - P_k), later point minus earlier point.")
    return check_points(got, expected, what=what, hint=f"the k-th point is {n} (P_(k+1) - P_k)")


# -- §24.5: degree elevation -----------------------------------------------------------------------------------

_STORED_ELEVATION = {"ctrl": _tup(ELEVATION_CTRL)}


def _elevation_swapped(P):
    n1 = len(P)
    a = (np.arange(1, n1) / n1)[:, None]
    return np.vstack([P[:1], (1 - a) * P[:-1] + a * P[1:], P[-1:]])


def _elevation_answer(p):
    return bezier.elevate_degree(_arr(p["ctrl"]))


def _elevation_slips(p):
    P = _arr(p["ctrl"])
    return {"weights swapped": _elevation_swapped(P), "the quadratic's own points": P}


def _elevation_generate(rng) -> dict:
    # every point congruent mod 3 coordinate by coordinate: the thirds of the elevation come out whole
    return {"ctrl": _tup(rng.integers(0, 3, size=2) + 3 * rng.integers(-1, 4, size=(3, 2)))}


def _elevation_statement(p) -> str:
    return (f"Elevate the quadratic with control points {fmt_points(_arr(p['ctrl']))} to degree 3: give the four new "
            f"control points (Goldman §24.5).")


def _elevation_steps(p) -> str:
    P = _arr(p["ctrl"])
    Q = _elevation_answer(p)
    return (f"Q_k = k/3 P_(k-1) + (1 - k/3) P_k; the end points stay.\n"
            f"1. Q_0 = P_0 = {fmt(P[0])}.\n"
            f"2. Q_1 = 1/3 P_0 + 2/3 P_1 = {_f(Q[1])}.\n"
            f"3. Q_2 = 2/3 P_1 + 1/3 P_2 = {_f(Q[2])}.\n"
            f"4. Q_3 = P_2 = {fmt(P[2])}.")


@DECK.exercise(stored=_STORED_ELEVATION, generate=_elevation_generate, answer=_elevation_answer,
               slips=_elevation_slips, statement=_elevation_statement, steps=_elevation_steps, same=_SAME)
def check_degree_elevation(answer, p) -> Result:
    """Check the control points of the statement's quadratic elevated to degree 3 (Goldman §24.5).

    answer: (4, 2).  Recognises the weights swapped between ``P_{k-1}`` and ``P_k``, moved end
    points and a wrong number of points.

    >>> check_degree_elevation([[0, 0], [2, 1], [4, 7], [3, 9]])
    Not yet: the weights are swapped: Q_k = k/(n+1) P_(k-1) + (1 - k/(n+1)) P_k gives P_(k-1) the weight k/(n+1).
    """
    what = "the elevated control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P = _arr(p["ctrl"])
    expected = bezier.elevate_degree(P)
    if got.shape != expected.shape:
        return wrong(f"{what} should be four points, as a cubic has; your answer has {len(got) if got.ndim else 'one'} entries.")
    if np.allclose(got, _elevation_swapped(P), atol=1e-6):
        return wrong("the weights are swapped: Q_k = k/(n+1) P_(k-1) + (1 - k/(n+1)) P_k gives P_(k-1) "
                     "the weight k/(n+1).")
    if np.linalg.norm(got[0] - P[0]) > 1e-6 or np.linalg.norm(got[-1] - P[-1]) > 1e-6:
        return wrong("degree elevation keeps the curve, so it keeps its end points: Q_0 = P_0 and Q_3 = P_2.")
    return check_points(got, expected, what=what,
                        hint="the end points stay; Q_k = k/(n+1) P_(k-1) + (1 - k/(n+1)) P_k")


# -- §24.5.1: a C1 join over unequal intervals -------------------------------------------------------------

_STORED_JOIN = {"ctrl": _tup(JOIN_CTRL), "r": JOIN_RATIO}


def _join_answer(p):
    return bezier.smooth_join(_arr(p["ctrl"]), "C1", ratio=p["r"])


def _join_slips(p):
    P, r = _arr(p["ctrl"]), p["r"]
    lead = P[-1] - P[-2]
    return {"equal intervals": np.array([P[-1], P[-1] + lead]), "ratio inverted": np.array([P[-1], P[-1] + lead / r]),
            "a cusp": np.array([P[-1], P[-1] - r * lead])}


def _join_generate(rng) -> dict:
    return {"ctrl": _ints(rng, -2, 8, (4, 2)), "r": float(rng.choice([2.0, 3.0, 0.5, 1.5, 2.5]))}


def _join_ok(p):
    P = _arr(p["ctrl"])
    if np.allclose(P[-1], P[-2]):
        return "P3 = P2: the curve has no tangent direction at its end"
    return None


def _join_statement(p) -> str:
    r = p["r"]
    return (f"The cubic P with control points {fmt_points(_arr(p['ctrl']))} runs over the parameter interval [0, 1]; a "
            f"second cubic Q continues it over [1, {fmt(1 + r)}], an interval {fmt(r)} times as long. Give Q0 and "
            f"Q1 so that the join is C1 in the global parameter (Goldman §24.5.1).")


def _join_steps(p) -> str:
    P, r = _arr(p["ctrl"]), p["r"]
    Q = _join_answer(p)
    return (f"1. C0: Q0 = P3 = {fmt(P[-1])}.\n"
            f"2. In the global parameter P'(1) = 3 (P3 - P2) / 1 and Q'(1) = 3 (Q1 - Q0) / {fmt(r)}; equal when "
            f"Q1 - Q0 = {fmt(r)} (P3 - P2) = {fmt(r)}·{fmt(P[-1] - P[-2])}.\n"
            f"3. Q1 = {_f(Q[1])}.")


@DECK.exercise(stored=_STORED_JOIN, generate=_join_generate, answer=_join_answer, slips=_join_slips,
               statement=_join_statement, steps=_join_steps, same=_SAME, well_posed=_join_ok)
def check_c1_join_unequal(answer, p) -> Result:
    """Check Q0, Q1 of a cubic over an interval the statement's ratio times as long that continues
    its cubic P with C1 continuity (Goldman §24.5.1).

    answer: (2, 2), the points Q0 and Q1.  Recognises a gap at the join, the equal-interval answer
    (G1 only), the ratio inverted, and a tangent pointing the wrong way (a cusp).

    >>> check_c1_join_unequal([[6, 3], [8, 2]])
    Not yet: this would be C1 for equal parameter intervals; here the join is only G1. In the global parameter Q'(1) = 3 (Q1 - Q0) / 2 must equal P'(1) = 3 (P3 - P2) / 1: scale the leg by the ratio of the intervals.
    """
    what = "Q0 and Q1"
    got, err = read_points(answer, what, ask=what + " as [[x0, y0], [x1, y1]]")
    if err is not None:
        return err
    if got.shape != (2, 2):
        return wrong(f"{what} should be two points, shape (2, 2); yours has shape {got.shape}.")
    P, r = _arr(p["ctrl"]), p["r"]
    expected = bezier.smooth_join(P, "C1", ratio=r)
    if np.linalg.norm(got[0] - expected[0]) > 1e-6:
        return wrong("Q0 must be P3 so that the curves meet (C0); yours leaves a gap at the join.")
    lead = P[-1] - P[-2]
    leg = got[1] - got[0]
    if np.linalg.norm(leg - r * lead) <= 1e-6:
        return correct(f"the join is C1: Q0 = P3 and Q1 - Q0 = {fmt(r)} (P3 - P2), the ratio of the parameter intervals.")
    rr = fmt(r)
    if np.linalg.norm(leg - lead) <= 1e-6:
        return wrong(f"this would be C1 for equal parameter intervals; here the join is only G1. In the global "
                     f"parameter Q'(1) = 3 (Q1 - Q0) / {rr} must equal P'(1) = 3 (P3 - P2) / 1: scale the leg by "
                     f"the ratio of the intervals.")
    if np.linalg.norm(leg - lead / r) <= 1e-6:
        longer = "longer" if r > 1 else "shorter"
        return wrong(f"the ratio is inverted: Q runs over the {longer} interval, so to keep the same speed in the "
                     f"global parameter its first leg must be {longer} than P's last leg, not "
                     f"{'shorter' if r > 1 else 'longer'}.")
    cross = lead[0] * leg[1] - lead[1] * leg[0]
    collinear = abs(cross) <= 1e-6 * max(1.0, float(np.linalg.norm(leg)))
    if collinear and leg @ lead < 0:
        return wrong("Q1 lies on the tangent line but on the wrong side of Q0: the curve would turn back "
                     "(a cusp). Q1 - Q0 must point the way P3 - P2 does.")
    if collinear and leg @ lead > 0:
        return wrong("the tangent direction is right (G1), but the length of Q1 - Q0 is not: Q1 - Q0 must be "
                     "P3 - P2 times the ratio of the parameter intervals (Q's over P's).")
    return wrong(f"Q1 is {far_off(got[1], expected[1])} from where it should be: Q1 - Q0 "
                 f"must be parallel to P3 - P2 and scaled by the ratio of the parameter intervals.")


# -- §24.6: a point of a tensor-product patch -----------------------------------------------------------------

_STORED_PATCH = {"net": _tup(PATCH_NET), "u": PATCH_U, "v": PATCH_V}


def _corners(net):
    return np.array([[net[0, 0], net[0, -1]], [net[-1, 0], net[-1, -1]]])


def _patch_answer(p):
    return bezier.patch_de_casteljau(_arr(p["net"]), p["u"], p["v"])


def _patch_slips(p):
    net, u, v = _arr(p["net"]), p["u"], p["v"]
    return {"u and v exchanged": bezier.patch_de_casteljau(net, v, u),
            "bilinear corners": bezier.patch_de_casteljau(_corners(net), u, v),
            "average": net.reshape(-1, 3).mean(axis=0)}


def _patch_generate(rng) -> dict:
    z = rng.integers(0, 5, size=(3, 3))
    net = [[[2.0 * j, 2.0 * i, float(z[i, j])] for j in range(3)] for i in range(3)]
    u, v = rng.choice([0.25, 0.5, 0.75], size=2, replace=False)
    return {"net": _tup(net), "u": float(u), "v": float(v)}


def _patch_statement(p) -> str:
    return (f"The biquadratic patch P(u, v) = sum_i sum_j B_i^2(u) B_j^2(v) P_ij has the control net "
            f"{_net_text(_arr(p['net']))} (the row index i goes with u, the column index j with v). Give the point "
            f"P({fmt(p['u'])}, {fmt(p['v'])}) as [x, y, z] (Goldman §24.6).")


def _patch_steps(p) -> str:
    net, u, v = _arr(p["net"]), p["u"], p["v"]
    rows = np.array([bezier.de_casteljau(row, v) for row in net])
    return (f"1. The Bernstein weights: B^2({fmt(u)}) = {_f(bezier.bernstein(2, u))} in u, "
            f"B^2({fmt(v)}) = {_f(bezier.bernstein(2, v))} in v.\n"
            f"2. Each row (j = 0, 1, 2) at v = {fmt(v)}: " + ", ".join(_f(r) for r in rows) + ".\n"
            f"3. Those three points at u = {fmt(u)}: P({fmt(u)}, {fmt(v)}) = {_f(_patch_answer(p))}.")


@DECK.exercise(stored=_STORED_PATCH, generate=_patch_generate, answer=_patch_answer, slips=_patch_slips,
               statement=_patch_statement, steps=_patch_steps, same=_SAME)
def check_patch_point(answer, p) -> Result:
    """Check the point of the statement's biquadratic patch at its (u, v) (Goldman §24.6).

    answer: [x, y, z].  Recognises u and v exchanged (rows evaluated at u), the bilinear
    interpolation of the four corners only, and the plain average of the nine control points.
    Tolerance 1e-4.

    >>> check_patch_point([1, 2, 0.5])
    Not yet: that is the bilinear interpolation of the four corner points: the patch also weights the five other control points, by the products of the quadratic Bernstein values in u and in v.
    """
    u, v = p["u"], p["v"]
    what = f"P({fmt(u)}, {fmt(v)})"
    got, err = read_points(answer, "your point", ask=what + " as [x, y, z]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"{what} should be one point [x, y, z]; yours has shape {got.shape}.")
    net = _arr(p["net"])
    expected = bezier.patch_de_casteljau(net, u, v)
    if np.linalg.norm(got - expected) <= 1e-4:
        return correct(f"{what} is {fmt(expected)}.")
    if np.linalg.norm(got - bezier.patch_de_casteljau(net, v, u)) <= 1e-4:
        return wrong("u and v are exchanged: the row index i goes with u, so evaluate each row (j = 0, 1, 2) at "
                     "v, then the resulting three points at u.")
    if np.linalg.norm(got - bezier.patch_de_casteljau(_corners(net), u, v)) <= 1e-4:
        return wrong("that is the bilinear interpolation of the four corner points: the patch also weights the "
                     "five other control points, by the products of the quadratic Bernstein values in u and in v.")
    if np.linalg.norm(got - net.reshape(-1, 3).mean(axis=0)) <= 1e-4:
        return wrong("that is the plain average of the nine control points; the patch weights P_ij by the "
                     "products of the Bernstein values in u and in v, which are not equal.")
    return wrong(f"your point is {far_off(got, expected)} from the patch point; run de "
                 f"Casteljau on each row at v, then on the three results at u.")


# -- §24.1: Neville's pyramid ---------------------------------------------------------------------------------

_STORED_NEVILLE = {"points": _tup(NEVILLE_POINTS), "nodes": _tup(NEVILLE_NODES), "t": NEVILLE_T}


def _neville_answer(p):
    return bezier.neville(_arr(p["points"]), p["t"], nodes=_arr(p["nodes"]))


def _level1(p, i):
    P, nodes = _arr(p["points"]), _arr(p["nodes"])
    return bezier.neville(P[i:i + 2], p["t"], nodes=nodes[i:i + 2])


def _neville_forms(p):
    """Every point the checker recognises, answer first."""
    P, t = _arr(p["points"]), p["t"]
    return [_neville_answer(p), bezier.de_casteljau(P, t), _level1(p, 0), _level1(p, 1)] + list(P)


def _neville_slips(p):
    P, t, nodes = _arr(p["points"]), p["t"], _arr(p["nodes"])
    near = int(np.argmin(np.abs(nodes - t)))
    return {"the Bezier point": bezier.de_casteljau(P, t), "level 1": _level1(p, 0 if t < nodes[1] else 1),
            "a data point": P[near]}


def _neville_generate(rng) -> dict:
    return {"points": _ints(rng, 0, 8, (3, 2)), "nodes": (0.0, 0.5, 1.0), "t": float(rng.choice([0.25, 0.75]))}


def _neville_ok(p):
    if not _apart(_neville_forms(p)):
        return "two points the checker recognises coincide (the data points and both first-level points included)"
    return None


def _neville_statement(p) -> str:
    return (f"The quadratic curve L(t) passes through the points {fmt_points(_arr(p['points']))} at the parameters "
            f"t = {', '.join(fmt(x) for x in p['nodes'])}. Run Neville's pyramid by hand and give L({fmt(p['t'])}) "
            f"as [x, y] (Goldman §24.1).")


def _neville_steps(p) -> str:
    t, nodes = p["t"], p["nodes"]
    return (f"Level r combines neighbours with the weights (t_(i+r) - t)/(t_(i+r) - t_i) and (t - t_i)/(t_(i+r) - t_i), "
            f"t = {fmt(t)}.\n"
            f"1. Level 1, nodes {fmt(nodes[0])}, {fmt(nodes[1])}: {_f(_level1(p, 0))}; nodes {fmt(nodes[1])}, "
            f"{fmt(nodes[2])}: {_f(_level1(p, 1))}.\n"
            f"2. Level 2, nodes {fmt(nodes[0])}, {fmt(nodes[2])}: L({fmt(t)}) = {_f(_neville_answer(p))}.")


@DECK.exercise(stored=_STORED_NEVILLE, generate=_neville_generate, answer=_neville_answer, slips=_neville_slips,
               statement=_neville_statement, steps=_neville_steps, same=_SAME, well_posed=_neville_ok)
def check_neville_point(answer, p) -> Result:
    """Check the point of the interpolating quadratic through the statement's points at its t (Goldman §24.1).

    answer: [x, y].  Recognises the Bezier point of the same three points (approximation instead of
    interpolation: de Casteljau's weights 1-t and t on every level), a point of the first level of
    Neville's pyramid (stopped too early), and a data point itself.
    """
    t = p["t"]
    P, nodes = _arr(p["points"]), _arr(p["nodes"])
    what = f"L({fmt(t)})"
    got, err = read_points(answer, "your point", ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} should be one point [x, y]; yours has shape {got.shape}.")
    expected = bezier.neville(P, t, nodes=nodes)
    dist = float(np.linalg.norm(got - expected))
    if dist <= 1e-4:
        return correct(f"{what} = {fmt(expected)}, on the parabola through the three points.")
    if np.linalg.norm(got - bezier.de_casteljau(P, t)) <= 1e-4:
        return wrong("that is the point of the Bezier curve of the three points (de Casteljau's weights 1 - t and t): "
                     "it approximates the points, it does not pass through the middle one. Neville's weights are "
                     "(t_(i+r) - t) / (t_(i+r) - t_i) and (t - t_i) / (t_(i+r) - t_i), with each node's own interval.")
    for i in range(2):
        if np.linalg.norm(got - _level1(p, i)) <= 1e-4:
            return wrong(f"that is a point of the first level of the pyramid (the line through P{i} and P{i + 1}); "
                         "a quadratic needs a second level, which combines the two first-level points over the nodes' "
                         "whole interval.")
    if np.any(np.linalg.norm(P - got, axis=1) <= 1e-4):
        return wrong(f"that is one of the data points; the curve passes through them at their nodes, and {fmt(t)} is "
                     "not one of the nodes.")
    return wrong(f"your point is {far_off(got, expected)} from {what}; each level of Neville's pyramid is an affine combination "
                 "weighted by distances to the nodes, and extrapolation (a weight below 0) is allowed.")


#: Deal another instance of an exercise (``deal("check_hodograph")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


SLIPS = {
    "check_de_casteljau_point": [[9.0, 4.5], [2.0, 3.5], [6.0, 4.0], [5.0, 8.0]],
    "check_bernstein_weights": [[0.4096, 0.1024, 0.0256, 0.0064, 0.0016],
                                [0.0016, 0.0256, 0.1536, 0.4096, 0.4096], [0.4, 0.4, 0.15, 0.03]],
    "check_end_conditions": [[[1, 1], [7, 4], [4, 7], [7, 1]], [[1, 1], [3, 2], [8, -1], [7, 1]],
                             [[0, 0], [3, 2], [6, 3], [7, 1]]],
    "check_hodograph": [[[1, 3], [3, 1], [1, -3]], [[-3, -9], [-9, -3], [-3, 9]], [[3, 9], [9, 3]]],
    "check_degree_elevation": [[[0, 0], [2, 1], [4, 7], [3, 9]], [[0, 0], [6, 3], [3, 9]],
                               [[0, 0], [4, 2], [5, 5], [3, 8]]],
    "check_c1_join_unequal": [[[6, 3], [8, 2]], [[6, 3], [7, 2.5]], [[6, 3], [2, 5]], [[6, 4], [10, 1]],
                              [[6, 3], [12, 0]]],
    "check_patch_point": [[2, 1, 1.8125], [1, 2, 0.5], [2, 2, 16 / 9]],
    "check_neville_point": [[2, 1.5], [2, 2], [2, 6], [4, 4], [2, 1]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

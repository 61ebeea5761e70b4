"""Exercise checkers for chapter 26, blossoming (Goldman §26.2-26.4).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0
is the module constants below, which the stored notebook shows; ``deal("check_...")`` (or the button
beside the exercise) deals another, and the checker, ``PROBLEMS`` and ``steps("check_...")`` follow the
current instance.  The chapter's "show that" exercises (in :mod:`goldman_lib.exercises.proofs`) ask for
an identity, not a number, so they do not deal.  ``SLIPS`` holds the wrong answers of the kinds each
checker recognises, for the stored instance.  The data differ from the chapter's worked examples (its
cubic (0, 0), (1, 2.5), (3, 2.5), (4, 0.5) and the polynomial 1 + 3t - 3t^2 + 2t^3) and from the
exercises of chapters 24 and 25.

>>> print(PROBLEMS["check_polar_form"])
The cubic polynomial P(t) = 2t^3 + 3t^2 - 6t + 1 has a blossom p(u1, u2, u3) of degree 3. Write it down from the blossoms of the monomials and give the value p(1, 2, 3) (Goldman §26.2).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import blossom as bl
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import (Result, check_points, correct, fmt, fmt_points, off_by, read_number, read_points,
                                   wrong)
from goldman_lib.exercises.deal import Deck, integers as _ints, plain as _tup, steps_number as _f, within

__all__ = ["PROBLEMS", "SLIPS", "POLAR_COEFFS", "POLAR_ARGS", "BLOSSOM_CTRL", "BLOSSOM_ARGS", "INTERVAL_CTRL",
           "INTERVAL", "SECOND_CTRL", "SECOND_T", "MONOMIAL_COEFFS", "BEZIER_COEFFS",
           "check_polar_form", "check_blossom_value", "check_interval_points", "check_second_derivative",
           "check_monomial_to_bezier", "check_bezier_to_monomial", "DECK", "deal", "steps", "current", "deal_button"]

#: Exercise 1 (§26.2): the scalar cubic 1 - 6t + 3t^2 + 2t^3 (lowest degree first) and the arguments.
POLAR_COEFFS = np.array([1.0, -6.0, 3.0, 2.0])
POLAR_ARGS = (1.0, 2.0, 3.0)
#: Exercise 2 (§26.2): a cubic Bezier curve and blossom arguments, one of them outside [0, 1].
BLOSSOM_CTRL = np.array([[0.0, 0.0], [2.0, 6.0], [6.0, 6.0], [8.0, 0.0]])
BLOSSOM_ARGS = (0.5, 0.5, 2.0)
#: Exercise 3 (§26.3): a quadratic and the interval [a, b] (reaching outside [0, 1]).
INTERVAL_CTRL = np.array([[0.0, 2.0], [2.0, 0.0], [4.0, 4.0]])
INTERVAL = (-1.0, 1.0)
#: Exercise 4 (§26.4): the cubic whose second derivative at SECOND_T is asked for.
SECOND_CTRL = np.array([[0.0, 0.0], [1.0, 3.0], [4.0, 4.0], [6.0, 0.0]])
SECOND_T = 0.25
#: Exercise 5 (§26.4): the scalar cubic 2 - 3t + 6t^2 + t^3, lowest degree first.
MONOMIAL_COEFFS = np.array([2.0, -3.0, 6.0, 1.0])
#: Exercise 6 (§26.4): the Bezier coefficients of a scalar cubic.
BEZIER_COEFFS = np.array([1.0, 0.0, 0.0, 2.0])


def _poly_text(a, ascending: bool = False) -> str:
    """'2t^3 + 3t^2 - 6t + 1' from the coefficients a_0..a_n (or '1 - 6t + ...' if ascending)."""
    order = range(len(a)) if ascending else range(len(a) - 1, -1, -1)
    terms = []
    for j in order:
        c = float(a[j])
        if c == 0:
            continue
        mag = abs(c)
        body = ("" if mag == 1 and j else fmt(mag)) + ("t" if j else "") + (f"^{j}" if j > 1 else "")
        terms.append(("-" if c < 0 else "+", body))
    text = ("-" if terms[0][0] == "-" else "") + terms[0][1]
    return text + "".join(f" {s} {b}" for s, b in terms[1:])


def _args_text(u) -> str:
    return "(" + ", ".join(fmt(x) for x in u) + ")"


DECK = Deck("ch26")


def _arr(x):
    return np.asarray(x, dtype=float)


def _apart(forms, tol=1e-3) -> bool:
    """Whether the forms a checker recognises are pairwise apart by more than ``tol`` in some
    coordinate (forms of different shapes are apart), so that each gets its own message."""
    forms = [_arr(f) for f in forms]
    return not any(u.shape == v.shape and np.all(np.abs(u - v) <= tol)
                   for i, u in enumerate(forms) for v in forms[i + 1:])


def _m(x) -> str:
    """A factor of a product in the worked steps: negative numbers in parentheses."""
    text = _f(x)
    return f"({text})" if text.startswith("-") else text


def _signed(c) -> str:
    """' + 3' or ' - 6': a coefficient after the first term."""
    return f" - {fmt(-c)}" if c < 0 else f" + {fmt(c)}"


_SAME = within(1e-3)


def _scalar_blossom(coeffs, args) -> float:
    """The blossom of the scalar polynomial with monomial ``coeffs`` at ``args`` (library calls only)."""
    ctrl = bl.monomial_to_bezier(coeffs)[:, None]
    return float(bl.blossom(ctrl, list(args))[0])


def _whole_cubic(rng):
    """Monomial coefficients a_0..a_3 with a_1 and a_2 multiples of 3 (so that the C(3, j) divide out)
    and a_3 not 0."""
    a3 = int(rng.choice([-2, -1, 1, 2, 3]))
    return (float(rng.integers(-4, 5)), float(3 * rng.integers(-2, 3)), float(3 * rng.integers(-2, 3)), float(a3))


# -- §26.2: the blossom of a polynomial --------------------------------------------------------------------

_STORED_POLAR = {"a": _tup(POLAR_COEFFS), "u": _tup(POLAR_ARGS)}


def _polar_forms(p):
    a, u = _arr(p["a"]), _arr(p["u"])
    e1, e2, e3 = u.sum(), u[0] * u[1] + u[0] * u[2] + u[1] * u[2], u.prod()
    return {"the average": float(np.polynomial.Polynomial(a)(u.mean())),
            "no division by C(3, j)": float(a[0] + a[1] * e1 + a[2] * e2 + a[3] * e3),
            "not symmetric": float(a[0] + a[1] * u[0] + a[2] * u[0] * u[1] + a[3] * e3)}


def _polar_answer(p):
    return _scalar_blossom(_arr(p["a"]), _arr(p["u"]))


def _polar_generate(rng) -> dict:
    return {"a": _whole_cubic(rng), "u": _tup(rng.choice([-1, 1, 2, 3, 4], size=3, replace=False))}


def _polar_statement(p) -> str:
    return (f"The cubic polynomial P(t) = {_poly_text(p['a'])} has a blossom p(u1, u2, u3) of degree 3. Write it "
            f"down from the blossoms of the monomials and give the value p{_args_text(p['u'])} (Goldman §26.2).")


def _polar_steps(p) -> str:
    a, u = _arr(p["a"]), _arr(p["u"])
    e1, e2, e3 = u.sum(), u[0] * u[1] + u[0] * u[2] + u[1] * u[2], u.prod()
    return (f"1. Blossoms of the monomials in degree 3: t^3 -> u1u2u3, t^2 -> (u1u2 + u1u3 + u2u3)/3, "
            f"t -> (u1 + u2 + u3)/3, 1 -> 1.\n"
            f"2. At {_args_text(u)}: u1u2u3 = {fmt(e3)}, (u1u2 + u1u3 + u2u3)/3 = {_f(e2 / 3)}, (u1 + u2 + u3)/3 = "
            f"{_f(e1 / 3)}.\n"
            f"3. p = {fmt(a[3])}·{_m(e3)}{_signed(a[2])}·{_m(e2 / 3)}{_signed(a[1])}·{_m(e1 / 3)}{_signed(a[0])} = "
            f"{_f(_polar_answer(p))}.")


@DECK.exercise(stored=_STORED_POLAR, generate=_polar_generate, answer=_polar_answer, slips=_polar_forms,
               statement=_polar_statement, steps=_polar_steps, same=_SAME)
def check_polar_form(answer, p) -> Result:
    """Check the blossom of the statement's polynomial at its arguments (Goldman §26.2).

    Recognises the curve at the average of the arguments (not multiaffine), the elementary
    symmetric functions without the division by C(3, j), and the non-symmetric guess t^2 -> u1 u2,
    t -> u1 (the first arguments only).

    >>> check_polar_form(17)
    Not yet: that is P at the average of the arguments; the blossom is not a function of the average (that would not be affine in each argument). Replace t^3 by u1u2u3, t^2 by (u1u2 + u1u3 + u2u3)/3 and t by (u1 + u2 + u3)/3.
    """
    a, u = _arr(p["a"]), _arr(p["u"])
    value, err = read_number(answer, "the blossom value")
    if err is not None:
        return err
    expected = _scalar_blossom(a, u)
    if abs(value - expected) <= 1e-6:
        return correct(f"p{_args_text(u)} = {fmt(expected)}: {fmt(a[3])} u1u2u3{_signed(a[2])} (u1u2 + u1u3 + u2u3)/3"
                       f"{_signed(a[1])} (u1 + u2 + u3)/3{_signed(a[0])}.")
    forms = _polar_forms(p)
    if abs(value - forms["the average"]) <= 1e-6:
        return wrong("that is P at the average of the arguments; the blossom is not a function of the average (that "
                     "would not be affine in each argument). Replace t^3 by u1u2u3, t^2 by (u1u2 + u1u3 + u2u3)/3 and "
                     "t by (u1 + u2 + u3)/3.")
    if abs(value - forms["no division by C(3, j)"]) <= 1e-6:
        return wrong("you used the elementary symmetric functions without dividing by C(3, j): the blossom of t^2 in "
                     "degree 3 is (u1u2 + u1u3 + u2u3)/3 and that of t is (u1 + u2 + u3)/3, so that the diagonal "
                     "gives t^2 and t back.")
    if abs(value - forms["not symmetric"]) <= 1e-6:
        return wrong("replacing t^2 by u1u2 and t by u1 is not symmetric: the blossom must not change when the "
                     "arguments are exchanged, so average over all the ways to pick them.")
    return wrong(f"the value is {off_by(value, expected)}. The blossom of t^j in degree 3 is the sum of the products of "
                 f"j of the arguments divided by C(3, j).")


# -- §26.2: a blossom value of a Bezier curve ----------------------------------------------------------------

_STORED_BLOSSOM = {"ctrl": _tup(BLOSSOM_CTRL), "u": _tup(BLOSSOM_ARGS)}


def _blossom_answer(p):
    return bl.blossom(_arr(p["ctrl"]), _arr(p["u"]))


def _blossom_slips(p):
    P, u = _arr(p["ctrl"]), _arr(p["u"])
    return {"the average": bl.blossom(P, [u.mean()] * 3), "the curve at u1": bl.blossom(P, [u[0]] * 3),
            "weights exchanged": bl.blossom(P, 1 - u), "level 2": bl.blossom_steps(P, u)[2][0]}


def _blossom_generate(rng) -> dict:
    u = list(rng.choice([0.0, 0.5, 1.0], size=2)) + [float(rng.choice([-1.0, -0.5, 1.5, 2.0]))]
    return {"ctrl": _ints(rng, 0, 8, (4, 2)), "u": _tup(rng.permutation(u))}


def _blossom_ok(p):
    P, u = _arr(p["ctrl"]), _arr(p["u"])
    slips = _blossom_slips(p)
    del slips["level 2"]                       # one of the two points of level 2, added below
    forms = [_blossom_answer(p)] + list(slips.values()) + list(bl.blossom_steps(P, u)[2])
    if not _apart(forms):
        return "two points the checker recognises coincide (both points of level 2 included)"
    return None


def _blossom_statement(p) -> str:
    return (f"Compute the blossom value p{_args_text(p['u'])} of the cubic Bezier curve with control points "
            f"{fmt_points(_arr(p['ctrl']))} by the de Casteljau algorithm with a different parameter at each level, "
            f"(1 - u_r) P_j + u_r P_(j+1); give it as [x, y] (Goldman §26.2).")


def _blossom_steps(p) -> str:
    P, u = _arr(p["ctrl"]), _arr(p["u"])
    levels = bl.blossom_steps(P, u)
    return "\n".join(f"{r}. Level {r}, u{r} = {fmt(u[r - 1])}: " + ", ".join(_f(q) for q in levels[r])
                     for r in range(1, 4)) + f"\n\nThe apex is p{_args_text(u)} = {_f(levels[3][0])}."


@DECK.exercise(stored=_STORED_BLOSSOM, generate=_blossom_generate, answer=_blossom_answer, slips=_blossom_slips,
               statement=_blossom_statement, steps=_blossom_steps, same=_SAME, well_posed=_blossom_ok)
def check_blossom_value(answer, p) -> Result:
    """Check the blossom value of the statement's cubic at its arguments (Goldman §26.2).

    Recognises the curve at the average of the arguments, the curve at the in-range parameter,
    the weights exchanged (u_r P_j + (1 - u_r) P_(j+1)) and a stop one level early.
    """
    u = _arr(p["u"])
    P = _arr(p["ctrl"])
    got, err = read_points(answer, "your point", ask=f"p{_args_text(u)} as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"the blossom of a plane curve is one point [x, y]; your answer has shape {got.shape}.")
    expected = bl.blossom(P, u)
    if np.linalg.norm(got - expected) <= 1e-6:
        return correct(f"p{_args_text(u)} = {fmt(expected)}; the order of the arguments does not matter (symmetry).")
    if np.linalg.norm(got - bl.blossom(P, [u.mean()] * 3)) <= 1e-6:
        return wrong("that is the curve at the average of the arguments; the blossom is not a function of the "
                     "average: use a different parameter at each level.")
    if np.linalg.norm(got - bl.blossom(P, [u[0]] * 3)) <= 1e-6:
        return wrong("that is the curve point P(u1): each level must use its own parameter, u1, u2, then u3.")
    if np.linalg.norm(got - bl.blossom(P, 1 - u)) <= 1e-6:
        if u[2] == 2:
            return wrong(f"the weights are exchanged: level r is (1 - u_r) P_j + u_r P_(j+1), so u_r = {fmt(u[2])} goes "
                         f"twice as far as P_(j+1) from P_j, past it.")
        return wrong("the weights are exchanged: level r is (1 - u_r) P_j + u_r P_(j+1), so u_r is the fraction of the "
                     "way from P_j towards P_(j+1), and an argument outside [0, 1] lands beyond P_(j+1) or behind P_j.")
    two = bl.blossom_steps(P, u)[2]
    if np.any(np.linalg.norm(two - got, axis=1) <= 1e-6):
        return wrong("that is a point of level 2 of the pyramid; a cubic's blossom has three arguments and three "
                     "levels.")
    return wrong(f"your point is {far_off(got, expected)} from p{_args_text(u)}; run the three "
                 f"levels with u1, u2, u3 (the argument outside [0, 1] extrapolates).")


# -- §26.3: control points over an interval -----------------------------------------------------------------

_STORED_INTERVAL = {"ctrl": _tup(INTERVAL_CTRL), "ab": _tup(INTERVAL)}


def _interval_answer(p):
    a, b = p["ab"]
    return bl.control_points_on_interval(_arr(p["ctrl"]), a, b)


def _interval_slips(p):
    a, b = p["ab"]
    return {"points on the curve": bl.blossom(_arr(p["ctrl"]), [[a, a], [(a + b) / 2] * 2, [b, b]]),
            "reversed": _interval_answer(p)[::-1]}


def _interval_generate(rng) -> dict:
    a, b = sorted(rng.choice([-2.0, -1.0, 0.0, 1.0, 2.0], size=2, replace=False))
    return {"ctrl": _ints(rng, -2, 6, (3, 2)), "ab": (float(a), float(b))}


def _interval_ok(p):
    if tuple(p["ab"]) == (0.0, 1.0):
        return "[0, 1] gives the control points back"
    if not _apart([_interval_answer(p)] + list(_interval_slips(p).values())):
        return "two recognised answers coincide"
    return None


def _interval_statement(p) -> str:
    a, b = p["ab"]
    return (f"Give the control points of the quadratic with control points {fmt_points(_arr(p['ctrl']))} over the "
            f"interval [{fmt(a)}, {fmt(b)}], i.e. the blossom values p(a, a), p(a, b), p(b, b) (Goldman §26.3).")


def _interval_steps(p) -> str:
    a, b = p["ab"]
    P = _arr(p["ctrl"])
    Q = _interval_answer(p)
    rows = [f"{k + 1}. p({', '.join(fmt(x) for x in args)}): levels "
            + "; ".join(", ".join(_f(q) for q in lev) for lev in bl.blossom_steps(P, args)[1:]) + f" -> {_f(Q[k])}"
            for k, args in enumerate(([a, a], [a, b], [b, b]))]
    return "Run the two levels of de Casteljau with the arguments of each blossom value:\n" + "\n".join(rows)


@DECK.exercise(stored=_STORED_INTERVAL, generate=_interval_generate, answer=_interval_answer, slips=_interval_slips,
               statement=_interval_statement, steps=_interval_steps, same=_SAME, well_posed=_interval_ok)
def check_interval_points(answer, p) -> Result:
    """Check the control points of the statement's quadratic over its interval [a, b] (Goldman §26.3).

    answer: (3, 2).  Recognises the curve points P(a), P((a+b)/2), P(b) (points on the curve,
    not blossom values), the points in reverse order and a wrong number of points.
    """
    a, b = p["ab"]
    P = _arr(p["ctrl"])
    what = "the control points"
    got, err = read_points(answer, what, ask="the three control points as [[x0, y0], [x1, y1], [x2, y2]]")
    if err is not None:
        return err
    expected = bl.control_points_on_interval(P, a, b)
    if got.shape != expected.shape:
        return wrong(f"{what} should be three points [x, y] (the piece of a quadratic is a quadratic); your answer "
                     f"has shape {got.shape}.")
    if np.allclose(got, expected, atol=1e-6):
        return correct(f"the control points over [{fmt(a)}, {fmt(b)}] are p(a, a), p(a, b), p(b, b).")
    curve = bl.blossom(P, [[a, a], [(a + b) / 2] * 2, [b, b]])
    if np.allclose(got, curve, atol=1e-6):
        return wrong("these are points ON the curve, P(a), P((a+b)/2), P(b); the middle control point is the blossom "
                     "value p(a, b), which in general lies off the curve.")
    if np.allclose(got, expected[::-1], atol=1e-6):
        return wrong("the points are in reverse order: the curve over [a, b] starts at P(a) = p(a, a).")
    return check_points(got, expected, what=what, hint="Q_k = p(a^(2-k), b^k): run the two levels with a and b")


# -- §26.4: the second derivative by the homogeneous blossom --------------------------------------------------

_STORED_SECOND = {"ctrl": _tup(SECOND_CTRL), "t": SECOND_T}


def _second_answer(p):
    return bl.derivative_by_blossom(_arr(p["ctrl"]), p["t"], 2)


def _second_slips(p):
    P, t = _arr(p["ctrl"]), p["t"]
    D = _second_answer(p)
    return {"no factor n(n-1)": D / 6, "factor n only": D / 2, "the first derivative": bl.derivative_by_blossom(P, t, 1),
            "the point": bl.blossom(P, [t] * 3)}


def _second_generate(rng) -> dict:
    return {"ctrl": _ints(rng, -2, 8, (4, 2)), "t": float(rng.choice([0.25, 0.5, 0.75]))}


def _second_ok(p):
    if np.linalg.norm(_second_answer(p)) < 1:
        return "the second derivative nearly vanishes"
    return None


def _second_statement(p) -> str:
    t = p["t"]
    return (f"Use the homogeneous blossom to compute the second derivative P''({fmt(t)}) of the cubic with control "
            f"points {fmt_points(_arr(p['ctrl']))}: P''(t) = n(n-1) p((t, 1), delta, delta) with delta = (1, 0); give "
            f"it as [x, y] (Goldman §26.4).")


def _second_steps(p) -> str:
    P, t = _arr(p["ctrl"]), p["t"]
    d1 = np.diff(P, axis=0)
    d2 = np.diff(d1, axis=0)
    D = _second_answer(p)
    return (f"1. Two levels with delta = (1, 0) take differences: {', '.join(_f(d) for d in d1)}, then "
            f"{', '.join(_f(d) for d in d2)}.\n"
            f"2. One level at t = {fmt(t)}: p((t, 1), delta, delta) = {_f(D / 6)}.\n"
            f"3. Times n(n-1) = 6: P''({fmt(t)}) = {_f(D)}.")


@DECK.exercise(stored=_STORED_SECOND, generate=_second_generate, answer=_second_answer, slips=_second_slips,
               statement=_second_statement, steps=_second_steps, same=_SAME, well_posed=_second_ok)
def check_second_derivative(answer, p) -> Result:
    """Check P''(t) of the statement's cubic by the homogeneous blossom (Goldman §26.4).

    Recognises the blossom value without the factor n(n-1), with only the factor n, the first
    derivative instead of the second, and the point P(t).

    >>> check_second_derivative([1.25, -2.75])
    Not yet: that is p((t, 1), delta, delta) itself; the second derivative is n(n-1) = 6 times it.
    """
    t, P = p["t"], _arr(p["ctrl"])
    n = len(P) - 1
    got, err = read_points(answer, "your vector", ask=f"P''({fmt(t)}) as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"P''(t) of a plane curve is one vector [x, y]; your answer has shape {got.shape}.")
    expected = bl.derivative_by_blossom(P, t, 2)
    if np.linalg.norm(got - expected) <= 1e-6:
        return correct(f"P''({fmt(t)}) = {n * (n - 1)} p(({fmt(t)}, 1), delta, delta) = {fmt(expected)}.")
    ff = n * (n - 1)
    if np.linalg.norm(got - expected / ff) <= 1e-6:
        return wrong(f"that is p((t, 1), delta, delta) itself; the second derivative is n(n-1) = {ff} times it.")
    if np.linalg.norm(got - expected / ff * n) <= 1e-6:
        return wrong(f"you multiplied by n = {n}; each of the two deltas brings a factor, n(n-1) = {ff} in all.")
    if np.linalg.norm(got - bl.derivative_by_blossom(P, t, 1)) <= 1e-6:
        return wrong("that is the first derivative n p((t,1), (t,1), delta); the second puts delta into two of the "
                     "three slots.")
    if np.linalg.norm(got - bl.blossom(P, [t] * n)) <= 1e-6:
        return wrong("that is the point P(t) = p((t,1), (t,1), (t,1)); the second derivative puts delta = (1, 0) into "
                     "two slots.")
    return wrong(f"your vector is {far_off(got, expected)} from P''(t). With delta at two "
                 f"levels, take second differences of the control points, then one level at t, then the factor n(n-1).")


# -- §26.4: monomial to Bezier form --------------------------------------------------------------------------

_STORED_M2B = {"a": _tup(MONOMIAL_COEFFS)}


def _undivided(a):
    return np.array([sum(math.comb(k, j) * a[j] for j in range(k + 1)) for k in range(len(a))])


def _m2b_answer(p):
    return bl.monomial_to_bezier(_arr(p["a"]))


def _m2b_slips(p):
    a = _arr(p["a"])
    return {"the monomial coefficients": a, "no division by C(n, j)": _undivided(a)}


def _m2b_statement(p) -> str:
    return (f"Give the Bezier coefficients (control values) P0, P1, P2, P3 of the cubic polynomial "
            f"{_poly_text(p['a'])} over [0, 1] (Goldman §26.4).")


def _m2b_steps(p) -> str:
    a = _arr(p["a"])
    Q = _m2b_answer(p)
    rows = [f"- P{k} = " + " + ".join(f"C({k}, {j})/C(3, {j})·{_m(a[j])}" for j in range(k + 1)) + f" = {_f(Q[k])}"
            for k in range(4)]
    return ("P_k is the blossom value p(0^(3-k), 1^k): the blossom of t^j there is C(k, j)/C(3, j), so "
            "P_k = sum_(j<=k) C(k, j)/C(3, j) a_j:\n\n" + "\n".join(rows))


@DECK.exercise(stored=_STORED_M2B, generate=lambda rng: {"a": _whole_cubic(rng)}, answer=_m2b_answer,
               slips=_m2b_slips, statement=_m2b_statement, steps=_m2b_steps, same=_SAME)
def check_monomial_to_bezier(answer, p) -> Result:
    """Check the Bezier coefficients of the statement's cubic (Goldman §26.4).

    Recognises the monomial coefficients themselves, the conversion without dividing by
    C(n, j), and a wrong count.

    >>> check_monomial_to_bezier([2, -1, 2, 12])
    Not yet: you used P_k = sum_j C(k, j) a_j: the blossom of t^j at (0^(n-k), 1^k) is C(k, j)/C(n, j), so divide by C(3, j).
    """
    a = _arr(p["a"])
    n = len(a) - 1
    what = "the Bezier coefficients"
    got, err = read_points(answer, what, ask="the four Bezier coefficients [P0, P1, P2, P3]")
    if err is not None:
        return err
    expected = bl.monomial_to_bezier(a)
    if got.shape != expected.shape:
        return wrong(f"{what} of a cubic are four numbers [P0, P1, P2, P3]; your answer has shape {got.shape}.")
    if np.allclose(got, expected, atol=1e-4):
        return correct(f"P_k = sum_j C(k, j)/C({n}, j) a_j gives {fmt_points(expected[:, None]).replace('(', '').replace(')', '')}.")
    if np.allclose(got, a, atol=1e-4):
        return wrong("these are the monomial coefficients a_j; the Bezier coefficients are the blossom values "
                     "p(0^(n-k), 1^k) of the polynomial.")
    if np.allclose(got, _undivided(a), atol=1e-4):
        return wrong(f"you used P_k = sum_j C(k, j) a_j: the blossom of t^j at (0^(n-k), 1^k) is C(k, j)/C(n, j), so "
                     f"divide by C({n}, j).")
    bad = int(np.flatnonzero(np.abs(got - expected) > 1e-4)[0])
    hint = " (P0 is the value at t = 0 and P3 the value at t = 1.)" if bad in (0, n) else ""
    return wrong(f"P{bad} is {off_by(got[bad], expected[bad])}.{hint} Use P_k = sum_(j<=k) C(k, j)/C({n}, j) a_j.")


# -- §26.4: Bezier to monomial form --------------------------------------------------------------------------

_STORED_B2M = {"b": _tup(BEZIER_COEFFS)}


def _b2m_answer(p):
    return bl.bezier_to_monomial(_arr(p["b"]))


def _b2m_slips(p):
    P = _arr(p["b"])
    return {"forward differences": np.array([np.diff(P, j)[0] for j in range(len(P))]),
            "reversed": _b2m_answer(p)[::-1]}


def _b2m_generate(rng) -> dict:
    return {"b": _ints(rng, -3, 4, 4)}


def _b2m_statement(p) -> str:
    return (f"The cubic polynomial with Bezier coefficients {fmt_points(_arr(p['b']))} is a0 + a1 t + a2 t^2 + a3 t^3. "
            f"Give a0, a1, a2, a3 (Goldman §26.4).")


def _b2m_steps(p) -> str:
    P = _arr(p["b"])
    diffs = [np.diff(P, j) for j in range(4)]
    a = _b2m_answer(p)
    return ("Forward differences of the Bezier coefficients: "
            + "; ".join(f"Delta^{j}: {', '.join(fmt(v) for v in diffs[j])}" for j in range(1, 4)) + ".\n\n"
            + "\n".join(f"- a{j} = C(3, {j}) Delta^{j} P_0 = {math.comb(3, j)}·{_m(diffs[j][0])} = {fmt(a[j])}"
                        for j in range(4)))


@DECK.exercise(stored=_STORED_B2M, generate=_b2m_generate, answer=_b2m_answer, slips=_b2m_slips,
               statement=_b2m_statement, steps=_b2m_steps, same=_SAME)
def check_bezier_to_monomial(answer, p) -> Result:
    """Check the monomial coefficients of the cubic with the statement's Bezier coefficients (Goldman §26.4).

    Recognises the forward differences without the binomial factor C(n, j), the coefficients
    highest degree first, and a wrong count.

    >>> check_bezier_to_monomial([1, -1, 1, 1])
    Not yet: these are the forward differences Delta^j P_0 alone; a_j = P^(j)(0)/j! = C(n, j) Delta^j P_0 also has the binomial factor.
    """
    P = _arr(p["b"])
    n = len(P) - 1
    what = "the monomial coefficients"
    got, err = read_points(answer, what, ask="the four coefficients [a0, a1, a2, a3]")
    if err is not None:
        return err
    expected = bl.bezier_to_monomial(P)
    if got.shape != expected.shape:
        return wrong(f"{what} of a cubic are four numbers [a0, a1, a2, a3]; your answer has shape {got.shape}.")
    if np.allclose(got, expected, atol=1e-4):
        return correct(f"a_j = C({n}, j) Delta^j P_0 gives {_poly_text(expected, ascending=True)}.")
    diffs = np.array([np.diff(P, j)[0] for j in range(n + 1)])
    if np.allclose(got, diffs, atol=1e-4):
        return wrong("these are the forward differences Delta^j P_0 alone; a_j = P^(j)(0)/j! = C(n, j) Delta^j P_0 "
                     "also has the binomial factor.")
    if np.allclose(got, expected[::-1], atol=1e-4):
        return wrong("the coefficients are in reverse order: give a0 (the constant term) first, as in a0 + a1 t + ...")
    bad = int(np.flatnonzero(np.abs(got - expected) > 1e-4)[0])
    return wrong(f"a{bad} is {off_by(got[bad], expected[bad])}. Use a_j = C({n}, j) Delta^j P_0, the j-th forward "
                 f"difference of the Bezier coefficients at the start.")


#: Deal another instance of an exercise (``deal("check_polar_form")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


SLIPS = {
    "check_polar_form": [17.0, 10.0, 13.0],
    "check_blossom_value": [[8.0, 0.0], [4.0, 4.5], [-0.5, 4.5], [2.5, 4.5]],
    "check_interval_points": [[[-4, 12], [0, 2], [4, 4]], [[4, 4], [0, -4], [-4, 12]], [[-4, 12], [4, 4]]],
    "check_second_derivative": [[1.25, -2.75], [3.75, -8.25]],
    "check_monomial_to_bezier": [[2, -3, 6, 1], [2, -1, 2, 12]],
    "check_bezier_to_monomial": [[1, -1, 1, 1], [1, 3, -3, 1]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

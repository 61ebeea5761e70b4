"""Exercise checkers for chapter 26, blossoming (Goldman §26.2-26.4).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name.

>>> print(PROBLEMS["check_derivative"])
Use the homogeneous blossom to compute the derivative P'(0.5) of the cubic with control points (0, 0), (1, 3), (3, 3), (4, 0): P'(t) = n p(t, t, delta) with delta = (1, 0) (Goldman §26.4).
>>> check_derivative([4.5, 0])
Correct: P'(0.5) = 3 p(0.5, 0.5, delta) = (4.5, 0).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import bezier
from goldman_lib import blossom as bl
from goldman_lib.exercises import fmt_points, Result, check_points, correct, fmt, read_points, wrong

__all__ = ["PROBLEMS", "BLOSSOM_CTRL", "BLOSSOM_ARGS", "MONOMIAL_COEFFS", "INTERVAL_CTRL", "INTERVAL",
           "DERIVATIVE_CTRL", "DERIVATIVE_T", "BEZIER_COEFFS", "check_blossom_value", "check_monomial_to_bezier",
           "check_interval_points", "check_derivative", "check_bezier_to_monomial"]

#: Exercise 1: the quadratic and the blossom arguments.
BLOSSOM_CTRL = np.array([[0.0, 0.0], [2.0, 4.0], [4.0, 0.0]])
BLOSSOM_ARGS = (0.25, 0.75)
#: Exercise 2: the scalar cubic 1 + 3t - 3t^2 + 2t^3, lowest degree first.
MONOMIAL_COEFFS = np.array([1.0, 3.0, -3.0, 2.0])
#: Exercise 3: the quadratic and the interval [a, b].
INTERVAL_CTRL = BLOSSOM_CTRL
INTERVAL = (0.5, 1.0)
#: Exercise 4: the cubic and the parameter of the derivative.
DERIVATIVE_CTRL = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0]])
DERIVATIVE_T = 0.5
#: Exercise 5: the Bezier coefficients of a scalar quadratic.
BEZIER_COEFFS = np.array([0.0, 1.0, 3.0])


PROBLEMS = {
    "check_blossom_value": (
        f"Compute the blossom value p{fmt(BLOSSOM_ARGS)} of the quadratic with control points {fmt_points(BLOSSOM_CTRL)} "
        f"by the de Casteljau algorithm with u1 at the first level and u2 at the second (Goldman §26.2)."),
    "check_monomial_to_bezier": (
        "Give the Bezier coefficients (control values) P0, P1, P2, P3 of the cubic polynomial "
        "1 + 3t - 3t^2 + 2t^3 (Goldman §26.4)."),
    "check_interval_points": (
        f"Give the control points of the quadratic with control points {fmt_points(INTERVAL_CTRL)} over the interval "
        f"[{fmt(INTERVAL[0])}, {fmt(INTERVAL[1])}], i.e. p(a, a), p(a, b), p(b, b) (Goldman §26.3)."),
    "check_derivative": (
        f"Use the homogeneous blossom to compute the derivative P'({fmt(DERIVATIVE_T)}) of the cubic with control "
        f"points {fmt_points(DERIVATIVE_CTRL)}: P'(t) = n p(t, t, delta) with delta = (1, 0) (Goldman §26.4)."),
    "check_bezier_to_monomial": (
        f"The quadratic polynomial with Bezier coefficients {fmt_points(BEZIER_COEFFS)} is a0 + a1 t + a2 t^2. "
        f"Give a0, a1, a2 (Goldman §26.4)."),
}


def check_blossom_value(answer) -> Result:
    """Check ``p(BLOSSOM_ARGS)`` of ``BLOSSOM_CTRL`` (Goldman §26.2).

    Recognises the curve point at the average of the arguments and the curve at one argument.

    >>> check_blossom_value([2, 2.5])
    Correct: p(0.25, 0.75) = (2, 2.5); swapping the arguments gives the same point (symmetry).
    >>> check_blossom_value([2, 2])
    Not yet: (2, 2) is the curve at the average 0.5 of the arguments, P(0.5) = p(0.5, 0.5); the blossom is not a function of the average: use u1 = 0.25 at the first level and u2 = 0.75 at the second.
    """
    u = np.array(BLOSSOM_ARGS)
    what = f"p{fmt(u)}"
    got, err = read_points(answer, what, ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} should be one point [x, y]; yours has shape {got.shape}.")
    expected = bl.blossom(BLOSSOM_CTRL, u)
    if np.linalg.norm(got - expected) <= 1e-6:
        return correct(f"{what} = {fmt(expected)}; swapping the arguments gives the same point (symmetry).")
    mean = bezier.de_casteljau(BLOSSOM_CTRL, u.mean())
    if np.linalg.norm(got - mean) <= 1e-6:
        return wrong(f"{fmt(got)} is the curve at the average {fmt(u.mean())} of the arguments, P({fmt(u.mean())}) = "
                     f"p({fmt(u.mean())}, {fmt(u.mean())}); the blossom is not a function of the average: use "
                     f"u1 = {fmt(u[0])} at the first level and u2 = {fmt(u[1])} at the second.")
    for x in u:
        if np.linalg.norm(got - bezier.de_casteljau(BLOSSOM_CTRL, x)) <= 1e-6:
            return wrong(f"{fmt(got)} is the curve point P({fmt(x)}) = p({fmt(x)}, {fmt(x)}): the same parameter at "
                         f"both levels. The blossom uses a different one at each level.")
    return check_points(got, expected, what=what, hint="level 1: (1-u1) P_j + u1 P_(j+1); level 2 the same with u2")


def check_monomial_to_bezier(answer) -> Result:
    """Check the Bezier coefficients of ``1 + 3t - 3t^2 + 2t^3`` (Goldman §26.4).

    Recognises the monomial coefficients copied and their partial sums.

    >>> check_monomial_to_bezier([1, 2, 2, 3])
    Correct: P_k = sum_j C(k, j)/C(3, j) a_j gives (1, 2, 2, 3); P0 = a0 and P3 = a0 + a1 + a2 + a3 are the values at 0 and 1.
    >>> check_monomial_to_bezier([1, 4, 1, 3])
    Not yet: these are partial sums a0 + ... + ak; each a_j must be weighted by C(k, j)/C(n, j), the blossom of t^j at (0, ..., 0, 1, ..., 1).
    """
    what = "the Bezier coefficients"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    a = MONOMIAL_COEFFS
    expected = bl.monomial_to_bezier(a)
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} numbers (a cubic has four); yours has shape {got.shape}.")
    if np.allclose(got, expected, atol=1e-6):
        return correct(f"P_k = sum_j C(k, j)/C(3, j) a_j gives {fmt(expected)}; P0 = a0 and P3 = a0 + a1 + a2 + a3 "
                       f"are the values at 0 and 1.")
    if np.allclose(got, a, atol=1e-6):
        return wrong("these are the monomial coefficients themselves; the Bezier coefficients are blossom values "
                     "p(0, ..., 0, 1, ..., 1) of the polynomial.")
    if np.allclose(got, np.cumsum(a), atol=1e-6):
        return wrong("these are partial sums a0 + ... + ak; each a_j must be weighted by C(k, j)/C(n, j), the blossom "
                     "of t^j at (0, ..., 0, 1, ..., 1).")
    return check_points(got, expected, what=what, hint="P_k = sum over j <= k of C(k, j)/C(n, j) a_j")


def check_interval_points(answer) -> Result:
    """Check the control points of ``INTERVAL_CTRL`` over ``INTERVAL`` (Goldman §26.3).

    Recognises the reversed order and the other half [0, a].

    >>> check_interval_points([[2, 2], [3, 2], [4, 0]])
    Correct: p(0.5, 0.5), p(0.5, 1), p(1, 1) = (2, 2), (3, 2), (4, 0): the right half of the subdivision at 0.5.
    >>> check_interval_points([[4, 0], [3, 2], [2, 2]])
    Not yet: the points are right but reversed: Q_0 = p(a, a) is the curve at a, where the piece starts.
    """
    a, b = INTERVAL
    what = "the control points over the interval"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    expected = bl.control_points_on_interval(INTERVAL_CTRL, a, b)
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points, shape {expected.shape}; yours has shape {got.shape}.")
    if np.allclose(got, expected, atol=1e-6):
        return correct(f"p({fmt(a)}, {fmt(a)}), p({fmt(a)}, {fmt(b)}), p({fmt(b)}, {fmt(b)}) = {fmt_points(expected)}: "
                       f"the right half of the subdivision at {fmt(a)}.")
    if np.allclose(got, expected[::-1], atol=1e-6):
        return wrong("the points are right but reversed: Q_0 = p(a, a) is the curve at a, where the piece starts.")
    other = bl.control_points_on_interval(INTERVAL_CTRL, 0.0, a)
    if np.allclose(got, other, atol=1e-6):
        return wrong(f"these are the control points over [0, {fmt(a)}], p(0, 0), p(0, {fmt(a)}), p({fmt(a)}, {fmt(a)}); "
                     f"the interval asked is [{fmt(a)}, {fmt(b)}].")
    return check_points(got, expected, what=what, hint="Q_k = p(a, ..., a, b, ..., b) with k copies of b")


def check_derivative(answer) -> Result:
    """Check ``P'(DERIVATIVE_T)`` of ``DERIVATIVE_CTRL`` (Goldman §26.4).

    Recognises the blossom value without the factor n.

    >>> check_derivative([1.5, 0])
    Not yet: (1.5, 0) is p(0.5, 0.5, delta) alone; the derivative is n = 3 times it.
    """
    t = DERIVATIVE_T
    n = len(DERIVATIVE_CTRL) - 1
    what = f"P'({fmt(t)})"
    got, err = read_points(answer, what, ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} should be one vector [x, y]; yours has shape {got.shape}.")
    expected = bl.derivative_by_blossom(DERIVATIVE_CTRL, t)
    if np.linalg.norm(got - expected) <= 1e-6:
        return correct(f"{what} = {n} p({fmt(t)}, {fmt(t)}, delta) = {fmt(expected)}.")
    if np.linalg.norm(got - expected / n) <= 1e-6:
        return wrong(f"{fmt(got)} is p({fmt(t)}, {fmt(t)}, delta) alone; the derivative is n = {n} times it.")
    if np.linalg.norm(got - bezier.de_casteljau(DERIVATIVE_CTRL, t)) <= 1e-6:
        return wrong(f"{fmt(got)} is the point P({fmt(t)}); the derivative replaces one argument by delta = (1, 0), "
                     f"whose de Casteljau step is the difference P_(j+1) - P_j.")
    return check_points(got, expected, what=what, hint="the level with delta = (1, 0) takes differences P_(j+1) - P_j")


def check_bezier_to_monomial(answer) -> Result:
    """Check the monomial coefficients of the quadratic with Bezier coefficients ``BEZIER_COEFFS`` (Goldman §26.4).

    Recognises the forward differences without the binomial coefficients.

    >>> check_bezier_to_monomial([0, 2, 1])
    Correct: a_j = C(2, j) Delta^j P_0 gives (0, 2, 1): the polynomial is 2t + t^2.
    >>> check_bezier_to_monomial([0, 1, 1])
    Not yet: these are the differences Delta^j P_0; the coefficients also carry the binomials C(n, j) = 1, 2, 1.
    """
    what = "the monomial coefficients"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P = BEZIER_COEFFS
    n = len(P) - 1
    expected = bl.bezier_to_monomial(P)
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} numbers a0, ..., a{n}; yours has shape {got.shape}.")
    if np.allclose(got, expected, atol=1e-6):
        return correct(f"a_j = C({n}, j) Delta^j P_0 gives {fmt(expected)}: the polynomial is 2t + t^2.")
    diffs = np.array([np.diff(P, j)[0] for j in range(n + 1)])
    if np.allclose(got, diffs, atol=1e-6):
        binoms = ", ".join(str(math.comb(n, j)) for j in range(n + 1))
        return wrong(f"these are the differences Delta^j P_0; the coefficients also carry the binomials "
                     f"C(n, j) = {binoms}.")
    if np.allclose(got, P, atol=1e-6):
        return wrong("these are the Bezier coefficients themselves; expand sum_k P_k C(n, k) t^k (1-t)^(n-k) in powers "
                     "of t.")
    return check_points(got, expected, what=what, hint="a_j = C(n, j) Delta^j P_0, or expand the Bernstein form")

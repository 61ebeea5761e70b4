"""Exercise checkers for chapter 26, blossoming (Goldman §26.2-26.4).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers of the kinds each checker recognises.  The data differ from the
chapter's worked examples (its cubic (0, 0), (1, 2.5), (3, 2.5), (4, 0.5) and the polynomial
1 + 3t - 3t^2 + 2t^3) and from the exercises of chapters 24 and 25.

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

__all__ = ["PROBLEMS", "SLIPS", "POLAR_COEFFS", "POLAR_ARGS", "BLOSSOM_CTRL", "BLOSSOM_ARGS", "INTERVAL_CTRL",
           "INTERVAL", "SECOND_CTRL", "SECOND_T", "MONOMIAL_COEFFS", "BEZIER_COEFFS",
           "check_polar_form", "check_blossom_value", "check_interval_points", "check_second_derivative",
           "check_monomial_to_bezier", "check_bezier_to_monomial"]

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


PROBLEMS = {
    "check_polar_form": (
        f"The cubic polynomial P(t) = {_poly_text(POLAR_COEFFS)} has a blossom p(u1, u2, u3) of degree 3. Write it "
        f"down from the blossoms of the monomials and give the value p{_args_text(POLAR_ARGS)} (Goldman §26.2)."),
    "check_blossom_value": (
        f"Compute the blossom value p{_args_text(BLOSSOM_ARGS)} of the cubic Bezier curve with control points "
        f"{fmt_points(BLOSSOM_CTRL)} by the de Casteljau algorithm with a different parameter at each level, "
        f"(1 - u_r) P_j + u_r P_(j+1); give it as [x, y] (Goldman §26.2)."),
    "check_interval_points": (
        f"Give the control points of the quadratic with control points {fmt_points(INTERVAL_CTRL)} over the interval "
        f"[{fmt(INTERVAL[0])}, {fmt(INTERVAL[1])}], i.e. the blossom values p(a, a), p(a, b), p(b, b) "
        f"(Goldman §26.3)."),
    "check_second_derivative": (
        f"Use the homogeneous blossom to compute the second derivative P''({fmt(SECOND_T)}) of the cubic with control "
        f"points {fmt_points(SECOND_CTRL)}: P''(t) = n(n-1) p((t, 1), delta, delta) with delta = (1, 0); give it as "
        f"[x, y] (Goldman §26.4)."),
    "check_monomial_to_bezier": (
        f"Give the Bezier coefficients (control values) P0, P1, P2, P3 of the cubic polynomial "
        f"{_poly_text(MONOMIAL_COEFFS)} over [0, 1] (Goldman §26.4)."),
    "check_bezier_to_monomial": (
        f"The cubic polynomial with Bezier coefficients {fmt_points(BEZIER_COEFFS)} is a0 + a1 t + a2 t^2 + a3 t^3. "
        f"Give a0, a1, a2, a3 (Goldman §26.4)."),
}


def _scalar_blossom(coeffs, args) -> float:
    """The blossom of the scalar polynomial with monomial ``coeffs`` at ``args`` (library calls only)."""
    ctrl = bl.monomial_to_bezier(coeffs)[:, None]
    return float(bl.blossom(ctrl, list(args))[0])


def check_polar_form(answer) -> Result:
    """Check the blossom of the polynomial ``POLAR_COEFFS`` at ``POLAR_ARGS`` (Goldman §26.2).

    Recognises the curve at the average of the arguments (not multiaffine), the elementary
    symmetric functions without the division by C(3, j), and the non-symmetric guess t^2 -> u1 u2,
    t -> u1 (the first arguments only).

    >>> check_polar_form(17)
    Not yet: that is P at the average of the arguments; the blossom is not a function of the average (that would not be affine in each argument). Replace t^3 by u1u2u3, t^2 by (u1u2 + u1u3 + u2u3)/3 and t by (u1 + u2 + u3)/3.
    """
    a, u = POLAR_COEFFS, np.array(POLAR_ARGS)
    value, err = read_number(answer, "the blossom value")
    if err is not None:
        return err
    expected = _scalar_blossom(a, u)
    if abs(value - expected) <= 1e-6:
        return correct(f"p{_args_text(u)} = {fmt(expected)}: {fmt(a[3])} u1u2u3 + {fmt(a[2])} (u1u2 + u1u3 + u2u3)/3 - "
                       f"{fmt(-a[1])} (u1 + u2 + u3)/3 + {fmt(a[0])}.")
    e1, e2, e3 = u.sum(), u[0] * u[1] + u[0] * u[2] + u[1] * u[2], u.prod()
    mean = float(np.polynomial.Polynomial(a)(u.mean()))
    if abs(value - mean) <= 1e-6:
        return wrong("that is P at the average of the arguments; the blossom is not a function of the average (that "
                     "would not be affine in each argument). Replace t^3 by u1u2u3, t^2 by (u1u2 + u1u3 + u2u3)/3 and "
                     "t by (u1 + u2 + u3)/3.")
    if abs(value - (a[0] + a[1] * e1 + a[2] * e2 + a[3] * e3)) <= 1e-6:
        return wrong("you used the elementary symmetric functions without dividing by C(3, j): the blossom of t^2 in "
                     "degree 3 is (u1u2 + u1u3 + u2u3)/3 and that of t is (u1 + u2 + u3)/3, so that the diagonal "
                     "gives t^2 and t back.")
    if abs(value - (a[0] + a[1] * u[0] + a[2] * u[0] * u[1] + a[3] * e3)) <= 1e-6:
        return wrong("replacing t^2 by u1u2 and t by u1 is not symmetric: the blossom must not change when the "
                     "arguments are exchanged, so average over all the ways to pick them.")
    return wrong(f"the value is {off_by(value, expected)}. The blossom of t^j in degree 3 is the sum of the products of "
                 f"j of the arguments divided by C(3, j).")


def check_blossom_value(answer) -> Result:
    """Check ``p(BLOSSOM_ARGS)`` of ``BLOSSOM_CTRL`` (Goldman §26.2).

    Recognises the curve at the average of the arguments, the curve at the in-range parameter,
    the weights exchanged (u_r P_j + (1 - u_r) P_(j+1)) and a stop one level early.
    """
    u = np.array(BLOSSOM_ARGS)
    P = BLOSSOM_CTRL
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
        return wrong(f"the weights are exchanged: level r is (1 - u_r) P_j + u_r P_(j+1), so u_r = {fmt(u[2])} goes "
                     f"twice as far as P_(j+1) from P_j, past it.")
    two = bl.blossom_steps(P, u)[2]
    if np.any(np.linalg.norm(two - got, axis=1) <= 1e-6):
        return wrong("that is a point of level 2 of the pyramid; a cubic's blossom has three arguments and three "
                     "levels.")
    return wrong(f"your point is {far_off(got, expected)} from p{_args_text(u)}; run the three "
                 f"levels with u1, u2, u3 (the argument outside [0, 1] extrapolates).")


def check_interval_points(answer) -> Result:
    """Check the control points of ``INTERVAL_CTRL`` over ``INTERVAL`` (Goldman §26.3).

    answer: (3, 2).  Recognises the curve points P(a), P((a+b)/2), P(b) (points on the curve,
    not blossom values), the points in reverse order and a wrong number of points.
    """
    a, b = INTERVAL
    P = INTERVAL_CTRL
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


def check_second_derivative(answer) -> Result:
    """Check P''(``SECOND_T``) of ``SECOND_CTRL`` by the homogeneous blossom (Goldman §26.4).

    Recognises the blossom value without the factor n(n-1), with only the factor n, the first
    derivative instead of the second, and the point P(t).

    >>> check_second_derivative([1.25, -2.75])
    Not yet: that is p((t, 1), delta, delta) itself; the second derivative is n(n-1) = 6 times it.
    """
    t, P = SECOND_T, SECOND_CTRL
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


def check_monomial_to_bezier(answer) -> Result:
    """Check the Bezier coefficients of the cubic ``MONOMIAL_COEFFS`` (Goldman §26.4).

    Recognises the monomial coefficients themselves, the conversion without dividing by
    C(n, j), and a wrong count.

    >>> check_monomial_to_bezier([2, -1, 2, 12])
    Not yet: you used P_k = sum_j C(k, j) a_j: the blossom of t^j at (0^(n-k), 1^k) is C(k, j)/C(n, j), so divide by C(3, j).
    """
    a = MONOMIAL_COEFFS
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
    k = np.arange(n + 1)
    undivided = np.array([sum(math.comb(int(kk), j) * a[j] for j in range(int(kk) + 1)) for kk in k])
    if np.allclose(got, undivided, atol=1e-4):
        return wrong(f"you used P_k = sum_j C(k, j) a_j: the blossom of t^j at (0^(n-k), 1^k) is C(k, j)/C(n, j), so "
                     f"divide by C({n}, j).")
    bad = int(np.flatnonzero(np.abs(got - expected) > 1e-4)[0])
    hint = " (P0 is the value at t = 0 and P3 the value at t = 1.)" if bad in (0, n) else ""
    return wrong(f"P{bad} is {off_by(got[bad], expected[bad])}.{hint} Use P_k = sum_(j<=k) C(k, j)/C({n}, j) a_j.")


def check_bezier_to_monomial(answer) -> Result:
    """Check the monomial coefficients of the cubic with Bezier coefficients ``BEZIER_COEFFS`` (Goldman §26.4).

    Recognises the forward differences without the binomial factor C(n, j), the coefficients
    highest degree first, and a wrong count.

    >>> check_bezier_to_monomial([1, -1, 1, 1])
    Not yet: these are the forward differences Delta^j P_0 alone; a_j = P^(j)(0)/j! = C(n, j) Delta^j P_0 also has the binomial factor.
    """
    P = BEZIER_COEFFS
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

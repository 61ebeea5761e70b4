"""Exercise checkers for chapter 27, B-spline curves and surfaces (Goldman §27.2-27.9).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name.

>>> print(PROBLEMS["check_continuity"])
A cubic B-spline has the interior knot 0.5 with multiplicity 2. How many times is the curve continuously differentiable there? Give k for C^k (Goldman §27.4).
>>> check_continuity(1)
Correct: a cubic is C^(p - m) = C^(3 - 2) = C^1 at a knot of multiplicity 2.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import bspline
from goldman_lib.exercises import (fmt_points, Result, correct, fmt, read_number, read_points, wrong)

__all__ = ["PROBLEMS", "SPAN_KNOTS", "SPAN_DEGREE", "SPAN_U", "DE_BOOR_CTRL", "DE_BOOR_KNOTS", "DE_BOOR_U",
           "BASIS_K", "BASIS_U", "CONT_DEGREE", "CONT_MULT",
           "check_span_control_points", "check_de_boor_point", "check_basis_value", "check_continuity",
           "check_circle_weight"]

#: Exercise 1: which control points act at u on this quadratic knot vector?
SPAN_KNOTS, SPAN_DEGREE, SPAN_U = np.array([0.0, 0, 0, 1, 2, 3, 3, 3]), 2, 1.5
#: Exercise 2: the quadratic B-spline evaluated by hand with de Boor's algorithm.
DE_BOOR_CTRL = np.array([[0.0, 0.0], [2.0, 4.0], [4.0, 0.0], [6.0, 2.0]])
DE_BOOR_KNOTS = np.array([0.0, 0, 0, 1, 2, 2, 2])
DE_BOOR_U = 1.5
#: Exercise 3: the basis value N_{BASIS_K,2}(BASIS_U) on DE_BOOR_KNOTS.
BASIS_K, BASIS_U = 1, 0.5
#: Exercise 4: continuity of a degree-CONT_DEGREE spline at a knot of multiplicity CONT_MULT.
CONT_DEGREE, CONT_MULT = 3, 2


def _knots(t) -> str:
    return "[" + ", ".join(fmt(x) for x in t) + "]"


PROBLEMS = {
    "check_span_control_points": (
        f"A quadratic B-spline has the knots {_knots(SPAN_KNOTS)}. Which control points (give their indices "
        f"as a list) take part in computing C({fmt(SPAN_U)})? (Goldman §27.2)"),
    "check_de_boor_point": (
        f"Run de Boor's algorithm by hand on the quadratic B-spline with control points {fmt_points(DE_BOOR_CTRL)} "
        f"and knots {_knots(DE_BOOR_KNOTS)} at u = {fmt(DE_BOOR_U)}: give C(u) as (x, y) (Goldman §27.3)."),
    "check_basis_value": (
        f"Compute the quadratic basis function N_{BASIS_K},2({fmt(BASIS_U)}) on the knots "
        f"{_knots(DE_BOOR_KNOTS)} with the recurrence of §27.3."),
    "check_continuity": (
        f"A cubic B-spline has the interior knot 0.5 with multiplicity {CONT_MULT}. How many times is the curve "
        f"continuously differentiable there? Give k for C^k (Goldman §27.4)."),
    "check_circle_weight": (
        "A quarter of the unit circle is a rational quadratic with control points (1, 0), (1, 1), (0, 1) and "
        "weights 1, w, 1. Which w makes it exact? (Goldman §27.9)"),
}


def check_span_control_points(answer) -> Result:
    """Check the indices of the control points acting at ``SPAN_U`` (Goldman §27.2).

    >>> check_span_control_points([1, 2, 3])
    Correct: u = 1.5 lies in the span [t3, t4) = [1, 2), so P1..P3 (p+1 = 3 points) act.
    >>> check_span_control_points([3, 4, 5])
    Not yet: the span index is k = 3 (t3 <= u < t4), but the points are P_(k-p)..P_k = P1..P3, ending at P_k.
    """
    what = "the indices of the control points"
    got, err = read_points(answer, what, ask=what + " as a list, e.g. [0, 1, 2]")
    if err is not None:
        return err
    got = np.sort(got.reshape(-1))
    p = SPAN_DEGREE
    k = bspline.find_span(SPAN_KNOTS, p, SPAN_U)
    expected = np.arange(k - p, k + 1)
    if got.shape == expected.shape and np.array_equal(got, expected):
        return correct(f"u = {fmt(SPAN_U)} lies in the span [t{k}, t{k + 1}) = [{fmt(SPAN_KNOTS[k])}, "
                       f"{fmt(SPAN_KNOTS[k + 1])}), so P{k - p}..P{k} (p+1 = {p + 1} points) act.")
    if got.size != p + 1:
        return wrong(f"a degree-{p} B-spline uses p+1 = {p + 1} control points at each u; you gave {got.size}.")
    if np.array_equal(got, np.arange(k, k + p + 1)):
        return wrong(f"the span index is k = {k} (t{k} <= u < t{k + 1}), but the points are P_(k-p)..P_k = "
                     f"P{k - p}..P{k}, ending at P_k.")
    return wrong(f"find the span first: t{k} = {fmt(SPAN_KNOTS[k])} <= u < t{k + 1} = {fmt(SPAN_KNOTS[k + 1])}; "
                 f"then the p+1 points ending at P_k act.")


def check_de_boor_point(answer) -> Result:
    """Check C(``DE_BOOR_U``) of the quadratic ``DE_BOOR_CTRL`` (Goldman §27.3).

    >>> check_de_boor_point([4.25, 1])
    Correct: C(1.5) = (4.25, 1).
    >>> check_de_boor_point([3.5, 1])
    Not yet: (3.5, 1) is a point of the first level of the pyramid; a quadratic needs 2 levels.
    """
    what = f"C({fmt(DE_BOOR_U)})"
    got, err = read_points(answer, "your point", ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} should be one point [x, y]; yours has shape {got.shape}.")
    steps = bspline.de_boor_steps(DE_BOOR_CTRL, DE_BOOR_KNOTS, 2, DE_BOOR_U)
    expected = steps[-1][0]
    dist = float(np.linalg.norm(got - expected))
    if dist <= 1e-6:
        return correct(f"{what} = {fmt(expected)}.")
    if np.any(np.linalg.norm(steps[1] - got, axis=1) <= 1e-6):
        return wrong(f"{fmt(got)} is a point of the first level of the pyramid; a quadratic needs 2 levels.")
    # the classic slip: Bezier weights (u - a)/(b - a) over the span instead of the knot spans of each node
    k = bspline.find_span(DE_BOOR_KNOTS, 2, DE_BOOR_U)
    s = (DE_BOOR_U - DE_BOOR_KNOTS[k]) / (DE_BOOR_KNOTS[k + 1] - DE_BOOR_KNOTS[k])
    P = DE_BOOR_CTRL[k - 2:k + 1]
    bez = (1 - s) ** 2 * P[0] + 2 * s * (1 - s) * P[1] + s ** 2 * P[2]
    if np.linalg.norm(got - bez) <= 1e-6:
        return wrong("you used de Casteljau's weights (u - t_k)/(t_(k+1) - t_k) on every level; de Boor's weight "
                     "at a node is (u - t_i)/(t_(i+p+1-r) - t_i), with the knots of that node's label.")
    return wrong(f"your point is {fmt(dist, 2)} from C({fmt(DE_BOOR_U)}); on level r the weight is "
                 f"(u - t_i)/(t_(i+p+1-r) - t_i).")


def check_basis_value(answer) -> Result:
    """Check ``N_{BASIS_K,2}(BASIS_U)`` on ``DE_BOOR_KNOTS`` (Goldman §27.3).

    >>> check_basis_value(0.625)
    Correct: N_1,2(0.5) is 0.625.
    >>> check_basis_value(0.5)
    Not yet: 0.5 is the Bernstein value B_1^2(0.5); with knots [0, 0, 0, 1, 2, 2, 2] the B-spline N_1,2 is not a Bernstein polynomial. Use N_k,r = (u - t_k)/(t_(k+r) - t_k) N_k,r-1 + (t_(k+r+1) - u)/(t_(k+r+1) - t_(k+1)) N_k+1,r-1.
    """
    what = f"N_{BASIS_K},2({fmt(BASIS_U)})"
    value, err = read_number(answer, what)
    if err is not None:
        return err
    N = bspline.basis(DE_BOOR_KNOTS, 2, BASIS_U)
    expected = float(N[BASIS_K])
    if abs(value - expected) <= 1e-6:
        return correct(f"{what} is {fmt(expected)}.")
    recurrence = ("Use N_k,r = (u - t_k)/(t_(k+r) - t_k) N_k,r-1 + (t_(k+r+1) - u)/(t_(k+r+1) - t_(k+1)) "
                  "N_k+1,r-1.")
    if abs(value - 2 * BASIS_U * (1 - BASIS_U)) <= 1e-6:
        return wrong(f"{fmt(value)} is the Bernstein value B_1^2({fmt(BASIS_U)}); with knots {_knots(DE_BOOR_KNOTS)} "
                     f"the B-spline N_1,2 is not a Bernstein polynomial. {recurrence}")
    for j, v in enumerate(N):
        if j != BASIS_K and abs(value - v) <= 1e-6:
            return wrong(f"{fmt(value)} is N_{j},2({fmt(BASIS_U)}), a neighbouring basis function; count k from 0. {recurrence}")
    return wrong(f"{what} should be {fmt(expected)}, you gave {fmt(value)}. {recurrence}")


def check_continuity(answer) -> Result:
    """Check the order of continuity at a knot of multiplicity ``CONT_MULT`` (Goldman §27.4).

    >>> check_continuity(2)
    Not yet: C^2 is the continuity at a simple knot of a cubic; each repetition of a knot removes one order: C^(p - m) = C^(3 - 2).
    """
    value, err = read_number(answer, "k (for C^k)")
    if err is not None:
        return err
    p, m = CONT_DEGREE, CONT_MULT
    expected = p - m
    if value == expected:
        return correct(f"a cubic is C^(p - m) = C^({p} - {m}) = C^{expected} at a knot of multiplicity {m}.")
    if value == p - 1:
        return wrong(f"C^{p - 1} is the continuity at a simple knot of a cubic; each repetition of a knot removes "
                     f"one order: C^(p - m) = C^({p} - {m}).")
    if value == p - m - 1:
        return wrong(f"one order too few: the rule is C^(p - m), so multiplicity p + 1 = {p + 1} (not {p}) is "
                     f"where the curve may jump (C^-1).")
    return wrong(f"at a knot of multiplicity m a degree-p B-spline is C^(p - m); here p = {p}, m = {m}.")


def check_circle_weight(answer) -> Result:
    """Check the middle weight of a rational quadratic quarter circle (Goldman §27.9).

    >>> check_circle_weight(math.sqrt(2) / 2)
    Correct: w = cos 45° = sqrt(2)/2 ≈ 0.7071; then every point is at distance 1 from the origin.
    >>> check_circle_weight(1)
    Not yet: with w = 1 the curve is a polynomial quadratic: a parabola, whose midpoint (0.75, 0.75) lies 0.0607 outside the circle.
    """
    value, err = read_number(answer, "the weight w")
    if err is not None:
        return err
    expected = math.sqrt(0.5)
    if abs(value - expected) <= 1e-4:
        return correct("w = cos 45° = sqrt(2)/2 ≈ 0.7071; then every point is at distance 1 from the origin.")
    if value <= 0:
        return wrong("weights must be positive, or the denominator can vanish and the curve leaves the hull.")
    ctrl = np.array([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    mid = bspline.nurbs_curve(ctrl, [1.0, value, 1.0], [0, 0, 0, 1, 1, 1], 2, 0.5)
    gap = float(np.hypot(*mid) - 1)
    if abs(value - 1) <= 1e-9:
        return wrong(f"with w = 1 the curve is a polynomial quadratic: a parabola, whose midpoint {fmt(mid)} lies "
                     f"{fmt(gap, 3)} outside the circle.")
    if abs(value - math.sqrt(2)) <= 1e-4:
        return wrong(f"that is 1/cos 45°; the weight is cos of half the arc's angle, cos 45°. With w = sqrt(2) the "
                     f"midpoint is {fmt(abs(gap), 3)} outside the circle.")
    side = "outside" if gap > 0 else "inside"
    return wrong(f"with w = {fmt(value)} the midpoint C(1/2) = {fmt(mid)} lies {fmt(abs(gap), 3)} {side} the circle; "
                 f"a larger weight pulls the curve towards (1, 1).")

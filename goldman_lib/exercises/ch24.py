"""Exercise checkers for chapter 24, Bezier curves and surfaces (Goldman §24.2-24.5).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name.

>>> print(PROBLEMS["check_bernstein_value"])
Compute the Bernstein basis value B_2^4(0.5) (Goldman §24.3).
>>> check_bernstein_value(6 / 16)
Correct: B_2^4(0.5) is 0.375.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import bezier
from goldman_lib.exercises import (fmt_points, Result, check_number, check_points, correct, fmt, is_unanswered,
                                   read_points, wrong)

__all__ = ["PROBLEMS", "DE_CASTELJAU_CTRL", "DE_CASTELJAU_T", "HODOGRAPH_CTRL", "ELEVATION_CTRL",
           "JOIN_CTRL", "BERNSTEIN_N", "BERNSTEIN_K", "BERNSTEIN_T",
           "check_de_casteljau_point", "check_hodograph", "check_degree_elevation", "check_c1_join",
           "check_bernstein_value"]

#: Exercise 1: the cubic whose point at t = 1/2 is computed by hand with de Casteljau.
DE_CASTELJAU_CTRL = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0]])
DE_CASTELJAU_T = 0.5
#: Exercise 2: the cubic whose hodograph (derivative curve) is asked for.
HODOGRAPH_CTRL = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
#: Exercise 3: the quadratic to elevate to degree 3.
ELEVATION_CTRL = np.array([[0.0, 0.0], [3.0, 3.0], [6.0, 0.0]])
#: Exercise 4: the cubic that a second cubic must continue with C1 continuity (equal parameter
#: intervals); the answer is the second curve's first two control points Q0, Q1.
JOIN_CTRL = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 2.0]])
#: Exercise 5: the Bernstein value B_K^N(T).
BERNSTEIN_N, BERNSTEIN_K, BERNSTEIN_T = 4, 2, 0.5


PROBLEMS = {
    "check_de_casteljau_point": (
        f"Run de Casteljau's algorithm by hand on the cubic with control points {fmt_points(DE_CASTELJAU_CTRL)} "
        f"at t = {fmt(DE_CASTELJAU_T)}: give the point on the curve as (x, y) (Goldman §24.2)."),
    "check_hodograph": (
        f"Give the control points of the hodograph (the derivative curve) of the cubic with control points "
        f"{fmt_points(HODOGRAPH_CTRL)} (Goldman §24.5)."),
    "check_degree_elevation": (
        f"Elevate the quadratic with control points {fmt_points(ELEVATION_CTRL)} to degree 3: give the four new "
        f"control points (Goldman §24.5)."),
    "check_c1_join": (
        f"A second cubic Q continues the cubic with control points {fmt_points(JOIN_CTRL)}, over a parameter interval "
        f"of the same length. Give Q0 and Q1 so that the join is C1 (Goldman §24.5.1)."),
    "check_bernstein_value": (
        f"Compute the Bernstein basis value B_{BERNSTEIN_K}^{BERNSTEIN_N}({fmt(BERNSTEIN_T)}) (Goldman §24.3)."),
}


def check_de_casteljau_point(answer) -> Result:
    """Check the point of the cubic ``DE_CASTELJAU_CTRL`` at ``t = DE_CASTELJAU_T`` (Goldman §24.2).

    answer: (x, y).  Says how far the answer is from the curve point, and recognises a point of an
    intermediate level of the construction (stopped too early) and the centroid of the control
    points (equal weights instead of the Bernstein weights).

    >>> check_de_casteljau_point([2, 2.25])
    Correct: the point at t=0.5 is (2, 2.25).
    >>> check_de_casteljau_point([2, 2.28])
    Not yet: your point is 0.03 from the curve at t=0.5; the curve point is a repeated affine combination (1-t) P_j + t P_{j+1}, three levels deep for a cubic.
    >>> check_de_casteljau_point([1.25, 2.25])
    Not yet: (1.25, 2.25) is a point of level 2 of the construction, not the end: a cubic needs 3 levels of affine combinations.
    """
    what = f"the point at t={fmt(DE_CASTELJAU_T)}"
    got, err = read_points(answer, "your point", ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} should be one point [x, y]; yours has shape {got.shape}.")
    steps = bezier.de_casteljau_steps(DE_CASTELJAU_CTRL, DE_CASTELJAU_T)
    expected = steps[-1][0]
    dist = float(np.linalg.norm(got - expected))
    if dist <= 1e-6:
        return correct(f"{what} is {fmt(expected)}.")
    for level, pts in enumerate(steps[1:-1], start=1):
        if np.any(np.linalg.norm(pts - got, axis=1) <= 1e-6):
            return wrong(f"{fmt(got)} is a point of level {level} of the construction, not the end: "
                         f"a cubic needs {len(steps) - 1} levels of affine combinations.")
    if np.linalg.norm(got - DE_CASTELJAU_CTRL.mean(axis=0)) <= 1e-6:
        return wrong(f"{fmt(got)} is the average of the control points; the curve weights them by "
                     f"the Bernstein values 1/8, 3/8, 3/8, 1/8 at t=1/2, not equally.")
    return wrong(f"your point is {fmt(dist, 2)} from the curve at t={fmt(DE_CASTELJAU_T)}; the curve point "
                 f"is a repeated affine combination (1-t) P_j + t P_{{j+1}}, three levels deep for a cubic.")


def check_hodograph(answer) -> Result:
    """Check the control points of the hodograph of ``HODOGRAPH_CTRL`` (Goldman §24.5).

    answer: (3, 2), the points ``n (P_{k+1} - P_k)``.  Recognises the differences without the
    factor n, and a wrong number of points.

    >>> check_hodograph([[3, 6], [6, 0], [3, -6]])
    Correct: the hodograph's control points match.
    >>> check_hodograph([[1, 2], [2, 0], [1, -2]])
    Not yet: these are the differences P_{k+1} - P_k; the hodograph multiplies them by the degree n = 3.
    """
    what = "the hodograph's control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    n = len(HODOGRAPH_CTRL) - 1
    expected = bezier.hodograph(HODOGRAPH_CTRL)
    if got.shape != expected.shape:
        return wrong(f"{what} should be {n} points of shape {expected.shape}: the derivative of a degree-{n} "
                     f"curve has degree {n - 1}; yours has shape {got.shape}.")
    if np.allclose(got, expected / n, atol=1e-6):
        return wrong(f"these are the differences P_{{k+1}} - P_k; the hodograph multiplies them by the "
                     f"degree n = {n}.")
    return check_points(got, expected, what=what, hint=f"the k-th point is {n} (P_(k+1) - P_k)")


def check_degree_elevation(answer) -> Result:
    """Check the control points of ``ELEVATION_CTRL`` elevated to degree 3 (Goldman §24.5).

    answer: (4, 2).  Recognises the weights swapped between ``P_{k-1}`` and ``P_k`` and a wrong
    number of points.

    >>> check_degree_elevation([[0, 0], [2, 2], [4, 2], [6, 0]])
    Correct: the elevated control points match.
    >>> check_degree_elevation([[0, 0], [1, 1], [5, 1], [6, 0]])
    Not yet: the weights are swapped: Q_k = k/(n+1) P_(k-1) + (1 - k/(n+1)) P_k gives P_(k-1) the weight k/(n+1).
    """
    what = "the elevated control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P = ELEVATION_CTRL
    expected = bezier.elevate_degree(P)
    if got.shape != expected.shape:
        return wrong(f"{what} should be {len(expected)} points (a degree-{len(P)} curve has {len(P) + 1}); "
                     f"yours has shape {got.shape}.")
    n1 = len(P)
    a = (np.arange(1, n1) / n1)[:, None]
    swapped = np.vstack([P[:1], (1 - a) * P[:-1] + a * P[1:], P[-1:]])
    if not np.allclose(swapped, expected) and np.allclose(got, swapped, atol=1e-6):
        return wrong("the weights are swapped: Q_k = k/(n+1) P_(k-1) + (1 - k/(n+1)) P_k gives P_(k-1) "
                     "the weight k/(n+1).")
    return check_points(got, expected, what=what,
                        hint="the end points stay; Q_k = k/(n+1) P_(k-1) + (1 - k/(n+1)) P_k")


def check_c1_join(answer) -> Result:
    """Check Q0, Q1 of a cubic that continues ``JOIN_CTRL`` with C1 continuity (Goldman §24.5.1).

    answer: (2, 2), the points Q0 and Q1.  Explains a gap at the join, a G1-but-not-C1 answer
    (right direction, wrong length) and a tangent pointing the wrong way.

    >>> check_c1_join([[4, 2], [5, 1]])
    Correct: the join is C1: Q0 = P3 and Q1 - Q0 = P3 - P2.
    >>> check_c1_join([[4, 2], [6, 0]])
    Not yet: the tangent direction is right, so the join is G1, but not C1: with equal parameter intervals Q1 - Q0 must equal P3 - P2 = (1, -1), yours is (2, -2).
    """
    what = "Q0 and Q1"
    got, err = read_points(answer, what, ask=what + " as [[x0, y0], [x1, y1]]")
    if err is not None:
        return err
    if got.shape != (2, 2):
        return wrong(f"{what} should be two points, shape (2, 2); yours has shape {got.shape}.")
    P = JOIN_CTRL
    expected = bezier.smooth_join(P, "C1")
    n = len(P) - 1
    if np.linalg.norm(got[0] - expected[0]) > 1e-6:
        return wrong(f"Q0 should be P{n} = {fmt(P[-1])} so that the curves meet (C0); you gave {fmt(got[0])}.")
    want = P[-1] - P[-2]
    leg = got[1] - got[0]
    if np.linalg.norm(leg - want) <= 1e-6:
        return correct(f"the join is C1: Q0 = P{n} and Q1 - Q0 = P{n} - P{n - 1}.")
    cross = want[0] * leg[1] - want[1] * leg[0]
    if abs(cross) <= 1e-6 * max(1.0, np.linalg.norm(leg)) and leg @ want > 0:
        return wrong(f"the tangent direction is right, so the join is G1, but not C1: with equal parameter "
                     f"intervals Q1 - Q0 must equal P{n} - P{n - 1} = {fmt(want)}, yours is {fmt(leg)}.")
    if abs(cross) <= 1e-6 * max(1.0, np.linalg.norm(leg)) and leg @ want < 0:
        return wrong(f"Q1 lies on the tangent line but on the wrong side of Q0: the curve would turn back "
                     f"(a cusp). Q1 - Q0 must equal P{n} - P{n - 1} = {fmt(want)}.")
    return wrong(f"Q1 should be {fmt(expected[1])}: Q1 - Q0 must equal P{n} - P{n - 1} = {fmt(want)}, "
                 f"yours is {fmt(leg)}.")


def check_bernstein_value(answer) -> Result:
    """Check the value B_K^N(T) with ``BERNSTEIN_N, BERNSTEIN_K, BERNSTEIN_T`` = 4, 2, 0.5 (Goldman §24.3).

    Recognises the answer without the binomial coefficient.

    >>> check_bernstein_value(1 / 16)
    Not yet: 1/16 is t^2 (1-t)^2 alone; B_2^4 also has the binomial coefficient C(4, 2) = 6.
    """
    n, k, t = BERNSTEIN_N, BERNSTEIN_K, BERNSTEIN_T
    what = f"B_{k}^{n}({fmt(t)})"
    expected = float(bezier.bernstein(n, t)[k])
    if not is_unanswered(answer):
        try:
            value = float(answer)
        except (TypeError, ValueError):
            value = None
        bare = t ** k * (1 - t) ** (n - k)
        if value is not None and abs(value - bare) <= 1e-9 and abs(bare - expected) > 1e-9:
            return wrong(f"1/{round(1 / bare)} is t^{k} (1-t)^{n - k} alone; B_{k}^{n} also has the binomial "
                         f"coefficient C({n}, {k}) = {math.comb(n, k)}.")
    return check_number(answer, expected, what=what, tol=1e-9,
                        hint=f"B_k^n(t) = C(n, k) t^k (1-t)^(n-k) with C({n}, {k}) = {math.comb(n, k)}")

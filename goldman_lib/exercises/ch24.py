"""Exercise checkers for chapter 24, Bezier curves and surfaces (Goldman §24.2-24.6).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers of the kinds each checker recognises (``tests/test_solutions.py`` feeds
them to the checkers and fails a message that gives the answer away).  The data differ from the
chapter's worked examples (the cubic (0, 0), (1, 2.5), (3, 2.5), (4, 0.5) and the bicubic patch of
§24.6), so no exercise asks for a number the chapter printed.

>>> print(PROBLEMS["check_bernstein_weights"])
Give the 5 Bernstein weights B_0^4(0.2), ..., B_4^4(0.2) that the quartic Bezier curve gives its control points at t = 0.2, as a list (Goldman §24.3).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import bezier
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import (Result, check_points, correct, fmt, fmt_points, is_unanswered, off_by,
                                   read_points, unanswered, wrong)

__all__ = ["PROBLEMS", "SLIPS", "DE_CASTELJAU_CTRL", "DE_CASTELJAU_T", "BERNSTEIN_N", "BERNSTEIN_T",
           "END_P0", "END_D0", "END_P3", "END_D1", "HODOGRAPH_CTRL", "ELEVATION_CTRL", "JOIN_CTRL",
           "JOIN_RATIO", "PATCH_NET", "PATCH_U", "PATCH_V", "NEVILLE_POINTS", "NEVILLE_NODES", "NEVILLE_T",
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


def _net_text(net) -> str:
    return "; ".join(f"row {i}: " + fmt_points(row) for i, row in enumerate(net))


PROBLEMS = {
    "check_de_casteljau_point": (
        f"Run de Casteljau's algorithm by hand on the cubic with control points {fmt_points(DE_CASTELJAU_CTRL)} "
        f"at t = {fmt(DE_CASTELJAU_T)}: give the point on the curve as [x, y] (Goldman §24.2)."),
    "check_bernstein_weights": (
        f"Give the {BERNSTEIN_N + 1} Bernstein weights B_0^{BERNSTEIN_N}({fmt(BERNSTEIN_T)}), ..., "
        f"B_{BERNSTEIN_N}^{BERNSTEIN_N}({fmt(BERNSTEIN_T)}) that the quartic Bezier curve gives its control points "
        f"at t = {fmt(BERNSTEIN_T)}, as a list (Goldman §24.3)."),
    "check_end_conditions": (
        f"A cubic Bezier curve starts at C(0) = {fmt(END_P0)} with velocity C'(0) = {fmt(END_D0)} and ends at "
        f"C(1) = {fmt(END_P3)} with velocity C'(1) = {fmt(END_D1)}. Use endpoint interpolation and the end "
        f"tangents of §24.4 to give its four control points P0, P1, P2, P3 (Goldman §24.4)."),
    "check_hodograph": (
        f"Give the control points of the hodograph (the derivative curve) of the cubic with control points "
        f"{fmt_points(HODOGRAPH_CTRL)} (Goldman §24.5)."),
    "check_degree_elevation": (
        f"Elevate the quadratic with control points {fmt_points(ELEVATION_CTRL)} to degree 3: give the four new "
        f"control points (Goldman §24.5)."),
    "check_c1_join_unequal": (
        f"The cubic P with control points {fmt_points(JOIN_CTRL)} runs over the parameter interval [0, 1]; a second "
        f"cubic Q continues it over [1, {fmt(1 + JOIN_RATIO)}], an interval {fmt(JOIN_RATIO)} times as long. Give Q0 and "
        f"Q1 so that the join is C1 in the global parameter (Goldman §24.5.1)."),
    "check_patch_point": (
        f"The biquadratic patch P(u, v) = sum_i sum_j B_i^2(u) B_j^2(v) P_ij has the control net "
        f"{_net_text(PATCH_NET)} (the row index i goes with u, the column index j with v). Give the point "
        f"P({fmt(PATCH_U)}, {fmt(PATCH_V)}) as [x, y, z] (Goldman §24.6)."),
    "check_neville_point": (
        f"The quadratic curve L(t) passes through the points {fmt_points(NEVILLE_POINTS)} at the parameters "
        f"t = {', '.join(fmt(x) for x in NEVILLE_NODES)}. Run Neville's pyramid by hand and give L({fmt(NEVILLE_T)}) "
        f"as [x, y] (Goldman §24.1)."),
}


def _steps(ctrl, t):
    return bezier.de_casteljau_steps(ctrl, t)


def check_de_casteljau_point(answer) -> Result:
    """Check the point of the cubic ``DE_CASTELJAU_CTRL`` at ``t = DE_CASTELJAU_T`` (Goldman §24.2).

    answer: [x, y].  Recognises a point of an intermediate level of the construction (stopped too
    early), the point at 1 - t (t and 1 - t exchanged in (1-t) P_j + t P_{j+1}) and the centroid of
    the control points (equal weights instead of the Bernstein weights).
    """
    t = DE_CASTELJAU_T
    what = f"the point at t={fmt(t)}"
    got, err = read_points(answer, "your point", ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} should be one point [x, y]; yours has shape {got.shape}.")
    steps = _steps(DE_CASTELJAU_CTRL, t)
    expected = steps[-1][0]
    dist = float(np.linalg.norm(got - expected))
    if dist <= 1e-4:
        return correct(f"{what} is {fmt(expected)}.")
    for level, pts in enumerate(steps[1:-1], start=1):
        if np.any(np.linalg.norm(pts - got, axis=1) <= 1e-4):
            return wrong(f"your point is a point of level {level} of the construction, not the end: "
                         "a cubic needs three levels of affine combinations.")
    if np.linalg.norm(got - bezier.de_casteljau(DE_CASTELJAU_CTRL, 1 - t)) <= 1e-4:
        return wrong(f"that is the point at t = {fmt(1 - t)}: each step must move a fraction t = {fmt(t)} of the way "
                     f"from P_j towards P_(j+1), (1-t) P_j + t P_(j+1), not a fraction 1 - t.")
    if np.linalg.norm(got - DE_CASTELJAU_CTRL.mean(axis=0)) <= 1e-4:
        return wrong(f"your point is the average of the control points; the curve weights them by the "
                     f"Bernstein values at t, which are not equal.")
    return wrong(f"your point is {far_off(got, expected)} from the curve at t={fmt(t)}; the curve point is a repeated "
                 f"affine combination (1-t) P_j + t P_(j+1), three levels deep for a cubic.")


def check_bernstein_weights(answer) -> Result:
    """Check the list B_k^N(T), k = 0..N, with ``BERNSTEIN_N, BERNSTEIN_T`` (Goldman §24.3).

    Recognises the weights without the binomial coefficients, the list in reverse order (t and
    1 - t exchanged) and a wrong number of weights; otherwise names the first weight that is off.
    Tolerance 1e-4 per weight.
    """
    n, t = BERNSTEIN_N, BERNSTEIN_T
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


def check_end_conditions(answer) -> Result:
    """Check the control points of the cubic with end data ``END_P0, END_D0, END_P3, END_D1`` (Goldman §24.4).

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
    n = 3
    expected = np.array([END_P0, END_P0 + END_D0 / n, END_P3 - END_D1 / n, END_P3])
    if np.allclose(got, expected, atol=1e-4):
        return correct("the control points match: P1 = P0 + C'(0)/3 and P2 = P3 - C'(1)/3.")
    if np.linalg.norm(got[0] - END_P0) > 1e-4 or np.linalg.norm(got[3] - END_P3) > 1e-4:
        return wrong("a Bezier curve interpolates its end control points: P0 must be C(0) and P3 must be C(1).")
    no_third = np.array([END_P0, END_P0 + END_D0, END_P3 - END_D1, END_P3])
    if np.allclose(got, no_third, atol=1e-4):
        return wrong("the inner points are the right direction but three times too far: C'(0) = 3 (P1 - P0) for a "
                     "cubic, so P1 - P0 is a third of C'(0) (and likewise at the other end).")
    if np.linalg.norm(got[2] - (END_P3 + END_D1 / n)) <= 1e-4:
        return wrong("P2 is on the wrong side of P3: the curve arrives at P3 from the direction of P2, "
                     "C'(1) = 3 (P3 - P2), so P2 = P3 - C'(1)/3.")
    return check_points(got, expected, what=what,
                        hint="C'(0) = 3 (P1 - P0) and C'(1) = 3 (P3 - P2) for a cubic")


def check_hodograph(answer) -> Result:
    """Check the control points of the hodograph of ``HODOGRAPH_CTRL`` (Goldman §24.5).

    answer: (3, 2), the points ``n (P_{k+1} - P_k)``.  Recognises the differences without the
    factor n, the differences taken the other way (P_k - P_{k+1}) and a wrong number of points.

    >>> check_hodograph([[1, 3], [3, 1], [1, -3]])
    Not yet: these are the differences P_(k+1) - P_k; the hodograph multiplies them by the degree n = 3.
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
        return wrong(f"these are the differences P_(k+1) - P_k; the hodograph multiplies them by the degree n = {n}.")
    if np.allclose(got, -expected, atol=1e-6) or np.allclose(got, -expected / n, atol=1e-6):
        return wrong("the differences point backwards: the derivative follows the curve's direction, "
                     "n (P_(k+1) - P_k), later point minus earlier point.")
    return check_points(got, expected, what=what, hint=f"the k-th point is {n} (P_(k+1) - P_k)")


def check_degree_elevation(answer) -> Result:
    """Check the control points of ``ELEVATION_CTRL`` elevated to degree 3 (Goldman §24.5).

    answer: (4, 2).  Recognises the weights swapped between ``P_{k-1}`` and ``P_k``, moved end
    points and a wrong number of points.

    >>> check_degree_elevation([[0, 0], [2, 1], [4, 7], [3, 9]])
    Not yet: the weights are swapped: Q_k = k/(n+1) P_(k-1) + (1 - k/(n+1)) P_k gives P_(k-1) the weight k/(n+1).
    """
    what = "the elevated control points"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    P = ELEVATION_CTRL
    expected = bezier.elevate_degree(P)
    if got.shape != expected.shape:
        return wrong(f"{what} should be four points, as a cubic has; your answer has {len(got) if got.ndim else 'one'} entries.")
    n1 = len(P)
    a = (np.arange(1, n1) / n1)[:, None]
    swapped = np.vstack([P[:1], (1 - a) * P[:-1] + a * P[1:], P[-1:]])
    if np.allclose(got, swapped, atol=1e-6):
        return wrong("the weights are swapped: Q_k = k/(n+1) P_(k-1) + (1 - k/(n+1)) P_k gives P_(k-1) "
                     "the weight k/(n+1).")
    if np.linalg.norm(got[0] - P[0]) > 1e-6 or np.linalg.norm(got[-1] - P[-1]) > 1e-6:
        return wrong("degree elevation keeps the curve, so it keeps its end points: Q_0 = P_0 and Q_3 = P_2.")
    return check_points(got, expected, what=what,
                        hint="the end points stay; Q_k = k/(n+1) P_(k-1) + (1 - k/(n+1)) P_k")


def check_c1_join_unequal(answer) -> Result:
    """Check Q0, Q1 of a cubic over an interval ``JOIN_RATIO`` times as long that continues
    ``JOIN_CTRL`` with C1 continuity (Goldman §24.5.1).

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
    P, r = JOIN_CTRL, JOIN_RATIO
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
        return wrong("the ratio is inverted: Q runs over the longer interval, so to keep the same speed in the "
                     "global parameter its first leg must be longer than P's last leg, not shorter.")
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


def check_patch_point(answer) -> Result:
    """Check the point ``PATCH_NET`` at (``PATCH_U``, ``PATCH_V``) of the biquadratic patch (Goldman §24.6).

    answer: [x, y, z].  Recognises u and v exchanged (rows evaluated at u), the bilinear
    interpolation of the four corners only, and the plain average of the nine control points.
    Tolerance 1e-4.

    >>> check_patch_point([1, 2, 0.5])
    Not yet: that is the bilinear interpolation of the four corner points: the patch also weights the five other control points, by the products of the quadratic Bernstein values in u and in v.
    """
    u, v = PATCH_U, PATCH_V
    what = f"P({fmt(u)}, {fmt(v)})"
    got, err = read_points(answer, "your point", ask=what + " as [x, y, z]")
    if err is not None:
        return err
    if got.shape != (3,):
        return wrong(f"{what} should be one point [x, y, z]; yours has shape {got.shape}.")
    net = PATCH_NET
    expected = bezier.patch_de_casteljau(net, u, v)
    if np.linalg.norm(got - expected) <= 1e-4:
        return correct(f"{what} is {fmt(expected)}.")
    if np.linalg.norm(got - bezier.patch_de_casteljau(net, v, u)) <= 1e-4:
        return wrong("u and v are exchanged: the row index i goes with u, so evaluate each row (j = 0, 1, 2) at "
                     "v, then the resulting three points at u.")
    corners = np.array([[net[0, 0], net[0, -1]], [net[-1, 0], net[-1, -1]]])
    if np.linalg.norm(got - bezier.patch_de_casteljau(corners, u, v)) <= 1e-4:
        return wrong("that is the bilinear interpolation of the four corner points: the patch also weights the "
                     "five other control points, by the products of the quadratic Bernstein values in u and in v.")
    if np.linalg.norm(got - net.reshape(-1, 3).mean(axis=0)) <= 1e-4:
        return wrong("that is the plain average of the nine control points; the patch weights P_ij by the "
                     "products of the Bernstein values in u and in v, which are not equal.")
    return wrong(f"your point is {far_off(got, expected)} from the patch point; run de "
                 f"Casteljau on each row at v, then on the three results at u.")


def check_neville_point(answer) -> Result:
    """Check the point of the interpolating quadratic through ``NEVILLE_POINTS`` at ``NEVILLE_T`` (Goldman §24.1).

    answer: [x, y].  Recognises the Bezier point of the same three points (approximation instead of
    interpolation: de Casteljau's weights 1-t and t on every level), a point of the first level of
    Neville's pyramid (stopped too early), and a data point itself.
    """
    t = NEVILLE_T
    what = f"L({fmt(t)})"
    got, err = read_points(answer, "your point", ask=what + " as [x, y]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} should be one point [x, y]; yours has shape {got.shape}.")
    expected = bezier.neville(NEVILLE_POINTS, t, nodes=NEVILLE_NODES)
    dist = float(np.linalg.norm(got - expected))
    if dist <= 1e-4:
        return correct(f"{what} = {fmt(expected)}, on the parabola through the three points.")
    if np.linalg.norm(got - bezier.de_casteljau(NEVILLE_POINTS, t)) <= 1e-4:
        return wrong("that is the point of the Bezier curve of the three points (de Casteljau's weights 1 - t and t): "
                     "it approximates the points, it does not pass through the middle one. Neville's weights are "
                     "(t_(i+r) - t) / (t_(i+r) - t_i) and (t - t_i) / (t_(i+r) - t_i), with each node's own interval.")
    for i in range(2):
        lo, hi = NEVILLE_NODES[i], NEVILLE_NODES[i + 1]
        level1 = bezier.neville(NEVILLE_POINTS[i:i + 2], t, nodes=[lo, hi])
        if np.linalg.norm(got - level1) <= 1e-4:
            return wrong(f"that is a point of the first level of the pyramid (the line through P{i} and P{i + 1}); "
                         "a quadratic needs a second level, which combines the two first-level points over the nodes' "
                         "whole interval.")
    if np.any(np.linalg.norm(NEVILLE_POINTS - got, axis=1) <= 1e-4):
        return wrong(f"that is one of the data points; the curve passes through them at their nodes, and {fmt(t)} is "
                     "not one of the nodes.")
    return wrong(f"your point is {far_off(got, expected)} from {what}; each level of Neville's pyramid is an affine combination "
                 "weighted by distances to the nodes, and extrapolation (a weight below 0) is allowed.")


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

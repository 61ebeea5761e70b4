"""Exercise checkers for chapter 27, B-spline curves and surfaces (Goldman §27.2-27.9).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers of the kinds each checker recognises.  The data differ from the
chapter's worked examples (its cubic on clamped uniform knots, the quadratic u^2 spline, the
circle and the sphere).

>>> print(PROBLEMS["check_continuity_orders"])  # doctest: +ELLIPSIS
A quartic B-spline (degree 4) has the knots ... (Goldman §27.4).
"""

from __future__ import annotations

import numpy as np

from goldman_lib import bspline
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, fmt_points, off_by, read_points, wrong

__all__ = ["PROBLEMS", "SLIPS",
           "CURVE_CTRL", "CURVE_KNOTS", "CURVE_DEGREE", "DE_BOOR_U", "BASIS_U",
           "CONT_DEGREE", "CONT_KNOTS", "CONT_AT",
           "SPLINE_PIECES", "SPLINE_BREAKS", "SPLINE_CONTINUITY",
           "SURF_HEIGHTS", "SURF_KNOTS_U", "SURF_KNOTS_V", "SURF_DEGREES", "SURF_UV",
           "NURBS_CTRL", "NURBS_WEIGHTS", "NURBS_KNOTS", "NURBS_U", "PYRAMID_KNOTS", "PYRAMID_DEGREE", "PYRAMID_NODE",
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


def _knots(t) -> str:
    return "[" + ", ".join(fmt(x) for x in t) + "]"


def _surface_net() -> np.ndarray:
    m, n = SURF_HEIGHTS.shape
    i, j = np.meshgrid(np.arange(m, dtype=float), np.arange(n, dtype=float), indexing="ij")
    return np.stack([i, j, SURF_HEIGHTS], axis=-1)


PROBLEMS = {
    "check_local_de_boor": (
        f"The quadratic B-spline with control points {fmt_points(CURVE_CTRL)} and knots {_knots(CURVE_KNOTS)}: "
        f"evaluate C({fmt(DE_BOOR_U)}) by the local de Boor algorithm (find the span, then two levels of "
        f"affine combinations, each with the knots of its own node). Give C(u) as [x, y] (Goldman §27.2)."),
    "check_basis_values": (
        f"On the same knots {_knots(CURVE_KNOTS)}, three quadratic B-splines are non-zero at u = {fmt(BASIS_U)}. "
        f"Compute them with the recurrence of the global de Boor algorithm, from the degree-0 functions up, and "
        f"give [N_1,2(u), N_2,2(u), N_3,2(u)] to 4 decimals (Goldman §27.3)."),
    "check_continuity_orders": (
        f"A quartic B-spline (degree {CONT_DEGREE}) has the knots {_knots(CONT_KNOTS)}. How smooth is it at each "
        f"interior knot? Give [k1, k2, k3, k4] for C^k at u = {', '.join(fmt(x) for x in CONT_AT)} (Goldman §27.4)."),
    "check_spline_control_points": (
        "The quadratic spline s(u) = 2u - u^2 on [0, 1] and s(u) = 0.5 + u - u^2/2 on [1, 3] is C^1 at u = 1. "
        f"As a B-spline on the knots {_knots(bspline.spline_to_bspline(SPLINE_PIECES, SPLINE_BREAKS, SPLINE_CONTINUITY)[1])} "
        "its control points are the blossoms of the pieces at consecutive knots: give the four (numbers) "
        "[P0, P1, P2, P3] (Goldman §27.6)."),
    "check_surface_point": (
        f"A B-spline surface has degree {SURF_DEGREES[0]} in u with knots {_knots(SURF_KNOTS_U)} and degree "
        f"{SURF_DEGREES[1]} in v with knots {_knots(SURF_KNOTS_V)}. Its control net is P_ij = (i, j, z_ij), "
        f"i, j = 0, 1, 2 (i goes with u, j with v), with heights z_0j = {fmt(SURF_HEIGHTS[0])}, "
        f"z_1j = {fmt(SURF_HEIGHTS[1])}, z_2j = {fmt(SURF_HEIGHTS[2])}. Give S({fmt(SURF_UV[0])}, "
        f"{fmt(SURF_UV[1])}) as [x, y, z] (Goldman §27.8)."),
    "check_nurbs_point": (
        f"The quadratic NURBS curve with control points {fmt_points(NURBS_CTRL)}, weights "
        f"{', '.join(fmt(w) for w in NURBS_WEIGHTS)} and knots {_knots(NURBS_KNOTS)}: compute C({fmt(NURBS_U)}) "
        f"= sum w_k N_k,2(u) P_k / sum w_k N_k,2(u). Give [x, y] to 3 decimals (Goldman §27.9)."),
    "check_pyramid_node_interval": (
        f"In the global de Boor pyramid of a quadratic B-spline (degree {PYRAMID_DEGREE}) on the knots "
        f"{_knots(PYRAMID_KNOTS)}, take the node P_{PYRAMID_NODE[1]}^{PYRAMID_NODE[0]} (level {PYRAMID_NODE[0]}, "
        f"index {PYRAMID_NODE[1]}). On which interval [a, b] of u is this node a blossom value of the curve's "
        f"polynomial pieces (the union of the spans whose local pyramids use it)? Give [a, b] (Goldman §27.5)."),
}


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


# -- Exercise 1 -----------------------------------------------------------------------------------

def _span_curve(k: int, u: float) -> np.ndarray:
    """C(u) computed with the pyramid of span k (right for k = the span of u, a slip otherwise)."""
    p, t = CURVE_DEGREE, CURVE_KNOTS
    pts = CURVE_CTRL[k - p:k + 1].copy()
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            i = k - p + j
            a = (u - t[i]) / (t[i + p + 1 - r] - t[i])
            pts[j] = (1 - a) * pts[j - 1] + a * pts[j]
    return pts[p]


def check_local_de_boor(answer) -> Result:
    """Check C(``DE_BOOR_U``) of the quadratic ``CURVE_CTRL`` by local de Boor (Goldman §27.2).

    >>> check_local_de_boor([4, 3.75])
    Not yet: you used de Casteljau's weight (u - t_k)/(t_(k+1) - t_k) on every level, as if P1..P3 were a Bezier polygon over the span; de Boor's weight at node i of level r is (u - t_i)/(t_(i+p+1-r) - t_i), with the knots of that node.
    """
    what = f"C({fmt(DE_BOOR_U)})"
    got, err = _read_point(answer, what, 2)
    if err is not None:
        return err
    p, t, u = CURVE_DEGREE, CURVE_KNOTS, DE_BOOR_U
    k = int(bspline.find_span(t, p, u))
    steps = bspline.de_boor_steps(CURVE_CTRL, t, p, u)
    expected = steps[-1][0]
    if _near(got, expected, 1e-6):
        return correct(f"{what} = {fmt(expected)}: the span [t{k}, t{k + 1}) = [{fmt(t[k])}, {fmt(t[k + 1])}), "
                       f"points P{k - p}..P{k}, weights 2/3 and 1/3 on level 1, 1/2 on level 2.")
    if any(_near(got, q, 1e-6) for q in steps[1]):
        return wrong(f"that is a point of level 1 of the pyramid; a quadratic needs 2 levels: combine the "
                     f"two level-1 points once more, with the weight (u - t_i)/(t_(i+1) - t_i).")
    s = (u - t[k]) / (t[k + 1] - t[k])
    Q = CURVE_CTRL[k - p:k + 1]
    if _near(got, (1 - s) ** 2 * Q[0] + 2 * s * (1 - s) * Q[1] + s ** 2 * Q[2], 1e-6):
        return wrong(f"you used de Casteljau's weight (u - t_k)/(t_(k+1) - t_k) on every level, as if "
                     f"P{k - p}..P{k} were a Bezier polygon over the span; de Boor's weight at node i of level r is "
                     f"(u - t_i)/(t_(i+p+1-r) - t_i), with the knots of that node.")
    for other in (k - 1, k + 1):
        if p <= other <= len(CURVE_CTRL) - 1 and _near(got, _span_curve(other, u), 1e-6):
            return wrong(f"you ran the pyramid on P{other - p}..P{other}, the points of another span; u = {fmt(u)} "
                         f"lies in [t{k}, t{k + 1}) = [{fmt(t[k])}, {fmt(t[k + 1])}), so P_(k-p)..P_k act.")
    return wrong(f"your point is {far_off(got, expected)} from {what}. Find the span "
                 f"t_k <= u < t_(k+1) first; on level r the weight of node i is (u - t_i)/(t_(i+p+1-r) - t_i).")


# -- Exercise 2 -----------------------------------------------------------------------------------

def check_basis_values(answer) -> Result:
    """Check the three quadratic B-splines non-zero at ``BASIS_U`` (Goldman §27.3).
    """
    what = f"[N_1,2, N_2,2, N_3,2] at u = {fmt(BASIS_U)}"
    got, err = read_points(answer, "your basis values", ask=what + " as a list of three numbers")
    if err is not None:
        return err
    got = got.reshape(-1)
    if got.size != 3:
        return wrong(f"give the three basis functions that are non-zero at u = {fmt(BASIS_U)}, "
                     f"[N_1,2, N_2,2, N_3,2]; you gave {got.size} numbers.")
    p, t, u = CURVE_DEGREE, CURVE_KNOTS, BASIS_U
    expected = bspline.basis(t, p, u)[1:4]
    if _near(got, expected, 1e-4):
        return correct(f"N_1,2, N_2,2, N_3,2 at u = {fmt(u)} match, and they sum to 1 (partition of unity).")
    k = int(bspline.find_span(t, p, u))
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
    return wrong(f"N_{bad + 1},2 is {off_by(got[bad], expected[bad])}. Start from N_3,0 = 1 on [t3, t4), then "
                 f"N_k,r = (u - t_k)/(t_(k+r) - t_k) N_k,r-1 + (t_(k+r+1) - u)/(t_(k+r+1) - t_(k+1)) N_k+1,r-1.")


# -- Exercise 3 -----------------------------------------------------------------------------------

def check_continuity_orders(answer) -> Result:
    """Check the order of continuity at each interior knot of ``CONT_KNOTS`` (Goldman §27.4).

    >>> check_continuity_orders([1, 2, 3, 4])
    Not yet: those are the multiplicities of the knots; the smoothness goes the other way: each repetition of a knot removes one order of continuity, C^(p - m).
    """
    what = "[k1, k2, k3, k4]"
    got, err = read_points(answer, "your orders", ask=what + " for C^k at the four interior knots")
    if err is not None:
        return err
    got = got.reshape(-1)
    p = CONT_DEGREE
    mult = np.array([bspline.multiplicity(CONT_KNOTS, x) for x in CONT_AT])
    if got.size != mult.size:
        return wrong(f"give one order for each of the {mult.size} interior knots; you gave {got.size}.")
    expected = p - mult
    if np.array_equal(got, expected):
        orders = ", ".join(f"C^{k}" for k in expected)
        return correct(f"at a knot of multiplicity m a quartic is C^({p} - m): {orders} at the knots "
                       f"{', '.join(fmt(x) for x in CONT_AT)}.")
    if np.array_equal(got, mult):
        return wrong("those are the multiplicities of the knots; the smoothness goes the other way: each "
                     "repetition of a knot removes one order of continuity, C^(p - m).")
    if np.array_equal(got, expected - 1):
        return wrong(f"every order is one too low: a simple knot of a degree-{p} spline leaves C^(p - 1), so the "
                     f"rule is C^(p - m), and only multiplicity p + 1 lets the curve jump.")
    if np.all(got == got[0]) and got[0] == p - 1:
        return wrong(f"C^(p - 1) holds at a simple knot only; count how often each knot is repeated: C^(p - m).")
    bad = int(np.flatnonzero(got != expected)[0])
    return wrong(f"the order at u = {fmt(CONT_AT[bad])} is not right: count how often that knot appears in the "
                 f"knot vector (m) and use C^(p - m) with p = {p}.")


# -- Exercise 4 -----------------------------------------------------------------------------------

def _spline() -> tuple[np.ndarray, np.ndarray]:
    ctrl, knots, _ = bspline.spline_to_bspline(SPLINE_PIECES, SPLINE_BREAKS, SPLINE_CONTINUITY)
    return ctrl.reshape(-1), knots


def _piece_value(i: int, x) -> np.ndarray:
    c = SPLINE_PIECES[i, :, 0]
    x = np.asarray(x, dtype=float)
    return c[0] + c[1] * x + c[2] * x * x


def check_spline_control_points(answer) -> Result:
    """Check the B-spline control points of the piecewise quadratic ``SPLINE_PIECES`` (Goldman §27.6).

    >>> check_spline_control_points([0, 1, 1, -3])
    Not yet: P3 = b(3, 3) has a label in the span [1, 3]: use the blossom of the second piece there (you used the first piece's blossom beyond its span).
    """
    what = "[P0, P1, P2, P3]"
    got, err = read_points(answer, "your control points", ask=what + " as a list of four numbers")
    if err is not None:
        return err
    got = got.reshape(-1)
    expected, knots = _spline()
    if got.size != expected.size:
        return wrong(f"a quadratic with the knots {_knots(knots)} has {expected.size} control points "
                     f"(number of knots - p - 1); you gave {got.size}.")
    if _near(got, expected, 1e-6):
        return correct("the control points are the blossoms b(0, 0), b(0, 1), b(1, 3), b(3, 3); P2 comes out the "
                       "same from either piece because the spline is C^1 at u = 1.")
    greville = (knots[1:-2] + knots[2:-1]) / 2
    pieces = np.searchsorted(SPLINE_BREAKS, greville, side="right") - 1
    values = np.array([_piece_value(min(i, len(SPLINE_PIECES) - 1), x) for i, x in zip(pieces, greville)])
    if _near(got, values, 1e-6):
        return wrong("those are values of the spline (at the midpoints of the labels); a control point is not a "
                     "point of the curve but the blossom: replace u^2 by u1 u2 and u by (u1 + u2)/2, then put in "
                     "the two knots of the label.")
    c0 = SPLINE_PIECES[0, :, 0]
    first = np.array([c0[0] + c0[1] * (a + b) / 2 + c0[2] * a * b for a, b in zip(knots[1:-2], knots[2:-1])])
    if _near(got, first, 1e-6):
        return wrong("P3 = b(3, 3) has a label in the span [1, 3]: use the blossom of the second piece there "
                     "(you used the first piece's blossom beyond its span).")
    bad = int(np.flatnonzero(np.abs(got - expected) > 1e-6)[0])
    label = (knots[bad + 1], knots[bad + 2])
    return wrong(f"P{bad} is {off_by(got[bad], expected[bad])}. Its label is ({fmt(label[0])}, {fmt(label[1])}); the "
                 f"blossom of a + b u + c u^2 is a + b (u1 + u2)/2 + c u1 u2.")


# -- Exercise 5 -----------------------------------------------------------------------------------

def check_surface_point(answer) -> Result:
    """Check S(``SURF_UV``) of the degree (1, 2) surface (Goldman §27.8).

    >>> check_surface_point([1, 1.5, 2.5])
    Not yet: you used the u knots along j and the v knots along i; i goes with u (the first knot vector), j with v.
    """
    what = f"S({fmt(SURF_UV[0])}, {fmt(SURF_UV[1])})"
    got, err = _read_point(answer, what, 3)
    if err is not None:
        return err
    net = _surface_net()
    (p, q), (u, v) = SURF_DEGREES, SURF_UV
    expected = bspline.surface_de_boor(net, SURF_KNOTS_U, SURF_KNOTS_V, p, q, u, v)
    if _near(got, expected, 1e-6):
        return correct(f"{what} = {fmt(expected)}: rows 1 and 2 weigh 1/2 each in u, the Bernstein weights "
                       f"1/4, 1/2, 1/4 act in v.")
    swapped = np.einsum("j,i,ijd->d", bspline.basis(SURF_KNOTS_U, p, u), bspline.basis(SURF_KNOTS_V, q, v), net)
    if _near(got, swapped, 1e-6):
        return wrong("you used the u knots along j and the v knots along i; i goes with u (the first knot vector), "
                     "j with v.")
    Nu, Nv = bspline.basis(SURF_KNOTS_U, p, u), bspline.basis(SURF_KNOTS_V, q, v)
    rows = np.einsum("j,ijd->id", Nv, net)
    for i in np.flatnonzero(Nu > 0):
        if _near(got, rows[i], 1e-6):
            return wrong(f"that is the v-curve of row {i} alone; u = {fmt(u)} lies in the span [1, 2) of the linear "
                         f"u direction, so two rows take part: combine their v-points with the weights N_i,1(u).")
    if _near(got[:2], expected[:2], 1e-6):
        return wrong(f"x and y are right, the height is {off_by(got[2], expected[2])}; run the v direction on the "
                     f"heights of each active row, then combine the rows in u.")
    return wrong(f"your point is {far_off(got, expected)} from {what}. Find u's span in the "
                 f"u knots and v's in the v knots; S = sum_i sum_j N_i,1(u) N_j,2(v) P_ij.")


# -- Exercise 6 -----------------------------------------------------------------------------------

def check_nurbs_point(answer) -> Result:
    """Check C(``NURBS_U``) of the rational quadratic with weights ``NURBS_WEIGHTS`` (Goldman §27.9).

    >>> check_nurbs_point([3, 1.5])
    Not yet: that is the polynomial B-spline (every weight equal); multiply each N_k,2(u) by its weight w_k, and divide by the sum of the weighted basis values.
    """
    what = f"C({fmt(NURBS_U)})"
    got, err = _read_point(answer, what, 2)
    if err is not None:
        return err
    P, w, t, u = NURBS_CTRL, NURBS_WEIGHTS, NURBS_KNOTS, NURBS_U
    expected = bspline.nurbs_curve(P, w, t, 2, u)
    if _near(got, expected, 1e-3):
        return correct(f"{what} matches: the weights 2 and 3 pull the point towards P1 and P3 compared with the "
                       f"polynomial B-spline.")
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
    return wrong(f"your point is {far_off(got, expected)} from {what}. Compute N_1,2, "
                 f"N_2,2, N_3,2 at u = {fmt(u)}, then C = sum w_k N_k P_k / sum w_k N_k.")


# -- Exercise 7 -----------------------------------------------------------------------------------

def check_pyramid_node_interval(answer) -> Result:
    """Check the locality interval ``[t_i, t_(i+p+1-r)]`` of the node ``PYRAMID_NODE`` (Goldman §27.5).

    answer: [a, b].  Recognises the support of the basis function N_i,p (the level ignored), the one
    span [t_i, t_(i+1)] (the node is shared by several spans), and a knot index shifted by one.
    """
    r, i = PYRAMID_NODE
    p, t = PYRAMID_DEGREE, PYRAMID_KNOTS
    got, err = read_points(answer, "your interval", ask="the interval as [a, b]")
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"the interval should be two numbers [a, b]; yours has shape {got.shape}.")
    info = bspline.global_pyramid_labels(t, p)[r][i - r]
    expected = np.array(info["interval"])
    if _near(got, expected, 1e-9):
        label = ", ".join(["u"] * r + [fmt(x) for x in info["knots"]])
        pieces = " and ".join(f"[{fmt(t[k])}, {fmt(t[k + 1])})" for k in info["spans"])
        return correct(f"the node P_{i}^{r} is labelled ({label}) and is a blossom value of the pieces on {pieces}: "
                       f"u in [{fmt(expected[0])}, {fmt(expected[1])}].")
    if _near(got, [t[i], t[i + p + 1]], 1e-9):
        return wrong(f"that is the support of the basis function N_{i},{p}, the reach of a control point at level 0; "
                     f"a node of level {r} has its parents' common knots, one fewer per level, so it reaches fewer spans.")
    if _near(got, [t[i], t[i + 1]], 1e-9):
        return wrong("that is a single knot span; a node below the apex is shared by the local pyramids of several "
                     "neighbouring spans: count the knots in its label.")
    for shift in (-1, 1):
        j = i + shift
        if 0 <= j and j + p + 1 - r < t.size and _near(got, [t[j], t[j + p + 1 - r]], 1e-9):
            return wrong("your interval has the right length in knots but starts at the wrong knot: node i of level r "
                         "combines with the weight (u - t_i) / (t_(i+p+1-r) - t_i), so its interval starts at t_i.")
    return wrong("your interval is not one the node's label gives; the node's label is (u^r, t_(i+1), ..., t_(i+p-r)) "
                 "and it serves the spans k with i <= k <= i+p-r.")


#: Wrong answers of the kinds each checker recognises (tests/test_solutions.py feeds them in).
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

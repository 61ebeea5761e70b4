"""B-spline curves and surfaces, and NURBS (Goldman, chapter 27).

A B-spline curve of degree ``p`` has control points ``P_0 .. P_n`` (``ctrl``, shape ``(n+1, d)``)
and a non-decreasing knot vector ``t_0 <= ... <= t_{n+p+1}`` (``knots``, ``n+p+2`` numbers).  On
each knot span ``[t_k, t_{k+1})`` with ``p <= k <= n`` the curve is a polynomial of degree ``p``
whose blossom takes the value ``P_i`` at the ``p`` consecutive knots ``t_{i+1}, ..., t_{i+p}``
(§27.2); the curve is defined on the domain ``[t_p, t_{n+1}]``.

Two layers, as everywhere in ``goldman_lib``:

- pure functions on arrays: knot vectors (:func:`check_knots`, :func:`clamped_knots`,
  :func:`uniform_knots`, :func:`find_span`, :func:`multiplicity`), the local de Boor algorithm
  from blossoming (§27.2: :func:`blossom`, :func:`local_de_boor`, :func:`de_boor_steps`,
  :func:`control_point_labels`), the global de Boor algorithm and the B-spline basis
  (§27.3: :func:`de_boor`, :func:`basis`, :func:`global_de_boor`), derivatives and smoothness at
  the knots (§27.4: :func:`derivative_ctrl`, :func:`derivative`, :func:`continuity_at`,
  :func:`derivative_jumps`), labelling and locality in the global pyramid (§27.5:
  :func:`global_pyramid_labels`, :func:`global_pyramid`), "every spline is a B-spline" (§27.6: :func:`spline_to_bspline`,
  :func:`bspline_to_pieces`), the properties of §27.7 (:func:`support`,
  :func:`affected_span`), tensor-product surfaces (§27.8: :func:`surface_de_boor`,
  :func:`surface_grid`) and NURBS (§27.9: :func:`nurbs_curve`, :func:`nurbs_surface`,
  :func:`nurbs_surface_grid`, :func:`nurbs_circle`, :func:`nurbs_sphere`);
- thin classes over them for the notebook: :class:`BSplineCurve` and :class:`NURBSCurve`.

Knot vectors are validated by :func:`check_knots`, one message per rule (non-decreasing, a knot
repeated at most ``degree + 1`` times, ``len(knots) = n_ctrl + degree + 1``, a non-empty domain).
A parameter outside the domain ``[t_p, t_{n+1}]`` raises ``ValueError`` naming it.

>>> de_boor([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5)
array([1., 1.])
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib.kernels import number, pyramids
from goldman_lib.validation import (as_float, as_float_array, as_int, as_parameter, as_points, check_finite,
                                     finite_result, within_budget)

__all__ = [
    "check_knots", "clamped_knots", "uniform_knots", "find_span", "multiplicity", "domain",
    "blossom", "local_de_boor", "de_boor_steps", "control_point_labels",
    "de_boor", "basis", "global_de_boor",
    "derivative_ctrl", "derivative", "continuity_at", "derivative_jumps",
    "global_pyramid_labels", "global_pyramid",
    "spline_to_bspline", "bspline_to_pieces", "rational_basis",
    "support", "affected_span",
    "surface_de_boor", "surface_grid",
    "nurbs_curve", "nurbs_surface", "nurbs_surface_grid", "nurbs_circle", "nurbs_sphere",
    "BSplineCurve", "NURBSCurve",
]


# --------------------------------------------------------------------------------------------
# knot vectors
# --------------------------------------------------------------------------------------------

_fmt = number


def check_knots(knots, degree, n_ctrl=None, name: str = "knots", *, degree_name: str = "degree",
                count_name: str = "n_ctrl") -> np.ndarray:
    """Validate a knot vector for a B-spline of ``degree`` and return it as a float array (Goldman §27.2).

    The rules, each with its own message: ``knots`` is a finite 1-D array; it is non-decreasing;
    no knot is repeated more than ``degree + 1`` times; its length is ``n_ctrl + degree + 1``
    (if ``n_ctrl`` is given; otherwise at least ``2 (degree + 1)``, so there is at least one
    control point per basis function); and the domain ``[t_p, t_{n+1}]`` is not a single point.

    knots: (n+p+2,) numbers.  degree: int >= 0.  n_ctrl: number of control points or None.
    name: the parameter name used in messages (degree_name: the degree's; count_name: what n_ctrl
    counts, e.g. ``"len(ctrl)"``).  Returns a new (n+p+2,) float array.
    Raises TypeError for non-numeric input or a non-integer degree, ValueError naming the rule.

    >>> check_knots([0, 0, 0, 1, 1, 1], 2, 3).tolist()
    [0.0, 0.0, 0.0, 1.0, 1.0, 1.0]
    >>> check_knots([0, 0, 0.5, 0.2, 1, 1], 1)
    Traceback (most recent call last):
    ...
    ValueError: knots must be non-decreasing; knots[3]=0.2 < knots[2]=0.5
    """
    degree = as_int(degree, degree_name, minimum=0)
    t = np.array(as_float_array(knots, name))  # a copy: the caller's array is never aliased
    if t.ndim != 1:
        raise ValueError(f"{name} must be a 1-D array of knots; got shape {t.shape}")
    check_finite(t, name)
    spread = float(t[-1]) - float(t[0]) if t.size else 0.0      # Python floats overflow to inf quietly
    if not math.isfinite(spread) and np.all(t[1:] >= t[:-1]):
        # de Boor's weights (u - t_i) / (t_j - t_i) would be inf / inf: the curve is not computable
        raise ValueError(f"{name} is too large in magnitude: {name}[-1] - {name}[0] = {_fmt(t[-1])} - {_fmt(t[0])} "
                         f"overflows float64 (knots must span less than about 1.8e308)")
    down = t[1:] < t[:-1]
    if down.any():
        i = int(np.flatnonzero(down)[0]) + 1
        raise ValueError(f"{name} must be non-decreasing; {name}[{i}]={_fmt(t[i])} < {name}[{i - 1}]={_fmt(t[i - 1])}")
    # non-decreasing, so a knot repeats more than degree+1 times exactly where t[i] == t[i+degree+1]
    if t.size > degree + 1 and (t[degree + 1:] == t[:t.size - degree - 1]).any():
        starts = np.flatnonzero(np.r_[True, t[1:] != t[:-1]])
        counts = np.diff(np.r_[starts, t.size])
        big = np.flatnonzero(counts > degree + 1)
        if big.size:
            s = int(starts[big[0]])
            raise ValueError(f"{name} may repeat a knot at most {degree_name}+1 = {degree + 1} times; "
                             f"{name}[{s}]={_fmt(t[s])} appears {int(counts[big[0]])} times")
    if n_ctrl is not None:
        n_ctrl = as_int(n_ctrl, count_name, minimum=1)
        count = count_name
        if t.size != n_ctrl + degree + 1:
            raise ValueError(f"{name} must have length {count} + {degree_name} + 1 = {n_ctrl} + {degree} + 1 = "
                             f"{n_ctrl + degree + 1}; got {t.size}")
        if n_ctrl < degree + 1:
            raise ValueError(f"a B-spline of {degree_name} {degree} needs at least {degree_name}+1 = {degree + 1} "
                             f"control points; {count} is {n_ctrl}")
    elif t.size < 2 * (degree + 1):
        raise ValueError(f"{name} must have at least 2*({degree_name}+1) = {2 * (degree + 1)} knots for "
                         f"{degree_name} {degree}; got {t.size}")
    n = t.size - degree - 2
    if not t[degree] < t[n + 1]:
        raise ValueError(f"{name} must give a non-empty domain; {name}[{degree}]={_fmt(t[degree])} "
                         f"and {name}[{n + 1}]={_fmt(t[n + 1])} are equal")
    return t


def clamped_knots(n_ctrl, degree, interior=None) -> np.ndarray:
    """A clamped (open) knot vector on [0, 1]: ``degree + 1`` zeros, the interior knots, ``degree + 1`` ones (Goldman §27.7).

    The curve of a clamped knot vector starts at ``P_0`` and ends at ``P_n``, like a Bezier curve.
    n_ctrl: number of control points, >= degree + 1, with ``n_ctrl + degree + 1`` knots at most
    :data:`~goldman_lib.validation.MAX_ITEMS` (the work budget).  degree: int >= 0.  interior: the
    ``n_ctrl - degree - 1`` interior knots in [0, 1] (non-decreasing), or None for equally spaced ones.
    Returns (n_ctrl + degree + 1,).
    Raises ValueError if n_ctrl < degree + 1, the interior has the wrong length, lies outside
    [0, 1], or breaks a rule of :func:`check_knots`.

    >>> clamped_knots(5, 2).tolist()
    [0.0, 0.0, 0.0, 0.3333333333333333, 0.6666666666666666, 1.0, 1.0, 1.0]
    """
    degree = within_budget(degree, "degree", cost=lambda v: 2 * v + 2, what="the knot vector", unit="knots")
    n_ctrl = within_budget(n_ctrl, "n_ctrl", cost=lambda v: v + degree + 1, what="the knot vector", unit="knots",
                           minimum=1)
    if n_ctrl < degree + 1:
        raise ValueError(f"n_ctrl must be at least degree+1 = {degree + 1} for a clamped knot vector; got {n_ctrl}")
    m = n_ctrl - degree - 1
    if interior is None:
        inner = np.arange(1, m + 1) / (m + 1)
    else:
        inner = as_parameter(interior, "interior", low=0.0, high=1.0).reshape(-1)
        if inner.size != m:
            raise ValueError(f"interior must hold n_ctrl - degree - 1 = {m} knots; got {inner.size}")
    knots = np.concatenate([np.zeros(degree + 1), inner, np.ones(degree + 1)])
    return check_knots(knots, degree, n_ctrl)


def uniform_knots(n_ctrl, degree) -> np.ndarray:
    """A uniform (floating) knot vector: ``n_ctrl + degree + 1`` equally spaced knots, scaled so the domain ``[t_p, t_{n+1}]`` is [0, 1] (Goldman §27.7).

    n_ctrl: number of control points, >= degree + 1, with ``n_ctrl + degree + 1`` knots at most
    :data:`~goldman_lib.validation.MAX_ITEMS` (the work budget).  degree: int >= 0.  Returns
    ``(k - degree) / (n_ctrl - degree)`` for k = 0 .. n_ctrl + degree.
    Raises ValueError if n_ctrl < degree + 1.

    >>> uniform_knots(4, 2).tolist()
    [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0]
    """
    degree = within_budget(degree, "degree", cost=lambda v: 2 * v + 2, what="the knot vector", unit="knots")
    n_ctrl = within_budget(n_ctrl, "n_ctrl", cost=lambda v: v + degree + 1, what="the knot vector", unit="knots",
                           minimum=1)
    if n_ctrl < degree + 1:
        raise ValueError(f"n_ctrl must be at least degree+1 = {degree + 1}; got {n_ctrl}")
    return (np.arange(n_ctrl + degree + 1, dtype=float) - degree) / (n_ctrl - degree)


def domain(knots, degree) -> tuple[float, float]:
    """The parameter domain ``(t_p, t_{n+1})`` of a B-spline with these knots (Goldman §27.2).

    >>> domain([0, 0, 0, 0.5, 1, 1, 1], 2)
    (0.0, 1.0)
    """
    t = check_knots(knots, degree)
    return pyramids.domain(t, int(degree))


def multiplicity(knots, value, tol: float = 0.0) -> int:
    """How many times ``value`` occurs in the knot vector (within ``tol``) (Goldman §27.4).

    >>> multiplicity([0, 0, 0, 0.5, 0.5, 1, 1, 1], 0.5)
    2
    """
    t = check_finite(as_float_array(knots, "knots"), "knots")
    value = as_float(value, "value")
    tol = as_float(tol, "tol")
    if tol < 0:
        raise ValueError(f"tol must be >= 0; got {tol}")
    return int(np.count_nonzero(np.abs(t - value) <= tol))


def _check_u(u, t: np.ndarray, p: int, name: str = "u") -> np.ndarray:
    arr = as_parameter(u, name)
    lo, hi = pyramids.domain(t, p)
    if arr.size and (arr.min() < lo or arr.max() > hi):
        bad = (arr < lo) | (arr > hi)
        flat = int(np.flatnonzero(bad)[0])
        where = name if arr.ndim == 0 else f"{name}[{', '.join(str(int(i)) for i in np.unravel_index(flat, arr.shape))}]"
        raise ValueError(f"{name} must lie in the domain [knots[{p}], knots[{t.size - p - 1}]] = "
                         f"[{_fmt(lo)}, {_fmt(hi)}]; {where} is {_fmt(arr.flat[flat])}")
    return arr


def _spans(t: np.ndarray, p: int, u: np.ndarray, side: str = "right") -> np.ndarray:
    """Span index k with t[k] <= u < t[k+1] (side 'right') or t[k] < u <= t[k+1] (side 'left'),
    restricted to the non-empty spans of the domain; u already validated.  Counted among the knots
    strictly inside the first and last non-empty spans, so no clipping is needed."""
    n = t.size - p - 2
    lo_k = int(np.searchsorted(t, t[p], side="right")) - 1        # first non-empty span
    hi_k = int(np.searchsorted(t, t[n + 1], side="left")) - 1     # last non-empty span
    inner = t[lo_k + 1:hi_k + 1]
    side = "right" if side == "right" else "left"
    if u.ndim == 1 and u.size > 4 * inner.size + 16 and not (u[1:] < u[:-1]).any():
        # sorted u (a sampled curve): place the few knots among the parameters instead, and repeat
        # each span index over its run of parameters (the same counts, no binary search per u)
        starts = np.searchsorted(u, inner, side="left" if side == "right" else "right")
        return np.repeat(np.arange(lo_k, hi_k + 1), np.diff(np.concatenate(([0], starts, [u.size]))))
    k = np.searchsorted(inner, u, side=side)
    k += lo_k
    return k


def find_span(knots, degree, u, side: str = "right"):
    """The knot span index ``k`` with ``t_k <= u < t_{k+1}``, ``degree <= k <= n`` (Goldman §27.2).

    At the right end of the domain ``u = t_{n+1}`` the last non-empty span is returned.  With
    ``side="left"`` the span is ``t_k < u <= t_{k+1}`` instead (the left limit at a knot; at the
    left end the first non-empty span).  Only non-empty spans (``t_k < t_{k+1}``) are returned.

    knots: (n+p+2,) valid knots.  degree: int >= 0.  u: scalar or array in the domain.
    Returns an int (scalar u) or an int array of u's shape.
    Raises ValueError for a bad knot vector, a bad side, or u outside [t_p, t_{n+1}].

    >>> find_span([0, 0, 0, 0.5, 1, 1, 1], 2, [0.0, 0.25, 0.5, 1.0]).tolist()
    [2, 2, 3, 3]
    >>> int(find_span([0, 0, 0, 0.5, 1, 1, 1], 2, 0.5, side="left"))
    2
    """
    t = check_knots(knots, degree)
    p = int(degree)
    if side not in ("left", "right"):
        raise ValueError(f"side must be 'left' or 'right'; got {side!r}")
    u = _check_u(u, t, p)
    k = _spans(t, p, u, side)
    return int(k) if np.ndim(k) == 0 else k


# --------------------------------------------------------------------------------------------
# §27.2 the local de Boor algorithm from blossoming
# --------------------------------------------------------------------------------------------

def _curve_args(ctrl, knots, degree, cname="ctrl"):
    p = as_int(degree, "degree", minimum=0)
    P = as_points(ctrl, cname, ndim=2)
    t = check_knots(knots, p, P.shape[0], count_name=f"len({cname})")
    return P, t, p


def control_point_labels(knots, degree) -> list[tuple[float, ...]]:
    """The blossom label of every control point: ``P_i = b(t_{i+1}, ..., t_{i+p})`` (Goldman §27.2).

    >>> control_point_labels([0, 0, 0, 0.5, 1, 1, 1], 2)
    [(0.0, 0.0), (0.0, 0.5), (0.5, 1.0), (1.0, 1.0)]
    """
    t = check_knots(knots, degree)
    p = int(degree)
    n = t.size - p - 2
    return [tuple(float(x) for x in t[i + 1:i + p + 1]) for i in range(n + 1)]


def blossom(ctrl, knots, degree, args, span=None) -> np.ndarray:
    """The blossom ``b_k(u_1, ..., u_p)`` of the polynomial piece on knot span ``k`` (Goldman §27.2).

    The local de Boor pyramid with a different argument on each level: the control points
    ``P_{k-p} .. P_k`` sit at the base with labels ``(t_{i+1}, ..., t_{i+p})``; level ``r``
    combines neighbours with the weights ``(t_{i+p+1-r} - u_r) / (t_{i+p+1-r} - t_i)`` and
    ``(u_r - t_i) / (t_{i+p+1-r} - t_i)``, replacing the label ``t_i`` or ``t_{i+p+1-r}`` by
    ``u_r``.  The blossom is symmetric and multi-affine in its arguments, and
    ``b_k(t_{i+1}, ..., t_{i+p}) = P_i`` for ``k-p <= i <= k``.

    ctrl: (n+1, d).  knots: (n+p+2,).  degree: p.  args: p numbers (any real values).
    span: the span index k (p <= k <= n with t_k < t_{k+1}); default the span of ``args[0]``.
    Returns (d,).
    Raises ValueError for a bad curve, len(args) != p, or a bad span.

    >>> knots = [0, 0, 0, 0.5, 1, 1, 1]
    >>> blossom([[0, 0], [1, 2], [2, 2], [3, 0]], knots, 2, [0.5, 1.0]).tolist()
    [2.0, 2.0]
    """
    P, t, p = _curve_args(ctrl, knots, degree)
    a = np.asarray(as_parameter(args, "args"), dtype=float).reshape(-1)
    if a.size != p:
        raise ValueError(f"args must hold degree = {p} arguments; got {a.size}")
    n = P.shape[0] - 1
    if span is None:
        if p == 0:
            raise ValueError("span must be given for degree 0 (there are no arguments to locate it)")
        lo, hi = pyramids.domain(t, p)
        k = int(_spans(t, p, np.clip(a[0], lo, hi)))
    else:
        k = as_int(span, "span", minimum=p, maximum=n)
        if not t[k] < t[k + 1]:
            raise ValueError(f"span must index a non-empty knot span; knots[{k}] = knots[{k + 1}] = {_fmt(t[k])}")
    with np.errstate(over='ignore', invalid='ignore'):
        out = pyramids.de_boor_blossom(P, t, p, np.array([k]), a[None, :])[0]
    return finite_result(out, "args")


def local_de_boor(ctrl, knots, degree, u) -> np.ndarray:
    """Evaluate a B-spline curve point by point as the diagonal of the blossom, ``C(u) = b_k(u, ..., u)`` (Goldman §27.2).

    The local de Boor algorithm, written straight from blossoming with a Python loop over the
    parameters (a teaching version; :func:`de_boor` is the same pyramid for all parameters at once).

    ctrl: (n+1, d).  knots: (n+p+2,).  degree: p.  u: scalar or array inside the domain.
    Returns u.shape + (d,).  Raises ValueError as :func:`de_boor`.

    >>> local_de_boor([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5).tolist()
    [1.0, 1.0]
    """
    P, t, p = _curve_args(ctrl, knots, degree)
    u = _check_u(u, t, p)
    flat = u.reshape(-1)
    spans = _spans(t, p, flat)
    out = np.empty((flat.size, P.shape[1]))
    for m, (x, k) in enumerate(zip(flat, spans)):
        out[m] = blossom(P, t, p, np.full(p, x), span=int(k)) if p else P[k]
    return out.reshape(u.shape + (P.shape[1],))


def de_boor_steps(ctrl, knots, degree, u) -> list[np.ndarray]:
    """Every level of the local de Boor pyramid at one parameter (Goldman §27.2), for drawing.

    Level 0 holds the ``p+1`` control points ``P_{k-p} .. P_k`` of the span containing u, level r
    holds ``p+1-r`` points, and the last level is the single point ``C(u)``.

    >>> [lvl.tolist() for lvl in de_boor_steps([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5)]
    [[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], [[0.5, 1.0], [1.5, 1.0]], [[1.0, 1.0]]]
    """
    P, t, p = _curve_args(ctrl, knots, degree)
    u = _check_u(u, t, p)
    if u.ndim != 0:
        raise ValueError(f"u must be a scalar for de_boor_steps; got shape {u.shape}")
    x = float(u)
    k = int(_spans(t, p, u))
    pts = P[k - p:k + 1].copy()
    levels = []

    def weight(r, j, q):
        i = k - p + j
        return (x - t[i]) / (t[i + p + 1 - r] - t[i])
    pyramids.de_boor_pyramid(pts, weight, p, record=levels)
    return levels


# --------------------------------------------------------------------------------------------
# §27.3 the global de Boor algorithm and the B-spline basis
# --------------------------------------------------------------------------------------------

def _basis_local(t: np.ndarray, p: int, u: np.ndarray, k: np.ndarray) -> np.ndarray:
    """The p+1 B-splines that are non-zero on span k, N_{k-p,p}(u) .. N_{k,p}(u): (p+1, N)."""
    N = np.empty((p + 1, u.size))
    N[0] = 1.0
    if p == 0:
        return N
    left = [None] + [u - t[k + 1 - j] for j in range(1, p + 1)]
    right = [None] + [t[k + j] - u for j in range(1, p + 1)]
    for j in range(1, p + 1):
        saved = np.zeros(u.size)
        for r in range(j):
            temp = N[r] / (right[r + 1] + left[j - r])
            N[r] = saved + right[r + 1] * temp
            saved = left[j - r] * temp
        N[j] = saved
    return N


def de_boor(ctrl, knots, degree, u) -> np.ndarray:
    """Evaluate a B-spline curve by de Boor's algorithm (Goldman §27.2-27.3).

    For each parameter, the knot span ``[t_k, t_{k+1})`` containing it is found and de Boor's
    pyramid runs on ``P_{k-p} .. P_k``: level ``r`` replaces ``P_{i-1}, P_i`` by
    ``(1 - a) P_{i-1} + a P_i`` with ``a = (u - t_i) / (t_{i+p+1-r} - t_i)``.  All parameters are
    processed at once (one array operation per pyramid node, no Python loop over ``u``).
    ``C(u) = sum_k N_{k,p}(u) P_k`` (:func:`global_de_boor`) is the same curve.

    ctrl: (n+1, d) control points.  knots: (n+p+2,) non-decreasing.  degree: p >= 0.
    u: scalar or array inside [knots[p], knots[n+1]].  Returns u.shape + (d,).
    Raises ValueError naming the rule a knot vector or u breaks; TypeError for non-numeric input.

    >>> de_boor([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5)
    array([1., 1.])
    >>> de_boor([[0, 0], [1, 2], [2, 2], [3, 0]], [0, 0, 0, 0.5, 1, 1, 1], 2, [0.0, 1.0]).tolist()
    [[0.0, 0.0], [3.0, 0.0]]
    """
    P, t, p = _curve_args(ctrl, knots, degree)
    u = _check_u(u, t, p)
    flat = u.reshape(-1)
    k = _spans(t, p, flat)
    out = pyramids.de_boor_points(P, t, p, flat, k)
    return out.T.reshape(u.shape + (P.shape[1],))


def basis(knots, degree, u) -> np.ndarray:
    """All B-spline basis functions ``N_{k,p}(u)``, k = 0..n, at u (Goldman §27.3).

    Computed by the global de Boor (Cox-de Boor) recurrence
    ``N_{k,r}(u) = (u - t_k)/(t_{k+r} - t_k) N_{k,r-1}(u) + (t_{k+r+1} - u)/(t_{k+r+1} - t_{k+1}) N_{k+1,r-1}(u)``
    from the characteristic functions of the knot spans, only for the ``p+1`` functions that are
    non-zero on u's span (the rest are zero: local support).  At the right end of the domain the
    last span's polynomials are used, so the basis is continuous there.

    knots: (n+p+2,).  degree: p.  u: scalar or array inside the domain.
    Returns u.shape + (n+1,).  Raises ValueError as :func:`check_knots` and for u outside the domain.

    >>> basis([0, 0, 0, 1, 1, 1], 2, 0.5)
    array([0.25, 0.5 , 0.25])
    """
    t = check_knots(knots, degree)
    p = int(degree)
    n = t.size - p - 2
    u = _check_u(u, t, p)
    flat = u.reshape(-1)
    k = _spans(t, p, flat)
    local = _basis_local(t, p, flat, k)                        # (p+1, N)
    out = np.zeros((flat.size, n + 1))
    rows = np.arange(flat.size)
    for j in range(p + 1):
        out[rows, k - p + j] = local[j]
    return out.reshape(u.shape + (n + 1,))


def global_de_boor(ctrl, knots, degree, u) -> np.ndarray:
    """Evaluate a B-spline curve as ``sum_k N_{k,p}(u) P_k`` over all control points (Goldman §27.3).

    The global de Boor algorithm: the pyramid run over the whole control polygon, which is the
    basis functions of :func:`basis` times the control points.  Same result as :func:`de_boor`.

    ctrl: (n+1, d).  knots: (n+p+2,).  degree: p.  u: scalar or array inside the domain.
    Returns u.shape + (d,).

    >>> global_de_boor([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5).tolist()
    [1.0, 1.0]
    """
    P, t, p = _curve_args(ctrl, knots, degree)
    return basis(t, p, u) @ P


# --------------------------------------------------------------------------------------------
# §27.4 derivatives and smoothness at the knots
# --------------------------------------------------------------------------------------------

def _derivative_ctrl(P: np.ndarray, t: np.ndarray, p: int):
    """Control points and knots of the derivative (no validation); p >= 1."""
    den = t[p + 1:p + 1 + P.shape[0] - 1] - t[1:P.shape[0]]
    diff = P[1:] - P[:-1]
    scale = np.divide(p, den, out=np.zeros_like(den), where=den > 0)
    return diff * scale[:, None], t[1:-1], p - 1


def derivative_ctrl(ctrl, knots, degree):
    """The derivative of a B-spline curve as a B-spline of one degree less (Goldman §27.4).

    ``C'(u) = sum_i Q_i N_{i+1,p-1}(u)`` with ``Q_i = p (P_{i+1} - P_i) / (t_{i+p+1} - t_{i+1})``
    on the knots ``t_1 .. t_{n+p}`` (the end knots dropped).  Where ``t_{i+p+1} = t_{i+1}`` (a knot
    of multiplicity p+1, where the curve may jump) the basis function of ``Q_i`` vanishes and
    ``Q_i`` is set to 0.

    ctrl: (n+1, d) with n >= 1.  knots: (n+p+2,).  degree: p >= 1.
    Returns ``(Q, knots', p - 1)`` with Q (n, d) and knots' (n+p,).
    Raises ValueError for a bad curve or degree 0.

    >>> Q, t1, p1 = derivative_ctrl([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2)
    >>> Q.tolist(), t1.tolist(), p1
    ([[2.0, 4.0], [2.0, -4.0]], [0.0, 0.0, 1.0, 1.0], 1)
    """
    P, t, p = _curve_args(ctrl, knots, degree)
    if p < 1:
        raise ValueError("degree must be >= 1 to differentiate (a degree-0 spline is piecewise constant)")
    return _derivative_ctrl(P, t, p)


def _evaluate(P: np.ndarray, t: np.ndarray, p: int, flat: np.ndarray, side: str = "right") -> np.ndarray:
    """Validated data, flat u: (N, d)."""
    k = _spans(t, p, flat, side)
    return pyramids.de_boor_points(P, t, p, flat, k).T


def derivative(ctrl, knots, degree, u, order: int = 1, side: str = "right") -> np.ndarray:
    """The ``order``-th derivative of a B-spline curve at u (Goldman §27.4).

    Differentiates the control polygon ``order`` times (:func:`derivative_ctrl`) and runs de Boor
    on the result.  At a knot the derivative may jump: ``side="right"`` gives the derivative from
    the right (the polynomial of the span starting at u), ``side="left"`` from the left.  Above the
    degree the derivative is 0.

    ctrl: (n+1, d).  knots: (n+p+2,).  degree: p.  u: scalar or array inside the domain.
    order: int >= 0.  Returns u.shape + (d,).
    Raises ValueError as :func:`de_boor`, for a negative order, or a side other than left/right.

    >>> derivative([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5).tolist()
    [2.0, 0.0]
    """
    P, t, p = _curve_args(ctrl, knots, degree)
    order = as_int(order, "order", minimum=0)
    if side not in ("left", "right"):
        raise ValueError(f"side must be 'left' or 'right'; got {side!r}")
    u = _check_u(u, t, p)
    flat = u.reshape(-1)
    if order > p:
        return np.zeros(u.shape + (P.shape[1],))
    Q, s, q = P, t, p
    # spans are located on the original knots, so a one-sided limit keeps its side at every order
    k = _spans(t, p, flat, side)
    for _ in range(order):
        Q, s, q = _derivative_ctrl(Q, s, q)
    out = pyramids.de_boor_points(Q, s, q, flat, k - order).T
    return out.reshape(u.shape + (P.shape[1],))


def continuity_at(knots, degree, value) -> int:
    """The order of continuity ``C^(p - m)`` of every B-spline at a knot of multiplicity ``m`` (Goldman §27.4).

    Returns ``degree - multiplicity(knots, value)``: ``p`` (a polynomial, C^infinity in fact)
    where value is not a knot, ``-1`` where the curve may jump (multiplicity p+1).

    >>> continuity_at([0, 0, 0, 0, 0.5, 0.5, 1, 1, 1, 1], 3, 0.5)
    1
    """
    t = check_knots(knots, degree)
    return int(degree) - multiplicity(t, value)


def derivative_jumps(ctrl, knots, degree, value) -> np.ndarray:
    """The jumps ``|C^(r)(value+) - C^(r)(value-)|`` of the derivatives r = 0..p at an interior parameter (Goldman §27.4).

    At a knot of multiplicity m the first ``p - m + 1`` entries (orders 0 .. p-m) are 0 up to
    rounding: the curve is ``C^(p-m)`` there.

    ctrl: (n+1, d).  knots: (n+p+2,).  degree: p.  value: a scalar strictly inside the domain.
    Returns (p+1,) Euclidean lengths of the jumps.

    >>> derivative_jumps([[0], [0], [1], [0]], [0, 0, 0, 0.5, 1, 1, 1], 2, 0.5).round(12).tolist()
    [0.0, 0.0, 16.0]
    """
    P, t, p = _curve_args(ctrl, knots, degree)
    x = _check_u(as_float(value, "value"), t, p, "value")
    lo, hi = pyramids.domain(t, p)
    if not lo < x < hi:
        raise ValueError(f"value must lie strictly inside the domain ({_fmt(lo)}, {_fmt(hi)}); got {_fmt(x)}")
    out = np.empty(p + 1)
    for r in range(p + 1):
        right = derivative(P, t, p, x, r, side="right")
        left = derivative(P, t, p, x, r, side="left")
        out[r] = np.linalg.norm(right - left)
    return finite_result(out, "ctrl", why="is too large in magnitude (or knots too close)")


# --------------------------------------------------------------------------------------------
# §27.5 labelling and locality in the global de Boor algorithm
# --------------------------------------------------------------------------------------------

def global_pyramid_labels(knots, degree) -> list[list[dict]]:
    """The blossom labels and the locality of every node of the global de Boor pyramid (Goldman §27.5).

    The global pyramid runs the de Boor recurrence over *all* control points: level 0 holds
    ``P_0 .. P_n`` with labels ``(t_{i+1}, ..., t_{i+p})``; level r holds nodes i = r..n,

    ``P_i^r(u) = ((t_{i+p+1-r} - u) P_{i-1}^{r-1} + (u - t_i) P_i^{r-1}) / (t_{i+p+1-r} - t_i)``,

    with the label ``(u^r, t_{i+1}, ..., t_{i+p-r})``: r copies of u and the knots the parents share.
    Locality: the node is a polynomial of degree r in u, and it is the blossom value
    ``b_k(u^r, t_{i+1}, ..., t_{i+p-r})`` of the piece on every span k with ``i <= k <= i+p-r``,
    that is for u in ``[t_i, t_{i+p+1-r}]``; the apex nodes (r = p) are the pieces themselves, node k
    being C(u) only for u in ``[t_k, t_{k+1})``.

    knots: (n+p+2,) valid for degree p.  Returns a list of p+1 levels; level r lists, for
    i = r..n, a dict with ``index`` i, ``knots`` (the p-r knots of the label), ``u_count`` r,
    ``interval`` ``(t_i, t_{i+p+1-r})`` (the edge factors are ``interval[1] - u`` on the edge from
    node i-1 and ``u - interval[0]`` on the edge from node i), ``spans`` (the non-empty spans k that
    use the node) and ``defined`` (False when the interval is empty: a knot repeated p+2-r or more
    times; such a node is used by no span).
    Raises ValueError/TypeError for a bad knot vector or degree.

    >>> levels = global_pyramid_labels([0, 0, 0, 1, 2, 2, 2], 2)
    >>> [(d["index"], d["knots"], d["interval"], d["spans"]) for d in levels[1]]
    [(1, (0.0,), (0.0, 1.0), [2]), (2, (1.0,), (0.0, 2.0), [2, 3]), (3, (2.0,), (1.0, 2.0), [3])]
    """
    p = as_int(degree, "degree", minimum=0)
    t = check_knots(knots, p)
    n = t.size - p - 2
    levels = []
    for r in range(p + 1):
        level = []
        for i in range(r, n + 1):
            lo, hi = float(t[i]), float(t[i + p + 1 - r])
            spans = [k for k in range(max(i, p), min(i + p - r, n) + 1) if t[k] < t[k + 1]]
            level.append({"index": i, "knots": tuple(float(x) for x in t[i + 1:i + p + 1 - r]), "u_count": r,
                          "interval": (lo, hi), "spans": spans, "defined": lo < hi})
        levels.append(level)
    return levels


def global_pyramid(ctrl, knots, degree, u) -> list[np.ndarray]:
    """The values of every node of the global de Boor pyramid at one parameter u (Goldman §27.5).

    Level r is an array (n+1-r, d) of the nodes i = r..n of :func:`global_pyramid_labels`
    (row ``i - r``).  Each node is computed by the recurrence for *any* real u (a polynomial of
    degree r in u); by locality it is the blossom value ``b_k(u^r, t_{i+1}, ..., t_{i+p-r})`` of the
    pieces k listed in its ``spans``, and the apex row holds every piece of the curve at u:
    ``global_pyramid(...)[p][k - p]`` is C(u) when u lies in span k.  A node whose interval is
    empty (``defined`` False in the labels) belongs to no piece; its row holds NaN, by design.

    ctrl: (n+1, d).  knots: (n+p+2,).  degree: p.  u: a finite scalar (any real value).
    Returns a list of p+1 arrays.  Raises ValueError/TypeError for a bad curve or u, and ValueError
    naming u when u is so far from the knots that a node overflows float64.

    >>> top = global_pyramid([[0, 0], [1, 2], [2, 2], [3, 0]], [0, 0, 0, 1, 2, 2, 2], 2, 0.5)[-1]
    >>> top.tolist()   # the pieces on [0, 1) and [1, 2) at u = 0.5; the first is C(0.5)
    [[0.875, 1.5], [1.125, 1.5]]
    """
    P, t, p = _curve_args(ctrl, knots, degree)
    x = as_parameter(u, "u")
    if x.ndim != 0:
        raise ValueError(f"u must be a scalar for global_pyramid; got shape {x.shape}")
    x = float(x)
    n = P.shape[0] - 1
    levels = []

    def weight(r):                      # nodes i = r .. n of level r
        lo, hi = t[r:n + 1], t[r + p + 1 - r:n + p + 2 - r]
        den = hi - lo
        return np.divide(x - lo, den, out=np.full(den.shape, np.nan), where=den > 0)
    with np.errstate(over="ignore", invalid="ignore"):
        pyramids.de_boor_pyramid(P.copy(), weight, p, top=n, record=levels, per_level=True)
    for r in range(1, p + 1):
        ok = t[r + p + 1 - r:n + p + 2 - r] - t[r:n + 1] > 0
        finite_result(levels[r][ok], "u", x)   # an overflow (|u| huge) is reported naming u; undefined nodes stay NaN
    return levels


# --------------------------------------------------------------------------------------------
# §27.6 every spline is a B-spline
# --------------------------------------------------------------------------------------------

def _elementary_symmetric(args: np.ndarray) -> np.ndarray:
    """e_0 .. e_p of p numbers (the coefficients of prod (1 + a_i x))."""
    e = np.zeros(args.size + 1)
    e[0] = 1.0
    for a in args:
        e[1:] = e[1:] + a * e[:-1]
    return e


def _monomial_blossom(coeffs: np.ndarray, args: np.ndarray) -> np.ndarray:
    """Blossom of sum_m coeffs[m] t^m (coeffs (p+1, d)) at p arguments: sum_m c_m e_m / C(p, m)."""
    p = args.size
    e = _elementary_symmetric(args)
    w = e / np.array([math.comb(p, m) for m in range(p + 1)], dtype=float)
    return w @ coeffs


def spline_to_bspline(pieces, breaks, continuity):
    """Write a piecewise polynomial with given smoothness in B-spline form (Goldman §27.6).

    Piece ``i`` is the polynomial ``sum_m pieces[i, m] u^m`` on ``[breaks[i], breaks[i+1]]``
    (power coefficients in the global parameter u, lowest first, as numpy.polynomial).  At the
    interior break ``breaks[i]`` the pieces join with ``C^c`` continuity, ``c = continuity[i-1]``
    in ``-1 .. p-1``.  The knot vector repeats each interior break ``p - c`` times and each end
    ``p + 1`` times, and the control point ``P_j`` is the blossom of any piece whose span lies
    in the support of ``N_{j,p}``, at ``(t_{j+1}, ..., t_{j+p})`` -- the smoothness is exactly
    what makes these blossoms agree (the dual functional property).

    pieces: (L, p+1, d).  breaks: (L+1,) strictly increasing.  continuity: an int for every
    break or (L-1,) ints in -1 .. p-1.  Returns ``(ctrl, knots, p)``.
    Raises ValueError if the shapes disagree, the breaks do not increase, a continuity is out
    of range, or the pieces do not actually join with the stated smoothness (naming the break).

    >>> # the parabola u^2 on [0, 2], cut at 1 with C^1 continuity
    >>> ctrl, knots, p = spline_to_bspline([[[0], [0], [1]], [[0], [0], [1]]], [0, 1, 2], 1)
    >>> ctrl.ravel().tolist(), knots.tolist()
    ([0.0, 0.0, 2.0, 4.0], [0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])
    """
    C = as_points(pieces, "pieces", ndim=3)
    L, p1, d = C.shape
    p = p1 - 1
    br = as_parameter(breaks, "breaks").reshape(-1)
    if br.size != L + 1:
        raise ValueError(f"breaks must hold len(pieces) + 1 = {L + 1} numbers; got {br.size}")
    if np.any(np.diff(br) <= 0):
        i = int(np.flatnonzero(np.diff(br) <= 0)[0]) + 1
        raise ValueError(f"breaks must be strictly increasing; breaks[{i}]={_fmt(br[i])} <= breaks[{i - 1}]={_fmt(br[i - 1])}")
    try:
        cont = np.asarray(continuity)
    except ValueError:
        raise TypeError(f"continuity must be an int or a sequence of ints; got {continuity!r}") from None
    if cont.ndim == 0:
        cont = np.full(max(L - 1, 0), cont)
    cont = np.asarray([as_int(c, "continuity", minimum=-1, maximum=p - 1) for c in cont.reshape(-1)], dtype=int)
    if cont.size != L - 1:
        raise ValueError(f"continuity must hold one order per interior break, {L - 1}; got {cont.size}")
    knots = np.concatenate([np.full(p + 1, br[0])] + [np.full(p - c, b) for b, c in zip(br[1:-1], cont)]
                           + [np.full(p + 1, br[-1])])
    n = knots.size - p - 2
    ctrl = np.empty((n + 1, d))
    piece_of_span = np.searchsorted(br, knots[:-1], side="right") - 1
    for j in range(n + 1):
        k = next(k for k in range(max(j, p), min(j + p, n) + 1) if knots[k] < knots[k + 1])
        ctrl[j] = _monomial_blossom(C[piece_of_span[k]], knots[j + 1:j + p + 1])
    # check: the B-spline must reproduce every piece (it does iff the stated smoothness holds)
    try:
        back, _ = bspline_to_pieces(ctrl, knots, p)
    except ValueError:
        raise ValueError("breaks are too large in magnitude: the pieces' power coefficients overflow float64") from None
    scale = max(1.0, float(np.abs(C).max()))
    bad = np.abs(back - C).max(axis=(1, 2)) > 1e-8 * scale * (1 + np.abs(br).max()) ** p
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        where = max(i, 1)
        raise ValueError(f"pieces must join with the stated continuity; piece {i} is not reproduced "
                         f"(check the smoothness at breaks[{where}]={_fmt(br[where])})")
    return ctrl, knots, p


def bspline_to_pieces(ctrl, knots, degree):
    """The polynomial pieces of a B-spline curve in power form (Goldman §27.6).

    For every non-empty knot span ``[t_k, t_{k+1}]`` of the domain, the coefficients of
    ``sum_m c_m u^m`` (global parameter, lowest first), found from the right derivatives at
    ``t_k`` (Taylor) and expanded about 0.

    ctrl: (n+1, d).  knots: (n+p+2,).  degree: p.
    Returns ``(pieces, breaks)``: pieces (L, p+1, d), breaks (L+1,).

    >>> pieces, breaks = bspline_to_pieces([[0], [0], [2], [4]], [0, 0, 0, 1, 2, 2, 2], 2)
    >>> pieces[:, :, 0].round(12).tolist(), breaks.tolist()
    ([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]], [0.0, 1.0, 2.0])
    """
    P, t, p = _curve_args(ctrl, knots, degree)
    n = P.shape[0] - 1
    starts = np.array([k for k in range(p, n + 1) if t[k] < t[k + 1]])
    a = t[starts]
    breaks = np.append(a, t[n + 1])
    taylor = np.stack([derivative(P, t, p, a, r) / math.factorial(r) for r in range(p + 1)], 1)  # (L, p+1, d)
    pieces = np.zeros_like(taylor)
    for m in range(p + 1):            # c_m (u - a)^m = sum_j c_m C(m, j) (-a)^(m-j) u^j
        for j in range(m + 1):
            pieces[:, j] += taylor[:, m] * (math.comb(m, j) * (-a) ** (m - j))[:, None]
    return finite_result(pieces, "knots", why="are too large in magnitude (powers of the knots)"), breaks


# --------------------------------------------------------------------------------------------
# §27.7 properties: local support, local control
# --------------------------------------------------------------------------------------------

def support(knots, degree, i) -> tuple[float, float]:
    """The interval ``[t_i, t_{i+p+1}]`` outside which the basis function ``N_{i,p}`` vanishes (Goldman §27.7).

    >>> support([0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1], 2, 3)
    (0.25, 1.0)
    """
    t = check_knots(knots, degree)
    p = int(degree)
    i = as_int(i, "i", minimum=0, maximum=t.size - p - 2)
    return float(t[i]), float(t[i + p + 1])


def affected_span(knots, degree, i) -> tuple[float, float]:
    """The part of the domain that moves when control point ``P_i`` moves: local control (Goldman §27.7).

    It is the support of ``N_{i,p}`` cut to the domain ``[t_p, t_{n+1}]``.

    >>> affected_span([0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1], 2, 0)
    (0.0, 0.25)
    """
    t = check_knots(knots, degree)
    p = int(degree)
    lo, hi = support(t, p, i)
    dlo, dhi = pyramids.domain(t, p)
    return max(lo, dlo), min(hi, dhi)


# --------------------------------------------------------------------------------------------
# §27.8 tensor-product B-spline surfaces
# --------------------------------------------------------------------------------------------

def _surface_args(ctrl, knots_u, knots_v, degree_u, degree_v, cname="ctrl"):
    P = as_points(ctrl, cname, ndim=3)
    pu = as_int(degree_u, "degree_u", minimum=0)
    pv = as_int(degree_v, "degree_v", minimum=0)
    tu = check_knots(knots_u, pu, P.shape[0], "knots_u", degree_name="degree_u", count_name=f"{cname}.shape[0]")
    tv = check_knots(knots_v, pv, P.shape[1], "knots_v", degree_name="degree_v", count_name=f"{cname}.shape[1]")
    return P, tu, tv, pu, pv


def _basis_dense(t: np.ndarray, p: int, flat: np.ndarray) -> np.ndarray:
    n = t.size - p - 2
    k = _spans(t, p, flat)
    local = _basis_local(t, p, flat, k)
    out = np.zeros((flat.size, n + 1))
    rows = np.arange(flat.size)
    for j in range(p + 1):
        out[rows, k - p + j] = local[j]
    return out


def surface_de_boor(ctrl, knots_u, knots_v, degree_u, degree_v, u, v) -> np.ndarray:
    """Evaluate a tensor-product B-spline surface at parameter pairs (u, v) (Goldman §27.8).

    ``S(u, v) = sum_i sum_j N_{i,p}(u) N_{j,q}(v) P_ij``: de Boor in v along each of the p+1 rows
    of the control net that matter for u's span, then de Boor in u on the results -- computed
    here with the p+1 and q+1 non-zero basis functions of the two spans.

    ctrl: (m+1, n+1, d).  knots_u: (m+p+2,).  knots_v: (n+q+2,).  degree_u: p.  degree_v: q.
    u, v: scalars or arrays that broadcast, inside their domains.  Returns broadcast shape + (d,).
    Raises ValueError naming the knot vector or parameter that breaks a rule.

    >>> net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    >>> surface_de_boor(net, [0, 0, 1, 1], [0, 0, 1, 1], 1, 1, 0.5, 0.5).tolist()
    [0.5, 0.5, 0.25]
    """
    P, tu, tv, pu, pv = _surface_args(ctrl, knots_u, knots_v, degree_u, degree_v)
    u = _check_u(u, tu, pu, "u")
    v = _check_u(v, tv, pv, "v")
    u, v = np.broadcast_arrays(u, v)
    fu, fv = u.reshape(-1), v.reshape(-1)
    ku, kv = _spans(tu, pu, fu), _spans(tv, pv, fv)
    Nu = _basis_local(tu, pu, fu, ku)            # (p+1, N)
    Nv = _basis_local(tv, pv, fv, kv)            # (q+1, N)
    out = np.zeros((fu.size, P.shape[2]))
    for a in range(pu + 1):
        for b in range(pv + 1):
            out += (Nu[a] * Nv[b])[:, None] * P[ku - pu + a, kv - pv + b]
    return out.reshape(u.shape + (P.shape[2],))


def surface_grid(ctrl, knots_u, knots_v, degree_u, degree_v, u, v) -> np.ndarray:
    """Evaluate a tensor-product B-spline surface on the grid u x v as ``N(u) P N(v)^T`` (Goldman §27.8).

    One product of basis matrices per coordinate: ``N(u)`` (a, m+1) from :func:`basis`, the net
    (m+1, n+1), ``N(v)^T`` (n+1, b).  The fast path for meshes.

    ctrl: (m+1, n+1, d).  u: (a,), v: (b,) 1-D parameter arrays inside the domains.
    Returns (a, b, d) with ``[i, j] = S(u[i], v[j])``.

    >>> net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    >>> surface_grid(net, [0, 0, 1, 1], [0, 0, 1, 1], 1, 1, [0, 1], [0, 0.5, 1])[:, :, 2].tolist()
    [[0.0, 0.0, 0.0], [0.0, 0.5, 1.0]]
    """
    P, tu, tv, pu, pv = _surface_args(ctrl, knots_u, knots_v, degree_u, degree_v)
    u = _check_u(u, tu, pu, "u")
    v = _check_u(v, tv, pv, "v")
    for name, arr in (("u", u), ("v", v)):
        if arr.ndim != 1:
            raise ValueError(f"{name} must be a 1-D array of parameters; got shape {arr.shape}")
    Nu = _basis_dense(tu, pu, u)                  # (a, m+1)
    Nv = _basis_dense(tv, pv, v)                  # (b, n+1)
    out = Nu @ P.transpose(2, 0, 1) @ Nv.T        # (d, a, b)
    return np.ascontiguousarray(np.moveaxis(out, 0, -1))


# --------------------------------------------------------------------------------------------
# §27.9 NURBS
# --------------------------------------------------------------------------------------------

def _weights(weights, shape, name="weights") -> np.ndarray:
    w = np.asarray(as_parameter(weights, name), dtype=float)
    if w.shape != shape:
        raise ValueError(f"{name} must have shape {shape} (one weight per control point); got {w.shape}")
    bad = np.flatnonzero(w.reshape(-1) <= 0)
    if bad.size:
        idx = ", ".join(str(int(i)) for i in np.unravel_index(int(bad[0]), w.shape))
        raise ValueError(f"{name} must be positive; {name}[{idx}] is {_fmt(w.reshape(-1)[bad[0]])}")
    return w


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def nurbs_curve(ctrl, weights, knots, degree, u) -> np.ndarray:
    """Evaluate a NURBS curve ``sum w_k N_k(u) P_k / sum w_k N_k(u)`` (Goldman §27.9).

    The rational curve is the perspective projection of the polynomial B-spline with
    homogeneous control points ``(w_k P_k, w_k)``: run de Boor on those, then divide by the last
    coordinate.

    ctrl: (n+1, d).  weights: (n+1,) positive.  knots: (n+p+2,).  degree: p.  u: scalar or array
    inside the domain.  Returns u.shape + (d,).
    Raises ValueError for non-positive or mis-shaped weights, and as :func:`de_boor`.

    >>> c = nurbs_curve([[1, 0], [1, 1], [0, 1]], [1, 2 ** -0.5, 1], [0, 0, 0, 1, 1, 1], 2, 0.5)
    >>> round(float(np.hypot(*c)), 12)
    1.0
    """
    P, t, p = _curve_args(ctrl, knots, degree)
    w = _weights(weights, (P.shape[0],))
    H = np.concatenate([P * w[:, None], w[:, None]], axis=1)
    u = _check_u(u, t, p)
    flat = u.reshape(-1)
    h = _evaluate(H, t, p, flat)
    with np.errstate(all="ignore"):
        out = (h[:, :-1] / h[:, -1:]).reshape(u.shape + (P.shape[1],))
    return finite_result(out, "weights", why=_WEIGHTS_TOO_WIDE)


_WEIGHTS_TOO_WIDE = "are too large (or too far apart) for float64 times the control points"


def rational_basis(knots, degree, weights, u) -> np.ndarray:
    """The rational basis functions of a NURBS curve, ``R_k(u) = w_k N_k,p(u) / sum_j w_j N_j,p(u)``
    (Goldman §27.9): ``u.shape + (n+1,)``, summing to 1 at every ``u`` like the B-splines they
    weight.  weights: (n+1,) positive; other arguments as :func:`basis`.

    >>> R = rational_basis([0, 0, 0, 1, 1, 1], 2, [1, 2 ** -0.5, 1], [0.0, 0.5, 1.0])
    >>> R.sum(axis=-1).round(12).tolist(), R[1].round(6).tolist()
    ([1.0, 1.0, 1.0], [0.292893, 0.414214, 0.292893])
    """
    N = basis(knots, degree, u)
    w = _weights(weights, (N.shape[-1],))
    weighted = N * w
    return weighted / weighted.sum(axis=-1, keepdims=True)


# -- knot vectors an editor can hold (the knot-vector editor of chapters 27-28) ---------------------
# Public for the views (no underscore) but out of __all__: they map any slider values to a legal
# knot vector instead of refusing them, so the learner-facing checks of __all__ do not apply.

#: The knot-vector presets of :func:`knots_from_values` (the knot-vector editor of chapters 27-28).
KNOT_PRESETS = ("clamped", "uniform", "custom")

#: The least gap kept between interior knots where more than ``max(p, 1)`` would coincide, and
#: between interior knots and the ends 0 and 1 (a slider step).
KNOT_GAP = 0.01

def _knot_cap(degree: int) -> int:
    return max(int(degree), 1)


def knots_from_values(values, degree, n_ctrl, preset: str = "custom") -> np.ndarray:
    """Map any slider values to a valid knot vector with domain [0, 1] (Goldman §27.3: knots never
    decrease, at most ``p`` interior knots coincide; the rule is ours, for the knot-vector editor).

    ``preset="clamped"``: p+1 zeros, ``n_ctrl-p-1`` evenly spaced interior knots, p+1 ones.
    ``preset="uniform"``: :func:`uniform_knots`.  ``preset="custom"``:
    clamped ends, interior knots from the first ``n_ctrl-p-1`` values: each clipped into
    [KNOT_GAP, 1-KNOT_GAP], raised to its left neighbour if below it, and moved apart by KNOT_GAP where more than
    ``max(p, 1)`` would coincide (a backward pass then keeps them below 1-KNOT_GAP).  Extra values are
    ignored; missing or non-finite ones are taken from the clamped preset.

    values: sequence of floats.  degree: int >= 0 (clipped into [0, n_ctrl-1]).  n_ctrl: >= 1.
    Returns (n_ctrl + p + 1,) knots that :func:`check_knots` accepts.
    Raises ValueError only for an unknown preset.

    >>> knots_from_values([0.5, 0.5, 0.5], 2, 6, "custom").tolist()
    [0.0, 0.0, 0.0, 0.5, 0.5, 0.51, 1.0, 1.0, 1.0]
    >>> knots_from_values([], 2, 4, "uniform").tolist()
    [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0]
    """
    if preset not in KNOT_PRESETS:
        raise ValueError(f"preset must be one of {KNOT_PRESETS}; got {preset!r}")
    n_ctrl = max(int(n_ctrl), 1)
    p = int(min(max(int(degree), 0), n_ctrl - 1))
    if preset == "uniform":
        return uniform_knots(n_ctrl, p)
    m = n_ctrl - p - 1
    even = np.arange(1, m + 1) / (m + 1)
    if preset == "clamped" or m == 0:
        inner = even
    else:
        v = np.asarray(list(values)[:m] if values is not None else [], dtype=float)
        v = np.concatenate([v, even[v.size:]])
        v = np.where(np.isfinite(v), v, even)
        inner = _legal_interior_knots(v, _knot_cap(p))
    return np.concatenate([np.zeros(p + 1), inner, np.ones(p + 1)])


def _legal_interior_knots(v: np.ndarray, cap: int) -> np.ndarray:
    """Forward pass (clip, raise to the left neighbour, keep cap+1 apart) then backward pass."""
    m = v.size
    lo, hi = KNOT_GAP, 1.0 - KNOT_GAP
    gap = min(KNOT_GAP, (hi - lo) / (m // cap + 1))
    t = np.clip(v, lo, hi).astype(float)
    for i in range(m):
        if i:
            t[i] = max(t[i], t[i - 1])
        if i >= cap:
            t[i] = max(t[i], t[i - cap] + gap)
    for i in range(m - 1, -1, -1):
        t[i] = min(t[i], hi)
        if i + 1 < m:
            t[i] = min(t[i], t[i + 1])
        if i + cap < m:
            t[i] = min(t[i], t[i + cap] - gap)
    return np.round(t, 12)


def push_knots(values, moved: int, degree) -> np.ndarray:
    """The push rule applied to the sliders when knot ``moved`` is dragged: its neighbours on the
    side it moved to are pushed along, so the moved knot keeps its value where it can.

    >>> push_knots([0.2, 0.4, 0.6], 0, 2).tolist()      # unchanged: already legal
    [0.2, 0.4, 0.6]
    >>> push_knots([0.7, 0.4, 0.6], 0, 2).tolist()      # knot 0 dragged to 0.7 pushes 1 and 2
    [0.7, 0.7, 0.71]
    >>> push_knots([0.2, 0.1, 0.6], 1, 2).tolist()      # knot 1 dragged to 0.1 pushes 0 down
    [0.1, 0.1, 0.6]
    """
    v = np.asarray(values, dtype=float).copy()
    m = v.size
    cap = _knot_cap(degree)
    lo, hi = KNOT_GAP, 1.0 - KNOT_GAP
    gap = min(KNOT_GAP, (hi - lo) / (m // cap + 1))
    v = np.clip(v, lo, hi)
    x = v[moved]
    # where can the moved knot go so that the knots on both sides still fit?
    left_room = lo + (moved // cap) * gap
    right_room = hi - ((m - 1 - moved) // cap) * gap
    x = min(max(x, left_room), right_room)
    v[moved] = x
    for i in range(moved + 1, m):             # push right neighbours up
        v[i] = max(v[i], v[i - 1])
        if i - cap >= 0:
            v[i] = max(v[i], v[i - cap] + gap)
    for i in range(moved - 1, -1, -1):        # push left neighbours down
        v[i] = min(v[i], v[i + 1])
        if i + cap < m:
            v[i] = min(v[i], v[i + cap] - gap)
    return np.round(_legal_interior_knots(v, cap), 12)


def interior_values(knots, degree) -> np.ndarray:
    """The interior knots ``t_{p+1} .. t_n`` of a knot vector (what the sliders show).

    >>> interior_values([0, 0, 0, 0.3, 0.6, 1, 1, 1], 2).tolist()
    [0.3, 0.6]
    """
    t = np.asarray(knots, dtype=float)
    p = int(degree)
    return t[p + 1:t.size - p - 1]


def _homogeneous_net(ctrl, weights, knots_u, knots_v, degree_u, degree_v):
    P, tu, tv, pu, pv = _surface_args(ctrl, knots_u, knots_v, degree_u, degree_v)
    w = _weights(weights, P.shape[:2])
    H = np.concatenate([P * w[..., None], w[..., None]], axis=2)
    return H, tu, tv, pu, pv


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def nurbs_surface(ctrl, weights, knots_u, knots_v, degree_u, degree_v, u, v) -> np.ndarray:
    """Evaluate a NURBS surface at parameter pairs (u, v) (Goldman §27.9).

    The tensor-product B-spline of the homogeneous net ``(w_ij P_ij, w_ij)`` divided by its last
    coordinate.

    ctrl: (m+1, n+1, d).  weights: (m+1, n+1) positive.  Other arguments as :func:`surface_de_boor`.
    Returns broadcast(u, v).shape + (d,).

    >>> ctrl, w, tu, tv, p, q = nurbs_sphere()
    >>> round(float(np.linalg.norm(nurbs_surface(ctrl, w, tu, tv, p, q, 0.3, 0.6))), 12)
    1.0
    """
    H, tu, tv, pu, pv = _homogeneous_net(ctrl, weights, knots_u, knots_v, degree_u, degree_v)
    h = surface_de_boor(H, tu, tv, pu, pv, u, v)
    with np.errstate(all="ignore"):
        return finite_result(h[..., :-1] / h[..., -1:], "weights", why=_WEIGHTS_TOO_WIDE)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def nurbs_surface_grid(ctrl, weights, knots_u, knots_v, degree_u, degree_v, u, v) -> np.ndarray:
    """Evaluate a NURBS surface on the grid u x v (Goldman §27.9); the fast path of :func:`nurbs_surface`.

    Returns (a, b, d) for 1-D u (a,) and v (b,).

    >>> ctrl, w, tu, tv, p, q = nurbs_sphere()
    >>> g = nurbs_surface_grid(ctrl, w, tu, tv, p, q, np.linspace(0, 1, 5), np.linspace(0, 1, 3))
    >>> bool(np.allclose(np.linalg.norm(g, axis=-1), 1.0))
    True
    """
    H, tu, tv, pu, pv = _homogeneous_net(ctrl, weights, knots_u, knots_v, degree_u, degree_v)
    h = surface_grid(H, tu, tv, pu, pv, u, v)
    with np.errstate(all="ignore"):
        return finite_result(h[..., :-1] / h[..., -1:], "weights", why=_WEIGHTS_TOO_WIDE)


_QUARTER = np.array([0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0])


def nurbs_circle(radius: float = 1.0, center=(0.0, 0.0)):
    """A whole circle as an exact quadratic NURBS curve: 9 control points on a square (Goldman §27.9).

    Each quarter is a rational quadratic Bezier arc with weights ``1, sqrt(2)/2, 1`` (the middle
    control point is the corner of the square); knots ``0,0,0, 1/4,1/4, 1/2,1/2, 3/4,3/4, 1,1,1``.

    radius: positive.  center: (2,).  Returns ``(ctrl (9, 2), weights (9,), knots (12,), 2)``.
    Raises ValueError for a non-positive radius or a bad center.

    >>> ctrl, w, knots, p = nurbs_circle()
    >>> pts = nurbs_curve(ctrl, w, knots, p, np.linspace(0, 1, 7))
    >>> bool(np.abs(np.hypot(pts[:, 0], pts[:, 1]) - 1).max() < 1e-15)
    True
    """
    r = as_float(radius, "radius", positive=True)
    c = as_points(center, "center", ndim=1, dim=2)
    sq = np.array([[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]], dtype=float)
    w = np.where(np.arange(9) % 2 == 1, math.sqrt(0.5), 1.0)
    return c + r * sq, w, _QUARTER.copy(), 2


def nurbs_sphere(radius: float = 1.0, center=(0.0, 0.0, 0.0)):
    """A whole sphere as an exact biquadratic NURBS surface: a half circle swept around the z axis (Goldman §27.9).

    The net is the tensor product of the circle of :func:`nurbs_circle` (u, around the z axis)
    and a half circle from the south pole to the north pole (v; 5 control points, knots
    ``0,0,0, 1/2,1/2, 1,1,1``): ``P_ij = (x_j c_i, z_j)``, ``w_ij = w_i w_j``.

    radius: positive.  center: (3,).
    Returns ``(ctrl (9, 5, 3), weights (9, 5), knots_u (12,), knots_v (8,), 2, 2)``.

    >>> ctrl, w, tu, tv, p, q = nurbs_sphere(2.0)
    >>> ctrl.shape, w.shape
    ((9, 5, 3), (9, 5))
    """
    r = as_float(radius, "radius", positive=True)
    c = as_points(center, "center", ndim=1, dim=3)
    circ, wc, tu, _ = nurbs_circle()
    prof = np.array([[0, -1], [1, -1], [1, 0], [1, 1], [0, 1]], dtype=float)   # (x, z) of the half circle
    wp = np.array([1.0, math.sqrt(0.5), 1.0, math.sqrt(0.5), 1.0])
    tv = np.array([0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0])
    ctrl = np.empty((9, 5, 3))
    ctrl[..., 0] = circ[:, None, 0] * prof[None, :, 0]
    ctrl[..., 1] = circ[:, None, 1] * prof[None, :, 0]
    ctrl[..., 2] = np.broadcast_to(prof[None, :, 1], (9, 5))
    return c + r * ctrl, wc[:, None] * wp[None, :], tu, tv, 2, 2


# --------------------------------------------------------------------------------------------
# thin classes for the notebook
# --------------------------------------------------------------------------------------------

class BSplineCurve:
    """A B-spline curve: control points, knots and degree, validated once (Goldman §27.2-27.7).

    >>> c = BSplineCurve([[0, 0], [1, 2], [2, 2], [3, 0]], [0, 0, 0, 0.5, 1, 1, 1], 2)
    >>> c.evaluate(0.5).tolist(), c.domain
    ([1.5, 2.0], (0.0, 1.0))
    """

    def __init__(self, ctrl, knots, degree):
        self.ctrl, self.knots, self.degree = _curve_args(ctrl, knots, degree)

    @property
    def domain(self) -> tuple[float, float]:
        return pyramids.domain(self.knots, self.degree)

    def evaluate(self, u) -> np.ndarray:
        """Points ``C(u)`` by :func:`de_boor`."""
        return de_boor(self.ctrl, self.knots, self.degree, u)

    def basis(self, u) -> np.ndarray:
        """Basis values ``N_{k,p}(u)`` by :func:`basis`."""
        return basis(self.knots, self.degree, u)

    def derivative(self, u, order: int = 1, side: str = "right") -> np.ndarray:
        """Derivatives by :func:`derivative`."""
        return derivative(self.ctrl, self.knots, self.degree, u, order, side)

    def sample(self, count: int = 200) -> np.ndarray:
        """``count`` points at equally spaced parameters over the domain (count >= 2, the
        ``count * d`` coordinates at most :data:`~goldman_lib.validation.MAX_ITEMS`)."""
        count = within_budget(count, "count", cost=lambda v: v * self.ctrl.shape[1], what="the sampled curve",
                              unit="coordinates", minimum=2)
        return self.evaluate(np.linspace(*self.domain, count))

    def __repr__(self) -> str:
        return f"BSplineCurve(degree={self.degree}, {self.ctrl.shape[0]} control points, knots={self.knots.tolist()})"


class NURBSCurve(BSplineCurve):
    """A NURBS curve: a B-spline curve with a positive weight per control point (Goldman §27.9).

    >>> c = NURBSCurve(*nurbs_circle())
    >>> round(float(np.hypot(*c.evaluate(0.1))), 12)
    1.0
    """

    def __init__(self, ctrl, weights, knots, degree):
        super().__init__(ctrl, knots, degree)
        self.weights = _weights(weights, (self.ctrl.shape[0],))

    def evaluate(self, u) -> np.ndarray:
        """Points by :func:`nurbs_curve`."""
        return nurbs_curve(self.ctrl, self.weights, self.knots, self.degree, u)

    def derivative(self, u, order: int = 1, side: str = "right") -> np.ndarray:
        """``C(u)`` (order 0) or ``C'(u) = (A'(u) - w'(u) C(u)) / w(u)`` (order 1) from the
        homogeneous B-spline ``(A, w) = sum N_k (w_k P_k, w_k)`` (quotient rule)."""
        order = as_int(order, "order", minimum=0, maximum=1)
        H = np.concatenate([self.ctrl * self.weights[:, None], self.weights[:, None]], axis=1)
        h = derivative(H, self.knots, self.degree, u, 0, side)
        if order == 0:
            return h[..., :-1] / h[..., -1:]
        dh = derivative(H, self.knots, self.degree, u, 1, side)
        c = h[..., :-1] / h[..., -1:]
        return (dh[..., :-1] - dh[..., -1:] * c) / h[..., -1:]

    def __repr__(self) -> str:
        return f"NURBSCurve(degree={self.degree}, {self.ctrl.shape[0]} control points, weights={self.weights.tolist()})"

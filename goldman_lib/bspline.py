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
  :func:`derivative_jumps`), "every spline is a B-spline" (§27.6: :func:`spline_to_bspline`,
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

from goldman_lib.validation import as_float, as_int, as_parameter, as_points, check_finite

__all__ = [
    "check_knots", "clamped_knots", "uniform_knots", "find_span", "multiplicity", "domain",
    "blossom", "local_de_boor", "de_boor_steps", "control_point_labels",
    "de_boor", "basis", "global_de_boor",
    "derivative_ctrl", "derivative", "continuity_at", "derivative_jumps",
    "spline_to_bspline", "bspline_to_pieces",
    "support", "affected_span",
    "surface_de_boor", "surface_grid",
    "nurbs_curve", "nurbs_surface", "nurbs_surface_grid", "nurbs_circle", "nurbs_sphere",
    "BSplineCurve", "NURBSCurve",
]


# --------------------------------------------------------------------------------------------
# knot vectors
# --------------------------------------------------------------------------------------------

def _fmt(x: float) -> str:
    return f"{float(x):.6g}"


def check_knots(knots, degree, n_ctrl=None, name: str = "knots") -> np.ndarray:
    """Validate a knot vector for a B-spline of ``degree`` and return it as a float array (Goldman §27.2).

    The rules, each with its own message: ``knots`` is a finite 1-D array; it is non-decreasing;
    no knot is repeated more than ``degree + 1`` times; its length is ``n_ctrl + degree + 1``
    (if ``n_ctrl`` is given; otherwise at least ``2 (degree + 1)``, so there is at least one
    control point per basis function); and the domain ``[t_p, t_{n+1}]`` is not a single point.

    knots: (n+p+2,) numbers.  degree: int >= 0.  n_ctrl: number of control points or None.
    name: the parameter name used in messages.  Returns a new (n+p+2,) float array.
    Raises TypeError for non-numeric input or a non-integer degree, ValueError naming the rule.

    >>> check_knots([0, 0, 0, 1, 1, 1], 2, 3).tolist()
    [0.0, 0.0, 0.0, 1.0, 1.0, 1.0]
    >>> check_knots([0, 0, 0.5, 0.2, 1, 1], 1)
    Traceback (most recent call last):
    ...
    ValueError: knots must be non-decreasing; knots[3]=0.2 < knots[2]=0.5
    """
    degree = as_int(degree, "degree", minimum=0)
    if isinstance(knots, (str, bytes)):
        raise TypeError(f"{name} must be numeric, not {type(knots).__name__}")
    try:
        t = np.array(knots, dtype=float)
    except (TypeError, ValueError) as exc:
        raise TypeError(f"{name} must be a numeric array-like; got {type(knots).__name__} ({exc})") from None
    if t.ndim != 1:
        raise ValueError(f"{name} must be a 1-D array of knots; got shape {t.shape}")
    check_finite(t, name)
    dec = np.flatnonzero(t[1:] < t[:-1])
    if dec.size:
        i = int(dec[0]) + 1
        raise ValueError(f"{name} must be non-decreasing; {name}[{i}]={_fmt(t[i])} < {name}[{i - 1}]={_fmt(t[i - 1])}")
    if t.size:
        starts = np.flatnonzero(np.r_[True, t[1:] != t[:-1]])
        counts = np.diff(np.r_[starts, t.size])
        big = np.flatnonzero(counts > degree + 1)
        if big.size:
            s = int(starts[big[0]])
            raise ValueError(f"{name} may repeat a knot at most degree+1 = {degree + 1} times; "
                             f"{name}[{s}]={_fmt(t[s])} appears {int(counts[big[0]])} times")
    if n_ctrl is not None:
        n_ctrl = as_int(n_ctrl, "n_ctrl", minimum=1)
        if t.size != n_ctrl + degree + 1:
            raise ValueError(f"{name} must have length n_ctrl + degree + 1 = {n_ctrl} + {degree} + 1 = "
                             f"{n_ctrl + degree + 1}; got {t.size}")
        if n_ctrl < degree + 1:
            raise ValueError(f"a B-spline of degree {degree} needs at least degree+1 = {degree + 1} control points; got {n_ctrl}")
    elif t.size < 2 * (degree + 1):
        raise ValueError(f"{name} must have at least 2*(degree+1) = {2 * (degree + 1)} knots for degree {degree}; got {t.size}")
    n = t.size - degree - 2
    if not t[degree] < t[n + 1]:
        raise ValueError(f"{name} must give a non-empty domain; {name}[{degree}]={_fmt(t[degree])} "
                         f"and {name}[{n + 1}]={_fmt(t[n + 1])} are equal")
    return t


def clamped_knots(n_ctrl, degree, interior=None) -> np.ndarray:
    """A clamped (open) knot vector on [0, 1]: ``degree + 1`` zeros, the interior knots, ``degree + 1`` ones (Goldman §27.7).

    The curve of a clamped knot vector starts at ``P_0`` and ends at ``P_n``, like a Bezier curve.
    n_ctrl: number of control points, >= degree + 1.  degree: int >= 0.  interior: the
    ``n_ctrl - degree - 1`` interior knots in [0, 1] (non-decreasing), or None for equally spaced ones.
    Returns (n_ctrl + degree + 1,).
    Raises ValueError if n_ctrl < degree + 1, the interior has the wrong length, lies outside
    [0, 1], or breaks a rule of :func:`check_knots`.

    >>> clamped_knots(5, 2).tolist()
    [0.0, 0.0, 0.0, 0.3333333333333333, 0.6666666666666666, 1.0, 1.0, 1.0]
    """
    degree = as_int(degree, "degree", minimum=0)
    n_ctrl = as_int(n_ctrl, "n_ctrl", minimum=1)
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

    n_ctrl: number of control points, >= degree + 1.  degree: int >= 0.  Returns
    ``(k - degree) / (n_ctrl - degree)`` for k = 0 .. n_ctrl + degree.
    Raises ValueError if n_ctrl < degree + 1.

    >>> uniform_knots(4, 2).tolist()
    [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0]
    """
    degree = as_int(degree, "degree", minimum=0)
    n_ctrl = as_int(n_ctrl, "n_ctrl", minimum=1)
    if n_ctrl < degree + 1:
        raise ValueError(f"n_ctrl must be at least degree+1 = {degree + 1}; got {n_ctrl}")
    return (np.arange(n_ctrl + degree + 1, dtype=float) - degree) / (n_ctrl - degree)


def domain(knots, degree) -> tuple[float, float]:
    """The parameter domain ``(t_p, t_{n+1})`` of a B-spline with these knots (Goldman §27.2).

    >>> domain([0, 0, 0, 0.5, 1, 1, 1], 2)
    (0.0, 1.0)
    """
    t = check_knots(knots, degree)
    p = int(degree)
    return float(t[p]), float(t[t.size - p - 1])


def multiplicity(knots, value, tol: float = 0.0) -> int:
    """How many times ``value`` occurs in the knot vector (within ``tol``) (Goldman §27.4).

    >>> multiplicity([0, 0, 0, 0.5, 0.5, 1, 1, 1], 0.5)
    2
    """
    t = np.asarray(knots, dtype=float)
    value = as_float(value, "value")
    return int(np.count_nonzero(np.abs(t - value) <= tol))


def _check_u(u, t: np.ndarray, p: int, name: str = "u") -> np.ndarray:
    arr = as_parameter(u, name)
    lo, hi = t[p], t[t.size - p - 1]
    bad = (arr < lo) | (arr > hi)
    if bad.any():
        flat = int(np.flatnonzero(bad)[0])
        where = name if arr.ndim == 0 else f"{name}[{', '.join(str(int(i)) for i in np.unravel_index(flat, arr.shape))}]"
        raise ValueError(f"{name} must lie in the domain [knots[{p}], knots[{t.size - p - 1}]] = "
                         f"[{_fmt(lo)}, {_fmt(hi)}]; {where} is {_fmt(arr.flat[flat])}")
    return arr


def _spans(t: np.ndarray, p: int, u: np.ndarray, side: str = "right") -> np.ndarray:
    """Span index k with t[k] <= u < t[k+1] (side 'right') or t[k] < u <= t[k+1] (side 'left'),
    restricted to the non-empty spans of the domain; u already validated."""
    n = t.size - p - 2
    lo_k = int(np.searchsorted(t, t[p], side="right")) - 1        # first non-empty span
    hi_k = int(np.searchsorted(t, t[n + 1], side="left")) - 1     # last non-empty span
    if side == "right":
        k = np.searchsorted(t, u, side="right") - 1
    else:
        k = np.searchsorted(t, u, side="left") - 1
    return np.clip(k, lo_k, hi_k)


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
    t = check_knots(knots, p, P.shape[0])
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
        lo, hi = t[p], t[n + 1]
        k = int(_spans(t, p, np.clip(a[0], lo, hi)))
    else:
        k = as_int(span, "span", minimum=p, maximum=n)
        if not t[k] < t[k + 1]:
            raise ValueError(f"span must index a non-empty knot span; knots[{k}] = knots[{k + 1}] = {_fmt(t[k])}")
    pts = P[k - p:k + 1].copy()
    for r in range(1, p + 1):
        x = a[r - 1]
        for j in range(p, r - 1, -1):
            i = k - p + j
            lo, hi = t[i], t[i + p + 1 - r]
            alpha = (x - lo) / (hi - lo)
            pts[j] = (1.0 - alpha) * pts[j - 1] + alpha * pts[j]
    return pts[p]


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
    levels = [pts.copy()]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            i = k - p + j
            alpha = (x - t[i]) / (t[i + p + 1 - r] - t[i])
            pts[j] = (1.0 - alpha) * pts[j - 1] + alpha * pts[j]
        levels.append(pts[r:].copy())
    return levels


# --------------------------------------------------------------------------------------------
# §27.3 the global de Boor algorithm and the B-spline basis
# --------------------------------------------------------------------------------------------

def _pyramid(P: np.ndarray, t: np.ndarray, p: int, u: np.ndarray, k: np.ndarray) -> np.ndarray:
    """de Boor's pyramid for flat u (N,) with spans k (N,), ctrl P (n+1, d); returns (d, N).

    Points are kept as (d, N) rows (one per pyramid node), updated in place."""
    PT = P.T                                                   # (d, n+1)
    rows = [PT[:, k - p + j] for j in range(p + 1)]           # fancy indexing copies
    if p == 0:
        return rows[0]
    # knots t[k-p+1 .. k+p] for every parameter: row q holds t[k - p + 1 + q]
    tk = t[k[None, :] + np.arange(-p + 1, p + 1)[:, None]]     # (2p, N)
    buf = np.empty_like(rows[0])
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            # i = k - p + j; lo = t[i] = tk[j - 1]; hi = t[i + p + 1 - r] = tk[j + p - r]
            lo = tk[j - 1]
            alpha = (u - lo) / (tk[j + p - r] - lo)
            row = rows[j]
            row -= rows[j - 1]
            row *= alpha
            row += rows[j - 1]
    return rows[p]


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
    out = _pyramid(P, t, p, flat, k)
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

__all__ = [_n for _n in __all__ if _n in globals()]  # (temporary: the rest of the chapter follows)

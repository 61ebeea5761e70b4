"""Bezier curves and tensor-product Bezier patches (Goldman, chapter 24).

Two layers, as everywhere in ``goldman_lib``:

- pure functions on arrays: :func:`neville` (interpolation, the counterpart of §24.1),
  :func:`de_casteljau` (§24.2), :func:`bernstein` and
  :func:`bernstein_evaluate` (§24.3), the properties of §24.4 (:func:`variation_count`,
  :func:`curve_crossings`, :func:`convex_hull`, :func:`convex_hull_contains`, :func:`apply_affine`),
  derivatives and smooth joins of §24.5 (:func:`hodograph`, :func:`derivative`,
  :func:`de_casteljau_with_derivative`,
  :func:`elevate_degree`, :func:`smooth_join`, :func:`join_continuity`) and tensor-product
  patches of §24.6 (:func:`patch_de_casteljau`, :func:`patch_evaluate_grid`, :func:`patch_grid`,
  :func:`patch_derivatives`, :func:`patch_normal`);
- thin classes over them for the notebook: :class:`BezierCurve` and :class:`BezierPatch`.

Chapter 25 has its own modules, whose public names are re-exported here (``bezier.subdivide``
keeps working): subdivision and rendering in :mod:`goldman_lib.bezier_subdivision`,
intersection in :mod:`goldman_lib.bezier_intersection`.

Shapes: a control polygon is ``(n+1, d)`` (degree ``n``, points of any dimension ``d`` in the
last axis); a control net of a patch is ``(m+1, n+1, d)``.  A parameter ``t`` may be a scalar or
an array of any shape, and the result's leading shape follows it: ``t.shape + (d,)``.

Curves may be evaluated outside ``[0, 1]``: a Bezier curve is a polynomial, and extrapolating it
is legitimate (the convex-hull property, however, only holds on ``[0, 1]``).  Parameters and
control points must be finite; bad input raises ``ValueError``/``TypeError`` naming the
parameter and the rule.

Matrices follow the book's convention: points are row vectors and an affine map acts on the
right, ``Q = P @ M``, with a 3x3 matrix in 2D and a 4x4 matrix in 3D whose last row is the
translation (see :func:`apply_affine`).

>>> de_casteljau([[0, 0], [1, 2], [2, 0]], 0.5)
array([1., 1.])
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import affine, transforms
from goldman_lib.kernels import polygons, pyramids
from goldman_lib.validation import (MAX_ITEMS, as_float, as_hyperplane, as_int,
                                     as_parameter, as_points, finite_result, overflow_culprit, within_budget)

__all__ = [
    "neville", "de_casteljau", "de_casteljau_steps", "bernstein", "bernstein_evaluate",
    "hodograph", "derivative", "de_casteljau_with_derivative", "elevate_degree",
    "smooth_join", "join_continuity",
    "variation_count", "curve_crossings", "convex_hull", "convex_hull_contains", "apply_affine",
    "patch_de_casteljau", "patch_evaluate_grid", "patch_grid", "patch_derivatives", "patch_normal",
    "BezierCurve", "BezierPatch", "CurveSampler", "curve_sampler",
]


# --------------------------------------------------------------------------------------------
# internal helpers (no validation)
# --------------------------------------------------------------------------------------------

def _ctrl(ctrl, name: str = "ctrl") -> np.ndarray:
    return as_points(ctrl, name, ndim=2)



def _net(ctrl, name: str = "ctrl") -> np.ndarray:
    return as_points(ctrl, name, ndim=3)


def _finite_points(out: np.ndarray, t: np.ndarray) -> np.ndarray:
    """``out`` (curve points at t) if finite, else :func:`finite_result`'s ValueError naming t or
    ctrl; the culprit is looked for only then (two passes over t saved on every good call)."""
    if np.isfinite(out).all():
        return out
    return finite_result(out, *overflow_culprit(t))


# --------------------------------------------------------------------------------------------
# §24.1 interpolation versus approximation: Neville's pyramid
# --------------------------------------------------------------------------------------------

@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def neville(points, t, nodes=None) -> np.ndarray:
    """The interpolating polynomial through ``points`` at ``nodes``, evaluated by Neville's algorithm (Goldman §24.1).

    Neville's pyramid is de Casteljau's with other weights: level r replaces neighbours by
    ``((t_{i+r} - t) P_i^{r-1} + (t - t_i) P_{i+1}^{r-1}) / (t_{i+r} - t_i)``, so the apex is the
    unique polynomial curve of degree n that passes through every point, ``L(t_i) = P_i`` (Lagrange
    interpolation).  The Bezier curve of the same points (:func:`de_casteljau`) only approximates
    them: it interpolates the first and last and is pulled towards the others.

    points: (n+1, d).  t: scalar or array of any shape.  nodes: (n+1,) distinct parameters,
    default equally spaced on [0, 1] (``i / n``; a single point gets the node 0).
    Returns ``t.shape + (d,)``.
    Raises ValueError for bad points, nodes of the wrong length, repeated or non-finite nodes,
    or a result that overflows float64.

    >>> neville([[0, 0], [1, 2], [2, 0]], 0.5)
    array([1., 2.])
    >>> neville([[0, 0], [1, 2], [2, 0]], [0.0, 1.0], nodes=[0, 0.5, 1]).tolist()
    [[0.0, 0.0], [2.0, 0.0]]
    """
    P = _ctrl(points, "points")
    t = as_parameter(t, "t")
    n1 = P.shape[0]
    if nodes is None:
        x = np.linspace(0.0, 1.0, n1) if n1 > 1 else np.zeros(1)
    else:
        x = np.asarray(as_parameter(nodes, "nodes"), dtype=float).reshape(-1)
        if x.size != n1:
            raise ValueError(f"nodes must hold one parameter per point ({n1}); got {x.size}")
        srt = np.sort(x)
        same = np.flatnonzero(np.diff(srt) == 0)
        if same.size:
            raise ValueError(f"nodes must be distinct; {srt[same[0]]:g} appears twice "
                             "(no polynomial takes two values at one parameter)")
    flat = t.reshape(-1)
    level = [np.broadcast_to(P[i][:, None], (P.shape[1], flat.size)).astype(float) for i in range(n1)]
    for r in range(1, n1):
        level = [((x[i + r] - flat) * level[i] + (flat - x[i]) * level[i + 1]) / (x[i + r] - x[i])
                 for i in range(n1 - r)]
    out = level[0].T.reshape(t.shape + (P.shape[1],))
    return finite_result(out, "t", t)


# --------------------------------------------------------------------------------------------
# §24.2 de Casteljau
# --------------------------------------------------------------------------------------------

@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def de_casteljau(ctrl, t) -> np.ndarray:
    """Evaluate a Bezier curve by the de Casteljau algorithm (Goldman §24.2).

    Each level of the algorithm replaces consecutive control points by the affine combinations
    ``(1-t) P_j + t P_{j+1}``; after ``n`` levels one point is left, the point on the curve.  All
    parameters are processed at once (three array operations per node of the pyramid, in place in
    a reused scratch array, no loop over ``t``: :func:`goldman_lib.kernels.pyramids.casteljau_apex`).

    ctrl: (n+1, d) control points, any degree n >= 0 and any dimension d >= 1.
    t: scalar or array of any shape; values outside [0, 1] extrapolate the polynomial curve.
    Returns ``t.shape + (d,)``.
    Raises ValueError if ctrl is not (n+1, d) with n+1 >= 1, if ctrl or t holds NaN/inf, or if t is
    so far outside [0, 1] that the point overflows float64 (about ``|t|**n * |P|`` > 1e308);
    TypeError if either is not numeric.

    >>> de_casteljau([[0, 0], [1, 2], [2, 0]], 0.5)
    array([1., 1.])
    >>> de_casteljau([[0, 0], [1, 2], [2, 0]], [0.0, 1.0]).tolist()
    [[0.0, 0.0], [2.0, 0.0]]
    """
    P = _ctrl(ctrl)
    t = as_parameter(t, "t")
    return _finite_points(pyramids.curve_points(P, t), t)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def de_casteljau_steps(ctrl, t) -> list[np.ndarray]:
    """Every level of the de Casteljau algorithm at one parameter (Goldman §24.2).

    For drawing the construction: level 0 is the control polygon, level k holds the n+1-k
    points ``(1-t) P_j^{k-1} + t P_{j+1}^{k-1}``, and the last level is the single point on the
    curve.

    ctrl: (n+1, d) control points.  t: a finite scalar (outside [0, 1] extrapolates).
    Returns a list of n+1 arrays with shapes (n+1, d), (n, d), ..., (1, d).
    Raises ValueError for a bad ctrl, a non-finite t, or a t that is not a scalar.

    >>> [lvl.tolist() for lvl in de_casteljau_steps([[0, 0], [1, 2], [2, 0]], 0.5)]
    [[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], [[0.5, 1.0], [1.5, 1.0]], [[1.0, 1.0]]]
    """
    P = _ctrl(ctrl)
    t = as_parameter(t, "t")
    if t.ndim != 0:
        raise ValueError(f"t must be a scalar for de_casteljau_steps; got shape {t.shape}")
    t = float(t)
    levels = pyramids.casteljau_levels(P, [t] * (P.shape[0] - 1))
    return [levels[0]] + [finite_result(cur, *overflow_culprit(t)) for cur in levels[1:]]


# --------------------------------------------------------------------------------------------
# §24.3 Bernstein basis
# --------------------------------------------------------------------------------------------

@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def bernstein(n, t) -> np.ndarray:
    """The Bernstein basis functions ``B_k^n(t) = C(n, k) t^k (1-t)^(n-k)``, k = 0..n (Goldman §24.3).

    Computed as binomial times powers built by repeated multiplication (exact at t = 0 and
    t = 1, no cancellation on [0, 1]); above degree 1000 the binomials overflow and the
    recurrence ``B_k^n = (1-t) B_k^{n-1} + t B_{k-1}^{n-1}`` is used instead.

    n: the degree, an int >= 0, within the work budget: ``(n+1) * t.size`` values (``(n+1)**2 *
    t.size / 2`` operations above degree 1000) at most :data:`~goldman_lib.validation.MAX_ITEMS`,
    so n <= 4471 for one parameter.  t: scalar or array of any shape (outside [0, 1] allowed).
    Returns ``t.shape + (n+1,)``.
    Raises TypeError if n is not an integer, ValueError if n < 0, n is over the budget, t is not
    finite, or t is so far outside [0, 1] that a value overflows float64.

    >>> bernstein(2, 0.5)
    array([0.25, 0.5 , 0.25])
    >>> float(bernstein(4, 0.5)[2])
    0.375
    """
    t = as_parameter(t, "t")
    n = within_budget(n, "n", cost=lambda v: _bernstein_cost(v, t.size), what=f"the Bernstein basis at {t.size} parameter(s)",
                      unit="values computed")
    rows = pyramids.bernstein_rows(n, t.reshape(-1))
    return finite_result(np.ascontiguousarray(rows.T).reshape(t.shape + (n + 1,)), "t", t)


def _bernstein_cost(n: int, count: int) -> int:
    """Values :func:`goldman_lib.kernels.pyramids.bernstein_rows` computes: the (n+1) x count table, or the recurrence's
    (n+1)^2/2 per parameter above the power-form degree."""
    per = n + 1 if n <= pyramids.POWER_FORM_MAX_DEGREE else (n + 1) ** 2 // 2
    return per * max(count, 1)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def bernstein_evaluate(ctrl, t) -> np.ndarray:
    """Evaluate a Bezier curve from its Bernstein form ``sum_k B_k^n(t) P_k`` (Goldman §24.3).

    The same curve as :func:`de_casteljau`, computed from the Bernstein form by a Horner-like
    scheme (Volk and Schumaker's, as in the ``bezier`` package): ``r = (r + C(n,k) t^k P_k)(1-t)``
    for k = 0..n-1, then ``r + t^n P_n``.  It is the binomial-times-powers form without storing
    the (n+1) x len(t) Bernstein matrix: O(n d) array operations on (d, len(t)) arrays, so the
    fast path for drawing many points.  Above degree 1000 (binomials overflow) it falls back to
    the Bernstein matrix of :func:`bernstein`.

    ctrl: (n+1, d) control points.  t: scalar or array of any shape (outside [0, 1] allowed).
    Returns ``t.shape + (d,)``.
    Raises ValueError/TypeError as :func:`de_casteljau`.

    >>> bernstein_evaluate([[0, 0], [1, 2], [2, 0]], 0.5)
    array([1., 1.])
    """
    P = _ctrl(ctrl)
    t = as_parameter(t, "t")
    n, d = P.shape[0] - 1, P.shape[1]
    tf = t.reshape(-1)
    if n == 0:
        out = np.broadcast_to(P[0][:, None], (d, tf.shape[0])).copy()
    elif n > pyramids.POWER_FORM_MAX_DEGREE:
        out = P.T @ pyramids.bernstein_rows(n, tf)
    else:
        s = 1.0 - tf
        out = np.multiply(P[0][:, None], s)          # (d, N)
        buf = np.empty_like(out)
        tpow = tf.copy()                             # t^k
        for k in range(1, n):
            out += np.multiply((math.comb(n, k) * P[k])[:, None], tpow, out=buf)
            out *= s
            tpow *= tf
        out += np.multiply(P[n][:, None], tpow, out=buf)
    return _finite_points(out.T.reshape(t.shape + (d,)), t)


# --------------------------------------------------------------------------------------------
# §24.5 derivatives, degree elevation
# --------------------------------------------------------------------------------------------

def hodograph(ctrl) -> np.ndarray:
    """The control points of the derivative curve, ``n (P_{k+1} - P_k)`` (Goldman §24.5).

    ctrl: (n+1, d).  Returns (n, d), the hodograph, a Bezier curve of degree n-1.  For a
    degree-0 (constant) curve the derivative is the constant zero curve, returned as (1, d) zeros
    so that the result is always a valid control polygon.
    Raises ValueError/TypeError for a bad ctrl.

    >>> hodograph([[0, 0], [1, 2], [2, 0]])
    array([[ 2.,  4.],
           [ 2., -4.]])
    """
    P = _ctrl(ctrl)
    n = P.shape[0] - 1
    if n == 0:
        return np.zeros_like(P)
    return n * np.diff(P, axis=0)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def derivative(ctrl, t, order=1) -> np.ndarray:
    """The ``order``-th derivative of a Bezier curve at ``t`` (Goldman §24.5).

    The r-th derivative is the Bezier curve of degree n-r with control points
    ``n!/(n-r)! * Delta^r P_k``, evaluated by de Casteljau.  order 0 is the curve itself; an
    order above the degree gives zeros.

    ctrl: (n+1, d).  t: scalar or array of any shape.  order: int >= 0.
    Returns ``t.shape + (d,)``.
    Raises TypeError if order is not an integer (1.5, True), ValueError if order < 0, and as
    :func:`de_casteljau` for bad ctrl or t.

    >>> derivative([[0, 0], [1, 2], [2, 0]], 0.5)
    array([2., 0.])
    >>> derivative([[0, 0], [1, 2], [2, 0]], 0.5, order=2)
    array([ 0., -8.])
    """
    P = _ctrl(ctrl)
    t = as_parameter(t, "t")
    order = as_int(order, "order", minimum=0)
    n = P.shape[0] - 1
    if order > n:
        return np.zeros(t.shape + (P.shape[1],))
    D = np.diff(P, n=order, axis=0) * float(math.perm(n, order)) if order else P
    return _finite_points(pyramids.curve_points(D, t), t)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def de_casteljau_with_derivative(ctrl, t) -> tuple[np.ndarray, np.ndarray]:
    """The curve point and its derivative from one de Casteljau pyramid (Goldman §24.5).

    Differentiating the de Casteljau algorithm: the last level but one holds two points,
    ``P_0^{n-1}(t)`` (the curve of ``P_0 .. P_{n-1}``) and ``P_1^{n-1}(t)`` (the curve of
    ``P_1 .. P_n``); the point is ``C(t) = (1-t) P_0^{n-1} + t P_1^{n-1}`` and the derivative is
    ``C'(t) = n (P_1^{n-1}(t) - P_0^{n-1}(t))``: the last leg of the pyramid is the tangent, and
    n times it is the velocity.  A degree-0 curve has derivative zero.

    ctrl: (n+1, d).  t: scalar or array of any shape.
    Returns ``(point, derivative)``, each ``t.shape + (d,)``.
    Raises as :func:`de_casteljau`.

    >>> pt, vel = de_casteljau_with_derivative([[0, 0], [1, 2], [2, 0]], 0.5)
    >>> pt.tolist(), vel.tolist()
    ([1.0, 1.0], [2.0, 0.0])
    """
    P = _ctrl(ctrl)
    t = as_parameter(t, "t")
    n = P.shape[0] - 1
    if n == 0:
        return finite_result(pyramids.curve_points(P, t), "t", t), np.zeros(t.shape + (P.shape[1],))
    first, second = pyramids.curve_points(P[:-1], t), pyramids.curve_points(P[1:], t)
    point, = pyramids.casteljau_level([first, second], t[..., None])
    return finite_result(point, "t", t), finite_result(n * (second - first), "t", t)


def elevate_degree(ctrl, times=1) -> np.ndarray:
    """Control points of the same curve written with degree n+times (Goldman §24.5, as a consequence of uniqueness).

    One elevation: ``Q_0 = P_0``, ``Q_k = k/(n+1) P_{k-1} + (1 - k/(n+1)) P_k``, ``Q_{n+1} = P_n``.
    The new control polygon lies closer to the curve; repeated elevation converges to it.

    ctrl: (n+1, d).  times: int >= 0, within the work budget: the coordinates computed over all
    elevations, ``d * (times (n+1) + times (times+1) / 2)``, at most
    :data:`~goldman_lib.validation.MAX_ITEMS` (times <= 3157 for a planar cubic).
    Returns (n+1+times, d).
    Raises TypeError if times is not an integer, ValueError if times < 0, times is over the budget
    or ctrl is bad.

    >>> elevate_degree([[0, 0], [1, 2], [2, 0]])
    array([[0.        , 0.        ],
           [0.66666667, 1.33333333],
           [1.33333333, 1.33333333],
           [2.        , 0.        ]])
    """
    P = _ctrl(ctrl)
    n1, d = P.shape
    times = within_budget(times, "times", cost=lambda v: d * (v * n1 + v * (v + 1) // 2),
                          what=f"elevating a degree-{n1 - 1} curve", unit="coordinates computed")
    return P.copy() if times == 0 else polygons.elevate(P, times)


# --------------------------------------------------------------------------------------------
# §24.5.1 smooth joins
# --------------------------------------------------------------------------------------------

_CONTINUITIES = ("C0", "G1", "C1", "C2")


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def smooth_join(ctrl, continuity="C1", ratio=1.0, degree=None) -> np.ndarray:
    """The leading control points a following curve needs to join ``ctrl`` smoothly (Goldman §24.5.1).

    The curve P (degree n) runs over a parameter interval of length D1 and the next curve Q
    (degree m) over one of length D2 = ratio * D1.  Matching derivatives in the global
    parameter gives

    - ``"C0"``: ``Q_0 = P_n``                                         (returns 1 point)
    - ``"G1"``: also ``Q_1 = P_n + ratio (P_n - P_{n-1})`` for any ratio > 0: the same tangent
      direction, with ``ratio`` only setting the length of the first leg  (returns 2 points)
    - ``"C1"``: ``Q_1 = P_n + (n/m) ratio (P_n - P_{n-1})``               (returns 2 points)
    - ``"C2"``: also ``Q_2 = 2 Q_1 - Q_0 + n(n-1)/(m(m-1)) ratio^2 (P_n - 2 P_{n-1} + P_{n-2})``
      (returns 3 points)

    The remaining control points of Q (from the returned count up to m) are free: any choice keeps
    the join as smooth as asked.

    ctrl: (n+1, d) control points of the first curve.  continuity: "C0", "G1", "C1" or "C2".
    ratio: positive float, the next parameter interval over this one (for G1, the leg length
    factor).  degree: the degree m of the next curve (default n).
    Returns (k, d), k = 1, 2, 2, 3 for C0, G1, C1, C2.
    Raises ValueError for an unknown continuity, ratio <= 0, a next degree too small to hold the
    constrained points, or G1 at a degenerate end (P_n == P_{n-1}, no tangent direction).

    >>> smooth_join([[0, 0], [1, 1], [2, 0]], "C1")
    array([[ 2.,  0.],
           [ 3., -1.]])
    >>> smooth_join([[0, 0], [1, 1], [2, 0]], "C1", ratio=0.5)
    array([[ 2. ,  0. ],
           [ 2.5, -0.5]])
    """
    P = _ctrl(ctrl)
    if continuity not in _CONTINUITIES:
        raise ValueError(f"continuity must be one of {', '.join(_CONTINUITIES)}; got {continuity!r}")
    ratio = as_float(ratio, "ratio", positive=True)
    n = P.shape[0] - 1
    m = n if degree is None else as_int(degree, "degree", minimum=0)
    need = {"C0": 1, "G1": 2, "C1": 2, "C2": 3}[continuity]
    if m + 1 < need:
        what = "degree must be" if degree is not None else "ctrl must have degree (the next curve's by default)"
        raise ValueError(f"{what} >= {need - 1} for a {continuity} join (the next curve needs "
                         f"{need} constrained control points); got {m}")
    Q0 = P[-1]
    if continuity == "C0":
        return Q0[None, :].copy()
    lead = P[-1] - P[-2] if n >= 1 else np.zeros_like(Q0)
    if continuity == "G1":
        if not np.any(lead):
            raise ValueError("ctrl must have distinct last two control points for a G1 join; "
                             "P[n] == P[n-1] leaves the end tangent direction undefined")
        return finite_result(np.stack([Q0, Q0 + ratio * lead]), "ratio", ratio)
    Q1 = Q0 + (n / m) * ratio * lead
    if continuity == "C1":
        return finite_result(np.stack([Q0, Q1]), "ratio", ratio)
    second = P[-1] - 2 * P[-2] + P[-3] if n >= 2 else np.zeros_like(Q0)
    try:
        Q2 = 2 * Q1 - Q0 + (n * (n - 1)) / (m * (m - 1)) * ratio ** 2 * second
    except OverflowError:
        raise ValueError(f"ratio is too large in magnitude: the result overflows float64 at ratio = {ratio:g}") from None
    return finite_result(np.stack([Q0, Q1, Q2]), "ratio", ratio)


def join_continuity(a, b, tol=1e-9, ratio=1.0) -> dict[str, bool]:
    """Which of C0, G1, C1 and C2 hold where curve ``a`` ends and curve ``b`` begins (Goldman §24.5.1).

    With ``ratio`` = (parameter interval of b) / (parameter interval of a):
    C0: ``b(0) = a(1)``; C1: C0 and ``b'(0) = ratio a'(1)``; G1: C0 and the end tangents are
    nonzero and point the same way; C2: C1 and ``b''(0) = ratio^2 a''(1)``.  Comparisons use the
    tolerance ``tol`` relative to the size of the control points (at least 1).

    a: (n+1, d), b: (m+1, d) with the same d.  tol: positive float.  ratio: positive float.
    Returns a dict ``{"C0": bool, "G1": bool, "C1": bool, "C2": bool}``.
    Raises ValueError if the dimensions differ, and as :func:`de_casteljau` for bad points.

    >>> join_continuity([[0, 0], [1, 1], [2, 0]], [[2, 0], [3, -1], [4, 0]])
    {'C0': True, 'G1': True, 'C1': True, 'C2': False}
    """
    A = _ctrl(a, "a")
    B = _ctrl(b, "b")
    if A.shape[1] != B.shape[1]:
        raise ValueError(f"a and b must hold points of the same dimension; got shapes {A.shape} and {B.shape}")
    tol = as_float(tol, "tol", positive=True)
    ratio = as_float(ratio, "ratio", positive=True)
    scale = max(1.0, float(np.abs(A).max()), float(np.abs(B).max()))

    def close(x, y, s=1.0):
        return bool(np.linalg.norm(x - y) <= tol * scale * s)

    def deriv(P, r, end):
        n = P.shape[0] - 1
        if r > n:
            return np.zeros(P.shape[1])
        D = np.diff(P, n=r, axis=0) * float(math.perm(n, r))
        return D[-1] if end else D[0]

    c0 = close(A[-1], B[0])
    da, db = deriv(A, 1, True), deriv(B, 1, False)
    size1 = max(1.0, A.shape[0], B.shape[0], ratio)
    c1 = c0 and close(db, ratio * da, size1)
    na, nb = np.linalg.norm(da), np.linalg.norm(db)
    g1 = c0 and na > tol * scale and nb > tol * scale and bool(np.linalg.norm(da / na - db / nb) <= tol * size1)
    dda, ddb = deriv(A, 2, True), deriv(B, 2, False)
    c2 = c1 and close(ddb, ratio * ratio * dda, size1 ** 2 * max(1.0, ratio))
    return {"C0": c0, "G1": g1, "C1": c1, "C2": c2}


# --------------------------------------------------------------------------------------------
# §24.4 properties: variation diminishing, convex hull, affine invariance
# --------------------------------------------------------------------------------------------

def _signed_distances(points, line_point, line_normal, d):
    p, nrm = as_hyperplane(line_point, line_normal, d)
    return polygons.signed_distances(points, p, nrm)


def variation_count(ctrl, line_point, line_normal, tol=1e-12) -> int:
    """How many times the control polygon crosses a line (Goldman §24.4, variation diminishing).

    Counts sign changes of the signed distances of the control points from the line through
    ``line_point`` with normal ``line_normal`` (in 3D, the plane; in general the hyperplane).
    Control points within ``tol`` of the line are skipped, so touching without crossing does
    not count.  The variation-diminishing property says
    ``curve_crossings(...) <= variation_count(...)``.

    ctrl: (n+1, d).  line_point, line_normal: (d,), the normal nonzero.  tol: float >= 0.
    Returns an int.
    Raises ValueError for bad shapes, non-finite values, or a zero normal.

    >>> variation_count([[0, 0], [1, 2], [2, -2], [3, 1]], [0, 0], [0, 1])
    2
    """
    P = _ctrl(ctrl)
    tol = as_float(tol, "tol")
    return polygons.sign_changes(_signed_distances(P, line_point, line_normal, P.shape[1]), tol)


def curve_crossings(ctrl, line_point, line_normal, samples=1001, tol=1e-12) -> int:
    """How many times the Bezier curve over [0, 1] crosses a line, counted on samples (Goldman §24.4).

    The curve is evaluated at ``samples`` evenly spaced parameters and sign changes of the signed
    distance are counted (points within ``tol`` skipped).  Sampling can only miss crossings, so
    this is a lower bound on the true count, and it equals it once samples resolve the curve.

    ctrl: (n+1, d).  line_point, line_normal: (d,).  samples: int >= 2, at most
    :data:`~goldman_lib.validation.MAX_ITEMS` / d curve points (the work budget).  tol: float >= 0.
    Returns an int.
    Raises ValueError for bad shapes, non-finite values, a zero normal, or samples < 2.

    >>> curve_crossings([[0, 0], [1, 2], [2, -2], [3, 1]], [0, 0], [0, 1])
    2
    """
    P = _ctrl(ctrl)
    samples = within_budget(samples, "samples", cost=lambda v: v * P.shape[1], what="the sampled curve",
                            unit="coordinates", minimum=2)
    tol = as_float(tol, "tol")
    pts = pyramids.curve_points(P, np.linspace(0.0, 1.0, samples))
    return polygons.sign_changes(_signed_distances(pts, line_point, line_normal, P.shape[1]), tol)


def _cross2(o, a, b):
    return (a[..., 0] - o[..., 0]) * (b[..., 1] - o[..., 1]) - (a[..., 1] - o[..., 1]) * (b[..., 0] - o[..., 0])


def convex_hull(points) -> np.ndarray:
    """The convex hull of 2D points, counter-clockwise, by Andrew's monotone chain (Goldman §24.4).

    points: (k, 2).  Returns (h, 2), the hull vertices counter-clockwise starting from the
    lowest-leftmost point, without repeating it; collinear points on edges are dropped
    (h = 1 for coincident points, h = 2 for collinear ones).
    Raises ValueError if points are not (k, 2), k >= 1, finite.

    >>> convex_hull([[0, 0], [1, 2], [2, 0], [1, 0.5]]).tolist()
    [[0.0, 0.0], [2.0, 0.0], [1.0, 2.0]]
    """
    P = as_points(points, "points", ndim=2, dim=2)
    pts = np.unique(P, axis=0)  # sorted by x, then y
    if len(pts) <= 2:
        return pts

    def chain(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and _cross2(out[-2], out[-1], p) <= 0:
                out.pop()
            out.append(p)
        return out

    lower = chain(pts)
    upper = chain(pts[::-1])
    hull = np.array(lower[:-1] + upper[:-1])
    return hull


def convex_hull_contains(ctrl, points, tol=1e-9) -> np.ndarray:
    """Whether each point lies in the convex hull of the control points (Goldman §24.4), 2D only.

    The hull is built by :func:`convex_hull` and each point is tested against every edge's
    half-plane (numpy only, no scipy).  The convex-hull property says that every point of the
    curve for t in [0, 1] passes this test.  Only planar points are supported; for a 3D curve,
    test its projections onto coordinate planes (each projection is the Bezier curve of the
    projected control points, by affine invariance).

    ctrl: (n+1, 2).  points: (2,) or (..., 2).  tol: float >= 0, the distance a point may lie
    outside an edge (scaled by the size of the hull).
    Returns a bool (for one point) or a bool array of ``points.shape[:-1]``.
    Raises ValueError for points that are not 2D or not finite.

    >>> ctrl = [[0, 0], [1, 2], [2, 0]]
    >>> convex_hull_contains(ctrl, de_casteljau(ctrl, [0.1, 0.5, 0.9])).tolist()
    [True, True, True]
    >>> bool(convex_hull_contains(ctrl, [0.2, 1.0]))
    False
    """
    H = convex_hull(_ctrl_2d(ctrl))
    X = as_points(points, "points", ndim=None, dim=2)
    tol = as_float(tol, "tol")
    scale = max(1.0, float(np.abs(H).max()))
    eps = tol * scale
    if len(H) == 1:
        inside = np.linalg.norm(X - H[0], axis=-1) <= eps
    elif len(H) == 2:
        a, b = H
        ab = b - a
        L = np.linalg.norm(ab)
        along = ((X - a) @ ab) / L
        off = np.abs(_cross2(a, b, X)) / L
        inside = (off <= eps) & (along >= -eps) & (along <= L + eps)
    else:
        a = H
        b = np.roll(H, -1, axis=0)
        edge_len = np.linalg.norm(b - a, axis=1)
        # signed distance of each point to the left of each edge: (..., h)
        Xe = X[..., None, :]
        dist = _cross2(a, b, Xe) / edge_len
        inside = np.all(dist >= -eps, axis=-1)
    return bool(inside) if np.ndim(inside) == 0 else inside


def _ctrl_2d(ctrl):
    return as_points(ctrl, "ctrl", ndim=2, dim=2)


def apply_affine(points, M) -> np.ndarray:
    """Apply an affine map in the book's row-vector convention, ``Q = [P, 1] @ M`` (Goldman §24.4).

    Affine invariance (§24.4): the Bezier curve of the mapped control points is the mapped
    Bezier curve.  One rule with the transformation modules: planar points go to
    :func:`goldman_lib.affine.apply` (chapter 4), points in space to
    :func:`goldman_lib.transforms.apply` (chapter 13) after checking that M is affine.

    points: (..., d) with d = 2 or 3.  M: (d+1, d+1) whose last column is (0, ..., 0, 1) within
    1e-12 (an affine, not projective, map); the last row is the translation.
    Returns the mapped points, same shape as ``points``.
    Raises ValueError if M has the wrong shape, is not affine, or is not finite.

    >>> M = [[0, 1, 0], [-1, 0, 0], [5, 0, 1]]   # rotate by 90 degrees, then move by (5, 0)
    >>> apply_affine([[1, 0], [0, 2]], M)
    array([[5., 1.],
           [3., 0.]])
    """
    P = as_points(points, "points", ndim=None, dim=(2, 3))
    if P.shape[-1] == 2:
        return affine.apply(P, M)
    A = as_points(M, "M", ndim=2, dim=4)
    if A.shape != (4, 4):
        raise ValueError(f"M must have shape (4, 4) for 3-dimensional points; got shape {A.shape}")
    if not np.allclose(A[:, 3], [0.0, 0.0, 0.0, 1.0], rtol=0.0, atol=1e-12):
        raise ValueError(f"M must be affine: its last column must be (0, 0, 0, 1) (row-vector convention: the "
                         f"translation is the last row); got {A[:, 3].tolist()}")
    return transforms.apply(P, A)


# --------------------------------------------------------------------------------------------
# §24.6 tensor-product patches
# --------------------------------------------------------------------------------------------

def _uv(u, v):
    u = as_parameter(u, "u")
    v = as_parameter(v, "v")
    try:
        shape = np.broadcast_shapes(u.shape, v.shape)
    except ValueError:
        raise ValueError(f"u and v must have the same (or broadcastable) shapes; got {u.shape} and {v.shape}") from None
    return np.broadcast_to(u, shape).reshape(-1), np.broadcast_to(v, shape).reshape(-1), shape


def _patch_finite(result: np.ndarray, u, v) -> np.ndarray:
    """``result``, or the ValueError of :func:`~goldman_lib.validation.finite_result` naming the
    parameter (u or v) farthest from [0, 1]."""
    if np.all(np.isfinite(result)):
        return result
    if max((float(np.max(np.abs(x))) if np.size(x) else 0.0) for x in (u, v)) <= 1:
        return finite_result(result, "ctrl")
    far = [(float(np.max(np.abs(x))) if np.size(x) else 0.0, name, x) for name, x in (("u", u), ("v", v))]
    _, name, x = max(far, key=lambda f: f[0])
    x = np.asarray(x)
    return finite_result(result, name, x.flat[int(np.argmax(np.abs(x)))] if x.size else None)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def patch_de_casteljau(ctrl, u, v) -> np.ndarray:
    """Evaluate a tensor-product Bezier patch by de Casteljau in v then in u (Goldman §24.6).

    ``S(u, v) = sum_i sum_j B_i^m(u) B_j^n(v) P_ij``: each row of the net is a Bezier curve in v,
    and the points of the rows at v are the control points of a Bezier curve in u.

    ctrl: (m+1, n+1, d) control net (row index i goes with u).  u, v: scalars or arrays of the
    same (or broadcastable) shape.  Returns ``broadcast(u, v).shape + (d,)``.
    Raises ValueError if ctrl is not (m+1, n+1, d), if u and v do not broadcast, or if any value
    is not finite.

    >>> net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]   # bilinear
    >>> patch_de_casteljau(net, 0.5, 0.5)
    array([0.5 , 0.5 , 0.25])
    """
    P = _net(ctrl)
    uf, vf, shape = _uv(u, v)
    return _patch_finite(pyramids.patch_points(P, uf, vf).T.reshape(shape + (P.shape[2],)), uf, vf)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def patch_evaluate_grid(ctrl, u, v) -> np.ndarray:
    """Evaluate a Bezier patch on the tensor grid u x v, as ``B(u) P B(v)^T`` (Goldman §24.6).

    One matrix product per coordinate with the Bernstein matrices ``B(u)`` (a, m+1) and
    ``B(v)`` (b, n+1): the fast path for surfaces drawn as meshes.

    ctrl: (m+1, n+1, d).  u: (a,), v: (b,) 1-D parameter arrays.  Returns (a, b, d) with
    ``[i, j] = S(u[i], v[j])``.
    Raises ValueError for a bad net, u or v not 1-D, or non-finite values.

    >>> net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    >>> patch_evaluate_grid(net, [0, 1], [0, 0.5, 1])[:, :, 2].tolist()
    [[0.0, 0.0, 0.0], [0.0, 0.5, 1.0]]
    """
    P = _net(ctrl)
    u = as_parameter(u, "u")
    v = as_parameter(v, "v")
    for name, arr in (("u", u), ("v", v)):
        if arr.ndim != 1:
            raise ValueError(f"{name} must be a 1-D array of parameters; got shape {arr.shape}")
    Bu = pyramids.bernstein_rows(P.shape[0] - 1, u)           # (m+1, a)
    Bv = pyramids.bernstein_rows(P.shape[1] - 1, v)           # (n+1, b)
    # one (a, m+1) @ (m+1, n+1) @ (n+1, b) product per coordinate, batched over d by matmul
    out = Bu.T @ P.transpose(2, 0, 1) @ Bv          # (d, a, b)
    return _patch_finite(np.ascontiguousarray(np.moveaxis(out, 0, -1)), u, v)


def patch_grid(ctrl, nu=21, nv=21) -> np.ndarray:
    """Evaluate a Bezier patch on an evenly spaced nu x nv grid over [0, 1]^2 (Goldman §24.6).

    ctrl: (m+1, n+1, d).  nu, nv: ints >= 2, with nu * nv * d at most
    :data:`~goldman_lib.validation.MAX_ITEMS` coordinates (the work budget).  Returns (nu, nv, d),
    ready for a mesh.
    Raises TypeError/ValueError for non-integer, too small or over-budget nu, nv, and for a bad net.

    >>> patch_grid([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], 2, 2)[:, :, 2].tolist()
    [[0.0, 0.0], [0.0, 1.0]]
    """
    d = _net(ctrl).shape[-1]
    nu = within_budget(nu, "nu", cost=lambda k: k * 2 * d, what="the patch grid", unit="coordinates", minimum=2)
    nv = within_budget(nv, "nv", cost=lambda k: nu * k * d, what=f"the patch grid with nu = {nu}",
                       unit="coordinates", minimum=2)
    return patch_evaluate_grid(ctrl, np.linspace(0.0, 1.0, nu), np.linspace(0.0, 1.0, nv))


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def patch_derivatives(ctrl, u, v) -> tuple[np.ndarray, np.ndarray]:
    """The partial derivatives ``S_u`` and ``S_v`` of a Bezier patch (Goldman §24.6, §24.5).

    ``S_u`` is the patch of degree (m-1, n) with net ``m (P_{i+1,j} - P_ij)``; ``S_v`` likewise in
    j.  A degree-0 direction has zero derivative.

    ctrl: (m+1, n+1, d).  u, v: same (or broadcastable) shapes.
    Returns ``(S_u, S_v)``, each ``broadcast(u, v).shape + (d,)``.
    Raises as :func:`patch_de_casteljau`.

    >>> net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    >>> [s.tolist() for s in patch_derivatives(net, 0.5, 0.5)]
    [[1.0, 0.0, 0.5], [0.0, 1.0, 0.5]]
    """
    P = _net(ctrl)
    uf, vf, shape = _uv(u, v)
    m, n, d = P.shape[0] - 1, P.shape[1] - 1, P.shape[2]
    out = []
    for axis, deg in ((0, m), (1, n)):
        if deg == 0:
            out.append(np.zeros(shape + (d,)))
            continue
        D = deg * np.diff(P, axis=axis)
        out.append(pyramids.patch_points(D, uf, vf).T.reshape(shape + (d,)))
    return _patch_finite(out[0], uf, vf), _patch_finite(out[1], uf, vf)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def patch_normal(ctrl, u, v, normalize=True) -> np.ndarray:
    """The surface normal ``S_u x S_v`` of a 3D Bezier patch (Goldman §24.6).

    ctrl: (m+1, n+1, 3).  u, v: same (or broadcastable) shapes.  normalize: return unit normals.
    Returns ``broadcast(u, v).shape + (3,)``.  Where the cross product vanishes (a degenerate
    point such as a collapsed corner) the normal is undefined and the zero vector is returned.
    Raises ValueError if the net is not 3D, and as :func:`patch_de_casteljau`.

    >>> patch_normal([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]], 0.5, 0.5)
    array([0., 0., 1.])
    """
    P = as_points(ctrl, "ctrl", ndim=3, dim=3)
    su, sv = patch_derivatives(P, u, v)
    nrm = _patch_finite(np.cross(su, sv), u, v)
    if not normalize:
        return nrm
    length = np.linalg.norm(nrm, axis=-1, keepdims=True)
    scale = max(1.0, float(np.abs(P).max())) ** 2
    safe = length > 1e-14 * scale
    return np.where(safe, nrm / np.where(safe, length, 1.0), 0.0)


# --------------------------------------------------------------------------------------------
# thin classes
# --------------------------------------------------------------------------------------------

class BezierCurve:
    """A Bezier curve of degree n in d dimensions, a thin object over the functions (Goldman §24.2-24.5).

    >>> c = BezierCurve([[0, 0], [1, 2], [2, 0]])
    >>> c.degree, c.dimension
    (2, 2)
    >>> c(0.5)
    array([1., 1.])
    >>> c.hodograph().ctrl.tolist()
    [[2.0, 4.0], [2.0, -4.0]]
    >>> c.elevate().degree
    3
    """

    def __init__(self, ctrl):
        self.ctrl = _ctrl(ctrl).copy()

    @property
    def degree(self) -> int:
        return self.ctrl.shape[0] - 1

    @property
    def dimension(self) -> int:
        return self.ctrl.shape[1]

    def evaluate(self, t) -> np.ndarray:
        """The points at t, ``t.shape + (d,)``, by :func:`de_casteljau`."""
        return de_casteljau(self.ctrl, t)

    __call__ = evaluate

    def derivative(self, t, order=1) -> np.ndarray:
        """The order-th derivative at t, by :func:`derivative`."""
        return derivative(self.ctrl, t, order)

    def hodograph(self) -> "BezierCurve":
        """The derivative curve, by :func:`hodograph`."""
        return BezierCurve(hodograph(self.ctrl))

    def elevate(self, times=1) -> "BezierCurve":
        """The same curve with degree raised by ``times``, by :func:`elevate_degree`."""
        return BezierCurve(elevate_degree(self.ctrl, times))

    def steps(self, t) -> list[np.ndarray]:
        """The levels of the de Casteljau construction at scalar t, by :func:`de_casteljau_steps`."""
        return de_casteljau_steps(self.ctrl, t)

    def __repr__(self) -> str:
        return f"BezierCurve(degree={self.degree}, ctrl={self.ctrl.tolist()})"


class CurveSampler:
    """Bezier curves of one degree drawn at fixed parameters: the Bernstein form as one matrix
    (Goldman §24.3), ``points = B @ ctrl`` with ``B[i, k] = B_k^n(t_i)``.

    A view redraws its curve at the same parameters every time a control point moves; only the
    control points change.  The basis at those parameters is computed once (by :func:`bernstein`),
    and each curve is then one matrix product: the same points as :func:`de_casteljau` to rounding
    (both are convex combinations on [0, 1]; tested to 1e-15 of the control points' size).  It is
    the drawing path of the chapter 24-26 views.

    degree: an int >= 0.  t: the parameters, any shape (outside [0, 1] extrapolates).  Calling it
    with ctrl ``(degree + 1, d)`` returns ``t.shape + (d,)``.  Raises ValueError/TypeError for a bad
    degree or t (as :func:`bernstein`), for ctrl of another degree, or for control points that
    are not finite or whose curve overflows.

    >>> draw = CurveSampler(2, [0.0, 0.5, 1.0])
    >>> draw([[0, 0], [1, 2], [2, 0]]).tolist()
    [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]
    """

    def __init__(self, degree, t):
        t = as_parameter(t, "t")
        self.degree = within_budget(degree, "degree", cost=lambda v: _bernstein_cost(v, t.size),
                                    what=f"the Bernstein basis at {t.size} parameter(s)", unit="values computed")
        self.t = t
        basis = bernstein(self.degree, t).reshape(-1, self.degree + 1)
        basis.flags.writeable = False
        self.basis = basis
        self._convex = bool(t.size == 0 or (t.min() >= 0.0 and t.max() <= 1.0))
        self._shape2 = (self.degree + 1, 2)          # the planar curves of the views take the fast path

    def __call__(self, ctrl) -> np.ndarray:
        if (self._convex and type(ctrl) is np.ndarray and ctrl.dtype == np.float64 and ctrl.shape == self._shape2
                and np.abs(ctrl).max() < 1e300):
            # The views' call, checked in one pass: finite control points (NaN fails the comparison)
            # well inside float64, and parameters on [0, 1], so each point is a convex combination
            # of them and cannot overflow.
            return (self.basis @ ctrl).reshape(self.t.shape + (2,))
        P = _ctrl(ctrl)
        if P.shape[0] != self.degree + 1:
            raise ValueError(f"ctrl must hold {self.degree + 1} control points (degree {self.degree}) for this sampler; "
                             f"got shape {P.shape}")
        with np.errstate(over="ignore", invalid="ignore"):
            out = self.basis @ P
        if not np.isfinite(out).all():
            finite_result(out, "ctrl", why="is too large: its curve overflows float64")
        return out.reshape(self.t.shape + (P.shape[1],))

    def __repr__(self) -> str:
        return f"CurveSampler(degree={self.degree}, parameters={self.t.size})"


_SAMPLERS: dict[tuple[int, int], CurveSampler] = {}


def curve_sampler(degree, samples) -> CurveSampler:
    """The :class:`CurveSampler` of ``degree`` at ``samples`` equally spaced parameters on [0, 1],
    made once and kept (Goldman §24.3): what a view calls on every redraw.

    >>> curve_sampler(3, 400) is curve_sampler(3, 400)
    True
    >>> curve_sampler(1, 3)([[0, 0], [2, 4]]).tolist()
    [[0.0, 0.0], [1.0, 2.0], [2.0, 4.0]]
    """
    if type(degree) is int and type(samples) is int:       # the views' call: a lookup, checked on a miss
        sampler = _SAMPLERS.get((degree, samples))
        if sampler is not None:
            return sampler
    degree = within_budget(degree, "degree", cost=lambda v: 2 * (v + 1), what="the sampled Bernstein basis at 2 or more parameters",
                           unit="values", minimum=0)
    samples = within_budget(samples, "samples", cost=lambda v: (degree + 1) * v, what="the sampled Bernstein basis",
                            unit="values", minimum=2)
    key = (degree, samples)
    sampler = _SAMPLERS.get(key)
    if sampler is None:
        if len(_SAMPLERS) >= 64:          # a bounded cache: views use a handful of (degree, samples)
            _SAMPLERS.clear()
        sampler = _SAMPLERS[key] = CurveSampler(key[0], np.linspace(0.0, 1.0, key[1]))
    return sampler


class BezierPatch:
    """A tensor-product Bezier patch of degree (m, n), a thin object over the functions (Goldman §24.6).

    >>> p = BezierPatch([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    >>> p.degree
    (1, 1)
    >>> p.evaluate(0.5, 0.5)
    array([0.5 , 0.5 , 0.25])
    >>> p.grid(3, 4).shape
    (3, 4, 3)
    """

    def __init__(self, ctrl):
        self.ctrl = _net(ctrl).copy()

    @property
    def degree(self) -> tuple[int, int]:
        return self.ctrl.shape[0] - 1, self.ctrl.shape[1] - 1

    @property
    def dimension(self) -> int:
        return self.ctrl.shape[2]

    def evaluate(self, u, v) -> np.ndarray:
        """The points at (u, v), by :func:`patch_de_casteljau`."""
        return patch_de_casteljau(self.ctrl, u, v)

    __call__ = evaluate

    def grid(self, nu=21, nv=21) -> np.ndarray:
        """The (nu, nv, d) grid of points over [0, 1]^2, by :func:`patch_grid`."""
        return patch_grid(self.ctrl, nu, nv)

    def derivatives(self, u, v) -> tuple[np.ndarray, np.ndarray]:
        """``(S_u, S_v)`` at (u, v), by :func:`patch_derivatives`."""
        return patch_derivatives(self.ctrl, u, v)

    def normal(self, u, v, normalize=True) -> np.ndarray:
        """The surface normal at (u, v), by :func:`patch_normal` (3D nets only)."""
        return patch_normal(self.ctrl, u, v, normalize)

    def __repr__(self) -> str:
        return f"BezierPatch(degree={self.degree}, dimension={self.dimension})"


# --------------------------------------------------------------------------------------------
# Chapter 25 lives in its own modules; its public names stay importable from here.
# --------------------------------------------------------------------------------------------

from goldman_lib.bezier_intersection import (intersect_curves, intersect_patches, intersect_ray_patch,  # noqa: E402
                                             intersection_boxes)
from goldman_lib.bezier_subdivision import (flatness, is_flat, join_order, net_distance, patch_flatness,  # noqa: E402
                                            polygon_distance, render_by_subdivision, render_patch_by_subdivision,
                                            smooth_continuation, subdivide, subdivide_patch, subdivide_patch_uniform,
                                            subdivide_uniform, subdivision_variation_counts)

__all__ += ["subdivide", "subdivide_uniform", "flatness", "is_flat", "polygon_distance", "render_by_subdivision",
            "subdivide_patch", "subdivide_patch_uniform", "net_distance", "patch_flatness",
            "render_patch_by_subdivision", "subdivision_variation_counts", "smooth_continuation", "join_order",
            "intersect_curves", "intersection_boxes", "intersect_ray_patch", "intersect_patches"]

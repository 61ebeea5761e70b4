"""Bezier curves and tensor-product Bezier patches (Goldman, chapter 24).

Two layers, as everywhere in ``goldman_lib``:

- pure functions on arrays: :func:`de_casteljau` (§24.2), :func:`bernstein` and
  :func:`bernstein_evaluate` (§24.3), the properties of §24.4 (:func:`variation_count`,
  :func:`curve_crossings`, :func:`convex_hull`, :func:`convex_hull_contains`, :func:`apply_affine`),
  derivatives and smooth joins of §24.5 (:func:`hodograph`, :func:`derivative`,
  :func:`elevate_degree`, :func:`smooth_join`, :func:`join_continuity`) and tensor-product
  patches of §24.6 (:func:`patch_de_casteljau`, :func:`patch_evaluate_grid`, :func:`patch_grid`,
  :func:`patch_derivatives`, :func:`patch_normal`);
- thin classes over them for the notebook: :class:`BezierCurve` and :class:`BezierPatch`.

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
from goldman_lib._kernels import flatness as _flatness, split as _split
from goldman_lib.validation import (as_float, as_float_array, as_int, as_parameter, as_points,
                                     finite_result, within_budget)

__all__ = [
    "de_casteljau", "de_casteljau_steps", "bernstein", "bernstein_evaluate",
    "hodograph", "derivative", "elevate_degree",
    "smooth_join", "join_continuity",
    "variation_count", "curve_crossings", "convex_hull", "convex_hull_contains", "apply_affine",
    "patch_de_casteljau", "patch_evaluate_grid", "patch_grid", "patch_derivatives", "patch_normal",
    "BezierCurve", "BezierPatch",
]

# Above this degree the binomial coefficients overflow a float; bernstein() then switches from
# "binomial times powers" to the (slower, equally stable) de Casteljau-like recurrence.
_POWER_FORM_MAX_DEGREE = 1000


# --------------------------------------------------------------------------------------------
# internal helpers (no validation)
# --------------------------------------------------------------------------------------------

def _ctrl(ctrl, name: str = "ctrl") -> np.ndarray:
    return as_points(ctrl, name, ndim=2)


def _net(ctrl, name: str = "ctrl") -> np.ndarray:
    return as_points(ctrl, name, ndim=3)


def _levels(pts: np.ndarray, t: np.ndarray) -> np.ndarray:
    """de Casteljau on a stack of polygons laid out (n+1, D, 1 or N) with t of shape (N,).

    Each level replaces the k points by k-1 affine combinations (1-t) P_j + t P_{j+1}, for all
    N parameters at once.  The points of a level are kept as separate (D, N) arrays updated in
    place: each array operation then works on a cache-sized block, which is about 4x faster than
    one operation on the whole (k, D, N) level.  Returns (D, N).
    """
    k = pts.shape[0]
    shape = (pts.shape[1], t.shape[0])
    if k == 1:
        return np.broadcast_to(pts[0], shape).copy()
    s = 1.0 - t
    buf = np.empty(shape)
    level = []
    for j in range(k - 1):
        row = np.multiply(pts[j], s)
        row += np.multiply(pts[j + 1], t, out=buf)
        level.append(row)
    for m in range(k - 2, 0, -1):          # level k-m: m+1 points become m
        for j in range(m):
            row = level[j]
            row *= s
            row += np.multiply(level[j + 1], t, out=buf)
    return level[0]


def _curve_points(ctrl: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Evaluate validated ctrl (n+1, d) at validated t by de Casteljau; returns t.shape + (d,)."""
    flat = t.reshape(-1)
    out = _levels(ctrl[:, :, None], flat)  # (d, N)
    return out.T.reshape(t.shape + (ctrl.shape[1],))


def _bernstein_rows(n: int, t: np.ndarray) -> np.ndarray:
    """B_k^n(t) for flat t (N,), laid out (n+1, N)."""
    N = t.shape[0]
    if n > _POWER_FORM_MAX_DEGREE:
        rows = np.zeros((n + 1, N))
        rows[0] = 1.0
        s = 1.0 - t
        for j in range(1, n + 1):
            # B_k^j = (1-t) B_k^{j-1} + t B_{k-1}^{j-1}, computed from the top down in place
            rows[1:j + 1] = rows[1:j + 1] * s + rows[0:j] * t
            rows[0] *= s
        return rows
    s = 1.0 - t
    tp = np.empty((n + 1, N))
    sp = np.empty((n + 1, N))
    tp[0] = 1.0
    sp[0] = 1.0
    for k in range(1, n + 1):
        np.multiply(tp[k - 1], t, out=tp[k])
        np.multiply(sp[k - 1], s, out=sp[k])
    binom = np.array([float(math.comb(n, k)) for k in range(n + 1)])
    tp *= binom[:, None]
    tp *= sp[::-1]
    return tp


# --------------------------------------------------------------------------------------------
# §24.2 de Casteljau
# --------------------------------------------------------------------------------------------

@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def de_casteljau(ctrl, t) -> np.ndarray:
    """Evaluate a Bezier curve by the de Casteljau algorithm (Goldman §24.2).

    Each level of the algorithm replaces consecutive control points by the affine combinations
    ``(1-t) P_j + t P_{j+1}``; after ``n`` levels one point is left, the point on the curve.  All
    parameters are processed at once (one array operation per level, no loop over ``t``).

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
    return finite_result(_curve_points(P, t), "t", t)


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
    levels = [P.copy()]
    cur = P
    while cur.shape[0] > 1:
        cur = (1.0 - t) * cur[:-1] + t * cur[1:]
        levels.append(finite_result(cur, "t", t))
    return levels


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
    rows = _bernstein_rows(n, t.reshape(-1))
    return finite_result(np.ascontiguousarray(rows.T).reshape(t.shape + (n + 1,)), "t", t)


def _bernstein_cost(n: int, count: int) -> int:
    """Values :func:`_bernstein_rows` computes: the (n+1) x count table, or the recurrence's
    (n+1)^2/2 per parameter above the power-form degree."""
    per = n + 1 if n <= _POWER_FORM_MAX_DEGREE else (n + 1) ** 2 // 2
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
    elif n > _POWER_FORM_MAX_DEGREE:
        out = P.T @ _bernstein_rows(n, tf)
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
    return finite_result(out.T.reshape(t.shape + (d,)), "t", t)


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
    return finite_result(_curve_points(D, t), "t", t)


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
    for _ in range(times):
        n1 = P.shape[0]  # n + 1
        a = (np.arange(1, n1) / n1)[:, None]
        Q = np.empty((n1 + 1, P.shape[1]))
        Q[0], Q[-1] = P[0], P[-1]
        Q[1:-1] = a * P[:-1] + (1.0 - a) * P[1:]
        P = Q
    return P.copy() if times == 0 else P


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
    for name, value in (("line_point", line_point), ("line_normal", line_normal)):
        shape = as_float_array(value, name).shape
        if len(shape) == 1 and shape != (d,):
            raise ValueError(f"{name} must hold {d}-dimensional points (last axis of length {d}), as ctrl does; "
                             f"got shape {shape}")
    p = as_points(line_point, "line_point", ndim=1, dim=d)
    nrm = as_points(line_normal, "line_normal", ndim=1, dim=d)
    if not np.any(nrm):
        raise ValueError("line_normal must be a nonzero vector; got all zeros")
    return (points - p) @ (nrm / np.linalg.norm(nrm))


def _sign_changes(s: np.ndarray, tol: float) -> int:
    signs = np.sign(s[np.abs(s) > tol])
    return int(np.count_nonzero(signs[1:] != signs[:-1]))


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
    return _sign_changes(_signed_distances(P, line_point, line_normal, P.shape[1]), tol)


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
    pts = _curve_points(P, np.linspace(0.0, 1.0, samples))
    return _sign_changes(_signed_distances(pts, line_point, line_normal, P.shape[1]), tol)


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


def _patch_points(P: np.ndarray, uf: np.ndarray, vf: np.ndarray) -> np.ndarray:
    """de Casteljau in v on every row, then in u on the resulting points: returns (d, N)."""
    m1, n1, d = P.shape
    # rows: (n+1, d*(m+1)... ) -> evaluate each row at v: stack rows along the coordinate axis
    rows = P.transpose(1, 0, 2).reshape(n1, m1 * d)[:, :, None]   # (n+1, (m+1)*d, 1)
    along_v = _levels(rows, vf)                                      # ((m+1)*d, N)
    cols = along_v.reshape(m1, d, -1)                               # (m+1, d, N)
    return _levels(cols, uf)                                         # (d, N)


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
    return _patch_points(P, uf, vf).T.reshape(shape + (P.shape[2],))


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
    Bu = _bernstein_rows(P.shape[0] - 1, u)           # (m+1, a)
    Bv = _bernstein_rows(P.shape[1] - 1, v)           # (n+1, b)
    # one (a, m+1) @ (m+1, n+1) @ (n+1, b) product per coordinate, batched over d by matmul
    out = Bu.T @ P.transpose(2, 0, 1) @ Bv          # (d, a, b)
    return np.ascontiguousarray(np.moveaxis(out, 0, -1))


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
        out.append(_patch_points(D, uf, vf).T.reshape(shape + (d,)))
    return out[0], out[1]


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
    nrm = np.cross(su, sv)
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


# ============================================================================================
# Chapter 25: Bezier subdivision (Goldman §25.2-25.5)
#
# Added for chapter 25; nothing above this line depends on it.  subdivide (§25.2); flatness,
# is_flat and render_by_subdivision (§25.3); intersect_curves and intersection_boxes (§25.3.1);
# subdivide_patch, patch_flatness, render_patch_by_subdivision and intersect_ray_patch (§25.3.2);
# subdivide_uniform and subdivision_variation_counts (§25.4); smooth_continuation and
# join_order (§25.5).
# ============================================================================================

__all__ += [
    "subdivide", "subdivide_uniform", "flatness", "is_flat", "render_by_subdivision",
    "intersect_curves", "intersection_boxes",
    "subdivide_patch", "patch_flatness", "render_patch_by_subdivision", "intersect_ray_patch",
    "subdivision_variation_counts", "smooth_continuation", "join_order",
]


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def subdivide(ctrl, t=0.5) -> tuple[np.ndarray, np.ndarray]:
    """Split a Bezier curve at ``t`` into two Bezier curves by the de Casteljau algorithm (Goldman §25.2).

    The points down the left edge of the de Casteljau pyramid, ``P_0^0, P_0^1, ..., P_0^n``, are
    the control points of the curve over ``[0, t]``; the points up the right edge,
    ``P_0^n, P_1^{n-1}, ..., P_n^0``, those of the curve over ``[t, 1]``.  Each piece is
    parametrised over [0, 1] again: ``left(s) = C(t s)`` and ``right(s) = C(t + (1 - t) s)``.
    A ``t`` outside [0, 1] is allowed and gives the control points of the extrapolated curve
    (for t > 1 the left piece is the curve over [0, t]).

    ctrl: (n+1, d) control points.  t: a finite scalar.
    Returns ``(left, right)``, each (n+1, d).
    Raises ValueError for a bad ctrl or a non-finite or non-scalar t; TypeError if not numeric.

    >>> left, right = subdivide([[0, 0], [1, 2], [2, 0]])
    >>> left.tolist(), right.tolist()
    ([[0.0, 0.0], [0.5, 1.0], [1.0, 1.0]], [[1.0, 1.0], [1.5, 1.0], [2.0, 0.0]])
    """
    P = _ctrl(ctrl)
    t = as_parameter(t, "t")
    if t.ndim != 0:
        raise ValueError(f"t must be a scalar for subdivide; got shape {t.shape}")
    left, right = _split(P, float(t))
    return finite_result(left, "t", t), finite_result(right, "t", t)


def subdivide_uniform(ctrl, depth, t=0.5) -> np.ndarray:
    """Subdivide a Bezier curve ``depth`` times, every piece at ``t``: 2**depth control polygons (Goldman §25.2, §25.4).

    With the default ``t = 1/2`` piece ``k`` is the curve over ``[k / 2**depth, (k+1) / 2**depth]``;
    another ``t`` (a finite scalar) splits every piece at its own parameter t, pieces in order
    along the curve.  As the depth grows the
    polygons converge to the curve (the distance shrinks by about 4 with each level), which is
    the basis of rendering by subdivision and of the proof of variation diminishing.

    ctrl: (n+1, d).  depth: int >= 0 within the work budget: the ``2**depth * (n+1) * d``
    coordinates of the result at most :data:`~goldman_lib.validation.MAX_ITEMS` (depth <= 20 for
    a planar cubic).
    Returns (2**depth, n+1, d).
    Raises TypeError if depth is not an integer, ValueError if it is negative or over the budget,
    ctrl is bad, or t is not a finite scalar.

    >>> subdivide_uniform([[0, 0], [1, 2], [2, 0]], 1)[1].tolist()
    [[1.0, 1.0], [1.5, 1.0], [2.0, 0.0]]
    """
    P = _ctrl(ctrl)
    t = as_parameter(t, "t")
    if t.ndim != 0:
        raise ValueError(f"t must be a scalar for subdivide_uniform; got shape {t.shape}")
    t = float(t)
    depth = within_budget(depth, "depth", cost=lambda v: 2 ** v * P.size, what="the subdivided curve",
                          unit="coordinates")
    pieces = P[None]
    for _ in range(depth):
        left, right = _split(pieces, t, axis=1)
        pieces = np.stack([left, right], axis=1).reshape((-1,) + P.shape)
    return pieces.copy() if depth == 0 else pieces


def flatness(ctrl, even=True):
    """How far a Bezier curve can be from the segment between its end points (Goldman §25.3).

    With ``even=True`` (the default) this is ``max_k |P_k - L_k|`` with ``L_k = (1 - k/n) P_0 +
    (k/n) P_n`` the *evenly spaced* points on the chord.  Those ``L_k`` are the control points of
    the chord written as a degree-n curve, so by the convex-hull property
    ``|C(t) - ((1-t) P_0 + t P_n)| <= flatness`` for every t in [0, 1]: the curve is close to
    the chord *and* its parametrisation is close to the chord's uniform one.  With
    ``even=False`` it is only the largest distance of a control point from the chord segment: a
    straight but unevenly parametrised polygon then counts as flat, which is enough for
    drawing but not for locating parameters (see :func:`intersect_curves`).

    ctrl: (n+1, d), or a stack (..., n+1, d) of polygons.  even: bool.  Returns a float >= 0 (0
    for a degree-0 curve), or an array (...) for a stack.
    Raises ValueError/TypeError for a bad ctrl.

    >>> flatness([[0, 0], [1, 2], [2, 0]])
    2.0
    >>> flatness([[0, 0], [1.8, 0], [2, 0]]), flatness([[0, 0], [1.8, 0], [2, 0]], even=False)
    (0.8, 0.0)
    >>> flatness([[[0, 0], [1, 2], [2, 0]], [[0, 0], [1, 0], [2, 0]]]).tolist()   # a stack of polygons
    [2.0, 0.0]
    """
    P = as_points(ctrl, "ctrl", ndim=None)
    if P.ndim < 2:
        raise ValueError(f"ctrl must have shape (n+1, d) or a stack (..., n+1, d); got shape {P.shape}")
    out = _flatness(P, bool(even))
    return float(out) if P.ndim == 2 else out


def is_flat(ctrl, tol, even=True) -> bool:
    """Whether a Bezier curve is within ``tol`` of its chord, ``flatness(ctrl, even) <= tol`` (Goldman §25.3).

    ctrl: (n+1, d).  tol: float >= 0.  even: as :func:`flatness`.  Returns a bool.
    Raises ValueError for a negative or non-finite tol, and as :func:`flatness`.

    >>> is_flat([[0, 0], [1, 0.001], [2, 0]], 0.01)
    True
    """
    tol = as_float(tol, "tol")
    if tol < 0:
        raise ValueError(f"tol must be >= 0; got {tol}")
    return flatness(ctrl, even) <= tol


def _tolerance(tol, name="tol") -> float:
    tol = as_float(tol, name, positive=True)
    return tol


def render_by_subdivision(ctrl, tol=1e-3, max_depth=24) -> tuple[np.ndarray, np.ndarray]:
    """A polyline within ``tol`` of a Bezier curve, by adaptive subdivision (Goldman §25.3).

    Subdivide at the midpoint until every piece is flat (:func:`flatness` <= tol), then draw
    each piece as the segment between its end points.  Flat parts of the curve get few points,
    tight bends many.  Since every vertex lies on the curve and each piece is within ``tol`` of
    its chord (evenly parametrised), the polyline is within ``tol`` of the curve.

    ctrl: (n+1, d).  tol: positive float, an absolute distance.  max_depth: int in [0, 40], the
    deepest subdivision (a safety stop; pieces at that depth are drawn flat or not).
    Returns ``(t, points)``: the parameters (k,) increasing from 0 to 1 and the points (k, d)
    on the curve at them.
    Raises ValueError for a non-positive tol, a bad max_depth or a bad ctrl.

    >>> t, pts = render_by_subdivision([[0, 0], [1, 2], [2, 0]], tol=0.2)
    >>> t.tolist()
    [0.0, 0.25, 0.5, 0.75, 1.0]
    """
    P = _ctrl(ctrl)
    tol = _tolerance(tol)
    max_depth = as_int(max_depth, "max_depth", minimum=0, maximum=40)
    pieces = P[None]
    starts = np.zeros(1)
    width = 1.0
    done_t, done_p = [np.zeros(1)], [P[:1]]
    for depth in range(max_depth + 1):
        flat = _flatness(pieces) <= tol
        if depth == max_depth:
            flat[:] = True
        done_t.append(starts[flat] + width)
        done_p.append(pieces[flat, -1])
        pieces, starts = pieces[~flat], starts[~flat]
        if len(pieces) == 0:
            break
        left, right = _split(pieces, 0.5, axis=1)
        width /= 2
        pieces = np.concatenate([left, right])
        starts = np.concatenate([starts, starts + width])
    t = np.concatenate(done_t)
    pts = np.concatenate(done_p)
    order = np.argsort(t, kind="stable")
    return t[order], pts[order]


# -- §25.3.1 curve-curve intersection ----------------------------------------------------------

def _boxes(P: np.ndarray) -> np.ndarray:
    """Axis-aligned bounding boxes of a stack of polygons (N, n+1, d): (N, 2, d) [min; max]."""
    return np.stack([P.min(axis=1), P.max(axis=1)], axis=1)


def _overlap(ba: np.ndarray, bb: np.ndarray, pad: float) -> np.ndarray:
    return np.all((ba[:, 0] <= bb[:, 1] + pad) & (bb[:, 0] <= ba[:, 1] + pad), axis=-1)


def _pair_levels(A: np.ndarray, B: np.ndarray, pad: float, flat_tol: float, max_depth: int, max_pairs: int):
    """Breadth-first subdivision of a pair of curves (Goldman §25.3.1), yielding one level at a time.

    Yields ``(level, a_pieces, b_pieces, a_intervals, b_intervals, flat)`` for the pairs whose
    bounding boxes overlap at that level; ``flat`` marks the pairs where both pieces are flat
    (they are not subdivided further).  Stops when no pair is left, at ``max_depth``, or
    when more than ``max_pairs`` pairs would be kept (then every kept pair is marked flat).
    """
    pa, pb = A[None], B[None]
    ia = np.array([[0.0, 1.0]])
    ib = np.array([[0.0, 1.0]])
    for level in range(max_depth + 1):
        keep = _overlap(_boxes(pa), _boxes(pb), pad)
        pa, pb, ia, ib = pa[keep], pb[keep], ia[keep], ib[keep]
        flat = (_flatness(pa) <= flat_tol) & (_flatness(pb) <= flat_tol)
        if level == max_depth or 4 * np.count_nonzero(~flat) > max_pairs:
            flat[:] = True
        yield level, pa, pb, ia, ib, flat
        pa, pb, ia, ib = pa[~flat], pb[~flat], ia[~flat], ib[~flat]
        if len(pa) == 0:
            return
        # both pieces of every pair are halved: four child pairs
        al, ar = _split(pa, 0.5, axis=1)
        bl, br = _split(pb, 0.5, axis=1)
        am = ia.mean(axis=1)
        bm = ib.mean(axis=1)
        ial = np.stack([ia[:, 0], am], 1)
        iar = np.stack([am, ia[:, 1]], 1)
        ibl = np.stack([ib[:, 0], bm], 1)
        ibr = np.stack([bm, ib[:, 1]], 1)
        pa = np.concatenate([al, al, ar, ar])
        pb = np.concatenate([bl, br, bl, br])
        ia = np.concatenate([ial, ial, iar, iar])
        ib = np.concatenate([ibl, ibr, ibl, ibr])


def _chord_guesses(pa, pb, ia, ib) -> np.ndarray:
    """Parameter guesses (N, 2) from intersecting the chords of flat piece pairs.

    The chord of a flat piece, parametrised uniformly, is within the flatness of the piece, so
    the chords' intersection parameters approximate the curves'.  Parallel chords (no single
    intersection) give the middle of both pieces; guesses are clipped to the pieces.
    """
    a0, a1 = pa[:, 0], pa[:, -1]
    b0, b1 = pb[:, 0], pb[:, -1]
    da, db, r = a1 - a0, b1 - b0, b0 - a0
    det = da[:, 0] * (-db[:, 1]) - da[:, 1] * (-db[:, 0])
    scale = np.linalg.norm(da, axis=1) * np.linalg.norm(db, axis=1)
    ok = np.abs(det) > 1e-12 * np.maximum(scale, 1e-300)
    safe = np.where(ok, det, 1.0)
    sig = (r[:, 0] * (-db[:, 1]) - r[:, 1] * (-db[:, 0])) / safe
    tau = (da[:, 0] * r[:, 1] - da[:, 1] * r[:, 0]) / safe
    sig = np.clip(np.where(ok, sig, 0.5), 0.0, 1.0)
    tau = np.clip(np.where(ok, tau, 0.5), 0.0, 1.0)
    s = ia[:, 0] + sig * (ia[:, 1] - ia[:, 0])
    t = ib[:, 0] + tau * (ib[:, 1] - ib[:, 0])
    return np.stack([s, t], axis=1)


def _solve2(J: np.ndarray, F: np.ndarray) -> np.ndarray:
    """Newton steps ``-J^+ F`` for a stack of 2x2 systems, (N, 2, 2) and (N, 2) -> (N, 2).

    Cramer's rule where J is comfortably invertible; elsewhere (a tangential intersection makes
    J singular) the least-squares step of the regularised normal equations, which tends to the
    minimum-norm (pseudo-inverse) step.
    """
    a, b, c, d = J[:, 0, 0], J[:, 0, 1], J[:, 1, 0], J[:, 1, 1]
    det = a * d - b * c
    size = a * a + b * b + c * c + d * d
    good = np.abs(det) > 1e-12 * size
    safe = np.where(good, det, 1.0)
    x = (d * F[:, 0] - b * F[:, 1]) / safe
    y = (a * F[:, 1] - c * F[:, 0]) / safe
    if not good.all():
        # (J^T J + lam I) step = J^T F
        g0 = a * F[:, 0] + c * F[:, 1]
        g1 = b * F[:, 0] + d * F[:, 1]
        lam = 1e-14 * size + 1e-300
        m00 = a * a + c * c + lam
        m01 = a * b + c * d
        m11 = b * b + d * d + lam
        mdet = m00 * m11 - m01 * m01
        x = np.where(good, x, (m11 * g0 - m01 * g1) / mdet)
        y = np.where(good, y, (m00 * g1 - m01 * g0) / mdet)
    return -np.stack([x, y], axis=1)


def _newton_pairs(A: np.ndarray, B: np.ndarray, st: np.ndarray, iterations: int = 100) -> tuple[np.ndarray, np.ndarray]:
    """Newton's method on a(s) - b(t) = 0 for many starting pairs at once, kept inside [0, 1]^2.

    The Jacobian [a'(s), -b'(t)] is singular at a tangential intersection, so there each step is
    the least-squares (minimum-norm) step, and the iterate is clipped to the unit square: at a
    tangency or at a smooth end-to-end join this converges linearly rather than quadratically,
    which is still ample for the tolerances asked.  A start still far from any solution after
    a dozen steps is dropped.  Returns (st, residual norms).
    """
    n, m = A.shape[0] - 1, B.shape[0] - 1
    HA = n * np.diff(A, axis=0) if n else np.zeros_like(A)
    HB = m * np.diff(B, axis=0) if m else np.zeros_like(B)
    scale = max(1.0, float(np.abs(A).max()), float(np.abs(B).max()))
    st = st.copy()
    active = np.ones(len(st), dtype=bool)
    for it in range(iterations):
        idx = np.flatnonzero(active)
        if idx.size == 0:
            break
        s, t = st[idx, 0], st[idx, 1]
        F = _curve_points(A, s) - _curve_points(B, t)
        if it == 12:
            hopeless = np.linalg.norm(F, axis=1) > 1e-3 * scale
            active[idx[hopeless]] = False
            keep = ~hopeless
            idx, s, t, F = idx[keep], s[keep], t[keep], F[keep]
        exact = np.linalg.norm(F, axis=1) <= 4e-16 * scale      # nothing left to improve
        active[idx[exact]] = False
        idx, s, t, F = idx[~exact], s[~exact], t[~exact], F[~exact]
        J = np.stack([_curve_points(HA, s), -_curve_points(HB, t)], axis=-1)   # (N, 2, 2)
        new = np.clip(st[idx] + _solve2(J, F), 0.0, 1.0)
        moved = np.abs(new - st[idx]).max(axis=1)
        st[idx] = new
        active[idx[moved <= 1e-15]] = False
    res = np.linalg.norm(_curve_points(A, st[:, 0]) - _curve_points(B, st[:, 1]), axis=1)
    return st, res


def _merge_solutions(st: np.ndarray, res: np.ndarray, meet, tol_abs: float, close: float = 1e-3) -> np.ndarray:
    """Deduplicate converged parameter points: two solutions are one if they are within 1e-9,
    or within ``close`` and the curves still meet half way between them (a tangential contact
    approached from several candidates).  Each cluster is represented by its best residual."""
    order = np.argsort(res, kind="stable")
    kept: list[np.ndarray] = []
    for i in order:
        p = st[i]
        same = False
        for q in kept:
            gap = np.abs(p - q).max()
            if gap <= 1e-9 or (gap <= close and meet((p + q) / 2) <= tol_abs):
                same = True
                break
        if not same:
            kept.append(p)
    if not kept:
        return np.zeros((0, st.shape[1]))
    out = np.array(kept)
    return out[np.lexsort(out.T[::-1])]


def _curves_pair(a, b):
    A = as_points(a, "a", ndim=2, dim=2)
    B = as_points(b, "b", ndim=2, dim=2)
    return A, B


def intersect_curves(a, b, tol=1e-10, max_depth=40) -> np.ndarray:
    """The parameter pairs ``(s, t)`` with ``a(s) = b(t)`` of two planar Bezier curves, by subdivision (Goldman §25.3.1).

    Subdivision finds where to look, Newton's method says exactly where:

    1. Keep a list of pairs of pieces, starting with the two whole curves.  Discard every pair
       whose control-point bounding boxes do not overlap: by the convex-hull property the
       pieces cannot meet.
    2. When both pieces of a pair are flat -- close to their chords *and* evenly parametrised,
       :func:`flatness` with ``even=True``, relative tolerance 1e-3 -- intersect the chords;
       the chord parameters approximate the curves'.  Otherwise halve both pieces and go on.
    3. Polish every guess by Newton's method on ``a(s) - b(t) = 0`` over the whole curves
       (least-squares steps kept inside [0, 1]^2, so tangential contacts converge too), keep
       the guesses where the curves meet within ``tol`` (relative to the size of the control
       points), and merge guesses that are the same intersection.

    The flatness test must ask for evenly spaced control points: a nearly straight curve with
    an uneven parametrisation has a straight polygon, but its chord's parameters are far from
    the curve's.

    a: (n+1, 2), b: (m+1, 2) control points.  tol: positive float, how close (relative to the
    size of the control points, at least 1) the curves must come to count as meeting.
    max_depth: int in [1, 60], the deepest subdivision.
    Returns (k, 2) parameter pairs ``[s, t]`` sorted by s; k = 0 if the curves do not meet.
    Transversal intersections are accurate to about 1e-15; tangential ones (double roots) to
    about 1e-8 and triple roots to about 1e-5.  A degree-0 curve (one point) gets parameter 0.
    Curves that overlap along a piece (infinitely many intersections) are not handled: a sample
    of points along the overlap is returned.
    Raises ValueError if a or b is not (k, 2) finite points, for a non-positive tol or a bad
    max_depth.

    >>> intersect_curves([[0, 0], [1, 2], [2, 0]], [[0, 0.75], [2, 0.75]]).round(12).tolist()
    [[0.25, 0.25], [0.75, 0.75]]
    >>> intersect_curves([[0, 0], [1, 0]], [[0, 1], [1, 1]]).shape
    (0, 2)
    """
    A, B = _curves_pair(a, b)
    tol = _tolerance(tol)
    max_depth = as_int(max_depth, "max_depth", minimum=1, maximum=60)
    scale = max(1.0, float(np.abs(A).max()), float(np.abs(B).max()))
    guesses = [np.array([[0.0, 0.0], [0.0, 1.0], [1.0, 0.0], [1.0, 1.0]])]
    for _, pa, pb, ia, ib, flat in _pair_levels(A, B, pad=1e-12 * scale, flat_tol=1e-3 * scale,
                                                  max_depth=max_depth, max_pairs=20000):
        if flat.any():
            guesses.append(_chord_guesses(pa[flat], pb[flat], ia[flat], ib[flat]))
    st = np.concatenate(guesses)
    st = np.unique(np.round(st, 12), axis=0)
    st, res = _newton_pairs(A, B, st)
    for axis, P in ((0, A), (1, B)):
        if len(P) == 1:          # a degree-0 "curve" is one point: its parameter is immaterial, call it 0
            st[:, axis] = 0.0
    tol_abs = tol * scale
    good = res <= tol_abs

    def meet(p):
        return float(np.linalg.norm(_curve_points(A, np.array(p[0])) - _curve_points(B, np.array(p[1]))))

    return _merge_solutions(st[good], res[good], meet, tol_abs)


def intersection_boxes(a, b, level) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The pieces of two curves still in play at one level of subdivision intersection (Goldman §25.3.1).

    For the picture of :func:`intersect_curves`: at ``level`` (0 = the whole curves) both curves
    have been halved ``level`` times and only the pairs of pieces whose bounding boxes overlap
    are kept.  Pairs that became flat at an earlier level stopped being split there; they are
    included as they were (their chords gave the first guesses of the intersections).

    a: (n+1, 2), b: (m+1, 2).  level: int in [0, 30].
    Returns ``(boxes_a, boxes_b, intervals_a, intervals_b)``: the distinct bounding boxes of the
    kept pieces of each curve, (k, 2, 2) as ``[[xmin, ymin], [xmax, ymax]]``, and their
    parameter intervals (k, 2).  Empty (0, 2, 2) arrays when no pair is left.
    Raises ValueError for bad curves or level.

    >>> ba, bb, ia, ib = intersection_boxes([[0, 0], [1, 2], [2, 0]], [[0, 1], [2, 1]], 1)
    >>> ia.tolist(), ib.tolist()
    ([[0.0, 0.5], [0.5, 1.0]], [[0.0, 0.5], [0.5, 1.0]])
    """
    A, B = _curves_pair(a, b)
    level = as_int(level, "level", minimum=0, maximum=30)
    scale = max(1.0, float(np.abs(A).max()), float(np.abs(B).max()))
    kept_a, kept_b, kept_ia, kept_ib = [], [], [], []
    for lv, pa, pb, ia, ib, flat in _pair_levels(A, B, pad=1e-12 * scale, flat_tol=1e-3 * scale,
                                                   max_depth=level, max_pairs=20000):
        take = slice(None) if lv == level else flat
        kept_a.append(pa[take])
        kept_b.append(pb[take])
        kept_ia.append(ia[take])
        kept_ib.append(ib[take])
    pa, pb = np.concatenate(kept_a), np.concatenate(kept_b)
    ia, ib = np.concatenate(kept_ia), np.concatenate(kept_ib)
    if len(pa) == 0:
        return np.zeros((0, 2, 2)), np.zeros((0, 2, 2)), np.zeros((0, 2)), np.zeros((0, 2))
    ua, ka = np.unique(ia, axis=0, return_index=True)
    ub, kb = np.unique(ib, axis=0, return_index=True)
    return _boxes(pa[ka]), _boxes(pb[kb]), ua, ub


# -- §25.3.2 surfaces ------------------------------------------------------------------------

def subdivide_patch(ctrl, u=0.5, v=0.5) -> np.ndarray:
    """Split a tensor-product Bezier patch at ``(u, v)`` into four patches (Goldman §25.3.2).

    Subdivide every row of the net at v and every column at u (de Casteljau along each
    direction, :func:`subdivide` applied to the rows and columns).

    ctrl: (m+1, n+1, d).  u, v: finite scalars.
    Returns (2, 2, m+1, n+1, d): ``[i, j]`` is the piece over ``[0, u]`` (i = 0) or ``[u, 1]``
    (i = 1) in u and ``[0, v]`` (j = 0) or ``[v, 1]`` (j = 1) in v, each reparametrised to
    [0, 1]^2.
    Raises ValueError for a bad net or non-scalar, non-finite u or v.

    >>> net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    >>> subdivide_patch(net)[1, 1, 0, 0].tolist()      # the patch's centre S(1/2, 1/2)
    [0.5, 0.5, 0.25]
    """
    P = _net(ctrl)
    u = as_parameter(u, "u")
    v = as_parameter(v, "v")
    for name, x in (("u", u), ("v", v)):
        if x.ndim != 0:
            raise ValueError(f"{name} must be a scalar for subdivide_patch; got shape {x.shape}")
    return _split_patches(P[None], float(u), float(v))[0]


def _split_patches(P: np.ndarray, u: float = 0.5, v: float = 0.5) -> np.ndarray:
    """Four-way split of a stack of nets (N, m+1, n+1, d) -> (N, 2, 2, m+1, n+1, d)."""
    lo, hi = _split(P, u, axis=1)
    out = []
    for half in (lo, hi):
        a, b = _split(half, v, axis=2)
        out.append(np.stack([a, b], axis=1))
    return np.stack(out, axis=1)


def _patch_flatness(P: np.ndarray) -> np.ndarray:
    """Flatness of a stack of nets (N, m+1, n+1, d) (no validation): (N,)."""
    m, n = P.shape[1] - 1, P.shape[2] - 1
    u = (np.arange(m + 1) / max(m, 1))[:, None, None]
    v = (np.arange(n + 1) / max(n, 1))[None, :, None]
    c00, c01 = P[:, :1, :1], P[:, :1, -1:]
    c10, c11 = P[:, -1:, :1], P[:, -1:, -1:]
    bilinear = (1 - u) * (1 - v) * c00 + (1 - u) * v * c01 + u * (1 - v) * c10 + u * v * c11
    off = np.linalg.norm(P - bilinear, axis=-1).max(axis=(1, 2))
    twist = np.linalg.norm((c00 - c01 - c10 + c11)[:, 0, 0], axis=-1)
    return off + twist / 4


def patch_flatness(ctrl) -> float:
    """How far a Bezier patch can be from the two triangles on its corners (Goldman §25.3.2).

    ``max_ij |P_ij - L_ij| + |P_00 - P_0n - P_m0 + P_mn| / 4``, where ``L_ij`` is the bilinear
    interpolant of the four corners at ``(i/m, j/n)``.  The first term bounds the distance from
    the patch to the bilinear patch of its corners (its control net is the ``L_ij``, by
    degree elevation), the second the distance from that bilinear patch to the two triangles
    ``P_00 P_m0 P_mn`` and ``P_00 P_mn P_0n``.

    ctrl: (m+1, n+1, d).  Returns a float >= 0.
    Raises ValueError/TypeError for a bad net.

    >>> patch_flatness([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]])
    0.0
    >>> patch_flatness([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    0.25
    """
    return float(_patch_flatness(_net(ctrl)[None])[0])


def render_patch_by_subdivision(ctrl, tol=1e-2, max_depth=10) -> tuple[np.ndarray, np.ndarray]:
    """Flat pieces covering a Bezier patch, by adaptive subdivision (Goldman §25.3.2).

    Split the patch into four until each piece is within ``tol`` of the two triangles on its
    corners (:func:`patch_flatness`); draw each piece as those two triangles.  (Neighbouring
    pieces of different sizes can leave hairline cracks along their common edge, of width at
    most ``tol``.)

    ctrl: (m+1, n+1, d).  tol: positive float (absolute distance).  max_depth: int in [0, 12].
    Returns ``(corners, domains)``: the corner points of the pieces (k, 4, d) in the order
    ``S(u0, v0), S(u1, v0), S(u1, v1), S(u0, v1)``, and their parameter rectangles (k, 4) as
    ``[u0, u1, v0, v1]``.
    Raises ValueError for a non-positive tol, a bad max_depth or a bad net.

    >>> corners, domains = render_patch_by_subdivision([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], 0.1)
    >>> len(domains)
    4
    """
    P = _net(ctrl)
    tol = _tolerance(tol)
    max_depth = as_int(max_depth, "max_depth", minimum=0, maximum=12)
    nets = P[None]
    dom = np.array([[0.0, 1.0, 0.0, 1.0]])
    out_c, out_d = [], []
    for depth in range(max_depth + 1):
        flat = _patch_flatness(nets) <= tol
        if depth == max_depth:
            flat[:] = True
        f = nets[flat]
        out_c.append(np.stack([f[:, 0, 0], f[:, -1, 0], f[:, -1, -1], f[:, 0, -1]], axis=1))
        out_d.append(dom[flat])
        nets, dom = nets[~flat], dom[~flat]
        if len(nets) == 0:
            break
        nets, dom = _quarter(nets, dom)
    return np.concatenate(out_c), np.concatenate(out_d)


def _quarter(nets: np.ndarray, dom: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Split nets (N, ...) and their domains (N, 4) into four: (4N, ...) and (4N, 4)."""
    split = _split_patches(nets)
    nets = split.reshape((-1,) + nets.shape[1:])
    um = (dom[:, 0] + dom[:, 1]) / 2
    vm = (dom[:, 2] + dom[:, 3]) / 2
    kids = []
    for i in (0, 1):
        for j in (0, 1):
            kids.append(np.stack([np.where(i, um, dom[:, 0]), np.where(i, dom[:, 1], um),
                                  np.where(j, vm, dom[:, 2]), np.where(j, dom[:, 3], vm)], axis=1))
    return nets, np.stack(kids, axis=1).reshape(-1, 4)


def _ray_hits_boxes(boxes: np.ndarray, o: np.ndarray, d: np.ndarray, pad: float) -> np.ndarray:
    """Slab test of the ray o + s d, s >= 0, against boxes (N, 2, 3)."""
    lo = boxes[:, 0] - pad
    hi = boxes[:, 1] + pad
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / d
        t1 = (lo - o) * inv
        t2 = (hi - o) * inv
    tmin = np.where(d == 0, np.where((o >= lo) & (o <= hi), -np.inf, np.inf), np.minimum(t1, t2))
    tmax = np.where(d == 0, np.where((o >= lo) & (o <= hi), np.inf, -np.inf), np.maximum(t1, t2))
    enter = tmin.max(axis=1)
    leave = tmax.min(axis=1)
    return (enter <= leave) & (leave >= 0)


def intersect_ray_patch(ctrl, origin, direction, tol=1e-10, max_depth=16) -> np.ndarray:
    """Where a ray meets a Bezier patch, by subdivision and Newton's method (Goldman §25.3.2).

    Split the patch into four, keep the pieces whose control-point bounding boxes the ray
    ``origin + s direction`` (s >= 0) passes through, until the pieces are flat; then polish
    each flat piece's centre by Newton's method on ``S(u, v) - origin - s direction = 0``
    (three equations, three unknowns, kept inside [0, 1]^2) and merge repeated solutions.

    ctrl: (m+1, n+1, 3).  origin: (3,).  direction: (3,), nonzero.  tol: positive float, how
    close (relative to the size of the net, at least 1) a solution must be.  max_depth: int in
    [1, 24].
    Returns (k, 3) rows ``[u, v, s]`` sorted by s (the nearest hit first); k = 0 if the ray
    misses.  A ray lying in a flat patch (infinitely many hits) is not handled.
    Raises ValueError for a net that is not 3D, a zero direction, a non-positive tol or a bad
    max_depth.

    >>> net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]   # the unit square in z = 0
    >>> intersect_ray_patch(net, [0.25, 0.5, 1.0], [0, 0, -1]).tolist()
    [[0.25, 0.5, 1.0]]
    """
    P = as_points(ctrl, "ctrl", ndim=3, dim=3)
    o = as_points(origin, "origin", ndim=1, dim=3)
    d = as_points(direction, "direction", ndim=1, dim=3)
    if not np.any(d):
        raise ValueError("direction must be a nonzero vector; got all zeros")
    tol = _tolerance(tol)
    max_depth = as_int(max_depth, "max_depth", minimum=1, maximum=24)
    scale = max(1.0, float(np.abs(P).max()), float(np.abs(o).max()))
    flat_tol = 1e-3 * scale
    nets = P[None]
    dom = np.array([[0.0, 1.0, 0.0, 1.0]])
    guesses = []
    for depth in range(max_depth + 1):
        boxes = np.stack([nets.min(axis=(1, 2)), nets.max(axis=(1, 2))], axis=1)
        keep = _ray_hits_boxes(boxes, o, d, 1e-12 * scale)
        nets, dom = nets[keep], dom[keep]
        if len(nets) == 0:
            break
        flat = _patch_flatness(nets) <= flat_tol
        if depth == max_depth or 4 * np.count_nonzero(~flat) > 20000:
            flat[:] = True
        guesses.append(np.stack([(dom[flat, 0] + dom[flat, 1]) / 2, (dom[flat, 2] + dom[flat, 3]) / 2], 1))
        nets, dom = nets[~flat], dom[~flat]
        if len(nets) == 0:
            break
        nets, dom = _quarter(nets, dom)
    if not guesses:
        return np.zeros((0, 3))
    uv = np.concatenate(guesses)
    if len(uv) == 0:
        return np.zeros((0, 3))
    uvs, res = _newton_ray(P, o, d, uv)
    tol_abs = tol * scale
    good = (res <= tol_abs) & (uvs[:, 2] >= -tol)

    def meet(p):
        return float(np.linalg.norm(_patch_points(P, np.array([p[0]]), np.array([p[1]]))[:, 0] - o - p[2] * d))

    out = _merge_solutions(uvs[good], res[good], meet, tol_abs)
    return out[np.argsort(out[:, 2], kind="stable")] if len(out) else out


def _newton_ray(P, o, d, uv, iterations=60):
    """Newton on S(u, v) - o - s d = 0 from many (u, v) starts (s starts at the projection)."""
    m, n = P.shape[0] - 1, P.shape[1] - 1
    Du = m * np.diff(P, axis=0) if m else np.zeros_like(P)
    Dv = n * np.diff(P, axis=1) if n else np.zeros_like(P)
    u, v = uv[:, 0].copy(), uv[:, 1].copy()
    S = _patch_points(P, u, v).T
    s = (S - o) @ d / (d @ d)
    x = np.stack([u, v, s], 1)
    for _ in range(iterations):
        S = _patch_points(P, x[:, 0], x[:, 1]).T
        F = S - o - x[:, 2:3] * d
        J = np.stack([_patch_points(Du, x[:, 0], x[:, 1]).T, _patch_points(Dv, x[:, 0], x[:, 1]).T,
                      np.broadcast_to(-d, F.shape)], axis=-1)
        step = -(np.linalg.pinv(J, rcond=1e-13) @ F[:, :, None])[:, :, 0]
        new = x + step
        new[:, :2] = np.clip(new[:, :2], 0.0, 1.0)
        moved = np.abs(new - x).max()
        x = new
        if moved <= 1e-15:
            break
    S = _patch_points(P, x[:, 0], x[:, 1]).T
    res = np.linalg.norm(S - o - x[:, 2:3] * d, axis=1)
    return x, res


# -- §25.4 variation diminishing by subdivision ----------------------------------------------

def subdivision_variation_counts(ctrl, line_point, line_normal, max_depth=8, tol=1e-12) -> list[int]:
    """Line crossings of the subdivided control polygons, depth 0 to ``max_depth`` (Goldman §25.4).

    At depth k the curve is split into 2**k pieces at the midpoints and their control polygons,
    joined end to end, form one polygon (each shared end point counted once).  Each
    subdivision step is a sequence of corner cuttings, which never increase the number of
    crossings with a line, and the polygons converge to the curve: so the counts decrease to
    the number of times the curve crosses the line -- the proof of the variation diminishing
    property (:func:`variation_count` >= :func:`curve_crossings`).

    ctrl: (n+1, d).  line_point, line_normal: (d,), the normal nonzero.  max_depth: int in
    [0, 16].  tol: float >= 0, distances below which a point counts as on the line.
    Returns a list of max_depth + 1 ints, non-increasing.
    Raises ValueError for bad shapes, non-finite values, a zero normal or a bad max_depth.

    >>> subdivision_variation_counts([[0, 1], [1, -2], [2, 0], [3, 1]], [0, -0.7], [0, 1], 4)
    [2, 2, 0, 0, 0]
    """
    P = _ctrl(ctrl)
    max_depth = as_int(max_depth, "max_depth", minimum=0, maximum=16)
    tol = as_float(tol, "tol")
    counts = []
    for depth in range(max_depth + 1):
        pieces = subdivide_uniform(P, depth)
        joined = np.concatenate([pieces[:, :-1].reshape(-1, P.shape[1]), pieces[-1, -1:]])
        counts.append(_sign_changes(_signed_distances(joined, line_point, line_normal, P.shape[1]), tol))
    return counts


# -- §25.5 smooth joins ----------------------------------------------------------------------

@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def smooth_continuation(ctrl, ratio=1.0) -> np.ndarray:
    """The control points of a Bezier curve's own polynomial continued past its end (Goldman §25.5).

    The curve P runs over [0, 1]; its polynomial over the next interval [1, 1 + ratio],
    reparametrised to [0, 1], has control points ``Q`` with ``Q(s) = P(1 + ratio s)``.  They
    come from one extrapolating subdivision (of the reversed polygon at ``t = -ratio``).  A
    curve R of the same degree meets P with C^k continuity (parameter intervals in the ratio
    ``ratio``) exactly when ``R_0, ..., R_k`` equal ``Q_0, ..., Q_k``: the first k+1 control
    points of R are those of a subdivision of one polynomial curve.

    ctrl: (n+1, d).  ratio: positive float, (next interval length) / (this one).
    Returns (n+1, d).
    Raises ValueError for ratio <= 0, a ratio so large that the points overflow float64, and as
    :func:`subdivide`.

    >>> smooth_continuation([[0, 0], [1, 2], [2, 0]]).tolist()
    [[2.0, 0.0], [3.0, -2.0], [4.0, -8.0]]
    """
    P = _ctrl(ctrl)
    ratio = as_float(ratio, "ratio", positive=True)
    return finite_result(_split(P[::-1], -ratio)[0], "ratio", ratio)


def join_order(a, b, ratio=1.0, tol=1e-9) -> int:
    """The order of continuity where curve ``a`` ends and curve ``b`` begins: the largest k with C^k (Goldman §25.5).

    Both curves are written with the larger of their degrees (:func:`elevate_degree`, which
    does not change them) and b's control points are compared with
    :func:`smooth_continuation` of a: the join is C^k exactly when the first k+1 agree.  (When
    b's interval is the longer one, a's reversed polygon is compared with b's polynomial
    continued backwards instead: the same test, with less amplification of rounding errors.)
    Returns -1 if the curves do not even meet, and the common degree n if b continues a's
    polynomial (C^n then means C^infinity: the two are one polynomial curve).  The two halves
    of a subdivided curve meet with ``ratio = (1 - t) / t``, order n.

    a: (n+1, d), b: (m+1, d), same d.  ratio: positive float, (b's parameter interval) / (a's).
    tol: positive float, relative to the size of the control points (at least 1).
    Returns an int in [-1, max(n, m)].
    Raises ValueError for different dimensions, ratio <= 0 or tol <= 0.

    >>> left, right = subdivide([[0, 0], [1, 2], [3, 2], [4, 0]], 0.25)
    >>> join_order(left, right, ratio=3.0)
    3
    >>> join_order([[0, 0], [1, 1], [2, 0]], [[2, 0], [3, -1], [4, 0]])
    1
    """
    A = _ctrl(a, "a")
    B = _ctrl(b, "b")
    if A.shape[1] != B.shape[1]:
        raise ValueError(f"a and b must hold points of the same dimension; got shapes {A.shape} and {B.shape}")
    ratio = as_float(ratio, "ratio", positive=True)
    tol = as_float(tol, "tol", positive=True)
    n = max(A.shape[0], B.shape[0]) - 1
    A = elevate_degree(A, n - (A.shape[0] - 1))
    B = elevate_degree(B, n - (B.shape[0] - 1))
    # Extrapolate over the shorter interval (ratio <= 1): extrapolation multiplies rounding errors
    # by up to (1 + 2 ratio)^n.  Continuing b backwards over a's interval gives a reversed.
    if ratio <= 1.0:
        Q, target = _split(A[::-1], -ratio)[0], B
    else:
        Q, target = _split(B, -1.0 / ratio)[0], A[::-1]
    scale = max(1.0, float(np.abs(A).max()), float(np.abs(B).max()), float(np.abs(Q).max()))
    order = -1
    for k in range(n + 1):
        if np.linalg.norm(Q[k] - target[k]) > tol * scale:
            break
        order = k
    return order


# -- §25.3.2 surface-surface intersection ------------------------------------------------------

__all__ += ["intersect_patches"]


def _triangle_pair_segments(T, S, TP, SP, eps=1e-9):
    """Intersection segments of triangle pairs (no validation).

    T, S: (N, 3, 3) vertices; TP, SP: (N, 3, 2) the (u, v) parameters at those vertices.
    Every edge of S is cut with the plane of T (and every edge of T with the plane of S); the
    cut points inside the other triangle are where the triangles meet, and the two farthest
    apart are the ends of the segment.  Returns ``(ends (N, 2, 3), params (N, 2, 4), hit (N,))``
    with params ``[u_T, v_T, u_S, v_S]``.  Coplanar triangles give no segment.
    """
    def cuts(X, Y, XP, YP):
        # points where the edges of Y cross the plane of X and lie inside X
        n = np.cross(X[:, 1] - X[:, 0], X[:, 2] - X[:, 0])
        d = ((Y - X[:, None, 0]) * n[:, None]).sum(-1)                      # (N, 3)
        d0, d1 = d, np.roll(d, -1, axis=1)
        y0, y1 = Y, np.roll(Y, -1, axis=1)
        p0, p1 = YP, np.roll(YP, -1, axis=1)
        cross = ((d0 <= 0) & (d1 >= 0) | (d0 >= 0) & (d1 <= 0)) & (d0 != d1)
        lam = np.clip(d0 / np.where(d0 != d1, d0 - d1, 1.0), 0.0, 1.0)[..., None]
        pts = y0 + lam * (y1 - y0)
        par_y = p0 + lam * (p1 - p0)
        # barycentric coordinates of the cut points in X
        e1, e2 = X[:, 1] - X[:, 0], X[:, 2] - X[:, 0]
        w = pts - X[:, None, 0]
        d11, d12, d22 = (e1 * e1).sum(-1), (e1 * e2).sum(-1), (e2 * e2).sum(-1)
        den = d11 * d22 - d12 * d12
        ok = den > 1e-30 * np.maximum(d11 * d22, 1e-300)
        den = np.where(ok, den, 1.0)[:, None]
        w1, w2 = (w * e1[:, None]).sum(-1), (w * e2[:, None]).sum(-1)
        b1 = (d22[:, None] * w1 - d12[:, None] * w2) / den
        b2 = (d11[:, None] * w2 - d12[:, None] * w1) / den
        b0 = 1.0 - b1 - b2
        inside = cross & ok[:, None] & (b0 >= -eps) & (b1 >= -eps) & (b2 >= -eps)
        bary = np.clip(np.stack([b0, b1, b2], -1), 0.0, 1.0)
        bary /= bary.sum(-1, keepdims=True)
        par_x = (bary[..., :, None] * XP[:, None]).sum(-2)
        return pts, par_x, par_y, inside

    pa, ta, sa, ina = cuts(T, S, TP, SP)          # edges of S: params on T, on S
    pb, sb, tb, inb = cuts(S, T, SP, TP)          # edges of T: params on S, on T
    pts = np.concatenate([pa, pb], axis=1)                                            # (N, 6, 3)
    par = np.concatenate([np.concatenate([ta, sa], -1), np.concatenate([tb, sb], -1)], axis=1)
    ok = np.concatenate([ina, inb], axis=1)
    dist = np.linalg.norm(pts[:, :, None] - pts[:, None, :], axis=-1)
    dist = np.where(ok[:, :, None] & ok[:, None, :], dist, -1.0)
    flat_idx = dist.reshape(len(T), -1).argmax(axis=1)
    i, j = np.divmod(flat_idx, 6)
    rows = np.arange(len(T))
    ends = np.stack([pts[rows, i], pts[rows, j]], axis=1)
    params = np.stack([par[rows, i], par[rows, j]], axis=1)
    return ends, params, ok.any(axis=1)


def _corner_triangles(nets: np.ndarray, dom: np.ndarray):
    """The two corner triangles of each net, P00 Pm0 Pmn and P00 Pmn P0n, with their parameters:
    (2N, 3, 3) and (2N, 3, 2), first triangles then second."""
    c = np.stack([nets[:, 0, 0], nets[:, -1, 0], nets[:, -1, -1], nets[:, 0, -1]], axis=1)
    u0, u1, v0, v1 = dom.T
    p = np.stack([np.stack([u0, v0], 1), np.stack([u1, v0], 1), np.stack([u1, v1], 1), np.stack([u0, v1], 1)], 1)
    tri = np.concatenate([c[:, [0, 1, 2]], c[:, [0, 2, 3]]])
    par = np.concatenate([p[:, [0, 1, 2]], p[:, [0, 2, 3]]])
    return tri, par


def _patch_pair_segments(A: np.ndarray, B: np.ndarray, tol: float, max_depth: int, max_pairs: int = 40000):
    """Subdivide two nets in pairs until both pieces are flat to ``tol`` (or boxes miss); intersect the
    corner triangles of the flat pairs.  Returns segment ends (k, 2, 3) and their params (k, 2, 4)."""
    scale = max(1.0, float(np.abs(A).max()), float(np.abs(B).max()))
    pad = 1e-12 * scale
    na, nb = A[None], B[None]
    da = db = np.array([[0.0, 1.0, 0.0, 1.0]])
    flat_a, flat_b = [], []
    for depth in range(max_depth + 1):
        ba = np.stack([na.min(axis=(1, 2)), na.max(axis=(1, 2))], axis=1)
        bb = np.stack([nb.min(axis=(1, 2)), nb.max(axis=(1, 2))], axis=1)
        keep = _overlap(ba, bb, pad)
        na, da, nb, db = na[keep], da[keep], nb[keep], db[keep]
        if len(na) == 0:
            break
        fa = _patch_flatness(na) <= tol
        fb = _patch_flatness(nb) <= tol
        done = fa & fb
        growth = np.where(fa | fb, 4, 16)[~done].sum()
        if depth == max_depth or growth > max_pairs:
            done[:] = True
        flat_a.append((na[done], da[done]))
        flat_b.append((nb[done], db[done]))
        rest = ~done
        na, da, nb, db, fa, fb = na[rest], da[rest], nb[rest], db[rest], fa[rest], fb[rest]
        if len(na) == 0:
            break
        parts = []
        for split_a, split_b in ((True, True), (True, False), (False, True)):
            g = (~fa == split_a) & (~fb == split_b)
            if not g.any():
                continue
            ga, gda, gb, gdb = na[g], da[g], nb[g], db[g]
            ka = kb = 1
            if split_a:
                ga, gda = _quarter(ga, gda)
                ka = 4
            if split_b:
                gb, gdb = _quarter(gb, gdb)
                kb = 4
            k = len(na[g])
            # every child of the piece of a meets every child of the piece of b
            ia = np.repeat(np.arange(k * ka).reshape(k, ka), kb, axis=1).ravel()
            ib = np.tile(np.arange(k * kb).reshape(k, kb), (1, ka)).ravel()
            parts.append((ga[ia], gda[ia], gb[ib], gdb[ib]))
        na = np.concatenate([p[0] for p in parts])
        da = np.concatenate([p[1] for p in parts])
        nb = np.concatenate([p[2] for p in parts])
        db = np.concatenate([p[3] for p in parts])
    if not flat_a or sum(len(x[0]) for x in flat_a) == 0:
        return np.zeros((0, 2, 3)), np.zeros((0, 2, 4))
    na = np.concatenate([x[0] for x in flat_a])
    da = np.concatenate([x[1] for x in flat_a])
    nb = np.concatenate([x[0] for x in flat_b])
    db = np.concatenate([x[1] for x in flat_b])
    ta, pa = _corner_triangles(na, da)          # (2N, ...): triangle 1 of every piece, then triangle 2
    tb, pb = _corner_triangles(nb, db)
    N = len(na)
    ia = np.concatenate([np.arange(N), np.arange(N), np.arange(N) + N, np.arange(N) + N])
    ib = np.concatenate([np.arange(N), np.arange(N) + N, np.arange(N), np.arange(N) + N])
    ends, params, hit = _triangle_pair_segments(ta[ia], tb[ib], pa[ia], pb[ib])
    return ends[hit], params[hit]


def _newton_patches(A: np.ndarray, B: np.ndarray, x: np.ndarray, iterations: int = 30):
    """Gauss-Newton on A(u, v) - B(s, t) = 0 (3 equations, 4 unknowns) from many starts (N, 4).

    Each step is the least-norm solution of the linearised system, ``-J^+ F`` with J the 3x4
    Jacobian ``[A_u, A_v, -B_s, -B_t]``: it moves the parameters as little as possible, so each
    start lands on the intersection curve near where it began.  Parameters are kept in [0, 1].
    Returns (x, residual norms).
    """
    def derivs(P):
        m, n = P.shape[0] - 1, P.shape[1] - 1
        return (m * np.diff(P, axis=0) if m else np.zeros_like(P)), (n * np.diff(P, axis=1) if n else np.zeros_like(P))

    Au, Av = derivs(A)
    Bs, Bt = derivs(B)
    x = x.copy()
    for _ in range(iterations):
        F = _patch_points(A, x[:, 0], x[:, 1]).T - _patch_points(B, x[:, 2], x[:, 3]).T
        J = np.stack([_patch_points(Au, x[:, 0], x[:, 1]).T, _patch_points(Av, x[:, 0], x[:, 1]).T,
                      -_patch_points(Bs, x[:, 2], x[:, 3]).T, -_patch_points(Bt, x[:, 2], x[:, 3]).T], axis=-1)
        step = -(np.linalg.pinv(J, rcond=1e-12) @ F[:, :, None])[:, :, 0]
        new = np.clip(x + step, 0.0, 1.0)
        moved = float(np.abs(new - x).max()) if len(x) else 0.0
        x = new
        if moved <= 1e-15:
            break
    res = np.linalg.norm(_patch_points(A, x[:, 0], x[:, 1]).T - _patch_points(B, x[:, 2], x[:, 3]).T, axis=1)
    return x, res


def intersect_patches(a, b, tol=1e-2, max_depth=10, polish=True, segments=False) -> tuple[np.ndarray, ...]:
    """Sample points of the curve where two Bezier patches meet, by subdivision (Goldman §25.3.2).

    The surface version of curve-curve intersection (:func:`intersect_curves`):

    1. Keep a list of pairs of pieces, starting with the two whole patches; discard every pair
       whose control-point bounding boxes do not overlap (by the convex-hull property the pieces
       cannot meet).
    2. Split into four (:func:`subdivide_patch`) every piece of a pair that is not yet flat to
       ``tol`` (:func:`patch_flatness`: within ``tol`` of the two triangles on its corners), and
       pair the children.
    3. When both pieces of a pair are flat, intersect their corner triangles (four triangle
       pairs); each crossing gives a short segment whose ends, with their parameters, sample
       the intersection curve to within about ``tol``.
    4. With ``polish=True`` move every sample onto both surfaces by Newton's method on
       ``a(u, v) - b(s, t) = 0`` -- three equations in four unknowns, so each step is the
       least-norm (Gauss-Newton, pseudo-inverse) step, which slides the sample as little as
       possible -- and merge samples that coincide.

    Consecutive samples along the curve are at most one flat piece apart, so a smaller ``tol``
    gives a denser sampling.  Patches that overlap in a region (coplanar pieces) are not handled.

    a: (m+1, n+1, 3), b: (p+1, q+1, 3) control nets.  tol: positive float, the flatness
    tolerance (an absolute distance).  max_depth: int in [0, 12], the deepest subdivision.
    polish: bool.  segments: bool, also return how the samples join up.
    Returns ``(points, params)``: (k, 3) points and (k, 4) parameters ``[u, v, s, t]`` with
    ``points ~ a(u, v) ~ b(s, t)``, sorted by the parameters on a; k = 0 if the patches do not
    meet.  A sample whose Newton iteration fails keeps its unpolished value.  With
    ``segments=True``, ``(points, params, pairs)``: pairs (j, 2) are the indices of the samples
    joined by a triangle-triangle segment -- the intersection curve as a polyline.
    Raises ValueError if a or b is not a finite (m+1, n+1, 3) net, for a non-positive tol or a
    bad max_depth; TypeError if max_depth is not an integer.

    >>> floor = [[[0, 0, 0], [0, 2, 0]], [[2, 0, 0], [2, 2, 0]]]          # z = 0 over [0, 2]^2
    >>> ramp = [[[0, 0.5, -1], [0, 1.5, -1]], [[2, 0.5, 1], [2, 1.5, 1]]]  # z = x - 1
    >>> points, params = intersect_patches(floor, ramp)
    >>> points.round(12).tolist()
    [[1.0, 0.5, 0.0], [1.0, 1.0, 0.0], [1.0, 1.5, 0.0]]
    >>> params[0].round(12).tolist()
    [0.5, 0.25, 0.5, 0.0]
    """
    A = as_points(a, "a", ndim=3, dim=3)
    B = as_points(b, "b", ndim=3, dim=3)
    tol = _tolerance(tol)
    max_depth = as_int(max_depth, "max_depth", minimum=0, maximum=12)
    ends, params = _patch_pair_segments(A, B, tol, max_depth)
    if len(ends) == 0:
        return (np.zeros((0, 3)), np.zeros((0, 4))) + ((np.zeros((0, 2), dtype=int),) if segments else ())
    pts = ends.reshape(-1, 3)
    x = params.reshape(-1, 4)
    scale = max(1.0, float(np.abs(A).max()), float(np.abs(B).max()))
    if polish:
        x0 = x
        x, res = _newton_patches(A, B, x0)
        res0 = np.linalg.norm(_patch_points(A, x0[:, 0], x0[:, 1]).T - _patch_points(B, x0[:, 2], x0[:, 3]).T, axis=1)
        better = res <= res0
        x = np.where(better[:, None], x, x0)
        pa = _patch_points(A, x[:, 0], x[:, 1]).T
        pb = _patch_points(B, x[:, 2], x[:, 3]).T
        pts = np.where(better[:, None], (pa + pb) / 2, pts)
    # merge repeated samples (segment ends shared by neighbouring triangles and pieces)
    key = np.round(np.concatenate([pts / scale, x], axis=1), 9)
    _, first, which = np.unique(key, axis=0, return_index=True, return_inverse=True)
    pts, x = pts[first], x[first]
    order = np.lexsort(x[:, ::-1].T)
    if not segments:
        return pts[order], x[order]
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    pairs = np.sort(rank[np.asarray(which).reshape(-1, 2)], axis=1)
    pairs = np.unique(pairs[pairs[:, 0] != pairs[:, 1]], axis=0)
    return pts[order], x[order], _bridge_cracks(pts[order], x[order], pairs)


def _bridge_cracks(pts: np.ndarray, x: np.ndarray, pairs: np.ndarray) -> np.ndarray:
    """Join the loose ends of a sampled intersection polyline across the cracks between flat pieces
    of different sizes: an end inside both parameter squares (the curve cannot end there) is
    joined to the nearest other such end, if it is no farther than the longest segment."""
    if len(pairs) == 0:
        return pairs
    degree = np.bincount(pairs.ravel(), minlength=len(pts))
    inside = np.all((x > 1e-9) & (x < 1 - 1e-9), axis=1)
    loose = list(np.flatnonzero((degree == 1) & inside))
    reach = float(np.linalg.norm(pts[pairs[:, 0]] - pts[pairs[:, 1]], axis=1).max())
    extra = []
    while len(loose) >= 2:
        i = loose.pop(0)
        d = np.linalg.norm(pts[loose] - pts[i], axis=1)
        k = int(np.argmin(d))
        if d[k] <= reach:
            extra.append(sorted((i, loose.pop(k))))
    if not extra:
        return pairs
    return np.unique(np.concatenate([pairs, np.array(extra)]), axis=0)

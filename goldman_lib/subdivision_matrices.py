"""Subdivision matrices and iterated function systems: curves as attractors, normal curves, and
fractals with control points (Goldman, chapter 29).

Subdivision splits a curve with control points ``P`` (rows, ``(n+1, d)``) into two halves whose
control points are ``L @ P`` and ``R @ P``, with *subdivision matrices* ``L`` and ``R`` that depend
only on the degree (§29.2: :func:`bezier_subdivision_matrices`, :func:`bspline_subdivision_matrices`).
Every row of ``L`` and ``R`` sums to one (the new control points are affine combinations).

If ``P`` is square and invertible — a control point per row, in homogeneous coordinates
``[x y ... 1]``, *lifted* to extra coordinates when the points live in too few dimensions
(:func:`lift_control_points`) — then the maps ``P^-1 L P`` and ``P^-1 R P`` act on points as row
vectors (``Q = X @ M``, translation in the last row, the book's convention) and send the control
polygon to the control polygons of the two halves.  So the curve is the attractor of the IFS
``{P^-1 L P, P^-1 R P}`` (§29.3: :func:`curve_ifs`, :func:`attractor`).  For ``P`` the vertices of
the standard simplex the curve is the *normal curve* (:func:`normal_curve`), whose IFS is ``{L, R}``
itself; every Bezier curve of degree n is an affine image of it.

Replacing ``L`` and ``R`` by any other matrices with rows summing to one gives fractals that move
with their control points (§29.4: :func:`fractal_matrices`, :func:`sierpinski_matrices`,
:func:`control_point_ifs`).  For three control points in the plane the maps are 3x3 and
:func:`control_point_ifs` returns a :class:`goldman_lib.ifs.IFS`, drawn by ``ifs.deterministic``
or ``ifs.chaos_game``; in higher dimensions :func:`attractor` runs the deterministic algorithm.

>>> L, R = bezier_subdivision_matrices(2)
>>> (L * 4).tolist()
[[4.0, 0.0, 0.0], [2.0, 2.0, 0.0], [1.0, 2.0, 1.0]]
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import ifs
from goldman_lib.kernels import iteration
from goldman_lib.validation import (as_float, as_float_array, as_int, as_parameter, as_points, as_tolerance,
                                     check_finite, finite_result, within_budget)

__all__ = ["bezier_subdivision_matrices", "bspline_subdivision_matrices", "check_rows_sum_to_one",
           "lift_control_points", "curve_ifs", "contraction_factors", "attractor", "curve_as_attractor", "normal_curve",
           "normal_curve_control_points", "fractal_matrices", "sierpinski_matrices", "control_point_ifs",
           "barycentric_attractor", "MAX_POINTS"]

#: The most points :func:`attractor` will produce.
MAX_POINTS = 2_000_000
#: The highest degree of the matrices and normal curves: above it (about 1029) the binomial
#: coefficients C(n, k) overflow float64.
MAX_DEGREE = 1000


def _degree(n, name: str = "n", minimum: int = 0) -> int:
    n = as_int(n, name, minimum=minimum)
    if n > MAX_DEGREE:
        raise ValueError(f"{name} must be <= {MAX_DEGREE}: the binomial coefficients C({name}, k) of higher degrees "
                         f"overflow float64 (and the work grows like {name}^2); got {n}")
    return n


# --------------------------------------------------------------------------------------------
# §29.2 subdivision matrices
# --------------------------------------------------------------------------------------------

def bezier_subdivision_matrices(n: int, t: float = 0.5) -> tuple[np.ndarray, np.ndarray]:
    """The subdivision matrices ``(L, R)`` of a degree-n Bezier curve at parameter t (Goldman §29.2).

    ``L @ P`` are the control points of the curve on [0, t] and ``R @ P`` those on [t, 1]:
    ``L[i, j] = B_j^i(t)`` (the left edge of the de Casteljau triangle) and
    ``R[i, j] = B_{j-i}^{n-i}(t)`` (its right edge).  Both are ``(n+1, n+1)``, lower and upper
    triangular, with rows summing to one.

    n: degree, 0 <= n <= :data:`MAX_DEGREE` (1000: beyond it the binomial coefficients overflow
    float64).  t: the split parameter (default 1/2), any finite number.
    Raises TypeError/ValueError for a non-integer, negative or too large n, a non-finite t, or a t
    so far from [0, 1] that an entry overflows float64.

    >>> L, R = bezier_subdivision_matrices(1)
    >>> L.tolist(), R.tolist()
    ([[1.0, 0.0], [0.5, 0.5]], [[0.5, 0.5], [0.0, 1.0]])
    """
    n = _degree(n)
    t = as_float(t, "t")
    try:
        # the same products as comb(i, j) * t**j * (1-t)**(i-j) entry by entry, one row at a time
        tp = np.array([t ** j for j in range(n + 1)])
        sp = np.array([(1 - t) ** j for j in range(n + 1)])
    except OverflowError:
        raise ValueError(f"t is too large in magnitude: the matrix entries overflow float64 at t = {t:g}") from None
    rows = [np.ones(1)]
    pascal = [1]
    for i in range(1, n + 1):
        pascal = [1] + [a + b for a, b in zip(pascal, pascal[1:])] + [1]
        rows.append(np.array(pascal, dtype=float))
    L = np.zeros((n + 1, n + 1))
    R = np.zeros((n + 1, n + 1))
    with np.errstate(all="ignore"):
        for i in range(n + 1):
            L[i, :i + 1] = rows[i] * tp[:i + 1] * sp[i::-1]
            m = n - i
            R[i, i:] = rows[m] * tp[:m + 1] * sp[m::-1]
    return finite_result(L, "t", t), finite_result(R, "t", t)


def bspline_subdivision_matrices(n: int) -> tuple[np.ndarray, np.ndarray]:
    """The subdivision matrices ``(L, R)`` of one segment of a uniform B-spline of degree n (Goldman §29.2).

    A segment is controlled by n+1 consecutive control points; halving the knot spacing, its
    left and right halves are controlled by ``L @ P`` and ``R @ P``.  The entries are those of
    the Lane-Riesenfeld mask ``m_k = C(n+1, k) / 2^n`` (k = 0..n+1):
    ``L[j, i] = m[2i - j + 1]`` and ``R[j, i] = m[2i - j]``.  For the cubic,
    ``8 L = [[4,4,0,0], [1,6,1,0], [0,4,4,0], [0,1,6,1]]``.

    n: degree, 0 <= n <= :data:`MAX_DEGREE`.

    >>> L, R = bspline_subdivision_matrices(2)
    >>> (L * 4).tolist()
    [[3.0, 1.0, 0.0], [1.0, 3.0, 0.0], [0.0, 3.0, 1.0]]
    """
    n = _degree(n)
    mask = np.array([math.comb(n + 1, k) for k in range(n + 2)], dtype=float) / 2 ** n
    padded = np.concatenate([mask, [0.0]])            # index -1 and n+2.. read the 0.0
    i = np.arange(n + 1)[None, :]
    j = np.arange(n + 1)[:, None]

    def m(k):
        return padded[np.where((k >= 0) & (k <= n + 1), k, n + 2)]

    return m(2 * i - j + 1), m(2 * i - j)


def check_rows_sum_to_one(M, name: str = "M", tol: float = 1e-9) -> np.ndarray:
    """Return ``M`` as a finite square float matrix whose rows sum to one, or raise ValueError
    naming the first row that does not (Goldman §29.4: such matrices make affine combinations,
    so their IFS moves with the control points).

    >>> check_rows_sum_to_one([[1, 0], [0.5, 0.4]], "L")
    Traceback (most recent call last):
    ...
    ValueError: the rows of L must sum to 1 (affine combinations); row 1 sums to 0.9
    """
    A = check_finite(as_float_array(M, name), name)
    tol = as_tolerance(tol)
    if A.ndim != 2 or A.shape[0] != A.shape[1]:
        raise ValueError(f"{name} must be a square matrix; got shape {A.shape}")
    sums = A.sum(axis=1)
    bad = np.flatnonzero(np.abs(sums - 1) > tol)
    if bad.size:
        raise ValueError(f"the rows of {name} must sum to 1 (affine combinations); row {int(bad[0])} sums to {sums[bad[0]]:.6g}")
    return A


# --------------------------------------------------------------------------------------------
# §29.3 curves as attractors, lifting, normal curves
# --------------------------------------------------------------------------------------------

def lift_control_points(ctrl) -> np.ndarray:
    """Lift n+1 control points to a square invertible matrix ``[P | Z | 1]`` (Goldman §29.3).

    ``ctrl`` is ``(n+1, d)`` with ``d <= n``; the points are given ``n - d`` extra coordinates
    ``Z`` (columns of the identity, chosen greedily so that the result is invertible) and the
    homogeneous coordinate 1.  The first d coordinates of the lifted curve are the original curve.
    Raises ValueError if ``d > n`` or if the points are affinely dependent in their own coordinates
    beyond repair (e.g. the three control points of a quadratic on one line: ``[P | 1]`` is then
    singular, and no extra coordinate can be added without a fourth point).

    >>> lift_control_points([[0, 0], [1, 2], [2, 0], [3, 1]])
    array([[0., 0., 1., 1.],
           [1., 2., 0., 1.],
           [2., 0., 0., 1.],
           [3., 1., 0., 1.]])
    """
    P = as_points(ctrl, "ctrl", ndim=2)
    n1, d = P.shape
    n = n1 - 1
    if d > n:
        raise ValueError(f"ctrl must have at most n = {n} coordinates to lift {n1} points to a square matrix; got {d} "
                         f"(project the points or use more of them)")
    base = np.column_stack([P, np.ones(n1)])
    if np.linalg.matrix_rank(base) < d + 1:
        raise ValueError("ctrl must be affinely independent in its own coordinates ([P | 1] has full column rank); "
                         "these control points are affinely dependent (e.g. collinear), so P^-1 does not exist")
    cols = []
    for k in range(n1):
        if len(cols) == n - d:
            break
        trial = np.column_stack([P] + cols + [np.eye(n1)[:, k], np.ones(n1)])
        if np.linalg.matrix_rank(trial) == trial.shape[1]:
            cols.append(np.eye(n1)[:, k])
    return np.column_stack([P] + cols + [np.ones(n1)])


def _square(ctrl) -> np.ndarray:
    P = check_finite(as_float_array(ctrl, "ctrl"), "ctrl")
    if P.ndim == 2 and P.shape[0] == P.shape[1] and np.allclose(P[:, -1], 1.0):
        if abs(np.linalg.det(P)) < 1e-12:
            raise ValueError("the lifted control points must form an invertible matrix")
        return P
    return lift_control_points(ctrl)


def curve_ifs(ctrl, kind: str = "bezier") -> tuple[np.ndarray, np.ndarray]:
    """The IFS ``{P^-1 L P, P^-1 R P}`` whose attractor is the curve with control points ``ctrl``
    (Goldman §29.3).

    ctrl: ``(n+1, d)`` control points with ``d <= n`` (lifted by :func:`lift_control_points`), or an
    already lifted square matrix with last column 1.  kind: ``"bezier"`` or ``"bspline"`` (one
    uniform B-spline segment).  Returns ``(maps, lifted)``: ``maps`` is ``(2, n+1, n+1)``, each
    acting on lifted homogeneous points as row vectors (``X @ M``), and ``lifted`` the square matrix
    ``P``.  The maps send the lifted control polygon to those of the two halves:
    ``P @ maps[0] == L @ P``.

    >>> maps, P = curve_ifs([[0, 0], [1, 2], [2, 0]])
    >>> np.allclose(P @ maps[0], bezier_subdivision_matrices(2)[0] @ P)
    True
    """
    if kind not in ("bezier", "bspline"):
        raise ValueError(f"kind must be 'bezier' or 'bspline'; got {kind!r}")
    P = _square(ctrl)
    n = len(P) - 1
    L, R = bezier_subdivision_matrices(n) if kind == "bezier" else bspline_subdivision_matrices(n)
    Pinv = np.linalg.inv(P)
    return np.stack([Pinv @ L @ P, Pinv @ R @ P]), P


def contraction_factors(maps, length: int = 1) -> np.ndarray:
    """Contraction factors of all compositions of ``length`` maps of an IFS, in any dimension
    (Goldman §29.3; §7.3.3 in the plane).

    maps: ``(k, D+1, D+1)`` affine maps on homogeneous row vectors (``X @ M``, translation in the
    last row), e.g. the maps of :func:`curve_ifs`.  length: how many maps are composed (>= 1).
    Returns ``(k^length,)``: the spectral norm of the linear part of ``M_{i_1} @ ... @ M_{i_length}``,
    the most that composition stretches any distance, for every word ``i_1 ... i_length`` in base-k
    order.  A map of a curve's IFS may stretch some direction (a factor above 1) while every
    composition of two or three maps shrinks; then the Hutchinson operator applied that many times is
    a contraction, which is enough for the curve to be the unique attractor.
    Raises ValueError for maps that are not square or for more than ``MAX_POINTS`` compositions.

    >>> maps, _ = curve_ifs([[0, 0], [1, 2], [2, 0]])
    >>> contraction_factors(maps).round(4).tolist()
    [0.7302, 0.7302]
    """
    M = check_finite(as_float_array(maps, "maps"), "maps")
    if M.ndim != 3 or M.shape[1] != M.shape[2] or M.shape[1] < 2:
        raise ValueError(f"maps must be a stack of square matrices (k, D+1, D+1); got shape {M.shape}")
    k = len(M)
    length = within_budget(length, "length", cost=lambda m: k ** m, what="the compositions of the maps",
                           unit="compositions", limit=MAX_POINTS, minimum=1)
    A = M[:, :-1, :-1]
    products = A
    for _ in range(length - 1):
        products = np.matmul(products[:, None], A[None]).reshape(-1, *A.shape[1:])
    return np.linalg.svd(products, compute_uv=False)[:, 0]


def attractor(maps, levels: int, start) -> np.ndarray:
    """The deterministic algorithm in any dimension: every map applied to the set, ``levels`` times
    (Goldman §29.3; §6.1 in the plane).

    maps: ``(k, D+1, D+1)`` affine maps on homogeneous row vectors.  start: ``(m, D+1)``
    homogeneous points (last coordinate 1) or ``(m, D)`` points.  Returns ``(m k^levels, D)``
    points in blocks of m, the copies of a polyline in order (block ``i_L ... i_1`` in base k is
    ``start @ M_{i_1} @ ... @ M_{i_L}``).  levels: int >= 0 with ``m k^levels`` at most
    :data:`MAX_POINTS` points (the work budget); raises ValueError beyond it.

    >>> maps, P = curve_ifs([[0, 0], [1, 2], [2, 0]])
    >>> attractor(maps, 1, P[[0, -1]])[:, :2].tolist()
    [[0.0, 0.0], [1.0, 1.0], [1.0, 1.0], [2.0, 0.0]]
    """
    M = check_finite(as_float_array(maps, "maps"), "maps")
    if M.ndim != 3 or M.shape[1] != M.shape[2] or M.shape[0] < 1 or M.shape[1] < 2:
        raise ValueError(f"maps must be a stack of at least one square matrix (k, D+1, D+1); got shape {M.shape}")
    X = as_points(start, "start", ndim=2)
    D1 = M.shape[1]
    if X.shape[1] == D1 - 1:
        X = np.column_stack([X, np.ones(len(X))])
    if X.shape[1] != D1:
        raise ValueError(f"start must hold points with {D1 - 1} coordinates (or {D1} homogeneous); got shape {X.shape}")
    levels = within_budget(levels, "levels", cost=lambda v: len(X) * len(M) ** v, what="the attractor",
                           unit="points", limit=MAX_POINTS)
    X = iteration.iterate_maps(X, M, levels)
    with np.errstate(all="ignore"):
        out = X[:, :-1] / X[:, -1:]
    if not np.all(np.isfinite(out)):
        raise ValueError("maps must keep the points finite (affine maps, last column (0, ..., 0, 1)); "
                         f"after {levels} levels a point overflows or has homogeneous coordinate 0")
    return out


def barycentric_attractor(matrices, levels: int, start_rows=(0, -1)) -> np.ndarray:
    """The deterministic algorithm on barycentric coordinates: rows of the identity (the control
    points themselves) mapped by ``x -> x @ M_k``, ``levels`` times (Goldman §29.4).

    Needs no inverse, so it also works for collinear control points: the attractor for control
    points P is ``barycentric_attractor(...) @ P``.  Returns ``(len(start_rows) k^levels, n+1)``,
    at most :data:`MAX_POINTS` rows (the work budget).

    >>> L, R = bezier_subdivision_matrices(2)
    >>> (barycentric_attractor([L, R], 1) @ np.array([[0, 0], [1, 2], [2, 0]])).tolist()
    [[0.0, 0.0], [1.0, 1.0], [1.0, 1.0], [2.0, 0.0]]
    """
    M = check_finite(as_float_array(matrices, "matrices"), "matrices")
    if M.ndim != 3 or M.shape[1] != M.shape[2] or len(M) < 1:
        raise ValueError(f"matrices must be a stack (k, n+1, n+1) of square matrices; got shape {M.shape}")
    rows = check_finite(as_float_array(start_rows, "start_rows"), "start_rows")
    size = M.shape[1]
    if rows.ndim != 1 or rows.size == 0 or np.any(rows != np.round(rows)) or np.any((rows < -size) | (rows >= size)):
        raise ValueError(f"start_rows must be a nonempty list of row indices from {-size} to {size - 1}")
    X = np.eye(M.shape[1])[rows.astype(np.intp)]
    levels = within_budget(levels, "levels", cost=lambda v: len(X) * len(M) ** v, what="the attractor",
                           unit="points", limit=MAX_POINTS)
    return iteration.iterate_maps(X, M, levels)


def curve_as_attractor(ctrl, levels: int = 8, kind: str = "bezier") -> np.ndarray:
    """Points of the curve with control points ``ctrl`` drawn as the attractor of its IFS (Goldman §29.3).

    Runs :func:`attractor` from the lifted control polygon and projects back to the original d
    coordinates: after ``levels`` levels the points are the ``2^levels`` control polygons of the
    pieces of the curve, in order, which converge to the curve.  Returns ``((n+1) 2^levels, d)``.

    >>> pts = curve_as_attractor([[0, 0], [1, 2], [2, 0]], levels=6)
    >>> pts.shape, bool(abs(pts[:, 1].max() - 1.0) < 1e-3)
    ((192, 2), True)
    """
    P0 = as_points(ctrl, "ctrl", ndim=2)
    maps, P = curve_ifs(P0, kind)
    return attractor(maps, levels, P)[:, :P0.shape[1]]


def normal_curve_control_points(n: int) -> np.ndarray:
    """The control points of the normal curve of degree n: the origin and the unit points
    ``e_1, ..., e_n`` of R^n, ``(n+1, n)`` (Goldman §29.3).

    n: 1 <= n <= :data:`MAX_DEGREE`.

    >>> normal_curve_control_points(2).tolist()
    [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
    """
    n = _degree(n, minimum=1)
    return np.vstack([np.zeros(n), np.eye(n)])


def normal_curve(n: int, t) -> np.ndarray:
    """Points of the normal curve of degree n, ``N(t) = (B_1^n(t), ..., B_n^n(t))`` (Goldman §29.3).

    The Bezier curve whose control points are the vertices of the standard simplex; its IFS is
    ``{L, R}`` itself (in the homogeneous coordinates of the simplex), and every degree-n Bezier
    curve with control points P is its affine image ``C(t) = P_0 + sum_k N_k(t) (P_k - P_0)``.
    n: 1 <= n <= :data:`MAX_DEGREE`, with ``n * t.size`` values at most
    :data:`~goldman_lib.validation.MAX_ITEMS` (the work budget).  t: finite, scalar or array.
    Returns ``t.shape + (n,)``.  Raises ValueError for a t so far from [0, 1] that a value
    overflows float64.

    >>> normal_curve(2, 0.5).tolist()
    [0.5, 0.25]
    """
    t = as_parameter(t, "t")
    n = _degree(n, minimum=1)
    n = within_budget(n, "n", cost=lambda v: v * max(t.size, 1), what=f"the normal curve at {t.size} parameter(s)",
                      unit="values", minimum=1)
    k = np.arange(1, n + 1)
    binom = np.array([math.comb(n, int(j)) for j in k], dtype=float)
    tt = t[..., None]
    with np.errstate(all="ignore"):
        out = binom * tt ** k * (1 - tt) ** (n - k)
    return finite_result(out, "t", t)


# --------------------------------------------------------------------------------------------
# §29.4 fractals with control points
# --------------------------------------------------------------------------------------------

def fractal_matrices(middle: float = 0.5, a: float = 0.5, b: float = 0.5) -> tuple[np.ndarray, np.ndarray]:
    """A family of 3x3 subdivision-like matrices with rows summing to one (Goldman §29.4).

    ``L = [[1, 0, 0], [1-a, a, 0], [u, v, w]]`` and ``R = [[u, v, w], [0, b, 1-b], [0, 0, 1]]`` with
    ``v = middle`` and ``u = w = (1 - v)/2``.  Row 0 of L and row 2 of R fix the end control points,
    and L's last row equals R's first, so the two pieces of the attractor meet: the attractor is a
    curve from ``P0`` to ``P2``.  ``middle = a = b = 1/2`` gives the quadratic Bezier matrices;
    other values give fractal curves (de Rham curves) that move with the control points.

    >>> L, R = fractal_matrices()
    >>> np.allclose(L, bezier_subdivision_matrices(2)[0]) and np.allclose(R, bezier_subdivision_matrices(2)[1])
    True
    """
    v = as_float(middle, "middle")
    a = as_float(a, "a")
    b = as_float(b, "b")
    u = (1 - v) / 2
    L = np.array([[1.0, 0, 0], [1 - a, a, 0], [u, v, u]])
    R = np.array([[u, v, u], [0, b, 1 - b], [0, 0, 1.0]])
    return L, R


def sierpinski_matrices() -> np.ndarray:
    """The three matrices ``S_k = (I + 1 e_k^T) / 2`` whose attractor, with the control points of a
    triangle, is the Sierpinski gasket of that triangle (Goldman §29.4): row i of ``S_k`` is the
    midpoint of vertex i and vertex k.  Returns ``(3, 3, 3)``.

    >>> (sierpinski_matrices()[0] * 2).tolist()
    [[2.0, 0.0, 0.0], [1.0, 1.0, 0.0], [1.0, 0.0, 1.0]]
    """
    eye = np.eye(3)
    return np.stack([(eye + np.outer(np.ones(3), eye[k])) / 2 for k in range(3)])


def control_point_ifs(ctrl, matrices, name: str = "") -> ifs.IFS:
    """The IFS ``{P^-1 M_k P}`` of matrices with rows summing to one and three control points in the
    plane, as a :class:`goldman_lib.ifs.IFS` (Goldman §29.4).

    ctrl: ``(3, 2)`` control points, not collinear (``P = [ctrl | 1]`` must be invertible).
    matrices: ``(k, 3, 3)`` (or a pair ``(L, R)``), each with rows summing to one.  Moving the control
    points moves the attractor by the affine map between the old and new control triangles.
    Raises ValueError for collinear control points or a row that does not sum to one.

    >>> from goldman_lib import ifs
    >>> system = control_point_ifs([[0, 0], [1, 2], [2, 0]], fractal_matrices())
    >>> ifs.deterministic(system, 1, start=[[0, 0], [2, 0]]).tolist()
    [[0.0, 0.0], [1.0, 1.0], [1.0, 1.0], [2.0, 0.0]]
    """
    P0 = as_points(ctrl, "ctrl", ndim=2, dim=2)
    if len(P0) != 3:
        raise ValueError(f"ctrl must hold 3 control points for 3x3 maps of the plane; got {len(P0)}")
    stack = check_finite(as_float_array(matrices, "matrices"), "matrices")
    if stack.ndim != 3 or stack.shape[0] < 1:
        raise ValueError(f"matrices must be a stack (k, 3, 3) of at least one matrix; got shape {stack.shape}")
    mats = [check_rows_sum_to_one(M, f"matrices[{k}]") for k, M in enumerate(stack)]
    for k, M in enumerate(mats):
        if M.shape != (3, 3):
            raise ValueError(f"matrices[{k}] must be 3x3; got shape {M.shape}")
    P = np.column_stack([P0, np.ones(3)])
    if abs(np.linalg.det(P)) < 1e-12 * max(1.0, np.abs(P0).max() ** 2):
        raise ValueError("ctrl must not be collinear: the matrix [P | 1] of the control points must be invertible")
    Pinv = np.linalg.inv(P)
    maps = np.stack([Pinv @ M @ P for M in mats])
    maps[:, :, 2] = [0.0, 0.0, 1.0]  # exact affine form (rows of M sum to one)
    return ifs.IFS(maps, name=name)

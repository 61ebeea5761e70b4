"""Bezier subdivision and rendering (Goldman chapter 25, §25.2-25.5).

:func:`subdivide` and :func:`subdivide_uniform` (§25.2, §25.4) with :func:`polygon_distance`; :func:`flatness`, :func:`is_flat`
and :func:`render_by_subdivision` (§25.3); :func:`subdivide_patch`, :func:`patch_flatness` and
:func:`render_patch_by_subdivision` (§25.3.2); :func:`subdivision_variation_counts` (§25.4);
:func:`smooth_continuation` and :func:`join_order` (§25.5).  Evaluation (chapter 24) is in
:mod:`goldman_lib.bezier`, intersection (§25.3.1-25.3.2) in :mod:`goldman_lib.bezier_intersection`;
every public name here is also importable as ``goldman_lib.bezier.<name>``.

>>> left, right = subdivide([[0, 0], [1, 2], [2, 0]])
>>> left.tolist()
[[0.0, 0.0], [0.5, 1.0], [1.0, 1.0]]
"""

from __future__ import annotations

import numpy as np

from goldman_lib.kernels import polygons, pyramids
from goldman_lib.validation import (MAX_ITEMS, as_float, as_hyperplane, as_int, as_parameter, as_points, finite_result,
                                    moderate, overflow_culprit, within_budget)

__all__ = [
    "subdivide", "subdivide_uniform", "flatness", "is_flat", "polygon_distance", "render_by_subdivision",
    "subdivide_patch", "subdivide_patch_uniform", "net_distance", "patch_flatness", "render_patch_by_subdivision",
    "subdivision_variation_counts", "smooth_continuation", "join_order",
]
# Public inside the package (knot_insertion renders B-splines by subdivision too), not learner-facing
# and so not in __all__: check_subdivision_budget, resolvable_tolerance.


def _ctrl(ctrl, name: str = "ctrl") -> np.ndarray:
    return as_points(ctrl, name, ndim=2)


def _net(ctrl, name: str = "ctrl") -> np.ndarray:
    return as_points(ctrl, name, ndim=3)


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
    left, right = pyramids.split(P, float(t))
    return finite_result(left, *overflow_culprit(t)), finite_result(right, *overflow_culprit(t))


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
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
        left, right = pyramids.split(pieces, t, axis=1)
        pieces = np.stack([left, right], axis=1).reshape((-1,) + P.shape)
    return finite_result(pieces.copy() if depth == 0 else pieces, *overflow_culprit(np.asarray(t)))


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
    P = moderate(as_points(ctrl, "ctrl", ndim=None))
    if P.ndim < 2:
        raise ValueError(f"ctrl must have shape (n+1, d) or a stack (..., n+1, d); got shape {P.shape}")
    out = polygons.flatness(P, bool(even))
    return float(out) if P.ndim == 2 else out


def polygon_distance(ctrl) -> float:
    """How far a Bezier control polygon is from its curve: ``max_k |P_k - C(k/n)|``, each control
    point against the curve point at its Greville abscissa ``k/n`` (Goldman §25.2, §25.4; the
    Bezier case of :func:`goldman_lib.knot_insertion.control_polygon_distance`).  After ``depth``
    levels of uniform subdivision the pieces' polygons are ``O(4^-depth)`` from the curve.

    ctrl: (n+1, d), or a stack (..., n+1, d) of polygons (the pieces of
    :func:`subdivide_uniform`): the largest distance over all of them.  Returns a float >= 0
    (0 for a degree-0 curve).  Raises ValueError/TypeError for a bad ctrl.

    >>> polygon_distance([[0, 0], [1, 2], [2, 0]])          # P_1 = (1, 2) against C(1/2) = (1, 1)
    1.0
    >>> polygon_distance(subdivide_uniform([[0, 0], [1, 2], [2, 0]], 1))
    0.25
    """
    P = moderate(as_points(ctrl, "ctrl", ndim=None))
    if P.ndim < 2:
        raise ValueError(f"ctrl must have shape (n+1, d) or a stack (..., n+1, d); got shape {P.shape}")
    n = P.shape[-2] - 1
    if n == 0 or P.size == 0:
        return 0.0
    B = np.ascontiguousarray(pyramids.bernstein_rows(n, np.arange(n + 1) / n).T)   # B[k, j] = B_j^n(k/n)
    on_curve = np.einsum("kj,...jd->...kd", B, P)
    return float(finite_result(np.linalg.norm(P - on_curve, axis=-1), "ctrl").max())


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


def check_subdivision_budget(count: int, per_piece: int, tol: float, depth_name: str = "max_depth",
                             what: str = "curve") -> None:
    """The work budget of adaptive subdivision (Goldman §25.3), whose depth the tolerance sets: raise
    a ValueError naming ``tol`` before a level of ``count`` pieces of ``per_piece`` coordinates that
    would hold more than :data:`~goldman_lib.validation.MAX_ITEMS` coordinates (a tol far below the
    curve's size in float64).  For library modules, on validated numbers (not in ``__all__``).

    >>> check_subdivision_budget(10, 8, 1e-3)      # well within the budget: nothing happens
    """
    if count * per_piece > MAX_ITEMS:
        raise ValueError(f"tol = {tol:g} is too small for this {what}: the next level of subdivision would hold "
                         f"{count:,} pieces ({count * per_piece:,} coordinates, over the limit of {MAX_ITEMS:,}); "
                         f"use a larger tol or a smaller {depth_name}")


def _tolerance(tol, name="tol") -> float:
    return as_float(tol, name, positive=True)


def resolvable_tolerance(tol: float, P: np.ndarray, name: str = "ctrl") -> float:
    """``tol`` if float64 can resolve it at the scale of ``P``: at least 1e-15 times its largest
    coordinate (below that, adaptive subdivision would split down to rounding noise, Goldman §25.3);
    else a ValueError naming ``tol`` and ``name``.  For library modules, on a validated tol and P (not in
    ``__all__``).

    >>> resolvable_tolerance(1e-3, np.array([[0.0, 0.0], [2.0, 1.0]]))
    0.001
    """
    scale = float(np.abs(P).max()) if P.size else 0.0
    if tol < 1e-15 * scale:
        raise ValueError(f"tol must be at least 1e-15 times the size of {name} (float64 resolves no less): "
                         f"got tol = {tol:g} for coordinates up to {scale:g}")
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
    P = moderate(_ctrl(ctrl))
    tol = resolvable_tolerance(_tolerance(tol), P)
    max_depth = as_int(max_depth, "max_depth", minimum=0, maximum=40)
    pieces = P[None]
    starts = np.zeros(1)
    width = 1.0
    done_t, done_p = [np.zeros(1)], [P[:1]]
    for depth in range(max_depth + 1):
        flat = polygons.flatness(pieces) <= tol
        if depth == max_depth:
            flat[:] = True
        done_t.append(starts[flat] + width)
        done_p.append(pieces[flat, -1])
        pieces, starts = pieces[~flat], starts[~flat]
        if len(pieces) == 0:
            break
        check_subdivision_budget(2 * len(pieces), P.size, tol)
        left, right = pyramids.split(pieces, 0.5, axis=1)
        width /= 2
        pieces = np.concatenate([left, right])
        starts = np.concatenate([starts, starts + width])
    t = np.concatenate(done_t)
    pts = np.concatenate(done_p)
    order = np.argsort(t, kind="stable")
    return t[order], pts[order]


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
    return pyramids.split_patches(P[None], float(u), float(v))[0]


def subdivide_patch_uniform(ctrl, depth) -> tuple[np.ndarray, np.ndarray]:
    """Split a Bezier patch at the middle ``depth`` times: its ``4**depth`` sub-nets and their
    parameter rectangles (Goldman §25.3.2, the patch version of :func:`subdivide_uniform`).

    ctrl: (m+1, n+1, d).  depth: int >= 0 within the work budget (the ``4**depth`` nets' coordinates
    at most :data:`~goldman_lib.validation.MAX_ITEMS`).  Returns ``(nets (4**depth, m+1, n+1, d),
    domains (4**depth, 4))``, a domain being ``[u0, u1, v0, v1]``; each parent's four children
    come in the order of :func:`subdivide_patch` (``[0, 0], [0, 1], [1, 0], [1, 1]``).
    Raises ValueError for a bad net or depth.

    >>> nets, domains = subdivide_patch_uniform([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], 1)
    >>> nets.shape, domains[3].tolist()
    ((4, 2, 2, 3), [0.5, 1.0, 0.5, 1.0])
    """
    P = _net(ctrl)
    depth = within_budget(depth, "depth", cost=lambda v: 4 ** v * P.size, what="the subdivided patch",
                          unit="coordinates")
    nets, dom = P[None], np.array([[0.0, 1.0, 0.0, 1.0]])
    for _ in range(depth):
        nets, dom = pyramids.quarter(nets, dom)
    return (nets.copy() if depth == 0 else nets), dom


def net_distance(ctrl) -> float:
    """How far a Bezier patch's control net is from its surface: ``max |P_ij - S(i/m, j/n)|``
    (Goldman §25.3.2; the patch case of :func:`polygon_distance`).  After ``depth`` levels of
    :func:`subdivide_patch_uniform` the sub-nets are ``O(4^-depth)`` from the surface.

    ctrl: (m+1, n+1, d), or a stack (..., m+1, n+1, d) of nets: the largest distance over all.
    Returns a float >= 0.  Raises ValueError/TypeError for a bad ctrl.

    >>> net_distance([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])      # bilinear: on its surface
    0.0
    >>> net_distance([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]], [[2, 0, 0], [2, 1, 0]]])
    0.0
    """
    P = moderate(as_points(ctrl, "ctrl", ndim=None))
    if P.ndim < 3:
        raise ValueError(f"ctrl must have shape (m+1, n+1, d) or a stack (..., m+1, n+1, d); got shape {P.shape}")
    m, n = P.shape[-3] - 1, P.shape[-2] - 1
    Bu = np.ascontiguousarray(pyramids.bernstein_rows(m, np.arange(m + 1) / m).T) if m else np.ones((1, 1))
    Bv = np.ascontiguousarray(pyramids.bernstein_rows(n, np.arange(n + 1) / n).T) if n else np.ones((1, 1))
    on = np.einsum("ia,jb,...abd->...ijd", Bu, Bv, P)
    return float(finite_result(np.linalg.norm(P - on, axis=-1), "ctrl").max())


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
    return float(polygons.patch_flatness(moderate(_net(ctrl))[None])[0])


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
    P = moderate(_net(ctrl))
    tol = resolvable_tolerance(_tolerance(tol), P)
    max_depth = as_int(max_depth, "max_depth", minimum=0, maximum=12)
    nets = P[None]
    dom = np.array([[0.0, 1.0, 0.0, 1.0]])
    out_c, out_d = [], []
    for depth in range(max_depth + 1):
        flat = polygons.patch_flatness(nets) <= tol
        if depth == max_depth:
            flat[:] = True
        f = nets[flat]
        out_c.append(np.stack([f[:, 0, 0], f[:, -1, 0], f[:, -1, -1], f[:, 0, -1]], axis=1))
        out_d.append(dom[flat])
        nets, dom = nets[~flat], dom[~flat]
        if len(nets) == 0:
            break
        check_subdivision_budget(4 * len(nets), P.size, tol, what="patch")
        nets, dom = pyramids.quarter(nets, dom)
    return np.concatenate(out_c), np.concatenate(out_d)


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
    P = moderate(_ctrl(ctrl))
    max_depth = as_int(max_depth, "max_depth", minimum=0, maximum=16)
    tol = as_float(tol, "tol")
    line = as_hyperplane(line_point, line_normal, P.shape[1])
    counts = []
    for depth in range(max_depth + 1):
        pieces = subdivide_uniform(P, depth)
        joined = np.concatenate([pieces[:, :-1].reshape(-1, P.shape[1]), pieces[-1, -1:]])
        counts.append(polygons.sign_changes(polygons.signed_distances(joined, *line), tol))
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
    return finite_result(pyramids.split(P[::-1], -ratio)[0], "ratio", ratio)


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
    A = polygons.elevate(A, n - (A.shape[0] - 1))
    B = polygons.elevate(B, n - (B.shape[0] - 1))
    # Extrapolate over the shorter interval (ratio <= 1): extrapolation multiplies rounding errors
    # by up to (1 + 2 ratio)^n.  Continuing b backwards over a's interval gives a reversed.
    if ratio <= 1.0:
        Q, target = pyramids.split(A[::-1], -ratio)[0], B
    else:
        Q, target = pyramids.split(B, -1.0 / ratio)[0], A[::-1]
    scale = max(1.0, float(np.abs(A).max()), float(np.abs(B).max()), float(np.abs(Q).max()))
    order = -1
    for k in range(n + 1):
        if np.linalg.norm(Q[k] - target[k]) > tol * scale:
            break
        order = k
    return order

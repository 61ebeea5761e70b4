"""Knot insertion for B-spline curves (Goldman, chapter 28).

Inserting a knot into the knot vector of a B-spline curve gives a longer control polygon for the
*same* curve.  The new control points are blossom values: with the new knots ``tau``, the new
control point ``Q_j`` is the blossom ``b(tau_{j+1}, ..., tau_{j+p})`` of the curve (§27.2), and
each algorithm of the chapter is a way of computing these blossom values cheaply.

Two layers, as everywhere in ``goldman_lib``:

- pure functions on arrays: Boehm's algorithm (§28.3.1: :func:`boehm_insert`,
  :func:`boehm_steps`), the Oslo algorithm (§28.3.2: :func:`oslo`, :func:`oslo_steps`),
  conversion to piecewise Bezier form (§28.3.3: :func:`to_piecewise_bezier`), the
  variation-diminishing property (§28.3.4: :func:`variation_diminishing`), rendering and
  intersecting by knot insertion (§28.3.5 and §28.4.4: :func:`split`, :func:`render_by_subdivision`,
  :func:`intersect`), the uniform subdivision algorithms of §28.4 (:func:`lane_riesenfeld`,
  :func:`lane_riesenfeld_steps`, :func:`lane_riesenfeld_knots`, :func:`schaefer`,
  :func:`schaefer_steps`, :func:`midpoint_knots`) and the convergence of the refined control
  polygons to the curve (§28.4.3: :func:`greville`, :func:`control_polygon_distance`,
  :func:`convergence_study`);
- the curve is always given as three arrays ``(ctrl, knots, degree)``: ``ctrl`` ``(n+1, d)``,
  ``knots`` ``(n+p+2,)`` non-decreasing (validated by :func:`goldman_lib.bspline.check_knots`) and
  the degree ``p``; the curve lives on the domain ``[t_p, t_{n+1}]``.

Knot insertion never changes the curve, only its representation; the tests check this against
``scipy.interpolate.BSpline`` built from the original control points and knots.

>>> ctrl, knots = boehm_insert([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5)
>>> ctrl.tolist()
[[0.0, 0.0], [0.5, 1.0], [1.5, 1.0], [2.0, 0.0]]
>>> knots.tolist()
[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]
"""

from __future__ import annotations

import numpy as np

from goldman_lib import bezier, bezier_intersection, bezier_subdivision, bspline
from goldman_lib.kernels import number, polygons, pyramids
from goldman_lib.validation import as_float, as_int, as_parameter, as_points, moderate, within_budget

__all__ = [
    "boehm_insert", "boehm_steps", "oslo", "oslo_steps", "to_piecewise_bezier",
    "variation_diminishing", "split", "render_by_subdivision", "intersect",
    "lane_riesenfeld", "lane_riesenfeld_steps", "lane_riesenfeld_knots",
    "midpoint_knots", "schaefer", "schaefer_steps", "schaefer_labels",
    "greville", "closed_curve", "control_polygon_distance", "convergence_study",
]


# --------------------------------------------------------------------------------------------
# internal helpers (no validation)
# --------------------------------------------------------------------------------------------

def _curve(ctrl, knots, degree, cname="ctrl", kname="knots"):
    """Validate a B-spline curve: (P (n+1, d), t (n+p+2,), p)."""
    p = as_int(degree, "degree", minimum=0)
    P = as_points(ctrl, cname, ndim=2)
    t = bspline.check_knots(knots, p, P.shape[0], name=kname, count_name=f"len({cname})")
    return P, t, p


def _refined_count(m: int, p: int, levels: int, closed: bool = False) -> int:
    """Control points after ``levels`` midpoint refinements of m points of degree p:
    ``2 m - p`` per level open (``2^L (m - p) + p``), ``2 m`` closed."""
    return 2 ** levels * m if closed else 2 ** levels * (m - p) + p


_fmt = number


def _domain_spans(t: np.ndarray, p: int, x: np.ndarray) -> np.ndarray:
    """Span index k with t[k] <= x < t[k+1], clipped to the non-empty spans of the domain."""
    n = t.size - p - 2
    lo_k = int(np.searchsorted(t, t[p], side="right")) - 1
    hi_k = int(np.searchsorted(t, t[n + 1], side="left")) - 1
    return np.clip(np.searchsorted(t, x, side="right") - 1, lo_k, hi_k)


def _refinement_spans(t: np.ndarray, tau: np.ndarray, p: int) -> np.ndarray:
    """For every new control point j, a span k of the old knots inside the support of the new
    B-spline N_j and inside the domain (so that Q_j = b_k(tau_{j+1..j+p}))."""
    n_new = tau.size - p - 2
    j = np.arange(n_new + 1)
    m = np.full(j.shape, -1)
    lo, hi = pyramids.domain(t, p)
    for off in range(p + 1):                         # first non-empty new span tau_m < tau_{m+1} with j <= m <= j+p
        cand = j + off
        ok = (m < 0) & (cand >= p) & (cand <= n_new)
        ok[ok] &= (tau[cand[ok]] < tau[cand[ok] + 1]) & (tau[cand[ok]] >= lo) & (tau[cand[ok] + 1] <= hi)
        m[ok] = cand[ok]
    m[m < 0] = np.clip(j[m < 0], p, n_new)          # cannot happen for a valid refinement; keep a span
    return _domain_spans(t, p, tau[m])


def _check_refinement(t: np.ndarray, tau: np.ndarray, p: int) -> None:
    """tau must contain every knot of t (with multiplicity) and insert only inside the domain."""
    i = j = 0
    extra = []
    while i < t.size and j < tau.size:
        if t[i] == tau[j]:
            i += 1
            j += 1
        elif tau[j] < t[i]:
            extra.append(tau[j])
            j += 1
        else:
            raise ValueError(f"new_knots must contain every old knot; knots[{i}]={_fmt(t[i])} is missing "
                             f"(or appears fewer times) in new_knots")
    if i < t.size:
        raise ValueError(f"new_knots must contain every old knot; knots[{i}]={_fmt(t[i])} is missing in new_knots")
    extra.extend(tau[j:])
    lo, hi = pyramids.domain(t, p)
    for x in extra:
        if not lo <= x <= hi:
            raise ValueError(f"new_knots may only add knots inside the domain [{_fmt(lo)}, {_fmt(hi)}]; "
                             f"{_fmt(x)} is outside")


# --------------------------------------------------------------------------------------------
# §28.3.1 Boehm's algorithm
# --------------------------------------------------------------------------------------------

def _boehm_once(P: np.ndarray, t: np.ndarray, p: int, u: float):
    """Insert u once; returns (Q, tau, k, replaced) where Q[k-p+1..k] are the new points."""
    n = P.shape[0] - 1
    lo_k = int(t.searchsorted(t[p], "right")) - 1             # first non-empty span of the domain
    hi_k = int(t.searchsorted(t[n + 1], "left")) - 1          # last one
    k = min(max(int(t.searchsorted(u, "right")) - 1, lo_k), hi_k)
    Q = np.empty((n + 2, P.shape[1]))
    Q[:k - p + 1] = P[:k - p + 1]
    Q[k + 1:] = P[k:]
    i = np.arange(k - p + 1, k + 1)
    if p:
        a = ((u - t[k - p + 1:k + 1]) / (t[k + 1:k + p + 1] - t[k - p + 1:k + 1]))[:, None]
        Q[k - p + 1:k + 1] = P[k - p:k] + a * (P[k - p + 1:k + 1] - P[k - p:k])
    tau = np.concatenate((t[:k + 1], (u,), t[k + 1:]))
    return Q, tau, k, i


def _check_insert(t: np.ndarray, p: int, u: float, times: int) -> None:
    lo, hi = pyramids.domain(t, p)
    if not lo <= u <= hi:
        raise ValueError(f"u must lie in the domain [knots[{p}], knots[{t.size - p - 1}]] = [{_fmt(lo)}, {_fmt(hi)}]; "
                         f"u is {_fmt(u)}")
    s = int(np.count_nonzero(t == u))
    if s + times > p + 1:
        raise ValueError(f"times must keep the multiplicity of u at most degree+1 = {p + 1}; u={_fmt(u)} already "
                         f"appears {s} times, so at most {p + 1 - s} more insertions are possible, not {times}")


def boehm_insert(ctrl, knots, degree, u, times=1):
    """Insert the knot ``u`` into a B-spline curve ``times`` times by Boehm's algorithm (Goldman §28.3.1).

    With ``t_k <= u < t_{k+1}``, one insertion keeps ``P_0 .. P_{k-p}`` and ``P_k .. P_n`` (shifted
    one place) and replaces the ``p-1`` points between by ``p`` new ones on the legs of the old
    polygon:

    ``Q_i = (1 - a_i) P_{i-1} + a_i P_i``,  ``a_i = (u - t_i) / (t_{i+p} - t_i)``,  ``k-p+1 <= i <= k``.

    In blossom terms ``Q_i`` is the blossom at the old label of ``P_i`` with one knot replaced
    by ``u``.  The curve does not change.

    ctrl: (n+1, d) control points.  knots: (n+p+2,) non-decreasing.  degree: p >= 0.
    u: a number in the domain ``[t_p, t_{n+1}]``.  times: int >= 0.
    Returns ``(new_ctrl (n+1+times, d), new_knots (n+p+2+times,))``.
    Raises ValueError for a bad curve (see :func:`goldman_lib.bspline.check_knots`), u outside the
    domain, or a multiplicity of u above degree+1 after insertion; TypeError for non-integer times.

    >>> ctrl, knots = boehm_insert([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5, times=2)
    >>> ctrl.tolist()
    [[0.0, 0.0], [0.5, 1.0], [1.0, 1.0], [1.5, 1.0], [2.0, 0.0]]
    """
    P, t, p = _curve(ctrl, knots, degree)
    u = as_float(u, "u")
    times = as_int(times, "times", minimum=0)
    _check_insert(t, p, u, times)
    for _ in range(times):
        P, t, _, _ = _boehm_once(P, t, p, u)
    return P.copy(), t.copy()


def boehm_steps(ctrl, knots, degree, u, times=1) -> list[dict]:
    """Every intermediate polygon of Boehm's algorithm, for drawing (Goldman §28.3.1).

    Returns ``times + 1`` dicts: step 0 is the original curve; step s holds ``ctrl`` and
    ``knots`` after s insertions, ``replaced`` (the indices of the old points that were dropped),
    ``new`` (the indices of the new points in ``ctrl``), ``span`` k and ``alphas`` (the weights a_i).
    Raises ValueError as :func:`boehm_insert`.

    >>> [len(s["ctrl"]) for s in boehm_steps([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5, 2)]
    [3, 4, 5]
    """
    P, t, p = _curve(ctrl, knots, degree)
    u = as_float(u, "u")
    times = as_int(times, "times", minimum=0)
    _check_insert(t, p, u, times)
    steps = [{"ctrl": P.copy(), "knots": t.copy(), "replaced": np.array([], dtype=int),
              "new": np.array([], dtype=int), "span": None, "alphas": np.array([])}]
    for _ in range(times):
        Q, tau, k, i = _boehm_once(P, t, p, u)
        alphas = (u - t[i]) / (t[i + p] - t[i]) if i.size else np.array([])
        steps.append({"ctrl": Q, "knots": tau, "replaced": np.arange(k - p + 1, k), "new": i,
                      "span": k, "alphas": alphas})
        P, t = Q, tau
    return steps


# --------------------------------------------------------------------------------------------
# §28.3.2 the Oslo algorithm
# --------------------------------------------------------------------------------------------

def oslo(ctrl, knots, degree, new_knots) -> np.ndarray:
    """Control points of the same curve over a refined knot vector, by the Oslo algorithm (Goldman §28.3.2).

    Every new control point is a blossom value, ``Q_j = b(tau_{j+1}, ..., tau_{j+p})``, computed by
    de Boor's pyramid with the p new knots as arguments, one per level (all points at once).  Many
    knots are inserted in one pass, rather than one at a time as in Boehm's algorithm.

    ctrl: (n+1, d).  knots: (n+p+2,).  degree: p.  new_knots: (m+p+2,), non-decreasing, containing
    every old knot (with its multiplicity) and adding knots only inside the domain.
    Returns (m+1, d), the control points over ``new_knots``.
    Raises ValueError for a bad curve, bad new knots, or new knots that are not a refinement.

    >>> oslo([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, [0, 0, 0, 0.5, 0.5, 1, 1, 1]).tolist()
    [[0.0, 0.0], [0.5, 1.0], [1.0, 1.0], [1.5, 1.0], [2.0, 0.0]]
    """
    P, t, p = _curve(ctrl, knots, degree)
    tau = bspline.check_knots(new_knots, p, name="new_knots")
    _check_refinement(t, tau, p)
    return _oslo(P, t, p, tau)


def _oslo(P, t, p, tau):
    n_new = tau.size - p - 2
    spans = _refinement_spans(t, tau, p)
    idx = np.arange(n_new + 1)[:, None] + np.arange(1, p + 1)[None, :]
    return pyramids.de_boor_blossom(P, t, p, spans, tau[idx])


def oslo_steps(ctrl, knots, degree, new_knots) -> list[dict]:
    """The Oslo algorithm one new control point at a time, for drawing (Goldman §28.3.2).

    Returns one dict per new control point j: ``point`` (d,), ``label`` (the p new knots
    ``tau_{j+1..j+p}``), ``span`` k of the old knots used, and ``levels``: de Boor's pyramid with
    the label as arguments, level 0 being the old points ``P_{k-p} .. P_k``, and ``labels``: the
    blossom label of every point of every level, sorted (level r, point of old index i: the first r
    new knots of the label and ``t_{i+1} .. t_{i+p-r}``; level 0 the labels of the old points).
    Raises ValueError as :func:`oslo`.

    >>> s = oslo_steps([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, [0, 0, 0, 0.5, 1, 1, 1])
    >>> [step["point"].tolist() for step in s]
    [[0.0, 0.0], [0.5, 1.0], [1.5, 1.0], [2.0, 0.0]]
    >>> s[1]["labels"]
    [[(0.0, 0.0), (0.0, 1.0), (1.0, 1.0)], [(0.0, 0.0), (0.0, 1.0)], [(0.0, 0.5)]]
    """
    P, t, p = _curve(ctrl, knots, degree)
    tau = bspline.check_knots(new_knots, p, name="new_knots")
    _check_refinement(t, tau, p)
    spans = _refinement_spans(t, tau, p)
    out = []
    for j, k in enumerate(spans):
        k = int(k)
        label = tau[j + 1:j + p + 1].copy()
        pts = P[k - p:k + 1].copy()
        levels = []

        def weight(r, jj, q, k=k, label=label):
            i = k - p + jj
            return (label[r - 1] - t[i]) / (t[i + p + 1 - r] - t[i])
        pyramids.de_boor_pyramid(pts, weight, p, record=levels)
        labels = [[tuple(sorted(float(x) for x in np.r_[label[:r], t[k - p + jj + 1:k + jj - r + 1]]))
                   for jj in range(r, p + 1)] for r in range(p + 1)]
        out.append({"point": pts[p].copy(), "label": label, "span": k, "levels": levels, "labels": labels})
    return out


# --------------------------------------------------------------------------------------------
# §28.3.3 conversion to piecewise Bezier form
# --------------------------------------------------------------------------------------------

def to_piecewise_bezier(ctrl, knots, degree):
    """The Bezier control polygons of the polynomial pieces of a B-spline curve (Goldman §28.3.3).

    Inserting every interior knot until it has multiplicity p splits the control polygon into
    Bezier polygons; equivalently, the Bezier points of the piece over ``[a, b]`` are the
    blossom values ``b(a^{p-i}, b^i)``, i = 0..p, computed here directly by the Oslo pyramid.
    Piece j is the Bezier curve ``C(a + (b-a) s)``, s in [0, 1].

    ctrl: (n+1, d).  knots: (n+p+2,).  degree: p.
    Returns ``(pieces (m, p+1, d), breaks (m+1,))``: one Bezier polygon per non-empty knot span
    of the domain and the parameter values where the pieces meet.
    Raises ValueError for a bad curve.

    >>> pieces, breaks = to_piecewise_bezier([[0, 0], [1, 2], [2, 2], [3, 0]], [0, 0, 0, 0.5, 1, 1, 1], 2)
    >>> pieces.tolist()
    [[[0.0, 0.0], [1.0, 2.0], [1.5, 2.0]], [[1.5, 2.0], [2.0, 2.0], [3.0, 0.0]]]
    >>> breaks.tolist()
    [0.0, 0.5, 1.0]
    """
    P, t, p = _curve(ctrl, knots, degree)
    lo, hi = pyramids.domain(t, p)
    breaks = np.unique(t[(t >= lo) & (t <= hi)])
    a, b = breaks[:-1], breaks[1:]
    m = a.size
    spans = _domain_spans(t, p, a)
    i = np.arange(p + 1)
    # args[piece, i, level]: p - i copies of a, then i copies of b
    lev = np.arange(p)[None, None, :]
    args = np.where(lev < (p - i)[None, :, None], a[:, None, None], b[:, None, None])
    flat = pyramids.de_boor_blossom(P, t, p, np.repeat(spans, p + 1), args.reshape(m * (p + 1), p))
    return flat.reshape(m, p + 1, P.shape[1]), breaks


# --------------------------------------------------------------------------------------------
# §28.3.4 the variation-diminishing property
# --------------------------------------------------------------------------------------------

def variation_diminishing(ctrl, knots, degree, line_point, line_normal, samples=2001) -> tuple[int, int]:
    """How often a line crosses the control polygon and the B-spline curve (Goldman §28.3.4).

    Knot insertion replaces legs of the control polygon by cutting corners, so it never adds a
    crossing; inserting knots until the polygon converges to the curve proves that the curve
    crosses any line at most as often as its control polygon.

    ctrl: (n+1, 2) (or any dimension: a hyperplane then).  knots, degree: the curve.
    line_point, line_normal: (d,), the normal nonzero.  samples: curve samples used to count its
    crossings (a lower bound that is exact once the samples resolve the curve), at most
    :data:`~goldman_lib.validation.MAX_ITEMS` / d (the work budget).
    Returns ``(polygon_crossings, curve_crossings)``.
    Raises ValueError for a bad curve, bad line, samples < 2 or over the budget.

    >>> variation_diminishing([[0, 1], [1, -1], [2, 1], [3, -1]], [0, 0, 0, 1, 2, 2, 2], 2, [0, 0], [0, 1])
    (3, 3)
    """
    P, t, p = _curve(ctrl, knots, degree)
    samples = within_budget(samples, "samples", cost=lambda v: v * P.shape[1], what="the sampled curve",
                            unit="coordinates", minimum=2)
    poly = bezier.variation_count(P, line_point, line_normal)
    lo, hi = pyramids.domain(t, p)
    pts = bspline.de_boor(P, t, p, np.linspace(lo, hi, samples))
    # crossings of the sampled curve: sign changes of the signed distances
    nrm = np.asarray(line_normal, dtype=float)
    s = (pts - np.asarray(line_point, dtype=float)) @ nrm
    s = s[np.abs(s) > 1e-12 * max(1.0, float(np.abs(pts).max()))]
    curve = int(np.count_nonzero(np.sign(s[1:]) != np.sign(s[:-1])))
    return poly, curve


# --------------------------------------------------------------------------------------------
# §28.4.1 the Lane-Riesenfeld algorithm
# --------------------------------------------------------------------------------------------

def _lr_level(P: np.ndarray, p: int, closed: bool) -> list[np.ndarray]:
    """One Lane-Riesenfeld level: the doubled polygon, then each of the p averaging rounds."""
    Q = np.repeat(P, 2, axis=0)
    rounds = [Q]
    for _ in range(p):
        if closed:
            Q = 0.5 * (Q + np.roll(Q, -1, axis=0))
        else:
            Q = 0.5 * (Q[:-1] + Q[1:])
        rounds.append(Q)
    return rounds


def _lr_args(ctrl, degree, levels, closed, rounds=1):
    P = as_points(ctrl, "ctrl", ndim=2)
    if not isinstance(closed, (bool, np.bool_)):
        raise TypeError(f"closed must be True or False; got {closed!r}")
    m, d = P.shape
    p = as_int(degree, "degree", minimum=0)
    if not closed and m < p + 1:
        raise ValueError(f"ctrl must hold at least degree+1 = {p + 1} points for an open curve of degree {p}; "
                         f"got {m}")
    # each level averages p times a polygon of about twice the points: (p + 1) * 2 m * d coordinates
    p = within_budget(p, "degree", cost=lambda v: (v + 1) * 2 * m * d, what="one Lane-Riesenfeld level",
                      unit="coordinates computed")
    levels = within_budget(levels, "levels", cost=lambda v: _refined_count(m, p, v, closed) * d * rounds * (p + 1),
                           what="the refined polygon" if rounds == 1 else "the refined polygons of every round",
                           unit="coordinates computed")
    return P, p, levels, bool(closed)


def lane_riesenfeld(ctrl, degree, levels=1, closed=False) -> np.ndarray:
    """Refine a uniform B-spline control polygon by the Lane-Riesenfeld algorithm (Goldman §28.4.1).

    One level doubles every control point and then averages neighbours ``degree`` times; this
    inserts the midpoint of every knot interval of a uniform knot vector.  Degree 2 gives Chaikin's
    corner cutting (3/4, 1/4), degree 3 the cubic rule (1/8, 6/8, 1/8) and (1/2, 1/2).

    ctrl: (n+1, d).  degree: p >= 0.  levels: int >= 0 within the work budget: the coordinates
    computed, ``(p + 1) d`` times the refined point count, at most
    :data:`~goldman_lib.validation.MAX_ITEMS` (levels <= 20 for a planar cubic of 4 points).
    closed: a closed (periodic)
    curve, the polygon wrapping around, or an open one with uniform knots (the default).
    Returns the refined polygon: open, ``2 m - p`` points from m per level (the knots of
    :func:`lane_riesenfeld_knots`); closed, ``2^levels (n+1)`` points, new point i belonging to
    the uniform B-spline that starts at parameter ``(i + p) / 2`` when the old point i starts at i.
    Raises ValueError for too few points for an open curve or levels over the budget.

    >>> lane_riesenfeld([[0, 0], [4, 0], [4, 4]], 2, 1).tolist()
    [[1.0, 0.0], [3.0, 0.0], [4.0, 1.0], [4.0, 3.0]]
    >>> lane_riesenfeld([[0, 0], [4, 0], [4, 4], [0, 4]], 2, 1, closed=True)[:2].tolist()
    [[1.0, 0.0], [3.0, 0.0]]
    """
    P, p, levels, closed = _lr_args(ctrl, degree, levels, closed)
    for _ in range(levels):
        P = _lr_level(P, p, closed)[-1]
    return P.copy() if levels == 0 else P


def lane_riesenfeld_steps(ctrl, degree, levels=1, closed=False) -> list[list[np.ndarray]]:
    """Every intermediate polygon of the Lane-Riesenfeld algorithm, for drawing (Goldman §28.4.1).

    Returns one list per level: ``[doubled, after round 1, ..., after round p]``.
    Raises ValueError as :func:`lane_riesenfeld`.

    >>> [len(r) for r in lane_riesenfeld_steps([[0, 0], [4, 0], [4, 4]], 2, 1)[0]]
    [6, 5, 4]
    """
    P, p, levels, closed = _lr_args(ctrl, degree, levels, closed, rounds=2)
    out = []
    for _ in range(levels):
        rounds = _lr_level(P, p, closed)
        out.append(rounds)
        P = rounds[-1]
    return out


def lane_riesenfeld_knots(n_ctrl, degree, levels=1) -> np.ndarray:
    """The knots of the open Lane-Riesenfeld polygon after ``levels`` levels (Goldman §28.4.1).

    The original open curve has the uniform knots ``0, 1, ..., n+p+1`` (domain ``[p, n+1]``);
    each level halves the spacing and drops ``p`` points, so the refined knots start at
    ``p (1 - 2^-levels)`` with spacing ``2^-levels``, over the same domain.

    n_ctrl: n+1 >= degree+1.  degree: p.  levels: int >= 0.  The knot vector, ``2^levels (n_ctrl -
    p) + 2p + 1`` knots, is at most :data:`~goldman_lib.validation.MAX_ITEMS` long (the work budget).
    Returns the knot vector.
    Raises ValueError for n_ctrl < degree + 1 or a knot vector over the budget.

    >>> lane_riesenfeld_knots(3, 2, 1).tolist()
    [1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0]
    """
    p = within_budget(degree, "degree", cost=lambda v: 2 * v + 2, what="the knot vector", unit="knots")
    n_ctrl = within_budget(n_ctrl, "n_ctrl", cost=lambda v: v + p + 1, what="the knot vector", unit="knots")
    if n_ctrl < p + 1:
        raise ValueError(f"n_ctrl must be >= degree+1 = {p + 1}; got {n_ctrl}")
    levels = within_budget(levels, "levels", cost=lambda v: _refined_count(n_ctrl, p, v) + p + 1,
                           what="the refined knot vector", unit="knots")
    m = n_ctrl
    for _ in range(levels):
        m = 2 * m - p
    h = 2.0 ** -levels
    return p * (1.0 - h) + h * np.arange(m + p + 1)


# --------------------------------------------------------------------------------------------
# §28.4.2 Schaefer's algorithm
# --------------------------------------------------------------------------------------------

def midpoint_knots(knots) -> np.ndarray:
    """The knot vector with the midpoint of every knot interval inserted, ``t_0, s_0, t_1, s_1, ...``
    (``s_j = (t_j + t_{j+1}) / 2``), the knots behind one level of subdivision (Goldman §28.4).

    knots: (N,) non-decreasing, N >= 1.  Returns (2N - 1,).
    Raises ValueError for no knots or a non-finite knot, TypeError for non-numbers.

    >>> midpoint_knots([0, 1, 3]).tolist()
    [0.0, 0.5, 1.0, 2.0, 3.0]
    """
    t = as_parameter(knots, "knots").reshape(-1)
    if t.size == 0:
        raise ValueError("knots must hold at least one knot; got an empty knot vector")
    u = np.empty(2 * t.size - 1)
    u[0::2] = t
    u[1::2] = 0.5 * (t[:-1] + t[1:])
    return u


def _drop_zero_support(P: np.ndarray, u: np.ndarray, p: int) -> tuple[np.ndarray, np.ndarray]:
    """Drop the B-splines of zero support (``u_j = u_{j+p+1}``) with their control points and one
    copy of the knot, until no knot repeats more than p+1 times.  Only a knot of multiplicity m with
    2m - 1 > p + 1 (the midpoint of a zero-length interval is the knot again) needs it; such a B-spline
    is identically zero, so its coefficient is no control point of the curve."""
    zero = u[p + 1:] == u[:-p - 1]
    if not zero.any():
        return P, u
    keep_pts = np.ones(len(P), dtype=bool)
    keep_knots = np.ones(len(u), dtype=bool)
    j, kept = 0, list(range(len(u)))
    while j + p + 1 < len(kept):                   # drop one at a time: each drop shifts the window
        if u[kept[j]] == u[kept[j + p + 1]]:
            keep_knots[kept[j]] = False
            keep_pts[kept[j]] = False              # point j sits under the knots j..j+p+1
            del kept[j]
        else:
            j += 1
    # points and knots are dropped at the same original indices (point j pairs with knot j)
    return P[keep_pts[:len(P)]], u[keep_knots]


def _schaefer_level(P: np.ndarray, t: np.ndarray, p: int) -> tuple[list[np.ndarray], np.ndarray]:
    """One level of Schaefer's algorithm: doubling, then p rounds of blossom averaging.

    With u the midpoint knot vector (u_{2m} = t_m, u_{2m+1} = s_m), round r gives the point i the
    blossom label {u_{i+r+1}, ..., u_{i+2r}} followed by the next p-r old knots after u_{i+2r}.
    Point i of round r comes from points i and i+1 of round r-1: for even i it is point i+1
    (same label), for odd i the affine combination that replaces the label value a = u_{i+r} by
    c = u_{i+2r} along b = u_{i+2p+1}:  ((b - c) R_i + (c - a) R_{i+1}) / (b - a).
    Returns (rounds, new knots).
    """
    n1 = P.shape[0]
    u = midpoint_knots(t)
    R = np.repeat(P, 2, axis=0)
    rounds = [R]
    for r in range(1, p + 1):
        m = R.shape[0] - 1
        new = np.empty((m, P.shape[1]))
        new[0::2] = R[1::2][: (m + 1) // 2]
        i = np.arange(1, m, 2)
        a, c, b = u[i + r], u[i + 2 * r], u[i + 2 * p + 1]
        den = b - a
        safe = np.where(den > 0, den, 1.0)
        wa = np.where(den > 0, (b - c) / safe, 1.0)[:, None]
        wb = np.where(den > 0, (c - a) / safe, 0.0)[:, None]
        new[1::2] = wa * R[i] + wb * R[i + 1]
        R = new
        rounds.append(R)
    return rounds, u[p:2 * n1 + p + 1].copy()


def _schaefer_refine(P: np.ndarray, t: np.ndarray, p: int) -> tuple[list[np.ndarray], np.ndarray, np.ndarray]:
    """One level: (rounds as computed, the final control points, the final knots), zero-support
    B-splines dropped from the last two (see :func:`_drop_zero_support`)."""
    rounds, u = _schaefer_level(P, t, p)
    Q, u = _drop_zero_support(rounds[-1], u, p)
    return rounds, Q, u


def schaefer_labels(knots, degree, rnd: int) -> list[tuple[float, ...]]:
    """The blossom labels of the points after round ``rnd`` of one level of Schaefer's algorithm
    (Goldman §28.4.2): point i has ``{u_{i+r+1}..u_{i+2r}}`` plus the next ``p-r`` old knots.

    >>> schaefer_labels([0, 0, 0, 1, 1, 1], 2, 2)
    [(0.0, 0.0), (0.0, 0.5), (0.5, 1.0), (1.0, 1.0)]
    """
    p = as_int(degree, "degree", minimum=0)
    t = bspline.check_knots(knots, p)
    r = as_int(rnd, "rnd", minimum=0, maximum=p)
    u = midpoint_knots(t)
    count = 2 * (t.size - p - 1) - r
    labels = []
    for i in range(count):
        lab = list(u[i + r + 1:i + 2 * r + 1])
        pos = i + 2 * r + 1
        while len(lab) < p:
            if pos % 2 == 0:
                lab.append(u[pos])
            pos += 1
        labels.append(tuple(float(x) for x in lab))
    return labels


def schaefer(ctrl, knots, degree, levels=1):
    """Halve every knot interval of a B-spline by Schaefer's algorithm (Goldman §28.4.2).

    Like Lane-Riesenfeld, each level doubles the control points and then runs ``degree`` rounds
    of averaging of neighbours; unlike it, the weights come from blossoming, so it works for
    non-uniform knots too (Schaefer and Goldman, 2009).  Every intermediate point is a blossom
    value whose label mixes old knots ``t_m`` and midpoints ``s_m``; round r moves one label
    value from an old knot to a midpoint (see :func:`schaefer_labels`).  The result is the curve
    over the knot vector with every interval halved; on uniform knots it equals
    :func:`lane_riesenfeld`.

    Any knot vector works, repeated knots included (clamped or floating ends, interior knots up to
    multiplicity p+1).  The midpoint of a zero-length interval is the knot itself, so a knot of
    multiplicity m comes out with multiplicity 2m - 1: the rounds run unchanged (an affine step whose
    two label values coincide keeps its first point), and the result is the Boehm/Oslo insertion of
    every midpoint.  Where 2m - 1 exceeds p + 1 the refined vector would repeat the knot more than
    p + 1 times; the B-splines of zero support there (``u_j = u_{j+p+1}``) are identically zero, so
    their coefficients are dropped with one copy of the knot each, and the knot comes out with
    multiplicity p + 1, i.e. min(2m - 1, p + 1) in every case (the curve is unchanged: the dropped
    B-splines vanish everywhere).
    The tests check every case against :func:`oslo` inserting the same midpoints.

    ctrl: (n+1, d).  knots: (n+p+2,), any valid knot vector (:func:`goldman_lib.bspline.check_knots`).
    degree: p.  levels: int >= 0 within the work budget: ``(p + 1) d`` times the refined point
    count at most :data:`~goldman_lib.validation.MAX_ITEMS` coordinates computed.
    Returns ``(new_ctrl, new_knots)``: ``2 m - p`` points from m per level (fewer where zero-support
    B-splines were dropped).
    Raises ValueError for a bad curve.

    >>> ctrl, knots = schaefer([[0, 0], [4, 0], [4, 4]], [0, 0, 0, 1, 1, 1], 2)
    >>> ctrl.tolist()
    [[0.0, 0.0], [2.0, 0.0], [4.0, 2.0], [4.0, 4.0]]
    >>> knots.tolist()
    [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]
    """
    P, t, p = _curve(ctrl, knots, degree)
    m, d = P.shape
    levels = within_budget(levels, "levels", cost=lambda v: _refined_count(m, p, v) * d * (p + 1),
                           what="the refined polygon", unit="coordinates computed")
    for _ in range(levels):
        _, P, t = _schaefer_refine(P, t, p)
    return P.copy(), t.copy()


def schaefer_steps(ctrl, knots, degree) -> dict:
    """One level of Schaefer's algorithm, round by round, for drawing (Goldman §28.4.2).

    Returns ``{"rounds": [doubled, round 1, ..., round p], "labels": [labels of each round],
    "knots": the new knot vector, "ctrl": the new control points}``; ``ctrl`` is the last round
    except where a knot of high multiplicity made B-splines of zero support, whose points
    :func:`schaefer` drops.  Raises ValueError as :func:`schaefer`.

    >>> s = schaefer_steps([[0, 0], [4, 0], [4, 4]], [0, 0, 0, 1, 1, 1], 2)
    >>> [len(r) for r in s["rounds"]], s["labels"][2][1]
    ([6, 5, 4], (0.0, 0.5))
    """
    P, t, p = _curve(ctrl, knots, degree)
    rounds, Q, u = _schaefer_refine(P, t, p)
    labels = [schaefer_labels(t, p, r) for r in range(p + 1)]
    return {"rounds": rounds, "labels": labels, "knots": u, "ctrl": Q}


# --------------------------------------------------------------------------------------------
# §28.4.3 convergence
# --------------------------------------------------------------------------------------------

def greville(knots, degree) -> np.ndarray:
    """The Greville abscissae ``(t_{i+1} + ... + t_{i+p}) / p``, where control point i "sits" (Goldman §28.4.3).

    knots: (n+p+2,).  degree: p >= 1.  Returns (n+1,).
    Raises ValueError for a bad knot vector or degree 0.

    >>> greville([0, 0, 0, 0.5, 1, 1, 1], 2).tolist()
    [0.0, 0.25, 0.75, 1.0]
    """
    p = as_int(degree, "degree", minimum=1)
    t = bspline.check_knots(knots, p)
    c = np.concatenate([[0.0], np.cumsum(t)])
    n1 = t.size - p - 1
    i = np.arange(n1)
    return (c[i + p + 1] - c[i + 1]) / p


def closed_curve(ctrl, degree) -> tuple[np.ndarray, np.ndarray]:
    """A closed (periodic) uniform B-spline written as an ordinary one (Goldman §28.4.1): the
    polygon wrapped round, its first ``degree`` points repeated at the end, on the integer knots
    ``0, 1, ..., m + 2p``.  The domain ``[p, m + p]`` is one trip round the curve, which is the
    curve :func:`lane_riesenfeld` refines with ``closed=True``.

    ctrl: (m, d), m >= 1 points of the closed polygon.  degree: p >= 1.  Returns ``(points (m+p, d),
    knots (m+2p+1,))``.  Raises ValueError for a bad polygon or degree.

    >>> P, t = closed_curve([[0, 0], [1, 0], [0, 1]], 2)
    >>> P.tolist(), t.tolist()
    ([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [0.0, 0.0], [1.0, 0.0]], [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0])
    """
    P = as_points(ctrl, "ctrl", ndim=2)
    p = as_int(degree, "degree", minimum=1)
    m, d = P.shape
    p = within_budget(p, "degree", cost=lambda v: (m + v) * d, what="the wrapped polygon",
                      unit="coordinates")
    return P[np.arange(m + p) % m], np.arange(m + 2 * p + 1, dtype=float)


def control_polygon_distance(ctrl, knots, degree, *, closed: bool = False, skip_outside: bool = False) -> float:
    """The largest distance from a control point to the curve point at its Greville abscissa,
    ``max_i |P_i - C(xi_i)|``: how far the control polygon is from the curve (Goldman §28.4.3).

    ctrl, knots, degree (>= 1): the curve.  A control point whose abscissa falls outside the
    domain (the end points of an unclamped knot vector) is measured against the nearer end of the
    curve, or left out with ``skip_outside=True`` (it then sits about p/2 knot intervals beyond
    the curve's end and would hide the O(h^2) convergence of the others).  closed: ``ctrl`` is a
    closed polygon of the uniform periodic curve of :func:`closed_curve`; ``knots`` must then be
    None, and every control point is measured (each has its abscissa once round the curve).
    Returns a float.  Raises ValueError for a bad curve, TypeError for a flag that is not a bool.

    >>> control_polygon_distance([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2)
    1.0
    >>> control_polygon_distance([[1, 0], [0, 1], [-1, 0], [0, -1]], None, 2, closed=True)   # |2P_i - P_i-1 - P_i+1| / 8
    0.25
    """
    for flag, name in ((closed, "closed"), (skip_outside, "skip_outside")):
        if not isinstance(flag, (bool, np.bool_)):
            raise TypeError(f"{name} must be True or False; got {flag!r}")
    if closed:
        if knots is not None:
            raise ValueError("knots must be None for a closed curve (its knots are the integers of closed_curve)")
        P, t = closed_curve(ctrl, degree)
        p = int(degree)
        skip_outside = True
    else:
        P, t, p = _curve(ctrl, knots, degree)
    moderate(P)
    if p < 1:
        raise ValueError("degree must be >= 1 for control_polygon_distance (Greville abscissae need a knot)")
    lo, hi = pyramids.domain(t, p)
    xi = greville(t, p)
    Q = P
    if skip_outside:
        inside = (xi >= lo) & (xi <= hi)
        if not inside.any():
            raise ValueError("knots leave no Greville abscissa inside the domain: nothing to measure with skip_outside")
        Q, xi = P[inside], xi[inside]
    else:
        xi = np.clip(xi, lo, hi)
    C = bspline.de_boor(P, t, p, xi)
    return float(np.linalg.norm(Q - C, axis=1).max())


def convergence_study(ctrl, knots, degree, levels=6) -> dict:
    """How fast the subdivided control polygons approach the curve (Goldman §28.4.3).

    Applies :func:`schaefer` level after level and records :func:`control_polygon_distance`;
    halving the knot spacing divides the distance by about 4 (it is O(h^2), h the largest knot
    interval), so the distances fall like ``4^-level``.

    ctrl, knots, degree (>= 1): the curve (as :func:`schaefer`).  levels: int in [1, 12], and
    within the work budget of :func:`schaefer`.
    Returns ``{"levels": (L+1,), "distance": (L+1,), "ratio": (L,) distance[l-1] / distance[l],
    "points": [number of control points per level]}``; a ratio is 0 where the distance is already
    0 (a polygon on its curve, nothing left to converge).
    Raises ValueError as :func:`schaefer`.

    >>> study = convergence_study([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 3)
    >>> study["ratio"].tolist()
    [4.0, 4.0, 4.0]
    """
    P, t, p = _curve(ctrl, knots, degree)
    moderate(P)
    if p < 1:
        raise ValueError("degree must be >= 1 for a convergence study")
    levels = as_int(levels, "levels", minimum=1, maximum=12)
    m, d = P.shape
    levels = within_budget(levels, "levels", cost=lambda v: _refined_count(m, p, v) * d * (p + 1),
                           what="the refined polygon", unit="coordinates computed", minimum=1)
    dist = [control_polygon_distance(P, t, p)]
    counts = [P.shape[0]]
    for _ in range(levels):
        _, P, t = _schaefer_refine(P, t, p)
        dist.append(control_polygon_distance(P, t, p))
        counts.append(P.shape[0])
    d = np.array(dist)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(d[1:] > 0, d[:-1] / np.where(d[1:] > 0, d[1:], 1.0), 0.0)
    return {"levels": np.arange(levels + 1), "distance": d, "ratio": ratio, "points": counts}


# --------------------------------------------------------------------------------------------
# §28.3.5 and §28.4.4 rendering and intersecting by knot insertion
# --------------------------------------------------------------------------------------------

def split(ctrl, knots, degree, u):
    """Cut a B-spline curve in two at ``u`` by inserting u until it has multiplicity p (Goldman §28.3.5).

    At multiplicity p the control point with label ``(u, ..., u)`` is the curve point C(u): the
    control points up to it form the left curve and those from it the right curve.

    ctrl, knots, degree (>= 1): the curve.  u: a number strictly inside the domain.
    Returns ``((left_ctrl, left_knots), (right_ctrl, right_knots))``, both of degree p, the left
    over ``[t_p, u]`` and the right over ``[u, t_{n+1}]``.
    Raises ValueError for a bad curve or u not strictly inside the domain.

    >>> (l, lk), (r, rk) = split([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5)
    >>> l.tolist(), lk.tolist()
    ([[0.0, 0.0], [0.5, 1.0], [1.0, 1.0]], [0.0, 0.0, 0.0, 0.5, 0.5, 0.5])
    """
    P, t, p = _curve(ctrl, knots, degree)
    if p < 1:
        raise ValueError("degree must be >= 1 to split a curve by knot insertion")
    u = as_float(u, "u")
    lo, hi = pyramids.domain(t, p)
    if not lo < u < hi:
        raise ValueError(f"u must lie strictly inside the domain ({_fmt(lo)}, {_fmt(hi)}); u is {_fmt(u)}")
    s = int(np.count_nonzero(t == u))
    times = max(p - s, 0)
    Q, tau = P, t
    for _ in range(times):
        Q, tau, _, _ = _boehm_once(Q, tau, p, u)
    # the point with label (u, ..., u): the last index whose knots t_{i+1..i+p} are all u
    first = int(np.searchsorted(tau, u, side="left"))       # first knot equal to u
    c = first - 1                                            # label tau[c+1 .. c+p] = u ... u
    left_knots = np.concatenate([tau[:first + p], [u]])
    right_knots = np.concatenate([[u], tau[first:]])
    return (Q[:c + 1].copy(), left_knots), (Q[c:].copy(), right_knots)


def _corner_flatness(P: np.ndarray) -> float:
    """Largest distance of a control point from the segment joining its two neighbours (O(h^2))."""
    if P.shape[0] < 3:
        return 0.0
    a, b, c = P[:-2], P[1:-1], P[2:]
    ac = c - a
    L2 = (ac * ac).sum(1)
    w = b - a
    s = np.clip(np.where(L2 > 0, (w * ac).sum(1) / np.where(L2 > 0, L2, 1.0), 0.0), 0.0, 1.0)
    return float(np.linalg.norm(w - s[:, None] * ac, axis=1).max())


def render_by_subdivision(ctrl, knots, degree, tol=1e-3, method="bezier", max_levels=16):
    """A polyline within about ``tol`` of a B-spline curve, by knot insertion (Goldman §28.3.5, §28.4.4).

    ``method="bezier"`` (§28.3.5): convert to piecewise Bezier form (§28.3.3), then split each
    piece in half (de Casteljau subdivision) until its control polygon is within ``tol`` of its
    chord; the convex hull property puts the curve within tol of the chords, which are returned.
    ``method="subdivision"`` (§28.4.4): halve all knot intervals (:func:`schaefer`) until every
    control point is within ``tol`` of the chord of its two neighbours, and return the control
    polygon itself, which converges to the curve like ``4^-level`` (§28.4.3).

    ctrl, knots, degree (>= 1): the curve.  tol: float > 0.  method: "bezier" or "subdivision".
    max_levels: int in [0, 20], the most halvings.
    Returns ``(points (N, d), levels)``, levels the number of halvings used (the deepest, for "bezier").
    Raises ValueError for a bad curve, degree 0, tol <= 0, an unknown method, or a tol so small that a
    level would hold more than :data:`~goldman_lib.validation.MAX_ITEMS` coordinates (the work budget).

    >>> pts, used = render_by_subdivision([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, tol=0.1)
    >>> len(pts), used
    (7, 3)
    """
    P, t, p = _curve(ctrl, knots, degree)
    if p < 1:
        raise ValueError("degree must be >= 1 to render by subdivision")
    tol = bezier_subdivision.resolvable_tolerance(as_float(tol, "tol", positive=True), moderate(P))
    max_levels = as_int(max_levels, "max_levels", minimum=0, maximum=20)
    if method not in ("bezier", "subdivision"):
        raise ValueError(f"method must be 'bezier' or 'subdivision'; got {method!r}")
    if method == "subdivision":
        level = 0
        while level < max_levels and _corner_flatness(P) > tol:
            bezier_subdivision.check_subdivision_budget(_refined_count(P.shape[0], p, 1), P.shape[1] * (p + 1), tol, "max_levels")
            _, P, t = _schaefer_refine(P, t, p)
            level += 1
        return P.copy(), level
    pieces, _ = to_piecewise_bezier(P, t, p)
    level = 0
    while True:
        flat = polygons.flatness(pieces, even=False) <= tol
        if flat.all() or level >= max_levels:
            break
        bezier_subdivision.check_subdivision_budget(len(pieces) + int(np.count_nonzero(~flat)), pieces[0].size, tol, "max_levels")
        left, right = pyramids.split(pieces[~flat], 0.5, axis=1)
        counts = np.where(flat, 1, 2)
        start = np.cumsum(counts) - counts
        new = np.empty((int(counts.sum()),) + pieces.shape[1:])
        new[start[flat]] = pieces[flat]
        new[start[~flat]] = left
        new[start[~flat] + 1] = right
        pieces = new
        level += 1
    return np.vstack([pieces[:, 0], pieces[-1:, -1]]), level


def intersect(a, b, tol=1e-10):
    """Intersection points of two planar B-spline curves (Goldman §28.3.5, §28.4.4).

    Both curves are converted to piecewise Bezier form by knot insertion (§28.3.3); every pair of
    Bezier pieces is then intersected by Bezier subdivision with a Newton polish
    (:func:`goldman_lib.bezier_intersection.intersect_curves`: pieces whose control-point boxes miss cannot
    meet, by the convex hull property), and the piece parameters are mapped back to the knot
    intervals.  A crossing at a knot, found by the two pieces that meet there, is kept once.

    a, b: curves as ``(ctrl (n+1, 2), knots, degree)`` tuples, degree >= 1.  tol: float > 0, how
    close the curves must come to count as meeting (relative to the size of the control points).
    Returns ``(params (k, 2), points (k, 2))``: the parameter on a, on b, and the point, sorted by
    the parameter on a; k = 0 if the curves do not meet.
    Raises TypeError if a or b is not a 3-tuple; ValueError for bad curves (a 3D curve, degree 0)
    or tol <= 0.

    >>> line = ([[0, 0.5], [2, 0.5]], [0, 0, 1, 1], 1)
    >>> arch = ([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2)
    >>> params, points = intersect(line, arch)
    >>> points.round(6).tolist()
    [[0.292893, 0.5], [1.707107, 0.5]]
    """
    curves = []
    for name, c in (("a", a), ("b", b)):
        if not isinstance(c, (tuple, list)) or len(c) != 3:
            raise TypeError(f"{name} must be a (ctrl, knots, degree) tuple")
        P, t, p = _curve(c[0], c[1], c[2], cname=f"{name}[0] (ctrl)", kname=f"{name}[1] (knots)")
        if P.shape[1] != 2:
            raise ValueError(f"{name} must be a planar curve: ctrl of shape (n+1, 2); got {P.shape}")
        if p < 1:
            raise ValueError(f"{name} must have degree >= 1 to intersect by subdivision")
        curves.append((P, t, p, *to_piecewise_bezier(P, t, p)))
    tol = as_float(tol, "tol", positive=True)
    (Pa, ta, pa_deg, pa, ba), (Pb, _, _, pb, bb) = curves
    hits = []
    lo_a, hi_a = pa.min(1), pa.max(1)                         # control-point boxes of the pieces
    lo_b, hi_b = pb.min(1), pb.max(1)
    pad = 1e-9 * max(1.0, float(np.abs(Pa).max()), float(np.abs(Pb).max()))
    for i, A in enumerate(pa):
        for j, B in enumerate(pb):
            if np.any(lo_a[i] > hi_b[j] + pad) or np.any(lo_b[j] > hi_a[i] + pad):
                continue                                        # convex hulls apart: no intersection
            st = bezier_intersection.intersect_curves(A, B, tol=tol)
            for s_, t_ in st:
                hits.append((ba[i] + (ba[i + 1] - ba[i]) * s_, bb[j] + (bb[j + 1] - bb[j]) * t_))
    if not hits:
        return np.zeros((0, 2)), np.zeros((0, 2))
    hp = np.array(sorted(hits))
    pts = bspline.de_boor(Pa, ta, pa_deg, hp[:, 0])
    scale = max(1.0, float(np.abs(Pa).max()), float(np.abs(Pb).max()))
    keep = [0]
    for k in range(1, len(hp)):
        if np.linalg.norm(pts[k] - pts[keep[-1]]) > 1e-7 * scale:
            keep.append(k)
    return hp[keep], pts[keep]

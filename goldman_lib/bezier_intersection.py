"""Intersection by Bezier subdivision (Goldman chapter 25, §25.3.1-25.3.2).

:func:`intersect_curves` and :func:`intersection_boxes` (§25.3.1, curve-curve), and for surfaces
:func:`intersect_ray_patch` and :func:`intersect_patches` (§25.3.2).  They prune pairs of pieces
by the convex hull property (bounding boxes) and polish by Newton's method.  B-spline curves are
intersected by converting to Bezier pieces first (:func:`goldman_lib.knot_insertion.intersect`,
which calls :func:`intersect_curves`).  Every public name here is also importable as
``goldman_lib.bezier.<name>``.

>>> intersect_curves([[0, 0], [1, 2], [2, 0]], [[0, 0.75], [2, 0.75]]).round(12).tolist()
[[0.25, 0.25], [0.75, 0.75]]
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib.kernels import polygons, pyramids
from goldman_lib.kernels.pyramids import point_and_tangent as _point_and_tangent
from goldman_lib.kernels.pyramids import split_xy as _split_xy
from goldman_lib.validation import MAX_SQUARABLE
from goldman_lib.validation import as_float, as_int, as_points
from goldman_lib.validation import moderate as _moderate

__all__ = ["intersect_curves", "intersection_boxes", "intersect_ray_patch", "intersect_patches"]


def _tolerance(tol, name="tol") -> float:
    return as_float(tol, name, positive=True)


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
        flat = (polygons.flatness(pa) <= flat_tol) & (polygons.flatness(pb) <= flat_tol)
        if level == max_depth or 4 * np.count_nonzero(~flat) > max_pairs:
            flat[:] = True
        yield level, pa, pb, ia, ib, flat
        pa, pb, ia, ib = pa[~flat], pb[~flat], ia[~flat], ib[~flat]
        if len(pa) == 0:
            return
        # both pieces of every pair are halved: four child pairs
        al, ar = pyramids.split(pa, 0.5, axis=1)
        bl, br = pyramids.split(pb, 0.5, axis=1)
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
        F = pyramids.curve_points(A, s) - pyramids.curve_points(B, t)
        if it == 12:
            hopeless = np.linalg.norm(F, axis=1) > 1e-3 * scale
            active[idx[hopeless]] = False
            keep = ~hopeless
            idx, s, t, F = idx[keep], s[keep], t[keep], F[keep]
        exact = np.linalg.norm(F, axis=1) <= 4e-16 * scale      # nothing left to improve
        active[idx[exact]] = False
        idx, s, t, F = idx[~exact], s[~exact], t[~exact], F[~exact]
        J = np.stack([pyramids.curve_points(HA, s), -pyramids.curve_points(HB, t)], axis=-1)   # (N, 2, 2)
        new = np.clip(st[idx] + _solve2(J, F), 0.0, 1.0)
        moved = np.abs(new - st[idx]).max(axis=1)
        st[idx] = new
        active[idx[moved <= 1e-15]] = False
    res = np.linalg.norm(pyramids.curve_points(A, st[:, 0]) - pyramids.curve_points(B, st[:, 1]), axis=1)
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


def _curves_pair(a, b, moderate: bool = False):
    A = as_points(a, "a", ndim=2, dim=2)
    B = as_points(b, "b", ndim=2, dim=2)
    return (_moderate(A, "a"), _moderate(B, "b")) if moderate else (A, B)


# -- the scalar path for small curves ----------------------------------------------------------
# For two curves of a few control points each, numpy's per-call overhead (microseconds per array
# operation on arrays of 4 points) is most of the time of the array version above.  The same
# algorithm on plain Python floats -- the same boxes, flatness, chord guesses, Newton's method and
# merging -- is many times faster there.  Each piece is subdivided once however many pairs it is
# in (its halves are cached), corner guesses are tried only where a flat pair reaches the corner,
# and at a tangency (a double root: Newton's steps only halve the error) a doubled step is taken
# when it does better, which restores fast convergence there.  A pair that can touch at most once
# (:func:`_may_touch`) is settled by a tangential contact found inside it rather than subdivided
# until flat, and de Casteljau's steps for cubics and quadratics are written out (no lists).  A
# small float64 array is checked on plain floats too (:func:`_small_floats`): numpy's checks cost
# microseconds each, as much as the whole search at a tangency.

#: Curves with at most this many control points each take the scalar path.
_SMALL = 8

#: A pair of pieces whose chords make an angle with sine below this may hold a tangency: see
#: :func:`_may_touch`.
_TANGENT_SINE = 0.25


# The weights of :meth:`_Piece.flat` for a cubic, as its loop computes them: w = k/3 and 1 - w.
_THIRD = 1 / 3
_TWO_THIRDS = 1.0 - _THIRD
_TWO_THIRDS_W = 2 / 3
_ONE_MINUS_TWO_THIRDS = 1.0 - _TWO_THIRDS_W


class _Piece:
    """A piece of a curve: control points xs, ys (tuples), parameter interval [lo, hi], its box,
    and, once asked for, its (even) flatness and its two halves."""

    __slots__ = ("xs", "ys", "lo", "hi", "x0", "x1", "y0", "y1", "_flat", "_halves", "_turn")

    def __init__(self, xs, ys, lo, hi):
        self.xs, self.ys, self.lo, self.hi = xs, ys, lo, hi
        self._flat = self._halves = self._turn = None
        if len(xs) != 4:
            self.x0, self.x1, self.y0, self.y1 = min(xs), max(xs), min(ys), max(ys)
            return
        # a cubic's box written out: min and max exactly (the first extreme entry kept), a third
        # of the time of the four builtin calls, and a piece is made at every halving
        a, b, c, d = xs
        x0 = x1 = a
        if b < x0:
            x0 = b
        elif b > x1:
            x1 = b
        if c < x0:
            x0 = c
        elif c > x1:
            x1 = c
        if d < x0:
            x0 = d
        elif d > x1:
            x1 = d
        a, b, c, d = ys
        y0 = y1 = a
        if b < y0:
            y0 = b
        elif b > y1:
            y1 = b
        if c < y0:
            y0 = c
        elif c > y1:
            y1 = c
        if d < y0:
            y0 = d
        elif d > y1:
            y1 = d
        self.x0, self.x1, self.y0, self.y1 = x0, x1, y0, y1

    def turn(self) -> int:
        """How the control polygon turns: 1 all left (or straight), -1 all right, 0 straight, 2 both ways."""
        if self._turn is None:
            xs, ys = self.xs, self.ys
            left = right = False
            for k in range(len(xs) - 2):
                c = (xs[k + 1] - xs[k]) * (ys[k + 2] - ys[k + 1]) - (ys[k + 1] - ys[k]) * (xs[k + 2] - xs[k + 1])
                if c > 0.0:
                    left = True
                elif c < 0.0:
                    right = True
            self._turn = 2 if left and right else 1 if left else -1 if right else 0
        return self._turn

    def flat(self) -> float:
        """:func:`goldman_lib.kernels.polygons.flatness` (even) of this piece."""
        if self._flat is None:
            xs, ys = self.xs, self.ys
            n = len(xs) - 1
            f = 0.0
            ax, ay, bx, by = xs[0], ys[0], xs[-1], ys[-1]
            if n == 3:                 # the cubic written out, the same arithmetic (w = 1/3, 2/3)
                dx = xs[1] - (_TWO_THIRDS * ax + _THIRD * bx)
                dy = ys[1] - (_TWO_THIRDS * ay + _THIRD * by)
                f = dx * dx + dy * dy
                dx = xs[2] - (_ONE_MINUS_TWO_THIRDS * ax + _TWO_THIRDS_W * bx)
                dy = ys[2] - (_ONE_MINUS_TWO_THIRDS * ay + _TWO_THIRDS_W * by)
                d = dx * dx + dy * dy
                if d > f:
                    f = d
                self._flat = f ** 0.5
                return self._flat
            for k in range(1, n):
                w = k / n
                dx = xs[k] - ((1.0 - w) * ax + w * bx)
                dy = ys[k] - ((1.0 - w) * ay + w * by)
                d = dx * dx + dy * dy
                if d > f:
                    f = d
            self._flat = f ** 0.5
        return self._flat

    def halves(self):
        if self._halves is None:
            mid = 0.5 * (self.lo + self.hi)
            xs, ys = self.xs, self.ys
            lx, rx, ly, ry = _split_xy(xs, ys, 0.5)
            self._halves = (_Piece(lx, ly, self.lo, mid), _Piece(rx, ry, mid, self.hi))
        return self._halves


def _chord_guess(p: _Piece, q: _Piece):
    """:func:`_chord_guesses` for one pair."""
    ax, ay, bx, by = p.xs[0], p.ys[0], q.xs[0], q.ys[0]
    dax, day = p.xs[-1] - ax, p.ys[-1] - ay
    dbx, dby = q.xs[-1] - bx, q.ys[-1] - by
    rx, ry = bx - ax, by - ay
    det = dax * (-dby) - day * (-dbx)
    scale = (dax * dax + day * day) ** 0.5 * (dbx * dbx + dby * dby) ** 0.5
    if abs(det) > 1e-12 * max(scale, 1e-300):
        sig = min(max((rx * (-dby) - ry * (-dbx)) / det, 0.0), 1.0)
        tau = min(max((dax * ry - day * rx) / det, 0.0), 1.0)
    else:
        sig = tau = 0.5
    return p.lo + sig * (p.hi - p.lo), q.lo + tau * (q.hi - q.lo)


def _nearly_parallel(p: _Piece, q: _Piece, sine: float = 0.1) -> bool:
    """Whether the chords of two pieces make an angle with sine below ``sine``."""
    dax, day = p.xs[-1] - p.xs[0], p.ys[-1] - p.ys[0]
    dbx, dby = q.xs[-1] - q.xs[0], q.ys[-1] - q.ys[0]
    return abs(dax * dby - day * dbx) <= sine * ((dax * dax + day * day) * (dbx * dbx + dby * dby)) ** 0.5


def _fat_line_apart(p: _Piece, q: _Piece, pad: float) -> bool:
    """Whether q's control points all lie on one side of p's fat line (the band round p's chord
    that holds p's control points), farther than ``pad``: then, by the convex hull property, the
    pieces do not meet (the fat-line test of Bezier clipping, Sederberg and Nishita)."""
    xs, ys = p.xs, p.ys
    nx, ny = ys[0] - ys[-1], xs[-1] - xs[0]              # normal of the chord (not unit)
    size = (nx * nx + ny * ny) ** 0.5
    if size == 0.0:
        return False
    x0, y0 = xs[0], ys[0]
    lo = hi = 0.0
    for k in range(1, len(xs) - 1):
        d = (xs[k] - x0) * nx + (ys[k] - y0) * ny
        if d < lo:
            lo = d
        elif d > hi:
            hi = d
    gap = pad * size
    qx, qy = q.xs, q.ys
    dlo = dhi = (qx[0] - x0) * nx + (qy[0] - y0) * ny
    for k in range(1, len(qx)):
        d = (qx[k] - x0) * nx + (qy[k] - y0) * ny
        if d < dlo:
            dlo = d
        elif d > dhi:
            dhi = d
    return dlo > hi + gap or dhi < lo - gap


def _graph(xs, ys, ux, uy):
    """The polygon xs, ys as a graph over the direction (ux, uy): None unless every leg points along
    it (positive dot product) or every leg against it; else (sign, least slope, greatest slope)
    with the legs' slopes against (ux, uy) -- by the hodograph's convex hull, the curve's slopes
    lie between them."""
    sign = 0
    lo, hi = float("inf"), float("-inf")
    for k in range(len(xs) - 1):
        dx, dy = xs[k + 1] - xs[k], ys[k + 1] - ys[k]
        d = dx * ux + dy * uy
        if d > 0.0 and sign >= 0:
            sign = 1
        elif d < 0.0 and sign <= 0:
            sign = -1
        else:
            return None
        m = (dy * ux - dx * uy) / d
        if m < lo:
            lo = m
        if m > hi:
            hi = m
    return sign, lo, hi


def _may_touch(p: _Piece, q: _Piece) -> bool:
    """Whether two pieces are graphs over one direction, one convex and the other concave, whose
    slopes can be equal.

    Along u, the sum of the two chords (oriented alike), a piece whose control polygon legs all
    point one way is a graph y = f(x) over u; one whose polygon turns one way only is a convex arc
    (variation diminishing: a line meets the curve no more often than its polygon), convex or
    concave as a graph by the turn and the leg direction.  Then f - g is convex (or concave) where
    both are defined, so the pieces meet at most twice, and once only if they meet tangentially
    (a zero with zero slope is the extremum of f - g); they can meet tangentially only if the
    ranges of slopes of their legs overlap.  A straight piece counts as convex and as concave.
    """
    tp, tq = p.turn(), q.turn()
    if tp == 2 or tq == 2:
        return False
    ux, uy = p.xs[-1] - p.xs[0], p.ys[-1] - p.ys[0]
    vx, vy = q.xs[-1] - q.xs[0], q.ys[-1] - q.ys[0]
    if ux * vx + uy * vy < 0.0:
        vx, vy = -vx, -vy
    ux, uy = ux + vx, uy + vy
    gp = _graph(p.xs, p.ys, ux, uy)
    if gp is None:
        return False
    gq = _graph(q.xs, q.ys, ux, uy)
    if gq is None:
        return False
    return tp * gp[0] * tq * gq[0] <= 0 and gp[1] <= gq[2] and gq[1] <= gp[2]


def _step2(a, b, c, d, f0, f1):
    """:func:`_solve2` for one 2x2 system [[a, b], [c, d]] step = -J^+ F."""
    det = a * d - b * c
    size = a * a + b * b + c * c + d * d
    if abs(det) > 1e-12 * size:
        return -(d * f0 - b * f1) / det, -(a * f1 - c * f0) / det
    g0 = a * f0 + c * f1
    g1 = b * f0 + d * f1
    lam = 1e-14 * size + 1e-300
    m00 = a * a + c * c + lam
    m01 = a * b + c * d
    m11 = b * b + d * d + lam
    mdet = m00 * m11 - m01 * m01
    return -(m11 * g0 - m01 * g1) / mdet, -(m00 * g1 - m01 * g0) / mdet


def _newton_small(A, B, s, t, scale, iterations=100, patience=0, start=None):
    """:func:`_newton_pairs` for one start on plain floats: ``(s, t, residual, tangential)``, or None
    for a start dropped as hopeless; ``tangential`` says whether the curves' tangents at the end
    are parallel (sine below 1e-6).  With ``patience`` > 0 the start is also dropped after that
    many steps in a row that do not halve the residual (the curves come close but do not meet).

    After a step that cut the residual by less than 5 (a tangency: the residual only quarters per
    step), the doubled step is tried too and kept if it meets better -- Newton's method for a
    double root -- so a tangential contact converges in a few steps instead of fifty.

    start: the :func:`~goldman_lib.kernels.pyramids.point_and_tangent` pair at (s, t) if the
    caller has it (the ordering of the starts computes it), so it is not computed twice."""
    (ax, ay), (bx, by) = A, B
    if start is None:
        pa = _point_and_tangent(ax, ay, s)
        pb = _point_and_tangent(bx, by, t)
    else:
        pa, pb = start
    f0, f1 = pa[0] - pb[0], pa[1] - pb[1]
    res = (f0 * f0 + f1 * f1) ** 0.5
    stalled = 0
    for it in range(iterations):
        if it == 12 and res > 1e-3 * scale:
            return None
        if res <= 4e-16 * scale:
            break
        a, b, c, d = pa[2], -pb[2], pa[3], -pb[3]
        det = a * d - b * c            # _step2's regular case written out (the same arithmetic)
        if abs(det) > 1e-12 * (a * a + b * b + c * c + d * d):
            ds, dt = -(d * f0 - b * f1) / det, -(a * f1 - c * f0) / det
        else:
            ds, dt = _step2(a, b, c, d, f0, f1)
        ns, nt = s + ds, t + dt        # min(max(., 0), 1) written out (the same value, NaN too)
        if ns < 0.0:
            ns = 0.0
        elif ns > 1.0:
            ns = 1.0
        if nt < 0.0:
            nt = 0.0
        elif nt > 1.0:
            nt = 1.0
        pa2 = _point_and_tangent(ax, ay, ns)
        pb2 = _point_and_tangent(bx, by, nt)
        g0, g1 = pa2[0] - pb2[0], pa2[1] - pb2[1]
        new_res = (g0 * g0 + g1 * g1) ** 0.5
        if new_res > 0.2 * res:
            s2, t2 = min(max(s + 2.0 * ds, 0.0), 1.0), min(max(t + 2.0 * dt, 0.0), 1.0)
            pa3 = _point_and_tangent(ax, ay, s2)
            pb3 = _point_and_tangent(bx, by, t2)
            h0, h1 = pa3[0] - pb3[0], pa3[1] - pb3[1]
            res3 = (h0 * h0 + h1 * h1) ** 0.5
            if res3 < new_res:
                ns, nt, pa2, pb2, g0, g1, new_res = s2, t2, pa3, pb3, h0, h1, res3
        if patience:
            stalled = stalled + 1 if new_res > 0.5 * res else 0
            if stalled >= patience:
                return None
        moved = max(abs(ns - s), abs(nt - t))
        s, t, pa, pb, f0, f1, res = ns, nt, pa2, pb2, g0, g1, new_res
        if moved <= 1e-15:
            break
    cross = pa[2] * pb[3] - pa[3] * pb[2]
    tangential = abs(cross) <= 1e-6 * (pa[2] * pa[2] + pa[3] * pa[3]) ** 0.5 * (pb[2] * pb[2] + pb[3] * pb[3]) ** 0.5
    return s, t, res, tangential


def _small_floats(P):
    """For :func:`intersect_curves`: ``((xs, ys), size)`` -- coordinate tuples and the largest
    magnitude -- if ``P`` is a float64 (k, 2) array of 2 to :data:`_SMALL` finite points within
    :data:`goldman_lib.validation.MAX_SQUARABLE`, the checks of :func:`_curves_pair` passed without their numpy calls
    (microseconds each on a few points); None for anything else, which the general checks take."""
    if type(P) is not np.ndarray or P.dtype.char != "d" or P.ndim != 2 or P.shape[1] != 2 \
            or not 2 <= P.shape[0] <= _SMALL:
        return None
    xs, ys = P.T.tolist()
    if not math.isfinite(sum(xs) + sum(ys)):                # a nan or an infinity anywhere
        return None
    big = max(map(abs, xs + ys))
    if big > MAX_SQUARABLE:
        return None
    return (tuple(xs), tuple(ys)), big


def _intersect_small(ca, cb, tol_abs: float, scale: float, max_depth: int, max_pairs: int = 20000) -> np.ndarray:
    """:func:`intersect_curves` on plain floats for curves of 2 to :data:`_SMALL` points each,
    given as ``(xs, ys)`` tuples of their control points' coordinates."""
    pad = 1e-12 * scale
    flat_tol = 1e-3 * scale
    pairs = [(_Piece(ca[0], ca[1], 0.0, 1.0), _Piece(cb[0], cb[1], 0.0, 1.0), True)]   # (p, q, may try Newton)
    guesses = {}                       # start (s, t) -> the parameter box of its flat pair
    extra = {}                         # more starts, in the flat pairs whose chords are nearly parallel
    reach = set()                      # corners of the unit square that a flat pair reaches
    first = pairs[0]
    if not (first[0].x0 <= first[1].x1 + pad and first[1].x0 <= first[0].x1 + pad
            and first[0].y0 <= first[1].y1 + pad and first[1].y0 <= first[0].y1 + pad):
        pairs = []
    found = []                         # Newton's solutions (s, t, residual)
    contacts = []                      # those that are tangential contacts
    margin = 1e-9
    for level in range(max_depth + 1):
        kept = pairs                   # every pair here has overlapping boxes
        flat = [p.flat() <= flat_tol and q.flat() <= flat_tol for p, q, _ in kept]
        if level == max_depth or 4 * flat.count(False) > max_pairs:
            flat = [True] * len(kept)
        pairs = []
        append = pairs.append
        for (p, q, may_try), f in zip(kept, flat):
            if not f:
                if contacts and any(p.lo - margin <= u <= p.hi + margin and q.lo - margin <= v <= q.hi + margin
                                    for u, v in contacts):
                    if _may_touch(p, q):
                        continue               # a tangential contact found before settles this pair too
                elif may_try and _nearly_parallel(p, q, _TANGENT_SINE) and _may_touch(p, q):
                    # a tangency in the making: nearly parallel chords, and the pieces meet at most
                    # twice, once only at a tangential contact.  Try Newton from the chords once;
                    # a tangential contact inside the pair settles it (no more subdivision there)
                    may_try = False            # nor will the children of this pair
                    if _fat_line_apart(p, q, pad) or _fat_line_apart(q, p, pad):
                        continue               # a near miss: the pieces do not meet
                    s, t = _chord_guess(p, q)
                    r = _newton_small(ca, cb, s, t, scale, iterations=20, patience=2)
                    if r is not None and r[2] <= tol_abs:
                        found.append(r)
                        if r[3]:
                            contacts.append(r[:2])
                            if p.lo - margin <= r[0] <= p.hi + margin and q.lo - margin <= r[1] <= q.hi + margin:
                                continue
            if f:
                s, t = _chord_guess(p, q)
                box = (p.lo, p.hi, q.lo, q.hi)
                guesses.setdefault((round(s, 12), round(t, 12)), box)
                if _nearly_parallel(p, q):
                    # two nearly parallel flat pieces may cross twice (or touch): start from the
                    # corners of the pair's parameter box too, so that Newton reaches both crossings
                    for cs in (p.lo, p.hi):
                        for ct in (q.lo, q.hi):
                            extra.setdefault((cs, ct), box)
                for cs in (0.0, 1.0):
                    if p.lo <= cs <= p.hi:
                        for ct in (0.0, 1.0):
                            if q.lo <= ct <= q.hi:
                                reach.add((cs, ct))
            else:
                # the four child pairs, those whose boxes miss dropped at once
                d, e = q.halves()
                dx1, dy1, ex1, ey1 = d.x1 + pad, d.y1 + pad, e.x1 + pad, e.y1 + pad
                for c in p.halves():
                    cx0, cx1, cy0, cy1 = c.x0, c.x1 + pad, c.y0, c.y1 + pad
                    if cx0 <= dx1 and d.x0 <= cx1 and cy0 <= dy1 and d.y0 <= cy1:
                        append((c, d, may_try))
                    if cx0 <= ex1 and e.x0 <= cx1 and cy0 <= ey1 and e.y0 <= cy1:
                        append((c, e, may_try))
        if not pairs:
            break
    for c in reach:
        extra.setdefault(c, (c[0], c[0], c[1], c[1]))
    # Newton from the chord guesses where the curves come closest first, then from the extra
    # starts (corners of nearly parallel flat pairs, corners of the unit square).  A start whose flat pair holds a
    # tangential contact already found is skipped: at a tangency every pair round the contact
    # holds it (one Newton run instead of four), and a second crossing within the pair would be
    # so close that its midpoint with the contact meets within tol, merging the two anyway
    # (transversal solutions skip nothing: two close crossings can share a flat pair).
    at = {}                            # start -> the curves' points and tangents there, for Newton

    def gap_at(st):
        pa = _point_and_tangent(ca[0], ca[1], st[0])
        pb = _point_and_tangent(cb[0], cb[1], st[1])
        at[st] = pa, pb
        return (pa[0] - pb[0]) ** 2 + (pa[1] - pb[1]) ** 2

    starts = []
    if guesses or extra:               # (none when a tangential contact settled every pair)
        starts = sorted(guesses, key=lambda st: (gap_at(st), st))
        starts += sorted(st for st in extra if st not in guesses)
        guesses.update((st, box) for st, box in extra.items() if st not in guesses)
    for s, t in starts:
        s0, s1, t0, t1 = guesses[(s, t)]
        if any(s0 - margin <= u <= s1 + margin and t0 - margin <= v <= t1 + margin for u, v in contacts):
            continue
        r = _newton_small(ca, cb, s, t, scale, start=at.get((s, t)))
        if r is not None and r[2] <= tol_abs:
            found.append(r)
            if r[3]:
                contacts.append(r[:2])
    # :func:`_merge_solutions` on floats: best residual first, one solution per cluster
    if len(found) > 1:
        found.sort(key=lambda r: r[2])
    kept = []
    for s, t, _, _ in found:
        for u, v in kept:
            gap = max(abs(s - u), abs(t - v))
            if gap <= 1e-9:
                break
            if gap <= 1e-3:
                pa = _point_and_tangent(ca[0], ca[1], 0.5 * (s + u))
                pb = _point_and_tangent(cb[0], cb[1], 0.5 * (t + v))
                if ((pa[0] - pb[0]) ** 2 + (pa[1] - pb[1]) ** 2) ** 0.5 <= tol_abs:
                    break
        else:
            kept.append((s, t))
    kept.sort()
    return np.array(kept) if kept else np.empty((0, 2))


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

    Curves of at most 8 control points each (the usual case) run the same steps on plain Python
    floats, which is many times faster than numpy on such small arrays; there a flat pair whose
    chords are nearly parallel also starts Newton from the corners of its parameter box (two
    close crossings can share one flat pair), Newton takes the doubled step where the residual
    only quarters (a tangency), and a tangential contact once found is not polished again from
    the neighbouring pairs that all contain it.  A tangency is also cut short before its pieces
    are flat (§25.3.1 would halve them level after level, four pairs round the contact at every
    level): a pair whose chords are nearly parallel and whose pieces bend apart -- graphs over
    one direction, one convex and one concave, with slopes that can agree -- meets at most twice,
    and only once if it meets tangentially, so Newton is tried on it once (and on none of its
    descendants; a near miss is dropped first if the fat lines of Bezier clipping show the pieces
    apart, and Newton gives up after two steps in a row that do not halve the gap); a tangential
    contact inside the pair ends the search there, and settles every other such pair round it.
    Near a tangency this also finds both of two crossings a hair apart that the flat pairs alone
    can miss.

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
    fa = _small_floats(a)
    fb = _small_floats(b) if fa else None
    if fb:                             # valid small float arrays: the same checks, on plain floats
        (ca, big_a), (cb, big_b) = fa, fb
    else:
        A, B = _curves_pair(a, b)
    if type(tol) is not float or not 0.0 < tol < math.inf:
        tol = _tolerance(tol)
    if type(max_depth) is not int or not 1 <= max_depth <= 60:
        max_depth = as_int(max_depth, "max_depth", minimum=1, maximum=60)
    if fb:
        scale = max(1.0, big_a, big_b)
        return _intersect_small(ca, cb, tol * scale, scale, max_depth)
    small = 2 <= len(A) <= _SMALL and 2 <= len(B) <= _SMALL
    if small:                          # plain floats from here on (cheaper than numpy's reductions)
        ca, cb = tuple(map(tuple, A.T.tolist())), tuple(map(tuple, B.T.tolist()))
        big_a, big_b = max(map(abs, ca[0] + ca[1])), max(map(abs, cb[0] + cb[1]))
    else:
        big_a, big_b = float(np.abs(A).max()), float(np.abs(B).max())
    if max(big_a, big_b) > MAX_SQUARABLE:
        _moderate(A, "a"), _moderate(B, "b")          # raises, naming the curve
    scale = max(1.0, big_a, big_b)
    if small:
        return _intersect_small(ca, cb, tol * scale, scale, max_depth)
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
        return float(np.linalg.norm(pyramids.curve_points(A, np.array(p[0])) - pyramids.curve_points(B, np.array(p[1]))))

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
    A, B = _curves_pair(a, b, moderate=True)
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
    P = _moderate(as_points(ctrl, "ctrl", ndim=3, dim=3))
    o = _moderate(as_points(origin, "origin", ndim=1, dim=3), "origin")
    d = _moderate(as_points(direction, "direction", ndim=1, dim=3), "direction")
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
        flat = polygons.patch_flatness(nets) <= flat_tol
        if depth == max_depth or 4 * np.count_nonzero(~flat) > 20000:
            flat[:] = True
        guesses.append(np.stack([(dom[flat, 0] + dom[flat, 1]) / 2, (dom[flat, 2] + dom[flat, 3]) / 2], 1))
        nets, dom = nets[~flat], dom[~flat]
        if len(nets) == 0:
            break
        nets, dom = pyramids.quarter(nets, dom)
    if not guesses:
        return np.zeros((0, 3))
    uv = np.concatenate(guesses)
    if len(uv) == 0:
        return np.zeros((0, 3))
    uvs, res = _newton_ray(P, o, d, uv)
    tol_abs = tol * scale
    good = (res <= tol_abs) & (uvs[:, 2] >= -tol)

    def meet(p):
        return float(np.linalg.norm(pyramids.patch_points(P, np.array([p[0]]), np.array([p[1]]))[:, 0] - o - p[2] * d))

    out = _merge_solutions(uvs[good], res[good], meet, tol_abs)
    return out[np.argsort(out[:, 2], kind="stable")] if len(out) else out


def _newton_ray(P, o, d, uv, iterations=60):
    """Newton on S(u, v) - o - s d = 0 from many (u, v) starts (s starts at the projection)."""
    m, n = P.shape[0] - 1, P.shape[1] - 1
    Du = m * np.diff(P, axis=0) if m else np.zeros_like(P)
    Dv = n * np.diff(P, axis=1) if n else np.zeros_like(P)
    u, v = uv[:, 0].copy(), uv[:, 1].copy()
    S = pyramids.patch_points(P, u, v).T
    s = (S - o) @ d / (d @ d)
    x = np.stack([u, v, s], 1)
    for _ in range(iterations):
        S = pyramids.patch_points(P, x[:, 0], x[:, 1]).T
        F = S - o - x[:, 2:3] * d
        J = np.stack([pyramids.patch_points(Du, x[:, 0], x[:, 1]).T, pyramids.patch_points(Dv, x[:, 0], x[:, 1]).T,
                      np.broadcast_to(-d, F.shape)], axis=-1)
        step = -(np.linalg.pinv(J, rcond=1e-13) @ F[:, :, None])[:, :, 0]
        new = x + step
        new[:, :2] = np.clip(new[:, :2], 0.0, 1.0)
        moved = np.abs(new - x).max()
        x = new
        if moved <= 1e-15:
            break
    S = pyramids.patch_points(P, x[:, 0], x[:, 1]).T
    res = np.linalg.norm(S - o - x[:, 2:3] * d, axis=1)
    return x, res


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
        fa = polygons.patch_flatness(na) <= tol
        fb = polygons.patch_flatness(nb) <= tol
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
                ga, gda = pyramids.quarter(ga, gda)
                ka = 4
            if split_b:
                gb, gdb = pyramids.quarter(gb, gdb)
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
        F = pyramids.patch_points(A, x[:, 0], x[:, 1]).T - pyramids.patch_points(B, x[:, 2], x[:, 3]).T
        J = np.stack([pyramids.patch_points(Au, x[:, 0], x[:, 1]).T, pyramids.patch_points(Av, x[:, 0], x[:, 1]).T,
                      -pyramids.patch_points(Bs, x[:, 2], x[:, 3]).T, -pyramids.patch_points(Bt, x[:, 2], x[:, 3]).T], axis=-1)
        step = -(np.linalg.pinv(J, rcond=1e-12) @ F[:, :, None])[:, :, 0]
        new = np.clip(x + step, 0.0, 1.0)
        moved = float(np.abs(new - x).max()) if len(x) else 0.0
        x = new
        if moved <= 1e-15:
            break
    res = np.linalg.norm(pyramids.patch_points(A, x[:, 0], x[:, 1]).T - pyramids.patch_points(B, x[:, 2], x[:, 3]).T, axis=1)
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
    A = _moderate(as_points(a, "a", ndim=3, dim=3), "a")
    B = _moderate(as_points(b, "b", ndim=3, dim=3), "b")
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
        res0 = np.linalg.norm(pyramids.patch_points(A, x0[:, 0], x0[:, 1]).T - pyramids.patch_points(B, x0[:, 2], x0[:, 3]).T, axis=1)
        better = res <= res0
        x = np.where(better[:, None], x, x0)
        pa = pyramids.patch_points(A, x[:, 0], x[:, 1]).T
        pb = pyramids.patch_points(B, x[:, 2], x[:, 3]).T
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

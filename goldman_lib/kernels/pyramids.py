"""Pyramids: de Casteljau's (Goldman §24.2, §25.2, §26.2) and de Boor's (§27.2-27.5, §28.2), unchecked.

Two routines do the arithmetic, and every pyramid of the library goes through one of them:

- :func:`casteljau_level`, one level of de Casteljau's pyramid, ``s P_j + t P_{j+1}`` with
  ``s = 1 - t``, on an array of points, a list of arrays or a list of numbers (its hot case, the
  apex for many parameters, is :func:`casteljau_apex`: the same arithmetic node by node in a
  reused scratch array, tested bit for bit against it);
- :func:`de_boor_pyramid`, de Boor's pyramid in place, ``P_j <- P_{j-1} + a (P_j - P_{j-1})``
  with the weight ``a`` of each node supplied by the caller (a knot ratio, a tabulated
  ``A u + B``, a blossom argument's ratio).

The rest are the shapes the callers need: the apex for many parameters (:func:`curve_points`,
:func:`patch_points`), both edges (:func:`split`, :func:`split_patches`, :func:`quarter`), every
level (:func:`casteljau_levels`), the blossom's apex (:func:`casteljau_blossom`), the curve point
and tangent of one scalar polygon (:func:`point_and_tangent`), the Bernstein table
(:func:`bernstein_rows`), and de Boor's pyramid for many parameters (:func:`de_boor_points`) and
for many blossom label sets (:func:`de_boor_blossom`).  Nothing here checks its input.
"""

from __future__ import annotations

import math
import threading

import numpy as np

__all__ = ["casteljau_level", "casteljau_levels", "casteljau_apex", "workspace", "WORKSPACE_MAX_BYTES",
           "curve_points", "patch_points", "casteljau_blossom", "split", "split_xy", "split_patches", "quarter",
           "point_and_tangent", "bernstein_rows",
           "POWER_FORM_MAX_DEGREE", "domain", "de_boor_pyramid", "de_boor_tables", "de_boor_points",
           "de_boor_blossom"]


# --------------------------------------------------------------------------------------------
# de Casteljau (§24.2)
# --------------------------------------------------------------------------------------------

def casteljau_level(level, t, s=None, inplace: bool = False, buf=None, axis: int = 0):
    """One level of de Casteljau's pyramid (Goldman §24.2): the ``k - 1`` affine combinations
    ``s P_j + t P_{j+1}`` (``s = 1 - t`` unless given) of ``k`` consecutive points.

    level: an array ``(k, ...)`` of points along axis 0 (or ``axis``; ``t`` broadcasting against the
    rest), returning an array ``(k - 1, ...)``; or a list of ``k`` numbers or arrays, returning a list.
    inplace (a list of arrays only): overwrite ``level[j]`` and drop the last entry, allocating
    nothing but one buffer ``buf`` (made if not given; pass one to reuse it across levels), about 4x
    faster than one operation on a whole large level.  A list of arrays not in place also uses ``buf``
    (of the level's broadcast shape) if given.

    >>> casteljau_level(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]), 0.5).tolist()
    [[0.5, 1.0], [1.5, 1.0]]
    >>> casteljau_level([0.0, 1.0, 2.0, 4.0], 0.5)
    [0.5, 1.5, 3.0]
    """
    if s is None:
        s = 1.0 - t
    if isinstance(level, np.ndarray):
        if axis == 0:
            return s * level[:-1] + t * level[1:]
        head = (slice(None),) * axis
        return s * level[head + (slice(None, -1),)] + t * level[head + (slice(1, None),)]
    if inplace:
        buf = np.empty_like(level[0]) if buf is None else buf
        for j in range(len(level) - 1):
            row = level[j]
            row *= s
            row += np.multiply(level[j + 1], t, out=buf)
        level.pop()
        return level
    if isinstance(level[0], np.ndarray):      # arrays: one new array per point, one shared buffer
        out = []
        for a, b in zip(level[:-1], level[1:]):
            row = np.multiply(a, s)
            buf = np.multiply(b, t, out=buf)
            row += buf
            out.append(row)
        return out
    return [s * a + t * b for a, b in zip(level[:-1], level[1:])]


def casteljau_levels(P: np.ndarray, ts) -> list[np.ndarray]:
    """Every level of the pyramid of P ``(n+1, ...)`` with parameter ``ts[r-1]`` on level r: the
    ordinary pyramid for ``ts = [t] * n`` (§24.2), the blossom's for ``ts = (u_1, ..., u_n)``
    (§26.3).  Returns ``[P.copy(), level 1, ..., level len(ts)]``.

    >>> [lvl.tolist() for lvl in casteljau_levels(np.array([[0.0], [2.0], [4.0]]), [0.5, 0.25])]
    [[[0.0], [2.0], [4.0]], [[1.0], [3.0]], [[1.5]]]
    """
    levels = [P.copy()]
    cur = P
    for t in ts:
        cur = casteljau_level(cur, t)
        levels.append(cur)
    return levels


# de Casteljau's pyramid for many parameters keeps its levels in a per-thread scratch array that
# lives across calls (as LAPACK's work arrays do), aligned to a 2 MiB huge page.  Measured for
# degree 7 at 10,000 parameters (about 1.4 MB of levels), CPU time per call: 660 us with fresh
# arrays per call (glibc maps blocks above 128 KB afresh and unmaps them on free, so every call
# paid a page fault per 4 KB touched), 480 us in a reused scratch on 4 KB pages (TLB misses on
# this VM), 310 us in a reused scratch on huge pages.  numpy asks the kernel for huge pages
# (madvise) on allocations of 4 MiB or more, so the scratch is at least that (virtual; only the
# pages touched become resident).  Only intermediate levels live there: the apex goes to a fresh
# (or the caller's) array, so no result is overwritten by the next call.  Above
# WORKSPACE_MAX_BYTES the scratch is a temporary array.
_scratch = threading.local()
_HUGE_PAGE = 2 ** 21

#: The most bytes of scratch one thread keeps between calls of :func:`casteljau_apex`.
WORKSPACE_MAX_BYTES = 8 * 2 ** 20


def workspace(size: int) -> np.ndarray:
    """A float64 scratch array of ``size`` entries for this thread, reused across calls while it
    stays under :data:`WORKSPACE_MAX_BYTES`, starting on a 2 MiB boundary (its contents are
    garbage; the next call overwrites them).

    >>> workspace(4).shape
    (4,)
    """
    if 8 * size > WORKSPACE_MAX_BYTES:
        return np.empty(size)
    buf = getattr(_scratch, "buf", None)
    if buf is None or buf.size < size:
        want = max(-(-8 * size // _HUGE_PAGE), 2) * _HUGE_PAGE        # bytes, whole huge pages
        raw = np.empty((want + _HUGE_PAGE) // 8)                         # >= 4 MiB: numpy madvises huge pages
        skip = (-raw.ctypes.data) % _HUGE_PAGE // 8
        buf = _scratch.buf = raw[skip:skip + want // 8]
    return buf[:size]


def casteljau_apex(rows, t: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """The apex of the pyramid for many parameters at once (§24.2): rows ``(k, D, 1 or N)`` (k points
    of D coordinates), t ``(N,)``; returns ``(D, N)`` (written into ``out``, any ``(D, N)`` view, if given).

    Node by node, ``P_j <- s P_j + t P_{j+1}`` with ``s = 1 - t`` (:func:`casteljau_level`'s
    arithmetic, bit for bit), each node one ``(D, N)`` row updated in place: the first level
    writes its rows into the thread's scratch (:func:`workspace`), the later ones overwrite them,
    the last writes the apex into ``out``.

    >>> casteljau_apex(np.array([[[0.0], [0.0]], [[1.0], [2.0]], [[2.0], [0.0]]]), np.array([0.0, 0.5, 1.0])).tolist()
    [[0.0, 1.0, 2.0], [0.0, 1.0, 0.0]]
    """
    k = len(rows)
    D, N = rows[0].shape[0], t.shape[0]
    if out is None:
        out = np.empty((D, N))
    if k == 1:
        out[...] = rows[0]
        return out
    ws = workspace((k + 1) * D * N)
    s = np.subtract(1.0, t, out=ws[:N])
    buf = ws[N:N + D * N].reshape(D, N)
    level = [out] if k == 2 else list(ws[N + D * N:N + k * D * N].reshape(k - 1, D, N))
    mul = np.multiply
    for j in range(k - 1):                    # level 1 from the points given
        row = level[j]
        mul(rows[j], s, out=row)
        row += mul(rows[j + 1], t, out=buf)
    for m in range(k - 2, 1, -1):             # then in place, m nodes on the level
        for j in range(m):
            row = level[j]
            row *= s
            row += mul(level[j + 1], t, out=buf)
    if k > 2:                                 # the apex, into out
        row = level[0]
        row *= s
        np.add(row, mul(level[1], t, out=buf), out=out)
    return out


def curve_points(ctrl: np.ndarray, t: np.ndarray) -> np.ndarray:
    """The Bezier curve of ctrl ``(n+1, d)`` at the parameters t (any shape): ``t.shape + (d,)`` (§24.2).

    >>> curve_points(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]), np.array(0.5)).tolist()
    [1.0, 1.0]
    """
    tf = t.reshape(-1)
    out = np.empty((tf.shape[0], ctrl.shape[1]))
    casteljau_apex(ctrl[:, :, None], tf, out=out.T)     # the apex written straight into (N, d)
    return out.reshape(t.shape + (ctrl.shape[1],))


def patch_points(P: np.ndarray, uf: np.ndarray, vf: np.ndarray) -> np.ndarray:
    """The tensor-product patch of the net P ``(m+1, n+1, d)`` at flat parameters uf, vf ``(N,)``:
    de Casteljau in v on every row, then in u on the resulting points (§24.6).  Returns ``(d, N)``."""
    m1, n1, d = P.shape
    rows = P.transpose(1, 0, 2).reshape(n1, m1 * d)[:, :, None]   # (n+1, (m+1)*d, 1)
    along_v = casteljau_apex(rows, vf)                              # ((m+1)*d, N)
    return casteljau_apex(along_v.reshape(m1, d, -1), uf)           # (d, N)


def casteljau_blossom(P: np.ndarray, U: np.ndarray) -> np.ndarray:
    """The blossom of the Bezier curve P ``(n+1, d)`` at N argument sets U ``(N, n)``: the pyramid
    with argument ``U[:, r-1]`` on level r (§26.2).  Returns ``(N, d)``.

    >>> casteljau_blossom(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]), np.array([[0.5, 1.0]])).tolist()
    [[1.5, 1.0]]
    """
    cur = np.broadcast_to(P, (U.shape[0],) + P.shape)
    for r in range(U.shape[1]):
        cur = casteljau_level(cur, U[:, r, None, None], axis=1)
    return cur[:, 0]


def split(P, t, axis: int = 0):
    """de Casteljau subdivision at ``t`` (§25.2): the left piece keeps the first point of every level
    of the pyramid, the right piece the last point of every level (in reverse order).

    P: an array with the control points along ``axis`` (any other axes ride along, and ``t`` may be
    an array broadcasting against them); returns two arrays of P's shape.  Or a sequence of numbers
    (one coordinate of a polygon, the scalar path of curve intersection); returns two tuples.

    >>> split([0.0, 2.0, 4.0], 0.5)
    ((0.0, 1.0, 2.0), (2.0, 3.0, 4.0))
    """
    s = 1.0 - t
    if not isinstance(P, np.ndarray):
        if len(P) == 4:        # cubics and quadratics written out: the same arithmetic as casteljau_level,
            a, b, c, d = P     # about 5x faster on the scalar path of curve intersection
            ab, bc, cd = s * a + t * b, s * b + t * c, s * c + t * d
            abc, bcd = s * ab + t * bc, s * bc + t * cd
            m = s * abc + t * bcd
            return (a, ab, abc, m), (m, bcd, cd, d)
        if len(P) == 3:
            a, b, c = P
            ab, bc = s * a + t * b, s * b + t * c
            m = s * ab + t * bc
            return (a, ab, m), (m, bc, c)
        cur = list(P)
        left, right = [cur[0]], [cur[-1]]
        while len(cur) > 1:
            cur = casteljau_level(cur, t, s)
            left.append(cur[0])
            right.append(cur[-1])
        right.reverse()
        return tuple(left), tuple(right)
    cur = np.moveaxis(P, axis, 0)
    n1 = cur.shape[0]
    left = np.empty_like(cur)
    right = np.empty_like(cur)
    for k in range(n1):
        left[k] = cur[0]
        right[n1 - 1 - k] = cur[-1]
        if k < n1 - 1:
            cur = casteljau_level(cur, t, s)
    return np.moveaxis(left, 0, axis), np.moveaxis(right, 0, axis)


def split_patches(P: np.ndarray, u: float = 0.5, v: float = 0.5) -> np.ndarray:
    """Four-way split of a stack of nets ``(N, m+1, n+1, d)`` at (u, v) (§25.3.2): ``(N, 2, 2, m+1, n+1, d)``."""
    lo, hi = split(P, u, axis=1)
    out = []
    for half in (lo, hi):
        a, b = split(half, v, axis=2)
        out.append(np.stack([a, b], axis=1))
    return np.stack(out, axis=1)


def quarter(nets: np.ndarray, dom: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Split nets ``(N, ...)`` at their middle and their parameter domains ``(N, 4)`` (u0, u1, v0, v1)
    with them (§25.3.2): ``(4N, ...)`` and ``(4N, 4)``."""
    halves = split_patches(nets)
    nets = halves.reshape((-1,) + nets.shape[1:])
    um = (dom[:, 0] + dom[:, 1]) / 2
    vm = (dom[:, 2] + dom[:, 3]) / 2
    kids = []
    for i in (0, 1):
        for j in (0, 1):
            kids.append(np.stack([np.where(i, um, dom[:, 0]), np.where(i, dom[:, 1], um),
                                  np.where(j, vm, dom[:, 2]), np.where(j, dom[:, 3], vm)], axis=1))
    return nets, np.stack(kids, axis=1).reshape(-1, 4)


def split_xy(xs, ys, t):
    """:func:`split` of both coordinates of a planar polygon given as two sequences of numbers, in one
    call (the inner loop of curve intersection, §25.3.1): ``(left_x, right_x, left_y, right_y)``.

    >>> split_xy([0.0, 2.0], [4.0, 0.0], 0.5)
    ((0.0, 1.0), (1.0, 2.0), (4.0, 2.0), (2.0, 0.0))
    """
    if len(xs) == 4:           # cubics and quadratics written out: the same arithmetic as casteljau_level
        s = 1.0 - t
        a, b, c, d = xs
        ab, bc, cd = s * a + t * b, s * b + t * c, s * c + t * d
        abc, bcd = s * ab + t * bc, s * bc + t * cd
        m = s * abc + t * bcd
        e, f, g, h = ys
        ef, fg, gh = s * e + t * f, s * f + t * g, s * g + t * h
        efg, fgh = s * ef + t * fg, s * fg + t * gh
        k = s * efg + t * fgh
        return (a, ab, abc, m), (m, bcd, cd, d), (e, ef, efg, k), (k, fgh, gh, h)
    if len(xs) == 3:           # and quadratics
        s = 1.0 - t
        a, b, c = xs
        ab, bc = s * a + t * b, s * b + t * c
        m = s * ab + t * bc
        e, f, g = ys
        ef, fg = s * e + t * f, s * f + t * g
        k = s * ef + t * fg
        return (a, ab, m), (m, bc, c), (e, ef, k), (k, fg, g)
    lx, rx = split(xs, t)
    ly, ry = split(ys, t)
    return lx, rx, ly, ry


def point_and_tangent(xs, ys, t):
    """The point and derivative at t of the planar Bezier curve with coordinates xs, ys (sequences
    of numbers) from one pyramid (§24.5): the last leg of the pyramid is ``C'(t) / n``.
    Returns ``(x, y, dx, dy)``.

    >>> point_and_tangent([0.0, 1.0, 2.0], [0.0, 2.0, 0.0], 0.5)
    (1.0, 1.0, 2.0, 0.0)
    """
    n = len(xs) - 1
    s = 1.0 - t
    if n == 3:                 # the usual cubic and quadratic written out (casteljau_level's arithmetic)
        x0, x1, x2, x3 = xs
        y0, y1, y2, y3 = ys
        x0, x1, x2 = s * x0 + t * x1, s * x1 + t * x2, s * x2 + t * x3
        y0, y1, y2 = s * y0 + t * y1, s * y1 + t * y2, s * y2 + t * y3
        x0, x1 = s * x0 + t * x1, s * x1 + t * x2
        y0, y1 = s * y0 + t * y1, s * y1 + t * y2
        return s * x0 + t * x1, s * y0 + t * y1, 3 * (x1 - x0), 3 * (y1 - y0)
    if n == 2:
        x0, x1, x2 = xs
        y0, y1, y2 = ys
        x0, x1 = s * x0 + t * x1, s * x1 + t * x2
        y0, y1 = s * y0 + t * y1, s * y1 + t * y2
        return s * x0 + t * x1, s * y0 + t * y1, 2 * (x1 - x0), 2 * (y1 - y0)
    if n == 0:
        return xs[0], ys[0], 0.0, 0.0
    x, y = list(xs), list(ys)
    while len(x) > 2:
        x = casteljau_level(x, t, s)
        y = casteljau_level(y, t, s)
    return s * x[0] + t * x[1], s * y[0] + t * y[1], n * (x[1] - x[0]), n * (y[1] - y[0])


#: Above this degree the binomial coefficients overflow a float; :func:`bernstein_rows` then
#: switches from "binomial times powers" to the (slower, equally stable) recurrence.
POWER_FORM_MAX_DEGREE = 1000


def bernstein_rows(n: int, t: np.ndarray) -> np.ndarray:
    """The Bernstein basis ``B_k^n(t)`` for flat t ``(N,)``, laid out ``(n+1, N)`` (§24.3): binomial
    times powers, or above degree :data:`POWER_FORM_MAX_DEGREE` the recurrence
    ``B_k^j = (1-t) B_k^{j-1} + t B_{k-1}^{j-1}`` (de Casteljau's pyramid run on the unit vectors).

    >>> bernstein_rows(2, np.array([0.5])).ravel().tolist()
    [0.25, 0.5, 0.25]
    """
    N = t.shape[0]
    if n > POWER_FORM_MAX_DEGREE:
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
# de Boor (§27.2-27.5, §28.2)
# --------------------------------------------------------------------------------------------

def domain(t: np.ndarray, p: int) -> tuple[float, float]:
    """The parameter domain ``(t_p, t_{n+1})`` of a B-spline of degree p with knot vector t (§27.2).

    >>> domain(np.array([0.0, 0, 0, 1, 2, 2, 2]), 2)
    (0.0, 2.0)
    """
    return float(t[p]), float(t[t.size - p - 1])


def de_boor_pyramid(rows, weight, levels: int, top: int | None = None, record: list | None = None,
                    per_level: bool = False):
    """de Boor's pyramid in place (Goldman §27.2-27.3): for ``r = 1 .. levels`` and ``j = top .. r``
    (downwards), ``rows[j] <- rows[j-1] + a (rows[j] - rows[j-1])`` with ``a = weight(r, j, q)``
    (q counts the nodes from 0).  rows: a list of arrays, or an array whose rows are points.

    ``top`` defaults to ``levels`` (the local pyramid of one span: rows hold ``P_{k-p} .. P_k``,
    and ``rows[p]`` ends as the apex); the global pyramid (§27.5) passes ``top = n`` with all
    ``n+1`` control points.  record: a list to which a copy of the nodes of each level,
    ``rows[0:]`` then ``rows[r:]``, is appended.  per_level (rows an array): ``weight(r)`` gives the
    weights of the level's nodes ``j = r .. top`` at once, and the level is one array operation
    with the same arithmetic per node (the descending order only protects ``rows[j-1]``, which the
    whole-level form reads before it writes).  Returns ``rows``.

    >>> rows = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]])
    >>> de_boor_pyramid(rows, lambda r, j, q: 0.5, 2)[2].tolist()
    [1.0, 1.0]
    """
    top = levels if top is None else top
    if record is not None:
        record.append(np.array(rows[0:], dtype=float))
    q = 0
    for r in range(1, levels + 1):
        if per_level:
            a = weight(r)[:, None]
            prev = rows[r - 1:top]
            rows[r:top + 1] = prev + a * (rows[r:top + 1] - prev)
            if record is not None:
                record.append(np.array(rows[r:], dtype=float))
            continue
        for j in range(top, r - 1, -1):
            a = weight(r, j, q)
            row, prev = rows[j], rows[j - 1]
            row -= prev
            row *= a
            row += prev
            q += 1
        if record is not None:
            record.append(np.array(rows[r:], dtype=float))
    return rows


# The per-span data of de Boor's pyramid for many parameters (the p+1 control points of each span,
# and the weights a = (u - t_i)/(t_{i+p+1-r} - t_i) = A u + B of every pyramid node) are tabulated
# once, then gathered for each parameter with one column-gather.  Parameters are processed in
# blocks (2048 for a cubic in 3D, whose table has 24 rows; CPU time for 10,000 parameters measured
# best among blocks of 256 to 4096: 798, 551, 484, 440, 432, 416, 573 us): few calls, and the
# gathered rows, on which the pyramid runs in place, stay in the 2 MB L2 cache.
_BLOCK_BYTES = 384 * 1024


def de_boor_tables(P: np.ndarray, t: np.ndarray, p: int):
    """The table of :func:`de_boor_points`, one column per span ``k = p .. n``, ``((p+1) d + 2 m, n+1-p)``:
    first the control points ``P_{k-p} .. P_k`` (row ``j d + c`` is coordinate c of ``P_{k-p+j}``),
    then the weights ``A`` and then ``B``, ``a = A u + B``, of the m pyramid nodes ``(r, j)`` in the
    order :func:`de_boor_pyramid` visits them (level by level, ``j = p .. r`` downwards within a
    level); and the nodes in that order."""
    n, d = P.shape[0] - 1, P.shape[1]
    ks = np.arange(n + 1 - p)                                          # k - p for the spans k = p .. n
    nodes = [(r, j) for r in range(1, p + 1) for j in range(p, r - 1, -1)]    # de_boor_pyramid's order
    m, c = len(nodes), (p + 1) * d
    tab = np.zeros((c + 2 * m, n + 1 - p))
    tab[:c] = P[ks + np.arange(p + 1)[:, None]].transpose(0, 2, 1).reshape(c, n + 1 - p)
    if m:
        r, j = np.array(nodes).T[:, :, None]
        lo = t[ks + j]                                                 # t_i, i = k - p + j: (m, n+1-p)
        den = t[ks + (p + 1) + j - r] - lo                             # t_{i+p+1-r} - t_i
        A = tab[c:c + m]
        np.divide(1.0, den, out=A, where=den > 0)                      # den = 0 only on empty spans
        np.multiply(-lo, A, out=tab[c + m:])
    return tab, nodes


def de_boor_points(P: np.ndarray, t: np.ndarray, p: int, u: np.ndarray, k: np.ndarray) -> np.ndarray:
    """The B-spline curve (ctrl P ``(n+1, d)``, knots t, degree p) at flat u ``(N,)`` in the non-empty
    spans k ``(N,)`` by de Boor's pyramid (§27.3), weights tabulated per span.  Returns ``(d, N)``.

    For a block of parameters the p+1 control points and the weights of every node are gathered
    with one column-gather of :func:`de_boor_tables`, the alphas ``a = A u + B`` of all nodes are
    made in one pass, and :func:`de_boor_pyramid` runs node by node in place on the gathered rows
    ``(d, N)`` (no allocation inside the pyramid: 25% faster than whole levels at a time).

    >>> de_boor_points(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]), np.array([0.0, 0, 0, 1, 1, 1]), 2,
    ...                np.array([0.5]), np.array([2])).ravel().tolist()
    [1.0, 1.0]
    """
    d = P.shape[1]
    tab, nodes = de_boor_tables(P, t, p)
    m, c = len(nodes), (p + 1) * d
    idx = k - p
    out = np.empty((d, u.size))
    block = max(64, _BLOCK_BYTES // (8 * tab.shape[0]))
    for s in range(0, u.size, block):
        ub, ib = u[s:s + block], idx[s:s + block]
        G = np.take(tab, ib, axis=1)
        Q = G[:c].reshape(p + 1, d, ub.size)                            # P_{k-p+j}, j = 0 .. p
        if m:
            a = G[c:c + m] * ub
            a += G[c + m:]                                                  # every node's alpha
            de_boor_pyramid(Q, lambda r, j, q, a=a: a[q], p)                # in place, node by node
        out[:, s:s + block] = Q[p]
    return out


def de_boor_blossom(P: np.ndarray, t: np.ndarray, p: int, spans: np.ndarray, args: np.ndarray) -> np.ndarray:
    """Blossoms ``b_k(args[m, 0], ..., args[m, p-1])`` of the B-spline pieces ``k = spans[m]`` (§27.2, §28.2).

    P ``(n+1, d)``, knots t, degree p; spans ``(N,)`` non-empty spans; args ``(N, p)``.  Returns
    ``(N, d)``.  de Boor's pyramid with a different argument on each level, for all N label sets at
    once: level r combines neighbours with ``a = (u_r - t_i) / (t_{i+p+1-r} - t_i)``, replacing the
    label t_i of P_i (or t_{i+p+1-r}) by ``u_r = args[:, r-1]``.  (:func:`de_boor_points` runs the
    same pyramid on the diagonal ``u_1 = ... = u_p = u`` with its weights tabulated per span.)

    >>> de_boor_blossom(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]), np.array([0.0, 0, 0, 1, 1, 1]), 2,
    ...                 np.array([2]), np.array([[0.5, 1.0]])).tolist()
    [[1.5, 1.0]]
    """
    rows = [P[spans - p + j] for j in range(p + 1)]            # each (N, d), fresh copies

    def weight(r, j, q):
        i = spans - p + j
        lo, hi = t[i][:, None], t[i + p + 1 - r][:, None]
        return (args[:, r - 1][:, None] - lo) / (hi - lo)
    return de_boor_pyramid(rows, weight, p)[p]

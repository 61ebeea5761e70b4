"""Unchecked array kernels under the checked public functions (the ``hazmat`` layer).

Each algorithm that several modules need lives here once, on arrays that are already validated:
no input checking, no copying beyond what the algorithm needs, stacks of problems at once.  The
public functions (``bezier.subdivide``, ``bezier.flatness``, ``bspline.domain``, ...) validate
their input and call these; other library modules call these directly on data they validated.
Views, notebooks and exercise checkers call the public functions only.
"""

from __future__ import annotations

import numpy as np


def norm(v: np.ndarray, axis: int = -1, keepdims: bool = False) -> np.ndarray:
    """Unchecked (``v`` a finite float array): the Euclidean length of ``v`` along ``axis``, right at
    every finite magnitude: the plain ``sqrt(v · v)`` (bit for bit :func:`numpy.linalg.norm`) where ``v · v`` is a normal float, and
    ``m sqrt((v/m) · (v/m))`` with ``m = max |v_i|`` where it overflows or underflows (entries over
    about 1e154 or under 1e-154), so a vector of length 1e300 has length 1e300, not inf.

    >>> float(norm(np.array([3 * 2.0 ** 900, 4 * 2.0 ** 900]))) == 5 * 2.0 ** 900
    True
    >>> float(norm(np.array([3e-200, 4e-200])))
    5e-200
    """
    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        out = np.linalg.norm(v, axis=axis, keepdims=keepdims)
        tiny = np.finfo(float).tiny ** 0.5
        redo = ~np.isfinite(out) | (out < tiny)
        if not np.any(redo & np.any(v != 0, axis=axis, keepdims=keepdims)):
            return out
        m = np.max(np.abs(v), axis=axis, keepdims=True)
        safe = np.ldexp(1.0, np.frexp(np.where(m > 0, m, 1.0))[1] - 1)  # a power of two <= m: exact scaling
        scaled = np.linalg.norm(v / safe, axis=axis, keepdims=True) * safe
        if not keepdims:
            scaled = np.squeeze(scaled, axis=axis)
        return np.where(redo, scaled, out)


def number(x) -> str:
    """A number in error messages and status lines: six significant digits (``0.333333``, ``1e-07``)."""
    return f"{float(x):.6g}"


def domain(t: np.ndarray, p: int) -> tuple[float, float]:
    """The parameter domain ``(t_p, t_{n+1})`` of a B-spline of degree p with knot vector t (§27.2)."""
    return float(t[p]), float(t[t.size - p - 1])


def split(P: np.ndarray, t, axis: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """de Casteljau subdivision at ``t`` of control points along ``axis`` (Goldman §25.2).

    The left piece keeps the first point of every level of the pyramid, the right piece the
    last point of every level (in reverse order).  Works on stacks: any other axes ride along,
    and ``t`` may be a scalar or an array broadcasting against them.
    """
    cur = np.moveaxis(P, axis, 0)
    n1 = cur.shape[0]
    left = np.empty_like(cur)
    right = np.empty_like(cur)
    s = 1.0 - t
    for k in range(n1):
        left[k] = cur[0]
        right[n1 - 1 - k] = cur[-1]
        if k < n1 - 1:
            cur = s * cur[:-1] + t * cur[1:]
    return np.moveaxis(left, 0, axis), np.moveaxis(right, 0, axis)


def flatness(P: np.ndarray, even: bool = True) -> np.ndarray:
    """Flatness of a stack of polygons (..., n+1, d); returns (...,) (Goldman §25.3).

    ``even=True``: ``max_k |P_k - L_k|`` with ``L_k = (1 - k/n) P_0 + (k/n) P_n`` evenly spaced on
    the chord.  ``even=False``: the largest distance of a control point from the chord segment.
    """
    n = P.shape[-2] - 1
    if n <= 0:
        return np.zeros(P.shape[:-2])
    a = P[..., :1, :]
    b = P[..., -1:, :]
    if even:
        w = (np.arange(n + 1) / n)[:, None]
        return np.linalg.norm(P - ((1.0 - w) * a + w * b), axis=-1).max(axis=-1)
    chord = b - a
    length2 = (chord ** 2).sum(-1, keepdims=True)
    safe = np.where(length2 > 0, length2, 1.0)
    along = np.clip(((P - a) * chord).sum(-1, keepdims=True) / safe, 0.0, 1.0)
    return np.linalg.norm(P - (a + along * chord), axis=-1).max(axis=-1)


def blossom(P: np.ndarray, t: np.ndarray, p: int, spans: np.ndarray, args: np.ndarray) -> np.ndarray:
    """Blossoms ``b_k(args[m, 0], ..., args[m, p-1])`` of the B-spline pieces ``k = spans[m]`` (§27.2, §28.2).

    P (n+1, d), knots t, degree p; spans (N,) non-empty spans; args (N, p).  Returns (N, d).
    de Boor's pyramid with a different argument on each level, for all N label sets at once:
    level r combines neighbours with ``alpha = (u_r - t_i) / (t_{i+p+1-r} - t_i)``, replacing the
    label t_i of P_i (or t_{i+p+1-r}) by ``u_r = args[:, r-1]``.  (``bspline.de_boor`` runs the
    same pyramid on the diagonal ``u_1 = ... = u_p = u`` with its weights tabulated per span.)
    """
    rows = [P[spans - p + j] for j in range(p + 1)]            # each (N, d)
    for r in range(1, p + 1):
        x = args[:, r - 1][:, None]
        for j in range(p, r - 1, -1):
            i = spans - p + j
            lo, hi = t[i][:, None], t[i + p + 1 - r][:, None]
            alpha = (x - lo) / (hi - lo)
            rows[j] = rows[j - 1] + alpha * (rows[j] - rows[j - 1])
    return rows[p]


def iterate_maps(X: np.ndarray, M: np.ndarray, levels: int) -> np.ndarray:
    """The deterministic algorithm on homogeneous rows (Goldman §6.1, §29.3-29.4): every matrix of
    the stack M (k, D, D) applied to every row of X (m, D), ``levels`` times.  Returns
    ``(m k^levels, D)`` in blocks of m rows; block ``i_L ... i_1`` read in base k is
    ``X @ M_{i_1} @ ... @ M_{i_L}``."""
    for _ in range(levels):
        X = np.matmul(X[None], M).reshape(-1, M.shape[-1])
    return X

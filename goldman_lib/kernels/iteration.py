"""Iterated function systems: every map applied to every point (Goldman §6.1, §6.3, §29.3-29.4), unchecked.

:func:`apply_affine_maps` applies k affine maps, given as linear parts and translations, to m
points; :func:`apply_maps` applies k matrices to m homogeneous (or barycentric) rows;
:func:`iterate_maps` repeats :func:`apply_maps` (the deterministic algorithm in any dimension).
Results come in blocks of m rows, one block per map.  :func:`choose` draws the random algorithm's
map choices and :func:`chaos_steps` moves its chains (the chaos game, §6.3).  Nothing here checks
its input.
"""

from __future__ import annotations

import numpy as np

__all__ = ["apply_affine_maps", "apply_maps", "iterate_maps", "choose", "chaos_steps"]


def apply_affine_maps(pts: np.ndarray, L: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Every affine map ``x -> x L_i + t_i`` applied to every point (row-vector convention, §6.1):
    pts ``(m, d)``, L ``(k, d, d)``, t ``(k, d)``; returns ``(k m, d)`` in blocks of m per map.

    Written out per coordinate (``x' = x a + y c + e``, ``y' = x b + y d + f`` in the plane) into one
    output array, in that order: the arithmetic of ``pts @ L[i] + t[i]`` (to the last bit where
    matmul does not fuse a multiply-add), about 6x faster than numpy's batched matmul, whose 2x2
    inner products do not vectorise.

    >>> apply_affine_maps(np.array([[1.0, 0.0]]), np.array([np.eye(2) / 2]), np.array([[0.5, 0.0]])).tolist()
    [[1.0, 0.0]]
    """
    k, n = len(L), len(pts)
    d = pts.shape[1]
    out = np.empty((k, n, d))
    tmp = np.empty(n)
    for i in range(k):
        for j in range(d):
            col = out[i, :, j]
            np.multiply(pts[:, 0], L[i, 0, j], out=col)
            for c in range(1, d):
                col += np.multiply(pts[:, c], L[i, c, j], out=tmp)
            col += t[i, j]
    return out.reshape(-1, d)


def apply_maps(X: np.ndarray, M: np.ndarray) -> np.ndarray:
    """Every matrix of the stack M ``(k, D, D)`` applied to every row of X ``(m, D)`` (``X @ M_i``,
    §29.3): ``(k m, D)`` in blocks of m rows.

    >>> apply_maps(np.array([[1.0, 2.0]]), np.array([np.eye(2), 2 * np.eye(2)])).tolist()
    [[1.0, 2.0], [2.0, 4.0]]
    """
    return np.matmul(X[None], M).reshape(-1, M.shape[-1])


def iterate_maps(X: np.ndarray, M: np.ndarray, levels: int) -> np.ndarray:
    """The deterministic algorithm on homogeneous rows (Goldman §6.1, §29.3-29.4): every matrix of
    the stack M ``(k, D, D)`` applied to every row of X ``(m, D)``, ``levels`` times.  Returns
    ``(m k^levels, D)`` in blocks of m rows; block ``i_L ... i_1`` read in base k is
    ``X @ M_{i_1} @ ... @ M_{i_L}``.

    >>> iterate_maps(np.array([[1.0, 1.0]]), np.array([[[0.5, 0], [0, 1]], [[0.5, 0], [0.5, 1]]]), 1).tolist()
    [[0.5, 1.0], [1.0, 1.0]]
    """
    for _ in range(levels):
        X = apply_maps(X, M)
    return X


def choose(gen: np.random.Generator, p: np.ndarray, shape) -> np.ndarray:
    """Indices ``0 .. len(p)-1`` drawn with probabilities p, an intp array of the given shape: the
    same numbers from the same draws as ``gen.choice(len(p), size=shape, p=p)`` (numpy draws
    ``u = gen.random(shape)`` and counts the cumulative probabilities ``cdf <= u`` with a binary
    search; counting them with one comparison per map is about 3x faster for a few maps).

    >>> choose(np.random.default_rng(0), np.array([0.25, 0.75]), 5).tolist()
    [1, 1, 0, 0, 1]
    """
    cdf = np.cumsum(p)
    cdf /= cdf[-1]
    u = gen.random(shape)
    idx = np.zeros(u.shape, np.intp)
    for c in cdf[:-1]:            # u < 1 = cdf[-1]: the last entry never counts
        idx += u >= c
    return idx


def chaos_steps(coef: np.ndarray, idx: np.ndarray, start, burn_in: int, out: np.ndarray,
                jump_to: np.ndarray | None = None) -> np.ndarray:
    """The chaos game's chains (Goldman §6.3): at step s chain j moves by map ``i = idx[s, j]``,
    ``x' = x a_i + y c_i + e_i``, ``y' = x b_i + y d_i + f_i`` (``(x, y, 1) @ M_i``, in that order).

    coef ``(6, k)``: the rows ``a, c, e, b, d, f`` of the k maps.  idx ``(S, chains)`` intp.
    start ``(2,)``: every chain's first point.  out ``(S - burn_in, chains, 2)``: receives the points
    after steps ``burn_in .. S-1`` (the first ``burn_in`` are discarded).  jump_to ``(S, chains, 2)``
    or None: where ``idx == k - 1`` the point jumps there instead (the condensation "map" of §6.4,
    whose coefficients are zero).  Every chain moves at once, x and y apart (structure of arrays),
    into buffers made once; the step writes straight into out.  Returns out.

    >>> coef = np.array([[0.5], [0.0], [0.0], [0.0], [0.5], [0.5]])    # one map: x/2, (y + 1)/2
    >>> chaos_steps(coef, np.zeros((2, 1), np.intp), [0.0, 0.0], 1, np.empty((1, 1, 2))).tolist()
    [[[0.0, 0.75]]]
    """
    chains = idx.shape[1]
    k = coef.shape[1]
    x, y = np.full(chains, float(start[0])), np.full(chains, float(start[1]))
    X, Y, tmp = np.empty(chains), np.empty(chains), np.empty(chains)
    G = np.empty((6, chains))
    with np.errstate(over="ignore", invalid="ignore"):
        for s in range(idx.shape[0]):
            i = idx[s]
            np.take(coef, i, axis=1, out=G)
            np.multiply(x, G[0], out=X)
            X += np.multiply(y, G[1], out=tmp)
            X += G[2]
            np.multiply(x, G[3], out=Y)
            Y += np.multiply(y, G[4], out=tmp)
            Y += G[5]
            if jump_to is not None:
                jump = i == k - 1
                np.copyto(X, jump_to[s, :, 0], where=jump)
                np.copyto(Y, jump_to[s, :, 1], where=jump)
            x, X = X, x
            y, Y = Y, y
            if s >= burn_in:
                out[s - burn_in, :, 0] = x
                out[s - burn_in, :, 1] = y
    return out

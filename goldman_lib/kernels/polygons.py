"""Polygons: control polygons measured and rewritten (Goldman §24.4-24.5, §25.3), unchecked.

:func:`flatness` and :func:`patch_flatness` (how far a polygon or net is from its chord or its
bilinear corners, §25.3), :func:`signed_distances` and :func:`sign_changes` (the variation count
of §24.4), :func:`elevate` (degree elevation, §24.5).  Nothing here checks its input.
"""

from __future__ import annotations

import numpy as np

__all__ = ["flatness", "patch_flatness", "signed_distances", "sign_changes", "elevate"]


def flatness(P: np.ndarray, even: bool = True) -> np.ndarray:
    """Flatness of a stack of polygons ``(..., n+1, d)``; returns ``(...)`` (Goldman §25.3).

    ``even=True``: ``max_k |P_k - L_k|`` with ``L_k = (1 - k/n) P_0 + (k/n) P_n`` evenly spaced on
    the chord.  ``even=False``: the largest distance of a control point from the chord segment.

    >>> float(flatness(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]])))
    2.0
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


def patch_flatness(P: np.ndarray) -> np.ndarray:
    """Flatness of a stack of nets ``(N, m+1, n+1, d)``: ``(N,)`` (Goldman §25.3.2): the largest
    distance of a control point from the bilinear patch of the corners, plus a quarter of the twist.

    >>> patch_flatness(np.array([[[[0.0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]])).tolist()
    [0.0]
    """
    m, n = P.shape[1] - 1, P.shape[2] - 1
    u = (np.arange(m + 1) / max(m, 1))[:, None, None]
    v = (np.arange(n + 1) / max(n, 1))[None, :, None]
    c00, c01 = P[:, :1, :1], P[:, :1, -1:]
    c10, c11 = P[:, -1:, :1], P[:, -1:, -1:]
    bilinear = (1 - u) * (1 - v) * c00 + (1 - u) * v * c01 + u * (1 - v) * c10 + u * v * c11
    off = np.linalg.norm(P - bilinear, axis=-1).max(axis=(1, 2))
    twist = np.linalg.norm((c00 - c01 - c10 + c11)[:, 0, 0], axis=-1)
    return off + twist / 4


def signed_distances(points: np.ndarray, p: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """Signed distances of points ``(..., d)`` from the hyperplane through p with the nonzero
    normal ``normal`` (§24.4): ``(points - p) . normal / |normal|``.

    >>> signed_distances(np.array([[0.0, 2.0], [1.0, -1.0]]), np.zeros(2), np.array([0.0, 2.0])).tolist()
    [2.0, -1.0]
    """
    return (points - p) @ (normal / np.linalg.norm(normal))


def sign_changes(s: np.ndarray, tol: float) -> int:
    """How often the sequence s changes sign, entries within tol of 0 skipped (§24.4).

    >>> sign_changes(np.array([1.0, 0.0, -2.0, 3.0]), 1e-12)
    2
    """
    signs = np.sign(s[np.abs(s) > tol])
    return int(np.count_nonzero(signs[1:] != signs[:-1]))


def elevate(P: np.ndarray, times: int) -> np.ndarray:
    """The Bezier control points ``(n+1+times, d)`` of the curve of P ``(n+1, d)`` written with degree
    ``n + times`` (§24.5): ``Q_k = k/(n+1) P_{k-1} + (1 - k/(n+1)) P_k`` once per elevation.
    Returns P itself for ``times = 0``.

    >>> elevate(np.array([[0.0], [3.0]]), 1).ravel().tolist()
    [0.0, 1.5, 3.0]
    """
    for _ in range(times):
        n1 = P.shape[0]  # n + 1
        a = (np.arange(1, n1) / n1)[:, None]
        Q = np.empty((n1 + 1, P.shape[1]))
        Q[0], Q[-1] = P[0], P[-1]
        Q[1:-1] = a * P[:-1] + (1.0 - a) * P[1:]
        P = Q
    return P

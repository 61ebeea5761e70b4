"""Polygons: control polygons measured and rewritten (Goldman §24.4-24.5, §25.3), unchecked.

:func:`flatness` and :func:`patch_flatness` (how far a polygon or net is from its chord or its
bilinear corners, §25.3), :func:`signed_distances` and :func:`sign_changes` (the variation count
of §24.4), :func:`elevate` (degree elevation, §24.5); :func:`ear_clip` triangulates a simple polygon
(``simple_surfaces.Polygon.mesh``, §19.3) and :func:`clip_half_space` cuts a polygon at a plane
(``camera.Camera.clip_polygon``, §22.1).  Nothing here checks its input.
"""

from __future__ import annotations

import numpy as np

__all__ = ["flatness", "patch_flatness", "signed_distances", "sign_changes", "elevate", "ear_clip", "clip_half_space", "clip_to_view"]


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


def ear_clip(uv: np.ndarray) -> np.ndarray:
    """Triangles ``(k - 2, 3)`` of indices into a simple counterclockwise polygon uv ``(k, 2)`` by ear
    clipping (our way of drawing the polygons of Goldman §19.3): cut off a convex corner with no other
    vertex inside, repeat; what is left (convex or degenerate) becomes a fan.

    >>> ear_clip(np.array([[0.0, 0], [2, 0], [2, 2], [1, 1], [0, 2]])).tolist()
    [[1, 2, 3], [0, 1, 3], [0, 3, 4]]
    """
    idx = list(range(len(uv)))
    tris = []
    guard = 0
    while len(idx) > 3 and guard < 10 * len(uv) ** 2:
        guard += 1
        for k in range(len(idx)):
            i, j, m = idx[k - 1], idx[k], idx[(k + 1) % len(idx)]
            a, b, c = uv[i], uv[j], uv[m]
            if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 0:
                continue                                             # a reflex (or flat) corner is no ear
            others = uv[[p for p in idx if p not in (i, j, m)]]
            if len(others):
                s1 = (b[0] - a[0]) * (others[:, 1] - a[1]) - (b[1] - a[1]) * (others[:, 0] - a[0])
                s2 = (c[0] - b[0]) * (others[:, 1] - b[1]) - (c[1] - b[1]) * (others[:, 0] - b[0])
                s3 = (a[0] - c[0]) * (others[:, 1] - c[1]) - (a[1] - c[1]) * (others[:, 0] - c[0])
                if np.any((s1 >= 0) & (s2 >= 0) & (s3 >= 0)):
                    continue                                         # another vertex inside: no ear
            tris.append([i, j, m])
            idx.pop(k)
            break
        else:
            break
    while len(idx) >= 3:                                             # what is left (convex or degenerate): a fan
        tris.append([idx[0], idx[1], idx[2]])
        idx.pop(1)
    return np.array(tris, dtype=np.int64)


def clip_half_space(P: np.ndarray, s: np.ndarray):
    """Sutherland and Hodgman's clipping against one plane (Goldman §22.1's near plane): the
    part of polygon P ``(k, 3)`` where the signed distance s ``(k,)`` is >= 0, or None if it has no
    area.  A polygon wholly on the kept side is returned as is (the same array), so a scene the
    plane does not cut is drawn bit for bit as before.  :meth:`goldman_lib.camera.Camera.clip_polygon`
    runs it on checked polygons (the near plane and the guard band).

    >>> clip_half_space(np.array([[0.0, -1, 0], [1, 3, 0], [-1, 3, 0]]), np.array([-2.0, 2.0, 2.0])).tolist()
    [[0.5, 1.0, 0.0], [1.0, 3.0, 0.0], [-1.0, 3.0, 0.0], [-0.5, 1.0, 0.0]]
    """
    if np.all(s >= 0):
        return P
    if not np.any(s > 0):
        return None
    out = []
    k = len(P)
    for i in range(k):
        a, b, sa, sb = P[i], P[(i + 1) % k], s[i], s[(i + 1) % k]
        if sa >= 0:
            out.append(a)
        if (sa > 0 and sb < 0) or (sa < 0 and sb > 0):
            out.append(a + (sa / (sa - sb)) * (b - a))
    if len(out) < 3:
        return None
    return np.array(out)


def clip_to_view(P: np.ndarray, eye, view, right, up, near: float, slopes=None):
    """The part of polygon P ``(k, 3)`` at or beyond the near plane of a camera (distance ``near``
    along the unit ``view`` direction from ``eye``), and, if ``slopes = (tx, ty)`` is given, inside the
    frustum ``|x| <= tx w``, ``|y| <= ty w`` (x, y along ``right``, ``up``; w along ``view``): repeated
    :func:`clip_half_space` (Goldman §22.1).  None if nothing is left.
    :meth:`goldman_lib.camera.Camera.clip_polygon` checks its input and calls this;
    :mod:`goldman_lib.hidden_surfaces` calls it on polygons it has checked.

    >>> E, n, r, u = np.zeros(3), np.array([0.0, 1, 0]), np.array([1.0, 0, 0]), np.array([0.0, 0, 1])
    >>> clip_to_view(np.array([[0.0, -1, 0], [1, 3, 0], [-1, 3, 0]]), E, n, r, u, 1.0).tolist()
    [[0.5, 1.0, 0.0], [1.0, 3.0, 0.0], [-1.0, 3.0, 0.0], [-0.5, 1.0, 0.0]]
    """
    C = clip_half_space(P, (P - eye) @ view - near)
    if C is None or slopes is None:
        return C
    tx, ty = slopes
    for normal in (tx * view - right, tx * view + right, ty * view - up, ty * view + up):
        C = clip_half_space(C, (C - eye) @ normal)
        if C is None:
            return None
    return C

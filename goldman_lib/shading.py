"""Shading polygonal models (Goldman chapter 21): normals of polygons and meshes.

The normal of a polygon by Newell's formula (§21.2) and area-weighted face and vertex normals of a
triangle mesh, used by every 3D view.  How light meets a surface is :mod:`goldman_lib.lighting`.

>>> newell_normal([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]).tolist()
[0.0, 0.0, 1.0]
"""

from __future__ import annotations

import numpy as np

from goldman_lib.validation import as_float, as_float_array, as_int, as_points, check_finite, finite_result

__all__ = ["newell_normal", "face_normals", "vertex_normals"]


def newell_normal(polygon) -> np.ndarray:
    """The unit normal of a (possibly non-planar) polygon by Newell's formula.

    ``N_x = sum (y_i - y_j)(z_i + z_j)`` and cyclically, j = i+1: twice the area vector of the
    polygon, robust for nearly collinear vertices.  polygon: (k, 3), k >= 3.  Returns (3,); zeros
    for a degenerate polygon.

    >>> newell_normal([[0, 0, 0], [0, 0, 1], [0, 1, 0]]).tolist()
    [-1.0, 0.0, 0.0]
    """
    P = as_points(polygon, "polygon", dim=3, min_count=3)
    Q = np.roll(P, -1, axis=0)
    with np.errstate(over="ignore", invalid="ignore"):
        n = finite_result(np.array([((P[:, 1] - Q[:, 1]) * (P[:, 2] + Q[:, 2])).sum(),
                  ((P[:, 2] - Q[:, 2]) * (P[:, 0] + Q[:, 0])).sum(),
                  ((P[:, 0] - Q[:, 0]) * (P[:, 1] + Q[:, 1])).sum()]), "polygon")
        length = finite_result(np.linalg.norm(n), "polygon")
    return n / length if length > 0 else n


def _mesh(positions, triangles) -> tuple[np.ndarray, np.ndarray]:
    """Validated vertex positions (n, 3) and triangle indices (m, 3) below n."""
    V = as_points(positions, "positions", dim=3)
    T = as_float_array(triangles, "triangles")
    if T.ndim != 2 or T.shape[1] != 3:
        raise ValueError(f"triangles must have shape (m, 3); got shape {T.shape}")
    check_finite(T, "triangles")
    if np.any(T != np.round(T)) or (T.size and T.min() < 0):
        raise ValueError("triangles must hold non-negative integer vertex indices")
    if T.size and T.max() >= len(V):
        raise ValueError(f"positions must hold every vertex the triangles index: {len(V)} positions, "
                         f"but triangles index vertex {int(T.max())}")
    return V, T.astype(np.intp)


def face_normals(positions, triangles) -> np.ndarray:
    """Area-weighted normals ``(b - a) x (c - a)`` of triangles (not normalised): (m, 3).

    >>> face_normals([[0, 0, 0], [2, 0, 0], [0, 1, 0]], [[0, 1, 2]]).tolist()
    [[0.0, 0.0, 2.0]]
    """
    V, T = _mesh(positions, triangles)
    tris = V[T]
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    return finite_result(out, "positions", why="are too large in magnitude")


def vertex_normals(positions, triangles) -> np.ndarray:
    """Unit vertex normals: area-weighted sums of the face normals around each vertex ((0, 0, 1)
    for a vertex on no face of positive area).

    >>> vertex_normals(np.array([[0., 0, 0], [1, 0, 0], [0, 1, 0]]), np.array([[0, 1, 2]])).tolist()
    [[0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0]]
    """
    V, T = _mesh(positions, triangles)
    fn = face_normals(V, T)
    n = np.zeros_like(V)
    for k in range(3):
        np.add.at(n, T[:, k], fn)
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return np.divide(n, length, out=np.zeros_like(n) + [0.0, 0.0, 1.0], where=length > 1e-300)

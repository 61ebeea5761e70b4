"""Normals and flat shading for drawing meshes and patches (used by the 3D views).

The mathematics the views need to light a surface, in one tested place: the normal of a polygon
by Newell's formula, area-weighted face and vertex normals of a triangle mesh, a light direction
from azimuth and elevation (degrees), and an ambient + diffuse shade.  The diffuse term is the
cosine ``n . l`` rescaled to [0, 1] over the faces drawn (the hill-shading of matplotlib's
``LightSource.shade_normals``, so faces turned away keep some contrast), then
``colour * (ambient + diffuse * intensity)``.

>>> newell_normal([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]).tolist()
[0.0, 0.0, 1.0]
"""

from __future__ import annotations

import numpy as np

from goldman_lib.validation import as_float, as_float_array, as_int, as_points, check_finite, finite_result

__all__ = ["newell_normal", "face_normals", "vertex_normals", "light_direction", "diffuse", "shade"]


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


def light_direction(azimuth=315.0, elevation=45.0) -> np.ndarray:
    """The unit vector towards a light at ``azimuth`` degrees (clockwise from north, the y axis)
    and ``elevation`` degrees above the xy plane.

    >>> light_direction(0, 90).round(12).tolist()
    [0.0, 0.0, 1.0]
    """
    az = np.radians(90 - as_float(azimuth, "azimuth"))
    alt = np.radians(as_float(elevation, "elevation"))
    return np.array([np.cos(az) * np.cos(alt), np.sin(az) * np.cos(alt), np.sin(alt)])


def diffuse(normals, direction=None, fraction=0.9) -> np.ndarray:
    """The diffuse (Lambert) term ``n . l`` of each normal, scaled by ``fraction`` and rescaled to
    [0, 1] over all the normals given when they differ (hill shading), clipped to [0, 1].

    >>> diffuse([[0, 0, 1], [0, 0, -1], [1, 0, 0]], [0, 0, 1], fraction=1.0).tolist()
    [1.0, 0.0, 0.5]
    """
    N = as_points(normals, "normals", ndim=None, dim=3)
    L = light_direction() if direction is None else as_points(direction, "direction", ndim=1, dim=3)
    fraction = as_float(fraction, "fraction")
    with np.errstate(over="ignore", invalid="ignore"):
        intensity = finite_result(N @ L, "normals and direction", why="are too large in magnitude")
    imin, imax = intensity.min(), intensity.max()
    intensity *= fraction
    if (imax - imin) > 1e-6:
        intensity -= imin
        intensity /= (imax - imin)
    return np.clip(intensity, 0, 1)


def shade(colour, intensity, ambient=0.45, diffuse_weight=0.55) -> np.ndarray:
    """Face colours ``colour * (ambient + diffuse_weight * intensity)``, clipped to [0, 1]: (m, 3).

    >>> shade([1.0, 0.5, 0.0], [0.0, 1.0]).tolist()
    [[0.45, 0.225, 0.0], [1.0, 0.5, 0.0]]
    """
    base = as_points(colour, "colour", ndim=1, dim=3)
    level = check_finite(as_float_array(intensity, "intensity"), "intensity")
    if level.ndim != 1:
        raise ValueError(f"intensity must be one value per face, shape (m,); got shape {level.shape}")
    a, w = as_float(ambient, "ambient"), as_float(diffuse_weight, "diffuse_weight")
    with np.errstate(over="ignore", invalid="ignore"):
        out = base[None] * (a + w * level[:, None])
    return np.clip(finite_result(out, "intensity", why="with these weights is too large in magnitude"), 0, 1)

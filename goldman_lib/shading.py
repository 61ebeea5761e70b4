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

from goldman_lib.validation import as_float, as_points

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
    n = np.array([((P[:, 1] - Q[:, 1]) * (P[:, 2] + Q[:, 2])).sum(),
                  ((P[:, 2] - Q[:, 2]) * (P[:, 0] + Q[:, 0])).sum(),
                  ((P[:, 0] - Q[:, 0]) * (P[:, 1] + Q[:, 1])).sum()])
    length = np.linalg.norm(n)
    return n / length if length > 0 else n


def face_normals(positions, triangles) -> np.ndarray:
    """Area-weighted normals ``(b - a) x (c - a)`` of triangles (not normalised): (m, 3).

    >>> face_normals([[0, 0, 0], [2, 0, 0], [0, 1, 0]], [[0, 1, 2]]).tolist()
    [[0.0, 0.0, 2.0]]
    """
    V = np.asarray(positions, dtype=float)
    tris = V[np.asarray(triangles, dtype=int)]
    return np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])


def vertex_normals(positions, triangles) -> np.ndarray:
    """Unit vertex normals: area-weighted sums of the face normals around each vertex ((0, 0, 1)
    for a vertex on no face of positive area).

    >>> vertex_normals(np.array([[0., 0, 0], [1, 0, 0], [0, 1, 0]]), np.array([[0, 1, 2]])).tolist()
    [[0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0]]
    """
    V = np.asarray(positions, dtype=float)
    T = np.asarray(triangles, dtype=int)
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
    N = np.asarray(normals, dtype=float)
    L = light_direction() if direction is None else np.asarray(direction, dtype=float)
    intensity = N.dot(L)
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
    base = np.asarray(colour, dtype=float)
    return np.clip(base[None] * (ambient + diffuse_weight * np.asarray(intensity, dtype=float)[:, None]), 0, 1)

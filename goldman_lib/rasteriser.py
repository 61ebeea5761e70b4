"""The rasteriser (Goldman §21.2-21.4, §22.1-22.3): triangles in screen coordinates become pixels.

The pipeline of Part III, stage by stage: :class:`goldman_lib.camera.Camera` projects vertices to
screen coordinates and depths (and clips polygons at its near plane,
:meth:`~goldman_lib.camera.Camera.clip_polygon`); :func:`rasterise_triangles` scan-converts every triangle by
barycentric coverage of the pixel centres in its bounding box, vectorised over batches of triangles,
and keeps the nearest fragment per pixel in a depth buffer (:class:`Fragments`); the shading modes of
:func:`goldman_lib.shading.render` (chapter 21) and the z-buffer of
:mod:`goldman_lib.hidden_surfaces` (chapter 22) read the fragments.  :func:`gouraud_triangle` shades
one triangle from its vertex intensities (§21.3).  The scan conversion itself is the unchecked kernel
:func:`goldman_lib.kernels.meshes.rasterise`; this module checks what it is given.

>>> f = rasterise_triangles([[0, 0, 0.5], [2, 0, 0.5], [0, 2, 0.5]], [[0, 1, 2]], 2, 2)
>>> f.triangle.tolist()
[[0, 0], [0, -1]]
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from goldman_lib.camera import image_size
from goldman_lib.kernels import meshes
from goldman_lib.validation import MAX_ITEMS, as_float_array, as_points, check_finite, finite_result

__all__ = ["triangle_mesh", "Fragments", "rasterise_triangles", "gouraud_triangle"]


def triangle_mesh(positions, triangles, name: str = "positions") -> tuple[np.ndarray, np.ndarray]:
    """A checked triangle mesh (Goldman §21.1): vertex positions ``(n, 3)`` as floats and triangles
    ``(m, 3)`` as integer indices below n.  Raises ValueError naming ``name`` or ``triangles``.

    >>> V, T = triangle_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]); T.dtype == np.intp
    True
    """
    V = as_points(positions, name, dim=3)
    T = as_float_array(triangles, "triangles")
    if T.ndim != 2 or T.shape[1] != 3:
        raise ValueError(f"triangles must have shape (m, 3); got shape {T.shape}")
    check_finite(T, "triangles")
    if np.any(T != np.round(T)) or (T.size and T.min() < 0):
        raise ValueError("triangles must hold non-negative integer vertex indices")
    if T.size and T.max() >= len(V):
        raise ValueError(f"{name} must hold every vertex the triangles index: {len(V)} {name}, "
                         f"but triangles index vertex {int(T.max())}")
    return V, T.astype(np.intp)


# -- the scan conversion: one home for chapters 21 and 22 ------------------------------------------

class Fragments(NamedTuple):
    """What :func:`rasterise_triangles` leaves in each pixel: ``triangle`` (h, w) the index of the
    nearest triangle covering the pixel centre (-1 for none), ``depth`` (h, w) its depth (1.0, the
    far value, for none) and ``weights`` (h, w, 3) the pixel centre's screen-space barycentric
    coordinates in that triangle (zeros for none)."""

    triangle: np.ndarray
    depth: np.ndarray
    weights: np.ndarray


def rasterise_triangles(screen, triangles, width: int, height: int) -> Fragments:
    """Scan-convert triangles with a depth buffer (Goldman §21.2-21.4, §22.3): the one scan
    conversion of the course, used by :func:`goldman_lib.shading.render` and by chapter 22's z-buffer.

    screen: (n, 3) vertices in screen coordinates ``(x, y, z)`` -- x, y in pixels (pixel (i, j) is
    centred at ``(j + 0.5, i + 0.5)``), z the depth (smaller is nearer), as
    :meth:`goldman_lib.camera.Camera.project`
    gives.  triangles: (m, 3) vertex indices.  A pixel belongs to a triangle when its centre lies
    inside or on its boundary (barycentric coordinates >= 0, tested over the triangle's bounding box,
    vectorised over batches of triangles); fragments with z outside [0, 1) are clipped (the near
    and far planes) and zero-area (edge-on) triangles draw nothing.  Of the fragments in a pixel the
    nearest is kept, and of equally near ones the first triangle's.  Returns :class:`Fragments`.

    >>> f = rasterise_triangles([[0, 0, 0.5], [4, 0, 0.5], [0, 4, 0.5]], [[0, 1, 2]], 4, 4)
    >>> (f.triangle + 1).tolist()
    [[1, 1, 1, 1], [1, 1, 1, 0], [1, 1, 0, 0], [1, 0, 0, 0]]
    """
    width, height = image_size(width, height)
    S, T = triangle_mesh(screen, triangles, "screen")
    if len(T) > MAX_ITEMS:
        raise ValueError(f"triangles must hold at most {MAX_ITEMS:,} triangles; got {len(T):,}")
    if np.abs(S[:, :2]).max() > 1e9:
        raise ValueError("screen must hold pixel coordinates within 1e9 of the image")
    return Fragments(*meshes.rasterise(S, T, width, height))


def gouraud_triangle(screen, intensities, width: int, height: int) -> np.ndarray:
    """Gouraud shading of one triangle in screen coordinates (Goldman §21.3): the intensities given at
    its three vertices, interpolated linearly (by the screen barycentric coordinates of each pixel
    centre) at every pixel the triangle covers, 0 elsewhere.  A pixel whose centre lies on an edge
    is covered; a degenerate (zero-area) triangle covers nothing.  Scan conversion by
    :func:`rasterise_triangles`.

    screen: (3, 2) vertex pixel coordinates (x right, y down; pixel (i, j) centred at (j + 0.5, i + 0.5)).
    intensities: (3,).  Returns (height, width).

    >>> gouraud_triangle([[0, 0], [4, 0], [0, 4]], [0.0, 1.0, 0.5], 4, 2).round(3).tolist()
    [[0.188, 0.438, 0.688, 0.938], [0.312, 0.562, 0.812, 0.0]]
    """
    P = as_points(screen, "screen", dim=2)
    if P.shape != (3, 2):
        raise ValueError(f"screen must hold the three vertices of one triangle, shape (3, 2); got {P.shape}")
    c = check_finite(as_float_array(intensities, "intensities"), "intensities")
    if c.shape != (3,):
        raise ValueError(f"intensities must be three numbers, one per vertex; got shape {c.shape}")
    width, height = image_size(width, height)
    if np.abs(P).max() > 1e9:
        raise ValueError("screen must hold pixel coordinates within 1e9 of the image")
    f = Fragments(*meshes.rasterise(np.hstack([P, np.full((3, 1), 0.5)]), np.array([[0, 1, 2]]), width, height))
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.where(f.triangle >= 0, f.weights @ c, 0.0)
    return finite_result(out, "intensities")

"""Shading polygonal models (Goldman chapter 21): normals and five shading modes.

§21.1 polygonal models: a mesh is plain arrays, vertex ``positions`` (n, 3) and ``triangles`` (m, 3)
of vertex indices (counterclockwise seen from outside); :func:`uv_sphere` makes the chapter's sphere.
The normal of a polygon by Newell's formula (:func:`unit_newell_normal`, :func:`newell_face_normals`)
and vertex normals averaged from the faces around a vertex (:func:`average_vertex_normals`;
:func:`vertex_normals` weights by area).

:func:`render` is the pipeline of the chapter: a :class:`goldman_lib.camera.Camera` projects the
vertices (the perspective matrix of §13.6.2), the rasteriser scan-converts the triangles with a depth
buffer (:mod:`goldman_lib.rasteriser`, the one scan conversion of the course: chapter 22's z-buffer
runs it too), and one of the shading modes colours what it covers:

* ``uniform`` (§21.2): one intensity per face, at its centroid with its Newell normal;
* ``gouraud`` (§21.3): intensities at the vertices, interpolated across the face;
* ``phong`` (§21.4.1): normals (and points) interpolated, lit at every pixel;
* ``fast_phong`` (§21.4.2-3): the diffuse and specular cosines as quadratics in the screen
  coordinates (second-order Taylor expansions, evaluated incrementally along a scan line by forward
  differences, :func:`forward_differences`);
* ``slerp`` (§21.4.4): normals interpolated by spherical linear interpolation
  (:func:`goldman_lib.vector_geometry.slerp`), so they stay unit length.

Mach bands (§21.3-21.4): :func:`scanline_profile` reads the intensity along one row of a rendered
image and its slope per pixel, and :func:`edge_slopes` measures the slope on each side of every mesh
edge the row crosses -- Gouraud's slope jumps at the edges, Phong's changes (nearly) continuously.

All light comes from :func:`goldman_lib.lighting.intensity`, except the fast-Phong mode, which
combines its approximate cosines with the same material and lights term by term as that function
does (the tests check the two agree when the cosines are exact).

>>> unit_newell_normal([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]).tolist()
[0.0, 0.0, 1.0]
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from goldman_lib import lighting
from goldman_lib.camera import Camera
from goldman_lib.kernels import frames, meshes
from goldman_lib.rasteriser import Fragments, triangle_mesh
from goldman_lib.validation import (MAX_ITEMS, as_colour, as_float, as_float_array, as_int, as_points, check_finite,
                                    finite_result, within_budget)

__all__ = ["unit_newell_normal", "face_normals", "vertex_normals", "newell_face_normals", "average_vertex_normals",
           "uv_sphere", "SHADING_MODES", "render",
           "slerp_normals", "taylor_cosines", "forward_differences", "EdgeSlopes", "edge_slopes",
           "scanline_profile"]


def unit_newell_normal(polygon) -> np.ndarray:
    """The unit normal of a (possibly non-planar) polygon by Newell's formula (Goldman §21.1).

    ``N_x = sum (y_i - y_j)(z_i + z_j)`` and cyclically, j = i+1: twice the area vector of the
    polygon, robust for nearly collinear vertices.  polygon: (k, 3), k >= 3.  Returns (3,); zeros
    for a degenerate polygon.

    >>> unit_newell_normal([[0, 0, 0], [0, 0, 1], [0, 1, 0]]).tolist()
    [-1.0, 0.0, 0.0]
    """
    P = as_points(polygon, "polygon", dim=3, min_count=3)
    with np.errstate(over="ignore", invalid="ignore"):
        return finite_result(frames.unit_newell(P), "polygon")      # NaN (named) where the area overflows


def face_normals(positions, triangles) -> np.ndarray:
    """Area-weighted normals ``(b - a) x (c - a)`` of triangles (not normalised): (m, 3) (Goldman §21.1;
    for a triangle this is Newell's vector).

    >>> face_normals([[0, 0, 0], [2, 0, 0], [0, 1, 0]], [[0, 1, 2]]).tolist()
    [[0.0, 0.0, 2.0]]
    """
    V, T = triangle_mesh(positions, triangles)
    tris = V[T]
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    return finite_result(out, "positions", why="are too large in magnitude")


def vertex_normals(positions, triangles) -> np.ndarray:
    """Unit vertex normals (Goldman §21.1): area-weighted sums of the face normals around each vertex ((0, 0, 1)
    for a vertex on no face of positive area).

    >>> vertex_normals(np.array([[0., 0, 0], [1, 0, 0], [0, 1, 0]]), np.array([[0, 1, 2]])).tolist()
    [[0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0]]
    """
    V, T = triangle_mesh(positions, triangles)
    return _vertex_sums(V, T, face_normals(V, T), 1e-300)


def _vertex_sums(V, T, face_vectors, tiny) -> np.ndarray:
    """Unchecked: the sum of ``face_vectors`` over the faces at each vertex, normalised ((0, 0, 1)
    where the sum is no longer than ``tiny``)."""
    n = np.zeros_like(V)
    for k in range(3):
        np.add.at(n, T[:, k], face_vectors)
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return np.divide(n, length, out=np.zeros_like(n) + [0.0, 0.0, 1.0], where=length > tiny)


# -- §21.1 polygonal models -------------------------------------------------------------------------

def newell_face_normals(positions, triangles) -> np.ndarray:
    """Unit Newell normals of the faces of a triangle mesh (Goldman §21.1): (m, 3), zeros for a
    degenerate (zero-area) face.  For a triangle Newell's vector is ``(b - a) x (c - a)``.

    >>> newell_face_normals([[0, 0, 0], [2, 0, 0], [0, 1, 0]], [[0, 1, 2]]).tolist()
    [[0.0, 0.0, 1.0]]
    """
    fn = face_normals(positions, triangles)
    return lighting.unit_rows(fn, "face normals") if len(fn) else fn


def average_vertex_normals(positions, triangles) -> np.ndarray:
    """The book's vertex normals (Goldman §21.1): the average of the unit Newell normals of the faces
    that meet at each vertex, normalised: (n, 3) unit ((0, 0, 1) for a vertex on no proper face).

    >>> average_vertex_normals([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
    ...                        [[0, 2, 1], [0, 1, 3]]).round(4).tolist()[0]
    [0.0, -0.7071, -0.7071]
    """
    V, T = triangle_mesh(positions, triangles)
    return _vertex_sums(V, T, newell_face_normals(V, T), 1e-12)


def uv_sphere(stacks: int = 12, slices: int = 24, radius=1.0, center=(0.0, 0.0, 0.0)):
    """A polygonal model of a sphere (Goldman §21.1): ``stacks`` bands of latitude and ``slices`` of
    longitude, triangulated, counterclockwise seen from outside.  Returns ``(positions, triangles)``
    with ``(stacks - 1) * slices + 2`` vertices and ``2 * slices * (stacks - 1)`` triangles.

    >>> V, T = uv_sphere(3, 4)
    >>> V.shape, T.shape
    ((10, 3), (16, 3))
    """
    stacks = as_int(stacks, "stacks", minimum=2)
    slices = within_budget(slices, "slices", cost=lambda s: 2 * s * 2, what="the sphere mesh", unit="triangles",
                           minimum=3)
    within_budget(stacks, "stacks", cost=lambda s: 2 * slices * s, what="the sphere mesh", unit="triangles",
                  minimum=2)
    r = as_float(radius, "radius", positive=True)
    c = as_points(center, "center", ndim=1, dim=3)
    theta = np.pi * np.arange(1, stacks) / stacks                 # polar angle of each inner ring
    phi = 2 * np.pi * np.arange(slices) / slices
    ring = np.stack([np.sin(theta)[:, None] * np.cos(phi), np.sin(theta)[:, None] * np.sin(phi),
                     np.cos(theta)[:, None] * np.ones_like(phi)], axis=-1).reshape(-1, 3)
    V = np.vstack([[0.0, 0.0, 1.0], ring, [0.0, 0.0, -1.0]])
    with np.errstate(over="ignore", invalid="ignore"):
        V = finite_result(c + r * V, "radius and center")
    idx = 1 + np.arange((stacks - 1) * slices).reshape(stacks - 1, slices)
    nxt = np.roll(idx, -1, axis=1)
    tris = [np.stack([np.zeros(slices, np.intp), idx[0], nxt[0]], 1)]
    a, b, cc, d = idx[:-1], nxt[:-1], idx[1:], nxt[1:]
    tris.append(np.stack([a, cc, d], -1).reshape(-1, 3))
    tris.append(np.stack([a, d, b], -1).reshape(-1, 3))
    south = len(V) - 1
    tris.append(np.stack([np.full(slices, south), nxt[-1], idx[-1]], 1))
    return V, np.vstack(tris).astype(np.intp)


# -- §21.4.2-3 fast Phong: Taylor expansions evaluated by forward differences ----------------------


def scanline_profile(image, row: int) -> tuple[np.ndarray, np.ndarray]:
    """The intensity along one scan line of a rendered image and its slope (Goldman §21.3-21.4):
    ``(grey, slope)``, the grey level of each pixel of row ``row`` (w,) -- the mean of its colour
    channels -- and the first differences ``grey[j + 1] - grey[j]`` (w - 1,), the slope per pixel
    between neighbours.  A Gouraud-shaded face gives a constant slope, which steps at each edge.

    image: (h, w, c) colours or (h, w) intensities.  row: 0 <= row < h.

    >>> grey, slope = scanline_profile([[[0.0, 0.2, 0.4], [0.4, 0.4, 0.4], [0.6, 0.6, 0.6]]], 0)
    >>> np.round(grey, 6).tolist(), np.round(slope, 6).tolist()
    ([0.2, 0.4, 0.6], [0.2, 0.2])
    """
    img = check_finite(as_float_array(image, "image"), "image")
    if img.ndim not in (2, 3):
        raise ValueError(f"image must be (h, w) intensities or (h, w, c) colours; got shape {img.shape}")
    row = as_int(row, "row", minimum=0, maximum=img.shape[0] - 1)
    grey = img[row] if img.ndim == 2 else img[row].mean(axis=1)
    return grey, np.diff(grey)


class EdgeSlopes(NamedTuple):
    """What :func:`edge_slopes` measures at each mesh edge a scan line crosses: ``columns`` (k,) the
    pixel column j where the covering triangle changes (the edge lies between columns j - 1 and j),
    ``left`` and ``right`` (k,) the intensity's slope per pixel just left and just right of it, and
    ``jump`` (k,) ``right - left``."""

    columns: np.ndarray
    left: np.ndarray
    right: np.ndarray
    jump: np.ndarray


def edge_slopes(values, triangle_ids, width: int = 2) -> EdgeSlopes:
    """The slope of an intensity profile on each side of every mesh edge along one scan line, and its
    jump there (Goldman §21.3, Mach bands): Gouraud shading is linear on each face, so its profile is
    continuous but its slope jumps at the edges -- the kinks the eye exaggerates into Mach bands;
    Phong shading (§21.4) interpolates normals, and its slope changes (nearly) continuously.  (The
    measurement is ours, not the book's.)

    values: (w,) intensities along a row of a rendered image, or (w, c) colours (their channels are
    averaged: a grey level).  triangle_ids: (w,) the triangle covering each pixel of that row (the
    row of :attr:`goldman_lib.rasteriser.Fragments.triangle`; -1 for none).  An edge is a change of
    triangle between two covered neighbours; the slope on each side is the mean first difference over ``width`` pixel
    pairs lying wholly in that side's triangle (edges without that much room on both sides, and the
    outline, where a pixel is not covered, are skipped).  Returns :class:`EdgeSlopes`, slopes in
    intensity per pixel.

    >>> profile = [0.0, 0.1, 0.2, 0.3, 0.35, 0.4, 0.45]     # the slope drops from 0.1 to 0.05 at column 3
    >>> e = edge_slopes(profile, [0, 0, 0, 1, 1, 1, 1])
    >>> e.columns.tolist(), np.round(e.left, 6).tolist(), np.round(e.right, 6).tolist()
    ([3], [0.1], [0.05])
    """
    v = check_finite(as_float_array(values, "values"), "values")
    if v.size > MAX_ITEMS:
        raise ValueError(f"values must hold at most {MAX_ITEMS:,} numbers (one row of an image); got {v.size:,}")
    if v.ndim == 2:
        v = v.mean(axis=1)
    if v.ndim != 1:
        raise ValueError(f"values must be (w,) intensities or (w, c) colours of one row; got shape {v.shape}")
    ids = as_float_array(triangle_ids, "triangle_ids")
    if ids.shape != v.shape:
        raise ValueError(f"values and triangle_ids must have one entry per pixel of the row: values has shape "
                         f"{v.shape}, triangle_ids {ids.shape}")
    if not np.all(np.isfinite(ids)) or np.any(ids != np.round(ids)):
        raise ValueError("triangle_ids must be whole numbers (-1 for an uncovered pixel)")
    ids = ids.astype(np.intp)
    width = as_int(width, "width", minimum=1, maximum=max(1, len(v)))
    d = np.diff(v)
    cols, left, right = [], [], []
    for j in np.flatnonzero((ids[1:] != ids[:-1]) & (ids[1:] >= 0) & (ids[:-1] >= 0)) + 1:
        a, b = ids[j - 1], ids[j]
        lo, hi = j - 1 - width, j + width           # pixels lo..j-1 in triangle a, j..hi in triangle b
        if lo < 0 or hi >= len(v) or np.any(ids[lo:j] != a) or np.any(ids[j:hi + 1] != b):
            continue
        cols.append(j)
        left.append(d[lo:j - 1].mean())
        right.append(d[j:hi].mean())
    cols, left, right = np.array(cols, dtype=np.intp), np.array(left, float), np.array(right, float)
    return EdgeSlopes(cols, left, right, right - left)


def taylor_cosines(normal, normal_x, normal_y, light_direction, eye_direction):
    """The fast-Phong quadratics (Goldman §21.4.2-3): second-order Taylor expansions, in the screen
    offsets ``(X, Y)`` from a triangle's reference pixel, of the diffuse cosine ``L . N / |N|`` and the
    specular cosine ``R . V = 2 (L . N)(V . N) / (N . N) - L . V`` for a normal interpolated
    *linearly* across the screen, ``N = N0 + X Nx + Y Ny`` (Phong's un-normalised normal).

    ``L . N`` and ``V . N`` are linear and ``N . N`` quadratic in (X, Y), so only the division by
    ``|N|`` (diffuse) and by ``N . N`` (specular) needs the expansion; the light and the eye are
    taken as directions (fixed over the triangle), as the book's fast shading does.  The expansion
    about the reference pixel and the form of the specular numerator are our formulation.

    normal, normal_x, normal_y: (m, 3) N0, Nx, Ny.  light_direction, eye_direction: (m, 3) unit L, V.
    Returns ``(diffuse, specular)``, each (m, 6): the coefficients of ``1, X, Y, X^2, XY, Y^2``.

    >>> d, s = taylor_cosines([[0, 0, 1]], [[0.01, 0, 0]], [[0, 0, 0]], [[0, 0, 1]], [[0, 0, 1]])
    >>> d.round(6).tolist()
    [[1.0, 0.0, 0.0, -5e-05, 0.0, 0.0]]
    """
    N0 = as_points(normal, "normal", dim=3)
    Nx = as_points(normal_x, "normal_x", dim=3)
    Ny = as_points(normal_y, "normal_y", dim=3)
    L = lighting.unit_rows(light_direction, "light_direction")
    V = lighting.unit_rows(eye_direction, "eye_direction")
    for name, arr in (("normal_x", Nx), ("normal_y", Ny), ("light_direction", L), ("eye_direction", V)):
        if arr.shape != N0.shape:
            raise ValueError(f"{name} must have the shape of normal {N0.shape}; got {arr.shape}")
    if np.any(np.einsum("ij,ij->i", N0, N0) <= 1e-24):
        raise ValueError("normal must be nonzero at the reference pixel")
    with np.errstate(over="ignore", invalid="ignore"):
        out = _taylor(N0, Nx, Ny, L, V)
    why = "are too large in magnitude (the normal varies too fast across the triangle)"
    return (finite_result(out[0], "normal, normal_x and normal_y", why=why),
            finite_result(out[1], "normal, normal_x and normal_y", why=why))


def _taylor(N0, Nx, Ny, L, V):
    dot = lambda a, b: np.einsum("ij,ij->i", a, b)  # noqa: E731
    d0, dx, dy = dot(L, N0), dot(L, Nx), dot(L, Ny)
    e0, ex, ey = dot(V, N0), dot(V, Nx), dot(V, Ny)
    q0 = dot(N0, N0)
    q = (2 * dot(N0, Nx), 2 * dot(N0, Ny))                           # first partials of N . N
    qq = {(0, 0): 2 * dot(Nx, Nx), (0, 1): 2 * dot(Nx, Ny), (1, 1): 2 * dot(Ny, Ny)}   # second partials
    # g = q^(-1/2) and h = 1/q: values, first and second partials at the reference pixel.
    g0 = q0 ** -0.5
    g = tuple(-0.5 * q0 ** -1.5 * qi for qi in q)
    gg = {ij: 0.75 * q0 ** -2.5 * q[ij[0]] * q[ij[1]] - 0.5 * q0 ** -1.5 * v for ij, v in qq.items()}
    h0 = 1.0 / q0
    h = tuple(-qi / q0 ** 2 for qi in q)
    hh = {ij: 2 * q[ij[0]] * q[ij[1]] / q0 ** 3 - v / q0 ** 2 for ij, v in qq.items()}
    d, e = (dx, dy), (ex, ey)
    # diffuse f = d g (d linear); specular f = p h - L.V with p = 2 d e.
    f0 = d0 * g0
    f = [d[i] * g0 + d0 * g[i] for i in range(2)]
    ff = {(i, j): d[i] * g[j] + d[j] * g[i] + d0 * gg[i, j] for (i, j) in qq}
    diffuse = np.stack([f0, f[0], f[1], 0.5 * ff[0, 0], ff[0, 1], 0.5 * ff[1, 1]], 1)
    p0 = 2 * d0 * e0
    p = [2 * (d[i] * e0 + d0 * e[i]) for i in range(2)]
    pp = {(i, j): 2 * (d[i] * e[j] + d[j] * e[i]) for (i, j) in qq}
    s0 = p0 * h0 - dot(L, V)
    s = [p[i] * h0 + p0 * h[i] for i in range(2)]
    ss = {(i, j): pp[i, j] * h0 + p[i] * h[j] + p[j] * h[i] + p0 * hh[i, j] for (i, j) in qq}
    specular = np.stack([s0, s[0], s[1], 0.5 * ss[0, 0], ss[0, 1], 0.5 * ss[1, 1]], 1)
    return diffuse, specular


def forward_differences(coefficients, x0, y, count: int) -> np.ndarray:
    """A quadratic ``c0 + c1 X + c2 Y + c3 X^2 + c4 XY + c5 Y^2`` along one scan line, by forward
    differences (Goldman §21.4.2): at ``X = x0, x0 + 1, ...`` (``count`` pixels) on row ``Y = y``,
    each value is the last plus a first difference, and each first difference the last plus the
    constant second difference ``2 c3`` -- two additions per pixel, no multiplication.  (The
    renderer evaluates the same quadratic at every pixel at once, which numpy does faster.)

    >>> forward_differences([1, 2, 0, 1, 0, 0], 0, 0, 4).tolist()
    [1.0, 4.0, 9.0, 16.0]
    """
    c = as_float_array(coefficients, "coefficients")
    if c.shape != (6,):
        raise ValueError(f"coefficients must be 6 numbers (1, X, Y, X^2, XY, Y^2); got shape {c.shape}")
    check_finite(c, "coefficients")
    x0 = as_float(x0, "x0")
    y = as_float(y, "y")
    count = within_budget(count, "count", cost=lambda n: n, what="the scan line", unit="pixels", minimum=1)
    with np.errstate(over="ignore", invalid="ignore"):
        first = c[0] + c[1] * x0 + c[2] * y + c[3] * x0 * x0 + c[4] * x0 * y + c[5] * y * y
        delta = c[1] + c[4] * y + c[3] * (2 * x0 + 1)                  # f(x0 + 1) - f(x0)
        steps = np.full(count, 2 * c[3])
        steps[0] = 0.0
        deltas = delta + np.cumsum(steps)                              # first differences, by additions
        values = first + np.concatenate([[0.0], np.cumsum(deltas[:-1])])
    return finite_result(values, "coefficients, x0 and y")


# -- §21.4.4 Phong shading with slerp -------------------------------------------------------------

def slerp_normals(normals, weights) -> np.ndarray:
    """Normals across a triangle by spherical linear interpolation (Goldman §21.4.4), with the one
    slerp of the library (:func:`goldman_lib.vector_geometry.slerp`): first along the edge from
    ``N0`` to ``N1`` at ``w1 / (w0 + w1)``, then from there towards ``N2`` at ``w2`` (our way of
    extending the book's slerp along edges and scan lines to barycentric weights).  Unit normals in,
    unit normals out.  Opposite normals (no unique arc) fall back to normalised linear interpolation.

    normals: (k, 3, 3) the three unit vertex normals per point; weights: (k, 3) barycentric.
    Returns (k, 3).

    >>> slerp_normals([[[1, 0, 0], [0, 1, 0], [0, 0, 1]]], [[0.5, 0.5, 0]]).round(6).tolist()
    [[0.707107, 0.707107, 0.0]]
    """
    N = as_points(normals, "normals", ndim=3, dim=3)
    W = as_points(weights, "weights", dim=3)
    if N.shape[:2] != (len(W), 3):
        raise ValueError(f"normals must have shape ({len(W)}, 3, 3) (three normals per row of weights); "
                         f"got {N.shape}")
    N = lighting.unit_rows(N, "normals")
    if np.any(np.einsum("...i,...i->...", N, N) < 0.5):
        raise ValueError("normals must be nonzero")
    if np.any(W < -1e-9) or np.any(np.abs(W.sum(1) - 1) > 1e-6):
        raise ValueError("weights must be barycentric: non-negative and summing to 1")
    return _slerp_normals(N, np.clip(W, 0, 1))


def _slerp_pair(a, b, t):
    out = np.empty_like(a)
    opposite = np.einsum("ij,ij->i", a, b) <= -1 + 1e-9
    ok = ~opposite
    if ok.any():
        out[ok] = frames.slerp(a[ok], b[ok], t[ok])
    if opposite.any():
        lerp = (1 - t[opposite, None]) * a[opposite] + t[opposite, None] * b[opposite]
        out[opposite] = lighting.unit_rows(lerp + 1e-12 * np.array([0.0, 0.0, 1.0]))
    return out


def _slerp_normals(N, W):
    s = W[:, 0] + W[:, 1]
    t = np.divide(W[:, 1], s, out=np.zeros_like(s), where=s > 1e-12)
    edge = _slerp_pair(N[:, 0], N[:, 1], t)
    return _slerp_pair(edge, N[:, 2], W[:, 2])


# -- §21.2-21.4 rendering ------------------------------------------------------------------------

#: The shading modes of :func:`render`, by name, with the section that describes each.
SHADING_MODES = {"uniform": "§21.2", "gouraud": "§21.3", "phong": "§21.4.1", "fast_phong": "§21.4.2-3",
                 "slerp": "§21.4.4"}


def _combine(diffuse_cos, specular_cos, lit, lights, material, ambient_light):
    """``I_a k_a C + sum I_p (k_d C cos_d + k_s S cos_s^n)``: the terms of lighting.intensity, from
    cosines already computed (the fast-Phong mode)."""
    C, S = np.asarray(material.colour), np.asarray(material.specular_colour)
    ia = np.asarray(ambient_light, float) * material.ambient
    total = np.broadcast_to(ia * C, diffuse_cos.shape[:1] + (3,)).copy()
    for k, light in enumerate(lights):
        d = np.where(lit[:, k], np.maximum(diffuse_cos[:, k], 0.0), 0.0)
        rv = np.where(lit[:, k], np.clip(specular_cos[:, k], 0.0, 1.0), 0.0)
        with np.errstate(under="ignore"):
            s = np.where(rv > 0, rv ** material.exponent, 0.0)
        total += (material.diffuse * d[:, None] * C + material.specular * s[:, None] * S) * light.rgb
    return total


def render(positions, triangles, camera: Camera, lights, material=None, mode: str = "phong",
           normals=None, ambient_light=0.2, background=(0.0, 0.0, 0.0), cull_backfaces: bool = False):
    """Render a triangle mesh with one of the shading modes of Goldman chapter 21 (§21.2-21.4):
    project with ``camera``, scan-convert with :func:`goldman_lib.rasteriser.rasterise_triangles`, light with
    :func:`goldman_lib.lighting.intensity`.  Returns an (height, width, 3) image in [0, 1].

    positions (n, 3), triangles (m, 3): the mesh.  lights: a Light or a sequence of them.
    material: a :class:`goldman_lib.lighting.Material` (default a grey plastic).  mode: a key of
    :data:`SHADING_MODES`.  normals: (n, 3) vertex normals (default :func:`average_vertex_normals`).
    cull_backfaces: skip triangles facing away from the eye (for closed meshes).

    Points, normals and vertex intensities are interpolated with perspective-correct weights (the
    screen barycentrics divided by each vertex's depth w and renormalised: the same as the book's
    interpolation along scan lines for a parallel view); fast Phong interpolates the normal
    linearly in screen space, as §21.4.2 does.  Lighting is two-sided: where the eye sees the back of
    a face, its normal is flipped towards the eye first.

    >>> V = [[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]]
    >>> cam = Camera(eye=(0, -4, 0), target=(0, 0, 0), width=4, height=4, fov=60)
    >>> img = render(V, [[0, 1, 2], [0, 2, 3]], cam, lighting.Light((0, -4, 0)), mode="uniform")
    >>> img.shape, bool(img[2, 2, 0] > 0)
    ((4, 4, 3), True)
    """
    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be a goldman_lib.camera.Camera; got {type(camera).__name__}")
    if not isinstance(mode, str) or mode not in SHADING_MODES:
        raise ValueError(f"mode must be one of {sorted(SHADING_MODES)}; got {mode!r}")
    material = lighting.Material() if material is None else material
    if not isinstance(material, lighting.Material):
        raise TypeError(f"material must be a goldman_lib.lighting.Material; got {type(material).__name__}")
    lights = lighting.as_lights(lights)
    bg = np.asarray(as_colour(background, "background"))
    V, T = triangle_mesh(positions, triangles)
    if normals is None:
        N = average_vertex_normals(V, T)
    else:
        N = lighting.unit_rows(as_points(normals, "normals", dim=3), "normals")
        if N.shape != V.shape:
            raise ValueError(f"normals must have the shape of positions {V.shape}; got {N.shape}")
    ambient_light = lighting.scaled_terms(np.float64(1.0), 1.0, ambient_light, "ambient_light", "ambient_light")
    eye = np.asarray(camera.eye)
    S = camera.project(V)
    if cull_backfaces and len(T):
        fn = face_normals(V, T)
        T = T[np.einsum("ij,ij->i", fn, eye - V[T[:, 0]]) > 0]
    frags = Fragments(*meshes.rasterise(S[:, :3], T, camera.width, camera.height))
    image = np.broadcast_to(bg, (camera.height, camera.width, 3)).copy()
    covered = frags.triangle >= 0
    if not covered.any():
        return image
    tri = frags.triangle[covered]
    lam = frags.weights[covered]
    idx = T[tri]                                           # (k, 3) vertex indices per pixel
    with np.errstate(over="ignore", invalid="ignore"):
        shade = _shade(mode, V, T, N, S, tri, idx, lam, covered, eye, lights, material, ambient_light)
    image[covered] = lighting.to_image(finite_result(shade, "positions", why="are too large in magnitude"))
    return image


def _facing(normals, points, eye):
    """Flip normals to face the eye (one-sided lighting of whichever side is seen)."""
    back = np.einsum("ij,ij->i", normals, eye - points) < 0
    return np.where(back[:, None], -normals, normals)


def _shade(mode, V, T, N, S, tri, idx, lam, covered, eye, lights, material, ambient_light):
    w = S[:, 3]
    pc = lam / w[idx]
    pc /= pc.sum(1, keepdims=True)                         # perspective-correct weights
    if mode == "uniform":
        faces = np.unique(tri)
        centroid = V[T[faces]].mean(1)
        fn = newell_face_normals(V, T[faces])
        colour = lighting.intensity(centroid, _facing(fn, centroid, eye), eye, lights, material, ambient_light)
        lookup = np.zeros((len(T), 3))
        lookup[faces] = colour
        return lookup[tri]
    if mode == "gouraud":
        verts = np.unique(idx)
        colour = np.zeros((len(V), 3))
        # a vertex is lit on the side of the mesh the eye sees: the normal is flipped where it faces away
        colour[verts] = lighting.intensity(V[verts], _facing(N[verts], V[verts], eye), eye, lights, material,
                                           ambient_light)
        return np.einsum("ki,kij->kj", pc, colour[idx])
    P = np.einsum("ki,kij->kj", pc, V[idx])
    if mode == "phong":
        normal = np.einsum("ki,kij->kj", pc, N[idx])
        return lighting.intensity(P, _facing(normal, P, eye), eye, lights, material, ambient_light)
    if mode == "slerp":
        normal = _slerp_normals(N[idx], pc)
        return lighting.intensity(P, _facing(normal, P, eye), eye, lights, material, ambient_light)
    return _fast_phong(V, T, N, S, tri, covered, eye, lights, material, ambient_light)


def _fast_phong(V, T, N, S, tri, covered, eye, lights, material, ambient_light):
    """§21.4.2-3: per triangle, the linear screen-space normal N0 + X Nx + Y Ny about its first
    vertex's pixel, Taylor quadratics of the cosines (:func:`taylor_cosines`), evaluated at each pixel."""
    faces, inverse = np.unique(tri, return_inverse=True)
    Tf = T[faces]
    xy = S[Tf][:, :, :2]                                   # (f, 3, 2)
    ref = xy.mean(1)                                       # reference pixel: the projected centroid
    A = np.concatenate([xy - ref[:, None], np.ones((len(Tf), 3, 1))], axis=2)   # rows (X_i, Y_i, 1)
    det = np.linalg.det(A)
    A[np.abs(det) < 1e-12] = np.eye(3)
    coef = np.linalg.solve(A, N[Tf])                       # rows Nx, Ny, N0: N at vertex i = X_i Nx + Y_i Ny + N0
    Nx, Ny, N0 = coef[:, 0], coef[:, 1], coef[:, 2]
    centroid = V[Tf].mean(1)
    flip = np.einsum("ij,ij->i", N0, eye - centroid) < 0   # seen from behind: light the other side
    sign = np.where(flip, -1.0, 1.0)[:, None]
    N0, Nx, Ny = N0 * sign, Nx * sign, Ny * sign
    small = np.einsum("ij,ij->i", N0, N0) < 1e-12
    N0[small] = N[Tf[small, 0]]
    Veye = lighting.unit_rows(eye - centroid)
    rows, cols = np.nonzero(covered)
    X = cols + 0.5 - ref[inverse, 0]
    Y = rows + 0.5 - ref[inverse, 1]
    basis = np.stack([np.ones_like(X), X, Y, X * X, X * Y, Y * Y], 1)
    dcos = np.empty((len(X), len(lights)))
    scos = np.empty_like(dcos)
    for k, light in enumerate(lights):
        L = lighting.unit_rows(np.asarray(light.position) - centroid)
        dq, sq = _taylor(N0, Nx, Ny, L, Veye)
        dcos[:, k] = np.einsum("ij,ij->i", basis, dq[inverse])
        scos[:, k] = np.einsum("ij,ij->i", basis, sq[inverse])
    return _combine(dcos, scos, dcos > 0, lights, material, ambient_light)

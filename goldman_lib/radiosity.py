"""Radiosity (Goldman ch. 23): light bounced between diffuse patches until it settles.

A scene is cut into small flat patches.  Each patch ``i`` has an area ``A_i``, a reflectance
``rho_i`` (per RGB channel) and an emission ``E_i``; its **radiosity** ``B_i`` is the light leaving
it per unit area.  The rendering equation, restricted to diffuse surfaces and made discrete, is
the **radiosity equation** (§23.2)

    B_i = E_i + rho_i sum_j F_ij B_j ,      that is      (I - diag(rho) F) B = E,

where the **form factor** ``F_ij`` is the fraction of the light leaving patch ``i`` that arrives at
patch ``j`` (the book's convention: row ``i`` is what ``i`` sees).  Form factors obey
**reciprocity**, ``A_i F_ij = A_j F_ji``, and in a closed scene every row sums to 1.

This module gives:

* form factors in closed form for the two cases the book treats -- two directly opposed equal
  rectangles (:func:`form_factor_parallel_rectangles`) and two rectangles at right angles sharing an
  edge (:func:`form_factor_perpendicular_rectangles`) -- and from a point to a polygon
  (:func:`form_factor_point_polygon`, Lambert's contour formula);
* form factors between the patches of a scene by **hemi-cubes** (§23.3,
  :func:`hemicube_form_factors`): the delta form factors of the cells of a hemi-cube's top and side
  faces (:func:`hemicube_delta_form_factors`), every patch projected onto the hemi-cube of each patch
  and the nearest one kept in each cell (an item buffer, vectorised over cells and patches);
* the solvers of §23.5: gathering by :func:`jacobi` and :func:`gauss_seidel`, shooting by
  :func:`progressive_refinement`, each stopping when the residual ``max |E + rho F B - B|`` is at most
  ``tol`` (or after ``max_iter`` iterations) and, on request (``full_output=True``), returning
  ``(B, report)``: the library's one iteration record, :class:`~goldman_lib.fixed_point.Convergence`
  (defined in :mod:`goldman_lib.kernels.relaxation`), with the residual and the radiosities after
  every iteration.  ``fixed_point.jacobi`` and ``fixed_point.gauss_seidel`` are the same methods for
  ``A x = b`` (§7.3.2), with the same keywords and record; both run the sweeps of the kernels;
* a Cornell box (:func:`cornell_box`) with several hundred patches and a square light on its
  ceiling, and the display step of §23.4: radiosities averaged at the vertices for smooth (Gouraud)
  display (:func:`vertex_radiosities`) and mapped to colours (:func:`to_colours`).

These choices are ours, not the book's: residuals are measured in the max norm, the
hemi-cube is sampled at cell centres (a ray per cell, which is what projecting the patches and
keeping the nearest in each cell computes), and the iterations start from ``B = E``.

Points are row vectors; the box is ``[0, 1]^3`` with ``z`` up, its open side at ``y = 0``.

>>> round(form_factor_parallel_rectangles(1, 1, 1), 4), round(form_factor_perpendicular_rectangles(1, 1, 1), 4)
(0.1998, 0.2)
>>> F = np.array([[0.0, 0.5], [0.5, 0.0]]); rho = np.array([0.5, 0.5]); E = np.array([1.0, 0.0])
>>> np.round(jacobi(F, rho, E, tol=1e-12), 6)
array([1.066667, 0.266667])
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from goldman_lib.fixed_point import ConvergenceError
from goldman_lib.kernels import frames, relaxation
from goldman_lib.kernels.relaxation import Convergence
from goldman_lib.validation import (MAX_ITEMS, MAX_ITERATIONS, as_float, as_float_array, as_int, as_points,
                                    as_tolerance, check_finite, within_budget)

__all__ = ["Patches", "form_factor_parallel_rectangles", "form_factor_perpendicular_rectangles",
           "form_factor_point_polygon", "hemicube_cells", "hemicube_delta_form_factors", "hemicube_form_factors",
           "reciprocity_error", "enforce_reciprocity", "radiosity_matrix", "residual", "jacobi", "gauss_seidel", "progressive_refinement",
           "ShootingOperators", "shooting_operators",
           "cornell_box", "light_emission", "patch_mesh", "vertex_radiosities", "corner_radiosities", "to_colours", "CORNELL_COLOURS"]

#: The reflectances of the Cornell box's surfaces (RGB): white walls, red left wall, green right wall.
CORNELL_COLOURS = {"white": (0.75, 0.75, 0.75), "red": (0.63, 0.065, 0.05), "green": (0.14, 0.45, 0.09)}

#: The most ray-patch tests one call of :func:`hemicube_form_factors` may make (about a minute's work).
MAX_HEMICUBE_TESTS = 200 * MAX_ITEMS


# -- patches -----------------------------------------------------------------------------------------

@dataclass(frozen=True, eq=False)
class Patches:
    """The patches of a radiosity scene (Goldman §23.2): parallelograms ``origin + s edge_u + t
    edge_v`` for ``0 <= s, t <= 1``, facing along ``edge_u x edge_v``.

    origin, edge_u, edge_v: ``(n, 3)``.  reflectance, emission: ``(n, 3)`` RGB (reflectance in
    [0, 1], emission >= 0).  labels: a name per patch (its wall).  Derived: :attr:`centres`,
    :attr:`normals` (unit), :attr:`areas`, :attr:`corners` ``(n, 4, 3)``.
    """

    origin: np.ndarray
    edge_u: np.ndarray
    edge_v: np.ndarray
    reflectance: np.ndarray
    emission: np.ndarray
    labels: tuple = ()
    grids: tuple = ()

    def __post_init__(self):
        origin = as_points(self.origin, "origin", dim=3)
        n = len(origin)
        edge_u = as_points(self.edge_u, "edge_u", dim=3)
        edge_v = as_points(self.edge_v, "edge_v", dim=3)
        refl = as_points(self.reflectance, "reflectance", dim=3)
        emis = as_points(self.emission, "emission", dim=3)
        for name, arr in (("edge_u", edge_u), ("edge_v", edge_v), ("reflectance", refl), ("emission", emis)):
            if len(arr) != n:
                raise ValueError(f"{name} must hold one row per patch, as many as origin has ({n}); got shape "
                                 f"{arr.shape}")
        cross = np.cross(edge_u, edge_v)
        area = np.linalg.norm(cross, axis=1)
        if np.any(area <= 1e-12 * np.maximum(1.0, np.linalg.norm(edge_u, axis=1) * np.linalg.norm(edge_v, axis=1))):
            k = int(np.flatnonzero(area <= 1e-12 * np.maximum(1.0, np.linalg.norm(edge_u, axis=1)
                                                                * np.linalg.norm(edge_v, axis=1)))[0])
            raise ValueError(f"edge_u and edge_v must span a parallelogram; patch {k} has zero area")
        if not np.all(np.isfinite(area)) or not np.all(np.isfinite(origin + edge_u + edge_v)):
            raise ValueError("origin must be small enough that the patches' corners and areas are finite")
        if np.any((refl < 0) | (refl > 1)):
            raise ValueError("reflectance must be in [0, 1] in every channel")
        if np.any(emis < 0):
            raise ValueError("emission must be >= 0 in every channel")
        if isinstance(self.labels, str) or not isinstance(self.labels, (tuple, list)):
            raise TypeError(f"labels must be a tuple or list of names, one per patch; got {type(self.labels).__name__}")
        if not isinstance(self.grids, (tuple, list)):
            raise TypeError(f"grids must be a tuple of (start, nu, nv) triples; got {type(self.grids).__name__}")
        labels = tuple(str(s) for s in self.labels) if len(self.labels) else ("patch",) * n
        if len(labels) != n:
            raise ValueError(f"labels must name every patch ({n}); got {len(labels)}")
        for name, arr in (("origin", origin), ("edge_u", edge_u), ("edge_v", edge_v), ("reflectance", refl),
                          ("emission", emis)):
            object.__setattr__(self, name, arr)
        object.__setattr__(self, "labels", labels)
        object.__setattr__(self, "grids", self._check_grids(self.grids, n))

    def _check_grids(self, grids, n):
        out = []
        used = np.zeros(n, bool)
        for g in grids:
            if not isinstance(g, (tuple, list)) or len(g) != 3:
                raise ValueError(f"grids must hold (start, nu, nv) triples; got {g!r}")
            start, nu, nv = (as_int(v, "grids", minimum=0) for v in g)
            if nu < 1 or nv < 1 or start + nu * nv > n:
                raise ValueError(f"grids: ({start}, {nu}, {nv}) must name nu x nv >= 1 patches among the {n}")
            if used[start:start + nu * nv].any():
                raise ValueError(f"grids must not overlap; ({start}, {nu}, {nv}) overlaps another grid")
            used[start:start + nu * nv] = True
            a, b = np.divmod(np.arange(nu * nv), nv)
            k = start + a * nv + b
            expect = self.origin[start] + a[:, None] * self.edge_u[start] + b[:, None] * self.edge_v[start]
            size = np.abs(self.edge_u[start]).max() + np.abs(self.edge_v[start]).max()
            if (np.abs(self.origin[k] - expect).max() > 1e-9 * size
                    or np.abs(self.edge_u[k] - self.edge_u[start]).max() > 1e-9 * size
                    or np.abs(self.edge_v[k] - self.edge_v[start]).max() > 1e-9 * size):
                raise ValueError(f"grids: the patches ({start}, {nu}, {nv}) do not tile a parallelogram in order")
            out.append((start, nu, nv))
        return tuple(out)

    def __len__(self) -> int:
        return len(self.origin)

    @property
    def areas(self) -> np.ndarray:
        """``(n,)`` the patches' areas ``|edge_u x edge_v|``."""
        return np.linalg.norm(np.cross(self.edge_u, self.edge_v), axis=1)

    @property
    def normals(self) -> np.ndarray:
        """``(n, 3)`` unit normals along ``edge_u x edge_v`` (the side that emits and reflects)."""
        cross = np.cross(self.edge_u, self.edge_v)
        return cross / np.linalg.norm(cross, axis=1, keepdims=True)

    @property
    def centres(self) -> np.ndarray:
        """``(n, 3)`` the patches' centres."""
        return self.origin + 0.5 * (self.edge_u + self.edge_v)

    @property
    def corners(self) -> np.ndarray:
        """``(n, 4, 3)`` corners in order ``origin, +edge_u, +edge_u+edge_v, +edge_v``."""
        o, u, v = self.origin, self.edge_u, self.edge_v
        return np.stack([o, o + u, o + u + v, o + v], axis=1)

    def with_emission(self, emission) -> "Patches":
        """The same patches with another emission ``(n, 3)``."""
        return Patches(self.origin, self.edge_u, self.edge_v, self.reflectance, emission, self.labels, self.grids)


# -- analytic form factors ---------------------------------------------------------------------------

def _positive(x, name):
    value = as_float(x, name)
    if value <= 0:
        raise ValueError(f"{name} must be > 0; got {value}")
    if value > 1e100 or value < 1e-100:
        raise ValueError(f"{name} must be between 1e-100 and 1e100; got {value}")
    return value


def form_factor_parallel_rectangles(width, height, distance) -> float:
    """The form factor between two equal ``width`` x ``height`` rectangles directly opposite each
    other at ``distance`` (parallel, aligned, facing each other) in closed form (Goldman §23.3):

        F = 2 / (pi X Y) [ ln sqrt((1+X^2)(1+Y^2) / (1+X^2+Y^2)) + X sqrt(1+Y^2) atan(X / sqrt(1+Y^2))
                           + Y sqrt(1+X^2) atan(Y / sqrt(1+X^2)) - X atan X - Y atan Y ],

    ``X = width / distance``, ``Y = height / distance``.  All three must be > 0.

    >>> round(form_factor_parallel_rectangles(1, 1, 1), 5)
    0.19982
    """
    a, b, c = _positive(width, "width"), _positive(height, "height"), _positive(distance, "distance")
    X, Y = a / c, b / c
    if X > 1e6 or Y > 1e6 or X < 1e-6 or Y < 1e-6:
        raise ValueError(f"width/distance and height/distance must be between 1e-6 and 1e6; got {X:g} and {Y:g}")
    x2, y2 = X * X, Y * Y
    sx, sy = math.sqrt(1 + x2), math.sqrt(1 + y2)
    value = (0.5 * (math.log1p(x2) + math.log1p(y2) - math.log1p(x2 + y2))
             + X * sy * math.atan(X / sy) + Y * sx * math.atan(Y / sx) - X * math.atan(X) - Y * math.atan(Y))
    return float(min(max(2.0 / (math.pi * X * Y) * value, 0.0), 1.0))


def form_factor_perpendicular_rectangles(common_edge, width_from, width_to) -> float:
    """The form factor from a ``common_edge`` x ``width_from`` rectangle to a ``common_edge`` x
    ``width_to`` rectangle at right angles to it, the two sharing the edge of length
    ``common_edge`` (Goldman §23.3), in closed form: with ``W = width_from / l``, ``H = width_to / l``,

        F = 1 / (pi W) [ W atan(1/W) + H atan(1/H) - sqrt(H^2+W^2) atan(1/sqrt(H^2+W^2))
            + 1/4 ln( (1+W^2)(1+H^2)/(1+W^2+H^2) * (W^2 (1+W^2+H^2) / ((1+W^2)(W^2+H^2)))^(W^2)
                                                 * (H^2 (1+H^2+W^2) / ((1+H^2)(H^2+W^2)))^(H^2) ) ].

    >>> round(form_factor_perpendicular_rectangles(1, 1, 1), 5)
    0.20004
    """
    ell = _positive(common_edge, "common_edge")
    W, H = _positive(width_from, "width_from") / ell, _positive(width_to, "width_to") / ell
    if W > 1e6 or H > 1e6 or W < 1e-6 or H < 1e-6:
        raise ValueError(f"width_from/common_edge and width_to/common_edge must be between 1e-6 and 1e6; "
                         f"got {W:g} and {H:g}")
    w2, h2 = W * W, H * H
    r = math.sqrt(w2 + h2)
    log_term = (math.log1p(w2) + math.log1p(h2) - math.log1p(w2 + h2)
                + w2 * (math.log(w2) + math.log1p(w2 + h2) - math.log1p(w2) - math.log(w2 + h2))
                + h2 * (math.log(h2) + math.log1p(w2 + h2) - math.log1p(h2) - math.log(w2 + h2)))
    value = W * math.atan(1 / W) + H * math.atan(1 / H) - r * math.atan(1 / r) + 0.25 * log_term
    return float(min(max(value / (math.pi * W), 0.0), 1.0))


def form_factor_point_polygon(point, normal, polygon) -> float:
    """The form factor from a differential area at ``point`` with unit ``normal`` to a planar
    ``polygon`` (Goldman §23.3, the limit of a small patch): Lambert's contour formula

        F = 1 / (2 pi) sum_k gamma_k  n . (R_k x R_{k+1}) / |R_k x R_{k+1}|,

    ``R_k`` the vertices relative to ``point`` and ``gamma_k`` the angle between ``R_k`` and
    ``R_{k+1}``.  The part of the polygon below the point's tangent plane is clipped away first.
    point, normal: ``(3,)``; polygon: ``(k, 3)``, ``k >= 3``, its vertices in either order.

    >>> round(form_factor_point_polygon([0, 0, 0], [0, 0, 1], [[-9e3, -9e3, 1], [9e3, -9e3, 1], [9e3, 9e3, 1], [-9e3, 9e3, 1]]), 4)
    1.0
    """
    p = as_points(point, "point", ndim=1, dim=3)
    n = as_points(normal, "normal", ndim=1, dim=3)
    poly = as_points(polygon, "polygon", dim=3)
    if len(poly) < 3:
        raise ValueError(f"polygon must have at least 3 vertices; got {len(poly)}")
    length = float(np.linalg.norm(n))
    if not np.isfinite(length) or length == 0:
        raise ValueError("normal must be a nonzero vector")
    n = n / length
    scale = float(np.abs(poly - p).max())
    if not np.isfinite(scale) or scale > 1e100:
        raise ValueError("polygon must lie within 1e100 of point")
    R = poly - p
    h = R @ n
    eps = 1e-12 * max(scale, 1e-300)
    # clip to the half-space above the tangent plane (Sutherland-Hodgman with one plane)
    clipped = []
    for k in range(len(R)):
        a, b, ha, hb = R[k], R[(k + 1) % len(R)], h[k], h[(k + 1) % len(R)]
        if ha > eps:
            clipped.append(a)
        if (ha > eps) != (hb > eps):
            t = (eps - ha) / (hb - ha)
            clipped.append(a + t * (b - a))
    if len(clipped) < 3:
        return 0.0
    R = np.array(clipped)
    R = R / np.linalg.norm(R, axis=1, keepdims=True)
    Rn = np.roll(R, -1, axis=0)
    cross = np.cross(R, Rn)
    sin = np.linalg.norm(cross, axis=1)
    gamma = np.arctan2(sin, np.einsum("ij,ij->i", R, Rn))
    safe = np.where(sin > 0, sin, 1.0)
    total = np.sum(np.where(sin > 0, gamma * (cross @ n) / safe, 0.0))
    return float(min(abs(total) / (2 * math.pi), 1.0))


# -- hemi-cubes --------------------------------------------------------------------------------------

def _check_resolution(resolution):
    res = as_int(resolution, "resolution", minimum=2)
    if res % 2:
        raise ValueError(f"resolution must be even (the side faces are half as tall as they are wide); got {res}")
    return within_budget(res, "resolution", cost=lambda r: 3 * r * r, what="the hemi-cube", unit="cells")


def hemicube_cells(resolution=16):
    """The cells of a unit hemi-cube (Goldman §23.3): the top face ``z = 1``, ``-1 <= x, y <= 1`` cut
    into ``resolution`` x ``resolution`` cells, and the four half side faces (``x = +-1`` or
    ``y = +-1``, ``0 <= z <= 1``) into ``resolution`` x ``resolution/2`` cells each.

    Returns ``(directions, face)``: ``directions`` ``(3 r^2, 3)`` the cell centres (the directions from
    the patch's centre, in its local frame with the normal along ``z``), ``face`` ``(3 r^2,)`` 0 for
    the top face and 1-4 for the sides.  ``resolution`` must be even.

    >>> d, face = hemicube_cells(4)
    >>> d.shape, int((face == 0).sum())
    ((48, 3), 16)
    """
    r = _check_resolution(resolution)
    c = -1 + (np.arange(r) + 0.5) * (2.0 / r)            # centres across a face
    z = (np.arange(r // 2) + 0.5) * (2.0 / r)            # centres up a side face
    X, Y = np.meshgrid(c, c, indexing="ij")
    top = np.stack([X.ravel(), Y.ravel(), np.ones(r * r)], axis=1)
    S, Z = np.meshgrid(c, z, indexing="ij")
    s, zz, one = S.ravel(), Z.ravel(), np.ones(S.size)
    sides = [np.stack([one, s, zz], 1), np.stack([-one, s, zz], 1), np.stack([s, one, zz], 1),
             np.stack([s, -one, zz], 1)]
    directions = np.concatenate([top] + sides)
    face = np.concatenate([np.zeros(r * r, int)] + [np.full(S.size, k, int) for k in range(1, 5)])
    return directions, face


def hemicube_delta_form_factors(resolution=16) -> np.ndarray:
    """The delta form factors of the hemi-cube's cells (Goldman §23.3), in the order of
    :func:`hemicube_cells`: a cell of area ``dA = (2/r)^2`` at ``(x, y, 1)`` on the top face has
    ``dF = dA / (pi (x^2 + y^2 + 1)^2)``; one at ``(1, y, z)`` on a side face has
    ``dF = z dA / (pi (y^2 + z^2 + 1)^2)``.  Both are ``dA cos(theta_patch) cos(theta_cell) / (pi d^2)``
    and they sum to about 1 (exactly 1 as ``r`` grows).

    >>> round(float(hemicube_delta_form_factors(64).sum()), 3)
    1.0
    """
    d, _ = hemicube_cells(resolution)
    r = int(resolution)
    dA = (2.0 / r) ** 2
    d2 = np.einsum("ij,ij->i", d, d)
    return dA * d[:, 2] / (np.pi * d2 * d2)


def _surfaces(patches: Patches):
    """The rectangles the patches tile: (origin, edge_u, edge_v, nu, nv, start) arrays, one row per
    grid of :attr:`Patches.grids` (a lone patch is a 1 x 1 grid)."""
    n = len(patches)
    grids = list(patches.grids)
    covered = np.zeros(n, bool)
    for start, nu, nv in grids:
        covered[start:start + nu * nv] = True
    grids += [(int(k), 1, 1) for k in np.flatnonzero(~covered)]
    start = np.array([g[0] for g in grids]); nu = np.array([g[1] for g in grids]); nv = np.array([g[2] for g in grids])
    return (patches.origin[start], patches.edge_u[start] * nu[:, None], patches.edge_v[start] * nv[:, None],
            nu, nv, start)


def hemicube_form_factors(patches: Patches, resolution=16, subdivisions=1, progress=None) -> np.ndarray:
    """Form factors ``F_ij`` between all patches of a scene by hemi-cubes (Goldman §23.3).

    For each patch ``i`` a hemi-cube is set on its centre, facing along its normal; every other patch
    is projected onto the hemi-cube's cells and each cell keeps the nearest patch it sees (an item
    buffer: the smallest depth along the cell's ray wins, so hidden patches get nothing).
    ``F_ij`` is the sum of the delta form factors (:func:`hemicube_delta_form_factors`) of the cells
    that keep ``j``; a cell that sees the back of a patch, or nothing, counts for no one.
    ``subdivisions`` ``s > 1`` puts hemi-cubes at the centres of an ``s`` x ``s`` grid on patch ``i``
    and averages them (the area average that defines ``F_ij``; one hemi-cube at the centre assumes the
    patch is small beside its distance to the others).

    Vectorised over cells, surfaces and hemi-cubes: the patches of a rectangle cut into a grid
    (:attr:`Patches.grids`, as :func:`cornell_box` makes) are projected together -- the cell's ray
    meets the rectangle's plane at grid coordinates that name the patch -- so the work grows with the
    number of rectangles, not of patches.  Returns ``(n, n)`` with zero diagonal.  resolution: even,
    cells across the top face; the work (``n s^2 3 r^2`` cells times the rectangles) is bounded
    (:data:`MAX_HEMICUBE_TESTS`).

    progress: ``progress(done, total)`` is called with the hemi-cubes finished so far (of ``n s^2``)
    after each batch of them (about 400,000 cell-rectangle tests a batch), for a progress bar
    (:class:`goldman_lib.widgets.render_control.ProgressBar`); the result does not depend on it.  An
    interrupt between batches leaves nothing half-written (``F`` is returned only at the end).

    >>> two = Patches([[0, 0, 0], [0, 1, 1]], [[1, 0, 0], [1, 0, 0]], [[0, 1, 0], [0, -1, 0]],
    ...               [[0.5] * 3] * 2, [[0.0] * 3] * 2)
    >>> F = hemicube_form_factors(two, resolution=32, subdivisions=6)
    >>> bool(abs(F[0, 1] - 0.1998) < 0.004)
    True
    >>> seen = []
    >>> F2 = hemicube_form_factors(two, resolution=32, subdivisions=6, progress=lambda k, n: seen.append((k, n)))
    >>> seen[-1], bool(np.array_equal(F, F2))
    ((72, 72), True)
    """
    if not isinstance(patches, Patches):
        raise TypeError(f"patches must be a radiosity.Patches; got {type(patches).__name__}")
    if progress is not None and not callable(progress):
        raise TypeError(f"progress must be a function progress(done, total) or None; got {type(progress).__name__}")
    n = len(patches)
    subdivisions = as_int(subdivisions, "subdivisions", minimum=1)
    res = _check_resolution(resolution)
    so, su_, sv_, nu, nv, first = _surfaces(patches)
    m = len(so)
    if n * n > MAX_ITEMS:
        raise ValueError(f"patches must number at most {math.isqrt(MAX_ITEMS):,}: their form factors are n x n = "
                         f"{n * n:,} numbers, over the limit of {MAX_ITEMS:,}; got {n:,} patches")
    one = n * 3 * res * res * m                              # the tests of one hemi-cube per patch
    if one > MAX_HEMICUBE_TESTS:
        largest = 2 * math.isqrt(MAX_HEMICUBE_TESTS // (n * 3 * m * 4))
        raise ValueError(f"resolution must be <= {largest} for {n} patches ({m} rectangles): one hemi-cube per patch at "
                         f"resolution {res} makes {one:,} ray-rectangle tests, over the limit of {MAX_HEMICUBE_TESTS:,}")
    within_budget(subdivisions, "subdivisions", cost=lambda s: n * s * s * 3 * res * res * m,
                  what=f"the hemi-cubes of {n} patches at resolution {res}", unit="ray-rectangle tests",
                  limit=MAX_HEMICUBE_TESTS, minimum=1)
    directions, _ = hemicube_cells(res)
    delta = hemicube_delta_form_factors(res)
    R = len(directions)
    cross = np.cross(su_, sv_)
    c2 = np.einsum("ij,ij->i", cross, cross)
    dual_u = np.cross(sv_, cross) / c2[:, None]             # (p - o) . dual_u = s in [0, 1]
    dual_v = np.cross(cross, su_) / c2[:, None]             # (p - o) . dual_v = t in [0, 1]
    normals = patches.normals
    t1, t2 = frames.frame(normals)[:, :2].transpose(1, 0, 2)     # unit tangents, (t1, t2, normal) right-handed
    grid = (np.arange(subdivisions) + 0.5) / subdivisions
    ga, gb = [g.ravel() for g in np.meshgrid(grid, grid, indexing="ij")]
    # the eyes: s^2 points on every patch, each with its patch's frame
    eyes = (patches.origin[:, None, :] + ga[None, :, None] * patches.edge_u[:, None, :]
            + gb[None, :, None] * patches.edge_v[:, None, :]).reshape(-1, 3)
    owner = np.repeat(np.arange(n), len(ga))
    # turn each hemi-cube about its normal by its own angle (the golden angle times the patch's
    # index): cells then do not line up with the edges of a regular grid of patches, which would
    # send whole rows of cell rays onto patch boundaries (aliasing)
    turn = np.radians(137.50776405 * np.arange(n))[:, None]
    t1, t2 = np.cos(turn) * t1 + np.sin(turn) * t2, -np.sin(turn) * t1 + np.cos(turn) * t2
    axes = np.stack([t1, t2, normals], axis=1)            # (n, 3, 3) rows: local x, y, z
    scale = float(np.abs(patches.origin).max() + np.linalg.norm(patches.edge_u, axis=1).max()
                  + np.linalg.norm(patches.edge_v, axis=1).max())
    eps = 1e-9 * max(scale, 1e-300)
    wn0, wu0, wv0 = (np.einsum("ij,ij->i", so, c) for c in (cross, dual_u, dual_v))
    F = np.zeros((n, n))
    chunk = max(1, 400_000 // (R * m))
    cells = np.arange(R)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for lo in range(0, len(eyes), chunk):
            x, who = eyes[lo:lo + chunk], owner[lo:lo + chunk]
            D = np.einsum("cj,ejk->eck", directions, axes[who])        # (e, R, 3) world directions
            Dn, Du, Dv = D @ cross.T, D @ dual_u.T, D @ dual_v.T          # (e, R, m)
            wn = (wn0[None, :] - x @ cross.T)[:, None, :]                 # (e, 1, m): (o - x) . cross
            t = wn / Dn
            s = t * Du - (wu0[None, :] - x @ dual_u.T)[:, None, :]
            u = t * Dv - (wv0[None, :] - x @ dual_v.T)[:, None, :]
            hit = (t > eps) & (s >= 0) & (s <= 1) & (u >= 0) & (u <= 1)
            depth = np.where(hit, t, np.inf)
            k = depth.argmin(axis=2)                                      # (e, R) nearest rectangle
            e_idx = np.arange(len(x))[:, None]
            seen = np.isfinite(depth[e_idx, cells[None, :], k]) & (Dn[e_idx, cells[None, :], k] < 0)
            a = np.minimum((s[e_idx, cells[None, :], k] * nu[k]).astype(int), nu[k] - 1)
            b = np.minimum((u[e_idx, cells[None, :], k] * nv[k]).astype(int), nv[k] - 1)
            patch = first[k] + np.clip(a, 0, None) * nv[k] + np.clip(b, 0, None)
            rows = np.broadcast_to(who[:, None], patch.shape)
            weights = np.broadcast_to(delta[None, :], patch.shape)
            F += np.bincount((rows * n + patch)[seen], weights=weights[seen], minlength=n * n).reshape(n, n)
            if progress is not None:
                progress(min(lo + chunk, len(eyes)), len(eyes))
    F /= len(ga)
    np.fill_diagonal(F, 0.0)
    return F


def reciprocity_error(F, area) -> float:
    """How far form factors are from reciprocity ``A_i F_ij = A_j F_ji`` (Goldman §23.3): the total
    ``sum |A_i F_ij - A_j F_ji|`` relative to ``sum A_i F_ij`` (0 for exact form factors; hemi-cubes,
    which sample each row from one point, give a small positive number).

    >>> reciprocity_error([[0, 0.5], [0.25, 0]], [1, 2])
    0.0
    >>> reciprocity_error([[0, 0.5], [0.5, 0]], [1, 2])          # A F: 0.5 and 1.0, off by 0.5 twice in 1.5
    0.6666666666666666
    """
    F = _check_F(F)
    A = _check_area(area, len(F))
    AF = A[:, None] * F
    total = float(AF.sum())
    if total == 0:
        return 0.0
    return float(np.abs(AF - AF.T).sum() / total)


def enforce_reciprocity(F, area) -> np.ndarray:
    """Form factors made reciprocal (Goldman §23.3): ``F'_ij = (A_i F_ij + A_j F_ji) / (2 A_i)``, the
    average of what the hemi-cubes of ``i`` and of ``j`` say about the pair, so that
    ``A_i F'_ij = A_j F'_ji`` exactly.  Shooting (:func:`progressive_refinement`) and gathering then
    solve the same equation.

    >>> enforce_reciprocity([[0, 0.5], [0.5, 0]], [1, 2]).tolist()
    [[0.0, 0.75], [0.375, 0.0]]
    """
    F = _check_F(F)
    A = _check_area(area, len(F))
    AF = A[:, None] * F
    return (AF + AF.T) / (2 * A[:, None])


# -- the radiosity equation and its solvers --------------------------------------------------------------

def _check_F(F) -> np.ndarray:
    F = check_finite(as_float_array(F, "F"), "F")
    if F.ndim != 2 or F.shape[0] != F.shape[1] or F.shape[0] == 0:
        raise ValueError(f"F must be a square (n, n) matrix of form factors; got shape {F.shape}")
    if np.any(F < 0) or np.any(F > 1):
        raise ValueError("F must hold form factors in [0, 1]")
    rows = F.sum(axis=1)
    if np.any(rows > 1.05):
        k = int(np.argmax(rows))
        raise ValueError(f"F's rows must sum to at most 1 (a patch cannot send out more than all its light); "
                         f"row {k} sums to {rows[k]:.4g}")
    return F


def _check_area(area, n) -> np.ndarray:
    A = check_finite(as_float_array(area, "area"), "area")
    if A.shape != (n,):
        raise ValueError(f"area must hold one area per patch, shape ({n},); got shape {A.shape}")
    if np.any(A <= 0) or np.any(A > 1e150):
        raise ValueError("area must be positive (and below 1e150)")
    return A


def _check_system(F, rho, E):
    F = _check_F(F)
    n = len(F)
    E = check_finite(as_float_array(E, "E"), "E")
    if E.ndim not in (1, 2) or E.shape[0] != n:
        raise ValueError(f"E must have shape ({n},) or ({n}, channels); got shape {E.shape}")
    if np.any(E < 0) or np.any(E > 1e100):
        raise ValueError("E must be >= 0 (emitted light) and below 1e100")
    rho = check_finite(as_float_array(rho, "rho"), "rho")
    if rho.ndim == 0 or rho.shape[0] != n or rho.ndim > 2:
        raise ValueError(f"rho must have shape ({n},) or ({n}, channels); got shape {rho.shape}")
    if np.any(rho < 0) or np.any(rho > 1):
        raise ValueError("rho must be a reflectance in [0, 1]")
    if not (rho.shape == E.shape or rho.shape == (n,)):
        raise ValueError(f"rho must have the shape of E, {E.shape}, or ({n},) (one reflectance for every channel); "
                         f"got shape {rho.shape}")
    if rho.ndim < E.ndim:
        rho = rho[:, None]
    shape = np.broadcast_shapes(rho.shape, E.shape)
    return F, np.broadcast_to(rho, shape).astype(float), np.broadcast_to(E, shape).astype(float)


def _check_iterations(value, n, channels, keep, name="max_iter"):
    if value is None:                       # as many as the budget allows
        return MAX_ITERATIONS if not keep else min(MAX_ITERATIONS, MAX_ITEMS // (n * channels) - 1)
    k = as_int(value, name, minimum=0)
    within_budget(k, name, cost=lambda m: m, what="the solver", unit="iterations", limit=MAX_ITERATIONS)
    if keep:
        within_budget(k, name, cost=lambda m: (m + 1) * n * channels, what="the stored iterates",
                      unit="numbers", limit=MAX_ITEMS)
    return k


#: Iterations without a new smallest residual after which a solver calls its iteration stalled.
STALL_ITERATIONS = 1000


def _check_solvable(F, rho) -> None:
    """Refuse, before iterating, a radiosity system ``B = E + rho F B`` that has no solution the
    iterations can reach (Goldman §23.5).  With ``M = diag(rho) F`` nonnegative, the Jacobi,
    Gauss-Seidel and shooting iterations converge for every ``E`` exactly when the spectral radius of
    ``M`` is < 1 (Perron-Frobenius; Stein-Rosenberg for Gauss-Seidel; shooting solves the equation
    of ``diag(rho) A^-1 F^T A``, whose spectral radius is the same); otherwise light is never lost
    and no nonnegative ``B`` solves the equation for a positive ``E``.  The spectral radius is < 1
    when every row of ``M`` sums to less than 1 (``rho < 1``, or rows of ``F`` summing to less than
    1: a contraction in the max norm, the usual case, checked first); else exactly when ``(I - M) y
    = 1`` has a solution ``y >= 1`` (then ``M y = y - 1 < y``, so ``max (M y)_i / y_i < 1``; and
    conversely ``y = sum M^k 1``), solved once per channel.  ``y`` beyond 1e12 is singular to
    working precision (the iterations would need more than 1e12 steps)."""
    rows = F.sum(axis=1)
    M_rows = rho * (rows if rho.ndim == 1 else rows[:, None])
    if float(M_rows.max()) < 1.0:
        return
    R = rho if rho.ndim == 2 else rho[:, None]
    n = len(F)
    for c in range(R.shape[1]):
        if c and np.array_equal(R[:, c], R[:, c - 1]):
            continue
        within_budget(n, "F", cost=lambda m: m ** 3 // 3, what="the solvability check (one LU factorisation)",
                      unit="operations", limit=100 * MAX_ITEMS)
        with np.errstate(all="ignore"):
            try:
                y = np.linalg.solve(np.eye(n) - R[:, c, None] * F, np.ones(n))
            except np.linalg.LinAlgError:
                y = None
        if y is None or not np.all(np.isfinite(y)) or y.min() < 1 - 1e-9 or y.max() > 1e12:
            where = "" if R.shape[1] == 1 else f" (channel {c})"
            raise ValueError(f"rho and F must let light escape: B = E + rho F B has a solution the iterations reach "
                             f"only when the spectral radius of rho F is < 1, and here it is >= 1{where} -- the "
                             f"patches keep all the light they receive (rho = 1 where F's rows sum to 1, as in a "
                             f"closed box of perfect reflectors: light bounces forever and grows without bound)")


class _Watch:
    """What a solver's residuals show: divergence (a residual not finite, or grown a millionfold),
    a stall (no new smallest residual in :data:`STALL_ITERATIONS` iterations: ``tol`` is below the
    round-off of these radiosities) or, when the solver runs to the default cap, a rate of decrease
    (measured over the last 500 iterations, every 1000) that would need more than ten times the cap
    to reach ``tol``.  Raises ValueError saying what was seen."""

    def __init__(self, solver, r0, tol, kmax, default_cap):
        self.solver, self.tol, self.kmax, self.default_cap = solver, tol, kmax, default_cap
        self.first, self.best, self.at = r0, r0, 0

    def __call__(self, k, r, residuals):
        if not math.isfinite(r) or r > 1e6 * max(self.first, 1e-300) + 1e-300:
            raise ValueError(f"rho, F and E gave a diverging {self.solver} iteration: the residual grew from "
                             f"{self.first:.3g} to {r:.3g} in {k} iterations")
        if r < self.best:
            self.best, self.at = r, k
        elif k - self.at >= STALL_ITERATIONS:
            raise ValueError(f"tol must be reachable: the {self.solver} iteration stalled at residual {self.best:.3g} "
                             f"(no smaller residual in {STALL_ITERATIONS} iterations, after {k} in all), above "
                             f"tol = {self.tol:g}; round-off allows no better")
        if self.default_cap and k % STALL_ITERATIONS == 0 and k >= STALL_ITERATIONS and r > self.tol:
            back = residuals[-1 - STALL_ITERATIONS // 2] if len(residuals) > STALL_ITERATIONS // 2 else None
            if back and back > r > 0:
                rate = (r / back) ** (1.0 / (STALL_ITERATIONS // 2))
                more = math.log(self.tol / r) / math.log(rate)
                if k + more > 10 * self.kmax:           # (rates change as light spreads: a wide margin)
                    raise ValueError(f"rho and F converge too slowly for tol = {self.tol:g}: the {self.solver} "
                                     f"residual falls by a factor {rate:.9f} per iteration (it is {r:.3g} after {k}); "
                                     f"reaching tol would take about {k + more:,.0f} iterations, far over the limit "
                                     f"of {self.kmax:,}")


def radiosity_matrix(F, rho) -> np.ndarray:
    """The matrix ``I - diag(rho) F`` of the radiosity equation ``(I - diag(rho) F) B = E`` (Goldman
    §23.2) for one channel (``rho`` of shape ``(n,)``).

    >>> radiosity_matrix([[0, 0.5], [0.5, 0]], [0.5, 0.2])
    array([[ 1.  , -0.25],
           [-0.1 ,  1.  ]])
    """
    F = _check_F(F)
    rho = check_finite(as_float_array(rho, "rho"), "rho")
    if rho.shape != (len(F),):
        raise ValueError(f"rho must have shape ({len(F)},) (one channel); got shape {rho.shape}")
    if np.any(rho < 0) or np.any(rho > 1):
        raise ValueError("rho must be a reflectance in [0, 1]")
    return np.eye(len(F)) - rho[:, None] * F


def residual(F, rho, E, B) -> float:
    """The residual ``max |E + rho F B - B|`` of radiosities ``B`` in the radiosity equation (Goldman
    §23.2): 0 for the solution.  Shapes as for :func:`jacobi`.

    >>> residual([[0, 0.5], [0.5, 0]], [0.5, 0.5], [1, 0], [1, 0])
    0.25
    """
    F, rho, E = _check_system(F, rho, E)
    B = check_finite(as_float_array(B, "B"), "B")
    if B.shape != E.shape:
        raise ValueError(f"B must have the shape of E, {E.shape}; got {B.shape}")
    return float(np.abs(E + rho * (F @ B) - B).max())


def _finish(iterates, residuals, tol, full_output, method, shooters=None):
    """B, or ``(B, Convergence)`` with ``full_output`` (its history every iterate, B^(0) = E first);
    as ``fixed_point``'s solvers, a ConvergenceError carrying the report when B is not converged and
    the report was not asked for."""
    B = iterates[-1]
    converged = bool(residuals[-1] <= tol)
    reason = "converged" if converged else "max iterations"
    message = "" if converged else (f"the residual {residuals[-1]:.3g} is above tol = {tol:g} after "
                                    f"{len(residuals) - 1} iterations (max_iter)")
    if not full_output:
        if not converged:
            rep = Convergence(B, False, reason, len(residuals) - 1, np.array(iterates), np.array(residuals), method,
                              message, ["history holds the last iterate only (full_output=True keeps every one)"])
            raise ConvergenceError(f"{method} did not converge: {message}", rep)
        return B
    return B, Convergence(B, converged, reason, len(residuals) - 1, np.array(iterates), np.array(residuals), method,
                          message, shooters=None if shooters is None else np.array(shooters, dtype=int))


def jacobi(F, rho, E, *, tol=1e-6, max_iter=None, full_output=False):
    """Solve the radiosity equation ``B = E + rho F B`` by Jacobi iteration, a gathering method
    (Goldman §23.5); for a linear system ``A x = b`` see ``fixed_point.jacobi`` (same keywords, same
    record).  Every patch gathers light from the radiosities of the previous iteration,

        B_i^(k+1) = E_i + rho_i sum_j F_ij B_j^(k),      B^(0) = E,

    so ``B^(k)`` holds the light after ``k`` bounces.  Stops when the residual ``max |E + rho F B - B|``
    is ``<= tol`` or after ``max_iter`` iterations, 0 or more (default and bound: the work budget,
    ``100 MAX_ITEMS`` multiply-adds by default, and with ``full_output`` the memory its iterates take).
    As ``fixed_point.jacobi``: reaching ``max_iter`` first raises ``fixed_point.ConvergenceError`` (a
    ValueError carrying the report), unless ``full_output`` asks for the report, which then says so.

    Before iterating, a system without a solution the iteration reaches (spectral radius of
    ``rho F`` >= 1: ``rho = 1`` on a closed box) is refused; while iterating, divergence, a stall
    above ``tol`` (round-off) and, at the default cap, a rate that cannot reach ``tol`` in ten times
    the cap are ValueErrors saying what was seen.  The same holds for :func:`gauss_seidel` and
    :func:`progressive_refinement`.

    F: ``(n, n)`` form factors (rows summing to at most 1).  rho: ``(n,)`` or ``(n, c)`` reflectances in
    [0, 1].  E: ``(n,)`` or ``(n, c)`` emission (c colour channels).  Returns the radiosities (the shape
    of E), or with ``full_output=True`` ``(B, report)``, the report a
    :class:`~goldman_lib.fixed_point.Convergence` whose ``history`` holds ``B`` after every iteration
    (``history[0] = E``) and ``residuals`` the residual of each.

    >>> B, rep = jacobi([[0, 0.5], [0.5, 0]], [0.5, 0.5], [1, 0], tol=1e-10, full_output=True)
    >>> rep.history[1].tolist(), rep.converged, rep.method
    ([1.0, 0.25], True, 'Jacobi')
    """
    F, rho, E = _check_system(F, rho, E)
    tol = as_tolerance(tol)
    channels = 1 if E.ndim == 1 else E.shape[1]
    kmax = _check_iterations(max_iter, len(F), channels, full_output)
    if max_iter is None:                       # an iteration is n^2 c work: the default cap counts it
        kmax = min(kmax, max(1, 100 * MAX_ITEMS // (len(F) ** 2 * channels)))
    _check_solvable(F, rho)
    B = E.copy()
    gathered = relaxation.gather(F, B, rho)
    residuals = [float(np.abs(E + gathered - B).max())]
    watch = _Watch("Jacobi", residuals[0], tol, kmax, max_iter is None)
    iterates = [B]
    while residuals[-1] > tol and len(residuals) <= kmax:
        B = relaxation.jacobi_update(E, gathered)
        gathered = relaxation.gather(F, B, rho)
        residuals.append(float(np.abs(E + gathered - B).max()))
        iterates.append(B) if full_output else iterates.__setitem__(0, B)
        watch(len(residuals) - 1, residuals[-1], residuals)
    return _finish(iterates, residuals, tol, full_output, "Jacobi")


def gauss_seidel(F, rho, E, *, tol=1e-6, max_iter=None, full_output=False):
    """Solve the radiosity equation ``B = E + rho F B`` by Gauss-Seidel iteration, a gathering method
    (Goldman §23.5); for a linear system ``A x = b`` see ``fixed_point.gauss_seidel``.  Like
    :func:`jacobi`, but each patch gathers with the radiosities already updated in this sweep,

        B_i^(k+1) = E_i + rho_i (sum_{j<i} F_ij B_j^(k+1) + sum_{j>=i} F_ij B_j^(k)),

    so one sweep carries light further and the iteration converges in fewer sweeps.  One iteration is
    one sweep over all patches.  Arguments and result as for :func:`jacobi`.

    >>> B, rep = gauss_seidel([[0, 0.5], [0.5, 0]], [0.5, 0.5], [1, 1], tol=1e-10, full_output=True)
    >>> rep.history[1].tolist()          # Jacobi's first iterate is [1.25, 1.25]
    [1.25, 1.3125]
    """
    F, rho, E = _check_system(F, rho, E)
    tol = as_tolerance(tol)
    channels = 1 if E.ndim == 1 else E.shape[1]
    kmax = _check_iterations(max_iter, len(F), channels, full_output)
    if max_iter is None:                       # a sweep is n steps of Python: the default cap counts steps
        kmax = min(kmax, max(1, MAX_ITERATIONS // len(F)))
    _check_solvable(F, rho)
    B = E.copy()
    residuals = [float(np.abs(E + rho * (F @ B) - B).max())]
    watch = _Watch("Gauss-Seidel", residuals[0], tol, kmax, max_iter is None)
    iterates = [B.copy()]
    while residuals[-1] > tol and len(residuals) <= kmax:
        relaxation.gauss_seidel_sweep(F, E, B, rho)
        residuals.append(float(np.abs(E + rho * (F @ B) - B).max()))
        iterates.append(B.copy()) if full_output else iterates.__setitem__(0, B.copy())
        watch(len(residuals) - 1, residuals[-1], residuals)
    return _finish(iterates, residuals, tol, full_output, "Gauss-Seidel")


@dataclass(frozen=True, eq=False)
class ShootingOperators:
    """What progressive refinement needs of a scene that does not depend on its emission (Goldman
    §23.5), made once by :func:`shooting_operators` and reused while only the lights change.

    ``received[i]`` is what every patch receives per unit of radiosity shot from patch ``i``,
    ``rho_j F_ji = rho_j A_i F_ij / A_j`` (shape ``(n, n)`` or ``(n, n, c)``); ``received_by[j, i]``
    is ``F_ji`` (the residual ``rho F dB`` is ``rho * (received_by @ dB)``); ``change[i]``, when
    made, is how the residual vector moves per unit shot from ``i`` (``rho F received[i] -
    received[i]``), which turns the residual after a shot into an O(n) update; ``F``, ``rho`` and
    ``area`` are the arrays it was made from."""

    F: np.ndarray
    rho: np.ndarray
    area: np.ndarray
    received: np.ndarray
    received_by: np.ndarray
    change: np.ndarray | None


def shooting_operators(F, rho, area, update_residual=True) -> ShootingOperators:
    """The emission-independent part of :func:`progressive_refinement` for form factors ``F``
    ``(n, n)``, reflectances ``rho`` (``(n,)`` or ``(n, c)``, the shape of the emission to be shot)
    and patch areas ``area`` ``(n,)``: ``n^2`` numbers per channel.  With ``update_residual`` (the
    default) it also forms the residual updates ``change`` (``n^3`` work and ``n^2`` more numbers per
    channel), which pays when many shots are made or the scene is solved for several lights.  Bounded
    by the work budget (``MAX_ITEMS`` numbers kept).

    >>> ops = shooting_operators([[0, 0.5], [0.5, 0]], [0.5, 0.5], [1, 1])
    >>> ops.received.tolist()                     # rho_j F_ji: patch 1 gets 0.25 per unit shot from 0
    [[0.0, 0.25], [0.25, 0.0]]
    >>> progressive_refinement([[0, 0.5], [0.5, 0]], [0.5, 0.5], [1, 0], [1, 1], tol=1e-12,
    ...                        operators=ops).round(6)
    array([1.066667, 0.266667])
    """
    F = _check_F(F)
    n = len(F)
    A = _check_area(area, n)
    rho = check_finite(as_float_array(rho, "rho"), "rho")
    if rho.ndim not in (1, 2) or rho.shape[0] != n:
        raise ValueError(f"rho must have shape ({n},) or ({n}, c); got shape {rho.shape}")
    if np.any(rho < 0) or np.any(rho > 1):
        raise ValueError("rho must be a reflectance in [0, 1]")
    channels = 1 if rho.ndim == 1 else rho.shape[1]
    within_budget(n, "F", cost=lambda m: m * m * channels * (3 if update_residual else 1),
                  what="the shooting operators", unit="numbers", limit=MAX_ITEMS)
    shoot = F * (A[:, None] / A[None, :])                                    # shoot[i, j] = F_ji = A_i F_ij / A_j
    received_by = np.ascontiguousarray((A[None, :] * F.T) / A[:, None])     # [j, i] = A_i F_ij / A_j
    if rho.ndim == 1:
        received = np.ascontiguousarray(rho[None, :] * shoot)
    else:
        received = np.ascontiguousarray(rho[None, :, :] * shoot[:, :, None])   # (i, j, c)
    change = None
    if update_residual:
        # a shot of dB_i from i adds c = received[i] dB_i to dB (and takes dB_i from dB_i), so the
        # residual vector rho F dB moves by rho F c - c for the received part: H[:, i] - received[i]
        if rho.ndim == 1:
            rf = rho[:, None] * received_by
            change = np.ascontiguousarray((rf @ rf).T - received)
        else:
            H = np.stack([(rho[:, c, None] * received_by) @ (rho[:, c, None] * received_by)
                          for c in range(channels)], axis=2)                    # H[j, i, c]
            change = np.ascontiguousarray(H.transpose(1, 0, 2) - received)
    F, rho, A = (np.array(a) for a in (F, rho, A))                            # copies: the caller's stay writable
    for a in (F, rho, A, received, received_by) + ((change,) if change is not None else ()):
        a.setflags(write=False)
    return ShootingOperators(F, rho, A, received, received_by, change)


def _same(a, b) -> bool:
    return a is b or (a.shape == b.shape and np.array_equal(a, b))


def progressive_refinement(F, rho, E, area, *, tol=1e-6, max_iter=None, full_output=False, operators=None):
    """Solve the radiosity equation by progressive refinement, a shooting method (Goldman §23.5).

    Every patch keeps its radiosity ``B`` and its unshot radiosity ``dB`` (both start at ``E``).  Each
    iteration shoots from the patch ``i`` with the most unshot power ``A_i dB_i`` (summed over the
    channels): every patch ``j`` receives ``rho_j F_ji dB_i``, with ``F_ji = A_i F_ij / A_j`` by
    reciprocity (so only row ``i`` of ``F`` -- one hemi-cube -- is needed), added to both ``B_j`` and
    ``dB_j``; then ``dB_i = 0``.  Shooting uses row ``i`` only, so it solves the equation whose form
    factors are ``F_ji = A_i F_ij / A_j``: the same as the gathering methods' when ``F`` is reciprocal
    (:func:`enforce_reciprocity`).  The residual ``max |E + rho F B - B|`` of that equation equals
    ``max |rho F dB|``.  Stops when it is ``<= tol`` or after ``max_iter`` shots.

    area: ``(n,)`` patch areas; the rest as for :func:`jacobi` (one iteration is one shot).  With
    ``full_output`` the report's ``shooters`` lists the patch shot at each step.  operators: the :func:`shooting_operators` of these ``F``, ``rho`` (of
    the shape of ``E``) and ``area``, to reuse when the same scene is solved for several emissions
    (a moving light); made here when not given.

    >>> progressive_refinement([[0, 0.5], [0.5, 0]], [0.5, 0.5], [1, 0], [1, 1], tol=1e-12).round(6)
    array([1.066667, 0.266667])
    """
    F, rho, E = _check_system(F, rho, E)
    A = _check_area(area, len(F))
    tol = as_tolerance(tol)
    channels = 1 if E.ndim == 1 else E.shape[1]
    kmax = _check_iterations(max_iter, len(F), channels, full_output)
    _check_solvable(F, rho)
    if operators is None and len(F) <= 600 and kmax > 2 * len(F):
        # The residual after a shot follows from the one before in O(n) (ShootingOperators.change),
        # formed once (n^3) when up to 600 patches may shoot more than 2n times; otherwise each shot
        # pays a matrix-vector product.
        operators = shooting_operators(F, rho, A)
    if operators is None:                                 # what a shot sends, formed shot by shot
        shoot = F * (A[:, None] / A[None, :])             # shoot[i, j] = F_ji = A_i F_ij / A_j
        shoot = shoot[:, :, None] if E.ndim == 2 else shoot
        received_of, change = None, None
        received_by = np.ascontiguousarray((A[None, :] * F.T) / A[:, None])   # [j, i] = A_i F_ij / A_j
    elif not isinstance(operators, ShootingOperators):
        raise TypeError(f"operators must come from shooting_operators(F, rho, area); got {type(operators).__name__}")
    elif not (_same(operators.F, F) and _same(operators.rho, rho) and _same(operators.area, A)):
        raise ValueError("operators must be the shooting_operators of these F, rho (the shape of E) and area")
    else:
        received_of, received_by, change = operators.received, operators.received_by, operators.change
    B = E.copy()
    dB = E.copy()
    power_weight = A if E.ndim == 1 else A[:, None]
    r = rho * (received_by @ dB)                          # the residual vector rho F dB
    residuals = [float(np.abs(r).max())]
    watch = _Watch("progressive refinement", residuals[0], tol, kmax, max_iter is None)
    iterates = [B.copy()]
    shooters = []
    while residuals[-1] > tol and len(residuals) <= kmax:
        power = power_weight * dB
        i = int(np.argmax(power if E.ndim == 1 else power.sum(axis=1)))
        shot = dB[i].copy()
        received = received_of[i] * shot if received_of is not None else rho * (shoot[i] * shot)
        B += received
        dB[i] -= shot                                         # shot; what i sends itself (F_ii > 0) stays unshot
        dB += received
        shooters.append(i)
        if change is not None:
            r += change[i] * shot
            value = float(np.abs(r).max())
            if value <= tol:                                  # confirm without the round-off of the updates
                r = rho * (received_by @ dB)
                value = float(np.abs(r).max())
        else:
            value = float(np.abs(rho * (received_by @ dB)).max())
        residuals.append(value)
        if full_output:
            iterates.append(B.copy())
        watch(len(residuals) - 1, value, residuals)
    iterates[-1 if full_output else 0:] = [B]
    return _finish(iterates, residuals, tol, full_output, "progressive refinement", shooters)


# -- the Cornell box ---------------------------------------------------------------------------------

def _grid(origin, edge_u, edge_v, nu, nv):
    """A rectangle cut into nu x nv patches: (origins, edge_u, edge_v) arrays."""
    origin, edge_u, edge_v = (np.asarray(a, float) for a in (origin, edge_u, edge_v))
    a, b = np.meshgrid(np.arange(nu) / nu, np.arange(nv) / nv, indexing="ij")
    origins = origin + a.ravel()[:, None] * edge_u + b.ravel()[:, None] * edge_v
    count = nu * nv
    return origins, np.tile(edge_u / nu, (count, 1)), np.tile(edge_v / nv, (count, 1))


#: The blocks of :func:`cornell_box`: (label, lowest corner, highest corner), on the floor.
_BLOCKS = (("short block", (0.5, 0.125, 0.0), (0.875, 0.5, 0.375)),
           ("tall block", (0.125, 0.5, 0.0), (0.5, 0.875, 0.75)))


def _block(lo, hi, n):
    """The five visible faces (top and sides) of an axis-aligned block, facing outwards."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    div = lambda length: max(1, int(round(length * n)))  # noqa: E731
    dx, dy, dz = x1 - x0, y1 - y0, z1 - z0
    faces = [
        ((x0, y0, z1), (dx, 0, 0), (0, dy, 0), div(dx), div(dy)),      # top, +z
        ((x0, y0, z0), (dx, 0, 0), (0, 0, dz), div(dx), div(dz)),      # front, -y
        ((x1, y1, z0), (-dx, 0, 0), (0, 0, dz), div(dx), div(dz)),     # back, +y
        ((x0, y1, z0), (0, -dy, 0), (0, 0, dz), div(dy), div(dz)),     # left, -x
        ((x1, y0, z0), (0, dy, 0), (0, 0, dz), div(dy), div(dz)),      # right, +x
    ]
    return faces


def light_emission(patches: Patches, x=0.5, y=0.5, size=0.25, emission=(10.0, 10.0, 10.0)) -> np.ndarray:
    """The emission of a square light of side ``size`` centred at ``(x, y)`` on the ceiling ``z = 1``
    of a :func:`cornell_box` (Goldman §23.2): the light is part of the ceiling, so each ceiling patch
    emits ``emission`` times the fraction of its area the square covers (a light moved by a fraction
    of a patch changes the emission smoothly).  Returns ``(n, 3)``.

    >>> box = cornell_box(4, blocks=False)
    >>> E = light_emission(box, 0.5, 0.5, 0.5, (1, 1, 1))
    >>> float((E[:, 0] * box.areas).sum())              # emitted power = emission x the light's area
    0.25
    """
    if not isinstance(patches, Patches):
        raise TypeError(f"patches must be a radiosity.Patches; got {type(patches).__name__}")
    x, y = as_float(x, "x"), as_float(y, "y")
    size = as_float(size, "size")
    if not 0 < size <= 1:
        raise ValueError(f"size must be in (0, 1] (the light is a square on the unit ceiling); got {size}")
    half = size / 2
    for name, v in (("x", x), ("y", y)):
        if not half <= v <= 1 - half:
            raise ValueError(f"{name} must keep the light on the ceiling: in [{half:g}, {1 - half:g}]; got {v}")
    emis = as_points(emission, "emission", ndim=1, dim=3)
    if np.any(emis < 0) or np.any(emis > 1e100):
        raise ValueError("emission must be >= 0 (and below 1e100) in every channel")
    normals, corners = patches.normals, patches.corners
    ceiling = (normals[:, 2] < -0.999) & (np.abs(corners[:, :, 2] - 1.0).max(axis=1) < 1e-9)
    lo, hi = corners[:, :, :2].min(axis=1), corners[:, :, :2].max(axis=1)
    ox = np.clip(np.minimum(hi[:, 0], x + half) - np.maximum(lo[:, 0], x - half), 0, None)
    oy = np.clip(np.minimum(hi[:, 1], y + half) - np.maximum(lo[:, 1], y - half), 0, None)
    fraction = np.where(ceiling, ox * oy / patches.areas, 0.0)
    return fraction[:, None] * emis[None, :]


def cornell_box(n=8, closed=False, blocks=True, light=(0.5, 0.5), light_size=0.25,
                light_emission_rgb=(10.0, 10.0, 10.0)) -> Patches:
    """A Cornell box (Goldman §23.2): the unit cube ``[0, 1]^3`` (``z`` up) with a white floor, ceiling
    and back wall, a red left wall (``x = 0``), a green right wall (``x = 1``), each cut into ``n`` x ``n``
    patches facing inwards; the front ``y = 0`` open (``closed=True`` closes it with a white wall);
    with ``blocks`` two white blocks on the floor; a square light of side ``light_size`` at ``light``
    on the ceiling (:func:`light_emission`).  The floor's patches under the blocks see nothing and
    are seen by nothing.  ``n = 8`` gives 446 patches; every wall and block face is a grid (:attr:`Patches.grids`).
    ``n`` is bounded so that the form factors (patches x patches numbers) fit the work budget
    (``n <= 21`` with the blocks).

    >>> len(cornell_box()), len(cornell_box(4, closed=True, blocks=False))
    (446, 96)
    """
    n = as_int(n, "n", minimum=1)
    walls = 6 if closed else 5
    blocks_on = bool(blocks)

    def patches(m):
        count = walls * m * m
        if blocks_on:
            for lo, hi in (b[1:] for b in _BLOCKS):
                count += sum(nu * nv for *_, nu, nv in _block(lo, hi, m))
        return count

    # the form factors of p patches are p x p numbers: the box must leave room for them
    n = within_budget(n, "n", cost=lambda m: patches(m) ** 2, what="the Cornell box's form factors (patches x patches)",
                      unit="numbers", minimum=1)
    lx, ly = (as_float(v, "light") for v in as_points(light, "light", ndim=1, dim=2))
    light_size = as_float(light_size, "light_size")
    if not 0 < light_size <= 1:
        raise ValueError(f"light_size must be in (0, 1] (a square on the unit ceiling); got {light_size}")
    if not (light_size / 2 <= lx <= 1 - light_size / 2 and light_size / 2 <= ly <= 1 - light_size / 2):
        raise ValueError(f"light must keep the light on the ceiling: both in [{light_size / 2:g}, {1 - light_size / 2:g}]; "
                         f"got ({lx}, {ly})")
    rgb = as_points(light_emission_rgb, "light_emission_rgb", ndim=1, dim=3)
    if np.any(rgb < 0) or np.any(rgb > 1e100):
        raise ValueError("light_emission_rgb must be >= 0 (and below 1e100) in every channel")
    walls = [
        ("floor", (0, 0, 0), (1, 0, 0), (0, 1, 0), "white"),
        ("ceiling", (0, 0, 1), (0, 1, 0), (1, 0, 0), "white"),
        ("back", (0, 1, 0), (1, 0, 0), (0, 0, 1), "white"),
        ("left", (0, 0, 0), (0, 1, 0), (0, 0, 1), "red"),
        ("right", (1, 0, 0), (0, 0, 1), (0, 1, 0), "green"),
    ]
    if closed:
        walls.append(("front", (0, 0, 0), (0, 0, 1), (1, 0, 0), "white"))
    parts = []                                  # (label, origins, edge_u, edge_v, colour, grid (nu, nv) or None)
    for name, o, u, v, colour in walls:
        orig, eu, ev = _grid(o, u, v, n, n)
        parts.append((name, orig, eu, ev, colour, (n, n)))
    for name, lo, hi in (_BLOCKS if blocks else []):
        for o, u, v, nu, nv in _block(lo, hi, n):
            parts.append((name, *_grid(o, u, v, nu, nv), "white", (nu, nv)))
    origin = np.concatenate([p[1] for p in parts])
    edge_u = np.concatenate([p[2] for p in parts])
    edge_v = np.concatenate([p[3] for p in parts])
    refl = np.concatenate([np.tile(CORNELL_COLOURS[p[4]], (len(p[1]), 1)) for p in parts])
    labels = tuple(name for p in parts for name in [p[0]] * len(p[1]))
    starts = np.cumsum([0] + [len(p[1]) for p in parts])[:-1]
    grids = tuple((int(st), *p[5]) for st, p in zip(starts, parts) if p[5] is not None)
    box = Patches(origin, edge_u, edge_v, refl, np.zeros_like(refl), labels, grids)
    return box.with_emission(light_emission(box, lx, ly, light_size, rgb))


# -- display (§23.4) -----------------------------------------------------------------------------------

def patch_mesh(patches: Patches, shared=True):
    """Triangles to draw the patches (Goldman §23.4): ``(positions, triangles, patch_of_vertex)``.
    With ``shared`` the patches of one plane share their corner vertices (for smooth display); otherwise
    every patch has its own four (flat display).  Each patch gives two triangles, patch ``k`` being
    triangles ``2k`` and ``2k + 1``; ``patch_of_vertex`` is -1 for shared vertices.

    >>> pos, tri, owner = patch_mesh(cornell_box(2, blocks=False))
    >>> pos.shape, tri.shape
    ((45, 3), (40, 3))
    """
    if not isinstance(patches, Patches):
        raise TypeError(f"patches must be a radiosity.Patches; got {type(patches).__name__}")
    corners = patches.corners.reshape(-1, 3)
    n = len(patches)
    local = np.array([[0, 1, 2], [0, 2, 3]])
    if not shared:
        tri = (4 * np.arange(n)[:, None, None] + local[None]).reshape(-1, 3)
        return corners, tri, np.repeat(np.arange(n), 4)
    key = np.concatenate([np.round(corners * 1e6), np.repeat(np.round(patches.normals * 1e3), 4, axis=0)], axis=1)
    _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.ravel()
    positions = corners[first]
    tri = inverse[(4 * np.arange(n)[:, None, None] + local[None]).reshape(-1, 3)]
    return positions, tri, np.full(len(positions), -1)


def vertex_radiosities(patches: Patches, B) -> tuple:
    """Radiosities at the vertices for smooth display (Goldman §23.4): each vertex of
    :func:`patch_mesh` (``shared=True``) gets the average of the radiosities of the patches (of its
    plane) that meet there, so Gouraud interpolation across the triangles hides the patch edges.

    B: ``(n,)`` or ``(n, c)``.  Returns ``(positions, triangles, vertex_B)``.

    >>> box = cornell_box(2, blocks=False)
    >>> pos, tri, VB = vertex_radiosities(box, np.arange(len(box), dtype=float))
    >>> float(VB[np.argmin(np.abs(pos - [0.5, 0.5, 0]).sum(1))])     # the floor's centre: 4 patches
    1.5
    """
    if not isinstance(patches, Patches):
        raise TypeError(f"patches must be a radiosity.Patches; got {type(patches).__name__}")
    B = check_finite(as_float_array(B, "B"), "B")
    if B.ndim not in (1, 2) or B.shape[0] != len(patches):
        raise ValueError(f"B must have shape ({len(patches)},) or ({len(patches)}, c); got shape {B.shape}")
    positions, tri, _ = patch_mesh(patches, shared=True)
    quads = tri.reshape(-1, 6)[:, [0, 1, 2, 5]]              # the four corners of each patch
    count = np.bincount(quads.ravel(), minlength=len(positions)).astype(float)
    flat = B.reshape(len(patches), -1)
    total = np.zeros((len(positions), flat.shape[1]))
    np.add.at(total, quads.ravel(), np.repeat(flat, 4, axis=0))
    VB = total / count[:, None]
    return positions, tri, VB.reshape((len(positions),) + B.shape[1:])


def corner_radiosities(patches: Patches, B, smooth=True) -> np.ndarray:
    """Radiosities at the four corners of every patch, in the vertex order of
    ``patch_mesh(patches, shared=False)`` (Goldman §23.4): flat display gives all four the patch's
    radiosity; smooth display gives each corner the vertex radiosity of :func:`vertex_radiosities`.
    Returns ``(4 n,)`` or ``(4 n, c)``.

    >>> box = cornell_box(2, blocks=False)
    >>> corner_radiosities(box, np.arange(len(box), dtype=float), smooth=False)[:5].tolist()
    [0.0, 0.0, 0.0, 0.0, 1.0]
    """
    if not isinstance(patches, Patches):
        raise TypeError(f"patches must be a radiosity.Patches; got {type(patches).__name__}")
    B = check_finite(as_float_array(B, "B"), "B")
    if B.ndim not in (1, 2) or B.shape[0] != len(patches):
        raise ValueError(f"B must have shape ({len(patches)},) or ({len(patches)}, c); got shape {B.shape}")
    if not smooth:
        return np.repeat(B, 4, axis=0)
    _, tri, VB = vertex_radiosities(patches, B)
    quads = tri.reshape(-1, 6)[:, [0, 1, 2, 5]]
    return VB[quads.ravel()]


def to_colours(B, white=1.0, gamma=2.2) -> np.ndarray:
    """Display colours in [0, 1] for radiosities ``B`` (Goldman §23.4): ``(B / white)^(1/gamma)``
    clipped to [0, 1] (``white`` the radiosity shown as full white).

    >>> to_colours([0.25, 1.0, 4.0], white=1.0, gamma=2.0).tolist()
    [0.5, 1.0, 1.0]
    """
    B = check_finite(as_float_array(B, "B"), "B")
    white = as_float(white, "white")
    gamma = as_float(gamma, "gamma")
    if not 1e-100 < white < 1e100:
        raise ValueError(f"white must be positive (and below 1e100); got {white}")
    if not 0.1 <= gamma <= 10:
        raise ValueError(f"gamma must be in [0.1, 10]; got {gamma}")
    return np.clip(np.clip(B / white, 0, None) ** (1.0 / gamma), 0.0, 1.0)

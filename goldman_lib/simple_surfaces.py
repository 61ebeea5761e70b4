"""Simple surfaces: ray intersections and normals (Goldman chapter 19).

Every surface here answers the same questions, vectorised over rays ``P(t) = origin + t direction``
(directions need not be unit; ``t`` is measured in units of the direction):

* ``hits(origins, directions)`` -> ``(N, K)``: every real parameter where each ray meets the
  surface, sorted ascending, padded with ``inf`` (``K`` is fixed per kind: 1 for a plane, 2 for a
  quadric, 4 for a torus);
* ``intersect(origins, directions)`` -> ``(N,)``: the nearest parameter ``t > EPS`` per ray, ``inf``
  on a miss (what a ray tracer asks);
* ``normal(points)`` -> ``(N, 3)``: unit normals, pointing out of the solid for closed surfaces;
* ``hit(origins, directions)`` -> ``(t, normals)``: the nearest hit and the unit normal there (zero
  rows on a miss): what a renderer asks of anything it draws, simple surface or CSG solid;
* ``contains(points)`` -> ``(N,)`` booleans, for surfaces that bound a solid (a plane bounds the
  half-space behind its normal): what CSG (chapter 20) classifies ray intervals with.

Each surface carries a :class:`goldman_lib.lighting.Material` for the renderers.

>>> s = Sphere([0, 0, 0], 1)
>>> s.intersect([[0, 0, -5], [0, 3, -5]], [[0, 0, 1], [0, 0, 1]]).tolist()
[4.0, inf]
>>> s.hits([[0, 0, 0]], [[0, 0, 2]]).tolist()     # from the centre: one hit behind, one ahead
[[-0.5, 0.5]]
>>> t, n = s.hit([[0, 0, -5]], [[0, 0, 1]]); t.tolist(), n.tolist()
([4.0], [[0.0, 0.0, -1.0]])
"""

from __future__ import annotations

import numpy as np

from goldman_lib.lighting import Material, unit_rows
from goldman_lib.validation import as_float, as_float_array, as_points, check_finite, finite_result

__all__ = ["EPS", "MAX_COORDINATE", "Surface", "rays", "Plane", "Sphere", "quadratic_roots"]

#: Hits at parameters ``t <= EPS`` are not in front of the ray (a ray leaving a surface must not hit
#: it again at t = 0 because of rounding).
EPS = 1e-9
#: Ray origins and directions are refused beyond this magnitude: quartics in them must not overflow.
MAX_COORDINATE = 1e60


def rays(origins, directions) -> tuple[np.ndarray, np.ndarray]:
    """Validated ray origins and directions: two ``(N, 3)`` arrays (a single ray may be given as two
    ``(3,)`` vectors); no direction may be zero.

    >>> o, d = rays([0, 0, 0], [0, 0, 1]); o.shape, d.shape
    ((1, 3), (1, 3))
    """
    o = np.atleast_2d(as_points(origins, "origins", ndim=None, dim=3))
    d = np.atleast_2d(as_points(directions, "directions", ndim=None, dim=3))
    if o.ndim != 2 or d.ndim != 2:
        raise ValueError(f"origins and directions must have shape (N, 3); got {o.shape} and {d.shape}")
    if o.shape != d.shape:
        if len(o) == 1:
            o = np.broadcast_to(o, d.shape)
        elif len(d) == 1:
            d = np.broadcast_to(d, o.shape)
        else:
            raise ValueError(f"origins and directions must hold as many rays; got {o.shape} and {d.shape}")
    for arr, name in ((o, "origins"), (d, "directions")):
        if arr.size and np.abs(arr).max() > MAX_COORDINATE:
            raise ValueError(f"{name} must have coordinates at most {MAX_COORDINATE:g} in magnitude "
                             f"(their squares must not overflow); got {np.abs(arr).max():g}")
    if np.any(~np.any(d != 0, axis=1)):
        raise ValueError("directions must be nonzero vectors (a ray needs a direction)")
    return o, d


def quadratic_roots(a, b, c) -> np.ndarray:
    """The real roots of ``a t^2 + b t + c = 0`` per entry, sorted, ``inf``-padded: ``(N, 2)``.

    Computed without cancellation (``q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2``, roots ``q/a`` and
    ``c/q``); where ``a = 0`` the single root ``-c/b``; no real root gives ``[inf, inf]``.

    >>> quadratic_roots([1.0, 1.0, 0.0], [-3.0, 0.0, 2.0], [2.0, 1.0, -4.0]).tolist()
    [[1.0, 2.0], [inf, inf], [2.0, inf]]
    """
    a, b, c = (check_finite(as_float_array(x, name), name) for x, name in ((a, "a"), (b, "b"), (c, "c")))
    try:
        a, b, c = np.broadcast_arrays(a, b, c)
    except ValueError:
        raise ValueError(f"a, b and c must have the same shape; got {a.shape}, {b.shape} and {c.shape}") from None
    with np.errstate(all="ignore"):
        disc = b * b - 4 * a * c
        root = np.sqrt(np.maximum(disc, 0.0))
        q = -0.5 * (b + np.where(b >= 0, root, -root))
        t1 = np.where(q != 0, q / a, 0.0)
        t2 = np.where(q != 0, c / q, 0.0)
        linear = a == 0
        t_lin = np.where(b != 0, -c / b, np.inf)
        out = np.stack([np.where(linear, t_lin, np.minimum(t1, t2)),
                        np.where(linear, np.inf, np.maximum(t1, t2))], axis=-1)
        out[(disc < 0) & ~linear] = np.inf
        out[~np.isfinite(out)] = np.inf
    return np.sort(out, axis=-1)


class Surface:
    """What every simple surface provides (see the module docstring).  Subclasses implement
    ``_hits(o, d)`` and ``_normal(points)`` on validated arrays, and ``_contains`` if they bound a
    solid."""

    material: Material = Material()

    def hits(self, origins, directions) -> np.ndarray:
        """Every real parameter where each ray meets the surface, sorted, ``inf``-padded: (N, K)."""
        o, d = rays(origins, directions)
        with np.errstate(all="ignore"):
            return self._hits(o, d)

    def intersect(self, origins, directions) -> np.ndarray:
        """The nearest parameter ``t > EPS`` per ray, ``inf`` on a miss: (N,)."""
        t = self.hits(origins, directions)
        return np.where(t > EPS, t, np.inf).min(axis=1)

    def hit(self, origins, directions) -> tuple[np.ndarray, np.ndarray]:
        """The nearest parameter ``t > EPS`` per ray (``inf`` on a miss) and the unit normal of the
        surface there (a zero row on a miss): ``((N,), (N, 3))``."""
        o, d = rays(origins, directions)
        t = self.intersect(o, d)
        normals = np.zeros_like(o)
        found = np.isfinite(t)
        if found.any():
            normals[found] = self.normal(o[found] + t[found, None] * d[found])
        return t, normals

    def normal(self, points) -> np.ndarray:
        """Unit normals at points on the surface: (N, 3)."""
        P = np.atleast_2d(as_points(points, "points", ndim=None, dim=3))
        with np.errstate(all="ignore"):
            n = finite_result(self._normal(P), "points", why="are too large in magnitude")
            scale = np.abs(n).max(axis=-1, keepdims=True)
            return unit_rows(np.divide(n, scale, out=np.zeros_like(n), where=scale > 0), "points")

    def contains(self, points) -> np.ndarray:
        """True for points inside the solid the surface bounds (boundary included): (N,)."""
        P = np.atleast_2d(as_points(points, "points", ndim=None, dim=3))
        with np.errstate(all="ignore"):
            return self._contains(P)

    def _contains(self, P):
        raise TypeError(f"a {type(self).__name__} bounds no solid: it has no inside")

    def _set_material(self, material):
        if material is None:
            material = Material()
        if not isinstance(material, Material):
            raise TypeError(f"material must be a goldman_lib.lighting.Material; got {type(material).__name__}")
        self.material = material


class Plane(Surface):
    """The plane through ``point`` with normal ``normal`` (Goldman §19.2): a ray meets it at
    ``t = N . (Q - P0) / N . d`` unless it runs parallel.  Bounds the half-space ``N . (P - Q) <= 0``.

    >>> Plane([0, 0, 1], [0, 0, 2]).intersect([[0, 0, 0], [0, 0, 0]], [[1, 0, 1], [1, 0, 0]]).tolist()
    [1.0, inf]
    """

    def __init__(self, point, normal, material: Material | None = None):
        self.point = as_points(point, "point", ndim=1, dim=3)
        n = as_points(normal, "normal", ndim=1, dim=3)
        if not np.any(n != 0):
            raise ValueError("normal must be a nonzero vector")
        self.unit_normal = unit_rows(n / np.abs(n).max(), "normal")
        self._set_material(material)

    def _hits(self, o, d):
        nd = d @ self.unit_normal
        t = np.where(nd != 0, ((self.point - o) @ self.unit_normal) / nd, np.inf)
        return np.where(np.isfinite(t), t, np.inf)[:, None]

    def _normal(self, P):
        return np.broadcast_to(self.unit_normal, P.shape)

    def _contains(self, P):
        return (P - self.point) @ self.unit_normal <= 0


class Sphere(Surface):
    """The sphere ``|P - C| = r`` (Goldman §19.3): substituting the ray gives the quadratic
    ``(d.d) t^2 + 2 d.(P0 - C) t + |P0 - C|^2 - r^2 = 0``; the outward normal at ``P`` is
    ``(P - C) / r``.

    >>> Sphere([1, 0, 0], 2).normal([[3, 0, 0]]).tolist()
    [[1.0, 0.0, 0.0]]
    """

    def __init__(self, center, radius, material: Material | None = None):
        self.center = as_points(center, "center", ndim=1, dim=3)
        self.radius = as_float(radius, "radius", positive=True)
        self._set_material(material)

    def _hits(self, o, d):
        oc = o - self.center
        return quadratic_roots(np.einsum("ij,ij->i", d, d), 2 * np.einsum("ij,ij->i", d, oc),
                               np.einsum("ij,ij->i", oc, oc) - self.radius ** 2)

    def _normal(self, P):
        return (P - self.center) / self.radius

    def _contains(self, P):
        return np.einsum("ij,ij->i", P - self.center, P - self.center) <= self.radius ** 2

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

from goldman_lib.kernels import frames, polygons, roots
from goldman_lib.lighting import Material, unit_rows
from goldman_lib.roots import MAX_DEGREE
from goldman_lib.validation import as_float, as_float_array, as_points, check_finite, finite_result, within_budget

__all__ = ["EPS", "MAX_COORDINATE", "MAX_RESOLUTION", "MAX_PROFILE_DEGREE", "Surface", "rays", "Plane",
           "Sphere", "Polygon", "Cylinder", "EllipticCylinder", "Cone", "EllipticCone", "Ellipsoid", "Quadric", "Torus",
           "SurfaceOfRevolution", "line_sphere_geometric"]

#: Hits at parameters ``t <= EPS`` are not in front of the ray (a ray leaving a surface must not hit
#: it again at t = 0 because of rounding).
EPS = 1e-9
#: The largest ``resolution`` of :meth:`Surface.mesh` (about 2.4 million triangles).
MAX_RESOLUTION = 1000
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
        o, d = rays(origins, directions)       # checked once: the tracer calls hit at every ray level
        with np.errstate(all="ignore"):
            h = self._hits(o, d)                # what intersect does, on the rays just checked
        t = np.where(h > EPS, h, np.inf).min(axis=1)
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

    def mesh(self, resolution: int = 32, extent: float = 2.0) -> tuple[np.ndarray, np.ndarray]:
        """A triangle mesh of the surface for three.js: ``(positions (n, 3), triangles (k, 3))``.

        resolution: samples around (and along) the surface, 3..:data:`MAX_RESOLUTION`.  extent: how
        far an unbounded surface (plane, infinite cylinder or cone, general quadric) is drawn from its
        reference point (half the side of the square or box shown); bounded surfaces ignore it.
        """
        n = within_budget(resolution, "resolution", cost=lambda v: v * v * 6, what="the mesh",
                          unit="triangle indices", limit=6 * MAX_RESOLUTION ** 2, minimum=3)
        extent = as_float(extent, "extent", positive=True)
        if extent > MAX_COORDINATE:
            raise ValueError(f"extent must be at most {MAX_COORDINATE:g}; got {extent:g}")
        with np.errstate(all="ignore"):
            positions, triangles = self._mesh(n, extent)
        return finite_result(np.asarray(positions, dtype=float).reshape(-1, 3), "extent", extent), \
            np.asarray(triangles, dtype=np.int64).reshape(-1, 3)

    @property
    def bounding_sphere(self):
        """``(center (3,), radius)`` of a sphere enclosing a bounded surface, or None for an unbounded
        one: a renderer skips a surface's own test for rays that miss it (Goldman §19.6.1)."""
        return None

    def _set_material(self, material):
        if material is None:
            material = Material()
        if not isinstance(material, Material):
            raise TypeError(f"material must be a goldman_lib.lighting.Material; got {type(material).__name__}")
        self.material = material


class Plane(Surface):
    """The plane through ``point`` with normal ``normal`` (Goldman §19.3): a ray meets it at
    ``t = N . (Q - P0) / N . d`` unless it runs parallel.  Bounds the half-space ``N . (P - Q) <= 0``.

    >>> Plane([0, 0, 1], [0, 0, 2]).intersect([[0, 0, 0], [0, 0, 0]], [[1, 0, 1], [1, 0, 0]]).tolist()
    [1.0, inf]
    """

    def __init__(self, point, normal, material: Material | None = None):
        self.point = _position(point, "point")
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

    def _mesh(self, n, extent):
        u, v, _ = frames.frame(self.unit_normal)
        s = np.linspace(-extent, extent, n)
        S, T = np.meshgrid(s, s, indexing="ij")
        return self.point + S[..., None] * u + T[..., None] * v, _grid(n, n)


class Sphere(Surface):
    """The sphere ``|P - C| = r`` (Goldman §19.4.1): substituting the ray gives the quadratic
    ``(d.d) t^2 + 2 d.(P0 - C) t + |P0 - C|^2 - r^2 = 0``; the outward normal at ``P`` is
    ``(P - C) / r``.

    >>> Sphere([1, 0, 0], 2).normal([[3, 0, 0]]).tolist()
    [[1.0, 0.0, 0.0]]
    """

    def __init__(self, center, radius, material: Material | None = None):
        self.center = _position(center, "center")
        self.radius = _length(radius, "radius")
        self._set_material(material)

    def _hits(self, o, d):
        oc = o - self.center
        return roots.quadratic_roots(np.einsum("ij,ij->i", d, d), 2 * np.einsum("ij,ij->i", d, oc),
                                np.einsum("ij,ij->i", oc, oc) - self.radius ** 2)

    def _normal(self, P):
        return (P - self.center) / self.radius

    def _contains(self, P):
        return np.einsum("ij,ij->i", P - self.center, P - self.center) <= self.radius ** 2

    @property
    def bounding_sphere(self):
        return self.center, self.radius

    def _mesh(self, n, extent):
        X = _unit_sphere_grid(n)
        return (self.center + self.radius * X).reshape(-1, 3), _grid(n, 2 * n, wrap=True)


# -- helpers: frames, grids, root finding ----------------------------------------------------------

def line_sphere_geometric(origins, directions, center, radius) -> dict:
    """Where lines meet a sphere, found geometrically (Goldman §19.4.1): project the center ``C`` onto
    the line ``P0 + t d`` (the foot at ``t_c = (C - P0) . d / (d . d)``), measure the distance ``q``
    from ``C`` to the line, and by Pythagoras the line meets the sphere ``sqrt(r^2 - q^2) / |d|`` on
    either side of the foot; no line meets it if ``q > r``.  The same parameters as the roots of the
    quadratic :meth:`Sphere.hits` solves, reached without forming it.

    Returns ``{"t": (N, 2)`` the two parameters, sorted, ``inf`` on a miss, ``"foot": (N,)`` t_c,
    ``"distance": (N,)`` q``}``.

    >>> r = line_sphere_geometric([[-5, 0, 0], [-5, 3, 0]], [[1, 0, 0], [1, 0, 0]], [0, 0, 0], 2)
    >>> r["t"].tolist(), r["foot"].tolist(), r["distance"].tolist()
    ([[3.0, 7.0], [inf, inf]], [5.0, 5.0], [0.0, 3.0])
    """
    o, d = rays(origins, directions)
    c = _position(center, "center")
    r = _length(radius, "radius")
    with np.errstate(all="ignore"):
        dd = np.einsum("ij,ij->i", d, d)
        foot = np.einsum("ij,ij->i", c - o, d) / dd
        q = np.linalg.norm(c - (o + foot[:, None] * d), axis=1)
        meets = q <= r
        half = np.sqrt(np.maximum(r * r - q * q, 0.0) / dd)
        t = np.where(meets[:, None], np.stack([foot - half, foot + half], axis=1), np.inf)
    if not (np.all(np.isfinite(foot)) and np.all(np.isfinite(q)) and not np.isnan(t).any()):
        raise ValueError("origins, directions, center and radius are too large in magnitude: the projection "
                         "of the center onto a line overflowed")
    return {"t": t, "foot": foot, "distance": q}


def _unit_vector(v, name: str) -> np.ndarray:
    v = as_points(v, name, ndim=1, dim=3)
    scale = np.abs(v).max()
    if scale == 0:
        raise ValueError(f"{name} must be a nonzero vector")
    v = v / scale
    return v / np.linalg.norm(v)


def _grid(rows: int, cols: int, wrap: bool = False) -> np.ndarray:
    """Triangles of a ``rows x cols`` vertex grid stored row by row (columns wrap around if asked)."""
    r, c = np.meshgrid(np.arange(rows - 1), np.arange(cols if wrap else cols - 1), indexing="ij")
    a = (r * cols + c).ravel()
    b = (r * cols + (c + 1) % cols).ravel()
    return np.concatenate([np.stack([a, b, b + cols], 1), np.stack([a, b + cols, a + cols], 1)])


def _unit_sphere_grid(n: int) -> np.ndarray:
    theta = np.linspace(0.0, np.pi, n)[:, None]
    phi = np.linspace(0.0, 2 * np.pi, 2 * n, endpoint=False)[None, :]
    return np.stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta) + 0 * phi], -1)


def _disc(center, u, v, radius_u, radius_v, n) -> tuple[np.ndarray, np.ndarray]:
    """A fan of triangles: an elliptic disc (a cap)."""
    phi = np.linspace(0.0, 2 * np.pi, n, endpoint=False)[:, None]
    rim = center + radius_u * np.cos(phi) * u + radius_v * np.sin(phi) * v
    k = np.arange(n)
    return np.vstack([center[None, :], rim]), np.stack([np.zeros(n, int), 1 + k, 1 + (k + 1) % n], 1)


def _join(*parts) -> tuple[np.ndarray, np.ndarray]:
    positions, triangles, offset = [], [], 0
    for pos, tri in parts:
        positions.append(np.asarray(pos, float).reshape(-1, 3))
        triangles.append(np.asarray(tri) + offset)
        offset += len(positions[-1])
    return np.vstack(positions), np.vstack(triangles)


def _interval_hull(lo1, hi1, lo2, hi2, s1, s2) -> np.ndarray:
    """Clip the union of two parameter intervals to the slab interval ``[s1, s2]`` and return the
    hull of what is left, ``(N, 2)`` (``[inf, inf]`` if nothing): the entry and exit of a ray through
    a convex solid (a capped cylinder or cone)."""
    a1, b1 = np.maximum(lo1, s1), np.minimum(hi1, s2)
    a2, b2 = np.maximum(lo2, s1), np.minimum(hi2, s2)
    ok1, ok2 = a1 <= b1, a2 <= b2
    lo = np.minimum(np.where(ok1, a1, np.inf), np.where(ok2, a2, np.inf))
    hi = np.maximum(np.where(ok1, b1, -np.inf), np.where(ok2, b2, -np.inf))
    hit = (ok1 | ok2) & np.isfinite(lo) & np.isfinite(hi)
    return np.stack([np.where(hit, lo, np.inf), np.where(hit, hi, np.inf)], axis=1)


def _slab(qz, ez, height):
    """Parameters where ``0 <= qz + t ez <= height``: ``(s1, s2)`` (all t, or none, for ez = 0)."""
    inside = (qz >= 0) & (qz <= height)
    with np.errstate(all="ignore"):
        a, b = -qz / ez, (height - qz) / ez
    s1 = np.where(ez != 0, np.minimum(a, b), np.where(inside, -np.inf, np.inf))
    s2 = np.where(ez != 0, np.maximum(a, b), np.where(inside, np.inf, -np.inf))
    return s1, s2


def _below(A, B, C):
    """Where ``A t^2 + B t + C <= 0`` along each ray: the union of two intervals ``lo1, hi1, lo2, hi2``."""
    r = roots.quadratic_roots(A, B, C)
    t1, t2 = r[:, 0], r[:, 1]
    real = np.isfinite(t2)
    inf = np.full_like(A, np.inf)
    empty = (inf, -inf)
    # A > 0: between the roots; A < 0: outside them (everything if no real root)
    lo1 = np.where(A > 0, np.where(real, t1, inf), np.where(A < 0, -inf, inf))
    hi1 = np.where(A > 0, np.where(real, t2, -inf), np.where(A < 0, np.where(real, t1, inf), -inf))
    lo2 = np.where((A < 0) & real, t2, empty[0])
    hi2 = np.where((A < 0) & real, inf, empty[1])
    # A = 0: the half-line B t + C <= 0 (all or nothing if B = 0 too)
    with np.errstate(all="ignore"):
        cut = -C / B
    lin_lo = np.where(B < 0, cut, np.where((B == 0) & (C <= 0), -inf, np.where(B > 0, -inf, inf)))
    lin_hi = np.where(B > 0, cut, np.where((B == 0) & (C <= 0), inf, np.where(B < 0, inf, -inf)))
    flat = A == 0
    return (np.where(flat, lin_lo, lo1), np.where(flat, lin_hi, hi1), np.where(flat, inf, lo2),
            np.where(flat, -inf, hi2))


def _bounded_height(height, name="height"):
    if height is None:
        return None
    h = as_float(height, name, positive=True)
    if h > MAX_COORDINATE:
        raise ValueError(f"{name} must be at most {MAX_COORDINATE:g}; got {h:g}")
    return h


def _position(x, name):
    """A point of a surface's geometry (a centre, a base, an apex): within :data:`MAX_COORDINATE`, the
    bound on ray origins, so the squared distances of the intersection stay representable."""
    P = as_points(x, name, ndim=1, dim=3)
    if np.abs(P).max() > MAX_COORDINATE:
        raise ValueError(f"{name} must have coordinates at most {MAX_COORDINATE:g} in magnitude "
                         f"(their squares must not overflow); got {np.abs(P).max():g}")
    return P


def _length(x, name):
    v = as_float(x, name, positive=True)
    if v > MAX_COORDINATE:
        raise ValueError(f"{name} must be at most {MAX_COORDINATE:g}; got {v:g}")
    return v


# -- §19.3 polygons ---------------------------------------------------------------------------------

class Polygon(Surface):
    """A planar polygon, convex or not (Goldman §19.3): the ray meets its plane (Newell's normal,
    §11.4, through the first vertex) at ``t = N . (V0 - P0) / N . d``; the hit counts when that point
    lies inside the polygon.  Convex polygons use the edge test (the point is on the inner side of
    every edge: ``(V_{i+1} - V_i) x (P - V_i)`` along ``N`` for all ``i``, boundary included);
    non-convex ones the even-odd ray-casting test of §11.7
    (:func:`goldman_lib.vector_geometry.ray_casting_inside`) in the polygon's plane.

    vertices: ``(n, 3)``, ``n >= 3``, in order around the polygon and coplanar (to ``1e-9`` of its
    size).  The normal follows the right-hand rule on the vertex order.  A polygon bounds no solid.

    >>> L = Polygon([[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0]])
    >>> L.convex, L.intersect([[0.5, 1.5, 1], [1.5, 1.5, 1]], [[0, 0, -1], [0, 0, -1]]).tolist()
    (False, [1.0, inf])
    """

    def __init__(self, vertices, material: Material | None = None):
        from goldman_lib import vector_geometry

        V = as_points(vertices, "vertices", dim=3)
        if len(V) >= 2 and np.array_equal(V[0], V[-1]):
            V = V[:-1]
        if len(V) < 3:
            raise ValueError(f"vertices must hold at least 3 distinct points; got {len(V)}")
        if np.abs(V).max() > MAX_COORDINATE:
            raise ValueError(f"vertices must have coordinates at most {MAX_COORDINATE:g} in magnitude "
                             f"(their squares must not overflow); got {np.abs(V).max():g}")
        size = np.abs(V - V[0]).max()
        if size == 0 or size > MAX_COORDINATE:
            raise ValueError("vertices must span a polygon of positive, representable size")
        N = vector_geometry.newell_normal((V - V[0]) / size)
        if np.linalg.norm(N) < 1e-12:
            raise ValueError("vertices must enclose a nonzero area (they are collinear or cancel out)")
        self.vertices = V
        self.unit_normal = N / np.linalg.norm(N)
        off = np.abs((V - V[0]) @ self.unit_normal).max()
        if off > 1e-9 * size:
            raise ValueError(f"vertices must be coplanar; a vertex lies {off:.3g} off the plane of the polygon")
        self._frame = frames.frame(self.unit_normal, V[1] - V[0])
        self._uv = (V - V[0]) @ self._frame[:2].T
        e = np.roll(self._uv, -1, axis=0) - self._uv
        turn = e[:, 0] * np.roll(e, -1, axis=0)[:, 1] - e[:, 1] * np.roll(e, -1, axis=0)[:, 0]
        self.convex = bool(np.all(turn >= -1e-12 * size ** 2))
        self._set_material(material)

    def inside(self, points) -> np.ndarray:
        """Whether points of the polygon's plane lie inside it (Goldman §19.3): (N,) booleans.

        >>> Polygon([[0, 0, 0], [1, 0, 0], [0, 1, 0]]).inside([[0.2, 0.2, 0], [1, 1, 0]]).tolist()
        [True, False]
        """
        P = np.atleast_2d(as_points(points, "points", ndim=None, dim=3))
        with np.errstate(all="ignore"):
            return self._inside(P)

    def _inside(self, P):
        from goldman_lib import vector_geometry

        uv = (P - self.vertices[0]) @ self._frame[:2].T
        if self.convex:
            a, b = self._uv, np.roll(self._uv, -1, axis=0)
            e = b - a
            side = e[None, :, 0] * (uv[:, None, 1] - a[None, :, 1]) - e[None, :, 1] * (uv[:, None, 0] - a[None, :, 0])
            scale = np.abs(self._uv).max() + np.abs(uv).max(axis=1)
            return np.all(side >= -1e-12 * scale[:, None] ** 2, axis=1)
        ok = np.all(np.isfinite(uv), axis=1)
        out = np.zeros(len(P), dtype=bool)
        if ok.any():
            out[ok] = vector_geometry.ray_casting_inside(self._uv, uv[ok])
        return out

    def _hits(self, o, d):
        nd = d @ self.unit_normal
        t = np.where(nd != 0, ((self.vertices[0] - o) @ self.unit_normal) / nd, np.inf)
        t = np.where(np.isfinite(t), t, np.inf)
        found = np.isfinite(t)
        if found.any():
            P = o[found] + t[found, None] * d[found]
            t[np.flatnonzero(found)[~self._inside(P)]] = np.inf
        return t[:, None]

    def _normal(self, P):
        return np.broadcast_to(self.unit_normal, P.shape)

    @property
    def bounding_sphere(self):
        c = self.vertices.mean(axis=0)
        return c, float(np.linalg.norm(self.vertices - c, axis=1).max())

    def _mesh(self, n, extent):
        return self.vertices.copy(), polygons.ear_clip(self._uv)


# -- §19.4 quadrics along an axis: elliptic cylinders and cones, and the circular ones -----------------

class _AxialQuadric(Surface):
    """An elliptic cylinder or cone in its own frame: local coordinates ``(x/a, y/b, z)`` with ``z``
    along the axis from ``origin``; bounded ones run over ``0 <= z <= height``."""

    _kind = ""

    def _setup(self, origin, axis, scales, height, major, capped, material):
        self.origin = _position(origin, "base" if self._kind == "cylinder" else "apex")
        self.axis = _unit_vector(axis, "axis")
        m = None if major is None else _unit_vector(major, "major")
        if m is not None and abs(float(m @ self.axis)) > 1 - 1e-9:
            raise ValueError("major must not be parallel to axis (it sets the direction of the first radius)")
        self.height = _bounded_height(height)
        if not isinstance(capped, (bool, np.bool_)):
            raise TypeError(f"capped must be True or False; got {capped!r}")
        self.capped = bool(capped) and self.height is not None
        self._F = frames.frame(self.axis, m)
        self._scale = np.array([1.0 / scales[0], 1.0 / scales[1], 1.0])
        self._set_material(material)

    def _local(self, P):
        return ((P - self.origin) @ self._F.T) * self._scale

    def _local_dir(self, d):
        return (d @ self._F.T) * self._scale

    # Each subclass (elliptic cylinder, elliptic cone) defines ``_lateral(q, e)`` -> the quadratic's
    # coefficients (A, B, C) in local coordinates and ``_lateral_residual(L)`` -> its implicit value.

    def _hits(self, o, d):
        q, e = self._local(o), self._local_dir(d)
        A, B, C = self._lateral(q, e)
        if self.height is None or not self.capped:
            t = roots.quadratic_roots(A, B, C)
            z = q[:, 2:3] + t * e[:, 2:3]
            keep = np.isfinite(t) & (z >= (0 if self._kind == "cone" else -np.inf))
            if self.height is not None:
                keep &= (z >= 0) & (z <= self.height)
            return np.sort(np.where(keep, t, np.inf), axis=1)
        s1, s2 = _slab(q[:, 2], e[:, 2], self.height)
        return _interval_hull(*_below(A, B, C), s1, s2)

    def _which(self, L):
        """0 for the lateral surface, 1 for the bottom cap, 2 for the top cap (nearest residual)."""
        res = [np.abs(self._lateral_residual(L))]
        if self.capped:
            res.append(np.abs(L[:, 2]) if self._kind == "cylinder" else np.full(len(L), np.inf))
            res.append(np.abs(L[:, 2] - self.height))
        return np.argmin(np.stack(res, 1), axis=1)

    def _normal(self, P):
        L = self._local(P)
        g = self._gradient(L)
        which = self._which(L)
        g[which == 1] = [0.0, 0.0, -1.0]
        g[which == 2] = [0.0, 0.0, 1.0]
        g = np.where((which == 0)[:, None], g * self._scale, g)
        return g @ self._F

    def _contains(self, P):
        if self.height is not None and not self.capped:
            raise TypeError(f"an uncapped {self._kind} bounds no solid: it has no inside (use capped=True)")
        L = self._local(P)
        inside = self._lateral_residual(L) <= 0
        if self._kind == "cone":
            inside &= L[:, 2] >= 0
        if self.height is not None:
            inside &= (L[:, 2] >= 0) & (L[:, 2] <= self.height)
        return inside

    @property
    def bounding_sphere(self):
        if self.height is None:
            return None
        h, widest = self.height, 1.0 / self._scale[:2].min()     # the largest semi-axis (or tangent, for a cone)
        across = widest if self._kind == "cylinder" else h * widest
        return self.origin + h / 2 * self.axis, float(np.hypot(h / 2, across))

    def _to_world(self, L):
        return self.origin + (L / self._scale) @ self._F


class EllipticCylinder(_AxialQuadric):
    """The elliptic cylinder ``(x/a)^2 + (y/b)^2 = 1`` about an axis (Goldman §19.4.2): in the frame of
    the axis the ray gives the quadratic ``A t^2 + B t + C = 0`` with ``A = ex^2 + ey^2``,
    ``B = 2 (qx ex + qy ey)``, ``C = qx^2 + qy^2 - 1`` (scaled local origin ``q``, direction ``e``).

    base: a point of the axis (the bottom end if bounded).  axis: its direction.  radii: ``(a, b)``,
    ``a`` along ``major`` (projected off the axis; by default a direction chosen from the axis).
    height: None for the infinite cylinder, otherwise it runs from ``base`` along ``+axis`` for that
    length.  capped: a bounded cylinder is closed by its two elliptic end discs (a solid, as CSG
    needs: ``hits`` gives its entry and exit, found by clipping the parameter interval inside the
    infinite cylinder to the slab between the caps); ``capped=False`` leaves an open tube (its
    wall hits only; no inside).  The infinite cylinder bounds the solid ``(x/a)^2 + (y/b)^2 <= 1``.

    >>> c = EllipticCylinder([0, 0, 0], [0, 0, 1], [2, 1], height=3, major=[1, 0, 0])
    >>> c.hits([[-5, 0, 1], [0, -5, 1], [0, 0, -1]], [[1, 0, 0], [0, 1, 0], [0, 0, 1]]).tolist()
    [[3.0, 7.0], [4.0, 6.0], [1.0, 4.0]]
    """

    _kind = "cylinder"

    def __init__(self, base, axis, radii, height=None, major=None, capped: bool = True,
                 material: Material | None = None):
        r = as_points(radii, "radii", ndim=1, dim=2)
        self.radii = (_length(r[0], "radii[0]"), _length(r[1], "radii[1]"))
        self._setup(base, axis, self.radii, height, major, capped, material)
        self.base = self.origin

    def _lateral(self, q, e):
        return (e[:, 0] ** 2 + e[:, 1] ** 2, 2 * (q[:, 0] * e[:, 0] + q[:, 1] * e[:, 1]),
                q[:, 0] ** 2 + q[:, 1] ** 2 - 1.0)

    def _lateral_residual(self, L):
        return np.hypot(L[:, 0], L[:, 1]) - 1.0

    def _gradient(self, L):
        return np.stack([L[:, 0], L[:, 1], np.zeros(len(L))], 1)

    def _mesh(self, n, extent):
        u, v, w = self._F
        z0, z1 = (0.0, self.height) if self.height is not None else (-extent, extent)
        phi = np.linspace(0, 2 * np.pi, 2 * n, endpoint=False)
        z = np.linspace(z0, z1, n)
        L = np.stack(np.broadcast_arrays(np.cos(phi)[None, :], np.sin(phi)[None, :], z[:, None]), -1)
        parts = [(self._to_world(L.reshape(-1, 3)), _grid(n, 2 * n, wrap=True))]
        if self.capped:
            a, b = self.radii
            parts += [_disc(self.origin, u, v, a, b, 2 * n), _disc(self.origin + self.height * w, u, v, a, b, 2 * n)]
        return _join(*parts)


class Cylinder(EllipticCylinder):
    """The circular cylinder of radius ``radius`` about the axis through ``base`` along ``axis``
    (Goldman §19.4.2): ``|P - base|^2 - ((P - base) . w)^2 = r^2``, ``w`` the unit axis; infinite when
    ``height`` is None, otherwise from ``base`` (its bottom end) along ``+axis`` for ``height``, closed
    by its two end discs unless ``capped=False`` (see :class:`EllipticCylinder`).  Outward normal on the
    wall: the component of ``P - base`` perpendicular to the axis, over ``r``; on the caps ``-w`` and ``+w``.

    >>> c = Cylinder([0, 0, 0], [0, 0, 1], 1, height=2)
    >>> c.hits([[-3, 0, 1], [0.5, 0, 5]], [[1, 0, 0], [0, 0, -1]]).tolist()     # across; down the axis
    [[2.0, 4.0], [3.0, 5.0]]
    >>> c.normal([[0, 1, 1], [0.5, 0, 2]]).tolist()
    [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    """

    def __init__(self, base, axis, radius, height=None, capped: bool = True, material: Material | None = None):
        self.radius = _length(radius, "radius")
        super().__init__(base, axis, (self.radius, self.radius), height, None, capped, material)


def _half_angle(angle, name):
    a = as_float(angle, name)
    if not 0 < a < 90:
        raise ValueError(f"{name} must lie strictly between 0 and 90 degrees; got {a}")
    return a


class EllipticCone(_AxialQuadric):
    """The elliptic cone ``(x / tan α)^2 + (y / tan β)^2 = z^2``, ``z >= 0`` (Goldman §19.4.3): one nappe
    opening from ``apex`` along ``+axis`` with half-angles ``α`` (towards ``major``) and ``β`` in
    degrees.  In the scaled frame the ray gives ``A = ex^2 + ey^2 - ez^2``, ``B = 2 (qx ex + qy ey -
    qz ez)``, ``C = qx^2 + qy^2 - qz^2``; roots on the other nappe (``z < 0``) are dropped.

    height: None for the infinite nappe; otherwise the cone runs from the apex to ``height`` along
    the axis, closed by its base disc unless ``capped=False`` (entry and exit of the convex solid,
    from the parameters where the quadratic is ``<= 0`` clipped to the slab ``0 <= z <= height``).

    >>> k = EllipticCone([0, 0, 0], [0, 0, 1], [45, 45], height=2)
    >>> k.hits([[-5, 0, 1]], [[1, 0, 0]]).round(12).tolist()   # the circle of radius 1 at height 1
    [[4.0, 6.0]]
    """

    _kind = "cone"

    def __init__(self, apex, axis, half_angles, height=None, major=None, capped: bool = True,
                 material: Material | None = None):
        a = as_points(half_angles, "half_angles", ndim=1, dim=2)
        self.half_angles = (_half_angle(a[0], "half_angles[0]"), _half_angle(a[1], "half_angles[1]"))
        tans = np.tan(np.radians(self.half_angles))
        self._setup(apex, axis, tans, height, major, capped, material)
        self.apex = self.origin

    def _lateral(self, q, e):
        return (e[:, 0] ** 2 + e[:, 1] ** 2 - e[:, 2] ** 2,
                2 * (q[:, 0] * e[:, 0] + q[:, 1] * e[:, 1] - q[:, 2] * e[:, 2]),
                q[:, 0] ** 2 + q[:, 1] ** 2 - q[:, 2] ** 2)

    def _lateral_residual(self, L):
        return (np.hypot(L[:, 0], L[:, 1]) - L[:, 2]) / np.sqrt(2.0)

    def _gradient(self, L):
        return np.stack([L[:, 0], L[:, 1], -L[:, 2]], 1)

    def _mesh(self, n, extent):
        u, v, w = self._F
        h = self.height if self.height is not None else extent
        phi = np.linspace(0, 2 * np.pi, 2 * n, endpoint=False)
        z = np.linspace(0.0, h, n)
        L = np.stack(np.broadcast_arrays(z[:, None] * np.cos(phi)[None, :], z[:, None] * np.sin(phi)[None, :],
                                         z[:, None]), -1)
        parts = [(self._to_world(L.reshape(-1, 3)), _grid(n, 2 * n, wrap=True))]
        if self.capped:
            a, b = h / self._scale[:2]
            parts.append(_disc(self.origin + h * w, u, v, a, b, 2 * n))
        return _join(*parts)


class Cone(EllipticCone):
    """The circular cone with vertex ``apex``, opening along ``+axis`` with half-angle ``half_angle``
    degrees (Goldman §19.4.3): ``((P - V) . w)^2 = |P - V|^2 cos^2 θ`` on the nappe ``(P - V) . w >= 0``;
    infinite when ``height`` is None, otherwise cut at ``height`` along the axis and closed by its
    base disc unless ``capped=False`` (see :class:`EllipticCone`).

    >>> k = Cone([0, 0, 0], [0, 0, 1], 45, height=2)
    >>> k.intersect([[-5, 0, 1], [0, 0, 5]], [[1, 0, 0], [0, 0, -1]]).round(12).tolist()
    [4.0, 3.0]
    """

    def __init__(self, apex, axis, half_angle, height=None, capped: bool = True, material: Material | None = None):
        self.half_angle = _half_angle(half_angle, "half_angle")
        super().__init__(apex, axis, (self.half_angle, self.half_angle), height, None, capped, material)


class Ellipsoid(Surface):
    """The ellipsoid ``(x/a)^2 + (y/b)^2 + (z/c)^2 = 1`` about ``center`` (Goldman §19.4.4), its
    semi-axes along the rows of ``axes`` (orthonormal; default the coordinate axes): the ray is
    mapped by the scaling that takes the ellipsoid to the unit sphere (parameters do not change)
    and meets that sphere as in §19.4.1.  Normal: the gradient ``2 (x/a^2, y/b^2, z/c^2)`` taken back
    to world coordinates.

    >>> e = Ellipsoid([0, 0, 0], [3, 2, 1])
    >>> e.hits([[-5, 0, 0], [0, 0, -5]], [[1, 0, 0], [0, 0, 1]]).round(12).tolist()
    [[2.0, 8.0], [4.0, 6.0]]
    """

    def __init__(self, center, radii, axes=None, material: Material | None = None):
        self.center = _position(center, "center")
        r = as_points(radii, "radii", ndim=1, dim=3)
        self.radii = tuple(_length(r[k], f"radii[{k}]") for k in range(3))
        if axes is None:
            F = np.eye(3)
        else:
            F = as_points(axes, "axes", ndim=2, dim=3)
            if F.shape != (3, 3):
                raise ValueError(f"axes must be a (3, 3) array of three orthonormal rows; got shape {F.shape}")
            norms = np.linalg.norm(F, axis=1)
            if np.any(norms == 0) or not np.all(np.isfinite(norms)):
                raise ValueError("axes must hold three nonzero rows")
            F = F / norms[:, None]
            if np.abs(F @ F.T - np.eye(3)).max() > 1e-9:
                raise ValueError("axes must be mutually perpendicular")
        self.axes = F
        self._inv = 1.0 / np.array(self.radii)
        self._set_material(material)

    def _hits(self, o, d):
        q = ((o - self.center) @ self.axes.T) * self._inv
        e = (d @ self.axes.T) * self._inv
        return roots.quadratic_roots(np.einsum("ij,ij->i", e, e), 2 * np.einsum("ij,ij->i", e, q),
                                np.einsum("ij,ij->i", q, q) - 1.0)

    def _normal(self, P):
        L = (P - self.center) @ self.axes.T
        return (L * self._inv ** 2) @ self.axes

    def _contains(self, P):
        L = ((P - self.center) @ self.axes.T) * self._inv
        return np.einsum("ij,ij->i", L, L) <= 1.0

    @property
    def bounding_sphere(self):
        return self.center, max(self.radii)

    def _mesh(self, n, extent):
        X = _unit_sphere_grid(n).reshape(-1, 3)
        return self.center + (X * np.array(self.radii)) @ self.axes, _grid(n, 2 * n, wrap=True)


# -- §19.5 general quadrics --------------------------------------------------------------------------

def _quadric_matrix(coefficients) -> np.ndarray:
    c = as_float_array(coefficients, "coefficients")
    check_finite(c, "coefficients")
    if c.shape == (10,):
        A, B, C, D, E, F, G, H, I, J = c
        Q = np.array([[A, D / 2, E / 2, G / 2], [D / 2, B, F / 2, H / 2], [E / 2, F / 2, C, I / 2],
                      [G / 2, H / 2, I / 2, J]])
    elif c.shape == (4, 4):
        scale = np.abs(c).max()
        if np.abs(c - c.T).max() > 1e-12 * scale:
            raise ValueError("coefficients must be a symmetric 4x4 matrix (or the 10 coefficients A..J)")
        Q = (c + c.T) / 2
    else:
        raise ValueError(f"coefficients must be the 10 numbers A..J or a symmetric (4, 4) matrix; got shape {c.shape}")
    scale = np.abs(Q).max()
    if scale == 0 or np.abs(Q[:3]).max() == 0:
        raise ValueError("coefficients must describe a surface: the quadric's x, y, z terms are all zero")
    return Q


class Quadric(Surface):
    """The general quadric surface ``f(P) = [P 1] Q [P 1]^T = 0`` (Goldman §19.5), ``Q`` symmetric 4x4;
    in coefficients ``f = A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J``.

    Along the ray ``[P0 1] + t [d 0]`` the equation is the quadratic ``a t^2 + b t + c`` with
    ``a = [d 0] Q [d 0]^T``, ``b = 2 [P0 1] Q [d 0]^T``, ``c = f(P0)``.  The normal is the gradient
    ``2 (P Q33 + q)`` (``Q33`` the upper-left 3x3 block, ``q`` the last column's first three
    entries), pointing to where ``f`` grows; the solid is ``f <= 0``.

    coefficients: the 10 numbers ``A..J`` or the symmetric ``(4, 4)`` matrix ``Q`` (scaled internally:
    a multiple of ``Q`` is the same surface).

    >>> hyperboloid = Quadric([1, 1, -1, 0, 0, 0, 0, 0, 0, -1])      # x^2 + y^2 - z^2 = 1
    >>> hyperboloid.hits([[-5, 0, 0], [0, 0, -5]], [[1, 0, 0], [0, 0, 1]]).tolist()
    [[4.0, 6.0], [inf, inf]]
    """

    def __init__(self, coefficients, material: Material | None = None):
        Q = _quadric_matrix(coefficients)
        self.matrix = Q
        self._Q = Q / np.abs(Q).max()
        self._set_material(material)

    def value(self, points) -> np.ndarray:
        """``f(P)`` at points (negative inside): (N,).

        >>> Quadric([1, 1, 1, 0, 0, 0, 0, 0, 0, -4]).value([[2, 0, 0], [0, 0, 0]]).tolist()
        [0.0, -4.0]
        """
        P = np.atleast_2d(as_points(points, "points", ndim=None, dim=3))
        with np.errstate(all="ignore"):
            H = np.hstack([P, np.ones((len(P), 1))])
            return finite_result(np.einsum("ij,jk,ik->i", H, self.matrix, H), "points")

    def _hits(self, o, d):
        Q3, q, J = self._Q[:3, :3], self._Q[:3, 3], self._Q[3, 3]
        dQ = d @ Q3
        oQ = o @ Q3
        a = np.einsum("ij,ij->i", dQ, d)
        b = 2 * (np.einsum("ij,ij->i", oQ, d) + d @ q)
        c = np.einsum("ij,ij->i", oQ, o) + 2 * (o @ q) + J
        return roots.quadratic_roots(a, b, c)

    def _normal(self, P):
        return P @ self._Q[:3, :3] + self._Q[:3, 3]

    def _contains(self, P):
        H = np.hstack([P, np.ones((len(P), 1))])
        return np.einsum("ij,jk,ik->i", H, self._Q, H) <= 0

    def _mesh(self, n, extent):
        """Marching tetrahedra on an ``n^3`` grid over the cube of half-side ``extent`` about the
        quadric's centre ``-q Q33^-1`` (the origin if ``Q33`` is singular, as for a paraboloid)."""
        Q3, q = self._Q[:3, :3], self._Q[:3, 3]
        center = np.zeros(3)
        if abs(np.linalg.det(Q3)) > 1e-9 * np.abs(Q3).max() ** 3:
            center = -np.linalg.solve(Q3, q)
            if not np.all(np.isfinite(center)) or np.abs(center).max() > MAX_COORDINATE:
                center = np.zeros(3)
        s = np.linspace(-extent, extent, n)
        X = center + np.stack(np.meshgrid(s, s, s, indexing="ij"), -1).reshape(-1, 3)
        H = np.hstack([X, np.ones((len(X), 1))])
        f = np.einsum("ij,jk,ik->i", H, self._Q, H)
        return _marching_tetrahedra(X, f, n)


#: The six tetrahedra of a cube (corner k has bits x = k&1, y = k>>1&1, z = k>>2&1) around its diagonal 0-7.
_CUBE_TETS = np.array([[0, 1, 3, 7], [0, 3, 2, 7], [0, 2, 6, 7], [0, 6, 4, 7], [0, 4, 5, 7], [0, 5, 1, 7]])


def _marching_tetrahedra(X, f, n):
    """Triangles of the zero set of ``f`` sampled on an ``n^3`` grid (vertices ``X`` in ``ij`` order)."""
    i, j, k = np.meshgrid(np.arange(n - 1), np.arange(n - 1), np.arange(n - 1), indexing="ij")
    base = (i * n * n + j * n + k).ravel()
    corner = np.array([(b & 1) * n * n + ((b >> 1) & 1) * n + ((b >> 2) & 1) for b in range(8)])
    tets = (base[:, None, None] + corner[_CUBE_TETS][None]).reshape(-1, 4)
    inside = f[tets] < 0
    count = inside.sum(1)
    tets, inside, count = tets[(count > 0) & (count < 4)], inside[(count > 0) & (count < 4)], count[(count > 0) & (count < 4)]
    if len(tets) == 0:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)
    # flip so that at most two corners are inside, then order corners: inside first
    flip = count > 2
    inside = np.where(flip[:, None], ~inside, inside)
    order = np.argsort(~inside, axis=1, kind="stable")
    T = np.take_along_axis(tets, order, 1)
    c = np.where(flip, 4 - count, count)

    def cut(a, b):
        fa, fb = f[a], f[b]
        w = np.where(fa != fb, fa / (fa - fb), 0.5)[:, None]
        return X[a] + w * (X[b] - X[a])

    one, two = c == 1, c == 2
    t1 = T[one]
    tri1 = np.stack([cut(t1[:, 0], t1[:, 1]), cut(t1[:, 0], t1[:, 2]), cut(t1[:, 0], t1[:, 3])], 1)
    t2 = T[two]
    p = [cut(t2[:, 0], t2[:, 2]), cut(t2[:, 0], t2[:, 3]), cut(t2[:, 1], t2[:, 3]), cut(t2[:, 1], t2[:, 2])]
    tri2 = np.concatenate([np.stack([p[0], p[1], p[2]], 1), np.stack([p[0], p[2], p[3]], 1)])
    tris = np.concatenate([tri1, tri2]).reshape(-1, 3)
    return tris, np.arange(len(tris)).reshape(-1, 3)


# -- §19.6 tori ---------------------------------------------------------------------------------------

class Torus(Surface):
    """The torus swept by a circle of radius ``r`` whose centre runs around a circle of radius ``R``
    about ``axis`` through ``center`` (Goldman §19.6): in the torus's frame (``z`` along the axis)
    ``(|P|^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + y^2)``.  Along a ray this is a quartic in ``t``; we solve it
    for every ray at once after moving each ray's origin to its point nearest the centre (so the cubic
    term vanishes) and scaling lengths by ``R + r``, so the quartic is well conditioned whatever the
    ray: Ferrari's closed form, vectorised, polished by Newton's method (``numpy.roots`` of the same
    quartic agrees; :func:`goldman_lib.roots.real_roots`, the companion-matrix solver, does too and is about ten times
    slower).

    The bounding test of §19.6.1 (``bound=True``): a ray that misses the bounding sphere of radius
    ``R + r``, or the slab ``|z| <= r`` inside it, cannot meet the torus and skips the quartic;
    :attr:`quartics_solved` counts the quartics the last call solved.  The normal is the gradient
    ``4 (|P|^2 + R^2 - r^2) P - 8 R^2 (x, y, 0)``; the solid is where the left side is below the right.

    >>> T = Torus([0, 0, 0], [0, 0, 1], 2, 0.5)
    >>> T.hits([[-5, 0, 0], [0, 0, 5], [-5, 0, 1]], [[1, 0, 0], [0, 0, -1], [1, 0, 0]]).round(12).tolist()
    [[2.5, 3.5, 6.5, 7.5], [inf, inf, inf, inf], [inf, inf, inf, inf]]
    >>> T.quartics_solved         # through both tubes, down the hole: solved; above the slab |z| <= r: skipped
    2
    """

    def __init__(self, center, axis, R, r, bound: bool = True, material: Material | None = None):
        self.center = _position(center, "center")
        self.axis = _unit_vector(axis, "axis")
        self.R = _length(R, "R")
        self.r = _length(r, "r")
        if not isinstance(bound, (bool, np.bool_)):
            raise TypeError(f"bound must be True or False; got {bound!r}")
        self.bound = bool(bound)
        self._F = frames.frame(self.axis)
        self.quartics_solved = 0
        self._set_material(material)

    def quartic(self, origin, direction) -> np.ndarray:
        """The coefficients ``[c4, c3, c2, c1, c0]`` of the torus quartic along one ray, in the ray's
        own parameter (Goldman §19.6), highest first as ``numpy.roots`` takes them.

        >>> Torus([0, 0, 0], [0, 0, 1], 2, 1).quartic([-4, 0, 0], [1, 0, 0]).tolist()
        [1.0, -16.0, 86.0, -176.0, 105.0]
        """
        o = as_points(origin, "origin", ndim=1, dim=3)
        d = as_points(direction, "direction", ndim=1, dim=3)
        for v, name in ((o, "origin"), (d, "direction")):
            if np.abs(v).max() > MAX_COORDINATE:
                raise ValueError(f"{name} must have coordinates at most {MAX_COORDINATE:g} in magnitude")
        if not np.any(d != 0):
            raise ValueError("direction must be a nonzero vector")
        q = (o - self.center) @ self._F.T
        e = d @ self._F.T
        R2, K = self.R ** 2, q @ q + self.R ** 2 - self.r ** 2
        dd, qd = e @ e, q @ e
        with np.errstate(all="ignore"):
            c = np.array([dd * dd, 4 * dd * qd, 2 * dd * K + 4 * qd * qd - 4 * R2 * (e[0] ** 2 + e[1] ** 2),
                          4 * qd * K - 8 * R2 * (q[0] * e[0] + q[1] * e[1]), K * K - 4 * R2 * (q[0] ** 2 + q[1] ** 2)])
        return finite_result(c, "origin", why="is too far from the torus")

    def _hits(self, o, d):
        S = self.R + self.r
        q = ((o - self.center) @ self._F.T) / S
        e = d @ self._F.T
        length = np.linalg.norm(e / np.abs(e).max(axis=1, keepdims=True), axis=1) * np.abs(e).max(axis=1)
        e = e / length[:, None]
        t0 = -np.einsum("ij,ij->i", q, e)
        p = q + t0[:, None] * e                                      # the ray's point nearest the centre
        R, r = self.R / S, self.r / S
        out = np.full((len(o), 4), np.inf)
        pending = np.isfinite(t0) & np.all(np.isfinite(p), axis=1)
        if self.bound:
            pp = np.einsum("ij,ij->i", p, p)
            half = np.sqrt(np.maximum(1.0 - pp, 0.0))
            s1, s2 = _slab(p[:, 2] + r, e[:, 2], 2 * r)
            pending &= (pp <= 1.0) & (np.maximum(-half, s1) <= np.minimum(half, s2))
        rows = np.flatnonzero(pending)
        self.quartics_solved = int(len(rows))
        if len(rows) == 0:
            return out
        p, e = p[rows], e[rows]
        K = np.einsum("ij,ij->i", p, p) + R * R - r * r
        c = np.stack([np.ones(len(rows)), np.zeros(len(rows)), 2 * K - 4 * R * R * (e[:, 0] ** 2 + e[:, 1] ** 2),
                      -8 * R * R * (p[:, 0] * e[:, 0] + p[:, 1] * e[:, 1]),
                      K * K - 4 * R * R * (p[:, 0] ** 2 + p[:, 1] ** 2)], 1)
        s = roots.depressed_quartic_roots(c[:, 2], c[:, 3], c[:, 4])
        out[rows] = (t0[rows, None] + s) * S / length[rows, None]
        out[~np.isfinite(out)] = np.inf
        return np.sort(out, axis=1)

    @property
    def bounding_sphere(self):
        return self.center, self.R + self.r

    def _f_parts(self, P):
        L = (P - self.center) @ self._F.T
        return L, np.einsum("ij,ij->i", L, L) + self.R ** 2 - self.r ** 2

    def _normal(self, P):
        L, K = self._f_parts(P)
        g = 4 * K[:, None] * L - 8 * self.R ** 2 * L * np.array([1.0, 1.0, 0.0])
        return g @ self._F

    def _contains(self, P):
        L, K = self._f_parts(P)
        return K * K <= 4 * self.R ** 2 * (L[:, 0] ** 2 + L[:, 1] ** 2)

    def _mesh(self, n, extent):
        u = np.linspace(0, 2 * np.pi, 2 * n, endpoint=False)[:, None]
        v = np.linspace(0, 2 * np.pi, n, endpoint=False)[None, :]
        ring = self.R + self.r * np.cos(v)
        L = np.stack(np.broadcast_arrays(ring * np.cos(u), ring * np.sin(u), self.r * np.sin(v)), -1).reshape(-1, 3)
        tri = _grid(2 * n + 1, n, wrap=True)
        tri = tri % (2 * n * n)                                      # the last row of the grid is the first
        return self.center + L @ self._F, tri


# -- §19.7 surfaces of revolution ---------------------------------------------------------------------

#: The highest degree of a profile polynomial (its square along a ray has degree 12 = MAX_DEGREE).
MAX_PROFILE_DEGREE = MAX_DEGREE // 2


class SurfaceOfRevolution(Surface):
    """The surface swept by the profile curve ``ρ = r(z)``, ``0 <= z <= height``, turning about an axis
    (Goldman §19.7); ``z`` is measured from ``base`` along ``+axis`` and ``ρ`` is the distance from the
    axis.  Our formulation: the profile is a polynomial ``r(z) = c0 + c1 z + ... + cm z^m``
    (``profile = [c0, ..., cm]``, ``m <=`` :data:`MAX_PROFILE_DEGREE`), positive on ``[0, height]``;
    a point is on the surface when ``x^2 + y^2 = r(z)^2``, so along a ray ``P(t)`` the intersection is
    the single polynomial equation ``x(t)^2 + y(t)^2 - r(z(t))^2 = 0`` of degree ``max(2, 2m)``,
    solved for every ray at once (:func:`goldman_lib.roots.real_roots`), keeping roots with ``0 <= z <= height``.  (The
    book reduces the problem to the plane of the profile; squaring ``ρ`` is the same reduction
    written as one polynomial in ``t``.)  capped: the end discs ``z = 0`` and ``z = height`` close
    the solid ``x^2 + y^2 <= r(z)^2``.  Normal on the wall: the gradient ``(x, y, -r(z) r'(z))``.

    >>> vase = SurfaceOfRevolution([0, 0, 0], [0, 0, 1], [1, 0, -0.25], 1)     # r(z) = 1 - z^2/4
    >>> vase.hits([[-5, 0, 1], [0, 0, -1]], [[1, 0, 0], [0, 0, 1]]).round(12).tolist()   # r(1) = 0.75; up the axis
    [[4.25, 5.75, inf, inf, inf, inf], [1.0, 2.0, inf, inf, inf, inf]]
    """

    def __init__(self, base, axis, profile, height, capped: bool = True, material: Material | None = None):
        self.base = _position(base, "base")
        self.axis = _unit_vector(axis, "axis")
        c = as_float_array(profile, "profile")
        if c.ndim != 1 or len(c) == 0:
            raise ValueError(f"profile must be a list of polynomial coefficients [c0, c1, ...]; got shape {c.shape}")
        c = check_finite(c, "profile")
        c = np.trim_zeros(c, "b") if np.any(c != 0) else c[:1]
        if len(c) - 1 > MAX_PROFILE_DEGREE:
            raise ValueError(f"profile must have degree at most {MAX_PROFILE_DEGREE}; got degree {len(c) - 1}")
        self.height = _length(height, "height")
        z = np.linspace(0.0, self.height, 1025)
        with np.errstate(all="ignore"):
            rz = np.polynomial.polynomial.polyval(z, c)
            interior = np.roots(c[::-1]) if len(c) > 1 else np.array([])
        interior = interior.real[(np.abs(interior.imag) < 1e-12) & (interior.real >= 0) & (interior.real <= self.height)]
        if not np.all(np.isfinite(rz)) or rz.min() <= 0 or len(interior):
            raise ValueError("profile must be positive on [0, height] (the radius r(z) of the surface of revolution)")
        if rz.max() > MAX_COORDINATE:
            raise ValueError("profile must stay below 1e60 on [0, height]")
        if not isinstance(capped, (bool, np.bool_)):
            raise TypeError(f"capped must be True or False; got {capped!r}")
        self.profile = c
        self.capped = bool(capped)
        self._F = frames.frame(self.axis)
        self._S = max(self.height, float(rz.max()))
        crit = np.roots(np.polynomial.polynomial.polyder(c)[::-1]) if len(c) > 2 else np.array([])
        crit = crit.real[(np.abs(crit.imag) < 1e-9) & (crit.real >= 0) & (crit.real <= self.height)]
        self._rmax = float(max(rz.max(), *np.polynomial.polynomial.polyval(crit, c))) if len(crit) else float(rz.max())
        self._set_material(material)

    def radius(self, z) -> np.ndarray:
        """The profile radius ``r(z)``.

        >>> SurfaceOfRevolution([0, 0, 0], [0, 0, 1], [1, 0, -0.25], 1).radius([0, 1]).tolist()
        [1.0, 0.75]
        """
        z = check_finite(as_float_array(z, "z"), "z")
        with np.errstate(all="ignore"):
            return finite_result(np.polynomial.polynomial.polyval(z, self.profile), "z", z)

    def _hits(self, o, d):
        S = self._S
        q = ((o - self.base) @ self._F.T) / S
        e = d @ self._F.T
        big = np.abs(e).max(axis=1, keepdims=True)
        length = np.linalg.norm(e / big, axis=1) * big[:, 0]
        e = e / length[:, None]
        mid = np.array([0.0, 0.0, self.height / S / 2])
        t0 = -np.einsum("ij,ij->i", q - mid, e)
        p = q + t0[:, None] * e
        # the bounding test (as for the torus, §19.6.1): a ray whose line misses the bounding sphere
        # (about the axis's midpoint, radius sqrt((h/2)^2 + max r^2)) skips the polynomial
        reach = (self.height / 2) ** 2 + self._rmax ** 2
        near = np.einsum("ij,ij->i", p - mid, p - mid) <= reach / S ** 2 * (1 + 1e-9)
        out = np.full((len(o), max(2, 2 * (len(self.profile) - 1)) + 2 * self.capped), np.inf)
        if not near.any():
            return out
        rows = np.flatnonzero(near)
        q, e, p, t0, length = q[rows], e[rows], p[rows], t0[rows], length[rows]
        o = o[rows]
        m = len(self.profile) - 1
        cs = self.profile * S ** (np.arange(m + 1) - 1.0)              # r in units of S: r_S(z) = r(S z) / S
        # r_S(pz + s ez) as a polynomial in s (ascending), by Horner's rule on polynomials
        poly = np.zeros((len(o), m + 1))
        poly[:, 0] = cs[m]
        for k in range(m - 1, -1, -1):
            shifted = np.zeros_like(poly)
            shifted[:, 1:] = poly[:, :-1] * e[:, 2:3]
            poly = poly * p[:, 2:3] + shifted
            poly[:, 0] += cs[k]
        D = max(2, 2 * m)
        g = np.zeros((len(o), D + 1))
        for i in range(m + 1):
            for j in range(m + 1):
                g[:, i + j] -= poly[:, i] * poly[:, j]
        g[:, 0] += p[:, 0] ** 2 + p[:, 1] ** 2
        g[:, 1] += 2 * (p[:, 0] * e[:, 0] + p[:, 1] * e[:, 1])
        g[:, 2] += e[:, 0] ** 2 + e[:, 1] ** 2
        scale = np.abs(g).max(axis=1, keepdims=True)
        gs = np.divide(g, scale, out=np.zeros_like(g), where=scale > 0)[:, ::-1]
        s = roots.polynomial_roots(np.where(np.isfinite(gs), gs, 0.0))
        z = p[:, 2:3] + s * e[:, 2:3]
        hs = self.height / S
        s = np.where(np.isfinite(s) & (z >= 0) & (z <= hs), s, np.inf)
        parts = [s]
        if self.capped:
            for zc in (0.0, hs):
                with np.errstate(all="ignore"):
                    sc = np.where(e[:, 2] != 0, (zc - p[:, 2]) / e[:, 2], np.inf)
                X = p + np.where(np.isfinite(sc), sc, 0.0)[:, None] * e
                rc = np.polynomial.polynomial.polyval(zc, cs)
                sc = np.where(np.isfinite(sc) & (X[:, 0] ** 2 + X[:, 1] ** 2 <= rc * rc), sc, np.inf)
                parts.append(sc[:, None])
        s = np.concatenate(parts, 1)
        t = (t0[:, None] + s) * S / length[:, None]
        t[~np.isfinite(t)] = np.inf
        out[rows] = np.sort(t, axis=1)
        return out

    @property
    def bounding_sphere(self):
        return self.base + self.height / 2 * self.axis, float(np.hypot(self.height / 2, self._rmax * (1 + 1e-6)))

    def _local(self, P):
        return (P - self.base) @ self._F.T

    def _normal(self, P):
        L = self._local(P)
        rz = np.polynomial.polynomial.polyval(L[:, 2], self.profile)
        drz = np.polynomial.polynomial.polyval(L[:, 2], np.polynomial.polynomial.polyder(self.profile))
        g = np.stack([L[:, 0], L[:, 1], -rz * drz], 1)
        if self.capped:
            lateral = np.abs(np.hypot(L[:, 0], L[:, 1]) - rz)
            bottom, top = np.abs(L[:, 2]), np.abs(L[:, 2] - self.height)
            which = np.argmin(np.stack([lateral, bottom, top], 1), axis=1)
            g[which == 1] = [0.0, 0.0, -1.0]
            g[which == 2] = [0.0, 0.0, 1.0]
        return g @ self._F

    def _contains(self, P):
        if not self.capped:
            raise TypeError("an uncapped surface of revolution bounds no solid: it has no inside (use capped=True)")
        L = self._local(P)
        rz = np.polynomial.polynomial.polyval(L[:, 2], self.profile)
        return (L[:, 2] >= 0) & (L[:, 2] <= self.height) & (L[:, 0] ** 2 + L[:, 1] ** 2 <= rz * rz)

    def _mesh(self, n, extent):
        u, v, w = self._F
        z = np.linspace(0.0, self.height, n)
        rz = np.polynomial.polynomial.polyval(z, self.profile)[:, None]
        phi = np.linspace(0, 2 * np.pi, 2 * n, endpoint=False)[None, :]
        L = np.stack(np.broadcast_arrays(rz * np.cos(phi), rz * np.sin(phi), z[:, None] + 0 * phi), -1).reshape(-1, 3)
        parts = [(self.base + L @ self._F, _grid(n, 2 * n, wrap=True))]
        if self.capped:
            parts += [_disc(self.base, u, v, rz[0, 0], rz[0, 0], 2 * n),
                      _disc(self.base + self.height * w, u, v, rz[-1, 0], rz[-1, 0], 2 * n)]
        return _join(*parts)

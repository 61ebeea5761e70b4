"""Applications of vector geometry: triangles, lines and planes, distances, areas and volumes,
intersections, spherical linear interpolation, inside-outside tests (Goldman Chapter 11).

Points and vectors are numpy arrays with coordinates in the last axis; a line is a point and a
direction ``(P, v)``, a plane a point and a normal ``(Q, N)``.  Every formula is the book's
vector form (dot, cross and determinant products, :mod:`goldman_lib.vectors`), vectorised over
leading axes where the arguments allow.  Degenerate input (a zero direction or normal, parallel
planes, a polygon with fewer than three vertices) raises ``ValueError`` saying what is degenerate.

>>> float(line_line_distance([0, 0, 0], [1, 0, 0], [0, 1, 3], [0, 1, 0]))
3.0
"""

from __future__ import annotations

import numpy as np

from goldman_lib.validation import as_float, as_parameter, as_points, check_finite, as_float_array, finite_result
from goldman_lib.kernels import frames
from goldman_lib.kernels.frames import norm as _norm   # np.linalg.norm, right where v·v over/underflows
from goldman_lib.vectors import cross

__all__ = ["law_of_cosines", "law_of_sines", "plane_through", "point_line_distance", "point_plane_distance",
           "line_line_distance", "foot_on_plane", "triangle_area", "newell_normal", "polygon_area", "tetrahedron_volume",
           "parallelepiped_volume", "intersect_lines", "intersect_two_planes", "intersect_three_planes", "slerp",
           "nlerp", "ray_casting_inside", "winding_number", "ray_crossings"]

_EPS = 1e-12


def _vec(x, name: str, dim=None, like: str | None = None) -> np.ndarray:
    """``x`` as a finite array of points or vectors; ``dim``: the required number of coordinates,
    which ``like`` (a parameter's name) has, for the message."""
    arr = check_finite(as_float_array(x, name), name)
    if arr.ndim == 0:
        raise ValueError(f"{name} must be a point or vector with coordinates in its last axis, not a scalar")
    if dim is not None and arr.shape[-1] != dim:
        of = f" as {like} has" if like else ""
        raise ValueError(f"{name} must have {dim} coordinates (last axis of length {dim}){of}; got shape {arr.shape}")
    return arr


def _not_huge(v: np.ndarray, name: str) -> None:
    """ValueError naming ``name`` when the squared length of ``v`` overflows float64."""
    with np.errstate(over="ignore", invalid="ignore"):
        sq = np.einsum("...i,...i->...", v, v)
    finite_result(sq, name, why="is too large in magnitude (its squared length)")


def _nonzero(v: np.ndarray, name: str, what: str) -> np.ndarray:
    n = _norm(v, axis=-1)
    if np.any(n == 0):                   # any other length is a direction (1e-170 and 1e300 included)
        raise ValueError(f"{name} must be nonzero: {what}")
    return n


def _dot(a, b):
    return frames.row_dots(*np.broadcast_arrays(a, b))


def _out(x):
    return float(x) if np.ndim(x) == 0 else x


# -- §11.2 trigonometric laws: triangles -------------------------------------------------------------

def law_of_cosines(a, b, gamma):
    """The third side ``c`` of a triangle from sides ``a``, ``b`` and the angle ``gamma`` (degrees)
    between them: ``c² = a² + b² - 2ab cos γ`` (Goldman §11.2), derived from ``|u - v|²``.

    >>> round(float(law_of_cosines(3, 4, 90)), 12)
    5.0
    """
    a = as_parameter(a, "a", low=0)
    b = as_parameter(b, "b", low=0)
    g = as_parameter(gamma, "gamma", low=0, high=180)
    out = np.sqrt(np.maximum(a * a + b * b - 2 * a * b * np.cos(np.radians(g)), 0))
    return _out(finite_result(out, "a and b", why="are too large in magnitude"))


def law_of_sines(a, alpha, beta):
    """The side ``b`` opposite the angle ``beta`` from the side ``a`` opposite ``alpha`` (degrees):
    ``a / sin α = b / sin β`` (Goldman §11.2), from two expressions of ``|u × v|``.

    >>> round(float(law_of_sines(1, 30, 90)), 12)
    2.0
    """
    a = as_parameter(a, "a", low=0)
    al = as_parameter(alpha, "alpha", low=0, high=180)
    be = as_parameter(beta, "beta", low=0, high=180)
    if np.any(al + be >= 180):
        raise ValueError("alpha + beta must be < 180: the two angles of a triangle leave room for a third")
    s = np.sin(np.radians(al))
    if np.any(s <= _EPS):
        raise ValueError("alpha must be strictly between 0 and 180 degrees")
    return _out(finite_result(a * np.sin(np.radians(be)) / s, "a"))


# -- §11.3 lines and planes ------------------------------------------------------------------------

def plane_through(P, Q, R) -> tuple[np.ndarray, np.ndarray]:
    """The plane through three non-collinear points as ``(point, unit normal)`` with normal
    ``(Q - P) × (R - P)`` normalised (Goldman §11.3).

    >>> [x.tolist() for x in plane_through([0, 0, 1], [1, 0, 1], [0, 1, 1])]
    [[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]]
    """
    P, Q, R = (_vec(x, n, 3) for x, n in ((P, "P"), (Q, "Q"), (R, "R")))
    N = cross(Q - P, R - P)
    n = _norm(N, axis=-1)
    if np.any(n <= _EPS * (1 + _norm(Q - P, axis=-1) * _norm(R - P, axis=-1))):
        raise ValueError("P, Q, R must not be collinear: collinear points lie on many planes")
    return P, N / n[..., None]


# -- §11.4 distances, areas, volumes -----------------------------------------------------------------

def point_line_distance(points, line_point, direction):
    """Distance from points to the line ``P + t v``: ``|(Q - P) × v| / |v|`` in 3D, and the
    perpendicular component ``|(Q - P) - ((Q - P)·v / v·v) v|`` in any dimension (Goldman §11.4).

    >>> float(point_line_distance([1, 5], [0, 0], [1, 0]))
    5.0
    """
    Q = _vec(points, "points")
    P = _vec(line_point, "line_point", Q.shape[-1], like="points")
    v = _vec(direction, "direction", Q.shape[-1], like="points")
    nv = _nonzero(v, "direction", "a line needs a direction")
    with np.errstate(over="ignore", under="ignore"):
        vv = nv ** 2
    if not np.all((vv > 1e-290) & (vv < 1e290)):      # v·v over- or underflows: use the unit direction
        v, vv = v / nv[..., None], 1.0
    w = Q - P
    perp = w - (_dot(w, v) / vv)[..., None] * v
    out = _norm(perp, axis=-1)
    return _out(finite_result(out, "points", why="(or line_point) is too large in magnitude"))


def point_plane_distance(points, plane_point, normal, signed: bool = False):
    """Distance from points to the plane through ``plane_point`` with normal ``N``:
    ``(Q - P)·N / |N|`` (Goldman §11.4); signed (positive on the side N points to) if asked.

    >>> float(point_plane_distance([1, 2, -3], [0, 0, 0], [0, 0, 2], signed=True))
    -3.0
    """
    Q = _vec(points, "points", 3)
    P = _vec(plane_point, "plane_point", 3)
    N = _vec(normal, "normal", 3)
    d = _dot(Q - P, N) / _nonzero(N, "normal", "a plane needs a normal direction")
    return _out(d if signed else np.abs(d))


def foot_on_plane(points, plane_point, normal) -> np.ndarray:
    """The foot of the perpendicular from points to the plane through ``plane_point`` with normal
    ``N``: ``Q - [(Q - P)·N / N·N] N``, the point of the plane closest to ``Q`` (Goldman §11.4); the
    distance of :func:`point_plane_distance` is ``|Q - foot|``.  Vectorised over the points.

    >>> foot_on_plane([1, 2, -3], [0, 0, 0], [0, 0, 2]).tolist()
    [1.0, 2.0, 0.0]
    """
    Q = _vec(points, "points", 3)
    P = _vec(plane_point, "plane_point", 3)
    N = _vec(normal, "normal", 3)
    n = _nonzero(N, "normal", "a plane needs a normal direction")
    with np.errstate(over="ignore", under="ignore"):
        nn = n ** 2
    if not np.all((nn > 1e-290) & (nn < 1e290)):      # N·N over- or underflows: use the unit normal
        N, nn = N / n[..., None], 1.0
    with np.errstate(over="ignore", invalid="ignore"):
        out = Q - (_dot(Q - P, N) / nn)[..., None] * N
    return finite_result(out, "points or plane_point", why="is too large in magnitude")


def line_line_distance(p1, d1, p2, d2):
    """Distance between the lines ``p1 + s d1`` and ``p2 + t d2`` in 3D (Goldman §11.4):
    ``|(p2 - p1)·(d1 × d2)| / |d1 × d2|`` for skew or intersecting lines, and the point-line
    distance for parallel lines.

    >>> float(line_line_distance([0, 0, 0], [1, 1, 0], [0, 0, 2], [2, 2, 0]))  # parallel
    2.0
    """
    p1, d1, p2, d2 = (_vec(x, n, 3) for x, n in ((p1, "p1"), (d1, "d1"), (p2, "p2"), (d2, "d2")))
    _nonzero(d1, "d1", "a line needs a direction")
    _nonzero(d2, "d2", "a line needs a direction")
    c = cross(d1, d2)
    nc = _norm(c, axis=-1)
    w = p2 - p1
    parallel = nc <= 1e-12 * _norm(d1, axis=-1) * _norm(d2, axis=-1)
    skew = np.abs(_dot(w, c)) / np.where(parallel, 1, nc)
    vv = _dot(d1, d1)
    perp = _norm(w - (_dot(w, d1) / vv)[..., None] * d1, axis=-1)
    return _out(np.where(parallel, perp, skew))


def triangle_area(P, Q, R):
    """Area of triangles ``|(Q - P) × (R - P)| / 2`` (Goldman §11.4); 2D triangles are taken in
    the plane z = 0.  Vectorised over leading axes.

    >>> float(triangle_area([0, 0], [4, 0], [0, 3]))
    6.0
    """
    P, Q, R = (_vec(x, n) for x, n in ((P, "P"), (Q, "Q"), (R, "R")))
    if not (P.shape[-1] == Q.shape[-1] == R.shape[-1]) or P.shape[-1] not in (2, 3):
        raise ValueError(f"P, Q, R must be 2D or 3D points of the same dimension; got {P.shape}, {Q.shape}, {R.shape}")
    if P.shape[-1] == 2:
        u, v = Q - P, R - P
        return _out(np.abs(u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]) / 2)
    return _out(_norm(cross(Q - P, R - P), axis=-1) / 2)


def _polygon(polygon, name="polygon", dims=(2, 3)) -> np.ndarray:
    pts = as_points(polygon, name, dim=dims)
    if len(pts) >= 2 and np.array_equal(pts[0], pts[-1]):
        pts = pts[:-1]  # a closing vertex repeated
    if len(pts) < 3:
        raise ValueError(f"{name} must have at least three distinct vertices; got {len(pts)}")
    return pts


def newell_normal(polygon) -> np.ndarray:
    """Newell's normal of a polygon ``(n, 3)`` (Goldman §11.4), *unnormalised*: ``N = Σ P_i × P_{i+1}``,
    whose length is twice the area of a planar polygon and whose direction is its normal by the
    right-hand rule on the order of the vertices; robust for nearly planar polygons.  Computed in
    Newell's own form ``N_x = Σ (y_i - y_{i+1})(z_i + z_{i+1})`` (and cyclically), which does not
    lose digits far from the origin (:func:`goldman_lib.kernels.frames.newell`).  The unit normal
    of chapter 21 is :func:`goldman_lib.shading.unit_newell_normal` (the same vector scaled to length 1).

    >>> newell_normal([[0, 0, 0], [2, 0, 0], [2, 3, 0], [0, 3, 0]]).tolist()
    [0.0, 0.0, 12.0]
    """
    pts = _polygon(polygon, dims=(3,))
    with np.errstate(over="ignore", invalid="ignore"):
        return finite_result(frames.newell(pts), "polygon")


def polygon_area(polygon) -> float:
    """Area of a simple planar polygon, 2D ``(n, 2)`` (the shoelace form of Newell's formula) or 3D
    ``(n, 3)`` (half the length of :func:`newell_normal`) (Goldman §11.4).

    >>> polygon_area([[0, 0], [4, 0], [4, 1], [1, 1], [1, 3], [0, 3]])
    6.0
    """
    pts = _polygon(polygon)
    if pts.shape[1] == 2:
        x, y = pts[:, 0], pts[:, 1]
        area = abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) / 2
    else:
        area = _norm(newell_normal(pts)) / 2
    return float(finite_result(np.asarray(area), "polygon"))


def tetrahedron_volume(P0, P1, P2, P3):
    """Volume of tetrahedra ``|det(P1 - P0, P2 - P0, P3 - P0)| / 6`` (Goldman §11.4).

    >>> float(tetrahedron_volume([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1])) * 6
    1.0
    """
    P0, P1, P2, P3 = (_vec(x, n, 3) for x, n in ((P0, "P0"), (P1, "P1"), (P2, "P2"), (P3, "P3")))
    return _out(np.abs(_dot(cross(P1 - P0, P2 - P0), P3 - P0)) / 6)


def parallelepiped_volume(u, v, w):
    """Volume ``|det(u, v, w)|`` of the parallelepiped spanned by three vectors (Goldman §11.4).

    >>> float(parallelepiped_volume([2, 0, 0], [1, 3, 0], [5, 5, 4]))
    24.0
    """
    u, v, w = (_vec(x, n, 3) for x, n in ((u, "u"), (v, "v"), (w, "w")))
    return _out(np.abs(_dot(cross(u, v), w)))


# -- §11.5 intersections ----------------------------------------------------------------------------

def intersect_lines(p1, d1, p2, d2) -> tuple[np.ndarray, np.ndarray, float]:
    """Intersect the lines ``p1 + s d1`` and ``p2 + t d2`` in 2D or 3D (Goldman §11.5).

    Returns ``(A, B, distance)``: the closest points on the two lines and their distance; for
    intersecting lines ``A == B`` is the intersection.  Parallel lines raise ValueError (every point
    is equally close).

    >>> A, B, d = intersect_lines([0, 0], [1, 1], [2, 0], [0, 1])
    >>> A.tolist(), B.tolist(), d
    ([2.0, 2.0], [2.0, 2.0], 0.0)
    """
    p1 = _vec(p1, "p1")
    if p1.ndim != 1 or p1.shape[0] not in (2, 3):
        raise ValueError(f"p1 must be one 2D or 3D point; got shape {p1.shape}")
    dim = p1.shape[0]
    d1, p2, d2 = (_vec(x, n, dim, like="p1") for x, n in ((d1, "d1"), (p2, "p2"), (d2, "d2")))
    for x, n in ((d1, "d1"), (p2, "p2"), (d2, "d2")):
        if x.shape != (dim,):
            raise ValueError(f"{n} must be one {dim}D point or vector, as p1 is; got shape {x.shape}")
    _nonzero(d1, "d1", "a line needs a direction")
    _nonzero(d2, "d2", "a line needs a direction")
    _not_huge(d1, "d1")
    _not_huge(d2, "d2")
    # minimise |p1 + s d1 - p2 - t d2|^2: the 2x2 normal equations
    a, b, c = d1 @ d1, d1 @ d2, d2 @ d2
    w = p1 - p2
    denom = a * c - b * b
    if denom <= 1e-12 * a * c:
        raise ValueError("d1 and d2 must not be parallel: parallel lines have no single closest pair")
    s = (b * (d2 @ w) - c * (d1 @ w)) / denom
    t = (a * (d2 @ w) - b * (d1 @ w)) / denom
    A, B = p1 + s * d1, p2 + t * d2
    finite_result(np.concatenate([A, B, [s, t]]), "p1, d1, p2 and d2", why="are too large in magnitude")
    dist = float(_norm(A - B))
    if dist <= 1e-12 * (1 + _norm(A)):
        B, dist = A.copy(), 0.0
    return A, B, dist


def _plane(plane, name):
    try:
        point, normal = plane
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a pair (point, normal)") from None
    P = _vec(point, f"{name} point", 3)
    N = _vec(normal, f"{name} normal", 3)
    _nonzero(N, f"{name} normal", "a plane needs a normal direction")
    _not_huge(N, f"{name} normal")
    return P, N


def intersect_two_planes(plane1, plane2) -> tuple[np.ndarray, np.ndarray]:
    """The line where two planes meet, as ``(point, direction)`` with direction ``N1 × N2`` and
    the point on it closest to the origin (Goldman §11.5).  Parallel planes raise ValueError.

    >>> P, v = intersect_two_planes(([0, 0, 1], [0, 0, 1]), ([2, 0, 0], [1, 0, 0]))
    >>> P.tolist(), v.tolist()
    ([2.0, 0.0, 1.0], [0.0, 1.0, 0.0])
    """
    P1, N1 = _plane(plane1, "plane1")
    P2, N2 = _plane(plane2, "plane2")
    v = cross(N1, N2)
    nv = _norm(v)
    if nv <= 1e-12 * _norm(N1) * _norm(N2):
        raise ValueError("plane1 and plane2 must not be parallel: parallel planes do not meet in a line")
    # the point on the line closest to the origin: the three planes N1, N2 and v through the origin
    point = intersect_three_planes((P1, N1), (P2, N2), (np.zeros(3), v))
    return point, v / nv


def intersect_three_planes(plane1, plane2, plane3) -> np.ndarray:
    """The point where three planes ``(point, normal)`` meet (Goldman §11.5):
    ``P = [(P1·N1)(N2 × N3) + (P2·N2)(N3 × N1) + (P3·N3)(N1 × N2)] / det(N1, N2, N3)``.
    Raises ValueError when the normals are dependent (no single common point).

    >>> intersect_three_planes(([1, 0, 0], [1, 0, 0]), ([0, 2, 0], [0, 1, 0]), ([0, 0, 3], [0, 0, 1])).tolist()
    [1.0, 2.0, 3.0]
    """
    (P1, N1), (P2, N2), (P3, N3) = (_plane(p, n) for p, n in ((plane1, "plane1"), (plane2, "plane2"), (plane3, "plane3")))
    d = float(np.dot(cross(N1, N2), N3))
    scale = _norm(N1) * _norm(N2) * _norm(N3)
    if abs(d) <= 1e-12 * scale:
        raise ValueError("the three normals must be independent (det(N1, N2, N3) != 0): otherwise two planes are "
                         "parallel or all three share a line, and there is no single common point")
    out = (np.dot(P1, N1) * cross(N2, N3) + np.dot(P2, N2) * cross(N3, N1) + np.dot(P3, N3) * cross(N1, N2)) / d
    return finite_result(out, "plane1, plane2 and plane3", why="are too large in magnitude")


# -- §11.6 spherical linear interpolation -------------------------------------------------------------

def slerp(v0, v1, t) -> np.ndarray:
    """Spherical linear interpolation of two vectors (Goldman §11.6):
    ``sin((1-t)θ)/sin θ v0 + sin(tθ)/sin θ v1`` where θ is the angle between them; for unit vectors
    the result moves along the great arc at constant speed.  Linear interpolation when θ is 0;
    opposite vectors raise ValueError (the arc between them is not unique).

    v0 and v1 must have the same length r (to a relative 1e-9): the result then stays on the sphere of
    radius r about the origin.  Vectors of different lengths raise ValueError naming the rule: the
    formula would return points on no sphere (neither radius, nor a blend of the two), so normalise
    them first, or interpolate the directions with slerp and the lengths separately.

    >>> np.round(slerp([1, 0], [0, 1], 0.5), 12).tolist()
    [0.707106781187, 0.707106781187]
    >>> np.round(slerp([2, 0], [0, 2], 0.5), 12).tolist()      # equal lengths: on the circle of radius 2
    [1.414213562373, 1.414213562373]
    """
    a = _vec(v0, "v0")
    b = _vec(v1, "v1", a.shape[-1], like="v0")
    la = _nonzero(a, "v0", "slerp needs directions")
    lb = _nonzero(b, "v1", "slerp needs directions")
    unequal = np.abs(la - lb) > 1e-9 * np.maximum(la, lb)
    if np.any(unequal):
        k = int(np.flatnonzero(np.broadcast_to(unequal, np.broadcast_shapes(np.shape(la), np.shape(lb))))[0])
        l0, l1 = np.broadcast_to(la, unequal.shape).flat[k], np.broadcast_to(lb, unequal.shape).flat[k]
        where = "" if unequal.ndim == 0 else f" (at index {k})"
        raise ValueError(f"v0 and v1 must have the same length for slerp, which moves on a sphere about the origin; "
                         f"|v0| = {l0:.6g} and |v1| = {l1:.6g}{where}: normalise them, or interpolate the lengths "
                         f"separately")
    t = as_parameter(t, "t")
    cos = np.clip(_dot(a, b) / (la * lb), -1, 1)
    if np.any(cos <= -1 + 1e-12):
        raise ValueError("v0 and v1 must not point in opposite directions: the great arc between them is not unique")
    return frames.slerp(a, b, t, la, lb, cos)


def nlerp(v0, v1, t) -> np.ndarray:
    """Normalised linear interpolation ``((1-t) v0 + t v1) / |(1-t) v0 + t v1|`` of two unit
    directions: the comparison that shows why §11.6 needs slerp (our addition, not a formula of the
    book).  It follows the same great arc as :func:`slerp` but not at constant speed: it lags near
    the ends and rushes through the middle.  Opposite vectors raise ValueError (at t = 1/2 the chord
    passes through the origin).

    >>> np.round(nlerp([1, 0], [0, 1], 0.5), 12).tolist()
    [0.707106781187, 0.707106781187]
    """
    a = _vec(v0, "v0")
    b = _vec(v1, "v1", a.shape[-1], like="v0")
    _nonzero(a, "v0", "nlerp needs directions")
    _nonzero(b, "v1", "nlerp needs directions")
    tt = as_parameter(t, "t")[..., None]
    chord = (1 - tt) * a + tt * b
    n = _norm(chord, axis=-1, keepdims=True)
    if np.any(n <= 1e-12 * (_norm(a, axis=-1, keepdims=True) + _norm(b, axis=-1, keepdims=True))):
        raise ValueError("v0 and v1 must not point in opposite directions: the chord between them passes through "
                         "the origin, which has no direction")
    return chord / n


# -- §11.7 inside-outside tests ------------------------------------------------------------------------

def _polygon_and_queries(polygon, points):
    poly = _polygon(polygon, dims=(2,))
    Q = as_points(points, "points", ndim=None, dim=2)
    return poly, Q


def ray_casting_inside(polygon, points) -> np.ndarray:
    """Inside test by ray casting (Goldman §11.7): a point is inside when a ray from it crosses the
    polygon's edges an odd number of times (the even-odd rule).  Each edge counts for the half-open
    range of heights ``min(y) <= y < max(y)``, so a ray through a vertex is counted once.

    polygon: (n, 2).  points: (..., 2).  Returns a boolean array of shape ``points.shape[:-1]``.

    >>> ray_casting_inside([[0, 0], [4, 0], [4, 4], [0, 4]], [[1, 1], [5, 1]]).tolist()
    [True, False]
    """
    poly, Q = _polygon_and_queries(polygon, points)
    return (_crossings(poly, Q.reshape(-1, 2), signed=False) % 2 == 1).reshape(Q.shape[:-1])


def winding_number(polygon, points) -> np.ndarray:
    """Winding numbers of a closed polygon about query points (Goldman §11.7): the number of times
    the polygon winds counterclockwise around each point (negative for clockwise).  A point is inside
    by the nonzero rule when its winding number is not 0.  Computed by signed crossings of a
    horizontal ray (an upward edge crossing to the right of the point counts +1, a downward one -1),
    vectorised over the query points.

    polygon: (n, 2), vertices in order (a repeated closing vertex is ignored).  points: (..., 2).
    Returns an ``int`` array of shape ``points.shape[:-1]``.  Points on an edge get the count of one
    of the two sides.

    >>> winding_number([[0, 0], [2, 0], [2, 2], [0, 2]], [[1, 1], [3, 1]]).tolist()
    [1, 0]
    >>> star = [[0, 3], [-1.76, -2.43], [2.85, 0.93], [-2.85, 0.93], [1.76, -2.43]]   # {5/2} star, counterclockwise
    >>> winding_number(star, [[0, 0], [0, 2.4]]).tolist()
    [2, 1]
    """
    poly, Q = _polygon_and_queries(polygon, points)
    return _crossings(poly, Q.reshape(-1, 2), signed=True).reshape(Q.shape[:-1])


def ray_crossings(polygon, point) -> tuple[np.ndarray, np.ndarray]:
    """Where the rightward horizontal ray from one query point crosses the polygon's edges, and
    how (Goldman §11.7): ``(crossings, signs)``, the crossing points ``(k, 2)`` sorted from the
    query point outwards and ``+1`` for an edge going up, ``-1`` for one going down.  The count
    ``k`` decides the even-odd rule (:func:`ray_casting_inside`), the sum of the signs is the
    winding number (:func:`winding_number`); the same half-open rule for vertices is used.

    >>> pts, signs = ray_crossings([[0, 0], [4, 0], [4, 4], [0, 4]], [1, 1])
    >>> pts.tolist(), signs.tolist()
    ([[4.0, 1.0]], [1])
    """
    poly = _polygon(polygon, dims=(2,))
    Q = as_points(point, "point", ndim=1, dim=2)
    a = poly
    b = np.roll(poly, -1, axis=0)
    up = a[:, 1] < b[:, 1]
    lo = np.where(up, a[:, 1], b[:, 1])
    hi = np.where(up, b[:, 1], a[:, 1])
    span = (lo <= Q[1]) & (Q[1] < hi)
    dy = np.where(span, b[:, 1] - a[:, 1], 1.0)
    x_edge = a[:, 0] + (Q[1] - a[:, 1]) * (b[:, 0] - a[:, 0]) / dy
    hit = span & (Q[0] < x_edge)
    order = np.argsort(x_edge[hit], kind="stable")
    xs = x_edge[hit][order]
    signs = np.where(up[hit], 1, -1)[order]
    return np.column_stack([xs, np.full(len(xs), Q[1])]), signs.astype(np.int64)


def _crossings(poly: np.ndarray, Q: np.ndarray, signed: bool) -> np.ndarray:
    """Signed (or unsigned) crossings of the rightward horizontal ray from each query point.

    The query points are sorted by height once; each edge then touches only the points whose
    height lies in its half-open range (found by binary search), so the work is the number of
    (edge, point) pairs that can cross, not every pair.
    """
    count = np.zeros(len(Q), dtype=np.int64)
    if len(Q) == 0:
        return count
    order = np.argsort(Q[:, 1])
    ys = Q[order, 1]
    xs = Q[order, 0]
    a = poly
    b = np.roll(poly, -1, axis=0)
    up = a[:, 1] < b[:, 1]
    lo = np.where(up, a[:, 1], b[:, 1])
    hi = np.where(up, b[:, 1], a[:, 1])
    start = np.searchsorted(ys, lo, side="left")
    stop = np.searchsorted(ys, hi, side="left")
    acc = np.zeros(len(Q), dtype=np.int64)
    for k in np.flatnonzero(stop > start):
        i, j = start[k], stop[k]
        (ax, ay), (bx, by) = a[k], b[k]
        y = ys[i:j]
        # x of the edge at height y; the point is left of the crossing when x_point < x_edge
        x_edge = ax + (y - ay) * (bx - ax) / (by - ay)
        hit = xs[i:j] < x_edge
        acc[i:j] += hit * (1 if (up[k] or not signed) else -1)
    count[order] = acc
    return count

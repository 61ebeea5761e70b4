"""Points and vectors, and the products of vectors (Goldman Chapters 9 and 10).

Chapter 9 separates two kinds of objects that coordinates blur: *vectors* (directions and
lengths, which can be added and scaled) and *points* (locations, which cannot be added: the sum
of two points depends on where the origin is).  The rules:

* point - point = vector;  point + vector = point;  vector + vector = vector;  c * vector = vector;
* point + point, c * point: illegal -- except *affine combinations* ``Σ w_i P_i`` with ``Σ w_i = 1``,
  which do not depend on the origin (:func:`affine_combination`).

:class:`Point` and :class:`Vector` enforce these rules over numpy arrays (coordinates in the last
axis, any leading shape).  The products -- :func:`dot`, :func:`cross`, :func:`det` -- are computed
by the rectangular-coordinate formulas of Chapter 10 and vectorise over leading axes; the
coordinate-free definitions of Chapter 9 (:func:`dot_from_lengths`, :func:`cross_from_geometry`)
compute the same numbers from lengths and angles alone, and the tests check the two agree.

>>> P, Q = Point([1, 2, 0]), Point([4, 6, 0])
>>> Q - P
Vector([3., 4., 0.])
>>> (Q - P).length()
5.0
>>> P + Q
Traceback (most recent call last):
...
TypeError: point + point is not defined: the sum of two points depends on the origin (Goldman §9.3); use affine_combination(points, weights) with weights summing to 1, or add a vector to a point
"""

from __future__ import annotations

import numbers

import numpy as np

from goldman_lib.validation import as_float_array, as_tolerance, check_finite, finite_result
from goldman_lib.kernels.frames import norm as _norm   # np.linalg.norm, right where v·v over/underflows

__all__ = ["Point", "Vector", "affine_combination", "combination_kind", "weighted_sum_from_origin", "dot", "cross",
           "det", "det_cofactor_terms", "length", "angle_between", "dot_from_lengths", "cross_from_geometry",
           "cross_associator"]


def _coords(x, name: str) -> np.ndarray:
    if isinstance(x, (Point, Vector)):
        return x.coords
    arr = check_finite(as_float_array(x, name), name)
    if arr.ndim == 0 or arr.shape[-1] < 1:
        raise ValueError(f"{name} must have coordinates in its last axis; got shape {arr.shape}")
    return arr


def _vector3(x, name: str) -> np.ndarray:
    if isinstance(x, Point):
        raise TypeError(f"{name} must be a vector, not a point: products are defined for vectors (Goldman §9.4); "
                        f"subtract two points to get one")
    arr = _coords(x, name)
    if arr.shape[-1] != 3:
        raise ValueError(f"{name} must be a 3D vector (last axis of length 3); got shape {arr.shape}")
    return arr


def _not_huge(arr: np.ndarray, name: str) -> None:
    """ValueError naming ``name`` when the squared length of ``arr`` overflows float64 (entries near 1e154 and over)."""
    with np.errstate(over="ignore", invalid="ignore"):
        sq = np.einsum("...i,...i->...", arr, arr)
    finite_result(sq, name, why="is too large in magnitude (its squared length)")


def _moderate(arr: np.ndarray) -> np.ndarray:
    """``arr`` with each vector scaled by a power of two (exactly) into a range where products of
    two coordinates neither overflow nor underflow, if any is outside it: for results that depend only
    on directions (angles)."""
    m = np.abs(arr).max(axis=-1, keepdims=True)
    if np.all((m == 0) | ((m > 1e-100) & (m < 1e100))):
        return arr
    return arr / np.ldexp(1.0, np.frexp(np.where(m > 0, m, 1.0))[1] - 1)


def _scalar(c, name: str) -> float | np.ndarray:
    if isinstance(c, bool) or not isinstance(c, (numbers.Real, np.ndarray)):
        raise TypeError(f"{name} must be a real number; got {c!r}")
    arr = check_finite(as_float_array(c, name), name)
    return arr[..., None] if arr.ndim else float(arr)


class _Affine:
    __slots__ = ("coords",)
    __array_priority__ = 1000  # numpy scalars on the left defer to our operators

    def __init__(self, coords):
        self.coords = _coords(coords, "coords").copy()
        self.coords.setflags(write=False)

    @property
    def dim(self) -> int:
        return self.coords.shape[-1]

    def __repr__(self) -> str:
        body = np.array2string(self.coords, separator=", ")
        return f"{type(self).__name__}({body})"

    def __eq__(self, other):
        return type(self) is type(other) and np.array_equal(self.coords, other.coords)

    __hash__ = None

    def __array__(self, dtype=None, copy=None):
        return np.asarray(self.coords, dtype=dtype)

    def _same_dim(self, other):
        if self.dim != other.dim:
            raise ValueError(f"cannot combine a {self.dim}D {type(self).__name__.lower()} with a {other.dim}D "
                             f"{type(other).__name__.lower()}")


class Vector(_Affine):
    """A vector (or an array of vectors): a direction and a length, with no location (Goldman §9.2).

    Vectors add, subtract, scale, and add to points.

    >>> 2 * Vector([1, 0]) - Vector([0, 1])
    Vector([ 2., -1.])
    """

    __slots__ = ()

    def __add__(self, other):
        if isinstance(other, Vector):
            self._same_dim(other)
            return Vector(self.coords + other.coords)
        if isinstance(other, Point):
            self._same_dim(other)
            return Point(self.coords + other.coords)
        return NotImplemented

    __radd__ = __add__

    def __sub__(self, other):
        if isinstance(other, Vector):
            self._same_dim(other)
            return Vector(self.coords - other.coords)
        if isinstance(other, Point):
            raise TypeError("vector - point is not defined (Goldman §9.3): subtract a vector from a point, "
                            "or two points to get a vector")
        return NotImplemented

    def __neg__(self):
        return Vector(-self.coords)

    def __mul__(self, c):
        if isinstance(c, (Point, Vector)):
            raise TypeError("vector * vector is ambiguous: use dot(u, v) or cross(u, v) (Goldman §9.4)")
        return Vector(self.coords * _scalar(c, "c"))

    __rmul__ = __mul__

    def __truediv__(self, c):
        c = _scalar(c, "c")
        if np.any(np.asarray(c) == 0):
            raise ValueError("c must be nonzero: a vector cannot be divided by 0")
        return Vector(self.coords / c)

    def length(self):
        """The length |v| (Goldman §9.4)."""
        out = finite_result(_norm(self.coords, axis=-1), "v")
        return float(out) if out.ndim == 0 else out

    def dot(self, other):
        """``dot(self, other)``."""
        if isinstance(other, Point):
            raise TypeError("other must be a vector, not a point: dot takes vectors (Goldman §9.4)")
        o = _coords(other, "other")
        if o.shape[-1] != self.dim:
            raise ValueError(f"other must have the dimension of this vector ({self.dim}); got shape {o.shape}")
        return dot(self, o)

    def cross(self, other):
        """``cross(self, other)`` as a :class:`Vector`."""
        return Vector(cross(self, _vector3(other, "other")))


class Point(_Affine):
    """A point (or an array of points): a location, with no length or direction (Goldman §9.3).

    point - point = vector; point ± vector = point; point + point and c * point are TypeErrors.

    >>> Point([1, 1]) + Vector([2, 0])
    Point([3., 1.])
    """

    __slots__ = ()

    def __add__(self, other):
        if isinstance(other, Vector):
            self._same_dim(other)
            return Point(self.coords + other.coords)
        if isinstance(other, Point):
            raise TypeError("point + point is not defined: the sum of two points depends on the origin "
                            "(Goldman §9.3); use affine_combination(points, weights) with weights summing to 1, "
                            "or add a vector to a point")
        return NotImplemented

    def __radd__(self, other):
        return self.__add__(other)

    def __sub__(self, other):
        if isinstance(other, Point):
            self._same_dim(other)
            return Vector(self.coords - other.coords)
        if isinstance(other, Vector):
            self._same_dim(other)
            return Point(self.coords - other.coords)
        return NotImplemented

    def __mul__(self, c):
        raise TypeError("c * point is not defined: scaling a point depends on the origin (Goldman §9.3); "
                        "scale the vector P - Q from a chosen centre Q instead, or use affine_combination")

    __rmul__ = __mul__

    def __neg__(self):
        raise TypeError("-point is not defined (Goldman §9.3): negate a vector instead")


def affine_combination(points, weights) -> Point:
    """The affine combination ``Σ w_i P_i`` of points with weights summing to 1 (Goldman §9.3): the
    point ``P_0 + Σ w_i (P_i - P_0)``, which does not depend on the origin.

    points: (k, d) array or a sequence of :class:`Point`.  weights: (k,), summing to 1 (to 1e-9).
    Raises TypeError for vectors among the points and ValueError when the weights do not sum to 1.

    >>> affine_combination([[0, 0], [4, 0], [0, 4]], [0.5, 0.25, 0.25])
    Point([1., 1.])
    >>> affine_combination([[0, 0], [4, 0]], [1, 1])
    Traceback (most recent call last):
    ...
    ValueError: weights must sum to 1 for an affine combination of points (Goldman §9.3); they sum to 2: a sum of points with weights summing to 2 depends on the origin
    """
    if isinstance(points, Vector) or (isinstance(points, (list, tuple)) and any(isinstance(p, Vector) for p in points)):
        raise TypeError("points must be points, not vectors: a combination of vectors is a linear combination")
    if isinstance(points, (list, tuple)) and points and all(isinstance(p, Point) for p in points):
        pts = np.stack([p.coords for p in points])
    else:
        pts = _coords(points, "points")
    w = check_finite(as_float_array(weights, "weights"), "weights")
    if pts.ndim < 2 or w.ndim != 1 or w.shape[0] != pts.shape[-2]:
        raise ValueError(f"weights must have one entry per point: {pts.shape[-2] if pts.ndim >= 2 else 1} points, "
                         f"weights of shape {w.shape}")
    total = float(w.sum())
    if abs(total - 1) > 1e-9:
        raise ValueError(f"weights must sum to 1 for an affine combination of points (Goldman §9.3); they sum to "
                         f"{total:.6g}: a sum of points with weights summing to {total:.6g} depends on the origin")
    base = pts[..., :1, :]
    return Point(base[..., 0, :] + np.einsum("k,...kd->...d", w, pts - base))


def combination_kind(weights, tol: float = 1e-9) -> str:
    """What the formal sum ``Σ w_i P_i`` of points is (Goldman §9.3, Appendix B): ``"point"`` when
    the weights sum to 1 (an affine combination), ``"vector"`` when they sum to 0 (for instance
    ``P - Q``), ``"undefined"`` otherwise (the result would depend on the origin).

    weights: (k,) finite numbers; tol: how close to 1 or 0 the sum must be.

    >>> combination_kind([2, -1]), combination_kind([1, -1]), combination_kind([1, 1])
    ('point', 'vector', 'undefined')
    """
    w = check_finite(as_float_array(weights, "weights"), "weights")
    tol = as_tolerance(tol, "tol")
    if w.ndim != 1 or w.size == 0:
        raise ValueError(f"weights must be a non-empty 1D sequence; got shape {w.shape}")
    total = float(w.sum())
    if abs(total - 1) <= tol:
        return "point"
    if abs(total) <= tol:
        return "vector"
    return "undefined"


def weighted_sum_from_origin(points, weights, origin) -> np.ndarray:
    """The location ``O + Σ w_i (P_i - O)``: what the coordinate sum ``Σ w_i P_i`` means when the
    coordinates are measured from the origin ``O`` (Goldman §9.3).  Its location does not depend on
    ``O`` exactly when the weights sum to 1 (then it is the affine combination); otherwise it moves
    by ``(1 - Σ w_i)`` times the move of the origin.

    points: (k, d).  weights: (k,).  origin: (d,) or (m, d) for several origins at once.  Returns
    the location(s), shape (d,) or (m, d), as coordinates in the original frame.

    >>> weighted_sum_from_origin([[0, 0], [4, 0]], [1, 1], [0, 0]).tolist()
    [4.0, 0.0]
    >>> weighted_sum_from_origin([[0, 0], [4, 0]], [1, 1], [1, 2]).tolist()   # moved with the origin
    [3.0, -2.0]
    >>> weighted_sum_from_origin([[0, 0], [4, 0]], [0.5, 0.5], [1, 2]).tolist()  # the midpoint, always
    [2.0, 0.0]
    """
    pts = _coords(points, "points")
    w = check_finite(as_float_array(weights, "weights"), "weights")
    O = _coords(origin, "origin")
    if pts.ndim != 2:
        raise ValueError(f"points must have shape (k, d); got shape {pts.shape}")
    if w.shape != (pts.shape[0],):
        raise ValueError(f"weights must have one entry per point: {pts.shape[0]} points, weights of shape {w.shape}")
    if O.shape[-1] != pts.shape[-1] or O.ndim > 2:
        raise ValueError(f"origin must have shape ({pts.shape[-1]},) or (m, {pts.shape[-1]}), the dimension of points; "
                         f"got shape {O.shape}")
    return O + np.einsum("k,...kd->...d", w, pts - O[..., None, :])


def dot(u, v):
    """The dot product ``Σ u_i v_i`` in rectangular coordinates (Goldman §10.3.1), vectorised over
    leading axes.  Points are refused: the dot product is defined for vectors.

    >>> float(dot([1, 2, 3], [4, -5, 6]))
    12.0
    """
    if isinstance(u, Point) or isinstance(v, Point):
        raise TypeError("dot takes vectors, not points (Goldman §9.4): subtract two points to get a vector")
    a, b = _coords(u, "u"), _coords(v, "v")
    if a.shape[-1] != b.shape[-1]:
        raise ValueError(f"u and v must have the same dimension; got {a.shape[-1]} and {b.shape[-1]}")
    with np.errstate(over="ignore", invalid="ignore"):
        out = finite_result(np.einsum("...i,...i->...", a, b), "u and v", why="are too large in magnitude")
    return float(out) if out.ndim == 0 else out


def cross(u, v) -> np.ndarray:
    """The cross product of 3D vectors by the determinant formula (Goldman §10.3):
    ``(u2 v3 - u3 v2, u3 v1 - u1 v3, u1 v2 - u2 v1)``, vectorised over leading axes.

    >>> cross([1, 0, 0], [0, 1, 0]).tolist()
    [0.0, 0.0, 1.0]
    """
    a, b = _vector3(u, "u"), _vector3(v, "v")
    a, b = np.broadcast_arrays(a, b)
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.stack([a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1],
                        a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2],
                        a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]], axis=-1)
    return finite_result(out, "u and v", why="are too large in magnitude")


def det(u, v, w):
    """The determinant (triple product) ``det(u, v, w) = (u × v) · w`` of three 3D vectors
    (Goldman §9.4, §10.3): the signed volume of the parallelepiped they span.

    >>> float(det([1, 0, 0], [0, 2, 0], [0, 0, 3]))
    6.0
    """
    u, v, w = _vector3(u, "u"), _vector3(v, "v"), _vector3(w, "w")
    try:
        return dot(cross(u, v), w)
    except ValueError:
        raise ValueError("u, v and w are too large in magnitude: the result overflows float64") from None


def det_cofactor_terms(u, v, w) -> np.ndarray:
    """The three terms of the cofactor expansion of ``det(u, v, w)`` along its first row (Goldman §10.3),
    rows u, v, w: ``u1 (v2 w3 - v3 w2)``, ``-u2 (v1 w3 - v3 w1)``, ``u3 (v1 w2 - v2 w1)``.  Their sum is
    :func:`det`.  Vectorised over leading axes; returns shape (..., 3).

    >>> det_cofactor_terms([1, 2, 3], [0, 1, 4], [5, 6, 0]).tolist()
    [-24.0, 40.0, -15.0]
    """
    a, b, c = _vector3(u, "u"), _vector3(v, "v"), _vector3(w, "w")
    a, b, c = np.broadcast_arrays(a, b, c)
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.stack([a[..., 0] * (b[..., 1] * c[..., 2] - b[..., 2] * c[..., 1]),
                        -a[..., 1] * (b[..., 0] * c[..., 2] - b[..., 2] * c[..., 0]),
                        a[..., 2] * (b[..., 0] * c[..., 1] - b[..., 1] * c[..., 0])], axis=-1)
    return finite_result(out, "u, v and w", why="are too large in magnitude")


def length(v):
    """The length ``sqrt(v · v)`` (Goldman §9.4).

    >>> float(length([3, 4]))
    5.0
    """
    if isinstance(v, Point):
        raise TypeError("a point has no length (Goldman §9.3): take the length of a vector P - Q")
    out = finite_result(_norm(_coords(v, "v"), axis=-1), "v")
    return float(out) if out.ndim == 0 else out


def angle_between(u, v):
    """The angle between two nonzero vectors in degrees, in [0, 180] (Goldman §9.4), from
    ``atan2(|u × v|, u · v)`` in 3D (accurate near 0 and 180) and ``acos`` of the normalised dot
    product otherwise.

    >>> round(float(angle_between([1, 0, 0], [1, 1, 0])), 9)
    45.0
    """
    a, b = _coords(u, "u"), _coords(v, "v")
    if np.any(_norm(a, axis=-1) == 0) or np.any(_norm(b, axis=-1) == 0):
        raise ValueError("u and v must be nonzero: the zero vector has no direction")
    a, b = _moderate(a), _moderate(b)
    if a.shape[-1] == 3 and b.shape[-1] == 3:
        out = np.degrees(np.arctan2(_norm(cross(a, b), axis=-1), np.einsum("...i,...i->...", *np.broadcast_arrays(a, b))))
    else:
        c = dot(a, b) / (_norm(a, axis=-1) * _norm(b, axis=-1))
        out = np.degrees(np.arccos(np.clip(c, -1, 1)))
    return float(out) if np.ndim(out) == 0 else out


def dot_from_lengths(u, v):
    """The dot product from lengths alone (Goldman §9.4, by the law of cosines):
    ``u · v = |u| |v| cos θ = (|u|² + |v|² - |u - v|²) / 2`` -- no coordinates of u and v enter
    except through lengths.

    >>> round(float(dot_from_lengths([1, 2, 3], [4, -5, 6])), 9)
    12.0
    """
    a, b = _coords(u, "u"), _coords(v, "v")
    if a.shape[-1] != b.shape[-1]:
        raise ValueError(f"u and v must have the same dimension; got {a.shape[-1]} and {b.shape[-1]}")
    _not_huge(a, "u")
    _not_huge(b, "v")
    la, lb, lab = (_norm(x, axis=-1) for x in (a, b, a - b))
    out = finite_result((la ** 2 + lb ** 2 - lab ** 2) / 2, "u and v", why="are too large in magnitude")
    return float(out) if np.ndim(out) == 0 else out


def cross_from_geometry(u, v, normal) -> np.ndarray:
    """The cross product by its geometric definition (Goldman §9.4): the vector of length
    ``|u| |v| sin θ`` perpendicular to u and v, on the side of the plane of u and v that makes
    ``(u, v, u × v)`` right-handed.  ``normal`` is any vector on that side (it fixes "right-handed"
    without coordinates); the unit normal is found by removing from it its components along u and v.

    >>> cross_from_geometry([2, 0, 0], [1, 1, 0], [0.3, -0.2, 5]).round(12).tolist()
    [0.0, 0.0, 2.0]
    """
    a, b, n = _vector3(u, "u"), _vector3(v, "v"), _vector3(normal, "normal")
    _not_huge(a, "u")
    _not_huge(b, "v")
    _not_huge(n, "normal")
    la, lb = _norm(a, axis=-1), _norm(b, axis=-1)
    if np.any(la == 0) or np.any(lb == 0):
        return np.zeros(np.broadcast_shapes(a.shape, b.shape))
    e1 = a / la[..., None]
    b_perp = b - np.einsum("...i,...i->...", b, e1)[..., None] * e1
    lperp = _norm(b_perp, axis=-1)
    sin = lperp / lb
    e2 = np.where(lperp[..., None] > 0, b_perp / np.where(lperp > 0, lperp, 1)[..., None], 0.0)
    m = n - np.einsum("...i,...i->...", n, e1)[..., None] * e1 - np.einsum("...i,...i->...", n, e2)[..., None] * e2
    lm = _norm(m, axis=-1)
    if np.any((lm == 0) & (sin > 0)):
        raise ValueError("normal must not lie in the plane of u and v: it must say which side is 'up'")
    unit = m / np.where(lm > 0, lm, 1)[..., None]
    return finite_result((la * lb * sin)[..., None] * unit, "u and v", why="are too large in magnitude")


def cross_associator(u, v, w) -> np.ndarray:
    """``(u × v) × w - u × (v × w)``: the cross product is not associative (Goldman §9, Appendix A);
    by the expansion ``(a × b) × c = (a·c) b - (b·c) a`` this equals ``(u·v) w - (v·w) u``, zero only
    in special positions (for instance when v is perpendicular to both u and w).

    >>> cross_associator([1, 0, 0], [1, 0, 0], [0, 1, 0]).tolist()
    [0.0, 1.0, 0.0]
    """
    a, b, c = _vector3(u, "u"), _vector3(v, "v"), _vector3(w, "w")
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            return finite_result(cross(cross(a, b), c) - cross(a, cross(b, c)), "u, v and w")
    except ValueError:
        raise ValueError("u, v and w are too large in magnitude: the result overflows float64") from None

"""Two-dimensional affine transformations as 3x3 matrices (Goldman §4.2-4.7).

The book's convention, used everywhere in this course: **points are row vectors and a
transformation acts on the right**.  A point ``P = (x, y)`` gets affine coordinates ``(x, y, 1)``
and a vector ``v = (a, b)`` gets ``(a, b, 0)``; an affine map is a 3x3 matrix

    M = | a  b  0 |        (x, y, 1) @ M = (a x + c y + e,  b x + d y + f,  1)
        | c  d  0 |
        | e  f  1 |

whose upper-left 2x2 block ``L`` is the linear part and whose **last row** ``(e, f)`` is the
translation (§4.5).  Vectors ignore the translation: ``(a, b, 0) @ M = (a, b) @ L``.  Composition
reads left to right: ``P @ M1 @ M2`` applies ``M1`` first, so ``compose(M1, M2) = M1 @ M2``.

Angles are in degrees (counterclockwise positive), as in the turtle language.

>>> M = compose(rotation(90), translation([1, 0]))
>>> apply([[1, 0]], M).round(12)
array([[1., 1.]])

Importing this module imports numpy only.
"""

from __future__ import annotations

import math

import numpy as np

from .angles import cos_sin_degrees
from .validation import as_float, as_float_array, as_points, as_tolerance, check_finite

__all__ = [
    "identity", "translation", "rotation", "scaling", "directional_scaling", "shear", "similarity",
    "from_parameters", "to_parameters", "affine_from_point_and_vectors", "affine_from_points",
    "apply", "apply_vectors", "compose", "inverse", "as_affine", "linear_part", "translation_part",
    "fixed_point", "is_conformal", "is_similarity", "conformal_from_point_and_vector",
    "mirror", "affine_coordinates", "vector_coordinates", "affine_combination", "barycentric_coordinates",
    "commute", "is_rigid",
]


def _point(p, name: str) -> np.ndarray:
    return as_points(p, name, ndim=1, dim=2)


def _matrix(L, t=(0.0, 0.0)) -> np.ndarray:
    M = np.eye(3)
    M[:2, :2] = L
    M[2, :2] = t
    return M


def _square(x: float) -> float:
    """``x**2`` for a size in a tolerance, inf rather than an OverflowError for a huge ``x``."""
    return x * x if x < 1e154 else math.inf


def _finite(M: np.ndarray, names: str) -> np.ndarray:
    """``M`` if every entry is finite; otherwise a ValueError saying which inputs overflowed it."""
    if not np.all(np.isfinite(M)):
        raise ValueError(f"{names} too large: the result overflows a float (entries became infinite or "
                         f"undefined); use smaller values")
    return M


def _factor(factor, name: str) -> np.ndarray:
    f = as_float_array(factor, name)
    if f.ndim == 0:
        f = np.array([f, f])
    if f.shape != (2,):
        raise ValueError(f"{name} must be a number or a pair (sx, sy); got shape {f.shape}")
    return check_finite(f, name)


def _squared_extent(arr: np.ndarray, name: str) -> float:
    """The square of the largest absolute entry of ``arr`` (a scale for collinearity tests), or a
    ValueError naming ``name`` when it overflows a float."""
    m = float(np.abs(arr).max())
    sq = m * m
    if not math.isfinite(sq):
        raise ValueError(f"{name} is too large in magnitude: its squared size overflows a float; use smaller values")
    return sq


def _about(M: np.ndarray, center, names: str = "center or the map's parameters are") -> np.ndarray:
    """Conjugate ``M`` by the translation taking ``center`` to the origin (a map about a point).
    names: the parameters to blame if the result overflows."""
    if center is None:
        return M
    c = _point(center, "center")
    with np.errstate(over="ignore", invalid="ignore"):
        out = translation(-c) @ M @ translation(c)
    return _finite(out, names)


def as_affine(M, name: str = "M") -> np.ndarray:
    """Validate a 3x3 affine matrix (or a stack ``(..., 3, 3)``) in the row-vector convention (§4.5).

    The last column must be ``(0, 0, 1)``: the translation sits in the last row.  Returns a float
    copy.  Raises ValueError naming ``name`` and the rule it breaks.

    >>> as_affine([[1, 0, 0], [0, 1, 0], [2, 3, 1]])[2]
    array([2., 3., 1.])
    >>> as_affine([[1, 0, 2], [0, 1, 3], [0, 0, 1]])
    Traceback (most recent call last):
    ...
    ValueError: M must have last column (0, 0, 1) (row-vector convention: the translation is the last row); got column [2. 3. 1.]
    """
    try:
        arr = as_float_array(M, name).copy()
    except TypeError as exc:
        raise TypeError(f"{name} must be a 3x3 numeric matrix of real numbers; got {type(M).__name__} ({exc})") from None
    if arr.ndim < 2 or arr.shape[-2:] != (3, 3):
        raise ValueError(f"{name} must have shape (3, 3) (or a stack (k, 3, 3)); got shape {arr.shape}")
    check_finite(arr, name)
    col = arr[..., :, 2]
    bad = ~np.all(np.isclose(col, [0.0, 0.0, 1.0], atol=1e-12), axis=-1)
    if np.any(bad):
        where = np.argwhere(np.atleast_1d(bad))[0]
        shown = col if arr.ndim == 2 else col[tuple(where)]
        label = name if arr.ndim == 2 else f"{name}[{', '.join(map(str, where))}]"
        raise ValueError(f"{label} must have last column (0, 0, 1) (row-vector convention: the translation "
                         f"is the last row); got column {shown}")
    return arr


def identity() -> np.ndarray:
    """The identity map (Goldman §4.5).

    >>> identity()[2]
    array([0., 0., 1.])
    """
    return np.eye(3)


def translation(v) -> np.ndarray:
    """Translation by the vector ``v`` (Goldman §4.2.1): ``P -> P + v``; ``v`` is the last row.

    v: (2,).  Raises ValueError if ``v`` is not a finite 2-vector.

    >>> apply([[1, 1]], translation([2, -1]))
    array([[3., 0.]])
    """
    return _matrix(np.eye(2), _point(v, "v"))


def rotation(angle, center=None) -> np.ndarray:
    """Rotation by ``angle`` degrees counterclockwise about ``center`` (default the origin) (Goldman §4.2.2).

    About the origin the linear part is ``[[cos, sin], [-sin, cos]]`` (row vectors, acting on the
    right); about a point Q it is ``T(-Q) R T(Q)`` (§4.4).

    >>> apply([[2, 1]], rotation(90, center=[1, 1])).round(12)
    array([[1., 2.]])
    """
    c, s = cos_sin_degrees(as_float(angle, "angle"))
    return _about(_matrix([[c, s], [-s, c]]), center)


def scaling(factor, center=None) -> np.ndarray:
    """Scaling about ``center`` (default the origin) (Goldman §4.2.3, §4.7.2).

    factor: a number (uniform scaling, §4.2.3) or a pair ``(sx, sy)`` (nonuniform scaling along the
    coordinate axes).  A zero factor is allowed (it collapses the plane onto a line or point, as
    the condensation maps of an IFS may); use :func:`inverse` to find out if a map is invertible.

    >>> apply([[3, 1]], scaling(2, center=[1, 1]))
    array([[5., 1.]])
    >>> apply([[1, 1]], scaling([2, 3]))
    array([[2., 3.]])
    """
    return _about(_matrix(np.diag(_factor(factor, "factor"))), center, "factor or center are")


def directional_scaling(factor, direction, center=None) -> np.ndarray:
    """Nonuniform scaling by ``factor`` along ``direction`` about ``center`` (Goldman §4.7.2).

    Components parallel to the unit vector ``w`` are multiplied by ``factor``; perpendicular
    components are unchanged: ``v -> v + (factor - 1) (v . w) w``.

    direction: (2,) nonzero vector.  Raises ValueError for a zero direction.

    >>> apply([[1, 1]], directional_scaling(3, [1, 0]))
    array([[3., 1.]])
    """
    s = as_float(factor, "factor")
    w = _point(direction, "direction")
    n = math.hypot(*w)
    if n == 0:
        raise ValueError("direction must be a nonzero vector; got (0, 0)")
    w = w / n
    with np.errstate(over="ignore", invalid="ignore"):
        L = _finite(np.eye(2) + (s - 1.0) * np.outer(w, w), "factor is")
    return _about(_matrix(L), center, "factor or center are")


def shear(k, center=None) -> np.ndarray:
    """The horizontal shear ``(x, y) -> (x + k y, y)`` about ``center`` (Goldman §4.7).

    >>> apply([[1, 2]], shear(0.5))
    array([[2., 2.]])
    """
    return _about(_matrix([[1.0, 0.0], [as_float(k, "k"), 1.0]]), center, "k or center are")


def similarity(scale, angle, translate=(0.0, 0.0), *, reflect: bool = False) -> np.ndarray:
    """A similarity: scale by ``scale``, optionally reflect in the x-axis, rotate by ``angle``
    degrees, then translate (Goldman §8.3: the maps of a conformal IFS).  Without ``reflect`` it
    is conformal in the book's sense (§4.6, :func:`is_conformal`); with it, it is a mirror image
    of a conformal map (:func:`is_similarity` only).

    >>> apply([[1, 0]], similarity(0.5, 90, [1, 1])).round(12)
    array([[1. , 1.5]])
    """
    M = scaling(as_float(scale, "scale"))
    translate = _point(translate, "translate")
    if reflect:
        M = M @ scaling([1.0, -1.0])
    with np.errstate(over="ignore", invalid="ignore"):
        out = M @ rotation(angle) @ translation(translate)
    return _finite(out, "scale or translate is")


def from_parameters(angle=0.0, scale=(1.0, 1.0), shear=0.0, translate=(0.0, 0.0)) -> np.ndarray:
    """The map "scale, then shear, then rotate, then translate" (the IFS editor's sliders).

    ``M = S(sx, sy) H(shear) R(angle) T(translate)``, so a point is scaled along the axes first,
    sheared ``(x, y) -> (x + shear y, y)``, rotated counterclockwise by ``angle`` degrees and
    translated last.  Every 2D affine map has this form (:func:`to_parameters` inverts it), so a
    handful of sliders reach every map.

    >>> M = from_parameters(angle=30, scale=(0.5, 0.25), shear=0.2, translate=(1, 2))
    >>> np.allclose(from_parameters(**to_parameters(M)), M)
    True
    """
    H = _matrix([[1.0, 0.0], [as_float(shear, "shear"), 1.0]])
    S = _matrix(np.diag(_factor(scale, "scale")))
    translate = _point(translate, "translate")
    with np.errstate(over="ignore", invalid="ignore"):
        out = S @ H @ rotation(angle) @ translation(translate)
    return _finite(out, "scale, shear or translate is")


def to_parameters(M) -> dict:
    """The parameters ``angle, scale, shear, translate`` with ``from_parameters(**p) == M``.

    Write the linear part as ``L = D H R`` (diagonal, shear, rotation).  Row 0 of ``L`` is
    ``sx (cos a, sin a)``, which gives ``a`` and ``sx >= 0``; row 1 times ``R^T`` is
    ``(sy h, sy)``.  A reflection shows up as ``sy < 0``.  If row 0 is zero the angle is taken as 0.

    >>> p = to_parameters(rotation(90) @ translation([1, 2]))
    >>> round(p["angle"], 9), p["scale"], p["translate"]
    (90.0, (1.0, 1.0), (1.0, 2.0))
    """
    M = as_affine(M)
    L = M[:2, :2]
    sx = math.hypot(L[0, 0], L[0, 1])
    angle = math.degrees(math.atan2(L[0, 1], L[0, 0])) if sx > 0 else 0.0
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    R = np.array([[c, s], [-s, c]])
    v = L[1] @ R.T
    sy = float(v[1])
    with np.errstate(over="ignore"):
        h = float(v[0] / sy) if sy != 0 else 0.0
    if not math.isfinite(h):
        raise ValueError("M is too close to singular: its shear parameter overflows a float")
    return {"angle": angle, "scale": (float(sx), sy), "shear": h,
            "translate": (float(M[2, 0]), float(M[2, 1]))}


def affine_from_point_and_vectors(point, vectors, image_point, image_vectors) -> np.ndarray:
    """The unique affine map sending a point and two vectors to given images (Goldman §4.7.1).

    point, image_point: (2,).  vectors, image_vectors: (2, 2), one vector per row; the two
    ``vectors`` must be linearly independent.  Then ``L = V^-1 W`` and the translation makes
    ``point -> image_point``.  Raises ValueError if the vectors are parallel.

    >>> M = affine_from_point_and_vectors([0, 0], [[1, 0], [0, 1]], [1, 1], [[0, 1], [-1, 0]])
    >>> np.allclose(M, rotation(90) @ translation([1, 1]))
    True
    """
    P = _point(point, "point")
    Q = _point(image_point, "image_point")
    V = as_points(vectors, "vectors", dim=2)
    W = as_points(image_vectors, "image_vectors", dim=2)
    if V.shape != (2, 2) or W.shape != (2, 2):
        raise ValueError(f"vectors and image_vectors must each hold two 2D vectors, shape (2, 2); "
                         f"got {V.shape} and {W.shape}")
    det = V[0, 0] * V[1, 1] - V[0, 1] * V[1, 0]
    if abs(det) <= 1e-12 * max(1.0, _squared_extent(V, "vectors")):
        raise ValueError(f"vectors must be linearly independent; {V[0]} and {V[1]} are parallel")
    with np.errstate(over="ignore", invalid="ignore"):
        L = np.linalg.solve(V, W)
        out = _matrix(L, Q - P @ L)
    return _finite(out, "the points or vectors are")


def conformal_from_point_and_vector(point, vector, image_point, image_vector) -> np.ndarray:
    """The unique conformal map (translation, rotation and uniform scaling, no mirror) sending a
    point and one nonzero vector to given images (Goldman §4.6).

    A conformal map is multiplication by a complex number followed by a translation,
    ``z -> c z + d``; in the row-vector convention its linear part is ``[[a, b], [-b, a]]`` with
    ``c = a + i b``.  So one vector fixes it: ``c = image_vector / vector`` (complex division:
    the scale factor is the ratio of lengths, the angle the angle between them), and ``point ->
    image_point`` fixes ``d``.  A general affine map needs two vectors
    (:func:`affine_from_point_and_vectors`).  point, image_point, vector, image_vector: (2,).
    Raises ValueError for a zero ``vector``.

    >>> M = conformal_from_point_and_vector([0, 0], [1, 0], [1, 1], [0, 2])
    >>> np.allclose(M, scaling(2) @ rotation(90) @ translation([1, 1])), is_conformal(M)
    (True, True)
    """
    P = _point(point, "point")
    Q = _point(image_point, "image_point")
    v = _point(vector, "vector")
    w = _point(image_vector, "image_vector")
    if math.hypot(*v) == 0:
        raise ValueError("vector must be a nonzero vector; got (0, 0)")
    with np.errstate(over="ignore", invalid="ignore"):
        c = complex(w[0], w[1]) / complex(v[0], v[1])
        L = np.array([[c.real, c.imag], [-c.imag, c.real]])
        out = _matrix(L, Q - P @ L)
    return _finite(out, "the points or vectors are")


def affine_from_points(src, dst) -> np.ndarray:
    """The unique affine map sending three non-collinear points to three points (Goldman §4.7.3).

    src, dst: (3, 2).  Solves ``[src | 1] @ M = [dst | 1]``.  Raises ValueError if the source
    points are collinear (then no map, or infinitely many, exist).

    >>> M = affine_from_points([[0, 0], [1, 0], [0, 1]], [[1, 1], [3, 1], [1, 4]])
    >>> M.round(12)
    array([[2., 0., 0.],
           [0., 3., 0.],
           [1., 1., 1.]])
    """
    A = as_points(src, "src", dim=2)
    B = as_points(dst, "dst", dim=2)
    if A.shape != (3, 2) or B.shape != (3, 2):
        raise ValueError(f"src and dst must each hold three 2D points, shape (3, 2); got {A.shape} and {B.shape}")
    u, v = A[1] - A[0], A[2] - A[0]
    area2 = u[0] * v[1] - u[1] * v[0]
    with np.errstate(over="ignore", invalid="ignore"):
        spread = A - A[0]
    scale = max(1.0, _squared_extent(spread, "src"))
    if abs(area2) <= 1e-12 * scale:
        raise ValueError(f"src points must not be collinear; {A.tolist()} lie on one line")
    H = np.column_stack([A, np.ones(3)])
    with np.errstate(over="ignore", invalid="ignore"):
        M = np.linalg.solve(H, np.column_stack([B, np.ones(3)]))
    M[:, 2] = (0.0, 0.0, 1.0)
    return _finite(M, "src or dst is")


def apply(points, M) -> np.ndarray:
    """Apply an affine map to points (Goldman §4.5): ``Q = [P 1] @ M``.

    points: (..., 2).  M: (3, 3).  Returns the same shape as ``points``.

    >>> apply([[0, 0], [1, 0]], translation([0, 1]))
    array([[0., 1.],
           [1., 1.]])
    """
    P = as_points(points, "points", ndim=None, dim=2)
    M = as_affine(M)
    with np.errstate(over="ignore", invalid="ignore"):
        Q = P @ M[:2, :2] + M[2, :2]
    return _finite(Q, "points or M is")


def apply_vectors(vectors, M) -> np.ndarray:
    """Apply an affine map to vectors (Goldman §4.5): ``[v 0] @ M``, the translation ignored.

    >>> apply_vectors([[1, 0]], translation([5, 5]))
    array([[1., 0.]])
    """
    V = as_points(vectors, "vectors", ndim=None, dim=2)
    M = as_affine(M)
    with np.errstate(over="ignore", invalid="ignore"):
        W = V @ M[:2, :2]
    return _finite(W, "vectors or M is")


def compose(*maps) -> np.ndarray:
    """The map that applies ``maps[0]`` first, then ``maps[1]``, ... (Goldman §4.3): their product
    left to right, since points are row vectors.

    >>> np.allclose(compose(translation([1, 0]), rotation(90)), translation([1, 0]) @ rotation(90))
    True
    """
    out = np.eye(3)
    for i, M in enumerate(maps):
        with np.errstate(over="ignore", invalid="ignore"):
            out = out @ as_affine(M, f"maps[{i}]")
        _finite(out, f"maps (up to maps[{i}]) are")
    return out


def inverse(M) -> np.ndarray:
    """The inverse affine map (Goldman §4.3).  Raises ValueError if ``M`` is singular.

    >>> np.allclose(inverse(rotation(30)) @ rotation(30), np.eye(3))
    True
    """
    M = as_affine(M)
    det = np.linalg.det(M[:2, :2])
    if abs(det) < 1e-14:
        raise ValueError(f"M must be invertible; its linear part has determinant {det:.3g}")
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.linalg.inv(M)
    out[:, 2] = (0.0, 0.0, 1.0)
    return _finite(out, "M is too close to singular or")


def linear_part(M) -> np.ndarray:
    """The 2x2 linear part of an affine map (acting on row vectors).

    >>> linear_part(scaling(2))
    array([[2., 0.],
           [0., 2.]])
    """
    return as_affine(M)[..., :2, :2].copy()


def translation_part(M) -> np.ndarray:
    """The translation of an affine map: its last row, the image of the origin.

    >>> translation_part(translation([1, 2]))
    array([1., 2.])
    """
    return as_affine(M)[..., 2, :2].copy()


def fixed_point(M) -> np.ndarray:
    """The fixed point ``P = P M`` of an affine map (Goldman §6.2, §7.2).

    Solves ``P (I - L) = t``.  Every contraction has exactly one fixed point.  Raises ValueError if
    ``I - L`` is singular (no fixed point, or a whole line of them).

    >>> fixed_point(scaling(0.5, center=[2, 1]))
    array([2., 1.])
    """
    M = as_affine(M)
    A = np.eye(2) - M[:2, :2]
    if abs(np.linalg.det(A)) < 1e-14:
        raise ValueError("M must have a unique fixed point; I - L is singular (1 is an eigenvalue of its linear part)")
    with np.errstate(over="ignore", invalid="ignore"):
        P = np.linalg.solve(A.T, M[2, :2])
    return _finite(P, "M is too close to having no fixed point, or its translation is")


def is_similarity(M, tol: float = 1e-9) -> bool:
    """Whether a map multiplies every distance by one factor (a similarity: translation, rotation,
    uniform scaling, **and reflection**), Goldman §4.6.  True iff ``L L^T`` is a multiple of the
    identity.  Mirrors preserve the size of angles but reverse their orientation, so a similarity
    is conformal in the book's sense (:func:`is_conformal`) only if it does not reflect.

    >>> is_similarity(mirror([0, 0], [1, 0])), is_similarity(scaling([1, 2]))
    (True, False)
    """
    tol = as_tolerance(tol)
    L = as_affine(M)[:2, :2]
    with np.errstate(over="ignore", invalid="ignore"):
        G = _finite(L @ L.T, "M is")
    return bool(abs(G[0, 1]) <= tol * max(1.0, abs(G[0, 0])) and abs(G[0, 0] - G[1, 1]) <= tol * max(1.0, abs(G[0, 0])))


def is_conformal(M, tol: float = 1e-9) -> bool:
    """Whether a map is conformal in the book's sense: a composite of translation, rotation and
    uniform scaling, **no mirror** (Goldman §4.6, §8.2: what a turtle can do by changing its state).

    In the row-vector convention the linear part is then ``[[a, b], [-b, a]]`` (``s`` times a
    rotation, ``a = s cos t``, ``b = s sin t``), the matrix of multiplication by a complex number.
    A mirror is a similarity (:func:`is_similarity`) but not conformal here: it reverses
    orientation.  The degenerate scaling by 0 (``a = b = 0``) passes.

    >>> is_conformal(similarity(0.5, 30, [1, 2])), is_conformal(scaling([1, 2]))
    (True, False)
    >>> is_conformal(mirror([0, 0], [1, 0]))
    False
    """
    tol = as_tolerance(tol)
    L = as_affine(M)[:2, :2]
    with np.errstate(over="ignore", invalid="ignore"):
        size = _finite(np.abs(L).max(), "M is")
    bound = tol * max(1.0, float(size))
    return bool(abs(L[0, 0] - L[1, 1]) <= bound and abs(L[0, 1] + L[1, 0]) <= bound)


# ---------------------------------------------------------------------------------------------
# Chapter 4 additions: mirrors, affine coordinates, affine combinations, the algebra of §4.3
# ---------------------------------------------------------------------------------------------

def mirror(point, direction) -> np.ndarray:
    """Reflection in the line through ``point`` with direction ``direction`` (Goldman §4.7.2).

    A mirror is the nonuniform scaling by ``-1`` along the unit normal ``n`` of the line, about a
    point of the line: ``v -> v - 2 (v . n) n``.  point: (2,).  direction: (2,) nonzero.
    Raises ValueError for a zero direction.

    >>> apply([[3, 0]], mirror([0, 1], [1, 0]))
    array([[3., 2.]])
    >>> apply([[1, 0]], mirror([0, 0], [1, 1])).round(12)
    array([[0., 1.]])
    """
    P = _point(point, "point")
    w = _point(direction, "direction")
    if math.hypot(*w) == 0:
        raise ValueError("direction must be a nonzero vector; got (0, 0)")
    return directional_scaling(-1.0, [-w[1], w[0]], center=P)


def affine_coordinates(points) -> np.ndarray:
    """Affine coordinates of points (Goldman §4.5): ``(x, y) -> (x, y, 1)``.

    points: (..., 2).  Returns (..., 3).  A point times an affine matrix is translated;
    compare :func:`vector_coordinates`, whose last coordinate 0 makes vectors ignore translation.

    >>> affine_coordinates([[2, 3]]) @ translation([1, 1])
    array([[3., 4., 1.]])
    """
    P = as_points(points, "points", ndim=None, dim=2)
    return np.concatenate([P, np.ones(P.shape[:-1] + (1,))], axis=-1)


def vector_coordinates(vectors) -> np.ndarray:
    """Affine coordinates of vectors (Goldman §4.5): ``(a, b) -> (a, b, 0)``.

    vectors: (..., 2).  Returns (..., 3).

    >>> vector_coordinates([[2, 3]]) @ translation([1, 1])
    array([[2., 3., 0.]])
    """
    V = as_points(vectors, "vectors", ndim=None, dim=2)
    return np.concatenate([V, np.zeros(V.shape[:-1] + (1,))], axis=-1)


def affine_combination(points, weights, *, tol: float = 1e-9) -> np.ndarray:
    """The affine combination ``sum_k c_k P_k`` of points whose weights sum to 1 (Goldman §4.3).

    An affine combination is a point wherever the origin is put, and affine maps preserve it:
    ``A(sum c_k P_k) = sum c_k A(P_k)``.  points: (k, 2).  weights: (k,), summing to 1 within
    ``tol``.  Raises ValueError if the weights do not sum to 1 (then the "combination" depends on
    the choice of origin: ``P + Q`` is not a point).

    >>> affine_combination([[0, 0], [2, 4]], [0.5, 0.5])
    array([1., 2.])
    """
    tol = as_tolerance(tol)
    P = as_points(points, "points", dim=2)
    c = as_points(np.reshape(as_float_array(weights, "weights"), (-1, 1)), "weights", dim=1)[:, 0]
    if c.shape[0] != P.shape[0]:
        raise ValueError(f"weights must hold one weight per point; got {c.shape[0]} weights for {P.shape[0]} points")
    total = float(c.sum())
    if abs(total - 1.0) > tol:
        raise ValueError(f"weights must sum to 1 for an affine combination of points; they sum to {total:.6g}")
    with np.errstate(over="ignore", invalid="ignore"):
        out = c @ P
    return _finite(out, "points or weights are")


def barycentric_coordinates(points, triangle) -> np.ndarray:
    """Barycentric coordinates of points with respect to a triangle (Goldman §4.5, §4.7.3).

    The weights ``(a, b, c)``, summing to 1, with ``P = a T0 + b T1 + c T2``.  An affine map
    preserves them: that is why three points and their images fix the map.  points: (..., 2).
    triangle: (3, 2), not collinear.  Returns (..., 3).  Raises ValueError for a collinear
    triangle.

    >>> barycentric_coordinates([[0.25, 0.5]], [[0, 0], [1, 0], [0, 1]])
    array([[0.25, 0.25, 0.5 ]])
    """
    P = as_points(points, "points", ndim=None, dim=2)
    T = as_points(triangle, "triangle", dim=2)
    if T.shape != (3, 2):
        raise ValueError(f"triangle must hold three 2D points, shape (3, 2); got {T.shape}")
    u, v = T[1] - T[0], T[2] - T[0]
    area2 = u[0] * v[1] - u[1] * v[0]
    with np.errstate(over="ignore", invalid="ignore"):
        spread = T - T[0]
    if abs(area2) <= 1e-12 * max(1.0, _squared_extent(spread, "triangle")):
        raise ValueError(f"triangle must not be collinear; {T.tolist()} lie on one line")
    with np.errstate(over="ignore", invalid="ignore"):
        d = P - T[0]
        b = (d[..., 0] * v[1] - d[..., 1] * v[0]) / area2
        c = (u[0] * d[..., 1] - u[1] * d[..., 0]) / area2
        out = np.stack([1.0 - b - c, b, c], axis=-1)
    return _finite(out, "points or triangle are")


def commute(M, N, tol: float = 1e-9) -> bool:
    """Whether two affine maps commute, ``M N = N M`` (Goldman §4.3).

    Translations commute with each other, and so do rotations (and uniform scalings) about the
    same point; a translation and a rotation do not.

    >>> commute(rotation(30, [1, 2]), rotation(50, [1, 2])), commute(rotation(30), translation([1, 0]))
    (True, False)
    """
    tol = as_tolerance(tol)
    A, B = as_affine(M, "M"), as_affine(N, "N")
    with np.errstate(over="ignore", invalid="ignore"):
        AB, BA = _finite(A @ B, "M or N is"), _finite(B @ A, "M or N is")
    return bool(np.allclose(AB, BA, atol=tol, rtol=0))


def is_rigid(M, tol: float = 1e-9) -> bool:
    """Whether a map is a rigid motion (Goldman §4.4): it preserves lengths, ``L L^T = I``.

    >>> is_rigid(rotation(30, [1, 2]) @ translation([3, 0])), is_rigid(scaling(2))
    (True, False)
    """
    tol = as_tolerance(tol)
    L = as_affine(M)[:2, :2]
    with np.errstate(over="ignore", invalid="ignore"):
        G = _finite(L @ L.T, "M is")
    return bool(np.allclose(G, np.eye(2), atol=tol, rtol=0))

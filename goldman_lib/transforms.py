"""Affine and projective transformations of 3-space: the coordinate-free formulas of Goldman
Chapter 12 and their 4x4 matrices (Chapter 13).

Convention (the book's, as everywhere in this library): points are **row vectors** and a matrix
acts on the right, ``[Q 1] = [P 1] @ M``.  A 4x4 matrix holds the linear part in its upper-left
3x3 block, the translation in its **last row**, and (for projections) the homogeneous column in
its last column; :func:`apply` multiplies and divides by the homogeneous coordinate.

Each transformation exists twice: as a function on points written with dot and cross products
(``rotate``, ``reflect``, ``scale``, ``scale_along``, ``project_orthogonal``,
``project_perspective``, ``translate`` -- Chapter 12) and as the matrix that does the same
(``rotation``, ``mirror``, ``scaling``, ``nonuniform_scaling``, ``orthogonal_projection``,
``perspective``, ``translation`` -- Chapter 13).  The tests check every pair agrees.

>>> M = rotation([0, 0, 1], 90)
>>> (np.round(apply([[1, 0, 0]], M), 12) + 0.0).tolist()
[[0.0, 1.0, 0.0]]
>>> (np.round(rotate([[1, 0, 0]], [0, 0, 1], 90), 12) + 0.0).tolist()
[[0.0, 1.0, 0.0]]
"""

from __future__ import annotations

import functools

import numpy as np

from goldman_lib.validation import as_float, as_float_array, as_points, check_finite, finite_result
from goldman_lib.kernels.frames import norm as _norm

__all__ = ["translation", "rotation", "mirror", "scaling", "nonuniform_scaling", "orthogonal_projection",
           "perspective", "apply", "homogeneous", "apply_to_vectors", "compose", "affine_from_points",
           "rigid_inverse", "translate", "rotate", "reflect", "scale", "scale_along",
           "project_orthogonal", "project_perspective"]


def _refuses_overflow(names: str):
    """The rule of every function here: a result float64 cannot hold is a ValueError naming the
    inputs that made it (``names``), never an inf or NaN (as in :mod:`goldman_lib.affine`)."""
    def decorate(fn):
        @functools.wraps(fn)
        def checked(*args, **kwargs):
            with np.errstate(over="ignore", invalid="ignore"):
                out = fn(*args, **kwargs)
            return finite_result(out, names, why="too large in magnitude")
        return checked
    return decorate


def _point(x, name: str) -> np.ndarray:
    arr = check_finite(as_float_array(x, name), name)
    if arr.shape != (3,):
        raise ValueError(f"{name} must be one 3D point or vector (shape (3,)); got shape {arr.shape}")
    return arr


def _unit(x, name: str, what: str) -> np.ndarray:
    v = _point(x, name)
    n = _norm(v)                       # right at any magnitude: only the direction matters
    if n == 0:
        raise ValueError(f"{name} must be a nonzero vector: {what}")
    return v / n


def _points(points) -> np.ndarray:
    return as_points(points, "points", ndim=None, dim=3)


def _affine(linear: np.ndarray, fixed: np.ndarray) -> np.ndarray:
    """The 4x4 matrix with linear part ``linear`` (row convention) fixing the point ``fixed``."""
    M = np.eye(4)
    M[:3, :3] = linear
    M[3, :3] = fixed - fixed @ linear
    return M


def _cross_matrix(w: np.ndarray) -> np.ndarray:
    """The 3x3 matrix A with ``v @ A == w × v`` for row vectors v."""
    return np.array([[0.0, w[2], -w[1]], [-w[2], 0.0, w[0]], [w[1], -w[0], 0.0]])


# -- Chapter 12: the formulas on points -------------------------------------------------------------

@_refuses_overflow("points or v is")
def translate(points, v) -> np.ndarray:
    """``P + v`` (Goldman §12.3.1).

    >>> translate([[1, 2, 3]], [1, 0, -1]).tolist()
    [[2.0, 2.0, 2.0]]
    """
    return _points(points) + _point(v, "v")


@_refuses_overflow("points or point is")
def rotate(points, axis, angle, point=None) -> np.ndarray:
    """Rotate points by ``angle`` degrees about the line through ``point`` (default the origin) along
    ``axis``, counterclockwise looking down the axis (Goldman §12.3.2, Rodrigues' formula):
    ``R(v) = cos θ v + (1 - cos θ)(v·w) w + sin θ (w × v)`` applied to ``v = P - Q``.

    >>> (np.round(rotate([[1, 0, 5]], [0, 0, 2], 180, point=[1, 1, 0]), 12) + 0.0).tolist()
    [[1.0, 2.0, 5.0]]
    """
    P = _points(points)
    w = _unit(axis, "axis", "a rotation needs an axis direction")
    th = np.radians(as_float(angle, "angle"))
    Q = np.zeros(3) if point is None else _point(point, "point")
    v = P - Q
    c, s = np.cos(th), np.sin(th)
    return Q + c * v + (1 - c) * (v @ w)[..., None] * w + s * np.cross(w, v)


@_refuses_overflow("points or plane_point is")
def reflect(points, plane_point, normal) -> np.ndarray:
    """Mirror points in the plane through ``plane_point`` with ``normal`` (Goldman §12.3.3):
    ``P - 2 ((P - Q)·N) N`` for the unit normal N.

    >>> reflect([[1, 2, 3]], [0, 0, 1], [0, 0, 5]).tolist()
    [[1.0, 2.0, -1.0]]
    """
    P = _points(points)
    Q = _point(plane_point, "plane_point")
    N = _unit(normal, "normal", "a mirror plane needs a normal direction")
    return P - 2 * ((P - Q) @ N)[..., None] * N


@_refuses_overflow("points, s or center is")
def scale(points, s, center=None) -> np.ndarray:
    """Uniform scaling by ``s`` about ``center`` (default the origin): ``Q + s (P - Q)`` (Goldman §12.4).

    >>> scale([[2, 2, 2]], 3, center=[1, 1, 1]).tolist()
    [[4.0, 4.0, 4.0]]
    """
    P = _points(points)
    s = as_float(s, "s")
    Q = np.zeros(3) if center is None else _point(center, "center")
    return Q + s * (P - Q)


@_refuses_overflow("points, s or center is")
def scale_along(points, s, direction, center=None) -> np.ndarray:
    """Nonuniform scaling by ``s`` along ``direction`` about ``center`` (Goldman §12.4):
    ``P + (s - 1)((P - Q)·w) w`` for the unit direction w; directions perpendicular to w are kept.

    >>> scale_along([[1, 1, 1]], 3, [0, 1, 0]).tolist()
    [[1.0, 3.0, 1.0]]
    """
    P = _points(points)
    s = as_float(s, "s")
    w = _unit(direction, "direction", "a scaling needs a direction to stretch along")
    Q = np.zeros(3) if center is None else _point(center, "center")
    return P + (s - 1) * ((P - Q) @ w)[..., None] * w


@_refuses_overflow("points or plane_point is")
def project_orthogonal(points, plane_point, normal) -> np.ndarray:
    """Orthogonal projection onto the plane (Goldman §12.5): ``P - ((P - Q)·N) N`` for the unit N.

    >>> project_orthogonal([[1, 2, 3]], [0, 0, 1], [0, 0, 1]).tolist()
    [[1.0, 2.0, 1.0]]
    """
    P = _points(points)
    Q = _point(plane_point, "plane_point")
    N = _unit(normal, "normal", "a plane needs a normal direction")
    return P - ((P - Q) @ N)[..., None] * N


def _check_perspective(eye, Q, N):
    with np.errstate(over="ignore", invalid="ignore"):
        gap = _norm(Q - eye)
    finite_result(np.asarray(gap), "plane_point", why="is too far from eye")
    if abs((Q - eye) @ N) <= 1e-12 * (1 + gap):
        raise ValueError("eye must not lie on the plane of projection (the plane through plane_point with normal "
                         "normal): every line through it would meet the plane at the eye itself")


@_refuses_overflow("points, eye or plane_point is")
def project_perspective(points, eye, plane_point, normal) -> np.ndarray:
    """Perspective projection from ``eye`` onto the plane (Goldman §12.5): the point where the line
    from the eye through P meets the plane, ``E + [(Q - E)·N / (P - E)·N] (P - E)``.

    Raises ValueError for a point whose line of sight is parallel to the plane ((P - E)·N = 0: its
    image is at infinity) and for an eye on the plane.

    >>> project_perspective([[2, 4, 2]], [0, 0, 0], [0, 0, 1], [0, 0, 1]).tolist()
    [[1.0, 2.0, 1.0]]
    """
    P = _points(points)
    E = _point(eye, "eye")
    Q = _point(plane_point, "plane_point")
    N = _unit(normal, "normal", "a plane needs a normal direction")
    _check_perspective(E, Q, N)
    d = (P - E) @ N
    if np.any(np.abs(d) <= 1e-12 * (1 + _norm(P - E))):
        raise ValueError("points must not lie on the plane through the eye parallel to the projection plane: "
                         "their images are at infinity")
    return E + (((Q - E) @ N) / d)[..., None] * (P - E)


# -- Chapter 13: the same maps as 4x4 matrices --------------------------------------------------------

def translation(v) -> np.ndarray:
    """The 4x4 matrix of translation by ``v`` (Goldman §13.3.1): the identity with ``v`` in the last row.

    >>> translation([1, 2, 3])[3].tolist()
    [1.0, 2.0, 3.0, 1.0]
    """
    M = np.eye(4)
    M[3, :3] = _point(v, "v")
    return M


@_refuses_overflow("point is")
def rotation(axis, angle, point=None) -> np.ndarray:
    """The 4x4 matrix of the rotation of :func:`rotate` (Goldman §13.3): linear part
    ``cos θ I + (1 - cos θ) wᵀw + sin θ A_w`` with ``v A_w = w × v``, and the translation row that
    keeps ``point`` fixed.

    >>> (np.round(rotation([1, 0, 0], 90)[:3, :3], 12) + 0.0).tolist()
    [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]]
    """
    w = _unit(axis, "axis", "a rotation needs an axis direction")
    th = np.radians(as_float(angle, "angle"))
    Q = np.zeros(3) if point is None else _point(point, "point")
    c, s = np.cos(th), np.sin(th)
    linear = c * np.eye(3) + (1 - c) * np.outer(w, w) + s * _cross_matrix(w)
    return _affine(linear, Q)


@_refuses_overflow("plane_point is")
def mirror(plane_point, normal) -> np.ndarray:
    """The 4x4 matrix of the mirror of :func:`reflect` (Goldman §13.3): linear part ``I - 2 NᵀN``,
    translation row ``2 (Q·N) N``.  An involution with determinant -1.

    >>> mirror([0, 0, 1], [0, 0, 1])[3].tolist()
    [0.0, 0.0, 2.0, 1.0]
    """
    Q = _point(plane_point, "plane_point")
    N = _unit(normal, "normal", "a mirror plane needs a normal direction")
    return _affine(np.eye(3) - 2 * np.outer(N, N), Q)


@_refuses_overflow("s or center is")
def scaling(s, center=None) -> np.ndarray:
    """The 4x4 matrix of uniform scaling about ``center`` (Goldman §13.4).

    >>> scaling(2, center=[1, 0, 0])[3].tolist()
    [-1.0, 0.0, 0.0, 1.0]
    """
    s = as_float(s, "s")
    Q = np.zeros(3) if center is None else _point(center, "center")
    return _affine(s * np.eye(3), Q)


@_refuses_overflow("s or center is")
def nonuniform_scaling(s, direction, center=None) -> np.ndarray:
    """The 4x4 matrix of scaling by ``s`` along ``direction`` about ``center`` (Goldman §13.4):
    linear part ``I + (s - 1) wᵀw``.

    >>> nonuniform_scaling(3, [0, 0, 1])[:3, :3].tolist()
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 3.0]]
    """
    s = as_float(s, "s")
    w = _unit(direction, "direction", "a scaling needs a direction to stretch along")
    Q = np.zeros(3) if center is None else _point(center, "center")
    return _affine(np.eye(3) + (s - 1) * np.outer(w, w), Q)


@_refuses_overflow("plane_point is")
def orthogonal_projection(plane_point, normal) -> np.ndarray:
    """The 4x4 matrix of orthogonal projection onto a plane (Goldman §13.5): ``I - NᵀN`` and the
    translation row ``(Q·N) N``; singular (determinant 0).

    >>> orthogonal_projection([0, 0, 2], [0, 0, 1])[:, 2].tolist()
    [0.0, 0.0, 0.0, 2.0]
    """
    Q = _point(plane_point, "plane_point")
    N = _unit(normal, "normal", "a plane needs a normal direction")
    return _affine(np.eye(3) - np.outer(N, N), Q)


@_refuses_overflow("eye or plane_point is")
def perspective(eye, plane_point, normal) -> np.ndarray:
    """The 4x4 matrix of perspective projection from ``eye`` onto the plane (Goldman §13.6.2):

        | c I + Nᵀ E    Nᵀ    |        c = (Q - E)·N,  N the unit normal
        | -(Q·N) E    -(E·N)  |

    so ``[P 1] M = [c P + ((P - E)·N) E - c E ... , (P - E)·N]``, whose homogeneous divide is the
    point of :func:`project_perspective`.  Raises ValueError for an eye on the plane.

    >>> M = perspective([0, 0, 0], [0, 0, 1], [0, 0, 1])
    >>> apply([[2, 4, 2]], M).tolist()
    [[1.0, 2.0, 1.0]]
    """
    E = _point(eye, "eye")
    Q = _point(plane_point, "plane_point")
    N = _unit(normal, "normal", "a plane needs a normal direction")
    _check_perspective(E, Q, N)
    c = (Q - E) @ N
    M = np.zeros((4, 4))
    M[:3, :3] = c * np.eye(3) + np.outer(N, E)
    M[:3, 3] = N
    M[3, :3] = -(Q @ N) * E
    M[3, 3] = -(E @ N)
    return M


def compose(*matrices) -> np.ndarray:
    """The matrix of applying ``matrices`` in the order given: ``compose(A, B) == A @ B`` in the
    row convention (A first, then B).

    >>> compose(translation([1, 0, 0]), scaling(2))[3].tolist()
    [2.0, 0.0, 0.0, 1.0]
    """
    if not matrices:
        raise ValueError("matrices must hold at least one 4x4 matrix")
    out = np.eye(4)
    for k, m in enumerate(matrices):
        A = check_finite(as_float_array(m, f"matrices[{k}]"), f"matrices[{k}]")
        if A.shape != (4, 4):
            raise ValueError(f"matrices[{k}] must be a 4x4 matrix; got shape {A.shape}")
        with np.errstate(over="ignore", invalid="ignore"):
            out = out @ A
        finite_result(out, f"matrices (up to matrices[{k}]) are", why="too large in magnitude")
    return out


def affine_from_points(sources, images) -> np.ndarray:
    """The 4x4 matrix (row convention) of the affine map of 3-space that sends four affinely
    independent points ``sources[i]`` to ``images[i]`` (Goldman §13.1; the 2D case is §4.7): an
    affine map is fixed by the images of an affine frame, the point ``P0`` and the vectors
    ``P_i - P0``.  The block ``L`` solves ``(P_i - P0) L = Q_i - Q0`` (i = 1, 2, 3) and the
    translation row is ``t = Q0 - P0 L``, so that ``[P0 1] M = [Q0 1]``.

    sources, images: (4, 3).  Returns (4, 4) with last column (0, 0, 0, 1).  The images may be
    dependent (the map is then singular).  Raises ValueError when the sources are affinely
    dependent (coplanar): the frame then fixes no map.

    >>> affine_from_points([[1, 0, 0], [2, 0, 0], [1, 1, 0], [1, 0, 1]],
    ...                    [[0, 0, 0], [0, 1, 0], [-1, 0, 0], [0, 0, 1]]).tolist()
    [[0.0, 1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, -1.0, 0.0, 1.0]]
    """
    P = as_points(sources, "sources", dim=3)
    Q = as_points(images, "images", dim=3)
    if P.shape != (4, 3):
        raise ValueError(f"sources must hold four 3D points (shape (4, 3)); got shape {P.shape}")
    if Q.shape != (4, 3):
        raise ValueError(f"images must hold four 3D points (shape (4, 3)); got shape {Q.shape}")
    V, W = P[1:] - P[0], Q[1:] - Q[0]
    scale_ = max(1.0, float(np.abs(V).max()))
    if abs(np.linalg.det(V / scale_)) <= 1e-12:
        raise ValueError("sources must be affinely independent (not coplanar): the vectors P_i - P0 are dependent, "
                         "so they fix no linear part")
    with np.errstate(over="ignore", invalid="ignore"):
        L = np.linalg.solve(V, W)
        M = np.eye(4)
        M[:3, :3] = L
        M[3, :3] = Q[0] - P[0] @ L
    return finite_result(M, "sources or images are", why="too large in magnitude")


def rigid_inverse(M) -> np.ndarray:
    """The inverse of the 4x4 matrix of a rigid motion (Goldman §13.3): its block ``R`` is
    orthogonal, so the inverse has the block ``Rᵀ`` and the translation row ``-t Rᵀ``
    (``[P 1] M = [P R + t 1]`` is undone by ``P = (Q - t) Rᵀ``).  No linear solve is needed.

    M: (4, 4), affine (last column (0, 0, 0, 1)) with an orthogonal block (to 1e-9).
    Raises ValueError for any other matrix.

    >>> (rigid_inverse(rotation([0, 0, 1], 90, point=[1, 0, 0])).round(12) + 0.0).tolist()
    [[0.0, -1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [1.0, 1.0, 0.0, 1.0]]
    """
    A = check_finite(as_float_array(M, "M"), "M")
    if A.shape != (4, 4):
        raise ValueError(f"M must be a 4x4 matrix; got shape {A.shape}")
    if not np.allclose(A[:, 3], [0, 0, 0, 1], atol=1e-12):
        raise ValueError(f"M must be affine (last column (0, 0, 0, 1)); got last column {A[:, 3].tolist()}")
    R, t = A[:3, :3], A[3, :3]
    if not np.allclose(R @ R.T, np.eye(3), atol=1e-9):
        raise ValueError("M must be a rigid motion: its 3x3 block must be orthogonal (R Rᵀ = I)")
    out = np.eye(4)
    out[:3, :3] = R.T
    out[3, :3] = -t @ R.T
    return out


@_refuses_overflow("points or M is")
def apply(points, M) -> np.ndarray:
    """Apply a 4x4 matrix to points in the row convention, ``[P 1] @ M``, and divide by the
    homogeneous coordinate (Goldman §13.1).  Raises ValueError for a point sent to infinity
    (homogeneous coordinate 0).

    points: (..., 3).  M: (4, 4).  Returns (..., 3).

    >>> apply([[1, 1, 1], [0, 0, 0]], translation([0, 0, 5])).tolist()
    [[1.0, 1.0, 6.0], [0.0, 0.0, 5.0]]
    """
    P = _points(points)
    A = check_finite(as_float_array(M, "M"), "M")
    if A.shape != (4, 4):
        raise ValueError(f"M must be a 4x4 matrix; got shape {A.shape}")
    h = finite_result(P @ A[:3] + A[3], "points or M is", why="too large in magnitude")
    w = h[..., 3]
    scale_ = np.maximum(1.0, np.abs(h[..., :3]).max(axis=-1))
    if np.any(np.abs(w) <= 1e-12 * scale_):
        k = int(np.flatnonzero(np.abs(w).ravel() <= 1e-12 * scale_.ravel())[0])
        raise ValueError(f"points[{k}] is sent to infinity by M (its homogeneous coordinate is 0)")
    return h[..., :3] / w[..., None]


@_refuses_overflow("points or M is")
def homogeneous(points, M) -> np.ndarray:
    """The homogeneous coordinates ``[P 1] @ M`` of the images of points, before the divide
    (Goldman §13.1, §13.6): the last coordinate is the weight ``w`` that :func:`apply` divides by.

    points: (..., 3).  M: (4, 4).  Returns (..., 4).

    >>> homogeneous([[2, 4, 2]], perspective([0, 0, 0], [0, 0, 1], [0, 0, 1])).tolist()
    [[2.0, 4.0, 2.0, 2.0]]
    """
    P = _points(points)
    A = check_finite(as_float_array(M, "M"), "M")
    if A.shape != (4, 4):
        raise ValueError(f"M must be a 4x4 matrix; got shape {A.shape}")
    return P @ A[:3] + A[3]


@_refuses_overflow("vectors or M is")
def apply_to_vectors(vectors, M) -> np.ndarray:
    """Apply an affine 4x4 matrix to vectors, ``[v 0] @ M`` (Goldman §13.1): a vector has
    homogeneous coordinate 0, so the translation row does not act on it and only the upper-left
    3x3 block does.  Raises ValueError if M is not affine (its last column must be (0, 0, 0, 1):
    a projective map sends some vectors to points, so "the image of a vector" has no meaning).

    vectors: (..., 3).  M: (4, 4).  Returns (..., 3).

    >>> apply_to_vectors([[1, 0, 0]], translation([5, 5, 5])).tolist()
    [[1.0, 0.0, 0.0]]
    """
    v = as_points(vectors, "vectors", ndim=None, dim=3)
    A = check_finite(as_float_array(M, "M"), "M")
    if A.shape != (4, 4):
        raise ValueError(f"M must be a 4x4 matrix; got shape {A.shape}")
    if not np.allclose(A[:, 3], [0, 0, 0, 1], atol=1e-12):
        raise ValueError("M must be affine (last column (0, 0, 0, 1)) to act on vectors; got last column "
                         f"{A[:, 3].tolist()}")
    return v @ A[:3, :3]

"""Complex numbers and quaternions as rotations and conformal maps (Goldman Chapter 15).

Quaternions are numpy arrays ``(..., 4)`` in the order ``(w, x, y, z)``: ``w`` the scalar part and
``(x, y, z)`` the vector part; every function vectorises over leading axes.  Angles are in degrees.
Matrices follow the book's convention used throughout the library: points are row vectors and a
transformation acts on the right, ``Q = P @ M``; 4x4 matrices hold the translation in the last
row.  So ``to_matrix(q)`` is the *transpose* of the column-convention matrix found in many texts,
and ``v @ to_matrix(q)[:3, :3] == rotate(q, v)``.

>>> q = from_axis_angle([0, 0, 1], 90)
>>> np.round(rotate(q, [1, 0, 0]), 12) + 0.0
array([0., 1., 0.])
"""

from __future__ import annotations

import numpy as np

from goldman_lib.validation import as_float, as_float_array, as_parameter, as_points, check_finite, finite_result
from goldman_lib.kernels.frames import norm as _length

__all__ = ["complex_rotation", "complex_polar", "complex_multiply", "multiply", "conjugate", "norm", "inverse", "normalize",
           "from_axis_angle", "to_axis_angle", "rotate", "conformal_map", "to_matrix", "from_matrix", "slerp",
           "key_frames", "matrix_lerp", "matrix_key_frames", "matrix_distortion", "pure", "mirror",
           "rotation_from_mirrors", "nlerp", "stereographic", "inverse_stereographic"]


def _quaternions(q, name: str) -> np.ndarray:
    arr = check_finite(as_float_array(q, name), name)
    if arr.ndim == 0 or arr.shape[-1] != 4:
        raise ValueError(f"{name} must hold quaternions (w, x, y, z) in its last axis of length 4; got shape {arr.shape}")
    return arr


def _join(w: np.ndarray, vec: np.ndarray) -> np.ndarray:
    """Scalar parts (..., 1) and vector parts (..., 3) into quaternions, broadcasting leading axes."""
    lead = np.broadcast_shapes(w.shape[:-1], vec.shape[:-1])
    return np.concatenate([np.broadcast_to(w, lead + (1,)), np.broadcast_to(vec, lead + (3,))], axis=-1)


def _scale_rows(q: np.ndarray, c: np.ndarray) -> np.ndarray:
    """``q * c[..., None]``, computed with the long axis innermost (a broadcast over a last axis of
    length 4 runs numpy's inner loop four elements at a time, three times slower)."""
    return np.ascontiguousarray(np.moveaxis(np.moveaxis(q, -1, 0) * c, 0, -1))


def _magnitude(q: np.ndarray) -> np.ndarray:
    """``|q|``, right at every magnitude (a quaternion of norm 1e160 has norm 1e160, not inf)."""
    with np.errstate(over="ignore", under="ignore"):
        n = np.sqrt(np.einsum("...i,...i->...", q, q))
    if not np.all(np.isfinite(n) & (n > 1e-150)):
        n = _length(q)                   # |q|^2 overflowed or underflowed: scale before squaring
    return n


def _nonzero(q: np.ndarray, name: str) -> np.ndarray:
    n = _magnitude(q)
    if np.any(n == 0):
        raise ValueError(f"{name} must be nonzero: the zero quaternion has no inverse and is no rotation")
    return n


# -- §15.2: complex numbers as rotations and scalings of the plane ---------------------------------

def complex_rotation(angle, scale=1.0) -> complex:
    """The complex number ``scale * e^{i angle}`` (Goldman §15.2): multiplying a point ``x + iy``
    by it rotates the point about the origin by ``angle`` degrees and scales it by ``scale``.

    >>> z = complex_rotation(90)
    >>> complex(np.round(z * (1 + 0j), 12))
    1j
    """
    values = []
    for value, name in ((angle, "angle"), (scale, "scale")):
        arr = as_parameter(value, name)
        if arr.ndim != 0:
            raise ValueError(f"{name} must be one number; got shape {arr.shape}")
        values.append(float(arr))
    a, s = np.radians(values[0]), values[1]
    return complex(s * np.cos(a), s * np.sin(a))


def complex_polar(z) -> tuple[float, float]:
    """The scale ``|z|`` and the angle ``arg z`` in degrees, in (-180, 180], of the complex number
    ``z``: multiplying by ``z`` scales the plane by ``|z|`` and rotates it by ``arg z`` (Goldman
    §15.2; the inverse of :func:`complex_rotation`).  ``z = 0`` has scale 0 and, by convention,
    angle 0 (it collapses the plane to the origin and rotates nothing).

    >>> [round(v, 9) for v in complex_polar(complex_rotation(135, 2.0))]
    [2.0, 135.0]
    >>> complex_polar(-1 + 1j)[1]
    135.0
    """
    if not isinstance(z, (int, float, complex, np.number)) or isinstance(z, bool):
        raise TypeError(f"z must be a complex number; got {z!r}")
    z = complex(z)
    if not (np.isfinite(z.real) and np.isfinite(z.imag)):
        raise ValueError(f"z must be finite; got {z}")
    return float(abs(z)), float(np.degrees(np.arctan2(z.imag, z.real))) + 0.0


def complex_multiply(points, z) -> np.ndarray:
    """Apply the complex number ``z`` to 2D points ``(n, 2)`` (rows ``(x, y)`` as ``x + iy``): the
    conformal map of the plane that rotates by ``arg z`` and scales by ``|z|`` (Goldman §15.2).

    >>> complex_multiply([[1, 0], [0, 2]], 2j).tolist()
    [[0.0, 2.0], [-4.0, 0.0]]
    """
    pts = as_points(points, "points", ndim=None, dim=2)
    if not isinstance(z, (int, float, complex, np.number)) or isinstance(z, bool):
        raise TypeError(f"z must be a complex number; got {z!r}")
    z = complex(z)
    if not (np.isfinite(z.real) and np.isfinite(z.imag)):
        raise ValueError(f"z must be finite; got {z}")
    with np.errstate(over="ignore", invalid="ignore"):
        w = (pts[..., 0] + 1j * pts[..., 1]) * z
    out = np.stack([w.real, w.imag], axis=-1)
    if not np.all(np.isfinite(out)):
        raise ValueError(f"z is too large in magnitude for these points: the image overflows float64 (|z| = {abs(z):.3g})")
    return out


# -- §15.3.1: the quaternion algebra ---------------------------------------------------------------

def multiply(p, q) -> np.ndarray:
    """The quaternion product ``p q`` (Goldman §15.3.1), not commutative:
    ``(a, u)(b, v) = (ab - u·v, a v + b u + u × v)``.

    >>> multiply([0, 1, 0, 0], [0, 0, 1, 0]).tolist()   # i j = k
    [0.0, 0.0, 0.0, 1.0]
    >>> multiply([0, 0, 1, 0], [0, 1, 0, 0]).tolist()   # j i = -k
    [0.0, 0.0, 0.0, -1.0]
    """
    p = _quaternions(p, "p")
    q = _quaternions(q, "q")
    a, u = p[..., :1], p[..., 1:]
    b, v = q[..., :1], q[..., 1:]
    with np.errstate(over="ignore", invalid="ignore"):
        w = a * b - np.sum(u * v, axis=-1, keepdims=True)
        vec = a * v + b * u + np.cross(u, v)
        out = _join(w, vec)
    return finite_result(out, "p and q", why="are too large in magnitude")


def conjugate(q) -> np.ndarray:
    """The conjugate ``q* = (w, -x, -y, -z)`` (Goldman §15.3.1).

    >>> conjugate([1, 2, 3, 4]).tolist()
    [1.0, -2.0, -3.0, -4.0]
    """
    q = _quaternions(q, "q")
    return q * np.array([1.0, -1.0, -1.0, -1.0])


def norm(q) -> np.ndarray:
    """The norm ``|q| = sqrt(q q*)`` (Goldman §15.3.1).

    >>> float(norm([1, 2, 2, 4]))
    5.0
    """
    q = _quaternions(q, "q")
    return finite_result(_magnitude(q), "q")


def inverse(q) -> np.ndarray:
    """The inverse ``q^{-1} = q* / |q|^2`` (Goldman §15.3.1).  Raises ValueError for zero.

    >>> inverse([0, 0, 2, 0]).tolist()
    [0.0, -0.0, -0.5, -0.0]
    """
    q = _quaternions(q, "q")
    n = _nonzero(q, "q")
    with np.errstate(over="ignore", under="ignore"):
        n2 = n * n
    if np.all(np.isfinite(n2) & (n2 > 1e-300)):
        return conjugate(q) / n2[..., None]
    # |q|^2 overflows or underflows: divide by |q| twice; refuse an inverse too large to represent
    with np.errstate(over="ignore"):
        return finite_result(conjugate(q) / n[..., None] / n[..., None], "q", why="is too small in magnitude")


def normalize(q) -> np.ndarray:
    """``q / |q|``, a unit quaternion.  Raises ValueError for zero.

    >>> normalize([0, 0, 0, 3]).tolist()
    [0.0, 0.0, 0.0, 1.0]
    """
    q = _quaternions(q, "q")
    n = _nonzero(q, "q")
    if np.all(n > 1e-300):
        return _scale_rows(q, 1.0 / n)
    return q / n[..., None]              # 1/|q| would overflow: divide


# -- §15.3.2: rotations and conformal maps -----------------------------------------------------

def from_axis_angle(axis, angle) -> np.ndarray:
    """The unit quaternion ``(cos(θ/2), sin(θ/2) u)`` that rotates by ``angle`` degrees about the
    unit vector ``u`` along ``axis`` (counterclockwise looking down the axis; Goldman §15.3.2).

    axis: (3,) or (..., 3), nonzero.  angle: degrees, scalar or array broadcasting with the axes.

    >>> np.round(from_axis_angle([0, 0, 2], 180), 12).tolist()
    [0.0, 0.0, 0.0, 1.0]
    """
    ax = check_finite(as_float_array(axis, "axis"), "axis")
    if ax.ndim == 0 or ax.shape[-1] != 3:
        raise ValueError(f"axis must be a 3D vector (last axis of length 3); got shape {ax.shape}")
    length = _length(ax, keepdims=True)
    if np.any(length == 0):
        raise ValueError("axis must be nonzero: a rotation needs a direction to turn about")
    half = np.radians(as_parameter(angle, "angle"))[..., None] / 2
    u = ax / length
    w = np.cos(half)
    return _join(w, np.sin(half) * u)


def to_axis_angle(q) -> tuple[np.ndarray, np.ndarray]:
    """The unit axis and the angle in degrees, in [0, 180], of the rotation of ``q`` (Goldman
    §15.3.2).  For the identity rotation the axis is (1, 0, 0) by convention.

    >>> axis, angle = to_axis_angle(from_axis_angle([0, 1, 0], 270))
    >>> (np.round(axis, 12) + 0.0).tolist(), round(float(angle), 9)
    ([0.0, -1.0, 0.0], 90.0)
    """
    q = normalize(q)
    q = np.where(q[..., :1] < 0, -q, q)
    vec = q[..., 1:]
    s = np.linalg.norm(vec, axis=-1)
    angle = np.degrees(2 * np.arctan2(s, q[..., 0]))
    safe = np.where(s[..., None] > 0, vec / np.where(s > 0, s, 1)[..., None], np.array([1.0, 0.0, 0.0]))
    return safe, angle


def rotate(q, v) -> np.ndarray:
    """Rotate vectors ``v`` by the unit quaternion ``q``: the vector part of ``q v q*`` (Goldman
    §15.3.2).  ``q`` is normalised first, so any nonzero ``q`` gives a pure rotation (use
    :func:`conformal_map` for the rotation and scaling of a non-unit ``q``).

    q: (..., 4).  v: (..., 3).  Returns the broadcast shape (..., 3).

    >>> (np.round(rotate(from_axis_angle([1, 1, 1], 120), [1, 0, 0]), 12) + 0.0).tolist()
    [0.0, 1.0, 0.0]
    """
    q = normalize(q)
    vec = check_finite(as_float_array(v, "v"), "v")
    if vec.ndim == 0 or vec.shape[-1] != 3:
        raise ValueError(f"v must hold 3D vectors (last axis of length 3); got shape {vec.shape}")
    w, u = q[..., :1], q[..., 1:]
    # q v q* = v + 2w (u × v) + 2 u × (u × v) for a unit q
    t = 2 * np.cross(u, vec)
    return vec + w * t + np.cross(u, t)


def conformal_map(q, v) -> np.ndarray:
    """``q v q*`` for any nonzero quaternion: the rotation of ``q / |q|`` followed by scaling by
    ``|q|^2`` -- the conformal maps of 3-space fixing the origin (Goldman §15.3.2).

    >>> conformal_map([0, 0, 0, 2], [1, 0, 0]).tolist()   # 180° about z, scaled by 4
    [-4.0, 0.0, 0.0]
    """
    q = _quaternions(q, "q")
    n = _nonzero(q, "q")
    return finite_result(rotate(q, v) * (n * n)[..., None], "q", why="(or v) is too large in magnitude")


# -- §15.3.6: conversion formulas ----------------------------------------------------------------------

def to_matrix(q) -> np.ndarray:
    """The 4x4 matrix of the rotation of ``q`` in the book's row convention ``P' = P @ M``
    (rotation in the upper-left 3x3 block, no translation; Goldman §15.3.6).

    >>> M = to_matrix(from_axis_angle([0, 0, 1], 90))
    >>> (np.round(np.array([1, 0, 0, 1]) @ M, 12) + 0.0).tolist()
    [0.0, 1.0, 0.0, 1.0]
    """
    w, x, y, z = np.moveaxis(normalize(q), -1, 0)
    shape = w.shape
    M = np.zeros(shape + (4, 4))
    # column-convention R, stored transposed: M[i, j] = R[j, i]
    M[..., 0, 0] = 1 - 2 * (y * y + z * z)
    M[..., 1, 0] = 2 * (x * y - w * z)
    M[..., 2, 0] = 2 * (x * z + w * y)
    M[..., 0, 1] = 2 * (x * y + w * z)
    M[..., 1, 1] = 1 - 2 * (x * x + z * z)
    M[..., 2, 1] = 2 * (y * z - w * x)
    M[..., 0, 2] = 2 * (x * z - w * y)
    M[..., 1, 2] = 2 * (y * z + w * x)
    M[..., 2, 2] = 1 - 2 * (x * x + y * y)
    M[..., 3, 3] = 1.0
    return M


def from_matrix(M, tol: float = 1e-6) -> np.ndarray:
    """The unit quaternion (with ``w >= 0``) of a rotation matrix in the row convention, 3x3 or 4x4
    (Goldman §15.3.6; Shepperd's stable choice of the largest of w, x, y, z to divide by).

    M: (..., 3, 3) or (..., 4, 4).  Raises ValueError if the 3x3 block is not a rotation (not
    orthogonal with determinant 1 to within ``tol``) or a 4x4 matrix has a translation.

    >>> np.round(from_matrix(to_matrix([0.5, 0.5, 0.5, 0.5])), 12).tolist()
    [0.5, 0.5, 0.5, 0.5]
    """
    A = check_finite(as_float_array(M, "M"), "M")
    if A.ndim < 2 or A.shape[-2:] not in ((3, 3), (4, 4)):
        raise ValueError(f"M must be a 3x3 or 4x4 matrix (or a stack of them); got shape {A.shape}")
    tol = as_float(tol, "tol", positive=True)
    if A.shape[-1] == 4:
        if np.any(np.abs(A[..., 3, :3]) > tol) or np.any(np.abs(A[..., :3, 3]) > tol) or np.any(np.abs(A[..., 3, 3] - 1) > tol):
            raise ValueError("M must be a pure rotation: its last row and column must be (0, 0, 0, 1)")
        A = A[..., :3, :3]
    if np.any(np.abs(A @ np.swapaxes(A, -1, -2) - np.eye(3)) > tol) or np.any(np.abs(np.linalg.det(A) - 1) > tol):
        raise ValueError("M must be a rotation matrix: orthogonal with determinant +1")
    R = np.swapaxes(A, -1, -2)  # column convention
    tr = R[..., 0, 0] + R[..., 1, 1] + R[..., 2, 2]
    cands = np.stack([tr, R[..., 0, 0], R[..., 1, 1], R[..., 2, 2]], axis=-1)
    k = np.argmax(cands, axis=-1)
    q = np.empty(A.shape[:-2] + (4,))
    # 4 w^2 = 1 + tr, 4 x^2 = 1 + 2 R00 - tr, ...
    big = np.sqrt(np.maximum(1 + 2 * np.take_along_axis(cands, k[..., None], -1)[..., 0] - tr, 0.0)) / 2
    s = 1 / (4 * big)
    r = {(i, j): R[..., i, j] for i in range(3) for j in range(3)}
    options = [
        np.stack([big, (r[2, 1] - r[1, 2]) * s, (r[0, 2] - r[2, 0]) * s, (r[1, 0] - r[0, 1]) * s], -1),
        np.stack([(r[2, 1] - r[1, 2]) * s, big, (r[0, 1] + r[1, 0]) * s, (r[0, 2] + r[2, 0]) * s], -1),
        np.stack([(r[0, 2] - r[2, 0]) * s, (r[0, 1] + r[1, 0]) * s, big, (r[1, 2] + r[2, 1]) * s], -1),
        np.stack([(r[1, 0] - r[0, 1]) * s, (r[0, 2] + r[2, 0]) * s, (r[1, 2] + r[2, 1]) * s, big], -1),
    ]
    q = np.choose(k[..., None], options)
    q = np.where(q[..., :1] < 0, -q, q)
    return q / _length(q, keepdims=True)


# -- §15.3.4-15.3.5: interpolation without distortion; key frames -------------------------------------

def slerp(q0, q1, t) -> np.ndarray:
    """Spherical linear interpolation of unit quaternions along the shorter arc (Goldman §15.3.4):
    ``sin((1-t)θ)/sin θ q0 + sin(tθ)/sin θ q1`` with ``cos θ = |q0·q1|`` (``q1`` is negated when
    ``q0·q1 < 0``, since ``q`` and ``-q`` are the same rotation).  Inputs are normalised.

    q0, q1: (..., 4).  t: scalar or array; the result has the broadcast shape of ``q0[..., 0]``,
    ``q1[..., 0]`` and ``t``, plus (4,).

    >>> np.round(slerp([1, 0, 0, 0], from_axis_angle([0, 0, 1], 90), 0.5), 6).tolist()
    [0.92388, 0.0, 0.0, 0.382683]
    """
    a = _quaternions(q0, "q0")
    b = _quaternions(q1, "q1")
    tt = as_parameter(t, "t")
    na, nb = _nonzero(a, "q0"), _nonzero(b, "q1")      # normalised through the weights below
    if np.any((na > 1e150) | (na < 1e-150)):             # a·b or na·nb would overflow or underflow:
        a = a / na[..., None]                            # normalise first (rare)
        na = _nonzero(a, "q0")
    if np.any((nb > 1e150) | (nb < 1e-150)):
        b = b / nb[..., None]
        nb = _nonzero(b, "q1")
    lead = np.broadcast_shapes(a.shape[:-1], b.shape[:-1], tt.shape)
    a, b, tt = np.broadcast_to(a, lead + (4,)), np.broadcast_to(b, lead + (4,)), np.broadcast_to(tt, lead)
    na, nb = np.broadcast_to(na, lead), np.broadcast_to(nb, lead)
    d = np.einsum("...i,...i->...", a, b) / (na * nb)
    sign = np.where(d < 0, -1.0, 1.0)
    d = np.minimum(np.abs(d), 1.0)
    theta = np.arccos(d)
    sin = np.sqrt(1.0 - d * d)            # sin θ for θ in [0, π/2]
    small = sin < 1e-9                    # (nearly) equal rotations: linear interpolation is exact enough
    inv = 1.0 / np.where(small, 1.0, sin)
    wa = np.where(small, 1 - tt, np.sin((1 - tt) * theta) * inv) / na
    wb = np.where(small, tt, np.sin(tt * theta) * inv) * sign / nb
    out = _scale_rows(a, wa)
    out += _scale_rows(b, wb)
    if np.any(small):
        out = _scale_rows(out, 1.0 / np.sqrt(np.einsum("...i,...i->...", out, out)))
    return out


def key_frames(orientations, times, t) -> np.ndarray:
    """Key-frame animation (Goldman §15.3.5): the orientation at time(s) ``t`` interpolated by slerp
    between the key orientations (unit quaternions) at the key ``times`` (strictly increasing).
    Times outside ``[times[0], times[-1]]`` are clamped to the first/last key.

    >>> keys = [[1, 0, 0, 0], from_axis_angle([0, 0, 1], 90), from_axis_angle([0, 0, 1], 180)]
    >>> axis, angle = to_axis_angle(key_frames(keys, [0, 1, 2], 1.5))
    >>> round(float(angle), 9)
    135.0
    """
    keys = _quaternions(orientations, "orientations")
    if keys.ndim != 2 or len(keys) < 2:
        raise ValueError(f"orientations must be at least two quaternions (k, 4); got shape {keys.shape}")
    ts = check_finite(as_float_array(times, "times"), "times")
    if ts.shape != (len(keys),):
        raise ValueError(f"times must have one entry per orientation ({len(keys)}); got shape {ts.shape}")
    if np.any(np.diff(ts) <= 0):
        i = int(np.flatnonzero(np.diff(ts) <= 0)[0])
        raise ValueError(f"times must be strictly increasing; times[{i + 1}]={ts[i + 1]} <= times[{i}]={ts[i]}")
    tt = np.clip(as_parameter(t, "t"), ts[0], ts[-1])
    seg = np.clip(np.searchsorted(ts, tt, side="right") - 1, 0, len(ts) - 2)
    local = (tt - ts[seg]) / (ts[seg + 1] - ts[seg])
    return slerp(keys[seg], keys[seg + 1], local)


def matrix_lerp(M0, M1, t) -> np.ndarray:
    """Linear interpolation ``(1-t) M0 + t M1`` of two matrices: what §15.3.4 warns against for
    rotations, since the result is in general not a rotation (it shears and shrinks).

    >>> M = matrix_lerp(np.eye(3), to_matrix(from_axis_angle([0, 0, 1], 180))[:3, :3], 0.5)
    >>> np.round(M, 12).tolist()[2]
    [0.0, 0.0, 1.0]
    """
    A = check_finite(as_float_array(M0, "M0"), "M0")
    B = check_finite(as_float_array(M1, "M1"), "M1")
    if A.shape != B.shape or A.ndim < 2:
        raise ValueError(f"M0 and M1 must be matrices of the same shape; got {A.shape} and {B.shape}")
    tt = as_parameter(t, "t")[..., None, None]
    with np.errstate(over="ignore", invalid="ignore"):
        out = (1 - tt) * A + tt * B
    if not np.all(np.isfinite(out)):
        raise ValueError("t is too large in magnitude: the blend (1-t) M0 + t M1 overflows float64")
    return out


def matrix_key_frames(orientations, times, t) -> np.ndarray:
    """The counterpart of :func:`key_frames` that §15.3.4 warns against: the 4x4 matrices (row
    convention) of the key orientations interpolated *linearly* between key times,
    ``(1-s) M_k + s M_{k+1}``.  Between keys the result is in general not a rotation (measure it
    with :func:`matrix_distortion`).  Times outside ``[times[0], times[-1]]`` are clamped.

    orientations: (k, 4) quaternions, k >= 2.  times: (k,) strictly increasing.  t: scalar or
    array; returns ``t.shape + (4, 4)``.

    >>> keys = [[1, 0, 0, 0], from_axis_angle([0, 0, 1], 180)]
    >>> M = matrix_key_frames(keys, [0, 1], 0.5)
    >>> (np.round(M[:3, :3], 12) + 0.0).tolist()     # the xy-plane collapses to the origin
    [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    """
    keys = _quaternions(orientations, "orientations")
    if keys.ndim != 2 or len(keys) < 2:
        raise ValueError(f"orientations must be at least two quaternions (k, 4); got shape {keys.shape}")
    _nonzero(keys, "orientations")
    ts = check_finite(as_float_array(times, "times"), "times")
    if ts.shape != (len(keys),):
        raise ValueError(f"times must have one entry per orientation ({len(keys)}); got shape {ts.shape}")
    if np.any(np.diff(ts) <= 0):
        i = int(np.flatnonzero(np.diff(ts) <= 0)[0])
        raise ValueError(f"times must be strictly increasing; times[{i + 1}]={ts[i + 1]} <= times[{i}]={ts[i]}")
    mats = to_matrix(keys)
    tt = np.clip(as_parameter(t, "t"), ts[0], ts[-1])
    seg = np.clip(np.searchsorted(ts, tt, side="right") - 1, 0, len(ts) - 2)
    local = (tt - ts[seg]) / (ts[seg + 1] - ts[seg])
    return matrix_lerp(mats[seg], mats[seg + 1], local)


def matrix_distortion(M) -> np.ndarray:
    """How far the 3x3 block of ``M`` is from a rotation: ``max |σ_i - 1|`` over its singular values
    (0 for a rotation; a linear interpolation of rotations shrinks some directions; Goldman §15.3.4).

    >>> float(matrix_distortion(np.diag([1.0, 1.0, 0.5])))
    0.5
    """
    A = check_finite(as_float_array(M, "M"), "M")
    if A.ndim < 2 or A.shape[-2:] not in ((3, 3), (4, 4)):
        raise ValueError(f"M must be a 3x3 or 4x4 matrix (or a stack of them); got shape {A.shape}")
    sv = np.linalg.svd(A[..., :3, :3], compute_uv=False)
    return np.max(np.abs(sv - 1), axis=-1)


# -- Chapter 15's framing: why a sandwich, mirrors, the double cover, slerp drawn on S³ ------------------

def pure(v) -> np.ndarray:
    """The pure quaternion ``(0, v)`` of 3D vectors ``v``: a vector as a mass-point of mass 0, the
    way the sandwich ``q v q*`` reads it (Goldman §15.3.2).

    v: (..., 3).  Returns (..., 4).

    >>> pure([1, 2, 3]).tolist()
    [0.0, 1.0, 2.0, 3.0]
    """
    vec = check_finite(as_float_array(v, "v"), "v")
    if vec.ndim == 0 or vec.shape[-1] != 3:
        raise ValueError(f"v must hold 3D vectors (last axis of length 3); got shape {vec.shape}")
    return _join(np.zeros(vec.shape[:-1] + (1,)), vec)


def mirror(normal, v) -> np.ndarray:
    """The mirror image of vectors ``v`` in the plane through the origin perpendicular to ``normal``,
    computed as the sandwich ``N v N`` of the unit pure quaternion ``N = (0, normal/|normal|)``
    (Goldman §15.3.2): ``N v N = v - 2 (v·N) N``.  For a pure unit ``N``, ``N* = -N``, so
    ``-N v N*`` is the same map.

    normal: (3,) nonzero.  v: (..., 3).  Returns (..., 3).

    >>> mirror([0, 0, 2], [1, 2, 3]).tolist()
    [1.0, 2.0, -3.0]
    """
    n = check_finite(as_float_array(normal, "normal"), "normal")
    if n.shape != (3,):
        raise ValueError(f"normal must be one 3D vector; got shape {n.shape}")
    length = float(np.linalg.norm(n))
    if length == 0:
        raise ValueError("normal must be nonzero: a mirror plane needs a normal direction")
    N = pure(n / length)
    return multiply(multiply(N, pure(v)), N)[..., 1:]


def rotation_from_mirrors(normal1, normal2) -> np.ndarray:
    """The unit quaternion ``N2 N1`` of two mirrors, in the planes through the origin perpendicular to
    ``normal1`` and then to ``normal2`` (Goldman §15.3.2): ``N2 (N1 v N1) N2 = (N2 N1) v (N2 N1)*``,
    the rotation about ``normal1 × normal2`` by twice the angle from ``normal1`` to ``normal2``.

    >>> axis, angle = to_axis_angle(rotation_from_mirrors([1, 0, 0], [1, 1, 0]))
    >>> (np.round(axis, 12) + 0.0).tolist(), round(float(angle), 9)
    ([0.0, 0.0, 1.0], 90.0)
    """
    n1 = check_finite(as_float_array(normal1, "normal1"), "normal1")
    n2 = check_finite(as_float_array(normal2, "normal2"), "normal2")
    for name, n in (("normal1", n1), ("normal2", n2)):
        if n.shape != (3,) or not np.any(n):
            raise ValueError(f"{name} must be one nonzero 3D vector; got {n.tolist()}")
    return multiply(pure(n2 / np.linalg.norm(n2)), pure(n1 / np.linalg.norm(n1)))


def nlerp(q0, q1, t) -> np.ndarray:
    """Normalised linear interpolation of unit quaternions along the shorter side, ``((1-t) q0 + t q1)
    / |(1-t) q0 + t q1|`` with ``q1`` negated when ``q0·q1 < 0``: the chord of 4-space pushed back
    onto the sphere.  It runs along the same great arc as :func:`slerp` but not at constant speed (our
    formulation, the foil to slerp in §15.3.4).  On the shorter side the chord never passes through
    0 (``q1 = -q0`` is negated to ``q0``).

    >>> np.round(nlerp([1, 0, 0, 0], from_axis_angle([0, 0, 1], 90), 0.5), 6).tolist()
    [0.92388, 0.0, 0.0, 0.382683]
    """
    a = _quaternions(q0, "q0")
    b = _quaternions(q1, "q1")
    a = a / _nonzero(a, "q0")[..., None]
    b = b / _nonzero(b, "q1")[..., None]
    tt = as_parameter(t, "t")[..., None]
    d = np.sum(a * b, axis=-1, keepdims=True)
    b = np.where(d < 0, -b, b)
    with np.errstate(over="ignore", invalid="ignore"):
        chord = (1 - tt) * a + tt * b
    chord = finite_result(chord, "t", why="is too large in magnitude")
    return chord / _nonzero(chord, "t")[..., None]


def stereographic(q) -> np.ndarray:
    """Stereographic projection of unit quaternions from the pole ``-1 = (-1, 0, 0, 0)`` to 3-space:
    ``(w, x, y, z) -> (x, y, z) / (1 + w)`` (our formulation, to draw §15.3.4's slerp on S³).  The
    identity ``1`` goes to the origin, the rotation by θ about the unit u, ``(cos(θ/2), sin(θ/2) u)``,
    to ``tan(θ/4) u``; great circles go to circles or lines, and angles are kept (a conformal map).
    ``q`` is normalised first.  Raises ValueError for ``q`` at (or within 1e-9 of) the pole, which
    goes to infinity: pass ``-q``, the same rotation, instead.

    q: (..., 4).  Returns (..., 3).

    >>> (np.round(stereographic(from_axis_angle([0, 0, 1], 180)), 12) + 0.0).tolist()
    [0.0, 0.0, 1.0]
    """
    u = normalize(q)
    if np.any(1 + u[..., 0] < 1e-9):
        raise ValueError("q must not be the pole -1 = (-1, 0, 0, 0) of the projection (it goes to infinity); "
                         "-q is the same rotation and projects to the origin's side")
    return u[..., 1:] / (1 + u[..., :1])


def inverse_stereographic(p) -> np.ndarray:
    """The unit quaternion that :func:`stereographic` sends to the point ``p`` of 3-space:
    ``((1 - |p|^2) / (1 + |p|^2), 2 p / (1 + |p|^2))`` (our formulation).

    p: (..., 3).  Returns (..., 4).

    >>> inverse_stereographic([0, 0, 1]).tolist()
    [0.0, 0.0, 0.0, 1.0]
    """
    P = check_finite(as_float_array(p, "p"), "p")
    if P.ndim == 0 or P.shape[-1] != 3:
        raise ValueError(f"p must hold 3D points (last axis of length 3); got shape {P.shape}")
    s = np.sum(P * P, axis=-1, keepdims=True)
    with np.errstate(over="ignore", invalid="ignore"):
        out = _join((1 - s) / (1 + s), 2 * P / (1 + s))
    return finite_result(out, "p", why="is too far out (its preimage is the pole)")

"""Vectors, frames and polygon normals (Goldman §3, §11.4, §16.5, §21.1), unchecked.

:func:`norm` (lengths, right at every finite magnitude), :func:`unit_rows` (rows scaled to length
1, zero rows kept), :func:`row_dots` (row-by-row dot products) and :func:`newell` (Newell's normal
of a stack of polygons, unnormalised; :func:`unit_rows` of it is the unit normal), :func:`slerp` (spherical linear interpolation, §11.6,
per pixel in Phong shading, §21.4.4) and :func:`frame` (orthonormal frames completing unit vectors:
the local axes of ``simple_surfaces``' planes, discs, cylinders and cones, §19, and of ``radiosity``'s
hemi-cubes, §23.3).  Nothing here checks its input: callers pass finite float arrays.
"""

from __future__ import annotations

import numpy as np

__all__ = ["norm", "unit_rows", "row_dots", "newell", "slerp", "frame"]


def norm(v: np.ndarray, axis: int = -1, keepdims: bool = False) -> np.ndarray:
    """The Euclidean length of ``v`` along ``axis``, right at every finite magnitude (Goldman §3): the
    plain ``sqrt(v · v)`` (bit for bit :func:`numpy.linalg.norm`) where ``v · v`` is a normal float,
    and ``m sqrt((v/m) · (v/m))`` with ``m = max |v_i|`` where it overflows or underflows (entries
    over about 1e154 or under 1e-154), so a vector of length 1e300 has length 1e300, not inf.

    >>> float(norm(np.array([3 * 2.0 ** 900, 4 * 2.0 ** 900]))) == 5 * 2.0 ** 900
    True
    >>> float(norm(np.array([3e-200, 4e-200])))
    5e-200
    """
    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        out = np.linalg.norm(v, axis=axis, keepdims=keepdims)
        tiny = np.finfo(float).tiny ** 0.5
        redo = ~np.isfinite(out) | (out < tiny)
        if not np.any(redo & np.any(v != 0, axis=axis, keepdims=keepdims)):
            return out
        m = np.max(np.abs(v), axis=axis, keepdims=True)
        safe = np.ldexp(1.0, np.frexp(np.where(m > 0, m, 1.0))[1] - 1)  # a power of two <= m: exact scaling
        scaled = np.linalg.norm(v / safe, axis=axis, keepdims=True) * safe
        if not keepdims:
            scaled = np.squeeze(scaled, axis=axis)
        return np.where(redo, scaled, out)


def row_dots(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Dot products of corresponding rows (last axis) of a and b: ``(...)``.

    >>> row_dots(np.array([[1.0, 2.0, 3.0]]), np.array([[4.0, 5.0, 6.0]])).tolist()
    [32.0]
    """
    return np.einsum("...i,...i->...", a, b)


def unit_rows(v: np.ndarray) -> np.ndarray:
    """Rows of ``v`` (last axis) scaled to length 1; zero rows stay zero (Goldman §16.5, the unit
    vectors of the lighting model).  ``sqrt(v · v)`` where it is a normal float, :func:`norm` where
    ``|v|^2`` overflows or underflows.

    >>> unit_rows(np.array([[3.0, 0.0, 4.0], [0.0, 0.0, 0.0]])).tolist()
    [[0.6, 0.0, 0.8], [0.0, 0.0, 0.0]]
    """
    with np.errstate(over="ignore", under="ignore"):
        length = np.sqrt(np.einsum("...i,...i->...", v, v))[..., None]
    if not np.all(np.isfinite(length) & (length > 1e-150)) and np.all(np.isfinite(v)):
        length = norm(v, keepdims=True)     # |v|^2 overflowed or underflowed: scale before squaring
    return np.divide(v, length, out=np.zeros_like(v), where=length > 0)


def newell(P: np.ndarray) -> np.ndarray:
    """Newell's normal of polygons ``(..., k, 3)`` (Goldman §11.4, §21.1), unnormalised: ``(...,
    3)``, ``N_x = sum (y_i - y_j)(z_i + z_j)`` and cyclically with ``j = i + 1``.  It equals
    ``sum P_i x P_{i+1}`` (twice the area vector of a planar polygon) but is written with
    differences, so it does not lose digits when the polygon is far from the origin.

    >>> newell(np.array([[0.0, 0, 0], [2, 0, 0], [2, 3, 0], [0, 3, 0]])).tolist()
    [0.0, 0.0, 12.0]
    """
    Q = np.roll(P, -1, axis=-2)
    x, y, z = P[..., 0], P[..., 1], P[..., 2]
    qx, qy, qz = Q[..., 0], Q[..., 1], Q[..., 2]
    return np.stack([((y - qy) * (z + qz)).sum(-1), ((z - qz) * (x + qx)).sum(-1), ((x - qx) * (y + qy)).sum(-1)],
                    axis=-1)


def unit_newell(P: np.ndarray) -> np.ndarray:
    """Newell's unit normal of one polygon ``(k, 3)`` (Goldman §21.1, §20.3): :func:`newell` divided
    by its length (``numpy.linalg.norm``, or :func:`norm` where the squares overflow or
    underflow), zeros for a polygon without area; NaN where :func:`newell` itself overflowed.  Callers:
    ``shading.unit_newell_normal`` (checked) and ``solid_modeling``'s planarity test of B-rep faces.

    >>> unit_newell(np.array([[0.0, 0, 0], [0, 0, 1], [0, 1, 0]])).tolist()
    [-1.0, 0.0, 0.0]
    """
    n = newell(P)
    with np.errstate(over="ignore", under="ignore"):
        length = np.linalg.norm(n)
    if not (np.isfinite(length) and length > 1e-150) and np.isfinite(n).all():
        length = norm(n)                  # |n|^2 overflowed or underflowed: scale before squaring
    return n / length if length > 0 else n


def slerp(a: np.ndarray, b: np.ndarray, t: np.ndarray, la=None, lb=None, cos=None) -> np.ndarray:
    """Spherical linear interpolation ``sin((1-t)θ)/sin θ a + sin(tθ)/sin θ b`` of nonzero vectors a, b
    ``(..., d)`` of equal length that are not opposite, at t ``(...)`` (Goldman §11.6); linear
    interpolation where ``sin θ < 1e-9``.  la, lb: their lengths if known (default :func:`norm`);
    cos: ``cos θ`` clipped to [-1, 1], if the caller has it.

    >>> np.round(slerp(np.array([1.0, 0.0]), np.array([0.0, 1.0]), np.array(0.5)), 12).tolist()
    [0.707106781187, 0.707106781187]
    """
    la = norm(a, axis=-1) if la is None else la
    lb = norm(b, axis=-1) if lb is None else lb
    tt = t[..., None]
    if cos is None:
        cos = np.clip(row_dots(*np.broadcast_arrays(a, b)) / (la * lb), -1, 1)
    cos = cos[..., None]
    theta = np.arccos(cos)
    sin = np.sin(theta)
    small = sin < 1e-9
    safe = np.where(small, 1, sin)
    wa = np.where(small, 1 - tt, np.sin((1 - tt) * theta) / safe)
    wb = np.where(small, tt, np.sin(tt * theta) / safe)
    return wa * a + wb * b


def frame(w: np.ndarray, major=None) -> np.ndarray:
    """Right-handed orthonormal frames completing unit vectors w ``(..., 3)``: ``(..., 3, 3)``, rows
    ``u, v, w`` with ``u x v = w`` (Goldman §19, §23.3).  ``u`` is ``major`` ``(3,)`` or ``(..., 3)``
    projected off w and normalised, ``u = (m - (m . w) w) / |...|``, where ``major`` is given and not
    along w (``|major . w| < (1 - 1e-9) |major|``; any length); elsewhere ``m`` is the coordinate axis
    of least ``|w_i|`` (the first of equals), which is never within 54.7 degrees of w.  ``v = w x u``.

    >>> frame(np.array([0.0, 0.0, 1.0])).tolist()
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    >>> frame(np.array([[0.0, 0.0, 1.0]]), np.array([0.0, 2.0, 0.0]))[0].tolist()
    [[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    """
    w = np.asarray(w, dtype=float)
    axis = np.eye(3)[np.argmin(np.abs(w), axis=-1)]
    if major is None:
        m = axis
    else:
        m = np.broadcast_to(np.asarray(major, dtype=float), w.shape)
        m = np.where(np.abs(_dots(m, w)) >= (1 - 1e-9) * np.sqrt(_dots(m, m)), axis, m)   # zero, or along w
    u = m - _dots(m, w) * w
    u = u / np.sqrt(_dots(u, u))
    return np.stack([u, np.cross(w, u), w], axis=-2)


def _dots(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row dot products ``(..., 1)`` summed as :func:`numpy.dot` sums them (``matmul``), so a single
    frame is the same to the last bit as one written with ``np.dot``."""
    return (a[..., None, :] @ b[..., :, None])[..., 0]

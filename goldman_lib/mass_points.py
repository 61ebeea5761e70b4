"""Projective space and mass-points; perspective, the law of the lever, pseudoperspective and
pseudodepth (Goldman Chapter 14).

A **mass-point** is a point P with a nonzero mass m, stored as ``(m P, m)``; a **vector** v is
stored as ``(v, 0)``: a mass-point of mass zero.  With these coordinates the sum of two
mass-points is the mass-point at their centre of mass with the total mass -- Archimedes' law of
the lever -- and affine space sits inside a space where everything adds (Goldman §14.3).  Arrays
are ``(..., d + 1)`` with the mass last; functions vectorise over leading axes.

Projective space (Goldman §14.2) identifies nonzero ``(x, w)`` that differ by a scale: the
mass-point ``(m P, m)`` and the point P are the same projective point for every m ≠ 0, and the
vectors ``(v, 0)`` are its points at infinity.

>>> a, b = mass_point([0, 0], 3), mass_point([4, 0], 1)
>>> point_of(add(a, b)).tolist(), float(mass_of(add(a, b)))      # the lever balances at x = 1
([1.0, 0.0], 4.0)
"""

from __future__ import annotations

import numpy as np

from goldman_lib.validation import as_float, as_float_array, as_int, as_points, check_finite, finite_result
from goldman_lib.kernels.frames import norm as _norm   # np.linalg.norm, right where v·v over/underflows

__all__ = ["mass_point", "vector", "add", "scale", "mass_of", "point_of", "center_of_mass", "same_projective_point",
           "projective_factor",
           "perspective_mass", "pseudoperspective", "pseudoperspective_matrix", "pseudodepth",
           "normalized_depth", "depth_resolution"]


def _mp(a, name: str) -> np.ndarray:
    arr = check_finite(as_float_array(a, name), name)
    if arr.ndim == 0 or arr.shape[-1] < 2:
        raise ValueError(f"{name} must be mass-points (m P, m) or vectors (v, 0) with the mass last; got shape {arr.shape}")
    return arr


def mass_point(P, m) -> np.ndarray:
    """The mass-point ``(m P, m)`` of point(s) ``P`` with mass ``m ≠ 0`` (Goldman §14.3).

    >>> mass_point([1, 2], 2).tolist()
    [2.0, 4.0, 2.0]
    """
    pts = as_points(P, "P", ndim=None)
    mass = check_finite(as_float_array(m, "m"), "m")
    if np.any(mass == 0):
        raise ValueError("m must be nonzero: a mass of zero makes a vector, not a mass-point (use vector(v))")
    mass = np.broadcast_to(mass, np.broadcast_shapes(mass.shape, pts.shape[:-1]))
    pts = np.broadcast_to(pts, mass.shape + pts.shape[-1:])
    return np.concatenate([pts * mass[..., None], mass[..., None]], axis=-1)


def vector(v) -> np.ndarray:
    """The vector(s) ``v`` as mass-points of mass zero, ``(v, 0)`` (Goldman §14.3).

    >>> vector([3, 4]).tolist()
    [3.0, 4.0, 0.0]
    """
    arr = as_points(v, "v", ndim=None)
    return np.concatenate([arr, np.zeros(arr.shape[:-1] + (1,))], axis=-1)


def add(a, b) -> np.ndarray:
    """The sum of mass-points and vectors, coordinate by coordinate (Goldman §14.3): two mass-points
    give their centre of mass with the total mass (the law of the lever); a mass-point plus a vector
    translates the point; masses that cancel give a vector.

    >>> add(mass_point([0, 0], 1), mass_point([2, 0], -1)).tolist()   # masses cancel: a vector
    [-2.0, 0.0, 0.0]
    """
    x, y = _mp(a, "a"), _mp(b, "b")
    if x.shape[-1] != y.shape[-1]:
        raise ValueError(f"a and b must have the same dimension; got {x.shape[-1] - 1} and {y.shape[-1] - 1}")
    return x + y


def scale(c, a) -> np.ndarray:
    """``c (m P, m) = (c m P, c m)``: the same point with c times the mass (Goldman §14.3).

    >>> scale(2, mass_point([1, 1], 3)).tolist()
    [6.0, 6.0, 6.0]
    """
    return finite_result(as_float(c, "c") * _mp(a, "a"), "c", why="(times a) is too large in magnitude")


def mass_of(a):
    """The mass (last coordinate) of mass-points; 0 for vectors.

    >>> float(mass_of([6, 6, 3]))
    3.0
    """
    out = _mp(a, "a")[..., -1]
    return float(out) if out.ndim == 0 else out


def point_of(a) -> np.ndarray:
    """The point P of mass-points ``(m P, m)``: divide by the mass.  Raises ValueError for a vector
    (mass 0): it is a point at infinity of projective space, not a point of affine space.

    >>> point_of([6, 3, 3]).tolist()
    [2.0, 1.0]
    """
    x = _mp(a, "a")
    m = x[..., -1]
    if np.any(m == 0):
        raise ValueError("a must have nonzero mass: a mass-point of mass 0 is a vector (a point at infinity)")
    return x[..., :-1] / m[..., None]


def center_of_mass(points, masses) -> np.ndarray:
    """The centre of mass ``Σ m_i P_i / Σ m_i`` of points with masses of nonzero total: the point of
    the sum of the mass-points (Goldman §14.3).

    >>> center_of_mass([[0, 0], [4, 0], [0, 4]], [2, 1, 1]).tolist()
    [1.0, 1.0]
    """
    pts = as_points(points, "points")
    m = check_finite(as_float_array(masses, "masses"), "masses")
    if m.shape != pts.shape[:1]:
        raise ValueError(f"masses must have one entry per point of points ({len(pts)}); got shape {m.shape}")
    if m.sum() == 0:
        raise ValueError("masses must not sum to 0: the sum of the mass-points is then a vector, with no centre")
    return point_of((pts * m[:, None]).sum(axis=0).tolist() + [float(m.sum())])


def same_projective_point(a, b, tol: float = 1e-12):
    """Whether two nonzero coordinate tuples ``(x, w)`` are the same point of projective space, that
    is proportional (Goldman §14.2): the mass-point model and the projective model agree up to scale.

    >>> bool(same_projective_point([2, 4, 2], [-1, -2, -1])), bool(same_projective_point([1, 0, 0], [1, 0, 1]))
    (True, False)
    """
    x, y = _mp(a, "a"), _mp(b, "b")
    if x.shape[-1] != y.shape[-1]:
        raise ValueError(f"a and b must have the same number of coordinates; got shapes {x.shape} and {y.shape}")
    tol = as_float(tol, "tol", positive=True)
    nx, ny = _norm(x, axis=-1), _norm(y, axis=-1)
    if np.any(nx == 0) or np.any(ny == 0):
        raise ValueError("a and b must be nonzero: (0, ..., 0) is no point of projective space")
    ux, uy = x / nx[..., None], y / ny[..., None]
    # proportional iff the 2 x (d+1) matrix [ux; uy] has rank 1: |ux ∧ uy|^2 = 1 - (ux.uy)^2
    c = np.einsum("...i,...i->...", ux, uy)
    out = 1 - c * c <= tol
    return bool(out) if np.ndim(out) == 0 else out


def projective_factor(a, b, tol: float = 1e-12):
    """The factor λ with ``b = λ a`` when two nonzero tuples ``(x, w)`` are the same projective
    point (Goldman §14.2), else None: what :func:`same_projective_point` decides, with the scale shown.

    a, b: (d+1,) tuples, or (..., d+1) arrays of them; for arrays the result is an array with NaN
    where the pair is not proportional.  λ = ±|b| / |a|, with the sign of a·b.
    Raises ValueError for zero tuples or tuples of different lengths.

    >>> projective_factor([1, -2, 4, 1], [3, -6, 12, 3]), projective_factor([1, 0, 1], [1, 0, 2])
    (3.0, None)
    """
    same = same_projective_point(a, b, tol)
    x, y = _mp(a, "a"), _mp(b, "b")
    nx, ny = _norm(x, axis=-1), _norm(y, axis=-1)
    c = np.einsum("...i,...i->...", x / nx[..., None], y / ny[..., None])
    with np.errstate(over="ignore"):
        lam = np.sign(c) * (ny / nx)      # |λ| = |b| / |a|, its sign that of a·b: no overflow in a·a
    finite_result(np.asarray(lam), "b", why="is too large relative to a")
    if np.ndim(lam) == 0:
        return float(lam) if same else None
    return np.where(same, lam, np.nan)


def _frame(eye, plane_point, normal):
    E = check_finite(as_float_array(eye, "eye"), "eye")
    Q = check_finite(as_float_array(plane_point, "plane_point"), "plane_point")
    N = check_finite(as_float_array(normal, "normal"), "normal")
    for arr, name in ((E, "eye"), (Q, "plane_point"), (N, "normal")):
        if arr.shape != (3,):
            raise ValueError(f"{name} must be a 3D point or vector (shape (3,)); got shape {arr.shape}")
    with np.errstate(over="ignore", invalid="ignore"):
        n = _norm(N)
        gap = _norm(Q - E)
    finite_result(np.asarray(n), "normal")
    finite_result(np.asarray(gap), "plane_point", why="is too far from eye")
    if n == 0:
        raise ValueError("normal must be a nonzero vector: a plane needs a normal direction")
    N = N / n
    c = float((Q - E) @ N)
    if abs(c) <= 1e-12 * (1 + gap):
        raise ValueError("eye must not lie on the plane of projection (the plane through plane_point with normal "
                         "normal)")
    return E, Q, N, c


def perspective_mass(points, eye, plane_point, normal) -> np.ndarray:
    """Perspective projection as a mass-point (Goldman §14.4.1): the image of P from eye E onto the
    plane is the sum of the mass-points ``(cP, c)`` and ``((s - c)E, s - c)``, that is ``(c (P - E) + s E, s)``,
    with ``s = (P - E)·N`` and ``c = (Q - E)·N``.  By the law of the lever the sum sits on the line EP
    at the balance point of the two masses, which is on the plane.  Points with ``s = 0`` go to
    vectors (points at infinity).

    >>> point_of(perspective_mass([[2, 4, 2]], [0, 0, 0], [0, 0, 1], [0, 0, 1])).tolist()
    [[1.0, 2.0, 1.0]]
    """
    P = as_points(points, "points", ndim=None, dim=3)
    E, Q, N, c = _frame(eye, plane_point, normal)
    s = (P - E) @ N
    return np.concatenate([c * (P - E) + s[..., None] * E, s[..., None]], axis=-1)


def pseudodepth(points, eye, plane_point, normal) -> np.ndarray:
    """Pseudodepth ``δ = 1 - c / s`` with ``s = (P - E)·N`` the depth of P in front of the eye and
    ``c = (Q - E)·N`` that of the projection plane (formulation ours, after Goldman §14.4.2): 0 on the
    plane, approaching 1 at infinity, and strictly increasing in s for points in front of the eye --
    so it keeps the depth order that perspective projection throws away, while (unlike s itself)
    being a ratio of affine functions, so that pseudoperspective maps lines to lines.

    >>> pseudodepth([[0, 0, 1], [0, 0, 2], [0, 0, 4]], [0, 0, 0], [0, 0, 1], [0, 0, 1]).tolist()
    [0.0, 0.5, 0.75]
    """
    P = as_points(points, "points", ndim=None, dim=3)
    E, Q, N, c = _frame(eye, plane_point, normal)
    s = (P - E) @ N
    if np.any(s * np.sign(c) <= 0):
        raise ValueError("points must lie in front of the eye (on the side of the projection plane)")
    return 1 - c / s


def normalized_depth(pseudodepths, c, near, far) -> np.ndarray:
    """The affine change of the pseudodepth ``δ = 1 - c/s`` that sends the depth ``near`` to -1 and
    ``far`` to +1: ``z = 2 (δ - δ_near) / (δ_far - δ_near) - 1``.  Written in the depth ``s`` it is
    ``(f + n)/(f - n) - 2 f n / ((f - n) s)``, the depth row of the familiar frustum (OpenGL) matrix:
    that matrix is pseudoperspective followed by an affine map of the depth coordinate, so it keeps
    lines straight and the depth order (formulation ours, after Goldman §14.4).  c: the projection
    plane's depth ``(Q - E)·N`` (nonzero); 0 < near < far, with the signs of ``c``.

    >>> normalized_depth([1 - 1 / 1, 1 - 1 / 10], 1.0, 1.0, 10.0).tolist()
    [-1.0, 1.0]
    """
    d = as_float_array(pseudodepths, "pseudodepths")
    c = float(as_float(c, "c"))
    n, f = float(as_float(near, "near", positive=True)), float(as_float(far, "far", positive=True))
    if c == 0:
        raise ValueError("c must be nonzero (the projection plane cannot pass through the eye)")
    if not f > n:
        raise ValueError(f"far must be greater than near; got near {n:g} and far {f:g}")
    dn, df = 1 - c / n, 1 - c / f
    with np.errstate(over="ignore", invalid="ignore"):
        out = 2 * (d - dn) / (df - dn) - 1
    return finite_result(out, "pseudodepths, c, near or far", why="are too large or too small in magnitude")


def depth_resolution(depths, near, far, bits: int = 24) -> np.ndarray:
    """The smallest difference in depth ``s`` a ``bits``-bit depth buffer can tell apart at ``s``,
    when it stores :func:`normalized_depth` in ``2^bits`` equal steps over [-1, 1]: one step
    divided by the slope ``dz/ds = 2 f n / ((f - n) s^2)``, that is ``s^2 (f - n) / (2^bits f n)``.
    It grows like ``s^2 / near``: pushing ``near`` out buys precision everywhere, pulling ``far`` in
    hardly any (our formulation).

    >>> [f"{r:.4e}" for r in depth_resolution([1.0, 10.0], 1.0, 100.0, bits=8)]     # 99 s^2 / 25600
    ['3.8672e-03', '3.8672e-01']
    """
    s = as_float_array(depths, "depths")
    n, f = float(as_float(near, "near", positive=True)), float(as_float(far, "far", positive=True))
    if not f > n:
        raise ValueError(f"far must be greater than near; got near {n:g} and far {f:g}")
    b = as_int(bits, "bits", minimum=1)
    if b > 64:
        raise ValueError(f"bits must be at most 64; got {b}")
    if np.any(s <= 0):
        raise ValueError("depths must be positive (in front of the eye)")
    with np.errstate(over="ignore", invalid="ignore"):
        out = s * s * (f - n) / (2.0 ** b * f * n)
    return finite_result(out, "depths, near or far", why="are too large or too small in magnitude")


def pseudoperspective_matrix(eye, plane_point, normal) -> np.ndarray:
    """The 4x4 matrix (row convention, ``[P 1] @ M``) of pseudoperspective (formulation ours, after
    Goldman §14.4.2): ``P ↦ persp(P) + c δ(P) N``, the perspective image moved off the plane along N
    by ``c`` times the pseudodepth.  In mass-point form the image is ``(s E + c (P - E) + c (s - c) N, s)``,
    affine in P, hence a projective map: lines go to lines, planes to planes, and depth order is kept.

    >>> M = pseudoperspective_matrix([0, 0, 0], [0, 0, 1], [0, 0, 1])
    >>> from goldman_lib.transforms import apply
    >>> apply([[2, 4, 2]], M).tolist()
    [[1.0, 2.0, 1.5]]
    """
    E, Q, N, c = _frame(eye, plane_point, normal)
    with np.errstate(over="ignore", invalid="ignore"):
        eN = float(E @ N)
        M = np.zeros((4, 4))
        # numerator = s E + c (P - E) + c (s - c) N with s = P.N - E.N
        M[:3, :3] = np.outer(N, E) + c * np.eye(3) + c * np.outer(N, N)
        M[3, :3] = -eN * E - c * E - c * eN * N - c * c * N
        M[:3, 3] = N
        M[3, 3] = -eN
    return finite_result(M, "eye or plane_point", why="is too large in magnitude")


def pseudoperspective(points, eye, plane_point, normal) -> np.ndarray:
    """Apply pseudoperspective to points in front of the eye: the perspective image in the plane's
    directions, pseudodepth (times ``c``) along the normal (see :func:`pseudoperspective_matrix`).

    >>> pseudoperspective([[2, 4, 2], [1, 2, 1]], [0, 0, 0], [0, 0, 1], [0, 0, 1]).tolist()
    [[1.0, 2.0, 1.5], [1.0, 2.0, 1.0]]
    """
    P = as_points(points, "points", ndim=None, dim=3)
    E, Q, N, c = _frame(eye, plane_point, normal)
    delta = pseudodepth(P, E, Q, N)
    with np.errstate(over="ignore", invalid="ignore"):
        s = (P - E) @ N
        persp = E + (c / s)[..., None] * (P - E)
        out = persp + (c * delta)[..., None] * N
    return finite_result(out, "points, eye or plane_point", why="is too large in magnitude")

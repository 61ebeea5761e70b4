"""Surfaces, the general theory (Goldman chapter 18): implicit, parametric, deformed and procedural
surfaces; their normals; ray-surface intersection; mean and Gaussian curvature.

* **Implicit** (§18.1): the points where ``F(x, y, z) = 0``; the normal is ``grad F`` (§18.2).  A ray
  ``P(t) = O + t d`` meets the surface at the roots of the one-variable function ``F(O + t d)``
  (§18.3): :class:`ImplicitSurface` brackets them by sampling ``F`` along the part of each ray inside
  a bounding sphere and refines each sign change by bisection, vectorised over all rays at once.
  (Roots where ``F`` touches 0 without changing sign -- a ray grazing the surface -- are not found;
  a finer ``samples`` finds two close roots.)
* **Parametric** (§18.1): the points ``X(u, v)``; the normal is ``X_u x X_v`` (§18.2).  A ray meets
  it where ``O + t d = X(u, v)``, three equations in ``(t, u, v)`` solved by Newton's method (§18.3)
  from the best points of a grid of the surface (:class:`ParametricSurface`).
* **Deformed** (§18.1-18.2): the image ``A(S)`` of a surface under a map ``A``.  Tangent vectors map
  by the Jacobian ``J`` of ``A``, so normals map by its inverse transpose, ``n' = J^{-T} n``
  (:func:`deformed_normals`; ``J[i, j] = dA_i/dx_j``, columns as in calculus: for a linear map
  ``Q = P M`` in the book's row convention ``J = M^T`` and ``n' = n (M^{-1})^T`` as a row).  The image
  of an implicit surface is implicit again, ``F(A^{-1}(Q)) = 0`` (:class:`DeformedSurface`).
* **Procedural** (§18.1): surfaces made by a procedure rather than a formula.  Ours is a fractal
  terrain by random midpoint displacement (the diamond-square algorithm, our choice of example):
  :func:`fractal_heights` and :func:`height_field_mesh`.
* **Curvature** (§18.4): :func:`curvature_implicit` from the gradient and Hessian of ``F``,
  :func:`curvature_parametric` from the first and second fundamental forms, and
  :func:`curvature_deformed` for an implicit surface under an affine map (§18.4.3: the gradient and
  Hessian of ``F(A^{-1}(Q))`` by the chain rule, then the implicit formulas).

Sign convention of the mean curvature (the tests compare ``|H|``): we use the formulas of §18.4 in
the form (Goldman, *Curvature formulas for implicit curves and surfaces*, 2005)
``H = (grad F . Hess F . grad F - |grad F|^2 trace Hess F) / (2 |grad F|^3)`` and, for a parametric
surface with ``n = X_u x X_v / |X_u x X_v|``, ``H = (E N - 2 F M + G L) / (2 (E G - F^2))`` with
``L = X_uu . n``, ``M = X_uv . n``, ``N = X_vv . n``.  Both give ``H = -1/r`` on a sphere whose normal
points out of it (``F < 0`` inside; ``X_u x X_v`` outward): **H is negative where the surface bends
away from its normal**; reversing the normal (``F -> -F``, or swapping ``u`` and ``v``) flips the sign
of ``H`` and keeps ``K``.  ``K = -det [[Hess F, grad F^T], [grad F, 0]] / |grad F|^4 =
(L N - M^2) / (E G - F^2)``.

>>> s = implicit_sphere([0, 0, 0], 2.0)
>>> s.intersect([[0, 0, -5]], [[0, 0, 1]]).round(12).tolist()
[3.0]
>>> H, K = curvature_implicit(s.f, s.grad, s.hess, [[0, 0, 2.0]])
>>> float(H[0]), float(K[0])
(-0.5, 0.25)
"""

from __future__ import annotations

import numpy as np

from goldman_lib.lighting import Material, unit_rows
from goldman_lib.simple_surfaces import EPS, Sphere, Surface, rays
from goldman_lib.validation import as_float, as_float_array, as_int, as_points, check_finite, finite_result, \
    within_budget

__all__ = ["ImplicitSurface", "ParametricSurface", "Deformation", "DeformedSurface", "implicit_normal",
           "parametric_normal", "deformed_normals", "curvature_implicit", "curvature_deformed", "curvature_parametric",
           "implicit_sphere", "implicit_cylinder", "implicit_torus", "parametric_sphere", "parametric_cylinder",
           "parametric_torus", "parametric_graph", "twist", "taper", "fractal_heights", "height_field_mesh",
           "MAX_SAMPLES", "AffineInstance"]

#: Most samples along a ray that the implicit intersection may be asked for.
MAX_SAMPLES = 4096
_MAX_WORK = 20_000_000          # rays x samples (function evaluations) per call


# -- checked calls of the learner's functions ---------------------------------------------------------

_MAX_SIZE = 1e100


def _size(x, name: str) -> float:
    v = as_float(x, name, positive=True)
    if v > _MAX_SIZE:
        raise ValueError(f"{name} must be at most {_MAX_SIZE:g}; got {v:g}")
    return v


def _callable(fn, name: str):
    if not callable(fn):
        raise TypeError(f"{name} must be a callable (a function of points); got {type(fn).__name__}")
    return fn


def _call(fn, name: str, shape: tuple, *args) -> np.ndarray:
    """``fn(*args)`` as a float array of ``shape`` (finite), with errors naming ``name``."""
    with np.errstate(all="ignore"):
        try:
            out = np.asarray(fn(*args), dtype=float)
        except (TypeError, ValueError) as exc:
            raise ValueError(f"{name} failed on its input: {exc}") from None
    if out.shape != shape:
        try:
            out = np.broadcast_to(out, shape).copy()
        except ValueError:
            raise ValueError(f"{name} must return an array of shape {shape}; got {out.shape}") from None
    if not np.all(np.isfinite(out)):
        raise ValueError(f"{name} returned NaN or infinity at the points given")
    return out


def _gradient(f, grad, P, h=1e-6):
    if grad is not None:
        return _call(grad, "grad", P.shape, P)
    scale = h * np.maximum(1.0, np.abs(P))
    g = np.empty_like(P)
    for i in range(3):
        e = np.zeros(3)
        e[i] = 1.0
        g[:, i] = (_call(f, "f", (len(P),), P + scale[:, i:i + 1] * e)
                   - _call(f, "f", (len(P),), P - scale[:, i:i + 1] * e)) / (2 * scale[:, i])
    return g


def _hessian(f, grad, hess, P, h=1e-4):
    if hess is not None:
        return _call(hess, "hess", P.shape + (3,), P)
    scale = h * np.maximum(1.0, np.abs(P))
    out = np.empty(P.shape + (3,))
    for i in range(3):
        e = np.zeros(3)
        e[i] = 1.0
        step = scale[:, i:i + 1] * e
        out[:, i, :] = (_gradient(f, grad, P + step, h=1e-5) - _gradient(f, grad, P - step, h=1e-5)) / (2 * scale[:, i:i + 1])
    return 0.5 * (out + np.swapaxes(out, 1, 2))


def _uv(u, v):
    u = check_finite(as_float_array(u, "u"), "u")
    v = check_finite(as_float_array(v, "v"), "v")
    try:
        u, v = np.broadcast_arrays(u, v)
    except ValueError:
        raise ValueError(f"u and v must have the same shape; got {u.shape} and {v.shape}") from None
    if u.size == 0:
        raise ValueError("u and v must hold at least one parameter")
    return u, v


def _first_partials(X, u, v, partials=None):
    """``(X_u, X_v)`` only (four evaluations of ``X`` by central differences): what Newton needs."""
    if partials is not None:
        return _partials(X, u, v, partials)[:2]
    shape = u.shape + (3,)
    h = 1e-6 * np.maximum(1.0, np.maximum(np.abs(u), np.abs(v)))
    H = h[..., None]
    x = lambda a, b: _call(X, "X(u, v)", shape, a, b)  # noqa: E731
    return (x(u + h, v) - x(u - h, v)) / (2 * H), (x(u, v + h) - x(u, v - h)) / (2 * H)


def _partials(X, u, v, partials=None):
    """``(X_u, X_v, X_uu, X_uv, X_vv)`` at the parameters (each ``u.shape + (3,)``): from
    ``partials(u, v)`` if given, otherwise by central differences of ``X``."""
    shape = u.shape + (3,)
    if partials is not None:
        with np.errstate(all="ignore"):
            try:
                got = partials(u, v)
            except (TypeError, ValueError) as exc:
                raise ValueError(f"partials failed on its input: {exc}") from None
        if len(got) != 5:
            raise ValueError("partials must return five arrays (X_u, X_v, X_uu, X_uv, X_vv)")
        return tuple(_call(lambda a=a: a, "partials", shape) for a in got)
    x = lambda a, b: _call(X, "X(u, v)", shape, a, b)  # noqa: E731
    h1 = 1e-5 * np.maximum(1.0, np.maximum(np.abs(u), np.abs(v)))
    h2 = 1e-4 * np.maximum(1.0, np.maximum(np.abs(u), np.abs(v)))
    H1, H2 = h1[..., None], h2[..., None]
    Xu = (x(u + h1, v) - x(u - h1, v)) / (2 * H1)
    Xv = (x(u, v + h1) - x(u, v - h1)) / (2 * H1)
    X0 = x(u, v)
    Xuu = (x(u + h2, v) - 2 * X0 + x(u - h2, v)) / H2 ** 2
    Xvv = (x(u, v + h2) - 2 * X0 + x(u, v - h2)) / H2 ** 2
    Xuv = (x(u + h2, v + h2) - x(u + h2, v - h2) - x(u - h2, v + h2) + x(u - h2, v - h2)) / (4 * H2 ** 2)
    return Xu, Xv, Xuu, Xuv, Xvv


# -- §18.2 normals -------------------------------------------------------------------------------------

def implicit_normal(grad, points) -> np.ndarray:
    """Unit normals ``grad F / |grad F|`` of an implicit surface ``F = 0`` at points on it (Goldman
    §18.2).  grad: a callable ``(n, 3) -> (n, 3)``.  A zero gradient (a singular point) gives a zero row.

    >>> implicit_normal(lambda P: 2 * P, [[0, 3.0, 4.0]]).tolist()
    [[0.0, 0.6, 0.8]]
    """
    _callable(grad, "grad")
    P = as_points(points, "points", dim=3)
    return unit_rows(_call(grad, "grad at the points", P.shape, P), "grad at the points")


def parametric_normal(X, u, v, partials=None) -> np.ndarray:
    """Unit normals ``X_u x X_v / |X_u x X_v|`` of a parametric surface at parameters ``(u, v)``
    (Goldman §18.2).  X: a callable ``X(u, v) -> u.shape + (3,)``; partials: optional callable giving
    ``(X_u, X_v, X_uu, X_uv, X_vv)`` (otherwise central differences).  Returns ``u.shape + (3,)``.

    >>> parametric_normal(parametric_sphere(2.0).X, 0.0, 0.0).round(9).tolist()
    [1.0, 0.0, 0.0]
    """
    _callable(X, "X")
    u, v = _uv(u, v)
    Xu, Xv, *_ = _partials(X, u, v, partials)
    return unit_rows(np.cross(Xu, Xv), "X")


def deformed_normals(jacobians, normals) -> np.ndarray:
    """Normals of a deformed surface (Goldman §18.2): if a map ``A`` with Jacobian ``J`` at ``P``
    (``J[i, j] = dA_i/dx_j``) takes a surface with normal ``n`` at ``P`` to ``A(S)``, the normal at
    ``A(P)`` is ``J^{-T} n`` (tangents map by ``J``, and ``(J^{-T} n) . (J t) = n . t = 0``), returned
    as unit vectors.  jacobians: ``(n, 3, 3)`` invertible; normals: ``(n, 3)``.

    >>> deformed_normals([np.diag([2.0, 1.0, 1.0])], [[1.0, 1.0, 0.0]]).round(6).tolist()   # stretch x by 2
    [[0.447214, 0.894427, 0.0]]
    """
    J = as_float_array(jacobians, "jacobians")
    if J.ndim != 3 or J.shape[1:] != (3, 3):
        raise ValueError(f"jacobians must have shape (n, 3, 3); got {J.shape}")
    check_finite(J, "jacobians")
    n = as_points(normals, "normals", dim=3)
    if len(n) != len(J):
        raise ValueError(f"normals must hold one normal per Jacobian ({len(J)}); got {len(n)}")
    with np.errstate(all="ignore"):
        det = np.linalg.det(J)
        scale = np.abs(J).reshape(len(J), -1).max(axis=1) if len(J) else np.zeros(0)
        if np.any(~np.isfinite(det)) or np.any(np.abs(det) <= 1e-12 * np.maximum(scale, 1e-300) ** 3):
            raise ValueError("jacobians must be invertible (a deformation may not flatten the surface)")
        out = np.linalg.solve(np.swapaxes(J, 1, 2), n[..., None])[..., 0]
    return unit_rows(finite_result(out, "jacobians and normals", why="are too large or too nearly singular"),
                     "jacobians and normals")


# -- §18.4 curvature -----------------------------------------------------------------------------------

def _adjugate(Hs):
    a, b, c = Hs[:, 0, 0], Hs[:, 0, 1], Hs[:, 0, 2]
    d, e, f = Hs[:, 1, 0], Hs[:, 1, 1], Hs[:, 1, 2]
    g, h, i = Hs[:, 2, 0], Hs[:, 2, 1], Hs[:, 2, 2]
    return np.stack([np.stack([e * i - f * h, c * h - b * i, b * f - c * e], -1),
                     np.stack([f * g - d * i, a * i - c * g, c * d - a * f], -1),
                     np.stack([d * h - e * g, b * g - a * h, a * e - b * d], -1)], 1)


def curvature_implicit(f, grad, hess, points) -> tuple[np.ndarray, np.ndarray]:
    """Mean and Gaussian curvature ``(H, K)`` of the implicit surface ``f = 0`` at points on it
    (Goldman §18.4): with ``g = grad f`` and ``Hs`` the Hessian,
    ``K = g adj(Hs) g^T / |g|^4`` (= ``-det [[Hs, g^T], [g, 0]] / |g|^4``) and
    ``H = (g Hs g^T - |g|^2 trace Hs) / (2 |g|^3)`` (negative on a sphere with ``f < 0`` inside; see
    the module docstring for the sign).

    f: callable ``(n, 3) -> (n,)``; grad: callable ``(n, 3) -> (n, 3)`` or None; hess: callable
    ``(n, 3) -> (n, 3, 3)`` or None (None: central differences of ``f``, or of ``grad``).  Points
    where the gradient vanishes (singular points) are refused.

    >>> H, K = curvature_implicit(lambda P: P[:, 0] ** 2 + P[:, 1] ** 2 - 4, None, None, [[2.0, 0, 0]])
    >>> round(float(H[0]), 6), round(float(K[0]), 6)                 # a cylinder of radius 2
    (-0.25, 0.0)
    """
    _callable(f, "f")
    if grad is not None:
        _callable(grad, "grad")
    if hess is not None:
        _callable(hess, "hess")
    P = as_points(points, "points", dim=3)
    return _curvature_from(_gradient(f, grad, P), _hessian(f, grad, hess, P))


def _curvature_from(g, Hs) -> tuple[np.ndarray, np.ndarray]:
    """``(H, K)`` of §18.4.1 from gradients ``g (n, 3)`` and Hessians ``Hs (n, 3, 3)`` at points on a surface."""
    g2 = np.einsum("ij,ij->i", g, g)
    scale = np.abs(g).max(axis=1) if len(g) else np.zeros(0)
    if np.any(g2 <= 0) or np.any(~np.isfinite(g2)):
        raise ValueError("points must not be singular points of f: its gradient vanishes (or overflows) there")
    with np.errstate(all="ignore"):
        gn = g / scale[:, None]                        # scaled for safety; the ratios are homogeneous
        gHg = np.einsum("ij,ijk,ik->i", gn, Hs, gn)
        n2 = np.einsum("ij,ij->i", gn, gn)
        trace = np.trace(Hs, axis1=1, axis2=2)
        K = np.einsum("ij,ijk,ik->i", gn, _adjugate(Hs), gn) / (n2 * n2 * scale ** 2)
        H = (gHg - n2 * trace) / (2 * n2 ** 1.5 * scale)
    return finite_result(H, "points"), finite_result(K, "points")


def curvature_deformed(f, grad, hess, M, points, shift=(0.0, 0.0, 0.0)) -> tuple[np.ndarray, np.ndarray]:
    """Mean and Gaussian curvature ``(H, K)`` of an implicit surface ``f = 0`` deformed by the affine map
    ``A(P) = P M + shift`` (row vectors, the book's convention), at points ``Q`` of the image, by formula
    (Goldman §18.4.3): the image is ``G(Q) = f((Q - shift) M^{-1}) = 0``, so with ``P = A^{-1}(Q)`` and
    ``N = M^{-1}`` the chain rule gives, as a row and a matrix,

        ``grad G(Q) = grad f(P) N^T``        ``Hess G(Q) = N Hess f(P) N^T``

    (a linear map has no second derivatives, so no other term), and ``K``, ``H`` follow from the
    implicit formulas of §18.4.1 (:func:`curvature_implicit`) with these.  Nothing is differentiated
    numerically when ``grad`` and ``hess`` are given.

    f, grad, hess: the base surface as in :func:`curvature_implicit` (callables; ``grad``/``hess`` may be
    None for central differences of ``f``).  M: an invertible 3x3 matrix.  shift: (3,).  points:
    ``(n, 3)`` on the image.  Returns two ``(n,)`` arrays.  Raises ValueError for a singular ``M``.

    The unit sphere stretched by ``diag(a, b, c)`` is the ellipsoid ``x^2/a^2 + y^2/b^2 + z^2/c^2 = 1``,
    whose ``K = 1 / (a^2 b^2 c^2 (x^2/a^4 + y^2/b^4 + z^2/c^4)^2)``.  With radii (3, 2, 1), at the vertex
    ``(3, 0, 0)`` the principal curvatures are ``a/b^2 = 3/4`` and ``a/c^2 = 3``: ``K = 9/4`` and
    ``H = -(3/4 + 3)/2`` (negative: the sphere's ``f`` is negative inside, see the module docstring):

    >>> s = implicit_sphere([0, 0, 0], 1.0)
    >>> H, K = curvature_deformed(s.f, s.grad, s.hess, np.diag([3.0, 2.0, 1.0]), [[3.0, 0.0, 0.0]])
    >>> round(float(K[0]), 12), round(float(H[0]), 12)
    (2.25, -1.875)
    """
    _callable(f, "f")
    if grad is not None:
        _callable(grad, "grad")
    if hess is not None:
        _callable(hess, "hess")
    M = check_finite(as_float_array(M, "M"), "M")
    if M.shape != (3, 3):
        raise ValueError(f"M must be a 3x3 matrix; got shape {M.shape}")
    scale = float(np.abs(M).max())
    if not scale > 0 or abs(np.linalg.det(M / scale)) < 1e-12:
        raise ValueError("M must be invertible (a singular M flattens the surface: it has no curvature)")
    if not 1e-100 <= scale <= 1e100:
        raise ValueError(f"M must have entries of moderate size (largest between 1e-100 and 1e100); got "
                         f"{scale:.3g}: the curvatures scale by its inverse and leave float64")
    shift = as_points(shift, "shift", ndim=1, dim=3)
    Q = as_points(points, "points", dim=3)
    N = np.linalg.inv(M)
    P = (Q - shift) @ N
    g = _gradient(f, grad, P) @ N.T
    Hs = N @ _hessian(f, grad, hess, P) @ N.T
    return _curvature_from(g, 0.5 * (Hs + np.swapaxes(Hs, 1, 2)))


def curvature_parametric(X, u, v, partials=None) -> tuple[np.ndarray, np.ndarray]:
    """Mean and Gaussian curvature ``(H, K)`` of the parametric surface ``X(u, v)`` (Goldman §18.4):
    with the first fundamental form ``E = X_u . X_u``, ``F = X_u . X_v``, ``G = X_v . X_v`` and the
    second ``L = X_uu . n``, ``M = X_uv . n``, ``N = X_vv . n`` (``n = X_u x X_v`` normalised),
    ``K = (L N - M^2) / (E G - F^2)`` and ``H = (E N - 2 F M + G L) / (2 (E G - F^2))``.

    X: callable ``X(u, v) -> u.shape + (3,)``; u, v: numbers or arrays (broadcast); partials:
    optional callable ``(u, v) -> (X_u, X_v, X_uu, X_uv, X_vv)``, otherwise central differences
    (about 1e-8 accurate).  Returns two arrays of ``u``'s shape.  Singular parameters
    (``X_u x X_v = 0``, such as a sphere's poles) are refused.

    >>> sphere = parametric_sphere(2.0)
    >>> H, K = curvature_parametric(sphere.X, 0.3, 0.4)
    >>> round(float(H), 6), round(float(K), 6)
    (-0.5, 0.25)
    """
    _callable(X, "X")
    if partials is not None:
        _callable(partials, "partials")
    u, v = _uv(u, v)
    Xu, Xv, Xuu, Xuv, Xvv = _partials(X, u, v, partials)
    with np.errstate(all="ignore"):
        cross = np.cross(Xu, Xv)
        length = np.sqrt(np.einsum("...i,...i->...", cross, cross))
        E, F, G = (np.einsum("...i,...i->...", a, b) for a, b in ((Xu, Xu), (Xu, Xv), (Xv, Xv)))
        W = E * G - F * F
        if np.any(length <= 1e-12 * np.maximum(E + G, 1e-300)) or np.any(~np.isfinite(W)):
            raise ValueError("u and v must not be singular parameters of X: X_u x X_v vanishes there")
        n = cross / length[..., None]
        L, M, N = (np.einsum("...i,...i->...", a, n) for a in (Xuu, Xuv, Xvv))
        K = (L * N - M * M) / W
        H = (E * N - 2 * F * M + G * L) / (2 * W)
    return finite_result(H, "u and v"), finite_result(K, "u and v")


# -- §18.1 and §18.3: implicit surfaces ---------------------------------------------------------------

class ImplicitSurface(Surface):
    """The surface ``f(x, y, z) = 0`` inside the bounding sphere ``bound`` (Goldman §18.1-18.3), with
    ``f < 0`` inside (normals ``grad f`` then point out).  It follows the ray-surface contract of
    :mod:`goldman_lib.simple_surfaces` (``hits``, ``intersect``, ``normal``, ``hit``, ``contains``,
    ``material``), so renderers draw it.

    f: callable ``(n, 3) -> (n,)``, vectorised.  grad, hess: callables ``(n, 3) -> (n, 3)`` and
    ``(n, 3) -> (n, 3, 3)``, or None for central differences.  bound: ``(center, radius)`` of a sphere
    holding the part of the surface to draw.  samples: points sampled along each ray's chord of the
    bounding sphere to bracket roots (4..:data:`MAX_SAMPLES`).  max_hits: roots reported per ray.
    """

    def __init__(self, f, grad=None, hess=None, bound=((0.0, 0.0, 0.0), 2.0), samples: int = 96,
                 max_hits: int = 4, material: Material | None = None):
        self.f = _callable(f, "f")
        self.grad = None if grad is None else _callable(grad, "grad")
        self.hess = None if hess is None else _callable(hess, "hess")
        try:
            center, radius = bound
        except (TypeError, ValueError):
            raise TypeError("bound must be a pair (center, radius)") from None
        try:
            self._bound = Sphere(center, radius)
        except (TypeError, ValueError) as exc:
            raise type(exc)(f"bound must be (center (3,), radius > 0): {exc}") from None
        self.samples = as_int(samples, "samples", minimum=4, maximum=MAX_SAMPLES)
        self.max_hits = as_int(max_hits, "max_hits", minimum=1, maximum=16)
        self._set_material(material)

    @property
    def bounding_sphere(self):
        """``(center, radius)`` of the bounding sphere."""
        return self._bound.center, self._bound.radius

    def value(self, points) -> np.ndarray:
        """``f`` at points: (n,)."""
        P = as_points(points, "points", dim=3)
        return _call(self.f, "f", (len(P),), P)

    def _hits(self, o, d):
        n, S = len(o), self.samples
        if n * S > _MAX_WORK:
            raise ValueError(f"origins: {n} rays x {S} samples is over the limit of {_MAX_WORK:,} evaluations of f")
        out = np.full((n, self.max_hits), np.inf)
        chord = self._bound.hits(o, d)                         # (n, 2): where each ray is inside the bound
        live = np.isfinite(chord[:, 0])
        if not live.any():
            return out
        idx = np.flatnonzero(live)
        t0, t1 = chord[idx, 0], chord[idx, 1]
        ts = t0[:, None] + (t1 - t0)[:, None] * np.linspace(0.0, 1.0, S)[None, :]
        pts = o[idx, None, :] + ts[..., None] * d[idx, None, :]
        F = _call(self.f, "f", (len(idx) * S,), pts.reshape(-1, 3)).reshape(len(idx), S)
        zero = F[:, :-1] == 0
        change = (np.sign(F[:, :-1]) * np.sign(F[:, 1:]) < 0) | zero
        change[:, -1] |= F[:, -1] == 0
        rows, cols = np.nonzero(change)
        if rows.size == 0:
            return out
        a, b = ts[rows, cols].copy(), ts[rows, cols + 1].copy()
        fa = F[rows, cols].copy()
        exact_a = fa == 0
        exact_b = (F[rows, cols + 1] == 0) & (cols + 1 == S - 1)
        oo, dd = o[idx[rows]], d[idx[rows]]
        for _ in range(60):                                     # bisection: the bracket halves each step
            m = 0.5 * (a + b)
            fm = _call(self.f, "f", (len(m),), oo + m[:, None] * dd)
            left = np.sign(fm) * np.sign(fa) <= 0
            b = np.where(left, m, b)
            a = np.where(left, a, m)
            fa = np.where(left, fa, fm)
            if np.all(b - a <= 1e-13 * np.maximum(1.0, np.abs(a))):
                break
        root = np.where(exact_a, ts[rows, cols], np.where(exact_b, ts[rows, cols + 1], 0.5 * (a + b)))
        rank = np.zeros_like(rows)
        starts = np.r_[0, np.flatnonzero(np.diff(rows)) + 1]
        counts = np.diff(np.r_[starts, len(rows)])
        rank = np.arange(len(rows)) - np.repeat(starts, counts)
        keep = rank < self.max_hits
        out[idx[rows[keep]], rank[keep]] = root[keep]
        return np.sort(out, axis=1)

    def _normal(self, P):
        return _gradient(self.f, self.grad, P)

    def _contains(self, P):
        return _call(self.f, "f", (len(P),), P) <= 0

    def curvature(self, points) -> tuple[np.ndarray, np.ndarray]:
        """``(H, K)`` at points on the surface (:func:`curvature_implicit`)."""
        return curvature_implicit(self.f, self.grad, self.hess, points)


def implicit_sphere(center=(0.0, 0.0, 0.0), radius: float = 1.0, material: Material | None = None) -> ImplicitSurface:
    """The sphere ``|P - C|^2 - r^2 = 0`` as an implicit surface, with its gradient ``2 (P - C)`` and
    Hessian ``2 I`` (Goldman §18.1).

    >>> implicit_sphere([1, 0, 0], 1.0).contains([[1.5, 0, 0], [3, 0, 0]]).tolist()
    [True, False]
    """
    c = as_points(center, "center", ndim=1, dim=3)
    r = _size(radius, "radius")
    return ImplicitSurface(lambda P: np.einsum("ij,ij->i", P - c, P - c) - r * r, lambda P: 2 * (P - c),
                           lambda P: np.broadcast_to(2 * np.eye(3), (len(P), 3, 3)), bound=(c, 1.01 * r),
                           max_hits=2, material=material)


def implicit_cylinder(radius: float = 1.0, height: float = 2.0, material: Material | None = None) -> ImplicitSurface:
    """The cylinder ``x^2 + y^2 - r^2 = 0`` about the z-axis (drawn for ``|z| <= height/2`` by its
    bounding sphere), with gradient ``(2x, 2y, 0)`` and Hessian ``diag(2, 2, 0)`` (Goldman §18.1).

    >>> implicit_cylinder(1.0).normal([[0, 1, 0.3]]).tolist()
    [[0.0, 1.0, 0.0]]
    """
    r = _size(radius, "radius")
    h = _size(height, "height")
    return ImplicitSurface(lambda P: P[:, 0] ** 2 + P[:, 1] ** 2 - r * r,
                           lambda P: np.stack([2 * P[:, 0], 2 * P[:, 1], 0 * P[:, 2]], -1),
                           lambda P: np.broadcast_to(np.diag([2.0, 2.0, 0.0]), (len(P), 3, 3)),
                           bound=((0.0, 0.0, 0.0), float(np.hypot(r, h / 2))), max_hits=2, material=material)


def implicit_torus(R: float = 1.0, r: float = 0.4, material: Material | None = None) -> ImplicitSurface:
    """The torus ``(|P|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2) = 0`` about the z-axis (tube radius ``r``
    around the circle of radius ``R > r``), with its gradient and Hessian (Goldman §18.1).

    >>> implicit_torus(2.0, 0.5).intersect([[5, 0, 0]], [[-1, 0, 0]]).round(9).tolist()
    [2.5]
    """
    R = _size(R, "R")
    r = _size(r, "r")
    if r >= R:
        raise ValueError(f"r must be smaller than R (a ring torus); got R = {R}, r = {r}")

    def f(P):
        s = np.einsum("ij,ij->i", P, P) + R * R - r * r
        return s * s - 4 * R * R * (P[:, 0] ** 2 + P[:, 1] ** 2)

    def grad(P):
        s = np.einsum("ij,ij->i", P, P) + R * R - r * r
        return np.stack([(4 * s - 8 * R * R) * P[:, 0], (4 * s - 8 * R * R) * P[:, 1], 4 * s * P[:, 2]], -1)

    def hess(P):
        s = np.einsum("ij,ij->i", P, P) + R * R - r * r
        out = 8 * P[:, :, None] * P[:, None, :]
        out += (4 * s)[:, None, None] * np.eye(3)
        out[:, 0, 0] -= 8 * R * R
        out[:, 1, 1] -= 8 * R * R
        return out

    return ImplicitSurface(f, grad, hess, bound=((0.0, 0.0, 0.0), 1.01 * (R + r)), samples=128, max_hits=4,
                           material=material)


# -- §18.1 and §18.3: parametric surfaces -------------------------------------------------------------

class ParametricSurface(Surface):
    """The surface ``X(u, v)`` for ``u`` in ``u_range`` and ``v`` in ``v_range`` (Goldman §18.1-18.3),
    following the ray-surface contract of :mod:`goldman_lib.simple_surfaces`; normals are
    ``X_u x X_v`` (§18.2).  Rays are intersected by Newton's method on ``O + t d - X(u, v) = 0`` in
    ``(t, u, v)`` (§18.3), started from the ``starts`` points of a ``grid x grid`` sample of the
    surface nearest each ray (one per stretch of half a grid spacing along the ray, nearest first);
    parameters of a ``periodic`` direction wrap round.  ``hits`` reports the distinct roots Newton
    reached -- every one a true hit, the nearest found first, but a far one may be missed (a renderer
    needs the nearest).

    X: callable ``X(u, v) -> u.shape + (3,)``, vectorised; partials: optional callable
    ``(u, v) -> (X_u, X_v, X_uu, X_uv, X_vv)`` (otherwise central differences).
    """

    def __init__(self, X, u_range=(0.0, 1.0), v_range=(0.0, 1.0), partials=None, periodic=(False, False),
                 grid: int = 24, starts: int = 8, material: Material | None = None):
        self.X = _callable(X, "X")
        self.partials = None if partials is None else _callable(partials, "partials")
        self.u_range = self._range(u_range, "u_range")
        self.v_range = self._range(v_range, "v_range")
        try:
            if len(periodic) != 2:
                raise ValueError
            self.periodic = (bool(periodic[0]), bool(periodic[1]))
        except (TypeError, IndexError, ValueError):
            raise TypeError("periodic must be a pair of booleans (u periodic, v periodic)") from None
        self.grid = as_int(grid, "grid", minimum=2, maximum=200)
        self.starts = as_int(starts, "starts", minimum=1, maximum=16)
        self._set_material(material)
        u, v = self._samples(self.grid)
        self._seed_uv = np.stack([u.ravel(), v.ravel()], -1)
        self._seed_xyz = self.point(u.ravel(), v.ravel())
        g = self._seed_xyz.reshape(self.grid, self.grid, 3)
        self._spacing = float(max(np.linalg.norm(np.diff(g, axis=0), axis=-1).max(),
                                  np.linalg.norm(np.diff(g, axis=1), axis=-1).max()))
        c = self._seed_xyz.mean(axis=0)
        self._bound = (c, float(np.sqrt(((self._seed_xyz - c) ** 2).sum(axis=1)).max()) * 1.05 + 1e-9)

    @staticmethod
    def _range(r, name):
        arr = check_finite(as_float_array(r, name), name)
        if arr.shape != (2,) or not arr[0] < arr[1]:
            raise ValueError(f"{name} must be (low, high) with low < high; got {arr.tolist()}")
        return float(arr[0]), float(arr[1])

    def _samples(self, n):
        u = np.linspace(*self.u_range, n)
        v = np.linspace(*self.v_range, n)
        return np.meshgrid(u, v, indexing="ij")

    def point(self, u, v) -> np.ndarray:
        """``X(u, v)``: ``u.shape + (3,)``."""
        u, v = _uv(u, v)
        return _call(self.X, "X(u, v)", u.shape + (3,), u, v)

    def normal_at(self, u, v) -> np.ndarray:
        """The unit normal ``X_u x X_v / |X_u x X_v|`` at parameters ``(u, v)`` (§18.2)."""
        return parametric_normal(self.X, u, v, self.partials)

    def curvature(self, u, v) -> tuple[np.ndarray, np.ndarray]:
        """``(H, K)`` at parameters ``(u, v)`` (:func:`curvature_parametric`)."""
        return curvature_parametric(self.X, u, v, self.partials)

    @property
    def bounding_sphere(self):
        """A sphere around the sampled surface (5% margin)."""
        return self._bound

    def _wrap(self, u, v):
        for k, (lo, hi) in enumerate((self.u_range, self.v_range)):
            if self.periodic[k]:
                w = hi - lo
                if k == 0:
                    u = lo + np.mod(u - lo, w)
                else:
                    v = lo + np.mod(v - lo, w)
        return u, v

    def _inside(self, u, v, tol=1e-9):
        (ul, uh), (vl, vh) = self.u_range, self.v_range
        su, sv = tol * (uh - ul), tol * (vh - vl)
        return (u >= ul - su) & (u <= uh + su) & (v >= vl - sv) & (v <= vh + sv)

    def _newton(self, o, d):
        """Newton's method on (t, u, v) from the nearest grid points: ``(t (n, k), u, v)``."""
        n, k = len(o), min(self.starts, len(self._seed_xyz))
        if n * len(self._seed_xyz) > _MAX_WORK:
            raise ValueError(f"origins: {n} rays is over the limit of {_MAX_WORK // len(self._seed_xyz):,} per call")
        dn = d / np.linalg.norm(d, axis=1)[:, None]
        rel = self._seed_xyz[None, :, :] - o[:, None, :]                     # (n, m, 3)
        along = np.einsum("nmi,ni->nm", rel, dn)
        dist2 = np.einsum("nmi,nmi->nm", rel, rel) - along ** 2
        dist2 = np.where(along > 0, dist2, np.inf)
        # seeds: grid points within a grid spacing of the ray, nearest along it first (so the first
        # hits are found), then the points nearest the ray
        # (one seed per stretch of half a spacing along the ray, so later hits get seeds too)
        near = dist2 <= self._spacing ** 2
        score = np.where(near, along, np.inf)
        order_all = np.argsort(score, axis=1)
        sa = np.take_along_axis(score, order_all, axis=1)
        new = np.isfinite(sa)
        new[:, 1:] &= (sa[:, 1:] - sa[:, :-1]) > 0.5 * self._spacing
        pick = np.argsort(~new, axis=1, kind="stable")[:, :k]
        order = np.take_along_axis(order_all, pick, axis=1)
        have = np.take_along_axis(new, pick, axis=1)
        fallback = np.argsort(dist2, axis=1)[:, :k]
        best = np.where(have, order, fallback)                              # (n, k)
        u = self._seed_uv[best, 0].ravel()
        v = self._seed_uv[best, 1].ravel()
        oo, dd = np.repeat(o, k, axis=0), np.repeat(d, k, axis=0)
        t = np.einsum("ij,ij->i", self._seed_xyz[best.ravel()] - oo, dd) / np.einsum("ij,ij->i", dd, dd)
        ok = np.ones(len(t), dtype=bool)
        active = np.ones(len(t), dtype=bool)
        for it in range(40):
            a = np.flatnonzero(active & ok)
            if a.size == 0:
                break
            ua, va, ta = u[a], v[a], t[a]
            Xa = _call(self.X, "X(u, v)", (a.size, 3), ua, va)
            G = oo[a] + ta[:, None] * dd[a] - Xa
            if it >= 10:                       # not converging after 10 steps: a seed off any hit; drop it
                far = np.linalg.norm(G, axis=1) > 1e-6 * (1 + np.abs(Xa).max(axis=1))
                ok[a[far]] = False
                keep = ~far
                a, ua, va, ta, G = a[keep], ua[keep], va[keep], ta[keep], G[keep]
                if a.size == 0:
                    break
            Xu, Xv = _first_partials(self.X, ua, va, self.partials)
            J = np.stack([dd[a], -Xu, -Xv], axis=-1)                        # columns: d/dt, d/du, d/dv
            det = np.linalg.det(J)
            good = np.isfinite(det) & (np.abs(det) > 1e-300)
            step = np.zeros_like(G)
            if good.any():
                step[good] = np.linalg.solve(J[good], G[good][..., None])[..., 0]
            ta, ua, va = ta - step[:, 0], ua - step[:, 1], va - step[:, 2]
            ua, va = self._wrap(ua, va)
            fine = good & np.isfinite(ta) & np.isfinite(ua) & np.isfinite(va)
            ok[a] = fine
            t[a], u[a], v[a] = np.where(fine, ta, 0.0), np.where(fine, ua, 0.0), np.where(fine, va, 0.0)
            done = np.all(np.abs(step) <= 1e-14 * (1 + np.abs(np.stack([ta, ua, va], -1))), axis=1)
            active[a[done]] = False
        Xuv = _call(self.X, "X(u, v)", (len(u), 3), u, v)
        residual = np.linalg.norm(oo + t[:, None] * dd - Xuv, axis=1)
        scale = 1.0 + np.abs(Xuv).max(axis=1)
        ok &= (residual <= 1e-9 * scale) & self._inside(u, v)
        t = np.where(ok, t, np.inf)
        return t.reshape(n, k), u.reshape(n, k), v.reshape(n, k)

    def _hits(self, o, d):
        t, _, _ = self._newton(o, d)
        t = np.sort(t, axis=1)
        same = np.zeros_like(t, dtype=bool)
        same[:, 1:] = np.isfinite(t[:, 1:]) & (np.abs(np.diff(t, axis=1)) <= 1e-8 * (1 + np.abs(t[:, 1:])))
        t[same] = np.inf
        return np.sort(t, axis=1)

    def hit(self, origins, directions) -> tuple[np.ndarray, np.ndarray]:
        """The nearest hit ``t > EPS`` per ray (``inf`` on a miss) and the unit normal ``X_u x X_v``
        at the parameters Newton found there (a zero row on a miss)."""
        o, d = rays(origins, directions)
        with np.errstate(all="ignore"):
            t, u, v = self._newton(o, d)
        t = np.where(t > EPS, t, np.inf)
        k = np.argmin(t, axis=1)
        rows = np.arange(len(t))
        best = t[rows, k]
        normals = np.zeros_like(o)
        found = np.isfinite(best)
        if found.any():
            normals[found] = self.normal_at(u[rows, k][found], v[rows, k][found])
        return best, normals

    def parameters(self, points) -> tuple[np.ndarray, np.ndarray]:
        """The parameters ``(u, v)`` of points on the surface (nearest grid point, then Gauss-Newton on
        ``|X(u, v) - P|^2``)."""
        P = as_points(points, "points", dim=3)
        d2 = ((P[:, None, :] - self._seed_xyz[None, :, :]) ** 2).sum(-1)
        best = np.argmin(d2, axis=1)
        u, v = self._seed_uv[best, 0].copy(), self._seed_uv[best, 1].copy()
        with np.errstate(all="ignore"):
            for _ in range(30):
                Xu, Xv, *_ = _partials(self.X, u, v, self.partials)
                r = P - _call(self.X, "X", P.shape, u, v)
                A = np.stack([Xu, Xv], -1)                                   # (n, 3, 2)
                AtA = np.einsum("nik,nil->nkl", A, A)
                step = np.linalg.solve(AtA + 1e-300 * np.eye(2), np.einsum("nik,ni->nk", A, r)[..., None])[..., 0]
                u, v = self._wrap(u + step[:, 0], v + step[:, 1])
                if np.all(np.abs(step) <= 1e-13):
                    break
        return u, v

    def _normal(self, P):
        u, v = self.parameters(P)
        return self.normal_at(u, v)

    def _mesh(self, n, extent):
        positions, triangles, _, _ = self.grid_mesh(n)
        return positions, triangles

    def grid_mesh(self, n: int = 32):
        """A triangle mesh on an ``n x n`` grid of parameters: ``(positions (n*n, 3), triangles, u, v)``
        with each vertex's parameters (for colouring by curvature)."""
        n = as_int(n, "n", minimum=2, maximum=400)
        u, v = self._samples(n)
        positions = self.point(u.ravel(), v.ravel())
        idx = np.arange(n * n).reshape(n, n)
        a, b, c, e = idx[:-1, :-1].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()
        triangles = np.concatenate([np.stack([a, b, c], -1), np.stack([a, c, e], -1)])
        return positions, triangles, u.ravel(), v.ravel()


def parametric_sphere(radius: float = 1.0, material: Material | None = None) -> ParametricSurface:
    """The sphere ``r (cos u cos v, sin u cos v, sin v)``, ``u`` in [0, 2 pi] (longitude, periodic), ``v``
    in (-pi/2, pi/2) (latitude, the poles left out: there ``X_u = 0``) (Goldman §18.1).

    >>> parametric_sphere(2.0).normal_at(0.0, 0.0).round(9).tolist()
    [1.0, 0.0, 0.0]
    """
    r = _size(radius, "radius")

    def X(u, v):
        return r * np.stack([np.cos(u) * np.cos(v), np.sin(u) * np.cos(v), np.sin(v)], -1)

    return ParametricSurface(X, (0.0, 2 * np.pi), (-0.5 * np.pi + 1e-3, 0.5 * np.pi - 1e-3), periodic=(True, False),
                             material=material)


def parametric_cylinder(radius: float = 1.0, height: float = 2.0, material: Material | None = None) -> ParametricSurface:
    """The cylinder ``(r cos u, r sin u, v)`` about the z-axis, ``|v| <= height/2`` (Goldman §18.1).

    >>> parametric_cylinder(1.0).intersect([[3, 0, 0.2]], [[-1, 0, 0]]).round(9).tolist()
    [2.0]
    """
    r = _size(radius, "radius")
    h = _size(height, "height")

    def X(u, v):
        return np.stack([r * np.cos(u), r * np.sin(u), v + 0 * u], -1)

    return ParametricSurface(X, (0.0, 2 * np.pi), (-h / 2, h / 2), periodic=(True, False), material=material)


def parametric_torus(R: float = 1.0, r: float = 0.4, material: Material | None = None) -> ParametricSurface:
    """The torus ``((R + r cos v) cos u, (R + r cos v) sin u, r sin v)``, both angles periodic
    (Goldman §18.1); its Gaussian curvature is ``cos v / (r (R + r cos v))``.

    >>> round(float(parametric_torus(2.0, 0.5).curvature(0.0, 0.0)[1]), 6)       # outer equator: 1/(r (R + r))
    0.8
    """
    R = _size(R, "R")
    r = _size(r, "r")
    if r >= R:
        raise ValueError(f"r must be smaller than R (a ring torus); got R = {R}, r = {r}")

    def X(u, v):
        w = R + r * np.cos(v)
        return np.stack([w * np.cos(u), w * np.sin(u), r * np.sin(v)], -1)

    return ParametricSurface(X, (0.0, 2 * np.pi), (0.0, 2 * np.pi), periodic=(True, True), starts=12,
                             material=material)


def parametric_graph(height, extent: float = 1.0, material: Material | None = None) -> ParametricSurface:
    """The graph ``(u, v, h(u, v))`` of a height function over ``[-extent, extent]^2`` (Goldman §18.1):
    a parametric surface whose normal is ``(-h_u, -h_v, 1)``.

    >>> g = parametric_graph(lambda u, v: u * u - v * v)                 # a saddle
    >>> H, K = g.curvature(0.0, 0.0); round(float(H), 6), round(float(K), 6)
    (0.0, -4.0)
    """
    _callable(height, "height")
    e = _size(extent, "extent")

    def X(u, v):
        return np.stack([u + 0 * v, v + 0 * u, np.asarray(height(u, v), dtype=float) + 0 * u], -1)

    return ParametricSurface(X, (-e, e), (-e, e), material=material)


# -- §18.1-18.2: deformed surfaces --------------------------------------------------------------------

class Deformation:
    """A smooth invertible map ``A`` of space with its inverse and Jacobian (Goldman §18.1): ``forward``,
    ``inverse``: callables ``(n, 3) -> (n, 3)``; ``jacobian``: callable ``(n, 3) -> (n, 3, 3)``,
    ``J[i, j] = dA_i/dx_j`` at the (undeformed) point.  ``growth(R)``: a bound on ``|A(P)| / |P|``
    for ``|P| <= R`` (for bounding spheres).
    """

    def __init__(self, forward, inverse, jacobian, growth=lambda R: 1.0, name: str = "deformation"):
        self.forward = _callable(forward, "forward")
        self.inverse = _callable(inverse, "inverse")
        self.jacobian = _callable(jacobian, "jacobian")
        self.growth = _callable(growth, "growth")
        self.name = str(name)

    def apply(self, points) -> np.ndarray:
        """``A(P)`` for points ``(n, 3)``."""
        P = as_points(points, "points", dim=3)
        return _call(self.forward, "forward", P.shape, P)

    def undo(self, points) -> np.ndarray:
        """``A^{-1}(Q)`` for points ``(n, 3)``."""
        Q = as_points(points, "points", dim=3)
        return _call(self.inverse, "inverse", Q.shape, Q)

    def normals(self, points, normals) -> np.ndarray:
        """The normals at ``A(P)`` of a surface with ``normals`` at ``points`` P: ``J^{-T} n``, unit
        (:func:`deformed_normals`)."""
        P = as_points(points, "points", dim=3)
        try:
            return deformed_normals(_call(self.jacobian, "jacobian at the points", P.shape + (3,), P), normals)
        except ValueError as exc:
            if "jacobians must be invertible" in str(exc):
                raise ValueError("points: the deformation's Jacobian is not invertible there "
                                 "(it flattens the surface)") from None
            raise


def twist(degrees_per_unit: float, axis: str = "z") -> Deformation:
    """The twist about a coordinate axis: the point at height ``h`` along the axis turns about it by
    ``a h`` degrees (our example of a deformation, Goldman §18.1).  It keeps ``h`` and the distance from
    the axis.  axis: ``"x"``, ``"y"`` or ``"z"``.

    >>> twist(90).apply([[1.0, 0.0, 1.0]]).round(12).tolist()
    [[0.0, 1.0, 1.0]]
    >>> twist(90, axis="x").apply([[1.0, 1.0, 0.0]]).round(12).tolist()     # (y, z) turn at x = 1
    [[1.0, 0.0, 1.0]]
    """
    a = np.radians(as_float(degrees_per_unit, "degrees_per_unit"))
    if axis not in ("x", "y", "z"):
        raise ValueError(f"axis must be 'x', 'y' or 'z'; got {axis!r}")
    # coordinates (p, q, h): h along the axis, (p, q) turning counterclockwise seen from +h
    order = {"x": [1, 2, 0], "y": [2, 0, 1], "z": [0, 1, 2]}[axis]
    back = np.argsort(order)

    def turn(P, sign):
        L = P[:, order]
        c, s = np.cos(sign * a * L[:, 2]), np.sin(sign * a * L[:, 2])
        return np.stack([c * L[:, 0] - s * L[:, 1], s * L[:, 0] + c * L[:, 1], L[:, 2]], -1)[:, back]

    def jacobian(P):
        L = P[:, order]
        th = a * L[:, 2]
        c, s = np.cos(th), np.sin(th)
        x, y = L[:, 0], L[:, 1]
        J = np.zeros((len(P), 3, 3))
        J[:, 0, 0], J[:, 0, 1], J[:, 0, 2] = c, -s, a * (-s * x - c * y)
        J[:, 1, 0], J[:, 1, 1], J[:, 1, 2] = s, c, a * (c * x - s * y)
        J[:, 2, 2] = 1.0
        return J[:, back][:, :, back]

    return Deformation(lambda P: turn(P, 1.0), lambda Q: turn(Q, -1.0), jacobian,
                       name=f"twist {np.degrees(a):g}°/unit about {axis}")


def taper(rate: float) -> Deformation:
    """The taper along the z-axis: ``(x, y, z) -> ((1 + k z) x, (1 + k z) y, z)`` (our example of a
    deformation), invertible where ``1 + k z > 0``; used for ``|k z| < 1``.

    >>> taper(0.5).apply([[1.0, 2.0, 1.0]]).tolist()
    [[1.5, 3.0, 1.0]]
    """
    k = as_float(rate, "rate")
    if abs(k) > 0.9:
        raise ValueError(f"rate must be in [-0.9, 0.9] (1 + rate z must stay positive on |z| <= 1); got {k}")

    def forward(P):
        s = 1 + k * P[:, 2]
        return np.stack([s * P[:, 0], s * P[:, 1], P[:, 2]], -1)

    def inverse(Q):
        s = 1 + k * Q[:, 2]
        return np.stack([Q[:, 0] / s, Q[:, 1] / s, Q[:, 2]], -1)

    def jacobian(P):
        s = 1 + k * P[:, 2]
        J = np.zeros((len(P), 3, 3))
        J[:, 0, 0] = J[:, 1, 1] = s
        J[:, 0, 2], J[:, 1, 2] = k * P[:, 0], k * P[:, 1]
        J[:, 2, 2] = 1.0
        return J

    return Deformation(forward, inverse, jacobian, growth=lambda R: 1 + abs(k) * R, name=f"taper {k:g}")


class DeformedSurface(ImplicitSurface):
    """The image ``A(S)`` of an implicit surface ``S: f = 0`` under a :class:`Deformation` ``A``
    (Goldman §18.1-18.2): the implicit surface ``f(A^{-1}(Q)) = 0``, whose gradient at ``Q = A(P)`` is
    ``J^{-T} grad f(P)`` (the inverse transpose of ``A``'s Jacobian at ``P``), so its normals are the
    base surface's normals mapped by the inverse transpose.  Drawn by the implicit intersection.

    >>> s = DeformedSurface(implicit_sphere([0, 0, 0], 1.0), taper(0.5))
    >>> s.intersect([[0, 0, 5]], [[0, 0, -1]]).round(9).tolist()          # the pole stays at z = 1
    [4.0]
    """

    def __init__(self, base: ImplicitSurface, deformation: Deformation, material: Material | None = None):
        if not isinstance(base, ImplicitSurface):
            raise TypeError(f"base must be an ImplicitSurface; got {type(base).__name__}")
        if not isinstance(deformation, Deformation):
            raise TypeError(f"deformation must be a Deformation; got {type(deformation).__name__}")
        self.base, self.deformation = base, deformation
        c, r = base.bounding_sphere
        reach = float(np.linalg.norm(c)) + r
        radius = reach * float(deformation.growth(reach)) * 1.01

        def f(Q):
            return _call(base.f, "f", (len(Q),), _call(deformation.inverse, "inverse", Q.shape, Q))

        def grad(Q):
            P = _call(deformation.inverse, "inverse", Q.shape, Q)
            J = _call(deformation.jacobian, "jacobian", Q.shape + (3,), P)
            g = _gradient(base.f, base.grad, P)
            return np.linalg.solve(np.swapaxes(J, 1, 2), g[..., None])[..., 0]

        super().__init__(f, grad, None, bound=((0.0, 0.0, 0.0), radius), samples=base.samples,
                         max_hits=base.max_hits, material=material if material is not None else base.material)


class AffineInstance(Surface):
    """The image of a surface under the affine map ``A(P) = P M + shift`` (row vectors, as in chapter
    13), intersected by mapping the ray back (Goldman §18.3.3): ``A^{-1}(O + t d) = A^{-1}(O) + t (d M^{-1})``
    is again a ray, *with the same parameter* ``t``, so the base surface's own intersection answers for
    the image (one sphere, many ellipsoids: instancing).  Normals are the base's mapped by the inverse
    transpose (§18.2).  base: any :class:`~goldman_lib.simple_surfaces.Surface`; M: an invertible 3x3
    matrix; shift: (3,).

    normal_map: ``"inverse transpose"`` (the default, right: ``n' = n (M^{-1})^T`` as a row) or
    ``"linear part"``, the classic slip of mapping the normal like a tangent, ``n' = n M`` (unit
    length): kept to show what goes wrong -- under a shear or a non-uniform scale such a "normal" is
    no longer perpendicular to the surface (``(n M) . (t M) != n . t = 0`` unless ``M`` is a rotation
    times a scale), so shading that uses it is wrong.  :meth:`normal_error` measures the angle.
    Raises ValueError for any other value.

    >>> e = AffineInstance(Sphere([0, 0, 0], 1.0), np.diag([3.0, 2.0, 1.0]), [0, 0, 0])
    >>> e.hits([[-5, 0, 0], [0, 0, -5]], [[1, 0, 0], [0, 0, 1]]).round(12).tolist()
    [[2.0, 8.0], [4.0, 6.0]]
    """

    #: The two ways of mapping normals :class:`AffineInstance` knows (the first is the right one).
    NORMAL_MAPS = ("inverse transpose", "linear part")

    def __init__(self, base: Surface, M, shift=(0.0, 0.0, 0.0), material: Material | None = None,
                 normal_map: str = "inverse transpose"):
        if not isinstance(normal_map, str) or normal_map not in self.NORMAL_MAPS:
            raise ValueError(f"normal_map must be one of {self.NORMAL_MAPS}; got {normal_map!r}")
        self.normal_map = normal_map
        if not isinstance(base, Surface):
            raise TypeError(f"base must be a goldman_lib.simple_surfaces.Surface; got {type(base).__name__}")
        M = check_finite(as_float_array(M, "M"), "M")
        if M.shape != (3, 3):
            raise ValueError(f"M must be a 3x3 matrix; got shape {M.shape}")
        scale = float(np.abs(M).max())
        if not scale > 0 or abs(np.linalg.det(M / scale)) < 1e-12:
            raise ValueError("M must be invertible (a singular M flattens the surface and has no inverse ray)")
        self.base, self.M = base, M
        self.shift = as_points(shift, "shift", ndim=1, dim=3)
        self.M_inv = np.linalg.inv(M)
        self._set_material(material if material is not None else base.material)

    def apply(self, points) -> np.ndarray:
        """``A(P) = P M + shift`` for points ``(n, 3)`` of the base surface: their images.

        >>> AffineInstance(Sphere([0, 0, 0], 1.0), np.diag([3.0, 2.0, 1.0]), [0, 0, 1]).apply([[1, 1, 1]]).tolist()
        [[3.0, 2.0, 2.0]]
        """
        P = np.atleast_2d(as_points(points, "points", ndim=None, dim=3))
        return P @ self.M + self.shift

    def undo(self, points) -> np.ndarray:
        """``A^{-1}(Q) = (Q - shift) M^{-1}`` for points ``(n, 3)``."""
        Q = np.atleast_2d(as_points(points, "points", ndim=None, dim=3))
        return (Q - self.shift) @ self.M_inv

    def _hits(self, o, d):
        return self.base.hits((o - self.shift) @ self.M_inv, d @ self.M_inv)

    def _normal(self, P):
        # Q = P M + s, so F(Q) = f((Q - s) M^{-1}) and, as rows, grad F(Q) = grad f(P) (M^{-1})^T
        n = self.base.normal((P - self.shift) @ self.M_inv)
        if self.normal_map == "linear part":           # the slip: the normal moved like a tangent
            m = n @ self.M
            return m / np.linalg.norm(m, axis=-1, keepdims=True)
        return n @ self.M_inv.T

    def normal_error(self, points) -> np.ndarray:
        """The angle in degrees, at points ``(n, 3)`` of the image, between this instance's normal
        and the true normal (the inverse transpose's; Goldman §18.2): 0 for the default
        ``normal_map``; for ``"linear part"``, how far the tangent-mapped "normal" leans off the
        perpendicular of the surface.

        >>> from goldman_lib.simple_surfaces import Sphere
        >>> shear = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 1.0]]        # x' = x + z
        >>> wrong = AffineInstance(Sphere([0, 0, 0], 1.0), shear, normal_map="linear part")
        >>> Q = wrong.M[0] * 1.0                                                # the image of (1, 0, 0)
        >>> round(float(wrong.normal_error([Q])[0]), 6)                         # (1, 0, 0) M^-T = (1, 0, -1)
        45.0
        """
        from goldman_lib.vectors import angle_between

        Q = np.atleast_2d(as_points(points, "points", ndim=None, dim=3))
        right = self.base.normal((Q - self.shift) @ self.M_inv) @ self.M_inv.T
        return np.atleast_1d(angle_between(self.normal(Q), right))

    def _contains(self, P):
        return self.base.contains((P - self.shift) @ self.M_inv)

    @property
    def bounding_sphere(self):
        b = self.base.bounding_sphere
        if b is None:
            return None
        c, r = b
        return np.asarray(c, dtype=float) @ self.M + self.shift, float(r) * float(np.linalg.norm(self.M, 2))

    def _mesh(self, n, extent):
        positions, triangles = self.base.mesh(n, extent)
        return positions @ self.M + self.shift, triangles


# -- §18.1: procedural surfaces -------------------------------------------------------------------------

def fractal_heights(level: int, roughness: float = 0.5, rng=None, amplitude: float = 1.0) -> np.ndarray:
    """A fractal terrain by random midpoint displacement (the diamond-square algorithm; our example of
    a procedural surface, Goldman §18.1): a ``(2^level + 1)``-square grid of heights, the corners 0,
    each new midpoint the average of its neighbours plus a random offset whose size shrinks by
    ``roughness`` per level (``roughness = 2^{-H}``, ``H`` the Hurst exponent).

    >>> h = fractal_heights(3, 0.5, rng=1); h.shape, float(h[0, 0])
    ((9, 9), 0.0)
    """
    n = within_budget(level, "level", cost=lambda k: (2 ** k + 1) ** 2, what="the height field",
                      unit="heights", limit=2 ** 22, minimum=0)
    rough = as_float(roughness, "roughness", positive=True)
    if rough > 1:
        raise ValueError(f"roughness must be in (0, 1]; got {rough}")
    amp = as_float(amplitude, "amplitude")
    if abs(amp) > _MAX_SIZE:
        raise ValueError(f"amplitude must be at most {_MAX_SIZE:g} in magnitude; got {amp:g}")
    gen = rng if isinstance(rng, np.random.Generator) else np.random.default_rng(
        None if rng is None else as_int(rng, "rng", minimum=0))
    size = 2 ** n + 1
    h = np.zeros((size, size))
    step, scale = size - 1, amp
    while step > 1:
        half = step // 2
        # diamond step: centres of squares
        c = (h[0:-1:step, 0:-1:step] + h[step::step, 0:-1:step] + h[0:-1:step, step::step] + h[step::step, step::step]) / 4
        h[half::step, half::step] = c + scale * gen.uniform(-1, 1, c.shape)
        # square step: midpoints of edges (average of the available neighbours)
        for i0, j0 in ((0, half), (half, 0)):
            ii, jj = np.meshgrid(np.arange(i0, size, step), np.arange(j0, size, step), indexing="ij")
            total = np.zeros(ii.shape)
            count = np.zeros(ii.shape)
            for di, dj in ((-half, 0), (half, 0), (0, -half), (0, half)):
                a, b = ii + di, jj + dj
                ok = (a >= 0) & (a < size) & (b >= 0) & (b < size)
                total[ok] += h[a[ok], b[ok]]
                count[ok] += 1
            h[ii, jj] = total / count + scale * gen.uniform(-1, 1, ii.shape)
        h[0, 0] = h[0, -1] = h[-1, 0] = h[-1, -1] = 0.0
        step, scale = half, scale * rough
    return h


def height_field_mesh(heights, size: float = 2.0) -> tuple[np.ndarray, np.ndarray]:
    """The triangle mesh of a height field over the square ``[-size/2, size/2]^2``:
    ``(positions (m*n, 3), triangles (2 (m-1)(n-1), 3))`` (Goldman §18.1, a procedural surface drawn).

    >>> p, t = height_field_mesh(np.zeros((3, 3))); p.shape, t.shape
    ((9, 3), (8, 3))
    """
    h = as_float_array(heights, "heights")
    if h.ndim != 2 or min(h.shape) < 2:
        raise ValueError(f"heights must be a 2D grid of at least 2 x 2; got shape {h.shape}")
    check_finite(h, "heights")
    s = as_float(size, "size", positive=True)
    m, n = h.shape
    x, y = np.meshgrid(np.linspace(-s / 2, s / 2, m), np.linspace(-s / 2, s / 2, n), indexing="ij")
    positions = np.stack([x.ravel(), y.ravel(), h.ravel()], -1)
    idx = np.arange(m * n).reshape(m, n)
    a, b, c, e = idx[:-1, :-1].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()
    return positions, np.concatenate([np.stack([a, b, c], -1), np.stack([a, c, e], -1)])

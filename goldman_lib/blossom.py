"""Blossoming: the polar form of a polynomial curve (Goldman, chapter 26).

The blossom of a degree-n polynomial curve ``P(t)`` is the unique function ``p(u_1, ..., u_n)``
of n parameters that is

- **symmetric**: the order of the arguments does not matter;
- **multiaffine**: affine in each argument when the others are fixed;
- **diagonal**: ``p(t, ..., t) = P(t)``.

Everything about Bezier curves reads off the blossom: the control points are
``P_k = p(0, ..., 0, 1, ..., 1)`` (n-k zeros, k ones, §26.3), the control points over any
interval ``[a, b]`` are ``p(a, ..., a, b, ..., b)`` (so subdivision, §26.3), and the points of
the de Casteljau pyramid are blossom values.  The *homogeneous* blossom (§26.4) takes pairs
``(t, w)``; with the argument ``delta = (1, 0)`` it gives derivatives:
``P^(r)(t) = n!/(n-r)! p((t,1)^(n-r), delta^r)``.  It also converts between the monomial and the
Bezier forms of a polynomial.

Functions on arrays, as everywhere in ``goldman_lib``: control points are ``(n+1, d)`` rows
(coordinates in the last axis); blossom arguments are ``(..., n)`` and the result's leading shape
follows them.

>>> blossom([[0, 0], [1, 2], [2, 0]], [0.5, 0.5])   # the diagonal: the curve at t = 1/2
array([1., 1.])
>>> blossom([[0, 0], [1, 2], [2, 0]], [0, 1])       # the control point P_1
array([1., 2.])
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib.kernels import pyramids
from goldman_lib.validation import as_float, as_int, as_parameter, as_points, finite_result

__all__ = ["blossom", "blossom_steps", "control_points_on_interval", "subdivide_by_blossom",
           "homogeneous_blossom", "derivative_by_blossom", "monomial_to_bezier", "bezier_to_monomial"]

#: Above this degree the binomial coefficients of the conversions overflow a float.
_MAX_CONVERSION_DEGREE = 1000


def _ctrl(ctrl, name: str = "ctrl") -> np.ndarray:
    return as_points(ctrl, name, ndim=2)


def _args(args, n: int, name: str = "args") -> np.ndarray:
    u = as_parameter(args, name)
    if u.ndim == 0 or u.shape[-1] != n:
        raise ValueError(f"{name} must have shape (..., n) with n = {n} (the degree of ctrl) arguments in the last axis; "
                         f"got shape {u.shape}")
    return u


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def blossom(ctrl, args) -> np.ndarray:
    """The blossom ``p(u_1, ..., u_n)`` of a Bezier curve, by the de Casteljau algorithm with a different parameter at each level (Goldman §26.2).

    Level r of the pyramid combines neighbours with ``(1 - u_r) P_j + u_r P_{j+1}``; with all
    ``u_r = t`` this is the ordinary de Casteljau algorithm, which is why the blossom's diagonal
    is the curve.  The result is symmetric and affine in each argument.

    ctrl: (n+1, d) control points.  args: (..., n), the n arguments in the last axis (any real
    values; outside [0, 1] extrapolates).  Returns ``args.shape[:-1] + (d,)``.
    Raises ValueError if args does not end in n = degree arguments, for a bad ctrl, or for
    non-finite values; TypeError if not numeric.

    >>> P = [[0, 0], [1, 3], [3, 3], [4, 0]]
    >>> blossom(P, [0, 0, 1]), blossom(P, [0.2, 0.5, 0.9]) - blossom(P, [0.9, 0.2, 0.5])
    (array([1., 3.]), array([0., 0.]))
    """
    P = _ctrl(ctrl)
    n = P.shape[0] - 1
    U = _args(args, n)
    lead = U.shape[:-1]
    out = pyramids.casteljau_blossom(P, U.reshape(math.prod(lead), n)).reshape(lead + (P.shape[1],))
    return finite_result(out, "args", None)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def blossom_steps(ctrl, args) -> list[np.ndarray]:
    """Every level of the blossom's de Casteljau-like pyramid for one set of arguments (Goldman §26.3).

    Level r holds the n+1-r points ``p(u_1, ..., u_r, 0^(n-r-k), 1^k)``, k = 0..n-r: each point
    of the diagram is itself a blossom value, and level 0 is the control polygon
    ``p(0^(n-k), 1^k) = P_k``.

    ctrl: (n+1, d).  args: (n,).  Returns a list of n+1 arrays of shapes (n+1, d), ..., (1, d).
    Raises ValueError if args is not (n,), and as :func:`blossom`.

    >>> [lvl.tolist() for lvl in blossom_steps([[0, 0], [1, 2], [2, 0]], [0.5, 1.0])]
    [[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], [[0.5, 1.0], [1.5, 1.0]], [[1.5, 1.0]]]
    """
    P = _ctrl(ctrl)
    n = P.shape[0] - 1
    U = _args(args, n)
    if U.ndim != 1:
        raise ValueError(f"args must have shape ({n},) for blossom_steps; got shape {U.shape}")
    levels = pyramids.casteljau_levels(P, U)
    return [levels[0]] + [finite_result(cur, "args", None) for cur in levels[1:]]


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def control_points_on_interval(ctrl, a, b) -> np.ndarray:
    """The Bezier control points of the same curve over the interval ``[a, b]``: ``p(a^(n-k), b^k)`` (Goldman §26.3).

    The curve Q with these control points satisfies ``Q(s) = P(a + (b - a) s)``.  With
    ``[0, t]`` and ``[t, 1]`` this is subdivision; with an interval beyond [0, 1] it is
    extrapolation; with a > b the curve is traversed backwards.

    ctrl: (n+1, d).  a, b: finite scalars.  Returns (n+1, d).
    Raises ValueError for a bad ctrl, a non-scalar, non-finite a or b, or an interval so far from
    [0, 1] that the control points overflow float64.

    >>> control_points_on_interval([[0, 0], [1, 2], [2, 0]], 0.0, 0.5).tolist()
    [[0.0, 0.0], [0.5, 1.0], [1.0, 1.0]]
    """
    P = _ctrl(ctrl)
    n = P.shape[0] - 1
    a = as_float(a, "a")
    b = as_float(b, "b")
    k = np.arange(n + 1)
    U = np.where(np.arange(n)[None, :] < (n - k)[:, None], a, b)   # row k: a^(n-k) b^k
    far = "a" if abs(a) >= abs(b) else "b"
    return finite_result(pyramids.casteljau_blossom(P, U.reshape(n + 1, n)), far, a if far == "a" else b)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def subdivide_by_blossom(ctrl, t=0.5) -> tuple[np.ndarray, np.ndarray]:
    """Split a Bezier curve at ``t`` from its blossom: ``p(0^(n-k), t^k)`` and ``p(t^(n-k), 1^k)`` (Goldman §26.3).

    The same two control polygons as the de Casteljau subdivision of §25.2 (they are the left
    and right edges of the pyramid, and the blossom names every point of the pyramid).

    ctrl: (n+1, d).  t: finite scalar.  Returns ``(left, right)``, each (n+1, d).
    Raises as :func:`control_points_on_interval`.

    >>> left, right = subdivide_by_blossom([[0, 0], [1, 2], [2, 0]], 0.5)
    >>> right.tolist()
    [[1.0, 1.0], [1.5, 1.0], [2.0, 0.0]]
    """
    t = as_float(t, "t")
    P = _ctrl(ctrl)
    n = P.shape[0] - 1
    k = np.arange(n + 1)
    halves = []
    for a, b in ((0.0, t), (t, 1.0)):
        U = np.where(np.arange(n)[None, :] < (n - k)[:, None], a, b)
        halves.append(finite_result(pyramids.casteljau_blossom(P, U.reshape(n + 1, n)), "t", t))
    return halves[0], halves[1]


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def homogeneous_blossom(ctrl, args) -> np.ndarray:
    """The homogeneous blossom ``p((t_1, w_1), ..., (t_n, w_n))`` of a Bezier curve (Goldman §26.4).

    The curve is homogenised: ``P(t, w) = sum_k C(n, k) t^k (w - t)^(n-k) P_k`` with the control
    points taken as mass points ``(P_k, 1)``.  Its blossom is computed by the de Casteljau
    recurrence ``(w_r - t_r) P_j + t_r P_{j+1}`` at level r.  The result is a mass point
    ``(w P, w)`` with mass ``w = w_1 ... w_n``: for pairs ``(t, 1)`` it is the ordinary blossom
    with mass 1; one argument ``delta = (1, 0)`` gives mass 0, a vector, and
    ``n p((t,1)^(n-1), delta) = P'(t)`` (see :func:`derivative_by_blossom`).

    ctrl: (n+1, d).  args: (..., n, 2), the pairs ``(t, w)`` along the last two axes.
    Returns ``args.shape[:-2] + (d+1,)``: the coordinates times the mass, then the mass.
    Raises ValueError if args is not (..., n, 2), and as :func:`blossom`.

    >>> homogeneous_blossom([[0, 0], [1, 2], [2, 0]], [[0.5, 1], [0.5, 1]])   # P(1/2), mass 1
    array([1., 1., 1.])
    >>> homogeneous_blossom([[0, 0], [1, 2], [2, 0]], [[0.5, 1], [1, 0]])     # P'(1/2) / 2, mass 0
    array([1., 0., 0.])
    """
    P = _ctrl(ctrl)
    n = P.shape[0] - 1
    A = as_parameter(args, "args")
    if A.ndim < 2 or A.shape[-2:] != (n, 2):
        raise ValueError(f"args must have shape (..., {n}, 2): n = {n} (the degree of ctrl) pairs (t, w); "
                         f"got shape {A.shape}")
    lead = A.shape[:-2]
    A = A.reshape(math.prod(lead), n, 2)
    M = np.concatenate([P, np.ones((n + 1, 1))], axis=1)           # mass points (P_k, 1)
    cur = np.broadcast_to(M, (A.shape[0],) + M.shape)
    for r in range(n):
        t = A[:, r, 0, None, None]
        cur = pyramids.casteljau_level(cur, t, s=A[:, r, 1, None, None] - t, axis=1)   # (w - t) P_j + t P_{j+1}
    return finite_result(cur[:, 0].reshape(lead + (P.shape[1] + 1,)), "args", None)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported as a ValueError naming the input
def derivative_by_blossom(ctrl, t, order=1) -> np.ndarray:
    """The ``order``-th derivative of a Bezier curve from its homogeneous blossom (Goldman §26.4).

    ``P^(r)(t) = n!/(n-r)! p((t,1)^(n-r), delta^r)`` with ``delta = (1, 0)``: differentiating the
    diagonal ``P(t) = p((t,1), ..., (t,1))`` in t differentiates each of the n symmetric slots,
    and the derivative of the pair ``(t, 1)`` is ``delta``.  An order above the degree gives 0.

    ctrl: (n+1, d).  t: scalar or array.  order: int >= 0.  Returns ``t.shape + (d,)``.
    Raises TypeError if order is not an integer, ValueError if it is negative, and as
    :func:`blossom`.

    >>> derivative_by_blossom([[0, 0], [1, 2], [2, 0]], 0.5)
    array([2., 0.])
    """
    P = _ctrl(ctrl)
    t = as_parameter(t, "t")
    order = as_int(order, "order", minimum=0)
    n, d = P.shape[0] - 1, P.shape[1]
    if order > n:
        return np.zeros(t.shape + (d,))
    tf = t.reshape(-1)
    A = np.zeros((tf.shape[0], n, 2))
    A[:, : n - order, 0] = tf[:, None]
    A[:, : n - order, 1] = 1.0
    A[:, n - order:, 0] = 1.0                 # delta = (1, 0)
    try:
        value = homogeneous_blossom(P, A)[:, :d] * float(math.perm(n, order))
    except ValueError:
        value = np.full((tf.shape[0], d), np.inf)
    return finite_result(value.reshape(t.shape + (d,)), "t", t)


def _coeff_array(x, name: str) -> tuple[np.ndarray, bool]:
    arr = as_points(x, name, ndim=None)
    if arr.ndim == 1:
        return arr[:, None], True
    if arr.ndim != 2:
        raise ValueError(f"{name} must have shape (n+1,) or (n+1, d); got shape {arr.shape}")
    return arr, False


def _check_conversion_degree(n: int, name: str) -> None:
    if n > _MAX_CONVERSION_DEGREE:
        raise ValueError(f"{name} must have degree <= {_MAX_CONVERSION_DEGREE} (binomial coefficients overflow); "
                         f"got degree {n}")


def monomial_to_bezier(coeffs) -> np.ndarray:
    """The Bezier control points of the polynomial ``sum_j a_j t^j`` (Goldman §26.4).

    The blossom of ``t^j`` in degree n is the elementary symmetric function of the arguments
    divided by ``C(n, j)``, and at ``(0^(n-k), 1^k)`` it is ``C(k, j) / C(n, j)``; so
    ``P_k = sum_{j<=k} C(k, j) / C(n, j) a_j``.

    coeffs: (n+1,) or (n+1, d), the coefficients ``a_0, ..., a_n`` (lowest degree first, as in
    ``numpy.polynomial.Polynomial``); a 1-D input is a scalar polynomial.
    Returns the control points, the same shape as coeffs.
    Raises ValueError for non-finite values, a bad shape, or a degree above 1000.

    >>> monomial_to_bezier([1.0, 2.0, 3.0])      # 1 + 2t + 3t^2
    array([1., 2., 6.])
    """
    a, flat = _coeff_array(coeffs, "coeffs")
    n = a.shape[0] - 1
    _check_conversion_degree(n, "coeffs")
    M = np.zeros((n + 1, n + 1))
    for k in range(n + 1):
        for j in range(k + 1):
            M[k, j] = math.comb(k, j) / math.comb(n, j)
    P = M @ a
    return P[:, 0] if flat else P


def bezier_to_monomial(ctrl) -> np.ndarray:
    """The monomial coefficients ``a_j`` of a Bezier curve: ``a_j = C(n, j) Delta^j P_0`` (Goldman §26.4).

    The j-th derivative at 0 is ``n!/(n-j)! Delta^j P_0`` (the blossom ``p(0^(n-j), delta^j)``),
    and ``a_j = P^(j)(0) / j!``.

    ctrl: (n+1,) or (n+1, d) control points (1-D: a scalar polynomial).
    Returns the coefficients ``a_0, ..., a_n``, the same shape as ctrl.
    Raises ValueError for non-finite values, a bad shape, or a degree above 1000.

    >>> bezier_to_monomial([1.0, 2.0, 6.0])
    array([1., 2., 3.])
    """
    P, flat = _coeff_array(ctrl, "ctrl")
    n = P.shape[0] - 1
    _check_conversion_degree(n, "ctrl")
    a = np.empty_like(P)
    D = P
    for j in range(n + 1):
        a[j] = math.comb(n, j) * D[0]
        D = np.diff(D, axis=0)
    return a[:, 0] if flat else a

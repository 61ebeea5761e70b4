"""Real roots of polynomials (Goldman §19.2-19.7): what a ray meets a surface at.

A ray ``P(t) = origin + t direction`` substituted into a surface's implicit equation gives a
polynomial in t: a quadratic for the quadrics (§19.4-19.5), a quartic for the torus (§19.6), degree
up to :data:`MAX_DEGREE` for a surface of revolution (§19.7).  :func:`quadratic_roots` solves
quadratics without cancellation; :func:`real_roots` solves stacks of polynomials of any degree up
to :data:`MAX_DEGREE` (closed forms for degrees 2 and 4, companion matrices otherwise).  These are the
checked public functions; the surfaces of :mod:`goldman_lib.simple_surfaces` call the unchecked
kernels of :mod:`goldman_lib.kernels.roots` per ray.

>>> real_roots([1, -3, 2]).tolist()
[[1.0, 2.0]]
"""

from __future__ import annotations

import numpy as np

from goldman_lib.kernels import roots as kernels
from goldman_lib.validation import as_float_array, check_finite

__all__ = ["MAX_DEGREE", "quadratic_roots", "real_roots"]


#: The highest degree :func:`real_roots` solves (a profile of degree 6 gives degree 12 along a ray).
MAX_DEGREE = 12


def quadratic_roots(a, b, c) -> np.ndarray:
    """The real roots of ``a t^2 + b t + c = 0`` per entry (Goldman §19.4), sorted, ``inf``-padded: ``(N, 2)``.

    Computed without cancellation (``q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2``, roots ``q/a`` and
    ``c/q``); where ``a = 0`` the single root ``-c/b``; no real root gives ``[inf, inf]``.

    >>> quadratic_roots([1.0, 1.0, 0.0], [-3.0, 0.0, 2.0], [2.0, 1.0, -4.0]).tolist()
    [[1.0, 2.0], [inf, inf], [2.0, inf]]
    """
    a, b, c = (check_finite(as_float_array(x, name), name) for x, name in ((a, "a"), (b, "b"), (c, "c")))
    try:
        a, b, c = np.broadcast_arrays(a, b, c)
    except ValueError:
        raise ValueError(f"a, b and c must have the same shape; got {a.shape}, {b.shape} and {c.shape}") from None
    return kernels.quadratic_roots(a, b, c)


def real_roots(coefficients) -> np.ndarray:
    """The real roots of many polynomials at once (Goldman §19.6: the torus quartic, §19.7): quadratics
    and quartics in closed form (the stable quadratic formula; Ferrari's method after removing the
    cubic term), other degrees by the eigenvalues of each companion matrix (``numpy.linalg.eigvals``
    on a stack); roots polished by Newton's method.  Sorted ascending, ``inf``-padded: ``(N, n)``.

    coefficients: ``(N, n+1)`` (or ``(n+1,)`` for one), highest degree first as ``numpy.roots``
    takes them, ``1 <= n <=`` :data:`MAX_DEGREE`.  Leading zeros lower a row's degree (a zero row has
    no roots).  The closed forms decide real or not by the sign of their discriminants; from the
    eigenvalues a root counts as real when its imaginary part is below ``1e-7`` of its size.  A ray
    exactly tangent to a surface gives a double root; rounding may turn it into a near miss.

    >>> real_roots([[1, 0, -5, 0, 4], [1, 0, 1, 0, 0]]).tolist()    # (t^2-1)(t^2-4); t^2 (t^2+1)
    [[-2.0, -1.0, 1.0, 2.0], [0.0, 0.0, inf, inf]]
    """
    c = check_finite(as_float_array(coefficients, "coefficients"), "coefficients")
    if c.ndim == 1:
        c = c[None, :]
    if c.ndim != 2 or not 2 <= c.shape[1] <= MAX_DEGREE + 1:
        raise ValueError(f"coefficients must have shape (N, n+1) with 1 <= n <= {MAX_DEGREE}; got shape {c.shape}")
    scale = np.abs(c).max(axis=1, keepdims=True)
    with np.errstate(all="ignore"):
        return kernels.polynomial_roots(np.divide(c, scale, out=np.zeros_like(c), where=scale > 0))

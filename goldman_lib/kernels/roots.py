"""Roots: real roots of polynomials, many at once (Goldman §19.2-19.7), unchecked.

:func:`quadratic_roots` (the stable quadratic formula), :func:`depressed_quartic_roots` (Ferrari's
method) and :func:`polynomial_roots` (closed forms for degrees 2 and 4, companion matrices for the
others, Newton polishing).  The hot path of the ray tracer: every quadric, the torus and the surface
of revolution of :mod:`goldman_lib.simple_surfaces` call them per ray, on arrays they checked once;
:func:`goldman_lib.roots.quadratic_roots` and :func:`goldman_lib.roots.real_roots` are the checked
public functions over them.  Nothing here checks its input.
"""

from __future__ import annotations

import numpy as np

__all__ = ["quadratic_roots", "polynomial_roots", "depressed_quartic_roots"]


def quadratic_roots(a, b, c) -> np.ndarray:
    """The real roots of ``a t^2 + b t + c = 0`` per entry of arrays of one shape (Goldman §19.4),
    sorted, ``inf``-padded: ``shape + (2,)``.  Without cancellation: ``q = -(b + sign(b) sqrt(b^2 -
    4ac)) / 2``, roots ``q/a`` and ``c/q``; where ``a = 0`` the single root ``-c/b``.

    >>> quadratic_roots(np.array([1.0]), np.array([-3.0]), np.array([2.0])).tolist()
    [[1.0, 2.0]]
    """
    with np.errstate(all="ignore"):
        disc = b * b - 4 * a * c
        root = np.sqrt(np.maximum(disc, 0.0))
        q = -0.5 * (b + np.where(b >= 0, root, -root))
        t1 = np.where(q != 0, q / a, 0.0)
        t2 = np.where(q != 0, c / q, 0.0)
        linear = a == 0
        t_lin = np.where(b != 0, -c / b, np.inf)
        out = np.stack([np.where(linear, t_lin, np.minimum(t1, t2)),
                        np.where(linear, np.inf, np.maximum(t1, t2))], axis=-1)
        out[(disc < 0) & ~linear] = np.inf
        out[~np.isfinite(out)] = np.inf
    return np.sort(out, axis=-1)


def polynomial_roots(c: np.ndarray) -> np.ndarray:
    """The real roots of polynomials with finite, row-scaled coefficients ``(N, n+1)`` (highest degree
    first; Goldman §19.6-19.7): ``(N, n)`` sorted, ``inf``-padded.  Degree 2 by the quadratic formula,
    degree 4 by Ferrari's method, others by companion-matrix eigenvalues; Newton-polished.

    >>> polynomial_roots(np.array([[1.0, 0.0, -5.0, 0.0, 4.0]])).tolist()
    [[-2.0, -1.0, 1.0, 2.0]]
    """
    N, n = c.shape[0], c.shape[1] - 1
    out = np.full((N, n), np.inf)
    if N == 0:
        return out
    big = np.abs(c).max(axis=1)
    lead = np.argmax(np.abs(c) > 1e-13 * big[:, None], axis=1)      # index of the first non-negligible coefficient
    lead[big == 0] = n
    for first in np.unique(lead):
        degree = n - first
        rows = np.flatnonzero(lead == first)
        if degree <= 0:
            continue
        p = c[rows, first:] / c[rows, first:first + 1]               # monic, degree `degree`
        if degree == 2:                                              # closed forms: quadratic, and Ferrari
            out[rows, :2] = quadratic_roots(np.ones(len(rows)), p[:, 1], p[:, 2])
            continue
        if degree == 4:
            shift = p[:, 1] / 4                                      # x = s - c3/4 removes the cubic term
            a, b, cc, dd = p[:, 1], p[:, 2], p[:, 3], p[:, 4]
            pd = b - 3 * a * a / 8
            qd = cc - a * b / 2 + a ** 3 / 8
            rd = dd - a * cc / 4 + a * a * b / 16 - 3 * a ** 4 / 256
            x = depressed_quartic_roots(pd, qd, rd) - shift[:, None]
            for _ in range(2):                                       # Newton on the quartic as given
                f = (((x + a[:, None]) * x + b[:, None]) * x + cc[:, None]) * x + dd[:, None]
                df = ((4 * x + 3 * a[:, None]) * x + 2 * b[:, None]) * x + cc[:, None]
                step = np.divide(f, df, out=np.zeros_like(f), where=np.isfinite(x) & (df != 0))
                x = np.where(np.isfinite(step) & (np.abs(step) < 1e-3 * (1 + np.abs(x))), x - step, x)
            out[rows, :4] = np.where(np.isfinite(x), x, np.inf)
            continue
        if degree == 1:
            roots = -p[:, 1:2] + 0j
        else:
            comp = np.zeros((len(rows), degree, degree))
            comp[:, 0, :] = -p[:, 1:]
            comp[:, np.arange(1, degree), np.arange(degree - 1)] = 1.0
            roots = np.linalg.eigvals(comp)
        x = roots.real.copy()
        for _ in range(3):                                           # Newton on the real parts
            f = np.ones_like(x) * p[:, :1]
            df = np.zeros_like(x)
            for k in range(1, degree + 1):
                df = df * x + f
                f = f * x + p[:, k:k + 1]
            step = np.divide(f, df, out=np.zeros_like(f), where=df != 0)
            x = np.where(np.isfinite(step) & (np.abs(step) < 1e-3 * (1 + np.abs(x))), x - step, x)
        real = np.abs(roots.imag) <= 1e-7 * (1 + np.abs(roots.real))
        vals = np.sort(np.where(real & np.isfinite(x), x, np.inf), axis=1)
        out[rows, :degree] = vals
    return np.sort(out, axis=1) + 0.0                               # no -0.0


def depressed_quartic_roots(p, q, r) -> np.ndarray:
    """Real roots of ``s^4 + p s^2 + q s + r = 0`` per entry by Ferrari's method, polished by Newton's
    method on the quartic: ``(N, 4)`` sorted, ``inf``-padded.  The largest root ``m >= 0`` of the
    resolvent cubic ``8 m^3 + 8 p m^2 + (2 p^2 - 8 r) m - q^2 = 0`` (closed form: Cardano or the
    trigonometric form, then Newton) splits the quartic into the two quadratics
    ``s^2 -+ sqrt(2m) s + p/2 + m +- q / (2 sqrt(2m)) = 0``; where ``m = 0`` (so ``q = 0``) it is the
    quadratic ``u^2 + p u + r = 0`` in ``u = s^2`` (Goldman §19.6, the torus).

    >>> depressed_quartic_roots(np.array([-5.0]), np.array([0.0]), np.array([4.0])).tolist()
    [[-2.0, -1.0, 1.0, 2.0]]
    """
    a, b, c = p, p * p / 4 - r, -q * q / 8                       # the resolvent, monic
    P, Q = b - a * a / 3, 2 * a ** 3 / 27 - a * b / 3 + c
    disc = (Q / 2) ** 2 + (P / 3) ** 3
    sq = np.sqrt(np.maximum(disc, 0.0))
    one = np.cbrt(-Q / 2 + sq) + np.cbrt(-Q / 2 - sq)
    Pn = np.minimum(P, -1e-300)
    arg = np.clip(3 * Q / (2 * Pn) * np.sqrt(-3 / Pn), -1.0, 1.0)
    three = 2 * np.sqrt(-Pn / 3) * np.cos(np.arccos(arg) / 3)
    m = np.where(disc > 0, one, three) - a / 3
    for _ in range(2):
        f = ((m + a) * m + b) * m + c
        df = (3 * m + 2 * a) * m + b
        step = np.divide(f, df, out=np.zeros_like(f), where=df != 0)
        m = np.where(np.isfinite(step), m - step, m)
    m = np.maximum(m, 0.0)
    k = np.sqrt(2 * m)
    safe = k > 1e-7 * (1 + np.abs(p))
    h = np.divide(q, 2 * k, out=np.zeros_like(q), where=safe)
    one_ = np.ones_like(p)
    r1 = quadratic_roots(one_, -k, p / 2 + m + h)
    r2 = quadratic_roots(one_, k, p / 2 + m - h)
    u = quadratic_roots(one_, p, r)                             # the biquadratic case, u = s^2
    su = np.sqrt(np.where(np.isfinite(u) & (u >= 0), u, np.nan))
    bi = np.concatenate([-su, su], 1)
    s = np.where(safe[:, None], np.concatenate([r1, r2], 1), np.where(np.isnan(bi), np.inf, bi))
    x = np.where(np.isfinite(s), s, 0.0)
    for _ in range(2):
        f = ((x * x + p[:, None]) * x + q[:, None]) * x + r[:, None]
        df = (4 * x * x + 2 * p[:, None]) * x + q[:, None]
        step = np.divide(f, df, out=np.zeros_like(f), where=df != 0)
        x = np.where(np.isfinite(step) & (np.abs(step) < 1e-2), x - step, x)
    return np.sort(np.where(np.isfinite(s), x, np.inf), axis=1)

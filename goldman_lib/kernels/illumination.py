"""The shading model of chapter 16 on checked arrays: the one implementation of its terms.

``lighting.intensity``, ``diffuse``, ``specular`` and ``reflect`` check their input and call these;
the ray tracer's inner levels call them directly on rays it has already checked (issue 19 §1: no
checked public function on a hot path).
"""

from __future__ import annotations

import numpy as np

from goldman_lib.kernels.frames import row_dots, unit_rows

__all__ = ["reflect", "cosines", "phong"]


def reflect(v, n):
    """``2 (v . N) N - v`` per row: the mirror image of ``v`` about the unit normal ``n`` (Goldman §16.5)."""
    return 2 * row_dots(v, n)[..., None] * n - v


def cosines(P, N, light_position, V=None, exponent=None, clamp=True):
    """The cosines of one light (Goldman §16.4-16.5): ``max(L . N, 0)`` and, given unit ``V``,
    ``(R . V)^n`` (0 where ``L . N <= 0`` or ``R . V <= 0``), using ``R . V = 2 (L . N)(N . V) - L . V``
    so ``R`` is never formed.  P, N (unit), V: (..., 3).  ``clamp=False``: ``L . N`` as it is and
    the specular term not switched off where it is negative (the slip §16.4's clamp prevents)."""
    with np.errstate(over="ignore", invalid="ignore"):
        L = unit_rows(light_position - P)
    ln = row_dots(L, N)
    cos_d = np.maximum(ln, 0.0) if clamp else ln
    if V is None:
        return cos_d, None
    rv = 2.0 * ln * row_dots(N, V) - row_dots(L, V)
    rv = np.where(ln > 0, np.maximum(rv, 0.0), 0.0) if clamp else np.maximum(rv, 0.0)
    with np.errstate(under="ignore", divide="ignore"):
        power = np.where(rv > 0, np.power(rv, exponent), 0.0)
    return cos_d, power


def phong(P, N, V, lights, colour, specular_colour, ambient_term, kd, ks, exponent, *, clamp=True,
          shadowed=None, fraction=None):
    """``I_a k_a C + sum over lights of I_p (k_d C (L . N) + k_s S (R . V)^n)`` (Goldman §16.6) on
    checked arrays: P, N (unit): (..., 3); V: unit vectors to the eye (..., 3), or None when
    ``ks == 0``; lights: ``(position (3,), rgb (3,))`` pairs; ``ambient_term``: ``k_a I_a`` (a number
    or RGB triple); shadowed, fraction: optional (..., len(lights)) (a blocked light adds nothing;
    a fraction scales a light's terms).  Returns (..., 3), unclipped."""
    total = np.broadcast_to(ambient_term * colour, P.shape).copy()
    with np.errstate(over="ignore", invalid="ignore"):
        for k, (position, rgb) in enumerate(lights):
            cos_d, power = cosines(P, N, position, V, exponent, clamp)
            term = cos_d[..., None] * (kd * colour * rgb)
            if power is not None:
                term += power[..., None] * (ks * specular_colour * rgb)
            if shadowed is not None:
                term[shadowed[..., k]] = 0.0
            if fraction is not None:
                term *= fraction[..., k, None]
            total += term
    return total

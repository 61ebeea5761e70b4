"""Angles in degrees, the unit of every public function of the course (CONVENTIONS, "API style").

Importing this module imports numpy only.
"""

from __future__ import annotations

import numpy as np

from goldman_lib.validation import as_float_array, check_finite

__all__ = ["cos_sin_degrees"]

_C4 = np.array([1.0, 0.0, -1.0, 0.0])
_S4 = np.array([0.0, 1.0, 0.0, -1.0])


def cos_sin_degrees(theta):
    """cos and sin of angles in degrees, exact at multiples of 90 (so squares close exactly and a
    quarter turn of (1, 0) is exactly (0, 1)).  Used by the turtle (Goldman §1.2) and the affine
    maps (§4.2).

    theta: a finite real number or array.  Returns ``(cos, sin)`` as floats for a number, arrays
    otherwise.  Raises TypeError/ValueError naming ``theta`` for a non-numeric, complex or
    non-finite angle (whose cosine would be NaN).

    >>> cos_sin_degrees(90)
    (0.0, 1.0)
    >>> [v.round(6).tolist() for v in cos_sin_degrees([0, 30, 270])]
    [[1.0, 0.866025, 0.0], [0.0, 0.5, -1.0]]
    """
    theta = check_finite(as_float_array(theta, "theta"), "theta")
    scalar = theta.ndim == 0
    t = np.mod(theta, 360.0).reshape(-1) if scalar else np.mod(theta, 360.0)
    rad = np.radians(t)
    c, s = np.cos(rad), np.sin(rad)
    q = t / 90.0
    exact = q == np.round(q)
    if exact.any():
        k = np.round(q[exact]).astype(int) % 4
        c[exact] = _C4[k]
        s[exact] = _S4[k]
    if scalar:
        return float(c[0]), float(s[0])
    return c, s

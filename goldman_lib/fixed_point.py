"""Fixed points, root finding, relaxation and the fractal theorem (Goldman §7.2-7.3).

This module starts with the metric the fractal chapters share: the Hausdorff distance between
two compact sets, here finite point sets sampling them (§7.3.3).

Importing this module imports numpy only.
"""

from __future__ import annotations

import numpy as np

from .validation import as_points

__all__ = ["hausdorff_distance", "directed_hausdorff"]

_CHUNK = 2048


def _nearest_sq(A: np.ndarray, B: np.ndarray) -> np.ndarray:
    """For each row of A, the squared distance to the nearest row of B (chunked, so memory
    stays at ``_CHUNK * len(B)`` floats)."""
    out = np.empty(len(A))
    b2 = np.einsum("ij,ij->i", B, B)
    for start in range(0, len(A), _CHUNK):
        a = A[start:start + _CHUNK]
        d2 = np.einsum("ij,ij->i", a, a)[:, None] - 2.0 * (a @ B.T) + b2[None, :]
        out[start:start + _CHUNK] = np.maximum(d2.min(axis=1), 0.0)
    return out


def directed_hausdorff(A, B) -> float:
    """The directed Hausdorff distance ``max over a in A of min over b in B of |a - b|`` (Goldman §7.3.3).

    A: (n, d) points.  B: (m, d) points, same d.  Raises ValueError for empty sets or mismatched
    dimensions.

    >>> directed_hausdorff([[0, 0], [1, 0]], [[0, 0]])
    1.0
    """
    A = as_points(A, "A")
    B = as_points(B, "B", dim=A.shape[1])
    return float(np.sqrt(_nearest_sq(A, B).max()))


def hausdorff_distance(A, B) -> float:
    """The Hausdorff distance between two finite point sets (Goldman §7.3.3).

    ``h(A, B) = max(sup_a inf_b |a - b|, sup_b inf_a |a - b|)``: the smallest r such that each
    set lies within distance r of the other.  It is a metric on compact sets; the fractal theorem
    says an IFS of contractions is a contraction in this metric, so its iterates converge to one
    attractor from any start.

    A: (n, d) points.  B: (m, d) points, same d.  Cost O(n m) time, O(2048 m) memory.
    Raises ValueError for empty sets or mismatched dimensions.

    >>> hausdorff_distance([[0, 0], [1, 0]], [[0, 0], [0, 3]])
    3.0
    """
    A = as_points(A, "A")
    B = as_points(B, "B", dim=A.shape[1])
    return float(np.sqrt(max(_nearest_sq(A, B).max(), _nearest_sq(B, A).max())))

"""Relaxation: Jacobi and Gauss-Seidel sweeps for ``x = (c + w (G x)) / d`` (Goldman §7.3.2, §23.5), unchecked.

One form serves both chapters that relax a linear system:

- ``A x = b`` split as ``A = D + R`` (§7.3.2): ``x = (b - R x) / d`` is ``c = b``, ``G = -R``,
  no ``w``, ``d = diag(A)`` (``b + (-R) x`` is ``b - R x`` to the last bit: negation is exact);
- the radiosity equation ``B = E + rho F B`` (§23.5): ``c = E``, ``G = F``, ``w = rho``, no ``d``.

A Jacobi step is :func:`gather` then :func:`jacobi_update` (so a caller that needs ``w (G x)``
for its residual computes it once); :func:`gauss_seidel_sweep` updates in place, each new
component used at once.  ``w`` and ``d`` broadcast against the rows of x (an ``(n, c)`` x with
``w`` of shape ``(n,)`` or ``(n, c)`` solves c channels at once).  Nothing here checks its input.

:class:`Convergence` is the one record every iteration of the library returns on request
(``full_output=True``): ``fixed_point``'s fixed-point iteration, Newton's method, Jacobi and
Gauss-Seidel for ``A x = b``, and ``radiosity``'s Jacobi, Gauss-Seidel and progressive refinement
for ``B = E + rho F B``.  Its home is here, beside the sweeps, because both chapters return it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["Convergence", "gather", "jacobi_update", "gauss_seidel_sweep"]


@dataclass
class Convergence:
    """What an iteration did (Goldman §7.2-7.3, §23.5): ``x`` the last iterate (the solution when
    ``converged``), ``converged``, ``reason`` (``"converged"``, ``"zero derivative"``, ``"cycle"``,
    ``"diverged"``, ``"max iterations"``), ``iterations`` (steps taken: sweeps, or shots),
    ``history`` (every iterate, the start first: ``iterations + 1`` of them), ``residuals`` (one per
    iterate: ``|f(x_n)|`` for root finding, ``||b - A x_n||_inf`` for a linear system, ``|F(x_n) -
    x_n|`` for a fixed point, ``max |E + rho F B_n - B_n|`` for the radiosity equation), ``method``
    and ``message``; ``notes`` (remarks such as "A is not diagonally dominant") and ``shooters``
    (progressive refinement: the patch shot at each step; None for the other methods).

    >>> rep = Convergence(0.5, True, "converged", 1, np.array([1.0, 0.5]), np.array([0.5, 0.0]), "Jacobi")
    >>> str(rep)
    'Jacobi: converged after 1 iterations (last residual 0)'
    """

    x: object
    converged: bool
    reason: str
    iterations: int
    history: np.ndarray
    residuals: np.ndarray
    method: str = ""
    message: str = ""
    notes: list = field(default_factory=list)
    shooters: np.ndarray | None = None

    def __str__(self) -> str:
        last = self.residuals[-1] if len(self.residuals) else float("nan")
        return (f"{self.method}: {self.reason} after {self.iterations} iterations "
                f"(last residual {last:.3g}){'; ' + self.message if self.message else ''}")


def gather(G: np.ndarray, x: np.ndarray, w=None) -> np.ndarray:
    """What every unknown gathers from the current iterate: ``w * (G @ x)`` (``G @ x`` without w).

    >>> gather(np.array([[0.0, 0.5], [0.5, 0.0]]), np.array([1.0, 0.0]), np.array([0.5, 0.5])).tolist()
    [0.0, 0.25]
    """
    g = G @ x
    return g if w is None else w * g


def jacobi_update(c: np.ndarray, gathered: np.ndarray, d=None) -> np.ndarray:
    """The Jacobi iterate from what was gathered: ``(c + gathered) / d`` (``c + gathered`` without d).

    >>> jacobi_update(np.array([1.0, 2.0]), np.array([-0.5, -1.0]), np.array([4.0, 5.0])).tolist()
    [0.125, 0.2]
    """
    x = c + gathered
    return x if d is None else x / d


def gauss_seidel_sweep(G: np.ndarray, c: np.ndarray, x: np.ndarray, w=None, d=None) -> np.ndarray:
    """One Gauss-Seidel sweep in place: ``x_i <- (c_i + w_i (G_i . x)) / d_i`` for i = 0, 1, ...,
    each new ``x_i`` used at once by the rows after it.  Returns x.

    >>> gauss_seidel_sweep(np.array([[0.0, 0.5], [0.5, 0.0]]), np.array([1.0, 1.0]), np.array([1.0, 1.0]),
    ...                    np.array([0.5, 0.5])).tolist()
    [1.25, 1.3125]
    """
    n = len(c)
    if w is None and d is None:
        for i in range(n):
            x[i] = c[i] + G[i] @ x
    elif d is None:
        for i in range(n):
            x[i] = c[i] + w[i] * (G[i] @ x)
    elif w is None:
        for i in range(n):
            x[i] = (c[i] + G[i] @ x) / d[i]
    else:
        for i in range(n):
            x[i] = (c[i] + w[i] * (G[i] @ x)) / d[i]
    return x

"""Fixed points, root finding, relaxation and the fractal theorem (Goldman §7.2-7.3).

One idea runs through the chapter: to solve ``x = F(x)``, iterate ``x_{n+1} = F(x_n)``.

* §7.2, the trivial fixed-point theorem: if the iterates of a continuous ``F`` converge, their
  limit is a fixed point (:func:`fixed_point_iteration`).
* §7.3.1, root finding: Newton's method is the iteration of ``F(x) = x - f(x)/f'(x)``
  (:func:`newton`), with its failures reported by name: a zero derivative, a cycle, divergence.
* §7.3.2, relaxation: Jacobi and Gauss-Seidel iterate ``x = D^-1 (b - (A - D) x)`` to solve a
  linear system (:func:`jacobi`, :func:`gauss_seidel`).
* §7.3.3, the fractal theorem: the set map of an IFS of contractions is a contraction of the
  compact sets in the Hausdorff metric (:func:`hausdorff_distance`), with factor
  ``s = max contraction_factor(w_i)``, so ``h(W^n(A_0), A) <= s^n h(A_0, A)`` from any start
  (:func:`fractal_theorem`).

Every iteration returns a :class:`Convergence` report (iterates, residuals, why it stopped) when
asked with ``full_output=True``; a failure raises :class:`ConvergenceError` carrying the report.
The record is the library's one iteration record (its home is :mod:`goldman_lib.kernels.relaxation`):
``radiosity.jacobi``, ``radiosity.gauss_seidel`` and ``radiosity.progressive_refinement`` return it
too, with the same keywords ``tol``, ``max_iter`` and ``full_output``.  Same method, another system:
this module's :func:`jacobi` and :func:`gauss_seidel` solve ``A x = b`` (§7.3.2), radiosity's
solve the radiosity equation ``B = E + rho F B`` (§23.5); both run the sweeps of
:mod:`goldman_lib.kernels.relaxation`.

>>> round(newton(lambda x: x * x - 2, lambda x: 2 * x, 1.0), 15)
1.414213562373095

Importing this module imports numpy only.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from . import affine
from .kernels import relaxation
from .kernels.relaxation import Convergence
from .validation import (MAX_ITEMS, MAX_ITERATIONS, as_float, as_float_array, as_int, as_points, as_tolerance,
                         check_finite, finite_result, within_budget)

__all__ = ["MAX_PAIRS", "Convergence", "ConvergenceError", "fixed_point_iteration", "newton", "newton_steps", "jacobi",
           "gauss_seidel", "is_diagonally_dominant", "jacobi_factor", "contraction_factor", "hausdorff_distance",
           "directed_hausdorff", "fractal_theorem", "FractalTheorem"]


class ConvergenceError(ArithmeticError, ValueError):
    """An iteration failed to converge; ``.report`` is its :class:`Convergence` report.

    Also a ``ValueError`` (as numpy's ``LinAlgError`` is): the inputs given -- the start, the
    function, the tolerance -- are ones from which the iteration does not reach an answer."""

    def __init__(self, message: str, report: Convergence):
        super().__init__(message)
        self.report = report


def _as_x0(x0) -> np.ndarray:
    return as_float_array(x0, "x0").copy()


def _finish(report: Convergence, full_output: bool):
    if full_output:
        return report.x, report
    if not report.converged:
        raise ConvergenceError(f"{report.method} did not converge: {report.message}", report)
    return report.x


#: The most point pairs one (directed) Hausdorff distance may compare, ``len(A) * len(B)``: five
#: times :data:`goldman_lib.validation.MAX_ITEMS`, a few seconds of numpy work.
MAX_PAIRS = 5 * MAX_ITEMS


def _iterations(max_iter, size: int = 1) -> int:
    """``max_iter``: at most MAX_ITERATIONS steps, and the history it keeps (``max_iter + 1``
    iterates of ``size`` numbers) at most MAX_ITEMS numbers."""
    max_iter = within_budget(max_iter, "max_iter", cost=lambda v: v, what="the iteration", unit="iterations",
                             limit=MAX_ITERATIONS, minimum=1)
    return within_budget(max_iter, "max_iter", cost=lambda v: (v + 1) * max(size, 1),
                         what="the history of iterates", unit="numbers", minimum=1)


def _callable(f, name: str):
    if not callable(f):
        raise TypeError(f"{name} must be a function; got {type(f).__name__}")
    return f


def fixed_point_iteration(F, x0, *, tol: float = 1e-12, max_iter: int = 1000, full_output: bool = False):
    """Iterate ``x_{n+1} = F(x_n)`` until it settles (Goldman §7.2, the trivial fixed-point theorem).

    If the iterates converge and ``F`` is continuous, the limit ``L`` satisfies ``L = F(L)``.
    F: a function of a number or of an array ``(d,)``.  x0: the start.  Stops when
    ``|x_{n+1} - x_n| <= tol * max(1, |x_{n+1}|)`` (max norm).  Returns the fixed point (float or
    array), or ``(x, Convergence)`` with ``full_output``.  Raises ConvergenceError if the
    iterates diverge (become non-finite) or do not settle in ``max_iter`` steps (unless
    ``full_output``); ValueError for a non-finite start.  max_iter: 1 to
    :data:`goldman_lib.validation.MAX_ITERATIONS`, and ``(max_iter + 1) * x0.size`` (the history
    kept) at most :data:`goldman_lib.validation.MAX_ITEMS`.  tol: finite and positive.

    >>> round(fixed_point_iteration(math.cos, 1.0), 10)   # the solution of cos x = x
    0.7390851332
    """
    F = _callable(F, "F")
    x = check_finite(_as_x0(x0), "x0")
    scalar = x.ndim == 0
    if x.size == 0:
        raise ValueError(f"x0 must hold at least one number; got shape {x.shape}")
    tol = as_tolerance(tol)
    max_iter = _iterations(max_iter, x.size)
    history, residuals = [x.copy()], []
    reason, message = "max iterations", f"no fixed point within {max_iter} iterations"
    with np.errstate(all="ignore"):
        for it in range(1, max_iter + 1):
            try:
                nxt = np.array(F(float(x) if scalar else x.copy()), dtype=float)
            except (OverflowError, ZeroDivisionError, ValueError) as exc:
                reason, message = "diverged", f"F failed at x = {x}: {exc}"
                break
            step = float(np.max(np.abs(nxt - x))) if nxt.size else 0.0
            residuals.append(step)
            history.append(nxt.copy())
            x = nxt
            if not np.all(np.isfinite(x)):
                reason, message = "diverged", "the iterates grew without bound"
                break
            if step <= tol * max(1.0, float(np.max(np.abs(x)))):
                reason, message = "converged", ""
                break
    it = len(history) - 1
    rep = Convergence(float(x) if scalar else x, reason == "converged", reason, it, np.array(history),
                      np.array(residuals), "fixed-point iteration", message)
    return _finish(rep, full_output)


def newton(f, df, x0, *, tol: float = 1e-12, max_iter: int = 50, full_output: bool = False):
    """Newton's method for a root of ``f`` (Goldman §7.3.1): iterate ``N(x) = x - f(x)/f'(x)``.

    A root ``r`` of ``f`` is a fixed point of ``N``; near a simple root the iteration converges
    quadratically (the number of correct digits doubles each step).  The failures the book
    discusses are detected and named in the report: a **zero derivative** (the tangent is
    horizontal), a **cycle** (the iterates repeat, e.g. ``x^3 - 2x + 2`` from 0: 0, 1, 0, 1, ...),
    and **divergence** (the iterates run off, e.g. ``arctan`` started beyond 1.39).

    f, df: functions of a float.  x0: the start.  Converged when ``f(x) = 0`` or a step is below
    ``tol * max(1, |x|)`` (quadratic convergence then leaves the root correct to rounding).  Returns the root, or ``(x, Convergence)`` with
    ``full_output`` (no exception then).  Raises ConvergenceError naming the failure otherwise.

    >>> newton(lambda x: x**3 - 2*x + 2, lambda x: 3*x**2 - 2, 0.0)
    Traceback (most recent call last):
    ...
    goldman_lib.fixed_point.ConvergenceError: Newton's method did not converge: the iterates cycle with period 2: 0, 1, ...
    """
    rep = newton_steps(f, df, x0, tol=tol, max_iter=max_iter)
    return _finish(rep, full_output)


def newton_steps(f, df, x0, *, tol: float = 1e-12, max_iter: int = 50) -> Convergence:
    """The full :class:`Convergence` report of Newton's method (Goldman §7.3.1); never raises
    for a failing iteration (see :func:`newton`).  ``history`` holds ``x_0, x_1, ...``.
    max_iter: 1 to :data:`goldman_lib.validation.MAX_ITERATIONS`; tol finite and positive.

    >>> rep = newton_steps(lambda x: x * x - 2, lambda x: 2 * x, 0.0)
    >>> rep.reason, rep.iterations
    ('zero derivative', 0)
    """
    f, df = _callable(f, "f"), _callable(df, "df")
    x = as_float(x0, "x0")
    tol = as_tolerance(tol)
    max_iter = _iterations(max_iter)
    history, residuals = [x], []
    reason, message = "max iterations", f"no root within {max_iter} iterations"
    for _ in range(max_iter + 1):
        try:
            fx, dfx = float(f(x)), float(df(x))
        except (OverflowError, ZeroDivisionError, ValueError) as exc:
            reason, message = "diverged", f"f or df failed at x = {x:.6g}: {exc}"
            break
        if not (math.isfinite(fx) and math.isfinite(dfx)):
            reason, message = "diverged", f"f(x) is not finite at x = {x:.6g}"
            break
        residuals.append(abs(fx))
        if fx == 0.0:
            reason, message = "converged", ""
            break
        if len(history) > max_iter:
            break
        if dfx == 0.0 or abs(fx) > 1e12 * abs(dfx) * max(1.0, abs(x)):
            reason, message = "zero derivative", (f"f'(x) = {dfx:.3g} at x = {x:.6g}: the tangent is (nearly) "
                                                  f"horizontal and meets the axis far away or never")
            break
        nxt = x - fx / dfx
        if not math.isfinite(nxt) or abs(nxt) > 1e100:
            reason, message = "diverged", f"the iterates ran off to {nxt:.3g}"
            history.append(nxt if math.isfinite(nxt) else math.copysign(1e300, nxt))
            break
        step = abs(nxt - x)
        history.append(nxt)
        x = nxt
        if step <= tol * max(1.0, abs(x)):
            fnew = float(f(x))
            if abs(fnew) > abs(fx):   # a last step at rounding level may make it worse: keep the better
                history[-1] = x = history[-2]
                fnew = fx
            residuals.append(abs(fnew))
            reason, message = "converged", ""
            break
        period = _cycle(history, tol)
        if period:
            cyc = ", ".join(f"{v:.6g}" for v in history[-period - 1:-1])
            reason, message = "cycle", f"the iterates cycle with period {period}: {cyc}, ..."
            break
        if abs(x) > 1e6 * max(1.0, abs(history[0])) and abs(x) > 10 * abs(history[-2]):
            reason, message = "diverged", f"the iterates run off to infinity (x = {x:.3g})"
            break
    return Convergence(x, reason == "converged", reason, len(history) - 1, np.array(history, dtype=float),
                       np.array(residuals, dtype=float), "Newton's method", message)


def _cycle(history, tol) -> int:
    """The period p (2..8) if the last iterate repeats the one p steps before, else 0."""
    x = history[-1]
    for p in range(2, 9):
        if len(history) > p and abs(history[-1 - p] - x) <= max(tol, 1e-12) * max(1.0, abs(x)):
            # a genuine cycle, not convergence: the points of the cycle are distinct
            if abs(history[-2] - x) > 1e3 * max(tol, 1e-12) * max(1.0, abs(x)):
                return p
    return 0


def _linear_system(A, b, x0):
    A = as_float_array(A, "A")
    if A.ndim != 2 or A.shape[0] != A.shape[1] or A.shape[0] == 0:
        raise ValueError(f"A must be a square matrix (n, n); got shape {A.shape}")
    check_finite(A, "A")
    n = len(A)
    b = as_points(b, "b", ndim=1)
    if b.shape != (n,):
        raise ValueError(f"b must have one entry per row of A ({n}); got shape {b.shape}")
    diag = np.diag(A)
    zero = np.flatnonzero(diag == 0)
    if zero.size:
        i = int(zero[0])
        raise ValueError(f"A must have a nonzero diagonal for relaxation; A[{i}, {i}] = 0 "
                         f"(reorder the equations so no diagonal entry is zero)")
    x = np.zeros(n) if x0 is None else as_points(x0, "x0", ndim=1)
    if x.shape != (n,):
        raise ValueError(f"x0 must have shape ({n},); got {x.shape}")
    return A, b, x.copy()


def is_diagonally_dominant(A) -> bool:
    """Whether ``|A[i, i]| > sum_{j != i} |A[i, j]|`` in every row (Goldman §7.3.2): then Jacobi
    and Gauss-Seidel converge from any start.

    >>> is_diagonally_dominant([[4, 1], [2, 5]]), is_diagonally_dominant([[1, 2], [3, 4]])
    (True, False)
    """
    A = np.abs(check_finite(as_float_array(A, "A"), "A"))
    if A.ndim != 2 or A.shape[0] != A.shape[1]:
        raise ValueError(f"A must be a square matrix (n, n); got shape {A.shape}")
    d = np.diag(A)
    return bool(np.all(d > A.sum(axis=1) - d))


def jacobi_factor(A) -> float:
    """The contraction factor of Jacobi's map ``x -> D^-1 (b - R x)`` in the max norm (Goldman §7.3.2):
    ``max_i sum_{j != i} |A[i, j]| / |A[i, i]|``.  It is below 1 exactly when ``A`` is strictly
    diagonally dominant, and then each Jacobi sweep shrinks the error ``||x_n - x||_inf`` at least
    by this factor.  Raises ValueError for a non-square ``A`` or a zero on the diagonal.

    >>> jacobi_factor([[4, 1], [2, 5]])
    0.4
    """
    A = np.abs(check_finite(as_float_array(A, "A"), "A"))
    if A.ndim != 2 or A.shape[0] != A.shape[1] or A.shape[0] == 0:
        raise ValueError(f"A must be a non-empty square matrix (n, n); got shape {A.shape}")
    d = np.diag(A)
    if np.any(d == 0):
        i = int(np.argmin(d))
        raise ValueError(f"A must have no zero on its diagonal (Jacobi divides by it); A[{i}, {i}] = 0")
    with np.errstate(over="ignore", invalid="ignore"):
        R = A / d[:, None]                    # row i divided by |a_ii| first, so huge rows do not overflow
        np.fill_diagonal(R, 0.0)
        off = R.sum(axis=1)
    return float(finite_result(off, "A", why="has off-diagonal entries too large against its diagonal").max())


def _relax(A, b, x0, tol, max_iter, full_output, method):
    A, b, x = _linear_system(A, b, x0)
    tol = as_tolerance(tol)
    max_iter = _iterations(max_iter, len(b))
    d = np.diag(A)
    R = A - np.diag(d)
    G = -R                                  # x = (b - R x) / d is relaxation's (c + G x) / d, bit for bit
    scale_A = float(np.abs(A).sum(axis=1).max())
    scale_b = float(np.abs(b).max())
    history = [x.copy()]
    r0 = float(np.abs(b - A @ x).max())
    residuals = [r0]
    reason, message = "max iterations", f"the residual did not fall below the tolerance in {max_iter} iterations"
    dominant = is_diagonally_dominant(A)
    stalled = 0
    best = r0  # the least residual so far
    with np.errstate(all="ignore"):
        for it in range(1, max_iter + 1):
            if method == "Jacobi":
                x = relaxation.jacobi_update(b, relaxation.gather(G, x), d)
            else:  # Gauss-Seidel: each new component is used at once
                relaxation.gauss_seidel_sweep(G, b, x, d=d)
            res = float(np.abs(b - A @ x).max())
            history.append(x.copy())
            residuals.append(res)
            if not np.isfinite(res) or res > 1e12 * max(r0, scale_b, 1e-300):
                reason = "diverged"
                message = "the iterates grew without bound"
                if not dominant:
                    message += " (A is not diagonally dominant, and this iteration diverges for it)"
                break
            if res <= tol * (scale_A * float(np.abs(x).max()) + scale_b) or res == 0.0:
                reason, message = "converged", ""
                break
            # at rounding level the residual stops falling: accept if tiny, stop if stuck
            stalled = stalled + 1 if res >= best else 0
            best = min(best, res)
            if stalled >= 20 and res <= 1e3 * tol * (scale_A * float(np.abs(x).max()) + scale_b):
                reason, message = "converged", "stopped at rounding level"
                break
    if reason == "max iterations" and not dominant:
        message += " (A is not diagonally dominant, so convergence is not guaranteed)"
    finite_x = np.where(np.isfinite(x), x, 0.0) if reason == "diverged" else x
    rep = Convergence(finite_x if reason == "diverged" else x, reason == "converged", reason, len(history) - 1,
                      np.array(history), np.array(residuals), method, message)
    if not dominant:
        rep.notes.append("A is not diagonally dominant")
        if reason != "converged":
            warnings.warn(f"{method}: A is not diagonally dominant and the iteration {reason}", RuntimeWarning,
                          stacklevel=3)
    return _finish(rep, full_output)


def jacobi(A, b, x0=None, *, tol: float = 1e-15, max_iter: int = 10_000, full_output: bool = False):
    """Solve the linear system ``A x = b`` by Jacobi relaxation (Goldman §7.3.2); for the radiosity
    equation ``B = E + rho F B`` see ``radiosity.jacobi`` (same keywords, same record).

    Write ``A = D + R`` (diagonal and the rest); ``x`` solves the system iff it is a fixed point
    of ``x -> D^-1 (b - R x)``, which Jacobi iterates, updating all components at once.  It
    converges from any start if ``A`` is strictly diagonally dominant.

    A: (n, n) with a nonzero diagonal.  b: (n,).  x0: (n,) start (default zeros).  Converged when
    ``||b - A x||_inf <= tol (||A||_inf ||x||_inf + ||b||_inf)`` (the default is near machine
    precision).  max_iter: 1 to :data:`goldman_lib.validation.MAX_ITERATIONS`, with the history
    kept, ``(max_iter + 1) n`` numbers, at most :data:`goldman_lib.validation.MAX_ITEMS`.  tol:
    finite and positive.  Returns ``x`` (n,), or ``(x, Convergence)`` with ``full_output``.
    Raises ValueError for a non-square ``A``, a zero diagonal entry or a mismatched ``b``;
    ConvergenceError if the iteration diverges or runs out of iterations (with a
    RuntimeWarning if ``A`` is not diagonally dominant).

    >>> jacobi([[4.0, 1.0], [2.0, 5.0]], [1.0, 2.0]).round(12).tolist()
    [0.166666666667, 0.333333333333]
    """
    return _relax(A, b, x0, tol, max_iter, full_output, "Jacobi")


def gauss_seidel(A, b, x0=None, *, tol: float = 1e-15, max_iter: int = 10_000, full_output: bool = False):
    """Solve the linear system ``A x = b`` by Gauss-Seidel relaxation (Goldman §7.3.2); for the
    radiosity equation see ``radiosity.gauss_seidel`` (same keywords, same record).

    Like :func:`jacobi`, but each new component ``x_i = (b_i - sum_{j != i} A_ij x_j) / A_ii`` is
    used at once for the components after it, which usually halves the iterations.  Same
    arguments, stopping rule, returns and errors as :func:`jacobi`.

    >>> x, rep = gauss_seidel([[4.0, 1.0], [2.0, 5.0]], [1.0, 2.0], full_output=True)
    >>> x.round(12).tolist(), rep.converged
    ([0.166666666667, 0.333333333333], True)
    """
    return _relax(A, b, x0, tol, max_iter, full_output, "Gauss-Seidel")


def contraction_factor(M) -> float | np.ndarray:
    """The contraction factor of an affine map: the spectral norm of its linear part, the most
    it stretches a distance, ``max |v L| / |v|`` (Goldman §7.3.3).

    M: a 3x3 affine matrix (row-vector convention), a 2x2 linear part, or a stack ``(k, 3, 3)``.
    The map is a contraction iff the factor is < 1; for a similarity it is the scale ratio.
    Returns a float (or ``(k,)`` for a stack).

    >>> contraction_factor(affine.similarity(0.5, 30, [1, 2]))
    0.5
    >>> round(contraction_factor([[1.0, 0.0], [1.0, 1.0]]), 6)   # a shear stretches by the golden ratio
    1.618034
    """
    arr = as_float_array(M, "M")
    if arr.ndim >= 2 and arr.shape[-2:] == (3, 3):
        arr = affine.as_affine(arr, "M")[..., :2, :2]
    elif arr.ndim < 2 or arr.shape[-2:] != (2, 2):
        raise ValueError(f"M must be a 3x3 affine matrix or a 2x2 linear part; got shape {arr.shape}")
    check_finite(arr, "M")
    s = np.linalg.svd(arr, compute_uv=False)[..., 0]
    return float(s) if s.ndim == 0 else s


#: The Hausdorff distance's search (:func:`_directed_sq`): every point of A is first measured against
#: ``_PROBE`` points of B; scans compute about ``_WORK`` distances a step (64 KB temporaries, below
#: the size at which each allocation would map fresh pages); grid-neighbour bounds (``_WINDOW``
#: neighbours, :class:`_Grid`) are computed when the scan still ahead is expected to exceed
#: ``_SCAN_LIMIT`` distances.
_PROBE, _WORK, _WINDOW, _SCAN_LIMIT = 16, 8192, 16, 1 << 13


class _Grid:
    """Two point sets in one order in which neighbours are near in the plane: strips of equal width
    over the union's bounding box (first two coordinates), points in each strip by y, every other
    strip reversed (a snake).  ``side(0)`` gives each point of A's place among the sorted points of B,
    B and that order; ``side(1)`` the same for B among A.  Built once for both directions."""

    def __init__(self, A: np.ndarray, B: np.ndarray, w: int):
        n, m = len(A), len(B)
        P = np.concatenate([A, B])
        x = P[:, 0]
        if P.shape[1] >= 2:
            y = P[:, 1]
            xlo, ylo = x.min(), y.min()
            X, H = float(x.max() - xlo), float(y.max() - ylo)
            most = max((n + m) // (2 * w), 1)
            with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
                S = np.sqrt((n + m) / 2 * X / (H * w)) if H > 0 else most
                strips = int(min(S, most)) if np.isfinite(S) else 1
                strips = max(strips, 1)
                s = ((x - xlo) * (strips / X)).astype(np.int64) if 0 < X < np.inf else np.zeros(n + m, np.int64)
                np.clip(s, 0, strips - 1, out=s)
                v = (y - ylo) / H if 0 < H < np.inf else np.zeros(n + m)
            key = np.where(s & 1, 1.0 - v, v)
            key += 2.0 * s
        else:
            key = x
        o = np.argsort(key)
        in_b = o >= n
        b_before = np.cumsum(in_b)
        a_before = np.arange(1, n + m + 1) - b_before
        self.order_a, self.order_b = o[~in_b], o[in_b] - n
        self.pos_a = np.empty(n, np.intp)
        self.pos_a[self.order_a] = b_before[~in_b]
        self.pos_b = np.empty(m, np.intp)
        self.pos_b[self.order_b] = a_before[in_b]
        self.A, self.B = A, B

    def side(self, which: int):
        return (self.pos_a, self.B, self.order_b) if which == 0 else (self.pos_b, self.A, self.order_a)


def _sq_dist(Ac, rows, Bc, lo: int, hi: int) -> np.ndarray:
    """``|a - b|^2`` for a in A[rows], b in B[lo:hi], ``(len(rows), hi - lo)``, summed over the
    coordinates in order from the differences (the arithmetic of scipy's directed_hausdorff)."""
    d2 = None
    for ak, bk in zip(Ac, Bc):
        diff = ak[rows][:, None] - bk[None, lo:hi]
        diff *= diff
        d2 = diff if d2 is None else d2.__iadd__(diff)
    return d2


def _window_bounds(Ac, rows: np.ndarray, pos: np.ndarray, T: np.ndarray, order: np.ndarray, w: int) -> np.ndarray:
    """For each point A[rows], the squared distance to the nearest of the w points of T about its
    place ``pos`` in the grid order: a distance to a point of T, so an upper bound on its distance to
    T, and usually a close one."""
    m = len(T)
    start = np.clip(pos[rows] - w // 2, 0, m - w)
    out = np.empty(rows.size)
    chunk = max(1, _WORK // w)
    near = [np.lib.stride_tricks.sliding_window_view(T[order, k], w) for k in range(T.shape[1])]
    for s in range(0, rows.size, chunk):
        st, r = start[s:s + chunk], rows[s:s + chunk]
        d2 = None
        for ak, nk in zip(Ac, near):
            diff = nk[st]
            diff -= ak[r, None]
            diff *= diff
            d2 = diff if d2 is None else d2.__iadd__(diff)
        d2.min(axis=1, out=out[s:s + chunk])
    return out


def _directed_sq(A: np.ndarray, B: np.ndarray, cmax: float = 0.0, grid: _Grid | None = None,
                 which: int = 0) -> tuple[float, _Grid | None]:
    """``max(cmax, max_a min_b |a - b|^2)`` by a branch-and-bound form of Taha and Hanbury's
    early-exit scan (as scipy's ``directed_hausdorff``), vectorised; returns it and the grid if built.

    A lower bound comes first: ``min_b |a - b|^2`` is at least a's squared distance to B's bounding
    box, so the answer is at least the largest of these, and ``cmax`` starts one step below it (when
    the sets are apart it is close to the answer).  Each point of A gets an upper bound
    ``ub(a) >= min_b |a - b|^2``, a distance to some point of B: first to ``_PROBE`` points of B in a
    fixed pseudo-random order and to B's extreme points (in two rounds); then,
    if a scan would still be long (the probe says how likely a random point of B is to come within
    ``sqrt(cmax)``), to its ``_WINDOW`` neighbours in a grid order of both sets (:class:`_Grid`).  A
    point with ``ub(a) <= cmax`` cannot raise the maximum and is dropped.  The rest are taken largest
    bound first, in blocks (8, doubling): each scans B in the pseudo-random order and leaves as soon as
    its running minimum falls to ``cmax``; those reaching the end have their exact minimum and raise
    ``cmax``.  The search stops when the largest remaining bound is at most ``cmax``.  Every value
    compared is a computed distance ``sum_k (a_k - b_k)^2`` and min and max are exact, so the result
    is the brute-force maximum to the last bit, whatever the order.  ``cmax`` carries the other
    direction's value into :func:`hausdorff_distance`, where only points above it matter.
    """
    n, d = A.shape
    m = len(B)
    perm = np.random.default_rng(0).permutation(m)
    Bc = [B[:, k][perm] for k in range(d)]
    Ac = [np.ascontiguousarray(A[:, k]) for k in range(d)]
    # a lower bound on the answer: a point's distance to B's bounding box is at most its distance to
    # B (term by term, rounding is monotone); one step below the largest, only points beyond it count
    gap = None
    for ak, bk in zip(Ac, Bc):
        g = ak - np.clip(ak, bk.min(), bk.max())
        g *= g
        gap = g if gap is None else gap.__iadd__(g)
    cmax = max(cmax, float(np.nextafter(gap.max(), 0.0)))
    # the probe, in two rounds (points bounded below cmax by the first leave before the second)
    R = min(_PROBE, m)
    second = set(range(R // 2, R))
    if m > R:        # B's extreme points in the coordinate and diagonal directions
        for v in Bc + ([Bc[0] + Bc[1], Bc[0] - Bc[1]] if d >= 2 else []):
            second.update((int(v.argmin()), int(v.argmax())))
    cand, ub, cols = np.arange(n), np.full(n, np.inf), Ac
    for part in (range(R // 2), sorted(second)):
        if cand.size < n:
            cols = [ak[cand] for ak in Ac]
        d2, tmp = np.empty(cand.size), np.empty(cand.size)
        for j in part:
            np.subtract(cols[0], Bc[0][j], out=d2)
            d2 *= d2
            for k in range(1, d):
                np.subtract(cols[k], Bc[k][j], out=tmp)
                tmp *= tmp
                d2 += tmp
            np.minimum(ub, d2, out=ub)
        if cmax > 0:
            keep = ub > cmax
            cand, ub = cand[keep], ub[keep]
    if R == m:                   # the probe measured every point of B: the bounds are the minima
        return (max(cmax, float(ub.max())) if ub.size else cmax), grid
    o = np.argsort(-ub)
    cand, ubs = cand[o], ub[o]
    i, size, bounded = 0, max(1, min(8, (1 << 16) // m)), False     # the first block scans all of B
    while i < cand.size and ubs[i] > cmax:
        if not bounded and (i > 0 or cmax > 0):
            bounded = True           # cmax is known: is a scan of the rest short enough?
            keep = ubs[i:] > cmax
            cand, ubs, i = cand[i:][keep], ubs[i:][keep], 0
            f = cand.size / n        # the fraction of A that none of R random points of B came near
            q = 1.0 - f ** (1.0 / R) if f < 1 else 0.0
            if cand.size > 64 and (q <= 0 or cand.size / q > _SCAN_LIMIT):
                if grid is None:
                    grid, which = _Grid(A, B, min(_WINDOW, m)), 0
                pos, T, order = grid.side(which)
                np.minimum(ubs, _window_bounds(Ac, cand, pos, T, order, min(_WINDOW, m)), out=ubs)
                keep = ubs > cmax
                cand, ubs = cand[keep], ubs[keep]
                o = np.argsort(-ubs)
                cand, ubs = cand[o], ubs[o]
            if not cand.size:
                break
        stop = min(i + size, cand.size)
        rows = cand[i:stop]
        best = ubs[i:stop].copy()
        alive = np.flatnonzero(best > cmax)
        j = R
        while j < m and alive.size:
            step = min(max(_WORK // alive.size, 16), m - j)
            best[alive] = np.minimum(best[alive], _sq_dist(Ac, rows[alive], Bc, j, j + step).min(axis=1))
            alive = alive[best[alive] > cmax]
            j += step
        if alive.size:
            cmax = max(cmax, float(best[alive].max()))
        i, size = stop, min(2 * size, 512)
    return cmax, grid


def _point_sets(A, B) -> tuple[np.ndarray, np.ndarray]:
    """Two finite point sets of one dimension whose pairs are at most MAX_PAIRS."""
    A = as_points(A, "A")
    B = as_points(B, "B")
    if A.shape[1] != B.shape[1]:
        raise ValueError(f"A and B must hold points of the same dimension; A has {A.shape[1]}-dimensional points "
                         f"(shape {A.shape}), B has {B.shape[1]}-dimensional points (shape {B.shape})")
    if len(A) * len(B) > MAX_PAIRS:
        raise ValueError(f"A and B are too large: their Hausdorff distance compares len(A) * len(B) = "
                         f"{len(A):,} * {len(B):,} = {len(A) * len(B):,} pairs of points, over the limit of "
                         f"{MAX_PAIRS:,}; use fewer points")
    return A, B


def directed_hausdorff(A, B) -> float:
    """The directed Hausdorff distance ``max over a in A of min over b in B of |a - b|`` (Goldman §7.3.3).

    Computed by an early-exit scan (Taha and Hanbury 2015, as scipy's ``directed_hausdorff``) with
    bounds: a point of A stops scanning B as soon as some b is closer than the largest minimum found
    so far, since it cannot raise the maximum, and most points stop before scanning, bounded by
    their distance to a few points of B or to their grid neighbours in B (see ``_directed_sq``).
    O(n m) at worst, near O(n + m) for most sets; the value is exact (the brute-force maximum of
    the minima, to the last bit) whatever the order.

    A: (n, d) points.  B: (m, d) points, same d, with ``n m`` at most :data:`MAX_PAIRS`.  Raises
    ValueError for empty sets, mismatched dimensions or too many pairs.

    >>> directed_hausdorff([[0, 0], [1, 0]], [[0, 0]])
    1.0
    """
    A, B = _point_sets(A, B)
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.sqrt(_directed_sq(A, B)[0])
    return float(finite_result(out, "A and B", why="are too large in magnitude"))


def hausdorff_distance(A, B) -> float:
    """The Hausdorff distance between two finite point sets (Goldman §7.3.3).

    ``h(A, B) = max(sup_a inf_b |a - b|, sup_b inf_a |a - b|)``: the smallest r such that each
    set lies within distance r of the other.  It is a metric on compact sets; the fractal theorem
    says an IFS of contractions is a contraction in this metric, so its iterates converge to one
    attractor from any start.

    A: (n, d) points.  B: (m, d) points, same d.  Cost O(n m) time at worst, usually far less (an
    early-exit scan with bounds, see :func:`directed_hausdorff`; the second direction searches only
    for points beyond the first direction's value), memory O(n + m) beyond the inputs;
    ``n m`` at most :data:`MAX_PAIRS`.  Raises ValueError for empty sets, mismatched dimensions
    or too many pairs.

    >>> hausdorff_distance([[0, 0], [1, 0]], [[0, 0], [0, 3]])
    3.0
    """
    A, B = _point_sets(A, B)
    with np.errstate(over="ignore", invalid="ignore"):
        h, grid = _directed_sq(A, B)
        out = np.sqrt(_directed_sq(B, A, h, grid, 1)[0])     # only points of B beyond h matter
    return float(finite_result(out, "A and B", why="are too large in magnitude"))



@dataclass
class FractalTheorem:
    """The fractal theorem measured level by level (Goldman §7.3.3): ``distances[n] = h(W^n(A_0), A)``,
    ``bounds[n] = s^n h(A_0, A)``, the contraction factor ``s``, the iterates ``sets[n] = W^n(A_0)``
    and the attractor sample ``attractor`` (within ``attractor_error`` of the true attractor)."""

    distances: np.ndarray
    bounds: np.ndarray
    factor: float
    sets: list
    attractor: np.ndarray
    attractor_error: float

    def holds(self) -> bool:
        """Whether every measured distance is within its bound (up to the attractor sample's error)."""
        return bool(np.all(self.distances <= self.bounds + 2 * self.attractor_error + 1e-12))

    def table(self) -> str:
        """One line per level: n, h(W^n(A_0), A), s^n h(A_0, A)."""
        lines = ["level  h(W^n(A0), A)  s^n h(A0, A)"]
        for n, (d, b) in enumerate(zip(self.distances, self.bounds)):
            lines.append(f"{n:5d}  {d:13.6f}  {b:12.6f}")
        return "\n".join(lines)


def fractal_theorem(system, start, levels: int, *, attractor_points: int = 6000) -> FractalTheorem:
    """Measure the fractal theorem on an IFS (Goldman §7.3.3): from any compact start ``A_0`` the
    iterates ``W^n(A_0)`` converge to the attractor ``A`` with ``h(W^n(A_0), A) <= s^n h(A_0, A)``,
    ``s`` the largest contraction factor of the maps.

    system: an :class:`~goldman_lib.ifs.IFS` of contractions.  start: ``(m, 2)`` points sampling
    ``A_0``.  levels: how many iterates, at most 40 (the last has ``k**levels * m`` points, at most
    200,000).  attractor_points: 1 to :data:`goldman_lib.ifs.MAX_POINTS`.
    The attractor is sampled by the deterministic algorithm from a fixed point with about
    ``attractor_points`` points; that sample is within ``s^L diam(A)`` of ``A`` (stored as
    ``attractor_error``).  Raises ValueError if a map is not a contraction or the sets grow too big.

    >>> from goldman_lib import ifs
    >>> r = fractal_theorem(ifs.sierpinski(), [[3.0, 3.0]], 4)
    >>> r.factor, r.holds()
    (0.5, True)
    """
    from . import ifs as _ifs

    s = _ifs.as_ifs(system)
    A0 = as_points(start, "start", dim=2)
    with np.errstate(over="ignore", invalid="ignore"):
        finite_result(np.einsum("ij,ij->i", A0, A0), "start", why="is too large in magnitude (its squared distances)")
    k = len(s)
    levels = within_budget(levels, "levels", cost=lambda v: len(A0) * k ** v if v <= 40 else 10 ** 9,
                           what="the last iterate W^levels(start)", limit=200_000)
    attractor_points = as_int(attractor_points, "attractor_points", minimum=1, maximum=_ifs.MAX_POINTS)
    factors = s.contraction_factors()
    if np.any(factors >= 1.0):
        i = int(np.argmax(factors))
        raise ValueError(f"every map must be a contraction for the fractal theorem; map {i} has factor {factors[i]:.3g} >= 1")
    plain = _ifs.IFS(s.maps, s.probabilities, s.condensation, s.name)
    L = max(1, int(math.log(max(attractor_points, 2)) / math.log(k))) if k > 1 else 1
    A = _ifs.deterministic(plain, L)
    if plain.condensation is None:
        A = np.concatenate([s.fixed_points(), A])
    sfac = float(factors.max())
    diam = float(np.ptp(A, axis=0).max()) * math.sqrt(2)
    err = sfac ** L * max(diam, 1e-300) if plain.condensation is None else sfac ** L * max(diam, 1e-300)
    sets = [A0]
    for _ in range(levels):
        sets.append(_ifs.set_map(plain, sets[-1]))
    dist = np.array([hausdorff_distance(S, A) for S in sets])
    bounds = sfac ** np.arange(levels + 1) * dist[0]
    return FractalTheorem(dist, bounds, sfac, sets, A, err)

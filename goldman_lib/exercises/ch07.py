"""Exercise checkers for chapter 7, the fixed-point theorem and its applications (Goldman §7.2-7.3).

Every exercise uses other functions, systems, sets and maps than the chapter's worked examples, and
every checker names the slip it recognises (one Newton step instead of two, the Jacobi step when
Gauss-Seidel was asked, one direction of the Hausdorff distance, the area factor instead of the
stretch, ...).  The programming project, :func:`check_gauss_seidel_project`, runs the learner's
Gauss-Seidel sweeps against :func:`goldman_lib.fixed_point.gauss_seidel`.

>>> print(PROBLEMS["check_newton_step"])
Take two steps of Newton's method for f(x) = x^3 - 10 from x0 = 2: give x2 to 6 decimals (Goldman §7.3.1).
>>> check_newton_step(2.166667)
Not yet: that is x1, one step of Newton's method; take a second step x2 = x1 - f(x1)/f'(x1).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import fixed_point as fp
from goldman_lib.exercises import guard_checkers
from goldman_lib.exercises import Result, check_number, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "LIMIT_START", "NEWTON_START", "SEIDEL_A", "SEIDEL_B", "JACOBI_A", "JACOBI_B",
           "JACOBI_X0", "JACOBI_SWEEPS", "HAUSDORFF_A", "HAUSDORFF_B", "STRETCH_L", "LEVEL_FACTORS",
           "LEVEL_START_DISTANCE", "LEVEL_TOL", "check_fixed_point_limit", "check_newton_step",
           "check_gauss_seidel_sweep", "check_jacobi_sweeps", "check_hausdorff", "check_contraction_factor",
           "check_levels_needed", "check_gauss_seidel_project", "gauss_seidel_project_cases"]


def _limit_map(x):
    """The map of exercise 1, F(x) = sqrt(6 + x)."""
    return math.sqrt(6.0 + x)


#: Exercise 1: iterate F(x) = sqrt(6 + x) from this start.
LIMIT_START = 0.0
#: Exercise 2: Newton's method for f(x) = x^3 - 10 from this start, two steps.
NEWTON_START = 2.0
#: Exercise 3: one Gauss-Seidel sweep from zero on this 3x3 system.
SEIDEL_A = np.array([[4.0, 1.0, 1.0], [1.0, 5.0, 2.0], [2.0, 1.0, 6.0]])
SEIDEL_B = np.array([8.0, 7.0, 8.0])
#: Exercise 4: two Jacobi sweeps on this 2x2 system from JACOBI_X0.
JACOBI_A = np.array([[5.0, 2.0], [1.0, 4.0]])
JACOBI_B = np.array([9.0, 6.0])
JACOBI_X0 = np.array([1.0, 1.0])
JACOBI_SWEEPS = 2
#: Exercise 5: two finite point sets.
HAUSDORFF_A = np.array([[0.0, 0.0], [4.0, 0.0]])
HAUSDORFF_B = np.array([[0.0, 3.0], [12.0, 6.0]])
#: Exercise 6: the linear part of the map (x, y) -> (0.3 x, 0.4 x + 0.5 y) + (1, 2), row-vector convention.
STRETCH_L = np.array([[0.3, 0.4], [0.0, 0.5]])
#: Exercise 7: an IFS with these contraction factors, a start set this far from the attractor, a tolerance.
LEVEL_FACTORS = (0.6, 0.75, 0.5)
LEVEL_START_DISTANCE = 4.0
LEVEL_TOL = 0.01


def _eq(a: str) -> str:
    return a.replace("+ -", "- ").replace("1x", "x").replace("1y", "y").replace("1z", "z")


def _system_text(A, b, names) -> str:
    rows = []
    for row, rhs in zip(A, b):
        terms = " + ".join(f"{fmt(c)}{v}" for c, v in zip(row, names) if c != 0)
        rows.append(_eq(f"{terms} = {fmt(rhs)}"))
    return ", ".join(rows)


PROBLEMS = {
    "check_fixed_point_limit": (
        f"Iterate x_(n+1) = F(x_n) = sqrt(6 + x_n) from x0 = {fmt(LIMIT_START)}. The iterates converge; by the "
        f"trivial fixed-point theorem, what is their limit L (Goldman §7.2)?"),
    "check_newton_step": (
        f"Take two steps of Newton's method for f(x) = x^3 - 10 from x0 = {fmt(NEWTON_START)}: "
        f"give x2 to 6 decimals (Goldman §7.3.1)."),
    "check_gauss_seidel_sweep": (
        f"Do one Gauss-Seidel sweep (x, then y, then z) for {_system_text(SEIDEL_A, SEIDEL_B, 'xyz')} "
        f"from (x, y, z) = (0, 0, 0): give the new [x, y, z] (Goldman §7.3.2)."),
    "check_jacobi_sweeps": (
        f"Do {JACOBI_SWEEPS} Jacobi sweeps for {_system_text(JACOBI_A, JACOBI_B, 'xy')} from "
        f"(x, y) = {fmt(JACOBI_X0)}: give [x, y] after the second sweep (Goldman §7.3.2)."),
    "check_hausdorff": (
        f"Compute the Hausdorff distance h(A, B) between A = {{(0, 0), (4, 0)}} and "
        f"B = {{(0, 3), (12, 6)}} (Goldman §7.3.3)."),
    "check_contraction_factor": (
        "The affine map (x, y) -> (0.3 x, 0.4 x + 0.5 y) + (1, 2) has linear part L = [[0.3, 0.4], [0, 0.5]] "
        "(rows: Q = P L). Give its contraction factor, the most it stretches any distance, max |v L| / |v|, "
        "to 4 decimals (Goldman §7.3.3)."),
    "check_levels_needed": (
        f"An IFS has three maps with contraction factors {', '.join(fmt(s) for s in LEVEL_FACTORS)}, and the start "
        f"set A0 is at Hausdorff distance {fmt(LEVEL_START_DISTANCE)} from the attractor A. By the fractal theorem, "
        f"what is the smallest number of levels n that guarantees h(W^n(A0), A) <= {fmt(LEVEL_TOL)} "
        f"(Goldman §7.3.3)?"),
}


# -- §7.2 ------------------------------------------------------------------------------------------

def _limit_iterates():
    return fp.fixed_point_iteration(_limit_map, LIMIT_START, full_output=True)


def check_fixed_point_limit(answer) -> Result:
    """Check the limit of x -> sqrt(6 + x) from 0, a fixed point L = sqrt(6 + L) (Goldman §7.2);
    recognises the root of the quadratic that is not a fixed point (a square root is never negative)."""
    value, problem = read_number(answer, "the limit L")
    if problem is not None:
        return problem
    limit, rep = _limit_iterates()
    x1, x2 = rep.history[1], rep.history[2]
    if abs(value + 2) <= 1e-6:
        return wrong("-2 solves L^2 = 6 + L, but it is not a fixed point of F: sqrt(6 - 2) is 2, not -2 "
                     "(a square root is never negative). Take the other root.")
    if abs(value - x1) <= 1e-4:
        return wrong("that is x1 = F(x0), the first iterate; the theorem is about the limit: solve L = F(L).")
    if abs(value - x2) <= 1e-4:
        return wrong("that is x2, an early iterate; the theorem is about the limit: solve L = F(L).")
    return check_number(value, limit, what="the limit L", tol=1e-4,
                        hint="a limit L of x_(n+1) = F(x_n) satisfies L = F(L); square both sides")


# -- §7.3.1 ----------------------------------------------------------------------------------------

def _f_newton(x):
    return x ** 3 - 10.0


def _df_newton(x):
    return 3.0 * x * x


def check_newton_step(answer) -> Result:
    """Check x2 of Newton's method on ``x^3 - 10`` from 2 (Goldman §7.3.1).

    Recognises one step (x1), the limit (the cube root of 10), the sign slip ``x + f/f'`` and the
    derivative without its factor 3.
    """
    value, problem = read_number(answer, "x2")
    if problem is not None:
        return problem
    x2 = fp.newton_steps(_f_newton, _df_newton, NEWTON_START, max_iter=2).history[2]
    x1 = fp.newton_steps(_f_newton, _df_newton, NEWTON_START, max_iter=1).history[1]
    plus = fp.newton_steps(lambda x: -_f_newton(x), _df_newton, NEWTON_START, max_iter=2).history[2]
    no3 = fp.newton_steps(_f_newton, lambda x: x * x, NEWTON_START, max_iter=2).history[2]
    root = fp.newton(_f_newton, _df_newton, NEWTON_START)
    tol = 1e-5
    if abs(value - x2) <= tol:
        return correct(f"x2 is {x2:.6f}, already within 1e-4 of the cube root of 10: the correct digits roughly "
                       f"double at each step.")
    if abs(value - x1) <= tol:
        return wrong("that is x1, one step of Newton's method; take a second step x2 = x1 - f(x1)/f'(x1).")
    if abs(value - root) <= tol / 10:
        return wrong("that is the cube root of 10 itself, the limit; the exercise asks for the second iterate, "
                     "which is not there yet.")
    if abs(value - plus) <= tol:
        return wrong("that is what x_(n+1) = x_n + f(x_n)/f'(x_n) gives: Newton's step subtracts f/f' (follow the "
                     "tangent down to the axis).")
    if abs(value - no3) <= tol:
        return wrong("that is what you get dividing f(x_n) by x_n squared: the derivative of x cubed is three times "
                     "x squared.")
    return wrong(f"x2 is {off_by(value, x2)}. Check x1 = x0 - f(x0)/f'(x0) with f'(x) three times x squared, then repeat from x1.")


# -- §7.3.2 ----------------------------------------------------------------------------------------

def _sweeps(method, A, b, x0, sweeps: int) -> np.ndarray:
    """The iterate after ``sweeps`` sweeps of the library's Jacobi or Gauss-Seidel (the history of
    its report; if it converged earlier, later sweeps change nothing beyond rounding)."""
    x0 = np.asarray(x0, dtype=float)
    if sweeps == 0:
        return x0.copy()
    _, rep = method(A, b, x0, max_iter=sweeps, full_output=True)
    return np.asarray(rep.history[min(sweeps, len(rep.history) - 1)], dtype=float)


def _backward_gauss_seidel(A, b, x0, sweeps: int) -> np.ndarray:
    """Gauss-Seidel sweeping the unknowns from last to first (the library's sweep on the reversed system)."""
    A = np.asarray(A, dtype=float)
    return _sweeps(fp.gauss_seidel, A[::-1, ::-1], np.asarray(b, dtype=float)[::-1],
                   np.asarray(x0, dtype=float)[::-1], sweeps)[::-1]


def _components_off(got, expected, names: str, what: str, hint: str) -> Result:
    """Name the components that are off and by how much (never where they should be)."""
    off = [f"{names[i]} is {off_by(got[i], expected[i])}" for i in range(len(expected))
           if abs(got[i] - expected[i]) > 1e-4]
    right = [names[i] for i in range(len(expected)) if abs(got[i] - expected[i]) <= 1e-4]
    lead = f"{' and '.join(right)} {'is' if len(right) == 1 else 'are'} right; " if right else ""
    return wrong(f"in {what}, {lead}{'; '.join(off)}. Check: {hint}.")


def _read_vector(answer, what: str, n: int):
    got, err = read_points(answer, what)
    if err is not None:
        return None, err
    if got.shape != (n,):
        return None, wrong(f"{what} is one list of {n} numbers; yours has shape {got.shape}.")
    return got, None


def check_gauss_seidel_sweep(answer) -> Result:
    """Check one Gauss-Seidel sweep from 0 on ``SEIDEL_A x = SEIDEL_B``: x first, then y with the new
    x, then z with the new x and y (Goldman §7.3.2).

    Recognises the Jacobi step (no new value used), the new x used but not the new y, a sweep
    from the last unknown to the first, and the exact solution.
    """
    what = "the new [x, y, z]"
    got, err = _read_vector(answer, what, 3)
    if err is not None:
        return err
    zero = np.zeros(3)
    expected = _sweeps(fp.gauss_seidel, SEIDEL_A, SEIDEL_B, zero, 1)
    jacobi = _sweeps(fp.jacobi, SEIDEL_A, SEIDEL_B, zero, 1)
    if np.allclose(got, expected, atol=1e-4):
        return correct(f"{what} is {fmt(expected)}: each new value is used at once.")
    if np.allclose(got, jacobi, atol=1e-4):
        return wrong("that is the Jacobi step: every component computed from the old (0, 0, 0). Gauss-Seidel uses "
                     "each new value as soon as it is computed: the new x in the equation for y, the new x and y "
                     "in the one for z.")
    if np.allclose(got[:2], expected[:2], atol=1e-4) and not np.isclose(got[2], expected[2], atol=1e-4):
        z_old_y = (SEIDEL_B[2] - SEIDEL_A[2, 0] * expected[0]) / SEIDEL_A[2, 2]
        if abs(got[2] - z_old_y) <= 1e-4:
            return wrong("x and y are right, but z used the old y = 0; use the new y as well as the new x.")
        return wrong(f"x and y are right; z is {off_by(got[2], expected[2])}: solve the third equation for z "
                     f"with the new x and y.")
    if np.allclose(got, _backward_gauss_seidel(SEIDEL_A, SEIDEL_B, zero, 1), atol=1e-4):
        return wrong("that is a sweep from z back to x; the exercise sweeps x first, then y, then z.")
    if np.allclose(got, np.linalg.solve(SEIDEL_A, SEIDEL_B), atol=1e-4):
        return wrong("that is the exact solution of the system; one sweep only gets part of the way there.")
    return _components_off(got, expected, "xyz", what,
                           "x from the first equation with y = z = 0, y from the second with the new x, "
                           "z from the third with the new x and y")


def check_jacobi_sweeps(answer) -> Result:
    """Check two Jacobi sweeps on ``JACOBI_A x = JACOBI_B`` from (1, 1) (Goldman §7.3.2).

    Recognises the Gauss-Seidel iterate, one sweep only, and the exact solution.
    """
    what = "[x, y] after two sweeps"
    got, err = _read_vector(answer, what, 2)
    if err is not None:
        return err
    expected = _sweeps(fp.jacobi, JACOBI_A, JACOBI_B, JACOBI_X0, JACOBI_SWEEPS)
    if np.allclose(got, expected, atol=1e-4):
        return correct(f"{what} is {fmt(expected)}.")
    if np.allclose(got, _sweeps(fp.gauss_seidel, JACOBI_A, JACOBI_B, JACOBI_X0, JACOBI_SWEEPS), atol=1e-4):
        return wrong("that is the Gauss-Seidel iterate: you used the new x at once in the equation for y. Jacobi "
                     "computes both components of a sweep from the previous iterate only.")
    if np.allclose(got, _sweeps(fp.gauss_seidel, JACOBI_A, JACOBI_B, JACOBI_X0, 1), atol=1e-4):
        return wrong("that is one Gauss-Seidel sweep (the new x used for y); Jacobi uses only the previous "
                     "iterate, and the exercise asks for two sweeps.")
    if np.allclose(got, _sweeps(fp.jacobi, JACOBI_A, JACOBI_B, JACOBI_X0, 1), atol=1e-4):
        return wrong("that is the iterate after one Jacobi sweep; do a second sweep from it.")
    if np.allclose(got, np.linalg.solve(JACOBI_A, JACOBI_B), atol=1e-4):
        return wrong("that is the exact solution of the system; two sweeps only get part of the way there.")
    return _components_off(got, expected, "xy", what,
                           "a Jacobi sweep is x = (9 - 2y)/5, y = (6 - x)/4 with the previous x and y on the right")


# -- §7.3.3 ----------------------------------------------------------------------------------------

def check_hausdorff(answer) -> Result:
    """Check the Hausdorff distance h(A, B) for ``HAUSDORFF_A``, ``HAUSDORFF_B``: the larger of the two
    one-sided distances (Goldman §7.3.3).

    Recognises one direction only, the closest pair, and the farthest pair.
    """
    value, problem = read_number(answer, "the Hausdorff distance")
    if problem is not None:
        return problem
    expected = fp.hausdorff_distance(HAUSDORFF_A, HAUSDORFF_B)
    a_to_b = fp.directed_hausdorff(HAUSDORFF_A, HAUSDORFF_B)
    pair = np.linalg.norm(HAUSDORFF_A[:, None, :] - HAUSDORFF_B[None, :, :], axis=-1)
    if abs(value - expected) <= 1e-4:
        return correct(f"the Hausdorff distance is {fmt(expected)}: the point (12, 6) of B is that far from A.")
    if abs(value - a_to_b) <= 1e-4:
        return wrong("that is only the distance from A to B (how far a point of A is from its nearest point of B); "
                     "the Hausdorff distance is the larger of the two directions: measure from B to A too.")
    if abs(value - pair.min()) <= 1e-4:
        return wrong("that is the distance between the closest two points of A and B; the Hausdorff distance asks "
                     "how far the worst point of each set is from the nearest point of the other.")
    if abs(value - pair.max()) <= 1e-4:
        return wrong("that is the largest distance between any two points; the Hausdorff distance uses the "
                     "distance to the *nearest* point of the other set.")
    return check_number(value, expected, what="the Hausdorff distance", tol=1e-4,
                        hint="for each point, find its nearest point in the other set; take the largest of these")


def check_contraction_factor(answer) -> Result:
    """Check the contraction factor of ``STRETCH_L``: the square root of the largest eigenvalue of
    L^T L (Goldman §7.3.3).

    Recognises the eigenvalue (the diagonal of a triangular L), the area factor (determinant),
    the Frobenius norm, the largest column length and a forgotten square root.
    """
    value, problem = read_number(answer, "the contraction factor")
    if problem is not None:
        return problem
    s = fp.contraction_factor(STRETCH_L)
    tol = 1e-4
    if abs(value - s) <= tol:
        return correct(f"the contraction factor is {s:.4f}, more than either diagonal entry: a shearing map "
                       f"stretches some direction more than its eigenvalues say.")
    if abs(value - s * s) <= tol:
        return wrong(f"{fmt(value)} is the largest eigenvalue of L^T L, the square of the stretch; take its square root.")
    if abs(value - max(abs(np.linalg.eigvals(STRETCH_L)))) <= tol:
        return wrong(f"{fmt(value)} is the largest eigenvalue of L (the diagonal of a triangular matrix); the stretch "
                     f"is the largest singular value, the square root of the largest eigenvalue of L^T L.")
    det = abs(np.linalg.det(STRETCH_L))
    if abs(value - det) <= tol or abs(value - math.sqrt(det)) <= tol:
        return wrong(f"{fmt(value)} comes from the determinant, the area factor; the contraction factor is the most "
                     f"the map stretches one distance.")
    if abs(value - np.linalg.norm(STRETCH_L)) <= tol:
        return wrong(f"{fmt(value)} is the Frobenius norm (root of the sum of squared entries), only an upper bound on "
                     f"the stretch; compute the largest eigenvalue of L^T L.")
    if abs(value - np.linalg.norm(STRETCH_L, axis=0).max()) <= tol:
        return wrong(f"{fmt(value)} is the length of a column of L, the image of no vector; with Q = P L the images of "
                     f"(1, 0) and (0, 1) are the rows, and the most stretched direction is neither.")
    return check_number(value, s, what="the contraction factor", tol=tol,
                        hint="the square root of the largest eigenvalue of L^T L (trace and determinant give it)")


def _levels(s: float, h0: float, tol: float) -> int:
    """The smallest n with s^n h0 <= tol."""
    n = max(0, math.ceil(math.log(tol / h0) / math.log(s)))
    while s ** n * h0 > tol:
        n += 1
    while n > 0 and s ** (n - 1) * h0 <= tol:
        n -= 1
    return n


def check_levels_needed(answer) -> Result:
    """Check the smallest n with s^n h(A0, A) <= ``LEVEL_TOL``, s the largest factor of the maps
    (Goldman §7.3.3).

    Recognises the smallest or average factor used instead of the largest, the distance h(A0, A)
    forgotten, and a count one too small or too large.
    """
    value, problem = read_number(answer, "n")
    if problem is not None:
        return problem
    if value != int(value):
        return wrong(f"n counts levels, a whole number; you gave {fmt(value)}. Round up the n that solves "
                     f"s^n h(A0, A) = {fmt(LEVEL_TOL)}.")
    v = int(value)
    if v < 0:
        return wrong(f"n counts levels, a whole number 0 or more; you gave {fmt(value)}.")
    s, h0 = max(LEVEL_FACTORS), LEVEL_START_DISTANCE
    n = _levels(s, h0, LEVEL_TOL)
    if v == n:
        return correct(f"n is {n}: s = {fmt(s)} (the largest factor), and {fmt(s)}^{n} x {fmt(h0)} <= {fmt(LEVEL_TOL)} "
                       f"while one level fewer is not enough.")
    if v == _levels(min(LEVEL_FACTORS), h0, LEVEL_TOL):
        return wrong(f"{v} levels is what the smallest factor, {fmt(min(LEVEL_FACTORS))}, would need; the theorem's s "
                     f"is the largest factor of the maps (the slowest map sets the pace).")
    if v == _levels(sum(LEVEL_FACTORS) / len(LEVEL_FACTORS), h0, LEVEL_TOL):
        return wrong(f"{v} levels is what the average factor would need; the theorem's s is the largest factor of "
                     f"the maps.")
    if v == _levels(s, 1.0, LEVEL_TOL):
        return wrong(f"{v} levels would do if A0 started at distance 1; the bound is s^n h(A0, A) with "
                     f"h(A0, A) = {fmt(h0)}.")
    if v < n:
        return wrong(f"with {v} levels the bound s^n h(A0, A) = {s ** v * h0:.4g} is still above {fmt(LEVEL_TOL)}; "
                     f"{'one more level is' if v == n - 1 else 'more levels are'} needed.")
    return wrong(f"{v} levels are enough but not the fewest; find the smallest n with s^n h(A0, A) <= "
                 f"{fmt(LEVEL_TOL)} (a logarithm, then round up).")


# -- the programming project: Gauss-Seidel sweeps (§7.3.2) -------------------------------------------

def _dominant_system(rng, n: int, *, negative: bool = False):
    """A strictly diagonally dominant n x n system with small decimal entries."""
    A = np.round(rng.uniform(-2, 2, (n, n)), 1)
    np.fill_diagonal(A, 0.0)
    diag = np.abs(A).sum(axis=1) + np.round(rng.uniform(1, 3, n), 1)
    if negative:
        diag = diag * np.where(rng.uniform(size=n) < 0.5, -1.0, 1.0)
    A = A + np.diag(diag)
    b = np.round(rng.uniform(-9, 9, n), 1)
    return A, b


def gauss_seidel_project_cases() -> list[Case]:
    """The project's cases, generated from a fixed seed: sizes 1 to 6, zero and nonzero starts,
    zero, one and several sweeps, a negative diagonal, b = 0 and a start at the solution."""
    rng = np.random.default_rng(7)
    cases: list[Case] = []

    def add(A, b, x0, sweeps, kind, note=""):
        n = len(b)
        label = (f"{n}x{n} system{note}, {sweeps} sweep{'s' if sweeps != 1 else ''} from "
                 f"x0 = {fmt(x0)}")
        if n <= 3:
            label += f", A = [{'; '.join(fmt(r) for r in A)}], b = {fmt(b)}"
        cases.append(Case(label, (A, b, x0, sweeps), kind=kind))

    A, b = _dominant_system(rng, 3)
    add(A, b, np.zeros(3), 3, "")
    A, b = _dominant_system(rng, 2)
    add(A, b, np.zeros(2), 1, "")
    for n in (4, 5, 6):
        A, b = _dominant_system(rng, n)
        add(A, b, np.round(rng.uniform(-3, 3, n), 1), int(rng.integers(2, 6)), "")
    A, b = _dominant_system(rng, 1)
    add(A, b, np.zeros(1), 1, "1x1 systems")
    add(A, b, np.array([5.0]), 4, "1x1 systems")
    A, b = _dominant_system(rng, 3)
    add(A, b, np.array([1.0, -1.0, 2.0]), 0, "no sweeps (x0 returned)")
    A, b = _dominant_system(rng, 4, negative=True)
    add(A, b, np.zeros(4), 3, "negative diagonal entries", " with negative diagonal entries")
    A, _ = _dominant_system(rng, 3)
    add(A, np.zeros(3), np.array([2.0, -1.0, 0.5]), 3, "b = 0", " with b = 0")
    A = np.array([[4.0, -1.0, 0.0], [-1.0, 4.0, -1.0], [0.0, -1.0, 4.0]])
    add(A, A @ np.array([1.0, 2.0, 3.0]), np.array([1.0, 2.0, 3.0]), 2, "start at the solution",
        " started at its solution")
    A, b = _dominant_system(rng, 5)
    add(A, b, np.zeros(5), 25, "many sweeps")
    return cases


def _gauss_seidel_reference(A, b, x0, sweeps):
    return _sweeps(fp.gauss_seidel, A, b, x0, sweeps)


def _compare_gauss_seidel(got, expected, case) -> str | None:
    A, b, x0, sweeps = case.args
    arr = np.asarray(got, dtype=float)
    n = len(b)
    if arr.shape != (n,):
        return f"it should be one vector x of shape ({n},), like b; yours has shape {arr.shape}"
    if not np.all(np.isfinite(arr)):
        return "it contains NaN or infinite values"
    tol = 1e-8 * (1.0 + float(np.abs(expected).max()))
    diff = float(np.abs(arr - expected).max())
    if diff <= tol:
        return None
    head = f"after {sweeps} sweep{'s' if sweeps != 1 else ''} your x differs from Gauss-Seidel's by {fmt(diff, 2)}"
    if sweeps >= 1 and np.allclose(arr, _sweeps(fp.jacobi, A, b, x0, sweeps), rtol=0, atol=tol):
        return f"{head} -- it matches the Jacobi iterate: use the new values as soon as they are computed"
    if sweeps >= 1 and np.allclose(arr, _sweeps(fp.gauss_seidel, A, b, x0, sweeps - 1), rtol=0, atol=tol):
        return f"{head} -- it matches the iterate after {sweeps - 1} sweep{'s' if sweeps - 1 != 1 else ''}: one sweep too few"
    if np.allclose(arr, _sweeps(fp.gauss_seidel, A, b, x0, sweeps + 1), rtol=0, atol=tol):
        return f"{head} -- it matches the iterate after {sweeps + 1} sweep{'s' if sweeps + 1 != 1 else ''}: one sweep too many"
    if sweeps >= 1 and np.allclose(arr, _backward_gauss_seidel(A, b, x0, sweeps), rtol=0, atol=tol):
        return f"{head} -- it matches sweeps from the last unknown to the first: update x[0] first, then x[1] and so on"
    A_, b_ = np.asarray(A, dtype=float), np.asarray(b, dtype=float)
    with_diagonal = np.array(x0, dtype=float)
    for _ in range(sweeps):
        for i in range(n):
            with_diagonal[i] = (b_[i] - A_[i] @ with_diagonal) / A_[i, i]
    if sweeps >= 1 and np.all(np.isfinite(with_diagonal)) and np.allclose(arr, with_diagonal, rtol=0, atol=tol):
        return f"{head} -- your sum includes the diagonal term a_ii x_i: the sum is over j != i only"
    exact = np.linalg.solve(A_, b_)
    if sweeps < 25 and np.allclose(arr, exact, rtol=0, atol=tol):
        return (f"{head} -- it is the exact solution of A x = b: return the iterate after exactly {sweeps} "
                f"sweep{'s' if sweeps != 1 else ''}, not the limit")
    k = int(np.argmax(np.abs(arr - expected) > tol))
    return (f"{head}; the first wrong component is x[{k}], expected {fmt(expected, 6)}; "
            f"x[i] = (b[i] - sum of A[i, j] x[j] over j != i) / A[i, i]")


def check_gauss_seidel_project(function) -> Result:
    """Check the learner's ``gauss_seidel(A, b, x0, sweeps)`` against the library's Gauss-Seidel
    (:func:`goldman_lib.fixed_point.gauss_seidel`) on :func:`gauss_seidel_project_cases`: the x
    after exactly ``sweeps`` sweeps (Goldman §7.3.2).

    >>> def lazy(A, b, x0, sweeps):
    ...     return x0
    >>> print(check_gauss_seidel_project(lazy).message)   # doctest: +ELLIPSIS
    case 1 of 12 (3x3 system, 3 sweeps from x0 = (0, 0, 0), ...): your function returned (0, 0, 0); after 3 sweeps your x differs from Gauss-Seidel's by ...
    """
    return check_project(function, gauss_seidel_project_cases(), reference=_gauss_seidel_reference,
                         compare=_compare_gauss_seidel, what="gauss_seidel",
                         hint="sweep i = 0, 1, ..., n-1 and overwrite x[i] in place, so later rows see it")


SLIPS = {
    "check_fixed_point_limit": [-2, math.sqrt(6), math.sqrt(6 + math.sqrt(6))],
    "check_newton_step": [13 / 6, 10 ** (1 / 3), 1.6],
    "check_gauss_seidel_sweep": [[2, 1.4, 4 / 3], [2, 1, 2 / 3], [1.45, 13 / 15, 4 / 3]],
    "check_jacobi_sweeps": [[1.34, 1.165], [1.4, 1.25], [1.4, 1.15], [4 / 3, 7 / 6]],
    "check_hausdorff": [5, 3, math.hypot(12, 6)],
    "check_contraction_factor": [0.45, 0.5, 0.15, math.sqrt(0.5), math.hypot(0.4, 0.5)],
    "check_levels_needed": [9, 13, 17, 20, 22],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

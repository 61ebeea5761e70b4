"""Exercise checkers for chapter 7, the fixed-point theorem and its applications (Goldman §7.2-7.3).

>>> print(PROBLEMS["check_newton_step"])
Take two steps of Newton's method for f(x) = x^2 - 2 from x0 = 1: give x2 (Goldman §7.3.1).
>>> check_newton_step(17 / 12)
Correct: x2 is 1.417.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import affine
from goldman_lib.exercises import Result, check_number, correct, fmt, read_number, read_points, wrong

__all__ = ["PROBLEMS", "SEIDEL_A", "SEIDEL_B", "CONTRACTION_MAP", "HAUSDORFF_A", "HAUSDORFF_B", "LEVELS_TOL",
           "check_newton_step", "check_gauss_seidel_sweep", "check_contraction_factor", "check_hausdorff",
           "check_levels_needed"]

#: Exercise 2: one Gauss-Seidel sweep from x = 0 on this system.
SEIDEL_A = np.array([[4.0, 1.0], [2.0, 5.0]])
SEIDEL_B = np.array([8.0, 9.0])
#: Exercise 3: the map whose contraction factor is asked for: scale (0.6, 0.3), rotate 40, translate.
CONTRACTION_MAP = affine.from_parameters(angle=40, scale=(0.6, 0.3), translate=(2, 1))
#: Exercise 4: two point sets.
HAUSDORFF_A = np.array([[0.0, 0.0], [1.0, 0.0]])
HAUSDORFF_B = np.array([[0.0, 0.0], [1.0, 0.0], [4.0, 0.0]])
#: Exercise 5: the tolerance for the Sierpinski gasket iterates (s = 1/2, h(A0, A) = 1).
LEVELS_TOL = 1e-3

PROBLEMS = {
    "check_newton_step": "Take two steps of Newton's method for f(x) = x^2 - 2 from x0 = 1: give x2 (Goldman §7.3.1).",
    "check_gauss_seidel_sweep": ("Do one Gauss-Seidel sweep for 4x + y = 8, 2x + 5y = 9 from (x, y) = (0, 0): "
                                 "give the new (x, y) (Goldman §7.3.2)."),
    "check_contraction_factor": ("The map scales by (0.6, 0.3) along the axes, rotates by 40 degrees and translates "
                                 "by (2, 1). What is its contraction factor (Goldman §7.3.3)?"),
    "check_hausdorff": ("Compute the Hausdorff distance between A = {(0,0), (1,0)} and "
                        "B = {(0,0), (1,0), (4,0)} (Goldman §7.3.3)."),
    "check_levels_needed": (f"An IFS has contraction factor s = 1/2 and the start set is at Hausdorff distance 1 "
                            f"from the attractor. By the fractal theorem, what is the smallest number of levels n "
                            f"that guarantees h(W^n(A0), A) <= {LEVELS_TOL:g} (Goldman §7.3.3)?"),
}


def check_newton_step(answer) -> Result:
    """Check x2 of Newton's method on ``x^2 - 2`` from 1: x1 = 3/2, x2 = 17/12 (Goldman §7.3.1).

    >>> check_newton_step(1.5)
    Not yet: 1.5 is x1, one step; take a second step x2 = x1 - f(x1)/f'(x1).
    """
    value, problem = read_number(answer, "x2")
    if problem is not None:
        return problem
    if abs(value - 1.5) <= 1e-6:
        return wrong("1.5 is x1, one step; take a second step x2 = x1 - f(x1)/f'(x1).")
    if abs(value - math.sqrt(2)) <= 1e-6:
        return wrong("that is sqrt(2) itself, the limit; after two steps Newton's method is at 17/12.")
    return check_number(value, 17 / 12, what="x2", tol=1e-4, hint="x_(n+1) = x_n - (x_n^2 - 2) / (2 x_n)")


def check_gauss_seidel_sweep(answer) -> Result:
    """Check one Gauss-Seidel sweep from 0: x = 8/4 = 2, then y = (9 - 2*2)/5 = 1 (Goldman §7.3.2).

    Recognises the Jacobi step (the old x used for y).

    >>> check_gauss_seidel_sweep([2, 1.8])
    Not yet: (2, 1.8) is the Jacobi step; Gauss-Seidel uses the new x = 2 at once when it updates y.
    """
    what = "the new (x, y)"
    got, err = read_points(answer, what)
    if err is not None:
        return err
    if got.shape != (2,):
        return wrong(f"{what} is one pair [x, y]; yours has shape {got.shape}.")
    d = np.diag(SEIDEL_A)
    x = SEIDEL_B[0] / d[0]
    expected = np.array([x, (SEIDEL_B[1] - SEIDEL_A[1, 0] * x) / d[1]])
    jacobi = SEIDEL_B / d
    if np.allclose(got, expected, atol=1e-6):
        return correct(f"{what} is {fmt(expected)}.")
    if np.allclose(got, jacobi, atol=1e-6):
        return wrong(f"{fmt(got)} is the Jacobi step; Gauss-Seidel uses the new x = {fmt(x)} at once when it updates y.")
    if np.allclose(got, np.linalg.solve(SEIDEL_A, SEIDEL_B), atol=1e-6):
        return wrong("that is the exact solution; one sweep only gets part of the way there.")
    return wrong(f"{what} should be {fmt(expected)}: x = (8 - y)/4 with y = 0, then y = (9 - 2x)/5 with the new x.")


def check_contraction_factor(answer) -> Result:
    """Check the contraction factor of ``CONTRACTION_MAP``: the largest scale, 0.6 (rotations and
    translations do not stretch).  Recognises the area factor (the determinant).

    >>> check_contraction_factor(0.18)
    Not yet: 0.18 = 0.6 x 0.3 is the area factor (the determinant); the contraction factor is the most the map stretches any distance.
    """
    value, problem = read_number(answer, "the contraction factor")
    if problem is not None:
        return problem
    if abs(value - 0.18) <= 1e-6:
        return wrong("0.18 = 0.6 x 0.3 is the area factor (the determinant); the contraction factor is the most the "
                     "map stretches any distance.")
    if abs(value - 0.3) <= 1e-6:
        return wrong("0.3 is the least the map stretches; the contraction factor is the largest stretch.")
    expected = float(np.linalg.svd(CONTRACTION_MAP[:2, :2], compute_uv=False)[0])
    return check_number(value, expected, what="the contraction factor", tol=1e-4,
                        hint="rotations and translations keep distances; only the scaling stretches")


def check_hausdorff(answer) -> Result:
    """Check h(A, B) for ``HAUSDORFF_A`` and ``HAUSDORFF_B``: 3 (the point (4, 0) is 3 from A).

    >>> check_hausdorff(0)
    Not yet: 0 is only the distance from A to B (every point of A is in B); the Hausdorff distance also measures B to A: (4, 0) is 3 from A.
    """
    value, problem = read_number(answer, "the Hausdorff distance")
    if problem is not None:
        return problem
    if value == 0:
        return wrong("0 is only the distance from A to B (every point of A is in B); the Hausdorff distance also "
                     "measures B to A: (4, 0) is 3 from A.")
    if abs(value - 4) <= 1e-6:
        return wrong("4 is the largest distance between any two points; the Hausdorff distance uses the distance "
                     "to the *nearest* point of the other set.")
    return check_number(value, 3.0, what="the Hausdorff distance", hint="the nearest point of A to (4, 0) is (1, 0)")


def check_levels_needed(answer) -> Result:
    """Check the smallest n with (1/2)^n <= ``LEVELS_TOL``: 10.

    >>> check_levels_needed(9)
    Not yet: (1/2)^9 = 0.001953 is still above 0.001; one more level is needed.
    """
    value, problem = read_number(answer, "n")
    if problem is not None:
        return problem
    n = math.ceil(math.log(LEVELS_TOL) / math.log(0.5))
    if value == int(value) and value < n:
        return wrong(f"(1/2)^{int(value)} = {0.5 ** value:.4g} is still above {LEVELS_TOL:g}; "
                     f"{'one more level is' if value == n - 1 else 'more levels are'} needed.")
    if value == int(value) and value > n:
        return wrong(f"{int(value)} levels are enough but not the fewest: (1/2)^{n} = {0.5 ** n:.4g} <= {LEVELS_TOL:g} already.")
    return check_number(value, n, what="n", tol=1e-9, hint="solve (1/2)^n <= 0.001 with logarithms")

"""Corpus of the chapter-7 project (Gauss-Seidel sweeps): correct solutions written from the
statement alone (a double loop on arrays, the matrix splitting (D + L) x' = b - U x solved by
forward substitution, pure Python lists, recursion over the sweeps) must be accepted; realistic
wrong ones must be rejected with the slip named."""

import numpy as np
import pytest

from goldman_lib.exercises import ch07


# -- accepted ------------------------------------------------------------------------------------------

def loops(A, b, x0, sweeps):
    A, b = np.asarray(A, float), np.asarray(b, float)
    x = np.array(x0, dtype=float)
    for _ in range(sweeps):
        for i in range(len(b)):
            x[i] = (b[i] - A[i, :i] @ x[:i] - A[i, i + 1:] @ x[i + 1:]) / A[i, i]
    return x


def splitting(A, b, x0, sweeps):
    """(D + L) x_new = b - U x_old, with a forward substitution of my own."""
    A, b = np.asarray(A, float), np.asarray(b, float)
    DL, U = np.tril(A), np.triu(A, 1)
    x = np.asarray(x0, float).copy()
    for _ in range(sweeps):
        rhs = b - U @ x
        new = np.zeros_like(x)
        for i in range(len(b)):
            new[i] = (rhs[i] - DL[i, :i] @ new[:i]) / DL[i, i]
        x = new
    return x


def pure_lists(A, b, x0, sweeps):
    """Python lists throughout, a list returned."""
    A = [[float(v) for v in row] for row in A]
    x = [float(v) for v in x0]
    n = len(x)
    for _ in range(sweeps):
        for i in range(n):
            s = sum(A[i][j] * x[j] for j in range(n) if j != i)
            x[i] = (float(b[i]) - s) / A[i][i]
    return x


def recursive(A, b, x0, sweeps):
    if sweeps == 0:
        return np.asarray(x0, float).copy()
    return loops(A, b, recursive(A, b, x0, sweeps - 1), 1)


ACCEPTED = [loops, splitting, pure_lists, recursive]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch07.check_gauss_seidel_project(solution)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def jacobi(A, b, x0, sweeps):                    # the old values throughout a sweep
    A, b = np.asarray(A, float), np.asarray(b, float)
    x = np.array(x0, dtype=float)
    D = np.diag(A)
    for _ in range(sweeps):
        x = (b - (A @ x - D * x)) / D
    return x


def one_sweep_too_many(A, b, x0, sweeps):        # range(sweeps + 1)
    return loops(A, b, x0, sweeps + 1)


def one_sweep_too_few(A, b, x0, sweeps):         # the first sweep skipped
    return loops(A, b, x0, max(sweeps - 1, 0))


def backwards(A, b, x0, sweeps):                 # i = n-1, ..., 0
    A, b = np.asarray(A, float), np.asarray(b, float)
    x = np.array(x0, dtype=float)
    for _ in range(sweeps):
        for i in reversed(range(len(b))):
            x[i] = (b[i] - (A[i] @ x - A[i, i] * x[i])) / A[i, i]
    return x


def diagonal_in_the_sum(A, b, x0, sweeps):       # sum over all j, the a_ii x_i term included
    A, b = np.asarray(A, float), np.asarray(b, float)
    x = np.array(x0, dtype=float)
    for _ in range(sweeps):
        for i in range(len(b)):
            x[i] = (b[i] - A[i] @ x) / A[i, i]
    return x


def the_limit(A, b, x0, sweeps):                 # the solution, not the iterate
    return np.linalg.solve(np.asarray(A, float), np.asarray(b, float))


REJECTED = [
    (jacobi, "Jacobi iterate"),
    (one_sweep_too_many, "one sweep too many"),
    (one_sweep_too_few, "one sweep too few"),
    (backwards, "from the last unknown to the first"),
    (diagonal_in_the_sum, "includes the diagonal term"),
    (the_limit, "exact solution of A x = b"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch07.check_gauss_seidel_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message

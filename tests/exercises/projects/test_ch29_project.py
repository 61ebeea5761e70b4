"""Corpus of the chapter-29 project (the subdivision matrices of a Bézier curve): correct solutions
written from the statement alone (de Casteljau on the identity, the Bernstein formulas with lists,
R obtained from L by the symmetry R(t) = J L(1 - t) J) must be accepted; realistic wrong ones must be
rejected with the slip named."""

from math import comb

import numpy as np
import pytest

from goldman_lib.exercises import ch29


# -- accepted ------------------------------------------------------------------------------------------

def casteljau_identity(n, t=0.5):
    P = np.eye(n + 1)
    L, R = np.zeros((n + 1, n + 1)), np.zeros((n + 1, n + 1))
    for r in range(n + 1):
        L[r], R[n - r] = P[0], P[-1]
        P = (1 - t) * P[:-1] + t * P[1:]
    return L, R


def bernstein_lists(n, t=0.5):
    """L[i][j] = C(i, j) t^j (1-t)^(i-j); R[i][j] = C(n-i, j-i) t^(j-i) (1-t)^(n-j); lists of lists."""
    L = [[comb(i, j) * t ** j * (1 - t) ** (i - j) if j <= i else 0.0 for j in range(n + 1)] for i in range(n + 1)]
    R = [[comb(n - i, j - i) * t ** (j - i) * (1 - t) ** (n - j) if j >= i else 0.0 for j in range(n + 1)]
         for i in range(n + 1)]
    return [L, R]


def by_symmetry(n, t=0.5):
    """L from the formula, R by reversing the curve: R(t) = J L(1 - t) J."""
    def left(s):
        return np.array([[comb(i, j) * s ** j * (1 - s) ** (i - j) if j <= i else 0.0 for j in range(n + 1)]
                         for i in range(n + 1)])
    J = np.eye(n + 1)[::-1]
    return left(t), J @ left(1 - t) @ J


ACCEPTED = [casteljau_identity, bernstein_lists, by_symmetry]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch29.check_subdivision_matrices_project(solution)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def swapped(n, t=0.5):
    L, R = casteljau_identity(n, t)
    return R, L


def transposed(n, t=0.5):                        # the column convention
    L, R = casteljau_identity(n, t)
    return L.T, R.T


def right_rows_reversed(n, t=0.5):               # R[r] = last point of row r
    P = np.eye(n + 1)
    L, R = np.zeros((n + 1, n + 1)), np.zeros((n + 1, n + 1))
    for r in range(n + 1):
        L[r], R[r] = P[0], P[-1]
        P = (1 - t) * P[:-1] + t * P[1:]
    return L, R


def one_minus_t(n, t=0.5):                       # t P_j + (1 - t) P_(j+1)
    return casteljau_identity(n, 1 - t)


def always_half(n, t=0.5):                       # the midpoint matrices whatever t
    return casteljau_identity(n, 0.5)


REJECTED = [
    (swapped, "L and R are swapped"),
    (transposed, "is transposed"),
    (right_rows_reversed, "the rows of R are in reverse order"),
    (one_minus_t, "the split at 1 - t"),
    (always_half, "the split at t = 1/2"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch29.check_subdivision_matrices_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message

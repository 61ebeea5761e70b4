"""Corpus of the chapter-23 project (progressive refinement): correct solvers written from the
statement alone (shooting with F_ji = A_i F_ij / A_j, shooting that reads F[j, i] and picks the
largest dB_i, a direct solve, Gauss-Seidel gathering; lists or arrays) must be accepted -- the closed
box included, whose expected radiosities must satisfy B = E + rho F B; realistic wrong ones must be
rejected with the slip named."""

import numpy as np
import pytest

from goldman_lib.exercises import ch23


# -- accepted ------------------------------------------------------------------------------------------

def shooting(F, rho, E, area):
    F, rho, E, area = (np.asarray(a, float) for a in (F, rho, E, area))
    B, dB = E.copy(), E.copy()
    while dB.max() > 1e-13:
        i = int(np.argmax(area * dB))
        got = rho * (area[i] * F[i] / area) * dB[i]
        B += got
        dB += got
        dB[i] = 0.0
    return B


def shooting_by_column(F, rho, E, area):
    """Reads F_ji straight from the matrix, shoots the largest dB_i (not A_i dB_i), returns a list."""
    n = len(E)
    B, dB = [float(e) for e in E], [float(e) for e in E]
    while max(dB) > 1e-13:
        i = max(range(n), key=lambda k: dB[k])
        shot = dB[i]
        dB[i] = 0.0
        for j in range(n):
            r = rho[j] * F[j][i] * shot
            B[j] += r
            dB[j] += r
    return B


def direct_solve(F, rho, E, area):
    F = np.asarray(F, float)
    return np.linalg.solve(np.eye(len(F)) - np.asarray(rho, float)[:, None] * F, np.asarray(E, float))


def gauss_seidel(F, rho, E, area):
    F, rho, E = (np.asarray(a, float) for a in (F, rho, E))
    B = E.copy()
    for _ in range(10000):
        old = B.copy()
        for i in range(len(B)):
            B[i] = E[i] + rho[i] * (F[i] @ B)
        if np.abs(B - old).max() < 1e-14:
            break
    return B


ACCEPTED = [shooting, shooting_by_column, direct_solve, gauss_seidel]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch23.check_progressive_refinement_project(solution)
    assert r.correct, r.message


def test_every_case_is_reciprocal_and_its_expected_b_solves_the_equation():
    for c in ch23.project_cases():
        F, rho, E, area = c.args
        S = area[:, None] * F
        assert np.abs(S - S.T).max() < 1e-12
        assert F.sum(axis=1).max() <= 1 + 1e-12
        B = ch23._reference(*c.args)
        assert np.abs(E + rho * (F @ B) - B).max() < 1e-12
        if c.kind == "closed box":
            assert np.allclose(F.sum(axis=1), 1, atol=1e-12)


# -- rejected ------------------------------------------------------------------------------------------

def _shoot(F, rho, E, area, received, tol=1e-13):
    F, rho, E, area = (np.asarray(a, float) for a in (F, rho, E, area))
    B, dB = E.copy(), E.copy()
    for _ in range(200000):
        if dB.max() <= tol:
            break
        i = int(np.argmax(area * dB))
        got = received(F, rho, area, i) * dB[i]
        B += got
        dB += got
        dB[i] = 0.0
    return B


def gather_once(F, rho, E, area):               # one Jacobi step from B = E
    return np.asarray(E, float) + np.asarray(rho, float) * (np.asarray(F, float) @ np.asarray(E, float))


def row_for_column(F, rho, E, area):            # F_ij used for F_ji (no reciprocity)
    return _shoot(F, rho, E, area, lambda F, rho, A, i: rho * F[i])


def area_ratio_upside_down(F, rho, E, area):    # A_j F_ij / A_i
    return _shoot(F, rho, E, area, lambda F, rho, A, i: rho * F[i] * A / A[i])


def shooters_reflectance(F, rho, E, area):      # rho_i instead of rho_j
    return _shoot(F, rho, E, area, lambda F, rho, A, i: rho[i] * F[i] * A[i] / A)


def stops_early(F, rho, E, area):               # stops when the unshot radiosity is below 1e-2
    return _shoot(F, rho, E, area, lambda F, rho, A, i: rho * F[i] * A[i] / A, tol=1e-2)


def no_reflectance(F, rho, E, area):            # rho_j forgotten
    return _shoot(F, rho, E, area, lambda F, rho, A, i: F[i] * A[i] / A, tol=1e-9)


REJECTED = [
    (gather_once, "one gathering step"),
    (row_for_column, "read as F_ji"),
    (area_ratio_upside_down, "area ratio is upside down"),
    (shooters_reflectance, "the shooter's reflectance"),
    (stops_early, "did you shoot until the unshot radiosity is negligible"),
    (no_reflectance, "reflectance rho_j is missing"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch23.check_progressive_refinement_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message

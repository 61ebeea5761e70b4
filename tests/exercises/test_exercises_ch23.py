"""Chapter 23 checkers: right answers worked by hand, each slip's message, and the project checker
(a correct solver, a subtly wrong one, a crashing one)."""

import numpy as np

from goldman_lib.exercises import ch23


def test_right_answers_by_hand():
    # Jacobi: B1 = 2 + 0.5*0.4*1 = 2.2, B2 = 1 + 0.8*0.2*2 = 1.32
    assert ch23.check_jacobi_step([2.2, 1.32]).correct
    # Gauss-Seidel: B1 = 1 + 0.6*0.4*3 = 1.72, B2 = 3 + 0.5*0.2*1.72 = 3.172
    assert ch23.check_gauss_seidel_step([1.72, 3.172]).correct
    # reciprocity: 2.5 * 0.12 / 0.8 = 0.375
    assert ch23.check_reciprocity(0.375).correct
    # closed form, X = Y = 2: 0.41525
    assert ch23.check_parallel_form_factor(0.415).correct and ch23.check_parallel_form_factor(0.4153).correct
    # shot: F_21 = 2*0.3/1 = 0.6, F_31 = 2*0.1/0.5 = 0.4; dB2 = 1 + 0.5*0.6*1.5, dB3 = 2 + 0.8*0.4*1.5
    assert ch23.check_shot([0, 1.45, 2.48]).correct


def test_slips_get_their_messages():
    assert "Gauss-Seidel" in ch23.check_jacobi_step([2.2, 1.352]).message
    assert "F_ji where F_ij" in ch23.check_jacobi_step([2.1, 1.64]).message
    assert "reflectance is missing" in ch23.check_jacobi_step([2.4, 1.4]).message
    assert "own emission" in ch23.check_jacobi_step([0.2, 0.32]).message
    assert "Jacobi step" in ch23.check_gauss_seidel_step([1.72, 3.1]).message
    assert "patch 2 first" in ch23.check_gauss_seidel_step([1.744, 3.1]).message
    assert "emission is missing" in ch23.check_gauss_seidel_step([0.72, 0.172]).message
    assert "wrong way" in ch23.check_reciprocity(0.0384).message
    assert "not symmetric" in ch23.check_reciprocity(0.12).message
    assert "1 - F_ij" in ch23.check_reciprocity(0.88).message
    assert "distance / side" in ch23.check_parallel_form_factor(0.0686).message
    assert "A / (pi d^2)" in ch23.check_parallel_form_factor(1.2732).message
    assert "unit squares" in ch23.check_parallel_form_factor(0.1998).message
    assert "reciprocity" in ch23.check_shot([0, 1.225, 2.12]).message
    assert "clear its dB" in ch23.check_shot([1.5, 1.45, 2.48]).message
    assert "reflectance is missing" in ch23.check_shot([0, 1.9, 2.6]).message
    assert not ch23.check_shot(None).correct and "Not answered" in repr(ch23.check_shot(None))
    assert "3 numbers" in ch23.check_shot([1, 2]).message
    assert "number" in ch23.check_reciprocity("abc").message


def _correct(F, rho, E, area):
    B, dB = E.astype(float).copy(), E.astype(float).copy()
    while np.abs(dB).max() > 1e-13:
        i = int(np.argmax(area * dB))
        received = rho * F[i] * area[i] / area * dB[i]
        B += received
        dB += received
        dB[i] = 0.0
    return B


def _no_reciprocity(F, rho, E, area):
    B, dB = E.astype(float).copy(), E.astype(float).copy()
    while np.abs(dB).max() > 1e-13:
        i = int(np.argmax(area * dB))
        received = rho * F[i] * dB[i]                # F_ij used as F_ji
        B += received
        dB += received
        dB[i] = 0.0
    return B


def _crashing(F, rho, E, area):
    return F[len(F)] * E


def test_project_checker():
    assert ch23.check_progressive_refinement_project(_correct).correct
    msg = ch23.check_progressive_refinement_project(_no_reciprocity).message
    assert msg.startswith("case 1 of 6 (a random scene of 4 patches with unequal areas)")
    bad = ch23.check_progressive_refinement_project(_crashing).message
    assert "IndexError" in bad and "F[len(F)]" in bad
    assert "Not answered" in repr(ch23.check_progressive_refinement_project(None))
    kinds = {c.kind for c in ch23.project_cases()}
    assert kinds == {"random scene", "closed box", "no emission", "black patch", "one patch"}

"""Chapter 7 exercise checkers: hand-worked right answers pass, each recognised slip gets its own
message, None is 'not answered'; the Gauss-Seidel project checker passes a correct function and names
the failing case of a subtly wrong or crashing one."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import ch07

CASES = [
    # L = sqrt(6 + L): L^2 - L - 6 = (L - 3)(L + 2) = 0; -2 is no fixed point of a square root
    (ch07.check_fixed_point_limit, 3, -2, "never negative"),
    # x1 = 2 + 2/12 = 13/6; x2 = 13/6 - (37/216)/(169/12) = 3277/1521
    (ch07.check_newton_step, 3277 / 1521, 13 / 6, "x1, one step"),
    # x = 8/4 = 2; y = (7 - 2)/5 = 1; z = (8 - 4 - 1)/6 = 1/2; Jacobi: (2, 7/5, 8/6)
    (ch07.check_gauss_seidel_sweep, [2, 1, 0.5], [2, 1.4, 4 / 3], "Jacobi step"),
    # sweep 1: (7/5, 5/4); sweep 2: ((9 - 2.5)/5, (6 - 1.4)/4) = (1.3, 1.15); Gauss-Seidel: (1.34, 1.165)
    (ch07.check_jacobi_sweeps, [1.3, 1.15], [1.34, 1.165], "Gauss-Seidel iterate"),
    # A -> B: 5 ((4, 0) to (0, 3)); B -> A: 10 ((12, 6) to (4, 0), a 6-8-10 triangle)
    (ch07.check_hausdorff, 10, 5, "only the distance from A to B"),
    # L^T L = [[0.09, 0.12], [0.12, 0.41]], eigenvalues 0.45 and 0.05: s = sqrt(0.45)
    (ch07.check_contraction_factor, math.sqrt(0.45), 0.45, "square root"),
    # 4 * 0.75^n <= 0.01: n >= ln(0.0025)/ln(0.75) = 20.8
    (ch07.check_levels_needed, 21, 9, "smallest factor"),
]


@pytest.mark.parametrize("checker,right,wrong_answer,reason", CASES, ids=[c[0].__name__ for c in CASES])
def test_right_wrong_and_unanswered(checker, right, wrong_answer, reason):
    r = checker(right)
    assert r.correct and r.answered, r
    w = checker(wrong_answer)
    assert not w.correct and w.answered and reason in w.message, w
    assert not checker(None).answered


def test_hand_decimals_are_accepted():
    assert ch07.check_newton_step(2.154504).correct
    assert ch07.check_gauss_seidel_sweep([2.0, 1.0, 0.50001]).correct
    assert ch07.check_contraction_factor(0.6708).correct
    assert ch07.check_fixed_point_limit(3.00001).correct


@pytest.mark.parametrize("checker,slip,reason", [
    (ch07.check_fixed_point_limit, math.sqrt(6), "x1"),
    (ch07.check_fixed_point_limit, math.sqrt(6 + math.sqrt(6)), "x2, an early iterate"),
    (ch07.check_newton_step, 10 ** (1 / 3), "the limit"),           # 2.154435, not the second iterate
    (ch07.check_newton_step, 1.6, "three times x squared"),                 # x1 = 2 + 2/4, x2 = 2.5 - 5.625/6.25
    (ch07.check_newton_step, 1.452709, "subtracts f/f'"),           # x1 = 11/6, x2 = x1 + f(x1)/f'(x1)
    (ch07.check_gauss_seidel_sweep, [2, 1, 2 / 3], "old y"),        # z = (8 - 4 - 0)/6
    (ch07.check_gauss_seidel_sweep, [1.45, 13 / 15, 4 / 3], "from z back to x"),
    (ch07.check_gauss_seidel_sweep, [165 / 101, 82 / 101, 66 / 101], "exact solution"),  # 4*165 + 82 + 66 = 808 = 8*101
    (ch07.check_jacobi_sweeps, [1.4, 1.25], "after one Jacobi sweep"),
    (ch07.check_jacobi_sweeps, [1.4, 1.15], "one Gauss-Seidel sweep"),
    (ch07.check_jacobi_sweeps, [4 / 3, 7 / 6], "exact solution"),
    (ch07.check_hausdorff, 3, "closest two points"),
    (ch07.check_hausdorff, math.hypot(12, 6), "largest distance between any two points"),
    (ch07.check_contraction_factor, 0.5, "eigenvalue of L"),
    (ch07.check_contraction_factor, 0.15, "determinant"),
    (ch07.check_contraction_factor, math.sqrt(0.5), "Frobenius"),
    (ch07.check_contraction_factor, math.hypot(0.4, 0.5), "column"),
    (ch07.check_levels_needed, 13, "average factor"),
    (ch07.check_levels_needed, 17, "distance 1"),
    (ch07.check_levels_needed, 20, "one more level"),
    (ch07.check_levels_needed, 22, "not the fewest"),
    (ch07.check_levels_needed, 20.8, "whole number"),
])
def test_each_slip_is_named(checker, slip, reason):
    r = checker(slip)
    assert r.answered and not r.correct and reason in r.message, r


def test_garbage_and_wrong_shapes_get_messages():
    assert "shape" in ch07.check_gauss_seidel_sweep([2, 1]).message
    assert "shape" in ch07.check_jacobi_sweeps([[1.3, 1.15]]).message
    assert not ch07.check_hausdorff("ten").correct


# -- the programming project -------------------------------------------------------------------------

def gauss_seidel(A, b, x0, sweeps):
    A, b, x = np.asarray(A, float), np.asarray(b, float), np.array(x0, float)
    for _ in range(sweeps):
        for i in range(len(b)):
            x[i] = (b[i] - (A[i] @ x - A[i, i] * x[i])) / A[i, i]
    return x


def jacobi_instead(A, b, x0, sweeps):
    A, b, x = np.asarray(A, float), np.asarray(b, float), np.array(x0, float)
    d = np.diag(A)
    for _ in range(sweeps):
        x = (b - (A - np.diag(d)) @ x) / d
    return x


def one_sweep_too_few(A, b, x0, sweeps):
    return gauss_seidel(A, b, x0, max(sweeps - 1, 0))


def at_least_one_sweep(A, b, x0, sweeps):
    return gauss_seidel(A, b, x0, max(sweeps, 1))


def crashing(A, b, x0, sweeps):
    x = list(x0)
    return x[len(b)]


def test_project_accepts_a_correct_gauss_seidel():
    r = ch07.check_gauss_seidel_project(gauss_seidel)
    assert r.correct, r
    assert "1x1 systems" in r.message and "no sweeps" in r.message


def test_project_names_the_jacobi_slip_in_the_failing_case():
    r = ch07.check_gauss_seidel_project(jacobi_instead)
    assert not r.correct and r.answered
    assert r.message.startswith("case 1 of 12 (3x3 system, 3 sweeps from x0 = (0, 0, 0)"), r
    assert "after 3 sweeps your x differs from Gauss-Seidel's by" in r.message
    assert "it matches the Jacobi iterate: use the new values as soon as they are computed" in r.message


def test_project_names_one_sweep_too_few_and_too_many():
    r = ch07.check_gauss_seidel_project(one_sweep_too_few)
    assert "case 1 of 12" in r.message and "after 2 sweeps: one sweep too few" in r.message, r
    r = ch07.check_gauss_seidel_project(at_least_one_sweep)
    assert "0 sweeps from x0 = (1, -1, 2)" in r.message and "one sweep too many" in r.message, r


def test_project_reports_a_crash_with_the_learners_line():
    r = ch07.check_gauss_seidel_project(crashing)
    assert not r.correct and "raised IndexError" in r.message and "return x[len(b)]" in r.message, r


def test_project_unanswered_and_not_a_function():
    def starter(A, b, x0, sweeps):
        """docstring only"""
        ...
    assert not ch07.check_gauss_seidel_project(starter).answered
    assert not ch07.check_gauss_seidel_project(None).answered
    assert "function itself" in ch07.check_gauss_seidel_project(np.zeros(3)).message


def test_project_cases_are_fixed_and_cover_the_degenerate_kinds():
    a, b = ch07.gauss_seidel_project_cases(), ch07.gauss_seidel_project_cases()
    assert [c.label for c in a] == [c.label for c in b]
    assert {len(c.args[1]) for c in a} == {1, 2, 3, 4, 5, 6}
    assert {"1x1 systems", "no sweeps (x0 returned)", "b = 0", "start at the solution",
            "negative diagonal entries"} <= {c.kind for c in a}

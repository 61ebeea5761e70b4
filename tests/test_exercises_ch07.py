"""Chapter 7 exercise checkers: hand-worked right answers pass, typical slips fail with the reason,
None is 'not answered'."""

import pytest

from goldman_lib.exercises import ch07

CASES = [
    # x1 = 1 - (1 - 2)/2 = 3/2; x2 = 3/2 - (9/4 - 2)/3 = 17/12
    (ch07.check_newton_step, 17 / 12, 1.5, "x1"),
    # x = 8/4 = 2; y = (9 - 2*2)/5 = 1; Jacobi would give y = 9/5
    (ch07.check_gauss_seidel_sweep, [2, 1], [2, 1.8], "Jacobi"),
    # rotation and translation keep lengths: the largest axis scale
    (ch07.check_contraction_factor, 0.6, 0.18, "determinant"),
    # (4, 0) is 3 from (1, 0)
    (ch07.check_hausdorff, 3, 0, "B to A"),
    # 2^-10 = 1/1024 <= 0.001 < 2^-9
    (ch07.check_levels_needed, 10, 9, "one more level"),
]


@pytest.mark.parametrize("checker,right,wrong_answer,reason", CASES, ids=[c[0].__name__ for c in CASES])
def test_right_wrong_and_unanswered(checker, right, wrong_answer, reason):
    r = checker(right)
    assert r.correct and r.answered, r
    w = checker(wrong_answer)
    assert not w.correct and w.answered and reason in w.message, w
    n = checker(None)
    assert not n.answered


def test_other_slips_are_explained():
    assert "limit" in ch07.check_newton_step(2 ** 0.5).message
    assert "exact solution" in ch07.check_gauss_seidel_sweep([31 / 18, 10 / 9]).message
    assert "least" in ch07.check_contraction_factor(0.3).message
    assert "nearest" in ch07.check_hausdorff(4).message
    assert "fewest" in ch07.check_levels_needed(12).message
    assert not ch07.check_hausdorff("three").correct

"""goldman_lib.roots: real roots of polynomials against numpy.roots and values written out (Goldman
§19.3-19.7), and the unchecked kernels the surfaces call per ray against the checked functions."""

import numpy as np
import pytest

from goldman_lib import roots
from goldman_lib.kernels import roots as kernels


def test_quadratic_roots_stable_for_tiny_roots():
    # t^2 - 1e8 t + 1 = 0: roots 1e8 and 1e-8; the naive formula loses the small one
    r = roots.quadratic_roots([1.0], [-1e8], [1.0])[0]
    assert r[0] == pytest.approx(1e-8, rel=1e-12) and r[1] == pytest.approx(1e8, rel=1e-12)


def test_real_roots_against_numpy_roots():
    rng = np.random.default_rng(4)
    c = rng.normal(size=(200, 7))
    got = roots.real_roots(c)
    for k in range(200):
        r = np.roots(c[k])
        if np.any((np.abs(r.imag) > 1e-9) & (np.abs(r.imag) < 1e-5)):
            continue
        real = np.sort(r.real[np.abs(r.imag) <= 1e-9])
        assert np.allclose(got[k, :len(real)], real, rtol=1e-8, atol=1e-8)
        assert np.all(np.isinf(got[k, len(real):]))
    for degree in (2, 3, 4):
        c = rng.normal(size=(300, degree + 1))
        got = roots.real_roots(c)
        for k in range(300):
            r = np.roots(c[k])
            if np.any((np.abs(r.imag) > 1e-9) & (np.abs(r.imag) < 1e-5)):
                continue
            real = np.sort(r.real[np.abs(r.imag) <= 1e-9])
            assert np.allclose(got[k, :len(real)], real, rtol=1e-7, atol=1e-7), (degree, k)
            assert np.all(np.isinf(got[k, len(real):])), (degree, k)
    # a lower degree by leading zeros
    assert np.allclose(roots.real_roots([[0, 0, 1, -3, 2]]), [[1, 2, np.inf, np.inf]])


@pytest.mark.parametrize("coefficients, expected", [
    ([1, -3, 2], [1.0, 2.0]),                                   # (t - 1)(t - 2)
    ([1, 0, 1], [np.inf, np.inf]),                              # t^2 + 1: none
    ([1, -6, 11, -6], [1.0, 2.0, 3.0]),                         # (t - 1)(t - 2)(t - 3), by the companion matrix
    ([2, 0, -2, 0], [-1.0, 0.0, 1.0]),                          # 2t (t^2 - 1)
    ([1, -10, 35, -50, 24], [1.0, 2.0, 3.0, 4.0]),              # (t-1)(t-2)(t-3)(t-4), by Ferrari
    ([1, 0, -2, 0, 1], [-1.0, -1.0, 1.0, 1.0]),                 # (t^2 - 1)^2: double roots
    ([1, 0, 0, 0, -16], [-2.0, 2.0, np.inf, np.inf]),           # t^4 - 16: two real, two imaginary
    ([1, -15, 85, -225, 274, -120], [1.0, 2.0, 3.0, 4.0, 5.0]),  # degree 5
])
def test_real_roots_written_out(coefficients, expected):
    got = roots.real_roots(coefficients)[0]
    assert got == pytest.approx(expected, rel=1e-9, abs=1e-9)
    finite = np.isfinite(expected)
    want = np.sort(np.roots(coefficients).real[np.abs(np.roots(coefficients).imag) < 1e-6])
    assert got[finite] == pytest.approx(want, rel=1e-6, abs=1e-6)


def test_a_quartic_as_numpy_polynomial_sees_it():
    # Polynomial takes its coefficients lowest degree first; its roots of t^4 - 5 t^2 + 4
    P = np.polynomial.Polynomial([4, 0, -5, 0, 1])
    assert roots.real_roots([1, 0, -5, 0, 4])[0] == pytest.approx(np.sort(P.roots().real))


def test_the_kernels_are_what_the_checked_functions_return():
    rng = np.random.default_rng(7)
    a, b, c = rng.normal(size=(3, 500))
    assert np.array_equal(kernels.quadratic_roots(a, b, c), roots.quadratic_roots(a, b, c))
    C = rng.normal(size=(300, 5))
    scaled = C / np.abs(C).max(axis=1, keepdims=True)
    with np.errstate(all="ignore"):                   # the kernels leave floating-point flags to their callers
        assert np.array_equal(kernels.polynomial_roots(scaled), roots.real_roots(C))
        # the depressed quartic s^4 - 5 s^2 + 4 (roots -2, -1, 1, 2) and s^4 - s (roots 0, 1)
        got = kernels.depressed_quartic_roots(np.array([-5.0, 0.0]), np.array([0.0, -1.0]), np.array([4.0, 0.0]))
    assert got[0] == pytest.approx([-2, -1, 1, 2]) and got[1] == pytest.approx([0, 1, np.inf, np.inf])


@pytest.mark.parametrize("bad, word", [
    (lambda: roots.real_roots([[1.0]]), "coefficients"),
    (lambda: roots.real_roots(np.ones((2, 15))), "coefficients"),
    (lambda: roots.real_roots([1, np.nan, 2]), "coefficients"),
    (lambda: roots.quadratic_roots([1, 2], [1, 2, 3], [1]), "same shape"),
    (lambda: roots.quadratic_roots([np.inf], [1], [1]), "a"),
])
def test_bad_coefficients_are_named(bad, word):
    with pytest.raises(ValueError, match=word):
        bad()

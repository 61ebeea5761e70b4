"""goldman_lib.blossom against independent references: the blossom's defining properties
(symmetric, multiaffine, diagonal) as hypothesis theorems, closed-form blossoms of monomials
(elementary symmetric functions), numpy.polynomial for the conversions and derivatives, and
de Casteljau evaluation for subdivision."""

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from numpy.polynomial import Polynomial

from goldman_lib import bezier
from goldman_lib import blossom as bl

coord = st.floats(-5, 5, allow_nan=False, allow_infinity=False)
param = st.floats(-2, 3, allow_nan=False, allow_infinity=False)


def curves(min_deg=1, max_deg=6, dim=2):
    return st.integers(min_deg, max_deg).flatmap(lambda n: arrays(float, (n + 1, dim), elements=coord))


def with_args(min_deg=1, max_deg=6, dim=2):
    return curves(min_deg, max_deg, dim).flatmap(
        lambda P: st.tuples(st.just(P), arrays(float, (len(P) - 1,), elements=param)))


def tol_for(P):
    return 1e-9 * max(1.0, np.abs(P).max()) * 30 ** (len(P) - 1) / 30


# -- §26.2 the three axioms -------------------------------------------------------------------

@settings(max_examples=60, deadline=None)
@given(with_args(), st.randoms(use_true_random=False))
def test_blossom_is_symmetric(Pu, rnd):
    P, u = Pu
    perm = list(u)
    rnd.shuffle(perm)
    np.testing.assert_allclose(bl.blossom(P, perm), bl.blossom(P, u), atol=tol_for(P))


@settings(max_examples=60, deadline=None)
@given(with_args(), param, param, st.floats(-1, 2), st.integers(0, 5))
def test_blossom_is_multiaffine(Pu, x, y, alpha, slot):
    P, u = Pu
    slot = slot % len(u)
    ux, uy, mix = u.copy(), u.copy(), u.copy()
    ux[slot], uy[slot], mix[slot] = x, y, (1 - alpha) * x + alpha * y
    expected = (1 - alpha) * bl.blossom(P, ux) + alpha * bl.blossom(P, uy)
    np.testing.assert_allclose(bl.blossom(P, mix), expected, atol=tol_for(P) * 10)


@settings(max_examples=60, deadline=None)
@given(curves(0, 8, 3), param)
def test_blossom_diagonal_is_the_curve(P, t):
    n = len(P) - 1
    np.testing.assert_allclose(bl.blossom(P, np.full(n, t)), bezier.de_casteljau(P, t), atol=tol_for(P))


@settings(max_examples=40, deadline=None)
@given(curves(0, 8, 2))
def test_control_points_are_blossom_values_at_zeros_and_ones(P):
    n = len(P) - 1
    args = [[0.0] * (n - k) + [1.0] * k for k in range(n + 1)]
    np.testing.assert_allclose(bl.blossom(P, np.array(args).reshape(n + 1, n)), P, atol=1e-12)


def test_blossom_of_monomials_is_the_elementary_symmetric_function():
    # t^j in degree n: the Bezier points come from the conversion; its blossom must be
    # e_j(u_1, ..., u_n) / C(n, j)  (closed form)
    n = 4
    u = np.array([0.3, -0.7, 1.9, 0.45])
    for j in range(n + 1):
        coeffs = np.zeros(n + 1)
        coeffs[j] = 1.0
        P = bl.monomial_to_bezier(coeffs)[:, None]
        e_j = sum(np.prod(c) for c in itertools.combinations(u, j)) if j else 1.0
        assert bl.blossom(P, u)[0] == pytest.approx(e_j / math.comb(n, j), abs=1e-12)


def test_blossom_is_vectorised_over_leading_axes():
    P = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0]])
    U = np.random.default_rng(0).uniform(0, 1, (5, 2, 3))
    out = bl.blossom(P, U)
    assert out.shape == (5, 2, 2)
    np.testing.assert_allclose(out[3, 1], bl.blossom(P, U[3, 1]))


def test_blossom_steps_are_blossom_values():
    P = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0]])
    u = np.array([0.2, 0.9, 0.4])
    n = 3
    for r, level in enumerate(bl.blossom_steps(P, u)):
        for k, point in enumerate(level):
            args = list(u[:r]) + [0.0] * (n - r - k) + [1.0] * k
            np.testing.assert_allclose(point, bl.blossom(P, args), atol=1e-13)


# -- §26.3 subdivision and intervals ------------------------------------------------------------

@settings(max_examples=50, deadline=None)
@given(curves(0, 7, 2), param, param)
def test_control_points_on_an_interval_reparametrise_the_curve(P, a, b):
    Q = bl.control_points_on_interval(P, a, b)
    s = np.linspace(0, 1, 9)
    scale = max(1.0, np.abs(P).max()) * 4 ** (len(P) - 1)
    np.testing.assert_allclose(bezier.de_casteljau(Q, s), bezier.de_casteljau(P, a + (b - a) * s), atol=1e-11 * scale)


@settings(max_examples=40, deadline=None)
@given(curves(0, 7, 2), st.floats(0, 1))
def test_subdivision_by_blossom_equals_de_casteljau_subdivision(P, t):
    left, right = bl.subdivide_by_blossom(P, t)
    ref_left, ref_right = bezier.subdivide(P, t)
    scale = max(1.0, np.abs(P).max())
    np.testing.assert_allclose(left, ref_left, atol=1e-12 * scale)
    np.testing.assert_allclose(right, ref_right, atol=1e-12 * scale)


# -- §26.4 homogeneous blossom, derivatives, conversions ------------------------------------

def power_polys(P):
    """The coordinate polynomials of a Bezier curve in numpy.polynomial (an independent reference)."""
    P = np.asarray(P, float)
    n = len(P) - 1
    return [sum(math.comb(n, k) * P[k, c] * Polynomial([0, 1]) ** k * Polynomial([1, -1]) ** (n - k)
                for k in range(n + 1)) for c in range(P.shape[1])]


@settings(max_examples=40, deadline=None)
@given(curves(0, 6, 2), st.floats(-1, 2), st.integers(0, 7))
def test_derivative_by_blossom_matches_numpy_polynomial(P, t, order):
    ref = np.array([p.deriv(order)(t) if order else p(t) for p in power_polys(P)])
    scale = max(1.0, np.abs(P).max()) * 10 ** min(order, len(P))
    np.testing.assert_allclose(bl.derivative_by_blossom(P, t, order), ref, atol=1e-9 * scale)


def test_homogeneous_blossom_with_unit_weights_is_the_blossom_and_mass_multiplies():
    P = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0]])
    u = np.array([0.2, 0.5, 0.9])
    hb = bl.homogeneous_blossom(P, np.stack([u, np.ones(3)], 1))
    np.testing.assert_allclose(hb, np.append(bl.blossom(P, u), 1.0))
    # multilinear (not just multiaffine): scaling a pair (t, w) scales the result
    pairs = np.array([[0.2, 1.0], [1.0, 2.0], [0.9, 1.0]])     # (1, 2) is the point t = 1/2 with mass 2
    out = bl.homogeneous_blossom(P, pairs)
    assert out[-1] == pytest.approx(2.0)
    np.testing.assert_allclose(out[:2] / out[-1], bl.blossom(P, [0.2, 0.5, 0.9]))
    # delta = (1, 0) gives a vector (mass 0): n p(t, t, delta) = P'(t)
    t = 0.3
    vec = bl.homogeneous_blossom(P, [[t, 1], [t, 1], [1, 0]])
    assert vec[-1] == 0
    np.testing.assert_allclose(3 * vec[:2], bezier.derivative(P, t))


@settings(max_examples=50, deadline=None)
@given(arrays(float, st.tuples(st.integers(1, 9), st.integers(1, 3)), elements=coord))
def test_monomial_to_bezier_evaluates_like_numpy_polynomial(coeffs):
    P = bl.monomial_to_bezier(coeffs)
    t = np.linspace(-0.5, 1.5, 13)
    ref = np.stack([Polynomial(coeffs[:, c])(t) for c in range(coeffs.shape[1])], axis=1)
    scale = max(1.0, np.abs(coeffs).max()) * 3 ** len(coeffs)
    np.testing.assert_allclose(bezier.de_casteljau(P, t), ref, atol=1e-11 * scale)


@settings(max_examples=50, deadline=None)
@given(curves(0, 8, 2))
def test_bezier_to_monomial_matches_numpy_polynomial_and_round_trips(P):
    a = bl.bezier_to_monomial(P)
    scale = max(1.0, np.abs(P).max()) * 4 ** len(P)
    for c, poly in enumerate(power_polys(P)):
        ref = np.zeros(len(P))
        ref[: len(poly.coef)] = poly.coef
        np.testing.assert_allclose(a[:, c], ref, atol=1e-10 * scale)
    np.testing.assert_allclose(bl.monomial_to_bezier(a), P, atol=1e-10 * scale)


def test_conversions_of_a_scalar_polynomial_closed_form():
    # 1 + 2t + 3t^2: P0 = a0, P1 = a0 + a1/2, P2 = a0 + a1 + a2
    np.testing.assert_allclose(bl.monomial_to_bezier([1.0, 2.0, 3.0]), [1.0, 2.0, 6.0])
    np.testing.assert_allclose(bl.bezier_to_monomial([1.0, 2.0, 6.0]), [1.0, 2.0, 3.0])
    # t^3 has control points 0, 0, 0, 1
    np.testing.assert_allclose(bl.monomial_to_bezier([0, 0, 0, 1.0]), [0, 0, 0, 1])


@pytest.mark.parametrize("call,match", [
    (lambda: bl.blossom([[0, 0], [1, 1], [2, 0]], [0.5]), r"shape \(\.\.\., n\) with n = 2"),
    (lambda: bl.blossom([[0, 0], [1, 1], [2, 0]], 0.5), "n = 2"),
    (lambda: bl.blossom([[0, 0], [1, 1], [2, 0]], [0.5, np.nan]), "args must be finite"),
    (lambda: bl.blossom([0, 1, 2], [0.5, 0.5]), "ctrl must have shape"),
    (lambda: bl.blossom_steps([[0, 0], [1, 1], [2, 0]], [[0.5, 0.5]]), r"shape \(2,\)"),
    (lambda: bl.homogeneous_blossom([[0, 0], [1, 1], [2, 0]], [0.5, 0.5]), r"\(\.\.\., 2, 2\)"),
    (lambda: bl.control_points_on_interval([[0, 0], [1, 1]], np.inf, 1), "a must be finite"),
    (lambda: bl.derivative_by_blossom([[0, 0], [1, 1]], 0.5, -1), "order must be >= 0"),
    (lambda: bl.monomial_to_bezier(np.zeros((2, 2, 2))), r"shape \(n\+1,\) or \(n\+1, d\)"),
    (lambda: bl.bezier_to_monomial(np.zeros(1002)), "degree <= 1000"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_bad_types():
    with pytest.raises(TypeError, match="order must be an integer"):
        bl.derivative_by_blossom([[0, 0], [1, 1]], 0.5, 1.5)
    with pytest.raises(TypeError, match="args must be"):
        bl.blossom([[0, 0], [1, 1]], "x")

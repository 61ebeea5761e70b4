"""goldman_lib.fixed_point (Goldman §7.2-7.3) against independent references: scipy's directed
Hausdorff distance, numpy.linalg.solve, scipy.optimize.brentq, known roots written out, the
spectral norm by numpy.linalg.norm(L, 2), and the fractal theorem's bound measured per level."""

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy.optimize import brentq
from scipy.spatial.distance import directed_hausdorff as scipy_directed

from goldman_lib import affine, ifs
from goldman_lib import fixed_point as fp

points = st.integers(1, 40).flatmap(lambda n: arrays(float, (n, 2), elements=st.floats(-100, 100)))


@settings(max_examples=60, deadline=None)
@given(A=points, B=points)
def test_hausdorff_matches_scipy(A, B):
    expected = max(scipy_directed(A, B)[0], scipy_directed(B, A)[0])
    assert fp.hausdorff_distance(A, B) == expected            # exact: the same distances, max and min
    assert fp.directed_hausdorff(A, B) == scipy_directed(A, B)[0]


def test_newton_finds_known_roots():
    assert fp.newton(lambda x: x * x - 2, lambda x: 2 * x, 1.0) == pytest.approx(1.4142135623730951, abs=1e-15)
    assert fp.newton(lambda x: x ** 3 - 2, lambda x: 3 * x * x, 1.0) == pytest.approx(1.2599210498948732, abs=1e-15)
    assert fp.newton(lambda x: x ** 3 + 8, lambda x: 3 * x * x, -1.0) == pytest.approx(-2.0, abs=1e-15)
    assert fp.newton(math.cos, lambda x: -math.sin(x), 1.0) == pytest.approx(math.pi / 2, abs=1e-15)


def test_newton_converges_quadratically_near_a_simple_root():
    x, rep = fp.newton(lambda x: x * x - 2, lambda x: 2 * x, 1.0, full_output=True)
    err = np.abs(rep.history - math.sqrt(2))
    ratios = err[1:4] / err[:3] ** 2       # e_{n+1} / e_n^2 -> f''/(2 f') = 1/(2 sqrt 2)
    assert rep.converged and rep.reason == "converged" and rep.iterations <= 6
    assert ratios[-1] == pytest.approx(1 / (2 * math.sqrt(2)), rel=0.05)


def test_newton_names_its_failures():
    r = fp.newton_steps(lambda x: x * x - 2, lambda x: 2 * x, 0.0)
    assert r.reason == "zero derivative" and not r.converged
    r = fp.newton_steps(lambda x: x ** 3 - 2 * x + 2, lambda x: 3 * x * x - 2, 0.0)
    assert r.reason == "cycle" and r.history.tolist() == [0.0, 1.0, 0.0]
    r = fp.newton_steps(math.atan, lambda x: 1 / (1 + x * x), 1.5)
    assert r.reason == "diverged" and abs(r.history[-1]) > 1e6
    assert fp.newton(math.atan, lambda x: 1 / (1 + x * x), 1.3) == pytest.approx(0.0, abs=1e-15)
    with pytest.raises(fp.ConvergenceError, match="cycle") as info:
        fp.newton(lambda x: x ** 3 - 2 * x + 2, lambda x: 3 * x * x - 2, 0.0)
    assert info.value.report.reason == "cycle"
    x, rep = fp.newton(lambda x: x * x + 1, lambda x: 2 * x, 0.5, full_output=True, max_iter=30)
    assert not rep.converged and rep.reason in {"max iterations", "cycle", "zero derivative", "diverged"}


def test_fixed_point_iteration_against_brentq():
    L = fp.fixed_point_iteration(math.cos, 1.0)
    assert L == pytest.approx(brentq(lambda x: math.cos(x) - x, 0, 1, xtol=1e-15), abs=1e-11)
    assert math.cos(L) == pytest.approx(L, abs=1e-11)          # the limit is a fixed point (§7.2)
    v = fp.fixed_point_iteration(lambda p: affine.apply(p[None], affine.scaling(0.5, center=[2, 1]))[0], [0.0, 0.0])
    np.testing.assert_allclose(v, [2, 1], atol=1e-11)
    with pytest.raises(fp.ConvergenceError, match="diverge|grew"):
        fp.fixed_point_iteration(lambda x: 2 * x + 1, 1.0, max_iter=2000)


def dominant_system(n, seed):
    rng = np.random.default_rng(seed)
    A = rng.uniform(-1, 1, (n, n))
    A += np.diag(np.abs(A).sum(axis=1) + rng.uniform(0.1, 2, n)) * np.sign(rng.uniform(-1, 1, n))
    return A, rng.uniform(-5, 5, n)


@pytest.mark.parametrize("solver", [fp.jacobi, fp.gauss_seidel], ids=["jacobi", "gauss_seidel"])
@pytest.mark.parametrize("n,seed", [(1, 0), (2, 1), (5, 2), (20, 3), (60, 4)])
def test_relaxation_matches_numpy_solve_to_machine_precision(solver, n, seed):
    A, b = dominant_system(n, seed)
    x, rep = solver(A, b, full_output=True)
    expected = np.linalg.solve(A, b)
    np.testing.assert_allclose(x, expected, rtol=1e-13, atol=1e-13 * np.abs(expected).max())
    assert rep.converged and rep.residuals[-1] <= 1e-13 * np.abs(b).max() + 1e-300
    assert len(rep.residuals) == rep.iterations + 1 and rep.history.shape == (rep.iterations + 1, n)


def test_gauss_seidel_needs_fewer_iterations_than_jacobi():
    A, b = dominant_system(30, 7)
    _, rj = fp.jacobi(A, b, full_output=True)
    _, rg = fp.gauss_seidel(A, b, full_output=True)
    assert rg.iterations < rj.iterations


def test_one_interface_for_both_systems():
    """A x = b (§7.3.2) and B = E + rho F B (§23.5) by the same methods: the same keywords and record.
    B = E + rho F B is (I - rho F) B = E, so fixed_point solves it as A x = b; both see the same
    first iterate (Jacobi: E, then E + rho F E), and the same record type."""
    from goldman_lib import radiosity as rd
    from goldman_lib.kernels import relaxation

    F, rho, E = np.array([[0.0, 0.5], [0.5, 0.0]]), np.array([0.5, 0.5]), np.array([1.0, 1.0])
    A = np.eye(2) - rho[:, None] * F
    for name in ("jacobi", "gauss_seidel"):
        x, rx = getattr(fp, name)(A, E, E, tol=1e-15, max_iter=200, full_output=True)
        B, rb = getattr(rd, name)(F, rho, E, tol=1e-15, max_iter=200, full_output=True)
        assert type(rx) is type(rb) is fp.Convergence is relaxation.Convergence
        assert rx.method == rb.method and rx.converged and rb.converged
        np.testing.assert_allclose(rx.history[1], rb.history[1], rtol=0, atol=1e-15)   # [1.25, 1.25] / [1.25, 1.3125]
        np.testing.assert_allclose(x, [4 / 3, 4 / 3], rtol=1e-14)
        np.testing.assert_allclose(B, [4 / 3, 4 / 3], rtol=1e-12)


def test_jacobi_first_step_is_b_over_the_diagonal():
    A = np.array([[4.0, 1.0], [2.0, 5.0]])
    _, rep = fp.jacobi(A, [1.0, 2.0], full_output=True)
    np.testing.assert_allclose(rep.history[1], [1 / 4, 2 / 5])
    _, rep = fp.gauss_seidel(A, [1.0, 2.0], full_output=True)
    np.testing.assert_allclose(rep.history[1], [1 / 4, (2 - 2 * 0.25) / 5])


def test_relaxation_reports_unsuitable_matrices():
    with pytest.raises(ValueError, match=r"A\[1, 1\] = 0"):
        fp.jacobi([[1.0, 2.0], [3.0, 0.0]], [1.0, 1.0])
    with pytest.raises(ValueError, match="square"):
        fp.gauss_seidel(np.ones((2, 3)), [1.0, 1.0])
    with pytest.raises(ValueError, match="b must have one entry per row"):
        fp.jacobi(np.eye(2), [1.0, 1.0, 1.0])
    bad = [[1.0, 3.0], [2.0, 1.0]]      # not diagonally dominant: spectral radius of D^-1 R is sqrt(6)
    with pytest.warns(RuntimeWarning, match="not diagonally dominant"):
        with pytest.raises(fp.ConvergenceError, match="diverged|grew"):
            fp.jacobi(bad, [1.0, 1.0])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        x, rep = fp.gauss_seidel(bad, [1.0, 1.0], full_output=True)
    assert rep.reason == "diverged" and np.all(np.isfinite(x)) and "not diagonally dominant" in rep.message
    assert fp.is_diagonally_dominant([[3, 1], [1, 3]]) and not fp.is_diagonally_dominant(bad)


@settings(max_examples=50, deadline=None)
@given(L=arrays(float, (2, 2), elements=st.floats(-3, 3)), t=arrays(float, (2,), elements=st.floats(-3, 3)))
def test_contraction_factor_is_the_spectral_norm(L, t):
    M = np.eye(3)
    M[:2, :2], M[2, :2] = L, t
    assert fp.contraction_factor(M) == pytest.approx(np.linalg.norm(L, 2), rel=1e-12, abs=1e-12)
    assert fp.contraction_factor(L) == pytest.approx(np.linalg.norm(L, 2), rel=1e-12, abs=1e-12)


def test_contraction_factor_closed_forms():
    assert fp.contraction_factor(affine.similarity(0.3, 77, [4, 5])) == pytest.approx(0.3)
    assert fp.contraction_factor(affine.scaling([0.2, -0.7])) == pytest.approx(0.7)
    assert fp.contraction_factor(affine.shear(1.0)) == pytest.approx((1 + math.sqrt(5)) / 2)
    np.testing.assert_allclose(fp.contraction_factor(ifs.sierpinski().maps), [0.5] * 3)
    with pytest.raises(ValueError, match="3x3 affine matrix or a 2x2"):
        fp.contraction_factor(np.eye(4))


@pytest.mark.parametrize("name", ["Sierpinski gasket", "Koch curve", "dragon", "C-curve", "Cantor set"])
@pytest.mark.parametrize("start", [[[5.0, -3.0]], [[0, 0], [1, 0], [1, 1], [0, 1]], [[-2, 2], [3, 1], [0.5, -1]]])
def test_fractal_theorem_bound_holds_level_by_level(name, start):
    s = ifs.STANDARD[name]()
    levels = 6 if len(s) <= 3 else 4
    r = fp.fractal_theorem(s, start, levels)
    assert r.factor == pytest.approx(max(np.linalg.norm(L, 2) for L in s.linear_parts))
    # the measured distance, recomputed by scipy, stays under s^n h(A0, A) (up to the sample's error)
    for n in range(levels + 1):
        d = max(scipy_directed(r.sets[n], r.attractor)[0], scipy_directed(r.attractor, r.sets[n])[0])
        assert d == pytest.approx(r.distances[n], abs=1e-9)
        assert d <= r.factor ** n * r.distances[0] + 2 * r.attractor_error + 1e-12
    assert r.holds() and r.distances[-1] < r.distances[0]


def test_fractal_theorem_rejects_expanding_maps():
    with pytest.raises(ValueError, match="contraction"):
        fp.fractal_theorem(ifs.IFS([affine.scaling(1.5)]), [[0, 0]], 2)


def _kind(case, rng):
    """Two point sets of one kind: overlapping, apart, one inside the other's hull, fractals, ..."""
    from goldman_lib import ifs

    A, B = rng.uniform(0, 1, (3000, 2)), rng.uniform(0, 1, (2500, 2))
    if case == "apart":
        B = B + [0.3, 0.1]
    elif case == "far apart":
        B = B + [30.0, -20.0]
    elif case == "clustered":
        A = rng.normal(0, 0.01, (3000, 2)) + rng.integers(0, 5, (3000, 1)) * 0.2
        B = rng.normal(0, 0.01, (2500, 2)) + rng.integers(0, 5, (2500, 1)) * 0.2
    elif case == "duplicates":
        B = np.concatenate([A[:1000], A[:1000]])
    elif case == "identical":
        B = A[::-1].copy()
    elif case == "collinear":
        A = np.stack([rng.uniform(0, 1, 3000), np.zeros(3000)], axis=1)
        B = np.stack([rng.uniform(0, 1, 2500), np.zeros(2500)], axis=1)
    elif case == "1d":
        A, B = A[:, :1], B[:, :1] * 2
    elif case == "3d":
        A, B = rng.uniform(0, 1, (3000, 3)), rng.uniform(0, 1, (2500, 3))
    elif case == "inside":
        A = rng.uniform(0.4, 0.6, (3000, 2))
    elif case == "ring inside":
        t = rng.uniform(0, 2 * np.pi, 2500)
        B = 0.5 + 0.3 * np.stack([np.cos(t), np.sin(t)], axis=1)
    elif case == "nested fractals":                 # the fern and a sparser sample of itself
        A = ifs.chaos_game(ifs.barnsley_fern(), 3000, rng=1)
        B = ifs.deterministic(ifs.barnsley_fern(), 5)
    elif case == "single point":
        B = np.array([[0.5, 0.25]])
    elif case == "far and huge":
        A, B = A * 1e150, B * 1e150 + 3e150
    return A, B


HAUSDORFF_KINDS = ["overlapping", "apart", "far apart", "clustered", "duplicates", "identical", "collinear", "1d",
                   "3d", "inside", "ring inside", "nested fractals", "single point", "far and huge"]


@pytest.mark.parametrize("case", HAUSDORFF_KINDS)
def test_hausdorff_distance_is_the_brute_force_value_on_every_kind_of_set(case):
    """The pruned search gives the brute-force max-min to the last bit (every value it compares is a
    computed distance), and scipy's directed_hausdorff (the reference), both directions."""
    from scipy.spatial.distance import directed_hausdorff

    A, B = _kind(case, np.random.default_rng(7))

    def brute(X, Y):       # sum_k (x_k - y_k)^2 in coordinate order, the min over Y, the max over X
        d2 = sum((X[:, None, k] - Y[None, :, k]) ** 2 for k in range(X.shape[1]))
        return float(np.sqrt(d2.min(axis=1).max()))
    ab, ba = brute(A, B), brute(B, A)
    assert fp.directed_hausdorff(A, B) == ab and fp.directed_hausdorff(B, A) == ba
    assert fp.hausdorff_distance(A, B) == max(ab, ba) == fp.hausdorff_distance(B, A)
    assert fp.hausdorff_distance(A, B) == max(directed_hausdorff(A, B)[0], directed_hausdorff(B, A)[0])
    for X, Y in ((A, A), (A[:1], B), (A, B[:1])):
        assert fp.hausdorff_distance(X, Y) == max(brute(X, Y), brute(Y, X))


@pytest.mark.parametrize("case", ["overlapping", "apart", "far apart", "duplicates", "identical", "3d", "inside"])
def test_hausdorff_distance_bounds_by_grid_neighbours_only_where_a_scan_would_be_long(case):
    """Overlapping sets take the grid-neighbour bounds (a random scan would be long); sets apart
    do not (the probe of B's random and extreme points already bounds almost every point)."""
    A, B = _kind(case, np.random.default_rng(7))
    used = []
    real = fp._window_bounds
    try:
        fp._window_bounds = lambda *args: (used.append(1), real(*args))[1]
        fp.hausdorff_distance(A, B)
    finally:
        fp._window_bounds = real
    if case in ("overlapping", "duplicates", "identical", "3d", "inside"):    # inside: the small set's side
        assert used, f"{case}: the grid-neighbour bounds were not used"
    if case in ("apart", "far apart"):
        assert not used, f"{case}: a short scan should do"


def test_jacobi_factor_is_the_max_norm_contraction_of_jacobis_map():
    # worked by hand: the rows give 1/4 and 2/5
    assert fp.jacobi_factor([[4, 1], [2, 5]]) == pytest.approx(0.4)
    assert fp.jacobi_factor([[1, 2], [3, 4]]) == pytest.approx(2.0)       # not dominant: factor above 1
    rng = np.random.default_rng(7)
    A = rng.uniform(-1, 1, (5, 5)) + np.diag([4.0, 5, 3, 6, 4])
    D, R = np.diag(A), A - np.diag(np.diag(A))
    step = lambda x: -(R @ x) / D                                          # Jacobi's map with b = 0
    k = fp.jacobi_factor(A)
    ratios = [np.abs(step(x)).max() / np.abs(x).max() for x in rng.normal(size=(200, 5))]
    assert max(ratios) <= k + 1e-12
    i = int(np.argmax((np.abs(R).sum(1)) / np.abs(D)))                    # the worst row, attained
    x = -np.sign(R[i]) * np.sign(D[i])
    x[i] = 1.0
    assert np.abs(step(x)).max() == pytest.approx(k)
    with pytest.raises(ValueError, match="diagonal"):
        fp.jacobi_factor([[0, 1], [1, 2]])
    with pytest.raises(ValueError, match="square"):
        fp.jacobi_factor([[1, 2, 3]])

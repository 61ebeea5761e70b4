"""goldman_lib.ifs (Goldman §6.1-6.4) against closed forms and independent checks: the two
algorithms draw the same attractor, every map's fixed point lies on it, the attractor is the
fixed point of the set map W, and the Sierpinski levels equal the closed-form set."""

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.distance import directed_hausdorff as scipy_directed

from goldman_lib import affine, ifs

SYSTEMS = sorted(ifs.STANDARD)


def h(A, B):
    """Hausdorff distance by scipy (the reference, not the code under test)."""
    return max(scipy_directed(A, B)[0], scipy_directed(B, A)[0])


def dense(system):
    """The system with its condensation polyline (if any) sampled densely, so that the
    deterministic algorithm's copies of it are point sets as dense as the chaos game's."""
    C = system.condensation
    if C is None:
        return system
    t = np.linspace(0, 1, 40)[:, None]
    Cd = np.concatenate([a + t * (b - a) for a, b in zip(C[:-1], C[1:])])
    return ifs.IFS(system.maps, system.probabilities, Cd, system.name)


def det_sample(system, max_points=20_000):
    system = dense(system)
    k = len(system)
    m = 1 if system.condensation is None else len(system.condensation)
    levels = int(math.log(max_points / m) / math.log(k))
    return ifs.deterministic(system, levels), levels


@pytest.mark.parametrize("name", SYSTEMS)
def test_chaos_game_and_deterministic_draw_the_same_attractor(name):
    s = ifs.STANDARD[name]()
    det, levels = det_sample(s)
    chaos = ifs.chaos_game(s, 20_000, rng=1, with_condensation=s.condensation is not None)
    diam = float(np.ptp(chaos, axis=0).max())
    # det lies on A (it starts on A), and the chaos sample is dense in A
    assert scipy_directed(det, chaos)[0] <= 0.03 * diam, name
    # the chaos points are on A, and W^L(start) is within s^L h(start, A) <= s^L diam of A
    assert scipy_directed(chaos, det)[0] <= max(s.contraction_factors()) ** levels * diam + 0.03 * diam, name


@pytest.mark.parametrize("name", SYSTEMS)
def test_every_fixed_point_of_a_map_lies_on_the_attractor(name):
    s = ifs.STANDARD[name]()
    det, levels = det_sample(s, 50_000)
    diam = float(np.ptp(det, axis=0).max())
    bound = max(s.contraction_factors()) ** levels * 2 * diam + 1e-9
    fixed = np.array([np.linalg.solve(np.eye(2) - M[:2, :2].T, M[2, :2]) for M in s.maps])  # P = P L + t
    np.testing.assert_allclose(s.fixed_points(), fixed, atol=1e-12)
    if s.condensation is None:
        assert scipy_directed(fixed, det)[0] <= bound


@pytest.mark.parametrize("name", ["Sierpinski gasket", "Koch curve", "dragon", "Barnsley fern"])
def test_the_attractor_is_the_fixed_point_of_the_set_map(name):
    s = ifs.STANDARD[name]()
    A = ifs.chaos_game(s, 5000, rng=3)
    WA = ifs.set_map(s, A)
    assert WA.shape == (len(s) * len(A), 2)
    # atol: a coordinate that cancels to about 1e-16 has no relative accuracy
    np.testing.assert_allclose(WA[:len(A)], A @ s.linear_parts[0] + s.translations[0], rtol=1e-12, atol=1e-15)
    diam = float(np.ptp(A, axis=0).max())
    assert h(WA, A) <= 0.06 * diam   # W(A) = A, up to the sampling of A


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_sierpinski_levels_are_the_closed_form_dyadic_set(n):
    corners = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, math.sqrt(3) / 2]])
    # W^n({0}) = { sum_{i=1..n} c_{a_i} 2^-i : a in {0,1,2}^n }
    expected = np.array([sum(corners[a] * 2.0 ** -(i + 1) for i, a in enumerate(word))
                         for word in itertools.product(range(3), repeat=n)])
    got = ifs.deterministic(ifs.sierpinski(), n, start=[[0.0, 0.0]])
    assert got.shape == (3 ** n, 2)
    key = lambda P: np.lexsort(np.round(P, 12).T[::-1])  # noqa: E731
    np.testing.assert_allclose(got[key(got)], expected[key(expected)], atol=1e-12)


def test_cantor_points_have_ternary_digits_0_and_2():
    pts = ifs.deterministic(ifs.cantor(), 6, start=[[0.0, 0.0]])[:, 0]
    N = np.round(pts * 3 ** 6).astype(int)
    np.testing.assert_allclose(pts * 3 ** 6, N, atol=1e-9)
    digits = (N[:, None] // 3 ** np.arange(6)) % 3
    assert set(np.unique(digits)) <= {0, 2}
    assert len(np.unique(np.round(pts, 12))) == 2 ** 6


def test_deterministic_point_counts_with_and_without_condensation():
    s = ifs.tree()
    k, m, c = 2, 1, 2
    for L in range(5):
        assert len(ifs.deterministic(ifs.IFS(s.maps), L, start=[[0, 0]])) == m * k ** L
        assert len(ifs.deterministic(s, L)) == c * (2 ** (L + 1) - 1)   # 1 + 2 + ... + 2^L trunks


def test_contraction_factors_are_spectral_norms_and_similarity_ratios():
    for name in SYSTEMS:
        s = ifs.STANDARD[name]()
        np.testing.assert_allclose(s.contraction_factors(), [np.linalg.norm(L, 2) for L in s.linear_parts])
    np.testing.assert_allclose(ifs.koch().contraction_factors(), 1 / 3)
    np.testing.assert_allclose(ifs.dragon().contraction_factors(), 1 / math.sqrt(2))
    assert ifs.sierpinski().is_contractive() and not ifs.IFS([affine.scaling(1.2)]).is_contractive()


@settings(max_examples=40, deadline=None)
@given(r=st.floats(-0.95, 0.95), cx=st.floats(-3, 3), cy=st.floats(-3, 3), n=st.integers(0, 12))
def test_iterating_a_scaling_about_a_point_closes_in_geometrically(r, cx, cy, n):
    P0 = np.array([[1.0, 2.0], [-1.0, 0.5]])
    shapes = ifs.iterate_map(affine.scaling(r, center=[cx, cy]), P0, n)
    c = np.array([cx, cy])
    np.testing.assert_allclose(shapes[-1], c + r ** n * (P0 - c), atol=1e-9)
    assert shapes.shape == (n + 1, 2, 2)


def test_chaos_game_is_reproducible_and_takes_generators():
    a = ifs.chaos_game(ifs.barnsley_fern(), 1000, rng=5)
    b = ifs.chaos_game(ifs.barnsley_fern(), 1000, rng=np.random.default_rng(5))
    np.testing.assert_array_equal(a, b)
    pts, maps = ifs.chaos_game_with_maps(ifs.barnsley_fern(), 1000, rng=5)
    np.testing.assert_array_equal(pts, a)
    assert maps.shape == (1000,) and set(np.unique(maps)) <= {0, 1, 2, 3}


def test_chaos_game_is_the_textbook_numpy_loop_point_for_point():
    """The chains, start, burn-in and draws as documented, against the loop a numpy user writes
    (Generator.choice, then x' = x a + y c + e, y' = x b + y d + f for every chain at once); and the
    first points of a small game written out (the sequence a given seed draws must not change)."""
    s = ifs.barnsley_fern()
    pts, maps = ifs.chaos_game_with_maps(s, 3, rng=0, chains=2, burn_in=1)
    assert pts.tolist() == [[0.064, 2.96], [0.064, 2.96], [0.1728, 4.113440000000001]] and maps.tolist() == [1, 1, 1]
    n, chains, burn_in = 10_000, 300, 7
    M = s.maps
    idx = np.random.default_rng(11).choice(4, size=(burn_in + 34, chains), p=s.probabilities)
    x = np.full(chains, affine.fixed_point(M[0])[0])
    y = np.full(chains, affine.fixed_point(M[0])[1])
    ref = []
    for step, i in enumerate(idx):
        x, y = x * M[i, 0, 0] + y * M[i, 1, 0] + M[i, 2, 0], x * M[i, 0, 1] + y * M[i, 1, 1] + M[i, 2, 1]
        if step >= burn_in:
            ref.append(np.stack([x, y], axis=1))
    pts, maps = ifs.chaos_game_with_maps(s, n, rng=11, chains=chains, burn_in=burn_in)
    assert np.array_equal(pts, np.concatenate(ref)[:n])
    assert np.array_equal(maps, idx[burn_in:].reshape(-1)[:n])


def test_chaos_game_labels_say_which_copy_a_point_lies_in():
    s = ifs.sierpinski()
    pts, maps = ifs.chaos_game_with_maps(s, 3000, rng=2)
    corners = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, math.sqrt(3) / 2]])
    for i in range(3):   # w_i(A) is the half-size gasket at corner i: within 1/2 of that corner
        assert np.all(np.linalg.norm(pts[maps == i] - corners[i], axis=1) <= 0.5 + 1e-9)


def test_chaos_game_with_condensation_stays_on_the_tree():
    s = ifs.tree()
    pts, maps = ifs.chaos_game_with_maps(s, 4000, rng=0, with_condensation=True)
    trunk = pts[maps == 2]
    assert len(trunk) > 500 and np.allclose(trunk[:, 0], 0) and trunk[:, 1].min() >= 0 and trunk[:, 1].max() <= 1
    det, levels = det_sample(s, 60_000)
    assert scipy_directed(pts, det)[0] < 0.6 ** levels * 3 + 0.03


def test_bad_input_is_rejected_naming_the_rule():
    with pytest.raises(ValueError, match="escaped to infinity"):
        ifs.chaos_game(ifs.IFS([affine.scaling(2.0), affine.scaling(2.0, center=[1, 0])]), 100, rng=0, burn_in=1100)
    with pytest.raises(ValueError, match="probabilities must be non-negative"):
        ifs.IFS([affine.scaling(0.5)] * 2, probabilities=[1, -1])
    with pytest.raises(ValueError, match="levels must be <= 14"):
        ifs.deterministic(ifs.sierpinski(), 20)
    with pytest.raises(ValueError, match="levels must be >= 0"):
        ifs.deterministic(ifs.sierpinski(), -1)
    with pytest.raises(ValueError, match="n must be >= 0"):
        ifs.iterate_map(affine.scaling(0.5), [[0, 0]], -1)
    with pytest.raises(ValueError, match="M must be one 3x3"):
        ifs.iterate_map(np.stack([np.eye(3)] * 2), [[0, 0]], 1)
    with pytest.raises(TypeError, match="rng must be"):
        ifs.chaos_game(ifs.sierpinski(), 10, rng="seed")


def test_grid_fractal_maps_send_the_square_onto_its_cells():
    # square with corner (1, -2) and side 3: cell (i, j) is [1 + i, 2 + i] x [-2 + j, -1 + j]
    cells = [(0, 0), (2, 1), (1, 2)]
    s = ifs.grid_fractal(cells, corner=(1, -2), side=3)
    square = np.array([[1.0, -2.0], [4.0, -2.0], [4.0, 1.0], [1.0, 1.0]])
    for M, (i, j) in zip(s.maps, cells):
        cell = np.array([[1 + i, -2 + j], [2 + i, -2 + j], [2 + i, -1 + j], [1 + i, -1 + j]], dtype=float)
        assert np.allclose(affine.apply(square, M), cell)
    assert np.allclose(s.contraction_factors(), 1 / 3)
    carpet = ifs.grid_fractal([(i, j) for i in range(3) for j in range(3) if (i, j) != (1, 1)])
    assert np.allclose(carpet.maps, ifs.sierpinski_carpet().maps)


def test_grid_fractal_rejects_bad_cells_and_sides():
    with pytest.raises(ValueError, match="cells must hold whole numbers"):
        ifs.grid_fractal([(0, 3)])
    with pytest.raises(ValueError, match="cells must hold whole numbers"):
        ifs.grid_fractal([(0.5, 1)])
    with pytest.raises(ValueError, match="cells must be a non-empty"):
        ifs.grid_fractal([])
    with pytest.raises(ValueError, match="side must be a positive"):
        ifs.grid_fractal([(0, 0)], side=0)


# --- §4.7.3 / §7.3.3: an IFS designed from three points per map --------------------------------

def test_ifs_from_points_rebuilds_the_gasket():
    corners = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, np.sqrt(3) / 2]])
    mid = lambda a, b: (corners[a] + corners[b]) / 2
    images = [[corners[0], mid(0, 1), mid(0, 2)], [mid(0, 1), corners[1], mid(1, 2)], [mid(0, 2), mid(1, 2), corners[2]]]
    s = ifs.ifs_from_points(corners, images)
    np.testing.assert_allclose(s.maps, ifs.sierpinski().maps, atol=1e-12)
    # each map sends the reference corners to its image triangle
    for M, T in zip(s.maps, images):
        np.testing.assert_allclose(affine.apply(corners, M), T, atol=1e-12)


def test_ifs_from_points_errors():
    with pytest.raises(ValueError, match="reference must be three"):
        ifs.ifs_from_points([[0, 0], [1, 0]], [[[0, 0], [1, 0], [0, 1]]])
    with pytest.raises(ValueError, match="images must hold one triangle per map"):
        ifs.ifs_from_points([[0, 0], [1, 0], [0, 1]], [[0, 0], [1, 0], [0, 1]])
    with pytest.raises(ValueError):
        ifs.ifs_from_points([[0, 0], [1, 1], [2, 2]], [[[0, 0], [1, 0], [0, 1]]])

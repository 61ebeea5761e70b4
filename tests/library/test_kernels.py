"""The unchecked kernels of goldman_lib.kernels against independent references (scipy, closed forms,
numpy's own products), and the written-out fast paths against the general routine, bit for bit."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.interpolate import BSpline
from scipy.stats import binom

from goldman_lib.kernels import frames, iteration, meshes, number, polygons, pyramids, relaxation

RNG = np.random.default_rng(19)


def bezier_reference(P, t):
    """sum_k C(n, k) t^k (1-t)^(n-k) P_k, written directly."""
    n = len(P) - 1
    t = np.asarray(t, dtype=float)[..., None]
    return sum(math.comb(n, k) * t ** k * (1 - t) ** (n - k) * P[k] for k in range(n + 1))


# -- pyramids: de Casteljau ---------------------------------------------------------------------------

@pytest.mark.parametrize("n", [0, 1, 2, 3, 5, 9])
def test_curve_points_is_the_bernstein_sum(n):
    P = RNG.normal(size=(n + 1, 3))
    t = np.linspace(-0.5, 1.5, 41).reshape(41, 1)
    assert pyramids.curve_points(P, t).shape == (41, 1, 3)
    assert np.allclose(pyramids.curve_points(P, t), bezier_reference(P, t), atol=1e-12)


def _pyramid_by_levels(P, t):
    """The apex by casteljau_level on whole arrays, one level at a time: the reference arithmetic."""
    cur = np.broadcast_to(P[:, :, None], P.shape + (t.size,))
    while cur.shape[0] > 1:
        cur = pyramids.casteljau_level(cur, t)
    return cur[0].T


@pytest.mark.parametrize("n", [0, 1, 2, 3, 7, 12])
@pytest.mark.parametrize("count", [0, 1, 7, 10_000])
def test_curve_points_is_casteljau_level_bit_for_bit(n, count):
    """The scratch-space pyramid of casteljau_apex does s P_j + t P_{j+1}, node by node, in the same
    order as casteljau_level: the same bits, at any degree and any number of parameters."""
    P = RNG.normal(size=(n + 1, 2)) * 10.0 ** RNG.integers(-3, 4, size=(n + 1, 1))
    t = RNG.uniform(-0.5, 1.5, count)
    got = pyramids.curve_points(P, t)
    assert got.shape == (count, 2) and got.flags.c_contiguous
    assert np.array_equal(got, _pyramid_by_levels(P, t))


@pytest.mark.parametrize("n", [1, 2, 3, 7, 20])
def test_curve_points_ends_are_the_end_points_exactly(n):
    """(1-t) a + t b is a at t = 0 and b at t = 1 exactly, so P(0) = P_0 and P(1) = P_n bit for bit
    (a + t (b - a) would not be: the book's affine invariance needs the endpoints exact)."""
    P = RNG.normal(size=(n + 1, 3)) * 1e3 + np.pi
    got = pyramids.curve_points(P, np.array([0.0, 1.0, 0.0, 1.0] * 2500))
    assert (got[0::2] == P[0]).all() and (got[1::2] == P[-1]).all()


def test_curve_points_agrees_with_numpy_polynomial_bernstein_sums():
    """Degree 7 at 10,000 parameters (the benchmark's case) against the power form by numpy.polynomial:
    sum_k C(7,k) t^k (1-t)^(7-k) P_k expanded with Polynomial arithmetic."""
    from numpy.polynomial import Polynomial as Poly
    n = 7
    P = RNG.uniform(-1, 1, (n + 1, 2))
    t = np.linspace(0.0, 1.0, 10_000)
    T, S = Poly([0.0, 1.0]), Poly([1.0, -1.0])
    for c in range(2):
        curve = sum((math.comb(n, k) * P[k, c]) * T ** k * S ** (n - k) for k in range(n + 1))
        assert np.abs(pyramids.curve_points(P, t)[:, c] - curve(t)).max() < 1e-13


def test_casteljau_apex_results_survive_the_next_call_and_other_threads():
    """The levels live in a per-thread scratch reused by the next call; results never do."""
    import threading
    P = RNG.normal(size=(6, 2))
    t = np.linspace(0.0, 1.0, 3000)
    first = pyramids.curve_points(P, t)
    keep = first.copy()
    pyramids.curve_points(P[::-1].copy(), t[::-1].copy())          # same scratch, other data
    assert np.array_equal(first, keep)
    net = RNG.normal(size=(4, 5, 3))                                # two apexes in a row (v then u)
    u, v = RNG.uniform(0, 1, (2, 200))
    along_v = np.stack([_pyramid_by_levels(net[i], v) for i in range(4)])   # (4, 200, 3)
    expect = np.stack([_pyramid_by_levels(along_v[:, m], u[m:m + 1])[0] for m in range(200)])
    assert np.array_equal(pyramids.patch_points(net, u, v).T, expect)
    results = {}

    def work(seed):
        Q = np.random.default_rng(seed).normal(size=(8, 2))
        results[seed] = [np.array_equal(pyramids.curve_points(Q, t), _pyramid_by_levels(Q, t)) for _ in range(20)]
    threads = [threading.Thread(target=work, args=(seed,)) for seed in range(4)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert all(all(r) for r in results.values())


def test_workspace_is_reused_aligned_and_bounded():
    a = pyramids.workspace(1000)
    b = pyramids.workspace(500)
    assert np.shares_memory(a, b) and a.ctypes.data % 2 ** 21 == 0
    big = pyramids.workspace(pyramids.WORKSPACE_MAX_BYTES // 8 + 1)   # over the bound: a temporary
    assert not np.shares_memory(big, pyramids.workspace(10))


def test_casteljau_level_is_the_same_on_arrays_lists_of_arrays_and_numbers():
    P = RNG.normal(size=(6, 2))
    t = 0.3
    as_array = pyramids.casteljau_level(P, t)
    as_rows = pyramids.casteljau_level(list(P), t)
    in_place = pyramids.casteljau_level([row.copy() for row in P], t, inplace=True)
    as_numbers = [pyramids.casteljau_level(list(P[:, c]), t) for c in (0, 1)]
    assert np.array_equal(as_array, np.array(as_rows)) and np.array_equal(as_array, np.array(in_place))
    assert np.array_equal(as_array, np.array(as_numbers).T)
    assert np.allclose(as_array, 0.7 * P[:-1] + 0.3 * P[1:], atol=1e-15)


@pytest.mark.parametrize("k", [2, 3, 4, 5, 7])
@pytest.mark.parametrize("t", [0.5, 0.3, 1.7])
def test_split_pieces_reparametrise_the_curve_and_the_scalar_path_is_the_array_path(k, t):
    P = RNG.normal(size=(k, 2))
    left, right = pyramids.split(P, t)
    s = np.linspace(0, 1, 11)
    assert np.allclose(bezier_reference(left, s), bezier_reference(P, t * s), atol=1e-10)
    assert np.allclose(bezier_reference(right, s), bezier_reference(P, t + (1 - t) * s), atol=1e-10)
    for c in (0, 1):                      # the written-out cubic and quadratic too: the same bits
        lo, hi = pyramids.split(tuple(P[:, c].tolist()), t)
        assert np.array_equal(np.array(lo), left[:, c]) and np.array_equal(np.array(hi), right[:, c])


def test_split_along_an_axis_of_a_stack():
    P = RNG.normal(size=(5, 4, 2))                # five polygons of four points
    left, right = pyramids.split(P, 0.25, axis=1)
    for m in range(5):
        a, b = pyramids.split(P[m], 0.25)
        assert np.array_equal(left[m], a) and np.array_equal(right[m], b)


@pytest.mark.parametrize("n", [0, 1, 2, 3, 4, 6])
def test_point_and_tangent_against_the_polynomial(n):
    P = RNG.normal(size=(n + 1, 2))
    t = 0.37
    x, y, dx, dy = pyramids.point_and_tangent(tuple(P[:, 0]), tuple(P[:, 1]), t)
    assert np.allclose([x, y], bezier_reference(P, t), atol=1e-12)
    h = 1e-6                                       # a central difference of the closed form
    deriv = (bezier_reference(P, t + h) - bezier_reference(P, t - h)) / (2 * h)
    assert np.allclose([dx, dy], deriv, atol=1e-6)


def test_casteljau_levels_and_the_blossom():
    P = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0]])
    assert pyramids.casteljau_blossom(P, np.array([[0.0, 0.0, 1.0]])).tolist() == [[1.0, 3.0]]   # p(0,0,1) = P_1
    U = RNG.uniform(-1, 2, size=(7, 3))
    out = pyramids.casteljau_blossom(P, U)
    assert np.allclose(out, pyramids.casteljau_blossom(P, U[:, ::-1]), atol=1e-12)                 # symmetric
    diag = pyramids.casteljau_blossom(P, np.repeat(U[:, :1], 3, axis=1))
    assert np.allclose(diag, bezier_reference(P, U[:, 0]), atol=1e-12)                           # diagonal = curve
    levels = pyramids.casteljau_levels(P, U[0])
    assert [lv.shape for lv in levels] == [(4, 2), (3, 2), (2, 2), (1, 2)]
    assert np.array_equal(levels[-1][0], out[0])


def test_patch_points_is_the_tensor_product():
    P = RNG.normal(size=(3, 4, 3))
    u, v = RNG.uniform(size=6), RNG.uniform(size=6)
    ref = sum(math.comb(2, i) * u ** i * (1 - u) ** (2 - i) * math.comb(3, j) * v ** j * (1 - v) ** (3 - j)
              * P[i, j][:, None] for i in range(3) for j in range(4))
    assert np.allclose(pyramids.patch_points(P, u, v), ref, atol=1e-12)


def test_quarter_splits_nets_and_domains():
    P = RNG.normal(size=(2, 3, 3, 3))
    dom = np.array([[0.0, 1.0, 0.0, 1.0], [0.0, 0.5, 0.5, 1.0]])
    nets, doms = pyramids.quarter(P, dom)
    assert nets.shape == (8, 3, 3, 3)
    assert doms[:4].tolist() == [[0.0, 0.5, 0.0, 0.5], [0.0, 0.5, 0.5, 1.0], [0.5, 1.0, 0.0, 0.5], [0.5, 1.0, 0.5, 1.0]]


@pytest.mark.parametrize("n", [0, 3, 20, 1500])
def test_bernstein_rows_are_the_binomial_distribution(n):
    t = np.array([0.0, 0.2, 0.5, 0.9, 1.0])
    rows = pyramids.bernstein_rows(n, t)
    ref = binom.pmf(np.arange(n + 1)[:, None], n, t[None, :])
    assert rows.shape == (n + 1, t.size)
    assert np.allclose(rows, ref, atol=1e-12)


# -- pyramids: de Boor ------------------------------------------------------------------------------

def spline_case():
    knots = np.array([0.0, 0, 0, 0, 0.5, 1.5, 1.5, 2.5, 3, 3, 3, 3])
    P = RNG.normal(size=(len(knots) - 4, 2))
    return P, knots, 3


def test_de_boor_points_agree_with_scipy():
    P, t, p = spline_case()
    u = np.linspace(0, 3, 301)
    k = np.clip(np.searchsorted(t, u, side="right") - 1, p, len(P) - 1)
    assert np.allclose(pyramids.de_boor_points(P, t, p, u, k).T, BSpline(t, P, p)(u), atol=1e-12)


def test_de_boor_blossom_recovers_the_control_points_and_its_diagonal_is_the_curve():
    P, t, p = spline_case()
    spans = np.array([4, 4, 6])
    labels = np.array([t[1 + 1:1 + 4], t[4:4 + 3], t[5:5 + 3]])      # b_k(t_{i+1} .. t_{i+p}) = P_i
    assert np.allclose(pyramids.de_boor_blossom(P, t, p, spans, labels), P[[1, 3, 4]], atol=1e-12)
    u = np.array([0.7, 1.2, 1.9])
    diag = pyramids.de_boor_blossom(P, t, p, spans, np.repeat(u[:, None], 3, axis=1))
    assert np.allclose(diag[:2], BSpline(t, P, p)(u[:2]), atol=1e-12)


def test_the_global_pyramid_apex_holds_every_piece():
    P, t, p = spline_case()
    n = len(P) - 1
    x = 1.0
    levels = []
    with np.errstate(invalid="ignore"):
        pyramids.de_boor_pyramid(P.copy(), lambda r, j, q: (x - t[j]) / (t[j + p + 1 - r] - t[j])
                                 if t[j + p + 1 - r] > t[j] else math.nan, p, top=n, record=levels)
    assert [lv.shape[0] for lv in levels] == [n + 1, n, n - 1, n - 2]
    assert np.allclose(levels[p][4 - p], BSpline(t, P, p)(x), atol=1e-12)      # x = 1 lies in span 4


def test_domain_and_number():
    assert pyramids.domain(np.array([0.0, 0, 0, 1, 2, 2, 2]), 2) == (0.0, 2.0)
    assert number(2 / 3) == "0.666667"


# -- polygons ---------------------------------------------------------------------------------------

def test_flatness_even_and_chord_distance():
    P = np.array([[0.0, 0.0], [1.8, 0.0], [2.0, 0.0]])
    assert float(polygons.flatness(P)) == pytest.approx(0.8)
    assert float(polygons.flatness(P, even=False)) == 0.0
    assert float(polygons.flatness(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]))) == 2.0


def test_patch_flatness_of_a_bilinear_and_a_bent_net():
    flat = np.array([[[[0.0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]])
    bent = np.array([[[[0.0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]])
    assert polygons.patch_flatness(flat).tolist() == [0.0]
    assert polygons.patch_flatness(bent).tolist() == [0.25]      # bilinear itself, twist (0, 0, 1) / 4


def test_signed_distances_and_sign_changes():
    pts = np.array([[0.0, 1.0], [1.0, -2.0], [2.0, -2.0], [3.0, 1.0]])
    s = polygons.signed_distances(pts, np.array([0.0, 0.0]), np.array([0.0, 5.0]))
    assert s.tolist() == [1.0, -2.0, -2.0, 1.0]
    assert polygons.sign_changes(s, 1e-12) == 2
    assert polygons.sign_changes(np.array([1.0, 1e-15, 1.0]), 1e-12) == 0


def test_elevate_keeps_the_curve():
    P = RNG.normal(size=(4, 2))
    Q = polygons.elevate(P, 3)
    t = np.linspace(0, 1, 17)
    assert Q.shape == (7, 2)
    assert np.allclose(bezier_reference(Q, t), bezier_reference(P, t), atol=1e-12)


# -- frames -----------------------------------------------------------------------------------------

def test_norm_unit_rows_and_dots():
    v = np.array([[3.0, 4.0, 12.0], [0.0, 0.0, 0.0], [1e300, 1e300, 0.0], [1e-300, 0.0, 0.0]])
    assert frames.norm(v).tolist() == [13.0, 0.0, math.hypot(1e300, 1e300), 1e-300]
    u = frames.unit_rows(v)
    assert np.allclose(u[0], [3 / 13, 4 / 13, 12 / 13]) and u[1].tolist() == [0.0, 0.0, 0.0]
    assert np.allclose(u[2], [math.sqrt(0.5), math.sqrt(0.5), 0.0]) and u[3].tolist() == [1.0, 0.0, 0.0]
    a, b = RNG.normal(size=(5, 3)), RNG.normal(size=(5, 3))
    assert np.allclose(frames.row_dots(a, b), [np.dot(x, y) for x, y in zip(a, b)])


def test_newell_is_the_sum_of_cross_products_and_twice_the_area():
    square = np.array([[0.0, 0, 0], [2, 0, 0], [2, 3, 0], [0, 3, 0]])
    assert frames.newell(square).tolist() == [0.0, 0.0, 12.0]
    P = RNG.normal(size=(3, 6, 3))                             # a stack of non-planar hexagons
    ref = np.cross(P, np.roll(P, -1, axis=1)).sum(axis=1)
    assert np.allclose(frames.newell(P), ref, atol=1e-12)
    far = square + 1e8                                         # far from the origin: no digits lost
    assert frames.newell(far).tolist() == [0.0, 0.0, 12.0]


# -- iteration --------------------------------------------------------------------------------------

def test_frame_is_orthonormal_right_handed_and_follows_major():
    rng = np.random.default_rng(3)
    w = rng.normal(size=(200, 3))
    w /= np.linalg.norm(w, axis=1, keepdims=True)
    major = rng.normal(size=(200, 3))
    for M in (frames.frame(w), frames.frame(w, major)):
        assert M.shape == (200, 3, 3)
        np.testing.assert_allclose(M @ M.transpose(0, 2, 1), np.broadcast_to(np.eye(3), M.shape), atol=1e-14)
        np.testing.assert_allclose(np.linalg.det(M), 1.0, atol=1e-14)            # right-handed: u x v = w
        assert np.array_equal(M[:, 2], w)
    # u lies in the plane of major and w, on major's side: u . major = |major - (major . w) w| > 0
    M = frames.frame(w, major)
    proj = major - np.sum(major * w, axis=1, keepdims=True) * w
    np.testing.assert_allclose(np.sum(M[:, 0] * major, axis=1), np.linalg.norm(proj, axis=1), rtol=1e-12)
    # without major (or with one along w): the axis of least |w_i| projected off w
    assert frames.frame(np.array([0.0, 0.6, 0.8])).round(12).tolist() == [[1, 0, 0], [0, 0.8, -0.6], [0, 0.6, 0.8]]
    assert frames.frame(np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, 3.0])).tolist() == \
        [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    # a stack and its rows one by one agree to the last bit
    assert all(np.array_equal(frames.frame(w[k], major[k]), frames.frame(w, major)[k]) for k in range(0, 200, 17))


def test_apply_affine_maps_is_x_l_plus_t():
    pts = RNG.normal(size=(50, 2))
    L, t = RNG.normal(size=(3, 2, 2)), RNG.normal(size=(3, 2))
    out = iteration.apply_affine_maps(pts, L, t)
    assert np.allclose(out, np.concatenate([pts @ L[i] + t[i] for i in range(3)]), atol=1e-14)
    written = np.concatenate([np.stack([pts[:, 0] * L[i, 0, j] + pts[:, 1] * L[i, 1, j] + t[i, j] for j in (0, 1)],
                                       axis=1) for i in range(3)])
    assert np.array_equal(out, written)            # x a + y c + e in that order, bit for bit
    pts3, L3, t3 = RNG.normal(size=(4, 3)), RNG.normal(size=(2, 3, 3)), RNG.normal(size=(2, 3))
    assert np.allclose(iteration.apply_affine_maps(pts3, L3, t3),
                       np.concatenate([pts3 @ L3[i] + t3[i] for i in range(2)]), atol=1e-14)


def test_iterate_maps_orders_blocks_in_base_k():
    M = RNG.normal(size=(2, 3, 3))
    X = RNG.normal(size=(2, 3))
    out = iteration.iterate_maps(X, M, 2)
    for i2 in range(2):
        for i1 in range(2):
            block = out[(2 * i2 + i1) * 2:(2 * i2 + i1 + 1) * 2]
            assert np.allclose(block, X @ M[i1] @ M[i2], atol=1e-12)


def test_choose_draws_what_generator_choice_draws():
    # numpy's Generator.choice, the reference, for probabilities with zeros at either end
    for p in ([0.01, 0.85, 0.07, 0.07], [0.0, 0.5, 0.5], [0.5, 0.5, 0.0], [1.0], [0.2, 0.0, 0.3, 0.0, 0.5]):
        for shape in ((1,), (7, 33), (2, 4096)):
            ref = np.random.default_rng(4).choice(len(p), size=shape, p=p)
            got = iteration.choose(np.random.default_rng(4), np.array(p), shape)
            assert got.dtype == np.intp and np.array_equal(got, ref), (p, shape)


def test_chaos_steps_is_the_plain_loop_bit_for_bit():
    coef = RNG.normal(size=(6, 3)) * 0.5
    idx = RNG.integers(0, 3, (9, 5))
    out = iteration.chaos_steps(coef, idx, [0.25, -1.0], 4, np.empty((5, 5, 2)))
    for j in range(5):                                # each chain written out point by point
        x, y = 0.25, -1.0
        for s in range(9):
            a, c, e, b, d, f = coef[:, idx[s, j]]
            x, y = x * a + y * c + e, x * b + y * d + f
            if s >= 4:
                assert out[s - 4, j].tolist() == [x, y]
    jump_to = RNG.normal(size=(9, 5, 2))              # map 2 is the condensation "map": jump
    out = iteration.chaos_steps(coef, idx, [0.25, -1.0], 0, np.empty((9, 5, 2)), jump_to)
    assert np.array_equal(out[idx == 2], jump_to[idx == 2])


# -- relaxation -------------------------------------------------------------------------------------

def test_jacobi_and_gauss_seidel_sweeps_converge_to_the_solution():
    A = np.array([[4.0, 1.0, 1.0], [2.0, 5.0, 1.0], [0.0, 1.0, 3.0]])
    b = np.array([1.0, 2.0, 3.0])
    d = np.diag(A)
    R = A - np.diag(d)
    xj, xg = np.zeros(3), np.zeros(3)
    for _ in range(200):
        xj = relaxation.jacobi_update(b, relaxation.gather(-R, xj), d)
        relaxation.gauss_seidel_sweep(-R, b, xg, d=d)
    exact = np.linalg.solve(A, b)
    assert np.allclose(xj, exact, atol=1e-14) and np.allclose(xg, exact, atol=1e-14)


def test_the_radiosity_form_with_channels():
    F = np.array([[0.0, 0.5], [0.5, 0.0]])
    rho = np.array([[0.5, 0.2], [0.5, 0.4]])
    E = np.array([[1.0, 1.0], [0.0, 1.0]])
    B = E.copy()
    for _ in range(100):
        relaxation.gauss_seidel_sweep(F, E, B, rho)
    exact = np.stack([np.linalg.solve(np.eye(2) - rho[:, c, None] * F, E[:, c]) for c in range(2)], axis=1)
    assert np.allclose(B, exact, atol=1e-14)
    assert relaxation.gauss_seidel_sweep(F, np.ones(2), np.ones(2), np.array([0.5, 0.5])).tolist() == [1.25, 1.3125]


# -- meshes -----------------------------------------------------------------------------------------

def test_rasterise_covers_the_pixel_centres_inside_and_keeps_the_nearest():
    S = np.array([[0.0, 0.0, 0.5], [8.0, 0.0, 0.5], [0.0, 8.0, 0.5], [0.0, 0.0, 0.2], [8.0, 0.0, 0.2],
                  [8.0, 8.0, 0.2]])
    T = np.array([[0, 1, 2], [3, 4, 5]])
    tri, depth, weights = meshes.rasterise(S, T, 8, 8)
    cx, cy = np.meshgrid(np.arange(8) + 0.5, np.arange(8) + 0.5)
    in_first = cx + cy <= 8
    in_second = cy <= cx
    assert np.array_equal(tri >= 0, in_first | in_second)
    assert np.all(tri[in_second] == 1) and np.allclose(depth[in_second], 0.2)       # the nearer one wins
    assert np.all(tri[in_first & ~in_second] == 0)
    assert np.allclose(weights[tri >= 0].sum(axis=1), 1.0)
    assert np.all(tri[~(in_first | in_second)] == -1) and np.all(depth[tri < 0] == 1.0)


def test_mesh_tables_edges_fans_and_orientation_against_plain_python():
    rng = np.random.default_rng(5)
    for _ in range(30):
        n = int(rng.integers(5, 12))
        loops = [rng.choice(n, size=int(rng.integers(3, 6)), replace=False).tolist() for _ in range(int(rng.integers(1, 8)))]
        corners, sizes = meshes.flatten(loops)
        assert corners.tolist() == [v for f in loops for v in f] and sizes.tolist() == [len(f) for f in loops]
        directed = [(f[k], f[(k + 1) % len(f)]) for f in loops for k in range(len(f))]
        edges, of_corner = meshes.edge_table(corners, sizes, n)
        assert [tuple(e) for e in edges.tolist()] == sorted({(min(a, b), max(a, b)) for a, b in directed})
        assert [tuple(edges[e]) for e in of_corner] == [(min(a, b), max(a, b)) for a, b in directed]
        twice = sorted({d for d in directed if directed.count(d) > 1})
        assert [tuple(r) for r in meshes.same_direction_edges(corners, sizes, n).tolist()] == twice
        assert meshes.fan_triangles(corners, sizes).tolist() == [[f[0], f[k], f[k + 1]] for f in loops
                                                                 for k in range(1, len(f) - 1)]
    # the polyhedra: unit-free corners of [-1, 1]^3, every edge of the cube of length 2 and run once each
    # way, the tetrahedron's of length 2 sqrt 2; outward: the divergence theorem's volume is positive
    for V, F, volume, length in ((meshes.CUBE_VERTICES, meshes.CUBE_FACES, 8.0, 2.0),
                                 (meshes.TETRAHEDRON_VERTICES, meshes.TETRAHEDRON_FACES, 8 / 3, 2 * math.sqrt(2))):
        assert not V.flags.writeable and not F.flags.writeable and np.all(np.abs(V) == 1)
        corners, sizes = meshes.flatten(F)
        edges, _ = meshes.edge_table(corners, sizes, len(V))
        assert np.allclose(np.linalg.norm(V[edges[:, 0]] - V[edges[:, 1]], axis=1), length)
        assert len(meshes.same_direction_edges(corners, sizes, len(V))) == 0
        T = V[meshes.fan_triangles(corners, sizes)]
        assert np.einsum("ij,ij->i", T[:, 0], np.cross(T[:, 1], T[:, 2])).sum() / 6 == pytest.approx(volume)
    assert meshes.CUBE_VERTICES[5].tolist() == [1, -1, 1]            # vertex k: the bits of k, x first


def test_split_xy_is_split_of_each_coordinate():
    for k in (2, 3, 4, 6):
        P = RNG.normal(size=(k, 2))
        xs, ys = tuple(P[:, 0].tolist()), tuple(P[:, 1].tolist())
        assert pyramids.split_xy(xs, ys, 0.5) == pyramids.split(xs, 0.5) + pyramids.split(ys, 0.5)


def test_de_boor_pyramid_per_level_is_node_by_node_bit_for_bit():
    P, t, p = spline_case()
    n, x = len(P) - 1, 1.2

    def node(r, j, q):
        return (x - t[j]) / (t[j + p + 1 - r] - t[j]) if t[j + p + 1 - r] > t[j] else math.nan

    def level(r):
        lo, hi = t[r:n + 1], t[p + 1:n + p + 2 - r]
        return np.divide(x - lo, hi - lo, out=np.full(lo.shape, np.nan), where=hi > lo)
    a, b = [], []
    with np.errstate(invalid="ignore"):
        pyramids.de_boor_pyramid(P.copy(), node, p, top=n, record=a)
        pyramids.de_boor_pyramid(P.copy(), level, p, top=n, record=b, per_level=True)
    assert all(np.array_equal(u, v, equal_nan=True) for u, v in zip(a, b))


def test_unit_newell_is_newell_over_its_length_and_right_where_the_squares_overflow():
    """kernels.frames.unit_newell: the one unit Newell normal (shading.unit_newell_normal and the B-rep
    faces of solid_modeling): bit for bit newell / numpy.linalg.norm on ordinary polygons, zeros for
    a polygon without area, and the right direction where |N|^2 overflows."""
    from goldman_lib.kernels import frames as fr

    rng = np.random.default_rng(5)
    for _ in range(200):
        P = rng.normal(size=(int(rng.integers(3, 8)), 3)) * 10.0 ** rng.integers(-5, 6)
        n = fr.newell(P)
        np.testing.assert_array_equal(fr.unit_newell(P), n / np.linalg.norm(n))
    assert fr.unit_newell(np.array([[0.0, 0, 0], [1, 1, 1], [2, 2, 2]])).tolist() == [0.0, 0.0, 0.0]
    big = np.array([[0.0, 0, 0], [0, 1e154, 0], [0, 0, 1e154]])         # |N|^2 = 1e616 overflows
    assert fr.unit_newell(big).tolist() == [1.0, 0.0, 0.0]

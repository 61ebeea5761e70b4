"""goldman_lib.radiosity against independent references: the closed forms of the form factors
(parallel unit squares at unit distance 0.19982, perpendicular unit squares 0.20004, the
differential-area-to-rectangle formula), numpy.linalg.solve of (I - diag(rho) F) B = E, values worked
by hand on 2-patch systems, row sums of 1 in a closed box, reciprocity."""

import math

import numpy as np
import pytest

from goldman_lib import fixed_point as fp
from goldman_lib import radiosity as rd


def _square_pair_parallel():
    return rd.Patches([[0, 0, 0], [0, 1, 1]], [[1, 0, 0], [1, 0, 0]], [[0, 1, 0], [0, -1, 0]],
                      [[0.5] * 3] * 2, [[0.0] * 3] * 2)


def _square_pair_perpendicular():
    # floor square [0,1]^2 at z=0 facing +z; wall square x in [0,1], z in [0,1] at y=0 facing +y
    return rd.Patches([[0, 0, 0], [0, 0, 0]], [[1, 0, 0], [0, 0, 1]], [[0, 1, 0], [1, 0, 0]],
                      [[0.5] * 3] * 2, [[0.0] * 3] * 2)


def test_closed_forms_against_the_published_values():
    assert rd.form_factor_parallel_rectangles(1, 1, 1) == pytest.approx(0.19982, abs=5e-6)
    assert rd.form_factor_perpendicular_rectangles(1, 1, 1) == pytest.approx(0.20004, abs=5e-6)
    # scale invariance and the limits: far apart -> A / (pi d^2); close -> 1
    assert rd.form_factor_parallel_rectangles(2, 2, 2) == pytest.approx(0.19982, abs=5e-6)
    assert rd.form_factor_parallel_rectangles(0.01, 0.01, 1) == pytest.approx(1e-4 / math.pi, rel=1e-3)
    assert rd.form_factor_parallel_rectangles(1000, 1000, 1) > 0.998
    # reciprocity for unequal perpendicular rectangles: A1 F12 = A2 F21
    l, w, h = 1.0, 2.0, 0.5
    assert w * rd.form_factor_perpendicular_rectangles(l, w, h) == pytest.approx(
        h * rd.form_factor_perpendicular_rectangles(l, h, w), rel=1e-12)


def test_point_to_polygon_against_the_corner_formula():
    # dA below the corner of an a x b rectangle at height c: F = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + ...]
    a, b, c = 1.0, 2.0, 1.5
    A, B = a / c, b / c
    exact = (A / math.sqrt(1 + A * A) * math.atan(B / math.sqrt(1 + A * A))
             + B / math.sqrt(1 + B * B) * math.atan(A / math.sqrt(1 + B * B))) / (2 * math.pi)
    got = rd.form_factor_point_polygon([0, 0, 0], [0, 0, 1], [[0, 0, c], [a, 0, c], [a, b, c], [0, b, c]])
    assert got == pytest.approx(exact, rel=1e-12)
    # a polygon below the tangent plane is invisible; one cut by it is clipped
    assert rd.form_factor_point_polygon([0, 0, 0], [0, 0, 1], [[0, 0, -1], [1, 0, -1], [0, 1, -1]]) == 0.0
    half = rd.form_factor_point_polygon([0, 0, 0], [0, 0, 1], [[-5, 1, -5], [5, 1, -5], [5, 1, 5], [-5, 1, 5]])
    top = rd.form_factor_point_polygon([0, 0, 0], [0, 0, 1], [[-5, 1, 0], [5, 1, 0], [5, 1, 5], [-5, 1, 5]])
    assert half == pytest.approx(top, rel=1e-9)


def test_delta_form_factors_sum_to_one():
    assert rd.hemicube_delta_form_factors(128).sum() == pytest.approx(1.0, abs=1e-4)
    d, face = rd.hemicube_cells(8)
    assert d.shape == (192, 3) and np.all(d[:, 2] > 0) and np.all(np.abs(d).max(axis=1) == 1)
    # a top-face cell at (x, y, 1): dA / (pi (x^2 + y^2 + 1)^2), worked for the first cell
    x = y = -1 + 0.125
    assert rd.hemicube_delta_form_factors(8)[0] == pytest.approx(0.0625 / (math.pi * (x * x + y * y + 1) ** 2))


def test_hemicube_within_two_percent_of_the_closed_forms():
    par = rd.hemicube_form_factors(_square_pair_parallel(), resolution=32, subdivisions=8)
    per = rd.hemicube_form_factors(_square_pair_perpendicular(), resolution=32, subdivisions=8)
    assert par[0, 1] == pytest.approx(0.19982, rel=0.02) and par[1, 0] == pytest.approx(0.19982, rel=0.02)
    assert per[0, 1] == pytest.approx(0.20004, rel=0.02) and per[1, 0] == pytest.approx(0.20004, rel=0.02)
    assert np.all(np.diag(par) == 0)


def test_hemicube_progress_counts_the_hemicubes_and_changes_nothing():
    box = rd.cornell_box(4)                                   # 128 patches, blocks included
    calls = []
    F = rd.hemicube_form_factors(box, resolution=16, subdivisions=2, progress=lambda k, n: calls.append((k, n)))
    assert len(calls) >= 2                                    # several batches, each reported
    done = [k for k, _ in calls]
    assert done == sorted(done) and len(set(done)) == len(done)
    assert {n for _, n in calls} == {len(box) * 4} and calls[-1] == (len(box) * 4, len(box) * 4)
    assert np.array_equal(F, rd.hemicube_form_factors(box, resolution=16, subdivisions=2))
    with pytest.raises(TypeError, match="progress must be a function"):
        rd.hemicube_form_factors(box, resolution=16, progress=3)


def test_hemicube_stops_when_interrupted():
    """The kernel's stop button raises KeyboardInterrupt inside the loop; here the callback raises it
    after the first batch, and nothing of the half-done work is returned."""
    def stop(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        rd.hemicube_form_factors(rd.cornell_box(4), resolution=16, progress=stop)


def test_hemicube_rows_against_the_point_formula():
    box = rd.cornell_box(4, blocks=False)
    F = rd.hemicube_form_factors(box, resolution=64)
    i = 5                                                     # a floor patch
    exact = [rd.form_factor_point_polygon(box.centres[i], box.normals[i], box.corners[j]) for j in range(len(box))]
    assert np.abs(F[i] - exact).sum() < 0.02


def test_closed_box_rows_sum_to_one_and_reciprocity():
    box = rd.cornell_box(6, closed=True, blocks=False)
    F = rd.hemicube_form_factors(box, resolution=24)
    assert np.allclose(F.sum(axis=1), 1.0, atol=0.01)
    assert rd.reciprocity_error(F, box.areas) < 0.3
    Fr = rd.enforce_reciprocity(F, box.areas)
    AF = box.areas[:, None] * Fr
    assert np.allclose(AF, AF.T, atol=1e-15) and rd.reciprocity_error(Fr, box.areas) < 1e-12
    # the open box and the blocks: rows sum to at most 1
    open_box = rd.cornell_box(4)
    G = rd.hemicube_form_factors(open_box, resolution=16)
    assert np.all(G.sum(axis=1) <= 1.005)


def _system(n=30, seed=3, channels=3):
    rng = np.random.default_rng(seed)
    area = rng.uniform(0.5, 2.0, n)
    S = rng.uniform(0, 1, (n, n))
    S = S + S.T
    np.fill_diagonal(S, 0)
    AF = S / S.sum() * area.sum() * 0.9 / 1.0
    F = AF / area[:, None]
    F = F / max(1.0, F.sum(axis=1).max())                    # rows <= 1, A F symmetric up to the scale
    F = rd.enforce_reciprocity(F, area)
    rho = rng.uniform(0.1, 0.9, (n, channels))
    E = np.zeros((n, channels))
    E[:3] = rng.uniform(1, 5, (3, channels))
    return F, rho, E, area


def _solve(F, rho, E):
    return np.stack([np.linalg.solve(np.eye(len(F)) - rho[:, c, None] * F, E[:, c]) for c in range(E.shape[1])], 1)


@pytest.mark.parametrize("name", ["jacobi", "gauss_seidel", "progressive_refinement"])
def test_solvers_agree_with_numpy_linalg_solve(name):
    F, rho, E, area = _system()
    exact = _solve(F, rho, E)
    args = (F, rho, E, area) if name == "progressive_refinement" else (F, rho, E)
    B = getattr(rd, name)(*args, tol=1e-11)
    assert isinstance(B, np.ndarray) and B.shape == E.shape
    assert np.abs(B - exact).max() < 1e-9
    B2, h = getattr(rd, name)(*args, tol=1e-11, full_output=True)
    assert isinstance(h, fp.Convergence) and h.reason == "converged" and h.message == ""
    assert np.array_equal(B2, B) and h.x is B2
    assert h.converged and h.residuals[-1] <= 1e-11 and np.allclose(h.x, B)
    assert len(h.history) == len(h.residuals) == h.iterations + 1 and np.allclose(h.history[0], E)
    for k in (0, 1, h.iterations):
        assert h.residuals[k] == pytest.approx(rd.residual(F, rho, E, h.history[k]), rel=1e-9, abs=1e-14)


def test_one_channel_and_two_patches_by_hand():
    F, rho, E = [[0, 0.5], [0.5, 0]], [0.5, 0.5], [1.0, 1.0]
    # exact: B0 = 1 + 0.25 B1, B1 = 1 + 0.25 B0 -> B = 4/3
    assert np.allclose(rd.jacobi(F, rho, E, tol=1e-13), [4 / 3, 4 / 3])
    _, hj = rd.jacobi(F, rho, E, tol=1e-13, full_output=True)
    assert hj.history[1].tolist() == [1.25, 1.25] and hj.residuals[0] == 0.25
    assert hj.method == "Jacobi" and hj.shooters is None
    _, hg = rd.gauss_seidel(F, rho, E, tol=1e-13, full_output=True)
    assert hg.history[1].tolist() == [1.25, 1.3125] and hg.iterations < hj.iterations
    assert hg.method == "Gauss-Seidel"
    _, hp = rd.progressive_refinement(F, rho, [2.0, 1.0], [1.0, 1.0], tol=1e-13, full_output=True)
    # first shot from patch 0 (power 2): patch 1 gets 0.5 * 0.5 * 2 = 0.5
    assert hp.shooters[0] == 0 and hp.history[1].tolist() == [2.0, 1.5]
    assert hp.method == "progressive refinement" and len(hp.shooters) == hp.iterations


def test_edge_cases_and_budgets():
    F, rho, E, area = _system(5)
    zero = np.zeros_like(E)
    for B in (rd.jacobi(F, rho, zero), rd.gauss_seidel(F, rho, zero), rd.progressive_refinement(F, rho, zero, area)):
        assert np.all(B == 0)                                     # a non-emitting scene stays dark
    black = rho.copy(); black[:] = 0
    assert np.allclose(rd.jacobi(F, black, E), E)                 # black patches reflect nothing
    one = rd.progressive_refinement([[0.0]], [0.5], [2.0], [1.0])
    assert one.tolist() == [2.0]
    B, h = rd.jacobi(F, rho, E, tol=1e-14, max_iter=2, full_output=True)
    assert h.iterations == 2 and not h.converged and h.reason == "max iterations" and "above tol" in h.message
    for solver, args in ((rd.jacobi, ()), (rd.gauss_seidel, ()), (rd.progressive_refinement, (area,))):
        with pytest.raises(fp.ConvergenceError, match="did not converge.*max_iter") as info:   # as fixed_point's
            solver(F, rho, E, *args, tol=1e-14, max_iter=2)
        assert info.value.report.iterations == 2 and not info.value.report.converged
    with pytest.raises(ValueError, match="max_iter"):
        rd.jacobi(F, rho, E, max_iter=10**9)
    for solver in (rd.jacobi, rd.gauss_seidel):               # one spelling: the old keywords are gone
        with pytest.raises(TypeError):
            solver(F, rho, E, max_iterations=2)
        with pytest.raises(TypeError):
            solver(F, rho, E, return_history=True)
    with pytest.raises(ValueError, match="rows must sum"):
        rd.jacobi([[0.6, 0.6], [0.5, 0]], [0.5, 0.5], [1, 0])
    with pytest.raises(ValueError, match="rho"):
        rd.jacobi(F, rho + 1, E)
    with pytest.raises(ValueError, match="resolution"):
        rd.hemicube_form_factors(_square_pair_parallel(), resolution=7)


def test_cornell_box_and_display():
    box = rd.cornell_box()
    assert 300 <= len(box) <= 600 and set(box.labels) >= {"floor", "ceiling", "back", "left", "right"}
    assert np.allclose(box.areas.sum(), 5 + 5 * 0.375 ** 2 + (0.375 ** 2 + 4 * 0.375 * 0.75))
    # the light: 0.25 x 0.25 of emission 10 at the ceiling's centre -> power 0.625 per channel
    assert (box.emission[:, 0] * box.areas).sum() == pytest.approx(0.625)
    assert np.all(box.normals[np.array(box.labels) == "ceiling"] == [0, 0, -1])
    moved = rd.light_emission(box, 0.3, 0.7, 0.25, (1, 2, 3))
    assert (moved * box.areas[:, None]).sum(axis=0) == pytest.approx([0.0625, 0.125, 0.1875])
    B = np.arange(len(box), dtype=float)
    pos, tri, VB = rd.vertex_radiosities(box, B)
    assert VB.shape == (len(pos),) and tri.shape == (2 * len(box), 3)
    corner = np.argmin(np.abs(pos - [0, 0, 0]).sum(axis=1))
    assert VB[corner] in B                                         # a corner of a wall has one patch
    flat, tri_f, owner = rd.patch_mesh(box, shared=False)
    assert len(flat) == 4 * len(box) and np.array_equal(owner, np.repeat(np.arange(len(box)), 4))
    assert rd.to_colours([0.0, 0.25, 9.0], white=1.0, gamma=2.0).tolist() == [0.0, 0.5, 1.0]


def test_a_patch_that_sees_itself():
    # F_ii > 0 (a concave patch): B = E + rho F B with F = 0.5 everywhere, rho = 0.5, E = (1, 0):
    # B1 = 1 + 0.25 (B1 + B2), B2 = 0.25 (B1 + B2) -> B2 = B1 / 3, B1 = 1.5
    F = np.full((2, 2), 0.5)
    for B in (rd.jacobi(F, [0.5, 0.5], [1.0, 0.0], tol=1e-13), rd.gauss_seidel(F, [0.5, 0.5], [1.0, 0.0], tol=1e-13),
              rd.progressive_refinement(F, [0.5, 0.5], [1.0, 0.0], [1.0, 1.0], tol=1e-13)):
        assert np.allclose(B, [1.5, 0.5], atol=1e-12)


def test_shooting_operators_are_reused_and_checked():
    F, rho, E, area = _system()
    ops = rd.shooting_operators(F, rho, area)
    _, plain = rd.progressive_refinement(F, rho, E, area, tol=1e-11, full_output=True)
    _, reused = rd.progressive_refinement(F, rho, E, area, tol=1e-11, full_output=True, operators=ops)
    assert np.array_equal(plain.shooters, reused.shooters)
    assert np.abs(plain.history - reused.history).max() < 1e-12
    moved = E[::-1].copy()                                   # another emission, the same operators
    assert np.abs(rd.progressive_refinement(F, rho, moved, area, tol=1e-11, operators=ops)
                  - _solve(F, rho, moved)).max() < 1e-9
    short = rd.shooting_operators(F, rho, area, update_residual=False)
    assert short.change is None
    assert np.abs(rd.progressive_refinement(F, rho, E, area, tol=1e-11, operators=short) - plain.x).max() < 1e-12
    with pytest.raises(ValueError, match="operators"):
        rd.progressive_refinement(F, rho * 0.5, E, area, operators=ops)
    with pytest.raises(TypeError, match="operators"):
        rd.progressive_refinement(F, rho, E, area, operators="cached")
    F[0, 0] += 0.01                                          # the caller's F stays writable; ops keep a copy
    with pytest.raises(ValueError, match="operators"):
        rd.progressive_refinement(F, rho, E, area, operators=ops)

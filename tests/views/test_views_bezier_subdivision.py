"""Chapter 25 widgets: every callback swept over its controls (corners included) draws finite
geometry, and what it draws is what the library computes (checked against de Casteljau
evaluation and closed forms, not against the view's own arithmetic)."""

import matplotlib
import numpy as np
import pytest

from goldman_lib import bezier
from goldman_lib.views import bezier_subdivision as views

matplotlib.use("Agg")

def test_bezier_subdivision_view_draws_pieces_of_the_curve():
    view = views.bezier_subdivision_view()
    ctrl = views.DEFAULT_CUBIC
    for depth, t in ((0, 0.5), (2, 0.5), (3, 0.3)):
        polys = view.set_values(depth=depth, t=t)["polygons"]
        assert len(polys) == 2 ** depth
        # consecutive pieces share end points, first and last are the curve's ends
        np.testing.assert_allclose(polys[0, 0], ctrl[0])
        np.testing.assert_allclose(polys[-1, -1], ctrl[-1])
        np.testing.assert_allclose(polys[1:, 0], polys[:-1, -1])
        # every joint is a point of the curve: the joints at depth 2, t=1/2 are C(k/4)
        if depth == 2 and t == 0.5:
            np.testing.assert_allclose(polys[:, 0], bezier.de_casteljau(ctrl, [0, 0.25, 0.5, 0.75]), atol=1e-12)
    gaps = [view.set_values(depth=d, t=0.5)["gap"] for d in range(5)]
    assert all(g1 < g0 for g0, g1 in zip(gaps, gaps[1:]))


def test_bezier_subdivision_view_control_points_are_dragged(hooks):
    view = views.bezier_subdivision_view(depth=2)
    hooks["press_at"](view.drag, 3.0, 2.5)          # on P2
    hooks["move_to"](view.drag, 2.0, 1.0)
    hooks["release"](view.drag)
    assert (view.values()["x2"], view.values()["y2"]) == (2.0, 1.0)
    P = np.array([[0, 0], [1, 2.5], [2, 1.0], [4, 0.5]])
    r = view.last_result
    np.testing.assert_allclose(r["polygon"], P)
    np.testing.assert_allclose(r["curve"], bezier.de_casteljau(P, np.linspace(0, 1, 400)), atol=1e-12)
    np.testing.assert_allclose(r["polygons"][:, 0], bezier.de_casteljau(P, [0, 0.25, 0.5, 0.75]), atol=1e-12)
    np.testing.assert_allclose(np.column_stack(view.ax.lines[1].get_data()), r["curve"])


def test_adaptive_rendering_view_polyline_lies_on_the_curve():
    view = views.adaptive_rendering_view()
    prev = 0
    for digits in (1, 2, 3, 4):
        r = view.set_values(digits=digits)
        np.testing.assert_allclose(r["polyline"], bezier.de_casteljau(views.WAVY, r["t"]), atol=1e-12)
        assert r["segments"] > prev
        prev = r["segments"]


def test_adaptive_rendering_view_control_points_are_dragged(hooks):
    view = views.adaptive_rendering_view(digits=3)
    hooks["press_at"](view.drag, 2.0, -1.0)         # on P2 of WAVY
    hooks["move_to"](view.drag, 2.0, 1.0)
    hooks["release"](view.drag)
    assert (view.values()["x2"], view.values()["y2"]) == (2.0, 1.0)
    P = views.WAVY.copy()
    P[2] = (2.0, 1.0)
    r = view.last_result
    np.testing.assert_allclose(r["polygon"], P)
    np.testing.assert_allclose(r["polyline"], bezier.de_casteljau(P, r["t"]), atol=1e-12)
    np.testing.assert_allclose(np.column_stack(view.ax.lines[2].get_data()), r["polyline"])
    np.testing.assert_allclose(np.column_stack(view.ax.lines[1].get_data()),
                               bezier.de_casteljau(P, np.linspace(0, 1, 2001))[::5], atol=1e-12)


def test_intersection_view_points_are_on_both_curves():
    view = views.intersection_view()
    r = view.set_values(case="two cubics, three crossings", level=10, shift=0.0)
    a, b = views.INTERSECTION_EXAMPLES["two cubics, three crossings"]
    # this pair is symmetric under the half turn about (1.5, 0.5) and meets at t = 1/2 and two more points
    assert len(r["params"]) == 3
    np.testing.assert_allclose(r["params"][1], [0.5, 0.5], atol=1e-12)
    np.testing.assert_allclose(bezier.de_casteljau(b, r["params"][:, 1]), r["points"], atol=1e-10)
    # the boxes kept at a deep level contain the intersection points
    for p in r["points"]:
        inside = np.all((r["boxes_a"][:, 0] <= p + 1e-9) & (p <= r["boxes_a"][:, 1] + 1e-9), axis=1)
        assert inside.any()


def test_intersection_view_shift_moves_the_second_curve():
    view = views.intersection_view()
    r0 = view.set_values(case="parabola and line", level=0, shift=0.0)
    r1 = view.set_values(case="parabola and line", level=0, shift=1.0)
    # parabola y = 6t(1-t) (max 1.5), line from 0.8 to 1.2: lifted by 1 it clears the apex
    assert len(r0["params"]) == 2 and len(r1["params"]) == 0
    np.testing.assert_allclose(r1["boxes_b"][0], [[0, 1.8], [3, 2.2]])


def test_intersection_view_rejects_an_unknown_case():
    with pytest.raises(ValueError, match="case must be one of"):
        views.intersection_view(case="nope")


def test_patch_rendering_view_covers_the_domain():
    view = views.patch_rendering_view()
    counts = []
    for digits in (0, 1, 2):
        r = view.set_values(digits=digits)
        dom = r["domains"]
        assert ((dom[:, 1] - dom[:, 0]) * (dom[:, 3] - dom[:, 2])).sum() == pytest.approx(1.0)
        np.testing.assert_allclose(r["corners"][:, 0], bezier.patch_de_casteljau(views.DEFAULT_PATCH_25, dom[:, 0], dom[:, 2]),
                                   atol=1e-12)
        counts.append(r["pieces"])
    assert counts[0] < counts[1] < counts[2]


def _bump(u, v):
    """DEFAULT_PATCH_25 in closed form: x = 3u, y = 3v, z = sum z_ij B_i(u) B_j(v) with the
    cubic Bernstein polynomials written out (z_11 = 2, z_12 = z_21 = 1, the rest 0)."""
    b1 = lambda t: 3 * t * (1 - t) ** 2          # noqa: E731
    b2 = lambda t: 3 * t ** 2 * (1 - t)          # noqa: E731
    return np.stack([3 * u, 3 * v, 2 * b1(u) * b1(v) + b1(u) * b2(v) + b2(u) * b1(v)], -1)


def test_patch_subdivision_3d_view_sub_nets_converge_to_the_surface():
    view = views.patch_subdivision_3d_view()
    gaps = []
    for level in range(5):
        r = view.set_values(mode="sub-nets", level=level, height=0.3)
        nets, doms = r["sub-nets"], r["domains"]
        assert nets.shape == (4 ** level, 4, 4, 3)
        # the rectangles tile the unit square, and the corner points of every sub-net are on the surface
        assert ((doms[:, 1] - doms[:, 0]) * (doms[:, 3] - doms[:, 2])).sum() == pytest.approx(1.0)
        for (i, j), (a, b) in {(0, 0): (0, 2), (-1, 0): (1, 2), (0, -1): (0, 3), (-1, -1): (1, 3)}.items():
            np.testing.assert_allclose(nets[:, i, j], _bump(doms[:, a], doms[:, b]), atol=1e-12)
        # what the three.js scene holds is what update returned
        drawn = view.scene.data("sub-nets")
        assert len(drawn["segments"]) == 24 * 4 ** level
        np.testing.assert_allclose(drawn["positions"], nets.reshape(-1, 3))
        gaps.append(r["gap"])
        assert len(r["points"]) == 0
    # each level brings the control points about four times closer (O(h^2) convergence)
    assert all(3.0 < g0 / g1 < 8.0 for g0, g1 in zip(gaps[1:], gaps[2:]))


@pytest.mark.parametrize("height", [0.1, 0.3, 0.6])
def test_patch_subdivision_3d_view_intersection_is_on_both_surfaces(height):
    view = views.patch_subdivision_3d_view()
    r = view.set_values(mode="intersection", level=3, height=height)
    pts, par = r["points"], r["params"]
    assert len(pts) >= 8
    np.testing.assert_allclose(_bump(par[:, 0], par[:, 1]), pts, atol=1e-9)     # on the bicubic patch
    np.testing.assert_allclose(pts[:, 2], height, atol=1e-9)                     # on the plane
    # the plane patch's own parameters: x = x0 + (x1 - x0) s over its square
    plane = view.scene.data("second patch")["positions"]
    x0, x1 = plane[:, 0].min(), plane[:, 0].max()
    np.testing.assert_allclose(x0 + (x1 - x0) * par[:, 2], pts[:, 0], atol=1e-9)
    np.testing.assert_allclose(plane[:, 2], height)
    # the drawn curve is a closed polyline through the points
    segs = r["segments"]
    assert len(segs) == len(pts)
    drawn = view.scene.data("intersection")["positions"]        # drawn a hair above the plane
    np.testing.assert_allclose(drawn[:, :2], pts[:, :2])
    assert np.all((drawn[:, 2] > pts[:, 2]) & (drawn[:, 2] <= pts[:, 2] + 0.021))   # 1% of the net height 2
    # the sub-nets drawn are exactly those whose boxes reach the plane
    for P in r["sub-nets"]:
        assert P[..., 2].min() <= height <= P[..., 2].max()
    assert len(r["sub-nets"]) < 4 ** 3


def test_patch_subdivision_3d_view_rejects_an_unknown_mode():
    with pytest.raises(ValueError, match="mode must be one of"):
        views.patch_subdivision_3d_view(mode="nope")

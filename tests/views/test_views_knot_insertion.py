"""Chapter 28 widgets: every callback swept over its slider ranges (corners included) draws finite
geometry, and what is drawn is the same curve as scipy's BSpline of the original control points."""

import numpy as np
import pytest
from scipy.interpolate import BSpline

from goldman_lib import knot_insertion as ki
from goldman_lib.views import knot_insertion as views

P, T, D = views.DEFAULT_POLYGON, views.DEFAULT_KNOTS, views.DEFAULT_DEGREE


def same_curve(ctrl, knots, p, new_ctrl, new_knots):
    u = np.linspace(knots[p], knots[len(knots) - p - 1], 60)[:-1]
    np.testing.assert_allclose(BSpline(new_knots, new_ctrl, p)(u), BSpline(knots, ctrl, p)(u), atol=1e-9)


@pytest.mark.parametrize("u,times", [(0.4, 1), (0.5, 2), (0.1, 3), (0.25, 3), (0.5, 4)])
def test_boehm_view_draws_the_inserted_polygon_of_the_same_curve(u, times):
    view = views.boehm_view()
    result = view.update(u=u, times=times)
    same_curve(P, T, D, result["polygon"], result["knots"])
    s = int(np.count_nonzero(T == u))
    assert len(result["polygon"]) == len(P) + min(times, D + 1 - s)
    # the crossed-out points are points of the polygon before the last step; the new points lie in the new polygon
    k = min(times, D + 1 - s)
    before = ki.boehm_insert(P, T, D, u, k - 1)[0] if k else P
    if len(result["replaced"]):
        assert len(result["replaced"]) == D - 1 and len(result["new"]) == D
        assert all(any(np.allclose(g, q) for q in before) for g in result["replaced"])
        assert all(any(np.allclose(g, q) for q in result["polygon"]) for g in result["new"])


def test_boehm_view_with_multiplicity_limit_says_so():
    result = views.boehm_view().update(u=0.5, times=4)   # 0.5 is already a knot: 3 more at most
    assert "at most 3 more" in result["status"]


@pytest.mark.parametrize("count,step", [(1, 0), (4, 3), (8, 14), (3, 14)])
def test_oslo_view_draws_the_refined_polygon_and_a_pyramid(count, step):
    result = views.oslo_view().update(count=count, step=step)
    tau = result["knots"]
    assert len(tau) == len(T) + count
    same_curve(P, T, D, result["polygon"], tau)
    np.testing.assert_allclose(result["done"][-1], result["point"])
    assert [len(lv) for lv in result["levels"]] == [D + 1, D, D - 1, 1][:D + 1]


def test_oslo_view_refuses_a_step_its_slider_cannot_reach():
    with pytest.raises(ValueError, match=r"step must be <= 14; got 100"):
        views.oslo_view().update(count=3, step=100)


@pytest.mark.parametrize("p", [1, 2, 3, 5])
@pytest.mark.parametrize("level", [0, 1, 3])
def test_bspline_subdivision_view_level_polygons_are_the_same_curve(p, level):
    view = views.bspline_subdivision_view()
    # open uniform Lane-Riesenfeld: knots spacing 2^-L from p (1 - 2^-L)
    result = view.update(algorithm="Lane-Riesenfeld (uniform)", degree=p, level=level, round=p)
    h = 2.0 ** -level
    knots = p * (1 - h) + h * np.arange(len(result["polygon"]) + p + 1)
    same_curve(P, np.arange(len(P) + p + 1.0), p, result["polygon"], knots)
    # Schaefer on the clamped curve
    result = view.update(algorithm="Schaefer (clamped)", degree=p, level=level, round=p)
    clamped = np.r_[np.zeros(p), np.linspace(0, 1, len(P) - p + 1), np.ones(p)]
    Q, tau = ki.schaefer(P, clamped, p, level)
    np.testing.assert_allclose(result["polygon"], Q)
    same_curve(P, clamped, p, Q, tau)


def test_bspline_subdivision_view_closed_and_rounds():
    view = views.bspline_subdivision_view()
    result = view.update(algorithm="Lane-Riesenfeld (closed)", degree=3, level=2, round=3)
    assert len(result["polygon"]) == 4 * len(P)
    doubled = view.update(algorithm="Lane-Riesenfeld (closed)", degree=3, level=1, round=0)["polygon"]
    np.testing.assert_allclose(doubled, np.repeat(P, 2, axis=0))


def test_subdivision_distance_falls_by_about_four_per_level():
    view = views.bspline_subdivision_view()
    d = [view.update(algorithm="Schaefer (clamped)", degree=3, level=L, round=3)["distance"] for L in range(5)]
    ratios = np.array(d[1:-1]) / np.array(d[2:])
    assert np.all(ratios > 2.5), ratios


def test_insertion_editor_inserts_into_the_editor_knot_vector():
    view = views.insertion_editor()
    knots, p, _ = _editor_knots(view)
    result = view.update(**{**view.values(), "u": 0.3, "times": 2})
    same_curve(P, knots, p, result["polygon"], result["knots"])
    assert len(result["polygon"]) == len(P) + 2


def _editor_knots(view):
    vals = view.values()
    from goldman_lib.widgets.knot_editor import knots_from_values
    names = sorted((k for k in vals if k.startswith("k") and k[1:].isdigit()), key=lambda k: int(k[1:]))
    knots = knots_from_values([vals[k] for k in names], vals["degree"], len(P), vals["preset"])
    return knots, vals["degree"], None


@pytest.mark.parametrize("method", ["Bezier pieces (28.3.5)", "subdivision (28.4.4)"])
@pytest.mark.parametrize("shift", [-1.2, 0.0, 0.7])
def test_render_view_draws_near_the_curve_and_marks_true_intersections(method, shift):
    result = views.render_view().update(method=method, digits=3, shift=shift)
    dense = BSpline(T, P, D)(np.linspace(0, 1, 3001))
    gap = np.sqrt(((result["polyline"][:, None] - dense[None]) ** 2).sum(-1)).min(1).max()
    assert gap < 5e-3
    q_ctrl, q_knots, q_deg = views.DEFAULT_SECOND
    other = BSpline(q_knots, q_ctrl + [0, shift], q_deg)
    params = result["params"]
    np.testing.assert_allclose(BSpline(T, P, D)(params[:, 0]), other(params[:, 1]), atol=1e-8)
    np.testing.assert_allclose(result["points"], other(params[:, 1]), atol=1e-8)
    # count sign changes of the vertical gap between the curves where both are graphs over x (here: all of them)
    x = np.linspace(1e-6, 6.8 - 1e-6, 6000)      # the x range of the first curve, inside the second one
    ua = np.interp(x, dense[:, 0], np.linspace(0, 1, 3001))
    ob = other(np.linspace(0, 1, 3001))
    yb = np.interp(x, ob[:, 0], ob[:, 1])
    diff = BSpline(T, P, D)(ua)[:, 1] - yb
    assert len(result["points"]) == int(np.count_nonzero(np.sign(diff[1:]) != np.sign(diff[:-1])))


def test_figures_carry_the_library_blossom_labels():
    """Boehm, Oslo and Schaefer figures write the blossom labels from the library beside the points."""
    from goldman_lib import bspline
    boehm = views.boehm_view()
    r = boehm.set_values(u=0.4, times=1)
    labels = bspline.control_point_labels(r["knots"], views.DEFAULT_DEGREE)
    assert r["new_labels"] == [labels[i] for i in range(2, 5)] and len(r["replaced_labels"]) == 2
    texts = [t.get_text() for t in boehm.figure.axes[0].texts]
    assert "b(0.25, 0.4, 0.5)" in texts and "b(0, 0.25, 0.5)" in texts
    oslo = views.oslo_view()
    r = oslo.set_values(count=4, step=3)
    assert r["labels"][-1] == [tuple(r["label"].tolist())]
    texts = [t.get_text() for t in oslo.figure.axes[0].texts]
    assert "b(" + ", ".join(f"{x:.3g}" for x in r["label"]) + ")" in texts
    sub = views.bspline_subdivision_view()
    r = sub.set_values(algorithm="Schaefer (clamped)", degree=3, level=1, round=2)
    want = ki.schaefer_labels(bspline.clamped_knots(len(views.DEFAULT_POLYGON), 3), 3, 2)
    assert r["labels"] == want and len(sub.figure.axes[0].texts) == len(want)
    # Lane-Riesenfeld's rounds are lower-degree splines: no labels; many points: no labels drawn
    assert sub.set_values(algorithm="Lane-Riesenfeld (uniform)")["labels"] == []
    sub.set_values(algorithm="Schaefer (clamped)", level=3)
    assert len(sub.figure.axes[0].texts) == 0

"""The knot-vector editor (shared by chapters 27 and 28): the rule never produces an invalid knot
vector for any slider values, the push rule acts on the sliders, the degree picker keeps the knot
count consistent, and the three views draw what scipy / geomdl compute for the knots they show."""

import matplotlib
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.interpolate import BSpline, bisplev

from goldman_lib import bspline
from goldman_lib.widgets import knot_editor as ke
from sweeps import sweep_values

matplotlib.use("Agg")

FAST = settings(max_examples=80, deadline=None, derandomize=True)
values = st.lists(st.floats(-2, 3, allow_nan=False), min_size=0, max_size=12)


@FAST
@given(values, st.integers(0, 6), st.integers(2, 12), st.sampled_from(ke.PRESETS))
def test_rule_always_gives_a_valid_knot_vector(vals, degree, n_ctrl, preset):
    knots = ke.knots_from_values(vals, degree, n_ctrl, preset)
    p = min(degree, n_ctrl - 1)
    bspline.check_knots(knots, p, n_ctrl)                 # raises if any rule is broken
    assert np.all(np.diff(knots) >= 0)
    assert (knots[p], knots[n_ctrl]) == (0.0, 1.0)       # the domain never moves
    inner = ke.interior_values(knots, p)
    assert np.all((inner > 0) & (inner < 1))
    if inner.size:
        assert np.unique(inner, return_counts=True)[1].max() <= max(p, 1)


@FAST
@given(values, st.integers(1, 5), st.integers(3, 10))
def test_legal_sliders_are_left_alone(vals, degree, n_ctrl):
    """Values the rule produced are a fixed point of the rule (the sliders don't jump)."""
    knots = ke.knots_from_values(vals, degree, n_ctrl, "custom")
    inner = ke.interior_values(knots, min(degree, n_ctrl - 1))
    again = ke.knots_from_values(inner, degree, n_ctrl, "custom")
    np.testing.assert_array_equal(again, knots)


@FAST
@given(st.lists(st.floats(0, 1), min_size=1, max_size=8), st.integers(1, 4), st.data())
def test_push_keeps_the_moved_knot_and_never_decreases(vals, degree, data):
    i = data.draw(st.integers(0, len(vals) - 1))
    pushed = ke.push_knots(vals, i, degree)
    assert np.all(np.diff(pushed) >= 0)
    cap = max(degree, 1)
    if len(pushed) > cap:
        assert np.all(pushed[cap:] > pushed[:-cap])
    target = min(max(vals[i], ke.GAP), 1 - ke.GAP)
    # the moved knot stays where it was dragged unless the others cannot fit beside it
    need_left = ke.GAP + (i // cap) * ke.GAP
    need_right = 1 - ke.GAP - ((len(vals) - 1 - i) // cap) * ke.GAP
    if need_left <= target <= need_right:
        assert pushed[i] == pytest.approx(target, abs=1e-12)


def test_rule_hand_examples():
    assert ke.knots_from_values([0.7, 0.2, 0.9], 2, 6, "custom").tolist() == [0, 0, 0, 0.7, 0.7, 0.9, 1, 1, 1]
    assert ke.knots_from_values([0.0, 1.0], 3, 6, "custom").tolist() == [0, 0, 0, 0, 0.01, 0.99, 1, 1, 1, 1]
    np.testing.assert_allclose(ke.knots_from_values([0.9], 2, 4, "clamped"), bspline.clamped_knots(4, 2))
    np.testing.assert_allclose(ke.knots_from_values([0.9], 2, 4, "uniform"), bspline.uniform_knots(4, 2))
    with pytest.raises(ValueError, match="preset must be one of"):
        ke.knots_from_values([], 2, 4, "open")


def test_editor_push_rule_moves_the_sliders():
    view = ke.bspline_curve_editor()                       # 7 points, cubic: 3 interior knots
    ed = view.editor
    assert [ed.controls[k].value for k in ("k1", "k2", "k3")] == pytest.approx([0.25, 0.5, 0.75])
    ed.controls["k1"].value = 0.8                          # dragged past both neighbours
    assert [ed.controls[k].value for k in ("k1", "k2", "k3")] == pytest.approx([0.8, 0.8, 0.8])
    np.testing.assert_allclose(view.last_result["knots"], [0, 0, 0, 0, 0.8, 0.8, 0.8, 1, 1, 1, 1])
    ed.controls["k3"].value = 0.3                          # dragged back down past both
    assert [ed.controls[k].value for k in ("k1", "k2", "k3")] == pytest.approx([0.3, 0.3, 0.3])
    assert "pushes the neighbour" in ed.rule.value


def test_degree_picker_keeps_the_knot_count_and_hides_sliders():
    view = ke.bspline_curve_editor()
    ed = view.editor
    for degree in (1, 2, 3, 4, 5):
        ed.controls["degree"].value = degree
        knots = view.last_result["knots"]
        assert len(knots) == 7 + degree + 1
        shown = [k for k in ed.knot_names if ed.controls[k].layout.display != "none"]
        assert len(shown) == 7 - degree - 1
        assert view.last_error is None


def test_presets_set_and_lock_the_sliders():
    view = ke.bspline_curve_editor()
    ed = view.editor
    ed.controls["k2"].value = 0.9
    ed.controls["preset"].value = "uniform"
    np.testing.assert_allclose(view.last_result["knots"], bspline.uniform_knots(7, 3))
    assert all(ed.controls[k].disabled for k in ed.knot_names)
    ed.controls["preset"].value = "clamped"
    np.testing.assert_allclose(view.last_result["knots"], bspline.clamped_knots(7, 3))
    ed.controls["preset"].value = "custom"
    assert not ed.controls["k1"].disabled


def test_curve_editor_draws_scipy_curve_and_basis():
    view = ke.bspline_curve_editor()
    for vals in sweep_values(view)[:40]:
        r = view.update(**vals)
        knots, p = r["knots"], len(r["knots"]) - 8
        u = np.linspace(0, 1, len(r["curve"]))
        ctrl = np.array([[vals[f"x{k}"], vals[f"y{k}"]] for k in range(len(ke.DEFAULT_POLYGON))])
        np.testing.assert_allclose(r["polygon"], ctrl)
        np.testing.assert_allclose(r["curve"], BSpline(knots, ctrl, p)(u), atol=1e-12)
        np.testing.assert_allclose(r["basis"], BSpline.design_matrix(u, knots, p).toarray(), atol=1e-12)
    fig = view.figure
    line = fig.axes[0].lines[1]
    np.testing.assert_allclose(np.c_[line.get_xdata(), line.get_ydata()], r["curve"])


def test_nurbs_editor_starts_as_the_circle_and_matches_geomdl():
    from geomdl import NURBS

    view = ke.nurbs_curve_editor()
    r = view.last_result
    np.testing.assert_allclose(np.hypot(r["curve"][:, 0], r["curve"][:, 1]), 1.0, atol=1e-12)
    np.testing.assert_allclose(r["basis"].sum(-1), 1.0, atol=1e-12)
    r = view.set_values(w1=3.0, w4=0.5)
    crv = NURBS.Curve()
    crv.degree = 2
    crv.ctrlptsw = [list(np.r_[q * w, w]) for q, w in zip(r["polygon"], r["weights"])]
    crv.knotvector = list(r["knots"])
    u = np.linspace(0, 1, len(r["curve"]))
    np.testing.assert_allclose(r["curve"], np.array(crv.evaluate_list(list(u))), atol=1e-12)


def test_curve_editors_control_points_are_dragged(hooks):
    view = ke.bspline_curve_editor()
    ctrl = ke.DEFAULT_POLYGON.copy()
    hooks["press_at"](view.drag, *ctrl[2])
    target = np.round(ctrl[2] + [-0.4, 0.3], 1)
    hooks["move_to"](view.drag, *target)
    hooks["release"](view.drag)
    assert (view.values()["x2"], view.values()["y2"]) == tuple(target)
    ctrl[2] = target
    r = view.last_result
    np.testing.assert_allclose(r["curve"], BSpline(r["knots"], ctrl, 3)(np.linspace(0, 1, len(r["curve"]))), atol=1e-12)
    np.testing.assert_allclose(np.column_stack(view.ax.lines[0].get_data()), ctrl)
    np.testing.assert_allclose(np.column_stack(view.ax.lines[1].get_data()), r["curve"])

    from geomdl import NURBS

    view = ke.nurbs_curve_editor()
    P = np.array(view.last_result["polygon"])
    hooks["press_at"](view.drag, *P[1])             # the circle's corner (1, 1): pull it out, the arc bulges
    hooks["move_to"](view.drag, 1.4, 1.4)
    hooks["release"](view.drag)
    r = view.last_result
    assert (view.values()["x1"], view.values()["y1"]) == (1.4, 1.4)
    P[1] = (1.4, 1.4)
    np.testing.assert_allclose(r["polygon"], P)
    crv = NURBS.Curve()
    crv.degree = 2
    crv.ctrlptsw = [list(np.r_[q * w, w]) for q, w in zip(r["polygon"], r["weights"])]
    crv.knotvector = list(r["knots"])
    u = np.linspace(0, 1, len(r["curve"]))
    np.testing.assert_allclose(r["curve"], np.array(crv.evaluate_list(list(u))), atol=1e-12)
    assert np.hypot(*r["curve"].T).max() > 1.05


def test_surface_editor_draws_bisplev_surface():
    view = ke.bspline_surface_editor()
    for vals in sweep_values(view)[:12]:
        r = view.update(**vals)
        tu, tv = r["knots_u"], r["knots_v"]
        pu, pv = len(tu) - 7, len(tv) - 7
        g = np.linspace(0, 1, r["surface"].shape[0])
        ref = np.stack([bisplev(g, g, (tu, tv, ke.DEFAULT_NET[:, :, c].ravel(), pu, pv)) for c in range(3)], -1)
        np.testing.assert_allclose(r["surface"], ref, atol=1e-12)
        np.testing.assert_allclose(view.scene.data("surface")["positions"], ref.reshape(-1, 3), atol=1e-12)
    assert view.static_png().startswith(b"\x89PNG")


def test_editor_argument_errors():
    with pytest.raises(ValueError, match="preset must be one of"):
        ke.knot_vector_editor(5, 2, preset="open")
    with pytest.raises(ValueError, match="weights must hold 5 positive"):
        ke.knot_vector_editor(5, 2, weights=[1, 1, 0, 1, 1])
    ed = ke.knot_vector_editor(5, 2, prefix="u_")
    assert "u_degree" in ed.controls and ed.read({"u_degree": 1})[0].size == 7

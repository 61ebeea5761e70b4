"""Chapter 24 widgets: every callback swept over its slider ranges (corners included) draws
finite geometry that agrees with the library, and never lets an exception escape."""

import numpy as np
import pytest

from goldman_lib import bezier
from goldman_lib.views import bezier as views

def test_explorer_draws_the_de_casteljau_point_of_the_slider_polygon():
    view = views.de_casteljau_explorer()
    result = view.set_values(t=0.5, x0=0, y0=0, x1=0, y1=2, x2=2, y2=2, x3=2, y3=0)
    # closed form for this cubic at t = 1/2: (P0 + 3P1 + 3P2 + P3) / 8 = (1, 1.5)
    np.testing.assert_allclose(result["point"], [1.0, 1.5])
    np.testing.assert_allclose(result["levels"][0], [[0, 1], [1, 2], [2, 1]])


def test_elevation_keeps_the_curve_and_closes_in_on_it():
    view = views.degree_elevation_view()
    gaps = [view.set_values(times=k)["gap"] for k in (0, 4, 12)]
    assert gaps[0] > gaps[1] > gaps[2]
    elevated = view.set_values(times=3)["polygon"]
    t = np.linspace(0, 1, 11)
    np.testing.assert_allclose(bezier.de_casteljau(elevated, t), bezier.de_casteljau(views.DEFAULT_CUBIC, t), atol=1e-12)


def test_explorer_control_point_follows_the_mouse_and_the_sliders_follow(hooks):
    view = views.de_casteljau_explorer()
    before = view.last_result["curve"].copy()
    hooks["press_at"](view.drag, 1.0, 2.5)          # on P1
    hooks["move_to"](view.drag, 1.5, 3.0)
    hooks["move_to"](view.drag, 2.04, 3.51)
    hooks["release"](view.drag)
    assert view.values()["x1"] == 2.0 and view.values()["y1"] == 3.5   # snapped to the 0.1 steps
    pts = np.array([[0, 0], [2.0, 3.5], [3, 2.5], [4, 0.5]])
    np.testing.assert_allclose(view.last_result["polygon"], pts)
    t = np.linspace(0, 1, 160)
    np.testing.assert_allclose(view.last_result["curve"], bezier.de_casteljau(pts, t), atol=1e-12)
    assert np.abs(view.last_result["curve"] - before).max() > 0.3
    np.testing.assert_allclose(np.column_stack(view.figure.axes[0].lines[1].get_data()), view.last_result["curve"])


def test_elevation_view_drags_the_original_points(hooks):
    view = views.degree_elevation_view(times=3)
    hooks["press_at"](view.drag, 3.0, 2.5)          # on P2
    hooks["move_to"](view.drag, 2.5, 1.5)
    hooks["release"](view.drag)
    assert (view.values()["x2"], view.values()["y2"]) == (2.5, 1.5)
    P = np.array([[0, 0], [1, 2.5], [2.5, 1.5], [4, 0.5]])
    np.testing.assert_allclose(view.last_result["original"], P)
    np.testing.assert_allclose(view.last_result["polygon"], bezier.elevate_degree(P, 3), atol=1e-12)
    t = np.linspace(0, 1, 400)
    np.testing.assert_allclose(view.last_result["curve"], bezier.de_casteljau(P, t), atol=1e-12)


def test_bernstein_view_values_sum_to_one():
    view = views.bernstein_view()
    for n in (0, 1, 5, 12):
        values = view.update(n=n, t=0.3)["values"]
        assert values.shape == (n + 1,) and values.sum() == pytest.approx(1.0)


def test_patch_editor_moves_the_net_and_updates_geometry_in_place():
    view = views.patch_editor()
    attr = view.scene._items["patch"]["geometry"].attributes["position"]
    before = np.array(attr.array)
    result = view.set_values(z11=-2.0)
    assert result["net"][1, 1, 2] == -2.0
    assert view.scene._items["patch"]["geometry"].attributes["position"] is attr
    assert not np.allclose(before, attr.array)
    # the drawn surface is the library's patch of the drawn net, corner to corner
    np.testing.assert_allclose(result["surface"][0, 0], result["net"][0, 0])
    np.testing.assert_allclose(result["surface"][-1, -1], result["net"][-1, -1])


def test_factories_reject_bad_input_naming_the_parameter():
    with pytest.raises(ValueError, match="ctrl must hold 2-dimensional points"):
        views.de_casteljau_explorer(ctrl=np.zeros((4, 3)))
    with pytest.raises(ValueError, match="ctrl must be at least a biquadratic net"):
        views.patch_editor(ctrl=np.zeros((2, 2, 3)))
    with pytest.raises(TypeError, match="max_times must be an integer"):
        views.degree_elevation_view(max_times=2.5)


def test_interpolation_vs_approximation_draws_both_curves_from_the_library():
    import matplotlib.pyplot as plt

    from goldman_lib import bezier
    from goldman_lib.views import bezier as views

    pts = np.array([[0, 0], [1, 2.5], [3, 2.5], [4, 0.5]])
    fig, ax = plt.subplots()
    interp, bez = views.plot_interpolation_vs_approximation(pts, ax, samples=31)
    x, y = interp.get_data()
    assert np.allclose(np.c_[x, y][[0, 10, 20, 30]], pts)             # through every point at i/3
    assert np.allclose(np.c_[bez.get_data()], bezier.de_casteljau(pts, np.linspace(0, 1, 31)))
    plt.close(fig)

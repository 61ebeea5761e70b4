"""Chapter 27 views: the de Boor explorer and the local-control view draw what scipy computes."""

import matplotlib
import numpy as np
from scipy.interpolate import BSpline

from goldman_lib import bspline
from goldman_lib.views import bspline as views
from sweeps import sweep_values

matplotlib.use("Agg")


def test_de_boor_explorer_draws_the_scipy_curve_and_point():
    view = views.de_boor_explorer()
    ctrl = views.DEFAULT_POLYGON
    for vals in sweep_values(view, n=5):
        r = view.update(**vals)
        ctrl = np.array([[vals[f"x{k}"], vals[f"y{k}"]] for k in range(len(views.DEFAULT_POLYGON))])
        p = vals["degree"]
        knots = np.r_[np.zeros(p), np.linspace(0, 1, len(ctrl) - p + 1), np.ones(p)]   # clamped, even
        np.testing.assert_allclose(r["knots"], knots, atol=1e-15)
        s = BSpline(knots, ctrl, p)
        np.testing.assert_allclose(r["curve"], s(np.linspace(0, 1, len(r["curve"]))), atol=1e-12)
        np.testing.assert_allclose(r["point"], s(vals["u"]), atol=1e-12)
        k = r["span"]
        assert knots[k] <= vals["u"] <= knots[k + 1] and len(r["levels"]) == p + 1
        np.testing.assert_allclose(r["levels"][0], ctrl[k - p:k + 1])


def test_de_boor_explorer_control_points_are_dragged(hooks):
    view = views.de_boor_explorer()
    ctrl = views.DEFAULT_POLYGON.copy()
    k = 3
    hooks["press_at"](view.drag, *ctrl[k])
    target = np.round(ctrl[k] + [0.3, -0.6], 1)
    hooks["move_to"](view.drag, *target)
    hooks["release"](view.drag)
    assert (view.values()[f"x{k}"], view.values()[f"y{k}"]) == tuple(target)
    ctrl[k] = target
    r = view.last_result
    knots = bspline.clamped_knots(len(ctrl), 3)
    np.testing.assert_allclose(r["polygon"], ctrl)
    np.testing.assert_allclose(r["curve"], BSpline(knots, ctrl, 3)(np.linspace(0, 1, 240)), atol=1e-12)
    np.testing.assert_allclose(np.column_stack(view.ax.lines[0].get_data()), ctrl)   # the drawn polygon
    np.testing.assert_allclose(np.column_stack(view.ax.lines[1].get_data()), r["curve"])


def test_local_control_changes_only_the_support():
    view = views.local_control_view()
    for vals in sweep_values(view, n=4):
        r = view.update(**vals)
        assert r["change_outside"] < 1e-12
        p, i = vals["degree"], vals["index"]
        knots = bspline.clamped_knots(len(views.LONG_POLYGON), p)
        # the support from the definition, not from the code under test
        lo, hi = max(knots[i], knots[p]), min(knots[i + p + 1], knots[-p - 1])
        np.testing.assert_allclose(r["interval"], [lo, hi])


def test_static_plots():
    ctrl = views.DEFAULT_POLYGON
    knots = bspline.clamped_knots(7, 3)
    line = views.plot_bspline_curve(ctrl, knots, 3)
    xy = np.c_[line.get_xdata(), line.get_ydata()]
    np.testing.assert_allclose(xy, BSpline(knots, ctrl, 3)(np.linspace(0, 1, len(xy))), atol=1e-12)
    lines, pt = views.plot_de_boor(ctrl, knots, 3, 0.3)
    assert len(lines) == 3
    np.testing.assert_allclose(pt.get_xydata()[0], BSpline(knots, ctrl, 3)(0.3), atol=1e-12)
    import matplotlib.pyplot as plt
    plt.close("all")


def test_global_pyramid_figure_labels_come_from_the_library():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from goldman_lib import bspline
    from goldman_lib.views import bspline as views

    knots = bspline.clamped_knots(7, 3)
    ax = views.plot_global_pyramid(knots, 3, u=0.4)
    texts = [t.get_text() for t in ax.texts]
    assert "$P_{3}$\n(0.25, 0.5, 0.75)" in texts                 # a base label: t_4, t_5, t_6
    assert "(u, 0.25, 0.5)" in texts and "0.75−u" in texts and "u−0.25" in texts
    assert sum("piece on" in t for t in texts) == 4               # one apex per non-empty span
    plt.close(ax.figure)


def test_nurbs_surface_figure_draws_the_sphere_and_its_net():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from goldman_lib import bspline
    from goldman_lib.views import bspline as views

    ctrl, w, tu, tv, p, q = bspline.nurbs_sphere()
    ax = views.plot_nurbs_surface(ctrl, w, tu, tv, p, q, resolution=9)
    assert len(ax.lines) == ctrl.shape[0] + ctrl.shape[1]        # the rows and columns of the net
    assert len(ax.collections) == 2                               # the surface and the control points
    plt.close(ax.figure)

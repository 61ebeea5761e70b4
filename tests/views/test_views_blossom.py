"""Chapter 26 widgets: the blossom diagram and the interval view, swept over their sliders, draw
finite geometry, and what they draw matches closed forms and de Casteljau evaluation."""

import matplotlib
import numpy as np
import pytest

from goldman_lib import bezier
from goldman_lib.views import blossom as views
from goldman_lib.views.bezier import DEFAULT_CUBIC

matplotlib.use("Agg")

def test_blossom_view_apex_on_the_diagonal_is_the_curve_point():
    view = views.blossom_view()
    r = view.set_values(u1=0.3, u2=0.3, u3=0.3)
    np.testing.assert_allclose(r["point"], bezier.de_casteljau(DEFAULT_CUBIC, 0.3), atol=1e-12)
    assert "on the curve" in r["status"]


def test_blossom_view_apex_is_symmetric_and_the_control_points_appear():
    view = views.blossom_view()
    p1 = view.set_values(u1=0.1, u2=0.6, u3=1.2)["point"].copy()
    p2 = view.set_values(u1=1.2, u2=0.1, u3=0.6)["point"]
    np.testing.assert_allclose(p1, p2, atol=1e-12)
    # p(0, 0, 1) is P1: arguments (0, 0, 1) end the pyramid at the control point (closed form)
    np.testing.assert_allclose(view.set_values(u1=0.0, u2=0.0, u3=1.0)["point"], DEFAULT_CUBIC[1], atol=1e-12)
    np.testing.assert_allclose(view.set_values(u1=1.0, u2=0.0, u3=1.0)["point"], DEFAULT_CUBIC[2], atol=1e-12)


def test_blossom_view_control_points_are_dragged_and_the_pyramid_follows(hooks):
    view = views.blossom_view()
    hooks["press_at"](view.drag, 4.0, 0.5)          # on P3
    hooks["move_to"](view.drag, 3.5, 1.5)
    hooks["release"](view.drag)
    assert (view.values()["x3"], view.values()["y3"]) == (3.5, 1.5)
    P = DEFAULT_CUBIC.copy()
    P[3] = (3.5, 1.5)
    r = view.last_result
    np.testing.assert_allclose(r["curve"], bezier.de_casteljau(P, np.linspace(0, 1, 200)), atol=1e-12)
    r = view.set_values(u1=0.4, u2=0.4, u3=0.4)
    np.testing.assert_allclose(r["point"], bezier.de_casteljau(P, 0.4), atol=1e-12)
    np.testing.assert_allclose(np.column_stack(view.ax.lines[0].get_data()), P)


def test_blossom_labels_follow_goldman():
    assert views.blossom_label(3, 0, 0) == "000"
    assert views.blossom_label(3, 0, 3) == "111"
    assert views.blossom_label(3, 2, 0) == "u₁u₂0"
    assert views.blossom_label(2, 2, 0, names=["s", "t"]) == "st"


def test_interval_view_piece_is_the_curve_on_the_interval():
    view = views.interval_view()
    for a, b in ((0.0, 0.5), (0.25, 0.75), (-0.5, 1.5), (1.0, 0.0)):
        r = view.set_values(a=a, b=b)
        s = np.linspace(0, 1, 160)
        np.testing.assert_allclose(r["piece"], bezier.de_casteljau(DEFAULT_CUBIC, a + (b - a) * s), atol=1e-12)
    # [0, 1/2] is the left half of subdivision
    r = view.set_values(a=0.0, b=0.5)
    np.testing.assert_allclose(r["polygon"], bezier.subdivide(DEFAULT_CUBIC, 0.5)[0], atol=1e-12)


def test_blossom_view_needs_one_argument_per_degree():
    with pytest.raises(ValueError, match="one argument per degree"):
        views.blossom_view(args=(0.5, 0.5))

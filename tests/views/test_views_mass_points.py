"""Chapter 14 widgets: the lever view draws the centre of mass (or the vector when the masses
cancel) where the law of the lever puts it, follows mouse drags, and the pseudoperspective view
draws perspective images and pseudodepths that agree with closed forms, keeps depth order and
lines, and turns degenerate positions into messages."""


import matplotlib
import numpy as np
import pytest

from goldman_lib.views import mass_points as views

matplotlib.use("Agg")


def test_lever_centre_by_hand():
    view = views.lever_view()
    # masses 3 at (-2, 0) and 1 at (2, 2): centre (3 (-2, 0) + (2, 2)) / 4 = (-1, 0.5), mass 4
    r = view.last_result
    assert r["center"].tolist() == [-1.0, 0.5] and r["vector"] is None
    assert r["sum"].tolist() == [-4.0, 2.0, 4.0]
    assert "centre of mass (-1.00, 0.50)" in r["status"] and "with mass 4" in r["status"]
    # the drawn centre marker is at the centre
    centre = [ln for ln in view.figure.axes[0].lines if ln.get_color() == "black"][0]
    assert list(centre.get_xdata()) == [-1.0] and list(centre.get_ydata()) == [0.5]


def test_lever_three_points_and_a_negative_mass():
    view = views.lever_view()
    # 2 (0, 0) - 1 (1, 1) + 1 (2, -2) = (1, -3), total mass 2: centre (0.5, -1.5)
    r = view.set_values(x0=0.0, y0=0.0, m0=2.0, x1=1.0, y1=1.0, m1=-1.0, x2=2.0, y2=-2.0, m2=1.0)
    np.testing.assert_allclose(r["center"], [0.5, -1.5], atol=1e-12)
    # a negative total mass is still a point
    r = view.set_values(x0=0.0, y0=0.0, m0=1.0, x1=2.0, y1=0.0, m1=-2.0, m2=0.0)
    np.testing.assert_allclose(r["center"], [4.0, 0.0], atol=1e-12)          # (0 - 4) / (-1)
    assert "negative total mass" in r["status"]


def test_lever_masses_that_cancel_give_a_vector_message():
    view = views.lever_view()
    r = view.set_values(x0=1.0, y0=0.0, m0=2.0, x1=0.0, y1=1.0, m1=-2.0, m2=0.0)
    assert r["center"] is None and r["vector"].tolist() == [2.0, -2.0]       # 2 (1, 0) - 2 (0, 1)
    assert "VECTOR" in r["status"] and "no centre of mass" in r["status"]
    r = view.set_values(x0=1.0, y0=1.0, m0=2.0, x1=1.0, y1=1.0, m1=-2.0, m2=0.0)
    assert "zero vector" in r["status"] and view.last_error is None


def test_lever_points_follow_the_mouse(hooks):
    view = views.lever_view()
    hooks["press_at"](view.drag, 2.0, 2.0)           # P1
    hooks["move_to"](view.drag, 3.0, -1.0)
    hooks["release"](view.drag)
    assert (view.values()["x1"], view.values()["y1"]) == (3.0, -1.0)
    # 3 (-2, 0) + (3, -1) = (-3, -1), mass 4
    np.testing.assert_allclose(view.last_result["center"], [-0.75, -0.25], atol=1e-12)


def test_pseudoperspective_view_default_scene():
    view = views.pseudoperspective_view()
    r = view.last_result
    # eye (0, 1, 0), plane z = 2: c = 2.  A = (0, 2, 4): s = 4, delta = 1 - 2/4 = 0.5, image height
    # 1 + (2/4)(2 - 1) = 1.5; B = (0, 3, 8): s = 8, delta = 0.75, height 1 + (2/8) 2 = 1.5 (same line of sight)
    np.testing.assert_allclose(r["labelled"]["A"], [4.0, 0.5, 1.5], atol=1e-12)
    np.testing.assert_allclose(r["labelled"]["B"], [8.0, 0.75, 1.5], atol=1e-12)
    np.testing.assert_allclose(r["labelled"]["C"], [11.0, 1 - 2 / 11, 1 + (2 / 11) * (0.5 - 1)], atol=1e-12)
    assert "A and B are on one line of sight" in r["status"] and ": the same" in r["status"]
    # perspective images lie on the plane z = 2; post A's image from height 1 + (2/4)(0 - 1) = 0.5 to 1.5
    for img in r["images"].values():
        np.testing.assert_allclose(img[:, 0], 2.0, atol=1e-12)
    np.testing.assert_allclose(r["images"]["post A"][[0, -1], 1], [0.5, 1.5], atol=1e-12)


def test_pseudoperspective_keeps_lines_and_depth_order():
    view = views.pseudoperspective_view()
    for eye_y, eye_z, plane_z in ((1.0, 0.0, 2.0), (3.0, -2.0, 1.0), (-1.0, 2.0, 3.5)):
        r = view.set_values(eye_y=eye_y, eye_z=eye_z, plane_z=plane_z)
        road = r["pseudo"]["road C"]
        # collinear: every (delta, height) pair on the line through the first and last
        d = road[-1] - road[0]
        cross = (road[:, 0] - road[0, 0]) * d[1] - (road[:, 1] - road[0, 1]) * d[0]
        assert np.abs(cross).max() < 1e-12
        # the road's samples go away from the eye: delta increases along it
        assert np.all(np.diff(road[:, 0]) > 0)
        lab = r["labelled"]
        depths = [lab[k][0] for k in lab]
        deltas = [lab[k][1] for k in lab]
        assert np.argsort(depths).tolist() == np.argsort(deltas).tolist()


def test_pseudoperspective_degenerate_positions_are_messages():
    view = views.pseudoperspective_view()
    r = view.set_values(eye_y=1.0, eye_z=3.0, plane_z=3.0)
    assert "lies on the projection plane" in r["status"] and view.last_error is None
    r = view.set_values(eye_y=1.0, eye_z=3.0, plane_z=1.0)
    assert "behind the eye" in r["status"] and view.last_error is None
    r = view.set_values(eye_y=1.0, eye_z=5.0, plane_z=7.0)
    assert "A: behind the eye" in r["status"] and "post A" in r["status"] and view.last_error is None
    assert r["images"]["post A"].shape == (0, 2)



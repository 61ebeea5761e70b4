"""The chapter 12-13 views draw what goldman_lib.transforms computes, and degenerate slider positions
(a zero axis or normal, an eye on the plane) give a message, not an exception."""

import numpy as np

from goldman_lib import transforms as tf
from goldman_lib.views import transforms as tv


def test_letter_f_is_three_boxes_without_mirror_symmetry():
    V, T, E = tv.letter_f()
    assert V.shape == (24, 3) and T.max() == 23 and E.max() == 23
    # the mirror image in x = 0.4 (the F's middle) is not the F itself: the arms point the other way
    mirrored = tf.reflect(V, [0.4, 0, 0], [1, 0, 0])
    assert not np.allclose(np.sort(mirrored, axis=0), np.sort(V, axis=0))


def test_axis_rotation_view_draws_the_library_rotation_and_the_axis():
    view = tv.axis_rotation_view()
    r = view.set_values(ax=0.0, ay=0.0, az=1.0, angle=90.0, px=1.0, py=0.0, pz=0.0)
    # 90 degrees about the vertical line through (1, 0, 0): (x, y, z) -> (1 - y, x - 1, z), by hand
    V = tv.F_VERTICES
    assert np.allclose(r["image"], np.c_[1 - V[:, 1], V[:, 0] - 1, V[:, 2]])
    assert np.allclose(r["axis"][:, :2], [[1, 0], [1, 0]])               # the axis is the vertical line
    assert np.allclose(r["path"][0], V[tv.TIP]) and np.allclose(r["path"][-1], r["image"][tv.TIP])
    assert "edge lengths kept to < 1e-12" in r["status"]
    r = view.set_values(ax=0.0, ay=0.0, az=0.0)
    assert view.last_error is None and r["status"].startswith("no rotation") and np.allclose(r["image"], V)


def test_mirror_view_reflects_and_reports_the_determinant():
    view = tv.mirror_view()
    r = view.set_values(qx=1.0, qy=0.0, qz=0.0, nx=2.0 / 2, ny=0.0, nz=0.0)
    V = tv.F_VERTICES
    assert np.allclose(r["image"], np.c_[2 - V[:, 0], V[:, 1:]])          # x -> 2 - x
    assert "det = -1" in r["status"]
    r = view.set_values(nx=0.0)
    assert view.last_error is None and r["status"].startswith("no mirror")


def test_scaling_view_uniform_and_nonuniform():
    view = tv.scaling_view()
    V = tv.F_VERTICES
    r = view.set_values(s=2.0, kind="uniform", cx=1.0, cy=0.0, cz=0.0)
    assert np.allclose(r["image"], [1, 0, 0] + 2 * (V - [1, 0, 0]))
    assert "ratio 8.000" in r["status"]
    r = view.set_values(s=2.0, kind="nonuniform", dx=0.0, dy=0.0, dz=-1.0, cx=0.0, cy=0.0, cz=0.0)
    assert np.allclose(r["image"], V * [1, 1, 2]) and "ratio 2.000" in r["status"]
    r = view.set_values(dz=0.0)
    assert view.last_error is None and r["status"].startswith("no scaling")


def test_projection_view_lands_on_the_plane_and_reports_the_eye_on_the_plane():
    view = tv.projection_view()
    r = view.set_values(kind="perspective", ex=0.0, ey=-4.0, ez=0.0, plane_y=-2.0, tilt=0.0)
    V = tv.F_VERTICES
    # eye (0, -4, 0), plane y = -2: the image is halfway along (P - E) scaled by 2 / (y + 4)
    t = 2.0 / (V[:, 1] + 4.0)
    assert np.allclose(r["image"], [0, -4, 0] + t[:, None] * (V - [0, -4, 0]))
    r = view.set_values(kind="orthogonal")
    assert np.allclose(r["image"], np.c_[V[:, 0], np.full(24, -2.0), V[:, 2]])
    r = view.set_values(kind="perspective", ey=-2.0)
    assert view.last_error is None and "eye must not lie on the plane" in r["status"]


def test_composition_view_applies_a_then_b_and_shows_the_product():
    view = tv.composition_view()
    r = view.set_values(first="translate by (t, 0, 0)", second="rotate about the x axis", t=1.0, angle=90.0)
    V = tv.F_VERTICES
    # (x, y, z) + (1, 0, 0), then 90 degrees about x: (x + 1, -z, y); translation along x commutes with it
    assert np.allclose(r["image"], np.c_[V[:, 0] + 1, -V[:, 2], V[:, 1]]) and "commute" in r["status"]
    r = view.set_values(first="scale by s along z about the origin", second="translate by (t, 0, 0)", s=2.0, t=0.5)
    assert np.allclose(r["image"], np.c_[V[:, 0] + 0.5, V[:, 1], 2 * V[:, 2]])
    assert np.allclose(r["matrix"][3], [0.5, 0, 0, 1]) and np.allclose(np.diag(r["matrix"]), [1, 1, 2, 1])
    r = view.set_values(first="translate by (t, 0, 0)", second="scale by s along z about the origin")
    assert "commute" in r["status"]
    r = view.set_values(first="translate by (t, 0, 0)", second="mirror in the plane x = m", t=1.0, m=1.0)
    # x -> x + 1 -> 2 - (x + 1) = 1 - x; the other order: x -> 2 - x -> 3 - x
    assert np.allclose(r["image"][:, 0], 1 - V[:, 0]) and np.allclose(r["other"][:, 0], 3 - V[:, 0])
    assert "A B" in view.children[1].children[0].children[2].value


def test_perspective_matrix_view_shows_the_homogeneous_coordinates():
    view = tv.perspective_matrix_view()
    r = view.set_values(ex=0.0, ey=-4.0, ez=0.0, plane_y=-2.0, tilt=0.0, corner=8)
    V = tv.F_VERTICES
    t = 2.0 / (V[:, 1] + 4.0)
    assert np.allclose(r["image"], [0, -4, 0] + t[:, None] * (V - [0, -4, 0]))
    assert np.allclose(r["corner"], [V[tv.FRONT[8]], r["image"][tv.FRONT[8]]])
    assert "to < 1e-9" in r["status"] and "[P 1] M = (" in r["status"]
    r = view.set_values(ey=-2.0)
    assert view.last_error is None and "eye must not lie on the plane" in r["status"]

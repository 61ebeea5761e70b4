"""Chapter 9-10 views draw what goldman_lib.vectors computes: the affine-combination view (points
and origin dragged with the mouse) and the determinant's parallelepiped."""

import numpy as np

from goldman_lib.views.vectors import affine_combination_view, determinant_view, parallelepiped_vertices


def test_affine_combination_stays_put_when_the_origin_moves():
    view = affine_combination_view()
    r = view.set_values(x0=0.0, y0=0.0, x1=4.0, y1=0.0, x2=0.0, y2=2.0, w0=0.5, w1=0.25, w2=0.25, ox=-3.0, oy=1.0)
    # by hand: 0.5 (0, 0) + 0.25 (4, 0) + 0.25 (0, 2) = (1, 0.5), from any origin
    assert np.allclose(r["from_origin"], [1.0, 0.5]) and np.allclose(r["from_zero"], [1.0, 0.5])
    assert r["kind"] == "point" and "affine combination" in r["status"]
    r = view.set_values(ox=2.0, oy=-2.0)
    assert np.allclose(r["from_origin"], [1.0, 0.5])


def test_a_non_affine_sum_moves_with_the_origin():
    view = affine_combination_view()
    r = view.set_values(x0=0.0, y0=0.0, x1=4.0, y1=0.0, x2=0.0, y2=2.0, w0=1.0, w1=1.0, w2=1.0, ox=1.0, oy=1.0)
    # by hand: O + (P0 - O) + (P1 - O) + (P2 - O) = (4, 2) - 2 (1, 1) = (2, 0); from (0, 0): (4, 2)
    assert np.allclose(r["from_origin"], [2.0, 0.0]) and np.allclose(r["from_zero"], [4.0, 2.0])
    assert r["kind"] == "undefined" and "not 1" in r["status"]
    r = view.set_values(w0=1.0, w1=-1.0, w2=0.0)
    assert r["kind"] == "vector" and "vector" in r["status"]
    # the picture holds what update returned
    ax = view.figure.axes[0]
    dots = [ln for ln in ax.lines if ln.get_label() == "Σ wᵢPᵢ from O"]
    assert np.allclose(np.ravel(dots[0].get_data()), r["from_origin"])


def test_points_and_origin_are_dragged_with_the_mouse(hooks):
    view = affine_combination_view()
    hooks["press_at"](view.drag, view.values()["ox"], view.values()["oy"])
    hooks["move_to"](view.drag, 1.5, -2.0)
    hooks["release"](view.drag)
    assert (view.values()["ox"], view.values()["oy"]) == (1.5, -2.0)
    x1, y1 = view.values()["x1"], view.values()["y1"]
    hooks["press_at"](view.drag, x1, y1)
    hooks["move_to"](view.drag, 3.0, 3.0)
    hooks["release"](view.drag)
    assert (view.values()["x1"], view.values()["y1"]) == (3.0, 3.0)
    assert np.allclose(view.last_result["from_origin"], view.last_result["from_zero"])   # default weights sum to 1


def test_determinant_view_shows_the_signed_volume():
    view = determinant_view()
    r = view.set_values(ux=1.0, uy=0.0, uz=0.0, vx=0.0, vy=2.0, vz=0.0, wx=0.5, wy=0.5, wz=1.5)
    assert np.isclose(r["det"], 3.0) and np.isclose(r["volume"], 3.0) and np.allclose(r["cross"], [0, 0, 2])
    assert np.isclose(r["terms"].sum(), 3.0) and "right-handed" in r["status"]
    r = view.set_values(wz=-1.5)
    assert np.isclose(r["det"], -3.0) and "left-handed" in r["status"]
    r = view.set_values(wx=1.0, wy=2.0, wz=0.0)      # w = u + v: flat
    assert np.isclose(r["det"], 0.0) and "coplanar" in r["status"]
    assert np.allclose(view_box(view), parallelepiped_vertices([1, 0, 0], [0, 2, 0], [1, 2, 0]))


def view_box(view):
    return view.last_result["vertices"]


def test_parallelepiped_corners():
    box = parallelepiped_vertices([1, 0, 0], [0, 2, 0], [0, 0, 3])
    assert box.shape == (8, 3) and box[7].tolist() == [1, 2, 3] and box[6].tolist() == [0, 2, 3]

"""Chapter-11 views draw what goldman_lib.vector_geometry computes: the foot of the perpendicular, the
closest points of two lines, the point of three planes, the volumes, the winding-number map of a
polygon (also when its points are dragged with the mouse) and slerp beside nlerp; degenerate
positions are reported in the status line, never raised."""

import inspect

import numpy as np
import pytest

from goldman_lib import vector_geometry as vg
from goldman_lib.views import vector_geometry as vgv


def test_point_plane_view_draws_the_foot_and_the_perpendicular():
    view = vgv.point_plane_view()
    # plane z = 0 (N = (0, 0, 0.5), not unit), Q = (1, -1, 1.5): foot (1, -1, 0), distance 1.5
    r = view.set_values(qx=1.0, qy=-1.0, qz=1.5, nx=0.0, ny=0.0, nz=0.5)
    assert np.allclose(r["foot"], [1, -1, 0]) and np.isclose(r["distance"], 1.5) and np.isclose(r["signed"], 1.5)
    assert np.isclose(r["dot"], 0.75)                       # (Q - P)·N before dividing by |N| = 0.5
    r = view.set_values(qx=0.5, qy=1.0, qz=-1.0, nx=0.3, ny=-0.4, nz=0.8)
    F = vg.foot_on_plane([0.5, 1.0, -1.0], [0, 0, 0], [0.3, -0.4, 0.8])
    assert np.allclose(r["foot"], F) and r["signed"] < 0 and "away from N" in r["status"]
    r = view.set_values(nx=0.0, ny=0.0, nz=0.0)
    assert "nonzero normal" in r["status"] and view.last_error is None


def _scene(view):
    """The VectorScene behind a three.js view (its renderer is the first displayed widget)."""
    for cell in inspect.unwrap(view.update).__closure__:
        obj = cell.cell_contents
        if hasattr(obj, "data") and hasattr(obj, "set_points"):
            return obj
    raise AssertionError("no scene in the view's closure")


def test_point_plane_scene_positions():
    view = vgv.point_plane_view()
    view.set_values(qx=1.0, qy=2.0, qz=2.0, nx=0.0, ny=0.0, nz=1.0)
    scene = _scene(view)
    assert np.allclose(scene.data("Q")["positions"], [[1, 2, 2]])
    assert np.allclose(scene.data("F")["positions"], [[1, 2, 0]])
    assert np.allclose(scene.data("perp")["positions"], [[1, 2, 2], [1, 2, 0]])
    assert np.allclose(scene.data("plane:fill")["positions"][:, 2], 0)     # the square lies in the plane


def test_skew_lines_view_closest_points_and_formula():
    view = vgv.skew_lines_view()
    # L1 = the x axis, L2 = (0, 0, 2) + t (0, 1, 0): A = origin, B = (0, 0, 2), distance 2
    r = view.set_values(d1x=1.0, d1y=0.0, d1z=0.0, p2x=0.0, p2y=0.0, p2z=2.0, d2x=0.0, d2y=1.0, d2z=0.0)
    assert np.allclose(r["A"], [0, 0, 0]) and np.allclose(r["B"], [0, 0, 2])
    assert np.isclose(r["distance"], 2) and np.isclose(r["formula"], 2) and "skew lines" in r["status"]
    scene = _scene(view)
    assert np.allclose(scene.data("AB")["positions"], [[0, 0, 0], [0, 0, 2]])
    # the lines (0,0,0) + s(1,1,0) and (1,0,0) + t(0,1,0) meet at (1, 1, 0)
    r = view.set_values(d1x=1.0, d1y=1.0, d1z=0.0, p2x=1.0, p2y=0.0, p2z=0.0, d2x=0.0, d2y=1.0, d2z=0.0)
    assert np.allclose(r["A"], [1, 1, 0]) and r["distance"] == 0 and "meet" in r["status"]
    r = view.set_values(d2x=0.5, d2y=0.5, d2z=0.0)              # parallel to d1
    assert "parallel" in r["status"] and np.isclose(r["formula"], np.sqrt(0.5)) and view.last_error is None
    r = view.set_values(d1x=0.0, d1y=0.0, d1z=0.0)
    assert "d1 = 0" in r["status"] and view.last_error is None


def test_three_planes_view_point_and_degenerate_positions():
    view = vgv.three_planes_view()
    N1, N2 = vgv.THREE_PLANE_NORMALS
    r = view.set_values(h1=1.0, h2=-0.5, h3=0.5, n3x=0.0, n3y=0.0, n3z=1.0)
    X = vg.intersect_three_planes(([1.0, 0, 0], N1), ([0, -0.5, 0], N2), ([0, 0, 0.5], [0, 0, 1.0]))
    assert np.allclose(r["X"], X) and np.isclose(r["X"][2], 0.5)
    scene = _scene(view)
    assert np.allclose(scene.data("X")["positions"], [X])
    for k, N in enumerate([N1, N2, np.array([0, 0, 1.0])]):
        corners = scene.data(f"plane{k + 1}:fill")["positions"]
        assert np.allclose((corners - X) @ N, 0, atol=1e-12)                 # every square lies in its plane
    assert np.isclose(vg.point_line_distance(X, r["line_point"], r["line_direction"]), 0, atol=1e-12)
    r = view.set_values(n3x=1.0, n3y=0.2, n3z=0.0)                          # plane 3 parallel to plane 1
    assert "planes 1 and 3 are parallel" in r["status"] and view.last_error is None
    r = view.set_values(n3x=0.5, n3y=0.6, n3z=0.15)                         # (N1 + N2) / 2: in the span of N1, N2
    assert "lie in one plane" in r["status"] and view.last_error is None
    r = view.set_values(n3x=0.0, n3y=0.0, n3z=0.0)
    assert "n3 = 0" in r["status"]


def test_volume_view():
    view = vgv.volume_view()
    r = view.set_values(ux=1.0, uy=0.0, uz=0.0, vx=0.0, vy=2.0, vz=0.0, wx=0.0, wy=0.0, wz=1.5)
    assert np.isclose(r["det"], 3) and np.isclose(r["parallelepiped"], 3) and np.isclose(r["tetrahedron"], 0.5)
    assert "right-handed" in r["status"]
    r = view.set_values(wz=-1.5)
    assert np.isclose(r["det"], -3) and "left-handed" in r["status"]
    r = view.set_values(wx=1.0, wy=2.0, wz=0.0)                             # w = u + v: coplanar
    assert r["parallelepiped"] == 0 and "coplanar" in r["status"]
    corners = _scene(view).data("box")["positions"]
    assert np.allclose(corners[-1], [2, 4, 0])                              # u + v + w


def test_inside_outside_map_is_the_winding_number_on_the_grid():
    view = vgv.inside_outside_view(grid=60)
    r = view.last_result
    xs = np.linspace(-3.5, 3.5, 60)
    grid = np.stack(np.meshgrid(xs, xs), axis=-1)
    assert np.array_equal(r["map"], vg.winding_number(vgv.STAR, grid))
    # the star's centre: wound twice, two crossings going up, outside by the even-odd rule
    r = view.set_values(qx=0.0, qy=0.0)
    assert r["winding"] == 2 and r["even_odd"] is False and r["signs"].tolist() == [1, 1]
    assert "winding number 2" in r["status"] and "disagree" in r["status"]
    image = view.ax.images[0].get_array()
    white = np.array([1.0, 1.0, 1.0, 1.0])
    inside = np.any(np.asarray(image) != white, axis=-1)
    assert np.array_equal(inside, r["map"] != 0)
    view.set_values(mode="differ")
    image = np.asarray(view.ax.images[0].get_array())
    differ = np.any(image != white, axis=-1)
    assert np.array_equal(differ, r["map"] == 2)                            # the central pentagon
    r = view.set_values(qx=0.0, qy=2.4)
    assert r["winding"] == 1 and r["even_odd"] is True and "disagree" not in r["status"]


def test_inside_outside_points_follow_the_mouse(hooks):
    view = vgv.inside_outside_view(grid=40)
    hooks["press_at"](view.drag, 0.2, 0.4)            # the query point's default position
    hooks["move_to"](view.drag, 3.0, -2.0)
    hooks["release"](view.drag)
    assert view.values()["qx"] == 3.0 and view.values()["qy"] == -2.0
    assert view.last_result["winding"] == 0 and "outside" in view.last_result["status"]
    hooks["press_at"](view.drag, 0.0, 3.0)            # vertex 0, the top of the star
    hooks["move_to"](view.drag, 0.0, 2.0)
    hooks["release"](view.drag)
    assert view.values()["y0"] == 2.0 and np.allclose(view.last_result["polygon"][0], [0, 2])


def test_inside_outside_degenerate_polygon_is_reported():
    view = vgv.inside_outside_view(grid=30)
    r = view.set_values(**{f"{a}{k}": 1.0 for k in range(5) for a in "xy"})
    assert isinstance(r["status"], str) and view.last_error is None


def test_slerp_view_dots_are_evenly_spaced_and_nlerp_is_not():
    view = vgv.slerp_view()
    r = view.set_values(a0=0.0, a1=120.0, t=0.25)
    assert np.isclose(r["slerp_angle"], 30) and not np.isclose(r["nlerp_angle"], 30)
    steps = np.degrees(np.diff(np.unwrap(np.arctan2(r["slerp_dots"][:, 1], r["slerp_dots"][:, 0]))))
    assert np.allclose(steps, 12)
    nsteps = np.diff(np.unwrap(np.arctan2(r["nlerp_dots"][:, 1], r["nlerp_dots"][:, 0])))
    assert nsteps.max() > 1.2 * nsteps.min()
    assert np.allclose(np.linalg.norm(r["slerp"]), 1) and np.linalg.norm(r["lerp"]) < 1
    r = view.set_values(a1=180.0)
    assert "opposite" in r["status"] and view.last_error is None



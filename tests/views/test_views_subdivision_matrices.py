"""Chapter 29 widgets: the fractal drawn is the attractor of the conjugated matrices at the slider
values (checked against the affine image of the barycentric attractor), the curve view converges
to the curve, and no slider position raises."""

import numpy as np
import pytest

from goldman_lib import subdivision_matrices as sm
from goldman_lib.views import subdivision_matrices as views


def test_fractal_is_the_affine_image_of_the_barycentric_attractor():
    view = views.fractal_editor()
    P = np.array([[0.0, 0.0], [2.0, 3.0], [4.0, 1.0]])
    result = view.set_values(middle=-0.4, levels=6, x0=0, y0=0, x1=2, y1=3, x2=4, y2=1)
    # an independent construction: barycentric rows of the identity mapped by L, R, then by P
    L = np.array([[1, 0, 0], [0.5, 0.5, 0], [0.7, -0.4, 0.7]])
    R = np.array([[0.7, -0.4, 0.7], [0, 0.5, 0.5], [0, 0, 1]])
    X = np.eye(3)[[0, 2]]
    for _ in range(6):
        X = np.matmul(X[None], np.stack([L, R])).reshape(-1, 3)  # block i is X @ M_i
    np.testing.assert_allclose(result["fractal"], X @ P, atol=1e-9)
    np.testing.assert_allclose(result["joint"], 0.7 * P[0] - 0.4 * P[1] + 0.7 * P[2])


def test_fractal_editor_at_one_half_draws_the_parabola_and_survives_collinear_points():
    view = views.fractal_editor()
    result = view.set_values(middle=0.5, levels=8, x0=0, y0=0, x1=2, y1=2, x2=4, y2=0)
    t = np.arange(256) / 256
    parabola = np.stack([4 * t, 4 * t * (1 - t)], -1)   # Bezier (0,0),(2,2),(4,0)
    np.testing.assert_allclose(result["fractal"][::2], parabola, atol=1e-12)
    flat = view.set_values(x1=2, y1=0)
    assert view.last_error is None and "collinear" in flat["status"] and np.allclose(flat["fractal"][:, 1], 0)


def test_fractal_editor_control_points_are_dragged(hooks):
    view = views.fractal_editor()
    before = view.last_result["fractal"].copy()
    hooks["press_at"](view.drag, 1.5, 2.5)          # on P1
    hooks["move_to"](view.drag, 2.0, 3.0)
    hooks["release"](view.drag)
    assert (view.values()["x1"], view.values()["y1"]) == (2.0, 3.0)
    P = np.array([[0.0, 0.0], [2.0, 3.0], [4.0, 0.0]])
    result = view.last_result
    np.testing.assert_allclose(result["polygon"], P)
    # the fractal is the affine image of the barycentric attractor: the same map moves it
    A = np.linalg.solve(np.c_[views.DEFAULT_TRIANGLE, np.ones(3)], np.c_[P, np.ones(3)])
    np.testing.assert_allclose(result["fractal"], (np.c_[before, np.ones(len(before))] @ A)[:, :2], atol=1e-9)
    np.testing.assert_allclose(np.column_stack(view.ax.lines[1].get_data()), result["fractal"])


def test_curve_view_converges():
    view = views.curve_attractor_view()
    for kind in ("bezier", "bspline"):
        flat = [view.update(kind=kind, levels=k)["flatness"] for k in (0, 2, 4, 6)]
        # pieces flatten by about 4x per level (the second difference halves twice)
        assert all(a > 3 * b for a, b in zip(flat, flat[1:])) and flat[-1] < 0.01
    np.testing.assert_allclose(view.update(kind="bspline", levels=3)["polygons"],
                               sm.curve_as_attractor(views.DEFAULT_CUBIC, 3, "bspline"))


def test_factories_reject_bad_arguments():
    with pytest.raises(ValueError, match="3 control points"):
        views.fractal_editor(ctrl=np.zeros((4, 2)))
    with pytest.raises(ValueError, match="max_levels must be <= 12"):
        views.curve_attractor_view(max_levels=20)

"""Chapter 4 views: what is drawn is the image of the figure under the map the sliders describe
(closed forms written here), the three-point view sends P1, P2, P3 to the slider points, the
T(-Q) R T(Q) steps end on the direct rotation, and no slider position raises."""

import math

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from goldman_lib import affine  # noqa: E402
from goldman_lib.views import affine as av  # noqa: E402
from sweeps import sweep_values

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def drawn(view, k):
    """The points of line k of the view's axes (after the two axis lines), NaN separators dropped."""
    xy = np.asarray(view.figure.axes[0].lines[k + 2].get_xydata(), dtype=float)
    return xy[~np.isnan(xy).any(axis=1)]


F = av.FIGURES["letter F"][0]


def closed_form(kind, tx=0, ty=0, angle=0, cx=0, cy=0, factor=1, direction=0, shear=0):
    """The image of the letter F, by the textbook formulas (not by goldman_lib.affine)."""
    P = F - [cx, cy]
    if kind == "translation":
        return F + [tx, ty]
    if kind == "rotation":
        c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
        Q = np.column_stack([c * P[:, 0] - s * P[:, 1], s * P[:, 0] + c * P[:, 1]])
    elif kind == "uniform scaling":
        Q = factor * P
    elif kind == "nonuniform scaling":
        w = np.array([math.cos(math.radians(direction)), math.sin(math.radians(direction))])
        Q = P + (factor - 1) * np.outer(P @ w, w)
    elif kind == "shear":
        Q = np.column_stack([P[:, 0] + shear * P[:, 1], P[:, 1]])
    else:  # mirror in the line through the centre with direction w
        w = np.array([math.cos(math.radians(direction)), math.sin(math.radians(direction))])
        Q = 2 * np.outer(P @ w, w) - P
    return Q + [cx, cy]


@pytest.mark.parametrize("kind", list(av.KINDS))
def test_transform_explorer_draws_the_image_under_each_map(kind):
    view = av.transform_explorer()
    values = dict(kind=kind, figure="letter F", tx=-1.2, ty=2.0, angle=135.0, cx=0.5, cy=-1.0, factor=-0.75,
                  direction=60.0, shear=1.25)
    result = view.set_values(**values)
    assert view.last_error is None
    expected = closed_form(**{k: v for k, v in values.items() if k != "figure"})
    np.testing.assert_allclose(result["image"][0], expected, atol=1e-12)
    np.testing.assert_allclose(drawn(view, 1), expected, atol=1e-12)          # the blue line
    np.testing.assert_allclose(drawn(view, 0), F)                             # the dashed original
    assert av.format_matrix(result["matrix"]) in result["status"]
    # only the sliders this map uses are visible
    shown = {k for k, w in view.controls.items() if k not in ("kind", "figure") and w.layout.display != "none"}
    assert shown == set(av.KINDS[kind])


def test_transform_explorer_zero_factor_collapses_without_nan():
    view = av.transform_explorer()
    r = view.set_values(kind="uniform scaling", factor=0.0, cx=1.0, cy=1.0)
    assert view.last_error is None
    np.testing.assert_allclose(r["image"][0], np.ones_like(F))
    assert "det = 0" in r["status"]


def test_three_point_explorer_sends_the_triangle_to_the_slider_points():
    view = av.three_point_explorer()
    r = view.set_values(x1=-1.0, y1=0.5, x2=2.0, y2=-1.0, x3=0.5, y3=3.0)
    T = np.array([[-1.0, 0.5], [2.0, -1.0], [0.5, 3.0]])
    np.testing.assert_allclose(r["target"], T)
    # (x, y) -> Q1 + x (Q2 - Q1) + y (Q3 - Q1): the map of the unit triangle, written out
    expected = T[0] + F[:, :1] * (T[1] - T[0]) + F[:, 1:] * (T[2] - T[0])
    np.testing.assert_allclose(r["image"][0], expected, atol=1e-12)
    np.testing.assert_allclose(drawn(view, 1), expected, atol=1e-12)
    np.testing.assert_allclose(drawn(view, 3)[:3], T)
    assert "det" in r["status"] and view.last_error is None


def test_three_point_explorer_reports_collinear_and_mirrored_images():
    view = av.three_point_explorer()
    r = view.set_values(x1=0.0, y1=0.0, x2=1.0, y2=1.0, x3=2.0, y3=2.0)
    assert "collinear" in r["status"] and np.isfinite(r["image"][0]).all()
    r = view.set_values(x1=0.0, y1=0.0, x2=0.0, y2=1.0, x3=1.0, y3=0.0)
    assert "reverses orientation" in r["status"]


def test_rotation_about_point_steps_end_on_the_direct_rotation():
    view = av.rotation_about_point_view()
    r = view.set_values(angle=-70.0, qx=2.5, qy=-1.5)
    Q = np.array([2.5, -1.5])
    np.testing.assert_allclose(r["steps"][1][0], F - Q)
    np.testing.assert_allclose(r["steps"][3][0], r["direct"][0], atol=1e-12)
    c, s = math.cos(math.radians(-70)), math.sin(math.radians(-70))
    P = F - Q
    np.testing.assert_allclose(r["direct"][0], np.column_stack([c * P[:, 0] - s * P[:, 1],
                                                                s * P[:, 0] + c * P[:, 1]]) + Q, atol=1e-12)
    for k in range(4):
        np.testing.assert_allclose(drawn(view, k), r["steps"][k][0], atol=1e-12)


def test_sweeps_static_images_and_bad_arguments():
    for view in (av.transform_explorer(), av.three_point_explorer(), av.rotation_about_point_view()):
        for values in sweep_values(view, n=3)[:40]:
            r = view.update(**values)
            polys = r["image"] if "image" in r else [p for step in r["steps"] for p in step]
            assert all(np.isfinite(p).all() for p in polys)
        assert view.static_png().startswith(PNG_MAGIC)
    with pytest.raises(ValueError, match="kind must be one of"):
        av.transform_explorer(kind="spin")
    with pytest.raises(ValueError, match="figure must be one of"):
        av.transform_explorer(figure="cat")
    with pytest.raises(ValueError, match="three 2D points"):
        av.three_point_explorer(images=[[0, 0], [1, 1]])


def test_plot_map_and_format_matrix():
    ax = av.plot_map(affine.scaling([2, 1]), "house")
    np.testing.assert_allclose(drawn_ax(ax, 1)[:6], av.FIGURES["house"][0] * [2, 1])
    assert av.format_matrix(affine.rotation(90)) == "[0 1 0; -1 0 0; 0 0 1]"
    with pytest.raises(ValueError, match="last column"):
        av.plot_map(np.ones((3, 3)))


def drawn_ax(ax, k):
    xy = np.asarray(ax.lines[k].get_xydata(), dtype=float)
    return xy[~np.isnan(xy).any(axis=1)]


@pytest.mark.parametrize("kind", list(av.KINDS))
def test_the_first_slider_on_the_page_moves_the_default_map(kind):
    import ipywidgets as widgets

    view = av.transform_explorer(kind=kind)
    box = view.children[1].children[1]      # title, then HBox(display, controls)
    first = next(w for w in box.children if isinstance(w, widgets.FloatSlider))
    name = next(k for k, w in view.controls.items() if w is first)
    assert name in av.KINDS[kind] and first.layout.display != "none"
    before = view.last_result["image"][0].copy()
    first.value = first.max if first.value != first.max else first.min
    assert not np.allclose(view.last_result["image"][0], before)

"""Chapter 8 views: what is drawn is the turtle's drawing (chapter 1/2 turtle as reference), the
IFS drawing is the deterministic algorithm of goldman_lib.ifs, and the two coincide."""

import math

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from goldman_lib import affine, fractals, ifs  # noqa: E402
from goldman_lib import conformal_ifs as cf  # noqa: E402
from goldman_lib.views import conformal_ifs as views  # noqa: E402

SQ3 = math.sqrt(3)


def _w(angle, scale):
    return scale * np.array([math.cos(math.radians(angle)), math.sin(math.radians(angle))])


@pytest.mark.parametrize("fractal, level, x, y, angle, scale", [
    ("Koch curve", 3, 0.0, 0.0, 0.0, 1.0), ("dragon curve", 6, 0.5, -0.5, 90.0, 0.5),
    ("Sierpinski gasket", 3, -1.0, 1.0, -45.0, 2.0), ("fractal tree", 4, 0.0, 0.0, 90.0, 1.0),
    ("Koch snowflake", 2, 0.2, 0.1, 30.0, 1.5)])
def test_turtle_ifs_view_draws_the_turtle_and_an_equal_ifs_drawing(fractal, level, x, y, angle, scale):
    view = views.turtle_ifs_view()
    out = view.set_values(fractal=fractal, level=level, x=x, y=y, angle=angle, scale=scale)
    expected = fractals.PROGRAMS[fractal]().polylines(level, (x, y), _w(angle, scale))
    assert len(out["turtle"]) == len(expected)
    assert all(np.allclose(a, b) for a, b in zip(out["turtle"], expected))
    assert cf.same_drawing(out["ifs"], expected)
    assert out["distance"] < 1e-9 and f"Hausdorff distance {out['distance']:.1e}" in out["status"]
    xs, ys = view.figure.axes[0].lines[0].get_data()
    assert np.count_nonzero(~np.isnan(np.asarray(xs, float))) == sum(len(p) for p in expected)


def test_turtle_ifs_view_pieces_are_the_koch_maps_applied_to_the_level_below():
    view = views.turtle_ifs_view()
    out = view.set_values(fractal="Koch curve", level=3, x=0.0, y=0.0, angle=0.0, scale=1.0)
    below = fractals.koch_curve_program().polylines(2)
    for i, T in enumerate(ifs.koch().maps):
        assert cf.same_drawing(out["pieces"][i], [affine.apply(p, T) for p in below])
    # the Koch IFS by hand: map 1 is scale 1/3, rotate 60, translate (1/3, 0)
    assert np.allclose(out["maps"][1], affine.similarity(1 / 3, 60, (1 / 3, 0)))


def test_turtle_ifs_view_lowers_big_levels_and_says_so():
    view = views.turtle_ifs_view()
    out = view.set_values(fractal="Sierpinski carpet", level=8)
    assert out["level"] < 8 and "level lowered to" in out["status"]


def test_initial_state_view_by_hand():
    view = views.initial_state_view()
    out = view.set_values(fractal="Koch curve", level=1, x=1.0, y=2.0, angle=90.0, scale=2.0)
    # (x, y) -> (1 - 2y, 2 + 2x) applied to the Koch level 1 vertices
    expected = [[1, 2], [1, 2 + 2 / 3], [1 - SQ3 / 3, 3], [1, 2 + 4 / 3], [1, 4]]
    assert np.allclose(out["moved"][0], expected) and np.allclose(out["mapped"][0], expected)
    assert out["error"] < 1e-12
    assert np.allclose(out["matrix"], [[0, 2, 0], [-2, 0, 0], [1, 2, 1]], atol=1e-12)


def test_tao_view_draws_the_edited_ifs_with_the_turtle():
    view = views.tao_view()
    out = view.last_result
    system = ifs.c_curve()
    level = out["level"]
    expected = ifs.deterministic(system, level, start=[[0, 0], [1, 0]]).reshape(-1, 2, 2)
    assert cf.drawing_distance(out["turtle"], list(expected)) < 1e-9
    assert "RECURSE" in out["program"]
    view.editor.load("Koch curve")
    out = view.last_result
    assert out["level"] <= view.values()["levels"]
    expected = ifs.deterministic(ifs.koch(), out["level"], start=[[0, 0], [1, 0]]).reshape(-1, 2, 2)
    assert cf.drawing_distance(out["turtle"], list(expected)) < 1e-9


def test_tao_view_names_the_map_a_turtle_cannot_follow():
    view = views.tao_view()
    out = view.set_values(shear1=0.3)
    assert "maps[1] is not conformal" in out["status"] and out["turtle"] == []
    out = view.set_values(shear1=0.0, sy1=-view.values()["sx1"])
    assert "maps[1] reverses orientation" in out["status"]
    assert view.last_error is None


@pytest.mark.parametrize("bump, program", [("Koch curve", fractals.koch_curve_program),
                                           ("dragon", fractals.dragon_program)])
def test_bump_view_at_height_1_draws_the_chapter_2_fractal(bump, program):
    view = views.bump_view()
    out = view.set_values(bump=bump, level=4, height=1.0)
    assert cf.same_drawing(out["turtle"], program().polylines(4))
    assert cf.same_drawing(out["ifs"], program().polylines(4))
    if bump == "Koch curve":
        assert out["dimension"] == pytest.approx(math.log(4) / math.log(3))


def test_bump_view_height_scales_the_bump():
    view = views.bump_view()
    out = view.set_values(bump="C-curve", level=1, height=0.5)
    assert np.allclose(out["bump"], [[0, 0], [0.5, 0.25], [1, 0]])
    assert cf.same_drawing(out["turtle"], [out["bump"]])
    out = view.set_values(bump="square Koch curve", height=0.0)
    assert view.last_error is None and out["distance"] < 1e-9


def test_static_pngs_and_static_plot():
    for factory in (views.turtle_ifs_view, views.initial_state_view, views.bump_view):
        assert factory().static_png().startswith(b"\x89PNG")
    fig = views.plot_turtle_and_ifs("C-curve", 3)
    assert len(fig.axes) == 2


def test_side_by_side_drawings_have_few_ticks():
    """The turtle/IFS panels are drawings: a few ticks each, which halves a slider's redraw (issue 13 §5)."""
    for view in (views.tao_view(), views.turtle_ifs_view(), views.bump_view()):
        view.figure.canvas.draw()
        for ax in view.figure.axes:
            assert len(ax.get_xticks()) <= 6 and len(ax.get_yticks()) <= 6, view.title

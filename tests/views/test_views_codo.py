"""Chapter 5 views: the editor draws exactly what codo.run draws (dots included), keeps the last
good drawing under any bad program and shows the message with line and token; the shortcoming
view draws the affine image and the best turtle state, with a zero gap exactly for similarities."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from goldman_lib import affine, codo, turtle  # noqa: E402
from goldman_lib.views import codo as cv  # noqa: E402


def line_points(view, k):
    xy = np.asarray(view.figure.axes[0].lines[k].get_xydata(), dtype=float)
    return xy[~np.isnan(xy).any(axis=1)]


@pytest.mark.parametrize("name", list(codo.SAMPLES))
def test_editor_draws_each_sample(name):
    view = cv.codo_program_editor()
    view.examples.value = name
    assert view.controls["program"].value == codo.SAMPLES[name]
    assert view.last_error is None
    expected = codo.run(codo.SAMPLES[name])
    got = view.last_result["polylines"]
    assert len(got) == len(expected)
    for a, b in zip(got, expected):
        np.testing.assert_array_equal(a, b)
    dots = np.concatenate(expected)
    np.testing.assert_array_equal(line_points(view, 0), dots)       # the lines
    np.testing.assert_array_equal(line_points(view, 1), dots)       # the dots
    x, _ = view.figure.axes[0].lines[0].get_data()
    assert np.isnan(np.asarray(x, float)).sum() == len(expected) - 1
    assert f"{len(expected)} polyline" in view.last_result["status"]


BAD = ["P = point(0, 0)\nQ = P + P", "CONNECT A, B", "REPEAT 3 [", "x = 1/0", "P = (1, 2)", "£",
       "P = point(0,0)\nREPEAT 1000 [ REPEAT 1000 [ P = P ] ]", "F = polygon(point(0,0), point(1,0))\nREPEAT 40 [ F = F + F ]",
       "x = 1e300 * 1e300", "P = point(1e308, 0) + vector(1e308, 0)"]


@pytest.mark.parametrize("program", BAD)
def test_editor_keeps_the_last_drawing_and_shows_line_and_token(program):
    view = cv.codo_program_editor()
    before = line_points(view, 0)
    with pytest.raises(codo.CodoError):
        view.update(program=program)
    view = cv.codo_program_editor()
    view.controls["program"].value = program
    assert view.last_error.split(":")[0] in ("CodoSyntaxError", "CodoTypeError", "CodoRuntimeError")
    assert "line " in view.status.value and ", at " in view.status.value and "Traceback" not in view.status.value
    np.testing.assert_array_equal(line_points(view, 0), before)
    view.controls["program"].value = "CONNECT point(0, 0), point(1, 1)"
    assert view.last_error is None


def test_editor_empty_program_and_type_check():
    view = cv.codo_program_editor("")
    assert view.last_error is None and view.last_result["polylines"] == []
    with pytest.raises(TypeError):
        cv.codo_program_editor(3)


def test_shortcoming_view_draws_the_image_and_the_best_turtle():
    view = cv.turtle_shortcoming_view()
    r = view.set_values(program="{5/2} star", sx=2.5, sy=0.5, shear=0.7)
    text = cv.TURTLE_PROGRAMS["{5/2} star"]
    (base,) = turtle.run(text)
    M_expected = np.array([[2.5, 0, 0], [0.7 * 0.5, 0.5, 0], [0, 0, 1]])   # scale, then shear
    np.testing.assert_allclose(r["image"][0], base @ M_expected[:2, :2], atol=1e-12)
    fit = codo.closest_turtle_state(text, r["image"])
    assert r["residual"] == pytest.approx(fit.residual) and r["residual"] > 0.1
    np.testing.assert_allclose(r["turtle"][0], turtle.run(text, point=fit.point, direction=fit.direction)[0])
    np.testing.assert_allclose(line_points(view, 0), r["image"][0], atol=1e-12)
    np.testing.assert_allclose(line_points(view, 1), r["turtle"][0], atol=1e-12)
    # a uniform scaling is a change of state: no gap
    r = view.set_values(sx=1.5, sy=1.5, shear=0.0)
    assert r["residual"] < 1e-12
    assert "largest gap to the image 0.000" in r["status"]


def test_plot_functions_and_static_images():
    ax = cv.plot_program(codo.SAMPLES["nested squares"])
    assert ax.lines[1].get_xydata().shape == (25, 2)
    for view in (cv.codo_program_editor(), cv.turtle_shortcoming_view()):
        assert view.static_png().startswith(b"\x89PNG")
    with pytest.raises(ValueError, match="program must be one of"):
        cv.turtle_shortcoming_view(program="circle")
    assert affine.is_conformal(affine.scaling(2))


def test_suggested_program_draws_a_triangle():
    view = cv.codo_program_editor()
    assert f'<code class="goldman-example">{cv.TRY_PROGRAM}</code>' in view.children[-2].children[-1].children[-1].value
    lines = view.update(program=cv.TRY_PROGRAM)["polylines"]
    assert len(lines) == 3
    np.testing.assert_allclose(lines[2][1], [1, 0], atol=1e-12)   # back at the start: a closed triangle

"""Chapter 1 views: widget sweeps over every slider range, the program editor under garbage
input, the static fallback image, and the callback time."""


import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from goldman_lib import turtle  # noqa: E402
from goldman_lib.views import turtle as tv  # noqa: E402
from sweeps import sweep_values

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def _check_drawn(result):
    polys = result["polylines"]
    for p in polys:
        assert p.ndim == 2 and p.shape[1] == 2 and p.shape[0] >= 2
        assert np.isfinite(p).all()
    assert np.isfinite(result["point"]).all() and np.isfinite(result["direction"]).all()
    assert isinstance(result["status"], str) and result["status"]


def _line_nans_are_separators(view, polys):
    x, y = view.figure.axes[0].lines[0].get_data()
    x, y = np.asarray(x, float), np.asarray(y, float)
    assert np.isnan(x).sum() == max(len(polys) - 1, 0)
    assert np.array_equal(np.isnan(x), np.isnan(y))


def test_polygon_explorer_sweep():
    view = tv.polygon_explorer()
    combos = sweep_values(view, n=4)
    assert len(combos) > 20
    for values in combos:
        result = view.update(**values)
        _check_drawn(result)
        _line_nans_are_separators(view, result["polylines"])
        assert len(result["polylines"]) == 1
        assert result["program"] in result["status"]
        x0, x1 = view.figure.axes[0].get_xlim()
        assert np.isfinite([x0, x1]).all() and x1 > x0


def test_polygon_explorer_status_reports_closing_and_turning():
    view = tv.polygon_explorer()
    assert view.set_values(angle=144.0, repetitions=5)["status"] == (
        "REPEAT 5 [FORWARD 1 TURN 144]  |  total turning 720°  |  closes after 5 steps")
    r = view.set_values(angle=60.0, repetitions=12)
    assert r["closes"] and "closes after 6 steps" in r["status"]
    r = view.set_values(angle=60.0, repetitions=5)
    assert not r["closes"] and "does not close: ends 1 from its start" in r["status"]
    r = view.set_values(angle=90.0, repetitions=4, factor=1.1)
    assert "RESIZE 1.1" in r["program"] and not r["closes"]
    assert view.last_error is None


PROGRAMS_OK = ["", "FORWARD 1", "MOVE 3", "REPEAT 3 [FORWARD 1 MOVE 1]", tv.DEFAULT_PROGRAM,
               *tv.EXAMPLES.values(), "REPEAT 100000 [FORWARD 1 TURN 1]"]
PROGRAMS_BAD = ["REPEAT 3 [FORWARD", "FORWARD abc", "TURN 1e400", "REPEAT 1000 [REPEAT 1000 [FORWARD 1]]",
                "REPEAT 1e300 [REPEAT 1e300 [REPEAT 1e300 [TURN 1]]]", "]", "[", "REPEAT -2 [FORWARD 1]",
                "FORWARD 1e300 RESIZE 1e300 FORWARD 1e300", "REPEAT 1 [" * 200, "FORWARD 1 £", "\x00",
                "REPEAT 3.5 [TURN 1]", "forward\n\n   ", "TURN 90 TURN"]


def test_turtle_program_editor_sweep_and_good_programs():
    view = tv.turtle_program_editor()
    for values in sweep_values(view):
        _check_drawn(view.update(**values))
    for program in PROGRAMS_OK:
        result = view.update(program=program)
        _check_drawn(result)
        _line_nans_are_separators(view, result["polylines"])
        assert len(result["polylines"]) == len(turtle.run(program))


@pytest.mark.parametrize("program", PROGRAMS_BAD)
def test_turtle_program_editor_garbage_raises_value_error_and_refresh_keeps_last_drawing(program):
    view = tv.turtle_program_editor("FORWARD 1 TURN 90 FORWARD 1")
    before = np.array(view.figure.axes[0].lines[0].get_xydata())
    with pytest.raises(ValueError):
        view.update(program=program)
    view = tv.turtle_program_editor("FORWARD 1 TURN 90 FORWARD 1")
    view.controls["program"].value = program  # the widget path: refresh swallows the error
    assert view.last_error is not None and "Traceback" not in view.status.value
    assert view.last_error.split(":")[0] in ("TurtleSyntaxError", "ValueError")
    np.testing.assert_allclose(view.figure.axes[0].lines[0].get_xydata(), before)
    view.controls["program"].value = "FORWARD 2"
    assert view.last_error is None


def test_turtle_program_editor_example_picker_fills_the_box():
    view = tv.turtle_program_editor()
    view.examples.value = "hexagon"
    assert view.controls["program"].value == turtle.polygon(6, 1)
    assert len(view.last_result["polylines"]) == 1


def test_static_png_and_plot_functions():
    for view in (tv.polygon_explorer(), tv.turtle_program_editor()):
        png = view.static_png()
        assert png.startswith(PNG_MAGIC) and len(png) > 2000
        assert "image/png" in view._repr_mimebundle_()
    ax = tv.plot_polylines(turtle.run("REPEAT 3 [FORWARD 1 MOVE 1]"))
    x, _ = ax.lines[0].get_data()
    assert np.isnan(x).sum() == 2
    ax = tv.plot_program(turtle.star(5, 2))
    assert ax.lines[0].get_xydata().shape == (6, 2)
    ax = tv.plot_polylines([])
    with pytest.raises(ValueError, match=r"polylines\[0\] must be finite"):
        tv.plot_polylines([np.array([[0, 0], [np.nan, 1]])])



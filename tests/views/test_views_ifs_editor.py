"""The IFS map editor draws what the library computes for the slider values: presets load every
slider, the drawn attractor is the chaos game (or deterministic algorithm) of system_from_values,
hidden rows follow the maps count, and non-contractive settings give a status, not a traceback."""

import matplotlib.pyplot as plt
import numpy as np
import pytest
from scipy.spatial.distance import directed_hausdorff

from goldman_lib import affine, ifs
from goldman_lib.widgets import ifs_editor as ed
from sweeps import sweep_values


@pytest.fixture
def view():
    v = ed.ifs_editor(points=5000)
    yield v
    plt.close(v.figure)


@pytest.mark.parametrize("name", sorted(ifs.STANDARD))
def test_presets_round_trip_through_the_sliders(name):
    s = ifs.STANDARD[name]()
    back = ed.system_from_values(ed.values_from_system(name))
    np.testing.assert_allclose(back.maps, s.maps, atol=1e-9)
    np.testing.assert_allclose(back.probabilities, s.probabilities, atol=1e-9)
    assert (back.condensation is None) == (s.condensation is None)


def test_drawn_points_are_the_chaos_game_of_the_sliders(view):
    result = view.load("Barnsley fern")
    s = ed.system_from_values(view.values())
    expected, labels = ifs.chaos_game_with_maps(s, view.values()["points"], rng=0)
    np.testing.assert_array_equal(result["points"], expected)
    np.testing.assert_array_equal(result["labels"], labels)
    np.testing.assert_allclose(result["images"], ifs.map_images(s))
    np.testing.assert_allclose(result["factors"], [np.linalg.norm(L, 2) for L in s.linear_parts])
    drawn = np.concatenate([np.c_[line.get_xdata(), line.get_ydata()] for line in view.axes.lines[1:10]
                            if len(line.get_xdata()) and line.get_linestyle() == "None"])
    assert len(drawn) == len(expected)


def test_a_slider_moves_one_map(view):
    before = view.update(**view.values())
    values = {**view.values(), "tx1": 0.9, "angle1": 30.0}
    after = view.update(**values)
    M = affine.from_parameters(angle=30, scale=(0.5, 0.5), translate=(0.9, 0.0))
    np.testing.assert_allclose(after["images"][1], affine.apply(ifs.UNIT_SQUARE, M), atol=1e-12)
    np.testing.assert_allclose(after["images"][0], before["images"][0])


def test_deterministic_mode_and_level_cap(view):
    values = {**view.values(), "algorithm": "deterministic", "levels": 5}
    result = view.update(**values)
    assert len(result["points"]) == 3 ** 5
    gasket = ifs.deterministic(ifs.sierpinski(), 5)
    assert directed_hausdorff(result["points"], gasket)[0] < 1e-9
    capped = view.update(**{**values, "levels": 12})
    assert len(capped["points"]) <= 100_000 and "capped" in capped["status"]


def test_maps_count_and_hidden_rows(view):
    view.set_values(maps=2, edit=2)
    result = view.last_result
    assert len(result["images"]) == 2
    view.controls["maps"].value = 1          # like the "- map" button
    assert view.controls["edit"].value == 1
    assert len(view.last_result["images"]) == 1


def test_non_contractive_maps_give_a_status_and_a_finite_drawing(view):
    values = {**view.values(), "sx0": 1.0, "sy0": 1.0, "shear0": 1.0}
    result = view.update(**values)
    assert "not a contraction" in result["status"]
    assert np.all(np.isfinite(result["points"])) and len(result["points"]) > 0
    view.set_values(sx0=1.0, sy0=-1.0, shear0=-1.0, maps=8)
    assert view.last_error is None


def test_condensation_trunk_in_both_algorithms(view):
    view.load("fractal tree")
    assert view.values()["condensation"] == "trunk (0,0)-(0,1)"
    chaos = view.last_result
    assert np.any(chaos["labels"] == 2)           # points on the trunk
    det = view.update(**{**view.values(), "algorithm": "deterministic", "levels": 4})
    assert len(det["points"]) == 2 * (2 ** 5 - 1)


def test_sweep_grid_is_safe_for_many_controls(view):
    combos = sweep_values(view)
    assert 400 < len(combos) < 2000 and all(set(c) == set(view.controls) for c in combos[:5])


def test_too_many_maps_is_rejected():
    with pytest.raises(ValueError, match="at most 2 maps"):
        ed.values_from_system("Sierpinski gasket", max_maps=2)


def test_a_map_is_edited_by_dragging_the_images_of_three_points(hooks):
    """§4.7.3: drag the image of (1, 0) under map 1 of the gasket; the map becomes the affine map
    through the three new images, and its sliders follow."""
    import numpy as np

    from goldman_lib import affine
    from goldman_lib.widgets.ifs_editor import REFERENCE_TRIANGLE, ifs_editor, system_from_values

    editor = ifs_editor("Sierpinski gasket", points=2000)
    before = affine.apply(REFERENCE_TRIANGLE, system_from_values(editor.values()).maps[0])
    assert np.allclose(before, [[0, 0], [0.5, 0], [0, 0.5]])           # the gasket's first map halves
    hooks["press_at"](editor.drag, 0.5, 0.0)
    hooks["move_to"](editor.drag, 0.5, 0.25)
    hooks["release"](editor.drag)
    after = affine.apply(REFERENCE_TRIANGLE, system_from_values(editor.values()).maps[0])
    # the sliders snap to steps of 0.001 and of 0.1 degree
    assert np.allclose(after, [[0, 0], [0.5, 0.25], [0, 0.5]], atol=6e-3)
    assert editor.last_error is None and editor.values()["angle0"] != 0


def test_the_frame_holds_still_while_a_grip_is_dragged_and_fits_on_release(hooks):
    """The editor fits its frame to the attractor after every change, except while a grip is being
    dragged: a frame that rescaled under the mouse would carry the grip away from it (a real-mouse
    drag in the browser moved a grip 93 px for a 40 px drag).  On release the frame fits again."""
    editor = ed.ifs_editor("Barnsley fern", points=2000)
    editor.figure.canvas.draw()
    limits = editor.ax.get_xlim(), editor.ax.get_ylim()
    plan = hooks["drag_plan"](editor.drag, distance=60)
    x, y = editor.ax.transData.inverted().transform(plan["start"])
    x1, y1 = editor.ax.transData.inverted().transform(plan["end"])
    hooks["press_at"](editor.drag, x, y)
    for t in (0.5, 1.0):
        hooks["move_to"](editor.drag, x + t * (x1 - x), y + t * (y1 - y))
        assert (editor.ax.get_xlim(), editor.ax.get_ylim()) == limits
    now = hooks["screen_position"](editor.drag, plan["index"])
    assert np.hypot(now[0] - plan["end"][0], now[1] - plan["end"][1]) < 6.0   # the grip is under the mouse
    hooks["release"](editor.drag)
    assert (editor.ax.get_xlim(), editor.ax.get_ylim()) != limits                 # fitted to the new attractor
    assert editor.last_error is None
    plt.close(editor.figure)

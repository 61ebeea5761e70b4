"""widgets.style.draw_once / freeze_axes_decorations: a static artist is rendered once and its pixels
pasted at later Agg redraws; the picture stays the picture drawn without them (within one level in
255, from blending in two steps), and it is made again when what it depends on changes."""

import io

import matplotlib

matplotlib.use("Agg")

import matplotlib.image as mimage  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.legend import Legend  # noqa: E402

from goldman_lib.widgets import style  # noqa: E402


def figure(freeze: bool):
    fig, ax = style.new_axes()
    ax.set_xlim(0.0, 4.0)
    ax.set_ylim(-1.0, 1.0)
    (line,) = ax.plot([0.0, 4.0], [0.0, 0.5], label="a line")
    ax.legend(loc="lower left")
    ax.set_title("a title")
    if freeze:
        style.freeze_axes_decorations(ax, ax.title)
    return fig, ax, line


def pixels(fig, dpi=None) -> np.ndarray:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi or fig.dpi)
    return (mimage.imread(io.BytesIO(buf.getvalue())) * 255).round().astype(int)


def assert_same_picture(a, b):
    assert a.shape == b.shape
    assert np.abs(a - b).max() <= 1


@pytest.fixture
def legend_draws(monkeypatch):
    """The renderers Legend.draw was called with (patched before the figures are made)."""
    calls = []
    draw = Legend.draw

    def counting(self, renderer):
        calls.append(type(renderer).__name__)
        return draw(self, renderer)

    monkeypatch.setattr(Legend, "draw", counting)
    return calls


def test_the_picture_is_the_picture_while_the_data_moves_under_the_frozen_parts():
    plain, _, line_a = figure(False)
    frozen, _, line_b = figure(True)
    for y in (0.5, -0.9, 0.2):            # the line crosses the frozen grid and passes under the legend
        line_a.set_ydata([0.0, y])
        line_b.set_ydata([0.0, y])
        frozen.canvas.draw()
        assert_same_picture(pixels(plain), pixels(frozen))
    plt.close(plain), plt.close(frozen)


def test_a_frozen_legend_is_rendered_once_and_again_only_when_its_state_changes(legend_draws):
    fig, ax, _ = figure(True)
    fig.canvas.draw()
    fig.canvas.draw()
    pixels(fig)                            # a PNG of the same size and dpi pastes the same pixels
    assert legend_draws == ["RendererAgg"]
    ax.set_title("another title")          # not the legend's state
    fig.canvas.draw()
    assert len(legend_draws) == 1
    ax.set_xlim(0.0, 5.0)                  # the limits are: rendered again
    fig.canvas.draw()
    assert len(legend_draws) == 2
    pixels(fig, dpi=50)                    # another dpi: rendered again at that dpi
    assert len(legend_draws) == 3
    plt.close(fig)


def test_changes_show_a_new_title_limits_and_dpi():
    plain, ax_a, _ = figure(False)
    frozen, ax_b, _ = figure(True)
    frozen.canvas.draw()
    for ax in (ax_a, ax_b):
        ax.set_title("another title")
        ax.set_xlim(-1.0, 3.0)
    frozen.canvas.draw()
    assert_same_picture(pixels(plain), pixels(frozen))
    assert_same_picture(pixels(plain, dpi=60), pixels(frozen, dpi=60))
    plt.close(plain), plt.close(frozen)


def test_other_renderers_draw_the_artist_itself(legend_draws):
    fig, _, _ = figure(True)
    fig.canvas.draw()
    fig.savefig(io.BytesIO(), format="svg")
    assert legend_draws[-1] != "RendererAgg" and len(legend_draws) == 2
    plt.close(fig)


def test_a_hidden_frozen_artist_is_not_drawn():
    plain, ax_a, _ = figure(False)
    frozen, ax_b, _ = figure(True)
    frozen.canvas.draw()
    ax_a.get_legend().set_visible(False)
    ax_b.get_legend().set_visible(False)
    assert_same_picture(pixels(plain), pixels(frozen))
    plt.close(plain), plt.close(frozen)


def test_pin_layout_rescaling_keeps_the_y_label_following_its_tick_labels():
    fig, ax = style.new_axes(equal=False)
    ax.set_xlabel("x"), ax.set_ylabel("y"), ax.set_title("t")
    style.pin_layout(fig, rescaling=(ax,))
    assert not ax.xaxis._autolabelpos and not ax._autotitlepos and ax.yaxis._autolabelpos
    ax.set_ylim(-100000.0, 100000.0)       # wider tick labels: the y label moves left of them
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    label = ax.yaxis.label.get_window_extent(renderer)
    ticks = [t.get_window_extent(renderer) for t in ax.get_yticklabels() if t.get_text()]
    assert label.x1 <= min(b.x0 for b in ticks)
    plt.close(fig)


def test_a_property_set_on_a_frozen_artist_shows():
    plain, ax_a, _ = figure(False)
    frozen, ax_b, _ = figure(True)
    frozen.canvas.draw()
    for ax in (ax_a, ax_b):
        ax.set_xlabel("a new label")        # the x axis: stale, rendered again
        ax.set_yticks([-1.0, 0.0, 1.0])
    frozen.canvas.draw()
    assert_same_picture(pixels(plain), pixels(frozen))
    plt.close(plain), plt.close(frozen)

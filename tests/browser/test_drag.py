"""Dragging a control point with the mouse in real JupyterLab (headless Chromium): chapter 24's
de Casteljau explorer.  The mouse goes down on P1, moves, and comes up; the ipympl canvas must
change (the curve and polygon moved) and P1's x/y sliders must show the point's new place.

Where P1 is on the screen is computed from the figure's own geometry: the test builds the same
view with the Agg backend, asks matplotlib where P1 is drawn in figure pixels, and maps that onto
the canvas element's box; the spot is then refined from the canvas screenshot (the centroid of the
control-polygon grey near it), so a few pixels of layout difference do not make the press miss.
Screenshots before and after go to tests/browser/screenshots/.
"""

from __future__ import annotations

import io
import time

import numpy as np
import pytest
from PIL import Image

from .conftest import REPO, SCREENSHOTS
from .labdriver import changed_fraction, drag_until, screenshot, wait_changed, wait_nonblank

pytestmark = pytest.mark.browser

NOTEBOOK = REPO / "course" / "24_bezier_curves_and_surfaces.ipynb"
MPL_CANVAS = ".jupyter-matplotlib-canvas-div canvas"
# The drag must change more than this fraction of the canvas's pixels (a moved cubic, its polygon
# and the construction lines: thousands of pixels of the 560 x 420 canvas).
CHANGE_TOLERANCE = 0.002
GRAB = (1.0, 2.5)            # P1 of DEFAULT_CUBIC, in data coordinates
MOVE = (1.0, 0.5)            # how far the mouse takes it, in data coordinates


def _figure_geometry():
    """P1's position in figure pixels (origin bottom left), pixels per data unit, and the figure size."""
    from goldman_lib.views import bezier as bezier_views

    view = bezier_views.de_casteljau_explorer()
    fig, ax = view.figure, view.ax
    fig.canvas.draw()
    p = ax.transData.transform(GRAB)
    q = ax.transData.transform((GRAB[0] + 1.0, GRAB[1] + 1.0))
    width, height = fig.get_size_inches() * fig.dpi
    return p, q - p, (width, height)


def _refine(png: bytes, guess_xy, box, radius: int = 14):
    """The centroid of control-polygon grey (#7a7a7a) pixels within ``radius`` of ``guess_xy``
    (page coordinates), or the guess if there is none."""
    a = np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.int16)
    sx, sy = a.shape[1] / box["width"], a.shape[0] / box["height"]
    gx, gy = (guess_xy[0] - box["x"]) * sx, (guess_xy[1] - box["y"]) * sy
    grey = (np.abs(a - np.array([0x7A, 0x7A, 0x7A])).max(axis=2) <= 18)
    ys, xs = np.nonzero(grey)
    near = np.hypot(xs - gx, ys - gy) <= radius * sx
    if near.sum() < 6:
        return guess_xy, 0
    cx, cy = xs[near].mean(), ys[near].mean()
    return (box["x"] + cx / sx, box["y"] + cy / sy), int(near.sum())


def _readout(view, name: str) -> float | None:
    """The value a slider shows (its readout; the handle's aria-valuenow if the readout is hidden)."""
    slider = view.locator(".widget-slider").filter(
        has=view.page.locator(".widget-label", has_text=name)).first
    for sel, attr in ((".widget-readout", None), (".noUi-handle", "aria-valuenow")):
        loc = slider.locator(sel).first
        if loc.count():
            text = loc.get_attribute(attr) if attr else loc.inner_text()
            try:
                return float(text)
            except (TypeError, ValueError):
                continue
    return None


def test_dragging_a_control_point_moves_the_curve_and_its_sliders(lab):
    started = time.monotonic()
    page = lab.page
    lab.open(NOTEBOOK.relative_to(lab.server["root"]).as_posix())
    state = lab.run_all(timeout=420)
    assert not state["errors"], "chapter 24 raised:\n" + "\n".join(state["errors"])
    nb = page.locator(".jp-NotebookPanel:not(.lm-mod-hidden) .jp-Notebook")
    view = nb.locator(".goldman-interactive").filter(has_text="de Casteljau explorer").first
    canvas = view.locator(MPL_CANVAS).first
    canvas.scroll_into_view_if_needed()
    before, st = wait_nonblank(canvas, timeout=60)
    assert st.nonblank(), f"the explorer's canvas looks blank ({st})"
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    (SCREENSHOTS / "drag-before.png").write_bytes(before)
    x0, y0 = _readout(view, "x1"), _readout(view, "y1")
    assert (x0, y0) == (1.0, 2.5), f"P1's sliders read {(x0, y0)} before the drag"

    p, per_unit, (fig_w, fig_h) = _figure_geometry()
    target = (GRAB[0] + MOVE[0], GRAB[1] + MOVE[1])

    def p1():
        return _readout(view, "x1"), _readout(view, "y1")

    def arrived():
        # the kernel handles the motion events one by one (slowly on a loaded machine): wait until
        # the sliders show the end of the drag, not merely its first step
        v = p1()
        return v if None not in v and abs(v[0] - target[0]) <= 0.15 and abs(v[1] - target[1]) <= 0.15 else None

    def plan():
        return p, (p[0] + MOVE[0] * per_unit[0], p[1] + MOVE[1] * per_unit[1]), (fig_w, fig_h)

    def refine(start, box):
        spot, hits = _refine(screenshot(canvas), start, box)
        print(f"press at {spot} (guess {start}, {hits} grey pixels near it)")
        return spot

    def missed(attempt):
        now = p1()
        assert now == (x0, y0), f"P1's sliders read {now} after a drag to about {target}"

    moved = drag_until(page, canvas, plan, arrived, timeout=90, steps=8, pause=0.05, refine=refine,
                       on_miss=missed, message="P1's sliders to follow the drag")
    # the other points stayed where they were
    assert (_readout(view, "x0"), _readout(view, "y0"), _readout(view, "x3")) == (0.0, 0.0, 4.0)
    after, frac = wait_changed(canvas, before, CHANGE_TOLERANCE, timeout=30)
    (SCREENSHOTS / "drag-after.png").write_bytes(after)
    assert frac > CHANGE_TOLERANCE, f"the canvas changed by only {frac:.4%} after the drag"
    assert changed_fraction(before, after) > CHANGE_TOLERANCE
    print(f"drag: P1 -> {moved}, {frac:.2%} of the canvas changed, {time.monotonic() - started:.0f} s")

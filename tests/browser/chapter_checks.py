"""Checks of one chapter's own interactions, made in real JupyterLab (headless Chromium) by
test_notebooks_in_lab right after it has run that chapter (:data:`EXTRAS`), so no chapter runs
twice: a learner drags the query point of chapter 11's inside-outside map with the mouse, presses
Play on chapter 15's key-frame animation, and walks the live decks of chapters 6 and 24 to a view
whose slider must work there (live_deck.py).  Each check returns a line for the report.

* Drag: the test asks the kernel where the query point is on the ipympl canvas (the view's axes
  transform, in figure pixels), presses the mouse there, drags it to where (3, -2) is drawn and lets
  go (``labdriver.drag_until``, which maps figure pixels onto the canvas's box and tries again if
  the press missed).  The canvas pixels must change, the query point's sliders must follow (qx = 3, qy = -2, to the
  slider step), and the status line must give the new winding number.
* Play: pressing the ``Play`` widget (CSS class ``goldman-play``) must advance the frame slider it
  drives and change the three.js picture of the two bricks.
"""

from __future__ import annotations

import json
import time

from .conftest import SCREENSHOTS
from .live_deck import DECKS, live_deck_view_responds
from .labdriver import drag_until, nudge_slider, wait_changed, wait_for, wait_nonblank


def _view_with(nb, text: str):
    views = nb.locator(".goldman-interactive")
    for i in range(views.count()):
        if text in views.nth(i).inner_text():
            return views.nth(i)
    raise AssertionError(f"no interactive view shows {text!r}")


def drag_the_query_point_of_the_inside_outside_map(lab, nb) -> str:
    page = lab.page
    view = _view_with(nb, "winding number")
    canvas = view.locator(".jupyter-matplotlib-canvas-div").first
    canvas.scroll_into_view_if_needed()
    before, _ = wait_nonblank(canvas)

    def plan():
        # asked afresh each attempt: a retry starts from wherever the point is now
        a_, b_, size = json.loads(lab.kernel((
            "import json\n"
            "v = inside_outside\n"
            "a = v.ax.transData.transform((v.values()['qx'], v.values()['qy']))\n"
            "b = v.ax.transData.transform((3.0, -2.0))\n"
            "print(json.dumps([[*map(float, a)], [*map(float, b)], [float(v.figure.bbox.width), float(v.figure.bbox.height)]]))"
        )).strip())
        return a_, b_, size

    def moved():
        vals = json.loads(lab.kernel("import json; print(json.dumps(inside_outside.values()))").strip())
        return vals if abs(vals["qx"] - 3.0) <= 0.06 and abs(vals["qy"] + 2.0) <= 0.06 else None

    canvas_el = view.locator(".jupyter-matplotlib-canvas-div canvas").first
    vals = drag_until(page, canvas_el, plan, moved, timeout=60,
                      message="the query point's sliders to follow the drag to (3, -2)")
    time.sleep(1.0)   # the last redraw reaches the browser after the sliders have moved
    after, frac = wait_changed(canvas, before, 0.001)
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    (SCREENSHOTS / "drag-inside-outside-before.png").write_bytes(before)
    (SCREENSHOTS / "drag-inside-outside-after.png").write_bytes(after)
    assert frac > 0.001, "dragging the query point did not change the picture"
    assert "winding number 0" in view.inner_text(), view.inner_text()
    return f"  inside-outside map: dragged the query point to ({vals['qx']}, {vals['qy']}); {frac:.1%} of the canvas changed"


def play_moves_the_key_frame_animation(lab, nb) -> str:
    page = lab.page
    play = nb.locator(".goldman-play").first
    play.scroll_into_view_if_needed()
    view = nb.locator(".goldman-interactive", has=page.locator(".goldman-play")).first
    display = view.locator(".goldman-display").first
    before, st = wait_nonblank(display)
    assert st.nonblank(), f"the key-frame view looks blank ({st})"
    frame0 = int(lab.kernel("print(animation.values()['frame'])").strip())
    play.locator("button").first.click()

    def advanced():
        f = int(lab.kernel("print(animation.values()['frame'])").strip())
        return f if f != frame0 else None

    frame1 = wait_for(advanced, 30, message="Play to advance the frame slider")
    after, frac = wait_changed(display, before, 0.001, timeout=20)
    (SCREENSHOTS / "play-key-frames-before.png").write_bytes(before)
    (SCREENSHOTS / "play-key-frames-after.png").write_bytes(after)
    # pause, so the animation does not keep the kernel busy for the next test
    buttons = play.locator("button")
    if buttons.count() > 1:
        buttons.nth(1).click()
    assert frac > 0.001, "the three.js picture did not change while playing"
    return f"  key frames: Play moved the frame from {frame0} to {frame1}; {frac:.1%} of the view changed"


def render_button_renders(lab, nb, rc, where: str, shot: str) -> str:
    """Press a render control's button (``widgets.render_control.RenderControl``): its progress bar
    must reach the end and a non-blank picture show; then the first slider of the view it renders
    moves (``goldman-renders-<uid>``), a second press must change the picture."""
    page = lab.page
    button = rc.locator("button").first
    status = rc.locator(".widget-html").first
    label = rc.locator(".goldman-progress .widget-label").last      # the bar's own description comes first
    image = rc.locator("img").first

    def press() -> tuple[str, str]:
        button.scroll_into_view_if_needed()
        # blank the status line in the page first: the kernel then writes "rendering..." and the
        # final line, so a status that reads "rendered in" again comes from this press
        status.evaluate("e => { (e.querySelector('.widget-html-content') || e).innerText = ''; }")
        button.click()
        text = wait_for(lambda: (lambda t: t if "rendered in" in t else None)(status.inner_text()),
                        180, interval=0.25, message=f"{where}: the render to finish")
        shown = label.inner_text().strip()
        done, _, total = shown.partition(" / ")
        assert done and done == total, f"{where}: the progress bar stopped at {shown!r} ({text})"
        return text, shown

    text, shown = press()
    first, st = wait_nonblank(image)
    (SCREENSHOTS / f"{shot}-first.png").write_bytes(first)
    assert st.nonblank(), f"{where}: the rendered picture looks blank ({st})"
    uid = rc.evaluate("e => ([...e.classList].find(c => c.startsWith('goldman-renders-')) || '').slice(16)")
    if not uid:
        return f"  render control: {text}; progress {shown}"
    view = nb.locator(f".goldman-view-{uid}").first
    display = view.locator(".goldman-display").first
    before, _ = wait_nonblank(display)
    nudge_slider(view.locator(".goldman-controls .noUi-handle").first, display, before, 0.001)
    page.wait_for_timeout(500)
    text2, shown2 = press()
    second, frac = wait_changed(image, first, 0.001, timeout=30)
    (SCREENSHOTS / f"{shot}-second.png").write_bytes(second)
    assert frac > 0.001, f"{where}: moving the view's first slider and rendering again did not change the picture"
    return f"  render control: {text} (progress {shown}); after a slider move, {text2}: {frac:.1%} of the picture changed"


#: The chapter's own checks, by notebook stem: ``first`` ones run right after the chapter has run,
#: before its sliders move (the query point's winding number assumes the polygon as the notebook
#: built it); ``last`` ones after every view has been checked (a deck re-lays the notebook out, so
#: it comes after the drags, which measure where a point is on the screen).
EXTRAS = {
    "11_vector_geometry_applications": {"first": [drag_the_query_point_of_the_inside_outside_map]},
    "15_quaternions": {"first": [play_moves_the_key_frame_animation]},
}
for _stem in DECKS:        # the live deck of chapters 24 and 6 (live_deck.py)
    EXTRAS.setdefault(_stem, {}).setdefault("last", []).append(
        lambda lab, nb, _stem=_stem: live_deck_view_responds(lab, _stem))

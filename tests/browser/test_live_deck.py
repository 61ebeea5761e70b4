"""The live deck (jupyterlab-slideshow) of the Bezier chapter: run the notebook, start the deck,
walk forward until a slide shows a three.js view, move that view's slider and check the canvas
changes, then stop the deck.  Cells stay live inside the deck, so pythreejs works there.

GOLDMAN_DECK_NOTEBOOK (a path under the served root) overrides the notebook, for development.
"""

from __future__ import annotations

import os

import pytest

from .conftest import LAB_ROOT, SCREENSHOTS
from .labdriver import changed_fraction, wait_changed, wait_for, wait_nonblank

pytestmark = pytest.mark.browser

DECK_NOTEBOOK = os.environ.get("GOLDMAN_DECK_NOTEBOOK", "course/24_bezier_curves_and_surfaces.ipynb")
CHANGE_TOLERANCE = 0.001

# Per three.js canvas: is it inside the window and on top at its centre (what a viewer sees)?
_JS_THREE_ON_SCREEN = """
() => Array.from(document.querySelectorAll('.jupyter-threejs canvas')).map((c, i) => {
  const r = c.getBoundingClientRect();
  const cx = r.x + r.width / 2, cy = r.y + r.height / 2;
  const inView = r.width > 0 && r.height > 0 && cx > 0 && cy > 0 && cx < innerWidth && cy < innerHeight;
  const top = inView ? document.elementFromPoint(cx, cy) : null;
  return {i, onTop: !!top && (top === c || c.parentElement.contains(top))};
})
"""

# Where the deck is: the active cell, the (sub)slide it belongs to (the nearest cell at or above it
# whose slide_type is slide or subslide) and that cell's heading.
_JS_SLIDE = """
() => {
  const nb = window.__goldmanNotebook.content;
  const cells = Array.from(nb.widgets);
  const active = nb.activeCellIndex;
  let start = active;
  const kind = c => ((c.model.getMetadata('slideshow') || {}).slide_type || '');
  while (start > 0 && !['slide', 'subslide'].includes(kind(cells[start]))) start -= 1;
  const h = cells[start].node.querySelector('h1, h2, h3, h4');
  return {key: String(active), slide: String(start), heading: h ? h.textContent.replace('\u00b6', '').trim() : `cell ${start}`};
}
"""


def test_live_deck_three_view_responds(request):
    assert (LAB_ROOT / DECK_NOTEBOOK).exists(), f"{DECK_NOTEBOOK} is missing: the live-deck test needs it"
    lab = request.getfixturevalue("lab")
    page = lab.page
    lab.open(DECK_NOTEBOOK)
    state = lab.run_all()
    assert not state["errors"], "cells raised:\n" + "\n".join(state["errors"])
    page.evaluate("() => { const w = window.__goldmanNotebook; w.content.activeCellIndex = 0; "
                  "w.content.deselectAll(); }")
    lab.command("deck:start")
    try:
        _walk_and_move(lab, page)
    finally:
        lab.command("deck:stop")
        page.wait_for_function("() => !document.querySelector('.jp-Deck')", timeout=30_000)


def _walk_and_move(lab, page):
    page.wait_for_function("() => !!document.querySelector('.jp-Deck')", timeout=30_000)

    slide = page.evaluate(_JS_SLIDE)
    steps, seen, found = 0, [slide["heading"]], None
    slides = {slide["slide"]}
    for _ in range(300):
        hits = [c for c in page.evaluate(_JS_THREE_ON_SCREEN) if c["onTop"]]
        if hits:
            found = hits[0]["i"]
            break
        # jupyterlab-slideshow: deck:down enters the subslides below the current slide; deck:forward
        # steps through the slide's fragments and then to the next slide to the right.
        moved = False
        for cmd, patience in (("deck:down", 1.5), ("deck:forward", 5)):
            lab.command(cmd)
            try:
                slide = wait_for(lambda: (lambda s: s if s["key"] != slide["key"] else None)(page.evaluate(_JS_SLIDE)),
                                 patience, interval=0.1, message="the deck to move")
            except TimeoutError:
                continue
            moved = True
            break
        if not moved:
            break
        steps += 1
        if slide["slide"] not in slides:
            slides.add(slide["slide"])
            seen.append(slide["heading"])
        page.wait_for_timeout(300)          # let the slide transition settle before judging visibility
    walked = len(slides)
    assert found is not None, f"walked {walked} slides ({seen}) and none showed a three.js canvas"

    canvas = page.locator(".jupyter-threejs canvas").nth(found)
    view = page.locator(".goldman-interactive").filter(has=canvas)
    before, st = wait_nonblank(canvas)
    (SCREENSHOTS / "live-deck-three-before.png").write_bytes(before)
    page.screenshot(path=str(SCREENSHOTS / "live-deck-slide.png"))
    assert st.nonblank(), f"the three.js canvas on slide {walked} looks blank ({st})"
    assert view.count() == 1, "the three.js canvas on the slide is not inside a goldman-interactive view"
    handle = view.locator(".goldman-controls .noUi-handle").first
    handle.focus()
    for _ in range(5):
        handle.press("ArrowRight")
    after, frac = wait_changed(canvas, before, CHANGE_TOLERANCE, timeout=15)
    if frac <= CHANGE_TOLERANCE:
        handle.press("End")
        after, frac = wait_changed(canvas, before, CHANGE_TOLERANCE, timeout=20)
    (SCREENSHOTS / "live-deck-three-after.png").write_bytes(after)
    # focusing the slider may make its code cell the active one, but the slide must stay, in view
    still_here = (page.evaluate(_JS_SLIDE)["slide"] == slide["slide"]
                  and page.evaluate(_JS_THREE_ON_SCREEN)[found]["onTop"])
    print(f"\nlive deck of {DECK_NOTEBOOK}: {steps} deck steps over {walked} slides {seen}; slide {walked} "
          f"({slide['heading']!r}) holds three.js canvas #{found} ({st}); moving its slider changed "
          f"{frac:.1%} of the canvas pixels (changed_fraction={changed_fraction(before, after):.4f})")
    assert still_here, "pressing keys on the slider moved the deck to another slide"
    assert frac > CHANGE_TOLERANCE, f"moving the slider changed only {frac:.2%} of the canvas pixels"

"""Live decks (jupyterlab-slideshow): in a chapter that has just run, start its deck, walk forward
until a slide shows a given live view, move that view's first slider and check its canvas changes,
then stop the deck.  Cells stay live inside the deck, so pythreejs and ipympl work there.

Two decks (:data:`DECKS`; test_notebooks_in_lab makes these checks right after it has run the
chapter, through chapter_checks.EXTRAS, so no chapter runs twice): chapter 24 up to its three.js
patch editor, and chapter 6 up to the IFS map editor (an ipympl figure, the shared Part I component
an instructor edits live).
"""

from __future__ import annotations

import sys

import pytest

from .conftest import SCREENSHOTS
from .labdriver import changed_fraction, nudge_slider, wait_for, wait_nonblank

CHANGE_TOLERANCE = 0.001

# notebook stem: (what to look for, the title of the view that holds it or "" for any view)
DECKS = {
    "24_bezier_curves_and_surfaces": (".jupyter-threejs canvas", ""),
    "06_ifs_fractals": (".jupyter-matplotlib-canvas-div", "IFS map editor"),
}

# Per canvas of the wanted kind (in a view with the wanted title): is it inside the window and on
# top at its centre (what a viewer sees)?
_JS_ON_SCREEN = """
([selector, title]) => Array.from(document.querySelectorAll(selector)).map((c, i) => {
  const view = c.closest('.goldman-interactive');
  if (title && !(view && view.textContent.includes(title))) return {i, onTop: false};
  const r = c.getBoundingClientRect();
  const cx = r.x + r.width / 2, cy = r.y + r.height / 2;
  const inView = r.width > 0 && r.height > 0 && cx > 0 && cy > 0 && cx < innerWidth && cy < innerHeight;
  const top = inView ? document.elementFromPoint(cx, cy) : null;
  return {i, onTop: !!top && (top === c || c.parentElement.contains(top))};
})
"""

_JS_DECK_WRAPS = """
() => { const c = document.querySelector('.jp-Deck .jp-CodeCell .cm-content');
        const o = document.querySelector('.jp-Deck .jp-OutputArea-output pre');
        return !!c && ['pre-wrap', 'break-spaces'].includes(getComputedStyle(c).whiteSpace) &&
               (!o || getComputedStyle(o).whiteSpace === 'pre-wrap'); }
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


def live_deck_view_responds(lab, notebook: str) -> str:
    """In the notebook (stem) that has just run: start its deck, walk to the view of DECKS, move its
    slider, stop the deck; returns the report line."""
    selector, title = DECKS[notebook]
    page = lab.page
    page.evaluate("() => { const w = window.__goldmanNotebook; w.content.activeCellIndex = 0; "
                  "w.content.deselectAll(); }")
    lab.command("deck:start")
    try:
        # the course's Lab settings (binder/overrides.json, installed by `make venv`): in the deck,
        # long code lines wrap (CodeMirror reads white-space from its content's style; without the
        # settings, a 900 px wide deck of chapter 17 showed 3 code cells wider than their editor)
        try:
            page.wait_for_function(_JS_DECK_WRAPS, timeout=30_000)
        except Exception:
            pytest.fail("code in the live deck does not wrap: binder/overrides.json is not installed as "
                        f"{sys.prefix}/share/jupyter/lab/settings/overrides.json (make venv installs it)")
        return _walk_and_move(lab, page, notebook, selector, title)
    finally:
        lab.command("deck:stop")
        page.wait_for_function("() => !document.querySelector('.jp-Deck')", timeout=30_000)


def _walk_and_move(lab, page, notebook, selector, title):
    stem = "live-deck-" + notebook[:2]
    on_screen = lambda: page.evaluate(_JS_ON_SCREEN, [selector, title])  # noqa: E731
    page.wait_for_function("() => !!document.querySelector('.jp-Deck')", timeout=30_000)

    slide = page.evaluate(_JS_SLIDE)
    steps, seen, found = 0, [slide["heading"]], None
    slides = {slide["slide"]}
    for _ in range(300):
        hits = [c for c in on_screen() if c["onTop"]]
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
    what = f"{title or 'a view'} ({selector})"
    assert found is not None, f"walked {walked} slides ({seen}) and none showed {what}"

    canvas = page.locator(selector).nth(found)
    # the view holding this canvas (its nearest goldman-interactive ancestor)
    view = canvas.locator("xpath=ancestor::*[contains(concat(' ', normalize-space(@class), ' '), "
                          "' goldman-interactive ')][1]")
    before, st = wait_nonblank(canvas)
    (SCREENSHOTS / f"{stem}-before.png").write_bytes(before)
    page.screenshot(path=str(SCREENSHOTS / f"{stem}-slide.png"))
    assert st.nonblank(), f"{what} on slide {walked} looks blank ({st})"
    assert view.count() == 1, f"{what} on the slide is not inside a goldman-interactive view"
    # (Home as a last resort: the chapter's own test may have left this slider at its end)
    after, frac, _ = nudge_slider(view.locator(".goldman-controls .noUi-handle").first, canvas, before,
                                  CHANGE_TOLERANCE)
    (SCREENSHOTS / f"{stem}-after.png").write_bytes(after)
    # focusing the slider may make its code cell the active one, but the slide must stay, in view
    still_here = (page.evaluate(_JS_SLIDE)["slide"] == slide["slide"]
                  and on_screen()[found]["onTop"])
    assert still_here, "pressing keys on the slider moved the deck to another slide"
    assert frac > CHANGE_TOLERANCE, f"moving the slider changed only {frac:.2%} of the canvas pixels"
    return (f"  live deck: {steps} deck steps over {walked} slides; slide {walked} ({slide['heading']!r}) holds "
            f"{what} #{found} ({st}); moving its slider changed {frac:.1%} of the canvas pixels "
            f"(changed_fraction={changed_fraction(before, after):.4f})")

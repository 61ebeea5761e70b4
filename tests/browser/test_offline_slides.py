"""`make slides`: the offline reveal.js deck of a chapter opens from file:// with no network, Reveal
initialises, each slide heading is a slide, and the widget views appear as their static PNGs.

The deck is built with scripts/build_slides.py into build/slides/ (its vendor/ copy of reveal.js,
require.js, jQuery and MathJax is fetched with npm on the first build and reused afterwards).
"""

from __future__ import annotations

import concurrent.futures
import importlib.util
import re
import shutil
import time
from html.parser import HTMLParser

import nbformat
import pytest

from .conftest import REPO, SCREENSHOTS, course_notebooks

pytestmark = pytest.mark.browser

PREFERRED = "24_bezier_curves_and_surfaces.ipynb"


def _load_build_slides():
    spec = importlib.util.spec_from_file_location("build_slides", REPO / "scripts" / "build_slides.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _chapter():
    """The Bezier chapter if it exists, else the chapter with the most stored images."""
    notebooks = course_notebooks()
    for nb in notebooks:
        if nb.name == PREFERRED:
            return nb
    def images(path):
        nb = nbformat.read(path, as_version=4)
        return sum("image/png" in o.get("data", {}) for c in nb.cells if c.cell_type == "code" for o in c.outputs)
    ranked = sorted(notebooks, key=lambda p: (-images(p), p.name))
    return ranked[0] if ranked else None


class _Resources(HTMLParser):
    """Every URL the page would load by itself: script src, link href, img/iframe/source src."""

    def __init__(self):
        super().__init__()
        self.urls: list[str] = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag in ("script", "img", "iframe", "source", "audio", "video", "embed") and a.get("src"):
            self.urls.append(a["src"])
        if tag == "link" and a.get("href"):
            self.urls.append(a["href"])


def _slide_headings(nb) -> list[list[str]]:
    """Words of the heading that opens each slide/subslide markdown cell (math left out)."""
    out = []
    for cell in nb.cells:
        st = cell.metadata.get("slideshow", {}).get("slide_type")
        if cell.cell_type != "markdown" or st not in ("slide", "subslide"):
            continue
        m = re.search(r"^\s{0,3}#{1,6}\s+(.+)$", cell.source, re.M)
        if m:
            text = re.sub(r"\$[^$]*\$", " ", m.group(1))
            words = re.findall(r"[A-Za-z0-9]+", text)
            if words:
                out.append(words)
    return out


def test_offline_deck(browser_page):
    chapter = _chapter()
    if chapter is None:
        pytest.skip("no notebooks in course/ yet")
    build_slides = _load_build_slides()
    vendored = (build_slides.OUT / build_slides.VENDOR_DIRNAME / "node_modules" / "reveal.js").is_dir()
    if not vendored and shutil.which("npm") is None:
        pytest.skip("the offline deck fetches reveal.js and MathJax with npm once: sudo apt-get install npm")
    deck = build_slides.build_deck(chapter)
    html = deck.read_text(encoding="utf-8")

    # 1. Nothing is fetched from a CDN: every script/link/img the page loads is local or inline.
    parser = _Resources()
    parser.feed(html)
    remote = [u for u in parser.urls if re.match(r"^(https?:)?//", u)]
    assert not remote, f"{deck.name} loads remote resources: {remote}"
    assert not re.search(r"""import\s+\w+\s+from\s+['"](https?:)?//""", html), "a module import from a CDN remains"
    # (https:// still occurs in comments of the inlined CSS and of the template's script, e.g.
    # "https://github.com/hakimel/reveal.js#configuration"; comments load nothing.)

    # 2. Open it from file:// with every non-local request blocked and recorded.
    page = browser_page
    requested: list[str] = []

    def guard(route):
        url = route.request.url
        if url.startswith(("file:", "data:", "blob:", "about:")):
            route.continue_()
        else:
            requested.append(url)
            route.abort()

    page.route("**/*", guard)
    page.goto(deck.as_uri(), wait_until="load")
    page.wait_for_function("() => !!document.querySelector('.reveal.ready')", timeout=60_000)
    sections = page.evaluate("() => document.querySelectorAll('.reveal .slides section').length")
    assert sections > 3, f"only {sections} reveal.js sections"
    assert not requested, f"the deck tried to reach the network: {requested}"

    # 3. Every slide heading is inside a section.
    nb = nbformat.read(chapter, as_version=4)
    heading_texts = page.evaluate("""() => Array.from(document.querySelectorAll(
        '.reveal .slides section h1, .reveal .slides section h2, .reveal .slides section h3, .reveal .slides section h4'))
        .map(h => h.textContent)""")
    missing = []
    for words in _slide_headings(nb):
        if not any(all(w in text for w in words) for text in heading_texts):
            missing.append(" ".join(words))
    assert not missing, f"slide headings not found as slides: {missing}"

    # 4. Widget outputs show their stored PNG; images decode.
    nb_static = nbformat.read(chapter, as_version=4)
    expected = 0
    for cell in nb_static.cells:
        if cell.cell_type == "code" and cell.metadata.get("slideshow", {}).get("slide_type") != "skip":
            expected += sum("image/png" in o.get("data", {}) for o in cell.outputs)
    images = page.evaluate("""() => Array.from(document.querySelectorAll('.reveal .slides img'))
        .filter(i => i.src.startsWith('data:image/png')).map(i => i.naturalWidth)""")
    assert len(images) >= expected, f"{len(images)} PNG images in the deck, expected at least {expected}"
    assert all(w > 0 for w in images), "a PNG image in the deck does not decode"
    assert "[interactive view" not in page.inner_text("body"), "a widget placeholder text is shown instead of its image"
    assert page.locator('script[type="application/vnd.jupyter.widget-view+json"]').count() == 0

    # 5. Worked solutions are in the deck but closed: no answer shows until the <summary> is clicked.
    solutions = sum("solution" in c.metadata.get("tags", []) for c in nb.cells)
    if solutions:
        found = page.evaluate("""() => Array.from(document.querySelectorAll('.reveal .slides details'))
            .map(d => ({open: d.open, summary: !!d.querySelector('summary'), code: !!d.querySelector('pre, code')}))""")
        assert len(found) >= solutions, f"{len(found)} <details> blocks in the deck, {solutions} worked solutions"
        assert all(not d["open"] and d["summary"] and d["code"] for d in found), "a worked solution is open in the deck"
        # go to the slide of the first solution: its summary shows, its code does not until opened
        page.evaluate("""() => {
            const d = document.querySelector('.reveal .slides details');
            const tops = Array.from(document.querySelectorAll('.reveal .slides > section'));
            const h = tops.findIndex(s => s.contains(d));
            const subs = Array.from(tops[h].querySelectorAll(':scope > section'));
            location.hash = `#/${h}/${Math.max(0, subs.findIndex(s => s.contains(d)))}`;
        }""")
        page.wait_for_function("() => { const d = document.querySelector('.reveal .slides details'); "
                               "return d.querySelector('summary').getClientRects().length > 0; }", timeout=20_000)
        # (a closed <details> keeps its content laid out under content-visibility: hidden in Chromium,
        # so visibility is asked with checkVisibility, which honours it)
        shown = page.evaluate("() => document.querySelector('.reveal .slides details pre, "
                              ".reveal .slides details code').checkVisibility()")
        assert not shown, "a worked solution's code is visible while its block is closed"
        assert "Correct:" not in page.inner_text("body"), "a checker's verdict on the answer shows in the deck"
        page.evaluate("() => { document.querySelector('.reveal .slides details summary').click(); }")
        page.wait_for_function("() => document.querySelector('.reveal .slides details pre, "
                               ".reveal .slides details code').checkVisibility()", timeout=10_000)

    # 6. MathJax (local) typesets the LaTeX of the markdown cells.
    has_math = any(c.cell_type == "markdown" and re.search(r"\$[^$]+\$", c.source) for c in nb.cells
                   if c.metadata.get("slideshow", {}).get("slide_type") != "skip")
    if has_math:
        page.wait_for_function("() => !!document.querySelector('.MathJax_CHTML, .MathJax')", timeout=60_000)
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(SCREENSHOTS / f"offline-deck-{chapter.stem}.png"))
    if images:   # also look at the first slide that shows a static image of a view
        page.evaluate("""() => {
            const img = Array.from(document.querySelectorAll('.reveal .slides img')).find(i => i.src.startsWith('data:image/png'));
            const tops = Array.from(document.querySelectorAll('.reveal .slides > section'));
            const h = tops.findIndex(s => s.contains(img));
            const subs = Array.from(tops[h].querySelectorAll(':scope > section'));
            const v = Math.max(0, subs.findIndex(s => s.contains(img)));
            location.hash = `#/${h}/${v}`;
        }""")
        page.wait_for_function("() => { const s = document.querySelector('.reveal .slides section.present img'); return !!s; }",
                               timeout=20_000)
        page.wait_for_timeout(800)   # the slide transition
        page.screenshot(path=str(SCREENSHOTS / f"offline-deck-{chapter.stem}-image.png"))
    print(f"\noffline deck {deck.relative_to(REPO) if deck.is_relative_to(REPO) else deck}: "
          f"{sections} sections, {len(heading_texts)} headings, {len(images)} PNG images "
          f"(expected >= {expected}), math={'typeset' if has_math else 'none'}, no network requests")


# -- every slide of every deck fits a 1280x720 projector ----------------------------------------------
PROJECTOR = {"width": 1280, "height": 720}

# Measure every slide of the open deck at once: reveal.js shows every slide (viewDistance past the
# deck's length; each stays at its own place beside the present one, at the same scale) and every
# worked solution is opened, so its code is measured too.  Returns what runs past its slide: a <pre>
# (code or output) wider than its own box, an element of a code cell (its code, its outputs)
# reaching past the slide's left or right edge, a slide that scrolls sideways; and counts of what
# was measured, and of the code blocks where a long line wraps.
_JS_WALK = """
() => {
  const R = Object.values(require.s.contexts._.defined).find(v => v && typeof v.getTotalSlides === 'function');
  R.configure({transition: 'none', backgroundTransition: 'none', viewDistance: 10000, mobileViewDistance: 10000});
  R.slide(0, 0);
  document.querySelectorAll('.reveal .slides details').forEach(d => { d.open = true; });
  const res = {slides: 0, code: 0, outputs: 0, wrapped: 0, problems: []};
  const short = e => (e.textContent || '').trim().replace(/\\s+/g, ' ').slice(0, 70);
  const what = e => e.closest('.jp-OutputArea') ? 'output' : (e.closest('.jp-CodeCell') ? 'code' : 'markdown code');
  const tops = Array.from(document.querySelectorAll('.reveal .slides > section'));
  tops.forEach((top, h) => {
    const subs = Array.from(top.querySelectorAll(':scope > section'));
    (subs.length ? subs : [top]).forEach((slide, v) => {
      const at = `slide ${h}/${v}`;
      res.slides += 1;
      if (!slide.checkVisibility()) { res.problems.push(`${at}: not shown (reveal.js hid it)`); return; }
      const box = slide.getBoundingClientRect();
      if (slide.scrollWidth > slide.clientWidth + 1)
        res.problems.push(`${at}: the slide scrolls sideways (${slide.scrollWidth} > ${slide.clientWidth} px)`);
      slide.querySelectorAll('pre').forEach(pre => {
        if (!pre.checkVisibility()) return;
        if (pre.closest('.jp-OutputArea')) res.outputs += 1; else res.code += 1;
        if (Array.from(pre.querySelectorAll('.goldman-line')).some(l => l.getClientRects().length > 1 ||
            l.getBoundingClientRect().height > 1.5 * parseFloat(getComputedStyle(l).lineHeight))) res.wrapped += 1;
        if (pre.scrollWidth > pre.clientWidth + 1)
          res.problems.push(`${at}: ${what(pre)} wider than its box (${pre.scrollWidth} > ${pre.clientWidth} px): ${short(pre)}`);
      });
      slide.querySelectorAll('.jp-CodeCell, .jp-CodeCell *').forEach(e => {
        const r = e.getBoundingClientRect();
        if (r.width === 0 || r.height === 0 || !e.checkVisibility()) return;
        if (r.right > box.right + 1 || r.left < box.left - 1)
          res.problems.push(`${at}: ${what(e)} <${e.tagName.toLowerCase()} class="${e.className}"> spans ` +
                            `${Math.round(r.left - box.left)}..${Math.round(r.right - box.left)} px of a ` +
                            `${Math.round(box.width)} px slide: ${short(e)}`);
      });
    });
  });
  return res;
}
"""


def _walk(page, deck) -> dict:
    page.goto(deck.as_uri(), wait_until="load")
    page.wait_for_function("() => !!document.querySelector('.reveal.ready')", timeout=60_000)
    return page.evaluate(_JS_WALK)


def test_every_slide_fits_a_projector(browser_context):
    """Every deck (`make slides`) at 1280x720: no code block or output wider than the slide, no part of
    a code cell cut off at the slide's edge, on any slide (worked solutions opened).

    The decks are built one ahead of the browser (a thread builds the next while Chromium measures
    this one).  MathJax is left to typeset as it likes: it changes the markdown, not the code cells.
    As a check that the measure can fail, chapter 17's deck built as before the fix (no wrapping
    CSS, no line blocks, the 960x700 slide) must show problems."""
    notebooks = course_notebooks()
    if not notebooks:
        pytest.skip("no notebooks in course/ yet")
    build_slides = _load_build_slides()
    vendored = (build_slides.OUT / build_slides.VENDOR_DIRNAME / "node_modules" / "reveal.js").is_dir()
    if not vendored and shutil.which("npm") is None:
        pytest.skip("the offline deck fetches reveal.js and MathJax with npm once: sudo apt-get install npm")
    started = time.monotonic()
    page = browser_context.new_page()
    page.set_viewport_size(PROJECTOR)
    problems, totals = [], {"slides": 0, "code": 0, "outputs": 0, "wrapped": 0}
    control_nb = next((nb for nb in notebooks if nb.name.startswith("17_")), notebooks[-1])
    control = None
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=1) as pool:
            # one thread builds the decks in order (nbconvert, in Python) while Chromium measures
            futures = [pool.submit(build_slides.build_deck, nb, quiet=True) for nb in notebooks]
            unfitted = pool.submit(build_slides.build_deck, control_nb, quiet=True, fit=False,
                                   name=f"unfitted-{control_nb.stem}.slides.html")
            for future in futures:
                deck = future.result()
                found = _walk(page, deck)
                for key in totals:
                    totals[key] += found[key]
                problems += [f"{deck.name} {p}" for p in found["problems"]]
            control = unfitted.result()
        walked = time.monotonic() - started
        # the measure can fail: the deck built as before the fix shows code past the slide
        before = _walk(page, control)
        assert before["problems"], f"the measure finds nothing wrong in {control.name}, built without the fix"
    finally:
        page.close()
        if control is not None:
            control.unlink(missing_ok=True)
    print(f"\n{len(notebooks)} decks at {PROJECTOR['width']}x{PROJECTOR['height']}: {totals['slides']} slides, "
          f"{totals['code']} code blocks, {totals['outputs']} outputs, {totals['wrapped']} blocks wrap a long line, "
          f"{len(problems)} problems (built and measured in {walked:.0f} s); without the fix, "
          f"{control.name} has {len(before['problems'])}")
    assert totals["slides"] >= len(notebooks), "a deck has no slides"
    assert not problems, f"{len(problems)} things run past the slide at 1280x720:\n" + "\n".join(problems[:40])

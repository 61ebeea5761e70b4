"""`make site`: the course website, opened page by page in headless Chromium.

One build per session (scripts/build_site.py into build/site-test/, with launch settings of its own;
reused while the notebooks, the build scripts and those settings are unchanged), served by a
threaded http.server on 127.0.0.1.  Every page (the course map and the thirty chapters) must:
load nothing from outside 127.0.0.1 and log no console error; decode every image, each with alt
text that says something; typeset every formula (no raw ``$...$``, ``\\(`` or ``\\[`` left, no
MathJax error); resolve every internal link and its anchor; keep every worked solution closed
(its text invisible until its block is opened); carry Binder and JupyterHub (nbgitpuller) launch
buttons for its own notebook on the configured repository and branch, and the "run it on your
machine" box; show each interactive view as its stored picture (no widget, no error box); link
its neighbours as previous/next.  The search finds chapter 24 for "de Casteljau" and chapter 15
for "quaternion".

This file's name sorts before test_notebooks_in_lab.py on purpose: the first browser process runs
it (build included) while the second one starts on the chapter runs (scripts/run_tests.py).
"""

from __future__ import annotations

import functools
import hashlib
import importlib.util
import json
import re
import shutil
import threading
from functools import partial
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from urllib.parse import parse_qs, unquote, urlsplit

import nbformat
import pytest

from .conftest import REPO, SCREENSHOTS
from .labdriver import await_js

pytestmark = pytest.mark.browser

COURSE = REPO / "course"
OUT = REPO / "build" / "site-test"
# Launch settings of this test's build (any repository works: nothing is fetched from it).
REPO_URL = "https://github.com/example-org/goldman-course"
BRANCH = "site-test"
HUB = "https://hub.example.edu"
BINDER = "https://mybinder.org"
PAGES = ["index"] + sorted(p.stem for p in COURSE.glob("[0-9][0-9]_*.ipynb"))
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
RAW_MATH = re.compile(r"\\\(|\\\)|\\\[|\\\]|\$[^$\n]{1,200}\$|\$\$")


def _load(name):
    spec = importlib.util.spec_from_file_location(name, REPO / "scripts" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _inputs_digest() -> str:
    """What the build depends on: the notebooks, the two build scripts, the settings, the versions."""
    h = hashlib.sha256()
    for path in sorted(COURSE.glob("*.ipynb")) + [REPO / "scripts" / "build_site.py",
                                                 REPO / "scripts" / "build_slides.py"]:
        h.update(path.name.encode())
        h.update(path.read_bytes())
    from importlib.metadata import version
    h.update(json.dumps([REPO_URL, BRANCH, HUB, BINDER, version("jupyter-book"), version("sphinx")]).encode())
    return h.hexdigest()


class _Quiet(SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@pytest.fixture(scope="session")
def site(browser_context):   # the browser first: without Chromium, skip before building
    """The built site served on 127.0.0.1: ``{"url": base, "html": folder, "seconds": build time}``."""
    if importlib.util.find_spec("jupyter_book") is None:
        pytest.skip("install the site extra: pip install -e '.[site]' (jupyter-book is missing)")
    build_site = _load("build_site")
    html, stamp = OUT / "html", OUT / "test-stamp.json"
    digest = _inputs_digest()
    seconds = 0.0
    if not (stamp.exists() and stamp.read_text() == digest and (html / "index.html").exists()):
        vendored = (OUT / "vendor" / "node_modules" / "mathjax").is_dir()
        if not vendored and shutil.which("npm") is None:
            pytest.skip("the site fetches MathJax with npm once: sudo apt-get install npm")
        import time
        start = time.monotonic()
        stamp.unlink(missing_ok=True)
        build_site.build(OUT, {"repo": REPO_URL, "branch": BRANCH, "hub": HUB, "binder": BINDER}, quiet=True)
        seconds = time.monotonic() - start
        stamp.write_text(digest)
    server = ThreadingHTTPServer(("127.0.0.1", 0), partial(_Quiet, directory=str(html)))
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        print(f"\nsite: {'built in %.0f s' % seconds if seconds else 'reused the build'} ({html.relative_to(REPO)})")
        yield {"url": f"http://127.0.0.1:{server.server_address[1]}", "html": html, "seconds": seconds}
    finally:
        server.shutdown()
        server.server_close()


@functools.lru_cache(maxsize=None)
def _ids(path: Path) -> frozenset[str]:
    return frozenset(re.findall(r'\bid="([^"]+)"', path.read_text(encoding="utf-8")))


def _notebook_facts(stem: str) -> dict:
    """What the page must show, read from the notebook itself."""
    nb = nbformat.read(COURSE / f"{stem}.ipynb", as_version=4)
    images = views = 0
    for cell in nb.cells:
        for out in cell.get("outputs", []):
            data = out.get("data", {})
            if any(k.startswith("image/") for k in data):
                images += 1
                views += WIDGET_VIEW in data and "[interactive view:" in "".join(data.get("text/plain", ""))
    solutions = sum("solution" in c.metadata.get("tags", []) for c in nb.cells)
    return {"images": images, "views": views, "solutions": solutions}


def _open(page, url: str) -> list[str]:
    """Go to ``url`` with every request outside 127.0.0.1 blocked; return those it tried."""
    outside: list[str] = []

    def guard(route):
        u = route.request.url
        if u.startswith(("http://127.0.0.1:", "data:", "blob:", "about:")):
            route.continue_()
        else:
            outside.append(u)
            route.abort()

    page.route("**/*", guard)
    page.on("response", lambda r: page.console_errors.append(f"HTTP {r.status}: {r.url}") if r.status >= 400 else None)
    page.goto(url, wait_until="load")
    return outside


PAGE_FACTS = """async () => {
  await Promise.all(Array.from(document.images).map(i => i.decode().catch(() => null)));
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) await MathJax.startup.promise;
  const main = document.querySelector('article.bd-article');
  const maths = Array.from(main.querySelectorAll('span.math, div.math'));
  const clone = main.cloneNode(true);
  clone.querySelectorAll('pre, code, mjx-container, script, style, .highlight').forEach(e => e.remove());
  return {
    title: main.querySelector('h1') ? main.querySelector('h1').textContent : '',
    images: Array.from(document.images).map(i => ({src: i.getAttribute('src'), alt: i.getAttribute('alt'),
                                                    width: i.naturalWidth, content: main.contains(i)})),
    maths: maths.length,
    untypeset: maths.filter(m => !m.querySelector('mjx-container')).map(m => m.textContent.slice(0, 80)),
    mathErrors: Array.from(main.querySelectorAll('mjx-merror, [data-mjx-error]')).map(e => e.textContent.slice(0, 80)),
    text: clone.textContent,
    links: Array.from(document.querySelectorAll('a[href]')).map(a => a.href),
    details: Array.from(main.querySelectorAll('details')).map(d => ({
      open: d.open, summary: d.querySelector(':scope > summary') ? d.querySelector(':scope > summary').textContent : null,
      body: Array.from(d.children).filter(c => c.tagName !== 'SUMMARY').map(c => c.textContent).join(' ').trim(),
      visible: Array.from(d.querySelectorAll(':scope > :not(summary)')).filter(c => c.checkVisibility()).length})),
    staticViews: main.querySelectorAll('figure.goldman-static-view img').length,
    contentImages: main.querySelectorAll('img[src^="_images/"]').length,
    widgets: document.querySelectorAll('.jupyter-widgets, script[type*="jupyter.widget"]').length,
    errorBoxes: Array.from(main.querySelectorAll('.output.error, .output.traceback, .system-message, .output.stderr'))
                  .map(e => e.textContent.slice(0, 120)),
    runBox: Array.from(main.querySelectorAll('.admonition')).filter(a => /Run it on your machine/.test(a.textContent))
              .map(a => a.textContent),
    prev: (document.querySelector('a.left-prev') || {}).href || null,
    next: (document.querySelector('a.right-next') || {}).href || null,
    searchBox: !!document.querySelector('.search-button-field, form.bd-search input[name="q"]'),
  };
}"""


@pytest.mark.parametrize("stem", PAGES)
def test_site_page(browser_page, site, stem):
    page = browser_page
    outside = _open(page, f"{site['url']}/{stem}.html")
    facts = await_js(page, PAGE_FACTS, what="the page's images and formulas")
    problems: list[str] = []
    if outside:
        problems.append(f"requests outside 127.0.0.1 (the site must work offline): {outside[:5]}")
    # images decode and say what they show
    for img in facts["images"]:
        alt = (img["alt"] or "").strip()
        if img["width"] == 0:
            problems.append(f"image does not decode: {img['src']}")
        if not alt or re.fullmatch(r"(?i)(png|image|img|figure|picture|[0-9a-f]{16,}.*|.*\.(png|svg|jpe?g))", alt):
            problems.append(f"image without meaningful alt text ({alt!r}): {img['src']}")
        elif img["content"] and len(alt.split()) < 4:
            problems.append(f"alt text too short to say what the picture shows ({alt!r}): {img['src']}")
    # mathematics typeset, none left raw
    if facts["untypeset"]:
        problems.append(f"{len(facts['untypeset'])} formulas not typeset, e.g. {facts['untypeset'][:3]}")
    if facts["mathErrors"]:
        problems.append(f"MathJax errors: {facts['mathErrors'][:3]}")
    raw = [facts["text"][max(0, m.start() - 40):m.end() + 40] for m in RAW_MATH.finditer(facts["text"])]
    if raw:
        problems.append(f"{len(raw)} raw LaTeX fragments left in the text, e.g. {raw[:3]}")
    # internal links and anchors resolve
    for href in sorted(set(facts["links"])):
        parts = urlsplit(href)
        if f"{parts.scheme}://{parts.netloc}" != site["url"]:
            continue
        target = site["html"] / unquote(parts.path).lstrip("/")
        if target.is_dir():
            target = target / "index.html"
        if not target.is_file():
            problems.append(f"broken link: {href}")
        elif parts.fragment and target.suffix == ".html" and unquote(parts.fragment) not in _ids(target):
            problems.append(f"missing anchor: {href}")
    # no widget, no error box; every stored picture shown, interactive views captioned as such
    nb = _notebook_facts(stem)
    if facts["widgets"]:
        problems.append(f"{facts['widgets']} widget elements or widget scripts on a static page")
    if facts["errorBoxes"]:
        problems.append(f"error boxes: {facts['errorBoxes'][:3]}")
    for marker in ("[interactive view:", "Canvas(", "Traceback"):
        if marker in facts["text"]:
            problems.append(f"{marker!r} shown as text")
    if facts["contentImages"] != nb["images"]:
        problems.append(f"{facts['contentImages']} pictures on the page, the notebook stores {nb['images']}")
    if facts["staticViews"] != nb["views"]:
        problems.append(f"{facts['staticViews']} interactive views shown as their picture, the notebook has {nb['views']}")
    # worked solutions: all there, all closed, nothing of them visible
    if len(facts["details"]) != nb["solutions"]:
        problems.append(f"{len(facts['details'])} collapsed blocks, the notebook has {nb['solutions']} worked solutions")
    for d in facts["details"]:
        if d["open"] or d["visible"] or not d["summary"] or not d["body"]:
            problems.append(f"a worked solution is open, visible or empty: {d['summary']!r} {d['body'][:80]!r}")
    # launch buttons for this very notebook, and the box with the two commands
    notebook = f"course/{stem}.ipynb"
    assert (REPO / notebook).is_file()
    binder = [h for h in facts["links"] if h.startswith(BINDER + "/")]
    hub = [h for h in facts["links"] if h.startswith(HUB + "/")]
    if binder != [f"{BINDER}/v2/gh/example-org/goldman-course/{BRANCH}?urlpath=lab/tree/{notebook}"]:
        problems.append(f"Binder launch link: {binder}")
    if len(hub) != 1:
        problems.append(f"JupyterHub launch links: {hub}")
    else:
        u = urlsplit(hub[0])
        q = {k: v[0] for k, v in parse_qs(u.query).items()}
        if (u.path, q) != ("/hub/user-redirect/git-pull",
                           {"repo": REPO_URL, "branch": BRANCH, "urlpath": f"lab/tree/goldman-course/{notebook}"}):
            problems.append(f"JupyterHub (nbgitpuller) link: {hub[0]}")
    if len(facts["runBox"]) != 1 or not all(s in facts["runBox"][0] for s in ("make lab", "make test", REPO_URL)):
        problems.append(f"the 'Run it on your machine' box: {facts['runBox']}")
    # previous / next follow the course: map, 1, 2, ..., 30
    i = PAGES.index(stem)
    want_prev = f"{site['url']}/{PAGES[i - 1]}.html" if i else None
    want_next = f"{site['url']}/{PAGES[i + 1]}.html" if i + 1 < len(PAGES) else None
    if (facts["prev"], facts["next"]) != (want_prev, want_next):
        problems.append(f"previous/next links {facts['prev']}, {facts['next']}; expected {want_prev}, {want_next}")
    if stem != "index" and not re.match(rf"Chapter {int(stem[:2])}\b", facts["title"]):
        problems.append(f"page title {facts['title']!r}")
    if not facts["searchBox"]:
        problems.append("no search box")
    if page.console_errors:
        problems.append(f"console errors: {page.console_errors[:5]}")
    if stem in ("index", "24_bezier_curves_and_surfaces"):
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        page.screenshot(path=str(SCREENSHOTS / f"site-{stem}.png"))
    assert not problems, f"{stem}.html:\n  " + "\n  ".join(problems)

    # Opening a worked solution shows it (the closed check above can fail).
    if facts["details"]:
        first = page.locator("article.bd-article details").first
        first.locator("summary").click()
        page.wait_for_function("() => { const d = document.querySelector('article.bd-article details');"
                               " return d.open && Array.from(d.querySelectorAll(':scope > :not(summary)'))"
                               ".some(c => c.checkVisibility()); }", timeout=10_000)


def test_site_navigation_lists_the_four_parts(browser_page, site):
    """The sidebar holds the book's four parts and the thirty chapters, in order, with their numbers."""
    page = browser_page
    _open(page, f"{site['url']}/index.html")
    nav = page.evaluate("""() => {
      const nav = document.querySelector('nav.bd-links');
      return {captions: Array.from(nav.querySelectorAll('p.caption')).map(p => p.textContent.trim()),
              links: Array.from(nav.querySelectorAll('a.reference')).map(a => [a.textContent.trim(), a.getAttribute('href')])};
    }""")
    assert [c.split(" — ")[0] for c in nav["captions"]] == ["Part I", "Part II", "Part III", "Part IV"], nav["captions"]
    chapters = [(t, h) for t, h in nav["links"] if re.match(r"\d\d_", h)]
    assert [h for _, h in chapters] == [f"{s}.html" for s in PAGES[1:]]
    assert [int(t.split(".")[0]) for t, _ in chapters] == list(range(1, len(PAGES)))
    assert not page.console_errors, page.console_errors


@pytest.mark.parametrize("query, stem", [("de Casteljau", "24_bezier_curves_and_surfaces"),
                                         ("quaternion", "15_quaternions")])
def test_site_search(browser_page, site, query, stem):
    """Sphinx's search (its index is a static file) finds the chapter, typed into the search box."""
    if not (COURSE / f"{stem}.ipynb").exists():
        pytest.skip(f"{stem} is not in the course")
    page = browser_page
    outside = _open(page, f"{site['url']}/index.html")
    page.keyboard.press("Control+k")           # the theme's search dialog, as a reader opens it
    box = page.locator("#pst-search-dialog input[name='q'], .search-button__search-container input[name='q']").first
    box.fill(query)
    box.press("Enter")
    page.wait_for_url("**/search.html?q=*")
    page.wait_for_function("() => { const s = document.querySelector('#search-results .search-summary, "
                           "#search-results p'); return s && /found|did not match/.test(s.textContent); }",
                           timeout=60_000)
    hits = page.evaluate("() => Array.from(document.querySelectorAll('#search-results ul.search li a'))"
                         ".map(a => a.getAttribute('href'))")
    assert any(h.split("#")[0].split("?")[0] == f"{stem}.html" for h in hits), f"{query!r} found {hits}"
    # the excerpts under the results quote the chapters, never a worked solution
    page.wait_for_function("() => Array.from(document.querySelectorAll('#search-results ul.search li'))"
                           ".every(li => li.querySelector('p.context'))", timeout=60_000)
    excerpts = page.evaluate("() => Array.from(document.querySelectorAll('#search-results ul.search li p.context'))"
                             ".map(p => p.textContent)")
    solutions = " ".join(s for h in hits for s in _solution_texts(h.split("#")[0].split("?")[0]))
    leaked = [e for e in excerpts if any(" ".join(w) in solutions for w in _windows(e.split(), 8))]
    assert not leaked, f"search excerpts quote worked solutions: {leaked}"
    assert not outside and not page.console_errors, (outside, page.console_errors)


def _windows(words: list[str], n: int):
    return [words[i:i + n] for i in range(max(0, len(words) - n + 1))]


@functools.lru_cache(maxsize=None)
def _solution_texts(page: str) -> tuple[str, ...]:
    """The text of each worked solution of a built page, whitespace normalised."""
    stem = page.removesuffix(".html")
    if not (COURSE / f"{stem}.ipynb").exists():
        return ()
    html = (OUT / "html" / page).read_text(encoding="utf-8")
    blocks = re.findall(r"<details>(.*?)</details>", html, re.S)
    texts = []
    for block in blocks:
        text = re.sub(r"<[^>]+>", " ", block)
        text = re.sub(r"&[a-z]+;|&#\d+;", " ", text)
        texts.append(" ".join(text.split()))
    assert len(texts) == _notebook_facts(stem)["solutions"]
    return tuple(texts)

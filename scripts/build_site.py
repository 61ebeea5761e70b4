"""`make site`: the whole course as a static website, build/site/html/, with Jupyter Book 1.x.

Built from the notebooks' *stored* outputs (nothing is executed) and offline: Jupyter Book 1.x is
Sphinx + MyST-NB + sphinx-book-theme, all installed from PyPI, and its theme ships inside the
package (Jupyter Book 2.x fetches its theme when it builds, which fails without a network).
MathJax 3 is served from the site itself (fetched once from npm into build/site/vendor/, the
mechanism of ``make slides``), intersphinx is off, and no widget JavaScript is loaded.

What the build does, all into build/site/ (nothing here is committed):

* ``src/``: the book's source, generated from the course each time: ``_toc.yml`` from the course
  map (``course/index.ipynb`` is the home page; the thirty chapters in the book's four parts, as
  the map's tables list them), ``_config.yml`` with the settings below, and a copy of every
  notebook prepared for a static page: each interactive view shows the PNG it stores beside its
  widget (``build_slides.static_widgets``, the decks' function), with a caption saying it is
  interactive in the notebook; every picture gets alt text from the figure's title, the view's
  name or the caption above it, and the section it is in; a "Run it on your machine" box follows
  each title.  Worked solutions stay the collapsed ``<details>`` blocks of the notebook.
* ``html/``: the site (``python -m http.server -d build/site/html`` previews it).

Settings (make variables of the same name, or environment variables):

* ``SITE_REPO``: the repository the launch buttons open (default: this clone's ``origin``);
* ``SITE_BRANCH``: its branch (default ``main``);
* ``SITE_HUB``: a JupyterHub's address; when set, every chapter also gets a JupyterHub button, an
  nbgitpuller link that pulls the repository into the learner's own hub account;
* ``SITE_BINDER``: the BinderHub (default ``https://mybinder.org``).

Usage: python scripts/build_site.py [--out DIR] [--repo URL] [--branch B] [--hub URL] [--binder URL]
"""

from __future__ import annotations

import argparse
import ast
import json
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

import nbformat

sys.path.insert(0, str(Path(__file__).resolve().parent))
from build_slides import WIDGET_VIEW, ensure_vendor, static_widgets  # noqa: E402  (one home for both)

REPO = Path(__file__).resolve().parents[1]
COURSE = REPO / "course"
OUT = REPO / "build" / "site"
TITLE = "Computer Graphics and Geometric Modeling"
# Used only when this clone has no ``origin`` remote; the build then says so.
PLACEHOLDER_REPO = "https://github.com/OWNER/REPO"
DEFAULT_BINDER = "https://mybinder.org"
# MathJax 3 for Sphinx (its default MathJax major version); the "full" bundle holds every TeX
# extension, so nothing is fetched when a page uses one.
MATHJAX = {"mathjax": "3.2.2"}
MATHJAX_FILES = ["es5/tex-chtml-full.js", "es5/output/chtml/fonts/woff-v2"]
VIEW_LABEL = re.compile(r"^\[interactive view: (?P<label>.*?); run the notebook to use it\]$", re.S)
PART = re.compile(r"^##\s+(Part\s+[IVX]+\s+—\s+.+?)\s*$", re.M)
ROW = re.compile(r"^\|\s*(\d+)\s*\|\s*\[([^\]]+)\]\((\d\d_[a-z0-9_]+)\.ipynb\)", re.M)
STATIC = "site_static"   # the source's static folder, copied into html/_static/
# sphinx-external-toc loads sphinx-multitoc-numbering, which does not say it is safe for parallel
# reading: Sphinx then reads the notebooks in one process (and writes the pages in -j processes).
SERIAL_READ = re.compile(r"sphinx_multitoc_numbering extension does not declare|doing serial read")
HEADING = re.compile(r"^(#{1,6})\s+(.+?)\s*$", re.M)

SITE_CSS = """\
/* The course site: worked solutions as quiet collapsed boxes; pictures never wider than the text. */
details { border: 1px solid var(--pst-color-border); border-radius: .3rem; padding: .4rem .8rem;
          margin: .6rem 0 1rem; }
details > summary { cursor: pointer; font-weight: 600; color: var(--pst-color-primary); }
details[open] > summary { margin-bottom: .5rem; }
div.cell_output img { max-width: 100%; height: auto; }
/* printed text (problem statements, tables) wraps instead of running off the page */
div.cell_output div.output pre { white-space: pre-wrap; }
figure.goldman-static-view figcaption { font-size: .9em; color: var(--pst-color-text-muted); }
figure.goldman-static-view .caption-number { display: none; }
"""


SEARCH_JS = """\
// Search excerpts never quote a worked solution: Sphinx makes each result's excerpt from the text
// of the page, closed <details> blocks included, so they are taken out first.
(function () {
  function patch() {
    if (typeof Search === "undefined" || Search.goldmanPatched || typeof Search.htmlToText !== "function") return;
    const htmlToText = Search.htmlToText;
    Search.htmlToText = function (htmlString, anchor) {
      const doc = new DOMParser().parseFromString(htmlString, "text/html");
      doc.querySelectorAll("details").forEach(function (d) { d.remove(); });
      return htmlToText(doc.documentElement.outerHTML, anchor);
    };
    Search.goldmanPatched = true;
  }
  patch();
  document.addEventListener("DOMContentLoaded", patch);
})();
"""


# --- settings ----------------------------------------------------------------------------------

def git_origin() -> str | None:
    """This clone's ``origin`` as an https URL, or None."""
    try:
        url = subprocess.run(["git", "remote", "get-url", "origin"], cwd=REPO, capture_output=True,
                             text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None
    m = re.match(r"^(?:git@|ssh://git@)([^:/]+)[:/](.+?)(?:\.git)?/?$", url)
    if m:
        return f"https://{m.group(1)}/{m.group(2)}"
    return re.sub(r"\.git/?$", "", url) if url.startswith("https://") else None


def settings(repo: str = "", branch: str = "", hub: str = "", binder: str = "") -> dict:
    """The launch settings, each from its argument, else its environment variable, else the default."""
    repo = (repo or os.environ.get("SITE_REPO") or git_origin() or PLACEHOLDER_REPO).rstrip("/")
    return {
        "repo": re.sub(r"\.git$", "", repo),
        "branch": branch or os.environ.get("SITE_BRANCH") or "main",
        "hub": (hub or os.environ.get("SITE_HUB") or "").rstrip("/"),
        "binder": (binder or os.environ.get("SITE_BINDER") or DEFAULT_BINDER).rstrip("/"),
    }


# --- the table of contents, from the course map ------------------------------------------------

def course_parts(index: Path = COURSE / "index.ipynb") -> list[dict]:
    """The course map's parts: ``[{"caption": "Part I — ...", "chapters": [(n, title, stem), ...]}]``
    in the map's order."""
    nb = nbformat.read(index, as_version=4)
    parts = []
    for cell in nb.cells:
        if cell.cell_type != "markdown":
            continue
        heading = PART.search(cell.source)
        if heading:
            rows = [(int(n), title.strip(), stem) for n, title, stem in ROW.findall(cell.source)]
            parts.append({"caption": heading.group(1), "chapters": rows})
    return parts


def toc_yaml(parts: list[dict]) -> str:
    """Jupyter Book's ``_toc.yml``: the course map as the root, a part per book part, each chapter
    titled with its number in the book."""
    lines = ["# Generated by scripts/build_site.py from course/index.ipynb: do not edit.",
             "format: jb-book", "root: index", "parts:"]
    for part in parts:
        lines.append(f"  - caption: {json.dumps(part['caption'], ensure_ascii=False)}")
        lines.append("    chapters:")
        for n, title, stem in part["chapters"]:
            lines.append(f"      - file: {stem}")
            lines.append(f"        title: {json.dumps(f'{n}. {title}', ensure_ascii=False)}")
    return "\n".join(lines) + "\n"


def config_yaml(cfg: dict) -> str:
    """Jupyter Book's ``_config.yml`` (JSON is YAML)."""
    launch = {"notebook_interface": "jupyterlab", "binderhub_url": cfg["binder"], "thebe": False,
              "colab_url": "", "jupyterhub_url": cfg["hub"]}
    config = {
        "title": TITLE,
        "author": "the authors of the goldman_lib course",
        "copyright": "2026",
        "only_build_toc_files": True,
        "execute": {"execute_notebooks": "off"},
        "parse": {"myst_enable_extensions": ["dollarmath", "amsmath", "colon_fence"]},
        "html": {"use_repository_button": True, "use_issues_button": False, "use_edit_page_button": False,
                 "use_download_button": True, "home_page_in_navbar": True, "use_multitoc_numbering": False},
        "repository": {"url": cfg["repo"], "path_to_book": "course", "branch": cfg["branch"]},
        "launch_buttons": launch,
        "sphinx": {
            "recursive_update": True,     # the html_theme_options below add to Jupyter Book's
            "config": {
                # one search box (the sidebar's): pydata-sphinx-theme 0.17 would add a second in a
                # header bar above the page
                "html_theme_options": {"navbar_persistent": [], "navbar_end": []},
                # Jupyter Book's list without thebe (it would load from a CDN), hypothes.is comments,
                # intersphinx and the LaTeX helpers; githubpages writes .nojekyll, so GitHub Pages
                # serves the _static/ folder too.
                "extensions": ["myst_nb", "jupyter_book", "sphinx_external_toc", "sphinx_design",
                               "sphinx_copybutton", "sphinx_book_theme", "sphinx.ext.githubpages"],
                "html_context": {"default_mode": "auto"},     # light or dark as the reader's system is
                "html_favicon": f"{STATIC}/favicon.png",
                "myst_dmath_double_inline": True,               # $$...$$ inside a paragraph, as in Jupyter
                "mathjax_path": "mathjax/tex-chtml-full.js",   # under _static/: no CDN
                "intersphinx_mapping": {},                      # nothing fetched from other sites
                "nb_ipywidgets_js": {},                         # widgets show their PNG: no widget JS
                # not "_static": Jupyter Book would add every .js file in it (MathJax's too) to every page
                "html_static_path": [STATIC],
                "html_css_files": ["site.css"],
                "html_js_files": ["search-excerpts.js"],
                "numfig": False,
                "html_show_sphinx": False,
            },
        },
    }
    return "# Generated by scripts/build_site.py: do not edit.\n" + json.dumps(config, indent=1, ensure_ascii=False) + "\n"


# --- notebooks prepared for a static page ------------------------------------------------------

def _plain(markdown: str) -> str:
    """Markdown and TeX reduced to words a screen reader can say."""
    text = re.sub(r"\\(?:frac|tfrac|dfrac)\{([^{}]*)\}\{([^{}]*)\}", r"\1/\2", markdown)
    text = re.sub(r"\\(?:text|mathrm|mathbf|operatorname)\{([^{}]*)\}", r"\1", text)
    text = re.sub(r"\\(?:to|rightarrow)\b", " to ", text)
    text = re.sub(r"\\(?:cdot|times)\b", " × ", text)
    text = re.sub(r"\\(?:dots|ldots|cdots)\b", "…", text)
    text = re.sub(r"\\[,;:! ]|\\quad|\\qquad", " ", text)
    text = re.sub(r"\\([A-Za-z]+)", r"\1", text)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)          # links: their text
    text = re.sub(r"[$*`{}#>|]", "", text.replace("\\_", "_"))
    return re.sub(r"\s+", " ", text).strip()


def _first_sentence(markdown: str, limit: int = 220) -> str:
    body = "\n".join(line for line in markdown.splitlines() if not line.lstrip().startswith("#"))
    text = _plain(body)
    m = re.match(r"(.+?[.!?])(\s|$)", text)
    sentence = (m.group(1) if m else text).rstrip(":;")
    if len(sentence) > limit:
        sentence = sentence[:limit].rsplit(" ", 1)[0] + "…"
    return sentence


def figure_titles(source: str) -> list[str]:
    """The literal titles a cell gives its figure (``set_title("...")``, ``suptitle("...")``,
    ``title="..."``); f-strings and computed titles are left out."""
    code = "\n".join(line for line in source.splitlines() if not line.lstrip().startswith(("%", "!")))
    try:
        tree = ast.parse(code)
    except SyntaxError:
        return []
    titles = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        name = getattr(node.func, "attr", getattr(node.func, "id", ""))
        args = list(node.args[:1]) if name in ("set_title", "suptitle", "title") else []
        args += [kw.value for kw in node.keywords if kw.arg == "title"]
        for arg in args:
            if isinstance(arg, ast.Constant) and isinstance(arg.value, str) and arg.value.strip():
                titles.append(_plain(arg.value))
    return titles


def alt_text(*, label: str | None, titles: list[str], heading: str, before: str) -> str:
    """What a picture shows, for its alt attribute: the view's name or the figure's titles, else the
    sentence that introduces it; and the section it illustrates."""
    where = f"section “{heading}”" if heading else "this chapter"
    if label:
        return f"{_plain(label)}: the interactive view at its default settings ({where})"
    if titles:
        return f"{'; '.join(titles)} (figure in {where})"
    if before:
        return f"Figure in {where}: {before}"
    return f"Figure in {where}"


def run_locally_box(cfg: dict, notebook: str) -> str:
    """The "Run it on your machine" box that follows each page's title (MyST markdown)."""
    folder = cfg["repo"].rstrip("/").rsplit("/", 1)[-1]
    target = f"open `course/{notebook}`" if notebook != "index.ipynb" else "it opens on this course map"
    return (
        ":::{admonition} Run it on your machine\n:class: tip\n\n"
        "This page shows the notebook with its stored outputs: every interactive view appears as a "
        "picture. To move the sliders, launch it from the rocket button at the top of the page"
        + (" (Binder or your JupyterHub)" if cfg["hub"] else " (Binder)")
        + ", or run it on your own machine (Python 3.10+ and `make`):\n\n"
        f"```bash\ngit clone {cfg['repo']}\ncd {folder}\n"
        "make lab     # installs everything, opens JupyterLab\n"
        "make test    # runs every test\n```\n\n"
        f"then {target}.\n:::\n"
    )


FENCE = re.compile(r"^(```|~~~).*?^\1[ \t]*$", re.M | re.S)
MATH_SPAN = re.compile(r"\$\$.+?\$\$|(?<![\\$])\$(?!\$)[^$]+?(?<!\\)\$", re.S)


def one_line_math(markdown: str) -> str:
    """Each ``$...$`` and ``$$...$$`` span on one line, outside code fences.  Jupyter takes the
    mathematics out before it reads the markdown, MyST after: a formula's continuation line that
    starts with ``- `` or ``1. `` would otherwise become a list item and leave the formula raw."""
    def join(m: re.Match) -> str:
        span = m.group(0)
        return span if "\n\n" in span else re.sub(r"[ \t]*\n[ \t]*", " ", span)

    out, last = [], 0
    for fence in FENCE.finditer(markdown):
        out.append(MATH_SPAN.sub(join, markdown[last:fence.start()]))
        out.append(fence.group(0))
        last = fence.end()
    out.append(MATH_SPAN.sub(join, markdown[last:]))
    return "".join(out)


def prepare_notebook(nb: nbformat.NotebookNode, name: str, cfg: dict) -> dict:
    """Prepare a notebook for its static page, in place; returns counts for the build log."""
    labels = {}
    for i, cell in enumerate(nb.cells):
        for out in cell.get("outputs", []):
            data = out.get("data", {})
            if WIDGET_VIEW in data:
                m = VIEW_LABEL.match("".join(data.get("text/plain", "")).strip())
                if m:
                    labels[i] = m.group("label")
    static = static_widgets(nb)
    heading, before, images = "", "", 0
    for i, cell in enumerate(nb.cells):
        if cell.cell_type == "markdown":
            cell.source = one_line_math(cell.source)
            found = HEADING.findall(cell.source)
            if found:
                heading = _plain(found[-1][1])
            if "solution" not in cell.metadata.get("tags", []):
                before = _first_sentence(cell.source)
            continue
        if cell.cell_type != "code":
            continue
        image_outputs = [o for o in cell.get("outputs", []) if any(k.startswith("image/") for k in o.get("data", {}))]
        if not image_outputs:
            continue
        for out in image_outputs:
            html = "".join(out["data"].get("text/html", ""))
            if "<img " in html and "data:image/" in html:
                del out["data"]["text/html"]   # ipympl's fallback: the same PNG without alt text
        images += len(image_outputs)
        mystnb = cell.metadata.setdefault("mystnb", {})
        mystnb["image"] = {"alt": alt_text(label=labels.get(i), titles=figure_titles(cell.source),
                                           heading=heading, before=before)}
        if i in labels:   # an interactive view (a plain ipympl figure needs no caption)
            mystnb["figure"] = {"classes": "goldman-static-view", "caption":
                                f"Interactive in the notebook: *{labels[i]}*, shown here at its default "
                                "settings. Launch the notebook (rocket button, top of the page) to use it."}
    box = nbformat.v4.new_markdown_cell(run_locally_box(cfg, name))
    nb.cells.insert(1, box)
    return {"static_views": static, "images": images}


def favicon() -> bytes:
    """A 64x64 PNG: a cubic Bézier curve and its control polygon (the same bytes every build)."""
    import io

    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    ctrl = [(0.1, 0.15), (0.25, 0.95), (0.75, 0.95), (0.9, 0.15)]
    t = [i / 40 for i in range(41)]
    curve = [tuple((1 - s) ** 3 * a + 3 * s * (1 - s) ** 2 * b + 3 * s * s * (1 - s) * c + s ** 3 * d
                   for a, b, c, d in zip(*ctrl)) for s in t]
    fig = Figure(figsize=(1, 1), dpi=64)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_axis_off()
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    ax.plot(*zip(*ctrl), color="#999999", linewidth=1.5, marker="o", markersize=4)
    ax.plot(*zip(*curve), color="#1f5fa8", linewidth=4)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", transparent=True, metadata={"Software": None})
    return buf.getvalue()


def _write_if_changed(path: Path, data: bytes | str) -> None:
    data = data.encode() if isinstance(data, str) else data
    if not path.exists() or path.read_bytes() != data:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)


def write_source(src: Path, cfg: dict, quiet: bool = False) -> dict:
    """Write the book's source into ``src`` (unchanged files are left alone, so Sphinx rebuilds
    only what changed)."""
    parts = course_parts()
    chapters = [stem for part in parts for _, _, stem in part["chapters"]]
    existing = sorted(p.stem for p in COURSE.glob("[0-9][0-9]_*.ipynb"))
    if sorted(chapters) != existing:
        raise SystemExit(f"build_site: the course map lists {sorted(set(chapters) ^ set(existing))} "
                         "differently from course/ (tests/notebooks/test_course_index.py says how they must agree)")
    _write_if_changed(src / "_toc.yml", toc_yaml(parts))
    _write_if_changed(src / "_config.yml", config_yaml(cfg))
    _write_if_changed(src / STATIC / "site.css", SITE_CSS)
    _write_if_changed(src / STATIC / "favicon.png", favicon())
    _write_if_changed(src / STATIC / "search-excerpts.js", SEARCH_JS)
    totals = {"static_views": 0, "images": 0}
    for stem in ["index", *chapters]:
        nb = nbformat.read(COURSE / f"{stem}.ipynb", as_version=4)
        for key, n in prepare_notebook(nb, f"{stem}.ipynb", cfg).items():
            totals[key] += n
        _write_if_changed(src / f"{stem}.ipynb", nbformat.writes(nb))
    keep = {f"{s}.ipynb" for s in ["index", *chapters]} | {"_toc.yml", "_config.yml", STATIC, "conf.py"}
    for stale in src.iterdir():
        if stale.name not in keep:
            shutil.rmtree(stale) if stale.is_dir() else stale.unlink()
    return totals


def vendor_mathjax(out: Path, src: Path, quiet: bool = False) -> None:
    """MathJax 3 from npm (once, into ``out/vendor``), copied into the site's ``_static/mathjax``."""
    vendor = ensure_vendor(out, quiet=quiet, packages=MATHJAX)
    root = vendor / "node_modules" / "mathjax"
    target = src / STATIC / "mathjax"
    for rel in MATHJAX_FILES:
        source, dest = root / rel, target / Path(rel).relative_to("es5")
        if source.is_dir():
            for f in source.rglob("*"):
                if f.is_file():
                    _write_if_changed(dest / f.relative_to(source), f.read_bytes())
        else:
            _write_if_changed(dest, source.read_bytes())


def build(out: Path = OUT, cfg: dict | None = None, quiet: bool = False, jobs: str = "2") -> Path:
    """Build the site into ``out/html``; return that folder."""
    cfg = cfg or settings()
    start = time.monotonic()
    src = out / "src"
    src.mkdir(parents=True, exist_ok=True)
    totals = write_source(src, cfg, quiet=quiet)
    vendor_mathjax(out, src, quiet=quiet)
    bindir = Path(sys.executable).parent
    jb = shutil.which("jupyter-book", path=str(bindir)) or shutil.which("jupyter-book")
    if jb is None:
        raise SystemExit("build_site: jupyter-book is missing; install the site extra: pip install -e '.[site]'")
    # Jupyter Book 1.x turns _config.yml and _toc.yml into Sphinx's conf.py ...
    subprocess.run([jb, "config", "sphinx", str(src)], check=True, capture_output=True)
    # ... and Sphinx builds (called directly, to choose the output folder and the number of jobs).
    cmd = [sys.executable, "-m", "sphinx", "-b", "html", "-j", jobs, "-q", "-d", str(out / "doctrees"),
           str(src), str(out / "html")]
    # Offline for real: anything Sphinx or an extension tried to fetch would go to a closed port
    # and fail, and every warning fails the build.
    dead = "http://127.0.0.1:9"
    env = dict(os.environ, http_proxy=dead, https_proxy=dead, HTTP_PROXY=dead, HTTPS_PROXY=dead,
               no_proxy="", NO_PROXY="")
    result = subprocess.run(cmd, cwd=src, capture_output=True, text=True, env=env)
    warnings = [line for line in result.stderr.splitlines() if line.strip() and not SERIAL_READ.search(line)]
    if result.returncode != 0 or warnings:
        sys.stderr.write(result.stdout[-4000:] + "\n".join(warnings[-60:]) + "\n")
        raise SystemExit(f"build_site: sphinx-build reported {len(warnings)} warning line(s) "
                         f"(exit status {result.returncode})")
    if not quiet:
        html = out / "html"
        shown = html.relative_to(REPO) if html.is_relative_to(REPO) else html
        print(f"build_site: {shown}/index.html, {len(list(html.glob('[0-9][0-9]_*.html'))) + 1} pages, "
              f"{totals['images']} pictures ({totals['static_views']} interactive views as their static "
              f"picture), in {time.monotonic() - start:.0f} s")
        print(f"  launch buttons: repository {cfg['repo']} branch {cfg['branch']}; Binder {cfg['binder']}; "
              + (f"JupyterHub {cfg['hub']}" if cfg["hub"] else "no JupyterHub (set SITE_HUB=https://your.hub)"))
        if cfg["repo"] == PLACEHOLDER_REPO:
            print(f"  this clone has no 'origin' remote: the launch buttons point at {PLACEHOLDER_REPO}; "
                  "set SITE_REPO=https://github.com/<owner>/<repo>")
        print(f"  preview: python -m http.server -d {shown}  (then open http://127.0.0.1:8000/)")
    return out / "html"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", type=Path, default=OUT, help="output folder (default: build/site)")
    parser.add_argument("--repo", default="", help="repository URL for the launch buttons (SITE_REPO)")
    parser.add_argument("--branch", default="", help="its branch (SITE_BRANCH, default main)")
    parser.add_argument("--hub", default="", help="JupyterHub address for the nbgitpuller button (SITE_HUB)")
    parser.add_argument("--binder", default="", help=f"BinderHub address (SITE_BINDER, default {DEFAULT_BINDER})")
    parser.add_argument("-j", "--jobs", default="2", help="Sphinx processes (default 2)")
    args = parser.parse_args(argv)
    build(args.out.resolve(), settings(args.repo, args.branch, args.hub, args.binder), jobs=args.jobs)
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""`make slides`: an offline reveal.js deck per chapter, build/slides/NN_slug.slides.html.

Every script and style sheet the deck loads comes from a local copy in build/slides/vendor/,
installed once from the npm registry with ``npm install`` (later builds reuse it):

* reveal.js 4.x: nbconvert 7's reveal template is written for reveal.js 4 (its default is
  ``https://unpkg.com/reveal.js@4.0.2``; it loads ``dist/reveal.js``, ``dist/reveal.css``,
  ``dist/theme/<theme>.css`` and ``plugin/notes/notes.js``), so the newest 4.x is pinned;
* require.js (the template loads reveal.js through it), jQuery (the template's scroll helper),
  MathJax 2.7 (the template configures MathJax 2: ``MathJax.Hub``) for the LaTeX in markdown.

The template's mermaid import is dropped (no chapter uses mermaid) and so is the widget-manager
block: the notebooks store no widget state, and each widget output is replaced by the PNG that
every interactive view stores beside its widget view (``InteractiveView`` and ipympl both do), so
the deck shows the picture of the view at its default slider values.

Usage: python scripts/build_slides.py [notebook.ipynb ...]   (default: course/*.ipynb, index too)
"""

from __future__ import annotations

import argparse
import functools
import html
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import jinja2
import nbformat
from nbconvert import SlidesExporter

REPO = Path(__file__).resolve().parents[1]
OUT = REPO / "build" / "slides"
VENDOR_DIRNAME = "vendor"
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
WIDGET_STATE = "application/vnd.jupyter.widget-state+json"

# npm package -> version.  Changing a version here re-installs the vendor directory.
VENDOR_PACKAGES = {
    "reveal.js": "4.6.0",
    "requirejs": "2.3.7",
    "jquery": "3.7.1",
    "mathjax": "2.7.9",
}

# The slide size: 16:9, a projector's shape.  At 1280x720 the deck's text and code have the size
# they had at reveal.js's default 960x700 (scale 1), and the code gets the width the 4:3 slide left
# empty on either side.
SLIDE_WIDTH, SLIDE_HEIGHT = 1280, 720

# Code and outputs wrap inside the slide instead of running off its right edge (at 960x700, 460 of
# 958 code blocks did).  Each line of a <pre> is its own block (see wrap_pre_lines), with a hanging
# indent: a wrapped line goes on 4 characters right of its own indentation, so the structure of the
# code stays visible.  Prompts ("In [3]:") are hidden: on a slide they only take width.
DECK_CSS = """
.reveal .slides pre { white-space: pre-wrap; overflow-wrap: anywhere; box-sizing: border-box; max-width: 100%; }
.reveal .slides pre code { white-space: inherit; overflow: visible; max-height: none; }
.reveal .slides pre .goldman-line { display: block; min-height: 1lh;
  padding-left: calc((var(--goldman-indent, 0) + 4) * 1ch);
  text-indent: calc((var(--goldman-indent, 0) + 4) * -1ch); }
.reveal .slides .jp-InputPrompt, .reveal .slides .jp-OutputPrompt { display: none; }
.reveal .slides .jp-Cell, .reveal .slides .jp-Cell-inputWrapper, .reveal .slides .jp-Cell-outputWrapper,
.reveal .slides .jp-InputArea, .reveal .slides .jp-InputArea-editor, .reveal .slides .jp-OutputArea,
.reveal .slides .jp-OutputArea-child, .reveal .slides .jp-OutputArea-output {
  min-width: 0; max-width: 100%; box-sizing: border-box; }
.reveal .slides .jp-RenderedHTMLCommon img, .reveal .slides .jp-OutputArea-output img { max-width: 100%; height: auto; }
.reveal .slides .jp-RenderedHTMLCommon table { display: block; max-width: 100%; overflow-x: auto; }
"""

# The deck template: nbconvert's reveal template without the CDN-only blocks (plus DECK_CSS).
_TEMPLATE = """{%- extends 'reveal/index.html.j2' -%}
{%- block html_head_js_mermaidjs -%}{%- endblock html_head_js_mermaidjs -%}
{% block jupyter_widgets %}{% endblock jupyter_widgets %}
"""
_TEMPLATE_CSS = """{%- block html_head_css -%}
<style type="text/css">""" + DECK_CSS + """</style>
{%- endblock html_head_css -%}
"""
_TEMPLATE_NAME = "goldman_offline_slides.html.j2"


def ensure_vendor(out: Path = OUT, quiet: bool = False, packages: dict[str, str] | None = None) -> Path:
    """Install reveal.js, require.js, jQuery and MathJax (or the npm ``packages`` given, name ->
    version: the site's MathJax) into ``out/vendor`` unless the same versions are already there;
    return the vendor directory."""
    packages = VENDOR_PACKAGES if packages is None else packages
    vendor = out / VENDOR_DIRNAME
    stamp = vendor / "goldman-vendor.json"
    wanted = json.dumps(packages, sort_keys=True)
    modules = vendor / "node_modules"
    if stamp.exists() and stamp.read_text() == wanted and all((modules / p).is_dir() for p in packages):
        return vendor
    npm = shutil.which("npm")
    if npm is None:
        raise SystemExit("build_slides: npm is needed once to fetch reveal.js, require.js, jQuery and "
                         "MathJax into build/slides/vendor (Debian: sudo apt-get install npm)")
    vendor.mkdir(parents=True, exist_ok=True)
    (vendor / "package.json").write_text(json.dumps(
        {"name": "goldman-slides-vendor", "private": True, "description": "local copies for the offline decks"},
        indent=1))
    specs = [f"{name}@{version}" for name, version in packages.items()]
    if not quiet:
        print(f"build_slides: fetching {' '.join(specs)} into {vendor.relative_to(REPO)} (once)")
    subprocess.run([npm, "install", "--prefix", str(vendor), "--no-audit", "--no-fund", "--no-save",
                    "--ignore-scripts", "--loglevel=error", *specs], check=True)
    missing = [p for p in packages if not (modules / p).is_dir()]
    if missing:
        raise SystemExit(f"build_slides: npm did not install {missing}")
    stamp.write_text(wanted)
    return vendor


@functools.lru_cache(maxsize=4)
def _exporter(vendor_url: str, fit: bool = True) -> SlidesExporter:
    """A reveal.js exporter whose every script and style sheet is under ``vendor_url`` (made once
    and reused for every deck).  ``fit=False`` gives the deck as it was before code wrapped: no
    DECK_CSS, reveal.js's default 960x700 slide (the browser test's check that its measure fails)."""
    nm = f"{vendor_url}/node_modules"
    exporter = SlidesExporter(
        extra_loaders=[jinja2.DictLoader({_TEMPLATE_NAME: _TEMPLATE + (_TEMPLATE_CSS if fit else "")})],
        template_file=_TEMPLATE_NAME,
        reveal_url_prefix=f"{nm}/reveal.js",
        reveal_theme="white",
        reveal_scroll=True,
        reveal_width=str(SLIDE_WIDTH if fit else 960),
        reveal_height=str(SLIDE_HEIGHT if fit else 700),
        require_js_url=f"{nm}/requirejs/require.js",
        jquery_url=f"{nm}/jquery/dist/jquery.min.js",
        mathjax_url=f"{nm}/mathjax/MathJax.js?config=TeX-AMS_CHTML-full,Safe",
        jupyter_widgets_base_url="",
        widget_renderer_url="",
    )
    exporter.mermaid_js_url = ""
    exporter.mermaid_layout_elk_js_url = ""
    return exporter


def static_widgets(nb: nbformat.NotebookNode) -> int:
    """Replace live widget views by their stored static image: drop saved widget state and the
    widget-view mimetype of every output that also carries an image.  Returns how many outputs
    now show their PNG instead of a widget.  Widget outputs without an image (a bare slider) are
    dropped entirely, since they cannot show anything offline."""
    nb.metadata.pop("widgets", None)
    replaced = 0
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        kept = []
        for out in cell.get("outputs", []):
            data = out.get("data", {})
            if WIDGET_VIEW in data:
                data.pop(WIDGET_VIEW)
                data.pop(WIDGET_STATE, None)
                if any(k.startswith("image/") for k in data):
                    replaced += 1
                    data.pop("text/plain", None)   # the "[interactive view ...]" placeholder
                else:
                    continue
            kept.append(out)
        cell.outputs = kept
    return replaced


_PRE = re.compile(r"(<pre\b[^>]*>)(.*?)(</pre>)", re.S)
_TAG_OR_NEWLINE = re.compile(r"(<(/?)([a-zA-Z][\w-]*)\b[^>]*>|\n)")


def _wrap_lines(body: str) -> str:
    """The content of one <pre>, each line in a <span class="goldman-line"> (with its indentation
    in --goldman-indent, in characters).  Elements open across a line end (a highlighted string or
    docstring spanning lines) are closed before it and opened again after it."""
    lines, current, stack = [], [], []
    pos = 0
    for m in _TAG_OR_NEWLINE.finditer(body):
        current.append(body[pos:m.start()])
        pos = m.end()
        if m.group(0) == "\n":
            current.extend(f"</{name}>" for name, _ in reversed(stack))
            lines.append("".join(current))
            current = [tag for _, tag in stack]
        elif m.group(2):                                  # a closing tag
            if stack and stack[-1][0] == m.group(3).lower():
                stack.pop()
            current.append(m.group(0))
        else:
            if not m.group(0).endswith("/>") and m.group(3).lower() not in ("br", "img", "hr", "wbr"):
                stack.append((m.group(3).lower(), m.group(0)))
            current.append(m.group(0))
    current.append(body[pos:])
    last = "".join(current)
    if re.sub(r"<[^>]*>", "", last):                      # text after the last newline
        lines.append(last)
    elif lines:
        lines[-1] += last                                 # only tags: keep them (nothing to show)
    out = []
    for line in lines:
        text = html.unescape(re.sub(r"<[^>]*>", "", line))
        indent = len(text) - len(text.lstrip(" "))
        style = f' style="--goldman-indent:{indent}"' if indent else ""
        out.append(f'<span class="goldman-line"{style}>{line}</span>')
    return "".join(out)


def wrap_pre_lines(page: str) -> str:
    """Every <pre> of the deck (code, outputs, code in markdown) with one block per line, for the
    hanging indent of DECK_CSS."""
    return _PRE.sub(lambda m: m.group(1) + _wrap_lines(m.group(2)) + m.group(3), page)


def build_deck(notebook: Path | str, out: Path = OUT, quiet: bool = False, *, fit: bool = True,
               name: str | None = None) -> Path:
    """Write ``out/<stem>.slides.html`` (or ``out/<name>``) for ``notebook`` and return its path.
    ``fit=False`` leaves out what makes code and outputs fit the slide (see ``_exporter``)."""
    notebook = Path(notebook).resolve()
    vendor = ensure_vendor(out, quiet=quiet)
    nb = nbformat.read(notebook, as_version=4)
    n_images = static_widgets(nb)
    exporter = _exporter(vendor.relative_to(out).as_posix(), fit)
    body, _ = exporter.from_notebook_node(nb, resources={"metadata": {"name": notebook.stem,
                                                                      "path": str(notebook.parent)}})
    target = out / (name or f"{notebook.stem}.slides.html")
    target.write_text(wrap_pre_lines(body) if fit else body, encoding="utf-8")
    if not quiet:
        shown = target.relative_to(REPO) if target.is_relative_to(REPO) else target
        print(f"wrote {shown} ({n_images} widget views shown as their static image)")
    return target


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("notebooks", nargs="*", help="notebooks to convert (default: course/*.ipynb)")
    parser.add_argument("--out", type=Path, default=OUT, help="output directory (default: build/slides)")
    args = parser.parse_args(argv)
    paths = [Path(p) for p in args.notebooks] or sorted((REPO / "course").glob("*.ipynb"))
    if not paths:
        print("build_slides: no notebooks in course/")
        return 0
    for path in paths:
        build_deck(path, out=args.out.resolve())
    return 0


if __name__ == "__main__":
    sys.exit(main())

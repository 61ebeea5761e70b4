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
import json
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

# The deck template: nbconvert's reveal template without the CDN-only blocks.
_TEMPLATE = """{%- extends 'reveal/index.html.j2' -%}
{%- block html_head_js_mermaidjs -%}{%- endblock html_head_js_mermaidjs -%}
{% block jupyter_widgets %}{% endblock jupyter_widgets %}
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


def _exporter(vendor_url: str) -> SlidesExporter:
    """A reveal.js exporter whose every script and style sheet is under ``vendor_url``."""
    nm = f"{vendor_url}/node_modules"
    exporter = SlidesExporter(
        extra_loaders=[jinja2.DictLoader({_TEMPLATE_NAME: _TEMPLATE})],
        template_file=_TEMPLATE_NAME,
        reveal_url_prefix=f"{nm}/reveal.js",
        reveal_theme="white",
        reveal_scroll=True,
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


def build_deck(notebook: Path | str, out: Path = OUT, quiet: bool = False) -> Path:
    """Write ``out/<stem>.slides.html`` for ``notebook`` and return its path."""
    notebook = Path(notebook).resolve()
    vendor = ensure_vendor(out, quiet=quiet)
    nb = nbformat.read(notebook, as_version=4)
    n_images = static_widgets(nb)
    exporter = _exporter(vendor.relative_to(out).as_posix())
    body, _ = exporter.from_notebook_node(nb, resources={"metadata": {"name": notebook.stem,
                                                                      "path": str(notebook.parent)}})
    target = out / f"{notebook.stem}.slides.html"
    target.write_text(body, encoding="utf-8")
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

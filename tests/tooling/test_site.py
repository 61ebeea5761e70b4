"""scripts/build_site.py without building: the table of contents comes from the course map and
stays in step with course/, each notebook is prepared for a static page (no widget left, alt
text on every picture, solutions untouched and closed), and the launch settings.

The built site itself is opened page by page in Chromium by tests/browser/test_course_site.py.
"""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[2]
COURSE = ROOT / "course"
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"


@pytest.fixture(scope="module")
def build_site():
    spec = importlib.util.spec_from_file_location("build_site", ROOT / "scripts" / "build_site.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


CFG = {"repo": "https://github.com/example-org/goldman-course", "branch": "b", "hub": "", "binder": "https://mybinder.org"}


def test_toc_has_the_four_parts_and_every_chapter_in_order(build_site):
    parts = build_site.course_parts()
    assert [p["caption"].split(" — ")[0] for p in parts] == ["Part I", "Part II", "Part III", "Part IV"]
    chapters = [c for p in parts for c in p["chapters"]]
    assert [n for n, _, _ in chapters] == list(range(1, 31))
    # the generated list is the course: one entry per chapter notebook, each of them
    assert [stem for _, _, stem in chapters] == sorted(p.stem for p in COURSE.glob("[0-9][0-9]_*.ipynb"))
    # the book's part boundaries (BOOK_TOC: parts start at chapters 1, 9, 16, 24)
    assert [p["chapters"][0][0] for p in parts] == [1, 9, 16, 24]
    toc = build_site.toc_yaml(parts)
    assert toc.count("- file: ") == 30 and "root: index" in toc
    assert '- file: 24_bezier_curves_and_surfaces\n        title: "24. Bézier curves and surfaces"' in toc


@pytest.mark.parametrize("stem", ["24_bezier_curves_and_surfaces", "15_quaternions", "index"])
def test_prepared_notebook_is_static_with_alt_text(build_site, stem):
    original = nbformat.read(COURSE / f"{stem}.ipynb", as_version=4)
    nb = nbformat.read(COURSE / f"{stem}.ipynb", as_version=4)
    build_site.prepare_notebook(nb, f"{stem}.ipynb", CFG)
    views = sum(WIDGET_VIEW in o.get("data", {}) and "image/png" in o.get("data", {})
                for c in original.cells for o in c.get("outputs", []))
    images = 0
    for cell in nb.cells:
        for out in cell.get("outputs", []):
            assert WIDGET_VIEW not in out.get("data", {})
            if "image/png" in out.get("data", {}):
                images += 1
                assert "text/html" not in out["data"], "ipympl's HTML fallback would hide the PNG and its alt"
                alt = cell.metadata["mystnb"]["image"]["alt"]
                assert len(alt.split()) >= 4 and not re.search(r"\$|\\[a-z]+|png\b", alt), alt
    assert "widgets" not in nb.metadata
    assert images >= views
    captions = [c.metadata["mystnb"]["figure"]["caption"] for c in nb.cells if "figure" in c.metadata.get("mystnb", {})]
    assert len(captions) == sum("[interactive view:" in "".join(o.get("data", {}).get("text/plain", ""))
                                for c in original.cells for o in c.get("outputs", []))
    # worked solutions: the same cells, still closed
    solutions = [c.source for c in nb.cells if "solution" in c.metadata.get("tags", [])]
    assert len(solutions) == sum("solution" in c.metadata.get("tags", []) for c in original.cells)
    assert all(s.lstrip().startswith("<details>") and "<details open" not in s for s in solutions)
    # the box with the README's two commands follows the title
    assert "Run it on your machine" in nb.cells[1].source and "make lab" in nb.cells[1].source
    assert CFG["repo"] in nb.cells[1].source


def test_alt_text_from_title_view_name_or_caption(build_site):
    src = 'fig, ax = style.new_axes()\nax.set_title("six points: through them", fontsize=10)\nfig.suptitle(f"level {n}")\nfig.canvas'
    assert build_site.figure_titles(src) == ["six points: through them"]
    assert build_site.figure_titles("%matplotlib widget\nplt.title('a ray and a torus')") == ["a ray and a torus"]
    alt = build_site.alt_text(label="de Casteljau explorer", titles=[], heading="24.2 The de Casteljau algorithm", before="")
    assert alt.startswith("de Casteljau explorer") and "24.2 The de Casteljau algorithm" in alt
    alt = build_site.alt_text(label=None, titles=[], heading="Ray tracing",
                              before=build_site._first_sentence("The scene: a mirror sphere ($k_r = 0.8$) and $\\frac{1}{2}$ light. More."))
    assert alt == "Figure in section “Ray tracing”: The scene: a mirror sphere (k_r = 0.8) and 1/2 light."


def test_multiline_formulas_are_joined_outside_code(build_site):
    md = "on $a$,\n   $$\\begin{pmatrix} s \\\\ t \\end{pmatrix}\n     - x,$$\n   and\n```\n$a\n- b$\n```\n"
    out = build_site.one_line_math(md)
    assert "$$\\begin{pmatrix} s \\\\ t \\end{pmatrix} - x,$$" in out      # no "- x" list item any more
    assert "```\n$a\n- b$\n```" in out                                       # code left alone


def test_launch_settings(build_site, monkeypatch):
    monkeypatch.setenv("SITE_REPO", "https://github.com/o/r.git")
    monkeypatch.setenv("SITE_HUB", "https://hub.example.edu/")
    monkeypatch.delenv("SITE_BRANCH", raising=False)
    monkeypatch.delenv("SITE_BINDER", raising=False)
    assert build_site.settings() == {"repo": "https://github.com/o/r", "branch": "main",
                                     "hub": "https://hub.example.edu", "binder": "https://mybinder.org"}
    assert build_site.settings(branch="dev", hub="https://h")["branch"] == "dev"
    config = build_site.config_yaml(build_site.settings())
    assert '"jupyterhub_url": "https://hub.example.edu"' in config and '"path_to_book": "course"' in config
    assert '"intersphinx_mapping": {}' in config and '"mathjax_path": "mathjax/tex-chtml-full.js"' in config

"""The course map lists all thirty chapters and links exactly the notebooks that exist."""

import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
COURSE = ROOT / "course"


def index_text():
    nb = json.loads((COURSE / "index.ipynb").read_text())
    return "\n".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown")


def test_index_lists_thirty_chapters_in_four_parts():
    text = index_text()
    rows = re.findall(r"^\| (\d+) \|", text, flags=re.M)
    assert [int(r) for r in rows] == list(range(1, 31))
    assert [p for p in ("Part I ", "Part II ", "Part III ", "Part IV ") if f"## {p}" in text] == \
        ["Part I ", "Part II ", "Part III ", "Part IV "]


def test_index_links_exactly_the_chapter_notebooks_that_exist():
    text = index_text()
    linked = set(re.findall(r"\]\((\d\d_[a-z0-9_]+\.ipynb)\)", text))
    existing = {p.name for p in COURSE.glob("[0-9][0-9]_*.ipynb")}
    assert linked == existing
    assert text.count("*(not yet written)*") == 30 - len(existing)


def test_no_empty_chapter_notebooks():
    for path in COURSE.glob("[0-9][0-9]_*.ipynb"):
        nb = json.loads(path.read_text())
        assert sum(c["cell_type"] == "code" for c in nb["cells"]) >= 5, f"{path.name} is nearly empty"

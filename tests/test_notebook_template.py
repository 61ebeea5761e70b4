"""Every chapter notebook follows the template of CONVENTIONS.md: title and motivation, "What you
will learn", one section per book section (from BOOK_OUTLINE.md), at least one interactive figure
with a static fallback image, Summary, Exercises with checkers and hidden worked solutions, slide
metadata, one matplotlib backend, and key results in checked text cells.
"""

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
CHAPTERS = sorted((ROOT / "course").glob("[0-9][0-9]_*.ipynb"))
OUTLINE = ROOT.parent / "shared" / "BOOK_OUTLINE.md"
WIDGET = "application/vnd.jupyter.widget-view+json"


def load(path):
    nb = json.loads(path.read_text())
    for cell in nb["cells"]:
        cell["text"] = "".join(cell["source"])
        cell["slide"] = cell["metadata"].get("slideshow", {}).get("slide_type")
        cell["tags"] = cell["metadata"].get("tags", [])
    return nb["cells"]


def headings(cells, level):
    return [m.group(1).strip() for c in cells if c["cell_type"] == "markdown"
            for m in re.finditer(rf"^{'#' * level} (.+)$", c["text"], re.M)]


def outline_sections(number):
    """Book sections of chapter ``number`` as listed in BOOK_OUTLINE.md (e.g. ['24.2', ...])."""
    for line in OUTLINE.read_text().splitlines():
        m = re.match(rf"^\| {number} \| `[^`]+` \| (.+?) \|", line)
        if m:
            return sorted(set(re.findall(rf"\b({number}\.\d+)\b", m.group(1))), key=lambda s: int(s.split(".")[1]))
    raise AssertionError(f"chapter {number} is not in BOOK_OUTLINE.md")


pytestmark = pytest.mark.parametrize("path", CHAPTERS, ids=[p.stem for p in CHAPTERS])


def test_title_motivation_and_learning_goals(path):
    cells = load(path)
    number = int(path.name[:2])
    first = cells[0]
    assert first["cell_type"] == "markdown" and first["slide"] == "slide"
    assert re.match(rf"# Chapter {number} — \S", first["text"]), "first cell must be '# Chapter N — title'"
    assert len(first["text"].split()) > 40, "the title cell needs a motivating paragraph"
    assert "What you will learn" in headings(cells, 2)


def test_a_section_per_book_section(path):
    if not OUTLINE.exists():
        pytest.skip(f"{OUTLINE} not found (the shared folder sits beside the repository)")
    number = int(path.name[:2])
    sections = headings(load(path), 2)
    for sec in outline_sections(number):
        assert any(h.startswith(sec + " ") for h in sections), f"no '## {sec} ...' section in {path.name}"


def test_summary_and_at_least_four_checked_exercises_with_hidden_solutions(path):
    cells = load(path)
    assert {"Summary", "Exercises"} <= set(headings(cells, 2))
    start = next(i for i, c in enumerate(cells) if c["text"].startswith("## Exercises"))
    exercise = [c for c in cells[start:] if c["cell_type"] == "code" and "solution" not in c["tags"]]
    solution = [c for c in cells[start:] if c["cell_type"] == "code" and "solution" in c["tags"]]
    assert len(exercise) >= 4 and len(solution) >= 4
    for c in exercise:
        assert re.search(r"^\w+ = None\b", c["text"], re.M), "an exercise cell starts from '... = None'"
        assert "Not answered yet" in json.dumps(c["outputs"]), "the stored exercise output is the checker's verdict"
    for c in solution:
        assert c["metadata"].get("jupyter", {}).get("source_hidden") is True, "worked solutions are hidden"
        assert "Correct:" in json.dumps(c["outputs"]), "each worked solution passes its own checker"
    assert all("nbval-check-output" in c["tags"] for c in exercise + solution)


def test_interactive_figures_carry_static_fallbacks(path):
    cells = load(path)
    widget_outputs = [o for c in cells if c["cell_type"] == "code" for o in c["outputs"] if WIDGET in o.get("data", {})]
    assert widget_outputs, "a chapter has at least one interactive figure"
    for out in widget_outputs:
        assert "image/png" in out["data"], "every widget output stores a static PNG beside it"


def test_one_matplotlib_backend_set_up_in_a_skipped_cell(path):
    cells = load(path)
    magics = [(i, m) for i, c in enumerate(cells) if c["cell_type"] == "code"
              for m in re.findall(r"^%matplotlib.*$", c["text"], re.M)]
    assert [m for _, m in magics] == ["%matplotlib widget"], "exactly one backend, ipympl, set once"
    assert cells[magics[0][0]]["slide"] == "skip"


def test_deck_metadata_and_checked_key_results(path):
    cells = load(path)
    assert sum(c["slide"] in ("slide", "subslide") for c in cells) >= 6
    assert all(c["slide"] != "-" for c in cells), "leave slide_type out instead of '-'"
    checked = [c for c in cells if "nbval-check-output" in c["tags"] and "solution" not in c["tags"]]
    assert len(checked) >= 8, "key results are printed in cells tagged nbval-check-output"

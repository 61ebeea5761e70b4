"""Every chapter notebook follows the template of CONVENTIONS.md: title and motivation, "What you
will learn", one section per book section (from BOOK_OUTLINE.md), at least one interactive figure
with a static fallback image, Summary, Exercises with checkers and hidden worked solutions, slide
metadata, one matplotlib backend, and key results in checked text cells.
"""

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CHAPTERS = sorted((ROOT / "course").glob("[0-9][0-9]_*.ipynb"))
# The repository's copy of the book outline (its chapter and section list); the shared folder's
# original, where it sits beside the clone, must agree with it (test_outline_copy_is_current).
OUTLINE = ROOT / "BOOK_OUTLINE.md"
SHARED_OUTLINE = ROOT.parent / "shared" / "BOOK_OUTLINE.md"
# Chapters whose book chapter ends with programming projects (CONVENTIONS, Practice).
PROJECT_CHAPTERS = {2, 6, 7, 8, 13, 15, 19, 20, 21, 22, 23, 25, 28, 29, 30}
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


def test_outline_copy_is_current():
    if not SHARED_OUTLINE.exists():
        pytest.skip("the shared folder is not beside this clone; the repository's BOOK_OUTLINE.md is used")
    assert SHARED_OUTLINE.read_text() == OUTLINE.read_text(), "copy ../shared/BOOK_OUTLINE.md to BOOK_OUTLINE.md"


chapter = pytest.mark.parametrize("path", CHAPTERS, ids=[p.stem for p in CHAPTERS])


@chapter
def test_title_motivation_and_learning_goals(path):
    cells = load(path)
    number = int(path.name[:2])
    first = cells[0]
    assert first["cell_type"] == "markdown" and first["slide"] == "slide"
    assert re.match(rf"# Chapter {number} — \S", first["text"]), "first cell must be '# Chapter N — title'"
    assert len(first["text"].split()) > 40, "the title cell needs a motivating paragraph"
    assert "What you will learn" in headings(cells, 2)


@chapter
def test_a_section_per_book_section(path):
    number = int(path.name[:2])
    sections = headings(load(path), 2)
    for sec in outline_sections(number):
        assert any(h.startswith(sec + " ") for h in sections), f"no '## {sec} ...' section in {path.name}"


@chapter
def test_summary_and_at_least_five_checked_exercises_with_collapsed_solutions(path):
    cells = load(path)
    assert {"Summary", "Exercises"} <= set(headings(cells, 2))
    start = next(i for i, c in enumerate(cells) if c["text"].startswith("## Exercises"))
    end = next((i for i, c in enumerate(cells) if c["text"].startswith("## Programming project")), len(cells))
    exercise = [c for c in cells[start:end] if c["cell_type"] == "code"
                and not re.fullmatch(r"ch\d\d\.deal_button\(\"\w+\"\)", c["text"].strip())]  # a Deal button
    solution = [c for c in cells[start:end] if "solution" in c["tags"]]
    assert len(exercise) >= 5 and len(solution) >= len(exercise), "five exercises or more, each with a solution"
    for c in exercise:
        assert re.search(r"^\w+ = None\b", c["text"], re.M), "an exercise cell starts from '... = None'"
        assert "Not answered yet" in json.dumps(c["outputs"]), "the stored exercise output is the checker's verdict"
        assert "nbval-check-output" in c["tags"]
    for c in solution:
        assert c["cell_type"] == "markdown" and c["text"].lstrip().startswith("<details"), (
            "a worked solution is a collapsed <details> block in markdown (tests/exercises/test_solutions.py)")


@chapter
def test_programming_project_where_the_book_has_them(path):
    number = int(path.name[:2])
    cells = load(path)
    starts = [i for i, c in enumerate(cells) if c["cell_type"] == "markdown"
              and re.match(r"## Programming project", c["text"])]
    if number not in PROJECT_CHAPTERS:
        return
    assert starts, f"chapter {number} ends with the book's programming projects: add '## Programming project'"
    body = cells[starts[0]:]
    code = [c for c in body if c["cell_type"] == "code"]
    starter = [c for c in code if re.search(r"^def \w+\(", c["text"], re.M) and '"""' in c["text"]]
    assert starter, "a starter cell with the function's signature and docstring"
    checks = [c for c in code if "check_" in c["text"] and "Not answered yet" in json.dumps(c["outputs"])]
    assert checks and all("nbval-check-output" in c["tags"] for c in checks), (
        "a check cell whose stored verdict is 'Not answered yet', tagged nbval-check-output")
    assert any("solution" in c["tags"] for c in body), "the reference solution, collapsed like any solution"


@chapter
def test_interactive_figures_carry_static_fallbacks(path):
    cells = load(path)
    widget_outputs = [o for c in cells if c["cell_type"] == "code" for o in c["outputs"] if WIDGET in o.get("data", {})]
    assert widget_outputs, "a chapter has at least one interactive figure"
    for out in widget_outputs:
        assert "image/png" in out["data"], "every widget output stores a static PNG beside it"


@chapter
def test_one_matplotlib_backend_set_up_in_a_skipped_cell(path):
    cells = load(path)
    magics = [(i, m) for i, c in enumerate(cells) if c["cell_type"] == "code"
              for m in re.findall(r"^%matplotlib.*$", c["text"], re.M)]
    assert [m for _, m in magics] == ["%matplotlib widget"], "exactly one backend, ipympl, set once"
    assert cells[magics[0][0]]["slide"] == "skip"


@chapter
def test_deck_metadata_and_checked_key_results(path):
    cells = load(path)
    assert sum(c["slide"] in ("slide", "subslide") for c in cells) >= 6
    assert all(c["slide"] != "-" for c in cells), "leave slide_type out instead of '-'"
    checked = [c for c in cells if "nbval-check-output" in c["tags"] and "solution" not in c["tags"]]
    assert len(checked) >= 8, "key results are printed in cells tagged nbval-check-output"


@pytest.mark.parametrize("path", sorted((ROOT / "course").glob("*.ipynb")), ids=lambda p: p.stem)
def test_no_stored_output_holds_a_memory_address(path):
    """Stored outputs are the same on every run: an object's repr with its address (``<contextlib.
    ExitStack at 0x7f…>``, left by a cell ending in ``plt.ioff()``) changes each time."""
    import re

    nb = json.loads(path.read_text())
    found = [f"cell {c.get('id')}: {m.group(0)}" for c in nb["cells"] if c["cell_type"] == "code"
             for o in c.get("outputs", []) for m in re.finditer(r"<[\w.]+ (?:object )?at 0x[0-9a-f]+>", json.dumps(o))]
    assert not found, f"{path.name}: outputs that change on every run: {found}"

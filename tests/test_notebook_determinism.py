"""Two runs of a notebook store identical text.

The stored outputs came from one clean run (`make outputs`); this test executes every course
notebook once more in a fresh kernel and compares every text output of every cell (stdout, plain
text, HTML, markdown) with the stored one.  Only widget model ids (random per run) and images are
left out.  A failure means a notebook is not deterministic or its outputs were not regenerated.
"""

import importlib.util
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "course").glob("*.ipynb"))
TEXT_TYPES = ("text/plain", "text/html", "text/markdown", "text/latex")

spec = importlib.util.spec_from_file_location("execute_notebooks", ROOT / "scripts" / "execute_notebooks.py")
execute_notebooks = importlib.util.module_from_spec(spec)
spec.loader.exec_module(execute_notebooks)


def text_outputs(nb):
    """[(cell index, output kind, text)] for every text output of every code cell (consecutive
    stream chunks merged: how a kernel splits printing into messages depends on timing)."""
    found = []
    for i, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        for out in execute_notebooks.coalesce_streams([dict(o) for o in cell.get("outputs", [])]):
            if out["output_type"] == "stream":
                found.append((i, out["name"], out["text"]))
            elif out["output_type"] == "error":
                found.append((i, "error", f"{out['ename']}: {out['evalue']}"))
            else:
                for kind in TEXT_TYPES:
                    if kind in out.get("data", {}):
                        text = out["data"][kind]
                        found.append((i, kind, "".join(text) if isinstance(text, list) else text))
    return found


@pytest.mark.notebooks
@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_a_second_run_stores_identical_text(path):
    stored = nbformat.read(path, as_version=4)
    fresh = execute_notebooks.execute(path)
    assert not [o for o in text_outputs(fresh) if o[1] == "error"], "the notebook raised an error"
    a, b = text_outputs(stored), text_outputs(fresh)
    for old, new in zip(a, b):
        assert old == new, f"cell {old[0]} {old[1]} differs between runs (run `make outputs`?)"
    assert len(a) == len(b), "the number of text outputs differs between runs (run `make outputs`?)"

"""Key results are the same on any CPU: a second run under another numpy SIMD dispatch stores the
same checked text.

The stored outputs came from one clean run (`make outputs`), and nbval compares the cells tagged
``nbval-check-output`` strictly.  A CPU with other vector instructions (or another BLAS kernel)
moves the last bits of floating-point results, so a checked cell that prints a residual to its last
bits passes here and fails elsewhere.  To catch that on one machine, this test executes every
notebook once more in a fresh kernel with numpy's dispatched SIMD extensions switched off
(``NPY_DISABLE_CPU_FEATURES``; the machine's OpenBLAS settings are left alone) and requires

* every checked cell to print exactly the stored text (the portable key results), and
* every other cell to produce the same kinds of output and no error (their text may differ in the
  last bits: they are explanations, not the regression baseline).

Only widget model ids (random per run) and images are left out.
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


def dispatched_simd_extensions() -> list[str]:
    """The SIMD extensions numpy found on this CPU and dispatches to at run time (not the baseline,
    which cannot be switched off)."""
    try:
        from numpy._core import _multiarray_umath as umath
    except ImportError:  # numpy 1.x
        from numpy.core import _multiarray_umath as umath
    features = umath.__cpu_features__
    return [name for name in umath.__cpu_dispatch__ if features.get(name)]


def text_outputs(nb, checked_only=False):
    """[(cell index, output kind, text)] for every text output of every code cell (consecutive
    stream chunks merged: how a kernel splits printing into messages depends on timing)."""
    found = []
    for i, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        if checked_only and "nbval-check-output" not in cell.metadata.get("tags", []):
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


def test_the_other_dispatch_is_a_real_change():
    import subprocess
    import sys

    found = dispatched_simd_extensions()
    if not found:
        pytest.skip("numpy dispatches no SIMD extension on this CPU: the baseline is the only code path")
    code = ("from numpy._core import _multiarray_umath as u; "
            "print(sum(bool(u.__cpu_features__.get(n)) for n in u.__cpu_dispatch__))")
    env = {"NPY_DISABLE_CPU_FEATURES": ",".join(found), "PATH": ""}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "0", "NPY_DISABLE_CPU_FEATURES did not switch the dispatched extensions off"


@pytest.mark.notebooks
@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_checked_text_is_the_same_under_another_simd_dispatch(path, monkeypatch):
    found = dispatched_simd_extensions()
    if found:
        monkeypatch.setenv("NPY_DISABLE_CPU_FEATURES", ",".join(found))
    stored = nbformat.read(path, as_version=4)
    fresh = execute_notebooks.execute(path)
    assert not [o for o in text_outputs(fresh) if o[1] == "error"], "the notebook raised an error"
    a, b = text_outputs(stored, checked_only=True), text_outputs(fresh, checked_only=True)
    for old, new in zip(a, b):
        assert old == new, (f"checked cell {old[0]} prints {new[2]!r} under another SIMD dispatch, "
                            f"{old[2]!r} stored: print a bound or a rounded value (or run `make outputs`)")
    assert len(a) == len(b), "the number of checked outputs differs between runs (run `make outputs`?)"
    kinds = [(i, kind) for i, kind, _ in text_outputs(stored)]
    assert kinds == [(i, kind) for i, kind, _ in text_outputs(fresh)], (
        "the cells' outputs differ in kind between runs (run `make outputs`?)")

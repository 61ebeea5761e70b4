"""Key results are the same on any CPU: a run under another numpy SIMD dispatch prints the same
checked text as the stored outputs.

The stored outputs came from one clean run (`make outputs`, with numpy's normal dispatch), and nbval
compares the cells tagged ``nbval-check-output`` strictly.  A CPU with other vector instructions (or
another BLAS kernel) moves the last bits of floating-point results, so a checked cell that prints a
residual to its last bits passes here and fails elsewhere.  To catch that on one machine, notebooks
are executed in a fresh kernel with numpy's dispatched SIMD extensions switched off
(``NPY_DISABLE_CPU_FEATURES``; the machine's OpenBLAS settings are left alone), and

* every checked cell must print exactly the stored text (the portable key results), and
* every other cell must produce the same kinds of output and no error (their text may differ in the
  last bits: they are explanations, not the regression baseline).

Only widget model ids (random per run) and images are left out.

In ``make test`` nbval itself runs its kernels under that dispatch (see the root ``conftest.py``):
each notebook is executed once, for nbval and this check together, and the stand-alone re-run below
is left out.  It runs when nbval does not execute the notebook in the same session, for example
``pytest tests/notebooks/test_notebook_determinism.py -k 16_`` while writing chapter 16.
"""

import importlib.util
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = sorted((ROOT / "course").glob("*.ipynb"))

spec = importlib.util.spec_from_file_location("execute_notebooks", ROOT / "scripts" / "execute_notebooks.py")
run = importlib.util.module_from_spec(spec)
spec.loader.exec_module(run)


def text_outputs(nb, checked_only=False):
    """[(cell index, output kind, text)] for every text output of every code cell (consecutive
    stream chunks merged: how a kernel splits printing into messages depends on timing)."""
    found = []
    for i, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        if checked_only and "nbval-check-output" not in cell.metadata.get("tags", []):
            continue
        found.extend((i, kind, text) for kind, text in run.text_outputs(cell.get("outputs", [])))
    return found


def test_the_other_dispatch_is_a_real_change():
    """The variable that nbval's kernels (and the re-run below) get switches every dispatched
    extension off in a new process: the kernels run another code path than `make outputs` did."""
    found = run.dispatched_simd_extensions()
    if not found:
        pytest.skip("numpy dispatches no SIMD extension on this CPU: the baseline is the only code path")
    env = run.other_dispatch_env()
    assert env, "NPY_DISABLE_CPU_FEATURES is set already: the kernels would run this process's dispatch"
    code = ("from numpy._core import _multiarray_umath as u; "
            "print(sum(bool(u.__cpu_features__.get(n)) for n in u.__cpu_dispatch__))")
    out = subprocess.run([sys.executable, "-c", code], env={**env, "PATH": ""}, capture_output=True,
                         text=True, check=True)
    assert out.stdout.strip() == "0", "NPY_DISABLE_CPU_FEATURES did not switch the dispatched extensions off"


@pytest.mark.notebooks
@pytest.mark.parametrize("path", [pytest.param(p, marks=pytest.mark.portability_rerun(p), id=p.name)
                                  for p in NOTEBOOKS])
def test_checked_text_is_the_same_under_another_simd_dispatch(path, monkeypatch):
    for name, value in run.other_dispatch_env().items():
        monkeypatch.setenv(name, value)
    stored = nbformat.read(path, as_version=4)
    fresh = run.execute(path)
    assert not [o for o in text_outputs(fresh) if o[1] == "error"], "the notebook raised an error"
    a, b = text_outputs(stored, checked_only=True), text_outputs(fresh, checked_only=True)
    for old, new in zip(a, b):
        assert old == new, (f"checked cell {old[0]} prints {new[2]!r} under another SIMD dispatch, "
                            f"{old[2]!r} stored: print a bound or a rounded value (or run `make outputs`)")
    assert len(a) == len(b), "the number of checked outputs differs between runs (run `make outputs`?)"
    kinds = [(i, kind) for i, kind, _ in text_outputs(stored)]
    assert kinds == [(i, kind) for i, kind, _ in text_outputs(fresh)], (
        "the cells' outputs differ in kind between runs (run `make outputs`?)")

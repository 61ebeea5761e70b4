"""`make outputs`: execute notebooks top to bottom in a clean kernel and store their outputs.

The stored outputs are nbval's regression baseline, so they must come from one clean run, with
execution counts 1..n and nothing that changes from run to run but widget model ids: no timing
metadata and no saved widget state (static pages show each view's fallback PNG instead).  They are
made with numpy's normal SIMD dispatch; the tests run the notebooks under another one
(:func:`other_dispatch_env`) and compare, so a checked result printed to its last bits fails there.

Usage: python scripts/execute_notebooks.py course/*.ipynb
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import nbformat
from nbclient import NotebookClient


def execute(path: Path, timeout: int = 600) -> nbformat.NotebookNode:
    """Execute the notebook at ``path`` in a fresh ``python3`` kernel, working directory beside it."""
    nb = nbformat.read(path, as_version=4)
    client = NotebookClient(nb, timeout=timeout, kernel_name="python3", record_timing=False,
                            store_widget_state=False, resources={"metadata": {"path": str(path.parent)}})
    client.execute()
    nb.metadata.pop("widgets", None)
    for cell in nb.cells:
        cell.metadata.pop("execution", None)
        if cell.cell_type == "code":
            cell.outputs = coalesce_streams(cell.outputs)
    return nb


def coalesce_streams(outputs: list) -> list:
    """Merge consecutive stream outputs of the same name (stdout, stderr) into one.

    How a kernel chunks one cell's printing into stream messages depends on timing (a loaded
    machine may split even a single ``print``), so the stored outputs keep one stream per run of
    printing: the text is the same on every run, and so is its shape.
    """
    merged: list = []
    for out in outputs:
        if (out.get("output_type") == "stream" and merged and merged[-1].get("output_type") == "stream"
                and merged[-1].get("name") == out.get("name")):
            merged[-1]["text"] = merged[-1]["text"] + out["text"]
        else:
            merged.append(out)
    return merged


def dispatched_simd_extensions() -> list[str]:
    """The SIMD extensions numpy found on this CPU and dispatches to at run time (not the baseline,
    which cannot be switched off)."""
    try:
        from numpy._core import _multiarray_umath as umath
    except ImportError:  # numpy 1.x
        from numpy.core import _multiarray_umath as umath
    features = umath.__cpu_features__
    return [name for name in umath.__cpu_dispatch__ if features.get(name)]


def other_dispatch_env() -> dict[str, str]:
    """The environment variable that makes a new process's numpy run another code path than this
    one's: ``NPY_DISABLE_CPU_FEATURES`` naming every dispatched SIMD extension ({} where numpy
    dispatches none, or where the caller already chose with ``NPY_DISABLE_CPU_FEATURES``)."""
    import os

    found = dispatched_simd_extensions()
    if not found or "NPY_DISABLE_CPU_FEATURES" in os.environ:
        return {}
    return {"NPY_DISABLE_CPU_FEATURES": ",".join(found)}


TEXT_TYPES = ("text/plain", "text/html", "text/markdown", "text/latex")


def text_outputs(outputs: list) -> list[tuple[str, str]]:
    """[(kind, text)] for a cell's text outputs, kind being the stream's name, ``error`` or a text
    mime type (consecutive stream chunks merged first; images and widget model ids left out)."""
    found = []
    for out in coalesce_streams([dict(o) for o in outputs]):
        if out["output_type"] == "stream":
            found.append((out["name"], out["text"]))
        elif out["output_type"] == "error":
            found.append(("error", f"{out['ename']}: {out['evalue']}"))
        else:
            for kind in TEXT_TYPES:
                if kind in out.get("data", {}):
                    text = out["data"][kind]
                    found.append((kind, "".join(text) if isinstance(text, list) else text))
    return found


def main(paths: list[str]) -> int:
    for name in paths:
        path = Path(name)
        start = time.perf_counter()
        nb = execute(path)
        nbformat.write(nb, path)
        print(f"executed {path} in {time.perf_counter() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

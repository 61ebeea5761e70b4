"""`make outputs`: execute notebooks top to bottom in a clean kernel and store their outputs.

The stored outputs are nbval's regression baseline, so they must come from one clean run, with
execution counts 1..n and nothing that changes from run to run but widget model ids: no timing
metadata and no saved widget state (static pages show each view's fallback PNG instead).

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
    return nb


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

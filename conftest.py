"""Root pytest configuration, shared by the unit tests, the doctests and nbval over course/.

The notebooks' ``python3`` kernel runs ``python`` from PATH (its kernel.json says so), so the
directory of the running interpreter goes first on PATH: kernels started by nbval and by the
browser tests' JupyterLab then use this environment, whoever invoked pytest.

nbval's kernels run under another numpy SIMD dispatch than the one the stored outputs were made
with (``make outputs`` uses the normal one): numpy's dispatched SIMD extensions are switched off in
the kernel (``NPY_DISABLE_CPU_FEATURES``), this process and every other one keep them.  nbval's strict
comparison of the ``nbval-check-output`` cells is then the portability check of *Portable results*
(a residual printed to its last bits differs there), with each notebook executed once.  On top of
nbval, every cell must produce the same kinds of text output as stored and no error (so stale
outputs fail too); ``tests/notebooks/test_notebook_determinism.py`` re-runs a notebook on its own only when
nbval does not run it in the same session.
"""

import importlib.util
import os
import sys
from pathlib import Path

os.environ["PATH"] = os.path.dirname(sys.executable) + os.pathsep + os.environ.get("PATH", "")
os.environ.setdefault("PYTHONHASHSEED", "0")
os.environ.setdefault("MPLBACKEND", "Agg")


import pytest  # noqa: E402

try:
    from nbval.plugin import IPyNbCell, NbCellError
except ImportError:  # pragma: no cover - the test extra installs nbval
    IPyNbCell = NbCellError = None

ROOT = Path(__file__).resolve().parent


def execute_notebooks():
    """scripts/execute_notebooks.py as a module (the helpers `make outputs` and the tests share)."""
    module = sys.modules.get("goldman_execute_notebooks")
    if module is None:
        spec = importlib.util.spec_from_file_location("goldman_execute_notebooks",
                                                      ROOT / "scripts" / "execute_notebooks.py")
        module = importlib.util.module_from_spec(spec)
        sys.modules[spec.name] = module
        spec.loader.exec_module(module)
    return module


def _nbval_cell(item) -> bool:
    return IPyNbCell is not None and isinstance(item, IPyNbCell)


@pytest.fixture(autouse=True)
def _close_figures():
    """Close the pyplot figures a test or doctest made (views create them through pyplot so
    ipympl can wrap them; pyplot would otherwise keep every one alive for the whole session)."""
    yield
    import sys as _sys

    if "matplotlib.pyplot" in _sys.modules:
        _sys.modules["matplotlib.pyplot"].close("all")


@pytest.hookimpl(wrapper=True)
def pytest_runtest_setup(item):
    """Start each notebook's nbval kernel (set up with the notebook's first cell) under the other
    SIMD dispatch; the variable is set only while the kernel starts."""
    if not _nbval_cell(item) or item.parent.kernel is not None:
        return (yield)
    env = execute_notebooks().other_dispatch_env()
    saved = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    try:
        return (yield)
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


@pytest.hookimpl(wrapper=True)
def pytest_runtest_call(item):
    """After nbval ran a cell (and compared it if checked): the same kinds of text output as the
    stored ones, and no error, in every cell (nbval-lax compares only the checked cells' text)."""
    result = yield
    if _nbval_cell(item) and item.cell.execution_count is not None and item.test_outputs is not None:
        text_outputs = execute_notebooks().text_outputs
        fresh = [kind for kind, _ in text_outputs(item.test_outputs)]
        stored = [kind for kind, _ in text_outputs(item.cell.outputs)]
        if "error" in fresh or fresh != stored:
            raise NbCellError(item.cell_num, (
                f"the cell's outputs are {fresh}, stored {stored}, under another SIMD dispatch "
                "(an error, or outputs that are not the stored ones: run `make outputs`?)"), item.cell.source)
    return result


def pytest_configure(config):
    """A notebook's cells run in order in one kernel: under pytest-xdist they must all go to one
    worker, which ``--dist loadfile`` does (``make test`` uses it); ``--dist load`` (the default of
    ``-n``) and ``worksteal`` would deal them out one by one."""
    nbval = getattr(config.option, "nbval", False) or getattr(config.option, "nbval_lax", False)
    if nbval and getattr(config.option, "dist", "no") in ("load", "worksteal"):
        raise pytest.UsageError("nbval under pytest-xdist needs --dist loadfile (each notebook in one worker)")


def pytest_collection_modifyitems(config, items):
    """Leave out the stand-alone re-run of a notebook (marked ``portability_rerun(path)``) when nbval
    executes the same notebook in this session: nbval's run is the portability check then."""
    by_nbval = {Path(str(item.parent.path)).resolve() for item in items if _nbval_cell(item)}
    if not by_nbval:
        return
    keep, drop = [], []
    for item in items:
        mark = item.get_closest_marker("portability_rerun")
        (drop if mark and Path(mark.args[0]).resolve() in by_nbval else keep).append(item)
    if drop:
        config.hook.pytest_deselected(items=drop)
        items[:] = keep

"""Root pytest configuration, shared by the unit tests, the doctests and nbval over course/.

The notebooks' ``python3`` kernel runs ``python`` from PATH (its kernel.json says so), so the
directory of the running interpreter goes first on PATH: kernels started by nbval and by the
browser tests' JupyterLab then use this environment, whoever invoked pytest.
"""

import os
import sys

os.environ["PATH"] = os.path.dirname(sys.executable) + os.pathsep + os.environ.get("PATH", "")
os.environ.setdefault("PYTHONHASHSEED", "0")
os.environ.setdefault("MPLBACKEND", "Agg")


import pytest  # noqa: E402


@pytest.fixture(autouse=True)
def _close_figures():
    """Close the pyplot figures a test or doctest made (views create them through pyplot so
    ipympl can wrap them; pyplot would otherwise keep every one alive for the whole session)."""
    yield
    import sys as _sys

    if "matplotlib.pyplot" in _sys.modules:
        _sys.modules["matplotlib.pyplot"].close("all")

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

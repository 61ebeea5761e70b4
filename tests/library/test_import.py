"""goldman_lib and its algorithm modules import without the heavy view libraries (nor sympy, which
only the "show that" checkers import)."""

import subprocess
import sys

import pytest

HEAVY = ("matplotlib", "pythreejs", "ipywidgets", "sympy")


@pytest.mark.parametrize("module", ["goldman_lib", "goldman_lib.turtle", "goldman_lib.bezier",
                                    "goldman_lib.exercises", "goldman_lib.validation"])
def test_import_is_light(module):
    code = (f"import sys, {module}\n"
            f"heavy = [m for m in {HEAVY!r} if m in sys.modules]\n"
            "print(','.join(heavy))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "", f"importing {module} imported {out.stdout.strip()}"


def test_widgets_import_heavy_libraries_lazily_only_where_needed():
    code = "import sys, goldman_lib.widgets.three as t; print('pythreejs' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False", "widgets.three must import pythreejs only when a SceneView is built"


def test_chapter_25_modules_import_in_any_order():
    """bezier re-exports the chapter-25 names (imported eagerly: bezier_subdivision and bezier_intersection
    import only kernels and validation, so there is no cycle), and importing a chapter-25 module first works."""
    import subprocess
    import sys

    for first in ("bezier_intersection", "bezier_subdivision", "knot_insertion", "bezier"):
        code = (f"import goldman_lib.{first}\nfrom goldman_lib import bezier, bezier_intersection\n"
                "assert bezier.intersect_curves is bezier_intersection.intersect_curves\n"
                "from goldman_lib.bezier import *\nassert callable(subdivide)")
        subprocess.run([sys.executable, "-c", code], check=True)

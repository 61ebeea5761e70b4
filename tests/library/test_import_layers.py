"""The layers import only downwards (issue 19 §3): the library proper imports neither the widget
framework nor the chapters' views, and the framework knows no chapter.

    goldman_lib.views     the chapters' views        may import the framework and the library
    goldman_lib.widgets   the widget framework       may import the library, never goldman_lib.views
    goldman_lib (the rest, kernels and exercises)    imports neither package

Read from the source with ``ast`` (every ``import`` and ``from ... import``, at the top of a module
or inside a function, relative imports resolved), so a lazy import inside a function counts too.
"""

from __future__ import annotations

import ast
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "goldman_lib"


def _module_name(path: pathlib.Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def imported(path: pathlib.Path) -> list[tuple[int, str]]:
    """``(line, module)`` for every goldman_lib module the file at ``path`` imports (for ``from X
    import y`` both ``X`` and ``X.y``, since ``y`` may be a module)."""
    here = _module_name(path)
    package = here.split(".") if path.name == "__init__.py" else here.split(".")[:-1]
    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), filename=str(path))):
        if isinstance(node, ast.Import):
            found += [(node.lineno, alias.name) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - (node.level - 1)]
                source = ".".join(base + ([node.module] if node.module else []))
            else:
                source = node.module or ""
            found.append((node.lineno, source))
            found += [(node.lineno, f"{source}.{alias.name}") for alias in node.names]
    return [(line, name) for line, name in found if name.split(".")[0] == "goldman_lib"]


def _inside(name: str, package: str) -> bool:
    return name == package or name.startswith(package + ".")


def _files(where):
    return sorted(where.rglob("*.py"))


WIDGETS = _files(PACKAGE / "widgets")
LIBRARY = [p for p in _files(PACKAGE) if not any(part in ("views", "widgets") for part in p.relative_to(PACKAGE).parts)]


def test_the_layers_are_where_the_test_looks():
    assert len(WIDGETS) >= 10 and (PACKAGE / "widgets" / "interactive.py") in WIDGETS
    assert (PACKAGE / "bezier.py") in LIBRARY and (PACKAGE / "kernels" / "__init__.py") in LIBRARY
    assert not [p for p in LIBRARY if "views" in p.parts or "widgets" in p.parts]


@pytest.mark.parametrize("path", WIDGETS, ids=[str(p.relative_to(ROOT)) for p in WIDGETS])
def test_the_framework_knows_no_chapter(path):
    bad = [f"{path.relative_to(ROOT)}:{line}: imports {name}" for line, name in imported(path)
           if _inside(name, "goldman_lib.views")]
    assert not bad, "the widget framework imports the chapters' views:\n" + "\n".join(bad)


@pytest.mark.parametrize("path", LIBRARY, ids=[str(p.relative_to(ROOT)) for p in LIBRARY])
def test_the_library_imports_neither_views_nor_widgets(path):
    bad = [f"{path.relative_to(ROOT)}:{line}: imports {name}" for line, name in imported(path)
           if _inside(name, "goldman_lib.views") or _inside(name, "goldman_lib.widgets")]
    assert not bad, "the library imports its views or the widget framework:\n" + "\n".join(bad)


def test_the_reader_sees_each_form(tmp_path, monkeypatch):
    """Absolute, relative, lazy (inside a function) and ``from package import module`` imports are seen."""
    import sys

    pkg = tmp_path / "goldman_lib" / "widgets"
    pkg.mkdir(parents=True)
    (pkg / "a.py").write_text(
        "import numpy\n"
        "from goldman_lib import views\n"                    # 2
        "from ..views.bezier import plot_curve\n"            # 3
        "def f():\n"
        "    import goldman_lib.views.turtle as t\n"         # 5
        "from goldman_lib.widgets import style\n")           # 6: fine
    monkeypatch.setattr(sys.modules[__name__], "ROOT", tmp_path)
    names = imported(pkg / "a.py")
    assert [line for line, name in names if _inside(name, "goldman_lib.views")] == [2, 3, 3, 5]
    assert (6, "goldman_lib.widgets.style") in names

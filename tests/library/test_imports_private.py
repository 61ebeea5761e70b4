"""No module of goldman_lib uses another module's private (``_``) name (issue 19 §1).

A kernel that several modules need lives in :mod:`goldman_lib.kernels`, where every name is public;
a check that several modules need is a public, documented name of the module it belongs to (most in
:mod:`goldman_lib.validation`).  This test reads the imports of every module of the package (views
and exercises included) with ``ast`` and fails, naming file and line, on

- ``from goldman_lib.X import _name`` (or the relative ``from .X import _name``, ``from . import _mod``),
- ``import goldman_lib._mod`` and any import from a private module ``goldman_lib.X._mod``,
- ``X._name`` where ``X`` is bound to another goldman_lib module (``from goldman_lib import X``,
  ``import goldman_lib.X as X``, ``from . import X``), and the dotted ``goldman_lib.X._name``.

Dunder names (``__version__``) are not private, and a private module of a package may be imported
by the modules of that same package: it is the package's own business, not another module's
private name.  (A module other packages import is public: the widget framework's ``checks`` and
``program_editor``, used by the chapters' views, have no leading underscore.)
"""

from __future__ import annotations

import ast
import pathlib
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "goldman_lib"

# Exceptions, each with a reason: (file relative to the repository, the private name used) -> why.
ALLOWED: dict = {}   # (file, name) -> why; empty: every cross-module private use is gone


def _private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def _module_name(path: pathlib.Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _is_module(dotted: str) -> bool:
    rel = pathlib.Path(*dotted.split("."))
    return (ROOT / rel).with_suffix(".py").is_file() or (ROOT / rel / "__init__.py").is_file()


def _absolute(node: ast.ImportFrom, here: str, is_package: bool) -> str | None:
    """The absolute module an ImportFrom reads from (resolving ``.`` and ``..``)."""
    if node.level == 0:
        return node.module
    base = here.split(".") if is_package else here.split(".")[:-1]
    base = base[:len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def _own_package_private_module(dotted: str, here: str) -> bool:
    """Whether ``dotted`` is (or lies inside) a private module of ``here``'s own package: a
    package-internal module (``pkg._helpers`` for ``pkg.module``) is the package's business."""
    parts = dotted.split(".")
    first = next((i for i, p in enumerate(parts) if _private(p)), None)
    if first is None or not _is_module(".".join(parts[:first + 1])):
        return False
    return ".".join(parts[:first]) == here.rsplit(".", 1)[0]


def violations(path: pathlib.Path) -> list[tuple[int, str, str]]:
    """``(line, private name, what)`` for every cross-module private use in the file at ``path``."""
    here = _module_name(path)
    is_package = path.name == "__init__.py"
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found = []
    bound = {}                                        # local name -> goldman_lib module it stands for
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if not alias.name.startswith("goldman_lib"):
                    continue
                parts = alias.name.split(".")
                bad = [p for p in parts if _private(p)]
                if bad and alias.name != here and not _own_package_private_module(alias.name, here):
                    found.append((node.lineno, bad[0], f"import {alias.name}"))
                if alias.asname:
                    bound[alias.asname] = alias.name
                else:
                    bound.setdefault("goldman_lib", "goldman_lib")
        elif isinstance(node, ast.ImportFrom):
            source = _absolute(node, here, is_package)
            if not source or not source.startswith("goldman_lib"):
                continue
            private_parts = [p for p in source.split(".") if _private(p)]
            if private_parts and source != here and not _own_package_private_module(source, here):
                found.append((node.lineno, private_parts[0], f"from {source} import ..."))
            for alias in node.names:
                target = f"{source}.{alias.name}"
                if (_private(alias.name) and source != here and target != here
                        and not _own_package_private_module(target, here)):
                    found.append((node.lineno, alias.name, f"from {source} import {alias.name}"))
                if _is_module(target):
                    bound[alias.asname or alias.name] = target
    for node in ast.walk(tree):
        if not isinstance(node, ast.Attribute) or not _private(node.attr):
            continue
        base = node.value
        dotted = []
        while isinstance(base, ast.Attribute):
            dotted.append(base.attr)
            base = base.value
        if not isinstance(base, ast.Name) or base.id not in bound:
            continue
        module = ".".join([bound[base.id]] + dotted[::-1])
        if module != here and _is_module(module):
            found.append((node.lineno, node.attr, f"{module}.{node.attr}"))
    return sorted(set(found))


FILES = sorted(PACKAGE.rglob("*.py"))


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(ROOT)) for p in FILES])
def test_no_module_uses_another_modules_private_name(path):
    rel = str(path.relative_to(ROOT))
    bad = [f"{rel}:{line}: {what} (the private name {name!r} of another module; use a kernel from "
           "goldman_lib.kernels or a public, documented name)"
           for line, name, what in violations(path) if (rel, name) not in ALLOWED]
    assert not bad, "\n".join(bad)


def test_the_checker_sees_each_form(tmp_path, monkeypatch):
    """The forms the rule forbids are found, and the allowed ones (own names, public names, dunders) are not."""
    pkg = tmp_path / "goldman_lib"
    (pkg / "sub").mkdir(parents=True)
    for name in ("__init__.py", "a.py", "_hidden.py", "sub/__init__.py", "sub/_inner.py", "sub/b.py"):
        (pkg / name).write_text("")
    (pkg / "c.py").write_text(
        "from goldman_lib.a import _helper, public\n"          # 1: private name
        "from goldman_lib import a, _hidden\n"                   # own package's private module: fine
        "import goldman_lib.sub.b as bee\n"
        "from . import a as alias\n"
        "x = a._secret + alias._other + bee._x + a.__doc__ + a.fine\n"   # 5: three uses
        "from .sub import _inner\n"                               # 6: relative, another package's private module
        "import goldman_lib.sub._inner\n"                         # 7: import of another package's private module
        "from goldman_lib.c import _mine\n"                       # own module: fine
        "y = _mine\n"
        "import goldman_lib._hidden\n")                           # own package's private module: fine
    monkeypatch.setattr(sys.modules[__name__], "ROOT", tmp_path)
    found = violations(pkg / "c.py")
    assert [(line, name) for line, name, _ in found] == [
        (1, "_helper"), (5, "_other"), (5, "_secret"), (5, "_x"), (6, "_inner"), (7, "_inner")]


def test_the_allow_list_holds_only_views_and_files_owned_elsewhere_today():
    """Library modules other than shading (a file other branches edit today) have no exemption."""
    for rel, _name in ALLOWED:
        assert rel.startswith("goldman_lib/views/") or rel == "goldman_lib/shading.py", rel

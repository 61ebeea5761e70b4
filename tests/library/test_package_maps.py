"""The package docstrings are the map a newcomer reads (issue 19 §3): every module of
``goldman_lib``, of the widget framework ``goldman_lib.widgets`` and of the chapters' views
``goldman_lib.views`` is named there, and the library's map names both packages."""

import pkgutil

import goldman_lib
import goldman_lib.views
import goldman_lib.widgets


def _modules(package, private: bool):
    return sorted(m.name for m in pkgutil.iter_modules(package.__path__) if private or not m.name.startswith("_"))


def test_the_library_docstring_names_every_module():
    missing = [n for n in _modules(goldman_lib, private=False) if f"``{n}``" not in goldman_lib.__doc__
               and f"``goldman_lib.{n}``" not in goldman_lib.__doc__]
    assert not missing, f"goldman_lib/__init__.py's docstring does not name: {missing}"


def test_the_library_docstring_names_both_view_packages():
    for package in ("goldman_lib.widgets", "goldman_lib.views"):
        assert f"``{package}``" in goldman_lib.__doc__, package


def test_the_views_docstring_names_every_module():
    doc = goldman_lib.views.__doc__
    missing = [n for n in _modules(goldman_lib.views, private=True) if f"``{n}``" not in doc
               and f"``views.{n}``" not in doc]
    assert not missing, f"goldman_lib/views/__init__.py's docstring does not name: {missing}"


def test_the_widgets_docstring_names_every_module_and_the_rule():
    doc = goldman_lib.widgets.__doc__
    missing = [n for n in _modules(goldman_lib.widgets, private=True) if f"``widgets.{n}``" not in doc]
    assert not missing, f"goldman_lib/widgets/__init__.py's docstring does not name: {missing}"
    words = " ".join(doc.split())
    assert "more than one chapter" in words and "knows no chapter" in words   # the rule that puts a module there


def test_views_holds_only_chapters_and_widgets_only_the_framework():
    """No module sits in both packages, and neither package has a private (helper) module."""
    views = set(_modules(goldman_lib.views, private=True))
    widgets = set(_modules(goldman_lib.widgets, private=True))
    assert not views & widgets, views & widgets
    assert not [n for n in views | widgets if n.startswith("_")]


def test_the_kernels_map_names_every_kernel_in_its_modules_section():
    """goldman_lib.kernels' docstring is where a kernel is found: every public callable of each kernel
    module is named in that module's section of the map (with its callers beside it)."""
    import importlib

    import goldman_lib.kernels as kernels

    doc = kernels.__doc__
    missing = []
    modules = [name for name in kernels.__all__ if name != "number"]
    assert len(modules) >= 7
    for name in modules:
        module = importlib.import_module(f"goldman_lib.kernels.{name}")
        start = doc.index(f"goldman_lib.kernels.{name}`")
        end = doc.find(":mod:", start + 1)
        section = doc[start:end if end > 0 else None]
        missing += [f"{name}.{k}" for k in module.__all__ if callable(getattr(module, k)) and f"``{k}``" not in section]
    assert not missing, f"kernels missing from the map in goldman_lib/kernels/__init__.py: {missing}"

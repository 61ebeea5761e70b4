"""The package docstrings are the map a newcomer reads (issue 19 §3): every module of
``goldman_lib`` and of ``goldman_lib.views`` is named there."""

import pkgutil

import goldman_lib
import goldman_lib.views


def _modules(package, private: bool):
    return sorted(m.name for m in pkgutil.iter_modules(package.__path__) if private or not m.name.startswith("_"))


def test_the_library_docstring_names_every_module():
    missing = [n for n in _modules(goldman_lib, private=False) if f"``{n}``" not in goldman_lib.__doc__
               and f"``goldman_lib.{n}``" not in goldman_lib.__doc__]
    assert not missing, f"goldman_lib/__init__.py's docstring does not name: {missing}"


def test_the_views_docstring_names_every_module():
    doc = goldman_lib.views.__doc__
    missing = [n for n in _modules(goldman_lib.views, private=True) if f"``{n}``" not in doc
               and f"``views.{n}``" not in doc]
    assert not missing, f"goldman_lib/views/__init__.py's docstring does not name: {missing}"

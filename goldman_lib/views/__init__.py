"""The chapters' views: one module per chapter (or pair of chapters), named as the library
module it shows, each holding the chapter's plot functions and widget factories.

A view is built from the widget framework, :mod:`goldman_lib.widgets` (the widget pattern
``InteractiveView``, sliders, drags, three.js scenes, the light control, the shared editors): a
module that knows no chapter, or that the views of several chapters are built on, lives there (the
rule is in its docstring), and this package holds only the chapters' own modules.  A chapter's
module may use an earlier chapter's drawings (Parts depend only backwards: ``affine``, ``codo``,
``fractals`` and ``conformal_ifs`` draw turtle strokes with ``turtle``'s; ``bezier_subdivision``
and ``blossom`` plot curves with ``bezier``'s).

Part I, two-dimensional computer graphics:
``turtle`` (1), ``fractals`` (2-3), ``affine`` (4), ``codo`` (5), ``ifs`` (6), ``fixed_point`` (7),
``conformal_ifs`` (8).

Part II, mathematical methods for three-dimensional computer graphics:
``vectors`` (9-10), ``vector_geometry`` (11), ``transforms`` (12-13), ``mass_points`` (14),
``quaternions`` (15).

Part III, three-dimensional computer graphics:
``color_intensity`` (16), ``ray_tracing`` (17), ``surfaces`` (18), ``simple_surfaces`` (19),
``solid_modeling`` (20), ``shading`` (21), ``hidden_surfaces`` (22), ``radiosity`` (23).

Part IV, geometric modeling:
``bezier`` (24), ``bezier_subdivision`` (25), ``blossom`` (26), ``bspline`` (27),
``knot_insertion`` (28), ``subdivision_matrices`` (29), ``subdivision_surfaces`` (30).

Every widget factory returns an :class:`~goldman_lib.widgets.interactive.InteractiveView`;
:func:`factories` lists them all (the chapters' and those of the shared editors the notebooks
display) for the sweep tests and the callback benchmark.

Importing this package imports nothing; its modules import matplotlib (Agg unless the notebook
chose ``%matplotlib widget``), ipywidgets and, when a scene is built, pythreejs.
"""

from __future__ import annotations

__all__ = ["factories"]


def factories() -> list:
    """Every widget factory a chapter displays, as ``("module.name", factory)`` pairs sorted by
    name: the public functions annotated ``-> InteractiveView`` that build a view with no
    argument, of every module of this package and of the framework's shared editors
    (:mod:`goldman_lib.widgets`; ``module`` is the module's own name, which no two modules of the
    two packages share).  A builder that needs arguments (``widgets.program_editor.program_editor``
    takes a language) is not a factory: the chapters' factories built on it are.  The widget sweeps (tests) and the
    callback benchmark both use this list, so a new chapter's widgets are swept and timed as soon
    as their factories exist.

    >>> table = dict(factories())
    >>> "bezier.de_casteljau_explorer" in table and "knot_editor.bspline_curve_editor" in table
    True
    """
    import importlib
    import inspect
    import pkgutil

    import goldman_lib.views as chapters
    import goldman_lib.widgets as framework
    from goldman_lib.widgets.interactive import InteractiveView

    found = []
    for package in (chapters, framework):
        for info in pkgutil.iter_modules(package.__path__):
            module = importlib.import_module(f"{package.__name__}.{info.name}")
            for name, fn in inspect.getmembers(module, inspect.isfunction):
                if fn.__module__ != module.__name__ or name.startswith("_"):
                    continue
                signature = inspect.signature(fn)
                needs = [p for p in signature.parameters.values()
                         if p.default is p.empty and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]
                if signature.return_annotation in (InteractiveView, "InteractiveView") and not needs:
                    found.append((f"{info.name}.{name}", fn))
    return sorted(found)

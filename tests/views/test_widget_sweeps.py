"""Every widget factory a chapter displays (:func:`goldman_lib.views.factories`), found by its return annotation (``->
InteractiveView``), is swept over its controls' ranges, corners included: no exception escapes
``update``, nothing it draws is NaN or infinite, it always reports a status, and the view has a
static fallback PNG.  A new chapter's widgets are covered as soon as they exist;
chapter tests add checks of *what* is drawn.
"""

import numpy as np
import pytest

from goldman_lib.views import factories
from goldman_lib.widgets import interactive
from goldman_lib.widgets.interactive import InteractiveView
from sweeps import sweep_values

FACTORIES = [pytest.param(fn, id=name) for name, fn in factories()]


def drawn_arrays(result):
    """Every numeric array in what update returned (lists and dicts walked), status left out."""
    if isinstance(result, dict):
        for key, value in result.items():
            if key != "status":
                yield from drawn_arrays(value)
    elif isinstance(result, (list, tuple)) and not (result and np.isscalar(result[0])):
        for value in result:
            yield from drawn_arrays(value)
    elif isinstance(result, (bool, str)) or result is None:
        return
    else:
        yield np.asarray(result, dtype=float)


def test_every_chapter_so_far_has_widget_factories():
    ids = {p.id.split(".")[0] for p in FACTORIES}
    assert {"bezier", "turtle", "ifs_editor", "knot_editor", "fractals", "subdivision_surfaces"} <= ids


def test_every_views_module_has_a_widget_factory():
    """``goldman_lib.views`` holds only chapters' modules, and a chapter's module whose factory loses
    its ``-> InteractiveView`` annotation would drop out of the sweeps (and the callback benchmark)
    silently; here it fails instead."""
    import pkgutil

    import goldman_lib.views as views_pkg

    modules = {m.name for m in pkgutil.iter_modules(views_pkg.__path__)}
    ids = {p.id.split(".")[0] for p in FACTORIES}
    missing = sorted(modules - ids)
    assert not missing, f"views modules without a widget factory (annotate it -> InteractiveView): {missing}"


def test_the_shared_editors_factories_are_listed():
    """The framework's shared editors hold factories the notebooks display (chapters 6-8, 9, 27);
    the chapter package lists them with its own, under the editor module's name."""
    ids = {p.id.split(".")[0] for p in FACTORIES}
    assert {"ifs_editor", "knot_editor", "vectors3d"} <= ids
    assert "program_editor" not in ids          # a builder that needs a language, not a factory


def test_no_two_factories_share_a_name():
    """A factory's name says what it shows without its module (``bezier_subdivision_view``,
    ``bspline_subdivision_view``, ``subdivision_surface_view``; ``turtle_program_editor`` and
    ``codo_program_editor``, both built by the one shared program editor)."""
    from collections import Counter

    names = Counter(name.split(".")[1] for name, _ in factories())
    shared = sorted(n for n, c in names.items() if c > 1)
    assert not shared, f"widget factories sharing a name across views modules: {shared}"


def test_no_private_module_or_name_is_listed():
    assert not [name for name, _ in factories() if name.startswith("_") or ":" in name or "._" in name]


def test_dropdown_helper_matches_the_slider_style():
    w = interactive.dropdown("map", [("one", 1), ("two", 2)])
    assert w.value == 1 and w.description == "map" and w.style.description_width == "48px"


def distinct(combos):
    """Each value combination once, in order.  A view with few controls has few corners (six
    controls: 64), and the sweep's 400 random corners repeat them (six times each, on average):
    the repeats call ``update`` with values it has already been called with."""
    seen, out = set(), []
    for values in combos:
        key = tuple(sorted((name, repr(value)) for name, value in values.items()))
        if key not in seen:
            seen.add(key)
            out.append(values)
    return out


def test_distinct_keeps_the_first_of_each_combination():
    combos = [{"a": 1, "b": 0.5}, {"b": 0.5, "a": 1}, {"a": 1, "b": 1.0}, {"a": 1.0, "b": 0.5}]
    assert distinct(combos) == [combos[0], combos[2], combos[3]]


_BARE = set(vars(InteractiveView(controls={}, views=[], update=lambda: {})))


@pytest.mark.parametrize("factory", FACTORIES)
def test_sweep_over_every_control_range(factory):
    view = factory()
    assert isinstance(view, InteractiveView) and view.last_error is None, view.last_error
    # what a view carries is declared on InteractiveView (issue 19 §3), not set ad hoc
    undeclared = sorted(k for k in set(vars(view)) - _BARE - InteractiveView.CARRIES if not k.startswith("_trait"))
    assert not undeclared, f"{factory.__name__} sets attributes InteractiveView does not declare: {undeclared}"
    combos = distinct(sweep_values(view, n=3))
    if any(hasattr(w, "min") and hasattr(w, "max") for w in view.controls.values()):
        assert len(combos) >= 3, "a view with sliders is swept over at least its ends and middle"
    for values in combos:
        result = view.update(**values)
        # every view says what it shows (a count, a distance, an error bound) in its status line
        assert isinstance(result, dict) and isinstance(result.get("status"), str) and result["status"], values
        for arr in drawn_arrays(result):
            assert np.all(np.isfinite(arr)), f"{factory.__name__} drew a non-finite value at {values}"
    view.set_values(**combos[-1])
    assert view.last_error is None, f"{factory.__name__} showed an error at {combos[-1]}: {view.last_error}"
    assert view.static_png().startswith(b"\x89PNG")

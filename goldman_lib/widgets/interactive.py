"""The widget pattern shared by every chapter (CONVENTIONS, "Views and widgets").

A widget factory builds its figure or three.js renderer once, then returns an
:class:`InteractiveView`: a box of controls (sliders, pickers, a program editor) beside the view,
whose ``update(**values)`` is a *plain function*.  Moving a control calls ``update`` with the
controls' values; ``update`` changes data in place (``line.set_data``, a ``BufferAttribute.array``)
and returns what it drew as arrays, so tests can call it for any slider value and check the result.

Two promises every view keeps:

* **No traceback, ever.**  If ``update`` raises (a learner typed a program that does not parse,
  three collinear points where a triangle is needed), the message is shown beside the drawing in
  the status line and the last good drawing stays.
* **A static fallback image.**  Displaying the view also stores a PNG of it (the view at its
  default values) in the same output, as ipympl does for its canvas: JupyterLab with a kernel shows
  the live widget, while GitHub, nbconvert and the offline deck show the picture.

Tests sweep every control over its range (``tests/views/sweeps.py``).
"""

from __future__ import annotations

import base64
import contextlib
import functools
import html
import io
import itertools
from typing import Callable, Mapping

import ipywidgets as widgets

__all__ = ["InteractiveView", "figure_widget", "figure_png", "float_slider", "int_slider", "dropdown",
           "check_control_values"]


def float_slider(description: str, value: float, low: float, high: float, step: float = 0.05, *,
                 width: str = "290px", label_width: str = "48px", readout: str = ".2f") -> widgets.FloatSlider:
    """A compact float slider in the house style: fixed label width so stacks of sliders align,
    and ``continuous_update`` on (callbacks are fast enough to follow the drag)."""
    return widgets.FloatSlider(value=value, min=low, max=high, step=step, description=description,
                               continuous_update=True, readout_format=readout,
                               style={"description_width": label_width}, layout=widgets.Layout(width=width))


def dropdown(description: str, options, value=None, *, width: str = "290px",
             label_width: str = "48px") -> widgets.Dropdown:
    """A compact dropdown in the house style (the label width of :func:`float_slider`, so it lines
    up with a stack of sliders).  options: a list of values or of ``(label, value)`` pairs; value:
    the one shown first (default the first option)."""
    options = list(options)
    if value is None and options:
        first = options[0]
        value = first[1] if isinstance(first, tuple) else first
    return widgets.Dropdown(options=options, value=value, description=description,
                            style={"description_width": label_width}, layout=widgets.Layout(width=width))


def int_slider(description: str, value: int, low: int, high: int, *, width: str = "290px",
               label_width: str = "48px") -> widgets.IntSlider:
    """A compact integer slider in the house style."""
    return widgets.IntSlider(value=value, min=low, max=high, step=1, description=description,
                             continuous_update=True, style={"description_width": label_width},
                             layout=widgets.Layout(width=width))


def figure_png(fig) -> bytes:
    """PNG bytes of a matplotlib figure as it is drawn now (the static fallback image)."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=fig.dpi, metadata={"Software": None})
    return buf.getvalue()


def figure_widget(fig) -> widgets.DOMWidget:
    """The widget that shows ``fig``: its ipympl canvas under ``%matplotlib widget``; otherwise
    (inline backend, plain Python) an ``Image`` widget that :class:`InteractiveView` refreshes."""
    if isinstance(fig.canvas, widgets.DOMWidget):
        return fig.canvas
    return widgets.Image(value=figure_png(fig), format="png")


def _options(w):
    opts = w.options
    if isinstance(opts, Mapping):
        return list(opts.items())
    return [(o, o) if not isinstance(o, tuple) else o for o in opts]


class InteractiveView(widgets.VBox):
    """Controls + a view + a plain ``update`` callback + a static fallback image.

    controls: ``{name: widget}``; each widget's ``value`` is passed to ``update`` by that name.
    views: the widgets that show the result (an ipympl canvas, a three.js renderer, ...).
    update: ``update(**values) -> dict`` of what was drawn (arrays; an optional ``"status"``
    string is shown in the status line).  figure: the matplotlib figure to redraw after an update,
    if any.  static: a callable returning PNG bytes for the fallback image (default: the figure's).
    side: put the controls to the right of the view instead of below it.  arrange: the widgets
    of the control area if not simply the controls in order (e.g. sliders in a grid).  extra:
    more widgets under the controls (a program editor's help text, a reset button).
    acts: which controls act in which mode, ``{control: {mode_control: allowed values}}``: the
    control acts only while every named mode control holds one of its allowed values (or, for a
    rule that is a function, while ``rule(values)`` is true), and is
    disabled (greyed, ``disabled=True``) otherwise, enabled again when the mode changes (issue 18:
    a slider that changes nothing in the current mode must not look as if it could).

    >>> v = InteractiveView(controls={"mode": dropdown("mode", ["a", "b"]), "k": int_slider("k", 1, 0, 5)},
    ...                     views=[], update=lambda mode, k: {}, acts={"k": {"mode": ["b"]}})
    >>> v.controls["k"].disabled, v.set_values(mode="b") is not None, v.controls["k"].disabled
    (True, True, False)
    """

    # -- what a view may carry besides its controls (issue 19 §3: declared, not set ad hoc) ----------
    #: The matplotlib axes of a 2D view (a single ``Axes``) and of a view with several panels.
    ax = None
    axes = None
    #: The three.js scene of a 3D view (:class:`goldman_lib.widgets.three.SceneView`).
    scene = None
    #: The mouse drag of a view whose points are dragged (:class:`goldman_lib.widgets.drag.PointDrag`).
    drag = None
    #: The light-position control of a lit view (:class:`goldman_lib.widgets.light_control.LightControl`)
    #: and a view's own light object, if it shows one.
    light_control = None
    light = None
    #: The shared editors a view is built on: a knot-vector editor (``editor``; ``editors`` for a
    #: surface's two) and the parts of the IFS and program editors (the example picker
    #: ``examples``, the preset picker ``preset`` and its ``load`` function).
    editor = None
    editors = None
    examples = None
    preset = None
    load = None
    #: A readout widget a view writes into besides its status line, and a figure's extra mouse
    #: handler id (``mpl_connect``), kept so it can be disconnected.
    readout = None
    click_cid = None
    #: The Play widget of an animated view (it drives a frame slider).
    play = None
    #: The full-size picture of the view's current state, ``render_full(progress, **values)``, for a
    #: :class:`goldman_lib.widgets.render_control.RenderControl` under the view.
    render_full = None
    #: Everything above, by name: the sweep tests fail a factory that sets any other attribute.
    CARRIES = frozenset({"ax", "axes", "scene", "drag", "light_control", "light", "editor", "editors", "examples",
                         "preset", "load", "readout", "click_cid", "play", "render_full"})

    #: Each view's number (``uid``), which its box carries as the CSS class ``goldman-view-<uid>``
    #: (how a browser test names the view it sees to the kernel: ``tests/browser/kernel_hooks.py``).
    _count = itertools.count()

    def __init__(self, *, controls: Mapping[str, widgets.Widget], views: list, update: Callable[..., dict],
                 figure=None, static: Callable[[], bytes] | None = None, title: str = "",
                 side: bool = False, extra: list | None = None, arrange: list | None = None,
                 acts: Mapping[str, Mapping[str, object]] | None = None):
        self.uid = next(InteractiveView._count)
        self.controls = dict(controls)
        self.acts = {}
        for name, modes in (acts or {}).items():
            if name not in self.controls:
                raise KeyError(f"acts names a control {name!r} the view does not have; controls are {sorted(self.controls)}")
            if callable(modes):
                self.acts[name] = modes
                continue
            for mode, allowed in modes.items():
                if mode not in self.controls:
                    raise KeyError(f"acts[{name!r}] names a mode control {mode!r} the view does not have")
            self.acts[name] = {mode: tuple(allowed) for mode, allowed in modes.items()}
        self.update = _checked(update, self.controls)
        self.figure = figure
        self._static = static
        self.title = title
        self.status = widgets.HTML(value="", layout=widgets.Layout(min_height="1.6em"))
        self.last_error: str | None = None
        self.last_result: dict = {}
        self._views = list(views)
        control_box = widgets.VBox(list(arrange or self.controls.values()) + list(extra or []),
                                   layout=widgets.Layout(min_width="300px" if side else None))
        # CSS classes the browser tests use to find each view and its display.
        display_box = widgets.VBox(self._views)
        display_box.add_class("goldman-display")
        control_box.add_class("goldman-controls")
        if side:
            body = [widgets.HBox([display_box, control_box]), self.status]
        else:
            body = [display_box, control_box, self.status]
        if title:
            body = [widgets.HTML(f"<b>{html.escape(title)}</b>")] + body
        super().__init__(body)
        self.add_class("goldman-interactive")
        self.add_class(f"goldman-view-{self.uid}")
        for w in self.controls.values():
            w.observe(self._on_change, names="value")
        self.refresh()

    # -- the plain-function side -------------------------------------------------------------
    def values(self) -> dict:
        """The controls' current values, by name."""
        return {k: w.value for k, w in self.controls.items()}

    def set_values(self, **values) -> dict:
        """Set controls (as a learner would) and return what the view then shows."""
        for k in values:
            if k not in self.controls:
                raise KeyError(f"no control named {k!r}; controls are {sorted(self.controls)}")
        with self.muted():
            for k, v in values.items():
                self.controls[k].value = v
        self.refresh()
        return self.last_result

    @contextlib.contextmanager
    def muted(self):
        """Change controls inside ``with view.muted():`` without a redraw per change (call
        :meth:`refresh` after); nests, and restores the previous state on the way out."""
        old = self._muted
        self._muted = True
        try:
            yield self
        finally:
            self._muted = old

    # -- the widget side -----------------------------------------------------------------------
    def acting(self, values: Mapping | None = None) -> dict:
        """``{control: True/False}``: whether each control acts in the mode ``values`` (default the
        controls' current values) holds, by the view's ``acts`` (a control it does not name always acts)."""
        values = self.values() if values is None else values

        def acts(rule):
            try:
                if callable(rule):
                    return bool(rule(values))
                return all(any(_equal(values.get(mode), a) for a in allowed) for mode, allowed in rule.items())
            except Exception:  # noqa: BLE001 - a mode value no option has (set by code): leave the control on
                return True

        return {name: acts(self.acts.get(name, {})) for name in self.controls}

    def _apply_modes(self):
        if not self.acts:
            return
        for name, on in self.acting().items():
            if name in self.acts:
                self.controls[name].disabled = not on

    def refresh(self):
        """Call ``update`` with the current values; show a message instead of a traceback."""
        self._apply_modes()
        try:
            result = self.update(**self.values()) or {}
        except Exception as exc:  # noqa: BLE001 - a widget must never show a traceback
            self.last_error = f"{type(exc).__name__}: {exc}"
            self.status.value = (f'<span style="color:#b3261e">&#9888; {html.escape(str(exc))}</span>')
            return
        self.last_error = None
        self.last_result = result
        status = result.get("status", "")
        self.status.value = html.escape(status) if status else ""
        try:
            self._redraw()
        except Exception as exc:  # noqa: BLE001 - a drawing error is shown, not raised
            self.last_error = f"{type(exc).__name__}: {exc}"
            self.status.value = (f'<span style="color:#b3261e">&#9888; could not redraw: {html.escape(str(exc))}</span>')

    _muted = False

    def _on_change(self, change):
        if not self._muted:
            self.refresh()

    def _redraw(self):
        if self.figure is None:
            return
        canvas = self.figure.canvas
        if isinstance(canvas, widgets.DOMWidget):
            canvas.draw_idle()
        else:
            for v in self._views:
                if isinstance(v, widgets.Image):
                    v.value = figure_png(self.figure)

    def static_png(self) -> bytes:
        """PNG bytes of the view as it is now: the static fallback image."""
        if self._static is not None:
            return self._static()
        if self.figure is not None:
            return figure_png(self.figure)
        return b""

    def _repr_mimebundle_(self, **kwargs):
        data = super()._repr_mimebundle_(**kwargs)
        png = self.static_png()
        if png:
            data["image/png"] = base64.b64encode(png).decode("ascii")
        data["text/plain"] = f"[interactive view{': ' + self.title if self.title else ''}; run the notebook to use it]"
        return data


def _equal(a, b) -> bool:
    """``a == b`` as one truth value (False for values, such as arrays, that give no single one)."""
    try:
        return bool(a == b)
    except Exception:  # noqa: BLE001
        return False


def check_control_values(controls: Mapping[str, widgets.Widget], values: Mapping) -> dict:
    """The values, checked: raise ValueError/TypeError naming the control if a value is one its
    widget cannot hold: a number outside a slider's range (or not a finite real number), an option
    a picker does not offer, anything but True or False for a checkbox or toggle, a string that is
    no colour for a colour picker, anything but a string for a text field (and, for a control of
    any other kind, a value of another type than its current one).  Values set through the widgets
    always pass; values passed to ``update`` by code (a notebook, a test, a saved state) are checked
    here before any work starts (issues 10 and 20).  The message is short whatever the value.

    Returns ``values`` with each control's value as its widget would hold it (an integer slider's
    ``3.0`` as ``3``, a float slider's ``1`` as ``1.0``; a name that is no control passes as it
    is), which is what ``update`` receives: a view's ``update`` need not check its values again.

    >>> check_control_values({"n": int_slider("n", 1, 0, 5), "t": float_slider("t", 0.5, 0.0, 1.0)}, {"n": 3.0, "t": 1})
    {'n': 3, 't': 1.0}
    >>> check_control_values({"t": float_slider("t", 0.5, 0.0, 1.0)}, {"t": 2.0})
    Traceback (most recent call last):
    ...
    ValueError: t must lie in [0, 1]; got 2
    """
    from goldman_lib.widgets import checks

    out = dict(values)
    for name, value in values.items():
        w = controls.get(name)
        if w is None:
            continue
        if isinstance(w, (widgets.IntSlider, widgets.BoundedIntText)):
            out[name] = checks.integer(value, name, w.min, w.max)
        elif isinstance(w, (widgets.FloatSlider, widgets.BoundedFloatText)):
            out[name] = checks.number(value, name, w.min, w.max)
        elif isinstance(w, (widgets.Dropdown, widgets.ToggleButtons, widgets.RadioButtons, widgets.SelectionSlider)):
            out[name] = checks.option([v for _, v in _options(w)], value, name)
        elif isinstance(w, (widgets.Checkbox, widgets.ToggleButton)):
            out[name] = checks.boolean(value, name)
        elif isinstance(w, widgets.ColorPicker):
            out[name] = checks.colour(value, name)
        elif isinstance(w, (widgets.Text, widgets.Textarea)):
            out[name] = checks.text(value, name)
        else:
            out[name] = checks.same_kind(value, getattr(w, "value", None), name)
    return out


def _checked(update: Callable[..., dict], controls: Mapping[str, widgets.Widget]) -> Callable[..., dict]:
    """``update`` with its keyword values checked (and given as their widgets hold them) by
    :func:`check_control_values` first."""
    @functools.wraps(update)
    def checked(*args, **values):
        return update(*args, **check_control_values(controls, values))

    checked.unchecked = update
    return checked

"""Points you drag with the mouse: the one drag helper every 2D view shares (CONVENTIONS, "Direct
manipulation").

Under ``%matplotlib widget`` (ipympl) the browser sends mouse events to the kernel, and matplotlib
delivers them to callbacks registered with ``canvas.mpl_connect``.  :class:`PointDrag` turns them
into drags: a press within ``radius`` pixels of a draggable point grabs the nearest one, each
motion reports its new position, a release lets go.  :func:`drag_sliders` connects the drags of a
view's points to the sliders that also set them, so both the mouse and the keyboard drive the
same plain ``update`` callback: a drag sets the point's two sliders (through
:meth:`InteractiveView.set_values`, which updates once for both) and the sliders follow the mouse.

The same events arrive on any canvas, so a drag works without a browser (the tests drive one with
the functions of ``tests/browser/kernel_hooks.py``, which send these events):

>>> from matplotlib.backend_bases import MouseEvent
>>> from matplotlib.figure import Figure
>>> fig = Figure(); ax = fig.add_subplot(); _ = ax.set_xlim(0, 10), ax.set_ylim(0, 10)
>>> pts = np.array([[2.0, 2.0], [8.0, 5.0]])
>>> moved = []
>>> drag = PointDrag(ax, lambda: pts, lambda k, x, y: moved.append((k, round(x, 3), round(y, 3))))
>>> for name, at in (("button_press_event", (8.1, 5.0)), ("motion_notify_event", (7.0, 6.0)),
...                  ("button_release_event", (7.0, 6.0))):
...     x, y = ax.transData.transform(at)
...     fig.canvas.callbacks.process(name, MouseEvent(name, fig.canvas, x, y, button=1))
>>> moved
[(1, 7.0, 6.0)]
"""

from __future__ import annotations

from typing import Callable, Sequence

import numpy as np

__all__ = ["PointDrag", "drag_sliders", "point_sliders", "point_pairs", "points_from", "pair_rows"]


class PointDrag:
    """Make the points returned by ``get_points()`` (an ``(n, 2)`` array in data coordinates of
    ``ax``) draggable; ``on_drag(index, x, y)`` is called for each mouse motion while a point is held.

    radius: how close (in display pixels) a press must be to grab a point.  ``enabled`` switches
    dragging off and on.  :meth:`disconnect` removes the callbacks.  ``sliders`` is None, or (set by
    :func:`drag_sliders`) point k's x and y slider names at index k: the controls a drag moves.
    """

    sliders: list[tuple[str, str]] | None = None

    def __init__(self, ax, get_points: Callable[[], np.ndarray], on_drag: Callable[[int, float, float], None],
                 radius: float = 12.0, on_release: Callable[[int], None] | None = None):
        self.ax = ax
        self.get_points = get_points
        self.on_drag = on_drag
        self.on_release = on_release
        self.radius = float(radius)
        self.active: int | None = None
        self.enabled = True
        canvas = ax.figure.canvas
        self._cids = [canvas.mpl_connect("button_press_event", self._press),
                      canvas.mpl_connect("motion_notify_event", self._motion),
                      canvas.mpl_connect("button_release_event", self._release)]

    def disconnect(self):
        """Stop listening to the canvas."""
        for cid in self._cids:
            self.ax.figure.canvas.mpl_disconnect(cid)
        self._cids = []

    def nearest(self, x_pixels: float, y_pixels: float) -> int | None:
        """The index of the draggable point within ``radius`` pixels of a display position, or None."""
        pts = np.asarray(self.get_points(), dtype=float).reshape(-1, 2)
        if len(pts) == 0:
            return None
        screen = self.ax.transData.transform(pts)
        d = np.hypot(screen[:, 0] - x_pixels, screen[:, 1] - y_pixels)
        k = int(np.argmin(d))
        return k if d[k] <= self.radius else None

    # -- matplotlib event handlers ------------------------------------------------------------------
    def _press(self, event):
        if not self.enabled or event.inaxes is not self.ax or event.button not in (1, None):
            return
        if self.ax.get_navigate_mode() is not None:   # the toolbar's pan or zoom has the mouse
            return
        self.active = self.nearest(event.x, event.y)

    def _motion(self, event):
        if self.active is None or event.inaxes is not self.ax or event.xdata is None:
            return
        self._drag_to(event.xdata, event.ydata)

    def _release(self, event):
        # The point ends where the mouse lets go, even if the last motion events never arrived (a
        # browser may coalesce or drop them while the kernel is busy drawing).
        if (self.active is not None and event.inaxes is self.ax and event.xdata is not None
                and self._last != (event.xdata, event.ydata)):
            self._drag_to(event.xdata, event.ydata)
        if self.active is not None and self.on_release is not None:
            self.on_release(self.active)
        self.active = None
        self._last = None

    _last = None

    def _drag_to(self, x, y):
        if x is None or y is None or not (np.isfinite(x) and np.isfinite(y)):
            return
        self._last = (x, y)
        self.on_drag(self.active, float(x), float(y))


def snap_to_slider(slider, value: float) -> float:
    """``value`` clamped to a slider's range and rounded to its step (what the slider would hold)."""
    lo, hi = slider.min, slider.max
    value = min(max(value, lo), hi)
    step = getattr(slider, "step", None)
    if step:
        value = lo + round((value - lo) / step) * step
        value = min(max(value, lo), hi)
    return float(round(value, 10))


def drag_sliders(view, ax, pairs: Sequence[tuple[str, str]], radius: float = 12.0) -> PointDrag:
    """Let the mouse drag the points of ``view`` whose coordinates are the slider pairs ``pairs``
    (``[("x0", "y0"), ("x1", "y1"), ...]``, point k's x and y sliders) in the axes ``ax``.

    A drag sets the two sliders of the grabbed point (clamped to their ranges, rounded to their
    steps) through ``view.set_values``, so the view updates once per motion and the sliders show
    where the point is.  Returns the :class:`PointDrag` (``view.drag`` also keeps it).
    """
    for x_name, y_name in pairs:
        for name in (x_name, y_name):
            if name not in view.controls:
                raise KeyError(f"pairs names a control {name!r} the view does not have; controls are {sorted(view.controls)}")

    def points():
        vals = view.values()
        return np.array([[vals[x], vals[y]] for x, y in pairs], dtype=float)

    def on_drag(k, x, y):
        x_name, y_name = pairs[k]
        view.set_values(**{x_name: snap_to_slider(view.controls[x_name], x), y_name: snap_to_slider(view.controls[y_name], y)})

    drag = PointDrag(ax, points, on_drag, radius=radius)
    drag.sliders = [(x_name, y_name) for x_name, y_name in pairs]
    view.drag = drag
    return drag


def point_sliders(points, box, step: float = 0.1, prefix: str = "", width: str = "290px",
                  label_width: str = "48px") -> dict:
    """An x and a y slider for each of ``points`` (``{"x0": ..., "y0": ..., "x1": ...}``, with
    ``prefix`` before each name), each over the view's ``box`` = (xmin, xmax, ymin, ymax), so the
    keyboard and tests place the points the mouse drags with :func:`drag_sliders`.

    >>> sorted(point_sliders([[0, 0], [1, 2]], (-1, 2, -1, 3)))
    ['x0', 'x1', 'y0', 'y1']
    """
    from goldman_lib.widgets.interactive import float_slider

    pts = np.asarray(points, dtype=float).reshape(-1, 2)
    xmin, xmax, ymin, ymax = (float(v) for v in box)
    controls = {}
    for k, (x, y) in enumerate(pts):
        for axis, v, lo, hi in (("x", x, xmin, xmax), ("y", y, ymin, ymax)):
            name = f"{prefix}{axis}{k}"
            controls[name] = float_slider(name, float(min(max(v, lo), hi)), lo, hi, step, width=width,
                                          label_width=label_width)
    return controls


def point_pairs(count: int, prefix: str = "") -> list[tuple[str, str]]:
    """The slider-name pairs ``[("x0", "y0"), ("x1", "y1"), ...]`` of :func:`point_sliders`."""
    return [(f"{prefix}x{k}", f"{prefix}y{k}") for k in range(count)]


#: The largest coordinate :func:`points_from` accepts: far past any slider's box, small enough that
#: a curve's arithmetic on it (powers, sums of products) stays finite.
POINT_LIMIT = 1e12


def points_from(values: dict, count: int, prefix: str = "") -> np.ndarray:
    """The ``(count, 2)`` points that the sliders of :func:`point_sliders` hold in ``values``.

    A value no slider can reach (NaN, infinite, beyond ``POINT_LIMIT``) raises ValueError naming
    the control, so the view shows a message instead of drawing nothing.
    """
    out = np.empty((count, 2))
    for k in range(count):
        for j, axis in enumerate("xy"):
            name = f"{prefix}{axis}{k}"
            v = values[name]
            if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)):
                raise TypeError(f"{name} must be a number; got {type(v).__name__}")
            if not (np.isfinite(v) and abs(v) <= POINT_LIMIT):
                raise ValueError(f"{name} must be a finite number of size at most {POINT_LIMIT:g}; got {v!r}")
            out[k, j] = float(v)
    return out


def pair_rows(controls: dict, count: int, prefix: str = "") -> list:
    """The point sliders laid out one row per point (x and y side by side), for a compact panel."""
    import ipywidgets as widgets

    return [widgets.HBox([controls[f"{prefix}x{k}"], controls[f"{prefix}y{k}"]]) for k in range(count)]

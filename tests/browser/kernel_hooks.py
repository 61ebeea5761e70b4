"""What the tests ask the notebook's kernel, and how they drive a view from code (issue 19 §3: test
hooks live with the tests, not in the library).  The browser tests run this file in the kernel with
``runpy.run_path`` and call its functions on the live views; the view tests load it the same way
(the ``hooks`` fixture of ``tests/views/conftest.py``).  Every function takes the view or the drag
and reads only its public attributes.

* :func:`find_view` -- the live :class:`~goldman_lib.widgets.interactive.InteractiveView` whose box
  carries the CSS class ``goldman-view-<uid>``.
* :func:`drag_plan` -- a drag a real mouse can make on a view's :class:`~goldman_lib.widgets.drag.PointDrag`.
* :func:`position`, :func:`screen_position` -- where a drag's point is now (data coordinates,
  figure pixels).
* :func:`press_at`, :func:`move_to`, :func:`release` -- the mouse, driven from code: matplotlib's
  own events sent through the figure's canvas, as ipympl sends them when a learner drags.
"""

import gc

import numpy as np

from goldman_lib.widgets.interactive import InteractiveView


def find_view(uid) -> InteractiveView:
    """The live view numbered ``uid`` (its box has the CSS class ``goldman-view-<uid>``)."""
    if isinstance(uid, bool) or not isinstance(uid, (int, np.integer)):
        raise TypeError(f"uid must be an integer; got {type(uid).__name__}")
    for obj in gc.get_objects():
        if isinstance(obj, InteractiveView) and obj.uid == int(uid):
            return obj
    raise ValueError(f"uid must name a live view; no view numbered {uid}")


def position(drag, index) -> list:
    """Where point ``index`` of ``drag`` is now, in data coordinates."""
    pts = np.asarray(drag.get_points(), dtype=float).reshape(-1, 2)
    if isinstance(index, bool) or not isinstance(index, (int, np.integer)) or not 0 <= index < len(pts):
        raise ValueError(f"index must be a point number in [0, {len(pts) - 1}]; got {index!r}")
    return [float(v) for v in pts[int(index)]]


def screen_position(drag, index) -> list:
    """Where point ``index`` of ``drag`` is drawn now, in figure pixels (origin bottom left)."""
    return [float(v) for v in drag.ax.transData.transform(position(drag, index))]


def _send(drag, name: str, x, y):
    from matplotlib.backend_bases import MouseEvent

    px, py = drag.ax.transData.transform((x, y)) if x is not None else (0, 0)
    canvas = drag.ax.figure.canvas
    canvas.callbacks.process(name, MouseEvent(name, canvas, px, py, button=1))


def press_at(drag, x: float, y: float):
    """Press the mouse at data position (x, y) of the drag's axes, as a learner would."""
    _send(drag, "button_press_event", x, y)


def move_to(drag, x: float, y: float):
    """Move the mouse to data position (x, y)."""
    _send(drag, "motion_notify_event", x, y)


def release(drag, x: float | None = None, y: float | None = None):
    """Release the mouse button (at data position (x, y) if given, so the held point ends there;
    otherwise at the figure's corner, outside the axes)."""
    _send(drag, "button_release_event", None if x is None or y is None else x, y)


def drag_plan(drag, distance: float = 40.0) -> dict | None:
    """A drag a test can make with a real mouse: a draggable point well inside the axes that a
    press on it grabs (no other point nearer), and where to take it, ``distance`` display pixels
    away in one of the four axis directions and still inside the axes.  Returns ``{"index",
    "start", "end", "figure", "start_data", "end_data", "pixels_per_unit"}``: positions in
    figure pixels (origin bottom left), the figure's width and height in pixels, the two
    positions in data coordinates and the axes' scale now (a view may refit its axes when the
    mouse lets go, so a test compares where the point ends in data coordinates).  None if no
    point can be dragged that far."""
    if isinstance(distance, bool) or not isinstance(distance, (int, float)) or not 0 < distance < 1e4:
        raise ValueError(f"distance must be a number of pixels in (0, 10000); got {distance!r}")
    pts = np.asarray(drag.get_points(), dtype=float).reshape(-1, 2)
    if len(pts) == 0:
        return None
    screen = drag.ax.transData.transform(pts)
    box = drag.ax.bbox
    margin = 6.0

    def inside(x, y):
        return box.x0 + margin <= x <= box.x1 - margin and box.y0 + margin <= y <= box.y1 - margin

    for k, (x, y) in enumerate(screen):
        if not (np.isfinite(x) and np.isfinite(y) and inside(x, y)) or drag.nearest(x, y) != k:
            continue
        for dx, dy in ((distance, 0.0), (-distance, 0.0), (0.0, distance), (0.0, -distance)):
            if inside(x + dx, y + dy):
                w, h = drag.ax.figure.bbox.width, drag.ax.figure.bbox.height
                inverse = drag.ax.transData.inverted()
                end_data = inverse.transform((x + dx, y + dy))
                one = drag.ax.transData.transform(pts[k] + 1.0) - drag.ax.transData.transform(pts[k])
                return {"index": k, "start": [float(x), float(y)], "end": [float(x + dx), float(y + dy)],
                        "figure": [float(w), float(h)], "start_data": [float(v) for v in pts[k]],
                        "end_data": [float(v) for v in end_data],
                        "pixels_per_unit": [float(abs(v)) for v in one]}
    return None

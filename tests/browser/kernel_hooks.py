"""What the browser tests ask the notebook's kernel (issue 19 §3: test hooks live with the tests,
not in the library).  The tests run this file in the kernel with ``runpy.run_path`` and call its
functions on the live views; the unit tests load it the same way.

* :func:`find_view` -- the live :class:`~goldman_lib.widgets.interactive.InteractiveView` whose box
  carries the CSS class ``goldman-view-<uid>`` (the framework keeps every live view by its number).
* :func:`drag_plan` -- a drag a real mouse can make on a view's :class:`~goldman_lib.widgets.drag.PointDrag`.
"""

import numpy as np

from goldman_lib.widgets.interactive import InteractiveView


def find_view(uid) -> InteractiveView:
    """The live view numbered ``uid`` (its box has the CSS class ``goldman-view-<uid>``)."""
    if isinstance(uid, bool) or not isinstance(uid, (int, np.integer)):
        raise TypeError(f"uid must be an integer; got {type(uid).__name__}")
    try:
        return InteractiveView._live[int(uid)]
    except KeyError:
        raise ValueError(f"uid must name a live view; no view numbered {uid}") from None


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

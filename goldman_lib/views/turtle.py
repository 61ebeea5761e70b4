"""Chapter 1 views: the turtle's path, a polygon explorer and a program editor (Goldman §1.1-1.3).

:func:`plot_polylines` and :func:`plot_program` draw in the house style and mark the turtle's
final position and heading with a small arrowhead.  The two widget factories return an
:class:`~goldman_lib.widgets.interactive.InteractiveView` (not displayed) whose ``update`` is a
plain function returning what it drew::

    {"polylines": [(k, 2) arrays, one per stroke], "point": (2,), "direction": (2,),
     "status": "..."}

All strokes live in one Line2D with a row of NaN between strokes (the only NaN drawn); the
polylines returned hold no NaN.

>>> view = polygon_explorer()
>>> out = view.update(**view.values())
>>> out["status"]
'REPEAT 5 [FORWARD 1 TURN 72]  |  total turning 360°  |  closes after 5 steps'
>>> [p.shape for p in out["polylines"]]
[(6, 2)]
"""

from __future__ import annotations

import numpy as np

from goldman_lib import turtle
from goldman_lib.validation import as_float, as_int, as_points
from goldman_lib.widgets import style
from goldman_lib.widgets.program_editor import program_editor
from goldman_lib.widgets.interactive import InteractiveView, figure_widget, float_slider, int_slider

__all__ = ["plot_polylines", "plot_program", "polygon_explorer", "turtle_program_editor", "EXAMPLES",
           "DEFAULT_PROGRAM", "stroke_data", "heading_marker"]

#: The program the editor opens with: a {5/2} star drawn as two nested REPEATs and a MOVE.
DEFAULT_PROGRAM = """# a five-pointed star, then a small square beside it
REPEAT 5 [FORWARD 2 TURN 144]
MOVE 3
REPEAT 4 [FORWARD 0.5 TURN 90]
"""

#: Programs the editor's example picker offers (name -> program text).
EXAMPLES = {
    "star and square": DEFAULT_PROGRAM,
    "hexagon": turtle.polygon(6, 1),
    "{7/3} star": turtle.star(7, 3),
    "spiral (RESIZE)": turtle.spiral(40, 89, 0.2, factor=1.06),
    "circle (36-gon)": turtle.circle(2, 36),
    "rosette": turtle.rosette(12, 6, 1),
    "nested squares": "REPEAT 8 [\n  REPEAT 4 [FORWARD 1 TURN 90]\n  MOVE 0.25 RESIZE 1.25\n]",
}

_ARROW = np.array([[1.0, 0.0], [-0.7, 0.6], [-0.3, 0.0], [-0.7, -0.6], [1.0, 0.0]])


#: The longest program the editor runs (it re-runs at every edit; parsing takes about 2 s a megabyte).
MAX_EDITOR_LENGTH = 100_000

def heading_marker(direction):
    """A matplotlib marker: an arrowhead pointing along ``direction`` ``(2,)`` (the turtle)."""
    from matplotlib.markers import MarkerStyle
    from matplotlib.path import Path
    from matplotlib.transforms import Affine2D

    w = np.asarray(direction, dtype=float)
    angle = float(np.degrees(np.arctan2(w[1], w[0]))) if np.any(w) else 0.0
    return MarkerStyle(Path(_ARROW, closed=True), transform=Affine2D().rotate_deg(angle))


def stroke_data(polylines) -> tuple[np.ndarray, np.ndarray]:
    """x and y of all strokes in one array each, with one NaN between strokes (for one Line2D).

    >>> x, y = stroke_data([np.array([[0, 0], [1, 0]]), np.array([[2, 0], [3, 1]])])
    >>> x.tolist()
    [0.0, 1.0, nan, 2.0, 3.0]
    """
    if not polylines:
        return np.zeros(0), np.zeros(0)
    sep = np.full((1, 2), np.nan)
    parts = []
    for i, p in enumerate(polylines):
        if i:
            parts.append(sep)
        parts.append(np.asarray(p, dtype=float))
    xy = np.concatenate(parts)
    return xy[:, 0], xy[:, 1]


def _limits(polylines, point, pad=0.08):
    pts = [np.asarray(p, dtype=float) for p in polylines] + [np.asarray(point, dtype=float)[None]]
    xy = np.concatenate(pts)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    span = float(max(hi[0] - lo[0], hi[1] - lo[1]))
    margin = pad * span if span > 0 else 1.0
    return (lo[0] - margin, hi[0] + margin), (lo[1] - margin, hi[1] + margin)


class PathArtists:
    """The artists of one turtle drawing: the strokes (one Line2D), the start, the turtle."""

    def __init__(self, ax, color=None, linewidth=1.6):
        pal = style.PALETTE
        (self.strokes,) = ax.plot([], [], color=color or pal["curve"], linewidth=linewidth,
                                  solid_joinstyle="round", solid_capstyle="round", zorder=2)
        (self.start,) = ax.plot([], [], "o", markersize=5, markerfacecolor="white",
                                markeredgecolor=pal["control"], zorder=3)
        (self.turtle,) = ax.plot([], [], linestyle="none", markersize=13, color=pal["point"], zorder=4)
        # Equal scales by shrinking the axes box, never by overriding the limits set below.
        ax.set_adjustable("box")
        self.ax = ax

    def set(self, polylines, start, point, direction):
        x, y = stroke_data(polylines)
        self.strokes.set_data(x, y)
        self.start.set_data([start[0]], [start[1]])
        self.turtle.set_data([point[0]], [point[1]])
        self.turtle.set_marker(heading_marker(direction))
        (x0, x1), (y0, y1) = _limits(list(polylines) + [np.asarray(start, float)[None]], point)
        style.set_equal_limits(self.ax, x0, x1, y0, y1)


def plot_polylines(polylines, ax=None, *, point=None, direction=None, start=None, color=None,
                   linewidth: float = 1.6, title: str | None = None):
    """Draw turtle strokes and mark the turtle's final position and heading (Goldman §1.1).

    polylines: one ``(k, 2)`` array or a list of them (as :func:`goldman_lib.turtle.run`
    returns).  point, direction: ``(2,)`` the turtle's final state; by default the end and
    direction of the last segment drawn.  start: ``(2,)`` where the turtle started (a small
    circle); by default the first point drawn.  Returns the axes.  Raises TypeError/ValueError
    naming ``polylines`` for arrays that are not finite ``(k, 2)`` points.

    >>> ax = plot_polylines(turtle.run("REPEAT 4 [FORWARD 1 TURN 90]"))
    >>> ax.lines[0].get_xydata().shape
    (5, 2)
    """
    if isinstance(polylines, np.ndarray) or (isinstance(polylines, (list, tuple)) and polylines
                                             and np.ndim(polylines[0]) == 1):
        polylines = [polylines]
    polys = [as_points(p, f"polylines[{i}]", ndim=2, dim=2) for i, p in enumerate(polylines)]
    if point is None:
        point = polys[-1][-1] if polys else np.zeros(2)
    point = as_points(point, "point", ndim=1, dim=2)
    if direction is None:
        direction = np.array([1.0, 0.0])
        if polys:
            seg = np.diff(polys[-1], axis=0)
            seg = seg[np.hypot(seg[:, 0], seg[:, 1]) > 0]
            if len(seg):
                direction = seg[-1]
    direction = as_points(direction, "direction", ndim=1, dim=2)
    if start is None:
        start = polys[0][0] if polys else point
    start = as_points(start, "start", ndim=1, dim=2)
    ax = style.get_axes(ax)
    PathArtists(ax, color=color, linewidth=linewidth).set(polys, start, point, direction)
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def plot_program(program, ax=None, *, point=(0, 0), direction=(1, 0), title: str | None = None, **kwargs):
    """Run a turtle program and draw it, marking the turtle's exact final state (Goldman §1.3).

    program: program text or a parsed Program; point, direction: the initial state ``(2,)``.
    Returns the axes.  Raises as :func:`goldman_lib.turtle.trace`.

    >>> plot_program(turtle.star(5, 2)).lines[0].get_xydata().shape
    (6, 2)
    """
    t = turtle.trace(program, point=point, direction=direction)
    return plot_polylines(t.polylines, ax, point=t.point, direction=t.direction,
                          start=np.asarray(point, dtype=float), title=title, **kwargs)


def _closing_status(polylines, start, tol) -> str:
    if not polylines:
        return "nothing drawn"
    pts = polylines[0]
    d = np.hypot(pts[1:, 0] - start[0], pts[1:, 1] - start[1])
    back = np.flatnonzero(d <= tol)
    end_gap = float(np.hypot(*(pts[-1] - start)))
    if back.size:
        first = int(back[0]) + 1
        if end_gap <= tol:
            return f"closes after {first} steps"
        return f"passes its start after {first} steps, ends {end_gap:.3g} away"
    return f"does not close: ends {end_gap:.3g} from its start"


def polygon_explorer(angle: float = 72.0, step: float = 1.0, repetitions: int = 5, factor: float = 1.0,
                     *, figsize=style.FIGSIZE) -> InteractiveView:
    """Sliders for ``REPEAT n [FORWARD step TURN angle RESIZE factor]`` (Goldman §1.3).

    angle (degrees, 0..360), step (0.1..3), repetitions (1..120), factor (the RESIZE factor,
    0.8..1.2; 1 leaves the RESIZE out).  The status line shows the program, the total turning
    and whether (and when) the path closes.  ``update(angle, step, repetitions, factor)``
    returns ``{"polylines", "point", "direction", "program", "total_turning", "closes",
    "status"}``.  Not displayed: the notebook displays it.

    >>> polygon_explorer(144, 1, 5).last_result["closes"]
    True
    """

    angle = as_float(angle, "angle")
    step = as_float(step, "step", positive=True)
    repetitions = as_int(repetitions, "repetitions", minimum=1, maximum=120)
    factor = as_float(factor, "factor", positive=True)
    wide = {"width": "330px", "label_width": "80px"}
    controls = {
        "angle": float_slider("TURN angle", angle, 0, 360, 0.5, readout=".1f", **wide),
        "step": float_slider("FORWARD", step, 0.1, 3, 0.1, readout=".1f", **wide),
        "repetitions": int_slider("REPEAT", repetitions, 1, 120, **wide),
        "factor": float_slider("RESIZE", factor, 0.8, 1.2, 0.01, **wide),
    }
    fig, ax = style.new_axes(figsize)
    artists = PathArtists(ax)

    def update(angle, step, repetitions, factor):
        body = f"FORWARD {turtle.format_number(round(step, 6))} TURN {turtle.format_number(round(angle, 6))}"
        if factor != 1:
            body += f" RESIZE {turtle.format_number(round(factor, 6))}"
        program = f"REPEAT {int(repetitions)} [{body}]"
        t = turtle.trace(program)
        artists.set(t.polylines, (0.0, 0.0), t.point, t.direction)
        extent = max((float(np.abs(p).max()) for p in t.polylines), default=1.0)
        tol = 1e-9 * max(1.0, extent)
        closed = bool(t.polylines) and turtle.closes(t.polylines[0], tol)
        status = (f"{program}  |  total turning {turtle.format_number(round(t.total_turning, 6))}°  |  "
                  f"{_closing_status(t.polylines, (0.0, 0.0), tol)}")
        return {"polylines": t.polylines, "point": t.point, "direction": t.direction,
                "program": program, "total_turning": t.total_turning, "closes": closed, "status": status}

    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Polygons, stars and spirals: REPEAT n [FORWARD step TURN angle]",
                           side=True)


_HELP = ("<small>Commands: <code>FORWARD d</code>, <code>MOVE d</code> (pen up), "
         "<code>TURN a</code> (degrees, counterclockwise), <code>RESIZE s</code>, "
         "<code>REPEAT n [ ... ]</code>; <code>#</code> starts a comment. "
         "Press Tab or click outside the box to draw.</small>")


def turtle_program_editor(program: str = DEFAULT_PROGRAM, *, figsize=style.FIGSIZE) -> InteractiveView:
    """A text box for a turtle program with live drawing (Goldman §1.3); the course's one program
    editor (:mod:`goldman_lib.widgets.program_editor`, shared with CODO) running the turtle.

    program: the initial text.  The turtle starts at ``(0, 0)`` heading ``(1, 0)``.  A program
    that does not parse leaves the last good drawing and shows the parser's message
    ("line 2, column 9: expected ...") in the status line.  An example picker fills the box
    with the programs of :data:`EXAMPLES` (``view.examples``).  ``update(program)`` returns ``{"polylines",
    "point", "direction", "status"}`` and raises ValueError (TurtleSyntaxError) for a program
    that does not parse or is longer than :data:`MAX_EDITOR_LENGTH`.

    >>> view = turtle_program_editor("FORWARD 1 TURN 90 FORWARD")
    >>> view.last_error
    'TurtleSyntaxError: line 1, column 26: expected a number after FORWARD, found end of program'
    """
    def make_runner(ax):
        artists = PathArtists(ax)

        def run(program):
            t = turtle.trace(program)
            artists.set(t.polylines, (0.0, 0.0), t.point, t.direction)
            heading = float(np.degrees(np.arctan2(t.direction[1], t.direction[0])))
            strokes = len(t.polylines)
            status = (f"{t.commands} command{'s' * (t.commands != 1)}, {strokes} stroke{'s' * (strokes != 1)}, "
                      f"total turning {turtle.format_number(round(t.total_turning, 6))}°; "
                      f"the turtle ends at ({t.point[0]:.3g}, {t.point[1]:.3g}) heading {heading + 0.0:.4g}°")
            return {"polylines": t.polylines, "point": t.point, "direction": t.direction, "status": status}

        return run

    return program_editor(program, make_runner=make_runner, examples=EXAMPLES, help_html=_HELP,
                          title="Turtle program editor", picker_label="(examples)", rows=8, height="170px",
                          max_length=MAX_EDITOR_LENGTH, figsize=figsize)

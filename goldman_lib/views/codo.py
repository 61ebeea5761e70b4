"""Chapter 5 views: a CODO program editor with live drawing, and the turtle's second shortcoming
made visible (Goldman §5.1-5.2).

Both factories return an :class:`~goldman_lib.widgets.interactive.InteractiveView` whose
``update`` is a plain function returning what it drew.

>>> view = codo_program_editor()
>>> out = view.update(**view.values())
>>> len(out["polylines"]), out["dots"].shape
(5, (10, 2))
"""

from __future__ import annotations

import numpy as np

from goldman_lib import affine, codo, turtle
from goldman_lib.widgets import style
from goldman_lib.widgets.program_editor import program_editor
from goldman_lib.widgets.interactive import dropdown, figure_widget, float_slider, InteractiveView
from goldman_lib.views.turtle import stroke_data

__all__ = ["DEFAULT_PROGRAM", "TRY_PROGRAM", "plot_drawing", "plot_program", "codo_program_editor", "TURTLE_PROGRAMS",
           "turtle_shortcoming_view"]

#: The program the editor opens with: the regular pentagon of §5.2.2.
DEFAULT_PROGRAM = codo.SAMPLES["regular pentagon"]
#: A one-line program the help text suggests (in a ``<code class="goldman-example">`` element, so a
#: browser test can read and type it).
TRY_PROGRAM = "C = point(0, 0); P = point(1, 0); R = rotate(C, 120); REPEAT 3 [ CONNECT P, R(P); P = R(P) ]"


def _fit(ax, pts, pad=0.08):
    """Limits around ``pts`` with the axes box's aspect, so equal scales need no adjustment."""
    if len(pts) == 0:
        pts = np.zeros((1, 2))
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    span = float(max(hi[0] - lo[0], hi[1] - lo[1]))
    m = pad * span if span > 0 else 1.0
    x0, x1, y0, y1 = lo[0] - m, hi[0] + m, lo[1] - m, hi[1] + m
    style.set_equal_limits(ax, x0, x1, y0, y1)


class _DrawingArtists:
    def __init__(self, ax):
        pal = style.PALETTE
        (self.lines,) = ax.plot([], [], color=pal["curve"], linewidth=1.6, solid_joinstyle="round", zorder=2)
        (self.dots,) = ax.plot([], [], "o", color=pal["point"], markersize=3.5, zorder=3)
        ax.set_adjustable("box")
        self.ax = ax

    def set(self, polylines):
        x, y = stroke_data(polylines)
        self.lines.set_data(x, y)
        dots = codo.vertices(polylines)
        self.dots.set_data(dots[:, 0], dots[:, 1])
        _fit(self.ax, dots)
        return dots


def plot_drawing(polylines, ax=None, *, title: str | None = None):
    """Draw CODO polylines and their dots (Goldman §5.2); returns the axes.

    >>> plot_drawing(codo.run(codo.SAMPLES["nested squares"])).lines[1].get_xydata().shape
    (25, 2)
    """
    ax = style.get_axes(ax)
    _DrawingArtists(ax).set([np.asarray(p, dtype=float) for p in polylines])
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def plot_program(program, ax=None, *, title: str | None = None):
    """Run a CODO program and draw it (Goldman §5.2.2); returns the axes.  Raises as
    :func:`goldman_lib.codo.run`.

    >>> len(plot_program(codo.SAMPLES["spiral"]).lines)
    2
    """
    return plot_drawing(codo.run(program), ax, title=title)


_HELP = ("<small><code>P = point(x, y)</code>, <code>v = vector(x, y)</code>, <code>P + v</code>, "
         "<code>Q - P</code>, <code>(P + Q)/2</code>; maps <code>translate(v)</code>, <code>rotate(C, a)</code>, "
         "<code>scale(C, s)</code>, <code>scale(C, w, s)</code>, <code>mirror(C, w)</code>, "
         "<code>affine(P1, P2, P3, Q1, Q2, Q3)</code>, applied as <code>M(P)</code>, composed as "
         "<code>M * N</code>; <code>CONNECT P, Q, ...</code>, <code>DRAW F</code>, "
         "<code>REPEAT n [ ... ]</code>; one statement a line or <code>;</code>. "
         "Press Tab or click outside the box to draw. Try: "
         f'<code class="goldman-example">{TRY_PROGRAM}</code></small>')


def codo_program_editor(program: str = DEFAULT_PROGRAM, *, figsize=style.FIGSIZE) -> InteractiveView:
    """A text box for a CODO program with live drawing (Goldman §5.2); the course's one program
    editor (:mod:`goldman_lib.widgets.program_editor`, shared with the turtle) running CODO.

    program: the initial text.  A program that does not parse or run leaves the last good
    drawing and shows the message ("line 3, column 7, at '+': ...") in the status line.  An
    example picker (``view.examples``) fills the box with the samples of
    :data:`goldman_lib.codo.SAMPLES`.  ``update(program)`` returns ``{"polylines", "dots",
    "status"}`` and raises :class:`goldman_lib.codo.CodoError` (a ValueError) for a bad program.

    >>> codo_program_editor("P = point(0, 0)\\nQ = P + P").last_error.split(": ")[0]
    'CodoTypeError'
    """
    def make_runner(ax):
        artists = _DrawingArtists(ax)

        def run(program):
            d = codo.execute(program)
            dots = artists.set(d.polylines)
            n = len(d.polylines)
            kinds = {}
            for v in d.variables.values():
                k = type(v).__name__.lower().replace("ndarray", "map").replace("float", "number")
                kinds[k] = kinds.get(k, 0) + 1
            held = ", ".join(f"{c} {k}{'s' * (c != 1)}" for k, c in sorted(kinds.items()))
            status = (f"{d.steps} statement{'s' * (d.steps != 1)} run; {n} polyline{'s' * (n != 1)} through "
                      f"{len(dots)} dots; variables: {held or 'none'}")
            return {"polylines": d.polylines, "dots": dots, "status": status}

        return run

    return program_editor(program, make_runner=make_runner, examples=codo.SAMPLES, help_html=_HELP,
                          title="CODO program editor", picker_label="(samples)", rows=10, height="200px",
                          figsize=figsize)


#: Turtle programs the shortcoming view offers.
TURTLE_PROGRAMS = {"square": turtle.polygon(4), "hexagon": turtle.polygon(6), "{5/2} star": turtle.star(5, 2),
                   "L": "FORWARD 2 TURN 90 FORWARD 0.5 TURN 90 FORWARD 1.5 TURN -90 FORWARD 1.5 TURN 90 "
                        "FORWARD 0.5 TURN 90 FORWARD 2"}


def turtle_shortcoming_view(program: str = "square", sx: float = 2.0, sy: float = 1.0,
                            shear: float = 0.0) -> InteractiveView:
    """The affine image of a turtle drawing, and the closest drawing the turtle can make by
    changing its initial state (Goldman §5.1, the second shortcoming).

    The map is ``scaling(sx, sy)`` followed by the shear ``(x, y) -> (x + shear*y, y)``.  CODO
    draws the image exactly (solid blue); the best the turtle can do from any initial state
    ``(P, w)`` is a similar copy (dashed red), :func:`goldman_lib.codo.closest_turtle_state`.
    When ``sx == sy`` and ``shear == 0`` the gap is zero.  ``update(program, sx, sy, shear)``
    returns ``{"image", "turtle", "residual", "status"}``.
    """
    import ipywidgets as widgets

    if program not in TURTLE_PROGRAMS:
        raise ValueError(f"program must be one of {list(TURTLE_PROGRAMS)}; got {program!r}")
    controls = {
        "program": dropdown("turtle", list(TURTLE_PROGRAMS), program, label_width="48px", width="290px"),
        "sx": float_slider("s_x", sx, 0.2, 3, 0.05),
        "sy": float_slider("s_y", sy, 0.2, 3, 0.05),
        "shear": float_slider("shear", shear, -1.5, 1.5, 0.05),
    }
    fig, ax = style.new_axes()
    pal = style.PALETTE
    (img_line,) = ax.plot([], [], color=pal["curve"], linewidth=2)
    (tur_line,) = ax.plot([], [], color=pal["point"], linewidth=1.5, linestyle="--")
    (start,) = ax.plot([], [], "o", color=pal["point"], markersize=5)
    legend = widgets.HTML(f'<small><div><b style="color:{pal["curve"]}">&#9473;&#9473;</b> the affine image '
                          f'(CODO draws it exactly)</div><div><b style="color:{pal["point"]}">- - -</b> the '
                          f'closest turtle drawing, from the best initial state (&#9679;)</div></small>',
                          layout=widgets.Layout(width="290px"))
    ax.set_adjustable("box")

    def update(program, sx, sy, shear):
        text = TURTLE_PROGRAMS[program]
        M = affine.scaling([sx, sy]) @ affine.shear(shear)
        image = [affine.apply(p, M) for p in turtle.run(text)]
        fit = codo.closest_turtle_state(text, image)
        best = turtle.run(text, point=fit.point, direction=fit.direction)
        _set_lines(img_line, image)
        _set_lines(tur_line, best)
        start.set_data([fit.point[0]], [fit.point[1]])
        _fit(ax, np.concatenate(image + best))
        status = (f"best turtle state P = ({fit.point[0]:.3f}, {fit.point[1]:.3f}), w = ({fit.direction[0]:.3f}, "
                  f"{fit.direction[1]:.3f}); largest gap to the image {fit.residual:.3f}")
        return {"image": image, "turtle": best, "residual": fit.residual, "status": status}

    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="What no turtle state can draw: a nonuniform image", side=True,
                           extra=[legend])


def _set_lines(line, polylines):
    x, y = stroke_data(polylines)
    line.set_data(x, y)

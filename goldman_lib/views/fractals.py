"""Chapter 2-3 views: recursive turtle fractals by level, the looping lemmas, and the base case
that does not matter (Goldman §2.2-2.3, §3.2-3.4).

Plot functions take ``ax=None`` and return the axes; widget factories return an
:class:`~goldman_lib.widgets.interactive.InteractiveView` (not displayed) whose ``update`` is a
plain function returning what it drew.  Strokes are drawn as one Line2D with a NaN row between
strokes (the drawing of :mod:`goldman_lib.views.turtle`), so a level-7 Koch curve redraws quickly.

>>> view = fractal_explorer()
>>> out = view.update(**view.values())
>>> out["status"]
'Koch curve, level 4: 256 segments, 1 stroke, ink length 3.16 = (4/3)^4, dimension 1.262'
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import fractals, turtle
from goldman_lib.validation import as_float, as_int
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import dropdown, figure_widget, float_slider, int_slider, InteractiveView
from goldman_lib.views.turtle import PathArtists, plot_polylines, stroke_data

__all__ = ["plot_fractal", "fractal_explorer", "looping_lemma_explorer", "base_case_explorer",
           "GROWS_UP", "MAX_DRAWN", "shown_level", "BASE_OPTIONS"]

#: Fractals drawn growing upwards (the turtle starts heading (0, 1)).
GROWS_UP = ("fractal tree", "fractal bush")
#: The most turtle commands a widget draws per slider move (keeps update + redraw under 50 ms).
MAX_DRAWN = 50_000


def _direction(name: str):
    return (0.0, 1.0) if name in GROWS_UP else (1.0, 0.0)


def shown_level(program: fractals.RecursiveTurtleProgram, level: int, max_commands: int = MAX_DRAWN) -> int:
    """The level a view draws for a requested ``level``: the same, or the highest level of at most
    ``max_commands`` commands if ``level`` needs more.

    >>> shown_level(fractals.koch_curve_program(), 8)
    7
    """
    level = as_int(level, "level", minimum=0)
    return min(level, program.max_level(max_commands))


def plot_fractal(name: str = "Koch curve", level: int = 4, ax=None, *, title: str | None = None, **kwargs):
    """Draw level ``level`` of a fractal of :data:`goldman_lib.fractals.PROGRAMS` (Goldman §2.3).

    name: a key of ``PROGRAMS``.  Trees and bushes grow upwards.  Returns the axes.  Raises
    ValueError for an unknown name or a level beyond the turtle's command limit.

    >>> len(plot_fractal("Sierpinski gasket", 2).lines[0].get_xydata())
    44
    """
    if name not in fractals.PROGRAMS:
        raise ValueError(f"name must be one of {sorted(fractals.PROGRAMS)}; got {name!r}")
    prog = fractals.PROGRAMS[name]()
    t = prog.trace(level, direction=_direction(name))
    return plot_polylines(t.polylines, ax, point=t.point, direction=t.direction,
                          start=np.zeros(2), title=title if title is not None else f"{name}, level {level}",
                          linewidth=kwargs.pop("linewidth", 1.0), **kwargs)


def _fraction(x: float) -> str:
    from fractions import Fraction

    f = Fraction(x).limit_denominator(12)
    return f"{f.numerator}/{f.denominator}" if abs(float(f) - x) < 1e-12 and f.denominator > 1 else None


def fractal_explorer(name: str = "Koch curve", level: int = 4, *, figsize=style.FIGSIZE) -> InteractiveView:
    """A fractal picker and a depth slider for the recursive turtle programs of Goldman §2.3.

    name: a key of :data:`goldman_lib.fractals.PROGRAMS` (gaskets, Koch curve and snowflake,
    C-curve, dragon, tree, bush).  level: 0..8; a level that needs more than :data:`MAX_DRAWN`
    commands is drawn at the highest level that fits, and the status says so.
    ``update(name, level)`` returns ``{"polylines", "point", "direction", "level", "status"}``.

    >>> fractal_explorer("dragon curve", 8).last_result["level"]
    8
    """
    import ipywidgets as widgets

    if name not in fractals.PROGRAMS:
        raise ValueError(f"name must be one of {sorted(fractals.PROGRAMS)}; got {name!r}")
    level = as_int(level, "level", minimum=0, maximum=8)
    controls = {
        "name": dropdown("fractal", list(fractals.PROGRAMS), name, label_width="48px", width="290px"),
        "level": int_slider("level", level, 0, 8),
    }
    fig, ax = style.new_axes(figsize)
    artists = PathArtists(ax, linewidth=1.0)
    programs = {k: f() for k, f in fractals.PROGRAMS.items()}
    text = widgets.HTML(layout=widgets.Layout(width="290px"))

    def update(name, level):
        prog = programs[name]
        shown = shown_level(prog, level)
        t = prog.trace(shown, direction=_direction(name))
        artists.set(t.polylines, (0.0, 0.0), t.point, t.direction)
        segments = int(sum(len(p) - 1 for p in t.polylines))
        strokes = len(t.polylines)
        ink = fractals.ink_length(prog, shown)
        scales = fractals.recursion_scales(prog)
        grow = float(scales.sum())
        frac = _fraction(grow)
        growth = f" = ({frac})^{shown}" if frac and name in ("Koch curve", "C-curve", "dragon curve") else ""
        status = (f"{name}, level {shown}: {segments:,} segment{'s' * (segments != 1)}, {strokes:,} "
                  f"stroke{'s' * (strokes != 1)}, ink length {ink:.3g}{growth}, dimension "
                  f"{fractals.program_dimension(prog):.3f}")
        if shown < level:
            status += f"  (level {level} needs {prog.count(level):,} commands; showing level {shown})"
        text.value = "<pre style='font-size:10px;line-height:1.2'>" + _program_html(prog) + "</pre>"
        return {"polylines": t.polylines, "point": t.point, "direction": t.direction, "level": shown,
                "status": status}

    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Recursive turtle fractals: pick a fractal, move the level", side=True,
                           extra=[text])


def _program_html(prog) -> str:
    import html

    def wrap(cmds):
        words = fractals.program_text(cmds).replace("RECURSE(mirror)", "MIRROR").split(" ")
        lines, line = [], ""
        for w in words:
            if len(line) + len(w) > 40:
                lines.append(line)
                line = ""
            line += ("" if not line else " ") + w
        return "\n    ".join(lines + [line])

    out = [prog.name, f"level 0: {wrap(prog.base)}", f"level n: {wrap(prog.body)}"]
    if prog.start != ((fractals.RECURSE, None),):
        out.append(f"drawn by: {wrap(prog.start)}")
    return html.escape("\n".join(out).replace("RECURSE", "R"))


def looping_lemma_explorer(angle: float = 150.0, repetitions: int = 12, bend: float = 0.0, *,
                           figsize=style.FIGSIZE) -> InteractiveView:
    """The looping lemmas (Goldman §2.2): ``REPEAT k [FORWARD 1 TURN bend FORWARD 1 TURN angle-bend]``.

    angle: the total turning ``T`` of one pass (degrees, 0..360); repetitions: ``k`` (1..72);
    bend: a turn inside the pass (0 gives ``FORWARD 1 TURN T`` with one FORWARD).  Draws the
    path, the circle about the centre ``c = d / (1 - e^{iT})`` through the pass starts, and the
    pass starts.  ``update(angle, repetitions, bend)`` returns ``{"polylines", "starts",
    "center", "closes", "period", "status"}``; the status compares ``k T`` with 360.

    >>> looping_lemma_explorer(144, 5).last_result["status"]
    'T = 144°, k = 5: k·T = 720° = 2·360°, so the turtle is back where it started. Period 5: a {5/2} star'
    """
    angle = as_float(angle, "angle")
    repetitions = as_int(repetitions, "repetitions", minimum=1, maximum=72)
    bend = as_float(bend, "bend")
    wide = {"width": "330px", "label_width": "80px"}
    controls = {
        "angle": float_slider("total turn T", angle, 0, 360, 1, readout=".0f", **wide),
        "repetitions": int_slider("REPEAT k", repetitions, 1, 72, **wide),
        "bend": float_slider("inner bend", bend, -90, 90, 5, readout=".0f", **wide),
    }
    fig, ax = style.new_axes(figsize)
    artists = PathArtists(ax, linewidth=1.4)
    pal = style.PALETTE
    (circle,) = ax.plot([], [], ":", color=pal["control"], linewidth=1, zorder=1)
    (starts_line,) = ax.plot([], [], "o", color=pal["accent"], markersize=4, zorder=3)
    (centre,) = ax.plot([], [], "+", color=pal["point"], markersize=10, zorder=3)
    theta = np.linspace(0, 2 * np.pi, 181)

    def update(angle, repetitions, bend):
        a, b, k = round(float(angle), 6), round(float(bend), 6), int(repetitions)
        body = [("FORWARD", 1.0)] + ([("TURN", b), ("FORWARD", 1.0)] if b else []) + [("TURN", a - b)]
        loop = fractals.loop_analysis(body)
        codes, values = fractals.program_codes(body)
        t = turtle.trace_arrays(np.tile(codes, k), np.tile(values, k), np.zeros(2), np.array([1.0, 0.0]))
        per = len(t.polylines[0]) // k if t.polylines else 1
        starts = t.polylines[0][::per] if t.polylines else np.zeros((1, 2))
        artists.set(t.polylines, (0.0, 0.0), t.point, t.direction)
        centre_xy = np.zeros((0, 2))
        if loop.center is not None and np.hypot(*loop.center) < 1e3:
            r = float(np.hypot(*loop.center))
            circle.set_data(loop.center[0] + r * np.cos(theta), loop.center[1] + r * np.sin(theta))
            centre.set_data([loop.center[0]], [loop.center[1]])
            centre_xy = loop.center[None, :]
        else:
            circle.set_data([], [])
            centre.set_data([], [])
        starts_line.set_data(starts[:, 0], starts[:, 1])
        closes = fractals.repeat_closes(body, k, tol=1e-7)
        kt = k * a
        multiple = abs(kt / 360 - round(kt / 360)) < 1e-9
        ktxt = f"k·T = {turtle.format_number(round(kt, 6))}°"
        if multiple:
            ktxt += f" = {round(kt / 360)}·360°"
        else:
            ktxt += " (not a multiple of 360°)"
        if loop.kind in ("polygon", "star"):
            shape = "a regular polygon" if loop.kind == "polygon" else f"a {{{loop.period}/{abs(loop.winding)}}} star"
            if b:
                shape = f"{loop.period}-fold symmetric"
            tail = f"Period {loop.period}: {shape}"
        elif loop.kind == "drift":
            tail = "T is a multiple of 360°: every pass is the last one shifted, the path drifts away"
        elif loop.kind == "retrace":
            tail = "one pass already returns to the start"
        else:
            tail = "T is not a rational multiple of 360° (to 1/10000): it never closes"
        verdict = "so the turtle is back where it started" if closes else "so the turtle is not back"
        status = f"T = {turtle.format_number(a)}°, k = {k}: {ktxt}, {verdict}. {tail}"
        return {"polylines": t.polylines, "starts": starts, "center": centre_xy, "closes": closes,
                "period": loop.period or 0, "status": status}

    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Looping lemma: REPEAT k [pass with total turning T]", side=True)


def _base_options() -> dict:
    short = {"Koch curve": "Koch", "Sierpinski gasket": "gasket"}
    return {f"{short[f]}: {b}": (f, b) for f, bases in fractals.BASE_CASES.items() for b in bases}


#: The base-case picker's options: label -> (fractal name, base-case name).
BASE_OPTIONS = _base_options()


def base_case_explorer(base: str = "Koch: tent", level: int = 1, *, figsize=style.WIDE_FIGSIZE) -> InteractiveView:
    """Different base cases, one fractal (Goldman §3.4): pick a base case, raise the level, and
    watch the drawing close in on the fractal drawn (grey) from the book's base case.

    base: a key of :data:`BASE_OPTIONS` (Koch curve or Sierpinski gasket with one of the base
    cases of :data:`goldman_lib.fractals.BASE_CASES`).  level: 0..5.  Left: the base case alone
    (level 0).  Right: level n with that base over level 5 with the book's base.  The status
    gives the Hausdorff distance to the book's base's drawing at the same level, which shrinks
    by the scale (1/3 or 1/2) per level.  ``update(base, level)`` returns ``{"base_polylines",
    "polylines", "reference", "distance", "status"}``.

    >>> round(base_case_explorer("gasket: square", 0).last_result["distance"], 6)
    0.517638
    """

    if base not in BASE_OPTIONS:
        raise ValueError(f"base must be one of {list(BASE_OPTIONS)}; got {base!r}")
    level = as_int(level, "level", minimum=0, maximum=5)
    controls = {
        "base": dropdown("base case", list(BASE_OPTIONS), base, label_width="64px", width="300px"),
        "level": int_slider("level", level, 0, 5),
    }
    fig = style.new_figure(figsize)
    ax0 = fig.add_subplot(1, 3, 1)
    ax1 = fig.add_subplot(1, 3, (2, 3))
    for ax in (ax0, ax1):
        style.style_axes(ax, equal=True)
        ax.set_axis_off()  # pictures of shapes: no coordinates needed, and ticks cost redraw time
    pal = style.PALETTE
    (ref_line,) = ax1.plot([], [], color="#c8c8c8", linewidth=2.0, zorder=1)
    (cur_line,) = ax1.plot([], [], color=pal["curve"], linewidth=1.0, zorder=2)
    base_artists = PathArtists(ax0, linewidth=1.6)
    programs = {f: fractals.PROGRAMS[f]() for f in fractals.BASE_CASES}
    reference = {f: p.polylines(5) for f, p in programs.items()}
    distances: dict = {}  # (base, level) -> Hausdorff distance, computed on the first visit
    limits = {"Koch curve": ((-0.05, 1.05), (-0.45, 0.6)), "Sierpinski gasket": ((-0.1, 1.1), (-0.15, 1.0))}

    def update(base, level):
        fractal, name = BASE_OPTIONS[base]
        prog = programs[fractal]
        alt = prog.with_base(fractals.BASE_CASES[fractal][name])
        t0 = alt.trace(0)
        base_artists.set(t0.polylines, (0.0, 0.0), t0.point, t0.direction)
        ax0.set_title("the base case (level 0)", fontsize=9)
        polys = alt.polylines(int(level))
        cur_line.set_data(*stroke_data(polys))
        ref_line.set_data(*stroke_data(reference[fractal]))
        (x0, x1), (y0, y1) = limits[fractal]
        ax1.set_xlim(x0, x1)
        ax1.set_ylim(y0, y1)
        ax1.set_title(f"level {level} (blue) and the {fractal} (grey)", fontsize=9)
        key = (base, int(level))
        if key not in distances:
            distances[key] = float(fractals.base_case_distances(prog, [alt.base], [int(level)],
                                                                per_segment=1)[0, 0])
        d = distances[key]
        s = float(fractals.recursion_scales(prog).max())
        status = (f"{fractal} from the base case '{name}', level {level}: Hausdorff distance "
                  f"{d:.3g} to the book's drawing at level {level} (shrinks by {_fraction(s)} per level)")
        return {"base_polylines": t0.polylines, "polylines": polys, "reference": reference[fractal],
                "distance": d, "status": status}

    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Attraction: any base case, the same fractal")

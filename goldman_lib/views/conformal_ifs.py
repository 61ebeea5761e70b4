"""Chapter 8 views: the same fractal drawn by the turtle and by a conformal IFS (Goldman §8.2-8.5).

* :func:`plot_turtle_and_ifs` draws a recursive turtle program beside the IFS that Ron's
  algorithm makes of it (static figure).
* :func:`initial_state_view` (§8.2): a fractal drawn from the standard state and from a state
  set by sliders, with the similarity between the two drawings.
* :func:`turtle_ifs_view` (§8.3-8.4): fractal picker, level slider and initial-state sliders;
  left the recursive turtle program's drawing, right the deterministic algorithm of the IFS that
  Ron's algorithm produced, each top-level copy in its map's colour; the Hausdorff distance
  between the two drawings in the status line.
* :func:`tao_view` (§8.4): the shared IFS map editor (:mod:`goldman_lib.widgets.ifs_editor`)
  above, and below the turtle program that Tao's algorithm writes for the edited IFS, drawn by
  the turtle.  A map the turtle cannot follow (a shear, unequal scales, a reflection) is named
  in the status line.
* :func:`bump_view` (§8.5): a bump picker, its height and a level; the bump program and the
  bump IFS side by side.

Every ``update`` is a plain function returning what it drew (lists of ``(k, 2)`` strokes, no
NaN) and a ``status`` string; it never raises (a message goes to the status line instead).

>>> view = turtle_ifs_view()
>>> out = view.update(**view.values())
>>> out["distance"] < 1e-12, len(out["turtle"]) == 1
(True, True)
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import affine, fixed_point, fractals, turtle
from goldman_lib import conformal_ifs as cf
from goldman_lib.validation import as_float, as_int
from goldman_lib.widgets import style
from goldman_lib.widgets.drag import drag_sliders
from goldman_lib.widgets.interactive import dropdown, figure_widget, float_slider, int_slider, InteractiveView
from goldman_lib.views.turtle import stroke_data

__all__ = ["plot_turtle_and_ifs", "initial_state_view", "turtle_ifs_view", "tao_view", "bump_view",
           "MAX_COMMANDS", "MAX_SEGMENTS", "map_pieces"]

#: The most turtle commands a view draws; higher levels are lowered to fit (and the status says so).
MAX_COMMANDS = 30_000
#: The most segments (about) the IFS panel draws.
MAX_SEGMENTS = 30_000

_COLOURS = ["#1f4e9c", "#d1495b", "#1b7f3b", "#edae49", "#5c3c92", "#00798c", "#9c6644", "#8f2d56"]
_GREY = "#777777"


def _heading(angle: float, scale: float) -> np.ndarray:
    a = math.radians(angle)
    return scale * np.array([math.cos(a), math.sin(a)])


def _bounds(polylines, extra=()) -> np.ndarray:
    """``[[xmin, ymin], [xmax, ymax]]`` of the strokes and extra points (one pass, for both panels)."""
    parts = [np.asarray(p, float) for p in polylines if len(p)] + [np.asarray(e, float).reshape(-1, 2) for e in extra]
    xy = np.concatenate(parts) if parts else np.zeros((1, 2))
    return np.array([xy.min(axis=0), xy.max(axis=0)])


def _fit(ax, polylines, extra=(), pad: float = 0.08, bounds=None):
    """Equal scales on both axes, fitted to the strokes (and extra points), or to ``bounds`` from
    :func:`_bounds`; box unchanged."""
    lo, hi = _bounds(polylines, extra) if bounds is None else bounds
    span = np.maximum(hi - lo, 1e-6) * (1 + 2 * pad)
    mid = (lo + hi) / 2
    box = ax.get_position()
    w, h = ax.figure.get_size_inches() * (box.width, box.height)
    scale = max(span[0] / w, span[1] / h)
    ax.set_xlim(mid[0] - scale * w / 2, mid[0] + scale * w / 2)
    ax.set_ylim(mid[1] - scale * h / 2, mid[1] + scale * h / 2)


def _fitting_level(program, level: int, max_commands: int = MAX_COMMANDS) -> int:
    return min(level, program.max_level(max_commands))


def map_pieces(conv: cf.TurtleIFS, level: int) -> tuple[list, list]:
    """The IFS drawing of level ``level`` split by the map that placed each piece (Goldman §8.3):
    ``(pieces, condensation)`` where ``pieces[i]`` holds the strokes of ``T_i(G_{level-1})``
    under every placement, and ``condensation`` the strokes of ``C`` (and the driver's own
    strokes).  At level 0 the base drawing is ``pieces[0]`` and the others are empty.

    >>> pieces, cond = map_pieces(cf.rons_algorithm(fractals.c_curve_program()), 1)
    >>> [len(p) for p in pieces], cond
    ([1, 1], [])
    """
    level = as_int(level, "level", minimum=0)
    k = len(conv.maps)
    pieces: list = [[] for _ in range(k)]
    cond = list(conv.frame)
    placements = conv.placements
    if level == 0:
        for U in placements:
            pieces[0].extend(cf.transform_polylines(conv.base, U))
        return pieces, cond
    below = cf.ifs_polylines(conv.maps, level - 1, conv.base, conv.condensation)
    for U in placements:
        for i, T in enumerate(conv.maps):
            pieces[i].extend(cf.transform_polylines(below, T @ U))
        cond.extend(cf.transform_polylines(conv.condensation, U))
    return pieces, cond


def _segments(polylines) -> int:
    return int(sum(max(len(p) - 1, 0) for p in polylines))


def plot_turtle_and_ifs(program, level: int = 4, *, point=(0, 0), direction=(1, 0), fig=None):
    """Draw a recursive turtle program (left) beside the IFS of Ron's algorithm (right), each
    top-level copy in its map's colour (Goldman §8.3-8.4).  Returns the figure.

    program: a :class:`goldman_lib.fractals.RecursiveTurtleProgram` or a name of
    :data:`goldman_lib.fractals.PROGRAMS`.  Raises as :func:`goldman_lib.conformal_ifs.rons_algorithm`.

    >>> len(plot_turtle_and_ifs("Koch curve", 2).axes)
    2
    """
    if isinstance(program, str):
        program = fractals.PROGRAMS[program]()
    conv = cf.rons_algorithm(program, point, direction)
    if fig is None:
        fig = style.new_figure(style.WIDE_FIGSIZE)
    left, right = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    for ax in (left, right):
        style.style_axes(ax, equal=False)
    strokes = program.polylines(level, point, direction)
    left.plot(*stroke_data(strokes), color=style.PALETTE["curve"], linewidth=1.0)
    pieces, cond = map_pieces(conv, level)
    for i, piece in enumerate(pieces):
        right.plot(*stroke_data(piece), color=_COLOURS[i % len(_COLOURS)], linewidth=1.0)
    right.plot(*stroke_data(cond), color=_GREY, linewidth=1.0)
    allp = [p for piece in pieces for p in piece] + cond
    for ax in (left, right):
        _fit(ax, strokes + allp)
    left.set_title(f"turtle: {program.name}, level {level}", fontsize=10)
    right.set_title(f"IFS of Ron's algorithm: {len(conv.maps)} maps, level {level}", fontsize=10)
    return fig


def _state_arrow(ax, colour):
    (line,) = ax.plot([], [], "-", color=colour, linewidth=2.2, zorder=5)
    (dot,) = ax.plot([], [], "o", color=colour, markersize=5, zorder=5)
    return line, dot


def _set_arrow(artists, p, w):
    line, dot = artists
    line.set_data([p[0], p[0] + w[0]], [p[1], p[1] + w[1]])
    dot.set_data([p[0]], [p[1]])


# ---------------------------------------------------------------------------------------------
# §8.2
# ---------------------------------------------------------------------------------------------

def initial_state_view(fractal: str = "Koch curve", level: int = 2, x: float = 0.5, y: float = 1.0,
                       angle: float = 30.0, scale: float = 0.75) -> InteractiveView:
    """Changing the turtle's initial state (Goldman §8.2): the drawing from the standard state
    ``((0, 0), (1, 0))`` in grey, the drawing from ``P = (x, y)``, ``w = scale (cos angle, sin
    angle)`` in blue, and the standard drawing mapped by the similarity ``M =
    state_map(P, w)`` as orange dots on top: they land exactly on the blue drawing.  P can be
    dragged with the mouse (``view.drag``).

    ``update(fractal, level, x, y, angle, scale)`` returns ``{"standard", "moved", "mapped"
    (lists of strokes), "matrix" (3, 3), "error" (largest distance between moved and mapped
    vertices), "status"}``.

    >>> initial_state_view().last_result["error"] < 1e-12
    True
    """

    if fractal not in fractals.PROGRAMS:
        raise ValueError(f"fractal must be one of {sorted(fractals.PROGRAMS)}; got {fractal!r}")
    controls = {
        "fractal": dropdown("fractal", list(fractals.PROGRAMS), fractal, label_width="60px", width="290px"),
        "level": int_slider("level", as_int(level, "level", minimum=0, maximum=5), 0, 5),
        "x": float_slider("P x", as_float(x, "x"), -2, 2, 0.05),
        "y": float_slider("P y", as_float(y, "y"), -2, 2, 0.05),
        "angle": float_slider("angle", as_float(angle, "angle"), -180, 180, 1, readout=".0f"),
        "scale": float_slider("|w|", as_float(scale, "scale", positive=True), 0.1, 2, 0.05),
    }
    fig, ax = style.new_axes()
    ax.set_aspect("auto")
    (standard_line,) = ax.plot([], [], color="#b0b0b0", linewidth=1.2)
    (moved_line,) = ax.plot([], [], color=style.PALETTE["curve"], linewidth=1.4)
    (mapped_dots,) = ax.plot([], [], ".", color=style.PALETTE["accent"], markersize=3.5)
    std_arrow = _state_arrow(ax, "#888888")
    new_arrow = _state_arrow(ax, style.PALETTE["point"])
    title = ax.set_title("", fontsize=10)
    frame: dict = {}

    def update(fractal, level, x, y, angle, scale):
        program = fractals.PROGRAMS[fractal]()
        lev = _fitting_level(program, int(level), 8000)
        w = _heading(angle, scale)
        standard = program.polylines(lev)
        moved = program.polylines(lev, (x, y), w)
        M = cf.state_map((x, y), w)
        mapped = cf.transform_polylines(standard, M)
        gaps = [np.abs(a - b).max() for a, b in zip(moved, mapped) if len(a)]
        error = float(max(gaps)) if gaps and len(moved) == len(mapped) else float("inf")
        standard_line.set_data(*stroke_data(standard))
        moved_line.set_data(*stroke_data(moved))
        dots = np.concatenate(mapped) if mapped else np.zeros((0, 2))
        mapped_dots.set_data(dots[:, 0], dots[:, 1])
        _set_arrow(std_arrow, (0.0, 0.0), (1.0, 0.0))
        _set_arrow(new_arrow, (x, y), w)
        if not frame.get("hold"):
            _fit(ax, standard + moved, extra=[[0, 0], [1, 0], [x, y], [x + w[0], y + w[1]]])
        title.set_text(f"{program.name}, level {lev}: from ((0,0),(1,0)) and from (P, w)")
        status = (f"M = rotate {angle:.0f}°, scale {scale:.2f}, translate ({x:.2f}, {y:.2f});  "
                  f"largest |turtle from (P,w) − M(turtle from standard)| = {error:.1e}")
        if lev < int(level):
            status += f"; level lowered to {lev} to stay quick"
        return {"standard": standard, "moved": moved, "mapped": mapped, "matrix": M,
                "error": error if np.isfinite(error) else -1.0, "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§8.2 Changing the turtle's initial state", side=True)
    _drag_start(view, ax, frame)
    return view


def _drag_start(view, ax, frame):
    """Let the mouse drag the turtle's start P (the sliders ``x``, ``y``) in ``ax``; while P is held
    the axes keep their limits (``frame["hold"]``), so P stays under the mouse, and refit on release."""
    drag = drag_sliders(view, ax, [("x", "y")])
    grab = drag.on_drag

    def on_drag(k, x, y):
        frame["hold"] = True
        grab(k, x, y)

    def on_release(k):
        if frame.pop("hold", False):
            view.refresh()

    drag.on_drag, drag.on_release = on_drag, on_release
    return drag


# ---------------------------------------------------------------------------------------------
# §8.3-8.4 turtle vs IFS
# ---------------------------------------------------------------------------------------------

def _two_panels():
    fig = style.new_figure(style.WIDE_FIGSIZE)
    fig.subplots_adjust(left=0.04, right=0.98, bottom=0.06, top=0.9, wspace=0.08)
    left, right = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    for ax in (left, right):
        style.style_axes(ax, equal=False)
        style.few_ticks(ax)       # drawings, not graphs: a few ticks, and a slider move redraws faster
    return fig, left, right


def turtle_ifs_view(fractal: str = "Koch curve", level: int = 4, x: float = 0.0, y: float = 0.0,
                    angle: float = 0.0, scale: float = 1.0) -> InteractiveView:
    """Turtle and IFS drawings side by side (Goldman §8.3-8.4): Ron's algorithm converts the
    chosen recursive turtle program, started in the state ``P = (x, y)``, ``w = scale (cos
    angle, sin angle)``, into a conformal IFS; the left panel is the turtle's level, the right
    the deterministic algorithm's level of the IFS (each top-level copy ``T_i(G_{n-1})`` in its
    own colour, the condensation set in grey).  The status line gives the Hausdorff distance
    between the two drawings (zero up to rounding: the equivalence theorem).  P can be dragged
    with the mouse in the left panel (``view.drag``).

    ``update(fractal, level, x, y, angle, scale)`` returns ``{"turtle", "ifs" (lists of
    strokes), "pieces" (strokes per map), "maps" (k, 3, 3), "distance", "level", "status"}``.
    Levels whose drawing would need more than :data:`MAX_COMMANDS` turtle commands are lowered.

    >>> view = turtle_ifs_view("dragon curve", 6)
    >>> view.last_result["maps"].shape, view.last_result["distance"] < 1e-12
    ((2, 3, 3), True)
    """

    if fractal not in fractals.PROGRAMS:
        raise ValueError(f"fractal must be one of {sorted(fractals.PROGRAMS)}; got {fractal!r}")
    controls = {
        "fractal": dropdown("fractal", list(fractals.PROGRAMS), fractal, label_width="60px", width="290px"),
        "level": int_slider("level", as_int(level, "level", minimum=0, maximum=8), 0, 8),
        "x": float_slider("P x", as_float(x, "x"), -1, 1, 0.05),
        "y": float_slider("P y", as_float(y, "y"), -1, 1, 0.05),
        "angle": float_slider("angle", as_float(angle, "angle"), -180, 180, 1, readout=".0f"),
        "scale": float_slider("|w|", as_float(scale, "scale", positive=True), 0.25, 2, 0.05),
    }
    fig, left, right = _two_panels()
    (turtle_line,) = left.plot([], [], color=style.PALETTE["curve"], linewidth=0.9)
    arrow = _state_arrow(left, style.PALETTE["point"])
    piece_lines = [right.plot([], [], color=c, linewidth=0.9)[0] for c in _COLOURS]
    (cond_line,) = right.plot([], [], color=_GREY, linewidth=0.9)
    left_title = left.set_title("", fontsize=10, y=1.0)
    right_title = right.set_title("", fontsize=10, y=1.0)
    cache: dict = {}
    frame: dict = {}

    def update(fractal, level, x, y, angle, scale):
        program = fractals.PROGRAMS[fractal]()
        w = _heading(angle, scale)
        key = (fractal, float(x), float(y), float(angle), float(scale))
        conv = cache.get(key)
        if conv is None:
            cache.clear()
            conv = cache[key] = cf.rons_algorithm(program, (x, y), w)
        lev = _fitting_level(program, int(level))
        strokes = program.polylines(lev, (x, y), w)
        pieces, cond = map_pieces(conv, lev)
        turtle_line.set_data(*stroke_data(strokes))
        _set_arrow(arrow, (x, y), w)
        for i, line in enumerate(piece_lines):
            # more maps than colours (the carpet has 8, the bush 3): wrap the colours
            group = [p for j in range(i, len(pieces), len(piece_lines)) for p in pieces[j]]
            line.set_data(*stroke_data(group))
        cond_line.set_data(*stroke_data(cond))
        drawn = [p for piece in pieces for p in piece] + cond
        box = _bounds(strokes + drawn, extra=[[x, y], [x + w[0], y + w[1]]])
        if not frame.get("hold"):
            for ax in (left, right):
                _fit(ax, (), bounds=box)
        distance = cf.drawing_distance(strokes, drawn)
        k = len(conv.maps)
        scales = sorted({round(float(f), 4) for f in fixed_point.contraction_factor(conv.maps)})
        left_title.set_text(f"turtle: {program.name}, level {lev}")
        right_title.set_text(f"IFS (Ron's algorithm): {k} maps, level {lev}")
        status = (f"Ron's algorithm: {k} similarities with scale {', '.join(f'{s:g}' for s in scales)}"
                  f"{', condensation set' if conv.condensation else ''}"
                  f"{', mirror calls' if conv.mirror is not None else ''};  "
                  f"{_segments(strokes)} turtle segments, {_segments(drawn)} IFS segments;  "
                  f"Hausdorff distance {distance:.1e}")
        if lev < int(level):
            status += f"  (level lowered to {lev} to stay quick)"
        return {"turtle": strokes, "ifs": drawn, "pieces": pieces, "maps": conv.maps, "distance": distance,
                "level": lev, "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Chapter 8: the turtle's drawing and the IFS's drawing, side by side")
    _drag_start(view, left, frame)
    return view


# ---------------------------------------------------------------------------------------------
# §8.4 Tao's algorithm with the IFS map editor
# ---------------------------------------------------------------------------------------------

def _program_text(program, width: int = 110) -> str:
    words = []
    for c, v in program.body:
        words.append("RECURSE" if c == "RECURSE" else f"{c} {turtle.format_number(round(v, 4))}")
    base = " ".join(f"{c} {turtle.format_number(round(v, 4))}" for c, v in program.base)
    lines, line = [], "level n:"
    for wd in words:
        if len(line) + len(wd) + 1 > width:
            lines.append(line)
            line = "        "
        line += " " + wd
    lines.append(line)
    return "level 0: " + base + "\n" + "\n".join(lines)


def tao_view(system: str = "C-curve", levels: int = 8) -> InteractiveView:
    """Tao's algorithm with the IFS map editor (Goldman §8.4): edit the maps of a conformal IFS
    in the shared editor; below, the recursive turtle program Tao's algorithm writes for it
    (MOVE/TURN/RESIZE to each map's state, RECURSE, and back) and the turtle's drawing of it,
    from the unit segment (or the condensation set's system) at the editor's level.

    system: a preset of :data:`goldman_lib.ifs.STANDARD`.  levels: the editor's deterministic
    level (0-12; the turtle's drawing is lowered to stay under :data:`MAX_COMMANDS` commands).
    ``update(**editor values)`` returns ``{"turtle" (strokes), "ifs" (strokes of the
    deterministic algorithm from the same base), "program" (text), "distance", "level", "status"}``; a
    map that is not an orientation-preserving similarity is named in the status and nothing is
    drawn.  ``view.editor`` is the embedded :func:`~goldman_lib.widgets.ifs_editor.ifs_editor`.

    >>> view = tao_view()
    >>> view.last_result["distance"] < 1e-9, view.last_result["program"].startswith("level 0: FORWARD 1")
    (True, True)
    """
    import ipywidgets as widgets

    from goldman_lib.widgets.ifs_editor import ifs_editor, system_from_values

    editor = ifs_editor(system, algorithm="deterministic", levels=as_int(levels, "levels", minimum=0, maximum=12))
    fig, left, right = _two_panels()
    fig.set_size_inches(style.WIDE_FIGSIZE[0], 3.4)
    (turtle_line,) = left.plot([], [], color=style.PALETTE["curve"], linewidth=0.9)
    (ifs_line,) = right.plot([], [], color=style.PALETTE["good"], linewidth=0.9)
    left_title = left.set_title("", fontsize=10, y=1.0)
    right_title = right.set_title("", fontsize=10, y=1.0)
    text = widgets.HTML(layout=widgets.Layout(width="960px"))
    unit = np.array([[0.0, 0.0], [1.0, 0.0]])

    def clear(message):
        turtle_line.set_data([], [])
        ifs_line.set_data([], [])
        left_title.set_text("turtle: no program")
        right_title.set_text("")
        text.value = ""
        return {"turtle": [], "ifs": [], "program": "", "distance": -1.0, "level": 0, "status": message}

    def update(**values):
        s = system_from_values(values)
        try:
            program = cf.tao_algorithm(s, unit)
        except ValueError as exc:
            return clear(f"Tao's algorithm refuses this IFS: {exc}")
        levels = values.get("levels", 0)
        level = min(levels, program.max_level(MAX_COMMANDS))
        cond = [s.condensation] if s.condensation is not None else []
        # keep the IFS drawing as small as the turtle's
        strokes = program.polylines(level)
        drawn = cf.ifs_polylines(s, level, [unit], cond)
        if not strokes or not drawn:
            return clear("nothing drawn")
        big = max(np.abs(np.concatenate(strokes)).max(), np.abs(np.concatenate(drawn)).max())
        if not np.isfinite(big) or big > 1e6:
            return clear("the drawing leaves the screen: make the maps contractions")
        turtle_line.set_data(*stroke_data(strokes))
        ifs_line.set_data(*stroke_data(drawn))
        box = _bounds(strokes + drawn)
        for ax in (left, right):
            _fit(ax, (), bounds=box)
        distance = cf.drawing_distance(strokes, drawn)
        ptext = _program_text(program)
        text.value = ("<pre style='font-size:11px;line-height:1.25;margin:0'>"
                      + ptext.replace("&", "&amp;").replace("<", "&lt;") + "</pre>")
        left_title.set_text(f"turtle running Tao's program, level {level}")
        right_title.set_text(f"IFS deterministic algorithm from the unit segment, level {level}")
        status = (f"Tao's algorithm: {len(s)} maps -> a body of {len(program.body)} commands "
                  f"({len(s)} RECURSE);  Hausdorff distance turtle vs IFS {distance:.1e}")
        if level < levels:
            status += f"  (level lowered to {level} to stay quick)"
        return {"turtle": strokes, "ifs": drawn, "program": ptext, "distance": distance, "level": level,
                "status": status}

    view = InteractiveView(controls=editor.controls, views=[editor, figure_widget(fig), text], update=update,
                           figure=fig, title="Tao's algorithm: from the IFS you edit to a recursive turtle program",
                           arrange=[widgets.HTML("")])
    view.editor = editor
    return view


# ---------------------------------------------------------------------------------------------
# §8.5 bump fractals
# ---------------------------------------------------------------------------------------------

def bump_view(bump: str = "Koch curve", level: int = 4, height: float = 1.0) -> InteractiveView:
    """Bump fractals both ways (Goldman §8.5): a bump (picker), its height (its y-coordinates
    multiplied by ``height``) and a level; left the bump's recursive turtle program
    (:func:`~goldman_lib.conformal_ifs.bump_program`), right the deterministic algorithm of its
    IFS (:func:`~goldman_lib.conformal_ifs.bump_ifs`) from the unit segment, with the bump
    itself dashed.  The status gives the similarity dimension and the Hausdorff distance.

    ``update(bump, level, height)`` returns ``{"bump" (m, 2), "turtle", "ifs" (strokes),
    "distance", "dimension", "status"}``.

    >>> bump_view("dragon", 8).last_result["distance"] < 1e-12
    True
    """

    if bump not in cf.BUMPS:
        raise ValueError(f"bump must be one of {sorted(cf.BUMPS)}; got {bump!r}")
    controls = {
        "bump": dropdown("bump", list(cf.BUMPS), bump, label_width="60px", width="290px"),
        "level": int_slider("level", as_int(level, "level", minimum=0, maximum=8), 0, 8),
        "height": float_slider("height", as_float(height, "height"), -1.5, 1.5, 0.05),
    }
    fig, left, right = _two_panels()
    (turtle_line,) = left.plot([], [], color=style.PALETTE["curve"], linewidth=0.9)
    (ifs_line,) = right.plot([], [], color=style.PALETTE["good"], linewidth=0.9)
    bump_lines = [ax.plot([], [], "--o", color=style.PALETTE["accent"], linewidth=1.0, markersize=3)[0]
                  for ax in (left, right)]
    left_title = left.set_title("", fontsize=10, y=1.0)
    right_title = right.set_title("", fontsize=10, y=1.0)

    def update(bump, level, height):
        poly, rev = cf.BUMPS[bump]
        poly = poly * np.array([1.0, height])
        if np.any(np.hypot(*np.diff(poly, axis=0).T) < 1e-9):
            # a height of 0 folds a vertical segment to nothing: nudge it
            poly = cf.BUMPS[bump][0] * np.array([1.0, 0.01 if height >= 0 else -0.01])
        program = cf.bump_program(poly, rev, name=bump)
        system = cf.bump_ifs(poly, rev, name=bump)
        lev = _fitting_level(program, int(level))
        while lev > 0 and len(system) ** lev > MAX_SEGMENTS:
            lev -= 1
        strokes = program.polylines(lev)
        drawn = cf.ifs_polylines(system, lev, [np.array([[0.0, 0.0], [1.0, 0.0]])])
        turtle_line.set_data(*stroke_data(strokes))
        ifs_line.set_data(*stroke_data(drawn))
        for line in bump_lines:
            line.set_data(poly[:, 0], poly[:, 1])
        box = _bounds(strokes + drawn + [poly])
        for ax in (left, right):
            _fit(ax, (), bounds=box)
        distance = cf.drawing_distance(strokes, drawn)
        scales = fixed_point.contraction_factor(system.maps)    # a similarity's scale (§7.3.3)
        try:
            dimension = fractals.similarity_dimension(scales)
            dim_text = f"similarity dimension {dimension:.4f}"
        except ValueError:
            dimension, dim_text = -1.0, "a scale >= 1: no similarity dimension"
        left_title.set_text(f"turtle: bump program, level {lev}")
        right_title.set_text(f"IFS: {len(system)} maps, level {lev}")
        status = (f"{bump}, height {height:.2f}: {len(system)} segments"
                  f"{', reversed ' + str(list(rev)) if rev else ''};  {dim_text};  "
                  f"Hausdorff distance turtle vs IFS {distance:.1e}")
        if lev < int(level):
            status += f"  (level lowered to {lev})"
        return {"bump": poly, "turtle": strokes, "ifs": drawn, "distance": distance, "dimension": dimension,
                "status": status}

    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§8.5 Bump fractals: the bump's turtle program and its IFS")

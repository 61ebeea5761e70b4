"""Chapter 6 views: iterating an IFS on a start shape, and condensation sets (Goldman §6.1-6.4).

The IFS map editor itself is :mod:`goldman_lib.widgets.ifs_editor` (shared with chapters 7 and 8).

>>> view = iteration_view()
>>> sorted(view.update(**view.values()))
['copies', 'status']
"""

from __future__ import annotations

import numpy as np

from goldman_lib import ifs
from goldman_lib.validation import as_int
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import dropdown, figure_widget, float_slider, int_slider, InteractiveView

__all__ = ["START_SHAPES", "plot_copies", "iteration_view", "condensation_view"]

#: Start shapes for the deterministic algorithm (§6.1, §6.3): any compact set leads to the same attractor.
START_SHAPES = {
    "unit square": ifs.UNIT_SQUARE.copy(),
    "triangle": np.array([[0.0, 0.0], [1.0, 0.0], [0.5, np.sqrt(3) / 2], [0.0, 0.0]]),
    "segment": np.array([[0.0, 0.0], [1.0, 0.0]]),
    "letter L": np.array([[0.1, 0.9], [0.1, 0.1], [0.6, 0.1]]),
    "far-away circle": np.c_[2.5 + 0.5 * np.cos(np.linspace(0, 2 * np.pi, 25)),
                             1.5 + 0.5 * np.sin(np.linspace(0, 2 * np.pi, 25))],
}

_MAX_POINTS = 60_000


def _strokes(copies: np.ndarray) -> np.ndarray:
    """``(c, m, 2)`` polylines as one NaN-separated ``(c * (m + 1), 2)`` array for one Line2D."""
    sep = np.full((len(copies), 1, 2), np.nan)
    return np.concatenate([copies, sep], axis=1).reshape(-1, 2)


def plot_copies(system, start, levels: int, ax=None, **kwargs):
    """Draw ``W^levels(start)`` (Goldman §6.1): every copy of the start polyline; returns the line."""
    start = np.asarray(start, dtype=float)
    pts = ifs.deterministic(system, levels, start=start)
    ax = style.get_axes(ax)
    strokes = _strokes(pts.reshape(-1, len(start), 2))
    (line,) = ax.plot(strokes[:, 0], strokes[:, 1], color=kwargs.pop("color", style.PALETTE["curve"]),
                      linewidth=kwargs.pop("linewidth", 0.8), **kwargs)
    return line


def _levels_cap(k: int, m: int, level: int) -> int:
    while level > 0 and ifs.deterministic_count(level, k, m) > _MAX_POINTS:
        level -= 1
    return level


def iteration_view(system: str = "Sierpinski gasket", start: str = "unit square", level: int = 3,
                   max_level: int = 8) -> InteractiveView:
    """The deterministic algorithm on a start shape (Goldman §6.1, §6.3): ``W^n(start)``, level by
    level, for a standard IFS and a start picked from :data:`START_SHAPES`.

    Whatever the start, the copies shrink onto the same attractor (grey).  ``update(system,
    start, level)`` returns ``copies`` ``(k**n, m, 2)``; levels are capped at 60,000 points.
    """

    names = [n for n in ifs.STANDARD if ifs.STANDARD[n]().condensation is None]
    if system not in names:
        raise ValueError(f"system must be one of {names}; got {system!r}")
    if start not in START_SHAPES:
        raise ValueError(f"start must be one of {list(START_SHAPES)}; got {start!r}")
    max_level = as_int(max_level, "max_level", minimum=1, maximum=12)
    level = as_int(level, "level", minimum=0, maximum=max_level)
    fig, ax = style.new_axes()
    attractor = ax.plot([], [], ",", color="#bbbbbb", zorder=0)[0]
    copies_line = ax.plot([], [], color=style.PALETTE["curve"], linewidth=0.9)[0]
    title = ax.set_title("", fontsize=10)
    cache = {}

    def update(system, start, level):
        s = ifs.STANDARD[system]()
        shape = START_SHAPES[start]
        if system not in cache:
            cache[system] = ifs.chaos_game(s, 30_000, rng=0)
        A = cache[system]
        used = _levels_cap(len(s), len(shape), int(level))
        pts = ifs.deterministic(s, used, start=shape)
        copies = pts.reshape(-1, len(shape), 2)
        strokes = _strokes(copies)
        attractor.set_data(A[:, 0], A[:, 1])
        copies_line.set_data(strokes[:, 0], strokes[:, 1])
        allp = np.concatenate([A, pts, shape])
        lo, hi = allp.min(axis=0), allp.max(axis=0)
        pad = 0.05 * (hi - lo).max()
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
        title.set_text(f"{system}: W^{used}({start})")
        capped = f" (level {level} capped at {used})" if used < level else ""
        return {"copies": copies,
                "status": f"level {used}: {len(copies):,} copies of the {start}{capped}"}

    controls = {"level": int_slider("level", level, 0, max_level),
                "system": dropdown("IFS", names, system, label_width="initial", width="260px"),
                "start": dropdown("start", list(START_SHAPES), start, label_width="initial", width="260px")}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="iterating an IFS on a start shape")


def condensation_view(angle: float = 30.0, ratio: float = 0.6, level: int = 6, max_level: int = 10) -> InteractiveView:
    """A fractal tree grown from a condensation set (Goldman §6.4): the trunk ``C`` and two maps
    that shrink by ``ratio`` and turn by ``±angle`` onto its top; ``A_{n+1} = C ∪ W(A_n)``.

    ``update(angle, ratio, level)`` returns ``branches`` ``(2**(level+1) - 1, 2, 2)``, one
    segment per trunk copy.
    """
    max_level = as_int(max_level, "max_level", minimum=1, maximum=14)
    level = as_int(level, "level", minimum=0, maximum=max_level)
    fig, ax = style.new_axes()
    line = ax.plot([], [], color="#5b3a1a", linewidth=1.0)[0]
    ax.set_xlim(-1.8, 1.8)
    ax.set_ylim(-0.1, 2.9)

    def update(angle, ratio, level):
        s = ifs.tree(angle, ratio)
        pts = ifs.deterministic(s, level)
        branches = pts.reshape(-1, 2, 2)
        strokes = _strokes(branches)
        line.set_data(strokes[:, 0], strokes[:, 1])
        height = 1.0 / (1.0 - ratio) if ratio < 1 else float("inf")
        ax.set_title(f"tree: angle {angle:.0f}°, ratio {ratio:.2f}, level {level}", fontsize=10)
        return {"branches": branches,
                "status": f"{len(branches):,} branches = 1 + 2 + ... + 2^{level}; "
                          f"a vertical path is at most 1/(1 - ratio) = {height:.2f} long"}

    controls = {"level": int_slider("level", level, 0, max_level),
                "angle": float_slider("angle", angle, 0.0, 90.0, 1.0, readout=".0f"),
                "ratio": float_slider("ratio", ratio, 0.3, 0.75, 0.01)}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="condensation set: a fractal tree")

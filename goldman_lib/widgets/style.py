"""One look for every chapter: figure size, dpi, palette and the axes style of 2D views.

>>> new_axes()[0].get_size_inches().tolist()
[5.6, 4.2]
"""

from __future__ import annotations

import math

import matplotlib
import numpy as np

FIGSIZE = (5.6, 4.2)      # inches; 560 x 420 px at DPI: fits beside sliders on a deck slide
WIDE_FIGSIZE = (9.6, 4.2)  # two panels side by side
DPI = 100

PALETTE = {
    "curve": "#1f4e9c",        # the curve, the turtle's path
    "control": "#7a7a7a",      # control polygon / net
    "point": "#d1495b",        # the highlighted point (curve point at t, turtle position)
    "accent": "#edae49",       # a second highlight (elevated polygon, construction)
    "good": "#1b7f3b",
    "surface": "#66a3d2",
}

#: colours of the de Casteljau construction levels, level 1 first.
LEVELS = ["#00798c", "#30a24b", "#edae49", "#d1495b", "#8f2d56", "#5c3c92", "#3d5a80", "#9c6644"]


def level_colour(k: int) -> str:
    """Colour of construction level ``k`` (1-based), cycling through :data:`LEVELS`."""
    return LEVELS[(k - 1) % len(LEVELS)]


def new_figure(figsize=FIGSIZE, **kwargs):
    """A new matplotlib figure in the house style that is never shown by itself.

    Through pyplot so that, in a notebook that chose ``%matplotlib widget``, ``fig.canvas`` is
    the ipympl widget; inside ``plt.ioff()`` so that creating it does not display it.
    """
    import matplotlib.pyplot as plt

    with plt.ioff():
        fig = plt.figure(figsize=figsize, dpi=DPI, **kwargs)
    canvas = fig.canvas
    for attr, value in (("header_visible", False), ("footer_visible", False),
                        ("toolbar_visible", False), ("resizable", False)):
        if hasattr(canvas, attr):
            try:
                setattr(canvas, attr, value)
            except Exception:  # pragma: no cover - older ipympl
                pass
    return fig


def new_axes(figsize=FIGSIZE, equal: bool = True):
    """A figure with one styled 2D axes; returns ``(fig, ax)``."""
    fig = new_figure(figsize)
    ax = fig.add_subplot(1, 1, 1)
    style_axes(ax, equal=equal)
    return fig, ax


def style_axes(ax, equal: bool = True):
    """Apply the house style to a 2D axes: equal aspect (optional), light grid, no top/right spines.

    Equal aspect adjusts the axes box, not the data limits, so a view may fix its limits.
    """
    if equal:
        ax.set_aspect("equal", adjustable="box")
    ax.grid(True, color="#e4e4e4", linewidth=0.6)
    ax.set_axisbelow(True)
    for side in ("top", "right"):
        ax.spines[side].set_visible(False)
    return ax


def get_axes(ax=None, equal: bool = True):
    """Return ``ax`` if given, else the axes of a new house-style figure."""
    if ax is not None:
        return ax
    return new_axes(equal=equal)[1]


__all__ = ["FIGSIZE", "WIDE_FIGSIZE", "DPI", "PALETTE", "LEVELS", "level_colour", "new_figure",
           "new_axes", "style_axes", "get_axes", "matplotlib"]


def set_equal_limits(ax, x0: float, x1: float, y0: float, y1: float) -> None:
    """Set limits covering ``[x0, x1] x [y0, y1]``, widened on one side to the axes box's own
    aspect, so x and y have equal scales without matplotlib overriding (and warning about) the
    limits.  The views that follow a drawing as it grows (turtle, CODO) call this on every update.
    """
    fw, fh = ax.figure.get_size_inches()
    pos = ax.get_position(original=True)
    box = (fh * pos.height) / (fw * pos.width)
    xs, ys = x1 - x0, y1 - y0
    if ys < box * xs:
        yc, ys = 0.5 * (y0 + y1), box * xs
        y0, y1 = yc - ys / 2, yc + ys / 2
    else:
        xc, xs = 0.5 * (x0 + x1), ys / box
        x0, x1 = xc - xs / 2, xc + xs / 2
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)


def few_ticks(ax, n: int = 3) -> None:
    """About ``n`` labelled ticks on each axis of ``ax``; a log axis gets decades labelled in plain
    text (``1e-3``, not mathtext) and no minor ticks.

    Tick labels are most of the cost of redrawing a small figure (each one is laid out and
    rendered by FreeType at every draw, a mathtext label several times over); a drawing whose
    coordinates matter little -- a fractal, a path in the plane -- reads as well with a few, and
    a slider then redraws it in about half the time.
    """
    from matplotlib import ticker

    for axis in (ax.xaxis, ax.yaxis):
        if axis.get_scale() == "log":
            axis.set_major_locator(ticker.LogLocator(numticks=n + 2))
            axis.set_minor_locator(ticker.NullLocator())
            axis.set_major_formatter(ticker.FuncFormatter(_plain_power))
        else:
            axis.set_major_locator(ticker.MaxNLocator(nbins=n))


def _plain_power(value, _pos=None) -> str:
    """``1e-3`` for 0.001: a log axis label without mathtext."""
    if value <= 0:
        return ""
    exponent = math.floor(math.log10(value) + 1e-9)
    mantissa = value / 10.0 ** exponent
    return f"1e{exponent}" if abs(mantissa - 1) < 1e-6 else f"{mantissa:.0f}e{exponent}"


__all__ += ["few_ticks"]


def equal_3d_limits(ax, points) -> None:
    """Give a 3D axes one scale on x, y and z: a cube of limits around ``points`` (n, 3), box aspect 1."""
    pts = np.asarray(points, dtype=float).reshape(-1, 3)
    lo, hi = pts.min(0), pts.max(0)
    mid, half = (lo + hi) / 2, max(float((hi - lo).max()) / 2, 1e-9)
    for setter, m in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), mid):
        setter(m - half, m + half)
    ax.set_box_aspect((1, 1, 1))


__all__ += ["equal_3d_limits"]


def pin_layout(fig, rescaling=()) -> None:
    """Pin every axes' titles and axis labels of ``fig`` where matplotlib's automatic placement puts
    them now, so that a redraw does not place them again.

    Matplotlib re-measures the tick labels of every axes at every draw to place each title (above
    any top tick labels) and each axis label (clear of the tick labels): up to a third of the redraw
    of a small figure.  A view whose limits and tick labels do not change with its sliders calls this
    once, after ``tight_layout``; the picture is the same (the positions are kept in axes
    coordinates, so they also hold at another dpi).  An axes whose limits follow the data is listed
    in ``rescaling``: its title and x label are pinned all the same (neither depends on the tick
    values: tick labels keep one height), its y label keeps following the widths of the tick labels.

    >>> fig, ax = new_axes(); _ = ax.set_title("t"); _ = ax.set_xlabel("x")
    >>> pin_layout(fig)
    >>> ax.xaxis._autolabelpos, ax._autotitlepos
    (False, False)
    """
    fig.draw_without_rendering()   # matplotlib places titles and labels while drawing (not on the
                                   # canvas: an ipympl canvas would send a picture before it is shown)
    for ax in fig.axes:
        to_axes = ax.transAxes.inverted()
        for axis in (ax.xaxis, ax.yaxis):
            label = axis.label
            if not label.get_text() or not label.get_visible() or (axis is ax.yaxis and ax in rescaling):
                continue
            display = label.get_transform().transform(label.get_position())
            axis.set_label_coords(*to_axes.transform(display))
        # what ``set_title(..., y=...)`` does (without resetting the titles' fonts): the titles stay
        # where they are, also when their text changes
        ax._autotitlepos = False


__all__ += ["pin_layout"]


def draw_once(artist, state=None):
    """Let a static ``artist`` (a legend, an axis with its ticks and grid, a title) be rendered once
    and its pixels pasted at every later redraw of an Agg canvas (ipympl's, a PNG).

    Matplotlib lays out and rasterises every text glyph by glyph at every draw: a legend of seven
    entries costs as much as redrawing an empty figure.  A view whose sliders leave an artist as it
    is renders it once into a transparent bitmap (cropped to what it painted) and composites that
    bitmap in its place in the drawing order; the picture is the same (blending in two steps may
    round a pixel by one level in 255).  The bitmap is made again when the canvas size or dpi
    changes, when the artist is marked stale (one of its own properties was set) or when ``state()``
    (a hashable summary of what else it depends on, such as the axes limits) changes; other
    renderers (PDF, SVG) draw the artist itself.  Returns ``artist``.

    >>> fig, ax = new_axes(); _ = ax.plot([0, 1], [0, 1], label="a line")
    >>> leg = draw_once(ax.legend())
    >>> fig.canvas.draw(); fig.canvas.draw()     # the second draw pastes the legend's pixels
    >>> leg.get_texts()[0].get_text()
    'a line'
    """
    from matplotlib.backends.backend_agg import RendererAgg

    draw = artist.draw
    cache: dict = {}

    def draw_or_paste(renderer):
        if not artist.get_visible():
            return
        if not isinstance(renderer, RendererAgg):
            return draw(renderer)
        key = (renderer.width, renderer.height, renderer.dpi, state() if state is not None else None)
        # stale: a property of the artist itself was set since it was last drawn (a new label, new ticks)
        if cache.get("key") != key or artist.stale:
            off = _offscreen(int(renderer.width), int(renderer.height), renderer.dpi)
            draw(off)
            rgba = np.asarray(off.buffer_rgba())
            rows, cols = np.flatnonzero(rgba[..., 3].any(axis=1)), np.flatnonzero(rgba[..., 3].any(axis=0))
            if len(rows):
                r0, r1, c0, c1 = rows[0], rows[-1] + 1, cols[0], cols[-1] + 1
                # bottom-up rows, placed by the lower-left corner in display pixels
                cache["pixels"] = (int(c0), int(renderer.height) - int(r1), rgba[r0:r1, c0:c1][::-1].copy())
            else:
                cache["pixels"] = None
            cache["key"] = key
        if cache["pixels"] is not None:
            x, y, pixels = cache["pixels"]
            gc = renderer.new_gc()
            renderer.draw_image(gc, x, y, pixels)
            gc.restore()
        artist.stale = False

    artist.draw = draw_or_paste
    return artist


_OFFSCREEN: list = []   # the last transparent canvas draw_once rendered on (one, reused while the size holds)


def _offscreen(width: int, height: int, dpi: float):
    """A cleared transparent Agg renderer of this size and dpi (the one kept from last time if it fits)."""
    from matplotlib.backends.backend_agg import RendererAgg

    if _OFFSCREEN and (_OFFSCREEN[0].width, _OFFSCREEN[0].height, _OFFSCREEN[0].dpi) == (width, height, dpi):
        _OFFSCREEN[0].clear()
    else:
        _OFFSCREEN[:] = [RendererAgg(width, height, dpi)]
    return _OFFSCREEN[0]


def freeze_axes_decorations(ax, *static, legend: bool = True):
    """:func:`draw_once` for what an axes with fixed limits draws the same at every redraw: its axes
    (grid, ticks, tick labels, axis labels), its legend (unless ``legend=False``) and the ``static``
    artists given (a title, an annotation: texts the sliders do not change).  Each is made again if
    the limits, the axes' place, (3D) the viewing angles or its own text change.  Returns ``ax``.
    """
    three_d = hasattr(ax, "zaxis")

    def placed():
        return (ax.get_xlim(), ax.get_ylim(), ax.get_zlim() if three_d else None, tuple(ax.get_position().bounds),
                getattr(ax, "elev", None), getattr(ax, "azim", None), getattr(ax, "roll", None))

    def state_of(artist):
        if hasattr(artist, "get_texts"):        # a legend
            return lambda: (placed(), tuple(t.get_text() for t in artist.get_texts()))
        if hasattr(artist, "get_text"):
            return lambda: (placed(), artist.get_text())
        return placed

    artists = [ax.xaxis, ax.yaxis] + ([ax.zaxis] if three_d else []) + list(static)
    if legend and ax.get_legend() is not None:
        artists.append(ax.get_legend())
    for artist in artists:
        draw_once(artist, state_of(artist))
    return ax


__all__ += ["draw_once", "freeze_axes_decorations"]

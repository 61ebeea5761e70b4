"""Chapter 26 views: the blossom's de Casteljau-like diagram and the control points of a curve over
any interval, read off the blossom (Goldman §26.2-26.3).

Curves and control polygons are drawn with the chapter-24 plot functions; the factories return
an :class:`~goldman_lib.widgets.interactive.InteractiveView` whose ``update`` is a plain function.

>>> view = blossom_view()
>>> sorted(view.update(**view.values()))
['curve', 'levels', 'point', 'polygon', 'status']
>>> blossom_label(3, 1, 2)
'u₁11'
"""

from __future__ import annotations

import numpy as np

from goldman_lib import bezier
from goldman_lib import blossom as bl
from goldman_lib.validation import as_int, as_points
from goldman_lib.widgets import style
from goldman_lib.views.bezier import DEFAULT_CUBIC, plot_control_polygon, plot_curve
from goldman_lib.widgets.drag import drag_sliders, pair_rows, point_pairs, point_sliders, points_from
from goldman_lib.widgets.interactive import InteractiveView, figure_widget, float_slider

__all__ = ["blossom_label", "plot_blossom_diagram", "blossom_view", "interval_view"]

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def blossom_label(n: int, r: int, k: int, names=None) -> str:
    """The blossom arguments of point k at level r of the diagram: ``u_1 ... u_r 0^(n-r-k) 1^k``
    (Goldman §26.3), written compactly as Goldman does (``u₁01`` for ``p(u₁, 0, 1)``)."""
    n = as_int(n, "n", minimum=0)
    r = as_int(r, "r", minimum=0, maximum=n)
    k = as_int(k, "k", minimum=0, maximum=n - r)
    names = names or [f"u{j + 1}".translate(_SUB) for j in range(n)]
    return "".join(list(names[:r]) + ["0"] * (n - r - k) + ["1"] * k)


def plot_blossom_diagram(ctrl, args, ax=None, labels: bool = True):
    """Draw the blossom's pyramid for ``args`` (Goldman §26.3): each level as a polygon, each point
    labelled with its blossom arguments.  Returns ``(level_lines, texts, point_marker)``."""
    ax = style.get_axes(ax)
    P = as_points(ctrl, "ctrl", dim=2)
    n = len(P) - 1
    steps = bl.blossom_steps(P, args)
    lines, texts = [], []
    for r, level in enumerate(steps[1:-1], start=1):
        (ln,) = ax.plot(level[:, 0], level[:, 1], "o-", color=style.level_colour(r), markersize=4, linewidth=1.2)
        lines.append(ln)
    if labels:
        for r, level in enumerate(steps):
            for k, p in enumerate(level):
                # the control polygon labelled above its points, the levels below theirs
                texts.append(ax.annotate(blossom_label(n, r, k), p, textcoords="offset points",
                                         xytext=(5, 5) if r == 0 else (5, -12), fontsize=8,
                                         color=("#444444" if r == 0 else style.PALETTE["point"] if r == n
                                                else style.level_colour(r))))
    (pt,) = ax.plot(*steps[-1][0], "o", color=style.PALETTE["point"], markersize=9, zorder=5)
    return lines, texts, pt


def blossom_view(ctrl=DEFAULT_CUBIC, args=(0.2, 0.5, 0.8), low: float = 0.0, high: float = 1.0) -> InteractiveView:
    """Sliders for the blossom's arguments ``u_1, ..., u_n`` over its de Casteljau-like diagram
    (Goldman §26.2-26.3), each slider over ``[low, high]``: level r of the pyramid uses ``u_r``, every point is a blossom value
    labelled by its arguments, and the apex is ``p(u_1, ..., u_n)``.  Equal arguments give a point
    of the curve (the diagonal); swapping two sliders leaves the apex where it is (symmetry).
    The control points have x/y sliders and can be dragged with the mouse (``view.drag``): the
    whole pyramid follows.

    ``update(u1, ..., un, x0, y0, ...)`` returns every level and the apex.
    """
    P = as_points(ctrl, "ctrl", dim=2, min_count=2)
    n = len(P) - 1
    args = np.asarray(args, dtype=float)
    if args.shape != (n,):
        raise ValueError(f"args must have shape ({n},), one argument per degree; got shape {args.shape}")
    fig, ax = style.new_axes()
    polygon = plot_control_polygon(P, ax, labels=False)
    curve = plot_curve(P, ax, alpha=0.5)
    lines, texts, apex = plot_blossom_diagram(P, args, ax)
    samples = np.linspace(0.0, 1.0, 200)
    # every blossom value with arguments in [low, high] lies in the hull of the curve's control
    # points over [low, high]: frame that
    hull = bl.control_points_on_interval(P, low, high)
    ax.set_xlim(hull[:, 0].min() - 0.4, hull[:, 0].max() + 0.8)
    ax.set_ylim(hull[:, 1].min() - 0.5, hull[:, 1].max() + 0.5)
    ax.set_title("the blossom p(u₁, ..., uₙ): de Casteljau, one u per level", fontsize=10)
    names = [f"u{j + 1}" for j in range(n)]

    def update(**values):
        u = np.array([values[name] for name in names], dtype=float)
        Q = points_from(values, n + 1)
        steps = bl.blossom_steps(Q, u)
        crv = bezier.curve_sampler(len(Q) - 1, samples.size)(Q)
        polygon.set_data(Q[:, 0], Q[:, 1])
        curve.set_data(crv[:, 0], crv[:, 1])
        for line, level in zip(lines, steps[1:-1]):
            line.set_data(level[:, 0], level[:, 1])
        flat = [p for level in steps for p in level]
        for text, p in zip(texts, flat):
            text.xy = p
        c = steps[-1][0]
        apex.set_data([c[0]], [c[1]])
        on_curve = "on the curve (all arguments equal)" if np.ptp(u) < 1e-12 else "off the curve unless the arguments agree"
        args_text = ", ".join(f"{x:.2f}" for x in u)
        return {"levels": steps, "point": c, "curve": crv, "polygon": Q,
                "status": f"p({args_text}) = ({c[0]:.3f}, {c[1]:.3f}); {on_curve}"}

    controls = {name: float_slider(name, float(v), low, high, 0.05) for name, v in zip(names, args)}
    controls.update(point_sliders(P, (*ax.get_xlim(), *ax.get_ylim()), width="200px", label_width="24px"))
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="blossom diagram",
                           arrange=[controls[name] for name in names] + pair_rows(controls, n + 1), side=True)
    view.ax = ax
    drag_sliders(view, ax, point_pairs(n + 1))
    return view


def interval_view(ctrl=DEFAULT_CUBIC, a: float = 0.25, b: float = 0.75, low: float = -0.5,
                  high: float = 1.5) -> InteractiveView:
    """Sliders for an interval ``[a, b]``: the control points ``p(a^(n-k), b^k)`` of the same
    polynomial curve over that interval (Goldman §26.3).  ``[0, t]`` and ``[t, 1]`` are
    subdivision; an interval beyond [0, 1] extrapolates.

    ``update(a, b)`` returns the new control polygon and the piece of curve it defines.
    """
    P = as_points(ctrl, "ctrl", dim=2, min_count=2)
    fig, ax = style.new_axes()
    ext = bezier.de_casteljau(P, np.linspace(low, high, 300))
    ax.plot(ext[:, 0], ext[:, 1], ":", color=style.PALETTE["curve"], linewidth=1, label="the polynomial, t in "
            f"[{low:g}, {high:g}]")
    plot_control_polygon(P, ax, labels=False, alpha=0.35)
    plot_curve(P, ax, alpha=0.35)
    Q = bl.control_points_on_interval(P, a, b)
    poly = plot_control_polygon(Q, ax, labels=False, color=style.PALETTE["point"])
    piece = plot_curve(Q, ax, color=style.PALETTE["point"], label="the piece over [a, b]")
    ax.legend(fontsize=8, loc="lower center", frameon=False)
    ax.set_xlim(ext[:, 0].min() - 0.3, ext[:, 0].max() + 0.3)
    ax.set_ylim(ext[:, 1].min() - 0.3, max(ext[:, 1].max(), P[:, 1].max()) + 0.3)
    s = np.linspace(0.0, 1.0, 160)

    def update(a, b):
        Q = bl.control_points_on_interval(P, a, b)
        pts = bezier.de_casteljau(Q, s)
        poly.set_data(Q[:, 0], Q[:, 1])
        piece.set_data(pts[:, 0], pts[:, 1])
        return {"polygon": Q, "piece": pts,
                "status": f"[a, b] = [{a:.2f}, {b:.2f}]: Q_k = p(a, ..., a, b, ..., b), "
                          f"Q_0 = ({Q[0, 0]:.2f}, {Q[0, 1]:.2f}), Q_n = ({Q[-1, 0]:.2f}, {Q[-1, 1]:.2f})"}

    controls = {"a": float_slider("a", a, low, high, 0.05), "b": float_slider("b", b, low, high, 0.05)}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="the curve over [a, b] from its blossom")

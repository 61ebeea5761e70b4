"""Chapter 27 views: the de Boor pyramid, local control, and static plots of B-spline curves
(Goldman §27.2-27.7).  The knot-vector editor and the NURBS and surface editors are the shared
component :mod:`goldman_lib.widgets.knot_editor`.

Plot functions take ``ax=None`` and return their artists; widget factories return an
:class:`~goldman_lib.widgets.interactive.InteractiveView` whose ``update`` is a plain function.

>>> view = de_boor_explorer()
>>> sorted(view.update(**view.values()))
['curve', 'knots', 'levels', 'point', 'polygon', 'span', 'status']
"""

from __future__ import annotations

import numpy as np

from goldman_lib import bspline
from goldman_lib.validation import as_int, as_points
from goldman_lib.widgets import style
from goldman_lib.widgets.drag import drag_sliders, pair_rows, point_pairs, point_sliders, points_from
from goldman_lib.widgets.interactive import InteractiveView, figure_widget, float_slider, int_slider
from goldman_lib.widgets.knot_editor import DEFAULT_POLYGON, plot_knot_marks

__all__ = ["plot_bspline_curve", "plot_de_boor", "de_boor_explorer", "local_control_view", "LONG_POLYGON"]

#: Ten control points in a zigzag: long enough that a cubic's basis functions each cover a part.
LONG_POLYGON = np.array([[0.0, 0.0], [0.8, 1.6], [1.8, 2.0], [2.6, 0.6], [3.6, 0.4], [4.4, 1.8],
                         [5.4, 2.0], [6.2, 0.6], [7.2, 0.2], [8.0, 1.4]])


def plot_bspline_curve(ctrl, knots, degree, ax=None, samples: int = 300, polygon: bool = True,
                       marks: bool = True, color=None, **kwargs):
    """Draw a planar B-spline curve (Goldman §27.3) with its control polygon and the curve points
    at the knots; returns the curve's line."""
    ctrl = as_points(ctrl, "ctrl", dim=2)
    t = bspline.check_knots(knots, degree, len(ctrl))
    p = int(degree)
    ax = style.get_axes(ax)
    if polygon:
        ax.plot(ctrl[:, 0], ctrl[:, 1], "o--", color=style.PALETTE["control"], markersize=5, linewidth=1)
    u = np.linspace(*bspline.domain(t, p), samples)
    pts = bspline.de_boor(ctrl, t, p, u)
    (line,) = ax.plot(pts[:, 0], pts[:, 1], color=color or style.PALETTE["curve"], linewidth=2.2, **kwargs)
    if marks:
        plot_knot_marks(ctrl, t, p, ax)
    return line


def plot_de_boor(ctrl, knots, degree, u: float, ax=None):
    """Draw the local de Boor pyramid at ``u`` (Goldman §27.2): the p+1 control points of u's
    span, every level, and the point C(u).  Returns ``(level_lines, point_marker)``."""
    ax = style.get_axes(ax)
    steps = bspline.de_boor_steps(ctrl, knots, degree, u)
    lines = []
    for k, level in enumerate(steps[:-1]):
        (ln,) = ax.plot(level[:, 0], level[:, 1], "o-", color=style.level_colour(k + 1), markersize=4 + (k == 0),
                        linewidth=1.2 + 0.8 * (k == 0))
        lines.append(ln)
    (pt,) = ax.plot(*steps[-1][0], "o", color=style.PALETTE["point"], markersize=9, zorder=5)
    return lines, pt


def _fixed_view(ax, ctrl, pad=0.5):
    lo, hi = ctrl.min(0), ctrl.max(0)
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)


def de_boor_explorer(ctrl=DEFAULT_POLYGON, u: float = 0.4, degree: int = 3, max_degree: int = 5) -> InteractiveView:
    """A u slider and a degree picker over the local de Boor algorithm (Goldman §27.2-27.3).

    The knots are clamped and evenly spaced.  For u, only the p+1 control points of u's knot
    span take part: they are drawn bold, then each level of the pyramid, then C(u).  The control
    points have x/y sliders and can be dragged with the mouse (``view.drag``).
    ``update(u, degree, x0, y0, ...)`` returns the curve, the knots, the span index, the levels and
    the point.
    """
    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=3)
    n1 = len(ctrl)
    max_degree = min(as_int(max_degree, "max_degree", minimum=1), n1 - 1)
    fig, ax = style.new_axes()
    _fixed_view(ax, ctrl)
    (polygon,) = ax.plot(ctrl[:, 0], ctrl[:, 1], "o--", color=style.PALETTE["control"], markersize=5, linewidth=1)
    labels = [ax.annotate(f"$P_{{{k}}}$", q, textcoords="offset points", xytext=(5, 5), fontsize=9)
              for k, q in enumerate(ctrl)]
    (curve,) = ax.plot([], [], color=style.PALETTE["curve"], linewidth=2.2)
    (marks,) = ax.plot([], [], "D", color=style.PALETTE["accent"], markersize=5, markeredgecolor="#333333", zorder=4)
    levels = [ax.plot([], [], "o-", color=style.level_colour(k + 1), markersize=4 + (k == 0),
                      linewidth=1.2 + 0.8 * (k == 0))[0] for k in range(max_degree)]
    (point,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=9, zorder=5)
    ax.set_title("local de Boor: only p+1 control points act at u", fontsize=10)
    samples = np.linspace(0.0, 1.0, 240)

    def update(u, degree, **coords):
        p = int(min(max(degree, 1), max_degree))
        ctrl = points_from(coords, n1)
        polygon.set_data(ctrl[:, 0], ctrl[:, 1])
        for label, q in zip(labels, ctrl):
            label.xy = q
        knots = bspline.clamped_knots(n1, p)
        crv = bspline.de_boor(ctrl, knots, p, samples)
        steps = bspline.de_boor_steps(ctrl, knots, p, u)
        k = bspline.find_span(knots, p, u)
        curve.set_data(crv[:, 0], crv[:, 1])
        kp = bspline.de_boor(ctrl, knots, p, np.unique(knots))
        marks.set_data(kp[:, 0], kp[:, 1])
        for j, line in enumerate(levels):
            if j < len(steps) - 1:
                line.set_data(steps[j][:, 0], steps[j][:, 1])
            else:
                line.set_data([], [])
        c = steps[-1][0]
        point.set_data([c[0]], [c[1]])
        return {"curve": crv, "knots": knots, "span": k, "levels": steps, "point": c, "polygon": ctrl,
                "status": f"u = {u:.2f} lies in [t{k}, t{k + 1}] = [{knots[k]:.3g}, {knots[k + 1]:.3g}): "
                          f"P{k - p}..P{k} and {p} levels give C(u) = ({c[0]:.3f}, {c[1]:.3f})"}

    controls = {"u": float_slider("u", u, 0.0, 1.0, 0.01), "degree": int_slider("degree", degree, 1, max_degree),
                **point_sliders(ctrl, (*ax.get_xlim(), *ax.get_ylim()), width="200px", label_width="24px")}
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="de Boor explorer",
                           arrange=[controls["u"], controls["degree"]] + pair_rows(controls, n1), side=True)
    view.ax = ax
    drag_sliders(view, ax, point_pairs(n1))
    return view


def local_control_view(ctrl=LONG_POLYGON, degree: int = 3, index: int = 4, dy: float = 1.2) -> InteractiveView:
    """Move one control point and see that only part of the curve moves: local control (Goldman §27.7).

    Clamped, evenly spaced knots.  Sliders: which control point moves, and by how much (up or
    down).  The original curve stays in grey; the part of the moved curve over the support
    ``[t_i, t_{i+p+1}]`` of ``N_{i,p}`` is drawn in red.  ``update(index, dy, degree)`` returns
    both curves, the affected parameter interval and the largest change outside it (zero).
    """
    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=3)
    n1 = len(ctrl)
    fig, ax = style.new_axes()
    _fixed_view(ax, ctrl, pad=1.2)
    samples = np.linspace(0.0, 1.0, 300)
    (old,) = ax.plot([], [], color="#b0b0b0", linewidth=2.0, label="before")
    (poly,) = ax.plot([], [], "o--", color=style.PALETTE["control"], markersize=5, linewidth=1)
    (new,) = ax.plot([], [], color=style.PALETTE["curve"], linewidth=2.2, label="after")
    (moved_part,) = ax.plot([], [], color=style.PALETTE["point"], linewidth=3.0, label="the part that moved")
    (handle,) = ax.plot([], [], "s", color=style.PALETTE["point"], markersize=8)
    ax.legend(loc="lower right", fontsize=8, frameon=False)
    ax.set_title("local control", fontsize=10)

    def update(index, dy, degree):
        p = int(min(max(degree, 1), n1 - 1))
        i = int(min(max(index, 0), n1 - 1))
        knots = bspline.clamped_knots(n1, p)
        moved = ctrl.copy()
        moved[i, 1] += dy
        before = bspline.de_boor(ctrl, knots, p, samples)
        after = bspline.de_boor(moved, knots, p, samples)
        lo, hi = bspline.affected_span(knots, p, i)
        inside = (samples >= lo) & (samples <= hi)
        old.set_data(before[:, 0], before[:, 1])
        poly.set_data(moved[:, 0], moved[:, 1])
        new.set_data(after[:, 0], after[:, 1])
        moved_part.set_data(after[inside, 0], after[inside, 1])
        handle.set_data([moved[i, 0]], [moved[i, 1]])
        outside = float(np.abs(after - before)[~inside].max()) if (~inside).any() else 0.0
        return {"before": before, "after": after, "interval": np.array([lo, hi]), "change_outside": outside,
                "status": f"moving P{i} changes the curve only for u in [{lo:.3g}, {hi:.3g}] "
                          f"(the support of N_{i},{p}); largest change outside: {outside:.1e}"}

    controls = {"index": int_slider("P_i", index, 0, n1 - 1), "dy": float_slider("move y", dy, -2.0, 2.0, 0.1),
                "degree": int_slider("degree", degree, 1, min(5, n1 - 1))}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="local control")


# -- §27.5 and §27.9 static figures (added at the end so the factories above stay untouched) ---------
def _fmt_knot(x: float) -> str:
    return f"{x:.3g}"


def plot_global_pyramid(knots, degree, u=None, ax=None, edge_labels: bool = True):
    """Draw Goldman's global de Boor pyramid with every node labelled by its blossom arguments (Goldman §27.5).

    Level 0 (bottom) holds ``P_0 .. P_n`` labelled ``(t_{i+1}, ..., t_{i+p})``; the node i of level r
    is labelled ``(u^r, t_{i+1}, ..., t_{i+p-r})`` and its two incoming edges carry the factors
    ``t_{i+p+1-r} - u`` (from node i-1) and ``u - t_i`` (from node i).  All numbers come from
    :func:`goldman_lib.bspline.global_pyramid_labels`.  If ``u`` is given, the nodes that the span of
    u uses (the local de Boor pyramid, locality) are drawn in colour and the rest in grey.
    Returns the axes.
    """
    import matplotlib.pyplot as plt

    levels = bspline.global_pyramid_labels(knots, degree)
    p = len(levels) - 1
    t = bspline.check_knots(knots, degree)
    k = bspline.find_span(t, p, u) if u is not None else None
    if ax is None:
        fig = plt.figure(figsize=(style.WIDE_FIGSIZE[0], 4.8), dpi=style.DPI)
        ax = fig.add_subplot(1, 1, 1)
    ax.set_axis_off()
    pos = {(r, d["index"]): (d["index"] - r / 2, r) for r, level in enumerate(levels) for d in level}

    def active(r, d):
        return k is not None and k in d["spans"]

    for r, level in enumerate(levels[1:], start=1):
        for d in level:
            i = d["index"]
            lo, hi = d["interval"]
            on = active(r, d)
            colour = style.PALETTE["curve"] if on else "#c8c8c8"
            for parent, text in (((r - 1, i - 1), f"{_fmt_knot(hi)}−u"), ((r - 1, i), f"u−{_fmt_knot(lo)}")):
                (x0, y0), (x1, y1) = pos[parent], pos[(r, i)]
                ax.plot([x0, x1], [y0, y1], color=colour, linewidth=1.6 if on else 0.8, zorder=1)
                if edge_labels and d["defined"]:       # written along the edge, nearer the parent
                    xm, ym = x0 + 0.4 * (x1 - x0), y0 + 0.4 * (y1 - y0)
                    angle = float(np.degrees(np.arctan2(y1 - y0, x1 - x0)))
                    angle = angle - 180 if angle > 90 else angle
                    ax.text(xm, ym, text, fontsize=6, ha="center", va="center", rotation=angle,
                            rotation_mode="anchor", transform_rotates_text=True,
                            color="#333333" if on else "#999999", zorder=2,
                            bbox=dict(boxstyle="square,pad=0.05", fc="white", ec="none"))
    for r, level in enumerate(levels):
        for d in level:
            x, y = pos[(r, d["index"])]
            args = ["u"] * r + [_fmt_knot(v) for v in d["knots"]]
            text = "(" + ", ".join(args) + ")" if args else "()"
            if r == 0:
                text = f"$P_{{{d['index']}}}$\n" + text
            elif r == p:
                lo_k, hi_k = d["interval"]
                text += f"\npiece on [{_fmt_knot(lo_k)}, {_fmt_knot(hi_k)})"
            on = active(r, d)
            face = style.level_colour(r) if on else "#eeeeee"
            ax.plot(x, y, "o", markersize=7, color=face, markeredgecolor="#555555", zorder=3)
            ax.text(x, y + (0.16 if r < p else 0.16), text, fontsize=6.5, ha="center", va="bottom",
                    color="#111111" if (on or k is None) else "#888888", zorder=4,
                    bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8))
    xs = [x for x, _ in pos.values()]
    ax.set_xlim(min(xs) - 0.7, max(xs) + 0.7)
    ax.set_ylim(-0.3, p + 0.75)
    title = f"global de Boor pyramid, degree {p}, knots {[float(_fmt_knot(v)) for v in t]}"
    if k is not None:
        title += f"\nu = {u:g} lies in [t{k}, t{k + 1}): the coloured nodes are its local pyramid"
    ax.set_title(title, fontsize=9)
    return ax


def plot_nurbs_surface(ctrl, weights, knots_u, knots_v, degree_u, degree_v, ax=None, resolution: int = 33,
                       net: bool = True):
    """Draw a NURBS surface (Goldman §27.9) with its control net in a static 3D matplotlib view.

    The surface points come from :func:`goldman_lib.bspline.nurbs_surface_grid` over the domains of
    the two knot vectors; the control net is drawn as its rows and columns with the points sized by
    their weights.  Returns the axes (a 3D axes; a new figure when ``ax`` is None).
    """
    import matplotlib.pyplot as plt

    P = as_points(ctrl, "ctrl", ndim=3, dim=3)
    resolution = as_int(resolution, "resolution", minimum=2, maximum=200)
    tu = bspline.check_knots(knots_u, degree_u, P.shape[0], name="knots_u")
    tv = bspline.check_knots(knots_v, degree_v, P.shape[1], name="knots_v")
    u = np.linspace(*bspline.domain(tu, degree_u), resolution)
    v = np.linspace(*bspline.domain(tv, degree_v), resolution)
    S = bspline.nurbs_surface_grid(P, weights, tu, tv, degree_u, degree_v, u, v)
    if ax is None:
        fig = plt.figure(figsize=style.FIGSIZE, dpi=style.DPI)
        ax = fig.add_subplot(1, 1, 1, projection="3d")
    ax.plot_surface(S[..., 0], S[..., 1], S[..., 2], color=style.PALETTE["curve"], alpha=0.55,
                    linewidth=0.2, edgecolor="#ffffff", shade=True)
    if net:
        for row in P:
            ax.plot(*row.T, color=style.PALETTE["control"], linewidth=0.9)
        for col in P.transpose(1, 0, 2):
            ax.plot(*col.T, color=style.PALETTE["control"], linewidth=0.9)
        w = np.asarray(weights, dtype=float).reshape(-1)
        ax.scatter(*P.reshape(-1, 3).T, s=14 * w / w.max() + 4, color=style.PALETTE["point"], depthshade=False)
    ax.set_box_aspect((np.ptp(P[..., 0]), np.ptp(P[..., 1]), np.ptp(P[..., 2])))
    return ax


__all__ += ["plot_global_pyramid", "plot_nurbs_surface"]

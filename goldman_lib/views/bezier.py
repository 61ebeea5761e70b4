"""Chapter 24 views: Bezier curves, the de Casteljau construction, degree elevation, the
Bernstein basis, and a three.js tensor-product patch (Goldman §24.2-24.6).

Plot functions take ``ax=None`` and return their artists; widget factories return an
:class:`~goldman_lib.widgets.interactive.InteractiveView` whose ``update`` is a plain function.

>>> view = de_casteljau_explorer()
>>> sorted(view.update(**view.values()))
['curve', 'levels', 'point', 'polygon', 'status']
"""

from __future__ import annotations

import numpy as np

from goldman_lib import bezier
from goldman_lib.validation import as_int, as_points, within_budget
from goldman_lib.widgets import style
from goldman_lib.widgets.drag import drag_sliders, pair_rows, point_pairs, point_sliders, points_from
from goldman_lib.widgets.interactive import InteractiveView, figure_widget, float_slider, int_slider
from goldman_lib.widgets.three import SceneView, grid_triangles

__all__ = ["plot_control_polygon", "plot_curve", "plot_construction", "plot_bernstein",
           "de_casteljau_explorer", "degree_elevation_view", "bernstein_view", "patch_editor",
           "DEFAULT_CUBIC", "DEFAULT_PATCH"]

#: The cubic the chapter starts from (a gentle S with a loop-free hull).
DEFAULT_CUBIC = np.array([[0.0, 0.0], [1.0, 2.5], [3.0, 2.5], [4.0, 0.5]])


def _default_patch() -> np.ndarray:
    """A bicubic control net over [0, 3] x [0, 3] with a raised middle."""
    i, j = np.meshgrid(np.arange(4.0), np.arange(4.0), indexing="ij")
    z = np.zeros((4, 4))
    z[1:3, 1:3] = 1.5
    z[0, 3] = z[3, 0] = 0.5
    return np.stack([i, j, z], axis=-1)


#: The bicubic patch of the three.js view: control net ``(4, 4, 3)``.
DEFAULT_PATCH = _default_patch()


# -- static plots -------------------------------------------------------------------------------
def plot_control_polygon(ctrl, ax=None, labels: bool = True, color=None, **kwargs):
    """Draw a control polygon with its points (labelled P0, P1, ... if ``labels``); returns the line."""
    ctrl = as_points(ctrl, "ctrl", dim=2)
    ax = style.get_axes(ax)
    (line,) = ax.plot(ctrl[:, 0], ctrl[:, 1], "o--", color=color or style.PALETTE["control"],
                      markersize=5, linewidth=1, **kwargs)
    if labels:
        for k, p in enumerate(ctrl):
            ax.annotate(f"$P_{{{k}}}$", p, textcoords="offset points", xytext=(5, 5), fontsize=9)
    return line


def plot_curve(ctrl, ax=None, samples: int = 200, color=None, **kwargs):
    """Draw the Bezier curve of ``ctrl`` (Goldman §24.2) sampled at ``samples`` parameters; returns the line."""
    ctrl = as_points(ctrl, "ctrl", dim=2)
    samples = within_budget(samples, "samples", cost=lambda v: 2 * v, what="the sampled curve",
                            unit="coordinates", minimum=2)
    ax = style.get_axes(ax)
    pts = bezier.de_casteljau(ctrl, np.linspace(0.0, 1.0, samples))
    (line,) = ax.plot(pts[:, 0], pts[:, 1], color=color or style.PALETTE["curve"], linewidth=2.2, **kwargs)
    return line


def plot_construction(ctrl, t: float, ax=None):
    """Draw the de Casteljau construction at ``t`` (Goldman §24.2): every intermediate level and
    the curve point.  Returns ``(level_lines, point_marker)``."""
    ax = style.get_axes(ax)
    steps = bezier.de_casteljau_steps(ctrl, t)
    lines = []
    for k, level in enumerate(steps[1:-1], start=1):
        (ln,) = ax.plot(level[:, 0], level[:, 1], "o-", color=style.level_colour(k), markersize=4, linewidth=1.2)
        lines.append(ln)
    (pt,) = ax.plot(*steps[-1][0], "o", color=style.PALETTE["point"], markersize=9, zorder=5)
    return lines, pt


def plot_bernstein(n: int, ax=None, samples: int = 200):
    """Draw the Bernstein basis functions ``B_k^n`` on [0, 1] (Goldman §24.3); returns the lines."""
    n = as_int(n, "n", minimum=0)
    samples = within_budget(samples, "samples", cost=lambda v: v, what="the sampled basis", unit="parameters",
                            minimum=2)
    ax = style.get_axes(ax, equal=False)
    t = np.linspace(0.0, 1.0, samples)
    values = bezier.bernstein(n, t)
    lines = ax.plot(t, values, linewidth=1.6)
    ax.set_xlabel("t")
    ax.set_ylim(-0.02, 1.02)
    return lines


# -- widgets ------------------------------------------------------------------------------------
def de_casteljau_explorer(ctrl=DEFAULT_CUBIC, t: float = 0.4, box=(-1.0, 5.0, -1.0, 4.0)) -> InteractiveView:
    """Control-point sliders (x and y of each point) and a t slider over the de Casteljau
    construction of a planar Bezier curve (Goldman §24.2).

    ``update(t, x0, y0, x1, y1, ...)`` redraws the curve, the control polygon, each level of the
    construction and the point ``C(t)``; it returns them as arrays.  ``box`` = (xmin, xmax, ymin,
    ymax) is both the sliders' range and the fixed view, so the picture does not jump.
    The control points can also be dragged with the mouse (``view.drag``, a
    :class:`~goldman_lib.widgets.drag.PointDrag`): a drag sets the point's two sliders.
    """
    import ipywidgets as widgets

    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=2)
    n = len(ctrl) - 1
    xmin, xmax, ymin, ymax = box
    fig, ax = style.new_axes()
    ax.set_xlim(xmin, xmax)
    ax.set_ylim(ymin, ymax)
    ax.set_aspect("equal", adjustable="box")
    # The artists are drawn once by the static plot functions, then moved in place by update.
    polygon = plot_control_polygon(ctrl, ax, labels=False)
    curve = plot_curve(ctrl, ax)
    levels, point = plot_construction(ctrl, t, ax)
    ax.set_title("de Casteljau construction", fontsize=10)
    samples = np.linspace(0.0, 1.0, 160)

    controls = {"t": float_slider("t", t, 0.0, 1.0, 0.01), **point_sliders(ctrl, box)}

    def update(t, **coords):
        pts = points_from(coords, n + 1)
        steps = bezier.de_casteljau_steps(pts, t)
        crv = bezier.curve_sampler(len(pts) - 1, samples.size)(pts)
        polygon.set_data(pts[:, 0], pts[:, 1])
        curve.set_data(crv[:, 0], crv[:, 1])
        for line, level in zip(levels, steps[1:-1]):
            line.set_data(level[:, 0], level[:, 1])
        c = steps[-1][0]
        point.set_data([c[0]], [c[1]])
        return {"curve": crv, "polygon": pts, "levels": steps[1:], "point": c,
                "status": f"t = {t:.2f}:  C(t) = ({c[0]:.3f}, {c[1]:.3f}); {n} levels of affine combinations"}

    # Controls beside the figure, t first and set apart, so the view fits on one deck slide.
    points_label = widgets.HTML("<small>control points (or drag them)</small>")
    arrange = [controls["t"], points_label] + [controls[f"{a}{k}"] for k in range(n + 1) for a in "xy"]
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="de Casteljau explorer", arrange=arrange, side=True)
    view.ax = ax
    drag_sliders(view, ax, point_pairs(n + 1))
    return view


def degree_elevation_view(ctrl=DEFAULT_CUBIC, times: int = 2, max_times: int = 12) -> InteractiveView:
    """A slider for how many times the degree is elevated (Goldman §24.5): the curve stays the
    same while the elevated control polygons close in on it.  The original control points have
    x/y sliders and can be dragged with the mouse (``view.drag``); each box is the figure's.

    ``update(times, x0, y0, ...)`` returns the original and the elevated polygon, the curve and
    the largest distance from the elevated control points to the curve.
    """
    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=2)
    max_times = as_int(max_times, "max_times", minimum=1, maximum=60)
    fig, ax = style.new_axes()
    crv = bezier.de_casteljau(ctrl, np.linspace(0.0, 1.0, 400))
    original = plot_control_polygon(ctrl, ax, labels=False, alpha=0.6)
    (curve,) = ax.plot(crv[:, 0], crv[:, 1], color=style.PALETTE["curve"], linewidth=2.4, label="the curve (unchanged)")
    (elevated,) = ax.plot([], [], "s-", color=style.PALETTE["accent"], markersize=4, linewidth=1.4,
                          label="elevated control polygon")
    ax.legend(loc="lower center", fontsize=8, frameon=False)
    pad = 0.3
    box = (ctrl[:, 0].min() - pad, ctrl[:, 0].max() + pad, ctrl[:, 1].min() - pad, ctrl[:, 1].max() + pad)
    ax.set_xlim(box[0], box[1])
    ax.set_ylim(box[2], box[3])
    ax.set_aspect("equal", adjustable="box")
    n = len(ctrl) - 1
    samples = np.linspace(0.0, 1.0, 400)

    def update(times, **coords):
        times = as_int(times, "times", minimum=0)
        P = points_from(coords, n + 1)
        crv = bezier.curve_sampler(len(P) - 1, samples.size)(P)
        pts = bezier.elevate_degree(P, times) if times else P
        original.set_data(P[:, 0], P[:, 1])
        curve.set_data(crv[:, 0], crv[:, 1])
        elevated.set_data(pts[:, 0], pts[:, 1])
        gap = float(np.sqrt(((pts[:, None, :] - crv[None]) ** 2).sum(-1)).min(1).max())
        return {"polygon": pts, "original": P, "curve": crv, "gap": gap,
                "status": f"degree {n} -> {n + times}: {len(pts)} control points, "
                          f"farthest control point {gap:.3f} from the curve"}

    times = as_int(times, "times", minimum=0, maximum=max_times)
    controls = {"times": int_slider("elevate", times, 0, max_times),
                **point_sliders(ctrl, box, width="200px", label_width="24px")}
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="degree elevation", side=True,
                           arrange=[controls["times"]] + pair_rows(controls, n + 1))
    view.ax = ax
    drag_sliders(view, ax, point_pairs(n + 1))
    return view


def bernstein_view(n: int = 3, t: float = 0.4, max_degree: int = 12) -> InteractiveView:
    """The Bernstein basis of degree ``n`` with a t marker (Goldman §24.3): the values at ``t``
    are the weights of the control points, non-negative and summing to one.

    ``update(n, t)`` returns the basis values at ``t``.
    """
    fig, ax = style.new_axes(equal=False)
    lines = plot_bernstein(max_degree, ax)  # one line per basis function of the largest degree
    ax.set_xlim(0, 1)
    samples = np.linspace(0.0, 1.0, 200)
    marker = ax.axvline(t, color=style.PALETTE["point"], linewidth=1)
    (dots,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=5)

    def update(n, t):
        values = bezier.bernstein(n, samples)
        for k, line in enumerate(lines):
            if k <= n:
                line.set_data(samples, values[:, k])
            else:
                line.set_data([], [])
        at_t = bezier.bernstein(n, t)
        marker.set_xdata([t, t])
        dots.set_data(np.full(n + 1, t), at_t)
        ax.set_title(f"Bernstein basis of degree {n}", fontsize=10)
        weights = ", ".join(f"{w:.3f}" for w in at_t)
        return {"values": at_t, "status": f"B_k^{n}({t:.2f}) = [{weights}]; sum = {at_t.sum():.3f}"}

    controls = {"n": int_slider("degree", n, 0, max_degree), "t": float_slider("t", t, 0.0, 1.0, 0.01)}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Bernstein basis")


def patch_editor(ctrl=DEFAULT_PATCH, resolution: int = 24, width: int = 480, height: int = 360) -> InteractiveView:
    """A three.js tensor-product Bezier patch (Goldman §24.6) whose control net moves with sliders.

    Sliders set the heights of the four interior control points and of the corner ``P33``, and
    the parameters ``(u, v)`` of a marked point on the patch.  ``update(**values)`` evaluates the
    patch on a ``resolution x resolution`` grid and updates the mesh, the net and the points in
    place (the renderer is built once).  Requires a bicubic-or-larger net ``(m+1, n+1, 3)``.
    """
    base = as_points(ctrl, "ctrl", ndim=3, dim=3, min_count=2)
    resolution = as_int(resolution, "resolution", minimum=2, maximum=200)
    m, n = base.shape[0] - 1, base.shape[1] - 1
    if m < 2 or n < 2:
        raise ValueError(f"ctrl must be at least a biquadratic net (3, 3, 3) so it has an interior point; got shape {base.shape}")
    movable = [(1, 1), (1, n - 1), (m - 1, 1), (m - 1, n - 1), (m, n)]
    movable = list(dict.fromkeys(movable))
    grid_u = np.linspace(0.0, 1.0, resolution)
    ii, jj = np.meshgrid(np.arange(m + 1), np.arange(n + 1), indexing="ij")
    idx = (ii * (n + 1) + jj)
    net_segments = np.concatenate([np.stack([idx[:, :-1].ravel(), idx[:, 1:].ravel()], 1),
                                   np.stack([idx[:-1, :].ravel(), idx[1:, :].ravel()], 1)])
    center = base.reshape(-1, 3).mean(0)
    scene = SceneView(width=width, height=height, target=tuple(center),
                      camera_position=tuple(center + np.array([3.2, -4.0, 3.4])), axes=1.0)
    surface = bezier.patch_evaluate_grid(base, grid_u, grid_u)
    scene.add_mesh("patch", surface.reshape(-1, 3), grid_triangles(resolution, resolution), color=style.PALETTE["surface"])
    scene.add_segments("net", base.reshape(-1, 3), net_segments, color="#555555")
    scene.add_points("control points", base.reshape(-1, 3), color="#333333", size=0.12)
    scene.add_points("P(u,v)", base[:1, 0], color=style.PALETTE["point"], size=0.35)

    controls = {f"z{i}{j}": float_slider(f"z{i}{j}", float(base[i, j, 2]), -2.0, 3.0, 0.1) for i, j in movable}
    controls["u"] = float_slider("u", 0.5, 0.0, 1.0, 0.01)
    controls["v"] = float_slider("v", 0.5, 0.0, 1.0, 0.01)

    def update(u, v, **heights):
        net = base.copy()
        for i, j in movable:
            net[i, j, 2] = heights[f"z{i}{j}"]
        surf = bezier.patch_evaluate_grid(net, grid_u, grid_u)
        p = bezier.patch_de_casteljau(net, u, v)
        scene.set_mesh("patch", surf.reshape(-1, 3))
        scene.set_segments("net", net.reshape(-1, 3))
        scene.set_points("control points", net.reshape(-1, 3))
        scene.set_points("P(u,v)", p[None])
        return {"surface": surf, "net": net, "point": p,
                "status": f"P({u:.2f}, {v:.2f}) = ({p[0]:.3f}, {p[1]:.3f}, {p[2]:.3f}); drag to orbit"}

    view = InteractiveView(controls=controls, views=[scene.widget], update=update, static=scene.to_png,
                           title="bicubic Bezier patch", side=True)
    view.scene = scene
    return view


# -- §24.1 interpolation versus approximation (added at the end so the factories above stay untouched)
def plot_interpolation_vs_approximation(points, ax=None, samples: int = 200, nodes=None):
    """Draw the interpolating polynomial through ``points`` (Neville, :func:`goldman_lib.bezier.neville`)
    and the Bezier curve of the same points (:func:`goldman_lib.bezier.de_casteljau`) (Goldman §24.1).

    The interpolant passes through every point at its node (equally spaced on [0, 1] by default) and
    may swing far outside their convex hull; the Bezier curve passes only through the first and last
    and follows the polygon.  Returns ``(interpolant_line, bezier_line)``.
    """
    pts = as_points(points, "points", dim=2)
    samples = within_budget(samples, "samples", cost=lambda v: 4 * v, what="the two sampled curves",
                            unit="coordinates", minimum=2)
    ax = style.get_axes(ax)
    plot_control_polygon(pts, ax)
    t = np.linspace(0.0, 1.0, samples)
    lag = bezier.neville(pts, t, nodes=nodes)
    (interp,) = ax.plot(lag[:, 0], lag[:, 1], color=style.PALETTE["point"], linewidth=2.0,
                        label="interpolating polynomial (Neville)")
    bez = plot_curve(pts, ax, samples=samples, label="Bézier curve (de Casteljau)")
    ax.legend(fontsize=8, loc="best", frameon=False)
    return interp, bez


__all__ += ["plot_interpolation_vs_approximation"]

"""Chapter 25 views: subdivision of Bezier curves, rendering and intersection by subdivision, and
the adaptive subdivision of a patch (Goldman §25.2-25.3).

The curves and control polygons are drawn with the chapter-24 plot functions
(:func:`goldman_lib.views.bezier.plot_curve`, :func:`~goldman_lib.views.bezier.plot_control_polygon`);
the factories return an :class:`~goldman_lib.widgets.interactive.InteractiveView` whose ``update``
is a plain function returning what it drew.

>>> view = bezier_subdivision_view()
>>> sorted(view.update(**view.values()))
['curve', 'gap', 'polygon', 'polygons', 'status']

:func:`patch_subdivision_3d_view` is the chapter's three.js view (through
:class:`goldman_lib.widgets.three.SceneView`): the sub-nets of a subdivided bicubic patch and the
intersection of two patches by subdivision.
"""

from __future__ import annotations

import numpy as np

from goldman_lib import bezier
from goldman_lib.validation import as_float, as_int, as_points
from goldman_lib.widgets import style
from goldman_lib.views.bezier import DEFAULT_CUBIC, plot_control_polygon, plot_curve
from goldman_lib.widgets.drag import drag_sliders, pair_rows, point_pairs, point_sliders, points_from
from goldman_lib.widgets.interactive import dropdown, figure_widget, float_slider, int_slider, InteractiveView

__all__ = ["plot_pieces", "plot_boxes", "plot_patch_domains", "bezier_subdivision_view", "adaptive_rendering_view",
           "intersection_view", "patch_rendering_view", "patch_subdivision_3d_view", "INTERSECTION_EXAMPLES", "WAVY", "DEFAULT_PATCH_25"]

#: A quartic with two bends: flat parts and tight parts for adaptive rendering.
WAVY = np.array([[0.0, 0.0], [0.5, 3.0], [2.0, -1.0], [3.5, 2.5], [4.0, 0.5]])

#: Pairs of curves for the intersection demo (in the spirit of the ``bezier`` package's cases).
INTERSECTION_EXAMPLES = {
    "two cubics, three crossings": (np.array([[0.0, 0.0], [1.0, 3.0], [2.0, -2.0], [3.0, 1.0]]),
                                    np.array([[0.0, 1.0], [1.0, -1.5], [2.0, 2.5], [3.0, 0.0]])),
    "parabola and line": (np.array([[0.0, 0.0], [1.5, 3.0], [3.0, 0.0]]),
                          np.array([[0.0, 0.8], [3.0, 1.2]])),
    "parabolas touching (tangent)": (np.array([[0.0, 0.0], [1.5, 1.5], [3.0, 0.0]]),
                                     np.array([[0.0, 1.5], [1.5, 0.0], [3.0, 1.5]])),
    "cubic with a loop and a line": (np.array([[0.0, 0.0], [3.5, 2.5], [-0.5, 2.5], [3.0, 0.0]]),
                                     np.array([[0.0, 0.9], [3.0, 0.6]])),
}


def _default_patch_25() -> np.ndarray:
    """A bicubic graph z = f(x, y) over [0, 3]^2 with one bump: flat corners, a curved middle."""
    i, j = np.meshgrid(np.arange(4.0), np.arange(4.0), indexing="ij")
    z = np.zeros((4, 4))
    z[1, 1], z[1, 2], z[2, 1], z[2, 2] = 2.0, 1.0, 1.0, 0.0
    return np.stack([i, j, z], axis=-1)


#: The bicubic patch of the chapter-25 surface figures: control net ``(4, 4, 3)``.
DEFAULT_PATCH_25 = _default_patch_25()


# -- static plots -------------------------------------------------------------------------------
def plot_pieces(pieces, ax=None, colors=None, linewidth: float = 1.2):
    """Draw the control polygons of subdivided pieces (k, n+1, 2), alternating colours, with their
    end points marked; returns the LineCollection."""
    from matplotlib.collections import LineCollection

    pieces = as_points(pieces, "pieces", ndim=3, dim=2)
    ax = style.get_axes(ax)
    colors = colors or [style.LEVELS[0], style.LEVELS[3]]
    coll = LineCollection(list(pieces), colors=[colors[k % len(colors)] for k in range(len(pieces))],
                          linewidths=linewidth, zorder=2)
    ax.add_collection(coll)
    return coll


def plot_boxes(boxes, ax=None, color=None, alpha: float = 0.18):
    """Draw axis-aligned boxes (k, 2, 2) given as ``[[xmin, ymin], [xmax, ymax]]``; returns the PolyCollection."""
    from matplotlib.collections import PolyCollection

    ax = style.get_axes(ax)
    coll = PolyCollection(_box_vertices(np.asarray(boxes, dtype=float).reshape(-1, 2, 2)),
                          facecolors=color or style.PALETTE["accent"], edgecolors=color or style.PALETTE["accent"],
                          alpha=alpha, linewidths=1.0, zorder=1)
    ax.add_collection(coll)
    return coll


def _box_vertices(boxes: np.ndarray) -> list[np.ndarray]:
    lo, hi = boxes[:, 0], boxes[:, 1]
    return list(np.stack([lo, np.stack([hi[:, 0], lo[:, 1]], 1), hi, np.stack([lo[:, 0], hi[:, 1]], 1)], axis=1))


def plot_patch_domains(domains, ax=None):
    """Draw parameter rectangles (k, 4) ``[u0, u1, v0, v1]`` of a patch subdivision; returns the PolyCollection."""
    from matplotlib.collections import PolyCollection

    ax = style.get_axes(ax)
    coll = PolyCollection(_domain_vertices(np.asarray(domains, dtype=float)), facecolors=style.PALETTE["surface"],
                          edgecolors="#333333", linewidths=0.6, alpha=0.55)
    ax.add_collection(coll)
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    ax.set_xlabel("u")
    ax.set_ylabel("v")
    return coll


def _domain_vertices(domains: np.ndarray) -> list[np.ndarray]:
    u0, u1, v0, v1 = domains.T
    return list(np.stack([np.stack([u0, v0], 1), np.stack([u1, v0], 1), np.stack([u1, v1], 1),
                          np.stack([u0, v1], 1)], axis=1))


def _limits(ax, *point_sets, pad: float = 0.4):
    pts = np.concatenate([np.asarray(p, dtype=float).reshape(-1, 2) for p in point_sets])
    ax.set_xlim(pts[:, 0].min() - pad, pts[:, 0].max() + pad)
    ax.set_ylim(pts[:, 1].min() - pad, pts[:, 1].max() + pad)


def _split_recursively(ctrl: np.ndarray, depth: int, t: float) -> np.ndarray:
    return bezier.subdivide_uniform(ctrl, depth, t)


# -- widgets ------------------------------------------------------------------------------------
def bezier_subdivision_view(ctrl=DEFAULT_CUBIC, depth: int = 1, t: float = 0.5, max_depth: int = 6) -> InteractiveView:
    """A subdivision-level slider (Goldman §25.2): the curve split ``depth`` times, each piece at its
    own parameter ``t``, and the 2**depth control polygons closing in on the curve.  The control
    points have x/y sliders and can be dragged with the mouse (``view.drag``).

    ``update(depth, t, x0, y0, ...)`` returns the control polygons (2**depth, n+1, 2) and the largest
    distance ``|P_k - piece(k/n)|`` from a control point of a piece to the piece's point at k/n.
    """
    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=2)
    max_depth = as_int(max_depth, "max_depth", minimum=1, maximum=8)
    fig, ax = style.new_axes()
    polygon = plot_control_polygon(ctrl, ax, labels=False, alpha=0.35)
    curve = plot_curve(ctrl, ax, samples=400)
    pieces = plot_pieces(_split_recursively(ctrl, depth, t), ax)
    (joints,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=4, zorder=4)
    _limits(ax, ctrl, pad=0.3)
    ax.set_title("de Casteljau subdivision", fontsize=10)
    n1 = len(ctrl)
    samples = np.linspace(0.0, 1.0, 400)

    def update(depth, t, **coords):
        depth = as_int(depth, "depth", minimum=0, maximum=max_depth)
        P = points_from(coords, n1)
        polys = _split_recursively(P, depth, t)
        crv = bezier.curve_sampler(len(P) - 1, samples.size)(P)
        polygon.set_data(P[:, 0], P[:, 1])
        curve.set_data(crv[:, 0], crv[:, 1])
        pieces.set_segments(list(polys))
        pieces.set_color([(style.LEVELS[0], style.LEVELS[3])[k % 2] for k in range(len(polys))])
        ends = np.concatenate([polys[:, 0], polys[-1:, -1]])
        joints.set_data(ends[:, 0], ends[:, 1])
        gap = bezier.polygon_distance(polys)
        return {"polygons": polys, "gap": gap, "curve": crv, "polygon": P,
                "status": f"depth {depth}: {len(polys)} pieces split at t = {t:.2f}; control points within "
                          f"{gap:.4f} of the curve (P_k vs the piece at k/n)"}

    depth = as_int(depth, "depth", minimum=0, maximum=max_depth)
    xlim, ylim = ax.get_xlim(), ax.get_ylim()
    controls = {"depth": int_slider("depth", depth, 0, max_depth),
                "t": float_slider("split t", t, 0.1, 0.9, 0.05),
                **point_sliders(ctrl, (*xlim, *ylim), width="200px", label_width="24px")}
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="subdivision level", side=True,
                           arrange=[controls["depth"], controls["t"]] + pair_rows(controls, n1))
    view.ax = ax
    drag_sliders(view, ax, point_pairs(n1))
    return view


def adaptive_rendering_view(ctrl=WAVY, digits: int = 2) -> InteractiveView:
    """Rendering by adaptive subdivision (Goldman §25.3): the tolerance slider sets ``tol = 10**-digits``
    and the polyline of :func:`goldman_lib.bezier.render_by_subdivision` is drawn with its vertices.

    ``update(digits, x0, y0, ...)`` returns the polyline, its parameters and the number of segments; the status
    compares it with the number of evenly spaced segments that reach the same accuracy.  The
    control points have x/y sliders and can be dragged with the mouse (``view.drag``).
    """
    ctrl = as_points(ctrl, "ctrl", dim=2, min_count=2)
    fig, ax = style.new_axes()
    polygon = plot_control_polygon(ctrl, ax, labels=False, alpha=0.35)
    curve = plot_curve(ctrl, ax, samples=400, alpha=0.35)
    (poly,) = ax.plot([], [], ".-", color=style.PALETTE["point"], markersize=6, linewidth=1.2)
    _limits(ax, ctrl, pad=0.3)
    dense = np.linspace(0.0, 1.0, 2001)
    n1 = len(ctrl)

    def uniform_segments(tol, dense_pts):
        # the fewest evenly spaced segments (powers of two) whose chords are within tol
        for k in range(0, 15):
            m = 2 ** k
            step = len(dense) // m if m < len(dense) else 1
            idx = np.arange(0, len(dense), max(step, 1))
            if idx[-1] != len(dense) - 1:
                idx = np.append(idx, len(dense) - 1)
            worst = max(bezier.flatness(dense_pts[a:b + 1]) for a, b in zip(idx[:-1], idx[1:]))
            if worst <= tol:
                return len(idx) - 1
        return len(dense) - 1

    cache: dict[tuple, int] = {}

    def update(digits, **coords):
        digits = as_int(digits, "digits", minimum=1, maximum=4)
        P = points_from(coords, n1)
        tol = 10.0 ** (-digits)
        t, pts = bezier.render_by_subdivision(P, tol)
        dense_pts = bezier.curve_sampler(len(P) - 1, dense.size)(P)
        polygon.set_data(P[:, 0], P[:, 1])
        curve.set_data(dense_pts[::5, 0], dense_pts[::5, 1])
        poly.set_data(pts[:, 0], pts[:, 1])
        key = (digits, P.tobytes())
        if key not in cache:
            if len(cache) > 64:
                cache.clear()
            cache[key] = uniform_segments(tol, dense_pts)
        ax.set_title(f"tolerance {tol:g}: {len(t) - 1} segments", fontsize=10)
        return {"polyline": pts, "t": t, "segments": len(t) - 1, "polygon": P,
                "status": f"tol = {tol:g}: {len(t) - 1} segments by adaptive subdivision; evenly spaced "
                          f"parameters need about {cache[key]}"}

    digits = as_int(digits, "digits", minimum=1, maximum=4)
    controls = {"digits": int_slider("tol 1e-", digits, 1, 4),
                **point_sliders(ctrl, (*ax.get_xlim(), *ax.get_ylim()), width="200px", label_width="24px")}
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="rendering by subdivision", side=True,
                           arrange=[controls["digits"]] + pair_rows(controls, n1))
    view.ax = ax
    drag_sliders(view, ax, point_pairs(n1))
    return view


def intersection_view(case: str = "two cubics, three crossings", level: int = 3, shift: float = 0.0,
                      max_level: int = 10) -> InteractiveView:
    """Curve-curve intersection by subdivision (Goldman §25.3.1): a picker of curve pairs, a slider
    that moves the second curve up or down, and a level slider showing the bounding boxes of
    the pieces still in play at that level of subdivision, with the intersections found.

    ``update(case, level, shift)`` returns the boxes of both curves (k, 2, 2), the parameter pairs
    and the points of :func:`goldman_lib.bezier.intersect_curves`.
    """
    if case not in INTERSECTION_EXAMPLES:
        raise ValueError(f"case must be one of {', '.join(INTERSECTION_EXAMPLES)}; got {case!r}")

    fig, ax = style.new_axes()
    a0, b0 = INTERSECTION_EXAMPLES[case]
    pa = plot_control_polygon(a0, ax, labels=False, alpha=0.45)
    pb = plot_control_polygon(b0, ax, labels=False, alpha=0.45, color=style.PALETTE["good"])
    ca = plot_curve(a0, ax)
    cb = plot_curve(b0, ax, color=style.PALETTE["good"])
    boxes_a = plot_boxes(np.zeros((0, 2, 2)), ax, color=style.PALETTE["curve"])
    boxes_b = plot_boxes(np.zeros((0, 2, 2)), ax, color=style.PALETTE["good"])
    (hits,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=8, zorder=5)
    samples = np.linspace(0.0, 1.0, 200)
    shown = [case]

    def frame(a, b):
        # the view fits both curves over the whole shift range, so it does not jump while shifting
        draw_a, draw_b = (bezier.curve_sampler(len(P) - 1, samples.size) for P in (a, b))
        pts = [draw_a(a)] + [draw_b(b) + [0.0, dy] for dy in (-1.0, 1.0)]
        pts = np.concatenate(pts)
        ax.set_xlim(pts[:, 0].min() - 0.3, pts[:, 0].max() + 0.3)
        ax.set_ylim(pts[:, 1].min() - 0.3, pts[:, 1].max() + 0.3)

    frame(a0, b0)

    def update(case, level, shift):
        if case not in INTERSECTION_EXAMPLES:
            raise ValueError(f"case must be one of {', '.join(INTERSECTION_EXAMPLES)}; got {case!r}")
        level = as_int(level, "level", minimum=0, maximum=max_level)
        shift = as_float(shift, "shift")
        a, b = INTERSECTION_EXAMPLES[case]
        if case != shown[0]:
            frame(a, b)
            shown[0] = case
        b = b + np.array([0.0, shift])
        for line, P in ((pa, a), (pb, b)):
            line.set_data(P[:, 0], P[:, 1])
        for line, P in ((ca, a), (cb, b)):
            pts = bezier.curve_sampler(len(P) - 1, samples.size)(P)
            line.set_data(pts[:, 0], pts[:, 1])
        ba, bb, ia, ib = bezier.intersection_boxes(a, b, level)
        boxes_a.set_verts(_box_vertices(ba))
        boxes_b.set_verts(_box_vertices(bb))
        st = bezier.intersect_curves(a, b)
        points = bezier.de_casteljau(a, st[:, 0]) if len(st) else np.zeros((0, 2))
        hits.set_data(points[:, 0], points[:, 1])
        ax.set_title(f"level {level}: {len(ba)} + {len(bb)} pieces kept", fontsize=10)
        found = "; ".join(f"(s, t) = ({s:.4f}, {t:.4f})" for s, t in st) or "none"
        return {"boxes_a": ba, "boxes_b": bb, "params": st, "points": points,
                "status": f"{len(st)} intersection(s): {found}"}

    level = as_int(level, "level", minimum=0, maximum=max_level)
    controls = {"case": dropdown("curves", list(INTERSECTION_EXAMPLES), case, label_width="48px", width="290px"),
                "level": int_slider("level", level, 0, max_level),
                "shift": float_slider("shift", shift, -1.0, 1.0, 0.05)}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="intersection by subdivision", side=True)


def patch_rendering_view(ctrl=DEFAULT_PATCH_25, digits: int = 1) -> InteractiveView:
    """Adaptive subdivision of a Bezier patch (Goldman §25.3.2): the tolerance slider sets
    ``tol = 10**-digits``; the left panel shows the parameter rectangles of the flat pieces, the
    right panel the pieces' corner quadrilaterals seen from above, shaded by height.

    ``update(digits)`` returns the rectangles (k, 4) and the number of pieces.
    """
    from matplotlib.collections import PolyCollection

    net = as_points(ctrl, "ctrl", ndim=3, dim=3, min_count=2)
    fig = style.new_figure(style.WIDE_FIGSIZE)
    ax_dom = style.style_axes(fig.add_subplot(1, 2, 1))
    ax_top = style.style_axes(fig.add_subplot(1, 2, 2))
    domains = plot_patch_domains(np.array([[0.0, 1.0, 0.0, 1.0]]), ax_dom)
    ax_dom.set_title("pieces in the (u, v) domain", fontsize=10)
    quads = PolyCollection([], cmap="viridis", edgecolors="#333333", linewidths=0.5)
    ax_top.add_collection(quads)
    xy = net.reshape(-1, 3)
    ax_top.set_xlim(xy[:, 0].min() - 0.1, xy[:, 0].max() + 0.1)
    ax_top.set_ylim(xy[:, 1].min() - 0.1, xy[:, 1].max() + 0.1)
    heights = bezier.patch_grid(net, 9, 9)[..., 2]
    zmin, zmax = float(heights.min()), float(heights.max())
    quads.set_clim(zmin, zmax if zmax > zmin else zmin + 1)
    ax_top.set_title("the flat pieces from above (colour: height)", fontsize=10)
    ax_top.set_xticks([])
    ax_top.set_yticks([])
    ax_top.grid(False)
    ax_dom.set_xticks([0, 0.5, 1])
    ax_dom.set_yticks([0, 0.5, 1])

    def update(digits):
        digits = as_int(digits, "digits", minimum=0, maximum=2)
        tol = 10.0 ** (-digits)
        corners, dom = bezier.render_patch_by_subdivision(net, tol)
        domains.set_verts(_domain_vertices(dom))
        quads.set_verts(list(corners[:, :, :2]))
        quads.set_array(corners[:, :, 2].mean(axis=1))
        return {"domains": dom, "corners": corners, "pieces": len(dom),
                "status": f"tol = {tol:g}: {len(dom)} flat pieces ({2 * len(dom)} triangles)"}

    digits = as_int(digits, "digits", minimum=0, maximum=2)
    controls = {"digits": int_slider("tol 1e-", digits, 0, 2)}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="patch rendering by subdivision")


# -- three.js: sub-nets and surface-surface intersection (§25.3.2) -------------------------------

def _net_segments(count: int, rows: int, cols: int) -> np.ndarray:
    """Index pairs (k, 2) of the row and column edges of ``count`` nets of ``rows x cols`` points
    stored one after another, row by row."""
    ii, jj = np.meshgrid(np.arange(rows), np.arange(cols), indexing="ij")
    idx = ii * cols + jj
    one = np.concatenate([np.stack([idx[:, :-1].ravel(), idx[:, 1:].ravel()], 1),
                          np.stack([idx[:-1, :].ravel(), idx[1:, :].ravel()], 1)])
    return (one[None] + (rows * cols) * np.arange(count)[:, None, None]).reshape(-1, 2)


def patch_subdivision_3d_view(ctrl=DEFAULT_PATCH_25, mode: str = "sub-nets", level: int = 2, height: float = 0.3,
                              tol: float = 0.02, resolution: int = 24, width: int = 480,
                              height_px: int = 360) -> InteractiveView:
    """Subdivision of a Bezier patch in three.js (Goldman §25.2-25.3.2), two modes.

    ``"sub-nets"``: the patch split ``level`` times at the middle of both parameters (0-4); the
    control nets of all 4**level sub-patches are drawn over the surface and close in on it.
    ``"intersection"``: a horizontal plane patch at ``height`` meets the patch; the sub-nets at
    ``level`` whose bounding boxes still meet the plane's are drawn, with the intersection curve
    of :func:`goldman_lib.bezier.intersect_patches` (flatness ``tol``), drawn as its polyline.

    ``update(mode, level, height)`` returns the drawn nets (k, m+1, n+1, 3), their parameter
    rectangles (k, 4), the surface grid, and in intersection mode the curve's points (k, 3),
    parameters (k, 4) and drawn segments (j, 2, 3).
    """

    from goldman_lib.widgets.three import SceneView, grid_triangles

    modes = ("sub-nets", "intersection")
    if mode not in modes:
        raise ValueError(f"mode must be one of {', '.join(modes)}; got {mode!r}")
    net = as_points(ctrl, "ctrl", ndim=3, dim=3, min_count=2)
    resolution = as_int(resolution, "resolution", minimum=2, maximum=100)
    tol = float(tol)
    rows, cols = net.shape[0], net.shape[1]
    grid = np.linspace(0.0, 1.0, resolution)
    surface = bezier.patch_evaluate_grid(net, grid, grid)
    lo, hi = net.reshape(-1, 3).min(0), net.reshape(-1, 3).max(0)
    margin = 0.1 * float((hi - lo)[:2].max())

    def plane(h):
        return np.array([[[lo[0] - margin, lo[1] - margin, h], [lo[0] - margin, hi[1] + margin, h]],
                         [[hi[0] + margin, lo[1] - margin, h], [hi[0] + margin, hi[1] + margin, h]]])

    # the sub-nets of every level, and how far their control points are from the surface (at the
    # parameters (i/m, j/n) of each piece), computed once
    levels = {}
    for L in range(5):
        nets, doms = bezier.subdivide_patch_uniform(net, L)
        levels[L] = (nets, doms, bezier.net_distance(nets))

    center = (lo + hi) / 2
    scene = SceneView(width=width, height=height_px, target=tuple(center),
                      camera_position=tuple(center + np.array([3.0, -4.2, 3.6])), axes=0)
    scene.add_mesh("surface", surface.reshape(-1, 3), grid_triangles(resolution, resolution),
                   color=style.PALETTE["surface"])
    P2 = plane(height)
    scene.add_mesh("second patch", P2.reshape(-1, 3), np.array([[0, 2, 1], [1, 2, 3]]), color="#edae49",
                   opacity=0.6)
    nets0 = levels[0][0]
    scene.add_segments("sub-nets", nets0.reshape(-1, 3), _net_segments(1, rows, cols), color="#333333", width=0.7)
    scene.add_segments("intersection", np.zeros((2, 3)) + center, [[0, 1]], color=style.PALETTE["point"], width=2.5)
    nowhere = np.zeros((1, 3)) + center        # a degenerate primitive stands for "nothing drawn"
    lift = np.array([0.0, 0.0, 0.01 * max(float(hi[2] - lo[2]), 1e-3)])
    nothing = {"sub-nets": nets0[:0], "domains": np.zeros((0, 4))}

    def update(mode, level, height):
        if mode not in modes:
            raise ValueError(f"mode must be one of {', '.join(modes)}; got {mode!r}")
        level = as_int(level, "level", minimum=0, maximum=4)
        height = as_float(height, "height")
        nets, doms, gap = levels[level]
        if mode == "sub-nets":
            shown, shown_doms = nets, doms
            scene.replace_mesh("second patch", np.repeat(nowhere, 3, axis=0), [[0, 1, 2]])
            scene.replace_segments("intersection", np.repeat(nowhere, 2, axis=0), [[0, 1]])
            points, params, segs = np.zeros((0, 3)), np.zeros((0, 4)), np.zeros((0, 2, 3))
            status = (f"level {level}: {len(nets)} sub-patches; their control points are within {gap:.4f} "
                      f"of the surface")
        else:
            P2 = plane(height)
            boxes = np.stack([nets.min(axis=(1, 2)), nets.max(axis=(1, 2))], axis=1)
            meet = np.all((boxes[:, 0] <= P2.max(axis=(0, 1))) & (P2.min(axis=(0, 1)) <= boxes[:, 1]), axis=1)
            shown, shown_doms = nets[meet], doms[meet]
            points, params, pairs = bezier.intersect_patches(net, P2, tol=tol, segments=True)
            segs = points[pairs] if len(pairs) else np.zeros((0, 2, 3))
            scene.replace_mesh("second patch", P2.reshape(-1, 3), [[0, 2, 1], [1, 2, 3]])
            if len(pairs):
                # drawn a hair above the plane, so the translucent plane does not hide it (z-fighting)
                scene.replace_segments("intersection", points + lift, pairs)
            else:
                scene.replace_segments("intersection", np.repeat(nowhere, 2, axis=0), [[0, 1]])
            res = 0.0
            if len(points):
                res = float(np.abs(bezier.patch_de_casteljau(net, params[:, 0], params[:, 1])[:, 2] - height).max())
            status = (f"plane z = {height:.2f}: {len(points)} points on the intersection curve "
                      f"(|z - {height:.2f}| <= {res:.1e}); level {level}: {len(shown)} of {len(nets)} "
                      f"sub-patches meet the plane's box")
        if len(shown):
            scene.replace_segments("sub-nets", shown.reshape(-1, 3), _net_segments(len(shown), rows, cols))
        else:
            scene.replace_segments("sub-nets", np.repeat(nowhere, 2, axis=0), [[0, 1]])
        return {"surface": surface, "sub-nets": shown if len(shown) else nothing["sub-nets"],
                "domains": shown_doms if len(shown) else nothing["domains"], "gap": gap,
                "points": points, "params": params, "segments": segs, "status": status}

    level = as_int(level, "level", minimum=0, maximum=4)
    controls = {"mode": dropdown("show", list(modes), mode, label_width="48px", width="290px"),
                "level": int_slider("level", level, 0, 4),
                "height": float_slider("plane z", height, 0.05, 0.6, 0.05)}
    view = InteractiveView(controls=controls, views=[scene.widget], update=update, static=scene.to_png,
                           title="patch subdivision and intersection", side=True,
                           acts={"height": {"mode": ["intersection"]}})     # the cutting plane: intersection only
    view.scene = scene
    return view

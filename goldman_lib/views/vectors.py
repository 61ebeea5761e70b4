"""Chapter 9-10 views: affine combinations in the plane, and the determinant as a signed volume.

* :func:`affine_combination_view` (Goldman §9.3): three points and an origin you drag with the
  mouse (ipympl, through :func:`~goldman_lib.widgets.drag.drag_sliders`), three weight sliders, and
  the location ``O + Σ w_i (P_i - O)`` that the coordinate sum ``Σ w_i P_i`` names when the
  coordinates are measured from the origin ``O``.  Drag the origin: with weights summing to 1 the
  point stays put among the P_i (an affine combination); otherwise it slides with the origin.
* :func:`determinant_view` (Goldman §9.4, §10.3): three vectors u, v, w in three.js, the
  parallelepiped they span, and u × v; the status line gives ``det(u, v, w) = (u × v) · w`` with
  its cofactor expansion and says whether (u, v, w) is right-handed, left-handed or flat.

Every number comes from :mod:`goldman_lib.vectors`; this module only draws.

>>> view = affine_combination_view()
>>> sorted(view.update(**view.values()))
['from_origin', 'from_zero', 'kind', 'status', 'total']
>>> view = determinant_view()
>>> sorted(view.update(**view.values()))
['cross', 'det', 'status', 'terms', 'vertices', 'volume']
"""

from __future__ import annotations

import numpy as np

from goldman_lib import vectors
from goldman_lib.widgets import style
from goldman_lib.widgets.drag import drag_sliders
from goldman_lib.widgets.interactive import InteractiveView, figure_widget, float_slider
from goldman_lib.widgets.vectors3d import COLOURS, VectorScene

__all__ = ["affine_combination_view", "determinant_view", "parallelepiped_vertices"]

_LIMIT = 4.0


def affine_combination_view(points=((-2.0, -1.0), (2.5, -1.5), (0.5, 2.0)), weights=(0.2, 0.5, 0.3),
                            origin=(-3.0, 2.5)) -> InteractiveView:
    """Three points P0, P1, P2 and an origin O (all draggable), weights w0, w1, w2, and the
    location ``O + Σ w_i (P_i - O)`` (Goldman §9.3), drawn filled, beside the same sum taken from
    the fixed origin (0, 0), drawn hollow.  The two coincide for every O exactly when the weights sum
    to 1; otherwise they are ``(1 - Σ w_i) |O|`` apart, and dragging O drags the sum.

    ``update(x0, y0, x1, y1, x2, y2, w0, w1, w2, ox, oy)`` returns both locations, the weights'
    total and :func:`~goldman_lib.vectors.combination_kind` of the weights.
    """
    P = np.asarray(points, dtype=float)
    if P.shape != (3, 2):
        raise ValueError(f"points must be three 2D points, shape (3, 2); got shape {P.shape}")
    fig, ax = style.new_axes()
    ax.set_xlim(-_LIMIT - 0.5, _LIMIT + 0.5)
    ax.set_ylim(-_LIMIT + 0.5, _LIMIT + 0.5)
    ax.set_title("Σ wᵢPᵢ measured from an origin O: drag O and the points", fontsize=10)
    (tri,) = ax.plot(*np.vstack([P, P[:1]]).T, "-", color=style.PALETTE["control"], linewidth=1)
    (pts,) = ax.plot(*P.T, "o", color=style.PALETTE["curve"], markersize=8, zorder=4)
    labels = [ax.annotate(f"P{k}", p, textcoords="offset points", xytext=(6, 6), fontsize=9,
                          color=style.PALETTE["curve"]) for k, p in enumerate(P)]
    spokes = [ax.plot([], [], ":", color="#999999", linewidth=0.9)[0] for _ in range(3)]
    (orig,) = ax.plot([], [], "s", color="#222222", markersize=8, zorder=5)
    orig_label = ax.annotate("O", (0, 0), textcoords="offset points", xytext=(6, -12), fontsize=9)
    ax.plot([0], [0], "+", color="#222222", markersize=10)
    (link,) = ax.plot([], [], "--", color=style.PALETTE["accent"], linewidth=1.2)
    (ghost,) = ax.plot([], [], "o", markerfacecolor="none", markeredgecolor=style.PALETTE["point"],
                       markersize=11, markeredgewidth=1.5, label="Σ wᵢPᵢ from (0, 0)", zorder=5)
    (dot,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=7, label="Σ wᵢPᵢ from O", zorder=6)
    ax.legend(fontsize=8, loc="lower right", frameon=False)

    def update(x0, y0, x1, y1, x2, y2, w0, w1, w2, ox, oy):
        Q = np.array([[x0, y0], [x1, y1], [x2, y2]], dtype=float)
        w = np.array([w0, w1, w2], dtype=float)
        O = np.array([ox, oy], dtype=float)
        here = vectors.weighted_sum_from_origin(Q, w, O)
        there = vectors.weighted_sum_from_origin(Q, w, np.zeros(2))
        kind = vectors.combination_kind(w, tol=1e-6)
        total = float(w.sum())
        tri.set_data(*np.vstack([Q, Q[:1]]).T)
        pts.set_data(*Q.T)
        for label, p in zip(labels, Q):
            label.xy = p
        for spoke, p in zip(spokes, Q):
            spoke.set_data([O[0], p[0]], [O[1], p[1]])
        orig.set_data([O[0]], [O[1]])
        orig_label.xy = O
        dot.set_data([here[0]], [here[1]])
        ghost.set_data([there[0]], [there[1]])
        link.set_data([there[0], here[0]], [there[1], here[1]])
        gap = float(vectors.length(here - there))
        where = f"({here[0]:.2f}, {here[1]:.2f})"
        if kind == "point":
            status = (f"w0 + w1 + w2 = {total:.2f}: an affine combination, the point {where} "
                      f"wherever O is")
        else:
            status = (f"w0 + w1 + w2 = {total:.2f}, not 1: from O the sum lands at {where}, {gap:.2f} from where it "
                      f"lands from (0, 0); it moves by (1 - Σw) times the move of O")
            if kind == "vector":
                status += " (weights summing to 0 give a vector, not a point)"
        return {"from_origin": here, "from_zero": there, "total": total, "kind": kind, "status": status}

    controls = {}
    for k, (x, y) in enumerate(P):
        controls[f"x{k}"] = float_slider(f"x{k}", float(x), -_LIMIT, _LIMIT, 0.1, width="220px", label_width="28px")
        controls[f"y{k}"] = float_slider(f"y{k}", float(y), -_LIMIT, _LIMIT, 0.1, width="220px", label_width="28px")
    for k, wk in enumerate(weights):
        controls[f"w{k}"] = float_slider(f"w{k}", float(wk), -1.0, 2.0, 0.05, width="220px", label_width="28px")
    controls["ox"] = float_slider("ox", float(origin[0]), -_LIMIT, _LIMIT, 0.1, width="220px", label_width="28px")
    controls["oy"] = float_slider("oy", float(origin[1]), -_LIMIT, _LIMIT, 0.1, width="220px", label_width="28px")
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="affine combinations do not depend on the origin", side=True)
    drag_sliders(view, ax, [("x0", "y0"), ("x1", "y1"), ("x2", "y2"), ("ox", "oy")])
    return view


def parallelepiped_vertices(u, v, w, origin=(0.0, 0.0, 0.0)) -> np.ndarray:
    """The eight corners ``O + a u + b v + c w`` (a, b, c in {0, 1}) of the parallelepiped spanned by
    u, v, w, in the order a + 2b + 4c (for drawing; Goldman §9.4).

    >>> parallelepiped_vertices([1, 0, 0], [0, 1, 0], [0, 0, 1])[7].tolist()
    [1.0, 1.0, 1.0]
    """
    E = np.array([u, v, w], dtype=float)
    bits = np.array([[(k >> i) & 1 for i in range(3)] for k in range(8)], dtype=float)
    return np.asarray(origin, dtype=float) + bits @ E


# the 12 triangles of the six faces, over the corner numbering a + 2b + 4c
_BOX_TRIANGLES = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                           [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
_BOX_EDGES = np.array([[0, 1], [2, 3], [4, 5], [6, 7], [0, 2], [1, 3], [4, 6], [5, 7],
                       [0, 4], [1, 5], [2, 6], [3, 7]])


def determinant_view(u=(1.5, 0.2, 0.0), v=(0.3, 1.3, 0.1), w=(0.4, 0.5, 1.2)) -> InteractiveView:
    """Three vectors u, v, w from the origin, the parallelepiped they span and u × v (Goldman §9.4,
    §10.3).  ``det(u, v, w) = (u × v) · w`` is its signed volume: positive when w lies on the side
    of the plane of u and v that u × v points to (a right-handed triple), negative on the other side,
    zero when the three are coplanar.  The status line shows the cofactor expansion along the first
    row, whose three terms add up to the determinant.

    ``update(ux, ..., wz)`` returns the determinant, its cofactor terms, the volume, u × v and the
    eight corners drawn.
    """
    scene = VectorScene(camera_position=(3.6, -4.6, 3.0), target=(0.5, 0.5, 0.4))
    zero = np.zeros((1, 3))
    a, b, c = (np.asarray(x, dtype=float)[None] for x in (u, v, w))
    corners = parallelepiped_vertices(a[0], b[0], c[0])
    scene.add_mesh("box", corners, _BOX_TRIANGLES, color=COLOURS["plane"], opacity=0.35)
    scene.add_segments("box:edges", corners, _BOX_EDGES, color="#7aa6c2", width=1.2)
    scene.add_arrows("u", zero, a, color=COLOURS["u"])
    scene.add_arrows("v", zero, b, color=COLOURS["v"])
    scene.add_arrows("w", zero, c, color=COLOURS["w"])
    scene.add_arrows("cross", zero, vectors.cross(a, b), color=COLOURS["cross"])
    controls = {}
    for name, value in (("u", u), ("v", v), ("w", w)):
        for axis, x in zip("xyz", value):
            controls[f"{name}{axis}"] = float_slider(f"{name}{axis}", float(x), -2.0, 2.0, 0.1, width="220px",
                                                     label_width="28px")

    def update(ux, uy, uz, vx, vy, vz, wx, wy, wz):
        a, b, c = np.array([[ux, uy, uz]]), np.array([[vx, vy, vz]]), np.array([[wx, wy, wz]])
        n = vectors.cross(a, b)
        box = parallelepiped_vertices(a[0], b[0], c[0])
        scene.set_mesh("box", box)
        scene.set_segments("box:edges", box)
        scene.set_arrows("u", zero, a)
        scene.set_arrows("v", zero, b)
        scene.set_arrows("w", zero, c)
        scene.set_arrows("cross", zero, n)
        d = float(vectors.det(a[0], b[0], c[0]))
        terms = vectors.det_cofactor_terms(a[0], b[0], c[0])
        scale = float(vectors.length(a[0]) * vectors.length(b[0]) * vectors.length(c[0]))
        if abs(d) <= 1e-9 * max(scale, 1.0):
            kind = "u, v, w are coplanar (or one is zero): the parallelepiped is flat"
        elif d > 0:
            kind = "positive, (u, v, w) is right-handed: w lies on the side u×v points to"
        else:
            kind = "negative, (u, v, w) is left-handed: w lies on the far side from u×v"
        shown = [round(float(t), 3) + 0.0 for t in terms]
        expansion = f"{shown[0]:.3f}" + "".join(f" {'+' if t >= 0 else '-'} {abs(t):.3f}" for t in shown[1:])
        status = f"det(u, v, w) = (u×v)·w = {expansion} = {round(d, 3) + 0.0:.3f}: {kind}; volume {abs(d):.3f}"
        return {"det": d, "terms": terms, "volume": abs(d), "cross": n[0], "vertices": box, "status": status}

    legend = ("<span style='color:%s'>&#9632; u</span> &nbsp;<span style='color:%s'>&#9632; v</span> &nbsp;"
              "<span style='color:%s'>&#9632; w</span> &nbsp;<span style='color:%s'>&#9632; u × v</span>"
              % (COLOURS["u"], COLOURS["v"], COLOURS["w"], COLOURS["cross"]))
    import ipywidgets as widgets

    return InteractiveView(controls=controls, views=[scene.widget, widgets.HTML(legend)], update=update,
                           static=scene.to_png, title="the determinant: a signed volume", side=True)

"""Chapter 4 views: a figure and its image under an affine map (Goldman §4.2-4.7).

:func:`plot_map` draws a figure (the letter F or a house, so that orientation shows) and its image
under a map.  Three widget factories return an
:class:`~goldman_lib.widgets.interactive.InteractiveView` whose ``update`` is a plain function
returning what it drew:

* :func:`transform_explorer`: pick translation, rotation, uniform scaling, nonuniform scaling,
  shear or mirror; sliders for its parameters (centre, angle, factor, direction); the mouse drags
  the centre (the tip of v for a translation);
* :func:`three_point_explorer`: sliders for the images of three points, the map
  :func:`goldman_lib.affine.affine_from_points` (§4.7.3); the mouse drags the three images;
* :func:`rotation_about_point_view`: rotation about ``Q`` as ``T(-Q) R T(Q)``, step by step (§4.4); the mouse drags Q.

Each point a learner places can be dragged (``view.drag``, the shared
:class:`~goldman_lib.widgets.drag.PointDrag`); a drag sets the point's sliders.

>>> view = transform_explorer()
>>> sorted(view.update(**view.values()))
['center', 'image', 'matrix', 'original', 'status']
"""

from __future__ import annotations

import numpy as np

from goldman_lib import affine
from goldman_lib.angles import cos_sin_degrees
from goldman_lib.validation import as_points
from goldman_lib.widgets import style
from goldman_lib.widgets.drag import PointDrag, drag_sliders, snap_to_slider
from goldman_lib.widgets.interactive import dropdown, figure_widget, float_slider, InteractiveView
from goldman_lib.views.turtle import stroke_data

__all__ = ["FIGURES", "KINDS", "plot_map", "format_matrix", "transform_explorer", "three_point_explorer",
           "rotation_about_point_view"]

#: Figures whose images show orientation: name -> list of closed ``(k, 2)`` polylines.
FIGURES = {
    "letter F": [np.array([[0, 0], [0.4, 0], [0.4, 0.9], [0.9, 0.9], [0.9, 1.3], [0.4, 1.3], [0.4, 1.6],
                           [1.2, 1.6], [1.2, 2.0], [0, 2.0], [0, 0]], dtype=float)],
    "house": [np.array([[0, 0], [1.2, 0], [1.2, 1], [0.6, 1.7], [0, 1], [0, 0]], dtype=float),
              np.array([[0.45, 0], [0.45, 0.55], [0.75, 0.55], [0.75, 0]], dtype=float)],
}

#: The transformations :func:`transform_explorer` offers, with the sliders each one uses.
KINDS = {
    "translation": ("tx", "ty"),
    "rotation": ("angle", "cx", "cy"),
    "uniform scaling": ("factor", "cx", "cy"),
    "nonuniform scaling": ("factor", "direction", "cx", "cy"),
    "shear": ("shear", "cx", "cy"),
    "mirror": ("direction", "cx", "cy"),
}

BOX = (-4.0, 5.0, -3.5, 5.0)


def _legend(entries) -> "widgets.HTML":
    """A legend as an HTML widget beside the controls: free to redraw, unlike a matplotlib legend."""
    import ipywidgets as widgets

    items = "".join(f'<div><span style="color:{c};font-weight:bold">{sym}</span> {text}</div>'
                    for c, sym, text in entries)
    return widgets.HTML(f"<small>{items}</small>", layout=widgets.Layout(width="290px"))


def format_matrix(M, digits: int = 3) -> str:
    """The 3x3 matrix as one line of text, rows separated by ``;`` (for status lines).

    >>> format_matrix(affine.translation([2, -1]))
    '[1 0 0; 0 1 0; 2 -1 1]'
    """
    rows = []
    for row in np.asarray(M, dtype=float):
        rows.append(" ".join(f"{(0.0 if abs(v) < 0.5 * 10 ** -digits else v):.{digits}g}" for v in row))
    return "[" + "; ".join(rows) + "]"


def _figure(figure):
    if isinstance(figure, str):
        if figure not in FIGURES:
            raise ValueError(f"figure must be one of {sorted(FIGURES)} or a list of polylines; got {figure!r}")
        return FIGURES[figure]
    if isinstance(figure, np.ndarray) and figure.ndim == 2:
        figure = [figure]
    return [as_points(p, f"figure[{i}]", dim=2) for i, p in enumerate(figure)]


def _image(polylines, M):
    return [affine.apply(p, M) for p in polylines]


def _set(line, polylines):
    x, y = stroke_data(polylines)
    line.set_data(x, y)


def _axes(box=BOX, title=None):
    fig, ax = style.new_axes()
    ax.set_xlim(box[0], box[1])
    ax.set_ylim(box[2], box[3])
    ax.set_aspect("equal", adjustable="box")
    ax.axhline(0, color="#bbbbbb", linewidth=0.8, zorder=0)
    ax.axvline(0, color="#bbbbbb", linewidth=0.8, zorder=0)
    if title:
        ax.set_title(title, fontsize=10)
    return fig, ax


def _artists(ax):
    pal = style.PALETTE
    (orig,) = ax.plot([], [], color=pal["control"], linewidth=1.2, linestyle="--")
    (image,) = ax.plot([], [], color=pal["curve"], linewidth=2.0)
    (fill_o,) = ax.fill([0], [0], color=pal["control"], alpha=0.12, linewidth=0)
    (fill_i,) = ax.fill([0], [0], color=pal["surface"], alpha=0.35, linewidth=0)
    return orig, image, fill_o, fill_i


def plot_map(M, figure="letter F", ax=None, *, title: str | None = None):
    """Draw a figure (dashed grey) and its image under the affine map ``M`` (blue), Goldman §4.5.

    M: (3, 3) in the row-vector convention.  figure: a name from :data:`FIGURES` or a list of
    ``(k, 2)`` polylines.  Returns the axes.  Raises ValueError for a bad map or figure.

    >>> ax = plot_map(affine.rotation(90))
    >>> ax.lines[0].get_xydata().shape, ax.lines[1].get_xydata()[1].round(12).tolist()
    ((11, 2), [0.0, 0.4])
    """
    M = affine.as_affine(M)
    polys = _figure(figure)
    ax = style.get_axes(ax)
    orig, image, fill_o, fill_i = _artists(ax)
    img = _image(polys, M)
    _set(orig, polys)
    _set(image, img)
    fill_o.set_xy(polys[0])
    fill_i.set_xy(img[0])
    pts = np.concatenate(polys + img)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    pad = 0.1 * max(1.0, float(np.max(hi - lo)))
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    if title:
        ax.set_title(title, fontsize=10)
    return ax


def _map_of(kind, tx, ty, angle, cx, cy, factor, direction, shear):
    c = (cx, cy)
    d = cos_sin_degrees(direction)
    if kind == "translation":
        return affine.translation([tx, ty]), f"T(v), v = ({tx:.2f}, {ty:.2f})"
    if kind == "rotation":
        return affine.rotation(angle, c), f"rotation by {angle:.0f}° about ({cx:.2f}, {cy:.2f})"
    if kind == "uniform scaling":
        return affine.scaling(factor, c), f"scaling by {factor:.2f} about ({cx:.2f}, {cy:.2f})"
    if kind == "nonuniform scaling":
        return (affine.directional_scaling(factor, d, c),
                f"scaling by {factor:.2f} along the direction {direction:.0f}° about ({cx:.2f}, {cy:.2f})")
    if kind == "shear":
        return affine.shear(shear, c), f"shear (x, y) -> (x + {shear:.2f} y, y) about ({cx:.2f}, {cy:.2f})"
    if kind == "mirror":
        return (affine.mirror(c, d), f"mirror in the line through ({cx:.2f}, {cy:.2f}) at {direction:.0f}°")
    raise ValueError(f"kind must be one of {list(KINDS)}; got {kind!r}")


def transform_explorer(kind: str = "rotation", figure: str = "letter F") -> InteractiveView:
    """Sliders for each basic affine map and the image of a figure under it (Goldman §4.2, §4.7).

    kind: one of :data:`KINDS` (translation, rotation, uniform scaling, nonuniform scaling,
    shear, mirror); only the sliders the chosen map uses are shown.  The centre ``(cx, cy)`` is
    the fixed point of rotation, scaling, shear and the point of the mirror line; ``direction``
    (degrees) is the direction of the nonuniform scaling and of the mirror line.  A zero factor
    is allowed: the image collapses onto a point or a line.
    ``update(kind, figure, tx, ty, angle, cx, cy, factor, direction, shear)`` returns
    ``{"original", "image", "matrix", "center", "status"}``; the status shows the matrix.
    """

    if kind not in KINDS:
        raise ValueError(f"kind must be one of {list(KINDS)}; got {kind!r}")
    _figure(figure)
    controls = {
        "kind": dropdown("map", list(KINDS), kind, label_width="70px", width="290px"),
        "figure": dropdown("figure", list(FIGURES), figure, label_width="70px", width="290px"),
        "tx": float_slider("v_x", 1.5, -3, 3, 0.1, label_width="70px"),
        "ty": float_slider("v_y", 0.5, -3, 3, 0.1, label_width="70px"),
        "angle": float_slider("angle °", 60, -180, 180, 1, readout=".0f", label_width="70px"),
        "cx": float_slider("centre x", 1.0, -2, 2, 0.1, label_width="70px"),
        "cy": float_slider("centre y", 0.0, -2, 2, 0.1, label_width="70px"),
        "factor": float_slider("factor", 1.5, -2, 2, 0.05, label_width="70px"),
        "direction": float_slider("direction °", 30, 0, 180, 1, readout=".0f", label_width="70px"),
        "shear": float_slider("shear", 0.6, -2, 2, 0.05, label_width="70px"),
    }
    fig, ax = _axes()
    orig, image, fill_o, fill_i = _artists(ax)
    (center,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=6, zorder=5)
    (guide,) = ax.plot([], [], color=style.PALETTE["accent"], linewidth=1.2, zorder=1)
    pal = style.PALETTE
    legend = _legend([(pal["control"], "- - -", "the figure"), (pal["curve"], "&#9473;&#9473;", "its image"),
                      (pal["point"], "&#9679;", "the centre (drag it)"),
                      (pal["accent"], "&#9473;&#9473;", "the direction (or the vector v)")])

    def show_relevant(change=None):
        used = KINDS[controls["kind"].value]
        for name in ("tx", "ty", "angle", "cx", "cy", "factor", "direction", "shear"):
            controls[name].layout.display = None if name in used else "none"

    controls["kind"].observe(show_relevant, names="value")
    show_relevant()

    def update(kind, figure, tx, ty, angle, cx, cy, factor, direction, shear):
        polys = _figure(figure)
        M, what = _map_of(kind, tx, ty, angle, cx, cy, factor, direction, shear)
        img = _image(polys, M)
        _set(orig, polys)
        _set(image, img)
        fill_o.set_xy(polys[0])
        fill_i.set_xy(img[0])
        c = np.array([0.0, 0.0]) if kind == "translation" else np.array([cx, cy])
        center.set_data([c[0]], [c[1]])
        if kind in ("nonuniform scaling", "mirror"):
            d = np.array(cos_sin_degrees(direction))
            seg = np.array([c - 10 * d, c + 10 * d])
            guide.set_data(seg[:, 0], seg[:, 1])
        elif kind == "translation":
            guide.set_data([0, tx], [0, ty])
        else:
            guide.set_data([], [])
        det = float(np.linalg.det(M[:2, :2]))
        status = f"{what}:  M = {format_matrix(M)},  det = {det:.3g}"
        return {"original": polys, "image": img, "matrix": M, "center": c, "status": status}

    # The default map's sliders first: the first slider on the page is one that moves the picture.
    names = ["kind", "figure"] + list(KINDS[kind]) + [n for n in ("tx", "ty", "angle", "cx", "cy", "factor",
                                                                   "direction", "shear") if n not in KINDS[kind]]
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Affine maps: a figure and its image", side=True,
                           arrange=[controls[n] for n in names], extra=[legend],
                           acts={n: {"kind": [k for k, used in KINDS.items() if n in used]}
                                 for n in ("tx", "ty", "angle", "cx", "cy", "factor", "direction", "shear")})

    # The mouse drags the point the chosen map has: the tip of v for a translation, else the centre.
    def grips():
        vals = view.values()
        if vals["kind"] == "translation":
            return np.array([[vals["tx"], vals["ty"]]])
        return np.array([[vals["cx"], vals["cy"]]])

    def on_drag(k, x, y):
        xs, ys = ("tx", "ty") if view.controls["kind"].value == "translation" else ("cx", "cy")
        view.set_values(**{xs: snap_to_slider(controls[xs], x), ys: snap_to_slider(controls[ys], y)})

    view.drag = PointDrag(ax, grips, on_drag)
    return view


#: The source triangle of :func:`three_point_explorer`.
SOURCE_TRIANGLE = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])


def three_point_explorer(images=((1.0, 0.5), (3.0, 1.0), (1.5, 2.5)), figure: str = "letter F") -> InteractiveView:
    """Sliders for the images ``Q1, Q2, Q3`` of the points ``(0, 0), (1, 0), (0, 1)``; the
    unique affine map sending them there moves the figure (Goldman §4.7.3).  Drag the images with
    the mouse (``view.drag``) or set them on their sliders.

    images: the initial ``(3, 2)`` images.  If the images are collinear the map is singular and
    the image of the figure collapses onto a line (the status says so).  ``update(figure, x1, y1,
    x2, y2, x3, y3)`` returns ``{"original", "image", "source", "target", "matrix", "status"}``.
    """

    Q = as_points(images, "images", dim=2)
    if Q.shape != (3, 2):
        raise ValueError(f"images must hold three 2D points, shape (3, 2); got {Q.shape}")
    _figure(figure)
    controls = {"figure": dropdown("figure", list(FIGURES), figure, label_width="48px", width="290px")}
    for k, (x, y) in enumerate(Q, start=1):
        controls[f"x{k}"] = float_slider(f"Q{k} x", float(x), -3, 4, 0.1)
        controls[f"y{k}"] = float_slider(f"Q{k} y", float(y), -3, 4, 0.1)
    fig, ax = _axes()
    orig, image, fill_o, fill_i = _artists(ax)
    pal = style.PALETTE
    (src,) = ax.plot(*np.vstack([SOURCE_TRIANGLE, SOURCE_TRIANGLE[:1]]).T, "o:", color=pal["control"],
                     markersize=5, linewidth=1)
    (dst,) = ax.plot([], [], "o:", color=pal["point"], markersize=6, linewidth=1.2, zorder=5)
    labels = [ax.annotate(f"$Q_{k}$", (0, 0), textcoords="offset points", xytext=(5, 5), fontsize=9,
                          color=pal["point"]) for k in (1, 2, 3)]
    for k, p in enumerate(SOURCE_TRIANGLE, start=1):
        ax.annotate(f"$P_{k}$", p, textcoords="offset points", xytext=(-12, -12), fontsize=9, color=pal["control"])
    legend = _legend([(pal["control"], "- - -", "the figure and P1 = (0, 0), P2 = (1, 0), P3 = (0, 1)"),
                      (pal["curve"], "&#9473;&#9473;", "its image"), (pal["point"], "&#9679;", "Q1, Q2, Q3 (drag them)")])

    def update(figure, x1, y1, x2, y2, x3, y3):
        polys = _figure(figure)
        T = np.array([[x1, y1], [x2, y2], [x3, y3]], dtype=float)
        M = affine.affine_from_points(SOURCE_TRIANGLE, T)
        img = _image(polys, M)
        _set(orig, polys)
        _set(image, img)
        fill_o.set_xy(polys[0])
        fill_i.set_xy(img[0])
        dst.set_data(*np.vstack([T, T[:1]]).T)
        for lab, p in zip(labels, T):
            lab.xy = (float(p[0]), float(p[1]))
        det = float(np.linalg.det(M[:2, :2]))
        note = ""
        if abs(det) < 1e-9:
            note = "  (Q1, Q2, Q3 are collinear: the map collapses the plane onto a line)"
        elif det < 0:
            note = "  (det < 0: the map reverses orientation, the figure is mirrored)"
        status = f"M = {format_matrix(M)},  det = {det:.3g}{note}"
        return {"original": polys, "image": img, "source": SOURCE_TRIANGLE.copy(), "target": T, "matrix": M,
                "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="The affine map of three points", side=True, extra=[legend])
    drag_sliders(view, ax, [("x1", "y1"), ("x2", "y2"), ("x3", "y3")])   # drag Q1, Q2, Q3 with the mouse
    return view


def rotation_about_point_view(angle: float = 60.0, qx: float = 2.0, qy: float = 1.0) -> InteractiveView:
    """Rotation about a point ``Q`` as three steps, ``T(-Q)``, ``R(angle)``, ``T(Q)`` (Goldman §4.4).

    The figure is moved so that ``Q`` goes to the origin (dotted), rotated about the origin
    (dash-dot), and moved back (solid): the result is the rotation about ``Q``.
    ``update(angle, qx, qy)`` returns ``{"steps": [figure, after T(-Q), after R, after T(Q)],
    "direct": rotation(angle, Q) applied to the figure, "matrix", "status"}``.
    """
    controls = {"angle": float_slider("angle °", angle, -180, 180, 1, readout=".0f", label_width="60px"),
                "qx": float_slider("Q x", qx, -2, 3, 0.1, label_width="60px"),
                "qy": float_slider("Q y", qy, -2, 3, 0.1, label_width="60px")}
    fig, ax = _axes(box=(-5.5, 5.5, -4.5, 5.0))
    pal = style.PALETTE
    styles = [(pal["control"], "--", "figure"), (style.level_colour(1), ":", "after T(-Q)"),
              (style.level_colour(2), "-.", "after T(-Q) R"), (pal["curve"], "-", "after T(-Q) R T(Q)")]
    lines = [ax.plot([], [], color=c, linestyle=ls, linewidth=2 if ls == "-" else 1.3)[0]
             for c, ls, lab in styles]
    (qdot,) = ax.plot([], [], "o", color=pal["point"], markersize=6, zorder=5)
    symbols = {"--": "- - -", ":": "&middot;&middot;&middot;&middot;", "-.": "-&middot;-&middot;",
               "-": "&#9473;&#9473;"}
    legend = _legend([(c, symbols[ls], lab) for c, ls, lab in styles] + [(pal["point"], "&#9679;", "Q (drag it)")])
    polys = FIGURES["letter F"]

    def update(angle, qx, qy):
        Q = np.array([qx, qy])
        maps = [affine.identity(), affine.translation(-Q), affine.rotation(angle), affine.translation(Q)]
        steps, M = [], affine.identity()
        for line, step in zip(lines, maps):
            M = M @ step
            img = _image(polys, M)
            _set(line, img)
            steps.append(img)
        qdot.set_data([qx], [qy])
        direct = _image(polys, affine.rotation(angle, Q))
        gap = max(float(np.abs(a - b).max()) for a, b in zip(direct, steps[-1]))
        status = (f"T(-Q) R T(Q) = {format_matrix(M)}; largest distance to rotation({angle:.0f}, Q) "
                  f"applied directly: {gap:.1e}")
        return {"steps": steps, "direct": direct, "matrix": M, "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="Rotation about Q = T(-Q) R T(Q)", side=True, extra=[legend])
    drag_sliders(view, ax, [("qx", "qy")])       # drag Q with the mouse
    return view

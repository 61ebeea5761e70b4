"""Chapter 11 views: the formulas of vector geometry drawn and printed (Goldman §11.3-11.7).

Four three.js scenes (:class:`~goldman_lib.widgets.vectors3d.VectorScene`) whose points, lines and
planes are set by sliders: a point and a plane with the foot of the perpendicular
(:func:`point_plane_view`), two skew lines with their closest points and common perpendicular
(:func:`skew_lines_view`), three planes meeting in a point (:func:`three_planes_view`) and the
volume of a parallelepiped and a tetrahedron (:func:`volume_view`).  Two matplotlib (ipympl)
pictures: the inside-outside map of a polygon coloured by winding number, with its vertices and a
query point draggable with the mouse (:func:`inside_outside_view`), and slerp against normalised
linear interpolation on the unit circle (:func:`slerp_view`).

Every number a view shows comes from :mod:`goldman_lib.vector_geometry` or
:mod:`goldman_lib.vectors`; the views only draw.  Degenerate positions (a zero normal, parallel
lines, parallel planes, coplanar edges, opposite vectors) are reported in the status line, never
raised.

>>> view = skew_lines_view()
>>> round(view.last_result["distance"], 6) == round(view.last_result["formula"], 6)
True
>>> view = inside_outside_view()
>>> view.last_result["winding"], bool(view.last_result["even_odd"])
(2, False)
"""

from __future__ import annotations

import numpy as np

from goldman_lib import vector_geometry as vg
from goldman_lib import vectors
from goldman_lib.validation import as_int, as_points
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import InteractiveView, dropdown, figure_widget, float_slider
from goldman_lib.widgets.vectors3d import COLOURS, VectorScene

__all__ = ["point_plane_view", "skew_lines_view", "three_planes_view", "volume_view", "inside_outside_view",
           "slerp_view", "STAR", "WINDING_COLOURS", "THREE_PLANE_NORMALS"]

#: The five-pointed star {5/2} of §11.7, counterclockwise: its centre has winding number 2.
STAR = np.array([[0.0, 3.0], [-1.76, -2.43], [2.85, 0.93], [-2.85, 0.93], [1.76, -2.43]])

#: Colours of the winding numbers -3 ... 3 in the inside-outside map (0 is white: outside).
WINDING_COLOURS = {-3: "#3f007d", -2: "#807dba", -1: "#dadaeb", 0: "#ffffff", 1: "#c7e9c0", 2: "#74c476", 3: "#238b45"}
_DIFFER = "#fdae6b"   # where the even-odd and nonzero rules disagree


def _fmt(p) -> str:
    return "(" + ", ".join(f"{float(x):.2f}" for x in np.ravel(p)) + ")"


def _slider3(prefix: str, value, low=-2.0, high=2.0, step=0.1):
    return {f"{prefix}{axis}": float_slider(f"{prefix}{axis}", float(v), low, high, step, width="230px",
                                            label_width="34px")
            for axis, v in zip("xyz", value)}


def _legend(items) -> "object":
    import ipywidgets as widgets

    return widgets.HTML(" &nbsp;".join(f"<span style='color:{c}'>&#9632; {t}</span>" for t, c in items))


def _is_zero(v) -> bool:
    return float(vectors.length(v)) <= 1e-12


# -- §11.4 a point and a plane ----------------------------------------------------------------------
def point_plane_view(point=(1.2, 0.6, 1.4), normal=(0.3, 0.4, 1.0)) -> InteractiveView:
    """A point Q and the plane through the origin with normal N (Goldman §11.3-11.4).

    Draws the plane (a square centred at the foot of the perpendicular), the normal N, the vector
    Q - P from the plane's point P = origin, the foot F of the perpendicular and the segment QF.  The
    status line gives ``(Q - P)·N``, ``|N|``, the signed distance ``(Q - P)·N / |N|`` and the distance
    ``|QF|``.  ``update(qx, qy, qz, nx, ny, nz)``.
    """
    P = np.zeros(3)
    Q0, N0 = np.array(point, float), np.array(normal, float)
    F0 = vg.foot_on_plane(Q0, P, N0)
    scene = VectorScene()
    scene.add_plane("plane", F0, N0, size=3.0, color=COLOURS["plane"])
    scene.add_arrows("N", P[None], N0[None], color=COLOURS["normal"])
    scene.add_arrows("QP", P[None], Q0[None], color=COLOURS["u"])
    scene.add_segments("perp", np.array([Q0, F0]), [[0, 1]], color=COLOURS["point"], width=2.0)
    scene.add_points("Q", Q0[None], color=COLOURS["point"], size=0.14)
    scene.add_points("F", F0[None], color=COLOURS["image"], size=0.14)
    controls = {**_slider3("q", Q0), **_slider3("n", N0, -1.0, 1.0, 0.05)}

    def update(qx, qy, qz, nx, ny, nz):
        Q, N = np.array([qx, qy, qz], float), np.array([nx, ny, nz], float)
        if _is_zero(N):
            return {"status": "N = 0 is no normal: a plane needs a nonzero normal vector (move a slider of N)"}
        F = vg.foot_on_plane(Q, P, N)
        signed = vg.point_plane_distance(Q, P, N, signed=True)
        dist = vg.point_plane_distance(Q, P, N)
        raw = vectors.dot(Q - P, N)
        scene.set_plane("plane", F, N, size=3.0)
        scene.set_arrows("N", P[None], N[None])
        scene.set_arrows("QP", P[None], Q[None])
        scene.set_segments("perp", np.array([Q, F]))
        scene.set_points("Q", Q[None])
        scene.set_points("F", F[None])
        side = "on the side N points to" if signed > 1e-12 else ("on the plane" if abs(signed) <= 1e-12 else
                                                                   "on the side away from N")
        status = (f"(Q−P)·N = {raw:.3f}, |N| = {float(vectors.length(N)):.3f}: signed distance {signed:.3f} "
                  f"(Q is {side}), distance |QF| = {dist:.3f}; foot F = {_fmt(F)}")
        return {"foot": F, "signed": signed, "distance": dist, "dot": raw, "status": status}

    legend = _legend([("plane", COLOURS["plane"]), ("N", COLOURS["normal"]), ("Q − P", COLOURS["u"]),
                      ("Q and QF", COLOURS["point"]), ("foot F", COLOURS["image"])])
    return InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="distance from a point to a plane", side=True)


# -- §11.4-11.5 two lines ------------------------------------------------------------------------
def _line_segment(p, d, half=2.5):
    """The piece of the line p + s d drawn on screen: |s d| <= half."""
    s = half / float(vectors.length(d))
    return np.array([p - s * d, p + s * d])


def skew_lines_view(d1=(1.0, 0.3, 0.0), p2=(0.2, -0.5, 1.2), d2=(-0.3, 1.0, 0.4)) -> InteractiveView:
    """Two lines, ``L1 = p1 + s d1`` through the origin and ``L2 = p2 + t d2`` (Goldman §11.4-11.5).

    Draws both lines, their closest points A on L1 and B on L2 (:func:`~goldman_lib.vector_geometry.intersect_lines`)
    and the common perpendicular AB, parallel to d1 × d2 (drawn as an arrow from p2).  The status
    compares ``|AB|`` with the book's formula ``|(p2 - p1)·(d1 × d2)| / |d1 × d2|``
    (:func:`~goldman_lib.vector_geometry.line_line_distance`); parallel lines are reported (every
    point has a closest partner, the distance is the point-line distance).
    ``update(d1x, d1y, d1z, p2x, p2y, p2z, d2x, d2y, d2z)``.
    """
    p1 = np.zeros(3)
    D1, P2, D2 = (np.array(x, float) for x in (d1, p2, d2))
    A, B, _ = vg.intersect_lines(p1, D1, P2, D2)
    scene = VectorScene()
    scene.add_segments("L1", _line_segment(p1, D1), [[0, 1]], color=COLOURS["u"], width=2.0)
    scene.add_segments("L2", _line_segment(P2, D2), [[0, 1]], color=COLOURS["v"], width=2.0)
    scene.add_segments("AB", np.array([A, B]), [[0, 1]], color=COLOURS["point"], width=2.5)
    scene.add_arrows("d1xd2", P2[None], vectors.cross(D1, D2)[None], color=COLOURS["cross"])
    scene.add_points("A", A[None], color=COLOURS["u"], size=0.14)
    scene.add_points("B", B[None], color=COLOURS["v"], size=0.14)
    scene.add_points("p2", P2[None], color=COLOURS["point"], size=0.08)
    controls = {**_slider3("d1", D1, -1.0, 1.0, 0.05), **_slider3("p2", P2), **_slider3("d2", D2, -1.0, 1.0, 0.05)}

    def update(d1x, d1y, d1z, p2x, p2y, p2z, d2x, d2y, d2z):
        d1_, p2_, d2_ = np.array([d1x, d1y, d1z]), np.array([p2x, p2y, p2z]), np.array([d2x, d2y, d2z])
        for name, d in (("d1", d1_), ("d2", d2_)):
            if _is_zero(d):
                return {"status": f"{name} = 0 is no direction: a line needs a nonzero direction vector"}
        formula = vg.line_line_distance(p1, d1_, p2_, d2_)
        c = vectors.cross(d1_, d2_)
        scene.set_segments("L1", _line_segment(p1, d1_))
        scene.set_segments("L2", _line_segment(p2_, d2_))
        scene.set_points("p2", p2_[None])
        try:
            A, B, dist = vg.intersect_lines(p1, d1_, p2_, d2_)
        except ValueError:
            scene.set_segments("AB", np.array([p1, p1]))
            scene.set_arrows("d1xd2", p1[None], np.zeros((1, 3)))
            scene.set_points("A", p1[None])
            scene.set_points("B", p1[None])
            return {"formula": formula, "cross": c,
                    "status": f"d1 × d2 = 0: the lines are parallel, {formula:.3f} apart (the distance from p2 to L1); "
                              f"every point has a closest partner, so there is no single common perpendicular"}
        scene.set_segments("AB", np.array([A, B]))
        scene.set_arrows("d1xd2", p2_[None], c[None])
        scene.set_points("A", A[None])
        scene.set_points("B", B[None])
        kind = "the lines meet at A = B" if dist == 0 else "skew lines"
        status = (f"{kind}: A = {_fmt(A)}, B = {_fmt(B)}, |AB| = {dist:.3f}; "
                  f"|(p2−p1)·(d1×d2)| / |d1×d2| = {abs(vectors.dot(p2_ - p1, c)):.3f} / "
                  f"{float(vectors.length(c)):.3f} = {formula:.3f}")
        return {"A": A, "B": B, "distance": dist, "formula": formula, "cross": c, "status": status}

    legend = _legend([("L1 = s d1", COLOURS["u"]), ("L2 = p2 + t d2", COLOURS["v"]), ("AB", COLOURS["point"]),
                      ("d1 × d2 at p2", COLOURS["cross"])])
    return InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="two lines: closest points and the common perpendicular", side=True)


# -- §11.5 three planes ---------------------------------------------------------------------------
#: The fixed normals of the first two planes of :func:`three_planes_view`.
THREE_PLANE_NORMALS = np.array([[1.0, 0.2, 0.0], [0.0, 1.0, 0.3]])


def three_planes_view(h=(0.6, 0.4, 0.5), n3=(0.2, 0.1, 1.0)) -> InteractiveView:
    """Three planes, plane k through ``h_k e_k`` (on the k-th axis); planes 1 and 2 have fixed
    normals, plane 3 the normal ``n3`` set by sliders (Goldman §11.5).

    Draws the three planes (squares centred at their common point X), X itself
    (:func:`~goldman_lib.vector_geometry.intersect_three_planes`) and the line where planes 1 and 2
    meet (:func:`~goldman_lib.vector_geometry.intersect_two_planes`), which passes through X.  When
    ``det(N1, N2, N3) = 0`` there is no single common point; the status says which planes are
    parallel.  ``update(h1, h2, h3, n3x, n3y, n3z)``.
    """
    N1, N2 = THREE_PLANE_NORMALS
    axes = np.eye(3)
    scene = VectorScene(camera_position=(3.6, -4.6, 3.0))
    colours = [COLOURS["u"], COLOURS["v"], COLOURS["w"]]
    for k in range(3):
        scene.add_plane(f"plane{k + 1}", np.zeros(3), [N1, N2, n3][k], size=2.4, color=colours[k], opacity=0.35)
    scene.add_segments("line12", np.zeros((2, 3)), [[0, 1]], color=COLOURS["sum"], width=2.5)
    scene.add_points("X", np.zeros((1, 3)), color=COLOURS["point"], size=0.16)
    controls = {f"h{k + 1}": float_slider(f"h{k + 1}", float(v), -1.5, 1.5, 0.05, width="230px", label_width="34px")
                for k, v in enumerate(h)}
    controls.update(_slider3("n3", n3, -1.0, 1.0, 0.05))

    def update(h1, h2, h3, n3x, n3y, n3z):
        N3 = np.array([n3x, n3y, n3z])
        if _is_zero(N3):
            return {"status": "n3 = 0 is no normal: plane 3 needs a nonzero normal vector"}
        points = np.array([h1, h2, h3])[:, None] * axes
        normals = [N1, N2, N3]
        planes = [(points[k], normals[k]) for k in range(3)]
        L0, v = vg.intersect_two_planes(planes[0], planes[1])
        d = vectors.det(N1, N2, N3)
        try:
            X = vg.intersect_three_planes(*planes)
        except ValueError:
            parallel = [f"{i + 1} and {j + 1}" for i, j in ((0, 1), (0, 2), (1, 2))
                        if float(vectors.length(vectors.cross(normals[i], normals[j]))) <= 1e-9]
            why = (f"planes {' and '.join(parallel)} are parallel" if parallel else
                   "the three normals lie in one plane, so the planes are parallel to one line")
            for k in range(3):
                scene.set_plane(f"plane{k + 1}", points[k], normals[k], size=2.4)
            scene.set_segments("line12", np.array([L0 - 1.5 * v, L0 + 1.5 * v]))
            scene.set_points("X", L0[None])
            return {"line_point": L0, "line_direction": v, "det": d,
                    "status": f"det(N1, N2, N3) = {d:.3f}: {why}; no single common point"}
        for k in range(3):
            scene.set_plane(f"plane{k + 1}", X, normals[k], size=2.4)
        scene.set_segments("line12", np.array([X - 1.5 * v, X + 1.5 * v]))
        scene.set_points("X", X[None])
        on_line = float(vg.point_line_distance(X, L0, v)) < 1e-9
        status = (f"X = {_fmt(X)}, det(N1, N2, N3) = {d:.3f}; X lies on the line where planes 1 and 2 meet: "
                  f"{'yes' if on_line else 'no'} (to 1e-9)")
        return {"X": X, "line_point": L0, "line_direction": v, "det": d, "status": status}

    legend = _legend([("plane 1", colours[0]), ("plane 2", colours[1]), ("plane 3", colours[2]),
                      ("line of planes 1, 2", COLOURS["sum"]), ("X", COLOURS["point"])])
    return InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="three planes meet in a point", side=True)


# -- §11.4 volumes -------------------------------------------------------------------------------------
_BOX_EDGES = [[0, 1], [0, 2], [0, 3], [1, 4], [1, 5], [2, 4], [2, 6], [3, 5], [3, 6], [4, 7], [5, 7], [6, 7]]


def _box_corners(u, v, w):
    """The eight corners 0, u, v, w, u+v, u+w, v+w, u+v+w of the parallelepiped (drawing only)."""
    return np.array([0 * u, u, v, w, u + v, u + w, v + w, u + v + w])


def volume_view(u=(1.4, 0.0, 0.0), v=(0.4, 1.2, 0.0), w=(0.3, 0.4, 1.1)) -> InteractiveView:
    """The parallelepiped spanned by u, v, w and the tetrahedron 0, u, v, w inside it
    (Goldman §11.4): volumes ``|det(u, v, w)|`` and ``|det(u, v, w)| / 6``.  The status gives the
    signed determinant (its sign: right- or left-handed) and both volumes; coplanar vectors give
    volume 0 and say so.  ``update(ux, uy, uz, vx, vy, vz, wx, wy, wz)``.
    """
    U, V, W = (np.array(x, float) for x in (u, v, w))
    scene = VectorScene()
    scene.add_segments("box", _box_corners(U, V, W), _BOX_EDGES, color="#7a7a7a", width=1.2)
    scene.add_mesh("tetra", np.array([0 * U, U, V, W]), [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
                   color=COLOURS["polygon"], opacity=0.7)
    zero = np.zeros((1, 3))
    scene.add_arrows("u", zero, U[None], color=COLOURS["u"])
    scene.add_arrows("v", zero, V[None], color=COLOURS["v"])
    scene.add_arrows("w", zero, W[None], color=COLOURS["w"])
    controls = {**_slider3("u", U), **_slider3("v", V), **_slider3("w", W)}

    def update(ux, uy, uz, vx, vy, vz, wx, wy, wz):
        a, b, c = np.array([ux, uy, uz]), np.array([vx, vy, vz]), np.array([wx, wy, wz])
        scene.set_segments("box", _box_corners(a, b, c))
        scene.set_mesh("tetra", np.array([0 * a, a, b, c]))
        scene.set_arrows("u", zero, a[None])
        scene.set_arrows("v", zero, b[None])
        scene.set_arrows("w", zero, c[None])
        d = float(vectors.det(a, b, c))
        box = float(vg.parallelepiped_volume(a, b, c))
        tet = float(vg.tetrahedron_volume(np.zeros(3), a, b, c))
        if box <= 1e-12:
            status = (f"det(u, v, w) = {d:.3f}: u, v, w are coplanar, the parallelepiped is flat and both volumes "
                      f"are 0")
        else:
            hand = "right-handed" if d > 0 else "left-handed"
            status = (f"det(u, v, w) = {d:.3f} ({hand}): parallelepiped volume {box:.3f}, tetrahedron volume "
                      f"{tet:.3f} = 1/6 of it")
        return {"det": d, "parallelepiped": box, "tetrahedron": tet, "status": status}

    legend = _legend([("u", COLOURS["u"]), ("v", COLOURS["v"]), ("w", COLOURS["w"]),
                      ("tetrahedron 0, u, v, w", "#2b6b2b")])
    return InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="volumes: parallelepiped and tetrahedron", side=True)


# -- §11.7 inside-outside tests --------------------------------------------------------------------------
_MODES = {"winding number (nonzero rule)": "winding", "even-odd rule (ray casting)": "even_odd",
          "where the two rules differ": "differ"}


def _rgba(hex_colour: str) -> np.ndarray:
    from matplotlib.colors import to_rgba

    return np.array(to_rgba(hex_colour))


def inside_outside_view(polygon=STAR, query=(0.2, 0.4), grid: int = 160, box: float = 3.5) -> InteractiveView:
    """The inside-outside map of a polygon (Goldman §11.7): every pixel of a ``grid`` x ``grid``
    image over ``[-box, box]²`` is coloured by its winding number
    (:func:`~goldman_lib.vector_geometry.winding_number`), by the even-odd rule
    (:func:`~goldman_lib.vector_geometry.ray_casting_inside`), or marked where the two rules
    disagree.  The polygon's vertices (sliders ``x0, y0, x1, y1, ...``) and the query point
    (sliders ``qx, qy``) can also be dragged with the mouse (:func:`~goldman_lib.widgets.drag.drag_sliders`).
    The query point's ray to the right is drawn with its crossings (▲ an edge going up, +1; ▼ going
    down, -1); the status gives its winding number, the crossing count and both verdicts.

    The figure's axes is ``view.ax``.  ``update(mode, qx, qy, x0, y0, ...)``.
    """
    import ipywidgets as widgets
    from matplotlib.patches import Patch

    poly = as_points(polygon, "polygon", dim=2, min_count=3)
    grid = as_int(grid, "grid", minimum=8, maximum=600)
    n = len(poly)
    xs = np.linspace(-box, box, grid)
    gx, gy = np.meshgrid(xs, xs)
    pixels = np.stack([gx, gy], axis=-1)
    table = np.array([_rgba(WINDING_COLOURS[k]) for k in range(-3, 4)])
    differ_rgba, inside_rgba = _rgba(_DIFFER), _rgba(WINDING_COLOURS[1])
    blank = np.ones((grid, grid, 4))

    fig, ax = style.new_axes()
    image = ax.imshow(blank, extent=(-box, box, -box, box), origin="lower",
                      interpolation="nearest", zorder=0)
    (outline,) = ax.plot([], [], "-", color="#2b2b2b", linewidth=1.4, zorder=2)
    (vertices,) = ax.plot([], [], "o", color=style.PALETTE["control"], markersize=7, zorder=3)
    labels = [ax.annotate(f"{k}", (0, 0), textcoords="offset points", xytext=(6, 4), fontsize=8, color="#444444")
              for k in range(n)]
    (ray,) = ax.plot([], [], "--", color=style.PALETTE["curve"], linewidth=1.0, zorder=2)
    (ups,) = ax.plot([], [], "^", color=style.PALETTE["good"], markersize=7, zorder=4)
    (downs,) = ax.plot([], [], "v", color=style.PALETTE["point"], markersize=7, zorder=4)
    (qmark,) = ax.plot([], [], "*", color="#111111", markersize=13, zorder=5)
    ax.set_xlim(-box, box)
    ax.set_ylim(-box, box)
    ax.legend(handles=[Patch(color=WINDING_COLOURS[k], label=f"w = {k}") for k in (-1, 1, 2, 3)]
              + [Patch(color=_DIFFER, label="rules differ")], fontsize=7, loc="lower left", frameon=True, ncol=5,
              handlelength=1.0, columnspacing=0.8)
    ax.set_title("winding numbers of the polygon (drag the vertices and the ★)", fontsize=9)

    controls = {"mode": dropdown("colour", _MODES.items(), "winding"),
                "qx": float_slider("qx", float(query[0]), -box, box, 0.05),
                "qy": float_slider("qy", float(query[1]), -box, box, 0.05)}
    for k, (x, y) in enumerate(poly):
        controls[f"x{k}"] = float_slider(f"x{k}", float(x), -box, box, 0.05)
        controls[f"y{k}"] = float_slider(f"y{k}", float(y), -box, box, 0.05)

    maps: dict = {}   # the polygon's pixel maps (moving the query point Q does not change them)

    def update(mode, qx, qy, **coords):
        pts = np.array([[coords[f"x{k}"], coords[f"y{k}"]] for k in range(n)], dtype=float)
        q = np.array([qx, qy], dtype=float)
        closed = np.vstack([pts, pts[:1]])
        outline.set_data(closed[:, 0], closed[:, 1])
        vertices.set_data(pts[:, 0], pts[:, 1])
        for k, label in enumerate(labels):
            label.xy = tuple(pts[k])
        qmark.set_data([qx], [qy])
        ray.set_data([qx, box], [qy, qy])
        try:
            key = pts.tobytes()
            if maps.get("key") != key:
                maps.clear()
                maps["wind"] = vg.winding_number(pts, pixels)
                maps["odd"] = vg.ray_casting_inside(pts, pixels)
                maps["key"] = key
                for a in (maps["wind"], maps["odd"]):
                    a.setflags(write=False)     # returned as "map": shared while Q moves
            wind, odd = maps["wind"], maps["odd"]
            crossings, signs = vg.ray_crossings(pts, q)
            w_q = int(vg.winding_number(pts, q))
            odd_q = bool(vg.ray_casting_inside(pts, q))
        except ValueError as exc:   # fewer than three distinct vertices
            ups.set_data([], [])
            downs.set_data([], [])
            image.set_data(blank)
            return {"polygon": pts, "status": f"no polygon to test: {exc}"}
        if mode == "winding":
            rgba = table[np.clip(wind, -3, 3) + 3]
        elif mode == "even_odd":
            rgba = np.where(odd[..., None], inside_rgba, table[3])
        else:
            rgba = np.where(((wind != 0) != odd)[..., None], differ_rgba, table[3])
        image.set_data(rgba)
        up = crossings[signs > 0]
        down = crossings[signs < 0]
        ups.set_data(up[:, 0], up[:, 1])
        downs.set_data(down[:, 0], down[:, 1])
        nonzero = "inside" if w_q != 0 else "outside"
        even_odd = "inside" if odd_q else "outside"
        status = (f"Q = ({qx:.2f}, {qy:.2f}): winding number {w_q} (nonzero rule: {nonzero}); the ray crosses "
                  f"{len(signs)} edge{'s' if len(signs) != 1 else ''} ({int((signs > 0).sum())} up, "
                  f"{int((signs < 0).sum())} down), even-odd rule: {even_odd}")
        if nonzero != even_odd:
            status += " — the two rules disagree here"
        return {"polygon": pts, "query": q, "winding": w_q, "even_odd": odd_q, "crossings": crossings,
                "signs": signs, "map": wind, "status": status}

    from goldman_lib.widgets.drag import drag_sliders

    arrange = ([controls["mode"], widgets.HTML("<small>query point ★</small>"), controls["qx"], controls["qy"],
                widgets.HTML("<small>polygon vertices</small>")]
               + [controls[f"{a}{k}"] for k in range(n) for a in "xy"])
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="inside or outside? winding number and ray casting", arrange=arrange, side=True)
    view.ax = ax
    drag_sliders(view, ax, [(f"x{k}", f"y{k}") for k in range(n)] + [("qx", "qy")])
    style.pin_layout(fig)       # fixed limits: the title need not be placed again at each redraw
    style.freeze_axes_decorations(ax, ax.title)   # axes, legend and title: rendered once, pasted at each redraw
    return view


# -- §11.6 slerp ----------------------------------------------------------------------------------------
def _unit(angle_degrees: float) -> np.ndarray:
    """The unit vector at an angle from the x axis (drawing only)."""
    a = np.radians(angle_degrees)
    return np.array([np.cos(a), np.sin(a)])


def slerp_view(a0: float = 20.0, a1: float = 150.0, t: float = 0.3, steps: int = 10) -> InteractiveView:
    """Spherical linear interpolation on the unit circle (Goldman §11.6): the unit vectors v0 and v1
    at angles ``a0``, ``a1`` (degrees), ``slerp(v0, v1, t)`` and the normalised linear interpolation
    ``nlerp`` beside it.  Dots mark both at t = 0, 1/steps, ..., 1: slerp's are evenly spaced along the
    arc, nlerp's bunch towards the middle.  The status gives the angles from v0 of both vectors
    (slerp's is exactly t·θ).  ``update(a0, a1, t)``.
    """
    steps = as_int(steps, "steps", minimum=2, maximum=100)
    fig, ax = style.new_axes()
    ang = np.radians(np.linspace(0, 360, 181))
    ax.plot(np.cos(ang), np.sin(ang), color="#dddddd", linewidth=1, zorder=0)
    (arc,) = ax.plot([], [], color=style.PALETTE["curve"], linewidth=2.2, label="slerp: the great arc")
    (chord,) = ax.plot([], [], ":", color=style.PALETTE["control"], linewidth=1.2, label="lerp: the chord")
    (s_dots,) = ax.plot([], [], "o", color=style.PALETTE["curve"], markersize=5, label=f"slerp at t = k/{steps}")
    (n_dots,) = ax.plot([], [], "o", mfc="none", color=style.PALETTE["accent"], markersize=9, mew=1.5,
                        label=f"nlerp at t = k/{steps}")
    arrows = ax.quiver(np.zeros(4), np.zeros(4), np.zeros(4), np.zeros(4), angles="xy", scale_units="xy", scale=1,
                       color=["#1f77b4", "#d62728", style.PALETTE["curve"], style.PALETTE["accent"]], width=0.008,
                       zorder=4)
    (lerp_pt,) = ax.plot([], [], "s", color=style.PALETTE["control"], markersize=5, zorder=5)
    ax.set_xlim(-1.35, 1.35)
    ax.set_ylim(-1.35, 1.35)
    ax.legend(fontsize=7, loc="lower left", frameon=False)
    ax.set_title("v0 (blue), v1 (red), slerp(t) and nlerp(t)", fontsize=9)
    ts = np.linspace(0, 1, steps + 1)
    fine = np.linspace(0, 1, 121)
    controls = {"a0": float_slider("a0 (°)", a0, 0, 360, 1, readout=".0f"),
                "a1": float_slider("a1 (°)", a1, 0, 360, 1, readout=".0f"),
                "t": float_slider("t", t, 0, 1, 0.01)}

    def update(a0, a1, t):
        v0, v1 = _unit(a0), _unit(a1)
        chord.set_data([v0[0], v1[0]], [v0[1], v1[1]])
        try:
            path = vg.slerp(v0, v1, fine)
            s = vg.slerp(v0, v1, t)
            n_ = vg.nlerp(v0, v1, t)
            sd = vg.slerp(v0, v1, ts)
            nd = vg.nlerp(v0, v1, ts)
        except ValueError:
            arc.set_data([], [])
            s_dots.set_data([], [])
            n_dots.set_data([], [])
            lerp_pt.set_data([], [])
            arrows.set_UVC([v0[0], v1[0], 0, 0], [v0[1], v1[1], 0, 0])
            return {"v0": v0, "v1": v1, "status": "v0 and v1 point in opposite directions: every half circle "
                                                  "joins them, so slerp has no single arc to follow"}
        lerp = np.asarray(vectors.affine_combination(np.array([v0, v1]), [1 - t, t]))
        arc.set_data(path[:, 0], path[:, 1])
        s_dots.set_data(sd[:, 0], sd[:, 1])
        n_dots.set_data(nd[:, 0], nd[:, 1])
        lerp_pt.set_data([lerp[0]], [lerp[1]])
        arrows.set_UVC([v0[0], v1[0], s[0], n_[0]], [v0[1], v1[1], s[1], n_[1]])
        theta = float(vectors.angle_between(v0, v1))
        if theta < 1e-9:
            status = "v0 = v1: θ = 0 and every interpolation stays at v0"
            s_angle = n_angle = 0.0
        else:
            s_angle = float(vectors.angle_between(v0, s)) if t > 0 else 0.0
            n_angle = float(vectors.angle_between(v0, n_)) if t > 0 else 0.0
            status = (f"θ = {theta:.1f}°; t = {t:.2f}: slerp is {s_angle:.1f}° from v0 (t·θ = {t * theta:.1f}°), "
                      f"nlerp is {n_angle:.1f}° from v0; the lerp point has length "
                      f"{float(vectors.length(lerp)):.3f}")
        return {"v0": v0, "v1": v1, "slerp": s, "nlerp": n_, "lerp": lerp, "slerp_dots": sd, "nlerp_dots": nd,
                "slerp_angle": s_angle, "nlerp_angle": n_angle, "status": status}

    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="slerp: constant speed along the arc", side=True)

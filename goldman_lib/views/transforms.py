"""Three.js views of the transformations of Goldman chapters 12 and 13: a solid letter F (no mirror
symmetry, so a rotation and a mirror image look different) moved by the library's formulas
(:mod:`goldman_lib.transforms`) -- rotation about an axis through a point, mirror in a plane,
uniform and nonuniform scaling, orthogonal and perspective projection -- and, for chapter 13, by
the 4x4 matrices, composed in order and shown as tables.

Every point a view draws comes from :mod:`goldman_lib.transforms`; this module only draws.  A
slider position where the transformation is not defined (a zero axis or normal, an eye on the
plane of projection) shows the reason in the status line and draws the F unmoved.

>>> V, T, E = letter_f()
>>> V.shape, T.shape, E.shape
((24, 3), (36, 3), (36, 2))
>>> view = axis_rotation_view()
>>> sorted(view.update(**view.values()))
['axis', 'image', 'path', 'status']
>>> view.update(**{**view.values(), "ax": 0.0, "ay": 0.0, "az": 0.0})["status"].startswith("no rotation")
True
"""

from __future__ import annotations

import html

import numpy as np

from goldman_lib import transforms, vector_geometry, vectors
from goldman_lib.widgets.interactive import InteractiveView, dropdown, float_slider
from goldman_lib.widgets.vectors3d import COLOURS, VectorScene

__all__ = ["letter_f", "axis_rotation_view", "mirror_view", "scaling_view", "projection_view", "matrix_html", "MAPS",
           "composition_view", "perspective_matrix_view"]

_GREY = "#9a9a9a"
_LINE = "#555555"
_SIGHT = "#e6a23c"


def _box(x0, x1, y0, y1, z0, z1):
    V = np.array([[x, y, z] for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)], dtype=float)
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris = [t for a, b, c, d in faces for t in ((a, b, c), (a, c, d))]
    edges = [(0, 1), (2, 3), (4, 5), (6, 7), (0, 2), (1, 3), (4, 6), (5, 7), (0, 4), (1, 5), (2, 6), (3, 7)]
    return V, np.array(tris), np.array(edges)


def letter_f():
    """The solid letter F of these views: three boxes (the stem, the top arm, the middle arm) in the
    x-z plane, 0.2 thick in y.  Returns ``(vertices (24, 3), triangles (36, 3), edges (36, 2))``."""
    boxes = [_box(0.0, 0.25, 0.0, 0.2, 0.0, 1.2), _box(0.25, 0.8, 0.0, 0.2, 0.95, 1.2),
             _box(0.25, 0.6, 0.0, 0.2, 0.5, 0.72)]
    V = np.concatenate([b[0] for b in boxes])
    T = np.concatenate([b[1] + 8 * k for k, b in enumerate(boxes)])
    E = np.concatenate([b[2] + 8 * k for k, b in enumerate(boxes)])
    return V, T, E


F_VERTICES, F_TRIANGLES, F_EDGES = letter_f()
#: The vertex of the F whose path the rotation view traces: the outer top corner of the top arm.
TIP = 13
#: Vertices whose lines of sight the projection views draw: the ten corners of the F's front face
#: (y = 0), in order round its outline.
FRONT = np.array([0, 1, 16, 17, 21, 20, 8, 9, 13, 4])


def _scene(target=(0.4, 0.0, 0.6), camera=(3.4, -4.6, 2.6)):
    scene = VectorScene(width=440, height=340, camera_position=camera, target=target, axes=0.8)
    scene.add_mesh("original", F_VERTICES, F_TRIANGLES, color=_GREY, opacity=0.3)
    scene.add_segments("original:edges", F_VERTICES, F_EDGES, color="#b0b0b0", width=0.8)
    return scene


def _add_image(scene):
    scene.add_mesh("image", F_VERTICES, F_TRIANGLES, color=COLOURS["image"], opacity=0.85)
    scene.add_segments("image:edges", F_VERTICES, F_EDGES, color="#8c2d6a", width=1.0)


def _set_image(scene, image):
    scene.set_mesh("image", image)
    scene.set_segments("image:edges", image)


def _v(x) -> str:
    return "(" + ", ".join(f"{float(c):.2f}" + "" for c in np.asarray(x, float).ravel()) + ")"


def _sliders(prefix, value, low, high, step=0.05):
    return {f"{prefix}{a}": float_slider(f"{prefix}{a}", float(v), low, high, step, width="250px", label_width="34px")
            for a, v in zip("xyz", value)}


def _legend(*items):
    import ipywidgets as widgets

    return widgets.HTML(" &nbsp;".join(f"<span style='color:{c}'>&#9632; {html.escape(t)}</span>" for t, c in items))


def _unit_for_drawing(v):
    """A unit vector along ``v`` for drawing a line or an arrow (z if ``v`` is zero)."""
    n = float(vectors.length(v))
    return np.asarray(v, float) / n if n > 1e-12 else np.array([0.0, 0.0, 1.0])


# -- §12.3 rotation about an axis through a point ------------------------------------------------------

def axis_rotation_view(axis=(0.3, 0.2, 1.0), angle=75.0, point=(1.0, 0.3, 0.0)) -> InteractiveView:
    """The F rotated by ``angle`` degrees about the line through ``point`` along ``axis``
    (Goldman §12.3, Rodrigues' formula, :func:`goldman_lib.transforms.rotate`).  The axis is drawn
    as a line, and the tip of the F's top arm leaves the arc it travels along.  The status line
    checks what a rotation keeps: the tip's distance to the axis and the lengths of the edges.
    """
    scene = _scene()
    _add_image(scene)
    scene.add_segments("axis", np.zeros((2, 3)), [[0, 1]], color=COLOURS["cross"], width=2.2)
    scene.add_points("point", np.zeros((1, 3)), color=COLOURS["point"], size=0.09)
    n_arc = 25
    scene.add_segments("path", np.zeros((n_arc, 3)), [[k, k + 1] for k in range(n_arc - 1)], color=COLOURS["w"],
                       width=1.8)
    controls = {**_sliders("a", axis, -1.0, 1.0), "angle": float_slider("angle", angle, -180, 180, 5, width="250px",
                                                                         label_width="34px", readout=".0f"),
                **_sliders("p", point, -1.5, 1.5)}

    def update(ax, ay, az, angle, px, py, pz):
        w, Q = np.array([ax, ay, az]), np.array([px, py, pz])
        scene.set_points("point", Q[None])
        try:
            image = transforms.rotate(F_VERTICES, w, angle, point=Q)
        except ValueError as exc:
            image, ends = F_VERTICES, np.stack([Q, Q])
            path = np.repeat(F_VERTICES[[TIP]], n_arc, axis=0)
            status = (f"no rotation: the axis {_v(w)} is the zero vector ({exc}); move an axis slider. "
                      f"The F is drawn unmoved.")
        else:
            u = _unit_for_drawing(w)
            ends = np.stack([Q - 1.6 * u, Q + 1.6 * u])
            path = np.concatenate([transforms.rotate(F_VERTICES[[TIP]], w, t, point=Q)
                                   for t in np.linspace(0.0, angle, n_arc)])
            r0 = float(vector_geometry.point_line_distance(F_VERTICES[TIP], Q, w))
            r1 = float(vector_geometry.point_line_distance(image[TIP], Q, w))
            lengths = [vectors.length(V[F_EDGES[:, 1]] - V[F_EDGES[:, 0]]) for V in (F_VERTICES, image)]
            kept = float(np.abs(lengths[0] - lengths[1]).max())
            status = (f"rotation by {angle:.0f}° about the line through {_v(Q)} along {_v(w)}: the tip stays "
                      f"{r1:.3f} from the axis (it was {r0:.3f}); all 36 edge lengths kept "
                      f"{'to < 1e-12' if kept < 1e-12 else f'only to {kept:.1e}'}.")
        _set_image(scene, image)
        scene.set_segments("axis", ends)
        scene.set_segments("path", path)
        return {"image": image, "axis": ends, "path": path, "status": status}

    legend = _legend(("F", _GREY), ("rotated F", COLOURS["image"]), ("axis", COLOURS["cross"]),
                     ("path of the tip", COLOURS["w"]))
    return InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="rotation about an axis through a point (§12.3)", side=True)


# -- §12.3 mirror ------------------------------------------------------------------------------------------

#: Vertices of the F joined to their mirror images in the mirror view.
_CONNECT = np.array([5, 13, 15, 21])


def mirror_view(point=(1.1, 0.0, 0.6), normal=(1.0, 0.2, 0.3)) -> InteractiveView:
    """The F and its mirror image in the plane through ``point`` with ``normal`` (Goldman §12.3,
    :func:`goldman_lib.transforms.reflect`).  The plane is drawn with its normal; four vertices are
    joined to their images, and the status line checks that the plane bisects each join and that
    the mirror's matrix has determinant -1 (the F reads backwards).
    """
    scene = _scene(target=(1.0, 0.0, 0.6), camera=(4.0, -5.2, 2.8))
    scene.add_plane("plane", point, normal, size=3.0, color=COLOURS["plane"], opacity=0.35)
    _add_image(scene)
    scene.add_arrows("normal", np.array([point]), [[0.0, 0.0, 1.0]], color=COLOURS["normal"])
    k = len(_CONNECT)
    scene.add_segments("joins", np.zeros((2 * k, 3)), [[2 * i, 2 * i + 1] for i in range(k)], color=_LINE, width=1.0)
    controls = {**_sliders("q", point, -1.5, 1.5), **_sliders("n", normal, -1.0, 1.0)}

    def update(qx, qy, qz, nx, ny, nz):
        Q, N = np.array([qx, qy, qz]), np.array([nx, ny, nz])
        u = _unit_for_drawing(N)
        scene.set_plane("plane", Q, u, size=3.0)
        scene.set_arrows("normal", Q[None], 0.6 * u[None])
        try:
            image = transforms.reflect(F_VERTICES, Q, N)
        except ValueError as exc:
            image = F_VERTICES
            status = f"no mirror: the normal {_v(N)} is the zero vector ({exc}); move a normal slider."
        else:
            mid = (F_VERTICES + image) / 2
            off = float(np.max(vector_geometry.point_plane_distance(mid, Q, N)))
            det = float(np.linalg.det(transforms.mirror(Q, N)[:3, :3]))
            status = (f"mirror in the plane through {_v(Q)} with normal {_v(N)}: every join's midpoint lies on the "
                      f"plane ({'< 1e-12' if off < 1e-12 else f'{off:.1e}'} away); det = {det:.0f}, so the "
                      f"image is the F reversed.")
        joins = np.stack([F_VERTICES[_CONNECT], image[_CONNECT]], axis=1).reshape(-1, 3)
        _set_image(scene, image)
        scene.set_segments("joins", joins)
        return {"image": image, "joins": joins, "status": status}

    legend = _legend(("F", _GREY), ("mirror image", COLOURS["image"]), ("normal", COLOURS["normal"]),
                     ("mirror plane", "#6baed6"))
    return InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="mirror in a plane (§12.3)", side=True)


# -- §12.4 scaling -------------------------------------------------------------------------------------------

def scaling_view(s=1.6, kind="nonuniform", direction=(1.0, 0.0, 0.6), center=(0.0, 0.0, 0.0)) -> InteractiveView:
    """The F scaled by ``s`` about ``center``: uniformly (:func:`goldman_lib.transforms.scale`) or
    only along ``direction`` (:func:`goldman_lib.transforms.scale_along`) (Goldman §12.4).  The
    centre and the direction are drawn; the status line compares the volume of a tetrahedron of
    F vertices before and after (a factor s³ for uniform, s for nonuniform scaling).
    """
    import ipywidgets as widgets

    scene = _scene(target=(0.5, 0.0, 0.7), camera=(4.2, -5.6, 3.2))
    _add_image(scene)
    scene.add_points("center", np.array([center]), color=COLOURS["point"], size=0.1)
    scene.add_arrows("direction", np.array([center]), np.array([[0.0, 0.0, 1.0]]), color=COLOURS["w"])
    controls = {"s": float_slider("s", s, -1.5, 2.5, 0.05, width="250px", label_width="34px"),
                "kind": widgets.ToggleButtons(options=["uniform", "nonuniform"], value=kind,
                                              style={"button_width": "90px"}),
                **_sliders("d", direction, -1.0, 1.0), **_sliders("c", center, -1.0, 1.0)}
    tet = F_VERTICES[[0, 1, 2, 13]]

    def update(s, kind, dx, dy, dz, cx, cy, cz):
        d, C = np.array([dx, dy, dz]), np.array([cx, cy, cz])
        scene.set_points("center", C[None])
        u = _unit_for_drawing(d)
        scene.set_arrows("direction", C[None], (0.8 * u if kind == "nonuniform" else 1e-9 * u)[None])
        try:
            if kind == "uniform":
                image = transforms.scale(F_VERTICES, s, center=C)
            else:
                image = transforms.scale_along(F_VERTICES, s, d, center=C)
        except ValueError as exc:
            image = F_VERTICES
            status = f"no scaling: the direction {_v(d)} is the zero vector ({exc}); move a direction slider."
        else:
            v0 = float(vector_geometry.tetrahedron_volume(*tet))
            v1 = float(vector_geometry.tetrahedron_volume(*image[[0, 1, 2, 13]]))
            what = (f"uniform scaling by {s:.2f} about {_v(C)}: lengths times |s|"
                    if kind == "uniform" else
                    f"scaling by {s:.2f} along {_v(d)} about {_v(C)}: lengths across the direction kept")
            flat = " (s = 0 flattens the F" + (" to the centre)" if kind == "uniform" else
                                                " onto the plane through the centre across the direction)")
            status = (f"{what}; a tetrahedron of F vertices has volume {v0:.4f} before, {v1:.4f} after "
                      f"(ratio {v1 / v0:.3f})" + (flat if abs(s) < 1e-12 else "") + ".")
        _set_image(scene, image)
        return {"image": image, "status": status}

    legend = _legend(("F", _GREY), ("scaled F", COLOURS["image"]), ("centre", COLOURS["point"]),
                     ("direction (nonuniform)", COLOURS["w"]))
    return InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="uniform and nonuniform scaling (§12.4)", side=True,
                           acts={k: {"kind": ["nonuniform"]} for k in ("dx", "dy", "dz")})   # the direction: nonuniform only


# -- §12.5 projections -----------------------------------------------------------------------------------------

def _screen_normal(tilt):
    """The normal of the projection plane: the y axis turned by ``tilt`` degrees about the z axis."""
    return transforms.rotate(np.array([[0.0, 1.0, 0.0]]), [0, 0, 1], -tilt)[0]


def _projection_scene():
    scene = _scene(target=(0.4, -1.2, 0.6), camera=(6.0, -6.5, 3.6))
    scene.add_plane("plane", [0, -1, 0.6], [0, 1, 0], size=3.2, color=COLOURS["plane"], opacity=0.35)
    scene.add_segments("sight", np.zeros((4 * len(FRONT), 3)), [[2 * i, 2 * i + 1] for i in range(2 * len(FRONT))],
                       color=_SIGHT, width=0.8)
    scene.add_mesh("image", F_VERTICES, F_TRIANGLES, color=COLOURS["image"], opacity=0.5)
    scene.add_segments("image:edges", F_VERTICES, F_EDGES, color="#8c2d6a", width=1.2)
    scene.add_points("eye", np.zeros((1, 3)), color=COLOURS["point"], size=0.12)
    return scene


def _project(kind, E, Q, N):
    """(image, sight segments, status) of the F under the projection, or raises ValueError."""
    P = F_VERTICES[FRONT]
    if kind == "orthogonal":
        image = transforms.project_orthogonal(F_VERTICES, Q, N)
        img = image[FRONT]
        sight = np.concatenate([np.stack([P, img], 1), np.stack([img, img], 1)]).reshape(-1, 3)
        off = float(np.max(vector_geometry.point_plane_distance(image, Q, N)))
        status = (f"orthogonal projection onto the plane through {_v(Q)} with normal {_v(N)}: the lines of "
                  f"projection are parallel to the normal (the eye plays no part); images on the plane "
                  f"{'to < 1e-9' if off < 1e-9 else f'only to {off:.1e}'}.")
        return image, sight, status
    image = transforms.project_perspective(F_VERTICES, E, Q, N)
    img = image[FRONT]
    sight = np.concatenate([np.stack([np.broadcast_to(E, P.shape), P], 1),
                            np.stack([np.broadcast_to(E, P.shape), img], 1)]).reshape(-1, 3)
    off = float(np.max(vector_geometry.point_plane_distance(image, Q, N)))
    side_eye = vectors.dot(Q - E, N)
    behind = int(np.sum(vectors.dot(F_VERTICES - E, N) * side_eye < 0))
    status = (f"perspective from the eye {_v(E)} onto the plane through {_v(Q)} with normal {_v(N)}: each image "
              f"is where the line of sight meets the plane (on the plane "
              f"{'to < 1e-9' if off < 1e-9 else f'only to {off:.1e}'})"
              + (f"; {behind} vertices lie behind the eye, and their images come through it, reversed" if behind else "")
              + ".")
    return image, sight, status


def projection_view(kind="perspective", eye=(0.6, -3.6, 1.6), plane_y=-1.2, tilt=0.0) -> InteractiveView:
    """The F projected onto a plane (Goldman §12.5): orthogonally
    (:func:`goldman_lib.transforms.project_orthogonal`) or in perspective from an eye
    (:func:`goldman_lib.transforms.project_perspective`).  The plane passes through (0, plane_y, 0.6)
    with its normal the y axis turned by ``tilt`` degrees about z.  Lines of sight run from the
    eye to the front corners of the F and to their images; for the orthogonal projection the lines of
    projection run from each corner to its image.  An eye on the plane or a vertex on the plane
    through the eye parallel to the screen (an image at infinity) is reported in the status line.
    """
    import ipywidgets as widgets

    scene = _projection_scene()
    controls = {"kind": widgets.ToggleButtons(options=["perspective", "orthogonal"], value=kind,
                                              style={"button_width": "90px"}),
                **_sliders("e", eye, -3.0, 3.0), "plane_y": float_slider("plane y", plane_y, -2.5, 0.5, 0.05,
                                                                         width="250px", label_width="50px"),
                "tilt": float_slider("tilt", tilt, -60, 60, 5, width="250px", label_width="34px", readout=".0f")}
    controls["ey"].min, controls["ey"].value = -6.0, eye[1]

    def update(kind, ex, ey, ez, plane_y, tilt):
        E, Q, N = np.array([ex, ey, ez]), np.array([0.0, plane_y, 0.6]), _screen_normal(tilt)
        scene.set_plane("plane", Q, N, size=3.2)
        scene.set_points("eye", E[None])
        try:
            image, sight, status = _project(kind, E, Q, N)
        except ValueError as exc:
            image = F_VERTICES
            sight = np.repeat(F_VERTICES[FRONT], 4, axis=0)
            status = f"no {kind} image here: {exc}. The F is drawn unprojected; move the eye or the plane."
        _set_image(scene, image)
        scene.set_segments("sight", sight)
        return {"image": image, "sight": sight, "status": status}

    legend = _legend(("F", _GREY), ("image on the plane", COLOURS["image"]), ("lines of sight", _SIGHT),
                     ("eye", COLOURS["point"]))
    return InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="orthogonal and perspective projection (§12.5)", side=True,
                           acts={k: {"kind": ["perspective"]} for k in ("ex", "ey", "ez")})   # the eye: perspective only


# -- chapter 13: the matrices ------------------------------------------------------------------------------

def matrix_html(M, title: str = "", digits: int = 3, highlight_row: int | None = None,
                highlight_col: int | None = None) -> str:
    """A 4x4 (or any) matrix as a small HTML table, rounded to ``digits`` decimals, with an optional
    caption and one row or column shaded (the translation row, the homogeneous column)."""
    A = np.round(np.asarray(M, dtype=float), digits) + 0.0
    rows = []
    for i, row in enumerate(A):
        cells = []
        for j, x in enumerate(row):
            shade = "background:#fdebd0;" if (i == highlight_row or j == highlight_col) else ""
            cells.append(f"<td style='padding:1px 6px;text-align:right;{shade}'>{x:g}</td>")
        rows.append("<tr>" + "".join(cells) + "</tr>")
    cap = f"<caption style='caption-side:top;font-size:90%'>{html.escape(title)}</caption>" if title else ""
    return ("<table style='border-collapse:collapse;border-left:1px solid #555;border-right:1px solid #555;"
            "font-family:monospace;font-size:85%;margin:2px 8px'>" + cap + "".join(rows) + "</table>")


#: The maps of the composition view: name -> (slider the map reads, the library's matrix for a value).
MAPS = {
    "rotate about the vertical line through (1, 0, 0)": ("angle", lambda a: transforms.rotation([0, 0, 1], a, [1, 0, 0])),
    "rotate about the x axis": ("angle", lambda a: transforms.rotation([1, 0, 0], a)),
    "mirror in the plane x = m": ("m", lambda m: transforms.mirror([m, 0, 0], [1, 0, 0])),
    "scale by s along z about the origin": ("s", lambda s: transforms.nonuniform_scaling(s, [0, 0, 1])),
    "translate by (t, 0, 0)": ("t", lambda t: transforms.translation([t, 0, 0])),
}


def composition_view(first="translate by (t, 0, 0)", second="rotate about the vertical line through (1, 0, 0)",
                     angle=90.0, m=1.0, s=1.5, t=1.0) -> InteractiveView:
    """Two transformations composed in order (our section of chapter 13; the book has none): the F moved by ``first`` and then by
    ``second``, whose matrix in the row convention is ``A @ B`` (:func:`goldman_lib.transforms.compose`),
    beside the F moved in the other order ``B @ A`` (faded).  The three matrices A, B and A B are shown
    as tables, the translation row shaded.  Each map reads its own slider: the angle for the
    rotations, m for the mirror, s for the scaling, t for the translation.
    """
    import ipywidgets as widgets

    scene = _scene(target=(0.6, 0.0, 0.4), camera=(4.6, -6.0, 3.4))
    scene.add_mesh("other", F_VERTICES, F_TRIANGLES, color=COLOURS["w"], opacity=0.25)
    scene.add_segments("other:edges", F_VERTICES, F_EDGES, color=COLOURS["w"], width=0.6)
    _add_image(scene)
    names = list(MAPS)
    controls = {"first": dropdown("first", names, first, width="330px", label_width="50px"),
                "second": dropdown("then", names, second, width="330px", label_width="50px"),
                "angle": float_slider("angle", angle, -180, 180, 5, width="250px", label_width="40px", readout=".0f"),
                "m": float_slider("m", m, -1.0, 2.0, 0.05, width="250px", label_width="40px"),
                "s": float_slider("s", s, -1.5, 2.5, 0.05, width="250px", label_width="40px"),
                "t": float_slider("t", t, -1.5, 1.5, 0.05, width="250px", label_width="40px")}
    tables = widgets.HTML()

    def update(first, second, angle, m, s, t):
        values = {"angle": angle, "m": m, "s": s, "t": t}
        A = MAPS[first][1](values[MAPS[first][0]])
        B = MAPS[second][1](values[MAPS[second][0]])
        AB, BA = transforms.compose(A, B), transforms.compose(B, A)
        image, other = transforms.apply(F_VERTICES, AB), transforms.apply(F_VERTICES, BA)
        _set_image(scene, image)
        scene.set_mesh("other", other)
        scene.set_segments("other:edges", other)
        tables.value = ("<div style='display:flex;flex-wrap:wrap;align-items:center'>"
                        + matrix_html(A, "A (first)", highlight_row=3) + "<b>·</b>"
                        + matrix_html(B, "B (then)", highlight_row=3) + "<b>=</b>"
                        + matrix_html(AB, "A B", highlight_row=3) + "</div>")
        gap = float(np.max(vectors.length(image - other)))
        order = ("the two orders agree here (these maps commute)" if gap < 1e-9 else
                 f"the other order B A (faded) puts some corner {gap:.2f} away")
        status = f"first {first}, then {second}: [P 1] (A B) = ([P 1] A) B; {order}."
        return {"image": image, "other": other, "matrix": AB, "status": status}

    legend = _legend(("F", _GREY), ("first A, then B", COLOURS["image"]), ("first B, then A", COLOURS["w"]))
    return InteractiveView(controls=controls, views=[scene.widget, legend, tables], update=update,
                           static=scene.to_png, title="composing transformations: first A, then B is A B (ch. 13)",
                           side=True,
                           # a parameter acts while one of the two chosen maps uses it
                           acts={name: (lambda v, name=name: name in (MAPS.get(v["first"], ("",))[0], MAPS.get(v["second"], ("",))[0]))
                                 for name in ("angle", "m", "s", "t")})


def perspective_matrix_view(eye=(0.6, -3.6, 1.6), plane_y=-1.2, tilt=0.0, corner=8) -> InteractiveView:
    """The perspective matrix of Goldman §13.6.2 (:func:`goldman_lib.transforms.perspective`) at work:
    the F projected by ``[P 1] M`` and the homogeneous divide (:func:`goldman_lib.transforms.apply`),
    the matrix shown as a table (its last column, the normal and -E·N, shaded), and for one corner
    of the F its homogeneous coordinates before the divide and its image after it, with its line of
    sight.  The status line compares the matrix's images with the formula of §12.5.
    """
    import ipywidgets as widgets

    scene = _projection_scene()
    scene.add_points("corner", np.zeros((2, 3)), color=COLOURS["v"], size=0.12)
    controls = {**_sliders("e", eye, -3.0, 3.0),
                "plane_y": float_slider("plane y", plane_y, -2.5, 0.5, 0.05, width="250px", label_width="50px"),
                "tilt": float_slider("tilt", tilt, -60, 60, 5, width="250px", label_width="34px", readout=".0f"),
                "corner": widgets.IntSlider(value=corner, min=0, max=len(FRONT) - 1, description="corner",
                                            style={"description_width": "50px"}, layout=widgets.Layout(width="250px"))}
    controls["ey"].min, controls["ey"].value = -6.0, eye[1]
    table = widgets.HTML()

    def update(ex, ey, ez, plane_y, tilt, corner):
        E, Q, N = np.array([ex, ey, ez]), np.array([0.0, plane_y, 0.6]), _screen_normal(tilt)
        scene.set_plane("plane", Q, N, size=3.2)
        scene.set_points("eye", E[None])
        P = F_VERTICES[FRONT[corner]]
        try:
            M = transforms.perspective(E, Q, N)
            image = transforms.apply(F_VERTICES, M)
        except ValueError as exc:
            image = F_VERTICES
            sight = np.repeat(F_VERTICES[FRONT], 4, axis=0)
            marks = np.stack([P, P])
            table.value = ""
            status = f"no perspective image here: {exc}. The F is drawn unprojected; move the eye or the plane."
        else:
            h = transforms.homogeneous(P[None], M)[0]
            img = image[FRONT]
            Pf = F_VERTICES[FRONT]
            sight = np.concatenate([np.stack([np.broadcast_to(E, Pf.shape), Pf], 1),
                                    np.stack([np.broadcast_to(E, Pf.shape), img], 1)]).reshape(-1, 3)
            marks = np.stack([P, image[FRONT[corner]]])
            formula = transforms.project_perspective(F_VERTICES, E, Q, N)
            gap = float(np.max(vectors.length(image - formula)))
            table.value = matrix_html(M, "the perspective matrix M (row convention)", highlight_col=3)
            status = (f"corner {corner}: [P 1] M = ({', '.join(f'{x:.3f}' for x in h)}); divided by w = {h[3]:.3f} "
                      f"it is {_v(image[FRONT[corner]])}. All 24 corners agree with the formula of §12.5 "
                      f"{'to < 1e-9' if gap < 1e-9 else f'only to {gap:.1e}'}.")
        _set_image(scene, image)
        scene.set_segments("sight", sight)
        scene.set_points("corner", marks)
        return {"image": image, "sight": sight, "corner": marks, "status": status}

    legend = _legend(("F", _GREY), ("image: [P 1] M, divided by w", COLOURS["image"]), ("the chosen corner", COLOURS["v"]),
                     ("lines of sight", _SIGHT))
    return InteractiveView(controls=controls, views=[scene.widget, legend, table], update=update,
                           static=scene.to_png, title="the perspective matrix and the homogeneous divide (§13.6.2)",
                           side=True)

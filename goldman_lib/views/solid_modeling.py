"""The views of chapter 20 (Goldman, solid modeling): a CSG tree picker shown as a ray-traced image
beside the ray-classification intervals of one ray (§20.2), with a render button for a full-size
picture of the tree (issue 18 §4), a B-rep validity readout (§20.3) and an octree depth slider with
the octree's cells in three.js (§20.4).

Every number a view shows comes from :mod:`goldman_lib.solid_modeling`; this module only draws.

>>> view = brep_view("cube with a flipped face")
>>> view.last_result["valid"], view.last_result["counts"]["E"]
(False, 12)
"""

from __future__ import annotations

import numpy as np
from matplotlib import ticker

from goldman_lib import lighting
from goldman_lib.camera import Camera
from goldman_lib import solid_modeling as sm
from goldman_lib.lighting import Material
from goldman_lib.simple_surfaces import Cylinder, Plane, Sphere, Torus
from goldman_lib.validation import as_float
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import InteractiveView, dropdown, figure_widget, float_slider, int_slider

__all__ = ["PRIMITIVES", "OPERATIONS", "BREPS", "SOLIDS", "csg_tree", "csg_view", "octree_view", "brep_view",
           "EXTENT", "FULL_SIZE", "csg_render", "csg_render_control"]

#: The primitives the CSG picker offers (they overlap around the origin).
PRIMITIVES = {
    "ball A (left)": Sphere([-0.45, 0.0, 0.0], 0.85, Material(colour=(0.85, 0.3, 0.25), specular=0.5)),
    "ball B (right)": Sphere([0.45, 0.0, 0.0], 0.85, Material(colour=(0.25, 0.45, 0.85), specular=0.5)),
    "ball C (small, front)": Sphere([0.0, -0.55, 0.45], 0.55, Material(colour=(0.3, 0.7, 0.35), specular=0.5)),
    "half-space z <= 0.2": Plane([0.0, 0.0, 0.2], [0.0, 0.0, 1.0], Material(colour=(0.85, 0.75, 0.35))),
    "cylinder D (drill along y)": Cylinder([0.0, -1.5, 0.1], [0.0, 1.0, 0.0], 0.35, 3.0,
                                           material=Material(colour=(0.6, 0.45, 0.75), specular=0.5)),
    "torus T (about z)": Torus([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 0.8, 0.25,
                               material=Material(colour=(0.9, 0.6, 0.3), specular=0.5)),
}
_LETTERS = {"ball A (left)": "A", "ball B (right)": "B", "ball C (small, front)": "C", "half-space z <= 0.2": "H",
            "cylinder D (drill along y)": "D", "torus T (about z)": "T"}
#: The operations of a CSG node.
OPERATIONS = {"union": sm.Union, "intersection": sm.Intersection, "difference": sm.Difference}
_SYMBOLS = {"union": "∪", "intersection": "∩", "difference": "−"}
#: The rendered window in the plane y = 0 (x from -W to W, z from -H to H), seen from the eye below.
EXTENT = (-1.6, 1.6, -1.2, 1.2)
_EYE = np.array([0.0, -6.0, 0.0])
_BACKGROUND = np.array([0.96, 0.96, 0.97])
_T_WINDOW = (-1.0, 7.0)
#: How many rendered CSG images the view keeps (one per tree formula; 84 x 112 RGB, 0.2 MB each).
_KEEP_IMAGES = 32


def csg_tree(first: str, op: str, second: str, op2: str = "none", third: str = "none"):
    """The CSG tree ``(first op second) op2 third`` from the names of :data:`PRIMITIVES` and
    :data:`OPERATIONS` (``op2 = "none"`` leaves the third out), and its formula in words.

    >>> tree, text = csg_tree("ball A (left)", "difference", "ball B (right)")
    >>> type(tree).__name__, text
    ('Difference', '(A − B)')
    """
    for value, name, options in ((first, "first", PRIMITIVES), (second, "second", PRIMITIVES),
                                 (op, "op", OPERATIONS)):
        if value not in options:
            raise ValueError(f"{name} must be one of {sorted(options)}; got {value!r}")
    letter = _LETTERS.get
    tree = OPERATIONS[op](PRIMITIVES[first], PRIMITIVES[second])
    text = f"({letter(first)} {_SYMBOLS[op]} {letter(second)})"
    if op2 != "none":
        if op2 not in OPERATIONS:
            raise ValueError(f"op2 must be 'none' or one of {sorted(OPERATIONS)}; got {op2!r}")
        if third not in PRIMITIVES:
            raise ValueError(f"third must be one of {sorted(PRIMITIVES)}; got {third!r}")
        tree = OPERATIONS[op2](tree, PRIMITIVES[third])
        text = f"({text} {_SYMBOLS[op2]} {letter(third)})"
    return tree, text


def _camera():
    """The pinhole camera at :data:`_EYE` looking along +y whose screen, carried to the plane y = 0,
    is exactly the window :data:`EXTENT` (so a point (x, 0, z) is drawn at (x, z) on the image)."""
    half_height = EXTENT[3] / -_EYE[1]
    return Camera(_EYE, (0.0, 0.0, 0.0), up=(0.0, 0.0, 1.0),
                  fov=2 * np.degrees(np.arctan(half_height)))


def csg_view(first: str = "ball A (left)", op: str = "difference", second: str = "ball B (right)",
             op2: str = "none", third: str = "ball C (small, front)", ray_z: float = 0.3,
             width: int = 112, height: int = 84) -> InteractiveView:
    """A CSG tree picker (Goldman §20.2): choose two primitives and an operation (and optionally a
    second operation with a third primitive); the solid is ray traced by ray classification (left,
    :func:`goldman_lib.ray_tracing.render`, depth 0: local light and shadows) and, on the right, the inside intervals of the horizontal ray ``(-3, 0, z) + t (1, 0, 0)`` (the
    dashed line on the image, height ``ray z``) are drawn for each primitive and for the result
    (:func:`goldman_lib.solid_modeling.intervals`).  A change of the tree re-renders the image (~50-100
    ms); the rendered images are kept per tree, so moving the ray (or coming back to a tree) only
    redraws.

    ``update(first, op, second, op2, third, ray_z)`` returns ``{"image" (h, w, 3), "intervals"
    {name: (M, 2)} (clipped to the drawn window of t, [-1, 7]), "tree", "status"}``.

    >>> r = csg_view().set_values(op="intersection", ray_z=0.0)
    >>> r["intervals"]["result"].tolist()
    [[2.6, 3.4]]
    """
    import matplotlib.pyplot as plt  # noqa: F401  (the figure is made through style)

    ray_z = as_float(ray_z, "ray_z")
    names = list(PRIMITIVES)
    ops = list(OPERATIONS)
    controls = {
        "first": dropdown("first", names, first, label_width="56px"),
        "op": dropdown("op", ops, op, label_width="56px"),
        "second": dropdown("second", names, second, label_width="56px"),
        "op2": dropdown("then", ["none"] + ops, op2, label_width="56px"),
        "third": dropdown("third", names, third, label_width="56px"),
        "ray_z": float_slider("ray z", ray_z, -1.1, 1.1, 0.05, label_width="56px"),
    }
    fig = style.new_figure(figsize=style.WIDE_FIGSIZE)
    ax_img = fig.add_subplot(1, 2, 1)
    ax_iv = fig.add_subplot(1, 2, 2)
    light = (lighting.Light((-1.5, -6.0, 3.0), intensity=1.0),)
    from goldman_lib import ray_tracing

    camera = _camera()
    im = ax_img.imshow(np.ones((height, width, 3)), extent=EXTENT, interpolation="nearest")
    ray_line = ax_img.axhline(ray_z, color="#222222", linestyle="--", linewidth=1.0)
    ax_img.set_xlabel("x"), ax_img.set_ylabel("z")
    # whole units on the image: its tick labels were a quarter of a redraw
    ax_img.xaxis.set_major_locator(ticker.MultipleLocator(1))
    ax_img.yaxis.set_major_locator(ticker.MultipleLocator(1))
    title = ax_img.set_title("", fontsize=10)
    rows = ["first", "second", "third", "result"]
    colours = {"first": "#d1495b", "second": "#3d5a80", "third": "#30a24b", "result": "#222222"}
    bars = {}
    for k, row in enumerate(rows):
        bars[row] = ax_iv.broken_barh([], (len(rows) - 1 - k - 0.3, 0.6), color=colours[row])
    ax_iv.set_yticks(range(len(rows)), rows[::-1])
    ax_iv.set_xlim(0.0, 6.0), ax_iv.set_ylim(-0.7, len(rows) - 0.3)
    ax_iv.set_xlabel("t along the ray (-3, 0, z) + t (1, 0, 0)")
    ax_iv.grid(axis="x", color="#e0e0e0")
    iv_title = ax_iv.set_title("", fontsize=10)
    fig.tight_layout()
    fig.subplots_adjust(top=0.9)

    rendered: dict = {}   # tree formula -> its image (the ray slider does not change it)

    def update(first, op, second, op2, third, ray_z):
        tree, text = csg_tree(first, op, second, op2, third)
        image = rendered.pop(text, None)
        if image is None:
            scene = ray_tracing.Scene([tree], light, ambient_light=0.3, background=_BACKGROUND)
            image = ray_tracing.render(scene, camera, width, height, depth=0)
            image.setflags(write=False)
            while len(rendered) >= _KEEP_IMAGES:
                rendered.pop(next(iter(rendered)))        # the least recently shown
        rendered[text] = image
        im.set_data(image)
        ray_line.set_ydata([ray_z, ray_z])
        o, d = [[-3.0, 0.0, ray_z]], [[1.0, 0.0, 0.0]]
        found, exact = {}, {}
        parts = {"first": PRIMITIVES[first], "second": PRIMITIVES[second], "result": tree}
        if op2 != "none":
            parts["third"] = PRIMITIVES[third]
        for row in rows:
            if row not in parts:
                bars[row].set_verts([])
                found[row] = np.zeros((0, 2))
                continue
            iv = sm.intervals(parts[row], o, d)[0]
            iv = iv[np.isfinite(iv[:, 0]) | (iv[:, 0] == -np.inf)]
            clipped = np.clip(iv, *_T_WINDOW)
            found[row] = clipped
            exact[row] = iv
            y = len(rows) - 1 - rows.index(row)
            bars[row].set_verts([[(a, y - 0.3), (a, y + 0.3), (b, y + 0.3), (b, y - 0.3)] for a, b in clipped])
        title.set_text(f"{text}: ray classification, one ray per pixel")
        words = "; ".join(f"[{a:.2f}, {b:.2f}]" for a, b in exact["result"]).replace("inf", "∞") or "empty"
        iv_title.set_text(f"inside intervals at z = {ray_z:.2f}")
        status = (f"{text}: the horizontal ray at z = {ray_z:.2f} is inside the result for t in {words} "
                  "(the operation applied to the primitives' interval lists)")
        return {"image": image, "intervals": found, "tree": text, "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§20.2 CSG by ray classification")
    style.pin_layout(fig)       # fixed limits: titles and labels need not be placed again at each redraw
    for ax in (ax_img, ax_iv):  # the axes (not the titles, which follow the sliders): rendered once, pasted
        style.freeze_axes_decorations(ax)
    return view


#: The full-size picture of the CSG view's render button: pixels, anti-aliasing (samples x samples
#: rays per pixel) and the depth of the reflected rays.
FULL_SIZE = dict(width=640, height=480, samples=2, depth=5)
#: The classification ray drawn in the full-size picture: a thin dark rod along it.
_ROD = dict(radius=0.012, material=Material(colour=(0.1, 0.1, 0.1), ambient=1.0, diffuse=0.0, specular=0.0))


def csg_render(progress=None, first: str = "ball A (left)", op: str = "difference", second: str = "ball B (right)",
               op2: str = "none", third: str = "ball C (small, front)", ray_z: float = 0.3, *,
               width: int = FULL_SIZE["width"], height: int = FULL_SIZE["height"],
               samples: int = FULL_SIZE["samples"], depth: int = FULL_SIZE["depth"]) -> np.ndarray:
    """The CSG view's solid as a full-size picture (Goldman §20.2, issue 18 §4): the tree of
    :func:`csg_tree` ray traced by ray classification (:func:`goldman_lib.ray_tracing.render`,
    ``samples x samples`` rays per pixel, reflections to ``depth``) with the view's camera, light and
    window, the classification ray ``(-3, 0, ray_z) + t (1, 0, 0)`` drawn as a thin dark rod.
    ``progress(done, total)`` is called as bands of rows are finished (a
    :class:`goldman_lib.widgets.render_control.ProgressBar`, say).  Returns ``(height, width, 3)``.

    >>> csg_render(None, op="intersection", width=8, height=6, samples=1, depth=1).shape
    (6, 8, 3)
    """
    from goldman_lib import ray_tracing

    ray_z = as_float(ray_z, "ray_z")
    tree, _ = csg_tree(first, op, second, op2, third)
    rod = Cylinder([-4.0, 0.0, ray_z], [1.0, 0.0, 0.0], _ROD["radius"], height=8.0, material=_ROD["material"])
    scene = ray_tracing.Scene([tree, rod], (lighting.Light((-1.5, -6.0, 3.0), intensity=1.0),), ambient_light=0.3,
                              background=_BACKGROUND)
    return ray_tracing.render(scene, _camera(), width, height, depth=depth, samples=samples, progress=progress)


def csg_render_control(view):
    """The render button under :func:`csg_view` (issue 18 §4): a
    :class:`goldman_lib.widgets.render_control.RenderControl` that renders the view's current tree with
    :func:`csg_render` at :data:`FULL_SIZE` (640 x 480, 2 x 2 anti-aliased, depth 5; several seconds)
    while a progress bar fills.  ``.render()`` does it from the keyboard."""
    from goldman_lib.widgets.render_control import RenderControl

    f = FULL_SIZE
    return RenderControl(csg_render, view=view,
                         label=f"Render {f['width']} x {f['height']}, {f['samples']} x {f['samples']} anti-aliased, "
                               f"depth {f['depth']}")


# -- §20.3 ---------------------------------------------------------------------------------------------

def _broken(kind: str) -> sm.BRep:
    box = sm.cube()
    if kind == "cube missing a face":
        return sm.BRep(box.vertices, box.faces[:5])
    if kind == "cube with a flipped face":
        return sm.BRep(box.vertices, [box.faces[0][::-1]] + box.faces[1:])
    if kind == "cube with a bent face":
        v = box.vertices.copy()
        v[7] += [0.15, 0.15, 0.25]
        return sm.BRep(v, box.faces)
    if kind == "cube and a dangling vertex":
        return sm.BRep(np.concatenate([box.vertices, [[1.0, 1.0, 1.0]]]), box.faces)
    raise ValueError(kind)


#: The solids the B-rep readout offers.
BREPS = {
    "cube": lambda: sm.cube(),
    "tetrahedron": lambda: sm.tetrahedron(),
    "torus mesh (8 x 6 quads)": lambda: sm.torus_mesh(0.9, 0.35, 8, 6),
    "frame (faces with rings)": lambda: sm.frame(1.8, 0.7, 0.6),
    "cube missing a face": lambda: _broken("cube missing a face"),
    "cube with a flipped face": lambda: _broken("cube with a flipped face"),
    "cube with a bent face": lambda: _broken("cube with a bent face"),
    "cube and a dangling vertex": lambda: _broken("cube and a dangling vertex"),
}


def brep_view(solid: str = "torus mesh (8 x 6 quads)", lift: float = 0.0) -> InteractiveView:
    """A B-rep validity readout (Goldman §20.3): pick a solid (valid ones and broken cubes); its
    faces and edges are drawn in three.js and the readout lists V, E, F, L, S, Euler's
    ``V - E + F``, the genus by the Euler-Poincare formula ``V - E + F - (L - F) = 2(S - G)`` and
    every problem :meth:`goldman_lib.solid_modeling.BRep.problems` finds.  The ``lift`` slider
    moves the solid's last vertex up by that much (the red dot): its faces stop being planar,
    though the counts -- and Euler's formula -- do not change.

    ``update(solid, lift)`` returns ``{"counts" {V, E, F, L, S}, "euler", "genus" (-1 if none), "problems"
    (one per line), "valid", "status"}``.
    """
    import ipywidgets as widgets

    from goldman_lib.widgets.three import SceneView

    if solid not in BREPS:
        raise ValueError(f"solid must be one of {sorted(BREPS)}; got {solid!r}")
    lift = as_float(lift, "lift")
    controls = {"solid": dropdown("solid", list(BREPS), solid, width="330px"),
                "lift": float_slider("lift", lift, 0.0, 0.4, 0.02, width="330px")}
    scene = SceneView(width=420, height=320, camera_position=(2.6, -3.4, 2.4), axes=0.0)
    first = BREPS[solid]()
    scene.add_mesh("faces", first.vertices, first.triangles(), color="#66a3d2", opacity=0.85)
    scene.add_segments("edges", first.vertices, first.edges(), color="#222222", width=1.5)
    scene.add_points("lifted", first.vertices[-1:], color="#d1495b", size=0.1)
    readout = widgets.HTML(layout=widgets.Layout(width="360px"))

    def update(solid, lift):
        b = BREPS[solid]()
        if lift:
            v = b.vertices.copy()
            v[-1, 2] += lift
            b = sm.BRep(v, b.faces, b.rings)
        scene.set_points("lifted", b.vertices[-1:])
        tris = b.triangles()
        scene.replace_mesh("faces", b.vertices, tris if len(tris) else np.zeros((1, 3), dtype=int))
        scene.replace_segments("edges", b.vertices, b.edges())
        counts = {"V": b.V, "E": b.E, "F": b.F, "L": b.L, "S": b.S}
        problems = b.problems()
        try:
            g = b.genus
        except ValueError:
            g = None
        chi = b.V - b.E + b.F
        lines = [f"V = {b.V}, E = {b.E}, F = {b.F}, L = {b.L}, S = {b.S}",
                 f"Euler: V − E + F = {chi}" + (" (= 2: a simple polyhedron)" if b.is_simple() else ""),
                 f"Euler–Poincaré: V − E + F − (L − F) = {chi - (b.L - b.F)} = 2(S − G)"
                 + (f" gives genus G = {g}" if g is not None else " has no whole genus ≥ 0")]
        if problems:
            lines += ["<b style='color:#b3261e'>not a valid solid:</b>"] + [f"• {p}" for p in problems]
        else:
            lines.append("<b style='color:#1b7f3b'>valid:</b> every edge in two faces with opposite "
                         "orientations, no dangling vertices, planar faces, outward")
        readout.value = "<br>".join(lines)
        status = (f"{solid}" + (f", last vertex lifted by {lift:.2f}" if lift else "") + ": "
                  + ("valid" if not problems else f"{len(problems)} problem(s)"))
        return {"counts": counts, "euler": chi, "genus": -1 if g is None else g, "problems": "\n".join(problems),
                "valid": not problems,
                "status": status}

    view = InteractiveView(controls=controls, views=[widgets.HBox([scene.widget, readout])], update=update,
                           static=scene.to_png, title="§20.3 B-rep validity")
    view.scene, view.readout = scene, readout
    return view


# -- §20.4 ---------------------------------------------------------------------------------------------

#: The solids the octree view offers: (inside test or solid, exact volume or None).
SOLIDS = {
    "ball (r = 0.8)": (Sphere([0.0, 0.0, 0.0], 0.8), 4.0 / 3.0 * np.pi * 0.8 ** 3),
    "lens A ∩ B": (sm.Intersection(Sphere([-0.45, 0, 0], 0.85), Sphere([0.45, 0, 0], 0.85)), None),
    "bitten ball A − B": (sm.Difference(Sphere([-0.45, 0, 0], 0.85), Sphere([0.45, 0, 0], 0.85)), None),
    "torus (R = 0.6, r = 0.25)": (Torus([0, 0, 0], [0, 0, 1], 0.6, 0.25), 2 * np.pi ** 2 * 0.6 * 0.25 ** 2),
    "ball drilled along y": (sm.Difference(Sphere([0, 0, 0], 0.8), Cylinder([0, -1, 0], [0, 1, 0], 0.3, 2.0)),
                             4 / 3 * np.pi * (0.8 ** 2 - 0.3 ** 2) ** 1.5),
}


def octree_view(solid: str = "ball (r = 0.8)", depth: int = 4, show: str = "full") -> InteractiveView:
    """An octree depth slider (Goldman §20.4): the octree of a solid in the cube [-1, 1]^3
    (:meth:`goldman_lib.solid_modeling.Octree.build`, our rule: corners and centre sampled), its
    full cells as boxes in three.js (blue) and, with ``show = "full and partial"``, the partial
    (boundary) cells as a wireframe.  The status gives the cell counts and the volume estimates.

    ``update(solid, depth, show)`` returns ``{"counts", "volume", "bounds" (2,), "boxes", "status"}``.

    >>> r = octree_view().set_values(depth=2)       # cells of edge 0.5: the eight corner cells are empty
    >>> r["counts"], r["bounds"].tolist()
    ({'empty': 8, 'full': 0, 'partial': 56}, [0.0, 7.0])
    """
    from goldman_lib.widgets.three import SceneView

    if solid not in SOLIDS:
        raise ValueError(f"solid must be one of {sorted(SOLIDS)}; got {solid!r}")
    controls = {
        "solid": dropdown("solid", list(SOLIDS), solid),
        "depth": int_slider("depth", int(depth), 0, 5),
        "show": dropdown("show", ["full", "full and partial"], show),
    }
    scene = SceneView(width=420, height=340, camera_position=(2.4, -3.2, 2.2), axes=0.0)
    scene.add_mesh("full", np.zeros((3, 3)), [[0, 1, 2]], color="#4f7cac")
    scene.add_segments("partial", np.zeros((2, 3)), [[0, 1]], color="#d1495b", width=0.6)
    outline = sm.Octree.build(lambda P: np.zeros(len(P), bool), size=2.0, depth=0).wireframe("empty")
    scene.add_segments("root", *outline, color="#9a9a9a", width=0.8)

    def update(solid, depth, show):
        inside, exact = SOLIDS[solid]
        tree = sm.Octree.build(inside, center=(0, 0, 0), size=2.0, depth=depth)
        pos, tri = tree.boxes("full")
        if len(tri):
            scene.replace_mesh("full", pos, tri)
        else:
            scene.replace_mesh("full", np.zeros((3, 3)), [[0, 1, 2]])
        wpos, wseg = tree.wireframe("partial") if show != "full" else (np.zeros((2, 3)), np.array([[0, 1]]))
        if len(wseg) == 0:
            wpos, wseg = np.zeros((2, 3)), np.array([[0, 1]])
        scene.replace_segments("partial", wpos, wseg)
        counts = tree.counts()
        low, high = tree.volume(0.0), tree.volume(1.0)
        est = tree.volume()
        exact_text = f"; exact {exact:.4f}" if exact is not None else ""
        status = (f"depth {depth}: {counts['full']} full, {counts['partial']} partial, {counts['empty']} empty leaf "
                  f"cells; volume between {low:.4f} (full cells) and {high:.4f} (full + partial), "
                  f"estimate {est:.4f} (half of each partial cell){exact_text}")
        return {"counts": counts, "volume": est, "bounds": np.array([low, high]), "boxes": len(tri) // 12,
                "status": status}

    view = InteractiveView(controls=controls, views=[scene.widget], update=update, static=scene.to_png,
                           title="§20.4 an octree, depth by depth", side=True)
    view.scene = scene
    return view

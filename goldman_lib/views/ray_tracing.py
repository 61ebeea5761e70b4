"""The view of chapter 17 (Goldman, recursive ray tracing): the ray-traced picture of the chapter's
scene beside one pixel's ray tree, drawn in the plane of its rays.

Left, the image :func:`goldman_lib.ray_tracing.render` makes of
:func:`goldman_lib.ray_tracing.default_scene` (built once with ``imshow``; a slider replaces its
data).  Right, the ray tree of the chosen pixel (:func:`goldman_lib.ray_tracing.ray_tree`) in the
plane of incidence at its first hit (:func:`ray_plane`: the primary ray and the first reflected or
refracted ray lie in it): the eye, the floor and each sphere where that plane cuts them (a sphere
the plane misses is not drawn), the primary ray, the reflected and refracted rays level by level,
and the shadow rays towards the light (dashed; red where blocked, violet where they
pass the glass sphere, which lets ``k_t`` of the light through).  A ray that leaves the plane is
drawn projected and broken where it passes over a sphere it misses (:func:`draw_tree`), so no ray
is drawn across a sphere it does not meet (issue 18: the former x-z side view overlapped spheres at
different y and drew a reflected ray through a sphere it missed).  The legend is part of the
figure, so the static picture carries it.  Choose the pixel with its sliders or by clicking the
image; drag the light in the right panel (it moves in the drawing's plane, keeping its distance
from it) or use its sliders (the shared :class:`~goldman_lib.widgets.light_control.LightControl`).
The depth slider sets the recursion depth, the index slider the glass sphere's index of refraction.

A slider move re-renders the whole image (about 27,000 rays at the default 160 x 120, depth 3):
the callback's budget is 100 ms.  Moving only the pixel recomputes only its ray tree.

>>> view = ray_tracing_view()
>>> r = view.set_values(depth=0)
>>> r["image"].shape, sorted(KINDS[k] for k in r["kinds"])
((120, 160, 3), ['primary', 'shadow'])
"""

from __future__ import annotations

from collections import OrderedDict

import numpy as np

from goldman_lib import ray_tracing as rt
from goldman_lib.simple_surfaces import Sphere
from goldman_lib.validation import as_float, as_int
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import InteractiveView, dropdown, figure_widget, float_slider, int_slider
from goldman_lib.widgets.light_control import LightControl

__all__ = ["ray_tracing_view", "image_strip", "ray_plane", "project", "draw_tree", "WIDTH", "HEIGHT", "KIND_COLOURS", "KINDS",
           "FULL_SIZE", "FULL_SAMPLES", "FULL_DEPTH", "SAFEGUARDS_OFF"]

#: The default image size of the view (a full re-render per slider move stays under 100 ms).
WIDTH, HEIGHT = 160, 120
#: The full-size picture a render button makes: (width, height), samples x samples rays per pixel, recursion depth.
FULL_SIZE, FULL_SAMPLES, FULL_DEPTH = (640, 480), 2, 5
#: The safeguards the view's "off" menu takes away: (label, the Scene keywords, what it shows).
SAFEGUARDS_OFF = {
    "none": ("none", {}, ""),
    "acne": ("shadow offset, float32 (§17.3)", {"shadow_offset": 0.0, "precision": "float32"},
             "hit points in single precision and no shadow offset: shadow acne, the points that shadow themselves"),
    "ratio": ("Snell's n1/n2 (§17.5)", {"index_ratio": "n2/n1"},
              "Snell's ratio upside down: rays entering the glass bend away from the normal"),
}
#: How each kind of ray is drawn in the side view.
KIND_COLOURS = {"primary": "#1f4e9c", "reflected": "#1b7f3b", "refracted": "#8f2d56", "shadow": "#edae49"}
#: The kinds of rays, in the order of the codes in an update's ``"kinds"``.
KINDS = tuple(KIND_COLOURS)
_BLOCKED = "#d1495b"
_THROUGH_GLASS = "#9b5de5"
_CACHE = 24


def ray_plane(tree, light=None):
    """The plane the ray tree of a pixel is drawn in: ``(origin, U, V)``, the eye and two orthonormal
    directions.  U is the primary ray's direction; V completes the plane of incidence at the first
    hit (the primary ray and the first reflected or refracted ray, which the laws of reflection and
    refraction keep in one plane with the normal); without one, the plane through the primary ray and
    the light; failing that, the vertical plane.  V points up (its z component is not negative).

    >>> tree = rt.ray_tree(rt.default_scene(), rt.default_camera(), 52, 70, depth=2)
    >>> o, U, V = ray_plane(tree)
    >>> round(float(U @ V), 12), o.tolist()
    (0.0, [-7.0, 0.0, 2.2])
    """
    origin = np.asarray(tree[0].start, dtype=float)
    U = np.asarray(tree[0].end, dtype=float) - origin
    U = U / np.linalg.norm(U)
    candidates = [s.end for s in tree if s.kind in ("reflected", "refracted") and s.level == 1]
    candidates += [s.end for s in tree if s.kind in ("reflected", "refracted")]
    if light is not None:
        candidates.append(np.asarray(light, dtype=float))
    candidates.append(origin + np.array([0.0, 0.0, 1.0]))
    candidates.append(origin + np.array([0.0, 1.0, 0.0]))
    for P in candidates:
        w = np.asarray(P, dtype=float) - origin
        w = w - np.dot(w, U) * U
        if np.linalg.norm(w) > 1e-9 * max(1.0, float(np.linalg.norm(P - origin))):
            V = w / np.linalg.norm(w)
            if V[2] < 0 or (V[2] == 0 and V[1] < 0):
                V = -V
            return origin, U, V
    raise ValueError("tree must have a primary ray of positive length")


def project(plane, points) -> np.ndarray:
    """The coordinates ``(n, 2)`` of 3D ``points`` projected orthogonally onto ``plane`` = (origin, U, V)."""
    origin, U, V = plane
    d = np.asarray(points, dtype=float).reshape(-1, 3) - origin
    return np.column_stack([d @ U, d @ V])


def draw_tree(tree, spheres, plane, samples: int = 97) -> dict:
    """What the ray-tree view draws of ``tree`` in ``plane``: each sphere where the plane cuts it (a
    disc ``(a, b, radius)``, or None if the plane misses the sphere), each ray's projected ends
    ``"segments"`` (n, 2, 2), and the ``"pieces"`` drawn, ``[(ray index, (m, 2) points)]``: a ray is
    drawn over a sphere's disc only where it is inside that sphere, so a ray that misses a sphere in
    space is never drawn across its disc (a ray in the plane never needs a break; one that leaves the
    plane is broken where its projection passes a sphere it misses).  ``"off_plane"`` (n,) flags the
    rays that leave the plane.
    """
    origin, U, V = plane
    N = np.cross(U, V)
    discs = []
    for obj in spheres:
        c = np.asarray(obj.center, dtype=float)
        dist = float(np.dot(c - origin, N))
        r = float(obj.radius)
        if abs(dist) < r:
            a, b = project(plane, c[None])[0]
            discs.append((float(a), float(b), float(np.sqrt(r * r - dist * dist))))
        else:
            discs.append(None)
    t = np.linspace(0.0, 1.0, samples)[:, None]
    segments, pieces, off = [], [], []
    for i, s in enumerate(tree):
        start, end = np.asarray(s.start, dtype=float), np.asarray(s.end, dtype=float)
        pts3 = start + t * (end - start)
        pts2 = project(plane, pts3)
        segments.append([pts2[0], pts2[-1]])
        scale = max(1.0, float(np.linalg.norm(end - start)))
        off.append(bool(np.max(np.abs((pts3 - origin) @ N)) > 1e-9 * scale))
        shown = np.ones(samples, dtype=bool)
        for obj, disc in zip(spheres, discs):
            if disc is None:
                continue
            over = np.hypot(pts2[:, 0] - disc[0], pts2[:, 1] - disc[1]) < disc[2]
            outside = np.linalg.norm(pts3 - np.asarray(obj.center, dtype=float), axis=1) > obj.radius * (1 + 1e-9)
            shown &= ~(over & outside)
        # runs of shown samples become the pieces drawn
        edges = np.flatnonzero(np.diff(np.concatenate([[0], shown.astype(int), [0]])))
        for a, b in zip(edges[::2], edges[1::2]):
            if b - a >= 2:
                pieces.append((i, pts2[a:b]))
    return {"segments": np.array(segments, dtype=float).reshape(-1, 2, 2), "pieces": pieces, "discs": discs,
            "off_plane": np.array(off, dtype=bool)}


def _floor_polygon(plane, limits) -> np.ndarray:
    """The part of the drawing's box where the plane is below the floor z = 0 (a convex polygon)."""
    origin, U, V = plane
    x0, x1, y0, y1 = limits
    box = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], dtype=float)
    height = lambda q: origin[2] + q[0] * U[2] + q[1] * V[2]
    out = []
    for k in range(4):
        p, q = box[k], box[(k + 1) % 4]
        hp, hq = height(p), height(q)
        if hp <= 0:
            out.append(p)
        if (hp < 0) != (hq < 0) and hp != hq:
            out.append(p + (q - p) * (hp / (hp - hq)))
    if len(out) < 3:
        return np.array([[x0, y0], [x0, y0], [x0, y0]])
    return np.array(out)


def image_strip(images, titles=None, width: float = 2.6) -> bytes:
    """A static picture (PNG bytes) of rendered images side by side, each ``width`` inches wide with
    its title: for comparing renders (depths, lights, indices) in a notebook.

    >>> image_strip([np.zeros((4, 6, 3)), np.ones((4, 6, 3))], ["black", "white"])[:4]
    b'\\x89PNG'
    """
    from matplotlib.figure import Figure

    from goldman_lib.widgets.interactive import figure_png

    images = [np.clip(np.asarray(img, dtype=float), 0, 1) for img in images]
    if not images or any(img.ndim != 3 or img.shape[2] != 3 for img in images):
        raise ValueError("images must be a non-empty list of (height, width, 3) RGB images")
    titles = list(titles) if titles is not None else [""] * len(images)
    if len(titles) != len(images):
        raise ValueError(f"titles must have one title per image ({len(images)}); got {len(titles)}")
    h, w = images[0].shape[:2]
    fig = Figure(figsize=(width * len(images), width * h / w + 0.35), dpi=style.DPI)
    for k, (img, title) in enumerate(zip(images, titles)):
        ax = fig.add_axes([k / len(images) + 0.005, 0.0, 1 / len(images) - 0.01, 1 - 0.35 / (width * h / w + 0.35)])
        ax.imshow(img, interpolation="nearest")
        ax.set_xticks([]), ax.set_yticks([])
        ax.set_title(title, fontsize=9)
    return figure_png(fig)


def ray_tracing_view(depth: int = 3, index: float = 1.5, px: int = 52, py: int = 70) -> InteractiveView:
    """Recursive ray tracing (Goldman §17.2-17.5): the image of the chapter's scene (left) at
    recursion depth ``depth`` with the glass sphere's index of refraction ``index``, and the ray tree
    of pixel ``(px, py)`` (column from the left, row from the top) in the plane of its rays (right),
    where the light can be dragged.  The menu "off" (control ``unsafe``) takes one safeguard of the tracer away to show
    what it prevents (:data:`SAFEGUARDS_OFF`: the shadow offset in single precision, §17.3 shadow acne;
    Snell's ratio upside down, §17.5).

    ``update(depth, index, px, py, unsafe, light0_x, light0_y, light0_z, light0_I, light0_colour)`` returns
    ``{"image" (120, 160, 3), "segments" (n, 2, 2) the rays' ends in the drawing's plane, "kinds" (n,)
    codes into :data:`KINDS`, "blocked" (n,) booleans, "pixel" (3,), "rays", "plane" (3, 3) rows origin, U, V,
    "cut" (k,) whether the plane cuts each sphere, "discs" (k, 3) the cuts (a, b, radius; zeros if
    none), "pieces" (the drawn parts of the rays, (m, 2) each), "piece_rays" (the ray of each piece),
    "off_plane" (n,), "status"}`` (see :func:`draw_tree`).

    ``view.render_full(progress, size=FULL_SIZE, samples=FULL_SAMPLES, full_depth=FULL_DEPTH, **values)``
    is the full-size picture of the view's scene (its glass index and light; the depth slider and the
    pixel are the small picture's): :func:`goldman_lib.ray_tracing.render` at 640 x 480, 2 x 2
    anti-aliased, depth 5, the function a :class:`goldman_lib.widgets.render_control.RenderControl`
    calls.  The glass index is the view's first slider (the render button's browser test moves it).

    >>> r = ray_tracing_view().set_values(depth=2, index=1.0)     # index 1: the glass bends nothing
    >>> "critical angle none" in r["status"]
    True
    """
    import ipywidgets as widgets

    depth = as_int(depth, "depth", minimum=0, maximum=6)
    index = as_float(index, "index")
    if not 1.0 <= index <= 2.5:
        raise ValueError(f"index must lie in [1, 2.5]; got {index}")
    px = as_int(px, "px", minimum=0, maximum=WIDTH - 1)
    py = as_int(py, "py", minimum=0, maximum=HEIGHT - 1)
    light = rt.default_lights()[0]
    control = LightControl([light], box=((-6.5, 4.0), (-5.0, 5.0), (0.2, 6.5)))
    controls = {
        "depth": int_slider("depth", depth, 0, 6),
        "index": float_slider("index", index, 1.0, 2.5, 0.05),
        "px": int_slider("pixel x", px, 0, WIDTH - 1),
        "py": int_slider("pixel y", py, 0, HEIGHT - 1),
        "unsafe": dropdown("off", [(label, key) for key, (label, _, _) in SAFEGUARDS_OFF.items()], "none"),
        **control.controls,
    }
    camera = rt.default_camera()
    scene0 = rt.default_scene(index=index)

    fig = style.new_figure(style.WIDE_FIGSIZE)
    ax_img = fig.add_axes([0.01, 0.08, 0.44, 0.84])
    ax_side = fig.add_axes([0.51, 0.1, 0.33, 0.82])
    image = ax_img.imshow(np.zeros((HEIGHT, WIDTH, 3)), origin="upper", interpolation="nearest",
                          extent=(-0.5, WIDTH - 0.5, HEIGHT - 0.5, -0.5))
    ax_img.set_xticks([]), ax_img.set_yticks([])
    (pixel_mark,) = ax_img.plot([], [], "s", markersize=9, markerfacecolor="none", markeredgecolor="#ff00ff",
                                markeredgewidth=1.5)
    img_title = ax_img.set_title("", fontsize=9)

    style.style_axes(ax_side)
    ax_side.tick_params(labelsize=7)
    ax_side.set_xlabel("along the primary ray", fontsize=8)
    ax_side.set_ylabel("across it, in the plane", fontsize=8)
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, Polygon

    floor_patch = Polygon(np.zeros((3, 2)), closed=True, facecolor="#d8d4c8", edgecolor="#8a8578", linewidth=0.8,
                          zorder=0)
    ax_side.add_patch(floor_patch)
    spheres = [obj for obj in scene0.objects if isinstance(obj, Sphere)]
    discs = []
    for obj in spheres:
        c = obj.material.colour
        face = (*c, 0.25 if obj.material.transmit > 0 else 0.5)
        disc = Circle((0, 0), 1.0, facecolor=face, edgecolor="#555555", linewidth=0.8, zorder=1, visible=False)
        ax_side.add_patch(disc)
        discs.append(disc)
    (eye_dot,) = ax_side.plot([0.0], [0.0], "o", color="#222222", markersize=6, zorder=4)
    eye_label = ax_side.annotate("eye", (0.0, 0.0), textcoords="offset points", xytext=(-6, 8), fontsize=8)
    lines = LineCollection([], linewidths=1.6, zorder=3)
    ax_side.add_collection(lines)
    (light_dot,) = ax_side.plot([], [], "o", color="#f2b700", markeredgecolor="#7a5c00", markersize=11, zorder=5)
    # the legend is part of the figure, so the static picture has it too
    handles = ([Line2D([], [], color="#f2b700", marker="o", linestyle="", markeredgecolor="#7a5c00",
                       label="light (drag it)")]
               + [Line2D([], [], color=c, linestyle="--" if k == "shadow" else "-", label=f"{k} ray")
                  for k, c in KIND_COLOURS.items()]
               + [Line2D([], [], color=_BLOCKED, linestyle="--", label="blocked shadow ray"),
                  Line2D([], [], color=_THROUGH_GLASS, linestyle="--", label="shadow ray through\nglass (k_t)")])
    side_legend = ax_side.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0),
                                 frameon=False, borderaxespad=0.2, handlelength=2.2)
    # the legend never changes (the side axes' limits follow the tree, but it is placed by the axes box):
    # rendered once, pasted at each redraw
    style.draw_once(side_legend, lambda: (tuple(ax_side.get_position().bounds),))
    legend = widgets.HTML("<small>Right: the ray tree in the plane of the primary ray and the first reflected or "
                          "refracted ray; each sphere is drawn where that plane cuts it.  A ray that leaves the "
                          "plane is drawn projected, broken where it passes a sphere it misses.</small>")
    side_title = ax_side.set_title("", fontsize=9)
    frame: dict = {}

    images: OrderedDict = OrderedDict()

    def the_scene(index, lights, unsafe):
        scene = rt.default_scene(index=index, lights=lights)
        if unsafe == "none":
            return scene
        return rt.Scene(scene.objects, scene.lights, scene.ambient_light, scene.background, scene.shadow_transmission,
                        **SAFEGUARDS_OFF[unsafe][1])

    def picture(depth, index, lights, unsafe="none"):
        key = (depth, index, tuple((lt.position, lt.colour, lt.intensity) for lt in lights), unsafe)
        if key in images:
            images.move_to_end(key)
            return images[key]
        scene = the_scene(index, lights, unsafe)
        counts: dict = {}
        img = rt.render(scene, camera, WIDTH, HEIGHT, depth, counts=counts)
        images[key] = (scene, img, counts)
        while len(images) > _CACHE:
            images.popitem(last=False)
        return images[key]

    def update(depth, index, px, py, unsafe="none", **light_values):
        lights = control.lights(light_values)
        scene, img, counts = picture(depth, index, lights, unsafe)
        tree = rt.ray_tree(scene, camera, px, py, depth, WIDTH, HEIGHT, miss_length=4.0)
        lamp = control.marker_positions(light_values)[0]
        if frame.get("hold") and "plane" in frame:
            plane = frame["plane"]            # a light being dragged: the plane holds still under the mouse
        else:
            plane = frame["plane"] = ray_plane(tree, lamp)
        image.set_data(img)
        pixel_mark.set_data([px], [py])
        drawing = draw_tree(tree, spheres, plane)
        seg = drawing["segments"]
        kinds = [s.kind for s in tree]
        blocked = np.array([s.kind == "shadow" and s.light == 0 for s in tree], dtype=bool)
        through = np.array([s.kind == "shadow" and s.hit and s.light > 0 for s in tree], dtype=bool)
        colours = [_BLOCKED if b else _THROUGH_GLASS if g else KIND_COLOURS[k]
                   for k, b, g in zip(kinds, blocked, through)]
        pieces = drawing["pieces"]
        lines.set_segments([pts for _, pts in pieces])
        lines.set_color([colours[i] for i, _ in pieces])
        lines.set_linestyle(["--" if kinds[i] == "shadow" else "-" for i, _ in pieces])
        for disc, cut in zip(discs, drawing["discs"]):
            disc.set_visible(cut is not None)
            if cut is not None:
                disc.center, disc.radius = (cut[0], cut[1]), cut[2]
        marker = project(plane, lamp[None])[0]
        light_dot.set_data([marker[0]], [marker[1]])
        if not frame.get("hold"):
            pts = np.vstack([seg.reshape(-1, 2), marker[None], [[0.0, 0.0]]]
                            + [[[c[0] - c[2], c[1] - c[2]], [c[0] + c[2], c[1] + c[2]]]
                               for c in drawing["discs"] if c is not None])
            lo, hi = pts.min(axis=0), pts.max(axis=0)
            pad = 0.08 * max(float(np.max(hi - lo)), 1.0)
            lo, hi = lo - pad, hi + pad
            # equal scales on both axes: widen the shorter range to the axes' shape
            box = ax_side.get_position()
            shape = (box.height * fig.get_figheight()) / (box.width * fig.get_figwidth())
            w, h = hi - lo
            mid = (lo + hi) / 2
            w, h = max(w, h / shape), max(h, w * shape)
            frame["limits"] = (mid[0] - w / 2, mid[0] + w / 2, mid[1] - h / 2, mid[1] + h / 2)
            ax_side.set_xlim(frame["limits"][:2]), ax_side.set_ylim(frame["limits"][2:])
        floor_patch.set_xy(_floor_polygon(plane, frame["limits"]))
        n = {k: kinds.count(k) for k in KIND_COLOURS}
        crit = rt.critical_angle(index, 1.0)
        img_title.set_text(f"depth {depth}, glass index {index:.2f}")
        side_title.set_text(f"ray tree of pixel ({px}, {py}) in the plane of its rays")
        off = int(np.sum(drawing["off_plane"]))
        status = (f"{WIDTH}x{HEIGHT} image at recursion depth {depth}: {counts['rays']:,} primary, reflected and "
                  f"refracted rays and {counts['shadow']:,} shadow rays.  Pixel ({px}, {py}): {n['primary']} primary, "
                  f"{n['reflected']} reflected, {n['refracted']} refracted and {n['shadow']} shadow rays "
                  f"({int(blocked.sum())} blocked, {int(through.sum())} through glass); at most "
                  f"{rt.ray_tree_size(depth, len(lights))} at this depth; {off} leave the drawing's plane (drawn projected).  "
                  f"Glass index {index:.2f}: critical angle "
                  + (f"{crit:.1f}° (inside the glass)" if crit is not None else "none (no total internal reflection)"))
        if unsafe != "none":
            status = f"Safeguard off: {SAFEGUARDS_OFF[unsafe][2]}.  " + status
        pixel = np.asarray(img[py, px], dtype=float)
        codes = np.array([KINDS.index(k) for k in kinds], dtype=int)
        return {"image": img, "segments": seg, "kinds": codes, "blocked": blocked, "pixel": pixel,
                "rays": counts["rays"], "pieces": [pts for _, pts in pieces],
                "piece_rays": np.array([i for i, _ in pieces], dtype=int), "plane": np.array(plane),
                "cut": np.array([c is not None for c in drawing["discs"]], dtype=bool),
                "discs": np.array([c if c is not None else (0.0, 0.0, 0.0) for c in drawing["discs"]], dtype=float),
                "off_plane": drawing["off_plane"], "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig), legend], update=update, figure=fig,
                           title="§17.2-17.5 recursive ray tracing: the image and one pixel's ray tree",
                           arrange=[widgets.HBox([widgets.VBox([controls["index"], controls["depth"],
                                                                controls["px"], controls["py"], controls["unsafe"]]),
                                                  widgets.VBox(list(control.controls.values()))])])

    # drag the light in the plane of the drawing (it keeps its distance from that plane)
    from goldman_lib.widgets.drag import PointDrag, snap_to_slider

    def light_point():
        return project(frame["plane"], control.marker_positions(view.values()))

    def on_drag(k, a, b):
        frame["hold"] = True
        origin, U, V = frame["plane"]
        lamp = control.marker_positions(view.values())[0]
        N = np.cross(U, V)
        P = origin + a * U + b * V + float(np.dot(lamp - origin, N)) * N
        names = [control.name(0, axis) for axis in "xyz"]
        view.set_values(**{name: snap_to_slider(view.controls[name], float(v)) for name, v in zip(names, P)})

    def on_release(k):
        if frame.pop("hold", False):
            view.refresh()

    view.drag = PointDrag(ax_side, light_point, on_drag, on_release=on_release)

    def on_click(event):
        if event.inaxes is not ax_img or event.xdata is None or event.ydata is None:
            return
        view.set_values(px=int(np.clip(round(event.xdata), 0, WIDTH - 1)),
                        py=int(np.clip(round(event.ydata), 0, HEIGHT - 1)))

    view.click_cid = fig.canvas.mpl_connect("button_press_event", on_click)
    view.light_control = control
    view.axes = (ax_img, ax_side)

    def render_full(progress=None, size=FULL_SIZE, samples=FULL_SAMPLES, full_depth=FULL_DEPTH, *, index, depth=None,
                    px=None, py=None, unsafe="none", **light_values):
        # depth, px, py: the small picture's recursion depth and chosen pixel; the full picture is full_depth deep
        scene = the_scene(index, control.lights(light_values), unsafe)
        return rt.render(scene, camera, size[0], size[1], full_depth, samples=samples, progress=progress)

    view.render_full = render_full
    # the titles and the x label are placed once; the side axes' y label follows its tick labels
    style.pin_layout(fig, rescaling=(ax_side,))
    # the picture's title changes with depth and index only: rendered once per text, pasted while the
    # pixel, the light or the safeguard moves (the side axes follow the tree: drawn afresh)
    style.freeze_axes_decorations(ax_img, img_title)
    return view

"""The views of chapter 19 (Goldman, simple surfaces): a ray-traced gallery of every simple surface
(§19.3-19.7) and the same surfaces in three.js, each with a surface picker and the sliders of its
parameters (radius, height, half-angle, R, r) and the shared light-position control.

The pictures are made by the library: :func:`goldman_lib.ray_tracing.render` ray traces a floor and
the chosen :mod:`goldman_lib.simple_surfaces` surface (each surface's ``hit``: its own intersection
and normal), lit by :mod:`goldman_lib.lighting` with shadows; the three.js view shows the surface's
``mesh``.  This module only picks the surface and draws.  :func:`gallery_render_control` renders the
gallery's current picture at full size (640 x 480, anti-aliased, depth 5) with a progress bar
(issue 18 §4), by the same library call.

>>> s = make_surface("torus", R=1.0, r=0.3)
>>> type(s).__name__, s.R, s.r
('Torus', 1.0, 0.3)
"""

from __future__ import annotations

import pickle

import numpy as np

from goldman_lib import lighting, simple_surfaces as S
from goldman_lib.camera import Camera
from goldman_lib.lighting import Material
from goldman_lib.validation import as_float, within_budget
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import InteractiveView, dropdown, figure_widget, float_slider
from goldman_lib.widgets.light_control import LightControl

__all__ = ["SURFACES", "make_surface", "gallery_view", "gallery_render_control", "gallery_figure",
           "surface_scene_view", "torus_ray_view", "GALLERY_SIZE"]

#: The surfaces of the picker, in the chapter's order, with the section each comes from.
SURFACES = {
    "plane": "§19.3", "polygon (non-convex)": "§19.3", "sphere": "§19.4.1", "cylinder": "§19.4.2",
    "cone": "§19.4.3", "ellipsoid": "§19.4.4", "elliptic cylinder": "§19.4.4", "elliptic cone": "§19.4.4",
    "quadric (hyperboloid)": "§19.5", "torus": "§19.6", "surface of revolution": "§19.7",
}

#: The ray-traced picture's default size (width, height) in pixels: one primary ray per pixel.
GALLERY_SIZE = (160, 120)
#: How many pictures the gallery view keeps (160 x 120 RGB, 0.5 MB each).
_KEEP_PICTURES = 8

_COLOURS = {
    "plane": (0.55, 0.7, 0.55), "polygon (non-convex)": (0.9, 0.55, 0.2), "sphere": (0.85, 0.2, 0.2),
    "cylinder": (0.25, 0.45, 0.85), "cone": (0.85, 0.7, 0.2), "ellipsoid": (0.6, 0.3, 0.75),
    "elliptic cylinder": (0.2, 0.65, 0.65), "elliptic cone": (0.8, 0.4, 0.5), "quadric (hyperboloid)": (0.4, 0.6, 0.3),
    "torus": (0.9, 0.45, 0.15), "surface of revolution": (0.3, 0.55, 0.8),
}
_FLOOR = Material(colour=(0.82, 0.8, 0.74), ambient=0.9, diffuse=0.7, specular=0.05, exponent=8)
_EYE, _TARGET = (4.2, -5.4, 3.0), (0.0, 0.0, 0.8)


def _material(kind: str) -> Material:
    return Material(colour=_COLOURS[kind], ambient=0.35, diffuse=0.7, specular=0.45, exponent=40)


def make_surface(kind: str = "torus", radius: float = 0.8, height: float = 1.6, half_angle: float = 25.0,
                 R: float = 1.0, r: float = 0.35) -> S.Surface:
    """The gallery's surface ``kind`` (a key of :data:`SURFACES`) standing on the floor z = 0, built
    from the sliders' values: ``radius`` (sphere, cylinders, ellipsoid, polygon, the profile's
    scale), ``height`` (bounded cylinders and cones, ellipsoid, surface of revolution),
    ``half_angle`` (cones, degrees), ``R`` and ``r`` (torus).  Each gets its own material.

    >>> make_surface("cone", height=2.0, half_angle=30).apex.tolist()     # apex up, opening downwards
    [0.0, 0.0, 2.0]
    """
    if kind not in SURFACES:
        raise ValueError(f"kind must be one of {sorted(SURFACES)}; got {kind!r}")
    radius, height = as_float(radius, "radius", positive=True), as_float(height, "height", positive=True)
    half_angle, R, r = as_float(half_angle, "half_angle"), as_float(R, "R", positive=True), as_float(r, "r", positive=True)
    m = _material(kind)
    if kind == "plane":
        return S.Plane([0.0, 1.2, 0.0], [0.0, -1.0, 1.2], m)
    if kind == "polygon (non-convex)":
        a = radius
        star = [(np.cos(t) * (a if k % 2 == 0 else 0.45 * a), 0.0, 1.2 * a + np.sin(t) * (a if k % 2 == 0 else 0.45 * a))
                for k, t in enumerate(np.radians(90 + 36 * np.arange(10)))]
        return S.Polygon(star, m)
    if kind == "sphere":
        return S.Sphere([0.0, 0.0, radius], radius, m)
    if kind == "cylinder":
        return S.Cylinder([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], radius, height=height, material=m)
    if kind == "cone":
        return S.Cone([0.0, 0.0, height], [0.0, 0.0, -1.0], half_angle, height=height, material=m)
    if kind == "ellipsoid":
        return S.Ellipsoid([0.0, 0.0, height / 2], [1.5 * radius, radius, height / 2], material=m)
    if kind == "elliptic cylinder":
        return S.EllipticCylinder([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.5 * radius, 0.7 * radius], height=height,
                                  major=[1.0, 0.0, 0.0], material=m)
    if kind == "elliptic cone":
        return S.EllipticCone([0.0, 0.0, height], [0.0, 0.0, -1.0], [half_angle, half_angle / 2], height=height,
                              major=[1.0, 0.0, 0.0], material=m)
    if kind == "quadric (hyperboloid)":      # x^2 + y^2 - (z - 1)^2 / 2 = radius^2 / 2
        return S.Quadric([1.0, 1.0, -0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -0.5 - radius ** 2 / 2], m)
    if kind == "torus":
        return S.Torus([0.0, 0.0, r], [0.0, 0.0, 1.0], R, r, material=m)
    # surface of revolution: the vase r(z) = radius (1 - 1.2 s + s^2), s = z / height
    return S.SurfaceOfRevolution([0.0, 0.0, 0.0], [0.0, 0.0, 1.0],
                                 [radius, -1.2 * radius / height, radius / height ** 2], height, material=m)


#: The shape sliders each surface of the gallery reads (measured: each other slider leaves its picture
#: unchanged); the others are disabled while it is shown.
USES = {"plane": (), "polygon (non-convex)": ("radius",), "sphere": ("radius",), "cylinder": ("radius", "height"),
        "cone": ("height", "half_angle"), "ellipsoid": ("radius", "height"), "elliptic cylinder": ("radius", "height"),
        "elliptic cone": ("height", "half_angle"), "quadric (hyperboloid)": ("radius",), "torus": ("R", "r"),
        "surface of revolution": ("radius", "height")}


def _acts():
    """The gallery's ``acts`` rule: each shape slider acts for the surfaces that read it."""
    return {name: {"kind": [k for k, used in USES.items() if name in used]}
            for name in ("R", "r", "radius", "height", "half_angle")}


def _controls(kind, radius, height, half_angle, R, r):
    # the torus (the default surface) first: its sliders are the ones that move the default picture
    return {
        "kind": dropdown("surface", list(SURFACES), kind),
        "R": float_slider("torus R", R, 0.5, 1.5, 0.05),
        "r": float_slider("torus r", r, 0.1, 0.6, 0.02),
        "radius": float_slider("radius", radius, 0.3, 1.3, 0.05),
        "height": float_slider("height", height, 0.4, 2.4, 0.05),
        "half_angle": float_slider("half-angle °", half_angle, 10.0, 60.0, 1.0),
    }


def _describe(surface, kind) -> str:
    text = f"{kind} ({SURFACES[kind]})"
    if isinstance(surface, S.Torus):
        text += f"; the bounding test let {surface.quartics_solved:,} rays solve the quartic"
    return text


def gallery_view(kind: str = "torus", radius: float = 0.8, height: float = 1.6, half_angle: float = 25.0,
                 R: float = 1.0, r: float = 0.35, width: int = GALLERY_SIZE[0],
                 height_px: int = GALLERY_SIZE[1]) -> InteractiveView:
    """A ray-traced gallery of the simple surfaces (Goldman §19.3-19.7): the picked surface on a floor,
    ray traced by :func:`goldman_lib.ray_tracing.render` (one primary ray per pixel, the surface's own
    intersection and normal, lighting and shadows from :mod:`goldman_lib.lighting`), under a light
    set by the light-position control.  The image is drawn once and updated with ``set_data``.

    ``update(kind, radius, height, half_angle, R, r, light0_x, ...)`` returns ``{"image" (h, w, 3),
    "status"}``.  A full re-render per slider move (under 100 ms at the default size); the last few
    pictures are kept, keyed by the surface and the lights themselves, so a slider the picked
    surface does not use (``R`` for a sphere) or a return to a picture redraws without re-rendering.

    >>> v = gallery_view(width=40, height_px=30)
    >>> v.set_values(kind="sphere")["image"].shape
    (30, 40, 3)
    """
    from goldman_lib import ray_tracing as rt

    width = within_budget(width, "width", cost=lambda v: v * v, what="the image", unit="pixels", minimum=8)
    height_px = within_budget(height_px, "height_px", cost=lambda v: width * v, what="the image", unit="pixels",
                              minimum=8)
    light = LightControl([(3.0, -3.5, 5.5)], box=(-6.0, 6.0), intensity_range=(0.0, 2.0))
    controls = {**_controls(kind, radius, height, half_angle, R, r), **light.controls}
    camera = Camera(_EYE, _TARGET, fov=40.0)
    floor = S.Plane([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], _FLOOR)
    fig = style.new_figure(figsize=(4.8, 3.6))
    ax = fig.add_axes([0.0, 0.0, 1.0, 0.92])
    ax.set_axis_off()
    im = ax.imshow(np.zeros((height_px, width, 3)), interpolation="nearest")
    title = ax.set_title("", fontsize=9)
    rendered: dict = {}   # (surface, lights) as pickled bytes -> picture, the least recently shown first

    def update(kind, radius, height, half_angle, R, r, **lights):
        surface = make_surface(kind, radius, height, half_angle, R, r)
        lamps = light.lights(lights)
        key = pickle.dumps((surface, lamps))      # the objects' own state: equal surfaces, equal keys
        image = rendered.pop(key, None)
        if image is None:
            image = rt.render(_gallery_scene(floor, surface, lamps), camera, width, height_px, depth=0)
            image.setflags(write=False)
            while len(rendered) >= _KEEP_PICTURES:
                rendered.pop(next(iter(rendered)))
        rendered[key] = image
        im.set_data(image)
        title.set_text(f"{kind} ({SURFACES[kind]}), ray traced")
        return {"image": image, "status": _describe(surface, kind)}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§19 simple surfaces, ray traced", side=True, acts=_acts())
    view.light_control = light
    style.pin_layout(fig)       # the title need not be placed again at each redraw
    return view


def _gallery_scene(floor, surface, lamps):
    from goldman_lib import ray_tracing as rt

    return rt.Scene([floor, surface], lamps, ambient_light=0.25, background=(0.62, 0.76, 0.92))


def gallery_render_control(view: InteractiveView, width: int = 640, height_px: int = 480, samples: int = 2,
                           depth: int = 5):
    """A "render" control for the gallery ``view`` of :func:`gallery_view` (issue 18 §4): its button ray
    traces the surface and the lights the view shows now, at ``width x height_px`` with ``samples x
    samples`` anti-aliasing and recursion ``depth`` (:func:`goldman_lib.ray_tracing.render`, the same
    scene and camera as the view's small picture), filling a progress bar as the rows are done; the
    sliders stay as fast as before.  Returns a :class:`goldman_lib.widgets.render_control.RenderControl`
    (not displayed); ``.render()`` does the same from the keyboard.

    >>> v = gallery_view(width=40, height_px=30)
    >>> rc = gallery_render_control(v, 16, 12, samples=1, depth=0)
    >>> v.set_values(kind="sphere") and rc.render().shape
    (12, 16, 3)
    """
    from goldman_lib import ray_tracing as rt
    from goldman_lib.widgets.render_control import RenderControl

    if not isinstance(view, InteractiveView) or not hasattr(view, "light_control"):
        raise TypeError("view must be the gallery's InteractiveView (from gallery_view())")
    camera = Camera(_EYE, _TARGET, fov=40.0)
    floor = S.Plane([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], _FLOOR)

    def render(progress, kind, radius, height, half_angle, R, r, **lights):
        surface = make_surface(kind, radius, height, half_angle, R, r)
        scene = _gallery_scene(floor, surface, view.light_control.lights(lights))
        return rt.render(scene, camera, width, height_px, depth=depth, samples=samples, progress=progress)

    return RenderControl(render, view=view,
                         label=f"Render {width} x {height_px}, {samples} x {samples} anti-aliased, depth {depth}")


def gallery_figure(width: int = 112, height_px: int = 84, columns: int = 4):
    """Every simple surface of :data:`SURFACES` at its default parameters, ray traced on the floor
    (Goldman §19.3-19.7), as one matplotlib figure of small pictures (the chapter's static gallery).
    Returns the figure.

    >>> len(gallery_figure(16, 12).axes)
    12
    """
    from goldman_lib import ray_tracing as rt

    width = within_budget(width, "width", cost=lambda v: v * v, what="each picture", unit="pixels", minimum=8)
    height_px = within_budget(height_px, "height_px", cost=lambda v: width * v, what="each picture", unit="pixels",
                              minimum=8)
    columns = within_budget(columns, "columns", cost=lambda v: v, what="the grid", unit="columns", limit=12, minimum=1)
    rows = -(-len(SURFACES) // columns)
    fig = style.new_figure(figsize=(2.4 * columns, 2.0 * rows))
    camera = Camera(_EYE, _TARGET, fov=40.0)
    floor = S.Plane([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], _FLOOR)
    light = LightControl([(3.0, -3.5, 5.5)])
    for k in range(rows * columns):
        ax = fig.add_subplot(rows, columns, k + 1)
        ax.set_axis_off()
        if k >= len(SURFACES):
            continue
        kind = list(SURFACES)[k]
        scene = rt.Scene([floor, make_surface(kind)], light.lights(light.defaults()), ambient_light=0.25,
                         background=(0.62, 0.76, 0.92))
        ax.imshow(rt.render(scene, camera, width, height_px, depth=0), interpolation="nearest")
        ax.set_title(f"{kind} {SURFACES[kind]}", fontsize=8)
    fig.tight_layout()
    return fig


def _floor_mesh(size=2.6):
    P = np.array([[-size, -size, 0.0], [size, -size, 0.0], [size, size, 0.0], [-size, size, 0.0]])
    return P, np.array([[0, 1, 2], [0, 2, 3]])


def _hex(rgb) -> str:
    return "#" + "".join(f"{int(round(255 * c)):02x}" for c in rgb)


def surface_scene_view(kind: str = "torus", radius: float = 0.8, height: float = 1.6, half_angle: float = 25.0,
                       R: float = 1.0, r: float = 0.35, resolution: int = 32) -> InteractiveView:
    """The same simple surfaces in three.js, to orbit with the mouse (Goldman §19.3-19.7): the picked
    surface's :meth:`~goldman_lib.simple_surfaces.Surface.mesh` (unbounded ones drawn within 2 of
    their reference point) on the floor, lit by the light-position control's light (its marker in
    yellow).  A slider replaces the mesh's arrays in place.

    ``update(kind, radius, height, half_angle, R, r, light0_x, ...)`` returns ``{"positions",
    "triangles", "status"}``.

    >>> v = surface_scene_view(resolution=8)
    >>> len(v.set_values(kind="cylinder", radius=0.5)["triangles"]) > 0
    True
    """
    from goldman_lib.widgets.three import SceneView

    resolution = within_budget(resolution, "resolution", cost=lambda v: 6 * v * v, what="the mesh", unit="indices",
                               limit=6 * 200 ** 2, minimum=3)
    light = LightControl([(3.0, -3.5, 5.5)], box=(-6.0, 6.0), intensity_range=(0.0, 2.0))
    controls = {**_controls(kind, radius, height, half_angle, R, r), **light.controls}
    scene = SceneView(width=460, height=340, camera_position=_EYE, target=_TARGET, axes=0.0,
                      lights=light.lights(light.defaults()))
    scene.add_mesh("floor", *_floor_mesh(), color=_hex(_FLOOR.colour))
    first = make_surface(kind, radius, height, half_angle, R, r)
    scene.add_mesh("surface", *first.mesh(resolution, extent=2.0), color=_hex(first.material.colour))
    state = {"kind": kind}

    def update(kind, radius, height, half_angle, R, r, **lights):
        surface = make_surface(kind, radius, height, half_angle, R, r)
        # the general quadric is meshed by marching tetrahedra on a 3D grid: a coarser grid keeps it quick
        res = resolution if kind != "quadric (hyperboloid)" else max(8, 2 * resolution // 3)
        positions, triangles = surface.mesh(res, extent=2.0)
        scene.replace_mesh("surface", positions, triangles)
        if kind != state["kind"]:
            scene.set_color("surface", _hex(surface.material.colour))
            state["kind"] = kind
        light.show_in_scene(scene, lights)
        return {"positions": positions, "triangles": triangles,
                "status": f"{kind} ({SURFACES[kind]}): {len(triangles):,} triangles; drag to orbit"}

    view = InteractiveView(controls=controls, views=[scene.widget], update=update, static=scene.to_png,
                           title="§19 simple surfaces in three.js", side=True, acts=_acts())
    view.scene = scene
    view.light_control = light
    return view


def torus_ray_view(ox: float = -3.5, oz: float = 1.2, angle: float = -15.0, R: float = 1.5,
                   r: float = 0.5) -> InteractiveView:
    """One ray against a torus, in the torus's cross-section (the x-z plane through its axis; Goldman
    §19.6): the tube's two circles, the bounding sphere of radius ``R + r`` and the slab ``|z| <= r``
    of §19.6.1 (dashed), the ray from the draggable origin ``(ox, 0, oz)`` at ``angle`` degrees from the
    x-axis, its hits in front of the origin (up to four, from :meth:`Torus.hits`) and the unit normals
    there (:meth:`Torus.normal`).  The status says whether the ray passed the bound (the quartic was
    solved) or skipped the quartic.

    ``update(ox, oz, angle, R, r)`` returns ``{"hits" (k, 3), "normals" (k, 3), "t" (k,), "solved",
    "status"}``.

    >>> v = torus_ray_view()
    >>> r = v.set_values(ox=-4.0, oz=0.0, angle=0.0, R=1.5, r=0.5)
    >>> np.round(r["t"], 9).tolist(), r["solved"]
    ([2.0, 3.0, 5.0, 6.0], True)
    """
    from matplotlib.patches import Circle

    from goldman_lib.widgets.drag import drag_sliders

    controls = {"ox": float_slider("origin x", ox, -4.0, 4.0, 0.05), "oz": float_slider("origin z", oz, -3.0, 3.0, 0.05),
                "angle": float_slider("angle °", angle, -180.0, 180.0, 1.0),
                "R": float_slider("R", R, 0.6, 2.0, 0.05), "r": float_slider("r", r, 0.1, 0.8, 0.02)}
    fig, ax = style.new_axes()
    ax.set_xlim(-4.2, 4.2), ax.set_ylim(-3.2, 3.2)
    ax.set_xlabel("x"), ax.set_ylabel("z")
    tubes = [Circle((0, 0), 1, facecolor="#f6c79b", edgecolor="#b35c00", linewidth=1.4) for _ in range(2)]
    bound = Circle((0, 0), 1, fill=False, edgecolor="#7a7a7a", linestyle="--", linewidth=1.0)
    for patch in (*tubes, bound):
        ax.add_patch(patch)
    (slab,) = ax.plot([], [], color="#7a7a7a", linestyle=":", linewidth=1.0, label="bound: sphere R + r and slab |z| ≤ r")
    (ray_line,) = ax.plot([], [], color=style.PALETTE["curve"], linewidth=1.6, label="ray")
    (hit_dots,) = ax.plot([], [], "o", color="#b3261e", markersize=6, label="hits")
    (normal_lines,) = ax.plot([], [], color="#b3261e", linewidth=1.2)
    (origin_dot,) = ax.plot([], [], "o", color="#333333", markersize=8, label="origin (drag me)")
    ax.legend(loc="lower left", fontsize=7)

    def update(ox, oz, angle, R, r):
        torus = S.Torus([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], R, r)
        o = np.array([ox, 0.0, oz])
        d = np.array([np.cos(np.radians(angle)), 0.0, np.sin(np.radians(angle))])
        all_t = torus.hits(o, d)[0]               # (and counts the quartics solved)
        solved = torus.quartics_solved == 1
        t = all_t[np.isfinite(all_t) & (all_t > S.EPS)]
        P = o + t[:, None] * d
        N = torus.normal(P) if len(P) else np.zeros((0, 3))
        for patch, x in zip(tubes, (-R, R)):
            patch.set_center((x, 0.0)), patch.set_radius(r)
        bound.set_radius(R + r)
        w = float(np.sqrt(max((R + r) ** 2 - r * r, 0.0)))
        slab.set_data([-w, w, np.nan, -w, w], [r, r, np.nan, -r, -r])
        ray_line.set_data([ox, ox + 12 * d[0]], [oz, oz + 12 * d[2]])
        hit_dots.set_data(P[:, 0], P[:, 2])
        seg = np.full((3 * len(P), 2), np.nan)
        seg[0::3], seg[1::3] = P[:, [0, 2]], P[:, [0, 2]] + 0.5 * N[:, [0, 2]]
        normal_lines.set_data(seg[:, 0], seg[:, 1])
        origin_dot.set_data([ox], [oz])
        if not solved:
            status = "the ray misses the bounding sphere or meets it only outside the slab |z| <= r: the quartic is skipped"
        else:
            status = (f"the ray passes the bound: the quartic is solved; {len(t)} hit(s) in front of the origin"
                      + (f" at t = {', '.join(f'{v:.3f}' for v in t)}" if len(t) else " (it goes through the hole or "
                                                                                        "past the tube)"))
        return {"hits": P, "normals": N, "t": t, "solved": solved, "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§19.6 a ray and a torus, with the bounding test", side=True)
    drag_sliders(view, ax, [("ox", "oz")])
    return view

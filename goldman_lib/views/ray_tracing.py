"""The view of chapter 17 (Goldman, recursive ray tracing): the ray-traced picture of the chapter's
scene beside a side view of one pixel's ray tree.

Left, the image :func:`goldman_lib.ray_tracing.render` makes of
:func:`goldman_lib.ray_tracing.default_scene` (built once with ``imshow``; a slider replaces its
data).  Right, the scene seen from the side (the x-z plane: the camera looks along +x): the floor,
the spheres' outlines, the eye, the light, and the ray tree of the chosen pixel
(:func:`goldman_lib.ray_tracing.ray_tree`) -- the primary ray, the reflected and refracted rays
level by level, and the shadow rays towards the light (dashed; red where blocked, violet where they
pass the glass sphere, which lets ``k_t`` of the light through).  Choose the
pixel with its sliders or by clicking the image; drag the light in the side view (or use its
sliders: the shared :class:`~goldman_lib.views.light_control.LightControl`).  The depth slider
sets the recursion depth, the index slider the glass sphere's index of refraction.

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
from goldman_lib.simple_surfaces import Plane, Sphere
from goldman_lib.validation import as_float, as_int
from goldman_lib.views import style
from goldman_lib.views.interactive import InteractiveView, figure_widget, float_slider, int_slider
from goldman_lib.views.light_control import LightControl

__all__ = ["ray_tracing_view", "image_strip", "WIDTH", "HEIGHT", "KIND_COLOURS", "KINDS"]

#: The default image size of the view (a full re-render per slider move stays under 100 ms).
WIDTH, HEIGHT = 160, 120
#: How each kind of ray is drawn in the side view.
KIND_COLOURS = {"primary": "#1f4e9c", "reflected": "#1b7f3b", "refracted": "#8f2d56", "shadow": "#edae49"}
#: The kinds of rays, in the order of the codes in an update's ``"kinds"``.
KINDS = tuple(KIND_COLOURS)
_BLOCKED = "#d1495b"
_THROUGH_GLASS = "#9b5de5"
_CACHE = 24


def _circle(center, radius, n=73):
    a = np.linspace(0, 2 * np.pi, n)
    return center[0] + radius * np.cos(a), center[2] + radius * np.sin(a)


def image_strip(images, titles=None, width: float = 2.6) -> bytes:
    """A static picture (PNG bytes) of rendered images side by side, each ``width`` inches wide with
    its title: for comparing renders (depths, lights, indices) in a notebook.

    >>> image_strip([np.zeros((4, 6, 3)), np.ones((4, 6, 3))], ["black", "white"])[:4]
    b'\\x89PNG'
    """
    from matplotlib.figure import Figure

    from goldman_lib.views.interactive import figure_png

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
    of pixel ``(px, py)`` (column from the left, row from the top) in a side view (right, the x-z
    plane), where the light can be dragged.

    ``update(depth, index, px, py, light0_x, light0_y, light0_z, light0_I, light0_colour)`` returns
    ``{"image" (120, 160, 3), "segments" (n, 2, 2) side-view ends, "kinds" (n,) codes into
    :data:`KINDS`, "blocked" (n,)
    booleans (a shadow ray no light passes), "pixel" (3,), "rays", "status"}``.

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
        **control.controls,
    }
    camera = rt.default_camera()
    scene0 = rt.default_scene(index=index)

    fig = style.new_figure(style.WIDE_FIGSIZE)
    ax_img = fig.add_axes([0.01, 0.08, 0.44, 0.84])
    ax_side = fig.add_axes([0.52, 0.1, 0.46, 0.82])
    image = ax_img.imshow(np.zeros((HEIGHT, WIDTH, 3)), origin="upper", interpolation="nearest",
                          extent=(-0.5, WIDTH - 0.5, HEIGHT - 0.5, -0.5))
    ax_img.set_xticks([]), ax_img.set_yticks([])
    (pixel_mark,) = ax_img.plot([], [], "s", markersize=9, markerfacecolor="none", markeredgecolor="#ff00ff",
                                markeredgewidth=1.5)
    img_title = ax_img.set_title("", fontsize=9)

    style.style_axes(ax_side)
    ax_side.set_xlim(-7.6, 4.2), ax_side.set_ylim(-0.6, 6.9)
    ax_side.set_xlabel("x", fontsize=8), ax_side.set_ylabel("z", fontsize=8)
    ax_side.tick_params(labelsize=7)
    ax_side.set_xticks([-6, -3, 0, 3]), ax_side.set_yticks([0, 2, 4, 6])
    for obj in scene0.objects:
        if isinstance(obj, Plane):
            ax_side.axhspan(-0.6, 0.0, color="#d8d4c8", zorder=0)
        elif isinstance(obj, Sphere):
            c = obj.material.colour
            face = (*c, 0.25 if obj.material.transmit > 0 else 0.5)
            ax_side.fill(*_circle(obj.center, obj.radius), facecolor=face, edgecolor="#555555", linewidth=0.8,
                         zorder=1)
    ax_side.plot([camera.eye[0]], [camera.eye[2]], "o", color="#222222", markersize=6, zorder=4)
    ax_side.annotate("eye", (camera.eye[0], camera.eye[2]), textcoords="offset points", xytext=(-6, 8), fontsize=8)
    from matplotlib.collections import LineCollection

    lines = LineCollection([], linewidths=1.6, zorder=3)
    ax_side.add_collection(lines)
    (light_dot,) = ax_side.plot([], [], "o", color="#f2b700", markeredgecolor="#7a5c00", markersize=11, zorder=5)
    legend = widgets.HTML(" &nbsp;".join(
        [f"<span style='color:#c99a00'>&#9679; light (drag it)</span>"]
        + [f"<span style='color:{c}'>{'- -' if k == 'shadow' else '&#9472;&#9472;'} {k}</span>"
           for k, c in KIND_COLOURS.items()]
        + [f"<span style='color:{_BLOCKED}'>- - blocked shadow</span>",
           f"<span style='color:{_THROUGH_GLASS}'>- - shadow through glass (k_t of the light)</span>"]))
    side_title = ax_side.set_title("", fontsize=9)

    images: OrderedDict = OrderedDict()

    def picture(depth, index, lights):
        key = (depth, index, tuple((lt.position, lt.colour, lt.intensity) for lt in lights))
        if key in images:
            images.move_to_end(key)
            return images[key]
        scene = rt.default_scene(index=index, lights=lights)
        counts: dict = {}
        img = rt.render(scene, camera, WIDTH, HEIGHT, depth, counts=counts)
        images[key] = (scene, img, counts)
        while len(images) > _CACHE:
            images.popitem(last=False)
        return images[key]

    def update(depth, index, px, py, **light_values):
        lights = control.lights(light_values)
        scene, img, counts = picture(depth, index, lights)
        tree = rt.ray_tree(scene, camera, px, py, depth, WIDTH, HEIGHT, miss_length=4.0)
        image.set_data(img)
        pixel_mark.set_data([px], [py])
        seg = np.array([[s.start[[0, 2]], s.end[[0, 2]]] for s in tree]).reshape(-1, 2, 2)
        kinds = [s.kind for s in tree]
        blocked = np.array([s.kind == "shadow" and s.light == 0 for s in tree], dtype=bool)
        through = np.array([s.kind == "shadow" and s.hit and s.light > 0 for s in tree], dtype=bool)
        lines.set_segments(list(seg))
        lines.set_color([_BLOCKED if b else _THROUGH_GLASS if g else KIND_COLOURS[k]
                         for k, b, g in zip(kinds, blocked, through)])
        lines.set_linestyle(["--" if k == "shadow" else "-" for k in kinds])
        marker = control.marker_positions(light_values)[0]
        light_dot.set_data([marker[0]], [marker[2]])
        n = {k: kinds.count(k) for k in KIND_COLOURS}
        crit = rt.critical_angle(index, 1.0)
        img_title.set_text(f"depth {depth}, glass index {index:.2f}")
        side_title.set_text(f"side view (x-z): ray tree of pixel ({px}, {py})")
        status = (f"{WIDTH}x{HEIGHT} image at recursion depth {depth}: {counts['rays']:,} primary, reflected and "
                  f"refracted rays and {counts['shadow']:,} shadow rays.  Pixel ({px}, {py}): {n['primary']} primary, "
                  f"{n['reflected']} reflected, {n['refracted']} refracted and {n['shadow']} shadow rays "
                  f"({int(blocked.sum())} blocked, {int(through.sum())} through glass); at most {rt.ray_tree_size(depth, len(lights))} at this depth.  "
                  f"Glass index {index:.2f}: critical angle "
                  + (f"{crit:.1f}° (inside the glass)" if crit is not None else "none (no total internal reflection)"))
        pixel = np.asarray(img[py, px], dtype=float)
        codes = np.array([KINDS.index(k) for k in kinds], dtype=int)
        return {"image": img, "segments": seg, "kinds": codes, "blocked": blocked, "pixel": pixel,
                "rays": counts["rays"], "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig), legend], update=update, figure=fig,
                           title="§17.2-17.5 recursive ray tracing: the image and one pixel's ray tree",
                           arrange=[widgets.HBox([widgets.VBox([controls["depth"], controls["index"],
                                                                controls["px"], controls["py"]]),
                                                  widgets.VBox(list(control.controls.values()))])])
    control.drag_in(view, ax_side, plane="xz")

    def on_click(event):
        if event.inaxes is not ax_img or event.xdata is None or event.ydata is None:
            return
        view.set_values(px=int(np.clip(round(event.xdata), 0, WIDTH - 1)),
                        py=int(np.clip(round(event.ydata), 0, HEIGHT - 1)))

    view.click_cid = fig.canvas.mpl_connect("button_press_event", on_click)
    view.light_control = control
    view.axes = (ax_img, ax_side)
    return view

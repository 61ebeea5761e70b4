"""The views of chapter 16 (Goldman, colour and intensity): a shaded sphere whose every pixel is lit
by :func:`goldman_lib.lighting.intensity` (material sliders, the light-position control, the light
dragged in a side view), the ambient, diffuse and specular terms side by side with their total under
two lights (§16.3-16.6, clipping shown), and the mixing of red, green and blue light on a wall
(§16.2).

Pictures are ray cast: a camera at :data:`EYE` looks down the z-axis through a square window of the
plane z = 0, and :meth:`goldman_lib.simple_surfaces.Sphere.hit` gives each pixel's point and unit
normal (once per image size: the geometry does not move); a slider move then calls
:mod:`goldman_lib.lighting` on those points and puts the result into the image with ``set_data``.
This module only draws.

>>> view = shaded_sphere_view(size=64)
>>> r = view.set_values(ka=0.0, kd=1.0, ks=0.0, light0_x=0.0, light0_y=0.0, light0_z=6.0)
>>> bool(r["image"].max() <= 1.0), bool(abs(r["highlight"][2] - 1.0) < 0.05)   # brightest at the top
(True, True)
"""

from __future__ import annotations

import functools

import ipywidgets as widgets
import numpy as np

from goldman_lib import lighting
from goldman_lib.camera import Camera
from goldman_lib.lighting import Light, Material
from goldman_lib.simple_surfaces import Sphere
from goldman_lib.validation import within_budget
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import InteractiveView, figure_widget, float_slider
from goldman_lib.widgets.light_control import LightControl

__all__ = ["shaded_sphere_view", "terms_view", "rgb_mixing_view", "EYE", "WINDOW", "SPHERE", "BACKGROUND",
           "sphere_pixels", "wall_pixels", "camera", "FULL_SIZE", "FULL_SAMPLES"]

#: Where the camera is: on the z-axis, looking down at the unit sphere at the origin.
EYE = np.array([0.0, 0.0, 6.0])
#: Half the side of the square window (in the plane z = 0) the camera looks through.
WINDOW = 1.25
#: The sphere every chapter-16 picture shades.
SPHERE = Sphere([0.0, 0.0, 0.0], 1.0)
#: The colour of pixels whose ray misses the sphere.
BACKGROUND = np.array([0.13, 0.13, 0.16])
#: Largest image side (pixels) a view may be asked for.
MAX_SIZE = 400
#: The full-size picture a render button makes (width, height) and its anti-aliasing (samples x samples rays).
FULL_SIZE = (640, 480)
FULL_SAMPLES = 2


def camera(size: int | None = None) -> Camera:
    """The views' camera (a :class:`goldman_lib.camera.Camera`): at :data:`EYE`, looking at the sphere's
    centre, y up.  ``size=None``: its vertical field of view is the window ``[-WINDOW, WINDOW]`` of the
    plane z = 0, edge to edge (what :func:`goldman_lib.ray_tracing.ray_cast` renders at full size).
    ``size=n``: the ``n`` x ``n`` camera of the interactive pictures (:func:`sphere_pixels`), whose
    outermost pixel *centres* lie on the window's edges -- the field of view widened by ``n / (n - 1)``,
    the pictures' framing since chapter 16 was written (pixel k of n centred at ``-WINDOW + k * 2 WINDOW
    / (n - 1)`` on the plane z = 0).

    >>> camera().fov == camera(160).fov, camera(160).width
    (False, 160)
    """
    if size is None:
        return Camera.framing(EYE, (0.0, 0.0, 0.0), WINDOW, up=(0.0, 1.0, 0.0))
    size = _size(size)
    half = WINDOW * size / (size - 1)                   # the window's half-side at the pixels' outer edges
    return Camera.framing(EYE, (0.0, 0.0, 0.0), half, up=(0.0, 1.0, 0.0), width=size, height=size)


def _size(size, name="size") -> int:
    size = within_budget(size, name, cost=lambda n: n * n, what="the image", unit="pixels", limit=MAX_SIZE ** 2,
                         minimum=0)
    if size < 8:
        raise ValueError(f"{name} must be >= 8 pixels; got {size}")
    return size


@functools.lru_cache(maxsize=8)
def sphere_pixels(size: int):
    """The pixels of a ``size`` x ``size`` picture of :data:`SPHERE` seen from :data:`EYE` (the rays of
    ``camera(size)``, through the window ``[-WINDOW, WINDOW]^2`` of the plane z = 0, top row first):
    ``(found (size, size) bool, points (m, 3), normals (m, 3))``, the hit point and the sphere's unit
    normal there for each pixel whose ray hits (:meth:`Sphere.hit`).  Cached per size."""
    size = _size(size)
    eye, directions = camera(size).rays()               # the one place a pixel becomes a ray
    directions = directions.reshape(-1, 3)
    t, normals = SPHERE.hit(eye, directions)
    found = np.isfinite(t)
    points = EYE + t[found, None] * directions[found]
    for arr in (found, points, normals):
        arr.setflags(write=False)
    return found.reshape(size, size), points, normals[found]


@functools.lru_cache(maxsize=4)
def wall_pixels(size: int, half: float = 1.5):
    """The points of a ``size`` x ``size`` grid on the wall z = 0 over ``[-half, half]^2`` (top row
    first) and its normal (0, 0, 1) at each: ``(points (size*size, 3), normals (size*size, 3))``."""
    size = _size(size)
    xs = np.linspace(-half, half, size)
    X, Y = np.meshgrid(xs, xs[::-1])
    points = np.stack([X, Y, np.zeros_like(X)], axis=-1).reshape(-1, 3)
    normals = np.broadcast_to([0.0, 0.0, 1.0], points.shape).copy()
    for arr in (points, normals):
        arr.setflags(write=False)
    return points, normals


def _rgb(value, name: str) -> tuple:
    from matplotlib.colors import to_rgb

    try:
        return to_rgb(value)
    except (ValueError, TypeError):
        raise ValueError(f"{name} must be a colour such as '#ff8800'; got {value!r}") from None


def _material_controls(ka, kd, ks, exponent, colour, ambient_light):
    return {
        "ka": float_slider("k_a", ka, 0.0, 1.0, 0.01),
        "kd": float_slider("k_d", kd, 0.0, 1.0, 0.01),
        "ks": float_slider("k_s", ks, 0.0, 1.0, 0.01),
        "n": float_slider("n", exponent, 1.0, 200.0, 1.0, readout=".0f"),
        "colour": widgets.ColorPicker(value=colour, description="colour", concise=False,
                                      style={"description_width": "48px"}, layout=widgets.Layout(width="290px")),
        "Ia": float_slider("I_a", ambient_light, 0.0, 1.0, 0.01),
    }


def _picture(found, values):
    """The RGB picture: the background where rays miss, ``values`` (clipped) where they hit."""
    image = np.empty(found.shape + (3,))
    image[...] = BACKGROUND
    image[found] = lighting.to_image(values)
    return image


def _fmt(p) -> str:
    return "(" + ", ".join(f"{v + 0.0:.1f}" for v in p) + ")"


# -- §16.3-16.5: the shaded sphere --------------------------------------------------------------------

def shaded_sphere_view(ka: float = 0.15, kd: float = 0.7, ks: float = 0.5, exponent: float = 30.0,
                       colour: str = "#d1495b", ambient_light: float = 1.0, size: int = 160) -> InteractiveView:
    """A unit sphere lit by one point light through :func:`goldman_lib.lighting.intensity` (Goldman
    §16.3-16.6): every pixel of the ``size`` x ``size`` picture is a ray from the eye, its point and
    normal from :meth:`Sphere.hit`.  Sliders for the material (``k_a``, ``k_d``, ``k_s``, the
    exponent ``n``, the colour) and the ambient light ``I_a``; the light-position control (x, y, z,
    intensity, colour) and a check box "clamp L·N at 0" (on: the lighting model of §16.4; off: the
    slip it prevents, a light behind the surface subtracting light and leaking a highlight there).
    Beside the picture a side view of the xz-plane shows the sphere, the eye and
    the light, which can be dragged there with the mouse; the brightest pixel (the highlight) is
    marked in both.

    ``update(**values)`` returns ``{"image" (size, size, 3), "intensity" (m, 3) unclipped,
    "highlight" (3,), "light" (3,), "clipped" (fraction of sphere pixels over 1), "status"}``.

    ``view.render_full(progress, size=FULL_SIZE, samples=FULL_SAMPLES, clamp=True, **values)`` is the
    full-size picture of the view's state (the function a
    :class:`goldman_lib.widgets.render_control.RenderControl` calls): the same sphere, material and
    light ray cast by :func:`goldman_lib.ray_tracing.ray_cast` at 640 x 480, 2 x 2 anti-aliased.
    """
    size = _size(size)
    found, points, normals = sphere_pixels(size)
    light = LightControl([Light((3.0, 2.0, 5.0))], box=(-6.0, 6.0))
    controls = {**_material_controls(ka, kd, ks, exponent, colour, ambient_light),
                "clamp": widgets.Checkbox(value=True, description="clamp L·N at 0 (§16.4)", indent=False),
                **light.controls}
    fig = style.new_figure(style.WIDE_FIGSIZE)
    ax_img = fig.add_subplot(1, 2, 1)
    ax_side = fig.add_subplot(1, 2, 2)
    im = ax_img.imshow(_picture(found, np.zeros((len(points), 3))), extent=(-WINDOW, WINDOW, -WINDOW, WINDOW),
                       interpolation="nearest")
    ax_img.set_title("what the eye sees (x right, y up)", fontsize=10)
    ax_img.set_xticks([]), ax_img.set_yticks([])
    (hi_img,) = ax_img.plot([], [], "+", color="#ffffff", markersize=10, markeredgewidth=1.5)
    style.style_axes(ax_side)
    ax_side.set_xlim(-6.5, 6.5), ax_side.set_ylim(-6.5, 7.0)
    circle = np.linspace(0, 2 * np.pi, 121)
    ax_side.fill(np.cos(circle), np.sin(circle), color="#f1c5cb", edgecolor="#d1495b", linewidth=1.2)
    ax_side.plot([EYE[0]], [EYE[2]], "s", color="#333333", markersize=7)
    ax_side.annotate("eye", (EYE[0], EYE[2]), textcoords="offset points", xytext=(6, -3), fontsize=9)
    ax_side.plot([-WINDOW, WINDOW], [0, 0], color="#999999", linewidth=0.8, linestyle=":")
    (to_light,) = ax_side.plot([], [], color=style.PALETTE["accent"], linewidth=1.0, linestyle="--")
    (to_eye,) = ax_side.plot([], [], color="#555555", linewidth=0.8, linestyle="--")
    (hi_side,) = ax_side.plot([], [], "o", color="#ffffff", markeredgecolor="#333333", markersize=6)
    (lamp,) = ax_side.plot([], [], "o", color="#f2b700", markeredgecolor="#8a6d00", markersize=12,
                           label="light (drag me)")
    ax_side.legend(loc="lower left", fontsize=8)
    ax_side.set_xlabel("x"), ax_side.set_ylabel("z")
    ax_side.set_title("side view (the xz-plane)", fontsize=10)
    fig.tight_layout()

    def update(ka, kd, ks, n, colour, Ia, clamp=True, **light_values):
        material = Material(colour=_rgb(colour, "colour"), ambient=ka, diffuse=kd, specular=ks, exponent=n)
        lights = light.lights(light_values)
        values = lighting.intensity(points, normals, EYE, lights, material, ambient_light=Ia, clamp=bool(clamp))
        image = _picture(found, values)
        im.set_data(image)
        brightness = values.sum(axis=1)
        k = int(np.argmax(brightness))
        hp = points[k]
        hi_img.set_data([hp[0]], [hp[1]])
        hi_side.set_data([hp[0]], [hp[2]])
        L = np.array(lights[0].position)
        lamp.set_data([L[0]], [L[2]])
        to_light.set_data([hp[0], L[0]], [hp[2], L[2]])
        to_eye.set_data([hp[0], EYE[0]], [hp[2], EYE[2]])
        clipped = float(np.mean(values.max(axis=1) > 1.0))
        inside = bool(np.dot(L, L) <= 1.0)
        status = (f"light at {_fmt(L)}: brightest pixel {values[k].max():.2f} at {_fmt(hp)} on the sphere; "
                  f"{100 * clipped:.1f}% of the sphere's pixels are over 1 in some channel and are clipped")
        if inside:
            status = "the light is inside the sphere: no outside point sees it, only the ambient term is left; " + status
        if not clamp:
            facing_away = float(np.mean(lighting.diffuse(points, normals, L, 1.0, 1.0, clamp=False) < 0))
            status = (f"L·N is not clamped: on the {100 * facing_away:.0f}% of the sphere's pixels the light is behind, "
                      f"the diffuse term is negative and subtracts light, and a highlight can leak there (§16.4); "
                      + status)
        return {"image": image, "intensity": values, "highlight": hp, "light": L, "clipped": clipped,
                "status": status}

    material_box = widgets.VBox([controls[k] for k in ("ka", "kd", "ks", "n", "colour", "Ia", "clamp")])
    light_box = widgets.VBox(list(light.controls.values()))
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§16.3-16.6 a sphere lit pixel by pixel",
                           arrange=[widgets.HBox([material_box, light_box])])
    light.drag_in(view, ax_side, plane="xz")
    view.light_control = light
    style.pin_layout(fig)       # fixed limits: titles and labels need not be placed again at each redraw
    # axes, legend, titles and the eye's label stay as they are: rendered once, pasted at each redraw
    style.freeze_axes_decorations(ax_img, ax_img.title)
    style.freeze_axes_decorations(ax_side, ax_side.title, *ax_side.texts)

    def render_full(progress=None, size=FULL_SIZE, samples=FULL_SAMPLES, clamp=True, *, ka, kd, ks, n, colour, Ia,
                    **light_values):
        from goldman_lib import ray_tracing as rt

        material = Material(colour=_rgb(colour, "colour"), ambient=ka, diffuse=kd, specular=ks, exponent=n)
        scene = rt.Scene([Sphere(SPHERE.center, SPHERE.radius, material)], light.lights(light_values),
                         ambient_light=Ia, background=BACKGROUND)
        return rt.ray_cast(scene, camera(), size[0], size[1], samples=samples, clamp=clamp, progress=progress)

    view.render_full = render_full
    return view


# -- §16.3-16.6: the terms side by side, two lights -----------------------------------------------------

TERMS = ("ambient", "diffuse", "specular", "total")


def terms_view(ka: float = 0.2, kd: float = 0.6, ks: float = 0.6, exponent: float = 20.0,
               colour: str = "#3d7dd8", ambient_light: float = 1.0, size: int = 110) -> InteractiveView:
    """The three terms of the lighting model and their sum, side by side on the same sphere (Goldman
    §16.3-16.6), under two point lights (the light-position control with two lights): the ambient
    term ``I_a k_a C``, the diffuse terms ``sum I_p k_d C (L . N)``, the specular terms
    ``sum I_p k_s (R . V)^n`` (each from :func:`goldman_lib.lighting.intensity` with the other
    coefficients set to 0) and their sum, the total.  Pixels of the total over 1 are clipped (§16.6): the status
    says how many.

    ``update(**values)`` returns ``{"ambient", "diffuse", "specular", "total"}`` (each (m, 3)
    unclipped, per sphere pixel), ``"images"`` (4, size, size, 3), ``"clipped"`` and ``"status"``.
    """
    size = _size(size)
    found, points, normals = sphere_pixels(size)
    light = LightControl([Light((3.0, 2.0, 5.0)), Light((-5.0, -1.0, 2.0), colour=(1.0, 0.85, 0.6), intensity=0.6)],
                         box=(-6.0, 6.0))
    controls = {**_material_controls(ka, kd, ks, exponent, colour, ambient_light), **light.controls}
    fig = style.new_figure((9.6, 2.9))
    axes = [fig.add_subplot(1, 4, k + 1) for k in range(4)]
    images, titles = [], []
    blank = _picture(found, np.zeros((len(points), 3)))
    for ax, name in zip(axes, TERMS):
        images.append(ax.imshow(blank, extent=(-WINDOW, WINDOW, -WINDOW, WINDOW), interpolation="nearest"))
        ax.set_xticks([]), ax.set_yticks([])
        titles.append(ax.set_title(name, fontsize=10))
    fig.tight_layout()

    def update(ka, kd, ks, n, colour, Ia, **light_values):
        c = _rgb(colour, "colour")
        lights = light.lights(light_values)
        parts = {"ambient": np.broadcast_to(lighting.ambient(ka, Ia) * np.asarray(c), points.shape)}
        for name, coeffs in (("diffuse", (kd, 0.0)), ("specular", (0.0, ks))):
            material = Material(colour=c, ambient=0.0, diffuse=coeffs[0], specular=coeffs[1], exponent=n)
            parts[name] = lighting.intensity(points, normals, EYE, lights, material, ambient_light=0.0)
        parts["total"] = parts["ambient"] + parts["diffuse"] + parts["specular"]
        pictures = []
        for k, name in enumerate(TERMS):
            pictures.append(_picture(found, parts[name]))
            images[k].set_data(pictures[-1])
            titles[k].set_text(f"{name}: max {parts[name].max():.2f}")
        clipped = float(np.mean(parts["total"].max(axis=1) > 1.0))
        status = (f"total = ambient + diffuse + specular at every pixel; its largest channel is "
                  f"{parts['total'].max():.2f}: {100 * clipped:.1f}% of the sphere's pixels are over 1 and are "
                  f"clipped to 1 (§16.6)")
        return {**parts, "images": np.stack(pictures), "clipped": clipped, "status": status}

    material_box = widgets.VBox([controls[k] for k in ("ka", "kd", "ks", "n", "colour", "Ia")])
    boxes = [widgets.VBox([light.controls[light.name(k, p)] for p in ("x", "y", "z", "I", "colour")])
             for k in range(2)]
    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§16.3-16.6 ambient + diffuse + specular = total (two lights)",
                           arrange=[widgets.HBox([material_box] + boxes)])
    view.light_control = light
    return view


# -- §16.2: red, green and blue light on a wall ---------------------------------------------------------

#: Where the three coloured lights stand over the wall (x, y), at the corners of a triangle.
MIX_POSITIONS = np.array([[0.0, 0.4], [-0.2 * np.sqrt(3), -0.2], [0.2 * np.sqrt(3), -0.2]])   # radius 0.4


def rgb_mixing_view(height: float = 0.3, intensity: float = 1.6, wall: str = "#ffffff", size: int = 100) -> InteractiveView:
    """Additive colour mixing (Goldman §16.2): a red, a green and a blue point light over a wall
    (the plane z = 0, seen from the front, a ``size`` x ``size`` grid of points), the wall lit by Lambert's diffuse term through
    :func:`goldman_lib.lighting.intensity`.  Where two lights overlap their colours add (red + green
    = yellow, green + blue = cyan, red + blue = magenta, all three white); the wall's colour then
    multiplies the light channel by channel (a yellow wall under blue light is black).  Each light's
    x, y, z and intensity have sliders, and each light can be dragged over the wall with the mouse.

    ``update(**values)`` returns ``{"image" (size, size, 3) clipped, "centre" (3,) unclipped,
    "lights" (3, 3), "status"}``.
    """
    size = _size(size)
    points, normals = wall_pixels(size)
    lights = [Light((x, y, height), colour=c, intensity=intensity)
              for (x, y), c in zip(MIX_POSITIONS, ((1, 0, 0), (0, 1, 0), (0, 0, 1)))]
    light = LightControl(lights, box=((-1.5, 1.5), (-1.5, 1.5), (0.05, 2.0)), intensity_range=(0.0, 3.0),
                         colour=False)
    controls = {"wall": widgets.ColorPicker(value=wall, description="wall", concise=False,
                                            style={"description_width": "48px"},
                                            layout=widgets.Layout(width="290px")),
                **light.controls}
    fig, ax = style.new_axes()
    ax.grid(False)
    im = ax.imshow(np.zeros((size, size, 3)), extent=(-1.5, 1.5, -1.5, 1.5), interpolation="bilinear")
    markers = ax.scatter(MIX_POSITIONS[:, 0], MIX_POSITIONS[:, 1], s=70, c=["#ff0000", "#00ff00", "#0000ff"],
                         edgecolors="#ffffff", linewidths=1.5, zorder=3)
    ax.set_xlabel("x"), ax.set_ylabel("y")
    ax.set_title("three coloured lights on a wall (drag them)", fontsize=10)
    fig.tight_layout()

    def update(wall, **light_values):
        material = Material(colour=_rgb(wall, "wall"), ambient=0.0, diffuse=1.0, specular=0.0)
        lit = light.lights(light_values)
        values = lighting.intensity(points, normals, EYE, lit, material, ambient_light=0.0)
        image = lighting.to_image(values).reshape(size, size, 3)
        im.set_data(image)
        where = light.marker_positions(light_values)
        markers.set_offsets(where[:, :2])
        centre = lighting.intensity([[0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]], EYE, lit, material, ambient_light=0.0)[0]
        status = (f"at the centre of the wall the light is RGB ({centre[0]:.2f}, {centre[1]:.2f}, {centre[2]:.2f}): "
                  f"each channel the sum of what the lights give it, times the wall's colour")
        return {"image": image, "centre": centre, "lights": where, "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§16.2 RGB: coloured lights add, a coloured surface filters", side=True)
    light.drag_in(view, ax, plane="xy")
    view.light_control = light
    style.pin_layout(fig)       # fixed limits: the title and labels need not be placed again at each redraw
    style.freeze_axes_decorations(ax, ax.title)   # axes and title: rendered once, pasted at each redraw
    return view

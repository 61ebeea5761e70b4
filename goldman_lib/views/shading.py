"""The view of chapter 21 (Goldman, shading): one polygonal sphere rendered by the course's software
rasteriser in two shading modes side by side (§21.2 uniform, §21.3 Gouraud, §21.4 Phong, fast Phong,
Phong with slerp), lit by the shared light-position control.  The light is also a marker in a 2D
picture of the scene as the camera sees it (the xz plane; the camera looks along +y), where the mouse
drags it.  Both images update in place (``imshow`` data), never by rebuilding the figure.

Every pixel comes from :func:`goldman_lib.shading.render`; this module only draws.

>>> view = shading_view()
>>> r = view.set_values(mode_a="uniform", mode_b="phong")
>>> r["images"].shape
(2, 128, 128, 3)
"""

from __future__ import annotations

import numpy as np

from goldman_lib import lighting, shading
from goldman_lib.views import style
from goldman_lib.views.interactive import InteractiveView, dropdown, figure_widget, float_slider, int_slider
from goldman_lib.views.light_control import LightControl

__all__ = ["shading_view", "plot_images", "MODE_LABELS", "SHADING_CAMERA"]

#: The shading modes as the picker shows them, with their sections.
MODE_LABELS = {"uniform": "uniform (§21.2)", "gouraud": "Gouraud (§21.3)", "phong": "Phong (§21.4.1)",
               "fast_phong": "fast Phong (§21.4.2-3)", "slerp": "Phong + slerp (§21.4.4)"}

#: Where the view's camera stands: on the -y axis looking at the origin, so its image is the xz plane.
SHADING_CAMERA = dict(eye=(0.0, -6.0, 0.0), target=(0.0, 0.0, 0.0), up=(0.0, 0.0, 1.0), fov=28.0)


def shading_view(mode_a: str = "gouraud", mode_b: str = "phong", facets: int = 8, exponent: float = 30.0,
                 size: int = 128) -> InteractiveView:
    """Two shading modes of one polygonal sphere side by side under a movable light (Goldman
    §21.2-21.4).  ``facets`` is the number of bands of latitude (the sphere has ``4 facets (facets - 1)``
    triangles): few facets show the faces of uniform shading, Gouraud's Mach bands and lost
    highlights, and how Phong and its fast and slerp variants keep the highlight round.

    ``update(mode_a, mode_b, facets, exponent, light0_x, ..., light0_colour)`` returns
    ``{"images" (2, size, size, 3), "light" (3,), "triangles", "status"}``.

    >>> r = shading_view(facets=4).set_values(light0_x=0.0, light0_z=0.0)
    >>> r["triangles"], r["light"].tolist()
    (48, [0.0, -4.0, 0.0])
    """
    size = int(size)
    control = LightControl([(2.5, -4.0, 3.0)], box=(-6.0, 6.0))
    options = [(label, key) for key, label in MODE_LABELS.items()]
    controls = {"mode_a": dropdown("left", options, mode_a), "mode_b": dropdown("right", options, mode_b),
                "facets": int_slider("facets", facets, 3, 24), "exponent": float_slider("n", exponent, 1.0, 120.0, 1.0)}
    controls.update(control.controls)
    camera = shading.Camera(width=size, height=size, **SHADING_CAMERA)

    fig = style.new_figure(figsize=(8.4, 2.9))
    ax_scene = fig.add_subplot(1, 3, 1)
    style.style_axes(ax_scene)
    ax_scene.set_xlim(-6, 6), ax_scene.set_ylim(-6, 6)
    ax_scene.set_xlabel("x"), ax_scene.set_ylabel("z")
    ax_scene.set_title("the scene from the eye (drag the light)", fontsize=9)
    angle = np.linspace(0, 2 * np.pi, 97)
    ax_scene.fill(np.cos(angle), np.sin(angle), facecolor="#d9d9d9", edgecolor="#7a7a7a", zorder=1,
                  label="the sphere")
    (marker,) = ax_scene.plot([], [], "o", color="#f2b700", markeredgecolor="#8a6d00", markersize=10, zorder=3,
                              label="light (drag me)")
    ax_scene.legend(loc="lower left", fontsize=8)
    axes, images, titles = [], [], []
    blank = np.zeros((size, size, 3))
    for k in range(2):
        ax = fig.add_subplot(1, 3, 2 + k)
        ax.set_axis_off()
        images.append(ax.imshow(blank, interpolation="nearest", vmin=0, vmax=1))
        titles.append(ax.set_title("", fontsize=9))
        axes.append(ax)
    fig.tight_layout()
    mesh_cache: dict = {}

    def mesh(n):
        if n not in mesh_cache:
            mesh_cache.clear()
            mesh_cache[n] = shading.uv_sphere(n, 2 * n)
        return mesh_cache[n]

    def update(mode_a, mode_b, facets, exponent, **light_values):
        V, T = mesh(int(facets))
        lights = control.lights(light_values)
        material = lighting.Material(colour=(0.85, 0.35, 0.25), ambient=0.25, diffuse=0.7, specular=0.5,
                                     exponent=exponent)
        out = []
        for image, title, mode in zip(images, titles, (mode_a, mode_b)):
            picture = shading.render(V, T, camera, lights, material, mode=mode, ambient_light=0.3,
                                     background=(1.0, 1.0, 1.0), cull_backfaces=True)
            image.set_data(picture)
            title.set_text(MODE_LABELS[mode])
            out.append(picture)
        position = control.marker_positions(light_values)[0]
        marker.set_data([position[0]], [position[2]])
        status = (f"{len(T)} triangles, {size}x{size} pixels each; light at ({position[0]:.1f}, {position[1]:.1f}, "
                  f"{position[2]:.1f}); left {MODE_LABELS[mode_a]}, right {MODE_LABELS[mode_b]}")
        return {"images": np.stack(out), "light": position, "triangles": len(T), "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§21.2-21.4 shading modes side by side")
    control.drag_in(view, ax_scene, plane="xz")
    style.pin_layout(fig)       # fixed limits: titles and labels need not be placed again at each redraw
    return view


def plot_images(images, titles=(), width: float = 2.4):
    """A row of rendered images (each (h, w, 3) in [0, 1]) with their titles, for a static picture.
    Returns the figure (show it with ``fig.canvas``).

    >>> fig = plot_images([np.zeros((4, 4, 3)), np.ones((4, 4, 3))], ["black", "white"])
    >>> len(fig.axes)
    2
    """
    images = list(images)
    if not images:
        raise ValueError("images must hold at least one image")
    titles = list(titles) + [""] * (len(images) - len(titles))
    fig = style.new_figure(figsize=(width * len(images), width + 0.3))
    for k, (image, title) in enumerate(zip(images, titles)):
        ax = fig.add_subplot(1, len(images), k + 1)
        ax.imshow(np.asarray(image), interpolation="nearest", vmin=0, vmax=1)
        ax.set_title(title, fontsize=9)
        ax.set_axis_off()
    fig.tight_layout()
    return fig

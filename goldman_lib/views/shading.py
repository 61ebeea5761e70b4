"""The view of chapter 21 (Goldman, shading): one polygonal sphere rendered by the course's software
rasteriser in two shading modes side by side (§21.2 uniform, §21.3 Gouraud, §21.4 Phong, fast Phong,
Phong with slerp), lit by the shared light-position control; and the Mach-band view, Gouraud beside
Phong with the intensity profile and its slope along one scan line across the mesh edges.  The light is also a marker in a 2D
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

from goldman_lib import lighting, rasteriser, shading
from goldman_lib.camera import Camera
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import InteractiveView, dropdown, figure_widget, float_slider, int_slider
from goldman_lib.widgets.light_control import LightControl

__all__ = ["shading_view", "mach_band_view", "plot_images", "MODE_LABELS", "SHADING_CAMERA", "MACH_LIGHT",
           "MACH_MATERIAL"]

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
    camera = Camera(width=size, height=size, **SHADING_CAMERA)

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
    # the scene's axes, legend and title stay as they are: rendered once, pasted at each redraw
    style.freeze_axes_decorations(ax_scene, ax_scene.title)
    return view


#: The light and the matte white material of the Mach-band view (a light in front, a little up and
#: to the left; no highlight: the profile's kinks come from the diffuse term alone).
MACH_LIGHT = (-1.0, -5.0, 1.0)
MACH_MATERIAL = dict(colour=(1.0, 1.0, 1.0), ambient=0.1, diffuse=0.9, specular=0.0)


def mach_band_view(row: int = 86, facets: int = 6, show: str = "Gouraud and Phong", size: int = 160) -> InteractiveView:
    """Mach bands, the failure and the fix (Goldman §21.3-21.4): a coarse polygonal sphere shaded by
    Gouraud and by Phong, each with the scan line ``row`` drawn across it, and beside them the
    intensity along that scan line and its slope per pixel (:func:`goldman_lib.shading.scanline_profile`),
    with the mesh edges it crosses marked (:func:`goldman_lib.shading.edge_slopes`).  Gouraud's
    intensity is linear on each face: its slope is a staircase that steps at every edge, kinks the
    eye exaggerates into bright and dark bands.  Phong's slope changes (nearly) continuously.
    ``show`` picks which profiles are drawn: both, or one of them.

    ``update(row, facets, show)`` returns ``{"images" (2, size, size, 3), "grey" (2, size),
    "slope" (2, size - 1), "edges" (k,), "jumps" (2, k), "status"}`` (index 0 Gouraud, 1 Phong).

    >>> r = mach_band_view().set_values(row=86)
    >>> k = int(np.argmin(abs(r["edges"] - 80)))        # the edge nearest the middle of the sphere
    >>> int(r["edges"][k]), bool(abs(r["jumps"][0, k]) > 5 * abs(r["jumps"][1, k]))
    (80, True)
    """
    size = int(size)
    choices = ["Gouraud and Phong", "Gouraud", "Phong"]
    if show not in choices:
        raise ValueError(f"show must be one of {choices}; got {show!r}")
    controls = {"row": int_slider("row", int(row), 0, size - 1), "facets": int_slider("facets", facets, 3, 16),
                "show": dropdown("show", choices, show)}
    camera = Camera(width=size, height=size, **SHADING_CAMERA)
    light = lighting.Light(MACH_LIGHT)
    material = lighting.Material(**MACH_MATERIAL)
    modes = ("gouraud", "phong")
    colours = {"gouraud": "#d1495b", "phong": "#2e6f95"}

    fig = style.new_figure(figsize=(9.6, 3.2))
    grid = fig.add_gridspec(2, 3, width_ratios=[1, 1, 1.5])
    images, lines = [], []
    blank = np.zeros((size, size, 3))
    for k, mode in enumerate(modes):
        ax = fig.add_subplot(grid[:, k])
        ax.set_axis_off()
        images.append(ax.imshow(blank, interpolation="nearest", vmin=0, vmax=1))
        ax.set_title(MODE_LABELS[mode], fontsize=9)
        lines.append(ax.axhline(row, color=colours[mode], linewidth=0.8))
    ax_grey = fig.add_subplot(grid[0, 2])
    ax_slope = fig.add_subplot(grid[1, 2], sharex=ax_grey)
    for ax in (ax_grey, ax_slope):
        style.style_axes(ax, equal=False)
        ax.set_xlim(0, size)
        ax.tick_params(labelsize=7)
    ax_grey.set_ylim(0, 1)
    ax_slope.set_ylim(-0.04, 0.04)
    ax_grey.set_ylabel("intensity", fontsize=8)
    ax_slope.set_ylabel("slope / pixel", fontsize=8)
    ax_slope.set_xlabel("x (pixels along the scan line)", fontsize=8)
    x = np.arange(size) + 0.5
    grey_lines = [ax_grey.plot(x, np.zeros(size), color=colours[m], linewidth=1.2, label=MODE_LABELS[m])[0] for m in modes]
    slope_lines = [ax_slope.step(x[1:], np.zeros(size - 1), where="mid", color=colours[m], linewidth=1.0)[0]
                   for m in modes]
    edge_marks = ax_slope.vlines([], -0.04, 0.04, colors="#9a9a9a", linewidth=0.6, linestyles="dotted",
                                 label="mesh edges")
    ax_grey.legend(loc="lower center", fontsize=7)
    ax_slope.legend(loc="lower right", fontsize=7)
    fig.tight_layout()
    style.pin_layout(fig)       # fixed limits: titles and labels need not be placed again at each redraw
    # the plots' axes and legends and the pictures' titles stay as they are: rendered once, pasted
    for ax in fig.axes:
        style.freeze_axes_decorations(ax, ax.title)
    mesh_cache: dict = {}

    def mesh(n):
        """The sphere of n bands, its triangle per pixel and its two renders (a row or show move
        re-renders nothing)."""
        if n not in mesh_cache:
            mesh_cache.clear()
            V, T = shading.uv_sphere(n, 2 * n)
            ids = rasteriser.rasterise_triangles(camera.project(V)[:, :3], T, size, size).triangle
            pictures = [shading.render(V, T, camera, light, material, mode=mode, ambient_light=0.3,
                                       background=(1.0, 1.0, 1.0)) for mode in modes]
            mesh_cache[n] = (ids, pictures)
        return mesh_cache[n]

    def update(row, facets, show):
        ids, rendered = mesh(int(facets))
        pictures, greys, slopes, jumps = [], [], [], []
        measured = shading.edge_slopes(np.zeros(size), ids[row])
        for k, mode in enumerate(modes):
            picture = rendered[k]
            grey, slope = shading.scanline_profile(picture, row)
            edges = shading.edge_slopes(grey, ids[row])
            images[k].set_data(picture)
            lines[k].set_ydata([row, row])
            drawn = show in ("Gouraud and Phong", MODE_LABELS[mode].split(" ")[0])
            grey_lines[k].set_ydata(grey)
            slope_lines[k].set_ydata(np.r_[slope, slope[-1:]][:size - 1])
            grey_lines[k].set_visible(drawn)
            slope_lines[k].set_visible(drawn)
            pictures.append(picture), greys.append(grey), slopes.append(slope), jumps.append(edges.jump)
        edge_marks.set_segments([[(c, -0.04), (c, 0.04)] for c in measured.columns])
        if len(measured.columns):
            k = int(np.argmin(np.abs(measured.columns - size / 2)))
            status = (f"row {row}: {len(measured.columns)} mesh edges measured; at the one nearest the middle "
                      f"(column {measured.columns[k]}) the slope jumps by {jumps[0][k]:+.4f} per pixel with Gouraud, "
                      f"{jumps[1][k]:+.4f} with Phong")
        else:
            status = f"row {row}: the scan line crosses no mesh edge with room on both sides to measure a slope"
        return {"images": np.stack(pictures), "grey": np.stack(greys), "slope": np.stack(slopes),
                "edges": measured.columns, "jumps": np.stack(jumps), "status": status}

    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§21.3-21.4 Mach bands: Gouraud's slope steps at the edges, Phong's does not")


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

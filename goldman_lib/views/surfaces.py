"""The views of chapter 18 (Goldman, surfaces: the general theory): a surface in three.js coloured by
its Gaussian or mean curvature (§18.4), with a picker of the surface and of the curvature, and a
slider that deforms the surface (a twist or a taper, §18.1) in place; a few normals of the deformed
surface are drawn, mapped by the inverse transpose of the deformation's Jacobian (§18.2).

Every number comes from :mod:`goldman_lib.surfaces`: the surfaces are its parametric forms, the
curvature of the deformed surface is :func:`~goldman_lib.surfaces.curvature_parametric` of the
composed map ``A(X(u, v))``, and the normals are :meth:`Deformation.normals`.  This module only
draws.  Two static pieces go with §18.3.3: :func:`normal_map_png`, a sheared sphere with its normals
mapped right (by the inverse transpose) and wrong (by the linear part itself), and
:func:`full_size_render`, the "render" control of a ray-traced scene at full size (issue 18 §4).

>>> view = curvature_view(resolution=16)
>>> r = view.set_values(surface="sphere", curvature="Gaussian K", amount=0.0)
>>> bool(abs(r["values"] - 1.0).max() < 1e-5)                # a unit sphere: K = 1 everywhere
True
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from goldman_lib import surfaces as sf
from goldman_lib.camera import Camera
from goldman_lib.widgets.interactive import InteractiveView, dropdown, float_slider, int_slider  # noqa: F401
from goldman_lib.widgets.three import SceneView

__all__ = ["curvature_view", "SURFACES", "CURVATURES", "DEFORMATIONS", "curvature_colours", "terrain_png",
           "SHEAR", "normal_map_png", "full_size_render"]

#: The surfaces of the picker (parametric forms from goldman_lib.surfaces), and what their curvature is.
SURFACES = {
    "sphere": (lambda: sf.parametric_sphere(1.0), "a sphere of radius 1: K = 1, |H| = 1 everywhere"),
    "cylinder": (lambda: sf.parametric_cylinder(0.7, 2.0), "a cylinder of radius 0.7: K = 0, |H| = 1/1.4"),
    "torus": (lambda: sf.parametric_torus(1.0, 0.4),
              "a torus R = 1, r = 0.4: K = cos v / (r (R + r cos v)), positive outside, negative inside"),
    "saddle": (lambda: sf.parametric_graph(lambda u, v: 0.6 * (u * u - v * v)),
               "the saddle z = 0.6 (x^2 - y^2): K < 0 everywhere, H = 0 at the centre"),
}
CURVATURES = ("Gaussian K", "mean H")
#: The deformations of the picker, each for an amount in [-1, 1].
DEFORMATIONS = {"twist about x": lambda a: sf.twist(120.0 * a, axis="x"), "taper along z": lambda a: sf.taper(0.6 * a)}


def curvature_colours(values, limit=None) -> tuple[np.ndarray, float]:
    """Colours ``(n, 3)`` of curvature values on a diverging map (blue negative, white 0, red
    positive), symmetric about 0 up to ``limit`` (default the largest ``|value|``, at least 1e-9);
    returns ``(colours, limit)``."""
    from matplotlib import colormaps

    v = np.asarray(values, dtype=float)
    lim = float(np.abs(v).max()) if limit is None else float(limit)
    lim = max(lim, 1e-9)
    rgb = colormaps["coolwarm"](0.5 + 0.5 * np.clip(v / lim, -1.0, 1.0))[:, :3]
    return np.clip(rgb, 0.0, 1.0), lim


def _deformed_X(X, A):
    def Y(u, v):
        P = np.asarray(X(u, v), dtype=float)
        return A.apply(P.reshape(-1, 3)).reshape(P.shape)
    return Y


def curvature_view(surface: str = "torus", curvature: str = "Gaussian K", deform: str = "twist about x",
                   amount: float = 0.0, resolution: int = 48) -> InteractiveView:
    """A surface coloured by its Gaussian curvature ``K`` or mean curvature ``H`` (Goldman §18.4) on a
    ``resolution x resolution`` grid of parameters, in three.js (blue ``< 0``, white ``0``, red
    ``> 0``; ``H`` with the sign convention of :mod:`goldman_lib.surfaces`: negative where the surface
    bends away from its outward normal).  Pickers choose the surface, the curvature and the
    deformation (twist about z or taper along z); the ``amount`` slider deforms the surface in place
    (positions and colours updated, never rebuilt): a twist about the x-axis or a taper along z.  Grey segments are normals of the deformed
    surface, the undeformed normals mapped by the inverse transpose of the Jacobian (§18.2).

    ``update(surface, curvature, deform, amount)`` returns ``{"positions" (n, 3), "values" (n,),
    "colours" (n, 3), "limit", "normals" (m, 3), "status"}``.
    """
    n = int(resolution)
    if not 8 <= n <= 160:
        raise ValueError(f"resolution must be in [8, 160]; got {resolution}")
    controls = {
        "surface": dropdown("surface", list(SURFACES), surface),
        "curvature": dropdown("colour", list(CURVATURES), curvature),
        "deform": dropdown("deform", list(DEFORMATIONS), deform),
        "amount": float_slider("amount", float(amount), -1.0, 1.0, 0.05),
    }
    built = {name: make() for name, (make, _) in SURFACES.items()}
    meshes = {name: s.grid_mesh(n) for name, s in built.items()}
    pos0, tri, _, _ = meshes[surface]
    k = max(2, n // 6)
    arrow = np.zeros((2 * ((n + k - 1) // k) ** 2, 3))
    scene = SceneView(width=480, height=380, camera_position=(2.6, -3.4, 2.6), axes=0)
    scene.add_mesh("surface", pos0, tri, colors=np.ones_like(pos0), lit=False)
    scene.add_segments("normals", arrow, np.arange(len(arrow)).reshape(-1, 2), color="#555555")
    legend = widgets.HTML("")

    def update(surface, curvature, deform, amount):
        s = built[surface]
        _, _, u, v = meshes[surface]
        A = DEFORMATIONS[deform](amount)
        Y = _deformed_X(s.X, A)
        P = s.point(u, v)
        Q = A.apply(P)
        H, K = sf.curvature_parametric(Y, u, v)
        values = K if curvature.startswith("Gaussian") else H
        colours, lim = curvature_colours(values)
        scene.set_mesh("surface", Q)
        scene.set_colors("surface", colours)
        pick = np.zeros((n, n), dtype=bool)
        pick[::k, ::k] = True
        pick = pick.ravel()
        normals = A.normals(P[pick], s.normal_at(u[pick], v[pick]))
        size = 0.12 * float(np.ptp(Q, axis=0).max())
        ends = np.empty((2 * pick.sum(), 3))
        ends[0::2], ends[1::2] = Q[pick], Q[pick] + size * normals
        scene.set_segments("normals", ends)
        _, what = SURFACES[surface]
        name = "K" if curvature.startswith("Gaussian") else "H"
        legend.value = (f"<span style='color:#3b4cc0'>&#9632; {name} = -{lim:.3g}</span> &nbsp; "
                        f"<span style='color:#999'>&#9632; 0</span> &nbsp; "
                        f"<span style='color:#b40426'>&#9632; {name} = +{lim:.3g}</span>")
        status = (f"{what}; {A.name if amount else 'undeformed'}: {name} ranges over "
                  f"[{values.min():.3g}, {values.max():.3g}] on the {n}x{n} grid")
        return {"positions": Q, "values": values, "colours": colours, "limit": lim, "normals": normals,
                "status": status}

    view = InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="§18.4 curvature of a (deformed) surface", side=True)
    view.scene = scene
    return view


def terrain_png(roughnesses=(0.35, 0.5, 0.7), level: int = 6, seed: int = 18) -> bytes:
    """The procedural surfaces of Goldman §18.1.4 drawn: one fractal terrain
    (:func:`goldman_lib.surfaces.fractal_heights` at ``level`` from ``seed``) per roughness, side by
    side, hill-shaded as if lit from the north-west (matplotlib's ``LightSource``) over a terrain
    colour map, with each panel's height range in its title.  A static picture (PNG bytes).

    >>> terrain_png((0.5,), level=3)[:4]
    b'\\x89PNG'
    """
    from matplotlib.colors import LightSource
    from matplotlib.figure import Figure

    from goldman_lib.widgets.interactive import figure_png

    roughnesses = [float(r) for r in roughnesses]
    if not 1 <= len(roughnesses) <= 6:
        raise ValueError(f"roughnesses must hold 1 to 6 values; got {len(roughnesses)}")
    fig = Figure(figsize=(3.2 * len(roughnesses), 3.4), dpi=100)
    light = LightSource(azdeg=315, altdeg=40)
    import matplotlib

    cmap = matplotlib.colormaps["terrain"]
    for k, r in enumerate(roughnesses):
        h = sf.fractal_heights(level, r, rng=seed)
        ax = fig.add_subplot(1, len(roughnesses), k + 1)
        span = float(h.max() - h.min()) or 1.0
        ax.imshow(light.shade(h, cmap=cmap, vert_exag=40.0 / span, blend_mode="soft"), origin="lower")
        ax.set_title(f"roughness {r:g}\nheights {h.min():.2f} to {h.max():.2f}", fontsize=9)
        ax.set_xticks([]), ax.set_yticks([])
    fig.suptitle(f"Fractal terrains (diamond-square, level {level}, seed {seed})", fontsize=10)
    fig.tight_layout()
    return figure_png(fig)



#: The shear of §18.3.3's "failure, then fix" picture: x' = x + 1.2 z (row vectors, ``Q = P M``).
SHEAR = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (1.2, 0.0, 1.0))


def normal_map_png(M=SHEAR, arrows: int = 16, size: tuple = (160, 120)) -> bytes:
    """The unit sphere sheared by ``M`` (:class:`goldman_lib.surfaces.AffineInstance`, Goldman §18.2
    and §18.3.3), its normals mapped two ways: by the inverse transpose (right, green) and by the
    linear part itself, like a tangent (wrong, red).  Left: the cross-section ``y = 0`` with
    ``arrows`` normals of each kind; middle and right: the surface on a floor ray traced
    (:func:`goldman_lib.ray_tracing.render`, ``size`` pixels, no recursion) with each kind of normal,
    the wrong one shading the sheared sides too dark or too bright.  Each panel's title gives the
    largest angle error (:meth:`~goldman_lib.surfaces.AffineInstance.normal_error`) over the
    section's points.  The picture is static (PNG bytes).  ``M`` must keep ``y = 0`` in place (map
    the plane to itself) for the section to be the image's own section.

    >>> normal_map_png(arrows=4, size=(16, 12))[:4]
    b'\\x89PNG'
    """
    from matplotlib.figure import Figure

    from goldman_lib import ray_tracing as rt
    from goldman_lib.lighting import Light, Material
    from goldman_lib.simple_surfaces import Plane, Sphere
    from goldman_lib.widgets.interactive import figure_png

    M = np.asarray(M, dtype=float)
    if M.shape != (3, 3) or abs(M[1, 1]) < 1e-9 or np.any(M[[0, 2], 1] != 0):
        raise ValueError("M must be a 3x3 matrix that maps the plane y = 0 to itself (M[0, 1] = M[2, 1] = 0)")
    arrows = int(arrows)
    if not 2 <= arrows <= 64:
        raise ValueError(f"arrows must be between 2 and 64; got {arrows}")
    width, height = (int(v) for v in size)
    if not (8 <= width <= 320 and 6 <= height <= 240):
        raise ValueError(f"size must be (width, height) within (8..320, 6..240); got {size}")
    material = Material(colour=(0.35, 0.55, 0.85), specular=0.4, exponent=25)
    kinds = {"inverse transpose": "#2a9d3a", "linear part": "#c62828"}
    shapes = {k: sf.AffineInstance(Sphere([0, 0, 0], 1.0), M, [0.0, 0.0, 1.0], material=material, normal_map=k)
              for k in kinds}
    angles = np.linspace(0.0, 2 * np.pi, 201)
    section = shapes["inverse transpose"].apply(np.stack([np.cos(angles), 0 * angles, np.sin(angles)], -1))
    at = np.linspace(0.0, 2 * np.pi, arrows, endpoint=False) + np.pi / arrows
    feet = shapes["inverse transpose"].apply(np.stack([np.cos(at), 0 * at, np.sin(at)], -1))
    worst = {k: float(shapes[k].normal_error(section).max()) for k in kinds}

    fig = Figure(figsize=(10.2, 3.3), dpi=100)
    ax = fig.add_subplot(1, 3, 1)
    ax.plot(section[:, 0], section[:, 2], color="#333333", lw=1.2)
    for k, colour in kinds.items():
        n = shapes[k].normal(feet)
        ax.quiver(feet[:, 0], feet[:, 2], n[:, 0], n[:, 2], color=colour, angles="xy", scale_units="xy", scale=2.5,
                  width=0.008)
    lo, hi = section.min(axis=0) - 0.5, section.max(axis=0) + 0.5
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[2], hi[2])
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("z")
    ax.set_title("the section y = 0: normals by the\ninverse transpose (green) and the linear part (red)", fontsize=9)
    floor = Plane([0, 0, -0.05], [0, 0, 1], material=Material(colour=(0.9, 0.9, 0.9)))
    camera = Camera((0.8, -5.0, 2.6), (0.5, 0.0, 1.0), fov=40)
    for j, k in enumerate(kinds):
        scene = rt.Scene([shapes[k], floor], [Light((4, -5, 6))], ambient_light=0.25, background=(0.62, 0.76, 0.92))
        axk = fig.add_subplot(1, 3, j + 2)
        axk.imshow(rt.render(scene, camera, width, height, depth=0), interpolation="nearest")
        axk.set_axis_off()
        axk.set_title(f"shaded with the {k}\n({'right' if j == 0 else 'wrong'}: up to {worst[k]:.0f}° off)",
                      fontsize=9)
    fig.tight_layout()
    return figure_png(fig)


def full_size_render(scene, camera, width: int = 640, height: int = 480, samples: int = 2, depth: int = 5):
    """A "render" control (:class:`goldman_lib.widgets.render_control.RenderControl`, issue 18 §4) that ray
    traces ``scene`` through ``camera`` at full size with :func:`goldman_lib.ray_tracing.render`
    (``samples x samples`` anti-aliasing, recursion ``depth``) when its button is pressed, with a
    progress bar; nothing is rendered until then.  For a picture the chapter draws once (no sliders).

    >>> from goldman_lib import ray_tracing as rt
    >>> rc = full_size_render(rt.default_scene(), rt.default_camera(), 16, 12, samples=1, depth=0)
    >>> rc.render().shape
    (12, 16, 3)
    """
    from goldman_lib import ray_tracing as rt
    from goldman_lib.widgets.render_control import RenderControl

    if not isinstance(scene, rt.Scene) or not isinstance(camera, Camera):
        raise TypeError("scene and camera must be a goldman_lib.ray_tracing.Scene and Camera (goldman_lib.camera)")

    def render(progress):
        return rt.render(scene, camera, width, height, depth=depth, samples=samples, progress=progress)

    return RenderControl(render, view=None,
                         label=f"Render {width} x {height}, {samples} x {samples} anti-aliased, depth {depth}")

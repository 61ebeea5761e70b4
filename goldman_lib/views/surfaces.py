"""The views of chapter 18 (Goldman, surfaces: the general theory): a surface in three.js coloured by
its Gaussian or mean curvature (§18.4), with a picker of the surface and of the curvature, and a
slider that deforms the surface (a twist or a taper, §18.1) in place; a few normals of the deformed
surface are drawn, mapped by the inverse transpose of the deformation's Jacobian (§18.2).

Every number comes from :mod:`goldman_lib.surfaces`: the surfaces are its parametric forms, the
curvature of the deformed surface is :func:`~goldman_lib.surfaces.curvature_parametric` of the
composed map ``A(X(u, v))``, and the normals are :meth:`Deformation.normals`.  This module only
draws.

>>> view = curvature_view(resolution=16)
>>> r = view.set_values(surface="sphere", curvature="Gaussian K", amount=0.0)
>>> bool(abs(r["values"] - 1.0).max() < 1e-5)                # a unit sphere: K = 1 everywhere
True
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from goldman_lib import surfaces as sf
from goldman_lib.views.interactive import InteractiveView, dropdown, float_slider, int_slider  # noqa: F401
from goldman_lib.views.three import SceneView

__all__ = ["curvature_view", "SURFACES", "CURVATURES", "DEFORMATIONS", "curvature_colours", "terrain_png"]

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

    from goldman_lib.views.interactive import figure_png

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


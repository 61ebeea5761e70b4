"""Chapter 30 views: split and average for curves, stencil diagrams, static mesh pictures, and a
three.js subdivision viewer with a mesh picker, a scheme picker and a level slider (Goldman §30.2-30.4).

Plot functions take ``ax=None`` and return their artists; widget factories return an
:class:`~goldman_lib.widgets.interactive.InteractiveView` whose ``update`` is a plain function.

>>> view = subdivision_surface_view()
>>> sorted(view.update(**view.values()))
['control', 'euler', 'status', 'triangles', 'vertices']
"""

from __future__ import annotations

import numpy as np

from goldman_lib import lighting, shading
from goldman_lib import subdivision_surfaces as ss
from goldman_lib.validation import as_int, as_points
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import dropdown, figure_widget, int_slider, InteractiveView
from goldman_lib.widgets.three import SceneView

__all__ = ["MESHES", "DEFAULT_POLYGON", "plot_polygon_levels", "plot_mesh", "plot_quad_stencils",
           "plot_triangle_stencils", "plot_cone_ratios", "plot_rule_comparison", "plot_angle_defects",
           "split_and_average_view",
           "subdivision_surface_view", "CONE_CASES"]

#: The meshes of the viewer, by the name the picker shows.
MESHES = {
    "cube": ss.cube,
    "tetrahedron": ss.tetrahedron,
    "octahedron": ss.octahedron,
    "star (valence 5)": lambda: ss.quad_star(5, rings=2),
    "pentagonal prism": lambda: ss.prism(5),
}

#: The open control polygon of the split-and-average view (a zig-zag, so smoothing is visible).
DEFAULT_POLYGON = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.2], [3.0, 2.4], [4.0, 0.0], [5.0, 1.6]])


# -- static plots -------------------------------------------------------------------------------
def plot_polygon_levels(ctrl, degree: int, levels: int, ax=None, closed: bool = False):
    """Draw a control polygon and its refinements by split and average (Goldman §30.2), one
    colour per level; returns the lines."""
    P = as_points(ctrl, "ctrl", dim=2)
    ax = style.get_axes(ax)
    lines = []
    for k in range(as_int(levels, "levels", minimum=0) + 1):
        Q = ss.split_and_average(P, degree, k, closed=closed)
        Q = np.vstack([Q, Q[:1]]) if closed else Q
        colour = style.PALETTE["control"] if k == 0 else style.level_colour(k)
        (ln,) = ax.plot(Q[:, 0], Q[:, 1], "o-" if k < 3 else "-", color=colour, markersize=3,
                        linewidth=1.0 if k == 0 else 1.6, label=f"level {k}")
        lines.append(ln)
    return lines


def plot_mesh(mesh: ss.Mesh, ax=None, color=None, edges: bool = True, control: ss.Mesh | None = None):
    """Draw a 3D mesh with matplotlib (flat-shaded faces, optional edges and control mesh); returns
    the axes.  For static pictures; the live view is :func:`subdivision_surface_view`."""
    from matplotlib.colors import to_rgb
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

    if ax is None:
        fig = style.new_figure()
        ax = fig.add_subplot(1, 1, 1, projection="3d")
    V = mesh.vertices
    faces = mesh.faces if mesh.face_size else list(mesh.faces)
    polys = [V[f] for f in faces]
    normals = shading.face_normals(V, mesh.triangles())
    first_tri = np.concatenate([[0], np.cumsum(mesh.face_sizes - 2)[:-1]])
    centroids = np.array([V[f].mean(axis=0) for f in faces])
    azim, elev = np.radians(ax.azim), np.radians(ax.elev)          # where matplotlib's 3D camera looks from
    eye = centroids.mean(axis=0) + 10 * np.array([np.cos(elev) * np.cos(azim), np.cos(elev) * np.sin(azim), np.sin(elev)])
    colours = lighting.shade_faces(centroids, normals[first_tri], eye, to_rgb(color or style.PALETTE["surface"]))
    ax.add_collection3d(Poly3DCollection(polys, facecolors=colours, edgecolors="#33333355" if edges else "none",
                                         linewidths=0.3))
    pts = V
    if control is not None:
        C = control.vertices
        ax.add_collection3d(Line3DCollection(C[control.edges], colors="#444444", linewidths=1.0))
        pts = np.concatenate([V, C])
    style.equal_3d_limits(ax, pts)
    ax.view_init(elev=28, azim=-55)
    ax.set_axis_off()
    return ax


def _ring(n, radius=1.0, phase=0.0):
    a = np.radians(phase) + 2 * np.pi * np.arange(n) / n
    return radius * np.stack([np.cos(a), np.sin(a)], axis=1)


def _weight(ax, p, text, colour):
    ax.plot(*p, "o", color=colour, markersize=9, zorder=3)
    ax.annotate(text, p, textcoords="offset points", xytext=(6, 6), fontsize=9, color=colour)


def plot_quad_stencils(valence: int = 4, ax=None):
    """Diagram of the vertex stencil of quadrilateral centroid averaging around a vertex of the
    given valence (Goldman §30.3.2): the weights of the vertex, its edge neighbours and its
    diagonal neighbours.  Returns the axes."""
    from fractions import Fraction

    n = as_int(valence, "valence", minimum=3, maximum=12)
    ax = style.get_axes(ax)
    a, b, c = (Fraction(9, 16), Fraction(3, 8 * n), Fraction(1, 16 * n))
    edge_nbrs = _ring(n, 1.0)
    diag = _ring(n, 1.25, 180 / n)
    for k in range(n):
        quad = np.array([[0, 0], edge_nbrs[k], diag[k], edge_nbrs[(k + 1) % n], [0, 0]])
        ax.plot(quad[:, 0], quad[:, 1], color=style.PALETTE["control"], linewidth=1)
    _weight(ax, (0.0, 0.0), f"{a}", style.PALETTE["point"])
    for p in edge_nbrs:
        _weight(ax, p, f"{b}", style.PALETTE["curve"])
    for p in diag:
        _weight(ax, p, f"{c}", style.PALETTE["good"])
    ax.set_title(f"quad vertex stencil, valence {n}", fontsize=10)
    ax.set_xlim(-1.7, 1.7)
    ax.set_ylim(-1.6, 1.6)
    ax.set_xticks([]), ax.set_yticks([])
    return ax


def plot_triangle_stencils(valence: int = 6, ax=None, self_weight: float = ss.BOX_SPLINE_SELF_WEIGHT):
    """Diagram of the vertex and edge stencils of triangle centroid averaging (Goldman §30.4.2) for
    a vertex of the given valence.  Returns the axes."""
    from fractions import Fraction

    n = as_int(valence, "valence", minimum=3, maximum=12)
    ax = style.get_axes(ax)
    a, b = ss.triangle_vertex_stencil(n, self_weight)
    ea, eb = ss.triangle_edge_stencil(self_weight)
    frac = [str(Fraction(x).limit_denominator(1000)) for x in (a, b, ea, eb)]
    ring = _ring(n)
    for k in range(n):
        tri = np.array([[0, 0], ring[k], ring[(k + 1) % n], [0, 0]])
        ax.plot(tri[:, 0], tri[:, 1], color=style.PALETTE["control"], linewidth=1)
    _weight(ax, (0.0, 0.0), frac[0], style.PALETTE["point"])
    for p in ring:
        _weight(ax, p, frac[1], style.PALETTE["curve"])
    ax.set_title(f"vertex stencil, valence {n}\n(edge stencil: {frac[2]} at the ends, {frac[3]} opposite)", fontsize=10)
    ax.set_xlim(-1.6, 1.6)
    ax.set_ylim(-1.5, 1.5)
    ax.set_xticks([]), ax.set_yticks([])
    return ax


#: The cases of :func:`plot_cone_ratios`: label -> (mesh factory, scheme, vertex rule).
CONE_CASES = {
    "tetrahedron, book's rule (valence 3)": (ss.tetrahedron, "triangle", "centroid"),
    "tetrahedron, Warren = Loop at valence 3": (ss.tetrahedron, "triangle", "loop"),
    "octahedron, book's rule = Warren (valence 4)": (ss.octahedron, "triangle", "centroid"),
    "octahedron, Loop (valence 4)": (ss.octahedron, "triangle", "loop"),
    "cube, quad scheme (valence 3)": (ss.cube, "quad", "centroid"),
}


def plot_cone_ratios(levels: int = 6, ax=None, cases=None):
    """The cone made visible (Goldman §30.4.2): for an original vertex, the height above its 1-ring
    over the ring's radius (:func:`goldman_lib.subdivision_surfaces.cone_ratios`) level after level,
    on a log scale, for the meshes and rules of :data:`CONE_CASES`.  A flat line is a cone that
    never flattens; a falling line a tangent plane.  Returns ``{label: ratios}``."""
    levels = as_int(levels, "levels", minimum=1, maximum=7)
    ax = style.get_axes(ax)
    cases = CONE_CASES if cases is None else cases
    out = {}
    styles = ["o-", "s--", "^-", "v--", "d-"]
    for k, (label, (make, scheme, rule)) in enumerate(cases.items()):
        r = ss.cone_ratios(make(), levels, 0, scheme=scheme, rule=rule)
        out[label] = r
        ax.semilogy(np.arange(levels + 1), r, styles[k % len(styles)], color=style.level_colour(k + 1),
                    markersize=5, linewidth=1.5, label=label)
    ax.set_xlabel("level")
    ax.set_ylabel("height above the 1-ring / ring radius")
    ax.set_title("a cone keeps its ratio; a tangent plane drives it to 0", fontsize=10)
    ax.legend(fontsize=7, frameon=False, loc="lower left")
    return out


def plot_rule_comparison(mesh: ss.Mesh | None = None, level: int = 4, fig=None, control: bool = False):
    """The same triangle mesh (default: the tetrahedron) after ``level`` levels under each vertex
    rule of :data:`~goldman_lib.subdivision_surfaces.VERTEX_RULES`, side by side (with the control
    mesh if ``control``); the book's rule keeps the corners of valence 3 pointed.  Returns the figure."""
    mesh = ss.tetrahedron() if mesh is None else mesh
    level = as_int(level, "level", minimum=0, maximum=5)
    fig = style.new_figure(figsize=style.WIDE_FIGSIZE) if fig is None else fig
    names = {"centroid": "book's rule 5/8, 3/(8n)", "warren": "Warren: 3/16 at n = 3", "loop": "Loop's beta(n)"}
    for k, rule in enumerate(ss.VERTEX_RULES):
        ax = fig.add_subplot(1, len(ss.VERTEX_RULES), k + 1, projection="3d")
        plot_mesh(ss.centroid_averaging(mesh, level, "triangle", rule=rule), ax, control=mesh if control else None)
        ax.set_title(f"{names[rule]}\nlevel {level}", fontsize=9)
    return fig


def plot_angle_defects(mesh: ss.Mesh | None = None, level: int = 4, fig=None):
    """Curvature colours (Goldman §30.4.2): the same triangle mesh (default: the tetrahedron) after
    ``level`` levels under each vertex rule of :data:`~goldman_lib.subdivision_surfaces.VERTEX_RULES`,
    every face coloured by the largest angle defect of its corners
    (:func:`goldman_lib.subdivision_surfaces.angle_defects`, the discrete Gaussian curvature) on one
    log scale, and the vertices whose defect is above 0.5 rad (a cone point) marked.  The book's
    rule keeps the whole defect pi of each valence-3 corner at one point -- a cone -- while
    Warren's and Loop's rules spread it out and each vertex's share fades.  Returns ``{rule: defects (V,)}``; the figure is
    ``fig`` (default: a new wide one)."""
    from matplotlib import cm, colors
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    mesh = ss.tetrahedron() if mesh is None else mesh
    level = as_int(level, "level", minimum=0, maximum=5)
    fig = style.new_figure(figsize=style.WIDE_FIGSIZE) if fig is None else fig
    names = {"centroid": "book's rule", "warren": "Warren: 3/16 at n = 3", "loop": "Loop's beta(n)"}
    norm = colors.LogNorm(vmin=1e-4, vmax=np.pi)
    import matplotlib

    cmap = matplotlib.colormaps["magma"]
    out = {}
    axes = []
    for k, rule in enumerate(ss.VERTEX_RULES):
        m = ss.centroid_averaging(mesh, level, "triangle", rule=rule)
        d = ss.angle_defects(m)
        out[rule] = d
        ax = fig.add_subplot(1, len(ss.VERTEX_RULES), k + 1, projection="3d")
        axes.append(ax)
        V, T = m.vertices, m.triangles()
        face_value = np.clip(np.abs(d)[T].max(axis=1), norm.vmin, norm.vmax)
        ax.add_collection3d(Poly3DCollection(V[T], facecolors=cmap(norm(face_value)), edgecolors="#00000022",
                                             linewidths=0.2))
        sharp = np.abs(d) > 0.5         # a cone: a whole finite angle at one point
        if sharp.any():
            ax.scatter(*V[sharp].T, s=28, color=cmap(norm(np.abs(d[sharp]))), edgecolors="white", linewidths=0.6,
                       depthshade=False)
        style.equal_3d_limits(ax, V)
        ax.view_init(elev=28, azim=-55)
        ax.set_axis_off()
        ax.set_title(f"{names[rule]}, level {level}\nlargest defect {np.abs(d).max():.3g}", fontsize=9)
    fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=axes, shrink=0.6, pad=0.02,
                 label="angle defect (rad)")
    return out


# -- widgets ------------------------------------------------------------------------------------
def split_and_average_view(ctrl=DEFAULT_POLYGON, degree: int = 3, levels: int = 3, max_degree: int = 6,
                           max_levels: int = 6) -> InteractiveView:
    """Sliders for the degree and the number of levels of split and average (Goldman §30.2): the
    control polygon of a uniform B-spline refines and converges to the curve.

    ``update(degree, levels)`` returns the refined polygon and its number of points.
    """
    P = as_points(ctrl, "ctrl", dim=2, min_count=2)
    max_degree = as_int(max_degree, "max_degree", minimum=1, maximum=2 * len(P) - 2)
    max_levels = as_int(max_levels, "max_levels", minimum=1, maximum=9)
    fig, ax = style.new_axes()
    ax.plot(P[:, 0], P[:, 1], "o--", color=style.PALETTE["control"], markersize=5, linewidth=1, label="control polygon")
    (refined,) = ax.plot([], [], "-", color=style.PALETTE["curve"], linewidth=1.8, marker="o", markersize=3,
                         label="after split and average")
    pad = 0.4
    ax.set_xlim(P[:, 0].min() - pad, P[:, 0].max() + pad)
    ax.set_ylim(P[:, 1].min() - pad, P[:, 1].max() + pad)
    ax.legend(loc="upper center", fontsize=8, frameon=False, ncol=2)

    def update(degree, levels):
        degree = as_int(degree, "degree", minimum=0)
        levels = as_int(levels, "levels", minimum=0)
        Q = ss.split_and_average(P, degree, levels)
        refined.set_data(Q[:, 0], Q[:, 1])
        refined.set_marker("o" if len(Q) <= 60 else "None")
        return {"polygon": Q, "status": f"degree {degree}, {levels} level(s): {len(Q)} control points "
                                        f"(split doubles, each of the {degree} averagings drops one)"}

    controls = {"degree": int_slider("degree", as_int(degree, "degree", minimum=0, maximum=max_degree), 0, max_degree),
                "levels": int_slider("levels", as_int(levels, "levels", minimum=0, maximum=max_levels), 0, max_levels)}
    return InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="split and average (Lane-Riesenfeld)")


def subdivision_surface_view(mesh: str = "cube", scheme: str = "quad", level: int = 2, max_level: int = 4,
                       width: int = 480, height: int = 360, rule: str = "centroid") -> InteractiveView:
    """A three.js view of centroid averaging (Goldman §30.3-30.4): pick a mesh, a scheme (quad or
    triangle) and a level; the subdivided mesh is drawn over its control mesh (grey segments).

    The triangle scheme triangulates a mesh with other faces first, and moves the old vertices by
    the vertex ``rule`` picked (:data:`~goldman_lib.subdivision_surfaces.VERTEX_RULES`: the book's
    centroid rule, Warren's or Loop's weights; the quad scheme has one rule).  Levels are computed
    once and cached, so moving the slider only swaps the geometry (:meth:`SceneView.replace_mesh`).
    ``update(mesh, scheme, level, rule="centroid")`` returns the drawn vertices and triangles, the
    control-mesh segments and ``V - E + F``.
    """
    import ipywidgets as widgets

    if mesh not in MESHES:
        raise ValueError(f"mesh must be one of {sorted(MESHES)}; got {mesh!r}")
    if scheme not in ("quad", "triangle"):
        raise ValueError(f"scheme must be 'quad' or 'triangle'; got {scheme!r}")
    if rule not in ss.VERTEX_RULES:
        raise ValueError(f"rule must be one of {ss.VERTEX_RULES}; got {rule!r}")
    max_level = as_int(max_level, "max_level", minimum=1, maximum=5)
    level = as_int(level, "level", minimum=0, maximum=max_level)
    controls_mesh = {name: make() for name, make in MESHES.items()}
    cache: dict[tuple, ss.Mesh] = {}

    def subdivided(name, sch, lvl, rl="centroid"):
        rl = rl if sch == "triangle" else "centroid"
        key = (name, sch, lvl, rl)
        if key not in cache:
            if lvl == 0:
                base = controls_mesh[name]
                cache[key] = ss.triangulate(base) if sch == "triangle" else base
            else:
                cache[key] = ss.centroid_averaging(subdivided(name, sch, lvl - 1, rl), 1, scheme=sch, rule=rl)
        return cache[key]

    scene = SceneView(width=width, height=height, camera_position=(3.2, -4.2, 3.0), target=(0.0, 0.0, 0.0), axes=0)
    first = subdivided(mesh, scheme, level, rule)
    ctrl = subdivided(mesh, scheme, 0)
    scene.add_mesh("surface", first.vertices, first.triangles(), color=style.PALETTE["surface"])
    scene.add_segments("control mesh", ctrl.vertices, ctrl.edges, color="#444444")

    def update(mesh, scheme, level, rule="centroid"):
        level = as_int(level, "level", minimum=0, maximum=max_level)
        if mesh not in MESHES:
            raise ValueError(f"mesh must be one of {sorted(MESHES)}; got {mesh!r}")
        if rule not in ss.VERTEX_RULES:
            raise ValueError(f"rule must be one of {ss.VERTEX_RULES}; got {rule!r}")
        m = subdivided(mesh, scheme, level, rule)
        c = subdivided(mesh, scheme, 0)
        V, T = m.vertices, m.triangles()
        scene.replace_mesh("surface", V, T)
        scene.replace_segments("control mesh", c.vertices, c.edges)
        counts = np.bincount(m.valences[~m.boundary_vertices], minlength=13)
        odd = [f"{int(k)}" for k in np.flatnonzero(counts) if k != (4 if scheme == "quad" else 6)]
        extra = f"; extraordinary valences {', '.join(odd)}" if odd else "; no extraordinary vertices"
        euler = m.euler_characteristic()
        how = (f"triangle scheme ({rule} vertex rule)" if scheme == "triangle" else
               "quad scheme" + ("" if rule == "centroid" else " (vertex rules are the triangle scheme's)"))
        return {"vertices": V, "triangles": T, "control": c.vertices[c.edges], "euler": euler,
                "status": f"{how}, level {level}: V={m.n_vertices}, E={m.n_edges}, F={m.n_faces}, "
                          f"V-E+F={euler}{extra}"}

    controls = {
        "mesh": dropdown("mesh", list(MESHES), mesh, label_width="48px", width="290px"),
        "scheme": widgets.ToggleButtons(options=["quad", "triangle"], value=scheme, description="scheme",
                                        style={"description_width": "48px", "button_width": "80px"}),
        "level": int_slider("level", level, 0, max_level),
        "rule": widgets.ToggleButtons(options=list(ss.VERTEX_RULES), value=rule, description="rule",
                                      style={"description_width": "48px", "button_width": "80px"}),
    }
    view = InteractiveView(controls=controls, views=[scene.widget], update=update, static=scene.to_png,
                           title="centroid averaging", side=True)
    view.scene = scene
    return view

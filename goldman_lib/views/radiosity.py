"""The view of chapter 23 (Goldman, radiosity): the patch radiosities of a Cornell box in three.js
(per-vertex colours, unlit: the colours ARE the solution), an iteration slider for each solver
(Jacobi and Gauss-Seidel sweeps, progressive-refinement shots, §23.5) with the residual curves and
the current iteration marked, flat or smooth display (§23.4: vertex radiosities), and the
light-position control moving the light -- which here is not a point light but an emitting square
of the ceiling (§23.2): its x and y slide it over the ceiling (z is the ceiling's), its intensity and
colour set its emission.

The form factors are computed once per box (hemi-cubes, made reciprocal) and cached, and so are
progressive refinement's shooting operators (they depend on the form factors, not on the light); the
solvers' iterates are stored per light, so an iteration slider only indexes them and a light move
re-solves one solver.  Every number shown comes from :mod:`goldman_lib.radiosity`; this module only draws.

>>> view = radiosity_view()
>>> r = view.set_values(solver="jacobi", jacobi_k=0)
>>> bool(r["residual"] > 0.1), r["iteration"]
(True, 0)
"""

from __future__ import annotations

import functools

import numpy as np
from matplotlib import ticker

from goldman_lib import radiosity as rd
from goldman_lib.validation import as_int
from goldman_lib.widgets import style
from goldman_lib.widgets.interactive import InteractiveView, dropdown, figure_png, figure_widget, int_slider
from goldman_lib.lighting import Light
from goldman_lib.widgets.light_control import LightControl

__all__ = ["radiosity_view", "cornell_scene", "SOLVERS", "MAX_STEPS", "LIGHT_SIZE", "EMISSION", "WHITE"]

#: The solvers the view offers, by control value.
SOLVERS = {"jacobi": "Jacobi (gathering)", "gauss_seidel": "Gauss-Seidel (gathering)",
           "progressive": "progressive refinement (shooting)"}
#: The most iterations each solver's slider offers (sweeps, sweeps, shots).
MAX_STEPS = {"jacobi": 30, "gauss_seidel": 15, "progressive": 500}
#: The light: a square of this side on the ceiling, emitting EMISSION x intensity x colour.
LIGHT_SIZE = 0.25
EMISSION = 10.0
#: The radiosity shown as full white.
WHITE = 0.3
_SLIDER = {"jacobi": "jacobi_k", "gauss_seidel": "gs_k", "progressive": "shots"}


_SCENES: dict = {}


def cornell_scene(n: int = 8, resolution: int = 16, progress=None):
    """The Cornell box of :func:`goldman_lib.radiosity.cornell_box` (``n`` x ``n`` patches a wall) and
    its hemi-cube form factors at ``resolution``, made reciprocal (cached: computed once per size).
    Returns ``(box, F)``.

    progress: ``progress(done, total)`` for the hemi-cubes as they are made (about a second at the
    default size; see :func:`goldman_lib.radiosity.hemicube_form_factors`), for instance a
    :class:`goldman_lib.widgets.render_control.ProgressBar`; a cached scene reports itself done at once."""
    n = as_int(n, "n", minimum=1)
    key = (n, resolution)
    if key not in _SCENES:
        box = rd.cornell_box(n)
        F = rd.enforce_reciprocity(rd.hemicube_form_factors(box, resolution, progress=progress), box.areas)
        F.setflags(write=False)
        if len(_SCENES) >= 4:                       # keep a few sizes, as the view needs one
            _SCENES.pop(next(iter(_SCENES)))
        _SCENES[key] = (box, F)
    elif progress is not None:
        progress(len(_SCENES[key][0]), len(_SCENES[key][0]))
    return _SCENES[key]


def _side_by_side(*pngs) -> bytes:
    """One PNG of several side by side (the static picture of a view with two panes)."""
    import io

    import matplotlib.image as mpimg

    images = [mpimg.imread(io.BytesIO(p), format="png")[..., :3] for p in pngs]
    height = max(im.shape[0] for im in images)
    padded = [np.concatenate([im, np.ones((height - im.shape[0],) + im.shape[1:])]) for im in images]
    buf = io.BytesIO()
    mpimg.imsave(buf, np.clip(np.concatenate(padded, axis=1), 0, 1), format="png", metadata={"Software": None})
    return buf.getvalue()


@functools.lru_cache(maxsize=4)
def _shooting(n: int = 8, resolution: int = 16):
    """The shooting operators of :func:`cornell_scene` (made once per box: a light move re-shoots
    with them instead of re-forming them)."""
    box, F = cornell_scene(n, resolution)
    return rd.shooting_operators(F, box.reflectance, box.areas)


def _solve(name, F, rho, E, area, operators=None):
    """The report (:class:`goldman_lib.fixed_point.Convergence`) of solver ``name``, its history kept."""
    steps = MAX_STEPS[name]
    if name == "jacobi":
        return rd.jacobi(F, rho, E, tol=1e-9, max_iter=steps, full_output=True)[1]
    if name == "gauss_seidel":
        return rd.gauss_seidel(F, rho, E, tol=1e-9, max_iter=steps, full_output=True)[1]
    return rd.progressive_refinement(F, rho, E, area, tol=1e-9, max_iter=steps, full_output=True,
                                     operators=operators)[1]


def radiosity_view(solver: str = "progressive", smooth: bool = True) -> InteractiveView:
    """Patch radiosities of the Cornell box (Goldman §23.2-23.5), solved by ``solver`` and shown after
    the iteration chosen on its slider (``jacobi_k`` and ``gs_k``: sweeps; ``shots``: shots of
    progressive refinement; 0 is the light alone), flat or smooth (``shading``), the light moved by
    the light-position control (``light0_x``, ``light0_y`` on the ceiling, ``light0_I``,
    ``light0_colour``).  Right: the residual ``max |E + rho F B - B|`` of every solver solved so far
    for this light against the work done, in sweeps (one shot is ``1/n`` of a sweep's work), the
    current iteration marked.  Left of it, the ceiling in the x, y plane with the emission of its patches:
    drag the light's marker there (the shared drag helper) or use its sliders.

    Only the chosen solver's step slider is enabled (the other two are greyed out: they would change
    nothing).  ``update(...)`` returns ``{"radiosities" (n, 3), "colours" (4n, 3), "iteration", "residual",
    "emission" (n, 3), "status"}``.
    """
    if solver not in SOLVERS:
        raise ValueError(f"solver must be one of {sorted(SOLVERS)}; got {solver!r}")
    import ipywidgets as widgets
    from goldman_lib.widgets.three import SceneView

    box, F = cornell_scene()
    shooting = _shooting()
    n = len(box)
    rho, area = box.reflectance, box.areas
    # the light stays on the ceiling: sliders for x and y only
    light = LightControl([Light((0.5, 0.5, 0.99), intensity=1.0)], box=[(LIGHT_SIZE / 2, 1 - LIGHT_SIZE / 2)] * 2 + [(0.0, 1.0)],
                         intensity_range=(0.0, 2.0), step=0.025, axes="xy")
    light_controls = light.controls
    controls = {
        "solver": dropdown("solver", [(v, k) for k, v in SOLVERS.items()], solver, label_width="60px"),
        "shots": int_slider("shots", 300, 0, MAX_STEPS["progressive"], label_width="60px"),
        "jacobi_k": int_slider("Jacobi k", 3, 0, MAX_STEPS["jacobi"], label_width="60px"),
        "gs_k": int_slider("G-S k", 2, 0, MAX_STEPS["gauss_seidel"], label_width="60px"),
        "shading": widgets.ToggleButtons(options=[("flat", "flat"), ("smooth", "smooth")],
                                         value="smooth" if smooth else "flat", description="display",
                                         style={"description_width": "60px", "button_width": "70px"}),
        **light_controls,
    }
    positions, triangles, _ = rd.patch_mesh(box, shared=False)
    scene = SceneView(width=420, height=400, camera_position=(0.25, -1.55, 0.95), target=(0.5, 0.5, 0.45), axes=0.0)
    scene.add_mesh("box", positions, triangles, colors=np.zeros((len(positions), 3)), lit=False)
    scene.add_points("light", [[0.5, 0.5, 0.99]], color="#f2b700", size=0.04)

    fig = style.new_figure(figsize=(6.6, 3.4))
    grid = fig.add_gridspec(1, 2, width_ratios=[1, 2])
    ax_map, ax = fig.add_subplot(grid[0]), fig.add_subplot(grid[1])
    style.style_axes(ax_map, equal=True)
    style.style_axes(ax, equal=False)
    # the ceiling in the x, y plane: its patches' emission, the light square, its marker
    ceiling = np.flatnonzero(np.array(box.labels) == "ceiling")
    side = int(round(np.sqrt(len(ceiling))))
    cell = np.floor(box.centres[ceiling, :2] * side).astype(int)
    glow = ax_map.imshow(np.zeros((side, side)), origin="lower", extent=(0, 1, 0, 1), cmap="inferno", vmin=0, vmax=1)
    (outline,) = ax_map.plot([], [], color="#f2b700", linewidth=1.2)
    (lamp_dot,) = ax_map.plot([], [], "o", color="#f2b700", markeredgecolor="#222222", markersize=8)
    ax_map.set_xlim(0, 1), ax_map.set_ylim(0, 1)
    ax_map.set_xticks([0, 0.5, 1]), ax_map.set_yticks([0, 0.5, 1])   # the same on both sides of the square
    ax_map.set_title("ceiling: drag the light", fontsize=9)
    ax_map.set_xlabel("x"), ax_map.set_ylabel("y")
    ax.set_yscale("log")
    # every second decade labelled, the others ticked: the 64 minor ticks and 9 labels had been half the
    # redraw of a slider move
    ax.yaxis.set_major_locator(ticker.LogLocator(numticks=6))
    ax.yaxis.set_minor_locator(ticker.LogLocator(subs=(1.0,), numticks=12))
    ax.yaxis.set_minor_formatter(ticker.NullFormatter())
    ax.xaxis.set_major_locator(ticker.MultipleLocator(10))
    ax.set_xlabel("work (sweeps; a shot is 1/n of one)")
    ax.set_ylabel("residual max |E + ρFB − B|")
    colours = {"jacobi": "#1f77b4", "gauss_seidel": "#2ca02c", "progressive": "#d62728"}
    curves = {k: ax.plot([], [], color=c, linewidth=1.4, label=SOLVERS[k].split(" (")[0])[0] for k, c in colours.items()}
    (marker,) = ax.plot([], [], "o", color="#222222", markersize=7)
    ax.set_xlim(0, MAX_STEPS["jacobi"])
    ax.set_ylim(1e-7, 20)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    solved: dict = {}
    defaults = {k: w.value for k, w in controls.items()}

    def update(solver, shots, jacobi_k, gs_k, shading, light0_x, light0_y, light0_I, light0_colour):
        (lamp,) = light.lights({"light0_x": light0_x, "light0_y": light0_y, "light0_I": light0_I,
                                "light0_colour": light0_colour})
        key = (round(light0_x, 6), round(light0_y, 6), round(light0_I, 6), lamp.colour)
        if solved.get("key") != key:
            solved.clear()
            solved["key"] = key
            solved["E"] = rd.light_emission(box, light0_x, light0_y, LIGHT_SIZE,
                                            EMISSION * light0_I * np.asarray(lamp.colour, float))
        E = solved["E"]
        if solver not in solved:
            solved[solver] = _solve(solver, F, rho, E, area, shooting)
        history = solved[solver]
        k = min(int({"jacobi": jacobi_k, "gauss_seidel": gs_k, "progressive": shots}[solver]), history.iterations)
        B = history.history[k]
        corner = rd.corner_radiosities(box, B, smooth=(shading == "smooth"))
        shown = rd.to_colours(corner, white=WHITE)
        scene.set_colors("box", shown)
        scene.set_points("light", [[light0_x, light0_y, 0.99]])
        image = np.zeros((side, side))
        image[cell[:, 1], cell[:, 0]] = E[ceiling].sum(axis=1)
        glow.set_data(image / max(float(image.max()), 1e-300))
        h2 = LIGHT_SIZE / 2
        outline.set_data([light0_x - h2, light0_x + h2, light0_x + h2, light0_x - h2, light0_x - h2],
                         [light0_y - h2, light0_y - h2, light0_y + h2, light0_y + h2, light0_y - h2])
        lamp_dot.set_data([light0_x], [light0_y])
        for name, line in curves.items():
            if name in solved:
                h = solved[name]
                work = np.arange(h.iterations + 1) / (n if name == "progressive" else 1)
                line.set_data(work, np.maximum(h.residuals, 1e-12))
            else:
                line.set_data([], [])
        x = k / n if solver == "progressive" else k
        marker.set_data([x], [max(history.residuals[k], 1e-12)])
        unit = "shots" if solver == "progressive" else "sweeps"
        status = (f"{SOLVERS[solver]} after {k} {unit}: residual {history.residuals[k]:.3g}; "
                  f"light at ({light0_x:.2f}, {light0_y:.2f}) on the ceiling, an emitting square of side "
                  f"{LIGHT_SIZE:g}; {n} patches, {shading} display")
        if solver == "progressive" and k > 0:
            status += f"; last shot from a {box.labels[int(history.shooters[k - 1])]} patch"
        return {"radiosities": B, "colours": shown, "iteration": k, "residual": float(history.residuals[k]),
                "emission": E, "status": status}

    # solve all three for the starting light, so the residual plot compares them from the start
    for name in SOLVERS:
        update(**{**defaults, "solver": name})
    legend = widgets.HTML("<small>The light is part of the ceiling (an emitting patch), not a point light: "
                          "its sliders move the square and set its emission.</small>")
    def static():
        return _side_by_side(scene.to_png(figsize=(4.2, 4.0)), figure_png(fig))

    view = InteractiveView(controls=controls, views=[widgets.HBox([scene.widget, figure_widget(fig)]), legend],
                           update=update, figure=fig, static=static,
                           title="§23.5 radiosity of a Cornell box, iteration by iteration",
                           # each solver's step slider acts only while that solver is shown
                           acts={"shots": {"solver": ["progressive"]}, "jacobi_k": {"solver": ["jacobi"]},
                                 "gs_k": {"solver": ["gauss_seidel"]}})
    light.drag_in(view, ax_map, plane="xy")
    style.pin_layout(fig)       # fixed limits: titles and labels need not be placed again at each redraw
    for a in (ax_map, ax):      # axes, legend and title stay as they are: rendered once, pasted at each redraw
        style.freeze_axes_decorations(a, a.title)
    view.scene, view.light = scene, light
    return view

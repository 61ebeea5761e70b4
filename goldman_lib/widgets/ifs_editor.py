"""The IFS map editor: sliders for every affine map of an iterated function system, and its
attractor redrawn live (Goldman §6.1-6.4; used again in chapters 7 and 8).

Each map is set by the parameters of :func:`goldman_lib.affine.from_parameters` — rotation
``angle`` (degrees), scales ``sx`` and ``sy`` (``sy < 0`` reflects), ``shear`` and the translation
``tx, ty`` — plus its chaos-game probability weight ``p``.  The dashed outline of each map's
image of the unit square shows what the map does; the attractor is drawn by the chaos game (a
point-count slider) or the deterministic algorithm (a level slider), coloured by the map that
placed each point, so you see ``A = w_1(A) ∪ ... ∪ w_k(A)``.

Each map can also be set by dragging, with the mouse, the images of the three points (0, 0), (1, 0),
(0, 1) of a reference triangle (the white squares of the map being edited): an affine map is fixed
by the images of three non-collinear points (Goldman §4.7.3), and the sliders follow.

How to reuse it from another chapter::

    from goldman_lib.widgets.ifs_editor import ifs_editor, system_from_values
    editor = ifs_editor("dragon")            # or any IFS: ifs_editor(my_ifs)
    editor                                   # display it
    system = system_from_values(editor.values())   # the IFS the sliders describe now

``values_from_system(system)`` gives the slider values of an IFS (at most :data:`MAX_MAPS` maps);
``editor.load(system_or_name)`` loads one into a live editor (what the preset picker does).

Design (the controls of an :class:`InteractiveView` are fixed when it is built): sliders exist for
:data:`MAX_MAPS` maps from the start; the ``maps`` slider (also moved by the "+ map" / "− map"
buttons) says how many are in use, and the ``edit`` picker says whose sliders are shown — the
others are hidden (``layout.display = "none"``).  ``update`` accepts any combination of values:
non-contractive maps give a status message and a best-effort drawing, never a traceback or NaN.

>>> editor = ifs_editor("Sierpinski gasket", points=2000)
>>> result = editor.update(**editor.values())
>>> result["points"].shape, result["status"].startswith("3 maps")
((2000, 2), True)
"""

from __future__ import annotations

import numpy as np

from goldman_lib import affine, ifs
from goldman_lib.validation import as_int
from goldman_lib.widgets import style
from goldman_lib.widgets import checks
from goldman_lib.widgets.interactive import dropdown, figure_widget, float_slider, int_slider, InteractiveView

__all__ = ["ifs_editor", "system_from_values", "values_from_system", "MAX_MAPS", "PARAMETERS",
           "CONDENSATIONS", "MAP_COLOURS", "attractor_points", "REFERENCE_TRIANGLE", "map_values_from_points"]

#: The most maps the editor holds (the Sierpinski carpet needs eight).
MAX_MAPS = 8

#: Slider of each map parameter: (label, low, high, step).
PARAMETERS = {
    "angle": ("rot°", -180.0, 180.0, 0.1),
    "sx": ("sx", 0.0, 1.0, 0.001),
    "sy": ("sy", -1.0, 1.0, 0.001),
    "shear": ("shear", -1.0, 1.0, 0.001),
    "tx": ("tx", -1.0, 2.0, 0.001),
    "ty": ("ty", -1.0, 2.0, 0.001),
    "p": ("p", 0.0, 1.0, 0.01),
}

#: The condensation sets the editor offers (§6.4), by name.
CONDENSATIONS = {
    "none": None,
    "trunk (0,0)-(0,1)": np.array([[0.0, 0.0], [0.0, 1.0]]),
    "segment (0,0)-(1,0)": np.array([[0.0, 0.0], [1.0, 0.0]]),
    "unit square": ifs.UNIT_SQUARE.copy(),
}

#: One colour per map (the last one marks condensation points).
MAP_COLOURS = ["#1f4e9c", "#d1495b", "#1b7f3b", "#edae49", "#5c3c92", "#00798c", "#9c6644", "#8f2d56", "#555555"]

_ALGORITHMS = ["chaos game", "deterministic"]
_MAX_DETERMINISTIC = 100_000
_SPARE = [(0.2, 0.2), (0.5, 0.6), (0.1, 0.6), (0.6, 0.1), (0.3, 0.4), (0.0, 0.3), (0.4, 0.0), (0.6, 0.6)]


def _spare_map(i: int) -> dict:
    """Slider values of a modest contraction for a map slot the preset does not use."""
    tx, ty = _SPARE[i % len(_SPARE)]
    return {"angle": 0.0, "sx": 0.4, "sy": 0.4, "shear": 0.0, "tx": tx, "ty": ty, "p": 0.5}


def values_from_system(system, max_maps: int = MAX_MAPS) -> dict:
    """The editor's slider values for an IFS (or the name of a standard one, see ``ifs.STANDARD``):
    ``maps``, ``condensation`` and ``angle{i}, sx{i}, sy{i}, shear{i}, tx{i}, ty{i}, p{i}`` for
    ``i < max_maps`` (unused slots get a modest default map).  Raises ValueError if the system
    has more than ``max_maps`` maps or a parameter outside the sliders' ranges.

    >>> v = values_from_system("Koch curve")
    >>> v["maps"], round(v["sx1"], 4), v["angle1"]
    (4, 0.3333, 60.0)
    """
    s = ifs.STANDARD[system]() if isinstance(system, str) else ifs.as_ifs(system)
    k = len(s)
    if k > max_maps:
        raise ValueError(f"system must have at most {max_maps} maps for the editor; it has {k}")
    values = {"maps": k, "condensation": "none"}
    if s.condensation is not None:
        for name, C in CONDENSATIONS.items():
            if C is not None and C.shape == s.condensation.shape and np.allclose(C, s.condensation):
                values["condensation"] = name
    top = float(s.probabilities.max())
    for i in range(max_maps):
        if i < k:
            p = affine.to_parameters(s.maps[i])
            row = {"angle": p["angle"], "sx": p["scale"][0], "sy": p["scale"][1], "shear": p["shear"],
                   "tx": p["translate"][0], "ty": p["translate"][1], "p": float(s.probabilities[i]) / top}
            row = {key: (0.0 if abs(v) < 1e-12 else round(float(v), 12)) for key, v in row.items()}
            for key, v in row.items():
                _, low, high, _ = PARAMETERS[key]
                if not low - 1e-9 <= v <= high + 1e-9:
                    raise ValueError(f"map {i} has {key} = {v:.4g}, outside the editor's range [{low}, {high}]")
                row[key] = min(max(v, low), high)
        else:
            row = _spare_map(i)
        for key, v in row.items():
            values[f"{key}{i}"] = v
    return values


def _map_parameters(values: dict, i: int) -> tuple:
    return tuple(checks.number(values.get(f"{key}{i}", _spare_map(i)[key]), f"{key}{i}") for key in PARAMETERS)


def system_from_values(values: dict, *, name: str = "edited IFS") -> ifs.IFS:
    """The IFS the editor's slider values describe: the first ``values["maps"]`` maps
    ``from_parameters(angle, (sx, sy), shear, (tx, ty))``, probabilities from the ``p`` weights
    (equal if all are zero) and the named condensation set.

    >>> s = system_from_values(values_from_system("Sierpinski gasket"))
    >>> np.allclose(s.maps, ifs.sierpinski().maps)
    True
    """
    k = checks.integer(values.get("maps", 1), "maps", 1, MAX_MAPS)
    maps, weights = [], []
    for i in range(k):
        angle, sx, sy, shear, tx, ty, p = _map_parameters(values, i)
        maps.append(affine.from_parameters(angle=angle, scale=(sx, sy), shear=shear, translate=(tx, ty)))
        weights.append(max(p, 0.0))
    weights = np.array(weights)
    probs = weights if weights.sum() > 0 else None
    C = CONDENSATIONS[checks.option(CONDENSATIONS, values.get("condensation", "none"), "condensation")]
    return ifs.IFS(maps, probabilities=probs, condensation=C, name=name)


def attractor_points(system, algorithm: str = "chaos game", points: int = 100_000, levels: int = 6,
                     rng=0) -> tuple[np.ndarray, np.ndarray, str]:
    """What the editor draws: ``(points (n, 2), labels (n,), note)``; ``labels`` is the map that
    placed each point (``len(system)`` for condensation points).  Never raises for a
    non-contractive system: it then draws a few deterministic levels from the unit square, drops
    what ran off, and says so in ``note``.  algorithm: ``"chaos game"`` or ``"deterministic"``;
    points: 1 to :data:`goldman_lib.ifs.MAX_POINTS`; levels: 0 to 64 (and capped further so that
    at most 100,000 points are drawn, as ``note`` says).  Raises ValueError/TypeError naming a bad
    one of these.
    """
    s = ifs.as_ifs(system)
    algorithm = checks.option(_ALGORITHMS, algorithm, "algorithm")
    points = checks.integer(points, "points", 1, ifs.MAX_POINTS)
    levels = checks.integer(levels, "levels", 0, 64)
    k = len(s)
    contractive = s.is_contractive()
    note = ""
    if contractive and algorithm == "chaos game":
        pts, labels = ifs.chaos_game_with_maps(s, points, rng=rng, with_condensation=s.condensation is not None)
        return pts, labels, note
    if contractive:
        m = 1
        start = None
        try:
            affine.fixed_point(s.maps[0])
        except ValueError:
            start = np.zeros((1, 2))
    else:
        start, m = ifs.UNIT_SQUARE[:4], 4
    C = s.condensation
    max_level = levels
    while max_level > 0 and _count(k, m, C, max_level) > _MAX_DETERMINISTIC:
        max_level -= 1
    if not contractive:
        max_level = min(max_level, 4)
    if max_level < levels:
        note = f"level {levels} capped at {max_level} ({_count(k, m, C, levels):,} points would be too many)"
    with np.errstate(all="ignore"):
        pts = ifs.deterministic(s, max_level, start=start if start is not None or C is None else None)
    labels = _deterministic_labels(len(pts), k, 0 if C is None else len(C), max_level)
    keep = np.all(np.isfinite(pts), axis=1) & np.all(np.abs(pts) < 1e6, axis=1)
    return pts[keep], labels[keep], note


def _count(k, m, C, levels):
    c = 0 if C is None else len(C)
    return ifs.deterministic_count(levels, k, c or m, condensation=c)


def _deterministic_labels(n: int, k: int, c: int, levels: int) -> np.ndarray:
    """The outermost map of each point of :func:`ifs.deterministic`'s output (blocks per map,
    condensation copies first)."""
    if levels == 0:
        return np.full(n, k if c else 0, dtype=np.intp)
    body = n - c
    labels = np.repeat(np.arange(k), body // k)
    return np.concatenate([np.full(c, k, dtype=np.intp), labels]).astype(np.intp)


def ifs_editor(system="Sierpinski gasket", *, algorithm: str = "chaos game", points: int = 100_000,
               levels: int = 6, max_maps: int = MAX_MAPS, rng=0) -> InteractiveView:
    """The IFS map editor (Goldman §6.1-6.4): sliders for each map's rotation, scales, shear,
    translation and probability; the images of the unit square; the attractor, live.

    system: a name from ``ifs.STANDARD`` or an :class:`~goldman_lib.ifs.IFS` (at most
    ``max_maps`` maps).  algorithm: ``"chaos game"`` or ``"deterministic"``.  points: chaos-game
    points (1,000-100,000).  levels: deterministic levels (0-12, capped at 100,000 points).
    rng: seed of the chaos game (the same seed every update, so the picture does not flicker).
    ``update(**values)`` returns ``points``, ``labels``, ``images`` (each map's unit square),
    ``factors`` (contraction factors) and ``status``.  ``view.load(system)`` loads a preset.
    """
    import ipywidgets as widgets

    max_maps = as_int(max_maps, "max_maps", minimum=1, maximum=len(MAP_COLOURS) - 1)
    if algorithm not in _ALGORITHMS:
        raise ValueError(f"algorithm must be one of {_ALGORITHMS}; got {algorithm!r}")
    initial = values_from_system(system, max_maps)
    points = as_int(points, "points", minimum=1000, maximum=100_000)
    levels = as_int(levels, "levels", minimum=0, maximum=12)

    fig, ax = style.new_axes()
    ax.set_aspect("auto")  # _fit sets limits with equal scales on both axes itself
    fig.subplots_adjust(left=0.08, right=0.98, bottom=0.07, top=0.93)
    unit = ax.plot(*ifs.UNIT_SQUARE.T, ":", color="#999999", linewidth=1)[0]
    clouds = [ax.plot([], [], ",", color=MAP_COLOURS[i], rasterized=True)[0] for i in range(max_maps + 1)]
    squares = [ax.plot([], [], "--", color=MAP_COLOURS[i], linewidth=1.2)[0] for i in range(max_maps)]
    strokes = ax.plot([], [], "-", color=MAP_COLOURS[-1], linewidth=1.0)[0]
    corners = ax.plot([], [], "o", color="#333333", markersize=3)[0]
    handles = ax.plot([], [], "s", color="#111111", markerfacecolor="#ffffff", markersize=7, zorder=5)[0]
    title = ax.set_title("", fontsize=10)

    controls = {"maps": int_slider("maps", initial["maps"], 1, max_maps, width="200px"),
                "edit": widgets.ToggleButtons(options=list(range(1, max_maps + 1)), value=1, description="edit",
                                              style={"button_width": "34px", "description_width": "48px"})}
    for i in range(max_maps):
        for key, (label, low, high, step) in PARAMETERS.items():
            controls[f"{key}{i}"] = float_slider(label, initial[f"{key}{i}"], low, high, step,
                                                 readout=".1f" if key == "angle" else ".3f")
    controls["algorithm"] = widgets.ToggleButtons(options=_ALGORITHMS, value=algorithm,
                                                  style={"button_width": "110px"})
    controls["points"] = int_slider("points", points, 1000, 100_000)
    controls["points"].step = 1000
    controls["levels"] = int_slider("levels", levels, 0, 12)
    controls["condensation"] = dropdown("condensation", list(CONDENSATIONS), initial["condensation"], label_width="90px", width="290px")

    # While a grip is dragged the frame holds still, so the grip stays under the mouse; the view
    # fits the new attractor when the mouse lets go.
    frame = {"hold": False}

    def update(maps, edit, algorithm, points, levels, condensation, **params):
        k = checks.integer(maps, "maps", 1, max_maps)
        values = {"maps": k, "condensation": condensation, **params}
        s = system_from_values(values)
        factors = s.contraction_factors()
        notes = []
        if not s.is_contractive():
            bad = int(np.argmax(factors))
            notes.append(f"map {bad + 1} is not a contraction (factor {factors[bad]:.2f} >= 1): no attractor; "
                         f"showing a few levels from the unit square")
        pts, labels, note = attractor_points(s, algorithm, points, levels, rng=rng)
        if note:
            notes.append(note)
        for i, line in enumerate(clouds):
            sel = pts[labels == i] if i <= k else pts[:0]
            if i == k and algorithm == "deterministic" and s.condensation is not None and len(sel):
                sel = pts[:0]  # condensation copies are drawn as strokes below
            line.set_data(sel[:, 0], sel[:, 1])
        if algorithm == "deterministic" and s.condensation is not None and s.is_contractive():
            copies = _condensation_copies(s, levels)
            strokes.set_data(copies[:, 0], copies[:, 1])
        else:
            strokes.set_data([], [])
        images = ifs.map_images(s)
        sel_map = int(edit) - 1
        for i, line in enumerate(squares):
            if i < k:
                line.set_data(images[i, :, 0], images[i, :, 1])
                line.set_linewidth(2.4 if i == sel_map else 1.0)
            else:
                line.set_data([], [])
        corners.set_data(images[:, 0, 0], images[:, 0, 1])
        if sel_map < k:
            grip = affine.apply(REFERENCE_TRIANGLE, s.maps[sel_map])
            handles.set_data(grip[:, 0], grip[:, 1])
        else:
            handles.set_data([], [])
        if not frame["hold"]:
            _fit(ax, pts if s.is_contractive() else np.zeros((0, 2)), images)
        count = f"{len(pts):,} points" if algorithm == "chaos game" else f"{len(pts):,} points, level {levels}"
        title.set_text(f"{s.name}: {algorithm}, {count}")
        if sel_map >= k:
            notes.append(f"map {sel_map + 1} is not in use (maps = {k})")
        probs = ", ".join(f"{p:.2f}" for p in s.probabilities)
        status = (f"{k} maps, contraction factors {', '.join(f'{f:.3f}' for f in factors)}; "
                  f"probabilities {probs}" + ("; " + "; ".join(notes) if notes else ""))
        return {"points": pts, "labels": labels, "images": images, "factors": factors, "status": status}

    # -- the layout: preset picker, maps +/-, the selected map's sliders, the algorithm -------------------
    preset = dropdown("preset", ["(choose a preset)"] + list(ifs.STANDARD), "(choose a preset)", label_width="60px", width="260px")
    add = widgets.Button(description="+ map", layout=widgets.Layout(width="64px"))
    remove = widgets.Button(description="− map", layout=widgets.Layout(width="64px"))
    rows = []
    for i in range(max_maps):
        row = widgets.VBox([controls[f"{key}{i}"] for key in PARAMETERS])
        rows.append(row)
    arrange = [preset, widgets.HBox([controls["maps"], add, remove]), controls["edit"], *rows,
               controls["algorithm"], controls["points"], controls["levels"], controls["condensation"]]

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="IFS map editor", side=True, arrange=arrange,
                           # a map's probability is the chaos game's: the deterministic algorithm ignores it
                           acts={f"p{i}": {"algorithm": ["chaos game"]} for i in range(MAX_MAPS)})

    def show_rows(_=None):
        k = controls["maps"].value
        sel = controls["edit"].value - 1
        for i, row in enumerate(rows):
            row.layout.display = None if (i == sel and i < k) else "none"
        controls["points"].layout.display = None if controls["algorithm"].value == "chaos game" else "none"
        controls["levels"].layout.display = None if controls["algorithm"].value == "deterministic" else "none"

    def on_maps(change):
        if controls["edit"].value > change["new"]:
            controls["edit"].value = change["new"]
        show_rows()

    def load(system_or_name):
        """Load an IFS (or a standard name) into every slider, as the preset picker does."""
        values = values_from_system(system_or_name, max_maps)
        values["edit"] = 1
        result = view.set_values(**values)
        show_rows()
        return result

    def on_preset(change):
        if change["new"] in ifs.STANDARD:
            load(change["new"])

    controls["maps"].observe(on_maps, names="value")
    controls["edit"].observe(show_rows, names="value")
    controls["algorithm"].observe(show_rows, names="value")
    preset.observe(on_preset, names="value")
    add.on_click(lambda _: setattr(controls["maps"], "value", min(max_maps, controls["maps"].value + 1)))
    remove.on_click(lambda _: setattr(controls["maps"], "value", max(1, controls["maps"].value - 1)))
    show_rows()
    view.load = load
    view.preset = preset
    view.axes = ax
    view.ax = ax

    # -- direct manipulation (§4.7.3): drag the images of the reference triangle's three points --------
    from goldman_lib.widgets.drag import PointDrag

    def grips():
        vals = view.values()
        i = int(vals["edit"]) - 1
        if i >= vals["maps"]:
            return np.zeros((0, 2))
        return affine.apply(REFERENCE_TRIANGLE, system_from_values(vals).maps[i])

    def on_drag(k, x, y):
        frame["hold"] = True
        i = int(controls["edit"].value) - 1
        view.set_values(**map_values_from_points(i, grips(), k, (x, y)))

    def on_release(k):
        if frame["hold"]:
            frame["hold"] = False
            view.refresh()

    view.drag = PointDrag(ax, grips, on_drag, on_release=on_release)
    return view


#: The reference triangle whose images set a map when dragged (Goldman §4.7.3): the origin and the
#: ends of the unit vectors, the corners the dashed unit-square images start from.
REFERENCE_TRIANGLE = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])


def map_values_from_points(i: int, images, k: int, new_point) -> dict:
    """The slider values of map ``i`` after its image of reference point ``k`` moves to
    ``new_point`` (the other two images kept): the affine map through three points
    (:func:`goldman_lib.affine.affine_from_points`, Goldman §4.7.3) written as the editor's
    parameters (:func:`goldman_lib.affine.to_parameters`), each clamped to its slider's range.
    Images that fall on a line leave the map unchanged (an empty dict).

    >>> v = map_values_from_points(0, [[0, 0], [0.5, 0], [0, 0.5]], 1, (0.5, 0.5))
    >>> round(v["angle0"], 6), round(v["tx0"], 6)
    (45.0, 0.0)
    """
    pts = np.array(images, dtype=float)
    pts[int(k)] = new_point
    try:
        M = affine.affine_from_points(REFERENCE_TRIANGLE, pts)
    except ValueError:
        return {}
    p = affine.to_parameters(M)
    raw = {"angle": p["angle"], "sx": p["scale"][0], "sy": p["scale"][1], "shear": p["shear"],
           "tx": p["translate"][0], "ty": p["translate"][1]}
    out = {}
    for key, value in raw.items():
        _, low, high, step = PARAMETERS[key]
        value = min(max(float(value), low), high)
        out[f"{key}{i}"] = round(low + round((value - low) / step) * step, 10)
    return out


def _condensation_copies(s: ifs.IFS, levels: int) -> np.ndarray:
    """The copies of the condensation polyline up to ``levels`` as one NaN-separated polyline."""
    C = s.condensation
    k = len(s)
    while levels > 0 and _count(k, 1, C, levels) > _MAX_DETERMINISTIC:
        levels -= 1
    copies = [C[None]]
    cur = C[None]
    for _ in range(levels):
        cur = np.matmul(cur[None], s.linear_parts[:, None]) + s.translations[:, None, None, :]
        cur = cur.reshape(-1, len(C), 2)
        copies.append(cur.reshape(-1, len(C), 2))
    allc = np.concatenate(copies)
    sep = np.full((len(allc), 1, 2), np.nan)
    return np.concatenate([allc, sep], axis=1).reshape(-1, 2)


def _fit(ax, pts: np.ndarray, images: np.ndarray, pad: float = 0.06):
    """Fit the view to the attractor and the unit square with its images, with equal scales on
    both axes (the limits are widened to the axes box's proportions, so the box never moves)."""
    parts = [ifs.UNIT_SQUARE, images.reshape(-1, 2)]
    if len(pts):
        sample = pts[::7]  # a sample is plenty for the frame, and 7x cheaper
        x, y = sample[:, 0], sample[:, 1]
        parts.append(np.array([[x.min(), y.min()], [x.max(), y.max()]]))
    allp = np.concatenate(parts)
    allp = allp[np.all(np.isfinite(allp), axis=1)]
    lo, hi = np.maximum(allp.min(axis=0), -50.0), np.minimum(allp.max(axis=0), 50.0)
    span = np.maximum(hi - lo, 1e-3) * (1 + 2 * pad)
    mid = (lo + hi) / 2
    box = ax.get_position()
    w, h = ax.figure.get_size_inches() * (box.width, box.height)
    scale = max(span[0] / w, span[1] / h)   # data units per inch, the same on both axes
    ax.set_xlim(mid[0] - scale * w / 2, mid[0] + scale * w / 2)
    ax.set_ylim(mid[1] - scale * h / 2, mid[1] + scale * h / 2)

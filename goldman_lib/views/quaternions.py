"""The views of chapter 15 (Goldman, complex numbers and quaternions): a complex number acting on
the plane (§15.2), the rotation ``q v q*`` of a body about an axis (§15.3.2, with the 4x4 matrix of
§15.3.6), and a key-frame animation played by slerp beside the same key frames blended linearly as
matrices (§15.3.4-15.3.5), so the distortion of the linear blend shows.

Every number a view shows comes from :mod:`goldman_lib.quaternions`; this module only draws.

>>> view = key_frame_view()
>>> r = view.set_values(frame=0)
>>> round(r["linear_distortion"], 12), round(r["slerp_distortion"], 12)
(0.0, 0.0)
>>> view.play.value == view.controls["frame"].value        # the Play widget drives the frame slider
True
"""

from __future__ import annotations

import numpy as np

from goldman_lib import quaternions as qt
from goldman_lib.validation import as_float
from goldman_lib.views import style
from goldman_lib.views.drag import drag_sliders
from goldman_lib.views.interactive import InteractiveView, figure_widget, float_slider, int_slider
from goldman_lib.views.vectors3d import COLOURS, VectorScene

__all__ = ["complex_plane_view", "quaternion_rotation_view", "key_frame_view", "FIGURE_F", "BODY_ARROWS", "KEY_SETS",
           "BRICK", "FRAMES"]

#: The asymmetric figure the complex numbers act on: a letter F (a closed outline), away from the origin.
FIGURE_F = np.array([[0.0, 0.0], [0.2, 0.0], [0.2, 0.4], [0.5, 0.4], [0.5, 0.6], [0.2, 0.6], [0.2, 0.8],
                     [0.6, 0.8], [0.6, 1.0], [0.0, 1.0], [0.0, 0.0]]) + [0.5, 0.2]

#: The body the rotation view turns: three arrows of different lengths (so the image shows handedness).
BODY_ARROWS = np.array([[0.9, 0.0, 0.0], [0.0, 0.6, 0.0], [0.0, 0.0, 0.35]])

#: A brick (8 corners, 12 triangles) for the key-frame animation, its long side along x.
BRICK = np.array([[x, y, z] for x in (-0.6, 0.6) for y in (-0.32, 0.32) for z in (-0.13, 0.13)])
_BRICK_TRIANGLES = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                             [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
_NOSE = np.array([[0.6, 0.0, 0.0]])

#: Frames of the animation (the Play widget and the frame slider run over 0..FRAMES).
FRAMES = 96


def _turns(*axis_angles):
    """A key orientation: the quaternion of the rotations (axis, degrees) applied in order."""
    q = np.array([1.0, 0.0, 0.0, 0.0])
    for axis, angle in axis_angles:
        q = qt.multiply(qt.from_axis_angle(axis, angle), q)
    return q


#: Key orientations (unit quaternions at times 0, 1, 2, ...) of the animation.
KEY_SETS = {
    "tumble": np.stack([_turns(), _turns(([0, 0, 1], 100)), _turns(([0, 0, 1], 100), ([1, 0, 0], 110)),
                        _turns(([0, 0, 1], 100), ([1, 0, 0], 110), ([0, 1, 0], 140)), _turns(([1, 1, 1], 30))]),
    "half turns": np.stack([_turns(), _turns(([0, 0, 1], 180)), _turns(([0, 0, 1], 180), ([1, 0, 0], 180)),
                            _turns()]),
}

_OFFSET = np.array([1.3, 0.0, 0.0])


def _fmt_q(q) -> str:
    return "(" + ", ".join(f"{v + 0.0:.3f}" for v in np.asarray(q)) + ")"


def _fmt_matrix(M) -> str:
    return "[" + ", ".join("[" + ", ".join(f"{v + 0.0:.3f}" for v in row) + "]" for row in np.asarray(M)) + "]"


def _legend(items) -> "widgets.HTML":
    import ipywidgets as widgets

    return widgets.HTML(" &nbsp;".join(f"<span style='color:{c}'>&#9632; {label}</span>" for label, c in items))


# -- §15.2 ---------------------------------------------------------------------------------------------

def complex_plane_view(re: float = 0.9, im: float = 0.5) -> InteractiveView:
    """Multiplication by a complex number z = re + i im on the plane (Goldman §15.2): the letter F
    in grey and its image z·F in blue; the point z (red, draggable with the mouse, or set by its
    sliders) is the image of 1.  Multiplying by z rotates the plane about the origin by ``arg z``
    and scales it by ``|z|`` (:func:`goldman_lib.quaternions.complex_polar`).

    ``update(re, im)`` returns ``{"image" (n, 2), "z" (2,), "scale", "angle", "status"}``.

    >>> r = complex_plane_view().set_values(re=0.0, im=1.5)
    >>> r["scale"], r["angle"]
    (1.5, 90.0)
    """
    re, im = as_float(re, "re"), as_float(im, "im")
    controls = {"re": float_slider("Re z", re, -1.6, 1.6, 0.05), "im": float_slider("Im z", im, -1.6, 1.6, 0.05)}
    fig, ax = style.new_axes()
    ax.set_xlim(-2.6, 2.6), ax.set_ylim(-2.6, 2.6)
    circle = np.exp(1j * np.linspace(0, 2 * np.pi, 121))
    ax.plot(circle.real, circle.imag, color="#c8c8c8", linewidth=0.8, linestyle="--")
    ax.axhline(0, color="#bbbbbb", linewidth=0.6), ax.axvline(0, color="#bbbbbb", linewidth=0.6)
    ax.plot(*FIGURE_F.T, color="#9a9a9a", linewidth=1.6, label="F")
    (image_line,) = ax.plot([], [], color=style.PALETTE["curve"], linewidth=2.0, label="z·F")
    (one_to_z,) = ax.plot([], [], color=style.PALETTE["point"], linewidth=1.0)
    ax.plot([1.0], [0.0], "o", color="#444444", markersize=5)
    ax.annotate("1", (1.0, 0.0), textcoords="offset points", xytext=(4, -12), fontsize=9)
    (z_dot,) = ax.plot([], [], "o", color=style.PALETTE["point"], markersize=8, label="z (drag me)")
    ax.legend(loc="lower left", fontsize=8)
    title = ax.set_title("", fontsize=10)

    def update(re, im):
        z = complex(re, im)
        image = qt.complex_multiply(FIGURE_F, z)
        scale, angle = qt.complex_polar(z)
        image_line.set_data(image[:, 0], image[:, 1])
        one_to_z.set_data([0.0, re], [0.0, im])
        z_dot.set_data([re], [im])
        if scale == 0:
            title.set_text("z = 0: the whole plane collapses to the origin")
            status = "z = 0: multiplying by 0 sends every point to the origin; there is no rotation (arg 0 is undefined)"
        else:
            title.set_text(f"z = {re:.2f} {'+' if im >= 0 else '-'} {abs(im):.2f} i")
            status = (f"z = {re:.2f} {'+' if im >= 0 else '-'} {abs(im):.2f} i:  |z| = {scale:.3f},  arg z = "
                      f"{angle:.1f}°  —  multiplying by z rotates F by {angle:.1f}° about the origin and scales it "
                      f"by {scale:.3f}; 1 goes to z")
        return {"image": image, "z": np.array([re, im]), "scale": scale, "angle": angle, "status": status}

    view = InteractiveView(controls=controls, views=[figure_widget(fig)], update=update, figure=fig,
                           title="§15.2 multiplying by a complex number z", side=True)
    drag_sliders(view, ax, [("re", "im")])
    return view


# -- §15.3.2 and §15.3.6 --------------------------------------------------------------------------------

def quaternion_rotation_view(ax: float = 1.0, ay: float = 1.0, az: float = 0.5, angle: float = 110.0,
                  size: float = 1.0) -> InteractiveView:
    """The conformal map ``v -> q v q*`` of the quaternion ``q = size (cos(θ/2), sin(θ/2) u)``, u
    the unit vector along the axis (ax, ay, az) (Goldman §15.3.2): the axis in orange, a body of
    three arrows (blue) and its image (pink), the path of the long arrow's tip under the rotation
    ``q/|q|`` (grey).  With ``size = |q| = 1`` the map is the rotation by θ about the axis; otherwise
    it also scales every length by ``|q|^2``.  The status gives q and the 4x4 matrix of its rotation
    in the book's row convention (:func:`goldman_lib.quaternions.to_matrix`, §15.3.6).

    ``update(ax, ay, az, angle, size)`` returns ``{"q" (4,), "image" (3, 3), "matrix" (4, 4),
    "scale", "status"}``.  A zero axis shows a message and leaves the body unmoved.

    >>> r = quaternion_rotation_view().set_values(ax=0.0, ay=0.0, az=1.0, angle=90.0, size=1.0)
    >>> (np.round(r["image"][0], 12) + 0.0).tolist()
    [0.0, 0.9, 0.0]
    """
    values = {k: as_float(v, k) for k, v in dict(ax=ax, ay=ay, az=az, angle=angle, size=size).items()}
    controls = {
        "ax": float_slider("axis x", values["ax"], -1.0, 1.0, 0.05, label_width="56px"),
        "ay": float_slider("axis y", values["ay"], -1.0, 1.0, 0.05, label_width="56px"),
        "az": float_slider("axis z", values["az"], -1.0, 1.0, 0.05, label_width="56px"),
        "angle": float_slider("θ", values["angle"], -180.0, 180.0, 1.0, readout=".0f", label_width="56px"),
        "size": float_slider("|q|", values["size"], 0.5, 1.4, 0.05, label_width="56px"),
    }
    scene = VectorScene(camera_position=(3.4, -4.0, 2.6))
    zero = np.zeros((1, 3))
    steps = np.linspace(0.0, 1.0, 33)
    scene.add_segments("path", np.repeat(BODY_ARROWS[:1], 33, axis=0), [[i, i + 1] for i in range(32)],
                       color="#9a9a9a", width=1.2)
    scene.add_arrows("axis", zero, [[0.0, 0.0, 1.4]], color=COLOURS["cross"])
    scene.add_arrows("body", zero, BODY_ARROWS, color=COLOURS["u"])
    scene.add_arrows("image", zero, BODY_ARROWS, color=COLOURS["image"])

    def update(ax, ay, az, angle, size):
        axis = np.array([ax, ay, az], dtype=float)
        if not np.any(axis):
            scene.set_arrows("axis", zero, np.zeros((1, 3)))
            scene.set_arrows("image", zero, BODY_ARROWS)
            scene.set_segments("path", np.repeat(BODY_ARROWS[:1], 33, axis=0))
            return {"q": np.array([size, 0.0, 0.0, 0.0]), "image": BODY_ARROWS.copy(), "matrix": np.eye(4),
                    "scale": size * size,
                    "status": "the axis (0, 0, 0) has no direction: choose a nonzero axis to rotate about"}
        unit = qt.from_axis_angle(axis, angle)
        q = size * unit
        image = qt.conformal_map(q, BODY_ARROWS)
        M = qt.to_matrix(q)
        n = float(qt.norm(q))
        path = qt.rotate(qt.from_axis_angle(axis, steps * angle), BODY_ARROWS[0])
        scene.set_arrows("axis", zero, 1.4 * axis[None] / np.linalg.norm(axis))
        scene.set_arrows("image", zero, image)
        scene.set_segments("path", path)
        scale = n * n
        what = (f"rotation by {angle:.0f}° about the axis" if abs(scale - 1) < 1e-9 else
                f"rotation by {angle:.0f}° about the axis, then scaling by |q|² = {scale:.3f}")
        status = (f"q = {_fmt_q(q)}, |q| = {n:.3f}: q v q* is the {what};  4x4 matrix of the rotation "
                  f"(row convention, v' = v M): {_fmt_matrix(M)}")
        return {"q": q, "image": image, "matrix": M, "scale": scale, "status": status}

    legend = _legend([("axis", COLOURS["cross"]), ("body v", COLOURS["u"]), ("image q v q*", COLOURS["image"]),
                      ("path of the tip", "#9a9a9a")])
    view = InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="§15.3.2 the rotation q v q*", side=True)
    view.scene = scene
    return view


# -- §15.3.4-15.3.5 -------------------------------------------------------------------------------------

def key_frame_view(keys: str = "tumble", frame: int = FRAMES // 8) -> InteractiveView:
    """Key-frame animation (Goldman §15.3.5): a brick moved through the key orientations
    :data:`KEY_SETS` ``[keys]`` (at times 0, 1, 2, ...) by slerp (left, blue,
    :func:`goldman_lib.quaternions.key_frames`), beside the same brick moved by the linear blend of
    the key orientations' matrices (right, red, :func:`goldman_lib.quaternions.matrix_key_frames`).
    Press the Play button (it drives the frame slider) or move the slider: between keys the linear
    blend is no rotation, and the brick shrinks and shears (§15.3.4).  The grey curves are the paths
    of the bricks' noses over the whole animation; the status gives ``matrix_distortion`` of both
    (0 for slerp).

    ``update(keys, frame)`` returns ``{"time", "slerp" (4,), "linear" (4, 4), "slerp_distortion",
    "linear_distortion", "status"}``.  The Play widget is ``view.play`` (CSS class
    ``goldman-play``), linked to the control ``frame``.

    >>> r = key_frame_view("half turns").set_values(frame=FRAMES // 6)   # halfway between two keys
    >>> round(r["linear_distortion"], 9)
    1.0
    """
    import ipywidgets as widgets

    if keys not in KEY_SETS:
        raise ValueError(f"keys must be one of {sorted(KEY_SETS)}; got {keys!r}")
    frame = int(round(as_float(frame, "frame")))
    if not 0 <= frame <= FRAMES:
        raise ValueError(f"frame must be in [0, {FRAMES}]; got {frame}")
    controls = {
        "keys": widgets.Dropdown(options=list(KEY_SETS), value=keys, description="keys",
                                 style={"description_width": "48px"}, layout=widgets.Layout(width="290px")),
        "frame": int_slider("frame", frame, 0, FRAMES, width="240px"),
    }
    play = widgets.Play(value=frame, min=0, max=FRAMES, step=1, interval=60, description="play",
                        layout=widgets.Layout(width="110px"))
    play.add_class("goldman-play")
    widgets.link((play, "value"), (controls["frame"], "value"))

    scene = VectorScene(width=460, height=320, camera_position=(0.6, -5.2, 2.4), axes=0.0)
    fine = np.linspace(0.0, 1.0, FRAMES + 1)
    scene.add_segments("slerp:path", np.zeros((FRAMES + 1, 3)), [[i, i + 1] for i in range(FRAMES)],
                       color="#9a9a9a", width=1.0)
    scene.add_segments("linear:path", np.zeros((FRAMES + 1, 3)), [[i, i + 1] for i in range(FRAMES)],
                       color="#9a9a9a", width=1.0)
    scene.add_mesh("slerp:brick", BRICK - _OFFSET, _BRICK_TRIANGLES, color=COLOURS["u"])
    scene.add_mesh("linear:brick", BRICK + _OFFSET, _BRICK_TRIANGLES, color=COLOURS["v"])
    scene.add_points("noses", np.concatenate([_NOSE - _OFFSET, _NOSE + _OFFSET]), color="#222222", size=0.09)
    shown = {"keys": None}

    def set_paths(name):
        orientations = KEY_SETS[name]
        times = np.arange(len(orientations), dtype=float)
        t = fine * times[-1]
        slerp_nose = qt.rotate(qt.key_frames(orientations, times, t), _NOSE[0])
        linear_nose = _NOSE[0] @ qt.matrix_key_frames(orientations, times, t)[..., :3, :3]
        scene.set_segments("slerp:path", slerp_nose - _OFFSET)
        scene.set_segments("linear:path", linear_nose + _OFFSET)
        shown["keys"] = name

    def update(keys, frame):
        orientations = KEY_SETS[keys]
        if shown["keys"] != keys:
            set_paths(keys)
        times = np.arange(len(orientations), dtype=float)
        t = float(frame) / FRAMES * times[-1]
        q = qt.key_frames(orientations, times, t)
        M_slerp = qt.to_matrix(q)
        M_linear = qt.matrix_key_frames(orientations, times, t)
        scene.set_mesh("slerp:brick", BRICK @ M_slerp[:3, :3] - _OFFSET)
        scene.set_mesh("linear:brick", BRICK @ M_linear[:3, :3] + _OFFSET)
        scene.set_points("noses", np.concatenate([_NOSE @ M_slerp[:3, :3] - _OFFSET,
                                                  _NOSE @ M_linear[:3, :3] + _OFFSET]))
        d_slerp = float(qt.matrix_distortion(M_slerp))
        d_linear = float(qt.matrix_distortion(M_linear))
        key = min(int(t), len(orientations) - 2)
        where = (f"at key {int(round(t))}" if abs(t - round(t)) < 1e-9 else f"between keys {key} and {key + 1}")
        status = (f"time {t:.3f} ({where}):  matrix_distortion of the slerp brick {d_slerp:.3f} (a rotation), "
                  f"of the linearly blended brick {d_linear:.3f}"
                  + ("  (collapsed: the blend is singular here)" if d_linear > 0.999 else ""))
        return {"time": t, "slerp": q, "linear": M_linear, "slerp_distortion": d_slerp,
                "linear_distortion": d_linear, "status": status}

    legend = _legend([("slerp of the key quaternions", COLOURS["u"]),
                      ("linear blend of the key matrices", COLOURS["v"])])
    view = InteractiveView(controls=controls, views=[scene.widget, legend], update=update, static=scene.to_png,
                           title="§15.3.5 key-frame animation: slerp (left) and linear matrices (right)",
                           arrange=[controls["keys"], widgets.HBox([play, controls["frame"]])])
    view.play, view.scene = play, scene
    return view

"""Chapter 15 views draw what goldman_lib.quaternions computes: the image of the letter F under a
complex number (§15.2), the conformal map q v q* of a body (§15.3.2) with its matrix (§15.3.6), and
the key-frame animation by slerp beside the linear blend of matrices (§15.3.4-15.3.5), driven by a
Play widget linked to the frame slider."""

import numpy as np

from goldman_lib import quaternions as qt
from goldman_lib.views import quaternions as qv


def test_complex_plane_view_rotates_and_scales_the_figure_by_z():
    view = qv.complex_plane_view()
    r = view.set_values(re=0.0, im=1.5)
    # multiplying by 1.5 i sends (x, y) to (-1.5 y, 1.5 x): worked by hand on the first corner (0.5, 0.2)
    assert np.allclose(r["image"][0], [-0.3, 0.75])
    assert np.allclose(r["image"], qt.complex_multiply(qv.FIGURE_F, 1.5j))
    assert np.isclose(r["scale"], 1.5) and np.isclose(r["angle"], 90) and "rotates F by 90.0°" in r["status"]
    r = view.set_values(re=0.0, im=0.0)
    assert "z = 0" in r["status"] and np.allclose(r["image"], 0) and view.last_error is None


def test_complex_plane_view_point_z_is_dragged_with_the_mouse(hooks):
    view = qv.complex_plane_view(re=1.0, im=0.0)
    hooks["press_at"](view.drag, 1.0, 0.0)
    hooks["move_to"](view.drag, -0.5, 1.2)
    hooks["release"](view.drag)
    assert view.values() == {"re": -0.5, "im": 1.2}
    assert np.allclose(view.last_result["image"], qt.complex_multiply(qv.FIGURE_F, -0.5 + 1.2j))


def test_quaternion_rotation_view_draws_q_v_qstar_and_its_matrix():
    view = qv.quaternion_rotation_view()
    r = view.set_values(ax=0.0, ay=0.0, az=1.0, angle=90.0, size=1.0)
    # a quarter turn about z: (0.9, 0, 0) -> (0, 0.9, 0), (0, 0.6, 0) -> (-0.6, 0, 0), z fixed
    assert np.allclose(r["image"], [[0, 0.9, 0], [-0.6, 0, 0], [0, 0, 0.35]], atol=1e-12)
    assert np.allclose(r["q"], [np.sqrt(0.5), 0, 0, np.sqrt(0.5)])
    assert np.allclose(r["matrix"], qt.to_matrix(r["q"])) and np.allclose(qv.BODY_ARROWS @ r["matrix"][:3, :3], r["image"])
    assert "4x4 matrix" in r["status"] and "q = (0.707, 0.000, 0.000, 0.707)" in r["status"]
    view.set_values(ax=1.0, ay=-1.0, az=0.5, angle=-130.0, size=1.0)
    tips = view.scene.data("image:head")["positions"].reshape(3, -1, 3)[:, 0]   # the cones' apexes
    assert np.allclose(tips, qt.rotate(qt.from_axis_angle([1, -1, 0.5], -130), qv.BODY_ARROWS), atol=1e-12)


def test_quaternion_rotation_view_scales_by_the_norm_squared_and_survives_a_zero_axis():
    view = qv.quaternion_rotation_view()
    r = view.set_values(ax=1.0, ay=0.0, az=0.0, angle=40.0, size=1.2)
    assert np.isclose(r["scale"], 1.44) and np.isclose(np.linalg.norm(r["image"][0]), 0.9 * 1.44)
    assert "scaling by |q|² = 1.440" in r["status"]
    r = view.set_values(ax=0.0, ay=0.0, az=0.0)
    assert view.last_error is None and "no direction" in r["status"] and np.allclose(r["image"], qv.BODY_ARROWS)


def test_key_frame_view_slerp_beside_linear_matrices():
    view = qv.key_frame_view("tumble")
    keys = qv.KEY_SETS["tumble"]
    times = np.arange(len(keys), dtype=float)
    for frame in (0, 7, 30, 61, qv.FRAMES):
        r = view.set_values(frame=frame)
        t = frame / qv.FRAMES * times[-1]
        assert np.isclose(r["time"], t)
        q = qt.key_frames(keys, times, t)
        assert np.allclose(r["slerp"], q) and r["slerp_distortion"] < 1e-9
        M = qt.matrix_key_frames(keys, times, t)
        assert np.isclose(r["linear_distortion"], qt.matrix_distortion(M))
        brick = view.scene.data("slerp:brick")["positions"]
        assert np.allclose(brick, qv.BRICK @ qt.to_matrix(q)[:3, :3] - qv._OFFSET)
        assert np.allclose(view.scene.data("linear:brick")["positions"], qv.BRICK @ M[:3, :3] + qv._OFFSET)
    assert view.set_values(frame=12)["linear_distortion"] > 0.1           # between keys the blend distorts
    r = view.set_values(keys="half turns", frame=qv.FRAMES // 6)           # halfway between I and a half turn
    assert np.isclose(r["linear_distortion"], 1.0) and "collapsed" in r["status"]
    # the nose paths follow the key set shown
    path = view.scene.data("slerp:path")["positions"]
    assert np.allclose(path[0], qv._NOSE[0] - qv._OFFSET)
    assert np.allclose(np.linalg.norm(path + qv._OFFSET, axis=1), np.linalg.norm(qv._NOSE))   # on a sphere


def test_the_play_widget_drives_the_frame_slider_and_the_plain_update():
    view = qv.key_frame_view()
    assert "goldman-play" in view.play._dom_classes
    view.play.value = 40
    assert view.controls["frame"].value == 40
    assert np.isclose(view.last_result["time"], 40 / qv.FRAMES * 4)
    view.set_values(frame=5)
    assert view.play.value == 5


def test_double_cover_view_comes_back_at_720_not_360():
    view = qv.double_cover_view()
    r = view.set_values(t=360.0)
    assert np.allclose(r["q"], [-1, 0, 0, 0]) and np.allclose(r["image"], qv.BODY_ARROWS)
    assert "other quaternion" in r["status"]
    r = view.set_values(t=720.0)
    assert np.allclose(r["q"], [1, 0, 0, 0]) and "both back" in r["status"]
    a, b = view.set_values(t=130.0), view.set_values(t=490.0)
    assert np.allclose(b["q"], -a["q"]) and np.allclose(b["image"], a["image"]) and np.allclose(b["matrix"], a["matrix"])
    assert "q(t) = −q(130°)" in b["status"]
    # the body drawn is the body turned by q(t) about COVER_AXIS (scipy as the reference)
    from scipy.spatial.transform import Rotation

    expected = Rotation.from_rotvec(np.radians(130.0) * qv.COVER_AXIS).apply(qv.BODY_ARROWS)
    assert np.allclose(a["image"], expected)


def test_slerp_s3_view_marks_slerp_evenly_and_nlerp_bunched():
    view = qv.slerp_s3_view()
    q0, q1 = qv.S3_KEYS[view.values()["keys"]]
    for t in (0.0, 0.1, 0.25, 0.5, 0.9, 1.0):
        r = view.set_values(t=t)
        assert np.isclose(r["slerp_turned"], t * r["total"])                    # constant speed
        assert np.allclose(r["slerp_point"], qt.stereographic(qt.slerp(q0, q1, t)))
        assert np.allclose(r["nlerp_point"], qt.stereographic(qt.nlerp(q0, q1, t)))
    r = view.set_values(t=0.2)
    assert r["nlerp_turned"] < 0.2 * r["total"] - 3                             # slow near the key
    r = view.set_values(t=0.5)
    assert np.isclose(r["nlerp_turned"], 0.5 * r["total"])
    for keys in qv.S3_KEYS:
        r = view.set_values(keys=keys, t=0.3)
        assert view.last_error is None and np.isfinite(r["slerp_point"]).all()


def test_one_sided_product_plot_draws_minus_sin_half_theta_u_dot_v_and_zero():
    v = np.array([0.3, -1.2, 2.0])
    u = np.array([1.0, 1.0, 1.0]) / np.sqrt(3)
    ax = qv.one_sided_product_plot([1, 1, 1], v)
    one_sided, sandwich = ax.get_lines()[:2]
    theta = one_sided.get_xdata()
    assert np.allclose(one_sided.get_ydata(), -np.sin(np.radians(theta) / 2) * (u @ v))   # -q⃗·v, by hand
    assert np.allclose(sandwich.get_ydata(), 0, atol=1e-12)

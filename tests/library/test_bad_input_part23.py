"""Overflow in Parts II and III, the Part I rule (issue 20, section 4): a result that cannot be
represented is refused with a ValueError naming the input; a result that can be is computed right
(scale before squaring or normalising).

Expected values are closed forms (a half turn about z sends x to -x; the cubic Bézier midpoint is
``(P0 + 3 P1 + 3 P2 + P3) / 8``; ``math.hypot`` for lengths) or theorems (a direction's length does
not change what it points at: a result that depends only on a direction is the same at 1e-170 and
at 1e300 times it).
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from goldman_lib import (bspline, lighting, mass_points, quaternions, ray_tracing, simple_surfaces, transforms,
                         vector_geometry, vectors)
from goldman_lib.camera import Camera
from goldman_lib.kernels.frames import norm

SCALES = [1e-170, 2.0 ** -600, 1e160, 1e300]


def _raises(call, pattern):
    with pytest.raises(ValueError) as info:
        call()
    assert re.search(pattern, str(info.value)), str(info.value)
    assert len(str(info.value)) < 400


# -- the reproducers -------------------------------------------------------------------------------

@pytest.mark.parametrize("k", [1.0, *SCALES])
def test_quaternion_of_any_norm_rotates(k):
    """``rotate([0, 0, 0, 1e160], x)`` is the half turn about z (it was the identity: |q|^2 overflowed)."""
    np.testing.assert_allclose(quaternions.rotate([0, 0, 0, k], [1, 0, 0]), [-1, 0, 0], atol=1e-15)
    np.testing.assert_allclose(quaternions.normalize([0, 0, k, 0]), [0, 0, 1, 0])
    np.testing.assert_allclose(quaternions.to_matrix([0, 0, 0, k])[0], [-1, 0, 0, 0], atol=1e-15)


def test_quaternion_norm_and_inverse_at_extreme_magnitudes():
    assert quaternions.norm([3e200, 4e200, 0, 0]) == pytest.approx(5e200, rel=1e-15)
    np.testing.assert_allclose(quaternions.inverse([0, 0, 1e200, 0]), [0, 0, -1e-200, 0], rtol=1e-15)
    _raises(lambda: quaternions.inverse([1e-310, 0, 0, 0]), r"^q is too small in magnitude")
    _raises(lambda: quaternions.multiply([1e200, 0, 0, 0], [1e200, 0, 0, 0]), r"^p and q are too large")


def test_transforms_compose_refuses_an_overflow():
    """It returned NaN where affine.compose refuses."""
    _raises(lambda: transforms.compose(*[transforms.scaling(2.0)] * 2000), r"^matrices \(up to matrices\[1023\]\)")
    assert transforms.compose(*[transforms.scaling(2.0)] * 1000)[0, 0] == 2.0 ** 1000


@pytest.mark.parametrize("call, name", [
    (lambda: transforms.translate([[1e308, 0, 0]], [1e308, 0, 0]), "points or v"),
    (lambda: transforms.apply([[1e308, 1e308, 1e308]], transforms.scaling(10)), "points or M"),
    (lambda: transforms.scale([[1e300, 0, 0]], 1e300), "points, s or center"),
    (lambda: transforms.apply_to_vectors([[1e300, 0, 0]], transforms.scaling(1e300)), "vectors or M"),
    (lambda: vectors.dot([1e200, 0, 0], [1e200, 0, 0]), "u and v"),
    (lambda: vectors.cross([1e200, 0, 0], [0, 1e200, 0]), "u and v"),
    (lambda: vectors.det([1e200, 0, 0], [0, 1e200, 0], [0, 0, 1e200]), "u, v and w"),
])
def test_unrepresentable_results_name_their_inputs(call, name):
    _raises(call, rf"^{re.escape(name)} (is|are) too large in magnitude")


def test_sphere_of_huge_radius_is_refused_naming_it():
    """``Sphere((0, 0, 0), 1e160).intersect(...)`` raised OverflowError from ``radius ** 2``."""
    _raises(lambda: simple_surfaces.Sphere((0, 0, 0), 1e160), r"^radius must be at most 1e\+60")
    _raises(lambda: simple_surfaces.Sphere((1e160, 0, 0), 1), r"^center must have coordinates at most")
    _raises(lambda: simple_surfaces.Plane((0, 0, 1e160), (0, 0, 1)), r"^point must have coordinates at most")
    big = simple_surfaces.Sphere((0, 0, 0), 5e59)                      # near the largest allowed: exact hits
    assert big.intersect([[0, 0, -1e60]], [[0, 0, 1]])[0] == pytest.approx(5e59, rel=1e-12)


def test_de_boor_with_knots_at_the_float_limit():
    """Knots at ±1e308 gave [0, 0]: their span overflows, so they are refused; at ±1e307 the curve is right."""
    ctrl = [[0, 0], [1, 2], [2, 1], [3, 3]]
    _raises(lambda: bspline.de_boor(ctrl, [-1e308] * 4 + [1e308] * 4, 3, 0.0), r"^knots is too large in magnitude")
    midpoint = (np.array(ctrl[0]) + 3 * np.array(ctrl[1]) + 3 * np.array(ctrl[2]) + np.array(ctrl[3])) / 8
    for a in (1.0, 1e200, 1e307):
        np.testing.assert_allclose(bspline.de_boor(ctrl, [-a] * 4 + [a] * 4, 3, 0.0), midpoint, rtol=1e-14)


def test_light_overflow_names_the_light_and_the_coefficient():
    """An overflow from light intensity times diffuse coefficient was blamed on "origins"."""
    hot = lighting.Material(diffuse=1e300)
    bright = lighting.Light((0, 0, 5), intensity=1e300)
    _raises(lambda: lighting.intensity([[0, 0, 1]], [[0, 0, 1]], [0, 0, 5], [bright], hot),
            r"^lights\[0\]\.intensity and material\.diffuse are too large")
    scene = ray_tracing.Scene([simple_surfaces.Sphere([0, 0, 0], 1, material=hot)], [bright])
    for call in (lambda: ray_tracing.trace(scene, [[0, 0, 5]], [[0, 0, -1]]),
                 lambda: ray_tracing.render(scene, ray_tracing.default_camera(), 8, 6)):
        with pytest.raises(ValueError) as info:
            call()
        assert "intensity" in str(info.value) and "diffuse" in str(info.value)
        assert "origins" not in str(info.value)
    _raises(lambda: ray_tracing.Scene([], [lighting.Light((0, 0, 1e160))]), r"^lights\[0\]\.position must have")
    _raises(lambda: Camera((0, -1e160, 0), (0, 0, 0)), r"\beye\b")
    _raises(lambda: ray_tracing.render(ray_tracing.default_scene(), Camera((0, -1e61, 0), (0, 0, 0)), 8, 6),
            r"^camera\.eye must have coordinates at most")


# -- results that depend only on a direction: the same at every magnitude -----------------------------------

DIRECTION_ONLY = [
    ("quaternions.normalize(q)", lambda k: quaternions.normalize(np.array([1.0, 2, 3, 4]) * k)),
    ("quaternions.rotate(q, v)", lambda k: quaternions.rotate(np.array([1.0, 2, 3, 4]) * k, [1, 0.5, -2])),
    ("quaternions.to_matrix(q)", lambda k: quaternions.to_matrix(np.array([1.0, 2, 3, 4]) * k)),
    ("quaternions.to_axis_angle(q)", lambda k: np.concatenate([
        quaternions.to_axis_angle(np.array([1.0, 2, 3, 4]) * k)[0],
        [quaternions.to_axis_angle(np.array([1.0, 2, 3, 4]) * k)[1]]])),
    ("quaternions.slerp(q0, q1, t)", lambda k: quaternions.slerp(np.array([1.0, 0, 0, 0]) * k, [0.5, 0.5, 0.5, 0.5],
                                                                 0.3)),
    ("quaternions.from_axis_angle(axis, angle)", lambda k: quaternions.from_axis_angle(np.array([1.0, 2, 2]) * k, 70)),
    ("vectors.angle_between(u, v) in 3D", lambda k: vectors.angle_between(np.array([1.0, 2, 3]) * k, [3, -1, 2])),
    ("vectors.angle_between(u, v) in 2D", lambda k: vectors.angle_between(np.array([1.0, 2]) * k, [3, -1])),
    ("transforms.rotation(axis, angle)", lambda k: transforms.rotation(np.array([1.0, 2, 2]) * k, 70)),
    ("transforms.mirror(point, normal)", lambda k: transforms.mirror([0, 0, 1], np.array([1.0, 2, 2]) * k)),
    ("transforms.reflect(points, point, normal)",
     lambda k: transforms.reflect([[1, 2, 3]], [0, 0, 1], np.array([1.0, 2, 2]) * k)),
    ("transforms.nonuniform_scaling(s, direction)",
     lambda k: transforms.nonuniform_scaling(3, np.array([1.0, 2, 2]) * k)),
    ("lighting.unit_rows(vectors)", lambda k: lighting.unit_rows(np.array([[3.0, 0, 4], [1, 2, 2]]) * k)),
    ("lighting.diffuse(normals)", lambda k: lighting.diffuse([[0, 0, 0]], np.array([[0.0, 1, 1]]) * k, [0, 3, 3], 1, 1)),
    ("vector_geometry.point_plane_distance(normal)",
     lambda k: vector_geometry.point_plane_distance([[1, 2, 3]], [0, 0, 1], np.array([1.0, 2, 2]) * k)),
    ("vector_geometry.foot_on_plane(normal)",
     lambda k: vector_geometry.foot_on_plane([[1, 2, 3]], [0, 0, 1], np.array([1.0, 2, 2]) * k)),
    ("ray_tracing.refract_rays(directions, normals)",
     lambda k: ray_tracing.refract_rays(np.array([[1.0, 0, -1]]) * k, np.array([[0.0, 0, 1]]) * k, 1.0, 1.5)[0]),
    ("mass_points.same_projective_point(a, b)",
     lambda k: mass_points.same_projective_point(np.array([1.0, 2, 3, 1]) * k, [2, 4, 6, 2])),
]


@pytest.mark.parametrize("k", SCALES)
@pytest.mark.parametrize("label, f", DIRECTION_ONLY, ids=[d[0] for d in DIRECTION_ONLY])
def test_a_direction_gives_the_same_result_at_every_magnitude(label, f, k):
    """Scale before squaring or normalising: a quaternion or normal 1e160 (or 1e-170) times a
    moderate one describes the same rotation, mirror or plane."""
    try:
        got = f(k)
    except ValueError as exc:    # a refusal is allowed only if it names an input; a wrong answer is not
        pytest.fail(f"{label} refused a representable case at scale {k:g}: {exc}")
    np.testing.assert_allclose(np.asarray(got, dtype=float), np.asarray(f(1.0), dtype=float), rtol=1e-12,
                               atol=1e-15)


# -- the length everyone uses ----------------------------------------------------------------------------------

@pytest.mark.parametrize("k", [1e-320, 1e-200, 1e-160, 1e154, 1e160, 1e300])
def test_norm_is_right_at_every_magnitude(k):
    v = np.array([[3.0, 4.0, 12.0], [1.0, 1.0, 1.0]]) * k
    expected = [math.hypot(*row) for row in v]
    np.testing.assert_allclose(norm(v), expected, rtol=1e-15 if k > 1e-300 else 1e-2)


def test_norm_is_numpy_bit_for_bit_at_moderate_magnitudes():
    """What keeps every stored notebook output unchanged."""
    rng = np.random.default_rng(20)
    v = rng.normal(size=(2000, 3)) * 10.0 ** rng.integers(-100, 100, size=(2000, 1))
    assert np.array_equal(norm(v), np.linalg.norm(v, axis=-1))
    assert np.array_equal(norm(v, keepdims=True), np.linalg.norm(v, axis=-1, keepdims=True))

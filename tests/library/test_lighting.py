"""goldman_lib.lighting: the ambient, diffuse and specular terms against values worked by hand, and
the total intensity as their sum (Goldman chapter 16)."""

import numpy as np
import pytest
from matplotlib.colors import LightSource

from goldman_lib import lighting
from goldman_lib.lighting import Light, Material

P0 = np.zeros((1, 3))
UP = np.array([[0.0, 0.0, 1.0]])


def test_diffuse_is_lamberts_cosine_by_hand():
    # light at (0, 0, 2): L = N, cos = 1; at (2, 0, 2): 45 degrees, cos = 1/sqrt 2; below: 0
    assert lighting.diffuse(P0, UP, [0, 0, 2], 0.6, 2.0)[0] == pytest.approx(1.2)
    assert lighting.diffuse(P0, UP, [2, 0, 2], 1.0, 1.0)[0] == pytest.approx(0.7071067811865476)
    assert lighting.diffuse(P0, UP, [0, 0, -2], 1.0, 1.0)[0] == 0.0
    # the angle from the point, not from the origin: a point at (1, 0, 0) under a light at (1, 0, 3)
    assert lighting.diffuse([[1, 0, 0]], UP, [1, 0, 3], 1.0, 1.0)[0] == pytest.approx(1.0)
    # no distance attenuation
    assert lighting.diffuse(P0, UP, [0, 0, 100], 1.0, 1.0)[0] == pytest.approx(1.0)


def test_diffuse_with_rgb_light_and_unnormalised_normals():
    d = lighting.diffuse(P0, [[0, 0, 5.0]], [0, 3, 4], [1.0, 0.5, 0.0], 1.0)   # cos = 4/5
    assert np.allclose(d, [[0.8, 0.4, 0.0]])


def test_specular_is_phong_by_hand():
    # L = (1, 0, 1)/sqrt2, R = (-1, 0, 1)/sqrt2; eye straight up: R.V = 1/sqrt2; n = 4 -> 1/4
    assert lighting.specular(P0, UP, [1, 0, 1], [0, 0, 3], 1.0, 4, 1.0)[0] == pytest.approx(0.25)
    # eye on the mirror ray: (R.V)^n = 1 for any n, times ks I_p
    assert lighting.specular(P0, UP, [1, 0, 1], [-2, 0, 2], 0.5, 50, 2.0)[0] == pytest.approx(1.0)
    # eye on the light's side, R.V = 0 -> 0; the light behind the surface -> 0
    assert lighting.specular(P0, UP, [1, 0, 0.0001], [1, 0, 0.0001], 1.0, 1, 1.0)[0] == pytest.approx(0, abs=1e-3)
    assert lighting.specular(P0, UP, [1, 0, -1], [-1, 0, -1], 1.0, 1, 1.0)[0] == 0.0
    # no N.L factor: a grazing light (L.N = sin 10 deg) seen along the mirror ray still gives ks
    a = np.radians(10)
    light = [np.cos(a), 0, np.sin(a)]
    assert lighting.specular(P0, UP, light, [-np.cos(a), 0, np.sin(a)], 0.7, 30, 1.0)[0] == pytest.approx(0.7)


def test_reflect_keeps_the_angle():
    rng = np.random.default_rng(1)
    v, n = rng.normal(size=(50, 3)), lighting.unit_rows(rng.normal(size=(50, 3)))
    r = lighting.reflected_direction(v, n)
    assert np.allclose(np.linalg.norm(r, axis=1), np.linalg.norm(v, axis=1))
    assert np.allclose((r * n).sum(1), (v * n).sum(1))
    assert np.allclose(np.cross(r + v, n), 0)           # r + v lies along n


def test_intensity_is_the_sum_of_the_three_terms():
    m = Material(colour=(1.0, 0.5, 0.25), ambient=0.1, diffuse=0.6, specular=0.3, exponent=8)
    lights = [Light((1, 1, 3), colour=(1, 1, 0.5)), Light((-2, 0, 1), intensity=0.5)]
    rng = np.random.default_rng(2)
    P, N = rng.normal(size=(20, 3)), rng.normal(size=(20, 3))
    eye = np.array([0.5, -4.0, 2.0])
    want = 0.1 * 0.3 * np.array(m.colour) + 0 * P
    for light in lights:
        d = lighting.diffuse(P, N, light.position, m.diffuse, 1.0)
        s = lighting.specular(P, N, light.position, eye, m.specular, m.exponent, 1.0)
        want = want + (d[:, None] * np.array(m.colour) + s[:, None]) * light.rgb
    assert np.allclose(lighting.intensity(P, N, eye, lights, m, ambient_light=0.3), want)


def test_one_light_by_hand_and_shadows():
    m = Material(colour=(1, 1, 1), ambient=0.2, diffuse=0.5, specular=0.25, exponent=1)
    # light and eye straight above: ambient 0.2*0.5 + diffuse 0.5 + specular 0.25
    got = lighting.intensity(P0, UP, [0, 0, 4], Light((0, 0, 4)), m, ambient_light=0.5)
    assert np.allclose(got, [[0.85, 0.85, 0.85]])
    shadow = lighting.intensity(P0, UP, [0, 0, 4], Light((0, 0, 4)), m, 0.5, shadowed=[[True]])
    assert np.allclose(shadow, [[0.1, 0.1, 0.1]])


def test_two_sided_flips_normals_towards_the_eye():
    m = Material(ambient=0.0, specular=0.0, diffuse=1.0, colour=(1, 1, 1))
    one = lighting.intensity(P0, -UP, [0, 0, 3], Light((0, 0, 3)), m, 0.0)
    two = lighting.intensity(P0, -UP, [0, 0, 3], Light((0, 0, 3)), m, 0.0, two_sided=True)
    assert np.allclose(one, 0) and np.allclose(two, 1)


def test_light_direction_matches_matplotlib():
    assert np.allclose(lighting.light_direction(315, 45), LightSource(azdeg=315, altdeg=45).direction)


@pytest.mark.parametrize("bad, word", [
    (lambda: Light((0, 0)), "position"),
    (lambda: Light((0, 0, 1), colour=(2, 0, 0)), "colour"),
    (lambda: Light((0, 0, 1), intensity=-1), "intensity"),
    (lambda: Material(exponent=-2), "exponent"),
    (lambda: Material(reflect=1.5), "reflect"),
    (lambda: Material(index=0), "index"),
    (lambda: lighting.diffuse(P0, [[0, 0, 1], [0, 0, 1]], [0, 0, 1], 1, 1), "normals"),
    (lambda: lighting.diffuse(P0, UP, [0, 0, 1], [1, 1], 1), "kd"),
    (lambda: lighting.specular(P0, UP, [0, 0, 1], [0, 0, 1], 1, -1, 1), "exponent"),
])
def test_bad_input_names_the_parameter(bad, word):
    with pytest.raises(ValueError, match=word):
        bad()


def test_intensity_refuses_other_types():
    with pytest.raises(TypeError, match="material"):
        lighting.intensity(P0, UP, [0, 0, 1], Light(), {"diffuse": 1})
    with pytest.raises(TypeError, match="lights"):
        lighting.intensity(P0, UP, [0, 0, 1], [(0, 0, 1)], Material())


# chapter 16: the highlight's width
def test_highlight_half_width_against_a_sweep_of_the_specular_term():
    # by hand: n = 1 -> arccos(1/2) = 60 degrees; n = 2 -> arccos(sqrt(1/2)) = 45 degrees
    assert lighting.highlight_half_width(1) == pytest.approx(60.0)
    assert lighting.highlight_half_width(2) == pytest.approx(45.0)
    assert lighting.highlight_half_width(3, fraction=0.125) == pytest.approx(60.0)
    # against the specular term itself: move the eye round the mirror direction until it halves
    for n in (5.0, 40.0, 200.0):
        angles = np.linspace(0.0, 89.0, 89001)
        light = [0.0, 0.0, 5.0]                         # light straight above: R = N
        eyes = np.stack([5 * np.sin(np.radians(angles)), np.zeros_like(angles), 5 * np.cos(np.radians(angles))], 1)
        s = np.array([lighting.specular(P0, UP, light, e, 1.0, n, 1.0)[0] for e in eyes[::100]])
        a = angles[::100]
        width = np.interp(0.5, s[::-1], a[::-1])
        assert width == pytest.approx(lighting.highlight_half_width(n), abs=0.05)
    with pytest.raises(ValueError, match="fraction"):
        lighting.highlight_half_width(3, fraction=1.0)
    with pytest.raises(ValueError, match="exponent"):
        lighting.highlight_half_width(0)


def test_one_eye_per_point_matches_one_call_per_point():
    """A ray tracer's secondary rays each see the surface from their own origin (chapter 17)."""
    P = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
    N = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]])
    eyes = np.array([[-1.0, 0.0, 1.0], [3.0, 0.0, 1.0]])
    light = Light((1.0, 0.0, 1.0))
    m = Material(specular=0.8, exponent=4)
    intensity, specular = lighting.intensity, lighting.specular
    both = intensity(P, N, eyes, light, m)
    for k in range(2):
        assert np.allclose(both[k], intensity(P[k:k + 1], N[k:k + 1], eyes[k], light, m)[0])
    # the eye on the mirror ray of the first point: R.V = 1, the full k_s
    assert specular(P, N, light.position, eyes, 0.8, 4, 1.0)[0] == pytest.approx(0.8)
    with pytest.raises(ValueError, match="eye"):
        intensity(P, N, eyes[:1].repeat(3, axis=0), light, m)


# -- Blinn's halfway vector (§16.5) ------------------------------------------------------------------------


def test_blinn_term_is_cos_of_half_the_phong_angle_in_the_plane():
    # N = z; L at angle a from N on one side, V at angle b on the other (both in the x-z plane).
    # Then R . V = cos(a - b) and H, the bisector of L and V, makes (a - b)/2 with N: N . H = cos((a - b)/2)
    # (sum-to-product: sin a - sin b = 2 cos((a+b)/2) sin((a-b)/2), cos a + cos b = 2 cos((a+b)/2) cos((a-b)/2)).
    rng = np.random.default_rng(165)
    a = rng.uniform(0.0, 1.5, 300)
    b = rng.uniform(0.0, 1.5, 300)
    P = np.zeros((300, 3))
    N = np.tile([0.0, 0.0, 1.0], (300, 1))
    eyes = 4.0 * np.stack([-np.sin(b), np.zeros(300), np.cos(b)], axis=1)
    for k in range(300):
        light = 3.0 * np.array([np.sin(a[k]), 0.0, np.cos(a[k])])
        blinn = lighting.blinn_specular(P[k:k + 1], N[k:k + 1], light, eyes[k], 1.0, 1, 1.0)[0]
        phong = lighting.specular(P[k:k + 1], N[k:k + 1], light, eyes[k], 1.0, 1, 1.0)[0]
        assert blinn == pytest.approx(np.cos((a[k] - b[k]) / 2), abs=1e-12)
        assert phong == pytest.approx(max(np.cos(a[k] - b[k]), 0.0), abs=1e-12)


def test_blinn_term_with_four_times_the_exponent_has_nearly_phongs_half_width():
    # in the plane, Phong's term falls to 1/2 at phi = arccos(2^(-1/n)), Blinn's (exponent m) at
    # phi = 2 arccos(2^(-1/m)); with m = 4n the two agree to within 1% for n >= 10
    for n in (10, 50, 200):
        phong = np.degrees(np.arccos(0.5 ** (1 / n)))
        blinn = 2 * np.degrees(np.arccos(0.5 ** (1 / (4 * n))))
        assert phong == pytest.approx(lighting.highlight_half_width(n), rel=1e-12)
        assert blinn == pytest.approx(phong, rel=0.01)


def test_blinn_term_is_zero_behind_the_surface_and_at_a_grazing_halfway_vector():
    P, N = [[0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]]
    assert lighting.blinn_specular(P, N, [1.0, 0.0, -1.0], [0.0, 0.0, 5.0], 1.0, 10, 1.0).tolist() == [0.0]
    assert lighting.blinn_specular(P, N, [1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], 1.0, 10, 1.0).tolist() == [0.0]
    rgb = lighting.blinn_specular(P, N, [0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [1.0, 0.5, 0.0], 3, 2.0)
    assert rgb.round(12).tolist() == [[2.0, 1.0, 0.0]]


def test_blinn_term_refuses_bad_input_naming_it():
    with pytest.raises(ValueError, match="exponent"):
        lighting.blinn_specular([[0, 0, 0]], [[0, 0, 1]], [0, 0, 1], [0, 0, 1], 1.0, -1, 1.0)
    with pytest.raises((ValueError, TypeError), match="light_position"):
        lighting.blinn_specular([[0, 0, 0]], [[0, 0, 1]], [0, 0], [0, 0, 1], 1.0, 1, 1.0)


# -- the clamp of L . N (§16.4), switched off to show what it prevents ------------------------------

def test_unclamped_diffuse_goes_negative_behind_the_surface():
    # the normal (0, 0, -1) turned away from a light at (0, 3, 3): L . N = -1/sqrt 2
    N = [[0.0, 0.0, -1.0]]
    assert lighting.diffuse(P0, N, [0, 3, 3], 0.5, 2.0)[0] == 0.0
    assert lighting.diffuse(P0, N, [0, 3, 3], 0.5, 2.0, clamp=False)[0] == pytest.approx(-1.0 / np.sqrt(2))
    # in front of the surface the switch changes nothing, bit for bit
    pts = np.random.default_rng(1).normal(size=(200, 3))
    normals = np.random.default_rng(2).normal(size=(200, 3))
    safe = lighting.diffuse(pts, normals, [1.0, 2.0, 3.0], 0.7, 1.3)
    unsafe = lighting.diffuse(pts, normals, [1.0, 2.0, 3.0], 0.7, 1.3, clamp=False)
    front = unsafe > 0
    assert np.array_equal(safe[front], unsafe[front]) and np.all(safe[~front] == 0) and np.all(unsafe[~front] <= 0)
    assert np.array_equal(safe, lighting.diffuse(pts, normals, [1.0, 2.0, 3.0], 0.7, 1.3, clamp=True))


def test_unclamped_specular_lets_a_light_behind_the_surface_make_a_highlight():
    # N = (0, 0, 1); the light just below the surface's plane on one side, the eye above on the other:
    # L . N < 0 but R = 2 (L . N) N - L has R . V > 0, worked by hand with numpy's dot products
    light, eye = np.array([4.0, 0.0, -0.4]), np.array([-4.0, 0.0, 0.8])
    L, V, N = light / np.linalg.norm(light), eye / np.linalg.norm(eye), np.array([0.0, 0.0, 1.0])
    R = 2 * (L @ N) * N - L
    assert L @ N < 0 and R @ V > 0
    assert lighting.specular(P0, UP, light, eye, 0.8, 6, 1.0)[0] == 0.0
    assert lighting.specular(P0, UP, light, eye, 0.8, 6, 1.0, clamp=False)[0] == pytest.approx(0.8 * (R @ V) ** 6)


def test_intensity_clamp_switch_default_unchanged_and_validated():
    m = Material(colour=(0.8, 0.3, 0.3), ambient=0.2, diffuse=0.7, specular=0.5, exponent=5)
    rng = np.random.default_rng(7)
    pts, normals = rng.normal(size=(300, 3)), rng.normal(size=(300, 3))
    lights = [Light((3.0, 2.0, 5.0)), Light((-4.0, 1.0, -3.0), intensity=0.5)]
    default = lighting.intensity(pts, normals, [0, 0, 6], lights, m, 1.0)
    assert np.array_equal(default, lighting.intensity(pts, normals, [0, 0, 6], lights, m, 1.0, clamp=True))
    unsafe = lighting.intensity(pts, normals, [0, 0, 6], lights, m, 1.0, clamp=False)
    behind = np.zeros(len(pts), dtype=bool)
    for light in lights:
        behind |= np.einsum("ij,ij->i", np.asarray(light.position) - pts, normals) <= 0
    assert np.array_equal(default[~behind], unsafe[~behind])     # only points with a light behind them change
    assert np.any(unsafe[behind] < default[behind])               # the negative diffuse term subtracts
    for bad in ("no", 1, None):
        with pytest.raises(TypeError, match="clamp"):
            lighting.intensity(P0, UP, [0, 0, 5], lights, m, clamp=bad)
        with pytest.raises(TypeError, match="clamp"):
            lighting.diffuse(P0, UP, [0, 0, 5], 1.0, 1.0, clamp=bad)

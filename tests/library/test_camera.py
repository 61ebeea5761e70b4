"""goldman_lib.camera: the one place a pixel becomes a ray and a point a pixel (Goldman §13.6.2, §17.2).

Values worked by hand, and the round trip under hypothesis: a pixel's ray passes through the pixel's
centre on the screen one unit in front of the eye, and any point of that ray projects back onto the
centre.  The last test reads the views' source: none of them builds rays from pixel coordinates.
"""

import ast
import math
import pathlib

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from goldman_lib import ray_tracing, shading
from goldman_lib.camera import Camera, image_size

#: tan(fov/2) = 1/2: at distance 4 the half-width 1 is 1/4 unit on the plane one unit ahead, and the
#: plane has 10 / (1/2) = 20 pixels per unit.
HALF_FOV_TAN_HALF = 2 * math.degrees(math.atan(0.5))


def _square_camera(**kw):
    return Camera(eye=(0, -4, 0), target=(0, 0, 0), up=(0, 0, 1), fov=HALF_FOV_TAN_HALF, width=20, height=20, **kw)


def test_camera_projects_as_worked_by_hand():
    cam = _square_camera()
    x, y, z, w = cam.project([[1, 0, 1]])[0]
    # (1, 0, 1) seen from (0, -4, 0): 1/4 right and 1/4 up on the plane, 20 px per unit
    assert (x, y) == pytest.approx((15.0, 5.0)) and w == pytest.approx(4.0) and z == pytest.approx(1 - 0.1 / 4)
    o, d = cam.rays()
    assert np.allclose(o, [0, -4, 0]) and d.shape == (20, 20, 3)
    assert np.allclose(d[0, 0], np.array([-9.5 / 20, 1, 9.5 / 20]) / np.linalg.norm([-9.5 / 20, 1, 9.5 / 20]))


def test_camera_rays_through_pixel_centres():
    cam = Camera((0, -5, 0), (0, 0, 0), fov=90, width=3, height=3)
    o, d = cam.rays()
    assert np.allclose(o, [0, -5, 0]) and np.allclose(np.linalg.norm(d, axis=-1), 1)
    assert d[1, 1] == pytest.approx([0, 1, 0])               # the centre pixel looks straight ahead
    # the screen's half-height is tan 45 = 1; pixel centres at -2/3, 0, 2/3; row 0 is the top
    assert d[0, 1] == pytest.approx(np.array([0, 1, 2 / 3]) / math.sqrt(1 + 4 / 9))
    assert d[1, 0] == pytest.approx(np.array([-2 / 3, 1, 0]) / math.sqrt(1 + 4 / 9))
    o1, d1 = cam.ray(0, 1)                                   # column 0, row 1: the same ray
    assert np.array_equal(o1, o) and np.array_equal(d1, d[1, 0])


@pytest.mark.parametrize("bad, word", [
    (lambda: Camera((0, 0, 5), (0, 0, 0), up=(0, 0, 1)), "up"),
    (lambda: Camera((0, -5, 0), (0, 0, 0), fov=180), "fov"),
    (lambda: Camera((0, -5, 0), (0, -5, 0)), "target"),
    (lambda: Camera((0, -5, 0), (0, 0, 0), width=0), "width"),
    (lambda: Camera((0, -5, 0), (0, 0, 0), near=0), "near"),
    (lambda: Camera((0, -5, 0), (0, 0, 0), width=4, height=3).ray(4, 0), "px"),
    (lambda: Camera((0, -5, 0), (0, 0, 0), width=4, height=3).ray(0, -1), "py"),
    (lambda: Camera((0, -5, 0), (0, 0, 0), width=4, height=3).pixel_directions([0, 1], [0]), "columns and rows"),
])
def test_bad_camera_input_names_the_parameter(bad, word):
    with pytest.raises(ValueError, match=word):
        bad()


def test_image_size_is_whole_pixels_within_the_budget():
    assert image_size(4, 3) == (4, 3) and image_size(4.0, 3.0) == (4, 3)
    with pytest.raises(ValueError, match="width"):
        image_size(10 ** 6, 10 ** 6)
    with pytest.raises(ValueError, match="height"):
        image_size(4, 0)


def test_one_camera_one_keyword_spelling():
    """One Camera: the renderers take goldman_lib.camera.Camera and export none of their own."""
    assert "Camera" not in shading.__all__ and "Camera" not in ray_tracing.__all__
    cam = ray_tracing.default_camera()
    assert isinstance(cam, Camera) and (cam.width, cam.height, cam.fov) == (160, 120, 45.0)
    assert cam.target == (0.0, 0.0, 0.8)
    with pytest.raises(TypeError, match="look_at"):
        Camera((0, -5, 0), look_at=(0, 0, 0))


_coordinate = st.floats(-20, 20, allow_nan=False)


@settings(max_examples=150, deadline=None)
@given(eye=st.tuples(_coordinate, _coordinate, _coordinate), target=st.tuples(_coordinate, _coordinate, _coordinate),
       fov=st.floats(5, 150), width=st.integers(1, 64), height=st.integers(1, 64), data=st.data())
def test_a_pixels_ray_passes_through_its_centre_and_projects_back_onto_it(eye, target, fov, width, height, data):
    E, T = np.array(eye), np.array(target)
    view = T - E
    dist = np.linalg.norm(view)
    if dist < 1e-3 or np.linalg.norm(np.cross(view / dist, [0, 0, 1])) < 1e-3:
        return                                               # no direction, or looking straight up/down
    cam = Camera(eye, target, fov=fov, width=width, height=height)
    px = data.draw(st.integers(0, width - 1))
    py = data.draw(st.integers(0, height - 1))
    o, d = cam.ray(px, py)
    assert np.allclose(o, E) and np.linalg.norm(d) == pytest.approx(1.0)
    # where the ray meets the screen one unit in front of the eye: a pixel is 1/scale units wide
    n = view / dist
    right = np.cross(n, [0, 0, 1])
    right /= np.linalg.norm(right)
    up = np.cross(right, n)
    S = o + d / (d @ n)
    scale = 0.5 * height / math.tan(math.radians(fov) / 2)
    assert (S - E - n) @ right * scale == pytest.approx(px + 0.5 - width / 2, abs=1e-8)
    assert (S - E - n) @ up * scale == pytest.approx(height / 2 - py - 0.5, abs=1e-8)
    # any point of the ray in front of the near plane projects back onto the pixel's centre
    t = data.draw(st.floats(0.2, 50))
    x, y, _, w = cam.project([o + t * d])[0]
    assert (x, y) == pytest.approx((px + 0.5, py + 0.5), abs=1e-7) and w == pytest.approx(t * (d @ n))


# -- no view builds its own rays -----------------------------------------------------------------------

VIEWS = pathlib.Path(__file__).resolve().parents[2] / "goldman_lib" / "views"


def _builds_rays(source: str, name: str) -> list[str]:
    """Calls in a view that hand directions to a ray intersection (``.hit``, ``.hits``, ``.intersect``,
    ``trace``, ``ray_cast``...) computed in the same function from a grid of pixel coordinates
    (``np.meshgrid``, ``np.mgrid``, ``np.indices``) rather than from a camera."""
    found = []
    tree = ast.parse(source)
    for fn in ast.walk(tree):
        if not isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef)):
            continue
        grids = {"meshgrid", "mgrid", "indices", "ogrid"}
        tainted: set = set()
        for node in ast.walk(fn):
            if isinstance(node, ast.Assign):
                names = {n.id for n in ast.walk(node.value) if isinstance(n, ast.Name)}
                attrs = {n.attr for n in ast.walk(node.value) if isinstance(n, ast.Attribute)}
                if attrs & grids or names & tainted:
                    for target in node.targets:
                        tainted |= {n.id for n in ast.walk(target) if isinstance(n, ast.Name)}
        for node in ast.walk(fn):
            if isinstance(node, ast.Call):
                func = node.func
                called = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
                if called in {"hit", "hits", "intersect", "trace", "ray_cast", "in_shadow", "light_fraction"}:
                    used = {n.id for a in node.args for n in ast.walk(a) if isinstance(n, ast.Name)}
                    if used & tainted:
                        found.append(f"{name}:{node.lineno} {fn.name}")
    return found


def test_the_ray_finder_finds_rays_built_from_a_pixel_grid():
    # what chapter 16's sphere_pixels did before it asked the camera: the finder must catch it
    code = ("def f(size):\n    xs = np.linspace(-1, 1, size)\n    X, Y = np.meshgrid(xs, xs)\n"
            "    d = np.stack([X, Y, -np.ones_like(X)], -1) - EYE\n    return SPHERE.hit(EYE, d)\n")
    assert _builds_rays(code, "probe.py") == ["probe.py:5 f"]
    assert _builds_rays(code.replace("X, Y = np.meshgrid(xs, xs)", "eye, d = camera(size).rays()"), "probe.py") == []


def test_no_view_builds_its_own_rays():
    offenders = [hit for path in sorted(VIEWS.rglob("*.py")) for hit in _builds_rays(path.read_text(), path.name)]
    assert not offenders, f"views that build rays from pixel grids instead of asking goldman_lib.camera: {offenders}"


def test_the_guard_band_clip_keeps_every_vertex_within_guard_image_sizes():
    """Camera.clip_polygon(guard=g) is kernels.polygons.clip_to_view on the camera's public frame
    and frustum slopes, and what it keeps projects within g image sizes of the image's centre."""
    from goldman_lib.kernels.polygons import clip_to_view

    cam = Camera(eye=(0.0, -6.0, 1.0), target=(0.0, 0.0, 0.0), width=40, height=30, fov=50)
    rng = np.random.default_rng(7)
    kept = 0
    for _ in range(50):
        P = rng.normal(scale=30.0, size=(3, 3))
        for g in (1.0, 3.0):
            C = cam.clip_polygon(P, guard=g)
            D = clip_to_view(P, *cam.frame, cam.near, cam.frustum_slopes(g))
            assert (C is None) == (D is None)
            if C is None:
                continue
            kept += 1
            np.testing.assert_array_equal(C, D)
            S = cam.project(C)
            assert np.all(np.abs(S[:, 0] - 20.0) <= g * 20.0 * (1 + 1e-9))
            assert np.all(np.abs(S[:, 1] - 15.0) <= g * 15.0 * (1 + 1e-9))
    assert kept > 10


def test_the_frame_is_orthonormal_and_looks_at_the_target():
    cam = Camera(eye=(1.0, -4.0, 2.0), target=(0.0, 1.0, 0.5), up=(0.0, 0.0, 1.0))
    E, view, right, up = cam.frame
    M = np.array([view, right, up])
    np.testing.assert_allclose(M @ M.T, np.eye(3), atol=1e-15)
    np.testing.assert_allclose(view, (np.array([-1.0, 5.0, -1.5]) / np.linalg.norm([-1.0, 5.0, -1.5])), atol=1e-15)
    assert up[2] > 0


def test_frustum_slopes_refuses_a_guard_below_one():
    with pytest.raises(ValueError, match="guard must be in"):
        Camera(eye=(0, -5, 0), target=(0, 0, 0)).frustum_slopes(0.5)


def test_framing_puts_the_images_top_edge_at_half_height_in_the_targets_plane():
    cam = Camera.framing((0.0, -5.0, 0.0), (0.0, 0.0, 0.0), 2.0, width=10, height=10)
    d = cam.pixel_directions(4.5, -0.5)              # the centre of the image's top edge
    t = 5.0 / d[1]                                   # where the ray meets the plane y = 0
    assert abs(t * d[2] - 2.0) < 1e-12 and abs(t * d[0]) < 1e-12
    assert abs(Camera.framing((0, 0, 6), (0, 0, 0), 6.0, up=(0, 1, 0)).fov - 90.0) < 1e-12


@pytest.mark.parametrize("half, exc, match", [(0.0, ValueError, "half_height"), (-1.0, ValueError, "half_height"),
                                              ("a", TypeError, "half_height")])
def test_framing_refuses_a_bad_half_height(half, exc, match):
    with pytest.raises(exc, match=match):
        Camera.framing((0, -5, 0), (0, 0, 0), half)

"""goldman_lib.shading: Newell, face and vertex normals."""

import numpy as np

from goldman_lib import shading


def test_newell_normal_of_a_tilted_square_and_a_bent_quad():
    sq = np.array([[0, 0, 0], [1, 0, 1], [1, 1, 1], [0, 1, 0]], dtype=float)   # the plane z = x
    assert np.allclose(shading.unit_newell_normal(sq), np.array([-1, 0, 1]) / np.sqrt(2))
    bent = sq + [[0, 0, 0], [0, 0, 0.1], [0, 0, 0], [0, 0, -0.1]]             # not planar: still a unit normal
    n = shading.unit_newell_normal(bent)
    assert abs(np.linalg.norm(n) - 1) < 1e-12 and n[2] > 0


def test_vertex_normals_of_a_closed_cube_point_outwards():
    V = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    hull_faces = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
    T = np.array([[f[0], f[1], f[2]] for f in hull_faces] + [[f[0], f[2], f[3]] for f in hull_faces])
    N = shading.vertex_normals(V, T)
    assert np.allclose(np.linalg.norm(N, axis=1), 1)
    assert np.all((N * (V - 0.5)).sum(1) > 0)       # each vertex normal points away from the centre


# -- chapter 21: polygonal models, the rasteriser and the shading modes ------------------------------

import math

import pytest

from goldman_lib import lighting, rasteriser
from goldman_lib.camera import Camera
from goldman_lib.simple_surfaces import Sphere

SQUARE = np.array([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], dtype=float)   # in the plane y = 0
SQUARE_T = np.array([[0, 1, 2], [0, 2, 3]])
#: tan(fov/2) = 1/2: at distance 4 the square's half-width 1 is 1/4 unit on the plane one unit
#: ahead, and the plane has 10 / (1/2) = 20 pixels per unit, so the square spans 10 +- 5 pixels.
HALF_FOV_TAN_HALF = 2 * math.degrees(math.atan(0.5))


def _square_camera(**kw):
    return Camera(eye=(0, -4, 0), target=(0, 0, 0), up=(0, 0, 1), fov=HALF_FOV_TAN_HALF,
                  width=20, height=20, **kw)


def test_newell_face_normals_and_book_vertex_normals_at_a_cube_corner():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    # three faces at the origin corner of a cube, each seen from outside (normals -x, -y, -z)
    T = np.array([[0, 3, 2], [0, 1, 3], [0, 2, 1]])
    assert np.allclose(shading.newell_face_normals(V, T), [[-1, 0, 0], [0, -1, 0], [0, 0, -1]])
    assert np.allclose(shading.average_vertex_normals(V, T)[0], -np.ones(3) / np.sqrt(3))
    # a big and a small face: the book's average of unit normals ignores area, vertex_normals does not
    V2 = np.array([[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 1], [0, -1, 0]], dtype=float)
    T2 = np.array([[0, 2, 1], [0, 4, 3]])             # normals -z (area 50) and -x (area 1/2)
    assert np.allclose(shading.average_vertex_normals(V2, T2)[0], [-1 / np.sqrt(2), 0, -1 / np.sqrt(2)])
    assert shading.vertex_normals(V2, T2)[0][2] < -0.99


def test_uv_sphere_is_closed_and_outward():
    V, T = shading.uv_sphere(6, 8, radius=2.0, center=(1, 0, 0))
    assert np.allclose(np.linalg.norm(V - [1, 0, 0], axis=1), 2)
    fn = shading.face_normals(V, T)
    assert np.all(np.einsum("ij,ij->i", fn, V[T].mean(1) - [1, 0, 0]) > 0)
    edges = np.sort(np.concatenate([T[:, [0, 1]], T[:, [1, 2]], T[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    assert np.all(counts == 2)                        # every edge on exactly two triangles: closed
    assert len(V) - len(counts) + len(T) == 2         # Euler: V - E + F = 2


def test_gouraud_equals_uniform_on_a_flat_face():
    cam = _square_camera()
    far_light = lighting.Light((0, -1e6, 0))          # so L is the same at every point of the face
    m = lighting.Material(specular=0.0)
    a = shading.render(SQUARE, SQUARE_T, cam, far_light, m, mode="uniform")
    b = shading.render(SQUARE, SQUARE_T, cam, far_light, m, mode="gouraud")
    c = shading.render(SQUARE, SQUARE_T, cam, far_light, m, mode="phong")
    assert np.abs(a - b).max() < 1e-6 and np.abs(a - c).max() < 1e-6
    # ambient 0.2 * 0.2 + diffuse 0.7 * cos 0, grey 0.8
    assert a[10, 10] == pytest.approx([0.8 * (0.04 + 0.7)] * 3)


def _sphere_scene(stacks=26, slices=40, size=96):
    V, T = shading.uv_sphere(stacks, slices)
    cam = Camera(eye=(0, -6, 2), target=(0, 0, 0), fov=30, width=size, height=size)
    return V, T, cam, (lighting.Light((4, -6, 6)),)


def test_phong_matches_exact_per_pixel_lighting_of_the_sphere():
    V, T, cam, lights = _sphere_scene()
    img = shading.render(V, T, cam, lights, mode="phong", normals=V)   # the true normals at the vertices
    o, d = cam.rays()
    t, normals = Sphere([0, 0, 0], 1.0).hit(np.broadcast_to(o, d.shape).reshape(-1, 3), d.reshape(-1, 3))
    hit = np.isfinite(t)
    P = o + t[hit, None] * d.reshape(-1, 3)[hit]
    exact = np.zeros((cam.height * cam.width, 3))
    exact[hit] = lighting.to_image(lighting.intensity(P, P, cam.eye, lights, lighting.Material()))
    exact = exact.reshape(img.shape)
    # away from the silhouette (the normal at least 25 degrees from grazing)
    facing = np.zeros(cam.height * cam.width)
    facing[hit] = np.einsum("ij,ij->i", P, lighting.unit_rows(np.asarray(cam.eye) - P))
    inner = facing.reshape(cam.height, cam.width) > 0.4
    diff = np.abs(img - exact).max(-1)[inner]
    assert inner.sum() > 2000
    assert diff.mean() < 0.005 and diff.max() < 0.06
    # Gouraud misses the highlight's peak: far worse than Phong there
    g = shading.render(V, T, cam, lights, mode="gouraud", normals=V)
    assert np.abs(g - exact).max(-1)[inner].max() > 2 * diff.max()


def test_fast_phong_agrees_with_phong_within_the_taylor_error():
    V, T, cam, lights = _sphere_scene(size=128)
    for m in (lighting.Material(specular=0.0), lighting.Material()):
        a = shading.render(V, T, cam, lights, m, mode="fast_phong", cull_backfaces=True)
        b = shading.render(V, T, cam, lights, m, mode="phong", cull_backfaces=True)
        d = np.abs(a - b).max(-1)
        assert np.percentile(d, 99) < 0.02
        assert (d > 0.05).mean() < 0.002                 # a few grazing triangles at the silhouette


def test_fast_phong_equals_phong_on_a_flat_face_with_far_light_and_eye():
    cam = Camera(eye=(0, -1000, 0), target=(0, 0, 0), fov=0.15, width=20, height=20)
    light = lighting.Light((300, -1e4, 200))
    m = lighting.Material(specular=0.6, exponent=5)
    a = shading.render(SQUARE, SQUARE_T, cam, light, m, mode="fast_phong")
    b = shading.render(SQUARE, SQUARE_T, cam, light, m, mode="phong")
    assert (a > 0).any() and np.abs(a - b).max() < 1e-3


def test_taylor_cosines_error_is_third_order():
    rng = np.random.default_rng(21)
    N0 = lighting.unit_rows(rng.normal(size=(1, 3)) + [0, 0, 3])
    Nx, Ny = rng.normal(size=(1, 3)), rng.normal(size=(1, 3))
    L = lighting.unit_rows([[0.3, 0.2, 1.0]])
    V = lighting.unit_rows([[-0.2, 0.1, 1.0]])
    errors = []
    for h in (0.02, 0.01):
        dq, sq = shading.taylor_cosines(N0, h * Nx, h * Ny, L, V)
        X, Y = 1.0, -0.7
        N = N0[0] + X * h * Nx[0] + Y * h * Ny[0]
        exact_d = L[0] @ N / np.linalg.norm(N)
        R = 2 * (L[0] @ N) * N / (N @ N) - L[0]
        exact_s = R @ V[0]
        basis = np.array([1, X, Y, X * X, X * Y, Y * Y])
        errors.append((abs(basis @ dq[0] - exact_d), abs(basis @ sq[0] - exact_s)))
    (d2, s2), (d1, s1) = errors
    assert 6 < d2 / d1 < 10 and 6 < s2 / s1 < 10      # halving the step divides the error by ~8


def test_forward_differences_are_the_quadratic():
    c = np.array([0.5, -0.2, 0.3, 0.01, -0.02, 0.005])
    X = 3.0 + np.arange(25)
    Y = -4.0
    direct = c[0] + c[1] * X + c[2] * Y + c[3] * X ** 2 + c[4] * X * Y + c[5] * Y ** 2
    assert np.allclose(shading.forward_differences(c, 3.0, -4.0, 25), direct, atol=1e-12)


def test_slerp_normals_stay_unit_and_move_at_constant_angle():
    rng = np.random.default_rng(4)
    N = lighting.unit_rows(rng.normal(size=(200, 3, 3)) + [0, 0, 2])
    W = rng.dirichlet(np.ones(3), size=200)
    out = shading.slerp_normals(N, W)
    assert np.allclose(np.linalg.norm(out, axis=1), 1, atol=1e-12)
    lerp = np.einsum("ki,kij->kj", W, N)
    assert np.linalg.norm(lerp, axis=1).min() < 0.999                # linear interpolation shrinks
    # on the edge N0 -> N1 at weight t the angle from N0 is t times the angle between them
    e = shading.slerp_normals(N[:1], [[0.7, 0.3, 0.0]])[0]
    theta = np.arccos(N[0, 0] @ N[0, 1])
    assert np.arccos(np.clip(e @ N[0, 0], -1, 1)) == pytest.approx(0.3 * theta)


def test_slerp_mode_renders_unit_normals_close_to_phong():
    V, T, cam, lights = _sphere_scene(stacks=8, slices=12, size=64)
    a = shading.render(V, T, cam, lights, mode="slerp")
    b = shading.render(V, T, cam, lights, mode="phong")
    assert 0 < np.abs(a - b).max() < 0.2


def test_render_rejects_bad_arguments():
    cam = _square_camera()
    with pytest.raises(ValueError, match="mode"):
        shading.render(SQUARE, SQUARE_T, cam, lighting.Light(), mode="flat")
    with pytest.raises(TypeError, match="camera"):
        shading.render(SQUARE, SQUARE_T, None, lighting.Light())


# -- Mach bands: the slope of a scan line's profile at the mesh edges (issue 18 §3) ------------------

def test_edge_slopes_of_a_kink_and_of_a_parabola():
    # |x - 10| sampled at the pixel centres x = j + 0.5 - 0.5: slope -1 left of the kink, +1 right of it
    j = np.arange(21)
    e = shading.edge_slopes(np.abs(j - 10.0), np.where(j < 10, 3, 7), width=3)
    assert e.columns.tolist() == [10]
    assert e.left.tolist() == [-1.0] and e.right.tolist() == [1.0] and e.jump.tolist() == [2.0]
    # a smooth x^2 has no kink: its first differences 2k + 1 grow steadily, so the one-sided means
    # over `width` pairs (k = c-1-w .. c-2 on the left, c .. c+w-1 on the right) differ by 2 (w + 1)
    x = np.arange(30.0)
    for w in (1, 2, 4):
        e = shading.edge_slopes(x ** 2, np.where(x < 15, 0, 1), width=w)
        assert e.columns.tolist() == [15]
        assert e.left[0] == pytest.approx(np.mean([2 * k + 1 for k in range(15 - 1 - w, 15 - 1)]))
        assert e.jump[0] == pytest.approx(2 * (w + 1))


def test_edge_slopes_of_gouraud_on_two_triangles():
    # a 16 x 16 square split along its diagonal y = x; on each triangle the intensity is the plane
    # through its vertex values: A (0,0)->0, (16,0)->1, (16,16)->0.5 has slope 1/16 in x;
    # B (0,0)->0, (16,16)->0.5, (0,16)->0.8 has slope -0.3/16 in x
    S = np.array([[0, 0, 0.5], [16, 0, 0.5], [16, 16, 0.5], [0, 16, 0.5]], float)
    f = rasteriser.rasterise_triangles(S, [[0, 1, 2], [0, 2, 3]], 16, 16)
    i = 8
    x = np.arange(16) + 0.5
    ids = f.triangle[i]
    values = np.where(ids == 0, x / 16 - (i + 0.5) / 32, -0.3 * x / 16 + 0.05 * (i + 0.5))
    e = shading.edge_slopes(values, ids)
    assert len(e.columns) == 1 and ids[e.columns[0] - 1] == 1 and ids[e.columns[0]] == 0
    assert e.left[0] == pytest.approx(-0.3 / 16) and e.right[0] == pytest.approx(1 / 16)
    assert e.jump[0] == pytest.approx(1 / 16 + 0.3 / 16)


def test_edge_slopes_skips_the_outline_and_edges_without_room():
    ids = np.array([-1, -1, 0, 0, 0, 0, 1, 2, 2, 2, 2, -1])
    e = shading.edge_slopes(np.linspace(0, 1, 12), ids, width=2)
    assert e.columns.tolist() == []           # 0 -> 1 and 1 -> 2: triangle 1 is one pixel wide
    assert shading.edge_slopes(np.linspace(0, 1, 12), ids, width=1).columns.tolist() == []
    e = shading.edge_slopes(np.c_[np.arange(6.0), np.arange(6.0) * 3], [0, 0, 0, 1, 1, 1], width=2)
    assert e.left.tolist() == [2.0] and e.right.tolist() == [2.0]     # colours: the channels averaged


def test_edge_slopes_and_scanline_profile_reject_bad_input():
    with pytest.raises(ValueError, match="triangle_ids"):
        shading.edge_slopes([0.0, 1.0, 2.0], [0, 1])
    with pytest.raises(ValueError, match="width"):
        shading.edge_slopes([0.0, 1.0, 2.0], [0, 1, 1], width=0)
    with pytest.raises(ValueError, match="values"):
        shading.edge_slopes([0.0, np.nan], [0, 1])
    with pytest.raises(ValueError, match="triangle_ids"):
        shading.edge_slopes([0.0, 1.0], [0.5, 1])
    with pytest.raises(ValueError, match="row"):
        shading.scanline_profile(np.zeros((4, 4, 3)), 4)
    with pytest.raises(ValueError, match="image"):
        shading.scanline_profile(np.zeros(4), 0)


def test_scanline_profile_is_the_grey_level_and_its_differences():
    image = np.zeros((3, 5, 3))
    image[1] = np.c_[np.arange(5.0), 2 * np.arange(5.0), 3 * np.arange(5.0)]
    grey, slope = shading.scanline_profile(image, 1)
    assert grey.tolist() == [0.0, 2.0, 4.0, 6.0, 8.0] and slope.tolist() == [2.0] * 4


def test_gouraud_kinks_at_the_edges_phong_does_not():
    # a coarse sphere seen head-on, lit from near the eye: at the meridian edge in the middle of the
    # picture Gouraud's slope jumps (the piecewise linear intensity's kink: I'' dx per pixel), while
    # Phong's slope changes only by its curvature over the measuring window
    V, T = shading.uv_sphere(6, 12)
    cam = Camera(eye=(0, -6, 0), target=(0, 0, 0), up=(0, 0, 1), fov=28, width=160, height=160)
    light = lighting.Light((-1.0, -5.0, 1.0))
    matte = lighting.Material(colour=(1, 1, 1), ambient=0.1, diffuse=0.9, specular=0.0)
    ids = rasteriser.rasterise_triangles(cam.project(V)[:, :3], T, 160, 160).triangle[86]
    jumps = {}
    for mode in ("gouraud", "phong"):
        image = shading.render(V, T, cam, light, matte, mode=mode, ambient_light=0.3, background=(1, 1, 1))
        e = shading.edge_slopes(shading.scanline_profile(image, 86)[0], ids)
        k = int(np.argmin(np.abs(e.columns - 80)))
        jumps[mode] = e.jump[k]
    assert abs(jumps["gouraud"]) > 5 * abs(jumps["phong"])
    assert jumps["gouraud"] < -0.005            # the slope falls: a bright ridge along the edge

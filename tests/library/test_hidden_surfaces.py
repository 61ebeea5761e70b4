"""goldman_lib.hidden_surfaces: six algorithms on one scene; all but the heedless painter agree pixel
by pixel up to edge pixels; splitting, BSP order and the scan-line spans checked by hand."""

import numpy as np
import pytest

from goldman_lib import hidden_surfaces as hs
from goldman_lib import shading
from goldman_lib.camera import Camera

CORRECT = ["z-buffer", "scan line", "ray casting", "depth sort", "BSP tree"]


@pytest.fixture(scope="module")
def scene():
    polygons, colours = hs.default_scene()
    camera = hs.default_camera(120, 90)
    return polygons, colours, camera, {name: f(polygons, camera) for name, (f, _) in hs.ALGORITHMS.items()}


def test_every_correct_algorithm_draws_the_same_image_up_to_edge_pixels(scene):
    polygons, _, camera, out = scene
    ref = out["z-buffer"].ids
    edges = hs.edge_pixels(ref)
    assert (ref >= 0).sum() > 1500 and set(np.unique(ref)) == {-1, 0, 1, 2, 3, 4}
    for name in CORRECT:
        ids = out[name].ids
        assert ids.shape == (90, 120)
        assert np.array_equal(ids[~edges], ref[~edges]), name
        assert (ids != ref).mean() < 0.01, name
    # the heedless painter gets the cycle and the piercing triangles wrong away from any edge
    assert ((out["heedless painter"].ids != ref) & ~edges).sum() > 100


def test_two_squares_crossing_along_a_line_by_hand():
    # A in the plane y = 0 facing the eye; B in the plane y = x: nearer than A where x < 0
    A = np.array([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], dtype=float)
    B = np.array([[-1, -1, -0.5], [1, 1, -0.5], [1, 1, 0.5], [-1, -1, 0.5]], dtype=float)
    camera = Camera(eye=(0, -10, 0), target=(0, 0, 0), fov=20, width=40, height=40)
    for name in CORRECT:
        ids = hs.ALGORITHMS[name][0]([A, B], camera).ids
        row = ids[20]                                     # the middle row, inside B's height
        assert np.all(row[10:19] == 1) and np.all(row[21:30] == 0), name   # left of centre B, right A
        assert ids[11, 20] == 0 and ids[3, 20] == -1          # above B only A; above A nothing


def test_split_polygon_by_hand():
    front, back = hs.split_polygon([[0, 0, 0], [3, 0, 0], [0, 3, 0]], [1, 0, 0], [1, 0, 0])
    # x >= 1: the triangle (1, 0), (3, 0), (1, 2); x <= 1: the quadrilateral (0,0), (1,0), (1,2), (0,3)
    assert np.allclose(front, [[1, 0, 0], [3, 0, 0], [1, 2, 0]])
    assert np.allclose(back, [[0, 0, 0], [1, 0, 0], [1, 2, 0], [0, 3, 0]])
    f, b = hs.split_polygon([[2, 0, 0], [3, 0, 0], [2, 1, 0]], [1, 0, 0], [1, 0, 0])
    assert b is None and f.shape == (3, 3)
    f, b = hs.split_polygon([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [0, 0, 0], [0, 0, 1])   # in the plane
    assert b is None and f.shape == (3, 3)
    with pytest.raises(ValueError, match="normal"):
        hs.split_polygon([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [0, 0, 0], [0, 0, 0])


def test_bsp_tree_orders_three_parallel_planes_for_either_eye():
    tri = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=float)
    polys = [tri + [0, 0, 1], tri + [0, 0, 0], tri + [0, 0, 2]]      # z = 1, 0, 2; root z = 1
    tree = hs.build_bsp(polys)
    assert [k for k, _ in tree.pieces] == [0] and tree.count() == 3
    assert [k for k, _ in hs.bsp_back_to_front(tree, [0.2, 0.2, 10])] == [1, 0, 2]
    assert [k for k, _ in hs.bsp_back_to_front(tree, [0.2, 0.2, -10])] == [2, 0, 1]
    assert [k for k, _ in hs.bsp_back_to_front(tree, [0.2, 0.2, 1.5])] == [1, 0, 2]


def test_bsp_splits_what_crosses_a_plane(scene):
    polygons = scene[0]
    tree = hs.build_bsp(polygons)
    assert tree.count() > len(polygons)
    order = hs.bsp_back_to_front(tree, scene[2].eye)
    area = lambda P: np.linalg.norm(shading.face_normals(P, [[0, k, k + 1] for k in range(1, len(P) - 1)]).sum(0)) / 2  # noqa: E731
    for k, P in enumerate(polygons):                      # the pieces of each polygon add up to it
        assert sum(area(Q) for j, Q in order if j == k) == pytest.approx(area(P))


def test_depth_sort_splits_the_cycle_of_three_bars(scene):
    polygons, _, camera, out = scene
    bars = polygons[:3]
    r = hs.depth_sort(bars, camera)
    assert len(r.order) > 3                                # no order of whole bars works
    z = hs.z_buffer(bars, camera).ids
    assert np.array_equal(r.ids[~hs.edge_pixels(z)], z[~hs.edge_pixels(z)])
    hp = hs.heedless_painter(bars, camera).ids
    assert (hp != z).sum() > 20


def test_scan_line_spans_cover_exactly_what_it_draws(scene):
    _, _, camera, out = scene
    r = out["scan line"]
    drawn = np.zeros_like(r.ids, dtype=int)
    for row, a, b, k in r.order:
        assert a <= b and np.all(r.ids[row, a:b + 1] == k)
        drawn[row, a:b + 1] += 1
    assert np.array_equal(drawn, (r.ids >= 0).astype(int))
    rows = [s[0] for s in r.order]
    assert rows == sorted(rows)                           # top to bottom


def test_frames_end_at_the_final_image(scene):
    polygons, _, _, _ = scene
    camera = hs.default_camera(40, 30)
    for name, (f, _) in hs.ALGORITHMS.items():
        fr = hs.frames(name, polygons, camera)
        final = f(polygons, camera)
        assert np.array_equal(fr[-1], final.ids), name
        assert len(fr) == (30 if name in ("scan line", "ray casting") else len(final.order)), name
        assert (fr[0] >= 0).sum() <= (fr[-1] >= 0).sum()


def test_shade_and_bad_input():
    polygons, colours = hs.default_scene()
    camera = hs.default_camera(20, 15)
    img = hs.shade(hs.z_buffer(polygons, camera).ids, polygons, colours, camera)
    assert img.shape == (15, 20, 3) and img.min() >= 0 and img.max() <= 1
    with pytest.raises(ValueError, match="algorithm"):
        hs.frames("painter", polygons, camera)
    with pytest.raises(TypeError, match="camera"):
        hs.z_buffer(polygons, None)
    with pytest.raises(ValueError, match=r"polygons\[1\]"):
        hs.z_buffer([polygons[0], [[0, 0, 0], [1, 1, 1]]], camera)

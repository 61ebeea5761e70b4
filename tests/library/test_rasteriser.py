"""goldman_lib.rasteriser: scan conversion with a depth buffer against pixels counted by hand
(Goldman §21.2-21.3, §22.1-22.3)."""

import math

import numpy as np
import pytest

from goldman_lib import rasteriser
from goldman_lib.kernels import polygons
from goldman_lib.camera import Camera

SQUARE = np.array([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], dtype=float)   # in the plane y = 0
SQUARE_T = np.array([[0, 1, 2], [0, 2, 3]])
#: tan(fov/2) = 1/2: at distance 4 the square's half-width 1 is 1/4 unit on the plane one unit
#: ahead, and the plane has 10 / (1/2) = 20 pixels per unit, so the square spans 10 +- 5 pixels.
HALF_FOV_TAN_HALF = 2 * math.degrees(math.atan(0.5))


def _square_camera(**kw):
    return Camera(eye=(0, -4, 0), target=(0, 0, 0), up=(0, 0, 1), fov=HALF_FOV_TAN_HALF, width=20, height=20, **kw)


def test_a_flat_square_facing_the_camera_fills_the_pixels_it_covers():
    cam = _square_camera()
    S = cam.project(SQUARE)[:, :3]
    f = rasteriser.rasterise_triangles(S, SQUARE_T, 20, 20)
    # the square spans pixels 5..14 in x and in y (centres 5.5 .. 14.5): 10 x 10 = 100 pixels
    expected = np.zeros((20, 20), bool)
    expected[5:15, 5:15] = True
    assert np.array_equal(f.triangle >= 0, expected)
    assert np.allclose(f.weights[expected].sum(1), 1) and np.all(f.weights[expected] >= 0)
    assert np.allclose(f.depth[expected], 1 - 0.1 / 4) and np.all(f.depth[~expected] == 1.0)
    # the diagonal from vertex 0 (bottom left) to 2 (top right) splits the square in two halves
    assert (f.triangle == 0).sum() + (f.triangle == 1).sum() == 100 and (f.triangle == 0).sum() == 55


def test_two_overlapping_triangles_the_nearer_wins_in_either_order():
    near = [[0, 0, 0.3], [8, 0, 0.3], [0, 8, 0.3]]
    far = [[0, 0, 0.6], [8, 0, 0.6], [8, 8, 0.6]]
    S = np.array(near + far, dtype=float)
    for T, near_id in (([[0, 1, 2], [3, 4, 5]], 0), ([[3, 4, 5], [0, 1, 2]], 1)):
        f = rasteriser.rasterise_triangles(S, T, 8, 8)
        assert f.triangle[1, 1] == near_id and f.depth[1, 1] == pytest.approx(0.3)
        assert f.triangle[6, 6] == 1 - near_id and f.depth[6, 6] == pytest.approx(0.6)


def test_rasteriser_clips_near_and_far_and_skips_edge_on_triangles():
    S = np.array([[0, 0, 0.5], [4, 0, 0.5], [0, 4, 0.5], [0, 0, 1.5], [4, 0, 1.5], [0, 4, 1.5],
                  [0, 0, 0.5], [2, 2, 0.5], [4, 4, 0.5]])
    f = rasteriser.rasterise_triangles(S, [[3, 4, 5], [6, 7, 8]], 4, 4)
    assert np.all(f.triangle == -1)
    with pytest.raises(ValueError, match="width"):
        rasteriser.rasterise_triangles(S, [[0, 1, 2]], 10 ** 6, 10 ** 6)


def test_gouraud_triangle_by_hand():
    # vertices (0, 0), (4, 0), (0, 4): at the centre (x, y) the weights are (1 - x/4 - y/4, x/4, y/4)
    out = rasteriser.gouraud_triangle([[0, 0], [4, 0], [0, 4]], [0.2, 1.0, 0.6], 4, 4)
    assert out[0, 0] == pytest.approx(0.75 * 0.2 + 0.125 * 1.0 + 0.125 * 0.6)
    assert out[1, 2] == pytest.approx(0.0 * 0.2 + 2.5 / 4 * 1.0 + 1.5 / 4 * 0.6)   # centre (2.5, 1.5) on the edge
    assert out[3, 3] == 0.0 and (out > 0).sum() == 10                      # 4 + 3 + 2 + 1 centres
    assert np.all(rasteriser.gouraud_triangle([[0, 0], [2, 2], [4, 4]], [1, 1, 1], 4, 4) == 0)   # edge-on


def test_clip_half_space_by_hand():
    P = np.array([[0.0, 0, 0], [4, 0, 0], [0, 4, 0]])
    assert polygons.clip_half_space(P, np.array([1.0, 1.0, 1.0])) is P           # untouched: the same array
    assert polygons.clip_half_space(P, np.array([-1.0, -1.0, 0.0])) is None       # nothing of positive area
    # keep x >= 2: s = x - 2 at the vertices -2, 2, -2; the edges cross x = 2 at (2, 0) and (2, 2)
    C = polygons.clip_half_space(P, P[:, 0] - 2)
    assert C.tolist() == [[2.0, 0.0, 0.0], [4.0, 0.0, 0.0], [2.0, 2.0, 0.0]]


def test_triangle_mesh_names_what_is_wrong():
    with pytest.raises(ValueError, match="triangles must hold non-negative integer"):
        rasteriser.triangle_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2.5]])
    with pytest.raises(ValueError, match="positions must hold every vertex"):
        rasteriser.triangle_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 3]])

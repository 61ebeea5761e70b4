"""goldman_lib.shading: Newell, face and vertex normals."""

import numpy as np

from goldman_lib import shading


def test_newell_normal_of_a_tilted_square_and_a_bent_quad():
    sq = np.array([[0, 0, 0], [1, 0, 1], [1, 1, 1], [0, 1, 0]], dtype=float)   # the plane z = x
    assert np.allclose(shading.newell_normal(sq), np.array([-1, 0, 1]) / np.sqrt(2))
    bent = sq + [[0, 0, 0], [0, 0, 0.1], [0, 0, 0], [0, 0, -0.1]]             # not planar: still a unit normal
    n = shading.newell_normal(bent)
    assert abs(np.linalg.norm(n) - 1) < 1e-12 and n[2] > 0


def test_vertex_normals_of_a_closed_cube_point_outwards():
    V = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    hull_faces = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
    T = np.array([[f[0], f[1], f[2]] for f in hull_faces] + [[f[0], f[2], f[3]] for f in hull_faces])
    N = shading.vertex_normals(V, T)
    assert np.allclose(np.linalg.norm(N, axis=1), 1)
    assert np.all((N * (V - 0.5)).sum(1) > 0)       # each vertex normal points away from the centre

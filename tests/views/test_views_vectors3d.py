"""The shared Part II three.js view: arrows, planes and polygons update in place; the chapter-9
products view draws what goldman_lib.vectors computes."""

import numpy as np

from goldman_lib.widgets.vectors3d import VectorScene, vector_products_view


def test_arrows_planes_and_polygons_update_in_place():
    scene = VectorScene()
    scene.add_arrows("a", [[0, 0, 0]], [[1, 0, 0], [0, 2, 0]])
    before = len(scene.scene.children)
    scene.set_arrows("a", [[0, 0, 0]], [[0, 0, 3], [1, 1, 0]])
    assert len(scene.scene.children) == before
    shaft = scene.data("a:shaft")["positions"]
    head = scene.data("a:head")["positions"]
    assert np.allclose(head[0], [0, 0, 3]) and shaft[1, 2] < 3   # tip at the end, shaft stops under the head
    scene.add_plane("p", [0, 0, 1], [0, 0, 2], size=2)
    corners = scene.data("p:fill")["positions"]
    assert np.allclose(corners[:, 2], 1) and np.isclose(np.ptp(corners[:, 0]) * np.ptp(corners[:, 1]), 4)
    scene.add_polygon("q", [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]])
    scene.set_polygon("q", [[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]])
    assert scene.data("q:edges")["positions"][:, 2].tolist() == [1, 1, 1, 1]
    assert scene.to_png().startswith(b"\x89PNG")


def test_products_view_shows_the_library_products():
    view = vector_products_view()
    r = view.set_values(ux=1.0, uy=0.0, uz=0.0, vx=0.0, vy=2.0, vz=0.0)
    assert np.allclose(r["cross"], [0, 0, 2]) and np.allclose(r["sum"], [1, 2, 0])
    assert r["dot"] == 0 and np.isclose(r["angle"], 90) and np.isclose(r["area"], 2) and np.isclose(r["triple"], 4)
    assert "u·v = 0.000" in r["status"]
    r = view.set_values(ux=0.0, uy=0.0, uz=0.0)
    assert r["angle"] is None and "undefined" in r["status"] and view.last_error is None

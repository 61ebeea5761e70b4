"""SceneView: built once, primitives updated in place; geometry helpers against closed forms."""

import numpy as np
import pytest

from goldman_lib.widgets.three import SceneView, grid_triangles, vertex_normals


def test_grid_triangles_cover_the_grid_once_with_consistent_orientation():
    rows, cols = 4, 5
    tri = grid_triangles(rows, cols)
    assert tri.shape == (2 * 3 * 4, 3)
    x, y = np.meshgrid(np.arange(cols, dtype=float), np.arange(rows, dtype=float))
    pos = np.stack([x.ravel(), y.ravel(), np.zeros(x.size)], 1)  # row-major grid in the xy-plane
    p = pos[tri]
    signed = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])[:, 2] / 2
    np.testing.assert_allclose(np.abs(signed), 0.5)          # every triangle is half a unit cell
    assert abs(signed.sum()) == pytest.approx((rows - 1) * (cols - 1))  # one orientation: total area
    assert len({tuple(sorted(t)) for t in tri.tolist()}) == len(tri)


def test_vertex_normals_of_a_sphere_grid_are_radial():
    u, v = np.meshgrid(np.linspace(0.3, 2.8, 30), np.linspace(0, 2 * np.pi, 60), indexing="ij")
    pos = np.stack([np.sin(u) * np.cos(v), np.sin(u) * np.sin(v), np.cos(u)], -1).reshape(-1, 3)
    n = vertex_normals(pos, grid_triangles(30, 60))
    interior = np.abs(np.sum(n * pos, 1))  # |cos| between normal and radius
    assert np.median(interior) > 0.999


def test_scene_updates_buffer_arrays_in_place():
    view = SceneView(width=120, height=90)
    grid = np.stack(np.meshgrid(np.linspace(0, 1, 3), np.linspace(0, 1, 3), indexing="ij"), -1).reshape(-1, 2)
    pos = np.concatenate([grid, np.zeros((9, 1))], 1)
    view.add_mesh("patch", pos, grid_triangles(3, 3))
    view.add_segments("net", pos, [[0, 1], [1, 2]])
    attr = view._items["patch"]["geometry"].attributes["position"]
    renderer = view.renderer
    lifted = pos + [0, 0, 1]
    view.set_mesh("patch", lifted)
    view.set_segments("net", lifted)
    assert view._items["patch"]["geometry"].attributes["position"] is attr and view.renderer is renderer
    np.testing.assert_allclose(attr.array[:, 2], 1.0)
    np.testing.assert_allclose(view._items["net"]["geometry"].attributes["position"].array[:, 2], 1.0)
    assert view.to_png().startswith(b"\x89PNG")


def test_scene_rejects_bad_input_naming_the_parameter():
    view = SceneView(width=120, height=90)
    with pytest.raises(ValueError, match="triangles must have shape"):
        view.add_mesh("m", np.zeros((3, 3)), [[0, 1, 5]])
    view.add_points("p", np.zeros((2, 3)))
    with pytest.raises(ValueError, match="positions for 'p' must keep shape"):
        view.set_points("p", np.zeros((3, 3)))
    with pytest.raises(ValueError, match="positions must be finite"):
        view.set_points("p", [[0, 0, np.nan], [0, 0, 0]])
    with pytest.raises(ValueError, match="already used"):
        view.add_points("p", np.zeros((1, 3)))


def test_replace_mesh_and_segments_change_the_vertex_count_in_place():
    view = SceneView(width=120, height=90)
    pos = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])
    view.add_mesh("m", pos, [[0, 1, 2]])
    view.add_segments("s", pos, [[0, 1]])
    geom = view._items["m"]["geometry"]
    attrs = {k: geom.attributes[k] for k in ("position", "normal", "index")}
    grid = np.stack(np.meshgrid(np.linspace(0, 1, 4), np.linspace(0, 1, 4), indexing="ij"), -1).reshape(-1, 2)
    bigger = np.concatenate([grid, np.zeros((16, 1))], 1)
    tris = grid_triangles(4, 4)
    view.replace_mesh("m", bigger, tris)
    view.replace_segments("s", bigger, [[0, 1], [1, 2], [2, 3]])
    assert view._items["m"]["geometry"] is geom
    assert all(geom.attributes[k] is a for k, a in attrs.items())
    assert geom.attributes["position"].array.shape == (16, 3)
    np.testing.assert_array_equal(geom.attributes["index"].array, tris.ravel())
    np.testing.assert_allclose(geom.attributes["normal"].array, vertex_normals(bigger, tris))
    assert view._items["s"]["geometry"].attributes["position"].array.shape == (6, 3)
    assert view.data("m")["triangles"].shape == (18, 3) and view._items["m"]["object"].frustumCulled is False
    view.set_mesh("m", bigger + [0, 0, 1])  # same-size updates keep working after a replace
    with pytest.raises(ValueError, match="triangles must have shape"):
        view.replace_mesh("m", pos, [[0, 1, 3]])
    with pytest.raises(ValueError, match="segments must have shape"):
        view.replace_segments("s", pos, [[0, 5]])
    assert view.to_png().startswith(b"\x89PNG")


def test_set_color_recolours_a_mesh_in_place():
    from goldman_lib.widgets.three import SceneView

    view = SceneView(width=80, height=60)
    view.add_mesh("m", [[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], color="#112233")
    view.set_color("m", "#ff8000")
    assert view.data("m")["color"] == "#ff8000"
    assert view._items["m"]["object"].material.color == "#ff8000"
    import pytest

    with pytest.raises(ValueError, match="color"):
        view.set_color("m", "not a colour")

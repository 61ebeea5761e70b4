"""Chapter 20 views draw what goldman_lib.solid_modeling computes: the CSG picker's image and the
intervals of its ray change with the tree (§20.2); the B-rep readout names each broken solid's
problem (§20.3); the octree's cells in three.js change with the depth slider (§20.4)."""

import numpy as np

from goldman_lib.views import solid_modeling as sv


def test_csg_view_image_and_intervals_follow_the_tree():
    view = sv.csg_view()
    r = view.set_values(first="ball A (left)", op="union", second="ball B (right)", op2="none", ray_z=0.0)
    # balls of radius 0.85 at x = -0.45 and 0.45, ray (-3, 0, 0) + t (1, 0, 0): by hand
    assert np.allclose(r["intervals"]["first"], [[1.7, 3.4]])
    assert np.allclose(r["intervals"]["second"], [[2.6, 4.3]])
    assert np.allclose(r["intervals"]["result"], [[1.7, 4.3]])
    union = r["image"].copy()
    r = view.set_values(op="intersection")
    assert np.allclose(r["intervals"]["result"], [[2.6, 3.4]])
    inter = r["image"].copy()
    r = view.set_values(op="difference")
    assert np.allclose(r["intervals"]["result"], [[1.7, 2.6]])
    background = np.all(np.isclose(union, sv._BACKGROUND), axis=-1)
    assert background.sum() < np.all(np.isclose(inter, sv._BACKGROUND), axis=-1).sum()   # the lens is smaller
    assert not np.allclose(union, r["image"]) and "A − B" in r["status"]
    assert r["image"].shape == (84, 112, 3) and np.all((r["image"] >= 0) & (r["image"] <= 1))
    im = view.figure.axes[0].images[0]
    assert np.allclose(im.get_array(), r["image"])              # the image is updated in place


def test_csg_view_third_primitive_and_the_ray_slider():
    view = sv.csg_view()
    r = view.set_values(op="union", op2="union", third="half-space z <= 0.2", ray_z=0.0)
    assert r["intervals"]["result"][0, 0] == -1.0                 # the ray at z = 0 is in the half-space:
    assert "[-∞, ∞]" in r["status"]                               # inside for every t
    r = view.set_values(ray_z=1.0, op2="none")
    assert len(r["intervals"]["result"]) == 0 and "empty" in r["status"]   # above both balls
    line = view.figure.axes[0].lines[0]
    assert np.allclose(line.get_ydata(), [1.0, 1.0])


def test_brep_view_reads_out_validity():
    view = sv.brep_view()
    r = view.set_values(solid="torus mesh (8 x 6 quads)")
    assert r["valid"] and r["counts"] == {"V": 48, "E": 96, "F": 48, "L": 48, "S": 1} and r["genus"] == 1
    r = view.set_values(solid="frame (faces with rings)")
    assert r["valid"] and r["counts"]["L"] == 12 and r["genus"] == 1
    for name, words in (("cube missing a face", "gap"), ("cube with a flipped face", "opposite directions"),
                        ("cube with a bent face", "not planar"), ("cube and a dangling vertex", "dangling")):
        r = view.set_values(solid=name)
        assert not r["valid"] and words in r["problems"], name
        assert words in view.readout.value
    r = view.set_values(solid="cube", lift=0.2)         # vertex 7 leaves the top face's plane (it stays in x = y = 0.5)
    assert not r["valid"] and r["problems"].count("not planar") == 1 and "face 1" in r["problems"] and r["euler"] == 2
    assert np.allclose(view.scene.data("lifted")["positions"], [[0.5, 0.5, 0.7]])
    view.set_values(solid="tetrahedron", lift=0.0)
    assert len(view.scene.data("faces")["triangles"]) == 4 and len(view.scene.data("edges")["segments"]) == 6


def test_octree_view_cells_change_with_depth():
    view = sv.octree_view()
    shown = []
    for depth in (2, 3, 4):
        r = view.set_values(depth=depth)
        tri = view.scene.data("full")["triangles"]
        shown.append(r["boxes"])
        assert r["boxes"] == r["counts"]["full"] or (r["counts"]["full"] == 0 and r["boxes"] == 0)
        if r["boxes"]:
            assert len(tri) == 12 * r["boxes"]
        low, high = r["bounds"]
        assert low <= 4 / 3 * np.pi * 0.8 ** 3 <= high
    assert shown[0] < shown[1] < shown[2]
    r = view.set_values(show="full and partial")
    assert len(view.scene.data("partial")["segments"]) == 12 * r["counts"]["partial"]
    r = view.set_values(solid="lens A ∩ B", depth=3)
    assert r["volume"] > 0 and view.last_error is None


def test_csg_render_is_the_ray_traced_tree_with_the_ray_drawn_as_a_rod():
    from goldman_lib import lighting, ray_tracing
    from goldman_lib.simple_surfaces import Cylinder

    values = dict(first="ball A (left)", op="union", second="ball B (right)", op2="none",
                  third="ball C (small, front)", ray_z=-0.6)
    small = dict(width=32, height=24, samples=2, depth=2)
    done = []
    image = sv.csg_render(lambda k, n: done.append((k, n)), **values, **small)
    tree, _ = sv.csg_tree("ball A (left)", "union", "ball B (right)")
    rod = Cylinder([-4, 0, -0.6], [1, 0, 0], 0.012, height=8.0, material=sv._ROD["material"])
    scene = ray_tracing.Scene([tree, rod], (lighting.Light((-1.5, -6.0, 3.0), intensity=1.0),), ambient_light=0.3,
                              background=sv._BACKGROUND)
    assert np.allclose(image, ray_tracing.render(scene, sv._camera(), 32, 24, depth=2, samples=2))
    assert done and done[-1] == (24, 24)                           # the progress reached the last row
    fine = dict(width=128, height=96, samples=2, depth=1)         # rays 0.0125 apart: the rod (0.024 wide) shows
    low, high = (sv.csg_render(None, **dict(values, ray_z=z), **fine) for z in (-0.6, 0.9))
    assert not np.allclose(low, high)                              # the rod follows the ray slider


def test_csg_render_control_renders_the_views_tree():
    view = sv.csg_view()
    rc = sv.csg_render_control(view)
    assert "640 x 480" in rc.button.description and "depth 5" in rc.button.description
    view.set_values(op="intersection")
    image = rc.render(**view.values(), width=16, height=12, samples=1, depth=1)
    assert image.shape == (12, 16, 3) and rc.progress.fraction == 1.0 and rc.last_error is None
    assert np.allclose(image, sv.csg_render(None, **view.values(), width=16, height=12, samples=1, depth=1))
    assert rc.render(**dict(view.values(), op="xor"), width=16, height=12) is None and "op" in rc.last_error

"""Tests of goldman_lib.solid_modeling (Goldman chapter 20) against values worked by hand and closed
forms: Euler's formula on a cube, a tetrahedron and a torus mesh; the Euler-Poincare formula on a
frame; CSG intervals along rays through two overlapping spheres worked by hand; an octree's volume
of a sphere converging to 4/3 pi r^3."""

import math

import numpy as np
import pytest

from goldman_lib import solid_modeling as sm
from goldman_lib.simple_surfaces import Plane, Sphere

A = Sphere([-0.5, 0.0, 0.0], 1.0)
B = Sphere([0.5, 0.0, 0.0], 1.0)


# -- §20.3 B-reps ------------------------------------------------------------------------------------
def test_euler_formula_on_cube_tetrahedron_torus():
    cube, tet, torus = sm.cube(), sm.tetrahedron(), sm.torus_mesh(n=8, m=6)
    assert (cube.V, cube.E, cube.F) == (8, 12, 6)
    assert (tet.V, tet.E, tet.F) == (4, 6, 4)
    assert (torus.V, torus.E, torus.F) == (48, 96, 48)       # nm, 2nm, nm by hand
    assert cube.euler_characteristic == 2 and tet.euler_characteristic == 2
    assert torus.euler_characteristic == 0
    assert cube.is_simple() and tet.is_simple() and not torus.is_simple()
    assert (cube.genus, tet.genus, torus.genus) == (0, 0, 1)
    assert all(s.is_valid() for s in (cube, tet, torus))


def test_euler_poincare_on_a_frame():
    f = sm.frame()
    assert (f.V, f.E, f.F, f.L, f.S) == (16, 24, 10, 12, 1)
    assert 16 - 24 + 10 - (12 - 10) == 2 * (1 - f.genus)
    assert f.genus == 1 and f.is_valid() and not f.is_simple()
    assert f.volume() == pytest.approx(3 * 3 * 1 - 1 * 1 * 1)


def test_counts_functions():
    assert sm.euler_characteristic(6, 12, 8) == 2              # octahedron
    assert sm.genus(8, 12, 6) == 0
    assert sm.genus(16, 32, 16) == 1
    assert sm.genus(16, 24, 10, L=12, S=1) == 1
    assert sm.genus(16, 24, 12, S=2) == 0                      # two separate cubes
    with pytest.raises(ValueError, match="odd"):
        sm.genus(8, 12, 5)
    with pytest.raises(ValueError, match="negative|< 0"):
        sm.genus(10, 12, 6)
    with pytest.raises(ValueError, match="L"):
        sm.genus(8, 12, 6, L=5)


def test_one_cube_and_tetrahedron_for_both_mesh_classes():
    from goldman_lib import subdivision_surfaces as ss

    for brep, mesh, V, E, F in ((sm.cube(2), ss.cube(), 8, 12, 6), (sm.tetrahedron(2), ss.tetrahedron(), 4, 6, 4)):
        # the same tables: at size 2 the B-rep's vertices are the Mesh's, its loops the Mesh's faces
        assert np.array_equal(brep.vertices, mesh.vertices)
        assert [list(f) for f in brep.faces] == mesh.faces.tolist()
        assert np.array_equal(brep.edges(), mesh.edges) and np.array_equal(brep.triangles(), mesh.triangles())
        assert (brep.V, brep.E, brep.F) == (V, E, F) == (mesh.n_vertices, mesh.n_edges, mesh.n_faces)
        back = sm.BRep.from_mesh(mesh)
        assert back.is_valid() and back.faces == brep.faces and np.array_equal(back.vertices, brep.vertices)
        assert np.array_equal(ss.Mesh.from_brep(brep).faces, mesh.faces)
    # volumes by hand: the cube [-1, 1]^3 is 8; the tetrahedron at its alternate corners a third of it
    assert sm.BRep.from_mesh(ss.cube()).volume() == pytest.approx(8.0)
    assert sm.BRep.from_mesh(ss.tetrahedron()).volume() == pytest.approx(8 / 3)
    # a subdivided mesh is a polyhedron too: V - E + F = 2
    smooth = sm.BRep.from_mesh(ss.triangulate(ss.cube()))
    assert smooth.euler_characteristic == 2 and smooth.F == 12
    with pytest.raises(ValueError, match="rings"):
        ss.Mesh.from_brep(sm.frame())
    with pytest.raises(TypeError, match="BRep"):
        ss.Mesh.from_brep([[0, 1, 2]])
    with pytest.raises(TypeError, match="Mesh"):
        sm.BRep.from_mesh("cube")
    with pytest.raises(ValueError, match="vertices"):
        sm.BRep.from_mesh(ss.Mesh([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]]))   # a planar mesh has no B-rep in space


def test_two_shells_counted():
    a, b = sm.cube(), sm.cube(center=(3, 0, 0))
    both = sm.BRep(np.concatenate([a.vertices, b.vertices]), a.faces + [[v + 8 for v in f] for f in b.faces])
    assert both.S == 2 and both.genus == 0 and both.is_valid()


def test_problems_name_what_is_wrong():
    box = sm.cube()
    gap = sm.BRep(box.vertices, box.faces[:5]).problems()
    assert any("lies in 1 face" in p and "gap" in p for p in gap)
    flipped = sm.BRep(box.vertices, [box.faces[0][::-1]] + box.faces[1:]).problems()
    assert any("opposite directions" in p for p in flipped)
    inward = sm.BRep(box.vertices, [f[::-1] for f in box.faces]).problems()
    assert inward and "inward" in inward[0]
    dangling = sm.BRep(np.concatenate([box.vertices, [[5.0, 5.0, 5.0]]]), box.faces).problems()
    assert dangling[0] == "vertices [8] are in no face (dangling vertices)"
    assert "odd" in dangling[1]                     # V = 9 breaks the Euler-Poincare count too
    bent = box.vertices.copy()
    bent[7] += [0.0, 0.0, 0.1]                      # vertex 7 lifts off the top face's plane
    bent_problems = sm.BRep(bent, box.faces).problems()
    assert any("not planar" in p for p in bent_problems)
    fin = sm.BRep(box.vertices, box.faces + [[0, 1, 7]]).problems()
    assert any("3 faces" in p for p in fin)


def test_brep_input_errors():
    with pytest.raises(ValueError, match="faces\\[0\\]"):
        sm.BRep([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 5]])
    with pytest.raises(ValueError, match="at least 3"):
        sm.BRep([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1]])
    with pytest.raises(TypeError, match="faces\\[0\\]\\[1\\]"):
        sm.BRep([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1.5, 2]])


# -- §20.4 octrees -------------------------------------------------------------------------------------
def test_octree_volume_of_sphere_converges():
    r = 0.8
    exact = 4 / 3 * math.pi * r ** 3
    errors = []
    for depth in (3, 4, 5, 6):
        tree = sm.Octree.build(Sphere([0, 0, 0], r), size=2.0, depth=depth)
        low, high = tree.volume(0.0), tree.volume(1.0)
        assert low <= exact <= high
        errors.append(abs(tree.volume() - exact))
        assert high - low <= 16 * math.pi * r ** 2 * (2.0 / 2 ** depth)   # boundary cells hug the surface
    assert errors[-1] < 0.01 * exact
    assert errors[-1] < errors[0]


def test_octree_of_a_slab_by_hand():
    # the slab z < 0.3 in the root cube [-1, 1]^3, depth 3 (cells of edge 0.25): the bottom four octants
    # are full at level 1; above, z in [0, 0.25] is full and z in [0.25, 0.5] partial at level 3;
    # z in [0.5, 1] is empty at level 2
    tree = sm.Octree.build(lambda P: P[:, 2] < 0.3, center=(0, 0, 0), size=2.0, depth=3)
    assert tree.counts() == {"empty": 16, "full": 4 + 64, "partial": 64}
    assert tree.volume(0.0) == 5.0 and tree.volume(1.0) == 6.0


def test_octree_locate_and_cells():
    tree = sm.Octree.build(Sphere([0, 0, 0], 1), size=2.0, depth=3)
    pts = np.array([[0.05, 0.05, 0.05], [0.99, 0.99, 0.99], [-0.3, 0.2, 0.1], [3, 0, 0]])
    idx = tree.locate(pts)
    assert idx[3] == -1
    for i, p in zip(idx[:3], pts[:3]):
        assert np.all(np.abs(p - tree.centers[i]) <= tree.sizes[i] / 2)   # the cell holds the point
        assert tree.children[i, 0] == -1                                 # and is a leaf
    assert tree.states[idx[0]] == sm.FULL and tree.states[idx[1]] == sm.EMPTY
    c, s, st = tree.cells(("full", "partial"))
    assert len(c) == tree.counts()["full"] + tree.counts()["partial"]
    pos, tri = tree.boxes("full")
    assert pos.shape == (8 * tree.counts()["full"], 3) and tri.shape == (12 * tree.counts()["full"], 3)


def test_octree_ray_queries():
    tree = sm.Octree.build(Sphere([0, 0, 0], 1), size=2.0, depth=2)
    idx, t = tree.ray_cells([-3, 0.1, 0.1], [1, 0, 0])
    assert t.tolist() == [2.0, 2.5, 3.0, 3.5]                 # cells of edge 0.5 entered at x = -1, -0.5, 0, 0.5
    assert tree.sizes[idx].tolist() == [0.5] * 4
    t, cell = tree.first_hit([[-3, 0.1, 0.1], [0.1, 0.1, 5]], [[1, 0, 0], [0, 0, -1]])
    assert t.tolist() == [2.5, 4.5]                           # the full cells span [-0.5, 0.5]^3
    assert np.all(tree.states[cell] == sm.FULL)


def test_octree_budget_and_inside_errors():
    with pytest.raises(ValueError, match="depth must be <="):
        sm.Octree.build(Sphere([0, 0, 0], 1), depth=40)
    with pytest.raises(TypeError, match="inside"):
        sm.Octree.build(3.0)
    with pytest.raises(ValueError, match="inside must return"):
        sm.Octree.build(lambda P: P, depth=1)


# -- §20.2 CSG by ray classification -----------------------------------------------------------------
def test_csg_intervals_by_hand_on_the_axis():
    o, d = [[-3.0, 0.0, 0.0]], [[1.0, 0.0, 0.0]]
    # A spans x in [-1.5, 0.5], B spans x in [-0.5, 1.5]; t = x + 3
    assert sm.intervals(A, o, d).tolist() == [[[1.5, 3.5]]]
    assert sm.intervals(B, o, d).tolist() == [[[2.5, 4.5]]]
    assert sm.Union(A, B).intervals(o, d).tolist() == [[[1.5, 4.5]]]
    assert sm.Intersection(A, B).intervals(o, d).tolist() == [[[2.5, 3.5]]]
    assert sm.Difference(A, B).intervals(o, d).tolist() == [[[1.5, 2.5]]]
    assert sm.Difference(B, A).intervals(o, d).tolist() == [[[3.5, 4.5]]]


def test_csg_intervals_by_hand_off_axis():
    # at y = 0.6 each sphere's chord is x = c +- 0.8: A [-1.3, 0.3], B [-0.3, 1.3]; t = x + 3
    o, d = [[-3.0, 0.6, 0.0]], [[1.0, 0.0, 0.0]]
    np.testing.assert_allclose(sm.Union(A, B).intervals(o, d), [[[1.7, 4.3]]], atol=1e-12)
    np.testing.assert_allclose(sm.Intersection(A, B).intervals(o, d), [[[2.7, 3.3]]], atol=1e-12)
    np.testing.assert_allclose(sm.Difference(A, B).intervals(o, d), [[[1.7, 2.7]]], atol=1e-12)
    # a ray between the spheres' caps: y = 0.9 gives chords c +- sqrt(0.19) that do not overlap
    h = math.sqrt(1 - 0.81)
    o, d = [[-3.0, 0.9, 0.0]], [[1.0, 0.0, 0.0]]
    np.testing.assert_allclose(sm.Union(A, B).intervals(o, d),
                               [[[2.5 - h, 2.5 + h], [3.5 - h, 3.5 + h]]], atol=1e-12)
    assert sm.Intersection(A, B).intervals(o, d)[0, :, 0].tolist() == [math.inf]


def test_half_space_and_miss():
    o, d = [[0.0, 0.0, 2.0], [0.0, 0.0, 2.0], [0.0, 0.0, -2.0]], [[0, 0, 1], [1, 0, 0], [1, 0, 0]]
    iv = sm.intervals(Plane([0, 0, 0], [0, 0, 1]), o, d)
    assert iv[0, 0].tolist() == [-math.inf, -2.0]
    assert iv[1, 0].tolist() == [math.inf, math.inf]         # parallel, above: never inside
    assert iv[2, 0].tolist() == [-math.inf, math.inf]        # parallel, below: always inside
    half = sm.Intersection(Sphere([0, 0, 0], 1), Plane([0, 0, 0], [0, 0, 1]))
    assert half.intervals([[0, 0, 5]], [[0, 0, -1]]).tolist() == [[[5.0, 6.0]]]


def test_contains_agrees_with_boolean_of_primitives():
    rng = np.random.default_rng(7)
    P = rng.uniform(-2, 2, size=(5000, 3))
    a, b = A.contains(P), B.contains(P)
    assert np.array_equal(sm.Union(A, B).contains(P), a | b)
    assert np.array_equal(sm.Intersection(A, B).contains(P), a & b)
    assert np.array_equal(sm.Difference(A, B).contains(P), a & ~b)
    C = Plane([0, 0, 0.3], [0, 0, 1])
    assert np.array_equal(sm.Difference(sm.Union(A, B), C).contains(P), (a | b) & ~C.contains(P))


def test_intervals_agree_with_contains_along_rays():
    rng = np.random.default_rng(3)
    C = Plane([0, 0, 0.3], [0, 0, 1])
    tree = sm.Intersection(sm.Difference(A, B), sm.Union(B, C))
    o, d = rng.normal(size=(300, 3)) * 3, rng.normal(size=(300, 3))
    iv = tree.intervals(o, d)
    ts = np.linspace(-8, 8, 801) + 1.234e-4
    inside = tree.contains((o[:, None] + ts[None, :, None] * d[:, None]).reshape(-1, 3)).reshape(300, -1)
    by_iv = ((iv[:, None, :, 0] <= ts[None, :, None]) & (ts[None, :, None] <= iv[:, None, :, 1])).any(-1)
    assert np.array_equal(inside, by_iv)


def test_difference_hit_normal_points_out_of_the_result():
    bite = sm.Difference(A, B)
    t, n = bite.hit([[3.0, 0.0, 0.0]], [[-1.0, 0.0, 0.0]])
    assert t.tolist() == [3.5]                            # x = -0.5, on B's boundary
    np.testing.assert_allclose(n, [[1.0, 0.0, 0.0]])      # B's normal there is -x, reversed
    rng = np.random.default_rng(11)
    o, d = rng.normal(size=(2000, 3)) * 3, rng.normal(size=(2000, 3))
    t, n = bite.hit(o, d)
    f = np.isfinite(t)
    Q = o[f] + t[f, None] * d[f]
    assert not bite.contains(Q + 1e-6 * n[f]).any()       # a step out along the normal leaves the solid
    assert bite.contains(Q - 1e-6 * n[f]).all()           # a step in enters it
    np.testing.assert_allclose(bite.normal(Q), n[f], atol=1e-9)
    assert np.all(n[~f] == 0)


def test_intersect_from_inside_is_the_exit():
    u = sm.Union(A, B)
    assert u.intersect([[0.0, 0.0, 0.0]], [[1.0, 0.0, 0.0]]).tolist() == [1.5]
    assert u.hits([[-3.0, 0.0, 0.0]], [[1.0, 0.0, 0.0]]).tolist() == [[1.5, 4.5]]


def test_combine_intervals_cases():
    c = sm.combine_intervals
    assert c([[0, 1]], [[1, 2]], "union").tolist() == [[0.0, 2.0]]          # touching merge
    assert c([[0, 1]], [[1, 2]], "intersection").tolist() == []               # touching: a point, dropped
    assert c([[0, 1]], [[1, 2]], "difference").tolist() == [[0.0, 1.0]]
    assert c([[0, 5]], [[1, 2]], "difference").tolist() == [[0.0, 1.0], [2.0, 5.0]]   # nested
    assert c([[0, 5]], [[1, 2]], "intersection").tolist() == [[1.0, 2.0]]
    assert c([[0, 2]], [[0, 2]], "difference").tolist() == []                 # identical
    assert c([[0, 2]], [[0, 2]], "union").tolist() == [[0.0, 2.0]]
    assert c([], [[0, 2]], "union").tolist() == [[0.0, 2.0]]                   # empty
    assert c([], [[0, 2]], "intersection").tolist() == []
    assert c([[-math.inf, 1]], [[0, math.inf]], "intersection").tolist() == [[0.0, 1.0]]
    assert c([[3, 4], [0, 1]], [[0.5, 3.5]], "union").tolist() == [[0.0, 4.0]]  # unsorted input
    batch = c([[[0, 1], [2, 3]], [[0, 4], [math.inf, math.inf]]], [[[0.5, 2.5]], [[1, 2]]], "difference")
    assert batch.tolist() == [[[0.0, 0.5], [2.5, 3.0]], [[0.0, 1.0], [2.0, 4.0]]]
    with pytest.raises(ValueError, match="operation"):
        c([[0, 1]], [[0, 1]], "xor")
    with pytest.raises(ValueError, match="start > end"):
        c([[2, 1]], [[0, 1]], "union")


def test_csg_rejects_non_solids():
    with pytest.raises(TypeError, match="a must be a solid"):
        sm.Union(3, B)


def test_octree_of_a_torus_is_not_lost_at_the_root():
    # the nine samples of the root cube [-1, 1]^3 all miss the torus: coarse cells are checked from below
    from goldman_lib.simple_surfaces import Torus
    R, r = 0.6, 0.25
    exact = 2 * math.pi ** 2 * R * r ** 2                       # Pappus
    tree = sm.Octree.build(Torus([0, 0, 0], [0, 0, 1], R, r), size=2.0, depth=5)
    assert tree.volume(0.0) <= exact <= tree.volume(1.0)
    assert abs(tree.volume() - exact) < 0.02 * exact
    assert sm.Octree.build(Torus([0, 0, 0], [0, 0, 1], R, r), size=2.0, depth=5, min_depth=0).counts()["full"] == 0
    # merged back: a solid the coarse samples classify correctly keeps its coarse full cells
    slab = sm.Octree.build(lambda P: P[:, 2] < 0.3, size=2.0, depth=3)
    assert np.sum(slab.levels[slab.leaves()] == 1) == 4


def test_csg_with_chapter_19_solids():
    # a ball drilled by a cylinder along y: the napkin-ring volume 4/3 pi h^3, h^2 = R^2 - a^2
    from goldman_lib.simple_surfaces import Cylinder
    drilled = sm.Difference(Sphere([0, 0, 0], 0.8), Cylinder([0, -1, 0], [0, 1, 0], 0.3, 2.0))
    assert drilled.intervals([[0, -3, 0]], [[0, 1, 0]])[0, 0, 0] == math.inf      # down the hole: nothing
    h = math.sqrt(0.8 ** 2 - 0.3 ** 2)
    np.testing.assert_allclose(drilled.intervals([[0, -3, 0.5]], [[0, 1, 0]])[0],
                               [[3 - math.sqrt(0.64 - 0.25), 3 + math.sqrt(0.64 - 0.25)]], atol=1e-12)
    tree = sm.Octree.build(drilled, size=2.0, depth=5)
    assert tree.volume(0) <= 4 / 3 * math.pi * h ** 3 <= tree.volume(1)
    t, n = drilled.hit([[0, -3, 0.32]], [[0, 1, 0]])          # grazes past the hole's rim onto the ball
    assert np.isfinite(t[0]) and n[0, 1] < 0

"""goldman_lib.subdivision_surfaces against independent references.

- quadrilateral centroid averaging on a regular grid is one level of bicubic B-spline subdivision:
  the explicit 1D Lane-Riesenfeld mask [1, 4, 6, 4, 1]/8 applied in each direction here, and, after
  several levels, the limit positions ([1, 4, 1]/6 in each direction) lie on the tensor-product
  cubic B-spline surface evaluated by scipy.interpolate.BSpline;
- triangle centroid averaging on a regular three-direction grid is one level of the quartic box
  spline: its mask (1+x)^2 (1+y)^2 (1+xy)^2 / 16 is multiplied out here with numpy convolutions;
- the stencils: one level equals the stencils applied by a plain Python loop written here, with
  weights derived by hand in the comments;
- split and average for curves reproduces the uniform B-spline (scipy.interpolate.BSpline);
- topology: V, E, F after a level by closed forms, Euler characteristic preserved;
- bad input: a test per validation rule.

Refined grid points are matched to mesh vertices by their (x, y) coordinates: the nets are laid on
the integer lattice, and every scheme here reproduces linear functions, so the refined (x, y) are the
refined lattice whatever the library's vertex numbering.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.interpolate import BSpline
from scipy.signal import convolve2d

from goldman_lib import subdivision_surfaces as ss

FAST = settings(max_examples=30, deadline=None, derandomize=True)


def lattice_net(m, n, z):
    I, J = np.meshgrid(np.arange(m, dtype=float), np.arange(n, dtype=float), indexing="ij")
    return np.stack([I, J, z], axis=-1)


def refine_with_mask(Z, mask, center):
    """Apply a subdivision mask: fine[I, J] = sum_ij mask[I - 2i + c, J - 2j + c] Z[i, j], with the
    fine lattice point (I, J) at coarse position (I/2, J/2).  Returns {(I, J): value} of the fine
    points whose mask support lies inside the net."""
    m, n = Z.shape
    up = np.zeros((2 * m - 1, 2 * n - 1))
    up[::2, ::2] = Z
    full = convolve2d(up, mask, mode="same") if mask.shape[0] % 2 else None
    out = {}
    h = center
    for I in range(2 * m - 1):
        for J in range(2 * n - 1):
            if h <= I < 2 * m - 1 - h and h <= J < 2 * n - 1 - h:
                out[(I, J)] = full[I, J]
    return out


def by_position(mesh, scale):
    """{(round(x*scale), round(y*scale)): z} for the vertices of a mesh on a refined lattice (the
    ones near the boundary, averaged over fewer faces, move off it and are left out; a point the
    tests expect and do not find is a KeyError)."""
    V = mesh.vertices
    keys = np.round(V[:, :2] * scale).astype(int)
    on = np.abs(keys / scale - V[:, :2]).max(axis=1) < 1e-9
    return {tuple(k): z for k, z, o in zip(keys.tolist(), V[:, 2], on) if o}


# --------------------------------------------------------------------------------------------
# regular grids: the B-spline and box-spline masks
# --------------------------------------------------------------------------------------------

# Lane-Riesenfeld for the cubic: split, then average three times -> (1 + x)^4 / 8 = [1, 4, 6, 4, 1] / 8.
CUBIC_MASK_1D = np.array([1, 4, 6, 4, 1]) / 8
CUBIC_MASK = np.outer(CUBIC_MASK_1D, CUBIC_MASK_1D)
# Quartic three-direction box spline: 4 * prod over (1,0),(1,0),(0,1),(0,1),(1,1),(1,1) of (1 + z^xi)/2.
E1 = np.array([[1.0], [1.0]]) / 2          # (1 + x)/2, x along axis 0
E2 = np.array([[1.0, 1.0]]) / 2            # (1 + y)/2
E3 = np.array([[1.0, 0.0], [0.0, 1.0]]) / 2  # (1 + xy)/2
BOX_MASK = 4 * E1
for factor in (E1, E2, E2, E3, E3):
    BOX_MASK = convolve2d(BOX_MASK, factor)


def test_box_mask_is_loops_regular_stencil():
    assert BOX_MASK.shape == (5, 5) and BOX_MASK.sum() == pytest.approx(4)
    # even-even entries: vertex stencil 10/16 at the centre, 1/16 at the six neighbours
    assert BOX_MASK[2, 2] * 16 == pytest.approx(10)
    for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1)):
        assert BOX_MASK[2 + 2 * di, 2 + 2 * dj] * 16 == pytest.approx(1)
    # the edge point between (0,0) and (1,0): 3/8, 3/8 and the opposite vertices (0,-1)... -> 1/8
    assert BOX_MASK[1, 2] * 8 == pytest.approx(3) and BOX_MASK[3, 2] * 8 == pytest.approx(3)


@FAST
@given(st.integers(5, 8), st.integers(5, 8), st.integers(0, 2 ** 31))
def test_quad_centroid_averaging_is_bicubic_lane_riesenfeld(m, n, seed):
    Z = np.random.default_rng(seed).normal(size=(m, n))
    refined = ss.centroid_averaging(ss.quad_grid(lattice_net(m, n, Z)), 1)
    got = by_position(refined, 2)
    expected = refine_with_mask(Z, CUBIC_MASK, center=3)  # support of [1,4,6,4,1] reaches 2 fine steps + 1
    assert len(expected) > 0
    for key, z in expected.items():
        assert got[key] == pytest.approx(z, abs=1e-12)


@FAST
@given(st.integers(5, 8), st.integers(5, 8), st.integers(0, 2 ** 31))
def test_triangle_centroid_averaging_is_the_quartic_box_spline(m, n, seed):
    Z = np.random.default_rng(seed).normal(size=(m, n))
    refined = ss.centroid_averaging(ss.triangle_grid(lattice_net(m, n, Z)), 1)
    got = by_position(refined, 2)
    expected = refine_with_mask(Z, BOX_MASK, center=3)
    for key, z in expected.items():
        assert got[key] == pytest.approx(z, abs=1e-12)


def test_plain_centroids_are_not_the_box_spline():
    # a delta at the centre: the vertex stays with weight w + (1-w)/2 after the midpoint split, i.e.
    # 2/3 for plain centroids (w = 1/3) against the box spline's 10/16.
    Z = np.zeros((7, 7))
    Z[3, 3] = 1.0
    plain = by_position(ss.centroid_averaging(ss.triangle_grid(lattice_net(7, 7, Z)), 1, self_weight=1 / 3), 2)
    box = by_position(ss.centroid_averaging(ss.triangle_grid(lattice_net(7, 7, Z)), 1), 2)
    assert plain[(6, 6)] == pytest.approx(2 / 3) and box[(6, 6)] == pytest.approx(10 / 16)


@pytest.mark.parametrize("mult,mask", [((4, 4, 0), CUBIC_MASK), ((2, 2, 2), BOX_MASK)], ids=["bicubic", "box222"])
def test_box_spline_split_and_average_against_the_mask(mult, mask):
    rng = np.random.default_rng(3)
    Z = rng.normal(size=(6, 7))
    net = lattice_net(6, 7, Z)
    out = ss.box_spline_split_and_average(net, mult, 1).reshape(-1, 3)
    keys = np.round(out[:, :2] * 2).astype(int)
    np.testing.assert_allclose(keys / 2, out[:, :2], atol=1e-12)
    expected = refine_with_mask(Z, mask, center=3)
    got = {tuple(k): z for k, z in zip(keys.tolist(), out[:, 2])}
    common = set(got) & set(expected)
    assert len(common) >= 0.8 * len(expected)
    for key in common:
        assert got[key] == pytest.approx(expected[key], abs=1e-12)


def test_box_spline_hat_function_reproduces_the_piecewise_constant_split():
    net = np.arange(6.0).reshape(2, 3, 1)
    out = ss.box_spline_split_and_average(net, (1, 1, 0), 1)[..., 0]
    np.testing.assert_array_equal(out, np.kron(net[..., 0], np.ones((2, 2))))


def cubic_surface(Z, x, y):
    """Tensor-product uniform cubic B-spline with control values Z[i, j] at Greville points (i, j)."""
    m, n = Z.shape
    tx, ty = np.arange(-2.0, m + 2), np.arange(-2.0, n + 2)
    Bx = BSpline.design_matrix(x, tx, 3).toarray()
    By = BSpline.design_matrix(y, ty, 3).toarray()
    return np.einsum("pi,ij,pj->p", Bx, Z, By)


def test_quad_limit_positions_lie_on_the_scipy_bicubic_surface():
    rng = np.random.default_rng(7)
    m = n = 8
    Z = rng.normal(size=(m, n))
    levels = 3
    scale = 2 ** levels
    refined = by_position(ss.centroid_averaging(ss.quad_grid(lattice_net(m, n, Z)), levels), scale)
    keys = np.array(list(refined))
    grid = np.full(tuple(keys.max(0) + 1), np.nan)
    grid[keys[:, 0], keys[:, 1]] = list(refined.values())
    limit_mask = np.outer([1, 4, 1], [1, 4, 1]) / 36     # limit of a bicubic vertex point
    limit = convolve2d(grid, limit_mask, mode="valid")
    I, J = np.meshgrid(np.arange(1, grid.shape[0] - 1), np.arange(1, grid.shape[1] - 1), indexing="ij")
    x, y = I.ravel() / scale, J.ravel() / scale
    # only where the surface is defined from the original net (x, y in [1, m-2]) and the grid is full
    keep = (x >= 1) & (x <= m - 2) & (y >= 1) & (y <= n - 2) & np.isfinite(limit.ravel())
    assert keep.sum() > 500
    np.testing.assert_allclose(limit.ravel()[keep], cubic_surface(Z, x[keep], y[keep]), atol=1e-12)


def test_quad_refined_nets_converge_to_the_surface():
    rng = np.random.default_rng(8)
    Z = rng.normal(size=(8, 8))
    errors = []
    for levels in (1, 2, 3):
        scale = 2 ** levels
        refined = by_position(ss.centroid_averaging(ss.quad_grid(lattice_net(8, 8, Z)), levels), scale)
        pts = np.array([(i / scale, j / scale, z) for (i, j), z in refined.items()
                        if 1.5 <= i / scale <= 5.5 and 1.5 <= j / scale <= 5.5])
        errors.append(np.abs(pts[:, 2] - cubic_surface(Z, pts[:, 0], pts[:, 1])).max())
    # control points converge to the surface at rate 1/4 per level (O(h^2))
    assert errors[1] < errors[0] / 3 and errors[2] < errors[1] / 3


# --------------------------------------------------------------------------------------------
# split and average for curves (Lane-Riesenfeld)
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("degree", [0, 1, 2, 3, 4])
def test_split_and_average_is_the_same_uniform_bspline(degree):
    rng = np.random.default_rng(degree)
    n = 9
    P = rng.normal(size=(n, 2))
    Q = ss.split_and_average(P, degree, levels=1)
    assert len(Q) == 2 * n - degree
    t = np.arange(n + degree + 1, dtype=float)
    t2 = np.arange(len(Q) + degree + 1) / 2 + degree / 2
    u = np.linspace(t[degree], t[n] - 1e-9, 57)
    np.testing.assert_allclose(BSpline(t2, Q, degree)(u), BSpline(t, P, degree)(u), atol=1e-12)


def test_closed_split_and_average_doubles_and_keeps_the_centroid():
    P = np.array([[0.0, 0], [4, 0], [4, 4], [0, 4]])
    Q = ss.split_and_average(P, 3, levels=2, closed=True)
    assert Q.shape == (16, 2)
    np.testing.assert_allclose(Q.mean(0), P.mean(0))


# --------------------------------------------------------------------------------------------
# topology
# --------------------------------------------------------------------------------------------

MESHES = {"cube": ss.cube, "tetrahedron": ss.tetrahedron, "octahedron": ss.octahedron,
          "prism5": lambda: ss.prism(5), "star5": lambda: ss.quad_star(5), "star3": lambda: ss.quad_star(3, 1),
          "quad_grid": lambda: ss.quad_grid(lattice_net(4, 5, np.zeros((4, 5)))),
          "triangle_grid": lambda: ss.triangle_grid(lattice_net(4, 5, np.zeros((4, 5))))}
EULER = {"cube": 2, "tetrahedron": 2, "octahedron": 2, "prism5": 2, "star5": 1, "star3": 1, "quad_grid": 1, "triangle_grid": 1}


def count_edges(faces):
    return len({frozenset((int(f[i]), int(f[(i + 1) % len(f)]))) for f in faces for i in range(len(f))})


@pytest.mark.parametrize("name", MESHES)
def test_counts_and_euler_characteristic_by_hand(name):
    mesh = MESHES[name]()
    faces = mesh.faces
    assert mesh.n_edges == count_edges(faces)
    assert mesh.euler_characteristic() == EULER[name]
    assert mesh.n_vertices - count_edges(faces) + len(faces) == EULER[name]


@pytest.mark.parametrize("scheme", ["quad", "triangle"])
@pytest.mark.parametrize("name", MESHES)
def test_each_level_preserves_euler_and_counts(name, scheme):
    mesh = MESHES[name]()
    if scheme == "triangle":
        mesh = ss.triangulate(mesh)
    for _ in range(3):
        V, E, F, corners = mesh.n_vertices, mesh.n_edges, mesh.n_faces, int(mesh.face_sizes.sum())
        nxt = ss.centroid_averaging(mesh, 1, scheme=scheme)
        if scheme == "quad":
            assert (nxt.n_vertices, nxt.n_edges, nxt.n_faces) == (V + E + F, 2 * E + corners, corners)
        else:
            assert (nxt.n_vertices, nxt.n_edges, nxt.n_faces) == (V + E, 2 * E + 3 * F, 4 * F)
        assert nxt.euler_characteristic() == EULER[name]
        ss.Mesh(nxt.vertices, nxt.faces)  # the result passes the full validation (manifold, oriented)
        mesh = nxt


def signed_volume(mesh):
    V, T = mesh.vertices, mesh.triangles()
    return np.einsum("ij,ij->i", V[T[:, 0]], np.cross(V[T[:, 1]], V[T[:, 2]])).sum() / 6


@pytest.mark.parametrize("name,volume", [("cube", 8.0), ("tetrahedron", 8 / 3), ("octahedron", 4 / 3)])
def test_closed_meshes_are_oriented_outwards(name, volume):
    assert signed_volume(MESHES[name]()) == pytest.approx(volume)


def test_refined_closed_meshes_shrink_inside_the_hull_and_stay_outward():
    cube = ss.cube()
    for scheme, mesh in (("quad", cube), ("triangle", ss.triangulate(cube))):
        refined = ss.centroid_averaging(mesh, 3, scheme=scheme)
        assert 0 < signed_volume(refined) < 8
        assert np.abs(refined.vertices).max() <= 1 + 1e-12  # convex combinations stay in the cube


def test_adjacency_of_the_cube():
    cube = ss.cube()
    assert cube.valences.tolist() == [3] * 8 and cube.is_closed and cube.is_quad
    assert (cube.edge_faces >= 0).all()
    for e, (f, g) in zip(cube.edges, cube.edge_faces):
        assert set(e) <= set(cube.faces[f]) and set(e) <= set(cube.faces[g]) and f != g
    np.testing.assert_allclose(np.abs(cube.face_centroids()).sum(1), 1.0)


def test_star_has_one_extraordinary_interior_vertex():
    star = ss.quad_star(5, rings=3)
    interior = ~star.boundary_vertices
    assert star.valences[0] == 5
    assert (star.valences[interior][1:] == 4).all()


# --------------------------------------------------------------------------------------------
# stencils (§30.3.2, §30.4.2)
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("n", [3, 4, 5, 6, 9])
def test_stencil_weights_by_hand(n):
    # quad vertex: v/2 + sum(u)/(4n) + sum(F)/(4n) with F = (v + u_i + d_i + u_{i+1})/4
    #   = (1/2 + 1/16) v + (1/(4n) + 2/(16n)) sum u + 1/(16n) sum d
    assert ss.quad_vertex_stencil(n) == pytest.approx((9 / 16, 3 / (8 * n), 1 / (16 * n)))
    a, b, c = ss.quad_vertex_stencil(n)
    assert a + n * b + n * c == pytest.approx(1)
    assert ss.quad_edge_stencil() == pytest.approx((3 / 8, 1 / 16))
    # triangle vertex with weights (1/4, 3/8, 3/8): v/4 + (3/8)(2/n) sum (v + u_i)/2 = 5/8 v + 3/(8n) sum u
    assert ss.triangle_vertex_stencil(n) == pytest.approx((5 / 8, 3 / (8 * n)))
    # plain centroid: v/3 + (1/3)(2/n) sum (v + u_i)/2 = 2/3 v + 1/(3n) sum u
    assert ss.triangle_vertex_stencil(n, 1 / 3) == pytest.approx((2 / 3, 1 / (3 * n)))
    assert ss.triangle_edge_stencil() == pytest.approx((3 / 8, 1 / 8))
    assert ss.triangle_edge_stencil(1 / 3) == pytest.approx((7 / 18, 1 / 9))


def quad_stencils_by_loop(mesh):
    """One level of the quad scheme from the stencils, vertex by vertex in plain Python."""
    V, faces = mesh.vertices, [list(map(int, f)) for f in mesh.faces]
    nbrs = {v: set() for v in range(len(V))}
    diags = {v: [] for v in range(len(V))}
    for f in faces:
        for i, v in enumerate(f):
            nbrs[v].add(f[(i + 1) % 4])
            nbrs[v].add(f[i - 1])
            diags[v].append(f[(i + 2) % 4])
    out = []
    for v in range(len(V)):
        n = len(nbrs[v])
        out.append(9 / 16 * V[v] + 3 / (8 * n) * sum(V[u] for u in nbrs[v]) + 1 / (16 * n) * sum(V[d] for d in diags[v]))
    for a, b in mesh.edges.tolist():
        wings = [V[u] for f in faces if a in f and b in f for u in f if u not in (a, b)]
        assert len(wings) == 4
        out.append(3 / 8 * (V[a] + V[b]) + 1 / 16 * sum(wings))
    for f in faces:
        out.append(sum(V[u] for u in f) / 4)
    return np.array(out)


def triangle_stencils_by_loop(mesh, w):
    V, faces = mesh.vertices, [list(map(int, f)) for f in mesh.faces]
    nbrs = {v: set() for v in range(len(V))}
    for f in faces:
        for i, v in enumerate(f):
            nbrs[v] |= {f[(i + 1) % 3], f[i - 1]}
    out = []
    for v in range(len(V)):
        n = len(nbrs[v])
        out.append((w + (1 - w) / 2) * V[v] + (1 - w) / (2 * n) * sum(V[u] for u in nbrs[v]))
    for a, b in mesh.edges.tolist():
        opposite = [V[u] for f in faces if a in f and b in f for u in f if u not in (a, b)]
        assert len(opposite) == 2
        out.append((w / 2 + (1 - w) / 3) * (V[a] + V[b]) + (1 - w) / 6 * sum(opposite))
    return np.array(out)


QUAD_CLOSED = {"cube (valence 3)": ss.cube,
               "prism after one level (valence 5)": lambda: ss.centroid_averaging(ss.prism(5), 1),
               "prism6 after one level (valence 6)": lambda: ss.centroid_averaging(ss.prism(6), 1)}
TRI_CLOSED = {"tetrahedron (valence 3)": ss.tetrahedron, "octahedron (valence 4)": ss.octahedron,
              "triangulated cube (valence 3-6)": lambda: ss.triangulate(ss.cube())}


@pytest.mark.parametrize("name", QUAD_CLOSED)
def test_one_quad_level_equals_the_stencils(name):
    mesh = QUAD_CLOSED[name]()
    mesh = mesh.with_vertices(mesh.vertices + np.random.default_rng(1).normal(scale=0.2, size=mesh.vertices.shape))
    expected = quad_stencils_by_loop(mesh)
    np.testing.assert_allclose(ss.centroid_averaging(mesh, 1, scheme="quad").vertices, expected, atol=1e-12)
    np.testing.assert_allclose(ss.apply_stencils(mesh, "quad"), expected, atol=1e-12)


@pytest.mark.parametrize("w", [0.25, 1 / 3])
@pytest.mark.parametrize("name", TRI_CLOSED)
def test_one_triangle_level_equals_the_stencils(name, w):
    mesh = TRI_CLOSED[name]()
    mesh = mesh.with_vertices(mesh.vertices + np.random.default_rng(2).normal(scale=0.2, size=mesh.vertices.shape))
    expected = triangle_stencils_by_loop(mesh, w)
    np.testing.assert_allclose(ss.centroid_averaging(mesh, 1, scheme="triangle", self_weight=w).vertices, expected, atol=1e-12)
    np.testing.assert_allclose(ss.apply_stencils(mesh, "triangle", self_weight=w), expected, atol=1e-12)


# --------------------------------------------------------------------------------------------
# properties
# --------------------------------------------------------------------------------------------

@FAST
@given(st.integers(0, 2 ** 31), st.sampled_from(["cube", "octahedron", "star5", "prism5"]))
def test_affine_invariance(seed, name):
    rng = np.random.default_rng(seed)
    mesh = MESHES[name]()
    A, b = rng.normal(size=(3, 3)), rng.normal(size=3)
    scheme = "quad" if name != "octahedron" else "triangle"
    moved_first = ss.centroid_averaging(mesh.with_vertices(mesh.vertices @ A + b), 2, scheme=scheme).vertices
    moved_after = ss.centroid_averaging(mesh, 2, scheme=scheme).vertices @ A + b
    np.testing.assert_allclose(moved_first, moved_after, atol=1e-9)


def test_planar_meshes_stay_planar_and_the_grid_linear():
    net = lattice_net(5, 6, np.zeros((5, 6)))
    net[..., 2] = 0.3 * net[..., 0] - 0.2 * net[..., 1] + 1  # a plane z = 0.3x - 0.2y + 1
    for mesh, scheme in ((ss.quad_grid(net), "quad"), (ss.triangle_grid(net), "triangle")):
        V = ss.centroid_averaging(mesh, 2, scheme=scheme).vertices
        np.testing.assert_allclose(V[:, 2], 0.3 * V[:, 0] - 0.2 * V[:, 1] + 1, atol=1e-12)


# --------------------------------------------------------------------------------------------
# bad input, a rule at a time
# --------------------------------------------------------------------------------------------

SQUARE = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]


def test_mesh_validation_rules():
    with pytest.raises(ValueError, match="at least 3 vertices; face 1 has 2"):
        ss.Mesh(SQUARE, [[0, 1, 2], [2, 3]])
    with pytest.raises(ValueError, match="existing vertices 0..3; face 0 uses vertex 4"):
        ss.Mesh(SQUARE, [[0, 1, 4]])
    with pytest.raises(ValueError, match="existing vertices"):
        ss.Mesh(SQUARE, [[0, 1, -1]])
    with pytest.raises(ValueError, match="vertex 3 belongs to none"):
        ss.Mesh(SQUARE, [[0, 1, 2]])
    with pytest.raises(ValueError, match="must not repeat a vertex"):
        ss.Mesh(SQUARE, [[0, 1, 1, 2], [0, 2, 3]])
    with pytest.raises(ValueError, match="must not repeat a vertex"):
        ss.Mesh(SQUARE + [[2, 2, 0]], [[0, 1, 2, 1, 4], [0, 2, 3]])
    with pytest.raises(ValueError, match="consistently oriented; faces 0 and 1"):
        ss.Mesh(SQUARE, [[0, 1, 2], [0, 3, 2]])
    with pytest.raises(ValueError, match="at most two faces"):
        ss.Mesh(SQUARE + [[0, 0, 1]], [[0, 1, 2], [1, 0, 3], [0, 1, 4]], check_orientation=False)
    with pytest.raises(TypeError, match="integer vertex indices"):
        ss.Mesh(SQUARE, [[0, 1, 2.5], [0, 2, 3]])
    with pytest.raises(ValueError, match="vertices must be finite"):
        ss.Mesh([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    with pytest.raises(ValueError, match="at least one face"):
        ss.Mesh(SQUARE, [])
    # the same faces, oriented consistently, are fine; mixed sizes are fine
    ss.Mesh(SQUARE, [[0, 1, 2], [0, 2, 3]])
    ss.Mesh(SQUARE + [[0.5, -1, 0]], [[0, 1, 2, 3], [0, 4, 1]])


def test_algorithm_argument_rules():
    with pytest.raises(TypeError, match="mesh must be a Mesh"):
        ss.centroid_averaging([[0, 1, 2]], 1)
    with pytest.raises(ValueError, match="levels must be >= 0"):
        ss.centroid_averaging(ss.cube(), -1)
    with pytest.raises(ValueError, match="scheme must be 'quad' or 'triangle'"):
        ss.centroid_averaging(ss.cube(), 1, scheme="loop")
    with pytest.raises(ValueError, match="triangulate"):
        ss.centroid_averaging(ss.cube(), 1, scheme="triangle")
    with pytest.raises(ValueError, match="self_weight must lie in"):
        ss.centroid_averaging(ss.octahedron(), 1, self_weight=1.5)
    with pytest.raises(ValueError, match="mesh must be closed"):
        ss.apply_stencils(ss.quad_star(5))
    with pytest.raises(ValueError, match="quadrilateral mesh"):
        ss.apply_stencils(ss.prism(5), "quad")
    with pytest.raises(ValueError, match="valence must be >= 3"):
        ss.quad_vertex_stencil(2)
    with pytest.raises(ValueError, match="multiplicities"):
        ss.box_spline_split_and_average(np.zeros((3, 3, 1)), (0, 2, 2))
    with pytest.raises(ValueError, match="too small a net"):
        ss.box_spline_split_and_average(np.zeros((1, 2, 1)), (4, 4, 0))
    with pytest.raises(ValueError, match="too short for degree 5"):
        ss.split_and_average([[0.0], [1.0]], 5)
    with pytest.raises(ValueError, match="points must have shape"):
        ss.quad_grid(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="vertices must hold 8 points"):
        ss.cube().with_vertices(np.zeros((7, 3)))


# -- the local subdivision matrix around one vertex -------------------------------------------------

def _ring(mesh, v):
    """The ring of vertex v read from the faces: (u_1..u_n) in cyclic order, (d_1..d_n) for quads
    (face i = (v, u_i, d_i, u_{i+1})), and the face indices."""
    faces = [(k, list(f)) for k, f in enumerate(mesh.faces) if v in list(f)]
    rotated = {}
    for k, f in faces:
        j = f.index(v)
        f = f[j:] + f[:j]
        rotated[f[1]] = (k, f)
    start = next(iter(rotated))
    us, ds, ks = [], [], []
    u = start
    for _ in range(len(faces)):
        k, f = rotated[u]
        us.append(f[1])
        ks.append(k)
        if len(f) == 4:
            ds.append(f[2])
        u = f[-1]
    return us, ds, ks


def _edge_index(mesh, a, b):
    e = mesh.edges
    return int(np.flatnonzero(((e[:, 0] == a) & (e[:, 1] == b)) | ((e[:, 0] == b) & (e[:, 1] == a)))[0])


def bipyramid(n):
    """A closed triangle mesh with two apices of valence n (an independent construction)."""
    ang = 2 * np.pi * np.arange(n) / n
    V = np.vstack([[0, 0, 1.3], np.column_stack([np.cos(ang), np.sin(ang), 0.1 * np.cos(3 * ang)]), [0, 0, -0.9]])
    faces = [[0, 1 + i, 1 + (i + 1) % n] for i in range(n)] + [[n + 1, 1 + (i + 1) % n, 1 + i] for i in range(n)]
    return ss.Mesh(V, faces)


@pytest.mark.parametrize("n", [3, 4, 5, 7, 12])
def test_local_triangle_matrix_is_the_stencils_of_a_closed_mesh(n):
    mesh = bipyramid(n)
    new = ss.apply_stencils(mesh)
    us, _, _ = _ring(mesh, 0)
    S = ss.local_subdivision_matrix(n, "triangle")
    got = S @ mesh.vertices[[0] + us]
    want = np.vstack([new[0]] + [new[mesh.n_vertices + _edge_index(mesh, 0, u)] for u in us])
    assert np.allclose(got, want, atol=1e-12)
    # by hand at valence 3: v' = 5/8 v + 1/8 sum u; e_i = 3/8 (v + u_i) + 1/8 (u_{i-1} + u_{i+1})
    if n == 3:
        assert np.allclose(S * 8, [[5, 1, 1, 1], [3, 3, 1, 1], [3, 1, 3, 1], [3, 1, 1, 3]])


@pytest.mark.parametrize("name,vertex", [("cube", 0), ("prism after one level", -1)])
def test_local_quad_matrix_is_the_stencils_of_a_closed_mesh(name, vertex):
    mesh = ss.cube() if name == "cube" else ss.centroid_averaging(ss.prism(5), 1)
    v = vertex % mesh.n_vertices
    if name != "cube":   # the face point of a pentagon: valence 5
        v = int(np.flatnonzero(mesh.valences == 5)[0])
    new = ss.apply_stencils(mesh)
    us, ds, ks = _ring(mesh, v)
    n = len(us)
    S = ss.local_subdivision_matrix(n, "quad")
    got = S @ mesh.vertices[[v] + us + ds]
    nv, ne = mesh.n_vertices, mesh.n_edges
    want = np.vstack([new[v]] + [new[nv + _edge_index(mesh, v, u)] for u in us] + [new[nv + ne + k] for k in ks])
    assert np.allclose(got, want, atol=1e-12)


def test_local_eigenvalues_by_hand():
    # triangle scheme: Fourier modes 3/8 + 1/4 cos(2 pi k / n), and 5/8 - 3/8 = 1/4 from the centre
    for n in (3, 4, 5, 6, 9):
        modes = sorted([1.0, 0.25] + [3 / 8 + np.cos(2 * np.pi * k / n) / 4 for k in range(1, n)], key=lambda x: -abs(x))
        assert np.allclose(ss.local_eigenvalues(n), modes, atol=1e-12)
    # valence 3: the subdominant eigenvalue 1/4 is triple (no tangent plane); valence 6: 1/2 double
    assert np.allclose(ss.local_eigenvalues(3)[1:], 0.25)
    assert np.allclose(ss.local_eigenvalues(6)[:4], [1, 0.5, 0.5, 0.25])
    # quad scheme at valence 4 is the bicubic B-spline: 1, 1/2, 1/2, 1/4, ...
    assert np.allclose(ss.local_eigenvalues(4, "quad")[:3], [1, 0.5, 0.5])
    assert np.allclose(ss.local_subdivision_matrix(5, "quad").sum(axis=1), 1)


def test_local_matrix_validation():
    with pytest.raises(ValueError, match="valence must be >= 3"):
        ss.local_subdivision_matrix(2)
    with pytest.raises(ValueError, match="scheme must be"):
        ss.local_subdivision_matrix(5, "loop")
    with pytest.raises(ValueError, match="valence must be <="):
        ss.local_subdivision_matrix(10 ** 6)


# ------------------------------------------------------------------ vertex rules smooth at every valence

def icosahedron():
    """An icosahedron built independently of the library (valence 5 everywhere), outward faces."""
    g = (1 + 5 ** 0.5) / 2
    V = np.array([[-1, g, 0], [1, g, 0], [-1, -g, 0], [1, -g, 0], [0, -1, g], [0, 1, g],
                  [0, -1, -g], [0, 1, -g], [g, 0, -1], [g, 0, 1], [-g, 0, -1], [-g, 0, 1]], float)
    F = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2],
         [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5],
         [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    return ss.Mesh(V, F)


def jittered_icosahedron():
    m = icosahedron()
    return m.with_vertices(m.vertices + np.random.default_rng(13).normal(scale=0.1, size=(12, 3)))


def test_loop_weights_match_trimesh_vertex_for_vertex():
    """One level of the triangle scheme with Loop's weights against trimesh.remesh.subdivide_loop,
    an independent implementation of Loop's scheme with Loop's original beta."""
    trimesh_remesh = pytest.importorskip("trimesh.remesh")
    from scipy.spatial import cKDTree
    meshes = {"tetrahedron": ss.tetrahedron(), "octahedron": ss.octahedron(), "icosahedron": jittered_icosahedron(),
              "bipyramid 7": bipyramid(7)}
    for name, mesh in meshes.items():
        ours = ss.centroid_averaging(mesh, 1, rule="loop")
        V, F = trimesh_remesh.subdivide_loop(mesh.vertices, mesh.faces, iterations=1)
        assert V.shape == ours.vertices.shape, name
        # the old vertices keep their numbers in both; the edge points come in another order: match by position
        assert np.allclose(ours.vertices[:mesh.n_vertices], V[:mesh.n_vertices], atol=1e-12), name
        dist, idx = cKDTree(V).query(ours.vertices)
        assert dist.max() < 1e-12 and len(set(idx.tolist())) == len(V), name
        # and the same triangles, once the numbering is translated
        ours_tris = {tuple(sorted(idx[t].tolist())) for t in ours.faces}
        assert ours_tris == {tuple(sorted(t)) for t in F.tolist()}, name
        # the book's rule differs from Loop's wherever beta differs (every valence but 6)
        plain = ss.centroid_averaging(mesh, 1)
        assert not np.allclose(plain.vertices[:mesh.n_vertices], V[:mesh.n_vertices]), name


@pytest.mark.parametrize("n", [3, 4, 5, 6, 7, 8, 12])
def test_loop_and_warren_beta_by_hand(n):
    # Loop's formula as trimesh writes it, simplified: (40 - (2 cos(2 pi/n) + 3)^2) / (64 n)
    assert ss.loop_beta(n) == pytest.approx((40 - (2 * np.cos(2 * np.pi / n) + 3) ** 2) / (64 * n), abs=1e-15)
    assert ss.warren_beta(n) == pytest.approx(3 / 16 if n == 3 else 3 / (8 * n))
    a, b = ss.triangle_vertex_stencil(n, rule="loop")
    assert b == pytest.approx(ss.loop_beta(n)) and a + n * b == pytest.approx(1)
    # the book's rule is Warren's above valence 3
    assert (ss.triangle_vertex_stencil(n, rule="warren") == pytest.approx(ss.triangle_vertex_stencil(n))) == (n != 3)
    np.testing.assert_allclose(ss.loop_beta(np.array([n, 6])), [ss.loop_beta(n), 1 / 16])


@pytest.mark.parametrize("n", [3, 4, 5, 6, 7, 8, 11])
def test_loop_eigenvalues_by_hand(n):
    """Loop's choice: the Fourier modes 3/8 + 1/4 cos(2 pi k/n) of the ring and the centre's
    5/8 - n beta; the subdominant pair 3/8 + 1/4 cos(2 pi/n) lies strictly above all the rest."""
    for rule, beta in (("loop", ss.loop_beta(n)), ("warren", ss.warren_beta(n))):
        modes = sorted([1.0, 5 / 8 - n * beta] + [3 / 8 + np.cos(2 * np.pi * k / n) / 4 for k in range(1, n)],
                       key=lambda x: -abs(x))
        np.testing.assert_allclose(ss.local_eigenvalues(n, rule=rule), modes, atol=1e-12)
        assert ss.tangent_plane_condition(n, rule=rule)
    assert ss.tangent_plane_condition(n) == (n != 3)
    assert ss.tangent_plane_condition(n, "quad")


def test_local_matrix_with_a_rule_is_the_stencils_of_a_closed_mesh():
    for n in (3, 5, 7):
        mesh = bipyramid(n)
        for rule in ("loop", "warren"):
            new = ss.apply_stencils(mesh, rule=rule)
            assert np.allclose(new, ss.centroid_averaging(mesh, 1, rule=rule).vertices, atol=1e-12)
            us, _, _ = _ring(mesh, 0)
            got = ss.local_subdivision_matrix(n, rule=rule) @ mesh.vertices[[0] + us]
            want = np.vstack([new[0]] + [new[mesh.n_vertices + _edge_index(mesh, 0, u)] for u in us])
            assert np.allclose(got, want, atol=1e-12)


def test_valence_table_and_cone_ratios():
    rows = ss.valence_table(range(3, 9))
    assert [r["valence"] for r in rows] == list(range(3, 9))
    assert [r["centroid"][3] for r in rows] == [False] + [True] * 5
    assert all(r["warren"][3] and r["loop"][3] and r["quad"][3] for r in rows)
    # the cone of the book's rule on the tetrahedron: height over ring radius sqrt(2) at every level;
    # Loop and Warren (the same beta = 3/16 at valence 3) flatten it by lambda_3 / lambda_1 = 1/4 a level
    np.testing.assert_allclose(ss.cone_ratios(ss.tetrahedron(), 4), 2 ** 0.5, atol=1e-12)
    for rule in ("loop", "warren"):
        r = ss.cone_ratios(ss.tetrahedron(), 4, rule=rule)
        np.testing.assert_allclose(r[2:] / r[1:-1], 0.25, atol=1e-9)
    # the octahedron (valence 4) flattens under every rule; the cube under the quad scheme
    for rule in ss.VERTEX_RULES:
        r = ss.cone_ratios(ss.octahedron(), 4, rule=rule)
        assert (np.diff(r) < 0).all()
    assert (np.diff(ss.cone_ratios(ss.cube(), 4)) < 0).all()


def test_rule_argument_rules():
    with pytest.raises(ValueError, match="rule must be one of"):
        ss.centroid_averaging(ss.tetrahedron(), 1, rule="butterfly")
    with pytest.raises(ValueError, match="quad scheme has rule 'centroid' only"):
        ss.centroid_averaging(ss.cube(), 1, rule="loop")
    with pytest.raises(ValueError, match="quad scheme has rule 'centroid' only"):
        ss.local_subdivision_matrix(4, "quad", rule="warren")
    with pytest.raises(ValueError, match="self_weight must be 0.25"):
        ss.centroid_averaging(ss.tetrahedron(), 1, self_weight=1 / 3, rule="loop")
    with pytest.raises(ValueError, match="valence must be >= 3"):
        ss.loop_beta(2)
    with pytest.raises(ValueError, match=r"valence\[0\] must be >= 3"):
        ss.warren_beta(np.array([2, 3]))
    with pytest.raises(TypeError, match="valences must be"):
        ss.valence_table([[3], [4, 5]])
    with pytest.raises(ValueError, match="d = 3"):
        ss.ring_height_ratio(ss.quad_grid(np.zeros((3, 3, 2))), 4)
    # an open mesh: the boundary vertices keep the averaging's points, the interior ones move by the rule
    grid = ss.triangle_grid(np.random.default_rng(3).normal(size=(4, 4, 3)))
    plain, loop = ss.centroid_averaging(grid, 1), ss.centroid_averaging(grid, 1, rule="loop")
    b = grid.boundary_vertices
    assert np.allclose(plain.vertices[:16][b], loop.vertices[:16][b])
    assert np.allclose(plain.vertices[16:], loop.vertices[16:])


# -- angle defects: the cone in curvature (issue 13 §1) -------------------------------------------

def test_angle_defects_by_hand_and_gauss_bonnet():
    # regular tetrahedron: three 60-degree angles at each corner, defect pi; cube: three right angles, pi/2
    np.testing.assert_allclose(ss.angle_defects(ss.tetrahedron()), np.pi, atol=1e-12)
    np.testing.assert_allclose(ss.angle_defects(ss.cube()), np.pi / 2, atol=1e-12)
    # discrete Gauss-Bonnet: the defects of a closed mesh of planar faces add up to 2 pi chi (triangles
    # are always planar: every level of the triangle scheme; the quad scheme's faces bend after a level)
    for mesh in (ss.cube(), ss.prism(5), ss.octahedron()):
        assert ss.angle_defects(mesh).sum() == pytest.approx(2 * np.pi * mesh.euler_characteristic(), abs=1e-9)
    for mesh in (ss.octahedron(), ss.triangulate(ss.prism(5)), ss.triangulate(ss.quad_star(5))):
        for rule in ss.VERTEX_RULES:
            m = ss.centroid_averaging(mesh, 2, "triangle", rule=rule)
            assert ss.angle_defects(m).sum() == pytest.approx(2 * np.pi * m.euler_characteristic(), abs=1e-9)


def test_angle_defects_flat_grid_and_boundary():
    # a planar grid: no curvature inside; a boundary vertex gets pi - (its angles), which is the
    # turning of the boundary there (pi/2 at the square's corners, 0 along its sides)
    g = np.stack(np.meshgrid(np.arange(4.0), np.arange(4.0), indexing="ij"), axis=-1)
    m = ss.quad_grid(np.concatenate([g, np.zeros((4, 4, 1))], axis=-1))
    d = ss.angle_defects(m)
    inside = ~m.boundary_vertices
    np.testing.assert_allclose(d[inside], 0.0, atol=1e-12)
    assert sorted(np.round(d[m.boundary_vertices], 12).tolist()).count(round(np.pi / 2, 12)) == 4
    assert d.sum() == pytest.approx(2 * np.pi, abs=1e-12)     # Gauss-Bonnet with boundary: 2 pi chi, chi = 1


def test_angle_defect_keeps_the_cone_under_the_books_rule_only():
    # the book's rule at valence 3: the corner and its ring keep their shape, so its defect stays pi;
    # Warren's and Loop's flatten it (about 16 times smaller a level)
    book = [ss.angle_defects(ss.centroid_averaging(ss.tetrahedron(), L, "triangle"))[0] for L in range(4)]
    np.testing.assert_allclose(book, np.pi, atol=1e-9)
    for rule in ("warren", "loop"):
        d = [ss.angle_defects(ss.centroid_averaging(ss.tetrahedron(), L, "triangle", rule=rule))[0] for L in (2, 3, 4)]
        assert d[0] > d[1] > d[2] and d[2] < 1e-3


def test_angle_defects_bad_input():
    with pytest.raises(ValueError, match="d = 3"):
        ss.angle_defects(ss.Mesh([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]]))
    with pytest.raises(ValueError, match="zero-length edge"):
        ss.angle_defects(ss.Mesh([[0, 0, 0], [0, 0, 0], [0, 1, 0]], [[0, 1, 2]]))

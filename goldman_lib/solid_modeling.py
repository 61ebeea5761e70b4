"""Solid modeling (Goldman chapter 20): boundary representations, octrees and constructive solid
geometry.

* **B-reps** (§20.3): :class:`BRep` stores a solid by its boundary -- vertices and faces given as
  vertex loops (an outer loop, counterclockwise seen from outside, and optional inner loops, the
  rings of a face with a hole) -- and checks that the boundary can be the surface of a solid:
  every edge in exactly two faces with opposite orientations, no dangling vertices, planar faces,
  and the Euler-Poincare formula ``V - E + F - (L - F) = 2(S - G)`` (Euler's formula
  ``V - E + F = 2`` for a simple polyhedron).  :func:`cube`, :func:`tetrahedron`,
  :func:`torus_mesh` and :func:`frame` build solids to test on.
* **Octrees** (§20.4): :meth:`Octree.build` subdivides a cube around a solid given by an inside
  test; cells are full, empty or partial (on the boundary); volume, point location and ray queries.
* **CSG** (§20.2): :class:`Union`, :class:`Intersection` and :class:`Difference` of solids that
  follow the :mod:`goldman_lib.simple_surfaces` contract, computed by **ray classification**: each
  primitive's inside intervals along each ray (:func:`intervals`) are combined by the boolean
  operation on interval lists (:func:`combine_intervals`), vectorised over rays.  A CSG node is a
  solid with the same contract (``hits``, ``intersect``, ``hit``, ``normal``, ``contains``,
  ``material``), so a ray tracer draws it like a sphere.

Intervals are closed; the booleans are *regularised*: an interval of zero length (a ray grazing a
sphere, two solids touching along the ray) is dropped, and touching intervals of a union merge.

>>> from goldman_lib.simple_surfaces import Sphere
>>> lens = Intersection(Sphere([-0.5, 0, 0], 1), Sphere([0.5, 0, 0], 1))
>>> lens.intervals([[-3, 0, 0]], [[1, 0, 0]]).tolist()          # the lens spans x in [-0.5, 0.5]
[[[2.5, 3.5]]]
>>> euler_characteristic(8, 12, 6)                               # a cube
2
"""

from __future__ import annotations

import numbers
from typing import Callable

import numpy as np

from goldman_lib.kernels import frames, meshes
from goldman_lib.lighting import Material
from goldman_lib.simple_surfaces import EPS, MAX_COORDINATE, Sphere, Surface, rays
from goldman_lib.validation import (MAX_ITEMS, as_float, as_int, as_points, as_tolerance, as_float_array,
                                    within_budget)

__all__ = ["euler_characteristic", "genus", "BRep", "cube", "tetrahedron", "torus_mesh", "frame",
           "Octree", "EMPTY", "FULL", "PARTIAL", "OPERATIONS", "intervals", "combine_intervals",
           "CSG", "Union", "Intersection", "Difference", "MAX_CSG_DEPTH", "MAX_INTERVALS"]


# ==================================================================================================
# §20.3 boundary representations
# ==================================================================================================

def _count(x, name: str) -> int:
    return as_int(x, name, minimum=0)


def euler_characteristic(V, E, F) -> int:
    """Euler's characteristic ``V - E + F`` of a polyhedron with V vertices, E edges and F faces
    (Goldman §20.3): 2 for every simple polyhedron (one shell, no holes through it, faces without
    rings).

    V, E, F: non-negative integers.  Raises TypeError/ValueError naming the count.

    >>> euler_characteristic(4, 6, 4), euler_characteristic(8, 12, 6)   # tetrahedron, cube
    (2, 2)
    """
    return _count(V, "V") - _count(E, "E") + _count(F, "F")


def genus(V, E, F, L=None, S=1) -> int:
    """The genus G (number of handles, holes through the solid) from the Euler-Poincare formula
    ``V - E + F - (L - F) = 2(S - G)`` (Goldman §20.3): ``G = S - (V - E + F - (L - F)) / 2``.

    V, E, F: counts of vertices, edges, faces; L: the number of loops (outer and inner) of all the
    faces (default F: no face has a ring); S: the number of shells (connected boundary surfaces).
    Raises ValueError if the counts give no whole, non-negative genus (they belong to no solid).

    >>> genus(8, 12, 6), genus(16, 32, 16), genus(16, 24, 10, L=12)   # cube, torus mesh, frame
    (0, 1, 1)
    """
    V, E, F = _count(V, "V"), _count(E, "E"), _count(F, "F")
    L = F if L is None else _count(L, "L")
    S = as_int(S, "S", minimum=1)
    if L < F:
        raise ValueError(f"L must be at least F (every face has an outer loop); got L={L} < F={F}")
    chi = V - E + F - (L - F)
    if chi % 2:
        raise ValueError(f"V - E + F - (L - F) = {chi} is odd: by the Euler-Poincare formula it is 2(S - G), "
                         "so these counts belong to no solid")
    g = S - chi // 2
    if g < 0:
        raise ValueError(f"V - E + F - (L - F) = {chi} > 2S = {2 * S}: the genus would be {g} < 0, "
                         "so these counts belong to no solid")
    return g


def _loop(loop, name: str, n_vertices: int) -> tuple[int, ...]:
    if isinstance(loop, (str, bytes)) or not hasattr(loop, "__len__"):
        raise TypeError(f"{name} must be a sequence of vertex indices; got {type(loop).__name__}")
    out = []
    for k, v in enumerate(loop):
        if isinstance(v, bool) or not isinstance(v, (numbers.Integral, np.integer)):
            raise TypeError(f"{name}[{k}] must be a vertex index (an integer); got {v!r}")
        v = int(v)
        if not 0 <= v < n_vertices:
            raise ValueError(f"{name}[{k}] = {v} is not a vertex index (there are {n_vertices} vertices)")
        out.append(v)
    if len(out) < 3:
        raise ValueError(f"{name} must have at least 3 vertices; got {len(out)}")
    for k in range(len(out)):
        if out[k] == out[(k + 1) % len(out)]:
            raise ValueError(f"{name} repeats vertex {out[k]} at positions {k} and {(k + 1) % len(out)} "
                             "(an edge needs two different ends)")
    return tuple(out)


class BRep:
    """A solid by its boundary (Goldman §20.3): vertices and faces as vertex loops.

    vertices: (V, 3).  faces: a list of F loops, each a list of >= 3 vertex indices in
    counterclockwise order seen from outside the solid (so the right-hand normal points out).
    rings: optional ``{face index: [inner loop, ...]}``, the holes in a face, each inner loop in
    clockwise order seen from outside.  tol: the planarity tolerance (distance from a face's plane).

    Counts: ``V``, ``E`` (distinct edges), ``F``, ``L`` (all loops), ``S`` (shells: faces connected
    through shared edges), and ``genus`` by the Euler-Poincare formula.  :meth:`problems` lists what
    keeps the boundary from being a valid solid, in words; :meth:`is_valid` is ``not problems()``.

    Beside ``subdivision_surfaces.Mesh`` (chapter 30's polygon mesh: any dimension, refused unless
    it is a manifold, adjacency cached for subdivision), a BRep holds what a Mesh cannot: faces with
    holes (rings), several shells, and a boundary with faults, described rather than refused, so a
    learner can see why it bounds no solid.  :meth:`from_mesh` and ``Mesh.from_brep`` convert; both
    take their edges, fans and polyhedra from :mod:`goldman_lib.kernels.meshes`.

    >>> box = cube()
    >>> (box.V, box.E, box.F, box.L, box.S, box.genus), box.is_valid()
    ((8, 12, 6, 6, 1, 0), True)
    >>> open_box = BRep(box.vertices, box.faces[:5])
    >>> open_box.problems()[0]
    'edge (1, 3) lies in 1 face (face 0), not 2: the boundary has a gap there'
    """

    def __init__(self, vertices, faces, rings=None, tol: float = 1e-9):
        self.vertices = as_points(vertices, "vertices", dim=3, min_count=1)
        n = len(self.vertices)
        if isinstance(faces, (str, bytes)) or not hasattr(faces, "__len__"):
            raise TypeError(f"faces must be a list of vertex loops; got {type(faces).__name__}")
        self.faces = [_loop(f, f"faces[{i}]", n) for i, f in enumerate(faces)]
        if not self.faces:
            raise ValueError("faces must hold at least one face")
        rings = {} if rings is None else rings
        if not isinstance(rings, dict):
            raise TypeError(f"rings must be a dict {{face index: [inner loops]}}; got {type(rings).__name__}")
        self.rings: dict[int, list[tuple[int, ...]]] = {}
        for key, loops in rings.items():
            if isinstance(key, bool) or not isinstance(key, (numbers.Integral, np.integer)) or not 0 <= key < len(self.faces):
                raise ValueError(f"rings keys must be face indices in [0, {len(self.faces) - 1}]; got {key!r}")
            if isinstance(loops, (str, bytes)) or not hasattr(loops, "__len__"):
                raise TypeError(f"rings[{key}] must be a list of inner loops; got {type(loops).__name__}")
            self.rings[int(key)] = [_loop(r, f"rings[{key}][{j}]", n) for j, r in enumerate(loops)]
        self.tol = as_tolerance(tol, "tol")
        self._edges = self._edge_uses()

    @classmethod
    def from_mesh(cls, mesh, tol: float = 1e-9) -> "BRep":
        """The B-rep of a polygon mesh in space (Goldman §30.3, §30.4 and §20.3): its vertices ``(V, 3)`` and faces
        as outer loops, in order, no rings; its counts, validity and volume then follow.

        >>> from goldman_lib import subdivision_surfaces as ss
        >>> b = BRep.from_mesh(ss.cube()); (b.V, b.E, b.F, b.genus, round(b.volume(), 12))
        (8, 12, 6, 0, 8.0)
        """
        if not hasattr(mesh, "faces") or not hasattr(mesh, "face_sizes") or not hasattr(mesh, "vertices"):
            raise TypeError(f"mesh must be a subdivision_surfaces.Mesh; got {type(mesh).__name__}")
        faces = mesh.faces
        return cls(mesh.vertices, [[int(v) for v in f] for f in faces], tol=tol)

    def _flat_loops(self, with_rings: bool = True):
        """``(corners, sizes)`` of the outer loops (and every ring) for the kernels of meshes."""
        loops = [loop for f in range(self.F) for loop in (self.loops(f) if with_rings else [self.faces[f]])]
        return meshes.flatten(loops)

    # -- counts -----------------------------------------------------------------------------------
    def loops(self, face: int) -> list[tuple[int, ...]]:
        """The loops of face ``face``: its outer loop, then its rings.

        >>> frame().loops(0)
        [(8, 9, 10, 11), (15, 14, 13, 12)]
        """
        face = as_int(face, "face", minimum=0, maximum=len(self.faces) - 1)
        return [self.faces[face]] + self.rings.get(face, [])

    def _edge_uses(self) -> dict[tuple[int, int], list[tuple[int, int, int]]]:
        """{undirected edge (i < j): [(face, i_from, j_to), ...]} over every loop of every face."""
        uses: dict[tuple[int, int], list] = {}
        for f in range(len(self.faces)):
            for loop in self.loops(f):
                for a, b in zip(loop, loop[1:] + loop[:1]):
                    uses.setdefault((min(a, b), max(a, b)), []).append((f, a, b))
        return uses

    @property
    def V(self) -> int:
        """Number of vertices."""
        return len(self.vertices)

    @property
    def E(self) -> int:
        """Number of distinct edges."""
        return len(self._edges)

    @property
    def F(self) -> int:
        """Number of faces."""
        return len(self.faces)

    @property
    def L(self) -> int:
        """Number of loops: one outer loop per face plus every ring."""
        return self.F + sum(len(r) for r in self.rings.values())

    @property
    def S(self) -> int:
        """Number of shells: classes of faces connected through shared edges (union-find)."""
        parent = list(range(self.F))

        def root(i):
            while parent[i] != i:
                parent[i] = parent[parent[i]]
                i = parent[i]
            return i

        for uses in self._edges.values():
            for f, _, _ in uses[1:]:
                parent[root(f)] = root(uses[0][0])
        return len({root(i) for i in range(self.F)})

    @property
    def euler_characteristic(self) -> int:
        """``V - E + F`` (2 for a simple polyhedron)."""
        return euler_characteristic(self.V, self.E, self.F)

    @property
    def genus(self) -> int:
        """The genus from the Euler-Poincare formula (:func:`genus`); ValueError if the counts give none."""
        return genus(self.V, self.E, self.F, self.L, self.S)

    # -- validity ---------------------------------------------------------------------------------
    def problems(self) -> list[str]:
        """What keeps this boundary from bounding a solid, one sentence each (empty when valid):
        edges not in exactly two faces, edges used twice in the same direction (inconsistent
        orientation), dangling vertices, non-planar faces (beyond ``tol``), and counts that break the
        Euler-Poincare formula (an odd ``V - E + F - (L - F)`` or a negative genus)."""
        out = []
        twice = {(min(a, b), max(a, b)) for a, b in meshes.same_direction_edges(*self._flat_loops(), self.V).tolist()}
        for (i, j), uses in sorted(self._edges.items()):
            faces = ", ".join(f"face {f}" for f, _, _ in uses)
            if len(uses) != 2:
                out.append(f"edge ({i}, {j}) lies in {len(uses)} face{'s' if len(uses) != 1 else ''} ({faces}), "
                           f"not 2: the boundary has {'a gap' if len(uses) < 2 else 'a fin (a non-manifold edge)'} there")
            elif (i, j) in twice:
                out.append(f"edge ({i}, {j}) runs from {uses[0][1]} to {uses[0][2]} in both {faces}: the faces must "
                           "traverse a shared edge in opposite directions (one of them is oriented inside out)")
        used = set(v for f in range(self.F) for loop in self.loops(f) for v in loop)
        dangling = [v for v in range(self.V) if v not in used]
        if dangling:
            out.append(f"vertices {dangling} are in no face (dangling vertices)")
        for f in range(self.F):
            pts = self.vertices[list(self.faces[f])]
            normal = frames.unit_newell(pts)
            if not np.any(normal):
                out.append(f"face {f} has no area (its outer loop is degenerate)")
                continue
            allpts = self.vertices[[v for loop in self.loops(f) for v in loop]]
            dist = np.abs((allpts - pts.mean(axis=0)) @ normal).max()
            scale = max(1.0, float(np.abs(pts).max()))
            if dist > self.tol * scale:
                out.append(f"face {f} is not planar: a vertex is {dist:.3g} from the plane of the face "
                           f"(tolerance {self.tol:g})")
        if not out and self.volume() < 0:
            out.append(f"the faces are oriented inward (the enclosed volume {self.volume():.3g} is negative): "
                       "list each loop counterclockwise seen from outside")
        chi = self.V - self.E + self.F - (self.L - self.F)
        if chi % 2:
            out.append(f"V - E + F - (L - F) = {chi} is odd, but the Euler-Poincare formula makes it 2(S - G)")
        elif self.S - chi // 2 < 0:
            out.append(f"V - E + F - (L - F) = {chi} > 2S = {2 * self.S}: the Euler-Poincare formula would need "
                       "a negative genus")
        return out

    def volume(self) -> float:
        """The signed volume enclosed by the faces, by the divergence theorem: the sum over fan
        triangles (of every loop, rings included) of ``det[P0, Pi, Pi+1] / 6``; positive when the
        loops are counterclockwise seen from outside.

        >>> round(cube(2).volume(), 12), round(frame().volume(), 12)
        (8.0, 8.0)
        """
        total = 0.0
        for f in range(self.F):
            for loop in self.loops(f):
                P = self.vertices[list(loop)]
                a, b, c = P[0], P[1:-1], P[2:]
                total += float(np.einsum("ij,ij->i", np.broadcast_to(a, b.shape), np.cross(b, c)).sum()) / 6
        return total

    def is_valid(self) -> bool:
        """True if :meth:`problems` finds nothing."""
        return not self.problems()

    def is_simple(self) -> bool:
        """A simple polyhedron (one shell, genus 0, no rings), for which Euler's formula
        ``V - E + F = 2`` holds."""
        return self.S == 1 and self.L == self.F and self.euler_characteristic == 2

    def edges(self) -> np.ndarray:
        """The distinct edges as vertex index pairs ``(E, 2)``, sorted (every loop's, rings included)."""
        return meshes.edge_table(*self._flat_loops(), self.V)[0]

    def triangles(self) -> np.ndarray:
        """Fan triangles ``(T, 3)`` of the faces without rings (convex faces triangulate correctly),
        for drawing."""
        corners, sizes = meshes.flatten([f for i, f in enumerate(self.faces) if i not in self.rings])
        return meshes.fan_triangles(corners, sizes).reshape(-1, 3)


def cube(size: float = 1.0, center=(0.0, 0.0, 0.0)) -> BRep:
    """The cube of edge ``size`` about ``center`` as a B-rep (Goldman §20.3): V=8, E=12, F=6; the tables
    :data:`goldman_lib.kernels.meshes.CUBE_VERTICES` and ``CUBE_FACES`` (``subdivision_surfaces.cube``'s), scaled.

    >>> cube(2).vertices.max(axis=0).tolist()
    [1.0, 1.0, 1.0]
    """
    size = as_float(size, "size", positive=True)
    c = as_points(center, "center", ndim=1, dim=3)
    return BRep(meshes.CUBE_VERTICES * size / 2 + c, meshes.CUBE_FACES)


def tetrahedron(size: float = 1.0) -> BRep:
    """A regular tetrahedron (alternate corners of a cube of edge ``size``) as a B-rep: V=4, E=6, F=4; the
    tables :data:`goldman_lib.kernels.meshes.TETRAHEDRON_VERTICES` and ``TETRAHEDRON_FACES``, scaled.

    >>> t = tetrahedron(); (t.V, t.E, t.F, t.is_valid())
    (4, 6, 4, True)
    """
    size = as_float(size, "size", positive=True)
    return BRep(meshes.TETRAHEDRON_VERTICES * size / 2, meshes.TETRAHEDRON_FACES)


def torus_mesh(R: float = 1.0, r: float = 0.4, n: int = 8, m: int = 6) -> BRep:
    """A torus as a polyhedron of ``n * m`` quadrilaterals (Goldman §20.3): ``n`` steps around the
    z-axis, ``m`` around the tube; V = nm, E = 2nm, F = nm, so V - E + F = 0 and the genus is 1.
    Each quadrilateral is an isosceles trapezoid, hence planar.  n, m >= 3; R > r > 0.

    >>> t = torus_mesh(); (t.V, t.E, t.F, t.genus, t.is_valid())
    (48, 96, 48, 1, True)
    """
    R, r = as_float(R, "R", positive=True), as_float(r, "r", positive=True)
    if r >= R:
        raise ValueError(f"r must be less than R (a torus with a hole); got r={r}, R={R}")
    n = within_budget(n, "n", cost=lambda k: 3 * k * k, what="the torus mesh", unit="vertices", minimum=3)
    m = within_budget(m, "m", cost=lambda k: 3 * n * k, what="the torus mesh", unit="vertices", minimum=3)
    u = np.arange(n) * 2 * np.pi / n
    w = np.arange(m) * 2 * np.pi / m
    U, W = np.meshgrid(u, w, indexing="ij")
    v = np.stack([(R + r * np.cos(W)) * np.cos(U), (R + r * np.cos(W)) * np.sin(U), r * np.sin(W)], -1).reshape(-1, 3)
    idx = lambda i, j: (i % n) * m + (j % m)  # noqa: E731
    faces = [[idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)] for i in range(n) for j in range(m)]
    return BRep(v, faces)


def frame(outer: float = 3.0, inner: float = 1.0, height: float = 1.0) -> BRep:
    """A square picture frame: a box ``outer x outer x height`` with a square hole ``inner x inner``
    through it (Goldman §20.3).  Its top and bottom faces have rings, so L = F + 2: V=16, E=24,
    F=10, L=12, S=1 and the Euler-Poincare formula gives genus 1.

    >>> f = frame(); (f.V, f.E, f.F, f.L, f.genus, f.is_valid())
    (16, 24, 10, 12, 1, True)
    """
    outer, inner = as_float(outer, "outer", positive=True), as_float(inner, "inner", positive=True)
    height = as_float(height, "height", positive=True)
    if inner >= outer:
        raise ValueError(f"inner must be less than outer; got inner={inner}, outer={outer}")
    a, b, h = outer / 2, inner / 2, height / 2
    square = lambda s: [(-s, -s), (s, -s), (s, s), (-s, s)]  # noqa: E731
    v = np.array([(x, y, z) for z in (-h, h) for s in (a, b) for x, y in square(s)])
    # indices: bottom outer 0-3, bottom inner 4-7, top outer 8-11, top inner 12-15 (counterclockwise from above)
    faces = [[8, 9, 10, 11], [3, 2, 1, 0]]                                     # top, bottom (outer loops)
    faces += [[k, (k + 1) % 4, (k + 1) % 4 + 8, k + 8] for k in range(4)]        # outer sides
    faces += [[4 + (k + 1) % 4, 4 + k, 12 + k, 12 + (k + 1) % 4] for k in range(4)]  # inner sides, facing the hole
    rings = {0: [[15, 14, 13, 12]], 1: [[4, 5, 6, 7]]}
    return BRep(v, faces, rings)


# ==================================================================================================
# §20.4 octrees
# ==================================================================================================

#: Octree cell states.
EMPTY, FULL, PARTIAL = 0, 1, 2
_STATE_NAMES = {"empty": EMPTY, "full": FULL, "partial": PARTIAL}
# 8 corners (in units of the half edge) and the centre: the samples of the classification rule.
_SAMPLES = np.array([[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)] + [[0, 0, 0]], dtype=float)
_OCTANTS = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=float) - 0.5
_BOX_TRIANGLES = np.array([[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4],
                           [2, 6, 7], [2, 7, 3], [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]])
_BOX_EDGES = np.array([[0, 1], [2, 3], [4, 5], [6, 7], [0, 2], [1, 3], [4, 6], [5, 7], [0, 4], [1, 5], [2, 6], [3, 7]])


def _octree_cost(depth: int) -> int:
    """Sample points the build may evaluate at worst (every cell subdivided): 9 (8^(d+1) - 1) / 7."""
    return 9 * (8 ** (depth + 1) - 1) // 7


def _inside_function(inside) -> Callable[[np.ndarray], np.ndarray]:
    if hasattr(inside, "contains") and callable(inside.contains):
        return inside.contains
    if callable(inside):
        return inside
    raise TypeError(f"inside must be a function of (N, 3) points returning (N,) booleans, or a solid with "
                    f".contains; got {type(inside).__name__}")


class Octree:
    """An octree (Goldman §20.4): a cube split recursively into eight, each cell full, empty or
    partial (on the boundary of the solid); only partial cells are split, down to a depth.

    Build with :meth:`Octree.build`.  Nodes are stored in flat arrays: ``centers`` (n, 3),
    ``sizes`` (n,) (edge lengths), ``levels`` (n,), ``states`` (n,) in {EMPTY, FULL, PARTIAL} and
    ``children`` (n, 8) (-1 for a leaf; child k covers the octant with bit 0/1/2 of k set where
    x/y/z is above the centre).  Node 0 is the root; ``alive`` (n,) is False for the cells merged
    back into their parent (see :meth:`build`).
    """

    def __init__(self, inside, center=(0.0, 0.0, 0.0), size: float = 2.0, depth: int = 4,
                 min_depth: int | None = None):
        """``Octree(inside, center, size, depth)`` is ``Octree.build(inside, center, size, depth)``."""
        built = self.build(inside, center, size, depth, min_depth)
        self.__dict__.update(built.__dict__)

    @classmethod
    def _from_arrays(cls, centers, sizes, levels, states, children, depth, alive=None) -> "Octree":
        tree = object.__new__(cls)
        tree.alive = np.ones(len(centers), dtype=bool) if alive is None else alive
        tree.centers, tree.sizes, tree.levels = centers, sizes, levels
        tree.states, tree.children, tree.depth = states, children, depth
        return tree

    @classmethod
    def build(cls, inside, center=(0.0, 0.0, 0.0), size: float = 2.0, depth: int = 4,
              min_depth: int | None = None) -> "Octree":
        """Build the octree of the solid ``inside`` in the cube of edge ``size`` about ``center``
        (Goldman §20.4), subdividing partial cells ``depth`` times.

        inside: a vectorised point test ``(N, 3) -> (N,)`` booleans, or a solid with ``.contains``
        (a sphere, a CSG tree).  **Our classification rule** (the book leaves the test to the
        solid): a cell is full if its 8 corners and its centre are all inside, empty if none is,
        partial otherwise -- so a feature thinner than a cell that misses all nine samples is lost.
        Coarse cells are checked from below: every cell above level ``min_depth`` (default
        ``min(depth, 2)``) is split whatever its samples say, and eight leaf children that are all
        full (or all empty) are merged back into their parent -- so a torus, whose root cube's nine
        samples all miss it, is not called empty.
        depth: 0.. as the work budget allows (at worst every cell splits: 9 (8^(d+1) - 1)/7 sample
        points, at most MAX_ITEMS).  Raises TypeError/ValueError naming the parameter.

        >>> from goldman_lib.simple_surfaces import Sphere
        >>> tree = Octree.build(Sphere([0, 0, 0], 1), size=2.0, depth=1)
        >>> tree.counts()
        {'empty': 0, 'full': 0, 'partial': 8}
        """
        test = _inside_function(inside)
        c = as_points(center, "center", ndim=1, dim=3)
        size = as_float(size, "size", positive=True)
        if size > MAX_COORDINATE or (c.size and np.abs(c).max() > MAX_COORDINATE):
            # the rule of every surface (simple_surfaces.MAX_COORDINATE): cell volumes size**3 and the
            # sample points' coordinates stay representable
            name = "size" if size > MAX_COORDINATE else "center"
            raise ValueError(f"{name} must be at most {MAX_COORDINATE:g} in magnitude (the octree's volumes "
                             f"are cubes of its sizes); got {size if name == 'size' else c.tolist()}")
        depth = within_budget(depth, "depth", cost=_octree_cost, what="the octree (every cell split)",
                              unit="sample points")
        min_depth = min(depth, 2) if min_depth is None else as_int(min_depth, "min_depth", minimum=0, maximum=depth)
        centers, sizes, levels = [c[None]], [np.array([size])], [np.zeros(1, dtype=int)]
        states, parents = [], []
        frontier_c, frontier_s, offset = c[None], size, 0
        for level in range(depth + 1):
            st = cls._classify(test, frontier_c, frontier_s)
            states.append(st)
            n_level = len(frontier_c)
            if level < min_depth:
                split = np.arange(len(st))
            else:
                split = np.flatnonzero(st == PARTIAL) if level < depth else np.array([], dtype=int)
            if len(split) == 0:
                break
            child_c = (frontier_c[split][:, None, :] + _OCTANTS[None] * (frontier_s / 2)).reshape(-1, 3)
            parents.append((offset + split, offset + n_level))
            offset += n_level
            frontier_c, frontier_s = child_c, frontier_s / 2
            centers.append(child_c)
            sizes.append(np.full(len(child_c), frontier_s))
            levels.append(np.full(len(child_c), level + 1))
        centers = np.concatenate(centers)
        total = len(centers)
        children = np.full((total, 8), -1, dtype=int)
        for split_nodes, first_child in parents:
            children[split_nodes] = first_child + np.arange(8 * len(split_nodes)).reshape(-1, 8)
        states = np.concatenate(states)
        levels = np.concatenate(levels)
        alive = np.ones(total, dtype=bool)
        for level in range(min_depth - 1, -1, -1):          # merge forced splits back, bottom up
            nodes = np.flatnonzero((levels == level) & (children[:, 0] >= 0))
            kids = children[nodes]
            kid_states = states[kids]
            leafy = np.all(children[kids, 0] < 0, axis=1)
            same = leafy & np.all(kid_states == kid_states[:, :1], axis=1) & (kid_states[:, 0] != PARTIAL)
            merged = nodes[same]
            states[merged] = kid_states[same, 0]
            alive[kids[same].ravel()] = False
            children[merged] = -1
            states[nodes[~same]] = PARTIAL
        return cls._from_arrays(centers, np.concatenate(sizes), levels, states, children, depth, alive)

    @staticmethod
    def _classify(test, centers: np.ndarray, size: float) -> np.ndarray:
        pts = (centers[:, None, :] + _SAMPLES[None] * (size / 2)).reshape(-1, 3)
        res = test(pts)
        res = np.asarray(res)
        if res.shape != (len(pts),) or res.dtype.kind not in "biuf":
            raise ValueError(f"inside must return one boolean per point, shape ({len(pts)},); got shape "
                             f"{res.shape} and dtype {res.dtype}")
        res = res.astype(bool).reshape(len(centers), len(_SAMPLES))
        return np.where(res.all(axis=1), FULL, np.where(res.any(axis=1), PARTIAL, EMPTY))

    # -- queries --------------------------------------------------------------------------------
    def leaves(self) -> np.ndarray:
        """Indices of the leaf cells (the cells that are not split)."""
        return np.flatnonzero((self.children[:, 0] < 0) & self.alive)

    def _which(self, which) -> np.ndarray:
        if isinstance(which, str):
            which = (which,)
        if isinstance(which, bytes) or not hasattr(which, "__iter__"):
            raise TypeError(f"which must be a state name or a sequence of them; got {which!r}")
        codes = []
        for w in which:
            if not isinstance(w, str) or w not in _STATE_NAMES:
                raise ValueError(f"which must name states among {sorted(_STATE_NAMES)}; got {w!r}")
            codes.append(_STATE_NAMES[w])
        leaves = self.leaves()
        return leaves[np.isin(self.states[leaves], codes)]

    def cells(self, which=("full", "partial")) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Leaf cells in the given states, for drawing: ``(centers (n, 3), sizes (n,), states (n,))``.

        >>> from goldman_lib.simple_surfaces import Sphere
        >>> c, s, st = Octree.build(Sphere([0, 0, 0], 1), size=2.0, depth=2).cells("full")
        >>> len(c), s.tolist()
        (8, [0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5])
        """
        idx = self._which(which)
        return self.centers[idx], self.sizes[idx], self.states[idx]

    def counts(self) -> dict:
        """Number of leaf cells in each state: ``{"empty": .., "full": .., "partial": ..}``."""
        st = self.states[self.leaves()]
        return {name: int(np.sum(st == code)) for name, code in _STATE_NAMES.items()}

    def volume(self, partial: float = 0.5) -> float:
        """The volume of the solid estimated from the octree (Goldman §20.4): the full cells' volume
        plus ``partial`` (in [0, 1]) times the partial cells' volume.  ``partial=0`` gives a lower
        bound and ``partial=1`` an upper bound when the classification is right; the default 0.5
        counts half of each boundary cell.

        >>> from goldman_lib.simple_surfaces import Sphere
        >>> tree = Octree.build(Sphere([0, 0, 0], 1), size=2.0, depth=2)
        >>> tree.volume(0), tree.volume(1)
        (1.0, 8.0)
        """
        partial = as_float(partial, "partial")
        if not 0 <= partial <= 1:
            raise ValueError(f"partial must be in [0, 1] (the fraction of each partial cell counted); got {partial}")
        leaves = self.leaves()
        vol = self.sizes[leaves] ** 3
        st = self.states[leaves]
        return float(vol[st == FULL].sum() + partial * vol[st == PARTIAL].sum())

    def locate(self, points) -> np.ndarray:
        """The leaf cell containing each point (Goldman §20.4), found by descending from the root,
        choosing the child octant by comparing with each cell's centre: (N,) node indices, -1 for
        points outside the root cube.  ``tree.states[index]`` says whether the point is in a full,
        empty or partial cell.

        >>> from goldman_lib.simple_surfaces import Sphere
        >>> tree = Octree.build(Sphere([0, 0, 0], 1), size=2.0, depth=2)
        >>> i = tree.locate([[0.1, 0.1, 0.1], [0.9, 0.9, 0.9], [5, 0, 0]])
        >>> tree.states[i[:2]].tolist(), int(i[2])          # FULL, PARTIAL; outside
        ([1, 2], -1)
        """
        P = np.atleast_2d(as_points(points, "points", ndim=None, dim=3))
        if P.ndim != 2:
            raise ValueError(f"points must have shape (N, 3); got {P.shape}")
        half = self.sizes[0] / 2
        inside = np.all(np.abs(P - self.centers[0]) <= half, axis=1)
        node = np.where(inside, 0, -1)
        for _ in range(self.depth):
            active = node >= 0
            active[active] = self.children[node[active], 0] >= 0
            if not active.any():
                break
            nd = node[active]
            above = P[active] >= self.centers[nd]
            octant = above[:, 0] * 1 + above[:, 1] * 2 + above[:, 2] * 4
            node[active] = self.children[nd, octant]
        return node

    def _slabs(self, o: np.ndarray, d: np.ndarray, idx: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Entry and exit parameters of rays (N,) through the cells idx (n,): (N, n) each (slab test)."""
        lo = self.centers[idx] - self.sizes[idx, None] / 2
        hi = self.centers[idx] + self.sizes[idx, None] / 2
        with np.errstate(divide="ignore", invalid="ignore"):
            inv = 1.0 / d
            t1 = (lo[None] - o[:, None]) * inv[:, None]
            t2 = (hi[None] - o[:, None]) * inv[:, None]
            par = (d == 0)[:, None, :]
            inside_slab = (o[:, None] >= lo[None]) & (o[:, None] <= hi[None])
            tmin = np.where(par, np.where(inside_slab, -np.inf, np.inf), np.minimum(t1, t2))
            tmax = np.where(par, np.where(inside_slab, np.inf, -np.inf), np.maximum(t1, t2))
        return tmin.max(axis=2), tmax.min(axis=2)

    def ray_cells(self, origins, directions) -> tuple[np.ndarray, np.ndarray]:
        """The leaf cells one ray (``origins`` and ``directions`` each one point) passes through for ``t >= 0``, in the order it enters them
        (Goldman §20.4): ``(indices (k,), entry parameters (k,))``.

        >>> from goldman_lib.simple_surfaces import Sphere
        >>> tree = Octree.build(Sphere([0, 0, 0], 1), size=2.0, depth=1)
        >>> idx, t = tree.ray_cells([-3, 0.5, 0.5], [1, 0, 0])
        >>> idx.tolist(), t.tolist()
        ([7, 8], [2.0, 3.0])
        """
        o, d = rays(origins, directions)
        if len(o) != 1:
            raise ValueError(f"origins and directions must be one ray here; got {len(o)}")
        leaves = self.leaves()
        tin, tout = self._slabs(o, d, leaves)
        tin, tout = tin[0], tout[0]
        hit = (tin <= tout) & (tout >= 0)
        order = np.argsort(np.maximum(tin[hit], 0.0), kind="stable")
        return leaves[hit][order], np.maximum(tin[hit], 0.0)[order]

    def first_hit(self, origins, directions, which=("full",)) -> tuple[np.ndarray, np.ndarray]:
        """The first cell in the given states (default full) each ray meets for ``t >= 0``
        (Goldman §20.4): ``(t (N,), cell (N,))``, ``inf`` and -1 on a miss.  Vectorised over rays and
        cells: rays x cells is bounded by MAX_ITEMS.

        >>> from goldman_lib.simple_surfaces import Sphere
        >>> tree = Octree.build(Sphere([0, 0, 0], 1), size=2.0, depth=2)
        >>> t, cell = tree.first_hit([[-3, 0.1, 0.1], [-3, 0.9, 0.9]], [[1, 0, 0], [1, 0, 0]])
        >>> t.tolist()
        [2.5, inf]
        """
        o, d = rays(origins, directions)
        idx = self._which(which)
        if len(o) * max(len(idx), 1) > MAX_ITEMS:
            raise ValueError(f"origins: {len(o)} rays x {len(idx)} cells is over the limit of {MAX_ITEMS:,} "
                             "slab tests; cast fewer rays at once")
        t = np.full(len(o), np.inf)
        cell = np.full(len(o), -1)
        if len(idx) and len(o):
            tin, tout = self._slabs(o, d, idx)
            ok = (tin <= tout) & (tout >= 0)
            tin = np.where(ok, np.maximum(tin, 0.0), np.inf)
            k = tin.argmin(axis=1)
            t = tin[np.arange(len(o)), k]
            cell = np.where(np.isfinite(t), idx[k], -1)
        return t, cell

    def boxes(self, which=("full",)) -> tuple[np.ndarray, np.ndarray]:
        """The leaf cells in the given states as one triangle mesh, for drawing:
        ``(positions (8n, 3), triangles (12n, 3))``."""
        c, s, _ = self.cells(which)
        pos = (c[:, None, :] + (_SAMPLES[:8] / 2)[None] * s[:, None, None]).reshape(-1, 3)
        tri = (_BOX_TRIANGLES[None] + 8 * np.arange(len(c))[:, None, None]).reshape(-1, 3)
        return pos, tri

    def wireframe(self, which=("partial",)) -> tuple[np.ndarray, np.ndarray]:
        """The edges of the leaf cells in the given states: ``(positions (8n, 3), segments (12n, 2))``."""
        c, s, _ = self.cells(which)
        pos = (c[:, None, :] + (_SAMPLES[:8] / 2)[None] * s[:, None, None]).reshape(-1, 3)
        seg = (_BOX_EDGES[None] + 8 * np.arange(len(c))[:, None, None]).reshape(-1, 2)
        return pos, seg


# ==================================================================================================
# §20.2 constructive solid geometry by ray classification
# ==================================================================================================

#: The boolean operations on interval lists, by name: inside the result iff (in a, in b) -> bool.
OPERATIONS = {
    "union": np.logical_or,
    "intersection": np.logical_and,
    "difference": lambda a, b: a & ~b,
}


def _merge(seg: np.ndarray, lab: np.ndarray | None = None):
    """Raw inside segments (N, P, 2) -- positive length, ``[inf, inf]`` where unused, any order --
    merged where they touch or overlap and compacted: (N, M, 2) sorted, inf-padded (and their end
    labels (N, M, 2) if ``lab`` is given).  Only the rows holding a segment are worked on."""
    N = seg.shape[0]
    rows = np.flatnonzero((seg[..., 0] < np.inf).any(axis=1)) if N else np.zeros(0, dtype=int)
    if len(rows) == 0:
        out = np.full((N, 1, 2), np.inf)
        return (out, np.zeros((N, 1, 2), dtype=int)) if lab is not None else out
    sub = seg[rows]
    sub = np.where((sub[..., 1] > sub[..., 0])[..., None], sub, np.inf)   # zero-length pieces are dropped
    order = np.argsort(sub[..., 0], axis=1, kind="stable")
    s = np.take_along_axis(sub[..., 0], order, axis=1)
    e = np.take_along_axis(sub[..., 1], order, axis=1)
    n = len(rows)
    valid = s < np.inf
    reach = np.maximum.accumulate(np.where(valid, e, -np.inf), axis=1)
    prev = np.concatenate([np.full((n, 1), -np.inf), reach[:, :-1]], axis=1)
    new = valid & (s > prev)
    new[:, 0] = valid[:, 0]                       # a first segment starts a run, even at -inf
    nxt_new = np.concatenate([new[:, 1:] | ~valid[:, 1:], np.ones((n, 1), bool)], axis=1)
    last = valid & nxt_new
    count = new.sum(axis=1)
    M = max(int(count.max()), 1)
    out = np.full((N, M, 2), np.inf)
    out_lab = np.zeros((N, M, 2), dtype=int) if lab is not None else None
    rs, cs = np.nonzero(new)
    re_, ce = np.nonzero(last)
    slot = np.arange(len(rs)) - np.repeat(np.cumsum(count) - count, count)
    out[rows[rs], slot, 0] = s[rs, cs]
    out[rows[re_], slot, 1] = reach[re_, ce]
    if lab is not None:
        sub_lab = lab[rows]
        ls = np.take_along_axis(sub_lab[..., 0], order, axis=1)
        le = np.take_along_axis(sub_lab[..., 1], order, axis=1)
        out_lab[rows[rs], slot, 0] = ls[rs, cs]
        out_lab[rows[re_], slot, 1] = le[re_, ce]
    return (out, out_lab) if lab is not None else out


def _primitive_segments(solid, o: np.ndarray, d: np.ndarray, label: int):
    """Raw inside segments of one primitive along each ray (N, K+1, 2), with boundary labels: the
    ray's hits cut the line into K+1 pieces, each classified by ``contains`` at its midpoint.  A ray
    that meets the surface nowhere is one piece, classified at its origin."""
    with np.errstate(all="ignore"):
        h = np.asarray(solid._hits(o, d), dtype=float)
    h = np.sort(np.where(np.isnan(h), np.inf, h), axis=1)
    N, K = h.shape
    seg = np.full((N, K + 1, 2), np.inf)
    lab = np.zeros((N, K + 1, 2), dtype=int)
    active = h[:, 0] < np.inf
    idle = np.flatnonzero(~active)
    if len(idle):
        with np.errstate(all="ignore"):
            whole = idle[np.asarray(solid._contains(o[idle]), dtype=bool)]
        seg[whole, 0] = (-np.inf, np.inf)
        lab[whole, 0] = label
    act = np.flatnonzero(active)
    if len(act):
        ha = h[act]
        n = len(act)
        breaks = np.concatenate([np.full((n, 1), -np.inf), ha, np.full((n, 1), np.inf)], axis=1)
        lo, hi = breaks[:, :-1], breaks[:, 1:]
        fin_hi = np.isfinite(hi)
        with np.errstate(all="ignore"):
            mid = np.where(fin_hi, 0.5 * (lo + hi), lo + 1.0 + np.abs(lo))
            mid[:, 0] = ha[:, 0] - 1.0 - np.abs(ha[:, 0])
        mid = np.where(np.isfinite(mid), mid, 0.0)
        pts = o[act, None, :] + mid[..., None] * d[act, None, :]
        with np.errstate(all="ignore"):
            inside = np.asarray(solid._contains(pts.reshape(-1, 3)), dtype=bool).reshape(lo.shape)
        keep = inside & (hi > lo)
        r, c = np.nonzero(keep)
        seg[act[r], c, 0] = lo[r, c]
        seg[act[r], c, 1] = hi[r, c]
        lab[act[r], c] = label
    return seg, lab


def _combine_raw(a, b, op, la=None, lb=None, operation="union"):
    """Raw inside segments of ``a op b`` from raw (or merged) segment lists (N, Ma, 2), (N, Mb, 2):
    the sorted ends of both cut the line into elementary pieces, each inside a list iff some
    interval of it covers the piece; the boolean ``op`` of the two memberships classifies it.  Rays
    where one list is empty are settled without the sweep."""
    N = a.shape[0]
    has_a = (a[..., 0] < np.inf).any(axis=1)
    has_b = (b[..., 0] < np.inf).any(axis=1)
    both = np.flatnonzero(has_a & has_b)
    labelled = la is not None
    W = 1
    if len(both):
        A, B = a[both], b[both]
        n = len(both)
        ends = np.concatenate([A.reshape(n, -1), B.reshape(n, -1)], axis=1)
        order = np.argsort(ends, axis=1, kind="stable")
        breaks = np.take_along_axis(ends, order, axis=1)
        used = int(np.max(np.sum(breaks < np.inf, axis=1)))
        width = max(min(breaks.shape[1], used + 1), 2)
        breaks, order = breaks[:, :width], order[:, :width]
        lo, hi = breaks[:, :-1], breaks[:, 1:]
        # an interval covers the piece (lo, hi) iff it starts at or before lo and ends after it (no
        # end lies strictly between lo and hi); those ending at or before lo started there too, so
        # the count #(starts <= lo) - #(ends <= lo) of the sorted ends decides: O(M log M) per ray
        src = order[:, :-1]
        Ka = A.shape[1] * 2
        kinds = [(src < Ka) & (src % 2 == 0), (src < Ka) & (src % 2 == 1),
                 (src >= Ka) & ((src - Ka) % 2 == 0), (src >= Ka) & ((src - Ka) % 2 == 1)]
        W0 = lo.shape[1]
        last = np.ones(lo.shape, bool)                   # the last of each run of equal ends
        last[:, :-1] = lo[:, 1:] != lo[:, :-1]
        idx = np.where(last, np.arange(W0), W0 - 1)
        g = np.minimum.accumulate(idx[:, ::-1], axis=1)[:, ::-1]
        rows_ = np.arange(n)[:, None]
        c = [np.cumsum(k, axis=1)[rows_, g] for k in kinds]
        ina = c[0] - c[1] > 0
        inb = c[2] - c[3] > 0
        keep = op(ina, inb) & (hi > lo)
        W = lo.shape[1]
    Ma, Mb = a.shape[1], b.shape[1]
    keep_a = {"union": True, "intersection": False, "difference": True}[operation]
    keep_b = operation == "union"
    out_w = max(W, Ma if keep_a else 1, Mb if keep_b else 1)
    seg = np.full((N, out_w, 2), np.inf)
    lab = np.zeros((N, out_w, 2), dtype=int) if labelled else None
    only_a = np.flatnonzero(has_a & ~has_b)
    only_b = np.flatnonzero(has_b & ~has_a)
    if keep_a and len(only_a):
        seg[only_a, :Ma] = a[only_a]
        if labelled:
            lab[only_a, :Ma] = la[only_a]
    if keep_b and len(only_b):
        seg[only_b, :Mb] = b[only_b]
        if labelled:
            lab[only_b, :Mb] = lb[only_b]
    if len(both):
        r, c = np.nonzero(keep)
        seg[both[r], c, 0] = lo[r, c]
        seg[both[r], c, 1] = hi[r, c]
        if labelled:
            labs = np.take_along_axis(np.concatenate([la[both].reshape(n, -1), lb[both].reshape(n, -1)], axis=1),
                                      order, axis=1)
            lab[both[r], c, 0] = labs[r, c]
            lab[both[r], c, 1] = labs[r, c + 1]
    return seg, lab


def _interval_list(x, name: str) -> np.ndarray:
    arr = as_float_array(x, name)
    if arr.size == 0:
        arr = arr.reshape(0, 2) if arr.ndim <= 2 else arr.reshape(arr.shape[:-2] + (0, 2))
    if arr.ndim not in (2, 3) or arr.shape[-1] != 2:
        raise ValueError(f"{name} must have shape (M, 2) or (N, M, 2) (intervals [start, end]); got shape {arr.shape}")
    if np.isnan(arr).any():
        raise ValueError(f"{name} must not contain NaN")
    bad = arr[..., 0] > arr[..., 1]
    if bad.any():
        k = tuple(int(i) for i in np.argwhere(bad)[0])
        raise ValueError(f"{name}{list(k)} has start > end: {arr[k][0]} > {arr[k][1]}")
    return arr


#: The most intervals (both lists, all rays) one :func:`combine_intervals` may combine: a second or
#: two of sorting and sweeping their ends.
MAX_INTERVALS = MAX_ITEMS // 4


def combine_intervals(first, second, operation: str) -> np.ndarray:
    """Combine two lists of closed parameter intervals by a boolean operation (Goldman §20.2): the
    step of ray classification that turns the intervals where a ray is inside ``A`` and inside
    ``B`` into the intervals where it is inside ``A op B``.

    first, second: ``(M, 2)`` lists of ``[start, end]`` (one ray; any order, overlaps allowed,
    ``+-inf`` allowed) or ``(N, M, 2)`` (N rays, rows padded with ``[inf, inf]``).  operation:
    ``"union"``, ``"intersection"`` or ``"difference"`` (first minus second).  Returns the result's
    disjoint intervals sorted by start, same rank as the input (padding with ``[inf, inf]`` for N
    rays).  Regularised: zero-length pieces are dropped, touching pieces merge.

    >>> combine_intervals([[0, 2], [3, 5]], [[1, 4]], "union").tolist()
    [[0.0, 5.0]]
    >>> combine_intervals([[0, 2], [3, 5]], [[1, 4]], "difference").tolist()
    [[0.0, 1.0], [4.0, 5.0]]
    >>> combine_intervals([[0, 1]], [[1, 2]], "intersection").tolist()   # they only touch
    []
    """
    if not isinstance(operation, str) or operation not in OPERATIONS:
        raise ValueError(f"operation must be one of {sorted(OPERATIONS)}; got {operation!r}")
    a, b = _interval_list(first, "first"), _interval_list(second, "second")
    single = a.ndim == 2
    if a.ndim != b.ndim:
        raise ValueError(f"first and second must both be (M, 2) or both (N, M, 2); got {a.shape} and {b.shape}")
    if single:
        a, b = a[None], b[None]
    if a.shape[0] != b.shape[0]:
        raise ValueError(f"first and second must hold as many rays; got {a.shape[0]} and {b.shape[0]}")
    if a[..., 0].size + b[..., 0].size > MAX_INTERVALS:
        raise ValueError(f"first and second must hold at most {MAX_INTERVALS:,} intervals together (their ends are "
                         f"sorted and swept, a few arrays of them); got {a[..., 0].size:,} and {b[..., 0].size:,}")
    a = a.reshape(a.shape[0], -1, 2) if a.shape[1] else np.full((a.shape[0], 1, 2), np.inf)
    b = b.reshape(b.shape[0], -1, 2) if b.shape[1] else np.full((b.shape[0], 1, 2), np.inf)
    out = _merge(_combine_raw(a, b, OPERATIONS[operation], operation=operation)[0])
    if single:
        out = out[0]
        return out[np.isfinite(out[:, 0]) | (out[:, 0] == -np.inf)].reshape(-1, 2)
    return out


def _bound(x):
    """A child's bounding sphere ``(center (3,), radius)`` or None (unbounded or unknown)."""
    b = getattr(x, "bounding_sphere", None)
    if b is None and isinstance(x, Sphere):
        return np.asarray(x.center, dtype=float), float(x.radius)
    if b is None:
        return None
    return np.asarray(b[0], dtype=float), float(b[1])


def _solid(x, name: str):
    if isinstance(x, CSG):
        return x
    if not isinstance(x, Surface):
        raise TypeError(f"{name} must be a solid (a simple_surfaces surface or a CSG node); got {type(x).__name__}")
    try:
        x.contains(np.zeros((1, 3)))
    except TypeError as exc:
        raise TypeError(f"{name} must bound a solid: {exc}") from None
    return x


def intervals(solid, origins, directions) -> np.ndarray:
    """The intervals of the parameter ``t`` where each ray ``origin + t direction`` is inside
    ``solid`` (Goldman §20.2): ``(N, M, 2)`` ``[start, end]`` rows sorted by start, padded with
    ``[inf, inf]``; a start may be ``-inf`` and an end ``inf`` (a half-space, a ray from inside).

    For a primitive the parameters where the ray crosses the surface (``hits``) cut the line into
    pieces, each classified by ``contains`` at its midpoint; for a CSG node the children's interval
    lists are combined by :func:`combine_intervals`.

    >>> from goldman_lib.simple_surfaces import Sphere, Plane
    >>> intervals(Sphere([0, 0, 0], 1), [[0, 0, -5], [0, 5, -5]], [[0, 0, 1], [0, 0, 1]]).tolist()
    [[[4.0, 6.0]], [[inf, inf]]]
    >>> intervals(Plane([0, 0, 0], [0, 0, 1]), [0, 0, 2], [0, 0, 1]).tolist()   # the half-space z <= 0
    [[[-inf, -2.0]]]
    """
    s = _solid(solid, "solid")
    o, d = rays(origins, directions)
    if isinstance(s, CSG):
        return s.intervals(o, d)
    return _merge(_primitive_segments(s, np.ascontiguousarray(o), np.ascontiguousarray(d), 1)[0])


#: The deepest CSG tree (levels from the root to the deepest leaf): every ray classification,
#: ``contains`` and bounding sphere recurses once per level.
MAX_CSG_DEPTH = 200


class CSG(Surface):
    """A node of a CSG tree (Goldman §20.2): the boolean ``operation`` of two solids ``a`` and ``b``
    (simple surfaces that bound solids, or CSG nodes).  Use :class:`Union`, :class:`Intersection`,
    :class:`Difference`.

    Ray classification: :meth:`intervals` combines the children's inside intervals; ``hits`` are
    the finite ends of those intervals; ``intersect`` the nearest one at ``t > EPS`` (an entry, or
    the exit for a ray starting inside); :meth:`hit` also returns the normal of the primitive whose
    boundary the hit lies on, reversed where that primitive is subtracted (so it points out of the
    result); ``contains`` is the boolean of the children's ``contains``.  ``material``: given, or the
    first operand's.
    """

    operation = "union"

    def __init__(self, a, b, material: Material | None = None):
        self.a, self.b = _solid(a, "a"), _solid(b, "b")
        self.depth = 1 + max(getattr(child, "depth", 0) if isinstance(child, CSG) else 0 for child in (self.a, self.b))
        if self.depth > MAX_CSG_DEPTH:
            deeper = "a" if getattr(self.a, "depth", 0) >= getattr(self.b, "depth", 0) else "b"
            raise ValueError(f"{deeper} must be a CSG tree at most {MAX_CSG_DEPTH - 1} deep: ray classification "
                             f"recurses once per level, and this node would be {self.depth} deep (over the limit of "
                             f"{MAX_CSG_DEPTH}); build a long chain of unions as a balanced tree (pairs of pairs)")
        self._set_material(material if material is not None else self.a.material)
        # leaf occurrences, each with its sign (+1, or -1 where it is subtracted an odd number of times)
        self.leaves: list = []
        self.signs: list[int] = []
        for child, flip in ((self.a, 1), (self.b, -1 if self.operation == "difference" else 1)):
            if isinstance(child, CSG):
                self.leaves += child.leaves
                self.signs += [s * flip for s in child.signs]
            else:
                self.leaves.append(child)
                self.signs.append(flip)

    def _labelled(self, o, d, first: int):
        """Raw (segments, labels) of this node, leaf labels numbered from ``first`` (1-based)."""
        parts = []
        k = first
        for child in (self.a, self.b):
            if isinstance(child, CSG):
                parts.append(child._labelled(o, d, k))
                k += len(child.leaves)
            else:
                parts.append(_primitive_segments(child, o, d, k))
                k += 1
        (ia, la), (ib, lb) = parts
        if self.operation == "difference":
            lb = -lb
        return _combine_raw(ia, ib, OPERATIONS[self.operation], la, lb, self.operation)

    def intervals(self, origins, directions) -> np.ndarray:
        """The inside intervals of the result along each ray, ``(N, M, 2)`` (see :func:`intervals`)."""
        o, d = rays(origins, directions)
        return _merge(self._labelled(np.ascontiguousarray(o), np.ascontiguousarray(d), 1)[0])

    def _hits(self, o, d):
        iv = _merge(self._labelled(np.ascontiguousarray(o), np.ascontiguousarray(d), 1)[0]).reshape(len(o), -1)
        return np.sort(np.where(np.isfinite(iv), iv, np.inf), axis=1)

    def hit(self, origins, directions) -> tuple[np.ndarray, np.ndarray]:
        """The nearest boundary parameter ``t > EPS`` per ray (``inf`` on a miss) and the unit
        outward normal of the result there (zero row on a miss): ``((N,), (N, 3))``."""
        o, d = rays(origins, directions)
        o, d = np.ascontiguousarray(o), np.ascontiguousarray(d)
        iv, lab = _merge(*self._labelled(o, d, 1))
        flat, flab = iv.reshape(len(o), -1), lab.reshape(len(o), -1)
        cand = np.where(np.isfinite(flat) & (flat > EPS), flat, np.inf)
        k = cand.argmin(axis=1) if cand.shape[1] else np.zeros(len(o), dtype=int)
        rows = np.arange(len(o))
        t = cand[rows, k] if cand.shape[1] else np.full(len(o), np.inf)
        label = flab[rows, k] if cand.shape[1] else np.zeros(len(o), dtype=int)
        normals = np.zeros_like(o)
        found = np.isfinite(t)
        for j, leaf in enumerate(self.leaves):
            sel = found & (np.abs(label) == j + 1)
            if sel.any():
                sign = np.where(label[sel] < 0, -1.0, 1.0)[:, None]
                normals[sel] = sign * leaf.normal(o[sel] + t[sel, None] * d[sel]) + 0.0
        return t, normals

    def _contains(self, P):
        ca, cb = self.a._contains(P), self.b._contains(P)
        return OPERATIONS[self.operation](np.asarray(ca, bool), np.asarray(cb, bool))

    def _normal(self, P):
        # the boundary of the result is made of the leaves' boundaries: take, per point, the leaf whose
        # surface is nearest along its own normal line, and its normal with the leaf's sign.
        best = np.full(len(P), np.inf)
        out = np.zeros_like(P)
        for leaf, sign in zip(self.leaves, self.signs):
            n = leaf.normal(P)
            dist = np.abs(leaf._hits(P, np.where(np.any(n != 0, axis=1)[:, None], n, [[0.0, 0.0, 1.0]])))
            dist = np.where(np.isfinite(dist), dist, np.inf).min(axis=1)
            closer = dist < best
            best = np.where(closer, dist, best)
            out[closer] = sign * n[closer]
        return out

    @property
    def bounding_sphere(self):
        """``(center, radius)`` of a sphere enclosing the solid, or None if it is unbounded (Goldman
        §19.6.1, what a renderer culls rays with): a union is enclosed by a sphere around both
        children's spheres, an intersection by the smaller of its bounded children's, a difference by
        its first operand's."""
        ba, bb = _bound(self.a), _bound(self.b)
        if self.operation == "difference":
            return ba
        if self.operation == "intersection":
            bounded = [x for x in (ba, bb) if x is not None]
            return min(bounded, key=lambda x: x[1]) if bounded else None
        if ba is None or bb is None:
            return None
        (c1, r1), (c2, r2) = ba, bb
        gap = float(np.linalg.norm(c2 - c1))
        if gap + r2 <= r1:
            return ba
        if gap + r1 <= r2:
            return bb
        radius = (gap + r1 + r2) / 2
        return c1 + (c2 - c1) * ((radius - r1) / gap), radius

    def _mesh(self, n, extent):
        # a CSG solid has no triangle mesh here: it is drawn by ray classification (a ray tracer)
        raise TypeError(f"a {type(self).__name__} has no mesh: draw it by ray tracing (its hit method)")

    def __repr__(self):
        return f"{type(self).__name__}({self.a!r}, {self.b!r})"


class Union(CSG):
    """The union ``a ∪ b`` of two solids (Goldman §20.2): inside where a ray is inside either.

    >>> from goldman_lib.simple_surfaces import Sphere
    >>> u = Union(Sphere([-0.5, 0, 0], 1), Sphere([0.5, 0, 0], 1))
    >>> u.intervals([[-3, 0, 0]], [[1, 0, 0]]).tolist(), u.contains([[1.4, 0, 0], [0, 1.2, 0]]).tolist()
    ([[[1.5, 4.5]]], [True, False])
    """

    operation = "union"


class Intersection(CSG):
    """The intersection ``a ∩ b`` of two solids (Goldman §20.2): inside where a ray is inside both.

    >>> from goldman_lib.simple_surfaces import Sphere, Plane
    >>> half_ball = Intersection(Sphere([0, 0, 0], 1), Plane([0, 0, 0], [0, 0, 1]))
    >>> half_ball.intersect([[0, 0, 5]], [[0, 0, -1]]).tolist()
    [5.0]
    """

    operation = "intersection"


class Difference(CSG):
    """The difference ``a - b`` of two solids (Goldman §20.2): inside where a ray is inside a and not
    inside b.  On b's part of the boundary the normal is b's reversed.

    >>> from goldman_lib.simple_surfaces import Sphere
    >>> bite = Difference(Sphere([-0.5, 0, 0], 1), Sphere([0.5, 0, 0], 1))
    >>> t, n = bite.hit([[3, 0, 0]], [[-1, 0, 0]]); t.tolist(), n.tolist()
    ([3.5], [[1.0, 0.0, 0.0]])
    """

    operation = "difference"

"""Subdivision surfaces: box splines by split and average, centroid averaging on quadrilateral and
triangular meshes of any topology, and the stencils it amounts to (Goldman, chapter 30).

Two layers, as everywhere in ``goldman_lib``:

- the mesh structure :class:`Mesh` (vertices ``(V, d)``, polygonal faces of any sizes) with the
  adjacency the algorithms need (edges, the faces of each edge, valences, neighbours, boundary),
  its Euler characteristic ``V - E + F``, and the meshes of the chapter (:func:`cube`,
  :func:`tetrahedron`, :func:`octahedron`, :func:`prism`, :func:`quad_star` with one
  extraordinary vertex, the regular grids :func:`quad_grid` and :func:`triangle_grid`);
- pure functions: split and average for uniform B-spline curves and for box-spline surfaces on
  regular grids (§30.2: :func:`split_and_average`, :func:`box_spline_split_and_average`); the two
  halves of centroid averaging, :func:`bilinear_split` and :func:`quad_average` (§30.3.1),
  :func:`midpoint_split` and :func:`triangle_average` (§30.4.1), put together in
  :func:`centroid_averaging`; and the stencils of §30.3.2 and §30.4.2 as functions of the valence,
  with :func:`apply_stencils` computing one level from them directly; around one vertex, the
  local subdivision matrix and its eigenvalues (:func:`local_subdivision_matrix`,
  :func:`local_eigenvalues`), which tell what the limit surface does at an extraordinary vertex.

Every algorithm is vectorised: a mesh keeps its faces as one flat array of *corners* (vertex
indices, face after face) with the faces' sizes, and adjacency as index arrays, so a level of
subdivision is a handful of ``np.bincount``/fancy-indexing operations, not a loop over faces.

Numbering after one level (so results can be matched with stencils): the new vertices are the old
vertices first (in order), then one per edge (in the order of :attr:`Mesh.edges`), then, for the
quadrilateral scheme, one per face (in face order).

Orientation: faces list their vertices counter-clockwise seen from outside; a mesh whose faces are
not consistently oriented is refused (``check_orientation=False`` skips the check).

>>> m = centroid_averaging(cube(), 1)
>>> m.n_vertices, m.n_faces, m.euler_characteristic()
(26, 24, 2)
"""

from __future__ import annotations

from functools import cached_property

import numpy as np

from goldman_lib.kernels import meshes
from goldman_lib.validation import MAX_ITEMS, as_float, as_int, as_points, within_budget

__all__ = [
    "Mesh", "cube", "tetrahedron", "octahedron", "prism", "quad_star", "quad_grid", "triangle_grid",
    "triangulate", "split_and_average", "box_spline_split_and_average",
    "bilinear_split", "quad_average", "midpoint_split", "triangle_average", "centroid_averaging",
    "quad_vertex_stencil", "quad_edge_stencil", "quad_face_stencil",
    "triangle_vertex_stencil", "triangle_edge_stencil", "apply_stencils",
    "local_subdivision_matrix", "local_eigenvalues", "BOX_SPLINE_SELF_WEIGHT",
    "VERTEX_RULES", "loop_beta", "warren_beta", "tangent_plane_condition", "valence_table",
    "ring_height_ratio", "cone_ratios", "angle_defects",
]

#: Weight of a vertex itself in the weighted triangle centroid used by the triangle scheme; the
#: other two corners get (1 - 1/4)/2 = 3/8 each.  On a regular grid this makes the averaging step
#: the three-direction averaging of the quartic box spline (see :func:`triangle_average`).
BOX_SPLINE_SELF_WEIGHT = 0.25


#: The vertex rules of the triangle scheme (Goldman §30.4.2 and the smooth variants of Loop's scheme):
#: ``"centroid"`` the book's weighted-centroid averaging, ``v' = 5/8 v + 3/(8n) sum u`` (a cone at
#: valence 3); ``"warren"`` Warren's weight beta = 3/16 at n = 3 and 3/(8n) otherwise; ``"loop"``
#: Loop's original beta(n) (:func:`loop_beta`).  The two last give ``v' = (1 - n beta) v + beta sum u``.
VERTEX_RULES = ("centroid", "warren", "loop")


def _scatter_sum(index: np.ndarray, values: np.ndarray, n: int) -> np.ndarray:
    """Sum the rows of ``values`` (N, d) into ``n`` bins by ``index`` (N,) (one bincount per column)."""
    return np.stack([np.bincount(index, weights=values[:, k], minlength=n) for k in range(values.shape[1])], axis=1)


# --------------------------------------------------------------------------------------------
# the mesh structure
# --------------------------------------------------------------------------------------------

class Mesh:
    """A polygonal mesh of any topology: vertices ``(V, d)`` and faces of three or more vertices.

    vertices: (V, d) points, d >= 1 (3 for surfaces in space).  faces: an (F, k) integer array
    (all faces k-gons) or a sequence of index sequences of any sizes >= 3.

    Validated: every face has at least 3 vertices, indexes existing vertices and repeats none;
    every vertex belongs to a face; every edge belongs to at most two faces (a manifold, with or
    without boundary); and, unless ``check_orientation=False``, the faces are consistently
    oriented (no two faces traverse an edge in the same direction).  Raises ValueError naming
    the face, vertex or edge that breaks a rule; TypeError for non-integer faces.

    Beside :class:`goldman_lib.solid_modeling.BRep` (chapter 20's boundary representation: faces
    with holes, faults described in words, volume and the Euler-Poincare formula), a Mesh is what
    subdivision needs: any dimension, refused unless it is a manifold, with its adjacency (edges,
    the faces of each edge, valences) cached as index arrays.  :meth:`from_brep` and
    ``BRep.from_mesh`` convert; both take their edges, fans and polyhedra from
    :mod:`goldman_lib.kernels.meshes`.

    >>> m = Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])
    >>> m.n_edges, m.euler_characteristic(), m.is_closed
    (4, 1, False)
    >>> Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0]], [[0, 1, 3]])
    Traceback (most recent call last):
    ...
    ValueError: faces must index existing vertices 0..2; face 0 uses vertex 3
    """

    def __init__(self, vertices, faces, *, check_orientation: bool = True):
        V = as_points(vertices, "vertices", ndim=2, min_count=1)
        corners, sizes = _read_faces(faces)
        nv = len(V)
        if corners.size and (corners.min() < 0 or corners.max() >= nv):
            bad = int(np.flatnonzero((corners < 0) | (corners >= nv))[0])
            face = int(np.searchsorted(np.cumsum(sizes), bad, side="right"))
            raise ValueError(f"faces must index existing vertices 0..{nv - 1}; face {face} uses vertex {int(corners[bad])}")
        self._set(V, corners, sizes)
        used = np.bincount(corners, minlength=nv)
        if (used == 0).any():
            raise ValueError(f"faces must use every vertex (every vertex must belong to a face); "
                             f"vertex {int(np.flatnonzero(used == 0)[0])} belongs to none")
        nxt = self._next
        same = corners == corners[nxt]
        if same.any():
            face = int(self._face_of_corner[np.flatnonzero(same)[0]])
            raise ValueError(f"faces must not repeat a vertex; face {face} repeats vertex {int(corners[np.flatnonzero(same)[0]])}")
        for face in np.flatnonzero(sizes > 3):  # a repeated vertex that is not adjacent (rare: only big faces)
            verts = corners[self._offsets[face]:self._offsets[face] + sizes[face]]
            if len(np.unique(verts)) < len(verts):
                raise ValueError(f"faces must not repeat a vertex; face {int(face)} is {verts.tolist()}")
        counts = np.bincount(self._corner_edge, minlength=len(self.edges))
        if (counts > 2).any():
            e = int(np.flatnonzero(counts > 2)[0])
            raise ValueError(f"faces must form a manifold mesh: every edge belongs to at most two faces; edge "
                             f"{tuple(self.edges[e].tolist())} belongs to {int(counts[e])}")
        if check_orientation:
            twice = meshes.same_direction_edges(corners, sizes, nv, nxt)
            if len(twice):
                a, b = (int(v) for v in twice[0])
                faces_with = np.unique(self._face_of_corner[(corners == a) & (corners[nxt] == b)]).tolist()
                raise ValueError(f"faces must be consistently oriented; faces {faces_with[0]} and {faces_with[1]} "
                                 f"both run along edge {a}->{b} in the same direction")

    # -- construction without checks (for results that are valid by construction) ----------------
    @classmethod
    def _trusted(cls, vertices: np.ndarray, corners: np.ndarray, sizes: np.ndarray) -> "Mesh":
        mesh = cls.__new__(cls)
        mesh._set(vertices, corners, sizes)
        return mesh

    def _set(self, V, corners, sizes):
        self._vertices = V
        self._corners = corners
        self._sizes = sizes
        self._offsets = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)

    # -- the data ---------------------------------------------------------------------------------
    @property
    def vertices(self) -> np.ndarray:
        """The vertex positions ``(V, d)`` (a copy)."""
        return self._vertices.copy()

    @property
    def faces(self):
        """The faces: an ``(F, k)`` array when all faces are k-gons, else a list of index arrays."""
        if self.face_size is not None:
            return self._corners.reshape(-1, self.face_size).copy()
        return [self._corners[o:o + s].copy() for o, s in zip(self._offsets, self._sizes)]

    @property
    def face_sizes(self) -> np.ndarray:
        """Number of vertices of each face ``(F,)``."""
        return self._sizes.copy()

    @cached_property
    def face_size(self) -> int | None:
        """k if every face is a k-gon, else None."""
        return int(self._sizes[0]) if (self._sizes == self._sizes[0]).all() else None

    @property
    def n_vertices(self) -> int:
        return len(self._vertices)

    @property
    def n_faces(self) -> int:
        return len(self._sizes)

    @property
    def n_edges(self) -> int:
        return len(self.edges)

    @property
    def is_quad(self) -> bool:
        """True if every face is a quadrilateral."""
        return self.face_size == 4

    @property
    def is_triangle(self) -> bool:
        """True if every face is a triangle."""
        return self.face_size == 3

    # -- adjacency (cached index arrays) ------------------------------------------------------------
    @cached_property
    def _face_of_corner(self) -> np.ndarray:
        return np.repeat(np.arange(len(self._sizes)), self._sizes)

    @cached_property
    def _next(self) -> np.ndarray:
        """Index of the next corner around the same face."""
        idx = np.arange(len(self._corners))
        nxt = idx + 1
        last = self._offsets + self._sizes - 1
        nxt[last] = self._offsets
        return nxt

    @cached_property
    def _prev(self) -> np.ndarray:
        prev = np.empty_like(self._next)
        prev[self._next] = np.arange(len(self._next))
        return prev

    @cached_property
    def _edge_data(self):
        return meshes.edge_table(self._corners, self._sizes, len(self._vertices), self._next)

    @property
    def edges(self) -> np.ndarray:
        """The edges ``(E, 2)``, each as (smaller index, larger index), sorted."""
        return self._edge_data[0]

    @property
    def _corner_edge(self) -> np.ndarray:
        """Edge id of the edge from each corner to the next corner of its face."""
        return self._edge_data[1]

    @cached_property
    def edge_faces(self) -> np.ndarray:
        """The faces on each side of each edge ``(E, 2)``; -1 where an edge is on the boundary."""
        ce = self._corner_edge
        order = np.argsort(ce, kind="stable")
        faces = self._face_of_corner[order]
        sorted_edges = ce[order]
        out = np.full((len(self.edges), 2), -1, dtype=np.int64)
        first = np.ones(len(order), dtype=bool)
        first[1:] = sorted_edges[1:] != sorted_edges[:-1]
        out[sorted_edges[first], 0] = faces[first]
        out[sorted_edges[~first], 1] = faces[~first]
        return out

    @cached_property
    def valences(self) -> np.ndarray:
        """Number of edges at each vertex ``(V,)`` (for a closed mesh, also the number of faces)."""
        return np.bincount(self.edges.ravel(), minlength=self.n_vertices)

    @cached_property
    def vertex_face_counts(self) -> np.ndarray:
        """Number of faces at each vertex ``(V,)``."""
        return np.bincount(self._corners, minlength=self.n_vertices)

    @property
    def boundary_edges(self) -> np.ndarray:
        """The edges that belong to one face only ``(B, 2)``."""
        return self.edges[self.edge_faces[:, 1] < 0]

    @cached_property
    def boundary_vertices(self) -> np.ndarray:
        """Boolean mask ``(V,)`` of the vertices on a boundary edge."""
        mask = np.zeros(self.n_vertices, dtype=bool)
        mask[self.boundary_edges.ravel()] = True
        return mask

    @property
    def is_closed(self) -> bool:
        """True if every edge belongs to two faces (no boundary)."""
        return bool((self.edge_faces[:, 1] >= 0).all())

    def neighbours(self, v: int) -> np.ndarray:
        """The vertices joined to vertex ``v`` by an edge, sorted.

        >>> cube().neighbours(0).tolist()
        [1, 2, 4]
        """
        v = as_int(v, "v", minimum=0, maximum=self.n_vertices - 1)
        e = self.edges
        return np.sort(np.concatenate([e[e[:, 0] == v, 1], e[e[:, 1] == v, 0]]))

    def face_centroids(self) -> np.ndarray:
        """The centroid (average of the vertices) of each face ``(F, d)``."""
        sums = np.add.reduceat(self._vertices[self._corners], self._offsets, axis=0)
        return sums / self._sizes[:, None]

    def euler_characteristic(self) -> int:
        """``V - E + F`` (2 for a sphere-like closed mesh, 1 for a disk, 0 for a torus).

        >>> tetrahedron().euler_characteristic()
        2
        """
        return self.n_vertices - self.n_edges + self.n_faces

    def triangles(self) -> np.ndarray:
        """Triangle indices ``(T, 3)`` of the faces fanned from their first vertex (for drawing)."""
        return triangulate(self).faces

    def with_vertices(self, vertices) -> "Mesh":
        """The same faces with new vertex positions ``(V, d)``."""
        V = as_points(vertices, "vertices", ndim=2)
        if len(V) != self.n_vertices:
            raise ValueError(f"vertices must hold {self.n_vertices} points, one per vertex; got {len(V)}")
        return Mesh._trusted(V, self._corners, self._sizes)

    @classmethod
    def from_brep(cls, brep) -> "Mesh":
        """The polygon mesh of a B-rep's faces (Goldman §20.3; §30.3, §30.4): its vertices and outer loops, in
        order (validated as any Mesh).  Raises ValueError for a B-rep whose faces have rings (holes),
        which a Mesh cannot hold.

        >>> from goldman_lib import solid_modeling
        >>> Mesh.from_brep(solid_modeling.cube(2)).faces.tolist() == cube().faces.tolist()
        True
        """
        rings = getattr(brep, "rings", None)
        if not hasattr(brep, "faces") or not hasattr(brep, "vertices") or rings is None:
            raise TypeError(f"brep must be a solid_modeling.BRep; got {type(brep).__name__}")
        if rings:
            raise ValueError(f"brep must have no rings (a Mesh face has no holes); faces {sorted(rings)} have rings")
        return cls(brep.vertices, [list(f) for f in brep.faces])

    def __repr__(self) -> str:
        kind = {3: "triangles", 4: "quadrilaterals"}.get(self.face_size, "polygons")
        return f"Mesh({self.n_vertices} vertices, {self.n_edges} edges, {self.n_faces} faces: {kind})"


def _read_faces(faces):
    """Flat corners and face sizes from an (F, k) array or a list of sequences."""
    if isinstance(faces, (str, bytes)) or not hasattr(faces, "__len__") or (
            isinstance(faces, np.ndarray) and faces.ndim == 0):
        raise TypeError(f"faces must be an (F, k) integer array or a list of index lists; got {type(faces).__name__}")
    if not isinstance(faces, np.ndarray) and any(isinstance(f, (str, bytes)) or not hasattr(f, "__len__") and np.ndim(f) != 0
                                                 for f in faces):
        raise TypeError("faces must be an (F, k) integer array or a list of index lists")
    if isinstance(faces, np.ndarray) and faces.ndim == 2 or (
            not isinstance(faces, np.ndarray) and len(faces) and all(np.ndim(f) == 1 for f in faces)
            and len({len(f) for f in faces}) == 1):
        arr = np.asarray(faces)
        if arr.ndim != 2:
            raise ValueError(f"faces must be an (F, k) array or a list of index lists; got shape {arr.shape}")
        rows = [arr[i] for i in range(len(arr))] if arr.size else []
    else:
        rows = list(faces) if not isinstance(faces, np.ndarray) else [faces] if faces.ndim == 1 else None
        if rows is None:
            raise ValueError(f"faces must be an (F, k) array or a list of index lists; got shape {faces.shape}")
    if len(rows) == 0:
        raise ValueError("faces must hold at least one face")
    sizes = np.array([len(np.atleast_1d(r)) for r in rows], dtype=np.int64)
    if (sizes < 3).any():
        k = int(np.flatnonzero(sizes < 3)[0])
        raise ValueError(f"faces must have at least 3 vertices; face {k} has {int(sizes[k])}")
    try:
        flat = np.concatenate([np.atleast_1d(np.asarray(r)) for r in rows])
    except (TypeError, ValueError) as exc:
        raise TypeError(f"faces must hold integer vertex indices ({exc})") from None
    if flat.dtype.kind not in "iu":
        if flat.dtype.kind == "f" and np.all(np.isfinite(flat)) and np.all(flat == np.round(flat)):
            flat = flat.astype(np.int64)
        else:
            raise TypeError(f"faces must hold integer vertex indices; got dtype {flat.dtype}")
    return flat.astype(np.int64), sizes


# --------------------------------------------------------------------------------------------
# the meshes of the chapter
# --------------------------------------------------------------------------------------------

def cube() -> Mesh:
    """The cube [-1, 1]^3: 8 vertices of valence 3, 6 quadrilaterals, outward orientation (the tables
    :data:`goldman_lib.kernels.meshes.CUBE_VERTICES` and ``CUBE_FACES``, shared with
    ``solid_modeling.cube``).

    >>> cube()
    Mesh(8 vertices, 12 edges, 6 faces: quadrilaterals)
    """
    return Mesh(meshes.CUBE_VERTICES.copy(), meshes.CUBE_FACES.copy())


def tetrahedron() -> Mesh:
    """The regular tetrahedron with vertices at alternate corners of the cube [-1, 1]^3 (the tables
    :data:`goldman_lib.kernels.meshes.TETRAHEDRON_VERTICES` and ``TETRAHEDRON_FACES``).

    >>> tetrahedron().valences.tolist()
    [3, 3, 3, 3]
    """
    return Mesh(meshes.TETRAHEDRON_VERTICES.copy(), meshes.TETRAHEDRON_FACES.copy())


def octahedron() -> Mesh:
    """The regular octahedron with vertices ``±e_x, ±e_y, ±e_z``: 8 triangles, valence 4.

    >>> octahedron().euler_characteristic()
    2
    """
    v = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]
    faces = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]
    return Mesh(v, faces)


def prism(n: int = 5, height: float = 1.5) -> Mesh:
    """A closed prism over a regular n-gon: two n-gon caps and n quadrilateral sides.

    One level of the quadrilateral scheme turns each cap into n quadrilaterals around a vertex
    of valence n (an extraordinary vertex when n != 4).

    n: the sides of the caps, >= 3, with the 2n vertices' coordinates at most
    :data:`~goldman_lib.validation.MAX_ITEMS` (the work budget).

    >>> prism(5).face_sizes.tolist()
    [5, 5, 4, 4, 4, 4, 4]
    """
    n = within_budget(n, "n", cost=lambda v: 6 * v, what="the prism", unit="vertex coordinates", minimum=3)
    height = as_float(height, "height", positive=True)
    ang = 2 * np.pi * np.arange(n) / n
    ring = np.stack([np.cos(ang), np.sin(ang)], axis=1)
    v = np.concatenate([np.column_stack([ring, np.full(n, -height / 2)]),
                        np.column_stack([ring, np.full(n, height / 2)])])
    k = np.arange(n)
    faces = [list(range(n - 1, -1, -1)), list(range(n, 2 * n))]
    faces += [[int(i), int((i + 1) % n), int((i + 1) % n + n), int(i + n)] for i in k]
    return Mesh(v, faces)


def quad_star(valence: int = 5, rings: int = 2, height: float = 0.8) -> Mesh:
    """An open quadrilateral mesh with one extraordinary vertex of the given valence at its centre.

    ``valence`` sectors, each a ``rings x rings`` grid of quadrilaterals spanned by two
    neighbouring spokes; every vertex other than the centre (and the boundary) has valence 4.
    The mesh is lifted into a bump of the given height, highest at the centre.

    valence >= 3 and rings >= 1, with the ``valence rings^2 + ...`` vertices at most
    :data:`~goldman_lib.validation.MAX_ITEMS` / 3 (the mesh is built in Python loops: a second or
    so at the limit of about 10^6 vertices is not reached by the chapter's stars).

    >>> m = quad_star(5)
    >>> int(m.valences[0]), m.n_faces, m.euler_characteristic()
    (5, 20, 1)
    """
    n = within_budget(valence, "valence", cost=lambda v: 3 * v * 2, what="the star", unit="vertex coordinates",
                      minimum=3)
    r = within_budget(rings, "rings", cost=lambda v: 3 * n * (v + 1) ** 2, what=f"the star of valence {n}",
                      unit="vertex coordinates", limit=MAX_ITEMS // 10, minimum=1)
    height = as_float(height, "height")
    ang = 2 * np.pi * np.arange(n) / n
    spokes = np.stack([np.cos(ang), np.sin(ang)], axis=1) / r
    pos = [np.zeros(2)]
    spoke_id = np.zeros((n, r + 1), dtype=np.int64)   # spoke s, step i (i = 0 is the centre)
    for s in range(n):
        for i in range(1, r + 1):
            spoke_id[s, i] = len(pos)
            pos.append(i * spokes[s])
    inner = np.zeros((n, r + 1, r + 1), dtype=np.int64)
    for s in range(n):
        for i in range(1, r + 1):
            for j in range(1, r + 1):
                inner[s, i, j] = len(pos)
                pos.append(i * spokes[s] + j * spokes[(s + 1) % n])

    def vid(s, i, j):
        if i == 0 and j == 0:
            return 0
        if j == 0:
            return spoke_id[s, i]
        if i == 0:
            return spoke_id[(s + 1) % n, j]
        return inner[s, i, j]

    faces = [[vid(s, i, j), vid(s, i + 1, j), vid(s, i + 1, j + 1), vid(s, i, j + 1)]
             for s in range(n) for i in range(r) for j in range(r)]
    xy = np.array(pos)
    rho2 = (xy ** 2).sum(1)
    z = height * np.exp(-2.0 * rho2)
    return Mesh(np.column_stack([xy, z]), np.array(faces, dtype=np.int64))


def _grid_net(points, name):
    P = as_points(points, name, ndim=3, min_count=2)
    return P


def quad_grid(points) -> Mesh:
    """The quadrilateral mesh of a regular grid of control points ``(m, n, d)``.

    Vertex ``(i, j)`` of the net is vertex ``i*n + j``; face ``(i, j)`` is
    ``(i, j), (i+1, j), (i+1, j+1), (i, j+1)``.

    >>> quad_grid(np.zeros((3, 4, 3)))
    Mesh(12 vertices, 17 edges, 6 faces: quadrilaterals)
    """
    P = _grid_net(points, "points")
    m, n = P.shape[:2]
    idx = np.arange(m * n).reshape(m, n)
    faces = np.stack([idx[:-1, :-1], idx[1:, :-1], idx[1:, 1:], idx[:-1, 1:]], axis=-1).reshape(-1, 4)
    return Mesh(P.reshape(m * n, -1), faces)


def triangle_grid(points) -> Mesh:
    """The triangular mesh of a regular grid of control points ``(m, n, d)``, three-direction:
    every grid square is cut along its diagonal from ``(i, j)`` to ``(i+1, j+1)`` (the third
    direction (1, 1) of the three-direction box splines).

    >>> int(triangle_grid(np.zeros((3, 3, 3))).valences[4])
    6
    """
    P = _grid_net(points, "points")
    m, n = P.shape[:2]
    idx = np.arange(m * n).reshape(m, n)
    a, b, c, d = idx[:-1, :-1], idx[1:, :-1], idx[1:, 1:], idx[:-1, 1:]
    faces = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    return Mesh(P.reshape(m * n, -1), faces)


def triangulate(mesh: Mesh) -> Mesh:
    """Cut every face into triangles fanned from its first vertex (same vertices, same orientation).

    >>> triangulate(cube()).n_faces
    12
    """
    if not isinstance(mesh, Mesh):
        raise TypeError(f"mesh must be a Mesh; got {type(mesh).__name__}")
    if mesh.face_size == 3:
        return mesh
    tris = meshes.fan_triangles(mesh._corners, mesh._sizes)
    return Mesh._trusted(mesh._vertices, tris.ravel(), np.full(len(tris), 3, dtype=np.int64))


# --------------------------------------------------------------------------------------------
# §30.2 box splines: split and average
# --------------------------------------------------------------------------------------------

def split_and_average(ctrl, degree: int, levels: int = 1, closed: bool = False) -> np.ndarray:
    """Uniform B-spline curve subdivision by split and average (Lane-Riesenfeld; Goldman §30.2).

    One level *splits* (doubles every control point) and then *averages* ``degree`` times
    (replaces the polygon by the midpoints of its legs).  The result is the control polygon of
    the same uniform B-spline curve of the given degree over knots of half the spacing; repeated,
    the polygons converge to the curve.

    ctrl: (n, d) control points.  degree: >= 0.  levels: >= 0.  closed: treat the polygon as
    closed (periodic): then every level doubles the number of points; else each averaging drops
    one point (the ends of an open polygon lose support), giving ``2 n - degree`` points a level.
    The work budget: ``(degree + 1) d`` times the refined point count at most
    :data:`~goldman_lib.validation.MAX_ITEMS` coordinates computed (levels <= 19 for a planar
    cubic of 5 points).
    Raises ValueError if an open polygon becomes too short or degree or levels is over the budget.

    >>> split_and_average([[0.0], [8.0]], degree=1).ravel().tolist()
    [0.0, 4.0, 8.0]
    >>> split_and_average([[0, 0], [4, 0], [4, 4], [0, 4]], degree=2, closed=True)[:2].tolist()
    [[1.0, 0.0], [3.0, 0.0]]
    """
    P = as_points(ctrl, "ctrl", ndim=2)
    if not isinstance(closed, (bool, np.bool_)):
        raise TypeError(f"closed must be True or False; got {closed!r}")
    m, d = P.shape
    degree = within_budget(degree, "degree", cost=lambda v: (v + 1) * 2 * m * d, what="one level",
                           unit="coordinates computed")

    def count(v):   # points after v levels (an open polygon that runs out raises below)
        return 2 ** v * m if closed else max(2 ** v * (m - degree) + degree, 2 ** v)

    levels = within_budget(levels, "levels", cost=lambda v: count(v) * d * (degree + 1), what="the refined polygon",
                           unit="coordinates computed")
    for _ in range(levels):
        P = np.repeat(P, 2, axis=0)
        for _ in range(degree):
            if closed:
                P = 0.5 * (P + np.roll(P, -1, axis=0))
            else:
                if len(P) < 2:
                    raise ValueError(f"ctrl is too short for degree {degree}: an open polygon of degree d needs at least d+1 points")
                P = 0.5 * (P[:-1] + P[1:])
    return P


def box_spline_split_and_average(points, multiplicities=(2, 2, 2), levels: int = 1) -> np.ndarray:
    """Subdivide the control net of a box spline on a regular grid by split and average (Goldman §30.2).

    A box spline over the directions ``e1 = (1, 0)``, ``e2 = (0, 1)``, ``e3 = (1, 1)`` repeated
    ``multiplicities = (r, s, t)`` times is subdivided by *splitting* (each control point becomes a
    2x2 block: the box over e1 and e2, the piecewise-constant spline) and then *averaging* in each
    remaining direction: ``r-1`` times along e1, ``s-1`` times along e2, ``t`` times along e3, each
    time replacing ``P[i, j]`` by ``(P[i, j] + P[i+a, j+b]) / 2`` for the direction (a, b).
    ``(4, 4, 0)`` is the bicubic tensor-product B-spline; ``(2, 2, 2)`` the three-direction
    quartic box spline; ``(1, 1, 1)`` the piecewise-linear hat function.

    points: (m, n, d) control net.  multiplicities: (r, s, t) with r, s >= 1, t >= 0.
    levels: >= 0, with the ``4^levels m n d`` coordinates of the split net at most
    :data:`~goldman_lib.validation.MAX_ITEMS` (the work budget).  Returns the refined net (every averaging trims one row or column: the
    boundary points that need data from outside the net are dropped).
    Raises ValueError for a multiplicity out of range or a net too small to average.

    >>> net = np.arange(4.0).reshape(2, 2, 1)
    >>> box_spline_split_and_average(net, (1, 1, 0))[..., 0].tolist()
    [[0.0, 0.0, 1.0, 1.0], [0.0, 0.0, 1.0, 1.0], [2.0, 2.0, 3.0, 3.0], [2.0, 2.0, 3.0, 3.0]]
    """
    P = as_points(points, "points", ndim=3)
    try:
        flat = np.ndim(multiplicities) == 1
    except ValueError:   # a ragged sequence
        flat = False
    if isinstance(multiplicities, (str, bytes)) or not hasattr(multiplicities, "__len__") or not flat:
        raise TypeError(f"multiplicities must be a sequence (r, s, t) of three integers; got {multiplicities!r}")
    if len(multiplicities) != 3:
        raise ValueError(f"multiplicities must be (r, s, t) for the directions (1,0), (0,1), (1,1); got {multiplicities!r}")
    r = as_int(multiplicities[0], "multiplicities[0]", minimum=1)
    s = as_int(multiplicities[1], "multiplicities[1]", minimum=1)
    t = as_int(multiplicities[2], "multiplicities[2]", minimum=0)
    levels = within_budget(levels, "levels", cost=lambda v: 4 ** v * P.size, what="the split net",
                           unit="coordinates")
    for _ in range(levels):
        P = np.repeat(np.repeat(P, 2, axis=0), 2, axis=1)
        for (a, b), times in (((1, 0), r - 1), ((0, 1), s - 1), ((1, 1), t)):
            for _ in range(times):
                if P.shape[0] <= a or P.shape[1] <= b:
                    raise ValueError(f"points is too small a net for multiplicities {(r, s, t)}; got shape {P.shape}")
                P = 0.5 * (P[:P.shape[0] - a, :P.shape[1] - b] + P[a:, b:])
    return P


# --------------------------------------------------------------------------------------------
# §30.3 quadrilateral meshes: centroid averaging
# --------------------------------------------------------------------------------------------

def _check_mesh(mesh, name="mesh"):
    if not isinstance(mesh, Mesh):
        raise TypeError(f"{name} must be a Mesh; got {type(mesh).__name__}")
    return mesh


def bilinear_split(mesh: Mesh) -> Mesh:
    """Split every face into quadrilaterals at its centroid and edge midpoints (Goldman §30.3.1).

    A k-gon becomes k quadrilaterals ``(v, midpoint(v, next), centroid, midpoint(prev, v))``; on
    a quadrilateral mesh this is one level of bilinear subdivision.  New vertices: the old ones,
    then the edge midpoints (in :attr:`Mesh.edges` order), then the face centroids.

    >>> bilinear_split(tetrahedron())
    Mesh(14 vertices, 24 edges, 12 faces: quadrilaterals)
    """
    mesh = _check_mesh(mesh)
    V, C = mesh._vertices, mesh._corners
    nv, ne = mesh.n_vertices, mesh.n_edges
    edges = mesh.edges
    verts = np.concatenate([V, 0.5 * (V[edges[:, 0]] + V[edges[:, 1]]), mesh.face_centroids()])
    ce = mesh._corner_edge
    quads = np.stack([C, nv + ce, nv + ne + mesh._face_of_corner, nv + ce[mesh._prev]], axis=1)
    return Mesh._trusted(verts, quads.ravel(), np.full(len(quads), 4, dtype=np.int64))


def quad_average(mesh: Mesh) -> Mesh:
    """Replace every vertex by the centroid of the centroids of its faces (Goldman §30.3.1).

    Works on any polygon mesh (the quadrilateral scheme applies it after :func:`bilinear_split`).

    >>> quad_average(quad_grid([[[0, 0], [0, 2]], [[2, 0], [2, 2]]])).vertices.tolist()
    [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]
    """
    mesh = _check_mesh(mesh)
    cent = mesh.face_centroids()
    sums = _scatter_sum(mesh._corners, cent[mesh._face_of_corner], mesh.n_vertices)
    return Mesh._trusted(sums / mesh.vertex_face_counts[:, None], mesh._corners, mesh._sizes)


# --------------------------------------------------------------------------------------------
# §30.4 triangular meshes
# --------------------------------------------------------------------------------------------

def midpoint_split(mesh: Mesh) -> Mesh:
    """Split every triangle into four at its edge midpoints (Goldman §30.4.1).

    ``(a, b, c)`` becomes ``(a, m_ab, m_ca), (m_ab, b, m_bc), (m_ca, m_bc, c), (m_ab, m_bc, m_ca)``.
    New vertices: the old ones, then the edge midpoints in :attr:`Mesh.edges` order.
    Raises ValueError if a face is not a triangle (use :func:`triangulate` first).

    >>> midpoint_split(tetrahedron())
    Mesh(10 vertices, 24 edges, 16 faces: triangles)
    """
    mesh = _check_mesh(mesh)
    if not mesh.is_triangle:
        raise ValueError("mesh must be a triangle mesh for midpoint_split; triangulate it first "
                         f"(face sizes {sorted(set(mesh._sizes.tolist()))})")
    V, nv, edges = mesh._vertices, mesh.n_vertices, mesh.edges
    verts = np.concatenate([V, 0.5 * (V[edges[:, 0]] + V[edges[:, 1]])])
    T = mesh._corners.reshape(-1, 3)
    E = nv + mesh._corner_edge.reshape(-1, 3)   # E[:, 0] = m_ab, E[:, 1] = m_bc, E[:, 2] = m_ca
    tris = np.concatenate([np.stack([T[:, 0], E[:, 0], E[:, 2]], 1), np.stack([E[:, 0], T[:, 1], E[:, 1]], 1),
                           np.stack([E[:, 2], E[:, 1], T[:, 2]], 1), np.stack([E[:, 0], E[:, 1], E[:, 2]], 1)])
    return Mesh._trusted(verts, tris.ravel(), np.full(len(tris), 3, dtype=np.int64))


def _self_weight(self_weight):
    w = as_float(self_weight, "self_weight")
    if not 0.0 <= w <= 1.0:
        raise ValueError(f"self_weight must lie in [0, 1]; got {w}")
    return w


def triangle_average(mesh: Mesh, self_weight: float = BOX_SPLINE_SELF_WEIGHT) -> Mesh:
    """Replace every vertex by the average, over its triangles, of a (weighted) centroid
    (Goldman §30.4.1).

    For a vertex ``v`` in triangle ``(v, a, b)`` the triangle contributes
    ``w v + (1 - w)/2 (a + b)`` with ``w = self_weight``.  ``w = 1/3`` is the plain centroid;
    the default ``w = 1/4`` (weights 1/4, 3/8, 3/8) is the choice that makes the averaging, on
    a regular grid, the three-direction averaging ``(2 v + sum of the six neighbours) / 8`` of the
    quartic box spline.  (Plain centroids give ``(3 v + sum of neighbours) / 9`` instead, a
    smooth scheme but not the box spline.)

    Raises ValueError if a face is not a triangle or self_weight is outside [0, 1].

    >>> m = triangle_average(triangle_grid(np.zeros((3, 3, 1)) + [[[0], [0], [0]], [[0], [8], [0]], [[0], [0], [0]]]))
    >>> float(m.vertices[4, 0])
    2.0
    """
    mesh = _check_mesh(mesh)
    if not mesh.is_triangle:
        raise ValueError("mesh must be a triangle mesh for triangle_average; triangulate it first")
    w = _self_weight(self_weight)
    V, T = mesh._vertices, mesh._corners.reshape(-1, 3)
    tri_sum = V[T].sum(axis=1)                                        # a + b + c per triangle
    own = V[T]                                                        # (T, 3, d): the corner itself
    contrib = (w - (1 - w) / 2) * own + ((1 - w) / 2) * tri_sum[:, None, :]
    sums = _scatter_sum(T.ravel(), contrib.reshape(-1, V.shape[1]), mesh.n_vertices)
    return Mesh._trusted(sums / mesh.vertex_face_counts[:, None], mesh._corners, mesh._sizes)


def centroid_averaging(mesh: Mesh, levels: int = 1, scheme: str | None = None,
                       self_weight: float = BOX_SPLINE_SELF_WEIGHT, rule: str = "centroid") -> Mesh:
    """Subdivide a mesh by centroid averaging, ``levels`` times (Goldman §30.3.1 and §30.4.1).

    scheme ``"quad"``: split every face into quadrilaterals (:func:`bilinear_split`), then
    replace every vertex by the centroid of the centroids of its faces (:func:`quad_average`).
    Any polygon mesh is accepted; after one level all faces are quadrilaterals.  On a regular
    quadrilateral grid one level is one level of bicubic B-spline subdivision.

    scheme ``"triangle"``: split every triangle into four (:func:`midpoint_split`), then replace
    every vertex by the average of the weighted centroids of its triangles
    (:func:`triangle_average` with ``self_weight``).  On a regular triangle grid (default weight)
    one level is one level of the three-direction quartic box spline.  Needs a triangle mesh.

    rule (triangle scheme only): ``"centroid"`` (the book's, default) or a vertex rule smooth at every
    valence, ``"warren"`` or ``"loop"`` (:data:`VERTEX_RULES`): the midpoint split and averaging
    give the edge points as before, and every interior old vertex then moves by
    ``(1 - n beta) v + beta sum u`` instead (:func:`triangle_vertex_stencil`); with ``"loop"`` one
    level is Loop's scheme with Loop's weights on a closed mesh.  Boundary vertices keep the
    averaging's point.

    scheme None picks ``"triangle"`` for a triangle mesh and ``"quad"`` otherwise.
    levels: >= 0, within the work budget: each level multiplies the face corners by 4, and
    ``4^levels`` times the corners of the mesh is at most :data:`~goldman_lib.validation.MAX_ITEMS`
    / 4 (levels <= 8 for the cube, 24 corners).  Returns a new Mesh (the input is unchanged).
    Raises TypeError if mesh is not a Mesh; ValueError for an unknown scheme or rule, a negative
    level, a level over the budget, the triangle scheme on a mesh with non-triangular faces, or a
    rule other than ``"centroid"`` with the quad scheme or another self_weight.

    >>> m = centroid_averaging(cube(), 2)
    >>> m.n_faces, m.euler_characteristic()
    (96, 2)
    >>> centroid_averaging(octahedron(), 1, scheme="triangle").n_faces
    32
    """
    mesh = _check_mesh(mesh)
    corners = int(mesh._corners.size)
    levels = within_budget(levels, "levels", cost=lambda v: 4 ** v * corners, what="the subdivided mesh",
                           unit="face corners", limit=MAX_ITEMS // 4)
    if scheme is None:
        scheme = "triangle" if mesh.is_triangle else "quad"
    if scheme not in ("quad", "triangle"):
        raise ValueError(f"scheme must be 'quad' or 'triangle'; got {scheme!r}")
    w = _self_weight(self_weight)
    rule = _rule(rule, w)
    if scheme == "triangle":
        if not mesh.is_triangle:
            raise ValueError("scheme 'triangle' needs a triangle mesh; call triangulate(mesh) first")
        for _ in range(levels):
            new = triangle_average(midpoint_split(mesh), w)
            if rule != "centroid":
                new = new.with_vertices(_smooth_vertex_points(mesh, new._vertices, rule))
            mesh = new
        return mesh
    if rule != "centroid":
        raise ValueError(f"rule {rule!r} is a vertex rule of the triangle scheme; the quad scheme has rule 'centroid' only")
    for _ in range(levels):
        mesh = quad_average(bilinear_split(mesh))
    return mesh


def _smooth_vertex_points(old: Mesh, new_vertices: np.ndarray, rule: str) -> np.ndarray:
    """The new vertex array with the interior old vertices (rows 0..V-1) moved by the rule's
    vertex stencil ``(1 - n beta) v + beta sum u`` over the old mesh."""
    V, edges, nv = old._vertices, old.edges, old.n_vertices
    n = old.valences
    nbr_sum = _scatter_sum(edges.ravel(), V[edges[:, ::-1].ravel()], nv)
    beta = _rule_beta(rule, np.maximum(n, 3))
    pts = (1 - n * beta)[:, None] * V + beta[:, None] * nbr_sum
    out = new_vertices.copy()
    interior = ~old.boundary_vertices
    out[:nv][interior] = pts[interior]
    return out


# --------------------------------------------------------------------------------------------
# §30.3.2 and §30.4.2 stencils
# --------------------------------------------------------------------------------------------

def loop_beta(valence) -> np.ndarray | float:
    """Loop's weight of each neighbour in the vertex rule of his scheme (Loop 1987; Goldman §30.4.2):
    ``beta(n) = (5/8 - (3/8 + 1/4 cos(2 pi / n))^2) / n``, so ``v' = (1 - n beta) v + beta sum u``.

    Chosen so that the subdominant eigenvalue of the local subdivision matrix is
    ``3/8 + 1/4 cos(2 pi / n)`` with the vertex eigenvalue ``5/8 - n beta`` below it: a tangent plane at
    every valence.  beta(6) = 1/16 (the box-spline stencil), beta(3) = 3/16 (Warren's choice).
    valence: an integer >= 3 or an integer array of them.  Raises ValueError below 3.

    >>> loop_beta(6), loop_beta(3)
    (0.0625, 0.1875)
    """
    n = _valences(valence)
    beta = (5 / 8 - (3 / 8 + np.cos(2 * np.pi / n) / 4) ** 2) / n
    return float(beta) if np.ndim(beta) == 0 else beta


def warren_beta(valence) -> np.ndarray | float:
    """Warren's simplified weight of each neighbour in Loop's vertex rule (Warren and Weimer 2002;
    Goldman §30.4.2): ``3/16`` at valence 3 and ``3/(8n)`` otherwise, so ``v' = (1 - n beta) v + beta sum u``.
    Above valence 3 it is the book's centroid-averaging rule; at valence 3 it replaces 1/8 by 3/16,
    which removes the cone of the plain rule.
    valence: an integer >= 3 or an integer array of them.  Raises ValueError below 3.

    >>> warren_beta(3), warren_beta(4)
    (0.1875, 0.09375)
    """
    n = _valences(valence)
    beta = np.where(n == 3, 3 / 16, 3 / (8 * n))
    return float(beta) if np.ndim(beta) == 0 else beta


def _valences(valence, name="valence", cost=lambda v: v, what="the stencil", unit="neighbours"):
    """An integer valence >= 3 (returned as int) or a 1-D sequence of them (an int array), each within
    the work budget."""
    if isinstance(valence, (str, bytes)) or valence is None:
        raise TypeError(f"{name} must be an integer >= 3 or a sequence of them; got {valence!r}")
    try:
        arr = np.asarray(valence)
    except ValueError:
        raise TypeError(f"{name} must be an integer >= 3 or a flat sequence of them; got a ragged sequence") from None
    if arr.ndim == 0:
        return within_budget(valence, name, cost=cost, what=what, unit=unit, minimum=3)
    if arr.ndim != 1 or arr.size == 0:
        raise ValueError(f"{name} must be an integer or a non-empty flat sequence of integers; got shape {arr.shape}")
    return np.array([within_budget(x, f"{name}[{k}]", cost=cost, what=what, unit=unit, minimum=3)
                     for k, x in enumerate(arr.tolist())], dtype=np.int64)


def _rule(rule, self_weight):
    if rule not in VERTEX_RULES:
        raise ValueError(f"rule must be one of {VERTEX_RULES}; got {rule!r}")
    if rule != "centroid" and _self_weight(self_weight) != BOX_SPLINE_SELF_WEIGHT:
        raise ValueError(f"self_weight must be {BOX_SPLINE_SELF_WEIGHT} (the edge rule 3/8, 1/8 of Loop's scheme) "
                         f"with rule {rule!r}; got {self_weight}")
    return rule


def _rule_beta(rule, n):
    return loop_beta(n) if rule == "loop" else warren_beta(n)


def quad_vertex_stencil(valence: int) -> tuple[float, float, float]:
    """Weights of the vertex stencil of quadrilateral centroid averaging (Goldman §30.3.2).

    A vertex ``v`` of valence ``n`` in a quadrilateral mesh moves to
    ``a v + b (sum of its n edge neighbours) + c (sum of its n diagonal neighbours)`` with
    ``(a, b, c) = (9/16, 3/(8n), 1/(16n))``.  Derivation: after the bilinear split ``v`` lies in
    n quadrilaterals ``(v, m_i, F_i, m_{i+1})``; the average of their centroids is
    ``v/2 + (sum u_i)/(4n) + (sum F_i)/(4n)``, and ``F_i = (v + u_i + d_i + u_{i+1})/4``.
    For n = 4 this is the bicubic B-spline stencil ``[1, 6, 1]/8 x [1, 6, 1]/8``.

    >>> quad_vertex_stencil(4)
    (0.5625, 0.09375, 0.015625)
    """
    n = within_budget(valence, "valence", cost=lambda v: v, what="the stencil", unit="neighbours", minimum=3)
    return 9 / 16, 3 / (8 * n), 1 / (16 * n)


def quad_edge_stencil() -> tuple[float, float]:
    """Weights of the edge stencil of quadrilateral centroid averaging (Goldman §30.3.2).

    The new point of an interior edge ``(v, w)`` between quadrilaterals ``(v, w, x1, y1)`` and
    ``(w, v, y2, x2)`` is ``a (v + w) + b (x1 + y1 + x2 + y2)`` with ``(a, b) = (3/8, 1/16)``,
    whatever the valences of v and w.

    >>> quad_edge_stencil()
    (0.375, 0.0625)
    """
    return 3 / 8, 1 / 16


def quad_face_stencil(sides: int = 4) -> float:
    """Weight of each vertex in the face stencil (Goldman §30.3.2): the new face point is the
    centroid of the face, ``1/k`` times the sum of its k vertices (centroid averaging leaves the
    centroid of the bilinear split where it was).

    >>> quad_face_stencil()
    0.25
    """
    k = within_budget(sides, "sides", cost=lambda v: v, what="the stencil", unit="vertices", minimum=3)
    return 1 / k


def triangle_vertex_stencil(valence: int, self_weight: float = BOX_SPLINE_SELF_WEIGHT,
                            rule: str = "centroid") -> tuple[float, float]:
    """Weights of the vertex stencil of triangle centroid averaging (Goldman §30.4.2).

    A vertex of valence n moves to ``a v + b (sum of its n neighbours)``.  rule ``"centroid"`` (the
    book's): ``a = w + (1-w)/2`` and ``b = (1-w)/(2n)`` for the centroid weight ``w = self_weight``;
    with the default ``w = 1/4``: ``(5/8, 3/(8n))``; at n = 6 that is Loop's regular stencil
    ``(10/16, 1/16)``.  rule ``"warren"`` or ``"loop"``: ``b = beta(n)`` (:func:`warren_beta`,
    :func:`loop_beta`) and ``a = 1 - n b``, smooth at every valence (these need the default
    self_weight, whose edge stencil 3/8, 1/8 is Loop's).
    Raises ValueError for a valence below 3, an unknown rule, or a rule with another self_weight.

    >>> triangle_vertex_stencil(6)
    (0.625, 0.0625)
    >>> triangle_vertex_stencil(3, rule="warren")
    (0.4375, 0.1875)
    """
    n = within_budget(valence, "valence", cost=lambda v: v, what="the stencil", unit="neighbours", minimum=3)
    w = _self_weight(self_weight)
    if _rule(rule, w) != "centroid":
        b = _rule_beta(rule, n)
        return 1 - n * b, b
    return w + (1 - w) / 2, (1 - w) / (2 * n)


def triangle_edge_stencil(self_weight: float = BOX_SPLINE_SELF_WEIGHT) -> tuple[float, float]:
    """Weights of the edge stencil of triangle centroid averaging (Goldman §30.4.2).

    The new point of an interior edge ``(v, w)`` with opposite vertices ``x`` and ``y`` is
    ``a (v + w) + b (x + y)`` with ``a = w/2 + (1-w)/3`` and ``b = (1-w)/6``; with the default
    ``w = 1/4``: ``(3/8, 1/8)``, the edge stencil of the quartic box spline (and of Loop).

    >>> triangle_edge_stencil()
    (0.375, 0.125)
    """
    w = _self_weight(self_weight)
    return w / 2 + (1 - w) / 3, (1 - w) / 6


def apply_stencils(mesh: Mesh, scheme: str | None = None, self_weight: float = BOX_SPLINE_SELF_WEIGHT,
                   rule: str = "centroid") -> np.ndarray:
    """One level of centroid averaging computed directly from the stencils (Goldman §30.3.2, §30.4.2).

    Returns the new vertex positions in the numbering of :func:`centroid_averaging`: the vertex
    points, then the edge points, then (quadrilateral scheme) the face points.  The stencils hold
    for interior vertices and edges, so the mesh must be closed; the quadrilateral scheme needs
    a quadrilateral mesh and the triangle scheme a triangle mesh.  rule: the triangle scheme's
    vertex rule (:data:`VERTEX_RULES`, see :func:`triangle_vertex_stencil`).
    Raises ValueError otherwise.

    >>> m = cube()
    >>> np.allclose(apply_stencils(m), centroid_averaging(m, 1).vertices)
    True
    """
    mesh = _check_mesh(mesh)
    if scheme is None:
        scheme = "triangle" if mesh.is_triangle else "quad"
    if scheme not in ("quad", "triangle"):
        raise ValueError(f"scheme must be 'quad' or 'triangle'; got {scheme!r}")
    if scheme == "quad" and rule != "centroid":
        raise ValueError(f"rule {rule!r} is a vertex rule of the triangle scheme; the quad scheme has rule 'centroid' only")
    if not mesh.is_closed:
        raise ValueError("mesh must be closed for apply_stencils: the stencils are those of interior vertices and edges")
    V, C, nxt = mesh._vertices, mesh._corners, mesh._next
    edges, nv = mesh.edges, mesh.n_vertices
    n = mesh.valences
    nbr_sum = _scatter_sum(edges.ravel(), V[edges[:, ::-1].ravel()], nv)
    face_sum = np.add.reduceat(V[C], mesh._offsets, axis=0)
    ef = mesh.edge_faces
    ends = V[edges[:, 0]] + V[edges[:, 1]]
    wings = face_sum[ef[:, 0]] + face_sum[ef[:, 1]] - 2 * ends     # the other vertices of both faces
    if scheme == "quad":
        if not mesh.is_quad:
            raise ValueError("scheme 'quad' stencils need a quadrilateral mesh (apply one level of centroid averaging first)")
        diag_sum = _scatter_sum(C, V[C[nxt[nxt]]], nv)
        a, b, c = 9 / 16, 3 / (8 * n), 1 / (16 * n)
        vertex_pts = a * V + b[:, None] * nbr_sum + c[:, None] * diag_sum
        ea, eb = quad_edge_stencil()
        edge_pts = ea * ends + eb * wings
        face_pts = face_sum * quad_face_stencil(4)
        return np.concatenate([vertex_pts, edge_pts, face_pts])
    if not mesh.is_triangle:
        raise ValueError("scheme 'triangle' stencils need a triangle mesh; triangulate it first")
    w = _self_weight(self_weight)
    if _rule(rule, w) != "centroid":
        b = _rule_beta(rule, n)
        a = (1 - n * b)[:, None]
    else:
        a = w + (1 - w) / 2
        b = (1 - w) / (2 * n)
    vertex_pts = a * V + b[:, None] * nbr_sum
    ea, eb = triangle_edge_stencil(w)
    return np.concatenate([vertex_pts, ea * ends + eb * wings])


# --------------------------------------------------------------------------------------------
# §30.3.2 and §30.4.2 around one vertex: the local subdivision matrix
# --------------------------------------------------------------------------------------------

def local_subdivision_matrix(valence: int, scheme: str = "triangle",
                             self_weight: float = BOX_SPLINE_SELF_WEIGHT, rule: str = "centroid") -> np.ndarray:
    """The matrix of one level of centroid averaging around a vertex of valence n (Goldman §30.3.2,
    §30.4.2): the stencils, written as one linear map from a vertex's ring to its new ring.

    scheme ``"triangle"``: the points (rows) ``[v, u_1, ..., u_n]``, the neighbours of ``v`` in
    cyclic order (triangles ``(v, u_i, u_{i+1})``), go to ``[v', e_1, ..., e_n]``: the new vertex
    point and the new edge points of the edges ``(v, u_i)``, whose opposite vertices are
    ``u_{i-1}`` and ``u_{i+1}``.  Shape ``(n+1, n+1)``; weights from :func:`triangle_vertex_stencil`
    (with ``self_weight`` and the vertex ``rule``) and :func:`triangle_edge_stencil`.

    scheme ``"quad"``: ``[v, u_1..u_n, d_1..d_n]`` with faces ``(v, u_i, d_i, u_{i+1})`` go to
    ``[v', e_1..e_n, f_1..f_n]``: the vertex point, the edge points of ``(v, u_i)`` and the face
    points of the n faces.  Shape ``(2n+1, 2n+1)``; weights from :func:`quad_vertex_stencil`,
    :func:`quad_edge_stencil` and :func:`quad_face_stencil`.

    The new ring has the same structure as the old one (v' has valence n again), so ``S^k @ ring``
    is the ring after k levels: the eigenvalues of S (:func:`local_eigenvalues`) decide how the
    surface behaves at the vertex.  Rows sum to one.
    Raises ValueError for a valence below 3 (or beyond the work budget), an unknown scheme or rule,
    or a rule other than ``"centroid"`` with the quad scheme.

    >>> (local_subdivision_matrix(3) * 8).tolist()
    [[5.0, 1.0, 1.0, 1.0], [3.0, 3.0, 1.0, 1.0], [3.0, 1.0, 3.0, 1.0], [3.0, 1.0, 1.0, 3.0]]
    """
    n = within_budget(valence, "valence", cost=lambda m: (2 * m + 1) ** 2, what="the local subdivision matrix",
                      unit="entries", minimum=3)
    if scheme not in ("quad", "triangle"):
        raise ValueError(f"scheme must be 'quad' or 'triangle'; got {scheme!r}")
    if scheme == "quad" and rule != "centroid":
        raise ValueError(f"rule {rule!r} is a vertex rule of the triangle scheme; the quad scheme has rule 'centroid' only")
    i = np.arange(n)
    if scheme == "triangle":
        a, b = triangle_vertex_stencil(n, self_weight, rule)
        ea, eb = triangle_edge_stencil(self_weight)
        S = np.zeros((n + 1, n + 1))
        S[0, 0], S[0, 1:] = a, b
        S[1 + i, 0] = ea
        S[1 + i, 1 + i] += ea
        S[1 + i, 1 + (i - 1) % n] += eb
        S[1 + i, 1 + (i + 1) % n] += eb
        return S
    a, b, c = quad_vertex_stencil(n)
    ea, eb = quad_edge_stencil()
    f = quad_face_stencil(4)
    u = lambda k: 1 + k % n          # noqa: E731  (column of u_k)
    d = lambda k: 1 + n + k % n      # noqa: E731  (column of d_k)
    S = np.zeros((2 * n + 1, 2 * n + 1))
    S[0, 0], S[0, 1:n + 1], S[0, n + 1:] = a, b, c
    S[u(i), 0] += ea
    S[u(i), u(i)] += ea
    for cols in (u(i - 1), d(i - 1), d(i), u(i + 1)):   # the other vertices of faces i-1 and i
        S[u(i), cols] += eb
    for cols in (np.zeros(n, dtype=int), u(i), d(i), u(i + 1)):
        S[d(i), cols] += f
    return S


def local_eigenvalues(valence: int, scheme: str = "triangle",
                      self_weight: float = BOX_SPLINE_SELF_WEIGHT, rule: str = "centroid") -> np.ndarray:
    """Eigenvalues of :func:`local_subdivision_matrix`, sorted by decreasing modulus (Goldman §30.4.2).

    The first is 1 (rows sum to one: the ring converges to a limit point).  The ring's shape near
    the limit point is governed by the next ones: a tangent plane needs the subdominant eigenvalues
    lambda_1 = lambda_2 to be equal and strictly larger in modulus than all the others (the ring then
    shrinks like lambda_1^k and flattens onto a plane).  Both spectra here are real; the real parts
    are returned (the imaginary parts are rounding noise).

    >>> local_eigenvalues(6).round(4).tolist()[:4]
    [1.0, 0.5, 0.5, 0.25]
    >>> local_eigenvalues(3).round(4).tolist()
    [1.0, 0.25, 0.25, 0.25]
    >>> local_eigenvalues(3, rule="warren").round(4).tolist()
    [1.0, 0.25, 0.25, 0.0625]
    """
    S = local_subdivision_matrix(valence, scheme, self_weight, rule)
    ev = np.linalg.eigvals(S)
    ev = ev[np.lexsort((-ev.real, -np.round(np.abs(ev), 12)))]
    return ev.real


def tangent_plane_condition(valence: int, scheme: str = "triangle", rule: str = "centroid",
                            self_weight: float = BOX_SPLINE_SELF_WEIGHT, tol: float = 1e-9) -> bool:
    """Whether one level around a vertex of valence n meets the eigenvalue condition for a tangent
    plane (Goldman §30.4.2): ``1 > lambda_1 = lambda_2 > |lambda_3|`` for the eigenvalues of
    :func:`local_subdivision_matrix` (equal and strictly larger up to ``tol``).  Necessary, not
    sufficient: Reif's characteristic-map test is not made here.

    >>> tangent_plane_condition(3), tangent_plane_condition(3, rule="loop")
    (False, True)
    """
    tol = as_float(tol, "tol")
    if not 0 <= tol < 0.5:
        raise ValueError(f"tol must lie in [0, 0.5); got {tol}")
    ev = np.abs(local_eigenvalues(valence, scheme, self_weight, rule))
    return bool(abs(ev[0] - 1) <= tol and ev[1] < 1 - tol and abs(ev[1] - ev[2]) <= tol and ev[2] > ev[3] + tol)


def valence_table(valences=range(3, 9)) -> list[dict]:
    """The eigen-analysis of one level around an extraordinary vertex, valence by valence, for the
    quad scheme and the triangle scheme under each vertex rule (Goldman §30.3.2, §30.4.2).

    Returns one row per valence: ``{"valence": n, "quad": (l1, l2, l3, ok), "centroid": ...,
    "warren": ..., "loop": ...}`` with the subdominant eigenvalues ``lambda_1, lambda_2, lambda_3``
    (:func:`local_eigenvalues`) and ``ok`` the verdict of :func:`tangent_plane_condition`.
    valences: integers >= 3 (at most 64 of them, each within the work budget of the matrix).

    >>> row = valence_table([3])[0]
    >>> row["centroid"][3], row["warren"][3], row["loop"][3], row["quad"][3]
    (False, True, True, True)
    """
    ns = np.atleast_1d(_valences(valences, "valences", cost=lambda m: (2 * m + 1) ** 2,
                                 what="the local subdivision matrix", unit="entries")).tolist()
    if len(ns) > 64:
        raise ValueError(f"valences must hold at most 64 valences; got {len(ns)}")
    rows = []
    for n in ns:
        row = {"valence": n}
        for key, scheme, rule in (("quad", "quad", "centroid"), ("centroid", "triangle", "centroid"),
                                  ("warren", "triangle", "warren"), ("loop", "triangle", "loop")):
            ev = local_eigenvalues(n, scheme, rule=rule)
            row[key] = (float(ev[1]), float(ev[2]), float(ev[3]), tangent_plane_condition(n, scheme, rule))
        rows.append(row)
    return rows


def ring_height_ratio(mesh: Mesh, vertex: int) -> float:
    """How pointed a mesh is at a vertex: the height of the vertex above the plane of its 1-ring
    (least-squares plane through the neighbours' centroid), over the ring's mean radius about that
    centroid (Goldman §30.4.2, a measure for the cone of the eigen-analysis).

    At a point where the limit surface has a tangent plane the ratio falls towards 0 level after
    level (height ~ curvature r^2 against radius r); at a cone it stays.  The tetrahedron's corner:
    sqrt(2).

    >>> round(ring_height_ratio(tetrahedron(), 0), 4)
    1.4142
    """
    mesh = _check_mesh(mesh)
    v = as_int(vertex, "vertex", minimum=0, maximum=mesh.n_vertices - 1)
    ring = mesh._vertices[mesh.neighbours(v)]
    if mesh._vertices.shape[1] != 3:
        raise ValueError(f"mesh must have vertices in space (d = 3) for ring_height_ratio; got d = {mesh._vertices.shape[1]}")
    c = ring.mean(axis=0)
    normal = np.linalg.svd(ring - c)[2][-1]
    radius = float(np.linalg.norm(ring - c, axis=1).mean())
    if radius == 0:
        raise ValueError(f"mesh has a degenerate ring at vertex {v} (all its neighbours coincide)")
    return abs(float((mesh._vertices[v] - c) @ normal)) / radius


def angle_defects(mesh: Mesh) -> np.ndarray:
    """The angle defect at every vertex, ``2 pi - (sum of the face angles there)`` (``pi - sum`` at
    a boundary vertex): the discrete Gaussian curvature, integrated over the vertex's share of the
    surface (Goldman §30.4.2, to make a cone visible).

    Over a mesh of planar faces (triangles always are) the defects add up to ``2 pi chi`` (the
    discrete Gauss-Bonnet theorem); a bent quadrilateral's angles need not add up to 2 pi.
    Where the limit surface has a tangent plane the defect at a vertex shrinks level after level
    (the surface round it flattens); at a cone it stays, because the vertex and its ring keep their
    shape.  The tetrahedron's corners: pi each; the cube's: pi/2.

    mesh: a :class:`Mesh` with vertices in space (d = 3).  Returns ``(V,)`` angles in radians.
    Raises ValueError for a mesh that is not 3D or has a face with a zero-length edge.

    >>> angle_defects(cube()).round(6).tolist() == [round(np.pi / 2, 6)] * 8
    True
    >>> round(float(angle_defects(centroid_averaging(tetrahedron(), 2)).sum() / np.pi), 12)   # 2 pi chi, chi = 2
    4.0
    """
    mesh = _check_mesh(mesh)
    V = mesh._vertices
    if V.shape[1] != 3:
        raise ValueError(f"mesh must have vertices in space (d = 3) for angle_defects; got d = {V.shape[1]}")
    c = mesh._corners
    to_next = V[c[mesh._next]] - V[c]
    to_prev = V[c[mesh._prev]] - V[c]
    ln, lp = np.linalg.norm(to_next, axis=1), np.linalg.norm(to_prev, axis=1)
    if not (ln > 0).all() or not (lp > 0).all():
        k = int(np.flatnonzero((ln <= 0) | (lp <= 0))[0])
        raise ValueError(f"mesh has a zero-length edge at face {int(mesh._face_of_corner[k])} (vertex {int(c[k])})")
    # the angle between the two edges at each corner, by atan2 (accurate for small and flat angles)
    angle = np.arctan2(np.linalg.norm(np.cross(to_next, to_prev), axis=1), np.einsum("ij,ij->i", to_next, to_prev))
    total = np.bincount(c, weights=angle, minlength=mesh.n_vertices)
    full = np.full(mesh.n_vertices, 2 * np.pi)
    full[mesh.boundary_vertices] = np.pi
    return full - total


def cone_ratios(mesh: Mesh, levels: int, vertex: int = 0, scheme: str | None = None, rule: str = "centroid",
                self_weight: float = BOX_SPLINE_SELF_WEIGHT) -> np.ndarray:
    """:func:`ring_height_ratio` of one original vertex after 0, 1, ..., ``levels`` levels of
    :func:`centroid_averaging` (old vertices keep their numbers, so vertex ``vertex`` is followed
    through the levels).  Constant ratios mean a cone; falling ratios a tangent plane.
    Returns ``(levels + 1,)``.  Raises as :func:`centroid_averaging` and :func:`ring_height_ratio`.

    >>> cone_ratios(tetrahedron(), 3).round(4).tolist()
    [1.4142, 1.4142, 1.4142, 1.4142]
    >>> bool(cone_ratios(tetrahedron(), 3, rule="loop")[-1] < 0.2)
    True
    """
    mesh = _check_mesh(mesh)
    corners = int(mesh._corners.size)
    levels = within_budget(levels, "levels", cost=lambda v: 4 ** v * corners, what="the subdivided mesh",
                           unit="face corners", limit=MAX_ITEMS // 4)
    out = [ring_height_ratio(mesh, vertex)]
    for _ in range(levels):
        mesh = centroid_averaging(mesh, 1, scheme, self_weight, rule)
        out.append(ring_height_ratio(mesh, vertex))
    return np.array(out)

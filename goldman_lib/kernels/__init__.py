"""The unchecked layer (``hazmat``): each kernel that several modules need, once, on validated arrays.

No input checking, no copying beyond what the algorithm needs, stacks of problems at once.  The
checked public functions validate their input and call these; other library modules call these
directly on data they validated (the hot paths: the tracer's inner levels, per-pixel work).
Views, notebooks and exercise checkers call the public functions only.  Every name here is
public inside the package: no library module imports another module's private (``_``) name
(``tests/library/test_imports_private.py`` reads the imports).

The map: each kernel, what it computes, the book section it serves, and who calls it.

:mod:`~goldman_lib.kernels.pyramids` -- de Casteljau's and de Boor's pyramids
    ``casteljau_level``: one level ``s P_j + t P_{j+1}`` (§24.2), the one de Casteljau routine; it
        runs every pyramid below, on arrays, lists of arrays, or lists of numbers.
    ``casteljau_apex``, ``curve_points``, ``patch_points``: curve and patch points for many parameters
        (§24.2, §24.6; ``casteljau_level``'s arithmetic node by node in a per-thread scratch, ``workspace``): ``bezier.de_casteljau``, ``derivative``, ``de_casteljau_with_derivative``,
        ``curve_crossings``, ``patch_de_casteljau``, ``patch_derivatives``; ``bezier_intersection``'s
        Newton steps and residuals.
    ``casteljau_levels``: every level, one parameter per level: ``bezier.de_casteljau_steps`` (§24.2),
        ``blossom.blossom_steps`` (§26.3).
    ``casteljau_blossom``: the Bezier blossom at many argument sets: ``blossom.blossom`` (§26.2).
    ``split``, ``split_patches``, ``quarter``: subdivision (§25.2, §25.3.2): ``bezier_subdivision``
        (``subdivide``, ``subdivide_uniform``, ``render_by_subdivision``, ``subdivide_patch``,
        ``subdivide_patch_uniform``, ``render_patch_by_subdivision``, ``smooth_continuation``,
        ``join_order``), ``bezier_intersection`` (curve and patch intersection), ``knot_insertion.render_by_subdivision``.
    ``split_xy``: both coordinates of a planar polygon of plain floats halved in one call (§25.3.1): the
        inner loop of ``bezier_intersection.intersect_curves`` (cubics and quadratics written out with
        ``casteljau_level``'s arithmetic; ``tests/library/test_kernels.py`` checks them against it bit for bit).
    ``point_and_tangent``: point and derivative from one scalar pyramid (§24.5; cubics and quadratics
        written out the same way):
        ``bezier_intersection``'s Newton refinement of curve intersections (§25.3.1).
    ``bernstein_rows``: the Bernstein table (§24.3): ``bezier.bernstein``, ``bernstein_evaluate``,
        ``patch_evaluate_grid``; ``bezier_subdivision.polygon_distance``, ``net_distance``.
    ``de_boor_pyramid``: de Boor's pyramid in place with caller-supplied node weights (§27.2-27.5),
        the one de Boor / blossom routine; it runs the two below and ``bspline.de_boor_steps``,
        ``bspline.global_pyramid`` (a level at a time), ``knot_insertion.oslo_steps``.
    ``de_boor_points``, ``de_boor_tables``: B-spline points for many parameters, weights tabulated
        per span (§27.3): ``bspline.de_boor``, ``bspline.derivative``, ``bspline.curve_points``.
    ``de_boor_blossom``: B-spline blossoms at many label sets (§27.2, §28.2): ``bspline.blossom``,
        ``knot_insertion`` (``boehm_insert``, ``oslo``, ``to_piecewise_bezier``, ...).
    ``domain``: the parameter domain of a knot vector (§27.2): ``bspline``, ``knot_insertion``.

:mod:`~goldman_lib.kernels.polygons` -- control polygons measured and rewritten
    ``flatness``, ``patch_flatness`` (§25.3): ``bezier_subdivision``, ``bezier_intersection``,
        ``knot_insertion.render_by_subdivision``.
    ``signed_distances``, ``sign_changes`` (§24.4): ``bezier.variation_count``, ``curve_crossings``,
        ``bezier_subdivision.subdivision_variation_counts``.
    ``elevate`` (§24.5): ``bezier.elevate_degree``, ``bezier_subdivision.join_order``.
    ``ear_clip`` (§19.3): the triangles that draw ``simple_surfaces.Polygon`` (``Polygon.mesh``).
    ``clip_half_space``, ``clip_to_view`` (§22.1): Sutherland-Hodgman against one plane, and against a
        camera's near plane and widened frustum: ``camera.Camera.clip_polygon`` (checked) and
        ``hidden_surfaces`` (the near plane and the guard band of every hidden-surface algorithm).

:mod:`~goldman_lib.kernels.roots` -- real roots of polynomials, many at once
    ``quadratic_roots``, ``depressed_quartic_roots``, ``polynomial_roots`` (§19.4-19.7): the checked
        ``roots.quadratic_roots`` and ``roots.real_roots`` and, per ray, the surfaces of
        ``simple_surfaces`` (quadrics, torus, surface of revolution).

:mod:`~goldman_lib.kernels.illumination` -- the shading model of chapter 16
    ``phong``, ``cosines``, ``reflect`` (§16.3-16.6): ``lighting.intensity``, ``diffuse``, ``specular``,
        ``reflect`` (checked) and, at every ray level, ``ray_tracing``'s local light and reflected rays.

:mod:`~goldman_lib.kernels.frames` -- vectors, lengths and normals
    ``norm`` (§3): lengths at any magnitude: ``vectors``, ``vector_geometry``, ``transforms``,
        ``quaternions``, ``mass_points``, ``lighting``, ``ray_tracing``.
    ``unit_rows``, ``row_dots`` (§16.5): ``lighting`` (``unit_rows`` and the shading model),
        ``ray_tracing``'s inner levels (reflected and refracted directions), ``vector_geometry``.
    ``newell`` (§11.4, §21.1): Newell's normal, unnormalised: ``vector_geometry.newell_normal``;
        ``unit_newell`` (§20.3, §21.1), of unit length:
        ``shading.unit_newell_normal`` (checked) and the planarity test of ``solid_modeling``'s B-rep faces.
    ``slerp`` (§11.6, §21.4.4): ``vector_geometry.slerp`` (checked) and, per pixel, Phong shading with
        slerp (``shading._slerp_pair``).
    ``frame`` (§19, §23.3): orthonormal frames ``u, v, w`` completing unit vectors, ``u`` along an optional
        ``major`` (else the coordinate axis of least ``|w_i|``) projected off ``w``, vectorised over rows:
        ``simple_surfaces``' planes, polygons, cylinders, cones and quadrics (their local axes) and
        ``radiosity.hemicube_form_factors`` (each patch's hemi-cube axes).

:mod:`~goldman_lib.kernels.iteration` -- iterated function systems
    ``apply_affine_maps`` (§6.1): ``ifs.deterministic``, ``ifs.map_images``.
    ``apply_maps``, ``iterate_maps`` (§29.3-29.4): ``subdivision_matrices.attractor``,
        ``barycentric_attractor``.
    ``choose``, ``chaos_steps`` (§6.3-6.4): the chaos game's map choices (``Generator.choice``'s
        numbers, faster) and its chains: ``ifs.chaos_game``, ``ifs.chaos_game_with_maps``.

:mod:`~goldman_lib.kernels.relaxation` -- Jacobi and Gauss-Seidel sweeps for ``x = (c + w G x) / d``
    ``gather``, ``jacobi_update``, ``gauss_seidel_sweep``: ``fixed_point.jacobi``,
        ``fixed_point.gauss_seidel`` (§7.3.2, ``A x = b``), ``radiosity.jacobi``, ``radiosity.gauss_seidel``
        (§23.5, ``B = E + rho F B``); one keyword spelling for all of them (``tol``, ``max_iter``,
        ``full_output``).
    ``Convergence``: the one record of an iteration (``full_output=True``), returned by every solver of
        ``fixed_point`` (also Newton and fixed-point iteration; it is ``fixed_point.Convergence``) and of
        ``radiosity`` (also ``progressive_refinement``, with its ``shooters``).

:mod:`~goldman_lib.kernels.meshes` -- polygon meshes and triangle meshes
    ``CUBE_VERTICES``, ``CUBE_FACES``, ``TETRAHEDRON_VERTICES``, ``TETRAHEDRON_FACES`` (§20.3, §30.4): the
        one cube and tetrahedron: ``subdivision_surfaces.cube``, ``tetrahedron`` and ``solid_modeling.cube``,
        ``tetrahedron`` (scaled).
    ``flatten``, ``edge_table``, ``fan_triangles`` (§20.3, §30.4): faces as flat corners, their distinct
        edges, their fans: ``subdivision_surfaces.Mesh`` (``edges``, ``edge_faces``, ``triangulate``) and
        ``solid_modeling.BRep`` (``edges``, ``triangles``); ``BRep.from_mesh`` and ``Mesh.from_brep`` convert.
    ``same_direction_edges`` (§20.3, §30.4): the directed edges two faces run the same way, the one
        orientation test: ``subdivision_surfaces.Mesh`` (its check on construction) and
        ``solid_modeling.BRep.problems``.
    ``rasterise`` (§21.2-21.3, §22.2): the one scan conversion: ``rasteriser.rasterise_triangles`` and
        ``rasteriser.gouraud_triangle`` (checked), ``shading.render``, ``hidden_surfaces``' painter's coverage.

``number`` (below): numbers in error messages, six significant digits: ``bspline``, ``knot_insertion``.
"""

from __future__ import annotations

from goldman_lib.kernels import frames, iteration, meshes, polygons, pyramids, relaxation, roots

__all__ = ["frames", "iteration", "meshes", "polygons", "pyramids", "relaxation", "roots", "number"]


def number(x) -> str:
    """A number in error messages and status lines: six significant digits (``0.333333``, ``1e-07``).

    >>> number(1 / 3), number(1e-7)
    ('0.333333', '1e-07')
    """
    return f"{float(x):.6g}"

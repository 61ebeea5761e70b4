"""Views and widget factories for the course notebooks.

The framework (knows no chapter):

- ``views.interactive``     the widget pattern: :class:`InteractiveView` (controls + view + a plain
                            ``update`` callback + a static fallback image), ``float_slider``,
                            ``int_slider``, ``dropdown``, the covering sweep of every factory
- ``views.drag``            points dragged with the mouse (one helper for every 2D view)
- ``views.three``           every use of pythreejs goes through :class:`SceneView`
- ``views.vectors3d``       the shared three.js view of Part II: points, arrows, planes, polygons
- ``views.light_control``   the one light-position control of Part III
- ``views.render_control``  progress bars and the full-size "render" button
- ``views.agreement``       a check printed as the values it compares (ours | reference | gap, the
                            gap as a portable bound), not as "...: True"
- ``views.style``           one figure size, dpi and palette for every chapter
- ``views._checks``         the checks of the values a widget's ``update`` receives
- ``views.ifs_editor``, ``views.knot_editor``, ``views._program_editor``: the shared editors (IFS
  maps, knot vectors, turtle and CODO programs)

The chapters' views, one module per library module (see :mod:`goldman_lib` for the chapters):
``turtle`` (1), ``fractals`` (2-3), ``affine`` (4), ``codo`` (5), ``ifs`` (6), ``fixed_point`` (7),
``conformal_ifs`` (8); ``vectors`` (9-10), ``vector_geometry`` (11), ``transforms`` (12-13),
``mass_points`` (14), ``quaternions`` (15); ``color_intensity`` (16), ``ray_tracing`` (17),
``surfaces`` (18), ``simple_surfaces`` (19), ``solid_modeling`` (20), ``shading`` (21),
``hidden_surfaces`` (22), ``radiosity`` (23); ``bezier`` (24), ``bezier_subdivision`` (25),
``blossom`` (26), ``bspline`` (27), ``knot_insertion`` (28), ``subdivision_matrices`` (29),
``subdivision_surfaces`` (30).  Every factory returns an :class:`InteractiveView` and is found by
``interactive.discover_factories`` for the sweep tests and the callback benchmark.

Importing this package imports matplotlib (Agg unless the notebook chose ``%matplotlib widget``);
ipywidgets and pythreejs are imported by the modules that need them.
"""

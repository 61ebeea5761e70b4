"""The widget framework of the course: what every chapter's views are built from.

The rule that puts a module here rather than in :mod:`goldman_lib.views`: **a module that is not
one chapter's views belongs to the framework if it knows no chapter, or if the views of more than
one chapter are built on it** (a shared editor, a shared scene); a chapter's own module (its plots
and factories, named as the library module it shows) stays in :mod:`goldman_lib.views`, even where
a later chapter's views reuse one of its drawings (``views.turtle``'s strokes in chapters 2-5 and
8, ``views.bezier``'s curve plots in chapters 25-26: Parts depend backwards).  The framework never
imports :mod:`goldman_lib.views` (``tests/library/test_import_layers.py`` reads the imports), so a
chapter's views can change without touching it; the library proper (every other module of
:mod:`goldman_lib`) imports neither package.

The pattern, every view:

- ``widgets.interactive``     :class:`~goldman_lib.widgets.interactive.InteractiveView` (controls +
                              view + a plain ``update`` callback + a static fallback image, the
                              attributes a view may carry declared in ``CARRIES``), ``float_slider``,
                              ``int_slider``, ``dropdown``, ``figure_widget``, ``figure_png``, and the
                              check of every value ``update`` receives (``check_control_values``)
- ``widgets.checks``          one check per kind of control (a number in a slider's range, an option
                              of a picker, ...): the messages name the control and the rule
- ``widgets.style``           one figure size, dpi and palette for every chapter
- ``widgets.drag``            points dragged with the mouse (:class:`~goldman_lib.widgets.drag.PointDrag`,
                              ``drag_sliders``: one helper for every 2D view)
- ``widgets.three``           every use of pythreejs goes through :class:`~goldman_lib.widgets.three.SceneView`
- ``widgets.render_control``  progress bars and the full-size "render" button of the rendering chapters
- ``widgets.agreement``       a check printed as the values it compares (ours | reference | gap, the
                              gap as a portable bound), not as "...: True"

Components shared by several chapters (each used by the views of more than one):

- ``widgets.light_control``   the one light-position control of Part III (chapters 16, 17, 19, 21, 23)
- ``widgets.vectors3d``       the three.js view of Part II (chapters 9-15): points, arrows, planes,
                              polygons; and chapter 9's vector-products widget built on it
- ``widgets.program_editor``  the program editor of the turtle (chapter 1) and CODO (chapter 5)
- ``widgets.ifs_editor``      the IFS map editor (chapters 6, 7 and 8)
- ``widgets.knot_editor``     the knot-vector editor (chapters 27 and 28) and chapter 27's editors
                              of B-spline and NURBS curves and surfaces built on it

The factories of the last three are displayed by the chapters' notebooks as they are; the chapter
package lists them with its own (:func:`goldman_lib.views.factories`), which is how the sweep
tests and the callback benchmark find every widget.  Test hooks (driving a drag from code,
finding a live view by its number) live with the tests (``tests/browser/kernel_hooks.py``).

Importing this package imports nothing heavy; its modules import matplotlib and ipywidgets, and
``widgets.three`` imports pythreejs only when a scene is built.
"""

"""goldman_lib: the support library of the course on Goldman's *An Integrated Introduction to
Computer Graphics and Geometric Modeling*.

One module per topic, named with the book's vocabulary, in the order of the book (the chapter's
notebook is ``course/NN_*.ipynb``; its views are the module of the same name in
:mod:`goldman_lib.views`, built from the widget framework :mod:`goldman_lib.widgets`; its exercise
checkers are ``goldman_lib.exercises.chNN``):

Part I, two-dimensional computer graphics: from common curves to intricate fractals

- ``turtle``                chapter 1, turtle graphics and the turtle-program language
- ``fractals``              chapters 2-3, recursive turtle programs, fractals and their strangeness
- ``affine``                chapter 4, affine transformations of the plane (3x3 matrices)
- ``codo``                  chapter 5, affine geometry and the CODO language
- ``ifs``                   chapter 6, iterated function systems and their fractals
- ``fixed_point``           chapter 7, the trivial fixed point theorem, Newton, Jacobi, Gauss-Seidel
- ``conformal_ifs``         chapter 8, recursive turtle programs as conformal IFS

Part II, mathematical methods for three-dimensional computer graphics

- ``vectors``               chapters 9-10, points, vectors, dot, cross and determinant
- ``vector_geometry``       chapter 11, applications of vector geometry
- ``transforms``            chapters 12-13, coordinate-free formulas and 4x4 matrices
- ``mass_points``           chapter 14, projective space, mass-points, pseudoperspective
- ``quaternions``           chapter 15, complex numbers and quaternions

Part III, three-dimensional computer graphics: realistic rendering

- ``lighting``              chapter 16, the one lighting model (used by every renderer below)
- ``camera``                chapters 17, 21-22, the pinhole ``Camera``: the one place a pixel becomes a
                            ray (``rays``) and a point a pixel (``project``, the near-plane clip)
- ``ray_tracing``           chapter 17, recursive ray tracing (``render`` with anti-aliasing and progress)
- ``surfaces``              chapter 18, implicit, parametric, deformed and procedural surfaces
- ``roots``                 chapter 19, real roots of polynomials (quadratics, quartics, companion matrices)
- ``simple_surfaces``       chapter 19, the simple surfaces and the ray-surface contract
- ``solid_modeling``        chapter 20, boundary representations, CSG and octrees
- ``rasteriser``            chapters 21-22, the one scan conversion with a depth buffer
- ``shading``               chapter 21, normals, the sphere mesh and five shading modes (``render``)
- ``hidden_surfaces``       chapter 22, six hidden-surface algorithms on one scene
- ``radiosity``             chapter 23, form factors and the radiosity equations

Part IV, geometric modeling: freeform curves and surfaces

- ``bezier``                chapter 24, Bezier curves and tensor-product patches
- ``bezier_subdivision``    chapter 25, subdivision and rendering
- ``bezier_intersection``   chapter 25, intersection by subdivision
- ``blossom``               chapter 26, blossoming
- ``bspline``               chapter 27, B-splines and NURBS
- ``knot_insertion``        chapter 28, knot insertion (Boehm, Oslo), subdivision
- ``subdivision_matrices``  chapter 29, subdivision matrices and IFS
- ``subdivision_surfaces``  chapter 30, subdivision surfaces

Under them all: ``validation`` (argument checks and work budgets: the messages name the parameter
and the rule), ``angles`` (degrees), ``kernels`` (the unchecked array kernels the checked functions share: de Casteljau and de Boor pyramids, polygons, frames, meshes, iteration, relaxation, roots; one home each), and

- ``goldman_lib.exercises``  the checkers of the notebooks' exercises, "show that" exercises and
  programming projects (``deal`` makes numeric exercises deal new instances)
- ``goldman_lib.widgets``    the widget framework: ``InteractiveView`` (controls + a plain ``update``),
  sliders, mouse drags, three.js scenes, the light control, the render button, the editors several
  chapters share (IFS maps, knot vectors, programs); it knows no chapter
- ``goldman_lib.views``      the chapters' views: one module per chapter, its plots and widget
  factories, built from ``goldman_lib.widgets`` (``views.factories()`` lists every factory)

Conventions shared by every module: points are numpy arrays with coordinates in the last axis;
angles are in degrees; transformation matrices act on row vectors from the right (``Q = P @ M``);
bad input raises ``ValueError``/``TypeError`` naming the parameter and the rule; randomness comes
in through an ``rng`` argument.

Importing ``goldman_lib`` (or any of the modules above) does not import matplotlib, ipywidgets or
pythreejs; only the modules of ``goldman_lib.widgets`` and ``goldman_lib.views`` do.  The layers
import only downwards: the library imports neither package, the framework never imports the views
(``tests/library/test_import_layers.py``).
"""

__version__ = "0.1.0"

__all__ = ["__version__"]

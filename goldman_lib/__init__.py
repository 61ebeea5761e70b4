"""goldman_lib: the support library of the course on Goldman's *An Integrated Introduction to
Computer Graphics and Geometric Modeling*.

One module per topic, named with the book's vocabulary:

- ``goldman_lib.turtle``     chapter 1, turtle graphics and a small turtle-program language
- ``goldman_lib.bezier``     chapter 24, Bezier curves and tensor-product patches
- ``goldman_lib.exercises``  checkers for the notebooks' exercises
- ``goldman_lib.views``      matplotlib and three.js views and the widget factories

Conventions shared by every module: points are numpy arrays with coordinates in the last axis;
angles are in degrees; transformation matrices act on row vectors from the right (``Q = P @ M``);
bad input raises ``ValueError``/``TypeError`` naming the parameter and the rule; randomness comes
in through an ``rng`` argument.

Importing ``goldman_lib`` (or ``goldman_lib.turtle`` / ``goldman_lib.bezier``) does not import
matplotlib, ipywidgets or pythreejs; only ``goldman_lib.views`` does.
"""

__version__ = "0.1.0"

__all__ = ["__version__"]

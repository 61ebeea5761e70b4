"""Every input gets bounded work and a clear answer: a fuzz test over every public function of
``goldman_lib`` (the views and the exercise checkers have their own sweeps).

Functions are found by discovery, as the widget sweeps find widget factories: each module of the
package (walked with :mod:`pkgutil`), each name in its ``__all__`` (or, without one, each name not
starting with ``_`` and defined there), functions, the constructors of classes that check their
input and those classes' public methods (exceptions and plain result records -- NamedTuples and
dataclasses without ``__post_init__`` -- are left out: they hold what the library computed, they
read no input).

Each function needs one *valid example call*.  The examples are found by running the modules'
doctests with every public function wrapped in a recorder (the first call a doctest makes is the
example); :func:`_extra_examples` adds the few that no doctest calls.  A public function without an
example fails :func:`test_every_public_function_has_a_valid_example`, so a new module of Parts II
and III adds a doctest (or an entry there) and is then fuzzed like the rest.

Then every parameter, in turn, gets a battery of bad values (NaN, +-inf, +-1e308, 10**12, 0, -1, an
empty list, a ragged list, a complex number, a string, None, and, for an array, a NaN inside,
all-equal points, a single point, wrong shapes and complex entries) with the other parameters at the
example's values.  In Parts II and III (:data:`PART23`) every parameter also gets magnitudes 1e160-1e308
(where a squared length or a product of two inputs overflows though the input is finite), and every
object a function or method is given (``self``, a scene, a camera, a light) is rebuilt by its
constructor with one input at those magnitudes (:func:`huge_objects`): a sphere of radius 1e160, a
light of intensity 1e300 inside a scene.  Each call runs in a worker subprocess with a wall-clock limit of
:data:`TIME_LIMIT` seconds and a memory limit (``RLIMIT_AS``, :data:`MEMORY_LIMIT` bytes more than
the parent uses) and must either return a finite result (no NaN or infinity anywhere in what it
returns) or raise ``ValueError``/``TypeError`` whose message names the parameter (a
library-specific subclass of ``ValueError``, such as the languages' syntax errors, passes as is).

:data:`PROBES` are the adversarial probe of the issue "Every input gets bounded work and a clear
answer", kept as explicit regression examples.
"""

from __future__ import annotations

import copy
import dataclasses
import doctest
import functools
import importlib
import inspect
import math
import multiprocessing
import os
import pkgutil
import re
import resource
import sys
import time
from multiprocessing.connection import wait

import numpy as np
import pytest

import goldman_lib

TIME_LIMIT = float(os.environ.get("GOLDMAN_FUZZ_TIME_LIMIT", "1.0"))
MEMORY_LIMIT = 2 * 1024 ** 3
WORKERS = max(1, min(4, os.cpu_count() or 1))
SKIP_PACKAGES = ("goldman_lib.views", "goldman_lib.widgets", "goldman_lib.exercises", "goldman_lib.kernels")


# -- discovery -----------------------------------------------------------------------------------
def _modules():
    found = []
    for info in pkgutil.walk_packages(goldman_lib.__path__, "goldman_lib."):
        if info.name.startswith(SKIP_PACKAGES) or info.name.rsplit(".", 1)[1].startswith("_"):
            continue   # private modules; goldman_lib.kernels is the unchecked layer under the checked API
        found.append(importlib.import_module(info.name))
    return found


def _is_record(cls) -> bool:
    """Exceptions and plain result records: their constructors read no learner input."""
    if issubclass(cls, BaseException):
        return True
    if issubclass(cls, tuple) and hasattr(cls, "_fields"):
        return True
    return dataclasses.is_dataclass(cls) and not hasattr(cls, "__post_init__")


def _public(module) -> dict:
    names = getattr(module, "__all__", None)
    if names is None:
        names = [k for k, v in vars(module).items() if not k.startswith("_")
                 and (inspect.isfunction(v) or inspect.isclass(v)) and v.__module__ == module.__name__]
    out = {}
    for name in names:
        obj = getattr(module, name)
        home = getattr(obj, "__module__", module.__name__) or module.__name__
        if home != module.__name__ and home.startswith("goldman_lib.") and not home.rsplit(".", 1)[1].startswith("_"):
            continue   # a re-export (bezier.subdivide is bezier_subdivision.subdivide): fuzzed in its home module
        if inspect.isfunction(obj) or (inspect.isclass(obj) and not _is_record(obj)):
            out[f"{module.__name__[len('goldman_lib.'):]}.{name}"] = obj
    return out


def _skipped_records(modules) -> list[str]:
    out = []
    for module in modules:
        for name in getattr(module, "__all__", []):
            obj = getattr(module, name)
            if inspect.isclass(obj) and _is_record(obj):
                out.append(f"{module.__name__[len('goldman_lib.'):]}.{name}")
    return out


def _methods(functions) -> dict:
    """The public methods (with parameters) of the fuzzed classes, as ``{"module.Class.method": function}``:
    an example call of a method is ``(instance, *args)``."""
    out = {}
    for key, cls in functions.items():
        if not inspect.isclass(cls):
            continue
        for name, fn in vars(cls).items():
            if name.startswith("_") or not inspect.isfunction(fn):
                continue
            if any(p != "self" for p in inspect.signature(fn).parameters):
                out[f"{key}.{name}"] = fn
    return out


def _record_examples(modules, functions) -> dict:
    """The first call of each public function and method in the modules' doctests:
    ``{key: (args, kwargs)}`` (a method's args start with its instance)."""
    found = {}
    patched = []
    for key, fn in functions.items():     # methods: recorded wherever a doctest calls them
        if key.count(".") == 2:
            cls = functions[key.rsplit(".", 1)[0]]

            def method_recorder(self, *args, _key=key, _fn=fn, **kwargs):
                try:
                    snapshot = copy.deepcopy(((self,) + args, kwargs))
                except Exception:  # noqa: BLE001
                    snapshot = None
                result = _fn(self, *args, **kwargs)
                if snapshot is not None:
                    found.setdefault(_key, snapshot)
                return result

            patched.append((cls, fn.__name__, fn))
            setattr(cls, fn.__name__, functools.wraps(fn)(method_recorder))
    try:
        _run_doctests(modules, functions, found)
    finally:
        for cls, name, fn in patched:
            setattr(cls, name, fn)
    return found


def _run_doctests(modules, functions, found) -> None:
    for module in modules:
        short = module.__name__[len("goldman_lib."):]
        globs = dict(vars(module))

        def wrap(key, fn):
            @functools.wraps(fn)
            def recorder(*args, **kwargs):
                try:
                    snapshot = copy.deepcopy((args, kwargs))
                except Exception:  # noqa: BLE001 - an argument that cannot be copied is no example
                    snapshot = None
                result = fn(*args, **kwargs)
                if snapshot is not None:
                    found.setdefault(key, snapshot)
                return result
            return recorder

        for key, fn in functions.items():
            if key.startswith(short + ".") and key.count(".") == 1 and inspect.isfunction(fn):
                globs[key.split(".", 1)[1]] = wrap(key, fn)
        for test in doctest.DocTestFinder().find(module, globs=globs):
            test.globs = dict(globs)
            doctest.DocTestRunner(verbose=False).run(test, out=lambda s: None)


def _camera():
    from goldman_lib.camera import Camera

    return Camera((0.0, -5.0, 1.0), (0.0, 0.0, 0.0), width=16, height=12)


def _extra_examples() -> dict:
    """Valid example calls of the public functions, classes and methods that no doctest calls (a
    method's arguments start with its instance)."""
    from goldman_lib import bezier, bspline, ifs, lighting, simple_surfaces, subdivision_surfaces, surfaces, turtle, \
        vectors

    cubic = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]
    net = [[[i, j, (i * j) % 2] for j in range(3)] for i in range(3)]
    knots = [0, 0, 0, 0, 1, 2, 2, 2, 2]
    polygon = [[0, 0], [1, 2], [2, 2], [3, 0], [4, 1]]
    from goldman_lib import solid_modeling  # chapter 20
    _ball, _ball2 = simple_surfaces.Sphere([-0.5, 0, 0], 1.0), simple_surfaces.Sphere([0.5, 0, 0], 1.0)
    return {
        "bezier.BezierCurve": ((cubic,), {}),
        "bezier.CurveSampler": ((3, [0.0, 0.25, 1.0]), {}),
        # chapter 23
        "radiosity.Patches": (([[0, 0, 0], [0, 1, 1]], [[1, 0, 0], [1, 0, 0]], [[0, 1, 0], [0, -1, 0]],
                               [[0.5, 0.5, 0.5]] * 2, [[1.0, 1.0, 1.0], [0.0, 0.0, 0.0]]), {}),
        "bezier.BezierPatch": ((net,), {}),
        "bspline.BSplineCurve": ((polygon, knots, 3), {}),
        "bspline.NURBSCurve": ((polygon, [1, 2, 1, 2, 1], knots, 3), {}),
        "subdivision_matrices.check_rows_sum_to_one": ((np.array([[0.5, 0.5], [0.0, 1.0]]),), {}),
        "validation.as_float": ((1.5, "step"), {}),
        "validation.check_finite": ((np.array([1.0, 2.0]), "t"), {}),
        "subdivision_surfaces.Mesh": ((subdivision_surfaces.cube().vertices, subdivision_surfaces.cube().faces), {}),
        "ifs.IFS": ((ifs.sierpinski().maps,), {}),
        "fractals.RecursiveTurtleProgram": (([("RESIZE", 0.5), ("RECURSE", None), ("MOVE", 1), ("RECURSE", None),
                                              ("RESIZE", 2)], [("FORWARD", 1)], "Cantor"), {}),
        "turtle.Turtle": (((0, 0), (1, 0)), {}),
        "bezier.BezierCurve.evaluate": ((bezier.BezierCurve(cubic), 0.5), {}),
        "bezier.BezierCurve.derivative": ((bezier.BezierCurve(cubic), 0.5, 1), {}),
        "bezier.BezierCurve.steps": ((bezier.BezierCurve(cubic), 0.5), {}),
        "bezier.BezierPatch.derivatives": ((bezier.BezierPatch(net), 0.5, 0.5), {}),
        "bezier.BezierPatch.normal": ((bezier.BezierPatch(net), 0.5, 0.5), {}),
        "bspline.BSplineCurve.basis": ((bspline.BSplineCurve(polygon, knots, 3), 0.5), {}),
        "bspline.BSplineCurve.derivative": ((bspline.BSplineCurve(polygon, knots, 3), 0.5), {}),
        "bspline.BSplineCurve.sample": ((bspline.BSplineCurve(polygon, knots, 3), 50), {}),
        "bspline.NURBSCurve.derivative": ((bspline.NURBSCurve(polygon, [1, 2, 1, 2, 1], knots, 3), 0.5), {}),
        "subdivision_surfaces.Mesh.with_vertices": ((subdivision_surfaces.cube(), subdivision_surfaces.cube().vertices),
                                                    {}),
        "turtle.Turtle.resize": ((turtle.Turtle(), 2.0), {}),
        "turtle.Turtle.run": ((turtle.Turtle(), "FORWARD 1"), {}),
        "lighting.Light": (((1.0, 2.0, 5.0), (1.0, 0.9, 0.8), 0.7), {}),
        "lighting.Material": (((0.8, 0.2, 0.2), 0.1, 0.6, 0.3, 16.0), {}),
        "simple_surfaces.Surface": ((), {}),
        "simple_surfaces.Plane": (([0.0, 0.0, 1.0], [0.0, 1.0, 1.0]), {}),
        "simple_surfaces.Sphere": (([0.0, 0.0, 1.0], 2.0), {}),
        "simple_surfaces.Surface.contains": ((simple_surfaces.Sphere([0, 0, 0], 1), [[0, 0, 0.5], [0, 2, 0]]), {}),
        # chapter 17
        "ray_tracing.Scene": (([simple_surfaces.Sphere([0, 0, 1], 1.0)], [lighting.Light((0.0, 0.0, 5.0))], 0.3,
                               (0.1, 0.2, 0.3)), {}),
        # chapter 19
        "simple_surfaces.Polygon": (([[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0]],), {}),
        "simple_surfaces.Cylinder": (([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0, 2.0), {}),
        "simple_surfaces.EllipticCylinder": (([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [2.0, 1.0], 3.0, [1.0, 0.0, 0.0]), {}),
        "simple_surfaces.Cone": (([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 30.0, 2.0), {}),
        "simple_surfaces.EllipticCone": (([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [45.0, 30.0], 2.0, [1.0, 0.0, 0.0]), {}),
        "simple_surfaces.Ellipsoid": (([0.0, 0.0, 0.0], [3.0, 2.0, 1.0], [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]), {}),
        "simple_surfaces.Quadric": (([1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0],), {}),
        "simple_surfaces.Torus": (([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 2.0, 0.5), {}),
        "simple_surfaces.SurfaceOfRevolution": (([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, -0.25], 1.0), {}),
        "simple_surfaces.Surface.mesh": ((simple_surfaces.Torus([0, 0, 0], [0, 0, 1], 2, 0.5), 12, 2.0), {}),
        # chapter 18
        "surfaces.ImplicitSurface": ((surfaces.implicit_sphere().f, surfaces.implicit_sphere().grad, None,
                                      ((0.0, 0.0, 0.0), 2.0), 32, 2), {}),
        "surfaces.ImplicitSurface.value": ((surfaces.implicit_torus(2.0, 0.5), [[2.5, 0.0, 0.0], [0.0, 0.0, 1.0]]), {}),
        "surfaces.ImplicitSurface.curvature": ((surfaces.implicit_torus(2.0, 0.5), [[2.5, 0.0, 0.0]]), {}),
        "surfaces.ParametricSurface": ((surfaces.parametric_torus(2.0, 0.5).X, (0.0, 6.0), (0.0, 6.0), None,
                                        (True, True), 12, 4), {}),
        "surfaces.ParametricSurface.grid_mesh": ((surfaces.parametric_sphere(1.0), 8), {}),
        "surfaces.ParametricSurface.hit": ((surfaces.parametric_sphere(1.0), [[0.0, 0.0, -3.0]], [[0.0, 0.1, 1.0]]), {}),
        "surfaces.ParametricSurface.parameters": ((surfaces.parametric_sphere(1.0), [[0.0, 1.0, 0.0]]), {}),
        "surfaces.Deformation": ((surfaces.twist(30.0).forward, surfaces.twist(30.0).inverse,
                                  surfaces.twist(30.0).jacobian), {}),
        "surfaces.Deformation.undo": ((surfaces.taper(0.5), [[1.5, 0.0, 1.0]]), {}),
        "surfaces.Deformation.normals": ((surfaces.taper(0.5), [[1.0, 0.0, 0.0]], [[1.0, 0.0, 0.0]]), {}),
        "surfaces.DeformedSurface": ((surfaces.implicit_sphere(), surfaces.twist(45.0)), {}),
        # §18.3.3: an affine instance of a sphere (the doctest's Sphere argument is not recorded)
        "surfaces.AffineInstance": ((simple_surfaces.Sphere([0.0, 0.0, 0.0], 1.0), np.diag([3.0, 2.0, 1.0]),
                                     [0.0, 0.0, 1.0]), {}),
        "surfaces.AffineInstance.undo": ((surfaces.AffineInstance(simple_surfaces.Sphere([0.0, 0.0, 0.0], 1.0),
                                                                  np.diag([3.0, 2.0, 1.0])), [[3.0, 0.0, 0.0]]), {}),
        "vectors.Point": (([1.0, 2.0, 0.0],), {}),
        "vectors.Vector": (([3.0, 4.0, 0.0],), {}),
        "vectors.Vector.dot": ((vectors.Vector([1.0, 2.0, 3.0]), vectors.Vector([4.0, -5.0, 6.0])), {}),
        "vectors.Vector.cross": ((vectors.Vector([1.0, 0.0, 0.0]), vectors.Vector([0.0, 1.0, 0.0])), {}),
        # chapter 20
        "solid_modeling.BRep": ((solid_modeling.cube().vertices, solid_modeling.cube().faces), {}),
        "solid_modeling.CSG": ((_ball, _ball2), {}),
        "solid_modeling.Union": ((_ball, _ball2), {}),
        "solid_modeling.Intersection": ((_ball, _ball2), {}),
        "solid_modeling.Difference": ((_ball, _ball2), {}),
        "solid_modeling.Octree": ((_ball, (0.0, 0.0, 0.0), 2.0, 2), {}),
        "solid_modeling.Octree.boxes": ((solid_modeling.Octree.build(_ball, depth=2), ("full",)), {}),
        "solid_modeling.Octree.wireframe": ((solid_modeling.Octree.build(_ball, depth=2), ("partial",)), {}),
        # chapters 17, 21, 22
        "camera.Camera": (((0.0, -5.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 40.0, 16, 12, 0.1), {}),
        "camera.Camera.project": ((_camera(), [[0.0, 0.0, 0.0], [1.0, 0.5, 0.2]]), {}),
        "camera.Camera.rays": ((_camera(),), {}),
    }


MODULES = _modules()
FUNCTIONS: dict = {}
for _m in MODULES:
    FUNCTIONS.update(_public(_m))
FUNCTIONS.update(_methods(FUNCTIONS))
EXAMPLES = _record_examples(MODULES, FUNCTIONS)
for _key, _example in _extra_examples().items():
    if _key in FUNCTIONS:
        EXAMPLES.setdefault(_key, _example)


def _bound(key):
    """The example as ``{parameter: value}`` (defaults filled in) and the fuzzable parameters."""
    fn = FUNCTIONS[key]
    args, kwargs = EXAMPLES[key]
    sig = inspect.signature(fn)
    bound = sig.bind(*args, **kwargs)
    bound.apply_defaults()
    params = [p.name for p in sig.parameters.values()
              if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD) and p.name != "self"
              and p.name not in CONFIGURATION.get(key, ())]
    return bound, params


#: Parameters that configure a check rather than carry input: the library passes them literal
#: constants (``as_int(n, "n", minimum=0)``), so a bad value there is a programming error in the
#: library, not a learner's input; they are not fuzzed.  The helpers' value parameters are.
CONFIGURATION = {
    "validation.as_points": {"ndim", "dim", "min_count"},
    "validation.as_parameter": {"low", "high"},
    "validation.as_int": {"minimum", "maximum"},
    "validation.as_float": {"positive", "nonzero"},
    "validation.largest_within": {"cost", "limit", "start"},
    "validation.within_budget": {"cost", "what", "unit", "limit", "minimum"},
    "validation.finite_result": {"why"},
}
#: Functions and methods (by their last name) whose result may hold +-inf by contract, never NaN: a
#: ray's parameter is inf where it misses (Part III's ``hits``/``intersect``/``intervals``).
INF_BY_CONTRACT = {"hits", "hit", "intersect", "intervals", "quadratic_roots", "real_roots", "line_sphere_geometric",
                   # chapter 20: a ray's first cell and the intervals' ends are inf on a miss
                   "first_hit", "combine_intervals"}
#: Functions whose result may hold NaN or infinity by contract (what the docstring says).
NONFINITE_BY_CONTRACT = {
    "validation.as_float_array": "it converts only; finiteness is check_finite's job (its docstring)",
}


# -- the battery of bad values ---------------------------------------------------------------------
GENERIC = [("nan", math.nan), ("inf", math.inf), ("-inf", -math.inf), ("1e308", 1e308), ("-1e308", -1e308),
           ("10**12", 10 ** 12), ("1e-300", 1e-300), ("0", 0), ("-1", -1), ("[]", []), ("ragged", [[0.0, 0.0], [1.0]]),
           ("complex", 1 + 2j), ("string", "x"), ("None", None)]


def _as_array(value):
    if isinstance(value, (str, bytes)) or value is None or np.isscalar(value):
        return None
    if not isinstance(value, (np.ndarray, list, tuple)):
        return None
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return None
    return arr if arr.ndim >= 1 and arr.size > 0 else None


#: The modules of Parts II and III (chapters 9-23): their parameters also get magnitudes 1e160-1e308, where a
#: squared length or a product of two inputs overflows although the input itself is finite.
PART23 = ("vectors", "vector_geometry", "transforms", "quaternions", "mass_points", "lighting", "ray_tracing",
          "surfaces", "simple_surfaces", "shading", "radiosity", "hidden_surfaces", "solid_modeling")
HUGE = [("1e160", 1e160), ("-1e160", -1e160), ("1e200", 1e200), ("3e250", 3e250)]


def battery(value, huge: bool = False) -> list[tuple[str, object]]:
    """Bad values for a parameter whose valid value is ``value``; with ``huge`` (Parts II and III), also
    magnitudes 1e160-1e308 (scalars, and the valid array scaled by 1e160, 1e200 and 1e300)."""
    out = list(GENERIC) + (HUGE if huge else [])
    arr = _as_array(value)
    if huge and arr is not None:
        for label, k in (("scaled 1e160", 1e160), ("scaled 1e200", 1e200), ("scaled 1e300", 1e300)):
            out.append((label, arr * k))
    if arr is not None:
        nan_inside = arr.copy()
        nan_inside.flat[-1] = math.nan
        out.append(("nan inside", nan_inside))
        out.append(("all equal", np.repeat(arr[:1], arr.shape[0], axis=0)))
        out.append(("one item", arr[:1].copy()))
        out.append(("huge entries", arr * 1e300 + np.sign(arr) * 1e300))
        if arr.ndim >= 2:
            out.append(("flattened", arr.reshape(-1)))
            if arr.shape[-1] > 1:
                out.append(("dropped coordinate", arr[..., :-1].copy()))
        else:
            out.append(("extra axis", arr[:, None].copy()))
        out.append(("extra coordinate", np.concatenate([arr[..., None], arr[..., None]], axis=-1)))
        out.append(("complex entries", arr + 1j))
    vertices = getattr(value, "vertices", None)
    if hasattr(value, "with_vertices") and isinstance(vertices, np.ndarray):
        try:
            out.append(("all-equal vertices", value.with_vertices(np.zeros_like(vertices))))
        except (TypeError, ValueError):
            pass
    return out


# -- what counts as a clear answer --------------------------------------------------------------------
def _nonfinite(result, depth=0, seen=None, allow_inf=False) -> str | None:
    """Where ``result`` holds a NaN or an infinity (only a NaN if ``allow_inf``), or None."""
    seen = set() if seen is None else seen
    if depth > 4 or id(result) in seen:
        return None
    if isinstance(result, (bool, str, bytes, int)) or result is None:
        return None
    bad = np.isnan if allow_inf else (lambda x: ~np.isfinite(x))
    if isinstance(result, (float, complex, np.number)):
        return repr(result) if bad(result) else None
    if isinstance(result, np.ndarray):
        if result.dtype.kind in "fc" and np.any(bad(result)):
            return f"array of shape {result.shape} with {'NaN' if allow_inf else 'non-finite'} entries"
        if result.dtype.kind == "O":
            return _nonfinite(list(result.flat[:1000]), depth + 1, seen, allow_inf)
        return None
    seen.add(id(result))
    if isinstance(result, dict):
        items = list(result.values())
    elif isinstance(result, (list, tuple, set, frozenset)):
        items = list(result)[:10000]
    elif inspect.isroutine(result) or inspect.ismodule(result) or inspect.isclass(result):
        return None
    elif hasattr(result, "__dict__") and type(result).__module__.startswith("goldman_lib"):
        items = list(vars(result).values())
    else:
        return None
    for item in items:
        where = _nonfinite(item, depth + 1, seen, allow_inf)
        if where:
            return where
    return None


def _names(message: str, param: str) -> bool:
    return re.search(rf"(?<![A-Za-z0-9_]){re.escape(param)}(?![A-Za-z0-9_])", message) is not None


def judge(call, param: str | None, alias: str | None = None, finite: bool = True):
    """Run ``call()``; return ``"ok"`` or what was wrong.  The message must name ``param`` (or
    ``alias``: the validation helpers name the caller's parameter, which they are given as
    ``name``).  ``finite``: whether a returned NaN or infinity is a failure (True), only a NaN
    ("inf allowed"), or nothing (False)."""
    try:
        result = call()
    except (ValueError, TypeError) as exc:
        if isinstance(exc, ValueError) and type(exc).__module__.startswith("goldman_lib"):
            return "ok"
        if param is None or _names(str(exc), param) or (alias and _names(str(exc), alias)):
            return "ok"
        return f"message does not name {param!r}: {type(exc).__name__}: {str(exc)[:200]}"
    except BaseException as exc:  # noqa: BLE001 - any other exception is the finding
        return f"raised {type(exc).__name__}: {str(exc)[:200]}"
    where = _nonfinite(result, allow_inf=finite == "inf allowed") if finite else None
    return "ok" if where is None else f"returned a non-finite result ({where})"


# -- the tasks ------------------------------------------------------------------------------------------
def _call_with(key, param, value):
    bound, _ = _bound(key)
    arguments = copy.deepcopy(dict(bound.arguments))
    fn = FUNCTIONS[key]
    sig = inspect.signature(fn)
    try:      # a fresh copy per call: a function that fills a list it is given (ray_tracing.trace's
        value = copy.deepcopy(value)     # ``record``) must not change the battery's shared ``[]``
    except Exception:  # noqa: BLE001 - a value that cannot be copied is passed as it is
        pass
    arguments[param] = value
    args, kwargs = [], {}
    for p in sig.parameters.values():
        if p.name not in arguments:
            continue
        if p.kind == p.VAR_POSITIONAL:
            args.extend(arguments[p.name])
        elif p.kind == p.VAR_KEYWORD:
            kwargs.update(arguments[p.name])
        elif p.kind == p.KEYWORD_ONLY:
            kwargs[p.name] = arguments[p.name]
        else:
            args.append(arguments[p.name])
    return fn(*args, **kwargs)


def _call_with_built(key, param, build, baseline):
    """``_call_with`` with the value of ``param`` built in the worker (a constructor given a huge input
    may itself refuse it, with a message the judge reads).  The call must be valid with the object
    built from its constructor's example unchanged (``baseline``): a method example recorded on
    another instance (a 32-pixel camera) may not fit the constructor's example (a 16-pixel one)."""
    try:
        _call_with(key, param, baseline())
    except Exception:  # noqa: BLE001 - the example does not fit this object: nothing to judge
        return None
    return _call_with(key, param, build())


def _huge_array_values(value) -> list[tuple[str, object]]:
    arr = _as_array(value)
    if isinstance(value, (bool, int, float)) and not isinstance(value, bool):
        return [(label, v if float(value) >= 0 else -v) for label, v in HUGE if label[0] != "-"]
    if arr is None:
        return []
    return [(label, arr * k) for label, k in (("scaled 1e160", 1e160), ("scaled 1e200", 1e200), ("scaled 1e300", 1e300))]


def _class_key(obj) -> str | None:
    cls = type(obj)
    if not cls.__module__.startswith("goldman_lib."):
        return None
    key = f"{cls.__module__[len('goldman_lib.'):]}.{cls.__name__}"
    return key if key in FUNCTIONS and key in EXAMPLES else None


def _baseline(obj):
    """A builder of ``obj``'s class from its constructor's example."""
    cls = FUNCTIONS[_class_key(obj)]
    args, kwargs = EXAMPLES[_class_key(obj)]
    return lambda: cls(*copy.deepcopy(args), **copy.deepcopy(kwargs))


def huge_objects(obj, depth: int = 0) -> list[tuple[str, str, object]]:
    """Objects of ``obj``'s class built, by its constructor's example, with one input at magnitudes
    1e160-1e308 (and, one level down, with such an object among its inputs: a scene whose light is
    huge): ``[(label, parameter to blame, builder)]``.  A method of an object, or a function given one
    (``trace(scene, ...)``), must refuse what the object cannot represent, or compute it right."""
    key = _class_key(obj) if depth <= 1 else None
    if key is None:
        return []
    cls = FUNCTIONS[key]
    args, kwargs = EXAMPLES[key]
    bound = inspect.signature(cls).bind(*copy.deepcopy(args), **copy.deepcopy(kwargs))
    short = key.split(".", 1)[1]
    out = []

    def builder(p, value):
        def build():
            arguments = dict(bound.arguments)
            arguments[p] = value() if callable(value) and not inspect.isclass(value) and p != "f" else value
            return cls(**arguments)
        return build

    for p, value in bound.arguments.items():
        for label, bad in _huge_array_values(value):
            out.append((f"{short}({p}={label})", p, builder(p, bad)))
        inner = value if _class_key(value) else None
        items = value if isinstance(value, (list, tuple)) and value and _class_key(value[0]) else None
        for label, blame, build in (huge_objects(inner, depth + 1) if inner is not None else []):
            out.append((f"{short}({p}={label})", blame, builder(p, build)))
        for label, blame, build in (huge_objects(items[0], depth + 1) if items is not None else []):
            out.append((f"{short}({p}=[{label}, ...])", blame,
                        builder(p, lambda build=build, rest=list(items[1:]): [build(), *rest])))
    return out


def _probe_cases():
    """The issue's adversarial probe, kept: ``(label, call, parameter the message must name)``."""
    from goldman_lib import (bezier, blossom, bspline, codo, fractals, ifs, knot_insertion, lighting, quaternions,
                             ray_tracing, simple_surfaces, subdivision_matrices, subdivision_surfaces, transforms,
                             turtle)
    C = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]
    polygon = [[0, 0], [1, 2], [2, 2], [3, 0], [4, 1]]
    knots = [0, 0, 0, 0, 1, 2, 2, 2, 2]
    return [
        ("subdivision_surfaces.centroid_averaging(cube(), 12)",
         lambda: subdivision_surfaces.centroid_averaging(subdivision_surfaces.cube(), 12), "levels"),
        ("subdivision_surfaces.split_and_average(C, 3, 40)",
         lambda: subdivision_surfaces.split_and_average(C, 3, 40), "levels"),
        ("subdivision_matrices.bezier_subdivision_matrices(1000)",
         lambda: subdivision_matrices.bezier_subdivision_matrices(1000), "n"),
        ("subdivision_matrices.bezier_subdivision_matrices(10**12)",
         lambda: subdivision_matrices.bezier_subdivision_matrices(10 ** 12), "n"),
        ("bezier.elevate_degree(C, 10**5)", lambda: bezier.elevate_degree(C, 10 ** 5), "times"),
        ("bezier.elevate_degree(C, 10**12)", lambda: bezier.elevate_degree(C, 10 ** 12), "times"),
        ("bezier.bernstein(10**6, 0.5)", lambda: bezier.bernstein(10 ** 6, 0.5), "n"),
        ("bezier.bernstein(10**12, 0.5)", lambda: bezier.bernstein(10 ** 12, 0.5), "n"),
        ("bezier.de_casteljau(C, 1e150)", lambda: bezier.de_casteljau(C, 1e150), "t"),
        ("bezier.bernstein_evaluate(C, 1e150)", lambda: bezier.bernstein_evaluate(C, 1e150), "t"),
        ("bezier.derivative(C, 1e150)", lambda: bezier.derivative(C, 1e150), "t"),
        ("blossom.blossom(C, [1e150, 1e150, 1e150])", lambda: blossom.blossom(C, [1e150] * 3), "args"),
        ("subdivision_matrices.normal_curve(3, 1e150)", lambda: subdivision_matrices.normal_curve(3, 1e150), "t"),
        ("bezier.render_by_subdivision(C, tol=nan)",
         lambda: bezier.render_by_subdivision(C, tol=math.nan), "tol"),
        ("knot_insertion.midpoint_knots([])", lambda: knot_insertion.midpoint_knots([]), "knots"),
        ("knot_insertion.lane_riesenfeld(C, 3, 10**12)",
         lambda: knot_insertion.lane_riesenfeld(C, 3, 10 ** 12), "levels"),
        ("knot_insertion.schaefer(polygon, knots, 3, 40)",
         lambda: knot_insertion.schaefer(polygon, knots, 3, 40), "levels"),
        ("bspline.de_boor(polygon, knots, 3, 1e300)", lambda: bspline.de_boor(polygon, knots, 3, 1e300), "u"),
        # Part I (the issue's probe of turtle, fractals, codo and ifs)
        ("fractals.koch_curve(10**6)", lambda: fractals.koch_curve(10 ** 6), "level"),
        ("ifs.deterministic(ifs.sierpinski(), 10**12)",
         lambda: ifs.deterministic(ifs.sierpinski(), 10 ** 12), "levels"),
        ("codo.run('REPEAT 20000 [ REPEAT 20000 [ ] ]')",
         lambda: codo.run("REPEAT 20000 [ REPEAT 20000 [ ] ]"), None),
        ("turtle.circle(1e308)", lambda: turtle.circle(1e308), "radius"),
        # issue 20 section 4: overflow in Parts II-III (their values are checked in test_bad_input_part23.py)
        ("transforms.compose(*[scaling(2.0)] * 2000)",
         lambda: transforms.compose(*[transforms.scaling(2.0)] * 2000), "matrices"),
        ("simple_surfaces.Sphere((0, 0, 0), 1e160).intersect(...)",
         lambda: simple_surfaces.Sphere((0, 0, 0), 1e160).intersect([[0, 0, -5]], [[0, 0, 1]]), "radius"),
        ("bspline.de_boor(knots at ±1e308)",
         lambda: bspline.de_boor(polygon[:4], [-1e308] * 4 + [1e308] * 4, 3, 0.0), "knots"),
        ("ray_tracing.trace(light intensity 1e300 x diffuse 1e300)",
         lambda: ray_tracing.trace(ray_tracing.Scene(
             [simple_surfaces.Sphere([0, 0, 0], 1, material=lighting.Material(diffuse=1e300))],
             [lighting.Light((0, 0, 5), intensity=1e300)]), [[0, 0, 5]], [[0, 0, -1]]), "intensity"),
        ("quaternions.rotate([0, 0, 0, 1e160], [1, 0, 0])",
         lambda: quaternions.rotate([0, 0, 0, 1e160], [1, 0, 0]), "q"),
    ] + _part3_probes()


def _part3_probes():
    """Issue 20, sections 2-3: many polygons, lights, patches and intervals, deep CSG trees,
    singular radiosity systems and geometry behind the eye (``param`` None: an answer, not a refusal,
    is expected)."""
    from goldman_lib import hidden_surfaces as hs, lighting, radiosity as rd, ray_tracing as rt
    from goldman_lib.camera import Camera
    from goldman_lib import simple_surfaces as ss, solid_modeling as sm

    big = Camera((0, -7, 0.6), (0, 0, 0.1), (0, 0, 1), 36, 1000, 1000)
    filling = [[[-50, k * 0.01, -50], [50, k * 0.01, -50], [50, k * 0.01, 50], [-50, k * 0.01, 50]] for k in range(200)]
    square = [[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]]
    floor = [[-3, -20, -1], [3, -20, -1], [3, 5, -1], [-3, 5, -1]]
    too_near = [[-0.1, -6.95, 0.5], [0.1, -6.95, 0.5], [0, -6.95, 0.7]]
    closed = (np.ones((50, 50)) - np.eye(50)) / 49
    many = np.stack([np.arange(3e6), np.arange(3e6) + 0.5], 1)

    def nested(count):
        solid = ss.Sphere((0, 0, 0), 1)
        for k in range(count):
            solid = sm.Union(solid, ss.Sphere((k * 0.01, 0, 0), 1))
        return solid

    probes = [(f"hidden_surfaces.{f.__name__}(200 screen-filling polygons, 1000x1000)",
               functools.partial(f, filling, big), "polygons") for f, _ in hs.ALGORITHMS.values()]
    probes += [(f"hidden_surfaces.{f.__name__}(a floor behind the eye, a triangle nearer than near)",
                functools.partial(f, [floor, too_near], hs.default_camera(40, 30)), None)
               for f, _ in hs.ALGORITHMS.values()]
    return probes + [
        ("hidden_surfaces.depth_sort(2000 coincident squares)",
         lambda: hs.depth_sort([square] * 2000, hs.default_camera(40, 30)), "polygons"),
        ("radiosity.jacobi(closed white box, rho = 1)", lambda: rd.jacobi([[0, 1.0], [1.0, 0]], [1, 1], [1, 1]), "rho"),
        ("radiosity.gauss_seidel(closed 50-patch box, rho = 1)",
         lambda: rd.gauss_seidel(closed, np.ones(50), np.ones(50)), "rho"),
        ("radiosity.progressive_refinement(closed 50-patch box, rho = 1)",
         lambda: rd.progressive_refinement(closed, np.ones(50), np.ones(50), np.ones(50)), "rho"),
        ("radiosity.jacobi(rho = 1 - 1e-7: hopelessly slow)",
         lambda: rd.jacobi([[0, 1.0], [1.0, 0]], [1, 0.9999999], [1, 1]), "rho"),
        ("radiosity.cornell_box(50)", lambda: rd.cornell_box(50), "n"),
        ("radiosity.hemicube_form_factors(cornell_box(), resolution=400)",
         lambda: rd.hemicube_form_factors(rd.cornell_box(), resolution=400), "resolution"),
        ("ray_tracing.render(3000 lights)",
         lambda: rt.render(rt.default_scene(lights=[lighting.Light((0, 0, 5 + k * 1e-3)) for k in range(3000)]),
                           rt.default_camera()), "scene"),
        ("solid_modeling.combine_intervals(3M intervals each)", lambda: sm.combine_intervals(many, many, "union"),
         "first"),
        ("solid_modeling.Union nested 1000 deep", lambda: nested(1000), "a"),
    ]


PROBES = _probe_cases()


def _tasks() -> list[tuple[str, str, object]]:
    """``(module, label, call, param, alias, finite)`` for every public function, parameter and bad value."""
    tasks = []
    for key in sorted(EXAMPLES):
        if key not in FUNCTIONS:
            continue
        bound, params = _bound(key)
        alias = bound.arguments.get("name")
        alias = alias if isinstance(alias, str) and alias else None
        finite = key not in NONFINITE_BY_CONTRACT and ("inf allowed" if key.rsplit(".", 1)[-1] in INF_BY_CONTRACT
                                                        else True)
        for param in params:
            for label, value in battery(bound.arguments.get(param), huge=key.split(".")[0] in PART23):
                call = functools.partial(_call_with, key, param, value)
                tasks.append((key.split(".")[0], f"{key}({param}={label})", call, param,
                              alias if param != "name" else None, finite))
        if key.split(".")[0] in PART23:     # objects (an instance, a scene, a light) holding a huge input
            objects = [(p, bound.arguments.get(p)) for p in ["self", *params] if p in bound.arguments]
            for param, value in objects:
                for label, blame, build in huge_objects(value):
                    call = functools.partial(_call_with_built, key, param, build, _baseline(value))
                    tasks.append((key.split(".")[0], f"{key}({param}={label})", call, blame, param, finite))
    for label, call, param in PROBES:
        tasks.append(("probe", label, call, param, None, True))
    return tasks


TASKS = _tasks()


# -- the worker pool ------------------------------------------------------------------------------------
def _worker(conn, memory_limit):
    import warnings

    warnings.simplefilter("ignore")
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    limit = memory_limit if hard == resource.RLIM_INFINITY else min(memory_limit, hard)
    resource.setrlimit(resource.RLIMIT_AS, (limit, hard))
    devnull = open(os.devnull, "w")
    sys.stdout = devnull
    while True:
        index = conn.recv()
        if index is None:
            return
        _, _, call, param, alias, finite = TASKS[index]
        cpu, wall = time.process_time(), time.perf_counter()
        outcome = judge(call, param, alias, finite)
        conn.send((index, outcome, time.process_time() - cpu, time.perf_counter() - wall))


def _vm_size() -> int:
    try:
        with open("/proc/self/status") as fh:
            for line in fh:
                if line.startswith("VmSize:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return 0


def run_tasks(indices, time_limit=TIME_LIMIT, workers=WORKERS, cpu_limit=None) -> dict[int, str]:
    """Run ``TASKS[i]`` for ``i`` in ``indices`` in worker subprocesses; ``{i: outcome}``.

    A call is stopped after ``time_limit`` seconds of wall-clock time.  With ``cpu_limit``, a call
    that finished must also have taken at most ``cpu_limit`` seconds of CPU time or of wall-clock
    time (CPU time is what a loaded machine does not stretch; wall-clock time counts the work of
    a multithreaded BLAS call once)."""
    ctx = multiprocessing.get_context("fork")
    memory_limit = _vm_size() + MEMORY_LIMIT
    pending = list(indices)[::-1]
    outcomes: dict[int, str] = {}
    slots = []  # [process, conn, index or None, deadline]

    def spawn():
        parent, child = ctx.Pipe()
        proc = ctx.Process(target=_worker, args=(child, memory_limit), daemon=True)
        proc.start()
        child.close()
        return [proc, parent, None, None]

    def assign(slot):
        if pending:
            slot[2] = pending.pop()
            slot[3] = time.monotonic() + time_limit
            slot[1].send(slot[2])

    for _ in range(min(workers, len(pending))):
        slot = spawn()
        slots.append(slot)
        assign(slot)
    while any(s[2] is not None for s in slots):
        busy = [s for s in slots if s[2] is not None]
        timeout = max(0.0, min(s[3] for s in busy) - time.monotonic())
        ready = wait([s[1] for s in busy], timeout=timeout)
        for slot in busy:
            if slot[1] in ready:
                try:
                    index, outcome, cpu, wall = slot[1].recv()
                    if cpu_limit is not None and min(cpu, wall) > cpu_limit:
                        outcome = f"took {cpu:.1f} s of CPU time ({wall:.1f} s) over {cpu_limit:g} s"
                except (EOFError, OSError):
                    index, outcome = slot[2], "the worker died (out of memory or a crash)"
                    slot[0].join(1)
                    slot[:] = spawn()
                outcomes[index] = outcome
                slot[2] = None
                assign(slot)
            elif time.monotonic() > slot[3]:
                outcomes[slot[2]] = f"took longer than {time_limit:g} s"
                slot[0].kill()
                slot[0].join(1)
                slot[1].close()
                slot[:] = spawn()
                assign(slot)
    for slot in slots:
        try:
            slot[1].send(None)
        except OSError:
            pass
        slot[0].join(1)
        if slot[0].is_alive():
            slot[0].kill()
    return outcomes


@functools.lru_cache(maxsize=None)
def fuzz_results():
    """Every task once.  Timeouts are retried once, alone, judged by the call's CPU time and given
    ten times the wall-clock time: `make test` runs this beside other tests (two pytest-xdist
    workers and the browser tests), and a loaded machine stretches a 0.2 s call past a second."""
    start = time.monotonic()
    outcomes = run_tasks(range(len(TASKS)))
    slow = [i for i, o in outcomes.items() if o.startswith("took longer")]
    if slow:
        outcomes.update(run_tasks(slow, time_limit=10 * TIME_LIMIT, workers=1 if len(slow) < 20 else WORKERS,
                                  cpu_limit=TIME_LIMIT))
    return outcomes, time.monotonic() - start


def _failures(group: str) -> list[str]:
    outcomes, _ = fuzz_results()
    return [f"{TASKS[i][1]}: {o}" for i, o in sorted(outcomes.items()) if TASKS[i][0] == group and o != "ok"]


# -- the tests ------------------------------------------------------------------------------------------
def test_every_public_function_has_a_valid_example():
    """A public function without an example call is not fuzzed: add a doctest or an _extra_examples row."""
    missing = sorted(set(FUNCTIONS) - set(EXAMPLES))
    assert not missing, f"public functions without a valid example call: {missing}"
    broken = []
    for key in sorted(FUNCTIONS):
        try:
            _bound(key)
        except TypeError as exc:
            broken.append(f"{key}: {exc}")
    assert not broken, broken


def test_discovery_finds_every_part():
    groups = {key.split(".")[0] for key in FUNCTIONS}
    assert {"bezier", "bspline", "knot_insertion", "subdivision_surfaces", "turtle", "fractals", "ifs"} <= groups
    assert len(FUNCTIONS) > 200


@pytest.mark.parametrize("group", sorted({t[0] for t in TASKS} - {"probe"}))
def test_fuzz(group):
    """Bad values for each parameter of the module's public functions: finite result or a clear error."""
    failures = _failures(group)
    assert not failures, f"{len(failures)} unclear answers:\n" + "\n".join(failures)


def test_issue_probes():
    """The issue's adversarial probe: bounded work and a message naming the parameter."""
    failures = _failures("probe")
    assert not failures, "\n".join(failures)


def test_summary(capsys):
    outcomes, seconds = fuzz_results()
    fuzzed = {TASKS[i][1].split("(")[0] for i in outcomes if TASKS[i][0] != "probe"}
    with capsys.disabled():
        print(f"\nfuzz: {len(FUNCTIONS)} public functions ({len(fuzzed)} with parameters), {len(outcomes)} calls "
              f"({len(PROBES)} probes), {seconds:.1f} s; records left out: {_skipped_records(MODULES)}")
    assert len(outcomes) == len(TASKS)

"""Checks on the arguments of the public functions, with messages that name the parameter and
the rule it breaks.

Every public function of ``goldman_lib`` validates at its boundary through these helpers, so a
learner who passes the wrong thing reads, for instance, ``t must be finite; t[3] is nan`` rather
than a NaN in a plot or a broadcasting error from deep inside numpy.

>>> as_points([[0, 0], [1, 2]], "ctrl").shape
(2, 2)
>>> as_points([[0, 0], [1, float("nan")]], "ctrl")
Traceback (most recent call last):
...
ValueError: ctrl must be finite; ctrl[1, 1] is nan
"""

from __future__ import annotations

import numbers

import numpy as np

__all__ = ["as_points", "as_parameter", "as_int", "as_float", "as_float_array", "check_finite", "within_budget",
           "largest_within", "MAX_ITEMS", "MAX_ITERATIONS", "as_tolerance", "finite_result",
           "MAX_SQUARABLE", "as_colour"]
# Public inside the package, for the library's modules (not learner-facing, so not in __all__):
# moderate, overflow_culprit, as_hyperplane -- checks on arrays a public function already validated.

#: The most points, segments, triangles or matrix entries one call may produce or allocate: about
#: 160 MB of float64 pairs, a second or two of numpy work on a 2-core machine.  Every level, count,
#: degree and size parameter is bounded through :func:`within_budget` so that its result stays under it.
MAX_ITEMS = 10_000_000
#: The most iterations (or interpreted steps) one call may run.
MAX_ITERATIONS = 1_000_000


def _index(arr, flat):
    idx = np.unravel_index(flat, arr.shape)
    return ", ".join(str(int(i)) for i in idx)


def check_finite(arr: np.ndarray, name: str) -> np.ndarray:
    """Raise ``ValueError`` naming the first non-finite entry of ``arr``; return ``arr``.

    >>> check_finite(np.array([1.0, np.inf]), "t")
    Traceback (most recent call last):
    ...
    ValueError: t must be finite; t[1] is inf
    """
    if not isinstance(arr, np.ndarray) or arr.dtype.kind not in "fiub":
        arr = as_float_array(arr, name)
    bad = ~np.isfinite(arr)
    if bad.any():
        flat = int(np.flatnonzero(bad)[0])
        if arr.ndim == 0:
            raise ValueError(f"{name} must be finite; {name} is {arr.item()}")
        raise ValueError(f"{name} must be finite; {name}[{_index(arr, flat)}] is {arr.flat[flat]}")
    return arr


def as_float_array(x, name: str) -> np.ndarray:
    """``x`` as a float array, or TypeError naming ``name`` if it is not numeric (finiteness is
    :func:`check_finite`'s job).

    >>> as_float_array([1, 2], "knots")
    array([1., 2.])
    >>> as_float_array([1 + 2j], "t")
    Traceback (most recent call last):
    ...
    TypeError: t must be real; complex numbers are not points or parameters here
    """
    if isinstance(x, (str, bytes)) or x is None:
        raise TypeError(f"{name} must be numeric, not {type(x).__name__}")
    if isinstance(x, (complex, np.complexfloating)) or (isinstance(x, np.ndarray) and np.iscomplexobj(x)):
        raise TypeError(f"{name} must be real; complex numbers are not points or parameters here")
    if isinstance(x, (list, tuple)):
        try:
            probe = np.asarray(x)
        except (TypeError, ValueError):
            probe = None
        if probe is not None and np.iscomplexobj(probe):
            raise TypeError(f"{name} must be real; complex numbers are not points or parameters here")
    try:
        arr = np.asarray(x, dtype=float)
    except OverflowError:
        raise ValueError(f"{name} must hold numbers a float can represent (|x| < 1.8e308); an integer is too large") from None
    except (TypeError, ValueError) as exc:
        raise TypeError(f"{name} must be a numeric array-like; got {type(x).__name__} ({exc})") from None
    return arr


def as_points(x, name: str, *, ndim: int | None = 2, dim: int | tuple[int, ...] | None = None,
              min_count: int = 1) -> np.ndarray:
    """Return ``x`` as a finite float array of points with coordinates in the last axis.

    ndim: the required number of axes (2 for a polygon ``(n, d)``, 3 for a patch net
    ``(m, n, d)``), or None for any number >= 1.  dim: the allowed point dimension(s).
    min_count: the least number of points along each leading axis.

    >>> as_points([[0, 0, 0]], "ctrl", dim=2)
    Traceback (most recent call last):
    ...
    ValueError: ctrl must hold 2-dimensional points (last axis of length 2); got shape (1, 3)
    """
    arr = as_float_array(x, name)
    if ndim is not None and arr.ndim != ndim:
        shape = {1: "(d,)", 2: "(n, d)", 3: "(m, n, d)"}.get(ndim, f"{ndim} axes")
        raise ValueError(f"{name} must have shape {shape} with coordinates in the last axis; got shape {arr.shape}")
    if arr.ndim == 0:
        raise ValueError(f"{name} must be an array of points, not a scalar")
    if dim is not None:
        dims = (dim,) if isinstance(dim, int) else tuple(dim)
        if arr.shape[-1] not in dims:
            want = " or ".join(str(d) for d in dims)
            raise ValueError(f"{name} must hold {want}-dimensional points (last axis of length {want}); got shape {arr.shape}")
    elif arr.shape[-1] < 1:
        raise ValueError(f"{name} must hold points with at least one coordinate; got shape {arr.shape}")
    for axis, count in enumerate(arr.shape[:-1]):
        if count < min_count:
            raise ValueError(f"{name} must hold at least {min_count} point(s) along axis {axis}; got shape {arr.shape}")
    return check_finite(arr, name)


def as_parameter(t, name: str = "t", *, low: float | None = None, high: float | None = None) -> np.ndarray:
    """Return a parameter (scalar or array) as a finite float array, optionally inside [low, high].

    >>> as_parameter([0.0, 0.5], "t").tolist()
    [0.0, 0.5]
    >>> as_parameter(2.0, "t", low=0.0, high=1.0)
    Traceback (most recent call last):
    ...
    ValueError: t must lie in [0.0, 1.0]; t is 2.0
    """
    arr = check_finite(as_float_array(t, name), name)
    for bound, bad in ((low, arr < low if low is not None else None), (high, arr > high if high is not None else None)):
        if bad is not None and bad.any():
            flat = int(np.flatnonzero(bad)[0])
            where = name if arr.ndim == 0 else f"{name}[{_index(arr, flat)}]"
            raise ValueError(f"{name} must lie in [{low}, {high}]; {where} is {arr.flat[flat]}")
    return arr


def as_int(x, name: str, *, minimum: int | None = None, maximum: int | None = None) -> int:
    """Return ``x`` as an ``int``; bools and non-integral floats are a ``TypeError``.

    >>> as_int(3, "n", minimum=0)
    3
    >>> as_int(2.5, "n")
    Traceback (most recent call last):
    ...
    TypeError: n must be an integer; got 2.5
    >>> as_int(-1, "order", minimum=0)
    Traceback (most recent call last):
    ...
    ValueError: order must be >= 0; got -1
    """
    if isinstance(x, bool) or not isinstance(x, numbers.Integral):
        if isinstance(x, numbers.Real) and not isinstance(x, bool) and float(x).is_integer():
            x = int(x)
        else:
            raise TypeError(f"{name} must be an integer; got {x!r}")
    x = int(x)
    if minimum is not None and x < minimum:
        raise ValueError(f"{name} must be >= {minimum}; got {x}")
    if maximum is not None and x > maximum:
        raise ValueError(f"{name} must be <= {maximum}; got {x}")
    return x


def as_float(x, name: str, *, positive: bool = False, nonzero: bool = False) -> float:
    """Return ``x`` as a finite ``float``.

    >>> as_float("1", "step")
    Traceback (most recent call last):
    ...
    TypeError: step must be a real number; got '1'
    >>> as_float(0, "factor", nonzero=True)
    Traceback (most recent call last):
    ...
    ValueError: factor must be nonzero; got 0.0
    """
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        text = repr(x)
        raise TypeError(f"{name} must be a real number; got {text if len(text) <= 60 else text[:57] + '...'}")
    try:
        x = float(x)
    except OverflowError:
        raise ValueError(f"{name} must be finite; got an integer too large for a float") from None
    if not np.isfinite(x):
        raise ValueError(f"{name} must be finite; got {x}")
    if positive and x <= 0:
        raise ValueError(f"{name} must be positive; got {x}")
    if nonzero and x == 0:
        raise ValueError(f"{name} must be nonzero; got {x}")
    return x


def largest_within(cost, limit: int, start: int = 0) -> int:
    """The largest integer ``v >= start`` with ``cost(v) <= limit``, for a non-decreasing ``cost``
    (``start - 1`` if even ``cost(start)`` is over).  Evaluates ``cost`` only at small arguments
    (doubling, then bisection), so an exponential cost is never computed at a huge input.

    >>> largest_within(lambda level: 4 ** level, 10_000_000)
    11
    """
    if cost(start) > limit:
        return start - 1
    lo, step = start, 1
    while cost(lo + step) <= limit:
        lo, step = lo + step, step * 2
        if step > 2 ** 62:
            return lo
    hi = lo + step  # cost(lo) <= limit < cost(hi)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (mid, hi) if cost(mid) <= limit else (lo, mid)
    return lo


def within_budget(value, name: str, *, cost, what: str, unit: str = "points", limit: int = MAX_ITEMS,
                  minimum: int = 0) -> int:
    """Check a size parameter (a level, count, degree, number of iterations) against the work its
    result would cost, before any work starts: the one work-budget rule of the library.

    value: the learner's integer.  cost(v) -> the number of ``unit`` the result has at ``v`` (exact,
    Python ints; non-decreasing in ``v``).  what: the result in words, for the message.  limit: the
    budget (:data:`MAX_ITEMS` points by default, :data:`MAX_ITERATIONS` for iteration counts).
    Returns ``value`` as an ``int``.  Raises ``TypeError`` for a non-integer and ``ValueError`` naming
    the parameter, the largest allowed value and why.

    >>> within_budget(5, "level", cost=lambda n: 4 ** n + 1, what="the Koch curve", unit="points")
    5
    >>> within_budget(10**6, "level", cost=lambda n: 4 ** n + 1, what="the Koch curve", unit="points")
    Traceback (most recent call last):
    ...
    ValueError: level must be <= 11: the Koch curve at level 12 has 16,777,217 points, over the limit of 10,000,000
    """
    value = as_int(value, name, minimum=minimum)
    if value <= minimum:
        return value
    largest = largest_within(cost, limit, start=minimum)
    if value > largest:
        over = largest + 1
        raise ValueError(f"{name} must be <= {largest}: {what} at {name} {over} has {cost(over):,} {unit}, "
                         f"over the limit of {limit:,}")
    return value


def as_tolerance(tol, name: str = "tol") -> float:
    """A tolerance: a finite, positive real number (NaN would make every comparison False).

    >>> as_tolerance(1e-9)
    1e-09
    >>> as_tolerance(float("nan"))
    Traceback (most recent call last):
    ...
    ValueError: tol must be finite; got nan
    """
    return as_float(tol, name, positive=True)


def finite_result(result, name: str, value=None, *, why: str = "is too large in magnitude") -> np.ndarray:
    """``result`` if every entry is finite; otherwise a ``ValueError`` saying which input made the
    result overflow float64 (a parameter far outside its domain, a huge ratio), so that no NaN or
    infinity leaves the library silently.

    name: the parameter to blame.  value: its value (a scalar, or an array whose shape leads the
    result's shape, so the first offending entry can be named).

    >>> finite_result(np.array([1.0, 2.0]), "t", 0.5)
    array([1., 2.])
    >>> finite_result(np.array([np.inf, np.nan]), "t", 1e150)
    Traceback (most recent call last):
    ...
    ValueError: t is too large in magnitude: the result overflows float64 at t = 1e+150
    """
    arr = result if isinstance(result, np.ndarray) else as_float_array(result, name)
    if arr.dtype.kind not in "fc" or np.all(np.isfinite(arr)):
        return result
    where = ""
    if value is not None:
        val = np.asarray(value)
        if val.ndim == 0:
            where = f" at {name} = {val.item():g}" if val.dtype.kind in "fiu" else ""
        elif arr.ndim >= val.ndim and arr.shape[:val.ndim] == val.shape:
            flat = int(np.flatnonzero(~np.isfinite(arr))[0])
            idx = np.unravel_index(flat, arr.shape)[:val.ndim]
            where = f" at {name}[{', '.join(str(int(i)) for i in idx)}] = {val[idx]:g}"
    raise ValueError(f"{name} {why}: the result overflows float64{where}")


#: Coordinates of at most this magnitude keep squared distances (flatness, boxes, Newton steps of
#: the Bezier chapters 24-25) inside float64.
MAX_SQUARABLE = 1e150


def moderate(P: np.ndarray, name: str = "ctrl") -> np.ndarray:
    """``P`` if its coordinates are at most :data:`MAX_SQUARABLE` in magnitude (the algorithms that
    square distances need it), else a ValueError naming ``name``.  For library modules, on an array
    already validated (not in ``__all__``).

    >>> moderate(np.array([1.0, -2.0])).tolist()
    [1.0, -2.0]

    >>> moderate(np.array([1e200]), "a")
    Traceback (most recent call last):
    ...
    ValueError: a is too large in magnitude: coordinates must stay within 1e+150 so that squared distances fit in float64; got 1e+200
    """
    big = float(np.abs(P).max()) if P.size else 0.0
    if big > MAX_SQUARABLE:
        raise ValueError(f"{name} is too large in magnitude: coordinates must stay within {MAX_SQUARABLE:g} so "
                         f"that squared distances fit in float64; got {big:g}")
    return P


def overflow_culprit(t, ctrl: str = "ctrl") -> tuple:
    """Who made a curve point overflow, as the ``(name, value)`` arguments of :func:`finite_result`:
    the parameter if it lies outside [-1, 1] (extrapolating multiplies by powers of t), else the
    control points.  For library modules, on a validated t (not in ``__all__``).

    >>> overflow_culprit(np.array(2.0))[0], overflow_culprit(np.array(0.5))
    ('t', ('ctrl', None))
    """
    return ("t", t) if np.any(np.abs(t) > 1) else (ctrl, None)


def as_hyperplane(point, normal, d: int, names=("line_point", "line_normal")) -> tuple[np.ndarray, np.ndarray]:
    """A point ``(d,)`` and a nonzero normal ``(d,)`` of a line (a plane in 3D, a hyperplane in
    general) checked against the dimension d of the points it will be compared with (for library
    modules, not in ``__all__``).

    >>> [v.tolist() for v in as_hyperplane([0, 1], [0, 2], 2)]
    [[0.0, 1.0], [0.0, 2.0]]

    >>> as_hyperplane([0, 0], [0, 0], 2)
    Traceback (most recent call last):
    ...
    ValueError: line_normal must be a nonzero vector; got all zeros
    """
    for name, value in zip(names, (point, normal)):
        shape = as_float_array(value, name).shape
        if len(shape) == 1 and shape != (d,):
            raise ValueError(f"{name} must hold {d}-dimensional points (last axis of length {d}), as ctrl does; "
                             f"got shape {shape}")
    p = as_points(point, names[0], ndim=1, dim=d)
    nrm = as_points(normal, names[1], ndim=1, dim=d)
    if not np.any(nrm):
        raise ValueError(f"{names[1]} must be a nonzero vector; got all zeros")
    return p, nrm


def as_colour(value, name: str) -> tuple[float, float, float]:
    """An RGB colour: three finite numbers in [0, 1], as a tuple of floats.

    >>> as_colour([1, 0.5, 0], "background")
    (1.0, 0.5, 0.0)
    """
    c = as_float_array(value, name)
    if c.shape != (3,):
        raise ValueError(f"{name} must be an RGB triple (3 numbers in [0, 1]); got shape {c.shape}")
    check_finite(c, name)
    if np.any(c < 0) or np.any(c > 1):
        raise ValueError(f"{name} must hold numbers in [0, 1] (an RGB colour); got {c.tolist()}")
    return tuple(float(v) for v in c)

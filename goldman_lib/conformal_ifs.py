"""Recursive turtle programs and conformal iterated function systems (Goldman §8.2-8.5).

A turtle's state ``(P, w)`` is a point and a vector.  FORWARD, MOVE, TURN and RESIZE are
*conformal*: translation, rotation and uniform scaling.  So (§8.2) if a turtle program drawn
from the standard state ``((0, 0), (1, 0))`` draws the set ``G``, the same program drawn from the
state ``(P, w)`` draws ``S(G)``, where ``S`` is the unique orientation-preserving similarity
sending ``(0, 0) -> P`` and ``(1, 0) -> P + w`` (:func:`state_map`).

A recursive turtle program (:class:`goldman_lib.fractals.RecursiveTurtleProgram`) at level
``n`` runs its body; each RECURSE draws level ``n - 1`` from the state the turtle is in.  Let
``T_i`` be the similarity sending the initial state to the state at the i-th RECURSE, and ``C``
the strokes the body draws itself.  Then level ``n`` is ``C ∪ T_1(G_{n-1}) ∪ ... ∪ T_k(G_{n-1})``:
exactly the deterministic algorithm of the conformal IFS ``{T_1, ..., T_k}`` with condensation
set ``C`` started from the base case's drawing ``G_0`` (§8.3).  Hence:

* :func:`rons_algorithm` (turtle program -> conformal IFS) walks the body once and records the
  state at each RECURSE (§8.4);
* :func:`tao_algorithm` (conformal IFS -> turtle program) writes a body that, for each map,
  moves the turtle with the pen up to the state ``T_i(P0, w0)``, turns and resizes, RECURSEs,
  and undoes the moves, so the body leaves the turtle where it started (§8.4);
* bump fractals (§8.5) come both ways from one polyline, the *bump*: :func:`bump_ifs` maps the
  unit segment onto each segment of the bump, :func:`bump_program` walks the bump with a RECURSE
  in place of each FORWARD.

**The formulation used here** (documented because the book states its theorems for the
programs of its chapters, and a library must say what it does with every program):

1. *State consistency.*  The state at the i-th RECURSE depends on how the earlier recursive
   calls moved the turtle.  Ron's algorithm needs every level to change the turtle's state the
   same way; it checks that level 1 changes it as the base case does (then, by induction, so
   does every level) and raises ValueError otherwise.
2. *Mirror calls.*  ``("RECURSE", -1)`` of :mod:`goldman_lib.fractals` runs the *mirror
   program* (every TURN negated).  Such a program is a pair of mutually recursive programs; it
   is a single IFS when the mirror program draws a similar copy ``M(G_n)`` of the program at
   every level.  Ron's algorithm looks for such an ``M`` (the similarities taking the chord of
   the base case onto the mirror's chord, forwards or backwards, with or without a reflection),
   verifies the sufficient condition that both bodies then produce the same maps, and uses
   ``M ∘ T_i`` for a mirror call.  For the Heighway dragon ``M`` is the half turn about the
   chord's midpoint (the mirror dragon is the dragon traversed backwards).
3. *Reflections.*  A turtle cannot reverse orientation, so Tao's algorithm accepts
   orientation-preserving similarities only; a non-conformal map or a reflection raises
   ValueError naming the map.
4. *Drawings are compared as sets* (of segments, or of vertices with the Hausdorff distance of
   :mod:`goldman_lib.fixed_point`): the turtle and the IFS draw the same segments in different
   orders, and the turtle joins strokes the IFS keeps apart.

Matrices follow :mod:`goldman_lib.affine`: points are row vectors, ``Q = [P 1] @ M``, the
translation is the last row, and ``A @ B`` applies ``A`` first.  Angles are in degrees.

>>> from goldman_lib import fractals
>>> koch = rons_algorithm(fractals.koch_curve_program())
>>> len(koch.maps), koch.maps[1].round(6)[:, :2].tolist()
(4, [[0.166667, 0.288675], [-0.288675, 0.166667], [0.333333, 0.0]])

Importing this module imports numpy only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from goldman_lib import affine
from goldman_lib import ifs as ifs_module
from goldman_lib.fixed_point import MAX_PAIRS, hausdorff_distance
from goldman_lib import fractals
from goldman_lib.fractals import RECURSE, RecursiveTurtleProgram
from goldman_lib.validation import (MAX_ITEMS, as_float, as_float_array, as_int, as_points, as_tolerance,
                                    check_finite, within_budget)

__all__ = [
    "STANDARD_POINT", "STANDARD_DIRECTION", "state_map", "initial_state_map", "state_after",
    "transform_polylines", "TurtleIFS", "rons_algorithm", "tao_algorithm", "polyline_commands",
    "move_commands", "ifs_polylines", "segment_set", "same_drawing", "shared_segments", "drawing_distance",
    "equivalence_distance", "contraction_ratio", "base_case_gaps",
    "BUMPS", "bump_ifs", "bump_program", "bump_of",
]

#: The turtle's standard initial state: at the origin, heading along the x-axis with step 1.
STANDARD_POINT = np.array([0.0, 0.0])
STANDARD_DIRECTION = np.array([1.0, 0.0])

_TOL = 1e-9


# ---------------------------------------------------------------------------------------------
# §8.2 Changing the turtle's initial state
# ---------------------------------------------------------------------------------------------

def _state(point, direction, names=("point", "direction")) -> tuple[np.ndarray, np.ndarray]:
    p = as_points(point, names[0], ndim=1, dim=2)
    w = as_points(direction, names[1], ndim=1, dim=2)
    if not np.any(w):
        raise ValueError(f"{names[1]} must be a nonzero vector (the turtle's heading and step); got (0, 0)")
    return p, w


def _frame(p: np.ndarray, w: np.ndarray) -> np.ndarray:
    """The similarity sending (0,0) -> p and (1,0) -> p + w (no validation)."""
    return np.array([[w[0], w[1], 0.0], [-w[1], w[0], 0.0], [p[0], p[1], 1.0]])


def state_map(point, direction) -> np.ndarray:
    """The conformal map sending the standard state ``((0, 0), (1, 0))`` to ``(point, direction)``
    (Goldman §8.2).

    It rotates by the heading of ``w = direction``, scales by ``|w|`` and translates by ``P =
    point``: in the row-vector convention ``M = [[w_x, w_y, 0], [-w_y, w_x, 0], [P_x, P_y, 1]]``.
    A turtle program started in the state ``(P, w)`` draws exactly ``M`` applied to what it
    draws from the standard state.  point, direction: ``(2,)``.  Returns ``(3, 3)``.
    Raises ValueError for a zero direction or non-finite input.

    >>> state_map([2, 1], [0, 2])
    array([[ 0.,  2.,  0.],
           [-2.,  0.,  0.],
           [ 2.,  1.,  1.]])
    """
    p, w = _state(point, direction)
    return _frame(p, w)


def initial_state_map(point, direction, new_point, new_direction) -> np.ndarray:
    """The conformal map sending the turtle state ``(point, direction)`` to ``(new_point,
    new_direction)`` (Goldman §8.2).

    Changing a turtle program's initial state from the first state to the second changes its
    drawing by exactly this map: ``inverse(state_map(P, w)) @ state_map(P', w')`` (first back to
    the standard state, then out to the new one).  All arguments ``(2,)``.  Returns ``(3, 3)``.
    Raises ValueError for a zero direction.

    >>> initial_state_map([0, 0], [1, 0], [1, 1], [0, 1]).round(12)
    array([[ 0.,  1.,  0.],
           [-1.,  0.,  0.],
           [ 1.,  1.,  1.]])
    """
    p, w = _state(point, direction)
    q, u = _state(new_point, new_direction, ("new_point", "new_direction"))
    return np.linalg.inv(_frame(p, w)) @ _frame(q, u)


def state_after(M, point=(0, 0), direction=(1, 0)) -> tuple[np.ndarray, np.ndarray]:
    """The image ``(P M, w L)`` of a turtle state under an affine map ``M`` (Goldman §8.2): the
    point gets the translation, the direction (a vector) only the linear part ``L``.

    >>> state_after(affine.similarity(0.5, 90, [1, 1]))
    (array([1., 1.]), array([0. , 0.5]))
    """
    M = affine.as_affine(M)
    p, w = _state(point, direction)
    return p @ M[:2, :2] + M[2, :2], w @ M[:2, :2]


def transform_polylines(polylines, M) -> list[np.ndarray]:
    """Apply an affine map to every stroke of a drawing: a list of ``(k, 2)`` arrays.

    >>> transform_polylines([[[0, 0], [1, 0]]], affine.translation([0, 1]))[0].tolist()
    [[0.0, 1.0], [1.0, 1.0]]
    """
    M = affine.as_affine(M)
    if polylines is None:
        raise TypeError("polylines must be a list of (k, 2) strokes; got None")
    return [p @ M[:2, :2] + M[2, :2] for p in _as_strokes(polylines, "polylines")]


# ---------------------------------------------------------------------------------------------
# Walking a body: the state at each RECURSE and the strokes drawn (the core of Ron's algorithm)
# ---------------------------------------------------------------------------------------------

def _rotation(angle: float) -> np.ndarray:
    return affine.rotation(angle)


@dataclass
class _Walk:
    calls: list            # (F (3, 3) standard-frame state at the call, kind +1 / -1)
    strokes: list          # polylines drawn by the entries themselves
    final: np.ndarray      # the state after the entries, as a similarity F


def _walk(entries, sign: float, change_pos: np.ndarray | None, change_neg: np.ndarray | None) -> _Walk:
    """Run the entries from the standard state with the turtle as a similarity ``F`` (state =
    ``F`` applied to the standard state).  A RECURSE applies the state change of the program
    (``change_pos``) or of its mirror (``change_neg``); TURNs are multiplied by ``sign``."""
    F = np.eye(3)
    calls, strokes, current = [], [], None
    for cmd, value in entries:
        if cmd == "TURN":
            F = _rotation(sign * value) @ F
        elif cmd == "RESIZE":
            F = affine.scaling(value) @ F
        elif cmd in ("FORWARD", "MOVE"):
            start = F[2, :2].copy()
            T = np.eye(3)
            T[2, 0] = value
            F = T @ F
            if cmd == "FORWARD":
                if current is None:
                    current = [start]
                current.append(F[2, :2].copy())
            elif current is not None:
                strokes.append(np.array(current))
                current = None
        elif cmd == RECURSE:
            if current is not None:
                strokes.append(np.array(current))
                current = None
            kind = -1 if value == -1 else 1
            calls.append((F.copy(), kind))
            F = (change_neg if kind < 0 else change_pos) @ F
    if current is not None:
        strokes.append(np.array(current))
    return _Walk(calls, strokes, F)


def _describe_state(F: np.ndarray) -> str:
    p, w = F[2, :2], F[0, :2]
    return f"point ({p[0]:.4g}, {p[1]:.4g}), direction ({w[0]:.4g}, {w[1]:.4g})"


def _close(A: np.ndarray, B: np.ndarray, tol: float = _TOL) -> bool:
    scale = max(1.0, float(np.abs(A).max()), float(np.abs(B).max()))
    return bool(np.abs(A - B).max() <= tol * scale)


def _maps_match(first: list, second: list, tol: float = 1e-8) -> bool:
    """Whether two lists of 3x3 maps are equal as multisets (up to ``tol``)."""
    if len(first) != len(second):
        return False
    left = list(second)
    for A in first:
        for j, B in enumerate(left):
            if _close(A, B, tol):
                del left[j]
                break
        else:
            return False
    return True


def segment_set(polylines, decimals: int = 9) -> np.ndarray:
    """The segments of a drawing as a sorted ``(s, 4)`` array of rounded ``(x0, y0, x1, y1)``,
    each segment's endpoints in lexicographic order and zero-length segments dropped: two
    drawings with equal segment sets draw the same picture whatever the order of their strokes.

    >>> segment_set([[[1, 0], [0, 0]], [[0, 0], [1, 0], [1, 0]]]).tolist()
    [[0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 1.0, 0.0]]
    """
    decimals = as_int(decimals, "decimals", minimum=-300, maximum=300)
    return _segment_set(polylines, decimals, "polylines")


def _segment_set(polylines, decimals: int, name: str) -> np.ndarray:
    segs = []
    for p in _as_strokes(polylines, name):
        if len(p) >= 2:
            segs.append(np.concatenate([p[:-1], p[1:]], axis=1))
    if not segs:
        return np.zeros((0, 4))
    with np.errstate(over="ignore", invalid="ignore"):
        s = np.round(np.concatenate(segs), decimals) + 0.0
    if not np.isfinite(s).all():
        raise ValueError(f"{name} is too large to round to {decimals} decimals (a coordinate overflows); "
                         f"scale them down or use fewer decimals")
    s = s[np.hypot(s[:, 2] - s[:, 0], s[:, 3] - s[:, 1]) > 0]
    swap = (s[:, 0] > s[:, 2]) | ((s[:, 0] == s[:, 2]) & (s[:, 1] > s[:, 3]))
    s[swap] = s[swap][:, [2, 3, 0, 1]]
    return s[np.lexsort(s.T[::-1])]


def same_drawing(first, second, tol: float = 1e-9) -> bool:
    """Whether two drawings (lists of strokes) consist of the same segments, up to order and
    ``tol``; duplicates count once.

    >>> same_drawing([[[0, 0], [2, 0]]], [[[2, 0], [1, 0], [0, 0]]])
    False
    >>> same_drawing([[[0, 0], [1, 0], [1, 1]]], [[[1, 1], [1, 0]], [[0, 0], [1, 0]]])
    True
    """
    tol = as_tolerance(tol)
    a, b = _segment_set(first, 9, "first"), _segment_set(second, 9, "second")
    a, b = np.unique(a, axis=0), np.unique(b, axis=0)
    if a.shape != b.shape:
        return False
    return bool(a.size == 0 or np.abs(a - b).max() <= tol * max(1.0, float(np.abs(a).max())))


def shared_segments(first, second, decimals: int = 9) -> tuple[int, int, int]:
    """How many distinct segments each drawing has and how many they share, endpoints rounded to
    ``decimals`` (Goldman §8.3: a turtle program and its IFS draw the same segments, so all three
    counts agree).  Returns ``(in first, in second, in both)``; segments count once whatever
    their direction or repeats.

    >>> shared_segments([[[0, 0], [1, 0], [1, 1]]], [[[1, 1], [1, 0]], [[0, 0], [2, 0]]])
    (2, 2, 1)
    """
    decimals = as_int(decimals, "decimals", minimum=-300, maximum=300)
    a = {tuple(row) for row in _segment_set(first, decimals, "first").tolist()}
    b = {tuple(row) for row in _segment_set(second, decimals, "second").tolist()}
    return len(a), len(b), len(a & b)


def _vertices(polylines, name: str = "polylines") -> np.ndarray:
    if isinstance(polylines, (list, tuple)) and len(polylines) == 0:
        return np.zeros((0, 2))
    pts = _as_strokes(polylines, name)
    return np.concatenate(pts) if pts else np.zeros((0, 2))


def _nearest_by_cells(A: np.ndarray, B: np.ndarray, cell: float) -> np.ndarray | None:
    """For each point of A, the distance to the nearest point of B in the same grid cell, the
    grid shifted by 0 or half a cell along each axis (four grids, so any two points closer than
    cell/4 along both axes share a cell of one of them); None if some point of A has no such
    partner."""
    B = np.unique(B, axis=0)  # exact repeats (strokes meeting at a vertex) add no candidates
    best = np.full(len(A), np.inf)
    for ox in (0.0, 0.5):
        for oy in (0.0, 0.5):
            off = np.array([ox, oy])
            ka = np.floor(A / cell + off).astype(np.int64)
            kb = np.floor(B / cell + off).astype(np.int64)
            keys_a = ka[:, 0] * (1 << 32) + ka[:, 1]
            keys_b = kb[:, 0] * (1 << 32) + kb[:, 1]
            order = np.argsort(keys_b, kind="stable")
            sorted_b = keys_b[order]
            lo = np.searchsorted(sorted_b, keys_a, side="left")
            hi = np.searchsorted(sorted_b, keys_a, side="right")
            for k in range(int((hi - lo).max(initial=0))):  # every candidate of the cell, nearest kept
                take = lo + k < hi
                partner = B[order[lo[take] + k]]
                d = np.hypot(*(A[take] - partner).T)
                best[take] = np.minimum(best[take], d)
    return None if np.isinf(best).any() else best


def _matched_distance(A: np.ndarray, B: np.ndarray, cell: float = 1e-6) -> float | None:
    """An upper bound on the Hausdorff distance, in linear time, when the two sets coincide (up to
    ~cell/4): every point is paired with a point of the other set in a shared grid cell.  None if
    some point has no partner (then the sets differ by more than rounding)."""
    if max(float(np.abs(A).max()), float(np.abs(B).max())) / cell > 2.0 ** 30:
        return None
    da = _nearest_by_cells(A, B, cell)
    if da is None:
        return None
    db = _nearest_by_cells(B, A, cell)
    if db is None:
        return None
    return float(max(da.max(), db.max()))


def drawing_distance(first, second) -> float:
    """The Hausdorff distance between the vertex sets of two drawings (Goldman §7.3.3, §8.3).

    first, second: lists of ``(k, 2)`` strokes, each drawing nonempty.  When every vertex of
    each drawing has a vertex of the other within about 1e-7 (the same fractal drawn two ways),
    the distance is computed from those partners, found by hashing grid cells in linear time (an
    upper bound, exact for coinciding sets); otherwise by
    :func:`goldman_lib.fixed_point.hausdorff_distance`, whose cost grows with the product of the
    two sizes -- too slow for a slider at level 6 and above; it is refused (ValueError naming
    ``first`` and ``second``) when ``len(first vertices) * len(second vertices)`` exceeds
    :data:`goldman_lib.fixed_point.MAX_PAIRS`.  Raises ValueError if a drawing is empty.

    >>> drawing_distance([[[0, 0], [1, 0]]], [[[0, 0], [1, 0.5]]])
    0.5
    """
    A, B = _vertices(first, "first"), _vertices(second, "second")
    distance = _distance(A, B)
    if not math.isfinite(distance):
        name = "first" if np.abs(A).max() >= np.abs(B).max() else "second"
        raise ValueError(f"{name} is too large in magnitude: the distance between the drawings overflows float64")
    return distance


def _distance(A: np.ndarray, B: np.ndarray) -> float:
    """The Hausdorff distance of two vertex sets (inf if it overflows) for :func:`drawing_distance`."""
    for name, P in (("first", A), ("second", B)):
        if len(P) == 0:
            raise ValueError(f"both drawings must draw something to have a Hausdorff distance; {name} has no strokes")
    with np.errstate(over="ignore", invalid="ignore"):
        distance = _matched_distance(A, B)
        if distance is None:
            _check_pairs(len(A), len(B))
            try:
                distance = hausdorff_distance(A, B)
            except ValueError as exc:
                if "overflow" not in str(exc):
                    raise
                distance = math.inf   # the callers name the input that made it overflow
    return distance


def _check_pairs(m: int, n: int, what: str = "first and second differ, so") -> None:
    if m * n > MAX_PAIRS:
        raise ValueError(f"{what} their Hausdorff distance compares every vertex of one with every vertex of the "
                         f"other: {m:,} * {n:,} = {m * n:,} pairs, over the limit of {MAX_PAIRS:,}; use lower levels")


# ---------------------------------------------------------------------------------------------
# Ron's algorithm (§8.4): turtle program -> conformal IFS
# ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class TurtleIFS:
    """What Ron's algorithm produces: a conformal IFS with the drawings that start it (Goldman §8.3-8.4).

    maps: ``(k, 3, 3)`` the similarities ``T_i`` (one per RECURSE of the body, in order).
    condensation: the strokes the body draws itself (the condensation set ``C``, §6.4).
    base: the strokes of the base case (level 0, the start set of the deterministic algorithm).
    placements: ``(j, 3, 3)`` where the driver of the program (``start``, e.g. the three sides of
    the Koch snowflake) puts copies of the fractal; the identity for a plain program.
    frame: the strokes the driver draws itself.  mirror: the similarity ``M`` with mirror
    program = ``M`` (program), or None.  name: a label.

    Level ``n`` of the program is ``frame ∪ U_1(G_n) ∪ ... ∪ U_j(G_n)`` where ``G_0`` = base and
    ``G_n = C ∪ T_1(G_{n-1}) ∪ ... ∪ T_k(G_{n-1})`` (:meth:`polylines`).
    """

    maps: np.ndarray
    condensation: tuple = ()
    base: tuple = ()
    placements: np.ndarray = field(default_factory=lambda: np.eye(3)[None])
    frame: tuple = ()
    mirror: np.ndarray | None = None
    name: str = ""

    @property
    def ifs(self) -> ifs_module.IFS:
        """The maps as a :class:`goldman_lib.ifs.IFS`, with the condensation strokes joined into
        its one condensation polyline (as a set of vertices it is the same; only a drawing would
        join separate strokes)."""
        C = np.concatenate(self.condensation) if self.condensation else None
        return ifs_module.IFS(self.maps, condensation=C, name=self.name)

    def polylines(self, level: int) -> list[np.ndarray]:
        """Level ``level`` drawn by the deterministic algorithm (Goldman §6.1, §8.3): the copies
        of the base strokes and of the condensation strokes, placed by the driver.  level >= 0,
        with the drawing at most :data:`goldman_lib.ifs.MAX_POINTS` points and
        :data:`goldman_lib.validation.MAX_ITERATIONS` strokes (ValueError naming ``level``).

        >>> from goldman_lib import fractals
        >>> len(rons_algorithm(fractals.sierpinski_gasket_program()).polylines(2))
        9
        """
        level = _drawing_level(level, len(self.maps), [len(b) for b in self.base],
                               [len(c) for c in self.condensation], len(self.placements))
        G = ifs_polylines(self.maps, level, self.base, self.condensation)
        if len(self.placements) == 1 and np.array_equal(self.placements[0], np.eye(3)):
            return list(self.frame) + G
        out = list(self.frame)
        for U in self.placements:
            out.extend(transform_polylines(G, U))
        return out

    def __repr__(self) -> str:
        return (f"TurtleIFS({self.name or 'unnamed'!r}, {len(self.maps)} maps, "
                f"{len(self.condensation)} condensation strokes, {len(self.base)} base strokes)")


def ifs_polylines(maps, level: int, start, condensation=()) -> list[np.ndarray]:
    """The deterministic algorithm applied to drawings: ``W^level(start) ∪ W^(level-1)(C) ∪ ...
    ∪ C`` as a list of strokes (Goldman §6.1, §6.4), ``W`` the union of the maps.

    maps: an :class:`goldman_lib.ifs.IFS` (its own condensation set is ignored here) or a list
    of 3x3 maps.  start, condensation: lists of ``(m, 2)`` strokes.  Each stroke's copies come
    from :func:`goldman_lib.ifs.deterministic` with that stroke as start set.  Raises ValueError
    naming ``level`` if the drawing would exceed :data:`goldman_lib.ifs.MAX_POINTS` points or
    :data:`goldman_lib.validation.MAX_ITERATIONS` strokes (checked before anything is drawn).

    >>> ifs_polylines(ifs_module.cantor(), 1, [[[0, 0], [1, 0]]])[1].tolist()
    [[0.6666666666666667, 0.0], [1.0, 0.0]]
    """
    M = maps.maps if isinstance(maps, ifs_module.IFS) else affine.as_affine(maps, "maps")
    if M.ndim == 2:
        M = M[None]
    system = ifs_module.IFS(M)
    start = _as_strokes(start, "start")
    condensation = _as_strokes(condensation, "condensation")
    level = _drawing_level(level, len(M), [len(s) for s in start], [len(c) for c in condensation])
    out = []
    for j, s in enumerate(start):
        s = as_points(s, f"start[{j}]", dim=2)
        out.extend(ifs_module.deterministic(system, level, start=s).reshape(-1, len(s), 2))
    for j, c in enumerate(condensation):
        c = as_points(c, f"condensation[{j}]", dim=2)
        for lev in range(level):
            out.extend(ifs_module.deterministic(system, lev, start=c).reshape(-1, len(c), 2))
    return out


def _drawing_size(level: int, k: int, starts: list, conds: list) -> tuple[int, int]:
    """(points, strokes) of :func:`ifs_polylines` at ``level``."""
    copies = k ** level
    below = sum(k ** j for j in range(level)) if k > 1 else level
    return (copies * sum(starts) + below * sum(conds), copies * len(starts) + below * len(conds))


def _drawing_level(level, k: int, starts: list, conds: list, placements: int = 1) -> int:
    """A level whose drawing has at most MAX_POINTS points and MAX_ITERATIONS strokes."""
    from goldman_lib.validation import MAX_ITERATIONS

    far = 10 ** 12

    def cost(v, i):
        return placements * _drawing_size(v, k, starts, conds)[i] if v <= 4096 else far

    level = within_budget(level, "level", cost=lambda v: cost(v, 0), what="the drawing",
                          limit=ifs_module.MAX_POINTS)
    return within_budget(level, "level", cost=lambda v: cost(v, 1), what="the drawing", unit="strokes",
                         limit=MAX_ITERATIONS)


def _mirror_candidates(base_pos: _Walk, base_neg: _Walk) -> list[np.ndarray]:
    """Similarities taking the program's chord (start -> end of the base case) onto the mirror's
    chord, forwards or backwards, with or without a reflection; the identity and the reflection
    in the heading line if the base case ends where it starts."""
    e = complex(*base_pos.final[2, :2])
    f = complex(*base_neg.final[2, :2])
    reflect = np.diag([1.0, -1.0, 1.0])
    cands = [np.eye(3), reflect]
    if abs(e) > _TOL:
        for a, b in ((0j, f), (f, 0j)):            # image of 0 and of e
            alpha = (b - a) / e
            cands.append(np.array([[alpha.real, alpha.imag, 0], [-alpha.imag, alpha.real, 0],
                                   [a.real, a.imag, 1.0]]))
            alpha = (b - a) / e.conjugate()     # z -> alpha conj(z) + a
            cands.append(np.array([[alpha.real, alpha.imag, 0], [alpha.imag, -alpha.real, 0],
                                   [a.real, a.imag, 1.0]]))
    return cands


def _find_mirror(body, pos: _Walk, neg: _Walk, base_pos: _Walk, base_neg: _Walk) -> np.ndarray | None:
    for M in _mirror_candidates(base_pos, base_neg):
        if not same_drawing(transform_polylines(base_pos.strokes, M), base_neg.strokes):
            continue
        if not same_drawing(transform_polylines(pos.strokes, M), neg.strokes):
            continue
        mine = [F if k > 0 else M @ F for F, k in neg.calls]
        want = [F @ M if k > 0 else M @ F @ M for F, k in pos.calls]
        if _maps_match(mine, want):
            return M
    return None


def rons_algorithm(program, point=(0, 0), direction=(1, 0)) -> TurtleIFS:
    """Ron's algorithm: convert a recursive turtle program into a conformal IFS (Goldman §8.4).

    Walk the body once from the initial state, treating each RECURSE as "draw nothing and change
    the state as the base case does"; the i-th map is the similarity sending the initial state
    to the state at the i-th RECURSE (:func:`initial_state_map`), and the strokes the body draws
    itself are the condensation set.  By §8.2 each recursive call draws the image of level
    ``n - 1`` under its map, so level ``n`` of the program is the deterministic algorithm's level
    ``n`` from the base case's drawing (:meth:`TurtleIFS.polylines`).

    program: a :class:`goldman_lib.fractals.RecursiveTurtleProgram`.  point, direction: ``(2,)``
    the turtle's initial state (the maps are conjugated by :func:`state_map`).  Returns a
    :class:`TurtleIFS`.  Raises TypeError for a program of another type, and ValueError if level
    1 leaves the turtle in another state than the base case (no single IFS then), or if the
    program calls its mirror program and the mirror program is not a similar copy of it (a pair
    of mutually recursive programs, not one IFS).

    >>> from goldman_lib import fractals
    >>> c = rons_algorithm(fractals.c_curve_program())
    >>> [round(affine.to_parameters(M)["angle"], 9) for M in c.maps]
    [45.0, -45.0]
    """
    if not isinstance(program, RecursiveTurtleProgram):
        raise TypeError(f"program must be a goldman_lib.fractals.RecursiveTurtleProgram; got {type(program).__name__}")
    p0, w0 = _state(point, direction)
    S = _frame(p0, w0)
    S_inv = np.linalg.inv(S)
    label = f"the {program.name}" if program.name else "the program"

    base_pos = _walk(program.base, 1.0, None, None)
    base_neg = _walk(program.base, -1.0, None, None)
    D, Dm = base_pos.final, base_neg.final
    pos = _walk(program.body, 1.0, D, Dm)
    if not _close(pos.final, D):
        raise ValueError(
            f"{label}: the base case leaves the turtle at {_describe_state(D)} but level 1 leaves it at "
            f"{_describe_state(pos.final)} (from the standard state); Ron's algorithm needs every level to "
            f"change the turtle's state the same way (Goldman §8.3)")
    mirrored = any(k < 0 for _, k in pos.calls) or any(c == RECURSE and v == -1 for c, v in program.start)
    M = None
    if mirrored:
        neg = _walk(program.body, -1.0, D, Dm)
        if not _close(neg.final, Dm):
            raise ValueError(f"{label}: the mirror program's base case and level 1 change the turtle's state "
                             f"differently; Ron's algorithm needs every level to change it the same way")
        M = _find_mirror(program.body, pos, neg, base_pos, base_neg)
        if M is None:
            raise ValueError(f"{label} calls its mirror program, and no similarity taking the program's chord "
                             f"onto the mirror's makes the mirror a copy of the program (both bodies giving the "
                             f"same maps): the two form a pair of mutually recursive programs (a graph-directed "
                             f"system), not a single IFS")
    maps = np.array([F if k > 0 else M @ F for F, k in pos.calls])
    driver = _walk(program.start, 1.0, D, Dm)
    placements = np.array([F if k > 0 else M @ F for F, k in driver.calls])
    return TurtleIFS(
        maps=S_inv @ maps @ S,
        condensation=tuple(transform_polylines(pos.strokes, S)),
        base=tuple(transform_polylines(base_pos.strokes, S)),
        placements=S_inv @ placements @ S,
        frame=tuple(transform_polylines(driver.strokes, S)),
        mirror=None if M is None else S_inv @ M @ S,
        name=program.name,
    )


def equivalence_distance(program, level: int, point=(0, 0), direction=(1, 0)) -> float:
    """The Hausdorff distance between level ``level`` drawn by the turtle and by the IFS of
    Ron's algorithm (Goldman §8.3: the equivalence theorem says it is 0, up to rounding).

    level: as :meth:`goldman_lib.fractals.RecursiveTurtleProgram.polylines` allows (at most the
    program's ``max_level()``).  Raises as :func:`rons_algorithm`, and ValueError if the level
    draws nothing or the two drawings differ by more than rounding and are too large to compare
    (:func:`drawing_distance`).

    >>> from goldman_lib import fractals
    >>> equivalence_distance(fractals.koch_curve_program(), 4) < 1e-12
    True
    """
    conv = rons_algorithm(program, point, direction)
    with np.errstate(over="ignore", invalid="ignore"):
        turtle_drawing = program.polylines(level, point, direction)
        ifs_drawing = conv.polylines(level)
        finite = all(np.isfinite(p).all() for p in turtle_drawing + ifs_drawing)
        distance = _distance(_vertices(turtle_drawing), _vertices(ifs_drawing)) if finite else math.inf
    if not math.isfinite(distance):
        p, w = _state(point, direction)
        name = "direction" if np.abs(w).max() >= np.abs(p).max() else "point"
        raise ValueError(f"{name} is too large in magnitude: level {level} drawn from it overflows float64")
    return distance


def contraction_ratio(system) -> float:
    """The largest scale factor of the maps of a conformal IFS: the contraction ratio ``s`` of
    the fractal theorem, ``h(W(A), W(B)) <= s h(A, B)`` (Goldman §7.3.3, §8.3).

    system: a :class:`TurtleIFS`, an :class:`goldman_lib.ifs.IFS` or a list of maps.  For a
    conformal map the scale is ``sqrt(|det L|)``; a mirror image of one (a similarity that
    reflects, :func:`goldman_lib.affine.is_similarity`) has a scale factor too and is accepted here.
    Raises ValueError if a map is not a similarity (it has no single scale factor).

    >>> round(contraction_ratio(ifs_module.dragon()), 12)
    0.707106781187
    """
    maps = _maps_of(system)
    for i, Mi in enumerate(maps):
        if not affine.is_similarity(Mi):
            raise ValueError(f"maps[{i}] is not conformal: it has no single scale factor")
    return float(np.sqrt(np.abs(np.linalg.det(maps[:, :2, :2]))).max())


def base_case_gaps(program, other_base, levels: int) -> np.ndarray:
    """Hausdorff distances between the drawings of a program with its base case and with
    ``other_base``, levels ``0..levels`` (Goldman §8.3 corollary: the fractal does not depend on
    the base case).

    The two programs have the same IFS (same body), so level ``n`` of each is ``W^n`` of its base
    drawing (plus the same condensation copies), and the distances shrink at least like
    ``s^n`` (:func:`contraction_ratio`).  other_base: a base case (sequence of ``(command,
    value)``).  levels: >= 0, with the Hausdorff distances of levels ``0..levels`` comparing at
    most :data:`goldman_lib.fixed_point.MAX_PAIRS` vertex pairs in all (two base cases draw
    different pictures, so the quadratic comparison is the expected cost; the C-curve with a box
    base reaches level 11, the Koch curve level 5), checked before anything is drawn.
    Returns ``(levels + 1,)``.  Raises ValueError if the two base cases change the
    turtle's state differently (then the bodies make different IFS) or one draws nothing.

    >>> from goldman_lib import fractals
    >>> box = [("TURN", 90), ("FORWARD", 0.5), ("TURN", -90), ("FORWARD", 1), ("TURN", -90),
    ...        ("FORWARD", 0.5), ("TURN", 90)]
    >>> base_case_gaps(fractals.c_curve_program(), box, 4).round(4).tolist()
    [0.5, 0.3536, 0.25, 0.1768, 0.125]
    """
    if not isinstance(program, RecursiveTurtleProgram):
        raise TypeError(f"program must be a goldman_lib.fractals.RecursiveTurtleProgram; got {type(program).__name__}")
    other = program.with_base(fractals.as_commands(other_base, "other_base", allow_recurse=False))
    a, b = rons_algorithm(program), rons_algorithm(other)
    if a.maps.shape != b.maps.shape or not _close(a.maps, b.maps, 1e-8):
        raise ValueError("other_base and the program's base case change the turtle's state differently, so "
                         "the two programs have different IFS; give a base case that ends in the same state")
    if not b.base and not b.condensation and not b.frame:
        raise ValueError("other_base draws nothing (only MOVE and TURN), and neither does the body: there is no "
                         "drawing to compare")

    def vertices(conv, n):
        if n > 4096:
            return 10 ** 12
        pts, _ = _drawing_size(n, len(conv.maps), [len(s) for s in conv.base], [len(c) for c in conv.condensation])
        return len(conv.placements) * pts + sum(len(f) for f in conv.frame)

    levels = within_budget(levels, "levels", cost=lambda v: sum(vertices(a, n) * vertices(b, n) for n in range(v + 1)),
                           what="the Hausdorff distances", unit="vertex pairs", limit=MAX_PAIRS)
    return np.array([drawing_distance(a.polylines(n), b.polylines(n)) for n in range(levels + 1)])


# ---------------------------------------------------------------------------------------------
# Tao's algorithm (§8.4): conformal IFS -> turtle program
# ---------------------------------------------------------------------------------------------

def _angle(v) -> float:
    return math.degrees(math.atan2(v[1], v[0]))


def _wrap(a: float) -> float:
    """An angle in degrees reduced to (-180, 180]."""
    a = math.fmod(a, 360.0)
    if a <= -180.0:
        a += 360.0
    elif a > 180.0:
        a -= 360.0
    return a


def _append(cmds: list, cmd: str, value: float, eps: float = 1e-13) -> None:
    """Append a command, merging it into a preceding one of the same kind and dropping no-ops."""
    if cmd == "TURN":
        value = _wrap(value)
    if cmds and cmds[-1][0] == cmd and cmd in ("TURN", "MOVE", "RESIZE"):
        prev = cmds.pop()[1]
        value = prev * value if cmd == "RESIZE" else prev + value
        if cmd == "TURN":
            value = _wrap(value)
    if (cmd in ("TURN", "MOVE") and abs(value) <= eps) or (cmd == "RESIZE" and abs(value - 1) <= eps):
        return
    snapped = round(value, 9)
    if abs(value - snapped) <= 1e-12 * max(1.0, abs(value)):
        value = snapped      # 120.00000000000001 -> 120 (a change far below the drawing's precision)
    cmds.append((cmd, float(value)))


def move_commands(point, direction, new_point, new_direction) -> list[tuple[str, float]]:
    """Commands taking the turtle from the state ``(point, direction)`` to ``(new_point,
    new_direction)`` with the pen up: TURN toward the new point, MOVE there, TURN to the new
    heading, RESIZE to the new step (Goldman §8.4, the moves of Tao's algorithm).

    Commands that do nothing (TURN 0, MOVE 0, RESIZE 1) are left out.  All arguments ``(2,)``.
    Raises ValueError for a zero direction.

    >>> move_commands([0, 0], [1, 0], [0, 2], [0, 0.5])
    [('TURN', 90.0), ('MOVE', 2.0), ('RESIZE', 0.5)]
    """
    p, w = _state(point, direction)
    q, u = _state(new_point, new_direction, ("new_point", "new_direction"))
    cmds: list = []
    step = math.hypot(*w)
    heading = _angle(w)
    d = q - p
    dist = math.hypot(*d)
    if dist > 0:
        _append(cmds, "TURN", _angle(d) - heading)
        _append(cmds, "MOVE", dist / step)
        heading = _angle(d)
    _append(cmds, "TURN", _angle(u) - heading)
    _append(cmds, "RESIZE", math.hypot(*u) / step)
    return cmds


def polyline_commands(polyline, *, draw: bool = True, home: bool = True) -> list[tuple[str, float]]:
    """Commands that draw a polyline from the standard state and (with ``home``) return the
    turtle to the standard state with the pen up (Goldman §8.4: the base case and condensation
    set of Tao's algorithm).

    polyline: ``(m, 2)``, in the turtle's own frame (start ``(0, 0)`` heading ``(1, 0)``).  The
    turtle MOVEs to the first point, then TURNs and goes FORWARD along each segment (MOVE if
    ``draw`` is False); zero-length segments are skipped.  Raises ValueError for a bad polyline.

    >>> polyline_commands([[0, 0], [1, 0], [1, 1]])
    [('FORWARD', 1.0), ('TURN', 90.0), ('FORWARD', 1.0), ('TURN', 135.0), ('MOVE', 1.4142135623730951), ('TURN', 135.0)]
    """
    P = as_points(polyline, "polyline", dim=2)
    cmds: list = []
    pos, heading = np.zeros(2), 0.0
    if np.hypot(*P[0]) > 0:
        _append(cmds, "TURN", _angle(P[0]))
        _append(cmds, "MOVE", float(np.hypot(*P[0])))
        heading = _angle(P[0])
    pos = P[0]
    for q in P[1:]:
        d = q - pos
        dist = float(np.hypot(*d))
        if dist == 0:
            continue
        _append(cmds, "TURN", _angle(d) - heading)
        cmds.append(("FORWARD" if draw else "MOVE", dist))
        heading, pos = _angle(d), q
    if len(P) == 1 and draw:
        cmds.append(("FORWARD", 0.0))
    if home:
        dist = float(np.hypot(*pos))
        if dist > 0:
            _append(cmds, "TURN", _angle(-pos) - heading)
            _append(cmds, "MOVE", dist)
            heading = _angle(-pos)
        _append(cmds, "TURN", -heading)
    return cmds


def _maps_of(system, name: str = "system") -> np.ndarray:
    if isinstance(system, TurtleIFS):
        return system.maps
    if isinstance(system, ifs_module.IFS):
        return system.maps
    try:
        arr = as_float_array(system, name)
    except TypeError as exc:
        raise TypeError(f"{name} must be an IFS, a TurtleIFS or a list of 3x3 maps; {exc}") from None
    if arr.ndim not in (2, 3) or arr.shape[-2:] != (3, 3) or len(arr) == 0:
        raise ValueError(f"{name} must be an IFS, a TurtleIFS or a list of 3x3 maps (shape (3, 3) or (k, 3, 3)); "
                         f"got shape {arr.shape}")
    M = affine.as_affine(check_finite(arr, name), "maps")
    return M[None] if M.ndim == 2 else M


def _ndim(x) -> int | None:
    try:
        return np.ndim(x)
    except (TypeError, ValueError):   # ragged: as_points names it
        return None


def _as_strokes(x, name: str) -> list[np.ndarray]:
    if x is None:
        return []
    if isinstance(x, np.ndarray) and x.ndim == 2:
        return [as_points(x, name, dim=2)]
    if isinstance(x, np.ndarray) and x.ndim == 3:
        return [as_points(p, f"{name}[{i}]", dim=2) for i, p in enumerate(x)]
    if isinstance(x, (list, tuple)) and x and _ndim(x[0]) == 1:
        return [as_points(x, name, dim=2)]
    if not isinstance(x, (list, tuple)):
        return [as_points(x, name, dim=2)]
    if x and all(type(p) is np.ndarray and p.dtype == np.float64 and p.ndim == 2 and p.shape[1] == 2 and len(p) for p in x):
        # the library's own drawings (thousands of short strokes at a slider's top level): one
        # finiteness check for all of them; a bad one is named by the stroke-by-stroke check below
        if np.isfinite(np.concatenate(x)).all():
            return list(x)
    return [as_points(p, f"{name}[{i}]", dim=2) for i, p in enumerate(x)]


def tao_algorithm(system, base=None, *, condensation=None, point=(0, 0), direction=(1, 0),
                  name: str | None = None) -> RecursiveTurtleProgram:
    """Tao's algorithm: convert a conformal IFS into a recursive turtle program (Goldman §8.4).

    For each map ``T_i`` the body moves the turtle with the pen up from the initial state ``(P0,
    w0)`` to the state ``T_i(P0, w0)`` (:func:`move_commands`), RECURSEs, and undoes the moves in
    reverse, so the body, like the base case, leaves the turtle where it started.  By §8.2 the
    i-th call then draws ``T_i`` of level ``n - 1``: level ``n`` of the program is the
    deterministic algorithm's level ``n`` started from the base drawing.

    system: an :class:`goldman_lib.ifs.IFS` (its condensation set, if any, is drawn by the body),
    a :class:`TurtleIFS`, or a list of 3x3 maps, each an orientation-preserving similarity.
    base: the start set, a ``(m, 2)`` polyline or a list of them in world coordinates (default:
    the segment from ``P0`` to ``P0 + w0``; for a TurtleIFS its base strokes).  condensation:
    strokes the body draws (default the system's).  point, direction: ``(2,)`` the initial state.
    name: a label (default the system's name).  Returns a
    :class:`goldman_lib.fractals.RecursiveTurtleProgram`.  Raises ValueError naming a map that is
    not conformal, reverses orientation (a turtle cannot reflect) or has scale 0.

    >>> prog = tao_algorithm(ifs_module.c_curve())
    >>> [(c, v if v is None else round(v, 9)) for c, v in prog.body]
    [('TURN', 45.0), ('RESIZE', 0.707106781), ('RECURSE', None), ('RESIZE', 1.414213562), ('MOVE', 0.707106781), ('TURN', -90.0), ('RESIZE', 0.707106781), ('RECURSE', None), ('RESIZE', 1.414213562), ('TURN', 90.0), ('MOVE', -0.707106781), ('TURN', -45.0)]
    >>> tao_algorithm(ifs_module.barnsley_fern())
    Traceback (most recent call last):
    ...
    ValueError: maps[0] is not conformal (its linear part [[0, 0], [0, 0.16]] stretches directions by different factors or shears them): a turtle can only move, turn and resize, so Tao's algorithm needs similarities (Goldman §8.4)
    """
    maps = _maps_of(system)
    p0, w0 = _state(point, direction)
    S = _frame(p0, w0)
    S_inv = np.linalg.inv(S)
    for i, Mi in enumerate(maps):
        L = Mi[:2, :2]
        if not affine.is_similarity(Mi):   # a reflection is a similarity: it gets its own message below
            shown = "[" + ", ".join("[" + ", ".join(f"{v:.4g}" for v in row) + "]" for row in L) + "]"
            raise ValueError(f"maps[{i}] is not conformal (its linear part {shown} stretches directions by "
                             f"different factors or shears them): a turtle can only move, turn and resize, "
                             f"so Tao's algorithm needs similarities (Goldman §8.4)")
        det = float(np.linalg.det(L))
        if abs(det) <= 1e-14:
            raise ValueError(f"maps[{i}] has scale 0 (it collapses the plane to a point); the turtle cannot "
                             f"RESIZE by 0")
        if det < 0:
            raise ValueError(f"maps[{i}] reverses orientation (a reflection, determinant {det:.4g} < 0): "
                             f"the turtle's FORWARD, MOVE, TURN and RESIZE preserve orientation, so Tao's "
                             f"algorithm needs orientation-preserving similarities")
    if base is None:
        if isinstance(system, TurtleIFS) and system.base:
            base_strokes = list(system.base)
        else:
            base_strokes = [np.array([p0, p0 + w0])]
    else:
        base_strokes = _as_strokes(base, "base")
    if condensation is None:
        if isinstance(system, TurtleIFS):
            cond = list(system.condensation)
        elif isinstance(system, ifs_module.IFS) and system.condensation is not None:
            cond = [system.condensation]
        else:
            cond = []
    else:
        cond = _as_strokes(condensation, "condensation")
    body: list = []
    for stroke in transform_polylines(cond, S_inv):
        for c, v in polyline_commands(stroke):
            _append(body, c, v) if c != "FORWARD" else body.append((c, v))
    origin, east = np.zeros(2), np.array([1.0, 0.0])
    for Mi in maps:
        T = S @ Mi @ S_inv                      # the map in the turtle's own frame
        q, u = T[2, :2], T[0, :2]
        go = move_commands(origin, east, q, u)
        for c, v in go:
            _append(body, c, v)
        body.append((RECURSE, None))
        for c, v in reversed(go):
            _append(body, c, 1.0 / v if c == "RESIZE" else -v)
    base_cmds: list = []
    for stroke in transform_polylines(base_strokes, S_inv):
        for c, v in polyline_commands(stroke):
            _append(base_cmds, c, v) if c != "FORWARD" else base_cmds.append((c, v))
    if not base_cmds:
        base_cmds = [("MOVE", 0.0)]
    if name is None:
        name = getattr(system, "name", "") or ""
    return RecursiveTurtleProgram(body, base_cmds, name)


# ---------------------------------------------------------------------------------------------
# §8.5 Bump fractals
# ---------------------------------------------------------------------------------------------

_H = math.sqrt(3) / 6


def _cesaro_bump(apex_angle: float) -> np.ndarray:
    """The Koch bump with the apex angle ``apex_angle`` (degrees) instead of 60: four equal
    segments, the middle two meeting at the apex."""
    a = math.radians(apex_angle)
    side = 1.0 / (2.0 + 2.0 * math.cos(a))   # base + 2 side*cos(a) + base with base = side
    return np.array([[0, 0], [side, 0], [0.5, side * math.sin(a)], [1 - side, 0], [1, 0]])


#: Standard bumps, name -> (polyline from (0, 0) to (1, 0), indices of the segments drawn backwards).
BUMPS = {
    "Koch curve": (np.array([[0, 0], [1 / 3, 0], [0.5, _H], [2 / 3, 0], [1, 0]]), ()),
    "C-curve": (np.array([[0, 0], [0.5, 0.5], [1, 0]]), ()),
    "dragon": (np.array([[0, 0], [0.5, 0.5], [1, 0]]), (1,)),
    "square Koch curve": (np.array([[0, 0], [1 / 3, 0], [1 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 0], [1, 0]]), ()),
    "Cesàro curve (80°)": (_cesaro_bump(80.0), ()),
}


def _as_bump(bump, reverse) -> tuple[np.ndarray, frozenset]:
    P = as_points(bump, "bump", dim=2, min_count=2)
    if len(P) < 2:
        raise ValueError("bump must have at least two points")
    if np.hypot(*(P[-1] - P[0])) <= _TOL:
        raise ValueError("bump must end away from where it starts (its chord is the segment it replaces)")
    seg = np.diff(P, axis=0)
    lens = np.hypot(seg[:, 0], seg[:, 1])
    if np.any(lens <= _TOL):
        i = int(np.argmax(lens <= _TOL))
        raise ValueError(f"bump segment {i} has length 0 (points {i} and {i + 1} coincide)")
    if reverse is None:
        reverse = ()
    if isinstance(reverse, (str, bytes)) or not hasattr(reverse, "__iter__"):
        raise TypeError(f"reverse must be a sequence of segment indices; got {type(reverse).__name__}")
    rev = set()
    for r in reverse:
        r = as_int(r, "reverse entry", minimum=0, maximum=len(seg) - 1)
        rev.add(r)
    return P, frozenset(rev)


def _chord_frame(P: np.ndarray) -> np.ndarray:
    """The similarity taking (0,0) -> P[0] and (1,0) -> P[-1]."""
    return _frame(P[0], P[-1] - P[0])


def bump_ifs(bump, reverse=(), name: str = "") -> ifs_module.IFS:
    """The IFS of a bump fractal (Goldman §8.5): one similarity per segment of the bump, taking
    the bump's chord (first point -> last point) onto that segment, or onto the segment traversed
    backwards for the indices in ``reverse``.

    bump: ``(m, 2)`` polyline, ``m >= 2``, first and last points distinct, no zero-length
    segment.  reverse: indices of the segments drawn backwards (a half turn added: the dragon).
    Raises ValueError naming the rule the bump breaks.

    >>> np.allclose(bump_ifs(*BUMPS["Koch curve"]).maps, ifs_module.koch().maps)
    True
    """
    P, rev = _as_bump(bump, reverse)
    C = _chord_frame(P)
    C_inv = np.linalg.inv(C)
    maps = []
    for i in range(len(P) - 1):
        a, b = (P[i + 1], P[i]) if i in rev else (P[i], P[i + 1])
        maps.append(C_inv @ _frame(a, b - a))
    return ifs_module.IFS(maps, name=name or "bump fractal")


def bump_program(bump, reverse=(), name: str = "") -> RecursiveTurtleProgram:
    """The recursive turtle program of a bump fractal (Goldman §8.5): walk the bump with a
    RECURSE in place of each FORWARD, RESIZEd to the segment's length.

    Normalised so the bump's chord is the turtle's step: level 0 is ``FORWARD 1``; level ``n``
    TURNs to each segment's heading, RESIZEs to its length and RECURSEs (so the turtle ends at
    the segment's end, as the base case does).  A reversed segment (index in ``reverse``) is
    crossed with the pen up, the turtle turns around (TURN 180), RECURSEs back to the segment's
    start, turns around and MOVEs to its end again.  Finally the turtle turns and resizes back,
    so every level leaves it one chord further on, heading the same way.  Raises as
    :func:`bump_ifs`.

    >>> print(bump_program(*BUMPS["C-curve"]).text().splitlines()[2])
      level n: TURN 45 RESIZE 0.7071067811865476 RECURSE TURN -90 RECURSE TURN 45 RESIZE 1.414213562373095
    """
    P, rev = _as_bump(bump, reverse)
    Q = transform_polylines([P], np.linalg.inv(_chord_frame(P)))[0]
    body: list = []
    heading, step = 0.0, 1.0
    for i in range(len(Q) - 1):
        d = Q[i + 1] - Q[i]
        length = float(np.hypot(*d))
        _append(body, "TURN", _angle(d) - heading)
        _append(body, "RESIZE", length / step)
        heading, step = _angle(d), length
        if i in rev:
            _append(body, "MOVE", 1.0)
            _append(body, "TURN", 180.0)
            body.append((RECURSE, None))
            _append(body, "TURN", 180.0)
            _append(body, "MOVE", 1.0)
        else:
            body.append((RECURSE, None))
    _append(body, "TURN", -heading)
    _append(body, "RESIZE", 1.0 / step)
    return RecursiveTurtleProgram(body, [("FORWARD", 1.0)], name or "bump fractal")


def bump_of(system, tol: float = 1e-9) -> tuple[np.ndarray, tuple]:
    """Recover the bump of a bump-fractal IFS (Goldman §8.5): the images of the unit segment
    must chain from (0, 0) to (1, 0), each map traversing its segment forwards or backwards.

    system: an IFS or list of maps.  Returns ``(bump (k+1, 2), reverse indices)``.  Raises
    ValueError if the images of the unit segment do not form a chain from (0, 0) to (1, 0).

    >>> bump, rev = bump_of(ifs_module.dragon())
    >>> bump.round(12).tolist(), rev
    ([[0.0, 0.0], [0.5, 0.5], [1.0, 0.0]], (1,))
    """
    maps = _maps_of(system)
    tol = as_tolerance(tol)
    floor = 1e-15 * max(1.0, float(np.abs(maps).max(initial=0.0)))
    if tol < floor:
        raise ValueError(f"tol must be at least {floor:.3g}: below that, float rounding alone breaks the chain of "
                         f"images of the unit segment; got {tol:g}")
    pts = [np.zeros(2)]
    rev = []
    for i, Mi in enumerate(maps):
        a, b = Mi[2, :2], Mi[0, :2] + Mi[2, :2]
        if np.hypot(*(a - pts[-1])) <= tol:
            pts.append(b)
        elif np.hypot(*(b - pts[-1])) <= tol:
            pts.append(a)
            rev.append(i)
        else:
            raise ValueError(f"maps[{i}] does not continue the chain: the image of the unit segment runs "
                             f"from ({a[0]:.4g}, {a[1]:.4g}) to ({b[0]:.4g}, {b[1]:.4g}), neither end at "
                             f"({pts[-1][0]:.4g}, {pts[-1][1]:.4g})")
    if np.hypot(*(pts[-1] - np.array([1.0, 0.0]))) > tol:
        raise ValueError(f"the chain of images of the unit segment ends at ({pts[-1][0]:.4g}, {pts[-1][1]:.4g}), "
                         f"not at (1, 0): not a bump fractal")
    return np.array(pts), tuple(rev)

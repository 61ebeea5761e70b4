"""Iterated function systems and their fractals (Goldman §6.1-6.4).

An IFS is a finite list of affine maps ``w_1, ..., w_k`` of the plane (3x3 matrices in the book's
row-vector convention of :mod:`goldman_lib.affine`: ``Q = [x y 1] @ M``, translation in the last
row).  Its attractor is the unique compact set ``A = w_1(A) ∪ ... ∪ w_k(A)`` (§6.3); with a
condensation set ``C`` it is ``A = C ∪ w_1(A) ∪ ... ∪ w_k(A)`` (§6.4).  Two algorithms draw it:

* :func:`deterministic` applies every map to the current set, level after level (§6.1): after
  ``L`` levels a start set of ``m`` points becomes ``k**L * m`` points, in blocks, so a start
  polyline stays a polyline in every copy.
* :func:`chaos_game` (the random algorithm) moves a point by a randomly chosen map, again and
  again.  Many independent points move at once (numpy), each starting at the fixed point of the
  first map, which lies on the attractor, so every point returned lies on the attractor.

§6.2 in code: the *set map* ``W(A) = w_1(A) ∪ ... ∪ w_k(A)`` is :func:`set_map`; the attractor is
its fixed point, and each map's own fixed point (:meth:`IFS.fixed_points`) lies on it.
:func:`iterate_map` iterates one transformation on a start shape (§6.1), :meth:`IFS.contraction_factors`
says whether the theorem of chapter 7 applies, and :func:`chaos_game_with_maps` also tells which
map moved each point last (which piece ``w_i(A)`` of the attractor it lies in).

Ready-made systems: :func:`sierpinski`, :func:`koch`, :func:`barnsley_fern`, :func:`dragon`,
:func:`c_curve`, :func:`tree` (with a trunk as condensation set), :func:`sierpinski_carpet`,
:func:`cantor`; :data:`STANDARD` maps their names to the constructors.

>>> pts = deterministic(sierpinski(), levels=3)
>>> pts.shape
(27, 2)

Importing this module imports numpy only.
"""

from __future__ import annotations

import math

import numpy as np

from . import affine
from .kernels import iteration
from .validation import (MAX_ITEMS, MAX_ITERATIONS, as_float, as_float_array, as_int, as_points, check_finite,
                         finite_result, within_budget)

__all__ = ["IFS", "deterministic", "deterministic_count", "chaos_game", "chaos_game_with_maps", "map_images", "set_map", "iterate_map", "UNIT_SQUARE", "MAX_POINTS", "STANDARD",
           "sierpinski", "koch", "barnsley_fern", "dragon", "c_curve", "tree", "sierpinski_carpet", "cantor",
           "grid_fractal", "ifs_from_points"]

#: The most points :func:`deterministic` or :func:`chaos_game` will produce (memory guard).
MAX_POINTS = 5_000_000

#: The unit square as a closed polyline, the default shape whose images show what each map does.
UNIT_SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]])


def _rng(rng) -> np.random.Generator:
    if isinstance(rng, np.random.Generator):
        return rng
    if rng is None or isinstance(rng, (int, np.integer)):
        if rng is not None and rng < 0:
            raise ValueError(f"rng must be a non-negative int seed (or a numpy.random.Generator, or None); got {rng}")
        return np.random.default_rng(rng)
    raise TypeError(f"rng must be a numpy.random.Generator, an int seed or None; got {type(rng).__name__}")


class IFS:
    """An iterated function system: affine maps, chaos-game probabilities, a condensation set
    (Goldman §6.1-6.4).

    maps: a sequence of 3x3 affine matrices (row-vector convention), or a ``(k, 3, 3)`` array.
    probabilities: ``(k,)`` non-negative weights for the chaos game, normalised to sum 1; by
    default proportional to each map's area factor ``|det L|`` (with a floor of 1% of the
    largest, so a map that flattens the plane is still chosen sometimes).  condensation: an
    optional ``(m, 2)`` polyline, the condensation set of §6.4 (drawn by :func:`deterministic`).

    Raises ValueError naming the map or probability that breaks a rule.

    >>> s = IFS([affine.scaling(0.5), affine.scaling(0.5, center=[1, 0])])
    >>> len(s), s.probabilities.tolist()
    (2, [0.5, 0.5])
    """

    def __init__(self, maps, probabilities=None, condensation=None, name: str = ""):
        arr = affine.as_affine(maps, "maps")
        if arr.ndim == 2:
            arr = arr[None]
        if arr.ndim != 3 or len(arr) == 0:
            raise ValueError(f"maps must be a non-empty list of 3x3 matrices; got shape {arr.shape}")
        self.maps = arr
        self.probabilities = self._probabilities(probabilities)
        self.condensation = None if condensation is None else as_points(condensation, "condensation", dim=2)
        self.name = str(name)

    def _probabilities(self, probabilities) -> np.ndarray:
        k = len(self.maps)
        if probabilities is None:
            with np.errstate(over="ignore", invalid="ignore"):
                area = np.abs(np.linalg.det(self.maps[:, :2, :2]))
            if not np.all(np.isfinite(area)):
                i = int(np.flatnonzero(~np.isfinite(area))[0])
                raise ValueError(f"maps[{i}] is too large: its area factor |det L| overflows a float (an IFS map "
                                 f"should shrink the plane)")
            top = area.max()
            w = np.maximum(area, 0.01 * top) if top > 0 else np.ones(k)
        else:
            from .validation import as_float_array
            w = as_float_array(probabilities, "probabilities").reshape(-1)
            if w.shape != (k,):
                raise ValueError(f"probabilities must have one entry per map ({k}); got {w.size}")
            check_finite(w, "probabilities")
            if np.any(w < 0):
                i = int(np.argmax(w < 0))
                raise ValueError(f"probabilities must be non-negative; probabilities[{i}]={w[i]:g}")
            if w.sum() <= 0:
                raise ValueError("probabilities must not all be zero")
        return w / w.sum()

    def __len__(self) -> int:
        return len(self.maps)

    @property
    def linear_parts(self) -> np.ndarray:
        """``(k, 2, 2)`` linear parts of the maps."""
        return self.maps[:, :2, :2]

    @property
    def translations(self) -> np.ndarray:
        """``(k, 2)`` translations (the last rows)."""
        return self.maps[:, 2, :2]

    def fixed_points(self) -> np.ndarray:
        """``(k, 2)`` fixed points of the maps (Goldman §6.2); each lies on the attractor when the
        maps are contractions.  Raises ValueError if a map has no unique fixed point."""
        return np.array([affine.fixed_point(M) for M in self.maps])

    def contraction_factors(self) -> np.ndarray:
        """``(k,)`` contraction factor of each map: the spectral norm of its linear part, the most
        it stretches any distance (Goldman §7.3.3).  A map is a contraction iff its factor is < 1.

        >>> sierpinski().contraction_factors().tolist()
        [0.5, 0.5, 0.5]
        """
        return np.linalg.svd(self.linear_parts, compute_uv=False)[:, 0]

    def is_contractive(self) -> bool:
        """True if every map is a contraction (factor < 1), so the IFS has a unique attractor.

        >>> sierpinski().is_contractive(), IFS([affine.rotation(30)]).is_contractive()
        (True, False)
        """
        return bool(np.all(self.contraction_factors() < 1.0))

    def __repr__(self) -> str:
        extra = ", with condensation" if self.condensation is not None else ""
        return f"IFS({self.name or 'unnamed'!r}, {len(self)} maps{extra})"


def as_ifs(system) -> IFS:
    """An :class:`IFS` from an IFS or a list of 3x3 affine maps (Goldman §6.1); every function of
    this module accepts either.  Raises TypeError naming ``system`` otherwise.

    >>> as_ifs([affine.scaling(0.5)])
    IFS('unnamed', 1 maps)
    """
    if isinstance(system, IFS):
        return system
    try:
        return IFS(system)
    except (TypeError, ValueError) as exc:
        raise TypeError(f"system must be an IFS or a list of 3x3 affine maps ({exc})") from exc


def deterministic(system, levels, start=None) -> np.ndarray:
    """The deterministic algorithm: apply every map of the IFS to the set, ``levels`` times (Goldman §6.1, §6.3).

    system: an :class:`IFS` (or a list of maps).  levels: int >= 0.  start: ``(m, 2)`` points, by
    default the fixed point of the first map (a point of the attractor, so every point returned is
    on the attractor).  Without a condensation set the result is ``W^levels(start)``: ``k**levels
    * m`` points, in blocks of ``m`` (``result.reshape(-1, m, 2)`` gives the copies of a start
    polyline; the copy ``w_{i_L}(...w_{i_1}(start))`` is block number ``i_L i_{L-1} ... i_1`` read
    in base k, so the copies of a curve's pieces come in order along the curve).  With a condensation set ``C`` (§6.4) it is ``A_levels`` where ``A_0 = start`` (or
    ``C``) and ``A_{n+1} = C ∪ W(A_n)``, with ``C``'s copies again in blocks of ``len(C)``.

    Raises ValueError naming ``levels`` if the result would exceed :data:`MAX_POINTS` points or
    the points computed on the way (all levels) :data:`goldman_lib.validation.MAX_ITEMS` (so
    ``levels <= 14`` for the Sierpinski gasket from one point, ``<= 22`` with two maps, and at most
    :data:`goldman_lib.validation.MAX_ITERATIONS` for one map), and naming ``system`` if the points
    overflow (the maps expand).

    >>> deterministic(IFS([affine.scaling(0.5), affine.scaling(0.5, center=[1, 0])]), 2, start=[[0, 0], [1, 0]])
    array([[0.  , 0.  ],
           [0.25, 0.  ],
           [0.25, 0.  ],
           [0.5 , 0.  ],
           [0.5 , 0.  ],
           [0.75, 0.  ],
           [0.75, 0.  ],
           [1.  , 0.  ]])
    """
    s = as_ifs(system)
    C = s.condensation
    if start is None:
        pts = C if C is not None else s.fixed_points()[:1]
    else:
        pts = as_points(start, "start", dim=2)
    levels = _levels(levels, len(s), len(pts), 0 if C is None else len(C))
    L, t = s.linear_parts, s.translations
    with np.errstate(over="ignore", invalid="ignore"):
        for level in range(levels):
            pts = iteration.apply_affine_maps(pts, L, t)
            if C is not None:
                pts = np.concatenate([C, pts])
            if not np.isfinite(pts).all():
                raise ValueError(f"system: the points overflow at level {level + 1} (the maps expand the plane; an "
                                 f"IFS's maps should be contractions)")
    return pts


def deterministic_count(levels: int, k: int, m: int, condensation: int = 0) -> int:
    """How many points :func:`deterministic` returns (Goldman §6.1, §6.4): ``m k^levels`` for ``k``
    maps and ``m`` start points, plus ``c (1 + k + ... + k^(levels-1))`` copies of a condensation
    set of ``c = condensation`` points.  (From the condensation set itself, ``m = c``.)

    levels: 0..10,000 (the count is an exact Python int; larger levels are refused by name).

    >>> deterministic_count(3, 3, 1), deterministic_count(2, 2, 4, condensation=4)
    (27, 28)
    """
    levels = as_int(levels, "levels", minimum=0, maximum=10_000)
    k = as_int(k, "k", minimum=1, maximum=10_000)
    m = as_int(m, "m", minimum=0)
    c = as_int(condensation, "condensation", minimum=0)
    return m * k ** levels + c * (k ** levels - 1) // (k - 1) if k > 1 else m + c * levels


def _size(levels: int, k: int, m: int, c: int = 0) -> int:
    """:func:`deterministic_count` without the checks (the budget probes it at large levels)."""
    return m * k ** levels + c * (k ** levels - 1) // (k - 1) if k > 1 else m + c * levels


def _work(level: int, k: int, m: int, c: int) -> int:
    """Points computed by all of levels 1..level, ``sum(_size(j) for j in 1..level)``, in closed form."""
    if k == 1:
        return m * level + c * level * (level + 1) // 2
    geo = (k ** (level + 1) - k) // (k - 1)          # k + k^2 + ... + k^level
    return m * geo + c * (geo - level) // (k - 1)     # sum_j (k^j - 1)/(k - 1)


def _levels(levels, k: int, m: int, c: int) -> int:
    """``levels`` checked against the points of the result (MAX_POINTS) and of all the levels on
    the way (MAX_ITEMS), before anything is computed."""
    levels = within_budget(levels, "levels", cost=lambda v: _size(v, k, m, c), what="the deterministic algorithm",
                           limit=MAX_POINTS)
    return within_budget(levels, "levels", cost=lambda v: _work(v, k, m, c) if v <= MAX_ITERATIONS else MAX_ITEMS + 1,
                         what="the deterministic algorithm (all levels together)", unit="points computed")


def chaos_game(system, n, rng=None, *, burn_in: int = 20, chains: int = 4096,
               with_condensation: bool = False) -> np.ndarray:
    """The random algorithm (chaos game) for the attractor of an IFS (Goldman §6.3).

    ``chains`` points move at once; at each step each is replaced by its image under a map
    chosen at random with the IFS's probabilities.  Every chain starts at the fixed point of the
    first map, which lies on the attractor, and the first ``burn_in`` steps are discarded as well,
    so every point returned lies on the attractor (up to rounding).  The condensation set, if
    any, is not used unless ``with_condensation`` (§6.4): then at each step a point jumps, with
    probability ``1/(k+1)``, to a random point of the condensation polyline ``C`` instead; since
    ``C`` lies in the attractor ``A = C ∪ W(A)``, every point still lies on it.

    system: an :class:`IFS`.  n: number of points (1 <= n <= MAX_POINTS).  rng: a
    ``numpy.random.Generator``, an int seed or None.  burn_in: steps discarded, >= 0, with the
    steps in all, ``burn_in + ceil(n / chains)``, at most :data:`goldman_lib.validation.MAX_ITERATIONS`
    and the map choices drawn, ``(burn_in + ceil(n / chains)) * chains``, at most
    :data:`goldman_lib.validation.MAX_ITEMS` (about ``burn_in <= 1,200`` at the default ``chains``
    and ``n`` = 5,000,000).  chains >= 1 (at most ``n`` are used).  Returns ``(n, 2)``.
    Raises ValueError if the points escape to infinity (the maps are not contractive).

    >>> chaos_game(sierpinski(), 4, rng=0).shape
    (4, 2)
    """
    pts, _ = chaos_game_with_maps(system, n, rng, burn_in=burn_in, chains=chains,
                                  with_condensation=with_condensation)
    return pts


def chaos_game_with_maps(system, n, rng=None, *, burn_in: int = 20, chains: int = 4096,
                         with_condensation: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The chaos game (Goldman §6.3), also returning which map moved each point last.

    Same arguments and points as :func:`chaos_game`.  Returns ``(points (n, 2), maps (n,))``:
    ``maps[j] = i`` means point ``j`` is ``w_i`` of a point of the attractor, so it lies in the
    piece ``w_i(A)`` (``i = k`` marks a point of the condensation set).  Colouring by ``maps``
    shows the attractor as the union of its images, ``A = w_1(A) ∪ ... ∪ w_k(A)``.

    >>> pts, maps = chaos_game_with_maps(sierpinski(), 1000, rng=1)
    >>> bool(np.all(pts[maps == 0] <= 0.5 + 1e-12))   # w_0(A) is the lower-left half-size copy
    True
    """
    s = as_ifs(system)
    n = as_int(n, "n", minimum=1, maximum=MAX_POINTS)
    chains = min(as_int(chains, "chains", minimum=1), n)
    steps = -(-n // chains)
    burn_in = within_budget(burn_in, "burn_in", cost=lambda v: v + steps, what="the chaos game",
                            unit="steps", limit=MAX_ITERATIONS)
    burn_in = within_budget(burn_in, "burn_in", cost=lambda v: (v + steps) * chains,
                            what=f"the chaos game with {chains:,} chains", unit="map choices")
    gen = _rng(rng)
    k = len(s)
    try:
        start = affine.fixed_point(s.maps[0])
    except ValueError:
        start = np.zeros(2)
    L, t = s.linear_parts, s.translations
    coef = np.stack([L[:, 0, 0], L[:, 1, 0], t[:, 0], L[:, 0, 1], L[:, 1, 1], t[:, 1]])   # a, c, e, b, d, f
    C = s.condensation if with_condensation else None
    jump_to = None
    if C is None:
        idx = iteration.choose(gen, s.probabilities, (burn_in + steps, chains))
    else:
        p = np.append(s.probabilities * k / (k + 1), 1.0 / (k + 1))
        idx = iteration.choose(gen, p, (burn_in + steps, chains))
        # the "condensation map" k sends a point to a uniformly random point of the polyline C
        jump_to = _sample_polyline(C, (burn_in + steps, chains), gen)
        coef = np.concatenate([coef, np.zeros((6, 1))], axis=1)
    out = np.empty((steps, chains, 2))
    iteration.chaos_steps(coef, idx, start, burn_in, out, jump_to)
    pts = out.reshape(-1, 2)[:n]
    # without jumps a chain that leaves the finite numbers never comes back (inf * 0 and inf - inf are
    # NaN), so the last `chains` points, one per chain, are finite exactly when all are
    if not np.all(np.isfinite(pts if C is not None else pts[-chains:])):
        raise ValueError("the chaos game's points escaped to infinity: the maps must be contractions "
                         "(every map shrinks distances)")
    return pts, idx[burn_in:].reshape(-1)[:n]


def _sample_polyline(C: np.ndarray, shape, gen: np.random.Generator) -> np.ndarray:
    """Uniform random points on the polyline ``C`` (by arc length; a single point if C is one)."""
    if len(C) == 1:
        return np.broadcast_to(C[0], tuple(shape) + (2,))
    seg = np.linalg.norm(np.diff(C, axis=0), axis=1)
    total = seg.sum()
    if total == 0:
        return np.broadcast_to(C[0], tuple(shape) + (2,))
    cum = np.concatenate([[0.0], np.cumsum(seg)])
    u = gen.random(shape) * total
    j = np.clip(np.searchsorted(cum, u, side="right") - 1, 0, len(seg) - 1)
    frac = np.where(seg[j] > 0, (u - cum[j]) / np.where(seg[j] > 0, seg[j], 1.0), 0.0)
    return C[j] + frac[..., None] * (C[j + 1] - C[j])


def set_map(system, points) -> np.ndarray:
    """One application of the set map ``W(A) = w_1(A) ∪ ... ∪ w_k(A)`` (Goldman §6.2), or
    ``C ∪ W(A)`` with a condensation set ``C`` (§6.4).

    The attractor is the fixed point of ``W``: ``W(A) = A``.  points: ``(m, 2)``, a finite sample
    of a set.  Returns ``(k*m, 2)`` (after ``len(C)`` condensation points if any), the copies in
    blocks of ``m``, map by map.  Equivalent to ``deterministic(system, 1, start=points)``.

    >>> set_map(cantor(), [[0, 0], [1, 0]]).tolist()
    [[0.0, 0.0], [0.3333333333333333, 0.0], [0.6666666666666667, 0.0], [1.0, 0.0]]
    """
    return deterministic(system, 1, start=as_points(points, "points", dim=2))


def iterate_map(M, shape, n) -> np.ndarray:
    """Iterate one affine transformation on a start shape (Goldman §6.1): ``shape, M(shape),
    M(M(shape)), ...``, ``n + 1`` shapes in all.

    M: 3x3 affine matrix.  shape: ``(m, 2)`` points.  n: 0 <= n <= 100,000, with the ``(n + 1) m``
    points of the result at most :data:`goldman_lib.validation.MAX_ITEMS`.  Returns
    ``(n + 1, m, 2)``.  For a contraction the shapes shrink towards the map's fixed point; a map
    that expands so much that the points overflow is a ValueError naming ``M``.

    >>> iterate_map(affine.scaling(0.5, center=[2, 0]), [[0, 0]], 3)[:, 0].tolist()
    [[0.0, 0.0], [1.0, 0.0], [1.5, 0.0], [1.75, 0.0]]
    """
    M = affine.as_affine(M)
    if M.ndim != 2:
        raise ValueError(f"M must be one 3x3 matrix; got shape {M.shape}")
    P = as_points(shape, "shape", dim=2)
    n = as_int(n, "n", minimum=0, maximum=100_000)
    n = within_budget(n, "n", cost=lambda v: (v + 1) * len(P), what="the iterated shapes")
    out = np.empty((n + 1,) + P.shape)
    out[0] = P
    L, t = M[:2, :2], M[2, :2]
    with np.errstate(over="ignore", invalid="ignore"):
        for j in range(n):
            out[j + 1] = out[j] @ L + t
    if not np.isfinite(out).all():
        j = int(np.flatnonzero(~np.isfinite(out).reshape(n + 1, -1).all(axis=1))[0])
        raise ValueError(f"M expands the shape so much that its points overflow after {j} iterations; use fewer "
                         f"iterations or a map that shrinks")
    return out


def map_images(system, shape=None) -> np.ndarray:
    """The image of a shape under each map of the IFS: ``(k, m, 2)`` (Goldman §6.1).

    shape: ``(m, 2)`` polyline, default :data:`UNIT_SQUARE`; the images show at a glance how each
    map moves, turns, shears and shrinks the plane.

    >>> map_images(IFS([affine.scaling(0.5)]))[0, 2]
    array([0.5, 0.5])
    """
    s = as_ifs(system)
    P = UNIT_SQUARE if shape is None else as_points(shape, "shape", dim=2)
    return iteration.apply_affine_maps(P, s.linear_parts, s.translations).reshape(len(s), len(P), 2)


def ifs_from_points(reference, images, probabilities=None, name: str = "") -> IFS:
    """An IFS designed by choosing, for each map, the images of three points (Goldman §4.7.3 and
    the fractal strategy of §7.3.3): map ``i`` is the unique affine map sending the reference
    triangle ``reference`` to the triangle ``images[i]``
    (:func:`goldman_lib.affine.affine_from_points`).

    The strategy: to get a fractal made of smaller copies of itself, draw the copies as triangles
    inside the reference triangle, one per piece, with corresponding corners in the same order
    (the order decides the rotation and whether a copy is mirrored).  If each image triangle is
    smaller than the reference in every direction, every map contracts and the attractor is the
    fractal whose pieces are those copies.

    reference: ``(3, 2)`` non-collinear points.  images: ``(k, 3, 2)``, k >= 1.  probabilities,
    name: as for :class:`IFS`.  Raises ValueError for collinear reference points or a wrong shape.

    >>> half = [[0, 0], [1, 0], [0, 1]]
    >>> s = ifs_from_points(half, [[[0, 0], [0.5, 0], [0, 0.5]], [[0.5, 0], [1, 0], [0.5, 0.5]],
    ...                            [[0, 0.5], [0.5, 0.5], [0, 1]]])
    >>> [m.round(12).tolist() for m in s.maps[1:2]]
    [[[0.5, 0.0, 0.0], [0.0, 0.5, 0.0], [0.5, 0.0, 1.0]]]
    """
    R = as_points(reference, "reference", dim=2)
    if R.shape != (3, 2):
        raise ValueError(f"reference must be three 2D points, shape (3, 2); got {R.shape}")
    Q = check_finite(as_float_array(images, "images"), "images")
    if Q.ndim != 3 or Q.shape[1:] != (3, 2) or len(Q) == 0:
        raise ValueError(f"images must hold one triangle per map, shape (k, 3, 2) with k >= 1; got {Q.shape}")
    try:
        maps = [affine.affine_from_points(R, T) for T in Q]
    except ValueError as exc:
        raise ValueError(f"reference: {exc}") from None
    try:
        return IFS(maps, probabilities, name=name)
    except ValueError as exc:
        if "maps[" in str(exc):
            raise ValueError(f"images: {exc}") from None
        raise
    return IFS(maps, probabilities, name=name)


# -- the standard systems --------------------------------------------------------------------------

def sierpinski() -> IFS:
    """The Sierpinski gasket (Goldman §6.1): three maps scaling by 1/2 about the corners of an
    equilateral triangle with vertices (0, 0), (1, 0), (1/2, sqrt(3)/2).

    >>> deterministic(sierpinski(), 1).round(3).tolist()
    [[0.0, 0.0], [0.5, 0.0], [0.25, 0.433]]
    """
    corners = [(0.0, 0.0), (1.0, 0.0), (0.5, math.sqrt(3) / 2)]
    return IFS([affine.scaling(0.5, center=c) for c in corners], name="Sierpinski gasket")


def koch() -> IFS:
    """The Koch curve from (0, 0) to (1, 0) (Goldman §6.1): four similarities with ratio 1/3.

    >>> len(koch()), deterministic(koch(), 0, start=[[0, 0], [1, 0]]).tolist()
    (4, [[0.0, 0.0], [1.0, 0.0]])
    """
    third = 1.0 / 3.0
    peak = (0.5, math.sqrt(3) / 6)
    maps = [affine.similarity(third, 0),
            affine.similarity(third, 60, (third, 0.0)),
            affine.similarity(third, -60, peak),
            affine.similarity(third, 0, (2 * third, 0.0))]
    return IFS(maps, name="Koch curve")


def barnsley_fern() -> IFS:
    """Barnsley's fern (Goldman §6.3) with its classic probabilities 0.01, 0.85, 0.07, 0.07.

    The classic coefficients act on column vectors, ``(x, y) -> A (x, y) + b``; in the row-vector
    convention the linear part is ``A`` transposed.

    >>> barnsley_fern().probabilities.tolist()
    [0.01, 0.85, 0.07, 0.07]
    """
    coeffs = [  # a, b, c, d, e, f for x' = a x + b y + e, y' = c x + d y + f
        (0.0, 0.0, 0.0, 0.16, 0.0, 0.0),
        (0.85, 0.04, -0.04, 0.85, 0.0, 1.6),
        (0.20, -0.26, 0.23, 0.22, 0.0, 1.6),
        (-0.15, 0.28, 0.26, 0.24, 0.0, 0.44),
    ]
    maps = [np.array([[a, c, 0.0], [b, d, 0.0], [e, f, 1.0]]) for a, b, c, d, e, f in coeffs]
    return IFS(maps, probabilities=[0.01, 0.85, 0.07, 0.07], name="Barnsley fern")


def dragon() -> IFS:
    """Heighway's dragon from (0, 0) to (1, 0) (Goldman §6.1): two similarities with ratio
    1/sqrt(2), turning by 45 and 135 degrees: ``z -> (1+i) z / 2`` and ``z -> 1 - (1-i) z / 2``.
    The two halves meet at (1/2, 1/2); the second map's fixed point is (3/5, 1/5).

    >>> dragon().fixed_points().round(12).tolist()
    [[0.0, 0.0], [0.6, 0.2]]
    """
    r = 1.0 / math.sqrt(2)
    return IFS([affine.similarity(r, 45), affine.similarity(r, 135, (1.0, 0.0))], name="dragon")


def c_curve() -> IFS:
    """Lévy's C-curve from (0, 0) to (1, 0) (Goldman §6.1): two similarities with ratio
    1/sqrt(2), turning by +45 and -45 degrees.

    >>> c_curve().fixed_points().round(12).tolist()
    [[0.0, 0.0], [1.0, 0.0]]
    """
    r = 1.0 / math.sqrt(2)
    return IFS([affine.similarity(r, 45), affine.similarity(r, -45, (0.5, 0.5))], name="C-curve")


def tree(angle: float = 30.0, ratio: float = 0.6) -> IFS:
    """A fractal tree (Goldman §6.4): a trunk from (0, 0) to (0, 1) as condensation set and two
    maps that shrink by ``ratio`` and turn by ``±angle`` degrees onto the top of the trunk.
    angle: finite degrees; ratio in (0, 1) (the maps must shrink).  Raises ValueError naming the
    parameter.

    >>> t = tree(); t.condensation.tolist(), len(t)
    ([[0.0, 0.0], [0.0, 1.0]], 2)
    """
    angle = as_float(angle, "angle")
    ratio = as_float(ratio, "ratio")
    if not 0 < ratio < 1:
        raise ValueError(f"ratio must lie in (0, 1) (the tree's maps must shrink); got {ratio}")
    trunk = np.array([[0.0, 0.0], [0.0, 1.0]])
    return IFS([affine.similarity(ratio, angle, (0.0, 1.0)), affine.similarity(ratio, -angle, (0.0, 1.0))],
               condensation=trunk, name="fractal tree")


def sierpinski_carpet() -> IFS:
    """The Sierpinski carpet: eight maps scaling the unit square by 1/3 onto its border cells.

    >>> len(sierpinski_carpet())
    8
    """
    cells = [(i, j) for i in range(3) for j in range(3) if (i, j) != (1, 1)]
    return IFS([affine.scaling(1 / 3) @ affine.translation([i / 3, j / 3]) for i, j in cells],
               name="Sierpinski carpet")


def cantor() -> IFS:
    """The Cantor set on [0, 1] (two maps scaling by 1/3 about 0 and about 1).

    >>> deterministic(cantor(), 1, start=[[0, 0], [1, 0]]).tolist()
    [[0.0, 0.0], [0.3333333333333333, 0.0], [0.6666666666666667, 0.0], [1.0, 0.0]]
    """
    return IFS([affine.scaling(1 / 3), affine.scaling(1 / 3, center=[1, 0])], name="Cantor set")


#: Name -> constructor of every ready-made system (the IFS editor's presets).
STANDARD = {
    "Sierpinski gasket": sierpinski,
    "Koch curve": koch,
    "Barnsley fern": barnsley_fern,
    "dragon": dragon,
    "C-curve": c_curve,
    "fractal tree": tree,
    "Sierpinski carpet": sierpinski_carpet,
    "Cantor set": cantor,
}


def grid_fractal(cells, corner=(0.0, 0.0), side=1.0, name: str = "") -> IFS:
    """A "grid fractal" (Goldman §6.3): cut a square into 3 x 3 cells and keep some of them.

    The map for the kept cell ``(i, j)`` (column ``i``, row ``j``, both in 0..2, counted from the
    lower-left corner) scales the square by 1/3 about its lower-left ``corner`` and then
    translates by ``(i, j) * side / 3``, so it sends the square onto that cell.  All eight border
    cells give the Sierpinski carpet, the four corners and the centre the Vicsek "box" fractal.

    cells: ``(k, 2)`` integer pairs in 0..2.  corner: ``(2,)``.  side: > 0.  Returns an
    :class:`IFS` of ``k`` maps, in the order of ``cells``.  Raises ValueError naming the
    parameter that breaks a rule.

    >>> box = grid_fractal([(0, 0), (2, 0), (1, 1), (0, 2), (2, 2)], corner=(1, 0), side=3)
    >>> deterministic(box, 1, start=[[1, 0]]).round(12).tolist()
    [[1.0, 0.0], [3.0, 0.0], [2.0, 1.0], [1.0, 2.0], [3.0, 2.0]]
    """
    as_float_array(cells, "cells")  # numeric, not ragged
    C = np.array(cells)
    if C.ndim != 2 or C.shape[1:] != (2,) or len(C) == 0:
        raise ValueError(f"cells must be a non-empty list of (i, j) pairs; got shape {C.shape}")
    if not np.issubdtype(C.dtype, np.integer) or C.min() < 0 or C.max() > 2:
        raise ValueError(f"cells must hold whole numbers 0, 1 or 2 (column i, row j); got {C.tolist()}")
    P = as_points(corner, "corner", ndim=1, dim=2)
    a = as_float(side, "side")
    if a <= 0:
        raise ValueError(f"side must be a positive number; got {side!r}")
    with np.errstate(over="ignore", invalid="ignore"):
        moves = [finite_result(np.array([i, j]) * a / 3.0, "side") for i, j in C.tolist()]
    shrink = affine.scaling(1.0 / 3.0, center=P)
    return IFS([shrink @ affine.translation(v) for v in moves], name=name or "grid fractal")

"""Recursive ray tracing (Goldman chapter 17), vectorised over rays.

A ray leaves the eye through each pixel (§17.2).  Where it first meets an object the tracer adds

* the **local** light of the point, by :func:`goldman_lib.lighting.intensity` (the one lighting
  model: ambient, Lambert diffuse and Phong specular), where each light counts by what its
  **shadow ray** from the point lets through (§17.3): all of it if the ray meets no object, ``k_t``
  for each transparent object it passes, none past an opaque one;
* ``k_r`` times the light arriving along the **reflected** ray ``reflected_direction(-d, N)`` (§17.4), the
  mirror image of the incoming direction about the normal, traced recursively;
* ``k_t`` times the light arriving along the **refracted** (transmitted) ray, bent by Snell's law
  ``n1 sin(theta1) = n2 sin(theta2)`` (§17.5); past the critical angle there is no refracted ray
  (total internal reflection) and that light goes along the reflected ray instead.

``I = I_local + k_r I_reflected + k_t I_refracted`` with ``k_r = material.reflect`` and
``k_t = material.transmit`` (:class:`goldman_lib.lighting.Material`).  The recursion stops at a
given depth (a depth-0 tracer is a ray caster with shadows).  The recursion is run level by level:
all the rays of one level (every pixel's reflected and refracted rays together) are one array, so
each level costs a few numpy calls per object, not a Python loop per ray.

Conventions: the scene's objects follow the :mod:`goldman_lib.simple_surfaces` contract (``.hit(o,
d) -> (t, normals)`` with outward normals for solids, and ``.material``).  A ray is entering an object
where ``d . N < 0`` (it goes from the outside medium, index 1, into the object's ``index``) and
leaving where ``d . N > 0``.  A shadow ray is not refracted: by default (``Scene(...,
shadow_transmission=True)``, Whitted's simple model of 1980) each transparent object it passes
multiplies the light by its transmission coefficient ``k_t``, and an opaque object (``k_t = 0``) stops
it; with ``shadow_transmission=False`` every object casts a full shadow.  Angles are in degrees.  The camera is
:class:`goldman_lib.camera.Camera`, a pinhole with a vertical field of view, the one place where a
pixel becomes a ray; pixel ``(px, py)`` counts columns from the left and rows from the top, as an
image does.  The image size is the camera's (``width``/``height`` of :func:`render`, :func:`ray_cast`
and :func:`ray_tree` override it; :func:`default_camera` is 160 x 120).

>>> scene, camera = default_scene(), default_camera()
>>> image = render(scene, camera, 32, 24, depth=2)
>>> image.shape, bool(image.min() >= 0 and image.max() <= 1)
((24, 32, 3), True)
>>> [round(v, 4) for v in refract([1, 0, -1], [0, 0, 1], 1.0, 1.5)]     # into glass at 45 degrees
[0.4714, 0.0, -0.8819]
"""

from __future__ import annotations

import dataclasses
import math
from typing import NamedTuple

import numpy as np

from goldman_lib import lighting
from goldman_lib.camera import Camera, image_size
from goldman_lib.lighting import Light, Material
from goldman_lib.simple_surfaces import MAX_COORDINATE, Plane, Sphere, rays
from goldman_lib.kernels import frames, illumination
from goldman_lib.kernels.frames import norm as _norm
from goldman_lib.validation import MAX_ITEMS, as_float, as_float_array, as_int, as_points, check_finite

__all__ = ["Scene", "RaySegment", "refract", "refract_rays", "critical_angle", "ray_tree_size",
           "trace", "render", "ray_tree", "in_shadow", "light_fraction", "default_scene", "default_camera", "default_lights", "MAX_DEPTH",
           "OFFSET", "INDEX_RANGE", "MATERIALS", "MAX_SAMPLES", "BANDS", "ray_cast", "PRECISIONS", "INDEX_RATIOS"]

#: The deepest recursion a render may ask for (a ray tree of depth d holds up to 2^(d+1) - 1 rays).
MAX_DEPTH = 12
#: Indices of refraction the tracer accepts (air 1.0003, water 1.33, glass 1.5, diamond 2.42).
INDEX_RANGE = (0.01, 100.0)
#: Secondary rays (shadow, reflected, refracted) start this far off the surface, on the side they
#: leave by, so that rounding does not make them hit the surface they start on.
OFFSET = 1e-7
#: The precisions a Scene's hit points may be rounded to before their shadow rays leave (``Scene(precision=...)``).
PRECISIONS = ("float64", "float32")
#: The ratio of indices Snell's law is given (``Scene(index_ratio=...)``): "n1/n2" is right, "n2/n1" the slip.
INDEX_RATIOS = ("n1/n2", "n2/n1")


def _unit(v, name):
    v = as_points(v, name, ndim=1, dim=3)
    length = float(_norm(v))
    if length == 0 or not np.isfinite(length):
        raise ValueError(f"{name} must be a nonzero vector of finite length; got {v.tolist()}")
    return v / length


def _dot(a, b):
    return frames.row_dots(a, b)


# -- the scene ---------------------------------------------------------------------------------------

class Scene:
    """What a ray tracer draws (Goldman §17.2): ``objects`` (each with ``.hit(origins, directions) ->
    (t, normals)`` and a ``.material``, as in :mod:`goldman_lib.simple_surfaces`), point ``lights``
    (:class:`goldman_lib.lighting.Light`), the ambient intensity ``I_a`` (a number or RGB triple)
    and the ``background`` colour a ray that hits nothing sees.
    shadow_transmission: True (the default) lets a shadow ray pass transparent objects, each
    multiplying the light by its ``material.transmit`` (Whitted 1980: attenuated, not refracted); False
    makes every object cast a full shadow, as an opaque one does.

    Three switches take a safeguard away, to show what it prevents (each default is the safe one):

    * shadow_offset (§17.3, shadow acne): None (the default) starts secondary rays :data:`OFFSET` off
      the surface on the side they leave by, and does not test a shadow ray against the surface it
      leaves where that surface cannot block it (a plane, or a sphere seen from outside: exact, so
      no rounding can make a point shadow itself).  A number ``>= 0`` is the classic safeguard alone:
      the rays start that far off the surface and a shadow ray is tested against every object, its
      own surface included.  A point rounded to just inside its surface then finds that surface
      between it and the light unless the offset exceeds the rounding error: speckled self-shadowing,
      "shadow acne".
    * precision (§17.3): "float64" (the default) or "float32": each hit point is rounded to single
      precision (a GPU's arithmetic) before its shadow and reflected rays leave, an error about
      1e-7 times the coordinates, where float64's (1e-16) hides under the intersection tolerance
      ``t > EPS`` of :mod:`goldman_lib.simple_surfaces` (why ``OFFSET = 0`` alone changes nothing).
    * index_ratio (§17.5): "n1/n2" (the default, Snell's law ``sin(theta2) = (n1 / n2) sin(theta1)``)
      or "n2/n1", the ratio upside down: a ray entering glass then bends away from the normal, as if
      the glass were thinner than the air, and past ``arcsin(n1 / n2)`` it cannot enter at all.

    >>> s = Scene([Sphere((0, 0, 0), 1)], [Light((0, 0, 5))], ambient_light=0.3)
    >>> len(s.objects), s.background.tolist(), s.shadow_transmission
    (1, [0.0, 0.0, 0.0], True)
    """

    def __init__(self, objects, lights, ambient_light=0.2, background=(0.0, 0.0, 0.0),
                 shadow_transmission: bool = True, *, shadow_offset=None, precision: str = "float64",
                 index_ratio: str = "n1/n2"):
        try:
            objects = tuple(objects)
        except TypeError:
            raise TypeError(f"objects must be a sequence of surfaces; got {type(objects).__name__}") from None
        for k, obj in enumerate(objects):
            if not callable(getattr(obj, "hit", None)) or not isinstance(getattr(obj, "material", None), Material):
                raise TypeError(f"objects[{k}] must have a .hit(origins, directions) method and a "
                                f"goldman_lib.lighting.Material as .material (a simple surface or a CSG solid); "
                                f"got {type(obj).__name__}")
        if isinstance(lights, Light):
            lights = (lights,)
        try:
            lights = tuple(lights)
        except TypeError:
            raise TypeError(f"lights must be a sequence of goldman_lib.lighting.Light; got {type(lights).__name__}") from None
        if not all(isinstance(light, Light) for light in lights):
            raise TypeError("lights must be a sequence of goldman_lib.lighting.Light")
        for k, obj in enumerate(objects):
            _index(obj.material.index, f"objects[{k}].material.index")
        for k, light in enumerate(lights):
            if np.abs(light.position).max() > MAX_COORDINATE:
                raise ValueError(f"lights[{k}].position must have coordinates at most {MAX_COORDINATE:g} in magnitude "
                                 f"(its shadow rays' directions must square without overflow); got "
                                 f"{np.abs(light.position).max():g}")
        self.objects = objects
        self.lights = lights
        a = check_finite(as_float_array(ambient_light, "ambient_light"), "ambient_light")
        if a.shape not in ((), (3,)) or np.any(a < 0):
            raise ValueError(f"ambient_light must be a number >= 0 or an RGB triple of them; got {a.tolist()}")
        self.ambient_light = a
        b = check_finite(as_float_array(background, "background"), "background")
        if b.shape != (3,) or np.any(b < 0) or np.any(b > 1):
            raise ValueError(f"background must be an RGB triple in [0, 1]; got {b.tolist()}")
        self.background = b
        if not isinstance(shadow_transmission, (bool, np.bool_)):
            raise TypeError(f"shadow_transmission must be True or False; got {type(shadow_transmission).__name__}")
        self.shadow_transmission = bool(shadow_transmission)
        if shadow_offset is not None:
            shadow_offset = as_float(shadow_offset, "shadow_offset")
            if not 0 <= shadow_offset <= 1:
                raise ValueError(f"shadow_offset must be None (the safe default) or a distance in [0, 1]; "
                                 f"got {shadow_offset}")
        self.shadow_offset = shadow_offset
        for name, value, allowed in (("precision", precision, PRECISIONS), ("index_ratio", index_ratio, INDEX_RATIOS)):
            if not isinstance(value, str) or value not in allowed:
                raise ValueError(f"{name} must be one of {', '.join(map(repr, allowed))}; got {value!r}")
        self.precision = precision
        self.index_ratio = index_ratio

    def _offset(self) -> tuple[float, bool]:
        """(how far secondary rays start off the surface, whether a shadow ray skips the surface it
        leaves where that surface cannot block it)."""
        return (OFFSET, True) if self.shadow_offset is None else (self.shadow_offset, False)

    def _leave(self, P):
        """Hit points as the scene's precision holds them before secondary rays leave."""
        return P.astype(np.float32).astype(float) if self.precision == "float32" else P


# -- refraction (§17.5) ------------------------------------------------------------------------------

def _index(value, name):
    arr = check_finite(as_float_array(value, name), name)
    lo, hi = INDEX_RANGE
    if np.any(arr < lo) or np.any(arr > hi):
        raise ValueError(f"{name} must lie in [{lo:g}, {hi:g}] (an index of refraction); got {arr.tolist()}")
    return arr


def refract_rays(directions, normals, n1, n2) -> tuple[np.ndarray, np.ndarray]:
    """Snell's law for many rays at once (Goldman §17.5): the unit refracted directions ``(N, 3)``
    and a boolean ``(N,)``, True where the ray is totally internally reflected (its row is then 0).

    directions, normals: (N, 3) (need not be unit; each normal is turned to face the incoming ray,
    so either side of the surface may be given).  n1: the index of the medium the ray comes from;
    n2: the index of the medium it enters; each a number or (N,) in :data:`INDEX_RANGE`.  With ``d`` and ``N`` unit,
    ``N . d < 0``, ``eta = n1 / n2`` and ``cos1 = -N . d``: ``sin^2(theta2) = eta^2 (1 - cos1^2)``;
    if it exceeds 1 the ray is totally reflected, otherwise
    ``T = eta d + (eta cos1 - cos2) N`` with ``cos2 = sqrt(1 - sin^2(theta2))``.

    >>> T, tir = refract_rays([[1, 0, -1], [1, 0, -3]], [[0, 0, 1], [0, 0, 1]], 1.5, 1.0)
    >>> tir.tolist()              # glass to air: 45 deg is past the critical 41.8 deg, 18.4 deg is not
    [True, False]
    >>> refract_rays([[0, 0, -1]], [[0, 0, 1]], 1.0, 1.33)[0].tolist()   # head on: no bending
    [[0.0, 0.0, -1.0]]
    """
    d = lighting.unit_rows(as_points(directions, "directions", dim=3), "directions")
    N = lighting.unit_rows(as_points(normals, "normals", dim=3), "normals")
    if N.shape != d.shape:
        raise ValueError(f"normals must have the shape of directions {d.shape}; got {N.shape}")
    if not np.all(np.any(d != 0, axis=1)):
        raise ValueError("directions must be nonzero vectors")
    if not np.all(np.any(N != 0, axis=1)):
        raise ValueError("normals must be nonzero vectors")
    indices = []
    for value, name in ((n1, "n1"), (n2, "n2")):
        arr = _index(value, name)
        if arr.shape not in ((), (len(d),)):
            raise ValueError(f"{name} must be a number or one per ray ({len(d)},); got shape {arr.shape}")
        indices.append(arr)
    return _refract(d, N, indices[0] / indices[1])


def _refract(d, N, eta):
    """Unchecked Snell's law: unit ``d``, unit ``N`` (any side), ``eta = n1/n2`` (scalar or (N,))."""
    facing = _dot(d, N)
    N = np.where((facing > 0)[:, None], -N, N)
    cos1 = np.abs(facing)
    eta = np.broadcast_to(eta, cos1.shape)
    sin2 = eta * eta * np.maximum(1.0 - cos1 * cos1, 0.0)
    tir = sin2 > 1.0
    cos2 = np.sqrt(np.maximum(1.0 - sin2, 0.0))
    T = eta[:, None] * d + (eta * cos1 - cos2)[:, None] * N
    T = frames.unit_rows(T)
    T[tir] = 0.0
    return T, tir


def refract(direction, normal, n1, n2):
    """The unit refracted direction of one ray by Snell's law (Goldman §17.5), or ``None`` on total
    internal reflection.

    direction, normal: (3,) (any length; the normal may face either side).  n1: the index of
    refraction of the medium the ray leaves, n2: of the medium it enters (both in :data:`INDEX_RANGE`).
    ``n1 sin(theta1) = n2 sin(theta2)``, the angles measured from the normal.

    >>> [round(v, 6) for v in refract([1, 0, -1], [0, 0, 1], 1.0, 1.0)]   # same medium: straight on
    [0.707107, 0.0, -0.707107]
    >>> refract([1, 0, -0.5], [0, 0, 1], 1.5, 1.0) is None                 # 63 deg in glass: TIR
    True
    """
    d = as_points(direction, "direction", ndim=1, dim=3)
    N = as_points(normal, "normal", ndim=1, dim=3)
    n1 = float(_index(as_float(n1, "n1"), "n1"))
    n2 = float(_index(as_float(n2, "n2"), "n2"))
    if not np.any(d != 0):
        raise ValueError("direction must be a nonzero vector")
    if not np.any(N != 0):
        raise ValueError("normal must be a nonzero vector")
    with np.errstate(over="ignore", invalid="ignore"):
        T, tir = refract_rays(d[None] / np.abs(d).max(), N[None] / np.abs(N).max(), n1, n2)
    if tir[0]:
        return None
    return [float(v) for v in T[0]]


def critical_angle(n1, n2):
    """The critical angle in degrees, ``arcsin(n2 / n1)``, for light going from a medium of index
    ``n1`` into one of index ``n2`` (Goldman §17.5): rays meeting the surface farther than this
    from the normal are totally internally reflected.  ``None`` if ``n1 <= n2`` (every ray passes).

    >>> round(critical_angle(1.5, 1.0), 4)          # glass to air
    41.8103
    >>> critical_angle(1.0, 1.5) is None
    True
    """
    n1 = as_float(n1, "n1", positive=True)
    n2 = as_float(n2, "n2", positive=True)
    if n1 <= n2:
        return None
    return math.degrees(math.asin(n2 / n1))


def ray_tree_size(depth: int, lights: int = 0) -> int:
    """The most rays a pixel's ray tree of recursion depth ``depth`` can hold (Goldman §17.2): each
    ray that hits spawns a reflected and a refracted ray, so ``2^(depth+1) - 1`` rays, and each of
    them that hits sends one shadow ray per light: times ``1 + lights``.

    >>> ray_tree_size(0), ray_tree_size(3), ray_tree_size(2, lights=2)
    (1, 15, 21)
    """
    depth = as_int(depth, "depth", minimum=0, maximum=MAX_DEPTH)
    lights = as_int(lights, "lights", minimum=0, maximum=1000)
    return (2 ** (depth + 1) - 1) * (1 + lights)


# -- the tracer (§17.2-17.5) -------------------------------------------------------------------------

class RaySegment(NamedTuple):
    """One segment of a ray tree (:func:`ray_tree`): ``kind`` (``"primary"``, ``"reflected"``,
    ``"refracted"`` or ``"shadow"``), ``start`` and ``end`` (3,), the recursion ``level`` (0 for the
    primary ray; a shadow ray has its parent's level), ``weight`` (the fraction of its light that
    reaches the pixel) and ``hit``: whether it ends on an object (for a shadow ray: an object lies
    between the point and the light; a ray that hits nothing ends ``miss_length`` along its
    direction).  ``light``: for a shadow ray, the fraction of the light that arrives (1 unobstructed,
    the product of the ``transmit`` of the transparent objects passed, 0 blocked); 1 for other rays."""

    kind: str
    start: np.ndarray
    end: np.ndarray
    level: int
    weight: float
    hit: bool
    light: float = 1.0


def _sized_camera(camera, width, height, depth) -> Camera:
    """``camera`` checked, at ``width`` x ``height`` where given (None: the camera's own size)."""
    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be a goldman_lib.camera.Camera; got {type(camera).__name__}")
    width, height = image_size(camera.width if width is None else width, camera.height if height is None else height)
    as_int(depth, "depth", minimum=0, maximum=MAX_DEPTH)
    # the rays the image will trace are counted level by level as they are spawned (see _trace): a
    # pixel's full binary tree of 2^(depth+1) - 1 rays is a bound few pixels come near
    if np.abs(camera.eye).max() > MAX_COORDINATE:
        raise ValueError(f"camera.eye must have coordinates at most {MAX_COORDINATE:g} in magnitude (the bound on "
                         f"ray origins: their squares must not overflow); got {np.abs(camera.eye).max():g}")
    if (width, height) == (camera.width, camera.height):
        return camera
    return dataclasses.replace(camera, width=width, height=height)


def _primary_rays(camera: Camera, width: int, height: int) -> tuple[np.ndarray, np.ndarray]:
    """The rays of ``camera`` at ``width`` x ``height`` (a supersampled image: the same view, more
    pixels), row by row from the top: origins and unit directions, each ``(height * width, 3)``."""
    eye, D = dataclasses.replace(camera, width=width, height=height).rays()
    d = D.reshape(-1, 3)
    return np.broadcast_to(eye, d.shape).copy(), d


def _bounding_sphere(obj):
    """A sphere enclosing ``obj`` (centre, radius) if it has one: ``obj.bounding_sphere()`` (the
    simple surfaces' cull, §19.6.1; None for an unbounded surface) or, for a :class:`Sphere`, itself.  Rays that miss it skip the object's own intersection test."""
    bound = getattr(obj, "bounding_sphere", None)
    if callable(bound):
        bound = bound()
    if bound is not None:
        return np.asarray(bound[0], dtype=float), float(bound[1])
    if isinstance(obj, Sphere):
        return obj.center, obj.radius
    return None


def _may_hit(bound, o, d, reach=None):
    """Which rays (unit ``d``) pass within the bounding sphere ahead of their origin (and, if
    ``reach`` is given, before parameter ``reach``): a cheap, conservative test."""
    if bound is None:
        return None
    center, radius = bound
    r = radius * (1 + 1e-6) + 1e-9
    oc = center - o
    along = _dot(oc, d)
    dist2 = _dot(oc, oc)
    near = dist2 - along * along <= r * r
    ahead = (along >= -r)
    if reach is not None:
        ahead &= along <= reach + r
    return near & ahead


def _nearest(objects, bounds, o, d):
    """Nearest hit over the objects: t (N,), index of the object (N,) (-1 on a miss), normals (N, 3)."""
    n = len(o)
    best = np.full(n, np.inf)
    which = np.full(n, -1)
    normals = np.zeros((n, 3))
    for k, obj in enumerate(objects):
        rows = _may_hit(bounds[k], o, d)
        if rows is None:
            t, nk = obj.hit(o, d)
            closer = t < best
            best[closer] = t[closer]
            which[closer] = k
            normals[closer] = nk[closer]
            continue
        rows = np.flatnonzero(rows)
        if len(rows) == 0:
            continue
        t, nk = obj.hit(o[rows], d[rows])
        closer = t < best[rows]
        idx = rows[closer]
        best[idx] = t[closer]
        which[idx] = k
        normals[idx] = nk[closer]
    return best, which, normals


def _light_fraction(objects, bounds, P, N_f, owner, entering, lights, transmission=True, skip_own=True):
    """Shadow rays (§17.3): the fraction of each light that reaches each point, (N, L), and whether
    an object lies between, (N, L) bool.  A light behind the surface (``L . N <= 0``) is blocked by
    the surface itself (fraction 0); otherwise a plane cannot shadow its own points, nor a sphere the
    points on its outside.  Each object the shadow ray meets before the light multiplies the
    fraction by its ``material.transmit`` if ``transmission`` (Whitted's attenuation: 0 for an
    opaque object), else by 0.  skip_own False: test the shadow ray against its own surface too
    (``Scene(shadow_offset=...)``)."""
    fraction = np.ones((len(P), len(lights)))
    between = np.zeros((len(P), len(lights)), dtype=bool)
    for j, light in enumerate(lights):
        to_light = np.asarray(light.position) - P
        distance = np.sqrt(_dot(to_light, to_light))
        fraction[_dot(to_light, N_f) <= 0, j] = 0.0
        unit = to_light / np.where(distance > 0, distance, 1.0)[:, None]
        for k, obj in enumerate(objects):
            test = (fraction[:, j] > 0) & (distance > 0)
            if not skip_own:
                pass
            elif isinstance(obj, Plane):
                test &= owner != k
            elif isinstance(obj, Sphere):
                test &= (owner != k) | ~entering
            near = _may_hit(bounds[k], P, unit, distance)
            if near is not None:
                test &= near
            rows = np.flatnonzero(test)
            if len(rows) == 0:
                continue
            intersect = getattr(obj, "intersect", None)
            t = intersect(P[rows], to_light[rows]) if intersect is not None else obj.hit(P[rows], to_light[rows])[0]
            crossed = rows[t < 1.0]
            between[crossed, j] = True
            fraction[crossed, j] *= float(obj.material.transmit) if transmission else 0.0
    return fraction, between | (fraction == 0)


def _shadow_rays(scene, points, normals):
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a goldman_lib.ray_tracing.Scene; got {type(scene).__name__}")
    P = as_points(points, "points", dim=3)
    N = lighting.unit_rows(as_points(normals, "normals", dim=3), "normals")
    if N.shape != P.shape:
        raise ValueError(f"normals must have the shape of points {P.shape}; got {N.shape}")
    if not np.all(np.any(N != 0, axis=1)):
        raise ValueError("normals must be nonzero vectors")
    if np.abs(P).max() > 1e15:
        raise ValueError("points must have coordinates at most 1e15 in magnitude")
    bounds = [_bounding_sphere(obj) for obj in scene.objects]
    offset, skip_own = scene._offset()
    with np.errstate(over="ignore", invalid="ignore", under="ignore"):
        return _light_fraction(scene.objects, bounds, scene._leave(P) + offset * N, N, np.full(len(P), -1),
                               np.ones(len(P), dtype=bool), scene.lights, scene.shadow_transmission, skip_own)


def in_shadow(scene: Scene, points, normals) -> np.ndarray:
    """Shadow rays (Goldman §17.3): True where an object lies between point ``i`` and light ``j``
    (opaque or transparent), or the light is behind the surface, shape (N, L).

    points: (N, 3) points on the scene's surfaces; normals: (N, 3) their normals on the side the
    point is seen from.  A shadow ray leaves each point (nudged off the surface by :data:`OFFSET`)
    towards each light; the light is blocked if an object lies between, or if the light is behind
    the surface (``L . N <= 0``: the surface itself is in the way).  How much of the light still
    arrives through transparent objects: :func:`light_fraction`.

    >>> s = Scene([Sphere((0, 0, 1), 0.5)], [Light((0, 0, 5)), Light((4, 0, 5))])
    >>> in_shadow(s, [[0, 0, 0]], [[0, 0, 1]]).tolist()      # under the sphere: only the first is blocked
    [[True, False]]
    """
    return _shadow_rays(scene, points, normals)[1]


def light_fraction(scene: Scene, points, normals) -> np.ndarray:
    """The fraction of light ``j`` that reaches point ``i`` along its shadow ray (Goldman §17.3 with
    Whitted's attenuation), shape (N, L): 1 unobstructed, the product of the ``material.transmit`` of
    the transparent objects the shadow ray passes (it is not refracted), 0 behind an opaque object or
    a light behind the surface.  With ``scene.shadow_transmission`` False every object stops it (0).
    points, normals: as in :func:`in_shadow`.

    >>> glass = Material(transmit=0.8, index=1.5)
    >>> s = Scene([Sphere((0, 0, 1), 0.5, glass), Sphere((0, 0, 3), 0.5, glass)], [Light((0, 0, 5))])
    >>> round(float(light_fraction(s, [[0, 0, 0]], [[0, 0, 1]])[0, 0]), 12)     # through both: 0.8 x 0.8
    0.64
    """
    return _shadow_rays(scene, points, normals)[0]


def _check_lights(scene, rays: int, max_rays: int = MAX_ITEMS) -> None:
    """Every ray that hits casts a shadow ray to every light: the ``rays`` primary rays alone trace
    ``rays x (1 + lights)`` rays, within the budget ``max_rays`` (checked before any is traced)."""
    lights = len(scene.lights)
    if rays * (1 + lights) > max_rays:
        most = max(max_rays // max(rays, 1) - 1, 0)
        if most == 0:
            raise ValueError(f"max_rays: {rays:,} primary rays, each with a shadow ray per light ({lights:,}), are "
                             f"{rays * (1 + lights):,} rays, over the budget max_rays = {max_rays:,}: make the "
                             f"image smaller")
        raise ValueError(f"scene.lights must number at most {most:,} for {rays:,} primary rays (each casts a shadow "
                         f"ray to every light: rays x (1 + lights) = {rays * (1 + lights):,}, over the budget "
                         f"max_rays = {max_rays:,}); got {lights:,} lights: use fewer lights or a smaller image")


def _as_budget(max_rays) -> int:
    return as_int(max_rays, "max_rays", minimum=1, maximum=MAX_ITEMS)


def trace(scene: Scene, origins, directions, depth: int = 3, *, record: list | None = None,
          miss_length: float = 3.0, counts: dict | None = None, max_rays: int = MAX_ITEMS) -> np.ndarray:
    """The colour each ray brings back, traced recursively to ``depth`` (Goldman §17.2-17.5):
    ``(N, 3)``, unclipped.  origins, directions: (N, 3) (a single ray as two (3,) vectors).

    The rays of one recursion level are traced together: nearest hit over the objects; local light
    by :func:`goldman_lib.lighting.intensity` with a shadow ray per light; then the reflected rays
    (weight ``k_r``) and refracted rays (weight ``k_t``; on total internal reflection the reflected
    ray gets ``k_r + k_t``) form the next level.  record: a list to append the :class:`RaySegment`
    of every ray traced (what :func:`ray_tree` draws; keep N small).  counts: a dict to receive the
    number of ``"rays"`` traced (primary, reflected and refracted) and of ``"shadow"`` rays.

    max_rays: the budget of rays traced, shadow rays included (at most, and by default,
    :data:`goldman_lib.validation.MAX_ITEMS`).  The rays are counted as they are spawned, level by
    level (most rays hit something matte and spawn none), and each level is checked before its
    work: a level whose rays (each with a shadow ray per light) would bring the total over the
    budget raises ValueError naming ``max_rays``, so even a hall of mirrors stops early.

    >>> s = Scene([Sphere((0, 0, 0), 1, Material(colour=(1, 1, 1), ambient=1, diffuse=0, specular=0))],
    ...           [Light((0, 0, 5))], ambient_light=0.25, background=(0, 0, 1))
    >>> trace(s, [[0, 0, -5], [0, 3, -5]], [[0, 0, 1], [0, 0, 1]], depth=0).tolist()
    [[0.25, 0.25, 0.25], [0.0, 0.0, 1.0]]
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a goldman_lib.ray_tracing.Scene; got {type(scene).__name__}")
    o, d = rays(origins, directions)
    depth = as_int(depth, "depth", minimum=0, maximum=MAX_DEPTH)
    max_rays = _as_budget(max_rays)
    _check_lights(scene, len(o), max_rays)
    miss_length = as_float(miss_length, "miss_length", positive=True)
    if counts is not None and not isinstance(counts, dict):
        raise TypeError(f"counts must be a dict (to receive the ray counts) or None; got {type(counts).__name__}")
    if record is not None and not isinstance(record, list):
        raise TypeError(f"record must be a list (to append the ray segments to) or None; got {type(record).__name__}")
    with np.errstate(over="ignore", invalid="ignore", under="ignore"):
        d = lighting.unit_rows(d / np.abs(d).max(axis=1, keepdims=True))
        colour = _trace(scene, np.array(o, dtype=float), d, depth, record, miss_length,
                        {} if counts is None else counts, max_rays)
    if not np.all(np.isfinite(colour)):
        raise ValueError(f"{_brightest(scene)} too large: the traced colour overflows float64")
    return colour


def _brightest(scene: Scene) -> str:
    """The scene's inputs to blame for a traced colour that overflows: the largest product of a
    material's coefficient and a light's (or the ambient) intensity.  (Origins and directions cannot
    be: :func:`goldman_lib.simple_surfaces.rays` bounds them, and the reflected and refracted
    weights are at most 1.)"""
    best, what = -1.0, "the scene's light intensities and material coefficients are"
    for j, obj in enumerate(scene.objects):
        m = obj.material
        terms = [(m.ambient * float(np.max(scene.ambient_light)), f"objects[{j}].material.ambient and ambient_light are")]
        for k, light in enumerate(scene.lights):
            for coef in ("diffuse", "specular"):
                terms.append((getattr(m, coef) * light.intensity,
                              f"objects[{j}].material.{coef} and lights[{k}].intensity are"))
        for value, name in terms:
            if value > best:
                best, what = value, name
    return what


def _trace(scene, o, d, depth, record, miss_length, counts, max_rays=MAX_ITEMS):
    n_rays = len(o)
    counts["rays"] = counts["shadow"] = 0
    colour = np.zeros((n_rays, 3))
    pixel = np.arange(n_rays)                # which input ray each ray of this level belongs to
    weight = np.ones(n_rays)
    kinds = np.zeros(n_rays, dtype=int)      # 0 primary, 1 reflected, 2 refracted
    names = ("primary", "reflected", "refracted")
    objects, lights = scene.objects, scene.lights
    bounds = [_bounding_sphere(obj) for obj in objects]
    offset, skip_own = scene._offset()
    light_terms = [(np.asarray(light.position), light.rgb) for light in lights]   # checked by Scene
    ambient = np.asarray(scene.ambient_light, dtype=float)
    for level in range(depth + 1):
        if len(o) == 0:
            break
        traced = counts["rays"] + counts["shadow"]
        coming = len(o) * (1 + len(scene.lights))      # this level's rays, each with a shadow ray per light
        if traced + coming > max_rays:
            raise ValueError(f"max_rays: tracing level {level} ({len(o):,} rays, {coming:,} with their shadow rays) "
                             f"would bring the rays traced to {traced + coming:,}, over the budget max_rays = "
                             f"{max_rays:,} ({traced:,} traced on levels 0-{level - 1}): lower the depth (now "
                             f"{depth}), make the image smaller or the scene less reflective")
        counts["rays"] += len(o)
        t, which, normals = _nearest(objects, bounds, o, d) if objects else (np.full(len(o), np.inf),
                                                                        np.full(len(o), -1), np.zeros((len(o), 3)))
        miss = which < 0
        brought = np.zeros((len(o), 3))      # what each ray of this level brings to its pixel
        brought[miss] = weight[miss, None] * scene.background
        hit = ~miss
        hit_rows = np.flatnonzero(hit)
        P = o[hit] + t[hit, None] * d[hit]
        if record is not None:
            ends = np.where(miss[:, None], o + miss_length * d, o + np.where(miss, 0.0, t)[:, None] * d)
            for i in range(len(o)):
                record.append(RaySegment(names[kinds[i]], o[i].copy(), ends[i].copy(), level, float(weight[i]),
                                         bool(hit[i])))
        if not hit.any():
            _accumulate(colour, pixel, brought, level)
            break
        d_h, N, w, pix, obj_h = d[hit], normals[hit], weight[hit], pixel[hit], which[hit]
        eye_h = o[hit]
        entering = _dot(d_h, N) < 0
        N_f = np.where(entering[:, None], N, -N)      # the normal on the side the ray arrives from
        P_leave = scene._leave(P)
        outside = P_leave + offset * N_f
        fraction, blocked = _light_fraction(objects, bounds, outside, N_f, obj_h, entering, lights,
                                            scene.shadow_transmission, skip_own)
        counts["shadow"] += blocked.size
        if record is not None:
            _record_shadows(record, objects, bounds, P, outside, w, blocked, lights, level, fraction)
        next_o, next_d, next_w, next_p, next_k = [], [], [], [], []
        order = np.argsort(obj_h, kind="stable")
        firsts = np.flatnonzero(np.diff(obj_h[order], prepend=-1))
        for sel in np.split(order, firsts[1:]):      # the hits on each object, as row indices
            m = objects[obj_h[sel[0]]].material
            # the local light (§16.6) by the lighting kernel: rays, lights and materials are checked
            V = frames.unit_rows(eye_h[sel] - P[sel]) if m.specular > 0 else None
            local = illumination.phong(P[sel], frames.unit_rows(N_f[sel]), V, light_terms, np.asarray(m.colour),
                                       np.asarray(m.specular_colour), m.ambient * ambient, m.diffuse, m.specular,
                                       m.exponent, fraction=fraction[sel])
            brought[hit_rows[sel]] = w[sel, None] * local
            if level == depth or (m.reflect == 0 and m.transmit == 0):
                continue
            r_weight = np.full(len(sel), m.reflect)
            if m.transmit > 0:
                eta = np.where(entering[sel], 1.0 / m.index, m.index)
                if scene.index_ratio == "n2/n1":
                    eta = 1.0 / eta                  # the slip, upside down (Scene(index_ratio="n2/n1"))
                T, tir = _refract(d_h[sel], N_f[sel], eta)
                r_weight = r_weight + np.where(tir, m.transmit, 0.0)
                go = sel[~tir]
                if len(go):
                    next_o.append(P_leave[go] - offset * N_f[go])
                    next_d.append(T[~tir])
                    next_w.append(w[go] * m.transmit)
                    next_p.append(pix[go])
                    next_k.append(np.full(len(go), 2))
            keep = r_weight > 0
            go = sel[keep]
            if len(go):
                next_o.append(outside[go])
                next_d.append(frames.unit_rows(illumination.reflect(-d_h[go], N_f[go])))
                next_w.append(w[go] * r_weight[keep])
                next_p.append(pix[go])
                next_k.append(np.full(len(go), 1))
        _accumulate(colour, pixel, brought, level)
        if not next_o:
            break
        o, d = np.concatenate(next_o), np.concatenate(next_d)
        weight, pixel, kinds = np.concatenate(next_w), np.concatenate(next_p), np.concatenate(next_k)
    return colour


def _accumulate(colour, pixel, brought, level):
    """Add each ray's light to its pixel (a pixel may have several rays on one level)."""
    if level == 0:
        colour += brought                    # one primary ray per pixel
    else:
        for c in range(3):
            colour[:, c] += np.bincount(pixel, brought[:, c], minlength=len(colour))


def _record_shadows(record, objects, bounds, P, outside, w, blocked, lights, level, fraction):
    """Append the shadow rays of one level to ``record``: to the light, or to the first object in
    the way, with the fraction of the light that arrives."""
    for j, light in enumerate(lights):
        end = np.broadcast_to(np.asarray(light.position, dtype=float), P.shape).copy()
        rows = np.flatnonzero(blocked[:, j])
        if len(rows):
            to_light = end[rows] - outside[rows]
            distance = np.sqrt(_dot(to_light, to_light))
            unit = to_light / np.where(distance > 0, distance, 1.0)[:, None]
            t, _, _ = _nearest(objects, bounds, outside[rows], np.where(distance[:, None] > 0, unit, [[0, 0, 1.0]]))
            end[rows] = outside[rows] + np.minimum(t, distance)[:, None] * unit
        for i in range(len(P)):
            record.append(RaySegment("shadow", P[i].copy(), end[i], level, float(w[i]), bool(blocked[i, j]),
                                     float(fraction[i, j])))


#: The most samples per pixel side :func:`render` takes (``samples=4``: 16 rays per pixel).
MAX_SAMPLES = 4
#: How many bands of rows :func:`render` traces one after another when it reports ``progress``.
BANDS = 24


def render(scene: Scene, camera: Camera, width: int | None = None, height: int | None = None, depth: int = 3, *,
           samples: int = 1, progress=None, counts: dict | None = None, max_rays: int = MAX_ITEMS) -> np.ndarray:
    """Ray trace ``scene`` seen by ``camera`` (Goldman §17.2): a ``(height, width, 3)`` image in
    [0, 1] (row 0 at the top), of the camera's size unless ``width`` or ``height`` is given.  depth: the recursion depth (0: local light and shadows only), at
    most :data:`MAX_DEPTH`.  The work is the rays actually traced, counted level by level against
    ``max_rays`` (default :data:`goldman_lib.validation.MAX_ITEMS`; see :func:`trace`): a 640x480
    image of :func:`default_scene` at depth 5 traces under 0.9 million rays, shadow rays included, far
    from the ``640 * 480 * 63`` (19 million) of a full binary tree per pixel.  counts: as in :func:`trace`.

    samples: anti-aliasing by supersampling (§17.1 raster graphics: a pixel is an area, not a point;
    the regular grid is our choice): each pixel is the mean of ``samples x samples`` rays through
    the centres of an even grid of sub-pixels, each clipped to [0, 1] before the mean; 1 (the
    default) is one ray through the pixel's centre.  At most :data:`MAX_SAMPLES`.
    progress: ``progress(done, total)`` is called with the image rows finished so far, after each
    of up to :data:`BANDS` bands of rows traced in turn (the image is the same, pixel for pixel, as
    without it), so a long render can show how far it is; an interrupt (Ctrl-C, the kernel's stop
    button) stops it between or inside bands.

    >>> img = render(default_scene(), default_camera(), 8, 6, depth=1)
    >>> img.shape
    (6, 8, 3)
    >>> done = []
    >>> img2 = render(default_scene(), default_camera(), 8, 6, depth=1, progress=lambda k, n: done.append((k, n)))
    >>> done[-1], bool((img2 == img).all())
    ((6, 6), True)
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a goldman_lib.ray_tracing.Scene; got {type(scene).__name__}")
    camera = _sized_camera(camera, width, height, depth)
    width, height = camera.width, camera.height
    samples = as_int(samples, "samples", minimum=1, maximum=MAX_SAMPLES)
    if progress is not None and not callable(progress):
        raise TypeError(f"progress must be a function progress(done, total) or None; got {type(progress).__name__}")
    if counts is not None and not isinstance(counts, dict):
        raise TypeError(f"counts must be a dict (to receive the ray counts) or None; got {type(counts).__name__}")
    budget = _as_budget(max_rays)
    big_w, big_h = width * samples, height * samples
    if big_w * big_h > budget:
        raise ValueError(f"samples={samples} makes {big_w * big_h:,} primary rays for a {width}x{height} image, "
                         f"over the budget max_rays={budget:,}; use fewer samples or a smaller image")
    _check_lights(scene, big_w * big_h, budget)   # before the primary rays are made
    o, d = _primary_rays(camera, big_w, big_h)
    if progress is None:
        colour = trace(scene, o, d, depth, counts=counts, max_rays=budget)
    else:
        colour = np.empty((big_w * big_h, 3))
        total = {"rays": 0, "shadow": 0}
        rows = -(-height // min(BANDS, height))            # image rows per band
        for top in range(0, height, rows):
            bottom = min(height, top + rows)
            a, b = top * samples * big_w, bottom * samples * big_w
            band: dict = {}
            colour[a:b] = trace(scene, o[a:b], d[a:b], depth, counts=band,
                                max_rays=max(1, budget - total["rays"] - total["shadow"]))
            total["rays"] += band["rays"]
            total["shadow"] += band["shadow"]
            progress(bottom, height)
        if counts is not None:
            counts.update(total)
    image = lighting.to_image(colour.reshape(big_h, big_w, 3))
    if samples > 1:
        image = image.reshape(height, samples, width, samples, 3).mean(axis=(1, 3))
    return image


def ray_cast(scene: Scene, camera: Camera, width: int | None = None, height: int | None = None, *, samples: int = 1,
             clamp: bool = True, progress=None) -> np.ndarray:
    """Ray cast ``scene`` seen by ``camera`` with local light only: the pictures of chapter 16
    (Goldman §16.6: each pixel's ray, its nearest hit and :func:`goldman_lib.lighting.intensity` there,
    no shadow rays and no recursion; :func:`render` adds those, §17.2).  A ``(height, width, 3)`` image
    in [0, 1] (row 0 at the top), of the camera's size unless ``width`` or ``height`` is given; a ray
    that hits nothing sees ``scene.background``.

    samples: ``samples x samples`` rays per pixel, averaged after clipping (anti-aliasing, as in
    :func:`render`), at most :data:`MAX_SAMPLES`.  clamp: passed to
    :func:`goldman_lib.lighting.intensity` (False: the unclamped ``L . N`` of §16.4, the slip).
    progress: ``progress(done, total)`` after each of up to :data:`BANDS` bands of image rows (the
    same image, pixel for pixel, as without it).  The work is ``width * height * samples^2`` rays,
    within :data:`goldman_lib.validation.MAX_ITEMS`.

    >>> s = Scene([Sphere((0, 0, 0), 1, Material(colour=(1, 1, 1), ambient=1, diffuse=0, specular=0))],
    ...           [Light((0, 0, 5))], ambient_light=0.5, background=(0, 0, 1))
    >>> img = ray_cast(s, Camera((0, -5, 0), (0, 0, 0), fov=30, width=4, height=3))
    >>> img[1, 1].tolist(), img[0, 0].tolist()          # the sphere in the middle, the background in a corner
    ([0.5, 0.5, 0.5], [0.0, 0.0, 1.0])
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a goldman_lib.ray_tracing.Scene; got {type(scene).__name__}")
    camera = _sized_camera(camera, width, height, 0)
    width, height = camera.width, camera.height
    samples = as_int(samples, "samples", minimum=1, maximum=MAX_SAMPLES)
    if not isinstance(clamp, (bool, np.bool_)):
        raise TypeError(f"clamp must be True or False; got {type(clamp).__name__}")
    if progress is not None and not callable(progress):
        raise TypeError(f"progress must be a function progress(done, total) or None; got {type(progress).__name__}")
    big_w, big_h = width * samples, height * samples
    if big_w * big_h > MAX_ITEMS:
        raise ValueError(f"samples={samples} makes {big_w * big_h:,} rays for a {width}x{height} image, over the "
                         f"budget {MAX_ITEMS:,}; use fewer samples or a smaller image")
    o, d = _primary_rays(camera, big_w, big_h)
    bounds = [_bounding_sphere(obj) for obj in scene.objects]
    colour = np.empty((big_w * big_h, 3))
    rows = -(-height // min(BANDS, height))
    for top in range(0, height, rows):
        bottom = min(height, top + rows)
        a, b = top * samples * big_w, bottom * samples * big_w
        with np.errstate(over="ignore", invalid="ignore", under="ignore"):
            t, which, normals = _nearest(scene.objects, bounds, o[a:b], d[a:b])
        band = np.broadcast_to(scene.background, (b - a, 3)).copy()
        for k, obj in enumerate(scene.objects):
            sel = np.flatnonzero(which == k)
            if len(sel) == 0:
                continue
            P = o[a:b][sel] + t[sel, None] * d[a:b][sel]
            N = normals[sel]
            N_f = np.where((_dot(d[a:b][sel], N) < 0)[:, None], N, -N)
            band[sel] = lighting.intensity(P, N_f, np.array(camera.eye), scene.lights, obj.material, scene.ambient_light,
                                           clamp=bool(clamp))
        colour[a:b] = band
        if progress is not None:
            progress(bottom, height)
    image = lighting.to_image(colour.reshape(big_h, big_w, 3))
    if samples > 1:
        image = image.reshape(height, samples, width, samples, 3).mean(axis=(1, 3))
    return image


def ray_tree(scene: Scene, camera: Camera, px: int, py: int, depth: int = 3, width: int | None = None,
             height: int | None = None, miss_length: float = 3.0) -> list[RaySegment]:
    """The ray tree of pixel ``(px, py)`` of the camera's image (or of a ``width`` x ``height`` one,
    where given) (Goldman §17.2): every
    ray the recursive tracer follows for that pixel, as :class:`RaySegment` s (primary, reflected,
    refracted and shadow rays), level by level.

    >>> tree = ray_tree(default_scene(), default_camera(), 80, 60, depth=2)
    >>> tree[0].kind, tree[0].level
    ('primary', 0)
    """
    o, d = _sized_camera(camera, width, height, depth).ray(px, py)
    segments: list[RaySegment] = []
    trace(scene, o[None], d[None], depth, record=segments, miss_length=miss_length)
    return segments


# -- the chapter's scene --------------------------------------------------------------------------------

#: The materials of :func:`default_scene`.
MATERIALS = {
    "floor": Material(colour=(0.82, 0.8, 0.74), ambient=0.9, diffuse=0.7, specular=0.05, exponent=8),
    "red": Material(colour=(0.85, 0.18, 0.15), ambient=0.3, diffuse=0.75, specular=0.5, exponent=40),
    "blue": Material(colour=(0.2, 0.35, 0.9), ambient=0.3, diffuse=0.7, specular=0.5, exponent=60),
    "mirror": Material(colour=(0.85, 0.85, 0.9), ambient=0.05, diffuse=0.1, specular=0.7, exponent=120,
                       reflect=0.8),
    "glass": Material(colour=(0.95, 0.97, 1.0), ambient=0.0, diffuse=0.05, specular=0.8, exponent=150,
                      reflect=0.08, transmit=0.88, index=1.5),
}


def default_lights() -> tuple[Light, ...]:
    """The light of :func:`default_scene`: one white point light above and in front of the spheres.

    >>> default_lights()[0].position
    (-2.5, -1.5, 5.0)
    """
    return (Light((-2.5, -1.5, 5.0), intensity=1.0),)


def default_scene(index: float = 1.5, lights=None, ambient_light=0.3, shadow_transmission: bool = True) -> Scene:
    """The chapter's scene: a floor (the plane z = 0) under four spheres, a red and a blue matte one,
    a mirror (``reflect = 0.8``) and a glass one (``transmit = 0.88``, index of refraction ``index``)
    in front, under :func:`default_lights` (or ``lights``), with a sky-blue background.  The camera
    :func:`default_camera` looks along +x, so the x-z plane is a side view of the scene.
    shadow_transmission: as in :class:`Scene` (True: the glass sphere's shadow lets ``k_t`` of the light through).

    >>> [type(o).__name__ for o in default_scene().objects]
    ['Plane', 'Sphere', 'Sphere', 'Sphere', 'Sphere']
    """
    index = as_float(index, "index", positive=True)
    glass = dataclasses.replace(MATERIALS["glass"], index=index)
    objects = [
        Plane((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), MATERIALS["floor"]),
        Sphere((-1.2, 0.55, 0.75), 0.75, glass),
        Sphere((1.6, -1.25, 1.0), 1.0, MATERIALS["mirror"]),
        Sphere((1.8, 1.5, 0.9), 0.9, MATERIALS["red"]),
        Sphere((0.6, 0.35, 0.45), 0.45, MATERIALS["blue"]),
    ]
    return Scene(objects, default_lights() if lights is None else lights, ambient_light=ambient_light,
                 background=(0.62, 0.76, 0.92), shadow_transmission=shadow_transmission)


def default_camera(fov: float = 45.0, width: int = 160, height: int = 120) -> Camera:
    """The camera of :func:`default_scene`: the eye at (-7, 0, 2.2) looking at (0, 0, 0.8), z up, a
    vertical field of view of ``fov`` degrees, a ``width`` x ``height`` image.

    >>> cam = default_camera()
    >>> cam.eye, (cam.width, cam.height)
    ((-7.0, 0.0, 2.2), (160, 120))
    """
    return Camera((-7.0, 0.0, 2.2), (0.0, 0.0, 0.8), up=(0.0, 0.0, 1.0), fov=fov, width=width, height=height)

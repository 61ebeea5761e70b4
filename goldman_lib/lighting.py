"""Colour and intensity: the one lighting model of the course (Goldman chapter 16).

Where light meets a surface, in one place.  Every renderer of Part III (the ray tracer of
chapter 17, the rasteriser of chapter 21, the hidden-surface algorithms of chapter 22, the
radiosity display of chapter 23), the static pictures of every three.js view and the lights of
:class:`goldman_lib.widgets.three.SceneView` take their lights from here.

Goldman §16.3-16.6 builds the intensity of light leaving a point ``P`` with unit normal ``N`` seen
from an eye at ``E`` as the sum of three terms, one colour channel at a time:

* **ambient** (§16.3): ``I_a k_a``, light scattered so often it comes from everywhere;
* **diffuse** (§16.4, Lambert's law): ``I_p k_d (L . N)``, ``L`` the unit vector from ``P`` to a
  point light; a matte surface scatters equally in all directions, so only the angle of
  incidence matters;
* **specular** (§16.5, Phong's model): ``I_p k_s (R . V)^n``, ``R = 2 (L . N) N - L`` the mirror
  image of ``L`` about the normal, ``V`` the unit vector from ``P`` to the eye and ``n`` the
  specular exponent: the larger ``n``, the smaller and sharper the highlight.

Conventions (the tests rely on them): a term is 0 where the light is behind the surface
(``L . N <= 0``) and the specular term also where ``R . V <= 0``: the clamp of §16.4 (``clamp=True``,
the default of :func:`diffuse`, :func:`specular` and :func:`intensity`; ``clamp=False`` takes it away,
to show what it prevents: a negative diffuse term that subtracts light, and a highlight on the side
turned away from the light); the specular term has no
``L . N`` factor; no term is attenuated with distance.  Colours are RGB triples in [0, 1]; a
material's colour multiplies its ambient and diffuse coefficients (the specular highlight takes
the light's colour, as on a plastic).  Intensities are returned unclipped; images clip them to
[0, 1] (:func:`to_image`).

>>> P, N = [[0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]]
>>> float(diffuse(P, N, [0, 0, 2], 0.5, 1.0)[0])          # light straight above: cos = 1
0.5
>>> round(float(specular(P, N, [1, 0, 1], [-1, 0, 1], 0.8, 10, 1.0)[0]), 12)   # the eye on the mirror ray
0.8
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from goldman_lib.validation import as_colour, as_float, as_float_array, as_points, check_finite, finite_result
from goldman_lib.kernels import frames, illumination

__all__ = ["Light", "Material", "unit_rows", "reflected_direction", "ambient", "diffuse", "specular", "blinn_specular",
           "intensity", "to_image", "light_direction", "default_lights", "shade_faces", "highlight_half_width"]


def _colour(value, name: str) -> tuple[float, float, float]:
    return as_colour(value, name)


def _non_negative(value, name: str) -> float:
    v = as_float(value, name)
    if v < 0:
        raise ValueError(f"{name} must be >= 0; got {v}")
    return v


@dataclass(frozen=True)
class Light:
    """A point light source (Goldman §16.4-16.5): where it is, its colour and its intensity ``I_p``.

    >>> Light((0, 0, 5)).rgb.tolist()
    [1.0, 1.0, 1.0]
    >>> Light((1, 2, 3), colour=(1, 0.5, 0), intensity=0.5).rgb.tolist()
    [0.5, 0.25, 0.0]
    """

    position: tuple = (0.0, 0.0, 5.0)
    colour: tuple = (1.0, 1.0, 1.0)
    intensity: float = 1.0

    def __post_init__(self):
        p = as_points(self.position, "position", ndim=1, dim=3)
        object.__setattr__(self, "position", tuple(float(v) for v in p))
        object.__setattr__(self, "colour", _colour(self.colour, "colour"))
        object.__setattr__(self, "intensity", _non_negative(self.intensity, "intensity"))

    @property
    def rgb(self) -> np.ndarray:
        """``colour * intensity``: the light's intensity per channel, shape (3,)."""
        return np.asarray(self.colour) * self.intensity


@dataclass(frozen=True)
class Material:
    """How a surface answers light (Goldman §16.2-16.5): its colour, the coefficients ``k_a``, ``k_d``,
    ``k_s`` (each >= 0) and the specular exponent ``n`` (>= 0).

    ``reflect`` and ``transmit`` (in [0, 1]) and ``index`` (the index of refraction, > 0) are what
    the recursive ray tracer of chapter 17 uses: the fractions of the reflected and refracted
    (transmitted) rays' light added to the local intensity.

    >>> Material(colour=(1, 0, 0)).diffuse
    0.7
    """

    colour: tuple = (0.8, 0.8, 0.8)
    ambient: float = 0.2
    diffuse: float = 0.7
    specular: float = 0.4
    exponent: float = 32.0
    reflect: float = 0.0
    transmit: float = 0.0
    index: float = 1.0
    specular_colour: tuple = field(default=(1.0, 1.0, 1.0))

    def __post_init__(self):
        object.__setattr__(self, "colour", _colour(self.colour, "colour"))
        object.__setattr__(self, "specular_colour", _colour(self.specular_colour, "specular_colour"))
        for name in ("ambient", "diffuse", "specular", "exponent"):
            object.__setattr__(self, name, _non_negative(getattr(self, name), name))
        for name in ("reflect", "transmit"):
            v = _non_negative(getattr(self, name), name)
            if v > 1:
                raise ValueError(f"{name} must be in [0, 1] (a fraction of the light); got {v}")
            object.__setattr__(self, name, v)
        object.__setattr__(self, "index", as_float(self.index, "index", positive=True))


def unit_rows(vectors, name: str = "vectors") -> np.ndarray:
    """Each row scaled to length 1 (a zero row stays zero): shape (..., 3).

    >>> unit_rows([[3, 0, 4], [0, 0, 0]]).tolist()
    [[0.6, 0.0, 0.8], [0.0, 0.0, 0.0]]
    """
    v = as_points(vectors, name, ndim=None, dim=3)
    return _unit(v)


def _dot(a, b):
    return frames.row_dots(a, b)


def reflected_direction(vectors, normals) -> np.ndarray:
    """The mirror image ``2 (v . N) N - v`` of each vector about its unit normal (Goldman §16.5:
    ``R`` from ``L``).  A ray travelling in direction ``d`` leaves a mirror in direction
    ``reflected_direction(-d, N)``.

    >>> reflected_direction([[1.0, 0.0, 1.0]], [[0.0, 0.0, 1.0]]).tolist()
    [[-1.0, 0.0, 1.0]]
    """
    v = as_points(vectors, "vectors", ndim=None, dim=3)
    n = as_points(normals, "normals", ndim=None, dim=3)
    with np.errstate(over="ignore", invalid="ignore"):
        return finite_result(illumination.reflect(v, n), "vectors and normals", why="are too large in magnitude")


def scaled_terms(cosines, k, light_intensity, k_name, i_name):
    """``k * I * cos`` with k and I each a number or an RGB triple: (N,) or (N, 3) (the factor of
    every term of §16.3-16.5; k and I checked, named by ``k_name`` and ``i_name``).  Public for the
    renderers (no underscore), out of ``__all__``: its inputs are already checked arrays.

    >>> scaled_terms(np.array([1.0, 0.5]), 0.8, (1.0, 0.5, 0.0), "kd", "I").tolist()
    [[0.8, 0.4, 0.0], [0.4, 0.2, 0.0]]
    """
    k = as_float_array(k, k_name)
    i = as_float_array(light_intensity, i_name)
    for arr, name in ((k, k_name), (i, i_name)):
        if arr.shape not in ((), (3,)):
            raise ValueError(f"{name} must be a number or an RGB triple; got shape {arr.shape}")
        check_finite(arr, name)
        if np.any(arr < 0):
            raise ValueError(f"{name} must be >= 0; got {arr.tolist()}")
    with np.errstate(over="ignore"):
        s = finite_result(k * i, f"{k_name} and {i_name}", why="are too large in magnitude")
    return cosines * s if s.ndim == 0 else cosines[..., None] * s


def _geometry(points, normals):
    P = as_points(points, "points", ndim=None, dim=3)
    N = unit_rows(normals, "normals")
    if N.shape != P.shape:
        raise ValueError(f"normals must have the shape of points {P.shape}; got {N.shape}")
    return P, N


def _eye(eye, P):
    """The eye: one point (3,), or one per point (the shape of ``points``; a ray tracer's secondary
    rays each have their own viewer, the ray's origin)."""
    E = as_points(eye, "eye", ndim=None, dim=3)
    if E.ndim > 1 and E.shape != P.shape:
        raise ValueError(f"eye must be one point (3,) or one per point {P.shape}; got shape {E.shape}")
    return E


def as_lights(lights) -> tuple:
    """``lights`` as a tuple of :class:`Light` (one Light, or a sequence of them); TypeError naming
    ``lights`` otherwise.  Public for the renderers, out of ``__all__``.

    >>> len(as_lights(Light((0, 0, 5))))
    1
    """
    if isinstance(lights, Light):
        return (lights,)
    try:
        lights = tuple(lights)
    except TypeError:
        raise TypeError(f"lights must be a Light or a sequence of goldman_lib.lighting.Light; "
                        f"got {type(lights).__name__}") from None
    if not all(isinstance(light, Light) for light in lights):
        raise TypeError("lights must be a Light or a sequence of goldman_lib.lighting.Light")
    return lights


def ambient(ka, ambient_intensity) -> np.ndarray:
    """The ambient term ``I_a k_a`` (Goldman §16.3); each a number or an RGB triple.

    >>> ambient(0.5, [1.0, 0.5, 0.0]).tolist()
    [0.5, 0.25, 0.0]
    """
    return scaled_terms(np.float64(1.0), ka, ambient_intensity, "ka", "ambient_intensity")


def _unit(v):
    """Unchecked: rows of ``v`` scaled to length 1 (zero rows stay zero)."""
    return frames.unit_rows(v)


def _check_clamp(clamp) -> bool:
    if not isinstance(clamp, (bool, np.bool_)):
        raise TypeError(f"clamp must be True or False; got {type(clamp).__name__}")
    return bool(clamp)


def _cosines(P, N, light_position, V=None, exponent=None, name="light_position", clamp=True):
    """:func:`goldman_lib.kernels.illumination.cosines` after checking that ``light_position - P``
    stays finite (``name``: the light's position, blamed with the points if it does not)."""
    with np.errstate(over="ignore", invalid="ignore"):
        finite_result(light_position - P, f"{name} or points", why="is too large in magnitude")
    return illumination.cosines(P, N, light_position, V, exponent, clamp)


def diffuse(points, normals, light_position, kd, light_intensity, *, clamp: bool = True) -> np.ndarray:
    """Lambert's diffuse term ``I_p k_d max(L . N, 0)`` at each point (Goldman §16.4).

    points, normals: (..., 3) (normals need not be unit); light_position: (3,); kd and
    light_intensity: numbers or RGB triples.  Returns (...) or (..., 3) if either is RGB.
    clamp: True (the default) clamps ``L . N`` at 0, so a light behind the surface adds nothing;
    False is the slip the clamp prevents (§16.4): ``I_p k_d (L . N)`` goes negative there and
    subtracts light.

    >>> diffuse([[0, 0, 0]], [[0, 0, -1]], [0, 3, 3], 1.0, 1.0, clamp=False).round(6).tolist()
    [-0.707107]

    >>> diffuse([[0, 0, 0], [0, 0, 0]], [[0, 0, 1], [0, 0, -1]], [0, 3, 3], 1.0, 1.0).round(6).tolist()
    [0.707107, 0.0]
    """
    clamp = _check_clamp(clamp)
    P, N = _geometry(points, normals)
    cos_d, _ = _cosines(P, N, as_points(light_position, "light_position", ndim=1, dim=3), clamp=clamp)
    return scaled_terms(cos_d, kd, light_intensity, "kd", "light_intensity")


def specular(points, normals, light_position, eye, ks, exponent, light_intensity, *, clamp: bool = True) -> np.ndarray:
    """Phong's specular term ``I_p k_s (R . V)^n`` (Goldman §16.5): ``R`` the mirror image of the
    unit vector ``L`` to the light, ``V`` the unit vector to the eye (one point (3,) or one per
    point); 0 where ``L . N <= 0`` (the
    light is behind the surface) or ``R . V <= 0``.  No ``L . N`` factor, no attenuation.
    clamp: False drops the test ``L . N > 0`` (§16.4's clamp; see :func:`diffuse`): a light behind the
    surface can then make a highlight on it.

    >>> specular([[0, 0, 0]], [[0, 0, 1]], [1, 0, 1], [0, 0, 1], 1.0, 2, 1.0).round(6).tolist()
    [0.5]
    """
    clamp = _check_clamp(clamp)
    P, N = _geometry(points, normals)
    light = as_points(light_position, "light_position", ndim=1, dim=3)
    with np.errstate(over="ignore", invalid="ignore"):
        V = unit_rows(finite_result(_eye(eye, P) - P, "eye or points", why="is too large in magnitude"), "eye - points")
    _, power = _cosines(P, N, light, V, _non_negative(exponent, "exponent"), clamp=clamp)
    return scaled_terms(power, ks, light_intensity, "ks", "light_intensity")


def blinn_specular(points, normals, light_position, eye, ks, exponent, light_intensity) -> np.ndarray:
    """Blinn's variant of the specular term (Goldman §16.5), ``I_p k_s (N . H)^n`` with the
    **halfway vector** ``H = (L + V) / |L + V|`` between the unit vectors ``L`` to the light and
    ``V`` to the eye: no mirror direction is formed.  0 where ``L . N <= 0`` (the light is behind the
    surface) or ``N . H <= 0``.  Arguments as in :func:`specular`.

    When ``L``, ``N`` and ``V`` lie in one plane, ``N . H = cos(phi / 2)`` where ``phi`` is the angle
    between ``R`` and ``V`` (``R . V = cos phi``), so Blinn's term with an exponent of about ``4n``
    gives nearly the highlight of Phong's with ``n``: ``cos^{4n}(phi/2) ~ cos^n(phi)`` for small
    ``phi`` (this comparison is our formulation).

    >>> blinn_specular([[0, 0, 0]], [[0, 0, 1]], [1, 0, 1], [-1, 0, 1], 1.0, 2, 1.0).round(6).tolist()
    [1.0]
    >>> blinn_specular([[0, 0, 0]], [[0, 0, 1]], [1, 0, 1], [0, 0, 1], 1.0, 1, 1.0).round(6).tolist()   # cos 22.5
    [0.92388]
    """
    P, N = _geometry(points, normals)
    light = as_points(light_position, "light_position", ndim=1, dim=3)
    n = _non_negative(exponent, "exponent")
    with np.errstate(over="ignore", invalid="ignore"):
        V = unit_rows(finite_result(_eye(eye, P) - P, "eye or points", why="is too large in magnitude"), "eye - points")
        L = _unit(finite_result(light - P, "light_position or points", why="is too large in magnitude"))
    S = L + V
    length = np.linalg.norm(S, axis=-1, keepdims=True)
    H = np.where(length > 0, S / np.where(length > 0, length, 1.0), 0.0)   # L = -V: no halfway vector, no highlight
    nh = np.where(_dot(L, N) > 0, np.maximum(_dot(N, H), 0.0), 0.0)
    with np.errstate(under="ignore", divide="ignore"):
        power = np.where(nh > 0, np.power(nh, n), 0.0)
    return scaled_terms(power, ks, light_intensity, "ks", "light_intensity")


def intensity(points, normals, eye, lights, material: Material, ambient_light=0.2, shadowed=None,
              two_sided: bool = False, light_fraction=None, *, clamp: bool = True) -> np.ndarray:
    """The total RGB intensity ``I_a k_a C + sum over lights of I_p (k_d C (L . N) + k_s S (R . V)^n)``
    at each point (Goldman §16.6), ``C`` the material's colour and ``S`` its specular colour.

    points, normals: (..., 3); eye: (3,), or one eye per point (..., 3) (a reflected or refracted
    ray's viewer is its own origin); lights: a :class:`Light` or a sequence of them;
    ambient_light: ``I_a``, a number or RGB triple.  shadowed: optional boolean (..., len(lights)),
    True where a light is blocked (chapter 17's shadow rays): that light adds nothing there.
    two_sided: flip each normal to face the eye first (for open surfaces and static pictures).
    light_fraction: optional (..., len(lights)) in [0, 1], the fraction of each light that reaches
    each point (chapter 17's shadow rays through transparent objects): it multiplies that light's
    diffuse and specular terms.  clamp: True (the default) clamps ``L . N`` at 0 (§16.4: a light
    behind the surface adds nothing); False, the slip it prevents, lets a light behind the surface
    subtract light through a negative diffuse term and make a highlight (see :func:`diffuse`,
    :func:`specular`).  Returns (..., 3), unclipped.

    >>> m = Material(colour=(1, 0, 0), ambient=0.1, diffuse=0.5, specular=0.0)
    >>> intensity([[0, 0, 0]], [[0, 0, 1]], [0, 0, 5], Light((0, 0, 5)), m, ambient_light=1.0).tolist()
    [[0.6, 0.0, 0.0]]
    >>> intensity([[0, 0, 0]], [[0, 0, -1]], [0, 0, 5], Light((0, 0, 5)), m, ambient_light=1.0, clamp=False).tolist()
    [[-0.4, 0.0, 0.0]]
    """
    if not isinstance(material, Material):
        raise TypeError(f"material must be a goldman_lib.lighting.Material; got {type(material).__name__}")
    clamp = _check_clamp(clamp)
    lights = as_lights(lights)
    P, N = _geometry(points, normals)
    E = _eye(eye, P)
    if two_sided:
        N = np.where((_dot(N, E - P) < 0)[..., None], -N, N)
    if shadowed is not None:
        try:
            shadowed = np.asarray(shadowed, dtype=bool)
        except (TypeError, ValueError) as exc:
            raise ValueError(f"shadowed must be a boolean array (points x lights): {exc}") from None
        if shadowed.shape != P.shape[:-1] + (len(lights),):
            raise ValueError(f"shadowed must have shape {P.shape[:-1] + (len(lights),)} (points x lights); "
                             f"got {shadowed.shape}")
    if light_fraction is not None:
        light_fraction = check_finite(as_float_array(light_fraction, "light_fraction"), "light_fraction")
        if light_fraction.shape != P.shape[:-1] + (len(lights),):
            raise ValueError(f"light_fraction must have shape {P.shape[:-1] + (len(lights),)} (points x lights); "
                             f"got {light_fraction.shape}")
        if np.any(light_fraction < 0) or np.any(light_fraction > 1):
            raise ValueError("light_fraction must lie in [0, 1] (the fraction of a light that reaches a point)")
    C, S = np.asarray(material.colour), np.asarray(material.specular_colour)
    ia = scaled_terms(np.float64(1.0), material.ambient, ambient_light, "material.ambient", "ambient_light")
    if material.specular > 0:                                                     # once for all lights
        with np.errstate(over="ignore", invalid="ignore"):
            V = unit_rows(finite_result(E - P, "eye or points", why="is too large in magnitude"), "eye - points")
    else:
        V = None
    with np.errstate(over="ignore", invalid="ignore"):
        for k, light in enumerate(lights):       # the checks of each light, then the terms in one kernel
            finite_result(np.asarray(light.position) - P, f"lights[{k}].position or points",
                          why="is too large in magnitude")
            finite_result(material.diffuse * C * light.rgb, f"lights[{k}].intensity and material.diffuse",
                          why="are too large in magnitude")
            finite_result(material.specular * S * light.rgb, f"lights[{k}].intensity and material.specular",
                          why="are too large in magnitude")
    total = illumination.phong(P, N, V, [(np.asarray(light.position), light.rgb) for light in lights], C, S, ia,
                               material.diffuse, material.specular if V is not None else 0.0, material.exponent,
                               clamp=clamp, shadowed=shadowed, fraction=light_fraction)
    return finite_result(total, "lights and material", why="are too bright together")


def highlight_half_width(exponent, fraction=0.5) -> float:
    """The angular half-width, in degrees, of a Phong highlight (Goldman §16.5): the angle between
    ``R`` and ``V`` at which ``(R . V)^n = cos^n`` falls to ``fraction`` of its peak,
    ``arccos(fraction^(1/n))``.  The larger the exponent ``n``, the narrower the highlight (for large
    ``n`` the width shrinks like ``1/sqrt(n)``).

    exponent: ``n > 0``.  fraction: in (0, 1) (default 0.5, the half-maximum).

    >>> round(highlight_half_width(1), 6), round(highlight_half_width(100), 4)
    (60.0, 6.7383)
    """
    n = as_float(exponent, "exponent", positive=True)
    f = as_float(fraction, "fraction", positive=True)
    if f >= 1:
        raise ValueError(f"fraction must be in (0, 1) (a fraction of the highlight's peak); got {f}")
    with np.errstate(under="ignore"):
        return float(np.degrees(np.arccos(f ** (1.0 / n))))


def to_image(values) -> np.ndarray:
    """Intensities clipped to [0, 1], ready for ``imshow`` or a vertex colour.

    >>> to_image([[1.5, 0.5, -0.1]]).tolist()
    [[1.0, 0.5, 0.0]]
    """
    return np.clip(check_finite(as_float_array(values, "values"), "values"), 0.0, 1.0)


def light_direction(azimuth=315.0, elevation=45.0) -> np.ndarray:
    """The unit vector towards a light at ``azimuth`` degrees (clockwise from north, the y axis)
    and ``elevation`` degrees above the xy plane (matplotlib's ``LightSource`` convention).

    >>> light_direction(0, 90).round(12).tolist()
    [0.0, 0.0, 1.0]
    """
    az = np.radians(90 - as_float(azimuth, "azimuth"))
    alt = np.radians(as_float(elevation, "elevation"))
    return np.array([np.cos(az) * np.cos(alt), np.sin(az) * np.cos(alt), np.sin(alt)])


def default_lights(distance: float = 20.0) -> tuple[Light, ...]:
    """The course's default lighting of a 3D view: a white key light up and to the left of the
    default camera, ``distance`` away (far enough to act almost like a directional light), and a
    dimmer fill light from the other side.

    >>> [round(v, 3) for v in default_lights()[0].position]
    [-10.0, -10.0, 14.142]
    """
    d = as_float(distance, "distance", positive=True)
    return (Light(tuple(d * light_direction(225, 45)), intensity=0.8),
            Light(tuple(d * light_direction(45, 30)), intensity=0.3))


def shade_faces(centroids, normals, eye, colour, lights=None, ambient_light=0.35) -> np.ndarray:
    """Two-sided face colours for a static picture of a mesh: :func:`intensity` at each face's
    centroid with a matte material of ``colour`` (``k_a = 1``, ``k_d = 0.8``, a soft highlight),
    clipped to [0, 1].  colour: one RGB triple, or one per face ``(m, 3)`` (then the light's
    ambient and diffuse parts tint each face's own colour).  lights: default :func:`default_lights`.
    Returns (m, 3).

    >>> shade_faces([[0, 0, 0]], [[0, 0, 1]], [0, 0, 5], (1, 1, 1), [Light((0, 0, 5))], 0.2).round(3).tolist()
    [[1.0, 1.0, 1.0]]
    """
    centroids = as_points(centroids, "centroids", dim=3)
    normals = as_points(normals, "normals", dim=3)
    if normals.shape != centroids.shape:
        raise ValueError(f"normals must have the shape of centroids {centroids.shape}; got {normals.shape}")
    eye = as_points(eye, "eye", ndim=1, dim=3)
    per_face = as_float_array(colour, "colour").ndim == 2
    if per_face:
        tint = as_points(colour, "colour", dim=3)
        if tint.shape != centroids.shape or tint.min() < 0 or tint.max() > 1:
            raise ValueError(f"colour must be an RGB triple or one per face {centroids.shape} in [0, 1]")
    material = Material(colour=(1.0, 1.0, 1.0) if per_face else colour, ambient=1.0, diffuse=0.8,
                        specular=0.0 if per_face else 0.15, exponent=20)
    lights = default_lights() if lights is None else as_lights(lights)
    with np.errstate(over="ignore", invalid="ignore"):
        shade = intensity(centroids, normals, eye, lights, material, ambient_light, two_sided=True)
        if per_face:
            shade = shade * tint
    return to_image(finite_result(shade, "centroids, normals and eye", why="are too large in magnitude"))

"""Exercise checkers for chapter 17, recursive ray tracing (Goldman §17.2-17.5).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
instance 0 is the module constants below, which the stored notebook shows; ``deal("check_...")``
(or the button beside the exercise) deals another, and the checker, ``PROBLEMS`` and
``steps("check_...")`` follow the current instance.  The chapter's "show that" exercises (in
:mod:`goldman_lib.exercises.proofs`) ask for an identity, not a number, so they do not deal.
``SLIPS`` holds the wrong answers each checker recognises, for the stored instance.  ``None`` or
``...`` means "not answered yet".  Every exercise uses other directions, indices, lights and depths
than the chapter's worked examples.  The book has no programming project for chapter 17.

>>> print(PROBLEMS["check_critical_angle"])
Light travels inside a block of flint glass (index of refraction 1.6) towards its flat face, on the other side of which is a liquid of index 1.2. Beyond which angle of incidence (measured from the normal) is the light totally internally reflected? Give the critical angle in degrees, to 2 decimals (Goldman §17.5).
>>> check_critical_angle(41.41)
Not yet: that is the angle measured from the surface, not from the normal: the angles of Snell's law are measured from the normal, so take arcsin, not arccos, of the ratio of the indices.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import lighting
from goldman_lib import ray_tracing as rt
from goldman_lib.exercises import guard_checkers, quote
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, unanswered, wrong, is_unanswered
from goldman_lib.exercises import read_vector as _read_vector, all_close as _close, distance_text as _dist  # shared readers
from goldman_lib.exercises.deal import Deck, memo, pick as _pick, steps_number as _f6, tenths as _tenths, within
from goldman_lib.lighting import Light, Material
from goldman_lib.simple_surfaces import Plane, Sphere

__all__ = ["PROBLEMS", "SLIPS", "REFLECT_D", "REFLECT_N", "REFRACT_D", "REFRACT_N", "REFRACT_N1", "REFRACT_N2",
           "CRITICAL_N1", "CRITICAL_N2", "SHADOW_POINT", "SHADOW_SPHERE", "SHADOW_LIGHTS", "TREE_DEPTH", "TREE_LIGHTS",
           "TREE_COLOURS", "DECK", "deal", "steps", "current", "deal_button",
           "check_reflected_direction", "check_refracted_direction", "check_critical_angle",
           "check_blocked_lights", "check_ray_tree_size", "check_ray_tree_colour"]

#: Exercise 1 (§17.4): a unit ray direction and the (not yet unit) normal of the mirror it meets.
REFLECT_D = (1 / 3, 2 / 3, -2 / 3)
REFLECT_N = (0.0, 3.0, 4.0)
#: Exercise 2 (§17.5): a unit direction meeting the flat surface z = 0 from above, and the indices.
REFRACT_D = (0.6, 0.0, -0.8)
REFRACT_N = (0.0, 0.0, 1.0)
REFRACT_N1 = 1.0
REFRACT_N2 = 1.25
#: Exercise 3 (§17.5): from flint glass into a liquid.
CRITICAL_N1 = 1.6
CRITICAL_N2 = 1.2
#: Exercise 4 (§17.3): a point on the floor z = 0 (normal +z), a sphere (centre, radius) and four lights.
SHADOW_POINT = (0.0, 0.0, 0.0)
SHADOW_SPHERE = ((1.0, 0.0, 2.0), 0.8)
SHADOW_LIGHTS = ((2.0, 0.0, 4.0), (-2.0, 1.0, 4.0), (0.5, 0.0, 1.0), (0.0, 2.0, -1.0))
#: Exercise 5 (§17.2): the depth of a ray tree and the number of lights.
TREE_DEPTH = 4
TREE_LIGHTS = 3
#: Exercise 6 (§17.2): the local colours and weights along one pixel's ray tree.
TREE_COLOURS = {
    "floor_local": (0.1, 0.1, 0.1), "floor_reflect": 0.6,
    "sphere_local": (0.8, 0.2, 0.2), "sphere_reflect": 0.5,
    "background": (0.2, 0.4, 1.0),
}

DECK = Deck("ch17")


def _a(v):
    return np.asarray(v, dtype=float)


def _tup(v) -> tuple:
    return tuple(float(x) for x in np.asarray(v, dtype=float).ravel())


def _apart(groups, tol) -> bool:
    """Whether every form of each group is more than ``tol`` from every form of the other groups."""
    groups = [[_a(v) for v in g] for g in groups]
    return not any(_close(u, v, tol) for i, g in enumerate(groups) for h in groups[i + 1:] for u in g for v in h)


#: whole vectors of whole length (hand-friendly |v|): (v, |v|)
_WHOLE = (((1, 2, 2), 3), ((2, 1, 2), 3), ((2, 2, 1), 3), ((0, 3, 4), 5), ((4, 0, 3), 5), ((3, 4, 0), 5),
          ((2, 3, 6), 7), ((6, 2, 3), 7), ((4, 4, 7), 9), ((1, 4, 8), 9))


def _whole(rng):
    v, n = _pick(rng, _WHOLE)
    return tuple(int(x) for x in np.array(v)[rng.permutation(3)] * rng.choice([-1, 1], size=3)), int(n)


def _fraction_text(v, n) -> str:
    return "(" + ", ".join("0" if x == 0 else f"{x}/{n}" for x in v) + ")"


# -- §17.4 ---------------------------------------------------------------------------------------------

_STORED_REFLECT = {"d": (1, 2, -2), "length": 3, "N": REFLECT_N}


@memo
def _reflect_answers(p):
    d = _a(p["d"]) / p["length"]
    raw = _a(p["N"])
    N = lighting.unit_rows(raw[None])[0]
    expected = lighting.reflected_direction(-d[None], N[None])[0]
    slips = {"-R": -expected, "sign of the correction": d + 2 * (d @ N) * N,
             "normal not unit": d - 2 * (d @ raw) * raw, "incoming direction": d}
    return expected, slips


def _reflect_generate(rng) -> dict:
    d, n = _whole(rng)
    N, _ = _whole(rng)
    return {"d": d, "length": n, "N": _tup(N)}


def _reflect_ok(p):
    d = _a(p["d"]) / p["length"]
    N = _a(p["N"]) / np.linalg.norm(p["N"])
    c = -float(d @ N)
    if c < 0.1:
        return "the ray does not meet the mirror's front (d . N >= 0) or grazes it"
    if c > 0.95:
        return "the ray meets the mirror (almost) head on"
    ans, slips = _reflect_answers(p)
    raw = slips["normal not unit"]
    if not _apart([[ans], [slips["-R"]], [slips["sign of the correction"]],
                   [raw, lighting.unit_rows(raw[None])[0]], [slips["incoming direction"]]], 2e-4):
        return "two recognised forms coincide"
    return None


def _reflect_statement(p) -> str:
    return (f"A ray travelling in the direction d = {_fraction_text(p['d'], p['length'])} meets a mirror whose normal "
            f"there points along {fmt(p['N'], 5)}. In which unit direction does the reflected ray leave? Give [x, y, z] "
            f"to 4 decimals (Goldman §17.4).")


def _reflect_steps(p) -> str:
    d = _a(p["d"]) / p["length"]
    raw = _a(p["N"])
    N = raw / np.linalg.norm(raw)
    dn = float(d @ N)
    return (f"1. The unit normal: N = {fmt(raw)}/{_f6(np.linalg.norm(raw))} = {_f6(N)}.\n"
            f"2. d . N = {_f6(dn)} (negative: the ray meets the mirror's front).\n"
            f"3. R = d - 2 (d . N) N = d + {_f6(-2 * dn)} N = {_f6(_reflect_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_REFLECT, generate=_reflect_generate, answer=lambda p: _reflect_answers(p)[0],
               slips=lambda p: _reflect_answers(p)[1], statement=_reflect_statement, steps=_reflect_steps,
               same=within(2e-4), well_posed=_reflect_ok)
def check_reflected_direction(answer, p) -> Result:
    """Check the mirror direction R = d - 2 (d · N) N of a ray off a mirror with unit normal N
    (Goldman §17.4).

    Recognises -R (the mirror image of d rather than of -d), a sign slip d + 2 (d . N) N (no bounce),
    the normal left unnormalised, and the incoming direction itself.
    """
    got, err = _read_vector(answer, "your direction", 3, "the reflected direction as [x, y, z]")
    if err is not None:
        return err
    d = _a(p["d"]) / p["length"]
    N = lighting.unit_rows(_a(p["N"])[None])[0]
    expected, slips = _reflect_answers(p)
    tol = 2e-4
    if _close(got, expected, tol):
        return correct(f"R = d - 2 (d . N) N = {fmt(expected)}: the angle of reflection equals the angle of "
                       f"incidence ({fmt(math.degrees(math.acos(float(-d @ N))), 4)} degrees from the normal), and "
                       f"R lies in the plane of d and N.")
    if _close(got, slips["-R"], tol):
        return wrong("that points back towards the mirror: you reflected d itself, not -d. The ray leaves along the "
                     "mirror image of -d about N, reflected_direction(-d, N) = d - 2 (d . N) N.")
    if _close(got, slips["sign of the correction"], tol):
        return wrong("with d + 2 (d . N) N the sign of the correction is wrong: the ray keeps going into the mirror. "
                     "Since d . N < 0, R = d - 2 (d . N) N turns the normal component of d around.")
    raw = slips["normal not unit"]
    if _close(got, raw, tol) or _close(got, lighting.unit_rows(raw[None])[0], tol):
        return wrong(f"you used the normal {fmt(p['N'], 5)} as it is; the formula R = d - 2 (d . N) N needs a unit "
                     f"normal: divide it by its length {fmt(np.linalg.norm(p['N']))} first.")
    if _close(got, d, tol):
        return wrong("that is the incoming direction: a mirror turns the ray around its normal component.")
    return wrong(f"your direction is {_dist(got, expected)} from the reflected one; check that it has length 1, "
                 f"that the angle to N equals the angle between -d and N, and use R = d - 2 (d . N) N with a unit N.")


# -- §17.5 ---------------------------------------------------------------------------------------------

_STORED_REFRACT = {"d": REFRACT_D, "n1": REFRACT_N1, "n2": REFRACT_N2}
#: unit directions with short decimals, going down into z = 0
_DOWN = ((0.6, 0.0, -0.8), (0.0, 0.6, -0.8), (0.36, 0.48, -0.8), (0.48, 0.36, -0.8), (0.28, 0.0, -0.96),
         (0.8, 0.0, -0.6), (0.0, 0.8, -0.6), (0.48, 0.64, -0.6), (0.64, 0.48, -0.6))


def _angle_divided(d, N, n1, n2):
    """The slip: theta1 / (n2 / n1) as the refracted angle, in the plane of d and N."""
    s1 = float(np.linalg.norm(np.cross(d, N)))
    tangent = d - (d @ N) * N
    tangent = tangent / np.linalg.norm(tangent)
    theta2 = math.radians(math.degrees(math.asin(s1)) / (n2 / n1))
    return math.sin(theta2) * tangent - math.cos(theta2) * N


@memo
def _refract_answers(p):
    d, N, n1, n2 = _a(p["d"]), _a(REFRACT_N), p["n1"], p["n2"]
    expected = _a(rt.refract(d, N, n1, n2))
    upside = rt.refract(d, N, n2, n1)
    slips = {"incoming direction": d, "other side of the normal": expected * [-1, -1, 1],
             "angle divided": _angle_divided(d, N, n1, n2), "reflected": lighting.reflected_direction(-d[None], N[None])[0]}
    if upside is not None:
        slips["upside down"] = _a(upside)
    return expected, slips


def _refract_generate(rng) -> dict:
    d = _a(_pick(rng, _DOWN)) * np.r_[rng.choice([-1.0, 1.0], size=2), 1.0]
    return {"d": _tup(d + 0.0), "n1": 1.0, "n2": float(_pick(rng, (1.2, 1.25, 1.3, 1.33, 1.4, 1.5, 1.6)))}


def _refract_ok(p):
    if "upside down" not in _refract_answers(p)[1]:
        return "the ratio upside down gives total internal reflection (no slip to recognise)"
    return None


def _refract_statement(p) -> str:
    return (f"A ray in air (index {fmt(p['n1'])}) travelling in the unit direction d = {fmt(p['d'], 5)} meets the flat "
            f"surface z = 0 of a transparent plastic of index {fmt(p['n2'])} (normal {fmt(REFRACT_N, 5)}). In which unit "
            f"direction does the refracted ray travel inside? Give [x, y, z] to 4 decimals (Goldman §17.5).")


def _refract_steps(p) -> str:
    d, n1, n2 = _a(p["d"]), p["n1"], p["n2"]
    cos1 = -float(d[2])
    s1 = math.sqrt(max(0.0, 1 - cos1 * cos1))
    s2 = n1 * s1 / n2
    cos2 = math.sqrt(1 - s2 * s2)
    eta = n1 / n2
    return (f"1. cos(theta1) = -d . N = {_f6(cos1)}, sin(theta1) = {_f6(s1)}.\n"
            f"2. Snell: sin(theta2) = (n1 / n2) sin(theta1) = {fmt(n1)} x {_f6(s1)} / {fmt(n2)} = {_f6(s2)}; "
            f"cos(theta2) = {_f6(cos2)}.\n"
            f"3. T = eta d + (eta cos(theta1) - cos(theta2)) N with eta = n1 / n2 = {_f6(eta)}: "
            f"T = {_f6(_refract_answers(p)[0])} (a unit vector, bent towards the normal).")


@DECK.exercise(stored=_STORED_REFRACT, generate=_refract_generate, answer=lambda p: _refract_answers(p)[0],
               slips=lambda p: _refract_answers(p)[1], statement=_refract_statement, steps=_refract_steps,
               same=within(2e-4), well_posed=_refract_ok)
def check_refracted_direction(answer, p) -> Result:
    """Check the refracted direction by Snell's law, n1 sin(theta1) = n2 sin(theta2) (Goldman §17.5).

    Recognises no bending, the ratio of indices upside down, bending to the other side of the normal,
    angles (not sines) divided by the index, and the reflected ray.
    """
    got, err = _read_vector(answer, "your direction", 3, "the refracted direction as [x, y, z]")
    if err is not None:
        return err
    d, n1, n2 = _a(p["d"]), p["n1"], p["n2"]
    expected, slips = _refract_answers(p)
    tol = 2e-4
    s1 = float(np.linalg.norm(np.cross(d, REFRACT_N)))
    if _close(got, expected, tol):
        return correct(f"T = {fmt(expected)}: sin(theta2) = {fmt(n1)} x {fmt(s1)} / {fmt(n2)}, so the "
                       f"ray bends towards the normal as it enters the denser medium.")
    if _close(got, d, tol):
        return wrong("that is the incoming direction: the ray changes speed at the surface and bends (the indices "
                     "differ), so sin(theta2) = (n1 / n2) sin(theta1).")
    if "upside down" in slips and _close(got, slips["upside down"], tol):
        return wrong("you used the ratio of the indices upside down: n1 sin(theta1) = n2 sin(theta2), so "
                     "sin(theta2) = (n1 / n2) sin(theta1) with n1 the medium the ray comes from; entering the denser "
                     "plastic, the ray bends towards the normal, not away from it.")
    if _close(got, slips["other side of the normal"], tol):
        return wrong("your ray crosses to the other side of the normal: the refracted ray goes on forward, keeping "
                     "the sideways direction of d (it lies in the plane of d and N); only its angle to the normal "
                     "changes.")
    if _close(got, slips["angle divided"], tol):
        return wrong("you divided the angle by the ratio of the indices; Snell's law divides the sines: "
                     "n1 sin(theta1) = n2 sin(theta2).")
    if _close(got, slips["reflected"], tol):
        return wrong("that is the reflected ray (it leaves the surface); the refracted ray goes on through it, "
                     "into the plastic.")
    return wrong(f"your direction is {_dist(got, expected)} from the refracted one; check that it is a unit "
                 f"vector going into the surface (z < 0) and that sin of its angle to the normal is "
                 f"(n1 / n2) sin(theta1).")


_STORED_CRITICAL = {"n1": CRITICAL_N1, "n2": CRITICAL_N2, "inside": "flint glass"}
_DENSE = ((1.5, "crown glass"), (1.6, "flint glass"), (1.7, "dense flint glass"), (1.9, "heavy flint glass"),
          (2.4, "diamond"))


@memo
def _critical_answers(p):
    e = rt.critical_angle(p["n1"], p["n2"])
    return e, {"from the surface": 90 - e, "into air": rt.critical_angle(p["n1"], 1.0), "radians": math.radians(e),
               "the sine": p["n2"] / p["n1"]}


def _critical_generate(rng) -> dict:
    n1, name = _pick(rng, _DENSE)
    return {"n1": n1, "n2": float(_pick(rng, (1.2, 1.25, 1.3, 1.33, 1.4))), "inside": name}


def _critical_statement(p) -> str:
    return (f"Light travels inside a block of {p['inside']} (index of refraction {fmt(p['n1'])}) towards its flat face, "
            f"on the other side of which is a liquid of index {fmt(p['n2'])}. Beyond which angle of incidence "
            f"(measured from the normal) is the light totally internally reflected? Give the critical angle in degrees, "
            f"to 2 decimals (Goldman §17.5).")


def _critical_steps(p) -> str:
    e = _critical_answers(p)[0]
    return (f"1. At the critical angle the refracted ray grazes the surface, theta2 = 90 degrees: "
            f"n1 sin(theta_c) = n2 sin 90 = n2.\n"
            f"2. sin(theta_c) = n2 / n1 = {fmt(p['n2'])} / {fmt(p['n1'])} = {_f6(p['n2'] / p['n1'])}.\n"
            f"3. theta_c = arcsin({_f6(p['n2'] / p['n1'])}) = {_f6(e)} degrees.")


@DECK.exercise(stored=_STORED_CRITICAL, generate=_critical_generate, answer=lambda p: _critical_answers(p)[0],
               slips=lambda p: _critical_answers(p)[1], statement=_critical_statement, steps=_critical_steps,
               same=within(0.01))
def check_critical_angle(answer, p) -> Result:
    """Check the critical angle of total internal reflection, in degrees, arcsin(n2 / n1) (Goldman §17.5).

    Recognises the angle from the surface (arccos), the critical angle into air (arcsin(1 / n1)),
    radians, and the ratio's sine without arcsin.
    """
    value, err = read_number(answer, "your critical angle", "number of degrees")
    if err is not None:
        return err
    expected, slips = _critical_answers(p)
    tol = 0.01
    if abs(value - expected) <= tol:
        return correct(f"sin(theta_c) = n2 / n1 = {fmt(p['n2'] / p['n1'])}, theta_c = {fmt(expected, 5)} "
                       f"degrees: past it sin(theta2) would exceed 1, so no refracted ray exists.")
    if abs(value - slips["from the surface"]) <= tol:
        return wrong("that is the angle measured from the surface, not from the normal: the angles of Snell's law "
                     "are measured from the normal, so take arcsin, not arccos, of the ratio of the indices.")
    if abs(value - slips["into air"]) <= tol:
        return wrong(f"that is the critical angle from this {p['inside']} into air (index 1); here it meets a liquid "
                     f"of index {fmt(p['n2'])}: sin(theta_c) = n2 / n1.")
    if abs(value - slips["radians"]) <= 1e-3:
        return wrong("that is in radians; give degrees.")
    if abs(value - slips["the sine"]) <= 1e-3:
        return wrong("that is sin(theta_c), the ratio n2 / n1; the angle is its arcsin, in degrees.")
    return wrong(f"your angle is {off_by(value, expected)}. At the critical angle the refracted ray grazes "
                 f"the surface (theta2 = 90 degrees): n1 sin(theta_c) = n2 sin 90.")


# -- §17.3 ---------------------------------------------------------------------------------------------

_STORED_SHADOW = {"P": SHADOW_POINT, "sphere": SHADOW_SPHERE, "lights": SHADOW_LIGHTS}


@memo
def _shadow_kinds(p):
    """(blocked answer, {light: kind}) with kind one of 'sphere' (blocked by it), 'below' (L . N <= 0),
    'between' (lit, the sphere beyond the light on the same line), 'lit'."""
    scene = rt.Scene([Sphere(*p["sphere"], Material()), Plane((0, 0, 0), (0, 0, 1), Material())],
                     [Light(q) for q in p["lights"]])
    blocked = rt.in_shadow(scene, [p["P"]], [[0.0, 0.0, 1.0]])[0]
    sphere = Sphere(*p["sphere"], Material())
    P = _a(p["P"])
    kinds = {}
    for k, q in enumerate(p["lights"]):
        D = _a(q) - P
        t = float(sphere.intersect(P[None], D[None])[0])
        if D[2] <= 0:
            kinds[k] = "below"
        elif blocked[k]:
            kinds[k] = "sphere"
        elif np.isfinite(t) and t > 1:
            kinds[k] = "between"
        else:
            kinds[k] = "lit"
    return sorted(int(k) for k in np.flatnonzero(blocked)), kinds


@memo
def _shadow_answers(p):
    expected, kinds = _shadow_kinds(p)
    e = set(expected)
    below = {k for k, v in kinds.items() if v == "below"}
    between = {k for k, v in kinds.items() if v == "between"}
    slips = {"the lit lights": sorted(set(kinds) - e), "continued past the light": sorted(e | between),
             "light below the floor forgotten": sorted(e - below), "both": sorted((e - below) | between)}
    return expected, slips


def _shadow_generate(rng) -> dict:
    P = _a([rng.integers(-2, 3), rng.integers(-2, 3), 0])
    up = _a([rng.integers(-1, 2), rng.integers(-1, 2), rng.integers(2, 4)])
    C, r = P + up, float(_pick(rng, (0.5, 0.6, 0.7, 0.8)))
    lights = [P + 2 * up, P + 0.5 * up,
              _a([P[0] + rng.integers(-3, 4), P[1] + rng.integers(-3, 4), -rng.integers(1, 3)])]
    for _ in range(50):
        free = _a([P[0] + rng.integers(-3, 4), P[1] + rng.integers(-3, 4), rng.integers(1, 6)])
        u = (free - P) / np.linalg.norm(free - P)
        if np.linalg.norm((C - P) - ((C - P) @ u) * u) > r + 0.4:
            break
    lights.append(free)
    order = rng.permutation(4)
    return {"P": _tup(P), "sphere": (_tup(C), r), "lights": tuple(_tup(lights[i] + 0.0) for i in order)}


def _shadow_ok(p):
    kinds = sorted(_shadow_kinds(p)[1].values())
    if kinds != ["below", "between", "lit", "sphere"]:
        return "the lights are not one of each kind (blocked by the sphere, below the floor, between, lit)"
    P, (C, r) = _a(p["P"]), p["sphere"]
    for q in p["lights"]:
        D = _a(q) - P
        u = D / np.linalg.norm(D)
        miss = float(np.linalg.norm((_a(C) - P) - ((_a(C) - P) @ u) * u))
        if abs(miss - r) < 0.3:
            return "a shadow ray grazes the sphere"
        if np.linalg.norm(_a(q) - _a(C)) < r + 0.2:
            return "a light is (almost) inside the sphere"
    return None


def _shadow_statement(p) -> str:
    (C, r) = p["sphere"]
    return (f"The point P = {fmt(p['P'], 5)} lies on the floor z = 0 (normal (0, 0, 1)); above it hangs an opaque "
            f"sphere of centre {fmt(C, 5)} and radius {fmt(r)}. The lights are "
            + ", ".join(f"L{k} = {fmt(q, 5)}" for k, q in enumerate(p["lights"]))
            + ". Send a shadow ray from P to each light: which lights does P not receive? Give the list of their "
              "numbers, e.g. [1, 3] (Goldman §17.3).")


def _shadow_steps(p) -> str:
    P, (C, r) = _a(p["P"]), p["sphere"]
    sphere = Sphere(C, r, Material())
    lines = []
    for k, q in enumerate(p["lights"]):
        D = _a(q) - P
        roots = sphere.hits(P[None], D[None])[0]
        roots = [float(t) for t in roots if np.isfinite(t)]
        if D[2] <= 0:
            why = f"L . N = {fmt(D[2])} <= 0: the light is below the floor, blocked by the surface itself"
        elif not roots:
            why = "the line P + t (L - P) misses the sphere: lit"
        else:
            span = ", ".join(_f6(t) for t in roots)
            why = (f"the line meets the sphere at t = {span}; "
                   + ("a root lies in (0, 1): blocked" if any(0 < t < 1 for t in roots) else
                      "no root in (0, 1), the sphere is beyond the light: lit"))
        lines.append(f"{k + 1}. L{k} - P = {fmt(D)}: {why}.")
    lines.append(f"{len(lines) + 1}. Blocked: {_shadow_answers(p)[0]}.")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_SHADOW, generate=_shadow_generate, answer=lambda p: _shadow_answers(p)[0],
               slips=lambda p: _shadow_answers(p)[1], statement=_shadow_statement, steps=_shadow_steps,
               same=lambda a, b: sorted(a) == sorted(b), well_posed=_shadow_ok)
def check_blocked_lights(answer, p) -> Result:
    """Check which lights the shadow rays from the surface point find blocked, by the sphere or by
    the surface itself (Goldman §17.3).

    Recognises the shadow ray continued past the light (a light hangs between P and the sphere),
    a light behind the surface forgotten, and the lit lights given instead of the blocked ones.
    """
    n = len(p["lights"])
    if is_unanswered(answer):
        return unanswered("the list of the blocked lights' numbers, e.g. [1, 3]")
    try:
        items = [answer] if np.isscalar(answer) else list(answer)
        got = {int(x) for x in items}
        if any(float(x) != int(x) for x in items):
            raise ValueError
    except (TypeError, ValueError, OverflowError):
        return wrong(f"give a list of light numbers (0 to {n - 1}), e.g. [1, 3]; you gave {quote(answer)}.")
    if not got <= set(range(n)):
        return wrong(f"the lights are numbered 0 to {n - 1}; you gave {quote(sorted(got))}.")
    expected_list, kinds = _shadow_kinds(p)
    expected = set(expected_list)
    name = {v: k for k, v in kinds.items()}
    if got == expected:
        return correct(f"the shadow ray to L{name['sphere']} passes through the sphere before reaching the light, and "
                       f"L{name['below']} is below the floor (L . N < 0), so the floor itself hides it; "
                       f"L{name['lit']} is seen past the sphere, and L{name['between']} hangs between P and the "
                       f"sphere, so the sphere beyond it casts no shadow.")
    lit = set(range(n)) - expected
    between, below = {name["between"]}, {name["below"]}
    if got == lit:
        return wrong("those are the lights P does receive; the question asks for the blocked ones.")
    if got == expected | between:
        return wrong(f"L{name['between']} is not blocked: the shadow ray runs from P to the light and stops there "
                     f"(0 < t < 1 with direction L - P); the sphere lies beyond L{name['between']}, so it casts no "
                     f"shadow on P from that light.")
    if got == expected - below:
        return wrong("a light below the floor cannot light P: check L . N for each light first: where it is <= 0 "
                     "the surface itself is between the point and the light.")
    if got == (expected - below) | between:
        return wrong("two things to check: a shadow ray stops at its light (t < 1 with direction L - P), and a light "
                     "behind the surface (L . N <= 0) never lights the point.")
    return wrong(f"{len(got ^ expected)} of the {n} lights are classified wrongly. For each light, "
                 f"check L . N at P, then solve |P + t (L - P) - C|^2 = r^2 for t: the light is blocked by the sphere "
                 f"if a root lies in (0, 1).")


# -- §17.2 ---------------------------------------------------------------------------------------------

@memo
def _tree_answers(p):
    d, k = p["depth"], p["lights"]
    nodes = rt.ray_tree_size(d)
    return rt.ray_tree_size(d, k), {"shadow rays forgotten": nodes, "shadow rays only": nodes * k,
                                    "depth off by one": rt.ray_tree_size(d + 1, k), "one level": 2 ** d}


def _tree_ok(p):
    d, k = p["depth"], p["lights"]
    ans, slips = _tree_answers(p)
    groups = [[ans], [slips["shadow rays forgotten"]], [slips["shadow rays only"]],
              [rt.ray_tree_size(d - 1, k), rt.ray_tree_size(d + 1, k)], [2 ** d, 2 ** (d + 1)]]
    if not _apart(groups, 0.5):
        return "two recognised counts coincide"
    return None


def _tree_statement(p) -> str:
    return (f"A recursive ray tracer follows, at every hit, one reflected and one refracted ray, down to recursion depth "
            f"{p['depth']} (the primary ray is depth 0), and sends a shadow ray to each of {p['lights']} lights from "
            f"every point a ray hits. At most how many rays (primary, reflected, refracted and shadow rays together) can "
            f"one pixel's ray tree hold? (Goldman §17.2)")


def _tree_steps(p) -> str:
    d, k = p["depth"], p["lights"]
    nodes = rt.ray_tree_size(d)
    return (f"1. Level j of the binary tree holds 2^j rays, j = 0, ..., {d}: "
            f"{' + '.join(str(2 ** j) for j in range(d + 1))} = 2^{d + 1} - 1 = {nodes}.\n"
            f"2. Each of them can send {k} shadow rays: {nodes} x {k} = {nodes * k}.\n"
            f"3. Together {nodes} x (1 + {k}) = {rt.ray_tree_size(d, k)}.")


@DECK.exercise(stored={"depth": TREE_DEPTH, "lights": TREE_LIGHTS},
               generate=lambda rng: {"depth": int(rng.integers(2, 7)), "lights": int(rng.integers(1, 6))},
               answer=lambda p: _tree_answers(p)[0], slips=lambda p: _tree_answers(p)[1],
               statement=_tree_statement, steps=_tree_steps, same=within(0.5), well_posed=_tree_ok)
def check_ray_tree_size(answer, p) -> Result:
    """Check the number of rays of a full ray tree of the given depth with shadow rays to every light
    (Goldman §17.2).

    Recognises the shadow rays forgotten, the shadow rays alone, the depth off by one, and 2^d.
    """
    value, err = read_number(answer, "your count", "whole number of rays")
    if err is not None:
        return err
    d, k = p["depth"], p["lights"]
    expected = rt.ray_tree_size(d, k)
    nodes = rt.ray_tree_size(d)
    if value == expected:
        return correct(f"a binary tree of depth {d} has 2^{d + 1} - 1 = {nodes} rays, and each of "
                       f"them can send {k} shadow rays: {nodes} x {1 + k} = {expected}.")
    if value == nodes:
        return wrong("that counts the primary, reflected and refracted rays; add the shadow rays, one per light "
                     "from every hit point.")
    if value == nodes * k:
        return wrong("that counts the shadow rays only; add the rays of the tree itself.")
    if value in (rt.ray_tree_size(d - 1, k), rt.ray_tree_size(d + 1, k)):
        return wrong("your depth is off by one: the primary ray is depth 0, so a tree of depth d has levels "
                     "0, 1, ..., d, with 2^k rays on level k.")
    if value in (2 ** d, 2 ** (d + 1)):
        return wrong("that is the number of rays on one level; the tree holds all levels 0 to d: 1 + 2 + 4 + ... "
                     "+ 2^d, and shadow rays besides.")
    return wrong(f"your count is {off_by(value, expected)}. Count the levels 0 to d of the binary tree (2^k rays on "
                 f"level k), then the shadow rays: one per light from each of them.")


@memo
def _colour_answers(p):
    c = {k: _a(v) for k, v in p.items()}
    expected = c["floor_local"] + c["floor_reflect"] * (c["sphere_local"] + c["sphere_reflect"] * c["background"])
    return expected, {
        "depth 1": c["floor_local"] + c["floor_reflect"] * c["sphere_local"],
        "weights not multiplied": c["floor_local"] + c["floor_reflect"] * c["sphere_local"]
        + c["sphere_reflect"] * c["background"],
        "weights left out": c["floor_local"] + c["sphere_local"] + c["background"]}


def _colour_generate(rng) -> dict:
    return {"floor_local": _tenths(rng, 0.0, 0.3, 3), "floor_reflect": _tenths(rng, 0.3, 0.8),
            "sphere_local": _tenths(rng, 0.0, 0.9, 3), "sphere_reflect": _tenths(rng, 0.3, 0.7),
            "background": _tenths(rng, 0.1, 1.0, 3)}


def _colour_statement(p) -> str:
    return (f"A pixel's primary ray hits a shiny floor: local colour {fmt(p['floor_local'], 5)}, reflection "
            f"coefficient k_r = {fmt(p['floor_reflect'])}. Its reflected ray hits a sphere: local colour "
            f"{fmt(p['sphere_local'], 5)}, k_r = {fmt(p['sphere_reflect'])}. The sphere's reflected ray "
            f"hits nothing and sees the background {fmt(p['background'], 5)}. Nothing is transparent. With "
            f"I = I_local + k_r I_reflected, what RGB colour does the pixel get at recursion depth 2? Give [r, g, b] "
            f"(Goldman §17.2).")


def _colour_steps(p) -> str:
    c = {k: _a(v) for k, v in p.items()}
    sphere = c["sphere_local"] + c["sphere_reflect"] * c["background"]
    return (f"1. The deepest hit, the sphere: {fmt(p['sphere_local'])} + {fmt(p['sphere_reflect'])} x "
            f"{fmt(p['background'])} = {_f6(sphere)}.\n"
            f"2. The floor: {fmt(p['floor_local'])} + {fmt(p['floor_reflect'])} x {_f6(sphere)} = "
            f"{_f6(_colour_answers(p)[0])}.")


@DECK.exercise(stored=TREE_COLOURS, generate=_colour_generate, answer=lambda p: _colour_answers(p)[0],
               slips=lambda p: _colour_answers(p)[1], statement=_colour_statement, steps=_colour_steps,
               same=within(1e-4))
def check_ray_tree_colour(answer, p) -> Result:
    """Check I = I_floor + k_floor (I_sphere + k_sphere I_background) for the ray tree of the exercise
    (Goldman §17.2).

    Recognises the depth-1 colour (the background not reached), the weights not multiplied along the
    path, and the weights left out.
    """
    got, err = _read_vector(answer, "your colour", 3, "the colour as [r, g, b]")
    if err is not None:
        return err
    expected, slips = _colour_answers(p)
    tol = 1e-4
    if _close(got, expected, tol):
        return correct(f"I = {fmt(expected)}: the background reaches the pixel with weight "
                       f"{fmt(float(p['floor_reflect'] * p['sphere_reflect']))} = k_r(floor) x k_r(sphere), the "
                       f"product of the coefficients along the path.")
    if _close(got, slips["depth 1"], tol):
        return wrong("that is the colour at depth 1: the sphere's reflected ray (depth 2) is also followed, and it "
                     "brings the background.")
    if _close(got, slips["weights not multiplied"], tol):
        return wrong("the background's light reaches the pixel through two reflections: its weight is the product "
                     "of both coefficients, k_r(floor) x k_r(sphere), not k_r(sphere) alone.")
    if _close(got, slips["weights left out"], tol):
        return wrong("you added the colours without the reflection coefficients: I = I_local + k_r I_reflected at "
                     "every hit.")
    return wrong(f"your colour is {_dist(got, expected)}; apply I = I_local + k_r I_reflected from the deepest "
                 f"hit upwards: first the sphere's colour, then the floor's.")


#: Deal another instance of an exercise (``deal("check_critical_angle")``, or with ``seed=``; 0 is
#: the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


SLIPS = {
    "check_reflected_direction": [[-1 / 3, -0.82667, 0.45333], [1 / 3, 0.50667, -0.88], [0.0504, 0.7062, 0.7062],
                                  list(REFLECT_D)],
    "check_refracted_direction": [[0.6, 0.0, -0.8], [0.75, 0.0, -0.66144], [-0.48, 0.0, -0.87727],
                                  [0.49237, 0.0, -0.87039], [0.6, 0.0, 0.8]],
    "check_critical_angle": [41.41, 38.68, 0.848, 0.75],
    "check_blocked_lights": [[1, 2], [0, 2, 3], [0], [0, 2]],
    "check_ray_tree_size": [31, 93, 60, 252, 16],
    "check_ray_tree_colour": [[0.58, 0.22, 0.22], [0.68, 0.42, 0.72], [1.1, 0.7, 1.3]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

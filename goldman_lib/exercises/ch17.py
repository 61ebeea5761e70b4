"""Exercise checkers for chapter 17, recursive ray tracing (Goldman §17.2-17.5).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers each checker recognises.  ``None`` or ``...`` means "not answered yet".
Every exercise uses other directions, indices, lights and depths than the chapter's worked examples.
The book has no programming project for chapter 17.

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
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, read_points, unanswered, wrong, is_unanswered
from goldman_lib.exercises import read_vector as _read_vector, all_close as _close, distance_text as _dist  # shared readers
from goldman_lib.lighting import Light, Material
from goldman_lib.simple_surfaces import Plane, Sphere

__all__ = ["PROBLEMS", "SLIPS", "REFLECT_D", "REFLECT_N", "REFRACT_D", "REFRACT_N", "REFRACT_N1", "REFRACT_N2",
           "CRITICAL_N1", "CRITICAL_N2", "SHADOW_POINT", "SHADOW_SPHERE", "SHADOW_LIGHTS", "TREE_DEPTH", "TREE_LIGHTS",
           "TREE_COLOURS", "check_reflected_direction", "check_refracted_direction", "check_critical_angle",
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


PROBLEMS = {
    "check_reflected_direction": (
        f"A ray travelling in the direction d = (1/3, 2/3, -2/3) meets a mirror whose normal there points along "
        f"{fmt(REFLECT_N, 5)}. In which unit direction does the reflected ray leave? Give [x, y, z] to 4 decimals "
        f"(Goldman §17.4)."),
    "check_refracted_direction": (
        f"A ray in air (index {fmt(REFRACT_N1)}) travelling in the unit direction d = {fmt(REFRACT_D, 5)} meets the flat "
        f"surface z = 0 of a transparent plastic of index {fmt(REFRACT_N2)} (normal {fmt(REFRACT_N, 5)}). In which unit "
        f"direction does the refracted ray travel inside? Give [x, y, z] to 4 decimals (Goldman §17.5)."),
    "check_critical_angle": (
        f"Light travels inside a block of flint glass (index of refraction {fmt(CRITICAL_N1)}) towards its flat face, "
        f"on the other side of which is a liquid of index {fmt(CRITICAL_N2)}. Beyond which angle of incidence "
        f"(measured from the normal) is the light totally internally reflected? Give the critical angle in degrees, "
        f"to 2 decimals (Goldman §17.5)."),
    "check_blocked_lights": (
        f"The point P = {fmt(SHADOW_POINT, 5)} lies on the floor z = 0 (normal (0, 0, 1)); above it hangs an opaque "
        f"sphere of centre {fmt(SHADOW_SPHERE[0], 5)} and radius {fmt(SHADOW_SPHERE[1])}. The lights are "
        + ", ".join(f"L{k} = {fmt(p, 5)}" for k, p in enumerate(SHADOW_LIGHTS))
        + ". Send a shadow ray from P to each light: which lights does P not receive? Give the list of their "
          "numbers, e.g. [1, 3] (Goldman §17.3)."),
    "check_ray_tree_size": (
        f"A recursive ray tracer follows, at every hit, one reflected and one refracted ray, down to recursion depth "
        f"{TREE_DEPTH} (the primary ray is depth 0), and sends a shadow ray to each of {TREE_LIGHTS} lights from "
        f"every point a ray hits. At most how many rays (primary, reflected, refracted and shadow rays together) can "
        f"one pixel's ray tree hold? (Goldman §17.2)"),
    "check_ray_tree_colour": (
        f"A pixel's primary ray hits a shiny floor: local colour {fmt(TREE_COLOURS['floor_local'], 5)}, reflection "
        f"coefficient k_r = {fmt(TREE_COLOURS['floor_reflect'])}. Its reflected ray hits a sphere: local colour "
        f"{fmt(TREE_COLOURS['sphere_local'], 5)}, k_r = {fmt(TREE_COLOURS['sphere_reflect'])}. The sphere's reflected ray "
        f"hits nothing and sees the background {fmt(TREE_COLOURS['background'], 5)}. Nothing is transparent. With "
        f"I = I_local + k_r I_reflected, what RGB colour does the pixel get at recursion depth 2? Give [r, g, b] "
        f"(Goldman §17.2)."),
}


# -- reading answers ---------------------------------------------------------------------------------

# -- §17.4 ---------------------------------------------------------------------------------------------

def check_reflected_direction(answer) -> Result:
    """Check the mirror direction R = d - 2 (d · N) N of a ray off a mirror with unit normal N
    (Goldman §17.4).

    Recognises -R (the mirror image of d rather than of -d), a sign slip d + 2 (d . N) N (no bounce),
    the normal left unnormalised, and the incoming direction itself.
    """
    got, err = _read_vector(answer, "your direction", 3, "the reflected direction as [x, y, z]")
    if err is not None:
        return err
    d = np.array(REFLECT_D)
    N = lighting.unit_rows(np.array([REFLECT_N]))[0]
    expected = lighting.reflect(-d[None], N[None])[0]
    tol = 2e-4
    if _close(got, expected, tol):
        return correct(f"R = d - 2 (d . N) N = {fmt(expected)}: the angle of reflection equals the angle of "
                       f"incidence ({fmt(math.degrees(math.acos(float(-d @ N))), 4)} degrees from the normal), and "
                       f"R lies in the plane of d and N.")
    if _close(got, -expected, tol):
        return wrong("that points back towards the mirror: you reflected d itself, not -d. The ray leaves along the "
                     "mirror image of -d about N, reflect(-d, N) = d - 2 (d . N) N.")
    if _close(got, d + 2 * (d @ N) * N, tol):
        return wrong("with d + 2 (d . N) N the sign of the correction is wrong: the ray keeps going into the mirror. "
                     "Since d . N < 0, R = d - 2 (d . N) N turns the normal component of d around.")
    raw = np.array(REFLECT_N)
    if _close(got, d - 2 * (d @ raw) * raw, tol) or _close(got, lighting.unit_rows((d - 2 * (d @ raw) * raw)[None])[0], tol):
        return wrong("you used the normal (0, 3, 4) as it is; the formula R = d - 2 (d . N) N needs a unit normal: "
                     "divide it by its length 5 first.")
    if _close(got, d, tol):
        return wrong("that is the incoming direction: a mirror turns the ray around its normal component.")
    return wrong(f"your direction is {_dist(got, expected)} from the reflected one; check that it has length 1, "
                 f"that the angle to N equals the angle between -d and N, and use R = d - 2 (d . N) N with a unit N.")


# -- §17.5 ---------------------------------------------------------------------------------------------

def check_refracted_direction(answer) -> Result:
    """Check the refracted direction by Snell's law, n1 sin(theta1) = n2 sin(theta2) (Goldman §17.5).

    Recognises no bending, the ratio of indices upside down, bending to the other side of the normal,
    angles (not sines) divided by the index, and the reflected ray.
    """
    got, err = _read_vector(answer, "your direction", 3, "the refracted direction as [x, y, z]")
    if err is not None:
        return err
    d, N = np.array(REFRACT_D), np.array(REFRACT_N)
    expected = np.array(rt.refract(d, N, REFRACT_N1, REFRACT_N2))
    tol = 2e-4
    s1 = float(np.linalg.norm(np.cross(d, N)))
    if _close(got, expected, tol):
        return correct(f"T = {fmt(expected)}: sin(theta2) = {fmt(REFRACT_N1)} x {fmt(s1)} / {fmt(REFRACT_N2)}, so the "
                       f"ray bends towards the normal as it enters the denser medium.")
    if _close(got, d, tol):
        return wrong("that is the incoming direction: the ray changes speed at the surface and bends (the indices "
                     "differ), so sin(theta2) = (n1 / n2) sin(theta1).")
    upside = rt.refract(d, N, REFRACT_N2, REFRACT_N1)
    if upside is not None and _close(got, upside, tol):
        return wrong("you used the ratio of the indices upside down: n1 sin(theta1) = n2 sin(theta2), so "
                     "sin(theta2) = (n1 / n2) sin(theta1) with n1 the medium the ray comes from; entering the denser "
                     "plastic, the ray bends towards the normal, not away from it.")
    if _close(got, expected * [-1, -1, 1], tol):
        return wrong("your ray crosses to the other side of the normal: the refracted ray goes on forward, keeping "
                     "the sideways direction of d (it lies in the plane of d and N); only its angle to the normal "
                     "changes.")
    theta2 = math.radians(math.degrees(math.asin(s1)) / (REFRACT_N2 / REFRACT_N1))
    if _close(got, [math.sin(theta2), 0.0, -math.cos(theta2)], tol):
        return wrong("you divided the angle by the ratio of the indices; Snell's law divides the sines: "
                     "n1 sin(theta1) = n2 sin(theta2).")
    if _close(got, lighting.reflect(-d[None], N[None])[0], tol):
        return wrong("that is the reflected ray (it leaves the surface); the refracted ray goes on through it, "
                     "into the plastic.")
    return wrong(f"your direction is {_dist(got, expected)} from the refracted one; check that it is a unit "
                 f"vector going into the surface (z < 0) and that sin of its angle to the normal is "
                 f"(n1 / n2) sin(theta1).")


def check_critical_angle(answer) -> Result:
    """Check the critical angle of total internal reflection, in degrees, arcsin(n2 / n1) (Goldman §17.5).

    Recognises the angle from the surface (arccos), the critical angle into air (arcsin(1 / 1.6)),
    radians, and the ratio's sine without arcsin.
    """
    value, err = read_number(answer, "your critical angle", "number of degrees")
    if err is not None:
        return err
    expected = rt.critical_angle(CRITICAL_N1, CRITICAL_N2)
    tol = 0.01
    if abs(value - expected) <= tol:
        return correct(f"sin(theta_c) = n2 / n1 = {fmt(CRITICAL_N2 / CRITICAL_N1)}, theta_c = {fmt(expected, 5)} "
                       f"degrees: past it sin(theta2) would exceed 1, so no refracted ray exists.")
    if abs(value - (90 - expected)) <= tol:
        return wrong("that is the angle measured from the surface, not from the normal: the angles of Snell's law "
                     "are measured from the normal, so take arcsin, not arccos, of the ratio of the indices.")
    air = rt.critical_angle(CRITICAL_N1, 1.0)
    if abs(value - air) <= tol:
        return wrong("that is the critical angle from this glass into air (index 1); here the glass meets a liquid "
                     "of index 1.2: sin(theta_c) = n2 / n1.")
    if abs(value - math.radians(expected)) <= 1e-3:
        return wrong("that is in radians; give degrees.")
    if abs(value - CRITICAL_N2 / CRITICAL_N1) <= 1e-3:
        return wrong("that is sin(theta_c), the ratio n2 / n1; the angle is its arcsin, in degrees.")
    return wrong(f"your angle is {off_by(value, expected)}. At the critical angle the refracted ray grazes "
                 f"the surface (theta2 = 90 degrees): n1 sin(theta_c) = n2 sin 90.")


# -- §17.3 ---------------------------------------------------------------------------------------------

def _shadow_answer():
    scene = rt.Scene([Sphere(*SHADOW_SPHERE, Material()), Plane((0, 0, 0), (0, 0, 1), Material())],
                     [Light(p) for p in SHADOW_LIGHTS])
    return set(np.flatnonzero(rt.in_shadow(scene, [SHADOW_POINT], [[0.0, 0.0, 1.0]])[0]).tolist())


def check_blocked_lights(answer) -> Result:
    """Check which lights the shadow rays from the surface point find blocked, by the sphere or by
    the surface itself (Goldman §17.3).

    Recognises the shadow ray continued past the light (L2's light hangs between P and the sphere),
    a light behind the surface forgotten, and the lit lights given instead of the blocked ones.
    """
    if is_unanswered(answer):
        return unanswered("the list of the blocked lights' numbers, e.g. [1, 3]")
    try:
        items = [answer] if np.isscalar(answer) else list(answer)
        got = {int(x) for x in items}
        if any(float(x) != int(x) for x in items):
            raise ValueError
    except (TypeError, ValueError, OverflowError):
        return wrong(f"give a list of light numbers (0 to {len(SHADOW_LIGHTS) - 1}), e.g. [1, 3]; you gave {quote(answer)}.")
    if not got <= set(range(len(SHADOW_LIGHTS))):
        return wrong(f"the lights are numbered 0 to {len(SHADOW_LIGHTS) - 1}; you gave {quote(sorted(got))}.")
    expected = _shadow_answer()
    if got == expected:
        return correct("the shadow ray to L0 passes through the sphere before reaching the light, and L3 is below the "
                       "floor (L . N < 0), so the floor itself hides it; L1 is seen past the sphere, and L2 hangs "
                       "between P and the sphere, so the sphere beyond it casts no shadow.")
    lit = set(range(len(SHADOW_LIGHTS))) - expected
    if got == lit:
        return wrong("those are the lights P does receive; the question asks for the blocked ones.")
    if got == expected | {2}:
        return wrong("L2 is not blocked: the shadow ray runs from P to the light and stops there (0 < t < 1 with "
                     "direction L - P); the sphere lies beyond L2, so it casts no shadow on P from that light.")
    if got == expected - {3}:
        return wrong("a light below the floor cannot light P: check L . N for each light first: where it is <= 0 "
                     "the surface itself is between the point and the light.")
    if got == (expected - {3}) | {2}:
        return wrong("two things to check: a shadow ray stops at its light (t < 1 with direction L - P), and a light "
                     "behind the surface (L . N <= 0) never lights the point.")
    return wrong(f"{len(got ^ expected)} of the {len(SHADOW_LIGHTS)} lights are classified wrongly. For each light, "
                 f"check L . N at P, then solve |P + t (L - P) - C|^2 = r^2 for t: the light is blocked by the sphere "
                 f"if a root lies in (0, 1).")


# -- §17.2 ---------------------------------------------------------------------------------------------

def check_ray_tree_size(answer) -> Result:
    """Check the number of rays of a full ray tree of the given depth with shadow rays to every light
    (Goldman §17.2).

    Recognises the shadow rays forgotten, the shadow rays alone, the depth off by one, and 2^d.
    """
    value, err = read_number(answer, "your count", "whole number of rays")
    if err is not None:
        return err
    expected = rt.ray_tree_size(TREE_DEPTH, TREE_LIGHTS)
    nodes = rt.ray_tree_size(TREE_DEPTH)
    if value == expected:
        return correct(f"a binary tree of depth {TREE_DEPTH} has 2^{TREE_DEPTH + 1} - 1 = {nodes} rays, and each of "
                       f"them can send {TREE_LIGHTS} shadow rays: {nodes} x {1 + TREE_LIGHTS} = {expected}.")
    if value == nodes:
        return wrong("that counts the primary, reflected and refracted rays; add the shadow rays, one per light "
                     "from every hit point.")
    if value == nodes * TREE_LIGHTS:
        return wrong("that counts the shadow rays only; add the rays of the tree itself.")
    if value in (rt.ray_tree_size(TREE_DEPTH - 1, TREE_LIGHTS), rt.ray_tree_size(TREE_DEPTH + 1, TREE_LIGHTS)):
        return wrong("your depth is off by one: the primary ray is depth 0, so a tree of depth d has levels "
                     "0, 1, ..., d, with 2^k rays on level k.")
    if value in (2 ** TREE_DEPTH, 2 ** (TREE_DEPTH + 1)):
        return wrong("that is the number of rays on one level; the tree holds all levels 0 to d: 1 + 2 + 4 + ... "
                     "+ 2^d, and shadow rays besides.")
    return wrong(f"your count is {off_by(value, expected)}. Count the levels 0 to d of the binary tree (2^k rays on "
                 f"level k), then the shadow rays: one per light from each of them.")


def check_ray_tree_colour(answer) -> Result:
    """Check I = I_floor + k_floor (I_sphere + k_sphere I_background) for the ray tree of the exercise
    (Goldman §17.2).

    Recognises the depth-1 colour (the background not reached), the weights not multiplied along the
    path, and the weights left out.
    """
    got, err = _read_vector(answer, "your colour", 3, "the colour as [r, g, b]")
    if err is not None:
        return err
    c = {k: np.asarray(v, float) for k, v in TREE_COLOURS.items()}
    expected = c["floor_local"] + c["floor_reflect"] * (c["sphere_local"] + c["sphere_reflect"] * c["background"])
    tol = 1e-4
    if _close(got, expected, tol):
        return correct(f"I = {fmt(expected)}: the background reaches the pixel with weight "
                       f"{fmt(float(c['floor_reflect'] * c['sphere_reflect']))} = k_r(floor) x k_r(sphere), the "
                       f"product of the coefficients along the path.")
    if _close(got, c["floor_local"] + c["floor_reflect"] * c["sphere_local"], tol):
        return wrong("that is the colour at depth 1: the sphere's reflected ray (depth 2) is also followed, and it "
                     "brings the background.")
    if _close(got, c["floor_local"] + c["floor_reflect"] * c["sphere_local"] + c["sphere_reflect"] * c["background"], tol):
        return wrong("the background's light reaches the pixel through two reflections: its weight is the product "
                     "of both coefficients, k_r(floor) x k_r(sphere), not k_r(sphere) alone.")
    if _close(got, c["floor_local"] + c["sphere_local"] + c["background"], tol):
        return wrong("you added the colours without the reflection coefficients: I = I_local + k_r I_reflected at "
                     "every hit.")
    return wrong(f"your colour is {_dist(got, expected)}; apply I = I_local + k_r I_reflected from the deepest "
                 f"hit upwards: first the sphere's colour, then the floor's.")


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

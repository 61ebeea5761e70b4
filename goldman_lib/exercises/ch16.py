"""Exercise checkers for chapter 16, colour and intensity (Goldman §16.2-16.6).

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers each checker recognises.  ``None`` or ``...`` means "not answered yet".
Every exercise uses other points, lights and materials than the chapter's worked examples.  The
lighting model is :mod:`goldman_lib.lighting`: diffuse ``I_p k_d (L . N)``, specular
``I_p k_s (R . V)^n`` with ``R = 2 (L . N) N - L`` (no ``L . N`` factor, no attenuation), all unit
vectors pointing away from the surface point.

>>> print(PROBLEMS["check_mirror_direction"])   # doctest: +ELLIPSIS
At a surface point the unit vector towards the light is L = (0.6, 0, 0.8) and the surface normal is along N = (1, 1, 1) (not unit). ...
>>> check_mirror_direction([-1 / 3, -14 / 15, -2 / 15])
Not yet: that is -R, L - 2 (L·N) N, the mirror image pointing into the surface; R = 2 (L·N) N - L points away from it, on the other side of the normal from L.
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import lighting
from goldman_lib.exercises import guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, read_points, wrong
from goldman_lib.exercises import read_vector as _read_vector, all_close as _close, distance_text as _dist  # shared readers
from goldman_lib.lighting import Light, Material

__all__ = ["PROBLEMS", "SLIPS", "MIX_LIGHTS", "MIX_SURFACE", "DIFFUSE_POINT", "DIFFUSE_NORMAL", "DIFFUSE_LIGHT",
           "DIFFUSE_KD", "DIFFUSE_I", "MIRROR_L", "MIRROR_N", "SPECULAR_LIGHT", "SPECULAR_EYE", "SPECULAR_KS",
           "SPECULAR_N", "HALF_WIDTH", "TOTAL_MATERIAL", "TOTAL_LIGHTS", "TOTAL_AMBIENT", "TOTAL_EYE",
           "check_reflected_colour", "check_diffuse", "check_mirror_direction", "check_specular",
           "check_highlight_exponent", "check_total_intensity"]

#: Exercise 1 (§16.2): two lights (colour, intensity) on a surface of colour MIX_SURFACE, k_d = 1, cos = 1.
MIX_LIGHTS = (((0.9, 0.3, 0.0), 0.8), ((0.2, 0.5, 1.0), 0.6))
MIX_SURFACE = (0.5, 1.0, 0.25)
#: Exercise 2 (§16.4): a point, its (non-unit) normal, a point light, k_d and I_p.
DIFFUSE_POINT = (1.0, 2.0, 0.0)
DIFFUSE_NORMAL = (0.0, 3.0, 4.0)
DIFFUSE_LIGHT = (3.0, 2.0, 4.0)
DIFFUSE_KD = 0.8
DIFFUSE_I = 1.5
#: Exercise 3 (§16.5): the unit vector to the light and a (non-unit) normal.
MIRROR_L = (0.6, 0.0, 0.8)
MIRROR_N = (1.0, 1.0, 1.0)
#: Exercise 4 (§16.5): the origin with normal (0, 0, 1), a light, an eye, k_s and n (I_p = 1).
SPECULAR_LIGHT = (2.0, 0.0, 2.0)
SPECULAR_EYE = (-1.0, 1.0, 3.0)
SPECULAR_KS = 0.9
SPECULAR_N = 8
#: Exercise 5 (§16.5): the angle (degrees) from the mirror direction where the highlight is at half strength.
HALF_WIDTH = 12.0
#: Exercise 6 (§16.3 and §16.6): the origin with normal (0, 0, 1), seen from TOTAL_EYE.
TOTAL_MATERIAL = dict(colour=(0.9, 0.5, 0.2), ambient=0.3, diffuse=0.7, specular=0.5, exponent=4)
TOTAL_LIGHTS = (((0.0, 3.0, 4.0), (1.0, 1.0, 1.0), 1.0), ((4.0, 0.0, 3.0), (1.0, 0.5, 0.5), 1.2))
TOTAL_AMBIENT = 0.4
TOTAL_EYE = (0.0, 0.0, 4.0)

_P0 = np.zeros((1, 3))
_UP = np.array([[0.0, 0.0, 1.0]])


def _t(v) -> str:
    return fmt(v)


PROBLEMS = {
    "check_reflected_colour": (
        f"Two lights shine on the same point of a matte surface of colour C = {_t(MIX_SURFACE)} (k_d = 1), both "
        f"straight along the normal (L . N = 1): one of colour {_t(MIX_LIGHTS[0][0])} at intensity "
        f"{fmt(MIX_LIGHTS[0][1])}, the other of colour {_t(MIX_LIGHTS[1][0])} at intensity {fmt(MIX_LIGHTS[1][1])}. "
        f"What RGB light does the point reflect (the diffuse terms only)? Give [r, g, b] (Goldman §16.2)."),
    "check_diffuse": (
        f"The point P = {_t(DIFFUSE_POINT)} of a surface has the normal N = {_t(DIFFUSE_NORMAL)} (not unit). A point "
        f"light of intensity I_p = {fmt(DIFFUSE_I)} stands at {_t(DIFFUSE_LIGHT)}; the surface has k_d = "
        f"{fmt(DIFFUSE_KD)}. Compute Lambert's diffuse intensity I_p k_d (L . N) at P, to 4 decimals "
        f"(Goldman §16.4)."),
    "check_mirror_direction": (
        f"At a surface point the unit vector towards the light is L = {_t(MIRROR_L)} and the surface normal is "
        f"along N = {_t(MIRROR_N)} (not unit). Compute the mirror direction R of L about the normal, the unit "
        f"vector Phong's specular term compares with the direction to the eye. Give [x, y, z], to 4 decimals "
        f"(Goldman §16.5)."),
    "check_specular": (
        f"The origin lies on a surface with unit normal N = (0, 0, 1). A point light of intensity 1 stands at "
        f"{_t(SPECULAR_LIGHT)} and the eye at {_t(SPECULAR_EYE)}; the surface has k_s = {fmt(SPECULAR_KS)} and the "
        f"specular exponent n = {SPECULAR_N}. Compute Phong's specular intensity k_s (R . V)^n at the origin, to 4 "
        f"decimals (Goldman §16.5)."),
    "check_highlight_exponent": (
        f"Which specular exponent n makes a Phong highlight fall to half its peak strength when the eye is "
        f"{fmt(HALF_WIDTH)} degrees away from the mirror direction R (that is, (R . V)^n = 1/2 at that angle)? "
        f"Give n to 2 decimals (Goldman §16.5)."),
    "check_total_intensity": (
        f"The origin lies on a surface with unit normal N = (0, 0, 1), seen from the eye at {_t(TOTAL_EYE)}. Its "
        f"material has colour C = {_t(TOTAL_MATERIAL['colour'])}, k_a = {fmt(TOTAL_MATERIAL['ambient'])}, "
        f"k_d = {fmt(TOTAL_MATERIAL['diffuse'])}, k_s = {fmt(TOTAL_MATERIAL['specular'])}, n = "
        f"{TOTAL_MATERIAL['exponent']}, and a white highlight (the specular term takes the light's colour). The "
        f"ambient light is I_a = {fmt(TOTAL_AMBIENT)} (white); light 1 stands at {_t(TOTAL_LIGHTS[0][0])}, white, "
        f"intensity {fmt(TOTAL_LIGHTS[0][2])}; light 2 at {_t(TOTAL_LIGHTS[1][0])}, colour "
        f"{_t(TOTAL_LIGHTS[1][1])}, intensity {fmt(TOTAL_LIGHTS[1][2])}. Compute the total intensity "
        f"I_a k_a C + sum over the lights of I_p (k_d C (L . N) + k_s (R . V)^n), then the colour a display "
        f"shows, each channel clipped to [0, 1]. Give the displayed [r, g, b] to 4 decimals "
        f"(Goldman §16.3 and §16.6)."),
}


# -- reading answers ---------------------------------------------------------------------------------

# -- §16.2 ---------------------------------------------------------------------------------------------

def check_reflected_colour(answer) -> Result:
    """Check the colour C * (I_1 c_1 + I_2 c_2) a surface of colour C reflects under two coloured
    lights (Goldman §16.2).

    Recognises the lights' colours without their intensities, the light alone (surface colour left
    out), the lights' colours multiplied instead of added, and the surface colour added.
    """
    got, err = _read_vector(answer, "your colour", 3, "the reflected colour as [r, g, b]")
    if err is not None:
        return err
    C = np.array(MIX_SURFACE)
    lights = [Light((0.0, 0.0, 1.0), colour=c, intensity=i) for c, i in MIX_LIGHTS]
    material = Material(colour=MIX_SURFACE, ambient=0.0, diffuse=1.0, specular=0.0)
    expected = lighting.intensity(_P0, _UP, [0.0, 0.0, 1.0], lights, material, ambient_light=0.0)[0]
    incoming = sum(light.rgb for light in lights)
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"the point reflects {fmt(expected)}: the lights add channel by channel to "
                       f"{fmt(incoming)}, and the surface keeps the fraction C of each channel.")
    if _close(got, C * sum(np.array(c) for c, _ in MIX_LIGHTS), tol):
        return wrong("you left out the intensities: each light brings its colour times its intensity I_p.")
    if _close(got, incoming, tol):
        return wrong("that is the light arriving, not the light reflected: the surface reflects only the fraction "
                     "C of each channel (multiply channel by channel by the surface colour).")
    if _close(got, C * lights[0].rgb * lights[1].rgb, tol):
        return wrong("you multiplied the two lights' colours; light adds: the light arriving is the sum "
                     "I_1 c_1 + I_2 c_2, channel by channel.")
    if _close(got, incoming + C, tol) or _close(got, np.clip(incoming + C, 0, 1), tol):
        return wrong("you added the surface colour; a surface filters light: multiply each channel of the light "
                     "by the surface's fraction C of that channel.")
    return wrong(f"your colour is {_dist(got, expected)}; add the two lights channel by channel (colour "
                 f"times intensity), then multiply channel by channel by C.")


# -- §16.4 ---------------------------------------------------------------------------------------------

def check_diffuse(answer) -> Result:
    """Check the diffuse intensity I_p k_d (L · N), with L the unit vector from the surface point to the
    light and N normalised (Goldman §16.4).

    Recognises an unnormalised normal, an unnormalised L, L taken from the origin instead of from
    P, and a missing k_d or I_p.
    """
    value, err = read_number(answer, "the diffuse intensity")
    if err is not None:
        return err
    P, N, Lp = (np.array(v) for v in (DIFFUSE_POINT, DIFFUSE_NORMAL, DIFFUSE_LIGHT))
    expected = float(lighting.diffuse([P], [N], Lp, DIFFUSE_KD, DIFFUSE_I)[0])
    scale = DIFFUSE_KD * DIFFUSE_I
    n = N / np.linalg.norm(N)
    tol = 5e-4
    if abs(value - expected) <= tol:
        angle = math.degrees(math.acos(expected / scale))
        return correct(f"the diffuse intensity is {fmt(expected)}: the light arrives {fmt(angle, 3)} degrees "
                       f"from the normal, and Lambert's law scales k_d I_p by the cosine of that angle.")
    if abs(value - scale * float(N @ (Lp - P)) / np.linalg.norm(Lp - P)) <= tol:
        return wrong("your normal is not a unit vector: divide N = (0, 3, 4) by its length 5 before the dot product "
                     "(otherwise L . N is not a cosine).")
    if abs(value - scale * float(n @ (Lp - P))) <= tol:
        return wrong("your L is not a unit vector: L is the direction from P to the light, divided by its length.")
    if abs(value - scale * float(n @ Lp) / np.linalg.norm(Lp)) <= tol:
        return wrong("you took L towards the light from the origin; L points from the surface point P to the light: "
                     "L = (light - P) / |light - P|.")
    if abs(value - expected / DIFFUSE_I) <= tol:
        return wrong(f"you left out the light's intensity I_p = {fmt(DIFFUSE_I)}.")
    if abs(value - expected / DIFFUSE_KD) <= tol:
        return wrong(f"you left out the diffuse coefficient k_d = {fmt(DIFFUSE_KD)}.")
    return wrong(f"your intensity is {off_by(value, expected)}; normalise both L = light - P and N, then "
                 f"multiply I_p k_d by their dot product.")


# -- §16.5 ---------------------------------------------------------------------------------------------

def check_mirror_direction(answer) -> Result:
    """Check the mirror direction R = 2 (L · N) N - L of the unit L about the unit normal N
    (Goldman §16.5).

    Recognises -R (the reflection pointing into the surface), an unnormalised N, and the missing
    factor 2.
    """
    got, err = _read_vector(answer, "your R", 3, "R as [x, y, z]")
    if err is not None:
        return err
    L, N = np.array(MIRROR_L), np.array(MIRROR_N)
    n = N / np.linalg.norm(N)
    expected = lighting.reflect(L, n)
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"R = {fmt(expected)}: a unit vector, making the same angle with N as L does "
                       f"(L . N = R . N = {fmt(float(L @ n))}), in the plane of L and N.")
    if _close(got, -expected, tol):
        return wrong("that is -R, L - 2 (L·N) N, the mirror image pointing into the surface; R = 2 (L·N) N - L "
                     "points away from it, on the other side of the normal from L.")
    if _close(got, 2 * (L @ N) * N - L, tol):
        return wrong("your N is not a unit vector: the formula 2 (L·N) N - L holds for |N| = 1; divide (1, 1, 1) by "
                     "its length first (your R is not a unit vector).")
    if _close(got, (L @ n) * n - L, tol):
        return wrong("you lack the factor 2: (L·N) N - L goes from L to the normal; R goes as far again, "
                     "R = 2 (L·N) N - L.")
    return wrong(f"your R is {_dist(got, expected)}; it should be a unit vector (yours has length "
                 f"{fmt(np.linalg.norm(got), 4)}). Normalise N, then R = 2 (L·N) N - L.")


def check_specular(answer) -> Result:
    """Check the specular intensity k_s (R · V)^n, with R the mirror direction of the unit L and V the
    unit vector to the eye (Goldman §16.5).

    Recognises Blinn's halfway vector (N . H)^n, a missing exponent, an extra L . N factor, and V
    pointing from the eye (R . V < 0 gives 0).
    """
    value, err = read_number(answer, "the specular intensity")
    if err is not None:
        return err
    Lp, E = np.array(SPECULAR_LIGHT), np.array(SPECULAR_EYE)
    expected = float(lighting.specular(_P0, _UP, Lp, E, SPECULAR_KS, SPECULAR_N, 1.0)[0])
    L, V = Lp / np.linalg.norm(Lp), E / np.linalg.norm(E)
    R = lighting.reflect(L, _UP[0])
    rv = float(R @ V)
    H = (L + V) / np.linalg.norm(L + V)
    tol = 5e-4
    if abs(value - expected) <= tol:
        return correct(f"the specular intensity is {fmt(expected)}: the eye is {fmt(math.degrees(math.acos(rv)), 3)} "
                       f"degrees off the mirror direction, and the exponent {SPECULAR_N} makes the highlight fade "
                       f"fast with that angle.")
    if abs(value - SPECULAR_KS * float(H[2]) ** SPECULAR_N) <= tol:
        return wrong("that is Blinn's variant (N·H)^n with the halfway vector H; Phong's term uses the mirror "
                     "direction R = 2 (L·N) N - L and (R·V)^n.")
    if abs(value - SPECULAR_KS * rv) <= tol:
        return wrong(f"you left out the exponent: the term is k_s (R·V)^n with n = {SPECULAR_N}.")
    if abs(value - expected * float(L[2])) <= tol:
        return wrong("you multiplied by L·N as in the diffuse term; Phong's specular term k_s (R·V)^n has no "
                     "L·N factor.")
    if abs(value) <= tol:
        return wrong("your V points the wrong way (or R does): both point away from the surface, V = (eye - P)/|eye - P| "
                     "and R = 2 (L·N) N - L; here R·V > 0 and the eye sees some highlight.")
    return wrong(f"your intensity is {off_by(value, expected)}; find the unit vectors L and V from the origin, "
                 f"R = 2 (L·N) N - L, then k_s (R·V)^n.")


def check_highlight_exponent(answer) -> Result:
    """Check the exponent n that halves the highlight at the given angle, (cos θ)^n = 1/2 (Goldman
    §16.5; :func:`goldman_lib.lighting.highlight_half_width` is its inverse).

    Recognises 12° taken as the full width (half-width 6°), the half-width doubled (24°), the
    small-angle approximation 2 ln 2 / θ², and 1/e instead of 1/2.
    """
    value, err = read_number(answer, "the exponent")
    if err is not None:
        return err

    def exponent(angle, fraction=0.5):
        return math.log(fraction) / math.log(math.cos(math.radians(angle)))

    expected = exponent(HALF_WIDTH)
    tol = 0.006
    if abs(value - expected) <= tol:
        return correct(f"n = {fmt(expected, 4)}: (cos {fmt(HALF_WIDTH)}°)^n = 1/2; indeed the highlight of this "
                       f"exponent is at half strength {fmt(lighting.highlight_half_width(value), 4)} degrees from R.")
    if value > 0 and abs(lighting.highlight_half_width(value) - HALF_WIDTH / 2) <= 0.02:
        return wrong(f"your exponent makes the highlight half as strong at {fmt(HALF_WIDTH / 2)} degrees: you took "
                     f"{fmt(HALF_WIDTH)} degrees as the full width; it is the half-width, the angle from R.")
    if value > 0 and abs(lighting.highlight_half_width(value) - 2 * HALF_WIDTH) <= 0.02:
        return wrong(f"your exponent halves the highlight at {fmt(2 * HALF_WIDTH)} degrees, twice the angle asked.")
    if abs(value - 2 * math.log(2) / math.radians(HALF_WIDTH) ** 2) <= tol:
        return wrong("that is the small-angle approximation cos θ ≈ 1 - θ²/2; solve (cos θ)^n = 1/2 exactly: "
                     "n = ln(1/2) / ln(cos θ).")
    if abs(value - exponent(HALF_WIDTH, math.exp(-1))) <= tol:
        return wrong("that exponent brings the highlight to 1/e of its peak; the half-width is where it is 1/2.")
    return wrong(f"your exponent is {off_by(value, expected)}; take logarithms of (cos θ)^n = 1/2 with "
                 f"θ = {fmt(HALF_WIDTH)} degrees (in degrees on your calculator).")


# -- §16.3 and §16.6 -------------------------------------------------------------------------------------

def _total(ambient=True, lights=None, specular_colour=(1.0, 1.0, 1.0), white=False):
    lights = TOTAL_LIGHTS if lights is None else lights
    material = Material(**TOTAL_MATERIAL, specular_colour=specular_colour)
    ls = [Light(p, colour=(1.0, 1.0, 1.0) if white else c, intensity=i) for p, c, i in lights]
    return lighting.intensity(_P0, _UP, TOTAL_EYE, ls, material, ambient_light=TOTAL_AMBIENT if ambient else 0.0)[0]


def check_total_intensity(answer) -> Result:
    """Check the displayed colour of the total intensity, ambient plus each light's diffuse and
    specular terms, clipped to [0, 1] (Goldman §16.3, §16.6).

    Recognises the unclipped total, the ambient term left out, one light left out, the specular
    highlight in the material's colour, and light 2 taken as white.
    """
    got, err = _read_vector(answer, "your colour", 3, "the displayed colour as [r, g, b]")
    if err is not None:
        return err
    total = _total()
    expected = lighting.to_image(total)
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"the display shows {fmt(expected)}: the red channel of the total went over 1 and is "
                       f"clipped; several lights add, so clipping is the price of bright scenes (§16.6).")
    if _close(got, total, tol):
        return wrong("that is the total intensity itself; a display cannot show more than 1 in a channel: clip each "
                     "channel to [0, 1].")
    slips = [
        (_total(ambient=False), "you left out the ambient term I_a k_a C."),
        (_total(lights=TOTAL_LIGHTS[:1]), "you left out light 2: the total sums the diffuse and specular terms over "
                                          "every light."),
        (_total(lights=TOTAL_LIGHTS[1:]), "you left out light 1: the total sums the diffuse and specular terms over "
                                          "every light."),
        (_total(specular_colour=TOTAL_MATERIAL["colour"]), "your highlight has the material's colour; here the "
                                                           "specular term takes the light's colour (k_s (R·V)^n times "
                                                           "the light's RGB, not times C)."),
        (_total(white=True), "you took light 2 as white: multiply its terms by its colour (1, 0.5, 0.5) times its "
                             "intensity."),
    ]
    for value, message in slips:
        if _close(got, value, tol) or _close(got, lighting.to_image(value), tol):
            return wrong(message)
    return wrong(f"your colour is {_dist(got, expected)} from the displayed one; work out L·N and R·V for each "
                 f"light (V = (0, 0, 1)), add the ambient term and both lights' terms, then clip.")


SLIPS = {
    "check_reflected_colour": [[0.55, 0.8, 0.25], [0.84, 0.54, 0.6], [0.0432, 0.072, 0.0], [1.0, 1.0, 0.85]],
    "check_diffuse": [4.2933, 3.84, 0.9805, 0.5724, 1.0733],
    "check_mirror_direction": [[-1 / 3, -14 / 15, -2 / 15], [2.2, 2.8, 2.0], [-2 / 15, 7 / 15, -1 / 3]],
    "check_specular": [0.6184, 0.7675, 0.178, 0.0],
    "check_highlight_exponent": [126.18, 7.67, 31.6, 45.26],
    "check_total_intensity": [[1.34816, 0.70968, 0.43008], [1.0, 0.64968, 0.40608], [0.8168, 0.5448, 0.3408],
                              [0.6394, 0.2249, 0.1133], [1.0, 0.5878, 0.2351], [1.0, 0.8746, 0.5194]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

"""Exercise checkers for chapter 16, colour and intensity (Goldman §16.2-16.6).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`):
instance 0 is the module constants below, which the stored notebook shows; ``deal("check_...")``
(or the button beside the exercise) deals another, and the checker, ``PROBLEMS`` and
``steps("check_...")`` follow the current instance.  The chapter's "show that" exercises (in
:mod:`goldman_lib.exercises.proofs`) ask for an identity, not a number, so they do not deal.
``SLIPS`` holds the wrong answers each checker recognises, for the stored instance.  ``None`` or
``...`` means "not answered yet".  Every exercise uses other points, lights and materials than the
chapter's worked examples.  The lighting model is :mod:`goldman_lib.lighting`: diffuse
``I_p k_d (L . N)``, specular ``I_p k_s (R . V)^n`` with ``R = 2 (L . N) N - L`` (no ``L . N``
factor, no attenuation), all unit vectors pointing away from the surface point.

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
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, wrong
from goldman_lib.exercises import read_vector as _read_vector, all_close as _close, distance_text as _dist  # shared readers
from goldman_lib.exercises.deal import Deck, memo, pick as _pick, steps_number as _f6, tenths as _tenths, within
from goldman_lib.lighting import Light, Material

__all__ = ["PROBLEMS", "SLIPS", "MIX_LIGHTS", "MIX_SURFACE", "DIFFUSE_POINT", "DIFFUSE_NORMAL", "DIFFUSE_LIGHT",
           "DIFFUSE_KD", "DIFFUSE_I", "MIRROR_L", "MIRROR_N", "SPECULAR_LIGHT", "SPECULAR_EYE", "SPECULAR_KS",
           "SPECULAR_N", "HALF_WIDTH", "TOTAL_MATERIAL", "TOTAL_LIGHTS", "TOTAL_AMBIENT", "TOTAL_EYE",
           "DECK", "deal", "steps", "current", "deal_button",
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

DECK = Deck("ch16")


def _t(v) -> str:
    return fmt(v)


def _a(v):
    return np.asarray(v, dtype=float)


def _tup(v) -> tuple:
    return tuple(float(x) for x in np.asarray(v, dtype=float).ravel())


def _apart(groups, tol) -> bool:
    """Whether every form of each group (a slip with the forms its checker accepts for it) is
    more than ``tol`` from every form of the other groups (the answer is the first group)."""
    groups = [[_a(v) for v in g] for g in groups]
    return not any(_close(u, v, tol) for i, g in enumerate(groups) for h in groups[i + 1:] for u in g for v in h)


#: whole vectors of whole length (hand-friendly |v|): (v, |v|)
_WHOLE = (((1.0, 2.0, 2.0), 3), ((2.0, 1.0, 2.0), 3), ((2.0, 2.0, 1.0), 3), ((0.0, 3.0, 4.0), 5), ((4.0, 0.0, 3.0), 5),
          ((3.0, 4.0, 0.0), 5), ((2.0, 3.0, 6.0), 7), ((6.0, 2.0, 3.0), 7), ((4.0, 4.0, 7.0), 9), ((1.0, 4.0, 8.0), 9))
#: unit vectors with short decimals: (0.6, 0, 0.8) = (3, 0, 4)/5, (0.36, 0.48, 0.8) = (9, 12, 20)/25, ...
_UNIT = ((0.6, 0.0, 0.8), (0.8, 0.0, 0.6), (0.0, 0.6, 0.8), (0.36, 0.48, 0.8), (0.48, 0.36, 0.8), (0.48, 0.6, 0.64),
         (0.6, 0.48, 0.64), (0.28, 0.0, 0.96), (0.64, 0.48, 0.6), (0.48, 0.64, 0.6))


def _whole(rng):
    v, _ = _pick(rng, _WHOLE)
    perm = rng.permutation(3)
    return _tup(np.array(v)[perm] * rng.choice([-1.0, 1.0], size=3) + 0.0)


def _signed_unit(rng):
    v = _a(_pick(rng, _UNIT))
    return _tup(v * np.r_[rng.choice([-1.0, 1.0], size=2), 1.0] + 0.0)


# -- §16.2 ---------------------------------------------------------------------------------------------

_STORED_MIX = {"lights": MIX_LIGHTS, "surface": MIX_SURFACE}


@memo
def _mix_answers(p):
    C = _a(p["surface"])
    lights = [Light((0.0, 0.0, 1.0), colour=c, intensity=i) for c, i in p["lights"]]
    material = Material(colour=p["surface"], ambient=0.0, diffuse=1.0, specular=0.0)
    expected = lighting.intensity(_P0, _UP, [0.0, 0.0, 1.0], lights, material, ambient_light=0.0)[0]
    incoming = sum(light.rgb for light in lights)
    slips = {"intensities left out": C * sum(_a(c) for c, _ in p["lights"]),
             "the light arriving": incoming,
             "lights multiplied": C * lights[0].rgb * lights[1].rgb,
             "surface colour added": incoming + C}
    return expected, slips


def _mix_generate(rng) -> dict:
    colours = [tuple(float(v) for v in rng.integers(0, 5, size=3) / 4) for _ in range(2)]
    return {"lights": tuple((c, _tenths(rng, 0.2, 0.9)) for c in colours),
            "surface": tuple(float(v) for v in rng.integers(1, 5, size=3) / 4)}


def _mix_ok(p):
    ans, slips = _mix_answers(p)
    if min(max(c) for c, _ in p["lights"]) == 0:
        return "a light is black"
    added = slips["surface colour added"]
    if not _apart([[ans], [slips["intensities left out"]], [slips["the light arriving"]], [slips["lights multiplied"]],
                   [added, np.clip(added, 0, 1)]], 5e-4):
        return "two recognised forms coincide"
    return None


def _mix_statement(p) -> str:
    (c1, i1), (c2, i2) = p["lights"]
    return (f"Two lights shine on the same point of a matte surface of colour C = {_t(p['surface'])} (k_d = 1), both "
            f"straight along the normal (L . N = 1): one of colour {_t(c1)} at intensity "
            f"{fmt(i1)}, the other of colour {_t(c2)} at intensity {fmt(i2)}. "
            f"What RGB light does the point reflect (the diffuse terms only)? Give [r, g, b] (Goldman §16.2).")


def _mix_steps(p) -> str:
    (c1, i1), (c2, i2) = p["lights"]
    ans, slips = _mix_answers(p)
    return (f"1. Each light brings its colour times its intensity: {fmt(i1)} {_t(c1)} = {_f6(i1 * _a(c1))} and "
            f"{fmt(i2)} {_t(c2)} = {_f6(i2 * _a(c2))}.\n"
            f"2. Light adds channel by channel: the light arriving is {_f6(slips['the light arriving'])}.\n"
            f"3. The surface keeps the fraction C = {_t(p['surface'])} of each channel: "
            f"{_f6(ans)}.")


@DECK.exercise(stored=_STORED_MIX, generate=_mix_generate, answer=lambda p: _mix_answers(p)[0],
               slips=lambda p: _mix_answers(p)[1], statement=_mix_statement, steps=_mix_steps,
               same=within(5e-4), well_posed=_mix_ok)
def check_reflected_colour(answer, p) -> Result:
    """Check the colour C * (I_1 c_1 + I_2 c_2) a surface of colour C reflects under two coloured
    lights (Goldman §16.2).

    Recognises the lights' colours without their intensities, the light alone (surface colour left
    out), the lights' colours multiplied instead of added, and the surface colour added.
    """
    got, err = _read_vector(answer, "your colour", 3, "the reflected colour as [r, g, b]")
    if err is not None:
        return err
    expected, slips = _mix_answers(p)
    incoming = slips["the light arriving"]
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"the point reflects {fmt(expected)}: the lights add channel by channel to "
                       f"{fmt(incoming)}, and the surface keeps the fraction C of each channel.")
    if _close(got, slips["intensities left out"], tol):
        return wrong("you left out the intensities: each light brings its colour times its intensity I_p.")
    if _close(got, incoming, tol):
        return wrong("that is the light arriving, not the light reflected: the surface reflects only the fraction "
                     "C of each channel (multiply channel by channel by the surface colour).")
    if _close(got, slips["lights multiplied"], tol):
        return wrong("you multiplied the two lights' colours; light adds: the light arriving is the sum "
                     "I_1 c_1 + I_2 c_2, channel by channel.")
    added = slips["surface colour added"]
    if _close(got, added, tol) or _close(got, np.clip(added, 0, 1), tol):
        return wrong("you added the surface colour; a surface filters light: multiply each channel of the light "
                     "by the surface's fraction C of that channel.")
    return wrong(f"your colour is {_dist(got, expected)}; add the two lights channel by channel (colour "
                 f"times intensity), then multiply channel by channel by C.")


# -- §16.4 ---------------------------------------------------------------------------------------------

_STORED_DIFFUSE = {"P": DIFFUSE_POINT, "N": DIFFUSE_NORMAL, "light": DIFFUSE_LIGHT, "kd": DIFFUSE_KD, "I": DIFFUSE_I}


@memo
def _diffuse_answers(p):
    P, N, Lp = _a(p["P"]), _a(p["N"]), _a(p["light"])
    kd, I = p["kd"], p["I"]
    expected = float(lighting.diffuse([P], [N], Lp, kd, I)[0])
    scale = kd * I
    n = N / np.linalg.norm(N)
    slips = {"N not unit": scale * float(N @ (Lp - P)) / np.linalg.norm(Lp - P),
             "L not unit": scale * float(n @ (Lp - P)),
             "L from the origin": scale * float(n @ Lp) / np.linalg.norm(Lp),
             "I_p left out": expected / I,
             "k_d left out": expected / kd}
    return expected, slips


def _diffuse_generate(rng) -> dict:
    P = _tup(rng.integers(-2, 3, size=3))
    N = _whole(rng)
    D = _whole(rng)
    return {"P": P, "N": N, "light": _tup(_a(P) + _a(D)), "kd": _tenths(rng, 0.5, 0.9), "I": _tenths(rng, 1.1, 2.0)}


def _diffuse_ok(p):
    P, N, Lp = _a(p["P"]), _a(p["N"]), _a(p["light"])
    cos = float((Lp - P) @ N) / (np.linalg.norm(Lp - P) * np.linalg.norm(N))
    if cos < 0.2:
        return "the light is behind the surface or grazes it (L . N < 0.2)"
    if np.linalg.norm(Lp) < 1:
        return "the light stands at the origin"
    if cos > 0.999:
        return "the light is straight along the normal (nothing to normalise)"
    return None


def _diffuse_statement(p) -> str:
    return (f"The point P = {_t(p['P'])} of a surface has the normal N = {_t(p['N'])} (not unit). A point "
            f"light of intensity I_p = {fmt(p['I'])} stands at {_t(p['light'])}; the surface has k_d = "
            f"{fmt(p['kd'])}. Compute Lambert's diffuse intensity I_p k_d (L . N) at P, to 4 decimals "
            f"(Goldman §16.4).")


def _diffuse_steps(p) -> str:
    P, N, Lp = _a(p["P"]), _a(p["N"]), _a(p["light"])
    D = Lp - P
    lD, lN = float(np.linalg.norm(D)), float(np.linalg.norm(N))
    cos = float(D @ N) / (lD * lN)
    return (f"1. L points from P to the light: light - P = {_t(D)}, of length {_f6(lD)}.\n"
            f"2. |N| = {_f6(lN)}, so the unit normal is {_t(N)}/{_f6(lN)}.\n"
            f"3. L . N = {fmt(float(D @ N))}/({_f6(lD)} x {_f6(lN)}) = {_f6(cos)}.\n"
            f"4. I_p k_d (L . N) = {fmt(p['I'])} x {fmt(p['kd'])} x {_f6(cos)} = {_f6(_diffuse_answers(p)[0])}.")


@DECK.exercise(stored=_STORED_DIFFUSE, generate=_diffuse_generate, answer=lambda p: _diffuse_answers(p)[0],
               slips=lambda p: _diffuse_answers(p)[1], statement=_diffuse_statement, steps=_diffuse_steps,
               same=within(5e-4), well_posed=_diffuse_ok)
def check_diffuse(answer, p) -> Result:
    """Check the diffuse intensity I_p k_d (L · N), with L the unit vector from the surface point to the
    light and N normalised (Goldman §16.4).

    Recognises an unnormalised normal, an unnormalised L, L taken from the origin instead of from
    P, and a missing k_d or I_p.
    """
    value, err = read_number(answer, "the diffuse intensity")
    if err is not None:
        return err
    expected, slips = _diffuse_answers(p)
    N = _a(p["N"])
    tol = 5e-4
    if abs(value - expected) <= tol:
        angle = math.degrees(math.acos(min(1.0, expected / (p["kd"] * p["I"]))))
        return correct(f"the diffuse intensity is {fmt(expected)}: the light arrives {fmt(angle, 3)} degrees "
                       f"from the normal, and Lambert's law scales k_d I_p by the cosine of that angle.")
    if abs(value - slips["N not unit"]) <= tol:
        return wrong(f"your normal is not a unit vector: divide N = {_t(N)} by its length {fmt(np.linalg.norm(N))} "
                     f"before the dot product (otherwise L . N is not a cosine).")
    if abs(value - slips["L not unit"]) <= tol:
        return wrong("your L is not a unit vector: L is the direction from P to the light, divided by its length.")
    if abs(value - slips["L from the origin"]) <= tol:
        return wrong("you took L towards the light from the origin; L points from the surface point P to the light: "
                     "L = (light - P) / |light - P|.")
    if abs(value - slips["I_p left out"]) <= tol:
        return wrong(f"you left out the light's intensity I_p = {fmt(p['I'])}.")
    if abs(value - slips["k_d left out"]) <= tol:
        return wrong(f"you left out the diffuse coefficient k_d = {fmt(p['kd'])}.")
    return wrong(f"your intensity is {off_by(value, expected)}; normalise both L = light - P and N, then "
                 f"multiply I_p k_d by their dot product.")


# -- §16.5 ---------------------------------------------------------------------------------------------

_STORED_MIRROR = {"L": MIRROR_L, "N": MIRROR_N}
_NORMALS = ((1.0, 1.0, 1.0), (1.0, 2.0, 2.0), (2.0, 1.0, 2.0), (0.0, 1.0, 1.0), (1.0, 0.0, 1.0), (1.0, 1.0, 0.0),
            (2.0, 2.0, 1.0), (1.0, 1.0, 2.0), (0.0, 3.0, 4.0), (1.0, -1.0, 1.0))


@memo
def _mirror_answers(p):
    L, N = _a(p["L"]), _a(p["N"])
    n = N / np.linalg.norm(N)
    expected = lighting.reflected_direction(L, n)
    slips = {"-R": -expected, "N not unit": 2 * (L @ N) * N - L, "factor 2 missing": (L @ n) * n - L}
    return expected, slips


def _mirror_generate(rng) -> dict:
    N = _a(_pick(rng, _NORMALS))[rng.permutation(3)]
    return {"L": _signed_unit(rng), "N": _tup(N)}


def _mirror_ok(p):
    L, N = _a(p["L"]), _a(p["N"])
    c = float(L @ N) / np.linalg.norm(N)
    if c < 0.2:
        return "the light is behind the surface or grazes it"
    if c > 0.98:
        return "L is (almost) along the normal: R = L"
    return None


def _mirror_statement(p) -> str:
    return (f"At a surface point the unit vector towards the light is L = {_t(p['L'])} and the surface normal is "
            f"along N = {_t(p['N'])} (not unit). Compute the mirror direction R of L about the normal, the unit "
            f"vector Phong's specular term compares with the direction to the eye. Give [x, y, z], to 4 decimals "
            f"(Goldman §16.5).")


def _mirror_steps(p) -> str:
    L, N = _a(p["L"]), _a(p["N"])
    lN = float(np.linalg.norm(N))
    ln = float(L @ N) / lN
    return (f"1. The unit normal: N/|N| = {_t(N)}/{_f6(lN)} = {_f6(N / lN)}.\n"
            f"2. L . N = {_f6(float(L @ N))}/{_f6(lN)} = {_f6(ln)}.\n"
            f"3. R = 2 (L . N) N - L = {_f6(2 * ln)} N - L = {_f6(_mirror_answers(p)[0])} (a unit vector).")


@DECK.exercise(stored=_STORED_MIRROR, generate=_mirror_generate, answer=lambda p: _mirror_answers(p)[0],
               slips=lambda p: _mirror_answers(p)[1], statement=_mirror_statement, steps=_mirror_steps,
               same=within(5e-4), well_posed=_mirror_ok)
def check_mirror_direction(answer, p) -> Result:
    """Check the mirror direction R = 2 (L · N) N - L of the unit L about the unit normal N
    (Goldman §16.5).

    Recognises -R (the reflection pointing into the surface), an unnormalised N, and the missing
    factor 2.
    """
    got, err = _read_vector(answer, "your R", 3, "R as [x, y, z]")
    if err is not None:
        return err
    L, N = _a(p["L"]), _a(p["N"])
    n = N / np.linalg.norm(N)
    expected, slips = _mirror_answers(p)
    tol = 5e-4
    if _close(got, expected, tol):
        return correct(f"R = {fmt(expected)}: a unit vector, making the same angle with N as L does "
                       f"(L . N = R . N = {fmt(float(L @ n))}), in the plane of L and N.")
    if _close(got, slips["-R"], tol):
        return wrong("that is -R, L - 2 (L·N) N, the mirror image pointing into the surface; R = 2 (L·N) N - L "
                     "points away from it, on the other side of the normal from L.")
    if _close(got, slips["N not unit"], tol):
        return wrong(f"your N is not a unit vector: the formula 2 (L·N) N - L holds for |N| = 1; divide {_t(N)} by "
                     f"its length first (your R is not a unit vector).")
    if _close(got, slips["factor 2 missing"], tol):
        return wrong("you lack the factor 2: (L·N) N - L goes from L to the normal; R goes as far again, "
                     "R = 2 (L·N) N - L.")
    return wrong(f"your R is {_dist(got, expected)}; it should be a unit vector (yours has length "
                 f"{fmt(np.linalg.norm(got), 4)}). Normalise N, then R = 2 (L·N) N - L.")


_STORED_SPECULAR = {"light": SPECULAR_LIGHT, "eye": SPECULAR_EYE, "ks": SPECULAR_KS, "n": SPECULAR_N}


@memo
def _specular_answers(p):
    Lp, E, ks, n = _a(p["light"]), _a(p["eye"]), p["ks"], p["n"]
    expected = float(lighting.specular(_P0, _UP, Lp, E, ks, n, 1.0)[0])
    L, V = Lp / np.linalg.norm(Lp), E / np.linalg.norm(E)
    R = lighting.reflected_direction(L, _UP[0])
    rv = float(R @ V)
    H = (L + V) / np.linalg.norm(L + V)
    slips = {"Blinn": ks * float(H[2]) ** n, "no exponent": ks * rv, "times L.N": expected * float(L[2]),
             "V reversed": 0.0}
    return expected, slips, rv


def _specular_generate(rng) -> dict:
    return {"light": _tup(np.r_[rng.integers(-3, 4, size=2), rng.integers(1, 5)]),
            "eye": _tup(np.r_[rng.integers(-3, 4, size=2), rng.integers(1, 5)]),
            "ks": _tenths(rng, 0.5, 0.9), "n": int(_pick(rng, (2, 3, 4, 5, 6, 8, 10)))}


def _specular_ok(p):
    rv = _specular_answers(p)[2]
    if rv < 0.75:
        return "the eye is far from the mirror direction: the highlight is (almost) nothing"
    if rv > 0.999:
        return "the eye is on the mirror direction: (R . V)^n = 1 whatever n"
    if p["light"][2] / np.linalg.norm(p["light"]) > 0.999:
        return "the light is straight above (L . N = 1)"
    return None


def _specular_statement(p) -> str:
    return (f"The origin lies on a surface with unit normal N = (0, 0, 1). A point light of intensity 1 stands at "
            f"{_t(p['light'])} and the eye at {_t(p['eye'])}; the surface has k_s = {fmt(p['ks'])} and the "
            f"specular exponent n = {p['n']}. Compute Phong's specular intensity k_s (R . V)^n at the origin, to 4 "
            f"decimals (Goldman §16.5).")


def _specular_steps(p) -> str:
    Lp, E = _a(p["light"]), _a(p["eye"])
    L, V = Lp / np.linalg.norm(Lp), E / np.linalg.norm(E)
    R = lighting.reflected_direction(L, _UP[0])
    expected, _, rv = _specular_answers(p)
    return (f"1. L = {_t(Lp)}/{_f6(np.linalg.norm(Lp))} = {_f6(L)}; V = {_t(E)}/{_f6(np.linalg.norm(E))} = {_f6(V)}.\n"
            f"2. L . N = {_f6(L[2])}, so R = 2 (L . N) N - L = {_f6(R)}.\n"
            f"3. R . V = {_f6(rv)}; k_s (R . V)^n = {fmt(p['ks'])} x {_f6(rv)}^{p['n']} = {_f6(expected)}.")


@DECK.exercise(stored=_STORED_SPECULAR, generate=_specular_generate, answer=lambda p: _specular_answers(p)[0],
               slips=lambda p: _specular_answers(p)[1], statement=_specular_statement, steps=_specular_steps,
               same=within(5e-4), well_posed=_specular_ok)
def check_specular(answer, p) -> Result:
    """Check the specular intensity k_s (R · V)^n, with R the mirror direction of the unit L and V the
    unit vector to the eye (Goldman §16.5).

    Recognises Blinn's halfway vector (N . H)^n, a missing exponent, an extra L . N factor, and V
    pointing from the eye (R . V < 0 gives 0).
    """
    value, err = read_number(answer, "the specular intensity")
    if err is not None:
        return err
    expected, slips, rv = _specular_answers(p)
    tol = 5e-4
    if abs(value - expected) <= tol:
        return correct(f"the specular intensity is {fmt(expected)}: the eye is {fmt(math.degrees(math.acos(rv)), 3)} "
                       f"degrees off the mirror direction, and the exponent {p['n']} makes the highlight fade "
                       f"fast with that angle.")
    if abs(value - slips["Blinn"]) <= tol:
        return wrong("that is Blinn's variant (N·H)^n with the halfway vector H; Phong's term uses the mirror "
                     "direction R = 2 (L·N) N - L and (R·V)^n.")
    if abs(value - slips["no exponent"]) <= tol:
        return wrong(f"you left out the exponent: the term is k_s (R·V)^n with n = {p['n']}.")
    if abs(value - slips["times L.N"]) <= tol:
        return wrong("you multiplied by L·N as in the diffuse term; Phong's specular term k_s (R·V)^n has no "
                     "L·N factor.")
    if abs(value) <= tol:
        return wrong("your V points the wrong way (or R does): both point away from the surface, V = (eye - P)/|eye - P| "
                     "and R = 2 (L·N) N - L; here R·V > 0 and the eye sees some highlight.")
    return wrong(f"your intensity is {off_by(value, expected)}; find the unit vectors L and V from the origin, "
                 f"R = 2 (L·N) N - L, then k_s (R·V)^n.")


def _exponent(angle, fraction=0.5):
    return math.log(fraction) / math.log(math.cos(math.radians(angle)))


@memo
def _half_answers(p):
    a = p["angle"]
    return _exponent(a), {"full width taken": _exponent(a / 2), "angle doubled": _exponent(2 * a),
                          "small-angle approximation": 2 * math.log(2) / math.radians(a) ** 2,
                          "1/e": _exponent(a, math.exp(-1))}


def _half_statement(p) -> str:
    return (f"Which specular exponent n makes a Phong highlight fall to half its peak strength when the eye is "
            f"{fmt(p['angle'])} degrees away from the mirror direction R (that is, (R . V)^n = 1/2 at that angle)? "
            f"Give n to 2 decimals (Goldman §16.5).")


def _half_steps(p) -> str:
    a = p["angle"]
    c = math.cos(math.radians(a))
    return (f"1. (cos {fmt(a)}°)^n = 1/2, with cos {fmt(a)}° = {_f6(c)}.\n"
            f"2. Take logarithms: n ln(cos {fmt(a)}°) = ln(1/2), so n = ln(1/2)/ln({_f6(c)}) = "
            f"{_f6(math.log(0.5))}/{_f6(math.log(c))} = {_f6(_half_answers(p)[0])}.\n"
            f"3. Check with the library: lighting.highlight_half_width(n) gives back "
            f"{_f6(lighting.highlight_half_width(_half_answers(p)[0]))} degrees.")


@DECK.exercise(stored={"angle": HALF_WIDTH}, generate=lambda rng: {"angle": float(rng.integers(5, 41))},
               answer=lambda p: _half_answers(p)[0], slips=lambda p: _half_answers(p)[1],
               statement=_half_statement, steps=_half_steps, same=within(0.006))
def check_highlight_exponent(answer, p) -> Result:
    """Check the exponent n that halves the highlight at the given angle, (cos θ)^n = 1/2 (Goldman
    §16.5; :func:`goldman_lib.lighting.highlight_half_width` is its inverse).

    Recognises the angle taken as the full width (half of it as the half-width), the half-width
    doubled, the small-angle approximation 2 ln 2 / θ², and 1/e instead of 1/2.
    """
    value, err = read_number(answer, "the exponent")
    if err is not None:
        return err
    a = p["angle"]
    expected, slips = _half_answers(p)
    tol = 0.006
    if abs(value - expected) <= tol:
        return correct(f"n = {fmt(expected, 4)}: (cos {fmt(a)}°)^n = 1/2; indeed the highlight of this "
                       f"exponent is at half strength {fmt(lighting.highlight_half_width(value), 4)} degrees from R.")
    if value > 0 and abs(lighting.highlight_half_width(value) - a / 2) <= 0.02:
        return wrong(f"your exponent makes the highlight half as strong at {fmt(a / 2)} degrees: you took "
                     f"{fmt(a)} degrees as the full width; it is the half-width, the angle from R.")
    if value > 0 and abs(lighting.highlight_half_width(value) - 2 * a) <= 0.02:
        return wrong(f"your exponent halves the highlight at {fmt(2 * a)} degrees, twice the angle asked.")
    if abs(value - slips["small-angle approximation"]) <= tol:
        return wrong("that is the small-angle approximation cos θ ≈ 1 - θ²/2; solve (cos θ)^n = 1/2 exactly: "
                     "n = ln(1/2) / ln(cos θ).")
    if abs(value - slips["1/e"]) <= tol:
        return wrong("that exponent brings the highlight to 1/e of its peak; the half-width is where it is 1/2.")
    return wrong(f"your exponent is {off_by(value, expected)}; take logarithms of (cos θ)^n = 1/2 with "
                 f"θ = {fmt(a)} degrees (in degrees on your calculator).")


# -- §16.3 and §16.6 -------------------------------------------------------------------------------------

_STORED_TOTAL = {"material": tuple(sorted(TOTAL_MATERIAL.items())), "lights": TOTAL_LIGHTS, "ambient": TOTAL_AMBIENT,
                 "eye": TOTAL_EYE}


def _total(p, ambient=True, lights=None, specular_colour=(1.0, 1.0, 1.0), white=False):
    lights = p["lights"] if lights is None else lights
    mat = dict(p["material"])
    material = Material(**mat, specular_colour=specular_colour)
    ls = [Light(q, colour=(1.0, 1.0, 1.0) if white else c, intensity=i) for q, c, i in lights]
    return lighting.intensity(_P0, _UP, p["eye"], ls, material, ambient_light=p["ambient"] if ambient else 0.0)[0]


@memo
def _total_answers(p):
    total = _total(p)
    slips = {"unclipped": total, "ambient left out": _total(p, ambient=False),
             "light 2 left out": _total(p, lights=p["lights"][:1]),
             "light 1 left out": _total(p, lights=p["lights"][1:]),
             "highlight in the material's colour": _total(p, specular_colour=dict(p["material"])["colour"]),
             "light 2 white": _total(p, white=True)}
    return lighting.to_image(total), slips


def _total_generate(rng) -> dict:
    material = dict(colour=_tenths(rng, 0.2, 0.9, 3), ambient=_tenths(rng, 0.2, 0.4), diffuse=_tenths(rng, 0.5, 0.8),
                    specular=_tenths(rng, 0.3, 0.6), exponent=int(_pick(rng, (2, 3, 4, 5))))
    colour2 = tuple(float(v) for v in _pick(rng, ((1.0, 0.5, 0.5), (0.5, 1.0, 0.5), (0.5, 0.5, 1.0), (1.0, 1.0, 0.5),
                                                  (1.0, 0.5, 1.0), (0.5, 1.0, 1.0))))
    positions = []
    for _ in range(2):
        v, _n = _pick(rng, _WHOLE[3:6])
        v = _a(v)[rng.permutation(3)] * np.r_[rng.choice([-1.0, 1.0], size=2), 1.0]
        positions.append(_tup(v + 0.0))
    lights = ((positions[0], (1.0, 1.0, 1.0), _tenths(rng, 0.8, 1.2)), (positions[1], colour2, _tenths(rng, 0.8, 1.4)))
    return {"material": tuple(sorted(material.items())), "lights": lights, "ambient": _tenths(rng, 0.2, 0.5),
            "eye": (0.0, 0.0, float(rng.integers(2, 6)))}


def _total_ok(p):
    ans, slips = _total_answers(p)
    if abs(p["lights"][0][0][2]) < 1e-9 or abs(p["lights"][1][0][2]) < 1e-9:
        return "a light lies in the surface's plane (L . N = 0)"
    if p["lights"][0][0] == p["lights"][1][0]:
        return "the two lights stand at one place"
    groups = [[ans], [slips["unclipped"]]] + [[v, lighting.to_image(v)] for k, v in slips.items() if k != "unclipped"]
    if not _apart(groups, 5e-4):
        return "two recognised forms coincide"
    return None


def _total_statement(p) -> str:
    m = dict(p["material"])
    (q1, _c1, i1), (q2, c2, i2) = p["lights"]
    return (f"The origin lies on a surface with unit normal N = (0, 0, 1), seen from the eye at {_t(p['eye'])}. Its "
            f"material has colour C = {_t(m['colour'])}, k_a = {fmt(m['ambient'])}, "
            f"k_d = {fmt(m['diffuse'])}, k_s = {fmt(m['specular'])}, n = "
            f"{m['exponent']}, and a white highlight (the specular term takes the light's colour). The "
            f"ambient light is I_a = {fmt(p['ambient'])} (white); light 1 stands at {_t(q1)}, white, "
            f"intensity {fmt(i1)}; light 2 at {_t(q2)}, colour "
            f"{_t(c2)}, intensity {fmt(i2)}. Compute the total intensity "
            f"I_a k_a C + sum over the lights of I_p (k_d C (L . N) + k_s (R . V)^n), then the colour a display "
            f"shows, each channel clipped to [0, 1]. Give the displayed [r, g, b] to 4 decimals "
            f"(Goldman §16.3 and §16.6).")


def _total_steps(p) -> str:
    m = dict(p["material"])
    C = _a(m["colour"])
    lines = [f"1. V = (0, 0, 1). Ambient: I_a k_a C = {fmt(p['ambient'])} x {fmt(m['ambient'])} C = "
             f"{_f6(p['ambient'] * m['ambient'] * C)}."]
    for k, (q, c, i) in enumerate(p["lights"], start=1):
        L = _a(q) / np.linalg.norm(q)
        ln = max(float(L[2]), 0.0)
        R = lighting.reflected_direction(L, _UP[0])
        rv = max(float(R[2]), 0.0) if ln > 0 else 0.0
        rgb = i * _a(c)
        term = _total(p, ambient=False, lights=[(q, c, i)])
        lines.append(f"{k + 1}. Light {k}: L = {_f6(L)}, L . N = {_f6(ln)}, R = {_f6(R)}, R . V = {_f6(rv)}; "
                     f"its RGB I_p = {_f6(rgb)}; (k_d C (L . N) + k_s (R . V)^{m['exponent']}) I_p = {_f6(term)}.")
    total = _total_answers(p)[1]["unclipped"]
    lines.append(f"4. Total {_f6(total)}; clipped to [0, 1]: {_f6(lighting.to_image(total))}.")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_TOTAL, generate=_total_generate, answer=lambda p: _total_answers(p)[0],
               slips=lambda p: _total_answers(p)[1], statement=_total_statement, steps=_total_steps,
               same=within(5e-4), well_posed=_total_ok)
def check_total_intensity(answer, p) -> Result:
    """Check the displayed colour of the total intensity, ambient plus each light's diffuse and
    specular terms, clipped to [0, 1] (Goldman §16.3, §16.6).

    Recognises the unclipped total, the ambient term left out, one light left out, the specular
    highlight in the material's colour, and light 2 taken as white.
    """
    got, err = _read_vector(answer, "your colour", 3, "the displayed colour as [r, g, b]")
    if err is not None:
        return err
    expected, slips = _total_answers(p)
    total = slips["unclipped"]
    tol = 5e-4
    if _close(got, expected, tol):
        over = [name for name, v in zip(("red", "green", "blue"), total) if v > 1]
        which = (f"the {' and '.join(over)} channel{'s' if len(over) > 1 else ''} of the total went over 1 and "
                 f"{'are' if len(over) > 1 else 'is'} clipped" if over else "no channel of the total went over 1")
        return correct(f"the display shows {fmt(expected)}: {which}; several lights add, so clipping is the price "
                       f"of bright scenes (§16.6).")
    if _close(got, total, tol):
        return wrong("that is the total intensity itself; a display cannot show more than 1 in a channel: clip each "
                     "channel to [0, 1].")
    c2 = p["lights"][1][1]
    messages = {
        "ambient left out": "you left out the ambient term I_a k_a C.",
        "light 2 left out": "you left out light 2: the total sums the diffuse and specular terms over every light.",
        "light 1 left out": "you left out light 1: the total sums the diffuse and specular terms over every light.",
        "highlight in the material's colour": "your highlight has the material's colour; here the specular term "
                                              "takes the light's colour (k_s (R·V)^n times the light's RGB, not "
                                              "times C).",
        "light 2 white": f"you took light 2 as white: multiply its terms by its colour {_t(c2)} times its intensity.",
    }
    for key, message in messages.items():
        value = slips[key]
        if _close(got, value, tol) or _close(got, lighting.to_image(value), tol):
            return wrong(message)
    return wrong(f"your colour is {_dist(got, expected)} from the displayed one; work out L·N and R·V for each "
                 f"light (V = (0, 0, 1)), add the ambient term and both lights' terms, then clip.")


#: Deal another instance of an exercise (``deal("check_diffuse")``, or with ``seed=``; 0 is the
#: stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


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

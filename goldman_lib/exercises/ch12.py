"""Exercise checkers for chapter 12, the coordinate-free formulas of affine and projective
transformations (Goldman §12.3-12.5): rotation about an axis through a point (Rodrigues' formula),
mirror in a plane, nonuniform scaling, orthogonal and perspective projection.

Every exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0 is
the module constants below, which the stored notebook shows; ``deal("check_...")`` (or the button
beside the exercise) deals another, and the checker, ``PROBLEMS`` and ``steps("check_...")`` follow
the current instance. The chapter's "show that" exercises (6 and 7, in
:mod:`goldman_lib.exercises.proofs`) ask for an identity, not a number, so they do not deal.
``SLIPS`` holds the wrong answers of the kinds each checker recognises, for the stored instance.
Hand-computed decimals are accepted to a relative 1e-4 (2/3 typed as 0.6667 is right). """

from __future__ import annotations

import math

import numpy as np

from goldman_lib import transforms
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, read_points, wrong
from goldman_lib.exercises.deal import Deck, integers as _ints, memo

__all__ = ["PROBLEMS", "SLIPS", "ROTATE_POINT", "ROTATE_AXIS", "ROTATE_THROUGH", "ROTATE_ANGLE", "MIRROR_POINT",
           "MIRROR_PLANE_POINT", "MIRROR_NORMAL", "SCALE_POINT", "SCALE_FACTOR", "SCALE_DIRECTION", "SCALE_CENTER",
           "ORTHO_POINT", "ORTHO_PLANE_POINT", "ORTHO_NORMAL", "PERSP_POINT", "PERSP_EYE", "PERSP_PLANE_POINT",
           "PERSP_NORMAL", "DECK", "deal", "steps", "current", "deal_button", "check_rotation_about_point",
           "check_mirror_point", "check_scale_along",
           "check_orthogonal_projection", "check_perspective_projection"]

#: Exercise 1: rotate P by 120 degrees about the line through ROTATE_THROUGH along (1, 1, 1).
ROTATE_POINT = np.array([3.0, 1.0, 1.0])
ROTATE_AXIS = np.array([1.0, 1.0, 1.0])
ROTATE_THROUGH = np.array([1.0, 0.0, 2.0])
ROTATE_ANGLE = 120.0
#: Exercise 2: mirror P in the plane through Q with the (not unit) normal N.
MIRROR_POINT = np.array([4.0, 1.0, 3.0])
MIRROR_PLANE_POINT = np.array([1.0, 0.0, 1.0])
MIRROR_NORMAL = np.array([1.0, 2.0, 2.0])
#: Exercise 3: scale P by 3 along the direction (0, 3, 4) about the centre (1, 1, 1).
SCALE_POINT = np.array([2.0, 3.0, 2.0])
SCALE_FACTOR = 3.0
SCALE_DIRECTION = np.array([0.0, 3.0, 4.0])
SCALE_CENTER = np.array([1.0, 1.0, 1.0])
#: Exercise 4: project P orthogonally onto the plane through Q with normal N.
ORTHO_POINT = np.array([4.0, -1.0, 4.0])
ORTHO_PLANE_POINT = np.array([1.0, 0.0, 0.0])
ORTHO_NORMAL = np.array([2.0, -1.0, 2.0])
#: Exercise 5: project P in perspective from the eye E onto the plane through Q with normal N.
PERSP_POINT = np.array([3.0, 1.0, 3.0])
PERSP_EYE = np.array([-1.0, -1.0, 1.0])
PERSP_PLANE_POINT = np.array([2.0, 0.0, 0.0])
PERSP_NORMAL = np.array([1.0, 1.0, 0.0])

#: Relative tolerance for hand-computed decimals.
REL_TOL = 1e-4

DECK = Deck("ch12")


def _p(x) -> str:
    return fmt(x)


def _arr(v):
    return np.asarray(v, dtype=float)


def _tup(a):
    return tuple(float(x) for x in np.asarray(a, dtype=float))


def _f6(x) -> str:
    """A number of the worked steps, to six digits (enough for the checker's tolerance)."""
    return fmt(x, 6)


def _r(x):
    """A value rounded for worked steps (no floating-point noise)."""
    return np.round(np.asarray(x, dtype=float), 6) + 0.0


def _same(a, b) -> bool:
    a, b = _arr(a), _arr(b)
    return a.shape == b.shape and _close(a, b) and _close(b, a)


def _groups_apart(groups) -> bool:
    """Whether every form a checker recognises (grouped by the slip it names) is apart from the
    forms of the other groups and from the answer (the first group)."""
    groups = [[_arr(v) for v in g] for g in groups]
    return not any(_same(u, v) for i, g in enumerate(groups) for h in groups[i + 1:] for u in g for v in h)


#: normals and directions of whole length (hand-friendly |N|), none a unit vector
_WHOLE = ((1.0, 2.0, 2.0), (2.0, 1.0, 2.0), (2.0, 2.0, 1.0), (2.0, -1.0, 2.0), (0.0, 3.0, 4.0), (4.0, 0.0, 3.0),
          (3.0, 4.0, 0.0), (2.0, 3.0, 6.0), (6.0, 2.0, 3.0), (4.0, 4.0, 7.0))


def _whole(rng):
    return _tup(np.array(_WHOLE[int(rng.integers(0, len(_WHOLE)))]) * rng.choice([-1.0, 1.0], size=3) + 0.0)


# -- reading and comparing -------------------------------------------------------------------------

def _read_point(answer, ask):
    got, err = read_points(answer, "your point", ask=ask)
    if err is not None:
        return None, err
    if got.shape != (3,):
        return None, wrong(f"the image should be one point [x, y, z]; yours has shape {got.shape}.")
    return got, None


def _close(got, expected) -> bool:
    exp = np.asarray(expected, dtype=float)
    return bool(np.all(np.abs(got - exp) <= REL_TOL * np.maximum(1.0, np.abs(exp))))


def _far(got, expected, hint) -> Result:
    hint = hint.rstrip(".")
    return wrong(f"your point is {far_off(got, expected)} from the image; {hint}.")


def _unit(v):
    return np.asarray(v, float) / np.linalg.norm(v)


def _on_plane_check(got, Q, N):
    """A note for a point off the plane of a projection: how far off (the image must lie on the plane)."""
    d = abs(float((got - Q) @ _unit(N)))
    if d > REL_TOL * max(1.0, float(np.abs(got).max())):
        return ". Your point is not on the plane, and a projection's image lies on it"
    return ""


# -- §12.3 ----------------------------------------------------------------------------------------------------

def _rodrigues_unnormalised(v, u, deg):
    th = np.radians(deg)
    return np.cos(th) * v + (1 - np.cos(th)) * (v @ u) * u + np.sin(th) * np.cross(u, v)


_STORED_ROTATE = {"P": _tup(ROTATE_POINT), "axis": _tup(ROTATE_AXIS), "Q": _tup(ROTATE_THROUGH), "angle": ROTATE_ANGLE}
#: cos and sin of the angles dealt, written exactly
_TRIG = {60.0: ("1/2", "√3/2"), 90.0: ("0", "1"), 120.0: ("-1/2", "√3/2"), 240.0: ("-1/2", "-√3/2"),
         270.0: ("0", "-1")}
_AXES = ((1.0, 1.0, 1.0), (1.0, -1.0, 1.0), (1.0, 1.0, -1.0), (-1.0, 1.0, 1.0), (1.0, 1.0, 0.0), (0.0, 1.0, 1.0),
         (1.0, 0.0, 1.0), (1.0, -1.0, 0.0), (0.0, 1.0, -1.0), (-1.0, 0.0, 1.0))


@memo
def _rotate_answers(p):
    P, w, Q, th = _arr(p["P"]), _arr(p["axis"]), _arr(p["Q"]), p["angle"]
    expected = transforms.rotate(P[None], w, th, point=Q)[0]
    slips = {"about the origin": transforms.rotate(P[None], w, th)[0],
             "the other way": transforms.rotate(P[None], w, -th, point=Q)[0],
             "Q not added back": expected - Q,
             "radians": transforms.rotate(P[None], w, math.degrees(th), point=Q)[0],
             "axis not normalised": Q + _rodrigues_unnormalised(P - Q, w, th)}
    return expected, slips


def _rotate_generate(rng) -> dict:
    return {"P": _ints(rng, -3, 3), "axis": _AXES[int(rng.integers(0, len(_AXES)))], "Q": _ints(rng, -2, 2),
            "angle": float(rng.choice(list(_TRIG)))}


def _rotate_ok(p):
    v, w = _arr(p["P"]) - _arr(p["Q"]), _arr(p["axis"])
    if float(np.linalg.norm(np.cross(v, w))) < 0.5:
        return "P lies on the axis: it does not move"
    return None


def _rotate_statement(p) -> str:
    return (f"Rotate the point P = {_p(p['P'])} by {fmt(p['angle'])} degrees about the line through "
            f"Q = {_p(p['Q'])} in the direction {_p(p['axis'])} (counterclockwise looking down the axis, "
            f"from its tip towards Q). Use Rodrigues' formula on v = P - Q: R(v) = cos θ v + (1 - cos θ)(v·w) w + "
            f"sin θ (w × v) with w the unit axis, then add Q back. Give [x, y, z] (Goldman §12.3).")


def _rotate_steps(p) -> str:
    P, a, Q, th = _arr(p["P"]), _arr(p["axis"]), _arr(p["Q"]), p["angle"]
    w = a / np.linalg.norm(a)
    v = P - Q
    cos_text, sin_text = _TRIG.get(th, (_f6(_r(np.cos(np.radians(th)))), _f6(_r(np.sin(np.radians(th))))))
    Rv = _rotate_answers(p)[0] - Q
    return (f"1. v = P - Q = {fmt(v)}; the unit axis w = {fmt(a)} / √{fmt(a @ a)} = {_f6(_r(w))}.\n"
            f"2. v·w = {_f6(_r(v @ w))}, so (v·w) w = {_f6(_r((v @ w) * w))}; w × v = {_f6(_r(np.cross(w, v)))}.\n"
            f"3. cos {fmt(th)}° = {cos_text}, sin {fmt(th)}° = {sin_text}: R(v) = cos θ v + (1 - cos θ)(v·w) w + "
            f"sin θ (w × v) = {_f6(_r(Rv))}.\n"
            f"4. P' = Q + R(v) = {_f6(_r(Rv + Q))}.")


@DECK.exercise(stored=_STORED_ROTATE, generate=_rotate_generate, answer=lambda p: _rotate_answers(p)[0],
               slips=lambda p: _rotate_answers(p)[1], statement=_rotate_statement, steps=_rotate_steps,
               same=_same, well_posed=_rotate_ok)
def check_rotation_about_point(answer, p) -> Result:
    """Check P rotated about the statement's axis through its point Q (Goldman §12.3);
    recognises the rotation about the origin, the other sense of rotation, Q not added back, and the
    axis left unnormalised in Rodrigues' formula.
    """
    got, err = _read_point(answer, "the rotated point as [x, y, z]")
    if err is not None:
        return err
    P, w, Q, th = _arr(p["P"]), _arr(p["axis"]), _arr(p["Q"]), p["angle"]
    expected = transforms.rotate(P[None], w, th, point=Q)[0]
    if _close(got, expected):
        v = P - Q
        how = (" (120° about (1, 1, 1) sends (x, y, z) to (z, x, y))" if p == _STORED_ROTATE else "")
        return correct(f"v = P - Q = {fmt(v)} turns into {fmt(expected - Q)}{how}, and P' = Q + {fmt(expected - Q)}.")
    if _close(got, transforms.rotate(P[None], w, th)[0]):
        return wrong("that is P rotated about the parallel axis through the origin. The axis passes through Q: "
                     "rotate v = P - Q, then add Q back.")
    if _close(got, transforms.rotate(P[None], w, -th, point=Q)[0]):
        return wrong("that is the rotation the other way (clockwise looking down the axis): check the sign of the "
                     "sin θ (w × v) term, w × v and not v × w.")
    if _close(got, expected - Q):
        return wrong("that is R(P - Q), the rotated vector; the rotated point is Q + R(P - Q).")
    cos_text, sin_text = _TRIG.get(th, (fmt(np.cos(np.radians(th))), fmt(np.sin(np.radians(th)))))
    if _close(got, transforms.rotate(P[None], w, math.degrees(th), point=Q)[0]):
        return wrong(f"you took cos and sin of {fmt(th)} as if it were radians: the angle is in degrees (np.cos and "
                     f"math.cos take radians; convert with np.radians first, cos {fmt(th)}° = {cos_text}).")
    if _close(got, Q + _rodrigues_unnormalised(P - Q, w, th)):
        return wrong(f"the axis direction was not normalised: Rodrigues' formula needs the unit vector "
                     f"w = {_p(w)}/|{_p(w)}| in (v·w) w and in w × v.")
    return _far(got, expected, f"write v = P - Q, compute v·w and w × v with the unit w, combine them with "
                               f"cos {fmt(th)}° = {cos_text} and sin {fmt(th)}° = {sin_text}, and add Q")


_STORED_MIRROR = {"P": _tup(MIRROR_POINT), "Q": _tup(MIRROR_PLANE_POINT), "N": _tup(MIRROR_NORMAL)}


@memo
def _mirror_answers(p):
    P, Q, N = _arr(p["P"]), _arr(p["Q"]), _arr(p["N"])
    n = _unit(N)
    d = float((P - Q) @ n)
    slips = {"the projection": transforms.project_orthogonal(P[None], Q, N)[0],
             "N not normalised": P - 2 * ((P - Q) @ N) * N,
             "plane through the origin": P - 2 * (P @ n) * n,
             "wrong sign": P + 2 * d * n}
    return transforms.reflect(P[None], Q, N)[0], slips


def _mirror_generate(rng) -> dict:
    return {"P": _ints(rng, -4, 4), "Q": _ints(rng, -2, 2), "N": _whole(rng)}


def _unnormalised_forms(P, Q, N, k):
    n = _unit(N)
    return [P - k * ((P - Q) @ N) * N, P - k * ((P - Q) @ n) * N, P - k * ((P - Q) @ N) * n]


def _mirror_ok(p):
    P, Q, N = _arr(p["P"]), _arr(p["Q"]), _arr(p["N"])
    if abs(float((P - Q) @ N)) < 0.5:
        return "P lies on the plane: it is its own mirror image"
    ans, slips = _mirror_answers(p)
    if not _groups_apart([[ans], [slips["the projection"]], _unnormalised_forms(P, Q, N, 2),
                          [slips["plane through the origin"]], [slips["wrong sign"]]]):
        return "two recognised forms coincide (the unnormalised normal's three forms included)"
    return None


def _ortho_ok(p):
    P, Q, N = _arr(p["P"]), _arr(p["Q"]), _arr(p["N"])
    if abs(float((P - Q) @ N)) < 0.5:
        return "P lies on the plane: it is its own projection"
    ans, slips = _ortho_answers(p)
    if not _groups_apart([[ans], [slips["the mirror"]], _unnormalised_forms(P, Q, N, 1),
                          [slips["plane through the origin"]]]):
        return "two recognised forms coincide (the unnormalised normal's three forms included)"
    return None


def _mirror_statement(p) -> str:
    return (f"Mirror the point P = {_p(p['P'])} in the plane through Q = {_p(p['Q'])} with normal "
            f"N = {_p(p['N'])}. Give the image [x, y, z] (Goldman §12.3).")


def _mirror_steps(p) -> str:
    P, Q, N = _arr(p["P"]), _arr(p["Q"]), _arr(p["N"])
    L = float(np.linalg.norm(N))
    d = float((P - Q) @ N) / L
    return (f"1. The unit normal n = N/|N| = {fmt(N)}/{_f6(_r(L))}.\n"
            f"2. The signed distance (P - Q)·n = {fmt((P - Q) @ N)}/{_f6(_r(L))} = {_f6(_r(d))}.\n"
            f"3. P' = P - 2((P - Q)·n) n = {fmt(P)} - {_f6(_r(2 * d))} n = {_f6(_r(_mirror_answers(p)[0]))}.")


@DECK.exercise(stored=_STORED_MIRROR, generate=_mirror_generate, answer=lambda p: _mirror_answers(p)[0],
               slips=lambda p: _mirror_answers(p)[1], statement=_mirror_statement, steps=_mirror_steps,
               same=_same, well_posed=_mirror_ok)
def check_mirror_point(answer, p) -> Result:
    """Check P mirrored in the statement's plane (Goldman §12.3);
    recognises the orthogonal projection (factor 1 instead of 2), the unnormalised normal, the plane
    taken through the origin (Q forgotten) and the wrong sign.

    >>> check_mirror_point([4 / 3, -13 / 3, -7 / 3])
    Not yet: that is the mirror in the parallel plane through the origin: use (P - Q)·n, the signed distance from the plane through Q.
    """
    got, err = _read_point(answer, "the mirror image as [x, y, z]")
    if err is not None:
        return err
    P, Q, N = _arr(p["P"]), _arr(p["Q"]), _arr(p["N"])
    n = _unit(N)
    expected = transforms.reflect(P[None], Q, N)[0]
    d = float((P - Q) @ n)
    if _close(got, expected):
        return correct(f"(P - Q)·n = {fmt(d)} for the unit normal n = N/{fmt(np.linalg.norm(N))}, so "
                       f"P' = P - 2·{fmt(d)} n.")
    if _close(got, transforms.project_orthogonal(P[None], Q, N)[0]):
        return wrong("that is the foot of the perpendicular, on the plane (factor 1): the mirror image is as far "
                     "beyond the plane as P is in front of it, P - 2((P - Q)·n) n.")
    if _close(got, P - 2 * ((P - Q) @ N) * N) or _close(got, P - 2 * ((P - Q) @ n) * N) \
            or _close(got, P - 2 * ((P - Q) @ N) * n):
        return wrong(f"the normal N = {_p(N)} has length {fmt(np.linalg.norm(N))}, not 1: divide it by its length "
                     f"before using P - 2((P - Q)·n) n.")
    if _close(got, P - 2 * (P @ n) * n):
        return wrong("that is the mirror in the parallel plane through the origin: use (P - Q)·n, the signed "
                     "distance from the plane through Q.")
    if _close(got, P + 2 * d * n):
        return wrong("the sign is wrong: that moves P further away from the plane. Subtract 2((P - Q)·n) n.")
    return _far(got, expected, "compute the signed distance (P - Q)·n with the unit normal, and go twice that "
                               "distance along -n")


# -- §12.4 ----------------------------------------------------------------------------------------------------

_STORED_SCALE = {"P": _tup(SCALE_POINT), "s": SCALE_FACTOR, "d": _tup(SCALE_DIRECTION), "Q": _tup(SCALE_CENTER)}


@memo
def _scale_answers(p):
    P, s, d, Q = _arr(p["P"]), p["s"], _arr(p["d"]), _arr(p["Q"])
    w = _unit(d)
    k = float((P - Q) @ w)
    slips = {"uniform": transforms.scale(P[None], s, center=Q)[0],
             "about the origin": transforms.scale_along(P[None], s, d)[0],
             "direction not normalised": P + (s - 1) * ((P - Q) @ d) * d,
             "s for s - 1": P + s * k * w}
    return transforms.scale_along(P[None], s, d, center=Q)[0], slips


def _scale_generate(rng) -> dict:
    return {"P": _ints(rng, -3, 4), "s": float(rng.choice([2.0, 3.0, 4.0, 0.5, -1.0])), "d": _whole(rng),
            "Q": _ints(rng, -2, 2)}


def _scale_ok(p):
    v, d = _arr(p["P"]) - _arr(p["Q"]), _arr(p["d"])
    if abs(float(v @ d)) < 0.5:
        return "P - Q is perpendicular to the direction: P does not move"
    if float(np.linalg.norm(np.cross(v, d))) < 0.5:
        return "P - Q lies along the direction: the uniform scaling would be right"
    P, s, d, Q = _arr(p["P"]), p["s"], _arr(p["d"]), _arr(p["Q"])
    ans, slips = _scale_answers(p)
    unnormalised = [P + (s - 1) * ((P - Q) @ d) * d, P + (s - 1) * ((P - Q) @ d) * _unit(d)]
    if not _groups_apart([[ans], [slips["uniform"]], [slips["about the origin"]], unnormalised, [slips["s for s - 1"]]]):
        return "two recognised forms coincide (the unnormalised direction's two forms included)"
    return None


def _scale_statement(p) -> str:
    return (f"Scale the point P = {_p(p['P'])} by the factor s = {fmt(p['s'])} in the direction "
            f"{_p(p['d'])} only (a nonuniform scaling: directions perpendicular to it are kept), about the "
            f"centre Q = {_p(p['Q'])}. Give the image [x, y, z] (Goldman §12.4).")


def _scale_steps(p) -> str:
    P, s, d, Q = _arr(p["P"]), p["s"], _arr(p["d"]), _arr(p["Q"])
    L = float(np.linalg.norm(d))
    k = float((P - Q) @ d) / L
    return (f"1. The unit direction w = {fmt(d)}/{_f6(_r(L))} = {_f6(_r(d / L))}.\n"
            f"2. The component of P - Q = {fmt(P - Q)} along w: (P - Q)·w = {_f6(_r(k))}.\n"
            f"3. It becomes s times itself, so P moves by (s - 1)((P - Q)·w) w = {_f6(_r((s - 1) * k * d / L))}.\n"
            f"4. P' = {_f6(_r(_scale_answers(p)[0]))}.")


@DECK.exercise(stored=_STORED_SCALE, generate=_scale_generate, answer=lambda p: _scale_answers(p)[0],
               slips=lambda p: _scale_answers(p)[1], statement=_scale_statement, steps=_scale_steps,
               same=_same, well_posed=_scale_ok)
def check_scale_along(answer, p) -> Result:
    """Check the nonuniform scaling of the statement's point P (Goldman §12.4); recognises the uniform scaling,
    the scaling about the origin, the unnormalised direction and the factor s used for s - 1.
    """
    got, err = _read_point(answer, "the scaled point as [x, y, z]")
    if err is not None:
        return err
    P, s, d, Q = _arr(p["P"]), p["s"], _arr(p["d"]), _arr(p["Q"])
    w = _unit(d)
    expected = transforms.scale_along(P[None], s, d, center=Q)[0]
    k = float((P - Q) @ w)
    if _close(got, expected):
        return correct(f"(P - Q)·w = {fmt(k)} along the unit w = {fmt(w)}, so P' = P + (s - 1)·{fmt(k)} w.")
    if _close(got, transforms.scale(P[None], s, center=Q)[0]):
        return wrong("that is the uniform scaling Q + s(P - Q): every direction is stretched. Here only the "
                     "component of P - Q along the direction is multiplied by s.")
    if _close(got, transforms.scale_along(P[None], s, d)[0]):
        return wrong("that is the scaling about the origin; the centre Q stays fixed, so use (P - Q)·w.")
    if _close(got, P + (s - 1) * ((P - Q) @ d) * d) or _close(got, P + (s - 1) * ((P - Q) @ d) * w):
        return wrong(f"the direction {_p(d)} has length {fmt(np.linalg.norm(d))}: divide it by its length before "
                     f"projecting onto it.")
    if _close(got, P + s * k * w):
        return wrong("the component along w becomes s times itself, so it grows by (s - 1) times itself: "
                     "P + (s - 1)((P - Q)·w) w, not s.")
    return _far(got, expected, "split P - Q into its part along the unit w and the rest, multiply the first by "
                               "s, and add Q")


# -- §12.5 ----------------------------------------------------------------------------------------------------

_STORED_ORTHO = {"P": _tup(ORTHO_POINT), "Q": _tup(ORTHO_PLANE_POINT), "N": _tup(ORTHO_NORMAL)}


@memo
def _ortho_answers(p):
    P, Q, N = _arr(p["P"]), _arr(p["Q"]), _arr(p["N"])
    n = _unit(N)
    slips = {"the mirror": transforms.reflect(P[None], Q, N)[0], "N not normalised": P - ((P - Q) @ N) * N,
             "plane through the origin": P - (P @ n) * n}
    return transforms.project_orthogonal(P[None], Q, N)[0], slips


def _ortho_statement(p) -> str:
    return (f"Project the point P = {_p(p['P'])} orthogonally onto the plane through Q = {_p(p['Q'])} "
            f"with normal N = {_p(p['N'])}. Give [x, y, z]; fractions or 4-digit decimals are fine "
            f"(Goldman §12.5).")


def _ortho_steps(p) -> str:
    P, Q, N = _arr(p["P"]), _arr(p["Q"]), _arr(p["N"])
    L = float(np.linalg.norm(N))
    d = float((P - Q) @ N) / L
    return (f"1. The unit normal n = N/|N| = {fmt(N)}/{_f6(_r(L))}.\n"
            f"2. The signed distance (P - Q)·n = {fmt((P - Q) @ N)}/{_f6(_r(L))} = {_f6(_r(d))}.\n"
            f"3. P' = P - ((P - Q)·n) n = {fmt(P)} - {_f6(_r(d))} n = {_f6(_r(_ortho_answers(p)[0]))}; check that "
            f"(P' - Q)·N = 0.")


@DECK.exercise(stored=_STORED_ORTHO, generate=_mirror_generate, answer=lambda p: _ortho_answers(p)[0],
               slips=lambda p: _ortho_answers(p)[1], statement=_ortho_statement, steps=_ortho_steps,
               same=_same, well_posed=_ortho_ok)
def check_orthogonal_projection(answer, p) -> Result:
    """Check the orthogonal projection of the statement's point P (Goldman §12.5); recognises the mirror image
    (factor 2), the unnormalised normal and the plane through the origin.
    """
    got, err = _read_point(answer, "the projected point as [x, y, z]")
    if err is not None:
        return err
    P, Q, N = _arr(p["P"]), _arr(p["Q"]), _arr(p["N"])
    n = _unit(N)
    expected = transforms.project_orthogonal(P[None], Q, N)[0]
    d = float((P - Q) @ n)
    if _close(got, expected):
        return correct(f"(P - Q)·n = {fmt(d)} for n = N/{fmt(np.linalg.norm(N))}, so P' = P - {fmt(d)} n, which lies "
                       f"on the plane.")
    if _close(got, transforms.reflect(P[None], Q, N)[0]):
        return wrong("that is the mirror image (factor 2): the projection stops on the plane, P - ((P - Q)·n) n.")
    if _close(got, P - ((P - Q) @ N) * N) or _close(got, P - ((P - Q) @ n) * N) or _close(got, P - ((P - Q) @ N) * n):
        return wrong(f"the normal {_p(N)} has length {fmt(np.linalg.norm(N))}, not 1: use n = N/|N| in both places "
                     f"of P - ((P - Q)·n) n" + _on_plane_check(got, Q, N) + ".")
    if _close(got, P - (P @ n) * n):
        return wrong("that projects onto the parallel plane through the origin: measure the distance from the "
                     "plane through Q, (P - Q)·n" + _on_plane_check(got, Q, N) + ".")
    return _far(got, expected, "subtract from P its signed distance (P - Q)·n times the unit normal"
                + _on_plane_check(got, Q, N))


_STORED_PERSP = {"P": _tup(PERSP_POINT), "E": _tup(PERSP_EYE), "Q": _tup(PERSP_PLANE_POINT), "N": _tup(PERSP_NORMAL)}


def _ratio(p):
    P, E, Q, N = (_arr(p[k]) for k in ("P", "E", "Q", "N"))
    num, den = float((Q - E) @ N), float((P - E) @ N)
    return (-num, -den) if den < 0 else (num, den)   # t's sign on the numerator (4/6, not -4/-6)


@memo
def _persp_answers(p):
    P, E, Q, N = (_arr(p[k]) for k in ("P", "E", "Q", "N"))
    num, den = _ratio(p)
    t = num / den
    slips = {"ratio upside down": E + (P - E) / t, "orthogonal": transforms.project_orthogonal(P[None], Q, N)[0],
             "eye at the origin": (Q @ N) / (P @ N) * P, "t P": t * P}
    return transforms.project_perspective(P[None], E, Q, N)[0], slips


def _persp_generate(rng) -> dict:
    N = _arr(_ints(rng, -1, 2))
    return {"P": _ints(rng, -3, 4), "E": _ints(rng, -3, 3), "Q": _ints(rng, -2, 3), "N": _tup(N)}


def _persp_ok(p):
    P, E, Q, N = (_arr(p[k]) for k in ("P", "E", "Q", "N"))
    num, den = _ratio(p)
    if not np.any(N) or abs(den) < 0.5 or abs(num) < 0.5:
        return "the line of sight is parallel to the plane, or the eye lies on it"
    if abs(float(P @ N)) < 0.5:
        return "P·N = 0: the perspective from the origin is undefined"
    if not 0.2 <= num / den <= 5:
        return "the image lies behind the eye or far out (t outside [0.2, 5])"
    ans, slips = _persp_answers(p)
    t = num / den
    if not _groups_apart([[ans], [slips["ratio upside down"]], [slips["orthogonal"]], [slips["eye at the origin"]],
                          [t * P, E + t * P]]):
        return "two recognised forms coincide"
    return None


def _persp_statement(p) -> str:
    return (f"Project the point P = {_p(p['P'])} in perspective from the eye E = {_p(p['E'])} onto the plane "
            f"through Q = {_p(p['Q'])} with normal N = {_p(p['N'])}: the image is where the line "
            f"from E through P meets the plane. Give [x, y, z]; fractions or 4-digit decimals are fine "
            f"(Goldman §12.5).")


def _persp_steps(p) -> str:
    P, E, Q, N = (_arr(p[k]) for k in ("P", "E", "Q", "N"))
    num, den = float((Q - E) @ N), float((P - E) @ N)
    return (f"1. The line of sight is E + t (P - E) with P - E = {fmt(P - E)}.\n"
            f"2. It meets the plane where (E + t (P - E) - Q)·N = 0: t = (Q - E)·N / (P - E)·N = "
            f"{fmt(num)}/{fmt(den)} = {_f6(_r(num / den))}.\n"
            f"3. P' = E + t (P - E) = {_f6(_r(_persp_answers(p)[0]))}.")


@DECK.exercise(stored=_STORED_PERSP, generate=_persp_generate, answer=lambda p: _persp_answers(p)[0],
               slips=lambda p: _persp_answers(p)[1], statement=_persp_statement, steps=_persp_steps,
               same=_same, well_posed=_persp_ok)
def check_perspective_projection(answer, p) -> Result:
    """Check the perspective image of the statement's point P (Goldman §12.5); recognises the ratio upside
    down, the orthogonal projection, the eye taken at the origin and the ratio applied to P itself.
    """
    got, err = _read_point(answer, "the perspective image as [x, y, z]")
    if err is not None:
        return err
    P, E, Q, N = (_arr(p[k]) for k in ("P", "E", "Q", "N"))
    expected = transforms.project_perspective(P[None], E, Q, N)[0]
    num, den = _ratio(p)
    t = num / den
    if _close(got, expected):
        return correct(f"P' = E + t (P - E) with t = (Q - E)·N / (P - E)·N = {fmt(num)}/{fmt(den)}; the length of N "
                       f"cancels.")
    if _close(got, E + (P - E) / t):
        return wrong("the ratio is upside down: t = (Q - E)·N / (P - E)·N, the eye's distance to the plane over "
                     "P's height above the eye" + _on_plane_check(got, Q, N) + ".")
    if _close(got, transforms.project_orthogonal(P[None], Q, N)[0]):
        return wrong("that is the orthogonal projection, along the normal; a perspective image lies on the line "
                     "of sight from the eye E through P.")
    if _close(got, (Q @ N) / (P @ N) * P):
        return wrong("that is the perspective from the origin; the eye is E, so use P - E and Q - E, and start "
                     "from E: E + t (P - E).")
    if _close(got, t * P) or _close(got, E + t * P):
        return wrong("the ratio t scales the vector P - E from the eye: P' = E + t (P - E).")
    return _far(got, expected, "find t with E + t (P - E) on the plane, ((E + t (P - E)) - Q)·N = 0"
                + _on_plane_check(got, Q, N))


#: Deal another instance of an exercise (``deal("check_mirror_point")``, or with ``seed=``; 0 is
#: the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


SLIPS = {
    "check_rotation_about_point": [
        [1, 3, 1],            # about the origin: (3, 1, 1) -> (1, 3, 1)
        [2, -1, 4],           # the other way: v -> (1, -1, 2)
        [-1, 2, 1],           # Q not added back
        [3 - 3 ** 0.5, 2.5 + 1.5 * 3 ** 0.5, 5.5 - 3 ** 0.5 / 2],   # the axis (1, 1, 1) not normalised
        list(ROTATE_THROUGH + _rodrigues_unnormalised(ROTATE_POINT - ROTATE_THROUGH,
                                                      ROTATE_AXIS / np.linalg.norm(ROTATE_AXIS),
                                                      math.degrees(120.0))),  # 120 taken as radians
    ],
    "check_mirror_point": [
        [3, -1, 1],           # factor 1: the projection
        [-14, -35, -33],      # unnormalised N: P - 2 ((P - Q)·N) N
        [4 / 3, -13 / 3, -7 / 3],   # plane through the origin
        [6, 5, 7],            # wrong sign
    ],
    "check_scale_along": [
        [4, 7, 4],            # uniform
        [2, 7.08, 7.44],      # about the origin
        [2, 63, 82],          # unnormalised direction
        [2, 6.6, 6.8],        # s instead of s - 1
    ],
    "check_orthogonal_projection": [
        [-8 / 3, 7 / 3, -8 / 3],    # mirror
        [-26, 14, -26],             # unnormalised normal
        [4 - 34 / 9, -1 + 17 / 9, 4 - 34 / 9],   # plane through the origin
    ],
    "check_perspective_projection": [
        [5, 2, 4],            # ratio upside down
        [2, 0, 3],            # orthogonal projection
        [1.5, 0.5, 1.5],      # eye at the origin
        [2, 2 / 3, 2],        # t P
    ],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

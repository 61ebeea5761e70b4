"""Exercise checkers for chapter 12, the coordinate-free formulas of affine and projective
transformations (Goldman §12.3-12.5): rotation about an axis through a point (Rodrigues' formula),
mirror in a plane, nonuniform scaling, orthogonal and perspective projection.

Each exercise's data are module constants, so the notebook prints the problem from here and the
checker and the statement never disagree; ``PROBLEMS`` holds the statements by checker name and
``SLIPS`` the wrong answers of the kinds each checker recognises.  Hand-computed decimals are
accepted to a relative 1e-4 (2/3 typed as 0.6667 is right).
"""

from __future__ import annotations

import math

import numpy as np

from goldman_lib import transforms
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_points, wrong

__all__ = ["PROBLEMS", "SLIPS", "ROTATE_POINT", "ROTATE_AXIS", "ROTATE_THROUGH", "ROTATE_ANGLE", "MIRROR_POINT",
           "MIRROR_PLANE_POINT", "MIRROR_NORMAL", "SCALE_POINT", "SCALE_FACTOR", "SCALE_DIRECTION", "SCALE_CENTER",
           "ORTHO_POINT", "ORTHO_PLANE_POINT", "ORTHO_NORMAL", "PERSP_POINT", "PERSP_EYE", "PERSP_PLANE_POINT",
           "PERSP_NORMAL", "check_rotation_about_point", "check_mirror_point", "check_scale_along",
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


def _p(x) -> str:
    return fmt(x)


PROBLEMS = {
    "check_rotation_about_point": (
        f"Rotate the point P = {_p(ROTATE_POINT)} by {fmt(ROTATE_ANGLE)} degrees about the line through "
        f"Q = {_p(ROTATE_THROUGH)} in the direction {_p(ROTATE_AXIS)} (counterclockwise looking down the axis, "
        f"from its tip towards Q). Use Rodrigues' formula on v = P - Q: R(v) = cos θ v + (1 - cos θ)(v·w) w + "
        f"sin θ (w × v) with w the unit axis, then add Q back. Give [x, y, z] (Goldman §12.3)."),
    "check_mirror_point": (
        f"Mirror the point P = {_p(MIRROR_POINT)} in the plane through Q = {_p(MIRROR_PLANE_POINT)} with normal "
        f"N = {_p(MIRROR_NORMAL)}. Give the image [x, y, z] (Goldman §12.3)."),
    "check_scale_along": (
        f"Scale the point P = {_p(SCALE_POINT)} by the factor s = {fmt(SCALE_FACTOR)} in the direction "
        f"{_p(SCALE_DIRECTION)} only (a nonuniform scaling: directions perpendicular to it are kept), about the "
        f"centre Q = {_p(SCALE_CENTER)}. Give the image [x, y, z] (Goldman §12.4)."),
    "check_orthogonal_projection": (
        f"Project the point P = {_p(ORTHO_POINT)} orthogonally onto the plane through Q = {_p(ORTHO_PLANE_POINT)} "
        f"with normal N = {_p(ORTHO_NORMAL)}. Give [x, y, z]; fractions or 4-digit decimals are fine "
        f"(Goldman §12.5)."),
    "check_perspective_projection": (
        f"Project the point P = {_p(PERSP_POINT)} in perspective from the eye E = {_p(PERSP_EYE)} onto the plane "
        f"through Q = {_p(PERSP_PLANE_POINT)} with normal N = {_p(PERSP_NORMAL)}: the image is where the line "
        f"from E through P meets the plane. Give [x, y, z]; fractions or 4-digit decimals are fine "
        f"(Goldman §12.5)."),
}


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


def check_rotation_about_point(answer) -> Result:
    """Check P rotated about the line through ``ROTATE_THROUGH`` along ``ROTATE_AXIS`` (Goldman §12.3);
    recognises the rotation about the origin, the other sense of rotation, Q not added back, and the
    axis left unnormalised in Rodrigues' formula.
    """
    got, err = _read_point(answer, "the rotated point as [x, y, z]")
    if err is not None:
        return err
    P, w, Q, th = ROTATE_POINT, ROTATE_AXIS, ROTATE_THROUGH, ROTATE_ANGLE
    expected = transforms.rotate(P[None], w, th, point=Q)[0]
    if _close(got, expected):
        v = P - Q
        return correct(f"v = P - Q = {fmt(v)} turns into {fmt(expected - Q)} (120° about (1, 1, 1) sends (x, y, z) "
                       f"to (z, x, y)), and P' = Q + {fmt(expected - Q)}.")
    if _close(got, transforms.rotate(P[None], w, th)[0]):
        return wrong("that is P rotated about the parallel axis through the origin. The axis passes through Q: "
                     "rotate v = P - Q, then add Q back.")
    if _close(got, transforms.rotate(P[None], w, -th, point=Q)[0]):
        return wrong("that is the rotation the other way (clockwise looking down the axis): check the sign of the "
                     "sin θ (w × v) term, w × v and not v × w.")
    if _close(got, expected - Q):
        return wrong("that is R(P - Q), the rotated vector; the rotated point is Q + R(P - Q).")
    if _close(got, transforms.rotate(P[None], w, math.degrees(th), point=Q)[0]):
        return wrong("you took cos and sin of 120 as if it were radians: the angle is in degrees (np.cos and "
                     "math.cos take radians; convert with np.radians first, cos 120° = -1/2).")
    if _close(got, Q + _rodrigues_unnormalised(P - Q, w, th)):
        return wrong("the axis direction was not normalised: Rodrigues' formula needs the unit vector "
                     "w = (1, 1, 1)/|(1, 1, 1)| in (v·w) w and in w × v.")
    return _far(got, expected, "write v = P - Q, compute v·w and w × v with the unit w, combine them with "
                               "cos 120° = -1/2 and sin 120° = √3/2, and add Q")


def check_mirror_point(answer) -> Result:
    """Check P mirrored in the plane through ``MIRROR_PLANE_POINT`` with ``MIRROR_NORMAL`` (Goldman §12.3);
    recognises the orthogonal projection (factor 1 instead of 2), the unnormalised normal, the plane
    taken through the origin (Q forgotten) and the wrong sign.

    >>> check_mirror_point([4 / 3, -13 / 3, -7 / 3])
    Not yet: that is the mirror in the parallel plane through the origin: use (P - Q)·n, the signed distance from the plane through Q.
    """
    got, err = _read_point(answer, "the mirror image as [x, y, z]")
    if err is not None:
        return err
    P, Q, N = MIRROR_POINT, MIRROR_PLANE_POINT, MIRROR_NORMAL
    n = _unit(N)
    expected = transforms.reflect(P[None], Q, N)[0]
    d = float((P - Q) @ n)
    if _close(got, expected):
        return correct(f"(P - Q)·n = {fmt(d)} for the unit normal n = N/3, so P' = P - 2·{fmt(d)} n.")
    if _close(got, transforms.project_orthogonal(P[None], Q, N)[0]):
        return wrong("that is the foot of the perpendicular, on the plane (factor 1): the mirror image is as far "
                     "beyond the plane as P is in front of it, P - 2((P - Q)·n) n.")
    if _close(got, P - 2 * ((P - Q) @ N) * N) or _close(got, P - 2 * ((P - Q) @ n) * N) \
            or _close(got, P - 2 * ((P - Q) @ N) * n):
        return wrong("the normal N = (1, 2, 2) has length 3, not 1: divide it by its length before using "
                     "P - 2((P - Q)·n) n.")
    if _close(got, P - 2 * (P @ n) * n):
        return wrong("that is the mirror in the parallel plane through the origin: use (P - Q)·n, the signed "
                     "distance from the plane through Q.")
    if _close(got, P + 2 * d * n):
        return wrong("the sign is wrong: that moves P further away from the plane. Subtract 2((P - Q)·n) n.")
    return _far(got, expected, "compute the signed distance (P - Q)·n with the unit normal, and go twice that "
                               "distance along -n")


# -- §12.4 ----------------------------------------------------------------------------------------------------

def check_scale_along(answer) -> Result:
    """Check the nonuniform scaling of ``SCALE_POINT`` (Goldman §12.4); recognises the uniform scaling,
    the scaling about the origin, the unnormalised direction and the factor s used for s - 1.
    """
    got, err = _read_point(answer, "the scaled point as [x, y, z]")
    if err is not None:
        return err
    P, s, d, Q = SCALE_POINT, SCALE_FACTOR, SCALE_DIRECTION, SCALE_CENTER
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
        return wrong("the direction (0, 3, 4) has length 5: divide it by its length before projecting onto it.")
    if _close(got, P + s * k * w):
        return wrong("the component along w becomes s times itself, so it grows by (s - 1) times itself: "
                     "P + (s - 1)((P - Q)·w) w, not s.")
    return _far(got, expected, "split P - Q into its part along the unit w and the rest, multiply the first by "
                               "s, and add Q")


# -- §12.5 ----------------------------------------------------------------------------------------------------

def check_orthogonal_projection(answer) -> Result:
    """Check the orthogonal projection of ``ORTHO_POINT`` (Goldman §12.5); recognises the mirror image
    (factor 2), the unnormalised normal and the plane through the origin.
    """
    got, err = _read_point(answer, "the projected point as [x, y, z]")
    if err is not None:
        return err
    P, Q, N = ORTHO_POINT, ORTHO_PLANE_POINT, ORTHO_NORMAL
    n = _unit(N)
    expected = transforms.project_orthogonal(P[None], Q, N)[0]
    d = float((P - Q) @ n)
    if _close(got, expected):
        return correct(f"(P - Q)·n = {fmt(d)} for n = N/3, so P' = P - {fmt(d)} n, which lies on the plane.")
    if _close(got, transforms.reflect(P[None], Q, N)[0]):
        return wrong("that is the mirror image (factor 2): the projection stops on the plane, P - ((P - Q)·n) n.")
    if _close(got, P - ((P - Q) @ N) * N) or _close(got, P - ((P - Q) @ n) * N) or _close(got, P - ((P - Q) @ N) * n):
        return wrong("the normal (2, -1, 2) has length 3, not 1: use n = N/|N| in both places of P - ((P - Q)·n) n"
                     + _on_plane_check(got, Q, N) + ".")
    if _close(got, P - (P @ n) * n):
        return wrong("that projects onto the parallel plane through the origin: measure the distance from the "
                     "plane through Q, (P - Q)·n" + _on_plane_check(got, Q, N) + ".")
    return _far(got, expected, "subtract from P its signed distance (P - Q)·n times the unit normal"
                + _on_plane_check(got, Q, N))


def check_perspective_projection(answer) -> Result:
    """Check the perspective image of ``PERSP_POINT`` (Goldman §12.5); recognises the ratio upside
    down, the orthogonal projection, the eye taken at the origin and the ratio applied to P itself.
    """
    got, err = _read_point(answer, "the perspective image as [x, y, z]")
    if err is not None:
        return err
    P, E, Q, N = PERSP_POINT, PERSP_EYE, PERSP_PLANE_POINT, PERSP_NORMAL
    expected = transforms.project_perspective(P[None], E, Q, N)[0]
    t = float((Q - E) @ N) / float((P - E) @ N)
    if _close(got, expected):
        return correct("P' = E + t (P - E) with t = (Q - E)·N / (P - E)·N = 4/6; the length of N cancels.")
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

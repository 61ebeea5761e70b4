"""Corpus of the chapter-15 project (slerp): correct solutions written from the statement alone by
other methods (the sine-weight formula with either tie rule at q0·q1 = 0, the power form
q0 (q0* q1)^t through the quaternion exp/log, a rotation in the plane of q0 and q1 by an orthonormal
pair, lists and arrays) must be accepted; realistic wrong ones must be rejected with the slip named,
among them normalised lerp for close pairs (the constant-speed defect of §15.3.4)."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import ch15


# -- accepted ------------------------------------------------------------------------------------------

def formula_slerp(q0, q1, t):
    """The sine weights, flip when q0·q1 < 0, a list as the result."""
    q0, q1 = [float(x) for x in q0], [float(x) for x in q1]
    d = sum(a * b for a, b in zip(q0, q1))
    if d < 0:
        q1, d = [-x for x in q1], -d
    theta = math.acos(min(1.0, d))
    s = math.sin(theta)
    if s < 1e-9:
        q = [(1 - t) * a + t * b for a, b in zip(q0, q1)]
        n = math.sqrt(sum(x * x for x in q))
        return [x / n for x in q]
    return [(math.sin((1 - t) * theta) * a + math.sin(t * theta) * b) / s for a, b in zip(q0, q1)]


def _mul(p, q):
    w1, x1, y1, z1 = p
    w2, x2, y2, z2 = q
    return np.array([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2])


def power_slerp(q0, q1, t):
    """q0 (q0* q1)^t, the power through the polar form cos φ + u sin φ -> cos tφ + u sin tφ; the
    tie q0·q1 = 0 resolved the other way (flip when q0·q1 <= 0)."""
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    if q0 @ q1 <= 0:
        q1 = -q1
    r = _mul(q0 * [1, -1, -1, -1], q1)          # q0* q1, a unit quaternion with r_w = q0·q1 >= 0
    v = r[1:]
    nv = np.linalg.norm(v)
    phi = math.atan2(nv, r[0])
    if nv < 1e-12:
        return q0.copy()
    rt = np.r_[math.cos(t * phi), math.sin(t * phi) * v / nv]
    return _mul(q0, rt)


def plane_slerp(q0, q1, t):
    """A rotation in the plane of q0 and q1: u = the unit part of q1 orthogonal to q0, then
    cos(tθ) q0 + sin(tθ) u; θ by atan2 (no arccos near 1)."""
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    d = q0 @ q1
    if d < 0:
        q1, d = -q1, -d
    u = q1 - d * q0
    nu = np.linalg.norm(u)
    if nu < 1e-14:
        return q0
    theta = math.atan2(nu, d)
    return math.cos(t * theta) * q0 + math.sin(t * theta) * u / nu


ACCEPTED = [formula_slerp, power_slerp, plane_slerp]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch15.check_slerp_project(solution)
    assert r.correct, r.message


def test_both_tie_rules_are_accepted_and_differ_on_the_tie_case():
    tie = next(c for c in ch15.slerp_project_cases() if "q0·q1 = 0" in c.kind)
    a, b = formula_slerp(*tie.args), power_slerp(*tie.args)
    assert min(np.linalg.norm(np.subtract(a, b)), np.linalg.norm(np.add(a, b))) > 0.1


def test_the_vectorised_cases_accept_a_loop_over_t():
    r = ch15.check_slerp_project(lambda q0, q1, t: np.array([plane_slerp(q0, q1, s) for s in np.atleast_1d(t)])
                                 if np.ndim(t) else plane_slerp(q0, q1, t), vectorised=True)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def _nlerp(q0, q1, t):
    q = (1 - t) * q0 + t * q1
    return q / np.linalg.norm(q)


def nlerp_when_close(q0, q1, t):                 # normalised lerp whenever q0·q1 > 0.7 (up to about 90 degrees)
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    if q0 @ q1 < 0:
        q1 = -q1
    if q0 @ q1 > 0.7:
        return _nlerp(q0, q1, t)
    return np.asarray(formula_slerp(q0, q1, t))


def nlerp_near_the_ends(q0, q1, t):              # the fallback taken far too early: sin θ < 0.1
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    if q0 @ q1 < 0:
        q1 = -q1
    if math.sqrt(max(0.0, 1 - (q0 @ q1) ** 2)) < 0.1:
        return _nlerp(q0, q1, t)
    return np.asarray(formula_slerp(q0, q1, t))


def no_flip(q0, q1, t):                          # the longer arc when q0·q1 < 0
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    theta = math.acos(max(-1.0, min(1.0, q0 @ q1)))
    if math.sin(theta) < 1e-9:
        return _nlerp(q0, q1, t)
    return (math.sin((1 - t) * theta) * q0 + math.sin(t * theta) * q1) / math.sin(theta)


def plain_lerp(q0, q1, t):                       # not even normalised
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    return (1 - t) * q0 + (t if q0 @ q1 >= 0 else -t) * q1


def swapped_weights(q0, q1, t):                  # sin(tθ) on q0
    return np.asarray(formula_slerp(q0, q1, 1 - t))


def unguarded(q0, q1, t):                        # divides by sin 0 for equal quaternions
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    d = q0 @ q1
    if d < 0:
        q1, d = -q1, -d
    theta = np.arccos(d)
    with np.errstate(all="ignore"):
        return (np.sin((1 - t) * theta) * q0 + np.sin(t * theta) * q1) / np.sin(theta)


REJECTED = [
    (nlerp_when_close, "normalised linear interpolation"),
    (nlerp_near_the_ends, "normalised linear interpolation"),
    (no_flip, "takes the longer arc"),
    (plain_lerp, "linear interpolation (1 - t) q0 + t q1"),
    (swapped_weights, "swapped weights"),
    (unguarded, "NaN"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch15.check_slerp_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message


def test_nlerp_is_caught_on_a_close_pair_away_from_the_middle():
    r = ch15.check_slerp_project(nlerp_when_close)
    assert "t = 0.5)" not in r.message.split(":")[0] and "t = 0.25" in r.message.split(":")[0]

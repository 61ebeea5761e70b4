"""Chapter 15 exercise checkers: right answers worked by hand here, each recognised slip gets its own
message (never the answer), and the slerp project checker accepts a correct slerp and names what
is wrong with a subtly wrong or crashing one."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import ch15

R2 = math.sqrt(2.0)

# Worked by hand:
# 1. z = (-1 + 3i)/(2 + i) = (-1 + 3i)(2 - i)/5 = (-2 + i + 6i + 3)/5 = (1 + 7i)/5.
# 2. p q with a = 1, u = (2, 0, -1), b = 2, v = (-1, 1, 3): ab - u·v = 2 - (-2 - 3) = 7;
#    a v + b u + u × v = (-1, 1, 3) + (4, 0, -2) + (1, -5, 2) = (4, -4, 3).
# 3. u = (1, 0, 1)/√2, v = (1, 2, 0): (v·u)u = (1/2, 0, 1/2), u × v = (-2, 1, 2)/√2, θ = 90°:
#    v' = (v·u)u + u × v = (1/2 - √2, √2/2, 1/2 + √2).
# 4. q = (1, (2, 0, 2)), v = (0, 1, 0): (w^2 - |u|^2) v + 2(u·v)u + 2w u × v = -7(0, 1, 0) + 2(-2, 0, 2).
# 5. q = (0.6, 0, 0.48, 0.64): 1 - 2(y^2 + z^2) = -0.28, 2(xy + wz) = 0.768, 2(xz - wy) = -0.576, ...
# 6. q0 turns 40° about z, q1 300° = -60°; q0·q1 < 0, so from 40° to -60° (shorter): 40 - 0.3·100 = 10.
# 7. In the xy-plane (3/4) I + (1/4) R acts as 3/4 + (1/4)e^{i120°} = 5/8 + i √3/8, modulus √28/8 = √7/4.
RIGHT = {
    "check_complex_factor": [0.2, 1.4],
    "check_quaternion_product": [7, 4, -4, 3],
    "check_rotated_vector": [0.5 - R2, R2 / 2, 0.5 + R2],
    "check_conformal_image": [-4, -7, 4],
    "check_rotation_matrix": [[-0.28, 0.768, -0.576], [-0.768, 0.1808, 0.6144], [0.576, 0.6144, 0.5392]],
    "check_slerp_angle": 10.0,
    "check_lerp_distortion": 1 - math.sqrt(7) / 4,
}


@pytest.mark.parametrize("name", sorted(RIGHT))
def test_right_answers_worked_by_hand(name):
    r = getattr(ch15, name)(RIGHT[name])
    assert r.correct, r


def test_rounded_answers_are_accepted():
    assert ch15.check_rotated_vector([-0.9142, 0.7071, 1.9142]).correct
    assert ch15.check_slerp_angle(10.00).correct and ch15.check_lerp_distortion(0.3386).correct
    M = np.eye(4)
    M[:3, :3] = RIGHT["check_rotation_matrix"]
    assert ch15.check_rotation_matrix(M.tolist()).correct      # the 4x4 form


SLIP_MESSAGES = {
    "check_complex_factor": ["the product", "upside down", "instead of its conjugate", "one by one"],
    "check_quaternion_product": ["that is q p", "lacks the cross product", "adds u·v", "coordinate by coordinate"],
    "check_rotated_vector": ["twice the angle", "that is q* v q", "q v q:", "not a unit quaternion", "as if it were radians"],
    "check_conformal_image": ["rotation alone", "scaled by |q|", "that is q* v q", "q v q:"],
    "check_rotation_matrix": ["transposed matrix", "off-diagonal entries are half", "diagonal entries lack",
                              "order (x, y, z, w)"],
    "check_slerp_angle": ["longer way round", "half angle", "measured t from q1", "normalised linear interpolation",
                          "as if it were radians"],
    "check_lerp_distortion": ["not a rotation", "the scale factor", "σ^2", "halfway"],
}


@pytest.mark.parametrize("name", sorted(SLIP_MESSAGES))
def test_each_slip_gets_its_own_message(name):
    slips = ch15.SLIPS[name]
    assert len(slips) == len(SLIP_MESSAGES[name])
    for slip, phrase in zip(slips, SLIP_MESSAGES[name]):
        r = getattr(ch15, name)(slip)
        assert r.answered and not r.correct and phrase in r.message, (slip, r)


def test_other_wrong_answers_say_how_far_off_and_what_to_check():
    r = ch15.check_quaternion_product([7, 4, -4, 2])
    assert "off from p q" in r.message
    r = ch15.check_rotated_vector([1, 1, 1])
    assert "its length should stay" in r.message
    r = ch15.check_slerp_angle(20)
    assert "much too large" in r.message
    r = ch15.check_rotation_matrix(np.eye(3).tolist())
    assert "entries are off" in r.message
    r = ch15.check_rotation_matrix(np.eye(4).tolist()[:3])
    assert "3x3 matrix" in r.message


# -- the programming project ---------------------------------------------------------------------------

def good_slerp(q0, q1, t):
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    d = float(q0 @ q1)
    if d < 0:
        q1, d = -q1, -d
    theta = math.acos(min(d, 1.0))
    if math.sin(theta) < 1e-9:
        q = (1 - t) * q0 + t * q1
        return q / np.linalg.norm(q)
    return (math.sin((1 - t) * theta) * q0 + math.sin(t * theta) * q1) / math.sin(theta)


def longer_arc_slerp(q0, q1, t):       # forgets to negate q1 when q0·q1 < 0
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    theta = math.acos(max(-1.0, min(float(q0 @ q1), 1.0)))
    if math.sin(theta) < 1e-9:
        q = (1 - t) * q0 + t * q1
        return q / np.linalg.norm(q)
    return (math.sin((1 - t) * theta) * q0 + math.sin(t * theta) * q1) / math.sin(theta)


def lerp(q0, q1, t):                   # linear interpolation, not normalised
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    if q0 @ q1 < 0:
        q1 = -q1
    return (1 - t) * q0 + t * q1


def unguarded_slerp(q0, q1, t):        # divides by sin θ = 0 for equal quaternions
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    d = float(q0 @ q1)
    if d < 0:
        q1, d = -q1, -d
    theta = np.arccos(d)
    with np.errstate(all="ignore"):
        return (np.sin((1 - t) * theta) * q0 + np.sin(t * theta) * q1) / np.sin(theta)


def crashing_slerp(q0, q1, t):
    theta = math.acos(q0 @ q1)
    return q0[4] * theta


def test_project_accepts_a_correct_slerp_and_names_the_case_kinds():
    r = ch15.check_slerp_project(good_slerp)
    assert r.correct, r
    assert "21 cases" in r.message and "nearly equal" in r.message and "q1 = -q0" in r.message


def test_project_accepts_either_sign_of_the_result():
    r = ch15.check_slerp_project(lambda q0, q1, t: -good_slerp(q0, q1, t))
    assert r.correct, r


def test_project_names_the_longer_arc():
    r = ch15.check_slerp_project(longer_arc_slerp)
    assert not r.correct and r.answered
    assert "case 6 of 21 (q0 = " in r.message and "t = 0.25" in r.message
    assert "takes the longer arc: negate q1 when q0·q1 < 0" in r.message


def test_project_names_linear_interpolation_without_normalising():
    r = ch15.check_slerp_project(lerp)
    assert "case 1 of 21" in r.message and "linear interpolation (1 - t) q0 + t q1, of length" in r.message


def test_project_names_a_division_by_sin_zero():
    r = ch15.check_slerp_project(unguarded_slerp)
    assert "(the same rotation)" not in r.message   # the label is the input, the kind is not printed
    assert "case 10 of 21" in r.message and "NaN" in r.message and "sin θ = 0" in r.message


def test_project_reports_a_crash_with_the_learners_line():
    r = ch15.check_slerp_project(crashing_slerp)
    assert not r.correct and r.answered
    assert "IndexError" in r.message and "return q0[4] * theta" in r.message


def test_project_unanswered_starter():
    def slerp(q0, q1, t):
        """Starter."""
        ...

    assert not ch15.check_slerp_project(slerp).answered
    assert not ch15.check_slerp_project(None).answered


def test_project_cases_are_fixed_by_the_seed_and_cover_the_degenerate_kinds():
    a, b = ch15.slerp_project_cases(), ch15.slerp_project_cases()
    assert [c.label for c in a] == [c.label for c in b]
    kinds = {c.kind for c in a}
    assert {"t = 0", "t = 1", "identical (θ = 0)", "nearly equal (θ ≈ 1e-9)", "q1 = -q0 (the same rotation)",
            "q0·q1 < 0 (the shorter arc)", "half a turn apart (q0·q1 = 0: either arc)"} <= kinds
    for c in a:
        q0, q1, _ = c.args
        assert np.isclose(np.linalg.norm(q0), 1) and np.isclose(np.linalg.norm(q1), 1)
        if c.kind.startswith("q0·q1 < 0"):
            assert q0 @ q1 < 0


def vector_slerp(q0, q1, t):
    t = np.asarray(t, dtype=float)
    if t.ndim == 0:
        return good_slerp(q0, q1, float(t))
    return np.array([good_slerp(q0, q1, float(s)) for s in t])


def test_project_checks_an_array_of_t_when_asked():
    r = ch15.check_slerp_project(vector_slerp, vectorised=True)
    assert r.correct and "24 cases" in r.message and "an array of t" in r.message, r
    r = ch15.check_slerp_project(good_slerp, vectorised=True)     # a scalar-only slerp fails the array cases
    assert not r.correct and "case 22 of 24" in r.message
    r = ch15.check_slerp_project(lambda q0, q1, t: np.array([lerp(q0, q1, s) for s in np.atleast_1d(t)]).squeeze(),
                                 vectorised=True)
    assert not r.correct and "linear interpolation" in r.message

"""Chapter 17 exercise checkers: right answers worked by hand here, each recognised slip gets its own
message (never the answer)."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import ch17

# Worked by hand:
# 1. N = (0, 3, 4)/5 = (0, 0.6, 0.8); d = (1, 2, -2)/3; d.N = (1.2 - 1.6)/3 = -2/15;
#    R = d - 2 (d.N) N = (1/3, 2/3 + 4/15 * 0.6, -2/3 + 4/15 * 0.8) = (1/3, 0.82667, -0.45333).
# 2. sin(theta1) = 0.6; sin(theta2) = 0.6 / 1.25 = 0.48; cos(theta2) = sqrt(1 - 0.2304) = sqrt(0.7696).
# 3. sin(theta_c) = 1.2 / 1.6 = 0.75; theta_c = asin(0.75) = 48.5904 degrees.
# 4. L0 = (2, 0, 4): the ray P + t (2, 0, 4) passes the centre (1, 0, 2) at t = 1/2 < 1: blocked.
#    L1 = (-2, 1, 4): |C|^2 - (C.u)^2 = 5 - 36/21 = 3.29 > 0.64: the line misses the sphere.
#    L2 = (0.5, 0, 1): the line meets the sphere for t in 2 -+ 0.8/sqrt(1.25) = [1.28, 2.72], beyond the light (t = 1).
#    L3 = (0, 2, -1): L.N = -1 < 0, below the floor.  Blocked: [0, 3].
# 5. levels 0..4 of a binary tree: 1 + 2 + 4 + 8 + 16 = 31 rays, each with 3 shadow rays: 31 * 4 = 124.
# 6. sphere: (0.8, 0.2, 0.2) + 0.5 (0.2, 0.4, 1.0) = (0.9, 0.4, 0.7); floor: (0.1, 0.1, 0.1) + 0.6 (0.9, 0.4, 0.7).
RIGHT = {
    "check_reflected_direction": [1 / 3, 2 / 3 + 0.16, -2 / 3 + 0.64 / 3],
    "check_refracted_direction": [0.48, 0.0, -math.sqrt(0.7696)],
    "check_critical_angle": math.degrees(math.asin(0.75)),
    "check_blocked_lights": [0, 3],
    "check_ray_tree_size": 124,
    "check_ray_tree_colour": [0.64, 0.34, 0.52],
}


@pytest.mark.parametrize("name", sorted(RIGHT))
def test_right_answers_worked_by_hand(name):
    r = getattr(ch17, name)(RIGHT[name])
    assert r.correct, r


def test_rounded_answers_and_other_forms_are_accepted():
    assert ch17.check_reflected_direction([0.3333, 0.8267, -0.4533]).correct
    assert ch17.check_refracted_direction([0.48, 0, -0.8773]).correct
    assert ch17.check_critical_angle(48.59).correct
    assert ch17.check_blocked_lights((3, 0)).correct and ch17.check_blocked_lights(np.array([0, 3])).correct
    assert ch17.check_ray_tree_size(124.0).correct


SLIP_MESSAGES = {
    "check_reflected_direction": ["reflected d itself", "sign of the correction", "needs a unit normal",
                                  "incoming direction"],
    "check_refracted_direction": ["incoming direction", "upside down", "other side of the normal",
                                  "divided the angle", "reflected ray"],
    "check_critical_angle": ["from the surface", "into air", "radians", "arcsin"],
    "check_blocked_lights": ["does receive", "stops there", "below the floor", "two things"],
    "check_ray_tree_size": ["add the shadow rays", "shadow rays only", "off by one", "off by one", "one level"],
    "check_ray_tree_colour": ["depth 1", "product of both", "without the reflection coefficients"],
}


@pytest.mark.parametrize("name", sorted(SLIP_MESSAGES))
def test_each_slip_gets_its_own_message(name):
    slips = ch17.SLIPS[name]
    assert len(slips) == len(SLIP_MESSAGES[name])
    for slip, phrase in zip(slips, SLIP_MESSAGES[name]):
        r = getattr(ch17, name)(slip)
        assert r.answered and not r.correct and phrase in r.message, (slip, r)


def test_other_wrong_answers_say_how_far_off_and_what_to_check():
    assert "a little too large" in ch17.check_critical_angle(50).message
    assert "2 of the 4 lights are classified wrongly" in ch17.check_blocked_lights([3, 1]).message
    assert "numbered 0 to 3" in ch17.check_blocked_lights([7]).message
    assert "list of light numbers" in ch17.check_blocked_lights("zero").message
    assert "a little too small" in ch17.check_ray_tree_size(120).message
    assert "unit vector" in ch17.check_refracted_direction([0, 0, -1]).message
    assert "should be 3 numbers" in ch17.check_ray_tree_colour([0.5, 0.5]).message
    assert not ch17.check_ray_tree_colour(None).answered

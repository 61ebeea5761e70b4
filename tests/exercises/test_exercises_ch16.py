"""Chapter 16 exercise checkers: right answers worked by hand here, each recognised slip gets its own
message (never the answer)."""

import math

import pytest

from goldman_lib.exercises import ch16

# Worked by hand:
# 1. light arriving (0.9, 0.3, 0) 0.8 + (0.2, 0.5, 1) 0.6 = (0.72, 0.24, 0) + (0.12, 0.3, 0.6) = (0.84, 0.54, 0.6);
#    times C = (0.5, 1, 0.25): (0.42, 0.54, 0.15).
# 2. N = (0, 3, 4)/5, light - P = (2, 0, 4), |.| = sqrt 20; cos = (0 + 0 + 3.2)/sqrt 20;
#    I_p k_d cos = 1.2 * 3.2 / sqrt 20.
# 3. N = (1, 1, 1)/sqrt 3, L.N = 1.4/sqrt 3, R = 2 (1.4/3)(1, 1, 1) - (0.6, 0, 0.8) = (1/3, 14/15, 2/15).
# 4. L = (1, 0, 1)/sqrt 2, R = (-1, 0, 1)/sqrt 2, V = (-1, 1, 3)/sqrt 11, R.V = 4/sqrt 22;
#    0.9 (16/22)^4.
# 5. (cos 12 deg)^n = 1/2: n = ln(1/2)/ln(cos 12 deg).
# 6. ambient 0.4*0.3 C = 0.12 (0.9, 0.5, 0.2) = (0.108, 0.06, 0.024);
#    light 1 at (0, 3, 4): L = (0, 0.6, 0.8), L.N = 0.8, R = (0, -0.6, 0.8), R.V = 0.8:
#      0.7*0.8 C + 0.5*0.8^4 = (0.504, 0.28, 0.112) + 0.2048;
#    light 2 at (4, 0, 3), RGB (1.2, 0.6, 0.6): L.N = 0.6 = R.V:
#      (0.42 C + 0.5*0.6^4) * (1.2, 0.6, 0.6) = (0.4428*1.2, 0.2748*0.6, 0.1488*0.6);
#    total (1.34816, 0.70968, 0.43008), displayed with red clipped to 1.
RIGHT = {
    "check_reflected_colour": [0.42, 0.54, 0.15],
    "check_diffuse": 1.2 * 3.2 / math.sqrt(20),
    "check_mirror_direction": [1 / 3, 14 / 15, 2 / 15],
    "check_specular": 0.9 * (16 / 22) ** 4,
    "check_highlight_exponent": math.log(0.5) / math.log(math.cos(math.radians(12))),
    "check_total_intensity": [1.0, 0.70968, 0.43008],
}


@pytest.mark.parametrize("name", sorted(RIGHT))
def test_right_answers_worked_by_hand(name):
    r = getattr(ch16, name)(RIGHT[name])
    assert r.correct, r


def test_rounded_answers_are_accepted():
    assert ch16.check_diffuse(0.8587).correct and ch16.check_specular(0.2518).correct
    assert ch16.check_mirror_direction([0.3333, 0.9333, 0.1333]).correct
    assert ch16.check_highlight_exponent(31.37).correct and ch16.check_total_intensity([1, 0.7097, 0.4301]).correct


SLIP_MESSAGES = {
    "check_reflected_colour": ["left out the intensities", "light arriving", "multiplied the two lights",
                               "added the surface colour"],
    "check_diffuse": ["normal is not a unit", "L is not a unit", "from the origin", "intensity I_p", "coefficient k_d"],
    "check_mirror_direction": ["that is -R", "N is not a unit", "factor 2"],
    "check_specular": ["Blinn", "left out the exponent", "no L·N factor", "V points the wrong way"],
    "check_highlight_exponent": ["full width", "twice the angle", "small-angle", "1/e"],
    "check_total_intensity": ["total intensity itself", "ambient term", "left out light 2", "left out light 1",
                              "material's colour", "light 2 as white"],
}


@pytest.mark.parametrize("name", sorted(SLIP_MESSAGES))
def test_each_slip_gets_its_own_message(name):
    slips = ch16.SLIPS[name]
    assert len(slips) == len(SLIP_MESSAGES[name])
    for slip, words in zip(slips, SLIP_MESSAGES[name]):
        r = getattr(ch16, name)(slip)
        assert not r.correct and r.answered and words in r.message, (slip, r)


def test_the_doubled_angle_slip_is_named():
    r = ch16.check_highlight_exponent(7.67)
    assert not r.correct and "24 degrees" in r.message


def test_shapes_and_unanswered():
    assert "3 numbers" in ch16.check_mirror_direction([1, 2]).message
    assert not ch16.check_total_intensity(None).answered

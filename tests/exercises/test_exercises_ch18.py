"""Chapter 18 exercise checkers: right answers worked by hand here, each recognised slip gets its own
message (never the answer)."""

import math

import pytest

from goldman_lib.exercises import ch18

S2, S19 = math.sqrt(2), math.sqrt(19)
# Worked by hand:
# 1. grad F = (2x, 4y, -2z) = (2, 4, -2 sqrt 2) at (1, 1, sqrt 2); |grad F| = sqrt(4 + 16 + 8) = sqrt 28.
# 2. X_u = (1, 0, 2uv) = (1, 0, 4), X_v = (0, 1, u^2) = (0, 1, 1); X_u x X_v = (0 - 4, 0 - 1, 1 - 0) = (-4, -1, 1).
# 3. J = [[1, 0, 2], [0, 3, 0], [0, 0, 1]]; J^T m = (1, 1, 1): m_x = 1, 3 m_y = 1, 2 m_x + m_z = 1 -> (1, 1/3, -1);
#    times 3: (3, 1, -3), length sqrt 19.
# 4. G(1, .5, .5) = (0, 0, 3) + (0, 0, -1) - (.5, .5, .5) = (-.5, -.5, 1.5); J = [d, -X_u, -X_v] with
#    X_u = (1, 0, -1), X_v = (0, 1, -1): rows (0, -1, 0), (0, 0, -1), (-1, 1, 1); s = (-.5, .5, .5);
#    (1, .5, .5) - s = (1.5, 0, 0).
# 5. principal curvatures 1/2.5 and 0: K = 0, |H| = 0.2.
# 6. cos 120 = -1/2: K = -0.5 / (1 (3 - 0.5)) = -0.2.
RIGHT = {
    "check_implicit_normal": [2 / math.sqrt(28), 4 / math.sqrt(28), -2 * S2 / math.sqrt(28)],
    "check_parametric_normal": [-4 / math.sqrt(18), -1 / math.sqrt(18), 1 / math.sqrt(18)],
    "check_deformed_normal": [3 / S19, 1 / S19, -3 / S19],
    "check_newton_step": [1.5, 0.0, 0.0],
    "check_cylinder_curvature": [0.0, 0.2],
    "check_torus_curvature": -0.2,
}


@pytest.mark.parametrize("name", sorted(RIGHT))
def test_right_answers_worked_by_hand(name):
    r = getattr(ch18, name)(RIGHT[name])
    assert r.correct, r


def test_rounded_answers_are_accepted_and_a_negative_abs_h_is_not():
    assert ch18.check_implicit_normal([0.378, 0.7559, -0.5345]).correct
    assert ch18.check_deformed_normal([0.6882, 0.2294, -0.6882]).correct
    r = ch18.check_cylinder_curvature([0, -0.2])                     # |H| asked for: never negative
    assert r.answered and not r.correct and "cannot be negative" in r.message, r


SLIP_MESSAGES = {
    "check_implicit_normal": ["grad F itself", "other way", "z-component"],
    "check_parametric_normal": ["X_v × X_u", "divide it by its length", "middle component"],
    "check_deformed_normal": ["like a tangent", "not transposed", "not inverted", "before normalising"],
    "check_newton_step": ["converges", "added the step", "-X_u"],
    "check_cylinder_curvature": ["sphere's values", "around the cylinder alone", "product", "cannot be negative"],
    "check_torus_curvature": ["lost the sign", "R + r cos v", "radians"],
}


@pytest.mark.parametrize("name", sorted(SLIP_MESSAGES))
def test_each_slip_gets_its_own_message(name):
    slips = ch18.SLIPS[name]
    assert len(slips) == len(SLIP_MESSAGES[name])
    for slip, words in zip(slips, SLIP_MESSAGES[name]):
        r = getattr(ch18, name)(slip)
        assert not r.correct and r.answered and words in r.message, (slip, r)

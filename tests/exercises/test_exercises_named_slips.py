"""Slips issue 17 asks chapters 12-15 to name (degrees fed to a radian function, a quaternion read
(x, y, z, w), a centre of mass written [M, x, y]): each wrong answer is computed here independently
(scipy's Rotation, the formulas by hand) and must get the message that names it."""

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from goldman_lib.exercises import ch12, ch13, ch14, ch15


def _unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def _ch12_radians():
    R = Rotation.from_rotvec(_unit(ch12.ROTATE_AXIS) * 120.0)          # 120 read as radians
    return ch12.ROTATE_THROUGH + R.apply(ch12.ROTATE_POINT - ch12.ROTATE_THROUGH)


def _ch13_radians():
    return Rotation.from_rotvec([0.0, 90.0, 0.0]).as_matrix().T           # row convention, 90 as radians


def _ch15_ex3_radians():
    return Rotation.from_rotvec(_unit(ch15.ROTATION_AXIS) * 90.0).apply(ch15.ROTATION_V)


def _ch15_ex5_xyzw():
    return Rotation.from_quat(ch15.MATRIX_Q).as_matrix().T                # scipy reads (x, y, z, w)


def _ch15_ex6_radians():
    q0, q1 = np.array(ch15.SLERP_Q0), -np.array(ch15.SLERP_Q1)           # the shorter arc
    th = math.degrees(math.acos(q0 @ q1))                                # degrees, fed to a radian sine
    q = (math.sin((1 - ch15.SLERP_T) * th) * q0 + math.sin(ch15.SLERP_T * th) * q1) / math.sin(th)
    ang = math.degrees(2 * math.atan2(q[3], q[0]))
    return (ang + 180.0) % 360.0 - 180.0


CASES = [
    (ch12.check_rotation_about_point, _ch12_radians, "radians"),
    (ch13.check_rotation_block, _ch13_radians, "radians"),
    (ch15.check_rotated_vector, _ch15_ex3_radians, "radians"),
    (ch15.check_rotation_matrix, _ch15_ex5_xyzw, "(x, y, z, w)"),
    (ch15.check_slerp_angle, _ch15_ex6_radians, "radians"),
    (ch14.check_center_of_mass, lambda: [4.0, 0.25, 3.25], "[M, x, y]"),
]


@pytest.mark.parametrize("checker, slip, words", CASES, ids=[c[0].__name__ for c in CASES])
def test_the_slip_is_named(checker, slip, words):
    result = checker(np.asarray(slip()).tolist())
    assert not result.correct and result.answered
    assert words in result.message, result.message


@pytest.mark.parametrize("checker, slip, words", CASES, ids=[c[0].__name__ for c in CASES])
def test_the_slip_is_in_slips(checker, slip, words):
    """The leak and solution tests feed SLIPS: each new slip is among them."""
    module = {ch12: ch12, ch13: ch13, ch14: ch14, ch15: ch15}
    mod = next(m for m in module if checker.__name__ in m.SLIPS)
    assert any(np.allclose(np.asarray(s, float), np.asarray(slip(), float), atol=1e-6)
               for s in mod.SLIPS[checker.__name__] if np.shape(s) == np.shape(slip()))

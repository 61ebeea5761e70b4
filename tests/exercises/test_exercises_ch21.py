"""Chapter 21 exercise checkers: right answers worked by hand here, each recognised slip gets its own
message (never the answer), and the Gouraud project checker accepts a correct shader and names what
is wrong with a subtly wrong or crashing one."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import ch21

# Worked by hand:
# 1. Newell on (0,0,0), (3,0,1), (3,2,2), (0,1,0): N_x = 0 - 6 + 2 + 0 = -4, N_y = -3 - 6 + 6 + 0 = -3,
#    N_z = 0 + 0 + 9 + 0 = 9; divided by sqrt(106).
# 2. unit normals (0,0,1), (1,0,0), (0,-1,1)/sqrt2; sum (1, -0.707107, 1.707107), length 2.101003.
# 3. rows y = 0.5 .. 6.5: the centres between the left edge AC and the right edge (AB, then BC) number
#    1, 4, 7, 5, 4, 3, 1 = 25.
# 4. centre (3.5, 2.5) in (0,0), (8,0), (0,6): weights (1 - 0.4375 - 0.416667, 0.4375, 0.416667);
#    0.9 * 0.145833 + 0.3 * 0.4375 + 0.5 * 0.416667 = 0.470833.
# 5. 0.7 (0, 0.6, 0.8) + 0.3 (0.8, 0, 0.6) = (0.24, 0.42, 0.74), length sqrt(0.7816);
#    L . N = (0.24 + 0.84 + 1.48) / 3 / 0.884081 = 0.965217.
# 6. f(12) = 0.576 - 0.6 + 0.9 = 0.876; f(13) = 0.676 - 0.65 + 0.9 = 0.926 (difference 0.05);
#    second difference 2a = 0.008.
# 7. (0.75, 0) + 0.25 (cos 120, sin 120) = (0.625, 0.216506): atan2 gives 19.1066 degrees.
RIGHT = {
    "check_newell_normal": list(np.array([-4, -3, 9]) / math.sqrt(106)),
    "check_vertex_normal": [1 / 2.101003, -0.707107 / 2.101003, 1.707107 / 2.101003],
    "check_pixels_covered": 25,
    "check_gouraud_pixel": 0.470833,
    "check_phong_diffuse": 0.965217,
    "check_forward_differences": [0.876, 0.05, 0.008],
    "check_lerp_angle": 19.107,
}

SLIP_WORDS = {
    "check_newell_normal": ["first corner alone", "other way", "before normalising"],
    "check_vertex_normal": ["by its area", "before normalising", "plain average"],
    "check_pixels_covered": ["area", "bounding box"],
    "check_gouraud_pixel": ["corner", "swapped", "average of the three", "one vertex"],
    "check_phong_diffuse": ["Gouraud", "other end"],
    "check_forward_differences": ["second difference is a", "derivative", "backward difference"],
    "check_lerp_angle": ["t θ", "from N1", "from N1"],
}


@pytest.mark.parametrize("name", sorted(RIGHT))
def test_right_answers_worked_by_hand(name):
    r = getattr(ch21, name)(RIGHT[name])
    assert r.correct, r


@pytest.mark.parametrize("name", sorted(SLIP_WORDS))
def test_each_slip_gets_its_own_message(name):
    for slip, words in zip(ch21.SLIPS[name], SLIP_WORDS[name]):
        r = getattr(ch21, name)(slip)
        assert not r.correct and words in r.message, (slip, r)


def test_pixel_count_by_an_independent_inside_test():
    from matplotlib.path import Path

    jj, ii = np.meshgrid(np.arange(12) + 0.5, np.arange(12) + 0.5)
    inside = Path(np.array(ch21.COVER_TRIANGLE)).contains_points(np.c_[jj.ravel(), ii.ravel()])
    assert inside.sum() == RIGHT["check_pixels_covered"]


def test_unanswered_and_garbage():
    for name in RIGHT:
        f = getattr(ch21, name)
        assert not f(None).answered
        r = f("abc")
        assert not r.correct and r.answered


# -- the programming project ------------------------------------------------------------------------

def good_shader(screen, intensities, width, height):
    P = np.asarray(screen, float)
    out = np.zeros((height, width))
    d1, d2 = P[1] - P[0], P[2] - P[0]
    area = d1[0] * d2[1] - d1[1] * d2[0]
    if abs(area) < 1e-12:
        return out
    for i in range(height):
        for j in range(width):
            qx, qy = j + 0.5 - P[0, 0], i + 0.5 - P[0, 1]
            b = (qx * d2[1] - qy * d2[0]) / area
            c = (d1[0] * qy - d1[1] * qx) / area
            a = 1 - b - c
            if a >= 0 and b >= 0 and c >= 0:
                out[i, j] = a * intensities[0] + b * intensities[1] + c * intensities[2]
    return out


def strict_shader(screen, intensities, width, height):
    """Subtly wrong: a centre on an edge is left out (> 0 instead of >= 0)."""
    out = good_shader(screen, intensities, width, height)
    P = np.asarray(screen, float)
    d1, d2 = P[1] - P[0], P[2] - P[0]
    area = d1[0] * d2[1] - d1[1] * d2[0]
    if abs(area) < 1e-12:
        return out
    for i in range(height):
        for j in range(width):
            qx, qy = j + 0.5 - P[0, 0], i + 0.5 - P[0, 1]
            b = (qx * d2[1] - qy * d2[0]) / area
            c = (d1[0] * qy - d1[1] * qx) / area
            if min(1 - b - c, b, c) == 0:
                out[i, j] = 0.0
    return out


def swapped_shader(screen, intensities, width, height):
    """Subtly wrong: the intensities of vertices 1 and 2 swapped."""
    return good_shader(screen, [intensities[0], intensities[2], intensities[1]], width, height)


def crashing_shader(screen, intensities, width, height):
    P = np.asarray(screen, float).tolist()
    area = (P[1][0] - P[0][0]) * (P[2][1] - P[0][1]) - (P[2][0] - P[0][0]) * (P[1][1] - P[0][1])
    scale = 1.0 / area
    return good_shader(screen, intensities, width, height) * scale * area


def test_project_accepts_a_correct_shader():
    r = ch21.check_gouraud_project(good_shader)
    assert r.correct and "14 cases" in r.message and "edge-on" in r.message and "sliver" in r.message


def test_project_names_a_centre_on_an_edge():
    r = ch21.check_gouraud_project(strict_shader)
    assert not r.correct and "edges through pixel centres" not in r.message     # the label, not the kind
    assert "case 9 of 14" in r.message and "on an edge (it counts as inside)" in r.message


def test_project_names_the_wrong_pixel_of_swapped_intensities():
    r = ch21.check_gouraud_project(swapped_shader)
    assert not r.correct and "case 1 of 14" in r.message and "pixel (row" in r.message and "expected" in r.message


def test_project_reports_a_crash_with_the_learners_line():
    r = ch21.check_gouraud_project(crashing_shader)
    assert not r.correct and "ZeroDivisionError" in r.message and "scale = 1.0 / area" in r.message
    assert "edge-on" in r.message or "collinear" in r.message or "case 11 of 14" in r.message


def test_project_unanswered():
    def starter(screen, intensities, width, height):
        ...
    assert not ch21.check_gouraud_project(starter).answered

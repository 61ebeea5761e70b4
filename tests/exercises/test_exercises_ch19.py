"""Chapter 19 exercise checkers: right answers worked by hand here, each recognised slip gets its own
message (never the answer), and the ray-quadric project checker accepts a correct intersector and names
what is wrong with a subtly wrong or crashing one."""

import math

import numpy as np
import pytest

from goldman_lib.exercises import ch19

# Worked by hand:
# 1. N = (1, 1, 2), Q - P0 = (-1, -2, -4): N·(Q - P0) = -11; N·d = 1 - 1 - 4 = -4; t = 11/4.
# 2. The U: arms 0 <= x <= 1 and 4 <= x <= 5 (up to y = 4), bar 0 <= y <= 1. (0.5, 3) left arm, (2.5, 3)
#    notch, (2.5, 0.5) bar, (4.5, 2) right arm, (5.5, 2) outside.
# 3. P0 - C = (-5, 3, 2): a = 6, b = 2(-10 - 3 - 2) = -30, c = 38 - 9 = 29; t = (30 - sqrt(204)) / 12.
# 4. The wall x = -1 at t = 1 has z = 3 > 2; the top cap z = 2 at t = 2 has x = 0 (inside the disc).
# 5. P = (2.52, 3.36, 1.6): the core circle's nearest point is 3 (0.6, 0.8, 0) = (1.8, 2.4, 0);
#    P - it = (0.72, 0.96, 1.6), of length 2 = r; the unit normal is (0.36, 0.48, 0.8).
# 6. R + r = 2.5, slab |z| <= 0.5: ray 1 (z = 0.3, through the center) passes; ray 2 (distance 3) misses the
#    sphere; ray 3 (z = 1) is above the slab; ray 4 down the axis passes (and misses the torus); ray 5
#    (distance 2.4, z = 0) passes.
RIGHT = {
    "check_plane_parameter": 2.75,
    "check_polygon_inside": [True, False, True, True, False],
    "check_sphere_hit": (30 - math.sqrt(204)) / 12,
    "check_cylinder_hit": 2.0,
    "check_torus_normal": [0.36, 0.48, 0.8],
    "check_torus_bound": [True, False, False, True, True],
}


@pytest.mark.parametrize("name", sorted(RIGHT))
def test_right_answers_worked_by_hand(name):
    r = getattr(ch19, name)(RIGHT[name])
    assert r.correct, r


def test_rounded_and_integer_answers_are_accepted():
    assert ch19.check_sphere_hit(1.3098).correct
    assert ch19.check_polygon_inside([1, 0, 1, 1, 0]).correct
    assert ch19.check_torus_bound(np.array([True, False, False, True, True])).correct


SLIP_MESSAGES = {
    "check_plane_parameter": ["the sign is wrong", "distance from the origin", "N·Q / N·d", "too large"],
    "check_polygon_inside": ["convex hull", "the convex test", "every answer is flipped"],
    "check_sphere_hit": ["far root", "a distance along the ray", "taking a = 1", "expand"],
    "check_cylinder_hit": ["infinite cylinder", "leaves through the wall", "bottom cap", "too large"],
    "check_torus_normal": ["inward normal", "its length is 2", "a sphere's normal", "differentiate"],
    "check_torus_bound": ["whether each ray hits the torus", "bounding sphere alone", "every answer is flipped"],
}


@pytest.mark.parametrize("name", sorted(SLIP_MESSAGES))
def test_each_slip_gets_its_own_message(name):
    slips = ch19.SLIPS[name]
    assert len(slips) == len(SLIP_MESSAGES[name])
    for slip, phrase in zip(slips, SLIP_MESSAGES[name]):
        r = getattr(ch19, name)(slip)
        assert r.answered and not r.correct and phrase in r.message, (slip, r)


def test_garbage_and_unanswered():
    assert not ch19.check_plane_parameter(None).answered
    assert not ch19.check_polygon_inside(...).answered
    for name in RIGHT:
        r = getattr(ch19, name)("abc")
        assert r.answered and not r.correct
    assert "5 True/False" in ch19.check_polygon_inside([True, False]).message


def test_statements_cite_their_sections():
    for name, text in ch19.PROBLEMS.items():
        assert "§19." in text, name


# -- the programming project ---------------------------------------------------------------------------

def good(Q, origins, directions):
    Q = np.asarray(Q, float)
    H = np.c_[origins, np.ones(len(origins))]
    D = np.c_[directions, np.zeros(len(directions))]
    a = np.einsum("ij,jk,ik->i", D, Q, D)
    b = 2 * np.einsum("ij,jk,ik->i", H, Q, D)
    c = np.einsum("ij,jk,ik->i", H, Q, H)
    out = np.full(len(a), np.inf)
    for k in range(len(a)):
        if a[k] == 0:
            roots = [-c[k] / b[k]] if b[k] != 0 else []
        else:
            disc = b[k] ** 2 - 4 * a[k] * c[k]
            if disc < 0:
                roots = []
            else:
                s = math.sqrt(disc)
                q = -0.5 * (b[k] + math.copysign(s, b[k]))
                roots = [q / a[k], c[k] / q] if q != 0 else [0.0, 0.0]
        front = [t for t in roots if t > 1e-9]
        out[k] = min(front) if front else np.inf
    return out


def no_linear_case(Q, origins, directions):        # divides by a = 0 for rays parallel to an axis
    Q = np.asarray(Q, float)
    H = np.c_[origins, np.ones(len(origins))]
    D = np.c_[directions, np.zeros(len(directions))]
    a = np.einsum("ij,jk,ik->i", D, Q, D)
    b = 2 * np.einsum("ij,jk,ik->i", H, Q, D)
    c = np.einsum("ij,jk,ik->i", H, Q, H)
    with np.errstate(all="ignore"):
        disc = np.sqrt(b * b - 4 * a * c)
        t1, t2 = (-b - disc) / (2 * a), (-b + disc) / (2 * a)
    lo, hi = np.minimum(t1, t2), np.maximum(t1, t2)
    t = np.where(lo > 1e-9, lo, np.where(hi > 1e-9, hi, np.inf))
    return np.where(np.isnan(disc), np.inf, t)


def keeps_t_zero(Q, origins, directions):           # counts t = 0 as a hit
    t = good(Q, origins, directions)
    Q = np.asarray(Q, float)
    H = np.c_[origins, np.ones(len(origins))]
    on = np.abs(np.einsum("ij,jk,ik->i", H, Q, H)) < 1e-9
    return np.where(on, 0.0, t)


def crashing(Q, origins, directions):
    return Q[4, 4] * origins


def test_project_accepts_a_correct_intersector_and_names_the_case_kinds():
    r = ch19.check_quadric_project(good)
    assert r.correct, r
    assert "9 cases" in r.message and "tangent rays" in r.message and "a = 0" in r.message


def test_project_names_the_linear_case():
    r = ch19.check_quadric_project(no_linear_case)
    assert not r.correct and r.answered
    assert "case 5 of 9 (paraboloid" in r.message and "ray 0" in r.message and "a = 0 the equation is linear" in r.message


def test_project_names_a_hit_at_t_zero():
    r = ch19.check_quadric_project(keeps_t_zero)
    assert "case 7 of 9" in r.message and "the root t = 0 is not a hit" in r.message


def test_project_reports_a_crash_with_the_learners_line():
    r = ch19.check_quadric_project(crashing)
    assert not r.correct and r.answered
    assert "IndexError" in r.message and "return Q[4, 4] * origins" in r.message


def test_project_unanswered_starter():
    def intersect_quadric(Q, origins, directions):
        """Starter."""
        ...

    assert not ch19.check_quadric_project(intersect_quadric).answered


def test_project_cases_are_fixed_by_the_seed_and_cover_the_degenerate_kinds():
    a, b = ch19.quadric_project_cases(), ch19.quadric_project_cases()
    assert all(np.array_equal(x.args[1], y.args[1]) for x, y in zip(a, b))
    kinds = {c.kind for c in a}
    assert {"tangent rays (a double root)", "parallel to the cylinder's axis (a = 0, b = 0)",
            "parallel to the paraboloid's axis (a = 0: one root)", "rays starting inside (one root behind)",
            "starting on the surface (t = 0 does not count)", "through the cone's apex"} <= kinds
    for c in a:
        assert np.allclose(c.args[0], c.args[0].T)

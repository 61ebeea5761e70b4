"""Chapter 14 checkers: hand-worked right answers pass, each recognised slip gets its reason, other
wrong answers say how far off or how many are wrong, and garbage gets a message."""

import numpy as np

from goldman_lib.exercises import ch14


def _assert_wrong(result, *fragments):
    assert result.answered and not result.correct, result
    for f in fragments:
        assert f in result.message, (f, result.message)


def test_problems_and_slips_listed():
    names = {"check_center_of_mass", "check_point_or_vector", "check_same_projective_point",
             "check_point_at_infinity", "check_perspective_by_lever", "check_pseudodepth", "check_depth_order"}
    assert set(ch14.PROBLEMS) == names == set(ch14.SLIPS)
    assert all("§14." in text for text in ch14.PROBLEMS.values())


def test_center_of_mass():
    # 3 (2, 1) - 1 (5, -2) + 2 (0, 4) = (6 - 5 + 0, 3 + 2 + 8) = (1, 13); M = 3 - 1 + 2 = 4
    assert ch14.check_center_of_mass([0.25, 3.25, 4]).correct
    assert ch14.check_center_of_mass([0.25001, 3.25, 4]).correct                 # hand-rounded decimals
    # sign dropped: 3 (2, 1) + (5, -2) + 2 (0, 4) = (11, 9), M = 6
    _assert_wrong(ch14.check_center_of_mass([11 / 6, 1.5, 6]), "drops the sign")
    _assert_wrong(ch14.check_center_of_mass([7 / 3, 1, 4]), "without their masses")   # (2 + 5 + 0, 1 - 2 + 4) / 3
    _assert_wrong(ch14.check_center_of_mass([1 / 3, 13 / 3, 4]), "number of points")
    _assert_wrong(ch14.check_center_of_mass([1 / 6, 13 / 6, 4]), "sizes of the masses")
    _assert_wrong(ch14.check_center_of_mass([1, 13, 4]), "dividing by the mass")
    _assert_wrong(ch14.check_center_of_mass([7 / 3, 1, 3]), "without their masses")   # the same slip, mass 3
    _assert_wrong(ch14.check_center_of_mass([0.25, 3.25, 6]), "WITH their signs")
    _assert_wrong(ch14.check_center_of_mass([0.25, 3.25, 5]), "too large")
    _assert_wrong(ch14.check_center_of_mass([0.25, 4.25, 4]), "mass is right", "centre of mass is off")
    _assert_wrong(ch14.check_center_of_mass([0.25, 3.25]), "three numbers")


def test_point_or_vector():
    # masses: A - 2B = 2 - 2 = 0, A - B = 1, 2B - C = -1, 3B - C + v = 0, A - B - v = 1, C - A - B + v = 0
    right = ["vector", "point", "point", "vector", "point", "vector"]
    assert ch14.check_point_or_vector(right).correct
    assert ch14.check_point_or_vector(["Vector", "point ", "point", "vector", "point", "vector"]).correct
    # coefficient sums: -1, 0, 1, 3, -1, 0
    _assert_wrong(ch14.check_point_or_vector(["point", "vector", "point", "point", "point", "vector"]),
                  "summed the coefficients")
    # v counted with mass 1: 0, 1, -1, 1, 0, 1
    _assert_wrong(ch14.check_point_or_vector(["vector", "point", "point", "point", "vector", "point"]), "mass of 1")
    _assert_wrong(ch14.check_point_or_vector(["vector", "point", "vector", "vector", "point", "vector"]),
                  "negative total mass")
    _assert_wrong(ch14.check_point_or_vector(["point", "point", "point", "vector", "point", "vector"]),
                  "answers not right: 1 of 6", "sum the coefficients")
    _assert_wrong(ch14.check_point_or_vector(["point", "vector"]), "list of 6 words")
    _assert_wrong(ch14.check_point_or_vector("vector"), "list of 6 words")


def test_same_projective_point():
    # (1) factor -1/2: same; (2) (1,2,3) vs (2,4,6) affine: different; (3) both directions (2, 1, 0): same;
    # (4) factor 1/3: same; (5) a point at infinity vs an affine point: different
    assert ch14.check_same_projective_point([True, False, True, True, False]).correct
    _assert_wrong(ch14.check_same_projective_point([False, False, False, True, False]), "positive scale")
    _assert_wrong(ch14.check_same_projective_point([True, True, True, True, True]), "ignored w")
    _assert_wrong(ch14.check_same_projective_point([False] * 5), "space of mass-points")
    # the key confusion (same mass-point vs same projective point at w = 0) is named, not counted
    _assert_wrong(ch14.check_same_projective_point([True, False, False, True, False]), "point at infinity")
    _assert_wrong(ch14.check_same_projective_point([True, True, True, True, False]), "answers not right: 1 of 5")
    _assert_wrong(ch14.check_same_projective_point([1, 0, 1, 1, 0]), "booleans")


def test_point_at_infinity():
    # 3x + 2y = 0 at w = 0: (2, -3, 0) and its multiples
    for ok in ([2, -3, 0], [-2, 3, 0], [0.5, -0.75, 0]):
        assert ch14.check_point_at_infinity(ok).correct
    _assert_wrong(ch14.check_point_at_infinity([3, 2, 0]), "NORMAL")
    _assert_wrong(ch14.check_point_at_infinity([2, -3, 1]), "right direction but w ≠ 0")
    _assert_wrong(ch14.check_point_at_infinity([3, 2, -11]), "coefficients")
    _assert_wrong(ch14.check_point_at_infinity([1, 4, 1]), "point of the line, but an affine one")  # 3 + 8 = 11
    _assert_wrong(ch14.check_point_at_infinity([1, 1, 1]), "not even on the line")
    _assert_wrong(ch14.check_point_at_infinity([0, 0, 0]), "never all 0")
    _assert_wrong(ch14.check_point_at_infinity([1, 1, 0]), "does not satisfy")


def test_perspective_by_lever():
    # c = (Q - E).N = 2 - (-2) = 4, s = (P - E).N = 10 - (-2) = 12; mass 4 at P, 8 at E:
    # (4 (6, 7, 10) + 8 (0, 1, -2)) / 12 = (24, 36, 24) / 12 = (2, 3, 2)
    assert ch14.check_perspective_by_lever([2, 3, 2]).correct
    _assert_wrong(ch14.check_perspective_by_lever([4, 5, 6]), "swaps the masses")     # (8 P + 4 E) / 12
    _assert_wrong(ch14.check_perspective_by_lever([24, 36, 24]), "divide by its mass")
    _assert_wrong(ch14.check_perspective_by_lever([6, 9, 6]), "divides by c")
    _assert_wrong(ch14.check_perspective_by_lever([3, 4.5, 3]), "divides by s - c")
    _assert_wrong(ch14.check_perspective_by_lever([3, 4, 4]), "midpoint")
    _assert_wrong(ch14.check_perspective_by_lever([-6, -5, -14]), "sign is wrong")    # (4 P - 8 E) / (-4)
    _assert_wrong(ch14.check_perspective_by_lever([1.2, 2.2, 0.4]), "from the origin")  # s = 10, c = 2
    _assert_wrong(ch14.check_perspective_by_lever([24, 36, 24, 12]), "mass-point", "right one")
    _assert_wrong(ch14.check_perspective_by_lever([2, 4, 2]), "your point is off", "not on the line EP")
    _assert_wrong(ch14.check_perspective_by_lever([2, 3, 3]), "not on the plane")


def test_pseudodepth():
    # c = (Q - E).N = (-4)(-1) = 4; s_A = 8, s_B = 16, s_C = 5: 1 - 4/8, 1 - 4/16, 1 - 4/5
    assert ch14.check_pseudodepth([0.5, 0.75, 0.2]).correct
    _assert_wrong(ch14.check_pseudodepth([0.5, 0.25, 0.8]), "c/s", "SHRINKS")
    _assert_wrong(ch14.check_pseudodepth([4 / 7, 0.8, 0.25]), "from the origin")      # s = 7, 15, 4; c = 3
    _assert_wrong(ch14.check_pseudodepth([2, 4, 1.25]), "s/c")
    _assert_wrong(ch14.check_pseudodepth([8, 16, 5]), "depths s themselves")
    _assert_wrong(ch14.check_pseudodepth([-1, -3, -0.25]), "1 - s/c")
    _assert_wrong(ch14.check_pseudodepth([0.5, 0.7, 0.2]), "pseudodepth of B is too small")
    _assert_wrong(ch14.check_pseudodepth([0.5, 0.75]), "three numbers")


def test_depth_order():
    # s = x + y (N = (1, 1, 0), E = 0): A 4, B 3, C 8, D 6 -> B, A, D, C
    assert ch14.check_depth_order("BADC").correct
    assert ch14.check_depth_order("b, a, d, c").correct and ch14.check_depth_order(["B", "A", "D", "C"]).correct
    _assert_wrong(ch14.check_depth_order("CDAB"), "FARTHEST")
    _assert_wrong(ch14.check_depth_order("BDAC"), "distances |P - E|")    # |P|^2: 35, 6, 40, 24
    _assert_wrong(ch14.check_depth_order("DBCA"), "by z")                 # z: 5, -1, 0, -2
    _assert_wrong(ch14.check_depth_order("ABDC"), "wrong place: 2 of 4")
    _assert_wrong(ch14.check_depth_order("ABC"), "each of the points")
    _assert_wrong(ch14.check_depth_order(3), "string")


def test_unanswered():
    for name in ch14.PROBLEMS:
        r = getattr(ch14, name)(None)
        assert not r.answered and repr(r).startswith("Not answered yet: replace None with")


def test_dealt_instances_are_checked_on_their_own_numbers():
    """A few dealt seeds, each answer worked here from the statement's data by the book's formulas."""
    try:
        for seed in (1, 2, 3):
            ch14.deal("check_center_of_mass", seed=seed)
            p = ch14.current("check_center_of_mass")[1]
            m, P = np.array(p["masses"]), np.array(p["points"])
            assert ch14.check_center_of_mass(list(m @ P / m.sum()) + [m.sum()]).correct
            ch14.deal("check_point_at_infinity", seed=seed)
            a, b, _ = ch14.current("check_point_at_infinity")[1]["line"]
            assert ch14.check_point_at_infinity([-2 * b, 2 * a, 0]).correct     # any nonzero multiple
            ch14.deal("check_perspective_by_lever", seed=seed)
            p = ch14.current("check_perspective_by_lever")[1]
            E, Q, N, X = (np.array(p[k]) for k in ("E", "Q", "N", "P"))
            t = (Q - E) @ N / ((X - E) @ N)                                     # the line E + t (P - E)
            assert ch14.check_perspective_by_lever(list(E + t * (X - E))).correct
            ch14.deal("check_pseudodepth", seed=seed)
            p = ch14.current("check_pseudodepth")[1]
            E, Q, N = (np.array(p[k]) for k in ("E", "Q", "N"))
            s = (np.array(p["points"]) - E) @ N
            assert ch14.check_pseudodepth(list(1 - ((Q - E) @ N) / s)).correct
            ch14.deal("check_depth_order", seed=seed)
            p = ch14.current("check_depth_order")[1]
            E, N = np.array(p["E"]), np.array(p["N"])
            s = (np.array(p["points"]) - E) @ N
            assert ch14.check_depth_order("".join("ABCD"[i] for i in np.argsort(s))).correct
            ch14.deal("check_point_or_vector", seed=seed)
            p = ch14.current("check_point_or_vector")[1]
            assert ch14.check_point_or_vector(ch14.DECK.exercises["check_point_or_vector"].answer(p).split()).correct
    finally:
        ch14.DECK.reset()


def test_point_or_vector_reads_one_string_too():
    assert ch14.check_point_or_vector("vector point point vector point vector").correct
    assert ch14.check_point_or_vector("vector, point, point, vector, point, vector").correct
    _assert_wrong(ch14.check_point_or_vector("vector point"), "list of 6 words")

"""Chapter 20 exercise checkers: right answers worked by hand, each slip gets its own message, and
the CSG classifier project catches subtly wrong and crashing classifiers."""

import math

from goldman_lib.exercises import ch20


def test_right_answers_worked_by_hand():
    # A: x in [-2, 2] -> t in [3, 7]; B: x in [0.5, 2.5] -> t in [5.5, 7.5]; A - B = [3, 5.5]
    assert ch20.check_csg_difference([[3, 5.5]]).correct
    assert ch20.check_csg_difference([3.00001, 5.49999]).correct          # one interval, flat
    # (A u B) - C = [1, 8] - [4, 6] = [1, 4], [6, 8]
    assert ch20.check_which_tree("c").correct and ch20.check_which_tree("(C)").correct
    # hexagonal prism: 12 vertices, 6 + 6 + 6 edges, 6 rectangles + 2 hexagons
    assert ch20.check_euler_counts([12, 18, 8]).correct
    # 24 - 36 + 14 - (18 - 14) = -2 = 2(1 - G) -> G = 2
    assert ch20.check_genus(2).correct and ch20.check_genus(2.0).correct
    # face 3 [3, 2, 4] runs 3->2 as the base [0, 3, 2, 1] does, 2->4 as face 2, 4->3 as face 4
    assert ch20.check_flipped_face(3).correct
    # lower 4 octants full; each upper octant: 4 full (z in [0, .5]), 4 partial (z in [.5, 1])
    assert ch20.check_octree_counts([20, 16, 0]).correct


def test_slips_get_their_own_messages():
    said = {
        ("check_csg_difference", str([[3, 7.5]])): "A ∪ B",
        ("check_csg_difference", str([[5.5, 7]])): "A ∩ B",
        ("check_csg_difference", str([[7, 7.5]])): "B − A",
        ("check_csg_difference", str([[3, 7]])): "alone",
        ("check_csg_difference", str([[3, 5.5], [7, 7.5]])): "symmetric difference",
        ("check_csg_difference", str([[-2, 0.5]])): "x-coordinates",
        ("check_which_tree", "'a'"): "subtracts C from B only",
        ("check_which_tree", "'b'"): "fills C's interval back",
        ("check_which_tree", "'d'"): "overlap of A and B",
        ("check_euler_counts", str([12, 36, 8])): "two faces",
        ("check_euler_counts", str([12, 18, 6])): "caps",
        ("check_euler_counts", str([7, 12, 7])): "pyramid",
        ("check_genus", "0"): "without the rings",
        ("check_genus", "3"): "halve",
        ("check_genus", "-2"): "sign is reversed",
        ("check_flipped_face", "2"): "shares an edge",
        ("check_flipped_face", "0"): "shares an edge",
        ("check_flipped_face", "1"): "as they should",
        ("check_octree_counts", str([48, 16, 0])): "only partial cells",
        ("check_octree_counts", str([4, 4, 0])): "stopped at depth 1",
        ("check_octree_counts", str([16, 16, 0])): "depth 1 are leaves too",
        ("check_octree_counts", str([20, 0, 16])): "swapped",
    }
    import ast
    for (name, text), words in said.items():
        r = getattr(ch20, name)(ast.literal_eval(text))
        assert not r.correct and r.answered and words in r.message, (name, text, r.message)


def test_unanswered_and_garbage():
    for name in ch20.PROBLEMS:
        check = getattr(ch20, name)
        assert not check(None).answered and not check(...).answered
        r = check("not an answer at all")
        assert r.answered and not r.correct
        r = check([[1, 2, 3]])
        assert not r.correct
    assert "letters" in ch20.check_which_tree(3).message
    assert "face index from 0" in ch20.check_flipped_face(9).message
    assert "whole number" in ch20.check_genus(1.5).message


def test_statements_cite_sections():
    for name, text in ch20.PROBLEMS.items():
        assert "§20." in text, name


def _classify(first, second, operation):
    ends = sorted({t for iv in list(first) + list(second) for t in iv})
    inside = lambda ivs, a, b: any(s <= a and b <= e for s, e in ivs)   # noqa: E731
    out = []
    for a, b in zip(ends, ends[1:]):
        ina, inb = inside(first, a, b), inside(second, a, b)
        keep = {"union": ina or inb, "intersection": ina and inb, "difference": ina and not inb}[operation]
        if keep:
            if out and out[-1][1] == a:
                out[-1][1] = b
            else:
                out.append([a, b])
    return out


def test_project_accepts_a_correct_classifier():
    r = ch20.check_csg_classifier_project(_classify)
    assert r.correct and "22 cases" in r.message


def test_project_names_the_failing_case_of_a_subtly_wrong_classifier():
    def no_merge(first, second, operation):
        # forgets to merge touching pieces
        ends = sorted({t for iv in list(first) + list(second) for t in iv})
        inside = lambda ivs, a, b: any(s <= a and b <= e for s, e in ivs)   # noqa: E731
        return [[a, b] for a, b in zip(ends, ends[1:])
                if {"union": inside(first, a, b) or inside(second, a, b),
                    "intersection": inside(first, a, b) and inside(second, a, b),
                    "difference": inside(first, a, b) and not inside(second, a, b)}[operation]]

    r = ch20.check_csg_classifier_project(no_merge)
    assert not r.correct and "case 1 of 22" in r.message and "merge into one" in r.message

    def keeps_points(first, second, operation):
        # an intersection of touching intervals returns the touching point as [1, 1]
        if operation == "intersection" and first == [[0.0, 1.0]] and second == [[1.0, 2.0]]:
            return [[1.0, 1.0]]
        return _classify(first, second, operation)

    r = ch20.check_csg_classifier_project(keeps_points)
    assert not r.correct and "zero length" in r.message
    assert "intersection of first = [[0.0, 1.0]] and second = [[1.0, 2.0]]" in r.message

    def wrong_difference(first, second, operation):
        if operation == "difference":
            operation = "intersection"
        return _classify(first, second, operation)

    r = ch20.check_csg_classifier_project(wrong_difference)
    assert not r.correct and "difference of first" in r.message


def test_project_reports_a_crash_with_the_learners_line():
    def crash(first, second, operation):
        return first[0][0] / 0.0 if not math.isinf(first[0][0]) else []

    r = ch20.check_csg_classifier_project(crash)
    assert not r.correct and "ZeroDivisionError" in r.message and "first[0][0] / 0.0" in r.message


def test_project_unanswered():
    assert not ch20.check_csg_classifier_project(None).answered

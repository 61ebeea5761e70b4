"""Chapter 22 exercise checkers: right answers worked by hand here, each recognised slip gets its own
message (never the answer), and the BSP project checker accepts a correct traversal and names what
is wrong with a subtly wrong or crashing one."""

import numpy as np
import pytest

from goldman_lib.exercises import ch22

# Worked by hand:
# 1. farthest vertices 5, 6, 4.6, 7: paint 3 (7), 1 (6), 0 (5), 2 (4.6).  (Nearest vertices 3, 1, 4, 2
#    give 2, 0, 3, 1; averages 4, 3, 4.367, 4.5 give 3, 2, 0, 1: three different orders.)
# 2. depth 1: (3, 0.8) written; (1, 0.6) written; (2, 0.75) no; (0, 0.35) written; (4, 0.35) no (not
#    strictly nearer); (2, 0.5) no: polygon 0, three writes.
# 3. the edges crossing y = 3.5 are (9, 2)-(7, 7.5): x = 9 - 2 * 1.5 / 5.5 = 8.454545, and
#    (2, 6)-(1, 0.5): x = 1 + 3 / 5.5 = 1.545455.
# 4. s = x + 2y - 3 at the vertices: -3, 3, 5; the edge (0,0)-(6,0) is cut at x = 3, the edge
#    (0,4)-(0,0) at y = 1.5.
# 5. eye (-1, 0, 2): in front of z = 0 -> back subtree (4), root (0), then the node x = 1 with the eye
#    behind it -> front (2), node (1), back (3).
RIGHT = {
    "check_painter_order": [3, 1, 0, 2],
    "check_z_buffer_pixel": [0, 3],
    "check_scan_line_span": [1 + 3 / 5.5, 9 - 3 / 5.5],
    "check_split_points": [[3, 0, 0], [0, 1.5, 0]],
    "check_bsp_order": [4, 0, 2, 1, 3],
}

SLIP_WORDS = {
    "check_painter_order": ["nearest first", "nearest vertex", "average depth"],
    "check_z_buffer_pixel": ["(<=)", "not every fragment", "last fragment"],
    "check_scan_line_span": ["y = row", "swapped", "whole polygon"],
    "check_split_points": ["midpoints"],
    "check_bsp_order": ["front to back", "always takes the back subtree"],
}


@pytest.mark.parametrize("name", sorted(RIGHT))
def test_right_answers_worked_by_hand(name):
    r = getattr(ch22, name)(RIGHT[name])
    assert r.correct, r


@pytest.mark.parametrize("name", sorted(SLIP_WORDS))
def test_each_slip_gets_its_own_message(name):
    for slip, words in zip(ch22.SLIPS[name], SLIP_WORDS[name]):
        r = getattr(ch22, name)(slip)
        assert not r.correct and words in r.message, (slip, r)


def test_unanswered_and_garbage():
    for name in RIGHT:
        f = getattr(ch22, name)
        assert not f(None).answered
        r = f("abc")
        assert not r.correct and r.answered


# -- the programming project ------------------------------------------------------------------------

def good(tree, eye):
    if tree is None:
        return []
    eye = np.asarray(eye, float)
    if (eye - tree.point) @ tree.normal >= 0:
        return good(tree.back, eye) + list(tree.pieces) + good(tree.front, eye)
    return good(tree.front, eye) + list(tree.pieces) + good(tree.back, eye)


def wrong_sign(tree, eye):
    """Subtly wrong: the eye's side tested the wrong way at every node but the root."""
    def walk(node, depth):
        if node is None:
            return []
        s = (np.asarray(eye, float) - node.point) @ node.normal
        front = s >= 0 if depth == 0 else s < 0
        if front:
            return walk(node.back, depth + 1) + list(node.pieces) + walk(node.front, depth + 1)
        return walk(node.front, depth + 1) + list(node.pieces) + walk(node.back, depth + 1)
    return walk(tree, 0)


def crashing(tree, eye):
    side = (np.asarray(eye) - tree.point) @ tree.normal
    return good(tree, eye) if side is not None else []


def test_project_accepts_a_correct_traversal():
    r = ch22.check_bsp_project(good)
    assert r.correct and "11 cases" in r.message and "cyclic overlap" in r.message


def test_project_names_the_first_misplaced_piece():
    r = ch22.check_bsp_project(wrong_sign)
    assert not r.correct and "case 1 of 11" in r.message and "breaks the rule at some node" in r.message


def test_project_reports_front_to_back():
    r = ch22.check_bsp_project(lambda tree, eye: good(tree, eye)[::-1])
    assert not r.correct and "front to back" in r.message


def test_project_reports_a_crash_on_the_empty_tree():
    r = ch22.check_bsp_project(crashing)
    assert not r.correct and "case 11 of 11" in r.message and "AttributeError" in r.message
    assert "side = (np.asarray(eye) - tree.point) @ tree.normal" in r.message


def test_project_unanswered():
    def starter(tree, eye):
        ...
    assert not ch22.check_bsp_project(starter).answered


def test_painter_data_separate_farthest_nearest_and_average():
    """Exercise 1's depths must give different orders for the three sort keys (and their reverses),
    or a learner who sorts by one key is told they used another."""
    depths = ch22.PAINTER_DEPTHS
    orders = {key.__name__: sorted(range(len(depths)), key=lambda k: -key(depths[k])) for key in (max, min, np.mean)}
    all_orders = [tuple(o) for o in orders.values()] + [tuple(o[::-1]) for o in orders.values()]
    assert len(set(all_orders)) == 6, orders
    assert orders["max"] == RIGHT["check_painter_order"]

"""Corpus of the chapter-22 project (back-to-front traversal of a BSP tree): correct traversals
written from the statement alone (recursion, an explicit stack, a generator; `>=` or `>` for the
eye's side, which differ only when the eye lies in a node's plane; a node's pieces in either order;
tuples or lists) must be accepted; realistic wrong ones must be rejected with the slip named."""

import numpy as np
import pytest

from goldman_lib.exercises import ch22


def _s(node, eye):
    return float((np.asarray(eye, float) - np.asarray(node.point, float)) @ np.asarray(node.normal, float))


# -- accepted ------------------------------------------------------------------------------------------

def recursive(tree, eye):
    if tree is None:
        return []
    if _s(tree, eye) >= 0:
        return recursive(tree.back, eye) + list(tree.pieces) + recursive(tree.front, eye)
    return recursive(tree.front, eye) + list(tree.pieces) + recursive(tree.back, eye)


def stack_strict(tree, eye):
    """An explicit stack, the statement's rule written with `>` (the other side first at a tie), and
    the pieces as [index, vertices-as-lists] lists."""
    out, stack = [], [(tree, False)]
    while stack:
        node, emit = stack.pop()
        if node is None:
            continue
        if emit:
            out.extend([int(k), np.asarray(P).tolist()] for k, P in node.pieces)
            continue
        far, near = (node.back, node.front) if _s(node, eye) > 0 else (node.front, node.back)
        stack += [(near, False), (node, True), (far, False)]
    return out


def generator_reversed_pieces(tree, eye):
    """A generator; each node's pieces in reverse order (they lie in one plane)."""
    def walk(node):
        if node is None:
            return
        s = _s(node, eye)
        first, last = (node.back, node.front) if s >= 0 else (node.front, node.back)
        yield from walk(first)
        yield from reversed(node.pieces)
        yield from walk(last)
    return list(walk(tree))


ACCEPTED = [recursive, stack_strict, generator_reversed_pieces]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch22.check_bsp_project(solution)
    assert r.correct, r.message


def test_the_accepted_orders_really_differ():
    cases = ch22.bsp_project_cases()
    tie = next(c for c in cases if c.kind == "eye in a polygon's plane")
    assert [k for k, _ in recursive(*tie.args)] != [k for k, _ in stack_strict(*tie.args)]
    coplanar = next(c for c in cases if c.kind == "coplanar polygons")
    assert [k for k, _ in recursive(*coplanar.args)] != [k for k, _ in generator_reversed_pieces(*coplanar.args)]


# -- rejected ------------------------------------------------------------------------------------------

def front_to_back(tree, eye):
    return recursive(tree, eye)[::-1]


def always_back_first(tree, eye):                # the eye never consulted
    if tree is None:
        return []
    return always_back_first(tree.back, eye) + list(tree.pieces) + always_back_first(tree.front, eye)


def node_first(tree, eye):                       # pre-order: the node's pieces before both subtrees
    if tree is None:
        return []
    far, near = (tree.back, tree.front) if _s(tree, eye) >= 0 else (tree.front, tree.back)
    return list(tree.pieces) + node_first(far, eye) + node_first(near, eye)


def sign_flipped_below_root(tree, eye, depth=0):  # the side test reversed below the root
    if tree is None:
        return []
    s = _s(tree, eye)
    in_front = s >= 0 if depth == 0 else s < 0
    far, near = (tree.back, tree.front) if in_front else (tree.front, tree.back)
    return (sign_flipped_below_root(far, eye, depth + 1) + list(tree.pieces)
            + sign_flipped_below_root(near, eye, depth + 1))


def first_piece_only(tree, eye):                 # a node's other coplanar pieces forgotten
    if tree is None:
        return []
    far, near = (tree.back, tree.front) if _s(tree, eye) >= 0 else (tree.front, tree.back)
    return first_piece_only(far, eye) + list(tree.pieces[:1]) + first_piece_only(near, eye)


def no_empty_tree(tree, eye):                    # the statement's empty tree (None) not handled
    far, near = (tree.back, tree.front) if _s(tree, eye) >= 0 else (tree.front, tree.back)
    return (no_empty_tree(far, eye) if far else []) + list(tree.pieces) + (no_empty_tree(near, eye) if near else [])


REJECTED = [
    (front_to_back, "front to back"),
    (always_back_first, "always lists the back subtree first"),
    (node_first, "before both subtrees"),
    (sign_flipped_below_root, "breaks the rule at some node"),
    (first_piece_only, "pieces; the tree holds"),
    (no_empty_tree, "AttributeError"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch22.check_bsp_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message


def test_the_tie_case_with_a_strict_test_is_not_called_front_to_back():
    """Case 6 (the eye in the root's plane): the rule written with `>` must pass, not be told
    'front to back' (the reverse test used to run before the branch that accepts a tie)."""
    cases = ch22.bsp_project_cases()
    k = next(i for i, c in enumerate(cases) if c.kind == "eye in a polygon's plane")
    tree, eye = cases[k].args
    assert ch22._compare_bsp(stack_strict(tree, eye), recursive(tree, eye), cases[k]) is None

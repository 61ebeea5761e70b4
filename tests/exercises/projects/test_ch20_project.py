"""Corpus of the chapter-20 project (the CSG interval classifier): correct solutions written from the
statement alone (cut the line at every end and test the pieces; a sweep over sorted events with
counters; interval algebra by merge, pairwise overlap and subtraction, returning tuples) must be
accepted; realistic wrong ones must be rejected with the slip named."""

import math

import pytest

from goldman_lib.exercises import ch20

KEEP = {"union": lambda a, b: a or b, "intersection": lambda a, b: a and b, "difference": lambda a, b: a and not b}


def _inside(intervals, t):
    return any(s <= t <= e for s, e in intervals)


def _mid(s, e):
    if math.isinf(s) and math.isinf(e):
        return 0.0
    if math.isinf(s):
        return e - 1.0
    if math.isinf(e):
        return s + 1.0
    return (s + e) / 2


# -- accepted ------------------------------------------------------------------------------------------

def cut_points(first, second, operation):
    ends = sorted({t for iv in list(first) + list(second) for t in iv})
    out = []
    for s, e in zip(ends, ends[1:]):
        m = _mid(s, e)
        if KEEP[operation](_inside(first, m), _inside(second, m)):
            if out and out[-1][1] == s:
                out[-1][1] = e
            else:
                out.append([s, e])
    return out


def sweep(first, second, operation):
    """Events sorted by position; at one position all ends and starts are applied before a piece is
    opened or closed, so touching pieces merge and zero-length ones never open."""
    events = sorted({t for iv in list(first) + list(second) for t in iv})
    out, open_at = [], None
    for k, t in enumerate(events):
        right = _mid(t, events[k + 1]) if k + 1 < len(events) else (t + 1.0 if not math.isinf(t) else None)
        now = right is not None and KEEP[operation](_inside(first, right), _inside(second, right))
        if now and open_at is None:
            open_at = t
        elif not now and open_at is not None:
            out.append([open_at, t])
            open_at = None
    return out


def algebra(first, second, operation):
    """Union by sorting and merging, intersection by pairwise overlaps, difference by subtracting each
    interval of second in turn; tuples returned."""
    def merge(ivs):
        res = []
        for s, e in sorted(ivs):
            if res and s <= res[-1][1]:
                res[-1][1] = max(res[-1][1], e)
            else:
                res.append([s, e])
        return res

    if operation == "union":
        res = merge(list(first) + list(second))
    elif operation == "intersection":
        res = merge([[max(a, c), min(b, d)] for a, b in first for c, d in second if max(a, c) < min(b, d)])
    else:
        res = [list(iv) for iv in first]
        for c, d in second:
            nxt = []
            for a, b in res:
                if a < c:
                    nxt.append([a, min(b, c)])
                if b > d:
                    nxt.append([max(a, d), b])
            res = [iv for iv in nxt if iv[0] < iv[1]]
        res = merge(res)
    return [tuple(iv) for iv in res]


ACCEPTED = [cut_points, sweep, algebra]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch20.check_csg_classifier_project(solution)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def touching_not_merged(first, second, operation):   # merges overlaps only, not touching ends
    out = []
    ends = sorted({t for iv in list(first) + list(second) for t in iv})
    for s, e in zip(ends, ends[1:]):
        if KEEP[operation](_inside(first, _mid(s, e)), _inside(second, _mid(s, e))):
            out.append([s, e])
    return out


def zero_length_kept(first, second, operation):      # closed intervals: a touching point kept
    res = algebra(first, second, operation)
    if operation == "intersection":
        res = [[max(a, c), min(b, d)] for a, b in first for c, d in second if max(a, c) <= min(b, d)]
    return [list(iv) for iv in res]


def difference_swapped(first, second, operation):    # second minus first
    return cut_points(second, first, operation) if operation == "difference" else cut_points(first, second,
                                                                                             operation)


def union_by_concatenation(first, second, operation):
    return list(first) + list(second) if operation == "union" else cut_points(first, second, operation)


def unsorted_result(first, second, operation):       # the right pieces, last first
    return cut_points(first, second, operation)[::-1]


REJECTED = [
    (touching_not_merged, "intervals that touch or overlap merge into one"),
    (zero_length_kept, "an interval of zero length"),
    (difference_swapped, "that is second minus first"),
    (union_by_concatenation, "intervals that touch or overlap merge into one"),
    (unsorted_result, "not sorted by their start"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch20.check_csg_classifier_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message

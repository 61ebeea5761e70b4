"""Corpus of the chapter-8 project (Ron's algorithm): correct solutions written from the statement
alone (a walk with vectors, a walk with complex numbers, the state kept as a 3x3 matrix updated by
left factors; arrays or nested lists) must be accepted; realistic wrong ones must be rejected with
the slip named."""

import cmath
import math

import numpy as np
import pytest

from goldman_lib.exercises import ch08


# -- accepted ------------------------------------------------------------------------------------------

def vectors(body):
    P, w = np.zeros(2), np.array([1.0, 0.0])
    maps = []
    for cmd, v in body:
        if cmd in ("FORWARD", "MOVE"):
            P = P + v * w
        elif cmd == "TURN":
            a = math.radians(v)
            w = np.array([math.cos(a) * w[0] - math.sin(a) * w[1], math.sin(a) * w[0] + math.cos(a) * w[1]])
        elif cmd == "RESIZE":
            w = v * w
        else:
            maps.append(np.array([[w[0], w[1], 0], [-w[1], w[0], 0], [P[0], P[1], 1]]))
            P = P + w
    return np.array(maps)


def complex_numbers(body):
    """P and w as complex numbers; TURN multiplies w by e^{ia}; nested lists returned."""
    P, w = 0j, 1 + 0j
    maps = []
    for cmd, v in body:
        if cmd in ("FORWARD", "MOVE"):
            P += v * w
        elif cmd == "TURN":
            w *= cmath.exp(1j * math.radians(v))
        elif cmd == "RESIZE":
            w *= v
        elif cmd == "RECURSE":
            maps.append([[w.real, w.imag, 0.0], [-w.imag, w.real, 0.0], [P.real, P.imag, 1.0]])
            P += w
    return maps


def state_matrix(body):
    """The state as the 3x3 map T of the standard state; each command multiplies T on the left."""
    T = np.eye(3)
    out = []

    def shift(d):
        M = np.eye(3)
        M[2, 0] = d
        return M

    for cmd, v in body:
        if cmd in ("FORWARD", "MOVE"):
            T = shift(v) @ T
        elif cmd == "TURN":
            a = math.radians(v)
            T = np.array([[math.cos(a), math.sin(a), 0], [-math.sin(a), math.cos(a), 0], [0, 0, 1]]) @ T
        elif cmd == "RESIZE":
            T = np.diag([v, v, 1.0]) @ T
        else:
            out.append(T.copy())
            T = shift(1.0) @ T
    return np.array(out)


ACCEPTED = [vectors, complex_numbers, state_matrix]


@pytest.mark.parametrize("solution", ACCEPTED, ids=lambda f: f.__name__)
def test_correct_solutions_are_accepted(solution):
    r = ch08.check_rons_algorithm_project(solution)
    assert r.correct, r.message


# -- rejected ------------------------------------------------------------------------------------------

def transposed(body):                            # the column-vector convention
    return vectors(body).transpose(0, 2, 1)


def clockwise(body):                             # TURN a taken clockwise
    return vectors([(c, -v if c == "TURN" else v) for c, v in body])


def calls_do_not_move(body):                     # RECURSE records but does not move the turtle
    P, w = np.zeros(2), np.array([1.0, 0.0])
    maps = []
    for cmd, v in body:
        if cmd in ("FORWARD", "MOVE"):
            P = P + v * w
        elif cmd == "TURN":
            a = math.radians(v)
            w = np.array([math.cos(a) * w[0] - math.sin(a) * w[1], math.sin(a) * w[0] + math.cos(a) * w[1]])
        elif cmd == "RESIZE":
            w = v * w
        else:
            maps.append(np.array([[w[0], w[1], 0], [-w[1], w[0], 0], [P[0], P[1], 1]]))
    return np.array(maps)


def resize_ignored(body):                        # RESIZE skipped
    return vectors([(c, v) for c, v in body if c != "RESIZE"])


def reflected(body):                             # second row (w_y, -w_x)
    M = vectors(body)
    M[:, 1, :2] = -M[:, 1, :2]
    return M


REJECTED = [
    (transposed, "transposed (column-vector convention)"),
    (clockwise, "your turns go clockwise"),
    (calls_do_not_move, "your calls do not move the turtle"),
    (resize_ignored, "you ignored RESIZE"),
    (reflected, "reflects: its second row"),
]


@pytest.mark.parametrize("solution, slip", REJECTED, ids=lambda x: getattr(x, "__name__", "slip"))
def test_wrong_solutions_are_rejected_with_the_slip_named(solution, slip):
    r = ch08.check_rons_algorithm_project(solution)
    assert not r.correct and r.answered
    assert slip in r.message, r.message

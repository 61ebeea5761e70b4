"""Exercise checkers for chapter 14, projective space and the universal space of mass-points
(Goldman §14.2-14.4).

Each checker recognises the usual slips (adding the points without their masses, dividing by the
wrong mass, dropping the sign of a negative mass, forgetting that masses which cancel give a
vector, a vector counted with mass 1, projective equality confused with equality of coordinates,
depth and pseudodepth order reversed) and names the misconception; it says how far off an answer is,
never what the answer is.  ``None`` or ``...`` means "not answered yet".

Every exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0 is
the module constants below, which the stored notebook shows; ``deal("check_...")`` (or the button
beside the exercise) deals another, and the checker, ``PROBLEMS`` and ``steps("check_...")`` follow
the current instance.  The chapter's "show that" exercises (in :mod:`goldman_lib.exercises.proofs`)
ask for an identity, not a number, so they do not deal.  ``SLIPS`` holds the wrong answers of the
kinds each checker recognises, for the stored instance.

>>> print(PROBLEMS["check_point_at_infinity"])
In homogeneous coordinates (x, y, w) the line 3x + 2y = 11 of the plane is 3x + 2y - 11w = 0. Give its point at infinity as [x, y, w] (any nonzero multiple will do) (Goldman §14.2).
"""

from __future__ import annotations

import re
from fractions import Fraction

import numpy as np

from goldman_lib import mass_points as mp
from goldman_lib.exercises import far_off, guard_checkers, quote
from goldman_lib.exercises import Result, correct, fmt, off_by, read_points, unanswered, is_unanswered, wrong
from goldman_lib.exercises.deal import Deck, integers as _ints, memo

__all__ = ["PROBLEMS", "SLIPS", "LEVER_POINTS", "LEVER_MASSES", "COMBO_MASSES", "COMBINATIONS", "TUPLE_PAIRS",
           "LINE", "PERSPECTIVE_EYE", "PERSPECTIVE_PLANE", "PERSPECTIVE_POINT", "DEPTH_EYE", "DEPTH_PLANE",
           "DEPTH_POINTS", "ORDER_EYE", "ORDER_PLANE", "ORDER_POINTS", "DECK", "deal", "steps", "current",
           "deal_button", "check_center_of_mass", "check_point_or_vector", "check_same_projective_point",
           "check_point_at_infinity", "check_perspective_by_lever", "check_pseudodepth", "check_depth_order"]

#: Exercise 1: three points with masses (one negative).
LEVER_POINTS = ((2.0, 1.0), (5.0, -2.0), (0.0, 4.0))
LEVER_MASSES = (3.0, -1.0, 2.0)
#: Exercise 2: the masses of the mass-points A, B, C; v is a vector (mass 0).
COMBO_MASSES = {"A": 2, "B": 1, "C": 3, "v": 0}
#: Exercise 2: combinations as {name: coefficient}.
COMBINATIONS = (
    ("A - 2B", {"A": 1, "B": -2}),
    ("A - B", {"A": 1, "B": -1}),
    ("2B - C", {"B": 2, "C": -1}),
    ("3B - C + v", {"B": 3, "C": -1, "v": 1}),
    ("A - B - v", {"A": 1, "B": -1, "v": -1}),
    ("C - A - B + v", {"C": 1, "A": -1, "B": -1, "v": 1}),
)
#: Exercise 3: pairs of homogeneous tuples (x, y, z, w).
TUPLE_PAIRS = (
    ((2, -4, 6, 2), (-1, 2, -3, -1)),
    ((1, 2, 3, 1), (2, 4, 6, 1)),
    ((4, 2, 0, 0), (-2, -1, 0, 0)),
    ((3, 6, 9, 3), (1, 2, 3, 1)),
    ((1, 0, 2, 0), (1, 0, 2, 1)),
)
#: Exercise 4: the line a x + b y = d, as (a, b, d).
LINE = (3.0, 2.0, 11.0)
#: Exercise 5: eye, plane (point, normal) and the point projected.
PERSPECTIVE_EYE = (0.0, 1.0, -2.0)
PERSPECTIVE_PLANE = ((0.0, 0.0, 2.0), (0.0, 0.0, 1.0))
PERSPECTIVE_POINT = (6.0, 7.0, 10.0)
#: Exercise 6: the eye looks down the z-axis at the plane z = -3.
DEPTH_EYE = (0.0, 0.0, 1.0)
DEPTH_PLANE = ((0.0, 0.0, -3.0), (0.0, 0.0, -1.0))
DEPTH_POINTS = {"A": (2.0, 1.0, -7.0), "B": (0.0, 3.0, -15.0), "C": (1.0, 1.0, -4.0)}
#: Exercise 7: a tilted plane; two of the points share a line of sight.
ORDER_EYE = (0.0, 0.0, 0.0)
ORDER_PLANE = ((2.0, 0.0, 0.0), (1.0, 1.0, 0.0))
ORDER_POINTS = {"A": (3.0, 1.0, 5.0), "B": (1.0, 2.0, -1.0), "C": (6.0, 2.0, 0.0), "D": (2.0, 4.0, -2.0)}

DECK = Deck("ch14")


def _tuple(t) -> str:
    return "(" + ", ".join(fmt(v) for v in t) + ")"


def _arr(v):
    return np.asarray(v, dtype=float)


def _ftup(a) -> tuple:
    a = np.asarray(a, dtype=float)
    return tuple(float(x) for x in a) if a.ndim == 1 else tuple(_ftup(r) for r in a)


def _r(x):
    return np.round(np.asarray(x, dtype=float), 6) + 0.0


def _f6(x) -> str:
    return fmt(_r(x), 6)


def _close_all(a, b) -> bool:
    a, b = _arr(a), _arr(b)
    return a.shape == b.shape and bool(np.allclose(a, b, atol=1e-6, rtol=1e-4) and np.allclose(b, a, atol=1e-6,
                                                                                                   rtol=1e-4))


def _equal(a, b) -> bool:
    return list(a) == list(b) if not isinstance(a, str) else a == b


def _linear(terms) -> str:
    """``[(3, "x"), (-2, "y")]`` as ``3x - 2y``."""
    out = []
    for c, var in terms:
        if c == 0:
            continue
        mag = "" if abs(c) == 1 else fmt(abs(c))
        sign = ("-" if c < 0 else "") if not out else (" - " if c < 0 else " + ")
        out.append(f"{sign}{mag}{var}")
    return "".join(out)


def _signed_sum(values) -> str:
    """``(3, -1, 2)`` as ``3 - 1 + 2``."""
    first, *rest = values
    return fmt(first) + "".join(f" - {fmt(-v)}" if v < 0 else f" + {fmt(v)}" for v in rest)


def _and(items) -> str:
    items = [str(i) for i in items]
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


# -- exercise 1: the sum of three mass-points --------------------------------------------------------

_STORED_LEVER = {"points": LEVER_POINTS, "masses": LEVER_MASSES}


def _lever_sum(masses, points) -> np.ndarray:
    total = mp.mass_point(points[0], masses[0])
    for P, m in zip(points[1:], masses[1:]):
        total = mp.add(total, mp.mass_point(P, m))
    return total


@memo
def _lever_answers(p):
    points, masses = p["points"], p["masses"]
    pts = np.array(points)
    total = _lever_sum(masses, points)
    right = np.append(mp.point_of(total), mp.mass_of(total))
    wp, M = total[:2], mp.mass_of(total)
    abs_sum = _lever_sum([abs(m) for m in masses], points)
    negative = [i + 1 for i, m in enumerate(masses) if m < 0]
    which = _and(f"P{i}" for i in negative)
    slips = {
        f"drops the sign of the negative mass: a mass of {fmt(masses[negative[0] - 1])} pushes instead of pulls, so "
        f"{which} enters the sum as {fmt(masses[negative[0] - 1])} · P{negative[0]} and the total mass counts "
        f"{fmt(masses[negative[0] - 1])}.": np.append(mp.point_of(abs_sum), mp.mass_of(abs_sum)),
        "adds the points without their masses: the centre of mass is (sum of m_i P_i) / (sum of m_i), every point "
        "weighted by its mass.": np.append(pts.mean(axis=0), M),
        "divides by the number of points; divide the weighted sum by the TOTAL MASS.": np.append(wp / len(pts), M),
        "divides by the sum of the sizes of the masses; the total mass keeps their signs.":
            np.append(wp / sum(abs(m) for m in masses), M),
        "gives the first coordinates of the summed mass-point, (M P, M); the point P is found by dividing by the "
        "mass M.": np.append(wp, M),
    }
    return right, slips


def _lever_generate(rng) -> dict:
    points = tuple(_ints(rng, -4, 5, 2) for _ in range(3))
    masses = [float(rng.choice([1, 2, 3, 4])) for _ in range(3)]
    k = int(rng.integers(0, 3))
    masses[k] = -float(rng.choice([1, 2, 3]))
    return {"points": points, "masses": tuple(masses)}


def _lever_ok(p):
    if abs(sum(p["masses"])) < 0.5:
        return "the masses cancel: the sum is a vector, not a point"
    if len(set(p["points"])) < 3:
        return "two points coincide"
    return None


def _lever_statement(p) -> str:
    return ("Add the mass-points of the points " + ", ".join(
        f"P{i + 1} = {_tuple(P)} with mass {fmt(m)}" for i, (P, m) in enumerate(zip(p["points"], p["masses"])))
        + ". The sum is a mass-point (M P, M): give its point P, the centre of mass, and its total mass M as "
          "[x, y, M] (Goldman §14.3).")


def _lever_steps(p) -> str:
    total = _lever_sum(p["masses"], p["points"])
    parts = [f"({_tuple(_r(mp.mass_point(P, m)[:2]))}, {fmt(m)})" for P, m in zip(p["points"], p["masses"])]
    return (f"1. The mass-points (m P, m): {', '.join(parts)}.\n"
            f"2. Their sum, coordinate by coordinate: ({_f6(total[:2])}, {fmt(total[2])}); the total mass "
            f"M = {_signed_sum(p['masses'])} = {fmt(total[2])}, with the signs.\n"
            f"3. The centre of mass is the first part divided by M: {_f6(mp.point_of(total))}.")


@DECK.exercise(stored=_STORED_LEVER, generate=_lever_generate, answer=lambda p: _lever_answers(p)[0],
               slips=lambda p: _lever_answers(p)[1], statement=_lever_statement, steps=_lever_steps,
               same=_close_all, well_posed=_lever_ok)
def check_center_of_mass(answer, p) -> Result:
    """Exercise 1: the sum of the statement's mass-points: the centre of mass and the total mass,
    ``[x, y, M]`` (Goldman §14.3).
    """
    got, problem = read_points(answer, "your answer", ask="the centre of mass and the total mass as [x, y, M]")
    if problem is not None:
        return problem
    if got.shape != (3,):
        return wrong(f"the answer is three numbers [x, y, M], the centre of mass and the total mass; yours has shape "
                     f"{got.shape}.")
    right, slips = _lever_answers(p)
    if np.allclose(got, right, atol=1e-6, rtol=1e-4):
        return correct(f"the sum is the mass-point at {fmt(right[:2])} with total mass {fmt(right[2])}.")
    for why, value in slips.items():
        if np.allclose(got, value, atol=1e-6, rtol=1e-4):
            return wrong(f"your answer {why}")
    if np.allclose(got, np.r_[right[2], right[:2]], atol=1e-6, rtol=1e-4) and not np.allclose(got, right):
        return wrong("your numbers are in the order [M, x, y]: the answer is [x, y, M], the centre of mass first "
                     "and the total mass last.")
    for why, value in slips.items():          # the same slip in the point, with another mass
        if np.allclose(got[:2], value[:2], atol=1e-6, rtol=1e-4):
            return wrong(f"your point {why}")
    if np.isclose(got[2], sum(abs(m) for m in p["masses"]), atol=1e-6):
        return wrong("your total mass drops the sign of the negative mass: the total mass is the sum of the masses "
                     "WITH their signs (a negative mass counts negatively).")
    if not np.isclose(got[2], right[2], atol=1e-6):
        return wrong(f"the total mass M is {off_by(got[2], right[2])}. Hint: M is the sum of the masses, with "
                     f"their signs.")
    return wrong(f"the mass is right; your centre of mass is {far_off(got[:2], right[:2])}"
                 f". Hint: add the mass-points (m P, m) coordinate by coordinate, then divide by the "
                 f"total mass.")


# -- exercise 2: point or vector ---------------------------------------------------------------------

_STORED_COMBO = {"masses": (2, 1, 3), "combos": tuple(name for name, _ in COMBINATIONS)}
_TERM = re.compile(r"([+-]?)\s*(\d*)\s*([ABCv])")


def _coefficients(text) -> dict:
    """``"3B - C + v"`` as ``{"B": 3, "C": -1, "v": 1}``."""
    out = {}
    for sign, digits, name in _TERM.findall(text):
        out[name] = out.get(name, 0) + (-1 if sign == "-" else 1) * (int(digits) if digits else 1)
    return out


def _mass_table(p, v_mass=0) -> dict:
    return {**dict(zip("ABC", p["masses"])), "v": v_mass}


def _totals(p, v_mass=0) -> list:
    m = _mass_table(p, v_mass)
    return [sum(c * m[k] for k, c in _coefficients(text).items()) for text in p["combos"]]


def _words(totals, vector_if=lambda t: t == 0) -> str:
    return " ".join("vector" if vector_if(t) else "point" for t in totals)


@memo
def _kinds(p):
    right = _words(_totals(p))
    coefficient_sum = _words([sum(_coefficients(text).values()) for text in p["combos"]])
    slips = {
        "you summed the coefficients, not the masses: the mass of c1 A + c2 B + ... is c1 mA + c2 mB + ..., "
        "and a combination is a vector exactly when that total mass is 0.": coefficient_sum,
        "you gave the vector v a mass of 1: a vector is a mass-point of mass 0, (v, 0); adding it changes the "
        "position, not the mass.": _words(_totals(p, v_mass=1)),
        "you took a negative total mass for a vector: a mass-point may have a negative mass and is still a point; "
        "only a total mass of exactly 0 gives a vector.": _words(_totals(p), vector_if=lambda t: t <= 0),
    }
    return right, slips


def _combo_generate(rng) -> dict:
    masses = tuple(int(m) for m in rng.integers(1, 5, size=3))
    combos = []
    while len(combos) < 6:
        names = list(rng.permutation(list("ABC"))[: int(rng.integers(2, 4))])
        coeffs = [int(rng.choice([-3, -2, -1, 1, 2, 3])) for _ in names]
        if len(combos) < 3:                       # make the masses cancel: c_last m_last = -(the rest)
            rest = sum(c * masses["ABC".index(n)] for c, n in zip(coeffs[:-1], names[:-1]))
            m_last = masses["ABC".index(names[-1])]
            if rest == 0 or rest % m_last or abs(rest // m_last) > 3:
                continue
            coeffs[-1] = -rest // m_last
        terms = list(zip(coeffs, names))
        positive = [k for k, (c, _) in enumerate(terms) if c > 0]
        if positive:                              # a positive term first, as one writes it
            terms = terms[positive[0]:] + terms[:positive[0]]
        if rng.random() < 0.5:
            terms.append((int(rng.choice([-1, 1])), "v"))
        text = _linear(terms)
        if text not in combos:
            combos.append(text)
    order = rng.permutation(6)
    return {"masses": masses, "combos": tuple(combos[i] for i in order)}


def _combo_ok(p):
    kinds = _kinds(p)[0].split()
    if kinds.count("vector") < 2 or kinds.count("point") < 2:
        return "too few points or too few vectors"
    return None


def _combo_statement(p) -> str:
    return ("A, B, C are mass-points with masses " + ", ".join(f"{k} = {m}" for k, m in zip("ABC", p["masses"]))
            + ", and v is a vector. For each combination " + ", ".join(p["combos"])
            + ", is the result a point (a mass-point) or a vector? Answer a list of six words 'point' or 'vector', "
              "in this order (Goldman §14.3).")


def _combo_steps(p) -> str:
    m = _mass_table(p)
    lines = [f"Add coefficient × mass, with {', '.join(f'{k} = {m[k]}' for k in 'ABC')} and v = 0 (a vector):"]
    for text, total in zip(p["combos"], _totals(p)):
        terms = " + ".join(f"({c})({m[k]})" for k, c in _coefficients(text).items())
        lines.append(f"* {text}: {terms} = {total}, a {'vector' if total == 0 else 'point'}.")
    return "\n".join(lines)


def _read_words(answer, n) -> tuple[list[str] | None, Result | None]:
    if is_unanswered(answer):
        return None, unanswered("a list of six words 'point' or 'vector'")
    if isinstance(answer, str) and answer.strip():
        answer = answer.replace(",", " ").split()
    if isinstance(answer, str) or not isinstance(answer, (list, tuple)):
        return None, wrong(f"the answer is a list of {n} words, each 'point' or 'vector'; you gave {quote(answer)}.")
    words = [w.strip().lower() if isinstance(w, str) else None for w in answer]
    if len(words) != n or any(w not in ("point", "vector") for w in words):
        return None, wrong(f"the answer is a list of {n} words, each 'point' or 'vector', one per combination; you "
                           f"gave {quote(answer)}.")
    return words, None


@DECK.exercise(stored=_STORED_COMBO, generate=_combo_generate, answer=lambda p: _kinds(p)[0],
               slips=lambda p: _kinds(p)[1], statement=_combo_statement, steps=_combo_steps,
               same=lambda a, b: a.split() == b.split(), well_posed=_combo_ok)
def check_point_or_vector(answer, p) -> Result:
    """Exercise 2: which of the statement's combinations are points and which vectors: a vector
    exactly when the total mass is 0 (Goldman §14.3).  answer: six words, as a list (or one string).
    """
    words, problem = _read_words(answer, len(p["combos"]))
    if problem is not None:
        return problem
    right, slips = _kinds(p)
    right = right.split()
    if words == right:
        return correct(f"the total masses are {', '.join(str(m) for m in _totals(p))}: a vector exactly where the "
                       f"masses cancel (a negative mass is still a point).")
    for why, value in slips.items():
        if words == value.split():
            return wrong(why)
    bad = sum(w != r for w, r in zip(words, right))
    checks = ["did you sum the coefficients instead of the masses?", "did you give the vector v a mass?",
              "did you take a negative total mass for a vector?"]
    hints = [check for check, value in zip(checks, slips.values())
             if any(w == v != r for w, v, r in zip(words, value.split(), right))]
    return wrong(f"answers not right: {bad} of {len(right)}. Hint: for each combination add up coefficient × mass "
                 f"(a vector has mass 0); total 0 means a vector." + (" Check: " + " ".join(hints) if hints else ""))


# -- exercise 3: the same projective point? ----------------------------------------------------------

_STORED_PAIRS = {"pairs": TUPLE_PAIRS}


def _proportional(a, b) -> bool:
    return bool(mp.same_projective_point(a, b))


@memo
def _same_answers(p):
    pairs = p["pairs"]
    right = [_proportional(a, b) for a, b in pairs]
    positive_only = [_proportional(a, b) and float(np.dot(a, b)) > 0 for a, b in pairs]
    ignore_w = [_proportional(a[:3], b[:3]) for a, b in pairs]
    identical = [tuple(a) == tuple(b) for a, b in pairs]
    # the mass-point reading of w = 0: two vectors, equal only if identical (not the projective reading)
    vectors_apart = [_proportional(a, b) if a[3] != 0 or b[3] != 0 else tuple(a) == tuple(b) for a, b in pairs]
    slips = {
        "you allowed only positive scale factors: (x, y, z, w) and c (x, y, z, w) are the same projective point "
        "for EVERY c ≠ 0, negative too (a mass-point with mass -1 is the same point as with mass 1).": positive_only,
        "you compared x, y, z and ignored w: two tuples are the same point only if ALL four coordinates are "
        "proportional, with the same factor (divide by w first when w ≠ 0).": ignore_w,
        "you asked for equal coordinates: that is equality in the space of mass-points (same point AND same mass); "
        "projective space forgets the mass, so proportional tuples are one point.": identical,
        "you compared the tuples with w = 0 as mass-points, that is as vectors, which are equal only when they are "
        "identical; in projective space a tuple with w = 0 is a point at infinity, and the same rule holds there: "
        "proportional tuples (any nonzero factor) are one point.": vectors_apart,
    }
    return right, slips


def _factor(a, b) -> Fraction:
    i = next(k for k, x in enumerate(a) if x != 0)
    return Fraction(int(b[i]), int(a[i]))


def _pair_generate(rng) -> dict:
    def base(w_zero=False):
        while True:
            v = [int(x) for x in rng.integers(-3, 4, size=4)]
            if w_zero:
                v[3] = 0
            elif v[3] == 0:
                continue
            if any(v[:3]):
                return v

    def scaled(v, k):
        return tuple(int(k * x) for x in v)

    def make(kind):
        f, g = (int(x) for x in rng.choice([1, 2, 3], size=2, replace=False))
        if kind == "negative":
            v = base()
            return scaled(v, f), scaled(v, -g)
        if kind == "positive":
            v = base()
            return scaled(v, f), scaled(v, g)
        if kind == "w only":
            v = base()
            a, b = scaled(v, f), list(scaled(v, g))
            b[3] = b[3] + int(rng.choice([-1, 1]))
            return a, tuple(b)
        if kind == "at infinity":
            v = base(w_zero=True)
            return scaled(v, f), scaled(v, -g)
        v = base(w_zero=True)                     # a point at infinity and an affine point
        b = list(v)
        b[3] = int(rng.choice([-2, -1, 1, 2]))
        return tuple(v), tuple(b)

    kinds = ["negative", "w only", "at infinity", str(rng.choice(["positive", "infinite and affine"])),
             str(rng.choice(["positive", "negative", "w only"]))]
    return {"pairs": tuple(make(kinds[i]) for i in rng.permutation(5))}


def _pair_ok(p):
    if any(not any(a) or not any(b) for a, b in p["pairs"]):
        return "a tuple of zeros is no point"
    return None


def _pair_statement(p) -> str:
    return ("Are these pairs of homogeneous coordinates (x, y, z, w) the same point of projective space? "
            + "; ".join(f"({k + 1}) {_tuple(a)} and {_tuple(b)}" for k, (a, b) in enumerate(p["pairs"]))
            + ". Answer a list of five True/False (Goldman §14.2).")


def _pair_steps(p) -> str:
    lines = []
    for k, (a, b) in enumerate(p["pairs"]):
        if _proportional(a, b):
            lines.append(f"({k + 1}) {_tuple(b)} = {_factor(a, b)} · {_tuple(a)}: the same point.")
        else:
            lines.append(f"({k + 1}) no one factor carries {_tuple(a)} to {_tuple(b)} in all four coordinates: "
                         f"different points.")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_PAIRS, generate=_pair_generate, answer=lambda p: _same_answers(p)[0],
               slips=lambda p: _same_answers(p)[1], statement=_pair_statement, steps=_pair_steps,
               same=_equal, well_posed=_pair_ok)
def check_same_projective_point(answer, p) -> Result:
    """Exercise 3: for each pair of the statement, whether the tuples are proportional, the same
    projective point (Goldman §14.2).  answer: five booleans.
    """
    if is_unanswered(answer):
        return unanswered("a list of five True/False")
    pairs = p["pairs"]
    n = len(pairs)
    if not isinstance(answer, (list, tuple)) or len(answer) != n or not all(isinstance(a, (bool, np.bool_))
                                                                             for a in answer):
        return wrong(f"the answer is a list of {n} booleans True/False, one per pair; you gave {quote(answer)}.")
    got = [bool(a) for a in answer]
    right, slips = _same_answers(p)
    if got == right:
        yes = [k + 1 for k, r in enumerate(right) if r]
        no = [k + 1 for k, r in enumerate(right) if not r]
        factors = ", ".join(str(_factor(*pairs[k - 1])) for k in yes)
        return correct(f"{'pairs' if len(yes) > 1 else 'pair'} {_and(yes)} {'are' if len(yes) > 1 else 'is'} "
                       f"proportional ({'factors' if len(yes) > 1 else 'factor'} {factors}); "
                       f"{'pairs' if len(no) > 1 else 'pair'} {_and(no)} {'are' if len(no) > 1 else 'is'} not.")
    for why, value in slips.items():
        if got == value:
            return wrong(why)
    bad = sum(g != r for g, r in zip(got, right))
    return wrong(f"answers not right: {bad} of {n}. Hint: two tuples are one projective point when one is a "
                 f"nonzero multiple (any sign) of the other, in all four coordinates.")


# -- exercise 4: the point at infinity of a line -----------------------------------------------------

_STORED_LINE = {"line": LINE}


def _line_answer(p):
    a, b, _ = p["line"]
    return np.array([b, -a, 0.0])


@memo
def _line_slips(p):
    a, b, d = p["line"]
    return {"the normal": np.array([a, b, 0.0]), "the coefficients": np.array([a, b, -d]),
            "w not 0": np.array([b, -a, 1.0])}


def _line_generate(rng) -> dict:
    a, b = (float(rng.choice([-5, -4, -3, -2, -1, 1, 2, 3, 4, 5])) for _ in range(2))
    return {"line": (a, b, float(rng.choice([-12, -9, -7, -5, -4, -3, -2, -1, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11])))}


def _line_statement(p) -> str:
    a, b, d = p["line"]
    return (f"In homogeneous coordinates (x, y, w) the line {_linear([(a, 'x'), (b, 'y')])} = {fmt(d)} of the "
            f"plane is {_linear([(a, 'x'), (b, 'y'), (-d, 'w')])} = 0. Give its point at infinity as [x, y, w] "
            f"(any nonzero multiple will do) (Goldman §14.2).")


def _line_steps(p) -> str:
    a, b, d = p["line"]
    return (f"1. A point at infinity has w = 0: put it into the equation, {_linear([(a, 'x'), (b, 'y')])} = 0.\n"
            f"2. A nonzero solution is (x, y) = {_tuple(_line_answer(p)[:2])}, the line's direction "
            f"(perpendicular to its normal {_tuple((a, b))}).\n"
            f"3. The point at infinity is {_tuple(_line_answer(p))}, or any nonzero multiple.")


@DECK.exercise(stored=_STORED_LINE, generate=_line_generate, answer=_line_answer, slips=_line_slips,
               statement=_line_statement, steps=_line_steps,
               same=lambda u, v: bool(mp.same_projective_point(u, v, tol=1e-8)))
def check_point_at_infinity(answer, p) -> Result:
    """Exercise 4: the point at infinity of the statement's line: ``w = 0`` and ``(x, y)`` a
    direction of the line, up to a nonzero factor (Goldman §14.2).

    >>> print(check_point_at_infinity([3, 2, 0]).message)
    (3, 2, 0) has w = 0, but (3, 2) is the line's NORMAL (the coefficients of x and y), perpendicular to the line: a point at infinity of a line is the direction along it.
    """
    got, problem = read_points(answer, "your point", ask="the point at infinity as [x, y, w]")
    if problem is not None:
        return problem
    if got.shape != (3,):
        return wrong(f"the answer is three homogeneous coordinates [x, y, w]; yours has shape {got.shape}.")
    if not np.any(got):
        return wrong("(0, 0, 0) is no point of projective space: the coordinates of a point are never all 0.")
    a, b, d = p["line"]
    direction = np.array([b, -a, 0.0])
    said = fmt(got)
    if bool(mp.same_projective_point(got, direction, tol=1e-8)):
        return correct(f"{said} is the line's point at infinity: w = 0 and (x, y) is a direction of the line.")
    if bool(mp.same_projective_point(got, [a, b, -d], tol=1e-8)) or bool(mp.same_projective_point(got, [a, b, d],
                                                                                                  tol=1e-8)):
        return wrong(f"{said} holds the line's coefficients: they describe the line (a point of the DUAL plane), not "
                     f"a point on it. A point on the line satisfies the equation; at infinity w = 0.")
    if abs(got[2]) > 1e-12 and np.any(got[:2]) and bool(mp.same_projective_point(got[:2], direction[:2], tol=1e-8)):
        return wrong(f"{said} has the right direction but w ≠ 0: that is an affine point (x/w, y/w), not a point "
                     f"at infinity. Points at infinity are the tuples with w = 0 (the vectors, mass 0).")
    if abs(got[2]) <= 1e-12 and bool(mp.same_projective_point(got[:2], [a, b], tol=1e-8)):
        return wrong(f"{said} has w = 0, but ({fmt(got[0])}, {fmt(got[1])}) is the line's NORMAL (the coefficients "
                     f"of x and y), perpendicular to the line: a point at infinity of a line is the direction along it.")
    if abs(got[2]) > 1e-12:
        on_line = abs(a * got[0] + b * got[1] - d * got[2]) <= 1e-8 * (1 + np.abs(got).max())
        where = "a point of the line, but an affine one" if on_line else "not even on the line"
        return wrong(f"{said} has w ≠ 0, so it is {where}; the point at infinity has w = 0. Hint: put w = 0 into "
                     f"the line's equation.")
    return wrong(f"{said} has w = 0, but it does not satisfy the line's equation with w = 0. Hint: solve "
                 f"{_linear([(a, 'x'), (b, 'y')])} = 0 for a nonzero (x, y).")


# -- exercise 5: perspective by the law of the lever -------------------------------------------------

_STORED_LEVER_PERSP = {"E": PERSPECTIVE_EYE, "Q": PERSPECTIVE_PLANE[0], "N": PERSPECTIVE_PLANE[1],
                       "P": PERSPECTIVE_POINT}


def _cs(p):
    E, Q, N, P = (_arr(p[k]) for k in ("E", "Q", "N", "P"))
    return float((Q - E) @ N), float((P - E) @ N)


@memo
def _perspective_answers(p):
    E, Q, N, P = (_arr(p[k]) for k in ("E", "Q", "N", "P"))
    image = mp.perspective_mass(P, E, Q, N)
    right = mp.point_of(image)
    s, c = float(mp.mass_of(image)), float(mp.mass_of(mp.perspective_mass(Q, E, Q, N)))
    s0, c0 = float(P @ N), float(Q @ N)
    if s - c > c:
        why = "here the eye is nearer the plane, so the eye gets the larger mass"
    elif s - c > 0:
        why = "here P is nearer the plane, so P gets the larger mass"
    else:
        why = "here P lies between the eye and the plane, so the eye's mass s - c is negative"
    slips = {
        f"swaps the masses: the mass c belongs at P and s - c at E (the heavier mass pulls the balance point towards "
        f"it; {why}).": mp.point_of(mp.add(mp.mass_point(P, s - c), mp.mass_point(E, c))),
        "is the first three coordinates of the summed mass-point (c P + (s - c) E, s); divide by its mass to get "
        "the point.": image[:3],
        "divides by c, the mass at P; the sum's mass is the TOTAL mass c + (s - c) = s.": image[:3] / c,
        "divides by s - c, the mass at E; the sum's mass is the TOTAL mass c + (s - c) = s.": image[:3] / (s - c),
        "is the midpoint of P and E: that gives both points the same mass; here the masses are c and s - c.":
            (P + E) / 2,
        "gives E the mass c - s: the sign is wrong. The masses c and s - c add up to s, the depth of P.":
            mp.point_of(mp.add(mp.mass_point(P, c), mp.mass_point(E, c - s))),
        "measures depths from the origin: s and c are depths from the EYE, (P - E)·N and (Q - E)·N.":
            (c0 * P + (s0 - c0) * E) / s0,
    }
    return right, slips


def _lever_persp_generate(rng) -> dict:
    k = int(rng.integers(0, 3))
    N = np.eye(3)[k]
    q = float(rng.integers(-2, 3))
    h = int(rng.integers(2, 6))
    E = np.array(_ints(rng, -3, 3))
    E[k] = q - h
    P = np.array(_ints(rng, -6, 6))
    P[k] = q - h + float(rng.choice([j for j in range(1, h + 9) if j != h]))
    return {"E": _ftup(E), "Q": _ftup(q * N), "N": _ftup(N), "P": _ftup(P)}


def _lever_persp_ok(p):
    c, s = _cs(p)
    s0, c0 = float(_arr(p["P"]) @ _arr(p["N"])), float(_arr(p["Q"]) @ _arr(p["N"]))
    if abs(s) < 0.5 or abs(s - c) < 0.5 or abs(s - 2 * c) < 0.5:
        return "a mass of the sum (or of a recognised slip) is zero"
    if abs(s0) < 0.5:
        return "P·N = 0: the depths from the origin give no point"
    return None


def _lever_persp_statement(p) -> str:
    return (f"The eye is E = {_tuple(p['E'])} and the plane of projection passes through Q = "
            f"{_tuple(p['Q'])} with normal N = {_tuple(p['N'])}. With c = (Q - E)·N and "
            f"s = (P - E)·N, the perspective image of P = {_tuple(p['P'])} is the sum of the mass-points "
            f"(cP, c) and ((s - c)E, s - c), written (mP, m) as in §14.3: mass c at P, mass s - c at E. Compute it "
            f"by the law of the lever and give the image point [x, y, z] (Goldman §14.4).")


def _lever_persp_steps(p) -> str:
    c, s = _cs(p)
    E, P = _arr(p["E"]), _arr(p["P"])
    total = c * P + (s - c) * E
    return (f"1. c = (Q - E)·N = {fmt(c)} and s = (P - E)·N = {fmt(s)}, so the masses are c = {fmt(c)} at P and "
            f"s - c = {fmt(s - c)} at E.\n"
            f"2. The sum of ({fmt(c)}P, {fmt(c)}) and ({fmt(s - c)}E, {fmt(s - c)}) is ({_f6(total)}, {fmt(s)}).\n"
            f"3. Divide by the total mass s = {fmt(s)}: the image is {_f6(_perspective_answers(p)[0])}, on the plane "
            f"and on the line EP.")


@DECK.exercise(stored=_STORED_LEVER_PERSP, generate=_lever_persp_generate, answer=lambda p: _perspective_answers(p)[0],
               slips=lambda p: _perspective_answers(p)[1], statement=_lever_persp_statement,
               steps=_lever_persp_steps, same=_close_all, well_posed=_lever_persp_ok)
def check_perspective_by_lever(answer, p) -> Result:
    """Exercise 5: the perspective image of the statement's point as the sum of the mass-points
    ``(cP, c)`` and ``((s - c)E, s - c)`` (Goldman §14.4).  answer: ``[x, y, z]``.
    """
    got, problem = read_points(answer, "your point", ask="the image point as [x, y, z]")
    if problem is not None:
        return problem
    right, slips = _perspective_answers(p)
    if got.shape == (4,) and got[3] != 0 and bool(mp.same_projective_point(got, np.append(right, 1.0), tol=1e-8)):
        return wrong("you gave a mass-point (four numbers) of the image, and it is the right one: now divide by its "
                     "mass and give the point [x, y, z].")
    if got.shape != (3,):
        return wrong(f"the image is one point [x, y, z]; yours has shape {got.shape}.")
    if np.allclose(got, right, atol=1e-6, rtol=1e-4):
        return correct(f"the image is {fmt(right)}, on the plane and on the line EP.")
    for why, value in slips.items():
        if np.allclose(got, value, atol=1e-6, rtol=1e-4):
            return wrong(f"your point {why}")
    Q, N = _arr(p["Q"]), _arr(p["N"])
    off_plane = abs(float((got - Q) @ N))
    where = "it is not on the plane of projection" if off_plane > 1e-6 else "it is on the plane, but not on the line EP"
    return wrong(f"your point is {far_off(got, right)}; {where}. Hint: compute c and s "
                 f"first, then (c P + (s - c) E) / s.")


# -- exercise 6: pseudodepth -------------------------------------------------------------------------

_STORED_DEPTH = {"E": DEPTH_EYE, "Q": DEPTH_PLANE[0], "N": DEPTH_PLANE[1], "points": tuple(DEPTH_POINTS.values())}


@memo
def _depth_answers(p):
    E, Q, N = _arr(p["E"]), _arr(p["Q"]), _arr(p["N"])
    P = np.array(p["points"])
    right = mp.pseudodepth(P, E, Q, N)
    s = mp.mass_of(mp.perspective_mass(P, E, Q, N))
    c = float(mp.mass_of(mp.perspective_mass(Q, E, Q, N)))
    s0, c0 = P @ N, float(Q @ N)
    slips = {
        "are c/s, the perspective scale factor: it SHRINKS with depth (reversing the depth order); pseudodepth is "
        "1 - c/s, which grows with depth.": c / s,
        "measure depth from the origin: s and c are depths from the EYE, (P - E)·N and (Q - E)·N.": 1 - c0 / s0,
        "are s/c, the ratio upside down; pseudodepth is 1 - c/s, between 0 (on the plane) and 1 (at infinity).": s / c,
        "are the depths s themselves; pseudodepth is 1 - c/s, between 0 (on the plane) and 1 (at infinity).": s,
        "are 1 - s/c, with the ratio upside down; pseudodepth is 1 - c/s.": 1 - s / c,
    }
    return right, slips


def _depth_generate(rng) -> dict:
    k = int(rng.integers(0, 3))
    N = np.eye(3)[k] * float(rng.choice([-1, 1]))
    E = np.array(_ints(rng, -2, 2))
    c = int(rng.integers(2, 6))
    Q = E + c * N + np.array(_ints(rng, -2, 2)) * (1 - np.abs(N))
    depths = rng.choice([d for d in range(1, 17) if d != c], size=3, replace=False)
    points = tuple(_ftup(E + float(d) * N + np.array(_ints(rng, -3, 3)) * (1 - np.abs(N))) for d in depths)
    return {"E": _ftup(E), "Q": _ftup(Q), "N": _ftup(N), "points": points}


def _depth_ok(p):
    P, N = np.array(p["points"]), _arr(p["N"])
    if np.any(np.abs(P @ N) < 0.5):
        return "a point with P·N = 0: depths from the origin divide by 0"
    return None


def _depth_statement(p) -> str:
    return (f"The eye is E = {_tuple(p['E'])}, looking at the plane through Q = {_tuple(p['Q'])} with "
            f"normal N = {_tuple(p['N'])} (towards the plane). With c = (Q - E)·N and s = (P - E)·N, the "
            f"pseudodepth of a point P in front of the eye is 1 - c/s. Give the pseudodepths of "
            + ", ".join(f"{k} = {_tuple(P)}" for k, P in zip("ABC", p["points"]))
            + " as [dA, dB, dC] (Goldman §14.4).")


def _depth_steps(p) -> str:
    E, Q, N = _arr(p["E"]), _arr(p["Q"]), _arr(p["N"])
    c = float((Q - E) @ N)
    lines = [f"1. c = (Q - E)·N = {_tuple(Q - E)}·{_tuple(N)} = {fmt(c)}."]
    for name, P, d in zip("ABC", p["points"], _depth_answers(p)[0]):
        s = float((_arr(P) - E) @ N)
        lines.append(f"* {name}: s = (P - E)·N = {fmt(s)}, pseudodepth 1 - {fmt(c)}/{fmt(s)} = {_f6(d)}.")
    return "\n".join(lines)


@DECK.exercise(stored=_STORED_DEPTH, generate=_depth_generate, answer=lambda p: _depth_answers(p)[0],
               slips=lambda p: _depth_answers(p)[1], statement=_depth_statement, steps=_depth_steps,
               same=lambda a, b: _arr(a).shape == _arr(b).shape and bool(
                   np.allclose(a, b, atol=1e-4, rtol=1e-4) or np.allclose(b, a, atol=1e-4, rtol=1e-4)),
               well_posed=_depth_ok)
def check_pseudodepth(answer, p) -> Result:
    """Exercise 6: the pseudodepths ``1 - c/s`` of the statement's three points (Goldman §14.4).
    answer: ``[dA, dB, dC]``.
    """
    got, problem = read_points(answer, "your pseudodepths", ask="the three pseudodepths as [dA, dB, dC]")
    if problem is not None:
        return problem
    if got.shape != (3,):
        return wrong(f"the answer is three numbers [dA, dB, dC]; yours has shape {got.shape}.")
    right, slips = _depth_answers(p)
    if np.allclose(got, right, atol=1e-4, rtol=1e-4):
        order = np.argsort(right, kind="stable")
        a, b, c = ("ABC"[i] for i in order)
        return correct(f"the pseudodepths are {fmt(right)}: {a} is nearest, then {b}, then {c}, the order of the "
                       f"depths s.")
    for why, value in slips.items():
        if np.allclose(got, value, atol=1e-4, rtol=1e-4):
            return wrong(f"your values {why}")
    k = int(np.argmax(np.abs(got - right) > 1e-4))
    return wrong(f"the pseudodepth of {'ABC'[k]} is {off_by(got[k], right[k])}. Hint: s = (P - E)·N is the depth of "
                 f"P in front of the eye, c = (Q - E)·N that of the plane; then 1 - c/s.")


# -- exercise 7: depth order by pseudodepth ----------------------------------------------------------

_STORED_ORDER = {"E": ORDER_EYE, "Q": ORDER_PLANE[0], "N": ORDER_PLANE[1], "points": tuple(ORDER_POINTS.values()),
                 "pair": ("B", "D")}
_TILTED = ((1.0, 1.0, 0.0), (1.0, 0.0, 1.0), (0.0, 1.0, 1.0), (1.0, -1.0, 0.0), (1.0, 2.0, 0.0), (2.0, 1.0, 0.0),
           (0.0, 1.0, 2.0), (1.0, 1.0, 1.0), (2.0, 0.0, 1.0))


def _order(keys) -> str:
    return "".join("ABCD"[i] for i in np.argsort(keys, kind="stable"))


@memo
def _order_answers(p):
    E, Q, N = _arr(p["E"]), _arr(p["Q"]), _arr(p["N"])
    P = np.array(p["points"])
    pd = mp.pseudodepth(P, E, Q, N)
    slips = {
        "farthest first": (_order(-pd), "that is the order from FARTHEST to nearest (or the order of c/s, which "
                                        "shrinks with depth); pseudodepth 1 - c/s grows with depth, and the "
                                        "nearest point comes first."),
        "distance": (_order(np.linalg.norm(P - E, axis=1)), "that is the order of the distances |P - E| from the eye; "
                                                            "depth, and so pseudodepth, is measured along the normal "
                                                            "N of the plane: s = (P - E)·N."),
        "z": (_order(P[:, 2]), f"that orders the points by z; here the eye looks along N = {_tuple(N)}, so depth is "
                               f"s = (P - E)·N, not a coordinate."),
    }
    return _order(pd), slips


def _order_generate(rng) -> dict:
    N = np.array(_TILTED[int(rng.integers(0, len(_TILTED)))])
    E = np.array(_ints(rng, -2, 2))
    Q = E + float(rng.choice([1, 2])) * N
    points = []
    while len(points) < 3:
        X = E + np.array(_ints(rng, -4, 4))
        if (X - E) @ N > 0.5:
            points.append(X)
    k = int(rng.integers(0, 3))
    points.append(E + float(rng.choice([2, 3])) * (points[k] - E))      # on the line of sight of points[k]
    order = [int(i) for i in rng.permutation(4)]
    names = {old: "ABCD"[new] for new, old in enumerate(order)}
    shuffled = [points[old] for old in order]
    return {"E": _ftup(E), "Q": _ftup(Q), "N": _ftup(N), "points": tuple(_ftup(x) for x in shuffled),
            "pair": tuple(sorted((names[k], names[3])))}


def _order_ok(p):
    E, N = _arr(p["E"]), _arr(p["N"])
    P = np.array(p["points"])
    s, dist, z = (P - E) @ N, np.linalg.norm(P - E, axis=1), P[:, 2]
    for keys, gap, what in ((s, 0.5, "depths"), (dist, 0.05, "distances"), (z, 0.5, "z coordinates")):
        d = np.abs(keys[:, None] - keys[None, :])[np.triu_indices(4, 1)]
        if d.min() < gap:
            return f"two {what} tie: the order is not one"
    return None


def _order_statement(p) -> str:
    return (f"The eye is E = {_tuple(p['E'])} and the plane of projection passes through Q = {_tuple(p['Q'])} "
            f"with normal N = {_tuple(p['N'])} (not a unit vector; c/s does not care). Order the points "
            + ", ".join(f"{k} = {_tuple(P)}" for k, P in zip("ABCD", p["points"]))
            + " by pseudodepth, from nearest the eye to farthest, as a string of letters such as 'ABCD' "
              "(Goldman §14.4).")


def _order_steps(p) -> str:
    E, Q, N = _arr(p["E"]), _arr(p["Q"]), _arr(p["N"])
    P = np.array(p["points"])
    c = float((Q - E) @ N)
    pd = mp.pseudodepth(P, E, Q, N)
    depth = ", ".join(f"s_{k} = {fmt(s)}" for k, s in zip("ABCD", (P - E) @ N))
    return (f"1. c = (Q - E)·N = {fmt(c)}; the depths s = (P - E)·N: {depth}.\n"
            f"2. Pseudodepth 1 - c/s grows with s: " + ", ".join(f"{k}: {_f6(d)}" for k, d in zip("ABCD", pd)) + ".\n"
            f"3. Nearest first: {_order_answers(p)[0]}. {p['pair'][0]} and {p['pair'][1]} lie on one line of sight "
            f"from E: perspective sends them to one point, pseudodepth keeps them apart.")


@DECK.exercise(stored=_STORED_ORDER, generate=_order_generate, answer=lambda p: _order_answers(p)[0],
               slips=lambda p: {k: v[0] for k, v in _order_answers(p)[1].items()}, statement=_order_statement,
               steps=_order_steps, same=_equal, well_posed=_order_ok)
def check_depth_order(answer, p) -> Result:
    """Exercise 7: the statement's four points from nearest to farthest by pseudodepth
    (Goldman §14.4).  answer: a string of letters such as ``"ABCD"``.
    """
    if is_unanswered(answer):
        return unanswered("the order as a string of letters such as 'ABCD'")
    if isinstance(answer, (list, tuple)) and all(isinstance(a, str) for a in answer):
        answer = "".join(answer)
    if not isinstance(answer, str):
        return wrong(f"the answer is a string of the four letters, nearest first, such as 'ABCD'; you gave {quote(answer)}.")
    letters = "".join(ch for ch in answer.upper() if ch.isalpha())
    if sorted(letters) != sorted("ABCD"):
        return wrong(f"the answer names each of the points A, B, C, D once, nearest first; you gave "
                     f"{quote(answer)}.")
    right, slips = _order_answers(p)
    if letters == right:
        a, b = p["pair"]
        return correct(f"{', '.join(right)} by pseudodepth, the order of the depths; {a} and {b} share a line of sight "
                       f"(perspective sends them to one point), and pseudodepth still tells them apart.")
    for order, message in slips.values():
        if letters == order:
            return wrong(message)
    place = sum(x != y for x, y in zip(letters, right))
    return wrong(f"points in the wrong place: {place} of 4. Hint: compute s = (P - E)·N for each point; "
                 f"1 - c/s grows with s, so the order of the pseudodepths is the order of the depths.")


#: Deal another instance of an exercise (``deal("check_pseudodepth")``, or with ``seed=``; 0 is
#: the stored one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


SLIPS = {
    "check_center_of_mass": [[11 / 6, 1.5, 6], [7 / 3, 1.0, 4], [1 / 3, 13 / 3, 4], [1 / 6, 13 / 6, 4], [1, 13, 4],
                             [0.25, 3.25, 6], [4, 0.25, 3.25]],
    "check_point_or_vector": [["point", "vector", "point", "point", "point", "vector"],
                              ["vector", "point", "point", "point", "vector", "point"],
                              ["vector", "point", "vector", "vector", "point", "vector"],
                              ["point", "point", "point", "vector", "point", "vector"]],
    "check_same_projective_point": [[False, False, False, True, False], [True, True, True, True, True],
                                    [False, False, False, False, False], [True, False, False, True, False]],
    "check_point_at_infinity": [[3, 2, 0], [2, -3, 1], [3, 2, -11], [1, 4, 1], [0, 0, 0], [1, 1, 0]],
    "check_perspective_by_lever": [[4, 5, 6], [24, 36, 24], [6, 9, 6], [3, 4.5, 3], [3, 4, 4], [-6, -5, -14],
                                   [1.2, 2.2, 0.4], [2, 3, 2, 1]],
    "check_pseudodepth": [[0.5, 0.25, 0.8], [4 / 7, 0.8, 0.25], [2, 4, 1.25], [8, 16, 5], [-1, -3, -0.25]],
    "check_depth_order": ["CDAB", "BDAC", "DBCA", "ABCD"],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())

"""Print a check as the values it compares: ours, the reference, the gap and the bound (issue 18, part 5).

A check a learner reads shows the objects, not "...: True".  These helpers format a few rows of
values side by side, rounded to the digits that matter, and the largest gap *as a bound*
("< 1e-12"), never to its last bits: the text is the same on every CPU and BLAS kernel, so it can
sit in a cell that nbval compares.  Formatting only; the mathematics stays in the library.

>>> print(side_by_side([0.0, 0.5, 1.0], [[0, 0], [1.5, 0.75], [3, 0]], [[0, 0], [1.5, 0.75], [3, 1e-17]],
...                    bound=1e-12, names=("t", "de Casteljau", "Bernstein")))
t   | de Casteljau | Bernstein   | gap
0   | (0, 0)       | (0, 0)      | < 1e-12
0.5 | (1.5, 0.75)  | (1.5, 0.75) | < 1e-12
1   | (3, 0)       | (3, 0)      | < 1e-12
largest gap over all 3: < 1e-12
"""

from __future__ import annotations

import re

import numpy as np


def number(x, digits: int = 4) -> str:
    """``x`` rounded to ``digits`` decimals, trailing zeros dropped, never ``-0``.

    A tie such as 0.90625 (common with dyadic data) rounds the same way whether the arithmetic
    left it an ulp above or below: ``x`` is first rounded to ``digits + 6`` decimals.

    >>> number(-1e-17), number(2 / 3), number(2.5), number(float("inf"))
    ('0', '0.6667', '2.5', 'inf')
    >>> number(0.90625 + 1e-16), number(0.90625 - 1e-16)
    ('0.9062', '0.9062')
    """
    x = float(x)
    if not np.isfinite(x):
        return str(x)
    text = f"{round(round(x, digits + 6), digits) + 0.0:.{digits}f}"
    text = text.rstrip("0").rstrip(".") if "." in text else text
    return "0" if text in ("-0", "") else text


def value(v, digits: int = 4) -> str:
    """A number, or a point as ``(x, y, ...)``, rounded by :func:`number`.

    >>> value([0.1234567, -2e-20, 3])
    '(0.1235, 0, 3)'
    """
    a = np.asarray(v, dtype=float)
    if a.ndim == 0:
        return number(a, digits)
    return "(" + ", ".join(number(x, digits) for x in a.ravel()) + ")"


def gap(g, bound: float) -> str:
    """The gap ``g`` as the learner should read it: ``< bound`` when within it (portable), else the
    gap itself to two digits and the word that it exceeds the bound.

    >>> gap(3.1e-16, 1e-12), gap(0.0123, 0.01), gap(0.0, 1e-9)
    ('< 1e-12', '0.012 (over the bound 0.01)', '< 1e-9')
    """
    g = float(g)
    return f"< {_short(bound)}" if g < bound else f"{_short(g, 2)} (over the bound {_short(bound)})"


def _short(x: float, digits: int = 6) -> str:
    """``x`` in ``g`` format without a padded exponent: 1e-9, not 1e-09."""
    return re.sub(r"e\+?(-?)0*(\d)", r"e\1\2", f"{x:.{digits}g}")


def table(header, rows) -> str:
    """Rows of strings (or values) as aligned text columns separated by ``|``.

    >>> print(table(["n", "F"], [[1, "0.2"], [16, "0.19"]]))
    n  | F
    1  | 0.2
    16 | 0.19
    """
    cells = [[str(c) for c in header]] + [[str(c) for c in row] for row in rows]
    widths = [max(len(r[j]) for r in cells) for j in range(len(header))]
    lines = [" | ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in cells]
    return "\n".join(lines)


def side_by_side(labels, ours, reference, bound: float, digits: int = 4, rows: int = 5,
                 names=("t", "ours", "reference")) -> str:
    """A few rows ``label | ours | reference | gap`` (evenly spread over all of them) and a last
    line with the largest gap over every row, as a bound.

    labels: (N,) what each row is at (a parameter, a point number).  ours, reference: (N,) numbers
    or (N, d) points, ``inf`` for "no hit".  The gap of a row is the largest coordinate difference
    (0 where both sides are the same infinity).
    """
    ours, reference = np.asarray(ours, dtype=float), np.asarray(reference, dtype=float)
    if ours.shape != reference.shape:
        raise ValueError(f"ours and reference must have the same shape; got {ours.shape} and {reference.shape}")
    labels = list(labels)
    if len(labels) != len(ours):
        raise ValueError(f"labels must give one label per row; got {len(labels)} for {len(ours)} rows")
    with np.errstate(invalid="ignore"):
        diff = np.where(ours == reference, 0.0, np.abs(ours - reference))
    gaps = diff.reshape(len(ours), -1).max(axis=1)
    pick = np.unique(np.linspace(0, len(ours) - 1, min(rows, len(ours))).round().astype(int))
    body = [[value(labels[i], digits) if np.ndim(labels[i]) or isinstance(labels[i], (int, float, np.number))
             else labels[i], value(ours[i], digits), value(reference[i], digits), gap(gaps[i], bound)]
            for i in pick]
    text = table([names[0], names[1], names[2], "gap"], body)
    return text + f"\nlargest gap over all {len(ours)}: {gap(gaps.max(), bound)}"

"""Show, don't print True: a check printed as a small table of the objects it is about.

Each row names a claim and shows our value beside the reference value (another formula, another
library, the closed form), the gap between them and whether it is inside the bound.  The gap is
printed as ``< bound`` when it holds, never to its last bits, so the printed table is the same on
every CPU and BLAS kernel (the course's nbval baseline compares it strictly); a gap outside the bound
is printed with two digits and flagged, so the baseline comparison fails where the claim does.

Values are rounded to ``digits`` decimals (trailing zeros dropped); a vector of up to ``max_shown``
entries is printed whole, and a batch (500 random pairs) by its first item and its size.

>>> print(agreement_table([("u·v", 5.0, 5.0), ("u x v", [0.5, -1.0, 4.0], [0.5, -1, 4])]))
claim  ours            reference       gap
u·v    5               5               < 1e-12
u x v  (0.5, -1, 4)    (0.5, -1, 4)    < 1e-12
"""

from __future__ import annotations

import numbers

import numpy as np

__all__ = ["agreement_table", "shown_value", "gap_text"]


def shown_value(value, digits: int = 4, max_shown: int = 6) -> str:
    """A value as a learner reads it: a number rounded to ``digits`` decimals, a short vector as a
    tuple, a batch by its first item and its size.

    >>> shown_value(0.7390851332151607)
    '0.7391'
    >>> shown_value([1.0, -0.0, 2.5])
    '(1, 0, 2.5)'
    >>> shown_value(np.arange(1000.0))
    '0, … (1000 values)'
    """
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)):
        return str(bool(value))
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 0:
        text = f"{float(np.round(arr, digits)) + 0.0:.{digits}f}"
        return text.rstrip("0").rstrip(".") if "." in text else text
    if arr.ndim == 1 and arr.size <= max_shown:
        return "(" + ", ".join(shown_value(x, digits) for x in arr) + ")"
    if arr.ndim == 2 and arr.size <= max_shown:
        return "(" + ", ".join(shown_value(row, digits) for row in arr) + ")"
    noun = "values" if arr.ndim == 1 else "items"
    return f"{shown_value(arr[0], digits, max_shown)}, … ({len(arr)} {noun})"


def gap_text(gap: float, bound: float) -> str:
    """The gap as portable text: ``'< 1e-12'`` inside the bound, else two digits and a flag.

    >>> gap_text(3e-16, 1e-12), gap_text(0.25, 1e-12)
    ('< 1e-12', '0.25 > 1e-12 (fails)')
    """
    if gap < bound:
        return f"< {bound:.0e}".replace("e-0", "e-")
    return f"{gap:.2g} > {bound:.0e} (fails)".replace("e-0", "e-")


def agreement_table(rows, *, bound: float = 1e-12, digits: int = 4, max_shown: int = 6,
                    headers=("claim", "ours", "reference", "gap")) -> str:
    """A table with one row per claim: ``label | ours | reference | gap``.

    rows: iterable of ``(label, ours, reference)``; ``ours`` and ``reference`` are numbers or arrays
    of the same (broadcastable) shape, and the gap is the largest ``|ours - reference|`` over all of
    them.  bound: positive; the gap is printed as ``< bound`` when it is below it.
    headers: four column titles (``ours`` may say which formula, ``reference`` which library).
    Raises ValueError when ``rows`` is empty, a row is not a triple, the two values' shapes differ,
    or ``bound`` is not a positive number; TypeError when a value is not numeric.

    >>> print(agreement_table([("cube root of 2", 2 ** (1 / 3), 1.2599210498948732)], digits=12,
    ...                       headers=("", "Newton", "2**(1/3)", "gap")))
                    Newton          2**(1/3)        gap
    cube root of 2  1.259921049895  1.259921049895  < 1e-12
    """
    if isinstance(bound, bool) or not isinstance(bound, numbers.Real) or not bound > 0:
        raise ValueError(f"bound must be a positive number, got {bound!r}")
    if len(headers) != 4:
        raise ValueError(f"headers must name four columns (claim, ours, reference, gap), got {len(headers)}")
    table = []
    for i, row in enumerate(rows):
        if not isinstance(row, (tuple, list)) or len(row) != 3:
            raise ValueError(f"rows[{i}] must be a triple (label, ours, reference)")
        label, ours, reference = row
        try:
            a, b = np.asarray(ours, dtype=float), np.asarray(reference, dtype=float)
        except (TypeError, ValueError) as exc:
            raise TypeError(f"rows[{i}] ({label!r}): ours and reference must be numbers or arrays") from exc
        try:
            diff = np.abs(a - b)
        except ValueError as exc:
            raise ValueError(f"rows[{i}] ({label!r}): ours has shape {a.shape} and reference {b.shape}; "
                             "they must match") from exc
        gap = float(diff.max()) if diff.size else 0.0
        if np.isnan(gap):
            gap = float("inf")
        table.append((str(label), shown_value(ours, digits, max_shown), shown_value(reference, digits, max_shown),
                      gap_text(gap, bound)))
    if not table:
        raise ValueError("rows must hold at least one (label, ours, reference) triple")
    widths = [max(len(h), *(len(r[k]) for r in table)) for k, h in enumerate(headers)]
    widths[1] = max(widths[1], 14)
    widths[2] = max(widths[2], 14)
    lines = ["  ".join(str(h).ljust(w) for h, w in zip(headers, widths)).rstrip()]
    lines += ["  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in table]
    return "\n".join(lines)

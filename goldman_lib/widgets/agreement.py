"""Print a check as the values it compares: ours, the reference, the gap and the bound.

"Show, don't print True" (CONVENTIONS.md): instead of ``claim: True`` a notebook prints the objects
side by side, rounded to the digits that matter, and the largest gap between them *as a bound*
(``< 1e-12``), never to its last bits: the text is the same on every CPU and BLAS kernel, so it can
sit in a cell that nbval compares.  A gap outside its bound is printed (rounded) and flagged, so the
stored output changes exactly where a claim fails.  A row may also claim that two objects *differ*
(``relation=">"``): then the gap itself is the point and is printed rounded.

Formatting only; what is compared is computed by the library in the notebook.

- :func:`number`, :func:`value`: a number or an array as a learner reads it;
- :func:`gap`: a gap against its bound;
- :func:`agreement_table`: one row per claim, ``label | ours | reference | largest gap``;
- :func:`side_by_side`: a few rows of one long comparison (spread over all of it) and the largest
  gap over every row;
- :func:`table`: any rows as aligned columns.

>>> print(agreement_table([("1/3 + 1/3", 1 / 3 + 1 / 3, 2 / 3), ("u x v", [0.5, -1.0, 4.0], [0.5, -1, 4])]))
           ours            reference       largest gap
1/3 + 1/3  0.6667          0.6667          < 1e-12
u x v      (0.5, -1, 4)    (0.5, -1, 4)    < 1e-12
>>> print(side_by_side([0.0, 0.5, 1.0], [[0, 0], [1.5, 0.75], [3, 0]], [[0, 0], [1.5, 0.75], [3, 1e-17]],
...                    bound=1e-12, names=("t", "de Casteljau", "Bernstein")))
t   | de Casteljau | Bernstein   | gap
0   | (0, 0)       | (0, 0)      | < 1e-12
0.5 | (1.5, 0.75)  | (1.5, 0.75) | < 1e-12
1   | (3, 0)       | (3, 0)      | < 1e-12
largest gap over all 3: < 1e-12
"""

from __future__ import annotations

import math
import re

import numpy as np

__all__ = ["number", "value", "gap", "table", "side_by_side", "agreement_table"]


def _digits(digits) -> int:
    if isinstance(digits, bool) or not isinstance(digits, (int, np.integer)) or not 0 <= digits <= 15:
        raise ValueError(f"digits must be a whole number in [0, 15]; got {digits!r}")
    return int(digits)


def number(x, digits: int = 4) -> str:
    """``x`` rounded to ``digits`` decimals, trailing zeros dropped, never ``-0``.

    A tie such as 0.90625 (common with dyadic data) rounds the same way whether the arithmetic
    left it an ulp above or below: ``x`` is first rounded to ``digits + 6`` decimals.

    >>> number(-1e-17), number(2 / 3), number(2.5), number(float("inf"))
    ('0', '0.6667', '2.5', 'inf')
    >>> number(0.90625 + 1e-16), number(0.90625 - 1e-16)
    ('0.9062', '0.9062')
    """
    digits = _digits(digits)
    x = float(x)
    if not math.isfinite(x):
        return str(x)
    text = f"{round(round(x, digits + 6), digits) + 0.0:.{digits}f}"
    text = text.rstrip("0").rstrip(".") if "." in text else text
    return "0" if text in ("-0", "") else text


def value(v, digits: int = 4, max_items: int | None = None) -> str:
    """A value as a learner reads it: text as it is, a truth value as True/False, a number by
    :func:`number`, a point as ``(x, y, ...)``, a matrix as ``((a, b), (c, d))``, a complex
    number as its real and imaginary parts.  With ``max_items``, an array of more numbers shows
    its first item and its shape: ``(1, 1, 1), … (500 x 3)``.

    >>> value([0.1234567, -2e-20, 3])
    '(0.1235, 0, 3)'
    >>> value(np.eye(2)), value(np.ones((500, 3)), max_items=6), value(np.arange(9.0), max_items=6)
    ('((1, 0), (0, 1))', '(1, 1, 1), … (500 x 3)', '0, … (9 values)')
    """
    digits = _digits(digits)
    if isinstance(v, str):
        return v
    if isinstance(v, (bool, np.bool_)):
        return str(bool(v))
    a = np.asarray(v)
    if a.dtype == object or not (np.issubdtype(a.dtype, np.number) or a.dtype == bool):
        raise TypeError(f"value must be a number or an array of numbers; got {type(v).__name__}")
    if np.iscomplexobj(a):
        a = np.stack([a.real, a.imag], axis=-1)

    def whole(x):
        if x.ndim == 0:
            return str(bool(x)) if x.dtype == bool else number(x, digits)
        return "(" + ", ".join(whole(y) for y in x) + ")"

    if a.ndim == 0 or max_items is None or a.size <= max_items:
        return whole(a)
    if a.ndim == 1:
        return f"{whole(a[0])}, … ({a.size} values)"
    return f"{whole(a[0])}, … ({' x '.join(str(n) for n in a.shape)})"


def _short(x: float, digits: int = 6) -> str:
    """``x`` in ``g`` format without a padded exponent: 1e-9, not 1e-09."""
    return re.sub(r"e\+?(-?)0*(\d)", r"e\1\2", f"{x:.{digits}g}")


def _bound(bound) -> float:
    if isinstance(bound, bool) or not isinstance(bound, (int, float, np.integer, np.floating)) \
            or not math.isfinite(bound) or bound <= 0:
        raise ValueError(f"bound must be a positive finite number; got {bound!r}")
    return float(bound)


def gap(g, bound: float, relation: str = "<") -> str:
    """The gap ``g`` as the learner should read it.  ``relation="<"`` (they agree): ``< bound``
    when within it (portable), else the gap to two digits and the word that it exceeds the bound.
    ``relation=">"`` (they differ): the gap, rounded, and ``> bound``, or ``NOT > bound``.
    A NaN gap never passes.

    >>> gap(3.1e-16, 1e-12), gap(0.0123, 0.01), gap(0.0, 1e-9), gap(2.3, 0.1, ">")
    ('< 1e-12', '0.012 (over the bound 0.01)', '< 1e-9', '2.3 > 0.1')
    """
    b = _bound(bound)
    g = float(g)
    if math.isnan(g):
        g = math.inf
    if relation == "<":
        return f"< {_short(b)}" if g < b else f"{_short(g, 2)} (over the bound {_short(b)})"
    if relation == ">":
        return f"{_short(g, 3)} > {_short(b)}" if g > b else f"{_short(g, 3)} NOT > {_short(b)}"
    raise ValueError(f"relation must be '<' or '>'; got {relation!r}")


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


def _largest_gap(ours, reference, where: str) -> float:
    try:
        a, b = np.asarray(ours), np.asarray(reference)
        if a.dtype == object or b.dtype == object:
            raise TypeError
        a, b = a.astype(float), b.astype(float)
    except (TypeError, ValueError):
        raise TypeError(f"{where}: ours and reference must be numbers or arrays of numbers") from None
    try:
        a, b = np.broadcast_arrays(a, b)
    except ValueError:
        raise ValueError(f"{where}: ours and reference must have the same shape; got {a.shape} and {b.shape}") from None
    if a.size == 0:
        raise ValueError(f"{where}: ours and reference must not be empty")
    with np.errstate(invalid="ignore"):
        d = np.where(a == b, 0.0, np.abs(a - b))     # the same infinity on both sides: no gap
    d = np.where(np.isnan(d), np.inf, d)
    return float(d.max())


def side_by_side(labels, ours, reference, bound: float, digits: int = 4, rows: int = 5,
                 names=("t", "ours", "reference")) -> str:
    """A few rows ``label | ours | reference | gap`` (evenly spread over all of them) and a last
    line with the largest gap over every row, as a bound.

    labels: (N,) what each row is at (a parameter, a point number).  ours, reference: (N,) numbers
    or (N, d) points, ``inf`` for "no hit".  The gap of a row is the largest coordinate difference
    (0 where both sides are the same infinity).
    """
    _bound(bound)
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


def agreement_table(rows, bound: float = 1e-12, digits: int = 4, max_items: int = 6,
                    headers=("", "ours", "reference", "largest gap"), width: int = 100) -> str:
    """A text table, one row per claim: its label, ours, the reference (by :func:`value`) and the
    largest gap between them (by :func:`gap`).

    rows: a sequence of ``(label, ours, reference)`` or ``(label, ours, reference, options)``,
    ``options`` a dict of ``bound`` (this row's bound), ``relation`` (``"<"``: they agree, the
    default; ``">"``: they differ by more than the bound) and ``digits``.  ``ours`` and
    ``reference`` are numbers or arrays of one shape; a batch (500 random pairs) shows its first
    item and its shape, and its gap is the largest over the whole batch.  headers: the four column
    titles.  A table wider than ``width`` characters puts each label on its own line with the
    values below it.  Raises ValueError for a row of the wrong length, shapes that differ, a bound
    that is not positive and finite, an unknown option or relation; TypeError for a value that is
    not numeric.

    >>> print(agreement_table([("p q", [1, 2], [1, 2]), ("q p", [2, 1], [1, 2], {"relation": ">", "bound": 0.1})]))
         ours            reference       largest gap
    p q  (1, 2)          (1, 2)          < 1e-12
    q p  (2, 1)          (1, 2)          1 > 0.1
    """
    if len(headers) != 4:
        raise ValueError(f"headers must name four columns (label, ours, reference, gap); got {len(headers)}")
    lines = []
    for k, row in enumerate(rows):
        if not isinstance(row, (tuple, list)) or len(row) not in (3, 4):
            raise ValueError(f"rows[{k}] must be (label, ours, reference) or (label, ours, reference, options)")
        label, ours, reference = row[:3]
        options = dict(row[3]) if len(row) == 4 else {}
        unknown = set(options) - {"bound", "relation", "digits"}
        if unknown:
            raise ValueError(f"rows[{k}] options may hold bound, relation, digits; got {sorted(unknown)}")
        try:
            b = _bound(options.get("bound", bound))
        except ValueError as exc:
            raise ValueError(f"{exc} in rows[{k}]") from None
        relation = options.get("relation", "<")
        if relation not in ("<", ">"):
            raise ValueError(f"relation must be '<' or '>'; got {relation!r} in rows[{k}]")
        d = options.get("digits", digits)
        g = _largest_gap(ours, reference, f"rows[{k}] ({str(label)[:40]!r})")
        lines.append((str(label), value(ours, d, max_items), value(reference, d, max_items), gap(g, b, relation)))
    if not lines:
        raise ValueError("rows must hold at least one comparison")
    head = tuple(str(h) for h in headers)
    widths = [max(len(r[c]) for r in [head] + lines) for c in range(4)]
    widths[1], widths[2] = max(widths[1], 14), max(widths[2], 14)
    if sum(widths) + 6 <= width:
        return "\n".join("  ".join(cell.ljust(w) for cell, w in zip(r, widths)).rstrip() for r in [head] + lines)
    # too wide for one line a claim: each label on its own line, the values below it
    cols = widths[1:]
    out = ["  " + "  ".join(h.ljust(w) for h, w in zip(head[1:], cols)).rstrip()]
    for r in lines:
        out += [r[0], "  " + "  ".join(cell.ljust(w) for cell, w in zip(r[1:], cols)).rstrip()]
    return "\n".join(out)

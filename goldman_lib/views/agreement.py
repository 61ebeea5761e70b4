"""A check a learner reads, shown as a table: what is compared, ours, the reference, the gap.

"Show, don't print True" (CONVENTIONS.md): instead of ``claim: True`` a notebook prints the two
objects side by side, rounded to the digits that matter, and the largest gap between them as a
portable bound (``< 1e-12``), never to its last bits (those differ between CPUs and BLAS kernels).
A row may also claim that two objects *differ* (``relation=">"``): then the gap itself is the point
and is printed rounded.

Only formatting lives here; what is compared is computed by the library in the notebook.

>>> print(agreement_table([("1/3 + 1/3", 1 / 3 + 1 / 3, 2 / 3)]))
           ours    reference  largest gap
1/3 + 1/3  0.6667  0.6667     < 1e-12
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["agreement_table", "shown_values"]


def shown_values(value, digits: int = 4, max_items: int = 6) -> str:
    """``value`` (a number, a bool, or an array) on one line, rounded to ``digits`` decimals.

    -0.0 shows as 0.0; an array with more than ``max_items`` numbers shows its first row (or first
    ``max_items`` numbers) and its shape, e.g. ``[0.3, 1.2, 2.0] ... (200 x 3)``.

    >>> shown_values([0.1 + 0.2, -1e-17, 2])
    '[0.3, 0.0, 2.0]'
    >>> shown_values(np.arange(12.0).reshape(4, 3))
    '[0.0, 1.0, 2.0] ... (4 x 3)'
    """
    if isinstance(value, str):
        return value
    if not isinstance(digits, (int, np.integer)) or isinstance(digits, bool) or digits < 0:
        raise ValueError(f"digits must be a non-negative integer; got {digits!r}")
    a = np.asarray(value)
    if a.dtype == bool:
        return str(a.tolist())
    if not np.issubdtype(a.dtype, np.number):
        raise TypeError(f"value must be a number or an array of numbers; got {type(value).__name__}")
    if np.iscomplexobj(a):
        a = np.stack([a.real, a.imag], axis=-1)

    def line(x):
        x = np.asarray(x)
        if x.ndim == 0 and np.issubdtype(x.dtype, np.integer):
            return repr(int(x))
        if x.ndim == 0:
            return repr(round(float(x), digits) + 0.0)
        return "[" + ", ".join(line(y) for y in x) + "]"

    if a.ndim == 0:
        return line(a)
    if a.size <= max_items:
        return line(a)
    shape = " x ".join(str(n) for n in a.shape)
    first = a[0] if a.ndim > 1 and a[0].size <= max_items else a.ravel()[:max_items]
    return f"{line(first)} ... ({shape})"


def _gap(ours, reference) -> float:
    a, b = np.asarray(ours), np.asarray(reference)
    try:
        a, b = np.broadcast_arrays(a, b)
    except ValueError:
        raise ValueError(f"ours and reference must have the same shape; got {a.shape} and {b.shape}") from None
    if a.size == 0:
        raise ValueError("ours and reference must not be empty")
    g = np.abs(a.astype(float) - b.astype(float)) if a.dtype == bool else np.abs(a - b)
    return float(np.max(g))


def _bound_text(bound: float) -> str:
    return f"{bound:g}"


def agreement_table(rows, bound: float = 1e-12, digits: int = 4, max_items: int = 6,
                    header=("ours", "reference", "largest gap"), width: int = 100) -> str:
    """A text table: one row per comparison with ours, the reference (rounded) and the largest gap.

    rows: a sequence of ``(label, ours, reference)`` or ``(label, ours, reference, options)``
    with ``options`` a dict of ``bound`` (this row's bound), ``relation`` (``"<"``: they agree,
    the default; ``">"``: they differ by more than the bound), ``digits``.
    A gap inside ``"<"``'s bound prints as ``< bound`` (portable); any other gap prints rounded to
    3 significant digits, with ``NOT < bound`` or ``> bound`` beside it, so a failed claim shows.
    ``header`` names the three value columns. A table wider than ``width`` characters puts each
    label on its own line with the values below it.
    Raises ValueError for a row of the wrong length, shapes that differ, a bound that is not
    positive and finite, or an unknown relation.

    >>> print(agreement_table([("p q", [1, 2], [1, 2]), ("q p", [2, 1], [1, 2], {"relation": ">", "bound": 0.1})]))
         ours    reference  largest gap
    p q  [1, 2]  [1, 2]     < 1e-12
    q p  [2, 1]  [1, 2]     1 > 0.1
    """
    lines = []
    for k, row in enumerate(rows):
        if not isinstance(row, (tuple, list)) or len(row) not in (3, 4):
            raise ValueError(f"rows[{k}] must be (label, ours, reference) or (label, ours, reference, options)")
        label, ours, reference = row[:3]
        options = dict(row[3]) if len(row) == 4 else {}
        unknown = set(options) - {"bound", "relation", "digits"}
        if unknown:
            raise ValueError(f"rows[{k}] options may hold bound, relation, digits; got {sorted(unknown)}")
        b = options.get("bound", bound)
        if not isinstance(b, (int, float, np.floating, np.integer)) or not math.isfinite(b) or b <= 0:
            raise ValueError(f"bound must be a positive finite number; got {b!r} in rows[{k}]")
        relation = options.get("relation", "<")
        if relation not in ("<", ">"):
            raise ValueError(f"relation must be '<' or '>'; got {relation!r} in rows[{k}]")
        d = options.get("digits", digits)
        gap = _gap(ours, reference)
        if relation == "<" and gap < b:
            g = f"< {_bound_text(b)}"
        elif relation == "<":
            g = f"{gap:.3g} NOT < {_bound_text(b)}"
        else:
            g = f"{gap:.3g} {'>' if gap > b else 'NOT >'} {_bound_text(b)}"
        lines.append((str(label), shown_values(ours, d, max_items), shown_values(reference, d, max_items), g))
    if not lines:
        raise ValueError("rows must hold at least one comparison")
    widths = [max(len(r[c]) for r in [("", *header)] + lines) for c in range(4)]
    if sum(widths) + 6 <= width:
        table = [("", *header)] + lines
        return "\n".join("  ".join(cell.ljust(w) for cell, w in zip(r, widths)).rstrip() for r in table)
    # too wide for one line a comparison: each label on its own line, the values below it
    cols = [max(len(r[c]) for r in [("", *header)] + lines) for c in range(1, 4)]
    out = ["  " + "  ".join(h.ljust(w) for h, w in zip(header, cols)).rstrip()]
    for r in lines:
        out += [r[0], "  " + "  ".join(cell.ljust(w) for cell, w in zip(r[1:], cols)).rstrip()]
    return "\n".join(out)

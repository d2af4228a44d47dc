"""Printed tables that fit the terminal and print user text as written.

* :func:`literal` — a name, file name or record title as a rich ``Text``: rich markup
  (``[bold]``, ``[link=…]``) and emoji codes (``:x:``) in it are printed as typed, never
  interpreted (the consoles of :mod:`pounding.cli.app` interpret neither either).
* :func:`number` — a number in a few significant digits without an exponent, so that a
  column of one unit reads alike (``7858``, ``0.0691``).
* :func:`print_table` — a table whose numbers are never cut: each column gets at least the
  width of its longest number (headers wrap between words), and a table wider than the
  console is printed as several, each repeating the key columns (building, storey).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from rich.cells import cell_len
from rich.console import Console
from rich.table import Table
from rich.text import Text

__all__ = ["Col", "building_label", "literal", "number", "print_table", "force_scale",
           "energy_scale"]


def literal(text: Any) -> Text:
    """``text`` as printed text: no markup, no emoji codes, no highlighting."""
    return text if isinstance(text, Text) else Text(str(text))


def building_label(b: int, name: str) -> str:
    """``B2 stiff`` for building 2 named "stiff"; ``B2`` alone when it has no name or its
    name is its label (a model file's default name)."""
    label = f"B{b + 1}"
    name = (name or "").strip()
    return label if not name or name == label else f"{label} {name}"


def number(value: float, digits: int = 4) -> str:
    """``value`` with ``digits`` significant digits and no exponent (all the digits of a
    larger whole number): ``7858``, ``17679``, ``0.6910``, ``0.0221``; ``–`` for NaN."""
    v = float(value)
    if math.isnan(v):
        return "–"
    if math.isinf(v):
        return "∞" if v > 0 else "−∞"
    if v == 0.0:
        return "0"
    decimals = max(0, digits - 1 - math.floor(math.log10(abs(v))))
    return f"{v:.{decimals}f}"


def force_scale(largest: float) -> tuple[float, str]:
    """``(factor, unit)`` for every force of one screen: kN, or MN from 100 MN on."""
    return (1e-6, "MN") if abs(largest) >= 1e8 else (1e-3, "kN")


def energy_scale(largest: float) -> tuple[float, str]:
    """``(factor, unit)`` for every energy of one screen: kJ, or MJ from 100 MJ on."""
    return (1e-6, "MJ") if abs(largest) >= 1e8 else (1e-3, "kJ")


@dataclass(frozen=True)
class Col:
    """A column: its header (units in brackets, wrapped between words if need be), how its
    cells align, and whether they are text that may wrap between words (names, lists);
    numbers never wrap and are never cut."""

    header: str
    justify: str = "right"
    wrap: bool = False


def _longest_word(text: str) -> int:
    return max((cell_len(w) for w in text.split()), default=0)


def _ranges(cols: Sequence[Col], rows: Sequence[Sequence[Any]]
            ) -> list[tuple[int, int, int]]:
    """The narrowest width of every column, the width at which its cells need not wrap
    (only its header), and its natural width (without padding)."""
    out = []
    for i, col in enumerate(cols):
        cells = [str(r[i]) for r in rows]
        if col.wrap:
            low = max((_longest_word(c) for c in cells), default=0)
        else:
            low = max((cell_len(c) for c in cells), default=0)
        high = max((cell_len(c) for c in cells), default=0)
        head = _longest_word(col.header)
        out.append((max(low, head, 1), max(high, head, 1), max(high, cell_len(col.header), 1)))
    return out


def _overhead(n: int) -> int:
    """Borders and padding of a table of ``n`` columns (rich's default box)."""
    return 3 * n + 1


def _widths(ranges: list[tuple[int, int, int]], room: int) -> list[int]:
    """Natural widths, narrowed to fit ``room``: first the headers wrap (the column with
    the most slack first), then the text cells that may wrap."""
    widths = [hi for _, _, hi in ranges]
    for floor in (1, 0):  # floor 1: cells whole; floor 0: down to the narrowest
        while sum(widths) > room:
            slack = [w - r[floor] for w, r in zip(widths, ranges)]
            k = max(range(len(widths)), key=lambda i: slack[i])
            if slack[k] <= 0:
                break
            widths[k] -= 1
    return widths


def _pack(ranges: list[tuple[int, int, int]], keys: int, cap: int) -> list[list[int]]:
    """Columns in order into groups whose narrowest widths fit ``cap`` (each group the key
    columns and at least one more)."""
    groups: list[list[int]] = []
    current = list(range(keys))
    for i in range(keys, len(ranges)):
        trial = current + [i]
        if (len(current) == keys
                or sum(ranges[j][0] for j in trial) + _overhead(len(trial)) <= cap):
            current = trial
        else:
            groups.append(current)
            current = list(range(keys)) + [i]
    groups.append(current)
    return groups


def _groups(ranges: list[tuple[int, int, int]], keys: int, width: int) -> list[list[int]]:
    """The columns of each part of a table ``width`` wide: one part if it fits, else as
    few parts as fit, made as even as they can be (the narrowest cap that needs no more
    parts)."""
    if sum(r[2] for r in ranges) + _overhead(len(ranges)) <= width:
        return [list(range(len(ranges)))]
    best = _pack(ranges, keys, width)
    cap = width
    while cap > 1:
        trial = _pack(ranges, keys, cap - 1)
        if len(trial) > len(best):
            break
        best, cap = trial, cap - 1
    return best


def print_table(console: Console, title: str, cols: Sequence[Col],
                rows: Sequence[Sequence[Any]], keys: int = 1, caption: str = "",
                show_header: bool = True) -> None:
    """Print ``rows`` under ``cols`` within the console's width.

    Parameters
    ----------
    console : Console
    title : str
        Printed literally; a table split in parts is titled "title (continued)" after the
        first.
    cols : sequence of Col
    rows : sequence of sequences
        Cells as text (``str`` or ``Text``), printed literally.
    keys : int
        The first ``keys`` columns name the row; every part of a split table repeats them.
    caption : str
        Printed under the last part.
    show_header : bool
        False for a table of (quantity, value) pairs.
    """
    width = console.size.width
    ranges = _ranges(cols, rows)
    groups = _groups(ranges, keys, width)
    for g, group in enumerate(groups):
        room = width - _overhead(len(group))
        widths = _widths([ranges[j] for j in group], room)
        table = Table(title=literal(title if g == 0 else f"{title} (continued)"),
                      caption=literal(caption) if caption and g == len(groups) - 1 else None,
                      show_header=show_header)
        for j, w in zip(group, widths):
            col = cols[j]
            table.add_column(literal(col.header), justify=col.justify,  # type: ignore[arg-type]
                             width=w, overflow="fold")
        for row in rows:
            table.add_row(*(literal(row[j]) for j in group))
        console.print(table)

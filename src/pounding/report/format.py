"""Shared formatting of the report pages: numbers, units, and the blocks a section is made of.

A section of a page is a list of blocks: :class:`Table`, :class:`Note`, :class:`Figure`,
:class:`Cards`, :class:`Pre` and :class:`Animation`. Each block holds plain values (text is never HTML here); the
macro of ``templates/blocks.html.j2`` named by its ``kind`` writes it out, HTML-escaped.
"""

from __future__ import annotations

import base64
import io
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from pounding.units import unit_of  # re-exported: the unit of a results column

__all__ = ["Animation", "Block", "Cards", "Figure", "Note", "Pre", "PageSection", "Table", "kv_table", "num",
           "png_bytes", "unit_of", "with_unit"]


# =============================================================================== numbers, units
def num(v: Any, digits: int = 4) -> str:
    """A number for a table cell (plain text, not escaped).

    Parameters
    ----------
    v : Any
        ``None``, a boolean, an integer, a float (NumPy's too) or anything else.
    digits : int, optional
        Significant digits of a float that is not a whole number.

    Returns
    -------
    str
        ``–`` for ``None`` and NaN, ``yes``/``no`` for booleans, ``∞``/``−∞``, a whole
        number without a decimal point, else ``digits`` significant digits; anything else
        as ``str(v)``.
    """
    if v is None:
        return "–"
    if isinstance(v, (bool, np.bool_)):
        return "yes" if v else "no"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        f = float(v)
        if math.isnan(f):
            return "–"
        if math.isinf(f):
            return "∞" if f > 0 else "−∞"
        if f == 0.0:
            return "0"
        if f.is_integer() and abs(f) < 1e6:
            return str(int(f))
        return f"{f:.{digits}g}"
    return str(v)


def with_unit(label: str, unit: str | None) -> str:
    """``label [unit]``, or ``label`` alone when ``unit`` is None or empty."""
    return f"{label} [{unit}]" if unit else label


# =============================================================================== blocks
@dataclass
class Table:
    """A table: a string cell is text (left-aligned), any other cell a number written with
    :func:`num` (right-aligned); ``scroll`` wraps it in a box that scrolls sideways."""

    headers: Sequence[str]
    rows: list[Sequence[Any]] = field(default_factory=list)
    caption: str = ""
    cls: str = ""
    scroll: bool = False
    kind: ClassVar[str] = "table"

    def add(self, *cells: Any) -> None:
        """Append a row of cells."""
        self.rows.append(cells)


def kv_table(items: Iterable[tuple[str, Any]], caption: str = "") -> Table:
    """A two-column table of (quantity, value) pairs."""
    t = Table(("quantity", "value"), caption=caption, cls="kv")
    for k, v in items:
        t.add(k, v)
    return t


@dataclass
class Note:
    """A paragraph of text; ``cls`` is ``note`` (muted) or ``warn``."""

    text: str
    cls: str = "note"
    kind: ClassVar[str] = "note"


@dataclass
class Figure:
    """A PNG image with its alternative text and caption, embedded as a ``data:`` URI."""

    png: bytes
    alt: str
    caption: str
    kind: ClassVar[str] = "figure"

    @property
    def src(self) -> str:
        """The image as a ``data:image/png;base64,…`` URI."""
        return "data:image/png;base64," + base64.b64encode(self.png).decode("ascii")


def png_bytes(fig: Any, dpi: int = 110) -> bytes:
    """A Matplotlib figure saved as PNG (cropped to its content)."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi, bbox_inches="tight")
    return buf.getvalue()


@dataclass
class Cards:
    """Headline numbers, each a (label, value) pair shown as a card."""

    items: list[tuple[str, str]]
    kind: ClassVar[str] = "cards"


@dataclass
class Pre:
    """Preformatted text; with a ``summary``, collapsed under it."""

    text: str
    summary: str = ""
    kind: ClassVar[str] = "pre"


@dataclass
class Animation:
    """The interactive animation of a run (``templates/animation_view.html.j2``): its frames
    as JSON-ready ``data`` (:func:`pounding.report.animate.animation_data`), their number,
    the frame rate and factor as shown, and notes (one sentence each)."""

    data: dict[str, Any]
    n_frames: int
    fps: str
    exaggeration: str
    notes: list[str] = field(default_factory=list)
    kind: ClassVar[str] = "animation"


Block = Table | Note | Figure | Cards | Pre | Animation
"""Anything a section is made of."""


@dataclass
class PageSection:
    """A section of a page: its anchor ``id``, its heading, and its blocks in order."""

    id: str
    heading: str
    blocks: list[Block]

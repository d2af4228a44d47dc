"""The numbers on a record's data lines.

Plain and E-notation numbers, Fortran ``D`` exponents (``0.5D-01``) and the fused runs of
Fortran fixed-width output (``-0.123E-02-0.456E-02``); spaces, tabs or commas between
them. :func:`parse_values` reads a data line, :func:`is_numeric_line` tells a data line
from a header line.
"""

from __future__ import annotations

import math
import re
import sys
from collections.abc import Mapping, Sequence

__all__ = ["is_numeric_line", "not_a_number", "parse_values", "split_fused", "to_float"]

_NUM = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][+-]?\d+)?"
_FUSED_PIECE = re.compile(_NUM)


def to_float(token: str) -> float | None:
    """A token as a float (Fortran ``D`` exponents allowed), or None."""
    try:
        return float(token)
    except ValueError:
        pass
    if "d" in token or "D" in token:
        try:
            return float(token.replace("d", "e").replace("D", "e"))
        except ValueError:
            return None
    return None


def split_fused(token: str) -> list[float] | None:
    """Split a Fortran fixed-width run such as ``-0.123E-02-0.456E-02`` into its numbers.

    Accepted only if the pieces cover the token exactly, every piece has a decimal point
    and every piece after the first starts with a sign (the only way two numbers fuse).
    """
    pieces = [m.group(0) for m in _FUSED_PIECE.finditer(token)]
    if len(pieces) < 2 or "".join(pieces) != token:
        return None
    if any("." not in p for p in pieces) or any(p[0] not in "+-" for p in pieces[1:]):
        return None
    values = [to_float(p) for p in pieces]
    return None if any(v is None for v in values) else values  # type: ignore[return-value]


def parse_values(line: str, lineno: int, where: str,
                 columns: Mapping[int, Sequence[str]] | None = None) -> list[float]:
    """Every number on a data line.

    Parameters
    ----------
    line : str
        The data line.
    lineno : int
        Its line number in the file (1 for the first), for the messages.
    where : str
        The file, for the messages.
    columns : mapping, optional
        What the values are, by position, keyed by how many values the line holds (e.g.
        ``{2: ("time", "acceleration")}``); values on any other line are accelerations.

    Raises
    ------
    ValueError
        Naming the file, the line and the token's place on it (never its text): a token that
        is not a number, or a value
        that is not finite (NaN, infinite, or written finite but beyond the largest float,
        such as ``1e309``, which overflows to infinity when read).
    """
    tokens = line.replace(",", " ").split()
    try:
        values = [float(t) for t in tokens]
    except ValueError:
        values = []
        for k, tok in enumerate(tokens, start=1):
            v = to_float(tok)
            if v is not None:
                values.append(v)
                continue
            fused = split_fused(tok)
            if fused is None:  # the token itself is never shown: the file may be anything
                raise ValueError(f"{where}: line {lineno}: {not_a_number(k, len(tokens))}"
                                 ) from None
            values.extend(fused)
    for i, v in enumerate(values):
        if not math.isfinite(v):
            names = (columns or {}).get(len(values), ())
            what = names[i] if i < len(names) else "acceleration"
            raise ValueError(f"{where}: line {lineno}: {what} value "
                             f"{_not_finite(_pieces(tokens)[i], v)}")
    return values


def not_a_number(k: int, n: int) -> str:
    """The message for token ``k`` (from 1) of ``n`` on a line that is not a number,
    without the token itself."""
    where = "the line" if n == 1 else f"item {k} of {n} on the line"
    return f"{where} is not a number (expected numbers separated by spaces, tabs or commas)"


def _pieces(tokens: list[str]) -> list[str]:
    """The text of each number in ``tokens``: a fused run gives one piece per number."""
    out: list[str] = []
    for tok in tokens:
        out.extend([tok] if to_float(tok) is not None else
                   [m.group(0) for m in _FUSED_PIECE.finditer(tok)])
    return out


def _not_finite(text: str, value: float) -> str:
    """Why a value is not finite: NaN and infinity as Python writes them; a number written
    finite but beyond the largest float, as written, and what it reads as."""
    if text.strip().lstrip("+-").lower() in ("nan", "inf", "infinity"):
        return f"{value} is not finite"
    return (f"{text} is not finite: it is beyond the largest float "
            f"({sys.float_info.max:.3g}) and reads as {value}")


def is_numeric_line(line: str) -> bool:
    tokens = line.replace(",", " ").split()
    return bool(tokens) and all(
        to_float(t) is not None or split_fused(t) is not None for t in tokens)

"""The seats of a bridge along its axis: where each deck end rests, how wide the seat is and
the minimum width a code clause asks for it.

A row of ``n`` frames has ``n + 1`` seats, named as the outputs name them:

* ``A1`` — the left abutment's seat, under the first deck's left end;
* ``J1`` … ``J(n−1)`` — the seat at each expansion joint, between decks ``j`` and ``j + 1``;
* ``A2`` — the right abutment's seat, under the last deck's right end.

The required width comes from the bridge's clause (:mod:`pounding.structure.seat_width`).
AASHTO LRFD Art. 4.7.4.4 reads L, "the length of the bridge deck to the adjacent expansion
joint, or to the end of the bridge deck", and H, "the average height of the columns
supporting the bridge deck from the seat to the next expansion joint". Here:

* at an abutment, L is the end frame's deck length (:attr:`BridgeFrame.deck_length`, the
  sum of its spans: from the abutment to the first joint, or to the other end of a
  one-frame bridge) and H the mean height of that frame's piers
  (:attr:`BridgeFrame.mean_pier_height`);
* at a joint, the seat carries the end of one of the two decks that meet there, and the
  model does not say which: the clause is evaluated with each frame's L and H, and the
  larger requirement is taken (its L and H are the ones reported).

A clause of given widths (:class:`~pounding.structure.seat_width.GivenSeatWidths`) states
each seat's requirement as it is.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from pounding.structure.bridge.frame import BridgeFrame
from pounding.structure.seat_width import AashtoLrfdSeatClause, GivenSeatWidths, SeatClause

__all__ = ["Seat", "seat_names", "seats_of"]


@dataclass(frozen=True)
class Seat:
    """One seat of a bridge with a width to check.

    Attributes
    ----------
    name : str
        ``A1``, ``J1`` … or ``A2`` (module docstring).
    index : int
        Its place among the bridge's seats (0: ``A1``; ``n_frames``: ``A2``).
    width_m : float
        The seat width provided [m].
    required_m : float or None
        The minimum width of the clause [m] (None without a clause).
    clause : str or None
        The clause's name (None without a clause).
    deck_length_m, pier_height_m : float or None
        The L and H the clause was evaluated with [m] (None for given widths or no clause).
    """

    name: str
    index: int
    width_m: float
    required_m: float | None = None
    clause: str | None = None
    deck_length_m: float | None = None
    pier_height_m: float | None = None


def seat_names(n_frames: int) -> list[str]:
    """``["A1", "J1", …, "J(n−1)", "A2"]``: the names of the ``n_frames + 1`` seats."""
    return ["A1", *(f"J{j + 1}" for j in range(n_frames - 1)), "A2"]


def _frames_under(index: int, n_frames: int) -> list[int]:
    """The frames whose deck may rest on seat ``index``: the end frame at an abutment, the
    two that meet at a joint."""
    if index == 0:
        return [0]
    if index == n_frames:
        return [n_frames - 1]
    return [index - 1, index]


def seats_of(frames: Sequence[BridgeFrame], widths: Sequence[float | None],
             clause: SeatClause | None) -> list[Seat]:
    """Every seat with a width, with the requirement of ``clause`` (module docstring).

    Parameters
    ----------
    frames : sequence of BridgeFrame
        Left to right.
    widths : sequence of float or None
        The width of every seat [m] (``len(frames) + 1``; None: not checked).
    clause : SeatClause or None
        What the widths are checked against.

    Returns
    -------
    list of Seat
        In order ``A1``, ``J1`` …, ``A2``, those with a width only.

    Raises
    ------
    ValueError
        A frame under a checked seat has no deck length for a clause that reads it; the
        message names the frame.
    """
    names = seat_names(len(frames))
    out = []
    for i, (name, width) in enumerate(zip(names, widths)):
        if width is None:
            continue
        if clause is None:
            out.append(Seat(name, i, float(width)))
        elif isinstance(clause, GivenSeatWidths):
            out.append(Seat(name, i, float(width), clause.required[i], clause.name))
        else:
            assert isinstance(clause, AashtoLrfdSeatClause)
            best: tuple[float, float, float] | None = None
            for f in _frames_under(i, len(frames)):
                length = frames[f].deck_length
                if length is None:
                    raise ValueError(f"frames[{f}]: seat {name} is checked against "
                                     f"{clause.name}, which reads the deck's length: give "
                                     "the frame its spans")
                height = frames[f].mean_pier_height
                need = clause.required(length, height)
                if best is None or need > best[0]:
                    best = (need, length, height)
            assert best is not None
            out.append(Seat(name, i, float(width), best[0], clause.name, best[1], best[2]))
    return out

"""The seats of a bridge run: how far each joint and abutment seat opened, against its
seat width (:mod:`pounding.structure.seat_width`).

A bridge along its axis is a row of frames (:mod:`pounding.structure.bridge`), each deck one
DOF ``u_i`` relative to the ground. A seat opens when the deck end on it moves away from its
support:

* the left abutment's seat, under the first deck's left end, opens by ``u_1``;
* the seat at joint ``j`` (between decks ``j`` and ``j + 1``) opens by ``u_{j+1} − u_j``;
* the right abutment's seat, under the last deck's right end, opens by ``−u_n``.

The peak opening is the largest of these at the output steps (0 if the seat only closed);
the margin is the seat width less it (negative: the deck came off its seat,
:func:`pounding.structure.seat_width.unseating_margin`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from pounding.structure.seat_width import AASHTO_LRFD_CLAUSE, SeatCheck, check_seat

__all__ = ["seat_checks", "seat_openings"]


def _decks(result: Any) -> list[int]:
    """The global DOF of every deck, left to right (every building a bridge frame)."""
    out = []
    for off, b in zip(result.model.system.offsets, result.model.buildings):
        deck = getattr(b, "deck_dof", None)
        if deck is None:
            raise ValueError(f"seats: building {b.name!r} is not a bridge frame (a bridge's "
                             "seats are its joints and abutments)")
        out.append(int(off) + int(deck))
    return out


def seat_openings(result: Any) -> tuple[list[str], np.ndarray]:
    """The seats' names (``A1``, ``J1``, …, ``A2``) and their openings [m] (nt, n_seats)
    at the output steps (module docstring)."""
    u = result.displacement[:, _decks(result)]
    names = ["A1"] + [f"J{j + 1}" for j in range(u.shape[1] - 1)] + ["A2"]
    openings = np.column_stack([u[:, 0], np.diff(u, axis=1), -u[:, -1]])
    return names, openings


def seat_checks(result: Any, seat_widths: Sequence[float | None],
                required: Sequence[float | None],
                clause: str = AASHTO_LRFD_CLAUSE) -> list[SeatCheck]:
    """Every seat's check: its width, the minimum the clause asks, the peak opening of the
    run and the margin.

    Parameters
    ----------
    result : pounding.result.Result
        A run of a bridge (every building a :class:`~pounding.structure.bridge.BridgeFrame`).
    seat_widths : sequence of float or None
        Seat width [m] of the left abutment, each joint left to right, the right abutment
        (``n_frames + 1`` values; None: a seat not checked, e.g. a free end).
    required : sequence of float or None
        The minimum width the clause asks at each seat [m] (e.g.
        :func:`pounding.structure.seat_width.aashto_lrfd_required_support_length`), in the
        same order (None where the seat is not checked).
    clause : str
        The clause ``required`` is from.

    Returns
    -------
    list of SeatCheck
        One per seat with a width (``margin_m`` < 0: unseated).
    """
    names, openings = seat_openings(result)
    for what, values in (("seat_widths", seat_widths), ("required", required)):
        if len(values) != len(names):
            raise ValueError(f"{what}: need {len(names)} (left abutment, {len(names) - 2} "
                             f"joint(s), right abutment; None for a seat not checked), got "
                             f"{len(values)}")
    peaks = np.maximum(openings.max(axis=0), 0.0)
    out = []
    for name, width, peak, need in zip(names, seat_widths, peaks, required):
        if width is None:
            continue
        if need is None:
            raise ValueError(f"required: seat {name} has a width but no required width")
        out.append(check_seat(name, float(width), float(peak), float(need), clause))
    return out

"""The seats of a bridge run: how far each joint and abutment seat opened, against its
seat width (:mod:`pounding.structure.seat_width`).

A bridge along its axis is a row of frames (:mod:`pounding.structure.bridge`), each deck one
DOF ``u_i`` relative to the ground. A seat opens when the deck end on it moves away from its
support:

* the left abutment's seat, under the first deck's left end, opens by ``u_1``;
* the seat at joint ``j`` (between decks ``j`` and ``j + 1``) opens by ``u_{j+1} − u_j``;
* the right abutment's seat, under the last deck's right end, opens by ``−u_n``.

On spatially varying ground each deck's ground motion is added (and the abutments' own
where they stand on their own ground): the opening is between the decks' total motions.

The peak opening is the largest of these at the output steps (0 if the seat only closed);
the margin is the seat width less it (negative: the deck came off its seat,
:func:`pounding.structure.seat_width.unseating_margin`).

A model made of a :class:`~pounding.structure.bridge.Bridge` keeps it
(:attr:`pounding.model.PoundingModel.bridge`): its seat widths and clause
(:meth:`~pounding.structure.bridge.Bridge.seats`) are what :func:`seat_checks` reads by
default, and what ``summary.json`` lists under ``seats`` (:func:`seat_summary`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from pounding.structure.seat_width import AASHTO_LRFD_CLAUSE, SeatCheck, check_seat

__all__ = ["SEAT_FIELDS", "seat_checks", "seat_openings", "seat_summary"]

SEAT_FIELDS: tuple[str, ...] = (
    "name", "width_m", "required_m", "clause", "peak_opening_m", "peak_opening_time_s",
    "margin_m", "unseated", "meets_minimum", "deck_length_m", "pier_height_m")
"""The keys of each seat in ``summary.json``'s ``seats`` (:func:`seat_summary`)."""


def _decks(result: Any) -> list[int]:
    """The global DOF of every deck, left to right (every building a bridge frame, along
    the bridge's axis)."""
    model = result.model
    if getattr(model, "stops", ()) or any(g == float("inf") for g in model.gaps):
        raise ValueError("seats: a bridge across its axis has no seats to unseat from (its "
                         "shear keys: Result.shear_keys)")
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
    at the output steps (module docstring); on spatially varying ground with the grounds'
    relative displacement (``Result.building_ground``, ``Result.wall_ground``)."""
    u = result.displacement[:, _decks(result)]
    names = ["A1"] + [f"J{j + 1}" for j in range(u.shape[1] - 1)] + ["A2"]
    grounds = getattr(result, "building_ground", None)
    if grounds is None:
        return names, np.column_stack([u[:, 0], np.diff(u, axis=1), -u[:, -1]])
    # on different grounds: the decks' motion plus their grounds', against the abutments'
    # grounds (their frame's unless on their own)
    x = u + grounds[0]
    walls = getattr(result, "wall_ground", None) or {}
    left = walls["left"][0] if "left" in walls else grounds[0][:, 0]
    right = walls["right"][0] if "right" in walls else grounds[0][:, -1]
    return names, np.column_stack([x[:, 0] - left, np.diff(x, axis=1), right - x[:, -1]])


def _peaks(result: Any) -> tuple[list[str], np.ndarray, np.ndarray]:
    """The seats' names, peak openings [m] (≥ 0) and their times [s] (NaN where the seat
    never opened)."""
    names, openings = seat_openings(result)
    k = np.argmax(openings, axis=0)
    peaks = openings[k, np.arange(openings.shape[1])]
    times = np.where(peaks > 0.0, np.asarray(result.time)[k], np.nan)
    return names, np.maximum(peaks, 0.0), times


def seat_checks(result: Any, seat_widths: Sequence[float | None] | None = None,
                required: Sequence[float | None] | None = None,
                clause: str = AASHTO_LRFD_CLAUSE) -> list[SeatCheck]:
    """Every seat's check: its width, the minimum the clause asks, the peak opening of the
    run, when it peaked, and the margin.

    Parameters
    ----------
    result : pounding.result.Result
        A run of a bridge (every building a :class:`~pounding.structure.bridge.BridgeFrame`).
    seat_widths : sequence of float or None, optional
        Seat width [m] of the left abutment, each joint left to right, the right abutment
        (``n_frames + 1`` values; None: a seat not checked, e.g. a free end). Default: the
        widths and clause of the bridge the model was made of
        (:meth:`pounding.structure.bridge.Bridge.seats`; ``required`` and ``clause`` are
        then not read).
    required : sequence of float or None, optional
        With ``seat_widths``: the minimum width the clause asks at each seat [m] (e.g.
        :func:`pounding.structure.seat_width.aashto_lrfd_required_support_length`), in the
        same order (None where the seat is not checked); leave out: no clause.
    clause : str
        The clause ``required`` is from.

    Returns
    -------
    list of SeatCheck
        One per seat with a width (``margin_m`` < 0: unseated), ``A1``, ``J1`` …, ``A2``.

    Raises
    ------
    ValueError
        The model is not a bridge, or (without ``seat_widths``) was not made from a
        :class:`~pounding.structure.bridge.Bridge`; a list of the wrong length.
    """
    names, peaks, times = _peaks(result)
    if seat_widths is None:
        bridge = getattr(result.model, "bridge", None)
        if bridge is None:
            raise ValueError("seat_checks: the model was not made from a Bridge "
                             "(PoundingModel.from_bridge); give seat_widths")
        return [check_seat(s.name, s.width_m, float(peaks[s.index]), s.required_m, s.clause,
                           peak_time_s=_time(times[s.index]), deck_length_m=s.deck_length_m,
                           pier_height_m=s.pier_height_m)
                for s in bridge.seats()]
    needs = [None] * len(names) if required is None else required
    for what, values in (("seat_widths", seat_widths), ("required", needs)):
        if len(values) != len(names):
            raise ValueError(f"{what}: need {len(names)} (left abutment, {len(names) - 2} "
                             f"joint(s), right abutment; None for a seat not checked), got "
                             f"{len(values)}")
    out = []
    for i, (name, width, peak, need) in enumerate(zip(names, seat_widths, peaks, needs)):
        if width is None:
            continue
        if need is None and required is not None:
            raise ValueError(f"required: seat {name} has a width but no required width")
        out.append(check_seat(name, float(width), float(peak),
                              None if need is None else float(need), clause,
                              peak_time_s=_time(times[i])))
    return out


def _time(t: float) -> float | None:
    return None if not np.isfinite(t) else float(t)


def seat_summary(result: Any) -> list[dict[str, Any]] | None:
    """The seats of a bridge run as ``summary.json`` lists them: one dict a seat with a
    width (keys :data:`SEAT_FIELDS`: ``name``; ``width_m``, ``required_m``,
    ``peak_opening_m``, ``margin_m``, ``deck_length_m``, ``pier_height_m`` [m];
    ``peak_opening_time_s`` [s]; ``clause``; ``unseated``, ``meets_minimum``; null where
    there is no clause, or the seat never opened); None when the model is not a bridge or
    gives no seat width."""
    bridge = getattr(result.model, "bridge", None)
    if bridge is None or not bridge.seats():
        return None
    return [{"name": c.seat, "width_m": c.width_m, "required_m": c.required_m,
             "clause": c.clause, "peak_opening_m": c.peak_relative_displacement_m,
             "peak_opening_time_s": c.peak_time_s, "margin_m": c.margin_m,
             "unseated": c.unseated, "meets_minimum": c.meets_minimum,
             "deck_length_m": c.deck_length_m, "pier_height_m": c.pier_height_m}
            for c in seat_checks(result)]

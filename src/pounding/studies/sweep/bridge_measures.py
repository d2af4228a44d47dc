"""A bridge's part of a case's row: what each expansion joint, abutment and restrainer did.

A bridge along its axis (:mod:`pounding.structure.bridge`) is a row of frames, each deck one
DOF. Its seats are named as in :func:`pounding.result.bridge_seats.seat_openings`: ``A1``
(the left abutment), ``J1``, ``J2`` … (the expansion joints, left to right), ``A2`` (the
right abutment). Per seat the row holds:

* ``n_impacts_<seat>`` — impacts there (every contact element of the seat: with a bumper,
  its pad's and the decks' own), and ``peak_impact_force_N_<seat>`` — the largest force of
  any of them [N] (located inside solver steps, as ``peak_contact_force_N``); at an
  expansion joint and at an abutment with a backwall (not at a free end);
* ``peak_opening_m_<seat>`` — the peak opening of the seat [m] (the deck end moving off it:
  ``u_{j+1} − u_j`` at joint ``j``, ``u_1`` at the left abutment, ``−u_n`` at the right one;
  0 if it only closed), read at the output steps through
  :func:`~pounding.result.bridge_seats.seat_openings`: the demand the seat width is checked
  against (unseating), with the grounds' relative displacement under a spatially varying
  motion (as the closing below).
* ``peak_closing_m_<seat>`` — the largest closing of the joint [m] (``u_j − u_{j+1}``; at the
  abutments the deck end toward the backwall), located between output steps on the cubic
  Hermite interpolant of the closing and its rate
  (:func:`pounding.studies.between_steps.hermite_max`, as the gap study locates an approach). In a run where the joint's contact never acted it
  is the joint gap that run needs: with any gap above it the decks never meet there, with
  any below it they do (the run is the same up to the first impact). At a joint with
  contact it is the gap plus the largest penetration. Under a spatially varying motion the
  decks' grounds are in it (an abutment stands on the ground of the frame beside it).

Per restrainer (every link of the bridge, named as in ``summary.json``: ``R1`` across joint
1, ``R1b`` a second one there) ``peak_force_N_<name>`` — its largest |force| at the output
steps [N].

Every column is absent for a model that is not a bridge.
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

__all__ = ["BRIDGE_MEASURES", "bridge_column_key", "bridge_row", "is_bridge"]

BRIDGE_MEASURES: dict[str, str] = {
    "n_impacts": "int64",
    "peak_impact_force_N": "float64",
    "peak_opening_m": "float64",
    "peak_closing_m": "float64",
    "peak_force_N": "float64",
}
"""The bridge's columns by prefix (column → type): ``<prefix>_<seat>`` for the seats
(``A1``, ``J1`` …, ``A2``), ``peak_force_N_<restrainer>`` for the restrainers."""

_SEAT = re.compile(r"(A)(\d+)|(J)(\d+)")


def is_bridge(model: Any) -> bool:
    """Whether the model is a bridge along its axis
    (:func:`pounding.result.bridge_peaks.is_bridge`: every building a bridge frame; across
    the axis there are no seats, its keys are :attr:`Result.shear_keys`)."""
    from pounding.result.bridge_peaks import is_bridge as along_the_axis

    return along_the_axis(model)


def _seat_of(contact: Any, n_frames: int) -> str:
    """The seat a contact is at: ``J<p+1>`` between decks ``p`` and ``p + 1``, the wall's
    name at an abutment (``A1``, ``A2``)."""
    from pounding.structure.wall import WallPoint

    for point in (contact.left, contact.right):
        if isinstance(point, WallPoint):
            return str(point.name)
    return f"J{contact.pair + 1}"


def bridge_row(result: Any) -> dict[str, Any]:
    """The bridge's columns of a run (module docstring); ``{}`` for a model that is not a
    bridge."""
    model = result.model
    if not is_bridge(model):
        return {}
    from pounding.result.bridge_seats import seat_openings
    from pounding.studies.between_steps import hermite_max

    n = len(model.buildings)
    row: dict[str, Any] = {}
    counts = result.impacts_per_contact
    peaks = result.peak_contact_force
    seats: dict[str, list[int]] = {}
    for k, c in enumerate(model.contacts):
        seats.setdefault(_seat_of(c, n), []).append(k)
    names, openings = seat_openings(result)
    decks = [int(off) + int(b.deck_dof) for off, b in zip(model.system.offsets,
                                                           model.buildings)]
    u = np.asarray(result.displacement)[:, decks]
    v = np.asarray(result.velocity)[:, decks]
    ground_u, ground_v = _grounds(result, len(decks), u.shape[0])
    # the abutments' grounds (displacement, velocity): their own, or their end deck's
    own = getattr(result, "wall_ground", None) or {}
    wall_u, wall_v = {}, {}
    for seat, side, col in (("A1", "left", 0), ("A2", "right", -1)):
        wall_u[seat], wall_v[seat] = (own[side] if side in own
                                      else (ground_u[:, col], ground_v[:, col]))
    u, v = u + ground_u, v + ground_v
    walls = {w.name for w in model.walls}
    for s, name in enumerate(names):
        at = seats.get(name, [])
        if name.startswith("J") or name in walls:
            row[f"n_impacts_{name}"] = int(counts[at].sum()) if at else 0
            row[f"peak_impact_force_N_{name}"] = float(peaks[at].max()) if at else 0.0
        row[f"peak_opening_m_{name}"] = float(max(openings[:, s].max(), 0.0))
        if name == "A1":
            closing, rate = wall_u["A1"] - u[:, 0], wall_v["A1"] - v[:, 0]
        elif name == "A2":
            closing, rate = u[:, -1] - wall_u["A2"], v[:, -1] - wall_v["A2"]
        else:
            j = int(name[1:]) - 1
            closing, rate = u[:, j] - u[:, j + 1], v[:, j] - v[:, j + 1]
        if name.startswith("J") or name in walls:
            top, _ = hermite_max(closing, rate, float(result.dt))
            row[f"peak_closing_m_{name}"] = max(float(top), 0.0)
    forces = result.link_peak_force
    for link, f in zip(model.links, forces):
        row[f"peak_force_N_{link.name}"] = float(f)
    return row


def _grounds(result: Any, n: int, nt: int) -> tuple[np.ndarray, np.ndarray]:
    """Each deck's ground displacement and velocity at the output steps (n_t, n): zero
    under one record; under a spatially varying motion each frame's own, as the run
    stepped it (``Result.building_ground``), else integrated from the records
    (:func:`pounding.studies.between_steps.ground_histories`)."""
    stepped = getattr(result, "building_ground", None)
    if stepped is not None:
        return np.asarray(stepped[0]), np.asarray(stepped[1])
    from pounding.studies.between_steps import ground_histories

    grounds = ground_histories(result.motion, n, float(result.dt), nt)
    return (np.column_stack([g[0] for g in grounds]),
            np.column_stack([g[1] for g in grounds]))


def bridge_column_key(column: str) -> tuple[int, int, int, str] | None:
    """Sort key of a bridge column: measure (in :data:`BRIDGE_MEASURES` order), then the
    seat left to right (``A1``, ``J1`` …, ``A2``) or the restrainer; None for any other
    column."""
    for gi, prefix in enumerate(BRIDGE_MEASURES):
        if not column.startswith(prefix + "_"):
            continue
        rest = column[len(prefix) + 1:]
        if prefix == "peak_force_N":
            return gi, 0, 0, rest
        m = _SEAT.fullmatch(rest)
        if m is None:
            return None
        if m.group(1):  # an abutment: A1 first, A2 last
            return gi, 0 if m.group(2) == "1" else 2, 0, rest
        return gi, 1, int(m.group(4)), rest
    return None

"""A bridge run element by element: every frame's deck, pier and bearing, every joint and
abutment, every restrainer, with its peaks over the run (:attr:`pounding.result.Result.bridge`,
``summary.json``'s ``bridge`` block, the bridge tables of ``pounding run``).

A bridge along its axis is a row of frames (:mod:`pounding.structure.bridge`): each frame a
building of the row, its deck DOF ``u_i`` relative to the ground, its piers (ground → cap)
and bearings (cap → deck) its elements; the expansion joints are the gaps between the decks,
the abutments walls at the ends, the restrainers links between decks. Here:

* **frame** — the deck's peak displacement relative to the ground [m] and peak absolute
  acceleration [m/s²] (located inside solver steps, as every floor's), its periods;
* **pier** — peak drift (cap relative to the ground) [m], drift ratio (over the pier's
  height, the cap's elevation) [-], peak shear [N], residual drift, and for a yielding pier
  its ductility (peak drift over the law's yield drift ``F_y / k``);
* **bearing** — peak displacement (deck relative to the cap) [m] and force [N], residual
  displacement;
* **joint / abutment** — impacts, peak impact force [N] and its time, energy dissipated by
  its finished impacts [J], and the envelope of its relative displacement: the largest
  opening and the largest closing [m] (:func:`pounding.result.bridge_seats.seat_openings`:
  joint ``j`` opens by ``u_{j+1} − u_j``, the left abutment's seat by ``u_1``, the right's
  by ``−u_n``; closing is the opposite);
* **restrainer** — peak force [N] and its time, the largest joint opening it saw, and for a
  cable restrainer whether it yielded (the opening passed ``slack + F_y / k``,
  :attr:`pounding.devices.Link.yield_elongation`) and its plastic elongation at the end.

An element's force is its law's (or its spring's ``k d``) plus its own dashpot ``c ḋ``
(:func:`pounding.result.storey_peaks.bridge_element_histories`): the Rayleigh damping of the
frame acts on the DOFs, not in the elements. Element, seat and restrainer peaks are read at
the output steps; the deck's and the contacts' inside solver steps.
"""

from __future__ import annotations

import math

from typing import TYPE_CHECKING, Any, NamedTuple, cast

import numpy as np

from pounding.result.bridge_seats import seat_openings
from pounding.result.columns import rounded_length
from pounding.result.storey_peaks import BridgeElementPeaks, bridge_element_peaks

if TYPE_CHECKING:
    from pounding.result.response import Response
    from pounding.structure.bridge import BridgeFrame

__all__ = ["BridgeBearingPeaks", "BridgePeaks", "FramePeaks", "PierPeaks", "RestrainerPeaks",
           "SeatPeaks", "bridge_peaks", "bridge_summary", "element_law_words", "is_bridge"]


class FramePeaks(NamedTuple):
    """One frame of the bridge: its deck's peaks, its piers and bearings."""

    frame: int
    """0-based frame (building) index."""
    label: str
    """``B1``, ``B2``, … (the frame's building label)."""
    name: str
    """The frame's name (``B1`` unless given)."""
    deck: str
    """The deck's DOF label (``B1F1``)."""
    deck_mass: float
    """[kg]."""
    deck_elevation: float
    """[m]."""
    spans: tuple[float, ...] | None
    """Span lengths [m] where the frame carries them (a ``spans`` attribute; a
    ``deck_length`` alone as one span); None where it does not (a frame built from
    ``[bridge]`` today)."""
    periods: tuple[float, ...]
    """The frame's natural periods on its initial stiffness [s], longest first."""
    peak_deck_displacement: float
    """Largest |deck displacement| relative to the ground [m]."""
    peak_deck_displacement_time: float
    """When [s]."""
    peak_deck_acceleration: float
    """Largest |absolute acceleration| of the deck [m/s²]."""
    peak_deck_acceleration_time: float
    """When [s]."""
    piers: tuple[PierPeaks, ...]
    bearings: tuple[BridgeBearingPeaks, ...]


class PierPeaks(NamedTuple):
    """One pier (ground → cap)."""

    label: str
    """``B1P1``: frame 1, pier 1."""
    law: str
    """``linear`` or its law in words."""
    height: float
    """Its cap's elevation [m]."""
    stiffness: float
    """Its (initial) lateral stiffness [N/m]."""
    peak_drift: float
    """Largest |cap displacement relative to the ground| [m]."""
    peak_drift_time: float
    """When [s]."""
    peak_shear: float
    """Largest |shear| [N]."""
    peak_shear_time: float
    """When [s]."""
    residual_drift: float
    """Drift left after unloading along its law's unloading stiffness [m] (0: linear)."""
    yield_force: float
    """``F_y`` of its law [N]; NaN for a linear pier."""

    @property
    def yield_drift(self) -> float:
        """``F_y / k`` [m]; NaN for a linear pier."""
        return self.yield_force / self.stiffness

    @property
    def peak_drift_ratio(self) -> float:
        """Peak drift over the pier's height [-]."""
        return self.peak_drift / self.height

    @property
    def ductility(self) -> float:
        """Peak drift over the yield drift [-]; NaN for a linear pier (> 1: it yielded)."""
        return self.peak_drift / self.yield_drift


class BridgeBearingPeaks(NamedTuple):
    """One bearing (cap → deck)."""

    label: str
    """``B2Br1``: frame 2, bearing 1 (on pier 1)."""
    kind: str
    """``elastomeric``, ``isolator`` or ``sliding``."""
    law: str
    """``linear`` or its law in words."""
    peak_displacement: float
    """Largest |deck displacement relative to the cap| [m]."""
    peak_displacement_time: float
    """When [s]."""
    peak_force: float
    """Largest |force| [N] (spring or law, plus its dashpot)."""
    peak_force_time: float
    """When [s]."""
    residual_displacement: float
    """Displacement left after unloading along its law's unloading stiffness [m]."""
    yield_force: float
    """``F_y`` of its law [N] (a slider's friction force ``μW``); NaN for a linear
    bearing."""


class SeatPeaks(NamedTuple):
    """One expansion joint or abutment: its impacts and the envelope of its relative
    displacement (module docstring)."""

    name: str
    """``J1`` (joint between frames 1 and 2), ``A1`` (left abutment), ``A2`` (right)."""
    kind: str
    """``joint`` or ``abutment``."""
    contacts: tuple[str, ...]
    """The labels of its contacts (``B1F1-B2F1``, ``A1-B1F1``)."""
    position: int
    """Where it stands along the bridge: 0 the left abutment, ``j`` the joint after frame
    ``j`` (1-based), ``n_frames`` the right abutment."""
    gap: float
    """Gap at rest [m]; NaN at a free end (no abutment)."""
    impacts: int
    """Impacts over the run."""
    peak_force: float
    """Largest impact force [N] (0: never struck)."""
    peak_force_time: float
    """When [s] (NaN: never struck)."""
    dissipated: float
    """Energy dissipated by its finished impacts [J]."""
    peak_opening: float
    """Largest opening of the seat [m] (≥ 0; 0 if it only closed)."""
    peak_opening_time: float
    """When [s]."""
    peak_closing: float
    """Largest closing [m] (≥ 0; past the gap: the penetration of the impact)."""
    peak_closing_time: float
    """When [s]."""


class RestrainerPeaks(NamedTuple):
    """One restrainer (a link between the decks either side of a joint)."""

    name: str
    """``R1`` (across joint 1)."""
    joint: str
    """``J1``."""
    kind: str
    """``restrainer`` (cables), or the link's kind (``kelvin``, ``viscous``, ``maxwell``)."""
    law: str
    """The link in words."""
    peak_force: float
    """Largest |force| [N]."""
    peak_force_time: float
    """When [s] (NaN if it never pulled)."""
    peak_opening: float
    """Largest opening of its joint [m] (``u_right − u_left``)."""
    yield_force: float
    """A cable restrainer's yield force [N]; NaN for an elastic one or another device."""
    yield_opening: float
    """The opening at first yield ``slack + F_y / k`` [m]; NaN where there is none."""
    yielded: bool
    """True if it yielded: its plastic elongation at the end is > 0 (the opening passed
    :attr:`yield_opening`)."""
    plastic_elongation: float
    """A cable restrainer's plastic elongation at the end [m] (0: it never yielded); NaN
    for another device."""


class BridgePeaks(NamedTuple):
    """A bridge run element by element (module docstring)."""

    frames: tuple[FramePeaks, ...]
    seats: tuple[SeatPeaks, ...]
    """Left abutment, joints left to right, right abutment (an end without an abutment is
    left out)."""
    restrainers: tuple[RestrainerPeaks, ...]

    @property
    def piers(self) -> list[PierPeaks]:
        """Every pier, frame by frame."""
        return [p for f in self.frames for p in f.piers]

    @property
    def bearings(self) -> list[BridgeBearingPeaks]:
        """Every bearing, frame by frame."""
        return [b for f in self.frames for b in f.bearings]


def element_law_words(law: str, yield_force: float | None, kind: str) -> str:
    """A pier's or bearing's law in a few words for a table: ``linear``, ``bilinear, F_y
    2000 kN``, ``friction μW 600.2 kN`` (a sliding bearing); forces in kN, MN from 100 MN.

    Parameters
    ----------
    law : str
        Its law as :attr:`PierPeaks.law` gives it (``linear`` or ``name(constants)``).
    yield_force : float or None
        Its law's ``F_y`` [N] (None or NaN: linear).
    kind : str
        ``pier`` or the bearing's kind (``elastomeric``, ``isolator``, ``sliding``).
    """
    if yield_force is None or not np.isfinite(yield_force):
        return "linear"
    factor, unit = (1e-6, "MN") if abs(yield_force) >= 1e8 else (1e-3, "kN")
    value = f"{yield_force * factor:.4g} {unit}"
    if kind == "sliding":
        return f"friction μW {value}"
    return f"{law.split('(')[0]}, F_y {value}"


def is_bridge(model: Any) -> bool:
    """True if every building of ``model`` is a bridge frame
    (:class:`~pounding.structure.bridge.BridgeFrame`) of a bridge along its axis (across it
    the frames never meet and shear keys hold them: :attr:`Result.shear_keys`)."""
    from pounding.structure.matrices import MatrixBuilding

    across = bool(getattr(model, "stops", ())) or any(g == math.inf for g in model.gaps)
    if across or not model.buildings or not all(isinstance(b, MatrixBuilding)
                                                for b in model.buildings):
        return False  # (a bridge frame is a matrix building: shear buildings need no import)
    from pounding.structure.bridge import BridgeFrame

    return all(isinstance(b, BridgeFrame) for b in model.buildings)


def _argmax(values: np.ndarray, time: np.ndarray) -> tuple[float, float]:
    """The largest value (≥ 0) and its time; ``(0, nan)`` if it never exceeds 0."""
    k = int(np.argmax(values))
    return (float(values[k]), float(time[k])) if values[k] > 0 else (0.0, float("nan"))


def _frames(result: Response) -> list[FramePeaks]:
    model = result.model
    elements: dict[str, BridgeElementPeaks] = {e.label: e for e in bridge_element_peaks(result)}
    labels = model.dof_labels()
    out = []
    frames = cast("list[BridgeFrame]", list(model.buildings))  # (is_bridge: all frames)
    for p, (off, bl) in enumerate(zip(model.system.offsets, frames)):
        piers, bearings = [], []
        for label, kind, _, _, k, law, _ in bl.elements():
            e = elements[f"B{p + 1}{label}"]
            fy = float(law.yield_forces([k])[0]) if law is not None else float("nan")
            if kind == "pier":
                piers.append(PierPeaks(e.label, e.law, e.height, float(k), e.peak_deformation,
                                       e.peak_deformation_time, e.peak_force,
                                       e.peak_force_time, e.residual_deformation, fy))
            else:
                bearings.append(BridgeBearingPeaks(
                    e.label, e.kind, e.law, e.peak_deformation, e.peak_deformation_time,
                    e.peak_force, e.peak_force_time, e.residual_deformation, fy))
        i = int(off) + bl.deck_dof
        # its spans where the frame keeps them (else its deck length as one "span")
        length = getattr(bl, "deck_length", None)
        spans = getattr(bl, "spans", None) or ([length] if length else None)
        out.append(FramePeaks(
            p, f"B{p + 1}", bl.name or f"B{p + 1}", labels[i], float(bl.deck_mass),
            float(bl.elevations[bl.deck_dof]),
            tuple(float(s) for s in spans) if spans else None,
            tuple(float(t) for t in bl.modes().periods),
            float(result.peak_displacement[i]), float(result.peak_displacement_time[i]),
            float(result.peak_abs_acceleration[i]),
            float(result.peak_abs_acceleration_time[i]), tuple(piers), tuple(bearings)))
    return out


def _seats(result: Response) -> list[SeatPeaks]:
    model = result.model
    n = len(model.buildings)
    names, openings = seat_openings(result)  # A1, J1 … J(n−1), A2
    t = result.time
    by_position: dict[int, list[Any]] = {}
    for c in model.contacts:
        position = 0 if (c.on_wall and c.pair < 0) else (n if c.on_wall else c.pair + 1)
        by_position.setdefault(position, []).append(c)
    count, pcf = result.impacts_per_contact, result.peak_contact_force
    pcf_t, diss = result.peak_contact_force_time, result.dissipated_per_contact
    out = []
    for position, name in enumerate(names):
        contacts = by_position.get(position, [])
        if name.startswith("A") and not contacts:
            continue  # a free end
        idx = [c.index for c in contacts]
        main = [c for c in contacts if not c.tag] or contacts
        gap = float(main[0].gap) if main else float("nan")
        if idx and pcf[idx].max() > 0:
            k = idx[int(np.argmax(pcf[idx]))]
            force, force_t = float(pcf[k]), float(pcf_t[k])
        else:
            force, force_t = 0.0, float("nan")
        rel = openings[:, position]
        opening, opening_t = _argmax(rel, t)
        closing, closing_t = _argmax(-rel, t)
        out.append(SeatPeaks(
            name, "abutment" if name.startswith("A") else "joint",
            tuple(c.label for c in contacts), position, gap, int(count[idx].sum()),
            force, force_t, float(diss[idx].sum()), opening, opening_t, closing, closing_t))
    return out


def _restrainers(result: Response) -> list[RestrainerPeaks]:
    model = result.model
    links = model.links
    if not links:
        return []
    t = result.time
    force = result.link_force if result.link_force is not None else np.zeros((t.size,
                                                                            len(links)))
    opening = result.link_displacement
    z = result.final_z if result.final_z is not None else np.zeros(0)
    z_links = z[z.size - sum(lk.has_internal_variable for lk in links):]
    buildings = {f"B{p + 1}": p for p in range(len(model.buildings))}
    out = []
    iz = 0
    for i, link in enumerate(links):
        f_peak, f_t = _argmax(np.abs(force[:, i]), t)
        left = link.floors[0]
        p = next((q for b, q in buildings.items() if left.startswith(b + "F")), 0)
        plastic = float("nan")
        if link.has_internal_variable:
            if link.kind == "restrainer":
                plastic = float(z_links[iz]) if iz < z_links.size else float("nan")
            iz += 1
        cable = link.kind == "restrainer"
        fy = float(link.yield_force) if cable and link.yield_force is not None else float("nan")
        y_open = float(link.yield_elongation) if cable else float("nan")
        peak_open = float(max(opening[:, i].max(), 0.0))
        y_open = y_open if np.isfinite(y_open) else float("nan")
        # yielded: its plastic elongation grew (exact, at the solver's steps); without it
        # the opening at the output steps passed the first-yield opening
        yielded = (plastic > 0.0 if np.isfinite(plastic)
                   else bool(np.isfinite(y_open) and peak_open > y_open))
        out.append(RestrainerPeaks(
            link.name, f"J{p + 1}", link.kind, link.readable().split(": ", 1)[-1],
            f_peak, f_t, peak_open, fy, y_open, bool(yielded),
            plastic if cable else float("nan")))
    return out


def bridge_peaks(result: Response) -> BridgePeaks | None:
    """The frames, seats and restrainers of a bridge run with their peaks (module
    docstring); None unless every building of the model is a bridge frame."""
    if not is_bridge(result.model):
        return None
    return BridgePeaks(tuple(_frames(result)), tuple(_seats(result)),
                       tuple(_restrainers(result)))


def _time(value: float) -> float | None:
    return None if not np.isfinite(value) else float(value)


def bridge_summary(result: Response) -> dict[str, Any]:
    """``bridge``: the bridge's elements with their peaks (units in the key names, as the
    rest of ``summary.json``): ``frames`` (each with its ``piers`` and ``bearings``),
    ``joints``, ``abutments`` and ``restrainers``; empty for a model that is no bridge."""
    bp = bridge_peaks(result)
    if bp is None:
        return {}
    frames = []
    for f in bp.frames:
        frames.append({
            "frame": f.label, "name": f.name, "deck": f.deck, "deck_mass_kg": f.deck_mass,
            "deck_elevation_m": rounded_length(f.deck_elevation),
            **({"spans_m": list(f.spans)} if f.spans else {}),
            "periods_s": list(f.periods),
            "peak_deck_displacement_m": f.peak_deck_displacement,
            "peak_deck_displacement_time_s": f.peak_deck_displacement_time,
            "peak_deck_acceleration_m_s2": f.peak_deck_acceleration,
            "peak_deck_acceleration_time_s": f.peak_deck_acceleration_time,
            "piers": [{"pier": p.label, "law": p.law, "height_m": rounded_length(p.height),
                       "stiffness_N_m": p.stiffness, "peak_drift_m": p.peak_drift,
                       "peak_drift_time_s": p.peak_drift_time,
                       "peak_drift_ratio": p.peak_drift_ratio, "peak_shear_N": p.peak_shear,
                       "peak_shear_time_s": p.peak_shear_time,
                       "residual_drift_m": p.residual_drift,
                       "yield_force_N": p.yield_force if np.isfinite(p.yield_force) else None,
                       "ductility": p.ductility if np.isfinite(p.ductility) else None}
                      for p in f.piers],
            "bearings": [{"bearing": b.label, "kind": b.kind, "law": b.law,
                          "peak_displacement_m": b.peak_displacement,
                          "peak_displacement_time_s": b.peak_displacement_time,
                          "peak_force_N": b.peak_force, "peak_force_time_s": b.peak_force_time,
                          "residual_displacement_m": b.residual_displacement,
                          "yield_force_N": (b.yield_force if np.isfinite(b.yield_force)
                                            else None)}
                         for b in f.bearings]})

    def seat(s: SeatPeaks) -> dict[str, Any]:
        return {("joint" if s.kind == "joint" else "abutment"): s.name,
                "contacts": list(s.contacts), "gap_m": s.gap, "impacts": s.impacts,
                "peak_impact_force_N": s.peak_force,
                "peak_impact_force_time_s": _time(s.peak_force_time),
                "impact_dissipated_J": s.dissipated,
                "peak_opening_m": s.peak_opening,
                "peak_opening_time_s": _time(s.peak_opening_time),
                "peak_closing_m": s.peak_closing,
                "peak_closing_time_s": _time(s.peak_closing_time)}

    return {"bridge": {
        "frames": frames,
        "joints": [seat(s) for s in bp.seats if s.kind == "joint"],
        "abutments": [seat(s) for s in bp.seats if s.kind == "abutment"],
        "restrainers": [{"restrainer": r.name, "joint": r.joint, "kind": r.kind, "law": r.law,
                         "peak_force_N": r.peak_force,
                         "peak_force_time_s": _time(r.peak_force_time),
                         "peak_opening_m": r.peak_opening,
                         **({"yield_force_N": r.yield_force,
                             "yield_opening_m": r.yield_opening,
                             "yielded": r.yielded,
                             "plastic_elongation_m": r.plastic_elongation}
                            if r.kind == "restrainer" else {})}
                        for r in bp.restrainers],
        "notes": "deck peaks located inside solver steps, as every floor's; pier, bearing, "
                 "seat and restrainer peaks at the output steps; openings: joint j "
                 "u_(j+1) − u_j, left abutment u_1, right abutment −u_n (closing: the "
                 "opposite); an element's force is its law's or spring's plus its own "
                 "dashpot (the frames' Rayleigh damping acts on the DOFs)"}}

"""The tables `pounding run` prints for a bridge (:mod:`pounding.structure.bridge`), in place
of the buildings' storey tables: its frames, piers, bearings, joints and abutments, and
restrainers (:attr:`pounding.result.Result.bridge`).

Units as the other run tables: displacements, drifts, gaps and openings in mm, forces in kN
(MN when they reach 100 MN), energies in kJ (MJ), masses in t, elevations and heights in m.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from pounding.cli.app import console
from pounding.cli.tables import Col, building_label, number, print_table
from pounding.result.bridge_peaks import element_law_words

__all__ = ["bridge_forces", "print_bridge_tables"]


def _t(value: float) -> str:
    """A time [s]: three decimals; ``–`` for NaN."""
    return "–" if not np.isfinite(value) else f"{value:.3f}"


def _mm(value: float) -> str:
    return number(1e3 * value)


def bridge_forces(bridge: Any) -> list[float]:
    """Every peak force of the bridge's tables [N] (to choose their one force unit)."""
    return [*(p.peak_shear for p in bridge.piers), *(b.peak_force for b in bridge.bearings),
            *(s.peak_force for s in bridge.seats), *(r.peak_force for r in bridge.restrainers)]


def print_bridge_tables(r: Any, units: tuple[float, str, float, str]) -> None:
    """Print the bridge's tables of the result ``r`` (every building a bridge frame);
    ``units`` the run's ``(force factor, force unit, energy factor, energy unit)``."""
    bridge = r.bridge
    _print_frames(r, bridge)
    _print_piers(bridge, units)
    _print_bearings(bridge, units)
    _print_seats(r, bridge, units)
    _print_restrainers(r, bridge, units)


def _print_frames(r: Any, bridge: Any) -> None:
    cols = [Col("frame", "left", wrap=True), Col("deck mass [t]"), Col("deck at [m]"),
            Col("piers"), Col("T1, T2 [s]", wrap=True), Col("peak deck displacement [mm]"),
            Col("at t [s]"), Col("peak deck acceleration [m/s²]"), Col("at t [s]")]
    rows = [[building_label(f.frame, f.name), number(1e-3 * f.deck_mass), f"{f.deck_elevation:g}",
             str(len(f.piers)), ", ".join(f"{t:.3f}" for t in f.periods[:2]),
             _mm(f.peak_deck_displacement), _t(f.peak_deck_displacement_time),
             number(f.peak_deck_acceleration), _t(f.peak_deck_acceleration_time)]
            for f in bridge.frames]
    print_table(console, "Bridge frames: decks (peaks located inside solver steps)", cols, rows,
                caption="displacement relative to the ground; periods on the frame's initial "
                        "stiffness (a slider's stick stiffness)")


def _print_piers(bridge: Any, units: tuple[float, str, float, str]) -> None:
    ff, fu, _, _ = units
    cols = [Col("pier", "left"), Col("law", "left", wrap=True), Col("height [m]"),
            Col("stiffness [kN/mm]"), Col("peak drift [mm]"), Col("drift ratio [%]"),
            Col("at t [s]"), Col(f"peak shear [{fu}]"), Col("at t [s]"), Col("ductility"),
            Col("residual drift [mm]")]
    rows = [[p.label, element_law_words(p.law, p.yield_force, "pier"), f"{p.height:g}",
             number(1e-6 * p.stiffness), _mm(p.peak_drift),
             number(100 * p.peak_drift_ratio, 3), _t(p.peak_drift_time),
             number(p.peak_shear * ff), _t(p.peak_shear_time),
             number(p.ductility, 3) if np.isfinite(p.ductility) else "–",
             f"{1e3 * p.residual_drift:+.2f}"] for p in bridge.piers]
    print_table(console, "Piers: drift (cap relative to the ground) and shear", cols, rows,
                keys=1, caption="drift ratio over the pier's height; ductility: peak drift over "
                                "the law's yield drift F_y/k (– linear)")


def _print_bearings(bridge: Any, units: tuple[float, str, float, str]) -> None:
    ff, fu, _, _ = units
    cols = [Col("bearing", "left"), Col("kind", "left"), Col("law", "left", wrap=True),
            Col("peak displacement [mm]"), Col("at t [s]"), Col(f"peak force [{fu}]"),
            Col("at t [s]"), Col("residual displacement [mm]")]
    rows = [[b.label, b.kind, element_law_words(b.law, b.yield_force, b.kind),
             _mm(b.peak_displacement), _t(b.peak_displacement_time),
             number(b.peak_force * ff), _t(b.peak_force_time),
             f"{1e3 * b.residual_displacement:+.2f}"] for b in bridge.bearings]
    print_table(console, "Bearings: deck relative to the pier cap", cols, rows, keys=1,
                caption="force: the bearing's law or spring plus its own dashpot")


def _print_seats(r: Any, bridge: Any, units: tuple[float, str, float, str]) -> None:
    ff, fu, ef, eu = units
    if not bridge.seats:
        return
    n = len(bridge.frames)
    cols = [Col("joint / abutment", "left", wrap=True), Col("between", "left", wrap=True),
            Col("gap [mm]"),
            Col("impacts"), Col(f"peak impact force [{fu}]"), Col("at t [s]"),
            Col(f"dissipated [{eu}]"), Col("max opening [mm]"), Col("at t [s]"),
            Col("max closing [mm]"), Col("at t [s]")]
    rows = []
    for s in bridge.seats:
        if s.kind == "joint":
            between = f"B{s.position} – B{s.position + 1}"
        else:
            between = "abutment – B1" if s.position == 0 else f"B{n} – abutment"
        hit = s.impacts > 0
        rows.append([s.name, between, number(1e3 * s.gap), str(s.impacts),
                     number(s.peak_force * ff) if hit else "–",
                     _t(s.peak_force_time) if hit else "–",
                     number(s.dissipated * ef) if hit else "–", _mm(s.peak_opening),
                     _t(s.peak_opening_time), _mm(s.peak_closing), _t(s.peak_closing_time)])
    print_table(console, "Joints and abutments: impacts and relative displacement", cols, rows,
                keys=1, caption="opening: the deck moving off its seat (joint j: u_(j+1) − u_j; "
                                "A1: u_1; A2: −u_n), closing the opposite, past the gap by the "
                                "impact's penetration; dissipated: finished impacts")


def _print_restrainers(r: Any, bridge: Any, units: tuple[float, str, float, str]) -> None:
    ff, fu, ef, eu = units
    if not bridge.restrainers:
        return
    dissipated = dict(zip((lk.name for lk in r.model.links), r.link_dissipated))
    cols = [Col("restrainer", "left"), Col("joint", "left"), Col("law", "left", wrap=True),
            Col(f"peak force [{fu}]"), Col("at t [s]"), Col("peak opening [mm]"),
            Col("yield opening [mm]"), Col("yielded", "left"),
            Col("plastic elongation [mm]"), Col(f"dissipated [{eu}]")]
    rows = []
    for x in bridge.restrainers:
        cable = x.kind == "restrainer"
        rows.append([x.name, x.joint, x.law, number(x.peak_force * ff), _t(x.peak_force_time),
                     _mm(x.peak_opening),
                     _mm(x.yield_opening) if np.isfinite(x.yield_opening) else "–",
                     ("yes" if x.yielded else "no") if cable else "–",
                     _mm(x.plastic_elongation) if cable and np.isfinite(x.plastic_elongation)
                     else "–", number(dissipated.get(x.name, float("nan")) * ef)])
    print_table(console, "Restrainers across the joints", cols, rows, keys=1,
                caption="yield opening: slack + F_y/k (– elastic cables or another device)")

"""The Bridge section of the run page: for a run of a bridge (``summary.json`` has its
``bridge`` block, :func:`pounding.result.bridge_peaks.bridge_summary`), its elevation
figure, its frames, piers, bearings, joints and abutments, restrainers, where the energy
went, and the seat margins (``summary.json``'s ``seats``, when the run checked its seats).

Units as the printed tables: mm, kN, kJ, t, m, s.
"""

from __future__ import annotations

import math
from typing import Any

from pounding.report.format import Block, Figure, Note, Table, kv_table, png_bytes
from pounding.report.run_folder import RunFolder
from pounding.result.bridge_peaks import element_law_words, is_bridge

__all__ = ["BRIDGE_FIGURE", "bridge_model_tables", "bridge_section"]

BRIDGE_FIGURE = "bridge_figure"
"""The key of the elevation figure (:data:`pounding.plot.registry.RUN_FIGURES`): the
Bridge section shows it, the Figures section leaves it out."""


def _f(value: Any, factor: float = 1.0) -> float:
    """``value`` × ``factor`` as a float, whole from 1000 on (``23592``, not ``2.359e+04``:
    a cell shows four significant digits); NaN (shown as –) for None or text."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return float("nan")
    v = float(value) * factor
    return float(round(v)) if math.isfinite(v) and abs(v) >= 1000.0 else v


def bridge_section(r: RunFolder) -> list[Block]:
    """The Bridge section's blocks (module docstring); empty for a run of buildings."""
    bridge = r.summary.get("bridge")
    if not isinstance(bridge, dict):
        return []
    seats = [s for s in (r.summary.get("seats") or []) if isinstance(s, dict)]
    out: list[Block] = [*_elevation(r, seats)]
    out += [_frames(bridge), _piers(bridge), _bearings(bridge), _joints(bridge)]
    if bridge.get("restrainers"):
        out.append(_restrainers(bridge))
    out.append(_energy(r.summary, bridge))
    out += _seats(seats)
    return out


def _elevation(r: RunFolder, seats: list[dict[str, Any]]) -> list[Block]:
    """The elevation figure: drawn again with the seat widths of ``seats`` where there are
    some and the results can be reloaded; else the folder's ``bridge.png``; else
    regenerated; else a warning."""
    from pounding.plot.registry import RUN_FIGURES

    fig = RUN_FIGURES[BRIDGE_FIGURE]
    widths = {str(s.get("name")): float(s["width_m"]) for s in seats
              if isinstance(s.get("width_m"), (int, float))}
    path = r.folder / fig.file
    why_not = r.build_error or "the model is unknown"
    if r.built is not None and (widths or not path.is_file()):
        from pounding.plot.bridge import plot_bridge_elevation
        from pounding.report.run_figures import result_from

        try:
            result = result_from(r)
        except (ValueError, KeyError) as exc:
            why_not = f"the results could not be reloaded ({exc})"
        else:
            how = ("drawn with the seat widths of summary.json's seats" if widths else
                   f"regenerated from timehistories.nc: {fig.file} is not in the folder")
            return [Figure(png_bytes(plot_bridge_elevation(result, seat_widths=widths)),
                           fig.caption, f"{fig.caption} ({how}).")]
    if path.is_file():
        return [Figure(path.read_bytes(), fig.caption, f"{fig.caption} ({fig.file} of the "
                                                       "run).")]
    return [Note(f"{fig.caption}: {fig.file} is not in the folder and could not be "
                 f"regenerated: {why_not}.", "warn")]


def _frames(bridge: dict[str, Any]) -> Table:
    t = Table(("frame", "deck mass [t]", "deck at [m]", "piers", "T1 [s]", "T2 [s]",
               "peak deck displacement [mm]", "at t [s]", "peak deck acceleration [m/s²]"),
              caption="Frames: each deck's peak displacement relative to the ground (located "
                      "inside solver steps) and absolute acceleration; periods on the frame's "
                      "initial stiffness")
    for f in bridge.get("frames", []):
        periods = list(f.get("periods_s") or []) + [None, None]
        name = str(f.get("name") or "")
        label = str(f.get("frame")) + (f" ({name})" if name and name != f.get("frame") else "")
        t.add(label, _f(f.get("deck_mass_kg"), 1e-3), _f(f.get("deck_elevation_m")),
              len(f.get("piers") or []), _f(periods[0]), _f(periods[1]),
              _f(f.get("peak_deck_displacement_m"), 1e3),
              _f(f.get("peak_deck_displacement_time_s")),
              _f(f.get("peak_deck_acceleration_m_s2")))
    return t


def _piers(bridge: dict[str, Any]) -> Table:
    t = Table(("pier", "law", "height [m]", "stiffness [kN/mm]", "peak drift [mm]",
               "drift ratio [%]", "at t [s]", "peak shear [kN]", "at t [s]", "ductility [-]",
               "residual drift [mm]"),
              caption="Piers: drift of the cap relative to the ground, shear; drift ratio over "
                      "the pier's height; ductility: peak drift over the law's yield drift "
                      "F_y/k (– linear); residual drift after unloading along the law")
    for f in bridge.get("frames", []):
        for p in f.get("piers", []):
            fy = p.get("yield_force_N")
            t.add(str(p.get("pier")), element_law_words(str(p.get("law")), _f(fy), "pier"),
                  _f(p.get("height_m")), _f(p.get("stiffness_N_m"), 1e-6),
                  _f(p.get("peak_drift_m"), 1e3), _f(p.get("peak_drift_ratio"), 100.0),
                  _f(p.get("peak_drift_time_s")), _f(p.get("peak_shear_N"), 1e-3),
                  _f(p.get("peak_shear_time_s")), _f(p.get("ductility")),
                  _f(p.get("residual_drift_m"), 1e3))
    return t


def _bearings(bridge: dict[str, Any]) -> Table:
    t = Table(("bearing", "kind", "law", "peak displacement [mm]", "at t [s]",
               "peak force [kN]", "at t [s]", "residual displacement [mm]"),
              caption="Bearings: the deck relative to the pier cap; force of the bearing's law "
                      "or spring plus its own dashpot")
    for f in bridge.get("frames", []):
        for b in f.get("bearings", []):
            kind = str(b.get("kind"))
            t.add(str(b.get("bearing")), kind,
                  element_law_words(str(b.get("law")), _f(b.get("yield_force_N")), kind),
                  _f(b.get("peak_displacement_m"), 1e3), _f(b.get("peak_displacement_time_s")),
                  _f(b.get("peak_force_N"), 1e-3), _f(b.get("peak_force_time_s")),
                  _f(b.get("residual_displacement_m"), 1e3))
    return t


def _joints(bridge: dict[str, Any]) -> Table:
    t = Table(("joint / abutment", "contacts", "gap [mm]", "impacts", "peak impact force [kN]",
               "at t [s]", "dissipated [kJ]", "largest opening [mm]", "at t [s]",
               "largest closing [mm]", "at t [s]"),
              caption="Joints and abutments: impacts, and the envelope of the relative "
                      "displacement at the seat (opening: the deck moving off its seat — joint "
                      "j u_(j+1) − u_j, left abutment u_1, right abutment −u_n; closing the "
                      "opposite, past the gap by the impact's penetration); dissipated: "
                      "finished impacts")
    abutments = {str(s.get("abutment")): s for s in bridge.get("abutments", [])}
    rows = ([("abutment", abutments[a]) for a in ("A1",) if a in abutments]
            + [("joint", s) for s in bridge.get("joints", [])]
            + [("abutment", abutments[a]) for a in ("A2",) if a in abutments])
    for key, s in rows:
        t.add(str(s.get(key)), ", ".join(s.get("contacts") or []), _f(s.get("gap_m"), 1e3),
              s.get("impacts"), _f(s.get("peak_impact_force_N"), 1e-3),
              _f(s.get("peak_impact_force_time_s")), _f(s.get("impact_dissipated_J"), 1e-3),
              _f(s.get("peak_opening_m"), 1e3), _f(s.get("peak_opening_time_s")),
              _f(s.get("peak_closing_m"), 1e3), _f(s.get("peak_closing_time_s")))
    return t


def _restrainers(bridge: dict[str, Any]) -> Table:
    t = Table(("restrainer", "joint", "law", "peak force [kN]", "at t [s]",
               "largest opening [mm]", "yield opening [mm]", "yielded",
               "plastic elongation [mm]"),
              caption="Restrainers across the joints: yield opening slack + F_y/k (– elastic "
                      "cables or another device)")
    for x in bridge.get("restrainers", []):
        yielded = x.get("yielded")
        t.add(str(x.get("restrainer")), str(x.get("joint")), str(x.get("law")),
              _f(x.get("peak_force_N"), 1e-3), _f(x.get("peak_force_time_s")),
              _f(x.get("peak_opening_m"), 1e3), _f(x.get("yield_opening_m"), 1e3),
              "–" if yielded is None else ("yes" if yielded else "no"),
              _f(x.get("plastic_elongation_m"), 1e3))
    return t


def _energy(summary: dict[str, Any], bridge: dict[str, Any]) -> Table:
    """Where the input energy went, in the bridge's terms."""
    fin = summary.get("energy_final_J") or {}
    joints = sum(_f(s.get("impact_dissipated_J")) for s in bridge.get("joints", []))
    abutments = sum(_f(s.get("impact_dissipated_J")) for s in bridge.get("abutments", []))
    items = [("input [kJ]", _f(fin.get("input"), 1e-3)),
             ("dissipated at the joints' impacts [kJ]", joints * 1e-3),
             ("dissipated at the abutments' impacts [kJ]", abutments * 1e-3),
             ("dissipated in all contacts (open impacts too) [kJ]",
              _f(summary.get("contact_dissipated_J"), 1e-3)),
             ("hysteretic: yielding piers and bearings [kJ]", _f(fin.get("hysteretic"), 1e-3)),
             ("dissipated by the restrainers [kJ]", _f(summary.get("links_dissipated_J"), 1e-3)
              if bridge.get("restrainers") else 0.0),
             ("structural damping [kJ]", _f(fin.get("damping"), 1e-3)),
             ("still in motion (kinetic + strain) [kJ]",
              _f(fin.get("kinetic"), 1e-3) + _f(fin.get("strain"), 1e-3)),
             ("energy-balance error [of peak input]", summary.get("energy_balance_error"))]
    return kv_table(items, caption="Where the energy went (final values; the Energy balance "
                                   "section has every term)")


def _seats(seats: list[dict[str, Any]]) -> list[Block]:
    """The seat margins of ``summary.json``'s ``seats`` (when the run checked them)."""
    if not seats:
        return [Note("Seat margins: not checked in this run (summary.json has no seats: no "
                     "seat widths given).")]
    t = Table(("seat", "seat width [mm]", "required [mm]", "clause", "peak opening [mm]",
               "margin [mm]", "unseated"),
              caption="Seats: width against the clause's minimum, and the margin the run left "
                      "(width − peak opening; negative: the deck came off its seat)")
    unseated = []
    short = []
    for s in seats:
        name = str(s.get("name"))
        if s.get("unseated"):
            unseated.append(name)
        width, need = _f(s.get("width_m")), _f(s.get("required_m"))
        if math.isfinite(width) and math.isfinite(need) and width < need:
            short.append(name)
        t.add(name, width * 1e3, need * 1e3, str(s.get("clause") or "–"),
              _f(s.get("peak_opening_m"), 1e3), _f(s.get("margin_m"), 1e3),
              "–" if s.get("unseated") is None else ("yes" if s.get("unseated") else "no"))
    out: list[Block] = [t]
    if unseated:
        out.append(Note(f"Unseated: {', '.join(unseated)} (the peak opening passed the seat "
                        "width).", "warn"))
    if short:
        out.append(Note(f"Narrower than the clause's minimum: {', '.join(short)}.", "warn"))
    return out


def bridge_model_tables(model: Any) -> list[Block]:
    """The Model section's tables of a bridge (every building a bridge frame), in place of
    the buildings' storeys: each frame's deck, piers and bearings, and the restrainers;
    empty for a model of buildings."""
    if not is_bridge(model):
        return []
    t = Table(("frame", "deck mass [t]", "deck at [m]", "element", "height [m]",
               "stiffness [kN/mm]", "law", "dashpot [kN·s/m]", "T1, T2 [s]", "damping"),
              caption="Frames, left to right: the deck on its piers (ground → cap) through its "
                      "bearings (cap → deck); stiffness the initial one; periods on it")
    for p, frame in enumerate(model.buildings):
        periods = ", ".join(f"{x:.3f}" for x in frame.modes().periods[:2])
        damping = (f"Rayleigh ζ = {frame.zeta:g} at modes 1, 2 (on the linear elements) "
                   "+ the bearings' dashpots")
        for k, (label, kind, lo, hi, stiffness, law, c) in enumerate(frame.elements()):
            fy = float(law.yield_forces([stiffness])[0]) if law is not None else None
            first = k == 0
            t.add(f"B{p + 1}" if first else "", _f(frame.deck_mass, 1e-3) if first else "",
                  _f(float(frame.elevations[frame.deck_dof])) if first else "",
                  f"B{p + 1}{label} ({kind})",
                  _f(float(frame.elevations[hi])) if kind == "pier" else "",
                  _f(stiffness, 1e-6),
                  element_law_words(law.describe() if law is not None else "linear", fy,
                                    kind),
                  _f(c, 1e-3) if c else "", periods if first else "",
                  damping if first else "")
    out: list[Block] = [t]
    if model.links:
        r = Table(("restrainer", "between", "law"), caption="Restrainers across the joints")
        for link in model.links:
            r.add(link.name, " – ".join(link.floors), link.readable().split(": ", 1)[-1])
        out.append(r)
    return out

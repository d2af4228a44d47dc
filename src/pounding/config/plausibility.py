"""Plausibility checks of a model file: valid inputs that are probably in the wrong unit.

Each check compares one input (or what follows from it: the fundamental period, the peak
ground acceleration after scaling) with the range real buildings and records fall in, and
returns one line naming the key, the value and the probable mistake. The thresholds are
far outside engineering practice on purpose, so that a model of a real building never
trips them, while a factor of 1000 (kg for tonnes, m for mm) or 100 (m/s² for cm/s²) does.
They are warnings (:class:`pounding.plausibility.PlausibilityWarning`), not errors: a
teaching model may be small on purpose.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from pounding.config.base import fmt

if TYPE_CHECKING:
    from pounding.config.run import Built, RunConfig

__all__ = ["MAX_PLAUSIBLE_GAP", "MAX_PLAUSIBLE_SEAT_WIDTH", "MIN_PLAUSIBLE_FLOOR_MASS", "MIN_PLAUSIBLE_PERIOD",
           "MAX_PLAUSIBLE_PERIOD", "MAX_PLAUSIBLE_PGA_G", "MAX_PLAUSIBLE_FRICTION",
           "plausibility_warnings"]

MAX_PLAUSIBLE_GAP = 2.0
"""Widest plausible gap between neighbours (or to a moat wall) [m].

Codes ask for separations of the order of the buildings' peak displacements: ASCE 7-22
§12.12.2 combines the two buildings' inelastic displacements, Eurocode 8 §4.4.2.7 their
SRSS, giving centimetres for low-rise buildings and tens of centimetres for tall ones; a
moat is as wide as the isolators' displacement capacity (0.2–1 m). Above 2 m the number
is most likely millimetres or centimetres written as metres (``gap = 40`` for 40 mm)."""

MAX_PLAUSIBLE_SEAT_WIDTH = 3.0
"""Widest plausible seat of a bridge deck at a joint or an abutment [m].

Seats are a few tenths of a metre to a little over one: AASHTO LRFD Art. 4.7.4.4's
empirical N = (8 + 0.02 L + 0.08 H) in is 0.90 m for a 300 m deck on 30 m columns, and its
highest-zone minimum, 150 % of N, 1.35 m (pounding.structure.seat_width). Above 3 m the number is most likely millimetres or
centimetres written as metres (``seat_width = 600`` for 600 mm)."""

MIN_PLAUSIBLE_FLOOR_MASS = 1000.0
"""Lightest plausible floor (or base slab) [kg].

A floor with its share of walls and contents weighs 0.5–1.5 t per square metre of floor
area (e.g. FEMA P-695 archetypes; ASCE 7 dead plus seismic live load), so a real floor
weighs tens to thousands of tonnes; 1000 kg is a floor of one or two square metres. A
smaller mass is most likely tonnes written as kilograms (``mass = 600`` for 600 t)."""

MIN_PLAUSIBLE_PERIOD = 0.05
"""Shortest plausible fundamental period [s].

T1 ≈ 0.1 s per storey (ASCE 7-22 Table 12.8-2, ``T_a = C_t h^x``): a stiff one-storey
masonry building has about 0.1 s. A mass in tonnes with a stiffness in N/m gives a period
√1000 ≈ 32 times too short, which this catches."""

MAX_PLAUSIBLE_PERIOD = 10.0
"""Longest plausible fundamental period [s].

The tallest towers have T1 of 6–9 s and base-isolated buildings 2–5 s. A stiffness in
kN/m with a mass in kg gives a period √1000 ≈ 32 times too long, which this catches."""

MAX_PLAUSIBLE_PGA_G = 3.0
"""Largest plausible peak ground acceleration [g] after scaling (the resultant of the
horizontal components).

The largest horizontal PGAs ever recorded are about 2.7–4 g (e.g. 2008 Iwate–Miyagi, station
IWTH25), a handful among tens of thousands of records; design spectra stay below 2 g. A
record in cm/s² read as m/s² (100 times too strong) or in m/s² read as g (9.81 times) is
what this catches. An incremental dynamic analysis that deliberately goes beyond 3 g
still runs."""

MAX_PLAUSIBLE_FRICTION = 0.3
"""Largest plausible friction coefficient of a friction pendulum bearing [-].

Sliding isolators (PTFE or composites on polished stainless steel) have μ of 0.03–0.12,
up to about 0.2 at low pressure and temperature (Constantinou, Mokha & Reinhorn 1990;
EN 15129 §8.3). Above 0.3 the bearing hardly slides; μ = 1 or more is refused."""


def plausibility_warnings(cfg: RunConfig, built: Built) -> list[str]:
    """The plausibility warnings of a model file and what it builds, one line each,
    ``<key>: <value> …, the probable mistake``; none for a plausible model."""
    out: list[str] = []
    out += _gaps(cfg)
    out += _bridge_lengths(cfg)
    out += _masses(cfg, built)
    out += _periods(cfg, built)
    out += _pga(cfg, built)
    out += _friction(cfg)
    return out


def _gaps(cfg: RunConfig) -> list[str]:
    out = []
    gaps: list[tuple[str, float]] = []
    if cfg.contact is not None and cfg.contact.gap is not None:
        gaps.append(("contact.gap", cfg.contact.gap))
    if cfg.contact is not None and cfg.contact.gaps is not None:
        gaps += [(f"contact.gaps[{i}]", g) for i, g in enumerate(cfg.contact.gaps)]
    gaps += [(f"wall[{i}].gap", w.gap) for i, w in enumerate(cfg.wall)]
    for key, gap in gaps:
        if gap > MAX_PLAUSIBLE_GAP:
            out.append(f"{key}: {fmt(gap)} m is wider than {fmt(MAX_PLAUSIBLE_GAP)} m, more "
                       f"than any separation of buildings; is it in mm or cm?")
    return out


def _bridge_lengths(cfg: RunConfig) -> list[str]:
    """A bridge's joint and abutment gaps (as :func:`_gaps`) and its seat widths."""
    bridge = cfg.bridge
    if bridge is None:
        return []
    out = []
    gaps = [(f"bridge.joint[{j}].gap", joint.gap) for j, joint in enumerate(bridge.joint)
            if joint.gap is not None]  # (across the axis a joint has keys, not a gap)
    gaps += [(f"bridge.abutment_gaps[{i}]", g)
             for i, g in enumerate(bridge.abutment_gaps or []) if g != "none"]
    for key, gap in gaps:
        if float(gap) > MAX_PLAUSIBLE_GAP:
            out.append(f"{key}: {fmt(float(gap))} m is wider than {fmt(MAX_PLAUSIBLE_GAP)} m, "
                       "more than any joint of a bridge; is it in mm or cm?")
    seats = [(f"bridge.joint[{j}].seat_width", joint.seat_width)
             for j, joint in enumerate(bridge.joint) if joint.seat_width is not None]
    seats += [(f"bridge.abutment_seat_widths[{i}]", w)
              for i, w in enumerate(bridge.abutment_seat_widths or []) if w != "none"]
    for key, width in seats:
        if float(width) > MAX_PLAUSIBLE_SEAT_WIDTH:
            out.append(f"{key}: {fmt(float(width))} m is wider than "
                       f"{fmt(MAX_PLAUSIBLE_SEAT_WIDTH)} m, more than any seat of a bridge; "
                       "is it in mm or cm?")
    return out


def _masses(cfg: RunConfig, built: Built) -> list[str]:
    out = []
    for i, (b, made) in enumerate(zip(cfg.building, built.model.buildings)):
        given: list[tuple[str, float]] = []
        if b.mass is not None:
            given.append((f"building[{i}].mass", b.mass))
        if b.masses is not None:
            given += [(f"building[{i}].masses[{k}]", m) for k, m in enumerate(b.masses)]
        if b.isolator is not None:
            given.append((f"building[{i}].isolator.base_mass", b.isolator.base_mass))
        if b.kind == "matrices":
            from pounding.structure.assembly import floor_dofs
            from pounding.structure.matrices import MatrixBuilding

            assert isinstance(made, MatrixBuilding)  # what a "matrices" table builds
            labels = list(made.labels)
            given += [(f"building[{i}]: the mass of floor {labels[k]!r} in M",
                       float(made.masses[k])) for k in floor_dofs(made)]
        light = [(key, m) for key, m in given if m < MIN_PLAUSIBLE_FLOOR_MASS]
        if light:
            key, m = light[0]
            more = f" (and {len(light) - 1} more)" if len(light) > 1 else ""
            out.append(f"{key}: {fmt(m)} kg{more} is lighter than {fmt(MIN_PLAUSIBLE_FLOOR_MASS)} "
                       f"kg, less than any floor of a building; is it in tonnes?")
    return out


def _periods(cfg: RunConfig, built: Built) -> list[str]:
    out = []
    for i, (b, made) in enumerate(zip(cfg.building, built.model.buildings)):
        period = float(made.fundamental_period)
        if MIN_PLAUSIBLE_PERIOD <= period <= MAX_PLAUSIBLE_PERIOD:
            continue
        key = (f"building[{i}].period" if b.period is not None and b.isolator is None
               else f"building[{i}]")
        if period < MIN_PLAUSIBLE_PERIOD:
            side, bound, why = "below", MIN_PLAUSIBLE_PERIOD, "a mass in tonnes rather than kg?"
        else:
            side, bound, why = "above", MAX_PLAUSIBLE_PERIOD, "a stiffness in kN/m rather than N/m?"
        if key.endswith(".period"):
            why = "is it in seconds?"
        else:
            why = "is " + why
        out.append(f"{key}: fundamental period T1 = {period:.4g} s is {side} {fmt(bound)} s, "
                   f"outside the range of buildings; {why}")
    return out


def _pga(cfg: RunConfig, built: Built) -> list[str]:
    import numpy as np

    from pounding.ground_motion import GroundMotion
    from pounding.units import G

    motion: Any = built.motion
    comps = [motion] if isinstance(motion, GroundMotion) else list(motion.components)
    n = max(c.accel.size for c in comps)
    resultant = np.zeros(n)
    for c in comps:  # the horizontal resultant, by hypot (no overflow for absurd records)
        resultant[: c.accel.size] = np.hypot(resultant[: c.accel.size], c.accel)
    pga_g = float(resultant.max()) / G
    if pga_g <= MAX_PLAUSIBLE_PGA_G:
        return []
    rec = cfg.record
    how = next((k for k in ("scale", "pga_g", "sa_g", "saavg_g") if getattr(rec, k) is not None),
               None)
    source = f" after {how} = {fmt(getattr(rec, how))}" if how else ""
    what = ("; is the record in cm/s² read as m/s² (units = …)?" if how is None
            else "; is the scaling meant?")
    return [f"record: peak ground acceleration {pga_g:.3g} g{source} is above "
            f"{fmt(MAX_PLAUSIBLE_PGA_G)} g, more than any record{what}"]


def _friction(cfg: RunConfig) -> list[str]:
    out = []
    for i, b in enumerate(cfg.building):
        iso = b.isolator
        if iso is not None and iso.mu is not None and iso.mu > MAX_PLAUSIBLE_FRICTION:
            out.append(f"building[{i}].isolator.mu: {fmt(iso.mu)} is above "
                       f"{fmt(MAX_PLAUSIBLE_FRICTION)}, more than the friction of any "
                       f"sliding bearing (0.03–0.2)")
    return out

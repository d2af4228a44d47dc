"""The engineering demands a run is measured by in a study: each a number per run (a column
of a sweep's table), with the unit it is shown in.

A fragility study (:mod:`pounding.studies.fragility`) puts its limit states on these
demands; its figures and tables show them in these units. They are defined here, below
the studies and the figures, because both read them.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["DEMANDS", "Demand"]


@dataclass(frozen=True)
class Demand:
    """An engineering demand recorded per run: the column of the sweep's table it comes
    from, how it is shown (label, unit, factor from SI to that unit) and whether it is
    binary (exceeded or not: its IDA capacity is the first level exceeded)."""

    key: str
    label: str
    unit: str
    factor: float
    binary: bool = False
    largest: float = 0.0
    """The largest limit that means something, in the demand's unit (a limit state beyond
    it is never reached)."""
    exceeded_by_collapse: bool = False
    """Whether a run that stopped because a frame lost its strength exceeds any limit on
    this demand (a deformation that grows without bound: the IDA curve's flatline)."""


DEMANDS: dict[str, Demand] = {
    "pounding": Demand("pounding", "pounding (any impact)", "-", 1.0, binary=True),
    "impacts": Demand("impacts", "number of impacts", "-", 1.0, largest=1e6),
    "impact_force": Demand("impact_force", "peak impact force", "MN", 1e-6, largest=1e7),
    "drift": Demand("drift", "peak storey drift ratio", "%", 100.0, largest=100.0,
                    exceeded_by_collapse=True),
    "acceleration": Demand("acceleration", "peak floor acceleration", "g", 1.0 / 9.80665,
                           largest=100.0),
    "ductility": Demand("ductility", "peak storey ductility", "-", 1.0, largest=1000.0),
    "plastic_rotation": Demand("plastic_rotation", "peak plastic hinge rotation", "rad", 1.0,
                               largest=1.0, exceeded_by_collapse=True),
    "collapse": Demand("collapse", "collapse", "-", 1.0, binary=True,
                       exceeded_by_collapse=True),
    "seat_opening": Demand("seat_opening", "peak seat opening", "m", 1.0, largest=100.0),
}
"""The demands a limit state can be put on. ``limit`` is given in the unit shown: impact
force in MN (at most 1e7 MN, the weight of 1e12 kg), drift ratio in % (at most 100: a
drift of the whole storey height), floor acceleration in g (at most 100), a number of
impacts (at most a million), a ductility (at most 1000) or a plastic hinge rotation
``|θ − M/k0|`` in rad (at most 1), or a bridge's peak seat opening in m (at most 100: the
limit is the seat width; :mod:`pounding.result.bridge_seats`). ``pounding`` and
``collapse`` are yes/no: collapse is a
hinge of a frame past its IMK capping rotation, a peak storey drift ratio beyond a drift
limit, or a run stopped because a frame lost its strength (:mod:`pounding.studies.fragility`)."""

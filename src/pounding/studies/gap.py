"""The separation gap: how wide must it be so that two neighbours never touch?

Two answers, side by side (``docs/gap.md``):

* **by simulation** — :func:`critical_gaps`: each building is simulated *alone* (no contact:
  the coupled system is block-diagonal until the first impact, so this is exactly the
  response before any impact), and at every shared floor level the critical gap is

      g_cr = max(0, max_t [u_left(t) − u_right(t)]),

  the largest approach of the left floor towards the right one (displacements positive to
  the right, :mod:`pounding.model`). With any gap larger than ``g_cr`` the buildings never
  touch at that level; with any smaller one they do. No bisection: one pair of uncoupled
  runs gives it exactly. The maximum between output samples is found from the cubic Hermite
  interpolant of ``(Δu, Δu̇)`` on every output step (:func:`hermite_max`).

* **by code rules** — :mod:`pounding.studies.separation_rules` (ABS, SRSS, DDC), from the peak
  displacements ``u1, u2`` of the two buildings at that level: either the simulated peaks
  (:meth:`GapStudy.rules_from_peaks`) or the fundamental-mode displacements from a design
  spectrum (:meth:`GapStudy.rules_from_spectrum`; the spectrum,
  :class:`~pounding.spectra.DesignSpectrum`, and :func:`~pounding.spectra.spectral_displacements`
  live in :mod:`pounding.spectra` and are re-exported here).

Units: m, s throughout; spectral accelerations in m/s² internally.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from pounding.contact.geometry import Contact, ContactPoint
from pounding.ground_motion import GroundMotion, GroundMotionComponents
from pounding.model import ContactSpec, PoundingModel
from pounding.progress import Progress
from pounding.spectra import DesignSpectrum, fundamental_mode, spectral_displacements
from pounding.structure import ShearBuilding
from pounding.structure.wall import WallPoint
from pounding.studies.between_steps import ground_histories, hermite_max, wall_ground_histories
from pounding.studies.separation_rules import RULES, code_gaps, cqc_correlation

if TYPE_CHECKING:
    import pandas as pd  # imported by the method that returns a DataFrame (0.2 s)

__all__ = [
    "DesignSpectrum",
    "GapStudy",
    "critical_gaps",
    "gap_label",
    "ground_histories",
    "fundamental_mode",
    "hermite_max",
    "spectral_displacements",
]

FloatArray = NDArray[np.float64]


# ============================================================================ simulation
@dataclass(frozen=True, eq=False)
class GapStudy:
    """Critical gaps by simulation, per record and per shared floor level.

    Levels are the contacts of the model, in :attr:`PoundingModel.contacts` order (pair by
    pair, bottom to top; then those with moat walls; a bumper's pad left out). Arrays are
    ``(n_records, n_levels)`` unless stated.

    Attributes
    ----------
    model : PoundingModel
    records : tuple of str
        Names of the ground motions.
    pair, elevation, labels : (n_levels,)
        Which gap (0 = between buildings 1 and 2; for a moat wall, −1 on the left of the
        row and the last building's index on its right), level above ground [m], contact
        label.
    critical : (n_records, n_levels)
        ``max(0, max_t (u_left − u_right))`` [m]: the smallest gap that is never closed.
    time_of_max : (n_records, n_levels)
        When ``u_left − u_right`` is largest [s].
    peak_relative : (n_records, n_levels)
        ``max_t |u_left − u_right|`` [m], either direction (what DDC estimates).
    peak_left, peak_right : (n_records, n_levels)
        Peak ``|u|`` [m] of the left and right building at that level.
    period, zeta : (n_buildings,)
        Fundamental period [s] and its damping ratio [-] of each building.
    rho : (n_pairs,)
        :func:`cqc_correlation` of the fundamental modes of each pair of neighbours.
    dt : float
        Output step of the uncoupled simulations [s].
    durations : (n_records,)
        Time simulated for each record [s].
    gap_names : (n_levels,)
        The gap each level's contact closes (:func:`gap_label`: ``'B1-B2'``, ``'B1-W'``).
    contacts : (n_levels,)
        The model's contacts studied.
    """

    model: PoundingModel
    records: tuple[str, ...]
    pair: NDArray[np.int64]
    elevation: FloatArray
    labels: tuple[str, ...]
    critical: FloatArray
    time_of_max: FloatArray
    peak_relative: FloatArray
    peak_left: FloatArray
    peak_right: FloatArray
    period: FloatArray
    zeta: FloatArray
    rho: FloatArray
    dt: float
    durations: FloatArray
    gap_names: tuple[str, ...] = ()
    contacts: tuple[Contact, ...] = ()

    @property
    def n_levels(self) -> int:
        """Number of shared floor levels (all pairs)."""
        return int(self.elevation.size)

    @property
    def mean_critical(self) -> FloatArray:
        """Mean over records of the critical gap [m] (n_levels,)."""
        return self.critical.mean(axis=0)

    @property
    def max_critical(self) -> FloatArray:
        """Largest over records of the critical gap [m] (n_levels,)."""
        return self.critical.max(axis=0)

    def governing(self) -> FloatArray:
        """Critical gap of each pair of buildings [m] (n_pairs,): largest over its levels
        and the records (moat walls: :meth:`governing_gaps`)."""
        n_pairs = len(self.model.buildings) - 1
        names = np.array(self.gap_names)
        return np.array([self.max_critical[names == f"B{p + 1}-B{p + 2}"].max(initial=0.0)
                         for p in range(n_pairs)])

    def governing_gaps(self) -> dict[str, float]:
        """Critical gap [m] of every gap of the model — between neighbours and between a
        building and a moat wall (the moat width it needs) — by :attr:`gap_names`: largest
        over its levels and the records."""
        names = np.array(self.gap_names)
        return {n: float(self.max_critical[names == n].max(initial=0.0))
                for n in dict.fromkeys(self.gap_names)}

    @property
    def level_rho(self) -> FloatArray:
        """CQC correlation of each level's two buildings (n_levels,); 0 for a moat wall,
        which does not move (its peak is 0, so any ρ gives the same rules)."""
        walls = np.array([isinstance(c.left, WallPoint) or isinstance(c.right, WallPoint)
                          for c in self.contacts], dtype=bool)
        pair = np.clip(self.pair, 0, max(self.rho.size - 1, 0))
        return np.where(walls, 0.0, self.rho[pair] if self.rho.size else 0.0)

    def rules_from_peaks(self, stat: str = "mean") -> dict[str, FloatArray]:
        """Code rules at every level from the simulated peak displacements [m].

        ``stat``: ``"mean"`` (default) or ``"max"`` over records of each building's peak at
        that level; or ``"record"`` for the rules of each record, shape (n_records, n_levels).
        """
        rho = self.level_rho
        if stat == "mean":
            u1, u2 = self.peak_left.mean(axis=0), self.peak_right.mean(axis=0)
        elif stat == "max":
            u1, u2 = self.peak_left.max(axis=0), self.peak_right.max(axis=0)
        elif stat == "record":
            return {k: np.stack([code_gaps(a, b, rho)[k]
                                 for a, b in zip(self.peak_left, self.peak_right)])
                    for k in RULES}
        else:
            raise ValueError(f"stat: choose mean, max or record (got {stat!r})")
        return code_gaps(u1, u2, rho)

    def spectral_peaks(self, spectrum: DesignSpectrum) -> tuple[FloatArray, FloatArray]:
        """Peak displacements [m] of the left and right building at every level from
        ``spectrum`` (:func:`spectral_displacements`), (n_levels,) each."""
        if any(_in_plan(b) for b in self.model.buildings):
            raise ValueError("spectrum: the code rules from a design spectrum take each "
                             "building's fundamental mode along the row, and a building in "
                             "plan sways and twists in modes of its own: use the rules from "
                             "the simulated peaks, without a spectrum")
        per_b = [spectral_displacements(b, spectrum) for b in self.model.buildings]

        def peak(p: ContactPoint) -> float:
            # fundamental-mode peaks: linear between the floors of a struck storey, like
            # the mode; a wall does not move
            return 0.0 if isinstance(p, WallPoint) else float(p.of(np.asarray(per_b[p.building])))

        u1 = np.array([peak(c.left) for c in self.contacts])
        u2 = np.array([peak(c.right) for c in self.contacts])
        return u1, u2

    def rules_from_spectrum(self, spectrum: DesignSpectrum) -> dict[str, FloatArray]:
        """Code rules at every level [m] from a design spectrum (fundamental modes)."""
        u1, u2 = self.spectral_peaks(spectrum)
        return code_gaps(u1, u2, self.level_rho)

    def to_frame(self, spectrum: DesignSpectrum | None = None) -> pd.DataFrame:
        """One row per level: pair, elevation [m], critical gap per record [m], mean, max,
        the rules from the mean simulated peaks and (with ``spectrum``) from the spectrum,
        each with its ratio to the simulated max and to the simulated mean (NaN where the
        simulated gap is 0)."""
        import pandas as pd

        df = pd.DataFrame({"pair": list(self.gap_names),
                           "contact": list(self.labels), "elevation_m": self.elevation})
        for name, row in zip(_unique(self.records), self.critical):
            df[f"critical_m[{name}]"] = row
        df["mean_m"] = self.mean_critical
        df["max_m"] = self.max_critical
        sim, avg = self.max_critical, self.mean_critical
        sets: list[tuple[str, dict[str, FloatArray]]] = [("peaks", self.rules_from_peaks())]
        if spectrum is not None:
            sets.append(("spectrum", self.rules_from_spectrum(spectrum)))
        for where, rules in sets:
            for k, v in rules.items():
                df[f"{k}_{where}_m"] = v
                for ref, stat in ((sim, "max"), (avg, "mean")):
                    df[f"{k}_{where}/{stat}"] = np.where(ref > 0, v / np.where(ref > 0, ref, 1.0),
                                                         np.nan)
        return df


def _unique(names: Sequence[str]) -> list[str]:
    """Names made unique by a suffix (``#2``, …) where repeated."""
    out: list[str] = []
    for n in names:
        k, m = n, 1
        while k in out:
            m += 1
            k = f"{n} #{m}"
        out.append(k)
    return out


@dataclass(frozen=True)
class _AloneRun:
    """What the gap study keeps of a building simulated alone: its output step [s], the
    time of its last output [s], its displacements and velocities (steps × DOFs)."""

    dt: float
    end: float
    displacement: FloatArray
    velocity: FloatArray

    @property
    def n(self) -> int:
        """Output steps."""
        return int(self.displacement.shape[0])


def _run_alone(building: ShearBuilding, motion: GroundMotion | GroundMotionComponents,
               dt: float | None, duration: float) -> _AloneRun:
    """Simulate one building alone under one record (a task of
    :func:`~pounding.studies.sweep.tasks.run_tasks`: what goes back is only what the gap
    study reads)."""
    from pounding.integrate import simulate

    run = simulate(_alone(building), motion, dt=dt, duration=duration,
                   free_stepping="rk" if building.is_inelastic else "auto")
    return _AloneRun(dt=float(run.dt), end=float(run.time[-1]),
                     displacement=np.asarray(run.displacement),
                     velocity=np.asarray(run.velocity))


def _own_record(motion: GroundMotion | GroundMotionComponents, building: int
                ) -> GroundMotion | GroundMotionComponents:
    """The record under ``building``: its own under a spatially varying motion, else the
    one record."""
    from pounding.ground_motion.spatial import SpatialMotion

    return motion.records[building] if isinstance(motion, SpatialMotion) else motion


def _alone(building: ShearBuilding) -> PoundingModel:
    return PoundingModel([building], [], ContactSpec("linear-spring", k=1.0),
                         name=building.name or "building")


def _in_plan(building: object) -> bool:
    from pounding.structure.plan_row import PlanMatrixBuilding

    return isinstance(building, PlanMatrixBuilding)


def gap_label(model: PoundingModel, contact: Contact) -> str:
    """The gap a contact closes: ``'B1-B2'`` between two buildings, ``'B1-W'`` / ``'W-B1'``
    between a building and the moat wall on its right / left."""
    if isinstance(contact.left, WallPoint):
        return f"{contact.left.label()}-B{contact.right.building + 1}"
    if isinstance(contact.right, WallPoint):
        return f"B{contact.left.building + 1}-{contact.right.label()}"
    return f"B{contact.pair + 1}-B{contact.pair + 2}"


def _check_motions(model: PoundingModel, motions: object
                   ) -> list[GroundMotion | GroundMotionComponents]:
    """The records as a list, each of the kind the model is shaken by (one component for a
    row of planar buildings, x and y components where a building is in plan)."""
    one = (GroundMotion, GroundMotionComponents)
    ms = [motions] if isinstance(motions, one) else list(motions)  # type: ignore[call-overload]
    if not ms:
        raise ValueError("motions: give at least one ground motion")
    in_plan = any(_in_plan(b) for b in model.buildings)
    for i, m in enumerate(ms):
        if not isinstance(m, one):
            raise ValueError(f"motions[{i}]: expected a GroundMotion (got {type(m).__name__})")
        if in_plan and not (isinstance(m, GroundMotionComponents) and m.n_components == 2):
            raise ValueError(f"motions[{i}]: the model has buildings in plan, shaken along x "
                             "and y: give each record as its two site components, "
                             "GroundMotionComponents(x, y) (pounding.ground_motion.at_incidence "
                             "turns one or two recorded components to an angle)")
        if not in_plan and isinstance(m, GroundMotionComponents):
            if m.n_components != 1:
                raise ValueError(f"motions[{i}]: {m.n_components} ground components for a row "
                                 "of buildings shaken along the row (one component; several "
                                 "are for buildings in plan)")
            ms[i] = m.components[0]
    return ms


def critical_gaps(model: PoundingModel,
                  motions: GroundMotion | GroundMotionComponents
                  | Sequence[GroundMotion | GroundMotionComponents], *,
                  dt: float | None = None, duration: float | None = None,
                  scheduler: str | None = None, n_workers: int | None = None,
                  progress: Progress | None = None) -> GapStudy:
    """Critical separation gap at every contact, by simulation, per record.

    Each building is simulated alone (exact stepping: no contact, so the propagator is exact
    on every output step, :func:`pounding.integrate.simulate`), and at every contact of the
    model the critical gap is the largest approach of its two points,
    ``max(0, max_t (u_left(t) − u_right(t)))``, the maximum taken on the cubic Hermite
    interpolant of the approach and its rate between output samples (:func:`hermite_max`).
    A gap larger than it is never closed in the same time window; a smaller one is. The gaps
    and contact law of ``model`` are not used.

    The contact points are those of the model's contacts: floors, points of a column
    between two floors, the two ends of the stretch where two façades in plan face each
    other (their displacement along x with the floor's rotation, rigid-floor kinematics:
    :meth:`~pounding.structure.plan.PlanBuilding.point_weights`), and the floors facing a
    moat wall (the wall does not move: the critical gap there is the moat width the
    building needs, its largest displacement toward the wall).

    Parameters
    ----------
    model : PoundingModel
        Two or more buildings with a contact between neighbours, or a building beside a
        moat wall. Links between buildings (:class:`pounding.devices.Link`) are refused:
        the buildings are simulated apart. Bumpers are ignored (they act only in contact).
    motions : GroundMotion, GroundMotionComponents, or a sequence of them
        The records (used as given: scale them beforehand); for a model with buildings in
        plan, each record's x and y site components (a planar building in such a row feels
        the x component, as in :class:`~pounding.model.PoundingModel`).
    dt : float, optional
        Output step [s] (default 1 ms, rounded to a divisor of each record's step).
    duration : float, optional
        Time simulated [s] (default each record's duration; longer adds free vibration).
    scheduler, n_workers : optional
        Where the runs (one per building and record) go: by default one after another in
        this process; ``n_workers`` processes of a local Dask cluster; or the Dask
        scheduler at ``scheduler`` (:func:`pounding.studies.sweep.tasks.run_tasks`).
    progress : Progress, optional
        Called as ``progress(done, total)``: runs finished, and in all.

    Returns
    -------
    GapStudy
    """
    from pounding.studies.sweep.tasks import run_tasks

    if not isinstance(model, PoundingModel):
        raise ValueError(f"model: expected a PoundingModel (got {type(model).__name__})")
    if len(model.buildings) < 2 and not model.walls:
        raise ValueError("model: a gap study needs two or more buildings, or a building "
                         f"beside a moat wall (got {len(model.buildings)} building and no "
                         "wall)")
    if model.links:
        raise ValueError(f"model: a gap study simulates each building alone, and "
                         f"{len(model.links)} link(s) (devices) tie the buildings together; "
                         "remove the links, or run the model (pounding run) at several gaps")
    cs = tuple(c for c in model.contacts if c.tag != "bumper")
    if not cs:
        raise ValueError("model: no contact level between neighbours (no shared floor level "
                         "and no floor facing a column), so no gap to study")
    ms = _check_motions(model, motions)
    nr, nc = len(ms), len(cs)
    crit = np.zeros((nr, nc))
    tmax = np.zeros((nr, nc))
    rel = np.zeros((nr, nc))
    pl = np.zeros((nr, nc))
    pr = np.zeros((nr, nc))
    durs = np.zeros(nr)
    step = 0.0
    # every building over the same time (the longest component's when two are given);
    # exact stepping for linear buildings up to EXACT_FREE_MAX_DOF floors (beyond, its
    # propagator alone takes minutes to build, in calls no signal can stop); yielding
    # ones are RK-stepped (not linear)
    # (under a spatially varying motion each building alone under its own record; the
    # contacts then add the grounds' relative displacement, _ground_on_grid)
    tasks = [(bl, _own_record(motion, b) if _in_plan(bl) or isinstance(motion, GroundMotion)
              else motion.components[0], dt, motion.duration if duration is None else duration)
             for motion in ms for b, bl in enumerate(model.buildings)]
    alone = run_tasks(_run_alone, tasks, scheduler=scheduler, n_workers=n_workers,
                      progress=progress)
    nb = len(model.buildings)
    for i in range(nr):
        runs = alone[i * nb:(i + 1) * nb]
        step = runs[0].dt
        durs[i] = runs[0].end

        grounds = ground_histories(ms[i], len(runs), step, runs[0].n)
        wall_grounds = wall_ground_histories(ms[i], step, runs[0].n)

        def point(p: ContactPoint, other: ContactPoint, side: str) -> tuple[FloatArray, ...]:
            """The point's displacement and velocity relative to its ground, and its
            ground's (a wall stands on its own ground, or on the building's beside it)."""
            if isinstance(p, WallPoint):
                zero = np.zeros(runs[0].n)
                return (zero, zero, *wall_grounds.get(side, grounds[other.building]))
            run = runs[p.building]
            return (p.of(run.displacement), p.of(run.velocity), *grounds[p.building])

        for k, c in enumerate(cs):
            # contact points: a floor, a column point between two floors (interpolated), a
            # façade point of a floor in plan (with the floor's rotation), or a wall
            ul, vl, ugl, vgl = point(c.left, c.right, "left")
            ur, vr, ugr, vgr = point(c.right, c.left, "right")
            d, dd = ul + ugl - ur - ugr, vl + vgl - vr - vgr
            top, when = hermite_max(d, dd, step)
            low, _ = hermite_max(-d, -dd, step)
            crit[i, k] = max(0.0, float(top))
            tmax[i, k] = float(when)
            rel[i, k] = max(float(top), float(low), 0.0)
            pl[i, k] = max(float(hermite_max(ul, vl, step)[0]),
                           float(hermite_max(-ul, -vl, step)[0]))
            pr[i, k] = max(float(hermite_max(ur, vr, step)[0]),
                           float(hermite_max(-ur, -vr, step)[0]))
    modes = [fundamental_mode(b) for b in model.buildings]
    period = np.array([m[0] for m in modes])
    zeta = np.array([m[1] for m in modes])
    rho = np.array([cqc_correlation(period[p], period[p + 1], zeta[p], zeta[p + 1])
                    for p in range(len(model.buildings) - 1)])
    return GapStudy(model=model, records=tuple(m.name for m in ms),
                    pair=np.array([c.pair for c in cs], dtype=np.int64),
                    elevation=np.array([c.elevation for c in cs]),
                    labels=tuple(c.label for c in cs), critical=crit, time_of_max=tmax,
                    peak_relative=rel, peak_left=pl, peak_right=pr, period=period, zeta=zeta,
                    rho=rho, dt=step, durations=durs,
                    gap_names=tuple(gap_label(model, c) for c in cs),
                    contacts=cs)

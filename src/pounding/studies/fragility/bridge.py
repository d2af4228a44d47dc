"""A fragility study of a bridge: its joints' gaps, the gap each record needs at the joints,
its limit states read at one joint or seat, and the seat width for a probability of
unseating.

A bridge along its axis (:mod:`pounding.structure.bridge`) is a row of frames, its
expansion joints the row's gaps, its abutments walls at the ends. A study of it differs
from one of buildings in three things (``docs/bridges.md``, "Studies"):

* **The gaps are the joints'.** Every run sets each joint's gap
  (``bridge.joint.<j>.gap``): the base model's own, or each value of ``[gap] values`` at
  every joint. The abutments' gaps are the base model's.
* **The gap the joints need** is found from runs of the whole bridge (abutments, bearings,
  restrainers as they are) in which no joint is ever reached: each joint's gap set to
  :data:`NO_CONTACT_GAP`. Until the decks first meet at a joint a run with contact there is
  that run, so with every joint's gap above ``g_n`` — the largest closing of any joint in it,
  located between output steps (``peak_closing_m_J<j>``,
  :mod:`pounding.studies.sweep.bridge_measures`) — no joint pounds, and with one below it
  some joint does. These runs are cases of the study's own sweep, after its runs, at every
  level and at the gap analysis' level. (The gap study of buildings,
  :func:`pounding.studies.gap.critical_gaps`, runs each building alone instead, which
  leaves out the abutments and would refuse the restrainers.) The code gaps beside it are
  ABS, SRSS and DDC of the decks' mean peak displacements in the same runs, with the CQC
  correlation of the two frames' fundamental modes, largest over the joints
  (:func:`pounding.studies.fragility.gaps.bridge_needed_gaps`).
* **Seats.** ``"seat_opening"`` is the peak opening of a seat [m] (every seat by default,
  or the one named by ``joint``: ``J1`` …, ``A1``, ``A2``), and the limit the seat width:
  P(unseating | IM) for that width. Against the seat width, at every level, the
  probability that a seat as wide as ``w`` at every seat is lost is the fraction of records
  whose largest seat opening exceeds ``w``, and its lognormal fit over records; the width
  for the target probability ``p`` is their ``1 − p`` fractile (:func:`seat_widths`) — the
  gap analysis' arithmetic (:mod:`.gap_probability`) with the seat opening for the needed
  gap. The model's response does not depend on a seat width (a deck is not dropped), so
  one set of runs answers for every width.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.studies.fragility.study import LimitStateSpec

__all__ = ["NO_CONTACT_GAP", "BridgeSeatsLayout", "SeatWidths", "bridge_layout", "check_joint",
           "joint_demand", "joint_pounding", "seat_widths"]

FloatArray = NDArray[np.float64]

NO_CONTACT_GAP = 1000.0
"""A joint's gap [m] in the runs that find the gap the joints need: the largest gap a model
file takes, never reached by a deck (a run that closes a joint by half as much is left
out)."""


@dataclass(frozen=True)
class BridgeSeatsLayout:
    """What a study needs of a bridge model.

    Attributes
    ----------
    joint_gaps : tuple of float
        The base model's gap of every expansion joint [m].
    walls : tuple of str
        The abutments with a backwall (``A1``, ``A2``).
    decks : tuple of str
        Every frame's deck DOF label (``B1F1``, …), left to right.
    periods, zetas : tuple of float
        Every frame's fundamental period [s] and its damping ratio.
    """

    joint_gaps: tuple[float, ...]
    walls: tuple[str, ...]
    decks: tuple[str, ...]
    periods: tuple[float, ...]
    zetas: tuple[float, ...]

    @property
    def n_joints(self) -> int:
        """Expansion joints."""
        return len(self.joint_gaps)

    @property
    def seats(self) -> tuple[str, ...]:
        """Every seat, left to right: ``A1``, ``J1`` …, ``A2``."""
        return ("A1", *(f"J{j + 1}" for j in range(self.n_joints)), "A2")

    def params(self) -> list[str]:
        """The sweep parameters of the joints' gaps."""
        return [f"bridge.joint.{j}.gap" for j in range(self.n_joints)]


def bridge_layout(model: Any) -> BridgeSeatsLayout | None:
    """The :class:`BridgeSeatsLayout` of a bridge model; None for any other model."""
    from pounding.spectra import fundamental_mode
    from pounding.studies.sweep.bridge_measures import is_bridge

    if not is_bridge(model):
        return None
    labels = model.dof_labels()
    decks = tuple(labels[int(off) + int(b.deck_dof)]
                  for off, b in zip(model.system.offsets, model.buildings))
    modes = [fundamental_mode(b) for b in model.buildings]
    return BridgeSeatsLayout(tuple(float(g) for g in model.gaps), tuple(w.name for w in model.walls),
                        decks, tuple(float(m[0]) for m in modes),
                        tuple(float(m[1]) for m in modes))


def check_joint(spec: LimitStateSpec, layout: BridgeSeatsLayout | None, where: str, i: int,
                base: str) -> None:
    """Refuse, in one line, a limit state's ``joint`` (or a seat opening) the base model
    does not have."""
    if layout is None:
        if spec.joint is not None or spec.demand == "seat_opening":
            what = "joint" if spec.joint is not None else "demand"
            got = spec.joint if spec.joint is not None else spec.demand
            raise ValueError(f"{where}: limit_state[{i}].{what}: a bridge's joints and seats, "
                             f"and {base} is no bridge ([bridge]) (got '{got}')")
        return
    joint = spec.joint
    if joint is None or joint in ("joints", "abutments"):
        if joint == "abutments" and spec.demand != "seat_opening" and not layout.walls:
            raise ValueError(f"{where}: limit_state[{i}].joint: the bridge of {base} has no "
                             "abutment with a backwall (bridge.abutment_gaps) to strike "
                             "(got 'abutments')")
        return
    if joint.startswith("J") and int(joint[1:]) > layout.n_joints:
        raise ValueError(f"{where}: limit_state[{i}].joint: the bridge of {base} has "
                         f"{layout.n_joints} expansion joint(s), J1 … J{layout.n_joints} "
                         f"(got '{joint}')")
    if joint.startswith("A") and spec.demand != "seat_opening" and joint not in layout.walls:
        raise ValueError(f"{where}: limit_state[{i}].joint: abutment {joint} of {base} has no "
                         "backwall to strike (bridge.abutment_gaps: \"none\"); its seat's "
                         f"opening is demand \"seat_opening\" (got '{joint}')")


def _seats(spec: LimitStateSpec, layout: BridgeSeatsLayout) -> list[str]:
    """The seats a limit state reads: those named by ``joint`` (every seat without one); an
    abutment is struck only where it has a backwall."""
    joint = spec.joint
    if joint is None:
        names: tuple[str, ...] = layout.seats
    elif joint == "joints":
        names = tuple(s for s in layout.seats if s.startswith("J"))
    elif joint == "abutments":
        names = ("A1", "A2")
    else:
        names = (joint,)
    struck = spec.demand != "seat_opening"
    return [s for s in names if not (struck and s.startswith("A") and s not in layout.walls)]


_PREFIX = {"pounding": "n_impacts", "impacts": "n_impacts",
           "impact_force": "peak_impact_force_N", "seat_opening": "peak_opening_m"}
"""The bridge column (:mod:`pounding.studies.sweep.bridge_measures`) of each demand a limit
state may read at a joint."""


def joint_demand(spec: LimitStateSpec, layout: BridgeSeatsLayout, table: Any) -> FloatArray:
    """A limit state's demand in every row of ``table`` (the study's runs) [SI]: the sum of
    the impacts, or the largest force or opening, over the seats it names; NaN where the
    run failed. For ``"pounding"``: 1.0 where it pounded there, else 0.0."""
    ok = (table["status"] == "ok").to_numpy()
    cols = [f"{_PREFIX[spec.demand]}_{s}" for s in _seats(spec, layout)]
    values = np.column_stack([table[c].to_numpy(dtype=float, na_value=np.nan) for c in cols])
    out = values.sum(axis=1) if spec.demand in ("pounding", "impacts") else values.max(axis=1)
    if spec.demand == "pounding":
        out = (out > 0).astype(float)
    return np.where(ok, out, np.nan)


def joint_pounding(layout: BridgeSeatsLayout, table: Any) -> FloatArray:
    """Whether each run pounded at any expansion joint (1.0, 0.0; NaN: failed)."""
    return joint_demand(LimitStateSpec(demand="pounding", joint="joints"), layout, table)


@dataclass(frozen=True)
class SeatWidths:
    """The seat width for a probability of unseating, at every level (module docstring).

    Attributes
    ----------
    target : float
        The probability of unseating allowed.
    median, beta : (n_levels,)
        Lognormal fit of the records' largest seat opening at each level (θ [m], β).
    width_fit, width_records : (n_levels,)
        The seat width [m] the target probability needs: from the fit, and from the
        records (the smallest width at most ⌊p n⌋ of them open beyond).
    width_fit_ci : (2, n_levels)
        Bootstrap interval of ``width_fit`` (expanded percentile, over records).
    grid : (n_grid,)
        Seat widths [m] of the surface.
    surface_empirical, surface_fit : (n_grid, n_levels)
        P(unseating | width, level): the fraction of records, the lognormal fit.
    """

    target: float
    median: FloatArray
    beta: FloatArray
    width_fit: FloatArray
    width_records: FloatArray
    width_fit_ci: FloatArray
    grid: FloatArray
    surface_empirical: FloatArray
    surface_fit: FloatArray


def seat_widths(openings: FloatArray, target: float, boot: NDArray[np.int64],
                confidence: float) -> SeatWidths:
    """The :class:`SeatWidths` of the records' largest seat openings ``openings``
    (n_records, n_levels) [m] (NaN: a failed run, left out), for the probability
    ``target``, with the bootstrap resamples of the records ``boot`` (n_boot, n_records)
    and the two-sided ``confidence`` of the interval."""
    from pounding.studies.fragility.bootstrap import expanded_confidence, percentile_interval
    from pounding.studies.fragility.gap_probability import (
        empirical_gap,
        gap_lognormal,
        lognormal_gap,
        pounding_probability,
        pounding_probability_fit,
    )

    n_levels = openings.shape[1]
    fits = [gap_lognormal(openings[:, j]) for j in range(n_levels)]
    median = np.array([m for m, _ in fits])
    beta = np.array([b for _, b in fits])
    width_fit = np.array([lognormal_gap(m, b, target) for m, b in fits])
    width_rec = np.array([empirical_gap(openings[:, j], target) for j in range(n_levels)])
    conf = expanded_confidence(confidence, int(np.isfinite(openings).any(axis=1).sum()))
    ci = np.full((2, n_levels), np.nan)
    if boot.size:
        widths = _lognormal_widths(openings[boot], target)  # (n_boot, n_levels)
        for j in range(n_levels):
            w = widths[:, j][np.isfinite(widths[:, j])]
            if w.size:
                ci[:, j] = percentile_interval(w, conf)
    top = float(np.nanmax(openings)) if np.isfinite(openings).any() else 0.0
    grid = np.linspace(0.0, max(top, 1e-3) * 1.05, 211)
    surface_fit = np.column_stack([pounding_probability_fit(m, b, grid) for m, b in fits])
    return SeatWidths(target, median, beta, width_fit, width_rec, ci, grid,
                      pounding_probability(openings, grid), surface_fit)


def _lognormal_widths(openings: FloatArray, target: float) -> FloatArray:
    """:func:`~pounding.studies.fragility.gap_probability.lognormal_gap` of the lognormal
    fit (:func:`~pounding.studies.fragility.gap_probability.gap_lognormal`) of every
    resample at every level, at once: ``openings`` (n_boot, n_records, n_levels) → (n_boot,
    n_levels); NaN where fewer than two finite openings, or one of them 0."""
    from scipy.special import ndtri

    finite = np.isfinite(openings)
    with np.errstate(divide="ignore", invalid="ignore"):
        logs = np.where(finite & (openings > 0), np.log(np.where(finite, openings, 1.0)),
                        np.nan)
        n = finite.sum(axis=1)
        bad = (n < 2) | np.any(finite & ~(openings > 0), axis=1)
        mean = np.nansum(logs, axis=1) / n
        var = np.nansum((logs - mean[:, None, :]) ** 2, axis=1) / (n - 1)
        width = np.exp(mean + np.sqrt(var) * float(ndtri(1.0 - target)))
    return np.where(bad, np.nan, width)

"""The time history beside a code's separation check: does the gap the code asks for
actually prevent pounding under a suite of records scaled to the code's spectrum?
(``docs/codes.md``, "Beside a time history").

For a model, its :class:`~pounding.studies.codes.common.CodeCheck` and a suite of records:

1. the suite is scaled to a target spectrum — by default the code's own elastic spectrum
   from the check's parameters (:func:`code_spectrum`) — by the code's rule for a suite
   (:func:`pounding.spectra.scale_suite`, ``method="code"``: one factor, the suite's mean
   nowhere below 90 % of the target from 0.2 T1 of the stiffest building to 2 T1 of the
   most flexible);
2. the model is simulated under every scaled record (:func:`pounding.integrate.simulate`,
   the model file's solver settings) twice: (a) with its own gaps and (b) with every gap set
   to the code's separation — one gap a pair of neighbours (a building's separation is the
   same at every height), the largest separation the code asks for at that pair's levels,
   so that every level meets the code;
3. the smallest gap that would have prevented pounding under each record, at every level,
   is its peak closing ``max(0, max_t (u_left − u_right))`` with the buildings apart
   (:func:`pounding.studies.gap.critical_gaps`: the coupled response is the uncoupled one
   until the first impact, so a gap above it is never closed and a gap below it is).

Per record: did it pound, how many impacts, the peak impact force [N]; per level: the peak
closing beside the code's separation there. Since the response is the uncoupled one until
the first impact, "would a gap of the code's separation *at each level* have been closed"
is exactly "peak closing > required" at some level (no run needed for it).

Units: m, s, N inside; :meth:`TimeHistoryCheck.to_dict` states its units (mm, kN).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, fields
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.studies.codes.common import CodeCheck

__all__ = ["STRONG_SHAKING", "CodeCheckBeside", "RunOutcomes", "TimeHistoryCheck",
           "check_duration", "code_spectrum", "refuse_linked", "time_history_check"]

FloatArray = NDArray[np.float64]

STRONG_SHAKING: tuple[float, float] = (0.05, 0.95)
"""The strong shaking of a record: from where it has built the first to where it has built
the second share of its Arias intensity (its significant duration D5-95, Trifunac & Brady
1975). A simulated time must reach every record's start of it (:func:`check_duration`); one
that stops before a record's end of it is said beside the verdicts
(:meth:`TimeHistoryCheck.verdicts`)."""


def check_duration(duration: float, motions: Sequence[Any], name: str = "duration") -> float:
    """``duration`` [s] if positive and reaching every record's strong shaking (its first
    :data:`STRONG_SHAKING` share of Arias intensity,
    :meth:`~pounding.ground_motion.GroundMotion.arias_time`), else one line naming ``name``
    (ValueError): a shorter run would judge the code's gap on a record before it shakes."""
    from pounding.validation import positive

    duration = positive(name, duration)
    starts = [float(m.arias_time(STRONG_SHAKING[0])) for m in motions]
    if starts and duration < max(starts):
        i = int(np.argmax(starts))
        enough = math.ceil(starts[i] * 100.0) / 100.0  # (rounded up: a value that passes)
        raise ValueError(f"{name}: {duration:g} s ends before the strong shaking of "
                         f"{motions[i].name} begins ({100 * STRONG_SHAKING[0]:g} % of its "
                         f"Arias intensity at {starts[i]:.4g} s); give at least "
                         f"{enough:g} s, or leave it out to run each record whole")
    return duration


def code_spectrum(check: CodeCheck) -> Any:
    """The code's elastic 5 %-damped spectrum from the check's parameters: the target a suite
    is scaled to beside the check (:class:`~pounding.spectra.DesignSpectrum`).

    * ``asce7-22``: the design response spectrum of §11.4.6 (S_DS, S_D1, T_L), the one the
      check used before dividing by R/I_e (the design earthquake: two thirds of MCE_R);
    * ``en1998-1``: the elastic spectrum of §3.2.2.2 for a_g = γ_I a_gR, the ground and
      spectrum type of the check (its design spectrum without q);
    * ``nzs1170.5``: the elastic site spectrum C(T) = C_h(T) Z R N of §3.1 (N = 1), the one
      whose modal deflections the check multiplies by μ/k_μ;
    * ``nbcc2020``: the design spectrum S(T) of Sentence 4.1.8.4 from the check's table, whose
      deflections are the check's (×R_d R_o/I_E of the reduced ones, Sentence 4.1.8.13);
    * ``is1893``: (Z/2) I (Sa/g) of §6.4, the check's spectrum without R (R Δ is the
      displacement on it).

    Raises
    ------
    ValueError
        A code whose spectrum is not known here: give the target spectrum yourself.
    """
    from pounding.spectra import DesignSpectrum

    p = check.parameters
    if check.code == "asce7-22":
        return DesignSpectrum.asce7(p["sds_g"], p["sd1_g"], p["tl_s"],
                                    name=f"ASCE 7-22 §11.4.6 design spectrum (S_DS = "
                                         f"{p['sds_g']:g} g, S_D1 = {p['sd1_g']:g} g, T_L = "
                                         f"{p['tl_s']:g} s)")
    if check.code == "en1998-1":
        return DesignSpectrum.eurocode8(
            p["agr_g"], p["ground_type"], p["spectrum_type"], importance=p["importance"],
            name=f"EN 1998-1 §3.2.2.2 elastic spectrum (type {p['spectrum_type']}, ground "
                 f"{p['ground_type']}, a_g = {p['ag_g']:g} g)")
    if check.code == "nzs1170.5":
        return DesignSpectrum.nzs1170_5(p["z"], p["ru"], p["site_class"],
                                        name=f"NZS 1170.5 §3.1 elastic site spectrum (Z = "
                                             f"{p['z']:g}, R = {p['ru']:g}, site class "
                                             f"{p['site_class']})")
    if check.code == "nbcc2020":
        return DesignSpectrum.nbcc2020(p["s_table_g"],
                                       name="NBCC 2020 Sentence 4.1.8.4 design spectrum S(T)")
    if check.code == "is1893":
        return DesignSpectrum.is1893(p["z"], p["importance"], 1.0, p["soil_type"],
                                     name=f"IS 1893 §6.4 (Z/2) I Sa/g (Z = {p['z']:g}, I = "
                                          f"{p['importance']:g}, soil type {p['soil_type']})")
    raise ValueError(f"design: no spectrum of {check.code} is known to the time-history "
                     "check; give the target spectrum (--design FILE)")


@dataclass(frozen=True, eq=False)
class RunOutcomes:
    """The runs of one set of gaps, every record: arrays ``(n_records, n_levels)``.

    Attributes
    ----------
    gaps : (n_levels,)
        The gap at each level in these runs [m].
    impacts : (n_records, n_levels) of int
        Impacts at each level.
    peak_force : (n_records, n_levels)
        Largest contact force at each level [N] (0 where it never closed).
    """

    gaps: FloatArray
    impacts: NDArray[np.int64]
    peak_force: FloatArray

    def pounded(self, levels: Sequence[int] | None = None) -> NDArray[np.bool_]:
        """Each record: any impact (at ``levels``, default all) (n_records,)."""
        cols = slice(None) if levels is None else list(levels)
        return np.asarray(self.impacts[:, cols].sum(axis=1) > 0)


@dataclass(frozen=True, eq=False)
class TimeHistoryCheck:
    """The time histories beside a code check (module docstring).

    Attributes
    ----------
    code : str
        The code's key.
    target : str
        The name of the spectrum the suite was scaled to.
    scaling : str
        How (method, rule, period range).
    records : tuple of str
        The records, in suite order.
    factors : (n_records,)
        Each record's scale factor [-].
    levels, pairs : tuple of str
        Each level's contact label (``B1F2-B2F2``) and pair (``B1-B2``), the check's rows'
        order.
    elevation, required : (n_levels,)
        Elevation [m] and the code's required separation [m] of each level.
    own, at_code : RunOutcomes
        The runs with the model's gaps and with every pair's gap at the code's.
    peak_closing : (n_records, n_levels)
        The smallest gap that prevents pounding at each level under each record [m]: the
        largest ``u_left − u_right`` of the buildings apart.
    duration : float or None
        Time simulated under every record [s] (None: each record's duration).
    """

    code: str
    target: str
    scaling: str
    records: tuple[str, ...]
    factors: FloatArray
    levels: tuple[str, ...]
    pairs: tuple[str, ...]
    elevation: FloatArray
    required: FloatArray
    own: RunOutcomes
    at_code: RunOutcomes
    peak_closing: FloatArray
    duration: float | None = None
    shaking_end: float = 0.0

    @property
    def factors_flagged(self) -> NDArray[np.bool_]:
        """True for a record scaled by a factor outside
        :data:`pounding.spectra.scaling.DEFAULT_LIMITS` (0.25–4, as ``pounding suite``
        flags them): far from its own intensity, a weak stand-in for the code's shaking."""
        from pounding.spectra.scaling import DEFAULT_LIMITS

        lo, hi = DEFAULT_LIMITS
        return np.asarray((self.factors < lo) | (self.factors > hi))

    def pair_levels(self, pair: str) -> list[int]:
        """The levels (indices) of ``pair``."""
        return [i for i, p in enumerate(self.pairs) if p == pair]

    @property
    def pair_names(self) -> list[str]:
        """The pairs, in order."""
        return list(dict.fromkeys(self.pairs))

    def closing_of_pair(self, pair: str) -> FloatArray:
        """Each record's smallest gap of ``pair`` that prevents pounding at every level of it
        [m]: the largest peak closing over its levels (n_records,)."""
        return np.asarray(self.peak_closing[:, self.pair_levels(pair)].max(axis=1))

    def code_gap(self, pair: str) -> float:
        """The gap of ``pair`` in the runs at the code's separation [m]."""
        return float(self.at_code.gaps[self.pair_levels(pair)[0]])

    @property
    def closes_past_required(self) -> NDArray[np.bool_]:
        """``(n_records, n_levels)``: the peak closing exceeds the code's separation at that
        level — a gap of the code's separation at each level would have been struck there."""
        return np.asarray(self.peak_closing > self.required[np.newaxis, :])

    def verdicts(self) -> list[str]:
        """One plain line a pair: how many records the code's gap kept from pounding, and
        the records' mean peak closing (the mean smallest gap that prevents pounding)."""
        out = []
        n = len(self.records)
        for pair in self.pair_names:
            idx = self.pair_levels(pair)
            kept = int(n - self.at_code.pounded(idx).sum())
            closing = self.closing_of_pair(pair)
            out.append(
                f"{pair}: the code's {1e3 * self.code_gap(pair):.1f} mm gap prevented pounding "
                f"in {kept} of {n} record{'s' if n != 1 else ''}; the records' mean peak "
                f"closing {1e3 * float(closing.mean()):.1f} mm (largest "
                f"{1e3 * float(closing.max()):.1f} mm)")
        if self.duration is not None and self.duration < self.shaking_end:
            out.append(f"caution: the runs stop at {self.duration:g} s, before the strong "
                       f"shaking of every record has ended ({100 * STRONG_SHAKING[1]:g} % of "
                       f"Arias intensity at up to {self.shaking_end:.3g} s): the verdicts are "
                       f"those of the first {self.duration:g} s")
        flagged = self.factors_flagged
        if flagged.any():
            from pounding.spectra.scaling import DEFAULT_LIMITS

            factors = sorted({f"{float(f):.3g}" for f in self.factors[flagged]})
            out.append(f"caution: scale factor {', '.join(factors)} outside "
                       f"{DEFAULT_LIMITS[0]:g}–{DEFAULT_LIMITS[1]:g} for {int(flagged.sum())} "
                       f"of {n} records: records scaled that far from their own intensity are "
                       "a weak stand-in for the code's shaking; choose records closer to it")
        return out

    def to_dict(self) -> dict[str, Any]:
        """The check as JSON-ready data (lengths in mm, forces in kN)."""
        def mm(x: Any) -> float:
            return float(1e3 * x)

        records = []
        for r, name in enumerate(self.records):
            records.append({
                "record": name, "factor": float(self.factors[r]),
                "factor_flagged": bool(self.factors_flagged[r]),
                "own_gap": {"pounded": bool(self.own.pounded()[r]),
                            "impacts": int(self.own.impacts[r].sum()),
                            "peak_force_kN": float(1e-3 * self.own.peak_force[r].max())},
                "code_gap": {"pounded": bool(self.at_code.pounded()[r]),
                             "impacts": int(self.at_code.impacts[r].sum()),
                             "peak_force_kN": float(1e-3 * self.at_code.peak_force[r].max())},
                "peak_closing_mm": {lv: mm(self.peak_closing[r, i])
                                    for i, lv in enumerate(self.levels)},
            })
        pairs = []
        for pair in self.pair_names:
            idx = self.pair_levels(pair)
            closing = self.closing_of_pair(pair)
            pairs.append({
                "pair": pair, "code_gap_mm": mm(self.code_gap(pair)),
                "own_gap_mm": mm(self.own.gaps[idx[0]]),
                "records_pounding_at_own_gap": int(self.own.pounded(idx).sum()),
                "records_pounding_at_code_gap": int(self.at_code.pounded(idx).sum()),
                "mean_peak_closing_mm": mm(closing.mean()),
                "largest_peak_closing_mm": mm(closing.max())})
        return {
            "units": "mm (gaps, closings), kN (forces), m (elevation)",
            "target": self.target, "scaling": self.scaling,
            "duration_s": self.duration,
            "strong_shaking_end_s": self.shaking_end,
            "runs": "each record twice: (a) the model's own gaps, (b) every pair's gap at "
                    "the code's separation (the largest the code asks for at its levels)",
            "peak_closing": "the smallest gap that prevents pounding: max(u_left - u_right) "
                            "with the buildings apart (the response until the first impact)",
            "verdicts": self.verdicts(),
            "levels": [{"pair": p, "contact": lv, "elevation_m": float(z),
                        "required_mm": mm(req),
                        "mean_peak_closing_mm": mm(self.peak_closing[:, i].mean()),
                        "records_closing_past_required":
                            int(self.closes_past_required[:, i].sum())}
                       for i, (p, lv, z, req) in enumerate(zip(
                           self.pairs, self.levels, self.elevation, self.required,
                           strict=True))],
            "pairs": pairs,
            "records": records,
        }


@dataclass(frozen=True)
class CodeCheckBeside(CodeCheck):
    """A :class:`CodeCheck` with its :class:`TimeHistoryCheck`: written by
    :func:`pounding.studies.codes.write_code_check` with a ``time_history`` block."""

    time_history: TimeHistoryCheck | None = None

    @classmethod
    def of(cls, check: CodeCheck, time_history: TimeHistoryCheck) -> CodeCheckBeside:
        """``check`` with ``time_history`` beside it."""
        return cls(**{f.name: getattr(check, f.name) for f in fields(check)},
                   time_history=time_history)

    def to_dict(self) -> dict[str, Any]:
        data = super().to_dict()
        if self.time_history is not None:
            data["time_history"] = self.time_history.to_dict()
        return data


def _with_gaps(model: Any, gaps: Sequence[float]) -> Any:
    """``model`` with other gaps between its neighbours (everything else the same)."""
    from pounding.model import PoundingModel

    return PoundingModel(model.buildings, gaps, model.contact, name=model.name,
                         floor_to_column=model.floor_to_column,
                         level_tolerance=model.level_tolerance, devices=model.devices,
                         walls=model.walls, bridge=model.bridge, stops=model.stops)


def refuse_linked(model: Any) -> None:
    """Refuse, in one line, a model whose buildings are tied by links: the peak closing of
    the time-history check needs the buildings apart (each run alone)."""
    if model.links:
        raise ValueError(f"model: the time-history check needs the buildings apart for the "
                         f"peak closing, and {len(model.links)} link(s) tie them together; "
                         "remove the links")


def time_history_check(model: Any, check: CodeCheck, motions: Sequence[Any], *,
                       target: Any = None, scaling_code: str | None = None,
                       solver: Mapping[str, Any] | None = None,
                       duration: float | None = None,
                       progress: Any = None) -> TimeHistoryCheck:
    """The time histories of ``model`` beside ``check`` under ``motions`` scaled to the
    code's spectrum (module docstring).

    Parameters
    ----------
    model : PoundingModel
        The model checked (``check`` must be its check: the levels are its contacts).
    check : CodeCheck
        :func:`pounding.studies.codes.code_check` of ``model``.
    motions : sequence of GroundMotion
        The suite, unscaled (a :class:`~pounding.ground_motion.RecordSuite` is one).
    target : DesignSpectrum, optional
        The spectrum the suite is scaled to; default :func:`code_spectrum`.
    scaling_code : {"asce7-22", "en1998-1"}, optional
        Whose rule scales the suite (:func:`pounding.spectra.scale_suite`); default the
        check's code where pounding has its rule for a suite, else ASCE 7-22's (said in
        :attr:`TimeHistoryCheck.scaling`).
    solver : mapping, optional
        Keyword arguments of :func:`pounding.integrate.simulate` (``dt``, ``rtol``, …: the
        model file's ``[solver]``); its ``duration`` (the model file's record's) is not
        used.
    duration : float, optional
        Time simulated under every record [s]; default each record's duration. It must
        reach every record's strong shaking (:func:`check_duration`); stopping before its
        end is said among the verdicts.
    progress : Progress, optional
        Called as ``progress(done, total)``: runs finished, and in all.

    Returns
    -------
    TimeHistoryCheck

    Raises
    ------
    ValueError
        One line: a check of another model, a model with links between its buildings (the
        peak closing needs the buildings apart), an empty suite, a target the scaling
        cannot use, a ``duration`` that ends before a record's strong shaking begins
        (:func:`check_duration`).
    """
    from pounding.integrate import simulate
    from pounding.spectra.scaling import CODES as SUITE_RULES
    from pounding.spectra.scaling import scale_suite
    from pounding.studies.codes.common import pair_contacts
    from pounding.studies.gap import critical_gaps

    motions = list(motions)
    if not motions:
        raise ValueError("records: the suite has no record")
    contacts = {c.label: c for c in pair_contacts(model)}
    unknown = [row.contact for row in check.rows if row.contact not in contacts]
    if unknown or not check.rows:
        raise ValueError(f"check: not a check of this model (its level {unknown[0]!r} is not "
                         f"one of the model's contacts)" if unknown else
                         "check: it has no level")
    refuse_linked(model)
    target = code_spectrum(check) if target is None else target
    rule = scaling_code if scaling_code is not None else (
        check.code if check.code in SUITE_RULES else "asce7-22")
    borrowed = "" if rule == check.code or scaling_code is not None else (
        f"; {check.code}'s own rule for a suite is not in pounding")
    firsts = [float(b.modes().periods[0]) for b in model.buildings]  # each one's T1 [s]
    t1 = max(firsts)
    period_range = (0.2 * min(firsts), 2.0 * t1)
    scaled = scale_suite(motions, target, t1, method="code", code=rule,
                         period_range=period_range)
    suite = [m.scaled(float(f)) for m, f in zip(motions, scaled.factors, strict=True)]

    rows = check.rows
    index = [contacts[row.contact].index for row in rows]
    required = np.array([row.required for row in rows])
    code_gaps = list(model.gaps)
    for p in {contacts[row.contact].pair for row in rows}:
        code_gaps[p] = max(row.required for row in rows if contacts[row.contact].pair == p)
    code_model = _with_gaps(model, code_gaps)

    if duration is not None:
        duration = check_duration(duration, motions)
    kwargs = {k: v for k, v in (solver or {}).items() if k != "duration"}
    kwargs["duration"] = duration
    same = tuple(code_gaps) == tuple(model.gaps)
    total = len(suite) * (1 if same else 2) + len(suite) * len(model.buildings)
    done = 0

    def step(n: int = 1) -> None:
        nonlocal done
        done += n
        if progress is not None:
            progress(done, total)

    def outcomes(m: Any) -> RunOutcomes:
        impacts = np.zeros((len(suite), len(rows)), dtype=np.int64)
        force = np.zeros((len(suite), len(rows)))
        for r, motion in enumerate(suite):
            result = simulate(m, motion, **kwargs)
            impacts[r] = result.impacts_per_contact[index]
            force[r] = result.peak_contact_force[index]
            step()
        gaps = np.array([m.contacts[i].gap for i in index])
        return RunOutcomes(gaps, impacts, force)

    own = outcomes(model)
    at_code = own if same else outcomes(code_model)
    study = critical_gaps(model, suite, dt=kwargs.get("dt"), duration=duration,
                          progress=None if progress is None else
                          (lambda d, t: progress(done + d, total)))
    step(len(suite) * len(model.buildings))
    where = {label: i for i, label in enumerate(study.labels)}
    closing = np.asarray(study.critical, dtype=float)[:, [where[row.contact] for row in rows]]
    lo, hi = scaled.period_range
    rule_text = {"asce7-22": "ASCE 7-22 §16.2.3", "en1998-1": "EN 1998-1 §3.2.3.1.2"}
    return TimeHistoryCheck(
        code=check.code, target=str(target.name),
        scaling=(f"one factor for the suite, its mean >= 90 % of the target from {lo:.3g} to "
                 f"{hi:.3g} s ({rule_text.get(rule, rule)}{borrowed}); factor "
                 f"{float(scaled.factors[0]):.4g}"),
        records=tuple(m.name for m in motions), factors=np.asarray(scaled.factors),
        levels=tuple(row.contact for row in rows), pairs=tuple(row.pair for row in rows),
        elevation=np.array([row.elevation for row in rows]), required=required,
        own=own, at_code=at_code, peak_closing=closing, duration=duration,
        shaking_end=max(float(m.arias_time(STRONG_SHAKING[1])) for m in motions))

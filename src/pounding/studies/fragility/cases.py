"""The cases of a study, as a sweep: every record of the suite at every intensity level (and
at every gap of ``[gap] values``), each a case of :mod:`pounding.studies.sweep` — so the runs
go on Dask, are saved batch by batch, resume after any interruption and give a table equal
bit for bit from one run to the next.

Each case sets the record (``record.bundled``, ``record.file`` or ``record.stochastic.index``;
with ``[suite] match`` the base model's ``[record] match`` matches it first) and its scaling:

* without ``[suite.scaling]`` every record is scaled so that its own intensity equals the
  level (incremental dynamic analysis: the stripe at level ``x`` has IM = ``x`` exactly):
  ``record.pga_g``, ``record.sa_g`` (with ``sa_period``, ``sa_damping``) or
  ``record.saavg_g`` (with ``saavg_periods``, ``saavg_n``, ``sa_damping``) = ``x``;
* with it, the suite is first scaled to the target spectrum (one factor ``f_i`` per record,
  :func:`pounding.spectra.scale_suite`) and a stripe at level ``x`` multiplies that suite by
  ``x / IM_target`` (``record.scale = f_i x / IM_target``): the stripe's intensity is the
  target's, the records keep their spread about it (multiple-stripe analysis of a
  code-scaled suite).
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from pounding.studies.fragility.study import StudyConfig, load_study

__all__ = ["StudyCases", "study_cases"]


@dataclass
class StudyCases:
    """A study file turned into its runs.

    Attributes
    ----------
    config : StudyConfig
    source : Path or None
        The study file.
    out : Path
        The output folder.
    records : list of str
        Record names (file stems; ``stochastic_01`` … for a simulated suite), in suite
        order.
    source_key : str
        ``"record.bundled"``, ``"record.file"`` or ``"record.stochastic.index"``.
    sources : list of str or int
        Each record's value of ``source_key``.
    levels : list of float
        Intensity levels [g].
    gaps : list of float or None
        ``[None]`` (the base model's gaps) or ``[gap] values`` [m].
    im_label : str
        The intensity measure for axes and tables, with its unit.
    saavg_range : (float, float) or None
        Periods of Sa_avg [s].
    factors : ndarray or None
        Suite scale factors to the target spectrum (``[suite.scaling]``), and
    im_target : float or None
        the target's intensity [g].
    periods : list of float
        Fundamental period of each building of the base model [s].
    sweep : Sweep
        The runs.
    rows : list of (int, int, int)
        Per case (in case order): record, level and gap index.
    record_note : str
        How each record shakes the model, where that needs saying (buildings in plan: one
        component along the base model's ``[record] incidence``); empty otherwise.
    """

    config: StudyConfig
    source: Path | None
    out: Path
    records: list[str]
    source_key: str
    sources: list[Any]
    levels: list[float]
    gaps: list[float | None]
    im_label: str
    saavg_range: tuple[float, float] | None
    factors: Any
    im_target: float | None
    periods: list[float]
    sweep: Any
    rows: list[tuple[int, int, int]] = field(repr=False, default_factory=list)
    record_note: str = ""
    bridge: Any = None
    """A bridge's :class:`~pounding.studies.fragility.bridge.BridgeSeatsLayout` (None: buildings):
    its runs set every joint's gap, and after them come its runs without joint contact."""
    needed_rows: list[tuple[int, int]] = field(repr=False, default_factory=list)
    """A bridge's runs without joint contact, after the study's :attr:`rows` in the sweep:
    record and index in :attr:`needed_levels` of each."""
    needed_levels: list[float] = field(default_factory=list)
    """The levels of those runs [g]: the study's, and the gap analysis' if it is none of
    them."""

    def case_values(self, record: int, level: float, gap: float | None = None,
                    joint_contact: bool = True) -> tuple[list[str], list[Any]]:
        """The sweep parameters and their values for ``record`` at ``level`` (any level,
        not only those of the study) and ``gap`` (None: the base model's). A bridge's case
        sets the gap of every joint (``gap``, else the base model's; without
        ``joint_contact``, :data:`~pounding.studies.fragility.bridge.NO_CONTACT_GAP`)."""
        params = [self.source_key]
        values: list[Any] = [self.sources[record]]
        if self.factors is not None:
            params.append("record.scale")
            assert self.im_target is not None  # set with the factors
            values.append(float(self.factors[record]) * level / float(self.im_target))
        else:
            params.append({"pga": "record.pga_g", "sa": "record.sa_g",
                           "saavg": "record.saavg_g"}[self.config.intensity.measure])
            values.append(float(level))
        if self.bridge is not None:
            from pounding.studies.fragility.bridge import NO_CONTACT_GAP

            params += self.bridge.params()
            values += [NO_CONTACT_GAP if not joint_contact else
                       float(gap) if gap is not None else g for g in self.bridge.joint_gaps]
        elif gap is not None:
            params.append("contact.gap")
            values.append(float(gap))
        return params, values

    def build(self, record: int, level: float) -> Any:
        """The model, motion and solver options of ``record`` at ``level``, exactly as
        the sweep's case builds them (:meth:`pounding.config.RunConfig.build`)."""
        from pounding.config import RunConfig
        from pounding.studies.sweep import apply_overrides

        params, values = self.case_values(record, level)
        data = apply_overrides(self.sweep.base, params, values)
        return RunConfig.model_validate(data, context={"base_dir": self.sweep.base_dir}).build()


def _suite(cfg: StudyConfig, here: Path) -> tuple[list[str], str, list[Any]]:
    """Names, the key that selects a record in a model file, and its value per record (a
    path or name; the index of a stochastic record)."""
    from pounding.ground_motion import RecordSuite, bundled_records

    s = cfg.suite
    if s.stochastic is not None:
        n = s.stochastic.count
        return ([f"stochastic_{i + 1:0{len(str(n))}d}" for i in range(n)],
                "record.stochastic.index", list(range(n)))
    if s.bundled:
        files = bundled_records()
        return [Path(f).stem for f in files], "record.bundled", [Path(f).stem for f in files]
    if s.folder is not None:
        suite = RecordSuite.from_folder(here / s.folder, dt=s.dt, units=s.units)
    else:
        suite = RecordSuite.from_paths([here / f for f in s.files or []], dt=s.dt,
                                       units=s.units)
    paths = [str(Path(p).resolve()) for p in suite.paths]
    if len(set(paths)) != len(paths):
        raise ValueError("suite.files: a record is given twice")
    return [Path(p).stem for p in paths], "record.file", paths


def study_cases(study: str | os.PathLike[str] | StudyConfig,
                folder: str | os.PathLike[str] | None = None,
                out: str | os.PathLike[str] | None = None) -> StudyCases:
    """The cases of a study: validate it, read its suite and build the sweep of its runs.

    Parameters
    ----------
    study : path or StudyConfig
        The study file, or a validated one (then ``folder`` is where its relative paths
        start).
    out : path, optional
        The output folder (default ``out`` of the file, relative to it, else ``<study file
        stem>-results`` in the current folder,
        :func:`pounding.io.output_folder.default_out_dir`; ``<name>-results`` in the current
        folder for a study not read from a file).

    Raises
    ------
    ValueError
        One line naming the key: a bad study file, base model or record.
    """
    import warnings

    from pounding.config import load_config
    from pounding.plausibility import PlausibilityWarning
    from pounding.spectra import fundamental_mode
    from pounding.studies.sweep import parse_sweep

    source: Path | None = None  # the study file, resolved
    given: Path | None = None  # the study file as given
    if isinstance(study, StudyConfig):
        cfg, here = study, Path(folder or ".").resolve()
    else:
        given = Path(study)
        source = given.resolve()
        cfg, here = load_study(study)
    where = str(source) if source else "study"
    model_file = here / cfg.base
    base_cfg = load_config(model_file)
    model, _, _ = base_cfg.build()
    from pounding.studies.fragility.bridge import bridge_layout, check_joint

    bridge = bridge_layout(model)
    if bridge is not None and bridge.n_joints == 0:
        raise ValueError(f"{where}: base: the bridge of {model_file} has one frame; a "
                         "fragility study of a bridge needs an expansion joint (two frames "
                         "or more)")
    for i, ls in enumerate(cfg.limit_state):
        check_joint(ls, bridge, where, i, cfg.base)
    if len(model.buildings) < 2:
        raise ValueError(f"{where}: base: {model_file} has one building; a fragility study of "
                         "pounding needs two or more buildings"
                         + (" (a moat wall is not supported here yet: pounding gap gives the "
                            "moat width a record needs, pounding sweep over wall.gap the rest)"
                            if model.walls else ""))
    _check_demands(cfg, model, where)
    periods = [float(fundamental_mode(b)[0]) for b in model.buildings]
    try:
        names, key, sources = _suite(cfg, here)
    except ValueError as exc:
        raise ValueError(f"{where}: suite: {exc}") from None
    if len(names) < 2:
        raise ValueError(f"{where}: suite: a study needs at least two records (got "
                         f"{len(names)})")
    levels = cfg.intensity.level_values()
    it = cfg.intensity
    base = base_cfg.to_dict(resolve_paths=True)
    rec: dict[str, Any] = ({"stochastic": cfg.suite.stochastic.record(0)}
                           if cfg.suite.stochastic is not None
                           else {key.split(".")[1]: sources[0]})
    if cfg.suite.match is not None:
        m = cfg.suite.match
        target = (here / m.target).resolve()
        if not target.is_file():
            raise ValueError(f"{where}: suite.match.target: no such spectrum file "
                             f"{str(target)!r} (got {m.target!r}; relative paths start at "
                             "the study file's folder)")
        rec["match"] = {"target": str(target), "range": list(m.range),
                        "tolerance": m.tolerance, "iterations": m.iterations}
    if cfg.suite.duration is not None:
        rec["duration"] = cfg.suite.duration
    if key == "record.file":
        for k in ("dt", "units"):
            if getattr(cfg.suite, k) is not None:
                rec[k] = getattr(cfg.suite, k)
    saavg: tuple[float, float] | None = None
    if it.measure == "saavg":
        lo, hi = it.periods if it.periods else (0.2 * min(periods), 3.0 * max(periods))
        saavg = (float(lo), float(hi))
    factors, im_target = None, None
    if cfg.suite.scaling is None:
        if it.measure == "sa":
            rec.update(sa_period=it.period, sa_damping=it.damping)
        elif it.measure == "saavg":
            assert saavg is not None
            rec.update(saavg_periods=list(saavg), saavg_n=it.n_periods, sa_damping=it.damping)
    note = ""
    if base_cfg.in_plan:
        # a record of the suite is one component: it shakes the buildings in plan along the
        # base model's incidence (its second component, if any, belongs to its own record)
        incidence = base_cfg.record.incidence or 0.0
        rec["incidence"] = incidence
        note = (f"buildings in plan: each record of the suite shakes them alone along the "
                f"incidence {incidence:g}° ([record] incidence of {cfg.base})"
                + (f"; the base model's second component ([record] "
                   f"{'second' if base_cfg.record.second else 'second_file'}) is not used"
                   if base_cfg.record.two_components else ""))
    base["record"] = rec
    cases = StudyCases(config=cfg, source=source,
                       out=_out_folder(cfg, here, out, where, given),
                       records=names, source_key=key,
                       sources=sources, levels=levels,
                       gaps=list(cfg.gap.values) if cfg.gap.values else [None],
                       im_label=_im_label(cfg, saavg), saavg_range=saavg, factors=None,
                       im_target=None, periods=periods, sweep=None, record_note=note,
                       bridge=bridge)
    if cfg.suite.scaling is not None:
        factors, im_target = _suite_factors(cases, base, here, model_file.parent, where)
        cases.factors, cases.im_target = factors, im_target
    first_params, first_values = cases.case_values(0, levels[0])
    for p, v in zip(first_params, first_values):
        if p.startswith("record."):
            node, *rest = p.split(".")[1:]
            if rest:  # record.stochastic.index
                rec[node][rest[0]] = v
            else:
                rec[node] = v
    rows: list[tuple[int, int, int]] = []
    cols: dict[str, list[Any]] = {p: [] for p in cases.case_values(0, levels[0],
                                                                   cases.gaps[0])[0]}
    for gi, g in enumerate(cases.gaps):
        for ri in range(len(names)):
            for li, x in enumerate(levels):
                params, values = cases.case_values(ri, x, g)
                for p, v in zip(params, values):
                    cols[p].append(v)
                rows.append((ri, li, gi))
    if bridge is not None:  # the runs that find the gap the joints need
        at = cfg.gap_at()
        cases.needed_levels = list(levels) + ([] if at in levels else [at])
        for ri in range(len(names)):
            for li, x in enumerate(cases.needed_levels):
                params, values = cases.case_values(ri, x, joint_contact=False)
                for p, v in zip(params, values):
                    cols[p].append(v)
                cases.needed_rows.append((ri, li))
    data: dict[str, Any] = {"name": cfg.name, "base": base, "list": cols,
            "histories": cfg.run.histories or False}
    if cfg.run.batch_size is not None:
        data["batch_size"] = cfg.run.batch_size
    with warnings.catch_warnings():  # the base model's were issued when it was loaded
        warnings.simplefilter("ignore", PlausibilityWarning)
        cases.sweep = parse_sweep(data, base_dir=model_file.parent, where=where)
    cases.sweep.source = source
    cases.rows = rows
    if cfg.suite.match is not None:
        _match_suite(cases, where)
    return cases


def _match_suite(cases: StudyCases, where: str) -> None:
    """Match every seed record now (remembered for the runs of this process), so a record
    that cannot be matched is refused in one line before anything is written."""
    from pounding.config import RunConfig
    from pounding.studies.sweep import apply_overrides

    for ri, name in enumerate(cases.records):
        data = apply_overrides(cases.sweep.base, [cases.source_key, "record.scale"],
                               [cases.sources[ri], 1.0])
        for k in ("pga_g", "sa_g", "sa_period", "sa_damping", "saavg_g", "saavg_periods",
                  "saavg_n"):
            data["record"].pop(k, None)
        try:
            RunConfig.model_validate(data, context={"base_dir": cases.sweep.base_dir}
                                     ).record.load()
        except ValueError as exc:
            raise ValueError(f"{where}: suite.match: record {name!r}: "
                             f"{str(exc).removeprefix('match: ')}") from None


def _check_demands(cfg: StudyConfig, model: Any, where: str) -> None:
    """Refuse, in one line, a limit state on a demand the base model cannot have: storey
    ductility without yielding storeys, a plastic rotation without plastic hinges, collapse
    of buildings that stay linear."""
    hinges = bool(model.yielding_frames)
    for i, ls in enumerate(cfg.limit_state):
        what = None
        if ls.demand == "ductility" and not model.is_inelastic:
            what = "yielding storeys"
        elif ls.demand == "plastic_rotation" and not hinges:
            what = "a frame with plastic hinges (building.frame with column_hinge / beam_hinge)"
        elif ls.demand == "collapse" and not (hinges or model.is_inelastic):
            what = "yielding storeys or a frame with plastic hinges"
        if what is not None:
            state = "have no plastic hinges" if ls.demand == "plastic_rotation" else "are linear"
            raise ValueError(f"{where}: limit_state[{i}].demand: \"{ls.demand}\" needs {what}, "
                             f"and the buildings of {cfg.base} {state} (got '{ls.demand}')")


def _out_folder(cfg: StudyConfig, here: Path, out: str | os.PathLike[str] | None,
                where: str, file: Path | None) -> Path:
    """The output folder: ``out`` given (the command line's ``--out``), else ``out`` of the
    study file — inside the file's folder (:func:`pounding.io.files.study_out`) — else
    ``<file stem>-results`` in the current folder
    (:func:`pounding.io.output_folder.default_out_dir`; ``<name>-results`` for a study not read
    from a file); the name is a label (:func:`pounding.io.files.check_label`).
    """
    from pounding.io.files import check_label, study_out
    from pounding.io.output_folder import default_out_dir

    name = check_label(cfg.name, where)
    if out is not None:
        return Path(out)
    if cfg.out is None:
        return default_out_dir(file if file is not None else f"{name}.toml")
    folder, refused = study_out(here, cfg.out, where)
    if refused is not None:
        raise ValueError(refused)
    return folder


def _im_label(cfg: StudyConfig, saavg: tuple[float, float] | None) -> str:
    it = cfg.intensity
    z = f"{100 * it.damping:g} %"
    if it.measure == "pga":
        return "PGA [g]"
    if it.measure == "sa":
        return f"Sa({it.period:g} s, {z}) [g]"
    assert saavg is not None
    return f"Sa_avg({saavg[0]:.3g}–{saavg[1]:.3g} s, {z}) [g]"


def _suite_factors(cases: StudyCases, base: dict[str, Any], here: Path, base_dir: Path,
                   where: str) -> tuple[Any, float]:
    """Scale factors of the suite to the target spectrum and the target's intensity [g]."""
    from pounding.config import RunConfig
    from pounding.spectra import DesignSpectrum, scale_suite
    from pounding.studies.sweep import apply_overrides

    sc = cases.config.suite.scaling
    it = cases.config.intensity
    assert sc is not None
    try:
        target = DesignSpectrum.from_file(here / sc.target)
    except ValueError as exc:
        raise ValueError(f"{where}: suite.scaling.target: {exc}") from None
    motions = []
    for ri in range(len(cases.records)):
        data = apply_overrides(base, [cases.source_key, "record.scale"],
                               [cases.sources[ri], 1.0])
        with_ctx = RunConfig.model_validate(data, context={"base_dir": base_dir})
        motions.append(with_ctx.record.load())
    try:
        s = scale_suite(motions, target, sc.period, method=sc.method, code=sc.code,
                        damping=it.damping)
        if it.measure == "pga":
            t = np.array([0.0])
        elif it.measure == "sa":
            t = np.array([it.period])
        else:
            from pounding.spectra.scaling import saavg_periods

            assert cases.saavg_range is not None
            t = saavg_periods(cases.saavg_range, it.n_periods)
        sa = np.asarray(target.sa_g(t), dtype=float)
    except ValueError as exc:
        raise ValueError(f"{where}: suite.scaling: {exc}") from None
    return s.factors, float(np.exp(np.mean(np.log(sa))))

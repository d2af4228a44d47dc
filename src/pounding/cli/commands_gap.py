"""`pounding gap`: the critical separation gap by simulation, beside the code rules."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.running import progress_bar
from pounding.cli.tables import Col, building_label, print_table


def _mm(value: float) -> str:
    """A gap [m] in mm, to 0.1 mm (every gap of the screen in one unit)."""
    return f"{1000.0 * value:.1f}"


def _ratio_cell(value: float, reference: float) -> str:
    """A rule's gap [m] in mm, and its ratio to the simulated one."""
    if reference > 0.0:
        return f"{_mm(value)} (×{value / reference:.2f})"
    return f"{_mm(value)} (-)"


def _read_file(f: Path, option: str, dt: float | None, units: str | None,
               choice: dict[str, int | None] | None = None) -> Any:
    from pounding.ground_motion import read_record

    if not f.is_file():
        raise ValueError(f"{option}: {f}: " + ("is a directory, not a record file"
                                               if f.is_dir() else "no such file"))
    return read_record(f, dt=dt, units=units, **(choice or {}))


def _load_records(cfg: Any, files: list[Path], seconds: list[Path], dt: float | None,
                  units: str | None, unscaled: bool,
                  choice: dict[str, int | None] | None = None) -> tuple[list[Any], str]:
    """The ground motions and a sentence saying how they were obtained: for a model with
    buildings in plan, each record's x and y site components (its second component, if
    given, orthogonal to it; both turned to the model's ``[record] incidence``)."""
    from pounding.ground_motion import GroundMotionComponents
    from pounding.ground_motion.incidence import at_incidence

    rec = cfg.record
    in_plan = cfg.in_plan
    if seconds and not in_plan:
        raise ValueError("--second: a second horizontal component is for a model with "
                         "buildings in plan; these buildings are planar, shaken along the row")
    if seconds and len(seconds) != len(files):
        raise ValueError(f"--second: give one second component for each --records file "
                         f"({len(files)}), in the same order (got {len(seconds)})")
    if not files:
        motion = rec.load(components=in_plan)
        how = ("record: [record] of the model file"
               + (" (its two components, [record] second, at the incidence "
                  f"{rec.incidence or 0.0:g}°)" if in_plan and rec.two_components else
                  f" (one component, along the incidence {rec.incidence or 0.0:g}°)"
                  if in_plan else "")
               + (f", trimmed to {rec.duration:g} s" if rec.duration is not None else "")
               + (f", scaled ×{rec.scale:g}" if rec.scale is not None else "")
               + (f", scaled to PGA {rec.pga_g:g} g" if rec.pga_g is not None else ""))
        return [motion], how
    motions = []
    for k, f in enumerate(files):
        pair = [_read_file(f, "--records", dt, units, choice)]
        if seconds:
            pair.append(_read_file(seconds[k], "--second", dt, units))
        if rec.duration is not None:
            pair = [gm.trimmed(rec.duration) for gm in pair]
        if not unscaled:
            # the second component by the first's factor, as the model file's record
            factor = 1.0
            if rec.scale is not None:
                factor = rec.scale
            if rec.pga_g is not None:
                factor = pair[0].scaled(factor).scaled_to_pga(rec.pga_g).pga / pair[0].pga
            pair = [gm.scaled(factor) for gm in pair]
        if in_plan:
            x, y = at_incidence(pair[0], pair[1] if len(pair) > 1 else None,
                                rec.incidence or 0.0)
            motions.append(GroundMotionComponents.of(x, y, name=x.name))
        else:
            motions.append(pair[0])
    steps = []
    if in_plan:
        steps.append(("each with its --second component" if seconds else
                      "each one component alone")
                     + f" at the incidence {rec.incidence or 0.0:g}° ([record] incidence)")
    if rec.duration is not None:
        steps.append(f"each trimmed to {rec.duration:g} s ([record] duration)")
    if unscaled or (rec.scale is None and rec.pga_g is None):
        steps.append("as recorded, not scaled"
                     + (" (--unscaled)" if unscaled and (rec.scale or rec.pga_g) else ""))
    elif rec.scale is not None:
        steps.append(f"each scaled ×{rec.scale:g} ([record] scale of the model file)")
    else:
        steps.append(f"each scaled to PGA {rec.pga_g:g} g ([record] pga_g of the model file)")
    return motions, "records: --records files, " + ", ".join(steps)


def _floors(building: Any) -> str:
    """``3 floors in plan``, ``5 storeys on isolators``, ``10 storey(s)``."""
    from pounding.structure.isolation import SuperstructureDamping

    plan = getattr(building, "plan", None)
    if plan is not None:
        return f"{plan.n_floors} floor(s) in plan"
    if isinstance(getattr(building, "damping", None), SuperstructureDamping):
        return f"{building.n - 1} storey(s) on isolators (floor 1: the base slab)"
    return f"{building.n} storey(s)"


def _isolated_period(building: Any) -> str:
    """For a base-isolated building, its period on the bearings once they slide or yield
    (the superstructure taken as rigid): a friction pendulum's ``2π √(R/g)``, a bilinear
    isolator's ``2π √(M / k₂)`` with ``M`` the whole building's mass; else ``""``.

    The ``T1`` beside it is of the bearings at their initial stiffness (stuck or elastic),
    which is what the linear analysis of the building alone gives."""
    import math

    import numpy as np

    from pounding.hysteresis.isolators import BilinearIsolator, FrictionPendulum

    iso = getattr(building, "isolator", None)
    if isinstance(iso, FrictionPendulum):
        return f" (bearings stuck; sliding: {iso.period:.4g} s, 2π√(R/g))"
    if isinstance(iso, BilinearIsolator) and iso.post_yield_stiffness > 0.0:
        period = 2.0 * math.pi * math.sqrt(float(np.sum(building.masses))
                                           / iso.post_yield_stiffness)
        return f" (bearings elastic; yielded: {period:.4g} s, 2π√(M/k₂))"
    return ""


@app.command("gap")
def gap_cmd(
    model: Annotated[Path, typer.Argument(
        help="TOML model file, as for `pounding run` (its gaps and contact "
                              "law are not used).", show_default=False)],
    more_records: Annotated[list[Path] | None, typer.Argument(
        metavar="RECORDS", help="More record files, after --records FILE.",
        show_default=False)] = None,
    records: Annotated[list[Path] | None, typer.Option(
        "--records", metavar="FILE", help="Record files (PEER .AT2 or text, read as by "
        "`pounding record`): --records A.AT2 B.AT2 ... or --records A --records B. "
        "Default: the model file's \\[record], whose duration, scale and pga_g are also "
        "applied to every file given here (see --unscaled).", show_default=False)] = None,
    dt: opt.Dt = None,
    units: opt.RecordUnits = None,
    column: opt.Column = None,
    time_column: opt.TimeColumn = None,
    channel: opt.Channel = None,
    second: Annotated[list[Path] | None, typer.Option(
        "--second", metavar="FILE", help="For a model with buildings in plan: the second "
        "horizontal component of each --records file, in the same order (orthogonal to it; "
        "both turned to the model's \\[record] incidence). Without it each file shakes "
        "alone along the incidence.", show_default=False)] = None,
    unscaled: Annotated[bool, typer.Option(
        "--unscaled", help="Use the --records files as recorded: ignore the model file's "
                           "\\[record] scale / pga_g.")] = False,
    duration: Annotated[float | None, typer.Option(
        "--duration", metavar="SECONDS", help="Time simulated \\[s] for every record. "
        "Default: \\[solver] duration of the model file, else each record's duration.",
        show_default=False)] = None,
    design: Annotated[Path | None, typer.Option(
        "--design", metavar="FILE", help=opt.DESIGN_HELP + " Adds the code rules from "
        "fundamental-mode spectral displacements (docs/gap.md).", show_default=False)] = None,
    plot: Annotated[Path | None, typer.Option(
        "--plot", metavar="FILE", help=opt.PLOT_HELP + " The figure: the critical gap "
        "against elevation.", show_default=False)] = None,
    csv: Annotated[Path | None, typer.Option(
        "--csv", metavar="FILE", help=opt.CSV_HELP + " One row per contact level: pair, "
        "contact, elevation_m, critical_m\\[record] of each record, mean_m, max_m, the rules "
        "\\[m] and their ratios to the simulated max and mean.", show_default=False)] = None,
    workers: opt.WorkersFew = None,
    scheduler: opt.SchedulerFew = None,
) -> None:
    """Critical separation gap per floor level by simulation, beside ABS, SRSS and DDC.

    Buildings in plan: the gap at the two ends of the stretch where their façades face
    each other, under the two ground components. A base-isolated building beside a moat
    wall: the moat width it needs on each side.

    Examples:

      pounding gap examples/two_10_storey.toml

      pounding gap examples/torsional_pair.toml

      pounding gap examples/isolated_moat_wall.toml

      pounding gap model.toml --records A.AT2 B.AT2 --csv gaps.csv --plot gaps.png

      pounding gap model.toml --design examples/spectrum_asce7_site.toml
    """
    from pounding.config import load_config
    from pounding.io.files import check_output_file
    from pounding.spectra import DesignSpectrum

    check_output_file(csv, "--csv")
    check_output_file(plot, "--plot", figure=True)
    from pounding.studies.gap import critical_gaps

    if more_records and not records:
        raise ValueError(f"unexpected argument(s) {', '.join(map(str, more_records))}: "
                         "give record files after --records")
    files = [*(records or []), *(more_records or [])]
    cfg = load_config(model)
    pounding_model, _, solver = cfg.build()
    if len(pounding_model.buildings) < 2 and not pounding_model.walls:
        raise ValueError(f"{model}: a gap study needs two or more buildings, or a "
                         f"building beside a moat wall ([[wall]]) (got "
                         f"{len(pounding_model.buildings)} building and no wall)")
    if pounding_model.links:
        raise ValueError(f"{model}: pounding gap simulates each building alone, and "
                         f"the model's {len(pounding_model.links)} link(s) ([[device]]) tie "
                         "them together; remove the links, or use pounding run at several "
                         "gaps")
    spec = DesignSpectrum.from_file(design) if design is not None else None
    if spec is not None and cfg.in_plan:
        raise ValueError("--design: the code rules from a design spectrum take each "
                         "building's fundamental mode along the row, and a building in plan "
                         "sways and twists in modes of its own; leave out --design (the "
                         "rules from the simulated peaks are in the table)")
    if spec is not None:  # fail before simulating if a fundamental period is off the table
        for bl in pounding_model.buildings:
            spec.sd(bl.fundamental_period)
    motions, how = _load_records(cfg, files, list(second or []), dt,
                                 None if units is None else str(units), unscaled,
                                 {"column": column, "time_column": time_column,
                                  "channel": channel})
    sim_duration = duration if duration is not None else solver.get("duration")
    with progress_bar(f"{len(pounding_model.buildings)} buildings alone under {len(motions)} "
                      "record(s)", "runs") as progress:
        study = critical_gaps(pounding_model, motions, dt=solver.get("dt"),
                              duration=sim_duration, scheduler=scheduler, n_workers=workers,
                              progress=progress)
    if spec is not None:
        spec_peaks = study.spectral_peaks(spec)
        spec_rules = study.rules_from_spectrum(spec)

    head = [(building_label(b, bl.name),
             f"{_floors(bl)}, T1 = {study.period[b]:.4g} s{_isolated_period(bl)}, "
             f"ζ1 = {study.zeta[b]:.3g}")
            for b, bl in enumerate(pounding_model.buildings)]
    head += [(f"ρ B{p + 1}-B{p + 2}", f"{rho:.4f} (CQC, fundamental modes)")
             for p, rho in enumerate(study.rho)]
    head += [(f"R{i + 1}", f"{m.name}: PGA {m.pga_g:.3f} g, simulated "
                           f"{study.durations[i]:g} s") for i, m in enumerate(motions)]
    head.append(("output step", f"{study.dt:g} s (peaks refined between samples)"))
    print_table(console, f"{pounding_model.name}: buildings and records",
                [Col("quantity", "left", wrap=True), Col("value", "left", wrap=True)], head,
                show_header=False)
    console.print(Text(how))

    names = list(study.records)
    plan_points = any("@y=" in label for label in study.labels)
    rules = study.rules_from_peaks("mean")
    cols = [Col("pair", "left"), Col("level [m]"),
            *([Col("contact", "left", wrap=True)] if plan_points else []),
            *(Col(f"R{i + 1}") for i in range(len(names))), Col("mean"), Col("max"),
            *(Col(rule, wrap=True) for rule in rules)]
    mean, top = study.mean_critical, study.max_critical
    rows = [[study.gap_names[k], f"{study.elevation[k]:g}",
             *([study.labels[k]] if plan_points else []),
             *(_mm(study.critical[i, k]) for i in range(len(names))),
             _mm(mean[k]), _mm(top[k]),
             *(_ratio_cell(float(v[k]), float(top[k])) for v in rules.values())]
            for k in range(study.n_levels)]
    print_table(console, f"{pounding_model.name}: critical separation gap [mm] by simulation "
                "and code rules", cols, rows, keys=2,
                caption="R1, R2, ...: critical gap = max over time of u_left − u_right from "
                        "each building simulated alone (no contact), 0 if never positive"
                        + ("; in plan, u of the contact point along x (the floor's sway and "
                           "twist)" if plan_points else "")
                        + ("; beside a moat wall, the building's largest displacement toward "
                           "the wall (the moat width it needs)" if pounding_model.walls else "")
                        + ". ABS = u1 + u2, SRSS = sqrt(u1² + u2²), DDC = sqrt(u1² + u2² − "
                        "2ρu1u2), with u1, u2 the mean over records of each building's "
                        "simulated peak |u| at that level; (×r) = rule / max simulated.")

    if spec is not None:
        cols = [Col("pair", "left"), Col("level [m]"), Col("u1 [mm]"), Col("u2 [mm]"),
                *(Col(rule, wrap=True) for rule in spec_rules)]
        rows = [[study.gap_names[k], f"{study.elevation[k]:g}",
                 _mm(spec_peaks[0][k]), _mm(spec_peaks[1][k]),
                 *(_ratio_cell(float(v[k]), float(top[k])) for v in spec_rules.values())]
                for k in range(study.n_levels)]
        print_table(console, f"Code rules from the design spectrum {spec.name!r} [mm] "
                    "(fundamental mode: u = |Γ1 φ1| Sd(T1))", cols, rows, keys=2,
                    caption="Sd(T1) [mm]: " + ", ".join(
                        f"B{b + 1} {_mm(float(spec.sd(study.period[b])))}"
                        for b in range(len(pounding_model.buildings)))
                    + "; (×r) = rule / max simulated")

    gov = study.governing_gaps()
    between = {f"B{p + 1}-B{p + 2}" for p in range(len(pounding_model.buildings) - 1)}
    if between:
        console.print(Text("governing critical gap per pair (max over levels and records): "
                           + ", ".join(f"{name} {_mm(g)} mm" for name, g in gov.items()
                                       if name in between)))
    if pounding_model.walls:
        console.print(Text("moat width needed (the building's largest displacement toward "
                            "each wall, max over records): " + ", ".join(
                                f"{name} {_mm(g)} mm" for name, g in gov.items()
                                if name not in between)))
    if csv is not None:
        from pounding.io.files import write_text

        write_text(csv, study.to_frame(spec).to_csv(index=False))
        console.print(f"table: {csv}", highlight=False)
    if plot is not None:
        from pounding.plot import save_figure
        from pounding.plot.gap import plot_gap_study

        console.print(f"figure: {save_figure(plot_gap_study(study, spec), plot)}",
                      highlight=False)

"""`pounding gap`: the critical separation gap by simulation, beside the code rules."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer
from rich.text import Text

from pounding.cli.app import app, console  # noqa: F401
from pounding.cli.tables import Col, building_label, print_table


def _ratio_cell(value: float, reference: float) -> str:
    if reference > 0.0:
        return f"{value:.4f} (×{value / reference:.2f})"
    return f"{value:.4f} (-)"


def _load_records(cfg: Any, files: list[Path], dt: float | None, units: str | None,
                  unscaled: bool) -> tuple[list[Any], str]:
    """The ground motions and a sentence saying how they were obtained."""
    from pounding.ground_motion import read_record

    rec = cfg.record
    if not files:
        motion = rec.load()
        how = ("record: [record] of the model file"
               + (f", trimmed to {rec.duration:g} s" if rec.duration is not None else "")
               + (f", scaled ×{rec.scale:g}" if rec.scale is not None else "")
               + (f", scaled to PGA {rec.pga_g:g} g" if rec.pga_g is not None else ""))
        return [motion], how
    motions = []
    for f in files:
        if not f.is_file():
            raise ValueError(f"--records: {f}: " + ("is a directory, not a record file"
                                                    if f.is_dir() else "no such file"))
        gm = read_record(f, dt=dt, units=units)
        if rec.duration is not None:
            gm = gm.trimmed(rec.duration)
        if not unscaled:
            if rec.scale is not None:
                gm = gm.scaled(rec.scale)
            if rec.pga_g is not None:
                gm = gm.scaled_to_pga(rec.pga_g)
        motions.append(gm)
    steps = []
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
    dt: Annotated[float | None, typer.Option(
        "--dt", help="Time step \\[s] for record files that do not give one.")] = None,
    units: Annotated[str | None, typer.Option(
        "--units", help="Acceleration unit for record files that do not state one.")] = None,
    unscaled: Annotated[bool, typer.Option(
        "--unscaled", help="Use the --records files as recorded: ignore the model file's "
                           "\\[record] scale / pga_g.")] = False,
    duration: Annotated[float | None, typer.Option(
        "--duration", help="Time simulated \\[s] for every record (default: \\[solver] "
                           "duration of the model file, else each record's duration).")] = None,
    spectrum: Annotated[Path | None, typer.Option(
        "--spectrum", metavar="FILE", help="Design spectrum (TOML: kind, units, periods, "
        "values; or asce7 = {sds, sd1, tl}; or eurocode8 = {agr, ground_type, type, "
        "importance, damping}; or CSV: period_s and sa_g, sa_m_s2 or sd_m); adds the rules "
        "from fundamental-mode spectral displacements. See docs/gap.md, docs/spectra.md.")
    ] = None,
    plot: Annotated[Path | None, typer.Option(
        "--plot", metavar="FILE", help="Draw gap against elevation to FILE (.png, .svg, .pdf).")
    ] = None,
    csv: Annotated[Path | None, typer.Option(
        "--csv", metavar="FILE", help="Write the table (all numbers) to FILE.")] = None,
) -> None:
    """Critical separation gap per floor level by simulation, beside ABS, SRSS and DDC.

    Examples:

      pounding gap examples/two_10_storey.toml

      pounding gap model.toml A.AT2 B.AT2 --csv gaps.csv --plot gaps.png
    """
    from pounding.config import load_config
    from pounding.io import check_output_file
    from pounding.spectra import DesignSpectrum

    check_output_file(csv, "--csv")
    check_output_file(plot, "--plot", figure=True)
    from pounding.studies.gap import critical_gaps

    if more_records and not records:
        raise ValueError(f"unexpected argument(s) {', '.join(map(str, more_records))}: "
                         "give record files after --records")
    files = [*(records or []), *(more_records or [])]
    model_path = model
    cfg = load_config(model_path)
    model, _, solver = cfg.build()
    if len(model.buildings) < 2:
        raise ValueError(f"{model_path}: a gap study needs at least two buildings "
                         f"(got {len(model.buildings)})")
    spec = DesignSpectrum.from_file(spectrum) if spectrum is not None else None
    if spec is not None:  # fail before simulating if a fundamental period is off the table
        for bl in model.buildings:
            spec.sd(bl.fundamental_period)
    motions, how = _load_records(cfg, files, dt, units, unscaled)
    sim_duration = duration if duration is not None else solver.get("duration")
    with console.status(f"simulating {len(model.buildings)} buildings alone under "
                        f"{len(motions)} record(s) ..."):
        study = critical_gaps(model, motions, dt=solver.get("dt"), duration=sim_duration)
    if spec is not None:
        spec_peaks = study.spectral_peaks(spec)
        spec_rules = study.rules_from_spectrum(spec)

    head = [(building_label(b, bl.name),
             f"{bl.n} storey(s), T1 = {study.period[b]:.4g} s, ζ1 = {study.zeta[b]:.3g}")
            for b, bl in enumerate(model.buildings)]
    head += [(f"ρ B{p + 1}-B{p + 2}", f"{rho:.4f} (CQC, fundamental modes)")
             for p, rho in enumerate(study.rho)]
    head += [(f"R{i + 1}", f"{m.name}: PGA {m.pga_g:.3f} g, simulated "
                           f"{study.durations[i]:g} s") for i, m in enumerate(motions)]
    head.append(("output step", f"{study.dt:g} s (peaks refined between samples)"))
    print_table(console, f"{model.name}: buildings and records",
                [Col("quantity", "left", wrap=True), Col("value", "left", wrap=True)], head,
                show_header=False)
    console.print(Text(how))

    names = list(study.records)
    rules = study.rules_from_peaks("mean")
    cols = [Col("pair", "left"), Col("level [m]"),
            *(Col(f"R{i + 1}") for i in range(len(names))), Col("mean"), Col("max"),
            *(Col(rule, wrap=True) for rule in rules)]
    mean, top = study.mean_critical, study.max_critical
    rows = [[f"B{study.pair[k] + 1}-B{study.pair[k] + 2}", f"{study.elevation[k]:g}",
             *(f"{study.critical[i, k]:.4f}" for i in range(len(names))),
             f"{mean[k]:.4f}", f"{top[k]:.4f}",
             *(_ratio_cell(float(v[k]), float(top[k])) for v in rules.values())]
            for k in range(study.n_levels)]
    print_table(console, f"{model.name}: critical separation gap [m] by simulation and code "
                "rules", cols, rows, keys=2,
                caption="R1, R2, ...: critical gap = max over time of u_left − u_right from "
                        "each building simulated alone (no contact), 0 if never positive. ABS "
                        "= u1 + u2, SRSS = sqrt(u1² + u2²), DDC = sqrt(u1² + u2² − 2ρu1u2), "
                        "with u1, u2 the mean over records of each building's simulated peak "
                        "|u| at that level; (×r) = rule / max simulated.")

    if spec is not None:
        cols = [Col("pair", "left"), Col("level [m]"), Col("u1 [m]"), Col("u2 [m]"),
                *(Col(rule, wrap=True) for rule in spec_rules)]
        rows = [[f"B{study.pair[k] + 1}-B{study.pair[k] + 2}", f"{study.elevation[k]:g}",
                 f"{spec_peaks[0][k]:.4f}", f"{spec_peaks[1][k]:.4f}",
                 *(_ratio_cell(float(v[k]), float(top[k])) for v in spec_rules.values())]
                for k in range(study.n_levels)]
        print_table(console, f"Code rules from the design spectrum {spec.name!r} [m] "
                    "(fundamental mode: u = |Γ1 φ1| Sd(T1))", cols, rows, keys=2,
                    caption="Sd(T1) [m]: " + ", ".join(
                        f"B{b + 1} {float(spec.sd(study.period[b])):.4f}"
                        for b in range(len(model.buildings))) + "; (×r) = rule / max simulated")

    gov = study.governing()
    console.print("governing critical gap per pair (max over levels and records): "
                  + ", ".join(f"B{p + 1}-B{p + 2} {g:.4f} m" for p, g in enumerate(gov)))
    if csv is not None:
        from pounding.io import write_text

        write_text(csv, "# lengths in m, elevation in m; */max, */mean = rule / simulated max, mean\n"
                   + study.to_frame(spec).to_csv(index=False))
        console.print(f"table: {csv}", highlight=False)
    if plot is not None:
        from pounding.plot import save_figure
        from pounding.plot.gap import plot_gap_study

        console.print(f"figure: {save_figure(plot_gap_study(study, spec), plot)}",
                      highlight=False)

"""`pounding fragility`."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.running import again, progress_bar, sigterm_as_interrupt, stopped
from pounding.cli.tables import Col, literal, number, print_table


@app.command("fragility")
def fragility_cmd(
    study_file: Annotated[Path, typer.Argument(
        help="TOML study file (see docs/fragility.md).", show_default=False)],
    out: opt.Out = None,
    overwrite: opt.OverwriteStudy = False,
    figures: opt.FiguresStudy = None,
    workers: opt.WorkersStudy = None,
    scheduler: opt.SchedulerStudy = None,
    code_check: opt.CodeCheckDir = None,
) -> None:
    """Probability of pounding: IDA of a record suite, fragility curves of the limit states,
    and the gap for a target probability beside the ABS/SRSS/DDC code gaps.

    Every record is scaled to every intensity level and run through the sweep machinery
    (Dask, resumable: a re-run does only the missing runs and redoes the analysis).

    Examples:

      pounding fragility examples/fragility_two_10_storey.toml -j 2

      pounding fragility study.toml --out study-results --overwrite
    """
    from pounding.studies.fragility import run_study, study_cases
    from pounding.studies.sweep import SweepInterrupted, SweepStopped

    from pounding.report.code_check import attach_code_check, other_model, read_code_check

    check = read_code_check(code_check) if code_check is not None else None
    cases = study_cases(study_file, out=out)
    if check is not None:  # a check of the study's base model (elevations; gaps may vary)
        from pounding.config import parse_config

        base = cases.sweep
        why = other_model(check, parse_config(base.base, base.base_dir).build()[0], gaps=False)
        if why is not None:
            raise ValueError(f"--code-check: {code_check} is a check of another model "
                             f"({why}); check the study's base model with pounding code-check")
    if cases.record_note:
        console.print(Text(cases.record_note))
    try:
        with sigterm_as_interrupt(), \
                progress_bar(f"fragility {cases.config.name}", "runs") as progress:
            res = run_study(cases, overwrite=overwrite, figures=figures, progress=progress,
                            scheduler=scheduler, n_workers=workers)
    except (SweepInterrupted, SweepStopped) as exc:
        stopped(exc, again(study_file, "fragility", out=out, workers=workers,
                           scheduler=scheduler), "runs")
    if check is not None:  # kept for the report's Code check section
        console.print(Text(f"code check kept: {attach_code_check(res.out_dir, check)}"))
    _print(res)


def _print(res: Any) -> None:
    """The tables printed after a study: intensities in g, gaps in mm."""
    a, cases = res.analysis, res.cases
    rows = []
    for r in a.limit_states:
        gap = "base" if r.gap is None else f"{1000 * r.gap:g}"
        for name, e in (("stripes, MLE", r.msa), ("IDA", r.ida)):
            rows.append((literal(r.spec.label), gap, name, number(e.median),
                         f"{number(e.median_ci[0], 3)} – {number(e.median_ci[1], 3)}",
                         f"{e.beta:.3f}", f"{e.beta_ci[0]:.3f} – {e.beta_ci[1]:.3f}",
                         f"{int((~r.censored).sum())}/{r.capacity.size}"))
    print_table(console, f"{cases.config.name}: fragility ({len(cases.records)} records × "
                         f"{len(cases.levels)} levels × {len(cases.gaps)} gap(s) = "
                         f"{res.sweep.n_cases} runs; {res.sweep.n_run} run now)",
                [Col("limit state", "left", wrap=True), Col("gap [mm]"),
                 Col("method", "left"), Col("median [g]"), Col("interval [g]"), Col("β [-]"),
                 Col("interval of β [-]"), Col("records exceeding")], rows, keys=3)
    ga = a.gap
    from pounding.studies.fragility.outputs import _gap_rows

    gap_rows = []
    for name, _, gm, lo, hi, pe, pf in _gap_rows(cases, a):
        ci = f" ({1000 * lo:.0f} – {1000 * hi:.0f})" if lo == lo else ""
        gap_rows.append((literal(name), f"{1000 * gm:.1f}{ci}", f"{pe:.2f}", f"{pf:.3f}"))
    joints = "joint gap" if cases.bridge is not None else "gap"
    print_table(console, f"{joints} at {cases.im_label.replace(' [g]', '')} = "
                         f"{ga.needed.at:g} g (needed gaps: lognormal θ = "
                         f"{1000 * ga.median:.1f} mm, β = {ga.beta:.3f})",
                [Col("gap from", "left", wrap=True), Col("gap [mm]"), Col("P(pounding), records"),
                 Col("P(pounding), lognormal")], gap_rows)
    if a.seats is not None:
        from pounding.studies.fragility.outputs import seat_rows

        seats = [(f"{x:g}", f"{1000 * med:.1f}", f"{beta:.3f}",
                  f"{1000 * w:.1f}" + (f" ({1000 * lo:.0f} – {1000 * hi:.0f})" if lo == lo
                                       else ""), f"{1000 * wr:.1f}")
                 for x, _, med, beta, w, lo, hi, wr in seat_rows(cases, a)]
        print_table(console, f"seat width for P(unseating) = {a.seats.target:g} (every seat "
                             "as wide; from the records' largest seat opening)",
                    [Col(cases.im_label), Col("opening θ [mm]"), Col("β [-]"),
                     Col("width, lognormal [mm]"), Col("width, records [mm]")], seats)
    if a.hinges is not None and a.hinges.collapses:
        console.print(Text(f"{len(a.hinges.collapses)} run(s) collapsed (a frame lost its "
                           "strength, or a storey drifted by more than its height): counted as "
                           "collapses and as exceeding every drift and plastic-rotation limit "
                           f"(first: {a.hinges.collapses[0]})"))
    if a.n_failed:
        console.print(Text.assemble((f"{a.n_failed} run(s) failed", "red"),
                                    f": see results.parquet (first: {a.failures[0]})"))
    console.print(Text(f"{res.wall_time:.1f} s (runs {res.sweep.run_time:.1f} s, gaps "
                       f"{res.gap_time:.1f} s, analysis and files {res.analysis_time:.1f} s); "
                       f"results in {cases.out}"))

"""`pounding sweep` and `pounding plot`."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.running import again, progress_bar, sigterm_as_interrupt, stopped
from pounding.cli.tables import Col, literal, print_table


@app.command("sweep")
def sweep_cmd(
    sweep_file: Annotated[Path, typer.Argument(help="TOML sweep file (see docs/sweep.md).",
                                               show_default=False)],
    out: opt.Out = None,
    overwrite: opt.OverwriteStudy = False,
    figures: opt.FiguresSweep = None,
    workers: opt.Workers = None,
    scheduler: opt.Scheduler = None,
    batch_size: Annotated[int | None, typer.Option(
        "--batch-size", min=1, metavar="N", help="Cases per Dask task. Default: batch_size "
        "of the sweep file, else automatic (10-500).", show_default=False)] = None,
    histories: Annotated[opt.Histories | None, typer.Option(
        "--histories", help="Write each case's time histories (none: do not). Default: "
                            "histories of the sweep file.", show_default=False)] = None,
    code_check: opt.CodeCheckDir = None,
) -> None:
    """Run a parameter sweep on Dask; resumable: a re-run does only the missing cases.

    Examples:

      pounding sweep examples/sweep_gap_e.toml -j 2

      pounding sweep study.toml --scheduler tcp://10.0.0.5:8786
    """
    from pounding.studies.sweep import SweepInterrupted, SweepStopped, load_sweep, run_sweep

    from pounding.report.code_check import attach_code_check, other_model, read_code_check

    check = read_code_check(code_check) if code_check is not None else None
    sweep = load_sweep(sweep_file)
    if check is not None:  # a check of the study's base model (elevations; gaps may vary)
        from pounding.config import parse_config

        base = sweep
        why = other_model(check, parse_config(base.base, base.base_dir).build()[0], gaps=False)
        if why is not None:
            raise ValueError(f"--code-check: {code_check} is a check of another model "
                             f"({why}); check the study's base model with pounding code-check")
    hist = None if histories is None else (False if histories == "none" else str(histories))
    try:
        with sigterm_as_interrupt(), progress_bar(f"sweep {sweep.name}", "cases") as progress:
            res = run_sweep(sweep, out, overwrite=overwrite, figures=figures,
                            progress=progress, scheduler=scheduler, n_workers=workers,
                            batch_size=batch_size, histories=hist)
    except (SweepInterrupted, SweepStopped) as exc:
        stopped(exc, again(sweep_file, "sweep", out=out, workers=workers, scheduler=scheduler,
                           batch_size=batch_size, histories=histories), "cases")
    if check is not None:  # kept for the report's Code check section
        console.print(Text(f"code check kept: {attach_code_check(res.out_dir, check)}"))
    rows: list[tuple[str, str | Text]] = [
        ("cases", f"{res.n_cases} ({len(sweep.params)} parameter(s): "
                  f"{', '.join(sweep.params)})")]
    if sweep.duplicates:
        rows.append(("duplicates skipped", str(sweep.duplicates)))
    rows += [("run now / done before", f"{res.n_run} / {res.n_cases - res.n_run}"),
             ("failed cases", Text(str(res.n_errors), style="red") if res.n_errors else "0"),
             ("workers / cases per task", f"{res.n_workers} / {res.batch_size}")]
    if res.n_run:
        rows.append(("running [s] / rate", f"{res.run_time:.2f} / {res.rate:,.1f} cases/s"))
    rows.append(("wall time [s]", f"{res.wall_time:.2f}"))
    print_table(console, f"{sweep.name}: sweep", [Col("quantity", "left", wrap=True),
                                                  Col("value", wrap=True)],
                [(literal(a), b) for a, b in rows], show_header=False)
    console.print(Text.assemble("table in ", (str(res.results), "bold")))
    if res.figure is not None:
        console.print(Text.assemble("figure in ", (str(res.figure), "bold")))


@app.command("plot")
def plot_cmd(
    results: Annotated[Path, typer.Argument(
        help="A sweep's results.parquet or its output folder.", show_default=False)],
    x: Annotated[str | None, typer.Option(
        "--x", metavar="PARAMETER", help="Parameter on the x axis. Default: the first swept "
                                         "parameter.", show_default=False)] = None,
    y: Annotated[str | None, typer.Option(
        "--y", metavar="PARAMETER", help="Second parameter: a heat map over x and y (--kind "
                                         "heatmap) or one line per value (--kind lines).",
        show_default=False)] = None,
    measure: Annotated[str, typer.Option(
        "--measure", "-m", metavar="COLUMN", help="Column of the table to draw.")
    ] = "peak_contact_force_N",
    kind: Annotated[opt.PlotKind, typer.Option(
        "--kind", help="With --y: a heat map, or one line per value of y.")
    ] = opt.PlotKind.heatmap,
    reduce: Annotated[opt.Reduce, typer.Option(
        "--reduce", help="How cases with equal x (and y) are combined.")] = opt.Reduce.mean,
    plot: Annotated[Path | None, typer.Option(
        "--plot", metavar="FILE", help=opt.PLOT_HELP + opt.escape(
            " Default: MEASURE_vs_X[_Y].png beside the table (in its folder's manifest)."),
        show_default=False)] = None,
    dpi: Annotated[int, typer.Option(
        "--dpi", min=30, max=1200, help=opt.escape("Resolution of a PNG figure [dots per inch]."))] = 150,
) -> None:
    """Draw a measure of a sweep against one or two swept parameters.

    Examples:

      pounding plot sweep_gap_e-results --x contact.gap --y contact.e

      pounding plot sweep_gap_e-results --x contact.gap --measure peak_contact_force_N --plot force.png
    """
    from pounding.io.files import check_output_file
    from pounding.plot import save_figure
    from pounding.plot.sweep import default_figure_name, plot_sweep
    from pounding.studies.sweep import load_results

    check_output_file(plot, "--plot", figure=True)
    df = load_results(results)
    fig, xs, ys = plot_sweep(df, x=x, y=y, measure=measure, kind=str(kind), reduce=str(reduce))
    folder = results if results.is_dir() else results.parent
    if plot is not None:
        target = plot
        save_figure(fig, target, dpi=dpi)
    else:  # beside the table: pounding's own file, in the folder's manifest
        from pounding.io.manifest import Manifest

        target = folder / default_figure_name(measure, xs, ys)
        manifest = Manifest(folder)
        if manifest.exists():
            with manifest.write(target) as tmp:
                save_figure(fig, tmp, dpi=dpi)
        else:
            save_figure(fig, target, dpi=dpi)
    console.print(Text.assemble("figure in ", (str(target), "bold")))

"""`pounding sweep` and `pounding plot`."""

from pounding.cli.app import app, console  # noqa: F401

from pathlib import Path  # noqa: E402
from typing import Annotated, Any, NoReturn  # noqa: E402

import typer  # noqa: E402
from rich.progress import (  # noqa: E402
    BarColumn,
    MofNCompleteColumn,
    Progress,
    ProgressColumn,
    TaskProgressColumn,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)
from rich.table import Table  # noqa: E402
from rich.text import Text  # noqa: E402


class _RateColumn(ProgressColumn):
    """Cases per second."""

    def render(self, task: Any) -> Text:
        speed = task.finished_speed or task.speed
        return Text("-- cases/s" if speed is None else f"{speed:,.0f} cases/s")


@app.command("sweep")
def sweep_cmd(
    sweep_file: Annotated[Path, typer.Argument(help="TOML sweep file (see docs/sweep.md).",
                                               show_default=False)],
    out: Annotated[Path | None, typer.Option(
        "--out", "-o", help="Output folder (default: out of the sweep file).",
        show_default=False)] = None,
    scheduler: Annotated[str | None, typer.Option(
        "--scheduler", help="Address of a running Dask scheduler (tcp://host:8786), or "
                            "'synchronous' to run in this process. Default: a local cluster.",
        show_default=False)] = None,
    workers: Annotated[int | None, typer.Option(
        "--workers", "-j", min=1, help="Workers of the local cluster (default: CPU count).",
        show_default=False)] = None,
    batch_size: Annotated[int | None, typer.Option(
        "--batch-size", min=1, help="Cases per Dask task (default: automatic, 10-500).",
        show_default=False)] = None,
    histories: Annotated[str | None, typer.Option(
        "--histories", help="Write time histories per case: netcdf, zarr or none "
                            "(default: histories of the sweep file).", show_default=False)] = None,
    overwrite: Annotated[bool, typer.Option(
        "--overwrite", help="Start afresh: discard finished cases in the output folder (only "
                            "the files pounding wrote there; refused if it holds others).")
] = False,
) -> None:
    """Run a parameter sweep on Dask; resumable: a re-run does only the missing cases.

    Examples:

      pounding sweep examples/sweep_gap_e.toml -j 2

      pounding sweep study.toml --scheduler tcp://10.0.0.5:8786
    """
    from pounding.cli.commands_run import _sigterm_as_interrupt
    from pounding.studies.sweep import SweepInterrupted, SweepStopped, load_sweep, run_sweep

    sweep = load_sweep(sweep_file)
    hist: Any = None if histories is None else (False if histories == "none" else histories)
    bar, progress = _progress(f"sweep {sweep.name}", len(sweep.cases))
    try:
        with _sigterm_as_interrupt(), bar:
            res = run_sweep(sweep, out, scheduler=scheduler, n_workers=workers,
                            batch_size=batch_size, overwrite=overwrite, histories=hist,
                            progress=progress)
    except (SweepInterrupted, SweepStopped) as exc:
        _stopped(exc, _again(sweep_file, out=out, scheduler=scheduler, workers=workers,
                             batch_size=batch_size, histories=histories), "cases")
    t = Table(title=f"{sweep.name}: sweep", show_header=False)
    t.add_column("quantity")
    t.add_column("value", justify="right")
    t.add_row("cases", f"{res.n_cases} ({len(sweep.params)} parameter(s): "
                       f"{', '.join(sweep.params)})")
    if sweep.duplicates:
        t.add_row("duplicates skipped", str(sweep.duplicates))
    t.add_row("run now / done before", f"{res.n_run} / {res.n_cases - res.n_run}")
    t.add_row("failed cases", Text(str(res.n_errors), style="red") if res.n_errors else "0")
    t.add_row("workers / cases per task", f"{res.n_workers} / {res.batch_size}")
    if res.n_run:
        t.add_row(Text("running [s] / rate"), f"{res.run_time:.2f} / {res.rate:,.1f} cases/s")
    t.add_row(Text("wall time [s]"), f"{res.wall_time:.2f}")
    console.print(t)
    console.print(Text.assemble("table in ", (str(res.results), "bold")))


def _progress(description: str, total: int) -> tuple[Progress, Any]:
    """A progress bar of cases (done / total, percent, cases per second, elapsed, left) and
    the ``progress(done, total)`` callback of :func:`~pounding.studies.sweep.run_sweep` that
    moves it; cases finished by an earlier run count as done from the start, without a
    rate."""
    bar = Progress(TextColumn("{task.description}", style="bold", markup=False), BarColumn(),
                   MofNCompleteColumn(),
                   TaskProgressColumn(), _RateColumn(), TimeElapsedColumn(),
                   TimeRemainingColumn(), console=console, transient=True,
                   disable=not console.is_terminal)  # (a log gets no bar)
    task = bar.add_task(description, total=total, start=False)
    state: dict[str, int | None] = {"first": None}

    def progress(done: int, total: int) -> None:
        if state["first"] is None:  # cases finished before this run: no rate for them
            state["first"] = done
            bar.update(task, completed=done)
            bar.start_task(task)
            return
        bar.update(task, completed=done)

    return bar, progress


def _stopped(exc: Any, again: str, what: str) -> NoReturn:
    """Say what a stopped sweep kept and how to resume it (``what``: ``cases``, ``runs``),
    and exit with 130 (interrupted) or 1 (stopped by the cluster)."""
    from pounding.cli import EXIT_FAILED, EXIT_INTERRUPTED, error_line
    from pounding.studies.sweep import SweepInterrupted

    if exc.n_saved:
        error_line(f"{exc.reason}: {exc.n_saved:,} of {exc.n_cases:,} {what} are saved in "
                   f"{exc.out_dir}; resume with: {again}")
    else:
        error_line(f"{exc.reason} before any {what[:-1]} was saved, leaving {exc.out_dir} as "
                   f"it was; start again with: {again}")
    raise typer.Exit(EXIT_INTERRUPTED if isinstance(exc, SweepInterrupted)
                     else EXIT_FAILED) from None


def _again(sweep_file: Path, command: str = "sweep", **options: Any) -> str:
    """The command that resumes a sweep (or another ``command`` run as one, such as
    ``fragility``): the same options, never ``--overwrite``."""
    import shlex

    argv = ["pounding", command, str(sweep_file)]
    for name, value in options.items():
        if value is not None:
            argv += [f"--{name.replace('_', '-')}", str(value)]
    return shlex.join(argv)


@app.command("plot")
def plot_cmd(
    results: Annotated[Path, typer.Argument(
        help="A sweep's results.parquet or its output folder.", show_default=False)],
    x: Annotated[str | None, typer.Option(
        "--x", help="Parameter on the x axis (default: the first swept parameter).",
        show_default=False)] = None,
    y: Annotated[str | None, typer.Option(
        "--y", help="Second parameter: a heat map over x and y (with --kind heatmap, the "
                    "default) or one line per value (--kind lines).",
        show_default=False)] = None,
    measure: Annotated[str, typer.Option(
        "--measure", "-m", help="Column to plot.")] = "peak_contact_force_N",
    kind: Annotated[str, typer.Option(
        "--kind", help="heatmap or lines (with two parameters).")] = "heatmap",
    reduce: Annotated[str, typer.Option(
        "--reduce", help="How cases with equal x (and y) are combined: mean, max, min, "
                         "median.")] = "mean",
    out: Annotated[Path | None, typer.Option(
        "--out", "-o", help="Figure file (default: <measure>_vs_<x>[_<y>].png beside the "
                            "table).", show_default=False)] = None,
    dpi: Annotated[int, typer.Option("--dpi", min=30, max=1200)] = 150,
) -> None:
    """Draw a measure of a sweep against one or two swept parameters.

    Examples:

      pounding plot sweep_gap_e-results --x contact.gap --y contact.e

      pounding plot sweep_gap_e-results --x contact.gap --measure peak_contact_force_N --out force.png
    """
    from pounding.io import check_output_file
    from pounding.plot import save_figure
    from pounding.plot.sweep import default_figure_name, plot_sweep
    from pounding.studies.sweep import load_results

    check_output_file(out, "--out", figure=True)
    df = load_results(results)
    fig, xs, ys = plot_sweep(df, x=x, y=y, measure=measure, kind=kind, reduce=reduce)
    folder = results if results.is_dir() else results.parent
    if out is not None:
        target = out
        save_figure(fig, target, dpi=dpi)
    else:  # beside the table: pounding's own file, in the folder's manifest
        from pounding.manifest import Manifest

        target = folder / default_figure_name(measure, xs, ys)
        manifest = Manifest(folder)
        if manifest.exists():
            with manifest.write(target) as tmp:
                save_figure(fig, tmp, dpi=dpi)
        else:
            save_figure(fig, target, dpi=dpi)
    console.print(Text.assemble("figure in ", (str(target), "bold")))

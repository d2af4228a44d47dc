"""`pounding fragility`."""

from pounding.cli.app import app, console  # noqa: F401

from pathlib import Path  # noqa: E402
from typing import Annotated, Any  # noqa: E402

import typer  # noqa: E402
from rich.table import Table  # noqa: E402
from rich.text import Text  # noqa: E402


@app.command("fragility")
def fragility_cmd(
    study_file: Annotated[Path, typer.Argument(
        help="TOML study file (see docs/fragility.md).", show_default=False)],
    out: Annotated[Path | None, typer.Option(
        "--out", "-o", help="Output folder (default: out of the study file).",
        show_default=False)] = None,
    workers: Annotated[int | None, typer.Option(
        "--workers", "-j", min=1, help="Workers of the local Dask cluster (default: "
                                       "run.workers of the study file, else the CPU "
                                       "count).",
        show_default=False)] = None,
    scheduler: Annotated[str | None, typer.Option(
        "--scheduler", help="Address of a running Dask scheduler (tcp://host:8786), or "
                            "'synchronous' to run in this process.",
        show_default=False)] = None,
    overwrite: Annotated[bool, typer.Option(
        "--overwrite", help="Start afresh: discard the runs saved in the output folder (only "
                            "the files pounding wrote there; refused if it holds others).")
    ] = False,
    figures: Annotated[bool, typer.Option(
        "--figures/--no-figures", help="Draw the figures (IDA, fragility, gap).")] = True,
) -> None:
    """Probability of pounding: IDA of a record suite, fragility curves of the limit states,
    and the gap for a target probability beside the ABS/SRSS/DDC code gaps.

    Every record is scaled to every intensity level and run through the sweep machinery
    (Dask, resumable: a re-run does only the missing runs and redoes the analysis).

    Examples:

      pounding fragility examples/fragility_two_10_storey.toml -j 2

      pounding fragility study.toml --out study-results --overwrite
    """
    from pounding.cli.commands_run import _sigterm_as_interrupt
    from pounding.cli.commands_sweep import _again, _progress, _stopped
    from pounding.studies.fragility import plan_study, run_study
    from pounding.studies.sweep import SweepInterrupted, SweepStopped

    plan = plan_study(study_file, out=out)
    if plan.record_note:
        console.print(Text(plan.record_note))
    bar, progress = _progress(f"fragility {plan.config.name}", len(plan.sweep.cases))
    try:
        with _sigterm_as_interrupt(), bar:
            res = run_study(plan, scheduler=scheduler, n_workers=workers, overwrite=overwrite,
                            figures=figures, progress=progress)
    except (SweepInterrupted, SweepStopped) as exc:
        _stopped(exc, _again(study_file, "fragility", out=out, workers=workers,
                             scheduler=scheduler), "runs")
    _print(res)


def _print(res: Any) -> None:
    """The tables printed after a study."""
    a, plan = res.analysis, res.plan
    t = Table(title=f"{plan.config.name}: fragility ({len(plan.records)} records × "
                    f"{len(plan.levels)} levels × {len(plan.gaps)} gap(s) = "
                    f"{res.sweep.n_cases} runs; {res.sweep.n_run} run now)")
    for h in ("limit state", "gap", "method", "median [g]", "interval [g]", "β",
              "interval", "records exceeding"):
        t.add_column(Text(h), justify="left" if h in ("limit state", "method") else "right")
    for r in a.limit_states:
        gap = "base" if r.gap is None else f"{1000 * r.gap:g} mm"
        for name, e in (("stripes, MLE", r.msa), ("IDA", r.ida)):
            t.add_row(r.spec.label, gap, name, f"{e.median:.4g}",
                      f"{e.median_ci[0]:.3g} – {e.median_ci[1]:.3g}", f"{e.beta:.3f}",
                      f"{e.beta_ci[0]:.3f} – {e.beta_ci[1]:.3f}",
                      f"{int((~r.censored).sum())}/{r.capacity.size}")
    console.print(t)
    ga = a.gap
    g = Table(title=f"gap at {plan.im_label.replace(' [g]', '')} = {ga.needed.at:g} g "
                    f"(needed gaps: lognormal θ = {1000 * ga.median:.1f} mm, β = "
                    f"{ga.beta:.3f})")
    for h in ("gap", "[mm]", "P(pounding), records", "P(pounding), lognormal"):
        g.add_column(Text(h), justify="left" if h == "gap" else "right")
    from pounding.studies.fragility.outputs import _gap_rows

    for name, _, gm, lo, hi, pe, pf in _gap_rows(plan, a):
        ci = f" ({1000 * lo:.0f} – {1000 * hi:.0f})" if lo == lo else ""
        g.add_row(name, f"{1000 * gm:.1f}{ci}", f"{pe:.2f}", f"{pf:.3f}")
    console.print(g)
    if a.n_failed:
        console.print(Text.assemble((f"{a.n_failed} run(s) failed", "red"),
                                    f": see results.parquet (first: {a.failures[0]})"))
    console.print(f"{res.wall_time:.1f} s (runs {res.sweep.run_time:.1f} s, gaps "
                  f"{res.gap_time:.1f} s, analysis and files {res.analysis_time:.1f} s); "
                  f"results in {plan.out}")


"""`pounding code-check ... --time-history`: the time histories of the model beside the
code's check, under a suite of records scaled to the code's spectrum
(:mod:`pounding.studies.codes.time_history`; docs/codes.md, "Beside a time history").

Its options are declared here and named in the signature of ``code-check``
(:mod:`pounding.cli.commands_code_check`); :func:`beside` runs the time histories and prints
their tables.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import console
from pounding.cli.tables import Col, literal, print_table

TimeHistory = Annotated[bool, typer.Option(
    "--time-history", help="Run the model beside the check under a suite of records scaled "
    "to the code's spectrum (the bundled suite unless --suite), with its own gaps and with "
    "every gap at the code's separation; prints whether the code's gap prevented pounding "
    "and the smallest gap that would have (docs/codes.md).")]
"""``--time-history`` of ``code-check``."""

Suite = Annotated[list[Path] | None, typer.Option(
    "--suite", metavar="PATH", help="Records of the suite for --time-history (implied): "
    "record files or a folder of them, --suite A.AT2 --suite B.AT2 or --suite records/. "
    "Default: the suite bundled with pounding.", show_default=False)]
"""``--suite`` of ``code-check``."""

Design = Annotated[Path | None, typer.Option(
    "--design", metavar="FILE", help=opt.DESIGN_HELP + " The target the suite is scaled to "
    "(--time-history). Default: the code's own elastic spectrum from the check's "
    "parameters.", show_default=False)]
"""``--design`` of ``code-check``."""

Duration = Annotated[float | None, typer.Option(
    "--duration", metavar="SECONDS", help="Time simulated \\[s] for every record. Default: "
    "each record's duration (--time-history).", show_default=False)]
"""``--duration`` of ``code-check``."""


def wanted(time_history: bool, suite: list[Path] | None, design: Path | None,
           duration: float | None) -> bool:
    """Whether the time histories are asked for; ``--design`` or ``--duration`` without them
    is refused in one line (they would do nothing)."""
    on = time_history or bool(suite)
    if not on and design is not None:
        raise ValueError("--design: the target of the suite's scaling, for --time-history "
                         "(or --suite); give one of them too")
    if not on and duration is not None:
        raise ValueError("--duration: the time simulated under each record, for "
                         "--time-history (or --suite); give one of them too")
    return on


def read_inputs(suite: list[Path] | None, design: Path | None,
                duration: float | None) -> tuple[Any, Any]:
    """The suite (bundled by default) and the target spectrum (None: the code's), read and
    checked before anything is computed."""
    from pounding.ground_motion.readers import UnitsRequired
    from pounding.ground_motion.suite import BUNDLED, read_suite
    from pounding.spectra import DesignSpectrum

    if duration is not None:
        from pounding.validation import positive

        positive("--duration", duration)
    target = DesignSpectrum.from_file(design) if design is not None else None
    source: Any = BUNDLED if not suite else (suite[0] if len(suite) == 1 else suite)
    try:
        records = read_suite(source)
    except UnitsRequired as exc:
        raise ValueError(f"--suite: {exc.path} is a plain-text record, which does not state "
                         "its acceleration unit or step; give PEER AT2 (or other) files "
                         "that do, or convert it with `pounding record`") from None
    for s in records.skipped:
        console.print(f"skipped: {s.reason}", highlight=False, markup=False)
    if duration is not None:
        from pounding.studies.codes.time_history import check_duration

        check_duration(duration, list(records), "--duration")
    return records, target


def beside(model: Any, check: Any, records: Any, target: Any, solver: dict[str, Any],
           duration: float | None) -> Any:
    """Run the time histories beside ``check``, print their tables and verdicts, and return
    the check with them (:class:`~pounding.studies.codes.time_history.CodeCheckBeside`)."""
    from pounding.cli.running import progress_bar
    from pounding.studies.codes.time_history import CodeCheckBeside, time_history_check

    with progress_bar("time histories beside the code check", "runs") as progress:
        th = time_history_check(model, check, list(records), target=target, solver=solver,
                                duration=duration, progress=progress)
    _print(th)
    return CodeCheckBeside.of(check, th)


def _print(th: Any) -> None:
    from pounding.spectra.scaling import DEFAULT_LIMITS as LIMITS

    rows = []
    for r, name in enumerate(th.records):
        flag = f" (outside {LIMITS[0]:g}–{LIMITS[1]:g})" if th.factors_flagged[r] else ""
        rows.append([literal(name), f"{th.factors[r]:.4g}{flag}",
                     "yes" if th.own.pounded()[r] else "no", str(int(th.own.impacts[r].sum())),
                     f"{1e-3 * th.own.peak_force[r].max():.0f}",
                     "yes" if th.at_code.pounded()[r] else "no",
                     str(int(th.at_code.impacts[r].sum())),
                     f"{1e-3 * th.at_code.peak_force[r].max():.0f}",
                     ", ".join(f"{1e3 * th.closing_of_pair(p)[r]:.1f}" for p in th.pair_names)])
    print_table(console, f"time histories beside the check: {len(th.records)} records scaled "
                f"to {th.target}", [
                    Col("record", "left", wrap=True), Col("factor"), Col("pounded (own gap)"),
                    Col("impacts"), Col("peak force [kN]"), Col("pounded (code gap)"),
                    Col("impacts"), Col("peak force [kN]"),
                    Col(f"peak closing [mm] ({', '.join(th.pair_names)})")],
                rows, caption=f"{th.scaling}. Own gap: the model's; code gap: every pair's "
                "gap at the code's separation (the largest it asks for at the pair's levels). "
                "Peak closing: max(u_left − u_right) with the buildings apart, the smallest gap "
                "that prevents pounding under the record.")
    levels = [[literal(lv), f"{z:.3g}", f"{1e3 * req:.1f}",
               f"{1e3 * th.peak_closing[:, i].mean():.1f}",
               f"{1e3 * th.peak_closing[:, i].max():.1f}",
               f"{int(th.closes_past_required[:, i].sum())} of {len(th.records)}"]
              for i, (lv, z, req) in enumerate(zip(th.levels, th.elevation, th.required,
                                                   strict=True))]
    print_table(console, "peak closing beside the code's separation, level by level [mm]", [
        Col("floor", "left"), Col("elevation [m]"), Col("required [mm]"),
        Col("mean peak closing [mm]"), Col("largest [mm]"),
        Col("records closing past it", "left")], levels,
        caption="A record closing past the required separation at a level would strike "
                "there with a gap of the code's separation at that level.")
    for line in th.verdicts():
        console.print(Text(line))

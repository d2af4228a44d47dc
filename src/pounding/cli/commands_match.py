"""`pounding match`: a record made spectrum-compatible with wavelets, written as a PEER AT2."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.tables import Col, print_table

MARK = "pounding match: spectrum-compatible record"
"""First line of every AT2 file ``pounding match`` writes: ``--overwrite`` replaces only a
file that starts with it."""


def _check_out(out: Path, overwrite: bool) -> None:
    """Refuse ``--out`` before any work: not an .AT2 name, a folder, an unwritable place, or
    an existing file unless ``--overwrite`` and pounding match wrote it."""
    from pounding.io.files import check_output_file

    if out.suffix.lower() != ".at2":
        raise ValueError(f"--out: the matched record is written as a PEER .AT2 file; give a "
                         f"name ending in .AT2 (got {out})")
    check_output_file(out, "--out")
    if out.exists() or out.is_symlink():
        if not overwrite:
            raise ValueError(f"--out: {out} exists; give --overwrite to replace a record "
                             "pounding match wrote, or another name")
        try:
            with out.open(encoding="utf-8") as f:
                first = f.readline()
        except (OSError, UnicodeDecodeError):
            first = ""
        if out.is_symlink() or not first.startswith(MARK):
            raise ValueError(f"--out: {out} is not a record pounding match wrote; it is left "
                             "as it is (give another name)")


@app.command("match")
def match_cmd(
    record: Annotated[Path, typer.Argument(
        help="The seed record (any format `pounding record` reads: PEER .AT2, K-NET, "
        "COSMOS, text).", show_default=False)],
    target: Annotated[Path, typer.Option(
        "--target", metavar="FILE", help=opt.DESIGN_HELP + " The spectrum to match.",
        show_default=False)] = ...,  # type: ignore[assignment]
    out: Annotated[Path, typer.Option(
        "--out", "-o", metavar="FILE.AT2", help="The matched record, a PEER .AT2 file (g).",
        show_default=False)] = ...,  # type: ignore[assignment]
    period_range: Annotated[str, typer.Option(
        "--range", metavar="LO,HI", help="Periods checked \\[s]. The record is matched over "
        "them.")] = "0.05,4",
    tolerance: Annotated[float, typer.Option(
        "--tolerance", metavar="FRACTION", help="Largest |PSA/target - 1| accepted over the "
        "range (0.1 = ±10 %).")] = 0.10,
    damping: Annotated[str, typer.Option(
        "--damping", metavar="LIST", help=opt.DAMPING_HELP + " Matching uses one: the "
        "target's.")] = "0.05",
    iterations: Annotated[int, typer.Option(
        "--iterations", metavar="N", help="Most iterations.")] = 30,
    overwrite: Annotated[bool, typer.Option(
        "--overwrite", help=opt.OVERWRITE_HELP + " Only a file pounding match wrote.")]
        = False,
    plot: Annotated[Path | None, typer.Option(
        "--plot", metavar="FILE", help=opt.PLOT_HELP + " The figure: the target with its "
        "±tolerance band, the seed's spectrum and the matched spectrum, PSA \\[g] against "
        "period \\[s].", show_default=False)] = None,
    dt: opt.Dt = None,
    units: opt.RecordUnits = None,
    column: opt.Column = None,
    time_column: opt.TimeColumn = None,
    channel: opt.Channel = None,
) -> None:
    """Make a record spectrum-compatible: wavelets added in time (Al Atik & Abrahamson 2010).

    The record is scaled, then wavelets that add no final velocity or displacement are added
    until its PSA is within the tolerance of the target over the range; see docs/records.md.

    Examples:

      pounding match elcentro.AT2 --target examples/spectrum_asce7_site.toml --out m.AT2

      pounding match rec.AT2 --target site.csv --range 0.1,3 --out m.AT2 --overwrite

      pounding match elcentro.AT2 --target site.toml --out m.AT2 --plot match.png
    """
    from pounding.cli.commands_spectrum import _read
    from pounding.cli.messages import EXIT_FAILED, error_line

    _check_out(out, overwrite)
    if plot is not None:
        from pounding.io.files import check_output_file

        check_output_file(plot, "--plot", figure=True)
    from pounding.spectra.response import parse_damping

    zetas = parse_damping(damping, "--damping")
    if zetas.size != 1:
        raise ValueError(f"--damping: give one damping ratio, the target's (got {damping!r})")
    zeta = float(zetas[0])
    parts = [p.strip() for p in period_range.split(",")]
    try:
        lo, hi = (float(p) for p in parts) if len(parts) == 2 else (None, None)
    except ValueError:
        lo = hi = None
    if lo is None or hi is None:
        raise ValueError(f"--range: give LO,HI in s, e.g. 0.05,4 (got {period_range!r})")
    from pounding.spectra import DesignSpectrum
    from pounding.spectra.matching import match_record

    spectrum = DesignSpectrum.from_file(target)
    motion = _read([record], dt, None if units is None else str(units), column=column,
                   time_column=time_column, channel=channel)[0]
    try:
        result = match_record(motion, spectrum, (lo, hi), damping=zeta,
                              tolerance=tolerance, iterations=iterations)
    except ValueError as exc:
        text = str(exc)
        for name in ("range", "tolerance", "damping", "iterations"):
            if text.startswith(f"{name}:"):
                text = "--" + text
        raise ValueError(text) from None

    rows = [(k, f"{a:.4g}", f"{b:.4g}", f"{b / a:.3f}" if a else "—")
            for k, (a, b) in result.measures().items()]
    print_table(console, f"{motion.name} matched to {spectrum.name} "
                f"(scaled by {result.scale_factor:.4g}, then {result.iterations} iterations)",
                [Col("measure", "left"), Col("original"), Col("matched"), Col("ratio")], rows,
                caption="PGV, PGD, final velocity and displacement by the trapezoidal rule "
                        "(no baseline correction); Arias intensity π/(2g)∫a² dt")
    console.print(f"PSA within {100 * result.max_misfit:.1f} % of the target at "
                  f"{result.periods.size} periods {lo:g}–{hi:g} s (ζ = {zeta:g})",
                  highlight=False)
    if not result.converged:
        error_line(f"match: after {result.iterations} iterations the spectrum is within "
                   f"{100 * result.max_misfit:.1f} % of the target, not the "
                   f"{100 * tolerance:g} % asked; nothing written (try more --iterations, "
                   "a narrower --range or a record closer to the target)")
        raise typer.Exit(EXIT_FAILED)
    from pounding.ground_motion.writers import at2_text
    from pounding.io.files import write_text

    write_text(out, at2_text(
        result.motion, MARK, f"{motion.name} matched to {spectrum.name}, {lo:g}-{hi:g} s, "
        f"within {100 * result.max_misfit:.1f} %, scale {result.scale_factor:.6g} "
        "(Al Atik & Abrahamson 2010 wavelets)"))
    console.print(f"record: {out}", highlight=False)
    if plot is not None:
        from pounding.plot import save_figure
        from pounding.plot.matching import plot_match

        fig = plot_match(result, motion.name, spectrum.name)
        console.print(f"figure: {save_figure(fig, plot)}", highlight=False)

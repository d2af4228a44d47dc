"""`pounding suite`: scale a suite of records to a target spectrum."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.tables import Col, literal, print_table

CSV_COLUMNS = ("record", "factor", "flagged", "pga_g", "scaled_pga_g", "sa_t1_g",
               "scaled_sa_t1_g")
"""Columns of ``pounding suite --csv``: one row per record."""


@app.command("suite", context_settings=opt.CODE_CONTEXT)
def suite_cmd(
    records: Annotated[list[Path] | None, typer.Argument(
        help="Record files or a folder of them (any format `pounding record` reads). "
        "Default: the suite bundled with pounding.", show_default=False)] = None,
    target: Annotated[Path, typer.Option(
        "--design", metavar="FILE", help=opt.DESIGN_HELP + " The target the records are "
        "scaled to.", show_default=False)] = ...,  # type: ignore[assignment]
    period: Annotated[float, typer.Option(
        "--t1", metavar="SECONDS", help="Fundamental period T1 of the structure \\[s].",
        show_default=False)] = ...,  # type: ignore[assignment]
    method: Annotated[opt.Method, typer.Option(
        "--method", help="code: one factor for the suite, its mean >= 90 % of the target "
        "over the range (ASCE 7-22 §16.2.3 / EN 1998-1 §3.2.3.1.2); sa: each record to "
        "Sa(T1); pga: each to the target's PGA; lsq: each by least squares on its "
        "log-spectrum over the range.")] = opt.Method.code,
    code: Annotated[opt.Code, typer.Option(
        "--code", metavar="CODE", help=f"{opt.CODE_HELP} Its rule for --method code: "
        "asce7-22 (§16.2.3) or en1998-1 (§3.2.3.1.2, which also keeps the mean PGA at the "
        "target's); nzs1170.5, nbcc2020 and is1893 have no suite rule in pounding.")
    ] = opt.Code.asce7_22,
    period_range: Annotated[str | None, typer.Option(
        "--range", metavar="LO,HI", help="Periods checked \\[s]. Default: 0.2 T1 to 2 T1 "
        "(ASCE 7-22 wants a lower bound low enough for 90 % of the modal mass).",
        show_default=False)] = None,
    limits: Annotated[str, typer.Option(
        "--limits", metavar="LO,HI", help="Flag factors outside this range.")] = "0.25,4",
    damping: Annotated[str, typer.Option(
        "--damping", metavar="LIST", help=opt.DAMPING_HELP + " Scaling uses one: the "
        "design spectrum's.")] = "0.05",
    csv: Annotated[Path | None, typer.Option(
        "--csv", metavar="FILE", help=opt.CSV_HELP + " One row per record: "
        + ", ".join(CSV_COLUMNS) + ".", show_default=False)] = None,
    plot: Annotated[Path | None, typer.Option(
        "--plot", metavar="FILE", help=opt.PLOT_HELP + " The figure: each scaled spectrum, "
        "the mean, the target and the range.", show_default=False)] = None,
    dt: opt.Dt = None,
    units: opt.RecordUnits = None,
    column: opt.Column = None,
    time_column: opt.TimeColumn = None,
    channel: opt.Channel = None,
) -> None:
    """Scale a suite of records to a target spectrum: the factors, the mean and dispersion.

    See docs/spectra.md (record scaling) for the methods and their sources.

    Examples:

      pounding suite --design examples/spectrum_asce7_site.toml --t1 1.0

      pounding suite records/ --design ec8.toml --t1 0.8 --code en1998-1 --plot suite.png

      pounding suite A.AT2 B.AT2 C.AT2 --design site.csv --t1 1.2 --method lsq --csv f.csv
    """
    import numpy as np

    from pounding.ground_motion.suite import BUNDLED, read_suite
    from pounding.io.files import check_output_file
    from pounding.spectra import DesignSpectrum
    from pounding.spectra.scaling import CODE_RATIO, scale_suite

    check_output_file(csv, "--csv")
    check_output_file(plot, "--plot", figure=True)
    lo_hi = _pair(period_range, "--range") if period_range is not None else None
    lims = _pair(limits, "--limits")
    from pounding.validation import positive

    period = positive("--t1", period)
    from pounding.spectra.scaling import CODES as SUITE_RULES

    if str(method) == "code" and str(code) not in SUITE_RULES:
        raise ValueError(f"--code: pounding scales a suite by the rule of asce7-22 (ASCE 7-22 "
                         f"§16.2.3) or en1998-1 (EN 1998-1 §3.2.3.1.2); {code} has none here "
                         f"(got {str(code)!r}; --method sa, pga or lsq scale without a code)")
    zetas = opt.split_floats(damping, "--damping") or []
    if len(zetas) != 1:
        raise ValueError(f"--damping: suite scaling uses one damping ratio, the design "
                         f"spectrum's (got {damping!r})")
    spectrum = DesignSpectrum.from_file(target)
    source: Any = BUNDLED if not records else (records[0] if len(records) == 1 else records)
    from pounding.ground_motion.readers import UnitsRequired

    try:
        suite = read_suite(source, dt=dt, units=None if units is None else str(units),
                           column=column, time_column=time_column, channel=channel)
    except UnitsRequired as exc:
        raise exc.named("--units") from None
    result = scale_suite(list(suite), spectrum, period, method=str(method), code=str(code),
                         damping=zetas[0], period_range=lo_hi, limits=lims)
    _print(result, suite)
    if csv is not None:
        from pounding.io.files import write_text
        from pounding.spectra.response import csv_text

        write_text(csv, csv_text(CSV_COLUMNS, _rows(result)))
        console.print(f"table: {csv}", highlight=False)
    if plot is not None:
        from pounding.plot import save_figure
        from pounding.plot.spectrum import plot_suite_scaling
        from pounding.spectra.response import response_spectrum

        lo, hi = result.period_range
        shown = np.geomspace(min(0.02, lo), max(5.0, 1.5 * hi), 200)
        shown = shown[shown <= spectrum.periods[-1]] if spectrum.periods[-1] > lo else shown
        spectra = np.array([f * response_spectrum(m, shown, result.damping).psa_g[0]
                            for f, m in zip(result.factors, suite, strict=True)])
        fig = plot_suite_scaling(shown, spectra, result.records, spectrum, result.period,
                                 result.period_range,
                                 CODE_RATIO if result.method == "code" else None,
                                 title=f"{suite.name}: {_method_text(result)}")
        console.print(f"figure: {save_figure(fig, plot)}", highlight=False)


def _pair(text: str, name: str) -> tuple[float, float]:
    parts = [p.strip() for p in text.split(",")]
    try:
        if len(parts) != 2:
            raise ValueError
        lo, hi = float(parts[0]), float(parts[1])
    except ValueError:
        raise ValueError(f"{name}: two numbers LO,HI (got {text!r})") from None
    return lo, hi


def _method_text(r: Any) -> str:
    if r.method == "code":
        rule = "ASCE 7-22 §16.2.3" if r.code == "asce7-22" else "EN 1998-1 §3.2.3.1.2"
        return f"one factor, mean ≥ 90 % of the target ({rule})"
    return {"sa": "each record to Sa(T1)", "pga": "each record to the target's PGA",
            "lsq": "each record by least squares on its log-spectrum"}[r.method]


def _rows(r: Any) -> list[tuple[Any, ...]]:
    j = r.at_period
    return [(name, float(f), bool(flag), float(pga), float(f * pga), float(sa),
             float(f * sa))
            for name, f, flag, pga, sa in zip(r.records, r.factors, r.flagged, r.pga_g,
                                              r.unscaled[:, j], strict=True)]


def _print(r: Any, suite: Any) -> None:
    import numpy as np

    lo, hi = r.period_range
    rows = []
    for name, f, flag, pga, _, sa, ssa in _rows(r):
        factor = Text(f"{f:.4f}")
        if flag:
            factor.append(" (outside limits)", style="red")
        rows.append((literal(name), f"{pga:.4f}", f"{sa:.4f}", factor, f"{f * pga:.4f}",
                     f"{ssa:.4f}"))
    j = r.at_period
    ratio = r.mean_over_target
    inside = (r.periods >= lo) & (r.periods <= hi)
    k = int(np.argmin(np.where(inside, ratio, np.inf)))
    print_table(console, f"{suite.name}: {len(r.records)} records scaled to {r.target.name}",
                [Col("record", "left", wrap=True), Col("PGA [g]"), Col("Sa(T1) [g]"),
                 Col("factor", wrap=True), Col("scaled PGA [g]"), Col("scaled Sa(T1) [g]")],
                rows, caption=(
                    f"{_method_text(r)}; T1 = {r.period:g} s, range {lo:.3g}–{hi:.3g} s, "
                    f"{100 * r.damping:g} % damping. Target Sa(T1) = {r.target_g[j]:.4f} g; "
                    f"mean scaled Sa(T1) = {r.mean[j]:.4f} g, dispersion (σ ln Sa) "
                    f"{r.dispersion[j]:.3f}; mean / target over the range: lowest "
                    f"{ratio[k]:.3f} at {r.periods[k]:.3g} s. Factors outside "
                    f"{r.limits[0]:g}–{r.limits[1]:g}: {int(r.flagged.sum())}."))
    for s in suite.skipped:
        console.print(f"skipped: {s.reason}", highlight=False, markup=False)

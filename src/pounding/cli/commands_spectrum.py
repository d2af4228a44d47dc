"""`pounding spectrum`: elastic response spectra of records, RotD50/RotD100 of pairs."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.tables import Col, print_table


def _pct(zeta: float) -> str:
    return f"ζ={100 * zeta:g}%"


@app.command("spectrum")
def spectrum_cmd(
    records: Annotated[list[Path], typer.Argument(
        help="Record files (any format `pounding record` reads: PEER .AT2, K-NET, "
        "COSMOS, text).", show_default=False)],
    damping: Annotated[str, typer.Option(
        "--damping", metavar="LIST", help=opt.DAMPING_HELP)] = "0.05",
    periods: Annotated[str, typer.Option(
        "--periods", metavar="SPEC", help="Periods \\[s]: a comma list (0.1,0.5,1) or "
        "FIRST:LAST:N, N periods log-spaced from FIRST to LAST (0.05:4:300).")]
        = "0.02:5:100",
    rotd: Annotated[bool, typer.Option(
        "--rotd", help="Take the records two at a time as the two horizontal components of "
        "one motion (same step and length): RotD50, RotD100 (Boore 2010) and the geometric "
        "mean.")] = False,
    design: Annotated[list[Path] | None, typer.Option(
        "--design", metavar="FILE", help=opt.DESIGN_HELP + " Drawn with --plot; repeat for "
        "more.", show_default=False)] = None,
    csv: Annotated[Path | None, typer.Option(
        "--csv", metavar="FILE", help=opt.CSV_HELP + " One row per record, damping and "
        "period: record, damping, period_s, sd_m, psv_m_s, psa_g, sa_abs_g (with --rotd: a "
        "measure column instead of sa_abs_g).", show_default=False)] = None,
    plot: Annotated[Path | None, typer.Option(
        "--plot", metavar="FILE", help=opt.PLOT_HELP + " The figure: PSA \\[g] against "
        "period \\[s].", show_default=False)] = None,
    dt: opt.Dt = None,
    units: opt.RecordUnits = None,
    column: opt.Column = None,
    time_column: opt.TimeColumn = None,
    channel: opt.Channel = None,
) -> None:
    """Elastic response spectra of records: Sd, PSV, PSA and absolute acceleration.

    Exact for a record linear between samples (Nigam & Jennings 1969), peaks inside steps.

    The oscillator starts at rest and is followed over the record; see docs/spectra.md.

    Examples:

      pounding spectrum elcentro.AT2 --damping 0.05,0.02 --plot psa.png

      pounding spectrum A.AT2 B.AT2 --periods 0.05:4:300 --csv spectra.csv

      pounding spectrum H1.AT2 H2.AT2 --rotd --design ec8.toml --plot rotd.png
    """
    from pounding.io.files import check_output_file
    from pounding.spectra.response import parse_damping, parse_periods

    check_output_file(csv, "--csv")
    check_output_file(plot, "--plot", figure=True)
    zetas = parse_damping(damping, "--damping")
    t = parse_periods(periods, "--periods")
    if rotd and len(records) % 2:
        raise ValueError(f"--rotd: give the records two at a time, the two horizontal "
                         f"components of each motion (got {len(records)} records)")
    from pounding.spectra import DesignSpectrum

    designs = [DesignSpectrum.from_file(f) for f in design or []]
    motions = _read(records, dt, None if units is None else str(units), column=column,
                    time_column=time_column, channel=channel)
    if rotd:
        curves, text = _rotd(motions, t, zetas)
    else:
        curves, text = _single(motions, t, zetas)
    if csv is not None:
        from pounding.io.files import write_text

        write_text(csv, text)
        console.print(f"table: {csv}", highlight=False)
    if plot is not None:
        from pounding.plot import save_figure
        from pounding.plot.spectrum import plot_spectra

        title = "RotD spectra" if rotd else "Response spectra"
        fig = plot_spectra(t, curves, designs, title=f"{title} (pseudo-acceleration)")
        console.print(f"figure: {save_figure(fig, plot)}", highlight=False)


def _read(files: list[Path], dt: float | None, units: str | None, *,
          column: int | None = None, time_column: int | None = None,
          channel: int | None = None) -> list[Any]:
    import dataclasses

    from pounding.ground_motion import read_record
    from pounding.ground_motion.readers import UnitsRequired

    motions = []
    for f in files:
        if f.is_dir():
            raise ValueError(f"{f}: is a directory, not a record file")
        try:
            gm = read_record(f, dt=dt, units=units, column=column, time_column=time_column,
                             channel=channel)
        except UnitsRequired as exc:
            raise exc.named("--units") from None
        # the file's name, and the column or channel read where the reader named one
        chosen = gm.name[len(f.stem):] if gm.name.startswith(f.stem) else ""
        motions.append(dataclasses.replace(gm, name=f.name + chosen))
    return motions


def _single(motions: list[Any], t: Any, zetas: Any) -> tuple[list[Any], str]:
    from pounding.spectra.response import response_spectrum, to_csv

    spectra = [response_spectrum(m, t, zetas) for m in motions]
    for m, s in zip(motions, spectra, strict=True):
        cols = [Col("T [s]")] + [Col(f"{what} {_pct(z)}") for z in s.damping
                                 for what in ("Sd [m]", "PSA [g]", "Sa,abs [g]")]
        rows = []
        for j, period in enumerate(s.periods):
            cells = [f"{period:.4g}"]
            for k in range(s.damping.size):
                cells += [f"{s.sd[k, j]:.5g}", f"{s.psa_g[k, j]:.4f}", f"{s.sa_abs_g[k, j]:.4f}"]
            rows.append(cells)
        print_table(console, f"{m.name}: PGA {m.pga_g:.4f} g, {m.npts} points at {m.dt:g} s",
                    cols, rows, caption="Sd: peak relative displacement; PSA = (2π/T)² Sd; "
                    "Sa,abs: peak absolute acceleration; g = 9.80665 m/s²")
    curves = [(f"{s.record}, {_pct(z)}", s.psa_g[k]) for s in spectra
              for k, z in enumerate(s.damping)]
    return curves, to_csv(spectra)


def _rotd(motions: list[Any], t: Any, zetas: Any) -> tuple[list[Any], str]:
    from pounding.spectra.rotd import rotd_spectrum, to_csv

    pairs = [rotd_spectrum(motions[i], motions[i + 1], t, zetas)
             for i in range(0, len(motions), 2)]
    curves = []
    for r in pairs:
        measures = r.measures()
        psa = {k: r.psa_g(v) for k, v in measures.items()}
        print_table(console, f"{r.label}: PSA [g]",
                    [Col("T [s]")] + [Col(f"{what} {_pct(z)}") for z in r.damping
                                      for what in measures],
                    [[f"{period:.4g}", *(f"{psa[what][k, j]:.4f}"
                                         for k in range(r.damping.size) for what in psa)]
                     for j, period in enumerate(r.periods)],
                    caption="H1, H2: the components as recorded; GeoMean = sqrt(H1 H2); "
                            "RotD50, RotD100: median and largest over azimuths 0-179° "
                            "(Boore 2010); PSA = (2π/T)² Sd")
        curves += [(f"{r.label} {what}, {_pct(z)}", psa[what][k])
                   for k, z in enumerate(r.damping) for what in ("GeoMean", "RotD50",
                                                                  "RotD100")]
    return curves, to_csv(pairs)

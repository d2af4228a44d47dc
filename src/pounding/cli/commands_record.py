"""`pounding record`."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.tables import Col, literal, print_table


@app.command("record")
def record(
    files: Annotated[list[Path] | None, typer.Argument(
        help="Record files: PEER .AT2 (units from the header, g if none stated), K-NET/"
             "KiK-net ASCII, COSMOS V1/V2, or text (needs --units) with one column (needs "
             "--dt), two columns time, acceleration, or several (needs --column).",
        show_default=False)] = None,
    bundled: Annotated[bool, typer.Option(
        "--bundled", help="Also the twelve real records shipped with pounding (the nine of "
                          "the bundled suite, a second digitisation of El Centro N-S kept "
                          "out of it, then the Düzce pair of orthogonal components; "
                          "provenance in pounding/data/records/SOURCES.md).")] = False,
    dt: opt.Dt = None,
    units: opt.RecordUnits = None,
    column: opt.Column = None,
    time_column: opt.TimeColumn = None,
    channel: opt.Channel = None,
    plot: Annotated[Path | None, typer.Option(
        "--plot", metavar="FILE", help=opt.PLOT_HELP + " The figure: each record's "
        "acceleration, velocity and displacement. With several record files, or a FILE that "
        "is an existing folder, FILE is a folder that gets one PNG per record, named "
        "RECORD-STEM.png.", show_default=False)] = None,
) -> None:
    """Read ground-motion records and print their step, duration, PGA and PGV.

    PGV is the peak of the trapezoidal integral of the acceleration (no baseline correction).

    Examples:

      pounding record elcentro.AT2 --plot elcentro.png

      pounding record accel.txt --dt 0.01 --units g

      pounding record station.txt --units g --column 2

      pounding record CE12345.V2 --channel 3

      pounding record MYG0041103111446.NS CE12345.V2c

      pounding record --bundled
    """
    from pounding.ground_motion import read_record
    from pounding.ground_motion.bundled import bundled_files, bundled_folder, load_bundled

    files = list(files or [])
    if not files and not bundled:
        raise ValueError("record: give record FILEs, or --bundled for the records shipped "
                         "with pounding")
    from pounding.ground_motion.readers import UnitsRequired

    try:
        motions = [read_record(f, dt=dt, units=None if units is None else str(units),
                               column=column, time_column=time_column, channel=channel)
                   for f in files]
    except UnitsRequired as exc:
        raise exc.named("--units") from None
    if bundled:
        files += [Path(str(bundled_folder().joinpath(f))) for f in bundled_files()]
        motions += [load_bundled(f) for f in bundled_files()]

    print_table(console, "Ground-motion records",
                [Col("file", "left", wrap=True), Col("points"), Col("step [s]"),
                 Col("duration [s]"), Col("units read", "left"), Col("PGA [g]"),
                 Col("PGV [m/s]")],
                [(literal(f.name), str(gm.npts), f"{gm.dt:g}", f"{gm.duration:.6g}",
                  gm.units_read, f"{gm.pga_g:.4f}", f"{gm.pgv:.3f}")
                 for f, gm in zip(files, motions, strict=True)])

    if plot is None:
        return
    if len(files) == 1 and not plot.is_dir():
        targets = [plot if plot.suffix else plot.with_suffix(".png")]
    else:
        if plot.exists() and not plot.is_dir():
            raise ValueError(f"--plot: {plot} is a file; with several records give a folder")
        # a figure per file, named by its stem, or by its whole name where components of
        # one record share the stem (K-NET's X.NS, X.EW, X.UD)
        stems = [f.stem for f in files]
        names = [f.name if stems.count(f.stem) > 1 else f.stem for f in files]
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise ValueError(f"--plot: several files are named {dup[0]!r} (in different "
                             "folders); their figures would overwrite each other; plot them "
                             "one at a time")
        targets = [plot / f"{n}.png" for n in names]
    for gm, target in zip(motions, targets, strict=True):
        from pounding.plot import save_figure
        from pounding.plot.record import plot_record

        fig = plot_record(gm)
        save_figure(fig, target)
        console.print(f"figure: {target}", highlight=False)

"""`pounding record`."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.table import Table
from rich.text import Text

from pounding.cli.app import app, console  # noqa: F401


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
    dt: Annotated[float | None, typer.Option(
        "--dt", help="Time step \\[s] for files that do not give one.")] = None,
    units: Annotated[str | None, typer.Option(
        "--units", help="Acceleration unit for files that do not state one: g, m/s2, "
                        "cm/s2, gal, ... (required for text files, which state none). An "
                        "AT2 header stating another unit is an error.")] = None,
    column: Annotated[int | None, typer.Option(
        "--column", min=1, help="Text files of several columns (t, NS, EW, V): the "
                                "acceleration's column, from 1.")] = None,
    time_column: Annotated[int | None, typer.Option(
        "--time-column", min=0, help="Text files: the time's column, from 1; 0 for none "
                                     "(then give --dt). Default: 1 with --column 2 or "
                                     "more.")] = None,
    channel: Annotated[int | None, typer.Option(
        "--channel", min=1, help="COSMOS files of several channels: the acceleration "
                                 "channel to read, from 1.")] = None,
    plot: Annotated[Path | None, typer.Option(
        "--plot", help="Draw each record (acceleration, velocity, displacement). With one "
                       "FILE, PATH is the figure file (format from its suffix: .png, .svg, "
                       ".pdf; none means .png). With several FILEs, or if PATH is an "
                       "existing folder, PATH is a folder that gets one PNG per file, named "
                       "FILE-STEM.png.",
        metavar="PATH")] = None,
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
        motions = [read_record(f, dt=dt, units=units, column=column,
                               time_column=time_column, channel=channel) for f in files]
    except UnitsRequired as exc:
        raise exc.named("--units") from None
    if bundled:
        files += [Path(str(bundled_folder().joinpath(f))) for f in bundled_files()]
        motions += [load_bundled(f) for f in bundled_files()]

    table = Table(title="Ground-motion records")
    table.add_column("file", overflow="fold")
    table.add_column("points", justify="right")
    table.add_column(Text("step [s]"), justify="right")
    table.add_column(Text("duration [s]"), justify="right")
    table.add_column("units read")
    table.add_column(Text("PGA [g]"), justify="right")
    table.add_column(Text("PGV [m/s]"), justify="right")
    for f, gm in zip(files, motions, strict=True):
        table.add_row(f.name, str(gm.npts), f"{gm.dt:g}", f"{gm.duration:.6g}", gm.units_read,
                      f"{gm.pga_g:.4f}", f"{gm.pgv:.3f}")
    console.print(table)

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

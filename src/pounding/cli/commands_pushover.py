"""`pounding pushover`."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.tables import Col, force_scale, literal, number, print_table


@app.command("pushover")
def pushover_cmd(
    model_file: Annotated[Path, typer.Argument(
        help="TOML model file with a building given as frame = {...} (docs/frames.md).",
        show_default=False)],
    out: opt.Out = None,
    overwrite: opt.Overwrite = False,
    figures: opt.FiguresStudy = None,
    building: Annotated[str | None, typer.Option(
        "--building", metavar="NAME", help="The frame to push (default: \\[pushover] building, "
        "else the first frame).", show_default=False)] = None,
    to: Annotated[float | None, typer.Option(
        "--to", metavar="METRES", help="Roof displacement to push to \\[m] (default: "
        "\\[pushover] target, else 5 % of the frame's height).", show_default=False)] = None,
    pattern: Annotated[str | None, typer.Option(
        "--pattern", metavar="NAME", help="Lateral load pattern: uniform, triangular or "
        "first-mode (default: \\[pushover] pattern, else uniform).", show_default=False)] = None,
    stop_below: Annotated[float | None, typer.Option(
        "--stop-below", metavar="FRACTION", help="Stop once the base shear falls below this "
        "fraction of its peak (the deteriorating branch), e.g. 0.2.", show_default=False)]
        = None,
) -> None:
    """Static pushover of a frame: its capacity curve, event by event.

    Gravity first, then lateral loads growing under control of the roof displacement; the
    curve is exact (straight between the events where hinges yield or unload), with no
    iterations that could fail to converge. Writes pushover.csv, hinges.csv, summary.json
    and pushover.png.

    Examples:

      pounding pushover examples/portal_pushover.toml

      pounding pushover frame.toml --pattern first-mode --to 0.5 --out push --overwrite
    """
    from pounding.studies.pushover import run_pushover

    res = run_pushover(model_file, out, overwrite=overwrite, figures=figures,
                       building=building, target=to, pattern=pattern, stop_below=stop_below)
    r = res.result
    scale, unit = force_scale(float(abs(r.base_shear).max()))
    k = int(r.base_shear.argmax())
    rows = [(literal(res.frame.name), r.pattern, number(r.peak_base_shear * scale),
             number(r.roof_displacement[k] * 1e3), number(r.roof_displacement[-1] * 1e3),
             str(r.base_shear.size - 1), r.stopped)]
    print_table(console, "pushover", [Col("frame", "left"), Col("pattern"),
                                      Col(f"peak base shear [{unit}]"),
                                      Col("at roof displacement [mm]"),
                                      Col("pushed to [mm]"), Col("events"), Col("ended")], rows)
    console.print(Text.assemble("results in ", (str(res.out_dir), "bold"), ": "
                                + ", ".join(sorted(p.name for p in res.files.values()))))

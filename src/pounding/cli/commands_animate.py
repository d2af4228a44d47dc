"""`pounding animate`."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import app, console


@app.command("animate")
def animate_cmd(
    run_folder: Annotated[Path, typer.Argument(
        help="Output folder of `pounding run` (summary.json, timehistories.nc).",
        show_default=False)],
    out: Annotated[Path | None, typer.Option(
        "--out", "-o", metavar="DIR", help=f"{opt.OUT_HELP} Default: RUN_FOLDER.",
        show_default=False)] = None,
    fps: Annotated[float, typer.Option(
        "--fps", help="Frames per second of ground-motion time (at most 60; the video "
                      "plays in real time).")] = 25.0,
    exaggeration: Annotated[float | None, typer.Option(
        "--exaggeration", help="Factor on the displacements drawn. Default: a round factor "
                               "drawing the largest move about a tenth of the drawing's size "
                               "(the tallest height; in plan the largest plan dimension; a "
                               "bridge: half its longest deck).",
        show_default=False)] = None,
    start: Annotated[float | None, typer.Option(
        "--start", help=opt.escape("First time animated [s]. Default: the run's start."),
        show_default=False)] = None,
    end: Annotated[float | None, typer.Option(
        "--end", help=opt.escape("Last time animated [s]. Default: the run's end."),
        show_default=False)] = None,
    video: Annotated[bool, typer.Option(
        "--video/--no-video", help="Write the video (MP4 with ffmpeg, else GIF) beside the "
                                   "page.")] = True,
) -> None:
    """Animate a run: the buildings (in a row, or in plan from above) or the bridge's decks
    swaying and striking, the ground motion and the contact forces below; an interactive
    page (animation.html) and a video.

    Examples:

      pounding animate pounding-demo

      pounding animate model-results --start 2 --end 8 --exaggeration 20

      pounding animate model-results --out movies --no-video
    """
    from pounding.report.animate import write_animation

    result = write_animation(run_folder, out, fps=fps, exaggeration=exaggeration, start=start,
                             end=end, video=video)
    written = [result.html] + ([result.video] if result.video is not None else [])
    console.print(Text.assemble(
        "animation written: ", (", ".join(str(p) for p in written), "bold"),
        f" ({result.n_frames} frames, displacements × {result.exaggeration:g})"))

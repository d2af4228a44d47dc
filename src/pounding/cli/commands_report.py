"""`pounding report`."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import app, console  # noqa: F401


@app.command("report")
def report_cmd(
    results_dir: Annotated[Path, typer.Argument(
        help="Output folder of `pounding run` (summary.json, timehistories.nc), of "
             "`pounding sweep` (results.parquet) or of `pounding fragility` "
             "(fragility.json).", show_default=False)],
    html: Annotated[Path | None, typer.Option(
        "--html", metavar="FILE", help="Write the page to FILE. Default: report.html in "
                                       "RESULTS_DIR (in its manifest).",
        show_default=False)] = None,
    code_check: Annotated[Path | None, typer.Option(
        "--code-check", metavar="DIR", help=f"{opt.CODE_CHECK_HELP} The page gains its Code "
        "check section (instead of the check kept in RESULTS_DIR, if any).",
        show_default=False)] = None,
) -> None:
    """Write one self-contained HTML page (figures embedded) for a run, a sweep or a
    fragility study.

    Examples:

      pounding report pounding-demo

      pounding report sweep_gap_e-results --html study.html

      pounding report fragility_two_10_storey-results

      pounding report pounding-demo --code-check check
    """
    from pounding.io.files import check_output_file
    from pounding.report import write_report

    check_output_file(html, "--html")
    path = write_report(results_dir, html, code_check=code_check)
    size = path.stat().st_size
    console.print(Text.assemble("report written: ", (str(path), "bold"),
                                f" ({size / 1024:.0f} kB, self-contained)"))

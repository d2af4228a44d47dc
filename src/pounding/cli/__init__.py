"""Command-line interface: ``pounding <command>``; see ``pounding --help``.

:func:`main` is the console-script entry point. Bad input (a ``ValueError`` from the public
API, a missing file) is printed as one line naming the field and value, without a
traceback, and the process exits with status 2; usage errors also exit with 2.
"""

from __future__ import annotations

import sys

from rich.markup import escape

from pounding.cli import (  # noqa: F401  (each module registers its commands on ``app``)
    commands_contact,
    commands_ellipse,
    commands_gap,
    commands_record,
    commands_report,
    commands_run,
    commands_sweep,
)
from pounding.cli.app import app, err_console

__all__ = ["app", "main"]


def main(argv: list[str] | None = None) -> int:
    """Run the CLI and return its exit status: 0 success, 2 bad input or usage.

    Called with ``argv=None`` (the console script) it exits the process with that status.
    """
    try:
        app(args=argv, prog_name="pounding")
        code = 0
    except SystemExit as exc:  # typer/click end every run this way in standalone mode
        code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    except (ValueError, FileNotFoundError, IsADirectoryError, NotADirectoryError) as exc:
        err_console.print(f"[bold red]error:[/] {escape(str(exc))}", highlight=False,
                          soft_wrap=True)
        code = 2
    if argv is None:
        sys.exit(code)
    return code

"""Command-line interface: ``pounding <command>``; see ``pounding --help``.

:func:`main` is the console-script entry point. Bad input (a ``ValueError`` from the public
API, or a usage error) is printed as one line naming the field and value, without a
traceback, and the process exits with status 2.
"""

from __future__ import annotations

import sys

import click

from pounding.cli import commands_contact  # noqa: F401  (registers zeta, audit, calibrate, fit)
from pounding.cli.app import app, err_console

__all__ = ["app", "main"]


def main(argv: list[str] | None = None) -> int:
    """Run the CLI; return (and exit with) 0 on success, 2 on bad input."""
    try:
        app(args=argv, standalone_mode=False)
    except click.exceptions.Exit as exc:
        code = exc.exit_code
    except click.ClickException as exc:
        exc.show()
        code = 2
    except click.exceptions.Abort:
        err_console.print("aborted")
        code = 1
    except (ValueError, FileNotFoundError, IsADirectoryError) as exc:
        err_console.print(f"[bold red]error:[/] {exc}", highlight=False)
        code = 2
    else:
        code = 0
    if argv is None:
        sys.exit(code)
    return code

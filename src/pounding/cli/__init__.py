"""Command-line interface: ``pounding <command>``; see ``pounding --help``.

:func:`main` is the console-script entry point (and ``python -m pounding``). Every error
reaches the user as one line on standard error that starts with ``error:`` and names the
field (or option) and the value, without a traceback:

* bad input (a ``ValueError`` from the public API, a missing or unreadable file, an output
  folder that cannot be written) and usage errors (an unknown option, a bad option value)
  exit with status 2;
* a run stopped with Ctrl-C or SIGTERM exits with status 130 after saying what was kept;
* a sweep stopped by its cluster (a lost Dask scheduler, a failed worker) exits with
  status 1 after saying what was kept and how to resume.

An input that is valid but probably in the wrong unit (a gap of 40 m, a floor of 600 kg;
:mod:`pounding.config.plausibility`) is one line on standard error that starts
``warning:``; the command goes on.

Command modules import nothing heavier than typer, rich and NumPy at module level (none of
numba, SciPy, pandas, xarray, matplotlib, Dask or pydantic: ``tests/test_startup.py``);
everything else is imported by the command that uses it, so ``pounding --help`` and
``pounding --version`` start at once.
"""

from __future__ import annotations

import contextlib
import sys
import warnings
from collections.abc import Iterator
from typing import Any

import typer
from rich.markup import escape

from pounding.cli import (  # noqa: F401  (each module registers its commands on ``app``)
    commands_contact,
    commands_ellipse,
    commands_fragility,
    commands_gap,
    commands_mitigate,
    commands_record,
    commands_report,
    commands_run,
    commands_spectrum,
    commands_suite,
    commands_sweep,
)
from pounding.cli.app import app, err_console

__all__ = ["app", "main", "error_line", "warning_line"]

EXIT_BAD_INPUT = 2
"""Exit status of bad input and usage errors."""

EXIT_INTERRUPTED = 130
"""Exit status of a command stopped by Ctrl-C (128 + SIGINT), as shells report it."""

EXIT_FAILED = 1
"""Exit status of a command its environment stopped (a sweep whose Dask scheduler was lost)."""


_LINES_SAID: list[int] = [0]
"""How many error lines this process printed (so :func:`main` knows whether a command that
ended interrupted said what was kept)."""


def error_line(message: str) -> None:
    """Print an error on standard error, every line starting ``error: `` (a model file with
    three problems gives three such lines)."""
    for line in str(message).splitlines() or [""]:
        text = " ".join(line.split())
        if text:
            _LINES_SAID[0] += 1
            err_console.print(f"[bold red]error:[/] {escape(text)}", highlight=False,
                              soft_wrap=True)


def _usage_error(exc: typer.TyperException) -> int:
    """One line for a usage error (unknown option, bad value): what, and where to look."""
    ctx = getattr(exc, "ctx", None)
    if type(exc).__name__ == "NoArgsIsHelpError" and ctx is not None:
        # ``pounding`` (or a group) given no command: its help, as click prints it
        typer.echo(ctx.get_help())
        return 0
    where = ctx.command_path if ctx is not None else "pounding"
    message = exc.format_message() if hasattr(exc, "format_message") else str(exc)
    error_line(f"{where}: {message} (see '{where} --help')")
    return int(getattr(exc, "exit_code", EXIT_BAD_INPUT) or EXIT_BAD_INPUT)


def warning_line(message: str) -> None:
    """Print a warning on standard error as one line starting ``warning: ``."""
    text = " ".join(str(message).split())
    err_console.print(f"[bold yellow]warning:[/] {escape(text)}", highlight=False,
                      soft_wrap=True)


@contextlib.contextmanager
def _plausibility_lines() -> Iterator[None]:
    """Show every :class:`~pounding.plausibility.PlausibilityWarning` issued while a command
    runs as one ``warning:`` line on standard error, each text once; other warnings as
    Python shows them."""
    from pounding.plausibility import PlausibilityWarning

    shown: set[str] = set()
    with warnings.catch_warnings():
        warnings.simplefilter("always", PlausibilityWarning)
        python_shows = warnings.showwarning

        def show(message: Any, category: type[Warning], filename: str, lineno: int,
                 file: Any = None, line: str | None = None) -> None:
            if not issubclass(category, PlausibilityWarning):
                python_shows(message, category, filename, lineno, file, line)
            elif str(message) not in shown:
                shown.add(str(message))
                warning_line(str(message))

        warnings.showwarning = show
        yield


def main(argv: list[str] | None = None) -> int:
    """Run the CLI and return its exit status: 0 success, 2 bad input or usage, 130
    interrupted. Plausibility warnings (inputs probably in the wrong unit) are printed as
    ``warning:`` lines on standard error and change nothing else.

    Called with ``argv=None`` (the console script) it exits the process with that status.
    """
    with _plausibility_lines():
        return _main(argv)


def _main(argv: list[str] | None) -> int:
    said = _LINES_SAID[0]
    try:
        # SIGTERM as Ctrl-C in every command (what was kept is said, nothing half-written)
        with commands_run._sigterm_as_interrupt():
            rv = app(args=argv, prog_name="pounding", standalone_mode=False)
        code = rv if isinstance(rv, int) else 0
        if code == EXIT_INTERRUPTED and _LINES_SAID[0] == said:
            # typer turns an interrupt the command did not handle into 130, silently
            raise KeyboardInterrupt
    except SystemExit as exc:  # a command that ended itself with a status
        code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    except typer.Exit as exc:
        code = exc.exit_code
    except (typer.Abort, KeyboardInterrupt):
        error_line("stopped (interrupted); finished results were kept and no half-written "
                   "output was left")
        code = EXIT_INTERRUPTED
    except typer.TyperException as exc:
        code = _usage_error(exc)
    except (ValueError, OSError) as exc:
        # bad input from the public API (field and value named there), or a file that
        # cannot be read or written (the OS names the path)
        error_line(_os_error_text(exc) if isinstance(exc, OSError) else str(exc))
        code = EXIT_BAD_INPUT
    if argv is None:
        sys.exit(code)
    return code


def _os_error_text(exc: OSError) -> str:
    """``<path>: <reason>`` for a file-system error (no errno prefix)."""
    reason = exc.strerror or str(exc)
    if exc.filename is not None:
        return f"{exc.filename}: {reason.lower() if reason[:1].isupper() else reason}"
    return reason

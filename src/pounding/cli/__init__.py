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

Command modules import only typer, rich and the CLI's own helpers (``app``, ``options``: the
options shared by several commands, ``running``: progress bars and SIGTERM, ``messages``,
``tables``) at module level; everything else is imported by the command that uses it, so
``pounding --help`` and ``pounding --version`` start at once (no NumPy;
``tests/test_startup.py``).
"""

from __future__ import annotations

import contextlib
import sys
import warnings
from collections.abc import Iterator
from typing import Any

import typer

from pounding.cli import (  # noqa: F401  (each module registers its commands on ``app``)
    commands_animate,
    commands_code_check,
    commands_contact,
    commands_ellipse,
    commands_fragility,
    commands_gap,
    commands_match,
    commands_mitigate,
    commands_pushover,
    commands_record,
    commands_report,
    commands_run,
    commands_spectrum,
    commands_suite,
    commands_sweep,
    commands_synthesize,
)
from pounding.cli.app import app, use_pounding_commands
from pounding.cli.messages import (
    EXIT_BAD_INPUT,
    EXIT_FAILED,
    EXIT_INTERRUPTED,
    error_line,
    lines_said,
    warning_line,
)
from pounding.cli.running import sigterm_as_interrupt

use_pounding_commands()

__all__ = ["EXIT_BAD_INPUT", "EXIT_FAILED", "EXIT_INTERRUPTED", "app", "main", "error_line",
           "warning_line"]

def _usage_error(exc: typer.TyperException) -> int:
    """One line for a usage error (unknown option, bad value): what, and where to look."""
    ctx = getattr(exc, "ctx", None)
    if type(exc).__name__ == "NoArgsIsHelpError" and ctx is not None:
        # ``pounding`` (or a group) given no command: its help, as click prints it
        typer.echo(ctx.get_help())
        return 0
    where = ctx.command_path if ctx is not None else "pounding"
    message = exc.format_message() if hasattr(exc, "format_message") else str(exc)
    message = " ".join(message.split())  # click lists choices one a line: one line here
    error_line(f"{where}: {message} (see '{where} --help')")
    return int(getattr(exc, "exit_code", EXIT_BAD_INPUT) or EXIT_BAD_INPUT)


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
    """Run the CLI and return its exit status: 0 success, 2 bad input or usage, 1 a run
    whose frame collapsed (or a study its environment stopped), 130 interrupted. Plausibility warnings (inputs probably in the wrong unit) are printed as
    ``warning:`` lines on standard error and change nothing else.

    Called with ``argv=None`` (the console script) it exits the process with that status.
    """
    with _plausibility_lines():
        return _main(argv)


def _main(argv: list[str] | None) -> int:
    said = lines_said()
    try:
        # SIGTERM as Ctrl-C in every command (what was kept is said, nothing half-written)
        with sigterm_as_interrupt():
            rv = app(args=argv, prog_name="pounding", standalone_mode=False)
        code = rv if isinstance(rv, int) else 0
        if code == EXIT_INTERRUPTED and lines_said() == said:
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
        # (an error that is a result, a frame that collapsed, says its own status)
        code = int(getattr(exc, "exit_status", EXIT_BAD_INPUT))
    if argv is None:
        sys.exit(code)
    return code


def _os_error_text(exc: OSError) -> str:
    """``<path>: <reason>`` for a file-system error (no errno prefix)."""
    reason = exc.strerror or str(exc)
    if exc.filename is not None:
        return f"{exc.filename}: {reason.lower() if reason[:1].isupper() else reason}"
    return reason

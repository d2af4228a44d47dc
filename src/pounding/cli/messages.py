"""What a command says on standard error, and the exit statuses.

Every error reaches the user as one line on standard error that starts with ``error:``
(:func:`error_line`), every warning as one that starts with ``warning:``
(:func:`warning_line`); :mod:`pounding.cli` says which exit status goes with which.
"""

from __future__ import annotations

from rich.markup import escape

from pounding.cli.app import err_console

__all__ = ["EXIT_BAD_INPUT", "EXIT_FAILED", "EXIT_INTERRUPTED", "error_line", "lines_said",
           "warning_line"]

EXIT_BAD_INPUT = 2
"""Exit status of bad input and usage errors."""

EXIT_INTERRUPTED = 130
"""Exit status of a command stopped by Ctrl-C (128 + SIGINT), as shells report it."""

EXIT_FAILED = 1
"""Exit status of a command its environment stopped (a sweep whose Dask scheduler was lost),
or a run that stopped because a frame collapsed
(:class:`pounding.structure.frame_configuration.FrameCollapse`: a result, not bad input)."""


_LINES_SAID: list[int] = [0]
"""How many error lines this process printed (so :func:`pounding.cli.main` knows whether a
command that ended interrupted said what was kept)."""


def lines_said() -> int:
    """How many error lines this process printed so far."""
    return _LINES_SAID[0]


def error_line(message: str) -> None:
    """Print an error on standard error, every line starting ``error: `` (a model file with
    three problems gives three such lines)."""
    for line in str(message).splitlines() or [""]:
        text = " ".join(line.split())
        if text:
            _LINES_SAID[0] += 1
            err_console.print(f"[bold red]error:[/] {escape(text)}", highlight=False,
                              soft_wrap=True)


def warning_line(message: str) -> None:
    """Print a warning on standard error as one line starting ``warning: ``."""
    text = " ".join(str(message).split())
    err_console.print(f"[bold yellow]warning:[/] {escape(text)}", highlight=False,
                      soft_wrap=True)

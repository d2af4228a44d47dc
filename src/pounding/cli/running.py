"""What every command that runs simulations shares: its progress bar, SIGTERM taken as
Ctrl-C, and what a stopped sweep (or study) says.

Every runner reports progress the same way, ``progress(done, total)``
(:class:`pounding.progress.Progress`); :func:`progress_bar` is the bar that shows it.
"""

from __future__ import annotations

import contextlib
import signal
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any, NoReturn

import typer
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    ProgressColumn,
    Task,
    TaskProgressColumn,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)
from rich.text import Text

from pounding.cli.app import compiling_text, console, err_console

__all__ = ["COMPILE_NOTE_AFTER", "PROGRESS_DELAY", "again", "compiling_text", "progress_bar",
           "sigterm_as_interrupt", "stopped"]

PROGRESS_DELAY = 1.0
"""Seconds before a progress bar appears: quick commands print no bar."""

COMPILE_NOTE_AFTER = 5.0
"""Seconds at 0 % after which a run's bar says why: the first run compiles the solver."""


class _DelayedProgress(Progress):
    """A rich progress display that renders nothing until ``delay`` seconds have passed."""

    def __init__(self, *columns: Any, delay: float = PROGRESS_DELAY, **kw: Any) -> None:
        self._t0 = time.monotonic()
        self._delay = delay
        super().__init__(*columns, **kw)

    def get_renderables(self) -> Iterator[Any]:
        if time.monotonic() - self._t0 >= self._delay:
            yield from super().get_renderables()


class _CompilingNote(ProgressColumn):
    """Says what a bar at 0 % is waiting for: on the first run after an install (or after the
    kernel's source changed, or with an empty ``NUMBA_CACHE_DIR``) numba compiles the solver
    once; the compiled code is cached, and later runs start at once.

    ``seconds``: the compiling the run will do first, as numba's cache index tells
    (:func:`pounding.integrate.solver_compile_seconds`): where positive, the note shows from
    the start; else (cached, or not known) only if the bar stays at 0 % for
    :data:`COMPILE_NOTE_AFTER` seconds, in case the cache did not hold this run's kernel."""

    def __init__(self, seconds: float = 0.0) -> None:
        self._seconds = seconds
        super().__init__()

    def render(self, task: Task) -> Text:
        if task.completed != 0:
            return Text("")
        if self._seconds > 0.0:
            return Text(compiling_text(self._seconds), style="dim")
        if (task.elapsed or 0.0) >= COMPILE_NOTE_AFTER:
            return Text("probably compiling the solver: first run only (cached after)",
                        style="dim")
        return Text("")


def solver_compile_seconds() -> float:
    """:func:`pounding.integrate.solver_compile_seconds` (imports the solver, which the work
    that follows a progress bar imports anyway)."""
    from pounding.integrate import solver_compile_seconds as seconds

    return seconds()


class _RateColumn(ProgressColumn):
    """Items (cases, runs) per second."""

    def __init__(self, items: str) -> None:
        self._items = items
        super().__init__()

    def render(self, task: Task) -> Text:
        speed = task.finished_speed or task.speed
        return Text(f"-- {self._items}/s" if speed is None else f"{speed:,.1f} {self._items}/s")


@contextlib.contextmanager
def progress_bar(label: str, items: str | None = None) -> Iterator[Any]:
    """A progress bar, and the ``progress(done, total)`` callback that moves it.

    Parameters
    ----------
    label : str
        What is running (printed literally).
    items : str, optional
        What is counted (``"cases"``, ``"runs"``): the bar then shows ``done/total`` and a
        rate; work finished by an earlier command (the first ``done``) counts as done from
        the start, without a rate. None: a run, counted in seconds of ground motion; a bar
        stuck at 0 % says the solver is probably compiling.

    The bar appears after :data:`PROGRESS_DELAY` seconds, on a terminal only (a log gets
    none), and goes when the block ends. Where the solver is not compiled yet (numba's
    cache holds none for this machine) the bar says so from the start, and off a terminal
    one line on standard error does (:func:`compiling_text`).
    """
    compiling = solver_compile_seconds()
    columns: list[Any] = [TextColumn("{task.description}", style="bold", markup=False),
                          BarColumn()]
    if items is not None:
        columns += [MofNCompleteColumn(), TaskProgressColumn(), _RateColumn(items),
                    TimeElapsedColumn(), TimeRemainingColumn()]
        if compiling > 0.0:
            columns.append(_CompilingNote(compiling))
    else:
        columns += [TaskProgressColumn(), TimeElapsedColumn(), TimeRemainingColumn(),
                    _CompilingNote(compiling)]
    bar = _DelayedProgress(*columns, console=console, transient=True,
                           disable=not console.is_terminal)
    if compiling > 0.0 and not console.is_terminal:
        err_console.print(Text(compiling_text(compiling), style="dim"))
    task = bar.add_task(label, total=None, start=items is None)
    first: list[float] = []

    def progress(done: float, total: float) -> None:
        if not first and items is not None:  # work finished before: no rate for it
            first.append(done)
            bar.update(task, total=total, completed=done)
            bar.start_task(task)
            return
        bar.update(task, total=total, completed=done)

    with bar:
        yield progress


@contextlib.contextmanager
def sigterm_as_interrupt() -> Iterator[None]:
    """Turn SIGTERM into KeyboardInterrupt while running, so the temporary output folder is
    removed on ``kill`` as on Ctrl-C."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def handler(signum: int, frame: Any) -> None:
        raise KeyboardInterrupt(f"signal {signum}")

    previous = signal.signal(signal.SIGTERM, handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def stopped(exc: Any, command: str, what: str) -> NoReturn:
    """Say what a stopped sweep kept and how to resume it (``command``: the command that
    resumes it, :func:`again`; ``what``: ``cases``, ``runs``), and exit with 130
    (interrupted) or 1 (stopped by the cluster)."""
    from pounding.cli.messages import EXIT_FAILED, EXIT_INTERRUPTED, error_line
    from pounding.studies.sweep import SweepInterrupted

    if exc.n_saved:
        error_line(f"{exc.reason}: {exc.n_saved:,} of {exc.n_cases:,} {what} are saved in "
                   f"{exc.out_dir}; resume with: {command}")
    else:
        error_line(f"{exc.reason} before any {what[:-1]} was saved, leaving {exc.out_dir} as "
                   f"it was; start again with: {command}")
    raise typer.Exit(EXIT_INTERRUPTED if isinstance(exc, SweepInterrupted)
                     else EXIT_FAILED) from None


def again(input_file: Path, command: str, **options: Any) -> str:
    """The command that resumes a sweep (or another ``command`` run as one, such as
    ``fragility``): the same options, never ``--overwrite``."""
    import shlex

    argv = ["pounding", command, str(input_file)]
    for name, value in options.items():
        if value is not None:
            argv += [f"--{name.replace('_', '-')}", str(value)]
    return shlex.join(argv)

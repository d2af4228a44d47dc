"""`pounding run` and `pounding demo`."""

from __future__ import annotations

import contextlib
import signal
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Annotated, Any

import typer
from rich.progress import (
    BarColumn,
    Progress,
    ProgressColumn,
    Task,
    TaskProgressColumn,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)
from rich.table import Table
from rich.text import Text

from pounding.cli.app import app, console

PROGRESS_DELAY = 1.0
"""Seconds before the progress bar appears: quick runs print no bar."""


class _DelayedProgress(Progress):
    """A rich progress display that renders nothing until ``delay`` seconds have passed."""

    def __init__(self, *columns: Any, delay: float = PROGRESS_DELAY, **kw: Any) -> None:
        self._t0 = time.monotonic()
        self._delay = delay
        super().__init__(*columns, **kw)

    def get_renderables(self) -> Iterator[Any]:  # type: ignore[override]
        if time.monotonic() - self._t0 >= self._delay:
            yield from super().get_renderables()


COMPILE_NOTE_AFTER = 5.0
"""Seconds at 0 % after which the bar says why: the first run compiles the solver."""


class _CompilingNote(ProgressColumn):
    """Says what a bar stuck at 0 % is waiting for: on the first run after an install (or
    after the kernel's source changed) numba compiles the solver, about 20–30 s on a
    2-core machine; the compiled code is cached, and later runs start at once."""

    def render(self, task: Task) -> Text:
        if task.completed == 0 and (task.elapsed or 0.0) >= COMPILE_NOTE_AFTER:
            return Text("probably compiling the solver: first run only, about 20–30 s "
                        "(cached after)", style="dim")
        return Text("")


@contextlib.contextmanager
def _progress_bar(label: str) -> Iterator[Callable[[float], None]]:
    bar = _DelayedProgress(TextColumn("{task.description}", style="bold", markup=False),
                           BarColumn(),
                           TaskProgressColumn(), TimeElapsedColumn(), TimeRemainingColumn(),
                           _CompilingNote(), console=console, transient=True,
                           disable=not console.is_terminal)  # (a log gets no bar)
    task = bar.add_task(label, total=1.0)

    def update(fraction: float) -> None:
        bar.update(task, completed=fraction)

    with bar:
        yield update


@contextlib.contextmanager
def _sigterm_as_interrupt() -> Iterator[None]:
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


def _run(model_file: Path, out: Path | None, overwrite: bool, figures: bool | None,
         label: str) -> None:
    from pounding.config import load_config
    from pounding.run_file import default_out_dir, run_config

    from pounding.cli import EXIT_INTERRUPTED, error_line

    cfg = load_config(model_file)
    target = out if out is not None else default_out_dir(model_file)
    try:
        with _sigterm_as_interrupt(), _progress_bar(label) as progress:
            result = run_config(cfg, target, progress=progress, overwrite=overwrite,
                                figures=figures)
    except KeyboardInterrupt:
        error_line(f"stopped: the run was interrupted, so nothing was written to {target} "
                   "(an earlier output there is as it was); run the same command again")
        raise typer.Exit(EXIT_INTERRUPTED) from None
    from pounding.cli.run_tables import print_run_summary

    print_run_summary(result)


OutOpt = Annotated[Path | None, typer.Option(
    "--out", "-o", help="Output folder (default: MODEL-STEM-results in the current folder). "
                        "Written complete or not at all.", show_default=False)]
OverwriteOpt = Annotated[bool, typer.Option(
    "--overwrite", help="Replace the output folder if it exists: only an empty folder or an "
                        "earlier run's, holding nothing but the files of its manifest; the old "
                        "one goes, file by file, once the new is complete.")]
FiguresOpt = Annotated[bool | None, typer.Option(
    "--figures/--no-figures", help="Write the PNG figures (default: [output] figures of the "
                                   "model file, true if not given).", show_default=False)]


@app.command("run")
def run_cmd(
    model: Annotated[Path, typer.Argument(help="TOML model file (see docs/running.md).",
                                          show_default=False)],
    out: OutOpt = None,
    overwrite: OverwriteOpt = False,
    figures: FiguresOpt = None,
) -> None:
    """Simulate a model file and write time histories, impacts, summary and figures.

    Examples:

      pounding run examples/seed_sdof_pair.toml --out results/sdof

      pounding run model.toml --no-figures --overwrite
    """
    _run(model, out, overwrite, figures, f"simulating {model.name}")


@app.command("demo")
def demo_cmd(
    out: Annotated[Path, typer.Option(
        "--out", "-o", help="Output folder.")] = Path("pounding-demo"),
    overwrite: Annotated[bool, typer.Option(
        "--overwrite/--no-overwrite",
        help="Replace an earlier output in the folder (default: yes, so the demo can be run "
             "again; a folder holding anything pounding did not write is never replaced).")
] = True,
    figures: FiguresOpt = None,
) -> None:
    """Two 10-storey buildings pounding under El Centro 1940: the bundled example
    two_10_storey.toml (see it with `pounding examples`).

    Examples:

      pounding demo

      pounding demo --out results/demo --no-figures
    """
    from pounding.example_files import DEMO, example_path

    _run(example_path(DEMO), out, overwrite, figures, "demo: two 10-storey buildings")


@app.command("examples")
def examples_cmd(
    copy: Annotated[Path | None, typer.Option(
        "--copy", metavar="DIR", help="Copy every example (and its README) into the folder "
                                      "DIR, made if missing.", show_default=False)] = None,
    overwrite: Annotated[bool, typer.Option(
        "--overwrite", help="With --copy: replace files of the same names.")] = False,
) -> None:
    """List the example model, sweep, spectrum and fragility files of pounding, or copy them.

    Examples:

      pounding examples

      pounding examples --copy my-examples && pounding run my-examples/seed_sdof_pair.toml
    """
    from pounding.example_files import copy_examples, example_path, examples

    if copy is not None:
        files = copy_examples(copy, overwrite=overwrite)
        console.print(Text.assemble(f"copied {len(files)} files into ", (str(copy), "bold"),
                                    ": " + ", ".join(p.name for p in files)))
        return
    table = Table(title=f"Examples (in {example_path('seed_sdof_pair').parent})")
    table.add_column("file")
    table.add_column("kind")
    table.add_column("what it shows", overflow="fold")
    for e in examples():
        table.add_row(e.name, e.kind, e.description)
    console.print(table)
    console.print("Run one with `pounding run FILE` (a sweep: `pounding sweep FILE`, a fragility "
                  "study: `pounding fragility FILE`); copy them with `pounding examples --copy "
                  "DIR`.", highlight=False)

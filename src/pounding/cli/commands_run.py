"""`pounding run` and `pounding demo`."""

from __future__ import annotations

import contextlib
import signal
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Annotated, Any

import numpy as np
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
    bar = _DelayedProgress(TextColumn("[bold]{task.description}"), BarColumn(),
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


def _h(text: str) -> Text:
    """A header cell: brackets in units are literal, not rich markup."""
    return Text(text)


def _print_summary(out: Any) -> None:
    """The tables printed after a run (``out`` is a :class:`pounding.run.RunOutput`)."""
    from pounding.structure.assembly import floor_dofs

    r = out.result
    model = r.model
    s = r.summary()

    head = Table(title=f"{model.name}: pounding run", show_header=False)
    head.add_column("quantity")
    head.add_column("value", justify="right")
    head.add_row("record", f"{r.motion.name}, PGA {r.motion.pga_g:.3f} g")
    head.add_row(_h("simulated [s] / output step [s]"), f"{s['duration_s']:g} / {r.dt:g}")
    head.add_row("buildings / contacts", f"{len(model.buildings)} / {len(model.contacts)}")
    if model.contacts:
        head.add_row("contact law", model.contact.describe())
    head.add_row("impacts", str(r.n_impacts))
    t_peak = s["peak_contact_force_time_s"]
    head.add_row(_h("peak contact force [N]"), f"{s['peak_contact_force_N']:.4g}"
                 + (f" at {t_peak:.3f} s" if t_peak is not None else ""))
    head.add_row(_h("energy input [J]"), f"{s['energy_final_J']['input']:.4g}")
    head.add_row(_h("dissipated in contacts [J]"), f"{s['contact_dissipated_J']:.4g}")
    if model.links:
        head.add_row(_h("dissipated by links [J]"), f"{s['links_dissipated_J']:.4g}")
    head.add_row("energy-balance error", f"{r.energy_balance_error:.2e} of peak input")
    if r.stats.impact_overflow:
        head.add_row("[red]impact table[/]", "[red]overflowed: some impacts not listed[/]")
    head.add_row(_h("wall time [s]"), f"{r.wall_time:.2f} integrating, {out.wall_time:.2f} total")
    console.print(head)

    from pounding.summary import floor_rotations

    rotations = {(b, k) for b, k, *_ in floor_rotations(r)}
    bt = Table(title="Buildings (peaks located inside solver steps)")
    cols = [("building", "left"), ("storeys", "right"), ("T1, T2, T3 [s]", "right"),
            ("peak roof displacement [m]", "right"), ("at t [s]", "right"),
            ("peak drift [m]", "right"), ("at storey", "right"), ("peak drift ratio", "right"),
            ("peak storey shear [kN]", "right")]
    inelastic = model.is_inelastic
    if inelastic:
        cols += [("storey law", "left"), ("peak ductility", "right"),
                 ("largest residual drift [m]", "right")]
    for col, just in cols:
        bt.add_column(_h(col), justify=just)  # type: ignore[arg-type]
    drift = r.peak_drift
    shear = r.peak_storey_shear
    for b, (bl, off) in enumerate(zip(model.buildings, model.system.offsets)):
        floors = floor_dofs(bl)  # storey k + 1 is the one below floors[k]
        d = drift[off + floors]
        j = int(np.argmax(d))
        v = shear[off + floors]
        jv = int(np.argmax(v)) if np.isfinite(v).all() else -1
        periods = ", ".join(f"{t:.3f}" for t in bl.modes().periods[:3])
        roof = off + int(floors[-1])
        row = [f"B{b + 1} {bl.name}".strip(), str(floors.size), periods,
               f"{r.peak_displacement[roof]:.4f}", f"{r.peak_displacement_time[roof]:.3f}",
               f"{d[j]:.4f}", str(j + 1), f"{d[j] / bl.heights[floors[j]]:.2%}",
               f"{v[jv] / 1e3:.4g} (storey {jv + 1})" if jv >= 0 else
               "– (in plan)" if any(k[0] == b for k in rotations) else "– (matrices)"]
        if inelastic:
            law = bl.storey_law
            if law is None:
                row += ["linear", "-", "-"]
            else:
                mu = r.ductility[off: off + bl.n]
                res = r.residual_drift[off: off + bl.n]
                jr = int(np.argmax(np.abs(res)))
                row += [law.label, f"{np.nanmax(mu):.2f} (storey {int(np.nanargmax(mu)) + 1})",
                        f"{res[jr]:+.4f} (storey {jr + 1})"]
        bt.add_row(*row)
    console.print(bt)
    _print_storeys(r)

    if model.contacts:
        ct = Table(title="Contacts")
        columns = any(c.struck is not None for c in model.contacts)
        for col in ("contact", "elevation [m]", "gap [m]", "impacts", "peak force [N]",
                    "at t [s]", "dissipated [J]") + (("peak column shear [N]", "÷ storey shear")
                                         if columns else ()):
            ct.add_column(_h(col), justify="left" if col == "contact" else "right")
        counts = r.impacts_per_contact
        dissipated = r.dissipated_per_contact
        pcf = r.peak_contact_force
        pcs = r.peak_column_shear if columns else None
        for c in model.contacts:
            hit = counts[c.index] > 0
            cells = [c.label, f"{c.elevation:g}", f"{c.gap:g}", str(counts[c.index]),
                     f"{pcf[c.index]:.4g}" if hit else "-",
                     f"{r.peak_contact_force_time[c.index]:.3f}" if hit else "-",
                     f"{dissipated[c.index]:.4g}" if hit else "-"]
            if pcs is not None:
                hit = hit and c.struck is not None and bool(np.isfinite(pcs[c.index]))
                cells += [f"{pcs[c.index]:.4g}" if hit else "-",
                          f"{r.column_shear_ratio[c.index]:.2f}" if hit else "-"]
            ct.add_row(*cells)
        console.print(ct)

    if model.links:
        lt = Table(title="Links between buildings")
        for col in ("link", "law", "peak force [kN]", "dissipated [J]"):
            lt.add_column(_h(col), justify="left" if col in ("link", "law") else "right")
        for link, f, e in zip(model.links, r.link_peak_force, r.link_dissipated):
            lt.add_row(link.name, link.readable().split(": ", 1)[1], f"{f / 1e3:.4g}",
                       f"{e:.4g}")
        console.print(lt)

    console.print(f"outputs in [bold]{out.out_dir}[/]: "
                  + ", ".join(sorted(p.name for p in out.files.values())), highlight=False)


STOREY_ROWS = 30
"""Buildings with more storeys list only the :data:`STOREY_ROWS` … of largest drift ratio."""


def _print_storeys(r: Any) -> None:
    """Every storey's peaks with their times (the envelope figure, as numbers); a building
    of more than :data:`STOREY_ROWS` storeys shows the ten with the largest drift ratio."""
    from pounding.structure.assembly import floor_dofs
    from pounding.summary import floor_rotations

    rotations = {(b, k): (v, t) for b, k, _, v, t in floor_rotations(r)}
    st = Table(title="Storeys: peaks and when (all of them in summary.json)"
               + ("; in plan: displacement and drift along x, rotation of the floor"
                  if rotations else ""))
    for col in ("building", "storey", "floor at [m]", "displacement [mm]", "t [s]",
                "drift ratio [%]", "t [s]", "storey shear [kN]", "t [s]",
                "abs. acceleration [m/s²]", "t [s]") + (
                    ("rotation [mrad]", "t [s]") if rotations else ()):
        st.add_column(_h(col), justify="left" if col == "building" else "right")
    ratio = r.peak_drift_ratio
    shear, shear_t = r.peak_storey_shear, r.peak_storey_shear_time
    for b, (bl, off) in enumerate(zip(r.model.buildings, r.model.system.offsets)):
        floors = floor_dofs(bl)  # storeys by elevation (a matrix building's floor DOFs)
        rows = range(floors.size)
        if floors.size > STOREY_ROWS:
            rows = sorted(np.argsort(-ratio[off + floors])[:10])
        for k in rows:
            j = int(floors[k])
            i = off + j
            has_shear = bool(np.isfinite(shear[i]))
            rot = rotations.get((b, int(k)))
            twist = ([f"{rot[0] * 1e3:.4g}", f"{rot[1]:.3f}"] if rot is not None
                     else ["–", "–"] if rotations else [])
            st.add_row(f"B{b + 1} {bl.name}".strip(), str(int(k) + 1),
                       f"{bl.floor_levels[j]:g}",
                       f"{r.peak_displacement[i] * 1e3:.2f}", f"{r.peak_displacement_time[i]:.3f}",
                       f"{ratio[i] * 100:.3f}", f"{r.peak_drift_time[i]:.3f}",
                       f"{shear[i] / 1e3:.5g}" if has_shear else "–",
                       f"{shear_t[i]:.3f}" if has_shear else "–",
                       f"{r.peak_abs_acceleration[i]:.4g}",
                       f"{r.peak_abs_acceleration_time[i]:.3f}", *twist)
        if floors.size > STOREY_ROWS:
            st.add_row(f"B{b + 1}", "…", "", "", "", "", "", "", "", "", "",
                       *([""] * (2 if rotations else 0)))
    console.print(st)


def _run(model_file: Path, out: Path | None, overwrite: bool, figures: bool | None,
         label: str) -> None:
    from pounding.config import load_config
    from pounding.run import default_out_dir, run_config

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
    _print_summary(result)


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
        console.print(f"copied {len(files)} files into [bold]{copy}[/]: "
                      + ", ".join(p.name for p in files), highlight=False)
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

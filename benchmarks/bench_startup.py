"""Whole-process CPU and wall time of the commands a user types first, each against its peer
measured in the same minute (not a test: a measurement).

Each command runs as its own process, as a user runs it, ``--repeat`` times (default 5).
Before every run of it the peer runs once, ``python -c "import numpy, numba"`` (what any
numba program pays before it does anything), so the two alternate and see the same machine.
For each command the table gives

* its CPU time (user + system of the process, from ``os.wait4``): the best and the spread
  (min–max) of the repeats;
* its wall time, best and spread;
* the ratio of its CPU to the peer's: best to best, and the spread of the ratios of the
  runs paired with their peer;
* for a run, the integration alone as the run reports it (``summary.json``:
  ``solver.wall_time_s``): the rest is start-up, loading the compiled kernel, writing files
  and figures;

and the machine's load average before and after.

Goals (issue 30), on the CPU ratio to the peer: a warm ``pounding run`` of the two-SDOF
example ≤ 2× with figures off, ≤ 4× with figures; a warm ``pounding demo`` ≤ 5×.
``--cold`` also measures the first run on a fresh machine: the demo with numba's cache
pointed at an empty folder (``NUMBA_CACHE_DIR``), so everything is compiled once (goal
≤ 20 s of CPU).

The commands run with ``PYTHONDONTWRITEBYTECODE`` removed from their environment, so that
pounding's modules are read from their compiled ``.pyc`` files, as an installed package's
are (a checkout run with that variable set compiles every module from source at each start,
~0.3 s more).

Run from the repository root::

    python benchmarks/bench_startup.py             # warm commands, 5 repeats
    python benchmarks/bench_startup.py --cold      # and the first (compiling) run
    python benchmarks/bench_startup.py --phases    # and where a warm run's CPU goes

The machine is shared: close other work, and compare within one run.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import _figures
from _environment import load

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
BIN = Path(sys.executable).parent
POUNDING = str(BIN / "pounding")
PEER = [sys.executable, "-c", "import numpy, numba"]


def child_env(**extra: str) -> dict[str, str]:
    """The environment of a measured command: this one, without
    ``PYTHONDONTWRITEBYTECODE`` (module docstring), with ``extra``."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    return {**env, **extra}


def measure(cmd: list[str], cwd: Path, env: dict[str, str]) -> tuple[float, float]:
    """``(cpu, wall)`` [s] of one process: its user + system CPU time, and the seconds from
    start to exit (its output discarded; a failure stops the benchmark, showing the end of
    what the process said on standard error)."""
    with tempfile.TemporaryFile() as errors:
        t = time.perf_counter()
        proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.DEVNULL,
                                stderr=errors)
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - t
        proc.returncode = os.waitstatus_to_exitcode(status)
        if proc.returncode != 0:
            errors.seek(0)
            said = errors.read().decode(errors="replace")[-2000:]
            raise SystemExit(f"{' '.join(cmd)}: exit status {proc.returncode}\n{said}")
    return usage.ru_utime + usage.ru_stime, wall


PHASES = """
import resource, sys, tempfile


def cpu():
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


marks = [("start", cpu())]
import numpy, numba
marks.append(("import numpy, numba (the peer's imports)", cpu()))
import scipy.linalg
marks.append(("import scipy.linalg (the propagator's expm)", cpu()))
import pydantic, typer, rich.console, rich.progress, rich.table
marks.append(("import pydantic, typer, rich", cpu()))
import h5netcdf
marks.append(("import h5netcdf, h5py (the NetCDF writer)", cpu()))
import pounding.cli, pounding.cli.run_tables, pounding.config.run, pounding.run_file
marks.append(("import pounding's modules of a run", cpu()))
from pounding.config import load_config
config = load_config(sys.argv[1])
marks.append(("load_config: read, validate, build, check", cpu()))
model, motion, options = config.build()
from pounding.integrate import simulate
result = simulate(model, motion, **options)
marks.append(("first simulate: the kernel loaded from numba's cache", cpu()))
result = simulate(model, motion, **options)
marks.append(("second simulate: the integration alone", cpu()))
result.save(tempfile.mkdtemp() + "/out")
marks.append(("save: NetCDF, CSV, JSON", cpu()))
for (_, before), (name, after) in zip(marks, marks[1:]):
    print(f"{after - before:6.3f} s  {name}")
print(f"{marks[-1][1]:6.3f} s  the whole process so far")
"""
"""An in-process account of the CPU a run spends, phase by phase (``--phases``)."""


def integration_time(out: Path) -> float:
    """The integration's own wall time [s], as the run wrote it in ``summary.json``."""
    return float(json.loads((out / "summary.json").read_text())["solver"]["wall_time_s"])


@dataclass
class Row:
    """The repeats of one command and of the peer run just before each."""

    name: str
    goal: float | None = None  #: the largest CPU ratio to the peer asked for
    cpu: list[float] = field(default_factory=list)
    wall: list[float] = field(default_factory=list)
    peer: list[float] = field(default_factory=list)
    solver: list[float] = field(default_factory=list)

    def ratio(self) -> float:
        """Best CPU over the peer's best CPU."""
        return min(self.cpu) / min(self.peer)

    def line(self) -> str:
        ratios = [c / p for c, p in zip(self.cpu, self.peer)]
        integrating = f"{min(self.solver) * 1e3:6.1f} ms" if self.solver else " " * 9
        goal = ""
        if self.goal is not None:
            goal = f"≤ {self.goal:g}×: {'met' if self.ratio() <= self.goal else 'MISSED'}"
        return (f"{self.name:46s} {min(self.cpu):5.2f} s ({min(self.cpu):.2f}–"
                f"{max(self.cpu):.2f})  {min(self.wall):5.2f} s ({min(self.wall):.2f}–"
                f"{max(self.wall):.2f})  {self.ratio():5.2f}× ({min(ratios):.2f}–"
                f"{max(ratios):.2f})  {integrating}  {goal}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=5, help="runs of each command (5)")
    ap.add_argument("--cold", action="store_true",
                    help="also time the first run with an empty numba cache")
    ap.add_argument("--phases", action="store_true",
                    help="also account for a warm run's CPU phase by phase, in one process")
    _figures.add_json_option(ap)
    args = ap.parse_args(argv)
    _figures.start("bench_startup", "Start-up: whole commands as a user types them")

    env = child_env()
    work = Path(tempfile.mkdtemp(prefix="bench-startup-"))
    try:
        print(f"{time.strftime('%Y-%m-%d %H:%M')}; {os.cpu_count()} CPUs; python "
              f"{sys.version.split()[0]}; {load()} (before)")
        # warm every cache once (the kernel, the figures' fonts, the modules' .pyc)
        for cmd in ([POUNDING, "run", str(SEED), "--out", str(work / "warm")],
                    [POUNDING, "demo", "--out", str(work / "demo")]):
            measure(cmd, work, env)
        cases: list[tuple[str, list[str], float | None, Path | None]] = [
            ("python -c pass", [sys.executable, "-c", "pass"], None, None),
            ("python -c 'import numpy, numba' (the peer)", PEER, None, None),
            ("python -c 'import pounding'", [sys.executable, "-c", "import pounding"],
             None, None),
            ("pounding --version", [POUNDING, "--version"], None, None),
            ("pounding --help", [POUNDING, "--help"], None, None),
            ("pounding run seed_sdof_pair.toml --no-figures",
             [POUNDING, "run", str(SEED), "--out", str(work / "a"), "--overwrite",
              "--no-figures"], 2.0, work / "a"),
            ("pounding run seed_sdof_pair.toml",
             [POUNDING, "run", str(SEED), "--out", str(work / "b"), "--overwrite"],
             4.0, work / "b"),
            ("pounding demo", [POUNDING, "demo", "--out", str(work / "demo")], 5.0,
             work / "demo"),
        ]
        print(f"\n{'command (whole process)':46s} {'CPU best (spread)':>19s}  "
              f"{'wall best (spread)':>19s}  {'CPU / peer (pairs)':>19s}  "
              f"{'integrating':>9s}  goal")
        for name, cmd, goal, out in cases:
            row = Row(name, goal)
            for _ in range(args.repeat):
                row.peer.append(measure(PEER, work, env)[0])
                cpu, wall = measure(cmd, work, env)
                row.cpu.append(cpu)
                row.wall.append(wall)
                if out is not None:
                    row.solver.append(integration_time(out))
            print(row.line(), flush=True)
            ratios = [c / p for c, p in zip(row.cpu, row.peer)]
            solver = (f"; integrating {min(row.solver) * 1e3:.1f} ms of it"
                      if row.solver else "")
            _figures.figure(
                f"{name}: CPU of the whole process{solver}", min(row.cpu),
                "python -c 'import numpy, numba'", min(row.peer),
                ratio_meaning="pounding / peer (CPU)",
                goal=None if goal is None else f"<= {goal:g}x",
                spread=(f"best of {args.repeat}; CPU {min(row.cpu):.2f}-{max(row.cpu):.2f} s, "
                        f"wall best {min(row.wall):.2f} s; paired ratios "
                        f"{min(ratios):.2f}-{max(ratios):.2f}x"),
                unit_note="CPU seconds (user + system)")
        if args.cold:
            cache = Path(tempfile.mkdtemp(prefix="numba-cache-"))
            row = Row("pounding demo, empty numba cache (first run)")
            row.peer.append(measure(PEER, work, env)[0])
            cpu, wall = measure([POUNDING, "demo", "--out", str(work / "cold")], work,
                                child_env(NUMBA_CACHE_DIR=str(cache)))
            row.cpu.append(cpu)
            row.wall.append(wall)
            row.solver.append(integration_time(work / "cold"))
            print(row.line() + f"goal ≤ 20 s of CPU: {'met' if cpu <= 20.0 else 'MISSED'}")
            _figures.figure("pounding demo, empty numba cache (first run): CPU", cpu,
                            "python -c 'import numpy, numba'", row.peer[0],
                            ratio_meaning="pounding / peer (CPU)", met=cpu <= 20.0,
                            goal="<= 20 s of CPU", unit_note="CPU seconds (user + system)")
            shutil.rmtree(cache, ignore_errors=True)
        if args.phases:
            print(f"\nwhere the CPU of a warm run of {SEED.name} goes (one process, "
                  "phase by phase):")
            phases = subprocess.run([sys.executable, "-c", PHASES, str(SEED)], cwd=work,
                                    env=env, check=True, capture_output=True, text=True)
            print(phases.stdout, end="", flush=True)
            for line in phases.stdout.splitlines():
                if line.strip():
                    _figures.note(f"phase of a warm run, CPU: {line.strip()}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"\n{load()} (after)")
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

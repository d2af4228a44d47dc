"""Whole-process wall time of the commands a user types first (not a test: a measurement).

Each command runs as its own process, as a user runs it, ``--repeat`` times (default 5),
and the table gives the best and the spread (min–max) of the wall time, beside two peers
measured in the same script:

* the integration alone, as the run reports it (``summary.json``: ``solver.wall_time_s``),
  so the rest is start-up, loading the compiled kernel, writing files and figures;
* ``python -c "import numpy, numba"``: what any numba program pays before it does anything.

Goals (issue 14): a warm ``pounding run`` of the two-SDOF example ≤ 1 s with figures off and
≤ 2 s with figures; a warm ``pounding demo`` ≤ 3 s; the first run on a fresh machine (empty
numba cache) ≤ 30 s. ``--cold`` also measures that first run: the demo with numba's cache
pointed at an empty folder (``NUMBA_CACHE_DIR``), so everything is compiled once.

Run from the repository root::

    python benchmarks/bench_startup.py             # warm commands, 5 repeats
    python benchmarks/bench_startup.py --cold      # and the first (compiling) run

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
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
BIN = Path(sys.executable).parent
POUNDING = str(BIN / "pounding")


def wall(cmd: list[str], cwd: Path, env: dict[str, str] | None = None) -> float:
    """Seconds from start to exit of one process (its output discarded)."""
    t = time.perf_counter()
    subprocess.run(cmd, cwd=cwd, env=env, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    return time.perf_counter() - t


def integration_time(out: Path) -> float:
    return float(json.loads((out / "summary.json").read_text())["solver"]["wall_time_s"])


def row(name: str, times: list[float], goal: str = "", solver: list[float] | None = None
        ) -> None:
    best = min(times)
    spread = f"{min(times):.2f}–{max(times):.2f}"
    extra = f"{min(solver) * 1e3:8.1f} ms" if solver else " " * 11
    print(f"{name:46s} {best:7.2f} s  {spread:>11s}  {extra}  {goal}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=5, help="runs of each command (5)")
    ap.add_argument("--cold", action="store_true",
                    help="also time the first run with an empty numba cache")
    args = ap.parse_args(argv)

    work = Path(tempfile.mkdtemp(prefix="bench-startup-"))
    try:
        # warm every cache once (the kernel, the figures' fonts)
        subprocess.run([POUNDING, "run", str(SEED), "--out", str(work / "warm")], cwd=work,
                       check=True, stdout=subprocess.DEVNULL)
        subprocess.run([POUNDING, "demo", "--out", str(work / "demo")], cwd=work,
                       check=True, stdout=subprocess.DEVNULL)
        print(f"{'command (whole process)':46s} {'best':>9s}  {'spread':>11s}  "
              f"{'integrating':>11s}  goal")
        cases: list[tuple[str, list[str], str, Path | None]] = [
            ("python -c pass", [sys.executable, "-c", "pass"], "", None),
            ("python -c 'import numpy, numba' (peer)",
             [sys.executable, "-c", "import numpy, numba"], "", None),
            ("python -c 'import pounding'", [sys.executable, "-c", "import pounding"], "", None),
            ("pounding --version", [POUNDING, "--version"], "", None),
            ("pounding --help", [POUNDING, "--help"], "", None),
            ("pounding run seed_sdof_pair.toml --no-figures",
             [POUNDING, "run", str(SEED), "--out", str(work / "a"), "--overwrite",
              "--no-figures"], "≤ 1 s", work / "a"),
            ("pounding run seed_sdof_pair.toml",
             [POUNDING, "run", str(SEED), "--out", str(work / "b"), "--overwrite"],
             "≤ 2 s", work / "b"),
            ("pounding demo", [POUNDING, "demo", "--out", str(work / "demo")], "≤ 3 s",
             work / "demo"),
        ]
        for name, cmd, goal, out in cases:
            times, solver = [], []
            for _ in range(args.repeat):
                times.append(wall(cmd, work))
                if out is not None:
                    solver.append(integration_time(out))
            row(name, times, goal, solver or None)
        if args.cold:
            cache = Path(tempfile.mkdtemp(prefix="numba-cache-"))
            env = {**os.environ, "NUMBA_CACHE_DIR": str(cache)}
            t = wall([POUNDING, "demo", "--out", str(work / "cold")], work, env)
            row("pounding demo, empty numba cache (first run)", [t], "≤ 30 s",
                [integration_time(work / "cold")])
            shutil.rmtree(cache, ignore_errors=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"\n{os.cpu_count()} CPUs; python {sys.version.split()[0]}; "
          f"{time.strftime('%Y-%m-%d %H:%M')}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

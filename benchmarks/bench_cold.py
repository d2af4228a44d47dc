"""A cold start: the first ``pounding run`` on a machine whose numba cache is empty (not a
test: a measurement).

Each command runs as its own process, with numba's cache pointed at an empty folder
(``NUMBA_CACHE_DIR``), and the table gives its CPU (user + system of the child) and wall
time, beside a peer measured in the same run: ``python -c "import numpy, numba"``, what any
numba program pays before it does anything. Rows:

* ``pounding run examples/seed_sdof_pair.toml --no-figures`` on an empty cache: the solver's
  kernel compiled once (goal, issue 30: ≤ 20 s of CPU on the project's 2-core machine);
* the same run again on the cache the first one filled (the kernel loaded);
* the response-spectrum kernel alone on an empty cache (what the first ``pounding
  fragility`` or ``pounding spectrum`` compiles besides the solver).

The first run also counts the compiled specialisations (signatures of every numba function
of pounding the run compiled).

Run from the repository root::

    python benchmarks/bench_cold.py             # one round
    python benchmarks/bench_cold.py --repeat 2  # best of two
    python benchmarks/bench_cold.py --json cold.json  # also the figures as JSON (run_all)

The machine is shared: compare within one run, and read the load printed at the end.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _figures

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
GOAL_CPU_S = 20.0
"""The goal of issue 30 for the cold run [s of CPU]."""

RUN_AND_COUNT = """
import json, sys
from pounding.cli import main
rc = main(["run", sys.argv[1], "--no-figures", "--out", sys.argv[2]])
from numba.core.registry import CPUDispatcher
sigs = {}
for name, mod in list(sys.modules.items()):
    if name.startswith("pounding"):
        for key, obj in vars(mod).items():
            if isinstance(obj, CPUDispatcher) and obj.py_func.__module__ == name and obj.signatures:
                sigs[name + "." + key] = len(obj.signatures)
with open(sys.argv[3], "w") as f:
    json.dump(sigs, f)
raise SystemExit(rc)
"""

SPECTRUM = """
import numpy as np
from pounding.ground_motion import el_centro
from pounding.spectra import response_spectrum
response_spectrum(el_centro(), np.array([0.5, 1.0]), 0.05)
"""


def child(cmd: list[str], env: dict[str, str]) -> tuple[float, float]:
    """CPU (user + system) and wall seconds of one child process (its output discarded)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    subprocess.run(cmd, cwd=ROOT, env=env, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), wall


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=1, help="rounds (1); the best is shown")
    _figures.add_json_option(ap)
    args = ap.parse_args(argv)
    _figures.start("bench_cold", "Cold start: the first run on an empty numba cache")
    work = Path(tempfile.mkdtemp(prefix="bench-cold-"))
    rows: dict[str, list[tuple[float, float]]] = {}
    n_sigs: dict[str, int] = {}
    try:
        for r in range(args.repeat):
            cache = work / f"cache-{r}"
            spectra_cache = work / f"spectra-cache-{r}"
            cache.mkdir()
            spectra_cache.mkdir()
            env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "NUMBA_CACHE_DIR": str(cache)}
            rows.setdefault("python -c 'import numpy, numba' (peer)", []).append(
                child([sys.executable, "-c", "import numpy, numba"], env))
            sig_file = work / "signatures.json"
            rows.setdefault("pounding run seed_sdof_pair --no-figures, empty cache", []).append(
                child([sys.executable, "-c", RUN_AND_COUNT, str(SEED), str(work / f"a{r}"),
                       str(sig_file)], env))
            n_sigs = json.loads(sig_file.read_text())
            rows.setdefault("the same run again (cache filled)", []).append(
                child([sys.executable, "-m", "pounding", "run", str(SEED), "--no-figures",
                       "--out", str(work / f"b{r}")], env))
            rows.setdefault("response spectrum kernel, empty cache", []).append(
                child([sys.executable, "-c", SPECTRUM],
                      {**env, "NUMBA_CACHE_DIR": str(spectra_cache)}))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    peer_name = "python -c 'import numpy, numba' (peer)"
    peer = min(c for c, _ in rows[peer_name])
    print(f"{'command (own process)':56s} {'CPU':>8s} {'wall':>8s} {'CPU/peer':>9s}")
    for name, times in rows.items():
        cpu = min(c for c, _ in times)
        wall = min(w for _, w in times)
        print(f"{name:56s} {cpu:7.2f}s {wall:7.2f}s {cpu / peer:8.1f}×")
        if "(peer)" not in name:
            _figures.figure(f"{name}: CPU (wall {wall:.2f} s)", cpu,
                            "python -c 'import numpy, numba'", peer,
                            ratio_meaning="pounding / peer (CPU)",
                            goal=(f"<= {GOAL_CPU_S:.0f} s of CPU" if "run" in name
                                  and "empty" in name else None),
                            met=cpu <= GOAL_CPU_S if "run" in name and "empty" in name else None,
                            spread=f"best of {args.repeat}",
                            unit_note="CPU seconds (user + system)")
    several = [k for k, v in n_sigs.items() if v > 1]
    print(f"\ncompiled by the cold run: {sum(n_sigs.values())} signatures of "
          f"{len(n_sigs)} numba functions" + ("; more than one: " + ", ".join(several)
                                             if several else ""))
    print(f"goal (issue 30): the cold run ≤ {GOAL_CPU_S:.0f} s of CPU")
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    print(f"{os.cpu_count()} CPUs; python {sys.version.split()[0]}; "
          f"load average {load}; {time.strftime('%Y-%m-%d %H:%M')}")
    _figures.note(f"compiled by the cold run: {sum(n_sigs.values())} signatures of "
                  f"{len(n_sigs)} numba functions")
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""Memory between runs: a loop of ``simulate`` calls with pounding's allocator setting
(:mod:`pounding.allocator`) and with glibc left alone (``POUNDING_KEEP_FREED_MEMORY=0``).

Each setting runs in its own fresh process (the setting is per process), alternately,
``--rounds`` times; each process times ``--calls`` calls after a first one and counts their
minor page faults (``getrusage``). Printed: best and median call, the faults a call, and
the ratio left-alone / kept of the best calls, with the spread over the rounds and the load
average.

    python benchmarks/bench_memory.py [--model two_10_storey.toml] [--calls 20] [--rounds 3]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _figures

SRC = Path(__file__).resolve().parents[1] / "src"
CHILD = """
import json, resource, sys, time
from pounding.config import load_config
from pounding.example_files import example_path
from pounding.integrate import simulate
m, g, s = load_config(example_path(sys.argv[1])).build()
simulate(m, g, **s)
faults, times = [], []
for _ in range(int(sys.argv[2])):
    before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    t0 = time.perf_counter()
    simulate(m, g, **s)
    times.append(time.perf_counter() - t0)
    faults.append(resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before)
times.sort()
print(json.dumps({"best": times[0], "median": times[len(times) // 2],
                  "faults": sorted(faults)[len(faults) // 2]}))
"""


def _one(model: str, calls: int, keep: bool) -> dict[str, float]:
    env = {**os.environ, "PYTHONPATH": str(SRC), "POUNDING_KEEP_FREED_MEMORY": "1" if keep else "0"}
    out = subprocess.run([sys.executable, "-c", CHILD, model, str(calls)], env=env,
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--model", default="two_10_storey.toml", help="a bundled example")
    ap.add_argument("--calls", type=int, default=20)
    ap.add_argument("--rounds", type=int, default=3)
    _figures.add_json_option(ap)
    args = ap.parse_args(argv)
    _figures.start("bench_memory", "Memory between runs")
    load0 = os.getloadavg()[0]
    kept, alone = [], []
    for _ in range(args.rounds):
        kept.append(_one(args.model, args.calls, True))
        alone.append(_one(args.model, args.calls, False))
    ratios = [a["best"] / k["best"] for k, a in zip(kept, alone)]
    for name, rows in (("kept (pounding's setting)", kept), ("glibc left alone", alone)):
        best = [1e3 * r["best"] for r in rows]
        med = [1e3 * r["median"] for r in rows]
        print(f"{name:26s} best {min(best):7.2f} ms ({min(best):.2f}-{max(best):.2f}), "
              f"median {min(med):7.2f}-{max(med):.2f} ms, page faults a call "
              f"{min(r['faults'] for r in rows):.0f}-{max(r['faults'] for r in rows):.0f}")
    print(f"left alone / kept, best call: {min(ratios):.2f}-{max(ratios):.2f}x "
          f"({args.model}, {args.calls} calls x {args.rounds} rounds; load average "
          f"{load0:.1f} -> {os.getloadavg()[0]:.1f})")
    _figures.figure(f"{args.model}: best of {args.calls} simulate() calls, freed memory kept",
                    min(r["best"] for r in kept), "the same calls with glibc left alone",
                    min(r["best"] for r in alone), ratio_meaning="peer / pounding",
                    spread=f"{args.rounds} rounds, each setting its own process; ratio of "
                           f"the best calls {min(ratios):.2f}-{max(ratios):.2f}x")
    for name, rows in (("kept", kept), ("left alone", alone)):
        _figures.note(f"{args.model}, {name}: page faults a call "
                      f"{min(r['faults'] for r in rows):.0f}-{max(r['faults'] for r in rows):.0f}")
    _figures.write(args.json)


if __name__ == "__main__":
    main()

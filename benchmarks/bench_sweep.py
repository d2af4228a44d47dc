"""Benchmark of parameter sweeps on Dask (``pounding.studies.sweep``).

Three measurements, printed as a table:

1. **10,000 cases**: the seed SDOF pair (``examples/seed_sdof_pair.toml``) under El Centro
   1940 trimmed to 20 s, grid gap × e × scale = 25 × 20 × 20, on a local cluster of
   ``--workers`` (2) processes. End-to-end wall time — sweep file parsing, cluster start,
   warm-up, all cases, every Parquet part, the consolidated table — and cases per second.
2. **Scaling**: the same kind of sweep, ``--scaling-cases`` (2000) cases, on 1 and on 2
   workers; efficiency = rate(2) / (2 × rate(1)), rates over the running phase.
3. **Overhead of a 1-case sweep** against a plain ``simulate`` call of the same case
   (in-process sweep, and on a local cluster of one worker).

Run from the repository root::

    python benchmarks/bench_sweep.py                 # everything
    python benchmarks/bench_sweep.py --only big      # just the 10,000 cases
    python benchmarks/bench_sweep.py --cases 2000    # a smaller "big" sweep

The machine is shared and timings are noisy: repeat (``--repeat``) and take the best.
"""

from __future__ import annotations

import argparse
import shutil
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
BASE = ROOT / "examples" / "seed_sdof_pair.toml"


def grid(n_gap: int, n_e: int, n_scale: int) -> dict:
    return {
        "contact.gap": [float(x) for x in np.round(np.linspace(0.0, 0.06, n_gap), 6)],
        "contact.e": [float(x) for x in np.round(np.linspace(0.4, 0.9, n_e), 6)],
        "record.scale": [float(x) for x in np.round(np.linspace(0.5, 2.0, n_scale), 6)],
    }


def sweep_data(g: dict, out: Path) -> dict:
    return {"name": "bench", "base": str(BASE), "out": str(out), "grid": g,
            "histories": False}


def shape_for(n: int) -> tuple[int, int, int]:
    """A gap × e × scale grid of about n cases (25 × 20 × 20 for 10,000)."""
    if n == 10_000:
        return 25, 20, 20
    k = max(1, round((n / 20 / 20)))
    return k, 20, 20 if k * 400 == n else max(1, round(n / (k * 20)))


def run_once(n_cases: int, workers: int | None, scheduler: str | None, tmp: Path,
             trim: float = 20.0) -> dict:
    from pounding.studies.sweep import parse_sweep, run_sweep

    t0 = time.perf_counter()
    ng, ne, ns = shape_for(n_cases)
    g = grid(ng, ne, ns)
    g["record.duration"] = [trim]
    out = tmp / f"bench-{n_cases}-{workers}-{scheduler}"
    shutil.rmtree(out, ignore_errors=True)
    sweep = parse_sweep(sweep_data(g, out), base_dir=tmp)
    res = run_sweep(sweep, scheduler=scheduler, n_workers=workers, overwrite=True)
    wall = time.perf_counter() - t0
    assert res.n_errors == 0, res
    return {"cases": res.n_cases, "workers": res.n_workers, "batch": res.batch_size,
            "wall": wall, "run": res.run_time, "rate_run": res.rate,
            "rate_wall": res.n_cases / wall}


def plain_case(trim: float = 20.0) -> float:
    from pounding.config import load_config, parse_config
    from pounding.integrate import simulate

    t0 = time.perf_counter()
    data = load_config(BASE).to_dict()
    data["record"]["duration"] = trim
    model, gm, kw = parse_config(data).build()
    simulate(model, gm, **kw).summary()
    return time.perf_counter() - t0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", type=int, default=10_000)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--scaling-cases", type=int, default=2000)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--only", choices=("big", "scaling", "overhead"))
    args = ap.parse_args()
    from pounding.studies.sweep import warm_up

    warm_up()
    tmp = Path(tempfile.mkdtemp(prefix="bench-sweep-"))
    rows = []
    try:
        if args.only in (None, "big"):
            for _ in range(args.repeat):
                r = run_once(args.cases, args.workers, None, tmp)
                rows.append((f"{r['cases']} cases, {r['workers']} workers "
                             f"(batch {r['batch']})", r))
        if args.only in (None, "scaling"):
            best = {}
            for w in (1, 2):
                rs = [run_once(args.scaling_cases, w, None, tmp) for _ in range(args.repeat)]
                best[w] = max(rs, key=lambda x: x["rate_run"])
                rows.append((f"scaling: {best[w]['cases']} cases, {w} worker(s)", best[w]))
            eff = best[2]["rate_run"] / (2 * best[1]["rate_run"])
            print(f"\nscaling efficiency 1 -> 2 workers (running phase): {eff:.0%}")
        if args.only in (None, "overhead"):
            plain = min(plain_case() for _ in range(max(3, args.repeat)))
            sync = min(run_once(1, None, "synchronous", tmp)["wall"]
                       for _ in range(max(3, args.repeat)))
            local = min(run_once(1, 1, None, tmp)["wall"] for _ in range(args.repeat))
            print(f"\n1 case: plain load+build+simulate+summary {plain * 1e3:.1f} ms; "
                  f"1-case sweep in-process {sync * 1e3:.1f} ms "
                  f"(overhead {(sync - plain) * 1e3:+.1f} ms); "
                  f"on a fresh 1-worker local cluster {local:.2f} s")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if rows:
        print(f"\n{'sweep':<44} {'wall [s]':>9} {'running [s]':>12} {'cases/s (wall)':>15} "
              f"{'cases/s (running)':>18}")
        for label, r in rows:
            print(f"{label:<44} {r['wall']:>9.2f} {r['run']:>12.2f} {r['rate_wall']:>15.1f} "
                  f"{r['rate_run']:>18.1f}")


if __name__ == "__main__":
    main()

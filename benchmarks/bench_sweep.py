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
4. **The sweep against the kernel** (``--only ratio``), side by side in one run, each
   repeat measuring all three in turn:

   * the kernel's own rate: the same ``--cases`` cases (every ``--kernel-every``-th),
     each built and simulated as a sweep case is, in 1 and in 2 processes at once (with
     the workers' memory settings); cases per second of compiled kernel alone
     (``Result.stats.wall_time``, summed per process, rates added over the processes),
     and of the whole case in that process (build, simulate, row). On 2 processes it is
     measured just before and just after the sweep, and the mean taken;
   * the sweep end to end on ``--workers`` (2) workers: cases / wall time (cluster start,
     warm-up, all cases, consolidation), and over the running phase;
   * the first repeat's sweep starts the server its workers are forked from
     (``pounding.studies.sweep.cluster._start_worker_server``: the workers' imports and
     the kernel's load, once); the later repeats reuse it, as a later sweep of the same
     process does. The line of each repeat shows each;
   * the ratio end-to-end rate / kernel rate on 2 processes, and the spread of each
     number over the repeats; and, since CPU time is what other jobs on a shared machine
     cannot inflate, the kernel's share of all the CPU time the sweep used (its client,
     scheduler and workers; the kernel's CPU per case from the runs on 2 processes).

Run from the repository root::

    python benchmarks/bench_sweep.py                 # everything
    python benchmarks/bench_sweep.py --only big      # just the 10,000 cases
    python benchmarks/bench_sweep.py --cases 2000    # a smaller "big" sweep
    python benchmarks/bench_sweep.py --only ratio --repeat 3 --kernel-every 3

The machine is shared and timings are noisy: repeat (``--repeat``) and take the best, or
(``ratio``) read the spread.
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

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _figures

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


def bench_sweep(n_cases: int, out: Path, trim: float = 20.0):
    """The benchmark's sweep of about ``n_cases`` cases (El Centro trimmed to ``trim`` s)."""
    from pounding.studies.sweep import parse_sweep

    g = grid(*shape_for(n_cases))
    g["record.duration"] = [trim]
    return parse_sweep(sweep_data(g, out), base_dir=out.parent)


def run_once(n_cases: int, workers: int | None, scheduler: str | None, tmp: Path,
             trim: float = 20.0) -> dict:
    from pounding.studies.sweep import run_sweep

    t0 = time.perf_counter()
    cpu0 = cpu_seconds()
    out = tmp / f"bench-{n_cases}-{workers}-{scheduler}"
    shutil.rmtree(out, ignore_errors=True)
    sweep = bench_sweep(n_cases, out, trim)
    res = run_sweep(sweep, scheduler=scheduler, n_workers=workers, overwrite=True)
    wall = time.perf_counter() - t0
    assert res.n_errors == 0, res
    return {"cases": res.n_cases, "workers": res.n_workers, "batch": res.batch_size,
            "wall": wall, "run": res.run_time, "rate_run": res.rate,
            "rate_wall": res.n_cases / wall, "cpu": cpu_seconds() - cpu0}


def cpu_seconds() -> float:
    """CPU seconds (user + system) of this process and of its children that have ended,
    and of the process the local cluster's workers are forked from with its children
    that have ended (the workers, once the cluster is closed)."""
    return sum(getattr(resource.getrusage(who), f) for who in
               (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)
               for f in ("ru_utime", "ru_stime")) + worker_server_cpu()


def worker_server_cpu() -> float:
    """CPU seconds of the server the sweep's workers are forked from
    (``pounding.studies.sweep.cluster._start_worker_server``) and of its children that
    have ended, read from ``/proc``; 0 if there is none (yet)."""
    from pounding.studies.sweep.cluster import worker_server_pid

    pid = worker_server_pid()
    if pid is None:
        return 0.0
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return 0.0
    # after the name: state ppid … utime stime cutime cstime (fields 14–17 of proc(5))
    return sum(int(x) for x in fields[11:15]) / os.sysconf("SC_CLK_TCK")


def plain_case(trim: float = 20.0) -> float:
    from pounding.config import load_config, parse_config
    from pounding.integrate import simulate

    t0 = time.perf_counter()
    data = load_config(BASE).to_dict()
    data["record"]["duration"] = trim
    model, gm, kw = parse_config(data).build()
    simulate(model, gm, **kw).summary()
    return time.perf_counter() - t0


def kernel_part(n_cases: int, part: int, parts: int, every: int, trim: float = 20.0) -> dict:
    """In this process, cases ``part``, ``part + parts``, … of every ``every``-th case of
    the sweep, each built, simulated and reduced to its row as a sweep case is: the cases
    run, seconds in the compiled kernel (``Result.stats.wall_time``) and in all."""
    import pounding.integrate as integrate
    from pounding.studies.sweep import warm_up
    from pounding.studies.sweep.execute import case_result
    from pounding.studies.sweep.measures import result_row

    warm_up()
    sweep = bench_sweep(n_cases, Path(tempfile.gettempdir()) / "bench-sweep-kernel", trim)
    cases = sweep.cases[::every][part::parts]
    compiled = integrate.integrate_chunk
    kernel_cpu = [0.0]

    def timed(*args: object) -> None:  # the kernel's CPU time (not stolen by other jobs)
        c0 = time.thread_time()
        compiled(*args)
        kernel_cpu[0] += time.thread_time() - c0

    integrate.integrate_chunk = timed
    kernel = total = 0.0
    for c in cases:
        t0 = time.perf_counter()
        result = case_result(sweep.base, sweep.base_dir, sweep.params, c.values)
        result_row(result)
        total += time.perf_counter() - t0
        kernel += result.stats.wall_time
    return {"n": len(cases), "kernel": kernel, "total": total, "kernel_cpu": kernel_cpu[0]}


def kernel_rate(n_cases: int, processes: int, every: int) -> dict:
    """:func:`kernel_part` in ``processes`` processes at once, each with the local
    cluster's worker memory settings: cases per second of kernel (``kernel_rate``) and of
    whole cases (``case_rate``), each process's rate added up."""
    from pounding.studies.sweep.cluster import WORKER_MALLOC_ENV

    env = {**os.environ, **{k: str(v) for k, v in WORKER_MALLOC_ENV.items()}}
    procs = [subprocess.Popen([sys.executable, __file__, "--kernel-part", f"{i}/{processes}",
                               "--cases", str(n_cases), "--kernel-every", str(every)],
                              stdout=subprocess.PIPE, env=env, text=True)
             for i in range(processes)]
    parts = []
    for p in procs:
        out, _ = p.communicate()
        if p.returncode:
            raise RuntimeError(f"kernel part failed (exit {p.returncode})")
        parts.append(json.loads(out.splitlines()[-1]))
    return {"n": sum(x["n"] for x in parts),
            "kernel_rate": sum(x["n"] / x["kernel"] for x in parts),
            "case_rate": sum(x["n"] / x["total"] for x in parts),
            "kernel_cpu": sum(x["kernel_cpu"] for x in parts) / sum(x["n"] for x in parts)}


def spread(values: list[float], fmt: str = ".0f") -> str:
    """``min–max`` of the values (one value alone)."""
    lo, hi = min(values), max(values)
    return f"{lo:{fmt}}" if len(values) == 1 else f"{lo:{fmt}}–{hi:{fmt}}"


def ratio_section(n_cases: int, workers: int, every: int, repeat: int, tmp: Path) -> None:
    """The sweep end to end against the kernel alone, side by side, ``repeat`` times."""
    runs = []
    for i in range(repeat):
        k1 = kernel_rate(n_cases, 1, every)
        before = kernel_rate(n_cases, 2, every)
        sw = run_once(n_cases, workers, None, tmp)
        after = kernel_rate(n_cases, 2, every)
        # the kernel on 2 processes just before and just after the sweep: other jobs on a
        # shared machine come and go, and the mean of the two brackets the sweep in time
        k2 = {key: (before[key] + after[key]) / 2
              for key in ("kernel_rate", "case_rate", "kernel_cpu")}
        k2["n"] = before["n"]
        runs.append((k1, k2, sw))
        _figures.figure(f"sweep of {sw['cases']} two-SDOF cases on {sw['workers']} workers, "
                        f"end to end (repeat {i + 1}): time a case", 1.0 / sw["rate_wall"],
                        "the compiled kernel alone on 2 processes, just before and after",
                        1.0 / k2["kernel_rate"], ratio_meaning="peer / pounding",
                        goal=">= 0.7x", spread=f"sweep {sw['wall']:.2f} s wall",
                        unit_note="seconds a case of wall time; the ratio is the sweep's "
                                  "rate over the kernel's")
        print(f"repeat {i + 1}: kernel {k1['kernel_rate']:.0f} / {k2['kernel_rate']:.0f} cases/s "
              f"(1 / 2 processes; 2: {before['kernel_rate']:.0f} before the sweep, "
              f"{after['kernel_rate']:.0f} after; {k2['n']} cases), whole cases in-process "
              f"{k1['case_rate']:.0f} / {k2['case_rate']:.0f}; sweep of {sw['cases']} on "
              f"{sw['workers']} workers {sw['wall']:.2f} s ({sw['wall'] - sw['run']:.2f} s "
              f"outside the running phase: parsing, cluster start and warm-up, close, "
              f"table): {sw['rate_wall']:.0f} cases/s "
              f"end to end, {sw['rate_run']:.0f} running; end to end / kernel (2 processes) "
              f"{sw['rate_wall'] / k2['kernel_rate']:.0%}", flush=True)
    rows = [
        ("kernel alone, 1 process", [k1["kernel_rate"] for k1, _, _ in runs]),
        ("kernel alone, 2 processes", [k2["kernel_rate"] for _, k2, _ in runs]),
        ("whole cases in-process, 1 process", [k1["case_rate"] for k1, _, _ in runs]),
        ("whole cases in-process, 2 processes", [k2["case_rate"] for _, k2, _ in runs]),
        (f"sweep end to end, {workers} workers", [sw["rate_wall"] for _, _, sw in runs]),
        (f"sweep while running, {workers} workers", [sw["rate_run"] for _, _, sw in runs]),
    ]
    print(f"\n{'cases/s over ' + str(repeat) + ' repeat(s)':<40} {'min–max':>12}")
    for label, vals in rows:
        print(f"{label:<40} {spread(vals):>12}")
    e2e = [sw["rate_wall"] / k2["kernel_rate"] for _, k2, sw in runs]
    run = [sw["rate_run"] / k2["kernel_rate"] for _, k2, sw in runs]
    print(f"{'end to end / kernel (2 processes)':<40} {spread([100 * x for x in e2e]):>11}%")
    print(f"{'running / kernel (2 processes)':<40} {spread([100 * x for x in run]):>11}%")
    # other jobs on a shared machine slow one measurement and not the next: the best of
    # each over the repeats is the nearest to an idle machine
    best_k2 = max(k2["kernel_rate"] for _, k2, _ in runs)
    best_sw = max(sw["rate_wall"] for _, _, sw in runs)
    print(f"{'best end to end / best kernel (2 proc.)':<40} {100 * best_sw / best_k2:>11.0f}%")
    print(f"sweep wall time [s]: {spread([sw['wall'] for _, _, sw in runs], '.2f')}")
    # CPU time is what other jobs cannot inflate: the kernel's share of all the CPU the
    # sweep used (client, scheduler and workers), the kernel's CPU per case taken from the
    # runs on 2 processes
    share = [k2["kernel_cpu"] * sw["cases"] / sw["cpu"] for _, k2, sw in runs]
    print(f"sweep CPU per case (all processes) [ms]: "
          f"{spread([1e3 * sw['cpu'] / sw['cases'] for _, _, sw in runs], '.2f')}; kernel CPU "
          f"per case [ms]: {spread([1e3 * k2['kernel_cpu'] for _, k2, _ in runs], '.2f')}; "
          f"kernel share of the sweep's CPU: {spread([100 * x for x in share])}%")
    _figures.note(f"kernel share of the sweep's CPU: {spread([100 * x for x in share])} %; "
                  f"sweep CPU a case (all processes) "
                  f"{spread([1e3 * sw['cpu'] / sw['cases'] for _, _, sw in runs], '.2f')} ms")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", type=int, default=10_000)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--scaling-cases", type=int, default=2000)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--only", choices=("big", "scaling", "overhead", "ratio"))
    ap.add_argument("--kernel-every", type=int, default=1,
                    help="ratio: time the kernel alone on every n-th case only")
    ap.add_argument("--kernel-part", help=argparse.SUPPRESS)  # "i/k": one process of ratio
    _figures.add_json_option(ap)
    args = ap.parse_args()
    _figures.start("bench_sweep", "Parameter sweeps")
    if args.kernel_part:
        i, k = map(int, args.kernel_part.split("/"))
        print(json.dumps(kernel_part(args.cases, i, k, args.kernel_every)))
        return
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
        if args.only in (None, "ratio"):
            print()
            ratio_section(args.cases, args.workers, args.kernel_every, args.repeat, tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if rows:
        print(f"\n{'sweep':<44} {'wall [s]':>9} {'running [s]':>12} {'cases/s (wall)':>15} "
              f"{'cases/s (running)':>18}")
        for label, r in rows:
            print(f"{label:<44} {r['wall']:>9.2f} {r['run']:>12.2f} {r['rate_wall']:>15.1f} "
                  f"{r['rate_run']:>18.1f}")
            _figures.note(f"{label}: {r['wall']:.2f} s wall, {r['rate_wall']:.1f} cases/s "
                          f"end to end, {r['rate_run']:.1f} while running")
    _figures.write(args.json)


if __name__ == "__main__":
    main()

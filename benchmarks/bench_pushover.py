"""Pushover of an LA9-type frame: pounding (exact, event to event) against OpenSeesPy's
displacement-controlled pushover of the same model, and the memory of a 40-storey pair.

Run from the repository root, in a Python holding pounding's requirements and
``openseespy`` (see ``benchmarks/README.md``)::

    PYTHONPATH=src:benchmarks python benchmarks/bench_pushover.py            # everything
    PYTHONPATH=src:benchmarks python benchmarks/bench_pushover.py --sections la9 --repeat 5
    PYTHONPATH=src:benchmarks python benchmarks/bench_pushover.py --steps 20,10,5

Sections:

la9     The LA9-type frame of ``frames_la9.la9_frame`` (IMK beams, bilinear columns, leaning
        column, P-Delta), first-mode load pattern, gravity first, pushed to 5 % roof drift.
        pounding: ``pushover(frame, target, pattern="first-mode")`` — gravity, modes, the
        event-to-event push, the result. OpenSees (``opensees_frame_models.py``): gravity in 10
        load steps, then ``DisplacementControl`` of the roof in steps of target/N, Newton
        (at most ``--newton-iterations``) with fallbacks, the roof displacement and base
        shear read after every step; it is given pounding's first-mode load shape (its own first mode is printed beside it,
        untimed), so its time has no eigen analysis in it and pounding's has. Whole wall
        time of each analysis; model building excluded (timed and printed apart). Runs
        alternate: pounding, then OpenSees at each step, ``--repeat`` times, after one
        untimed warm-up of each. OpenSees' error: the largest difference of its base shear
        from pounding's curve (exact, piecewise linear between events) at OpenSees' own
        roof displacements, relative to the peak base shear.
memory  pounding alone: a pair of regular 40-storey, 8-bay frames (``tall_pair``), one
        first-mode pushover each to 5 % roof drift, in a fresh subprocess: its peak resident
        memory (``resource.getrusage(RUSAGE_SELF).ru_maxrss``) after the imports, after
        building the pair and at the end, and the time of each pushover.

numpy's OpenBLAS runs on one thread unless ``--blas-threads`` says otherwise: on a shared
2-core machine its threads spin against the other jobs (a 400×400 Cholesky factorisation,
2.7 ms on one thread, took 0.78 s with the default threads at load average 3.8 on
2026-11-27), and OpenSees 3.7.1.2 solves with its own band solver on one thread.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import _figures

SECTIONS = ("la9", "memory")
DEFAULT_STEPS_MM = "20,10,5,2.5,1.25"
ROOF_DRIFT = 0.05
ROUND_OFF = 1e-9
"""An OpenSees error (relative to the peak base shear) this small is round-off: agreement."""


def _parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sections", default=",".join(SECTIONS),
                    help=f"comma-separated, of {', '.join(SECTIONS)} (default all)")
    ap.add_argument("--repeat", type=int, default=3,
                    help="timed runs of each tool and step, alternating (default 3, ≥ 1)")
    ap.add_argument("--steps", default=DEFAULT_STEPS_MM,
                    help="OpenSees' displacement steps [mm], comma-separated (each rounded "
                         f"to target/N; default {DEFAULT_STEPS_MM})")
    ap.add_argument("--hinges", default="imk-bilinear",
                    help="LA9 hinge model: imk-bilinear, bilinear or elastic-plastic")
    ap.add_argument("--newton-iterations", type=int, default=25,
                    help="OpenSees: Newton's iteration limit before the fallbacks (default 25)")
    ap.add_argument("--blas-threads", default="1",
                    help="OPENBLAS_NUM_THREADS for numpy (default 1; 'default': as set)")
    ap.add_argument("--tall-child", action="store_true", help=argparse.SUPPRESS)
    _figures.add_json_option(ap)
    return ap


def spread(values: list[float], scale: float = 1.0, fmt: str = ".3f") -> str:
    """``best (median–worst) xN`` of timing repeats."""
    import statistics

    return (f"{min(values) * scale:{fmt}} ({statistics.median(values) * scale:{fmt}}–"
            f"{max(values) * scale:{fmt}}) x{len(values)}")


# ===================================================================== the 40-storey pair
def tall_frame(name: str, stiffness: float = 1.0) -> Any:
    """A regular 40-storey, 8-bay steel-like moment frame (pounding's ``regular_frame``):
    bays 6 m, storeys 4.5 m then 3.6 m (144.9 m), column EI 3.0e9 → 0.6e9 N·m² and beam EI
    1.6e9 → 0.5e9 N·m² linearly up the height (× ``stiffness``), floor mass 6e5 kg, 20 %
    of each floor's weight on its beams and 80 % on a leaning column, P-Delta; hinges as
    the LA9 model's (``frames_la9``: springs n = 10 times the element, EI × 11/10): IMK
    bilinear beams (M_y = 4.8e-3 EI, θ_p 0.017, θ_pc 0.10, θ_u 0.2, Λ 0.8) and bilinear
    columns (M_y = 9.6e-3 EI, member hardening 3 %) — the M_p/EI ratios of the LA9 W36x160
    beams and W14x500 columns."""
    import numpy as np

    from pounding.hysteresis.hinges import BilinearHinge
    from pounding.hysteresis.imk import IMKBilinear
    from pounding.structure.frame import regular_frame

    ns, nb, bay, n = 40, 8, 6.0, 10.0
    heights = [4.5] + [3.6] * (ns - 1)
    z = np.linspace(0.0, 1.0, ns)
    col_ei = stiffness * (3.0e9 * (1.0 - z) + 0.6e9 * z)
    beam_ei = stiffness * (1.6e9 * (1.0 - z) + 0.5e9 * z)
    mass, g = 6.0e5, 9.81
    hardening = 0.03 / (1.0 + n * (1.0 - 0.03))
    columns = [BilinearHinge(k0=(n + 1) * 6 * col_ei[s] / heights[s], m_y=9.6e-3 * col_ei[s],
                             hardening=hardening) for s in range(ns)]
    beams = [IMKBilinear(k0=(n + 1) * 6 * beam_ei[s] / bay, m_y=4.8e-3 * beam_ei[s],
                         theta_p=0.017, theta_pc=0.10, theta_u=0.2, mc_my=1.11, kappa=0.4,
                         lambda_=0.8) for s in range(ns)]
    return regular_frame([bay] * nb, heights, column_EI=col_ei * (n + 1) / n,
                         beam_EI=beam_ei * (n + 1) / n, column_EA=2e10, beam_EA=1e10,
                         column_hinge=columns, beam_hinge=beams, floor_mass=mass,
                         beam_load=0.2 * mass * g / (nb * bay), leaning_load=0.8 * mass * g,
                         geometry="p-delta", name=name)


def tall_child() -> int:
    """The memory section's subprocess: prints one JSON line."""
    import resource

    def rss_mb() -> float:
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # kB on Linux

    import numpy as np

    from pounding.structure.frame_analysis import pushover

    out: dict[str, Any] = {"rss_imports_mb": rss_mb()}
    t = time.perf_counter()
    pair = [tall_frame("left"), tall_frame("right", stiffness=0.7)]
    out["build_s"] = time.perf_counter() - t
    out["rss_built_mb"] = rss_mb()
    f = pair[0]
    out["size"] = f.describe()
    out["dofs"] = 3 * f.n_nodes + len(f.hinges)
    results = []
    for frame in pair:
        height = float(frame.levels[-1] - frame.base)
        t = time.perf_counter()
        r = pushover(frame, ROOF_DRIFT * height, pattern="first-mode")
        dt = time.perf_counter() - t
        i = int(np.argmax(r.base_shear))
        results.append(r)
        out.setdefault("frames", []).append({
            "name": frame.name, "time_s": dt, "events": int(r.base_shear.size),
            "peak_kN": r.peak_base_shear / 1e3, "roof_at_peak_m": float(r.roof_displacement[i]),
            "height_m": height, "stopped": r.stopped, "rss_mb": rss_mb()})
    out["rss_end_mb"] = rss_mb()
    print(json.dumps(out))
    return 0


def memory_section() -> None:
    print("\n== memory: a pair of 40-storey, 8-bay frames, one pushover each (subprocess) ==")
    import textwrap

    print(textwrap.fill(" ".join((tall_frame.__doc__ or "").split()), width=92,
                        initial_indent="  ", subsequent_indent="  "))
    t = time.perf_counter()
    proc = subprocess.run([sys.executable, str(Path(__file__).resolve()), "--tall-child"],
                          capture_output=True, text=True, env=os.environ.copy(), check=False)
    wall = time.perf_counter() - t
    if proc.returncode != 0:
        print(f"  the subprocess failed ({proc.returncode}): {proc.stderr.strip()[-2000:]}")
        return
    d = json.loads(proc.stdout.strip().splitlines()[-1])
    print(f"  {d['size']}; {d['dofs']} DOFs a frame (3 per node + 1 per hinge)")
    print(f"  peak RSS [MB]: after imports {d['rss_imports_mb']:.0f}, after building the pair "
          f"{d['rss_built_mb']:.0f} ({d['build_s']:.2f} s)")
    for fr in d["frames"]:
        print(f"  {fr['name']:>5}: pushover {fr['time_s']:.1f} s, {fr['events']} events "
              f"({1e3 * fr['time_s'] / fr['events']:.0f} ms/event), peak {fr['peak_kN']:.0f} kN "
              f"at roof {fr['roof_at_peak_m']:.3f} m ({100 * fr['roof_at_peak_m'] / fr['height_m']:.2f} %), "
              f"stopped: {fr['stopped']}; peak RSS after it {fr['rss_mb']:.0f} MB")
    print(f"  peak RSS of the process: {d['rss_end_mb']:.0f} MB "
          f"(the pair and both results alive); subprocess wall {wall:.1f} s")


# ===================================================================== LA9 pushover
@dataclass
class StepRuns:
    """OpenSees at one step size."""

    n: int
    step: float
    times: list[float] = field(default_factory=list)
    error: float = float("nan")
    where: float = float("nan")
    rescued: int = 0
    complete: bool = True
    points: int = 0


def la9_section(args: argparse.Namespace, steps_mm: list[float]) -> None:
    import numpy as np
    import opensees_frame_models as osf
    import openseespy.opensees as ops
    from frames_la9 import la9_frame, total_height

    from pounding.structure.frame_analysis import frame_modes, gravity, pushover

    log = Path(os.environ.get("TMPDIR", "/tmp")) / f"bench_pushover_opensees_{os.getpid()}.log"
    ops.logFile(str(log), "-noEcho")  # OpenSees' failed-step warnings go there, not here

    t = time.perf_counter()
    frame = la9_frame(hinges=args.hinges)
    build_pounding = time.perf_counter() - t
    height = total_height()
    target = ROOF_DRIFT * height
    print(f"\n== la9: {frame.describe()} ==")
    print(f"  hinges {args.hinges}; height {height:.2f} m; first-mode pattern; target "
          f"{target:.4f} m ({100 * ROOF_DRIFT:.0f} % roof drift); building the Frame "
          f"{1e3 * build_pounding:.1f} ms (not timed below)")
    state = gravity(frame)
    periods = frame_modes(frame, state)[0]
    print(f"  periods under gravity (P-Delta): T1..T3 = "
          f"{', '.join(f'{p:.3f}' for p in periods[:3])} s")

    runs = [StepRuns(n, target / n) for n in
            sorted({max(1, round(target / (s / 1e3))) for s in steps_mm})]

    exact = pushover(frame, target, pattern="first-mode")  # warm-up (untimed)
    built = osf.build(ops, frame)
    osf.gravity(ops)
    their_shape = osf.first_mode_shape(ops, built)
    mass = frame.floor_masses
    their_load = mass * their_shape / np.sum(mass * their_shape)
    print(f"  OpenSees' own first-mode load shape against pounding's: largest difference "
          f"{np.max(np.abs(their_load - exact.load_shape)) / np.max(exact.load_shape):.1e} "
          f"(relative); OpenSees is given pounding's")
    t = time.perf_counter()
    built = osf.build(ops, frame)
    build_os = time.perf_counter() - t
    osf.gravity(ops)
    osf.pushover(ops, built, exact.load_shape, target, target / runs[0].n,
                 newton_iterations=args.newton_iterations)  # warm-up
    print(f"  building the OpenSees model {1e3 * build_os:.0f} ms (not timed below); "
          f"{args.repeat} timed runs each, alternating")

    ours: list[float] = []
    for _ in range(args.repeat):
        t = time.perf_counter()
        exact = pushover(frame, target, pattern="first-mode")
        ours.append(time.perf_counter() - t)
        for run in runs:
            built = osf.build(ops, frame)
            t = time.perf_counter()
            osf.gravity(ops)
            curve = osf.pushover(ops, built, exact.load_shape, target, run.step,
                                 newton_iterations=args.newton_iterations)
            run.times.append(time.perf_counter() - t)
            at = np.interp(curve.roof, exact.roof_displacement, exact.base_shear)
            err = np.abs(curve.base_shear - at) / exact.peak_base_shear
            k = int(np.argmax(err))
            run.error, run.where = float(err[k]), float(curve.roof[k])
            run.rescued, run.complete, run.points = curve.rescued, curve.complete, curve.roof.size
    ops.wipe()

    peak = int(np.argmax(exact.base_shear))
    weight = float(np.sum(frame.floor_masses)) * 9.81
    print(f"  pounding: {exact.base_shear.size} points (events), stopped: {exact.stopped}; "
          f"peak base shear {exact.peak_base_shear / 1e3:.0f} kN (V/W = "
          f"{exact.peak_base_shear / weight:.3f}, W = {weight / 1e3:.0f} kN) at roof "
          f"{exact.roof_displacement[peak]:.3f} m ({100 * exact.roof_displacement[peak] / height:.2f} % "
          f"drift); at the target {exact.base_shear[-1] / 1e3:.0f} kN")
    print(f"  pounding pushover [s], best (median–worst): {spread(ours)}")
    print(f"  OpenSees: DisplacementControl, NormDispIncr 1e-10 m, Newton (≤ "
          f"{args.newton_iterations} iterations) then, on a failed step, "
          + ", ".join(" ".join(a) + f" (≤ {i})" for a, i in osf.FALLBACKS[1:]) + ":")
    print(f"  {'step mm':>8} {'steps':>6} {'time s, best (median–worst)':>32} {'error/peak':>11}"
          f" {'at roof m':>9} {'rescued':>7} {'done':>5} {'ratio best':>10} {'ratio med':>9}")
    import statistics

    for run in runs:
        ratio = min(run.times) / min(ours)
        ratio_med = statistics.median(run.times) / statistics.median(ours)
        print(f"  {1e3 * run.step:8.3f} {run.n:6d} {spread(run.times):>32} {run.error:11.1e}"
              f" {run.where:9.3f} {run.rescued:7d} {'yes' if run.complete else 'NO':>5}"
              f" {ratio:9.1f}x {ratio_med:8.1f}x")
        _figures.figure(f"LA9-type frame pushover to {100 * ROOF_DRIFT:.0f} % roof drift: "
                        f"OpenSees at {1e3 * run.step:.3g} mm steps ({run.n} steps, error "
                        f"{run.error:.1e} of the peak base shear"
                        f"{'' if run.complete else ', DID NOT REACH THE TARGET'})",
                        min(ours), _figures.opensees_name(), min(run.times),
                        ratio_meaning="OpenSees / pounding",
                        spread=f"best of {len(ours)} alternating; median ratio "
                               f"{ratio_med:.1f}x")
    agreeing = [r for r in runs if r.error <= ROUND_OFF]
    if agreeing:  # OpenSees is exact too at these steps: the cheapest of them
        best = min(agreeing, key=lambda r: min(r.times))
        what = (f"OpenSees agrees with pounding to round-off (≤ {ROUND_OFF:g}) from step "
                f"{1e3 * best.step:.3f} mm ({best.error:.1e})")
    else:  # pounding is the more accurate at every step: OpenSees' most accurate run
        best = min(runs, key=lambda r: r.error)
        what = (f"OpenSees' smallest error is {best.error:.1e} of the peak (step "
                f"{1e3 * best.step:.3f} mm)")
    print(f"  at equal or better accuracy: pounding's curve is exact between its events; "
          f"{what}, where it takes {min(best.times) / min(ours):.1f}x (best) / "
          f"{statistics.median(best.times) / statistics.median(ours):.1f}x (median) "
          f"pounding's time")
    all_ratios = [t / o for r in runs for t in r.times for o in ours]
    print(f"  the day's spread of the ratio (every OpenSees run / every pounding run): "
          f"{min(all_ratios):.1f}x – {max(all_ratios):.1f}x")
    print(f"  (OpenSees' warnings: {log})")
    _figures.note(f"pounding: {exact.base_shear.size} events, peak base shear "
                  f"{exact.peak_base_shear / 1e3:.0f} kN at roof "
                  f"{exact.roof_displacement[peak]:.3f} m; {what}")


def main(argv: list[str] | None = None) -> int:
    ap = _parser()
    args = ap.parse_args(argv)
    _figures.start("bench_pushover", "Pushover of an LA9-type frame")
    if args.blas_threads != "default":
        os.environ["OPENBLAS_NUM_THREADS"] = str(int(args.blas_threads))
    if args.tall_child:
        return tall_child()
    if args.newton_iterations < 1:
        ap.error(f"--newton-iterations: need at least 1 (got {args.newton_iterations})")
    if args.repeat < 1:
        ap.error(f"--repeat: need at least 1 (got {args.repeat})")
    sys.path.insert(0, str(HERE))
    from _environment import load, parse_list, print_environment

    wanted = parse_list(ap, args.sections, SECTIONS)
    try:
        steps_mm = [float(s) for s in args.steps.split(",") if s.strip()]
    except ValueError:
        ap.error(f"--steps: need numbers [mm] separated by commas (got {args.steps!r})")
    if not steps_mm or any(not (s > 0) for s in steps_mm):
        ap.error(f"--steps: need steps > 0 [mm] (got {args.steps!r})")
    from frames_la9 import HINGE_TYPES

    if args.hinges not in HINGE_TYPES:
        ap.error(f"--hinges: one of {', '.join(HINGE_TYPES)} (got {args.hinges!r})")
    print_environment(False)
    print(f"OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS', '(not set)')}")
    if "la9" in wanted:
        la9_section(args, steps_mm)
    if "memory" in wanted:
        memory_section()
    print(f"\nend: {load()}")
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

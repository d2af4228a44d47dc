"""Torsional pounding: pounding vs OpenSeesPy on the torsional pair of
``opensees_plan.torsional_pair()`` (issue 18), whole records, in one process.

Two 3-storey buildings in plan (rigid floors, u_x, u_y, θ), offset so that their façades
face each other over half their depth; the right one twists under x shaking and strikes at
its corner. Contacts at both ends of the facing stretch of each floor, Kelvin–Voigt
k = 9.3×10⁸ N/m with the dashpot of e = 0.65 for the two floor masses (the c OpenSees used is
given to pounding explicitly), pulling until the gap reopens (OpenSees' ``ViscoelasticGap``,
pounding's ``tension=True``). Gap 20 mm. Cases:

* ``el-centro``  — El Centro 1940 (180) along x, 40 s;
* ``duzce``      — the Düzce pair (Kocaeli 1999, 180 and 270) at 60° (first component 60°
                   from x), 27.2 s: both corners strike.

Each record gets a zero sample in front (both tools start at rest from zero ground
acceleration; OpenSees' Newmark assumes it). Both at a 1 ms step. Printed: wall times
(pounding: the whole ``simulate`` call, best of at least ``--repeat`` runs after a warm-up,
and its kernel timer; OpenSees: the analysis loop with its per-step reads, best of
``--repeat``), the ratio; impacts and peak force of every contact by both, and the floor
displacement and rotation differences (relative to each one's peak). Then pounding against
the SciPy reference (``simulate_reference``: DOP853, every event located) on a short window
of each record: impacts, peak forces, displacements.

    PYTHONPATH=src:benchmarks /work/bench-venv/bin/python benchmarks/bench_plan.py [--repeat 3]

Not a test (``tests/structure/test_opensees_plan.py`` asserts the agreement on short windows
and its convergence with dt): timings on a shared machine vary; read the ratio.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _figures
import opensees_models as osm  # noqa: E402
import opensees_plan as osp  # noqa: E402
from _environment import load, print_environment  # noqa: E402
from _memory import keep_freed_memory  # noqa: E402
from pounding import PoundingModel, simulate  # noqa: E402
from pounding.ground_motion import (GroundMotion, GroundMotionComponents,  # noqa: E402
                                    el_centro, load_bundled)
from pounding.ground_motion.incidence import at_incidence  # noqa: E402
from pounding.integrate.reference import simulate_reference  # noqa: E402
from pounding.model import ContactSpec  # noqa: E402

DT = 1e-3
"""Output step of both tools and OpenSees' analysis step [s]."""
MIN_TIMED_WINDOW = 1.0
"""Seconds over which pounding's timing repeats are spread at least [s]."""


def from_rest(g: GroundMotion, t0: float = 0.0, t1: float | None = None) -> GroundMotion:
    """The record from t0 to t1 [s] (default its end) with a zero sample in front."""
    k0 = round(t0 / g.dt)
    k1 = g.npts - 1 if t1 is None else round(t1 / g.dt)
    return GroundMotion(g.dt, np.concatenate([[0.0], g.accel[k0: k1 + 1]]), name=g.name)


def cases() -> dict[str, tuple[GroundMotion, GroundMotion | None, float, tuple[float, float]]]:
    """name: (first component, second or None, incidence angle [°], reference window [s])."""
    h1 = load_bundled("kocaeli_1999_duzce_180_RSN1158")
    h2 = load_bundled("kocaeli_1999_duzce_270_RSN1158")
    return {"el-centro": (el_centro(), None, 0.0, (1.5, 4.5)),
            "duzce": (h1, h2, 60.0, (8.0, 10.4))}


def site_motion(first: GroundMotion, second: GroundMotion | None, angle: float,
                window: tuple[float, float | None] = (0.0, None)
                ) -> tuple[GroundMotion, GroundMotion, float]:
    a = from_rest(first, *window)
    b = None if second is None else from_rest(second, *window)
    gx, gy = at_incidence(a, b, angle)
    return gx, gy, (gx.npts - 1) * gx.dt


def pounding_model(c: float) -> PoundingModel:
    left, right, gap = osp.torsional_pair()
    return PoundingModel([left, right], gaps=[gap], contact=ContactSpec(
        "kelvin-voigt", k=osp.EXAMPLE_CONTACT["k"], c=c, tension=True))


def run_opensees(gx: GroundMotion, gy: GroundMotion | None, duration: float,
                 repeat: int) -> dict[str, Any]:
    left, right, gap = osp.torsional_pair()
    runs = [osp.run_opensees_plan([left, right], [gap], osp.EXAMPLE_CONTACT, gx.accel,
                                  None if gy is None else gy.accel, gx.dt, DT, duration)
            for _ in range(max(1, repeat))]
    r = runs[-1]
    r["loops"] = sorted(x["wall_analyze"] for x in runs)
    cs = {cl["c"] for cl in r["params"]["contact_laws"]}
    if len(cs) != 1:  # the pair's floors are alike: one dashpot for every contact
        raise RuntimeError(f"OpenSees used several dashpots {sorted(cs)}; one is needed")
    r["c"] = cs.pop()
    return r


def run_pounding(model: PoundingModel, motion: GroundMotionComponents, duration: float,
                 repeat: int) -> tuple[Any, list[float], list[float]]:
    simulate(model, motion, dt=DT, duration=min(0.5, duration))  # warm-up, not timed
    walls, kernel = [], []
    res = None
    t_start = time.perf_counter()
    while len(walls) < max(1, repeat) or time.perf_counter() - t_start < MIN_TIMED_WINDOW:
        t0 = time.perf_counter()
        res = simulate(model, motion, dt=DT, duration=duration)
        walls.append(time.perf_counter() - t0)
        kernel.append(float(res.wall_time))
    return res, sorted(walls), sorted(kernel)


def contact_table(labels: list[str], ours: list[tuple[int, float]],
                  theirs: list[tuple[int, float]], names: tuple[str, str]) -> None:
    print(f"  {'contact':22s} {'impacts':>15s}   {'peak force [kN]':>24s}   {'relative':>9s}")
    print(f"  {'':22s} {names[0]:>7s} {names[1]:>7s}   {names[0]:>11s} {names[1]:>12s}   "
          f"{'diff':>9s}")
    for lab, (ni, fi), (nj, fj) in zip(labels, ours, theirs):
        diff = f"{(fj - fi) / fi:+9.1e}" if fi > 0 else f"{'-':>9s}"
        print(f"  {lab:22s} {ni:7d} {nj:7d}   {fi / 1e3:11.2f} {fj / 1e3:12.2f}   {diff}")


def history_diff(u: np.ndarray, v: np.ndarray) -> str:
    """Largest difference of u_x, u_y, θ over all floors, relative to u's peak of each."""
    parts = []
    for k, name in enumerate(("u_x", "u_y", "θ")):
        peak = np.abs(u[:, k::3]).max()
        d = np.abs(u[:, k::3] - v[:, k::3]).max()
        parts.append(f"{name} {d / peak:.1e}" if peak > 1e-12 else
                     f"{name} none (peaks {peak:.0e}, {np.abs(v[:, k::3]).max():.0e})")
    return ", ".join(parts)


def section_compare(name: str, first: GroundMotion, second: GroundMotion | None, angle: float,
                    repeat: int) -> float:
    """Times and agreement on the whole record; returns the dashpot c [N·s/m] used."""
    gx, gy, duration = site_motion(first, second, angle)
    what = first.name if second is None else f"{first.name} + {second.name}"
    print(f"\n== {name}: {what} at {angle:g}°, {duration:g} s ({gx.npts} samples at "
          f"{gx.dt:g} s, a zero one in front), step {1e3 * DT:g} ms ==")
    ops = run_opensees(gx, None if second is None else gy, duration, repeat)
    model = pounding_model(ops["c"])
    motion = GroundMotionComponents((gx, gy))
    res, walls, kernel = run_pounding(model, motion, duration, repeat)
    loops = ops["loops"]
    print(f"contact: kelvin-voigt, k = {osp.EXAMPLE_CONTACT['k']:.3g} N/m, c = "
          f"{ops['c']:.6g} N·s/m at every contact (e = {osp.EXAMPLE_CONTACT['e']:g}), "
          f"tension; {load()}")
    print(f"pounding  simulate: best {walls[0] * 1e3:8.1f} ms (of {len(walls)}: "
          f"{walls[0] * 1e3:.1f}–{walls[-1] * 1e3:.1f}); kernel {kernel[0] * 1e3:.1f} ms; "
          f"{res.n_impacts} impacts")
    print(f"OpenSees  analysis loop: best {loops[0] * 1e3:8.1f} ms (of {len(loops)}: "
          f"{loops[0] * 1e3:.1f}–{loops[-1] * 1e3:.1f}) = "
          f"{1e6 * loops[0] / ops['n_steps']:.0f} µs/step; {ops['n_impacts']} impacts; "
          f"failed steps {ops['failed']}, retried {ops['retried']}")
    print(f"ratio OpenSees / pounding (best / best): {loops[0] / walls[0]:.1f}x "
          f"(worst / worst {loops[-1] / walls[-1]:.1f}x)")
    _figures.figure(f"{name}: {what} at {angle:g} deg, {duration:g} s, {1e3 * DT:g} ms "
                    f"(pounding's whole simulate(), OpenSees' analysis loop)", walls[0],
                    _figures.opensees_name(), loops[0], ratio_meaning="OpenSees / pounding",
                    spread=f"best of {len(walls)} / {len(loops)}; worst / worst "
                           f"{loops[-1] / walls[-1]:.1f}x")
    peaks = res.contact_peaks
    labels = list(peaks)
    ours = [(peaks[lab].impacts, peaks[lab].force) for lab in labels]
    theirs = [(osm.count_impacts(col), float(col.max())) for col in ops["force"].T]
    contact_table(labels, ours, theirs, ("pound.", "OpenSees"))
    u = np.asarray(res.displacement)
    v = ops["u"]
    n = min(u.shape[0], v.shape[0])
    print(f"  floor histories, OpenSees − pounding, largest over floors and time, relative "
          f"to the peak: {history_diff(u[:n], v[:n])}")
    print("  (OpenSees feels a contact from the first step end after its onset: first order "
          "in dt; tests/structure/test_opensees_plan.py shows it shrinking 1 → 0.25 ms)")
    return float(ops["c"])


def section_reference(name: str, first: GroundMotion, second: GroundMotion | None,
                      angle: float, window: tuple[float, float], c: float) -> None:
    gx, gy, duration = site_motion(first, second, angle, window)
    motion = GroundMotionComponents((gx, gy))
    model = pounding_model(c)
    print(f"\n-- {name}: pounding against the SciPy reference, window {window[0]:g}–"
          f"{window[1]:g} s of the record ({duration:g} s from rest) --")
    t0 = time.perf_counter()
    res = simulate(model, motion, dt=DT, duration=duration, rtol=1e-10)
    t_ours = time.perf_counter() - t0
    t0 = time.perf_counter()
    ref = simulate_reference(model, motion, dt=DT, duration=duration)
    t_ref = time.perf_counter() - t0
    labels = list(res.contact_peaks)
    ours = [(res.contact_peaks[lab].impacts, res.contact_peaks[lab].force) for lab in labels]
    theirs = [(ref.contact_peaks[lab].impacts, ref.contact_peaks[lab].force) for lab in labels]
    print(f"pounding (rtol 1e-10) {t_ours:.2f} s, reference {t_ref:.1f} s")
    contact_table(labels, theirs, ours, ("ref.", "pound."))
    u, ur = np.asarray(res.displacement), np.asarray(ref.displacement)
    print(f"  floor histories, pounding − reference, relative to the peak: "
          f"{history_diff(ur, u)}; energy balance error {res.energy_balance_error:.1e}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=3,
                    help="timing repeats, best kept (3; pounding: at least as many)")
    ap.add_argument("--no-reference", action="store_true",
                    help="skip the comparison with the SciPy reference")
    ap.add_argument("--fresh-memory", action="store_true",
                    help="leave glibc's malloc as it is (default: keep freed memory for reuse, "
                         "see benchmarks/_memory.py)")
    _figures.add_json_option(ap)
    args = ap.parse_args(argv)
    _figures.start("bench_plan", "Buildings in plan against OpenSees")
    if args.repeat < 1:
        ap.error(f"--repeat must be >= 1 (got {args.repeat!r})")
    kept = keep_freed_memory(args.fresh_memory)
    print_environment(kept)
    left, right, gap = osp.torsional_pair()
    for b in (left, right):
        ecc = b.stiffness_eccentricity()
        print(f"{b.name}: {b.width:g} m x {b.depth:g} m at site y = {b.site_y:g} m, periods "
              f"{', '.join(f'{t:.3f}' for t in b.modes().periods)} s; e_y storey 1 = "
              f"{ecc[0, 1]:.2f} m")
    print(f"gap {gap * 1e3:g} mm; contacts at y = 6 m (right building's corner) and 12 m "
          f"(left building's corner) on each floor")
    cs: dict[str, float] = {}
    for name, (first, second, angle, _) in cases().items():
        cs[name] = section_compare(name, first, second, angle, args.repeat)
    if not args.no_reference:
        for name, (first, second, angle, window) in cases().items():
            section_reference(name, first, second, angle, window, cs[name])
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

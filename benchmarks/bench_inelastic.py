"""Yielding storeys: pounding vs OpenSeesPy on the same models, in one process.

Run from the repository root, in a virtualenv holding both ``pounding`` and ``openseespy``
(see ``benchmarks/README.md``)::

    python benchmarks/bench_inelastic.py                    # every section, full El Centro
    python benchmarks/bench_inelastic.py --duration 10      # first 10 s of the record
    python benchmarks/bench_inelastic.py --sections bilinear,pair --repeat 5

Sections:

materials  The storey laws alone along a cyclic drift path: OpenSees ``Steel01`` /
           ``BoucWen`` (testUniaxialMaterial) against ``pounding.hysteresis
           .respond_drift_path``, largest shear difference in % of F_y, at two path
           resolutions (shows whether a difference is OpenSees' per-step integration).
sanity     OpenSees alone: the yielding SDOF model with F_y so large that it stays elastic
           must give the exact linear response (scipy lsim): checks the parallel dashpot.
bilinear   (a) bilinear SDOF (m = 2e5 kg, T = 0.5 s, 5 %, F_y = 0.15 m g, b = 0.05).
epp        (b) the same, elastic–perfectly plastic (b = 0; Steel01 accepts b = 0).
boucwen    (c) Bouc–Wen SDOF (alpha = 0.05, n = 2, beta = gamma = 0.5) vs OpenSees BoucWen.
pair       (d) the bilinear SDOF of (a) and a 3e5 kg, T = 1.0 s, 5 %, F_y = 0.15 m g,
           b = 0.05 bilinear SDOF, gap 20 mm, Kelvin–Voigt contact (OpenSees ViscoelasticGap).

Each of (a)–(d): wall time of each tool (best of --repeat), the ratio OpenSees / pounding,
and each tool's error against ``simulate_reference`` in peak displacement, residual drift,
hysteretic energy and, for the pair, peak contact force and number of impacts.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, Callable

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _figures
import opensees_inelastic as osi  # noqa: E402
from _memory import keep_freed_memory  # noqa: E402
import opensees_models as osm  # noqa: E402
from bench_opensees import best_of, header, linear_peaks, pct, table  # noqa: E402
from pounding.ground_motion import GroundMotion, el_centro  # noqa: E402

try:
    from pounding.hysteresis import Bilinear, BoucWen, respond_drift_path
    from pounding.integrate import simulate
    from pounding.integrate.reference import simulate_reference
    from pounding.model import ContactSpec, PoundingModel
    from pounding.structure import ShearBuilding
    OURS_ERROR: str | None = None
except ImportError as exc:  # pragma: no cover - depends on the state of the package
    OURS_ERROR = f"pounding's yielding-storey API not importable ({exc}); sections skipped"

G = osi.G
LEFT = osi.YieldingSdof(mass=2e5, period=0.5, zeta=0.05, fy=0.15 * 2e5 * G, law="bilinear",
                        b=0.05)
LEFT_EPP = replace(LEFT, b=0.0)
LEFT_BW = replace(LEFT, law="bouc-wen", alpha=0.05, n=2.0, beta=0.5, gamma=0.5)
RIGHT = osi.YieldingSdof(mass=3e5, period=1.0, zeta=0.05, fy=0.15 * 3e5 * G, law="bilinear",
                         b=0.05)
GAP, E_RESTITUTION, K_KV = 0.02, 0.65, osm.K_KV_DEFAULT


# ===================================================================== our engine
def our_law(s: osi.YieldingSdof) -> Any:
    if s.law == "bilinear":
        return Bilinear(yield_force=s.fy, hardening=s.b)
    return BoucWen(yield_force=s.fy, alpha=s.alpha, n=s.n, beta=s.beta, gamma=s.gamma)


def our_model(sdofs: list[osi.YieldingSdof], gap: float | None) -> Any:
    blds = [ShearBuilding.sdof(s.mass, period=s.period, damping_ratio=s.zeta,
                               name=("left", "right")[i]).with_storey_law(our_law(s))
            for i, s in enumerate(sdofs)]
    contact = ContactSpec("kelvin-voigt", k=K_KV, e=E_RESTITUTION, formula="anagnostopoulos",
                          tension=True)  # as OpenSees ViscoelasticGap
    return PoundingModel(blds, [gap] if gap is not None else [], contact)


def _summarise(res: Any, sdofs: list[osi.YieldingSdof], wall_total: float,
               wall_analyze: float) -> dict[str, Any]:
    u = np.asarray(res.displacement)
    v = np.asarray(res.storey_shear)
    out = {
        "time": np.asarray(res.time), "u": u, "shear": v,
        "peak_u": np.abs(u).max(axis=0),
        "residual_drift": np.asarray(res.residual_drift, dtype=float),
        "hysteretic_energy_total": float(res.energy[-1, 6]),
        # the same trapezoid as for OpenSees, on our own output grid (a cross-check)
        "hysteretic_energy": np.array([osi.hysteretic_energy(s, u[:, j], v[:, j])
                                       for j, s in enumerate(sdofs)]),
        "ductility": np.asarray(res.ductility), "balance": float(res.energy_balance_error),
        "wall_analyze": wall_analyze, "wall_total": wall_total, "n_steps": u.shape[0] - 1,
    }
    if len(res.model.contacts):
        out.update(force=np.asarray(res.contact_force)[:, 0],
                   peak_force=float(res.peak_contact_force[0]), n_impacts=int(res.n_impacts))
    return out


def run_ours(sdofs: list[osi.YieldingSdof], gap: float | None, motion: GroundMotion,
             dt: float, duration: float | None, repeat: int,
             reference: bool = False) -> dict[str, Any]:
    model = our_model(sdofs, gap)
    if reference:
        t0 = time.perf_counter()
        res = simulate_reference(model, motion, dt=dt, duration=duration)
        w = time.perf_counter() - t0
        return _summarise(res, sdofs, w, w)
    simulate(model, motion, dt=dt, duration=min(0.5, duration or motion.duration))  # warm-up
    best_a = best_t = math.inf
    res = None
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        res = simulate(model, motion, dt=dt, duration=duration)
        best_t = min(best_t, time.perf_counter() - t0)
        best_a = min(best_a, float(res.wall_time))
    return _summarise(res, sdofs, best_t, best_a)


def run_os(sdofs: list[osi.YieldingSdof], gap: float | None, motion: GroundMotion, dt: float,
           duration: float | None, repeat: int) -> dict[str, Any]:
    r = best_of(lambda: osi.run_opensees_yielding(sdofs, motion.accel, motion.dt, dt, gap=gap,
                                                  e=E_RESTITUTION, k_contact=K_KV,
                                                  duration=duration), repeat)
    r["hysteretic_energy_total"] = float(np.sum(r["hysteretic_energy"]))
    return r


# ===================================================================== sections
@dataclass
class Ctx:
    motion: GroundMotion
    duration: float | None
    repeat: int
    dt: float
    rows: list[list[str]]

    @property
    def t_end(self) -> float:
        return self.motion.duration if self.duration is None else self.duration


def section_materials(ctx: Ctx) -> None:
    header("Materials alone: OpenSees vs pounding along a cyclic drift path")
    if OURS_ERROR:
        print(OURS_ERROR)
        return
    rows = []
    for label, s in (("bilinear b = 0.05 / Steel01", LEFT), ("EPP b = 0 / Steel01", LEFT_EPP),
                     ("Bouc-Wen / BoucWen", LEFT_BW)):
        dy = s.dy
        peaks = np.array([0.0, 1.0, -1.0, 2.0, -2.0, 4.0, -4.0, 1.5, 0.0]) * dy
        for per_dy in (20, 200):
            path = np.concatenate([np.linspace(a, b, int(round(abs(b - a) / dy * per_dy)) + 1)[1:]
                                   for a, b in zip(peaks[:-1], peaks[1:])])
            path = np.concatenate([[0.0], path])
            v_os = osi.drive_material(s, path)
            v_us = respond_drift_path(our_law(s), s.k, path)
            diff = np.abs(v_os - v_us)
            i = int(np.argmax(diff))
            rows.append([label, f"d_y/{per_dy}", str(path.size), f"{100 * diff.max() / s.fy:.4f}",
                         f"{path[i] / dy:+.2f}", f"{100 * np.mean(diff) / s.fy:.4f}"])
    table(rows, ["law", "path step", "samples", "max |ΔV| % F_y", "at d/d_y", "mean |ΔV| % F_y"])
    print("Path: 0 → ±1 → ±2 → ±4 d_y → 1.5 d_y → 0, sampled every d_y/20 or d_y/200; "
          "pounding's respond_drift_path integrates z with RK4 (200 sub-steps per sample), "
          "OpenSees' BoucWen by one backward-Euler step per sample.")


def section_sanity(ctx: Ctx) -> None:
    header("Sanity: OpenSees' yielding SDOF with F_y = 1e12 N (stays elastic) vs lsim")
    rows = []
    for label, s in (("Steel01", LEFT), ("BoucWen", LEFT_BW)):
        big = replace(s, fy=1e12)
        r = osi.run_opensees_yielding([big], ctx.motion.accel, ctx.motion.dt, ctx.dt,
                                      duration=ctx.duration)
        lin = linear_peaks(np.array([[s.mass]]), np.array([[s.c]]), np.array([[s.k]]),
                           ctx.motion, ctx.t_end)[0]
        rows.append([label, f"{r['peak_u'][0]:.6f}", f"{lin:.6f}",
                     f"{pct(r['peak_u'][0], lin):+.4f}",
                     f"{np.abs(r['shear'][:, 0] - s.k * r['u'][:, 0]).max():.3g}"])
    table(rows, ["storey", "OS max|u| m", "lsim m", "diff %", "max |V − k u| N"])
    print("(Newmark at 1 ms vs the exact linear response: differences of order 0.01 %.)")


def _case(ctx: Ctx, label: str, sdofs: list[osi.YieldingSdof], gap: float | None) -> None:
    header(f"{label} ({1e3 * ctx.dt:g} ms, best of {ctx.repeat})")
    if OURS_ERROR:
        print(OURS_ERROR)
        return
    m = ctx.motion
    t0 = time.perf_counter()
    print("  computing the reference ...", flush=True)
    ref = run_ours(sdofs, gap, m, ctx.dt, ctx.duration, 1, reference=True)
    print(f"  ... {time.perf_counter() - t0:.1f} s", flush=True)
    ours = run_ours(sdofs, gap, m, ctx.dt, ctx.duration, ctx.repeat)
    r_os = run_os(sdofs, gap, m, ctx.dt, ctx.duration, ctx.repeat)
    ratio = (f"{r_os['wall_analyze'] / ours['wall_analyze']:.1f} / "
             f"{r_os['wall_total'] / ours['wall_total']:.1f}")
    pair = gap is not None
    eh_ref = ref["hysteretic_energy_total"]
    seconds = m.duration if ctx.duration is None else ctx.duration
    case = f"{label}, El Centro {seconds:.0f} s, {1e3 * ctx.dt:g} ms"
    _figures.figure(f"{case}: time-stepping loop", ours["wall_analyze"], _figures.opensees_name(),
                    r_os["wall_analyze"], ratio_meaning="OpenSees / pounding", goal=">= 20x",
                    spread=f"best of {ctx.repeat}")
    _figures.figure(f"{case}: whole call", ours["wall_total"], _figures.opensees_name(),
                    r_os["wall_total"], ratio_meaning="OpenSees / pounding",
                    spread=f"best of {ctx.repeat}")
    _figures.note(f"{label}: peak displacement against the SciPy reference: OpenSees "
                  + " / ".join(f"{pct(a, b):+.4f} %" for a, b in zip(r_os["peak_u"], ref["peak_u"]))
                  + ", pounding "
                  + " / ".join(f"{pct(a, b):+.4f} %" for a, b in zip(ours["peak_u"], ref["peak_u"]))
                  + f"; hysteretic energy OpenSees {pct(r_os['hysteretic_energy_total'], eh_ref):+.4f} %,"
                  f" pounding {pct(ours['hysteretic_energy_total'], eh_ref):+.4f} %")
    rows = []
    for tool, r in (("OpenSees", r_os), ("pounding", ours)):
        du = " / ".join(f"{pct(a, b):+.4f}" for a, b in zip(r["peak_u"], ref["peak_u"]))
        dres = " / ".join(f"{1e3 * (a - b):+.4f}"
                          for a, b in zip(r["residual_drift"], ref["residual_drift"]))
        dres_pct = " / ".join(f"{pct(a, b):+.2f}"
                              for a, b in zip(r["residual_drift"], ref["residual_drift"]))
        row = [label, tool, f"{r['wall_analyze']:.4f}", f"{r['wall_total']:.4f}",
               f"{1e6 * r['wall_analyze'] / r['n_steps']:.2f}",
               ratio if tool == "pounding" else "", du, dres, dres_pct,
               f"{pct(r['hysteretic_energy_total'], eh_ref):+.4f}"]
        if pair:
            row += [f"{pct(r['peak_force'], ref['peak_force']):+.3f}",
                    f"{r['n_impacts']} ({ref['n_impacts']})"]
        else:
            row += ["", ""]
        row += [f"{r.get('retried', '')}"]
        rows.append(row)
        ctx.rows.append(row)
    table(rows, HEAD)
    ref_line = (f"  reference: max|u| {' / '.join(f'{x:.6f}' for x in ref['peak_u'])} m, "
                f"residual drift {' / '.join(f'{1e3 * x:+.4f}' for x in ref['residual_drift'])} mm, "
                f"ductility {' / '.join(f'{x:.3f}' for x in ref['ductility'])}, "
                f"E_h {eh_ref:.6g} J")
    if pair:
        ref_line += f", Fmax {ref['peak_force']:.6g} N, {ref['n_impacts']} impacts"
    print(ref_line + f", energy balance error {ref['balance']:.1e}, wall {ref['wall_total']:.1f} s")
    print(f"  pounding energy balance error {ours['balance']:.1e}; E_h by the trapezoid on the "
          f"output grid vs the Result's energy column: reference "
          f"{pct(float(np.sum(ref['hysteretic_energy'])), eh_ref):+.4f} %, pounding "
          f"{pct(float(np.sum(ours['hysteretic_energy'])), ours['hysteretic_energy_total']):+.4f} %")
    if r_os["failed"]:
        print(f"  OpenSees stopped early: {r_os['failed']} step(s) failed")


HEAD = ["case", "tool", "analyze s", "total s", "µs/step", "ratio OS/ours", "Δmax|u| %",
        "Δresid mm", "Δresid %", "ΔE_h %", "ΔFmax %", "impacts (ref)", "retried"]


def section_bilinear(ctx: Ctx) -> None:
    _case(ctx, "(a) bilinear SDOF", [LEFT], None)


def section_epp(ctx: Ctx) -> None:
    _case(ctx, "(b) EPP SDOF", [LEFT_EPP], None)


def section_boucwen(ctx: Ctx) -> None:
    _case(ctx, "(c) Bouc-Wen SDOF", [LEFT_BW], None)


def section_pair(ctx: Ctx) -> None:
    _case(ctx, "(d) bilinear pair", [LEFT, RIGHT], GAP)


SECTIONS: dict[str, Callable[[Ctx], None]] = {
    "materials": section_materials, "sanity": section_sanity, "bilinear": section_bilinear,
    "epp": section_epp, "boucwen": section_boucwen, "pair": section_pair}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sections", default=",".join(SECTIONS),
                    help=f"comma-separated, from {', '.join(SECTIONS)} (default: all)")
    ap.add_argument("--duration", type=float, default=None,
                    help="seconds of El Centro to use (default: the whole record)")
    ap.add_argument("--repeat", type=int, default=3, help="timing repeats, best kept (3)")
    ap.add_argument("--dt", type=float, default=1e-3, help="output / analysis step [s] (1e-3)")
    ap.add_argument("--fresh-memory", action="store_true",
                    help="leave glibc's malloc as it is (default: keep freed memory for reuse, "
                         "see benchmarks/_memory.py)")
    _figures.add_json_option(ap)
    args = ap.parse_args(argv)
    _figures.start("bench_inelastic", "Yielding storeys against OpenSees")
    wanted = [s.strip() for s in args.sections.split(",") if s.strip()]
    bad = [s for s in wanted if s not in SECTIONS]
    if bad:
        ap.error(f"unknown section(s) {bad}; choose from {list(SECTIONS)}")
    keep_freed_memory(args.fresh_memory)

    import platform
    from importlib.metadata import PackageNotFoundError, version

    motion = el_centro()
    vers = {}
    for pkg in ("openseespy", "pounding", "numba", "scipy"):
        try:
            vers[pkg] = version(pkg)
        except PackageNotFoundError:
            vers[pkg] = "not installed"
    print(f"record: {motion.name}, {motion.npts} samples at {motion.dt} s, "
          f"{motion.duration if args.duration is None else args.duration:g} s used; "
          f"step {1e3 * args.dt:g} ms")
    print(f"python {platform.python_version()}, openseespy {vers['openseespy']}, "
          f"pounding {vers['pounding']}, numpy {np.__version__}, numba {vers['numba']}, "
          f"scipy {vers['scipy']}, {os.cpu_count()} CPUs "
          f"({platform.processor() or platform.machine()})")
    print(f"models: left m {LEFT.mass:g} kg, T {LEFT.period} s, k {LEFT.k:.6g} N/m, "
          f"c {LEFT.c:.6g} N s/m, F_y {LEFT.fy:.6g} N (d_y {1e3 * LEFT.dy:.4f} mm); right m "
          f"{RIGHT.mass:g} kg, T {RIGHT.period} s, k {RIGHT.k:.6g} N/m, F_y {RIGHT.fy:.6g} N "
          f"(d_y {1e3 * RIGHT.dy:.4f} mm); OpenSees BoucWen (alpha, ko, n, gamma, beta, Ao, "
          f"deltaA, deltaNu, deltaEta) = "
          f"({', '.join(f'{x:.6g}' for x in osi.boucwen_opensees_params(LEFT_BW))})")
    if OURS_ERROR:
        print(OURS_ERROR)
    ctx = Ctx(motion, args.duration, args.repeat, args.dt, [])
    for s in wanted:
        try:
            SECTIONS[s](ctx)
        except Exception as exc:  # one broken section must not hide the others
            print(f"section {s} failed: {type(exc).__name__}: {exc}")
            _figures.failure(f"section {s}: {type(exc).__name__}: {exc}")
    _figures.write(args.json)
    if ctx.rows:
        header("Summary")
        table(ctx.rows, HEAD)
        print("analyze = the time-stepping loop only (OpenSees: the analyze(1, dt) loop with "
              "its per-step reads of displacement, storey shear and contact force; pounding: "
              "the compiled kernel's own timer); total = model build + analysis (pounding: the "
              "whole simulate() call, numba compiled by a warm-up run). ratio = OpenSees / "
              "pounding, analyze / total. Errors against simulate_reference: Δmax|u| and "
              "Δresid (d_end − V_end / k_unload) per building (left / right), ΔE_h on the "
              "total hysteretic energy (work ∫V dd − recoverable energy; OpenSees: trapezoid "
              "on the output grid; pounding: Result.energy[-1, 6]). Timings: best of "
              f"{args.repeat} on a shared 2-core machine, ±20 % between runs.")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""Pounding vs OpenSeesPy on the same models, in one process.

Run from the repository root, in a virtualenv holding both ``pounding`` and ``openseespy``
(see ``benchmarks/README.md``)::

    python benchmarks/bench_opensees.py                    # every section, full El Centro
    python benchmarks/bench_opensees.py --duration 10      # first 10 s of the record
    python benchmarks/bench_opensees.py --sections sanity,compare

Sections:

sanity       OpenSees alone: with a gap so wide that nothing touches, its peak displacements
             must equal the linear response computed independently (scipy.signal.lsim, exact
             for a piecewise-linear input); also its raw peak forces, impacts and timings.
compare      SDOF pair (Kelvin–Voigt / Jankowski) and 10-storey pair (Kelvin–Voigt): wall time
             of each tool, the ratio, and each tool's error against the tight reference
             (``simulate_reference``) in peak contact force, number of impacts, peak
             displacement of each building.
convergence  OpenSees' peak-force error at output steps 2, 1, 0.5, 0.25 ms against the
             reference, with the observed order (and ours at the same steps).
scaling      Our engine: µs per step against the number of storeys (1 … 50) and the record
             length (El Centro tiled ×1, ×2, ×4).

The sections that need the ``pounding.model`` / ``pounding.integrate`` API say so and are
skipped if it cannot be imported.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _figures
from _memory import keep_freed_memory  # noqa: E402
import opensees_models as osm  # noqa: E402
from pounding.ground_motion import GroundMotion, el_centro  # noqa: E402

try:  # the engine API (being written alongside this script)
    from pounding.integrate import simulate
    from pounding.integrate.reference import simulate_reference
    from pounding.model import ContactSpec, PoundingModel
    from pounding.structure import ShearBuilding
    OURS_ERROR: str | None = None
except ImportError as exc:  # pragma: no cover - depends on the state of the package
    OURS_ERROR = (f"pounding engine API not importable ({exc}); the sections comparing with "
                  f"pounding are skipped. Needed: pounding.model.PoundingModel/ContactSpec, "
                  f"pounding.integrate.simulate, pounding.integrate.reference.simulate_reference")

# the models of the issue
SDOF = dict(m1=2e5, T1=0.5, m2=3e5, T2=1.0, zeta=0.05, gap=0.02, e=0.65)
SHEAR = dict(n_storeys=10, mass=2e5, T1=1.0, T2=1.5, zeta=0.05, gap=0.02, e=0.65)
K_KV = osm.K_KV_DEFAULT
K_H = osm.K_H_DEFAULT
OUR_LAW = {"kelvin-voigt": "kelvin-voigt", "jankowski": "nonlinear-viscoelastic"}


# ===================================================================== our engine
def _contact_spec(law: str, e: float, k: float = K_KV, k_h: float = K_H) -> Any:
    if law == "kelvin-voigt":
        # as OpenSees ViscoelasticGap: Anagnostopoulos c, the dashpot may pull (tension)
        return ContactSpec("kelvin-voigt", k=k, e=e, formula="anagnostopoulos", tension=True)
    if law == "jankowski":
        return ContactSpec("nonlinear-viscoelastic", k_h=k_h, e=e)  # Jankowski 2006 ζ
    raise ValueError(f"law must be one of {osm.LAWS} (got {law!r})")


def sdof_pair_model(law: str, *, m1: float = 2e5, T1: float = 0.5, m2: float = 3e5,
                    T2: float = 1.0, zeta: float = 0.05, gap: float = 0.02, e: float = 0.65,
                    k: float = K_KV, k_h: float = K_H) -> Any:
    """The SDOF pair as a PoundingModel (c = 2 ζ m ω in each oscillator)."""
    b1 = ShearBuilding.sdof(m1, period=T1, damping_ratio=zeta, name="left")
    b2 = ShearBuilding.sdof(m2, period=T2, damping_ratio=zeta, name="right")
    return PoundingModel([b1, b2], gaps=[gap], contact=_contact_spec(law, e, k, k_h),
                         name=f"SDOF pair, {law}")


def shear_pair_model(law: str = "kelvin-voigt", *, n_storeys: int = 10, mass: float = 2e5,
                     T1: float = 1.0, T2: float = 1.5, zeta: float = 0.05, gap: float = 0.02,
                     e: float = 0.65, k: float = K_KV, k_h: float = K_H) -> Any:
    """The shear pair as a PoundingModel: the same masses and stiffnesses as
    :func:`opensees_models.run_opensees_shear_pair`, Rayleigh ζ in modes 1 and 2."""
    from pounding.structure.damping import RayleighDamping

    blds = []
    for name, T in (("left", T1), ("right", T2)):
        m_, k_ = osm.uniform_building(n_storeys, mass, T)
        blds.append(ShearBuilding.uniform(n_storeys, float(m_[0]), float(k_[0]),
                                          damping=RayleighDamping(zeta), name=name))
    return PoundingModel(blds, gaps=[gap], contact=_contact_spec(law, e, k, k_h),
                         name=f"{n_storeys}-storey pair, {law}")


def _summarise(res: Any, n_left: int, wall_total: float) -> dict[str, Any]:
    u = np.asarray(res.displacement)
    ul, ur = u[:, :n_left], u[:, n_left:]
    f = np.asarray(res.contact_force)
    return {
        "time": np.asarray(res.time), "u_left": ul, "u_right": ur, "force": f,
        "peak_force": np.asarray(res.peak_contact_force, dtype=float),
        "n_impacts": int(res.n_impacts),
        "peak_u_left": np.abs(ul).max(axis=0), "peak_u_right": np.abs(ur).max(axis=0),
        "wall_analyze": float(res.wall_time), "wall_total": wall_total,
        "n_steps": u.shape[0] - 1, "result": res,
    }


MIN_TIMED_WINDOW = 0.5
"""Seconds over which pounding's timing repeats are spread at least [s]."""
MAX_REPEAT = 200


def _run_ours(model: Any, motion: GroundMotion, dt: float, duration: float | None,
              repeat: int, reference: bool) -> dict[str, Any]:
    n_left = model.buildings[0].n
    if reference:
        t0 = time.perf_counter()
        res = simulate_reference(model, motion, dt=dt, duration=duration)
        return _summarise(res, n_left, time.perf_counter() - t0)
    # warm-up (numba compilation, first-touch of caches) is not timed
    simulate(model, motion, dt=dt, duration=min(0.5, duration or motion.duration))
    best_a = best_t = math.inf
    res = None
    # At least `repeat` runs, and as many more as fit in MIN_TIMED_WINDOW: a best-of over a
    # few milliseconds is at the mercy of one burst of other work on a shared machine,
    # where OpenSees' repeats are spread over a second or more.
    t0 = time.perf_counter()
    simulate(model, motion, dt=dt, duration=duration)
    one = time.perf_counter() - t0
    for _ in range(max(1, repeat, min(MAX_REPEAT, math.ceil(MIN_TIMED_WINDOW / one)))):
        t0 = time.perf_counter()
        res = simulate(model, motion, dt=dt, duration=duration)
        best_t = min(best_t, time.perf_counter() - t0)
        best_a = min(best_a, float(res.wall_time))
    out = _summarise(res, n_left, best_t)
    out["wall_analyze"] = best_a
    return out


def run_pounding_sdof_pair(law: str, motion: GroundMotion, dt: float = 1e-3, *,
                           duration: float | None = None, repeat: int = 3,
                           reference: bool = False, **params: Any) -> dict[str, Any]:
    """Our engine (or, with ``reference=True``, the SciPy reference) on the SDOF pair.

    Same keys as :func:`opensees_models.run_opensees_sdof_pair` for the common quantities
    (``u1``, ``u2``, ``force`` 1-D; ``peak_force`` a float). ``wall_analyze`` is the
    kernel's own timer (best of ``repeat``), ``wall_total`` the whole ``simulate`` call.
    """
    r = _run_ours(sdof_pair_model(law, **params), motion, dt, duration, repeat, reference)
    r.update(u1=r["u_left"][:, 0], u2=r["u_right"][:, 0], force=r["force"][:, 0],
             peak_u1=float(r["peak_u_left"][0]), peak_u2=float(r["peak_u_right"][0]),
             peak_force=float(r["peak_force"][0]))
    return r


def run_pounding_shear_pair(motion: GroundMotion, dt: float = 1e-3, *, law: str = "kelvin-voigt",
                            duration: float | None = None, repeat: int = 3,
                            reference: bool = False, **params: Any) -> dict[str, Any]:
    """Our engine (or the reference) on the two shear buildings; keys as
    :func:`opensees_models.run_opensees_shear_pair`."""
    return _run_ours(shear_pair_model(law, **params), motion, dt, duration, repeat, reference)


# ===================================================================== OpenSees, timed
def best_of(fn: Callable[[], dict[str, Any]], repeat: int) -> dict[str, Any]:
    """Run ``fn`` ``repeat`` times; the last result with the best wall times."""
    best_a = best_t = math.inf
    out: dict[str, Any] = {}
    for _ in range(max(1, repeat)):
        out = fn()
        best_a = min(best_a, out["wall_analyze"])
        best_t = min(best_t, out["wall_total"])
    out["wall_analyze"], out["wall_total"] = best_a, best_t
    return out


def ops_sdof(law: str, motion: GroundMotion, dt: float, duration: float | None,
             repeat: int = 1, **over: Any) -> dict[str, Any]:
    p = {**SDOF, **over}
    return best_of(lambda: osm.run_opensees_sdof_pair(law, motion.accel, motion.dt, dt,
                                                      duration=duration, **p), repeat)


def ops_shear(motion: GroundMotion, dt: float, duration: float | None, repeat: int = 1,
              law: str = "kelvin-voigt", **over: Any) -> dict[str, Any]:
    p = {**SHEAR, **over}
    r = best_of(lambda: osm.run_opensees_shear_pair(motion.accel, motion.dt, dt, law=law,
                                                    duration=duration, **p), repeat)
    return r


def _as_pair(r: dict[str, Any]) -> tuple[float, float, float, int]:
    """Overall peak force, peak |u| of left and right building, impacts."""
    if np.ndim(r["peak_force"]) > 0:
        return (float(np.max(r["peak_force"])), float(np.max(r["peak_u_left"])),
                float(np.max(r["peak_u_right"])), int(r["n_impacts"]))
    return float(r["peak_force"]), r["peak_u1"], r["peak_u2"], int(r["n_impacts"])


def pct(x: float, ref: float) -> float:
    return 100.0 * (x - ref) / ref if ref != 0 else (0.0 if x == 0 else math.inf)


# ===================================================================== printing
def header(title: str) -> None:
    print()
    print(title)
    print("=" * len(title))


def table(rows: list[list[str]], head: list[str]) -> None:
    w = [max(len(str(x)) for x in col) for col in zip(head, *rows)]
    line = "  ".join(h.ljust(n) for h, n in zip(head, w))
    print(line)
    print("-" * len(line))
    for r in rows:
        print("  ".join(str(x).rjust(n) if i else str(x).ljust(n)
                        for i, (x, n) in enumerate(zip(r, w))))


def linear_peaks(M: np.ndarray, C: np.ndarray, K: np.ndarray, motion: GroundMotion,
                 t_end: float) -> np.ndarray:
    """Peak |u| of M ü + C u̇ + K u = −M 1 a_g (piecewise-linear a_g), by scipy lsim at the
    record's own samples with first-order hold: exact up to round-off at the samples; the
    response between samples is taken on a 1 ms grid."""
    from scipy.signal import StateSpace, lsim

    n = M.shape[0]
    minv = np.linalg.inv(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-minv @ K, -minv @ C]])
    B = np.concatenate([np.zeros(n), -np.ones(n)])[:, None]
    Cm = np.hstack([np.eye(n), np.zeros((n, n))])
    t = np.arange(int(round(t_end / 1e-3)) + 1) * 1e-3
    a = np.interp(t, motion.time, motion.accel, right=0.0)
    _, y, _ = lsim(StateSpace(A, B, Cm, np.zeros((n, 1))), a, t)
    return np.abs(np.atleast_2d(y.T).T).max(axis=0)


# ===================================================================== sections
@dataclass
class Ctx:
    motion: GroundMotion
    duration: float | None
    repeat: int
    dt: float
    refs: dict[str, dict[str, Any]]

    @property
    def t_end(self) -> float:
        return self.motion.duration if self.duration is None else self.duration


def section_sanity(ctx: Ctx) -> None:
    header("Sanity: OpenSees alone")
    m, t_end = ctx.motion, ctx.t_end
    # 1. no contact: a 10 m gap; compare with the independent linear response
    rows = []
    p = SDOF
    w1, w2 = 2 * math.pi / p["T1"], 2 * math.pi / p["T2"]
    for law in osm.LAWS:
        r = ops_sdof(law, m, ctx.dt, ctx.duration, gap=10.0)
        lin = [linear_peaks(np.array([[mm]]), np.array([[2 * p["zeta"] * mm * w]]),
                            np.array([[mm * w * w]]), m, t_end)[0]
               for mm, w in ((p["m1"], w1), (p["m2"], w2))]
        rows.append([f"SDOF pair, {law}, gap 10 m", f"{r['peak_u1']:.6f}", f"{lin[0]:.6f}",
                     f"{pct(r['peak_u1'], lin[0]):+.4f}", f"{r['peak_u2']:.6f}", f"{lin[1]:.6f}",
                     f"{pct(r['peak_u2'], lin[1]):+.4f}", f"{r['peak_force']:.3g}",
                     str(r["n_impacts"])])
    r = ops_shear(m, ctx.dt, ctx.duration, gap=10.0)
    lin_lr = []
    for side, (a0, a1) in zip(("left", "right"), r["params"]["rayleigh"]):
        mm, kk = r["params"][side]
        M, K = osm.shear_matrices(mm, kk)
        lin_lr.append(linear_peaks(M, a0 * M + a1 * K, K, m, t_end).max())
    pl, pr = float(r["peak_u_left"].max()), float(r["peak_u_right"].max())
    rows.append([f"{SHEAR['n_storeys']}-storey pair, gap 10 m", f"{pl:.6f}", f"{lin_lr[0]:.6f}",
                 f"{pct(pl, lin_lr[0]):+.4f}", f"{pr:.6f}", f"{lin_lr[1]:.6f}",
                 f"{pct(pr, lin_lr[1]):+.4f}", f"{r['peak_force'].max():.3g}",
                 str(r["n_impacts"])])
    table(rows, ["case", "OS max|u1| m", "lsim m", "diff %", "OS max|u2| m", "lsim m",
                 "diff %", "OS Fmax N", "impacts"])
    print("(Newmark average acceleration at 1 ms vs the exact linear response: the differences"
          " should be of order 0.01 %; no contact force may appear.)")

    # 2. the benchmark cases, OpenSees only
    rows = []
    for label, fn in (("SDOF pair, kelvin-voigt",
                       lambda: ops_sdof("kelvin-voigt", m, ctx.dt, ctx.duration, ctx.repeat)),
                      ("SDOF pair, jankowski",
                       lambda: ops_sdof("jankowski", m, ctx.dt, ctx.duration, ctx.repeat)),
                      (f"{SHEAR['n_storeys']}-storey pair, kelvin-voigt",
                       lambda: ops_shear(m, ctx.dt, ctx.duration, ctx.repeat))):
        r = fn()
        fmax, u1, u2, nimp = _as_pair(r)
        rows.append([label, f"{fmax:.5g}", str(nimp), f"{u1:.5f}", f"{u2:.5f}",
                     f"{r['wall_analyze']:.3f}", f"{r['wall_total']:.3f}",
                     f"{1e6 * r['wall_analyze'] / r['n_steps']:.1f}", str(r["retried"]),
                     str(r["failed"])])
    table(rows, ["case", "Fmax N", "impacts", "max|u1| m", "max|u2| m", "analyze s", "total s",
                 "µs/step", "retried", "failed"])
    print(f"(best of {ctx.repeat}; {rows and r['n_steps']} steps of {1e3 * ctx.dt:g} ms; "
          "'retried' = steps whose Newton iteration failed and were redone with another "
          "algorithm or sub-steps)")


def _reference(ctx: Ctx, key: str, fn: Callable[[], dict[str, Any]]) -> dict[str, Any]:
    if key not in ctx.refs:
        t0 = time.perf_counter()
        print(f"  computing the reference for {key} ...", flush=True)
        ctx.refs[key] = fn()
        print(f"  ... {time.perf_counter() - t0:.1f} s", flush=True)
    return ctx.refs[key]


def _ref_sdof(ctx: Ctx, law: str) -> dict[str, Any]:
    return _reference(ctx, f"sdof/{law}", lambda: run_pounding_sdof_pair(
        law, ctx.motion, ctx.dt, duration=ctx.duration, reference=True, **SDOF))


def _ref_shear(ctx: Ctx) -> dict[str, Any]:
    return _reference(ctx, "shear/kelvin-voigt", lambda: run_pounding_shear_pair(
        ctx.motion, ctx.dt, duration=ctx.duration, reference=True, **SHEAR))


def section_compare(ctx: Ctx) -> None:
    header(f"Comparison at {1e3 * ctx.dt:g} ms (best of {ctx.repeat}; pounding: of at least "
           f"{ctx.repeat} runs spread over {MIN_TIMED_WINDOW:g} s or more)")
    if OURS_ERROR:
        print(OURS_ERROR)
        return
    m = ctx.motion
    cases = [
        ("SDOF pair, kelvin-voigt",
         lambda: ops_sdof("kelvin-voigt", m, ctx.dt, ctx.duration, ctx.repeat),
         lambda: run_pounding_sdof_pair("kelvin-voigt", m, ctx.dt, duration=ctx.duration,
                                        repeat=ctx.repeat, **SDOF),
         lambda: _ref_sdof(ctx, "kelvin-voigt")),
        ("SDOF pair, jankowski",
         lambda: ops_sdof("jankowski", m, ctx.dt, ctx.duration, ctx.repeat),
         lambda: run_pounding_sdof_pair("jankowski", m, ctx.dt, duration=ctx.duration,
                                        repeat=ctx.repeat, **SDOF),
         lambda: _ref_sdof(ctx, "jankowski")),
        (f"{SHEAR['n_storeys']}-storey pair, kelvin-voigt",
         lambda: ops_shear(m, ctx.dt, ctx.duration, ctx.repeat),
         lambda: run_pounding_shear_pair(m, ctx.dt, duration=ctx.duration, repeat=ctx.repeat,
                                         **SHEAR),
         lambda: _ref_shear(ctx)),
    ]
    rows = []
    for label, f_os, f_ours, f_ref in cases:
        try:
            ref = f_ref()
            r_ours = f_ours()
        except Exception as exc:  # the engine is still moving: report, go on with the rest
            print(f"  {label}: pounding failed: {type(exc).__name__}: {exc}")
            _figures.failure(f"{label}: pounding failed: {type(exc).__name__}: {exc}")
            continue
        r_os = f_os()
        F_ref, u1_ref, u2_ref, n_ref = _as_pair(ref)
        ratio_a = r_os["wall_analyze"] / r_ours["wall_analyze"]
        ratio_t = r_os["wall_total"] / r_ours["wall_total"]
        goal = ">= 100x" if label.startswith("SDOF") else ">= 50x"
        seconds = ctx.motion.duration if ctx.duration is None else ctx.duration
        case = f"{label}, El Centro {seconds:.0f} s, {1e3 * ctx.dt:g} ms"
        _figures.figure(f"{case}: time-stepping loop", r_ours["wall_analyze"],
                        _figures.opensees_name(), r_os["wall_analyze"],
                        ratio_meaning="OpenSees / pounding", goal=goal,
                        spread=f"best of {ctx.repeat} (pounding: runs over "
                               f">= {MIN_TIMED_WINDOW:g} s)")
        _figures.figure(f"{case}: whole call (model build + analysis)", r_ours["wall_total"],
                        _figures.opensees_name(), r_os["wall_total"],
                        ratio_meaning="OpenSees / pounding", spread=f"best of {ctx.repeat}")
        F_os, _, _, n_os = _as_pair(r_os)
        F_po, _, _, n_po = _as_pair(r_ours)
        _figures.note(f"{label}: peak contact force against the SciPy reference: OpenSees "
                      f"{pct(F_os, F_ref):+.3f} %, pounding {pct(F_po, F_ref):+.4f} %; impacts "
                      f"{n_os} / {n_po} (reference {n_ref})")
        for tool, r in (("OpenSees", r_os), ("pounding", r_ours)):
            F, u1, u2, nimp = _as_pair(r)
            rows.append([label, tool, f"{r['wall_analyze']:.4f}", f"{r['wall_total']:.4f}",
                         f"{1e6 * r['wall_analyze'] / r['n_steps']:.2f}",
                         f"{ratio_a:.1f} / {ratio_t:.1f}" if tool == "pounding" else "",
                         f"{pct(F, F_ref):+.3f}", f"{nimp} ({n_ref})",
                         f"{pct(u1, u1_ref):+.4f}", f"{pct(u2, u2_ref):+.4f}"])
        if np.ndim(ref["peak_force"]) > 0 and np.size(ref["peak_force"]) > 1:  # per floor
            for tool, r in (("OpenSees", r_os), ("pounding", r_ours)):
                e = [abs(pct(a, b)) for a, b in zip(r["peak_force"], ref["peak_force"]) if b > 0]
                print(f"  {label}, {tool}: worst per-floor peak-force error "
                      f"{max(e) if e else float('nan'):.3f} % over {len(e)} floors in contact")
        print(f"  {label}: reference Fmax {F_ref:.6g} N, {n_ref} impacts, "
              f"max|u| {u1_ref:.6f} / {u2_ref:.6f} m, reference wall {ref['wall_total']:.1f} s")
    table(rows, ["case", "tool", "analyze s", "total s", "µs/step", "ratio OS/ours",
                 "ΔFmax %", "impacts (ref)", "Δmax|u1| %", "Δmax|u2| %"])
    print("analyze = the time-stepping loop only (OpenSees: the analyze(1, dt) loop with its "
          "per-step reads; pounding: the compiled kernel's own timer); total = model build + "
          "analysis (pounding: the whole simulate() call, numba already compiled). "
          "ratio = OpenSees / pounding, analyze / total. Errors are against simulate_reference; "
          "for the shear pair, force = the largest over the floors and max|u| over all floors.")


def section_convergence(ctx: Ctx) -> None:
    header("Convergence: peak-force error against the reference vs the output step")
    if OURS_ERROR:
        print(OURS_ERROR)
        return
    steps = (2e-3, 1e-3, 5e-4, 2.5e-4)
    for law in osm.LAWS:
        ref = _ref_sdof(ctx, law)
        F_ref = float(ref["peak_force"])
        rows, errs_f, errs_u, prev = [], [], [], None
        for h in steps:
            r = ops_sdof(law, ctx.motion, h, ctx.duration)
            ours = run_pounding_sdof_pair(law, ctx.motion, h, duration=ctx.duration, repeat=1,
                                          **SDOF)
            err = abs(pct(r["peak_force"], F_ref))
            eu = history_error(r["time"], np.c_[r["u1"], r["u2"]], ref["time"],
                               np.c_[ref["u1"], ref["u2"]])
            eu_ours = history_error(ours["time"], np.c_[ours["u1"], ours["u2"]], ref["time"],
                                    np.c_[ref["u1"], ref["u2"]])
            order = f"{math.log2(prev / eu):.2f}" if prev and eu > 0 else ""
            prev = eu
            errs_f.append(err)
            errs_u.append(eu)
            rows.append([f"{1e3 * h:g}", f"{r['peak_force']:.6g}",
                         f"{pct(r['peak_force'], F_ref):+.4f}",
                         f"{r['n_impacts']} ({ref['n_impacts']})",
                         f"{pct(r['peak_u1'], ref['peak_u1']):+.4f}", f"{eu:.4f}", order,
                         f"{pct(ours['peak_force'], F_ref):+.5f}", f"{eu_ours:.5f}",
                         f"{ours['n_impacts']}"])
        print(f"SDOF pair, {law}: reference Fmax {F_ref:.8g} N")
        table(rows, ["dt ms", "OS Fmax N", "OS ΔFmax %", "OS impacts (ref)", "OS Δmax|u1| %",
                     "OS u err %", "order", "ours ΔFmax %", "ours u err %", "ours impacts"])
        print(f"  fitted order (slope of log error vs log dt): peak force "
              f"{fitted_order(steps, errs_f):.2f}, displacement history "
              f"{fitted_order(steps, errs_u):.2f}")
        print()
    print("u err = largest |u − u_ref| over the common output times, both buildings, in % of "
          "the reference's largest |u|; order = log2(u err(2h) / u err(h)) between successive "
          "rows. The peak-force error mixes the late contact onset (first order) with where "
          "the output grid falls on the force peak, so it need not fall monotonically.")


def history_error(t: np.ndarray, u: np.ndarray, t_ref: np.ndarray, u_ref: np.ndarray) -> float:
    """max |u − u_ref| at the times both grids share, in % of max |u_ref|."""
    dt, dt_ref = t[1] - t[0], t_ref[1] - t_ref[0]
    if dt >= dt_ref * (1 - 1e-9):
        idx = np.rint(t / dt_ref).astype(int)
        keep = idx < len(t_ref)
        a, b = u[keep], u_ref[idx[keep]]
    else:
        step = int(round(dt_ref / dt))
        a = u[::step]
        n = min(len(a), len(u_ref))
        a, b = a[:n], u_ref[:n]
    return 100.0 * float(np.max(np.abs(a - b)) / np.max(np.abs(u_ref)))


def fitted_order(steps: tuple[float, ...], errs: list[float]) -> float:
    e = np.asarray(errs, dtype=float)
    ok = e > 0
    if ok.sum() < 2:
        return float("nan")
    return float(np.polyfit(np.log(np.asarray(steps)[ok]), np.log(e[ok]), 1)[0])


def section_scaling(ctx: Ctx) -> None:
    header("Scaling of pounding: µs per step")
    if OURS_ERROR:
        print(OURS_ERROR)
        return
    m = ctx.motion
    rows = []
    per_floor: list[tuple[int, float]] = []
    for n in (1, 2, 5, 10, 20, 50):
        T1 = max(0.5, 0.1 * n)
        r = run_pounding_shear_pair(m, ctx.dt, duration=ctx.duration, repeat=ctx.repeat,
                                    n_storeys=n, mass=2e5, T1=T1, T2=1.5 * T1, zeta=0.05,
                                    gap=0.02, e=0.65)
        us = 1e6 * r["wall_analyze"] / r["n_steps"]
        rows.append([str(n), str(2 * n), f"{T1:g} / {1.5 * T1:g}", str(r["n_impacts"]),
                     f"{r['wall_analyze']:.4f}", f"{us:.2f}", f"{us / (2 * n):.3f}"])
        per_floor.append((n, 1e-6 * us / (2 * n)))
    for n, t in per_floor[1:]:
        _figures.figure(f"two {n}-storey buildings: time a step a floor", t,
                        "two SDOF oscillators (1 storey each)", per_floor[0][1],
                        ratio_meaning="pounding / peer", spread=f"best of {ctx.repeat}",
                        unit_note="seconds a step a floor")
    print("Two uniform n-storey buildings (T1 = max(0.5, 0.1 n) s, T2 = 1.5 T1), "
          "Kelvin-Voigt contact at every floor:")
    table(rows, ["storeys", "DOFs", "T1 / T2 s", "impacts", "analyze s", "µs/step",
                 "µs/step/DOF"])
    print()
    rows = []
    base = m if ctx.duration is None else GroundMotion(
        m.dt, m.accel[: int(round(ctx.duration / m.dt)) + 1], name=m.name)
    for rep in (1, 2, 4):
        tiled = GroundMotion(base.dt, np.tile(base.accel, rep), name=f"{base.name} x{rep}")
        r = run_pounding_shear_pair(tiled, ctx.dt, repeat=ctx.repeat, **SHEAR)
        rows.append([f"x{rep}", f"{tiled.duration:.2f}", str(r["n_steps"]), str(r["n_impacts"]),
                     f"{r['wall_analyze']:.4f}",
                     f"{1e6 * r['wall_analyze'] / r['n_steps']:.2f}"])
    print(f"{SHEAR['n_storeys']}-storey pair, record tiled:")
    table(rows, ["record", "duration s", "steps", "impacts", "analyze s", "µs/step"])
    per_step = [float(r[-1]) * 1e-6 for r in rows]
    for row, t in zip(rows[1:], per_step[1:]):
        _figures.figure(f"{SHEAR['n_storeys']}-storey pair, record tiled {row[0]}: time a step",
                        t, "the same pair on the record once (x1)", per_step[0],
                        ratio_meaning="pounding / peer",
                        spread=f"best of {ctx.repeat}", unit_note="seconds a step")


SECTIONS = {"sanity": section_sanity, "compare": section_compare,
            "convergence": section_convergence, "scaling": section_scaling}


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
    _figures.start("bench_opensees", "The time-stepping kernel against OpenSees")
    wanted = [s.strip() for s in args.sections.split(",") if s.strip()]
    bad = [s for s in wanted if s not in SECTIONS]
    if bad:
        ap.error(f"unknown section(s) {bad}; choose from {list(SECTIONS)}")

    kept = keep_freed_memory(args.fresh_memory)
    motion = el_centro()
    import platform

    from importlib.metadata import PackageNotFoundError, version

    try:
        ops_version = version("openseespy")
    except PackageNotFoundError:
        ops_version = "not installed"
    print(f"record: {motion.name}, {motion.npts} samples at {motion.dt} s, "
          f"{motion.duration if args.duration is None else args.duration:g} s used; "
          f"step {1e3 * args.dt:g} ms")
    print(f"python {platform.python_version()}, openseespy {ops_version}, "
          f"numpy {np.__version__}, {os.cpu_count()} CPUs "
          f"({platform.processor() or platform.machine()})")
    print("malloc: freed memory kept for reuse (mallopt)" if kept else
          "malloc: as configured (outputs may come as fresh pages, faulted in while timed)")
    if OURS_ERROR:
        print(OURS_ERROR)
    ctx = Ctx(motion, args.duration, args.repeat, args.dt, {})
    for s in wanted:
        try:
            SECTIONS[s](ctx)
        except Exception as exc:  # one broken section must not hide the others
            print(f"section {s} failed: {type(exc).__name__}: {exc}")
            _figures.failure(f"section {s}: {type(exc).__name__}: {exc}")
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""The fragility study of ``examples/fragility_two_10_storey.toml``: its cost with pounding and
with OpenSeesPy, per run on a subset of its runs, and the whole study end to end.

Run from the repository root, in a virtualenv holding both ``pounding`` and ``openseespy``
(see ``benchmarks/README.md``)::

    python benchmarks/bench_fragility.py                          # 3 records x 3 levels, ~3 min
    python benchmarks/bench_fragility.py --records 5 --levels 4 --repeat 5
    python benchmarks/bench_fragility.py --sections runs --no-reference

Sections:

runs    For a subset of the study's 200 runs (``--records`` records spread over the suite x
        ``--levels`` intensity levels spread over the range, first and last included), each
        run with pounding and with OpenSees on the same model. The model is the study's
        base model (``two_10_storey.toml``) built by pounding's own config loading, and each
        run's ground motion is the one the study runs: ``StudyCases.build(record, level)``
        (the record trimmed to 30 s and scaled to Sa(1.15 s, 5 %) = level by the study's
        own scaling). OpenSees gets the same floor masses, storey stiffnesses, Rayleigh
        coefficients (pounding's own ``RayleighDamping.coefficients``), Jankowski law
        (``JankowskiImpact``: pounding's ``nonlinear-viscoelastic`` has it in OpenSees) with
        pounding's k_h, ξ and m_eff per contact, the 40 mm gap, the same record samples and
        the 1 ms step (``opensees_models.run_opensees_building_pair``; a law without an
        OpenSees material there is refused). Timed, best of ``--repeat`` (the worst repeat
        printed beside it; pounding repeats at least ``--repeat`` times and as many more as
        fit in ``--pounding-window`` = 0.5 s, as in ``bench_opensees.py``: its runs take
        ~30 ms, and a best of three spanning 0.1 s is at the mercy of one burst of other
        work where OpenSees' three span seconds), each a whole run:

        * pounding: what a study run does — the run's model and motion from the study
          (``StudyCases.build``: config validation, the record's trimming and Sa scaling,
          redone every repeat), ``pounding.simulate`` and the study's measures of the run
          (``result_row``: also energies and floor accelerations, ~6 ms, which OpenSees is
          not asked for);
        * OpenSees: building the model, the analysis with the displacements and contact
          forces read every step (as ``bench_opensees.py``; impacts and drifts need them),
          and the same measures from those histories. The scaled motion is given to it,
          not timed: its ~1 ms is on pounding's side only;
        * OpenSees, analysis alone: the same model and one ``analyze(n, dt)`` call with
          nothing read — a lower bound no study could use (no peak, no impact).

        Also printed per run: the agreement of the peak contact force, the number of
        impacts and the peak storey drift ratio between the tools; then the serial cost of
        all 200 runs extrapolated from the subset (mean µs per output step x the steps of
        all 200 runs: the records are 25–30 s long), and pounding's measured: all 200 runs
        one after the other in this process, as a study's worker runs them (``run_case``).
reference
        One run of the subset (the middle one) also with ``simulate_reference`` (SciPy
        DOP853, rtol 1e-10, located contact events; about 45 s): each tool's error in the
        three measures.
study   ``pounding fragility STUDY.toml --out DIR`` as a user runs it (a fresh output
        folder each time, ``--study-repeat`` times, numba cache warm from the runs above),
        its wall time as a process, the command's own line (runs / gaps / analysis), the
        summed per-run times of its 200 runs (``wall_time_s`` of ``results.parquet``), all
        beside the OpenSees cost extrapolated for the 200 runs.

Numba compilation (or loading from its cache) is excluded from the per-run timings by an
untimed warm-up run of each tool. Not a test: nothing is asserted; run it on a quiet machine
and read the spreads (the load average is printed at the start and at the end).
"""

from __future__ import annotations

import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

import _figures
from _memory import keep_freed_memory  # noqa: E402
import opensees_models as osm  # noqa: E402
from _environment import load, parse_list, print_environment  # noqa: E402
from bench_opensees import header, pct, table  # noqa: E402

import pounding  # noqa: E402
from pounding.integrate import simulate  # noqa: E402
from pounding.integrate.reference import simulate_reference  # noqa: E402
from pounding.studies.fragility import study_cases  # noqa: E402
from pounding.studies.sweep.measures import result_row  # noqa: E402

STUDY = ROOT / "examples" / "fragility_two_10_storey.toml"
OUR_TO_OPENSEES = {"nonlinear-viscoelastic": "jankowski", "kelvin-voigt": "kelvin-voigt"}
"""pounding's law → the OpenSees material of ``opensees_models`` (``JankowskiImpact`` /
``ViscoelasticGap``); other laws have no OpenSees counterpart there."""
MIN_TIMED_WINDOW = 0.5
"""Seconds over which pounding's repeats of a run are spread at least (bench_opensees.py)."""
MAX_REPEAT = 50


# ===================================================================== printing
# (header, table and pct: bench_opensees.py's, imported above)


def spread(values: list[float], fmt: str = ".3f") -> str:
    """``best (worst)`` of timing repeats."""
    return f"{min(values):{fmt}} ({max(values):{fmt}})"


# ===================================================================== the model
@dataclass
class Mapping:
    """The study's base model as OpenSees arguments, with the checks that they agree."""

    kwargs: dict[str, Any]
    law: str
    rows: list[list[str]] = field(default_factory=list)
    worst_c: float = 0.0


def opensees_mapping(model: Any) -> Mapping:
    """OpenSees arguments for pounding's ``model`` (two shear buildings, floor-to-floor
    contacts, one law): masses, stiffnesses, Rayleigh a0 / a1 from pounding's own damping
    model, contact pairs, law parameters. Checks, and reports, that they give pounding's
    matrices and laws; refuses what ``run_opensees_building_pair`` cannot build."""
    if len(model.buildings) != 2 or any(b.storey_law is not None for b in model.buildings):
        raise ValueError("needs two linear shear buildings")
    spec = model.contact
    if spec.law not in OUR_TO_OPENSEES:
        raise ValueError(f"contact law {spec.law!r} has no OpenSees counterpart in "
                         "opensees_models (ViscoelasticGap, JankowskiImpact)")
    if spec.law == "kelvin-voigt" and not spec.tension:
        raise ValueError("ViscoelasticGap's dashpot may pull before the gap reopens: "
                         "pounding's kelvin-voigt matches it with tension = true only")
    if len(set(model.gaps)) != 1:
        raise ValueError("needs one gap")
    bl, br = model.buildings
    ray, c_blocks = [], []
    for b in (bl, br):
        M, K = osm.shear_matrices(b.masses, b.stiffnesses)
        a0, a1 = b.damping.coefficients(M, K)
        ray.append((float(a0), float(a1)))
        c_blocks.append(a0 * M + a1 * K)
    # pounding's assembled damping matrix must be the block diagonal of a0 M + a1 K
    C = np.asarray(model.system.C)
    n1 = bl.n
    C_os = np.zeros_like(C)
    C_os[:n1, :n1], C_os[n1:, n1:] = c_blocks
    worst_c = float(np.max(np.abs(C - C_os)) / np.max(np.abs(C)))
    cdof, cw = model.contact_kinematics()
    pairs = []
    for c, d, w in zip(model.contacts, cdof, cw):
        # floor-to-floor: +1 on a left floor, −1 on a right floor
        if not (d[0] == d[1] and d[2] == d[3] and w[0] == 1.0 and w[2] == -1.0
                and w[1] == 0.0 and w[3] == 0.0 and d[0] < n1 <= d[2]):
            raise ValueError(f"contact {c.index} is not floor to floor: {d}, {w}")
        pairs.append((int(d[0]), int(d[2]) - n1))
    law = OUR_TO_OPENSEES[spec.law]
    e = float(spec.e)
    rows = []
    worst_law = 0.0
    for c, (i, j) in zip(model.contacts, pairs):
        m_eff = osm.m_effective(bl.masses[i], br.masses[j])
        if law == "jankowski":
            ours = (c.law.k_h, c.law.zeta, c.law.m_eff)
            theirs = (spec.k_h, osm.zeta_jankowski(e), m_eff)
        else:
            ours = (c.law.k, c.law.c)
            theirs = (spec.k, osm.kv_dashpot(spec.k, e, bl.masses[i], br.masses[j]))
        worst_law = max(worst_law, max(abs(pct(a, b)) for a, b in zip(theirs, ours)))
    c0 = model.contacts[0].law
    if law == "jankowski":
        rows.append(["contact law", f"nonlinear-viscoelastic k_h {c0.k_h:.4g} N/m^1.5, "
                     f"ζ {c0.zeta:.6f}, m_eff {c0.m_eff:.6g} kg",
                     f"JankowskiImpact Kh {spec.k_h:.4g}, ξ {osm.zeta_jankowski(e):.6f}, "
                     f"mEff {osm.m_effective(bl.masses[0], br.masses[0]):.6g}, n 1.5"])
    else:
        rows.append(["contact law", f"kelvin-voigt k {c0.k:.4g}, c {c0.c:.6g}",
                     f"ViscoelasticGap K {spec.k:.4g}, C "
                     f"{osm.kv_dashpot(spec.k, e, bl.masses[0], br.masses[0]):.6g}"])
    rows.append(["  largest difference, all contacts", "", f"{worst_law:.1e} %"])
    rows.append(["contacts", f"{len(pairs)}, floor i to floor i", f"{len(pairs)} zeroLength"])
    rows.append(["gap", f"{1e3 * model.gaps[0]:g} mm", f"{-1e3 * model.gaps[0]:g} mm (negative)"])
    for name, b, (a0, a1) in (("left", bl, ray[0]), ("right", br, ray[1])):
        rows.append([f"{name}: {b.name}", f"{b.n} floors, m {b.masses[0]:.4g} kg, "
                     f"k {b.stiffnesses[0]:.4g} N/m",
                     f"a0 {a0:.6f} 1/s (region -rayleigh), a1 {a1:.6e} s (Elastic eta)"])
    rows.append(["damping matrix", "model.system.C", f"a0 M + a1 K: max diff {worst_c:.1e} "
                 "of max |C|"])
    kwargs = dict(left=(bl.masses, bl.stiffnesses), right=(br.masses, br.stiffnesses),
                  rayleigh=ray, contacts=pairs, gap=float(model.gaps[0]), e=e, law=law)
    if law == "jankowski":
        kwargs.update(k_h=float(spec.k_h), n_exp=float(spec.n))
    else:
        kwargs.update(k=float(spec.k))
    return Mapping(kwargs, law, rows, worst_c)


# ===================================================================== one run
def measures_opensees(r: dict[str, Any], heights: tuple[np.ndarray, np.ndarray]
                      ) -> dict[str, float]:
    """The study's measures from OpenSees' histories at the output steps: impacts (runs
    of nonzero force), peak contact force, peak storey drift ratio (as ``result_row``)."""
    drift = 0.0
    for u, h in ((r["u_left"], heights[0]), (r["u_right"], heights[1])):
        d = np.abs(np.diff(u, axis=1, prepend=0.0)).max(axis=0)
        drift = max(drift, float(np.max(d / h)))
    return {"n_impacts": int(r["n_impacts"]), "peak_contact_force_N": float(r["peak_force"].max()),
            "peak_drift_ratio": drift}


@dataclass
class Run:
    record: int
    level: float
    name: str
    duration: float
    scale: float
    n_steps: int
    ours: list[float] = field(default_factory=list)
    os_read: list[float] = field(default_factory=list)
    os_bare: list[float] = field(default_factory=list)
    row: dict[str, Any] = field(default_factory=dict)
    os_row: dict[str, float] = field(default_factory=dict)
    retried: int = 0
    failed: int = 0


def _clear_scaled_records() -> None:
    """Forget the scaled motions made so far (``pounding.config.record.RECORDS``), so that
    every timed pounding repeat trims and scales its record as the study's run does once.
    The parsed record files stay cached, as they do in a study's worker (one parse per
    record for its 20 levels)."""
    from pounding.config.record import RECORDS

    RECORDS.clear()


def run_pounding(cases: Any, record: int, level: float) -> tuple[dict[str, Any], Any]:
    model, motion, solver = cases.build(record, level)
    res = simulate(model, motion, **solver)
    return result_row(res), (model, motion, solver)


def run_opensees(mapping: Mapping, motion: Any, dt: float, duration: float,
                 heights: tuple[np.ndarray, np.ndarray], reads: bool = True
                 ) -> tuple[float, dict[str, Any], dict[str, float] | None]:
    t0 = time.perf_counter()
    r = osm.run_opensees_building_pair(motion.accel, motion.dt, dt, duration=duration,
                                       reads=reads, **mapping.kwargs)
    row = measures_opensees(r, heights) if reads else None
    return time.perf_counter() - t0, r, row


def pick(n_total: int, n: int) -> list[int]:
    """``n`` indices spread evenly over ``range(n_total)``, first and last included."""
    n = max(1, min(n, n_total))
    if n == 1:
        return [n_total // 2]
    return sorted({int(round(x)) for x in np.linspace(0, n_total - 1, n)})


# ===================================================================== sections
@dataclass
class Ctx:
    cases: Any
    mapping: Mapping
    repeat: int
    n_records: int
    n_levels: int
    study_repeat: int
    study: str
    window: float
    runs: list[Run] = field(default_factory=list)
    all_steps: int = 0
    extrapolated: dict[str, float] = field(default_factory=dict)
    """Serial seconds of all the study's runs per tool, from the subset (best repeats)."""
    serial_ours: float = math.nan
    """Seconds of all the study's runs with pounding, one after the other, measured."""


def section_runs(ctx: Ctx) -> None:
    cases = ctx.cases
    recs, levs = pick(len(cases.records), ctx.n_records), pick(len(cases.levels), ctx.n_levels)
    header(f"Runs of the study: {len(recs)} records x {len(levs)} levels (best of "
           f"{ctx.repeat}, pounding of at least {ctx.repeat} spread over {ctx.window:g} s; "
           f"the worst repeat in brackets)")
    model0, _, solver0 = cases.build(0, cases.levels[0])
    heights = tuple(np.asarray(b.heights, dtype=float) for b in model0.buildings)
    dt = float(solver0["dt"])
    if solver0.get("duration") is not None:
        raise SystemExit("the base model sets [solver] duration: not handled here")
    # warm-up, untimed: numba's kernel (compiled, or loaded from its cache), OpenSees' import
    t0 = time.perf_counter()
    _, (_, motion, _) = run_pounding(cases, recs[0], cases.levels[levs[-1]])
    warm = time.perf_counter() - t0
    run_opensees(ctx.mapping, motion, dt, 1.0, heights)
    print(f"(warm-up, untimed: pounding's first run {warm:.2f} s — numba's kernel "
          f"{'compiled' if warm > 5 else 'loaded from its cache'})")
    for ri in recs:
        for li in levs:
            x = cases.levels[li]
            _, motion, _ = cases.build(ri, x)
            run = Run(ri, x, cases.records[ri], motion.duration,
                      float(motion.metadata.get("scale_factor", float("nan"))),
                      int(round(motion.duration / dt)))
            # at least --repeat runs, and as many more as fit in --pounding-window seconds
            # (as bench_opensees.py: a best of three 30 ms runs is at the mercy of one
            # burst of other work, where OpenSees' three repeats span seconds)
            t_start = time.perf_counter()
            while (len(run.ours) < ctx.repeat or (time.perf_counter() - t_start < ctx.window
                                                  and len(run.ours) < MAX_REPEAT)):
                _clear_scaled_records()
                t0 = time.perf_counter()
                row, (_, motion, _) = run_pounding(cases, ri, x)
                run.ours.append(time.perf_counter() - t0)
            run.row = row
            for _ in range(ctx.repeat):
                w, r, os_row = run_opensees(ctx.mapping, motion, dt, motion.duration, heights)
                run.os_read.append(w)
                run.retried, run.failed = r["retried"], r["failed"]
                run.os_row = os_row
            for _ in range(ctx.repeat):
                w, r, _ = run_opensees(ctx.mapping, motion, dt, motion.duration, heights,
                                       reads=False)
                run.os_bare.append(w)
                run.failed = max(run.failed, r["failed"])
            ctx.runs.append(run)
            _figures.figure(f"{run.name[:30]} at {x:.4g} g: one study run (build, simulate, "
                            f"measures)", min(run.ours), _figures.opensees_name(),
                            min(run.os_read), ratio_meaning="OpenSees / pounding",
                            spread=f"best of {len(run.ours)} / {len(run.os_read)}")
            print(f"  {run.name[:24]:24s} {x:.4f} g: pounding {min(run.ours):.3f} s, "
                  f"OpenSees {min(run.os_read):.3f} s", flush=True)

    rows = []
    for r in ctx.runs:
        rows.append([r.name[:30], f"{r.level:.4g}", f"{r.scale:.4g}", f"{r.duration:g}",
                     f"{spread(r.ours)} x{len(r.ours)}", spread(r.os_read), spread(r.os_bare),
                     f"{min(r.os_read) / min(r.ours):.1f}",
                     f"{min(r.os_bare) / min(r.ours):.1f}",
                     f"{r.row['n_impacts']} / {r.os_row['n_impacts']}",
                     f"{r.row['peak_contact_force_N'] / 1e6:.4g}",
                     f"{pct(r.os_row['peak_contact_force_N'], r.row['peak_contact_force_N']):+.3f}"
                     if r.row["peak_contact_force_N"] > 0 else "-",
                     f"{100 * r.row['peak_drift_ratio']:.4f}",
                     f"{pct(r.os_row['peak_drift_ratio'], r.row['peak_drift_ratio']):+.4f}",
                     f"{r.retried}/{r.failed}"])
    table(rows, ["record", "Sa g", "factor", "dur s", "pounding s", "OpenSees s",
                 "OS analysis alone s", "ratio", "ratio (alone)", "impacts ours/OS",
                 "Fmax MN", "OS ΔFmax %", "drift %", "OS Δdrift %", "OS retried/failed"])
    ratio = [min(r.os_read) / min(r.ours) for r in ctx.runs]
    ratio_bare = [min(r.os_bare) / min(r.ours) for r in ctx.runs]
    print(f"ratio OpenSees / pounding per run: {min(ratio):.1f}–{max(ratio):.1f} "
          f"(median {np.median(ratio):.1f}); OpenSees' analysis alone against pounding's "
          f"whole run: {min(ratio_bare):.1f}–{max(ratio_bare):.1f}")
    dF = [abs(pct(r.os_row["peak_contact_force_N"], r.row["peak_contact_force_N"]))
          for r in ctx.runs if r.row["peak_contact_force_N"] > 0]
    dD = [abs(pct(r.os_row["peak_drift_ratio"], r.row["peak_drift_ratio"])) for r in ctx.runs]
    same = sum(r.row["n_impacts"] == r.os_row["n_impacts"] for r in ctx.runs)
    print(f"agreement: impacts equal in {same} of {len(ctx.runs)} runs; |ΔFmax| ≤ "
          f"{max(dF) if dF else float('nan'):.3f} % ({len(dF)} runs with contact); "
          f"|Δdrift| ≤ {max(dD):.4f} %")
    _figures.note(f"ratio OpenSees / pounding per run: {min(ratio):.1f}-{max(ratio):.1f}x "
                  f"(median {np.median(ratio):.1f}); impacts equal in {same} of "
                  f"{len(ctx.runs)} runs; |peak force difference| <= "
                  f"{max(dF) if dF else float('nan'):.3f} %, |drift difference| <= "
                  f"{max(dD):.4f} %")
    print("pounding = StudyCases.build + simulate + result_row (what a study run does, its "
          "record scaled afresh each repeat); OpenSees = model build + analyze(1, dt) loop "
          "reading 20 displacements and 10 forces a step + the measures; 'analysis alone' = "
          "model build + one analyze(n, dt), nothing read. Fmax: pounding's located peak, "
          "OpenSees' largest at an output step; impacts: pounding's count, OpenSees' runs of "
          "nonzero force at the output steps; drift: largest storey drift / height at the "
          "output steps, both. Δ = OpenSees − pounding.")

    # the serial cost of the whole study, from the subset
    steps = 0
    for ri in range(len(cases.records)):
        _, m, _ = cases.build(ri, cases.levels[0])
        steps += int(round(m.duration / dt)) * len(cases.levels) * len(cases.gaps)
    ctx.all_steps = steps
    n_all = len(cases.sweep.cases)
    print()
    print(f"The whole study serially: {n_all} runs, {steps:,} output steps in all; from the "
          f"subset's mean µs per output step (best / worst repeat):")
    rows = []
    for label, attr in (("pounding", "ours"), ("OpenSees", "os_read"),
                        ("OpenSees, analysis alone", "os_bare")):
        per = [getattr(r, attr) for r in ctx.runs]
        us_best = np.mean([min(t) / r.n_steps for t, r in zip(per, ctx.runs)]) * 1e6
        us_worst = np.mean([max(t) / r.n_steps for t, r in zip(per, ctx.runs)]) * 1e6
        rows.append([label, f"{us_best:.2f} ({us_worst:.2f})",
                     f"{us_best * 1e-6 * steps:.1f} ({us_worst * 1e-6 * steps:.1f})",
                     f"{us_best * 1e-6 * steps / 60:.2f}"])
    table(rows, ["tool", "µs/step", f"{n_all} runs s", "min"])
    ctx.extrapolated = {row[0]: float(row[2].split()[0]) for row in rows}

    # pounding's side measured rather than extrapolated: every run of the study, serially
    from pounding.studies.sweep.execute import run_case

    sw = cases.sweep
    t0 = time.perf_counter()
    bad = 0
    for case in sw.cases:
        row, _ = run_case(sw.base, sw.base_dir, sw.params, case.values)
        bad += row["status"] != "ok"
    ctx.serial_ours = time.perf_counter() - t0
    print(f"pounding, all {len(sw.cases)} runs measured serially in this process (run_case, "
          f"as a study's worker runs them): {ctx.serial_ours:.1f} s"
          f"{f', {bad} failed' if bad else ''}; OpenSees / pounding "
          f"{ctx.extrapolated['OpenSees'] / ctx.serial_ours:.0f}x on that")
    _figures.figure(f"all {len(sw.cases)} runs of the study serially in one process",
                    ctx.serial_ours, f"{_figures.opensees_name()} (extrapolated from the subset)",
                    ctx.extrapolated["OpenSees"], ratio_meaning="OpenSees / pounding",
                    unit_note="pounding measured; OpenSees from its mean time a step")


def section_reference(ctx: Ctx) -> None:
    if not ctx.runs:
        print("\n(reference: needs the runs section)")
        return
    run = ctx.runs[len(ctx.runs) // 2]
    header(f"Against simulate_reference: {run.name}, Sa {run.level:.4g} g")
    model, motion, solver = ctx.cases.build(run.record, run.level)
    t0 = time.perf_counter()
    ref = result_row(simulate_reference(model, motion, dt=solver["dt"],
                                        duration=solver["duration"]))
    wall = time.perf_counter() - t0
    rows = []
    for tool, row in (("pounding", run.row), ("OpenSees", run.os_row)):
        rows.append([tool, f"{row['n_impacts']} ({ref['n_impacts']})",
                     f"{pct(row['peak_contact_force_N'], ref['peak_contact_force_N']):+.4f}"
                     if ref["peak_contact_force_N"] > 0 else "-",
                     f"{pct(row['peak_drift_ratio'], ref['peak_drift_ratio']):+.5f}"])
    table(rows, ["tool", "impacts (reference)", "ΔFmax %", "Δdrift %"])
    print(f"reference: {ref['n_impacts']} impacts, Fmax {ref['peak_contact_force_N']:.7g} N, "
          f"drift {100 * ref['peak_drift_ratio']:.6f} %, {wall:.1f} s (SciPy DOP853, rtol "
          f"1e-10, located events)")


_LINE = re.compile(r"([\d.]+) s \(runs ([\d.]+) s, gaps ([\d.]+) s, analysis and files "
                   r"([\d.]+) s\)")


def section_study(ctx: Ctx) -> None:
    study = Path(ctx.study)
    exe = Path(sys.executable).parent / "pounding"
    cmd = [str(exe)] if exe.exists() else [sys.executable, "-m", "pounding"]
    env = dict(os.environ)
    src = str(Path(pounding.__file__).resolve().parents[1])
    env["PYTHONPATH"] = os.pathsep.join([src, env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    header(f"The study end to end: {Path(cmd[0]).name} fragility {study.name} --out DIR "
           f"({ctx.study_repeat} x, a fresh DIR each)")
    check = subprocess.run([sys.executable, "-c", "import pounding; print(pounding.__file__)"],
                           env=env, capture_output=True, text=True, check=True).stdout.strip()
    print(f"pounding of the command: {check}")
    rows, walls = [], []
    for i in range(ctx.study_repeat):
        out = Path(tempfile.mkdtemp(prefix="bench-fragility-"))
        shutil.rmtree(out)  # fresh: the command creates it
        before = load()
        t0 = time.perf_counter()
        p = subprocess.run([*cmd, "fragility", str(study), "--out", str(out)], env=env,
                           capture_output=True, text=True, cwd=ROOT)
        wall = time.perf_counter() - t0
        if p.returncode != 0:
            print(f"run {i + 1} failed ({p.returncode}):\n{p.stdout[-2000:]}\n{p.stderr[-2000:]}")
            shutil.rmtree(out, ignore_errors=True)
            continue
        walls.append(wall)
        m = _LINE.search(" ".join(p.stdout.split()))
        inside = [float(g) for g in m.groups()] if m else [float("nan")] * 4
        serial = float("nan")
        try:
            import pandas as pd

            t = pd.read_parquet(out / "results.parquet")
            serial = float(t["wall_time_s"].sum())
            n_ok = int((t["status"] == "ok").sum())
        except Exception as exc:  # noqa: BLE001  (report, go on)
            print(f"  results.parquet not read: {type(exc).__name__}: {exc}")
            n_ok = -1
        rows.append([str(i + 1), f"{wall:.1f}", f"{inside[0]:.1f}", f"{inside[1]:.1f}",
                     f"{inside[2]:.1f}", f"{inside[3]:.1f}", f"{serial:.1f}", str(n_ok),
                     before])
        shutil.rmtree(out, ignore_errors=True)
    table(rows, ["run", "process s", "command s", "runs s", "gaps s", "analysis s",
                 "Σ run times s", "runs ok", "before it"])
    print("process = the whole command as a process (Python start-up, imports, Dask's workers, "
          "the runs, gap study, analysis, figures); command/runs/gaps/analysis = the "
          "command's own last line; Σ run times = the 200 runs' wall_time_s in "
          "results.parquet, summed (two workers at once: a run's time includes waiting for a "
          "core held by the other worker or other jobs).")
    ext = ctx.extrapolated
    if walls:
        _figures.figure(f"pounding fragility {study.name} end to end, as a process",
                        min(walls),
                        f"{_figures.opensees_name()}: the study's runs alone, serially "
                        f"(extrapolated)" if ext else "no peer measured",
                        ext["OpenSees"] if ext else float("nan"),
                        ratio_meaning="OpenSees / pounding", met=min(walls) <= 20.0,
                        goal="<= 20 s end to end",
                        spread=f"best of {len(walls)}; {min(walls):.1f}-{max(walls):.1f} s")
    if walls and ext:
        ours = (f"; its {len(ctx.cases.sweep.cases)} runs serially in one process "
                f"{ctx.serial_ours:.1f} s" if ctx.serial_ours == ctx.serial_ours else "")
        print(f"end to end {min(walls):.1f}–{max(walls):.1f} s with pounding (goal ≤ 20 s"
              f"{ours}); the 200 runs alone with OpenSees, serially, extrapolated: "
              f"{ext['OpenSees']:.0f} s ({ext['OpenSees'] / 60:.1f} min; analysis alone "
              f"{ext['OpenSees, analysis alone']:.0f} s), i.e. "
              f"{ext['OpenSees'] / min(walls):.0f}x pounding's whole study end to end "
              f"({ext['OpenSees'] / 2 / min(walls):.0f}x if OpenSees' runs were spread over "
              f"both cores with no overhead)")


SECTIONS = {"runs": section_runs, "reference": section_reference, "study": section_study}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--study", default=str(STUDY), help="the study file (default: the example)")
    ap.add_argument("--sections", default=",".join(SECTIONS),
                    help=f"comma-separated, from {', '.join(SECTIONS)} (default: all)")
    ap.add_argument("--records", type=int, default=3,
                    help="records of the suite, spread evenly, first and last included (3)")
    ap.add_argument("--levels", type=int, default=3,
                    help="intensity levels, spread evenly, first and last included (3)")
    ap.add_argument("--repeat", type=int, default=3, help="timing repeats per run, best kept (3)")
    ap.add_argument("--pounding-window", type=float, default=MIN_TIMED_WINDOW,
                    help="pounding repeats a run at least --repeat times and as many more as "
                         f"fit in this many seconds ({MIN_TIMED_WINDOW:g}; 0: --repeat times)")
    ap.add_argument("--study-repeat", type=int, default=2,
                    help="end-to-end runs of the study (2)")
    ap.add_argument("--no-reference", action="store_true",
                    help="skip simulate_reference (about 45 s) even if the section is asked")
    ap.add_argument("--fresh-memory", action="store_true",
                    help="leave glibc's malloc as it is (default: keep freed memory for reuse, "
                         "see benchmarks/_memory.py)")
    _figures.add_json_option(ap)
    args = ap.parse_args(argv)
    _figures.start("bench_fragility", "The fragility study against OpenSees")
    wanted = parse_list(ap, args.sections, SECTIONS)
    if args.no_reference and "reference" in wanted:
        wanted.remove("reference")

    kept = keep_freed_memory(args.fresh_memory)
    print_environment(kept)

    cases = study_cases(args.study, out=tempfile.gettempdir())
    model, motion, solver = cases.build(0, cases.levels[0])
    mapping = opensees_mapping(model)
    print(f"study: {args.study}, base {cases.config.base}: {len(cases.records)} records x "
          f"{len(cases.levels)} levels of {cases.im_label} ({cases.levels[0]:g} … "
          f"{cases.levels[-1]:g}) = {len(cases.sweep.cases)} runs; step {1e3 * solver['dt']:g} "
          f"ms, rtol {solver['rtol']:g}; records trimmed to {cases.config.suite.duration} s")
    header("The model in both tools")
    table(mapping.rows, ["", "pounding (the study's base model)", "OpenSees"])

    ctx = Ctx(cases, mapping, args.repeat, args.records, args.levels, args.study_repeat,
              args.study, args.pounding_window)
    for s in wanted:
        SECTIONS[s](ctx)
    print()
    print(f"at the end: {load()}")
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

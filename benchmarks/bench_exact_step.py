"""The kernel's exact step against a hand-written numba loop with the same outputs
(issue 30: "The kernel's exact step within 2× of the hand-written loop with the same
outputs").

The model: the seed SDOF pair (``examples/seed_sdof_pair.toml``) with a 10 m gap, so that
no contact closes and every one of El Centro's 40,000 steps of 1 ms is an exact step.

* **pounding**: ``simulate()``'s own timer (``Result.wall_time``, the compiled kernel alone)
  over the steps, best of ``--repeat`` after a warm-up.
* **hand loop, same outputs**: each floor's exact step by the Nigam–Jennings coefficients
  (written here from the closed form of the damped oscillator, not from pounding), and per
  step what the kernel writes: displacement, velocity and absolute acceleration of each
  floor, the gap's opening, the energies (input by the trapezoid of ``−m a_g v``, kinetic,
  strain, viscous by difference) and the peaks |u|, |v|, |a| — checked to agree with
  pounding's displacements to 1e-9 of their peak.
* **hand loop, bare**: the two floors' exact steps writing the displacements only.

A measurement, not a test. Prints ns a step and the ratio pounding / hand loop, with the
spread over ``--rounds`` rounds; ``--json PATH`` writes the figures
(``benchmarks/_figures.py``, read by ``benchmarks/run_all.py``).

    python benchmarks/bench_exact_step.py --rounds 3
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from pathlib import Path

import numpy as np
from numba import njit

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import _figures  # noqa: E402
from _environment import load, print_environment  # noqa: E402

SEED = ROOT / "examples" / "seed_sdof_pair.toml"


def coefficients(omega: float, zeta: float, h: float) -> tuple[float, ...]:
    """One exact step of ``ü + 2ζωu̇ + ω²u = −a_g`` with ``a_g`` linear over the step:
    ``u1 = a11 u + a12 v + b11 a0 + b12 a1`` and ``v1`` likewise (Nigam & Jennings 1969;
    Chopra, Dynamics of Structures, §5.2), from the free response and the responses to a
    unit step and a unit ramp of force, in closed form."""
    wd = omega * math.sqrt(1.0 - zeta * zeta)
    s = zeta * omega
    e = math.exp(-s * h)
    c, sn = math.cos(wd * h), math.sin(wd * h)
    # free response: u(h) from (1, 0) and from (0, 1), and their velocities
    a11 = e * (c + s / wd * sn)
    a12 = e * sn / wd
    a21 = -omega * omega * e * sn / wd
    a22 = e * (c - s / wd * sn)
    w2 = omega * omega
    # response at rest to a unit force step (f = 1) and ramp (f = τ/h) over the step
    step_u = (1.0 - a11) / w2
    step_v = -a21 / w2
    ramp_u = (h - 2.0 * s / w2 - (a12 - 2.0 * s / w2 * a11)) / (w2 * h)
    ramp_v = (1.0 - a22 - 2.0 * s * (-a21) / w2) / (w2 * h)
    # a_g = a0 (1 − τ/h) + a1 τ/h, force −a_g
    b11 = -(step_u - ramp_u)
    b12 = -ramp_u
    b21 = -(step_v - ramp_v)
    b22 = -ramp_v
    return a11, a12, a21, a22, b11, b12, b21, b22


@njit(cache=True)
def bare_loop(co, ag, u_out):  # pragma: no cover - compiled
    """Both floors' exact steps, the displacements written: nothing else."""
    n = co.shape[0]
    u = np.zeros(n)
    v = np.zeros(n)
    for k in range(ag.shape[0] - 1):
        a0 = ag[k]
        a1 = ag[k + 1]
        for i in range(n):
            u1 = co[i, 0] * u[i] + co[i, 1] * v[i] + co[i, 4] * a0 + co[i, 5] * a1
            v1 = co[i, 2] * u[i] + co[i, 3] * v[i] + co[i, 6] * a0 + co[i, 7] * a1
            u[i] = u1
            v[i] = v1
            u_out[k + 1, i] = u1


@njit(cache=True)
def full_loop(co, mass, k_s, c_s, gap, h, ag, u_out, v_out, a_out, pen_out, e_out,
              peaks):  # pragma: no cover - compiled
    """The exact steps with the kernel's outputs: u, v, absolute acceleration, the gap's
    opening, the energies (input, kinetic, strain, viscous) and the peaks |u|, |v|, |a|."""
    n = co.shape[0]
    u = np.zeros(n)
    v = np.zeros(n)
    e_in = 0.0
    for k in range(ag.shape[0] - 1):
        a0 = ag[k]
        a1 = ag[k + 1]
        ek = 0.0
        es = 0.0
        w_in = 0.0
        for i in range(n):
            u1 = co[i, 0] * u[i] + co[i, 1] * v[i] + co[i, 4] * a0 + co[i, 5] * a1
            v1 = co[i, 2] * u[i] + co[i, 3] * v[i] + co[i, 6] * a0 + co[i, 7] * a1
            acc = -(k_s[i] * u1 + c_s[i] * v1) / mass[i]
            w_in -= 0.5 * mass[i] * (a0 * v[i] + a1 * v1)
            u[i] = u1
            v[i] = v1
            u_out[k + 1, i] = u1
            v_out[k + 1, i] = v1
            a_out[k + 1, i] = acc
            ek += 0.5 * mass[i] * v1 * v1
            es += 0.5 * k_s[i] * u1 * u1
            if abs(u1) > peaks[i, 0]:
                peaks[i, 0] = abs(u1)
            if abs(v1) > peaks[i, 1]:
                peaks[i, 1] = abs(v1)
            if abs(acc) > peaks[i, 2]:
                peaks[i, 2] = abs(acc)
        pen_out[k + 1] = u[0] - u[1] - gap
        e_in += w_in * h
        e_out[k + 1, 0] = e_in
        e_out[k + 1, 1] = ek
        e_out[k + 1, 2] = es
        e_out[k + 1, 3] = e_in - (ek + es)


def best_per_step(fn, steps: int, min_time: float = 0.3) -> float:
    """Best seconds a step of ``fn()`` over repeats filling at least ``min_time``."""
    best = math.inf
    spent = 0.0
    while spent < min_time:
        t0 = time.perf_counter()
        fn()
        dt = time.perf_counter() - t0
        spent += dt
        best = min(best, dt)
    return best / steps


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=3, help="rounds, alternating (3)")
    _figures.add_json_option(ap)
    args = ap.parse_args()

    from pounding.allocator import keep_freed_memory
    from pounding.config import load_config
    from pounding.integrate import simulate
    from pounding.model import PoundingModel

    keep_freed_memory()
    print_environment(kept_memory=True)
    model, motion, solver = load_config(SEED).build()
    model = PoundingModel(model.buildings, [10.0], model.contact, name="seed pair, 10 m gap")
    res = simulate(model, motion, **solver)
    steps = res.time.size - 1
    assert res.n_impacts == 0
    h = float(solver.get("dt", motion.dt))
    # the record linear between its samples, at the run's steps (as the kernel takes it)
    ag = np.ascontiguousarray(motion.accel_at(np.asarray(res.time)), dtype=np.float64)
    mass = np.array([b.masses[0] for b in model.buildings], dtype=float)
    k_s = np.array([b.stiffnesses[0] for b in model.buildings], dtype=float)
    omega = np.sqrt(k_s / mass)
    c_s = np.array([float(b.damping_matrix()[0, 0]) for b in model.buildings])
    zeta = float(c_s[0] / (2.0 * omega[0] * mass[0]))
    assert np.allclose(c_s / (2.0 * omega * mass), zeta, rtol=1e-12)  # 5 % each
    co = np.array([coefficients(float(w), zeta, h) for w in omega])  # (2, 8)
    u_out = np.zeros((steps + 1, 2))
    v_out = np.zeros_like(u_out)
    a_out = np.zeros_like(u_out)
    pen_out = np.zeros(steps + 1)
    e_out = np.zeros((steps + 1, 4))
    peaks = np.zeros((2, 3))
    full_loop(co, mass, k_s, c_s, 10.0, h, ag, u_out, v_out, a_out, pen_out, e_out, peaks)
    bare_loop(co, ag, u_out)
    ours = np.asarray(res.displacement)[:, [0, 1]]
    err = float(np.max(np.abs(u_out - ours)) / np.max(np.abs(ours)))
    print(f"{steps} steps of {1e3 * h:g} ms; hand loop's displacements against pounding's: "
          f"{err:.1e} of the peak")
    if not err < 1e-9:
        print("the hand loop does not reproduce pounding's run: no comparison")
        return 1

    rows: dict[str, list[float]] = {"pounding": [], "full": [], "bare": []}
    for _ in range(args.rounds):
        best = math.inf
        for _ in range(20):
            best = min(best, simulate(model, motion, **solver).wall_time)
        rows["pounding"].append(best / steps)
        rows["full"].append(best_per_step(lambda: full_loop(
            co, mass, k_s, c_s, 10.0, h, ag, u_out, v_out, a_out, pen_out, e_out, peaks), steps))
        rows["bare"].append(best_per_step(lambda: bare_loop(co, ag, u_out), steps))
    ns = {k: 1e9 * min(v) for k, v in rows.items()}
    ratio_full = [p / f for p, f in zip(rows["pounding"], rows["full"], strict=True)]
    ratio_bare = [p / f for p, f in zip(rows["pounding"], rows["bare"], strict=True)]
    print(f"\nns a step (best of {args.rounds} rounds; {load()}):")
    print(f"  pounding's exact step (kernel timer)      {ns['pounding']:6.1f}")
    print(f"  hand loop, the same outputs               {ns['full']:6.1f}")
    print(f"  hand loop, bare (displacements only)      {ns['bare']:6.1f}")
    print(f"pounding / hand loop with outputs: {min(ratio_full):.2f}–{max(ratio_full):.2f}× "
          f"(goal ≤ 2×: {'met' if max(ratio_full) <= 2.0 else 'MISSED'}); "
          f"/ bare: {min(ratio_bare):.2f}–{max(ratio_bare):.2f}×")
    _figures.start("bench_exact_step", "The exact step against a hand-written loop")
    _figures.figure("seed SDOF pair, 10 m gap, El Centro 40 s at 1 ms: one exact step",
                    min(rows["pounding"]), "hand-written numba loop with the same outputs",
                    min(rows["full"]), ratio_meaning="pounding / peer", goal="<= 2x",
                    met=max(ratio_full) <= 2.0,
                    spread=f"ratios {min(ratio_full):.2f}-{max(ratio_full):.2f} over "
                           f"{args.rounds} rounds",
                    unit_note="seconds a step")
    _figures.figure("the same, against the bare loop (displacements only)",
                    min(rows["pounding"]), "hand-written numba loop, bare", min(rows["bare"]),
                    ratio_meaning="pounding / peer",
                    spread=f"ratios {min(ratio_bare):.2f}-{max(ratio_bare):.2f}",
                    unit_note="seconds a step")
    _figures.note(f"the hand loop's displacements agree with pounding's to {err:.1e} of the "
                  "peak")
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    os.environ.setdefault("POUNDING_KEEP_FREED_MEMORY", "1")
    raise SystemExit(main())

"""Tall buildings: the exact step's set-up and a step without contact, modal against dense
(not a test: a measurement).

Issue 30's goals: a no-contact step of a 100-storey pair ≤ 10 µs and the propagator set-up
≤ 0.1 s for 50 storeys, results unchanged to 1e-12. The peer of each figure is the dense
route, measured in the same run, alternating with the modal one round by round:

* set-up: :func:`pounding.integrate.propagator.compute_free_step` of the 50-storey pair
  (Rayleigh 5 %, the shear pair of ``bench_opensees.py``) from the modes (the default for
  classically damped blocks of ≥ 16 floors) against ``modal_from=0`` (every block from the
  matrix exponentials: Van Loan integrals by ``scipy.linalg.expm``);
* step: ``simulate`` of the 100-storey pair under El Centro with a 10 m gap (no contact),
  the kernel's own time (``Result.stats.wall_time``) per grid step, modal against dense;
  and how far apart the two routes' histories are.

Run from the repository root::

    python benchmarks/bench_tall.py                  # 5 rounds, 1 ms steps, 20 s of El Centro
    python benchmarks/bench_tall.py --json tall.json # also the figures as data (run_all)
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _figures
from _environment import load
from _memory import keep_freed_memory
from bench_opensees import shear_pair_model

from pounding.ground_motion import el_centro
from pounding.integrate import modal_propagator, propagator, simulate
from pounding.integrate.kernel_model import kernel_model

SETUP_GOAL_S = 0.1
STEP_GOAL_S = 10e-6


def pair(n: int, gap: float) -> Any:
    """Two uniform n-storey shear buildings, T1 = 0.1 n s and 1.5 times that."""
    t1 = max(0.5, 0.1 * n)
    return shear_pair_model("kelvin-voigt", n_storeys=n, mass=2e5, T1=t1, T2=1.5 * t1,
                            zeta=0.05, gap=gap, e=0.65)


def setup_once(model: Any, h: float, modal: bool) -> float:
    """Seconds of one compute_free_step of the model, modal (default) or dense."""
    km = kernel_model(model)
    fl = km.floors
    m = np.diag(fl.m_diag)
    t0 = time.perf_counter()
    propagator.compute_free_step(m, km.C, km.K, fl.r, h, km.C_links,
                                 modal_from=None if modal else 0)
    return time.perf_counter() - t0


def route_model(n: int, gap: float, modal: bool, motion: Any, dt: float) -> Any:
    """A fresh model whose exact steps take the chosen route (its FreeStep is made by the
    first simulate and kept with the model)."""
    model = pair(n, gap)
    least = modal_propagator.MODAL_MIN_FLOORS
    try:
        modal_propagator.MODAL_MIN_FLOORS = least if modal else 0
        propagator._FREE_CACHE.clear()
        simulate(model, motion, dt=dt, duration=0.5)  # (compiles or loads the kernel)
    finally:
        modal_propagator.MODAL_MIN_FLOORS = least
        propagator._FREE_CACHE.clear()
    return model


def per_step(model: Any, motion: Any, dt: float, duration: float, repeat: int
             ) -> tuple[float, Any]:
    """Best kernel seconds per grid step over ``repeat`` runs, and the last result."""
    best = math.inf
    res = None
    for _ in range(repeat):
        res = simulate(model, motion, dt=dt, duration=duration)
        best = min(best, float(res.stats.wall_time) / (res.displacement.shape[0] - 1))
    return best, res


def spread(values: list[float], fmt: str = "{:.3g}") -> str:
    return f"{fmt.format(min(values))}–{fmt.format(max(values))}"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rounds", type=int, default=5, help="alternating rounds (5)")
    ap.add_argument("--repeat", type=int, default=3, help="runs a route and round, best kept")
    ap.add_argument("--dt", type=float, default=1e-3, help="grid (output) step [s] (1e-3)")
    ap.add_argument("--duration", type=float, default=20.0, help="seconds of El Centro (20)")
    ap.add_argument("--storeys", type=int, default=100, help="storeys of the stepped pair")
    ap.add_argument("--setup-storeys", type=int, default=50,
                    help="storeys of the pair whose set-up is timed (50)")
    _figures.add_json_option(ap)
    args = ap.parse_args(argv)
    keep_freed_memory()
    motion = el_centro()
    print(f"{load()}; rounds {args.rounds}; step {1e3 * args.dt:g} ms, "
          f"{args.duration:g} s of {motion.name}")

    # --- set-up, 50 storeys
    setup_model = pair(args.setup_storeys, 0.02)
    setup_once(setup_model, args.dt, True)  # (imports scipy.linalg, first BLAS calls)
    s_modal: list[float] = []
    s_dense: list[float] = []
    for _ in range(args.rounds):
        s_modal.append(setup_once(setup_model, args.dt, True))
        s_dense.append(setup_once(setup_model, args.dt, False))
    ratios = [d / m for m, d in zip(s_modal, s_dense)]
    print(f"set-up of the {args.setup_storeys}-storey pair's exact step (h = {args.dt:g} s): "
          f"modal {min(s_modal):.4f} s (rounds {spread(s_modal, '{:.4f}')}), "
          f"matrix exponentials {min(s_dense):.4f} s (rounds {spread(s_dense, '{:.4f}')}); "
          f"expm / modal {min(s_dense) / min(s_modal):.1f}× (rounds {spread(ratios, '{:.1f}')}×)")

    # --- a step without contact, 100 storeys
    n = args.storeys
    modal_model = route_model(n, 10.0, True, motion, args.dt)
    dense_model = route_model(n, 10.0, False, motion, args.dt)
    assert kernel_model(modal_model).free_steps[args.dt].modal.any()
    assert not kernel_model(dense_model).free_steps[args.dt].modal.any()
    t_modal: list[float] = []
    t_dense: list[float] = []
    res_m = res_d = None
    for _ in range(args.rounds):
        tm, res_m = per_step(modal_model, motion, args.dt, args.duration, args.repeat)
        td, res_d = per_step(dense_model, motion, args.dt, args.duration, args.repeat)
        t_modal.append(tm)
        t_dense.append(td)
    assert res_m is not None and res_d is not None
    impacts = int(res_m.n_impacts) + int(res_d.n_impacts)
    step_ratios = [d / m for m, d in zip(t_modal, t_dense)]
    u_m, u_d = np.asarray(res_m.displacement), np.asarray(res_d.displacement)
    agree = float(np.abs(u_m - u_d).max() / np.abs(u_d).max())
    print(f"{n}-storey pair, gap 10 m ({impacts} impacts), µs per grid step: "
          f"modal {1e6 * min(t_modal):.2f} (rounds {spread([1e6 * t for t in t_modal])}), "
          f"dense {1e6 * min(t_dense):.2f} (rounds {spread([1e6 * t for t in t_dense])}); "
          f"dense / modal {min(t_dense) / min(t_modal):.2f}× "
          f"(rounds {spread(step_ratios, '{:.2f}')}×)")
    print(f"displacements, modal against dense: max |Δu| / max |u| = {agree:.1e}")
    print(load())

    _figures.start("bench_tall", "Tall buildings: exact steps from the modes")
    _figures.figure(f"{args.setup_storeys}-storey pair: exact-step set-up (modal)",
                    min(s_modal),
                    "the same set-up from matrix exponentials (scipy expm, Van Loan)",
                    min(s_dense), ratio_meaning="peer / pounding (expm / modal)",
                    goal=f"<= {SETUP_GOAL_S:g} s", met=min(s_modal) <= SETUP_GOAL_S,
                    spread=f"best of {args.rounds} alternating rounds; ratios "
                           f"{spread(ratios, '{:.1f}')}x")
    _figures.figure(f"{n}-storey pair, no contact, {motion.name} {args.duration:g} s at "
                    f"{1e3 * args.dt:g} ms: one exact step", min(t_modal),
                    "dense propagator (every block from expm, same run)", min(t_dense),
                    ratio_meaning="peer / pounding (dense / modal)", goal="<= 10 µs",
                    met=min(t_modal) <= STEP_GOAL_S,
                    spread=f"best of {args.repeat} runs x {args.rounds} alternating rounds; "
                           f"ratios {spread(step_ratios, '{:.2f}')}x",
                    unit_note="seconds per grid step (kernel time / steps)")
    _figures.note(f"modal and dense displacements agree to {agree:.1e} of the largest (both "
                  f"exact; the difference is round-off accumulated over {u_m.shape[0] - 1} "
                  "steps)")
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

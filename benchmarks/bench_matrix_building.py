"""What a building given as matrices costs the time stepper, against a shear building of the
same size in the same process (issue 18: "banded or dense matrices without a second code
path").

Two 10-storey buildings pounding under El Centro (the pair of ``examples/two_10_storey.toml``,
gap 40 mm, Jankowski's law), four ways:

* ``shear``      — both shear buildings (the peer);
* ``matrix``     — the right one as ``MatrixBuilding.from_shear_building``: the same matrices,
                   so any difference is the matrix building's own overhead;
* ``shuffled``   — the right one with its DOFs in a shuffled order: the same physics, but
                   ``K`` and ``C`` fill the whole band (half-bandwidth 9 instead of 1);
* ``frame``      — the right one replaced by a 10-storey one-bay frame with flexible beams
                   (rotations condensed out: a full ``K``; T1 0.77 s as the shear building):
                   a genuinely dense building, with its own impacts.

Each with the contact-free steps exact (``free_stepping="auto"``) and with every step
adaptive (``"rk"``, where the O(N·bandwidth) products are all the work). Runs interleaved,
``--repeat`` times each (default 7); the median wall time of the integration and the spread
(min–max), and the ratio of medians to ``shear``.

    PYTHONPATH=src python benchmarks/bench_matrix_building.py [--repeat 7]

Not a test: timings on a shared machine vary; read the ratios.
"""

from __future__ import annotations

import argparse
import statistics
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))
sys.path.insert(0, str(ROOT / "tests" / "integrate"))

import _figures
from _environment import load, print_environment  # noqa: E402


def models() -> dict[str, object]:
    from test_matrix_building import frame_matrices

    from pounding.model import ContactSpec, PoundingModel
    from pounding.structure import MatrixBuilding, ShearBuilding

    a = ShearBuilding.uniform(10, 6e5, 8e8, 3.2, name="flexible")
    b = ShearBuilding.uniform(10, 4e5, 1.2e9, 3.2, name="stiff")
    spec = ContactSpec("nonlinear-viscoelastic", k_h=2.75e9, e=0.65)
    perm = np.random.default_rng(18).permutation(10)
    P = np.ix_(perm, perm)
    shuffled = MatrixBuilding(M=b.mass_matrix()[P], K=b.stiffness_matrix()[P],
                              labels=[f"F{j + 1}" for j in perm],
                              elevations=b.floor_levels[perm], damping=b.damping, name="stiff")
    kc, _ = frame_matrices(10, 3.2, 6.0, 1.0, 0.5)
    frame = MatrixBuilding(M=b.mass_matrix(), K=kc, labels=[f"F{j + 1}" for j in range(10)],
                           elevations=b.floor_levels, name="frame")
    frame = MatrixBuilding(M=b.mass_matrix(), K=kc * (frame.fundamental_period / 0.7675) ** 2,
                           labels=frame.labels, elevations=b.floor_levels, name="frame")
    return {"shear": PoundingModel([a, b], [0.04], spec),
            "matrix": PoundingModel([a, MatrixBuilding.from_shear_building(b)], [0.04], spec),
            "shuffled": PoundingModel([a, shuffled], [0.04], spec),
            "frame": PoundingModel([a, frame], [0.04], spec)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=7)
    _figures.add_json_option(ap)
    args = ap.parse_args()
    _figures.start("bench_matrix_building", "Buildings given as matrices")
    print_environment(kept_memory=False)

    from pounding.ground_motion import el_centro
    from pounding.integrate import simulate
    from pounding.integrate.kernel_model import half_bandwidth

    gm = el_centro()
    cases = models()
    modes = ("auto", "rk")
    times: dict[tuple[str, str], list[float]] = {(c, m): [] for c in cases for m in modes}
    info: dict[str, tuple[int, int]] = {}
    for name, model in cases.items():  # warm-up: compile, assemble
        for mode in modes:
            r = simulate(model, gm, free_stepping=mode)
        bw = half_bandwidth(model.linear_stiffness(), model.system.C)  # type: ignore[attr-defined]
        info[name] = (bw, r.n_impacts)
    for _ in range(args.repeat):
        for name, model in cases.items():
            for mode in modes:
                times[(name, mode)].append(simulate(model, gm, free_stepping=mode).wall_time)
    print(f"El Centro 39.99 s, two 10-storey buildings, gap 40 mm; {args.repeat} runs each, "
          f"interleaved; {load()} at the end")
    print(f"{'case':<10} {'bw':>3} {'impacts':>8}  {'free steps':<10} {'median [s]':>10} "
          f"{'min–max [s]':>15} {'÷ shear':>8}")
    for mode in modes:
        ref = statistics.median(times[("shear", mode)])
        for name in cases:
            t = times[(name, mode)]
            med = statistics.median(t)
            bw, imp = info[name]
            print(f"{name:<10} {bw:>3} {imp:>8}  {mode:<10} {med:>10.3f} "
                  f"{min(t):>7.3f}–{max(t):<7.3f} {med / ref:>8.2f}")
            if name != "shear":
                _figures.figure(f"two 10-storey buildings, one as '{name}' (half-bandwidth {bw}, "
                                f"{imp} impacts), free steps {mode}: kernel time, median", med,
                                "the same pair as two shear buildings",
                                ref, ratio_meaning="pounding / peer",
                                spread=f"median of {args.repeat} interleaved runs")
    _figures.write(args.json)


if __name__ == "__main__":
    main()

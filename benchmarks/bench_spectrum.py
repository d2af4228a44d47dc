"""Time of a response spectrum (not a test: a measurement), beside peers in the same script.

The case of issue 15: a 300-period (0.02–5 s, log-spaced) × 3-damping (2, 5, 10 %)
spectrum of a 40 s record: El Centro 1940 as shipped in ``pounding/data`` (4000 samples at
0.01 s). Measured:

* ``pounding``: :func:`pounding.spectra.response_spectrum` (compiled kernel, peaks inside the
  steps, Sd and absolute acceleration), ``--repeat`` times after one warm-up call (which
  loads or compiles the kernel; its time is printed too): min / median / max;
* the plain reference (:func:`pounding.spectra.reference.reference_peaks`: NumPy/SciPy,
  matrix exponentials and Hermite maxima on sub-steps; ``--reference-repeat`` times), and
  its largest difference from pounding;
* ``eqsig`` (``eqsig.sdof.pseudo_response_spectra``, Nigam & Jennings' recurrence in NumPy,
  peaks at the samples only, PSA set to the PGA below 6 dt) if it is installed
  (``pip install eqsig``; not a dependency of pounding), and its largest difference;
* RotD50/RotD100 of a pair (El Centro and the same record reversed), 100 periods × 180
  azimuths, 5 %.

Run from the repository root::

    python benchmarks/bench_spectrum.py                 # 15 repeats, reference once
    python benchmarks/bench_spectrum.py --repeat 31 --reference-repeat 3
    python benchmarks/bench_spectrum.py --reference-repeat 0   # without the slow reference

The machine is shared: compare within one run.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import platform
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _figures

from pounding.ground_motion import el_centro
from pounding.spectra import response_spectrum, rotd_spectrum
from pounding.spectra.reference import reference_peaks
from pounding.units import G

PERIODS = np.geomspace(0.02, 5.0, 300)
DAMPING = np.array([0.02, 0.05, 0.10])


def timed(fn: Callable[[], object], repeat: int) -> tuple[list[float], object]:
    times, out = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return times, out


def line(name: str, times: list[float]) -> None:
    print(f"{name:58s} {min(times) * 1e3:9.1f} {statistics.median(times) * 1e3:9.1f} "
          f"{max(times) * 1e3:9.1f}   ({len(times)} runs)")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=15)
    ap.add_argument("--reference-repeat", type=int, default=1, help="0: skip the reference")
    _figures.add_json_option(ap)
    args = ap.parse_args()
    _figures.start("bench_spectrum", "Response spectra")
    gm = el_centro()
    print(f"record: {gm.name}, {gm.npts} samples at {gm.dt:g} s ({gm.duration:g} s); "
          f"{PERIODS.size} periods {PERIODS[0]:g}-{PERIODS[-1]:g} s x damping "
          f"{', '.join(f'{z:g}' for z in DAMPING)}")
    import numba

    print(f"python {platform.python_version()}, numpy {np.__version__}, numba "
          f"{numba.__version__}, {os.cpu_count()} cores")
    t = time.perf_counter()
    response_spectrum(gm, [1.0], [0.05])
    print(f"first call (loads the cached kernel, or compiles it): "
          f"{time.perf_counter() - t:.2f} s")
    print(f"{'':58s} {'min ms':>9s} {'median':>9s} {'max':>9s}")
    times, spec = timed(lambda: response_spectrum(gm, PERIODS, DAMPING), args.repeat)
    line("pounding response_spectrum (Sd, PSV, PSA, abs. accel.)", times)
    assert spec is not None
    ours = times
    what = (f"{PERIODS.size} periods x {DAMPING.size} damping ratios of El Centro "
            f"({gm.duration:.0f} s)")

    if args.reference_repeat > 0:
        times, ref = timed(lambda: reference_peaks(gm.accel, gm.dt, PERIODS, DAMPING),
                           args.reference_repeat)
        line("plain reference (NumPy/SciPy, Hermite on sub-steps)", times)
        _figures.figure(what, min(ours), "plain NumPy/SciPy reference (Hermite on sub-steps)",
                        min(times), ratio_meaning="peer / pounding",
                        spread=f"best of {args.repeat} / {args.reference_repeat}")
        sd_ref, sa_ref = ref  # type: ignore[misc]
        print(f"    largest difference from pounding: Sd "
              f"{np.max(np.abs(spec.sd / sd_ref - 1)):.1e}, abs. accel. "
              f"{np.max(np.abs(spec.sa_abs / sa_ref - 1)):.1e} (relative)")

    try:
        from eqsig import sdof
    except ImportError:
        print("eqsig: not installed (pip install eqsig to compare)")
    else:
        def eq() -> np.ndarray:
            return np.array([sdof.pseudo_response_spectra(gm.accel, gm.dt, PERIODS, z)[2]
                             for z in DAMPING])

        times, psa_eq = timed(eq, max(3, args.reference_repeat))
        line("eqsig 1.2.17 pseudo_response_spectra (PSA only)", times)
        _figures.figure(what, min(ours), "eqsig pseudo_response_spectra (PSA only)",
                        min(times), ratio_meaning="peer / pounding",
                        spread=f"best of {args.repeat} / {max(3, args.reference_repeat)}")
        rel = np.abs(np.asarray(psa_eq) / spec.psa - 1)
        k = np.unravel_index(np.argmax(rel), rel.shape)
        long = PERIODS >= 6 * gm.dt
        print(f"    largest difference from pounding: {rel.max():.1e} (PSA at T = "
              f"{PERIODS[k[1]]:.3f} s, zeta = {DAMPING[k[0]]:g}: eqsig "
              f"{psa_eq[k] / G:.4f} g, pounding {spec.psa_g[k]:.4f} g); for T >= 6 dt: "
              f"{rel[:, long].max():.1e}")

    back = dataclasses.replace(gm, accel=gm.accel[::-1].copy(), name="reversed")
    rot_periods = np.geomspace(0.02, 5.0, 100)
    rotd_spectrum(gm, back, [1.0])
    times, _ = timed(lambda: rotd_spectrum(gm, back, rot_periods, 0.05),
                     max(3, args.repeat // 3))
    line("pounding rotd_spectrum (100 periods x 180 azimuths, 5 %)", times)
    _figures.note(f"pounding response_spectrum, {what}: {min(ours) * 1e3:.1f} ms (best of "
                  f"{len(ours)}); rotd_spectrum, 100 periods x 180 azimuths: "
                  f"{min(times) * 1e3:.1f} ms (best of {len(times)})")
    _figures.write(args.json)


if __name__ == "__main__":
    main()

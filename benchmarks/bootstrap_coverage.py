"""Coverage of the fragility bootstrap intervals (not a test: a measurement by simulation).

Suites of ``n`` records are drawn from a known lognormal capacity (θ, β); for each, the 90 %
interval of the median is computed from the capacities (moments, Baker 2015 eqs. 4–5) and
from the MLE on 20 stripes of the same records (0.02–1.0 g, log-spaced), with 1000
resamples, both as a plain percentile interval and as the expanded percentile interval
pounding uses (Hesterberg 2015, :func:`pounding.studies.fragility.bootstrap.
expanded_confidence`). Printed: the share of suites whose interval covered the true median.
Results quoted in docs/fragility.md (2026-11-27, ``--trials 300``).

Run from the repository root::

    python benchmarks/bootstrap_coverage.py                     # 300 suites a case (~15 min)
    python benchmarks/bootstrap_coverage.py --trials 100 --boot 400
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))

from pounding.studies.fragility.bootstrap import (  # noqa: E402
    expanded_confidence,
    fit_from_capacities,
    fit_from_stripes,
    percentile_interval,
    resample,
)

LEVELS = np.geomspace(0.02, 1.0, 20)
CASES = ((0.085, 0.21), (0.25, 0.35), (0.4, 0.6))


def coverage(n: int, theta: float, beta: float, trials: int, n_boot: int, seed: int,
             confidence: float = 0.90) -> tuple[float, float, float, float]:
    """Shares covered: capacities plain, capacities expanded, stripes plain, stripes
    expanded."""
    rng = np.random.default_rng(seed)
    wide = expanded_confidence(confidence, n)
    hits = np.zeros(4)
    for k in range(trials):
        cap = np.exp(rng.normal(math.log(theta), beta, n))
        boot = resample(n, n_boot, k + 10_000 * seed)
        exceed = (cap[:, None] <= LEVELS[None, :]).astype(float)
        for j, est in enumerate((fit_from_capacities(cap, np.zeros(n, bool), boot, confidence),
                                 fit_from_stripes(LEVELS, exceed, boot, confidence))):
            for i, c in enumerate((confidence, wide)):
                lo, hi = percentile_interval(est.medians, c)
                hits[2 * j + i] += lo <= theta <= hi
    return tuple(hits / trials)  # type: ignore[return-value]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--trials", type=int, default=300)
    parser.add_argument("--boot", type=int, default=1000)
    parser.add_argument("--records", default="9,10,20")
    args = parser.parse_args()
    print("records  theta  beta   capacities plain/expanded   stripes plain/expanded")
    for n in (int(x) for x in args.records.split(",")):
        for theta, beta in CASES:
            t0 = time.perf_counter()
            cp, ce, sp, se = coverage(n, theta, beta, args.trials, args.boot, 1)
            print(f"{n:7d}  {theta:5.3f}  {beta:4.2f}   {cp:6.3f} / {ce:6.3f}"
                  f"              {sp:6.3f} / {se:6.3f}   ({time.perf_counter() - t0:.0f} s)",
                  flush=True)


if __name__ == "__main__":
    main()

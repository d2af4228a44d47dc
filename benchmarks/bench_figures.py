"""Time each figure of a run (build + save as PNG) on the demo model, best of N.

Runs the model `pounding demo` runs (``pounding/examples/two_10_storey.toml``: two 10-storey buildings,
El Centro 40 s at 1 ms, 40,000 samples a line) once, then builds and saves every figure
of the run registry N times and prints the best time of each.

    python benchmarks/bench_figures.py [--repeat 3] [--out DIR] [--model MODEL.toml]
"""

from __future__ import annotations

import argparse
import tempfile
import time
from importlib import resources
from pathlib import Path


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--out", type=Path, default=None, help="keep the PNGs here")
    ap.add_argument("--model", type=Path, default=None, help="default: the demo model")
    args = ap.parse_args()

    from pounding.config import load_config
    from pounding.integrate import simulate

    path = args.model or Path(str(resources.files("pounding") / "examples" / "two_10_storey.toml"))
    cfg = load_config(path)
    model, motion, solver = cfg.build()
    t0 = time.perf_counter()
    result = simulate(model, motion, **solver)
    print(f"simulate: {time.perf_counter() - t0:.2f} s, {result.time.size} samples")

    t0 = time.perf_counter()
    from pounding.plot import save_figure
    try:
        from pounding.plot.registry import RUN_FIGURES, figures_for
        import pounding.plot.envelope  # noqa: F401  (import time reported apart)
        import pounding.plot.response  # noqa: F401
        figures = figures_for(result)
    except ImportError:  # before the light registry
        from pounding.plot.response import RUN_FIGURES
        figures = RUN_FIGURES
    print(f"import figure modules (matplotlib): {time.perf_counter() - t0:.2f} s")

    out = args.out or Path(tempfile.mkdtemp(prefix="figbench-"))
    out.mkdir(parents=True, exist_ok=True)
    total = total_first = 0.0
    for key, fig in figures.items():
        best_build = best_all = float("inf")
        first = None
        for _ in range(args.repeat):
            t0 = time.perf_counter()
            f = fig.make(result)
            t1 = time.perf_counter()
            save_figure(f, out / fig.file, dpi=cfg.output.dpi)
            t2 = time.perf_counter()
            best_build = min(best_build, t1 - t0)
            best_all = min(best_all, t2 - t0)
            first = t2 - t0 if first is None else first
        total_first += first
        total += best_all
        size = (out / fig.file).stat().st_size / 1024
        print(f"{key:22s} build {best_build:6.3f} s  build+save {best_all:6.3f} s  first {first:6.3f} s  "
              f"({fig.file}, {size:.0f} KiB)")
    print(f"{'total':22s} {'':19s}build+save {total:6.3f} s  first {total_first:6.3f} s  "
          f"(best of {args.repeat} each; first: the first call in this process)")
    print(f"PNGs in {out}")


if __name__ == "__main__":
    main()

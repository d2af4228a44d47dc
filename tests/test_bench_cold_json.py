"""``benchmarks/bench_cold.py --json``: the figures in the benchmark JSON convention that
``benchmarks/run_all.py`` collects (keys, seconds, the ratio from the two times measured)."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import pytest

BENCH = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_cold.py"
PEER = "python -c 'import numpy, numba' (peer)"
COLD = "pounding run seed_sdof_pair --no-figures, empty cache"
FIGURE_KEYS = {"what", "pounding", "peer", "peer_time", "ratio", "ratio_meaning", "goal", "met",
               "spread", "unit_note"}


def _bench():
    spec = importlib.util.spec_from_file_location("bench_cold", BENCH)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("cold_cpu, met", [(42.0, False), (19.5, True)])
def test_figures_follow_the_convention(cold_cpu: float, met: bool) -> None:
    bench = _bench()
    rows = {PEER: [(0.5, 1.0), (0.4, 1.2)],
            COLD: [(cold_cpu + 3.0, 90.0), (cold_cpu, 80.0)],
            "the same run again (cache filled)": [(2.0, 4.0)]}
    doc = json.loads(json.dumps(bench.figures_json(rows, PEER, {"f": 2, "g": 1}, 2, "1.0")))
    assert doc["benchmark"] == "bench_cold" and doc["command"].startswith(
        "python benchmarks/bench_cold.py")
    cold, warm = doc["figures"]
    for fig in (cold, warm):
        assert set(fig) == FIGURE_KEYS
        assert fig["peer_time"] == 0.4  # the best of the peer's rounds
        assert fig["ratio"] == pytest.approx(fig["pounding"] / fig["peer_time"], rel=1e-12)
    assert cold["pounding"] == cold_cpu  # the best round, not the last
    assert cold["goal"] == "<= 20 s of CPU" and cold["met"] is met
    assert warm["goal"] is None and warm["met"] is None
    assert "3 signatures of 2 numba functions" in doc["notes"][0]

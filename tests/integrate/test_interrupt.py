"""Ctrl-C and SIGTERM stop a long run within about a second, whatever the terminal: the
kernel is called in pieces of bounded work (Python handles a signal only between calls), and
the pieces do not change the answer. Before, a run without a progress bar (``pounding
mitigate``, ``gap``, ``sweep``, the library) was one compiled call that held the signal
until the run ended."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import pounding.integrate as integrate
from pounding import PoundingModel, simulate
from pounding.ground_motion import el_centro
from pounding.hysteresis import Bilinear
from pounding.model import ContactSpec
from pounding.structure import ShearBuilding

SRC = Path(__file__).resolve().parents[2] / "src"

MARKED = '''
import signal, sys
signal.signal(signal.SIGINT, signal.default_int_handler)  # as in a terminal
import pounding.integrate as integrate
from pounding.cli import main

real = integrate.integrate_chunk
told = []


def marked(k0, k1, *args):
    """The kernel, unchanged; says on stderr when its first real call begins."""
    if k1 > k0 and not told:
        told.append(True)
        sys.stderr.write("kernel started\\n")
        sys.stderr.flush()
    return real(k0, k1, *args)


integrate.integrate_chunk = marked
sys.exit(main(sys.argv[1:]))
'''

MODEL = """[record]
bundled = "el_centro"
[[building]]
mass = 2e5
period = 0.5
storey_law = { type = "bilinear", yield_force = 2e5 }
[[building]]
mass = 3e5
period = 1.0
[contact]
law = "kelvin-voigt"
k = 9.3e8
e = 0.65
gap = 0.02
[solver]
duration = 60.0
h_max = 1e-5      # ~100 RK steps a grid step: some 10 s of integration, one call before
"""


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_a_signal_stops_a_long_run_within_a_second(sig, tmp_path: Path):
    (tmp_path / "model.toml").write_text(MODEL)
    (tmp_path / "study.toml").write_text('name = "m"\nbase = "model.toml"\n'
                                         'records = ["el_centro"]\n[[option]]\nname = "bare"\n')
    (tmp_path / "marked.py").write_text(MARKED)
    before = sorted(p.name for p in tmp_path.iterdir())
    env = {**os.environ, "PYTHONPATH": str(SRC), "POUNDING_SKIP_BROWSER": "1"}
    # (mitigate: no progress bar reaches the kernel, output not a terminal)
    proc = subprocess.Popen([sys.executable, str(tmp_path / "marked.py"), "mitigate",
                             str(tmp_path / "study.toml"), "--out", str(tmp_path / "out")],
                            cwd=tmp_path, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stderr is not None
        # (a cold numba cache compiles the kernel first, and says so in one line)
        line = proc.stderr.readline()
        if line.startswith("compiling the solver once"):
            line = proc.stderr.readline()
        assert line == "kernel started\n", line + proc.stderr.read()
        time.sleep(1.0)
        proc.send_signal(sig)
        sent = time.monotonic()
        out, err = proc.communicate(timeout=30)
        took = time.monotonic() - sent
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    # 2.5 s of wall time on a quiet machine; on a busy one the child gets a share of a core,
    # so the allowance grows with the load a core (a load of 12 on 2 cores gave 3-4.5 s)
    busy = max(1.0, os.getloadavg()[0] / (os.cpu_count() or 1))
    assert took < 2.5 * busy, f"{took:.1f} s after the signal (load {busy:.1f} a core)"
    assert proc.returncode == 130
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: stopped"), err
    assert sorted(p.name for p in tmp_path.iterdir()) == before  # nothing left behind


def test_calls_of_bounded_work_give_the_answer_of_one_call(monkeypatch):
    # a call of ~30 µs of estimated work: hundreds of calls, each returning at a grid point
    # inside contact episodes and yielding excursions, and the same bits as one call
    left = ShearBuilding.sdof(2e5, period=0.5).with_storey_law(Bilinear(yield_force=2e5,
                                                                        hardening=0.05))
    models = {"exact": PoundingModel([ShearBuilding.uniform(3, 2e5, 2e8),
                                      ShearBuilding.sdof(3e5, period=1.0)], [0.01],
                                     ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)),
              "yielding": PoundingModel([left, ShearBuilding.sdof(3e5, period=1.0)], [0.01],
                                        ContactSpec("nonlinear-viscoelastic", k_h=2.75e9,
                                                    e=0.65))}
    motion = el_centro().trimmed(5.0)
    calls = []
    real = integrate.integrate_chunk

    def counted(*args):
        calls.append(args[1] - args[0])
        return real(*args)

    monkeypatch.setattr(integrate, "integrate_chunk", counted)
    for name, model in models.items():
        whole = simulate(model, motion)
        monkeypatch.setattr(integrate, "CALL_WORK_NS", 3e4)
        calls.clear()
        cut = simulate(model, motion)
        monkeypatch.setattr(integrate, "CALL_WORK_NS", 1e8)
        assert len(calls) > 100, name
        assert whole.n_impacts > 0 and cut.stats.rk_steps == whole.stats.rk_steps
        for key in ("displacement", "velocity", "abs_acceleration", "contact_force", "energy",
                    "yielding_shear", "impact_array", "peak_displacement",
                    "peak_abs_acceleration_time", "contact_peak_time"):
            assert np.array_equal(np.asarray(getattr(whole, key)), np.asarray(getattr(cut, key)),
                                  equal_nan=True), (name, key)

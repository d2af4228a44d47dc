"""A first response spectrum on a machine compiles the spectra kernel (a few seconds): the
command line says so in one line before it starts, and says nothing once it is cached
(issue 30: "The first `pounding fragility` compiles a second kernel (spectra, ~6 s of CPU)
that no note mentions").
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from pounding.compiled_cache import before_first_call, tell_compiling_to, will_compile
from pounding.spectra.response import SPECTRA_COMPILE_S

ROOT = Path(__file__).resolve().parents[2]
RECORD = ROOT / "src" / "pounding" / "data" / "records" / "elcentro_1940_IV_ELC9_180_PEER.AT2"
NOTE = "compiling the response-spectrum kernel once"


def _spectrum(tmp_path: Path, cache: Path) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"), NUMBA_CACHE_DIR=str(cache))
    return subprocess.run([sys.executable, "-m", "pounding", "spectrum", str(RECORD),
                           "--csv", str(tmp_path / "s.csv")], env=env, capture_output=True,
                          check=False, text=True, timeout=600, cwd=tmp_path)


def test_the_spectra_kernel_says_it_compiles_once_then_not(tmp_path: Path) -> None:
    cache = tmp_path / "numba-cache"
    cache.mkdir()
    first = _spectrum(tmp_path, cache)
    assert first.returncode == 0, first.stderr[-2000:]
    notes = [ln for ln in first.stderr.splitlines() if NOTE in ln]
    assert len(notes) == 1 and f"about {SPECTRA_COMPILE_S:.0f} s" in notes[0], first.stderr
    again = _spectrum(tmp_path, cache)  # loads what the first compiled
    assert again.returncode == 0, again.stderr[-2000:]
    assert NOTE not in again.stderr and NOTE not in again.stdout
    assert (tmp_path / "s.csv").read_text() != ""


class _Uncompiled:
    """Stands for a numba dispatcher with nothing loaded and no cache at all."""

    signatures: tuple[str, ...] = ()


class _Loaded:
    signatures = ("(float64,)",)


def test_only_a_kernel_that_will_compile_is_told_and_only_to_a_listener() -> None:
    heard: list[tuple[str, float]] = []
    assert will_compile(_Uncompiled()) and not will_compile(_Loaded())
    try:
        before_first_call(_Uncompiled(), "k", 1.0)  # nobody listens: nothing happens
        tell_compiling_to(lambda what, s: heard.append((what, s)))
        before_first_call(_Loaded(), "loaded", 2.0)
        before_first_call(_Uncompiled(), "fresh", 3.0)
    finally:
        tell_compiling_to(None)
    assert heard == [("fresh", 3.0)]


def test_a_plain_function_never_compiles() -> None:
    """Under NUMBA_DISABLE_JIT=1 a kernel is a plain function: nothing to say (it was told
    on every call)."""
    def plain() -> None: ...

    assert not will_compile(plain)

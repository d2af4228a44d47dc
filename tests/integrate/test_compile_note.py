"""The progress line says the solver is compiling when numba's cache holds no compiled kernel
for this machine (an empty ``NUMBA_CACHE_DIR``), and says nothing of it when the kernel is
cached (issue 30).

The cold case is a real ``pounding run`` with an empty cache, stopped as soon as the line has
appeared (before the compiling, ~40 s, is done); the warm case runs to the end on the cache
this test session compiled into.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from pounding.integrate import simulate, solver_compile_seconds
from pounding.integrate.kernel_cache import COLD_COMPILE_S, cached_here

ROOT = Path(__file__).resolve().parents[2]
SRC = ROOT / "src"
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
NOTE = "compiling the solver once"


def _run_cli(out: Path, env: dict[str, str]) -> subprocess.Popen[str]:
    return subprocess.Popen([sys.executable, "-m", "pounding", "run", str(SEED), "--no-figures",
                             "--out", str(out)], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, cwd=out.parent)


def test_an_empty_numba_cache_is_told_on_the_progress_line(tmp_path: Path) -> None:
    cache = tmp_path / "numba-cache"
    cache.mkdir()
    env = dict(os.environ, PYTHONPATH=str(SRC), NUMBA_CACHE_DIR=str(cache))
    proc = _run_cli(tmp_path / "out", env)
    lines: list[str] = []
    try:
        assert proc.stderr is not None
        # printed before compiling starts: stop the run there (at the end of standard error
        # without it, the run has compiled and finished, and the test fails)
        for line in proc.stderr:
            lines.append(line)
            if NOTE in line:
                break
    finally:
        proc.kill()
        proc.communicate()
    note = [ln for ln in lines if NOTE in ln]
    assert note and f"about {COLD_COMPILE_S:.0f} s" in note[0], "".join(lines)[-2000:]


def test_a_cached_kernel_is_not_announced(tmp_path: Path) -> None:
    # this process compiles (or loads) the kernel into the cache the subprocess reads
    from pounding.config import load_config

    model, motion, solver = load_config(SEED).build()
    simulate(model, motion, **solver)
    assert solver_compile_seconds() == 0.0  # loaded in this process
    # (numba's cache log on standard output: the kernel loaded, none compiled and saved)
    env = dict(os.environ, PYTHONPATH=str(SRC), NUMBA_DEBUG_CACHE="1")
    proc = _run_cli(tmp_path / "out", env)
    stdout, stderr = proc.communicate(timeout=300)
    assert proc.returncode == 0, stderr[-2000:]
    assert NOTE not in stderr and NOTE not in stdout
    assert (tmp_path / "out" / "summary.json").is_file()
    kernel_log = [ln for ln in stdout.splitlines() if "kernel.integrate_chunk" in ln]
    assert any("data loaded" in ln for ln in kernel_log), stdout[-2000:]
    assert not any("data saved" in ln for ln in kernel_log), stdout[-2000:]


def test_the_index_of_another_machine_or_source_is_not_a_cached_kernel(tmp_path: Path) -> None:
    # numba's own index reading: an empty folder has none; an index whose entries are for
    # another code generator (another CPU) is not one this machine loads
    code = ("import pickle, numba\n"
            "from pounding.integrate.kernel import integrate_chunk\n"
            "from pounding.integrate.kernel_cache import cached_here\n"
            "f = integrate_chunk._cache._cache_file\n"
            "print(cached_here(integrate_chunk))\n"
            "with open(f._index_path, 'wb') as fh:\n"
            "    pickle.dump(f._version, fh)\n"
            "    fh.write(pickle.dumps((f._source_stamp, {('sig', ('other-cpu', ''), ()): 'x.nbc'})))\n"
            "open(f._cache_path + '/x.nbc', 'wb').close()\n"
            "print(cached_here(integrate_chunk))\n")
    env = dict(os.environ, PYTHONPATH=str(SRC), NUMBA_CACHE_DIR=str(tmp_path))
    out = subprocess.run([sys.executable, "-c", code], check=False, env=env, capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    assert out.stdout.split() == ["False", "False"]


def test_the_kernel_this_process_loaded_is_cached_here() -> None:
    from pounding.config import load_config
    from pounding.integrate.kernel import integrate_chunk

    model, motion, solver = load_config(SEED).build()
    simulate(model, motion, **solver)
    assert cached_here(integrate_chunk)


def test_the_bar_says_it_compiles_from_the_start_when_the_cache_is_cold() -> None:
    from rich.progress import Progress

    from pounding.cli.running import _CompilingNote

    bar = Progress(get_time=lambda: 0.0)
    task_id = bar.add_task("simulating", total=1.0)
    note = _CompilingNote(30.0)
    assert note.render(bar.tasks[0]).plain.startswith(f"{NOTE} (about 30 s")
    bar.update(task_id, completed=0.02)  # the first chunk is done: compiled
    assert note.render(bar.tasks[0]).plain == ""

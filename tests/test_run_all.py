"""``benchmarks/run_all.py``: docs/performance.md rendered from the benchmarks' JSON.

No benchmark runs here: the renderer is fed JSON fixtures written in ``tmp_path``, a run is
made with two stand-in scripts (one writes figures, one fails), and the table of sections
is checked against the scripts in ``benchmarks/``.
"""

from __future__ import annotations

import ast
import importlib.util
import json
import re
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import pytest

ROOT = Path(__file__).resolve().parents[1]
BENCH = ROOT / "benchmarks"


def _load(name: str) -> ModuleType:
    """A module of ``benchmarks/`` by its path (sys.path left as it is)."""
    spec = importlib.util.spec_from_file_location(f"_bench_{name}", BENCH / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


run_all = _load("run_all")
figures = _load("_figures")


def _figure(what: str, ours: float, peer_time: float, goal: str | None = None) -> dict:
    """A figure as a benchmark writes it (through _figures, so the ratio is its own)."""
    figures.start("fixture", "fixture")
    return figures.figure(what, ours, "OpenSeesPy 3.7.1.2", peer_time,
                          ratio_meaning="OpenSees / pounding", goal=goal, spread="best of 7")


def _record(key: str, commands: list[dict], when: str = "2031-01-02 03:04 UTC") -> dict:
    return {"section": key, "title": run_all.SECTIONS[key].title, "run_at": when,
            "quick": False, "commit": "abc1234 2031-01-02",
            "machine": {"cpu": "Test CPU", "cores": 2, "openblas_core": "Haswell",
                        "python": "3.11.7", "numba": "0.0.1", "numpy": "2.0",
                        "openseespy": "3.7.1.2", "system": "Linux"},
            "commands": commands, "status": run_all.status_of(commands),
            "wall_s": sum(c["wall_s"] for c in commands)}


def _command(output: dict | None, exit_status: int | None = 0, error: str | None = None) -> dict:
    c = {"command": "python benchmarks/x.py", "started": "2031-01-02 03:04 UTC",
         "load_before": [1.5, 1.25, 1.0], "load_after": [1.75, 1.5, 1.0], "wall_s": 12.5,
         "exit_status": exit_status, "output": output}
    if error:
        c["error"] = error
    return c


def _output(figs: list[dict], notes: list[str] = (), failures: list[str] = ()) -> dict:
    return {"benchmark": "x", "section": "x", "command": "python benchmarks/x.py",
            "figures": figs, "notes": list(notes), "failures": list(failures)}


def _section_text(page: str, key: str) -> str:
    """The part of the page under one section's anchor, up to the next one."""
    start = page.index(f'<a id="{key}"></a>')
    nxt = page.find('<a id="', start + 1)
    return page[start:] if nxt < 0 else page[start:nxt]


def test_figure_ratio_goal_and_command_line(tmp_path: Path, monkeypatch) -> None:
    figures.start("bench_x", "X")
    f = figures.figure("case", 0.002, "peer", 0.366, ratio_meaning="OpenSees / pounding",
                       goal=">= 100x")
    assert f["ratio"] == pytest.approx(183.0, rel=1e-12) and f["met"] is True
    g = figures.figure("cpu", 1.47, "python -c 'import numpy, numba'", 0.34,
                       ratio_meaning="pounding / peer (CPU)", goal="<= 2x")
    assert g["ratio"] == pytest.approx(1.47 / 0.34, rel=1e-12) and g["met"] is False
    assert figures.figure("no goal", 1.0, "p", 2.0)["met"] is None
    figures.note("a fact")
    monkeypatch.setattr(sys, "argv", ["benchmarks/bench_x.py", "--repeat", "7", "--json",
                                      str(tmp_path / "o.json"), "--sections=a b"])
    figures.write(tmp_path / "o.json")
    data = json.loads((tmp_path / "o.json").read_text(encoding="utf-8"))
    assert data["command"] == "python benchmarks/bench_x.py --repeat 7 '--sections=a b'"
    assert [x["what"] for x in data["figures"]] == ["case", "cpu", "no goal"]
    assert data["notes"] == ["a fact"] and data["failures"] == []
    figures.figure("nan peer", 1.0, "none", float("nan"))
    figures.write(tmp_path / "nan.json")  # NaN is not JSON: written as null
    assert json.loads((tmp_path / "nan.json").read_text())["figures"][-1]["peer_time"] is None


def test_render_from_fixtures(tmp_path: Path) -> None:
    kernel = _record("kernel", [_command(_output(
        [_figure("two SDOF, Kelvin-Voigt: time-stepping loop", 0.0019, 0.353, ">= 100x"),
         _figure("two 10-storey: time-stepping loop", 0.031, 1.24, ">= 50x")],
        notes=["peak contact force: OpenSees -0.700 %, pounding -0.0001 %"]))])
    startup = _record("startup", [_command(None, exit_status=1, error="exit status 1")])
    memory = _record("memory", [
        _command(_output([_figure("ten storeys: best call", 0.030, 0.0345)])),
        _command(_output([], failures=["section x: RuntimeError: boom"]))])
    for rec in (kernel, startup, memory):
        (tmp_path / f"{rec['section']}.json").write_text(json.dumps(rec), encoding="utf-8")
    (tmp_path / "scaling.json").write_text("{ not json", encoding="utf-8")

    page = run_all.render(tmp_path)

    k = _section_text(page, "kernel")
    assert "| two SDOF, Kelvin-Voigt: time-stepping loop | 1.9 ms | OpenSeesPy 3.7.1.2 | 353 ms" in k
    assert "186× (OpenSees / pounding) | >= 100x: met |" in k      # 0.353 / 0.0019
    assert "40× (OpenSees / pounding) | >= 50x: **missed** |" in k   # 1.24 / 0.031
    assert "load average (1, 5, 15 min) 1.50 1.25 1.00 before, 1.75 1.50 1.00 after" in k
    assert "2031-01-02 03:04 UTC" in k and "abc1234" in k
    assert "- peak contact force: OpenSees -0.700 %, pounding -0.0001 %" in k
    assert "1. Test CPU, 2 cores, OpenBLAS core Haswell" in page

    s = _section_text(page, "startup")
    assert "**Did not reproduce:**" in s and "exit status 1" in s and "| case |" not in s

    m = _section_text(page, "memory")
    assert "1.15× (OpenSees / pounding)" in m and "section x: RuntimeError: boom" in m
    assert run_all.status_of(memory["commands"]) == "partial"

    for key in ("scaling", "cold", "bridges"):  # unreadable or absent: not measured
        assert "*Not measured by `run_all.py` yet.*" in _section_text(page, key)
    assert "| [Start-up: whole commands as a user types them](#startup) | 2031-01-02 03:04 UTC" \
        " | 12 s | failed |" in page


FAKE_OK = """
import json, sys
path = sys.argv[sys.argv.index("--json") + 1]
json.dump({"benchmark": "fake", "section": "fake", "command": "python benchmarks/fake_ok.py",
           "figures": [{"what": "fake case", "pounding": 0.5, "peer": "fake peer",
                        "peer_time": 2.0, "ratio": 4.0, "ratio_meaning": "peer / pounding",
                        "goal": None, "met": None, "spread": None, "unit_note": None}],
           "notes": [], "failures": []}, open(path, "w"))
print("fake benchmark ran")
"""

FAKE_FAIL = "import sys; print('broken'); sys.exit(3)\n"


def test_partial_rerun_replaces_only_its_section_and_a_failure_removes_figures(
        tmp_path: Path, monkeypatch) -> None:
    bench = tmp_path / "benchmarks"
    bench.mkdir()
    (bench / "fake_ok.py").write_text(FAKE_OK, encoding="utf-8")
    (bench / "fake_fail.py").write_text(FAKE_FAIL, encoding="utf-8")
    results = tmp_path / "results"
    monkeypatch.setattr(run_all, "HERE", bench)
    monkeypatch.setattr(run_all, "_openblas_core", lambda: "fixture")
    ok = run_all.Section("kernel", "K", (("fake_ok.py", "--repeat", "7"),), ())
    bad = run_all.Section("kernel", "K", (("fake_fail.py",),), ())
    other = _record("bridges", [_command(_output([_figure("five frames", 0.033, 0.111)]))])
    results.mkdir()
    (results / "bridges.json").write_text(json.dumps(other), encoding="utf-8")

    rec = run_all.run_section(ok, results, quick=False, timeout=60)
    assert rec["status"] == "ok" and rec["commands"][0]["exit_status"] == 0
    assert rec["commands"][0]["command"] == "python benchmarks/fake_ok.py --repeat 7"
    assert len(rec["commands"][0]["load_before"]) == 3 and rec["wall_s"] > 0
    assert "fake benchmark ran" in (results / "kernel.log").read_text(encoding="utf-8")
    page = run_all.render(results)
    assert "| fake case | 500 ms | fake peer | 2 s | 4× (peer / pounding)" in page
    assert "| five frames |" in _section_text(page, "bridges")

    rec = run_all.run_section(bad, results, quick=False, timeout=60)  # the rerun fails
    assert rec["status"] == "failed" and rec["commands"][0]["error"] == "exit status 3"
    page = run_all.render(results)
    k = _section_text(page, "kernel")
    assert "**Did not reproduce:**" in k and "fake case" not in page  # removed, not kept
    assert "| five frames |" in _section_text(page, "bridges")        # the others kept


def test_every_section_names_a_script_that_writes_json() -> None:
    """Each command of the table runs a script of benchmarks/ that takes ``--json`` on its
    parser and writes it (read from the source: no benchmark is started)."""
    scripts = {c[0] for s in run_all.SECTIONS.values() for c in (*s.commands, *s.quick)}
    assert scripts
    for name in sorted(scripts):
        path = BENCH / name
        assert path.is_file(), name
        tree = ast.parse(path.read_text(encoding="utf-8"))
        calls = {ast.unparse(n.func) for n in ast.walk(tree) if isinstance(n, ast.Call)}
        assert {"_figures.add_json_option", "_figures.start", "_figures.write"} <= calls, name
        assert "_figures.figure" in calls, name
    for s in run_all.SECTIONS.values():
        assert {c[0] for c in s.quick} == {c[0] for c in s.commands}, s.key


def test_json_option_shown_by_help() -> None:
    """One real ``--help`` (a light script): the option is on the parser."""
    out = subprocess.run([sys.executable, str(BENCH / "bench_memory.py"), "--help"],
                         capture_output=True, text=True, timeout=60, check=False,
                         env={"PYTHONPATH": str(ROOT / "src"), "PATH": ""})
    assert out.returncode == 0 and "--json PATH" in out.stdout


def test_readme_quotes_no_timing_figures() -> None:
    """The README points to docs/performance.md for every speed figure (none of its own,
    which would go stale)."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "docs/performance.md" in readme
    assert not re.findall(r"\d\s*×(?!\s*10)", readme)              # ratios like 183×
    assert not re.findall(r"\d\s*(?:µs|ms)\b", readme)              # kernel times
    assert not re.findall(r"\d\s*s of CPU", readme)                 # start-up, compile
    assert not re.findall(r"\d+ min \d+ s", readme)                 # test-suite times


def test_a_comparison_without_its_peer_is_not_run(tmp_path: Path, monkeypatch) -> None:
    """Without OpenSeesPy a section that compares with it says so and shows no figure."""
    monkeypatch.setattr(run_all, "machine", lambda: {"openseespy": "not installed"})
    ran = []
    monkeypatch.setattr(run_all, "run_command", lambda *a: ran.append(a))
    sec = run_all.Section("kernel", "K", (("bench_opensees.py",),), (), needs_opensees=True)
    rec = run_all.run_section(sec, tmp_path, quick=False, timeout=None)
    assert ran == [] and rec["status"] == "failed"
    assert "OpenSeesPy is not installed" in rec["commands"][0]["error"]

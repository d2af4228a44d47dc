"""Run every benchmark a published figure comes from and write ``docs/performance.md``.

Each section of the page is one row of :data:`SECTIONS`: the benchmark script(s) it runs,
with the arguments its figures are published with. Every script runs as its own process
(``python benchmarks/<script> <arguments> --json PATH``; ``benchmarks/_figures.py`` is the
JSON it writes), and for each the date (UTC), the load average before and after, its wall
time and exit status are kept with its figures in ``benchmarks/results/<section>.json``
(and its printout in ``benchmarks/results/<section>.log``), together with the machine
(CPU, cores, OpenBLAS core type, Python, numba, NumPy, OpenSeesPy) and the commit. The
page is then rendered from every section's stored JSON by the template
``benchmarks/performance.md.j2``, so a partial rerun (``--only``) replaces only its own
sections. A benchmark that fails or writes no figure replaces its section's figures with
a line saying so: a figure that did not reproduce is removed, not kept.

    python benchmarks/run_all.py                      # everything (about an hour)
    python benchmarks/run_all.py --list               # the sections and their commands
    python benchmarks/run_all.py --only kernel startup
    python benchmarks/run_all.py --render             # only re-render the page
    python benchmarks/run_all.py --quick --results /tmp/r --out /tmp/p.md   # smoke test

``--quick`` runs each script with fewer repeats and a shorter record: a check that the
machinery works, not a measurement. Its sections say so on the page, in bold.
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
RESULTS = HERE / "results"
TEMPLATE = HERE / "performance.md.j2"
PAGE = ROOT / "docs" / "performance.md"


@dataclass(frozen=True)
class Section:
    """One section of docs/performance.md and the benchmark commands it comes from."""

    key: str
    title: str
    commands: tuple[tuple[str, ...], ...]
    """Each: the script in ``benchmarks/`` and its published arguments (``--json`` added)."""
    quick: tuple[tuple[str, ...], ...]
    """The same scripts with fewer repeats (``--quick``: a smoke test, not a figure)."""
    needs_opensees: bool = True
    minutes: float = 1.0
    """About how long the standard commands take on the project's 2-core machine (measured
    2026-11-28 at load average 6-10 where the section has been run by run_all.py)."""


SECTIONS: dict[str, Section] = {s.key: s for s in (
    Section("kernel", "The time-stepping kernel against OpenSees",
            (("bench_opensees.py", "--sections", "compare", "--repeat", "7"),),
            (("bench_opensees.py", "--sections", "compare", "--repeat", "1",
              "--duration", "2"),), minutes=8.5),
    Section("scaling", "Cost against model size and record length",
            (("bench_opensees.py", "--sections", "scaling", "--repeat", "7"),),
            (("bench_opensees.py", "--sections", "scaling", "--repeat", "1",
              "--duration", "2"),), needs_opensees=False, minutes=0.5),
    Section("inelastic", "Yielding storeys against OpenSees",
            (("bench_inelastic.py", "--sections", "bilinear,epp,boucwen,pair",
              "--repeat", "5"),),
            (("bench_inelastic.py", "--sections", "bilinear", "--repeat", "1",
              "--duration", "2"),), minutes=1.5),
    Section("startup", "Start-up: whole commands as a user types them",
            (("bench_startup.py", "--repeat", "5", "--phases"),),
            (("bench_startup.py", "--repeat", "1"),), needs_opensees=False, minutes=8),
    Section("cold", "Cold start: the first run on an empty numba cache",
            (("bench_cold.py",),), (("bench_cold.py",),), needs_opensees=False, minutes=3),
    Section("memory", "Memory between runs",
            (("bench_memory.py", "--rounds", "3"),
             ("bench_memory.py", "--rounds", "3", "--model", "seed_sdof_pair.toml")),
            (("bench_memory.py", "--rounds", "1", "--calls", "3"),),
            needs_opensees=False, minutes=1),
    Section("spectrum", "Response spectra",
            (("bench_spectrum.py",),),
            (("bench_spectrum.py", "--repeat", "2"),), needs_opensees=False, minutes=3),
    Section("fragility", "The fragility study against OpenSees",
            (("bench_fragility.py",),),
            (("bench_fragility.py", "--records", "1", "--levels", "1", "--repeat", "1",
              "--study-repeat", "1", "--no-reference", "--sections", "runs"),), minutes=4.5),
    Section("sweep", "Parameter sweeps",
            (("bench_sweep.py", "--only", "ratio", "--repeat", "2"),),
            (("bench_sweep.py", "--only", "ratio", "--repeat", "1", "--cases", "200"),),
            needs_opensees=False, minutes=12),
    Section("plan", "Buildings in plan against OpenSees",
            (("bench_plan.py", "--no-reference"),),
            (("bench_plan.py", "--no-reference", "--repeat", "1"),), minutes=1.5),
    Section("matrix", "Buildings given as matrices",
            (("bench_matrix_building.py",),),
            (("bench_matrix_building.py", "--repeat", "1"),), needs_opensees=False, minutes=0.5),
    Section("pushover", "Pushover of an LA9-type frame",
            (("bench_pushover.py", "--sections", "la9"),),
            (("bench_pushover.py", "--sections", "la9", "--repeat", "1", "--steps", "20"),),
            minutes=3.5),
    Section("frames", "LA9-type pair time history",
            (("bench_frames.py", "--sections", "speed,ida"),),
            (("bench_frames.py", "--sections", "speed", "--repeat", "1",
              "--opensees-repeat", "1", "--fine-dt", "0"),), minutes=4.5),
    Section("ssi", "Soil-structure interaction",
            (("bench_ssi.py", "--sections", "speed"),),
            (("bench_ssi.py", "--sections", "speed", "--rounds", "1",
              "--opensees-rounds", "1"),), minutes=0.5),
    Section("links", "Links between buildings",
            (("bench_devices.py", "--sections", "cost", "--kinds", "viscous,maxwell", "--repeat",
              "5", "--no-reference"),),
            (("bench_devices.py", "--sections", "cost", "--kinds", "viscous", "--repeat", "1",
              "--no-reference", "--duration", "2"),), minutes=5),
    Section("tall", "Tall buildings: exact steps from the modes",
            (("bench_tall.py",),),
            (("bench_tall.py", "--rounds", "1", "--repeat", "1", "--duration", "2"),),
            needs_opensees=False, minutes=1.5),
    Section("exactstep", "The exact step against a hand-written loop",
            (("bench_exact_step.py", "--rounds", "3"),),
            (("bench_exact_step.py", "--rounds", "1"),), needs_opensees=False, minutes=1),
    Section("bridges", "Bridges",
            (("bench_bridge.py", "--sections", "speed,cost", "--rounds", "7"),),
            (("bench_bridge.py", "--sections", "speed", "--rounds", "1"),), minutes=0.5),
)}


# ------------------------------------------------------------------ the machine
def _version(package: str) -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version(package)
    except PackageNotFoundError:
        return "not installed"


def _cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def _openblas_core() -> str:
    """``OPENBLAS_CORETYPE`` if set, else the core type OpenBLAS chose (threadpoolctl)."""
    if os.environ.get("OPENBLAS_CORETYPE"):
        return os.environ["OPENBLAS_CORETYPE"] + " (OPENBLAS_CORETYPE)"
    code = ("import numpy, threadpoolctl; print(','.join(sorted({i.get('architecture') or '?' "
            "for i in threadpoolctl.threadpool_info() if i.get('internal_api') == 'openblas'}))"
            " or 'no OpenBLAS')")
    try:
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                             check=False, timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return "unknown"
    return out.stdout.strip() or "unknown"


def commit() -> str:
    """The checkout's commit (short hash, date), ``+ changes`` if the tree differs from it."""
    try:
        head = subprocess.run(["git", "-C", str(ROOT), "log", "-1", "--format=%h %cs"],
                              capture_output=True, text=True, check=False).stdout.strip()
        # (run_all's own outputs, the stored figures and the page, are not the code measured)
        dirty = subprocess.run(["git", "-C", str(ROOT), "status", "--porcelain",
                                "--untracked-files=no", "--", ".", ":!benchmarks/results",
                                ":!docs/performance.md"], capture_output=True,
                               text=True, check=False).stdout.strip()
    except OSError:
        return "unknown"
    return (head or "unknown") + (" + uncommitted changes" if dirty else "")


def machine() -> dict[str, Any]:
    """What the figures were measured on."""
    return {"cpu": _cpu_model(), "cores": os.cpu_count(), "openblas_core": _openblas_core(),
            "python": platform.python_version(), "numba": _version("numba"),
            "numpy": _version("numpy"), "openseespy": _version("openseespy"),
            "system": f"{platform.system()} {platform.release()}"}


def _load() -> list[float] | None:
    try:
        return [round(x, 2) for x in os.getloadavg()]
    except OSError:
        return None


# ------------------------------------------------------------------ running
def run_command(script_args: Sequence[str], log: Any, timeout: float | None) -> dict[str, Any]:
    """Run one benchmark as its own process with ``--json``; what it did and wrote."""
    script, *args = script_args
    with tempfile.TemporaryDirectory(prefix="run-all-") as tmp:
        out = Path(tmp) / "figures.json"
        cmd = [sys.executable, str(HERE / script), *args, "--json", str(out)]
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join(
            p for p in (str(ROOT / "src"), str(HERE), env.get("PYTHONPATH", "")) if p)
        shown = " ".join(["python", f"benchmarks/{script}", *args])
        entry: dict[str, Any] = {"command": shown, "started": _now(), "load_before": _load()}
        log.write(f"$ {shown}\n")
        log.flush()
        t0 = time.perf_counter()
        try:
            proc = subprocess.run(cmd, cwd=ROOT, env=env, stdout=log, stderr=subprocess.STDOUT,
                                  check=False, timeout=timeout)
            entry["exit_status"] = proc.returncode
        except subprocess.TimeoutExpired:
            entry["exit_status"] = None
            entry["error"] = f"stopped after {timeout:g} s (--timeout)"
        entry["wall_s"] = round(time.perf_counter() - t0, 2)
        entry["load_after"] = _load()
        if entry["exit_status"] not in (0, None):
            entry["error"] = f"exit status {entry['exit_status']}"
        try:
            entry["output"] = json.loads(out.read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            entry["output"] = None
            entry.setdefault("error", f"no figures written ({type(exc).__name__})")
    log.write(f"# wall {entry['wall_s']} s, exit status {entry['exit_status']}\n\n")
    log.flush()
    return entry


def status_of(commands: list[dict[str, Any]]) -> str:
    """``ok`` (every command ran and gave figures), ``partial`` (some figures, something
    failed) or ``failed`` (no figure)."""
    figures = sum(len((c.get("output") or {}).get("figures") or []) for c in commands)
    broken = any(c.get("error") or (c.get("output") or {}).get("failures") for c in commands)
    if figures == 0:
        return "failed"
    return "partial" if broken else "ok"


def run_section(section: Section, results: Path, quick: bool,
                timeout: float | None) -> dict[str, Any]:
    """Run a section's commands and store what they gave in ``results/<key>.json``."""
    results.mkdir(parents=True, exist_ok=True)
    record: dict[str, Any] = {"section": section.key, "title": section.title,
                              "run_at": _now(), "quick": quick, "machine": machine(),
                              "commit": commit(), "commands": []}
    peerless = section.needs_opensees and record["machine"]["openseespy"] == "not installed"
    with open(results / f"{section.key}.log", "w", encoding="utf-8") as log:
        for script_args in (section.quick if quick else section.commands):
            if peerless:  # no peer, no figure: said so rather than run half a comparison
                record["commands"].append({
                    "command": " ".join(["python", f"benchmarks/{script_args[0]}",
                                         *script_args[1:]]),
                    "started": _now(), "load_before": _load(), "load_after": _load(),
                    "wall_s": 0.0, "exit_status": None, "output": None,
                    "error": "OpenSeesPy is not installed (pip install 'pounding[bench]'; "
                             "benchmarks/README.md)"})
                continue
            print(f"[{section.key}] python benchmarks/{' '.join(script_args)}", flush=True)
            entry = run_command(script_args, log, timeout)
            print(f"[{section.key}] {entry['wall_s']:.0f} s, "
                  f"{entry.get('error') or 'ok'}", flush=True)
            record["commands"].append(entry)
    record["status"] = status_of(record["commands"])
    record["wall_s"] = round(sum(c["wall_s"] for c in record["commands"]), 2)
    (results / f"{section.key}.json").write_text(
        json.dumps(record, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    return record


def _now() -> str:
    return _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")


# ------------------------------------------------------------------ rendering
def fmt_seconds(x: float | None) -> str:
    """A time in readable units: µs, ms or s, three significant digits."""
    if x is None or not isinstance(x, (int, float)) or not math.isfinite(x):
        return "–"
    for scale, unit in ((1.0, "s"), (1e-3, "ms"), (1e-6, "µs"), (1e-9, "ns")):
        if abs(x) >= scale or unit == "ns":
            v = x / scale
            return f"{v:.3g} {unit}" if v < 1000 else f"{v:,.0f} {unit}"
    return f"{x:g} s"


def fmt_ratio(x: float | None) -> str:
    if x is None or not isinstance(x, (int, float)) or not math.isfinite(x):
        return "–"
    return f"{x:.3g}×" if x < 100 else f"{x:.0f}×"


def fmt_goal(fig: dict[str, Any]) -> str:
    goal = fig.get("goal")
    if not goal:
        return ""
    met = fig.get("met")
    return f"{goal}: " + ("met" if met else "**missed**" if met is False else "not judged")


def fmt_load(load: list[float] | None) -> str:
    return "unknown" if not load else " ".join(f"{x:.2f}" for x in load)


def load_results(results: Path) -> dict[str, dict[str, Any]]:
    """Every stored section record, by key (a missing or unreadable one is left out)."""
    out: dict[str, dict[str, Any]] = {}
    for key in SECTIONS:
        path = results / f"{key}.json"
        try:
            out[key] = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue
    return out


def render(results: Path = RESULTS, template: Path = TEMPLATE) -> str:
    """The page, from the stored section records and the template."""
    import jinja2

    env = jinja2.Environment(loader=jinja2.FileSystemLoader(str(template.parent)),
                             undefined=jinja2.StrictUndefined, keep_trailing_newline=True,
                             autoescape=False, trim_blocks=True, lstrip_blocks=True)
    env.filters.update(seconds=fmt_seconds, ratio=fmt_ratio, goal=fmt_goal, load=fmt_load)
    records = load_results(results)
    machines: list[dict[str, Any]] = []
    for rec in records.values():
        if rec.get("machine") not in machines:
            machines.append(rec.get("machine"))
    sections = {}
    for key, sec in SECTIONS.items():
        rec = records.get(key)
        sections[key] = {
            "key": key, "title": sec.title,
            "commands": [" ".join(["python", f"benchmarks/{c[0]}", *c[1:]])
                         for c in sec.commands],
            "record": rec,
            "machine_no": (machines.index(rec.get("machine")) + 1) if rec else None,
            "figures": [f for c in (rec or {}).get("commands", [])
                        for f in ((c.get("output") or {}).get("figures") or [])],
            "notes": [n for c in (rec or {}).get("commands", [])
                      for n in ((c.get("output") or {}).get("notes") or [])],
            "failures": [x for c in (rec or {}).get("commands", [])
                         for x in ([c["error"]] if c.get("error") else [])
                         + ((c.get("output") or {}).get("failures") or [])],
        }
    return env.get_template(template.name).render(sections=sections, machines=machines,
                                                  order=list(SECTIONS))


# ------------------------------------------------------------------ command line
def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--only", nargs="+", metavar="SECTION", choices=list(SECTIONS),
                    help="run only these sections (the others' stored figures are kept)")
    ap.add_argument("--list", action="store_true",
                    help="list the sections, their commands and rough durations; run nothing")
    ap.add_argument("--quick", action="store_true",
                    help="fewer repeats, shorter records: a smoke test, marked on the page")
    ap.add_argument("--render", action="store_true",
                    help="run nothing; render the page from the stored results")
    ap.add_argument("--out", type=Path, default=PAGE, help="the page (docs/performance.md)")
    ap.add_argument("--results", type=Path, default=RESULTS,
                    help="where each section's JSON and log are kept (benchmarks/results)")
    ap.add_argument("--timeout", type=float, default=None,
                    help="stop a benchmark after this many seconds (default: none)")
    args = ap.parse_args(argv)
    if args.list:
        for sec in SECTIONS.values():
            cmds = "; ".join(" ".join(["python", f"benchmarks/{c[0]}", *c[1:]])
                             for c in sec.commands)
            print(f"{sec.key:10s} ~{sec.minutes:g} min  {sec.title}: {cmds}")
        return 0
    if args.timeout is not None and not args.timeout > 0:
        ap.error(f"--timeout: need seconds > 0 (got {args.timeout})")
    if not args.render:
        for key in args.only or list(SECTIONS):
            run_section(SECTIONS[key], args.results, args.quick, args.timeout)
    page = render(args.results)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(page, encoding="utf-8")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""The figures a benchmark prints, as data: its ``--json PATH`` option.

Every benchmark a published figure comes from takes ``--json PATH`` and, besides its usual
printout, writes one JSON object there (``benchmarks/run_all.py`` collects them and renders
``docs/performance.md`` from them)::

    {"benchmark": "<script stem>", "section": "<heading>", "command": "<command line>",
     "figures": [{"what": "<case>", "pounding": <s>, "peer": "<peer tool>",
                  "peer_time": <s>, "ratio": <float>, "ratio_meaning": "<peer / pounding>",
                  "goal": "<'>= 100x'> or null", "met": <bool or null>,
                  "spread": "<text> or null", "unit_note": "<text> or null"}],
     "notes": ["<one-line fact>"], "failures": ["<section that failed: why>"]}

Times are in seconds. The ratio is computed here from the two times of the same run:
``peer_time / pounding`` when ``ratio_meaning`` starts with the peer, ``pounding /
peer_time`` when it starts with "pounding". ``met`` is worked out from ``goal`` when the
goal is a comparison with a number (``>= 100x``, ``<= 1.5x``). ``failures`` (optional) lists
the parts of the benchmark that raised: run_all reports them instead of their figures.

A script uses the module-level recorder: ``add_json_option(ap)`` on its parser,
``start(benchmark, section)`` once, ``figure(...)`` / ``note(...)`` / ``failure(...)``
where it prints, and ``write(args.json)`` at the end (a no-op without ``--json``).
"""

from __future__ import annotations

import argparse
import json
import math
import re
import shlex
import sys
from pathlib import Path
from typing import Any

_STATE: dict[str, Any] = {"benchmark": None, "section": None, "figures": [], "notes": [],
                          "failures": []}

_GOAL = re.compile(r"^\s*(>=|<=|>|<|≥|≤)\s*([0-9.eE+-]+)\s*[x×]?\s*$")


def add_json_option(ap: argparse.ArgumentParser) -> None:
    """``--json PATH``: write the printed figures as JSON too (``benchmarks/_figures.py``)."""
    ap.add_argument("--json", type=Path, default=None, metavar="PATH",
                    help="also write the figures printed, with the peer's time of the same "
                         "run, as one JSON object to PATH (read by benchmarks/run_all.py)")


def start(benchmark: str, section: str) -> None:
    """Begin a record: the script's stem and the heading its figures belong under."""
    _STATE.update(benchmark=benchmark, section=section, figures=[], notes=[], failures=[])


def goal_met(goal: str | None, ratio: float) -> bool | None:
    """Whether ``ratio`` meets a goal written as ``'>= 100x'`` or ``'<= 1.5x'``; None if
    there is no goal or it is not such a comparison."""
    if goal is None or not math.isfinite(ratio):
        return None
    m = _GOAL.match(goal)
    if not m:
        return None
    op, value = m.group(1), float(m.group(2))
    return {">=": ratio >= value, "≥": ratio >= value, "<=": ratio <= value,
            "≤": ratio <= value, ">": ratio > value, "<": ratio < value}[op]


def ratio_of(pounding: float, peer_time: float, ratio_meaning: str) -> float:
    """The ratio the meaning names, from the two times: ``pounding / peer`` when the meaning
    starts with "pounding", else ``peer / pounding``."""
    num, den = ((pounding, peer_time) if ratio_meaning.strip().lower().startswith("pounding")
                else (peer_time, pounding))
    return num / den if den > 0 else float("nan")


def figure(what: str, pounding: float, peer: str, peer_time: float, *,
           ratio_meaning: str = "peer / pounding", goal: str | None = None,
           met: bool | None = None, spread: str | None = None,
           unit_note: str | None = None) -> dict[str, Any]:
    """Record one figure: pounding's time and its peer's (seconds, the same run)."""
    ratio = ratio_of(float(pounding), float(peer_time), ratio_meaning)
    fig = {"what": what, "pounding": float(pounding), "peer": peer,
           "peer_time": float(peer_time), "ratio": ratio, "ratio_meaning": ratio_meaning,
           "goal": goal, "met": goal_met(goal, ratio) if met is None else met,
           "spread": spread, "unit_note": unit_note}
    _STATE["figures"].append(fig)
    return fig


def note(text: str) -> None:
    """A one-line fact worth printing under the section's table."""
    _STATE["notes"].append(str(text))


def failure(text: str) -> None:
    """A part of the benchmark that raised (its figures are missing)."""
    _STATE["failures"].append(str(text))


def command_line(argv: list[str] | None = None) -> str:
    """The command that repeats this run: ``python benchmarks/<script> <arguments>``
    without ``--json PATH``."""
    argv = list(sys.argv if argv is None else argv)
    script, rest = argv[0], argv[1:]
    kept: list[str] = []
    skip = False
    for a in rest:
        if skip:
            skip = False
            continue
        if a == "--json":
            skip = True
            continue
        if a.startswith("--json="):
            continue
        kept.append(a)
    return " ".join(["python", f"benchmarks/{Path(script).name}", *map(shlex.quote, kept)])


def record() -> dict[str, Any]:
    """The JSON object as it stands."""
    return {"benchmark": _STATE["benchmark"], "section": _STATE["section"],
            "command": command_line(), "figures": list(_STATE["figures"]),
            "notes": list(_STATE["notes"]), "failures": list(_STATE["failures"])}


def _clean(x: Any) -> Any:
    """NaN and infinities as null (JSON has none)."""
    if isinstance(x, float) and not math.isfinite(x):
        return None
    if isinstance(x, dict):
        return {k: _clean(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_clean(v) for v in x]
    return x


def write(path: Path | None) -> None:
    """Write the record to ``path`` (nothing without ``--json``)."""
    if path is None:
        return
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(_clean(record()), indent=1, ensure_ascii=False) + "\n",
                    encoding="utf-8")


def opensees_name() -> str:
    """``OpenSeesPy <version>`` as installed (the peer's name in a figure)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return f"OpenSeesPy {version('openseespy')}"
    except PackageNotFoundError:
        return "OpenSeesPy (version unknown)"

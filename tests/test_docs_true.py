"""Sentences of docs/ that describe the code, checked against the code."""

from __future__ import annotations

import re
from pathlib import Path

from pounding.integrate import default_step_budget
from pounding.result import ENERGY_NAMES
from pounding.studies.sweep.bridge_measures import BRIDGE_MEASURES
from pounding.studies.sweep.hinge_measures import HINGE_MEASURES
from pounding.studies.sweep.measures import FLOOR_MEASURES, MEASURES, ROTATION_NAMES

DOCS = Path(__file__).resolve().parents[1] / "docs"


def _flat(name: str) -> str:
    return " ".join((DOCS / name).read_text(encoding="utf-8").split())


def test_the_sweep_table_lists_every_column_in_the_order_written() -> None:
    text = (DOCS / "sweep.md").read_text(encoding="utf-8")
    table = text.split("| column | type | |", 1)[1].split("\n\n", 1)[0]
    names: list[str] = []
    for row in table.splitlines()[2:]:
        first = row.split("|")[1]
        names += re.findall(r"`([^`]+)`", first) or [first.strip()]
    floor = [n.removesuffix("_B<b>F<f>") for n in names if n.endswith("_B<b>F<f>")]
    # a floor's rotation in plan: its own names, in radians (ROTATION_NAMES), in one row
    rotation = [n.removesuffix("_B<b>F<f>θ") for n in names if n.endswith("_B<b>F<f>θ")]
    assert rotation == [ROTATION_NAMES[m] for m in FLOOR_MEASURES]
    assert names[:2] == ["case_index", "case_id"]
    assert names[2] == "one per parameter"
    assert names[3:5] == ["status", "error"]
    assert names[5:5 + len(MEASURES)] == list(MEASURES)
    # then, for a model with plastic hinges only, their columns
    after = 5 + len(MEASURES)
    assert names[after:after + len(HINGE_MEASURES)] == list(HINGE_MEASURES)
    assert floor == list(FLOOR_MEASURES)
    # then, for a bridge only, its seats' and restrainers' columns, in the table's order
    bridge = [n.split("_<")[0] for n in names if n.endswith(("_<seat>", "_<restrainer>"))]
    assert bridge == list(BRIDGE_MEASURES)
    assert names[-1 - len(bridge):-1] == [f"{n}_<restrainer>" if n == "peak_force_N"
                                          else f"{n}_<seat>" for n in BRIDGE_MEASURES]
    assert names[-1] == "wall_time_s"
    assert len(names) == (5 + len(MEASURES) + len(HINGE_MEASURES) + 2 * len(FLOOR_MEASURES)
                          + len(BRIDGE_MEASURES) + 1)


def test_every_energy_term_is_named_where_the_docs_list_them() -> None:
    running = _flat("running.md")
    listed = re.search(r"`energy` \[J\] \(([^)]*)\)", running)
    assert listed is not None
    assert re.findall(r"`([a-z_]+)`", listed.group(1)) == list(ENERGY_NAMES)
    engine = _flat("engine.md")
    assert "eight terms" in engine and len(ENERGY_NAMES) == 8
    assert all(f"`{name}`" in engine for name in ENERGY_NAMES)
    # the closure of the balance includes the links wherever it is written out
    assert "W_c + E_links)|" in engine
    assert "W_contact + E_links" in _flat("storey_laws.md")


def test_the_step_budget_is_the_one_the_docs_give() -> None:
    engine = _flat("engine.md")
    assert "`100 · n_grid + 100,000`" in engine
    assert default_step_budget(39_991) == 4_099_100 and "4,099,100" in engine
    assert default_step_budget(3_001) == 400_100 and "400,100" in engine


def test_the_readme_points_only_at_files_that_exist() -> None:
    root = DOCS.parent
    readme = (root / "README.md").read_text(encoding="utf-8")
    named = set(re.findall(r"(?<![\w/])((?:docs|examples|benchmarks)/[\w./-]+\.(?:md|toml|py))",
                           readme))
    assert "docs/performance.md" in named and (root / "LICENSE").is_file()
    missing = sorted(n for n in named if not (root / n).is_file())
    assert not missing, missing
    # a guide, not a log: the dated measurements live in docs/performance.md
    assert len(readme.splitlines()) <= 200
    assert len(re.findall(r"2026-\d\d-\d\d", readme)) == 0

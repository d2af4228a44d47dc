"""The results table: every part consolidated into ``results.parquet`` (one row per case,
in case order, columns and types fixed by the sweep), and reading it back."""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pounding.studies.sweep.bridge_measures import BRIDGE_MEASURES, bridge_column_key
from pounding.studies.sweep.cases import _canon
from pounding.studies.sweep.hinge_measures import HINGE_MEASURES
from pounding.studies.sweep.measures import FLOOR_MEASURES, MEASURES
from pounding.studies.sweep.store import RESULTS_FILE

if TYPE_CHECKING:
    from pounding.studies.sweep.sweep_file import Sweep

__all__ = ["NONDETERMINISTIC_COLUMNS", "load_results"]

NONDETERMINISTIC_COLUMNS: tuple[str, ...] = ("wall_time_s",)
"""Columns of ``results.parquet`` that differ between runs (seconds spent on a case:
validation, building, integration and reduction). Every other column is bit-identical."""


def _param_array(values: list[Any]) -> Any:
    """A parameter's column: bool, int64, float64 or string; lists and tables as JSON."""
    import pyarrow as pa

    if all(isinstance(v, bool) for v in values):
        return pa.array(values, pa.bool_())
    if all(isinstance(v, int) and not isinstance(v, bool) for v in values):
        return pa.array(values, pa.int64())
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
        return pa.array([float(v) for v in values], pa.float64())
    if all(isinstance(v, str) for v in values):
        return pa.array(values, pa.string())
    return pa.array([_canon(v) for v in values], pa.string())


def _floor_key(column: str) -> tuple[int, int, int, str]:
    """Sort key of a per-floor column: measure, then building, then floor."""
    import re

    for gi, name in enumerate(FLOOR_MEASURES):
        if column.startswith(name + "_"):
            m = re.fullmatch(r"B(\d+)F(\d+)", column[len(name) + 1:])
            if m:
                return gi, int(m.group(1)), int(m.group(2)), column
    return len(FLOOR_MEASURES), 0, 0, column


def _consolidate(sweep: Sweep, rows: dict[str, dict[str, Any]]) -> Any:
    """The results table: one row per case in case order, columns and types fixed."""
    import pyarrow as pa

    cases = sweep.cases
    recs = [rows[c.id] for c in cases]
    cols: dict[str, Any] = {
        "case_index": pa.array([c.index for c in cases], pa.int64()),
        "case_id": pa.array([c.id for c in cases], pa.string()),
    }
    for j, p in enumerate(sweep.params):
        cols[p] = _param_array([c.values[j] for c in cases])
    cols["status"] = pa.array([r["status"] for r in recs], pa.string())
    cols["error"] = pa.array([r.get("error") for r in recs], pa.string())
    types = {"float64": pa.float64(), "int64": pa.int64(), "bool": pa.bool_()}
    for name, typ in MEASURES.items():
        cols[name] = pa.array([r.get(name) for r in recs], types[typ])
    names: set[str] = set()
    for r in recs:
        names.update(r)
    if names & set(HINGE_MEASURES):  # models with plastic hinges only
        for name, typ in HINGE_MEASURES.items():
            cols[name] = pa.array([r.get(name) for r in recs], types[typ])
    floor_cols = sorted((k for k in names if k.startswith(FLOOR_MEASURES)), key=_floor_key)
    for name in floor_cols:
        cols[name] = pa.array([r.get(name) for r in recs], pa.float64())
    bridge = sorted((k for k in names if k not in cols and bridge_column_key(k) is not None),
                    key=lambda k: bridge_column_key(k) or ())
    for name in bridge:  # a bridge's seats and restrainers
        typ = BRIDGE_MEASURES[next(p for p in BRIDGE_MEASURES if name.startswith(p + "_"))]
        cols[name] = pa.array([r.get(name) for r in recs], types[typ])
    cols["wall_time_s"] = pa.array([r.get("wall_time_s") for r in recs], pa.float64())
    meta = {"pounding.sweep": _canon({"name": sweep.name, "params": list(sweep.params),
                                      "fingerprint": sweep.fingerprint,
                                      "nondeterministic_columns":
                                          list(NONDETERMINISTIC_COLUMNS)})}
    return pa.table(cols).replace_schema_metadata(meta)


def _write_results(sweep: Sweep, rows: dict[str, dict[str, Any]], out: Path
                   ) -> tuple[Path, int]:
    """Consolidate ``rows`` into ``<out>/results.parquet`` (atomically, recorded in the
    manifest of ``out``; an earlier table is replaced only if pounding wrote it).

    Returns
    -------
    path : Path
        The table written.
    n_errors : int
        Cases whose status is not ``"ok"``.
    """
    import pyarrow.parquet as pq

    from pounding.io.manifest import Manifest

    table = _consolidate(sweep, rows)
    results = out / RESULTS_FILE
    with Manifest(out).write(results) as tmp:
        pq.write_table(table, tmp)
    n_err = sum(1 for s in table.column("status").to_pylist() if s != "ok")
    return results, n_err


def load_results(path: str | os.PathLike[str], deterministic: bool = False) -> Any:
    """Read a results table (a ``results.parquet`` or its sweep folder) as a DataFrame.

    With ``deterministic`` the columns that vary between runs are left out
    (:data:`NONDETERMINISTIC_COLUMNS`): what remains is bit-identical between two runs.
    """
    from pounding.studies.sweep.extra import require_sweep_packages

    require_sweep_packages("reading a sweep's table", dask=False)
    import pyarrow.parquet as pq

    p = Path(path)
    if p.is_dir():
        p = p / RESULTS_FILE
    if not p.is_file():
        raise ValueError(f"{path}: no sweep results here (expected {RESULTS_FILE})")
    table = pq.read_table(p)
    if deterministic:
        table = table.drop_columns([c for c in NONDETERMINISTIC_COLUMNS
                                    if c in table.column_names])
    return table.to_pandas()

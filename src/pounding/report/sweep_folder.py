"""What a sweep folder holds: the results table, read, its columns told apart into swept
parameters and measures (:func:`read_sweep`)."""

from __future__ import annotations

import json
import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd

from pounding.report.format import unit_of, with_unit

__all__ = ["MEASURE_PREFERENCE", "SWEEP_FILE", "SweepFolder", "is_numeric", "read_sweep"]

SWEEP_FILE = "results.parquet"
"""The file that makes a folder a sweep output."""

MEASURE_PREFERENCE: tuple[str, ...] = (
    "peak_contact_force_N", "peak_force_N", "peak_contact_force", "n_impacts",
    "contact_dissipated_J", "peak_displacement_m", "peak_drift_m",
)
"""The main measure of a sweep is the first of these present (else the first measure)."""

_MEASURE_HINTS = ("peak", "n_impacts", "impacts", "dissipated", "energy", "error", "drift",
                  "displacement", "force", "penetration", "wall_time", "critical", "touched",
                  "status", "ok", "error_message", "max_", "min_", "mean_", "rk_steps",
                  "rejected", "events", "overflow")


@dataclass
class SweepFolder:
    """The results of a sweep: one row per case, the parameter and measure columns, the
    main measure (None without a numeric measure), the stated units, the metadata, and how
    the parameters were recognised."""

    df: pd.DataFrame
    parameters: list[str]
    measures: list[str]
    main: str | None
    units: dict[str, str]
    meta: dict[str, Any]
    how: str

    def label(self, column: str) -> str:
        """``column [unit]``, or ``column`` alone when its unit is not known."""
        return with_unit(column, unit_of(column, self.units))


def is_numeric(s: pd.Series) -> bool:
    """Numbers or booleans (shown right-aligned, summarised)."""
    return bool(pd.api.types.is_numeric_dtype(s) or pd.api.types.is_bool_dtype(s))


def read_sweep(folder: Path) -> SweepFolder:
    """Read ``results.parquet`` of the sweep folder ``folder`` and its metadata.

    Raises
    ------
    ValueError
        ``results.parquet`` is not a readable Parquet file, or pyarrow (the sweep extra)
        is not installed.
    """
    from pounding.studies.sweep.extra import require_sweep_packages

    require_sweep_packages("the report of a sweep", dask=False)  # (pyarrow reads Parquet)
    path = folder / SWEEP_FILE
    try:
        df = pd.read_parquet(path)
    except Exception as exc:  # noqa: BLE001  (pyarrow raises many kinds)
        raise ValueError(f"report: {path}: unreadable Parquet file ({exc})") from None
    df.columns = [str(c) for c in df.columns]
    meta = {**_side_meta(folder), **_parquet_meta(path)}
    params, measures, how = _classify(df, meta)
    units = _find_units(meta)
    numeric = [m for m in measures if is_numeric(df[m]) and not pd.api.types.is_bool_dtype(df[m])]
    main = next((m for m in MEASURE_PREFERENCE if m in numeric), numeric[0] if numeric else None)
    return SweepFolder(df, params, measures, main, units, meta, how)


def _parquet_meta(path: Path) -> dict[str, Any]:
    """JSON metadata stored in the Parquet schema by the writer (pandas' own excluded)."""
    try:
        import pyarrow.parquet as pq

        raw = pq.read_schema(path).metadata or {}
    except Exception:  # noqa: BLE001  (metadata is optional)
        return {}
    out: dict[str, Any] = {}
    for k, v in raw.items():
        key = k.decode("utf-8", "replace")
        if key in ("pandas", "ARROW:schema"):
            continue
        text = v.decode("utf-8", "replace")
        try:
            out[key] = json.loads(text)
        except json.JSONDecodeError:
            out[key] = text
    return out


def _side_meta(folder: Path) -> dict[str, Any]:
    """A JSON description of the sweep beside the results, if the sweep wrote one."""
    for name in ("sweep.json", "meta.json", "metadata.json", "grid.json", "study.json"):
        p = folder / name
        if p.is_file():
            try:
                data = json.loads(p.read_text(encoding="utf-8"))
            except (OSError, json.JSONDecodeError):
                continue
            if isinstance(data, dict):
                return {"_file": name, **data}
    return {}


def _find_list(meta: dict[str, Any], keys: Sequence[str]) -> list[str] | None:
    """The first list (or dict keys) under one of ``keys``, searched one level deep too."""
    for where in [meta, *[v for v in meta.values() if isinstance(v, dict)]]:
        for k in keys:
            v = where.get(k)
            if isinstance(v, dict) and v:
                return [str(x) for x in v]
            if isinstance(v, list) and v and all(isinstance(x, str) for x in v):
                return [str(x) for x in v]
    return None


def _find_units(meta: dict[str, Any]) -> dict[str, str]:
    for where in [meta, *[v for v in meta.values() if isinstance(v, dict)]]:
        v = where.get("units")
        if isinstance(v, dict):
            return {str(k): str(u) for k, u in v.items()}
    return {}


def _classify(df: pd.DataFrame, meta: dict[str, Any]) -> tuple[list[str], list[str], str]:
    cols = [str(c) for c in df.columns]
    params = _find_list(meta, ("parameters", "params", "grid", "swept", "axes"))
    measures = _find_list(meta, ("measures", "outputs", "metrics"))
    if params:
        params = [p for p in params if p in cols]
    if measures:
        measures = [m for m in measures if m in cols]
    book = {"case_index", "case_id", "status", "error", "case", "index", "id"}
    if params:
        rest = [c for c in cols if c not in params and c not in book]
        return params, measures or [c for c in rest if is_numeric(df[c])], \
            "parameters as stated in the sweep's metadata"
    if measures:
        return [c for c in cols if c not in measures and c not in book], measures, \
            "measures as stated in the sweep's metadata; the other columns taken as parameters"
    # heuristics: prefixed parameter columns, else columns not named like a measure
    pref = [c for c in cols if c.startswith(("param.", "param_", "p.", "parameter."))]
    if pref:
        return pref, [c for c in cols if c not in pref and is_numeric(df[c])], \
            "parameters: the columns prefixed param"
    ignore = book | {"run", "folder", "path", "out_dir", "seed"}
    params, measures = [], []
    for c in cols:
        low = c.lower()
        if low in ignore:
            continue
        if any(h in low for h in _MEASURE_HINTS) or re.search(r"_(N|J)$", c):
            if is_numeric(df[c]):
                measures.append(c)
            continue
        if df[c].nunique(dropna=False) <= max(1, min(len(df), 50)):
            params.append(c)
    return params, measures, ("parameters and measures told apart by their names (the "
                              "results file does not list them)")

"""Parameter sweeps: one base model, many cases, one tidy Parquet table — run on Dask.

A sweep file (TOML, see ``docs/sweep.md``) names a base model file (or holds one inline)
and the cases: a ``[grid]`` (every combination), a ``[list]`` (columns zipped row by row)
or ``[random]`` samples drawn with a seed. Parameters are dotted paths into the model
file: ``"contact.gap"``, ``"contact.e"``, ``"record.scale"``, ``"building.0.period"``,
``"building.*.period"`` (every building), ``"contact.law"``, ``"record.file"``, …

Every case gets a deterministic id, a hash of its parameter values. Each case is applied to
the base configuration, validated by :mod:`pounding.config` (a bad value names the key),
built, simulated and reduced to one row of summary measures. A case that fails is recorded
(``status = "error"`` and the message) and the sweep goes on; an invalid base model or an
unknown parameter path stops the sweep before anything runs.

Persistence is loss-free and resumable. Cases run in batches (one Dask task each); the
client writes every finished batch as a small Parquet file ``parts/part-<hash>.parquet``
(temporary name, then rename) the moment it arrives. A sweep that is started again — after
Ctrl-C, a crash or SIGKILL — reads the parts present and runs only the missing cases. At the
end all parts are consolidated into ``results.parquet``, rows in case order, columns and
types fixed by the sweep: two runs of the same sweep give tables equal bit for bit in every
column except ``wall_time_s`` (:data:`NONDETERMINISTIC_COLUMNS`).
"""

from __future__ import annotations

import contextlib
import copy
import hashlib
import itertools
import json
import math
import os
import shutil
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from pounding.io import read_toml

__all__ = [
    "FLOOR_MEASURES",
    "MEASURES",
    "NONDETERMINISTIC_COLUMNS",
    "Case",
    "Sweep",
    "SweepOutcome",
    "apply_overrides",
    "case_id",
    "load_results",
    "load_sweep",
    "parse_sweep",
    "run_case",
    "run_sweep",
]

RESULTS_FILE = "results.parquet"
PARTS_DIR = "parts"
HISTORIES_DIR = "histories"
MANIFEST_FILE = "sweep.json"

MEASURES: dict[str, str] = {
    "n_impacts": "int64",
    "peak_contact_force_N": "float64",
    "contact_dissipated_J": "float64",
    "energy_input_J": "float64",
    "energy_balance_error": "float64",
    "peak_drift_ratio": "float64",
    "record_pga_g": "float64",
    "impact_overflow": "bool",
    "hysteretic_energy_J": "float64",
    "max_ductility": "float64",
    "max_residual_drift_m": "float64",
    "max_column_shear_ratio": "float64",
}
"""Measures of every case (column → type): impacts (all contacts), largest contact force,
energy dissipated in the contacts and put in by the ground at the end, relative
energy-balance error, largest storey drift / storey height over all storeys, PGA of the
record as applied, whether the impact table overflowed; with yielding storeys the
hysteretic energy at the end, the largest storey ductility demand and the largest
|residual drift| (null, null and 0 for linear storeys); with floor-to-column contacts the
largest struck-column shear over its storey's peak shear (null without)."""

FLOOR_MEASURES: tuple[str, ...] = ("peak_displacement_m", "peak_drift_m", "peak_abs_accel_m_s2")
"""Per-floor measures, one column per floor: ``<measure>_B1F1``, ``<measure>_B1F2``, …
(floor displacement relative to the ground, storey drift, absolute floor acceleration)."""

NONDETERMINISTIC_COLUMNS: tuple[str, ...] = ("wall_time_s",)
"""Columns of ``results.parquet`` that differ between runs (seconds spent on a case:
validation, building, integration and reduction). Every other column is bit-identical."""

HISTORY_FORMATS = ("netcdf", "zarr")


# ============================================================================ the sweep file
@dataclass(frozen=True)
class Case:
    """One case: its position in the sweep, its id and its parameter values."""

    index: int
    id: str
    values: tuple[Any, ...]


@dataclass
class Sweep:
    """A parsed sweep file (:func:`load_sweep`)."""

    name: str
    base: dict[str, Any]
    """The base model configuration as plain data (validated)."""
    base_dir: Path
    """Where relative paths of the base model start."""
    params: tuple[str, ...]
    cases: list[Case]
    out: Path
    histories: str | None = None
    batch_size: int | None = None
    source: Path | None = None
    duplicates: int = 0
    """Cases given twice (same values): run once."""
    records: dict[str, Any] = field(default_factory=dict, repr=False)

    @property
    def fingerprint(self) -> str:
        """Hash of everything that decides the table (base model, parameters, cases)."""
        text = _canon({"base": self.base, "base_dir": str(self.base_dir),
                       "params": list(self.params), "cases": [c.id for c in self.cases]})
        return hashlib.sha256(text.encode()).hexdigest()[:20]


def _canon(value: Any) -> str:
    """Canonical JSON (sorted keys, float repr): equal values give equal text."""
    return json.dumps(value, sort_keys=True, separators=(",", ":"), ensure_ascii=False,
                      allow_nan=False)


def case_id(params: Sequence[str], values: Sequence[Any]) -> str:
    """The id of a case: 16 hex digits of a hash of its ``{parameter: value}`` (order-free)."""
    text = _canon(dict(zip(params, values)))
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _norm(value: Any, where: str) -> Any:
    """A parameter value as plain TOML data (checks it is finite)."""
    if isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f"{where}: values must be finite (got {value!r})")
    if isinstance(value, (np.floating,)):
        return float(value)
    if isinstance(value, (np.integer,)):
        return int(value)
    return value


def _random_cases(table: dict[str, Any], where: str) -> tuple[tuple[str, ...], list[tuple]]:
    t = dict(table)
    n = t.pop("n", None)
    seed = t.pop("seed", None)
    if not isinstance(n, int) or isinstance(n, bool) or n < 1:
        raise ValueError(f"{where}: random.n: the number of samples, an integer >= 1 "
                         f"(got {n!r})")
    if not isinstance(seed, int) or isinstance(seed, bool):
        raise ValueError(f"{where}: random.seed: required, an integer (got {seed!r})")
    if not t:
        raise ValueError(f"{where}: random: give at least one parameter, e.g. "
                         "\"contact.gap\" = [0.0, 0.05]")
    draws: list[Callable[[np.random.Generator], Any]] = []
    for key, spec in t.items():
        w = f"{where}: random.{key}"
        if isinstance(spec, list):
            spec = {"uniform": spec}
        if not isinstance(spec, dict) or len(spec) != 1:
            raise ValueError(f"{w}: give [low, high] (uniform) or one of {{ uniform = [a, b] }}"
                             f", {{ log = [a, b] }}, {{ int = [a, b] }}, {{ choice = [...] }} "
                             f"(got {spec!r})")
        (kind, arg), = spec.items()
        if kind == "choice":
            if not isinstance(arg, list) or not arg:
                raise ValueError(f"{w}: choice needs a non-empty list (got {arg!r})")
            draws.append(lambda g, a=arg: a[int(g.integers(len(a)))])
            continue
        if (not isinstance(arg, list) or len(arg) != 2
                or not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in arg)
                or not arg[0] < arg[1]):
            raise ValueError(f"{w}: {kind} needs [low, high] with low < high (got {arg!r})")
        lo, hi = arg
        if kind == "uniform":
            draws.append(lambda g, a=float(lo), b=float(hi): float(g.uniform(a, b)))
        elif kind == "log":
            if lo <= 0:
                raise ValueError(f"{w}: log needs low > 0 (got {arg!r})")
            draws.append(lambda g, a=math.log(lo), b=math.log(hi): float(math.exp(g.uniform(a, b))))
        elif kind == "int":
            draws.append(lambda g, a=int(lo), b=int(hi): int(g.integers(a, b, endpoint=True)))
        else:
            raise ValueError(f"{w}: unknown distribution {kind!r}; use uniform, log, int or "
                             "choice")
    gen = np.random.Generator(np.random.PCG64(seed))
    rows = [tuple(d(gen) for d in draws) for _ in range(n)]
    return tuple(t), rows


def parse_sweep(data: dict[str, Any], base_dir: str | os.PathLike[str] = ".",
                where: str = "sweep") -> Sweep:
    """Validate a parsed sweep file; ``base_dir`` is where its relative paths start.

    Raises
    ------
    ValueError
        One message naming the key at fault: a bad sweep table, an unknown parameter
        path, or an invalid base model (its own validation message).
    """
    from pounding.config import SWEEP_CASE_TABLES, load_config, parse_config

    here = Path(base_dir).resolve()
    known = {"name", "base", "out", "histories", "batch_size", *SWEEP_CASE_TABLES}
    extra = sorted(set(data) - known)
    if extra:
        raise ValueError(f"{where}: unknown key(s) {', '.join(extra)}; keys of a sweep file: "
                         f"{', '.join(sorted(known))}")
    base = data.get("base")
    if isinstance(base, str):
        cfg = load_config(here / base)
        model_dir = (here / base).resolve().parent
    elif isinstance(base, dict):
        cfg = parse_config(base, base_dir=here, where=f"{where}: base")
        model_dir = here
    else:
        raise ValueError(f"{where}: base: required, the model file (base = \"model.toml\", "
                         f"relative to the sweep file) or an inline [base] table (got {base!r})")
    base_data = cfg.to_dict(resolve_paths=True)
    base_data.setdefault("output", {})["figures"] = False

    kinds = [k for k in SWEEP_CASE_TABLES if k in data]
    if len(kinds) != 1:
        raise ValueError(f"{where}: give exactly one of [grid], [list] and [random] "
                         f"(got {', '.join(kinds) or 'none'})")
    kind = kinds[0]
    table = data[kind]
    if not isinstance(table, dict):
        raise ValueError(f"{where}: {kind} must be a table (got {table!r})")
    if kind == "random":
        params, rows = _random_cases(table, where)
    else:
        params = tuple(table)
        if not params:
            raise ValueError(f"{where}: [{kind}] is empty; give e.g. \"contact.gap\" = [0.01, "
                             "0.02]")
        cols = []
        for key, vals in table.items():
            if not isinstance(vals, list) or not vals:
                raise ValueError(f"{where}: {kind}.{key}: a non-empty list of values "
                                 f"(got {vals!r})")
            cols.append([_norm(v, f"{where}: {kind}.{key}") for v in vals])
        if kind == "grid":
            rows = list(itertools.product(*cols))
        else:
            lengths = {len(c) for c in cols}
            if len(lengths) != 1:
                raise ValueError(f"{where}: list: every parameter needs the same number of "
                                 f"values (got {dict(zip(params, map(len, cols)))})")
            rows = list(zip(*cols))
    for p in params:
        _check_path(p, base_data, where)
    # record files in the cases are relative to the sweep file: make them absolute
    rows = [tuple(_resolve_value(p, v, here) for p, v in zip(params, r)) for r in rows]
    seen: set[str] = set()
    cases = []
    for r in rows:
        cid = case_id(params, r)
        if cid in seen:
            continue
        seen.add(cid)
        cases.append(Case(len(cases), cid, tuple(r)))
    hist = data.get("histories", False)
    if hist is False or hist is None or hist == "none":
        hist = None
    elif hist not in HISTORY_FORMATS:
        raise ValueError(f"{where}: histories: false, \"netcdf\" or \"zarr\" (got {hist!r})")
    batch = data.get("batch_size")
    if batch is not None and (not isinstance(batch, int) or isinstance(batch, bool) or batch < 1):
        raise ValueError(f"{where}: batch_size: an integer >= 1 (got {batch!r})")
    out = data.get("out", f"{data.get('name', 'sweep')}-results")
    if not isinstance(out, str) or not out:
        raise ValueError(f"{where}: out: a folder name (got {out!r})")
    sweep = Sweep(name=str(data.get("name", "sweep")), base=base_data, base_dir=model_dir,
                  params=params, cases=cases, out=here / out, histories=hist,
                  batch_size=batch, duplicates=len(rows) - len(cases))
    _check_first_case(sweep, where)
    return sweep


def load_sweep(path: str | os.PathLike[str]) -> Sweep:
    """Read and validate a sweep file (see :func:`parse_sweep`)."""
    p = Path(path)
    data = read_toml(p, "sweep file")
    sweep = parse_sweep(data, base_dir=p.resolve().parent, where=str(p))
    sweep.source = p.resolve()
    return sweep


def _resolve_value(path: str, value: Any, here: Path) -> Any:
    if path.split(".")[-1] == "file" and path.startswith("record") and isinstance(value, str):
        return str((here / Path(value).expanduser()).resolve())
    return value


def _check_path(path: str, base: dict[str, Any], where: str) -> None:
    """Fail fast on a parameter path that names no key of a model file."""
    from pydantic import BaseModel

    from pounding.config import RunConfig

    model: Any = RunConfig
    node: Any = base
    parts = path.split(".")
    for i, part in enumerate(parts):
        at = ".".join(parts[: i + 1])
        if isinstance(node, list):
            if part == "*":
                node = node[0] if node else None
                continue
            if not part.isdigit() or int(part) >= len(node):
                raise ValueError(f"{where}: {path}: {at}: need an index 0 … {len(node) - 1} "
                                 "or * (every one)")
            node = node[int(part)]
            continue
        if not (isinstance(model, type) and issubclass(model, BaseModel)):
            raise ValueError(f"{where}: {path}: {'.'.join(parts[:i])} has no keys")
        fields = model.model_fields
        if part not in fields:
            import difflib
            close = difflib.get_close_matches(part, list(fields), n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            raise ValueError(f"{where}: {path}: unknown key {part!r}{hint} (keys here: "
                             f"{', '.join(sorted(fields))})")
        model = _unwrap(fields[part].annotation)
        node = node.get(part) if isinstance(node, dict) else None
        if isinstance(node, list) and i == len(parts) - 1:
            continue
        if node is None and i < len(parts) - 1 and isinstance(model, list):
            raise ValueError(f"{where}: {path}: the base model has no {at}")
        if isinstance(model, list):
            model = model[0]
            if i < len(parts) - 1 and not isinstance(node, list):
                node = [node]


def _unwrap(tp: Any) -> Any:
    """``X | None``, ``Annotated[X, ...]`` → X; ``list[X]`` → ``[X]``."""
    import types
    import typing

    for _ in range(8):
        origin = typing.get_origin(tp)
        args = [a for a in typing.get_args(tp) if a is not type(None)]
        if origin in (typing.Union, types.UnionType, typing.Annotated) and args:
            tp = args[0]
        elif origin is list and args:
            return [_unwrap(args[0])]
        else:
            return tp
    return tp


def _check_first_case(sweep: Sweep, where: str) -> None:
    """The first case must at least pass the key check (catches misspelt paths early)."""
    from pydantic import ValidationError

    from pounding.config import RunConfig, format_validation_error

    if not sweep.cases:
        raise ValueError(f"{where}: the sweep has no cases")
    data = apply_overrides(sweep.base, sweep.params, sweep.cases[0].values)
    try:
        RunConfig.model_validate(data, context={"base_dir": sweep.base_dir})
    except ValidationError as exc:
        unknown = [e for e in exc.errors(include_url=False) if e.get("type") == "extra_forbidden"]
        if unknown:
            raise ValueError(f"{where}: case 0: "
                             + format_validation_error(exc).replace("\n", "; ")) from None


# ============================================================================ one case
_EXCLUSIVE: dict[tuple[str, str], tuple[str, ...]] = {
    ("contact", "gap"): ("gaps",),
    ("contact", "gaps"): ("gap",),
    ("record", "scale"): ("pga_g",),
    ("record", "pga_g"): ("scale",),
    ("record", "file"): ("bundled",),
    ("record", "bundled"): ("file", "dt", "units"),
    ("building", "period"): ("stiffness",),
    ("building", "stiffness"): ("period",),
}
"""Setting the key on the left removes the keys on the right from the base (they are
alternatives in a model file: setting ``record.scale`` replaces a base ``pga_g``)."""


def apply_overrides(base: dict[str, Any], params: Sequence[str],
                    values: Sequence[Any]) -> dict[str, Any]:
    """A copy of the base configuration with each dotted path set to its value.

    Alternatives of a key are removed (:data:`_EXCLUSIVE`); a new ``contact.law`` drops the
    base's contact keys that law does not read (those set by the case are kept, so a
    mismatch is reported).
    """
    from pounding.config import LAW_FIELDS

    data = copy.deepcopy(base)
    set_contact: set[str] = set()
    for path, value in zip(params, values):
        parts = path.split(".")
        for node in _parents(data, parts[:-1]):
            key = parts[-1]
            section = parts[0]
            for other in _EXCLUSIVE.get((section, key), ()):
                node.pop(other, None)
            node[key] = copy.deepcopy(value)
        if parts[0] == "contact" and len(parts) == 2:
            set_contact.add(parts[1])
    contact = data.get("contact")
    if "law" in set_contact and isinstance(contact, dict) and isinstance(contact.get("law"), str):
        used = LAW_FIELDS.get(contact["law"].strip().lower())
        if used is not None:
            for key in list(contact):
                if key not in used | {"law", "gap", "gaps"} | set_contact:
                    del contact[key]
    return data


def _parents(data: Any, parts: list[str]) -> Iterator[dict[str, Any]]:
    """The tables that hold the last key of a dotted path (several with ``*``)."""
    if not parts:
        yield data
        return
    head, rest = parts[0], parts[1:]
    if isinstance(data, list):
        items = data if head == "*" else [data[int(head)]]
        for item in items:
            yield from _parents(item, rest)
    else:
        yield from _parents(data.setdefault(head, {}), rest)


def _error_text(exc: BaseException) -> str:
    from pydantic import ValidationError

    from pounding.config import format_validation_error

    if isinstance(exc, ValidationError):
        return format_validation_error(exc).replace("\n", "; ")
    if isinstance(exc, ValueError):
        return str(exc).replace("\n", "; ")
    return f"{type(exc).__name__}: {exc}".replace("\n", "; ")


def _measures(result: Any) -> dict[str, Any]:
    """One row of :data:`MEASURES` and :data:`FLOOR_MEASURES` from a Result."""
    labels = result.model.dof_labels()
    e = result.energy
    pcf = result.peak_contact_force
    from pounding.result import peak_abs

    drift = peak_abs(result.drift)
    heights = np.concatenate([b.heights for b in result.model.buildings])
    row: dict[str, Any] = {
        "n_impacts": int(result.n_impacts),
        "peak_contact_force_N": float(pcf.max()) if pcf.size else 0.0,
        "contact_dissipated_J": float(e[-1, 4] - e[-1, 5]),
        "energy_input_J": float(e[-1, 0]),
        "energy_balance_error": float(result.energy_balance_error),
        "peak_drift_ratio": float(np.max(drift / heights)),
        "record_pga_g": float(result.motion.pga_g),
        "impact_overflow": bool(result.stats.impact_overflow),
        # not applicable → null (not NaN: a null compares equal, so tables stay comparable)
        "hysteretic_energy_J": float(e[-1, 6]) if result.model.is_inelastic else None,
        "max_ductility": (float(np.nanmax(result.ductility)) if result.model.is_inelastic
                          else None),
        "max_residual_drift_m": float(np.max(np.abs(result.residual_drift))),
        "max_column_shear_ratio": (float(np.nanmax(result.column_shear_ratio))
                                   if np.isfinite(result.column_shear_ratio).any() else None),
    }
    floor = {
        "peak_displacement_m": result.peak_displacement,
        "peak_drift_m": drift,
        "peak_abs_accel_m_s2": peak_abs(result.abs_acceleration),
    }
    for name in FLOOR_MEASURES:
        for lb, v in zip(labels, floor[name]):
            row[f"{name}_{lb}"] = float(v)
    return row


def run_case(base: dict[str, Any], base_dir: str | os.PathLike[str], params: Sequence[str],
             values: Sequence[Any], history: bool = False) -> tuple[dict[str, Any], Any]:
    """Run one case: ``(row, dataset or None)``; a failure is reported in the row.

    The row holds ``status`` (``"ok"`` / ``"error"``), ``error`` (the message or None),
    the measures and ``wall_time_s``.
    """
    from pounding.config import RunConfig
    from pounding.integrate import simulate

    start = time.perf_counter()
    dataset = None
    try:
        data = apply_overrides(base, params, values)
        cfg = RunConfig.model_validate(data, context={"base_dir": Path(base_dir)})
        model, motion, solver = cfg.build()
        result = simulate(model, motion, **solver)
        row: dict[str, Any] = {"status": "ok", "error": None, **_measures(result)}
        if history:
            dataset = result.to_dataset()
    except Exception as exc:  # noqa: BLE001  (recorded in the table, the sweep goes on)
        row = {"status": "error", "error": _error_text(exc)}
    row["wall_time_s"] = time.perf_counter() - start
    return row, dataset


# ============================================================================ worker side
def _run_batch(payload: dict[str, Any], batch: list[tuple[int, str, tuple]]
               ) -> list[tuple[str, dict[str, Any], Any]]:
    """Run a batch of cases (one Dask task): ``[(case_id, row, dataset), ...]``."""
    out = []
    for _, cid, values in batch:
        row, ds = run_case(payload["base"], payload["base_dir"], payload["params"], values,
                           history=payload["histories"] is not None)
        out.append((cid, row, ds))
    return out


def warm_up() -> float:
    """Load the compiled kernel (numba's disk cache) in this process; seconds taken."""
    from pounding.ground_motion import GroundMotion
    from pounding.integrate import simulate
    from pounding.model import PoundingModel
    from pounding.structure import ShearBuilding

    start = time.perf_counter()
    b1 = ShearBuilding(masses=[1.0e5], stiffnesses=[4.0e7], heights=[3.0], name="a")
    b2 = ShearBuilding(masses=[1.0e5], stiffnesses=[1.0e7], heights=[3.0], name="b")
    from pounding.model import ContactSpec
    model = PoundingModel([b1, b2], [0.001], ContactSpec("nonlinear-viscoelastic", k_h=2.75e9,
                                                         e=0.65))
    t = np.arange(101) * 0.01
    gm = GroundMotion(dt=0.01, accel=3.0 * np.sin(2 * np.pi * t), name="warm-up")
    simulate(model, gm)
    return time.perf_counter() - start


# ============================================================================ persistence
def _part_name(ids: Sequence[str]) -> str:
    return "part-" + hashlib.sha256("".join(sorted(ids)).encode()).hexdigest()[:16] + ".parquet"


def _write_part(folder: Path, rows: list[tuple[str, dict[str, Any]]]) -> Path:
    import pyarrow as pa
    import pyarrow.parquet as pq

    from pounding.io import atomic_path

    records = [{"case_id": cid, **row} for cid, row in rows]
    cols: dict[str, list[Any]] = {}
    for rec in records:
        for k in rec:
            cols.setdefault(k, [])
    table = pa.table({k: pa.array([rec.get(k) for rec in records]) for k in cols})
    target = folder / _part_name([cid for cid, _ in rows])
    with atomic_path(target) as tmp:
        pq.write_table(table, tmp)
        with open(tmp, "rb") as fh:
            os.fsync(fh.fileno())
    return target


def _read_parts(folder: Path) -> dict[str, dict[str, Any]]:
    """Rows of every complete part file, by case id (first copy wins)."""
    import pyarrow.parquet as pq

    rows: dict[str, dict[str, Any]] = {}
    if not folder.is_dir():
        return rows
    for p in sorted(folder.glob("part-*.parquet")):
        try:
            recs = pq.read_table(p).to_pylist()
        except Exception:  # noqa: BLE001  (cannot happen with atomic writes; be safe)
            p.unlink(missing_ok=True)
            continue
        for rec in recs:
            rows.setdefault(rec["case_id"], rec)
    return rows


def _write_history(folder: Path, cid: str, ds: Any, fmt: str) -> None:
    from pounding.io import atomic_path

    folder.mkdir(parents=True, exist_ok=True)
    if fmt == "netcdf":
        with atomic_path(folder / f"{cid}.nc") as tmp:
            ds.to_netcdf(tmp, engine="h5netcdf")
    else:
        import tempfile

        target = folder / f"{cid}.zarr"
        tmp = Path(tempfile.mkdtemp(prefix=f".{cid}.zarr.part-", dir=folder))
        try:
            ds.to_zarr(tmp / "store.zarr", mode="w")
            if target.exists():
                shutil.rmtree(target)
            os.replace(tmp / "store.zarr", target)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)


def _param_array(values: list[Any]) -> Any:
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
    floor_cols = sorted({k for r in recs for k in r if k.startswith(FLOOR_MEASURES)},
                        key=_floor_key)
    for name in floor_cols:
        cols[name] = pa.array([r.get(name) for r in recs], pa.float64())
    cols["wall_time_s"] = pa.array([r.get("wall_time_s") for r in recs], pa.float64())
    meta = {"pounding.sweep": _canon({"name": sweep.name, "params": list(sweep.params),
                                      "fingerprint": sweep.fingerprint,
                                      "nondeterministic_columns":
                                          list(NONDETERMINISTIC_COLUMNS)})}
    return pa.table(cols).replace_schema_metadata(meta)


def load_results(path: str | os.PathLike[str], deterministic: bool = False) -> Any:
    """Read a results table (a ``results.parquet`` or its sweep folder) as a DataFrame.

    With ``deterministic`` the columns that vary between runs are left out
    (:data:`NONDETERMINISTIC_COLUMNS`): what remains is bit-identical between two runs.
    """
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


# ============================================================================ running
@dataclass(frozen=True)
class SweepOutcome:
    """What :func:`run_sweep` did."""

    out_dir: Path
    results: Path
    n_cases: int
    n_run: int
    """Cases run this time (the others were finished before)."""
    n_errors: int
    wall_time: float
    """Seconds from start to the consolidated table [s]."""
    run_time: float
    """Seconds spent running cases (after the cluster was up) [s]."""
    n_workers: int
    batch_size: int

    @property
    def rate(self) -> float:
        """Cases run per second of :attr:`run_time`."""
        return self.n_run / self.run_time if self.run_time > 0 else float("nan")


def _prepare_out(sweep: Sweep, out: Path, overwrite: bool) -> None:
    manifest = out / MANIFEST_FILE
    if out.exists():
        if not out.is_dir():
            raise ValueError(f"out: {out} exists and is not a folder")
        if manifest.is_file():
            old = json.loads(manifest.read_text(encoding="utf-8")).get("fingerprint")
            if old == sweep.fingerprint and not overwrite:
                return  # resume
            if old != sweep.fingerprint and not overwrite:
                raise ValueError(f"out: {out} holds the results of another sweep (its base "
                                 "model or cases differ); give --overwrite to start afresh "
                                 "or choose another --out")
            for name in (PARTS_DIR, HISTORIES_DIR, RESULTS_FILE, MANIFEST_FILE):
                target = out / name
                if target.is_dir():
                    shutil.rmtree(target)
                elif target.exists():
                    target.unlink()
        elif any(out.iterdir()):
            raise ValueError(f"out: {out} is a non-empty folder that is not a sweep output "
                             f"(no {MANIFEST_FILE}); choose another --out")
    out.mkdir(parents=True, exist_ok=True)
    from pounding.io import write_text

    write_text(manifest, json.dumps({"name": sweep.name, "fingerprint": sweep.fingerprint,
                                     "params": list(sweep.params), "n_cases": len(sweep.cases),
                                     "source": str(sweep.source) if sweep.source else None},
                                    indent=2))


def _auto_batch(n_pending: int, n_workers: int) -> int:
    """About 8 batches per worker, 10 … 200 cases each (a case takes a few ms)."""
    return max(10, min(200, math.ceil(n_pending / max(1, 8 * n_workers))))


@contextlib.contextmanager
def _client(scheduler: str | None, n_workers: int | None) -> Iterator[Any]:
    """A Dask client: local cluster (default), an existing scheduler, or none (in-process)."""
    if scheduler in ("synchronous", "none", "sync"):
        yield None
        return
    from distributed import Client, LocalCluster

    if scheduler:
        with Client(scheduler) as client:
            yield client
        return
    n = n_workers or (os.cpu_count() or 1)
    import dask

    # Dask's nanny sets MALLOC_TRIM_THRESHOLD_=65536 in every worker, which turns off
    # glibc's adaptive mmap threshold: each output array of a case (hundreds of kB) is then
    # a fresh mmap whose pages fault in on first touch, and a case runs ~2x slower than in
    # this process. A large threshold keeps them on the reusable heap. (Dask already gives
    # each worker one BLAS/OpenMP thread.) The statistical profiler, which samples every
    # thread each 10 ms, is measurable on ms-long cases: off.
    environ = dict(dask.config.get("distributed.nanny.pre-spawn-environ", {}))
    environ["MALLOC_TRIM_THRESHOLD_"] = 1 << 30
    environ["MALLOC_MMAP_THRESHOLD_"] = 1 << 27
    with dask.config.set({"distributed.worker.profile.enabled": False,
                          "distributed.nanny.pre-spawn-environ": environ}), \
            LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                         dashboard_address=None, silence_logs=40) as cluster, \
            Client(cluster) as client:
        yield client


def run_sweep(sweep: Sweep | str | os.PathLike[str], out: str | os.PathLike[str] | None = None,
              *, scheduler: str | None = None, n_workers: int | None = None,
              batch_size: int | None = None, overwrite: bool = False,
              histories: str | None | bool = None,
              progress: Callable[[int, int], None] | None = None) -> SweepOutcome:
    """Run the missing cases of a sweep and write ``results.parquet``.

    Parameters
    ----------
    sweep : Sweep or path
        A sweep (:func:`load_sweep`) or its file.
    out : path-like, optional
        Output folder (default: ``out`` of the sweep file, relative to it).
    scheduler : str, optional
        None: a local Dask cluster (``n_workers`` processes, one thread each);
        ``"tcp://host:8786"``: that Dask scheduler; ``"synchronous"``: in this process.
    n_workers : int, optional
        Workers of the local cluster (default: the CPU count).
    batch_size : int, optional
        Cases per task (default from the sweep file, else automatic).
    overwrite : bool
        Start afresh even if ``out`` holds this sweep (partly) done, or another sweep.
    histories : {"netcdf", "zarr"} or False, optional
        Write every case's time histories (default from the sweep file).
    progress : callable, optional
        Called with ``(cases done, cases in all)`` as batches finish.
    """
    start = time.perf_counter()
    if not isinstance(sweep, Sweep):
        sweep = load_sweep(sweep)
    out_dir = Path(out) if out is not None else sweep.out
    hist = sweep.histories if histories is None else (histories or None)
    if hist not in (None, *HISTORY_FORMATS):
        raise ValueError(f"histories: netcdf, zarr or none (got {hist!r})")
    if hist == "zarr":
        try:
            import zarr  # noqa: F401
        except ImportError:
            raise ValueError("histories: zarr needs the zarr package (pip install zarr); "
                             "or use netcdf") from None
    _prepare_out(sweep, out_dir, overwrite)
    parts = out_dir / PARTS_DIR
    parts.mkdir(exist_ok=True)
    for stale in parts.glob(".*"):  # temporaries of a killed run
        if stale.is_dir():
            shutil.rmtree(stale, ignore_errors=True)
        else:
            stale.unlink(missing_ok=True)
    hist_dir = out_dir / HISTORIES_DIR
    if hist_dir.is_dir():
        for stale in hist_dir.glob(".*"):
            shutil.rmtree(stale, ignore_errors=True) if stale.is_dir() else stale.unlink()
    done = _read_parts(parts)
    wanted = {c.id for c in sweep.cases}
    pending = [c for c in sweep.cases if c.id not in done]
    n_total = len(sweep.cases)
    n_done = sum(1 for cid in done if cid in wanted)
    if progress is not None:
        progress(n_done, n_total)
    payload = {"base": sweep.base, "base_dir": str(sweep.base_dir), "params": sweep.params,
               "histories": hist}
    n_run = 0
    run_time = 0.0
    workers = 1
    bsize = batch_size or sweep.batch_size or 1
    if pending:
        with _client(scheduler, n_workers) as client:
            workers = max(1, len(client.scheduler_info(n_workers=-1)["workers"])) \
                if client is not None else 1
            bsize = batch_size or sweep.batch_size or _auto_batch(len(pending), workers)
            batches = [[(c.index, c.id, c.values) for c in pending[i:i + bsize]]
                       for i in range(0, len(pending), bsize)]
            if client is not None:
                client.run(warm_up)
            t0 = time.perf_counter()

            def finish(results: list[tuple[str, dict[str, Any], Any]]) -> None:
                nonlocal n_done, n_run
                if hist is not None:
                    for cid, row, ds in results:
                        if ds is not None:
                            _write_history(hist_dir, cid, ds, hist)
                _write_part(parts, [(cid, row) for cid, row, _ in results])
                for cid, row, _ in results:
                    done[cid] = {"case_id": cid, **row}
                n_done += len(results)
                n_run += len(results)
                if progress is not None:
                    progress(n_done, n_total)

            if client is None:
                for b in batches:
                    finish(_run_batch(payload, b))
            else:
                from distributed import as_completed

                [remote] = client.scatter([payload], broadcast=True, hash=False)
                futures = [client.submit(_run_batch, remote, b, pure=False,
                                         key=f"sweep-{_part_name([x[1] for x in b])[5:21]}")
                           for b in batches]
                try:
                    for fut in as_completed(futures):
                        finish(fut.result())
                        fut.release()
                except BaseException:
                    client.cancel(futures)
                    raise
            run_time = time.perf_counter() - t0
    table = _consolidate(sweep, done)
    import pyarrow.parquet as pq

    from pounding.io import atomic_path

    results = out_dir / RESULTS_FILE
    with atomic_path(results) as tmp:
        pq.write_table(table, tmp)
    n_err = sum(1 for s in table.column("status").to_pylist() if s != "ok")
    return SweepOutcome(out_dir=out_dir, results=results, n_cases=n_total, n_run=n_run,
                        n_errors=n_err, wall_time=time.perf_counter() - start,
                        run_time=run_time, n_workers=workers, batch_size=bsize)

"""The sweep file: read, validated and turned into a :class:`Sweep` (base model and cases).

Nothing runs here: :func:`parse_sweep` validates and builds the base model, reads the case
table (:mod:`~pounding.studies.sweep.cases`), checks every parameter path and the cases
(:mod:`~pounding.studies.sweep.checks`), and fixes the output folder and options.
"""

from __future__ import annotations

import hashlib
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pounding.io import check_label, read_toml, study_out
from pounding.studies.sweep.cases import Case, _canon, case_rows, unique_cases
from pounding.studies.sweep.checks import _check_path, check_cases

__all__ = ["HISTORY_FORMATS", "Sweep", "load_sweep", "parse_sweep"]

HISTORY_FORMATS = ("netcdf", "zarr")
"""Formats of the time histories a sweep can write per case."""


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
    """The output folder: ``out`` of the file (relative to it), else ``<file
    stem>-results`` in the current folder (:func:`pounding.output_folder.default_out_dir`;
    ``<name>-results`` for a sweep not read from a file)."""
    histories: str | None = None
    batch_size: int | None = None
    source: Path | None = None
    duplicates: int = 0
    """Cases given twice (same values): run once."""
    records: dict[str, Any] = field(default_factory=dict, repr=False)
    out_refused: str | None = None
    """Why ``out`` of the file cannot be used unless an output folder is given
    explicitly (it leads outside the file's folder, :func:`pounding.io.study_out`)."""

    @property
    def fingerprint(self) -> str:
        """Hash of everything that decides the table (base model, parameters, cases)."""
        text = _canon({"base": self.base, "base_dir": str(self.base_dir),
                       "params": list(self.params), "cases": [c.id for c in self.cases]})
        return hashlib.sha256(text.encode()).hexdigest()[:20]


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
    params, rows, samples = case_rows(kind, table, where)
    for p in params:
        _check_path(p, base_data, where)
    # record files in the cases are relative to the sweep file: make them absolute
    if any(_is_record_file(p) for p in params):
        rows = [tuple(_resolve_value(p, v, here) for p, v in zip(params, r)) for r in rows]
        samples = [[_resolve_value(p, v, here) for v in vals]
                   for p, vals in zip(params, samples)]
    cases = unique_cases(params, rows)
    hist = data.get("histories", False)
    if hist is False or hist is None or hist == "none":
        hist = None
    elif hist not in HISTORY_FORMATS:
        raise ValueError(f"{where}: histories: false, \"netcdf\" or \"zarr\" (got {hist!r})")
    batch = data.get("batch_size")
    if batch is not None and (not isinstance(batch, int) or isinstance(batch, bool) or batch < 1):
        raise ValueError(f"{where}: batch_size: an integer >= 1 (got {batch!r})")
    # an ``out`` the file names is relative to the file; by default, as for ``pounding run``,
    # NAME-results in the current folder (never inside a folder of examples one ran)
    # a name is a label: it never leads the default folder elsewhere
    name = check_label(data.get("name", "sweep"), where)
    out = data.get("out")
    if out is not None and (not isinstance(out, str) or not out or "\0" in out):
        raise ValueError(f"{where}: out: a folder name (got {out!r})")
    refused = None
    if out is not None:
        out_dir, refused = study_out(here, out, where)
    else:
        out_dir = Path.cwd() / f"{name}-results"
    sweep = Sweep(name=name, base=base_data, base_dir=model_dir,
                  params=params, cases=cases, out=out_dir, histories=hist,
                  batch_size=batch, duplicates=len(rows) - len(cases), out_refused=refused)
    check_cases(sweep, samples, where, kind)
    return sweep


def load_sweep(path: str | os.PathLike[str]) -> Sweep:
    """Read and validate a sweep file (see :func:`parse_sweep`)."""
    p = Path(path)
    data = read_toml(p, "sweep file")
    sweep = parse_sweep(data, base_dir=p.resolve().parent, where=str(p))
    sweep.source = p.resolve()
    if data.get("out") is None:
        from pounding.output_folder import default_out_dir

        sweep.out = default_out_dir(p)
    return sweep


def _is_record_file(path: str) -> bool:
    """Whether a parameter path names a record file."""
    return path.split(".")[-1] == "file" and path.startswith("record")


def _resolve_value(path: str, value: Any, here: Path) -> Any:
    """A record file given in a case, made absolute (relative to the sweep file)."""
    if _is_record_file(path) and isinstance(value, str):
        return str((here / Path(value).expanduser()).resolve())
    return value

"""The sweep file: read, validated and turned into a :class:`Sweep` (base model and cases).

Nothing runs here: :func:`parse_sweep` validates the file's keys and tables
(:mod:`~pounding.studies.sweep.sections`, one line per problem as for a model file),
validates and builds the base model, makes the cases
(:mod:`~pounding.studies.sweep.cases`), checks every parameter path and the cases
(:mod:`~pounding.studies.sweep.checks`), and fixes the output folder and options.
"""

from __future__ import annotations

import hashlib
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pounding.io.files import check_label, read_toml, study_out
from pounding.studies.sweep.cases import Case, _canon, case_rows, unique_cases
from pounding.studies.sweep.checks import _check_path, check_cases
from pounding.studies.sweep.sections import SweepFile

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
    stem>-results`` in the current folder (:func:`pounding.io.output_folder.default_out_dir`;
    ``<name>-results`` for a sweep not read from a file)."""
    histories: str | None = None
    batch_size: int | None = None
    source: Path | None = None
    duplicates: int = 0
    """Cases given twice (same values): run once."""
    records: dict[str, Any] = field(default_factory=dict, repr=False)
    out_refused: str | None = None
    """Why ``out`` of the file cannot be used unless an output folder is given
    explicitly (it leads outside the file's folder, :func:`pounding.io.files.study_out`)."""

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
        One line per problem naming the key at fault: a bad key or table of the sweep file
        (:class:`~pounding.studies.sweep.sections.SweepFile`), an unknown parameter path, a
        value of the wrong type for its key, or an invalid base model (its own validation
        message).
    """
    from pydantic import ValidationError

    from pounding.config import load_config, parse_config
    from pounding.config.errors import format_validation_error

    here = Path(base_dir).resolve()
    try:
        spec = SweepFile.model_validate(data)
    except ValidationError as exc:
        raise ValueError(format_validation_error(exc, prefix=f"{where}: ",
                                                 root=SweepFile)) from None
    # a name is a label: it never leads the default folder elsewhere
    name = check_label(spec.name, where)
    if isinstance(spec.base, str):
        cfg = load_config(here / spec.base)
        model_dir = (here / spec.base).resolve().parent
    else:
        cfg = parse_config(spec.base, base_dir=here, where=f"{where}: base")
        model_dir = here
    base_data = cfg.to_dict(resolve_paths=True)
    base_data.setdefault("output", {})["figures"] = False

    kind = spec.kind
    params, rows, samples = case_rows(kind, getattr(spec, kind), where)
    for p in params:
        _check_path(p, base_data, where, kind)
    # record files in the cases are relative to the sweep file: make them absolute
    if any(_is_record_file(p) for p in params):
        rows = [tuple(_resolve_value(p, v, here) for p, v in zip(params, r)) for r in rows]
        samples = [[_resolve_value(p, v, here) for v in vals]
                   for p, vals in zip(params, samples)]
    cases = unique_cases(params, rows)
    # an ``out`` the file names is relative to the file; by default, as for ``pounding run``,
    # NAME-results in the current folder (never inside a folder of examples one ran)
    refused = None
    if spec.out is not None:
        out_dir, refused = study_out(here, spec.out, where)
    else:
        out_dir = Path.cwd() / f"{name}-results"
    sweep = Sweep(name=name, base=base_data, base_dir=model_dir,
                  params=params, cases=cases, out=out_dir, histories=spec.history_format,
                  batch_size=spec.batch_size, duplicates=len(rows) - len(cases),
                  out_refused=refused)
    check_cases(base_data, model_dir, params, cases, samples, where, kind)
    return sweep


def load_sweep(path: str | os.PathLike[str]) -> Sweep:
    """Read and validate a sweep file (see :func:`parse_sweep`)."""
    p = Path(path)
    data = read_toml(p, "sweep file")
    sweep = parse_sweep(data, base_dir=p.resolve().parent, where=str(p))
    sweep.source = p.resolve()
    if data.get("out") is None:
        from pounding.io.output_folder import default_out_dir

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

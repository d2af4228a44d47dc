"""What a run folder holds, read once for the run page (:func:`read_run`)."""

from __future__ import annotations

import json
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd

__all__ = ["RUN_FILES", "RunFolder", "read_run"]

RUN_FILES: tuple[str, ...] = ("summary.json", "timehistories.nc")
"""Files that make a folder a run output."""


@dataclass
class RunFolder:
    """The files of a run folder, read: the summary, the time histories, the impacts, and
    the model file with the model rebuilt from it (or why it could not be)."""

    folder: Path
    summary: dict[str, Any]
    ds: Any  # xarray.Dataset, loaded into memory
    impacts: pd.DataFrame
    """The impact table, columns named as :attr:`pounding.result.Result.impacts` (and
    ``elevation``)."""
    impacts_units: str
    """The ``#`` line of units of an older ``impacts.csv`` ("" for one whose column names
    carry the units)."""
    toml_text: str | None
    toml: dict[str, Any]
    built: Any = None  # pounding.config.Built or None
    build_error: str | None = None

    def impacts_of(self, label: str) -> pd.DataFrame:
        """The rows of the impact table of contact ``label`` (empty without a table)."""
        if len(self.impacts) and "contact" in self.impacts:
            return self.impacts[self.impacts["contact"] == label]
        return pd.DataFrame()


def read_run(folder: Path) -> RunFolder:
    """Read the run folder ``folder``.

    Raises
    ------
    ValueError
        ``summary.json`` or ``timehistories.nc`` is unreadable. A missing, invalid or
        unbuildable ``model.toml`` is not an error: ``build_error`` says why.
    """
    import xarray as xr

    try:
        summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as exc:
        raise ValueError(f"report: {folder / 'summary.json'}: unreadable ({exc})") from None
    if not isinstance(summary, dict):
        raise ValueError(f"report: {folder / 'summary.json'}: not a JSON object")
    try:
        with xr.open_dataset(folder / "timehistories.nc", engine="h5netcdf") as ds:
            ds = ds.load()
    except (OSError, ValueError) as exc:
        raise ValueError(f"report: {folder / 'timehistories.nc'}: unreadable ({exc})") from None

    from pounding.result import IMPACTS_CSV_COLUMNS

    impacts = pd.DataFrame()
    units = ""
    csv = folder / "impacts.csv"
    if csv.is_file():
        # a folder written before the units went into the column names opens with a
        # ``#`` line of units, and names its columns without them
        with csv.open(encoding="utf-8") as fh:
            first = fh.readline()
        skip = 1 if first.startswith("#") else 0
        units = first.lstrip("#").strip() if skip else ""
        try:
            impacts = pd.read_csv(csv, skiprows=skip)
        except pd.errors.EmptyDataError:
            impacts = pd.DataFrame()
        impacts = impacts.rename(columns={v: k for k, v in IMPACTS_CSV_COLUMNS.items()})
    toml_text = None
    toml: dict[str, Any] = {}
    built = None
    build_error = None
    mt = folder / "model.toml"
    if mt.is_file():
        toml_text = mt.read_text(encoding="utf-8")
        try:
            toml = tomllib.loads(toml_text)
        except tomllib.TOMLDecodeError as exc:
            from pounding.io.files import toml_error_text

            build_error = f"model.toml is not valid TOML ({toml_error_text(exc)})"
        if build_error is None:
            from pounding.config import load_config

            try:
                built = load_config(mt).build()
            except (ValueError, OSError) as exc:
                build_error = f"model.toml could not be rebuilt ({exc})"
    else:
        build_error = "no model.toml in the folder"
    return RunFolder(folder, summary, ds, impacts, units, toml_text, toml, built, build_error)

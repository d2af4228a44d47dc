"""The files of a run: ``timehistories.nc``, ``impacts.csv`` and ``summary.json``.

Each is written atomically (:mod:`pounding.io.files`). The NetCDF file is serialised in memory
and then written with plain file I/O, so that HDF5 never meets a full disk or a file-size
limit (it crashes the process there); a failed write is one :class:`pounding.io.files.WriteFailed`
naming the file, costing about 0.03 s more for the demo's 42 MB. It is built with h5netcdf
directly from :func:`pounding.result.variables.history_variables` — the same variables,
units and coordinates :meth:`~pounding.result.Result.to_xarray` gives as an xarray Dataset, which
is also how to read the file back (``xarray.open_dataset(path, engine="h5netcdf")``). Going
without xarray and pandas here keeps a run's start-up short: importing them costs about a
second, more than the whole simulation of a small model.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from pounding.io.files import write_bytes, write_text
from pounding.result.columns import IMPACT_COLUMNS, rounded_length
from pounding.result.summary import summarize
from pounding.result.variables import HistoryVariables, history_variables

if TYPE_CHECKING:
    from pounding.result.response import Response

__all__ = ["IMPACTS_CSV_COLUMNS", "impacts_csv", "save_result", "write_netcdf"]

IMPACTS_CSV_COLUMNS: dict[str, str] = {
    "contact": "contact",
    "elevation": "elevation_m",
    "start": "start_s",
    "end": "end_s",
    "v0": "v0_m_s",
    "peak_force": "peak_force_N",
    "peak_force_time": "peak_force_time_s",
    "max_penetration": "max_penetration_m",
    "restitution": "restitution",
    "energy_dissipated": "energy_dissipated_J",
}
"""The columns of ``impacts.csv``: each column of :attr:`pounding.result.Result.impacts` (and
the contact's elevation) → its name in the file, which ends in its unit (``_m``, ``_s``,
``_m_s``, ``_N``, ``_J``; ``restitution`` is a ratio). The file is plain CSV, one header
row and no comment line, so ``pandas.read_csv(path)``, Excel and R's ``read.csv`` read it
as it is. ``restitution`` is separation speed / approach speed ``v0`` of the two contact
points (between buildings the ground and the storeys push the floors during the impact,
so it is no energy ratio and may exceed 1); ``energy_dissipated_J`` is the energy the
contact element dissipated in that impact (≥ 0). ``docs/running.md`` says the same."""


def save_result(result: Response, folder: str | os.PathLike[str],
                warnings: Sequence[str] = ()) -> dict[str, Path]:
    """Write ``timehistories.nc``, ``impacts.csv`` and ``summary.json`` into ``folder``.

    ``warnings`` (one line each: the plausibility warnings of the model file, say) are
    stored in ``summary.json`` under ``"warnings"`` (an empty list when there are none).
    Returns the paths by key (``timehistories``, ``impacts``, ``summary``).
    """
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    out = {"timehistories": folder / "timehistories.nc", "impacts": folder / "impacts.csv",
           "summary": folder / "summary.json"}
    buf = io.BytesIO()
    write_netcdf(history_variables(result), buf)
    write_bytes(out["timehistories"], buf.getbuffer())
    write_text(out["impacts"], impacts_csv(result))
    summary = {**summarize(result), "warnings": list(warnings)}
    write_text(out["summary"], json.dumps(json_ready(summary), indent=2))
    return out


def write_netcdf(variables: HistoryVariables, path: str | os.PathLike[str] | io.BytesIO
                 ) -> None:
    """Write a result's variables to a NetCDF-4 file (HDF5, via h5netcdf), or into a
    binary buffer (``io.BytesIO``).

    Coordinates named like their dimension become NetCDF dimension variables; the others
    (e.g. ``building`` and ``floor_elevation`` along ``floor``) are listed in each data
    variable's ``coordinates`` attribute, as the CF conventions and xarray read them.
    Strings are stored as variable-length UTF-8.
    """
    import h5netcdf

    sizes: dict[str, int] = {}
    for v in (*variables.coords.values(), *variables.data.values()):
        for dim, n in zip(v.dims, v.values.shape):
            sizes[dim] = n
    aux = [name for name, v in variables.coords.items() if v.dims != (name,)]
    with h5netcdf.File(path, "w") as f:
        f.dimensions = sizes
        for name, v in variables.coords.items():
            _create(f, name, v.dims, v.values, v.attrs)
        for name, v in variables.data.items():
            attrs = dict(v.attrs)
            own = [c for c in aux if set(variables.coords[c].dims) <= set(v.dims)]
            if own:
                attrs["coordinates"] = " ".join(own)
            _create(f, name, v.dims, v.values, attrs)
        for key, value in variables.attrs.items():
            f.attrs[key] = value


def _create(f: Any, name: str, dims: tuple[str, ...], values: np.ndarray,
            attrs: dict[str, Any]) -> None:
    if values.dtype == object or values.dtype.kind in "US":
        import h5py

        var = f.create_variable(name, dims, dtype=h5py.string_dtype(),
                                data=np.asarray([str(x) for x in values.ravel()],
                                                dtype=object).reshape(values.shape))
    else:
        var = f.create_variable(name, dims, data=np.ascontiguousarray(values))
    for key, value in attrs.items():
        var.attrs[key] = value


def impacts_csv(result: Response) -> str:
    """The impact table as CSV text: one header row (:data:`IMPACTS_CSV_COLUMNS`, units in
    the names), then one row per impact; a missing value (an impact still open at the end)
    is an empty field."""
    contacts = result.model.contacts
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow([IMPACTS_CSV_COLUMNS[c] for c in ("contact", "elevation", *IMPACT_COLUMNS[1:])])
    for row in result.impact_array:
        c = contacts[int(row[0])]
        w.writerow([c.label, _number(rounded_length(c.elevation)), *(_number(x) for x in row[1:])])
    return buf.getvalue()


def _number(x: float) -> str:
    """Shortest text that reads back as the same float; empty for NaN."""
    x = float(x)
    return "" if math.isnan(x) else repr(x)


def json_ready(obj: Any) -> Any:
    """JSON cannot hold NaN or infinity: turn them into None (recursively)."""
    if isinstance(obj, dict):
        return {k: json_ready(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [json_ready(v) for v in obj]
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj

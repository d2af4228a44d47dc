"""What a simulation returns, and what is made of it: one package, one way in.

Import every name from here (``from pounding.result import Result, ENERGY_NAMES``); the
modules below are how the package is built, each importing only those under it:

* :mod:`~pounding.result.columns` — the columns of the energy and impact arrays, and the
  rounding of elevations in the outputs;
* :mod:`~pounding.result.peaks` and :mod:`~pounding.result.reductions` — peaks of histories,
  in NumPy and compiled (numba);
* :mod:`~pounding.result.storeys` — storeys as an engineer reads them: isolation bearings,
  storey forces of buildings in plan, floor names;
* :mod:`~pounding.result.bridge_seats` — a bridge's seats: their openings, peaks and
  margins against the seat widths (:func:`seat_checks`);
* :mod:`~pounding.result.response` — :class:`Response`, the arrays of a run and every
  quantity derived from them (drifts, shears, peaks, impacts per contact, energies);
* :mod:`~pounding.result.storey_peaks` — the bearing and plan tables of a response;
* :mod:`~pounding.result.bridge_peaks` — a bridge run element by element (frames, piers,
  bearings, joints and abutments, restrainers);
* :mod:`~pounding.result.bridge_keys` — the shear keys of a run (peak force, set, failure);
* :mod:`~pounding.result.variables` — its histories as named variables with units (what
  the NetCDF file and the xarray Dataset hold);
* :mod:`~pounding.result.summary` — its headline numbers (``summary.json``);
* :mod:`~pounding.result.files` — the files of a run (``timehistories.nc``,
  ``impacts.csv``, ``summary.json``);
* :mod:`~pounding.result.display` — a run as a notebook shows it: the headline numbers
  with units and the key figure, inline (``Result._repr_html_``; matplotlib's own
  object-oriented API, imported when shown: :mod:`pounding.plot` is a layer above);
* :mod:`~pounding.result.result` — :class:`Result`, a :class:`Response` with its tables and
  files as methods (:meth:`Result.summary`, :meth:`Result.save`, :meth:`Result.to_xarray`):
  what :func:`pounding.simulate` returns.

Names are imported on first use (PEP 562): importing this package loads nothing heavy.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from pounding.lazy import lazy_exports

_EXPORTS: dict[str, str] = {
    **{name: "pounding.result.columns" for name in ("ENERGY_NAMES", "IMPACT_COLUMNS")},
    "peak_abs": "pounding.result.peaks",
    **{name: "pounding.result.reductions" for name in (
        "abs_max_columns", "abs_max_drift", "energy_residual_max")},
    **{name: "pounding.result.storeys" for name in (
        "bearing_law", "bearing_mask", "floor_name", "plan_storey_forces")},
    **{name: "pounding.result.bridge_seats" for name in (
        "SEAT_FIELDS", "seat_checks", "seat_openings", "seat_summary")},
    "ContactPeak": "pounding.result.contact_response",
    **{name: "pounding.result.bridge_keys" for name in ("KeyState", "shear_keys")},
    **{name: "pounding.result.response" for name in ("Response", "SolverStats")},
    **{name: "pounding.result.storey_peaks" for name in (
        "BearingPeaks", "PlanStoreys", "bearing_peaks", "plan_storeys")},
    **{name: "pounding.result.bridge_peaks" for name in (
        "BridgePeaks", "bridge_summary", "is_bridge")},
    **{name: "pounding.result.variables" for name in (
        "HistoryVariables", "Variable", "history_variables")},
    **{name: "pounding.result.demands" for name in ("DEMANDS", "Demand")},
    "summarize": "pounding.result.summary",
    **{name: "pounding.result.files" for name in ("IMPACTS_CSV_COLUMNS", "save_result")},
    "Result": "pounding.result.result",
}
"""Public name → the module that defines it."""

__all__ = [
    "DEMANDS",
    "Demand",
    "ENERGY_NAMES",
    "IMPACTS_CSV_COLUMNS",
    "IMPACT_COLUMNS",
    "BearingPeaks",
    "BridgePeaks",
    "ContactPeak",
    "HistoryVariables",
    "KeyState",
    "PlanStoreys",
    "Response",
    "SEAT_FIELDS",
    "Result",
    "SolverStats",
    "Variable",
    "abs_max_columns",
    "abs_max_drift",
    "bearing_law",
    "bearing_mask",
    "bearing_peaks",
    "bridge_summary",
    "energy_residual_max",
    "floor_name",
    "history_variables",
    "is_bridge",
    "peak_abs",
    "plan_storey_forces",
    "plan_storeys",
    "save_result",
    "seat_checks",
    "seat_openings",
    "seat_summary",
    "shear_keys",
    "summarize",
]


__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)


if TYPE_CHECKING:  # what type checkers and IDEs see: the same names, imported eagerly
    from pounding.result.bridge_peaks import (
        BridgePeaks,
        bridge_summary,
        is_bridge,
    )
    from pounding.result.bridge_seats import (
        SEAT_FIELDS,
        seat_checks,
        seat_openings,
        seat_summary,
    )
    from pounding.result.bridge_keys import KeyState, shear_keys
    from pounding.result.columns import ENERGY_NAMES, IMPACT_COLUMNS
    from pounding.result.contact_response import ContactPeak
    from pounding.result.demands import DEMANDS, Demand
    from pounding.result.files import IMPACTS_CSV_COLUMNS, save_result
    from pounding.result.peaks import peak_abs
    from pounding.result.reductions import (
        abs_max_columns,
        abs_max_drift,
        energy_residual_max,
    )
    from pounding.result.response import Response, SolverStats
    from pounding.result.result import Result
    from pounding.result.storey_peaks import (
        BearingPeaks,
        PlanStoreys,
        bearing_peaks,
        plan_storeys,
    )
    from pounding.result.storeys import (
        bearing_law,
        bearing_mask,
        floor_name,
        plan_storey_forces,
    )
    from pounding.result.summary import summarize
    from pounding.result.variables import HistoryVariables, Variable, history_variables

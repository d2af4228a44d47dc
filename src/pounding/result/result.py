"""What a simulation returns: its response, with the tables and files made of it.

:class:`Result` is a :class:`~pounding.result.response.Response` (the time histories, the
impact table, the energies, and the drifts, shears and peaks derived from them) with its
tables and files as methods: the impact table as a DataFrame, the bearing and plan tables,
the histories as named variables and as an xarray Dataset, the JSON summary, and
:meth:`Result.save`, which writes the files of a run into a folder
(:mod:`pounding.result.files`), each file atomically.

pandas and xarray are imported only by the methods that return their objects
(:attr:`Result.impacts`, :meth:`Result.to_xarray`): writing a run's files needs neither.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pounding.result.bridge_peaks import BridgePeaks, bridge_peaks
from pounding.result.bridge_seats import seat_checks
from pounding.result.bridge_keys import KeyState, shear_keys
from pounding.result.columns import IMPACT_COLUMNS, rounded_length
from pounding.result.files import save_result
from pounding.result.response import Response
from pounding.result.storey_peaks import (
    BearingPeaks,
    BridgeElementPeaks,
    PlanStoreys,
    bearing_peaks,
    bridge_element_peaks,
    plan_storeys,
)
from pounding.result.summary import summarize
from pounding.result.variables import HistoryVariables, Variable, history_variables

if TYPE_CHECKING:
    import pandas as pd
    import xarray as xr

    from pounding.structure.seat_width import SeatCheck

__all__ = ["Result"]


class Result(Response):
    """Time histories and impacts of one simulation (SI units), with their tables and
    files: what :func:`pounding.simulate` returns.

    Its data and derived quantities are those of :class:`~pounding.result.response.Response`
    (same fields, same constructor); a result adds :attr:`impacts`, :attr:`bearings`,
    :attr:`seats`, :attr:`plan_storeys`, :attr:`bridge_elements`, :attr:`bridge`,
    :meth:`history_variables`, :meth:`to_xarray` (alias :meth:`to_dataset`), :meth:`summary`
    and :meth:`save`; in Jupyter it shows as a summary with its key figure (``_repr_html_``).
    """

    @cached_property
    def seats(self) -> list[SeatCheck]:
        """The seats of a bridge with a width (``A1``, ``J1`` …, ``A2``): width, the
        clause's minimum, peak opening and its time, margin [m, s]
        (:class:`~pounding.structure.seat_width.SeatCheck`,
        :func:`pounding.result.bridge_seats.seat_checks`); empty when the model was not made
        from a :class:`~pounding.structure.bridge.Bridge` with seat widths."""
        bridge = getattr(self.model, "bridge", None)
        return seat_checks(self) if bridge is not None and bridge.seats() else []

    @cached_property
    def impacts(self) -> pd.DataFrame:
        """One row per impact: contact label, elevation [m], start/end [s], impact velocity
        v0 [m/s], peak force [N] and its time [s], maximum penetration [m], the velocity
        ratio ``restitution`` [-], the energy dissipated by the contact in the impact [J].

        An impact ends when the penetration returns to zero (``end``); for laws that cannot
        pull (clipped Kelvin–Voigt, Hunt–Crossley) the force may have returned to zero a
        little earlier, which is where :func:`pounding.contact.collision.simulate_collision`
        ends a free-body impact. ``restitution`` is ``−δ̇_separation / v0``, the ratio of
        the speeds at which the two contact points part and met. For two free bodies it is
        the law's coefficient of restitution (the kinetic energy of the relative motion
        keeps the fraction e² of itself); between buildings it is not: the ground and the
        storeys keep pushing the floors during the impact, so the ratio says nothing of
        the energy and may exceed 1 (the rest of each building pushing the floors apart
        faster than they met) — no energy is created. The impact's own loss is
        ``energy_dissipated``, the work of the contact force over the impact
        ``∫ F δ̇ dt`` (δ = 0 at both ends, so none of it is still stored), ≥ 0 for every
        passive law. Impacts still open at the end have NaN end, restitution and
        energy."""
        import pandas as pd

        df = pd.DataFrame(self.impact_array, columns=list(IMPACT_COLUMNS))
        labels = [c.label for c in self.model.contacts]
        df["contact"] = [labels[int(i)] for i in df["contact"]] if len(df) else []
        df.insert(1, "elevation", [rounded_length(self.model.contacts[labels.index(lb)]
                                                  .elevation)
                                   for lb in df["contact"]] if len(df) else [])
        return df

    @cached_property
    def plan_storeys(self) -> list[PlanStoreys]:
        """Floor-by-floor peaks of every building in plan (x, y, rotation, drifts, storey
        shears and torque: :class:`pounding.result.PlanStoreys`); empty without one."""
        return plan_storeys(self)

    @cached_property
    def bearings(self) -> list[BearingPeaks]:
        """The isolation bearing of every base-isolated building: its law, peak displacement
        and force with their times, residual displacement
        (:class:`pounding.result.BearingPeaks`); empty without one."""
        return bearing_peaks(self)

    @cached_property
    def bridge_elements(self) -> list[BridgeElementPeaks]:
        """Every pier and bearing of the bridge frames (:mod:`pounding.structure.bridge`):
        its kind and law, peak deformation (a pier's drift, a bearing's displacement) with
        its time, peak force (a pier's shear) and residual deformation
        (:class:`pounding.result.storey_peaks.BridgeElementPeaks`); empty without a bridge
        frame."""
        return bridge_element_peaks(self)

    @cached_property
    def bridge(self) -> BridgePeaks | None:
        """A bridge run element by element: every frame's deck, piers and bearings, every
        joint and abutment (impacts, the envelope of its opening and closing), every
        restrainer, with their peaks (:class:`pounding.result.bridge_peaks.BridgePeaks`);
        None unless every building is a bridge frame."""
        return bridge_peaks(self)

    @cached_property
    def shear_keys(self) -> list[KeyState]:
        """Every shear key (a bridge across its axis): its peak force and deformation, its
        set, whether and when it broke off (:class:`pounding.result.KeyState`); empty
        without keys."""
        return shear_keys(self)

    def history_variables(self) -> HistoryVariables:
        """Every time history and per-floor result as named variables with dimensions, units
        and descriptions: what :meth:`to_dataset` and the NetCDF file hold
        (:func:`pounding.result.history_variables`)."""
        return history_variables(self)

    def to_xarray(self) -> xr.Dataset:
        """The dataset ``timehistories.nc`` holds: every time history and per-floor result
        with its dimensions, coordinates, units and descriptions, and the run's attributes.

        Built from :meth:`history_variables`, the variables
        :func:`pounding.result.files.write_netcdf` writes into the file, so the two cannot
        drift: ``xarray.open_dataset(folder / "timehistories.nc", engine="h5netcdf")`` of a
        saved result equals this variable by variable, attributes included
        (``xarray.Dataset.identical``; text coordinates read back from the file as
        ``object`` arrays of the same strings)."""
        import xarray as xr

        hv = self.history_variables()

        def da(v: Variable) -> xr.DataArray:
            return xr.DataArray(v.values, dims=v.dims, attrs=dict(v.attrs))

        return xr.Dataset({k: da(v) for k, v in hv.data.items()},
                          coords={k: da(v) for k, v in hv.coords.items()},
                          attrs=dict(hv.attrs))

    def to_dataset(self) -> xr.Dataset:
        """The same as :meth:`to_xarray` (its older name)."""
        return self.to_xarray()

    def summary(self) -> dict[str, Any]:
        """Headline numbers (JSON-ready), each key naming its unit
        (:func:`pounding.result.summarize`)."""
        return summarize(self)

    def _repr_html_(self) -> str:
        """Jupyter's view: the headline numbers with units and the key figure (top-floor
        displacements and contact forces), an inline PNG; nothing written
        (:func:`pounding.result.display.result_html`)."""
        from pounding.result.display import result_html

        return result_html(self)

    def save(self, folder: str | os.PathLike[str],
             warnings: Sequence[str] = ()) -> dict[str, Path]:
        """Write ``timehistories.nc``, ``impacts.csv`` and ``summary.json`` into ``folder``
        (:func:`pounding.result.save_result`); each file is written under a temporary name
        and moved into place when complete. ``warnings`` (one line each, e.g. the model
        file's plausibility warnings) are kept in ``summary.json``."""
        return save_result(self, folder, warnings=warnings)

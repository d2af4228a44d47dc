"""The storey tables of a run: every isolation bearing, and every building in plan floor by
floor, with their peaks and times (:attr:`pounding.result.Result.bearings`,
:attr:`pounding.result.Result.plan_storeys`; the summary and the NetCDF file read them).

Functions of a :class:`~pounding.result.response.Response` (its peaks and histories); the
storeys themselves (bearing laws, storey forces of a building in plan, floor names) are in
:mod:`pounding.result.storeys`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

import numpy as np
from numpy.typing import NDArray

from pounding.result.peaks import sampled_peak
from pounding.result.storeys import bearing_law, plan_of

if TYPE_CHECKING:
    from pounding.result.response import Response

__all__ = ["BearingPeaks", "PlanStoreys", "bearing_peaks", "plan_storeys"]


class BearingPeaks(NamedTuple):
    """The isolation bearing of one base-isolated building (:func:`bearing_peaks`)."""

    building: int
    """0-based building index."""
    dof: int
    """Global DOF of its base slab."""
    law: str
    """The bearing's law in words (:func:`pounding.result.storeys.bearing_law`)."""
    kind: str
    """``friction pendulum`` or ``bilinear isolator``."""
    elevation: float
    """Elevation of the base slab [m]."""
    peak_displacement: float
    """Largest |displacement| of the bearing (base slab relative to the ground) [m],
    located inside solver steps."""
    peak_displacement_time: float
    """When [s]."""
    peak_force: float
    """Largest |force| of the bearing [N] (its law's, at the output steps)."""
    peak_force_time: float
    """When [s]."""
    residual_displacement: float
    """Displacement left after unloading along the law's unloading stiffness [m]."""


def bearing_peaks(result: Response) -> list[BearingPeaks]:
    """The bearing of every base-isolated building of ``result``, left to right."""
    model = result.model
    out = []
    for b, (off, bl) in enumerate(zip(model.system.offsets, model.buildings)):
        iso = getattr(bl, "isolator", None)
        if iso is None:
            continue
        i = int(off)
        out.append(BearingPeaks(
            b, i, bearing_law(iso), str(getattr(iso, "label", "isolator")),
            float(bl.floor_levels[0]), float(result.peak_drift[i]),
            float(result.peak_drift_time[i]), float(result.peak_storey_shear[i]),
            float(result.peak_storey_shear_time[i]), float(result.residual_drift[i])))
    return out


class PlanStoreys(NamedTuple):
    """Peaks of every floor and storey of one building in plan (:func:`plan_storeys`),
    arrays (n_floors,), floor 1 first, each with its time [s] (``…_time``). Displacements,
    drifts and accelerations are those of the floors' centres of mass; along x and the
    rotation located inside solver steps (as every floor's), along y the displacement and
    acceleration too; the y drifts and the storey forces at the output steps."""

    building: int
    offset: int
    elevation: NDArray[np.float64]
    height: NDArray[np.float64]
    displacement_x: NDArray[np.float64]
    displacement_x_time: NDArray[np.float64]
    displacement_y: NDArray[np.float64]
    displacement_y_time: NDArray[np.float64]
    rotation: NDArray[np.float64]
    rotation_time: NDArray[np.float64]
    drift_x: NDArray[np.float64]
    drift_x_time: NDArray[np.float64]
    drift_y: NDArray[np.float64]
    drift_y_time: NDArray[np.float64]
    shear_x: NDArray[np.float64]
    shear_x_time: NDArray[np.float64]
    shear_y: NDArray[np.float64]
    shear_y_time: NDArray[np.float64]
    torque: NDArray[np.float64]
    torque_time: NDArray[np.float64]
    acceleration_x: NDArray[np.float64]
    acceleration_x_time: NDArray[np.float64]
    acceleration_y: NDArray[np.float64]
    acceleration_y_time: NDArray[np.float64]
    has_elements: bool
    """False for a building given by its stiffness matrix: no storey forces (NaN)."""

    @property
    def drift_ratio_x(self) -> NDArray[np.float64]:
        """Peak drift along x over the storey height [-]."""
        return self.drift_x / self.height

    @property
    def drift_ratio_y(self) -> NDArray[np.float64]:
        """Peak drift along y over the storey height [-]."""
        return self.drift_y / self.height


def plan_storeys(result: Response) -> list[PlanStoreys]:
    """Floor by floor peaks of every building in plan of ``result`` (:class:`PlanStoreys`),
    with the storey shears and torques of
    :func:`pounding.result.storeys.plan_storey_forces`."""
    model = result.model
    time = result.time
    out = []
    for b, (off, bl) in enumerate(zip(model.system.offsets, model.buildings)):
        plan = plan_of(bl)
        if plan is None:
            continue
        off = int(off)
        n = plan.n_floors
        ix = off + 3 * np.arange(n)
        iy, it = ix + 1, ix + 2
        dy, dy_t = sampled_peak(result.drift[:, iy], time)
        (sx, sx_t), (sy, sy_t), (st, st_t) = (
            sampled_peak(v, time) for v in (result.storey_shear[:, ix],
                                             result.storey_shear[:, iy],
                                             result.storey_torque[:, it]))
        disp, disp_t = result.peak_displacement, result.peak_displacement_time
        acc, acc_t = result.peak_abs_acceleration, result.peak_abs_acceleration_time
        out.append(PlanStoreys(
            b, off, np.asarray(plan.floor_levels, dtype=float),
            np.asarray(plan.heights, dtype=float),
            disp[ix], disp_t[ix], disp[iy], disp_t[iy], disp[it], disp_t[it],
            result.peak_drift[ix], result.peak_drift_time[ix], dy, dy_t,
            sx, sx_t, sy, sy_t, st, st_t, acc[ix], acc_t[ix], acc[iy], acc_t[iy],
            bool(plan.elements)))
    return out

"""The storey tables of a run: every isolation bearing, every building in plan floor by
floor, and every pier and bearing of a bridge frame, with their peaks and times (:attr:`pounding.result.Result.bearings`,
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

__all__ = ["BearingPeaks", "BridgeElementPeaks", "PlanStoreys", "bearing_peaks",
           "bridge_element_histories", "bridge_element_peaks", "plan_storeys"]


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


class BridgeElementPeaks(NamedTuple):
    """One pier or bearing of a bridge frame (:func:`bridge_element_peaks`)."""

    building: int
    """0-based building (frame) index."""
    label: str
    """``'B1P1'`` (frame 1, pier 1), ``'B2Br1'`` (frame 2, bearing 1)."""
    kind: str
    """``pier``, or the bearing's kind (``elastomeric``, ``isolator``, ``sliding``)."""
    law: str
    """``linear`` or its law (:meth:`~pounding.hysteresis.base.StoreyLaw.describe`)."""
    height: float
    """A pier's height [m] (its cap's elevation); NaN for a bearing."""
    peak_deformation: float
    """Largest |deformation| [m]: a pier's drift (cap relative to the ground), a bearing's
    displacement (deck relative to the cap)."""
    peak_deformation_time: float
    """Its time [s]."""
    peak_force: float
    """Largest |force| [N]: a pier's shear, a bearing's force (a linear element's spring
    ``k d`` plus its own dashpot ``c ḋ``; a nonlinear one's law, plus its dashpot)."""
    residual_deformation: float
    """Deformation at the end unloaded along its law's unloading stiffness [m] (0 for a
    linear element)."""
    peak_force_time: float
    """When the force peaked [s]."""


def bridge_element_histories(result: Response) -> list[tuple[int, str, NDArray[np.float64],
                                                              NDArray[np.float64]]]:
    """``(building, label, deformation (nt,), force (nt,))`` of every pier and bearing of the
    bridge frames of the row, linear or not, in each frame's order (piers, then bearings):
    the deformation ``u[upper] − u[lower]`` [m] from the displacements, the force [N] from
    the element's law (its element row's) or its spring, plus its own dashpot."""
    from pounding.structure.bridge import BridgeFrame

    model = result.model
    u, v = result.displacement, result.velocity
    rows = {(p, row.label): r for r, (p, row) in enumerate(model.element_rows)}
    out = []
    for p, (off, bl) in enumerate(zip(model.system.offsets, model.buildings)):
        if not isinstance(bl, BridgeFrame):
            continue
        for label, _, lo, hi, k, law, c in bl.elements():
            d = u[:, off + hi] - (u[:, off + lo] if lo >= 0 else 0.0)
            rate = v[:, off + hi] - (v[:, off + lo] if lo >= 0 else 0.0)
            f = (result.element_force[:, rows[(p, label)]] if law is not None else k * d)
            out.append((p, f"B{p + 1}{label}", d, f + c * rate))
    return out


def bridge_element_peaks(result: Response) -> list[BridgeElementPeaks]:
    """Every pier and bearing of the bridge frames with its peaks (at the output steps)
    and residual deformation (:func:`bridge_element_histories`)."""
    from pounding.structure.bridge import BridgeFrame

    model = result.model
    residual = dict(zip(model.element_labels(), result.element_residual_deformation))
    kinds = {}
    for p, bl in enumerate(model.buildings):
        if isinstance(bl, BridgeFrame):
            for label, kind, _, hi, _, law, _ in bl.elements():
                height = float(bl.elevations[hi]) if kind == "pier" else float("nan")
                kinds[f"B{p + 1}{label}"] = (kind, law, height)
    out = []
    t = result.time
    for p, label, d, f in bridge_element_histories(result):
        kind, law, height = kinds[label]
        j = int(np.argmax(np.abs(d)))
        jf = int(np.argmax(np.abs(f)))
        out.append(BridgeElementPeaks(
            p, label, kind, "linear" if law is None else law.describe(),
            float(height), float(np.abs(d[j])), float(t[j]), float(np.abs(f[jf])),
            float(residual.get(label, 0.0)), float(t[jf])))
    return out

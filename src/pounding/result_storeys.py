"""A run's storeys as an engineer reads them: isolation bearings apart from the storeys above
them, buildings in plan floor by floor and direction by direction with their storey shears,
and the names of floors.

* **Bearings.** A base-isolated building (:meth:`pounding.structure.ShearBuilding.base_isolated`)
  is a shear building whose storey 1 is the isolation bearing under its base slab (floor 1).
  Its "drift" is the bearing's displacement and its "shear" the bearing's force: not a
  storey's drift ratio or ductility (a friction pendulum's 0.5 mm stick displacement makes a
  "ductility" of hundreds). :func:`bearing_peaks` reports each bearing by its law, peak
  displacement, force and residual displacement; :func:`bearing_mask` marks the base slabs,
  whose storey the outputs leave out of the storeys.
* **Buildings in plan** (:class:`pounding.structure.plan.PlanBuilding`): three DOFs a floor
  (``u_x``, ``u_y`` at the centre of mass, ``θ``). :func:`plan_storeys` gives, floor by
  floor, the peaks along x and y, the rotation, the drifts of the centres of mass and the
  storey shears ``V_x``, ``V_y`` and torque ``T`` from the lateral elements
  (:func:`plan_storey_forces`).
* **Names.** :func:`floor_name` names floor DOF ``j`` of a building: ``F3`` (a shear
  building), ``F3 x`` (a building in plan: floor 3, along x), a matrix building's own label.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from pounding.model import PoundingModel
    from pounding.result import Result
    from pounding.structure.plan import PlanBuilding

__all__ = ["BearingPeaks", "PlanStoreys", "bearing_law", "bearing_mask", "bearing_peaks",
           "floor_name", "plan_of", "plan_storey_forces", "plan_storeys"]


# =============================================================================== names
def plan_of(building: Any) -> PlanBuilding | None:
    """The plan of a building in plan as it stands in a row (its
    :class:`~pounding.structure.plan_row.PlanMatrixBuilding`), else None."""
    return getattr(building, "plan", None)


def floor_name(building: Any, j: int) -> str:
    """The name of DOF ``j`` (0-based) of ``building`` in tables and legends: ``F3`` for a
    shear building's floor 3; ``F3 x`` / ``F3 y`` / ``F3 θ`` for floor 3 of a building in
    plan along x, y and its rotation; a matrix building's own label (its DOFs are not
    numbered floors)."""
    if plan_of(building) is not None:
        label = str(building.labels[j])
        return f"{label[:-1]} {label[-1]}"
    labels = getattr(building, "labels", None)
    if labels is not None:
        return str(labels[j])
    return f"F{j + 1}"


# =============================================================================== bearings
def bearing_law(isolator: Any) -> str:
    """``friction pendulum (R = 2 m, μ = 0.05)``, ``bilinear isolator (k₁ = …, k₂ = …,
    Q = …)``: the bearing's law in words, with the constants an engineer gives for it."""
    from pounding.hysteresis.isolators import BilinearIsolator, FrictionPendulum
    from pounding.units import format_value

    if isinstance(isolator, FrictionPendulum):
        return (f"friction pendulum (R = {format_value(isolator.radius, 'm')}, "
                f"μ = {isolator.mu:g})")
    if isinstance(isolator, BilinearIsolator):
        return (f"bilinear isolator (k₁ = {format_value(isolator.pre_yield_stiffness, 'N/m')}"
                f", k₂ = {format_value(isolator.post_yield_stiffness, 'N/m')}, "
                f"Q = {format_value(float(isolator.characteristic_strength or 0.0), 'N')})")
    return str(getattr(isolator, "label", "isolator"))


def bearing_mask(model: PoundingModel) -> NDArray[np.bool_]:
    """True at every base slab (N,): the DOF whose "storey" below is an isolation bearing
    (storey 1 of a base-isolated building), not a storey."""
    out = np.zeros(model.n_dof, dtype=bool)
    for off, bl in zip(model.system.offsets, model.buildings):
        if getattr(bl, "isolator", None) is not None:
            out[int(off)] = True
    return out


class BearingPeaks(NamedTuple):
    """The isolation bearing of one base-isolated building (:func:`bearing_peaks`)."""

    building: int
    """0-based building index."""
    dof: int
    """Global DOF of its base slab."""
    law: str
    """The bearing's law in words (:func:`bearing_law`)."""
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


def bearing_peaks(result: Result) -> list[BearingPeaks]:
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


# =============================================================================== in plan
def plan_storey_forces(plan: PlanBuilding, u: NDArray[np.float64]
                       ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Storey shears ``V_x``, ``V_y`` [N] and torque ``T`` [N·m] of a building in plan from
    its lateral elements, each (nt, n_floors), storey j the one below floor j.

    Element e of storey j deforms by ``d = a_j · q_j − a_{j−1} · q_{j−1}`` (rigid-floor
    kinematics at the element, the ground below storey 1), with
    ``a_j = (c, s, −c (y_e − y_cj) + s (x_e − x_cj))``; it carries ``f = k_ej d`` along its
    direction ``(c, s)`` (Chopra §9.5.1; :func:`pounding.structure.plan.plan_stiffness_matrix`
    assembles the same terms). The storey's shears are ``V_x = Σ f c``, ``V_y = Σ f s`` and its
    torque about floor j's centre of mass ``T = Σ f (−c (y_e − y_cj) + s (x_e − x_cj))``:
    the force and moment the storey resists a positive deformation with (the floor above
    receives their negatives; :mod:`pounding.hysteresis.base`, item 1). NaN for a building
    given by its stiffness matrix (no elements: no storey forces).

    Parameters
    ----------
    plan : PlanBuilding
    u : ndarray (nt, 3 n_floors)
        The building's DOF histories ``u_x, u_y, θ`` floor by floor [m, m, rad].
    """
    u = np.asarray(u, dtype=float)
    n = plan.n_floors
    shape = (u.shape[0], n)
    vx, vy, tq = np.zeros(shape), np.zeros(shape), np.zeros(shape)
    if not plan.elements:
        return np.full(shape, np.nan), np.full(shape, np.nan), np.full(shape, np.nan)
    centres = plan.mass_centres
    for e in plan.elements:
        k = e.storey_stiffnesses(n)
        c, s = e.cosines

        def along(floor: int) -> tuple[NDArray[np.float64], float]:
            xc, yc = centres[floor]
            arm = -c * (e.y - yc) + s * (e.x - xc)
            q = u[:, 3 * floor: 3 * floor + 3]
            return c * q[:, 0] + s * q[:, 1] + arm * q[:, 2], arm

        below = np.zeros(u.shape[0])
        for j in range(n):
            here, arm = along(j)
            if k[j] != 0.0:
                f = k[j] * (here - below)
                vx[:, j] += f * c
                vy[:, j] += f * s
                tq[:, j] += f * arm
            below = here
    return vx, vy, tq


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


def _sampled_peak(a: NDArray[np.float64], time: NDArray[np.float64]
                  ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Largest |a| of every column at the output steps and its time."""
    if not a.shape[0]:
        return np.zeros(a.shape[1]), np.full(a.shape[1], np.nan)
    if np.isnan(a).all():
        return np.full(a.shape[1], np.nan), np.full(a.shape[1], np.nan)
    k = np.argmax(np.abs(a), axis=0)
    cols = np.arange(a.shape[1])
    return np.abs(a[k, cols]), time[k]


def plan_storeys(result: Result) -> list[PlanStoreys]:
    """Floor by floor peaks of every building in plan of ``result`` (:class:`PlanStoreys`),
    with the storey shears and torques of :func:`plan_storey_forces`."""
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
        dy, dy_t = _sampled_peak(result.drift[:, iy], time)
        (sx, sx_t), (sy, sy_t), (st, st_t) = (
            _sampled_peak(v, time) for v in (result.storey_shear[:, ix],
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

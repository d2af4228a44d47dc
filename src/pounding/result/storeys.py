"""A run's storeys as an engineer reads them: isolation bearings apart from the storeys above
them, buildings in plan direction by direction with their storey forces, the residual drift
of a yielding storey, the shear on a struck column, and the names of floors.

* **Bearings.** A base-isolated building (:meth:`pounding.structure.ShearBuilding.base_isolated`)
  is a shear building whose storey 1 is the isolation bearing under its base slab (floor 1).
  Its "drift" is the bearing's displacement and its "shear" the bearing's force: not a
  storey's drift ratio or ductility (a friction pendulum's 0.5 mm stick displacement makes a
  "ductility" of hundreds). :func:`bearing_law` names each bearing's law and
  :func:`bearing_mask` marks the base slabs, whose storey the outputs leave out of the
  storeys (:func:`pounding.result.storey_peaks.bearing_peaks` reports each bearing's peak
  displacement, force and residual displacement).
* **Buildings in plan** (:class:`pounding.structure.plan.PlanBuilding`): three DOFs a floor
  (``u_x``, ``u_y`` at the centre of mass, ``θ``). :func:`plan_storey_forces` gives the
  storey shears ``V_x``, ``V_y`` and torque ``T`` from the lateral elements
  (:func:`pounding.result.storey_peaks.plan_storeys`, floor by floor, the peaks along x and
  y, the rotation, the drifts of the centres of mass and those storey forces).
* **Frames** (:class:`pounding.structure.frame_linear.FrameBuilding`): :func:`frame_storey_shear`,
  each storey's shear from the frame's restoring forces above it.
* **Demands.** :func:`residual_storey_drift`, the drift a yielding storey keeps once
  unloaded; :func:`struck_column_shear`, the shear a floor-to-column impact puts on the
  struck column.
* **Names.** :func:`floor_name` names floor DOF ``j`` of a building: ``F3`` (a shear
  building), ``F3 x`` (a building in plan: floor 3, along x), a matrix building's own label.

Functions of the model and of arrays: :class:`pounding.result.response.Response` calls them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from pounding.model import PoundingModel
    from pounding.structure.plan import PlanBuilding

__all__ = ["bearing_law", "bearing_mask", "floor_name", "frame_storey_shear", "plan_of",
           "plan_storey_forces", "residual_storey_drift", "struck_column_shear"]

CUT_TOL: float = 1e-6
"""A DOF stands above the cut at the foot of a storey if it is this far [m] above the floor
below (:func:`frame_storey_shear`)."""


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


# =============================================================================== demands
def residual_storey_drift(model: PoundingModel, drift_end: NDArray[np.float64],
                          shear_end: NDArray[np.float64],
                          final_z: NDArray[np.float64] | None) -> NDArray[np.float64]:
    """Residual drift [m] (N,) of every yielding storey: unloaded from its state at the end
    of the run to zero shear along its unloading stiffness, ``d_end − V_end / k_unload``
    (:meth:`pounding.hysteresis.base.StoreyLaw.unloading_stiffness`; for the bilinear law:
    its plastic drift); 0 for the linear storeys.

    Parameters
    ----------
    model : PoundingModel
    drift_end, shear_end : ndarray (N,)
        Storey drift [m] and shear [N] at the end of the run.
    final_z : ndarray (n_z,), optional
        Internal variables at the end (Bouc–Wen rows' ``z`` first, in the order of the
        model's element rows).
    """
    out = np.zeros(model.n_dof)
    z_end = final_z if final_z is not None else np.zeros(0)
    zk = 0
    offsets = model.system.offsets
    for p, row in model.element_rows:  # (z counted over every row, storey or not)
        z = 0.0
        if row.law.has_internal_variable:
            z = float(z_end[zk]) if zk < z_end.size else 0.0
            zk += 1
        if row.storey < 0:
            continue  # a bridge frame's pier or bearing: no storey column
        col = offsets[p] + row.storey
        out[col] = drift_end[col] - shear_end[col] / row.law.unloading_stiffness(row.params, z)
    return out


def element_residual_deformation(model: PoundingModel, deformation_end: NDArray[np.float64],
                                 force_end: NDArray[np.float64],
                                 final_z: NDArray[np.float64] | None) -> NDArray[np.float64]:
    """Residual deformation [m] of every element row (:attr:`PoundingModel.element_rows`):
    unloaded from its state at the end to zero force along its law's unloading stiffness,
    ``d_end − V_end / k_unload`` (as :func:`residual_storey_drift` for a storey)."""
    out = np.zeros(len(model.element_rows))
    z_end = final_z if final_z is not None else np.zeros(0)
    zk = 0
    for r, (_, row) in enumerate(model.element_rows):
        z = 0.0
        if row.law.has_internal_variable:
            z = float(z_end[zk]) if zk < z_end.size else 0.0
            zk += 1
        out[r] = deformation_end[r] - force_end[r] / row.law.unloading_stiffness(row.params, z)
    return out


def struck_column_shear(model: PoundingModel, contact_force: NDArray[np.float64],
                        storey_shear: NDArray[np.float64]) -> NDArray[np.float64]:
    """Shear demand on the struck column of every floor-to-column contact [N] (nt, n_c);
    NaN for floor-to-floor contacts and for a column of a building given as matrices (no
    storey shear).

    A floor-to-column contact at position ξ of storey j of the struck building loads its
    column with a point force ``P`` (the contact force, signed in the direction it pushes
    the struck building), shared to the floors as ``(1 − ξ)P`` and ``ξP``
    (:class:`pounding.model.ContactPoint`). With the storey shear ``V`` (from the drift),
    equilibrium of the column gives the local shear ``V + (1 − ξ)P`` below the point and
    ``V − ξP`` above it; the demand is the larger in magnitude.

    Parameters
    ----------
    model : PoundingModel
    contact_force : ndarray (nt, n_c)
        Contact forces [N] (compression positive).
    storey_shear : ndarray (nt, N)
        Storey shears [N].
    """
    out = np.full((contact_force.shape[0], len(model.contacts)), np.nan)
    offsets = model.system.offsets
    for c in model.contacts:
        pt = c.struck
        if pt is None:
            continue
        p = contact_force[:, c.index] * (1.0 if pt is c.right else -1.0)
        v = storey_shear[:, offsets[pt.building] + pt.upper]
        out[:, c.index] = np.maximum(np.abs(v + (1.0 - pt.xi) * p), np.abs(v - pt.xi * p))
    return out


# =============================================================================== frames
def frame_storey_shear(model: PoundingModel, displacement: NDArray[np.float64],
                       restoring: NDArray[np.float64] | None
                       ) -> list[tuple[int, NDArray[np.float64]]]:
    """The storey shears [N] of every frame of the row, ``(floor DOF, history (nt,))``.

    The shear of storey j is the lateral force the frame resists across a cut at the storey's
    foot: the sum of the lateral restoring forces of its DOFs above the cut (its floors', and
    any node's with lateral mass), net of gravity — the columns' shears less the P-Delta
    shear of the gravity loads when the frame has P-Delta, as the pushover's base shear. For
    a frame with plastic hinges the restoring forces are the run's (``restoring``, (nt, N),
    :class:`pounding.integrate.frame_run.HingeOutputs`); for an elastic one ``K u``.
    """
    from pounding.structure.matrices import MatrixBuilding

    out: list[tuple[int, NDArray[np.float64]]] = []
    if not any(isinstance(b, MatrixBuilding) for b in model.buildings):
        return out  # (a frame is a matrix building: a row of shear buildings has none)
    from pounding.structure.frame_linear import FrameBuilding

    for off, b in zip(model.system.offsets, model.buildings):
        if not isinstance(b, FrameBuilding):
            continue
        cols = slice(int(off), int(off) + b.n)
        R = restoring[:, cols] if restoring is not None else None
        if R is None or not np.all(np.isfinite(R)):
            R = displacement[:, cols] @ b.K.T
        floors = b.floor_dofs
        z = b.elevations
        lateral = b.r == 1.0
        below = np.concatenate([[0.0], z[floors[:-1]]])
        for j, f in enumerate(floors):
            above = lateral & (z > below[j] + CUT_TOL)
            out.append((int(off) + int(f), R[:, above].sum(axis=1)))
    return out

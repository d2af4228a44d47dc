"""A result's histories as named variables with dimensions, units and descriptions: what
:meth:`pounding.result.Result.to_xarray` and the NetCDF file
(:func:`pounding.result.files.write_netcdf`) hold (one description, two writers)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from pounding.result.columns import ENERGY_NAMES, rounded_length
from pounding.result.storey_peaks import bearing_peaks, plan_storeys

if TYPE_CHECKING:
    from pounding.result.response import Response

__all__ = ["HingeRow", "HistoryVariables", "Variable", "hinge_table", "history_variables"]


class HingeRow(NamedTuple):
    """Where one plastic hinge of a yielding frame is, and what it did
    (:func:`hinge_table`)."""

    label: str  #: ``B1H3``: building 1, hinge 3 of its frame
    building: int  #: the building's index in the row (0-based)
    element: int  #: the member it is at, in its frame's order (0-based)
    end: int  #: 0 at the member's first node, 1 at its second
    member: str  #: ``column`` or ``beam``
    x: float  #: the node's x in the frame [m]
    y: float  #: its elevation above the frame's base [m]
    law: str  #: the hinge law in words
    yield_rotation: float  #: the law's ``m_y / k0`` [rad]
    peak_rotation: float  #: largest |θ| [rad]
    peak_rotation_time: float  #: its time [s]
    residual_rotation: float  #: θ at the end unloaded to zero moment [rad]
    peak_moment: float  #: largest |M| at the output steps [N·m]
    dissipated: float  #: hysteretic energy [J]
    capped: bool  #: it reached its capping point or fractured (``Result.hinge_capped``)


def hinge_table(result: Response) -> list[HingeRow]:
    """Every plastic hinge of the model's yielding frames with its peak and residual
    rotation, peak moment and hysteretic energy (empty without yielding frames)."""
    model = result.model
    frames = model.yielding_frames
    if not frames or result.hinge_peak_rotation is None:
        return []
    labels = model.hinge_labels()
    rows = []
    h = 0
    for b, bl in frames:
        frame = bl.frame
        col = frame.is_column
        for fh in frame.hinges:
            x, y = frame.nodes[frame.elements[fh.element, fh.end]]
            moment = result.hinge_moment[:, h] if result.hinge_moment is not None else None
            rows.append(HingeRow(
                labels[h], b, int(fh.element), int(fh.end),
                "column" if col[fh.element] else "beam", float(x), float(y - frame.base),
                fh.law.describe(), float(fh.law.theta_y), float(result.hinge_peak_rotation[h]),
                float(result.hinge_peak_rotation_time[h]),  # type: ignore[index]
                float(result.hinge_residual_rotation[h]),  # type: ignore[index]
                float(np.max(np.abs(moment))) if moment is not None and moment.size else 0.0,
                float(result.hinge_dissipated[h]),  # type: ignore[index]
                bool(result.hinge_capped[h]) if result.hinge_capped is not None else False))
            h += 1
    return rows


class Variable(NamedTuple):
    """One named array of a result: its dimensions, values and attributes (units, long
    name), as NetCDF and xarray hold it."""

    dims: tuple[str, ...]
    values: NDArray[Any]
    attrs: dict[str, Any]


class HistoryVariables(NamedTuple):
    """A result's data variables, coordinates and global attributes
    (:meth:`pounding.result.Result.history_variables`)."""

    data: dict[str, Variable]
    coords: dict[str, Variable]
    attrs: dict[str, Any]


def history_variables(result: Response) -> HistoryVariables:
    """Every time history and per-floor result as named variables with dimensions, units
    and descriptions: what :meth:`pounding.result.Result.to_xarray` and the NetCDF file
    hold (one description, two writers)."""
    model = result.model
    contacts = model.contacts
    bearings = bearing_peaks(result)

    def var(values: Any, dims: tuple[str, ...], units: str, desc: str) -> Variable:
        return Variable(dims, np.asarray(values), {"units": units, "long_name": desc})

    # one record: (time,); G components (a model whose influence matrix R has G columns):
    # (time, ground_component), the components in the order of R's columns
    ground_dims = ("time",) if np.ndim(result.ground) == 1 else ("time", "ground_component")
    data = {
        "ground_acceleration": var(result.ground, ground_dims, "m/s^2", "ground acceleration"),
        "displacement": var(result.displacement, ("time", "floor"), "m",
                            "floor displacement relative to the ground (in rad where "
                            "dof_unit is rad: a rotation)"),
        "velocity": var(result.velocity, ("time", "floor"), "m/s",
                        "floor velocity relative to the ground (in rad/s where dof_unit is "
                        "rad: a rotation)"),
        "absolute_acceleration": var(result.abs_acceleration, ("time", "floor"), "m/s^2",
                                     "absolute floor acceleration (in rad/s^2 where "
                                     "dof_unit is rad: a rotation)"),
        "drift": var(result.drift, ("time", "floor"), "m",
                     "storey drift (floor minus floor below; a building on a flexible "
                     "base: of its own deformation, x_j - x_(j-1) - (z_j - z_(j-1)) phi with "
                     "x_0 = u_f, the footing's sway and rocking taken out; a building in "
                     "plan: along x under its x DOFs, along y under its y DOFs, at the "
                     "centres of mass (on a flexible base: of its own deformation); under a "
                     "base slab: its isolation bearing's displacement, also "
                     "bearing_displacement; NaN: not a floor)"),
        "storey_shear": var(result.storey_shear, ("time", "floor"), "N",
                            "storey shear (a building in plan: from its lateral elements, "
                            "along x under its x DOFs, along y under its y DOFs; under a base "
                            "slab: its isolation bearing's force, also bearing_force; NaN: a "
                            "building given as matrices, which has no storey stiffness)"),
        "penetration": var(result.penetration, ("time", "contact"), "m",
                           "penetration u_left - u_right - gap (negative: open)"),
        "contact_force": var(result.contact_force, ("time", "contact"), "N",
                             "contact force (compression positive)"),
        "energy": var(result.energy, ("time", "energy_term"), "J", "cumulative energies"),
    }
    if any(ps.has_elements for ps in plan_storeys(result)):
        data["storey_torque"] = var(result.storey_torque, ("time", "floor"), "N m",
                                    "storey torque of a building in plan from its lateral "
                                    "elements, about the centre of mass of the floor above, "
                                    "under its θ DOFs (NaN elsewhere)")
    if bearings:
        dofs = [x.dof for x in bearings]
        data["bearing_displacement"] = var(result.drift[:, dofs], ("time", "bearing"), "m",
                                           "displacement of each isolation bearing (its "
                                           "base slab relative to the ground)")
        data["bearing_force"] = var(result.storey_shear[:, dofs], ("time", "bearing"), "N",
                                    "force of each isolation bearing (its law's)")
    if model.yielding_frames and not model.is_inelastic:
        data["residual_drift"] = var(result.residual_drift, ("floor",), "m",
                                     "residual storey drift after elastic unloading (a "
                                     "frame's floors unloaded along its hinges' unloading "
                                     "stiffness)")
    if model.is_inelastic:
        data["ductility"] = var(result.ductility, ("floor",), "1",
                                "storey ductility demand max|drift| / yield drift "
                                "(NaN: linear storey, or an isolation bearing)")
        data["residual_drift"] = var(result.residual_drift, ("floor",), "m",
                                     "residual storey drift after elastic unloading")
    if any(row.storey < 0 for _, row in model.element_rows):  # a bridge frame's elements
        data["element_deformation"] = var(result.element_deformation, ("time", "element"), "m",
                                          "deformation of each nonlinear element (a pier's "
                                          "drift, a bearing's displacement, a yielding "
                                          "storey's drift)")
        data["element_force"] = var(result.element_force, ("time", "element"), "N",
                                    "force of each nonlinear element from its law (a pier's "
                                    "shear, a bearing's force, a yielding storey's shear)")
    if any(c.struck is not None for c in contacts):
        data["column_shear"] = var(result.column_shear, ("time", "contact"), "N",
                                   "shear demand on the struck column of a "
                                   "floor-to-column contact (NaN: floor to floor)")
    if model.links and result.link_force is not None:
        data["link_force"] = var(result.link_force, ("time", "link"), "N",
                                 "force of each link between buildings (resisting the "
                                 "right floor moving away from the left one)")
        data["link_displacement"] = var(result.link_displacement, ("time", "link"), "m",
                                        "relative displacement across each link "
                                        "(right floor minus left floor, with their "
                                        "grounds' offset on different grounds)")
    hinges = hinge_table(result)
    if hinges and result.hinge_rotation is not None and result.hinge_moment is not None:
        data["hinge_rotation"] = var(result.hinge_rotation, ("time", "hinge"), "rad",
                                     "rotation of each plastic hinge of a yielding frame "
                                     "(its node's rotation less the member end's)")
        data["hinge_moment"] = var(result.hinge_moment, ("time", "hinge"), "N m",
                                   "moment of each plastic hinge of a yielding frame")
    if result.member_end_moment is not None:
        data["member_end_moment"] = var(result.member_end_moment, ("time", "member_end"),
                                        "N m", "end moment of each member of a yielding "
                                        "frame (the stiffness method's local end moment, "
                                        "counter-clockwise positive)")
    buildings = [f"B{b + 1}" for b, bl in enumerate(model.buildings) for _ in range(bl.n)]
    coords = {
        "time": var(result.time, ("time",), "s", "time"),
        "floor": Variable(("floor",), np.array(model.dof_labels(), dtype=object), {}),
        "contact": Variable(("contact",), np.array([c.label for c in contacts],
                                                   dtype=object), {}),
        "energy_term": Variable(("energy_term",), np.array(ENERGY_NAMES, dtype=object), {}),
        "building": Variable(("floor",), np.array(buildings, dtype=object),
                             {"long_name": "building of each floor (B1 leftmost)"}),
        "floor_elevation": var(rounded_length(np.concatenate([b.floor_levels
                                                                   for b in model.buildings])),
                               ("floor",), "m", "floor elevation above the ground"),
        "storey_height": var(rounded_length(np.concatenate([b.heights for b in model.buildings])),
                             ("floor",), "m", "height of the storey below the floor (NaN: "
                             "a degree of freedom that is not a floor)"),
        "dof_name": Variable(("floor",), np.array(model.dof_names(), dtype=object),
                             {"long_name": "the degree of freedom's name in its building (a "
                                           "matrix building's labels; a footing's Fdn, "
                                           "Fdn_r, ...; a DOF that is not a floor "
                                           "translation, a rotation say, is in rad: "
                                           "dof_unit)"}),
        "dof_unit": Variable(("floor",), np.array(model.dof_units(), dtype=object),
                             {"long_name": "unit of the degree of freedom's displacement: m "
                                           "(a translation), rad (a rotation: a building in "
                                           "plan's θ, a footing's rocking Fdn_r, Fdn_rx, "
                                           "Fdn_ry and torsion Fdn_t, a frame node's r), '' "
                                           "(a DOF of a building given as matrices that is "
                                           "no floor: as its matrices take it); its velocity "
                                           "per s, its acceleration per s^2"}),
        "contact_elevation": var(rounded_length([c.elevation for c in contacts]), ("contact",), "m",
                                 "elevation of the contact"),
    }
    if len(ground_dims) == 2:
        names = [c.name for c in getattr(result.motion, "components", ())]
        coords["ground_component"] = Variable(("ground_component",),
                                              np.array(names, dtype=object),
                                              {"long_name": "ground motion component "
                                                            "(column of the influence matrix)"})
    kind = np.where(result.is_bearing, "bearing", np.where(model.is_floor, "storey", ""))
    coords["storey_kind"] = Variable(("floor",), np.array(kind, dtype=object), {
        "long_name": "what lies under the floor: 'storey', 'bearing' (an isolation bearing "
                     "under a base slab, not a storey) or '' (not a floor)"})
    if bearings:
        coords["bearing"] = Variable(("bearing",), np.array(
            [f"B{x.building + 1}" for x in bearings], dtype=object),
            {"long_name": "building whose isolation bearing it is"})
        coords["bearing_law"] = Variable(("bearing",), np.array(
            [x.law for x in bearings], dtype=object),
            {"long_name": "the bearing's law"})
    if hinges:
        coords["hinge"] = Variable(("hinge",), np.array([h.label for h in hinges], dtype=object),
                                   {"long_name": "plastic hinge: building and its number in "
                                                 "the frame (B1H3: building 1, hinge 3)"})
        coords["hinge_member"] = Variable(("hinge",), np.array(
            [f"{h.member} {h.element + 1} end {h.end + 1}" for h in hinges], dtype=object),
            {"long_name": "the member end the hinge is at (members and ends numbered from 1 "
                          "in the frame's order)"})
        coords["hinge_x"] = var([h.x for h in hinges], ("hinge",), "m",
                                "x of the hinge's node in its frame")
        coords["hinge_y"] = var([h.y for h in hinges], ("hinge",), "m",
                                "elevation of the hinge's node above its frame's base")
        coords["hinge_law"] = Variable(("hinge",), np.array([h.law for h in hinges],
                                                            dtype=object),
                                       {"long_name": "the hinge's moment-rotation law"})
    if result.member_end_moment is not None:
        coords["member_end"] = Variable(("member_end",), np.array(model.member_end_labels(),
                                                                  dtype=object),
                                        {"long_name": "member end: building, member number "
                                                      "in its frame, end i (its first node) "
                                                      "or j (B1E3i)"})
    if "element_force" in data:
        coords["element"] = Variable(("element",), np.array(model.element_labels(),
                                                            dtype=object),
                                     {"long_name": "nonlinear element: building and its name "
                                                   "there (B1F2: storey 2; B2P1: pier 1, "
                                                   "B2Br1: bearing 1 of a bridge frame)"})
    if model.links:
        coords["link"] = Variable(("link",), np.array([lk.name for lk in model.links],
                                                      dtype=object), {})
    attrs = {"model": model.name, "record": result.motion.name,
             "solver": result.stats.solver, "rtol": result.stats.rtol,
             "energy_balance_error": result.energy_balance_error,
             "units": "SI (m, kg, s, N, J)"}
    return HistoryVariables(data, coords, attrs)

"""What a simulation computed: its arrays, and every quantity derived from them.

:class:`Response` holds plain arrays (SI units) — time histories, the impact table, the
cumulative energies — and derives from them the storey drifts and shears, the peaks with
their times, the impacts and peak force of every contact, the links' forces and energies,
and the energy balance, all as NumPy arrays (the contacts' and links' part in
:class:`pounding.result.contact_response.ContactsAndLinks`, its base).
:class:`pounding.result.Result` (what
:func:`pounding.simulate` returns) is a response with its tables and files: the impact table
as a DataFrame, the bearing and plan tables, the xarray Dataset, the summary, the saved
files.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from pounding.result.contact_response import ContactsAndLinks
from pounding.result.foundations import (
    flexible_base_drifts,
    flexible_base_storeys,
    plan_deformation,
)
from pounding.result.peaks import peak_abs, sampled_peak
from pounding.result.storeys import (
    bearing_mask,
    element_residual_deformation,
    frame_storey_shear,
    plan_of,
    plan_storey_forces,
    residual_storey_drift,
    struck_column_shear,
)

if TYPE_CHECKING:
    from pounding.ground_motion import GroundMotion, GroundMotionComponents
    from pounding.model import PoundingModel

__all__ = ["Response", "SolverStats"]


@dataclass(frozen=True)
class SolverStats:
    """How the integration went."""

    solver: str
    rtol: float
    rk_steps: int = 0
    rejected: int = 0
    events: int = 0
    impact_overflow: bool = False
    wall_time: float = 0.0
    """Seconds spent integrating (excluding set-up, and the loading of the compiled kernel
    that the first run in a process pays)."""


@dataclass(frozen=True, eq=False)
class Response(ContactsAndLinks):
    """Time histories and impacts of one simulation (SI units), and the quantities derived
    from them; :class:`pounding.result.Result` adds its tables and files.

    Attributes
    ----------
    model : PoundingModel
    motion : GroundMotion or GroundMotionComponents
    dt : float
        Output step [s]; ``time = k·dt``.
    ground : ndarray (nt,) or (nt, G)
        Ground acceleration at output times [m/s²]; (nt, G) under
        :class:`~pounding.ground_motion.GroundMotionComponents` (a model whose influence
        matrix R has G columns), the components in the order of R's columns.
    displacement, velocity : ndarray (nt, N)
        Floor displacement [m] and velocity [m/s] relative to the ground.
    abs_acceleration : ndarray (nt, N)
        Absolute floor acceleration [m/s²].
    penetration, contact_force : ndarray (nt, n_c)
        ``δ`` [m] (negative: open gap) and contact force [N] of every contact.
    energy : ndarray (nt, 8)
        Cumulative energies [J], columns :data:`~pounding.result.ENERGY_NAMES` (``links``:
        dissipated by the links between buildings, their springs' energy being in
        ``strain``).
    impact_array : ndarray (n_impacts, 8)
        Rows of the impact table, columns :data:`~pounding.result.IMPACT_COLUMNS`.
    stats : SolverStats
    contact_peak, contact_impacts : ndarray (n_c,), optional
        Peak force [N] and number of impacts of each contact, kept by the solver even when
        the impact table overflows (derived from the table when not given).
    yielding_shear : ndarray (nt, n_s), optional
        Force [N] of every element row (:attr:`PoundingModel.element_rows` order: yielding
        storeys, a bridge frame's piers and bearings), from its law.
    final_z : ndarray (n_z,), optional
        Internal variables at the end: Bouc–Wen rows' ``z`` (for the residual drift),
        then Maxwell links' spring deformations [m].
    link_force : ndarray (nt, n_l), optional
        Force [N] of every link between buildings (:attr:`PoundingModel.links` order),
        positive when it resists the right floor moving away from the left one.
    link_ground : ndarray (2, nt, n_l), optional
        Each link's grounds' offset ``u_g,right − u_g,left`` [m] and its rate [m/s] when
        links join buildings on different grounds (spatially varying motion; zero columns
        for a link on one ground); None otherwise.
    building_ground : ndarray (2, nt, n_b), optional
        Each building's ground displacement [m] and velocity [m/s] from rest when the
        buildings stand on different grounds (spatially varying motion); None otherwise.
    wall_ground : dict, optional
        The same (2, nt) of each end wall on a ground of its own, by side.
    contact_peak_time : ndarray (n_c,), optional
        Time of each contact's peak force [s].
    hinge_rotation, hinge_moment : ndarray (nt, n_h), optional
        Rotation [rad] and moment [N·m] of every plastic hinge of the yielding frames
        (:meth:`PoundingModel.hinge_labels` order).
    hinge_peak_rotation, hinge_peak_rotation_time : ndarray (n_h,), optional
        Every hinge's largest |rotation| [rad] (at its events and the output steps: a
        hinge on a one-way branch turns only at an event) and its time [s].
    hinge_residual_rotation : ndarray (n_h,), optional
        Every hinge's rotation at the end, unloaded to zero moment along its unloading
        stiffness [rad] (its plastic rotation).
    hinge_dissipated : ndarray (n_h,), optional
        Every hinge's hysteretic energy at the end [J] (its work ``∫ M dθ`` less the change
        of its recoverable energy).
    member_end_moment : ndarray (nt, n_me), optional
        The end moments [N·m] of every member of the yielding frames at the output steps
        (:meth:`PoundingModel.member_end_labels` order: frames, elements, end 1 then end 2;
        counter-clockwise positive, the stiffness method's local end moments).
    hinge_capped : ndarray (n_h,) of bool, optional
        Every hinge that reached its capping point in the run (moving onto a branch of
        negative tangent: post-capping softening) or whose moment jumped (fracture, complete
        deterioration) — by the branch its law put it on, so a capping point that cyclic
        deterioration moved inward counts.
    frame_residual_displacement : ndarray (N,), optional
        The floors of the yielding frames at the end, unloaded to zero lateral force along
        their hinges' unloading stiffness [m] (NaN for the other buildings' floors).
    frame_restoring_force : ndarray (nt, N), optional
        The yielding frames' restoring force on their DOFs at the output steps, net of
        gravity [N, N·m] (NaN off them): their storey shears
        (:func:`pounding.result.storeys.frame_storey_shear`).
    located_peaks : ndarray (N, 6), optional
        Every floor's largest |displacement| [m], |storey drift| [m] and |absolute
        acceleration| [m/s²], each followed by its time [s], located inside solver steps
        (:mod:`pounding.integrate.peaks`). Without it the peaks are read at the output
        steps.
    """

    model: PoundingModel
    motion: GroundMotion | GroundMotionComponents
    dt: float
    ground: NDArray[np.float64] = field(repr=False)
    displacement: NDArray[np.float64] = field(repr=False)
    velocity: NDArray[np.float64] = field(repr=False)
    abs_acceleration: NDArray[np.float64] = field(repr=False)
    penetration: NDArray[np.float64] = field(repr=False)
    contact_force: NDArray[np.float64] = field(repr=False)
    energy: NDArray[np.float64] = field(repr=False)
    impact_array: NDArray[np.float64] = field(repr=False)
    stats: SolverStats
    contact_peak: NDArray[np.float64] | None = field(default=None, repr=False)
    contact_impacts: NDArray[np.int64] | None = field(default=None, repr=False)
    yielding_shear: NDArray[np.float64] | None = field(default=None, repr=False)
    final_z: NDArray[np.float64] | None = field(default=None, repr=False)
    contact_peak_time: NDArray[np.float64] | None = field(default=None, repr=False)
    located_peaks: NDArray[np.float64] | None = field(default=None, repr=False)
    link_force: NDArray[np.float64] | None = field(default=None, repr=False)
    #: each link's grounds' offset u_g,right − u_g,left [m] and its rate [m/s]
    #: (2, nt, n_l) when links join buildings on different grounds; None otherwise
    link_ground: NDArray[np.float64] | None = field(default=None, repr=False)
    #: each building's ground displacement [m] and velocity [m/s] from rest (2, nt, n_b)
    #: when the buildings stand on different grounds; None otherwise
    building_ground: NDArray[np.float64] | None = field(default=None, repr=False)
    #: the end walls' on grounds of their own, by side ((2, nt) each); None otherwise
    wall_ground: dict[str, NDArray[np.float64]] | None = field(default=None, repr=False)
    hinge_rotation: NDArray[np.float64] | None = field(default=None, repr=False)
    hinge_moment: NDArray[np.float64] | None = field(default=None, repr=False)
    hinge_peak_rotation: NDArray[np.float64] | None = field(default=None, repr=False)
    hinge_peak_rotation_time: NDArray[np.float64] | None = field(default=None, repr=False)
    hinge_residual_rotation: NDArray[np.float64] | None = field(default=None, repr=False)
    hinge_dissipated: NDArray[np.float64] | None = field(default=None, repr=False)
    frame_residual_displacement: NDArray[np.float64] | None = field(default=None, repr=False)
    member_end_moment: NDArray[np.float64] | None = field(default=None, repr=False)
    hinge_capped: NDArray[np.bool_] | None = field(default=None, repr=False)
    frame_restoring_force: NDArray[np.float64] | None = field(default=None, repr=False)

    # ----------------------------------------------------------------- basic views
    @property
    def time(self) -> NDArray[np.float64]:
        """Output times [s]."""
        return np.asarray(np.arange(self.displacement.shape[0]) * self.dt, dtype=np.float64)

    @property
    def wall_time(self) -> float:
        """Integration time [s]."""
        return self.stats.wall_time

    @cached_property
    def drift(self) -> NDArray[np.float64]:
        """Storey drift ``u_j − u_{j−1}`` [m] (nt, N), storey j of each building: floor j
        less the floor below it (:meth:`PoundingModel.floor_below`; consecutive floors by
        elevation in a matrix building); NaN for a DOF that is not a floor — except the
        ``u_y`` DOFs of a building in plan, which hold the drift of the floors' centres of
        mass along y (its ``u_x`` DOFs are its floors, their drift along x). A base slab's
        drift is its isolation bearing's displacement (:attr:`Result.bearings`). A building
        on a flexible base has the drifts of its own deformation, not its floors less the
        floor below: ``x_j − x_{j−1} − (z_j − z_{j−1}) φ`` with ``x_0 = u_f``, the footing's
        sway and rocking taken out (in plan: along x and y at the centres of mass, the
        footing's rigid motion taken out;
        :func:`pounding.result.foundations.flexible_base_drifts`)."""
        u = self.displacement
        below = self.model.floor_below()
        out = u.copy()
        sub = np.flatnonzero(below >= 0)
        out[:, sub] -= u[:, below[sub]]
        out[:, below == -2] = np.nan
        for off, n in self._plan_blocks:
            iy = off + 1 + 3 * np.arange(n)
            out[:, iy] = u[:, iy]
            out[:, iy[1:]] -= u[:, iy[:-1]]
        for cols, d in flexible_base_drifts(self.model, u):
            out[:, cols] = d
        return out

    @cached_property
    def _plan_blocks(self) -> list[tuple[int, int]]:
        """``(first DOF, floors)`` of every building in plan."""
        return [(int(off), plan.n_floors)
                for off, bl in zip(self.model.system.offsets, self.model.buildings)
                if (plan := plan_of(bl)) is not None]

    @cached_property
    def _frame_shears(self) -> list[tuple[int, NDArray[np.float64]]]:
        """``(floor DOF, storey shear (nt,))`` of every frame's storeys."""
        return frame_storey_shear(self.model, self.displacement, self.frame_restoring_force)

    def _storey_stiffness(self) -> NDArray[np.float64]:
        """Storey stiffness [N/m] under every DOF: a shear building's ``k_j``; NaN for a
        matrix building (its ``K`` has no storey stiffness; a frame's storey shear comes from
        its restoring forces, :func:`pounding.result.storeys.frame_storey_shear`)."""
        return np.concatenate([b.stiffnesses if hasattr(b, "stiffnesses") else
                               flexible_base_storeys(b) for b in self.model.buildings])

    @cached_property
    def storey_shear(self) -> NDArray[np.float64]:
        """Storey shear [N] (nt, N): ``k_j × drift_j`` for linear storeys, the storey law's
        shear for yielding ones (a base slab's: its bearing's force); for a building in plan
        with lateral elements, ``V_x`` under its ``u_x`` DOFs and ``V_y`` under its ``u_y``
        DOFs (:func:`pounding.result.storeys.plan_storey_forces`; the torque is
        :attr:`storey_torque`); for a frame, the lateral restoring forces above the storey
        (:func:`pounding.result.storeys.frame_storey_shear`); NaN for another matrix
        building (no storey stiffness)."""
        k = self._storey_stiffness()
        out = self.drift * k
        cols = self._yielding_columns()
        if cols.size:
            if self.yielding_shear is None:
                raise ValueError("result: the model has yielding storeys but no yielding_shear")
            out[:, cols] = self.yielding_shear[:, self._storey_rows()]
        for (off, n), (vx, vy, _) in zip(self._plan_blocks, self._plan_forces):
            ix = off + 3 * np.arange(n)
            out[:, ix], out[:, ix + 1] = vx, vy
        for col, v in self._frame_shears:
            out[:, col] = v
        return out

    @cached_property
    def storey_torque(self) -> NDArray[np.float64]:
        """Storey torque [N·m] (nt, N) under the ``θ`` DOFs of a building in plan with
        lateral elements, about the centre of mass of the floor above
        (:func:`pounding.result.storeys.plan_storey_forces`); NaN elsewhere."""
        out = np.full(self.displacement.shape, np.nan)
        for (off, n), (_, _, tq) in zip(self._plan_blocks, self._plan_forces):
            out[:, off + 2 + 3 * np.arange(n)] = tq
        return out

    @cached_property
    def _plan_forces(self) -> list[tuple[NDArray[np.float64], ...]]:
        """``(V_x, V_y, T)`` histories of every building in plan, (nt, floors) each."""
        # (on a flexible base, the building's own deformation: the footing's motion out)
        plans = [(plan, bl) for bl in self.model.buildings if (plan := plan_of(bl)) is not None]
        u = self.displacement
        return [plan_storey_forces(plan, plan_deformation(bl, u[:, off: off + bl.n]))
                for (plan, bl), (off, _) in zip(plans, self._plan_blocks)]

    @cached_property
    def is_bearing(self) -> NDArray[np.bool_]:
        """True at every base slab (N,): its "storey" is an isolation bearing, reported by
        :attr:`Result.bearings` and left out of the storey measures
        (:attr:`peak_drift_ratio`, :attr:`ductility`)."""
        return bearing_mask(self.model)

    def _yielding_columns(self) -> NDArray[np.int64]:
        offsets = self.model.system.offsets
        return np.array([offsets[p] + j for p, j in self.model.yielding_storeys], dtype=np.int64)

    def _storey_rows(self) -> NDArray[np.int64]:
        """The element rows that are storeys (:attr:`PoundingModel.yielding_storeys` order)."""
        return np.array([r for r, (_, row) in enumerate(self.model.element_rows)
                         if row.storey >= 0], dtype=np.int64)

    @cached_property
    def element_deformation(self) -> NDArray[np.float64]:
        """Deformation [m] (nt, n_e) of every element row (:attr:`PoundingModel.element_rows`:
        yielding storeys, a bridge frame's piers and bearings; names
        :meth:`PoundingModel.element_labels`): ``u[upper] − u[lower] − lever · u[rock]``
        (a pier's drift, a bearing's displacement, a storey's drift)."""
        model, u = self.model, self.displacement
        out = np.zeros((u.shape[0], len(model.element_rows)))
        offsets = model.system.offsets
        for r, (p, row) in enumerate(model.element_rows):
            out[:, r] = u[:, offsets[p] + row.upper]
            if row.lower >= 0:
                out[:, r] -= u[:, offsets[p] + row.lower]
            if row.rock >= 0:
                out[:, r] -= row.lever * u[:, offsets[p] + row.rock]
        return out

    @property
    def element_force(self) -> NDArray[np.float64]:
        """Force [N] (nt, n_e) of every element row from its law (a pier's shear, a
        bearing's force, a storey's shear), positive when it resists a positive
        :attr:`element_deformation`."""
        if self.yielding_shear is None:
            return np.zeros((self.displacement.shape[0], len(self.model.element_rows)))
        return self.yielding_shear

    @cached_property
    def element_residual_deformation(self) -> NDArray[np.float64]:
        """Every element row's deformation at the end unloaded to zero force along its law's
        unloading stiffness [m] (n_e,) (:func:`~pounding.result.storeys.
        element_residual_deformation`)."""
        if not self.model.element_rows:
            return np.zeros(0)
        return element_residual_deformation(self.model, self.element_deformation[-1],
                                            self.element_force[-1], self.final_z)

    @cached_property
    def ductility(self) -> NDArray[np.float64]:
        """Storey ductility demand ``max|drift| / (F_y / k)`` [-] (N,); NaN for linear
        storeys (no yield point) and for an isolation bearing (not a storey: its
        displacement is in :attr:`Result.bearings`). The peak drift is :attr:`peak_drift`
        (located inside steps)."""
        out = np.full(self.model.n_dof, np.nan)
        peak = self.peak_drift
        k = self._storey_stiffness()
        for off, b in zip(self.model.system.offsets, self.model.buildings):
            fy = b.yield_forces  # (None for a linear building; NaN for a linear storey)
            if fy is not None:
                out[off: off + b.n] = peak[off: off + b.n] / (fy / k[off: off + b.n])
        out[self.is_bearing] = np.nan
        return out

    @cached_property
    def residual_drift(self) -> NDArray[np.float64]:
        """Residual storey drift [m] (N,): the drift left when the storey, from its state at
        the end of the run, is unloaded to zero shear along its unloading stiffness
        (:func:`pounding.result.storeys.residual_storey_drift`; for the bilinear law: its
        plastic drift); for a frame with plastic hinges, the drift of its floors unloaded to
        zero lateral force along its hinges' unloading stiffness
        (:attr:`frame_residual_displacement`). 0 for linear storeys. Run on past the record
        (``duration``) to let the motion die out first."""
        out = (residual_storey_drift(self.model, self.drift[-1], self.storey_shear[-1],
                                     self.final_z) if self.model.is_inelastic
               else np.zeros(self.model.n_dof))
        res = self.frame_residual_displacement
        if res is not None:
            below = self.model.floor_below()
            on = np.flatnonzero(np.isfinite(res) & (below > -2))  # the frames' floors
            out[on] = res[on] - np.where(below[on] >= 0, res[np.maximum(below[on], 0)], 0.0)
        return out

    @cached_property
    def column_shear(self) -> NDArray[np.float64]:
        """Shear demand on each struck column [N] (nt, n_c), the larger in magnitude of the
        local shears below and above the contact point
        (:func:`pounding.result.storeys.struck_column_shear`): NaN for floor-to-floor
        contacts and for a column of a building given as matrices (no storey shear). Read
        at the output steps (the contact force peak itself is located inside steps:
        :attr:`peak_contact_force`)."""
        return struck_column_shear(self.model, self.contact_force, self._storey_shear_of_columns)

    @cached_property
    def _storey_shear_of_columns(self) -> NDArray[np.float64]:
        """:attr:`storey_shear` where the storey is one column (NaN for a frame's: its
        columns share it, and :attr:`member_end_moment` gives each its own)."""
        frames = [col for col, _ in self._frame_shears]
        if not frames:
            return self.storey_shear
        out = self.storey_shear.copy()
        out[:, frames] = np.nan
        return out

    @cached_property
    def peak_column_shear(self) -> NDArray[np.float64]:
        """Largest :attr:`column_shear` of every contact [N] (NaN: floor to floor)."""
        cs = self.column_shear
        return np.array([np.nanmax(cs[:, j]) if np.isfinite(cs[:, j]).any() else np.nan
                         for j in range(cs.shape[1])])

    @cached_property
    def column_shear_ratio(self) -> NDArray[np.float64]:
        """:attr:`peak_column_shear` over the struck storey's own peak storey shear [-]
        (n_c,): how much the impacts raise the shear the column must carry (1: not at all;
        NaN: floor to floor, or a column of a building given as matrices, which has no
        storey shear)."""
        out = np.full(len(self.model.contacts), np.nan)
        struck = [(c.index, c.struck) for c in self.model.contacts if c.struck is not None]
        if not struck:
            return out  # floor to floor only: no storey-shear history needed
        peak_v = peak_abs(self._storey_shear_of_columns)
        offsets = self.model.system.offsets
        for index, pt in struck:
            v = peak_v[offsets[pt.building] + pt.upper]
            if np.isnan(v):
                continue  # a matrix building's column: no storey shear to compare with
            out[index] = self.peak_column_shear[index] / v if v > 0 else np.inf
        return out

    def _peak(self, col: int, sampled: NDArray[np.float64]) -> tuple[NDArray[np.float64],
                                                                     NDArray[np.float64]]:
        if self.located_peaks is not None:
            return self.located_peaks[:, col].copy(), self.located_peaks[:, col + 1].copy()
        a = np.abs(sampled)
        k = np.argmax(a, axis=0)
        return a[k, np.arange(a.shape[1])], self.time[k]

    @property
    def peak_displacement(self) -> NDArray[np.float64]:
        """Largest |displacement| of every floor [m] (N,), located inside solver steps."""
        return self._peak(0, self.displacement)[0]

    @property
    def peak_displacement_time(self) -> NDArray[np.float64]:
        """Time of every floor's :attr:`peak_displacement` [s] (N,)."""
        return self._peak(0, self.displacement)[1]

    @property
    def peak_drift(self) -> NDArray[np.float64]:
        """Largest |storey drift| of every storey [m] (N,: the storey below each floor),
        located inside solver steps (a building on a flexible base: the drift of its own
        deformation, read at the output steps, :attr:`drift`); NaN for a DOF that is not a
        floor; a building in plan: along x under its ``u_x`` DOFs, along y under its ``u_y``
        DOFs (read at the output steps), none under ``θ``)."""
        return np.where(self._drifts, self._drift_peaks[0], np.nan)

    @property
    def peak_drift_time(self) -> NDArray[np.float64]:
        """Time of every storey's :attr:`peak_drift` [s] (N,)."""
        return np.where(self._drifts, self._drift_peaks[1], np.nan)

    @cached_property
    def _plan_y(self) -> NDArray[np.int64]:
        """The ``u_y`` DOFs of the buildings in plan (their drifts along y)."""
        return np.concatenate([off + 1 + 3 * np.arange(n) for off, n in self._plan_blocks]
                              or [np.zeros(0, dtype=np.int64)]).astype(np.int64)

    @cached_property
    def _drifts(self) -> NDArray[np.bool_]:
        """True under every DOF with a storey drift: the floors, and a plan's ``u_y``."""
        out = np.array(self.model.is_floor, dtype=bool)
        out[self._plan_y] = True
        return out

    @cached_property
    def _drift_peaks(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        peak, when = self._peak(2, self.drift)
        cols = np.concatenate([c for c, _ in flexible_base_drifts(self.model,
                                                                  self.displacement[:1])]
                              + [self._plan_y])
        if cols.size:  # (the kernel located the floors' relative drift: not these)
            a = np.abs(self.drift[:, cols])
            k = np.argmax(a, axis=0)
            peak[cols], when[cols] = a[k, np.arange(cols.size)], self.time[k]
        return peak, when

    @property
    def peak_drift_ratio(self) -> NDArray[np.float64]:
        """:attr:`peak_drift` over the storey height [-] (N,); NaN for a DOF that is not a
        floor and under a base slab (its isolation bearing is no storey:
        :attr:`Result.bearings`)."""
        heights = np.concatenate([b.heights for b in self.model.buildings])
        heights[self._plan_y] = heights[self._plan_y - 1]  # (a plan's u_y: its storey's)
        ratio = self.peak_drift / heights
        return np.where(self.is_bearing, np.nan, ratio)

    @property
    def peak_abs_acceleration(self) -> NDArray[np.float64]:
        """Largest |absolute acceleration| of every floor [m/s²] (N,), located inside solver
        steps (at an impact the largest of the values just before and after)."""
        return self._peak(4, self.abs_acceleration)[0]

    @property
    def peak_abs_acceleration_time(self) -> NDArray[np.float64]:
        """Time of every floor's :attr:`peak_abs_acceleration` [s] (N,)."""
        return self._peak(4, self.abs_acceleration)[1]

    @cached_property
    def peak_storey_shear(self) -> NDArray[np.float64]:
        """Largest |storey shear| of every storey [N] (N,): ``k × peak drift`` for a linear
        storey (so located inside steps with the drift), the largest of the storey law's
        shear at the output steps for a yielding one or a frame; NaN for another matrix
        building."""
        k = self._storey_stiffness()
        out = k * self.peak_drift
        cols = self._yielding_columns()
        if cols.size:
            out[cols] = np.abs(self.storey_shear[:, cols]).max(axis=0)
        for off, n in self._plan_blocks:  # V_x, V_y at the output steps
            ix = off + 3 * np.arange(n)
            out[ix] = sampled_peak(self.storey_shear[:, ix], self.time)[0]
            out[ix + 1] = sampled_peak(self.storey_shear[:, ix + 1], self.time)[0]
        frames = [col for col, _ in self._frame_shears]  # (a frame's: at the output steps)
        if frames:
            out[frames] = sampled_peak(self.storey_shear[:, frames], self.time)[0]
        return out

    @cached_property
    def peak_storey_shear_time(self) -> NDArray[np.float64]:
        """Time of every storey's :attr:`peak_storey_shear` [s] (N,) (NaN where there is no
        storey shear)."""
        out = np.where(np.isnan(self._storey_stiffness()), np.nan, self.peak_drift_time)
        cols = self._yielding_columns()
        if cols.size:
            out[cols] = self.time[np.argmax(np.abs(self.storey_shear[:, cols]), axis=0)]
        for off, n in self._plan_blocks:
            ix = off + 3 * np.arange(n)
            out[ix] = sampled_peak(self.storey_shear[:, ix], self.time)[1]
            out[ix + 1] = sampled_peak(self.storey_shear[:, ix + 1], self.time)[1]
        frames = [col for col, _ in self._frame_shears]
        if frames:
            out[frames] = sampled_peak(self.storey_shear[:, frames], self.time)[1]
        return out

    @cached_property
    def energy_balance_error(self) -> float:
        """Largest ``|E_0 + E_input − (E_kin + E_strain + E_damping + E_hyst + W_contact +
        E_links)|`` over the run (``E_0`` the kinetic and strain energy at t = 0), relative
        to the larger of the largest input energy and ``E_0`` (dimensionless; 0 for a run
        with no energy)."""
        # one pass over the history (imported here: importing it imports numba)
        from pounding.result.reductions import energy_residual_max

        e = np.asarray(self.energy, dtype=float)
        e0 = e[0, 1] + e[0, 2]
        worst, largest = energy_residual_max(e)
        scale = max(largest, e0)
        if scale <= 0.0:
            return 0.0
        return float(worst / scale)

"""The yielding frames of one run, between the compiled kernel's calls.

A frame with plastic hinges stands in the row as its floors (a
:class:`~pounding.structure.frame_linear.FrameBuilding`), and in each configuration of its
hinges its floors' restoring force is linear, ``R = K_c u + f0``
(:mod:`pounding.structure.frame_configuration`). The kernel reads the configuration from
arrays that belong to the run, not to the model (whose arrays are shared by every run of
it, :data:`pounding.integrate.kernel_model.STRUCTURES`):

* the frame's block of the banded stiffness, a copy for the run, holds ``K_c``;
* ``Floors.f_rows`` holds the frame's floors, ``f0`` and the constant ``c`` that keeps the
  frame's work ``½ uᵀ K_c u + f0ᵀ u + c`` continuous across configurations (empty for models
  without yielding frames, whose arithmetic is then unchanged);
* :class:`~pounding.integrate.kernel_model.HingeRows` holds one row per hinge: its rotation
  ``θ = A_h u + a0_h`` over the frame's floors, the ends of the branch it is on, the
  direction that branch holds for, its moment line and its committed point and work
  (:data:`pounding.integrate.layout.HS_A0` …).

A frame on a flexible base (:class:`~pounding.structure.frame_linear.FlexibleBaseFrame`, its
footing's sway and rocking DOFs of their own) is the block ``y = [x, u_f, φ]`` of its DOFs
and its footing's; its hinges live in its own deformation ``u = T y`` (``T = [I | −1 |
−z]``), so the kernel is given the configuration in ``y``: the block's stiffness ``K_y =
Tᵀ K_c T + diag(0, k_x, k_φ)`` (the footing's rows and columns coupled to every DOF of the
frame), ``f0_y = Tᵀ f0`` and hinge rows ``A_h T`` over the whole block; its work
``½ yᵀ K_y y + f0_yᵀ y + c`` is the frame's ``½ uᵀ K_c u + f0ᵀ u + c`` plus the soil
springs' energy. The frame's motion (:class:`FrameMotion`) stays in ``u``; its drifts,
member moments and restoring forces are read from ``u``.

The kernel locates every hinge event (a rotation reaching an end of its branch, a one-way
branch reversing) on real Runge–Kutta steps like a contact event, accepts the step to it
and returns (``ws_i[I_STOP]``); :class:`FrameRun` then moves the frame's hinges along their
laws (the Python laws of :mod:`pounding.hysteresis.hinges`, the one implementation of each),
chooses the next configuration and writes it into the arrays, and the kernel resumes at the
same instant inside the grid step.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from pounding.integrate.kernel_model import HingeRows, KernelModel, kernel_bands
from pounding.integrate.layout import (
    EVENT_TOL,
    HS_A0,
    HS_COLUMNS,
    HS_DIR,
    HS_HI,
    HS_K_UNLOAD,
    HS_KT,
    HS_LO,
    HS_M_C,
    HS_Q,
    HS_REC0,
    HS_THETA_C,
    HS_WABS,
    HS_WORK_C,
    ROW_BLOCK,
)
from pounding.model import PoundingModel
from pounding.structure.frame_configuration import Configuration, FrameCollapse, FrameMotion

__all__ = ["SIDESWAY_RATIO", "FrameRun", "HingeOutputs"]

SIDESWAY_RATIO: float = 1.0
"""A storey drift ratio beyond which a yielding frame has collapsed sideways and the run
stops (:meth:`FrameRun.check_sidesway`)."""


@dataclass(frozen=True)
class HingeOutputs:
    """What a run reports of the hinges of its yielding frames (in
    :meth:`PoundingModel.hinge_labels` order)."""

    peak_rotation: NDArray[np.float64]  #: largest |θ| [rad], at events and output steps
    peak_rotation_time: NDArray[np.float64]  #: its time [s]
    residual_rotation: NDArray[np.float64]  #: θ unloaded to zero moment at the end [rad]
    dissipated: NDArray[np.float64]  #: hysteretic energy at the end [J]
    events: int  #: hinge events in the run
    #: every DOF's displacement [m] once each yielding frame is unloaded to zero lateral
    #: force along its hinges' unloading stiffness at the end (NaN off the frames)
    residual_floors: NDArray[np.float64]
    #: the frames' members' end moments at the output steps [N·m] (nt, Σ 2 m), frames in
    #: order, then elements, end 1 then end 2 (counter-clockwise positive)
    member_end_moment: NDArray[np.float64]
    #: each hinge reached its capping point (a branch of negative tangent ahead as it
    #: moved) or had its moment jump (fracture, complete deterioration) in the run
    capped: NDArray[np.bool_]
    #: the yielding frames' restoring force on their DOFs at the output steps [N, N·m]
    #: (nt, N), net of gravity (NaN off the frames)
    restoring: NDArray[np.float64]


@dataclass
class _Frame:
    building: int  #: its index in the row
    offset: int  #: its first floor's DOF
    rows: slice  #: its hinge rows
    motion: FrameMotion
    first: int  #: its first row in ``Floors.f_rows``
    #: ``T`` (n_floors, size): its own DOFs' displacement ``u = T y`` from its block's ``y``
    #: (the identity on a fixed base; ``[I | −1 | −z]`` on a footing)
    T: NDArray[np.float64]
    #: the soil's springs on its block's DOFs [N/m, N·m/rad] (size,), zero on a fixed base
    soil: NDArray[np.float64]
    band_rows: NDArray[np.int64]  #: where its K_c's entries go in the banded stiffness
    band_cols: NDArray[np.int64]
    heights: NDArray[np.float64]  #: its storeys' heights [m]
    work_constant: float = 0.0  #: c: its work is ``½ uᵀ K_c u + f0ᵀ u + c`` [J]
    #: each configuration it took: from when [s], its ``U = P u + p0`` and its floors'
    #: restoring force ``R = K u + f0``, as ``(t, P, p0, K, f0)``
    taken: list[tuple[float, NDArray[np.float64], NDArray[np.float64], NDArray[np.float64],
                      NDArray[np.float64]]] = field(default_factory=list)

    @property
    def size(self) -> int:
        """Its block's DOFs: its own, then its footing's sway and rocking (if on one)."""
        return int(self.T.shape[1])


def _base_transform(building: object, n_own: int
                    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """``(T, soil)`` of a yielding frame (:class:`_Frame`): on a fixed base the identity and
    no springs; on a flexible base (:class:`~pounding.structure.frame_linear.
    FlexibleBaseFrame`, its footing's sway and rocking DOFs of their own) the foundation's
    ``T = [I | −1 | −z]`` and the springs ``k_x``, ``k_φ`` on the footing's DOFs."""
    foundation = getattr(building, "foundation", None)
    if foundation is None:
        return np.eye(n_own), np.zeros(n_own)
    T = np.asarray(foundation.deformation, dtype=float)
    if T.shape != (n_own, n_own + 2) or not all(foundation.explicit):
        raise ValueError(f"building {getattr(building, 'name', '')!r}: foundation.mass and "
                         "foundation.inertia: a frame with plastic hinges on a flexible base "
                         "needs its footing's sway and rocking as DOFs (mass and inertia > 0)")
    imp = foundation.impedance
    return T, np.concatenate([np.zeros(n_own), [imp.k_x, imp.k_r]])


class FrameRun:
    """The yielding frames of a run: their motion and the kernel's arrays for them.

    Parameters
    ----------
    model : PoundingModel
        A model with yielding frames (:attr:`PoundingModel.yielding_frames`).
    km : KernelModel
        Its arrays as the kernel reads them (not modified: the run gets its own copies of
        those a configuration changes, :attr:`arrays`).
    atol : ndarray
        The run's absolute tolerances (displacements ``atol[0]``, velocities ``atol[n]``):
        a hinge whose rotation rate is within ``EVENT_TOL · atol[n] · Σ|A_h|`` of zero is
        moving the way its rate's rate says.
    """

    def __init__(self, model: PoundingModel, km: KernelModel, atol: NDArray[np.float64]) -> None:
        n = km.n
        self.n = n
        self.rate_tol = EVENT_TOL * float(atol[n])
        self.theta_tol = EVENT_TOL * float(atol[0])
        self.frames: list[_Frame] = []
        h0 = 0
        first = 0
        for b, bl in model.yielding_frames:
            motion = FrameMotion(bl.frame, bl.gravity_state, bl.kept)
            rows = slice(h0, h0 + motion.n_hinges)
            h0 += motion.n_hinges
            T, soil = _base_transform(bl, motion.n_floors)
            no_band = np.zeros((0, 0), dtype=np.int64)  # (set below, once the band is known)
            self.frames.append(_Frame(b, int(model.system.offsets[b]), rows, motion, first,
                                      T, soil, no_band, no_band,
                                      np.diff(bl.elevations[:len(bl.floors)], prepend=0.0)))
            first += T.shape[1]
        self.n_hinges = h0
        size_max = max(f.size for f in self.frames)
        width = -(-size_max // ROW_BLOCK) * ROW_BLOCK
        fl = km.floors
        # the frames' condensed stiffness is full over their blocks: a band wide enough
        bw = max(fl.bw, size_max - 1)
        self.bw = bw
        for f in self.frames:
            a = np.arange(f.size)
            rows_i, cols_j = np.meshgrid(a, a, indexing="ij")
            f.band_rows, f.band_cols = cols_j - rows_i + bw, f.offset + rows_i
        k_band, c_band = kernel_bands(km.K, km.C, bw)  # (the run's own copy of K's)
        f_dof = np.concatenate([f.offset + np.arange(f.size) for f in self.frames])
        self.h_dof = np.zeros((h0, width), dtype=np.int64)
        self.h_w = np.zeros((h0, width))
        self.h_state = np.zeros((h0, HS_COLUMNS))
        for f in self.frames:
            self.h_dof[f.rows] = f.offset  # (padding: weight 0 on the first floor)
            self.h_dof[f.rows, :f.size] = f.offset + np.arange(f.size)
        self.k_band = k_band
        self.f_rows = np.zeros((f_dof.size, 3))
        self.f_rows[:, 0] = f_dof
        self.floors = fl._replace(bw=bw, k_band=k_band, c_band=c_band, f_rows=self.f_rows)
        self.hinges = HingeRows(self.h_dof, self.h_w, self.h_state)
        self.arrays = km.arrays._replace(floors=self.floors, hinges=self.hinges)
        self.masses = fl.m_diag
        self.C = km.C
        self.R = fl.r
        self.peak = np.zeros(h0)
        self.peak_time = np.zeros(h0)
        self.events = 0
        self._last_event = (-1.0, 0)  # the time of the last event, and events at it
        self._chatter = 4 * h0 + 20

    # ------------------------------------------------------------------ start
    def start(self, x: NDArray[np.float64], ag0: NDArray[np.float64],
              ag_next: NDArray[np.float64]) -> None:
        """Configure every frame at the start, state ``x`` = [u, u̇] (its floors at rest in
        the gravity state, or moving), the ground components ``ag0`` at t = 0 [m/s²] and
        ``ag_next`` the first ones not all zero (which way the ground will push a frame at
        rest whose hinge's branch depends on the direction).

        Raises
        ------
        ValueError
            If the frames' floors are given an initial displacement.
        """
        for f in self.frames:
            sl = self._block(f)
            if np.any(x[sl] != 0.0):
                raise ValueError(f"initial_displacement: frame {f.motion.frame.name!r} (building "
                                 f"B{f.building + 1}) starts displaced; a yielding frame starts "
                                 "at rest in its gravity state (give it an initial velocity "
                                 "instead)")
            y = x[sl]
            dy = self._rates(f, x)
            m = self.masses[sl]
            C = self.C[sl, sl]
            R = self.R[sl]
            T, soil = f.T, f.soil

            def acceleration(cfg: Configuration, y: NDArray[np.float64] = y,
                             dy: NDArray[np.float64] = dy, m: NDArray[np.float64] = m,
                             C: NDArray[np.float64] = C, R: NDArray[np.float64] = R,
                             T: NDArray[np.float64] = T, soil: NDArray[np.float64] = soil
                             ) -> NDArray[np.float64]:
                # (the block's accelerations in the configuration, then the frame's own)
                force = T.T @ (cfg.K @ (T @ y) + cfg.f0) + soil * y + C @ dy
                return T @ (-force / m - R @ ag0)

            v = T @ dy
            # (at rest, which way the ground will push the frame's own DOFs: as on a fixed
            # base — on a footing the block's first acceleration is rigid, T r = 0)
            fallback = -(R[:f.motion.n_floors] @ ag_next)
            f.motion.configure(v, acceleration, self.rate_tol, fallback=fallback)
            self._write(f, 0.0)

    def initial_row(self, x: NDArray[np.float64], rotation: NDArray[np.float64],
                    moment: NDArray[np.float64]) -> None:
        """Write the hinges' rotations [rad] and moments [N·m] at t = 0 into the first rows
        of their histories."""
        for f in self.frames:
            cfg = f.motion.config
            assert cfg is not None
            theta = cfg.A @ self._own(f, x) + cfg.a0
            rotation[f.rows] = theta
            moment[f.rows] = cfg.tangents * theta + cfg.q
            self._track(f, theta, 0.0)

    # ------------------------------------------------------------------ events
    def on_event(self, x: NDArray[np.float64], f_x: NDArray[np.float64], t: float,
                 row: int) -> None:
        """A hinge event that ended a call of the kernel: commit the frame of hinge ``row``
        at state ``x`` (``f_x`` = f(x), whose velocity part gives the floors'
        accelerations), choose its next configuration and write it; likewise any other
        frame whose hinge is at or past an end of its branch (simultaneous events).

        Raises
        ------
        ValueError
            If the hinges keep changing configuration at one instant (more than ``4 n_h +
            20`` events there): a configuration its hinges cannot settle in.
        """
        self.events += 1
        last_t, count = self._last_event
        count = count + 1 if abs(t - last_t) <= 1e-12 * max(abs(t), 1.0) else 0
        self._last_event = (t, count)
        if count > self._chatter:
            frame = next(f for f in self.frames if f.rows.start <= row < f.rows.stop)
            raise ValueError(f"solver: the hinges of frame {frame.motion.frame.name!r} "
                             f"(building B{frame.building + 1}) keep changing branch at "
                             f"t = {t:.6f} s ({count} events at that instant) without "
                             "settling; check its hinge laws (a branch of zero length, or "
                             "a tangent that leaves its joints with no stiffness)")
        for f in self.frames:
            u = self._own(f, x)
            if not (f.rows.start <= row < f.rows.stop or self._due(f, x)):
                continue
            v = f.T @ self._rates(f, x)
            a = f.T @ self._rates(f, f_x)
            event = row - f.rows.start if f.rows.start <= row < f.rows.stop else None
            theta = f.motion.commit(u, land=f.motion.landing(u, v, self.theta_tol, event))
            self._track(f, theta, t)
            work = self._work(f, u)
            f.motion.configure(v, a, self.rate_tol)
            try:
                f.motion.redistribute(u, v, a, self.rate_tol, self.theta_tol)
            except FrameCollapse as exc:  # (said of the building, as the other stops are)
                name = f.motion.frame.name
                raise FrameCollapse(str(exc).replace(
                    f"{name}:", f"{name} (building B{f.building + 1}):", 1)
                    + f" at t = {t:.3f} s") from None
            f.work_constant = 0.0
            f.work_constant = work - self._work(f, u)
            self._write(f, t)

    def _due(self, f: _Frame, x: NDArray[np.float64]) -> bool:
        """Is a hinge of frame ``f`` at or past an end of its branch (within the event
        tolerance), or moving against its one-way branch?"""
        cfg = f.motion.config
        assert cfg is not None
        u = self._own(f, x)
        v = f.T @ self._rates(f, x)
        theta = cfg.A @ u + cfg.a0
        rate = cfg.A @ v
        wabs = np.sum(np.abs(cfg.A @ f.T), axis=1)  # (as the kernel's HS_WABS)
        tol = self.theta_tol * wabs
        past = (theta >= cfg.upper - tol) | (theta <= cfg.lower + tol)
        against = cfg.directions * rate < -self.rate_tol * wabs
        return bool(np.any(past | against))

    def finish(self, x: NDArray[np.float64], t_end: float, rotation: NDArray[np.float64],
               displacement: NDArray[np.float64]) -> HingeOutputs:
        """Commit every frame at the final state ``x`` and report its hinges (the peaks
        also over the output histories ``rotation`` (nt, n_h) [rad]) and its members' end
        moments at the output steps of ``displacement`` (nt, n) [m], evenly spaced to
        ``t_end``."""
        for f in self.frames:
            theta = f.motion.commit(self._own(f, x))
            self._track(f, theta, t_end)
        if rotation.size:
            # (the largest sample of each hinge first, then where it is only for the hinges
            # it beats: an argmax down the columns of a row-major array is slow)
            sampled = np.maximum(rotation.max(axis=0), -rotation.min(axis=0))  # (no copy)
            more = np.flatnonzero(sampled > self.peak)
            k = np.argmax(np.abs(rotation[:, more]), axis=0)
            self.peak[more] = sampled[more]
            self.peak_time[more] = k * (t_end / max(rotation.shape[0] - 1, 1))
        residual = np.concatenate([f.motion.plastic_rotations() for f in self.frames])
        dissipated = np.concatenate([f.motion.hysteretic_energy() for f in self.frames])
        floors = np.full(self.n, np.nan)
        for f in self.frames:
            try:
                unloaded = f.motion.residual_floors(self._own(f, x))
            except ValueError:  # unloaded, a mechanism: no residual position (NaN)
                continue
            # (unloaded, the soil's springs carry nothing: the footing back at rest, y = u)
            floors[self._block(f)] = np.concatenate([unloaded,
                                                     np.zeros(f.size - unloaded.size)])
        moments = np.concatenate([self._end_moments(f, displacement, t_end)
                                  for f in self.frames], axis=1)
        restoring = np.full(displacement.shape, np.nan)
        for f in self.frames:
            own = self._restoring(f, displacement, t_end)
            # (on the block's DOFs: Tᵀ R and the soil's springs — the frame's own DOFs R)
            restoring[:, self._block(f)] = (own @ f.T
                                            + displacement[:, self._block(f)] * f.soil)
        capped = np.concatenate([f.motion.capped for f in self.frames])
        return HingeOutputs(self.peak.copy(), self.peak_time.copy(), residual, dissipated,
                            self.events, floors, moments, capped, restoring)

    def _end_moments(self, f: _Frame, displacement: NDArray[np.float64], t_end: float
                     ) -> NDArray[np.float64]:
        """Frame ``f``'s members' end moments [N·m] (nt, 2 m) at the output steps: each step
        in the configuration the frame was in then, ``U = P u + p0``, through
        :func:`pounding.structure.frame_stiffness.end_moment_operator`."""
        import scipy.sparse

        from pounding.structure.frame_stiffness import end_moment_operator

        motion = f.motion
        E_dense, m0 = end_moment_operator(motion.frame, motion.dofs, motion.axial)
        E = scipy.sparse.csr_matrix(E_dense)
        by_P: dict[int, NDArray[np.float64]] = {}

        def linear(taken: tuple) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
            _, P, p0, _, _ = taken
            EP = by_P.get(id(P))
            if EP is None:
                EP = by_P[id(P)] = np.asarray(E @ P)
            return EP, E @ p0 + m0

        return self._at_output_steps(f, displacement, t_end, E.shape[0], linear)

    def _restoring(self, f: _Frame, displacement: NDArray[np.float64], t_end: float
                   ) -> NDArray[np.float64]:
        """Frame ``f``'s restoring force on its DOFs [N, N·m] (nt, n_f) at the output steps,
        net of gravity: ``R = K u + f0`` in the configuration it was in then."""
        return self._at_output_steps(f, displacement, t_end, f.motion.n_floors,
                                     lambda taken: (taken[3], taken[4]))

    def _at_output_steps(self, f: _Frame, displacement: NDArray[np.float64], t_end: float,
                         width: int, linear: Callable[[tuple], tuple[NDArray[np.float64],
                                                                     NDArray[np.float64]]]
                         ) -> NDArray[np.float64]:
        """``L u + c`` (nt, width) at the output steps of ``displacement`` (nt, n), evenly
        spaced to ``t_end``, with ``(L, c) = linear(taken)`` of the configuration frame ``f``
        was in at each step."""
        nt = displacement.shape[0]
        u = displacement[:, self._block(f)] @ f.T.T
        times = np.array([c[0] for c in f.taken])
        at = np.arange(nt) * (t_end / max(nt - 1, 1))
        which = np.searchsorted(times, at + 1e-12 * max(t_end, 1.0), side="right") - 1
        out = np.empty((nt, width))
        # (which never decreases: the output steps in runs of one configuration each)
        starts = np.concatenate([[0], np.flatnonzero(np.diff(which)) + 1, [nt]])
        for a, b in zip(starts[:-1], starts[1:]):
            L, c = linear(f.taken[int(which[a])])
            out[a:b] = u[a:b] @ L.T + c
        return out

    def check_sidesway(self, x: NDArray[np.float64], t: float) -> None:
        """Stop the run if a frame's storey has swayed past its own height (a drift ratio
        above 1: the frame collapsed sideways; the small-displacement model means nothing
        there, and a frame with no strength left would be integrated on to any drift).

        Raises
        ------
        FrameCollapse
            Naming the frame, the storey, its drift and the time.
        """
        for f in self.frames:
            u = self._own(f, x)[:f.heights.size]  # (the floors come first)
            drift = u.copy()
            drift[1:] -= u[:-1]
            ratio = np.abs(drift) / f.heights
            j = int(np.argmax(ratio))
            if ratio[j] > SIDESWAY_RATIO:
                raise FrameCollapse(
                    f"{f.motion.frame.name} (building B{f.building + 1}): collapsed sideways: "
                    f"storey {j + 1} drifted {drift[j]:.3g} m, more than its height "
                    f"{f.heights[j]:.3g} m, at t = {t:.3f} s (the run "
                    "stops there)")

    # ------------------------------------------------------------------ arrays
    @staticmethod
    def _work(f: _Frame, u: NDArray[np.float64]) -> float:
        """The work of frame ``f``'s restoring force since the start [J] at floor
        displacements ``u``, in its current configuration: ``½ uᵀ K_c u + f0ᵀ u + c``."""
        cfg = f.motion.config
        assert cfg is not None
        return float(0.5 * u @ cfg.K @ u + cfg.f0 @ u) + f.work_constant

    @staticmethod
    def _block(f: _Frame) -> slice:
        """Frame ``f``'s block of DOFs (its own, then its footing's)."""
        return slice(f.offset, f.offset + f.size)

    def _rates(self, f: _Frame, x: NDArray[np.float64]) -> NDArray[np.float64]:
        """The velocity part of state ``x`` (or accelerations of f(x)) on ``f``'s block."""
        return x[self.n + f.offset: self.n + f.offset + f.size]

    @staticmethod
    def _own(f: _Frame, x: NDArray[np.float64]) -> NDArray[np.float64]:
        """Frame ``f``'s own DOFs' displacements ``u = T y`` [m] at state ``x``."""
        return f.T @ x[f.offset: f.offset + f.size]

    def _track(self, f: _Frame, theta: NDArray[np.float64], t: float) -> None:
        a = np.abs(theta)
        peak = self.peak[f.rows]
        more = a > peak
        self.peak[f.rows] = np.where(more, a, peak)
        self.peak_time[f.rows] = np.where(more, t, self.peak_time[f.rows])

    def _write(self, f: _Frame, t: float) -> None:
        """Write frame ``f``'s configuration, taken at time ``t`` [s], into the run's arrays
        (in place: the kernel holds them)."""
        m = f.motion
        cfg = m.config
        assert cfg is not None
        f.taken.append((t, cfg.P, cfg.p0, cfg.K, cfg.f0))
        size = f.size
        T = f.T
        # band storage: kb[d, i] = K[i, i + d − bw]; over the block, Tᵀ K T + the springs
        self.k_band[f.band_rows, f.band_cols] = T.T @ cfg.K @ T + np.diag(f.soil)
        self.f_rows[f.first: f.first + size, 1] = T.T @ cfg.f0
        self.f_rows[f.first, 2] = f.work_constant
        hs = self.h_state[f.rows]
        A = cfg.A @ T
        self.h_w[f.rows, :size] = A
        hs[:, HS_A0] = cfg.a0
        hs[:, HS_LO] = cfg.lower
        hs[:, HS_HI] = cfg.upper
        hs[:, HS_DIR] = cfg.directions
        hs[:, HS_KT] = cfg.tangents
        hs[:, HS_Q] = cfg.q
        hs[:, HS_THETA_C] = m.rotations()
        hs[:, HS_M_C] = m.moments()
        hs[:, HS_WORK_C] = m.work
        hs[:, HS_K_UNLOAD] = m.unloading_stiffness()
        hs[:, HS_REC0] = m.recoverable0
        hs[:, HS_WABS] = np.sum(np.abs(A), axis=1)
        self.h_state[f.rows] = hs

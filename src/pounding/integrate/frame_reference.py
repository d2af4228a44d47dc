"""The plain SciPy reference for the time history of one nonlinear frame (no numba).

It is the oracle the compiled frame kernel is tested against, so it is written for clarity
and independence, not speed: NumPy/SciPy only, ``solve_ivp`` at a tight tolerance, every
event located and committed exactly. Short windows (seconds of record, a few storeys).

The model
---------
1. **Gravity first** (:func:`pounding.structure.frame_analysis.gravity`): displacements
   ``U_g``, hinge states, and ``base = K_el + K_geo`` (elastic elements plus the geometric
   stiffness of the gravity axial forces and the leaning column, held constant).
2. **Masses lumped** (:func:`~pounding.structure.frame_analysis._mass_vector`): the DOFs
   with mass (``m``) carry the dynamics, ``M ü_m + C u̇_m + f_m = −M r_m a_g(t)`` with ``u``
   the displacements from the gravity state relative to the ground, ``r`` 1 on every
   horizontal DOF, ``f = F(U) − G`` the restoring force net of gravity. The massless DOFs
   (``o``) are condensed statically at every instant, exactly, in the current
   configuration. A massless DOF whose row of the tangent stiffness is zero (a joint whose
   every connection is a plastic hinge of zero tangent) does not move (as in the pushover,
   :func:`~pounding.structure.frame_analysis._advance`).
3. **Configurations.** Each hinge stands on one straight branch of its law
   (``law.branch(state, direction)``); the frame is then linear with tangent stiffness
   ``K_t = configuration_stiffness(base, dofs, k_t)``. Within a configuration that started
   at the event ``e`` (the affine offsets the compiled kernel must mirror)::

       T   = −K_oo⁻¹ K_om                         (massless response to the mass DOFs)
       K_c = K_mm + K_mo T  = K_mm − K_mo K_oo⁻¹ K_om  (static condensation)
       U_o(u_m) = (U_o,e − T u_m,e) + T u_m           since f_o = 0 at e and after
       f_m(u_m) = (f_m,e − K_c u_m,e) + K_c u_m       f_m,e carried over from the last
       θ(u_m)   = (θ_e − Θ u_m,e) + Θ u_m,  Θ = B_m + B_o T
       M_h      = M_h,e + k_t,h (θ_h − θ_h,e)

   with ``θ = B U`` the hinge rotations (``θ_node − θ_end``) and ``θ_e`` the committed
   (landed) rotations. Derivation: ``F(U) = F_e + K_t (U − U_e)`` on one branch; the massless
   rows say ``F_o = G_o``, i.e. ``f_o = 0``; solving them for ``ΔU_o`` gives ``T`` and
   substituting in the mass rows gives ``K_c``. At every event the offsets are recomputed
   from the continuous ``u_m``, ``U_o`` and ``f_m`` there, so ``f_m`` and the displacements
   stay continuous (the massless DOFs' *velocities* may jump: they carry no momentum).
4. **Events** (terminal ``solve_ivp`` events): a hinge reaching the end of its branch
   (``theta_end``), and a hinge whose two branches differ in tangent (plastic, hardening, at
   a breakpoint) turning back: its rotation rate ``θ̇_h = Θ_h u̇_m`` crossing
   ``−ε_h d_h`` (``d_h`` the direction it moves, ``ε_h = 10⁻¹² ‖Θ_h‖ v_scale``: a band of
   width 2ε so that a restart at a reversal is never ambiguous; it delays a reversal by
   a rotation of order ε²/θ̈, negligible). A hinge whose tangent is the same both ways (on
   an elastic branch) watches both its ends instead; its reversals are non-terminal events
   that only record its peak rotation. At an event every hinge is committed with
   ``law.moved`` (the one that reached its breakpoint landed exactly on it, as the
   pushover does), then the directions are made consistent: a hinge assumed moving one way
   whose rate in the new configuration goes the other way (beyond the band) is given the
   other branch and the configuration rebuilt, until none disagrees (for one hinge changing
   branch, the signs of its rate in the two configurations agree — Sherman–Morrison — so
   this settles at once in practice).
5. **Damping** (``C`` on the mass DOFs, constant): ``"rayleigh-elastic"``, ``C = a₀ M + a₁
   K_c,el`` with ``K_c,el`` the condensed stiffness with every hinge at its elastic ``k0``
   (never the tangent: Zareian & Medina 2010, *Comput. Struct.* 88, keep the stiffness-
   proportional damping off the yielding hinges) and ``a₀, a₁`` from ``frame.damping`` (a
   :class:`~pounding.structure.damping.RayleighDamping`) at the elastic modes under gravity;
   ``"modal"``, ``frame.damping`` a :class:`~pounding.structure.damping.ModalDamping` on the
   same elastic modes.
6. **Ground** ``a_g``: linear between its samples (every ``dt``); after the last sample it
   returns linearly to zero over one step and stays there (as the shear-building reference,
   :mod:`pounding.integrate.reference_inputs`). Each record interval is integrated apart
   (``a_g`` is smooth on it).

Energy (since the gravity state, per unit of nothing: joules): with ``f`` the restoring
force, ``∫ f_m·du_m = Δ(½ Uᵀ K_el U + Σ R_h) + Δ(½ Uᵀ K_geo U − Gᵀ U) + Σ H_h`` where ``R_h``
is a hinge's recoverable energy (``law.recoverable``) and ``H_h = ∫ M_h dθ_h − ΔR_h`` its
hysteretic energy (``∫ M dθ`` summed exactly branch by branch). So
``E_input = E_kinetic + E_damping + E_strain + E_gravity + E_hysteretic`` and the residual
measures the integration.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.hysteresis.hinges import HingeLaw, HingeState
from pounding.structure.damping import ModalDamping, RayleighDamping
from pounding.structure.frame import Frame
from pounding.structure.frame_analysis import _mass_vector, frame_modes, gravity
from pounding.structure.frame_stiffness import (
    FrameDofs,
    configuration_stiffness,
    elastic_stiffness,
    gravity_load_vector,
)

__all__ = ["DAMPING_CHOICES", "FRAME_REFERENCE_RTOL", "FrameEnergy", "FrameReferenceResult",
           "simulate_frame_reference"]

FRAME_REFERENCE_RTOL: float = 1e-10
"""Default relative tolerance of ``solve_ivp``."""

DAMPING_CHOICES: tuple[str, ...] = ("rayleigh-elastic", "modal")
"""How the damping matrix is built (module docstring, item 5)."""

RATE_BAND: float = 1e-12
"""Half-width of the band a hinge's rotation rate must cross to count as a reversal,
relative to ``‖Θ_h‖ v_scale`` (module docstring, item 4)."""

MAX_EVENTS_PER_INTERVAL: int = 100_000
"""A bound on the events inside one record interval (a guard against an endless loop)."""


@dataclass(frozen=True)
class FrameEnergy:
    """The energy balance since the gravity state [J], at the output times, shape (nt,)."""

    input: NDArray[np.float64]  #: ``−∫ u̇_mᵀ M r a_g dt`` (relative input energy)
    kinetic: NDArray[np.float64]  #: ``½ u̇_mᵀ M u̇_m`` (relative velocities)
    strain: NDArray[np.float64]  #: elastic elements' strain energy + hinges' recoverable
    damping: NDArray[np.float64]  #: ``∫ u̇_mᵀ C u̇_m dt``
    hysteretic: NDArray[np.float64]  #: hinges' ``∫ M dθ`` minus their recoverable energy
    gravity: NDArray[np.float64]  #: ``Δ(½ Uᵀ K_geo U − Gᵀ U)``: gravity loads, P-Delta
    residual: NDArray[np.float64]  #: input − (kinetic + strain + damping + hysteretic + gravity)


@dataclass(frozen=True)
class FrameReferenceResult:
    """The reference time history of one frame (outputs at ``time = k dt``).

    Displacements and rotations are totals (gravity's included), relative to the ground;
    ``displacement``/``velocity`` of the mass DOFs are from the gravity state.
    """

    time: NDArray[np.float64]  #: output times [s], (nt,)
    ground: NDArray[np.float64]  #: ground acceleration at the output times [m/s²], (nt,)
    floor_displacements: NDArray[np.float64]  #: lateral floor displacements [m], (nt, nf)
    storey_drifts: NDArray[np.float64]  #: storey drifts [m] (first from the base), (nt, nf)
    hinge_rotations: NDArray[np.float64]  #: hinge rotations [rad], (nt, nh)
    hinge_moments: NDArray[np.float64]  #: hinge moments [N·m], (nt, nh)
    peak_hinge_rotation: NDArray[np.float64]  #: largest |rotation| of each hinge [rad] (exact)
    residual_drift: NDArray[np.float64]  #: storey drifts at the end of the window [m], (nf,)
    base_shear: NDArray[np.float64]  #: restoring base shear ``rᵀ f`` [N] (no damping), (nt,)
    energy: FrameEnergy  #: energy balance [J]
    mass_dofs: NDArray[np.int64]  #: the DOFs with mass (frame_stiffness numbering)
    displacement: NDArray[np.float64]  #: mass DOFs from the gravity state [m, rad], (nt, nm)
    velocity: NDArray[np.float64]  #: their velocities [m/s, rad/s], (nt, nm)
    dof_displacements: NDArray[np.float64]  #: every DOF, totals [m, rad], (nt, n)
    gravity_floor_displacements: NDArray[np.float64]  #: floors after gravity [m], (nf,)
    damping: str  #: the damping as built, one line
    rayleigh: tuple[float, float] | None  #: ``(a₀ [1/s], a₁ [s])`` for rayleigh-elastic
    damping_matrix: NDArray[np.float64]  #: ``C`` on the mass DOFs [N·s/m], (nm, nm)
    periods: NDArray[np.float64]  #: elastic periods under gravity [s]
    events: int  #: hinge events located and committed
    wall_time: float  #: seconds spent integrating


# ----------------------------------------------------------------------------- inputs
def _ground_knots(ag: ArrayLike, dt: float, duration: float | None
                  ) -> tuple[NDArray[np.float64], NDArray[np.float64], int]:
    """The record at its samples then zero (returning to zero over one step), the output
    times and their count."""
    a = np.asarray(ag, dtype=float)
    if a.ndim != 1 or a.size < 2:
        raise ValueError(f"ag: need a 1-D array of at least 2 ground accelerations [m/s²], "
                         f"got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        k = int(np.argmax(~np.isfinite(a)))
        raise ValueError(f"ag[{k}]: must be finite (got {a[k]!r})")
    step = float(dt)
    if not (math.isfinite(step) and step > 0.0):
        raise ValueError(f"dt: must be finite and > 0 [s] (got {dt!r})")
    t_end = (a.size - 1) * step if duration is None else float(duration)
    if not (math.isfinite(t_end) and t_end > 0.0):
        raise ValueError(f"duration: must be finite and > 0 [s] (got {duration!r})")
    nt = math.ceil(t_end / step - 1e-9) + 1
    if nt < 2:
        raise ValueError(f"duration: {t_end:g} s is shorter than one step ({step:g} s)")
    knots = np.zeros(max(a.size + 1, nt + 1))
    knots[: a.size] = a
    return knots, np.arange(nt, dtype=np.float64) * step, nt


def _damping(frame: Frame, choice: str, M: NDArray[np.float64], Kc_el: NDArray[np.float64]
             ) -> tuple[NDArray[np.float64], str, tuple[float, float] | None]:
    """``C``, its description and the Rayleigh coefficients (module docstring, item 5)."""
    if choice not in DAMPING_CHOICES:
        raise ValueError(f"damping: must be one of {', '.join(DAMPING_CHOICES)} "
                         f"(got {choice!r})")
    model = frame.damping
    Mm = np.diag(M)
    if choice == "rayleigh-elastic":
        if not isinstance(model, RayleighDamping):
            raise ValueError(f"damping: 'rayleigh-elastic' needs {frame.name}'s damping to be "
                             f"Rayleigh (it is {model.readable()}); use damping='modal'")
        a0, a1 = model.coefficients(Mm, Kc_el)
        C = a0 * Mm + a1 * Kc_el
        text = (f"rayleigh-elastic: C = a0 M + a1 K_c(hinges at k0), a0 = {a0:.6g} 1/s, "
                f"a1 = {a1:.6g} s ({model.readable()}, elastic modes under gravity)")
        return 0.5 * (C + C.T), text, (float(a0), float(a1))
    if not isinstance(model, ModalDamping):
        raise ValueError(f"damping: 'modal' needs {frame.name}'s damping to be modal (it is "
                         f"{model.readable()}); use damping='rayleigh-elastic'")
    C = model.matrix(Mm, Kc_el)
    return C, f"modal: {model.readable()}, elastic modes under gravity", None


# ----------------------------------------------------------------------------- configuration
@dataclass(frozen=True)
class _Configuration:
    """The frame linearised with every hinge on one branch (module docstring, item 3)."""

    tangents: NDArray[np.float64]  #: k_t of each hinge [N·m/rad]
    Kc: NDArray[np.float64]  #: condensed stiffness on the mass DOFs
    T: NDArray[np.float64]  #: massless DOFs' displacement per mass DOFs' (n_o, n_m)
    Theta: NDArray[np.float64]  #: hinge rotations per mass DOFs' displacement (nh, n_m)


def _hinge_incidence(dofs: FrameDofs) -> NDArray[np.float64]:
    """``B`` (nh, n): ``θ = B U`` (the node's rotation minus the member end's)."""
    B = np.zeros((dofs.hinge.size, dofs.n))
    for h in range(dofs.hinge.size):
        if dofs.hinge_node[h] >= 0:
            B[h, dofs.hinge_node[h]] = 1.0
        B[h, dofs.hinge[h]] -= 1.0
    return B


def _configuration(base: NDArray[np.float64], dofs: FrameDofs, B: NDArray[np.float64],
                   keep: NDArray[np.int64], other: NDArray[np.int64],
                   tangents: NDArray[np.float64], name: str, t: float) -> _Configuration:
    import scipy.linalg

    K = configuration_stiffness(base, dofs, tangents)
    live_rows = np.any(K[other] != 0.0, axis=1)  # dead massless DOFs stay where they are
    live = other[live_rows]
    T = np.zeros((other.size, keep.size))
    Kc = K[np.ix_(keep, keep)].copy()
    if live.size:
        Kom = K[np.ix_(live, keep)]
        try:
            X = -scipy.linalg.solve(K[np.ix_(live, live)], Kom, check_finite=False)
        except (np.linalg.LinAlgError, ValueError):
            X = np.full_like(Kom, np.nan)
        if not np.all(np.isfinite(X)):
            raise ValueError(f"{name}: at t = {t:.6g} s the DOFs without mass form a "
                             "mechanism on their own (their stiffness is singular): give "
                             "them mass or stiffer hinges")
        T[live_rows] = X
        Kc = Kc + K[np.ix_(keep, live)] @ X
    Theta = B[:, keep] + B[:, other] @ T
    return _Configuration(tangents.copy(), 0.5 * (Kc + Kc.T), T, Theta)


# ----------------------------------------------------------------------------- events
@dataclass(frozen=True)
class _BranchEnd:
    """``d (θ_h − θ_end)``, rising through zero where hinge ``h`` reaches the end of the
    branch it follows in direction ``d``."""

    h: int
    d: int
    end: float
    theta_e: float
    row: NDArray[np.float64]
    u_e: NDArray[np.float64]
    terminal: ClassVar[bool] = True
    direction: ClassVar[float] = 1.0

    def __call__(self, t: float, y: NDArray[np.float64]) -> float:
        return self.d * (self.theta_e + float(self.row @ (y[: self.u_e.size] - self.u_e))
                         - self.end)


@dataclass(frozen=True)
class _Reversal:
    """``d θ̇_h + ε_h``, falling through zero where a hinge moving in direction ``d`` turns
    back (past the band ε: module docstring, item 4)."""

    h: int
    d: int
    eps: float
    row: NDArray[np.float64]
    terminal: ClassVar[bool] = True
    direction: ClassVar[float] = -1.0

    def __call__(self, t: float, y: NDArray[np.float64]) -> float:
        n = self.row.size
        return self.d * float(self.row @ y[n: 2 * n]) + self.eps


@dataclass(frozen=True)
class _RateZero:
    """``θ̇_h`` crossing zero: an elastic hinge's extreme rotation (non-terminal; for its
    peak)."""

    h: int
    row: NDArray[np.float64]
    terminal: ClassVar[bool] = False
    direction: ClassVar[float] = 0.0

    def __call__(self, t: float, y: NDArray[np.float64]) -> float:
        n = self.row.size
        return float(self.row @ y[n: 2 * n])


_AnyEvent = _BranchEnd | _Reversal | _RateZero


# ----------------------------------------------------------------------------- the motion
class _Motion:
    """The frame between two events: its constant matrices, the hinge states committed at
    the last event, the configuration and the state there (``u_e, f_e, U_o,e, θ_e``) that
    the affine maps of the module docstring (item 3) start from."""

    def __init__(self, frame: Frame, dofs: FrameDofs, base: NDArray[np.float64],
                 U_g: NDArray[np.float64], hinges: list[HingeState], keep: NDArray[np.int64],
                 other: NDArray[np.int64], v_scale: float) -> None:
        self.frame, self.dofs, self.base, self.U_g = frame, dofs, base, U_g
        self.keep, self.other, self.v_scale = keep, other, v_scale
        self.laws: list[HingeLaw] = [h.law for h in frame.hinges]
        self.nh, self.nm = len(self.laws), keep.size
        self.B = _hinge_incidence(dofs)
        self.states = list(hinges)
        # a hinge loaded by gravity is taken to go on the way gravity moved it until it turns
        self.directions = np.array([1 if s.moment >= 0.0 else -1 for s in hinges],
                                   dtype=np.int64)
        self.u_e = np.zeros(self.nm)
        self.f_e = np.zeros(self.nm)
        self.Uo_e = U_g[other].copy()
        self.theta_e = np.array([s.theta for s in hinges])
        self.moment_e = np.array([s.moment for s in hinges])
        self.work = np.zeros(self.nh)  # each hinge's ∫ M dθ since gravity, to the last event
        self.peak = np.abs(self.theta_e)
        self.events = 0
        self._cache: dict[bytes, _Configuration] = {}
        self.cfg = self._configuration(self.directions, 0.0)

    # -- the configuration
    def _configuration(self, directions: NDArray[np.int64], t: float) -> _Configuration:
        tangents = np.array([law.branch(s, int(d)).k_t
                             for law, s, d in zip(self.laws, self.states, directions)])
        key = tangents.tobytes()
        if key not in self._cache:
            self._cache[key] = _configuration(self.base, self.dofs, self.B, self.keep,
                                              self.other, tangents, self.frame.name, t)
        return self._cache[key]

    def two_way(self, h: int) -> bool:
        """True if the hinge's tangent depends on the way it moves (a reversal matters)."""
        law, s = self.laws[h], self.states[h]
        return law.branch(s, 1).k_t != law.branch(s, -1).k_t

    def band(self, cfg: _Configuration) -> NDArray[np.float64]:
        """ε of each hinge [rad/s] (module docstring, item 4)."""
        return RATE_BAND * np.linalg.norm(cfg.Theta, axis=1) * self.v_scale

    # -- the state as a function of the mass DOFs' (affine in u within the configuration)
    def restoring(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        """``f_m`` [N, N·m]."""
        return self.f_e + self.cfg.Kc @ (u - self.u_e)

    def displacements(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        """Every DOF's total displacement ``U`` [m, rad]."""
        U = self.U_g.copy()
        U[self.keep] += u
        U[self.other] = self.Uo_e + self.cfg.T @ (u - self.u_e)
        return U

    def rotations(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        """Hinge rotations ``θ`` [rad]."""
        return self.theta_e + self.cfg.Theta @ (u - self.u_e)

    def work_done(self, theta: NDArray[np.float64]) -> NDArray[np.float64]:
        """Each hinge's ``∫ M dθ`` since gravity [J], exact along its branch."""
        dth = theta - self.theta_e
        return self.work + self.moment_e * dth + 0.5 * self.cfg.tangents * dth * dth

    # -- events
    def watch(self) -> tuple[list[_AnyEvent], list[bool]]:
        """The events of this configuration, and whether each is an end of branch."""
        cfg, eps = self.cfg, self.band(self.cfg)
        events: list[_AnyEvent] = []
        for h in range(self.nh):
            row = cfg.Theta[h]
            if not np.any(row):
                continue  # the hinge cannot move in this configuration
            law, s = self.laws[h], self.states[h]
            ways = [int(self.directions[h])] if self.two_way(h) else [1, -1]
            for d in ways:
                end = law.branch(s, d).theta_end
                if math.isfinite(end):
                    events.append(_BranchEnd(h, d, end, float(self.theta_e[h]), row, self.u_e))
            if len(ways) == 1:
                events.append(_Reversal(h, ways[0], float(eps[h]), row))
            else:
                events.append(_RateZero(h, row))
        return events, [isinstance(ev, _BranchEnd) for ev in events]

    def note_peaks(self, events: list[_AnyEvent], y_events: list[NDArray[np.float64]]
                   ) -> None:
        """Peak rotations of the elastic hinges at their extremes (non-terminal events)."""
        for ev, ys in zip(events, y_events):
            if isinstance(ev, _RateZero) and len(ys):
                th = self.theta_e[ev.h] + (ys[:, : self.nm] - self.u_e) @ self.cfg.Theta[ev.h]
                self.peak[ev.h] = max(self.peak[ev.h], float(np.max(np.abs(th))))

    def commit(self, t: float, y: NDArray[np.float64], events: list[_AnyEvent],
               fired: list[bool]) -> None:
        """Commit at the event ``(t, y)``: the hinges that reached a breakpoint land on it,
        those that turned back change direction, every hinge state is committed, the
        offsets restart from here, and the directions are made consistent."""
        nm = self.nm
        u, v = y[:nm], y[nm: 2 * nm]
        theta = self.rotations(u)
        land: dict[int, float] = {}
        for ev, hit in zip(events, fired):
            if isinstance(ev, _BranchEnd) and (
                    hit or ev(t, y) >= -1e-12 * max(abs(ev.end), self.laws[ev.h].theta_y)):
                land[ev.h] = ev.end  # (and any other at this instant)
                self.directions[ev.h] = ev.d
            elif isinstance(ev, _Reversal) and (hit or ev(t, y) <= 0.5 * ev.eps):
                self.directions[ev.h] = -ev.d
            else:
                continue
            self.events += 1
        self.f_e = self.restoring(u)
        self.Uo_e = self.Uo_e + self.cfg.T @ (u - self.u_e)
        theta_new = np.array([land.get(h, float(theta[h])) for h in range(self.nh)])
        self.work = self.work_done(theta_new)
        self.states = [law.moved(s, float(th))
                       for law, s, th in zip(self.laws, self.states, theta_new)]
        self.peak = np.maximum(self.peak, np.abs(theta_new))
        self.u_e = u.copy()
        self.theta_e = np.array([s.theta for s in self.states])
        self.moment_e = np.array([s.moment for s in self.states])
        self._settle(v, t)

    def _settle(self, v: NDArray[np.float64], t: float) -> None:
        """Give every two-way hinge whose rate (in the configuration being built) goes
        against its branch the other branch, until none does."""
        for _ in range(2 * self.nh + 2):
            cfg = self._configuration(self.directions, t)
            rate, eps = cfg.Theta @ v, self.band(cfg)
            against = [h for h in range(self.nh)
                       if self.directions[h] * rate[h] < -eps[h] and self.two_way(h)]
            if not against:
                self.cfg = cfg
                return
            self.directions[against] *= -1
        raise RuntimeError(f"{self.frame.name}: at t = {t:.6g} s no hinge configuration "
                           "agrees with the hinges' rotation rates")  # pragma: no cover


# ----------------------------------------------------------------------------- the run
def simulate_frame_reference(frame: Frame, ag: ArrayLike, dt: float, *,
                             duration: float | None = None,
                             rtol: float = FRAME_REFERENCE_RTOL,
                             damping: str = "rayleigh-elastic",
                             method: str = "DOP853") -> FrameReferenceResult:
    """Time history of one nonlinear frame under a horizontal ground acceleration.

    Parameters
    ----------
    frame : Frame
        The frame (masses lumped at its nodes; gravity loads applied first).
    ag : array_like, shape (N,)
        Ground acceleration [m/s²] at ``0, dt, 2 dt, …``, linear between samples.
    dt : float
        Sample step of ``ag`` and output step [s].
    duration : float, optional
        Time simulated [s] (default the record's, ``(N − 1) dt``; after the record the ground
        is at rest).
    rtol : float
        Relative tolerance of ``solve_ivp`` (absolute ones scaled from the record).
    damping : {"rayleigh-elastic", "modal"}
        How ``C`` is built from ``frame.damping`` (module docstring, item 5).
    method : {"DOP853", "Radau"}
        ``solve_ivp`` method.

    Returns
    -------
    FrameReferenceResult

    Raises
    ------
    ValueError
        Bad input (named), a frame without masses or that cannot carry its gravity loads,
        a damping choice that does not match ``frame.damping``.
    """
    from scipy.integrate import solve_ivp

    knots, t_grid, nt = _ground_knots(ag, dt, duration)
    step = float(dt)
    tol = float(rtol)
    if not (math.isfinite(tol) and 0.0 < tol < 1e-2):
        raise ValueError(f"rtol: must be in (0, 0.01) (got {rtol!r})")
    if method not in ("DOP853", "Radau"):
        raise ValueError(f"method: must be DOP853 or Radau (got {method!r})")
    if frame.levels.size == 0:
        raise ValueError(f"{frame.name}: no floor above the base")

    # gravity, masses, damping
    g_state = gravity(frame)
    dofs = g_state.dofs
    K_el = elastic_stiffness(frame, dofs)
    K_geo = g_state.base - K_el
    G = gravity_load_vector(frame, dofs)
    U_g = g_state.U.copy()
    mass = _mass_vector(frame, dofs)
    keep = np.flatnonzero(mass > 0.0).astype(np.int64)
    other = np.flatnonzero(mass == 0.0).astype(np.int64)
    if keep.size == 0:
        raise ValueError(f"{frame.name}: masses: none is given; a time history needs mass")
    M = mass[keep]
    horizontal = np.zeros(dofs.n)
    horizontal[dofs.node[:, 0][dofs.node[:, 0] >= 0]] = 1.0
    r_m = horizontal[keep]
    if not np.any(r_m):
        raise ValueError(f"{frame.name}: masses: no horizontal mass, so the ground motion "
                         "does not excite the frame")
    periods, _, _, Kc_el, _ = frame_modes(frame, g_state)
    C, damping_text, rayleigh = _damping(frame, damping, M, Kc_el)
    Mr = M * r_m
    nm = keep.size

    # scales of the tolerances and of the reversal band
    v_ground = np.concatenate([[0.0], np.cumsum(0.5 * (knots[1:] + knots[:-1]) * step)])
    v_scale = max(float(np.max(np.abs(v_ground))), 1e-3)
    u_scale = max(v_scale * float(periods[0]) / (2 * math.pi), 1e-6)
    e_scale = max(float(np.sum(Mr)) * v_scale ** 2, 1.0)
    atol = np.concatenate([np.full(nm, 1e-2 * tol * u_scale), np.full(nm, 1e-2 * tol * v_scale),
                           np.full(2, 1e-2 * tol * e_scale)])

    motion = _Motion(frame, dofs, g_state.base, U_g, g_state.hinges, keep, other, v_scale)
    laws, nh = motion.laws, motion.nh
    recoverable_g = np.array([law.recoverable(s) for law, s in zip(laws, g_state.hinges)])
    out = _Outputs(nt, nm, dofs.n, nh)

    def record(k: int, y: NDArray[np.float64]) -> None:
        u = y[:nm]
        out.u[k], out.v[k] = u, y[nm: 2 * nm]
        out.e_in[k], out.e_damp[k] = y[2 * nm], y[2 * nm + 1]
        out.f[k] = motion.restoring(u)
        out.U[k] = motion.displacements(u)
        theta = motion.rotations(u)
        now = [law.moved(s, float(th)) for law, s, th in zip(laws, motion.states, theta)]
        out.theta[k] = [s.theta for s in now]
        out.moment[k] = [s.moment for s in now]
        recoverable = sum(law.recoverable(s) for law, s in zip(laws, now)) \
            - float(np.sum(recoverable_g))
        out.recoverable[k] = recoverable
        out.hysteretic[k] = float(np.sum(motion.work_done(theta))) - recoverable
        motion.peak = np.maximum(motion.peak, np.abs(theta))

    y = np.zeros(2 * nm + 2)
    record(0, y)
    start = time.perf_counter()
    for i in range(nt - 1):
        t0, t1 = float(t_grid[i]), float(t_grid[i + 1])
        a0, slope = float(knots[i]), float((knots[i + 1] - knots[i]) / step)

        def rhs(t: float, y: NDArray[np.float64], a0: float = a0, slope: float = slope,
                t0: float = t0) -> NDArray[np.float64]:
            """``[u̇, ü, Ė_input, Ė_damping]`` in the motion's current configuration."""
            v = y[nm: 2 * nm]
            a_g = a0 + slope * (t - t0)
            cv = C @ v
            acc = (-motion.restoring(y[:nm]) - cv) / M - r_m * a_g
            return np.concatenate([v, acc, [-(v @ Mr) * a_g, v @ cv]])

        t = t0
        for _ in range(MAX_EVENTS_PER_INTERVAL):
            events, _ends = motion.watch()
            sol = solve_ivp(rhs, (t, t1), y, method=method, rtol=tol, atol=atol,
                            events=events or None)
            motion.note_peaks(events, sol.y_events or [])
            y, t = sol.y[:, -1].copy(), float(sol.t[-1])
            if sol.status != 1:
                break
            motion.commit(t, y, events, [len(te) > 0 and ev.terminal
                                         for ev, te in zip(events, sol.t_events)])
            if t >= t1:
                break
        else:  # pragma: no cover
            raise RuntimeError(f"{frame.name}: more than {MAX_EVENTS_PER_INTERVAL} events "
                               f"between {t0:g} and {t1:g} s")
        record(i + 1, y)
    wall = time.perf_counter() - start

    floors = out.U @ dofs.floor.T
    drifts = np.diff(np.concatenate([np.zeros((nt, 1)), floors], axis=1), axis=1)

    def quadratic(K: NDArray[np.float64]) -> NDArray[np.float64]:
        return 0.5 * (np.einsum("ki,ij,kj->k", out.U, K, out.U) - U_g @ K @ U_g)

    strain = quadratic(K_el) + out.recoverable
    grav = quadratic(K_geo) - (out.U - U_g) @ G
    kinetic = 0.5 * np.einsum("ki,i,ki->k", out.v, M, out.v)
    residual = out.e_in - (kinetic + strain + out.e_damp + out.hysteretic + grav)
    energy = FrameEnergy(input=out.e_in, kinetic=kinetic, strain=strain, damping=out.e_damp,
                         hysteretic=out.hysteretic, gravity=grav, residual=residual)
    return FrameReferenceResult(
        time=t_grid, ground=knots[:nt].copy(), floor_displacements=floors,
        storey_drifts=drifts, hinge_rotations=out.theta, hinge_moments=out.moment,
        peak_hinge_rotation=motion.peak.copy(), residual_drift=drifts[-1].copy(),
        base_shear=out.f @ r_m, energy=energy, mass_dofs=keep, displacement=out.u,
        velocity=out.v, dof_displacements=out.U,
        gravity_floor_displacements=dofs.floor @ U_g, damping=damping_text, rayleigh=rayleigh,
        damping_matrix=C, periods=periods, events=motion.events, wall_time=wall)


class _Outputs:
    """The output arrays, one row per output time."""

    def __init__(self, nt: int, nm: int, n: int, nh: int) -> None:
        self.u, self.v, self.f = np.zeros((nt, nm)), np.zeros((nt, nm)), np.zeros((nt, nm))
        self.e_in, self.e_damp = np.zeros(nt), np.zeros(nt)
        self.U = np.zeros((nt, n))
        self.theta, self.moment = np.zeros((nt, nh)), np.zeros((nt, nh))
        self.recoverable, self.hysteretic = np.zeros(nt), np.zeros(nt)

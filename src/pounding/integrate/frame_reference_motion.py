"""The frame between two events, for the SciPy frame reference
(:mod:`pounding.integrate.frame_reference`, whose module docstring states the model): a hinge
configuration and its condensation, the ``solve_ivp`` events of a configuration, and the
commit at an event.

Within a configuration that started at the event ``e`` everything is affine in the mass
DOFs' displacements ``u`` (from the gravity state)::

    U_o = U_o,e + T (u − u_e),   f_m = f_m,e + K_c (u − u_e),   θ = θ_e + Θ (u − u_e)

with ``T = −K_oo⁻¹ K_om``, ``K_c = K_mm + K_mo T`` and ``Θ = B_m + B_o T`` (``θ = B U``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from pounding.hysteresis.hinges import HingeLaw, HingeState
from pounding.structure.frame import Frame
from pounding.structure.frame_stiffness import FrameDofs, configuration_stiffness

__all__ = ["RATE_BAND", "AnyEvent", "BranchEnd", "ReferenceConfiguration", "Motion", "RateZero",
           "Reversal", "configuration", "hinge_incidence"]

RATE_BAND: float = 1e-12
"""Half-width of the band a hinge's rotation rate must cross to count as a reversal,
relative to ``‖Θ_h‖ v_scale`` (module docstring of the frame reference, item 4)."""


# ----------------------------------------------------------------------------- configuration
@dataclass(frozen=True)
class ReferenceConfiguration:
    """The frame linearised with every hinge on one branch: ``K_c``, ``T``, ``Θ``."""

    tangents: NDArray[np.float64]  #: k_t of each hinge [N·m/rad]
    Kc: NDArray[np.float64]  #: condensed stiffness on the mass DOFs
    T: NDArray[np.float64]  #: massless DOFs' displacement per mass DOFs' (n_o, n_m)
    Theta: NDArray[np.float64]  #: hinge rotations per mass DOFs' displacement (nh, n_m)


def hinge_incidence(dofs: FrameDofs) -> NDArray[np.float64]:
    """``B`` (nh, n): ``θ = B U`` (the node's rotation minus the member end's)."""
    B = np.zeros((dofs.hinge.size, dofs.n))
    for h in range(dofs.hinge.size):
        if dofs.hinge_node[h] >= 0:
            B[h, dofs.hinge_node[h]] = 1.0
        B[h, dofs.hinge[h]] -= 1.0
    return B


def configuration(base: NDArray[np.float64], dofs: FrameDofs, B: NDArray[np.float64],
                  keep: NDArray[np.int64], other: NDArray[np.int64],
                  tangents: NDArray[np.float64], name: str, t: float) -> ReferenceConfiguration:
    """The configuration whose hinges have the tangents ``tangents`` (``name``, ``t``: for
    the message if the DOFs without mass are a mechanism by themselves)."""
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
    return ReferenceConfiguration(tangents.copy(), 0.5 * (Kc + Kc.T), T, Theta)


# ----------------------------------------------------------------------------- events
@dataclass(frozen=True)
class BranchEnd:
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
class Reversal:
    """``d θ̇_h + ε_h``, falling through zero where a hinge moving in direction ``d`` turns
    back (past the band ε: frame_reference module docstring, item 4)."""

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
class RateZero:
    """``θ̇_h`` crossing zero: an elastic hinge's extreme rotation (non-terminal; for its
    peak)."""

    h: int
    row: NDArray[np.float64]
    terminal: ClassVar[bool] = False
    direction: ClassVar[float] = 0.0

    def __call__(self, t: float, y: NDArray[np.float64]) -> float:
        n = self.row.size
        return float(self.row @ y[n: 2 * n])


AnyEvent = BranchEnd | Reversal | RateZero


# ----------------------------------------------------------------------------- the motion
class Motion:
    """The frame between two events: its constant matrices, the hinge states committed at
    the last event, the configuration, and the state there (``u_e, f_e, U_o,e, θ_e``) that
    the affine maps of the module docstring start from."""

    def __init__(self, frame: Frame, dofs: FrameDofs, base: NDArray[np.float64],
                 U_g: NDArray[np.float64], hinges: list[HingeState], keep: NDArray[np.int64],
                 other: NDArray[np.int64], v_scale: float) -> None:
        self.frame, self.dofs, self.base, self.U_g = frame, dofs, base, U_g
        self.keep, self.other, self.v_scale = keep, other, v_scale
        self.laws: list[HingeLaw] = [h.law for h in frame.hinges]
        self.nh, self.nm = len(self.laws), keep.size
        self.B = hinge_incidence(dofs)
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
        self._cache: dict[bytes, ReferenceConfiguration] = {}
        self.cfg = self._configuration(self.directions, 0.0)

    # -- the configuration
    def _configuration(self, directions: NDArray[np.int64], t: float) -> ReferenceConfiguration:
        tangents = np.array([law.branch(s, int(d)).k_t for law, s, d
                             in zip(self.laws, self.states, directions, strict=True)])
        key = tangents.tobytes()
        if key not in self._cache:
            self._cache[key] = configuration(self.base, self.dofs, self.B, self.keep,
                                             self.other, tangents, self.frame.name, t)
        return self._cache[key]

    def two_way(self, h: int) -> bool:
        """True if the hinge's tangent depends on the way it moves (a reversal matters)."""
        law, s = self.laws[h], self.states[h]
        return law.branch(s, 1).k_t != law.branch(s, -1).k_t

    def band(self, cfg: ReferenceConfiguration) -> NDArray[np.float64]:
        """ε of each hinge [rad/s] (frame_reference module docstring, item 4)."""
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
    def watch(self) -> list[AnyEvent]:
        """The ``solve_ivp`` events of this configuration."""
        cfg, eps = self.cfg, self.band(self.cfg)
        events: list[AnyEvent] = []
        for h in range(self.nh):
            row = cfg.Theta[h]
            if not np.any(row):
                continue  # the hinge cannot move in this configuration
            law, s = self.laws[h], self.states[h]
            ways = [int(self.directions[h])] if self.two_way(h) else [1, -1]
            for d in ways:
                end = law.branch(s, d).theta_end
                if math.isfinite(end):
                    events.append(BranchEnd(h, d, end, float(self.theta_e[h]), row, self.u_e))
            if len(ways) == 1:
                events.append(Reversal(h, ways[0], float(eps[h]), row))
            else:
                events.append(RateZero(h, row))
        return events

    def note_peaks(self, events: list[AnyEvent], y_events: list[NDArray[np.float64]]
                   ) -> None:
        """Peak rotations of the elastic hinges at their extremes (non-terminal events)."""
        for ev, ys in zip(events, y_events, strict=True):
            if isinstance(ev, RateZero) and len(ys):
                th = self.theta_e[ev.h] + (ys[:, : self.nm] - self.u_e) @ self.cfg.Theta[ev.h]
                self.peak[ev.h] = max(self.peak[ev.h], float(np.max(np.abs(th))))

    def commit(self, t: float, y: NDArray[np.float64], events: list[AnyEvent],
               fired: list[bool]) -> None:
        """Commit at the event ``(t, y)``: the hinges that reached a breakpoint land on it,
        those that turned back change direction, every hinge state is committed, the
        offsets restart from here, and the directions are made consistent."""
        nm = self.nm
        u, v = y[:nm], y[nm: 2 * nm]
        theta = self.rotations(u)
        land: dict[int, float] = {}
        for ev, hit in zip(events, fired, strict=True):
            if isinstance(ev, BranchEnd) and (
                    hit or ev(t, y) >= -1e-12 * max(abs(ev.end), self.laws[ev.h].theta_y)):
                land[ev.h] = ev.end  # (and any other at this instant)
                self.directions[ev.h] = ev.d
            elif isinstance(ev, Reversal) and (hit or ev(t, y) <= 0.5 * ev.eps):
                self.directions[ev.h] = -ev.d
            else:
                continue
            self.events += 1
        self.f_e = self.restoring(u)
        self.Uo_e = self.Uo_e + self.cfg.T @ (u - self.u_e)
        theta_new = np.array([land.get(h, float(theta[h])) for h in range(self.nh)])
        self.work = self.work_done(theta_new)
        moved = [law.moved(s, float(th))
                 for law, s, th in zip(self.laws, self.states, theta_new, strict=True)]
        for h, (law, s, after) in enumerate(zip(self.laws, self.states, moved, strict=True)):
            d = 1 if after.theta > s.theta else -1
            br = law.branch(s, d)
            if abs(after.moment - (s.moment + br.k_t * (after.theta - s.theta))) > \
                    1e-9 * law.m_y:
                raise NotImplementedError(
                    f"{self.frame.name}: hinge {h}'s moment drops at t = {t:.6g} s (a "
                    f"fracture or complete deterioration, {law.label}); the SciPy reference "
                    "does not redistribute a moment that jumps (the compiled kernel and the "
                    "pushover do)")
        self.states = moved
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

"""A yielding frame in motion: each configuration of its hinges, condensed onto its floors.

Every hinge law is piecewise linear (:mod:`pounding.hysteresis.hinges`), so in a
*configuration* — each hinge on one straight branch of tangent ``k_t`` — the frame is
linear: its stiffness is ``K_t = configuration_stiffness(base, dofs, k_t)`` (``base`` the
elastic elements plus the geometric stiffness of the gravity loads) and the moment of hinge
h is ``M_h = k_t θ_h + q_h`` with ``q_h = M_h* − k_t θ_h*`` from the point ``(θ_h*, M_h*)``
where it was last committed. The DOFs with mass — the floors' lateral motion and, where
the frame has them, other masses (a node's own lateral or vertical motion, a joint's
rotation) — are here called its *floors* ``u`` for short (the floors come first); every
other DOF ``s`` (vertical displacements, joint and member-end rotations without mass) is
massless and in static equilibrium with them:

    K_ss U_s + K_sm u + (B q)_s = G_s   ⇒   U_s = S u + s0,
    S = −K_ss⁻¹ K_sm,   s0 = K_ss⁻¹ (G_s − (B q)_s),

with ``B`` the hinges' incidence (``θ_h = U_node − U_end``, ``B q`` their moments' nodal
loads) and ``G`` the gravity loads, held constant. The force the frame's floors exert back
(its restoring force) is then linear in ``u``:

    R = (K_t U + B q − G)_m = K_c u + f0,   K_c = K_mm + K_ms S,   f0 = K_ms s0 + (B q)_m − G_m,

net of the gravity loads, so the frame standing in its gravity state is at rest; and every
hinge rotation is ``θ = A u + a0`` with ``A = B_sᵀ S``, ``a0 = B_sᵀ s0`` (no hinge rotation is
a floor's DOF) — taken as ``a0 = θ* − A u*``, anchored where the hinges were committed (the
same up to rounding, but a commit at the same instant then moves no hinge at all). This is
the static condensation of Chopra, *Dynamics of Structures*, 4th ed., §9.3, carried out in
the configuration and with the constant part kept; what the tangents alone fix (``S``,
``K_c``, ``A``, the factorised ``K_ss``) is :mod:`pounding.structure.frame_condensation`'s.

Between events the frame's motion is linear; an *event* is a hinge reaching the end of its
branch in the direction it moves (yield, capping, the elastic branch's other bound) or a
hinge on a branch whose tangent depends on the direction (a plastic plateau, say)
reversing. At each event the hinges are committed where they stand (``law.moved``) and the
next configuration is chosen as the event-to-event pushover chooses it
(:func:`pounding.structure.frame_analysis._advance`): each hinge on the branch of the
direction it moves, ``sign(A_h u̇)`` — or, where that rate is zero (at a reversal), the sign
of its rate's rate ``A_h ü`` — checked in the configuration that choice gives and
flipped until the two agree. A joint whose every connection is a hinge of zero tangent has
no stiffness at all: it stays where it is (as in the pushover).

Floor displacements here are measured from the gravity state (``u = 0``: the frame at rest
under its gravity loads), as a run measures them; :class:`FrameMotion` is the state of one
frame through one run (NumPy; the time stepper that moves the floors is
:mod:`pounding.integrate`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from pounding.hysteresis.hinges import Branch, HingeLaw, HingeState
from pounding.structure.frame import Frame
from pounding.structure.frame_analysis import FrameState, gravity
from pounding.structure.frame_condensation import Condensation
from pounding.structure.frame_stiffness import gravity_load_vector, hinge_incidence

__all__ = ["Configuration", "FrameCollapse", "FrameMotion"]

JUMP_TOL: float = 1e-9
"""A hinge's moment jumps where its law's moment leaves the straight branch it was on by more
than this fraction of its yield moment (as the pushover judges it)."""


def _moved(law: HingeLaw, state: HingeState, theta: float,
           first: Branch | None = None) -> tuple[HingeState, bool]:
    """``law.moved(state, theta)``, walked branch by branch (contract 5), and whether the
    moment jumped anywhere on the way (at a breakpoint, or at the start of a reversal).
    ``first``: the branch from ``state`` in the direction of the move, if at hand."""
    if theta == state.theta:
        return state, False
    direction = 1 if theta > state.theta else -1
    tol = JUMP_TOL * law.m_y
    jumped = False
    current = state
    for _ in range(10_000):
        br = first if first is not None else law.branch(current, direction)
        first = None
        end = br.theta_end
        last = (direction > 0 and end >= theta) or (direction < 0 and end <= theta)
        to = theta if last else end
        nxt = law.moved(current, to)
        jumped = jumped or abs(nxt.moment - (current.moment + br.k_t * (to - current.theta))) > tol
        if last:
            return nxt, jumped
        current = nxt
    raise RuntimeError(f"{law.label}: more than 10000 branches in one move")  # pragma: no cover

Vector = NDArray[np.float64]


class FrameCollapse(ValueError):
    """A yielding frame lost its strength in a run — its hinges' moments cascading to zero
    (modified-IMK fractures, complete deterioration) with no equilibrium left, or a storey
    swaying past its own height — and the run stopped there: what would follow is not a
    frame's motion that this model describes. Studies count such a run as a collapse."""

    exit_status = 1
    """The command line ends with this status: a result (the frame collapsed), not bad
    input (2)."""


@dataclass(frozen=True)
class Configuration:
    """One configuration of a frame's hinges, condensed onto its floors (module docstring;
    displacements ``u`` of the floors from the gravity state, floors lowest first)."""

    directions: NDArray[np.int64]  #: the direction each hinge's branch holds for (0: both)
    tangents: Vector  #: each hinge's tangent k_t [N·m/rad]
    q: Vector  #: each hinge's moment offset, ``M = k_t θ + q`` [N·m]
    K: Vector  #: condensed tangent stiffness of the floors K_c [N/m] (n_f, n_f)
    f0: Vector  #: constant part of the floors' restoring force ``R = K u + f0`` [N] (n_f,)
    A: Vector  #: hinge rotations per floor displacement [rad/m] (n_h, n_f)
    a0: Vector  #: their constant part [rad] (n_h,): ``θ = A u + a0``
    lower: Vector  #: where each hinge's branch ends below [rad] (−inf: it does not)
    upper: Vector  #: and above [rad] (+inf: it does not)
    P: Vector  #: every DOF of the frame per floor displacement (n, n_f)
    p0: Vector  #: and its constant part (n,): ``U = P u + p0`` (total, not from gravity)
    #: the hinge rotations' constant part in the configuration's own equilibrium, ``B_sᵀ
    #: s0`` [rad] (``a0`` anchors them where they were committed instead; the two differ
    #: by rounding, or after a hinge's moment jumped)
    a0_equilibrium: Vector


class FrameMotion:
    """The state of a yielding frame through one run: its hinges' committed states and
    work, its displacements at the last commit, and its current :class:`Configuration`.

    Parameters
    ----------
    frame : Frame
        A frame with lumped masses.
    state : FrameState, optional
        Its gravity state (:func:`pounding.structure.frame_analysis.gravity`), computed if
        not given; it is not modified.
    kept : array_like of int, optional
        The frame's DOFs with mass, in the order of the run's (the "floors" ``u`` of this
        class: the floors' lateral DOFs first, then any other DOF with mass); default the
        floors' lateral DOFs (rigid floors, masses on them only).
    """

    def __init__(self, frame: Frame, state: FrameState | None = None,
                 kept: NDArray[np.int64] | None = None) -> None:
        state = state if state is not None else gravity(frame)
        dofs = state.dofs
        self.frame = frame
        self.dofs = dofs
        self.laws = [h.law for h in frame.hinges]
        self.hinges: list[HingeState] = list(state.hinges)
        self.directions = np.zeros(len(self.laws), dtype=np.int64)
        self.base = state.base
        self.axial = state.axial  #: the columns' gravity axial forces [N] (tension +)
        self.G = gravity_load_vector(frame, dofs)
        self.kept = np.asarray(dofs.floor_dof if kept is None else kept, dtype=np.int64)
        self.U = state.U.copy()
        self.U0 = self.U.copy()  #: the displacements at the start [m, rad]
        self.u_gravity = self.U[self.kept].copy()
        #: the floors' displacements (from the gravity state) where the hinges were last
        #: committed: each hinge's rotation is anchored there (:meth:`condensed`)
        self.u_commit = np.zeros(self.kept.size)
        self.work = np.zeros(len(self.laws))  #: ∫ M dθ of every hinge since the start [J]
        self.recoverable0 = np.array([law.recoverable(h) for law, h in
                                      zip(self.laws, self.hinges)])
        self.node = np.asarray(dofs.hinge_node, dtype=np.int64)
        self.end = np.asarray(dofs.hinge, dtype=np.int64)
        self.config: Configuration | None = None
        #: a hinge's moment jumped at the last commit (a fracture, complete deterioration):
        #: the frame must be brought to the equilibrium of its next configuration
        #: (:meth:`redistribute`)
        self.jumped = False
        self._condensation = Condensation(self.base, dofs, frame.name, self.kept)
        self._incidence = hinge_incidence(dofs)  # (B q: the nodal loads of moments q)
        # the committed rotations and moments; a hinge on a two-way branch (contract 7 of
        # the hinge laws) is committed here only, its law's state left behind at the last
        # point the law was asked about (``_behind``) until it leaves that branch
        self._theta = np.array([h.theta for h in self.hinges])
        self._moment = np.array([h.moment for h in self.hinges])
        self._behind = np.zeros(len(self.laws), dtype=bool)
        #: hinges that reached a branch of negative tangent moving onto it (a capping
        #: point: post-capping softening) or whose moment jumped (fracture, complete
        #: deterioration) at some time in the run
        self.capped = np.zeros(len(self.laws), dtype=bool)
        # each hinge's branches from its committed state: tangents and ends, up and down
        nh = len(self.laws)
        self._k_up, self._end_up = np.zeros(nh), np.zeros(nh)
        self._k_down, self._end_down = np.zeros(nh), np.zeros(nh)
        self._two_way = np.zeros(nh, dtype=bool)
        self._k_unload = np.zeros(nh)
        for h in range(nh):
            self._learn(h)

    # ------------------------------------------------------------------ the hinges now
    @property
    def n_floors(self) -> int:
        """Number of floors (the frame's DOFs with mass)."""
        return int(self.kept.size)

    @property
    def n_hinges(self) -> int:
        """Number of hinges."""
        return len(self.laws)

    def rotations(self) -> Vector:
        """Committed hinge rotations [rad]."""
        return self._theta.copy()

    def moments(self) -> Vector:
        """Committed hinge moments [N·m]."""
        return self._moment.copy()

    def unloading_stiffness(self) -> Vector:
        """Each hinge's unloading stiffness at its committed state [N·m/rad] (its
        recoverable energy is ``M²/(2 k)``)."""
        return self._k_unload.copy()

    def law_states(self) -> list[HingeState]:
        """Each hinge's committed state as its law keeps it (every hinge brought up to its
        committed rotation)."""
        self._catch_up(np.flatnonzero(self._behind))
        return list(self.hinges)

    def hysteretic_energy(self) -> Vector:
        """Each hinge's hysteretic energy at its committed state [J]: its work less the
        change of its recoverable energy since the start."""
        rec = np.array([law.recoverable(h) for law, h in zip(self.laws, self.law_states())])
        return self.work - rec + self.recoverable0

    def plastic_rotations(self) -> Vector:
        """Each hinge's rotation once unloaded to zero moment along its unloading
        stiffness [rad]: its residual (plastic) rotation."""
        self.law_states()
        return self.rotations() - self.moments() / self.unloading_stiffness()

    def _learn(self, h: int) -> None:
        """Read hinge ``h``'s branches, two-way flag and unloading stiffness from its law's
        (up-to-date) state."""
        law, st = self.laws[h], self.hinges[h]
        up, down, two_way = law.branches(st)
        self._k_up[h], self._end_up[h] = up.k_t, up.theta_end
        self._k_down[h], self._end_down[h] = down.k_t, down.theta_end
        self._two_way[h] = two_way
        self._k_unload[h] = law.unloading_stiffness(st)
        self._theta[h], self._moment[h] = st.theta, st.moment
        self._behind[h] = False

    def _catch_up(self, which: NDArray[np.int64]) -> bool:
        """Move the laws of hinges ``which`` to their committed rotations (contract 7: along
        their two-way branch); whether a moment jumped on the way."""
        jumped = False
        for h in which:
            h = int(h)
            st = self.hinges[h]
            theta = float(self._theta[h])
            # (its branch that way, as :meth:`_learn` read it from this state — or, for a
            # hinge left behind on its two-way branch, from where it was left)
            first = (Branch(float(self._k_up[h]), float(self._end_up[h]))
                     if theta > st.theta else
                     Branch(float(self._k_down[h]), float(self._end_down[h])))
            moving_up = theta > st.theta
            st, jump = _moved(self.laws[h], st, theta, first)
            self.hinges[h] = st
            self._learn(h)
            ahead = self._k_up[h] if moving_up else self._k_down[h]
            if jump or ahead < 0.0:
                self.capped[h] = True
            jumped = jumped or jump
        return jumped

    # ------------------------------------------------------------------ configurations
    def condensed(self, tangents: Vector, directions: NDArray[np.int64]) -> Configuration:
        """The configuration with hinge tangents ``tangents`` about the committed hinge
        states (module docstring).

        Raises
        ------
        ValueError
            If the frame's massless DOFs have no unique equilibrium in it (a mechanism that
            does not involve the floors).
        """
        kept = self.kept  # (the DOFs with mass: the floors first)
        theta_c = self._theta
        q = self._moment - tangents * theta_c
        lin = self._condensation.part(tangents)
        Bq = self._incidence @ q
        fixed = self.node < 0
        p0 = np.zeros(self.dofs.n)
        p0[lin.dead] = self.U[lin.dead]  # (a joint with no stiffness stays where it is)
        if lin.live.size:
            p0[lin.live] = lin.solve((self.G - Bq)[lin.live])
        f0 = lin.Kms @ p0[lin.live] + Bq[kept] - self.G[kept]
        node_p0 = np.where(fixed, 0.0, p0[np.maximum(self.node, 0)])
        # from total floor displacements to those from the gravity state
        ug = self.u_gravity
        a0_equilibrium = node_p0 - p0[self.end] + lin.A @ ug
        f0 = f0 + lin.Kc @ ug
        p0 = p0 + lin.P @ ug
        # each hinge's rotation anchored where it was committed, θ = θ* + A (u − u*), not
        # B_sᵀ s0 (the same up to rounding): at that point its rotation is θ* exactly, so a
        # second commit at the same instant (another hinge's event) moves it not at all —
        # a move of a rounding error the wrong way is a reversal to a law with memory
        a0 = theta_c - lin.A @ self.u_commit
        Kc, A, P = lin.Kc, lin.A, lin.P
        # a hinge on one branch both ways: events at both its ends; else at the end of the
        # branch of its direction
        both = self._k_up == self._k_down
        lower = np.where(both | (directions <= 0), self._end_down, -math.inf)
        upper = np.where(both | (directions > 0), self._end_up, math.inf)
        return Configuration(directions.copy(), tangents.copy(), q, Kc, f0, A, a0, lower,
                             upper, P, p0, a0_equilibrium)

    def one_way(self) -> NDArray[np.bool_]:
        """True for every hinge whose branch depends on the direction it moves."""
        return self._k_up != self._k_down

    def configure(self, velocity: Vector,
                  acceleration: Vector | Callable[[Configuration], Vector],
                  rate_tol: float, fallback: Vector | None = None) -> Configuration:
        """Choose and set the configuration for floor velocities ``velocity`` [m/s] (from the
        gravity state's; continuous across an event) as :func:`frame_analysis._advance` does:
        each one-way hinge on the branch of ``sign(A_h u̇)`` — where ``|A_h u̇|`` is within
        ``rate_tol · Σ|A_h|`` [m/s × rad/m] of zero, the sign of ``A_h ü`` (``acceleration``:
        the floors' accelerations [m/s²], or a function of the configuration giving them),
        and failing both, the sign of ``fallback`` (floor displacements that show which way
        the frame will move, say) or the direction it last moved — checked in the
        configuration that choice gives, and flipped until they agree (at most
        ``2 n_h + 2`` times, the pushover's bound)."""
        nh = self.n_hinges
        one_way = self.one_way()
        directions = self.directions.copy()
        directions[~one_way] = 0
        for h in np.flatnonzero(one_way & (directions == 0)):
            directions[h] = 1
        cfg = None
        for _ in range(2 * nh + 2):
            tangents = np.where(directions < 0, self._k_down, self._k_up)
            cfg = self.condensed(tangents, directions)
            if not np.any(one_way):
                break
            rate = cfg.A @ velocity
            tol = rate_tol * np.sum(np.abs(cfg.A), axis=1)
            acc = None
            flips = 0
            for h in np.flatnonzero(one_way):
                want = 0
                if abs(rate[h]) > tol[h]:
                    want = 1 if rate[h] > 0.0 else -1
                else:
                    if acc is None:
                        a = acceleration(cfg) if callable(acceleration) else acceleration
                        acc = cfg.A @ a
                    if acc[h] != 0.0:
                        want = 1 if acc[h] > 0.0 else -1
                    elif fallback is not None and (cfg.A[h] @ fallback) != 0.0:
                        want = 1 if cfg.A[h] @ fallback > 0.0 else -1
                if want != 0 and want != directions[h]:
                    directions[h] = want
                    flips += 1
            if not flips:
                break
        assert cfg is not None
        moving = directions != 0
        self.directions[moving] = directions[moving]
        self.config = cfg
        return cfg

    def commit(self, u: Vector, equilibrium: float | None = None,
               land: dict[int, float] | None = None) -> Vector:
        """Commit the hinges at floor displacements ``u`` [m] (from the gravity state) in
        the current configuration: each hinge moved to its rotation there along its law
        (``law.moved``, across any breakpoint the located event just passed; a hinge on a
        two-way branch it has not left is committed on its line and its law caught up
        later, contract 7 of :mod:`pounding.hysteresis.hinges`), its work
        ``∫ M dθ`` along the configuration's branch added, the frame's displacements kept;
        :attr:`jumped` set if a hinge's moment jumped on the way. ``equilibrium`` [rad/m]:
        the rotations of the configuration's own equilibrium at ``u`` (after a jump), not
        those anchored at the last commit — for each hinge whose equilibrium rotation is
        further than ``equilibrium · Σ|A_h|`` (and 10⁻¹² of its rotation) from where it
        stands (a move of a rounding error is a reversal to a law with memory). ``land``: hinges to commit at these rotations instead
        (an event's, on the end of its branch: :meth:`landing`). Returns the hinge
        rotations [rad]."""
        cfg = self.config
        assert cfg is not None
        theta_c, moment_c = self.rotations(), self.moments()
        theta = cfg.A @ (u - self.u_commit) + theta_c
        if equilibrium is not None:
            settled = cfg.A @ u + cfg.a0_equilibrium
            theta_y = np.array([law.theta_y for law in self.laws])
            near = np.maximum(equilibrium * np.sum(np.abs(cfg.A), axis=1),
                              1e-12 * (np.abs(theta) + theta_y))
            far = np.abs(settled - theta) > near
            theta = np.where(far, settled, theta)
        for h, th in (land or {}).items():
            theta[h] = th
        moment = cfg.tangents * theta + cfg.q
        self.work = self.work + 0.5 * (moment_c + moment) * (theta - theta_c)
        self.U = cfg.P @ u + cfg.p0
        self.u_commit = np.array(u, dtype=float)
        # the laws are asked only about the hinges that may have left their branch or whose
        # branch is not two-way (contract 7); the others are committed on their line
        ask = ~self._two_way | (cfg.directions != 0) | (theta <= cfg.lower) | \
            (theta >= cfg.upper)
        if land:
            ask[list(land)] = True
        if equilibrium is not None:
            ask |= far
        self._theta, self._moment = theta, moment
        self._behind |= ~ask
        self.jumped = self._catch_up(np.flatnonzero(ask))
        return self._theta.copy()

    def landing(self, u: Vector, velocity: Vector, theta_tol: float,
                event: int | None = None) -> dict[int, float]:
        """The hinges to commit on the end of their branch at floor displacements ``u``:
        each within ``theta_tol · Σ|A_h|`` [rad] of an end of its branch and heading there
        (velocity ``velocity``), and the event's hinge ``event`` (which the time stepper
        found past it), each at its rotation or on the end, whichever is further — never
        short of it by a rounding error, which would leave the law a branch of zero length
        there (and the time stepper the same event again and again)."""
        cfg = self.config
        assert cfg is not None
        theta = cfg.A @ (u - self.u_commit) + self._theta
        rate = cfg.A @ velocity
        tol = theta_tol * np.sum(np.abs(cfg.A), axis=1)
        heading = np.zeros(self.n_hinges, dtype=bool) if event is None else \
            (np.arange(self.n_hinges) == event)
        down = (theta <= cfg.lower + tol) & (heading | (rate < 0.0))
        up = (theta >= cfg.upper - tol) & (heading | (rate > 0.0)) & ~down
        out = {int(h): float(min(theta[h], cfg.lower[h])) for h in np.flatnonzero(down)}
        out.update({int(h): float(max(theta[h], cfg.upper[h])) for h in np.flatnonzero(up)})
        return out

    def redistribute(self, u: Vector, velocity: Vector, acceleration: Vector,
                     rate_tol: float, theta_tol: float) -> Configuration:
        """After a hinge's moment jumped at floor displacements ``u`` (:attr:`jumped`): the
        massless DOFs take the equilibrium of the configuration with the jumped moment at
        once (they have no mass to hold them), each hinge moved to its rotation there and
        the configuration chosen again, until no moment jumps. (The pushover releases such
        a jump event by event, :func:`pounding.structure.frame_analysis._advance`; here a
        hinge the release carries past the end of its branch is moved along its law at once,
        and the next configuration takes it from there.) ``theta_tol`` [rad/m]: a hinge
        within ``theta_tol · Σ|A_h|`` of its equilibrium rotation stays where it is.

        Raises
        ------
        ValueError
            If the jumps keep cascading (more than ``2 n_h + 10`` rounds).
        """
        cfg = self.config
        assert cfg is not None
        if not self.jumped:
            return cfg
        # (until no moment jumps and no hinge changes branch: a hinge the release carried
        # past a breakpoint follows its law, not the line the release assumed, and the next
        # round releases the difference; once the tangents stay, the equilibrium is where
        # the hinges are, to rounding)
        theta_y = np.array([law.theta_y for law in self.laws])
        for _ in range(2 * self.n_hinges + 10):
            before = cfg.tangents
            self.commit(u, equilibrium=theta_tol)
            cfg = self.configure(velocity, acceleration, rate_tol)
            if not self.jumped and np.array_equal(cfg.tangents, before):
                return cfg
        # (a law whose memory changes at every reversal — IMK's unloading stiffness — can
        # keep the last rounds moving hinges by rounding errors back and forth: accepted
        # where the equilibrium is that close)
        gap = np.abs(cfg.A @ u + cfg.a0_equilibrium - self.rotations())
        near = np.maximum(theta_tol * np.sum(np.abs(cfg.A), axis=1),
                          1e-9 * (np.abs(self.rotations()) + theta_y))
        if not self.jumped and np.all(gap <= near):
            return cfg
        raise FrameCollapse(f"{self.frame.name}: its hinges' moments keep jumping (fractures "
                            "cascading) without reaching an equilibrium")

    def residual_floors(self, u: Vector) -> Vector:
        """The floors' displacements [m] (from the gravity state) once the frame at floor
        displacements ``u`` (current configuration) is unloaded to zero lateral force with
        every hinge at its unloading stiffness: ``u − K_un⁻¹ (K_c u + f0)`` — its residual
        (permanent) displacements, as a storey's residual drift is its drift unloaded along
        its unloading stiffness. A hinge with nothing left to unload (complete
        deterioration) takes no moment.

        Raises
        ------
        ValueError
            If the unloaded frame is a mechanism (no unique residual position).
        """
        cfg = self.config
        assert cfg is not None
        self.law_states()
        k_un = np.where(np.isfinite(self._k_unload), self._k_unload, 0.0)
        part = self._condensation.part(k_un)
        return u - np.linalg.solve(part.Kc, cfg.K @ u + cfg.f0)

    def displacements(self, u: Vector) -> Vector:
        """Every DOF of the frame [m, rad] (total, from the undeformed frame) at floor
        displacements ``u`` from the gravity state, in the current configuration."""
        cfg = self.config
        assert cfg is not None
        return cfg.P @ u + cfg.p0

    def strain_energy(self, u: Vector) -> float:
        """The frame's recoverable energy [J] at floor displacements ``u`` (current
        configuration) relative to its gravity state: the elastic elements' and geometric
        ``½ Uᵀ K_base U − Gᵀ U`` and the hinges' recoverable ``M²/(2 k_unload)``, each less
        its value at the start. (For checks: the run integrates the restoring force's work
        instead.)"""
        cfg = self.config
        assert cfg is not None
        U = self.displacements(u)
        theta = cfg.A @ u + cfg.a0
        moment = cfg.tangents * theta + cfg.q
        k_un = self.unloading_stiffness()
        return float(0.5 * U @ self.base @ U - self.G @ U - self._elastic0
                     + np.sum(0.5 * moment ** 2 / k_un) - np.sum(self.recoverable0))

    @property
    def _elastic0(self) -> float:
        U0 = self.U0
        return float(0.5 * U0 @ self.base @ U0 - self.G @ U0)

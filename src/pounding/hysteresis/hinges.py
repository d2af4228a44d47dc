"""Plastic-hinge laws: moment–rotation laws of the concentrated hinges at a frame member's ends.

A hinge is a rotational spring in series with the elastic member (OpenSees: a
``zeroLength`` element with a uniaxial material between the joint and the member end). Its
law maps the hinge rotation ``θ`` [rad] (the joint's rotation minus the member end's) to the
moment ``M`` [N·m] it carries. Every law here is *piecewise linear* in ``θ`` along a
monotonic path, which is what lets a frame be analysed event to event — exactly, with no
equilibrium iterations and so with nothing that can fail to converge: between two events
each hinge sits on one straight branch, the frame is linear, and the next event (a hinge
reaching the end of its branch, or a hinge's rotation turning back) is found in closed form.

Contract (the frame analyses of :mod:`pounding.structure.frame_analysis` rely on it)
-----------------------------------------------------------------------------------------
1. **Sign convention.** ``θ > 0`` and ``M > 0`` in the same sense; a law is odd-symmetric
   about its start unless its constants say otherwise.
2. **State.** :class:`HingeState` is the committed state: ``theta``, ``moment`` and a tuple of
   the law's own memory (reversal points, dissipated energy, deteriorated strengths …).
   States are immutable; :meth:`HingeLaw.start` gives the unloaded one.
3. **Branch.** :meth:`HingeLaw.branch` ``(state, direction)`` with ``direction = ±1`` is the
   straight branch the moment follows if the rotation moves from ``state.theta`` that way:
   its tangent ``k_t`` [N·m/rad] (zero on a plastic plateau, negative after a capping point)
   and the rotation ``theta_end`` where the branch ends (``±inf``: never). The branch is
   right-continuous: a state exactly at a breakpoint reports the branch beyond it.
4. **Move.** :meth:`HingeLaw.moved` ``(state, theta)`` is the state after the rotation moved
   monotonically from ``state.theta`` to ``theta`` (across any number of breakpoints of that
   direction), committed there. A change of direction is simply the next call's direction:
   the memory a reversal updates (for instance cyclic deterioration) is updated then.
5. **Consistency.** Moving along a branch to its end and then asking for the branch again
   gives the next branch; ``moved`` over a whole path equals ``moved`` branch by branch
   (:func:`moment_path` uses the latter, tests compare with the former).
6. **Energy.** ``moment`` integrated over ``θ`` is the work done on the hinge; what it gives
   back when unloaded to zero moment along its elastic branch is
   :meth:`HingeLaw.recoverable`, ``M²/(2 k_unload)``; the rest is its hysteretic energy.
7. **Two-way branches.** Where :meth:`HingeLaw.two_way` says so — the branch up and the
   branch down have one tangent and a move either way updates no memory (an elastic
   branch) — the hinge may move back and forth along that line and be committed only when it
   leaves it: ``moved`` from the first state to the last equals ``moved`` through every
   point between. The time stepper of a yielding frame
   (:mod:`pounding.structure.frame_configuration`) asks the law nothing about such a hinge
   until it reaches an end of the branch.

Laws here: :class:`ElasticPlastic` (elastic–perfectly plastic, for hand checks) and
:class:`BilinearHinge` (bilinear, kinematic hardening; OpenSees ``Steel01`` with no isotropic
hardening). The modified Ibarra–Medina–Krawinkler laws are in :mod:`pounding.hysteresis.imk`.
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "BilinearHinge",
    "Branch",
    "ElasticPlastic",
    "HingeLaw",
    "HingeState",
    "moment_path",
]

INF = math.inf


@dataclass(frozen=True)
class HingeState:
    """Committed state of a hinge (contract 2)."""

    theta: float = 0.0  #: rotation [rad]
    moment: float = 0.0  #: moment [N·m]
    memory: tuple[float, ...] = field(default=())  #: the law's own history variables


@dataclass(frozen=True)
class Branch:
    """A straight branch of a hinge law (contract 3): ``M = moment + k_t (θ − theta)`` from the
    state's point until ``theta_end``."""

    k_t: float  #: tangent [N·m/rad]
    theta_end: float  #: rotation where the branch ends [rad] (±inf: never)


def _positive(name: str, value: float) -> float:
    v = float(value)
    if not (math.isfinite(v) and v > 0.0):
        raise ValueError(f"{name}: must be finite and > 0 (got {value!r})")
    return v


@dataclass(frozen=True)
class HingeLaw(ABC):
    """Base of every hinge law: the elastic stiffness ``k0`` [N·m/rad] and the yield moment
    ``m_y`` [N·m] (the strength that starts yielding, both directions unless a law says)."""

    k0: float
    m_y: float

    label: ClassVar[str]

    def __post_init__(self) -> None:
        object.__setattr__(self, "k0", _positive(f"{self.label}.k0", self.k0))
        object.__setattr__(self, "m_y", _positive(f"{self.label}.m_y", self.m_y))
        self._check()

    def _check(self) -> None:
        """Validate the law's own constants (subclasses)."""

    @property
    def theta_y(self) -> float:
        """Yield rotation ``m_y / k0`` [rad]."""
        return self.m_y / self.k0

    def start(self) -> HingeState:
        """The unloaded state."""
        return HingeState()

    @abstractmethod
    def branch(self, state: HingeState, direction: int) -> Branch:
        """The branch followed from ``state`` if the rotation moves in ``direction`` (±1)."""

    def moved(self, state: HingeState, theta: float) -> HingeState:
        """The state after a monotonic move from ``state.theta`` to ``theta`` (contract 4).

        The default walks the branches; laws whose memory changes at reversals override
        :meth:`_reversed` (called when the direction differs from the last move's).
        """
        theta = float(theta)
        if theta == state.theta:
            return state
        direction = 1 if theta > state.theta else -1
        state = self._reversed(state, direction)
        for _ in range(10_000):
            br = self.branch(state, direction)
            end = br.theta_end
            if (direction > 0 and end >= theta) or (direction < 0 and end <= theta):
                return self._along(state, br, theta, direction)
            state = self._along(state, br, end, direction)
        raise RuntimeError(f"{self.label}: more than 10000 branches in one move")  # pragma: no cover

    def _reversed(self, state: HingeState, direction: int) -> HingeState:
        """The state with the memory a move in ``direction`` starts from (default: as is)."""
        return state

    def _along(self, state: HingeState, br: Branch, theta: float,
               direction: int) -> HingeState:
        """The state at ``theta`` along branch ``br`` (laws add their memory updates)."""
        return HingeState(theta, state.moment + br.k_t * (theta - state.theta), state.memory)

    def two_way(self, state: HingeState, up: Branch | None = None,
                down: Branch | None = None) -> bool:
        """Whether ``state`` lies on one straight branch both ways whose memory a reversal
        leaves as it is (contract 7): the branches up and down share their tangent and the
        state is already what a move either way starts from. ``up``, ``down``: its
        branches, if at hand."""
        up = self.branch(state, 1) if up is None else up
        down = self.branch(state, -1) if down is None else down
        if up.k_t != down.k_t:
            return False
        return self._reversed(state, 1) == state and self._reversed(state, -1) == state

    def branches(self, state: HingeState) -> tuple[Branch, Branch, bool]:
        """The branches up and down from ``state`` and :meth:`two_way` of it, at once (laws
        whose branches share work override it)."""
        up, down = self.branch(state, 1), self.branch(state, -1)
        return up, down, self.two_way(state, up, down)

    def unloading_stiffness(self, state: HingeState) -> float:
        """Stiffness of the branch that unloads from ``state`` [N·m/rad] (default ``k0``)."""
        return self.k0

    def recoverable(self, state: HingeState) -> float:
        """Elastic energy [J] given back when unloaded to zero moment (contract 6)."""
        return 0.5 * state.moment ** 2 / self.unloading_stiffness(state)

    def describe(self) -> str:
        """One line: the law and its constants."""
        return f"{self.label}(k0={self.k0:.6g} N·m/rad, m_y={self.m_y:.6g} N·m{self._describe()})"

    def _describe(self) -> str:
        return ""


@dataclass(frozen=True)
class BilinearHinge(HingeLaw):
    """Bilinear hinge with kinematic hardening.

    The moment moves with slope ``k0`` inside a band of half-width ``(1 − b) m_y`` about the
    hardening line ``b k0 θ`` (the same law as the bilinear storey,
    :mod:`pounding.hysteresis.bilinear`, and OpenSees ``Steel01`` without isotropic hardening):
    skeleton ``±m_y`` at ``±θ_y`` then slope ``b k0``; unloading elastic; reverse yield after a
    change of ``2 m_y`` in moment.

    Parameters
    ----------
    k0 : float
        Elastic rotational stiffness [N·m/rad].
    m_y : float
        Yield moment [N·m].
    hardening : float
        Post-yield stiffness ratio ``b`` (0 ≤ b < 1).

    Examples
    --------
    >>> from pounding.hysteresis.hinges import BilinearHinge, moment_path
    >>> law = BilinearHinge(k0=1e8, m_y=3e5, hardening=0.05)
    >>> [round(m) for m in moment_path(law, [0.0, 0.003, 0.013, 0.0])]
    [0, 300000, 350000, -285000]
    """

    hardening: float = 0.0

    label = "bilinear"

    def _check(self) -> None:
        b = float(self.hardening)
        if not (0.0 <= b < 1.0):
            raise ValueError(f"{self.label}.hardening: the post-yield stiffness ratio must be "
                             f"in [0, 1) (got {self.hardening!r})")
        object.__setattr__(self, "hardening", b)

    def branch(self, state: HingeState, direction: int) -> Branch:
        k, b = self.k0, self.hardening
        band = (1.0 - b) * self.m_y
        bound = b * k * state.theta + direction * band  # the band edge it moves towards
        gap = direction * (bound - state.moment)
        if gap <= 1e-12 * self.m_y:  # on the edge, moving outward: hardening
            return Branch(b * k, direction * INF)
        # elastic until M + k (θ − θc) = b k θ + s band  ->  θ = (M − k θc − s band)/(b k − k)
        theta_end = (state.moment - k * state.theta - direction * band) / (b * k - k)
        return Branch(k, theta_end)

    def _along(self, state: HingeState, br: Branch, theta: float,
               direction: int) -> HingeState:
        if br.k_t == self.k0 and math.isfinite(br.theta_end) and theta == br.theta_end:
            # land exactly on the band edge (no rounding off it)
            b = self.hardening
            m = b * self.k0 * theta + direction * (1.0 - b) * self.m_y
            return HingeState(theta, m, state.memory)
        return super()._along(state, br, theta, direction)

    def _describe(self) -> str:
        return f", hardening={self.hardening:g}"


@dataclass(frozen=True)
class ElasticPlastic(BilinearHinge):
    """Elastic–perfectly plastic hinge (``hardening = 0``): moment ``k0 θ`` up to ``±m_y``, then
    constant; unloading elastic. For hand checks (plastic analysis, mechanism loads)."""

    label = "elastic-plastic"

    def _check(self) -> None:
        if float(self.hardening) != 0.0:
            raise ValueError(f"{self.label}.hardening: must be 0 (got {self.hardening!r}); "
                             "use bilinear for a hardening hinge")
        object.__setattr__(self, "hardening", 0.0)

    def _describe(self) -> str:
        return ""


def moment_path(law: HingeLaw, rotations: ArrayLike) -> NDArray[np.float64]:
    """Moment [N·m] along a rotation history [rad] (a cyclic test of one hinge), starting
    unloaded; between samples the rotation moves linearly, so every breakpoint between them
    is passed through branch by branch (contract 5)."""
    th = np.asarray(rotations, dtype=float)
    if th.ndim != 1 or not np.all(np.isfinite(th)):
        raise ValueError("rotations: need a 1-D array of finite values [rad]")
    state = law.start()
    out = np.zeros(th.size)
    for i, t in enumerate(th):
        state = law.moved(state, float(t))
        out[i] = state.moment
    return out

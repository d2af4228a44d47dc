"""The modified Ibarra–Medina–Krawinkler deterioration model as hinge laws: bilinear and
peak-oriented hysteresis (OpenSees ``IMKBilin`` and ``IMKPeakOriented``).

Sources: Ibarra, Medina & Krawinkler (2005), "Hysteretic models that incorporate strength and
stiffness deterioration", *Earthquake Engng Struct. Dyn.* 34(12):1489–1511 (the cyclic rules,
equation numbers below); Lignos & Krawinkler (2011), "Deterioration modeling of steel components
in support of collapse prediction of steel moment frames under earthquake loading",
*J. Struct. Eng.* 137(11):1291–1302 (the modified backbone: residual strength, ultimate
rotation, E_t = Λ M_y, sides that differ, rates D±). Where the papers leave a rule open, or
OpenSees does otherwise, this module follows the OpenSees source (IMKBilin "AE_KI (Nov22)",
IMKPeakOriented "AE_KI (Sep23)", as in OpenSeesPy 3.7), each place listed below.

Backbone (monotonic curve of one side; Lignos & Krawinkler 2011, Fig. 1)
-------------------------------------------------------------------------
With ``θ_y = M_y/K_e``, ``M_c = (M_c/M_y) M_y``, ``θ_c = θ_y + θ_p``, ``K_s = (M_c − M_y)/θ_p``::

    M = K_e θ                          0   <= θ <= θ_y
    M = M_y + K_s (θ − θ_y)            θ_y <= θ <= θ_c
    M = M_c − (M_c/θ_pc) (θ − θ_c)     θ_c <= θ <= θ_r,   θ_r: where it reaches κ M_y
    M = κ M_y                          θ_r <= θ <  θ_u
    M = 0                              θ   >= θ_u          (fracture)

Cyclic deterioration (Ibarra et al. 2005)
-----------------------------------------
Each excursion ``i`` dissipates the hysteretic energy ``E_i``; with the reference energy
``E_t = Λ M_y`` (Λ in rad; Ibarra et al.'s Eq. 2, ``E_t = γ F_y δ_y``, in Lignos & Krawinkler's
form) the rate of the excursion is, Eq. (1)::

    β_i = ( E_i / (E_t − Σ_{j=1..i} E_j) )^c

one β per mode, each with its own Λ and c (``s`` basic strength, ``c`` post-capping strength,
``k`` unloading stiffness, ``a`` accelerated reloading; OpenSees' ``Lamda_S/C/K/A``), applied
with the side's rate ``D``: Eq. (3) ``M_y,i = (1 − β_s,i D) M_y,i−1``; Eq. (4)
``K_s,i = (1 − β_s,i D) K_s,i−1``; Eq. (5) ``M_ref,i = (1 − β_c,i D) M_ref,i−1`` (``M_ref``: the
post-capping line's moment at θ = 0); Eq. (6) ``K_u,i = (1 − β_k,i) K_u,i−1``; Eq. (7) (peak-
oriented only) ``θ_t,i = (1 + β_a,i D) θ_t,i−1``, the target rotation of reloading. ``β >= 1``,
or ``E_t − Σ E_j <= 0``, is complete deterioration: the moment is 0 thereafter.

*Excursion* (as OpenSees): an excursion starts where the moment passes through zero on an
unloading/reloading branch (after the first yield); ``E_i`` is the work ``∫M dθ`` done since
the previous such crossing (the first: since the start), so at the crossing it is all
hysteretic. Eqs. (3)–(5) and (7) then update the backbone of the side the new excursion
heads to. Eq. (6) is applied at each reversal from the backbone (bilinear) or from a loading
branch (peak-oriented), with ``E_i`` the energy dissipated so far in the current excursion
and ``Σ E_j`` the total, both without the elastic energy ``M²/(2 K_u)``.

Where this follows OpenSees rather than the papers
--------------------------------------------------
* ``E_t = Λ M_y⁺`` for both sides (the positive side's yield moment); Λ = 0 switches a mode off.
* Bilinear: the post-yield line extends below the yield point (kinematic hardening) and the
  residual strength bounds it from below; after each excursion the post-capping slope turns
  with the strength, ``K_pc,i = K_pc,0 (M_y,i − κM_y)/(M_y,0 − κM_y)`` (the papers translate
  the branch at a constant slope, as the peak-oriented law here does); if the reloading line
  would meet the residual branch before the post-yield line, ``K_s`` is lowered so that they
  meet at one point; once the residual branch (or a fracture) has been reached, each
  reversal from the backbone sets ``K_u = K_e/2``; a fracture at ``θ_u`` on one side leaves the
  other side its residual strength only (OpenSees ``Failure_State`` 3/4).
* Peak-oriented: reloading heads to the last reversal point on that side (the "local peak")
  first when that is steeper than heading to the target, then to the target (the largest
  rotation so far on that side, on the current backbone); a fracture at ``θ_u`` or zero
  strength on either side ends the hinge (moment 0 both ways).

Where this differs from OpenSees (the law must stay exact and continuous)
-------------------------------------------------------------------------
* OpenSees uses the energy up to the last step before a zero crossing and clamps a negative
  β (``E_t − Σ E_j < 0``) to 0; here both are exact: the crossing is a breakpoint, and an
  exhausted energy capacity is complete deterioration (the papers).
* Peak-oriented: the backbone has the residual floor everywhere (OpenSees' post-yield branch
  may fall below κ M_y after heavy deterioration), and when the reloading start lies beyond
  the target (a strongly deteriorated ``K_u``) reloading follows ``K_u`` up to the backbone
  (OpenSees jumps onto it).
* After a fracture at ``θ_u``, a rotation that turned back and moves outward again beyond
  ``θ_u`` reloads along its unloading stiffness to zero moment and stays there; OpenSees drops
  the moment to zero at once (a jump at every such reversal, which leaves a frame with no
  consistent state: the hinge would chatter between the two sides of the jump).

Jumps (the only places the moment is discontinuous, as OpenSees): the fracture at ``θ_u``,
and complete deterioration at a reversal (``β_k >= 1`` or
the energy exhausted there). :meth:`~pounding.hysteresis.hinges.HingeLaw.branch` ends at ``θ_u``;
:meth:`~pounding.hysteresis.hinges.HingeLaw.moved` there returns the moment after the drop.

The peak-oriented law is in :mod:`pounding.hysteresis.imk_peak`, the shared backbone and
deterioration rules in :mod:`pounding.hysteresis.imk_backbone`; both laws are exported here.
"""

from __future__ import annotations

import operator
from dataclasses import dataclass
from typing import ClassVar, NamedTuple

from pounding.hysteresis.hinges import Branch, HingeState
from pounding.hysteresis.imk_backbone import (
    INF,
    Bound,
    IMKLaw,
    Side,
    deteriorate,
    side_bound,
    side_prefix,
)
from pounding.hysteresis.imk_peak import IMKPeakOriented

__all__ = ["IMKBilinear", "IMKPeakOriented"]


class _BilinMemory(NamedTuple):
    on_bound: float  # ±1: on that side's backbone (a reversal from here updates K_u); 0: not
    yielded: float  # 1: has reached the backbone once (excursions count from then)
    residual: float  # 1: has reached a residual branch or lost a side (K_u = K_e/2 at reversals)
    lost_pos: float  # 1: the positive side has no strength (fracture, or zero residual reached)
    lost_neg: float
    dead: float  # 1: complete deterioration, moment 0 for good
    exc_dir: float  # sign of the current excursion (0: none yet)
    k_u: float  # unloading (and reloading) stiffness K_u [N·m/rad]
    work: float  # ∫M dθ since the start [J]
    work_exc: float  # ∫M dθ at the start of the current excursion [J]
    pos_fy: float
    pos_kp: float
    pos_ucap: float
    pos_fcap: float
    pos_kpc: float
    neg_fy: float
    neg_kp: float
    neg_ucap: float
    neg_fcap: float
    neg_kpc: float


_SIDE = ("fy", "kp", "ucap", "fcap", "kpc")
_SIDE_FIELDS = {s: operator.itemgetter(*(_BilinMemory._fields.index(side_prefix(s) + f)
                                         for f in _SIDE)) for s in (1, -1)}
"""Each side's backbone fields in the memory (``_side``: called at every branch query)."""


@dataclass(frozen=True)
class IMKBilinear(IMKLaw):
    """Modified IMK model with bilinear hysteresis (OpenSees ``IMKBilin``).

    Unloading and reloading are straight lines of slope ``K_u`` (initially ``k0``) between the
    two sides' backbones, each ``max(κ M_y, L(θ))`` with ``L`` the post-yield line (extended
    below the yield point: kinematic hardening) and then the post-capping line. Memory, and
    every rule, as in the module docstring.

    Parameters
    ----------
    k0, m_y, theta_p, theta_pc, theta_u, mc_my, kappa, *_neg, lambda_, lambda_s, lambda_c, \
lambda_k, c, c_s, c_c, c_k, d_pos, d_neg
        As :class:`pounding.hysteresis.imk_backbone.IMKLaw` (SI units, rotations in rad).

    Examples
    --------
    >>> from pounding.hysteresis.imk import IMKBilinear
    >>> from pounding.hysteresis.hinges import moment_path
    >>> law = IMKBilinear(k0=1e8, m_y=3e5, theta_p=0.02, theta_pc=0.1, theta_u=0.2)
    >>> [round(m) for m in moment_path(law, [0.0, 0.003, 0.023, 0.05, 0.2])]
    [0, 300000, 330000, 240900, 0]
    """

    label: ClassVar[str] = "imk-bilinear"

    @property
    def _tol(self) -> float:
        return 1e-12 * self.m_y

    def start(self) -> HingeState:
        p, n = self.sides[1].initial, self.sides[-1].initial
        return HingeState(0.0, 0.0, _BilinMemory(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, self.k0,
                                                 0.0, 0.0, *p, *n))

    # ----------------------------------------------------------------- the contract
    def _along(self, state: HingeState, br: Branch, theta: float,
               direction: int) -> HingeState:
        state = self._prepare(state, direction)  # as branch() saw it (idempotent)
        d, m = direction, _BilinMemory._make(state.memory)
        moment = state.moment + br.k_t * (theta - state.theta)
        m = m._replace(work=m.work + 0.5 * (state.moment + moment) * (theta - state.theta))
        if theta == br.theta_end:
            event, x = self._plan(state, d)[2], d * theta
            if event == "ultimate":
                m, moment = self._lose(m, d), 0.0
            elif event == "zero":
                m, moment = self._excursion(m, d, x), 0.0
            elif event in ("hit", "bound"):
                b = self._bound(m, d).value(x)
                m, moment = m._replace(on_bound=float(d), yielded=1.0), d * b
                if b <= 0.0:
                    m, moment = self._lose(m, d), 0.0
            if m.dead:
                return HingeState(theta, 0.0, m._replace(on_bound=0.0))
        return HingeState(theta, moment, self._residual_reached(m, theta, moment))

    def unloading_stiffness(self, state: HingeState) -> float:
        m = _BilinMemory._make(state.memory)
        if m.on_bound and state.moment != 0.0 and not m.dead:
            k = self._unloading_after_reversal(m, state.moment)
            return INF if k is None else k
        return m.k_u

    # ----------------------------------------------------------------- the rules
    def _side(self, m: _BilinMemory, s: int) -> Side:
        return Side._make(_SIDE_FIELDS[s](m))

    def _bound(self, m: _BilinMemory, s: int) -> Bound:
        """The backbone towards side ``s`` in its coordinates (0 if the side is lost, its
        residual strength if the other side is, as OpenSees)."""
        if m.lost_pos if s > 0 else m.lost_neg:
            return Bound.constant(0.0)
        fres = self.sides[s].fres
        if m.lost_neg if s > 0 else m.lost_pos:
            return Bound.constant(fres)
        return side_bound(self._side(m, s), fres)

    def _lose(self, m: _BilinMemory, s: int) -> _BilinMemory:
        m = m._replace(**{("lost_pos" if s > 0 else "lost_neg"): 1.0}, yielded=1.0,
                       residual=1.0)
        return m._replace(dead=1.0) if m.lost_pos and m.lost_neg else m

    def _prepare(self, state: HingeState, d: int) -> HingeState:
        """Resolve what happens at the state's point when the rotation starts moving in ``d``:
        a reversal from the backbone (Eq. 6), fracture beyond ``θ_u``, an excursion starting
        at zero moment, arrival on the backbone. Idempotent."""
        m, theta, moment = _BilinMemory._make(state.memory), state.theta, state.moment
        if m.dead:
            return state if moment == 0.0 else HingeState(theta, 0.0, m)
        if m.on_bound and d != m.on_bound:  # a reversal from the backbone
            k_u = self._unloading_after_reversal(m, moment)
            if k_u is None:
                return HingeState(theta, 0.0, m._replace(dead=1.0, on_bound=0.0))
            m = m._replace(k_u=k_u, on_bound=0.0)
        lost = m.lost_pos if d > 0 else m.lost_neg
        if d * theta >= self.sides[d].uu and not lost:
            m, moment = self._lose(m, d), 0.0
        if not m.on_bound and m.yielded and moment == 0.0 and m.exc_dir != d and not m.dead:
            m = self._excursion(m, d, d * theta)
        if m.dead:
            return HingeState(theta, 0.0, m._replace(on_bound=0.0))
        b = self._bound(m, d).value(d * theta)
        if d * moment >= b - self._tol:
            m, moment = m._replace(on_bound=float(d), yielded=1.0), d * b
            if b <= 0.0:  # no strength left this way (OpenSees' FailRp/FailRn)
                m, moment = self._lose(m, d), 0.0
                if m.dead:
                    return HingeState(theta, 0.0, m._replace(on_bound=0.0))
        return HingeState(theta, moment, m)

    def _plan(self, state: HingeState, d: int) -> tuple[float, float, str]:
        """Tangent, end (side coordinates) and event at the end of the branch from a
        prepared state."""
        m = _BilinMemory._make(state.memory)
        x, mm, uu = d * state.theta, d * state.moment, self.sides[d].uu
        lost = m.lost_pos if d > 0 else m.lost_neg
        if m.dead or (x >= uu and not lost):
            return 0.0, INF, ""
        bound = self._bound(m, d)
        if mm >= bound.value(x) - self._tol:  # on the backbone
            kb = bound.slope_after(x)
            k, end, event = (kb, bound.next_break(x), "bound") if kb <= m.k_u else \
                (m.k_u, bound.next_break(x), "")
        else:
            k, event = m.k_u, "hit"
            end = bound.first_hit(x, mm, k)
            if m.yielded and not m.on_bound and mm < 0.0 and x - mm / k <= end:
                end, event = x - mm / k, "zero"
        if uu <= end and not lost:
            end, event = uu, "ultimate"
        return k, end, event

    def _unloading_after_reversal(self, m: _BilinMemory, moment: float) -> float | None:
        """K_u after a reversal at ``moment`` (Eq. 6; ``None``: complete deterioration)."""
        stored = 0.5 * moment * moment / m.k_u
        beta = self.beta("k", m.work - m.work_exc - stored, m.work - stored)
        if beta is None:
            return None
        return 0.5 * self.k0 if m.residual else m.k_u * (1.0 - beta)

    def _excursion(self, m: _BilinMemory, d: int, x: float) -> _BilinMemory:
        """A new excursion towards side ``d`` starting at rotation ``x`` (side coordinates):
        Eqs. (1), (3)–(5) with OpenSees' post-capping slope and reloading rules."""
        energy = m.work - m.work_exc
        beta_s, beta_c = self.beta("s", energy, m.work), self.beta("c", energy, m.work)
        m = m._replace(work_exc=m.work, exc_dir=float(d))
        if beta_s is None or beta_c is None:
            return m._replace(dead=1.0)
        c = self.sides[d]
        side = deteriorate(self._side(m, d), c, self.k0, beta_s, beta_c, rotate_post_cap=True)
        if side.fcap < c.fres:
            side = Side(c.fres, 0.0, 0.0, c.fres, 0.0)
        else:
            reach = side.ucap - x - c.fres / m.k_u  # reloading meets κM_y at ucap − reach
            if reach > 0.0 and 0.0 < (side.fcap - c.fres) / reach < side.kp:
                side = side._replace(kp=(side.fcap - c.fres) / reach)
        return m._replace(**{side_prefix(d) + f: v for f, v in zip(_SIDE, side, strict=True)})

    def _residual_reached(self, m: _BilinMemory, theta: float, moment: float) -> _BilinMemory:
        if m.residual:
            return m
        for s in (1, -1):
            side, fres = self._side(m, s), self.sides[s].fres
            if side.kpc == 0.0:
                # on the residual branch, not just touching it where the post-yield line
                # starts (as OpenSees, whose steps land beyond that point)
                reached = (m.on_bound == s and abs(s * moment - fres) <= self._tol
                           and self._bound(m, s).slope_after(s * theta) == 0.0)
            else:
                reached = s * theta >= side.ucap + (fres - side.fcap) / side.kpc
            if reached:
                return m._replace(residual=1.0)
        return m

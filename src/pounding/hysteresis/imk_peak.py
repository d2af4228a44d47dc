"""The modified IMK model with peak-oriented hysteresis (OpenSees ``IMKPeakOriented``), a hinge
law; the model, its sources and where it follows OpenSees: :mod:`pounding.hysteresis.imk`,
which exports it."""

from __future__ import annotations

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

__all__ = ["IMKPeakOriented"]


class _PeakMemory(NamedTuple):
    code: float  # 0 elastic (never yielded), 1 unloading, 2 to the local peak, 3 to the target,
    # 4 on the backbone
    side: float  # the side codes 2–4 load towards (±1)
    k_u: float  # unloading stiffness K_u [N·m/rad]
    k_r: float  # slope of the reloading branch (codes 2, 3)
    work: float  # ∫M dθ since the start [J]
    work_exc: float  # ∫M dθ at the start of the current excursion [J]
    dead: float  # 1: failed, moment 0 for good
    target_u: float  # end of the code-3 branch, side coordinates [rad]
    target_m: float  # ... and its moment [N·m]
    pos_fy: float
    pos_kp: float
    pos_ucap: float
    pos_fcap: float
    pos_ul: float  # local peak: the last reversal point on this side
    pos_ml: float
    pos_ug: float  # target ("global peak"): the largest rotation on this side (Eq. 7)
    pos_mg: float
    neg_fy: float
    neg_kp: float
    neg_ucap: float
    neg_fcap: float
    neg_ul: float
    neg_ml: float
    neg_ug: float
    neg_mg: float


_PEAK_SIDE = ("fy", "kp", "ucap", "fcap", "ul", "ml", "ug", "mg")


@dataclass(frozen=True)
class IMKPeakOriented(IMKLaw):
    """Modified IMK model with peak-oriented hysteresis (OpenSees ``IMKPeakOriented``).

    Unloading has slope ``K_u``; past zero moment, reloading heads for the target point on the
    side it moves to — the largest rotation reached on that side so far (grown by Eq. 7), on
    the current backbone — or first for the last reversal point there if that line is
    steeper; beyond the target the moment follows the backbone. Adds to
    :class:`IMKBilinear`'s constants ``lambda_a``, ``c_a`` (accelerated reloading stiffness).

    Examples
    --------
    >>> from pounding.hysteresis.imk import IMKPeakOriented
    >>> from pounding.hysteresis.hinges import moment_path
    >>> law = IMKPeakOriented(k0=1e8, m_y=3e5, theta_p=0.02, theta_pc=0.1)
    >>> [round(m) for m in moment_path(law, [0.0, 0.013, 0.0, -0.013, 0.0, 0.005])]
    [0, 315000, -229961, -315000, 135788, 204716]
    """

    lambda_a: float | None = None
    c_a: float | None = None

    label: ClassVar[str] = "imk-peak-oriented"
    _MODES: ClassVar[tuple[str, ...]] = ("s", "c", "k", "a")

    def start(self) -> HingeState:
        values: list[float] = []
        for s in (1, -1):
            c = self.sides[s]
            values += [c.fy0, c.kp0, c.ucap0, c.fcap0, c.uy0, c.fy0, c.uy0, c.fy0]
        return HingeState(0.0, 0.0, _PeakMemory(0.0, 0.0, self.k0, self.k0, 0.0, 0.0, 0.0,
                                                0.0, 0.0, *values))

    # ----------------------------------------------------------------- the contract
    def _along(self, state: HingeState, br: Branch, theta: float,
               direction: int) -> HingeState:
        state = self._prepare(state, direction)  # as branch() saw it (idempotent)
        d, m = direction, _PeakMemory._make(state.memory)
        moment = state.moment + br.k_t * (theta - state.theta)
        m = m._replace(work=m.work + 0.5 * (state.moment + moment) * (theta - state.theta))
        if theta == br.theta_end:
            event = self._plan(state, d)[2]
            if event == "ultimate":
                m = m._replace(dead=1.0)
            elif event == "zero":
                m, moment = self._excursion(m, d, d * theta), 0.0
            elif event:
                m, moment = self._arrive(m, d, theta, moment)
            if m.dead:
                return HingeState(theta, 0.0, m)
        return HingeState(theta, moment, m)

    def unloading_stiffness(self, state: HingeState) -> float:
        m = _PeakMemory._make(state.memory)
        if m.code >= 2 and state.moment != 0.0 and not m.dead:
            k = self._unloading_after_reversal(m, state.moment)
            return INF if k is None else k
        return m.k_u

    # ----------------------------------------------------------------- the rules
    def _peak(self, m: _PeakMemory, s: int, name: str) -> float:
        return float(getattr(m, side_prefix(s) + name))

    def _bound(self, m: _PeakMemory, s: int) -> Bound:
        return side_bound(self._backbone(m, s), self.sides[s].fres)

    def _backbone(self, m: _PeakMemory, s: int) -> Side:
        return Side(self._peak(m, s, "fy"), self._peak(m, s, "kp"), self._peak(m, s, "ucap"),
                    self._peak(m, s, "fcap"), self.sides[s].kpc0)

    def _prepare(self, state: HingeState, d: int) -> HingeState:
        """Resolve what happens at the state's point when the rotation starts moving in ``d``
        (reversal: peaks and Eq. 6; failure beyond ``θ_u``; an excursion starting at zero
        moment; arrival at the end of a branch). Idempotent."""
        m, theta, moment = _PeakMemory._make(state.memory), state.theta, state.moment
        if m.dead:
            return state if moment == 0.0 else HingeState(theta, 0.0, m)
        if m.code >= 2 and d != m.side:  # a reversal from a loading branch
            p = 1 if moment > 0.0 else -1
            peaks = {"ul": p * theta, "ml": p * moment}
            if p * theta > self._peak(m, p, "ug"):
                peaks.update(ug=p * theta, mg=p * moment)
            k_u = self._unloading_after_reversal(m, moment)
            m = m._replace(code=1.0, k_u=m.k_u if k_u is None else k_u,
                           dead=float(k_u is None or min(m.pos_mg, m.neg_mg) <= 0.0),
                           **{side_prefix(p) + k: v for k, v in peaks.items()})
        if d * theta >= self.sides[d].uu:
            m = m._replace(dead=1.0)
        if m.code == 1 and moment == 0.0 and not m.dead:
            m = self._excursion(m, d, d * theta)
        if not m.dead:
            m, moment = self._arrive(m, d, theta, moment)
        if m.dead or (m.code == 4 and m.side * moment <= 0.0):
            return HingeState(theta, 0.0, m._replace(dead=1.0))
        return HingeState(theta, moment, m)

    def _arrive(self, m: _PeakMemory, d: int, theta: float,
                moment: float) -> tuple[_PeakMemory, float]:
        """The branch beyond the point ``theta`` when moving in ``d`` (OpenSees' branch
        shifts), with the moment on it there."""
        x, uy0 = d * theta, self.sides[d].uy0
        ul, ml = self._peak(m, d, "ul"), self._peak(m, d, "ml")
        if m.code == 0 and x >= uy0:
            m = m._replace(code=4.0, side=float(d))
        if ((m.code == 1 and d * moment > 0.0) or (m.code == 2 and m.side == d)) and x >= ul:
            ug, mg = self._peak(m, d, "ug"), self._peak(m, d, "mg")
            k_r = (mg - ml) / (ug - ul) if ug > ul else m.k_r
            m = m._replace(code=3.0, side=float(d), k_r=k_r, target_u=ug, target_m=mg)
            moment = d * (mg + k_r * (x - ug))
        if m.code == 3 and m.side == d and x >= m.target_u:
            m = m._replace(code=4.0)
        if m.code == 4 and m.side == d:
            b = self._bound(m, d).value(x)
            moment = d * b
            if b <= 0.0:  # zero residual strength reached (OpenSees' FailRp/FailRn)
                m = m._replace(dead=1.0)
        return m, moment

    def _plan(self, state: HingeState, d: int) -> tuple[float, float, str]:
        m = _PeakMemory._make(state.memory)
        x, mm, uu = d * state.theta, d * state.moment, self.sides[d].uu
        if m.dead or x >= uu:
            return 0.0, INF, ""
        k, end, event = (m.k_r if m.code in (2, 3) else 0.0), INF, ""
        if m.code == 0:
            k, end, event = self.k0, self.sides[d].uy0, "yield"
        elif m.code == 1:
            k = m.k_u
            end, event = (x - mm / k, "zero") if mm < 0.0 else (self._peak(m, d, "ul"), "local")
        elif m.code == 2 and m.side == d:
            end, event = self._peak(m, d, "ul"), "local"
        elif m.code == 3 and m.side == d:
            end, event = m.target_u, "target"
        elif m.code == 4 and m.side == d:
            bound = self._bound(m, d)
            k, end, event = bound.slope_after(x), bound.next_break(x), "backbone"
        # else: moving back along a reloading branch from zero moment, as OpenSees does
        if uu <= end:
            end, event = uu, "ultimate"
        return k, end, event

    def _unloading_after_reversal(self, m: _PeakMemory, moment: float) -> float | None:
        stored = 0.5 * moment * moment / m.k_u
        beta = self.beta("k", m.work - m.work_exc - stored, m.work - stored)
        return None if beta is None else m.k_u * (1.0 - beta)

    def _excursion(self, m: _PeakMemory, d: int, x: float) -> _PeakMemory:
        """A new excursion towards side ``d`` from zero moment at ``x`` (side coordinates):
        Eqs. (1), (3)–(5), (7), and the reloading branch it starts on."""
        energy = m.work - m.work_exc
        betas = [self.beta(mode, energy, m.work) for mode in ("s", "c", "a")]
        m = m._replace(work_exc=m.work)
        if None in betas:
            return m._replace(dead=1.0)
        beta_s, beta_c, beta_a = (float(b) for b in betas)  # type: ignore[arg-type]
        c = self.sides[d]
        side = deteriorate(self._backbone(m, d), c, self.k0, beta_s, beta_c, rotate_post_cap=False)
        ug = self._peak(m, d, "ug") * (1.0 + beta_a * c.rate)
        bound = side_bound(side, c.fres)
        mg = bound.value(ug)
        ul, ml = self._peak(m, d, "ul"), self._peak(m, d, "ml")
        m = m._replace(side=float(d), **{side_prefix(d) + f: v for f, v in
                                         zip(_PEAK_SIDE, (*side[:4], ul, ml, ug, mg),
                                             strict=True)})
        if mg <= 0.0:
            return m._replace(dead=1.0)
        if ug <= x:  # start beyond the target: up to the backbone along K_u (see the module)
            end = bound.first_hit(x, 0.0, m.k_u)
            return m._replace(code=3.0, k_r=m.k_u, target_u=end, target_m=bound.value(end))
        k_global = mg / (ug - x)
        k_local = ml / (ul - x) if ul > x else -INF
        if ml < mg and k_local > k_global:
            return m._replace(code=2.0, k_r=k_local)
        return m._replace(code=3.0, k_r=k_global, target_u=ug, target_m=mg)


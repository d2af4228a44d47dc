"""Shared parts of the modified Ibarra–Medina–Krawinkler hinge laws (:mod:`pounding.hysteresis.imk`).

* :class:`IMKLaw` — the constants both laws share (backbone of each side, cyclic deterioration
  parameters), checked on construction;
* :class:`Side` and :func:`side_bound` — the current backbone of one side as a piecewise-linear
  function (:class:`Bound`) with exact breakpoints and tangents;
* :func:`cyclic_beta` — the deterioration rate of one excursion, Ibarra et al. (2005) Eq. (1);
* :func:`deteriorate` — the backbone of one side after an excursion, Eqs. (3)–(5).

Sides are written in their own coordinates: rotation and moment multiplied by the side's sign
``s = ±1``, so that both sides read as positive (a slope is the same in both coordinates).
"""

from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import dataclass
from functools import cached_property, lru_cache
from typing import ClassVar, NamedTuple

from pounding.hysteresis.hinges import Branch, HingeLaw, HingeState

INF = math.inf


class Side(NamedTuple):
    """The current backbone of one side, in that side's coordinates."""

    fy: float  #: yield moment M_y,i [N·m]
    kp: float  #: post-yield (hardening) slope K_s,i [N·m/rad], >= 0
    ucap: float  #: capping rotation θ_c,i [rad]
    fcap: float  #: capping moment M_c,i [N·m]
    kpc: float  #: post-capping slope K_pc,i [N·m/rad], <= 0


class SideConstants(NamedTuple):
    """The undeteriorated backbone of one side (the monotonic curve, Lignos & Krawinkler 2011)."""

    fy0: float  #: effective yield moment M_y [N·m]
    kp0: float  #: K_s = (M_c − M_y)/θ_p
    ucap0: float  #: θ_c = θ_y + θ_p
    fcap0: float  #: M_c
    kpc0: float  #: K_pc = −M_c/θ_pc
    fres: float  #: residual moment κ M_y
    uu: float  #: ultimate rotation θ_u (inf: none)
    uy0: float  #: θ_y = M_y/K_e
    rate: float  #: D, rate of cyclic deterioration on this side

    @property
    def initial(self) -> Side:
        return Side(self.fy0, self.kp0, self.ucap0, self.fcap0, self.kpc0)


@dataclass(frozen=True)
class Bound:
    """A continuous piecewise-linear function of the rotation: ``breaks`` ascending,
    ``values`` at them, ``slopes[i]`` on the interval left of ``breaks[i]`` (the last one
    right of the last break). Right-continuous queries, as the hinge contract asks."""

    breaks: tuple[float, ...]
    values: tuple[float, ...]
    slopes: tuple[float, ...]

    @staticmethod
    def constant(value: float) -> Bound:
        return Bound((), (value,), (0.0,))

    def value(self, x: float) -> float:
        if not self.breaks:
            return self.values[0]
        i = bisect_right(self.breaks, x)
        if i == 0:
            return self.values[0] + self.slopes[0] * (x - self.breaks[0])
        if x == self.breaks[i - 1]:
            return self.values[i - 1]
        return self.values[i - 1] + self.slopes[i] * (x - self.breaks[i - 1])

    def slope_after(self, x: float) -> float:
        return self.slopes[bisect_right(self.breaks, x)]

    def next_break(self, x: float) -> float:
        i = bisect_right(self.breaks, x)
        return self.breaks[i] if i < len(self.breaks) else INF

    def first_hit(self, x0: float, m0: float, k: float) -> float:
        """The first rotation ``x >= x0`` where the line ``m0 + k (x − x0)`` reaches the
        bound (``inf``: never)."""
        i = bisect_right(self.breaks, x0)
        x = x0
        while True:
            gap = self.value(x) - (m0 + k * (x - x0))  # > 0: still below
            if gap <= 0.0:
                return x
            end = self.breaks[i] if i < len(self.breaks) else INF
            closing = k - self.slopes[i]
            if closing > 0.0:
                hit = x + gap / closing
                if end < INF and abs(hit - end) <= 1e-12 * max(1.0, abs(end)):
                    return end  # at the breakpoint, up to rounding: exactly there
                if hit < end:
                    return hit
            if end == INF:
                return INF
            x, i = end, i + 1


def side_prefix(s: int) -> str:
    """The prefix of a side's fields in a law's memory."""
    return "pos_" if s > 0 else "neg_"


@lru_cache(maxsize=4096)
def side_bound(side: Side, fres: float) -> Bound:
    """The backbone of one side, ``max(κ M_y, L(θ))``: ``L`` the post-yield line through the
    capping point (slope ``kp``; extended below the yield point, the bilinear law's
    kinematic-hardening line) and then the post-capping line (slope ``kpc``); the residual
    branch ``κ M_y`` below both (Lignos & Krawinkler 2011, Fig. 1)."""
    _, kp, ucap, fcap, kpc = side
    if fcap <= fres:
        return Bound.constant(fres)
    breaks: list[float] = []
    values: list[float] = []
    slopes: list[float] = []
    if kp > 0.0:
        breaks.append(ucap - (fcap - fres) / kp)  # the post-yield line meets the residual
        values.append(fres)
        slopes.append(0.0)
    breaks.append(ucap)
    values.append(fcap)
    slopes.append(kp)
    slopes.append(kpc)
    if kpc < 0.0:
        breaks.append(ucap + (fres - fcap) / kpc)  # start of the residual branch
        values.append(fres)
        slopes.append(0.0)
    return Bound(tuple(breaks), tuple(values), tuple(slopes))


def cyclic_beta(energy: float, remaining: float, reference: float, c: float) -> float | None:
    """Ibarra et al. (2005) Eq. (1): ``β_i = (E_i / (E_t − Σ_{j=1..i} E_j))^c``.

    ``energy`` is ``E_i``, ``remaining`` is ``E_t − Σ_{j<=i} E_j``. A mode whose reference
    energy ``E_t`` is 0 or infinite is off (β = 0, OpenSees' convention for Λ = 0). ``None``
    means complete deterioration: ``β >= 1`` or the energy capacity exhausted
    (``remaining <= 0``; OpenSees instead clamps the negative β to 0 and goes on).
    """
    if reference == 0.0 or reference == INF:
        return 0.0
    if remaining <= 0.0:
        return None
    beta = (max(energy, 0.0) / remaining) ** c
    return None if beta >= 1.0 else beta


def deteriorate(side: Side, constants: SideConstants, k0: float, beta_s: float, beta_c: float,
                rotate_post_cap: bool) -> Side:
    """The backbone of a side after an excursion towards it (Ibarra et al. 2005):

    * Eq. (3), basic strength: ``M_y,i = (1 − β_s,i D) M_y,i−1``; Eq. (4), the post-yield
      slope ``K_s,i = (1 − β_s,i D) K_s,i−1``; the post-yield line passes through the
      deteriorated yield point on the elastic line, ``(M_y,i/K_e, M_y,i)``;
    * Eq. (5), post-capping strength: the reference moment (the post-capping line's value at
      θ = 0) ``M_ref,i = (1 − β_c,i D) M_ref,i−1``; the capping point is where the two lines
      meet. ``D`` is the side's rate (Lignos & Krawinkler 2011).

    With ``rotate_post_cap`` (OpenSees' IMKBilin, not in the papers) the post-capping slope also
    turns with the yield strength, ``K_pc,i = K_pc,0 (M_y,i − M_r)/(M_y,0 − M_r)``; without
    (the papers, OpenSees' IMKPeakOriented) it keeps ``K_pc,0``.
    """
    fy, kp, ucap, fcap, kpc = side
    fres, rate = constants.fres, constants.rate
    reference = fcap - kpc * ucap
    fy *= 1.0 - beta_s * rate
    kp *= 1.0 - beta_s * rate
    reference *= 1.0 - beta_c * rate
    if rotate_post_cap:
        kpc = 0.0 if fy < fres else constants.kpc0 * (fy - fres) / (constants.fy0 - fres)
    yield_line = fy - kp * fy / k0  # the post-yield line's value at θ = 0
    ucap = 0.0 if kp <= kpc else (reference - yield_line) / (kp - kpc)
    fcap = yield_line + kp * ucap
    return Side(fy, kp, ucap, fcap, kpc)


def _number(name: str, value: object, low: float, high: float = INF, *, low_open: bool = True,
           high_open: bool = False, allow_inf: bool = False) -> float:
    """``value`` as a float in the range, or ValueError naming the field and the value."""
    try:
        v = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ValueError(f"{name}: must be a number (got {value!r})") from None
    ok = (not math.isnan(v) and (allow_inf or math.isfinite(v))
          and (v > low if low_open else v >= low) and (v < high if high_open else v <= high))
    if not ok:
        lo = f"{'>' if low_open else '>='} {low:g}"
        hi = "" if high == INF else f" and {'<' if high_open else '<='} {high:g}"
        fin = " (inf allowed)" if allow_inf else ""
        raise ValueError(f"{name}: must be {lo}{hi}{fin} (got {value!r})")
    return v


@dataclass(frozen=True)
class IMKLaw(HingeLaw):
    """Constants of the modified IMK laws (the model: :mod:`pounding.hysteresis.imk`).

    Parameters
    ----------
    k0 : float
        Elastic stiffness K_e [N·m/rad].
    m_y : float
        Effective yield moment M_y of the positive side [N·m].
    theta_p : float
        Pre-capping plastic rotation θ_p [rad]: from yield to the capping point.
    theta_pc : float
        Post-capping rotation θ_pc [rad]: from the capping point to zero moment.
    theta_u : float, default inf
        Ultimate rotation θ_u [rad] (total rotation): the moment drops to 0 there (inf: never).
    mc_my : float, default 1.1
        Capping-to-yield moment ratio M_c/M_y (>= 1; 1.1: Lignos & Krawinkler 2011, beams).
    kappa : float, default 0.4
        Residual strength ratio κ: M_r = κ M_y (0 <= κ < 1).
    m_y_neg, theta_p_neg, theta_pc_neg, theta_u_neg, mc_my_neg, kappa_neg : float, optional
        The same for the negative side, as positive numbers (``None``: as the positive side).
    lambda_ : float, default 0
        Λ [rad] of every cyclic deterioration mode, reference energy E_t = Λ M_y (M_y of the
        positive side, as OpenSees); 0 or inf: no cyclic deterioration.
    lambda_s, lambda_c, lambda_k : float, optional
        Λ of one mode (basic strength, post-capping strength, unloading stiffness); ``None``:
        ``lambda_``. OpenSees' ``Lamda_S``, ``Lamda_C``, ``Lamda_K``.
    c : float, default 1
        Exponent c of every mode (Ibarra et al. 2005, Eq. 1).
    c_s, c_c, c_k : float, optional
        The exponent of one mode; ``None``: ``c``.
    d_pos, d_neg : float, default 1
        Rate D of cyclic deterioration on each side, 0 <= D <= 1 (Lignos & Krawinkler 2011).

    Raises
    ------
    ValueError
        A constant out of its range, in one line naming the field and the value.
    """

    theta_p: float
    theta_pc: float
    theta_u: float = INF
    mc_my: float = 1.1
    kappa: float = 0.4
    m_y_neg: float | None = None
    theta_p_neg: float | None = None
    theta_pc_neg: float | None = None
    theta_u_neg: float | None = None
    mc_my_neg: float | None = None
    kappa_neg: float | None = None
    lambda_: float = 0.0
    lambda_s: float | None = None
    lambda_c: float | None = None
    lambda_k: float | None = None
    c: float = 1.0
    c_s: float | None = None
    c_c: float | None = None
    c_k: float | None = None
    d_pos: float = 1.0
    d_neg: float = 1.0

    _MODES: ClassVar[tuple[str, ...]] = ("s", "c", "k")  # modes (IMKPeakOriented adds "a")

    def _check(self) -> None:
        def number(name: str, low: float = 0.0, high: float = INF, **kw: bool) -> None:
            value = getattr(self, name)
            if value is not None:
                object.__setattr__(self, name, _number(f"{self.label}.{name}", value, low,
                                                       high, **kw))

        for suffix in ("", "_neg"):
            number("theta_p" + suffix)
            number("theta_pc" + suffix)
            number("theta_u" + suffix, allow_inf=True)
            number("mc_my" + suffix, 1.0, low_open=False)
            number("kappa" + suffix, 0.0, 1.0, low_open=False, high_open=True)
        number("m_y_neg")
        for mode in self._MODES:
            number(f"lambda_{mode}", low_open=False, allow_inf=True)
            number(f"c_{mode}")
        number("lambda_", low_open=False, allow_inf=True)
        number("c")
        number("d_pos", 0.0, 1.0, low_open=False)
        number("d_neg", 0.0, 1.0, low_open=False)
        for s, suffix in ((1, ""), (-1, "_neg")):
            side = self.sides[s]
            if side.uu <= side.uy0:
                raise ValueError(f"{self.label}.theta_u{suffix}: must exceed the yield rotation "
                                 f"M_y/k0 = {side.uy0:g} rad (got {side.uu!r})")
            if side.kp0 >= self.k0:
                raise ValueError(f"{self.label}.mc_my{suffix}: the hardening slope (M_c − M_y)/θ_p = "
                                 f"{side.kp0:g} N·m/rad must be below k0 "
                                 f"(got {self._constant('mc_my', suffix)!r})")

    def _constant(self, name: str, suffix: str) -> float:
        value = getattr(self, name + suffix)
        return float(getattr(self, name) if value is None else value)

    @cached_property
    def sides(self) -> dict[int, SideConstants]:
        """The undeteriorated backbone of each side, by its sign (+1, −1)."""
        out = {}
        for s, suffix, rate in ((1, "", self.d_pos), (-1, "_neg", self.d_neg)):
            fy = self.m_y if s > 0 or self.m_y_neg is None else float(self.m_y_neg)
            theta_p = self._constant("theta_p", suffix)
            theta_pc = self._constant("theta_pc", suffix)
            fcap = self._constant("mc_my", suffix) * fy
            uy = fy / self.k0
            out[s] = SideConstants(fy, (fcap - fy) / theta_p, uy + theta_p, fcap,
                                   -fcap / theta_pc, self._constant("kappa", suffix) * fy,
                                   self._constant("theta_u", suffix), uy, float(rate))
        return out

    def reference_energy(self, mode: str) -> float:
        """E_t = Λ M_y [J] of a mode (Lignos & Krawinkler 2011; M_y of the positive side, as
        OpenSees)."""
        lam = getattr(self, f"lambda_{mode}")
        return float(self.lambda_ if lam is None else lam) * self.m_y

    def exponent(self, mode: str) -> float:
        """The exponent c of a mode (Ibarra et al. 2005 Eq. 1)."""
        c = getattr(self, f"c_{mode}")
        return float(self.c if c is None else c)

    def beta(self, mode: str, energy: float, used: float) -> float | None:
        """β of a mode for an excursion dissipating ``energy`` when ``used`` (including it)
        has been dissipated since the start (:func:`cyclic_beta`)."""
        ref = self.reference_energy(mode)
        return cyclic_beta(energy, ref - used, ref, self.exponent(mode))

    # ------------------------------------------------------ the contract, for both laws
    def branch(self, state: HingeState, direction: int) -> Branch:
        k, end, _ = self._plan(self._prepare(state, direction), direction)
        return Branch(k, direction * end)

    def _reversed(self, state: HingeState, direction: int) -> HingeState:
        return self._prepare(state, direction)

    def branches(self, state: HingeState) -> tuple[Branch, Branch, bool]:
        # (each direction prepared once: the branch and the two-way test both need it)
        up_state, down_state = self._prepare(state, 1), self._prepare(state, -1)
        k_up, end_up, _ = self._plan(up_state, 1)
        k_down, end_down, _ = self._plan(down_state, -1)
        two_way = k_up == k_down and up_state == state and down_state == state
        return Branch(k_up, end_up), Branch(k_down, -end_down), two_way

    def _prepare(self, state: HingeState, d: int) -> HingeState:
        """What happens at the state's point when the rotation starts moving in ``d``
        (each law's rules; idempotent)."""
        raise NotImplementedError

    def _plan(self, state: HingeState, d: int) -> tuple[float, float, str]:
        """Tangent, end (side coordinates) and event at the end of the branch from a
        prepared state (each law's rules)."""
        raise NotImplementedError

    def _describe(self) -> str:
        return (f", theta_p={self.theta_p:g} rad, theta_pc={self.theta_pc:g} rad, "
                f"theta_u={self.theta_u:g} rad, mc_my={self.mc_my:g}, kappa={self.kappa:g}, "
                f"lambda={self.lambda_:g} rad, c={self.c:g}")

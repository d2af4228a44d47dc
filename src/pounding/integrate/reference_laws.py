"""The SciPy reference's own force laws: every contact law, storey law and link written out
in plain Python from its published equation and the law object's constants — not the
compiled trials the kernel runs (:mod:`pounding.contact.dispatch`,
:mod:`pounding.hysteresis.dispatch`, :mod:`pounding.devices.laws`), so that a
kernel-versus-reference test checks those too.

Contact laws (δ > 0 the penetration [m], δ̇ its rate [m/s], ``v0`` the closing velocity at
onset; the contract of :mod:`pounding.contact.base`):

* linear spring ``F = k δ``; Kelvin–Voigt ``F = k δ + c δ̇`` (Anagnostopoulos 1988), clipped
  at zero unless it may pull (``tension``); modified Kelvin–Voigt ``k δ + c δ̇`` approaching,
  ``k δ`` separating (Mahmoud & Jankowski 2011);
* Hertz ``k_h δⁿ`` (Davis 1992); Hunt–Crossley ``k_h δⁿ (1 + χ δ̇ / v0)``, clipped at zero
  (Hunt & Crossley 1975); Jankowski's ``k_h δ^1.5 + c δ̇`` approaching, ``k_h δ^1.5``
  separating, ``c = 2 ζ sqrt(k_h sqrt(δ) m_eff)`` (Jankowski 2005, seed eqs 17–18);
* the bilinear impact element (Muthukumar 2003): a spring ``K2`` beside an elastic–
  perfectly-plastic spring of stiffness ``K1 − K2`` and yield force ``(K1 − K2) δy`` whose
  force cannot be negative; its plastic offset is the state carried from one committed
  instant to the next;
* the abutment backfill (Caltrans SDC; Shamsabadi et al. 2007): the force is the least of
  the line ``K (δ − s)`` and the backbone ``min(δ/(1/K + B δ), F_ult)``,
  ``B = 1/F_ult − 1/(K δ_ult)``, and never negative; ``s``, the backfill's permanent set,
  moves to ``δ − F/K`` while the force is on the backbone and, unlike the others' state,
  is kept from one impact to the next (:func:`keeps_set`);
* the shear key (:class:`~pounding.contact.shear_key.ShearKey`): the least of the line
  ``k (δ − s)`` and its capacity ``F_c``, never negative, its set ``s`` moving to
  ``δ − F_c/k`` on the plateau and kept from one impact to the next; where ``δ`` reaches
  its fracture deformation (an event, :func:`fracture_penetration`) it breaks off for good
  (its set ``+∞``: no force, and its gap closing again is no impact).

Storey laws: the bilinear storey in rate form (``V̇ = k ḋ`` elastic, ``b k ḋ`` on the yield
branch, switched at located events) and the Bouc–Wen storey's evolution law (Wen 1976),
each with its own state integrated with the motion. Links: ``F = c |ḋ|^α sgn ḋ``
(viscous), ``k d + c ḋ`` (Kelvin), and ``F = k z`` with ``ż = ḋ − sgn F (|F|/c)^(1/α)``
(Maxwell); a cable restrainer on three branches switched at located events (slack ``F = 0``,
taut ``F = k (d − s₀ − s_p)``, yielding on the bilinear backbone ``F_y + b k (d − s₀ −
F_y/k)``), its plastic elongation ``s_p`` read off the backbone where it unloads
(DesRoches & Fenves 2000), instead of the kernel's plastic elongation integrated with the
motion.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from pounding.contact import (
    AbutmentBackfill,
    BilinearImpact,
    Hertz,
    HuntCrossley,
    KelvinVoigt,
    LinearSpring,
    ModifiedKelvinVoigt,
    NonlinearViscoelastic,
    ShearKey,
)
from pounding.contact.base import ContactLaw
from pounding.devices import Link
from pounding.model import PoundingModel

TINY: float = 1e-300
"""A penetration just above zero [m], where a closed contact is evaluated at δ ≤ 0."""


def contact_force(law: ContactLaw, delta: float, rate: float, v0: float,
                  slip: float) -> tuple[float, float]:
    """Force [N] of a closed contact at ``(δ, δ̇)`` (δ ≤ 0 taken as just above zero), its
    impact's closing velocity ``v0`` [m/s] and the bilinear element's committed plastic
    offset ``slip`` [m]; and that offset after this trial (the others keep 0).

    Raises
    ------
    ValueError
        A law class with no reference here (one line naming it): no other law stands in.
    """
    d = max(delta, TINY)
    if isinstance(law, LinearSpring):
        return law.k * d, slip
    if isinstance(law, KelvinVoigt):
        f = law.k * d + law.c * rate
        return (f if law.tension else max(f, 0.0)), slip
    if isinstance(law, ModifiedKelvinVoigt):
        return law.k * d + (law.c * rate if rate > 0.0 else 0.0), slip
    if isinstance(law, Hertz):
        return law.k_h * d ** law.n, slip
    if isinstance(law, HuntCrossley):
        return max(law.k_h * d ** law.n * (1.0 + law.chi * rate / v0), 0.0), slip
    if isinstance(law, NonlinearViscoelastic):
        elastic = law.k_h * d ** 1.5
        if rate > 0.0:
            return elastic + 2.0 * law.zeta * math.sqrt(law.k_h * math.sqrt(d) * law.m_eff) \
                * rate, slip
        return elastic, slip
    if isinstance(law, BilinearImpact):
        kp = law.K1 - law.K2
        plastic = kp * (d - slip)  # the elasto-plastic spring's trial force
        if plastic > kp * law.delta_y:  # yielding: the offset follows
            return law.K2 * d + kp * law.delta_y, d - law.delta_y
        if plastic < 0.0:  # unloaded past zero force: the offset follows the other way
            return law.K2 * d, d
        return law.K2 * d + plastic, slip
    if isinstance(law, AbutmentBackfill):
        return _backfill(law, d, slip)
    if isinstance(law, ShearKey):
        return _key(law, d, slip)
    raise ValueError(f"reference: no reference force for contact law {type(law).__name__}")


def _backfill(law: AbutmentBackfill, d: float, s: float) -> tuple[float, float]:
    """Force [N] of the abutment backfill at penetration ``d`` [m] with permanent set ``s``
    [m], and the set after it."""
    if d <= s:  # inside the set: the backfill does not pull
        return 0.0, s
    b = 1.0 / law.capacity - 1.0 / (law.K * law.delta_ult)
    envelope = min(d / (1.0 / law.K + max(b, 0.0) * d), law.capacity)
    line = law.K * (d - s)
    if line >= envelope:  # on the backbone: the set grows
        return envelope, d - envelope / law.K
    return line, s


def _key(law: ShearKey, d: float, s: float) -> tuple[float, float]:
    """Force [N] of an intact (``s`` finite) or broken (``s = +∞``) shear key at penetration
    ``d`` [m] with permanent set ``s`` [m], and the set after it."""
    if d <= s:  # inside the set (or broken off): it does not pull
        return 0.0, s
    line = law.k * (d - s)
    if line >= law.capacity:  # on the plateau: the set grows
        return law.capacity, d - law.capacity / law.k
    return line, s


def keeps_set(law: ContactLaw) -> bool:
    """True for a law whose state outlasts its impact (the abutment backfill's set, the
    shear key's set and whether it has broken off)."""
    return isinstance(law, (AbutmentBackfill, ShearKey))


def fracture_penetration(law: ContactLaw) -> float | None:
    """The penetration [m] at which a shear key breaks off (an event of the reference);
    None for a key that never breaks and for every other law."""
    if isinstance(law, ShearKey):
        return law.fracture_displacement
    return None


def stored_energy(law: ContactLaw, delta: float, slip: float) -> float:
    """Elastic energy [J] a closed contact at penetration δ would give back (zero for
    δ ≤ 0): the area under its elastic spring (for the bilinear element, the ``K2`` spring
    and the elastic part of the elasto-plastic one)."""
    if delta <= 0.0:
        return 0.0
    if isinstance(law, (LinearSpring, KelvinVoigt, ModifiedKelvinVoigt)):
        return 0.5 * law.k * delta**2
    if isinstance(law, (Hertz, HuntCrossley)):
        return law.k_h * delta ** (law.n + 1.0) / (law.n + 1.0)
    if isinstance(law, NonlinearViscoelastic):
        return law.k_h * delta**2.5 / 2.5
    if isinstance(law, BilinearImpact):
        kp = law.K1 - law.K2
        plastic = min(max(kp * (delta - slip), 0.0), kp * law.delta_y)
        return 0.5 * law.K2 * delta**2 + 0.5 * plastic**2 / kp
    if isinstance(law, AbutmentBackfill):
        force = _backfill(law, delta, slip)[0]
        return 0.5 * force**2 / law.K  # what unloading along K gives back
    if isinstance(law, ShearKey):
        force = _key(law, delta, slip)[0]
        return 0.5 * force**2 / law.k
    raise ValueError(f"reference: no reference energy for contact law {type(law).__name__}")


def release_function(law: ContactLaw) -> Callable[[float, float], float] | None:
    """For a Kelvin–Voigt law clipped at zero (no tension, a dashpot): ``g(δ, δ̇) = k δ +
    c δ̇``, whose downward zero is where the bodies part with the spring still compressed
    and whose upward zero is where they engage again; None for every other law."""
    if isinstance(law, KelvinVoigt) and not law.tension and law.c > 0.0:
        k, c = law.k, law.c
        return lambda delta, rate: k * delta + c * rate
    return None


class Storey(NamedTuple):
    """A yielding storey as the reference reads it from its building."""

    kind: str  #: "bilinear" or "bouc-wen"
    lower: int  #: global DOF below (−1: the ground)
    upper: int  #: global DOF above
    k: float  #: elastic stiffness [N/m]
    fy: float  #: yield force [N]
    b: float = 0.0  #: bilinear: hardening ratio
    alpha: float = 0.0  #: Bouc–Wen: post-yield ratio
    n: float = 1.0  #: Bouc–Wen: smoothness
    beta: float = 0.5  #: Bouc–Wen: loop shape
    gamma: float = 0.5  #: Bouc–Wen: loop shape
    rock: int = -1  #: global DOF of a rocking footing under the storey (−1: none)
    lever: float = 0.0  #: the storey's height over it [m]: drift less ``lever · φ``


def storey_load(p: NDArray[np.float64], st: Storey, shear: float) -> None:
    """Add a yielding storey's shear ``V`` to the loads ``p`` [N]: ``−V`` on the floor
    above, ``+V`` on the one below, and the moment ``lever · V`` on a rocking footing under
    it (the transpose of its drift)."""
    p[st.upper] -= shear
    if st.lower >= 0:
        p[st.lower] += shear
    if st.rock >= 0:
        p[st.rock] += st.lever * shear


def storeys(model: PoundingModel) -> list[Storey]:
    """The element rows (:attr:`PoundingModel.element_rows`: yielding storeys, a bridge
    frame's piers and bearings), each read from its own law and constants ``[k, F_y, …]``
    (not the kernel arrays): only the elements that follow a law (a base-isolated
    building: its isolation storey); the others are in the linear stiffness matrix."""
    from pounding.hysteresis import Bilinear, BoucWen
    from pounding.hysteresis.base import P_FY, P_K

    out = []
    offsets = model.system.offsets
    for p, row in model.element_rows:
        law = row.law
        lo = int(offsets[p] + row.lower) if row.lower >= 0 else -1
        hi = int(offsets[p] + row.upper)
        rock = int(offsets[p] + row.rock) if row.rock >= 0 else -1
        k, fy = float(row.params[P_K]), float(row.params[P_FY])
        if isinstance(law, Bilinear):
            out.append(Storey("bilinear", lo, hi, k, fy, b=law.hardening, rock=rock,
                              lever=float(row.lever)))
        elif isinstance(law, BoucWen):
            out.append(Storey("bouc-wen", lo, hi, k, fy, alpha=law.alpha, n=law.n,
                              beta=law.beta, gamma=law.gamma, rock=rock,
                              lever=float(row.lever)))
        else:
            raise ValueError(f"reference: no reference for storey law {law!r}")
    return out


def storey_shear(st: Storey, drift: float, rate: float, h: float,
                 yielding: int) -> tuple[float, float]:
    """Shear [N] of a yielding storey at drift ``d`` and rate ``ḋ`` with its state ``h`` (the
    bilinear storey's shear itself, in rate form; Bouc–Wen's ``z``), and the rate of ``h``.
    ``yielding``: the bilinear storey's branch (0 elastic, ±1 yielding)."""
    if st.kind == "bilinear":
        return h, (st.b * st.k if yielding else st.k) * rate
    # Wen (1976): d_y ż = A ḋ − β |ḋ| |z|^(n−1) z − γ ḋ |z|^n, A = 1, d_y = F_y / k
    hdot = (rate - st.beta * abs(rate) * abs(h) ** (st.n - 1.0) * h
            - st.gamma * rate * abs(h) ** st.n) / (st.fy / st.k)
    return st.alpha * st.k * drift + (1.0 - st.alpha) * st.fy * h, hdot


def storey_recoverable(st: Storey, drift: np.ndarray, h: np.ndarray) -> np.ndarray:
    """Elastic energy [J] a yielding storey gives back: ``V²/(2k)`` bilinear; the two
    springs ``½ α k d² + ½ (1 − α) F_y d_y z²`` of Bouc–Wen."""
    if st.kind == "bilinear":
        return h**2 / (2.0 * st.k)
    return 0.5 * st.alpha * st.k * drift**2 + 0.5 * (1.0 - st.alpha) * st.fy**2 / st.k * h**2


def spring_stiffness(link: Link) -> float:
    """Stiffness ``k`` [N/m] of a kelvin or maxwell link's spring (:class:`Link` requires
    one for those kinds)."""
    if link.k is None:
        raise ValueError(f"reference: the {link.kind} link {link.name} has no spring "
                         "stiffness k")
    return float(link.k)


def dashpot_coefficient(link: Link) -> float:
    """Coefficient ``c`` of a link's dashpot (:class:`Link` requires one but for a
    restrainer)."""
    if link.c is None:
        raise ValueError(f"reference: the {link.kind} link {link.name} has no dashpot c")
    return float(link.c)


def link_force(link: Link, d: float, rate: float, z: float) -> float:
    """Force [N] of a link at relative displacement ``d`` [m] and rate ``ḋ`` [m/s] (a
    Maxwell link: at its spring's deformation ``z`` [m])."""
    if link.kind == "viscous":
        return math.copysign(dashpot_coefficient(link) * abs(rate) ** link.alpha, rate) if rate != 0.0 else 0.0
    if link.kind == "kelvin":
        return spring_stiffness(link) * d + dashpot_coefficient(link) * rate
    if link.kind == "maxwell":
        return spring_stiffness(link) * z
    if link.kind == "restrainer":
        raise ValueError("reference: a restrainer's force depends on its branch "
                         "(restrainer_force)")
    raise ValueError(f"reference: no reference for link kind {link.kind!r}")


RESTRAINER_SLACK, RESTRAINER_TAUT, RESTRAINER_YIELDING = 0, 1, 2
"""The reference's branches of a cable restrainer."""


def restrainer_force(link: Link, d: float, plastic: float, branch: int) -> float:
    """Force [N] of a cable restrainer at opening ``d`` [m] on ``branch``: 0 slack; taut
    ``k (d − slack − s_p)`` (``plastic``: its plastic elongation ``s_p`` [m]); yielding,
    the bilinear backbone ``F_y + b k (d − slack − F_y/k)``."""
    k = spring_stiffness(link)
    slack = float(link.slack)  # type: ignore[arg-type]
    if branch == RESTRAINER_SLACK:
        return 0.0
    if branch == RESTRAINER_TAUT:
        return k * (d - slack - plastic)
    fy = float(link.yield_force)  # type: ignore[arg-type]
    return fy + link.hardening * k * (d - slack - fy / k)


def restrainer_switches(link: Link, d: float, plastic: float, branch: int
                        ) -> list[tuple[int, float, int]]:
    """The restrainer's ways off ``branch`` at opening ``d``: ``(branch after, value,
    direction)`` with ``value`` the event function [N] (its zero the switch) crossing in
    ``direction``:
    slack → taut where ``k (d − slack − s_p)`` turns positive; taut → slack where it turns
    back, taut → yielding where it reaches the backbone (the rate-driven way off the yield
    branch, the opening's rate turning negative, is the caller's)."""
    k = spring_stiffness(link)
    elastic = k * (d - float(link.slack) - plastic)  # type: ignore[arg-type]
    if branch == RESTRAINER_SLACK:
        return [(RESTRAINER_TAUT, elastic, 1)]
    out = [(RESTRAINER_SLACK, elastic, -1)]
    if branch == RESTRAINER_TAUT and link.yield_force is not None:
        out.append((RESTRAINER_YIELDING, elastic - restrainer_force(link, d, plastic, RESTRAINER_YIELDING),
                    1))
    return out


def maxwell_spring_rate(link: Link, rate: float, z: float) -> float:
    """``ż`` [m/s] of a Maxwell link: the relative velocity less the dashpot's,
    ``sgn F (|F|/c)^(1/α)`` with ``F = k z``."""
    f = spring_stiffness(link) * z
    return rate - math.copysign((abs(f) / dashpot_coefficient(link)) ** (1.0 / link.alpha), f)


def link_recoverable(link: Link, d: np.ndarray, z: np.ndarray) -> np.ndarray:
    """Elastic energy [J] of a link's spring: ``½ k d²`` (Kelvin), ``½ k z²`` (Maxwell); a
    restrainer's ``F²/(2k)`` is the caller's (from its force on its branch)."""
    if link.kind == "kelvin":
        return 0.5 * spring_stiffness(link) * d**2
    if link.kind == "maxwell":
        return 0.5 * spring_stiffness(link) * z**2
    return np.zeros_like(d)

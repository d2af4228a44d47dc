"""A rigid surface footing on a half-space: its sway and rocking springs and dashpots.

A footing here is rigid, bonded to the surface of a homogeneous elastic half-space
(:class:`~pounding.structure.foundation.soil.Soil`, shear modulus ``G``, Poisson's ratio
``ν``), and moves in the plane of the row: sway ``u_f`` along the row and rocking ``φ`` about
the horizontal axis across it. Its soil is replaced by frequency-independent springs and
dashpots (a lumped-parameter model).

Springs: the static stiffnesses
  * circle of radius ``R`` (the elastic half-space solutions; Gazetas 1991, "Foundation
    vibrations", ch. 15 of *Foundation Engineering Handbook*, 2nd ed., Table 15-1)::

        k_x = 8 G R / (2 − ν),        k_φ = 8 G R³ / (3 (1 − ν));

  * rectangle ``2L × 2B`` (``L ≥ B``, ``x`` along ``L``): Pais & Kausel (1988), "Approximate
    formulas for dynamic stiffnesses of rigid foundations", Soil Dyn. Earthq. Eng. 7(4),
    as tabulated in NIST GCR 12-917-21 (2012), *Soil-Structure Interaction for Building
    Structures*, Table 2-2a::

        k_x  = G B / (2 − ν) [6.8 (L/B)^0.65 + 2.4]              (sway along L)
        k_y  = G B / (2 − ν) [6.8 (L/B)^0.65 + 0.8 L/B + 1.6]    (sway along B)
        k_yy = G B³ / (1 − ν) [3.73 (L/B)^2.4 + 0.27]           (rocking under sway along L)
        k_xx = G B³ / (1 − ν) [3.2 L/B + 0.8]                   (rocking under sway along B)

    (a square gives ``k_x = k_y`` and ``k_xx = k_yy``, and within 2 % the circle of the same
    area or moment of inertia; a long footing sways more easily along its length than
    across, as Gazetas' formulas have it too).

Dashpots: the cone models of Wolf (1994), *Foundation Vibration Analysis Using Simple
Physical Models*, Prentice Hall, §2 (a disk of radius ``r0``; a rectangle takes the disk of
the same area for sway and of the same moment of inertia ``I`` for rocking):

  * sway: a cone of apex height ``z0 = (π/8)(2 − ν) r0`` carrying shear waves (``V_s``):
    its stiffness is ``k_x`` above and its dashpot ``c_x = ρ V_s A``, independent of the
    frequency;
  * rocking: a cone of apex height ``z0 = (9π/32)(1 − ν) r0 (c/V_s)²`` carrying waves of
    velocity ``c = V_p`` (``ν ≤ 1/3``) or ``2 V_s`` (``1/3 < ν < 1/2``), whose dynamic stiffness
    is ``S(ω) = k_φ [1 − ⅓ b0²/(1 + b0²) + i ⅓ b0³/(1 + b0²)]``, ``b0 = ω z0 / c``: a dashpot
    ``c_φ(ω) = Im S / ω = ρ c I b0²/(1 + b0²)``, small at low frequency (a rocking footing
    radiates little there), ``ρ c I`` at high frequency.

A frequency-independent model takes the rocking dashpot at one frequency ``ω`` — the
flexible-base building's first mode (:mod:`pounding.structure.foundation.flexible_base`) —
and keeps the static springs (the issue's and practice's choice: NIST GCR 12-917-21 §2.2;
the cone's rocking spring would soften by ``⅓ b0²/(1 + b0²)``, 1.3 % at ``b0`` = 0.2). The
soil's own (material) damping ``β`` (EN 1998-5 Table 4.1,
:class:`~pounding.structure.foundation.soil.Soil`) adds ``2 β k / ω`` to each dashpot (a
hysteretic loss taken as viscous at ``ω``). Not modelled: embedment, layering over bedrock,
the trapped soil mass of Wolf's rocking cone for ``ν > 1/3``, the coupling of sway and
rocking (zero for a surface footing), and any coupling through the soil between adjacent
footings.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from pounding.structure.foundation.soil import Soil
from pounding.validation import non_negative, positive

__all__ = ["Footing", "Impedance", "footing_dashpots", "footing_stiffness"]


@dataclass(frozen=True)
class Footing:
    """A rigid surface footing (module docstring): a circle (``radius``) or a rectangle
    (``length`` along the row, ``width`` across it), with its mass and rocking inertia.

    Parameters
    ----------
    radius : float, optional
        Radius of a circular footing [m].
    length, width : float, optional
        Plan dimensions of a rectangular footing [m]: along the row (the direction of
        shaking) and across it.
    mass : float
        The footing's mass [kg] (0: massless, condensed out of the building's matrices).
    inertia : float
        Its mass moment of inertia about the rocking axis [kg·m²] (0: none).
    dashpots : bool
        Whether the soil's dashpots act (False: springs only).

    Examples
    --------
    >>> Footing(radius=5.0).area, round(Footing(radius=5.0).rocking_moment, 2)
    (78.53981633974483, 490.87)
    """

    radius: float | None = None
    length: float | None = None
    width: float | None = None
    mass: float = 0.0
    inertia: float = 0.0
    dashpots: bool = True

    def __post_init__(self) -> None:
        if self.radius is not None:
            positive("foundation.radius [m]", self.radius)
            if self.length is not None or self.width is not None:
                raise ValueError("foundation: give radius (a circle) or length and width (a "
                                 f"rectangle), not both (got radius = {self.radius:g} m)")
        else:
            if self.length is None or self.width is None:
                raise ValueError("foundation: give radius [m] (a circle) or length and width "
                                 "[m] (a rectangle: along the row and across it)")
            positive("foundation.length [m]", self.length)
            positive("foundation.width [m]", self.width)
        non_negative("foundation.mass [kg]", self.mass)
        non_negative("foundation.inertia [kg·m²]", self.inertia)

    @property
    def area(self) -> float:
        """Plan area ``A`` [m²]."""
        if self.radius is not None:
            return math.pi * self.radius ** 2
        return float(self.length) * float(self.width)  # type: ignore[arg-type]

    @property
    def rocking_moment(self) -> float:
        """Second moment of the plan area about the rocking axis ``I`` [m⁴] (across the
        row, through the centre): ``π R⁴/4``, or ``width · length³/12``."""
        if self.radius is not None:
            return math.pi * self.radius ** 4 / 4.0
        return float(self.width) * float(self.length) ** 3 / 12.0  # type: ignore[arg-type]


@dataclass(frozen=True)
class Impedance:
    """A footing's frequency-independent springs and dashpots (module docstring)."""

    k_x: float  #: sway spring [N/m]
    k_r: float  #: rocking spring [N·m/rad]
    c_x: float  #: sway dashpot [N·s/m]
    c_r: float  #: rocking dashpot [N·m·s/rad]
    omega: float  #: the circular frequency the dashpots were taken at [rad/s]


def footing_stiffness(footing: Footing, soil: Soil) -> tuple[float, float]:
    """The static sway and rocking springs ``(k_x [N/m], k_φ [N·m/rad])`` of ``footing`` on
    ``soil`` (module docstring: the circle's closed forms, Pais & Kausel's rectangle).

    Examples
    --------
    >>> k_x, k_r = footing_stiffness(Footing(radius=5.0), Soil(150.0, 1800.0, 0.33))
    >>> round(k_x / 1e6, 3), round(k_r / 1e9, 4)    # 8GR/(2−ν), 8GR³/(3(1−ν))
    (970.06, 20.1493)
    """
    G, nu = soil.shear_modulus, soil.poisson
    if footing.radius is not None:
        R = footing.radius
        return 8.0 * G * R / (2.0 - nu), 8.0 * G * R ** 3 / (3.0 * (1.0 - nu))
    along = 0.5 * float(footing.length)  # type: ignore[arg-type]
    across = 0.5 * float(footing.width)  # type: ignore[arg-type]
    L, B = max(along, across), min(along, across)
    a = L / B
    if along >= across:  # sway along L, rocking about the short axis (y)
        k_x = G * B / (2.0 - nu) * (6.8 * a ** 0.65 + 2.4)
        k_r = G * B ** 3 / (1.0 - nu) * (3.73 * a ** 2.4 + 0.27)
    else:  # sway along B, rocking about the long axis (x)
        k_x = G * B / (2.0 - nu) * (6.8 * a ** 0.65 + 0.8 * a + 1.6)
        k_r = G * B ** 3 / (1.0 - nu) * (3.2 * a + 0.8)
    return k_x, k_r


def rocking_wave_velocity(soil: Soil) -> float:
    """The velocity of the rocking cone's waves [m/s]: ``V_p`` for ``ν ≤ 1/3``, else
    ``2 V_s`` (Wolf 1994)."""
    return soil.vp if soil.poisson <= 1.0 / 3.0 else 2.0 * soil.vs


def footing_dashpots(footing: Footing, soil: Soil, omega: float) -> tuple[float, float]:
    """The sway and rocking dashpots ``(c_x [N·s/m], c_φ [N·m·s/rad])`` of ``footing`` on
    ``soil`` at circular frequency ``omega`` [rad/s]: the cones' radiation dashpots plus the
    soil's material damping ``2 β k / ω`` (module docstring); zero if
    ``footing.dashpots`` is False.

    Examples
    --------
    >>> c_x, c_r = footing_dashpots(Footing(radius=5.0), Soil(150.0, 1800.0, 0.33), 9.0)
    >>> round(c_x / 1e6, 3)                              # ρ V_s A
    21.206
    """
    positive("omega [rad/s]", omega)
    if not footing.dashpots:
        return 0.0, 0.0
    rho, vs = soil.density, soil.vs
    A, I_b = footing.area, footing.rocking_moment
    c = rocking_wave_velocity(soil)
    r0 = (4.0 * I_b / math.pi) ** 0.25  # the disk of the same moment of inertia
    z0 = 9.0 * math.pi / 32.0 * (1.0 - soil.poisson) * r0 * (c / vs) ** 2
    b0 = omega * z0 / c
    c_x = rho * vs * A
    c_r = rho * c * I_b * b0 ** 2 / (1.0 + b0 ** 2)
    k_x, k_r = footing_stiffness(footing, soil)
    beta = soil.damping_ratio
    return c_x + 2.0 * beta * k_x / omega, c_r + 2.0 * beta * k_r / omega


def footing_torsion(footing: Footing, soil: Soil, omega: float) -> tuple[float, float]:
    """The torsion spring and dashpot ``(k_t [N·m/rad], c_t [N·m·s/rad])`` of ``footing``
    on ``soil`` about the vertical axis through its centre, the dashpot at circular
    frequency ``omega`` [rad/s] (zero if ``footing.dashpots`` is False).

    Spring, the static stiffness:

    * circle of radius ``R``: ``k_t = 16 G R³ / 3`` (the elastic half-space solution;
      Gazetas 1991, Table 15-1; Richart, Hall & Woods 1970, ch. 10; Luco 1976:
      ``5.33 G R³``);
    * rectangle ``2L × 2B`` (``L ≥ B``, either along the row): Pais & Kausel (1988) as
      tabulated in NIST GCR 12-917-21 (2012) Table 2-2a,
      ``k_t = G B³ [4.25 (L/B)^2.45 + 4.06]`` (a square: ``8.31 G B³``, 4.8 % stiffer than
      the disk of the same polar moment of area).

    Dashpot: Wolf's (1994) torsional cone, a disk of the footing's polar moment of area
    ``J`` (``r0 = (2J/π)^¼``) on a cone of apex height ``z0 = (9π/32) r0`` carrying shear
    waves (``V_s``). The twist ``ϑ(z)`` of the cone's disk at distance ``z`` from the apex,
    whose polar moment is ``J (z/z0)⁴``, obeys ``ϑ'' + (4/z) ϑ' + (ω/V_s)² ϑ = 0`` — the
    rocking cone's equation with ``V_s`` for ``c`` — and the outgoing wave gives the
    dynamic stiffness ``S(ω) = −G J ϑ'(z0)/ϑ(z0) = k_c [1 − ⅓ b0²/(1 + b0²) + i ⅓ b0³/(1 +
    b0²)]``, ``k_c = 3 G J/z0`` (``= 16 G r0³/3``, the disk's exact static value), ``b0 = ω z0/V_s``;
    its imaginary part over ω is the dashpot

        c_t(ω) = ρ V_s J b0² / (1 + b0²),

    plus the soil's material damping ``2 β k_t / ω`` as for the other dashpots.

    Examples
    --------
    >>> k_t, c_t = footing_torsion(Footing(radius=5.0), Soil(150.0, 1800.0, 0.33), 9.0)
    >>> round(k_t / 1e9, 3)                          # 16 G R³ / 3
    27.0
    """
    positive("omega [rad/s]", omega)
    G, rho, vs = soil.shear_modulus, soil.density, soil.vs
    if footing.radius is not None:
        R = footing.radius
        k_t = 16.0 * G * R ** 3 / 3.0
        J = math.pi * R ** 4 / 2.0
    else:
        a, b = float(footing.length), float(footing.width)  # type: ignore[arg-type]
        L, B = 0.5 * max(a, b), 0.5 * min(a, b)
        k_t = G * B ** 3 * (4.25 * (L / B) ** 2.45 + 4.06)
        J = a * b * (a * a + b * b) / 12.0
    if not footing.dashpots:
        return k_t, 0.0
    r0 = (2.0 * J / math.pi) ** 0.25
    b0 = omega * (9.0 * math.pi / 32.0) * r0 / vs
    c_t = rho * vs * J * b0 ** 2 / (1.0 + b0 ** 2)
    return k_t, c_t + 2.0 * soil.damping_ratio * k_t / omega

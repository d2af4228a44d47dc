"""A rigid footing on or embedded in a half-space: its sway and rocking springs and dashpots.

A footing here is rigid, bonded to a homogeneous elastic half-space
(:class:`~pounding.structure.foundation.soil.Soil`, shear modulus ``G``, Poisson's ratio
``ν``) on its base and, if embedded to a depth ``D``, on its sidewalls over that depth, and
moves in the plane of the row: sway ``u_f`` along the row and rocking ``φ`` about the
horizontal axis across it, both taken at the centre of its base (the level the building's
elevations are measured from). Its soil is replaced by frequency-independent springs and
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

Embedment (:func:`embedment_factors`): an embedded footing's springs are the surface
footing's times the factors ``η`` of Pais & Kausel (1988), NIST GCR 12-917-21 Table 2-2b
(``D`` the embedment, sidewalls in contact with the soil over all of it)::

        η_x = η_y = 1 + (0.33 + 1.34 / (1 + L/B)) (D/B)^0.8       (sway, either way)
        η_yy = 1 + D/B + 1.6 / (0.35 + (L/B)⁴) (D/B)²             (rocking under sway along L)
        η_xx = 1 + D/B + 1.6 / (0.35 + L/B) (D/B)²                (rocking under sway along B)
        η_zz = 1 + (1.3 + 1.32 / (L/B)) (D/B)^0.9                 (torsion,
                                                      :func:`torsion_embedment_factor`)

  read here in three independent transcriptions that agree term by term (the open-source
  ``geofound`` (eng-tools) ``stiffness/pais_1988.py``; an ASCE 7-16 §19.3 SSI script that
  implements them with the full width; and a verification catalogue quoting NIST Table
  2-2b); NIST itself could not be opened here. A circle takes them with ``L/B = 1`` for the
  square of the same area (sway, ``B = R √π / 2``) or moment of inertia (rocking and torsion,
  ``B = R (3π/16)^¼``); those agree with Gazetas' (1991) own embedded-circle factors (the
  other column of NIST Table 2-2b) within 1 % in sway for ``D/R ≤ 1.75`` and 5 % in rocking
  for ``D/R ≤ 1`` (9.4 % at 1.75) (``tests/structure/test_embedment.py``). For rectangles the two sets of fits
  differ more (Gazetas' sway 10 % stiffer for a square at ``D/B = 1``): that spread is the
  formulas' uncertainty. The range of ``D/B`` Pais & Kausel fitted could not be read from
  the primary source here; pounding takes ``D ≤ 2B`` (no deeper than the footing is wide,
  for a circle the width of its equal-inertia square, ``1.75 R``) and refuses more.
  Not modelled: a sidewall in contact over only part of ``D`` (Pais & Kausel's factors have
  no contact height; Gazetas' have one); the sway–rocking coupling of an embedded footing
  (NIST Table 2-2b prints ``k_xφ ≈ (D/3) k_x,emb``, whose sign convention could not be
  checked here): ``docs/ground.md`` gives its size for the worked example.

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

An embedded footing's sidewalls add their own radiation (:func:`sidewall_dashpots`): a wall
moving normal to itself radiates at ``ψ V_s`` (``ψ = √(2(1 − ν)/(1 − 2ν)) ≤ 2.5``), one moving
in its plane at ``V_s``, per unit area and velocity — the sidewall terms of NIST GCR 12-917-21
Table 2-3b (Pais & Kausel 1988), which for a cylinder are the high-frequency limits of Luco
et al. (1978), quoted in the test. Sway: ``c_x,wall = ρ V_s (ψ A_⊥ + A_∥)``, ``A_⊥`` the walls
across the row (normal to the motion), ``A_∥`` those along it — NIST's embedded sway dashpot
exactly, less its base term ``ρ V_s A``, which is the sway cone's. Rocking: the walls' horizontal
motion ``z φ`` (``0 ≤ z ≤ D``) gives ``ρ V_s (ψ A_⊥ + A_∥) D²/3`` at every frequency (NIST's
frequency-independent sidewall term), their vertical motion ``x φ`` gives
``ρ V_s D ∮ x² ds`` (``x`` along the row, the integral round the footing's outline) times the
base cone's ``b0²/(1 + b0²)`` (NIST gives these terms its own fitted frequency factor, which
pounding replaces by the cone's, as it does for the base; NIST's bracket also repeats the
``(D/B)³`` terms, which the two transcriptions read here give differently, so pounding does
not).

A frequency-independent model takes the rocking dashpot at one frequency ``ω`` — the
flexible-base building's first mode (:mod:`pounding.structure.foundation.flexible_base`) —
and keeps the static springs (the issue's and practice's choice: NIST GCR 12-917-21 §2.2;
the cone's rocking spring would soften by ``⅓ b0²/(1 + b0²)``, 1.3 % at ``b0`` = 0.2). The
soil's own (material) damping ``β`` (EN 1998-5 Table 4.1,
:class:`~pounding.structure.foundation.soil.Soil`) adds ``2 β k / ω`` to each dashpot (a
hysteretic loss taken as viscous at ``ω``). Not modelled: layering over bedrock, the trapped
soil mass of Wolf's rocking cone for ``ν > 1/3``, the coupling of sway and rocking (zero for a
surface footing; see Embedment for an embedded one), and any coupling through the soil
between adjacent footings.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from pounding.structure.foundation.soil import Soil
from pounding.validation import non_negative, positive

__all__ = ["Footing", "Impedance", "embedment_factors", "footing_dashpots", "footing_stiffness",
           "max_embedment", "sidewall_dashpots", "torsion_embedment_factor"]

MAX_EMBEDMENT_RATIO = 2.0
"""The deepest embedment taken, ``D/B`` (module docstring: pounding's bound)."""


@dataclass(frozen=True)
class Footing:
    """A rigid footing (module docstring): a circle (``radius``) or a rectangle (``length``
    along the row, ``width`` across it), on the surface or embedded, with its mass and
    rocking inertia.

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
    embedment : float
        Depth of its base below the ground surface ``D`` [m], its sidewalls in contact
        with the soil over all of it (0: a surface footing); at most
        :func:`max_embedment`.

    Examples
    --------
    >>> Footing(radius=5.0).area, round(Footing(radius=5.0).rocking_moment, 2)
    (78.53981633974483, 490.87)
    >>> Footing(length=10.0, width=6.0, embedment=2.0).embedment
    2.0
    """

    radius: float | None = None
    length: float | None = None
    width: float | None = None
    mass: float = 0.0
    inertia: float = 0.0
    dashpots: bool = True
    embedment: float = 0.0

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
        non_negative("foundation.embedment [m]", self.embedment)
        deepest = max_embedment(self.radius, self.length, self.width)
        if self.embedment > deepest:
            raise ValueError("foundation.embedment "
                             + embedment_message(self.embedment, deepest))

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


def max_embedment(radius: float | None, length: float | None = None,
                  width: float | None = None) -> float:
    """The deepest embedment taken [m]: ``D ≤ 2B``, the footing's smaller plan dimension,
    for a circle the side of its square of the same moment of inertia
    (``2 (3π/16)^¼ R = 1.75 R``) (module docstring)."""
    if radius is not None:
        return MAX_EMBEDMENT_RATIO * _rocking_square_half(radius)
    return MAX_EMBEDMENT_RATIO * 0.5 * min(float(length), float(width))  # type: ignore[arg-type]


def embedment_message(embedment: float, deepest: float) -> str:
    """Why an embedment deeper than :func:`max_embedment` is refused (one line, after the
    field's name)."""
    return (f"must be <= {deepest:g} m, the footing's width (for a "
            "circle, of the square of the same moment of inertia, 1.75 R): Pais & Kausel's "
            f"embedment factors are taken up to D/B = 2 (got {embedment:g} m)")


def _area_square_half(radius: float) -> float:
    """Half-side of the square of the area of a disk of ``radius``."""
    return 0.5 * math.sqrt(math.pi) * radius


def _rocking_square_half(radius: float) -> float:
    """Half-side of the square of the moment of inertia (and polar moment) of the disk."""
    return (3.0 * math.pi / 16.0) ** 0.25 * radius


def _half_sides(footing: Footing, rocking: bool) -> tuple[float, float, bool]:
    """``(L, B, along)``: the half-sides Pais & Kausel's formulas take (``L ≥ B``; a circle's
    equivalent square for sway or for rocking) and whether the row runs along ``L``."""
    if footing.radius is not None:
        half = (_rocking_square_half if rocking else _area_square_half)(footing.radius)
        return half, half, True
    along = 0.5 * float(footing.length)  # type: ignore[arg-type]
    across = 0.5 * float(footing.width)  # type: ignore[arg-type]
    return max(along, across), min(along, across), along >= across


def embedment_factors(footing: Footing) -> tuple[float, float]:
    """The factors ``(η_x, η_φ)`` that take the surface footing's sway and rocking springs to
    the embedded footing's (Pais & Kausel 1988, NIST GCR 12-917-21 Table 2-2b; module
    docstring); ``(1, 1)`` at the surface.

    Examples
    --------
    A square 2B = 8 m embedded D = 2 m (D/B = 0.5):

    >>> [round(f, 4) for f in embedment_factors(Footing(length=8.0, width=8.0, embedment=2.0))]
    [1.5743, 1.7963]
    """
    D = footing.embedment
    L, B, along = _half_sides(footing, rocking=False)
    ratio, depth = L / B, D / B
    sway = 1.0 + (0.33 + 1.34 / (1.0 + ratio)) * depth ** 0.8
    L, B, along = _half_sides(footing, rocking=True)
    ratio, depth = L / B, D / B
    shape = ratio ** 4 if along else ratio  # rocking under sway along L (η_yy) or B (η_xx)
    rocking = 1.0 + depth + 1.6 / (0.35 + shape) * depth ** 2
    return sway, rocking


def torsion_embedment_factor(footing: Footing) -> float:
    """The factor ``η_zz = 1 + (1.3 + 1.32/(L/B)) (D/B)^0.9`` that takes the surface footing's
    torsional spring to the embedded footing's (Pais & Kausel 1988, NIST GCR 12-917-21
    Table 2-2b; a circle takes the square of the same polar moment of inertia).

    Examples
    --------
    >>> round(torsion_embedment_factor(Footing(length=8.0, width=8.0, embedment=2.0)), 4)
    2.404
    """
    L, B, _ = _half_sides(footing, rocking=True)
    return 1.0 + (1.3 + 1.32 / (L / B)) * (footing.embedment / B) ** 0.9


def sidewall_wave_ratio(soil: Soil) -> float:
    """``ψ = √(2(1 − ν)/(1 − 2ν))`` capped at 2.5 (``V_p/V_s`` so capped): the velocity, in
    ``V_s``, at which a sidewall moving normal to itself radiates (NIST GCR 12-917-21
    Table 2-3a/b)."""
    nu = soil.poisson
    return min(math.sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu)), 2.5)


def sidewall_dashpots(footing: Footing, soil: Soil) -> tuple[float, float, float]:
    """The sidewalls' radiation dashpots of an embedded footing (module docstring):
    ``(c_x [N·s/m], c_φ,h [N·m·s/rad], c_φ,v [N·m·s/rad])`` — sway, the rocking walls'
    horizontal motion (at every frequency) and their vertical motion (to be taken times the
    base cone's ``b0²/(1 + b0²)``); zeros at the surface.

    Examples
    --------
    A cylinder R = 1 m, D = 0.5 m, ρ V_s = 1, ν = 1/4 (ψ = √3): π D (1 + √3) R, π (1 + √3) R
    D³/3 and π R³ D:

    >>> [round(c, 4) for c in sidewall_dashpots(Footing(radius=1.0, embedment=0.5),
    ...                                         Soil(1.0, 1.0, 0.25))]
    [4.2915, 0.3576, 1.5708]
    """
    D = footing.embedment
    impedance = soil.density * soil.vs
    psi = sidewall_wave_ratio(soil)
    if footing.radius is not None:
        R = footing.radius
        across_walls = along_walls = math.pi * R * D  # ∮ cos²θ ds D = ∮ sin²θ ds D
        outline_moment = math.pi * R ** 3  # ∮ x² ds
    else:
        along, across = float(footing.length), float(footing.width)  # type: ignore[arg-type]
        across_walls = 2.0 * across * D
        along_walls = 2.0 * along * D
        outline_moment = 2.0 * across * (0.5 * along) ** 2 + 2.0 * along ** 3 / 12.0
    walls = impedance * (psi * across_walls + along_walls)
    return walls, walls * D ** 2 / 3.0, impedance * D * outline_moment


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
    ``soil`` (module docstring: the circle's closed forms, Pais & Kausel's rectangle, times
    the embedment factors of :func:`embedment_factors`).

    Examples
    --------
    >>> k_x, k_r = footing_stiffness(Footing(radius=5.0), Soil(150.0, 1800.0, 0.33))
    >>> round(k_x / 1e6, 3), round(k_r / 1e9, 4)    # 8GR/(2−ν), 8GR³/(3(1−ν))
    (970.06, 20.1493)
    """
    k_x, k_r = surface_stiffness(footing, soil)
    if footing.embedment == 0.0:
        return k_x, k_r
    eta_x, eta_r = embedment_factors(footing)
    return eta_x * k_x, eta_r * k_r


def surface_stiffness(footing: Footing, soil: Soil) -> tuple[float, float]:
    """The static springs of ``footing`` were it on the surface (its embedment ignored)."""
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
    ``soil`` at circular frequency ``omega`` [rad/s]: the cones' radiation dashpots, an
    embedded footing's sidewalls' (:func:`sidewall_dashpots`), plus the soil's material
    damping ``2 β k / ω`` (module docstring); zero if ``footing.dashpots`` is False.

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
    if footing.embedment > 0.0:
        wall_x, wall_h, wall_v = sidewall_dashpots(footing, soil)
        c_x, c_r = c_x + wall_x, c_r + wall_h + wall_v * b0 ** 2 / (1.0 + b0 ** 2)
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

    An embedded footing's spring is the surface one times :func:`torsion_embedment_factor`
    (Pais & Kausel 1988, NIST GCR 12-917-21 Table 2-2b); its dashpot stays the base's cone
    (the sidewalls' torsional radiation is not added: no formula for it was verified).

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
    if footing.embedment > 0.0:
        k_t *= torsion_embedment_factor(footing)
    if not footing.dashpots:
        return k_t, 0.0
    r0 = (2.0 * J / math.pi) ** 0.25
    b0 = omega * (9.0 * math.pi / 32.0) * r0 / vs
    c_t = rho * vs * J * b0 ** 2 / (1.0 + b0 ** 2)
    return k_t, c_t + 2.0 * soil.damping_ratio * k_t / omega

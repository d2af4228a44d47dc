"""The soil under a foundation: a homogeneous elastic half-space, and its strain-compatible
properties for a level of shaking.

A half-space is given by its small-strain shear-wave velocity ``V_s0`` [m/s], its density
``ρ`` [kg/m³] and Poisson's ratio ``ν`` [-]; its small-strain shear modulus is
``G_0 = ρ V_s0²`` [Pa]. Under strong shaking the soil softens and dissipates: EN 1998-5:2004
§4.2.3 and Table 4.1 give, for the design ground acceleration ratio ``α S`` (``α = a_g/g``
and ``S`` the soil factor), the average reduction of the shear-wave velocity and of the shear
modulus within 20 m depth, and the average soil damping ratio:

=========  ======================  ==============  ===========
``α S``    damping ratio ``β``     ``V_s/V_s0``    ``G/G_0``
=========  ======================  ==============  ===========
0.10       0.03                    0.90            0.80
0.20       0.06                    0.70            0.50
0.30       0.10                    0.60            0.36
=========  ======================  ==============  ===========

(the table also gives ± one standard deviation: ±0.07/±0.10, ±0.15/±0.20, ±0.15/±0.20 for the
velocity and modulus ratios). Between the rows the values are interpolated linearly here; the
table has no row below 0.10 or above 0.30, and a shaking outside that range is refused rather
than extrapolated. (``G/G_0`` is close to ``(V_s/V_s0)²``, as it must be: 0.81, 0.49, 0.36.)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from pounding.validation import in_range, positive

__all__ = ["EN1998_5_TABLE_4_1", "Soil", "en1998_5_reduction"]

EN1998_5_TABLE_4_1: tuple[tuple[float, float, float, float], ...] = (
    (0.10, 0.03, 0.90, 0.80),
    (0.20, 0.06, 0.70, 0.50),
    (0.30, 0.10, 0.60, 0.36),
)
"""EN 1998-5:2004 Table 4.1, row by row: the ground acceleration ratio ``α S``, the average
soil damping ratio ``β``, the velocity ratio ``V_s/V_s0`` and the modulus ratio ``G/G_0``."""


def en1998_5_reduction(alpha_s: float) -> tuple[float, float]:
    """``(G/G_0, β)``: the shear modulus ratio and the soil damping ratio of EN 1998-5:2004
    Table 4.1 for the ground acceleration ratio ``alpha_s`` = ``α S`` (module docstring),
    interpolated linearly between the table's rows.

    Raises
    ------
    ValueError
        If ``alpha_s`` is outside the table's range [0.1, 0.3].

    Examples
    --------
    >>> en1998_5_reduction(0.2)
    (0.5, 0.06)
    >>> [round(v, 4) for v in en1998_5_reduction(0.15)]
    [0.65, 0.045]
    """
    a = in_range("shaking (alpha S of EN 1998-5 Table 4.1)", alpha_s, 0.10, 0.30)
    rows = EN1998_5_TABLE_4_1
    for (a0, b0, _, g0), (a1, b1, _, g1) in zip(rows[:-1], rows[1:]):
        if a <= a1:
            w = (a - a0) / (a1 - a0)
            return g0 + w * (g1 - g0), b0 + w * (b1 - b0)
    raise AssertionError("unreachable")  # pragma: no cover


@dataclass(frozen=True)
class Soil:
    """A homogeneous elastic half-space (module docstring).

    Parameters
    ----------
    shear_wave_velocity : float
        Small-strain shear-wave velocity ``V_s0`` [m/s].
    density : float
        Mass density ``ρ`` [kg/m³].
    poisson : float
        Poisson's ratio ``ν`` [-], in [0, 0.5).
    shaking : float, optional
        The design ground acceleration ratio ``α S`` [-] for which the strain-compatible
        modulus and the soil's own damping of EN 1998-5 Table 4.1 are taken (0.1 to 0.3);
        default none: the small-strain modulus and no material damping.

    Examples
    --------
    >>> s = Soil(150.0, 1800.0, 0.33)
    >>> s.shear_modulus, s.damping_ratio
    (40500000.0, 0.0)
    >>> Soil(150.0, 1800.0, 0.33, shaking=0.2).shear_modulus
    20250000.0
    """

    shear_wave_velocity: float
    density: float
    poisson: float
    shaking: float | None = None

    def __post_init__(self) -> None:
        positive("soil.vs (shear-wave velocity [m/s])", self.shear_wave_velocity)
        positive("soil.density [kg/m³]", self.density)
        in_range("soil.poisson (Poisson's ratio)", self.poisson, 0.0, 0.5, high_open=True)
        if self.shaking is not None:
            en1998_5_reduction(self.shaking)

    @property
    def modulus_ratio(self) -> float:
        """``G/G_0`` [-] for :attr:`shaking` (1 without it)."""
        return 1.0 if self.shaking is None else en1998_5_reduction(self.shaking)[0]

    @property
    def damping_ratio(self) -> float:
        """The soil's material damping ratio ``β`` [-] for :attr:`shaking` (0 without it)."""
        return 0.0 if self.shaking is None else en1998_5_reduction(self.shaking)[1]

    @property
    def shear_modulus(self) -> float:
        """The strain-compatible shear modulus ``G = (G/G_0) ρ V_s0²`` [Pa]."""
        return self.modulus_ratio * self.density * self.shear_wave_velocity ** 2

    @property
    def vs(self) -> float:
        """The strain-compatible shear-wave velocity ``√(G/ρ)`` [m/s]."""
        return math.sqrt(self.shear_modulus / self.density)

    @property
    def vp(self) -> float:
        """The dilatational (P) wave velocity ``V_s √(2(1 − ν)/(1 − 2ν))`` [m/s]."""
        nu = self.poisson
        return self.vs * math.sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu))

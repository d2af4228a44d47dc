"""The numbers of model and study files: each kind of quantity with its unit and the range
of values that mean something physically.

A value outside its range is refused when the file is read, with the range in the message
(``building[0].height: must be in (0, 1000] m (got 1e+300)``). The ranges are generous on
purpose: they refuse what cannot be a building, a record or a contact — a storey a
kilometre tall, a floor heavier than a thousand of the heaviest buildings, an angle of
1e308 degrees — not what is merely unusual (that is what the plausibility warnings of
:mod:`pounding.config.plausibility` are for). Besides being nonsense, such numbers break
the arithmetic downstream (a storey height of 1e300 m divides by zero in the contact
geometry, a spectral period of 1e300 s in the spectrum), and the error then names a derived
quantity instead of the input.

=====================  ==============================  =========================================
quantity               range                           why the bound
=====================  ==============================  =========================================
mass                   (0, 1e12] kg                    the heaviest buildings weigh ~1e9 kg in
                                                       all; a floor 1000 times heavier is none
                                                       (a rigid wall is ``[[wall]]``)
stiffness              (0, 1e15] N/m                   real storeys and contacts: 1e6–1e11 N/m
force                  (0, 1e13] N                     the weight of 1e12 kg
damping coefficient    [0, 1e15] N·s/m                 as stiffness
length                 (0, 1000] m                     a storey, a wall, a pad, a yield drift: the
                                                       tallest building is 828 m in all
gap                    [0, 1000] m                     as length (gaps above 2 m are warned of)
plan length            (0, 10 000] m                   the largest footprints are ~1 km across
plan coordinate        [-10 000, 10 000] m             as plan length
elevation              [-1000, 1000] m                 as length (below 0: a basement)
time step              (0, 1] s                        a step above 1 s samples no earthquake
duration               (0, 1e5] s                      about a day
period                 (0, 100] s                      building and spectral periods: codes
                                                       define spectra up to 10–20 s
intensity              (0, 100] g                      recorded PGAs stay below 5 g
scale factor           [-1000, 1000], not 0            negative flips the record's polarity
angle                  [-360, 360] degrees             one turn either way
=====================  ==============================  =========================================

Dimensionless constants (ratios, exponents) carry the range of their law (for example
``0 < e <= 1``, ``1 <= n <= 3`` for a Hertz contact).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated

from pydantic import Field

__all__ = ["Unit", "MAX_MASS", "MAX_STIFFNESS", "MAX_FORCE", "MAX_LENGTH", "MAX_PLAN",
           "MAX_STEP", "MAX_DURATION", "MAX_PERIOD", "MAX_INTENSITY_G", "MAX_SCALE",
           "MAX_ANGLE"]


@dataclass(frozen=True)
class Unit:
    """The unit of a field, named after its range in validation messages (metadata of an
    ``Annotated`` type; pydantic ignores it)."""

    symbol: str


MAX_MASS = 1e12
"""Largest mass [kg] of a floor, base slab or building."""
MAX_STIFFNESS = 1e15
"""Largest stiffness [N/m] (storey, element, contact, device, isolator) and damping
coefficient [N·s/m]."""
MAX_FORCE = 1e13
"""Largest force [N] (yield force, characteristic strength, weight)."""
MAX_LENGTH = 1000.0
"""Largest length [m] of a storey, wall, gap, pad or yield displacement."""
MAX_PLAN = 10_000.0
"""Largest plan dimension and plan coordinate [m]."""
MAX_STEP = 1.0
"""Largest time step [s] (record sample step, output step, adaptive step)."""
MAX_DURATION = 1e5
"""Longest duration [s] (of a record kept, of a simulation)."""
MAX_PERIOD = 100.0
"""Longest period [s] (of a building, of a spectral ordinate)."""
MAX_INTENSITY_G = 100.0
"""Largest ground-motion intensity [g] (PGA, Sa) a record may be scaled to."""
MAX_SCALE = 1000.0
"""Largest |factor| a record may be multiplied by."""
MAX_ANGLE = 360.0
"""Largest |angle| [degrees] (a direction, an incidence)."""

Mass = Annotated[float, Field(gt=0, le=MAX_MASS), Unit("kg")]
Stiffness = Annotated[float, Field(gt=0, le=MAX_STIFFNESS), Unit("N/m")]
StiffnessOrZero = Annotated[float, Field(ge=0, le=MAX_STIFFNESS), Unit("N/m")]
HertzStiffness = Annotated[float, Field(gt=0, le=MAX_STIFFNESS), Unit("N/m^n")]
Force = Annotated[float, Field(gt=0, le=MAX_FORCE), Unit("N")]
DampingCoefficient = Annotated[float, Field(ge=0, le=MAX_STIFFNESS), Unit("N·s/m")]
PositiveDamping = Annotated[float, Field(gt=0, le=MAX_STIFFNESS), Unit("N·(s/m)^α")]
Length = Annotated[float, Field(gt=0, le=MAX_LENGTH), Unit("m")]
Gap = Annotated[float, Field(ge=0, le=MAX_LENGTH), Unit("m")]
PlanLength = Annotated[float, Field(gt=0, le=MAX_PLAN), Unit("m")]
Coordinate = Annotated[float, Field(ge=-MAX_PLAN, le=MAX_PLAN), Unit("m")]
Elevation = Annotated[float, Field(ge=-MAX_LENGTH, le=MAX_LENGTH), Unit("m")]
Step = Annotated[float, Field(gt=0, le=MAX_STEP), Unit("s")]
Duration = Annotated[float, Field(gt=0, le=MAX_DURATION), Unit("s")]
Period = Annotated[float, Field(gt=0, le=MAX_PERIOD), Unit("s")]
Intensity = Annotated[float, Field(gt=0, le=MAX_INTENSITY_G), Unit("g")]
Scale = Annotated[float, Field(ge=-MAX_SCALE, le=MAX_SCALE)]
Angle = Annotated[float, Field(ge=-MAX_ANGLE, le=MAX_ANGLE), Unit("degrees")]

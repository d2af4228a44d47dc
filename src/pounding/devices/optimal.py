"""The damper coefficient that best links two buildings.

Two answers:

* :func:`white_noise_optimum` (here) — closed forms for two undamped SDOF oscillators joined by a
  linear dashpot under stationary white-noise ground acceleration. The stationary
  covariance of ``[x1, x2, ẋ1, ẋ2]`` solves the Lyapunov equation
  ``A P + P Aᵀ + 2π S0 B Bᵀ = 0``; every mean-square response comes out as
  ``π S0 (a c + b / c)``, so the optimum is ``c = sqrt(b / a)`` (derived for this project,
  docs/mitigation.md; the setting of Bhaskararao & Jangid 2007, "Optimum viscous damper for
  connecting adjacent SDOF structures for harmonic and stationary white-noise random
  excitations", Earthquake Engng Struct. Dyn. 36:563–571, whose own expressions could not be
  consulted here). With ``D = |ω1² − ω2²|`` and ``M = m1 + m2``::

      E[x1²] least:      c = m1^{3/2} m2 D / (ω1 M^{3/2})
      E[x2²] least:      c = m2^{3/2} m1 D / (ω2 M^{3/2})
      E[ẍ1,abs²] least:  c = m1^{3/2} m2 D ω1 / (M^{1/2} (m1 ω1² + m2 ω2²))
      E[energy] least:   c = m1 m2 D sqrt((m1² + m2²) / (M³ (m1 ω1² + m2 ω2²)))

  The relative displacement ``E[(x1 − x2)²] = π S0 (m1/ω1² + m2/ω2²) / c`` has no finite
  optimum: more damping always keeps the floors closer together.

* :func:`pounding.studies.optimal_link.optimal_link_coefficient` — the same question on a
  real model and record: the coefficient of one link that minimises a chosen response of
  :func:`pounding.simulate`, found by a bounded scalar search on ``log c`` (a study: it runs
  the simulator, so it lives with the studies).
"""

from __future__ import annotations

import math

__all__ = ["OPTIMUM_RESPONSES", "white_noise_optimum"]

OPTIMUM_RESPONSES = ("displacement_1", "displacement_2", "acceleration_1", "energy")
"""The responses :func:`white_noise_optimum` minimises."""


def white_noise_optimum(m1: float, period1: float, m2: float, period2: float,
                        response: str = "displacement_1") -> float:
    """Damper coefficient [N·s/m] that minimises a mean-square response of two undamped
    oscillators linked by a dashpot under white noise (closed forms in the module
    docstring).

    Parameters
    ----------
    m1, m2 : float
        Masses [kg].
    period1, period2 : float
        Natural periods [s] (different: equal oscillators move together and a link between
        them does nothing).
    response : str
        One of :data:`OPTIMUM_RESPONSES`: the displacement of oscillator 1 or 2, the absolute
        acceleration of oscillator 1, or the total energy of both.

    Returns
    -------
    float
        The optimal coefficient c [N·s/m].

    Examples
    --------
    >>> round(white_noise_optimum(1.0, 2 * math.pi / 5, 3.0, 2 * math.pi / 9), 12)
    4.2
    """
    if response not in OPTIMUM_RESPONSES:
        raise ValueError(f"response: {response!r} is not one of {', '.join(OPTIMUM_RESPONSES)}")
    for name, v in (("m1", m1), ("m2", m2), ("period1", period1), ("period2", period2)):
        if not (math.isfinite(v) and v > 0):
            raise ValueError(f"{name}: must be finite and > 0 (got {v!r})")
    w1, w2 = 2 * math.pi / period1, 2 * math.pi / period2
    d = abs(w1 * w1 - w2 * w2)
    if d == 0.0:
        raise ValueError("period2: equal periods move together; a link between them does "
                         "nothing (no optimum)")
    big = m1 + m2
    if response == "displacement_1":
        return m1**1.5 * m2 * d / (w1 * big**1.5)
    if response == "displacement_2":
        return m2**1.5 * m1 * d / (w2 * big**1.5)
    if response == "acceleration_1":
        return m1**1.5 * m2 * d * w1 / (math.sqrt(big) * (m1 * w1 * w1 + m2 * w2 * w2))
    return m1 * m2 * d * math.sqrt((m1 * m1 + m2 * m2)
                                   / (big**3 * (m1 * w1 * w1 + m2 * w2 * w2)))

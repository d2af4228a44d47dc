"""The damper coefficient that best links two buildings.

Two answers:

* :func:`white_noise_optimum` — closed forms for two undamped SDOF oscillators joined by a
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

* :func:`optimal_link_coefficient` — the same question on a real model and record: the
  coefficient of one link that minimises a chosen response of :func:`pounding.simulate`,
  found by a bounded scalar search on ``log c``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from pounding.ground_motion import GroundMotion
    from pounding.model import PoundingModel
    from pounding.result import Result

__all__ = ["OPTIMUM_RESPONSES", "RESPONSES", "LinkOptimum", "optimal_link_coefficient",
           "white_noise_optimum"]

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


RESPONSES: dict[str, Callable[["Result"], float]] = {
    "peak_drift_ratio": lambda r: float(np.nanmax(r.peak_drift_ratio)),  # storeys only
    "peak_displacement": lambda r: float(np.max(r.peak_displacement)),
    "peak_abs_acceleration": lambda r: float(np.max(r.peak_abs_acceleration)),
    "peak_contact_force": lambda r: float(r.peak_contact_force.max()) if r.peak_contact_force.size
    else 0.0,
    "rms_displacement_B1": lambda r: float(np.sqrt(np.mean(
        r.displacement[:, r.model.system.offsets[0] + r.model.buildings[0].n - 1] ** 2))),
}
"""Named responses :func:`optimal_link_coefficient` can minimise (largest over all floors;
``rms_displacement_B1``: root-mean-square roof displacement of the first building)."""


@dataclass(frozen=True)
class LinkOptimum:
    """What :func:`optimal_link_coefficient` found."""

    c: float
    """The best coefficient [N·(s/m)^α]."""
    response: float
    """The response there."""
    evaluated: tuple[tuple[float, float], ...]
    """Every ``(c, response)`` the search evaluated, in order."""


def optimal_link_coefficient(model: "PoundingModel", motion: "GroundMotion", link_index: int = 0,
                             response: str | Callable[["Result"], float] = "peak_drift_ratio",
                             bounds: tuple[float, float] = (1e3, 1e9), xatol: float = 0.01,
                             **simulate_kw: Any) -> LinkOptimum:
    """The coefficient ``c`` of link ``link_index`` of the model that minimises a response.

    A bounded Brent search on ``log c`` (SciPy ``minimize_scalar``), each evaluation a run
    of :func:`pounding.simulate`. The other constants of the link (``α``, ``k``) stay.

    Parameters
    ----------
    model : PoundingModel
        With at least one link (:attr:`PoundingModel.links`).
    motion : GroundMotion
        The record.
    link_index : int
        Which link (position among the model's links).
    response : str or callable
        A name of :data:`RESPONSES` or ``f(result) -> float``.
    bounds : (float, float)
        Range of ``c`` searched [N·(s/m)^α].
    xatol : float
        Tolerance on ``ln c`` (0.01: about 1 %).
    **simulate_kw
        Passed to :func:`pounding.simulate`.

    Returns
    -------
    LinkOptimum
    """
    from scipy.optimize import minimize_scalar

    from pounding.integrate import simulate

    links = model.links
    if not 0 <= link_index < len(links):
        raise ValueError(f"link_index: the model has {len(links)} link(s) (got {link_index})")
    fn = RESPONSES[response] if isinstance(response, str) else response
    if isinstance(response, str) and response not in RESPONSES:
        raise ValueError(f"response: {response!r} is not one of {', '.join(RESPONSES)}")
    lo, hi = bounds
    if not (0 < lo < hi and math.isfinite(hi)):
        raise ValueError(f"bounds: need 0 < low < high (got {bounds!r})")
    target = links[link_index]
    seen: list[tuple[float, float]] = []

    def run(log_c: float) -> float:
        c = float(math.exp(log_c))
        devices = [replace(d, c=c) if d is target else d for d in model.devices]
        value = fn(simulate(replace(model, devices=devices), motion, **simulate_kw))
        seen.append((c, value))
        return value

    best = minimize_scalar(run, bounds=(math.log(lo), math.log(hi)), method="bounded",
                           options={"xatol": xatol})
    c_best, value = min(seen, key=lambda cv: cv[1])
    del best
    return LinkOptimum(c=c_best, response=value, evaluated=tuple(seen))

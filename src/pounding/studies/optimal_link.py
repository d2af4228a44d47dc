"""The damper coefficient of one link that minimises a response of a model under a record.

The closed forms for two oscillators under white noise are
:func:`pounding.devices.optimal.white_noise_optimum`; this is the same question asked of a
real model and record: a bounded Brent search on ``log c`` (SciPy ``minimize_scalar``), each
evaluation a run of :func:`pounding.simulate` (``docs/mitigation.md``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from pounding.ground_motion import GroundMotion
    from pounding.model import PoundingModel
    from pounding.result import Result

__all__ = ["RESPONSES", "LinkOptimum", "optimal_link_coefficient"]


def _roof(model: PoundingModel) -> int:
    """The global DOF of the first building's roof: its highest floor (not its last DOF,
    which is a footing's rocking on a flexible base, or a matrix building's rotation)."""
    off, n = int(model.system.offsets[0]), int(model.buildings[0].n)
    floors = np.flatnonzero(model.is_floor[off:off + n])
    levels = np.asarray(model.buildings[0].floor_levels, dtype=float)[floors]
    return off + int(floors[int(np.argmax(levels))])


def _largest(r: Result, values: NDArray[np.float64]) -> float:
    """The largest of a per-DOF peak over the DOFs that are no footing's (a footing's sway
    and rocking are DOFs, no floors: :func:`pounding.result.foundations.footing_dofs`)."""
    from pounding.result.foundations import footing_dofs

    return float(np.max(np.delete(values, footing_dofs(r.model))))


RESPONSES: dict[str, Callable[[Result], float]] = {
    "peak_drift_ratio": lambda r: float(np.nanmax(r.peak_drift_ratio)),  # storeys only
    "peak_displacement": lambda r: _largest(r, r.peak_displacement),
    "peak_abs_acceleration": lambda r: _largest(r, r.peak_abs_acceleration),
    "peak_contact_force": lambda r: float(r.peak_contact_force.max()) if r.peak_contact_force.size
    else 0.0,
    "rms_displacement_B1": lambda r: float(np.sqrt(np.mean(
        r.displacement[:, _roof(r.model)] ** 2))),
}
"""Named responses :func:`optimal_link_coefficient` can minimise (largest over all floors,
a footing's sway and rocking left out; ``rms_displacement_B1``: root-mean-square
displacement of the first building's roof, its highest floor)."""


@dataclass(frozen=True)
class LinkOptimum:
    """What :func:`optimal_link_coefficient` found."""

    c: float
    """The best coefficient [N·(s/m)^α]."""
    response: float
    """The response there."""
    evaluated: tuple[tuple[float, float], ...]
    """Every ``(c, response)`` the search evaluated, in order."""


def optimal_link_coefficient(model: PoundingModel, motion: GroundMotion, link_index: int = 0,
                             response: str | Callable[[Result], float] = "peak_drift_ratio",
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
        devices = tuple(replace(d, c=c) if d is target else d for d in model.devices)
        value = fn(simulate(replace(model, devices=devices), motion, **simulate_kw))
        seen.append((c, value))
        return value

    best = minimize_scalar(run, bounds=(math.log(lo), math.log(hi)), method="bounded",
                           options={"xatol": xatol})
    c_best, value = min(seen, key=lambda cv: cv[1])
    del best
    return LinkOptimum(c=c_best, response=value, evaluated=tuple(seen))

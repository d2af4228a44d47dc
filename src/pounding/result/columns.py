"""The columns of a result's arrays, and lengths as the outputs write them.

:data:`ENERGY_NAMES` names the columns of the cumulative energies, :data:`IMPACT_COLUMNS`
those of the impact table; :func:`rounded_length` rounds an elevation or storey height for
the outputs. The bottom of :mod:`pounding.result`: it imports nothing of pounding.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["ELEVATION_DECIMALS", "ENERGY_NAMES", "IMPACT_COLUMNS", "rounded_length"]

ENERGY_NAMES: tuple[str, ...] = ("input", "kinetic", "strain", "damping", "contact_work",
                                 "contact_stored", "hysteretic", "links")
"""Columns of :attr:`pounding.result.Result.energy` [J]: input energy ``−∫u̇ᵀMR a_g dt``,
kinetic ``½u̇ᵀMu̇`` (relative), elastic strain (``½uᵀKu`` of the linear storeys plus the
recoverable energy of the yielding ones), viscous damping ``∫u̇ᵀCu̇ dt``, total work of the
contact forces ``∫ΣF δ̇ dt``, the elastic energy still stored in closed contacts, and the
hysteretic energy of the yielding storeys (their work ``∫ΣV ḋ dt`` minus their recoverable
energy; see :mod:`pounding.hysteresis.base`), and the energy dissipated by the links between
buildings (their work less their springs' energy, which is in ``strain``; 0 without links).
Contact-dissipated energy is ``contact_work − contact_stored``. The balance: ``E_0 + input =
kinetic + strain + damping + hysteretic + contact_work + links``."""

IMPACT_COLUMNS: tuple[str, ...] = ("contact", "start", "end", "v0", "peak_force",
                                   "peak_force_time", "max_penetration", "restitution",
                                   "energy_dissipated")
"""Columns of :attr:`pounding.result.Result.impact_array` (the contact as its index) and
of :attr:`pounding.result.Result.impacts` (the contact as its label): start and end [s],
closing velocity v0 [m/s], peak force [N] and its time [s], largest penetration [m], the
velocity ratio ``restitution`` (separation over approach speed of the two contact points
[-]; the law's restitution only for free bodies: see
:attr:`pounding.result.Result.impacts`), and the energy the contact element dissipated in
the impact [J] (≥ 0)."""

ELEVATION_DECIMALS = 6
"""Decimals [m] of an elevation or storey height written to the outputs (1 µm): floor
elevations are sums of storey heights, ``3.2 × 10`` adds up to ``31.999999999999996``."""


def rounded_length(value: Any) -> Any:
    """An elevation or storey height [m] (a float or an array) rounded to
    :data:`ELEVATION_DECIMALS` for the outputs, so that it reads as given (``32.0``, not
    ``31.999999999999996``)."""
    if np.ndim(value) == 0:
        return round(float(value), ELEVATION_DECIMALS)
    return np.round(np.asarray(value, dtype=float), ELEVATION_DECIMALS)

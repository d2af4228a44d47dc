"""A sacrificial shear key, as a one-sided contact law: a gap, then stiff up to a capacity,
then broken off.

Exterior shear keys on a seat abutment (and keys at in-span hinges) hold a bridge's deck
transversely. In California they are designed as *sacrificial* elements: a structural fuse
that limits the transverse force reaching the abutment's stem wall and piles, and breaks off
in a strong earthquake (Bozorgzadeh, Megally, Restrepo & Ashford 2004, "Seismic response and
capacity evaluation of exterior sacrificial shear keys of bridge abutments", 13th WCEE,
paper 528). Goel & Chopra (2008, "Role of shear keys in seismic behavior of bridges crossing
fault-rupture zones", J. Bridge Eng., ASCE) bound a bridge's response with three key
models: *nonlinear keys that break off and cease to provide transverse restraint if
deformed beyond a certain limit*, *elastic keys* that never break, and *no keys*.

The law (each key is one-sided: a deck moving toward it closes its gap; a key on each side
of the deck is two contacts):

* ``F = 0`` while the gap is open (``δ ≤ 0``, ``δ`` the penetration past the gap [m]);
* elastic ``F = k (δ − s)`` up to the capacity ``F_c`` (``s`` the key's permanent set, 0 at
  first), then perfectly plastic: ``F = F_c`` while ``δ`` grows, the set following as
  ``s = δ − F_c/k``; unloading and reloading at ``k``, no tension, and the set kept from one
  impact to the next (a deck that has bent the key finds a wider gap);
* when ``δ`` reaches the fracture deformation ``δ_u`` (≥ ``δ_y = F_c/k``) the key breaks off:
  ``F`` drops to zero there, once and for all. ``δ_u = δ_y`` is an elastic–brittle key;
  without ``δ_u`` the key never breaks (elastic–perfectly-plastic; with a capacity no
  earthquake reaches, Goel & Chopra's elastic key).

The time-history kernel and the SciPy reference locate the instant ``δ = δ_u`` as an event
and drop the force there (:func:`pounding.contact.dispatch.fracture_value`); the key's
impact ends at that instant in the impact table. The energy the key takes from the deck is
its plastic work ``F_c (δ_u − δ_y)`` plus the elastic energy ``F_c²/(2k)`` it held when it
broke: ``F_c (δ_u − δ_y/2)`` for a key pushed monotonically to fracture.

What could not be read (stored public copies only, their openings): Megally, Silva & Seible
(2002), "Seismic response of sacrificial shear keys in bridge abutments", UCSD SSRP-2001/23,
and Bozorgzadeh et al. (2004) — their tested backbones (cracking, yield, a peak and a
softening branch, the sliding shear-friction mechanism and its capacity formula) were not
reached, so none of their numbers are here and the softening branch is idealised as the
sudden drop above; Caltrans SDC's shear-key sizing rule (the design force as a fraction of
the superstructure's dead-load reaction or of the piles' and wingwalls' capacity) was not
reached either, so the capacity is the user's.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from pounding.contact.base import ContactLaw
from pounding.contact.codes import SHEAR_KEY
from pounding.validation import positive

__all__ = ["ShearKey", "key_response"]


@dataclass(frozen=True)
class ShearKey(ContactLaw):
    """A sacrificial shear key (module docstring).

    Parameters
    ----------
    k : float
        Elastic stiffness of the key [N/m].
    capacity : float
        Force at which it yields, F_c [N].
    fracture_displacement : float, optional
        Penetration past the gap at which it breaks off, δ_u [m], at least ``capacity / k``
        (which is an elastic–brittle key); None: it never breaks.

    Examples
    --------
    >>> key = ShearKey(k=5.0e8, capacity=2.0e6, fracture_displacement=0.05)
    >>> key.yield_displacement
    0.004
    >>> round(key.dissipated_at_fracture / 1e3, 3)   # kJ: F_c (δ_u − δ_y/2)
    96.0
    """

    k: float
    capacity: float
    fracture_displacement: float | None = None
    code: ClassVar[int] = SHEAR_KEY
    label: ClassVar[str] = "shear key"
    source: ClassVar[str] = ""
    units: ClassVar[dict[str, str]] = {"k": "N/m", "capacity": "N",
                                       "fracture_displacement": "m"}

    def __post_init__(self) -> None:
        k = positive("k", self.k)
        fc = positive("capacity", self.capacity)
        object.__setattr__(self, "k", k)
        object.__setattr__(self, "capacity", fc)
        if self.fracture_displacement is not None:
            du = positive("fracture_displacement", self.fracture_displacement)
            if du < fc / k * (1.0 - 1e-12):
                raise ValueError(f"fracture_displacement: the key yields at capacity/k = "
                                 f"{fc / k:.6g} m and cannot break before it (got {du:g} m; "
                                 f"capacity/k itself is an elastic-brittle key)")
            object.__setattr__(self, "fracture_displacement", max(du, fc / k))

    @classmethod
    def brittle(cls, k: float, capacity: float) -> ShearKey:
        """An elastic–brittle key: it breaks off where it reaches its capacity."""
        kk = positive("k", k)
        return cls(kk, capacity, positive("capacity", capacity) / kk)

    @property
    def yield_displacement(self) -> float:
        """``δ_y = F_c / k`` [m]."""
        return self.capacity / self.k

    @property
    def breaks(self) -> bool:
        """True if the key breaks off at a fracture deformation."""
        return self.fracture_displacement is not None

    @property
    def dissipated_at_fracture(self) -> float:
        """Energy a key pushed monotonically to fracture takes from the deck [J]:
        ``F_c (δ_u − δ_y) + F_c²/(2k)``; ``inf`` for a key that never breaks."""
        if self.fracture_displacement is None:
            return float("inf")
        return self.capacity * (self.fracture_displacement - 0.5 * self.yield_displacement)

    def backbone(self, delta: float) -> float:
        """The force [N] of a key loaded monotonically to penetration ``delta`` [m]: ``k δ``
        up to ``F_c``, ``F_c`` up to ``δ_u`` (exclusive), 0 from there (and for δ ≤ 0)."""
        du = self.fracture_displacement
        if delta <= 0.0 or (du is not None and delta >= du):
            return 0.0
        return min(self.k * delta, self.capacity)

    def secant_stiffness(self, delta: float) -> float:
        """Secant ``F/δ`` of the intact key's backbone [N/m]: ``k`` up to ``δ_y``."""
        if delta <= self.yield_displacement:
            return self.k
        return self.capacity / delta

    def params(self) -> np.ndarray:
        return np.array([self.k, self.capacity, self.fracture_displacement or 0.0])


def key_response(law: ShearKey, mass: float, velocity: float) -> dict[str, float]:
    """Closed form of a free mass ``mass`` [kg] striking the key at ``velocity`` [m/s]
    (the gap closing at t = 0, no other force): the elastic phase ``δ = (v0/ω) sin ωt``,
    ``ω = √(k/m)``, to yield where ``k δ = F_c``; the plastic phase at constant force
    ``F_c`` to fracture at ``δ_u``; after it, free flight.

    Returns
    -------
    dict
        ``t_yield`` [s], ``v_yield`` [m/s] (velocity at yield), ``t_fracture`` [s],
        ``v_fracture`` [m/s] (velocity as the key breaks), and ``dissipated`` [J]
        (``½ m (v0² − v_f²)``); a mass too slow to yield rebounds elastically
        (``t_yield`` and the rest ``nan``, ``t_rebound = π/ω``), one too slow to break it
        comes to rest on the plateau (``t_fracture``, ``v_fracture`` ``nan``,
        ``delta_max`` the largest penetration).
    """
    m = positive("mass", mass)
    v0 = positive("velocity", velocity)
    k, fc = law.k, law.capacity
    w = float(np.sqrt(k / m))
    out = {"t_yield": np.nan, "v_yield": np.nan, "t_fracture": np.nan, "v_fracture": np.nan,
           "t_rebound": np.nan, "delta_max": np.nan, "dissipated": 0.0}
    s = fc * w / (k * v0)  # sin ωt at yield
    if s >= 1.0:  # elastic rebound
        out["t_rebound"] = np.pi / w
        out["delta_max"] = v0 / w
        return out
    t_y = float(np.arcsin(s)) / w
    v_y = float(np.sqrt(v0 * v0 - fc * fc / (k * m)))
    out["t_yield"], out["v_yield"] = t_y, v_y
    dy = fc / k
    reach = dy + 0.5 * m * v_y * v_y / fc  # where the plateau stops the mass
    du = law.fracture_displacement
    if du is None or reach < du:
        out["delta_max"] = reach
        out["dissipated"] = fc * (reach - dy)
        return out
    v_f = float(np.sqrt(max(v_y * v_y - 2.0 * fc * (du - dy) / m, 0.0)))
    out["t_fracture"] = t_y + (v_y - v_f) * m / fc
    out["v_fracture"] = v_f
    out["delta_max"] = du
    out["dissipated"] = 0.5 * m * (v0 * v0 - v_f * v_f)
    return out

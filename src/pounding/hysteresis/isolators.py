"""Isolation bearings as storey laws: the bilinear isolator and the friction pendulum.

An isolator is the storey between the ground and the base slab of a base-isolated building
(:meth:`pounding.structure.ShearBuilding.base_isolated`). Each class here takes the constants
engineers give for the bearing and builds the storey law the kernel already integrates
(:class:`pounding.hysteresis.Bilinear`, :class:`pounding.hysteresis.BoucWen`) together with
the isolation storey's elastic (initial) stiffness ``k``, which the law's contract takes
from the building (:mod:`pounding.hysteresis.base`, step 2).

* :class:`BilinearIsolator` — lead-rubber and similar bearings given by their pre-yield
  stiffness ``k₁``, post-yield stiffness ``k₂`` and characteristic strength ``Q`` (the
  force at zero displacement on the post-yield branch) or yield force ``F_y``:
  ``F_y = Q k₁/(k₁ − k₂)``, hardening ratio ``b = k₂/k₁`` (Naeim & Kelly 1999, *Design of
  Seismic Isolated Structures*, §4; the usual bilinear idealisation).
* :class:`FrictionPendulum` — the friction pendulum bearing (Zayas, Low & Mahin 1990,
  Earthquake Spectra 6(2):317–333): the restoring force of the pendulum plus friction,

      F = (W/R) u + μ W Z,
      Y Ż = A u̇ − β |u̇| Z |Z|^(n−1) − γ u̇ |Z|^n,   A = 1, β + γ = 1,

  with ``Z`` the Bouc–Wen variable of a small yield displacement ``Y`` that stands for the
  rigid-plastic friction law (Constantinou, Mokha & Reinhorn 1990, "Teflon bearings in base
  isolation II: modeling", J. Struct. Eng. 116(2):455–474; Mokha, Constantinou & Reinhorn
  1990, J. Struct. Eng. 116(2):438–454; the same model in Nagarajaiah, Reinhorn &
  Constantinou 1991, 3D-BASIS). This is *exactly* the Bouc–Wen storey of
  :mod:`pounding.hysteresis.bouc_wen`, ``V = α k d + (1 − α) F_y z`` with
  ``ż = (A ḋ − β |ḋ| |z|^(n−1) z − γ ḋ |z|^n)/d_y``, ``d_y = F_y/k``, under

      k = W/R + μW/Y,   F_y = k Y = (W/R) Y + μW,   α = (W/R)/k,   z = Z,

  since then ``α k = W/R``, ``(1 − α) F_y = F_y − α k Y = μW`` and ``d_y = Y``. The friction
  coefficient is constant (the velocity dependence of PTFE of Constantinou et al. 1990 is
  left out, as in most pounding studies of isolated buildings, e.g. Komodromos et al. 2007).
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from dataclasses import dataclass

from pounding.hysteresis.base import StoreyLaw
from pounding.hysteresis.bilinear import Bilinear
from pounding.hysteresis.bouc_wen import BoucWen
from pounding.validation import in_range, positive

__all__ = ["BilinearIsolator", "FrictionPendulum", "Isolator", "GRAVITY"]

GRAVITY: float = 9.80665
"""Standard gravity [m/s²] (the weight ``W = m g`` a friction pendulum carries)."""


class Isolator(ABC):
    """An isolation bearing: the initial stiffness of the isolation storey and its law.

    An abstract base: use :class:`BilinearIsolator` or :class:`FrictionPendulum` (a new
    bearing subclasses it and gives :attr:`stiffness` and :meth:`law`)."""

    label: str = "isolator"

    @property
    @abstractmethod
    def stiffness(self) -> float:
        """Elastic (initial) stiffness of the isolation storey ``k`` [N/m]."""

    @abstractmethod
    def law(self) -> StoreyLaw:
        """The storey law (its elastic stiffness is :attr:`stiffness`)."""

    def carrying(self, mass: float) -> Isolator:
        """The isolator under the weight of ``mass`` [kg] (only laws that depend on the
        weight change)."""
        return self


@dataclass(frozen=True)
class BilinearIsolator(Isolator):
    """A bilinear isolator (lead-rubber bearing and the like).

    Parameters
    ----------
    pre_yield_stiffness : float
        ``k₁`` [N/m], elastic stiffness of the whole isolation system.
    post_yield_stiffness : float
        ``k₂`` [N/m], ``0 ≤ k₂ < k₁``.
    characteristic_strength : float, optional
        ``Q`` [N], the post-yield branch's force at zero displacement.
    yield_force : float, optional
        ``F_y`` [N] instead of ``Q`` (``F_y = Q k₁/(k₁ − k₂)``).

    Examples
    --------
    >>> iso = BilinearIsolator(2.0e8, 2.0e7, characteristic_strength=9.0e5)
    >>> round(iso.yield_force), iso.law().hardening
    (1000000, 0.1)
    """

    pre_yield_stiffness: float
    post_yield_stiffness: float
    characteristic_strength: float | None = None
    yield_force: float | None = None

    label = "bilinear isolator"

    def __post_init__(self) -> None:
        k1 = positive("pre_yield_stiffness", self.pre_yield_stiffness)
        k2 = in_range("post_yield_stiffness", self.post_yield_stiffness, 0.0, k1,
                      high_open=True)
        if (self.characteristic_strength is None) == (self.yield_force is None):
            raise ValueError("isolator: give exactly one of characteristic_strength [N] and "
                             f"yield_force [N] (got characteristic_strength="
                             f"{self.characteristic_strength!r}, yield_force={self.yield_force!r})")
        if self.characteristic_strength is not None:
            q = positive("characteristic_strength", self.characteristic_strength)
            object.__setattr__(self, "yield_force", q * k1 / (k1 - k2))
        else:
            fy = positive("yield_force", self.yield_force)  # type: ignore[arg-type]
            object.__setattr__(self, "characteristic_strength", fy * (k1 - k2) / k1)
        object.__setattr__(self, "pre_yield_stiffness", k1)
        object.__setattr__(self, "post_yield_stiffness", k2)

    @property
    def stiffness(self) -> float:
        return float(self.pre_yield_stiffness)

    @property
    def yield_displacement(self) -> float:
        """``F_y / k₁`` [m]."""
        return float(self.yield_force) / self.pre_yield_stiffness  # type: ignore[arg-type]

    def law(self) -> Bilinear:
        return Bilinear(yield_force=float(self.yield_force),  # type: ignore[arg-type]
                        hardening=self.post_yield_stiffness / self.pre_yield_stiffness)


@dataclass(frozen=True)
class FrictionPendulum(Isolator):
    """A friction pendulum bearing (system of bearings), ``F = (W/R) u + μ W Z``.

    Parameters
    ----------
    radius : float
        Radius of curvature of the sliding surface ``R`` [m] (pendulum period
        ``2π √(R/g)``), above ``Y/μ`` (a pendulum stiffness ``W/R`` below the stick
        stiffness of friction ``μW/Y``: the Bouc–Wen ``α`` below 1/2).
    mu : float
        Coefficient of friction ``μ`` (0 < μ < 1), constant.
    weight : float, optional
        Weight carried ``W`` [N]; give it or ``mass``, or leave both out and let
        :meth:`pounding.structure.ShearBuilding.base_isolated` use the building's weight.
    mass : float, optional
        Mass carried [kg], ``W = m g``.
    yield_displacement : float
        ``Y`` [m], the small displacement over which friction builds up (the bearing's
        stick phase; default 0.5 mm). Smaller is closer to rigid-plastic friction and
        stiffer (``k = W/R + μW/Y``).
    n, beta, gamma : float
        Bouc–Wen shape (defaults ``n = 2``, ``β = γ = 0.5``; ``β + γ = 1`` makes ``|Z| → 1``,
        the friction force ``μW`` while sliding).

    Examples
    --------
    >>> fp = FrictionPendulum(radius=2.0, mu=0.05, weight=1.0e6)
    >>> fp.law().describe()[:8], round(fp.stiffness)
    ('Bouc-Wen', 100500000)
    """

    radius: float
    mu: float
    weight: float | None = None
    mass: float | None = None
    yield_displacement: float = 5e-4
    n: float = 2.0
    beta: float = 0.5
    gamma: float = 0.5

    label = "friction pendulum"

    def __post_init__(self) -> None:
        positive("radius", self.radius)
        in_range("mu", self.mu, 0.0, 1.0, low_open=True, high_open=True)
        positive("yield_displacement", self.yield_displacement)
        smallest = self.yield_displacement / self.mu
        if not self.radius > smallest:
            raise ValueError(f"radius must be > yield_displacement / mu = {smallest:g} m (got "
                             f"{self.radius:g}): on a smaller radius the pendulum's stiffness "
                             "W/R outgrows the friction's μW/Y and the bearing no longer "
                             "slides on friction (real radii: 0.5–10 m)")
        if self.weight is not None and self.mass is not None:
            raise ValueError(f"isolator: give weight [N] or mass [kg], not both (got "
                             f"weight={self.weight!r}, mass={self.mass!r})")
        if self.mass is not None:  # kept as the weight it makes
            object.__setattr__(self, "weight", positive("mass", self.mass) * GRAVITY)
            object.__setattr__(self, "mass", None)
        elif self.weight is not None:
            positive("weight", self.weight)
        self._bouc_wen(1.0)  # checks n, beta, gamma

    @property
    def period(self) -> float:
        """Pendulum (sliding) period ``2π √(R/g)`` [s], independent of the weight."""
        return 2.0 * math.pi * math.sqrt(self.radius / GRAVITY)

    def carrying(self, mass: float) -> FrictionPendulum:
        """The bearing under ``mass`` [kg] when no weight was given."""
        if self.weight is not None:
            return self
        return FrictionPendulum(self.radius, self.mu, mass=mass,
                                yield_displacement=self.yield_displacement, n=self.n,
                                beta=self.beta, gamma=self.gamma)

    def _weight(self) -> float:
        if self.weight is None:
            raise ValueError("isolator: the friction pendulum needs the weight it carries "
                             "(weight [N] or mass [kg])")
        return float(self.weight)

    @property
    def stiffness(self) -> float:
        """``k = W/R + μW/Y`` [N/m]."""
        w = self._weight()
        return w / self.radius + self.mu * w / self.yield_displacement

    def _bouc_wen(self, w: float) -> BoucWen:
        k = w / self.radius + self.mu * w / self.yield_displacement
        return BoucWen(yield_force=k * self.yield_displacement, alpha=(w / self.radius) / k,
                       n=self.n, beta=self.beta, gamma=self.gamma)

    def law(self) -> BoucWen:
        """The Bouc–Wen storey law ``F_y = k Y``, ``α = (W/R)/k`` (module docstring)."""
        return self._bouc_wen(self._weight())

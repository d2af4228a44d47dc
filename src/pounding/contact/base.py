"""The contact-law contract: what every impact law in :mod:`pounding.contact` promises.

A contact law is the link element of the seed paper (Naderpour, Khatami & Barros 2015): a
spring and a dashpot, or a nonlinear generalisation of them, that acts only while the gap
between two bodies is closed. Like an OpenSees uniaxial material it maps a deformation and
its rate to a force, and keeps a small per-impact state.

Contract
--------
1. **Sign convention.** The penetration is ``δ = u_i − u_j − gap`` [m]; ``δ > 0`` while the
   gap is closed. Its rate ``δ̇`` [m/s] is positive while the bodies approach. The contact
   force ``F`` [N] is positive in compression (it pushes the bodies apart).
2. **Open gap.** For ``δ ≤ 0`` the force and both tangents are zero and the trial state is the
   open state (all zeros): nothing is remembered from one impact to the next.
3. **Onset.** When the committed state is open (``state[V0] == 0``) and ``δ > 0``, an impact
   begins: the trial state records the impact velocity ``v0 = max(δ̇, V0_MIN)``. Callers
   evaluate the law at the located instant the gap closes, so ``v0`` is the true impact
   velocity (OpenSees' Hertzdamp, in contrast, takes it from its first trial step after
   contact).
4. **Trial, then commit.** A trial is a pure function of the law's constants, ``(δ, δ̇)``
   and the committed state: compiled, ``trial(p0, p1, p2, δ, δ̇, v0, slip, dmax)`` returns
   ``(F, ∂F/∂δ, ∂F/∂δ̇, v0', slip', dmax')``, the last three the trial state. The caller commits (copies ``out`` over ``committed``) once a
   step, or an event-bounded segment, is accepted. Within a segment where ``δ̇`` keeps its
   sign, ``trial`` evaluated from the segment's starting state is exact for every law here
   (the only path-dependent law, the bilinear element, is piecewise linear in ``δ``).
5. **No tension unless asked.** ``F ≥ 0`` for every law except the Kelvin–Voigt law built
   with ``tension=True``, whose dashpot pulls slightly just before separation.
6. **Data, not code.** A law is a frozen dataclass; its constants are a float64 vector
   (:meth:`ContactLaw.params`) and its family a small integer (:attr:`ContactLaw.code`) that
   the one compiled dispatcher, :func:`pounding.contact.dispatch.contact_trial`, switches on.
   The Python methods call the same compiled function the time-history kernel calls.

The codes and the layout of the state vector (``state[V0]``, ``state[SLIP]``,
``state[DMAX]``) are in :mod:`pounding.contact.codes`; each law's compiled trial is in
:mod:`pounding.contact.kernels`.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass, fields, replace
from typing import ClassVar, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.contact.codes import STATE_SIZE
from pounding.contact.dispatch import check_contact_law, contact_trial, respond_path
from pounding.units import format_value

SYMBOLS: dict[str, str] = {"zeta": "ζ", "chi": "χ", "delta_y": "δy"}
"""How :meth:`ContactLaw.readable` writes a field (its name where not listed)."""


class ContactResponse(NamedTuple):
    """What a law returns for one trial (δ, δ̇).

    Attributes
    ----------
    force : float
        Contact force [N], positive in compression.
    d_delta : float
        Tangent ∂F/∂δ [N/m].
    d_rate : float
        Tangent ∂F/∂δ̇ [N·s/m].
    state : numpy.ndarray
        Trial state (layout: :mod:`pounding.contact.codes`); commit it to keep it.
    """

    force: float
    d_delta: float
    d_rate: float
    state: NDArray[np.float64]


@dataclass(frozen=True)
class ContactLaw(ABC):
    """Base class of every contact law. Read the module docstring for the contract."""

    code: ClassVar[int]
    label: ClassVar[str]
    """Short human name used in tables and plots."""
    source: ClassVar[str] = ""
    """Who the law is named after or comes from, for :meth:`readable` (may be empty)."""
    damping_field: ClassVar[str | None] = None
    """Name of the field that sets energy dissipation (None for elastic laws)."""
    units: ClassVar[dict[str, str]] = {}
    """Unit of each field (``-`` if dimensionless); ``N/m^n`` reads the law's exponent
    ``n`` (:meth:`field_unit`)."""

    @abstractmethod
    def secant_stiffness(self, delta: float) -> float:
        """Secant stiffness ``F/δ`` of the law's elastic backbone (zero rate) at penetration
        ``delta`` [m], in N/m: the scale of the contact's natural period
        ``2π sqrt(m_eff / k)`` (:func:`pounding.integrate.periods.check_contact_periods`)."""

    @abstractmethod
    def params(self) -> NDArray[np.float64]:
        """The law's constants as the float64 vector the compiled dispatcher reads."""

    # ------------------------------------------------------------------ evaluation
    @staticmethod
    def initial_state() -> NDArray[np.float64]:
        """The open state: zeros of length :data:`~pounding.contact.codes.STATE_SIZE`."""
        return np.zeros(STATE_SIZE)

    def trial(self, delta: float, rate: float,
              committed: NDArray[np.float64] | None = None) -> ContactResponse:
        """Force and tangents at (δ [m], δ̇ [m/s]) from a committed state (step 4).

        ``committed=None`` means the open state, so the call starts a new impact at
        ``v0 = δ̇`` when ``δ > 0``.
        """
        check_contact_law(self)
        state = self.initial_state() if committed is None else np.asarray(committed, float)
        out = np.empty(STATE_SIZE)
        f, kd, kr = contact_trial(self.code, self.params(), float(delta), float(rate), state, out)
        return ContactResponse(f, kd, kr, out)

    def respond(self, delta: ArrayLike, rate: ArrayLike) -> NDArray[np.float64]:
        """Force history [N] along a sampled penetration path, committing at every sample.

        Parameters
        ----------
        delta, rate : array_like, shape (n,)
            Penetration [m] and its rate [m/s] at successive instants. An impact's ``v0`` is
            the rate at its first sample with ``δ > 0``; sample the onset itself for an
            exact ``v0``.

        Returns
        -------
        numpy.ndarray, shape (n,)
            Contact force at each sample [N].
        """
        check_contact_law(self)
        d = np.ascontiguousarray(delta, dtype=float)
        r = np.ascontiguousarray(rate, dtype=float)
        if d.shape != r.shape or d.ndim != 1:
            raise ValueError(f"delta and rate must be 1-D arrays of one length "
                             f"(got shapes {d.shape} and {r.shape})")
        return respond_path(self.code, self.params(), d, r)

    def release_function(self):
        """For laws that cannot pull: ``g(δ, δ̇, v0)`` whose downward zero crossing during
        restitution is the instant the force returns to zero with ``δ > 0`` (the bodies
        separate there). ``None`` for laws whose force stays positive until ``δ = 0``.

        Used to locate that instant as an event; the compiled kernel does not need it.
        """
        return None

    # ------------------------------------------------------------------ damping
    @property
    def damping(self) -> float:
        """Value of the damping parameter (:attr:`damping_field`)."""
        if self.damping_field is None:
            raise ValueError(f"{self.label}: this law has no damping parameter")
        return float(getattr(self, self.damping_field))

    def with_damping(self, value: float) -> "ContactLaw":
        """A copy of the law with its damping parameter set to ``value`` (validated)."""
        if self.damping_field is None:
            raise ValueError(f"{self.label}: this law has no damping parameter")
        return replace(self, **{self.damping_field: value})

    def describe(self) -> str:
        """One line: the label and the fields with their values (exact, as ``repr``)."""
        body = ", ".join(f"{f.name}={getattr(self, f.name)!r}" for f in fields(self))
        return f"{self.label}({body})"

    def field_unit(self, name: str) -> str:
        """The unit of field ``name`` (``-`` if dimensionless, ``""`` if not known), with the
        law's exponent in a Hertz stiffness: ``N/m^1.5``."""
        unit = self.units.get(name, "")
        return unit.replace("^n", f"^{getattr(self, 'n'):g}") if "^n" in unit else unit

    def readable(self) -> str:
        """One line for people: the law, its source, each field with its unit in three
        significant digits, e.g. ``nonlinear viscoelastic (Jankowski): k_h = 2.75e9
        N/m^1.5, ζ = 0.368, m_eff = 2.40e5 kg``; a yes/no field by its name or ``no``
        and its name (``no tension``)."""
        parts = []
        for f in fields(self):
            value = getattr(self, f.name)
            if isinstance(value, bool):
                parts.append(f.name if value else f"no {f.name}")
            else:
                parts.append(f"{SYMBOLS.get(f.name, f.name)} = "
                             f"{format_value(value, self.field_unit(f.name))}")
        head = f"{self.label} ({self.source})" if self.source else self.label
        return f"{head}: {', '.join(parts)}"


def m_effective(m1: float, m2: float) -> float:
    """Effective mass of two colliding bodies, ``m1 m2 / (m1 + m2)`` [kg].

    Either mass may be ``inf`` (a rigid wall); then the other mass is returned.
    """
    from pounding.validation import positive

    if np.isinf(m1) and m1 > 0:
        return positive("m2", m2)
    if np.isinf(m2) and m2 > 0:
        return positive("m1", m1)
    a = positive("m1", m1)
    b = positive("m2", m2)
    return a * b / (a + b)

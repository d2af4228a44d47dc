"""Linear contact laws: the gap spring, Kelvin–Voigt, and the modified Kelvin–Voigt law.

All three are the seed paper's link element (eqs 3–5: ``f = k δ + c δ̇``) or a piece of it,
acting only while the gap is closed.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from pounding.contact.base import ContactLaw, m_effective
from pounding.contact.codes import KELVIN_VOIGT, LINEAR_SPRING, MODIFIED_KELVIN_VOIGT
from pounding.validation import non_negative, positive


@dataclass(frozen=True)
class LinearSpring(ContactLaw):
    """Linear elastic gap element, ``F = k δ`` for ``δ > 0`` (seed eq 3, spring alone).

    Parameters
    ----------
    k : float
        Contact stiffness [N/m].

    Notes
    -----
    Conserves energy (e = 1): the classic gap element of Maison & Kasai (1990) and of the
    shaking-table comparisons of Filiatrault et al. (1995) cited by the seed.
    """

    k: float
    code: ClassVar[int] = LINEAR_SPRING
    label: ClassVar[str] = "linear spring"
    units: ClassVar[dict[str, str]] = {"k": "N/m"}

    def __post_init__(self) -> None:
        object.__setattr__(self, "k", positive("k", self.k))

    def secant_stiffness(self, delta: float) -> float:
        """Elastic secant stiffness F/δ at penetration ``delta`` [N/m]: ``k``."""
        return self.k

    def params(self) -> np.ndarray:
        return np.array([self.k])


@dataclass(frozen=True)
class KelvinVoigt(ContactLaw):
    """Linear viscoelastic (Kelvin–Voigt) law, ``F = k δ + c δ̇`` (seed eq 5).

    Source: Anagnostopoulos (1988), EESD 16(3):443–456, with ``c = 2 ζ sqrt(k m_eff)``.

    Parameters
    ----------
    k : float
        Contact stiffness [N/m].
    c : float
        Dashpot coefficient [N·s/m].
    tension : bool
        What happens at the end of contact. ``False`` (default, the physical choice: a
        contact cannot pull two buildings together): the force is clipped,
        ``F = max(k δ + c δ̇, 0)``; the bodies separate when it returns to zero, with the
        spring still compressed; ζ for a target e from Schwager & Pöschel's closed form
        (:func:`~pounding.contact.restitution.zeta_kelvin_voigt_clipped`). ``True`` (the law
        as Anagnostopoulos derived his ζ for, and as OpenSees' ``ViscoelasticGap`` does): the
        dashpot may pull with a tensile force until ``δ = 0``; ζ from
        :func:`~pounding.contact.restitution.zeta_anagnostopoulos`.
    """

    k: float
    c: float
    tension: bool = False
    code: ClassVar[int] = KELVIN_VOIGT
    label: ClassVar[str] = "Kelvin-Voigt"
    source: ClassVar[str] = "Anagnostopoulos"
    damping_field: ClassVar[str | None] = "c"
    units: ClassVar[dict[str, str]] = {"k": "N/m", "c": "N·s/m"}

    def __post_init__(self) -> None:
        object.__setattr__(self, "k", positive("k", self.k))
        object.__setattr__(self, "c", non_negative("c", self.c))
        object.__setattr__(self, "tension", bool(self.tension))

    def secant_stiffness(self, delta: float) -> float:
        """Elastic secant stiffness F/δ at penetration ``delta`` [N/m]: ``k``."""
        return self.k

    def params(self) -> np.ndarray:
        return np.array([self.k, self.c, 1.0 if self.tension else 0.0])

    def describe(self) -> str:
        """One line: the label, the fields, and whether the dashpot may pull."""
        return (f"Kelvin-Voigt(k={self.k!r}, c={self.c!r}, tension={self.tension}: "
                + ("the dashpot may pull until δ = 0)" if self.tension
                   else "no tension, the force clipped at zero)"))

    def release_function(self):
        if self.tension or self.c == 0.0:
            return None
        k, c = self.k, self.c
        return lambda delta, rate, v0: k * delta + c * rate

    @classmethod
    def from_zeta(cls, k: float, zeta: float, m1: float, m2: float,
                  tension: bool = False) -> "KelvinVoigt":
        """Build from an impact damping ratio: ``c = 2 ζ sqrt(k m_eff)``."""
        z = non_negative("zeta", zeta)
        return cls(k=k, c=2.0 * z * np.sqrt(positive("k", k) * m_effective(m1, m2)),
                   tension=tension)

    @classmethod
    def from_restitution(cls, k: float, e: float, m1: float, m2: float,
                         formula: str | None = None, tension: bool = False) -> "KelvinVoigt":
        """Build from a coefficient of restitution via a ζ formula (default: the exact one
        for the chosen end of contact, ``schwager-poschel`` without tension and
        ``anagnostopoulos`` with it)."""
        from pounding.contact.restitution import formula as _formula

        f = _formula(formula or ("anagnostopoulos" if tension else "schwager-poschel"))
        if f.kind != "zeta":
            raise ValueError(f"formula: {formula!r} gives a Hunt-Crossley chi, not a damping ratio")
        return cls.from_zeta(k, float(f(e)), m1, m2, tension=tension)


@dataclass(frozen=True)
class ModifiedKelvinVoigt(ContactLaw):
    """Modified linear viscoelastic law: dashpot only while approaching.

    ``F = k δ + c δ̇`` for ``δ̇ > 0``, ``F = k δ`` for ``δ̇ ≤ 0``; ``c = 2 ζ sqrt(k m_eff)``.

    Source: Mahmoud & Jankowski (2011), Iranian J. Sci. Technol. 35(C1):51–62; its damping
    ratio for ``e`` by default the exact inverse of its restitution
    (:func:`~pounding.contact.exact_restitution.zeta_modified_kelvin_voigt_exact`), of which
    seed eq 20 (:func:`~pounding.contact.restitution.zeta_mahmoud`) is an approximation. No
    tensile force ever arises.

    Parameters
    ----------
    k : float
        Contact stiffness [N/m].
    c : float
        Dashpot coefficient [N·s/m].
    """

    k: float
    c: float
    code: ClassVar[int] = MODIFIED_KELVIN_VOIGT
    label: ClassVar[str] = "modified Kelvin-Voigt"
    source: ClassVar[str] = "Mahmoud & Jankowski"
    damping_field: ClassVar[str | None] = "c"
    units: ClassVar[dict[str, str]] = {"k": "N/m", "c": "N·s/m"}

    def __post_init__(self) -> None:
        object.__setattr__(self, "k", positive("k", self.k))
        object.__setattr__(self, "c", non_negative("c", self.c))

    def secant_stiffness(self, delta: float) -> float:
        """Elastic secant stiffness F/δ at penetration ``delta`` [N/m]: ``k``."""
        return self.k

    def params(self) -> np.ndarray:
        return np.array([self.k, self.c])

    @classmethod
    def from_zeta(cls, k: float, zeta: float, m1: float, m2: float) -> "ModifiedKelvinVoigt":
        """Build from an impact damping ratio: ``c = 2 ζ sqrt(k m_eff)``."""
        z = non_negative("zeta", zeta)
        return cls(k=k, c=2.0 * z * np.sqrt(positive("k", k) * m_effective(m1, m2)))

    @classmethod
    def from_restitution(cls, k: float, e: float, m1: float, m2: float,
                         formula: str = "exact-modified-kelvin-voigt") -> "ModifiedKelvinVoigt":
        """Build from a coefficient of restitution via a ζ formula (default the exact one,
        which achieves ``e``; ``"mahmoud"`` is Mahmoud & Jankowski's eq 20)."""
        from pounding.contact.restitution import formula as _formula

        f = _formula(formula)
        if f.kind != "zeta":
            raise ValueError(f"formula: {formula!r} gives a Hunt-Crossley chi, not a damping ratio")
        return cls.from_zeta(k, float(f(e)), m1, m2)

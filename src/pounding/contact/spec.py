"""What a model file's ``[contact]`` says: a contact law by name and constants, built for
the two floors of each contact (:meth:`ContactSpec.build`)."""

from __future__ import annotations

from dataclasses import dataclass

from pounding.contact.base import ContactLaw
from pounding.contact.factory import make_law
from pounding.memo import Memo

__all__ = ["CONTACT_LAWS", "ContactSpec"]


@dataclass(frozen=True)
class ContactSpec:
    """How to build the contact law of every floor-to-floor contact.

    Fields are those of :func:`pounding.contact.factory.make_law`; the masses ``m1, m2``
    of each contact are the two floor masses that meet, so laws whose damping scales with
    the colliding masses (Kelvin–Voigt from ``e``, Jankowski's eq 18) are built per contact.

    Parameters
    ----------
    law : str
        A name of :data:`pounding.contact.factory.LAW_NAMES`.
    k, k_h : float, optional
        Linear stiffness [N/m] or Hertz stiffness [N/m^n].
    e : float, optional
        Coefficient of restitution (turned into damping by ``formula``).
    formula : str, optional
        Damping formula for ``e`` (default, or ``"exact"``: the one exact for the law,
        :data:`pounding.contact.factory.DEFAULT_FORMULA`; a published one by its key).
    c, zeta, chi : float, optional
        Damping given directly.
    n : float
        Hertz exponent.
    tension : bool
        Kelvin–Voigt only: may the dashpot pull before separation (default no: the force is
        clipped at zero, the physical choice; ``True`` as OpenSees' ``ViscoelasticGap``).
    delta_m : float, optional
        Bilinear element: assumed maximum penetration [m].
    a : float
        Bilinear element: yield ratio δy/δm (Muthukumar's 0.1).
    backbone : str, optional
        Abutment backfill: ``"caltrans"`` (default), ``"elastic-plastic"`` or
        ``"hyperbolic"`` (:func:`pounding.contact.abutment.make_abutment`).
    capacity : float, optional
        Abutment backfill: ultimate passive force [N]; shear key: its capacity [N].
    delta_ult : float, optional
        Abutment backfill, hyperbolic: penetration at the capacity [m].
    backwall_width, backwall_height : float, optional
        Abutment backfill, Caltrans: the backwall's width and height [m].
    fracture_displacement : float, optional
        Shear key (``k``, ``capacity``): the penetration at which it breaks off [m] (None:
        it never breaks; :class:`pounding.contact.shear_key.ShearKey`).
    """

    law: str
    k: float | None = None
    k_h: float | None = None
    e: float | None = None
    formula: str | None = None
    c: float | None = None
    zeta: float | None = None
    chi: float | None = None
    n: float = 1.5
    tension: bool = False
    delta_m: float | None = None
    a: float = 0.1
    backbone: str | None = None
    capacity: float | None = None
    delta_ult: float | None = None
    backwall_width: float | None = None
    backwall_height: float | None = None
    fracture_displacement: float | None = None

    def __post_init__(self) -> None:
        # build once with unit masses so a bad spec fails here, naming its field
        self.build(1.0, 1.0)

    def describe(self) -> str:
        """One line for outputs: the law, the fields given (with units), the damping formula
        ``e`` goes through and whether it is exact for the law (if not, the ``e`` an impact
        of two free bodies achieves with it), and for Kelvin–Voigt whether the dashpot may
        pull."""
        from pounding.contact.factory import resolve_formula

        units = {"k": " N/m", "k_h": f" N/m^{self.n:g}", "c": " N·s/m", "delta_m": " m",
                 "capacity": " N", "delta_ult": " m", "backwall_width": " m",
                 "backwall_height": " m", "fracture_displacement": " m"}
        formula = resolve_formula(self.law, self.formula, self.tension)
        parts = [f"{self.backbone or 'caltrans'} backbone"] if self.law == "abutment" else []
        for name in ("k", "k_h", "e", "c", "zeta", "chi", "delta_m", "capacity", "delta_ult",
                     "backwall_width", "backwall_height", "fracture_displacement"):
            value = getattr(self, name)
            if value is not None:
                via = f" via {formula}{self._exactness()}" if name == "e" and formula else ""
                parts.append(f"{name} = {value:g}{units.get(name, '')}{via}")
        if self.law == "kelvin-voigt":
            parts.append("tension (pulls until δ = 0)" if self.tension
                         else "no tension (clipped at zero)")
        return f"{self.law}: {', '.join(parts)}" if parts else self.law

    def _exactness(self) -> str:
        """`` (exact)`` if the formula gives the law exactly ``e`` in an impact of two free
        bodies (the bilinear element: one reaching ``delta_m``); otherwise the ``e`` such an
        impact achieves with it."""
        from pounding.contact.factory import is_exact

        if is_exact(self.law, self.formula, self.tension):
            return " (exact" + (" for an impact reaching delta_m)" if self.law == "bilinear-impact"
                                else ")")
        # (only here: calibration loads SciPy's optimizers and the collision integrator)
        from pounding.contact.calibration import restitution_of

        law = self.build(1.0, 1.0)
        achieved = restitution_of(law, 1.0, 1.0)
        if achieved is None:  # the bilinear element: at the penetration it is sized for
            achieved = law.restitution_at(self.delta_m)  # type: ignore[attr-defined]
            return f" (not exact: an impact reaching delta_m achieves e = {achieved:.4f})"
        return f" (not exact: an impact of two free bodies achieves e = {achieved:.4f})"

    def build(self, m1: float, m2: float) -> ContactLaw:
        """The contact law between two floors of masses ``m1`` and ``m2`` [kg].

        Remembered (:data:`CONTACT_LAWS`, keyed by the spec's and the masses' exact
        values): the cases of a sweep that share a law build it once. (A law is immutable.)
        """
        return CONTACT_LAWS.get((repr(self), repr(m1), repr(m2)), lambda: make_law(
            self.law, k=self.k, k_h=self.k_h, e=self.e, formula=self.formula, c=self.c,
            zeta=self.zeta, chi=self.chi, m1=m1, m2=m2, n=self.n, tension=self.tension,
            delta_m=self.delta_m, a=self.a, backbone=self.backbone, capacity=self.capacity,
            delta_ult=self.delta_ult, backwall_width=self.backwall_width,
            backwall_height=self.backwall_height,
            fracture_displacement=self.fracture_displacement))


CONTACT_LAWS = Memo(max_items=256)
"""Contact laws made by :meth:`ContactSpec.build`."""

"""Build a contact law from a name and engineering inputs, as a config file or the command
line gives them: a stiffness, and either a damping value or a coefficient of restitution
with the formula that turns it into damping.
"""

from __future__ import annotations

from pounding.contact.abutment import AbutmentBackfill, make_abutment
from pounding.contact.base import ContactLaw, m_effective
from pounding.contact.bilinear import BILINEAR_FORMULAS, BilinearImpact
from pounding.contact.hertz import Hertz, HuntCrossley, NonlinearViscoelastic
from pounding.contact.linear import KelvinVoigt, LinearSpring, ModifiedKelvinVoigt
from pounding.contact.names import IMPACT_LAW_NAMES, LAW_NAMES  # noqa: F401  (also named here)
from pounding.contact.restitution import FORMULAS, formula as get_formula
from pounding.contact.shear_key import ShearKey
from pounding.validation import choice

LAWS: dict[str, type[ContactLaw]] = {
    "linear-spring": LinearSpring,
    "kelvin-voigt": KelvinVoigt,
    "modified-kelvin-voigt": ModifiedKelvinVoigt,
    "hertz": Hertz,
    "hunt-crossley": HuntCrossley,
    "nonlinear-viscoelastic": NonlinearViscoelastic,
    "bilinear-impact": BilinearImpact,
    "abutment": AbutmentBackfill,
    "shear-key": ShearKey,
}
"""Every contact law class, keyed by the name used in configs and on the command line."""

DEFAULT_FORMULA: dict[str, str] = {
    "kelvin-voigt": "schwager-poschel",
    "modified-kelvin-voigt": "exact-modified-kelvin-voigt",
    "hunt-crossley": "exact-hunt-crossley",
    "hertzdamp": "exact-hunt-crossley",
    "nonlinear-viscoelastic": "exact-nonlinear-viscoelastic",
    "naderpour": "naderpour",
    "bilinear-impact": "exact-bilinear",
}
"""The formula each damped law uses for ``e`` unless told otherwise: the exact inverse of
the law's own restitution, so that an impact of two free bodies achieves the ``e`` asked
for (for Kelvin–Voigt, the exact one for its end of contact: ``schwager-poschel`` without
tension, ``anagnostopoulos`` with it, :func:`default_formula`; for the bilinear element,
exact for the impact that reaches ``delta_m``). The one exception is ``naderpour``, whose
name is the seed's eq 39 (it misses e: 0.157 for 0.65; ``nonlinear-viscoelastic`` is the
same law with the exact ζ). The published formulas stay available by name
(``formula = "lankarani-nikravesh"``, ``"mahmoud"``, ``"jankowski"``, ``"muthukumar"``…);
``formula = "exact"`` names the default."""


def default_formula(law: str, tension: bool = False) -> str | None:
    """The damping formula a law uses for ``e`` when none is named: the exact one
    (:data:`DEFAULT_FORMULA`; Kelvin–Voigt's for its end of contact, Anagnostopoulos with
    tension), None for a law without damping."""
    if law == "kelvin-voigt" and tension:
        return "anagnostopoulos"
    return DEFAULT_FORMULA.get(law)


def resolve_formula(law: str, formula: str | None, tension: bool = False) -> str | None:
    """The key of the formula a law uses: ``formula`` as given, its default when None, and
    the law's exact one for ``"exact"`` (:func:`default_formula`)."""
    if formula is None:
        return default_formula(law, tension)
    key = str(formula).strip().lower()
    if key == "exact":
        if law == "naderpour":
            raise ValueError("formula: the naderpour law is the seed's eq 39 (got 'exact'); "
                             "for the exact damping of the same law use law = "
                             "\"nonlinear-viscoelastic\"")
        return default_formula(law, tension)
    return key


def is_exact(law: str, formula: str | None, tension: bool = False) -> bool:
    """True if ``formula`` (None: the default) gives ``law`` exactly the ``e`` asked for in
    an impact of two free bodies (for the bilinear element: one that reaches ``delta_m``)."""
    key = resolve_formula(law, formula, tension)
    if law == "kelvin-voigt":
        return key == ("anagnostopoulos" if tension else "schwager-poschel")
    return key == DEFAULT_FORMULA.get(law) and law != "naderpour"


def _need(name: str, value: float | None, law: str) -> float:
    if value is None:
        raise ValueError(f"{name}: required for the {law} law")
    return value


def make_law(name: str, *, k: float | None = None, k_h: float | None = None,
             e: float | None = None, formula: str | None = None, c: float | None = None,
             zeta: float | None = None, chi: float | None = None, m1: float | None = None,
             m2: float | None = None, n: float = 1.5, tension: bool = False,
             delta_m: float | None = None, a: float = 0.1, backbone: str | None = None,
             capacity: float | None = None, delta_ult: float | None = None,
             backwall_width: float | None = None,
             backwall_height: float | None = None,
             fracture_displacement: float | None = None) -> ContactLaw:
    """Build a contact law by name.

    Parameters
    ----------
    name : str
        One of :data:`LAW_NAMES`.
    k : float
        Stiffness of the linear laws [N/m].
    k_h : float
        Hertz stiffness of the nonlinear laws [N/m^n].
    e : float
        Coefficient of restitution; converted to damping by ``formula``.
    formula : str
        A key of :data:`pounding.contact.restitution.FORMULAS` (for the bilinear element,
        of :data:`pounding.contact.bilinear.BILINEAR_FORMULAS`), or ``"exact"``; default
        :data:`DEFAULT_FORMULA` for the law, exact for it. ``naderpour`` fixes it to eq 39.
    c, zeta, chi : float
        Damping given directly instead of ``e``: dashpot [N·s/m], damping ratio, or
        Hunt–Crossley factor.
    m1, m2 : float
        Masses of the colliding bodies [kg] (needed where damping scales with them).
    n : float
        Hertz exponent (Hertz and Hunt–Crossley).
    tension : bool
        Kelvin–Voigt only: whether the dashpot may pull before separation (default no: the
        force is clipped at zero, and ζ for ``e`` is then Schwager & Pöschel's exact one).
    delta_m : float
        Bilinear element: assumed maximum penetration [m].
    a : float
        Bilinear element: yield ratio δy/δm.
    backbone, capacity, delta_ult, backwall_width, backwall_height
        Abutment backfill (:func:`pounding.contact.abutment.make_abutment`): the backbone
        (``caltrans`` from the backwall's width and height [m], ``elastic-plastic`` from
        ``k`` and ``capacity`` [N], ``hyperbolic`` from ``k``, ``capacity`` and
        ``delta_ult`` [m]).
    fracture_displacement : float
        Shear key (``k`` [N/m], ``capacity`` [N]): the penetration at which it breaks off
        [m] (:class:`pounding.contact.shear_key.ShearKey`; None: it never breaks).

    Returns
    -------
    ContactLaw
    """
    law = choice("law", name, LAW_NAMES)
    damping_keys = (("k_h", k_h), ("e", e), ("formula", formula), ("c", c), ("zeta", zeta),
                    ("chi", chi), ("delta_m", delta_m))
    if law == "shear-key":
        for key, value in (*damping_keys, ("backbone", backbone), ("delta_ult", delta_ult),
                           ("backwall_width", backwall_width),
                           ("backwall_height", backwall_height)):
            if value is not None:
                raise ValueError(f"{key}: not read by the shear-key law (got {value!r}); it "
                                 "reads k, capacity, fracture_displacement")
        return ShearKey(_need("k", k, law), _need("capacity", capacity, law),
                        fracture_displacement)
    if fracture_displacement is not None:
        raise ValueError(f"fracture_displacement: read only by the shear-key law (got "
                         f"{fracture_displacement!r} for the {law} law)")
    abutment_keys = {"backbone": backbone, "capacity": capacity, "delta_ult": delta_ult,
                     "backwall_width": backwall_width, "backwall_height": backwall_height}
    if law == "abutment":
        for key, value in damping_keys:
            if value is not None:
                raise ValueError(f"{key}: not read by the abutment law (got {value!r}); its "
                                 "backfill dissipates by yielding, not by a dashpot")
        return make_abutment(backbone, k=k, capacity=capacity, delta_ult=delta_ult,
                             backwall_width=backwall_width, backwall_height=backwall_height)
    for key, value in abutment_keys.items():
        if value is not None:
            raise ValueError(f"{key}: read only by the abutment law (got {value!r} for the "
                             f"{law} law)")
    if formula is not None and law == "naderpour" and formula != "naderpour":
        resolve_formula(law, formula)  # 'exact': says which law has the exact ζ
        raise ValueError(f"formula: the naderpour law uses eq 39 (got {formula!r})")
    if sum(x is not None for x in (e, c, zeta, chi)) > 1:
        raise ValueError(f"{law}: give only one of e, c, zeta, chi")
    if law in ("linear-spring", "hertz"):
        for key, value in (("e", e), ("formula", formula), ("c", c), ("zeta", zeta),
                           ("chi", chi)):
            if value is not None:
                raise ValueError(f"{key}: the {law} law is elastic, it has no damping (e = 1; "
                                 f"got {key} = {value!r}); choose a damped law such as "
                                 f"{'kelvin-voigt' if law == 'linear-spring' else 'hunt-crossley'}")

    def damping_ratio() -> float:
        if zeta is not None:
            return zeta
        f = get_formula(resolve_formula(law, formula, tension))  # type: ignore[arg-type]
        if f.kind != "zeta":
            raise ValueError(f"formula: {f.key!r} gives a Hunt-Crossley chi; the {law} law "
                             f"needs a damping ratio formula")
        return float(f(_need("e", e, law)))

    if law == "linear-spring":
        return LinearSpring(_need("k", k, law))
    if law == "hertz":
        return Hertz(_need("k_h", k_h, law), n)
    if law in ("kelvin-voigt", "modified-kelvin-voigt"):
        kk = _need("k", k, law)
        if c is None:
            c = 2.0 * damping_ratio() * (kk * m_effective(_need("m1", m1, law),
                                                          _need("m2", m2, law))) ** 0.5
        if law == "kelvin-voigt":
            return KelvinVoigt(kk, c, tension)
        return ModifiedKelvinVoigt(kk, c)
    if law in ("hunt-crossley", "hertzdamp"):
        if chi is None:
            f = get_formula(resolve_formula(law, formula))  # type: ignore[arg-type]
            if f.kind != "chi":
                raise ValueError(f"formula: {f.key!r} gives a damping ratio; the {law} law "
                                 f"needs a chi formula ({', '.join(k_ for k_, v in FORMULAS.items() if v.kind == 'chi')})")
            chi = float(f(_need("e", e, law)))
        return HuntCrossley(_need("k_h", k_h, law), chi, n)
    if law in ("nonlinear-viscoelastic", "naderpour"):
        return NonlinearViscoelastic(_need("k_h", k_h, law), damping_ratio(),
                                     m_effective(_need("m1", m1, law), _need("m2", m2, law)))
    # bilinear-impact
    key = choice("formula", resolve_formula(law, formula), BILINEAR_FORMULAS)  # type: ignore[arg-type]
    return getattr(BilinearImpact, BILINEAR_FORMULAS[key])(
        _need("k_h", k_h, law), _need("e", e, law), _need("delta_m", delta_m, law), a, n)

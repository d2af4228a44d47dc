"""The passive resistance of an abutment's backfill, as a one-sided contact law.

In a bridge's longitudinal model the deck's end closes the gap to the abutment's backwall,
then pushes the backwall into the backfill and mobilises its passive resistance. The force
is compression only; loading follows a backbone, unloading and reloading the initial
stiffness, and what the backfill does not give back is a permanent set: after unloading the
deck finds a larger gap (as OpenSees' ``HyperbolicGapMaterial``, Wilson & Elgamal, does).

Backbones (both are the one curve ``F = min(δ/(A + B δ), F_ult)``, ``A = 1/K``):

* **Caltrans SDC** (elastic–perfectly-plastic; Caltrans Seismic Design Criteria, the
  longitudinal abutment response: SDC 1.7 (2013) §7.8.1; SDC 2.0 (2019) moved it into its
  Section 6 on abutments, clause number not checked here):
  ``K_abut = K_i w (h / 5.5 ft)`` with ``K_i = 50 kip/in/ft`` (per foot of backwall
  width) and ``P_bw = A_e · 5.0 ksf · (h / 5.5 ft)``, ``A_e = w h`` the backwall's
  effective area. In SI (converted here, 1 kip = 4448.2216 N, 1 in = 0.0254 m,
  1 ft = 0.3048 m): ``K_i = 2.8728e7 N/m per m``, ``5.0 ksf = 239.40 kPa``,
  ``5.5 ft = 1.6764 m``. It is the case ``B = 0``: ``δ_ult = P_bw / K_abut``.
* **Hyperbolic** (Shamsabadi, Rollins & Kapuskar 2007, "Nonlinear soil–abutment–bridge
  structure interaction for seismic performance-based design", J. Geotech. Geoenviron.
  Eng. 133(6):707–720, the hyperbolic force–displacement "HFD" model): ``F = δ/(A + B δ)``
  with ``A = 1/K_max`` (the initial stiffness) and ``B`` such that ``F(δ_ult) = F_ult``:
  ``B = 1/F_ult − 1/(K_max δ_ult)``; beyond ``δ_ult`` the force stays at ``F_ult``.
  OpenSees' ``HyperbolicGapMaterial`` (Kmax, Kur, Rf, Fult, gap) is the same hyperbola
  with ``B = Rf/Fult`` (its documentation page and source: envelope
  ``(δ)/(1/Kmax + Rf δ/Fult)``, unloading at Kur to zero force, reloading at Kur from the
  strain where the force vanished back to the envelope), without the cap at ``F_ult``.

What could not be checked here: the papers' and the SDC's own text (not readable in the
references at hand: the SDC 2.0 clause number and whether its ``A_e`` is ``w h``; the HFD
parameters' derivation from ``K_max``, ``F_ult``, ``δ_ult`` is the algebra above, not
read from Shamsabadi et al.). OpenSees' source and documentation were read.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from pounding.contact.base import ContactLaw
from pounding.contact.codes import ABUTMENT
from pounding.validation import positive

KIP: float = 4448.2216152605
"""One kip [N]."""
INCH: float = 0.0254
"""One inch [m]."""
FOOT: float = 0.3048
"""One foot [m]."""

SDC_STIFFNESS_PER_WIDTH: float = 50.0 * KIP / INCH / FOOT
"""Caltrans SDC's ``K_i = 50 kip/in/ft`` of backwall width, in SI [N/m per m]: 2.8728e7."""
SDC_PASSIVE_PRESSURE: float = 5.0 * 1000.0 * 4.4482216152605 / FOOT**2
"""Caltrans SDC's passive pressure ``5.0 ksf`` in SI [Pa]: 239,400."""
SDC_REFERENCE_HEIGHT: float = 5.5 * FOOT
"""Caltrans SDC's reference backwall height ``5.5 ft`` [m]: 1.6764."""

BACKBONES: tuple[str, ...] = ("caltrans", "elastic-plastic", "hyperbolic")
"""How a model file names the backbone (:func:`make_abutment`)."""


@dataclass(frozen=True)
class AbutmentBackfill(ContactLaw):
    """The backfill behind an abutment's backwall (module docstring).

    Parameters
    ----------
    K : float
        Initial (and unloading/reloading) stiffness [N/m].
    capacity : float
        Ultimate passive force F_ult [N].
    delta_ult : float
        Penetration at which the backbone reaches ``capacity`` [m]; ``capacity / K`` (the
        least it can be) makes the backbone elastic–perfectly-plastic, a larger value the
        hyperbola ``δ/(A + B δ)`` through ``(delta_ult, capacity)``.

    See Also
    --------
    AbutmentBackfill.caltrans : the Caltrans SDC backbone of a backwall.
    AbutmentBackfill.hyperbolic : Shamsabadi et al.'s (2007) hyperbolic backbone.
    """

    K: float
    capacity: float
    delta_ult: float
    code: ClassVar[int] = ABUTMENT
    label: ClassVar[str] = "abutment backfill"
    source: ClassVar[str] = ""
    units: ClassVar[dict[str, str]] = {"K": "N/m", "capacity": "N", "delta_ult": "m"}

    def __post_init__(self) -> None:
        k = positive("K", self.K)
        fu = positive("capacity", self.capacity)
        yu = positive("delta_ult", self.delta_ult)
        if yu < fu / k * (1.0 - 1e-12):
            raise ValueError(f"delta_ult: the backbone reaches capacity {fu:g} N at stiffness "
                             f"{k:g} N/m no earlier than capacity/K = {fu / k:.6g} m "
                             f"(got {yu:g} m)")
        object.__setattr__(self, "K", k)
        object.__setattr__(self, "capacity", fu)
        object.__setattr__(self, "delta_ult", max(yu, fu / k))

    @classmethod
    def caltrans(cls, width: float, height: float) -> AbutmentBackfill:
        """Caltrans SDC's elastic–perfectly-plastic backfill of a backwall ``width`` ×
        ``height`` [m]: ``K = K_i w (h/5.5 ft)``, ``F_ult = w h · 5.0 ksf · (h/5.5 ft)``
        (in SI, :data:`SDC_STIFFNESS_PER_WIDTH`, :data:`SDC_PASSIVE_PRESSURE`,
        :data:`SDC_REFERENCE_HEIGHT`)."""
        w = positive("backwall_width", width)
        h = positive("backwall_height", height)
        ratio = h / SDC_REFERENCE_HEIGHT
        k = SDC_STIFFNESS_PER_WIDTH * w * ratio
        fu = w * h * SDC_PASSIVE_PRESSURE * ratio
        return cls(k, fu, fu / k)

    @classmethod
    def elastic_plastic(cls, k: float, capacity: float) -> AbutmentBackfill:
        """The elastic–perfectly-plastic backfill of stiffness ``k`` [N/m] and capacity
        [N]."""
        kk = positive("k", k)
        fu = positive("capacity", capacity)
        return cls(kk, fu, fu / kk)

    @classmethod
    def hyperbolic(cls, k_max: float, capacity: float, delta_ult: float) -> AbutmentBackfill:
        """Shamsabadi et al.'s (2007) hyperbolic backfill: initial stiffness ``k_max``
        [N/m], ``F_ult = capacity`` [N] reached at ``delta_ult`` [m]."""
        return cls(positive("k", k_max), capacity, delta_ult)

    @property
    def hyperbola(self) -> tuple[float, float]:
        """``(A, B)`` of the backbone ``δ/(A + B δ)``: ``A = 1/K`` [m/N],
        ``B = 1/F_ult − 1/(K δ_ult)`` [1/N] (0 for the elastic–perfectly-plastic one)."""
        return 1.0 / self.K, max(1.0 / self.capacity - 1.0 / (self.K * self.delta_ult), 0.0)

    def backbone(self, delta: float) -> float:
        """The backbone's force [N] at penetration ``delta`` [m] (0 for δ ≤ 0)."""
        if delta <= 0.0:
            return 0.0
        a, b = self.hyperbola
        return min(delta / (a + b * delta), self.capacity)

    def secant_stiffness(self, delta: float) -> float:
        """Secant ``F/δ`` of the backbone [N/m]: ``K`` at δ → 0."""
        if delta <= 0.0:
            return self.K
        return self.backbone(delta) / delta

    def params(self) -> np.ndarray:
        return np.array([self.K, self.capacity, self.delta_ult])


def make_abutment(backbone: str | None, *, k: float | None = None,
                  capacity: float | None = None, delta_ult: float | None = None,
                  backwall_width: float | None = None,
                  backwall_height: float | None = None) -> AbutmentBackfill:
    """The backfill a model file or command line describes: ``backbone = "caltrans"``
    (``backwall_width``, ``backwall_height`` [m]; the default), ``"elastic-plastic"``
    (``k`` [N/m], ``capacity`` [N]) or ``"hyperbolic"`` (``k`` = K_max, ``capacity`` =
    F_ult, ``delta_ult`` [m]). A key the backbone does not read is an error naming it."""
    from pounding.validation import choice

    kind = choice("backbone", backbone or "caltrans", BACKBONES)
    given = {"k": k, "capacity": capacity, "delta_ult": delta_ult,
             "backwall_width": backwall_width, "backwall_height": backwall_height}
    reads = {"caltrans": ("backwall_width", "backwall_height"),
             "elastic-plastic": ("k", "capacity"),
             "hyperbolic": ("k", "capacity", "delta_ult")}[kind]
    for key, value in given.items():
        if value is not None and key not in reads:
            raise ValueError(f"{key}: not read by the {kind} backbone of the abutment law "
                             f"(got {value!r}); it reads {', '.join(reads)}")
    for key in reads:
        if given[key] is None:
            raise ValueError(f"{key}: required for the {kind} backbone of the abutment law")
    if kind == "caltrans":
        return AbutmentBackfill.caltrans(backwall_width, backwall_height)  # type: ignore[arg-type]
    if kind == "elastic-plastic":
        return AbutmentBackfill.elastic_plastic(k, capacity)  # type: ignore[arg-type]
    return AbutmentBackfill.hyperbolic(k, capacity, delta_ult)  # type: ignore[arg-type]

"""A frame of a bridge along its axis: one deck segment on its piers, through its bearings.

A longitudinal bridge model is a row of *frames* (deck segments between expansion joints)
that pound across the joints (:mod:`pounding.structure.bridge.bridge`). One frame is

* the **deck**: a rigid mass, one DOF along the bridge's axis at the deck's elevation
  (DOF 0, ``F1`` in outputs) — or across it, in a transverse model
  (:mod:`pounding.structure.bridge.transverse`: every element's numbers then of that
  direction);
* a **cap** per pier (DOF ``i``, ``F(i+1)``): the pier cap's mass and the share of the column
  that moves with it (given);
* a **pier** per cap: an element between the ground and the cap, linear (``stiffness``,
  :func:`pier_stiffness` from the section's EI, its height and fixity) or following a
  storey law of :mod:`pounding.hysteresis` (:class:`~pounding.hysteresis.Bilinear`,
  :class:`~pounding.hysteresis.BoucWen`; its initial stiffness the pier's);
* a **bearing** per pier: an element between the cap and the deck — elastomeric (linear
  ``k`` and a dashpot ``c``), an isolator of :mod:`pounding.hysteresis.isolators`
  (:class:`~pounding.hysteresis.isolators.BilinearIsolator` for lead-rubber,
  :class:`~pounding.hysteresis.isolators.FrictionPendulum`), or a flat sliding bearing
  (:meth:`Bearing.sliding`: friction ``μ W`` regularised over a small stick displacement
  ``Y``, the Bouc–Wen law with ``α = 0`` of Constantinou, Mokha & Reinhorn 1990, "Teflon
  bearings in base isolation II: modeling", J. Struct. Eng. 116(2):455–474). There is no
  rigid-plastic (pure Coulomb) law in :mod:`pounding.hysteresis`: the slider always has its
  stick stiffness ``μW/Y``.

A :class:`BridgeFrame` is a :class:`~pounding.structure.MatrixBuilding`: ``M`` lumped,
``K`` the initial stiffness of every element (its periods, :meth:`~MatrixBuilding.modes`),
``C`` its damping; the nonlinear elements are its *element rows*, each with its own law
(:meth:`BridgeFrame.element_rows`, :mod:`pounding.structure.element_rows`), and the
stiffness handed to the time stepper holds the linear elements only
(:meth:`BridgeFrame.linear_stiffness_matrix`). Its floor and its faces — what a neighbour
strikes, what a link joins — are the deck alone: decks strike decks across the joints and
the abutments; caps strike nothing.

Damping (:meth:`BridgeFrame.damping_matrix`): Rayleigh per frame,
``C = a₀ M + a₁ K_lin + Σ c_b``, ``a₀, a₁`` giving ``zeta`` at the frame's modes 1 and 2 on
its initial stiffness (Chopra §11.4.1), the stiffness-proportional part on the *linear*
elements only, plus each bearing's own dashpot. Per frame because a frame is a building of
the row (the row's ``C`` is block-diagonal, and the frames are uncoupled but through
contacts and links, so the elastic modes of the whole bridge are the frames' own). The
stiffness-proportional part leaves out an element that yields or slides: a damper sized on
its initial (stick) stiffness would resist the sliding with forces that are not there —
the lesson of Ryan & Polanco 2008 ("Problems with Rayleigh damping in base-isolated
buildings", J. Struct. Eng. 134(11):1780–1784) for isolators; such an element dissipates by
its hysteresis and its dashpot.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from pounding.hysteresis.base import StoreyLaw
from pounding.hysteresis.bouc_wen import BoucWen
from pounding.hysteresis.isolators import GRAVITY, Isolator
from pounding.structure.damping import rayleigh_coefficients
from pounding.structure.element_rows import ElementRow
from pounding.structure.matrices import MatrixBuilding
from pounding.validation import in_range, non_negative, positive

__all__ = ["FIXITIES", "Bearing", "BridgeFrame", "Pier", "pier_stiffness"]

FIXITIES: dict[str, float] = {"cantilever": 3.0, "fixed": 12.0}
"""Lateral stiffness of a prismatic column ``k = coefficient · EI / H³``: ``cantilever``
(fixed at the foot, free to rotate at the cap: 3) and ``fixed`` (fixed at the foot, the
cap kept from rotating by a stiff deck or cap beam: 12)."""


def pier_stiffness(ei: float, height: float, fixity: str = "cantilever",
                   columns: int = 1) -> float:
    """Lateral stiffness [N/m] of a pier of ``columns`` equal prismatic columns of flexural
    rigidity ``ei`` [N·m²] and clear height ``height`` [m]: ``columns · c · EI / H³``, ``c``
    = 3 (cantilever) or 12 (fixed against rotation at the cap) (:data:`FIXITIES`; Chopra
    §1.3, shear deformation neglected).

    >>> pier_stiffness(1.0e10, 10.0, "fixed")
    120000000.0
    """
    if fixity not in FIXITIES:
        raise ValueError(f"fixity: {fixity!r} is not one of {', '.join(FIXITIES)}")
    if not (isinstance(columns, int) and columns >= 1):
        raise ValueError(f"columns: need a whole number ≥ 1 (got {columns!r})")
    return columns * FIXITIES[fixity] * positive("EI", ei) / positive("height", height) ** 3


@dataclass(frozen=True)
class Pier:
    """A pier: its cap's DOF and the element between it and the ground.

    Parameters
    ----------
    height : float
        Elevation of the cap (the bearing seat) above the ground [m].
    stiffness : float
        Lateral stiffness of the pier at the cap [N/m] (:func:`pier_stiffness`); the initial
        stiffness of its law if it has one.
    mass : float
        Mass moving with the cap [kg]: the cap and the share of the column (often a third
        of a cantilever column's, Priestley, Seible & Calvi 1996 §5.2).
    law : StoreyLaw, optional
        The pier's force–drift law (:class:`~pounding.hysteresis.Bilinear`,
        :class:`~pounding.hysteresis.BoucWen`, with its yield force or drift); linear if
        None.
    """

    height: float
    stiffness: float
    mass: float
    law: StoreyLaw | None = None

    def __post_init__(self) -> None:
        positive("height", self.height)
        positive("stiffness", self.stiffness)
        positive("mass", self.mass)
        if self.law is not None and not isinstance(self.law, StoreyLaw):
            raise ValueError(f"law: expected a storey law such as Bilinear or BoucWen (got "
                             f"{type(self.law).__name__})")


@dataclass(frozen=True)
class Bearing:
    """A bearing between a pier's cap and the deck.

    Build one with :meth:`elastomeric`, :meth:`isolator` or :meth:`sliding`.

    Parameters
    ----------
    stiffness : float
        Its (initial) stiffness [N/m].
    damping : float
        Its dashpot ``c`` [N·s/m] (default 0).
    law : StoreyLaw, optional
        Its force–displacement law (None: linear).
    kind : str
        ``"elastomeric"``, ``"isolator"`` or ``"sliding"`` (for outputs).
    """

    stiffness: float
    damping: float = 0.0
    law: StoreyLaw | None = None
    kind: str = "elastomeric"

    def __post_init__(self) -> None:
        positive("stiffness", self.stiffness)
        non_negative("damping", self.damping)

    @classmethod
    def elastomeric(cls, stiffness: float, damping: float = 0.0) -> Bearing:
        """A laminated elastomeric bearing: linear shear stiffness ``k = G A / h_r`` [N/m]
        and a dashpot ``c`` [N·s/m]."""
        return cls(stiffness, damping)

    @classmethod
    def isolator(cls, isolator: Isolator, damping: float = 0.0) -> Bearing:
        """An isolation bearing (:class:`~pounding.hysteresis.isolators.BilinearIsolator`,
        :class:`~pounding.hysteresis.isolators.FrictionPendulum` with the weight it
        carries): its initial stiffness and law."""
        return cls(isolator.stiffness, damping, isolator.law(), "isolator")

    @classmethod
    def sliding(cls, mu: float, weight: float, yield_displacement: float = 5e-4,
                damping: float = 0.0) -> Bearing:
        """A flat sliding bearing (PTFE on steel): friction ``μ W`` built up over the stick
        displacement ``Y`` [m], the Bouc–Wen law with ``α = 0``, ``n = 2``, ``β = γ = ½``,
        ``k = μW/Y``, ``F_y = μW`` (Constantinou et al. 1990; the friction pendulum of
        :mod:`pounding.hysteresis.isolators` with an infinite radius).

        Parameters
        ----------
        mu : float
            Friction coefficient (0 < μ < 1), constant.
        weight : float
            Weight carried [N].
        yield_displacement : float
            ``Y`` [m] (default 0.5 mm).
        """
        in_range("mu", mu, 0.0, 1.0, low_open=True, high_open=True)
        w = positive("weight", weight)
        y = positive("yield_displacement", yield_displacement)
        law = BoucWen(yield_force=mu * w, alpha=0.0, n=2.0, beta=0.5, gamma=0.5)
        return cls(mu * w / y, damping, law, "sliding")


def _element_stiffness(n: int, elements: Sequence[tuple[int, int, float]]) -> NDArray[np.float64]:
    """Stiffness matrix [N/m] of axial springs ``(lower, upper, k)`` (lower −1: the ground)."""
    k_mat = np.zeros((n, n))
    for lo, hi, k in elements:
        k_mat[hi, hi] += k
        if lo >= 0:
            k_mat[lo, lo] += k
            k_mat[lo, hi] -= k
            k_mat[hi, lo] -= k
    return k_mat


class BridgeFrame(MatrixBuilding):
    """One frame of a bridge: a rigid deck on piers through bearings (module docstring).

    Parameters
    ----------
    deck_mass : float
        Mass of the deck segment [kg] (with what moves with it: barriers, surfacing).
    piers : sequence of Pier
        Its piers (at least one).
    bearings : Bearing or sequence of Bearing
        One bearing per pier (one given: the same on every pier).
    deck_elevation : float, optional
        Elevation of the deck's DOF [m] (where it strikes its neighbours and the
        abutments); default the tallest pier's.
    zeta : float
        Damping ratio of the frame's modes 1 and 2 (default 0.05; module docstring).
    name : str
        A label.
    spans : sequence of float, optional
        The span lengths of the deck segment [m], left to right (its length along the axis
        is their sum, :attr:`deck_length`: the ``L`` of a seat-width clause,
        :mod:`pounding.structure.seat_width`); None if not given (the dynamics do not read
        it).

    Examples
    --------
    >>> frame = BridgeFrame(2.0e6, [Pier(8.0, 5.0e7, 1.0e5)], Bearing.elastomeric(2.0e7),
    ...                     spans=[30.0, 30.0])
    >>> frame.labels, frame.n, frame.deck_length
    (('deck', 'cap1'), 2, 60.0)
    """

    def __init__(self, deck_mass: float, piers: Sequence[Pier],
                 bearings: Bearing | Sequence[Bearing], deck_elevation: float | None = None,
                 zeta: float = 0.05, name: str = "",
                 spans: Sequence[float] | None = None) -> None:
        positive("deck_mass", deck_mass)
        spans_ = None if spans is None else tuple(float(s) for s in spans)
        if spans_ is not None:
            if not spans_:
                raise ValueError("spans: give at least one span length [m] (or None)")
            for i, s in enumerate(spans_):
                positive(f"spans[{i}]", s)
        piers_ = tuple(piers)
        if not piers_ or not all(isinstance(p, Pier) for p in piers_):
            raise ValueError("piers: give at least one Pier")
        bearings_ = ((bearings,) * len(piers_) if isinstance(bearings, Bearing)
                     else tuple(bearings))
        if len(bearings_) != len(piers_) or not all(isinstance(b, Bearing) for b in bearings_):
            raise ValueError(f"bearings: need one Bearing per pier ({len(piers_)}; got "
                             f"{len(bearings_)})")
        tallest = max(p.height for p in piers_)
        z_deck = tallest if deck_elevation is None else positive("deck_elevation",
                                                                  deck_elevation)
        if z_deck < tallest:
            raise ValueError(f"deck_elevation: {z_deck:g} m is below the tallest pier's cap "
                             f"({tallest:g} m)")
        in_range("zeta", zeta, 0.0, 1.0, high_open=True)
        n = 1 + len(piers_)
        masses = np.array([float(deck_mass), *(p.mass for p in piers_)])
        M = np.diag(masses)
        # elements: pier i (ground → cap i), bearing i (cap i → deck)
        elements = [(-1, i + 1, float(p.stiffness)) for i, p in enumerate(piers_)]
        elements += [(i + 1, 0, float(b.stiffness)) for i, b in enumerate(bearings_)]
        laws = [p.law for p in piers_] + [b.law for b in bearings_]
        K = _element_stiffness(n, elements)
        K_lin = _element_stiffness(n, [e for e, law in zip(elements, laws) if law is None])
        # Rayleigh at modes 1 and 2 of the initial stiffness, a₁ on the linear elements
        import scipy.linalg

        w2 = scipy.linalg.eigh(K, M, eigvals_only=True)
        w = np.sqrt(np.maximum(w2, 0.0))
        a0, a1 = rayleigh_coefficients(float(w[0]), float(w[1]), zeta, zeta)
        C = a0 * M + a1 * K_lin + _element_stiffness(
            n, [(i + 1, 0, float(b.damping)) for i, b in enumerate(bearings_)])
        labels = ["deck", *(f"cap{i + 1}" for i in range(len(piers_)))]
        super().__init__(M=M, K=K, labels=labels,
                         elevations=[z_deck, *(p.height for p in piers_)], r=np.ones(n),
                         C=C, name=name, floors=[0], faces={"left": [0], "right": [0]})
        frozen = object.__setattr__
        frozen(self, "deck_mass", float(deck_mass))
        frozen(self, "spans", spans_)
        frozen(self, "piers", piers_)
        frozen(self, "bearings", bearings_)
        frozen(self, "zeta", float(zeta))
        frozen(self, "rayleigh", (float(a0), float(a1)))
        frozen(self, "_linear_k", K_lin)
        frozen(self, "_elements", tuple(elements))
        frozen(self, "_laws", tuple(laws))

    # ----------------------------------------------------------------- the elements
    deck_mass: float
    spans: tuple[float, ...] | None
    piers: tuple[Pier, ...]
    bearings: tuple[Bearing, ...]
    zeta: float
    rayleigh: tuple[float, float]

    @property
    def deck_length(self) -> float | None:
        """Length of the deck segment along the axis [m]: the sum of its :attr:`spans`
        (None if they were not given)."""
        return None if self.spans is None else float(sum(self.spans))

    @property
    def mean_pier_height(self) -> float:
        """The average height of the frame's piers [m] (:attr:`Pier.height`, the cap above
        the ground): the ``H`` of a seat-width clause."""
        return float(np.mean([p.height for p in self.piers]))

    @property
    def deck_dof(self) -> int:
        """The deck's DOF (0)."""
        return 0

    def cap_dof(self, pier: int) -> int:
        """The DOF of pier ``pier``'s cap (0-based pier index)."""
        return pier + 1

    def elements(self) -> list[tuple[str, str, int, int, float, StoreyLaw | None, float]]:
        """Every element: ``(label, kind, lower, upper, k, law, c)`` — piers ``P1`` …
        (kind ``"pier"``, ground −1 → cap), then bearings ``Br1`` … (kind the bearing's,
        cap → deck); ``k`` [N/m] the (initial) stiffness, ``law`` None if linear, ``c``
        [N·s/m] the element's own dashpot (a bearing's)."""
        out = []
        n_p = len(self.piers)
        for e, ((lo, hi, k), law) in enumerate(zip(self._elements, self._laws)):  # type: ignore[attr-defined]
            pier = e < n_p
            i = e if pier else e - n_p
            out.append((f"P{i + 1}" if pier else f"Br{i + 1}",
                        "pier" if pier else self.bearings[i].kind, lo, hi, k, law,
                        0.0 if pier else self.bearings[i].damping))
        return out

    def element_rows(self) -> list[ElementRow]:
        """The nonlinear elements, piers first, each with its own law and constants
        (``[k, F_y, …]`` for its initial stiffness); no storey column (:attr:`storey` −1)."""
        return [ElementRow(lo, hi, -1, 0.0, law, law.params([k])[0], -1, label)
                for label, _, lo, hi, k, law, _ in self.elements() if law is not None]

    # ----------------------------------------------------------------- the row's questions
    @property
    def is_inelastic(self) -> bool:
        """True if a pier or bearing follows a nonlinear law."""
        return any(law is not None for law in self._laws)  # type: ignore[attr-defined]

    def linear_stiffness_matrix(self) -> NDArray[np.float64]:
        """Stiffness [N/m] of the linear elements only (the nonlinear ones' forces come from
        their laws: :meth:`element_rows`)."""
        return np.array(self._linear_k)  # type: ignore[attr-defined]

    @property
    def total_mass(self) -> float:
        """Deck and caps [kg]."""
        return float(np.trace(self.M))

    @property
    def weight(self) -> float:
        """Weight of the deck [N] (``m g``, what its bearings carry together)."""
        return self.deck_mass * GRAVITY

    def describe(self) -> str:
        """One line: the deck, its piers and bearings, and its periods."""
        t = self.modes().periods
        return (f"deck {self.deck_mass / 1e3:.0f} t at {self.elevations[0]:g} m on "
                f"{len(self.piers)} pier(s); T1 = {t[0]:.3f} s"
                + (f", T2 = {t[1]:.3f} s" if t.size > 1 else ""))

    def __eq__(self, other: object) -> bool:
        same = super().__eq__(other)
        if same is NotImplemented or not same:
            return same
        return (isinstance(other, BridgeFrame) and self.piers == other.piers
                and self.bearings == other.bearings and self.zeta == other.zeta
                and self.spans == other.spans)

    __hash__ = None

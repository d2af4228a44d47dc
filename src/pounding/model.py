"""The pounding problem: buildings in a row, the gaps between them, and the contact law.

A :class:`PoundingModel` is pure data: it says *what* collides, not how to integrate it
(that is :mod:`pounding.integrate`) nor what shakes it (:mod:`pounding.ground_motion`).

Geometry. Buildings stand left to right along x, building ``b`` and ``b + 1`` separated by
``gaps[b]``. Displacements are positive to the right, so at a shared floor level the
penetration is ``δ = u_left − u_right − gap`` (seed case 2A for two buildings of equal
floor levels, 2C for a row). Floors meet only where both buildings have a floor at the same
elevation; buildings of different heights therefore collide only up to the lower roof
(case 2B, floor-to-floor).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import NDArray

from pounding.contact.base import ContactLaw
from pounding.contact.dispatch import PARAMS_SIZE
from pounding.contact.factory import make_law
from pounding.structure import ShearBuilding
from pounding.structure.assembly import AssembledSystem, assemble, shared_levels
from pounding.validation import non_negative


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
        Damping formula (default: the law's own).
    c, zeta, chi : float, optional
        Damping given directly.
    n : float
        Hertz exponent.
    tension : bool
        Kelvin–Voigt only: may the dashpot pull before separation.
    delta_m : float, optional
        Bilinear element: assumed maximum penetration [m].
    a : float
        Bilinear element: yield ratio δy/δm (Muthukumar's 0.1).
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
    tension: bool = True
    delta_m: float | None = None
    a: float = 0.1

    def __post_init__(self) -> None:
        # build once with unit masses so a bad spec fails here, naming its field
        self.build(1.0, 1.0)

    def build(self, m1: float, m2: float) -> ContactLaw:
        """The contact law between two floors of masses ``m1`` and ``m2`` [kg]."""
        return make_law(self.law, k=self.k, k_h=self.k_h, e=self.e, formula=self.formula,
                        c=self.c, zeta=self.zeta, chi=self.chi, m1=m1, m2=m2, n=self.n,
                        tension=self.tension, delta_m=self.delta_m, a=self.a)


@dataclass(frozen=True)
class Contact:
    """One contact element between two floors at the same elevation.

    Attributes
    ----------
    index : int
        Position in :attr:`PoundingModel.contacts`.
    pair : int
        Which gap: between building ``pair`` and ``pair + 1``.
    left_floor, right_floor : int
        0-based floor index in the left / right building.
    dof_left, dof_right : int
        Global degrees of freedom of the two floors.
    elevation : float
        Height of the contact above ground [m].
    gap : float
        Separation gap at rest [m].
    law : ContactLaw
        The contact law, built with the two floor masses.
    """

    index: int
    pair: int
    left_floor: int
    right_floor: int
    dof_left: int
    dof_right: int
    elevation: float
    gap: float
    law: ContactLaw

    @property
    def label(self) -> str:
        """Readable name, e.g. ``'B1F3-B2F3'`` (1-based building and floor numbers)."""
        return f"B{self.pair + 1}F{self.left_floor + 1}-B{self.pair + 2}F{self.right_floor + 1}"


@dataclass(frozen=True)
class PoundingModel:
    """Buildings in a row, the gaps between them, and the contact law.

    Parameters
    ----------
    buildings : sequence of ShearBuilding
        From left to right (at least one; one building is a plain response analysis).
    gaps : sequence of float
        Separation gap between each pair of neighbours [m], ``len(buildings) − 1`` values.
    contact : ContactSpec
        The contact law used at every shared floor level.
    name : str
        A label for outputs.

    Examples
    --------
    >>> from pounding.structure import ShearBuilding
    >>> left = ShearBuilding.sdof(2e5, period=0.5)
    >>> right = ShearBuilding.sdof(3e5, period=1.0)
    >>> model = PoundingModel([left, right], gaps=[0.02],
    ...                       contact=ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))
    >>> [c.label for c in model.contacts]
    ['B1F1-B2F1']
    """

    buildings: Sequence[ShearBuilding]
    gaps: Sequence[float]
    contact: ContactSpec
    name: str = "model"

    def __post_init__(self) -> None:
        if len(self.buildings) < 1:
            raise ValueError("buildings: give at least one building")
        for i, b in enumerate(self.buildings):
            if not isinstance(b, ShearBuilding):
                raise ValueError(f"buildings[{i}]: expected a ShearBuilding (got {type(b).__name__})")
        if len(self.gaps) != len(self.buildings) - 1:
            raise ValueError(f"gaps: need {len(self.buildings) - 1} value(s) for "
                             f"{len(self.buildings)} buildings (got {len(self.gaps)})")
        object.__setattr__(self, "buildings", tuple(self.buildings))
        object.__setattr__(self, "gaps", tuple(non_negative(f"gaps[{i}]", g)
                                               for i, g in enumerate(self.gaps)))

    @cached_property
    def system(self) -> AssembledSystem:
        """Block-diagonal M, C, K, influence vector and DOF offsets of all buildings."""
        return assemble(self.buildings)

    @cached_property
    def contacts(self) -> tuple[Contact, ...]:
        """Every floor-to-floor contact, pair by pair, bottom to top."""
        out: list[Contact] = []
        offsets = self.system.offsets
        for p, (a, b) in enumerate(zip(self.buildings[:-1], self.buildings[1:])):
            for i, j in shared_levels(a, b):
                law = self.contact.build(float(a.masses[i]), float(b.masses[j]))
                out.append(Contact(len(out), p, i, j, int(offsets[p] + i), int(offsets[p + 1] + j),
                                   float(a.floor_levels[i]), float(self.gaps[p]), law))
        return tuple(out)

    @property
    def n_dof(self) -> int:
        """Total number of floors (degrees of freedom)."""
        return self.system.n_dof

    def contact_arrays(self) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.float64],
                                      NDArray[np.int64], NDArray[np.float64]]:
        """The contacts as plain arrays for the compiled kernel.

        Returns
        -------
        dof_left, dof_right : int64 (n_c,)
        gap : float64 (n_c,) [m]
        code : int64 (n_c,) law codes
        params : float64 (n_c, p) law constants, zero-padded
        """
        cs = self.contacts
        params = np.zeros((len(cs), PARAMS_SIZE))  # every law's constants fit, zero-padded
        for c in cs:
            p = c.law.params()
            params[c.index, : p.size] = p
        return (np.array([c.dof_left for c in cs], dtype=np.int64),
                np.array([c.dof_right for c in cs], dtype=np.int64),
                np.array([c.gap for c in cs], dtype=float),
                np.array([c.law.code for c in cs], dtype=np.int64), params)

    def dof_labels(self) -> list[str]:
        """``'B1F1'``, ``'B1F2'``, … for every degree of freedom (1-based)."""
        return [f"B{b + 1}F{j + 1}" for b, bl in enumerate(self.buildings) for j in range(bl.n)]

"""The model's contacts and nonlinear elements as the rows the compiled kernel takes: each
contact's DOFs and weights (its penetration ``δ = Σ w u − gap``), law code and constants;
each element row's (a yielding storey, a bridge pier or bearing, a link between buildings)
DOFs, law code, constants and internal-variable slot.

:class:`KernelRows` is a base of :class:`pounding.model.PoundingModel`, which gives it the
row's buildings, contacts, links and assembled system; these methods only read them.
"""

from __future__ import annotations

from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from pounding.contact.dispatch import PARAMS_SIZE, check_contact_law
from pounding.hysteresis.base import PARAMS_SIZE as STOREY_PARAMS_SIZE
from pounding.structure.element_rows import ElementRow, element_rows

if TYPE_CHECKING:
    from pounding.contact.geometry import Contact
    from pounding.devices import Link
    from pounding.structure.assembly import AssembledSystem, Building

__all__ = ["KernelRows"]


class KernelRows:
    """The kernel's rows of a model's contacts and elements (a base of
    :class:`~pounding.model.PoundingModel`, which defines what is declared here)."""

    buildings: tuple[Building, ...]

    if TYPE_CHECKING:
        @property
        def system(self) -> AssembledSystem: ...

        @property
        def contacts(self) -> tuple[Contact, ...]: ...

        @property
        def links(self) -> tuple[Link, ...]: ...

        @property
        def link_dofs(self) -> tuple[tuple[int, int], ...]: ...

    def contact_kinematics(self) -> tuple[NDArray[np.int64], NDArray[np.float64]]:
        """Global DOFs and signed weights of every contact, each shape ``(n_c, 4)`` (two
        slots a side: a floor, a column point between two floors, or a floor in plan and
        its rotation; the kernel takes rows of any width).

        ``δ = Σ_q w[c, q] u[dof[c, q]] − gap``: weights of the left point positive, of the
        right point negative; unused slots carry weight 0 (on a valid DOF). The force ``F`` of
        contact c acts on DOF ``dof[c, q]`` as ``−w[c, q] F``.
        """
        cs = self.contacts
        dof = np.zeros((len(cs), 4), dtype=np.int64)
        w = np.zeros((len(cs), 4))
        offsets = self.system.offsets
        for c in cs:
            for side, point, sign in ((0, c.left, 1.0), (2, c.right, -1.0)):
                fw = point.floor_weights()
                if not fw:
                    continue  # a rigid wall: no DOF (its slots keep weight 0 on DOF 0)
                base = int(offsets[point.building])
                for q in range(2):
                    i, wt = fw[q] if q < len(fw) else (fw[0][0], 0.0)
                    dof[c.index, side + q] = base + i
                    w[c.index, side + q] = sign * wt
        return dof, w

    def contact_penetration(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        """Penetration ``δ`` [m] of every contact from floor displacements ``u[..., N]``."""
        dof, w = self.contact_kinematics()
        gap = np.array([c.gap for c in self.contacts])
        return np.einsum("...cq,cq->...c", u[..., dof], w) - gap

    def contact_arrays(self) -> tuple[NDArray[np.int64], NDArray[np.float64], NDArray[np.float64],
                                      NDArray[np.int64], NDArray[np.float64]]:
        """The contacts as plain arrays for the compiled kernel.

        Returns
        -------
        dof, weight : int64 / float64 (n_c, 4)
            :meth:`contact_kinematics`.
        gap : float64 (n_c,) [m]
        code : int64 (n_c,) law codes
        params : float64 (n_c, p) law constants, zero-padded
        """
        cs = self.contacts
        params = np.zeros((len(cs), PARAMS_SIZE))  # every law's constants fit, zero-padded
        for c in cs:
            try:
                check_contact_law(c.law)
            except ValueError as exc:
                raise ValueError(f"contact {c.label}: {exc}") from None
            p = c.law.params()
            params[c.index, : p.size] = p
        dof, w = self.contact_kinematics()
        return (dof, w, np.array([c.gap for c in cs], dtype=float),
                np.array([c.law.code for c in cs], dtype=np.int64), params)

    @cached_property
    def element_rows(self) -> tuple[tuple[int, ElementRow], ...]:
        """``(building index, row)`` of every nonlinear element of the buildings, left to
        right and in each building's order: a shear building's yielding storeys (one law for
        all), a bridge frame's piers and bearings (a law each;
        :func:`pounding.structure.element_rows.element_rows`). The row's DOFs are its
        building's own."""
        return tuple((p, row) for p, b in enumerate(self.buildings) for row in element_rows(b))

    def element_labels(self) -> list[str]:
        """``'B1F1'`` (a yielding storey), ``'B2P1'`` (a bridge frame's pier 1), ``'B2Br1'``
        (its bearing 1) … for every row of :attr:`element_rows`."""
        return [f"B{p + 1}{row.label}" for p, row in self.element_rows]

    @cached_property
    def yielding_storeys(self) -> tuple[tuple[int, int], ...]:
        """``(building, storey index)`` of every element row that is a storey (its shear
        fills that storey's column of the per-floor outputs), in DOF order; a bridge
        frame's piers and bearings are element rows but no storeys."""
        return tuple((p, row.storey) for p, row in self.element_rows if row.storey >= 0)

    def storey_arrays(self) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64],
                                     NDArray[np.float64], NDArray[np.int64]]:
        """The element rows (:attr:`element_rows`: yielding storeys, a bridge frame's piers
        and bearings, each row with its own law), and then the links between buildings, as
        plain arrays for the compiled kernel.

        Returns
        -------
        lower, upper : int64 (n_s,)
            Global DOF of the floor below (−1: the ground) and above each storey.
        code : int64 (n_s,)
            Storey-law codes (:mod:`pounding.hysteresis.base`).
        params : float64 (n_s, P)
            Storey-law constants ``[k, F_y, …]``.
        z_index : int64 (n_s,)
            Index of the storey's internal variable among the ``z`` states (−1: none).
        """
        from pounding.hysteresis.dispatch import check_storey_law

        offsets = self.system.offsets
        lower, upper, code, zi = [], [], [], []
        rows: list[NDArray[np.float64]] = []
        nz = 0
        for p, row in self.element_rows:
            law = row.law
            check_storey_law(law)
            upper.append(int(offsets[p] + row.upper))
            lower.append(int(offsets[p] + row.lower) if row.lower >= 0 else -1)
            code.append(law.code)
            rows.append(row.params)
            zi.append(nz if law.has_internal_variable else -1)
            nz += 1 if law.has_internal_variable else 0
        # the links: rows of the same kind after the storeys, from the left end (lower) to
        # the right end (upper), so the "drift" is u_right − u_left
        width = rows[0].size if rows else STOREY_PARAMS_SIZE
        for link, (lo, hi) in zip(self.links, self.link_dofs):
            lower.append(lo)
            upper.append(hi)
            code.append(link.code)
            rows.append(link.params(width))
            zi.append(nz if link.has_internal_variable else -1)
            nz += 1 if link.has_internal_variable else 0
        return (np.array(lower, dtype=np.int64), np.array(upper, dtype=np.int64),
                np.array(code, dtype=np.int64),
                np.array(rows, dtype=float).reshape(len(rows), width),
                np.array(zi, dtype=np.int64))

    def storey_rocking(self) -> tuple[NDArray[np.int64], NDArray[np.float64]]:
        """For every row of :meth:`storey_arrays`, the DOF of the rocking footing under it
        (−1: none) and its lever [m]: the storey's drift is ``u[upper] − u[lower] −
        lever · u[rock]`` (a storey of a building on a flexible base,
        :meth:`pounding.structure.foundation.FlexibleBaseBuilding.yielding_storey_dofs`); the
        links after the storeys have none."""
        offsets = self.system.offsets
        rock: list[int] = []
        lever: list[float] = []
        for p, row in self.element_rows:
            rock.append(int(offsets[p] + row.rock) if row.rock >= 0 else -1)
            lever.append(float(row.lever))
        rock += [-1] * len(self.links)
        lever += [0.0] * len(self.links)
        return np.array(rock, dtype=np.int64), np.array(lever, dtype=float)

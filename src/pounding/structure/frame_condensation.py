"""A frame condensed onto its DOFs with mass for one set of hinge tangents.

In a configuration of its hinges (:mod:`pounding.structure.frame_configuration`) a frame's
tangent stiffness is its elastic and geometric stiffness ``K_base`` plus each hinge's spring of
tangent ``k_t`` between its joint's rotation and its member end's. The DOFs ``m`` that carry
mass (the floors' lateral motion, and where given the nodes' vertical motion, rotation or
own lateral motion) are kept; every other DOF ``s`` is massless and the static condensation
of Chopra, *Dynamics of Structures*, 4th ed., §9.3, gives

    S = −K_ss⁻¹ K_sm,   K_c = K_mm + K_ms S,   P = [I; S] (every DOF per kept displacement),

and the hinge rotations per kept displacement ``A = Bᵀ P`` (``B`` the hinges' incidence).
:class:`Condensation` keeps these for each set of tangents a run meets, and the factorised
``K_ss`` that turns the constant loads of a configuration (gravity, the hinges' moment
offsets) into the massless DOFs' constant displacements.

The springs of the hinges touch rotations only: a member end's own rotation (always
massless) and its joint's (massless unless the joint has a rotational mass). ``K_ss`` has a
fixed sparsity pattern (the base's and the springs'), assembled here by adding the tangents
into its values and factorised by SuperLU (a frame's ``K_ss`` has a few entries a row: dense
LAPACK took 14 ms for a 306-DOF frame on a loaded 2-core machine where SuperLU took 0.5 ms);
a spring whose joint rotation is kept adds ``k_t`` to ``K_mm`` and ``−k_t`` to ``K_ms``.

A set of tangents that differs from the first set met (the *anchor*, factorised as above) in
a few hinges ``c`` is the anchor's frame with springs ``Δk_c`` added, a rank-``|c|`` change
of ``K_ss``; its condensation follows from the anchor's by the Woodbury identity
(Hager, "Updating the inverse of a matrix", SIAM Review 31, 1989) without a factorisation:
with ``Z = K_ss⁻¹ B_s`` and ``F = B_sᵀ Z`` the anchor's (the hinges' flexibility with the
kept DOFs held), ``G = diag(1/Δk_c) + F_cc`` and ``W = G⁻¹ A_c``,

    K_c' = K_c + A_cᵀ W,   A' = A − F_{:,c} W,   S' = S − Z_{:,c} W,
    K_ss'⁻¹ x = y − Z_{:,c} G⁻¹ B_{s,c}ᵀ y,   y = K_ss⁻¹ x.

Where that does not hold cleanly — ``G`` near singular (a mechanism forming in the massless
DOFs), a joint losing all its stiffness, more than :data:`UPDATE_LIMIT` of the hinges
changed, or a hinge on a kept joint rotation — the set is factorised afresh. Both ways agree
to rounding (``tests/structure/test_frame_condensation.py``).
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from pounding.structure.frame_stiffness import FrameDofs, hinge_incidence

__all__ = ["PARTS_KEPT", "Condensation", "CondensedPart"]

Vector = NDArray[np.float64]

PARTS_KEPT: int = 256
"""The condensations a frame keeps for reuse (oldest forgotten first)."""

UPDATE_LIMIT: float = 0.5
"""A set of tangents is updated from the anchor's condensation (module docstring) when at
most this fraction of the hinges differ from it; beyond, it is factorised afresh."""

UPDATE_PIVOT: float = 1e-10
"""An equilibrated pivot of ``G`` this far below its largest: the update is not trusted and
the set is factorised afresh (which finds a mechanism, if there is one)."""

SINGULAR_PIVOT: float = 1e-13
"""A pivot of the equilibrated ``K_ss`` this far below its largest: no unique equilibrium."""


@dataclass(frozen=True)
class CondensedPart:
    """What a set of hinge tangents alone fixes: the live and dead massless DOFs (dead: no
    stiffness at all), ``x ↦ K_ss⁻¹ x`` over the live ones, ``K_ms``, the condensed ``K_c``
    (symmetrised), ``A`` and ``P``."""

    live: NDArray[np.int64]
    dead: NDArray[np.int64]
    solve: Callable[[Vector], Vector]
    Kms: Vector  #: (n_m, n_live)
    Kc: Vector  #: (n_m, n_m) [N/m, N, N·m]
    A: Vector  #: (n_h, n_m) [rad/m, rad/rad]
    P: Vector  #: (n, n_m)


class Condensation:
    """The condensations of one frame, by hinge tangents (module docstring).

    Parameters
    ----------
    base : ndarray (n, n)
        The frame's elastic and geometric stiffness without the hinges' springs.
    dofs : FrameDofs
        Its DOF numbering (floors, hinge DOFs).
    name : str
        The frame's name, for messages.
    kept : array_like of int, optional
        The DOFs kept (with mass), in the order of the condensed matrices; default the
        floors' lateral DOFs (``dofs.floor_dof``).
    """

    def __init__(self, base: Vector, dofs: FrameDofs, name: str,
                 kept: NDArray[np.int64] | None = None) -> None:
        import scipy.sparse

        n = dofs.n
        self.name = name
        self.kept = np.asarray(dofs.floor_dof if kept is None else kept, dtype=np.int64)
        self.other = np.setdiff1d(np.arange(n), self.kept)
        self.node = np.asarray(dofs.hinge_node, dtype=np.int64)
        self.end = np.asarray(dofs.hinge, dtype=np.int64)
        if np.isin(self.end, self.kept).any():
            raise ValueError(f"{name}: a member end's own rotation (a hinge's) cannot carry "
                             "mass")
        local = np.full(n, -1, dtype=np.int64)
        local[self.other] = np.arange(self.other.size)
        kept_at = np.full(n, -1, dtype=np.int64)
        kept_at[self.kept] = np.arange(self.kept.size)
        no = self.other.size
        # the pattern of K_ss over every massless DOF: the base's entries and the springs'
        # (a spring whose joint rotation is kept, ``kept_node``, reaches K_ss at its end only)
        on = (self.node >= 0) & (kept_at[np.maximum(self.node, 0)] < 0)
        kept_node = np.flatnonzero((self.node >= 0) & ~on)
        self._kept_node = kept_node
        self._kept_node_m = kept_at[self.node[kept_node]]
        self._kept_node_s = local[self.end[kept_node]]
        ha, hb = local[self.node[on]], local[self.end[on]]
        he = local[self.end]
        spring_rows = np.concatenate([he, ha, ha, hb])
        spring_cols = np.concatenate([he, ha, hb, ha])
        base_ss = base[np.ix_(self.other, self.other)]
        mask = base_ss != 0.0
        mask[spring_rows, spring_cols] = True
        pattern = scipy.sparse.csc_matrix(mask.astype(float))
        pattern.sort_indices()
        self._indices = pattern.indices.astype(np.int32)
        self._indptr = pattern.indptr.astype(np.int32)
        cols = np.repeat(np.arange(no), np.diff(pattern.indptr))
        rows = pattern.indices.astype(np.int64)
        self._rows = rows  # (each stored value's row in K_ss)
        position = np.full((no, no), -1, dtype=np.int64)
        position[rows, cols] = np.arange(rows.size)
        self._base_data = base_ss[rows, cols]
        # where each hinge's tangent goes in K_ss's values (``_scatter @ k``): +k at
        # (end, end) for every hinge, and at (node, node), −k at (node, end) and (end, node)
        # for a hinge on a free joint
        nh = self.end.size
        hon = np.flatnonzero(on)
        self._scatter = scipy.sparse.csr_matrix(
            (np.concatenate([np.ones(nh), np.ones(hon.size), -np.ones(2 * hon.size)]),
             (np.concatenate([position[he, he], position[ha, ha], position[ha, hb],
                              position[hb, ha]]),
              np.concatenate([np.arange(nh), hon, hon, hon]))),
            shape=(rows.size, nh))
        self._coupled = np.any(base[np.ix_(self.other, self.kept)] != 0.0, axis=1)
        self._Kmm = base[np.ix_(self.kept, self.kept)]
        self._Kmo = base[np.ix_(self.kept, self.other)]
        self._parts: dict[bytes, CondensedPart] = {}
        self._B = hinge_incidence(dofs)
        self._anchor: _Anchor | None = None

    def part(self, tangents: Vector) -> CondensedPart:
        """The condensation for hinge tangents ``tangents`` [N·m/rad], computed once for each
        set met (a frame returns to the same few: elastic, its mechanisms).

        Raises
        ------
        ValueError
            If the frame's massless DOFs have no unique equilibrium with these tangents (a
            mechanism that does not involve the floors).
        """
        key = tangents.tobytes()
        found = self._parts.get(key)
        if found is not None:
            return found
        part = self._updated(tangents) if self._anchor is not None else None
        if part is None:
            part = self._condense(tangents)
            if self._anchor is None:
                self._anchor = self._make_anchor(tangents, part)
        if len(self._parts) >= PARTS_KEPT:
            self._parts.pop(next(iter(self._parts)))
        self._parts[key] = part
        return part

    def _alive(self, data: Vector) -> NDArray[np.bool_]:
        """Which massless DOFs have stiffness, ``K_ss``'s values being ``data``: a DOF with
        none at all (a joint whose every connection is a hinge of zero tangent) stays where
        it is."""
        alive = self._coupled.copy()
        alive[self._rows[data != 0.0]] = True
        return alive

    def _make_anchor(self, tangents: Vector, part: CondensedPart) -> _Anchor:
        """The anchor of the updates: this set's condensation with ``Z`` and ``F``."""
        Bs = np.asarray(self._B[part.live].toarray())
        Z = part.solve(Bs) if part.live.size else Bs
        return _Anchor(np.array(tangents, dtype=float), part, Bs, Z, Bs.T @ Z)

    def _updated(self, tangents: Vector) -> CondensedPart | None:
        """The condensation for ``tangents`` updated from the anchor's (module docstring), or
        None where it is to be factorised afresh."""
        import scipy.linalg

        a = self._anchor
        assert a is not None
        k = np.asarray(tangents, dtype=float)
        c = np.flatnonzero(k != a.tangents)
        if c.size == 0:
            return a.part
        if self._kept_node.size or c.size > UPDATE_LIMIT * k.size:
            return None
        base = a.part
        if not np.array_equal(self.other[self._alive(self._base_data + self._scatter @ k)],
                              base.live):
            return None  # (a joint lost, or regained, all its stiffness)
        G = a.F[np.ix_(c, c)] + np.diag(1.0 / (k[c] - a.tangents[c]))
        scale = 1.0 / np.sqrt(np.maximum(np.abs(np.diag(G)), 1e-300))
        with warnings.catch_warnings():  # (an exactly singular G: judged just below)
            warnings.simplefilter("ignore", scipy.linalg.LinAlgWarning)
            lu, piv = scipy.linalg.lu_factor(G * scale[:, None] * scale[None, :],
                                             check_finite=False)
        pivots = np.abs(np.diag(lu))
        if not np.all(np.isfinite(pivots)) or np.min(pivots) <= UPDATE_PIVOT * np.max(pivots):
            return None

        def solve_G(y: Vector) -> Vector:
            d = scale if y.ndim == 1 else scale[:, None]
            return d * scipy.linalg.lu_solve((lu, piv), d * y, check_finite=False)

        W = solve_G(base.A[c])
        Kc = base.Kc + base.A[c].T @ W
        A = base.A - a.F[:, c] @ W
        P = base.P.copy()
        Zc, Bc = a.Z[:, c], a.Bs[:, c]
        P[base.live] -= Zc @ W

        def solve(x: Vector) -> Vector:
            y = base.solve(x)
            return y - Zc @ solve_G(Bc.T @ y)

        return CondensedPart(base.live, base.dead, solve, base.Kms, 0.5 * (Kc + Kc.T), A, P)

    def _condense(self, tangents: Vector) -> CondensedPart:
        import scipy.sparse
        import scipy.sparse.linalg

        k = np.asarray(tangents, dtype=float)
        data = self._base_data + self._scatter @ k
        Kmm, Kmo = self._Kmm, self._Kmo
        if self._kept_node.size:  # springs between a kept joint rotation and a member end
            kk = k[self._kept_node]
            Kmm, Kmo = Kmm.copy(), Kmo.copy()
            np.add.at(Kmm, (self._kept_node_m, self._kept_node_m), kk)
            np.add.at(Kmo, (self._kept_node_m, self._kept_node_s), -kk)
        no = self.other.size
        alive = self._alive(data)
        live_local = np.flatnonzero(alive)
        live, dead = self.other[alive], self.other[~alive]
        nf = self.kept.size
        Kss = scipy.sparse.csc_matrix((data, self._indices, self._indptr), shape=(no, no))
        if live_local.size != no:
            Kss = Kss[live_local][:, live_local].tocsc()
        Kms = Kmo[:, live_local]
        P = np.zeros((self.other.size + nf, nf))
        P[self.kept, np.arange(nf)] = 1.0
        Kc = Kmm.copy()
        solve: Callable[[Vector], Vector] = _nothing_to_solve
        if live.size:
            # equilibrate rows and columns by the diagonal so that the pivots compare DOFs
            # of different units
            diag = np.abs(Kss.diagonal())
            scale = np.sqrt(np.maximum(diag, np.max(np.abs(Kss.data)) * 1e-30))
            r = Kss.indices
            c = np.repeat(np.arange(Kss.shape[1]), np.diff(Kss.indptr))
            scaled = scipy.sparse.csc_matrix((Kss.data / scale[r] / scale[c], Kss.indices,
                                              Kss.indptr), shape=Kss.shape)
            try:
                # (K_ss is symmetric: a minimum-degree ordering of Kᵀ + K fills in 40 %
                # less than SuperLU's default COLAMD and factorises 3.5× faster, LA9-type)
                lu = scipy.sparse.linalg.splu(scaled, permc_spec="MMD_AT_PLUS_A")
                pivots = np.abs(lu.U.diagonal())
            except RuntimeError:  # exactly singular
                pivots = np.zeros(1)
            if not np.all(np.isfinite(pivots)) or np.min(pivots) <= SINGULAR_PIVOT * np.max(
                    pivots):
                raise ValueError(f"{self.name}: its joints and member ends have no unique "
                                 "equilibrium in this configuration of its hinges (a "
                                 "mechanism without mass); give the hinges some post-yield "
                                 "stiffness or put a floor mass on the moving part")
            solve = _scaled_solver(lu, scale)
            S = solve(-Kms.T) if nf else np.zeros((live.size, 0))
            P[live] = S
            Kc = Kc + Kms @ S
        fixed = self.node < 0
        A = np.where(fixed[:, None], 0.0, P[np.maximum(self.node, 0)]) - P[self.end]
        return CondensedPart(live, dead, solve, Kms, 0.5 * (Kc + Kc.T), A, P)


@dataclass(frozen=True)
class _Anchor:
    """The first set of tangents condensed by factorisation, from which the others are
    updated (module docstring)."""

    tangents: Vector  #: (n_h,) [N·m/rad]
    part: CondensedPart
    Bs: Vector  #: the hinges' incidence over the live massless DOFs (n_live, n_h)
    Z: Vector  #: K_ss⁻¹ B_s (n_live, n_h)
    F: Vector  #: B_sᵀ K_ss⁻¹ B_s (n_h, n_h) [rad/(N·m)]


def _nothing_to_solve(x: Vector) -> Vector:  # pragma: no cover - no live DOFs: never called
    return x


def _scaled_solver(lu: object, scale: Vector) -> Callable[[Vector], Vector]:
    """``x ↦ K_ss⁻¹ x`` from the LU of ``D⁻¹ K_ss D⁻¹`` (``D = diag(scale)``)."""
    def solve(x: Vector) -> Vector:
        d = scale if x.ndim == 1 else scale[:, None]  # (a vector or columns)
        return np.asarray(lu.solve(np.asfortranarray(x / d))) / d  # type: ignore[attr-defined]
    return solve

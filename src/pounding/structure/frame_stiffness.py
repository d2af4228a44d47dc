"""A frame's degrees of freedom, element matrices and stiffness in one hinge configuration.

Degrees of freedom (DOFs): three per node (``u_x``, ``u_y``, ``θ``), fewer where supported,
the ``u_x`` of a floor's nodes shared with rigid floors, and one more rotation per hinge —
the element end's own rotation, which the hinge ties to its node's (the hinge rotation is
``θ_node − θ_end``). Element matrices are the classical ones (McGuire, Gallagher & Ziemian,
*Matrix Structural Analysis*, 2nd ed., §4.3 for the elastic beam-column, §8.3 for the
geometric stiffness):

* elastic: ``EA/L`` axially; ``12EI/L³, 6EI/L², 4EI/L, 2EI/L`` in bending;
* geometric ``"p-delta"``: ``(N/L)[[1, −1], [−1, 1]]`` on the two ends' transverse
  displacements (OpenSees' ``PDelta`` transformation);
* geometric ``"consistent"``: ``(N/L)`` times ``[[6/5, L/10, −6/5, L/10], [L/10, 2L²/15,
  −L/10, −L²/30], …]`` on ``(v₁, θ₁, v₂, θ₂)`` (McGuire et al. eq. 8.14), the member's P-δ;

``N`` is the member's axial force, positive in tension, from the gravity analysis. The
leaning column adds ``−(P/h)[[1, −1], [−1, 1]]`` between the lateral displacements of two
consecutive floors, ``P`` the gravity load it carries in that storey.

In one *configuration* every hinge stands on one straight branch of its law with tangent
``k_t``; the frame is then linear, with stiffness :func:`configuration_stiffness`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.structure.frame import Frame

__all__ = ["FrameDofs", "configuration_stiffness", "element_end_forces", "end_moment_operator",
           "frame_dofs", "geometric_stiffness", "gravity_load_vector", "elastic_stiffness",
           "condense", "hinge_incidence", "member_transform"]


@dataclass(frozen=True)
class FrameDofs:
    """The numbering of a frame's DOFs."""

    n: int  #: number of free DOFs
    node: NDArray[np.int64]  #: (n_nodes, 3) DOF of each node's u_x, u_y, θ (−1: fixed)
    hinge: NDArray[np.int64]  #: (n_hinges,) DOF of each hinge's member-end rotation
    hinge_node: NDArray[np.int64]  #: (n_hinges,) DOF of the node rotation (−1: fixed)
    element: NDArray[np.int64]  #: (m, 6) DOFs of each element's ends (−1: fixed)
    floor: NDArray[np.float64]  #: (n_floors, n) floor lateral displacement = floor @ U
    floor_dof: NDArray[np.int64]  #: (n_floors,) a DOF carrying each floor's u_x


def frame_dofs(frame: Frame) -> FrameDofs:
    """Number the free DOFs of ``frame`` (see the module docstring)."""
    nn = frame.n_nodes
    node = np.full((nn, 3), -1, dtype=np.int64)
    level = frame.node_level
    nf = frame.levels.size
    shared: dict[int, int] = {}
    k = 0
    for i in range(nn):
        for d in range(3):
            if frame.supports[i, d]:
                continue
            if d == 0 and frame.diaphragm and level[i] >= 0:
                j = int(level[i])
                if j not in shared:
                    shared[j] = k
                    k += 1
                node[i, d] = shared[j]
                continue
            node[i, d] = k
            k += 1
    hinge = np.arange(k, k + len(frame.hinges), dtype=np.int64)
    k += len(frame.hinges)
    hinge_node = np.array([node[frame.elements[h.element, h.end], 2] for h in frame.hinges],
                          dtype=np.int64)
    element = np.full((frame.n_elements, 6), -1, dtype=np.int64)
    for e, (a, b) in enumerate(frame.elements):
        element[e, 0:3] = node[a]
        element[e, 3:6] = node[b]
    for h, fh in enumerate(frame.hinges):
        element[fh.element, 3 * fh.end + 2] = hinge[h]
    floor = np.zeros((nf, k))
    floor_dof = np.full(nf, -1, dtype=np.int64)
    for j in range(nf):
        members = [int(node[i, 0]) for i in np.flatnonzero(level == j) if node[i, 0] >= 0]
        if not members:
            raise ValueError(f"{frame.name}: floor {j + 1} (y = {frame.levels[j]:.6g} m): all "
                             "its nodes are fixed horizontally")
        for d in set(members):
            floor[j, d] += members.count(d) / len(members)
        floor_dof[j] = members[-1]
    return FrameDofs(k, node, hinge, hinge_node, element, floor, floor_dof)


def _rotation(frame: Frame, e: int) -> tuple[float, float, float]:
    a, b = frame.elements[e]
    dx, dy = frame.nodes[b] - frame.nodes[a]
    L = float(np.hypot(dx, dy))
    return dx / L, dy / L, L


def member_transform(c: float, s: float) -> NDArray[np.float64]:
    """From global ``(u_x, u_y, θ)`` at both ends to the member's axes ``(u, v, θ)``, for a
    member whose axis has direction cosines ``(c, s)``."""
    t = np.zeros((6, 6))
    for o in (0, 3):
        t[o, o], t[o, o + 1] = c, s
        t[o + 1, o], t[o + 1, o + 1] = -s, c
        t[o + 2, o + 2] = 1.0
    return t


def local_elastic(EA: float, EI: float, L: float) -> NDArray[np.float64]:
    """Local 6×6 stiffness of an elastic beam-column on ``(u₁, v₁, θ₁, u₂, v₂, θ₂)``."""
    a = EA / L
    b12, b6, b4, b2 = 12 * EI / L ** 3, 6 * EI / L ** 2, 4 * EI / L, 2 * EI / L
    return np.array([[a, 0, 0, -a, 0, 0],
                     [0, b12, b6, 0, -b12, b6],
                     [0, b6, b4, 0, -b6, b2],
                     [-a, 0, 0, a, 0, 0],
                     [0, -b12, -b6, 0, b12, -b6],
                     [0, b6, b2, 0, -b6, b4]])


def local_geometric(N: float, L: float, kind: str) -> NDArray[np.float64]:
    """Local 6×6 geometric stiffness for axial force ``N`` [N] (tension positive)."""
    g = np.zeros((6, 6))
    if kind == "p-delta":
        v = np.array([1, 4])
        g[np.ix_(v, v)] = (N / L) * np.array([[1.0, -1.0], [-1.0, 1.0]])
    elif kind == "consistent":
        q = np.array([1, 2, 4, 5])
        g[np.ix_(q, q)] = (N / L) * np.array([
            [6 / 5, L / 10, -6 / 5, L / 10],
            [L / 10, 2 * L * L / 15, -L / 10, -L * L / 30],
            [-6 / 5, -L / 10, 6 / 5, -L / 10],
            [L / 10, -L * L / 30, -L / 10, 2 * L * L / 15]])
    return g


def _scatter(K: NDArray[np.float64], dofs: NDArray[np.int64], ke: NDArray[np.float64]) -> None:
    ok = dofs >= 0
    idx = dofs[ok]
    np.add.at(K, (idx[:, None], idx[None, :]), ke[np.ix_(ok, ok)])


def elastic_stiffness(frame: Frame, dofs: FrameDofs) -> NDArray[np.float64]:
    """Stiffness of the elastic elements alone [N/m, N, N·m] (no hinge springs, no geometry)."""
    K = np.zeros((dofs.n, dofs.n))
    for e in range(frame.n_elements):
        c, s, L = _rotation(frame, e)
        T = member_transform(c, s)
        _scatter(K, dofs.element[e], T.T @ local_elastic(frame.EA[e], frame.EI[e], L) @ T)
    return K


def geometric_stiffness(frame: Frame, dofs: FrameDofs,
                        axial: NDArray[np.float64] | None) -> NDArray[np.float64]:
    """Geometric stiffness of the columns' axial forces ``axial`` [N] (per element, tension
    positive; per ``frame.geometry``) and of the leaning column's loads."""
    K = np.zeros((dofs.n, dofs.n))
    if frame.geometry != "linear" and axial is not None:
        col = frame.is_column
        for e in range(frame.n_elements):
            if not col[e] or axial[e] == 0.0:
                continue
            c, s, L = _rotation(frame, e)
            T = member_transform(c, s)
            _scatter(K, dofs.element[e], T.T @ local_geometric(float(axial[e]), L,
                                                                frame.geometry) @ T)
    lean = frame.leaning_loads
    if lean is not None and np.any(lean > 0):
        P = np.cumsum(lean[::-1])[::-1]  # load carried in each storey
        hs = frame.storey_heights
        for j in range(hs.size):
            k = P[j] / hs[j]
            up = dofs.floor[j]
            down = dofs.floor[j - 1] if j > 0 else np.zeros(dofs.n)
            d = up - down
            K -= k * np.outer(d, d)
    return K


def configuration_stiffness(base: NDArray[np.float64], dofs: FrameDofs,
                            tangents: NDArray[np.float64]) -> NDArray[np.float64]:
    """``base`` (elastic + geometric) plus each hinge's spring of tangent ``tangents[h]``
    [N·m/rad] between its node rotation and its member-end rotation."""
    K = base.copy()
    k = np.asarray(tangents, dtype=float)
    a, b = np.asarray(dofs.hinge_node), np.asarray(dofs.hinge)
    np.add.at(K, (b, b), k)  # (in hinge order, as a loop would add them)
    on = a >= 0
    np.add.at(K, (a[on], a[on]), k[on])
    np.add.at(K, (a[on], b[on]), -k[on])
    np.add.at(K, (b[on], a[on]), -k[on])
    return K


def hinge_incidence(dofs: FrameDofs) -> Any:
    """The hinges' incidence ``B`` (n, n_h), sparse: +1 at a hinge's joint rotation (none at a
    support), −1 at its member end's, so that the hinge rotations are ``Bᵀ U``, the nodal
    loads of hinge moments ``q`` are ``B q`` and the springs of tangents ``k`` are
    ``B diag(k) Bᵀ``."""
    import scipy.sparse

    node, end = np.asarray(dofs.hinge_node), np.asarray(dofs.hinge)
    on = node >= 0
    h = np.arange(end.size)
    return scipy.sparse.csr_matrix(
        (np.concatenate([np.ones(int(on.sum())), -np.ones(end.size)]),
         (np.concatenate([node[on], end]), np.concatenate([h[on], h]))),
        shape=(dofs.n, end.size))


def hinge_rotations(dofs: FrameDofs, U: NDArray[np.float64]) -> NDArray[np.float64]:
    """Hinge rotations ``θ_node − θ_end`` [rad] for displacements ``U``."""
    node = np.where(dofs.hinge_node >= 0, U[np.maximum(dofs.hinge_node, 0)], 0.0)
    return node - U[dofs.hinge]


def _fixed_end(frame: Frame, e: int) -> NDArray[np.float64]:
    """Local fixed-end forces of element e's uniform gravity load (forces the member ends
    exert on the nodes' opposite: the member's end forces with its ends fixed)."""
    w = float(frame.member_loads[e])
    if w == 0.0:
        return np.zeros(6)
    c, s, L = _rotation(frame, e)
    wx, wy = s * (-w), c * (-w)  # global (0, −w) in local axes: (c·0 + s·(−w), −s·0 + c·(−w))
    return -np.array([wx * L / 2, wy * L / 2, wy * L * L / 12,
                      wx * L / 2, wy * L / 2, -wy * L * L / 12])


def gravity_load_vector(frame: Frame, dofs: FrameDofs) -> NDArray[np.float64]:
    """Global load vector of the gravity loads (nodal loads and members' equivalent nodal
    loads) [N, N·m]."""
    F = np.zeros(dofs.n)
    for i in range(frame.n_nodes):
        for d in range(3):
            if dofs.node[i, d] >= 0:
                F[dofs.node[i, d]] += frame.nodal_loads[i, d]
    for e in range(frame.n_elements):
        fef = _fixed_end(frame, e)
        if not np.any(fef):
            continue
        c, s, _ = _rotation(frame, e)
        eq = -(member_transform(c, s).T @ fef)
        for q in range(6):
            if dofs.element[e, q] >= 0:
                F[dofs.element[e, q]] += eq[q]
    return F


def element_end_forces(frame: Frame, dofs: FrameDofs, U: NDArray[np.float64],
                       gravity_factor: float = 1.0) -> NDArray[np.float64]:
    """Local end forces of every element ``(N₁, V₁, M₁, N₂, V₂, M₂)`` [N, N·m], shape (m, 6):
    the elastic element's response to ``U`` plus the fixed-end forces of its member load
    (times ``gravity_factor``). ``−N₁`` is the axial force, tension positive."""
    out = np.zeros((frame.n_elements, 6))
    for e in range(frame.n_elements):
        c, s, L = _rotation(frame, e)
        d = np.where(dofs.element[e] >= 0, U[np.maximum(dofs.element[e], 0)], 0.0)
        out[e] = local_elastic(frame.EA[e], frame.EI[e], L) @ (member_transform(c, s) @ d) \
            + gravity_factor * _fixed_end(frame, e)
    return out


def end_moment_operator(frame: Frame, dofs: FrameDofs, axial: NDArray[np.float64] | None
                        ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The members' end moments as a linear function of the displacements: ``(E, m0)`` with
    ``M = E U + m0`` [N·m], shape (2 m,): elements in order, for each its end 1 then end 2 —
    the local end moments ``M₁, M₂`` of :func:`element_end_forces` (counter-clockwise
    positive, the stiffness method's convention) including the columns' geometric stiffness
    of their gravity axial forces ``axial`` [N] (tension positive; with ``geometry =
    "consistent"`` it carries moments, with ``"p-delta"`` none) and the fixed-end moments of
    the member loads, applied in full."""
    m = frame.n_elements
    E = np.zeros((2 * m, dofs.n))
    m0 = np.zeros(2 * m)
    col = frame.is_column
    for e in range(m):
        c, s, L = _rotation(frame, e)
        T = member_transform(c, s)
        k = local_elastic(frame.EA[e], frame.EI[e], L)
        if frame.geometry != "linear" and axial is not None and col[e] and axial[e] != 0.0:
            k = k + local_geometric(float(axial[e]), L, frame.geometry)
        rows = (k @ T)[[2, 5]]
        idx = dofs.element[e]
        ok = idx >= 0
        for r in range(2):  # (a rigid floor gives both ends of a beam one u_x: add)
            np.add.at(E[2 * e + r], idx[ok], rows[r, ok])
        m0[2 * e: 2 * e + 2] = _fixed_end(frame, e)[[2, 5]]
    return E, m0


def condense(K: NDArray[np.float64], keep: NDArray[np.int64]) -> NDArray[np.float64]:
    """Static condensation onto the DOFs ``keep``: ``K_kk − K_ko K_oo⁻¹ K_ok``."""
    n = K.shape[0]
    other = np.setdiff1d(np.arange(n), keep)
    if other.size == 0:
        return K[np.ix_(keep, keep)].copy()
    import scipy.linalg

    Kko = K[np.ix_(keep, other)]
    X = scipy.linalg.solve(K[np.ix_(other, other)], Kko.T, assume_a="sym")
    Kc = K[np.ix_(keep, keep)] - Kko @ X
    return 0.5 * (Kc + Kc.T)

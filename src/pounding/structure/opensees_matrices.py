"""Take a building's mass and stiffness matrices out of an OpenSeesPy model.

The user builds the model in OpenSeesPy as usual (nodes, ``fix``, ``equalDOF``, elements,
``mass``); :func:`matrices_from_opensees` then assembles the matrices of the whole domain the
documented OpenSeesPy way — the ``GimmeMCK`` integrator, whose system matrix is
``A = m·M + c·C + k·K (+ ki·K_initial)``, on a ``FullGeneral`` system printed with
``printA('-ret')`` — and returns them on the degrees of freedom (DOFs) the user chooses (for
example the horizontal DOF of one node per floor). The other DOFs are condensed out of ``K``
statically (Guyan 1965, *AIAA J.* 3(2):380; the static condensation of Chopra, *Dynamics of
Structures*, 4th ed., §9.3):

    K̂ = K_tt − K_to K_oo⁻¹ K_ot,

``t`` the chosen DOFs and ``o`` the others. The mass matrix is either ``M_tt`` as it is
(``mass="retained"``, the default: lumped floor masses stay diagonal, and mass on the
condensed DOFs — rotational inertia, vertical masses — is left out) or Guyan's
``M̂ = Tᵀ M T`` with ``T = [I; −K_oo⁻¹ K_ot]`` (``mass="guyan"``, generally full).

OpenSeesPy is imported inside the function only; pounding does not need it otherwise.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Literal, NamedTuple

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

__all__ = ["OpenSeesMatrices", "matrices_from_opensees"]


class OpenSeesMatrices(NamedTuple):
    """What :func:`matrices_from_opensees` returns (unpacks as ``M, K, labels``).

    Attributes
    ----------
    M : ndarray, shape (n, n)
        Mass matrix on the chosen DOFs [model units; kg with SI models].
    K : ndarray, shape (n, n)
        Condensed stiffness matrix on the chosen DOFs [N/m with SI models].
    labels : tuple of str
        ``"node <tag> dof <d>"`` for each chosen DOF, in order.
    """

    M: NDArray[np.float64]
    K: NDArray[np.float64]
    labels: tuple[str, ...]


def _gimme(ops: object, m: float, k: float, ki: float, constraints: str
           ) -> NDArray[np.float64]:
    """``A = m·M + k·K + ki·K_initial`` of the current domain from ``GimmeMCK``, dense."""
    o = ops  # the openseespy.opensees module
    o.wipeAnalysis()  # type: ignore[attr-defined]
    o.system("FullGeneral")  # type: ignore[attr-defined]
    o.numberer("Plain")  # type: ignore[attr-defined]
    o.constraints(constraints)  # type: ignore[attr-defined]
    o.integrator("GimmeMCK", m, 0.0, k, ki)  # type: ignore[attr-defined]
    o.algorithm("Linear")  # type: ignore[attr-defined]
    o.analysis("Transient")  # type: ignore[attr-defined]
    # GimmeMCK does not update the displacements (it only forms A); the solve of A x = b may
    # fail when A is singular (a mass matrix with massless rotations), which OpenSees reports
    # as a warning. A is formed either way.
    o.analyze(1, 0.0)  # type: ignore[attr-defined]
    n = int(o.systemSize())  # type: ignore[attr-defined]
    A = np.array(o.printA("-ret"), dtype=np.float64)  # type: ignore[attr-defined]
    if A.size != n * n:
        raise RuntimeError(f"OpenSees printA returned {A.size} numbers for a system of {n} "
                           "equations")
    return A.reshape(n, n)


def _check_plain_ties(ops: object) -> None:
    """Under the Plain handler every MP constraint must have been applied: its constrained
    DOFs share the equations of their retained DOFs. OpenSees ignores (with a warning) a
    constraint whose matrix is not the identity, which would leave the DOFs untied."""
    o = ops
    for c_node in o.getConstrainedNodes():  # type: ignore[attr-defined]
        for r_node in o.getRetainedNodes(c_node):  # type: ignore[attr-defined]
            c_dofs = o.getConstrainedDOFs(c_node, r_node)  # type: ignore[attr-defined]
            r_dofs = o.getRetainedDOFs(r_node, c_node)  # type: ignore[attr-defined]
            c_ids = o.nodeDOFs(c_node)  # type: ignore[attr-defined]
            r_ids = o.nodeDOFs(r_node)  # type: ignore[attr-defined]
            for cd, rd in zip(c_dofs, r_dofs, strict=False):
                if c_ids[int(cd) - 1] != r_ids[int(rd) - 1]:
                    raise ValueError(
                        f"the Plain constraint handler did not apply the MP constraint of node "
                        f"{c_node} on node {r_node} (not an equalDOF-type tie): use "
                        "constraints='Transformation'")


def matrices_from_opensees(dofs: Sequence[int | tuple[int, int]], dof: int = 1, *,
                           mass: Literal["retained", "guyan"] = "retained",
                           stiffness: Literal["initial", "current"] = "initial",
                           constraints: Literal["Plain", "Transformation"] = "Plain",
                           ) -> OpenSeesMatrices:
    """Mass and statically condensed stiffness matrices of the current OpenSeesPy domain.

    Call it after building the model (nodes, boundary conditions, elements, masses). It
    replaces any analysis the domain had (``wipeAnalysis`` before and after) and runs one
    ``GimmeMCK`` step of zero length, which does not move the model.

    Parameters
    ----------
    dofs : sequence of int or (int, int)
        The DOFs to keep, in the order wanted: a node tag (its DOF ``dof``) or a pair
        ``(node tag, dof)``, DOFs numbered from 1 as in OpenSees (1 = x translation).
        Choose free DOFs of retained nodes; a DOF tied by ``equalDOF`` to one already
        chosen is the same equation and is refused.
    dof : int
        The DOF taken for bare node tags (default 1, the horizontal x translation).
    mass : {"retained", "guyan"}
        ``"retained"``: ``M_tt``, the mass on the chosen DOFs as assembled (diagonal when the
        masses are lumped at them). ``"guyan"``: ``Tᵀ M T``, ``T = [I; −K_oo⁻¹ K_ot]``, which
        also carries the mass of the condensed DOFs.
    stiffness : {"initial", "current"}
        ``"initial"``: the initial stiffness (``GimmeMCK`` ``ki``); ``"current"``: the
        current tangent (``GimmeMCK`` ``k``). They are equal for a linear model.
    constraints : {"Plain", "Transformation"}
        OpenSees constraint handler. ``"Plain"`` handles ``fix`` and ties whose constraint
        matrix is the identity, as ``equalDOF`` (the tied DOF takes the retained DOF's
        equation); OpenSees ignores other MP constraints under it, with a warning.
        ``"Transformation"`` also handles ``rigidDiaphragm`` and ``rigidLink``; under it, only
        DOFs of nodes that no MP constraint constrains may be chosen.

    Returns
    -------
    OpenSeesMatrices
        ``(M, K, labels)``; ``M`` and ``K`` are symmetrised float64 (n, n).

    Raises
    ------
    ImportError
        If openseespy is not installed.
    ValueError
        A node not in the domain, a DOF that is fixed or constrained (not an equation of the
        system), the same equation chosen twice, or condensed DOFs that are not restrained by
        stiffness alone (``K_oo`` not positive definite: a mechanism, or an unrestrained DOF
        that should be chosen or fixed).

    Examples
    --------
    A three-storey column line, nodes 1 (base) … 4 (roof), horizontal DOF of nodes 2–4::

        M, K, labels = matrices_from_opensees([2, 3, 4])            # x of each floor node
        M, K, labels = matrices_from_opensees([(2, 1), (3, 1), (4, 1)])   # the same
    """
    if mass not in ("retained", "guyan"):
        raise ValueError(f"mass must be 'retained' or 'guyan' (got {mass!r})")
    if stiffness not in ("initial", "current"):
        raise ValueError(f"stiffness must be 'initial' or 'current' (got {stiffness!r})")
    if constraints not in ("Plain", "Transformation"):
        raise ValueError(f"constraints must be 'Plain' or 'Transformation' (got {constraints!r})")
    if isinstance(dofs, str | bytes) or len(dofs) == 0:
        raise ValueError(f"dofs must be a non-empty sequence of node tags or (node, dof) pairs "
                         f"(got {dofs!r})")
    chosen: list[tuple[int, int]] = []
    for item in dofs:
        pair = (item, dof) if not isinstance(item, tuple) else item
        if (len(pair) != 2 or any(isinstance(x, bool) or not isinstance(x, int | np.integer)
                                  for x in pair) or pair[1] < 1):
            raise ValueError(f"each entry of dofs must be a node tag or a (node tag, dof) pair of "
                             f"integers, dof from 1 (got {item!r})")
        chosen.append((int(pair[0]), int(pair[1])))

    import openseespy.opensees as ops

    try:
        ka, ki = (0.0, 1.0) if stiffness == "initial" else (1.0, 0.0)
        K_full = _gimme(ops, 0.0, ka, ki, constraints)
        M_full = _gimme(ops, 1.0, 0.0, 0.0, constraints)
        # Equation numbers are those of the analysis just set up (Plain numberer).
        tags = set(int(t) for t in ops.getNodeTags())
        # Under the Transformation handler, nodeDOFs of a node constrained by an MP constraint
        # does not give its equations in DOF order (OpenSeesPy 3.7.1); such nodes are refused.
        tied = (set(int(t) for t in ops.getConstrainedNodes())
                if constraints == "Transformation" else set())
        if constraints == "Plain":
            _check_plain_ties(ops)
        eqs: list[int] = []
        labels: list[str] = []
        for node, d in chosen:
            label = f"node {node} dof {d}"
            if node not in tags:
                raise ValueError(f"{label}: node {node} is not in the OpenSees domain")
            if node in tied:
                raise ValueError(f"{label}: node {node} is constrained by an MP constraint "
                                 "(equalDOF, rigidDiaphragm, rigidLink); choose its retained "
                                 "node's DOF")
            ids = list(ops.nodeDOFs(node))
            if d > len(ids):
                raise ValueError(f"{label}: node {node} has {len(ids)} DOFs")
            eq = int(ids[d - 1])
            if eq < 0:
                raise ValueError(f"{label} is fixed or constrained: it is not an equation of the "
                                 "system (choose a free DOF of a retained node)")
            if eq in eqs:
                other = labels[eqs.index(eq)]
                raise ValueError(f"{label} is the same equation as {other} (tied by equalDOF): "
                                 "choose one of them")
            eqs.append(eq)
            labels.append(label)
    finally:
        ops.wipeAnalysis()

    n_all = K_full.shape[0]
    t = np.array(eqs, dtype=np.intp)
    o = np.setdiff1d(np.arange(n_all), t)
    K_full = 0.5 * (K_full + K_full.T)
    M_full = 0.5 * (M_full + M_full.T)
    Ktt = K_full[np.ix_(t, t)]
    if o.size == 0:
        K_hat, T_o = Ktt, np.zeros((0, t.size))
    else:
        Koo = K_full[np.ix_(o, o)]
        Kot = K_full[np.ix_(o, t)]
        try:
            factor = scipy.linalg.cho_factor(Koo)
        except np.linalg.LinAlgError:
            lam = float(np.linalg.eigvalsh(Koo)[0])
            raise ValueError(
                "the DOFs to condense out are not restrained by stiffness alone (their "
                f"stiffness matrix K_oo has smallest eigenvalue {lam:.6g}): a mechanism, or a "
                "free DOF with no stiffness; choose it, fix it or tie it") from None
        T_o = -scipy.linalg.cho_solve(factor, Kot)          # K_oo⁻¹ K_ot, with the sign of T
        K_hat = Ktt + Kot.T @ T_o                           # K_tt − K_to K_oo⁻¹ K_ot
    if mass == "retained":
        M_hat = M_full[np.ix_(t, t)]
    else:
        T = np.zeros((n_all, t.size))
        T[t, np.arange(t.size)] = 1.0
        T[o, :] = T_o
        M_hat = T.T @ M_full @ T
    M_hat = np.ascontiguousarray(0.5 * (M_hat + M_hat.T))
    K_hat = np.ascontiguousarray(0.5 * (K_hat + K_hat.T))
    return OpenSeesMatrices(M=M_hat, K=K_hat, labels=tuple(labels))

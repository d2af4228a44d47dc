"""Checks of a building's matrices and of the per-DOF data that go with them.

A matrix (:func:`check_matrix`): non-empty, finite, square, symmetric to
:data:`SYMMETRY_RTOL` of its largest entry; positive definite by Cholesky factorisation
(:func:`check_positive_definite`); lumped masses (:func:`lumped_masses`, diagonal to
:data:`DIAGONAL_RTOL`). The DOFs' labels (:func:`dof_labels`), vectors such as elevations
and ``r`` (:func:`dof_vector`) and floors (:func:`floor_indices`). Every fault raises
:class:`ValueError` in one line that starts with ``where`` (a file, or a building) and names
the entry at fault, 0-based as in NumPy. Used by :class:`pounding.structure.MatrixBuilding`
(:mod:`pounding.structure.matrices`) and the readers of :mod:`pounding.structure.matrix_files`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.structure.floor_arrays import MAX_FLOORS

__all__ = ["DIAGONAL_RTOL", "SYMMETRY_RTOL", "check_matrix", "check_positive_definite",
           "dof_labels", "dof_vector", "floor_indices", "is_diagonal", "lumped_masses",
           "matrix_shape", "smallest_eigenvalue", "where_prefix"]

SYMMETRY_RTOL: float = 1e-10
"""A matrix ``A`` is taken as symmetric when ``max |A[i,j] − A[j,i]| <= SYMMETRY_RTOL ·
max |A|``; it is then stored as ``(A + Aᵀ)/2``. The same relative tolerance decides the
zero entries and zero row sums of the shear-building pattern
(:meth:`MatrixBuilding.is_shear_building`) and how negative an eigenvalue of ``C`` may be."""

DIAGONAL_RTOL: float = 1e-12
"""``M`` is diagonal (lumped) when every off-diagonal ``|M[i,j]| <= DIAGONAL_RTOL ·
max M[k,k]``."""


def where_prefix(where: str) -> str:
    """``"<where>: "`` to start a message, or nothing if ``where`` is empty."""
    return f"{where}: " if where else ""


def matrix_shape(A: NDArray[Any]) -> str:
    """An array's shape for a message: ``"3×3"``, or ``"a scalar"``."""
    return "×".join(str(s) for s in A.shape) if A.ndim else "a scalar"


def check_matrix(A: ArrayLike, name: str, where: str = "") -> NDArray[np.float64]:
    """Check that ``A`` is a non-empty, finite, square, symmetric real matrix.

    Symmetry is judged against the largest entry: ``max |A[i,j] − A[j,i]| <=``
    :data:`SYMMETRY_RTOL` ``· max |A|``.

    Parameters
    ----------
    A : array_like
        The matrix.
    name : str
        Its name in messages (``"M"``, ``"K"``, ``"C"``).
    where : str
        What to name at the head of a message: a file, or a building.

    Returns
    -------
    ndarray, shape (n, n)
        A float64 C-contiguous copy, ``(A + Aᵀ)/2``.

    Raises
    ------
    ValueError
        ``"<where>: K must be symmetric: K[0,2] = 1 but K[2,0] = 1.5 (…)"`` and the like.
    """
    pre = where_prefix(where)
    try:
        a = np.array(A, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{pre}{name} must be a matrix of real numbers (got {A!r})") from None
    if a.ndim != 2:
        raise ValueError(f"{pre}{name} must be a 2-D matrix (got {matrix_shape(a)})")
    if a.size == 0:
        raise ValueError(f"{pre}{name} is empty ({matrix_shape(a)})")
    if a.shape[0] != a.shape[1]:
        raise ValueError(f"{pre}{name} must be square (got {matrix_shape(a)})")
    if a.shape[0] > MAX_FLOORS:
        raise ValueError(f"{pre}{name} has {a.shape[0]} degrees of freedom; at most "
                         f"{MAX_FLOORS} are taken")
    bad = ~np.isfinite(a)
    if np.any(bad):
        i, j = (int(x) for x in np.argwhere(bad)[0])
        raise ValueError(f"{pre}{name}[{i},{j}] = {a[i, j]} is not finite")
    scale = float(np.max(np.abs(a)))
    diff = np.abs(a - a.T)
    i, j = (int(x) for x in np.unravel_index(int(np.argmax(diff)), diff.shape))
    if diff[i, j] > SYMMETRY_RTOL * scale:
        if i > j:
            i, j = j, i
        raise ValueError(f"{pre}{name} must be symmetric: {name}[{i},{j}] = {a[i, j]:.10g} but "
                         f"{name}[{j},{i}] = {a[j, i]:.10g} (difference {diff[i, j]:.3g} > "
                         f"{SYMMETRY_RTOL:g} × largest entry {scale:.6g})")
    return np.ascontiguousarray(0.5 * (a + a.T))


def smallest_eigenvalue(A: NDArray[np.float64]) -> float:
    """The smallest eigenvalue of the symmetric ``A``."""
    return float(np.linalg.eigvalsh(A)[0])


def check_positive_definite(A: NDArray[np.float64], name: str, where: str, hint: str) -> None:
    """Cholesky factorisation of the symmetric ``A``; on failure name its smallest eigenvalue."""
    try:
        np.linalg.cholesky(A)
    except np.linalg.LinAlgError:
        lam = smallest_eigenvalue(A)
        raise ValueError(f"{where_prefix(where)}{name} must be positive definite ({hint}); its "
                         f"smallest eigenvalue is {lam:.6g}") from None


def is_diagonal(M: NDArray[np.float64]) -> tuple[bool, int, int]:
    """(diagonal?, i, j of the largest off-diagonal entry)."""
    n = M.shape[0]
    if n == 1:
        return True, 0, 0
    off = np.abs(M - np.diag(np.diag(M)))
    i, j = (int(x) for x in np.unravel_index(int(np.argmax(off)), off.shape))
    scale = float(np.max(np.abs(np.diag(M))))
    return bool(off[i, j] <= DIAGONAL_RTOL * scale), min(i, j), max(i, j)


def lumped_masses(M: ArrayLike, where: str = "") -> NDArray[np.float64]:
    """The diagonal of a lumped (diagonal) mass matrix, or a clear refusal.

    The project's time stepper takes one mass per degree of freedom. ``M`` counts as diagonal
    when every off-diagonal entry is at most :data:`DIAGONAL_RTOL` times its largest diagonal
    entry.

    Parameters
    ----------
    M : array_like, shape (n, n)
        Mass matrix [kg].
    where : str
        What to name at the head of a message (a file, or a building).

    Returns
    -------
    ndarray, shape (n,)
        ``M[i,i]`` [kg], each > 0.

    Raises
    ------
    ValueError
        ``"M must be diagonal (lumped floor masses); got off-diagonal entry M[i,j] = …"``
        (naming the largest), or naming a diagonal entry that is not > 0.
    """
    Mf = check_matrix(M, "M", where)
    ok, i, j = is_diagonal(Mf)
    if not ok:
        raise ValueError(f"{where_prefix(where)}M must be diagonal (lumped floor masses); got "
                         f"off-diagonal entry M[{i},{j}] = {Mf[i, j]:.10g}")
    m = np.ascontiguousarray(np.diag(Mf))
    for k, x in enumerate(m):
        if not x > 0.0:
            raise ValueError(f"{where_prefix(where)}M[{k},{k}] = {x:g} must be > 0: every degree of "
                             "freedom needs a positive mass")
    return m


def dof_vector(name: str, value: ArrayLike, n: int, where: str) -> NDArray[np.float64]:
    """``value`` as a read-only float64 vector of one finite number per DOF (``n``)."""
    pre = where_prefix(where)
    try:
        v = np.array(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{pre}{name} must be numbers, one per degree of freedom "
                         f"(got {value!r})") from None
    v = np.atleast_1d(v)
    if v.ndim != 1:
        raise ValueError(f"{pre}{name} must be one-dimensional, one value per degree of freedom "
                         f"(got shape {v.shape})")
    if v.size != n:
        raise ValueError(f"{pre}{name} has {v.size} values but the matrices have {n} degrees "
                         "of freedom")
    bad = ~np.isfinite(v)
    if np.any(bad):
        k = int(np.argmax(bad))
        raise ValueError(f"{pre}{name}[{k}] = {v[k]} is not finite")
    v = np.ascontiguousarray(v)
    v.flags.writeable = False
    return v


def dof_labels(value: Any, n: int, where: str) -> tuple[str, ...]:
    """``value`` as ``n`` distinct, non-empty DOF labels."""
    pre = where_prefix(where)
    if isinstance(value, str) or not isinstance(value, Sequence | np.ndarray):
        raise ValueError(f"{pre}labels must be a sequence of strings, one per degree of freedom "
                         f"(got {value!r})")
    labels = tuple(value)
    if len(labels) != n:
        raise ValueError(f"{pre}labels has {len(labels)} entries but the matrices have {n} "
                         "degrees of freedom")
    seen: dict[str, int] = {}
    for k, lab in enumerate(labels):
        if not isinstance(lab, str) or not lab.strip():
            raise ValueError(f"{pre}labels[{k}] must be a non-empty string (got {lab!r})")
        if lab in seen:
            raise ValueError(f"{pre}labels[{k}] = {lab!r} repeats labels[{seen[lab]}]; each "
                             "degree of freedom needs its own label")
        seen[lab] = k
    return labels


def floor_indices(value: Any, labels: tuple[str, ...], where: str,
                  field: str = "floors") -> tuple[int, ...]:
    """The floor DOFs, 0-based and ascending, from indices or labels (default: all);
    ``field`` names them in messages."""
    n = len(labels)
    if value is None:
        return tuple(range(n))
    pre = where_prefix(where)
    if isinstance(value, str) or not isinstance(value, Sequence | np.ndarray) or not len(value):
        raise ValueError(f"{pre}{field} must be a non-empty sequence of degree-of-freedom "
                         f"indices or labels (got {value!r})")
    out: list[int] = []
    for k, f in enumerate(value):
        if isinstance(f, str):
            if f not in labels:
                raise ValueError(f"{pre}{field}[{k}] = {f!r} is not one of the labels")
            i = labels.index(f)
        elif isinstance(f, int | np.integer) and not isinstance(f, bool) and 0 <= f < n:
            i = int(f)
        else:
            raise ValueError(f"{pre}{field}[{k}] = {f!r} must be a label or an index in "
                             f"[0, {n - 1}]")
        if i in out:
            raise ValueError(f"{pre}{field}[{k}] = {f!r} is given twice")
        out.append(i)
    return tuple(sorted(out))

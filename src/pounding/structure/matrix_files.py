"""Matrices of a building read from files and checked: plain text, NumPy ``.npy`` / ``.npz``
and Matrix Market ``.mtx`` (:func:`read_matrix`), symmetric and positive definite
(:func:`check_matrix`), and the lumped masses the time stepper takes (:func:`lumped_masses`);
the per-DOF labels, vectors and floors that go with them; a
:class:`~pounding.structure.matrices.MatrixBuilding` read from its files
(:func:`read_matrix_building`). See :mod:`pounding.structure.matrices` for the formats and
the checks."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.structure.damping import DampingModel
from pounding.structure.shear_building import MAX_FLOORS

if TYPE_CHECKING:
    from pounding.structure.matrices import MatrixBuilding

__all__ = ["DIAGONAL_RTOL", "MATRIX_FORMATS", "SYMMETRY_RTOL", "StrPath", "check_matrix",
           "lumped_masses", "read_matrix", "read_matrix_building"]

StrPath = str | os.PathLike[str]

SYMMETRY_RTOL: float = 1e-10
"""A matrix ``A`` is taken as symmetric when ``max |A[i,j] − A[j,i]| <= SYMMETRY_RTOL ·
max |A|``; it is then stored as ``(A + Aᵀ)/2``. The same relative tolerance decides the
zero entries and zero row sums of the shear-building pattern
(:meth:`MatrixBuilding.is_shear_building`) and how negative an eigenvalue of ``C`` may be."""

DIAGONAL_RTOL: float = 1e-12
"""``M`` is diagonal (lumped) when every off-diagonal ``|M[i,j]| <= DIAGONAL_RTOL ·
max M[k,k]``."""

MATRIX_FORMATS: dict[str, str] = {
    ".csv": "text", ".txt": "text", ".dat": "text",
    ".npy": "npy", ".npz": "npz", ".mtx": "mtx",
}
"""File suffix (lower case) → format read by :func:`read_matrix`."""


def _prefix(where: str) -> str:
    return f"{where}: " if where else ""


def _shape(A: NDArray[Any]) -> str:
    return "×".join(str(s) for s in A.shape) if A.ndim else "a scalar"


# --------------------------------------------------------------------------- readers
def _read_text(path: Path) -> NDArray[np.float64]:
    """Plain numbers, one matrix row a line, comma- or whitespace-separated; ``#`` comments."""
    try:
        text = path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        raise ValueError(f"{path}: not a text file (expected plain numbers, comma or "
                         "whitespace separated)") from None
    rows: list[list[float]] = []
    first_line = 0
    for lineno, line in enumerate(text.splitlines(), start=1):
        body = line.split("#", 1)[0].strip()
        if not body:
            continue
        fields = [f.strip() for f in body.split(",")] if "," in body else body.split()
        row = []
        for f in fields:
            if not f:
                raise ValueError(f"{path}: line {lineno} has an empty field between commas")
            try:
                row.append(float(f))
            except ValueError:
                raise ValueError(f"{path}: line {lineno}: {f!r} is not a number (the file "
                                 "must hold plain numbers, comma or whitespace separated, "
                                 "no header)") from None
        if rows and len(row) != len(rows[0]):
            raise ValueError(f"{path}: line {lineno} has {len(row)} numbers but line "
                             f"{first_line} has {len(rows[0])}: every row of a matrix needs "
                             "as many")
        if not rows:
            first_line = lineno
        rows.append(row)
    if not rows:
        raise ValueError(f"{path}: holds no numbers")
    return np.array(rows, dtype=np.float64)


def _numeric(arr: Any, path: Path, what: str) -> NDArray[np.float64]:
    a = np.asarray(arr)
    if a.dtype == np.bool_ or not (np.issubdtype(a.dtype, np.integer)
                                    or np.issubdtype(a.dtype, np.floating)):
        raise ValueError(f"{path}: {what} holds {a.dtype} values; expected real numbers")
    return np.array(a, dtype=np.float64)


def _read_npy(path: Path) -> NDArray[np.float64]:
    try:
        arr = np.load(path, allow_pickle=False)
    except (OSError, ValueError, EOFError) as exc:
        raise ValueError(f"{path}: not a NumPy .npy file ({exc})") from None
    if isinstance(arr, np.lib.npyio.NpzFile):
        arr.close()
        raise ValueError(f"{path}: is an .npz archive, not an .npy array; name it .npz")
    return _numeric(arr, path, "the array")


def _read_npz(path: Path, name: str) -> NDArray[np.float64]:
    try:
        archive = np.load(path, allow_pickle=False)
    except (OSError, ValueError, EOFError) as exc:
        raise ValueError(f"{path}: not a NumPy .npz archive ({exc})") from None
    if not isinstance(archive, np.lib.npyio.NpzFile):
        raise ValueError(f"{path}: is a single .npy array, not an .npz archive; name it .npy")
    with archive:
        if name not in archive.files:
            held = ", ".join(archive.files) or "nothing"
            raise ValueError(f"{path}: has no array {name!r} (it holds {held}); a building's "
                             ".npz holds M, K and optionally C")
        try:
            arr = archive[name]
        except (OSError, ValueError) as exc:
            raise ValueError(f"{path}: array {name!r} cannot be read ({exc})") from None
        return _numeric(arr, path, f"array {name!r}")


def _read_mtx(path: Path) -> NDArray[np.float64]:
    import scipy.io  # only when a Matrix Market file is read

    try:
        info = scipy.io.mminfo(path)
    except (OSError, ValueError, IndexError) as exc:
        raise ValueError(f"{path}: not a Matrix Market file ({exc})") from None
    fld = str(info[4]).lower()
    if fld not in ("real", "integer", "double"):
        raise ValueError(f"{path}: Matrix Market field is {fld!r}; expected real or integer")
    try:
        arr = scipy.io.mmread(path)
    except (OSError, ValueError, IndexError) as exc:
        raise ValueError(f"{path}: cannot be read as Matrix Market ({exc})") from None
    if hasattr(arr, "toarray"):
        arr = arr.toarray()
    return _numeric(arr, path, "the matrix")


def read_matrix(path: StrPath, name: str = "M") -> NDArray[np.float64]:
    """Read one matrix from a file and check it with :func:`check_matrix`.

    Parameters
    ----------
    path : str or path-like
        A ``.csv``/``.txt``/``.dat`` file of plain numbers (comma or whitespace separated, one
        row a line, ``#`` comments, no header), a NumPy ``.npy`` or ``.npz`` file, or a Matrix
        Market ``.mtx`` file (:func:`scipy.io.mmread`; real or integer entries, general or
        symmetric storage, dense or sparse).
    name : str
        The matrix's name in messages (``"M"``, ``"K"``, ``"C"``); in an ``.npz`` file, the
        name of the array read.

    Returns
    -------
    ndarray, shape (n, n)
        Float64, C-contiguous, symmetrised as ``(A + Aᵀ)/2``.

    Raises
    ------
    ValueError
        One line naming the file and the problem: missing file, unknown suffix, a line that is
        not numbers, ragged rows, not 2-D, not square, not finite, not symmetric.
    """
    p = Path(path)
    fmt = MATRIX_FORMATS.get(p.suffix.lower())
    if fmt is None:
        known = ", ".join(MATRIX_FORMATS)
        raise ValueError(f"{p}: unknown matrix file type {p.suffix!r}; read are {known}")
    if not p.is_file():
        raise ValueError(f"{p}: no such file")
    if fmt == "text":
        A = _read_text(p)
    elif fmt == "npy":
        A = _read_npy(p)
    elif fmt == "npz":
        A = _read_npz(p, name)
    else:
        A = _read_mtx(p)
    return check_matrix(A, name, str(p))


# --------------------------------------------------------------------------- checks
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
    pre = _prefix(where)
    try:
        a = np.array(A, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{pre}{name} must be a matrix of real numbers (got {A!r})") from None
    if a.ndim != 2:
        raise ValueError(f"{pre}{name} must be a 2-D matrix (got {_shape(a)})")
    if a.size == 0:
        raise ValueError(f"{pre}{name} is empty ({_shape(a)})")
    if a.shape[0] != a.shape[1]:
        raise ValueError(f"{pre}{name} must be square (got {_shape(a)})")
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


def _smallest_eigenvalue(A: NDArray[np.float64]) -> float:
    return float(np.linalg.eigvalsh(A)[0])


def _check_positive_definite(A: NDArray[np.float64], name: str, where: str, hint: str) -> None:
    """Cholesky factorisation of the symmetric ``A``; on failure name its smallest eigenvalue."""
    try:
        np.linalg.cholesky(A)
    except np.linalg.LinAlgError:
        lam = _smallest_eigenvalue(A)
        raise ValueError(f"{_prefix(where)}{name} must be positive definite ({hint}); its "
                         f"smallest eigenvalue is {lam:.6g}") from None


def _is_diagonal(M: NDArray[np.float64]) -> tuple[bool, int, int]:
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
    ok, i, j = _is_diagonal(Mf)
    if not ok:
        raise ValueError(f"{_prefix(where)}M must be diagonal (lumped floor masses); got "
                         f"off-diagonal entry M[{i},{j}] = {Mf[i, j]:.10g}")
    m = np.ascontiguousarray(np.diag(Mf))
    for k, x in enumerate(m):
        if not x > 0.0:
            raise ValueError(f"{_prefix(where)}M[{k},{k}] = {x:g} must be > 0: every degree of "
                             "freedom needs a positive mass")
    return m


def _vector(name: str, value: ArrayLike, n: int, where: str) -> NDArray[np.float64]:
    pre = _prefix(where)
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


def _labels(value: Any, n: int, where: str) -> tuple[str, ...]:
    pre = _prefix(where)
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


def _floors(value: Any, labels: tuple[str, ...], where: str) -> tuple[int, ...]:
    """The floor DOFs, 0-based and ascending, from indices or labels (default: all)."""
    n = len(labels)
    if value is None:
        return tuple(range(n))
    pre = _prefix(where)
    if isinstance(value, str) or not isinstance(value, Sequence | np.ndarray) or not len(value):
        raise ValueError(f"{pre}floors must be a non-empty sequence of degree-of-freedom "
                         f"indices or labels (got {value!r})")
    out: list[int] = []
    for k, f in enumerate(value):
        if isinstance(f, str):
            if f not in labels:
                raise ValueError(f"{pre}floors[{k}] = {f!r} is not one of the labels")
            i = labels.index(f)
        elif isinstance(f, int | np.integer) and not isinstance(f, bool) and 0 <= f < n:
            i = int(f)
        else:
            raise ValueError(f"{pre}floors[{k}] = {f!r} must be a label or an index in "
                             f"[0, {n - 1}]")
        if i in out:
            raise ValueError(f"{pre}floors[{k}] = {f!r} is given twice")
        out.append(i)
    return tuple(sorted(out))


# --------------------------------------------------------------------------- from files
def read_matrix_building(M: StrPath, K: StrPath | None = None, C: StrPath | None = None, *,
                         labels: Sequence[str], elevations: ArrayLike,
                         r: ArrayLike | None = None, damping: DampingModel | None = None,
                         name: str = "", floors: Sequence[int | str] | None = None
                         ) -> MatrixBuilding:
    """Read a :class:`MatrixBuilding` from matrix files.

    Parameters
    ----------
    M : str or path-like
        The mass-matrix file (any format of :func:`read_matrix`), or an ``.npz`` archive
        holding arrays ``M``, ``K`` and optionally ``C``.
    K : str or path-like, optional
        The stiffness-matrix file; may be omitted when ``M`` is an ``.npz`` archive (``K`` is
        then read from it).
    C : str or path-like, optional
        A damping-matrix file. When it is not given and ``M`` is an ``.npz`` archive that
        holds a ``C``, that ``C`` is read (and giving ``damping`` too is an error).
    labels : sequence of str
        One label per degree of freedom.
    elevations : array_like
        One elevation [m] per degree of freedom.
    r : array_like, optional
        Influence vector (default all ones).
    damping : DampingModel, optional
        Damping model, if no ``C`` is read (default 5 % Rayleigh at modes 1 and 2).
    name : str
        The building's name.
    floors : sequence of int or str, optional
        The DOFs that are floor translations (:class:`MatrixBuilding`); default all.

    Returns
    -------
    MatrixBuilding
        With :attr:`MatrixBuilding.sources` naming the file of each matrix.

    Raises
    ------
    ValueError
        One line naming the file and the problem.
    """
    m_path = Path(M)
    sources: dict[str, str] = {"M": str(m_path)}
    Mx = read_matrix(m_path, "M")
    npz = m_path.suffix.lower() == ".npz"
    if K is None:
        if not npz:
            raise ValueError(f"{m_path}: give K's file too (only an .npz archive holds both)")
        k_path = m_path
    else:
        k_path = Path(K)
    Kx = read_matrix(k_path, "K")
    sources["K"] = str(k_path)
    Cx = None
    if C is not None:
        c_path = Path(C)
        Cx = read_matrix(c_path, "C")
        sources["C"] = str(c_path)
    elif npz:
        with np.load(m_path, allow_pickle=False) as archive:
            has_c = "C" in archive.files
        if has_c:
            if damping is not None:
                raise ValueError(f"{m_path}: holds a damping matrix C and a damping model was "
                                 "given too; give one")
            Cx = read_matrix(m_path, "C")
            sources["C"] = str(m_path)
    from pounding.structure.matrices import MatrixBuilding

    return MatrixBuilding(M=Mx, K=Kx, labels=tuple(labels),
                          elevations=elevations, r=r,  # type: ignore[arg-type]
                          C=Cx, damping=damping, name=name, sources=sources, floors=floors)

"""Matrices of a building read from files: plain text, NumPy ``.npy`` / ``.npz`` and Matrix
Market ``.mtx`` (:func:`read_matrix`), each checked on reading
(:func:`pounding.structure.matrix_checks.check_matrix`); a
:class:`~pounding.structure.matrices.MatrixBuilding` read from its files
(:func:`read_matrix_building`). See :mod:`pounding.structure.matrices` for the formats and
the checks."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.structure.damping import DampingModel
from pounding.structure.floor_arrays import MAX_FLOORS
from pounding.structure.matrices import MatrixBuilding
from pounding.structure.matrix_checks import check_matrix

__all__ = ["MATRIX_FORMATS", "StrPath", "read_matrix", "read_matrix_building"]

StrPath = str | os.PathLike[str]

MATRIX_FORMATS: dict[str, str] = {
    ".csv": "text", ".txt": "text", ".dat": "text",
    ".npy": "npy", ".npz": "npz", ".mtx": "mtx",
}
"""File suffix (lower case) → format read by :func:`read_matrix`."""


# --------------------------------------------------------------------------- readers
# No message here shows a file's text, nor an exception of the library that read it (which
# may quote the file): a file given as a matrix may be anything. Sizes are checked from a
# file's header before anything is allocated from them.
MAX_TEXT_LINE: int = 64 * MAX_FLOORS
"""Longest line of a text matrix file [characters]: a row of :data:`MAX_FLOORS` numbers
written to 17 significant digits with their separators fits well within it."""


def _too_large(path: Path, what: str, shape: tuple[int, ...]) -> ValueError:
    dims = "×".join(str(int(d)) for d in shape)
    return ValueError(f"{path}: {what} declares a {dims} array; a building's matrix is at most "
                      f"{MAX_FLOORS}×{MAX_FLOORS} (one row and column per degree of freedom)")


def _check_declared(path: Path, what: str, shape: tuple[int, ...]) -> None:
    """Refuse a shape declared by a file's header that no building matrix can have, before
    anything is allocated from it."""
    dims = [int(d) for d in shape]
    total = 1
    for d in dims:
        total *= d
    if any(d > MAX_FLOORS for d in dims) or total > MAX_FLOORS * MAX_FLOORS:
        raise _too_large(path, what, shape)


def _read_text(path: Path) -> NDArray[np.float64]:
    """Plain numbers, one matrix row a line, comma- or whitespace-separated; ``#`` comments.

    Read a line at a time: a line longer than :data:`MAX_TEXT_LINE` characters, or more
    than :data:`MAX_FLOORS` rows, is refused before it is held whole.
    """
    rows: list[NDArray[np.float64]] = []
    first_line = 0
    with path.open("rb") as f:
        lineno = 0
        while True:
            raw = f.readline(MAX_TEXT_LINE + 1)
            if not raw:
                break
            lineno += 1
            if len(raw) > MAX_TEXT_LINE and not raw.endswith(b"\n"):
                raise ValueError(f"{path}: line {lineno} is longer than {MAX_TEXT_LINE} "
                                 "characters, more than a row of any building matrix holds")
            try:
                line = raw.decode("utf-8")
            except UnicodeDecodeError:
                raise ValueError(f"{path}: not a text file (expected plain numbers, comma or "
                                 "whitespace separated)") from None
            if lineno == 1:
                line = line.removeprefix("\ufeff")
            body = line.split("#", 1)[0].strip()
            if not body:
                continue
            fields = [x.strip() for x in body.split(",")] if "," in body else body.split()
            row = np.empty(len(fields))
            for k, x in enumerate(fields):
                if not x:
                    raise ValueError(f"{path}: line {lineno} has an empty field between commas")
                try:
                    row[k] = float(x)
                except ValueError:  # the text is never shown: the file may be anything
                    place = "the line" if len(fields) == 1 else \
                        f"item {k + 1} of {len(fields)} on the line"
                    raise ValueError(f"{path}: line {lineno}: {place} is not a number (the "
                                     "file must hold plain numbers, comma or whitespace "
                                     "separated, no header)") from None
            if rows and row.size != rows[0].size:
                raise ValueError(f"{path}: line {lineno} has {row.size} numbers but line "
                                 f"{first_line} has {rows[0].size}: every row of a matrix "
                                 "needs as many")
            if not rows:
                first_line = lineno
            rows.append(row)
            if len(rows) > MAX_FLOORS:
                raise ValueError(f"{path}: more than {MAX_FLOORS} rows (line {lineno}); a "
                                 f"building's matrix is at most {MAX_FLOORS}×{MAX_FLOORS} (one "
                                 "row and column per degree of freedom)")
    if not rows:
        raise ValueError(f"{path}: holds no numbers")
    return np.array(rows, dtype=np.float64)


def _numeric(arr: Any, path: Path, what: str) -> NDArray[np.float64]:
    a = np.asarray(arr)
    if a.dtype == np.bool_ or not (np.issubdtype(a.dtype, np.integer)
                                    or np.issubdtype(a.dtype, np.floating)):
        raise ValueError(f"{path}: {what} holds {a.dtype} values; expected real numbers")
    return np.array(a, dtype=np.float64)


def _npy_header(f: Any, path: Path, what: str, available: int) -> None:
    """Read the ``.npy`` header at the start of the open binary stream ``f`` and refuse, in
    one line, an array no building matrix can be or one the stream is too short to hold
    (``available``: the bytes in the stream, header included)."""
    from numpy.lib import format as npy_format

    try:
        version = npy_format.read_magic(f)
        if version == (1, 0):
            shape, _, dtype = npy_format.read_array_header_1_0(f)
        else:  # 2.0, and 3.0, whose header differs only in its text encoding
            shape, _, dtype = npy_format.read_array_header_2_0(f)
    except (ValueError, OSError, EOFError, SyntaxError, TypeError):
        raise ValueError(f"{path}: not a NumPy .npy file ({what} has no valid .npy header)"
                         if what == "the file" else
                         f"{path}: {what} is not a NumPy .npy array (no valid .npy header)"
                         ) from None
    _check_declared(path, f"{what}'s .npy header", tuple(shape))
    count = 1
    for d in shape:
        count *= int(d)
    need = count * dtype.itemsize
    have = available - f.tell()
    if dtype.hasobject:
        raise ValueError(f"{path}: not a NumPy .npy file of numbers ({what} holds Python "
                         "objects, which pounding does not load)")
    if have < need:
        dims = "×".join(str(int(d)) for d in shape) or "scalar"
        raise ValueError(f"{path}: {what} is cut short: its header declares a {dims} "
                         f"{dtype} array ({need} bytes) but {max(have, 0)} bytes follow it")


def _read_npy(path: Path) -> NDArray[np.float64]:
    import zipfile

    if zipfile.is_zipfile(path):
        raise ValueError(f"{path}: is an .npz archive, not an .npy array; name it .npz")
    with path.open("rb") as f:
        _npy_header(f, path, "the file", path.stat().st_size)
    try:
        arr = np.load(path, allow_pickle=False)
    except (OSError, ValueError, EOFError):
        raise ValueError(f"{path}: not a NumPy .npy file (its array cannot be read)") from None
    return _numeric(arr, path, "the array")


def _read_npz(path: Path, name: str) -> NDArray[np.float64]:
    import zipfile

    if not zipfile.is_zipfile(path):
        with path.open("rb") as f:
            if f.read(6) == b"\x93NUMPY":
                raise ValueError(f"{path}: is a single .npy array, not an .npz archive; name "
                                 "it .npy")
        raise ValueError(f"{path}: not a NumPy .npz archive (not a zip archive)")
    try:
        archive = np.load(path, allow_pickle=False)
    except (OSError, ValueError, EOFError, zipfile.BadZipFile):
        raise ValueError(f"{path}: not a NumPy .npz archive (it cannot be opened)") from None
    if not isinstance(archive, np.lib.npyio.NpzFile):
        raise ValueError(f"{path}: is a single .npy array, not an .npz archive; name it .npy")
    with archive:
        zipped = archive.zip  # None only once the archive is closed
        assert zipped is not None
        members = zipped.namelist()
        if not all(m.endswith(".npy") for m in members):
            # a zip archive of other files: its member names are not shown either
            raise ValueError(f"{path}: a zip archive that is not a NumPy .npz archive (not "
                             "every member is an .npy array)")
        if name not in archive.files:
            held = ", ".join(archive.files) or "nothing"
            raise ValueError(f"{path}: has no array {name!r} (it holds {held}); a building's "
                             ".npz holds M, K and optionally C")
        info = zipped.getinfo(name + ".npy")
        with zipped.open(info) as member:
            _npy_header(member, path, f"array {name!r}", info.file_size)
        try:
            arr = archive[name]
        except (OSError, ValueError, EOFError, zipfile.BadZipFile):
            raise ValueError(f"{path}: array {name!r} cannot be read") from None
        return _numeric(arr, path, f"array {name!r}")


_MTX_SMALLEST_ENTRY = 6
"""Fewest bytes an entry line of a coordinate Matrix Market file takes (``1 1 1`` and its
line end); an array entry takes at least 2."""


def _read_mtx(path: Path) -> NDArray[np.float64]:
    import scipy.io  # only when a Matrix Market file is read

    try:
        rows, cols, entries, layout, fld, _ = scipy.io.mminfo(path)
    except (OSError, ValueError, IndexError, TypeError):  # scipy's message quotes the file
        raise ValueError(f"{path}: not a Matrix Market file (no valid '%%MatrixMarket' "
                         "banner and size line)") from None
    fld = str(fld).lower()
    if fld not in ("real", "integer", "double"):
        raise ValueError(f"{path}: Matrix Market field is {fld!r}; expected real or integer")
    _check_declared(path, "its Matrix Market size line", (int(rows), int(cols)))
    size = path.stat().st_size
    coordinate = str(layout).lower() == "coordinate"
    declared = int(entries) if coordinate else int(rows) * int(cols)
    if coordinate and declared > int(rows) * int(cols):
        raise ValueError(f"{path}: its Matrix Market size line declares {declared} entries, "
                         f"more than a {rows}×{cols} matrix has")
    smallest = _MTX_SMALLEST_ENTRY if coordinate else 2
    if declared * smallest > size:
        raise ValueError(f"{path}: its Matrix Market size line declares {declared} entries but "
                         f"the file is only {size} bytes long")
    try:
        arr = scipy.io.mmread(path)
    except (OSError, ValueError, IndexError, TypeError):
        raise ValueError(f"{path}: cannot be read as Matrix Market (its entries do not match "
                         "its header)") from None
    if hasattr(arr, "toarray"):
        arr = arr.toarray()
    return _numeric(arr, path, "the matrix")


def read_matrix(path: StrPath, name: str = "M") -> NDArray[np.float64]:
    """Read one matrix from a file and check it with
    :func:`~pounding.structure.matrix_checks.check_matrix`.

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
        not numbers, ragged rows, a size declared in the header beyond
        :data:`~pounding.structure.floor_arrays.MAX_FLOORS` degrees of freedom (refused
        before anything is allocated), not 2-D, not square, not finite, not symmetric. No
        message shows the file's text.
    """
    p = Path(path)
    fmt = MATRIX_FORMATS.get(p.suffix.lower())
    if fmt is None:
        known = ", ".join(MATRIX_FORMATS)
        raise ValueError(f"{p}: unknown matrix file type {p.suffix!r}; read are {known}")
    if not p.is_file():
        raise ValueError(f"{p}: " + ("is a directory, not a matrix file" if p.is_dir() else
                                     "not a regular file (a device, pipe or socket)"
                                     if p.exists() else "no such file"))
    if fmt == "text":
        A = _read_text(p)
    elif fmt == "npy":
        A = _read_npy(p)
    elif fmt == "npz":
        A = _read_npz(p, name)
    else:
        A = _read_mtx(p)
    return check_matrix(A, name, str(p))


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
    return MatrixBuilding(M=Mx, K=Kx, labels=tuple(labels),
                          elevations=elevations, r=r,
                          C=Cx, damping=damping, name=name, sources=sources, floors=floors)

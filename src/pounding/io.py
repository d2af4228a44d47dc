"""Loss-free output: every file is written to a temporary name beside its target and moved
into place only when complete, so an interrupted run never leaves a half-written file; and
the checks and folder bookkeeping every output folder (of a run, of a sweep) shares.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path


@contextlib.contextmanager
def atomic_path(target: str | os.PathLike[str]) -> Iterator[Path]:
    """Yield a temporary path in the target's folder; on success move it onto ``target``.

    The temporary name keeps the target's suffix, so writers that choose a format from the
    suffix (matplotlib, xarray) behave as they would with the target. On an exception the
    temporary file is removed and ``target`` is left as it was.
    """
    target = Path(target)
    if target.exists() and target.is_dir():
        raise IsADirectoryError(f"output: {target} is a directory, not a file")
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.part-", suffix=target.suffix,
                               dir=target.parent)
    os.close(fd)
    tmp_path = Path(tmp)
    try:
        yield tmp_path
        os.chmod(tmp_path, 0o666 & ~_umask())  # mkstemp makes 0600; give the usual mode
        os.replace(tmp_path, target)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            tmp_path.unlink()
        raise


def read_toml(path: str | os.PathLike[str], kind: str) -> dict:
    """Read a TOML file, raising one-line ``ValueError``s naming the file: missing, a
    directory, not UTF-8, or not valid TOML. ``kind`` names what the file should be
    (``"model file"``)."""
    import tomllib

    p = Path(path)
    if not p.is_file():
        raise ValueError(f"{p}: is a directory, not a {kind}" if p.is_dir() else
                         f"{p}: no such {kind}")
    try:
        return tomllib.loads(p.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{p}: not valid TOML: {exc}") from None
    except UnicodeDecodeError as exc:
        raise ValueError(f"{p}: not a UTF-8 text file ({exc.reason})") from None


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def write_text(target: str | os.PathLike[str], text: str) -> Path:
    """Write ``text`` to ``target`` atomically (UTF-8) and return the target path."""
    with atomic_path(target) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return Path(target)


def check_writable(out_dir: str | os.PathLike[str], inside: bool = False) -> None:
    """Refuse, before anything is written, an output folder that cannot be made or written.

    The nearest existing folder above ``out_dir`` (with ``inside``, ``out_dir`` itself if
    it exists: for outputs written into the folder rather than moved into place) must be a
    folder this process can write in.

    Parameters
    ----------
    out_dir : path-like
        The output folder (``--out``).
    inside : bool
        The output is written inside ``out_dir`` (a sweep's), not beside it (a run's).

    Raises
    ------
    ValueError
        One line: a file stands where a folder must be, or the folder is read-only.
    """
    out_dir = Path(out_dir)
    p = out_dir.absolute() if inside else out_dir.absolute().parent
    while not p.exists() and not p.is_symlink():
        p = p.parent
    if not p.is_dir():
        raise ValueError(f"out: {out_dir} cannot be made: {p} is a file, not a folder; "
                         "choose another --out")
    if not os.access(p, os.W_OK | os.X_OK):
        raise ValueError(f"out: cannot write in {p} (a read-only file system, or no "
                         "permission); choose another --out")


FIGURE_SUFFIXES: tuple[str, ...] = (".png", ".svg", ".svgz", ".pdf", ".eps", ".ps", ".jpg",
                                    ".jpeg", ".tif", ".tiff", ".webp", ".pgf")
"""File suffixes a figure can be written to (matplotlib's formats)."""


def check_output_file(path: str | os.PathLike[str] | None, option: str,
                      figure: bool = False) -> None:
    """Refuse, before any work, an output file option that cannot be written: a folder
    where the file should be, a parent that is a file or read-only, or (``figure``) a
    suffix no figure format has. ``None`` (option not given) passes.

    Raises
    ------
    ValueError
        One line naming the option and the value.
    """
    if path is None:
        return
    target = Path(path)
    if figure and target.suffix.lower() not in FIGURE_SUFFIXES:
        raise ValueError(f"{option}: {target} has no figure suffix; use one of "
                         f"{', '.join(FIGURE_SUFFIXES[:4])}, ... (got {target.suffix or 'none'!r})")
    if target.is_dir():
        raise ValueError(f"{option}: {target} is a folder; give a file name")
    try:
        check_writable(target)
    except ValueError as exc:
        raise ValueError(f"{option}: {str(exc).removeprefix('out: ').replace('--out', option)}"
                         ) from None


def make_folders(folder: str | os.PathLike[str]) -> list[Path]:
    """Create ``folder`` and its missing ancestors; return those created, deepest last."""
    missing = []
    p = Path(folder).absolute()
    while not p.exists():
        missing.append(p)
        p = p.parent
    Path(folder).mkdir(parents=True, exist_ok=True)
    return missing[::-1]


def remove_empty_folders(created: list[Path]) -> None:
    """Remove the folders :func:`make_folders` created, deepest first, where still empty."""
    for p in reversed(created):
        with contextlib.suppress(OSError):
            p.rmdir()

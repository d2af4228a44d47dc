"""Loss-free output: every file is written to a temporary name beside its target and moved
into place only when complete, so an interrupted run never leaves a half-written file; and
the checks and folder bookkeeping every output folder (of a run, of a sweep) shares (what
pounding wrote in a folder, and may remove, is :mod:`pounding.io.manifest`).

A temporary name carries the pid of the process writing it
(``.<name>.part-<pid>-XXXXXXXX<suffix>``), so a later run can tell the leftovers of a killed
process from those of one still running. A write that fails (a full disk, a file-size
limit) raises :class:`WriteFailed`: one line naming the file and the cause, the temporary
removed, the target as it was.
"""

from __future__ import annotations

import contextlib
import errno
import os
import re
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path


class WriteFailed(OSError):
    """A file could not be written: ``cannot write <target>: <cause>`` (e.g. ``no space
    left on device``, ``file too large``). Nothing was left in its place.

    Attributes
    ----------
    target : Path
        The file that was being written.
    reason : str
        The cause, in words.
    """

    def __init__(self, target: str | os.PathLike[str], reason: str,
                 code: int | None = None) -> None:
        self.target = Path(target)
        self.reason = reason
        super().__init__(code or errno.EIO, f"cannot write {self.target}: {reason}")

    def __str__(self) -> str:
        return str(self.strerror)

    def moved(self, old: Path, new: Path) -> WriteFailed:
        """The same failure told of ``new/…`` for a file written under ``old/…`` (a
        temporary folder renamed into place when complete)."""
        try:
            target = new / self.target.relative_to(old)
        except ValueError:
            target = self.target
        return WriteFailed(target, self.reason, self.errno)


def failure_reason(exc: BaseException) -> tuple[str, int | None]:
    """The cause of a failed write in words (``no space left on device``) and its errno:
    from the exception's errno, or an ``[errno N]`` in its message (pyarrow's)."""
    code = getattr(exc, "errno", None)
    if not code:
        m = re.search(r"\[errno (\d+)\]", str(exc), flags=re.IGNORECASE)
        code = int(m.group(1)) if m else None
    if code:
        text = os.strerror(code)
    else:
        text = (str(exc).strip().splitlines() or [type(exc).__name__])[0]
    return (text[:1].lower() + text[1:]), code


@contextlib.contextmanager
def atomic_path(target: str | os.PathLike[str],
                before_replace: Callable[[Path], None] | None = None) -> Iterator[Path]:
    """Yield a temporary path in the target's folder; on success move it onto ``target``.

    The temporary name keeps the target's suffix, so writers that choose a format from the
    suffix (matplotlib, xarray) behave as they would with the target. On an exception the
    temporary file is removed and ``target`` is left as it was; a file-system error (a
    full disk, a size limit) becomes :class:`WriteFailed`.

    Parameters
    ----------
    target : path-like
        The file to write.
    before_replace : callable, optional
        Called with the complete temporary file just before it is moved into place (to
        record it in a manifest, :mod:`pounding.io.manifest`).
    """
    target = Path(target)
    if target.exists() and target.is_dir():
        raise IsADirectoryError(f"output: {target} is a directory, not a file")
    target.parent.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(target)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.part-{os.getpid()}-",
                               suffix=target.suffix, dir=target.parent)
    os.close(fd)
    tmp_path = Path(tmp)
    try:
        yield tmp_path
        os.chmod(tmp_path, 0o666 & ~umask())  # mkstemp makes 0600; give the usual mode
        if before_replace is not None:
            before_replace(tmp_path)
        os.replace(tmp_path, target)
    except BaseException as exc:
        with contextlib.suppress(FileNotFoundError):
            tmp_path.unlink()
        if isinstance(exc, OSError) and not isinstance(exc, WriteFailed):
            reason, code = failure_reason(exc)
            raise WriteFailed(target, reason, code) from None
        raise


def remove_stale_temporaries(target: str | os.PathLike[str]) -> list[Path]:
    """Remove the temporaries :func:`atomic_path` made for ``target`` in processes no longer
    running (killed outright while writing it: ``.<name>.part-<pid>-XXXXXXXX<suffix>``
    beside it, the pid dead); return them. A file of another name, or of a live process,
    is never touched."""
    target = Path(target)
    pattern = re.compile(rf"^\.{re.escape(target.name)}\.part-(?P<pid>\d+)-[a-z0-9_]{{8}}"
                         rf"{re.escape(target.suffix)}$")
    removed = []
    with contextlib.suppress(OSError):
        for p in target.parent.iterdir():
            m = pattern.match(p.name)
            if (m and int(m["pid"]) != os.getpid() and not p.is_symlink() and p.is_file()
                    and not pid_alive(int(m["pid"]))):
                with contextlib.suppress(OSError):
                    p.unlink()
                    removed.append(p)
    return removed


def write_bytes(target: str | os.PathLike[str], data: bytes | memoryview) -> Path:
    """Write ``data`` to ``target`` atomically with plain file I/O and return the target
    (a failure is :class:`WriteFailed`; used for files serialised in memory, so that a
    library never meets a full disk)."""
    with atomic_path(target) as tmp:
        with open(tmp, "wb") as fh:
            fh.write(data)
    return Path(target)


def pid_alive(pid: int) -> bool:
    """Whether a process ``pid`` exists (one of another user counts as alive)."""
    if pid <= 0:
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:
        return True
    return True


_TOML_SYNTAX = {"=", "[", "]", "{", "}", ",", ".", "#", '"', "'", "\\n"}


def toml_error_text(exc: Exception) -> str:
    """tomllib's message without anything it quotes from the file: a key it cannot declare
    twice (``('a',)``) or a character it did not expect becomes ``…``; its own syntax
    characters (``'='``) and the position ``(at line 3, column 5)`` are kept."""
    import re

    def quoted(m: re.Match[str]) -> str:
        return m.group(0) if m.group(1) in _TOML_SYNTAX else "…"

    text = re.sub(r"'((?:[^'\\]|\\.)*)'", quoted, str(exc))
    text = re.sub(r"\((?!at line \d+, column \d+\)|at end of document\))[^()]*\)", "…", text)
    return text


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
        raise ValueError(f"{p}: not valid TOML: {toml_error_text(exc)}") from None
    except UnicodeDecodeError as exc:
        raise ValueError(f"{p}: not a UTF-8 text file ({exc.reason})") from None


def umask() -> int:
    """The process umask, read without setting it (``os.umask`` can only be read by
    setting it, for a moment, for every thread of the process): from ``/proc`` where
    there is one (Linux), else from the mode a new file is given."""
    with contextlib.suppress(OSError, ValueError):
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("Umask:"):
                return int(line.split()[1], 8)
    return _umask_of_a_new_file()


def _umask_of_a_new_file() -> int:
    """The umask, from the permissions of a file made with mode 0777 in a private
    temporary folder (then removed)."""
    with tempfile.TemporaryDirectory(prefix=".pounding-umask-") as folder:
        probe = os.path.join(folder, "probe")
        os.close(os.open(probe, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o777))
        return 0o777 & ~os.stat(probe).st_mode


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


def check_label(value: object, where: str, key: str = "name") -> str:
    """A study's ``name`` (it names the default output folder ``<name>-results``) is a
    label, not a path: refuse a path separator, NUL, a leading dot (``..``, a hidden
    folder) or an empty name. Returns the name as text.

    Raises
    ------
    ValueError
        One line naming the key and the value.
    """
    text = str(value)
    if (not text.strip() or any(c in text for c in ("/", "\\", "\0"))
            or text.startswith(".")):
        raise ValueError(f"{where}: {key}: a label, not a path: no '/', '\\', NUL or leading "
                         f"'.' (got {value!r})")
    return text


def study_out(here: str | os.PathLike[str], out: str, where: str) -> tuple[Path, str | None]:
    """The folder ``out`` of a study file names, relative to the file's folder ``here``,
    and why it is refused (None if not): a folder outside ``here`` (``"../x"``, an
    absolute path elsewhere) or ``here`` itself. The check is on the names, symlinks are
    not followed; an output folder given on the command line (``--out``) is not checked.
    """
    base = Path(os.path.abspath(here))
    if not out or "\0" in out:
        return base, f"{where}: out: a folder name (got {out!r})"
    target = Path(os.path.normpath(base / Path(out).expanduser()))
    if target == base or not target.is_relative_to(base):
        return target, (f"{where}: out: {out!r} is not a folder inside the study file's folder "
                        f"{base}; give the output folder on the command line (--out) to "
                        "write there")
    return target, None

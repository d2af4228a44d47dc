"""The life of an output folder on disk: temporary folders marked as pounding's, the
removal of what killed processes left, and a folder built whole and then put in place.

What pounding wrote in a folder, and may therefore remove there, is its manifest
(:mod:`pounding.io.manifest`); this module never removes anything else. A temporary folder is
made private (``mkdtemp``) and marked at once (:data:`pounding.io.manifest.TEMPORARY_MARKER`:
the pid that made it and the names it may hold), so a later process can tell it from a
folder of the user's that only looks like one.
"""

from __future__ import annotations

import contextlib
import json
import os
import tempfile
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path

from pounding.io.files import WriteFailed, umask
from pounding.io.manifest import (
    MANIFEST_FILE,
    TEMP_DIR,
    TEMP_FILE,
    TEMPORARY_MARKER,
    Manifest,
    files_under,
    foreign_entry,
    is_stale,
    is_stale_marker,
    read_marker,
    remove_outputs,
)

__all__ = ["DEFAULT_OUT_SUFFIX", "default_out_dir", "make_temporary_folder",
           "new_output_folder", "normal_permissions", "publish_folder", "remove_stale",
           "remove_temporary_folder"]

DEFAULT_OUT_SUFFIX = "-results"
"""What the default output folder adds to the input file's stem (:func:`default_out_dir`)."""


def default_out_dir(input: str | os.PathLike[str]) -> Path:
    """The output folder of a command given no ``--out``: ``<input file stem>-results`` in
    the current folder — ``pounding run model.toml`` writes ``model-results``, ``pounding
    sweep gaps.toml`` ``gaps-results`` — for every command that reads an input file (run,
    sweep, fragility, mitigate). A sweep, fragility or mitigation file may name its own
    folder with ``out`` (relative to the file, inside its folder:
    :func:`pounding.io.files.study_out`); that is asked for, not a default.

    The folder is never beside the input file: a bundled example (in the installed
    package) or a shared folder of models is only read.
    """
    return Path(f"{Path(input).stem}{DEFAULT_OUT_SUFFIX}")


def make_temporary_folder(parent: Path, name: str, kind: str, holds: Iterable[str]
                          ) -> Path:
    """Make a private folder ``parent/.<name>.<kind>-<pid>-XXXXXXXX`` marked as pounding's
    (:data:`pounding.io.manifest.TEMPORARY_MARKER`): its pid, and ``holds``, the names
    (relative paths; ending ``/**``: a whole tree, e.g. a Zarr store) of what may be put
    in it."""
    tmp = Path(tempfile.mkdtemp(prefix=f".{name}.{kind}-{os.getpid()}-", dir=parent))
    (tmp / TEMPORARY_MARKER).write_text(json.dumps(
        {"marker": "pounding temporary folder", "pid": os.getpid(), "holds": list(holds)}),
        encoding="utf-8")
    return tmp


def remove_temporary_folder(tmp: Path) -> None:
    """Remove a temporary folder of :func:`make_temporary_folder` (of this process, or of
    one no longer running): the names its marker lists and its manifest's files, pounding's
    temporaries, the marker, then the folder if empty. An entry it does not list stays, and
    so does the folder then."""
    marker = read_marker(tmp) or {"holds": []}
    for pattern in marker["holds"]:
        if not isinstance(pattern, str) or pattern.startswith(("/", "..")) or "/../" in pattern:
            continue
        if pattern.endswith("/**"):
            _remove_tree(tmp / pattern[:-3])
        else:
            with contextlib.suppress(IsADirectoryError, PermissionError):
                (tmp / pattern).unlink(missing_ok=True)
    if Manifest(tmp).exists():
        remove_outputs(tmp, keep_folder=True)
    for p in tmp.iterdir():
        if TEMP_FILE.match(p.name) and p.is_file() and not p.is_symlink():
            p.unlink(missing_ok=True)
    (tmp / TEMPORARY_MARKER).unlink(missing_ok=True)
    with contextlib.suppress(OSError):
        tmp.rmdir()


def _remove_tree(root: Path) -> None:
    """Remove the tree ``root`` listed in a marker as written by a library (a Zarr store)
    inside pounding's private temporary folder, files first, folders once empty; symlinks
    are removed as links, never followed."""
    if root.is_symlink() or not root.is_dir():
        return
    for dirpath, dirnames, filenames in os.walk(root, topdown=False):
        for f in filenames:
            with contextlib.suppress(OSError):
                (Path(dirpath) / f).unlink()
        for d in dirnames:
            p = Path(dirpath) / d
            with contextlib.suppress(OSError):
                p.unlink() if p.is_symlink() else p.rmdir()
    with contextlib.suppress(OSError):
        root.rmdir()


def remove_stale(folder: Path, restore: Path | None = None) -> None:
    """Remove from ``folder`` the temporaries of pounding processes no longer running:
    files ``.<name>.part-<pid>-XXXXXXXX[.suffix]`` and marked temporary folders
    (:func:`make_temporary_folder`). A folder ``.<name>.old-<pid>-…`` holds an earlier
    output a killed run was replacing: if ``restore`` (the output folder) is missing it is
    put back there, else removed by its manifest."""
    if not folder.is_dir() or folder.is_symlink():
        return
    if is_stale_marker(folder / TEMPORARY_MARKER):
        (folder / TEMPORARY_MARKER).unlink()
    for p in sorted(folder.iterdir()):
        if not is_stale(p):
            continue
        if p.is_file():
            p.unlink(missing_ok=True)
            continue
        m = TEMP_DIR.match(p.name)
        assert m is not None
        if m["kind"] != "old":
            remove_temporary_folder(p)
            continue
        for held in (read_marker(p) or {"holds": []})["holds"]:
            old = p / str(held)
            if "/" in str(held) or not old.is_dir() or old.is_symlink():
                continue
            if restore is not None and held == restore.name and not restore.exists():
                with contextlib.suppress(OSError):
                    os.replace(old, restore)
            elif Manifest(old).exists() and foreign_entry(old) is None:
                remove_outputs(old)
        (p / TEMPORARY_MARKER).unlink(missing_ok=True)
        with contextlib.suppress(OSError):
            p.rmdir()


def publish_folder(tmp: Path, out: Path) -> None:
    """Move the complete output folder ``tmp`` (a temporary folder of this process, its
    manifest written) to ``out``. An earlier output there (checked replaceable by the
    caller, :func:`pounding.io.manifest.check_replaceable`) is moved aside first, into a marked folder
    ``.<name>.old-<pid>-…``, and removed file by file from its manifest once the new one
    is in place; if this process is killed in between, :func:`remove_stale` puts it back
    or finishes the removal."""
    old = None
    if out.exists():
        old = make_temporary_folder(out.absolute().parent, out.name, "old", holds=[out.name])
        os.replace(out, old / out.name)
    try:
        os.replace(tmp, out)
    except BaseException:
        if old is not None:
            os.replace(old / out.name, out)
            (old / TEMPORARY_MARKER).unlink(missing_ok=True)
            old.rmdir()
        raise
    (out / TEMPORARY_MARKER).unlink()  # killed before this: remove_stale removes it
    if old is not None:
        with contextlib.suppress(OSError):
            remove_outputs(old / out.name)
            (old / TEMPORARY_MARKER).unlink(missing_ok=True)
            old.rmdir()


@contextlib.contextmanager
def new_output_folder(out: Path, kind: str, holds: Iterable[str],
                      check: Callable[[], None]) -> Iterator[Path]:
    """Build an output folder whole, then put it in place: yield a marked temporary folder
    beside ``out`` (``.<name>.tmp-<pid>-…``, :func:`make_temporary_folder` with ``holds``)
    to write into; on success record every file in it in a new manifest of ``kind``, give
    them the usual permissions, call ``check`` (the target may still be replaced: it
    raises if not) and move the folder to ``out`` (:func:`publish_folder`). On any failure
    the temporary folder is removed (with the parent folders made for it) and ``out`` is
    as it was; a :class:`pounding.io.files.WriteFailed` then names the file under ``out``."""
    import shutil

    from pounding.io.files import make_folders, remove_empty_folders

    parent = out.absolute().parent
    created = make_folders(parent)
    tmp = make_temporary_folder(parent, out.name, "tmp", [*holds, MANIFEST_FILE])
    try:
        yield tmp
        man = Manifest(tmp)
        man.start(kind)
        man.append(man.entry_of(p) for p in files_under(tmp)
                   if p.name not in (TEMPORARY_MARKER, MANIFEST_FILE) or p.parent != tmp)
        normal_permissions(tmp)
        remove_stale(parent, restore=out.absolute())
        check()
        publish_folder(tmp, out)
    except BaseException as exc:
        if tmp.is_dir():
            shutil.rmtree(tmp, ignore_errors=True)  # made whole by this process
        remove_empty_folders(created)
        if isinstance(exc, WriteFailed):
            raise exc.moved(tmp, out) from None
        raise


def normal_permissions(folder: Path) -> None:
    """Temporary files and folders are private (0600/0700): give the finished ones the
    permissions an ordinary ``mkdir``/``open`` would."""
    mask = umask()
    folder.chmod(0o777 & ~mask)
    for p in files_under(folder):
        p.chmod(0o666 & ~mask)
    for dirpath, dirnames, _ in os.walk(folder):
        for d in dirnames:
            (Path(dirpath) / d).chmod(0o777 & ~mask)

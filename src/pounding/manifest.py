"""What pounding wrote into an output folder, and the only things it may remove there.

Every output folder pounding writes (a run's, a sweep's, a mitigation study's) carries a
manifest, ``.pounding-manifest.jsonl``: a header line, then one JSON line per file written,
with its path relative to the folder, its size [bytes] and its SHA-256. A file is recorded
when complete and before it is moved into place, so the manifest never misses a file that
is in the folder (it may list one that is not: a file never moved, or removed since).

The rules built on it (``docs/running.md``, "What pounding promises"):

* a folder is **replaced** (``--overwrite``) only if every entry in it is a file the
  manifest lists with the size and hash it had when written (:func:`check_replaceable`);
  otherwise nothing is touched and the refusal names the first other entry. A folder
  with no manifest (written by someone else, or by pounding before manifests) is refused
  unless empty;
* old outputs are **removed file by file** from the manifest, and a folder only with
  ``rmdir`` once empty (:func:`remove_outputs`) — never a whole tree;
* a process killed outright (SIGKILL) leaves temporaries whose names carry its pid
  (``.<name>.part-<pid>-XXXXXXXX``, ``.<name>.tmp-<pid>-XXXXXXXX``); a later run removes
  them once that process is gone, and only those (:func:`remove_stale`): a temporary file by
  its name, a temporary folder only through the marker it was given when made (which
  lists what may be in it).

A one-line JSON Lines file rather than one JSON document: a sweep adds a line per finished
batch without rewriting what it recorded before, and a line cut short by a kill is simply
not a record (its file then counts as not pounding's: refused, never lost).
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import re
import tempfile
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

from pounding.io import WriteFailed, atomic_path, failure_reason, pid_alive, umask

__all__ = ["MANIFEST_FILE", "TEMPORARY_MARKER", "Entry", "Manifest", "check_replaceable",
           "foreign_entry", "make_temporary_folder", "new_output_folder", "normal_permissions",
           "publish_folder",
           "remove_outputs", "remove_stale", "remove_temporary_folder"]

MANIFEST_FILE = ".pounding-manifest.jsonl"
"""The manifest of an output folder (module docstring)."""

TEMPORARY_MARKER = ".pounding-temporary.json"
"""The marker of a temporary folder: the pid that made it and what may be in it."""

_HEADER = "pounding output folder"
_TEMP_FILE = re.compile(r"^\.(?P<name>.+)\.part-(?P<pid>\d+)-[a-z0-9_]{8}(\.[^.]+)?$")
_TEMP_DIR = re.compile(r"^\.(?P<name>.+)\.(?P<kind>tmp|old|stage|part)-(?P<pid>\d+)-"
                       r"[a-z0-9_]{8}$")
_CHUNK = 1 << 20


@dataclass(frozen=True)
class Entry:
    """A file as pounding wrote it: path relative to the folder (``/`` separated), size
    [bytes] and SHA-256 (hex)."""

    path: str
    size: int
    sha256: str

    def line(self) -> str:
        return json.dumps({"path": self.path, "size": self.size, "sha256": self.sha256}) + "\n"


def _file_hash(path: Path) -> tuple[int, str]:
    h = hashlib.sha256()
    size = 0
    with open(path, "rb") as fh:
        while chunk := fh.read(_CHUNK):
            h.update(chunk)
            size += len(chunk)
    return size, h.hexdigest()


def _rel(folder: Path, target: Path) -> str:
    """``target`` relative to ``folder`` (both made absolute, not resolved)."""
    rel = os.path.relpath(os.path.abspath(target), os.path.abspath(folder))
    if rel == os.curdir or rel.startswith(os.pardir):
        raise ValueError(f"{target} is not inside {folder}")
    return Path(rel).as_posix()


class Manifest:
    """The manifest of the output folder ``folder`` (module docstring).

    Parameters
    ----------
    folder : path-like
        The output folder (its manifest is ``folder/.pounding-manifest.jsonl``).
    """

    def __init__(self, folder: str | os.PathLike[str]) -> None:
        self.folder = Path(folder)
        self.path = self.folder / MANIFEST_FILE

    def exists(self) -> bool:
        """Whether the folder has a manifest."""
        return self.path.is_file()

    def kind(self) -> str | None:
        """What wrote the folder (``"run"``, ``"sweep"``, ``"mitigation"``), None if
        unknown."""
        header = self._lines()[0] if self.exists() else None
        return header.get("kind") if isinstance(header, dict) else None

    def start(self, kind: str) -> None:
        """Write a new manifest listing nothing yet (replacing any)."""
        self.folder.mkdir(parents=True, exist_ok=True)
        head = json.dumps({"manifest": _HEADER, "format": 1, "kind": kind})
        with atomic_path(self.path) as tmp:
            tmp.write_text(head + "\n", encoding="utf-8")

    def _lines(self) -> list[dict | None]:
        """Every line parsed (None: not a record, e.g. cut short by a kill)."""
        out: list[dict | None] = []
        text = self.path.read_text(encoding="utf-8", errors="replace")
        for line in text.splitlines(keepends=True):
            try:
                rec = json.loads(line) if line.endswith("\n") else None
            except ValueError:
                rec = None
            out.append(rec if isinstance(rec, dict) else None)
        return out or [None]

    def entries(self) -> dict[str, Entry]:
        """The files recorded, by relative path (a later record of a path wins)."""
        if not self.exists():
            return {}
        found: dict[str, Entry] = {}
        lines = self._lines()
        if isinstance(lines[0], dict) and lines[0].get("manifest") == _HEADER:
            lines = lines[1:]
        for rec in lines:
            with contextlib.suppress(KeyError, TypeError, ValueError):
                assert rec is not None
                e = Entry(str(rec["path"]), int(rec["size"]), str(rec["sha256"]))
                if e.path and not e.path.startswith(("/", "../")) and "/../" not in e.path:
                    found[e.path] = e
        return found

    def append(self, entries: Iterable[Entry]) -> None:
        """Record ``entries`` (one line each, synced to disk before returning)."""
        text = "".join(e.line() for e in entries)
        if not text:
            return
        try:
            with open(self.path, "a+b") as fh:
                if fh.tell() > 0:
                    fh.seek(-1, os.SEEK_END)
                    if fh.read(1) != b"\n":  # a line cut short: start on a new one
                        text = "\n" + text
                fh.write(text.encode("utf-8"))
                fh.flush()
                os.fsync(fh.fileno())
        except OSError as exc:
            reason, code = failure_reason(exc)
            raise WriteFailed(self.path, reason, code) from None

    def entry_of(self, target: Path, written: Path | None = None,
                 data: bytes | memoryview | None = None) -> Entry:
        """The record of ``target`` (a path in the folder) from its content: ``data``, or
        the file ``written`` (default ``target``)."""
        if data is not None:
            size, digest = len(data), hashlib.sha256(data).hexdigest()
        else:
            size, digest = _file_hash(written if written is not None else target)
        return Entry(_rel(self.folder, target), size, digest)

    def is_ours(self, target: Path, entries: dict[str, Entry] | None = None) -> bool:
        """Whether the file ``target`` is one pounding wrote here, unchanged since."""
        e = (self.entries() if entries is None else entries).get(_rel(self.folder, target))
        if e is None or target.is_symlink() or not target.is_file():
            return False
        real = Path(os.path.realpath(target))
        if real.parent != Path(os.path.realpath(self.folder)) / Path(e.path).parent:
            return False  # reached through a symlinked folder: not where pounding wrote it
        if target.stat().st_size != e.size:
            return False
        return _file_hash(target)[1] == e.sha256

    def check_free(self, target: Path) -> None:
        """Refuse to write ``target`` over a file pounding did not write (or that changed
        since it did).

        Raises
        ------
        ValueError
            One line naming the file.
        """
        if not target.exists() and not target.is_symlink():
            return
        if target.is_dir() and not target.is_symlink():
            raise ValueError(f"out: not writing {target}: a folder stands there")
        if not self.is_ours(target):
            raise ValueError(f"out: not replacing {target}: pounding did not write it (or it "
                             "changed since); move it away or choose another --out")

    @contextlib.contextmanager
    def write(self, target: Path) -> Iterator[Path]:
        """Write ``target`` atomically (:func:`pounding.io.atomic_path`) and record it:
        the temporary file is recorded when complete, then moved into place. A file
        already there is replaced only if pounding wrote it (:meth:`check_free`)."""
        self.check_free(target)
        with atomic_path(target, before_replace=lambda tmp: self.append(
                [self.entry_of(target, tmp)])) as tmp:
            yield tmp

    def write_bytes(self, target: Path, data: bytes | memoryview) -> Path:
        """Write ``data`` to ``target`` (as :meth:`write`), hashing it from memory."""
        self.check_free(target)
        entry = self.entry_of(target, data=data)
        with atomic_path(target, before_replace=lambda tmp: self.append([entry])) as tmp:
            with open(tmp, "wb") as fh:
                fh.write(data)
        return target

    def write_text(self, target: Path, text: str) -> Path:
        """Write ``text`` (UTF-8) to ``target`` (as :meth:`write_bytes`)."""
        return self.write_bytes(target, text.encode("utf-8"))

    def record_tree(self, root: Path) -> None:
        """Record every file under ``root`` (a folder in the manifest's folder)."""
        self.append(self.entry_of(p) for p in _files_under(root))

    def discard(self, target: Path) -> None:
        """Remove ``target`` if pounding wrote it and it is unchanged; else leave it."""
        if self.is_ours(target):
            target.unlink()


def _files_under(root: Path) -> list[Path]:
    """Every file under ``root`` (symlinks not followed), sorted."""
    out = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames.sort()
        out += [Path(dirpath) / f for f in sorted(filenames)]
    return out


def foreign_entry(folder: Path) -> str | None:
    """The first entry of ``folder`` that is not a file its manifest lists unchanged, as
    ``"<relative path> (<why>)"``; None if there is none.

    Temporaries of pounding processes no longer running do not count (:func:`remove_stale`
    removes them); one of a running process is named as such.
    """
    man = Manifest(folder)
    entries = man.entries()
    dirs_needed = {d for p in entries for d in _ancestors(Path(p).parent.as_posix())}
    for dirpath, dirnames, filenames in os.walk(folder):
        dirnames.sort()
        here = Path(dirpath)
        for name in sorted(filenames) + [d for d in dirnames if (here / d).is_symlink()]:
            p = here / name
            rel = _rel(folder, p)
            if rel == MANIFEST_FILE or _is_stale(p) or (
                    rel == TEMPORARY_MARKER and _is_stale_marker(p)):
                continue
            m = _TEMP_FILE.match(name)
            if m and pid_alive(int(m["pid"])):
                return f"{rel} (a temporary file of pounding process {m['pid']}, still running)"
            if rel not in entries:
                return f"{rel} (not a file pounding wrote)"
            if not man.is_ours(p, entries):
                return f"{rel} (changed since pounding wrote it)"
        for d in list(dirnames):
            p = here / d
            rel = _rel(folder, p)
            if p.is_symlink() or _is_stale(p):
                dirnames.remove(d)
            elif rel not in dirs_needed:
                m = _TEMP_DIR.match(d)
                if m and pid_alive(int(m["pid"])) and _marker(p) is not None:
                    return (f"{rel}/ (a temporary folder of pounding process {m['pid']}, "
                            "still running)")
                return f"{rel}/ (a folder pounding did not make)"
    return None


def _is_stale_marker(p: Path) -> bool:
    """Whether ``p`` is the marker of a temporary folder moved into place as an output
    folder by a process killed before it removed the marker (beside a manifest)."""
    if p.is_symlink() or not p.is_file() or not (p.parent / MANIFEST_FILE).is_file():
        return False
    marker = _marker(p.parent)
    return (marker is not None and isinstance(marker.get("pid"), int)
            and not pid_alive(marker["pid"]))


def _is_stale(p: Path) -> bool:
    """Whether ``p`` is a temporary of a pounding process no longer running: a file named
    as :func:`pounding.io.atomic_path` names them, or a folder carrying the marker of
    :func:`make_temporary_folder` with the pid of its name."""
    if p.is_symlink():
        return False
    m = _TEMP_FILE.match(p.name)
    if m and p.is_file():
        return not pid_alive(int(m["pid"]))
    m = _TEMP_DIR.match(p.name)
    if m and p.is_dir():
        marker = _marker(p)
        return (marker is not None and marker.get("pid") == int(m["pid"])
                and not pid_alive(int(m["pid"])))
    return False


def _ancestors(rel_dir: str) -> Iterator[str]:
    p = Path(rel_dir)
    while p.as_posix() not in (".", ""):
        yield p.as_posix()
        p = p.parent


def check_replaceable(folder: Path, kind: str, option: str = "--out") -> None:
    """Refuse to replace ``folder`` unless it is empty or holds only files its manifest
    lists, unchanged, and that manifest is of a ``kind`` output.

    Raises
    ------
    ValueError
        One line naming the folder and the first entry that is not pounding's.
    """
    if not any(folder.iterdir()):
        return
    man = Manifest(folder)
    if not man.exists():
        raise ValueError(f"out: not replacing it: {folder} has no manifest of pounding's files "
                         f"({MANIFEST_FILE}); remove it yourself or choose another {option}")
    found = man.kind()
    if found != kind:
        raise ValueError(f"out: not replacing {folder}: it holds the output of "
                         f"{_KIND_TEXT.get(str(found), 'something else')}, not of "
                         f"{_KIND_TEXT[kind]}; choose another {option}")
    foreign = foreign_entry(folder)
    if foreign is not None:
        raise ValueError(f"out: not replacing {folder}: it holds {foreign}; move it away or "
                         f"choose another {option}")


_KIND_TEXT = {"run": "a run", "sweep": "a sweep", "mitigation": "a mitigation study"}


def remove_outputs(folder: Path, keep_folder: bool = False) -> None:
    """Remove what pounding wrote in ``folder``: every file its manifest lists that is
    still as written, then the folders that held them once empty, the manifest, and
    ``folder`` itself if empty (unless ``keep_folder``). Nothing else is touched."""
    man = Manifest(folder)
    entries = man.entries()
    dirs: set[Path] = set()
    for rel in entries:
        p = folder / rel
        if man.is_ours(p, entries):
            p.unlink()
        q = p.parent
        while q != folder and folder in q.parents:
            dirs.add(q)
            q = q.parent
    for d in sorted(dirs, key=lambda d: len(d.parts), reverse=True):
        with contextlib.suppress(OSError):
            d.rmdir()
    man.path.unlink(missing_ok=True)
    if not keep_folder:
        with contextlib.suppress(OSError):
            folder.rmdir()


def make_temporary_folder(parent: Path, name: str, kind: str, holds: Iterable[str]) -> Path:
    """Make a private folder ``parent/.<name>.<kind>-<pid>-XXXXXXXX`` marked as pounding's
    (:data:`TEMPORARY_MARKER`): its pid, and ``holds``, the names (relative paths; ending
    ``/**``: a whole tree, e.g. a Zarr store) of what may be put in it."""
    tmp = Path(tempfile.mkdtemp(prefix=f".{name}.{kind}-{os.getpid()}-", dir=parent))
    (tmp / TEMPORARY_MARKER).write_text(json.dumps(
        {"marker": "pounding temporary folder", "pid": os.getpid(), "holds": list(holds)}),
        encoding="utf-8")
    return tmp


def _marker(folder: Path) -> dict | None:
    with contextlib.suppress(OSError, ValueError):
        m = json.loads((folder / TEMPORARY_MARKER).read_text(encoding="utf-8"))
        if isinstance(m, dict) and isinstance(m.get("holds"), list):
            return m
    return None


def remove_temporary_folder(tmp: Path) -> None:
    """Remove a temporary folder of :func:`make_temporary_folder` (of this process, or of
    one no longer running): the names its marker lists and its manifest's files, pounding's
    temporaries, the marker, then the folder if empty. An entry it does not list stays, and
    so does the folder then."""
    marker = _marker(tmp) or {"holds": []}
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
        if _TEMP_FILE.match(p.name) and p.is_file() and not p.is_symlink():
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
    if _is_stale_marker(folder / TEMPORARY_MARKER):
        (folder / TEMPORARY_MARKER).unlink()
    for p in sorted(folder.iterdir()):
        if not _is_stale(p):
            continue
        if p.is_file():
            p.unlink(missing_ok=True)
            continue
        m = _TEMP_DIR.match(p.name)
        assert m is not None
        if m["kind"] != "old":
            remove_temporary_folder(p)
            continue
        for held in (_marker(p) or {"holds": []})["holds"]:
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
    caller, :func:`check_replaceable`) is moved aside first, into a marked folder
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
    as it was; a :class:`pounding.io.WriteFailed` then names the file under ``out``."""
    import shutil

    from pounding.io import make_folders, remove_empty_folders

    parent = out.absolute().parent
    created = make_folders(parent)
    tmp = make_temporary_folder(parent, out.name, "tmp", [*holds, MANIFEST_FILE])
    try:
        yield tmp
        man = Manifest(tmp)
        man.start(kind)
        man.append(man.entry_of(p) for p in _files_under(tmp)
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
    for p in _files_under(folder):
        p.chmod(0o666 & ~mask)
    for dirpath, dirnames, _ in os.walk(folder):
        for d in dirnames:
            (Path(dirpath) / d).chmod(0o777 & ~mask)

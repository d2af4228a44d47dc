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
  them once that process is gone, and only those
  (:func:`pounding.io.output_folder.remove_stale`): a temporary file by its name, a temporary
  folder only through the marker it was given when made (which lists what may be in it).
  This module tells them apart (:func:`is_stale`); :mod:`pounding.io.output_folder` makes and
  removes them, and puts a finished folder in place.

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
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

from pounding.io.files import WriteFailed, atomic_path, failure_reason, pid_alive

__all__ = ["MANIFEST_FILE", "TEMPORARY_MARKER", "Entry", "Manifest", "check_out_folder",
           "check_replaceable",
           "files_under", "foreign_entry", "is_stale", "is_stale_marker", "read_marker",
           "remove_outputs"]

MANIFEST_FILE = ".pounding-manifest.jsonl"
"""The manifest of an output folder (module docstring)."""

TEMPORARY_MARKER = ".pounding-temporary.json"
"""The marker of a temporary folder: the pid that made it and what may be in it."""

_HEADER = "pounding output folder"
TEMP_FILE = re.compile(r"^\.(?P<name>.+)\.part-(?P<pid>\d+)-[a-z0-9_]{8}(\.[^.]+)?$")
TEMP_DIR = re.compile(r"^\.(?P<name>.+)\.(?P<kind>tmp|old|stage|part)-(?P<pid>\d+)-"
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
        """Write ``target`` atomically (:func:`pounding.io.files.atomic_path`) and record it:
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
        self.append(self.entry_of(p) for p in files_under(root))

    def discard(self, target: Path) -> None:
        """Remove ``target`` if pounding wrote it and it is unchanged; else leave it."""
        if self.is_ours(target):
            target.unlink()


def files_under(root: Path) -> list[Path]:
    """Every file under ``root`` (symlinks not followed), sorted."""
    out = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames.sort()
        out += [Path(dirpath) / f for f in sorted(filenames)]
    return out


def foreign_entry(folder: Path) -> str | None:
    """The first entry of ``folder`` that is not a file its manifest lists unchanged, as
    ``"<relative path> (<why>)"``; None if there is none.

    Temporaries of pounding processes no longer running do not count
    (:func:`pounding.io.output_folder.remove_stale` removes them); one of a running process is
    named as such.
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
            if rel == MANIFEST_FILE or is_stale(p) or (
                    rel == TEMPORARY_MARKER and is_stale_marker(p)):
                continue
            m = TEMP_FILE.match(name)
            if m and pid_alive(int(m["pid"])):
                return f"{rel} (a temporary file of pounding process {m['pid']}, still running)"
            if rel not in entries:
                return f"{rel} (not a file pounding wrote)"
            if not man.is_ours(p, entries):
                return f"{rel} (changed since pounding wrote it)"
        for d in list(dirnames):
            p = here / d
            rel = _rel(folder, p)
            if p.is_symlink() or is_stale(p):
                dirnames.remove(d)
            elif rel not in dirs_needed:
                m = TEMP_DIR.match(d)
                if m and pid_alive(int(m["pid"])) and read_marker(p) is not None:
                    return (f"{rel}/ (a temporary folder of pounding process {m['pid']}, "
                            "still running)")
                return f"{rel}/ (a folder pounding did not make)"
    return None


def is_stale_marker(p: Path) -> bool:
    """Whether ``p`` is the marker of a temporary folder moved into place as an output
    folder by a process killed before it removed the marker (beside a manifest)."""
    if p.is_symlink() or not p.is_file() or not (p.parent / MANIFEST_FILE).is_file():
        return False
    marker = read_marker(p.parent)
    return (marker is not None and isinstance(marker.get("pid"), int)
            and not pid_alive(marker["pid"]))


def is_stale(p: Path) -> bool:
    """Whether ``p`` is a temporary of a pounding process no longer running: a file named
    as :func:`pounding.io.files.atomic_path` names them, or a folder carrying the marker of
    :func:`pounding.io.output_folder.make_temporary_folder` with the pid of its name."""
    if p.is_symlink():
        return False
    m = TEMP_FILE.match(p.name)
    if m and p.is_file():
        return not pid_alive(int(m["pid"]))
    m = TEMP_DIR.match(p.name)
    if m and p.is_dir():
        marker = read_marker(p)
        return (marker is not None and marker.get("pid") == int(m["pid"])
                and not pid_alive(int(m["pid"])))
    return False


def _ancestors(rel_dir: str) -> Iterator[str]:
    p = Path(rel_dir)
    while p.as_posix() not in (".", ""):
        yield p.as_posix()
        p = p.parent


def check_out_folder(folder: Path, overwrite: bool, kind: str) -> None:
    """Refuse ``--out`` ``folder`` when it is a file or a link, or exists without
    ``overwrite``, or holds more than an earlier ``kind`` output of pounding
    (:func:`check_replaceable`): one line naming the folder, nothing touched."""
    if folder.exists() or folder.is_symlink():
        if not folder.is_dir() or folder.is_symlink():
            raise ValueError(f"out: {folder} exists and is not a folder; choose another --out")
        if not overwrite:
            raise ValueError(f"out: {folder} already exists; give --overwrite to replace it "
                             "or choose another --out")
        check_replaceable(folder, kind)


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
                         f"{_KIND_TEXT.get(kind, kind)}; choose another {option}")
    foreign = foreign_entry(folder)
    if foreign is not None:
        raise ValueError(f"out: not replacing {folder}: it holds {foreign}; move it away or "
                         f"choose another {option}")


_KIND_TEXT = {"run": "a run", "sweep": "a sweep", "mitigation": "a mitigation study",
              "pushover": "a pushover", "code-check": "a code check",
              "synthesize": "a suite of stochastic records"}
"""What each kind of output folder is called in a message (every kind a command writes:
``tests/test_output_safety.py`` checks that none is missing)."""


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


def read_marker(folder: Path) -> dict | None:
    with contextlib.suppress(OSError, ValueError):
        m = json.loads((folder / TEMPORARY_MARKER).read_text(encoding="utf-8"))
        if isinstance(m, dict) and isinstance(m.get("holds"), list):
            return m
    return None

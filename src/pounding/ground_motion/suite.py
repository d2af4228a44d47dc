"""Record suites: :class:`RecordSuite`, an ordered, named collection of ground motions and
the files they were read from, on which record scaling and IDA studies run.

A suite comes from a folder (:meth:`RecordSuite.from_folder`: every readable record in it,
the others reported in :attr:`RecordSuite.skipped`), a list of files
(:meth:`RecordSuite.from_paths`: each must read), or the records shipped with pounding
(:func:`bundled_suite`); :func:`read_suite` takes any of the three. Files are read by
:func:`pounding.ground_motion.readers.read_record`, so every format it reads can be in a
suite.
"""

from __future__ import annotations

import os
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import NamedTuple, overload

from pounding.ground_motion.bundled import bundled_folder, bundled_records, load_bundled
from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.readers.dispatch import read_record
from pounding.ground_motion.readers.units import UnitsRequired

__all__ = ["RecordSuite", "SkippedFile", "bundled_suite", "read_suite"]

BUNDLED = "bundled"
"""The name of the bundled suite, and what :func:`read_suite` takes for it."""


class SkippedFile(NamedTuple):
    """A file of a suite's folder that was not read: the file, and why (the reader's one-line
    message, which names the file)."""

    path: str
    reason: str


@dataclass(frozen=True)
class RecordSuite:
    """An ordered, named collection of ground motions and the files they came from.

    Parameters
    ----------
    name : str
        The suite's name (a folder's name, ``"bundled"``, or the caller's).
    motions : tuple of GroundMotion
        The records, in suite order (at least one).
    paths : tuple of str
        The file each record was read from, in the same order.
    skipped : tuple of SkippedFile
        The files of a suite's folder that could not be read, with the reason.

    Raises
    ------
    ValueError
        If there is no record, or ``paths`` and ``motions`` differ in length.
    """

    name: str
    motions: tuple[GroundMotion, ...]
    paths: tuple[str, ...]
    skipped: tuple[SkippedFile, ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "motions", tuple(self.motions))
        object.__setattr__(self, "paths", tuple(str(p) for p in self.paths))
        object.__setattr__(self, "skipped", tuple(SkippedFile(*s) for s in self.skipped))
        if not self.motions:
            raise ValueError(f"record suite {self.name!r}: no record")
        if len(self.paths) != len(self.motions):
            raise ValueError(f"record suite {self.name!r}: {len(self.motions)} records but "
                             f"{len(self.paths)} paths")
        bad = next((m for m in self.motions if not isinstance(m, GroundMotion)), None)
        if bad is not None:
            raise ValueError(f"record suite {self.name!r}: not a GroundMotion: {bad!r}")

    # ------------------------------------------------------------------ a sequence
    def __len__(self) -> int:
        return len(self.motions)

    def __iter__(self) -> Iterator[GroundMotion]:
        return iter(self.motions)

    @overload
    def __getitem__(self, key: int) -> GroundMotion: ...

    @overload
    def __getitem__(self, key: str) -> GroundMotion: ...

    def __getitem__(self, key: int | str) -> GroundMotion:
        """A record by position, or by name (its :attr:`GroundMotion.name`, or its file's
        name or stem).

        Raises
        ------
        IndexError
            For a position out of range.
        KeyError
            For a name that no record has, or that several have.
        """
        if isinstance(key, int):
            return self.motions[key]
        found = [m for m, p in zip(self.motions, self.paths, strict=True)
                 if key in (m.name, Path(p).name, Path(p).stem)]
        if len(found) != 1:
            what = "no record" if not found else f"{len(found)} records"
            raise KeyError(f"record suite {self.name!r}: {what} named {key!r}; the records "
                           f"are {', '.join(self.names)}")
        return found[0]

    @property
    def names(self) -> tuple[str, ...]:
        """The records' names, in suite order."""
        return tuple(m.name for m in self.motions)

    # ------------------------------------------------------------------ construction
    @classmethod
    def from_paths(cls, paths: Sequence[str | os.PathLike[str]], *, dt: float | None = None,
                   units: str | None = None, name: str = "records",
                   column: int | None = None, time_column: int | None = None,
                   channel: int | None = None) -> RecordSuite:
        """The records of ``paths``, in that order; each must read.

        ``dt`` and ``units`` are for files that do not state them, and ``column``,
        ``time_column`` (plain text) and ``channel`` (COSMOS) choose what a file of several
        series is read for, as in :func:`~pounding.ground_motion.readers.read_record`.

        Raises
        ------
        ValueError
            If ``paths`` is empty, or as the reader raises for a file (naming it).
        FileNotFoundError, IsADirectoryError
            For a path that is missing or a folder.
        """
        if isinstance(paths, (str, os.PathLike)):
            paths = [paths]
        if not paths:
            raise ValueError(f"record suite {name!r}: no record files given")
        return cls(name, tuple(read_record(p, dt=dt, units=units, column=column,
                                           time_column=time_column, channel=channel)
                               for p in paths),
                   tuple(str(p) for p in paths))

    @classmethod
    def from_folder(cls, folder: str | os.PathLike[str], *, dt: float | None = None,
                    units: str | None = None, name: str | None = None,
                    column: int | None = None, time_column: int | None = None,
                    channel: int | None = None) -> RecordSuite:
        """Every readable record file in ``folder`` (not its subfolders), by file name.

        Hidden files (names starting with ``.``) are passed over; a file that does not read
        is kept in :attr:`skipped` with the reader's message. ``dt`` and ``units`` apply to
        every file that does not state them; a plain-text record read without ``units`` is
        an error (:class:`~pounding.ground_motion.readers.UnitsRequired`), not skipped.

        Parameters
        ----------
        folder : path-like
            The folder.
        dt, units : optional
            As in :func:`~pounding.ground_motion.readers.read_record`.
        column, time_column, channel : int, optional
            As in :func:`~pounding.ground_motion.readers.read_record`, for every file: a file
            of a format they are not for is skipped, with the reason.
        name : str, optional
            The suite's name; default the folder's name.

        Raises
        ------
        FileNotFoundError, NotADirectoryError
            If ``folder`` is missing or not a folder.
        ValueError
            If no file in it reads: one line naming the folder, the number of files and the
            first file's reason.
        """
        root = Path(folder)
        if not root.exists():
            raise FileNotFoundError(f"{root}: no such folder")
        if not root.is_dir():
            raise NotADirectoryError(f"{root}: is a file, not a folder of records")
        files = sorted((p for p in root.iterdir() if p.is_file() and not p.name.startswith(".")),
                       key=lambda p: p.name)
        motions: list[GroundMotion] = []
        paths: list[str] = []
        skipped: list[SkippedFile] = []
        for p in files:
            try:
                motions.append(read_record(p, dt=dt, units=units, column=column,
                                           time_column=time_column, channel=channel))
            except UnitsRequired:
                raise  # a record, that needs the units of the folder's text files
            except (ValueError, OSError) as exc:
                skipped.append(SkippedFile(str(p), str(exc)))
                continue
            paths.append(str(p))
        if not motions:
            if not files:
                raise ValueError(f"{root}: no record files in this folder")
            raise ValueError(f"{root}: none of its {len(files)} files is a record pounding "
                             f"reads (first: {skipped[0].reason})")
        return cls(name if name is not None else root.resolve().name, tuple(motions),
                   tuple(paths), tuple(skipped))


def bundled_suite() -> RecordSuite:
    """The bundled suite: the nine real records of :func:`bundled_records` (every record
    shipped with pounding but the Düzce pair of orthogonal components and the Peknold
    digitisation of El Centro N–S, a second copy of the first record's motion), named
    ``"bundled"``, in the order of ``pounding/data/records/records.toml`` (provenance in
    SOURCES.md beside it and in each record's ``metadata["provenance"]``).

    Runs on a fresh install: the files ship inside the package.
    """
    files = bundled_records()
    return RecordSuite(BUNDLED, tuple(load_bundled(f) for f in files),
                       tuple(str(bundled_folder().joinpath(f)) for f in files))


def read_suite(source: str | os.PathLike[str] | Sequence[str | os.PathLike[str]], *,
               dt: float | None = None, units: str | None = None,
               column: int | None = None, time_column: int | None = None,
               channel: int | None = None) -> RecordSuite:
    """A record suite from ``"bundled"`` (:func:`bundled_suite`), a folder
    (:meth:`RecordSuite.from_folder`), a record file or a list of them
    (:meth:`RecordSuite.from_paths`).

    Raises
    ------
    ValueError
        As the constructor it calls; also for ``dt``, ``units``, ``column``,
        ``time_column`` or ``channel`` with the bundled suite, whose files state their own.
    """
    if isinstance(source, str) and source == BUNDLED:
        given = [k for k, v in {"dt": dt, "units": units, "column": column,
                                "time_column": time_column, "channel": channel}.items()
                 if v is not None]
        if given:
            raise ValueError(f"record suite 'bundled': {' and '.join(given)} "
                             f"{'is' if len(given) == 1 else 'are'} for record files; the "
                             "bundled records state their own")
        return bundled_suite()
    if isinstance(source, (str, os.PathLike)):
        path = Path(source)
        if path.is_dir():
            return RecordSuite.from_folder(path, dt=dt, units=units, column=column,
                                           time_column=time_column, channel=channel)
        return RecordSuite.from_paths([path], dt=dt, units=units, name=path.stem,
                                      column=column, time_column=time_column, channel=channel)
    return RecordSuite.from_paths(source, dt=dt, units=units, column=column,
                                  time_column=time_column, channel=channel)

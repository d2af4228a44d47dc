"""The records shipped in ``pounding/data/records`` (provenance in its SOURCES.md):
:func:`bundled_files` lists every one, :func:`bundled_records` those of the bundled suite in
suite order, :func:`load_bundled` reads one by name, :func:`bundled_companion` names the
other horizontal component of a record shipped with its orthogonal pair, and
:func:`el_centro` is the Imperial Valley 1940 El Centro record used in the examples. The
suite itself is :func:`pounding.ground_motion.suite.bundled_suite`.

``records.toml`` beside the files is the manifest: one ``[[record]]`` a file, the suite's in
suite order, with the unit of a file that does not state it, ``suite = false`` for a record
kept out of the suite, ``companion`` for one of a pair of orthogonal horizontal components,
and the record's provenance (earthquake, station, source repository and path, git blob id).
"""

from __future__ import annotations

import dataclasses
import functools
import tomllib
from importlib import resources
from importlib.resources.abc import Traversable
from pathlib import Path
from typing import Any

from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.readers.dispatch import read_record
from pounding.ground_motion.readers.units import ASSUMED

__all__ = ["BUNDLED_FOLDER", "bundled_companion", "bundled_files", "bundled_folder",
           "bundled_records", "el_centro", "load_bundled"]

BUNDLED_FOLDER = "data/records"
"""The folder of the bundled records inside the ``pounding`` package."""

_MANIFEST = "records.toml"
_EL_CENTRO = "elcentro_1940_IV_ELC9_180_PEER.AT2"
_PROVENANCE = ("earthquake", "station", "source", "git_blob")
"""The manifest keys copied into a bundled record's ``metadata["provenance"]``."""


def bundled_folder() -> Traversable:
    """The folder of the bundled records, as :mod:`importlib.resources` gives it (a
    :class:`pathlib.Path` for an installed or editable package)."""
    folder = resources.files("pounding")
    for part in BUNDLED_FOLDER.split("/"):
        folder = folder.joinpath(part)
    return folder


@functools.lru_cache(maxsize=1)
def _manifest() -> tuple[dict[str, Any], ...]:
    """The ``[[record]]`` entries of ``records.toml``, in manifest order."""
    return tuple(tomllib.loads(bundled_folder().joinpath(_MANIFEST).read_text(encoding="utf-8"))
                 ["record"])


def bundled_files() -> list[str]:
    """File names of every bundled record, in manifest order: the bundled suite's
    (:func:`bundled_records`), then those kept out of it (the Peknold digitisation of El
    Centro N–S, a second copy of the first record's motion, and the Düzce pair of
    orthogonal components). Provenance in ``pounding/data/records/SOURCES.md``."""
    return [entry["file"] for entry in _manifest()]


def bundled_records() -> list[str]:
    """File names of the records of the bundled suite, in suite order: every bundled
    record that ``records.toml`` does not mark ``suite = false`` (provenance in
    ``pounding/data/records/SOURCES.md``)."""
    return [entry["file"] for entry in _manifest() if entry.get("suite", True)]


def bundled_companion(name: str) -> str | None:
    """File name of the other horizontal component of bundled record ``name`` (file name or
    stem): recorded at the same station in the same earthquake, at right angles to it; None
    for a record shipped without its companion.

    Raises
    ------
    ValueError
        If ``name`` is not a bundled record; the message lists them.
    """
    companion: str | None = _manifest()[_index(name)].get("companion")
    return companion


def load_bundled(name: str) -> GroundMotion:
    """Read a bundled record by file name (see :func:`bundled_files`); the stem works too.

    Cached: the data ship with the package and a GroundMotion is immutable.

    Returns
    -------
    GroundMotion
        As :func:`~pounding.ground_motion.readers.read_record` reads the file, with
        ``source`` ``"pounding/data/records/<file> (bundled)"`` and
        ``metadata["provenance"]``: the record's ``earthquake``, ``station``, ``source``
        (repository : path) and ``git_blob``. A unit the manifest gives for a file that
        states none is reported as assumed (``"m/s2 (assumed)"``).

    Raises
    ------
    ValueError
        If ``name`` is not a bundled record; the message lists them.
    """
    return _load(_index(name))


def _index(name: str) -> int:
    """The manifest entry of bundled record ``name`` (file name or stem)."""
    index = next((i for i, e in enumerate(_manifest())
                  if name in (e["file"], Path(e["file"]).stem)), None)
    if index is None:
        raise ValueError(f"bundled record: unknown name {name!r}; choose one of "
                         f"{', '.join(bundled_files())}")
    return index


@functools.lru_cache(maxsize=16)
def _load(index: int) -> GroundMotion:
    """The bundled record of manifest entry ``index``, read once."""
    entry = _manifest()[index]
    with resources.as_file(bundled_folder().joinpath(entry["file"])) as file:
        gm = read_record(file, dt=entry.get("dt"), units=entry.get("units"))
    units_read = gm.units_read + ASSUMED if "units" in entry else gm.units_read
    provenance = {key: entry[key] for key in _PROVENANCE if key in entry}
    return dataclasses.replace(gm, source=f"pounding/{BUNDLED_FOLDER}/{entry['file']} (bundled)",
                               units_read=units_read,
                               metadata={**gm.metadata, "provenance": provenance})


@functools.lru_cache(maxsize=1)
def el_centro() -> GroundMotion:
    """Imperial Valley 1940, El Centro Array #9, component 180 (PEER; bundled).

    4000 samples at 0.01 s, PGA 0.3129 g. Provenance: ``pounding/data/records/SOURCES.md``.
    """
    gm = load_bundled(_EL_CENTRO)
    return dataclasses.replace(gm, name="El Centro 1940 (Array #9, 180)")

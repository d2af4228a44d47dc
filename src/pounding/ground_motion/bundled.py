"""The records shipped in ``pounding/data`` (provenance in ``pounding/data/SOURCES.md``):
:func:`bundled_records` lists them, :func:`load_bundled` reads one by name and
:func:`el_centro` is the Imperial Valley 1940 El Centro record used in the examples.
"""

from __future__ import annotations

import dataclasses
import functools
from importlib import resources
from pathlib import Path

from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.readers.at2 import read_at2

__all__ = ["bundled_records", "el_centro", "load_bundled"]

_DATA = "data"
_EL_CENTRO = "elcentro_1940_IV_ELC9_180_PEER.AT2"


def bundled_records() -> list[str]:
    """File names of the records shipped in ``pounding/data`` (provenance in its SOURCES.md)."""
    return list(_bundled_names())


@functools.lru_cache(maxsize=1)
def _bundled_names() -> tuple[str, ...]:
    folder = resources.files("pounding").joinpath(_DATA)
    return tuple(sorted(f.name for f in folder.iterdir()
                        if f.is_file() and f.name.lower().endswith(".at2")))


@functools.lru_cache(maxsize=16)
def load_bundled(name: str) -> GroundMotion:
    """Read a bundled record by file name (see :func:`bundled_records`); the stem works too.

    Cached: the data ship with the package and a GroundMotion is immutable."""
    names = bundled_records()
    match = [n for n in names if name in (n, Path(n).stem)]
    if not match:
        raise ValueError(f"bundled record: unknown name {name!r}; choose one of "
                         f"{', '.join(names)}")
    res = resources.files("pounding").joinpath(_DATA).joinpath(match[0])
    with resources.as_file(res) as file:
        gm = read_at2(file)
    return dataclasses.replace(gm, source=f"pounding/data/{match[0]} (bundled)")


@functools.lru_cache(maxsize=1)
def el_centro() -> GroundMotion:
    """Imperial Valley 1940, El Centro Array #9, component 180 (PEER; bundled).

    4000 samples at 0.01 s, PGA 0.3129 g. Provenance: ``pounding/data/SOURCES.md``.
    """
    gm = load_bundled(_EL_CENTRO)
    return dataclasses.replace(gm, name="El Centro 1940 (Array #9, 180)")

"""The example model, sweep, spectrum and fragility-study files that ship inside the package
(``pounding/examples``).

They are the same files as ``examples/`` of a clone of the repository (which links to
them), so an installed ``pounding`` can show and copy them: ``pounding examples`` lists
them, ``pounding examples --copy DIR`` copies them into a folder to edit and run, and
``pounding demo`` runs ``two_10_storey.toml`` from here.
"""

from __future__ import annotations

import os
from importlib import resources
from pathlib import Path
from typing import NamedTuple

from pounding.io.files import make_folders, remove_empty_folders, write_bytes

__all__ = ["DEMO", "KINDS", "SUFFIX_KINDS", "Example", "copy_examples", "example_kind",
           "example_path", "examples"]

DEMO = "two_10_storey.toml"
"""The example ``pounding demo`` runs."""

KINDS: tuple[str, ...] = ("sweep", "spectrum", "fragility", "mitigation")
"""Kinds of example other than a model file, told by the prefix ``<kind>_`` of the name."""

SUFFIX_KINDS: tuple[str, ...] = ("pushover",)
"""Kinds told by the suffix ``_<kind>`` of the name (``portal_pushover.toml``: a model file
made for ``pounding pushover``, with no record)."""


def example_kind(name: str) -> str:
    """The kind of the example file ``name``: a prefix of :data:`KINDS`, a suffix of
    :data:`SUFFIX_KINDS`, else ``"model"``."""
    stem = Path(name).stem
    return next((k for k in KINDS if stem.startswith(f"{k}_")),
                next((k for k in SUFFIX_KINDS if stem.endswith(f"_{k}")), "model"))


class Example(NamedTuple):
    """One bundled example: file name, kind (``model``, ``sweep``, ``spectrum``,
    ``fragility``, ``mitigation`` or ``pushover``: by the prefix ``sweep_`` / ``spectrum_`` /
    ``fragility_`` / ``mitigation_`` or the suffix ``_pushover`` of its name,
    :func:`example_kind`),
    what it shows."""

    name: str
    kind: str
    description: str


def _folder() -> Path:
    return Path(str(resources.files("pounding") / "examples"))


def example_path(name: str) -> Path:
    """The bundled example file ``name`` (``"seed_sdof_pair.toml"``; the suffix may be
    left out)."""
    file = name if name.endswith(".toml") else f"{name}.toml"
    path = _folder() / file
    if not path.is_file():
        raise ValueError(f"example: no bundled example {name!r}; there are "
                         f"{', '.join(e.name for e in examples())}")
    return path


def examples() -> list[Example]:
    """Every bundled example, with the first sentence of its opening comment."""
    out = []
    for path in sorted(_folder().glob("*.toml")):
        lines = []
        for line in path.read_text(encoding="utf-8").splitlines():
            if not line.startswith("#"):
                break
            lines.append(line.lstrip("# ").strip())
        text = " ".join(lines)
        first = text.split(". ")[0].rstrip(".")
        out.append(Example(path.name, example_kind(path.name), first))
    return out


DATA_SUFFIXES: tuple[str, ...] = (".csv", ".npy", ".npz", ".mtx")
"""Files an example reads (a building's matrices) that are copied out with it."""


def copy_examples(dest: str | os.PathLike[str], overwrite: bool = False) -> list[Path]:
    """Copy every bundled example (with the matrix files they read, and their README) into
    the folder ``dest`` (made if missing). An existing file is not replaced unless
    ``overwrite``. Each file is written whole (a temporary beside it, then renamed), so an
    interrupted copy leaves whole files only, and no folder it made empty. Returns the files
    written."""
    folder = Path(dest)
    if folder.exists() and not folder.is_dir():
        raise ValueError(f"copy: {folder} is a file, not a folder")
    sources = (sorted(_folder().glob("*.toml"))
               + sorted(p for p in _folder().iterdir() if p.suffix in DATA_SUFFIXES)
               + [_folder() / "README.md"])
    clash = [p.name for p in sources if (folder / p.name).exists()]
    if clash and not overwrite:
        raise ValueError(f"copy: {folder} already has {', '.join(clash)}; give --overwrite "
                         "to replace them")
    created = make_folders(folder)
    written: list[Path] = []
    try:
        for p in sources:  # each file whole or not at all (a full disk, Ctrl-C)
            written.append(write_bytes(folder / p.name, p.read_bytes()))
    except BaseException:
        remove_empty_folders(created)
        raise
    return written

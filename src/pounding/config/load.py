"""Reading a model file: validate it (:class:`~pounding.config.run.RunConfig`), check that
it builds, and warn of inputs probably in the wrong unit
(:mod:`pounding.config.plausibility`).

The top of the package: it uses the file's model (:mod:`pounding.config.run`), the
one-line errors (:mod:`pounding.config.errors`) and the plausibility checks, none of which
imports it.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from pounding.config.errors import format_validation_error
from pounding.config.plausibility import plausibility_warnings
from pounding.config.run import RunConfig
from pounding.io.files import read_toml
from pounding.plausibility import warn_plausibility

__all__ = ["SWEEP_CASE_TABLES", "load_config", "parse_config"]


def parse_config(data: dict[str, Any], base_dir: str | os.PathLike[str] = ".",
                 where: str = "config") -> RunConfig:
    """Validate already-parsed TOML data; ``base_dir`` is where relative paths start.

    An input that is valid but probably in the wrong unit (a gap of 40 m, a floor of 600
    kg, T1 below 0.05 s or above 10 s, a PGA above 3 g) is issued as a
    :class:`~pounding.plausibility.PlausibilityWarning`, ``<where>: <key>: …``, and kept in
    :attr:`RunConfig.plausibility`.

    Raises
    ------
    ValueError
        One line per problem, each ``<where>: <key path>: <problem> (got <value>)``.
    """
    cfg = _parse(data, base_dir, where)
    warn_plausibility(cfg.plausibility)
    return cfg


def _parse(data: dict[str, Any], base_dir: str | os.PathLike[str], where: str) -> RunConfig:
    """:func:`parse_config` without issuing its warnings."""
    try:
        cfg = RunConfig.model_validate(data, context={"base_dir": Path(base_dir)})
    except ValidationError as exc:
        raise ValueError(format_validation_error(exc, prefix=f"{where}: ",
                                                 root=RunConfig)) from None
    try:
        built = cfg.build()
    except ValueError as exc:
        raise ValueError(f"{where}: {exc}") from None
    cfg._plausibility = tuple(f"{where}: {line}" for line in plausibility_warnings(cfg, built))
    return cfg


SWEEP_CASE_TABLES = ("grid", "list", "random")
"""The tables of a sweep file that give its cases (:mod:`pounding.studies.sweep`); a file
with ``base`` and one of them is a sweep file, not a model file."""


def load_config(path: str | os.PathLike[str]) -> RunConfig:
    """Read and validate a TOML model file (and check it builds).

    Raises
    ------
    ValueError
        If the file is missing or not TOML, or any key is unknown or has a bad value:
        one line per problem naming the key path and the value.
    """
    p = Path(path)
    data = read_toml(p, "model file")
    if "base" in data and any(k in data for k in SWEEP_CASE_TABLES):
        raise ValueError(f"{p}: this is a sweep file (it has 'base' and a [grid], [list] or "
                         f"[random] table), not a model file: run it with `pounding sweep {p}`")
    cfg = _parse(data, base_dir=p.resolve().parent, where=str(p))
    cfg._source = p.resolve()
    warn_plausibility(cfg.plausibility)
    return cfg

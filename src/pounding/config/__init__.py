"""Model files: a pounding run described in TOML, validated before anything is computed.

A model file names the ground motion, the buildings from left to right, the contact law
and gaps, the solver options and what to write. :func:`load_config` reads and validates it
into a :class:`RunConfig`; :meth:`RunConfig.build` turns that into the objects of the
library — a :class:`~pounding.model.PoundingModel`, a
:class:`~pounding.ground_motion.GroundMotion` and the keyword arguments of
:func:`~pounding.integrate.simulate`.

Every problem is reported as one :class:`ValueError` holding one line per problem, each
naming the key by its path in the file and the value found, e.g.::

    model.toml: building[1].period: must be in (0, 100] s (got -0.5)
    model.toml: contact.gaps: need 1 value for 2 buildings (got 2: [0.02, 0.03])

(``building[1]`` is the second ``[[building]]`` table: indices are 0-based, as in the
error messages of the library itself). Every number has a physical range
(:mod:`~pounding.config.quantities`). An input that is valid but probably in the wrong unit
is a :class:`~pounding.plausibility.PlausibilityWarning`
(:mod:`~pounding.config.plausibility`). The format, key by key, is in ``docs/running.md``.

One section a module: :mod:`~pounding.config.record`, :mod:`~pounding.config.building`
(its damping and storey laws in :mod:`~pounding.config.storeys`, plans in
:mod:`~pounding.config.plan`, isolators and walls in :mod:`~pounding.config.isolation`),
:mod:`~pounding.config.contact`, :mod:`~pounding.config.device`, :mod:`~pounding.config.run`
(solver, output, the whole file), :mod:`~pounding.config.load` (reading a file: validating,
building, checking); :mod:`~pounding.config.quantities` gives every
number its unit and range, :mod:`~pounding.config.errors` turns validation errors into those
lines, :mod:`~pounding.config.plausibility` finds inputs probably in the wrong unit, and
:mod:`~pounding.config.toml` writes a model file back.

Names are imported on first use (PEP 562): importing one module of the package (say
:mod:`pounding.config.base`, for a study file's sections) loads only what that module
needs.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from pounding.lazy import lazy_exports

_EXPORTS: dict[str, str] = {
    "BuildingConfig": "pounding.config.building",
    "DampingConfig": "pounding.config.building",
    "StoreyLawConfig": "pounding.config.building",
    "CONTACT_COMMON": "pounding.config.contact",
    "LAW_FIELDS": "pounding.config.contact",
    "ContactConfig": "pounding.config.contact",
    "format_validation_error": "pounding.config.errors",
    "EL_CENTRO_ALIASES": "pounding.config.record",
    "RecordConfig": "pounding.config.record",
    "SWEEP_CASE_TABLES": "pounding.config.load",
    "Built": "pounding.config.run",
    "OutputConfig": "pounding.config.run",
    "RunConfig": "pounding.config.run",
    "SolverConfig": "pounding.config.run",
    "load_config": "pounding.config.load",
    "parse_config": "pounding.config.load",
    "dump_toml": "pounding.config.toml",
    "PushoverConfig": "pounding.config.pushover",
    "load_pushover": "pounding.config.pushover",
}
"""Public name → the module that defines it."""


__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)


if TYPE_CHECKING:  # what type checkers and IDEs see: the same names, imported eagerly
    from pounding.config.building import BuildingConfig, DampingConfig, StoreyLawConfig
    from pounding.config.contact import CONTACT_COMMON, LAW_FIELDS, ContactConfig
    from pounding.config.errors import format_validation_error
    from pounding.config.load import SWEEP_CASE_TABLES, load_config, parse_config
    from pounding.config.record import EL_CENTRO_ALIASES, RecordConfig
    from pounding.config.run import Built, OutputConfig, RunConfig, SolverConfig
    from pounding.config.pushover import PushoverConfig, load_pushover
    from pounding.config.toml import dump_toml

__all__ = [
    "BuildingConfig",
    "Built",
    "CONTACT_COMMON",
    "ContactConfig",
    "DampingConfig",
    "EL_CENTRO_ALIASES",
    "LAW_FIELDS",
    "OutputConfig",
    "PushoverConfig",
    "RecordConfig",
    "RunConfig",
    "SWEEP_CASE_TABLES",
    "SolverConfig",
    "StoreyLawConfig",
    "dump_toml",
    "format_validation_error",
    "load_config",
    "load_pushover",
    "parse_config",
]

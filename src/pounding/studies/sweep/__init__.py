"""Parameter sweeps: one base model, many cases, one tidy Parquet table — run on Dask.

A sweep file (TOML, see ``docs/sweep.md``) names a base model file (or holds one inline)
and the cases: a ``[grid]`` (every combination), a ``[list]`` (columns zipped row by row)
or ``[random]`` samples drawn with a seed. Parameters are dotted paths into the model
file: ``"contact.gap"``, ``"contact.e"``, ``"record.scale"``, ``"building.0.period"``,
``"building.*.period"`` (every building), ``"contact.law"``, ``"record.file"``, …

Every case gets a deterministic id, a hash of its parameter values. Each case is applied to
the base configuration, validated by :mod:`pounding.config` (a bad value names the key),
built, simulated and reduced to one row of summary measures. A case that fails is recorded
(``status = "error"`` and the message) and the sweep goes on; an invalid base model or an
unknown parameter path stops the sweep before anything runs.

Persistence is loss-free and resumable. Cases run in batches (one Dask task each); the
client writes every finished batch as a small Parquet file ``parts/part-<hash>.parquet``
(temporary name, then rename) the moment it arrives. A sweep that is started again — after
Ctrl-C, a crash or SIGKILL — reads the parts present and runs only the missing cases. At the
end all parts are consolidated into ``results.parquet``, rows in case order, columns and
types fixed by the sweep: two runs of the same sweep give tables equal bit for bit in every
column except ``wall_time_s`` (:data:`NONDETERMINISTIC_COLUMNS`).

The modules, one concept each:

* planning — :mod:`~pounding.studies.sweep.sweep_file` (the sweep file, :class:`Sweep`),
  :mod:`~pounding.studies.sweep.sections` (its keys and tables, validated as a model file's),
  :mod:`~pounding.studies.sweep.cases` (the case tables, case ids),
  :mod:`~pounding.studies.sweep.overrides` (a case applied to the base model),
  :mod:`~pounding.studies.sweep.checks` (what is checked before anything runs);
* execution — :mod:`~pounding.studies.sweep.execute` (one case, a batch, the warm-up:
  the worker side), :mod:`~pounding.studies.sweep.builder` (a case's model, motion and
  solver options, sharing what the cases of a sweep have in common),
  :mod:`~pounding.studies.sweep.measures` (the row of a case),
  :mod:`~pounding.studies.sweep.cluster` (the Dask client),
  :mod:`~pounding.studies.sweep.runner` (:func:`run_sweep`);
* storage — :mod:`~pounding.studies.sweep.store` (the output folder: manifest, parts,
  histories), :mod:`~pounding.studies.sweep.table` (``results.parquet``,
  :func:`load_results`).

Names are imported on first use (PEP 562): ``import pounding.studies.sweep.table`` (to read
a sweep's table) loads neither Dask nor the model, SciPy or numba.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from pounding.lazy import lazy_exports

_EXPORTS: dict[str, str] = {
    "MAX_CASES": "pounding.studies.sweep.cases",
    "Case": "pounding.studies.sweep.cases",
    "case_id": "pounding.studies.sweep.cases",
    "run_case": "pounding.studies.sweep.execute",
    "warm_up": "pounding.studies.sweep.execute",
    "FLOOR_MEASURES": "pounding.studies.sweep.measures",
    "MEASURES": "pounding.studies.sweep.measures",
    "apply_overrides": "pounding.studies.sweep.overrides",
    "HISTORY_FORMATS": "pounding.studies.sweep.sweep_file",
    "Sweep": "pounding.studies.sweep.sweep_file",
    "load_sweep": "pounding.studies.sweep.sweep_file",
    "parse_sweep": "pounding.studies.sweep.sweep_file",
    "SweepInterrupted": "pounding.studies.sweep.runner",
    "SweepOutcome": "pounding.studies.sweep.runner",
    "SweepStopped": "pounding.studies.sweep.runner",
    "run_sweep": "pounding.studies.sweep.runner",
    # names of the output folder
    "HISTORIES_DIR": "pounding.studies.sweep.store",
    "MANIFEST_FILE": "pounding.studies.sweep.store",
    "PARTS_DIR": "pounding.studies.sweep.store",
    "RESULTS_FILE": "pounding.studies.sweep.store",
    "NONDETERMINISTIC_COLUMNS": "pounding.studies.sweep.table",
    "load_results": "pounding.studies.sweep.table",
}
"""Public name → the module that defines it."""


__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)


if TYPE_CHECKING:  # what type checkers and IDEs see: the same names, imported eagerly
    from pounding.studies.sweep.cases import MAX_CASES, Case, case_id
    from pounding.studies.sweep.execute import run_case, warm_up  # noqa: F401
    from pounding.studies.sweep.measures import FLOOR_MEASURES, MEASURES
    from pounding.studies.sweep.overrides import apply_overrides
    from pounding.studies.sweep.runner import (
        SweepInterrupted,
        SweepOutcome,
        SweepStopped,
        run_sweep,
    )
    from pounding.studies.sweep.store import (  # noqa: F401  (names of the output folder)
        HISTORIES_DIR,
        MANIFEST_FILE,
        PARTS_DIR,
        RESULTS_FILE,
    )
    from pounding.studies.sweep.sweep_file import (  # noqa: F401
        HISTORY_FORMATS,
        Sweep,
        load_sweep,
        parse_sweep,
    )
    from pounding.studies.sweep.table import NONDETERMINISTIC_COLUMNS, load_results

__all__ = [
    "FLOOR_MEASURES",
    "MAX_CASES",
    "MEASURES",
    "NONDETERMINISTIC_COLUMNS",
    "Case",
    "Sweep",
    "SweepInterrupted",
    "SweepOutcome",
    "SweepStopped",
    "apply_overrides",
    "case_id",
    "load_results",
    "load_sweep",
    "parse_sweep",
    "run_case",
    "run_sweep",
]

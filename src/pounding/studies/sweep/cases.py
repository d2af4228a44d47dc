"""The cases of a sweep: the ``[grid]``, ``[list]`` and ``[random]`` tables, and case ids.

A case is a tuple of parameter values, one per swept parameter. Its id is a hash of its
``{parameter: value}`` in canonical JSON, so it does not depend on the order of the
parameters, the table that gave it, or the run.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial
from typing import Any

import numpy as np

__all__ = ["MAX_CASES", "Case", "case_id"]

MAX_CASES = 1_000_000
"""Most cases a sweep may have. The client holds every case and, at the end, every row in
memory (about 2 kB a case), and a million cases of a few ms each are hours on a small
machine: a larger table is almost surely a mistake (a grid with a parameter too many), and
is refused before any case is made."""


@dataclass(frozen=True)
class Case:
    """One case: its position in the sweep, its id and its parameter values."""

    index: int
    id: str
    values: tuple[Any, ...]


_CANON = json.JSONEncoder(sort_keys=True, separators=(",", ":"), ensure_ascii=False,
                          allow_nan=False)
"""The encoder of :func:`_canon`, made once (``json.dumps`` makes one a call)."""


def _canon(value: Any) -> str:
    """Canonical JSON (sorted keys, float repr): equal values give equal text."""
    return _CANON.encode(value)


def case_id(params: Sequence[str], values: Sequence[Any]) -> str:
    """The id of a case: 16 hex digits of a hash of its ``{parameter: value}`` (order-free)."""
    text = _canon(dict(zip(params, values)))
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _norm(value: Any, where: str) -> Any:
    """A parameter value as plain TOML data (checks it is finite)."""
    if isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f"{where}: values must be finite (got {value!r})")
    if isinstance(value, (np.floating,)):
        return float(value)
    if isinstance(value, (np.integer,)):
        return int(value)
    return value


def _draw_choice(values: Sequence[Any], gen: np.random.Generator) -> Any:
    """One of ``values``, each as likely."""
    return values[int(gen.integers(len(values)))]


def _draw_uniform(low: float, high: float, gen: np.random.Generator) -> float:
    """A number uniform in ``[low, high)``."""
    return float(gen.uniform(low, high))


def _draw_log_uniform(log_low: float, log_high: float, gen: np.random.Generator) -> float:
    """A number whose logarithm is uniform in ``[log_low, log_high)``."""
    return float(math.exp(gen.uniform(log_low, log_high)))


def _draw_integer(low: int, high: int, gen: np.random.Generator) -> int:
    """An integer from ``low`` to ``high``, both included, each as likely."""
    return int(gen.integers(low, high, endpoint=True))


def _random_cases(table: Any, where: str
                  ) -> tuple[tuple[str, ...], list[tuple], list[list[Any]]]:
    """The parameters, rows and samples (see :func:`case_rows`) of a ``[random]`` table
    (:class:`~pounding.studies.sweep.sections.RandomTable`: ``n`` samples drawn with
    ``seed``)."""
    n = table.n
    _check_count("random", n, f"n = {n:,}", where)
    draws: list[Callable[[np.random.Generator], Any]] = []
    choices: dict[int, list[Any]] = {}
    for key, dist in table.parameters.items():
        kind, arg = dist.kind, dist.argument
        if kind == "choice":
            choices[len(draws)] = [_norm(v, f"{where}: random.{key}") for v in arg]
            draws.append(partial(_draw_choice, arg))
        elif kind == "uniform":
            draws.append(partial(_draw_uniform, float(arg[0]), float(arg[1])))
        elif kind == "log":
            draws.append(partial(_draw_log_uniform, math.log(arg[0]), math.log(arg[1])))
        else:  # int
            draws.append(partial(_draw_integer, int(arg[0]), int(arg[1])))
    gen = np.random.Generator(np.random.PCG64(table.seed))
    rows = [tuple(d(gen) for d in draws) for _ in range(n)]
    # the values to check: every choice, and the smallest and largest number drawn
    samples = [choices[j] if j in choices else [min(r[j] for r in rows), max(r[j] for r in rows)]
               for j in range(len(draws))]
    return tuple(table.parameters), rows, samples


def _check_count(kind: str, n: int, how: str, where: str) -> None:
    """Refuse a case table of more than :data:`MAX_CASES` cases (before making them)."""
    if n > MAX_CASES:
        raise ValueError(f"{where}: [{kind}] gives {n:,} cases ({how}), more than the "
                         f"{MAX_CASES:,} a sweep may have; split it into several sweeps or "
                         "sample it with [random]")


def case_rows(kind: str, table: Any, where: str
              ) -> tuple[tuple[str, ...], list[tuple], list[list[Any]]]:
    """The parameters, the rows of values and the values to check of a case table.

    The number of cases is known before any is made: a table of more than
    :data:`MAX_CASES` is refused first.

    Parameters
    ----------
    kind : {"grid", "list", "random"}
        Which table: every combination, columns zipped, or random samples.
    table : dict or RandomTable
        The table, validated (:mod:`~pounding.studies.sweep.sections`): for ``grid`` and
        ``list`` each parameter's non-empty list of values, for ``random`` a
        :class:`~pounding.studies.sweep.sections.RandomTable`.
    where : str
        Prefix of error messages (the sweep file).

    Returns
    -------
    params : tuple of str
        The swept parameters (dotted paths), in the order of the table.
    rows : list of tuple
        One tuple of values per case, duplicates included.
    samples : list of list
        Per parameter, the values a check must see (:mod:`.checks`): every value given
        (``[grid]``, ``[list]``, ``choice``), else the smallest and the largest drawn.

    Raises
    ------
    ValueError
        A table of too many cases, or a ``[list]`` whose columns differ in length: one
        line naming the table.
    """
    if kind == "random":
        return _random_cases(table, where)
    params = tuple(table)
    cols = [[_norm(v, f"{where}: {kind}.{key}") for v in vals] for key, vals in table.items()]
    if kind == "grid":
        _check_count(kind, math.prod(len(c) for c in cols),
                     " × ".join(f"{len(c):,}" for c in cols) + " values", where)
        rows = list(itertools.product(*cols))
    else:
        lengths = {len(c) for c in cols}
        if len(lengths) != 1:
            raise ValueError(f"{where}: list: every parameter needs the same number of "
                             f"values (got {dict(zip(params, map(len, cols)))})")
        _check_count(kind, len(cols[0]), f"{len(cols[0]):,} values per parameter", where)
        rows = list(zip(*cols))
    return params, rows, cols


def unique_cases(params: Sequence[str], rows: list[tuple]) -> list[Case]:
    """The cases of ``rows`` in order, each set of values once (the first copy kept)."""
    seen: set[str] = set()
    cases: list[Case] = []
    for r in rows:
        cid = case_id(params, r)
        if cid in seen:
            continue
        seen.add(cid)
        cases.append(Case(len(cases), cid, tuple(r)))
    return cases

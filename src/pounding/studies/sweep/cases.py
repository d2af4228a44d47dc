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


def _random_cases(table: dict[str, Any], where: str
                  ) -> tuple[tuple[str, ...], list[tuple], list[list[Any]]]:
    """The parameters, rows and samples (see :func:`case_rows`) of a ``[random]`` table
    (``n`` samples drawn with ``seed``)."""
    t = dict(table)
    n = t.pop("n", None)
    seed = t.pop("seed", None)
    if not isinstance(n, int) or isinstance(n, bool) or n < 1:
        raise ValueError(f"{where}: random.n: the number of samples, an integer >= 1 "
                         f"(got {n!r})")
    if not isinstance(seed, int) or isinstance(seed, bool) or seed < 0:
        raise ValueError(f"{where}: random.seed: required, an integer >= 0 (got {seed!r})")
    _check_count("random", n, f"n = {n:,}", where)
    if not t:
        raise ValueError(f"{where}: random: give at least one parameter, e.g. "
                         "\"contact.gap\" = [0.0, 0.05]")
    draws: list[Callable[[np.random.Generator], Any]] = []
    choices: dict[int, list[Any]] = {}
    for key, spec in t.items():
        w = f"{where}: random.{key}"
        if isinstance(spec, list):
            spec = {"uniform": spec}
        if not isinstance(spec, dict) or len(spec) != 1:
            raise ValueError(f"{w}: give [low, high] (uniform) or one of {{ uniform = [a, b] }}"
                             f", {{ log = [a, b] }}, {{ int = [a, b] }}, {{ choice = [...] }} "
                             f"(got {spec!r})")
        (kind, arg), = spec.items()
        if kind == "choice":
            if not isinstance(arg, list) or not arg:
                raise ValueError(f"{w}: choice needs a non-empty list (got {arg!r})")
            choices[len(draws)] = [_norm(v, w) for v in arg]
            draws.append(lambda g, a=arg: a[int(g.integers(len(a)))])
            continue
        if (not isinstance(arg, list) or len(arg) != 2
                or not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in arg)
                or not arg[0] < arg[1]):
            raise ValueError(f"{w}: {kind} needs [low, high] with low < high (got {arg!r})")
        lo, hi = arg
        if kind == "uniform":
            draws.append(lambda g, a=float(lo), b=float(hi): float(g.uniform(a, b)))
        elif kind == "log":
            if lo <= 0:
                raise ValueError(f"{w}: log needs low > 0 (got {arg!r})")
            draws.append(lambda g, a=math.log(lo), b=math.log(hi): float(math.exp(g.uniform(a, b))))
        elif kind == "int":
            draws.append(lambda g, a=int(lo), b=int(hi): int(g.integers(a, b, endpoint=True)))
        else:
            raise ValueError(f"{w}: unknown distribution {kind!r}; use uniform, log, int or "
                             "choice")
    gen = np.random.Generator(np.random.PCG64(seed))
    rows = [tuple(d(gen) for d in draws) for _ in range(n)]
    # the values to check: every choice, and the smallest and largest number drawn
    samples = [choices[j] if j in choices else [min(r[j] for r in rows), max(r[j] for r in rows)]
               for j in range(len(draws))]
    return tuple(t), rows, samples


def _check_count(kind: str, n: int, how: str, where: str) -> None:
    """Refuse a case table of more than :data:`MAX_CASES` cases (before making them)."""
    if n > MAX_CASES:
        raise ValueError(f"{where}: [{kind}] gives {n:,} cases ({how}), more than the "
                         f"{MAX_CASES:,} a sweep may have; split it into several sweeps or "
                         "sample it with [random]")


def case_rows(kind: str, table: dict[str, Any], where: str
              ) -> tuple[tuple[str, ...], list[tuple], list[list[Any]]]:
    """The parameters, the rows of values and the values to check of a case table.

    The number of cases is known before any is made: a table of more than
    :data:`MAX_CASES` is refused first.

    Parameters
    ----------
    kind : {"grid", "list", "random"}
        Which table: every combination, columns zipped, or random samples.
    table : dict
        The table as read from the sweep file.
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
        A malformed table or one of too many cases, one line naming the key.
    """
    if kind == "random":
        return _random_cases(table, where)
    params = tuple(table)
    if not params:
        raise ValueError(f"{where}: [{kind}] is empty; give e.g. \"contact.gap\" = [0.01, "
                         "0.02]")
    cols = []
    for key, vals in table.items():
        if not isinstance(vals, list) or not vals:
            raise ValueError(f"{where}: {kind}.{key}: a non-empty list of values "
                             f"(got {vals!r})")
        cols.append([_norm(v, f"{where}: {kind}.{key}") for v in vals])
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
    cases = []
    for r in rows:
        cid = case_id(params, r)
        if cid in seen:
            continue
        seen.add(cid)
        cases.append(Case(len(cases), cid, tuple(r)))
    return cases

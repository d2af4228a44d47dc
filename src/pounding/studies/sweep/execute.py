"""Running cases: one case to one row, a batch of cases (one Dask task), and the warm-up
of a worker. This is what runs on the workers; it never writes a file."""

from __future__ import annotations

import gc
import os
import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from pounding.studies.sweep.builder import CaseBuilder, case_builder
from pounding.studies.sweep.bridge_measures import bridge_row
from pounding.studies.sweep.hinge_measures import hinge_row, stopped_row
from pounding.studies.sweep.measures import result_row

__all__ = ["Batch", "case_result", "run_case", "warm_up"]


def _error_text(exc: BaseException) -> str:
    """A failed case's message on one line (a validation error names the key)."""
    from pydantic import ValidationError

    from pounding.config import RunConfig, format_validation_error

    if isinstance(exc, ValidationError):
        return format_validation_error(exc, root=RunConfig).replace("\n", "; ")
    if isinstance(exc, ValueError):
        return str(exc).replace("\n", "; ")
    return f"{type(exc).__name__}: {exc}".replace("\n", "; ")


def case_result(base: dict[str, Any], base_dir: str | os.PathLike[str], params: Sequence[str],
                values: Sequence[Any]) -> Any:
    """Simulate one case: the base model with the case's values, validated, built and run.

    The cases of one sweep share what they have in common (:func:`.builder.case_builder`).

    Parameters
    ----------
    base, base_dir, params, values
        As :func:`run_case`.

    Returns
    -------
    pounding.result.Result

    Raises
    ------
    pydantic.ValidationError, ValueError
        A value the model does not accept, or a run that cannot be integrated.
    """
    return _simulate(case_builder(base, base_dir, params), values)


def _simulate(builder: CaseBuilder, values: Sequence[Any]) -> Any:
    """:func:`case_result` with the sweep's builder."""
    from pounding.integrate import simulate

    model, motion, solver = builder.build(values)
    return simulate(model, motion, **solver)


def run_case(base: dict[str, Any], base_dir: str | os.PathLike[str], params: Sequence[str],
             values: Sequence[Any], history: bool = False) -> tuple[dict[str, Any], Any]:
    """Run one case: ``(row, dataset or None)``; a failure is reported in the row.

    The row holds ``status`` (``"ok"`` / ``"error"``), ``error`` (the message or None),
    the measures and ``wall_time_s``; with plastic hinges their measures
    (:data:`~pounding.studies.sweep.hinge_measures.HINGE_MEASURES`), of which
    ``strength_lost`` is true for a run that stopped (``"error"``) because a frame lost its
    strength; for a bridge its joints', abutments' and restrainers' columns
    (:mod:`~pounding.studies.sweep.bridge_measures`).

    Parameters
    ----------
    base : dict
        The base model configuration as plain data.
    base_dir : path-like
        Where relative paths of the base model start.
    params : sequence of str
        The swept parameters (dotted paths).
    values : sequence
        The case's value of each parameter.
    history : bool
        Also return the time histories (:meth:`pounding.result.Result.to_dataset`).

    Returns
    -------
    row : dict
        The case's row of the results table (without its id).
    dataset : xarray.Dataset or None
        The time histories, if asked for and the case ran.
    """
    return _run(case_builder(base, base_dir, params), values, history)


def _run(builder: CaseBuilder, values: Sequence[Any], history: bool) -> tuple[dict[str, Any], Any]:
    """:func:`run_case` with the sweep's builder."""
    start = time.perf_counter()
    dataset = None
    try:
        result = _simulate(builder, values)
        row: dict[str, Any] = {"status": "ok", "error": None, **result_row(result),
                               **hinge_row(result), **bridge_row(result)}
        if history:
            dataset = result.to_dataset()
    except Exception as exc:  # noqa: BLE001  (recorded in the table, the sweep goes on)
        row = {"status": "error", "error": _error_text(exc), **stopped_row(exc)}
    row["wall_time_s"] = time.perf_counter() - start
    return row, dataset


@dataclass(frozen=True)
class Batch:
    """The cases of one Dask task, each ``(index, id, values)``.

    An object rather than a list: Dask walks every list and tuple in the arguments of a
    task, looking for futures (a few ms for hundreds of cases, in the client).
    """

    cases: tuple[tuple[int, str, tuple], ...]


def _run_batch(payload: dict[str, Any], batch: Batch) -> list[tuple[str, dict[str, Any], Any]]:
    """Run a batch of cases (one Dask task): ``[(case_id, row, dataset), ...]``."""
    builder = case_builder(payload["base"], payload["base_dir"], payload["params"])
    history = payload["histories"] is not None
    out = []
    for _, cid, values in batch.cases:
        row, ds = _run(builder, values, history)
        out.append((cid, row, ds))
    return out


def _start_local_worker() -> float:
    """Ready a worker of the sweep's own local cluster: :func:`warm_up`, then every object
    alive (modules, the compiled kernel: what the worker keeps to its end) frozen out of
    the cyclic garbage collector. Python's last collections at exit then skip them, and the
    worker stops in 0.03 s instead of 0.24 (measured 2026-11-25). Such a worker lives for
    one sweep: what it freezes lives as long, but for a few cycles the warm-up left, which
    a collection first (0.04 s) would free. Seconds taken."""
    seconds = warm_up()
    gc.freeze()
    return seconds


def warm_up() -> float:
    """Load the compiled kernel (numba's disk cache) in this process; seconds taken."""
    from pounding.ground_motion import GroundMotion
    from pounding.integrate import simulate
    from pounding.model import PoundingModel
    from pounding.structure import ShearBuilding

    start = time.perf_counter()
    b1 = ShearBuilding(masses=[1.0e5], stiffnesses=[4.0e7], heights=[3.0], name="a")
    b2 = ShearBuilding(masses=[1.0e5], stiffnesses=[1.0e7], heights=[3.0], name="b")
    from pounding.model import ContactSpec
    model = PoundingModel([b1, b2], [0.001], ContactSpec("nonlinear-viscoelastic", k_h=2.75e9,
                                                         e=0.65))
    t = np.arange(101) * 0.01
    gm = GroundMotion(dt=0.01, accel=3.0 * np.sin(2 * np.pi * t), name="warm-up")
    simulate(model, gm)
    return time.perf_counter() - start

"""Running a sweep: the pending cases in batches on the Dask client, each finished batch
saved the moment it arrives, then the consolidated table.

A sweep that stops before its end — Ctrl-C (:class:`SweepInterrupted`), a lost scheduler
or a failed worker (:class:`SweepStopped`) — keeps every batch saved so far; running it
again resumes it. One that stops before any case was saved leaves its output folder as it
was (a folder it made is removed).
"""

from __future__ import annotations

import contextlib
import os
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pounding.io.files import WriteFailed
from pounding.progress import Progress
from pounding.studies.sweep.cluster import (
    _auto_batch,
    _batch_sizes,
    _client,
    _start_worker_server,
)
from pounding.studies.sweep.execute import Batch, _run_batch, _start_local_worker, warm_up
from pounding.studies.sweep.extra import require_sweep_packages
from pounding.studies.sweep.store import (
    PARTS_DIR,
    _check_out,
    _part_name,
    _prepare_out,
    _read_parts,
    _remove_created,
    _saved_ids,
    _write_history,
    _write_part,
)
from pounding.studies.sweep.sweep_file import HISTORY_FORMATS, Sweep, load_sweep
from pounding.studies.sweep.table import _write_results

__all__ = ["SweepInterrupted", "SweepOutcome", "SweepStopped", "run_sweep"]


def _saved_text(n_saved: int, n_cases: int, out_dir: Path) -> str:
    """What a stopped sweep kept, for its message."""
    if n_saved == 0:
        return f"no case was saved, leaving {out_dir} as it was"
    return f"{n_saved:,} of {n_cases:,} cases are saved in {out_dir}"


class SweepStopped(RuntimeError):
    """A sweep stopped by its cluster (a lost scheduler, a failed worker), not by a case.

    The cases finished are saved; running the sweep again resumes it.

    Attributes
    ----------
    reason : str
        What happened, e.g. ``"the Dask scheduler at tcp://… was lost"``.
    n_saved, n_cases : int
        Cases saved in the output folder (before and during this run), and in all.
    out_dir : Path
        The output folder.
    """

    def __init__(self, reason: str, n_saved: int, n_cases: int, out_dir: Path) -> None:
        self.reason, self.n_saved, self.n_cases, self.out_dir = reason, n_saved, n_cases, out_dir
        super().__init__(f"{reason}: {_saved_text(n_saved, n_cases, out_dir)}; run the sweep "
                         "again to resume")


class SweepInterrupted(KeyboardInterrupt):
    """A sweep stopped by Ctrl-C (or SIGTERM, where the caller turns it into one).

    Attributes as :class:`SweepStopped` (``reason`` is ``"stopped (interrupted)"``).
    """

    def __init__(self, n_saved: int, n_cases: int, out_dir: Path) -> None:
        self.reason, self.n_saved, self.n_cases, self.out_dir = ("stopped (interrupted)",
                                                                 n_saved, n_cases, out_dir)
        super().__init__(f"{self.reason}: {_saved_text(n_saved, n_cases, out_dir)}; run the "
                         "sweep again to resume")


class _ClusterFailure(Exception):
    """The cluster failed under a running sweep (translated into :class:`SweepStopped`)."""


@dataclass(frozen=True)
class SweepOutcome:
    """What :func:`run_sweep` did."""

    out_dir: Path
    results: Path
    n_cases: int
    n_run: int
    """Cases run this time (the others were finished before)."""
    n_errors: int
    wall_time: float
    """Seconds from start to the consolidated table [s]."""
    run_time: float
    """Seconds spent running cases (after the cluster was up) [s]."""
    n_workers: int
    batch_size: int
    figure: Path | None = None
    """The figure drawn (``figures=True``), else None."""

    @property
    def rate(self) -> float:
        """Cases run per second of :attr:`run_time`."""
        return self.n_run / self.run_time if self.run_time > 0 else float("nan")

    def _repr_html_(self) -> str:
        """Jupyter's view: counts, times, the peak contact force over the cases [kN] and
        the sweep's figure, inline (:func:`pounding.studies.sweep.display.sweep_html`)."""
        from pounding.studies.sweep.display import sweep_html

        return sweep_html(self)


def run_sweep(input: Sweep | str | os.PathLike[str], out: str | os.PathLike[str] | None = None,
              *, overwrite: bool = False, figures: bool | None = None,
              progress: Progress | None = None, scheduler: str | None = None,
              n_workers: int | None = None, batch_size: int | None = None,
              histories: str | None | bool = None) -> SweepOutcome:
    """Run the missing cases of a sweep and write ``results.parquet``.

    The first arguments are those of every runner, in the same order (:func:`pounding.run`).

    Parameters
    ----------
    input : Sweep or path
        A sweep (:func:`load_sweep`) or its file.
    out : path-like, optional
        Output folder (default: ``out`` of the sweep file, relative to it, else
        ``<sweep file stem>-results`` in the current folder,
        :func:`pounding.io.output_folder.default_out_dir`).
    overwrite : bool
        Start afresh even if ``out`` holds this sweep (partly) done, or another sweep
        (only files pounding wrote there are removed).
    figures : bool, optional
        Draw the measure against the swept parameters into the folder, as ``pounding plot``
        does with its defaults: ``peak_contact_force_N`` against the first parameter, the
        mean over the others (:func:`pounding.plot.sweep.plot_sweep`), in
        :attr:`SweepOutcome.figure`. Default: no figure (a sweep is drawn as wanted with
        ``pounding plot`` and ``pounding report``).
    progress : Progress, optional
        Called as ``progress(done, total)``: cases finished (before and during this run)
        and cases in all, as batches finish (:class:`pounding.progress.Progress`).
    scheduler : str, optional
        None: a local Dask cluster (``n_workers`` processes, one thread each);
        ``"tcp://host:8786"``: that Dask scheduler; ``"synchronous"``: in this process.
    n_workers : int, optional
        Workers of the local cluster (default: the CPU count).
    batch_size : int, optional
        Cases per task (default from the sweep file, else automatic).
    histories : {"netcdf", "zarr"} or False, optional
        Write every case's time histories (default from the sweep file).

    Returns
    -------
    SweepOutcome

    Raises
    ------
    ValueError
        Bad input, one line: an output folder that cannot be used, no scheduler at
        ``scheduler`` (nothing is written then).
    SweepInterrupted
        Ctrl-C: the cases finished are saved.
    SweepStopped
        The scheduler was lost or a worker failed: the cases finished are saved.
    """
    sweep = input
    start = time.perf_counter()
    require_sweep_packages("a sweep", dask=scheduler not in ("synchronous", "sync", "none"))
    if not isinstance(sweep, Sweep):
        sweep = load_sweep(sweep)
    if out is None and sweep.out_refused is not None:
        raise ValueError(sweep.out_refused)
    out_dir = Path(out) if out is not None else sweep.out
    hist = sweep.histories if histories is None else (histories or None)
    if hist not in (None, *HISTORY_FORMATS):
        raise ValueError(f"histories: netcdf, zarr or none (got {hist!r})")
    if hist == "zarr":
        try:
            import zarr  # noqa: F401
        except ImportError:
            raise ValueError("histories: zarr needs the zarr package (pip install zarr); "
                             "or use netcdf") from None
    resume = _check_out(sweep, out_dir, overwrite)
    parts = out_dir / PARTS_DIR
    done: dict[str, dict[str, Any]] = {}
    if resume:
        done = _read_parts(parts)
    wanted = {c.id for c in sweep.cases}
    pending = [c for c in sweep.cases if c.id not in done]
    n_total = len(sweep.cases)
    n_done = sum(1 for cid in done if cid in wanted)
    if pending and scheduler is None:
        # the local cluster's workers load what they need while this process goes on
        _start_worker_server()
    if progress is not None:
        progress(n_done, n_total)
    payload = {"base": sweep.base, "base_dir": str(sweep.base_dir), "params": sweep.params,
               "histories": hist}

    def finish(results: list[tuple[str, dict[str, Any], Any]]) -> None:
        nonlocal n_done
        if hist is not None:
            for cid, row, ds in results:
                if ds is not None:
                    _write_history(out_dir, cid, ds, hist)
        _write_part(out_dir, [(cid, row) for cid, row, _ in results])
        for cid, row, _ in results:
            done[cid] = {"case_id": cid, **row}
        n_done += len(results)
        if progress is not None:
            progress(n_done, n_total)

    run_time = 0.0
    workers = 1
    bsize = batch_size or sweep.batch_size or 1
    created: list[Path] = []
    try:
        # the client first: no output is made for a sweep that cannot start
        with (_client(scheduler, n_workers) if pending else contextlib.nullcontext()) as client:
            _prepare_out(sweep, out_dir, resume, created, histories=hist is not None)
            if pending:
                workers = max(1, len(client.scheduler_info(n_workers=-1)["workers"])) \
                    if client is not None else 1
                given = batch_size or sweep.batch_size
                bsize = given or _auto_batch(len(pending), workers)
                batches, first = [], 0
                for size in _batch_sizes(len(pending), workers, bsize, taper=not given):
                    batches.append(Batch(tuple((c.index, c.id, c.values)
                                               for c in pending[first:first + size])))
                    first += size
                if client is not None:
                    client.run(_start_local_worker if scheduler is None else warm_up)
                t0 = time.perf_counter()
                if client is None:
                    for b in batches:
                        finish(_run_batch(payload, b))
                else:
                    _run_on(client, scheduler, payload, batches, finish)
                run_time = time.perf_counter() - t0
    except BaseException as exc:
        saved = len(_saved_ids(parts) & wanted)
        if saved == 0:
            _remove_created(out_dir, created)
        if isinstance(exc, KeyboardInterrupt):
            raise SweepInterrupted(saved, n_total, out_dir) from None
        if isinstance(exc, _ClusterFailure):
            raise SweepStopped(str(exc), saved, n_total, out_dir) from None
        if isinstance(exc, WriteFailed):
            raise WriteFailed(exc.target, f"{exc.reason}; {_saved_text(saved, n_total, out_dir)}"
                              + ("; run the sweep again to resume" if saved else ""),
                              exc.errno) from None
        raise
    try:
        results, n_err = _write_results(sweep, done, out_dir)
    except WriteFailed as exc:
        raise WriteFailed(exc.target, f"{exc.reason}; {_saved_text(n_total, n_total, out_dir)}; "
                          "run the sweep again to write the table", exc.errno) from None
    figure = _draw(out_dir, results) if figures else None
    return SweepOutcome(out_dir=out_dir, results=results, n_cases=n_total,
                        n_run=len(pending), n_errors=n_err,
                        wall_time=time.perf_counter() - start, run_time=run_time,
                        n_workers=workers, batch_size=bsize, figure=figure)


def _draw(out_dir: Path, results: Path) -> Path | None:
    """The default figure of ``pounding plot`` beside the table, in the folder's manifest;
    None when no case finished (nothing to draw)."""
    from pounding.io.manifest import Manifest
    from pounding.plot import save_figure
    from pounding.plot.sweep import default_figure_name, plot_sweep
    from pounding.studies.sweep.table import load_results

    table = load_results(results)
    if not (table["status"] == "ok").any():
        return None
    fig, x, y = plot_sweep(table)
    target = out_dir / default_figure_name("peak_contact_force_N", x, y)
    with Manifest(out_dir).write(target) as tmp:
        save_figure(fig, tmp)
    return target


def _run_on(client: Any, scheduler: str | None, payload: dict[str, Any],
            batches: list[Batch],
            finish: Callable[[list[tuple[str, dict[str, Any], Any]]], None]) -> None:
    """Run the batches on a Dask client, ``finish`` each result as it arrives.

    Raises
    ------
    _ClusterFailure
        The scheduler was lost, or a batch failed on the cluster (a worker died); the
        batches not finished are cancelled.
    """
    from distributed import as_completed

    futures: list[Any] = []
    try:
        [remote] = client.scatter([payload], broadcast=True, hash=False)
        futures = [client.submit(_run_batch, remote, b, pure=False,
                                 key=f"sweep-{_part_name([x[1] for x in b.cases])[5:21]}")
                   for b in batches]
        for fut, result in as_completed(futures, with_results=True, raise_errors=False):
            if fut.status != "finished":
                raise _ClusterFailure(_failure(client, scheduler, fut, result))
            finish(result)
            fut.release()
    except BaseException as exc:
        if client.status == "running":
            with contextlib.suppress(Exception):
                client.cancel(futures)
            raise
        if isinstance(exc, _ClusterFailure) or not isinstance(exc, Exception):
            raise
        raise _ClusterFailure(_lost(scheduler)) from exc


def _failure(client: Any, scheduler: str | None, fut: Any, result: Any) -> str:
    """What a batch that did not finish says about the cluster."""
    if client.status != "running":
        return _lost(scheduler)
    if fut.status == "error":
        return (f"a batch of cases failed on the cluster ({type(result[1]).__name__}: "
                f"{result[1]})")
    return "a batch of cases was cancelled on the cluster"


def _lost(scheduler: str | None) -> str:
    """What a lost scheduler is called in a message."""
    return (f"the Dask scheduler at {scheduler} was lost" if scheduler else
            "the local Dask cluster was lost")

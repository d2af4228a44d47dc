"""Running a sweep: the pending cases in batches on the Dask client, each finished batch
saved the moment it arrives, then the consolidated table."""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pounding.studies.sweep.cluster import _auto_batch, _client
from pounding.studies.sweep.execute import _run_batch, warm_up
from pounding.studies.sweep.plan import HISTORY_FORMATS, Sweep, load_sweep
from pounding.studies.sweep.store import (
    HISTORIES_DIR,
    PARTS_DIR,
    _part_name,
    _prepare_out,
    _read_parts,
    _remove_temporaries,
    _write_history,
    _write_part,
)
from pounding.studies.sweep.table import _write_results

__all__ = ["SweepOutcome", "run_sweep"]


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

    @property
    def rate(self) -> float:
        """Cases run per second of :attr:`run_time`."""
        return self.n_run / self.run_time if self.run_time > 0 else float("nan")


def run_sweep(sweep: Sweep | str | os.PathLike[str], out: str | os.PathLike[str] | None = None,
              *, scheduler: str | None = None, n_workers: int | None = None,
              batch_size: int | None = None, overwrite: bool = False,
              histories: str | None | bool = None,
              progress: Callable[[int, int], None] | None = None) -> SweepOutcome:
    """Run the missing cases of a sweep and write ``results.parquet``.

    Parameters
    ----------
    sweep : Sweep or path
        A sweep (:func:`load_sweep`) or its file.
    out : path-like, optional
        Output folder (default: ``out`` of the sweep file, relative to it).
    scheduler : str, optional
        None: a local Dask cluster (``n_workers`` processes, one thread each);
        ``"tcp://host:8786"``: that Dask scheduler; ``"synchronous"``: in this process.
    n_workers : int, optional
        Workers of the local cluster (default: the CPU count).
    batch_size : int, optional
        Cases per task (default from the sweep file, else automatic).
    overwrite : bool
        Start afresh even if ``out`` holds this sweep (partly) done, or another sweep.
    histories : {"netcdf", "zarr"} or False, optional
        Write every case's time histories (default from the sweep file).
    progress : callable, optional
        Called with ``(cases done, cases in all)`` as batches finish.

    Returns
    -------
    SweepOutcome
    """
    start = time.perf_counter()
    if not isinstance(sweep, Sweep):
        sweep = load_sweep(sweep)
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
    _prepare_out(sweep, out_dir, overwrite)
    parts = out_dir / PARTS_DIR
    parts.mkdir(exist_ok=True)
    _remove_temporaries(out_dir)
    hist_dir = out_dir / HISTORIES_DIR
    done = _read_parts(parts)
    wanted = {c.id for c in sweep.cases}
    pending = [c for c in sweep.cases if c.id not in done]
    n_total = len(sweep.cases)
    n_done = sum(1 for cid in done if cid in wanted)
    if progress is not None:
        progress(n_done, n_total)
    payload = {"base": sweep.base, "base_dir": str(sweep.base_dir), "params": sweep.params,
               "histories": hist}
    n_run = 0
    run_time = 0.0
    workers = 1
    bsize = batch_size or sweep.batch_size or 1
    if pending:
        with _client(scheduler, n_workers) as client:
            workers = max(1, len(client.scheduler_info(n_workers=-1)["workers"])) \
                if client is not None else 1
            bsize = batch_size or sweep.batch_size or _auto_batch(len(pending), workers)
            batches = [[(c.index, c.id, c.values) for c in pending[i:i + bsize]]
                       for i in range(0, len(pending), bsize)]
            if client is not None:
                client.run(warm_up)
            t0 = time.perf_counter()

            def finish(results: list[tuple[str, dict[str, Any], Any]]) -> None:
                nonlocal n_done, n_run
                if hist is not None:
                    for cid, row, ds in results:
                        if ds is not None:
                            _write_history(hist_dir, cid, ds, hist)
                _write_part(parts, [(cid, row) for cid, row, _ in results])
                for cid, row, _ in results:
                    done[cid] = {"case_id": cid, **row}
                n_done += len(results)
                n_run += len(results)
                if progress is not None:
                    progress(n_done, n_total)

            if client is None:
                for b in batches:
                    finish(_run_batch(payload, b))
            else:
                from distributed import as_completed

                [remote] = client.scatter([payload], broadcast=True, hash=False)
                futures = [client.submit(_run_batch, remote, b, pure=False,
                                         key=f"sweep-{_part_name([x[1] for x in b])[5:21]}")
                           for b in batches]
                try:
                    for fut in as_completed(futures):
                        finish(fut.result())
                        fut.release()
                except BaseException:
                    client.cancel(futures)
                    raise
            run_time = time.perf_counter() - t0
    results, n_err = _write_results(sweep, done, out_dir)
    return SweepOutcome(out_dir=out_dir, results=results, n_cases=n_total, n_run=n_run,
                        n_errors=n_err, wall_time=time.perf_counter() - start,
                        run_time=run_time, n_workers=workers, batch_size=bsize)

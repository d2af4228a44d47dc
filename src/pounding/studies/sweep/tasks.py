"""Independent runs on the sweep's Dask client: the execution path of the studies whose
runs are not sweep cases (``pounding mitigate``, ``pounding gap``).

:func:`run_tasks` calls one function on every task, in this process (the default: a study
of a few dozen runs takes less time than starting a cluster), on a local Dask cluster of
``n_workers`` processes, or on a running Dask scheduler — the same client, workers and
quiet stop as a sweep (:func:`pounding.studies.sweep.cluster._client`). Results come back
in the order of the tasks; nothing is saved on the way (these studies write their output
once, when every run is done).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import Any, TypeVar

from pounding.progress import Progress

__all__ = ["IN_PROCESS", "run_tasks"]

T = TypeVar("T")

IN_PROCESS: tuple[str, ...] = ("synchronous", "sync", "none")
"""Values of ``scheduler`` that mean "in this process", as for a sweep."""


def run_tasks(func: Callable[..., T], tasks: Iterable[Sequence[Any]], *,
              scheduler: str | None = None, n_workers: int | None = None,
              progress: Progress | None = None) -> list[T]:
    """``[func(*task) for task in tasks]``, in this process or on Dask.

    Parameters
    ----------
    func : callable
        A module-level function (it is sent to the workers by reference).
    tasks : iterable of sequences
        The arguments of each call.
    scheduler : str, optional
        The address of a running Dask scheduler (``tcp://host:8786``), or
        ``"synchronous"``: in this process. Default: a local cluster if ``n_workers`` is
        given, else this process.
    n_workers : int, optional
        Workers of a local Dask cluster (one thread each).
    progress : Progress, optional
        Called as ``progress(done, total)``: calls finished, and in all.

    Returns
    -------
    list
        The results, in the order of ``tasks``.

    Raises
    ------
    ValueError
        No scheduler answers at ``scheduler``; or the first exception a call raised
        (the others are cancelled).
    """
    todo = [tuple(t) for t in tasks]
    total = len(todo)
    if progress is not None:
        progress(0, total)
    if scheduler in IN_PROCESS or (scheduler is None and n_workers is None) or total == 0:
        results = []
        for k, args in enumerate(todo):
            results.append(func(*args))
            if progress is not None:
                progress(k + 1, total)
        return results
    from distributed import as_completed

    from pounding.studies.sweep.cluster import _client
    from pounding.studies.sweep.execute import _start_local_worker, warm_up

    with _client(scheduler, n_workers) as client:
        client.run(_start_local_worker if scheduler is None else warm_up)
        futures = [client.submit(func, *args, pure=False) for args in todo]
        where = {f.key: k for k, f in enumerate(futures)}
        out: list[Any] = [None] * total
        for done, fut in enumerate(as_completed(futures), start=1):
            out[where[fut.key]] = fut.result()  # the call's own exception, if it raised
            fut.release()
            if progress is not None:
                progress(done, total)
        return out

"""The packages only sweeps need, and one line saying how to get them.

Dask (``distributed``) runs a sweep's cases and pyarrow writes and reads its Parquet
tables; neither is needed by a single run, so both come with the ``sweep`` extra
(``pip install "pounding[sweep]"``, README) rather than with every install. A sweep, a
fragility study or a read of a sweep's table on an install without them stops before
anything is done, with one line naming the extra.
"""

from __future__ import annotations

import importlib.util

__all__ = ["SWEEP_EXTRA", "require_sweep_packages"]

SWEEP_EXTRA = 'pip install "pounding[sweep]"'
"""How to install what sweeps need."""


def require_sweep_packages(what: str, dask: bool = True) -> None:
    """Refuse ``what`` (``"a sweep"``) in one line if the packages of the sweep extra are
    not installed: pyarrow, and with ``dask`` Dask's ``distributed``. Nothing is imported
    here (``importlib.util.find_spec``).

    Raises
    ------
    ValueError
        ``a sweep needs pyarrow and distributed (Dask), which come with the sweep extra:
        pip install "pounding[sweep]"``
    """
    names = {"pyarrow": "pyarrow", "distributed": "distributed (Dask)"}
    wanted = ["pyarrow", "distributed"] if dask else ["pyarrow"]
    missing = [names[m] for m in wanted if importlib.util.find_spec(m) is None]
    if missing:
        verb = "comes" if len(missing) == 1 else "come"
        raise ValueError(f"{what} needs {' and '.join(missing)}, which {verb} with the sweep "
                         f"extra: {SWEEP_EXTRA}")

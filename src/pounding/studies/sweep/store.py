"""The output folder of a sweep: its manifest, the parts of finished cases and the time
histories, each written under a temporary name and renamed, so a file is whole or absent.

Layout::

    <out>/sweep.json                  the manifest: name, fingerprint, parameters, cases
    <out>/parts/part-<hash>.parquet   one per finished batch (rows keyed by case id)
    <out>/histories/<case_id>.nc      time histories of a case (or .zarr), if asked for
    <out>/results.parquet             the consolidated table (:mod:`.table`)
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import shutil
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from pounding.studies.sweep.plan import Sweep

__all__ = ["HISTORIES_DIR", "MANIFEST_FILE", "PARTS_DIR", "RESULTS_FILE"]

RESULTS_FILE = "results.parquet"
PARTS_DIR = "parts"
HISTORIES_DIR = "histories"
MANIFEST_FILE = "sweep.json"


def _check_out(sweep: Sweep, out: Path, overwrite: bool) -> bool:
    """Whether ``out`` holds ``sweep`` to resume; refuse what cannot be its output folder.

    Nothing is written: a sweep that cannot start (no scheduler answers, say) leaves the
    folder as it was.

    Raises
    ------
    ValueError
        One line: ``out`` cannot be made or written (a file on its path, a read-only
        folder), is a file, holds another sweep (without ``overwrite``), or is a non-empty
        folder that is not a sweep's.
    """
    from pounding.io import check_writable

    check_writable(out, inside=True)
    if not out.exists():
        return False
    if not out.is_dir():
        raise ValueError(f"out: {out} exists and is not a folder")
    manifest = out / MANIFEST_FILE
    if manifest.is_file():
        old = json.loads(manifest.read_text(encoding="utf-8")).get("fingerprint")
        if old != sweep.fingerprint and not overwrite:
            raise ValueError(f"out: {out} holds the results of another sweep (its base "
                             "model or cases differ); give --overwrite to start afresh "
                             "or choose another --out")
        return not overwrite
    if any(out.iterdir()):
        raise ValueError(f"out: {out} is a non-empty folder that is not a sweep output "
                         f"(no {MANIFEST_FILE}); choose another --out")
    return False


def _prepare_out(sweep: Sweep, out: Path, resume: bool, created: list[Path]) -> None:
    """Make ``out`` ready (checked by :func:`_check_out`): unless resuming, remove an
    earlier sweep's files and write the manifest; make the parts folder. What it creates
    (folders, the manifest) is appended to ``created`` as it goes, for
    :func:`_remove_created`."""
    from pounding.io import make_folders, write_text

    created += make_folders(out)
    manifest = out / MANIFEST_FILE
    if not resume:
        for name in (PARTS_DIR, HISTORIES_DIR, RESULTS_FILE, MANIFEST_FILE):
            target = out / name
            if target.is_dir():
                shutil.rmtree(target)
            elif target.exists():
                target.unlink()
        write_text(manifest, json.dumps(
            {"name": sweep.name, "fingerprint": sweep.fingerprint, "params": list(sweep.params),
             "n_cases": len(sweep.cases), "source": str(sweep.source) if sweep.source else None},
            indent=2))
        created.append(manifest)
    parts = out / PARTS_DIR
    if not parts.is_dir():
        parts.mkdir()
        created.append(parts)


def _remove_created(out: Path, created: list[Path]) -> None:
    """After a sweep stopped with no case saved: remove what :func:`_prepare_out` created
    (the folder, if it made it), so the folder is as it was. Nothing else is touched: a
    part, a history or a file of an earlier sweep keeps the folder."""
    from pounding.io import remove_empty_folders

    parts = out / PARTS_DIR
    if parts in created:
        with contextlib.suppress(OSError):
            parts.rmdir()  # only if empty
    manifest = out / MANIFEST_FILE
    if manifest in created and [p.name for p in out.iterdir()] == [MANIFEST_FILE]:
        manifest.unlink()
    remove_empty_folders([p for p in created if p not in (parts, manifest)])


def _saved_ids(folder: Path) -> set[str]:
    """The ids of the cases saved in the part files of ``folder`` (their id column only)."""
    import pyarrow.parquet as pq

    ids: set[str] = set()
    for p in folder.glob("part-*.parquet") if folder.is_dir() else ():
        with contextlib.suppress(Exception):
            ids.update(pq.read_table(p, columns=["case_id"]).column("case_id").to_pylist())
    return ids


def _remove_temporaries(out: Path) -> None:
    """Remove what a killed run left half-written: temporaries in ``parts`` and
    ``histories`` (their names start with a dot)."""
    parts = out / PARTS_DIR
    for stale in parts.glob(".*"):  # temporaries of a killed run
        if stale.is_dir():
            shutil.rmtree(stale, ignore_errors=True)
        else:
            stale.unlink(missing_ok=True)
    hist_dir = out / HISTORIES_DIR
    if hist_dir.is_dir():
        for stale in hist_dir.glob(".*"):
            shutil.rmtree(stale, ignore_errors=True) if stale.is_dir() else stale.unlink()


def _part_name(ids: Sequence[str]) -> str:
    """The file name of the part holding the cases ``ids`` (the same for the same cases)."""
    return "part-" + hashlib.sha256("".join(sorted(ids)).encode()).hexdigest()[:16] + ".parquet"


def _write_part(folder: Path, rows: list[tuple[str, dict[str, Any]]]) -> Path:
    """Write the rows of finished cases as one part file (atomically, synced to disk)."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    from pounding.io import atomic_path

    records = [{"case_id": cid, **row} for cid, row in rows]
    cols: dict[str, list[Any]] = {}
    for rec in records:
        for k in rec:
            cols.setdefault(k, [])
    table = pa.table({k: pa.array([rec.get(k) for rec in records]) for k in cols})
    target = folder / _part_name([cid for cid, _ in rows])
    with atomic_path(target) as tmp:
        pq.write_table(table, tmp)
        with open(tmp, "rb") as fh:
            os.fsync(fh.fileno())
    return target


def _read_parts(folder: Path) -> dict[str, dict[str, Any]]:
    """Rows of every complete part file, by case id (first copy wins)."""
    import pyarrow.parquet as pq

    rows: dict[str, dict[str, Any]] = {}
    if not folder.is_dir():
        return rows
    for p in sorted(folder.glob("part-*.parquet")):
        try:
            recs = pq.read_table(p).to_pylist()
        except Exception:  # noqa: BLE001  (cannot happen with atomic writes; be safe)
            p.unlink(missing_ok=True)
            continue
        for rec in recs:
            rows.setdefault(rec["case_id"], rec)
    return rows


def _write_history(folder: Path, cid: str, ds: Any, fmt: str) -> None:
    """Write a case's time histories as ``<cid>.nc`` or ``<cid>.zarr`` (atomically)."""
    from pounding.io import atomic_path

    folder.mkdir(parents=True, exist_ok=True)
    if fmt == "netcdf":
        with atomic_path(folder / f"{cid}.nc") as tmp:
            ds.to_netcdf(tmp, engine="h5netcdf")
    else:
        import tempfile

        target = folder / f"{cid}.zarr"
        tmp = Path(tempfile.mkdtemp(prefix=f".{cid}.zarr.part-", dir=folder))
        try:
            ds.to_zarr(tmp / "store.zarr", mode="w")
            if target.exists():
                shutil.rmtree(target)
            os.replace(tmp / "store.zarr", target)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)

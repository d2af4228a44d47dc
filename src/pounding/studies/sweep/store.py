"""The output folder of a sweep: its manifest, the parts of finished cases and the time
histories, each written under a temporary name and renamed, so a file is whole or absent.

Layout::

    <out>/.pounding-manifest.jsonl    every file pounding wrote here (:mod:`pounding.io.manifest`)
    <out>/sweep.json                  the sweep: name, fingerprint, parameters, cases
    <out>/parts/part-<hash>.parquet   one per finished batch (rows keyed by case id)
    <out>/histories/<case_id>.nc      time histories of a case (or .zarr), if asked for
    <out>/results.parquet             the consolidated table (:mod:`.table`)

Each file is recorded in the manifest when complete, before it is moved into place;
``--overwrite`` removes only what the manifest lists (and refuses a folder holding
anything else), and a run removes only the temporaries of pounding processes no longer
running.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pounding.io.manifest import Manifest

if TYPE_CHECKING:
    from pounding.studies.sweep.sweep_file import Sweep

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
        folder), is a file, holds another sweep (without ``overwrite``), is a non-empty
        folder that is not a sweep's, or (with ``overwrite``) holds something pounding did
        not write (:func:`pounding.io.manifest.check_replaceable`).
    """
    from pounding.io.files import check_writable
    from pounding.io.manifest import check_replaceable

    check_writable(out, inside=True)
    if not out.exists() and not out.is_symlink():
        return False
    if not out.is_dir() or out.is_symlink():
        raise ValueError(f"out: {out} exists and is not a folder")
    manifest = out / MANIFEST_FILE
    if manifest.is_file():
        try:
            old = json.loads(manifest.read_text(encoding="utf-8")).get("fingerprint")
        except (ValueError, AttributeError, OSError):
            raise ValueError(f"out: {out} holds a {MANIFEST_FILE} that is not a sweep's; "
                             "choose another --out") from None
        if old != sweep.fingerprint and not overwrite:
            raise ValueError(f"out: {out} holds the results of another sweep (its base "
                             "model or cases differ); give --overwrite to start afresh "
                             "or choose another --out")
        if overwrite:
            check_replaceable(out, "sweep")
        return not overwrite
    if any(out.iterdir()):
        raise ValueError(f"out: {out} is a non-empty folder that is not a sweep output "
                         f"(no {MANIFEST_FILE}); choose another --out")
    return False


def _prepare_out(sweep: Sweep, out: Path, resume: bool, created: list[Path],
                 histories: bool = False) -> None:
    """Make ``out`` ready (checked by :func:`_check_out`): remove the temporaries of killed
    runs; unless resuming, remove an earlier sweep's files (those its manifest lists) and
    write a new manifest and ``sweep.json``; make the parts folder. What it creates
    (folders, files) is appended to ``created`` as it goes, for :func:`_remove_created`."""
    from pounding.io.files import make_folders
    from pounding.io.manifest import remove_outputs

    created += make_folders(out)
    _remove_temporaries(out)
    man = Manifest(out)
    if not resume:
        if man.exists():
            remove_outputs(out, keep_folder=True)
        man.start("sweep")
        created.append(man.path)
        man.write_text(out / MANIFEST_FILE, json.dumps(
            {"name": sweep.name, "fingerprint": sweep.fingerprint, "params": list(sweep.params),
             "n_cases": len(sweep.cases), "source": str(sweep.source) if sweep.source else None},
            indent=2))
        created.append(out / MANIFEST_FILE)
    elif not man.exists():  # a sweep written before manifests: list what is added now
        man.start("sweep")
    for name in (PARTS_DIR, HISTORIES_DIR) if histories else (PARTS_DIR,):
        if not (out / name).is_dir():
            (out / name).mkdir()
            created.append(out / name)


def _remove_created(out: Path, created: list[Path]) -> None:
    """After a sweep stopped with no case saved: remove what :func:`_prepare_out` created
    (the folder, if it made it), so the folder is as it was. Nothing else is touched: a
    part, a history or a file of an earlier sweep keeps the folder."""
    from pounding.io.files import remove_empty_folders

    folders = [out / PARTS_DIR, out / HISTORIES_DIR]
    for folder in folders:
        if folder in created:
            with contextlib.suppress(OSError):
                folder.rmdir()  # only if empty
    made = {p for p in created if p.parent == out and p not in folders}
    if made and {p for p in out.iterdir()} == made:
        for p in made:
            p.unlink()
    remove_empty_folders([p for p in created if p not in folders and p not in made])


def _saved_ids(folder: Path) -> set[str]:
    """The ids of the cases saved in the part files of ``folder`` (their id column only)."""
    import pyarrow.parquet as pq

    ids: set[str] = set()
    for p in folder.glob("part-*.parquet") if folder.is_dir() else ():
        with contextlib.suppress(Exception):
            ids.update(pq.read_table(p, columns=["case_id"]).column("case_id").to_pylist())
    return ids


def _remove_temporaries(out: Path) -> None:
    """Remove what killed runs left half-written in ``out``, ``parts`` and ``histories``
    (:func:`pounding.io.output_folder.remove_stale`: temporaries named with the pid of a pounding
    process no longer running, e.g. ``.results.parquet.part-<pid>-XXXXXXXX.parquet``)."""
    from pounding.io.output_folder import remove_stale

    for folder in (out, out / PARTS_DIR, out / HISTORIES_DIR):
        remove_stale(folder)


def _part_name(ids: Sequence[str]) -> str:
    """The file name of the part holding the cases ``ids`` (the same for the same cases)."""
    return "part-" + hashlib.sha256("".join(sorted(ids)).encode()).hexdigest()[:16] + ".parquet"


def _write_part(out: Path, rows: list[tuple[str, dict[str, Any]]]) -> Path:
    """Write the rows of finished cases as one part file in ``out/parts`` (atomically,
    synced to disk, recorded in the manifest of ``out``)."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    records = [{"case_id": cid, **row} for cid, row in rows]
    cols: dict[str, list[Any]] = {}
    for rec in records:
        for k in rec:
            cols.setdefault(k, [])
    table = pa.table({k: pa.array([rec.get(k) for rec in records]) for k in cols})
    target = out / PARTS_DIR / _part_name([cid for cid, _ in rows])
    with Manifest(out).write(target) as tmp:
        pq.write_table(table, tmp)
        with open(tmp, "rb") as fh:
            os.fsync(fh.fileno())
    return target


def _read_parts(folder: Path) -> dict[str, dict[str, Any]]:
    """Rows of every complete part file, by case id (first copy wins); a part that cannot
    be read is left as it is and its cases run again."""
    import pyarrow.parquet as pq

    rows: dict[str, dict[str, Any]] = {}
    if not folder.is_dir():
        return rows
    for p in sorted(folder.glob("part-*.parquet")):
        try:
            recs = pq.read_table(p).to_pylist()
        except Exception:  # noqa: BLE001  (cannot happen with atomic writes; be safe)
            continue
        for rec in recs:
            rows.setdefault(rec["case_id"], rec)
    return rows


def _write_history(out: Path, cid: str, ds: Any, fmt: str) -> None:
    """Write a case's time histories as ``out/histories/<cid>.nc`` or ``<cid>.zarr``
    (atomically, recorded in the manifest of ``out``). NetCDF is serialised in memory and
    written with plain file I/O, so HDF5 never meets a full disk."""
    from pounding.io.files import WriteFailed

    folder = out / HISTORIES_DIR
    folder.mkdir(parents=True, exist_ok=True)
    man = Manifest(out)
    if fmt == "netcdf":
        man.write_bytes(folder / f"{cid}.nc", ds.to_netcdf(engine="h5netcdf"))
        return
    from pounding.io.output_folder import make_temporary_folder, remove_temporary_folder

    target = folder / f"{cid}.zarr"
    man.check_free(target)  # (a folder there is refused)
    tmp = make_temporary_folder(folder, f"{cid}.zarr", "part", holds=["store.zarr/**"])
    try:
        store = tmp / "store.zarr"
        try:
            ds.to_zarr(store, mode="w")
        except OSError as exc:
            from pounding.io.files import failure_reason

            reason, code = failure_reason(exc)
            raise WriteFailed(target, reason, code) from None
        man.append(man.entry_of(target / p.relative_to(store), p)
                   for p in sorted(store.rglob("*")) if p.is_file() and not p.is_symlink())
        os.replace(store, target)
    finally:
        remove_temporary_folder(tmp)

"""Comparing retrofit options for one building pair: bare gap, bumpers, links.

``pounding mitigate STUDY.toml`` (docs/mitigation.md). A study file names a base model, the
records, and the options — each a list of ``[[option.device]]`` tables added to the base
model's own devices (none: the bare gap)::

    base = "two_10_storey.toml"
    records = ["el_centro", "kobe_1995_KJMA_000_RSN1106"]   # default: the base's record
    [[option]]
    name = "bare gap"
    [[option]]
    name = "bumpers 20 mm"
    [[option.device]]
    type = "bumper"
    floors = "all"
    thickness = 0.02
    compression_limit = 0.7
    rubber = { law = "hertzdamp", k_h = 1e8, e = 0.5 }

Each option runs under each record (:func:`pounding.simulate`, one process: a few dozen runs
of a few ms to a few tens of ms). The answers are the engineer's trade-off: what each option
does to the impacts (number, peak force of the buildings' own contacts, and of the pads),
to the storeys (peak drift ratio, storey shear) and to the floors (peak absolute
acceleration: soft pads lower the impact forces but can raise accelerations), and the
energy each kind of device dissipates.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import numpy as np
from pydantic import Field, ValidationError

from pounding.config.base import Section
from pounding.config.device import DeviceConfig
from pounding.config.quantities import Step
from pounding.progress import Progress

if TYPE_CHECKING:
    import pandas as pd

    from pounding.result import Result

__all__ = ["BRIDGE_MEASURES", "MEASURES", "MitigationOutcome", "MitigationStudy", "OptionConfig",
           "load_mitigation", "measure_row", "run_mitigation", "summarise"]

MEASURES: dict[str, str] = {
    "n_impacts": "impacts of the buildings' own contacts",
    "peak_impact_force_N": "largest force of the buildings' own contacts [N]",
    "n_pad_impacts": "impacts on bumper pads",
    "peak_pad_force_N": "largest force on a bumper pad [N]",
    "peak_drift_ratio": "largest storey drift / storey height",
    "peak_storey_shear_N": "largest storey shear [N]",
    "peak_abs_accel_m_s2": "largest absolute floor acceleration [m/s²]",
    "contact_dissipated_J": "energy dissipated in the buildings' contacts [J]",
    "pads_dissipated_J": "energy dissipated by bumper pads [J]",
    "links_dissipated_J": "energy dissipated by links [J]",
    "peak_link_force_N": "largest |force| of any link [N]",
}
"""Columns of the comparison table, each for one option under one record."""

BRIDGE_MEASURES: dict[str, str] = {
    "peak_seat_opening_m": "largest opening of any seat (joints and abutments) [m]",
    "peak_joint_opening_m": "largest opening of any expansion joint [m]",
    "peak_pier_shear_N": "largest shear of any pier [N]",
    "peak_bearing_displacement_m": "largest displacement of any bearing [m]",
}
"""Columns added for a bridge (:mod:`pounding.structure.bridge`): its seats' openings —
what unseats a deck (:func:`pounding.result.bridge_seats.seat_openings`) — and its piers'
and bearings' peaks (:attr:`pounding.result.Result.bridge_elements`). A bridge's frames
have no storeys: its ``peak_storey_shear_N`` is empty, its ``peak_drift_ratio`` that of
the decks (their displacement over the deck's elevation)."""


class OptionConfig(Section):
    """``[[option]]``: a retrofit option, its ``name`` and its ``device`` tables."""

    name: Annotated[str, Field(min_length=1)]
    device: list[DeviceConfig] = []


class MitigationStudy(Section):
    """A study file (module docstring)."""

    name: str = "mitigation"
    base: str
    out: str | None = None
    records: Annotated[list[Annotated[str, Field(min_length=1)]],
                       Field(min_length=1)] | None = None
    dt: Step | None = None
    """Time step [s] of the ``records`` files that do not state one (plain text)."""
    units: str | None = None
    """Acceleration unit of the ``records`` files that do not state one (a plain-text record
    needs it: ``"g"``, ``"m/s2"``, ``"cm/s2"``, ...)."""
    option: Annotated[list[OptionConfig], Field(min_length=1)]


@dataclass
class MitigationOutcome:
    """What :func:`run_mitigation` did: the table of every run, its summary per option, and
    where they were written."""

    table: "pd.DataFrame"
    summary: "pd.DataFrame"
    out_dir: Path | None = None
    files: dict[str, Path] = field(default_factory=dict)


def load_mitigation(path: str | os.PathLike[str]) -> tuple[MitigationStudy, Path]:
    """Read and check a study file; the folder its paths are relative to."""
    from pounding.config.errors import format_validation_error
    from pounding.io.files import read_toml

    p = Path(path)
    data = read_toml(p, "mitigation study file")
    try:
        return MitigationStudy.model_validate(data), p.resolve().parent
    except ValidationError as exc:
        raise ValueError(format_validation_error(exc, prefix=f"{p}: ",
                                                 root=MitigationStudy)) from None


def _configs(study: MitigationStudy, here: Path, where: str = "study"
             ) -> list[tuple[str, str, Any]]:
    """``(option, record, RunConfig)`` of every run, each checked by building it.

    Raises
    ------
    ValueError
        One line naming the study's key (``records[1]``, ``option[2].device[0].c``) or the
        base model's.
    """
    from pounding.config import load_config, parse_config

    names = [o.name for o in study.option]
    for j, name in enumerate(names):
        if name in names[:j]:
            raise ValueError(f"{where}: option[{j}].name: two options are called {name!r}; "
                             "name them apart")
    base_file = (here / study.base).resolve()
    base = load_config(base_file)
    data = base.to_dict(resolve_paths=True)
    records: list[dict[str, Any]] = [data["record"]]
    if study.records:
        keep = {k: v for k, v in data["record"].items()
                if k not in ("file", "bundled", "dt", "units")}
        own = {k: v for k, v in (("dt", study.dt), ("units", study.units)) if v is not None}
        records = []
        for k, name in enumerate(study.records):
            rec = _record(name, k, here, where) | keep
            records.append(rec | own if "file" in rec else rec)
    base_devices = len(data.get("device", []))
    runs = []
    for i, opt in enumerate(study.option):
        devices = data.get("device", []) + [d.model_dump(exclude_unset=True)
                                            for d in opt.device]
        for k, rec in enumerate(records):
            case = dict(data, record=rec, device=devices)
            try:
                cfg = parse_config(case, base_file.parent, where=str(base_file))
            except ValueError as exc:
                raise ValueError(_case_error(str(exc).removeprefix(f"{base_file}: "), i, k,
                                             base_devices, bool(study.records), where,
                                             base_file)) from None
            label = rec.get("bundled") or Path(rec["file"]).stem
            runs.append((opt.name, str(label), cfg))
    return runs


def _record(name: str, k: int, here: Path, where: str) -> dict[str, Any]:
    """``records[k]`` as the ``[record]`` table of a model: a file (relative to the study
    file) if there is one, else a bundled record."""
    from pounding.config import EL_CENTRO_ALIASES
    from pounding.ground_motion import bundled_files

    path = here / Path(name).expanduser()
    if path.is_file():
        return {"file": str(path.resolve())}
    stems = {Path(f).stem for f in bundled_files()}
    if name.lower() in EL_CENTRO_ALIASES or name in stems or name in bundled_files():
        return {"bundled": name}
    what = "a folder" if path.is_dir() else "no such file"
    raise ValueError(f"{where}: records[{k}]: {name!r} is {what} ({path.resolve()}; relative "
                     f"paths start at the study file's folder) and no bundled record; bundled "
                     f"records: {', '.join(['el_centro', *sorted(stems)])}")


def _case_error(text: str, option: int, record: int, base_devices: int, own_records: bool,
                where: str, base_file: Path) -> str:
    """A run's validation error named by the study's key: its option's device, its record,
    or (else) the base model's key."""
    import re

    found = re.match(r"device\[(\d+)\]", text)
    if found and int(found[1]) >= base_devices:
        return (f"{where}: option[{option}].device[{int(found[1]) - base_devices}]"
                + text[found.end():])
    if own_records and text.startswith("record"):
        return f"{where}: records[{record}]{text[len('record'):]}"
    return f"{where}: option[{option}] on the base model {base_file}: {text}"


def measure_row(result: "Result") -> dict[str, float]:
    """The :data:`MEASURES` of one run (and, for a bridge, its :data:`BRIDGE_MEASURES`)."""
    return {**_measures(result), **_bridge_row(result)}


def _measures(result: "Result") -> dict[str, float]:
    """The :data:`MEASURES` of one run."""
    from pounding.result.foundations import footing_dofs

    contacts = result.model.contacts
    pads = np.array([c.tag == "bumper" for c in contacts], dtype=bool)
    pcf = result.peak_contact_force
    counts = result.impacts_per_contact
    diss = result.dissipated_per_contact
    links = result.model.links
    return {
        "n_impacts": int(counts[~pads].sum()),
        "peak_impact_force_N": float(pcf[~pads].max()) if (~pads).any() else 0.0,
        "n_pad_impacts": int(counts[pads].sum()),
        "peak_pad_force_N": float(pcf[pads].max()) if pads.any() else 0.0,
        # storeys only: NaN under a base slab (its bearing) and where there is no storey
        # shear (buildings given as matrices, frames): NaN when no building has one
        "peak_drift_ratio": _largest(result.peak_drift_ratio),
        "peak_storey_shear_N": _largest(result.peak_storey_shear[~result.is_bearing]),
        # floors only: a footing's sway and rocking are DOFs, no floors
        "peak_abs_accel_m_s2": float(np.max(np.delete(result.peak_abs_acceleration,
                                                      footing_dofs(result.model)))),
        "contact_dissipated_J": float(np.nansum(diss[~pads])),
        "pads_dissipated_J": float(np.nansum(diss[pads])),
        "links_dissipated_J": float(result.energy[-1, 7]) if links else 0.0,
        "peak_link_force_N": float(result.link_peak_force.max()) if links else 0.0,
    }


def _bridge_row(result: "Result") -> dict[str, float]:
    """A bridge's :data:`BRIDGE_MEASURES` of one run; ``{}`` for buildings."""
    from pounding.studies.sweep.bridge_measures import is_bridge

    if not is_bridge(result.model):
        return {}
    from pounding.result.bridge_seats import seat_openings

    names, openings = seat_openings(result)
    joints = [i for i, n in enumerate(names) if n.startswith("J")]
    elements = result.bridge_elements
    return {
        "peak_seat_opening_m": float(max(openings.max(), 0.0)),
        "peak_joint_opening_m": float(max(openings[:, joints].max(), 0.0)) if joints else 0.0,
        "peak_pier_shear_N": _largest([e.peak_force for e in elements if e.kind == "pier"]),
        "peak_bearing_displacement_m": _largest([e.peak_deformation for e in elements
                                                 if e.kind != "pier"]),
    }


def _largest(values: Any) -> float:
    """The largest value that is not NaN; NaN if there is none (no warning)."""
    v = np.asarray(values, dtype=float)
    v = v[~np.isnan(v)]
    return float(v.max()) if v.size else float("nan")


def summarise(table: "pd.DataFrame") -> "pd.DataFrame":
    """Per option (in the study's order), the mean of every measure over the records."""
    order = list(dict.fromkeys(table["option"]))
    columns = list(MEASURES) + [c for c in BRIDGE_MEASURES if c in table.columns]
    out = table.groupby("option", sort=False)[columns].mean()
    out.insert(0, "records", table.groupby("option", sort=False)["record"].count())
    return out.loc[order]


MITIGATION_FILES: tuple[str, ...] = ("runs.csv", "summary.csv", "study.toml", "mitigation.png")
"""The files of a study's output folder (and its manifest, :mod:`pounding.io.manifest`)."""


def _out_folder(study: MitigationStudy, here: Path, out: str | os.PathLike[str] | None,
                where: str, file: Path) -> Path:
    """The output folder: ``out`` given (``--out``), else ``out`` of the study file —
    inside the file's folder (:func:`pounding.io.files.study_out`) — else ``<file stem>-results``
    in the current folder (:func:`pounding.io.output_folder.default_out_dir`); the name is a
    label (:func:`pounding.io.files.check_label`)."""
    from pounding.io.files import check_label, study_out
    from pounding.io.output_folder import default_out_dir

    check_label(study.name, where)
    if out is not None:
        folder = Path(out)
    elif study.out is None:
        folder = default_out_dir(file)
    else:
        folder, refused = study_out(here, study.out, where)
        if refused is not None:
            raise ValueError(refused)
    if folder.name in ("", ".", ".."):
        raise ValueError(f"out: {folder} is not a folder name; give e.g. --out results")
    return folder


def _check_target(out_dir: Path, overwrite: bool) -> None:
    """Refuse an output folder that is a file, or one that holds anything unless
    ``overwrite`` and it holds only an earlier study's files (its manifest)."""
    from pounding.io.manifest import check_replaceable

    if out_dir.exists() or out_dir.is_symlink():
        if not out_dir.is_dir() or out_dir.is_symlink():
            raise ValueError(f"out: {out_dir} exists and is not a folder; choose another --out")
        if any(out_dir.iterdir()):
            if not overwrite:
                raise ValueError(f"out: {out_dir} exists and is not empty; give --overwrite "
                                 "to replace an earlier study's output, or choose another "
                                 "--out")
            check_replaceable(out_dir, "mitigation")


def _measure_run(option: str, record: str, config: Any) -> dict[str, Any]:
    """One run of a study: its option, record and :data:`MEASURES` (a task of
    :func:`~pounding.studies.sweep.tasks.run_tasks`)."""
    from pounding.integrate import simulate

    model, motion, solver = config.build()
    return {"option": option, "record": record, **measure_row(simulate(model, motion,
                                                                         **solver))}


def run_mitigation(input: str | os.PathLike[str], out: str | os.PathLike[str] | None = None,
                   *, overwrite: bool = False, figures: bool | None = None,
                   progress: Progress | None = None, scheduler: str | None = None,
                   n_workers: int | None = None) -> MitigationOutcome:
    """Run a study file and write its folder: ``runs.csv`` (every option under every
    record), ``summary.csv`` (mean per option), ``study.toml`` (the file as read) and
    ``mitigation.png`` (the trade-off figure).

    The first arguments are those of every runner, in the same order (:func:`pounding.run`).
    The folder is written whole or not at all, as a run's: built beside the target and
    moved into place when complete; an earlier study's folder is replaced (``overwrite``)
    only if it holds nothing but the files its manifest lists.

    Parameters
    ----------
    input : path-like
        The study file (module docstring, ``docs/mitigation.md``).
    out : path-like, optional
        Output folder (default: ``out`` of the study file, relative to it, else ``<study
        file stem>-results`` in the current folder).
    overwrite : bool
        Replace an earlier study's output folder.
    figures : bool, optional
        Draw the trade-off figure; default yes.
    progress : Progress, optional
        Called as ``progress(done, total)``: runs finished, and runs in all
        (:class:`pounding.progress.Progress`).
    scheduler, n_workers : optional
        Where the runs go (:func:`pounding.studies.sweep.tasks.run_tasks`): by default one
        after another in this process; ``n_workers`` processes of a local Dask cluster; or
        the Dask scheduler at ``scheduler`` (``"synchronous"``: this process).

    Raises
    ------
    ValueError
        One line naming the key: a bad study file, base model, record or device; an output
        folder that cannot be used.
    """
    import pandas as pd

    from pounding.io.files import atomic_path, check_writable, write_text
    from pounding.io.output_folder import new_output_folder, remove_stale
    from pounding.plot import save_figure
    from pounding.studies.sweep.tasks import run_tasks

    path = Path(input)
    study, here = load_mitigation(path)
    where = str(path)
    out_dir = _out_folder(study, here, out, where, path)
    runs = _configs(study, here, where=where)
    check_writable(out_dir)
    remove_stale(out_dir.absolute().parent, restore=out_dir.absolute())
    if out_dir.is_dir() and not out_dir.is_symlink():
        remove_stale(out_dir)
    _check_target(out_dir, overwrite)
    study_text = path.read_text(encoding="utf-8")
    drawn = True if figures is None else figures
    rows = run_tasks(_measure_run, runs, scheduler=scheduler, n_workers=n_workers,
                     progress=progress)
    table = pd.DataFrame(rows)
    summary = summarise(table)
    names = {"runs": "runs.csv", "summary": "summary.csv", "study": "study.toml",
             "figure": "mitigation.png"}
    with new_output_folder(out_dir, "mitigation", MITIGATION_FILES,
                           check=lambda: _check_target(out_dir, overwrite)) as tmp:
        with atomic_path(tmp / names["runs"]) as f:
            table.to_csv(f, index=False)
        with atomic_path(tmp / names["summary"]) as f:
            summary.to_csv(f)
        write_text(tmp / names["study"], study_text)
        if drawn:
            from pounding.plot.mitigation import plot_mitigation

            save_figure(plot_mitigation(summary, title=study.name), tmp / names["figure"])
    files = {k: out_dir / v for k, v in names.items() if k != "figure" or drawn}
    return MitigationOutcome(table=table, summary=summary, out_dir=out_dir, files=files)

"""One self-contained HTML page for a run folder or a sweep folder (``pounding report``).

:func:`write_report` reads what ``pounding run`` or ``pounding sweep`` wrote and writes a
single HTML file: inline CSS, every figure embedded as a base64 PNG (``data:`` URI), no
script, no external link — it opens the same offline, from a mail attachment or an archive.
Every text taken from the files is HTML-escaped; every quantity carries its unit.

* A **run** folder holds ``summary.json`` and ``timehistories.nc`` (and normally
  ``impacts.csv``, ``model.toml`` and the PNG figures). The page shows the model, the record,
  the headline numbers, the figures (the PNGs of the folder, or regenerated from the NetCDF
  when the model file can be rebuilt), the impact table, the energy balance and a gap check.
* A **fragility** folder (``pounding fragility``) holds ``fragility.json`` beside its
  sweep's table: the page shows the study, the fragility of every limit state with its
  intervals, the probability of pounding against the gap beside the code gaps, the counts
  at every stripe and the study's figures (:mod:`~pounding.report.fragility`).
* A **pushover** folder (``pounding pushover``) holds ``pushover.csv`` and ``summary.json``:
  the page shows the frame, the capacity curve's numbers and figure, the curve event by
  event and the hinges (:mod:`~pounding.report.pushover`).
* A **sweep** folder holds ``results.parquet`` (one row per case: parameters and measures).
  The page shows the parameter grid, the first rows of the results with summary statistics,
  and the main measure plotted against each swept parameter.

With a code check (``pounding run/sweep/fragility ... --code-check DIR`` kept one in the
folder, or ``pounding report FOLDER --code-check DIR``), the page ends with a "Code check"
section: the code's separation level by level, and for a run the run's own peak closing
beside it (:mod:`~pounding.report.code_check`).

The report only reads the folder; it writes nothing there but the report itself (written
atomically, :func:`pounding.io.files.write_text`; ``report.html`` is added to the folder's manifest,
:mod:`pounding.io.manifest`, so that ``--overwrite`` may replace it, and an existing
``report.html`` pounding did not write is not replaced). See ``docs/report.md``.

The package, by concept: this module (what a folder is, writing the page);
:mod:`~pounding.report.run` with :mod:`~pounding.report.run_folder` (reading it),
:mod:`~pounding.report.run_inputs` (model, record), :mod:`~pounding.report.run_figures` and
:mod:`~pounding.report.run_checks` (energy balance, gap check) for the run page;
:mod:`~pounding.report.sweep` with :mod:`~pounding.report.sweep_folder` for the sweep page;
:mod:`~pounding.report.format` (numbers, units, and the blocks a section is made of:
tables, notes, figures) and :mod:`~pounding.report.page` (the page, rendered with Jinja2 from
``templates/``) for both.
"""

from __future__ import annotations

import os
from pathlib import Path

from pounding.io.files import write_text
from pounding.report.code_check import CodeCheckFile, folder_code_check, read_code_check
from pounding.report.fragility import FRAGILITY_FILE, render_fragility
from pounding.report.pushover import is_pushover, render_pushover
from pounding.report.run import MAX_IMPACT_ROWS, render_run
from pounding.report.run_folder import RUN_FILES
from pounding.report.sweep import MAX_SWEEP_ROWS, render_sweep
from pounding.report.sweep_folder import SWEEP_FILE

__all__ = ["DEFAULT_NAME", "MAX_IMPACT_ROWS", "MAX_SWEEP_ROWS", "RUN_FILES", "SWEEP_FILE",
           "detect_kind", "render_report", "write_report"]

DEFAULT_NAME = "report.html"
"""File name of the report inside the results folder when no ``out`` is given."""


def detect_kind(results_dir: str | os.PathLike[str]) -> str:
    """``"run"``, ``"sweep"``, ``"fragility"`` or ``"pushover"``: what ``results_dir`` holds.

    Parameters
    ----------
    results_dir : path-like
        The folder to look at.

    Returns
    -------
    str
        ``"run"`` for a run output, ``"fragility"`` for the output of ``pounding
        fragility`` (``fragility.json``, beside its sweep's ``results.parquet``),
        ``"pushover"`` for the output of ``pounding pushover`` (``pushover.csv`` and
        ``summary.json``), ``"sweep"`` for a sweep output.

    Raises
    ------
    ValueError
        The folder does not exist, or is neither a run output (``summary.json`` and
        ``timehistories.nc``) nor a sweep output (``results.parquet``); the message names
        the folder and the files missing.
    """
    folder = Path(results_dir)
    if not folder.is_dir():
        what = "does not exist" if not folder.exists() else "is not a folder"
        raise ValueError(f"report: {folder} {what}; give the output folder of "
                         "`pounding run` or `pounding sweep`")
    run_missing = [f for f in RUN_FILES if not (folder / f).is_file()]
    if not run_missing:
        return "run"
    if (folder / FRAGILITY_FILE).is_file():
        return "fragility"
    if is_pushover(folder):
        return "pushover"
    if (folder / SWEEP_FILE).is_file():
        return "sweep"
    raise ValueError(
        f"report: {folder} is neither a run output (missing {', '.join(run_missing)}) nor a "
        f"sweep output (missing {SWEEP_FILE}); give the output folder of `pounding run` or "
        "`pounding sweep`")


def write_report(results_dir: str | os.PathLike[str],
                 out: str | os.PathLike[str] | None = None,
                 code_check: str | os.PathLike[str] | None = None) -> Path:
    """Write the HTML report of a run or sweep folder and return its path.

    Parameters
    ----------
    results_dir : path-like
        The output folder of ``pounding run`` or ``pounding sweep`` (:func:`detect_kind`).
    out : path-like, optional
        The HTML file to write; default ``results_dir/report.html``. Written atomically.
    code_check : path-like, optional
        A folder ``pounding code-check --out`` wrote: the page's "Code check" section
        (:mod:`~pounding.report.code_check`); default the check kept in ``results_dir``
        (``pounding run ... --code-check DIR``), if any.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    ValueError
        ``results_dir`` is neither a run nor a sweep output, or a file in it is unreadable;
        ``code_check`` is not a code check's folder.
    """
    from pounding.io.manifest import Manifest

    folder = Path(results_dir)
    detect_kind(folder)  # (a bad folder is named before a bad --code-check)
    check = read_code_check(code_check) if code_check is not None else None
    target = Path(out) if out is not None else folder / DEFAULT_NAME
    if target.is_dir():
        raise ValueError(f"report: --html {target} is a folder; give a file name such as "
                         f"{target / DEFAULT_NAME}")
    # pounding's own file in its folder: listed in the manifest, so replaceable by
    # --overwrite; a file of that name pounding did not write is refused before any work
    manifest = Manifest(folder) if out is None and Manifest(folder).exists() else None
    if manifest is not None:
        manifest.check_free(target)
    text = render_report(folder) if check is None else render_report(folder, check)
    if manifest is not None:
        return manifest.write_text(target, text)
    return write_text(target, text)


def render_report(results_dir: str | os.PathLike[str],
                  code_check: CodeCheckFile | None = None) -> str:
    """The HTML text of the report of ``results_dir`` (see :func:`write_report`).

    Parameters
    ----------
    results_dir : path-like
        The output folder of ``pounding run`` or ``pounding sweep``.
    code_check : CodeCheckFile, optional
        The check of the "Code check" section (:func:`~pounding.report.code_check.
        read_code_check`); default the one kept in the folder, if any.

    Returns
    -------
    str
        The whole page.

    Raises
    ------
    ValueError
        As :func:`write_report`.
    """
    folder = Path(results_dir)
    kind = detect_kind(folder)
    if kind == "pushover":
        return render_pushover(folder)
    check = code_check if code_check is not None else folder_code_check(folder)
    if kind == "fragility":
        return render_fragility(folder, check)
    return render_run(folder, check) if kind == "run" else render_sweep(folder, check)

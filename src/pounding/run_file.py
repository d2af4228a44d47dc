"""Run a model file end to end: load, simulate, write every output into one folder.

:func:`run` never leaves a half-written output folder. Everything is written into a hidden
temporary folder beside the target (``.<name>.tmp-<pid>-XXXXXXXX``, marked as pounding's,
:func:`pounding.io.output_folder.make_temporary_folder`) with a manifest of the files written
(:mod:`pounding.io.manifest`), and moved into place only when complete; if anything fails (a
full disk, an error, Ctrl-C or SIGTERM) the temporary folder is removed and a previous
output folder is left untouched. A run killed outright (SIGKILL) cannot clean up after
itself: the next run into the same folder removes what it left (and puts back an earlier
output it was replacing) — only folders marked as made by a process no longer running.

An existing output folder is replaced only with ``overwrite=True``, and only if it is empty
or holds nothing but the files its manifest lists, unchanged (an earlier run's output):
the new folder is complete before the old one is removed, file by file.
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass
from pathlib import Path

from pounding.config import RunConfig, load_config
from pounding.integrate import simulate
from pounding.io.files import check_writable, write_text
from pounding.io.manifest import check_out_folder
from pounding.io.output_folder import default_out_dir, new_output_folder, remove_stale
from pounding.plot.registry import RUN_FIGURES
from pounding.progress import Progress
from pounding.result import Result

__all__ = ["OUTPUT_FILES", "FIGURE_FILES", "RunOutput", "default_out_dir", "run", "run_config"]

OUTPUT_FILES: dict[str, str] = {
    "timehistories": "timehistories.nc",
    "impacts": "impacts.csv",
    "summary": "summary.json",
    "model": "model.toml",
}
"""Data files of every run (key → file name)."""


FIGURE_FILES: dict[str, str] = {key: fig.file for key, fig in RUN_FIGURES.items()}
"""Every figure a run can write (key → file name); a run writes those of its model
(:func:`pounding.plot.registry.figures_for`)."""

TEMPORARY_HOLDS: tuple[str, ...] = (*OUTPUT_FILES.values(), *FIGURE_FILES.values())
"""What a run's temporary folder may hold: what a run killed outright leaves is removed by
these names (:func:`pounding.io.output_folder.remove_temporary_folder`)."""


@dataclass(frozen=True)
class RunOutput:
    """What :func:`run` produced.

    Attributes
    ----------
    out_dir : Path
        The output folder (complete).
    files : dict[str, Path]
        Every file written, by key (:data:`OUTPUT_FILES`, :data:`FIGURE_FILES`).
    result : Result
        The simulation.
    config : RunConfig
        The configuration that was run.
    wall_time : float
        Seconds from start to finish (loading, integrating, writing) [s].
    """

    out_dir: Path
    files: dict[str, Path]
    result: Result
    config: RunConfig
    wall_time: float


def _check_target(out_dir: Path, overwrite: bool) -> None:
    check_out_folder(out_dir, overwrite, "run")


def _remove_stale(out_dir: Path) -> None:
    """Remove what a run into ``out_dir`` killed outright (SIGKILL, power loss) left behind
    (:func:`pounding.io.output_folder.remove_stale`): its temporary folder beside ``out_dir``, and
    if it was killed while replacing an earlier output, put that output back. Temporaries
    in ``out_dir`` itself (of a killed ``pounding report``) go too. Only what pounding
    marked, of processes no longer running, is touched."""
    remove_stale(out_dir.absolute().parent, restore=out_dir.absolute())
    if out_dir.is_dir() and not out_dir.is_symlink():
        remove_stale(out_dir)


def _write_figures(result: Result, folder: Path, dpi: int) -> dict[str, Path]:
    from pounding.plot import save_figure
    from pounding.plot.registry import figures_for

    out = {}
    for key, fig in figures_for(result).items():
        out[key] = save_figure(fig.make(result), folder / fig.file, dpi=dpi)
    return out


def run_config(config: RunConfig, out: str | os.PathLike[str], *, overwrite: bool = False,
               figures: bool | None = None, progress: Progress | None = None) -> RunOutput:
    """Simulate an already-loaded configuration and write its outputs into ``out``.

    See :func:`run` (the same arguments, ``config`` in place of the model file).
    """
    start = time.perf_counter()
    target = Path(out)
    if target.name in ("", ".", ".."):
        raise ValueError(f"out: {out!s} is not a folder name; give e.g. --out results")
    check_writable(target)
    _remove_stale(target)
    _check_target(target, overwrite)
    model, motion, solver = config.build()
    want_figures = config.output.figures if figures is None else figures
    fraction = None
    if progress is not None:
        seconds = float(solver["duration"] if solver.get("duration") is not None
                        else motion.duration)

        def fraction(f: float) -> None:
            progress(f * seconds, seconds)

    with new_output_folder(target, "run", TEMPORARY_HOLDS,
                           check=lambda: _check_target(target, overwrite)) as tmp:
        result = simulate(model, motion, progress=fraction, **solver)
        files = result.save(tmp, warnings=config.plausibility)
        source = str(config.source) if config.source is not None else "(not read from a file)"
        files["model"] = write_text(
            tmp / OUTPUT_FILES["model"],
            config.to_toml(resolve_paths=True, defaults=True,
                           header=f"The model file of this run, as pounding read it, with "
                                  f"every default it took written out.\n"
                                  f"Source: {source}\nRe-run: pounding run model.toml"))
        if want_figures:
            files.update(_write_figures(result, tmp, config.output.dpi))
    files = {k: target / Path(v).name for k, v in files.items()}
    return RunOutput(out_dir=target, files=files, result=result, config=config,
                     wall_time=time.perf_counter() - start)


def run(input: str | os.PathLike[str], out: str | os.PathLike[str] | None = None, *,
        overwrite: bool = False, figures: bool | None = None,
        progress: Progress | None = None) -> RunOutput:
    """Load a model file, simulate it and write every output into one folder.

    Every runner takes the same first arguments, in this order: :func:`run`,
    :func:`pounding.studies.sweep.run_sweep`, :func:`pounding.studies.fragility.run_study`,
    :func:`pounding.studies.mitigation.run_mitigation` (``docs/running.md``).

    Parameters
    ----------
    input : path-like
        The TOML model file (``docs/running.md``).
    out : path-like, optional
        Output folder; default ``<model file stem>-results`` in the current folder
        (:func:`pounding.io.output_folder.default_out_dir`). It receives ``timehistories.nc``,
        ``impacts.csv``, ``summary.json`` (:meth:`pounding.result.Result.save`),
        ``model.toml`` (the configuration as read, record path made absolute) and, unless
        turned off, the PNG figures of the model
        (:func:`pounding.plot.registry.figures_for`: five, six with yielding storeys; a
        bridge: its elevation and element figures in place of the storeys' two).
    overwrite : bool
        Replace an existing output folder (else it is an error): only an empty one or an
        earlier output of pounding, holding nothing but the files its manifest lists.
    figures : bool, optional
        Write the figures; default ``[output] figures`` of the model file (true if not
        given).
    progress : Progress, optional
        Called as ``progress(done, total)`` during the integration: seconds of ground
        motion simulated, and in all [s] (:class:`pounding.progress.Progress`).

    Returns
    -------
    RunOutput

    Raises
    ------
    ValueError
        A bad model file (one line per problem), or an output folder that exists.
        Nothing is written then.
    """
    config = load_config(input)
    target = default_out_dir(input) if out is None else Path(out)
    return run_config(config, target, overwrite=overwrite, figures=figures, progress=progress)

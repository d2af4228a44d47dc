"""Run a model file end to end: load, simulate, write every output into one folder.

:func:`run` never leaves a half-written output folder. Everything is written into a hidden
temporary folder beside the target (``.<name>.tmp-<pid>-XXXX``) and moved into place only
when complete; if anything fails (or the run is interrupted with Ctrl-C or SIGTERM) the
temporary folder is removed and a previous output folder is left untouched. A run killed
outright (SIGKILL) cannot clean up after itself: the next run into the same folder removes
what it left (and puts back an earlier output it was replacing).

An existing output folder is replaced only with ``overwrite=True``, and only if it looks like
an earlier output (it holds ``summary.json``) or is empty: the new folder is complete before
the old one is removed.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path


from pounding.config import RunConfig, load_config
from pounding.integrate import simulate
from pounding.io import check_writable, make_folders, remove_empty_folders, write_text
from pounding.plot.registry import RUN_FIGURES
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


def default_out_dir(config_path: str | os.PathLike[str]) -> Path:
    """``<model file stem>-results`` in the current folder."""
    return Path(f"{Path(config_path).stem}-results")


def _check_target(out_dir: Path, overwrite: bool) -> None:
    if out_dir.exists() or out_dir.is_symlink():
        if not out_dir.is_dir() or out_dir.is_symlink():
            raise ValueError(f"out: {out_dir} exists and is not a folder; choose another --out")
        if not overwrite:
            raise ValueError(f"out: {out_dir} already exists; give --overwrite to replace it "
                             "or choose another --out")
        if any(out_dir.iterdir()) and not (out_dir / OUTPUT_FILES["summary"]).is_file():
            raise ValueError(f"out: {out_dir} is a non-empty folder that is not a pounding "
                             "output (no summary.json); not replacing it")


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OSError):
        return True
    return True


def _remove_stale(out_dir: Path) -> None:
    """Remove what a run into ``out_dir`` killed outright (SIGKILL, power loss) left behind:
    its temporary folder ``.<name>.tmp-<pid>-*``; and if it was killed while replacing an
    earlier output, put that output back from ``.<name>.old-<pid>-*``. Only folders of
    processes no longer running are touched."""
    parent = out_dir.absolute().parent
    if not parent.is_dir():
        return
    for kind in ("old", "tmp"):
        for p in parent.glob(f".{out_dir.name}.{kind}-*-*"):
            pid = p.name[len(f".{out_dir.name}.{kind}-"):].split("-", 1)[0]
            if not pid.isdigit() or _pid_alive(int(pid)):
                continue
            held = p / out_dir.name
            if kind == "old" and held.is_dir() and not out_dir.exists():
                with contextlib.suppress(OSError):
                    os.replace(held, out_dir)
            shutil.rmtree(p, ignore_errors=True)


def _umask() -> int:
    """The process umask (from /proc where possible, so it is not changed even briefly)."""
    with contextlib.suppress(OSError, ValueError):
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("Umask:"):
                return int(line.split()[1], 8)
    old = os.umask(0o022)
    os.umask(old)
    return old


def _normal_permissions(folder: Path) -> None:
    """Temporary files and folders are private (0600/0700); give the finished output the
    permissions an ordinary ``mkdir``/``open`` would."""
    mask = _umask()
    folder.chmod(0o777 & ~mask)
    for f in folder.iterdir():
        if f.is_file():
            f.chmod(0o666 & ~mask)


def _write_figures(result: Result, folder: Path, dpi: int) -> dict[str, Path]:
    from pounding.plot import save_figure
    from pounding.plot.registry import figures_for

    out = {}
    for key, fig in figures_for(result).items():
        out[key] = save_figure(fig.make(result), folder / fig.file, dpi=dpi)
    return out


def run_config(cfg: RunConfig, out_dir: str | os.PathLike[str], *,
               progress: Callable[[float], None] | None = None, overwrite: bool = False,
               figures: bool | None = None) -> RunOutput:
    """Simulate an already-loaded configuration and write its outputs into ``out_dir``.

    See :func:`run`.
    """
    start = time.perf_counter()
    out = Path(out_dir)
    if out.name in ("", ".", ".."):
        raise ValueError(f"out: {out_dir!s} is not a folder name; give e.g. --out results")
    check_writable(out)
    _remove_stale(out)
    _check_target(out, overwrite)
    model, motion, solver = cfg.build()
    want_figures = cfg.output.figures if figures is None else figures

    created = make_folders(out.absolute().parent)
    tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.tmp-{os.getpid()}-",
                                dir=out.absolute().parent))
    try:
        result = simulate(model, motion, progress=progress, **solver)
        files = result.save(tmp)
        source = str(cfg.source) if cfg.source is not None else "(not read from a file)"
        files["model"] = write_text(
            tmp / OUTPUT_FILES["model"],
            cfg.to_toml(resolve_paths=True, defaults=True,
                        header=f"The model file of this run, as pounding read it, with every "
                               f"default it took written out.\n"
                               f"Source: {source}\nRe-run: pounding run model.toml"))
        if want_figures:
            files.update(_write_figures(result, tmp, cfg.output.dpi))
        _normal_permissions(tmp)
        # move into place: the old folder (if any) is removed only once the new one is in
        _check_target(out, overwrite)
        old = None
        if out.exists():
            old = Path(tempfile.mkdtemp(prefix=f".{out.name}.old-{os.getpid()}-",
                                        dir=out.absolute().parent))
            os.replace(out, old / out.name)
        try:
            os.replace(tmp, out)
        except BaseException:
            if old is not None:
                os.replace(old / out.name, out)
                shutil.rmtree(old, ignore_errors=True)
            raise
        if old is not None:
            shutil.rmtree(old, ignore_errors=True)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        remove_empty_folders(created)
        raise
    files = {k: out / Path(v).name for k, v in files.items()}
    return RunOutput(out_dir=out, files=files, result=result, config=cfg,
                     wall_time=time.perf_counter() - start)


def run(config_path: str | os.PathLike[str], out_dir: str | os.PathLike[str] | None = None,
        progress: Callable[[float], None] | None = None, *, overwrite: bool = False,
        figures: bool | None = None) -> RunOutput:
    """Load a model file, simulate it and write every output into ``out_dir``.

    Parameters
    ----------
    config_path : path-like
        The TOML model file (``docs/running.md``).
    out_dir : path-like, optional
        Output folder; default :func:`default_out_dir`. It receives ``timehistories.nc``,
        ``impacts.csv``, ``summary.json`` (:meth:`pounding.result.Result.save`),
        ``model.toml`` (the configuration as read, record path made absolute) and, unless
        turned off, the PNG figures of the model
        (:func:`pounding.plot.registry.figures_for`: five, six with yielding storeys).
    progress : callable, optional
        Called with the fraction done (0 … 1) during the integration.
    overwrite : bool
        Replace an existing output folder (else it is an error).
    figures : bool, optional
        Write the figures; default ``[output] figures`` of the model file.

    Returns
    -------
    RunOutput

    Raises
    ------
    ValueError
        A bad model file (one line per problem), or an output folder that exists.
        Nothing is written then.
    """
    cfg = load_config(config_path)
    target = default_out_dir(config_path) if out_dir is None else Path(out_dir)
    return run_config(cfg, target, progress=progress, overwrite=overwrite, figures=figures)

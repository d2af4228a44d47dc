"""``pounding pushover``: push a frame of a model file and write its capacity curve.

The analysis is :func:`pounding.structure.frame_analysis.pushover` (gravity first, then
lateral loads under roof-displacement control, event to event: exact, no iterations). The
output folder is built whole and put in place like a run's (:mod:`pounding.run_file`):

* ``pushover.csv`` — one row per event: ``roof_displacement_m, base_shear_N``, then per
  storey ``storey_<j>_drift_m`` and ``storey_<j>_shear_N``; the curve is straight between
  rows;
* ``hinges.csv`` — per hinge: where it is, its law, peak and final rotation [rad], final
  moment [N·m], whether it yielded;
* ``summary.json`` — the frame, the options, the peak base shear and where it was reached,
  the first yield, why the push ended; every key says its unit;
* ``pushover.png`` — the capacity curve and the storey drifts (unless figures are off).
"""

from __future__ import annotations

import json
import math
import os
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["PUSHOVER_FILES", "PushoverOutput", "run_pushover", "pushover_table"]

PUSHOVER_FILES: tuple[str, ...] = ("pushover.csv", "hinges.csv", "summary.json", "pushover.png")
"""The files of a pushover's output folder (and its manifest)."""


@dataclass(frozen=True)
class PushoverOutput:
    """What :func:`run_pushover` produced: the folder, its files, the curve, the frame."""

    out_dir: Path
    files: dict[str, Path]
    result: Any  #: :class:`pounding.structure.frame_analysis.PushoverResult`
    frame: Any  #: :class:`pounding.structure.frame.Frame`
    target: float  #: roof displacement pushed to [m]
    wall_time: float  #: seconds [s]


def pushover_table(result: Any) -> str:
    """``pushover.csv`` (module docstring)."""
    n = result.storey_drifts.shape[1]
    head = ["roof_displacement_m", "base_shear_N"]
    for j in range(n):
        head += [f"storey_{j + 1}_drift_m", f"storey_{j + 1}_shear_N"]
    lines = [",".join(head)]
    for i in range(result.base_shear.size):
        row = [result.roof_displacement[i], result.base_shear[i]]
        for j in range(n):
            row += [result.storey_drifts[i, j], result.storey_shears[i, j]]
        lines.append(",".join(f"{x:.10g}" for x in row))
    return "\n".join(lines) + "\n"


def _hinge_table(frame: Any, result: Any) -> str:
    lines = ["hinge,element,end,x_m,y_m,member,law,peak_rotation_rad,final_rotation_rad,"
             "final_moment_Nm,yielded"]
    col = frame.is_column
    for h, fh in enumerate(frame.hinges):
        node = frame.elements[fh.element, fh.end]
        x, y = frame.nodes[node]
        rot = result.hinge_rotations[:, h]
        mom = result.hinge_moments[:, h]
        yielded = bool(np.any(np.abs(mom) >= fh.law.m_y * (1 - 1e-9)))
        law = fh.law.describe().replace(",", ";")
        lines.append(f"{h},{fh.element},{fh.end},{x:.6g},{y:.6g},"
                     f"{'column' if col[fh.element] else 'beam'},\"{law}\","
                     f"{np.max(np.abs(rot)):.10g},{rot[-1]:.10g},{mom[-1]:.10g},"
                     f"{str(yielded).lower()}")
    return "\n".join(lines) + "\n"


def _summary(frame: Any, result: Any, target: float, name: str, source: Path) -> dict[str, Any]:
    v = result.base_shear
    u = result.roof_displacement
    k = int(np.argmax(v))
    first_yield: dict[str, Any] | None = None
    for i in range(1, v.size):
        hit = [h for h, fh in enumerate(frame.hinges)
               if abs(result.hinge_moments[i, h]) >= fh.law.m_y * (1 - 1e-9)]
        if hit:
            first_yield = {"roof_displacement_m": float(u[i]), "base_shear_N": float(v[i]),
                           "hinges": hit}
            break
    height = float(frame.levels[-1] - frame.base)
    return {
        "name": name, "source": str(source), "frame": frame.describe(),
        "pattern": result.pattern, "load_shape_per_N": [float(x) for x in result.load_shape],
        "target_roof_displacement_m": target, "stopped": result.stopped,
        "events": int(v.size - 1),
        "peak_base_shear_N": float(v[k]), "roof_displacement_at_peak_m": float(u[k]),
        "final_roof_displacement_m": float(u[-1]), "final_base_shear_N": float(v[-1]),
        "height_m": height, "final_roof_drift_ratio": float(u[-1] / height),
        "initial_stiffness_N_per_m": (float(v[1] / u[1]) if v.size > 1 and u[1] != 0 else None),
        "first_yield": first_yield,
        "units": "SI: m, N, N·m, rad",
    }


def _check_target(out_dir: Path, overwrite: bool) -> None:
    from pounding.io.manifest import check_out_folder

    check_out_folder(out_dir, overwrite, "pushover")


def run_pushover(input: str | os.PathLike[str], out: str | os.PathLike[str] | None = None, *,
                 overwrite: bool = False, figures: bool | None = None,
                 building: str | None = None, target: float | None = None,
                 pattern: str | None = None, stop_below: float | None = None,
                 dpi: int = 150) -> PushoverOutput:
    """Read a model file, push its frame and write the outputs into one folder.

    Parameters
    ----------
    input : path-like
        The model file (a building given as ``frame = {...}``, an optional ``[pushover]``
        table: :mod:`pounding.config.pushover`).
    out : path-like, optional
        Output folder; default ``<file stem>-results`` in the current folder.
    overwrite : bool
        Replace an earlier pushover's folder (only one holding nothing but its files).
    figures : bool, optional
        Write ``pushover.png`` (default true).
    building, target, pattern, stop_below : optional
        Override ``[pushover]``: the frame's name, the roof displacement to reach [m], the
        load pattern, the fraction of the peak base shear to stop below.

    Raises
    ------
    ValueError
        Bad input, in one line naming the key or option; nothing is written then.
    """
    from pounding.config.pushover import load_pushover
    from pounding.io.files import check_writable, write_text
    from pounding.io.output_folder import default_out_dir, new_output_folder, remove_stale
    from pounding.structure.frame_analysis import PATTERNS, pushover

    start = time.perf_counter()
    if target is not None and not (math.isfinite(target) and target > 0):
        raise ValueError(f"--to: the roof displacement must be finite and > 0 [m] "
                         f"(got {target!r})")
    if pattern is not None and pattern not in PATTERNS:
        raise ValueError(f"--pattern: must be one of {', '.join(PATTERNS)} (got {pattern!r})")
    if stop_below is not None and not (0.0 <= stop_below < 1.0):
        raise ValueError(f"--stop-below: must be in [0, 1) (got {stop_below!r})")
    pf = load_pushover(input, building=building)
    folder = default_out_dir(input) if out is None else Path(out)
    if folder.name in ("", ".", ".."):
        raise ValueError(f"out: {out!s} is not a folder name; give e.g. --out results")
    check_writable(folder)
    remove_stale(folder.absolute().parent, restore=folder.absolute())
    _check_target(folder, overwrite)
    push_to = float(target) if target is not None else pf.target
    how = pattern or pf.options.pattern
    below = stop_below if stop_below is not None else pf.options.stop_below
    result = pushover(pf.frame, push_to, pattern=how, stop_below=below)
    files: dict[str, Path] = {}
    with new_output_folder(folder, "pushover", PUSHOVER_FILES,
                           check=lambda: _check_target(folder, overwrite)) as tmp:
        files["pushover"] = write_text(tmp / "pushover.csv", pushover_table(result))
        files["hinges"] = write_text(tmp / "hinges.csv", _hinge_table(pf.frame, result))
        files["summary"] = write_text(
            tmp / "summary.json",
            json.dumps(_summary(pf.frame, result, push_to, pf.name, pf.source), indent=2) + "\n")
        if figures is not False:
            from pounding.plot import save_figure
            from pounding.plot.pushover import plot_pushover

            fig = plot_pushover(result, pf.frame.storey_heights, title=pf.frame.name)
            files["figure"] = save_figure(fig, tmp / "pushover.png", dpi=dpi)
    files = {k: folder / Path(v).name for k, v in files.items()}
    return PushoverOutput(out_dir=folder, files=files, result=result, frame=pf.frame,
                          target=push_to, wall_time=time.perf_counter() - start)

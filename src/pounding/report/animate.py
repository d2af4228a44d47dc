"""``pounding animate``: the animation of a run folder, as a video and an interactive page.

:func:`write_animation` reads a run folder (:func:`pounding.report.run_folder.read_run`),
makes its frames by the kind of its structures (:func:`run_frames`: buildings in a row,
buildings in plan, a bridge along or across its axis) and writes

* ``animation.html``: one self-contained page, the frames embedded as JSON and drawn with
  plain JavaScript on a canvas, with a time slider and play/pause (works offline; nothing is
  fetched); rendered from ``templates/animate.html.j2`` (the view itself:
  ``templates/animation_view.html.j2``, which the run report embeds too) with the report's
  Jinja2 environment;
* ``animation.mp4`` (ffmpeg found by matplotlib) or else ``animation.gif`` (Pillow).

Into the run folder, or into ``out`` (a folder). A folder with a manifest
(:mod:`pounding.io.manifest`, every folder pounding writes) gets the files recorded in it, and
an earlier animation pounding wrote there is replaced; a file of the same name pounding did not
write is never replaced (refused before any work). See ``docs/animate.md``.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pounding.report.run_folder import RUN_FILES

__all__ = ["HTML_NAME", "VIDEO_STEM", "AnimationOutput", "animation_block", "animation_data",
           "animation_page", "run_frames", "write_animation"]

HTML_NAME = "animation.html"
"""The interactive page's file name."""

VIDEO_STEM = "animation"
"""The video's file name without its suffix (``.mp4`` or ``.gif``)."""


@dataclass
class AnimationOutput:
    """What :func:`write_animation` wrote: the page, the video (None without one), the
    number of frames and the exaggeration factor used."""

    html: Path
    video: Path | None
    n_frames: int
    exaggeration: float


def _check_run_folder(folder: Path) -> None:
    if not folder.is_dir():
        what = "does not exist" if not folder.exists() else "is not a folder"
        raise ValueError(f"animate: {folder} {what}; give the output folder of `pounding run`")
    missing = [f for f in RUN_FILES if not (folder / f).is_file()]
    if missing:
        raise ValueError(f"animate: {folder} is not a run folder (missing {', '.join(missing)}); "
                         "give the output folder of `pounding run`")


def _rounded(values: Any, digits: int) -> list[Any]:
    import numpy as np

    return np.round(np.asarray(values, dtype=float), digits).tolist()


def run_frames(run: Any, *, fps: float = 25.0, exaggeration: float | None = None,
               start: float | None = None, end: float | None = None) -> Any:
    """The frames of a read run folder (:class:`pounding.report.run_folder.RunFolder`), by the
    kind of its structures: a bridge (along or across its axis), buildings in plan, or
    buildings in a row (:mod:`pounding.plot.animate` and its kinds).

    Raises
    ------
    ValueError
        An option out of range, or a run that cannot be drawn (one line).
    """
    from pounding.plot.animate import animation_frames
    from pounding.plot.animate_bridge import bridge_frames, is_bridge_model
    from pounding.plot.animate_plan import is_plan, plan_frames

    title = str(run.summary.get("model") or run.ds.attrs.get("model") or run.folder.name)
    options: dict[str, Any] = {"fps": fps, "exaggeration": exaggeration, "start": start,
                               "end": end, "title": title}
    model = run.built.model if run.built is not None else None
    if model is not None and is_bridge_model(model):
        bridge = run.toml.get("bridge")
        transverse = isinstance(bridge, dict) and bridge.get("direction") == "transverse"
        return bridge_frames(run.ds, model, transverse=transverse, **options)
    if model is not None and is_plan(model):
        return plan_frames(run.ds, model, **options)
    try:
        return animation_frames(run.ds, **options)
    except ValueError as exc:
        if model is None and "several degrees of freedom" in str(exc):
            raise ValueError(f"{exc}: {run.build_error}") from None
        raise


def animation_data(frames: Any) -> dict[str, Any]:
    """The JSON-ready data of the page's view of ``frames``
    (:class:`pounding.plot.animate.AnimationFrames`): displacements in mm (rotations in
    mrad) at the frames, forces in kN, times in s, the drawing in m."""
    def vertex(v: Any) -> list[Any]:
        return [round(v.x, 4), round(v.y, 4), [[c, round(w, 6)] for c, w in v.wx],
                [[c, round(w, 6)] for c, w in v.wy]]

    x0, x1, y0, y1 = frames.extent()
    if frames.view == "elevation":
        y0, y1 = min(y0, 0.0) - 0.03 * frames.height, max(y1, 1.12 * frames.height)
    pad_x, pad_y = 0.04 * (x1 - x0 or 1.0), 0.04 * (y1 - y0 or 1.0)
    return {
        "time": _rounded(frames.time, 6),
        "fps": frames.fps,
        "exaggeration": frames.exaggeration,
        "view": frames.view,
        "equal": frames.equal_scales,
        "y_label": frames.y_label,
        "extent": [x0 - pad_x, x1 + pad_x, y0 - pad_y, y1 + 3 * pad_y],
        "u_mm": _rounded(frames.channels * 1e3, 3),
        "shapes": [{"kind": s.kind, "closed": s.closed, "v": [vertex(v) for v in s.vertices]}
                   for s in frames.shapes],
        "labels": [[text, round(at.x, 4), round(at.y, 4)] for text, at in frames.labels],
        "contacts": [{"label": c.label, "mark": None if c.mark is None else vertex(c.mark),
                      "force_kn": _rounded(c.force / 1e3, 3)} for c in frames.contacts],
        "curve_time": _rounded(frames.curve_time, 6),
        "ground": _rounded(frames.ground_acceleration, 5),
        "force": [_rounded(f / 1e3, 3) for f in frames.contact_force],
    }


def animation_block(frames: Any, notes: list[str] | None = None) -> Any:
    """The page block (:class:`pounding.report.format.Animation`) of ``frames``."""
    from pounding.report.format import Animation

    return Animation(animation_data(frames), len(frames.time), f"{frames.fps:g}",
                     f"{frames.exaggeration:g}", [*frames.notes, *(notes or [])])


def animation_page(frames: Any, folder: Path) -> str:
    """The HTML text of the interactive page of ``frames``
    (:class:`pounding.plot.animate.AnimationFrames`)."""
    from pounding import __version__
    from pounding.report.page import _environment

    return _environment().get_template("animate.html.j2").render(
        title=f"{frames.title}: pounding animation", a=animation_block(frames),
        version=__version__, folder=str(folder.resolve()))


def write_animation(run_folder: str | os.PathLike[str], out: str | os.PathLike[str] | None = None,
                    *, fps: float = 25.0, exaggeration: float | None = None,
                    start: float | None = None, end: float | None = None,
                    video: bool = True) -> AnimationOutput:
    """Write the animation of a run folder (module docstring).

    Parameters
    ----------
    run_folder : path-like
        The output folder of ``pounding run`` (``summary.json``, ``timehistories.nc``).
    out : path-like, optional
        The folder to write into; default ``run_folder``.
    fps, exaggeration, start, end
        As :func:`pounding.plot.animate.animation_frames`.
    video : bool
        Write the video too (else only the page).

    Returns
    -------
    AnimationOutput

    Raises
    ------
    ValueError
        Not a run folder, an unreadable file, an option out of range, or a file in the way
        that pounding did not write (one line; nothing written).
    """
    from pounding.io.files import check_writable, write_bytes
    from pounding.io.manifest import Manifest
    from pounding.plot.animate_video import video_format, write_video
    from pounding.report.run_folder import read_run

    folder = Path(run_folder)
    _check_run_folder(folder)
    target_dir = Path(out) if out is not None else folder
    if target_dir.exists() and not target_dir.is_dir():
        raise ValueError(f"animate: --out {target_dir} is a file, not a folder")
    check_writable(target_dir, inside=True)
    suffix = video_format() if video else None
    targets = [target_dir / HTML_NAME] + ([target_dir / f"{VIDEO_STEM}.{suffix}"] if suffix else [])
    manifest = Manifest(target_dir) if Manifest(target_dir).exists() else None
    for target in targets:  # refused before any work
        if manifest is not None:
            manifest.check_free(target)
        elif target.exists() or target.is_symlink():
            raise ValueError(f"animate: not replacing {target}: pounding did not write it; "
                             "move it away or choose another --out")

    frames = run_frames(read_run(folder), fps=fps, exaggeration=exaggeration, start=start,
                        end=end)
    page = animation_page(frames, folder)

    if manifest is None and not target_dir.exists():
        manifest = Manifest(target_dir)
        manifest.start("animation")
    video_path = None
    if suffix:
        video_path = targets[1]
        if manifest is not None:
            with manifest.write(video_path) as tmp:
                write_video(frames, tmp)
        else:
            from pounding.io.files import atomic_path

            with atomic_path(video_path) as tmp:
                write_video(frames, tmp)
    html = page.encode("utf-8")
    if manifest is not None:
        manifest.write_bytes(targets[0], html)
    else:
        write_bytes(targets[0], html)
    return AnimationOutput(targets[0], video_path, len(frames.time), frames.exaggeration)

"""``pounding animate``: the animation of a run folder, as a video and an interactive page.

:func:`write_animation` reads a run folder (:func:`pounding.report.run_folder.read_run`),
makes its frames (:func:`pounding.plot.animate.animation_frames`) and writes

* ``animation.html``: one self-contained page, the frames embedded as JSON and drawn with
  plain JavaScript on a canvas, with a time slider and play/pause (works offline; nothing is
  fetched); rendered from ``templates/animate.html.j2`` with the report's Jinja2 environment;
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

__all__ = ["HTML_NAME", "VIDEO_STEM", "AnimationOutput", "animation_page", "write_animation"]

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


def animation_page(frames: Any, folder: Path) -> str:
    """The HTML text of the interactive page of ``frames``
    (:class:`pounding.plot.animate.AnimationFrames`)."""
    from pounding import __version__
    from pounding.report.page import _environment

    data = {
        "time": _rounded(frames.time, 6),
        "fps": frames.fps,
        "exaggeration": frames.exaggeration,
        "height": frames.height,
        "buildings": [{"name": b.name, "left": b.left, "width": b.width,
                       "elevations": _rounded(b.elevations, 4),
                       "peak_mm": float(abs(b.displacement).max() * 1e3),
                       "u_mm": _rounded(b.displacement * 1e3, 3)} for b in frames.buildings],
        "contacts": [{"label": c.label, "elevation": c.elevation, "left": c.left_building,
                      "right": c.right_building, "force_kn": _rounded(c.force / 1e3, 3)}
                     for c in frames.contacts],
        "curve_time": _rounded(frames.curve_time, 6),
        "ground": _rounded(frames.ground_acceleration, 5),
        "force": [_rounded(f / 1e3, 3) for f in frames.contact_force],
    }
    return _environment().get_template("animate.html.j2").render(
        title=f"{frames.title}: pounding animation", exaggeration=f"{frames.exaggeration:g}",
        frames=len(frames.time), fps=f"{frames.fps:g}", data=data, version=__version__,
        folder=str(folder.resolve()))


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
    from pounding.plot.animate import animation_frames, video_format, write_video
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

    run = read_run(folder)
    title = str(run.summary.get("model") or run.ds.attrs.get("model") or folder.name)
    frames = animation_frames(run.ds, fps=fps, exaggeration=exaggeration, start=start, end=end,
                              title=title)
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

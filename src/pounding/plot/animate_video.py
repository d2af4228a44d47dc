"""The video of an animation (:class:`pounding.plot.animate.AnimationFrames`, any kind of
structure): matplotlib draws the shapes, the impacts and the curves below with a moving
time cursor into an MP4 (ffmpeg) or, where no ffmpeg is found, a GIF (Pillow).

Each frame is drawn over a background drawn once (blitting: axes, ticks and curves a single
time). matplotlib is imported only here, when a video is written.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from pounding.plot.animate import AnimationFrames, Shape

__all__ = ["STYLES", "video_format", "write_video"]

STYLES: dict[str, dict[str, Any]] = {
    "outline": {"color": "C0", "lw": 1.6},
    "floor": {"color": "C0", "lw": 0.8},
    "slab": {"color": "C0", "lw": 1.4},
    "lower": {"color": "C0", "lw": 0.6, "alpha": 0.45},
    "deck": {"color": "C0", "lw": 3.0},
    "pier": {"color": "0.35", "lw": 1.6},
    "wall": {"color": "0.2", "lw": 2.4},
}
"""Line style of each kind of shape (the page uses the same colours and widths)."""


def video_format() -> str:
    """``"mp4"`` where matplotlib finds ffmpeg, else ``"gif"`` (Pillow, always there)."""
    from matplotlib import animation

    return "mp4" if animation.writers.is_available("ffmpeg") else "gif"


def _xy(shape: Shape, u: Any, factor: float) -> tuple[list[float], list[float]]:
    pts = [v.at(u, factor) for v in shape.vertices]
    if shape.closed:
        pts.append(pts[0])
    return [p[0] for p in pts], [p[1] for p in pts]


def write_video(frames: AnimationFrames, path: str | Path, *, dpi: int = 80) -> Path:
    """Draw ``frames`` into ``path``: MP4 by ffmpeg for a ``.mp4`` name, else a GIF by
    Pillow. The file is written where it is named (atomic placement is the caller's).

    Returns
    -------
    Path
        ``path``.
    """
    from matplotlib import animation

    from pounding.plot import new_figure

    path = Path(path)
    fig = new_figure(8.0, 6.4, laid_out=False)
    grid = fig.add_gridspec(3, 1, height_ratios=[3.2, 1, 1], hspace=0.45)
    ax = fig.add_subplot(grid[0])
    ax_g = fig.add_subplot(grid[1])
    ax_f = fig.add_subplot(grid[2], sharex=ax_g)
    fig.subplots_adjust(left=0.1, right=0.97, top=0.93, bottom=0.08)

    factor = frames.exaggeration
    x0, x1, y0, y1 = frames.extent()
    pad_x, pad_y = 0.05 * (x1 - x0 or 1.0), 0.05 * (y1 - y0 or 1.0)
    ax.set_xlim(x0 - pad_x, x1 + pad_x)
    if frames.view == "plan":
        ax.set_ylim(y0 - pad_y, y1 + 3 * pad_y)
        if frames.equal_scales:
            ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel("x [m] (displacements exaggerated)", fontsize=8)
    else:
        ax.set_ylim(min(y0, 0.0) - pad_y, max(y1, 1.12 * frames.height) + pad_y)
        ax.axhline(0.0, color="0.3", lw=2)
        ax.set_xticks([])
    ax.set_ylabel(frames.y_label)
    ax.set_title(f"{frames.title}  —  displacements × {factor:g}", fontsize=10)
    u0 = frames.channels[0]
    lines = [ax.plot(*_xy(s, u0, factor), **STYLES.get(s.kind, STYLES["outline"]))[0]
             for s in frames.shapes]
    for text, at in frames.labels:
        ax.text(at.x, at.y, text, ha="center", fontsize=9)
    marks = ax.scatter([], [], s=160, marker="*", color="C3", zorder=5)
    clock = fig.text(0.01, 0.985, "", va="top", fontsize=9)

    ax_g.plot(frames.curve_time, frames.ground_acceleration, color="0.3", lw=0.7)
    ax_g.set_ylabel("ground acc.\n[m/s²]", fontsize=8)
    for k, c in enumerate(frames.contacts):
        ax_f.plot(frames.curve_time, frames.contact_force[k] / 1e3, lw=0.8, label=c.label)
    if 1 < len(frames.contacts) <= 6:
        ax_f.legend(fontsize=7, loc="upper right")
    ax_f.set_ylabel("contact force\n[kN]", fontsize=8)
    ax_f.set_xlabel("time [s]")
    ax_g.set_xlim(frames.time[0], frames.time[-1])
    cursors = [a.axvline(frames.time[0], color="C3", lw=1) for a in (ax_g, ax_f)]

    def draw(i: int) -> list[Any]:
        u = frames.channels[i]
        for s, line in zip(frames.shapes, lines, strict=True):
            line.set_data(*_xy(s, u, factor))
        struck = [c for c in frames.contacts if c.force[i] > 0]
        pts = [c.mark.at(u, factor) for c in struck if c.mark is not None]
        marks.set_offsets(np.array(pts) if pts else np.empty((0, 2)))
        clock.set_text(f"t = {frames.time[i]:.2f} s" + ("   impact" if struck else ""))
        for cur in cursors:
            cur.set_xdata([frames.time[i], frames.time[i]])
        return [*lines, marks, clock, *cursors]

    animated = [*lines, marks, clock, *cursors]
    for artist in animated:
        artist.set_animated(True)
    if path.suffix.lower() == ".mp4":
        writer = animation.FFMpegWriter(fps=frames.fps)  # type: ignore[arg-type]  # (a float is fine)
        with writer.saving(fig, str(path), dpi):
            for i in range(len(frames.time)):
                draw(i)
                writer.grab_frame()
        return path
    _write_gif(fig, animated, draw, len(frames.time), frames.fps, path, dpi)
    return path


def _write_gif(fig: Any, animated: list[Any], draw: Any, n_frames: int, fps: float, path: Path,
               dpi: int) -> None:
    """Each frame drawn over a background drawn once, handed to Pillow one at a time (never
    all in memory)."""
    from PIL import Image

    fig.set_dpi(dpi)
    canvas = fig.canvas
    canvas.draw()
    background = canvas.copy_from_bbox(fig.bbox)

    def images() -> Any:
        for i in range(n_frames):
            canvas.restore_region(background)
            draw(i)
            for artist in animated:
                fig.draw_artist(artist)
            rgba = np.asarray(canvas.buffer_rgba())
            yield Image.fromarray(rgba[..., :3].copy()).quantize(colors=64)

    frames_iter = images()
    first = next(frames_iter)
    first.save(path, format="GIF", save_all=True, append_images=frames_iter,
               duration=round(1000.0 / fps), loop=0)

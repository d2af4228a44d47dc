"""The run page's "Animation" section: the interactive view ``pounding animate`` writes
(``templates/animation_view.html.j2``: time slider, play/pause, the structures swaying and
striking, the ground motion and contact forces below), embedded in the report.

The frames are embedded once, as JSON; the view draws them with a few lines of inline
JavaScript (nothing fetched: the page stays self-contained and works offline). To keep the
report small the frame rate is lowered for long runs so that at most
:data:`MAX_REPORT_FRAMES` frames are embedded (the page says so); ``pounding animate``
writes the full-rate page and the video.
"""

from __future__ import annotations

import math

from pounding.report.animate import animation_block, run_frames
from pounding.report.format import Block, Note
from pounding.report.run_folder import RunFolder

__all__ = ["MAX_REPORT_FRAMES", "REPORT_FPS", "animation_section", "report_fps"]

REPORT_FPS = 25.0
"""Frames a second of ground-motion time embedded in a short run's report."""

MAX_REPORT_FRAMES = 800
"""At most this many frames are embedded (a longer run gets a lower frame rate)."""


def report_fps(duration: float) -> float:
    """The frame rate embedded for a run of ``duration`` [s]: :data:`REPORT_FPS`, lowered
    to a round value so that the frames are at most :data:`MAX_REPORT_FRAMES`."""
    if not (math.isfinite(duration) and duration > 0):
        return REPORT_FPS
    fps = min(REPORT_FPS, (MAX_REPORT_FRAMES - 1) / duration)
    return max(math.floor(fps * 10.0) / 10.0, 0.1)


def animation_section(r: RunFolder) -> list[Block]:
    """The blocks of the section: the view, or a note saying why the run is not drawn."""
    t = r.ds["time"].values
    duration = float(t[-1] - t[0]) if t.size > 1 else 0.0
    fps = report_fps(duration)
    try:
        frames = run_frames(r, fps=fps)
    except ValueError as exc:
        return [Note(f"No animation of this run: {str(exc).removeprefix('animate: ')}.",
                     "note")]
    lowered = (f"Frame rate lowered to {fps:g} frames/s to keep the report small (at most "
               f"{MAX_REPORT_FRAMES} frames); the command pounding animate writes every "
               f"frame at {REPORT_FPS:g} frames/s, and a video")
    notes = [lowered] if fps < REPORT_FPS else []
    return [animation_block(frames, notes)]

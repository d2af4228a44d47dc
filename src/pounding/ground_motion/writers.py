"""Writing records: :func:`at2_text`, a record as a PEER strong-motion ``.AT2`` file that
:func:`pounding.ground_motion.readers.read_at2` (and the PEER tools) read back.

The layout is the PEER strong-motion database's: four header lines — a title, a
description, ``ACCELERATION TIME SERIES IN UNITS OF G``, ``NPTS=  N, DT= .01000 SEC`` —
then the accelerations in g, five a line, each ``%15.7E`` (8 significant digits: read back
to 5e-8 of each value).
"""

from __future__ import annotations

from pounding.ground_motion.motion import GroundMotion
from pounding.units import G

__all__ = ["AT2_DIGITS", "at2_text"]

AT2_DIGITS = 8
"""Significant digits of each value written (``%15.7E``)."""


def _one_line(text: str) -> str:
    return " ".join(str(text).split())


def at2_text(motion: GroundMotion, title: str, description: str = "") -> str:
    """The record as the text of a PEER ``.AT2`` file (module docstring).

    Parameters
    ----------
    motion : GroundMotion
        The record [m/s²]; written in g (9.80665 m/s²).
    title, description : str
        The first two header lines (each made one line).
    """
    values = motion.accel / G
    lines = [_one_line(title) or motion.name, _one_line(description) or motion.name,
             "ACCELERATION TIME SERIES IN UNITS OF G",
             f"NPTS= {motion.npts:7d}, DT= {motion.dt:.8f} SEC"]
    for k in range(0, values.size, 5):
        lines.append("".join(f"{x:15.7E}" for x in values[k:k + 5]))
    return "\n".join(lines) + "\n"

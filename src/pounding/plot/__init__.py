"""Figures (matplotlib only, no computation): one module per subject.

Every figure function takes results computed elsewhere and returns a
:class:`matplotlib.figure.Figure`; :func:`save_figure` writes it atomically.
"""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only; no screen on servers and CI

from matplotlib.figure import Figure  # noqa: E402

from pounding.io import atomic_path  # noqa: E402


def save_figure(fig: Figure, path: str | os.PathLike[str], dpi: int = 150) -> Path:
    """Save ``fig`` to ``path`` (format from the suffix) without leaving a partial file."""
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=dpi, bbox_inches="tight")
    return Path(path)

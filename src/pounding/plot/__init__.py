"""Figures (matplotlib only, no computation): one module per subject.

Every figure function takes results computed elsewhere and returns a
:class:`matplotlib.figure.Figure`; :func:`save_figure` writes it atomically.

Importing this package does not import matplotlib (``pounding run`` needs the figure file
names, :mod:`pounding.plot.registry`, before it knows whether it will draw any): the figure
modules import it, and :func:`new_figure` gives each figure its own Agg canvas. Nothing uses
pyplot, so no global backend is chosen, no window can open, and a notebook's own backend is
left alone.
"""

from __future__ import annotations

import os
import weakref
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from pounding.io.files import atomic_path

if TYPE_CHECKING:
    from matplotlib.figure import Figure
    from matplotlib.typing import RcKeyType

__all__ = ["new_figure", "save_figure"]

PNG_COMPRESS_LEVEL = 3
"""zlib level of the PNGs: level 3 writes a run figure about 1.5 times faster than
Pillow's default 6, for files 2–7 % larger."""

SAVE_RC: dict[RcKeyType, Any] = {"text.hinting": "none"}
"""Settings while a figure is drawn to a file: unhinted glyphs render about 10 % faster (the
text is most of a run figure's drawing time) and at 150 dpi look the same."""

_LAID_OUT: weakref.WeakSet[Any] = weakref.WeakSet()
"""Figures whose margins were set by :func:`new_figure` (they fit as they are)."""


def new_figure(width: float, height: float, *, laid_out: bool = True,
               layout: Literal["constrained", "compressed", "tight"] | None = None) -> Figure:
    """A figure ``width`` × ``height`` inches on its own Agg canvas (files only, no pyplot).

    Parameters
    ----------
    width, height : float
        Size [in].
    laid_out : bool
        True if the caller places every artist inside the figure itself (fixed margins,
        :mod:`pounding.plot.layout`): :func:`save_figure` then saves the page as it is,
        without the costly ``bbox_inches="tight"`` pass, which draws the figure twice.
    layout : {"constrained", "compressed", "tight"}, optional
        A matplotlib layout engine (``"constrained"``, ``"tight"``); none by default.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), layout=layout)
    FigureCanvasAgg(fig)
    if laid_out:
        _LAID_OUT.add(fig)
    return fig


def save_figure(fig: Figure, path: str | os.PathLike[str], dpi: int = 150,
                tight: bool | None = None) -> Path:
    """Save ``fig`` to ``path`` (format from the suffix) without leaving a partial file.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : path-like
        Target file; ``.png``, ``.svg``, ``.pdf``, … .
    dpi : int
        Resolution of raster formats [dots per inch].
    tight : bool, optional
        Crop the page to what is drawn (``bbox_inches="tight"``; draws the figure twice).
        Default: only for figures not laid out by :func:`new_figure`.
    """
    if tight is None:
        tight = fig not in _LAID_OUT
    from matplotlib import rc_context

    kw: dict[str, Any] = {}
    if Path(path).suffix.lower() == ".png":
        kw["pil_kwargs"] = {"compress_level": PNG_COMPRESS_LEVEL}
    with atomic_path(path) as tmp, rc_context(SAVE_RC):
        fig.savefig(tmp, dpi=dpi, bbox_inches="tight" if tight else None, **kw)
    return Path(path)

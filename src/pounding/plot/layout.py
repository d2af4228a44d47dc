"""Shared look of the run figures: fixed margins, readable units, plain tick labels,
histories drawn decimated, the ground-motion panel.

Fixed margins (in inches) instead of ``tight_layout`` / ``bbox_inches="tight"``: those
measure every text on the page by drawing it, which costs more than drawing the figure
itself. The margins here are sized for tick labels of at most five characters, which the
unit choice of :func:`scale_for` guarantees (values between 1 and 1000 in the chosen
unit).
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.ticker import ScalarFormatter
from numpy.typing import NDArray

from pounding.plot.decimate import buckets_for_width, envelope_indices
from pounding.units import G

__all__ = ["Scale", "scale_for", "axes_grid", "plain_ticks", "history", "ground_panel",
           "TITLE_SIZE", "LEGEND_SIZE"]

TITLE_SIZE = 9
"""Font size of panel titles [pt]."""
LEGEND_SIZE = 7
"""Font size of legends [pt]."""

_PREFIXES = ((1e9, "G"), (1e6, "M"), (1e3, "k"), (1.0, ""), (1e-3, "m"), (1e-6, "µ"),
             (1e-9, "n"))


class Scale(NamedTuple):
    """A display unit: ``value_in_unit = value_SI * factor``."""

    factor: float
    unit: str


def scale_for(peak: float, unit: str) -> Scale:
    """The multiple of ``unit`` (n, µ, m, ``unit``, k, M or G) in which ``peak`` reads
    between 1 and 1000, e.g. ``scale_for(7.8e6, "N") == Scale(1e-6, "MN")``; ``unit``
    itself for a peak of 0 or NaN (nothing to scale), n``unit`` below 1e-9."""
    peak = abs(float(peak))
    for size, prefix in _PREFIXES:
        if math.isfinite(peak) and peak >= size:
            return Scale(1.0 / size, prefix + unit)
    if peak > 0.0 and math.isfinite(peak):
        return Scale(1e9, "n" + unit)
    return Scale(1.0, unit)


MM = Scale(1e3, "mm")
"""Displacements and drifts are drawn in millimetres."""


def axes_grid(fig: Figure, nrows: int, ncols: int, *, left: float = 0.85,
              right: float = 0.25, top: float = 0.55, bottom: float = 0.55,
              wspace: float = 0.45, hspace: float = 0.45,
              height_ratios: list[float] | None = None, sharex: bool | str = False,
              sharey: bool | str = False) -> NDArray[Any]:
    """A ``nrows`` × ``ncols`` array of axes with margins and gaps given in inches.

    Parameters
    ----------
    fig : Figure
        From :func:`pounding.plot.new_figure`.
    left, right, top, bottom : float
        Page margins [in]: room for tick labels and axis labels (left, bottom), the title
        (top).
    wspace, hspace : float
        Gaps between columns and between rows [in].
    height_ratios : list of float, optional
        Relative row heights.
    sharex, sharey : bool or {"row", "col", "all", "none"}
        As :meth:`matplotlib.figure.Figure.subplots`.
    """
    w, h = fig.get_size_inches()
    axes_w = (w - left - right - (ncols - 1) * wspace) / ncols
    axes_h = (h - top - bottom - (nrows - 1) * hspace) / nrows
    gs = fig.add_gridspec(nrows, ncols, left=left / w, right=1.0 - right / w,
                          bottom=bottom / h, top=1.0 - top / h,
                          wspace=wspace / axes_w, hspace=hspace / axes_h,
                          height_ratios=height_ratios)
    return gs.subplots(sharex=sharex, sharey=sharey, squeeze=False)


def plain_ticks(fig: Figure) -> Figure:
    """Turn off the offset (``+1e3``) and scientific (``1e6``) notation of every linear
    axis of ``fig``: each tick label then reads as the value in the axis label's unit."""
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            fmt = axis.get_major_formatter()
            if isinstance(fmt, ScalarFormatter):
                fmt.set_useOffset(False)
                fmt.set_scientific(False)
    return fig


def axes_width(ax: Axes) -> float:
    """Width of ``ax`` on the page [in]."""
    return float(ax.get_position().width * ax.figure.get_figwidth())


def history(ax: Axes, t: NDArray[np.float64], y: NDArray[np.float64], **kw: Any) -> Any:
    """``ax.plot(t, y, **kw)`` of a long history, decimated for display by
    :func:`pounding.plot.decimate.envelope_indices` (every peak drawn exactly)."""
    idx = envelope_indices(y, buckets_for_width(axes_width(ax)))
    return ax.plot(t[idx], y[idx], **kw)[0]


def ground_panel(ax: Axes, time: NDArray[np.float64], ground: NDArray[np.float64],
                 name: str) -> None:
    """The ground acceleration [g] against time [s], its peak marked, in ``ax`` (the
    bottom panel of a time-history figure, sharing its time axis)."""
    ag = np.asarray(ground, dtype=float) / G
    history(ax, time, ag, color="0.25", lw=0.6)
    if ag.size:
        k = int(np.abs(ag).argmax())
        ax.plot([time[k]], [ag[k]], "o", ms=3, color="tab:red")
        ax.set_title(f"ground acceleration: {name}; peak {abs(ag[k]):.3g} g at "
                     f"{time[k]:.2f} s", fontsize=TITLE_SIZE, loc="left")
    ax.axhline(0.0, color="0.6", lw=0.5)
    ax.set_ylabel("ground acc. [g]")
    ax.grid(True, alpha=0.3)

"""Shared look of the figures: fixed margins, readable units, plain tick labels, titles
that fit the page, legends that hide no data, histories drawn decimated, the ground-motion
panel.

Fixed margins (in inches) instead of ``tight_layout`` / ``bbox_inches="tight"``: those
measure every text on the page by drawing it, which costs more than drawing the figure
itself. The margins here are sized for tick labels of at most five characters, which the
unit choice of :func:`scale_for` guarantees (values between 1 and 1000 in the chosen
unit). A title is measured alone (:func:`fit_text`, about a millisecond) and wrapped, or
cut, to the width it has; :func:`titled_figure` gives the page the room its lines need.
"""

from __future__ import annotations

import math
from typing import Any, Literal, NamedTuple

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.legend import Legend
from matplotlib.lines import Line2D
from matplotlib.textpath import TextToPath
from matplotlib.ticker import ScalarFormatter
from matplotlib.transforms import Bbox
from numpy.typing import NDArray

from pounding.plot import new_figure
from pounding.plot.decimate import buckets_for_width, envelope_indices
from pounding.units import G

__all__ = ["Scale", "scale_for", "display_scale", "axes_grid", "plain_ticks", "history",
           "ground_panel", "fit_text", "titled_figure", "place_legend",
           "TITLE_SIZE", "LEGEND_SIZE"]

ShareAxes = bool | Literal["row", "col", "all", "none"]
"""Which axes share an x or y axis (:meth:`matplotlib.figure.Figure.subplots`)."""

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


def display_scale(unit: str | None, peak: float) -> Scale:
    """The unit a figure draws a quantity of SI ``unit`` in, for values up to ``peak``.

    Parameters
    ----------
    unit : str or None
        The SI unit (``pounding.units.unit_of``): ``m``, ``N``, ``J``, ``N/m``, ``kg``, … .
    peak : float
        The largest magnitude drawn (SI).

    Returns
    -------
    Scale
        :data:`MM` for lengths; for forces, energies and stiffnesses (units of N or J) the
        multiple that reads between 1 and 1000 (:func:`scale_for`); tonnes for masses of
        10 t and more; else ``unit`` itself (``""`` for None).
    """
    if unit == "m":
        return MM
    if unit and (unit == "J" or unit.startswith("N")):
        return scale_for(peak, unit)
    if unit == "kg" and abs(peak) >= 1e4:
        return Scale(1e-3, "t")
    return Scale(1.0, unit or "")


def axes_grid(fig: Figure, nrows: int, ncols: int, *, left: float = 0.85,
              right: float = 0.25, top: float = 0.55, bottom: float = 0.55,
              wspace: float = 0.45, hspace: float = 0.45,
              height_ratios: list[float] | None = None, sharex: ShareAxes = False,
              sharey: ShareAxes = False) -> NDArray[Any]:
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


_TEXT_PATH = TextToPath()

LINE_SPACING = 1.2
"""Line spacing of a wrapped title [font sizes] (matplotlib's default)."""


def text_width(text: str, size: float) -> float:
    """Width of one line of ``text`` at ``size`` points in the default font [in] (measured
    from the glyphs, without drawing)."""
    w, _, _ = _TEXT_PATH.get_text_width_height_descent(text, FontProperties(size=size),
                                                      ismath=False)
    return float(w) / 72.0


def fit_text(text: str, width: float, size: float, max_lines: int = 3) -> str:
    """``text`` broken into lines at most ``width`` inches wide at ``size`` points.

    Parameters
    ----------
    text : str
        One line (a title).
    width : float
        The room it has [in].
    size : float
        Font size [pt].
    max_lines : int
        At most this many lines; what does not fit in them is cut and the last line ends
        in "…" (so does a single word wider than ``width``).

    Returns
    -------
    str
        The lines joined by newlines; ``text`` itself when it fits on one line.
    """
    if text_width(text, size) <= width:
        return text
    space = text_width("a a", size) - text_width("aa", size)
    lines: list[str] = []
    line, used = "", 0.0
    for word in text.split():
        w = text_width(word, size)
        if line and used + space + w <= width:
            line, used = f"{line} {word}", used + space + w
            continue
        if line:
            lines.append(line)
        line, used = word, w
    lines.append(line)
    cut = len(lines) > max_lines
    lines = lines[:max_lines]
    for i, ln in enumerate(lines):
        last = cut and i == len(lines) - 1
        if last or text_width(ln, size) > width:
            while ln and text_width(ln + "…", size) > width:
                ln = ln[:-1]
            lines[i] = ln.rstrip() + "…"
    return "\n".join(lines)


def titled_figure(name: str, subject: str, width: float, height: float,
                  size: float = TITLE_SIZE + 1) -> tuple[Figure, float]:
    """A figure (:func:`pounding.plot.new_figure`) titled ``"name: subject"``, the title
    fitted to the page.

    Parameters
    ----------
    name : str
        What is drawn (a model's name, any length).
    subject : str
        What the figure shows.
    width, height : float
        Size of the page with a one-line title [in].
    size : float
        Font size of the title [pt].

    Returns
    -------
    tuple of (Figure, float)
        The figure, its title 0.1 in below the top, broken into at most three lines that
        fit 0.1 in clear of each edge (:func:`fit_text`; a name too long for that is cut,
        ending in "…", the subject kept whole); and the height the lines after the first
        add to the page [in]: add it to the top margin of the axes.
    """
    head, whole = name, " ".join(subject.split())
    while True:
        lines = fit_text(f"{head}: {subject}", width - 0.2, size)
        if " ".join(lines.split()).endswith(whole) or len(head) <= 1:
            break
        head = name[:int(len(head) * 0.9)].rstrip() + "…"  # shorter by a tenth, until it fits
    extra = lines.count("\n") * LINE_SPACING * size / 72.0
    fig = new_figure(width, height + extra)
    fig.suptitle(lines, fontsize=size, y=1.0 - 0.1 / fig.get_figheight(), va="top")
    return fig, extra


LegendPlace = Literal["upper right", "upper left", "lower left", "lower right", "center right",
                      "center left", "lower center", "upper center", "center"]
"""A place for a legend inside the axes (matplotlib's ``loc``)."""

_LEGEND_PLACES: tuple[LegendPlace, ...] = ("upper right", "upper left", "lower left", "lower right", "center right",
                  "center left", "lower center", "upper center", "center")


def place_legend(ax: Axes, *args: Any, **kw: Any) -> Legend:
    """A legend of ``ax`` that covers no drawn line or marker.

    The first of the nine places inside the axes (upper right, upper left, …) where no
    line and no marker of ``ax`` is under the legend; else beside the axes, on the right,
    top-aligned — on a figure without a layout engine the axes are then narrowed so that
    the legend ends inside the page.

    Parameters
    ----------
    ax : Axes
        The axes, with its lines drawn and its limits set.
    *args
        Handles and labels, as for :meth:`matplotlib.axes.Axes.legend`.
    **kw
        More options of :meth:`~matplotlib.axes.Axes.legend` (``fontsize``, ``ncol``, …).

    Returns
    -------
    matplotlib.legend.Legend

    Notes
    -----
    Draws the figure once to know the size of the legend and where the axes are; a figure
    whose layout engine then moves the axes keeps the legend's place relative to them.
    """
    fig = ax.figure.figure  # the page (a subfigure's too)
    legend = ax.legend(*args, **kw)
    fig.draw_without_rendering()
    size = legend.get_window_extent()
    pad = legend.borderaxespad * legend.prop.get_size_in_points() * fig.dpi / 72.0
    inner = ax.bbox.padded(-pad)
    lines = [ln for ln in ax.get_lines()
             if ln.get_visible() and np.asarray(ln.get_xydata()).size]
    for place in _LEGEND_PLACES:
        vert, horiz = place.split() if " " in place else (place, place)
        x0 = {"left": inner.x0, "right": inner.x1 - size.width,
              "center": inner.x0 + (inner.width - size.width) / 2}[horiz]
        y0 = {"lower": inner.y0, "upper": inner.y1 - size.height,
              "center": inner.y0 + (inner.height - size.height) / 2}[vert]
        box = Bbox.from_bounds(x0, y0, size.width, size.height)
        if not any(_line_under(ln, box) for ln in lines):
            legend.set_loc(place)
            return legend
    legend = ax.legend(*args, loc="upper left", bbox_to_anchor=(1.02, 1.0),
                       borderaxespad=0.0, **kw)
    if fig.get_layout_engine() is None:
        # fixed margins (no layout engine to make room): narrow the axes until the legend
        # beside them ends inside the page, with the margin the axes had
        fig.draw_without_rendering()
        over = legend.get_window_extent().x1 - (fig.bbox.x1 - pad)
        if over > 0.0:
            box = ax.get_position()
            width = max(box.width - over / fig.bbox.width, 0.25 * box.width)
            ax.set_position((box.x0, box.y0, width, box.height))
    return legend


def _line_under(line: Line2D, box: Bbox) -> bool:
    """True if ``line`` (its markers, or its stroke) is drawn inside ``box`` (display)."""
    mark = float(line.get_markersize()) if line.get_marker() not in (None, "", "None", " ",
                                                                     "none") else 0.0
    dpi = line.figure.dpi
    path = line.get_transform().transform_path(line.get_path())
    if line.get_linestyle() not in ("None", "", " ", "none"):
        if path.intersects_bbox(box.padded(line.get_linewidth() * dpi / 144.0), filled=False):
            return True
    if mark:
        near = box.padded(mark * dpi / 144.0)
        vertices = np.asarray(path.vertices)
        return bool(near.count_contains(vertices[np.isfinite(vertices).all(1)]))
    return False


def axes_width(ax: Axes) -> float:
    """Width of ``ax`` on the page [in]."""
    return float(ax.get_position().width * ax.figure.figure.get_figwidth())


def history(ax: Axes, t: NDArray[np.float64], y: NDArray[np.float64], **kw: Any) -> Any:
    """``ax.plot(t, y, **kw)`` of a long history, decimated for display by
    :func:`pounding.plot.decimate.envelope_indices` (every peak drawn exactly)."""
    idx = envelope_indices(y, buckets_for_width(axes_width(ax)))
    return ax.plot(t[idx], y[idx], **kw)[0]


def ground_panel(ax: Axes, time: NDArray[np.float64], ground: NDArray[np.float64],
                 name: str) -> None:
    """The ground acceleration [g] against time [s], its peak marked, in ``ax`` (the
    bottom panel of a time-history figure, sharing its time axis).

    ``ground`` is one history (nt,) or G components (nt, G) applied together, along the
    columns of the model's influence matrix: two are the site's x and y axes (a building in
    plan), drawn and labelled ``x`` and ``y``, each with its peak marked."""
    ag = np.asarray(ground, dtype=float) / G
    if ag.ndim == 1:
        ag = ag[:, None]
    n_comp = ag.shape[1]
    labels = (["x", "y"] if n_comp == 2 else [""] if n_comp == 1
              else [f"component {g + 1}" for g in range(n_comp)])
    colors = ["0.25"] if n_comp == 1 else [f"C{g}" for g in range(n_comp)]
    peaks = []
    for g in range(n_comp):
        history(ax, time, ag[:, g], color=colors[g], lw=0.6, label=labels[g] or None)
        if ag.shape[0]:
            k = int(np.abs(ag[:, g]).argmax())
            ax.plot([time[k]], [ag[k, g]], "o", ms=3, color="tab:red")
            peaks.append(f"{labels[g] + ' ' if labels[g] else ''}{abs(ag[k, g]):.3g} g at "
                         f"{time[k]:.2f} s")
    if peaks:
        # several components: their peaks first, so a long name is what gets cut
        text = (f"ground acceleration: {name}; peak {peaks[0]}" if n_comp == 1 else
                f"ground acceleration, peak {', '.join(peaks)}: {name}")
        ax.set_title(fit_text(text,
                              axes_width(ax), TITLE_SIZE, max_lines=1),
                     fontsize=TITLE_SIZE, loc="left")
    if n_comp > 1:
        ax.legend(loc="upper right", fontsize=TITLE_SIZE, ncols=n_comp, frameon=False)
    ax.axhline(0.0, color="0.6", lw=0.5)
    ax.set_ylabel("ground acc. [g]")
    ax.grid(True, alpha=0.3)

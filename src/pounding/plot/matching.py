"""Figure of a spectrum-compatible record (``pounding match --plot``): the target, the
seed record's spectrum as given and as scaled, the matched record's spectrum and the
tolerance band about the target, PSA [g] against period [s]."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

import numpy as np
from numpy.typing import NDArray

from pounding.plot import new_figure
from pounding.plot.layout import place_legend

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["MatchFigureData", "plot_match"]


class MatchFigureData(Protocol):
    """What the figure reads of a match (:class:`pounding.spectra.matching.MatchResult`):
    spectra [g] at the check periods [s], the first scale factor, the tolerance, the misfit
    reached and the damping ratio."""

    @property
    def periods(self) -> NDArray[np.float64]: ...
    @property
    def target_g(self) -> NDArray[np.float64]: ...
    @property
    def original_g(self) -> NDArray[np.float64]: ...
    @property
    def matched_g(self) -> NDArray[np.float64]: ...
    @property
    def scale_factor(self) -> float: ...
    @property
    def tolerance(self) -> float: ...
    @property
    def max_misfit(self) -> float: ...
    @property
    def damping(self) -> float: ...


def plot_match(result: MatchFigureData, record: str, target: str) -> Figure:
    """Target (black, dashed) with its ±tolerance band (grey), the seed as given (thin
    grey) and scaled by the match's first factor (dotted), and the matched record (blue),
    on a logarithmic period axis.

    Parameters
    ----------
    result : MatchFigureData
        The match: spectra [g] at its check periods [s].
    record, target : str
        Names of the seed record and of the target spectrum, for the legend and title.
    """
    from matplotlib.ticker import FuncFormatter

    t = result.periods
    tol = result.tolerance
    fig = new_figure(8.0, 5.0, layout="constrained", laid_out=False)
    ax = fig.subplots()
    ax.fill_between(t, (1.0 - tol) * result.target_g, (1.0 + tol) * result.target_g,
                    color="0.85", lw=0, label=f"target ±{100 * tol:g} %")
    ax.plot(t, result.original_g, color="0.55", lw=1.0, label=f"{record} (seed)")
    ax.plot(t, result.scale_factor * result.original_g, color="0.35", lw=1.0, ls=":",
            label=f"seed × {result.scale_factor:.3g}")
    ax.plot(t, result.matched_g, color="tab:blue", lw=1.6,
            label=f"matched (within {100 * result.max_misfit:.1f} %)")
    ax.plot(t, result.target_g, color="black", lw=1.2, ls="--", label=target)
    ax.set_xscale("log")
    ax.xaxis.set_major_formatter(FuncFormatter(lambda x, _: f"{x:g}"))
    ax.set_xlim(float(t[0]), float(t[-1]))
    ax.set_ylim(bottom=0.0)
    ax.set_xlabel("period T [s]")
    ax.set_ylabel(f"pseudo-acceleration PSA [g] ({100 * result.damping:g} % damping)")
    ax.grid(True, which="both", lw=0.3, alpha=0.6)
    ax.set_title(f"{record} matched to {target}")
    place_legend(ax, fontsize=8)
    return fig

"""Figure of response spectra: pseudo-acceleration PSA [g] against period [s], one line per
record and damping ratio (or per RotD measure), with design spectra dashed."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from pounding.plot import new_figure

if TYPE_CHECKING:  # `pounding spectrum` imports this module when drawing only
    from matplotlib.figure import Figure

    from pounding.spectra import DesignSpectrum

__all__ = ["plot_spectra"]


def plot_spectra(periods: NDArray[np.float64],
                 curves: Sequence[tuple[str, NDArray[np.float64]]],
                 designs: Sequence[DesignSpectrum] = (), title: str = "Response spectra",
                 log_period: bool = True) -> Figure:
    """Draw PSA curves [g] against period [s].

    Parameters
    ----------
    periods : array
        Periods [s] shared by the curves.
    curves : sequence of (label, PSA [g]) pairs
        One line each (label: record and damping ratio, or a RotD measure).
    designs : sequence of DesignSpectrum
        Drawn in black, dashed, dotted, ... (Sa [g]) over the periods of the plot that their tables cover.
    title : str
        Figure title.
    log_period : bool
        Periods on a logarithmic axis (the default periods are log-spaced).
    """
    fig = new_figure(8.0, 5.0, layout="constrained", laid_out=False)
    ax = fig.subplots()
    for label, psa in curves:
        ax.plot(periods, psa, lw=1.2, label=label)
    styles = ("--", ":", "-.", (0, (5, 2, 1, 2)))
    for n, spec in enumerate(designs):
        lo, hi = max(spec.periods[0], float(periods.min())), min(spec.periods[-1],
                                                                 float(periods.max()))
        if hi <= lo:
            continue
        t = np.geomspace(max(lo, 1e-3), hi, 400) if log_period else np.linspace(lo, hi, 400)
        t = np.union1d(t, spec.periods[(spec.periods >= lo) & (spec.periods <= hi)])
        t = t[t > 0.0]
        ax.plot(t, spec.sa_g(t), linestyle=styles[n % len(styles)], color="black", lw=1.2,
                label=spec.name)
    if log_period:
        from matplotlib.ticker import FuncFormatter

        ax.set_xscale("log")
        ax.xaxis.set_major_formatter(FuncFormatter(lambda x, _: f"{x:g}"))
    ax.set_xlabel("period T [s]")
    ax.set_ylabel("pseudo-acceleration PSA [g]")
    ax.set_ylim(bottom=0.0)
    ax.grid(True, which="both", lw=0.3, alpha=0.6)
    ax.legend(fontsize=8)
    ax.set_title(title)
    return fig

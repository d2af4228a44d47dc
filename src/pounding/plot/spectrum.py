"""Figure of response spectra: pseudo-acceleration PSA [g] against period [s], one line per
record and damping ratio (or per RotD measure), with design spectra dashed."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from pounding.plot import new_figure
from pounding.plot.layout import place_legend

if TYPE_CHECKING:  # `pounding spectrum` imports this module when drawing only
    from matplotlib.figure import Figure

    from pounding.spectra import DesignSpectrum

__all__ = ["plot_spectra", "plot_suite_scaling"]


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
    ax.set_title(title)
    place_legend(ax, fontsize=8)  # where it hides no curve, else beside the axes
    return fig


def plot_suite_scaling(periods: NDArray[np.float64], scaled: NDArray[np.float64],
                       names: Sequence[str], target: DesignSpectrum,
                       period: float, period_range: tuple[float, float],
                       code_ratio: float | None = None,
                       title: str = "Suite scaled to the target") -> Figure:
    """Each record's scaled spectrum (thin), the suite's mean (thick), the target (black,
    dashed), ``code_ratio`` × the target (dotted, where a code's rule applies), the period
    range checked (shaded) and T1.

    Parameters
    ----------
    periods : array
        Periods [s] of the spectra.
    scaled : (m, n) array
        PSA [g] of each scaled record on ``periods``.
    names : sequence of str
        Record names (the legend lists at most ten).
    target : DesignSpectrum
        The target spectrum (Sa [g]).
    period : float
        The structure's period T1 [s].
    period_range : (float, float)
        The range the scaling was checked over [s].
    code_ratio : float, optional
        Draw this fraction of the target (0.9 for ASCE 7-22 and EN 1998-1).
    """
    fig = new_figure(10.5, 5.0, layout="constrained", laid_out=False)
    ax = fig.subplots()
    ax.axvspan(*period_range, color="0.92", zorder=0, label=f"range {period_range[0]:.3g}–"
               f"{period_range[1]:.3g} s")
    for k, (name, psa) in enumerate(zip(names, scaled, strict=True)):
        ax.plot(periods, psa, lw=0.8, alpha=0.7, label=name if k < 10 else None)
    ax.plot(periods, scaled.mean(axis=0), color="C3", lw=2.5, label="mean of the suite")
    inside = periods[(periods >= target.periods[0]) & (periods <= target.periods[-1])]
    sa = np.asarray(target.sa_g(inside))
    ax.plot(inside, sa, color="black", ls="--", lw=1.5, label=target.name)
    if code_ratio is not None:
        ax.plot(inside, code_ratio * sa, color="black", ls=":", lw=1.2,
                label=f"{code_ratio:g} × target")
    ax.axvline(period, color="0.3", lw=0.8)
    ax.annotate(f"T1 = {period:g} s", (period, 0.98), xycoords=("data", "axes fraction"),
                ha="left", va="top", fontsize=8, xytext=(3, 0), textcoords="offset points")
    from matplotlib.ticker import FuncFormatter

    ax.set_xscale("log")
    ax.xaxis.set_major_formatter(FuncFormatter(lambda x, _: f"{x:g}"))
    ax.set_xlabel("period T [s]")
    ax.set_ylabel("pseudo-acceleration PSA [g]")
    ax.set_ylim(bottom=0.0)
    ax.grid(True, which="both", lw=0.3, alpha=0.6)
    fig.legend(loc="outside right upper", fontsize=7)  # beside the axes: nothing hidden
    ax.set_title(title, fontsize=10)
    return fig

"""Figure of a ground-motion record: acceleration, velocity and displacement against time."""

from __future__ import annotations

from typing import TYPE_CHECKING

from pounding.plot import new_figure
from pounding.plot.layout import MM
from pounding.units import G

if TYPE_CHECKING:  # `pounding record` imports this module at start-up: no matplotlib here
    from matplotlib.figure import Figure

    from pounding.ground_motion import GroundMotion

__all__ = ["plot_record"]


def plot_record(gm: GroundMotion) -> Figure:
    """Draw a record's acceleration [g], velocity [m/s] and displacement [mm] against time [s].

    Velocity and displacement are :meth:`GroundMotion.velocity` and
    :meth:`GroundMotion.displacement` (trapezoidal, no baseline correction); each panel marks
    its peak.

    Parameters
    ----------
    gm : GroundMotion
        The record.

    Returns
    -------
    matplotlib.figure.Figure
        Three stacked panels sharing the time axis, titled with ``gm.name``; save it with
        :func:`pounding.plot.save_figure`.
    """
    t = gm.time
    series = [
        (gm.accel / G, "acceleration [g]", "PGA", "g", "tab:red"),
        (gm.velocity(), "velocity [m/s]", "PGV", "m/s", "tab:blue"),
        (gm.displacement() * MM.factor, f"displacement [{MM.unit}]", "PGD", MM.unit,
         "tab:green"),
    ]
    fig = new_figure(8.0, 7.0, layout="constrained", laid_out=False)
    axes = fig.subplots(3, 1, sharex=True)
    for ax, (y, label, peak_name, unit, colour) in zip(axes, series, strict=True):
        ax.plot(t, y, color=colour, lw=0.8)
        ax.axhline(0.0, color="0.6", lw=0.5)
        k = int(abs(y).argmax())
        ax.plot([t[k]], [y[k]], "o", color="black", ms=4)
        ax.annotate(f"{peak_name} = {abs(y[k]):.3g} {unit}", (t[k], y[k]),
                    xytext=(6, 0), textcoords="offset points", va="center", fontsize=8)
        ax.set_ylabel(label)
        ax.grid(True, lw=0.3, alpha=0.6)
    axes[-1].set_xlabel("time [s]")
    axes[-1].set_xlim(0.0, max(gm.duration, gm.dt))
    fig.suptitle(f"{gm.name}  (dt = {gm.dt:g} s, {gm.npts} points, read in {gm.units_read})")
    return fig

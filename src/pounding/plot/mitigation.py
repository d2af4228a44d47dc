"""The trade-off of retrofit options (``pounding mitigate``): impacts against floor
accelerations, and drift and the energy the devices dissipate."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from pounding.plot import new_figure

if TYPE_CHECKING:
    import pandas as pd
    from matplotlib.figure import Figure

__all__ = ["plot_mitigation"]

G = 9.80665


def plot_mitigation(summary: "pd.DataFrame", title: str = "") -> "Figure":
    """Two panels from :func:`pounding.studies.mitigation.summarise`: (left) each option's
    peak impact force of the buildings' contacts [MN] against its peak absolute floor
    acceleration [g], labelled; (right) peak storey drift ratio [%] per option, and the
    energy its devices dissipated [MJ] (pads and links) on a second axis."""
    fig = new_figure(12, 5.2, laid_out=False, layout="constrained")
    ax, bx = fig.subplots(1, 2)
    names = list(summary.index)
    acc = summary["peak_abs_accel_m_s2"].to_numpy() / G
    force = summary["peak_impact_force_N"].to_numpy() / 1e6
    colours = [f"C{i % 10}" for i in range(len(names))]
    for i, name in enumerate(names):
        ax.scatter(acc[i], force[i], s=60, color=colours[i], zorder=3)
        ax.annotate(name, (acc[i], force[i]), textcoords="offset points",
                    xytext=(6, -12 if i % 2 else 4),
                    fontsize=8)
    ax.set_xlabel("peak absolute floor acceleration [g]")
    ax.set_ylabel("peak impact force, buildings' contacts [MN]")
    ax.set_title("impacts against floor accelerations (mean over records)", fontsize=10)
    ax.grid(alpha=0.3)
    x = np.arange(len(names))
    drift = summary["peak_drift_ratio"].to_numpy() * 100
    bx.bar(x - 0.2, drift, width=0.4, color=colours, alpha=0.85, label="peak drift ratio")
    bx.set_ylabel("peak storey drift ratio [%]")
    bx.set_xticks(x, names, rotation=25, ha="right", fontsize=8)
    cx = bx.twinx()
    energy = (summary["pads_dissipated_J"] + summary["links_dissipated_J"]).to_numpy() / 1e6
    cx.bar(x + 0.2, energy, width=0.4, color="0.55", label="dissipated by devices")
    cx.set_ylabel("energy dissipated by the devices [MJ]")
    handles = [bx.patches[0], cx.patches[0]] if len(names) else []
    bx.legend(handles, ["peak drift ratio (colour)", "dissipated by devices (grey)"],
              fontsize=8, loc="upper right")
    bx.set_title("storey drift and device energy", fontsize=10)
    if title:
        fig.suptitle(f"{title}: retrofit options")
    return fig

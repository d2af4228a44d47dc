"""Force–deformation loops of one simulation: the contacts (force against penetration
while closed, the seed's Fig 2) and the yielding storeys (shear against drift).

Deformations are in mm, forces in the multiple of N that reads between 1 and 1000
(:func:`pounding.plot.layout.scale_for`); every panel of a figure shares both axes, so the
loops compare at a glance. Each function returns a :class:`matplotlib.figure.Figure` on its
own Agg canvas; save it with :func:`pounding.plot.save_figure`.
"""

from __future__ import annotations

import math

import matplotlib
import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from numpy.typing import NDArray

from pounding.plot.layout import MM, TITLE_SIZE, axes_grid, plain_ticks, scale_for, titled_figure
from pounding.result import Result, peak_abs

__all__ = ["MAX_HYSTERESIS_PANELS", "MAX_STOREY_PANELS", "plot_hysteresis",
           "plot_storey_hysteresis"]

MAX_HYSTERESIS_PANELS = 12
"""At most this many contacts get a hysteresis panel (those with the largest peak force)."""

MAX_STOREY_PANELS = 3
"""Storeys drawn per yielding building in the storey figure (those of largest peak drift)."""

PANEL_SIZE = (3.1, 2.3)
"""Width and height of one loop panel [in]."""


def _closed_runs(pen: NDArray[np.float64], force: NDArray[np.float64]
                 ) -> list[NDArray[np.float64]]:
    """The stretches of consecutive samples with δ > 0, each an (n, 2) array of (δ, F)."""
    closed = pen > 0.0
    if not closed.any():
        return []
    edges = np.flatnonzero(np.diff(np.concatenate([[0], closed.view(np.int8), [0]])))
    return [np.column_stack([pen[a:b], force[a:b]]) for a, b in zip(edges[::2], edges[1::2])]


def plot_hysteresis(result: Result) -> Figure:
    """Force [kN or MN] against penetration [mm] while each contact is closed (the seed's
    Fig 2).

    One panel per contact that had an impact (at most :data:`MAX_HYSTERESIS_PANELS`, those
    with the largest peak force), all on the same scales; each impact is one loop, later
    impacts lighter. The area of a loop is the energy the impact dissipated.
    """
    model = result.model
    imp = result.impact_array  # (numpy, not the DataFrame: drawing needs no pandas)
    hit = set(int(c) for c in imp[:, 0])
    peak = result.peak_contact_force
    chosen = sorted((c for c in model.contacts if c.index in hit),
                    key=lambda c: -peak[c.index])[:MAX_HYSTERESIS_PANELS]
    chosen.sort(key=lambda c: c.index)
    n = max(len(chosen), 1)
    ncol = min(n, 3 if n > 4 else n)
    nrow = math.ceil(n / ncol)
    force = scale_for(float(peak.max()) if peak.size else 0.0, "N")
    width, height = PANEL_SIZE
    more = len(hit) - len(chosen)
    fig, extra = titled_figure(
        model.name, "contact hysteresis while closed (dark: early impacts, light: late)"
        + (f"; {more} more contact(s) not shown" if more > 0 else ""),
        0.8 + ncol * width + (ncol - 1) * 0.25 + 0.25,
        0.6 + nrow * height + (nrow - 1) * 0.45 + 0.55)
    axes = axes_grid(fig, nrow, ncol, left=0.8, right=0.25, top=0.6 + extra, bottom=0.55,
                     wspace=0.25, hspace=0.45, sharex=True, sharey=True).ravel()
    cmap = matplotlib.colormaps["plasma"]
    t = result.time
    starts = imp[:, 1]
    ends = imp[:, 2]
    for ax, c in zip(axes, chosen):
        sel_rows = np.flatnonzero(imp[:, 0] == c.index)
        pen = result.penetration[:, c.index] * MM.factor
        f = result.contact_force[:, c.index] * force.factor
        segments, colours = [], []
        k_rows = sel_rows.size
        for i, r in enumerate(sel_rows):
            end = ends[r] if np.isfinite(ends[r]) else t[-1]
            # the samples within one output step of the impact
            a = max(int(np.ceil(starts[r] / result.dt - 1.0)), 0)
            b = min(int(np.floor(end / result.dt + 1.0)) + 1, t.size)
            runs = _closed_runs(pen[a:b], f[a:b])
            segments += runs
            colours += [cmap(0.85 * i / max(k_rows - 1, 1))] * len(runs)
        ax.add_collection(LineCollection(segments, colors=colours, linewidths=0.9))
        e_diss = float(np.nansum(imp[sel_rows, 8]))  # energy dissipated [J]
        joules = scale_for(e_diss, "J")
        ax.set_title(f"{c.label} ({c.elevation:g} m): {k_rows} impact(s), "
                     f"{e_diss * joules.factor:.3g} {joules.unit}", fontsize=TITLE_SIZE - 1)
        ax.axhline(0.0, color="0.6", lw=0.5)
        ax.grid(True, alpha=0.3)
    for ax in axes[len(chosen):]:
        ax.set_axis_off()
    if chosen:
        axes[0].autoscale_view()
    else:
        axes[0].set_axis_on()
        axes[0].text(0.5, 0.5, "no impact" if model.contacts else
                     "no contacts (a single building)", transform=axes[0].transAxes,
                     ha="center", va="center", color="0.4")
    n_drawn = max(len(chosen), 1)
    for i, ax in enumerate(axes[:n_drawn]):
        if i % ncol == 0:
            ax.set_ylabel(f"contact force [{force.unit}]")
        if i + ncol >= n_drawn:  # the lowest panel of its column (the last row may be short)
            ax.set_xlabel(f"penetration δ [{MM.unit}]")
            ax.xaxis.set_tick_params(labelbottom=True)
    return plain_ticks(fig)


def plot_storey_hysteresis(result: Result) -> Figure:
    """Storey shear [kN or MN] against storey drift [mm] of the yielding storeys; an
    isolation bearing's force against its displacement, titled as the bearing it is.

    One row per building with yielding storeys, its :data:`MAX_STOREY_PANELS` storeys of
    largest peak drift; the yield shears ``±F_y`` are dashed and each title gives the
    ductility demand and the residual drift. Buildings with linear storeys are left out
    (their loop is a straight line of slope ``k``); a model with none yielding gets one
    panel saying so (:func:`pounding.plot.registry.figures_for` does not draw it then).
    """
    model = result.model
    rows = [b for b, bl in enumerate(model.buildings) if bl.is_inelastic]
    ncol = max(1, min(MAX_STOREY_PANELS, max((len(model.buildings[b].yielding) for b in rows),
                                             default=1)))
    nrow = max(len(rows), 1)
    drift, shear = result.drift, result.storey_shear
    peak = peak_abs(drift)
    cols = [model.system.offsets[b] + j for b in rows for j in model.buildings[b].yielding]
    force = scale_for(float(peak_abs(shear[:, cols]).max()) if cols else 0.0, "N")
    width, height = PANEL_SIZE
    n_bearings = int(result.is_bearing.sum())
    subject = ("force against displacement of the isolation bearings"
               if n_bearings and n_bearings == len(cols) else
               "storey shear against drift of the yielding storeys"
               + (", force against displacement of the bearings" if n_bearings else ""))
    fig, extra = titled_figure(model.name, subject + " (dashed: yield force)",
                               0.8 + ncol * width + (ncol - 1) * 0.25 + 0.25,
                               0.9 + nrow * height + (nrow - 1) * 1.0 + 0.55)
    # one row per building, its storeys on the same shear scale
    axes = axes_grid(fig, nrow, ncol, left=0.8, right=0.25, top=0.9 + extra, bottom=0.55,
                     wspace=0.25, hspace=1.0, sharey="row")
    for ax_row, b in zip(axes, rows):
        bl, off = model.buildings[b], model.system.offsets[b]
        order = sorted(sorted(bl.yielding, key=lambda j: -peak[off + j])[:ncol])
        fy = bl.yield_forces
        for ax, j in zip(ax_row, order):
            col = off + j
            ax.plot(drift[:, col] * MM.factor, shear[:, col] * force.factor, lw=0.7,
                    color="tab:blue")
            if fy is not None:
                for sgn in (1.0, -1.0):
                    ax.axhline(sgn * fy[j] * force.factor, color="0.5", lw=0.6, ls="--")
            if result.is_bearing[col]:  # an isolation bearing, not a storey
                iso = getattr(bl, "isolator", None)
                ax.set_title(f"B{b + 1} bearing, {getattr(iso, 'label', 'isolator')}: peak "
                             f"{peak[col] * MM.factor:.3g} mm\nresidual "
                             f"{result.residual_drift[col] * MM.factor:+.3g} mm",
                             fontsize=TITLE_SIZE - 1)
                ax.set_xlabel(f"bearing displacement [{MM.unit}]")
                ax.set_ylabel(f"bearing force [{force.unit}]")
                ax.yaxis.set_tick_params(labelleft=True)
            else:
                storey = j + 1 - int(result.is_bearing[off])  # above a base slab: from 1
                ax.set_title(f"B{b + 1} storey {storey}: peak drift "
                             f"{peak[col] * MM.factor:.3g} mm\nductility "
                             f"{result.ductility[col]:.2f}, residual "
                             f"{result.residual_drift[col] * MM.factor:+.3g} mm",
                             fontsize=TITLE_SIZE - 1)
                ax.set_xlabel(f"storey drift [{MM.unit}]")
            ax.axhline(0.0, color="0.7", lw=0.4)
            ax.axvline(0.0, color="0.7", lw=0.4)
            ax.grid(True, alpha=0.3)
        if order and not result.is_bearing[off + order[0]]:
            ax_row[0].set_ylabel(f"storey shear [{force.unit}]")
        for ax in ax_row[len(order):]:
            ax.set_axis_off()
    if not rows:
        ax = axes[0][0]
        ax.text(0.5, 0.5, "no yielding storeys", transform=ax.transAxes, ha="center",
                va="center", color="0.4")
        ax.set_xlabel(f"storey drift [{MM.unit}]")
        ax.set_ylabel(f"storey shear [{force.unit}]")
    return plain_ticks(fig)

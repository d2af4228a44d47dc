"""The envelope figure: peak displacement, storey drift ratio and storey shear against
height, one profile per building — the figure an engineer draws first.

The quantities are :class:`pounding.result.Result`'s peaks, located inside solver steps:
peak ``|u|`` of each floor, peak ``|drift| / h`` of each storey (drift ``u_j − u_{j−1}``,
storey height ``h_j``) and peak ``|V|`` of each storey.
"""

from __future__ import annotations

from typing import NamedTuple

import matplotlib
import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.transforms import blended_transform_factory
from numpy.typing import NDArray

from pounding.plot.layout import (
    LEGEND_SIZE,
    MM,
    Scale,
    axes_grid,
    axes_width,
    fit_text,
    plain_ticks,
    scale_for,
    titled_figure,
)
from pounding.result import Result

__all__ = ["Envelopes", "envelopes", "plot_envelopes"]

DRIFT_RATIO = Scale(100.0, "%")
"""Drift ratios are drawn in per cent."""
LEGEND_COLUMN = 1.85
"""Widest building name in the legend [in]: four columns fit the page; longer names are cut."""


class Envelopes(NamedTuple):
    """Peak responses of every floor / storey of a result (SI units, in the floor order of
    :class:`pounding.model.PoundingModel`)."""

    displacement: NDArray[np.float64]
    """Peak |displacement| of each floor relative to the ground [m] (N,)."""
    drift_ratio: NDArray[np.float64]
    """Peak |storey drift| / storey height of each storey (the storey below each floor)
    [-] (N,); NaN under a base slab (its isolation bearing is no storey)."""
    shear: NDArray[np.float64]
    """Peak |storey shear| of each storey [N] (N,)."""


def envelopes(result: Result) -> Envelopes:
    """The peak displacement, drift ratio and storey shear of every floor of ``result``
    (:attr:`~pounding.result.Result.peak_displacement`, :attr:`~pounding.result.Result.
    peak_drift_ratio`, :attr:`~pounding.result.Result.peak_storey_shear`)."""
    return Envelopes(displacement=result.peak_displacement,
                     drift_ratio=result.peak_drift_ratio,
                     shear=result.peak_storey_shear)


def _floor_profile(levels: NDArray[np.float64], values: NDArray[np.float64]
                   ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """A floor quantity as a line from the ground (0 at elevation 0) through each floor."""
    return np.concatenate([[0.0], values]), np.concatenate([[0.0], levels])


def _storey_profile(levels: NDArray[np.float64], values: NDArray[np.float64],
                    base: float = 0.0) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """A storey quantity as steps: constant over each storey, from its floor below to its
    floor above; the lowest storey starts at ``base`` [m] (the ground, or the base slab of
    an isolated building)."""
    bottoms = np.concatenate([[base], levels[:-1]])
    z = np.column_stack([bottoms, levels]).ravel()
    return np.repeat(values, 2), z


def _mark_contacts(ax: Axes, result: Result) -> None:
    """Triangles on the right edge at each contact elevation: filled where impacts
    happened, hollow where the gap never closed."""
    hit = result.peak_contact_force > 0.0
    tr = blended_transform_factory(ax.transAxes, ax.transData)
    z = np.array([c.elevation for c in result.model.contacts])
    for closed, face in ((True, "tab:red"), (False, "none")):
        sel = hit == closed
        if sel.any():
            ax.plot(np.ones(int(sel.sum())), z[sel], "<", ms=5, mec="tab:red", mfc=face,
                    transform=tr, clip_on=False, zorder=5)


def plot_envelopes(result: Result) -> Figure:
    """Peak |displacement| [mm], peak |storey drift ratio| [%] and peak |storey shear|
    [kN or MN, by magnitude] against height [m], one line per building.

    Displacements are drawn floor by floor from 0 at the ground; drift ratio and shear are
    storey quantities, drawn as steps over each storey's height. An isolated building's
    drift ratio and shear are its superstructure's, from its base slab up: the isolation
    bearing under the slab is no storey, and its peak displacement and force are written in
    the drift panel instead. A building in plan is drawn along x (solid) and along y
    (dashed) at its floors' centres of mass, its shears from its lateral elements.
    Triangles on the right edge of each panel mark the contact elevations: filled where the
    floors hit, hollow where the gap never closed.
    """
    from pounding.structure.assembly import floor_dofs

    model = result.model
    env = envelopes(result)
    plans = {ps.building: ps for ps in result.plan_storeys}
    bearing = result.is_bearing
    shears = [env.shear[~bearing]] + [ps.shear_y for ps in plans.values()]
    largest_shear = max((float(np.nanmax(v)) for v in shears if np.isfinite(v).any()),
                        default=0.0)
    # a matrix building has no storey shear (NaN): no line in that panel
    force = scale_for(largest_shear, "N")
    fig, extra = titled_figure(model.name, "peak response against height "
                               f"({result.motion.name})", 10.0, 4.4)
    ax_u, ax_d, ax_v = axes_grid(fig, 1, 3, left=0.7, right=0.3, top=0.45 + extra,
                                 bottom=0.95, wspace=0.5, sharey=True)[0]
    colours = matplotlib.colormaps["tab10"]
    panels = ((ax_u, MM, "peak |displacement|"),
              (ax_d, DRIFT_RATIO, "peak |storey drift ratio|"),
              (ax_v, force, "peak |storey shear|"))
    no_shear: list[str] = []
    notes: list[str] = []
    largest = [0.0, 0.0, 0.0]
    for b, (bl, off) in enumerate(zip(model.buildings, model.system.offsets)):
        floors = floor_dofs(bl)  # by elevation; a matrix building's other DOFs left out
        storeys = np.array([j for j in floors if not bearing[off + j]], dtype=np.int64)
        base = float(bl.floor_levels[floors[0]]) if bearing[off] else 0.0
        name = fit_text(f"B{b + 1}" + (f" {bl.name}" if bl.name and bl.name != f"B{b + 1}"
                                       else ""), LEGEND_COLUMN, LEGEND_SIZE + 1, max_lines=1)
        ps = plans.get(b)
        lines = [("" if ps is None else " x", "-", env.displacement[off + floors],
                  env.drift_ratio[off + storeys], env.shear[off + storeys])]
        if ps is not None:
            lines.append((" y", "--", ps.displacement_y, ps.drift_ratio_y, ps.shear_y))
        for suffix, style, disp, ratio, shear in lines:
            label = name + suffix
            colour = colours(b % 10)
            x, z = _floor_profile(bl.floor_levels[floors], disp * MM.factor)
            ax_u.plot(x, z, color=colour, ls=style, lw=1.6, marker="o", ms=3, label=label)
            largest[0] = max(largest[0], float(np.nanmax(x)))
            for k, (ax, values, unit) in enumerate(((ax_d, ratio, DRIFT_RATIO),
                                                    (ax_v, shear, force)), start=1):
                if np.isnan(values).all():
                    if k == 2 and f"B{b + 1}" not in no_shear:
                        no_shear.append(f"B{b + 1}")
                    continue
                x, z = _storey_profile(bl.floor_levels[storeys], values * unit.factor, base)
                ax.plot(x, z, color=colour, ls=style, lw=1.6, label=label)
                largest[k] = max(largest[k], float(np.nanmax(x)))
        if bearing[off]:
            bp = next(x for x in result.bearings if x.building == b)
            bf = scale_for(bp.peak_force, "N")
            notes.append(f"B{b + 1} isolation bearing ({bp.kind}, not a storey): "
                         f"{bp.peak_displacement * MM.factor:.4g} mm, "
                         f"{bp.peak_force * bf.factor:.4g} {bf.unit}")
    top = max(float(bl.total_height) for bl in model.buildings)
    for (ax, unit, what), big in zip(panels, largest):
        ax.set_xlabel(f"{what} [{unit.unit}]")
        ax.set_xlim(0.0, 1.1 * big if big > 0.0 else 1.0)
        ax.grid(True, alpha=0.3)
        if model.contacts:
            _mark_contacts(ax, result)
    if no_shear:
        ax_v.text(0.03, 0.98, f"no storey shear: {', '.join(no_shear)} given as matrices",
                  transform=ax_v.transAxes, va="top", fontsize=LEGEND_SIZE)
    if notes:
        ax_d.text(0.03, 0.98, fit_text("; ".join(notes), axes_width(ax_d) - 0.1,
                                       LEGEND_SIZE, max_lines=4),
                  transform=ax_d.transAxes, va="top", fontsize=LEGEND_SIZE)
    ax_u.set_ylim(0.0, top * 1.04)
    ax_u.set_ylabel("height above ground [m]")
    handles, labels = ax_u.get_legend_handles_labels()
    hit = result.peak_contact_force > 0.0
    for shown, face, text in ((hit.any(), "tab:red", "contact elevation, impacts"),
                              ((~hit).any(), "none", "contact elevation, gap never closed")):
        if shown:
            handles.append(Line2D([], [], ls="", marker="<", ms=5, mec="tab:red", mfc=face))
            labels.append(text)
    fig.legend(handles, labels, loc="lower center", ncol=min(len(labels), 4),
               fontsize=LEGEND_SIZE + 1, frameon=False,
               bbox_to_anchor=(0.5, 0.02 / fig.get_figheight()))
    return plain_ticks(fig)

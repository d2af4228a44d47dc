"""Time-history figures of one simulation (:class:`pounding.result.Result`): floor
displacements and contact forces (each with the ground acceleration in a panel below,
sharing the time axis), and the energy balance.

Each function returns a :class:`matplotlib.figure.Figure` on its own Agg canvas, built
without pyplot; save it with :func:`pounding.plot.save_figure`. Histories are drawn
decimated for display (:mod:`pounding.plot.decimate`): every peak is drawn exactly.
Displacements are in mm, forces and energies in the multiple of N and J that reads between
1 and 1000 (:func:`pounding.plot.layout.scale_for`), no axis uses offset or scientific
notation.
"""

from __future__ import annotations

import math
from collections import defaultdict

import matplotlib
import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from pounding.plot.decimate import buckets_for_width, union_indices
from pounding.plot.layout import (
    LEGEND_SIZE,
    MM,
    TITLE_SIZE,
    axes_grid,
    axes_width,
    fit_text,
    ground_panel,
    history,
    plain_ticks,
    scale_for,
    text_width,
    titled_figure,
)
from pounding.plot.loops import plot_hysteresis, plot_storey_hysteresis
from pounding.plot.registry import RUN_FIGURES, RunFigure, figures_for
from pounding.result import Result

__all__ = ["plot_contact_forces", "plot_displacements", "plot_energy", "contact_floors",
           # re-exported for callers of the former single module
           "plot_hysteresis", "plot_storey_hysteresis", "RUN_FIGURES", "RunFigure",
           "figures_for"]

PANEL_HEIGHT = 2.1
"""Height of one response panel [in]."""
GROUND_HEIGHT = 1.1
"""Height of the ground-acceleration panel [in]."""
ENERGY_COLOURS = {"kinetic": "tab:blue", "elastic strain": "tab:orange",
                  "structural damping": "tab:green", "hysteretic (storeys yielding)": "tab:brown",
                  "hysteretic (isolation bearings)": "tab:brown",
                  "hysteretic (yielding storeys and bearings)": "tab:brown",
                  "dissipated by links": "tab:cyan", "dissipated in contacts": "tab:red",
                  "stored in closed contacts": "tab:purple"}
"""One colour per energy term, the same in every run."""
_CHAR_WIDTH = 0.052
"""Mean width of a legend character at :data:`LEGEND_SIZE` [in] (for the legend column)."""


def _empty(ax: Axes, text: str) -> None:
    ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center", va="center", color="0.4")


def contact_floors(result: Result) -> dict[int, set[int]]:
    """For each building (0-based), the 0-based floors that take part in a contact."""
    out: dict[int, set[int]] = defaultdict(set)
    for c in result.model.contacts:
        for point in (c.left, c.right):
            if point.building >= 0:  # not a wall's side
                out[point.building].add(point.upper)
    return out


def _building_label(result: Result, b: int) -> str:
    name = result.model.buildings[b].name
    return f"B{b + 1}" + (f" ({name})" if name and name != f"B{b + 1}" else "")


def _legend_columns(labels: list[str], rows: int) -> tuple[int, float]:
    """Columns of a legend of ``labels`` with at most ``rows`` rows, and its width [in]."""
    ncol = max(1, math.ceil(len(labels) / max(rows, 1)))
    longest = max((len(s) for s in labels), default=0)
    # wide glyphs (the '@' and '=' of a contact in plan) measured, not counted
    measured = max((text_width(s, LEGEND_SIZE) for s in labels), default=0.0)
    return ncol, ncol * (0.35 + max(_CHAR_WIDTH * longest, measured + 0.05))


def _history_figure(result: Result, n_panels: int, legend_width: float, subject: str
                    ) -> tuple[Figure, list[Axes], Axes]:
    """A figure titled with the model's name and ``subject``, of ``n_panels`` response panels
    and the ground panel below, time shared."""
    fig, extra = titled_figure(result.model.name, subject, 10.0 + legend_width,
                               0.55 + n_panels * (PANEL_HEIGHT + 0.4) + GROUND_HEIGHT + 0.55)
    axes = axes_grid(fig, n_panels + 1, 1, left=0.8, right=0.25 + legend_width,
                     top=0.55 + extra, bottom=0.55, hspace=0.4,
                     height_ratios=[PANEL_HEIGHT] * n_panels + [GROUND_HEIGHT],
                     sharex="col")[:, 0]
    ground_panel(axes[-1], result.time, result.ground, result.motion.name)
    axes[-1].set_xlabel("time [s]")
    axes[-1].set_xlim(0.0, float(result.time[-1]) if result.time.size > 1 else 1.0)
    return fig, list(axes[:-1]), axes[-1]


def plot_displacements(result: Result) -> Figure:
    """Displacement histories [mm] of each building's roof and of every floor with a
    contact, one panel per building, the ground acceleration [g] below.

    The roof is drawn thick; the legend names each floor (``F3``; of a building in plan
    ``F3 x``, its floor 3 along x; of a matrix building its DOF label) with its elevation
    [m].
    """
    from pounding.result import floor_name
    from pounding.structure.assembly import floor_dofs

    model = result.model
    t = result.time
    floors = contact_floors(result)
    roofs = [int(floor_dofs(bl)[-1]) for bl in model.buildings]  # the highest floor
    shown = [sorted(floors.get(b, set()) | {roofs[b]}) for b in range(len(model.buildings))]
    # floors by name: F3 (shear building), F3 x (in plan: floor 3 along x), a matrix label
    labels = [[f"{floor_name(bl, j)} (roof, {bl.floor_levels[j]:g} m)" if j == roof
               else f"{floor_name(bl, j)} ({bl.floor_levels[j]:g} m)" for j in show]
              for bl, show, roof in zip(model.buildings, shown, roofs)]
    rows = int(PANEL_HEIGHT / 0.15)
    ncols, width = zip(*(_legend_columns(lb, rows) for lb in labels))
    fig, axes, _ = _history_figure(result, len(model.buildings), max(width),
                                   "floor displacements relative to the ground")
    cmap = matplotlib.colormaps["viridis"]
    for b, (ax, bl, off) in enumerate(zip(axes, model.buildings, model.system.offsets)):
        for j, label in zip(shown[b], labels[b]):
            roof = j == roofs[b]
            colour = "k" if roof else cmap(0.1 + 0.75 * j / max(bl.n - 1, 1))
            history(ax, t, result.displacement[:, off + j] * MM.factor, color=colour,
                    lw=1.3 if roof else 0.7, label=label, zorder=3 if roof else 2)
        ax.axhline(0.0, color="0.6", lw=0.5)
        ax.set_ylabel(f"displacement [{MM.unit}]")
        ax.set_title(fit_text(f"{_building_label(result, b)}: {floor_dofs(bl).size} "
                              "storey(s); roof and "
                              "floors with a contact", axes_width(ax), TITLE_SIZE, max_lines=1),
                     fontsize=TITLE_SIZE, loc="left")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=LEGEND_SIZE, loc="upper left", bbox_to_anchor=(1.01, 1.0),
                  borderaxespad=0.0, ncol=ncols[b], frameon=False)
    return plain_ticks(fig)


def plot_contact_forces(result: Result) -> Figure:
    """Contact force histories [kN or MN], one panel per gap and per moat wall, the ground
    acceleration [g] below; dots mark each impact's peak force at its time, from the impact
    table (located between output samples)."""
    model = result.model
    t = result.time
    n_pairs = max(len(model.buildings) - 1, 1) if not model.walls or len(model.buildings) > 1 \
        else 0
    imp = result.impact_array  # (numpy, not the DataFrame: drawing needs no pandas)
    peak = result.peak_contact_force
    force = scale_for(float(peak.max()) if peak.size else 0.0, "N")
    # one panel a gap between buildings (none where they never meet: a bridge across its
    # axis), then one a wall (moat walls: pounding.structure.wall), then one for the stops
    # (shear keys: pounding.structure.stops)
    stops = [c for c in model.contacts if c.label.endswith("/key")]
    pairs = [p for p in range(n_pairs)
             if not (p < len(model.gaps) and math.isinf(model.gaps[p]))]
    groups = [[c for c in model.contacts if c.pair == p and not c.on_wall and c not in stops]
              for p in pairs]
    groups += [[c for c in model.contacts if c.on_wall and (c.pair < 0) == (wall.side == "left")
                and c not in stops] for wall in model.walls]
    if stops:
        groups.append(stops)
    n_pairs = len(pairs)
    hit_by_pair = [[c for c in cs if peak[c.index] > 0.0] for cs in groups]
    labels = [[f"{c.label} ({c.elevation:g} m)" for c in hit] for hit in hit_by_pair]
    rows = int(PANEL_HEIGHT / 0.15)
    ncols, width = zip(*(_legend_columns(lb, rows) for lb in labels))
    fig, axes, _ = _history_figure(result, len(groups), max(width) if any(labels) else 0.0,
                                   "contact forces")
    cmap = matplotlib.colormaps["tab10"]
    for p, ax in enumerate(axes):
        cs = groups[p]
        hit = hit_by_pair[p]
        for i, (c, label) in enumerate(zip(hit, labels[p])):
            colour = cmap(i % 10)
            history(ax, t, result.contact_force[:, c.index] * force.factor, color=colour,
                    lw=0.8, label=label)
            rows_c = imp[imp[:, 0] == c.index]
            ax.plot(rows_c[:, 5], rows_c[:, 4] * force.factor, "o", ms=3, color=colour)
        if not cs:
            _empty(ax, "no contacts (a single building)")
        elif not hit:
            _empty(ax, "no impact: the gap never closed")
        else:
            ax.legend(fontsize=LEGEND_SIZE, loc="upper left", bbox_to_anchor=(1.01, 1.0),
                      borderaxespad=0.0, ncol=ncols[p], frameon=False)
        if p < n_pairs:
            q = pairs[p]
            gap = model.gaps[q] if q < len(model.gaps) else float("nan")
            where = f"gap {q + 1}: B{q + 1}–B{q + 2}, {gap * MM.factor:g} mm"
        elif stops and p == len(groups) - 1:
            where = "shear keys (each with its own gap)"
        else:
            wall = model.walls[p - n_pairs]
            nb = 1 if wall.side == "left" else len(model.buildings)
            where = (f"wall {wall.name} ({wall.side} of B{nb}, top {wall.height:g} m): gap "
                     f"{wall.gap * MM.factor:g} mm")
        ax.set_title(where
                     + (f"; {len(hit)} of {len(cs)} contacts closed; dots: peak of each "
                        "impact" if cs else ""), fontsize=TITLE_SIZE, loc="left")
        ax.set_ylabel(f"contact force [{force.unit}]")
        ax.grid(True, alpha=0.3)
    return plain_ticks(fig)


def plot_energy(result: Result) -> Figure:
    """Energy balance [kJ or MJ]: stacked kinetic, strain, structural damping, hysteretic
    (yielding storeys), dissipated by links between buildings, contact-dissipated and contact-stored energy against the input
    energy; below, the closure error input − sum (in its own multiple of J)."""
    from pounding.result import ENERGY_NAMES

    e = result.energy
    col = {name: e[:, i] for i, name in enumerate(ENERGY_NAMES)}
    t = result.time
    terms = [
        ("kinetic", col["kinetic"]),
        ("elastic strain", col["strain"]),
        ("structural damping", col["damping"]),
        ("dissipated in contacts", col["contact_work"] - col["contact_stored"]),
        ("stored in closed contacts", col["contact_stored"]),
    ]
    if result.model.is_inelastic:
        bearings = int(result.is_bearing.sum())
        what = ("storeys yielding" if not bearings else "isolation bearings"
                if bearings == len(result.model.yielding_storeys)
                else "yielding storeys and bearings")
        terms.insert(3, (f"hysteretic ({what})", col["hysteretic"]))
    if result.model.links and "links" in col:
        terms.insert(3, ("dissipated by links", col["links"]))
    stack = np.column_stack([v for _, v in terms])
    edges = np.cumsum(stack, axis=1)
    closure = col["input"] - edges[:, -1]
    energy = scale_for(float(np.abs(np.column_stack([edges, col["input"]])).max())
                       if t.size else 0.0, "J")
    err = scale_for(float(np.abs(closure).max()) if t.size else 0.0, "J")
    names = [name for name, _ in terms] + ["input"]
    ncol, legend_width = _legend_columns(names, 20)
    fig, extra = titled_figure(result.model.name, f"energy balance ({result.motion.name})",
                               10.0 + legend_width, 6.0)
    ax, ax_r = axes_grid(fig, 2, 1, left=0.8, right=0.25 + legend_width, top=0.4 + extra,
                         bottom=0.55, hspace=0.45, height_ratios=[3.0, 1.0], sharex="col")[:, 0]
    n = buckets_for_width(axes_width(ax))
    idx = union_indices(np.column_stack([edges, col["input"]]), n)
    ax.stackplot(t[idx], *(stack[idx].T * energy.factor), labels=[name for name, _ in terms],
                 alpha=0.8, colors=[ENERGY_COLOURS[name] for name, _ in terms])
    ax.plot(t[idx], col["input"][idx] * energy.factor, "k", lw=1.2, label="input")
    ax.set_ylabel(f"energy [{energy.unit}]")
    handles, labels = ax.get_legend_handles_labels()  # input first: it bounds the stack
    ax.legend(handles[-1:] + handles[:-1], labels[-1:] + labels[:-1], fontsize=LEGEND_SIZE,
              loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, frameon=False)
    ax.grid(True, alpha=0.3)
    history(ax_r, t, closure * err.factor, color="r", lw=0.8)
    ax_r.set_ylabel(f"input − sum [{err.unit}]")
    ax_r.set_xlabel("time [s]")
    ax_r.set_xlim(0.0, float(t[-1]) if t.size > 1 else 1.0)
    ax_r.grid(True, alpha=0.3)
    worst = float(np.abs(closure).max()) if t.size else 0.0
    ax_r.set_title(f"closure error: largest |input − sum| = {worst * err.factor:.3g} "
                   f"{err.unit}, {result.energy_balance_error:.2e} of the largest input",
                   fontsize=TITLE_SIZE - 1, loc="left")
    return plain_ticks(fig)

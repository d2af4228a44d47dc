"""Figures of one simulation (:class:`pounding.result.Result`): floor displacements,
contact forces, contact hysteresis loops, and the energy balance.

Each function returns a :class:`matplotlib.figure.Figure` built without pyplot (nothing is
registered globally, so nothing leaks); save it with :func:`pounding.plot.save_figure`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple

import math
from collections import defaultdict

import matplotlib
import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from pounding.result import Result, peak_abs

__all__ = ["plot_contact_forces", "plot_displacements", "plot_energy", "plot_hysteresis",
           "contact_floors"]

MAX_HYSTERESIS_PANELS = 12
"""At most this many contacts get a hysteresis panel (those with the largest peak force)."""


def _empty(ax: Axes, text: str) -> None:
    ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center", va="center", color="0.4")


def contact_floors(result: Result) -> dict[int, set[int]]:
    """For each building (0-based), the 0-based floors that take part in a contact."""
    out: dict[int, set[int]] = defaultdict(set)
    for c in result.model.contacts:
        out[c.pair].add(c.left_floor)
        out[c.pair + 1].add(c.right_floor)
    return out


def _building_label(result: Result, b: int) -> str:
    name = result.model.buildings[b].name
    return f"B{b + 1}" + (f" ({name})" if name and name != f"B{b + 1}" else "")


def plot_displacements(result: Result) -> Figure:
    """Displacement histories [m] of each building's roof and of every floor with a contact.

    One panel per building, left to right from the top; the roof is drawn thick.
    """
    model = result.model
    t = result.time
    nb = len(model.buildings)
    fig = Figure(figsize=(10, 2.4 * nb + 0.8))
    axes = np.atleast_1d(fig.subplots(nb, 1, sharex=True, squeeze=False)[:, 0])
    floors = contact_floors(result)
    cmap = matplotlib.colormaps["viridis"]
    for b, (ax, bl, off) in enumerate(zip(axes, model.buildings, model.system.offsets)):
        show = sorted(floors.get(b, set()) | {bl.n - 1})
        for j in show:
            roof = j == bl.n - 1
            colour = "k" if roof else cmap(0.1 + 0.75 * j / max(bl.n - 1, 1))
            label = (f"F{j + 1} (roof, {bl.floor_levels[j]:g} m)" if roof
                     else f"F{j + 1} ({bl.floor_levels[j]:g} m)")
            ax.plot(t, result.displacement[:, off + j], color=colour, lw=1.4 if roof else 0.8,
                    label=label, zorder=3 if roof else 2)
        ax.axhline(0.0, color="0.6", lw=0.5)
        ax.set_ylabel("displacement [m]")
        ax.set_title(f"{_building_label(result, b)}: {bl.n} storey(s); roof and floors "
                     "with a contact", fontsize=9, loc="left")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper right", ncol=max(1, math.ceil(len(show) / 6)))
    axes[-1].set_xlabel("time [s]")
    fig.suptitle(f"{model.name}: floor displacements relative to the ground "
                 f"({result.motion.name})", fontsize=10)
    fig.tight_layout()
    return fig


def plot_contact_forces(result: Result) -> Figure:
    """Contact force histories [N], one panel per gap; dots mark each impact's peak force
    from the impact table (resolved between output samples)."""
    model = result.model
    t = result.time
    n_pairs = max(len(model.buildings) - 1, 1)
    fig = Figure(figsize=(10, 2.6 * n_pairs + 0.8))
    axes = np.atleast_1d(fig.subplots(n_pairs, 1, sharex=True, squeeze=False)[:, 0])
    imp = result.impacts
    cmap = matplotlib.colormaps["tab10"]
    for p, ax in enumerate(axes):
        cs = [c for c in model.contacts if c.pair == p]
        hit = [c for c in cs if (imp["contact"] == c.label).any()] if len(imp) else []
        for i, c in enumerate(hit):
            colour = cmap(i % 10)
            ax.plot(t, result.contact_force[:, c.index], color=colour, lw=0.8,
                    label=f"{c.label} ({c.elevation:g} m)")
            rows = imp[imp["contact"] == c.label]
            mid = 0.5 * (rows["start"] + rows["end"].fillna(t[-1]))
            ax.plot(mid, rows["peak_force"], "o", ms=3, color=colour)
        if not cs:
            _empty(ax, "no contacts (a single building)")
        elif not hit:
            _empty(ax, "no impact: the gap never closed")
        else:
            ax.legend(fontsize=7, loc="upper right", ncol=max(1, math.ceil(len(hit) / 6)))
        gap = model.gaps[p] if p < len(model.gaps) else float("nan")
        ax.set_title(f"gap {p + 1}: B{p + 1}–B{p + 2}, {gap:g} m"
                     + (f"; {len(hit)} of {len(cs)} contacts closed" if cs else ""),
                     fontsize=9, loc="left")
        ax.set_ylabel("contact force [N]")
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("time [s]")
    fig.suptitle(f"{model.name}: contact forces (dots: peak of each impact)", fontsize=10)
    fig.tight_layout()
    return fig


def _closed_runs(pen: np.ndarray, force: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The samples with δ > 0, each run of consecutive samples separated by NaN."""
    closed = pen > 0.0
    x = np.where(closed, pen, np.nan)
    y = np.where(closed, force, np.nan)
    # drop all-but-one NaN of each open stretch so the arrays stay short
    keep = closed | np.concatenate([[False], closed[:-1]])
    return x[keep], y[keep]


def plot_hysteresis(result: Result) -> Figure:
    """Force [N] against penetration [m] while each contact is closed (the seed's Fig 2).

    One panel per contact that had an impact (at most :data:`MAX_HYSTERESIS_PANELS`, those
    with the largest peak force); each impact is one loop, later impacts lighter. The area of
    a loop is the energy the impact dissipated.
    """
    model = result.model
    imp = result.impacts
    labels = list(imp["contact"].unique()) if len(imp) else []
    peak = result.peak_contact_force
    chosen = sorted((c for c in model.contacts if c.label in labels),
                    key=lambda c: -peak[c.index])[:MAX_HYSTERESIS_PANELS]
    chosen.sort(key=lambda c: c.index)
    n = max(len(chosen), 1)
    ncol = min(n, 3 if n > 4 else n)
    nrow = math.ceil(n / ncol)
    fig = Figure(figsize=(3.6 * ncol + 0.6, 3.0 * nrow + 0.8))
    axes = fig.subplots(nrow, ncol, squeeze=False).ravel()
    cmap = matplotlib.colormaps["plasma"]
    t = result.time
    for ax, c in zip(axes, chosen):
        rows = imp[imp["contact"] == c.label]
        pen = result.penetration[:, c.index]
        force = result.contact_force[:, c.index]
        k_rows = len(rows)
        for i, (_, r) in enumerate(rows.iterrows()):
            end = r["end"] if np.isfinite(r["end"]) else t[-1]
            sel = (t >= r["start"] - result.dt) & (t <= end + result.dt)
            x, y = _closed_runs(pen[sel], force[sel])
            ax.plot(x, y, color=cmap(0.85 * i / max(k_rows - 1, 1)), lw=0.9)
        e_diss = float(np.nansum(rows["energy_dissipated"]))
        ax.set_title(f"{c.label} ({c.elevation:g} m): {k_rows} impact(s), "
                     f"{e_diss:.3g} J", fontsize=8)
        ax.set_xlabel("penetration δ [m]")
        ax.set_ylabel("contact force [N]")
        ax.axhline(0.0, color="0.6", lw=0.5)
        ax.grid(True, alpha=0.3)
        ax.ticklabel_format(axis="x", style="sci", scilimits=(-2, 3))
    for ax in axes[len(chosen):]:
        ax.set_axis_off()
    if not chosen:
        axes[0].set_axis_on()
        _empty(axes[0], "no impact" if model.contacts else "no contacts (a single building)")
        axes[0].set_xlabel("penetration δ [m]")
        axes[0].set_ylabel("contact force [N]")
    more = len(labels) - len(chosen)
    fig.suptitle(f"{model.name}: contact hysteresis while closed (dark: early impacts, light: "
                 "late)" + (f"; {more} more contact(s) not shown" if more > 0 else ""),
                 fontsize=10)
    fig.tight_layout()
    return fig


def plot_energy(result: Result) -> Figure:
    """Energy balance [J]: stacked kinetic, strain, structural damping, hysteretic (yielding
    storeys), contact-dissipated and contact-stored energy against the input energy; below,
    the closure error."""
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
        terms.insert(3, ("hysteretic (storeys yielding)", col["hysteretic"]))
    total = sum(v for _, v in terms)
    closure = col["input"] - total
    fig = Figure(figsize=(10, 6))
    ax, ax_r = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": [3, 1]})
    ax.stackplot(t, *[v for _, v in terms], labels=[n for n, _ in terms], alpha=0.8,
                 colors=[matplotlib.colormaps["tab10"](i) for i in range(len(terms))])
    ax.plot(t, col["input"], "k", lw=1.2, label="input")
    ax.set_ylabel("energy [J]")
    ax.legend(fontsize=8, loc="upper left")
    ax.grid(True, alpha=0.3)
    ax.set_title(f"{result.model.name}: energy balance ({result.motion.name})", fontsize=10)
    ax_r.plot(t, closure, "r", lw=0.8)
    ax_r.set_ylabel("input − sum [J]")
    ax_r.set_xlabel("time [s]")
    ax_r.grid(True, alpha=0.3)
    ax_r.set_title(f"closure error: largest |input − sum| = {np.abs(closure).max():.3g} J, "
                   f"{result.energy_balance_error:.2e} of the largest input", fontsize=8,
                   loc="left")
    fig.tight_layout()
    return fig


MAX_STOREY_PANELS = 3
"""Storeys drawn per building in the storey figure (those with the largest peak drift)."""


def plot_storey_hysteresis(result: Result) -> Figure:
    """Storey shear [N] against storey drift [m]: the hysteresis of the storeys.

    One row per building, its :data:`MAX_STOREY_PANELS` storeys of largest peak drift; for a
    yielding storey the yield shears ``±F_y`` are dashed and the title gives the ductility
    demand and the residual drift. A linear storey draws a straight line of slope ``k``.
    """
    model = result.model
    nb = len(model.buildings)
    ncol = min(MAX_STOREY_PANELS, max(b.n for b in model.buildings))
    fig = Figure(figsize=(3.6 * ncol + 0.6, 2.9 * nb + 0.8))
    axes = fig.subplots(nb, ncol, squeeze=False)
    drift, shear = result.drift, result.storey_shear
    peak = peak_abs(drift)
    for b, (bl, off) in enumerate(zip(model.buildings, model.system.offsets)):
        order = sorted(range(bl.n), key=lambda j: -peak[off + j])[:ncol]
        fy = bl.yield_forces
        for ax, j in zip(axes[b], sorted(order)):
            col = off + j
            ax.plot(drift[:, col], shear[:, col], lw=0.7, color="tab:blue")
            title = f"B{b + 1} storey {j + 1}: peak drift {peak[col]:.3g} m"
            if fy is not None:
                for sgn in (1.0, -1.0):
                    ax.axhline(sgn * fy[j], color="0.5", lw=0.6, ls="--")
                title += (f"\nductility {result.ductility[col]:.2f}, residual "
                          f"{result.residual_drift[col]:+.3g} m")
            ax.set_title(title, fontsize=8)
            ax.set_xlabel("storey drift [m]")
            ax.set_ylabel("storey shear [N]")
            ax.axhline(0.0, color="0.7", lw=0.4)
            ax.axvline(0.0, color="0.7", lw=0.4)
            ax.grid(True, alpha=0.3)
            ax.ticklabel_format(axis="x", style="sci", scilimits=(-2, 3))
        for ax in axes[b][len(order):]:
            ax.set_axis_off()
    fig.suptitle(f"{model.name}: storey shear against drift"
                 + (" (dashed: yield shear)" if model.is_inelastic else " (linear storeys)"),
                 fontsize=10)
    fig.tight_layout()
    return fig


class RunFigure(NamedTuple):
    """One of the figures of a run folder."""

    file: str
    caption: str
    make: Callable[[Result], Figure]


RUN_FIGURES: dict[str, RunFigure] = {
    "displacement_figure": RunFigure("displacements.png", "Floor displacements",
                                     plot_displacements),
    "force_figure": RunFigure("contact_forces.png", "Contact forces", plot_contact_forces),
    "hysteresis_figure": RunFigure("hysteresis.png",
                                   "Contact hysteresis (force against penetration)",
                                   plot_hysteresis),
    "storey_figure": RunFigure("storeys.png", "Storey shear against drift (hysteresis)",
                               plot_storey_hysteresis),
    "energy_figure": RunFigure("energy.png", "Energy balance", plot_energy),
}
"""The figures `pounding run` writes and `pounding report` embeds, in page order."""

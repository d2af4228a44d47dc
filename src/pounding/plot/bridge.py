"""The figures of a bridge run (:mod:`pounding.structure.bridge`): its elevation with the
envelope of the relative displacement at every joint and abutment seat, and the
force–deformation loops of its piers, bearings and restrainers.

Read from :attr:`pounding.result.Result.bridge` (:mod:`pounding.result.bridge_peaks`):
displacements, gaps and openings in mm, forces in kN (MN from 100 MN on, as the printed
tables), elevations in m. Each function returns a
:class:`matplotlib.figure.Figure` on its own Agg canvas; save it with
:func:`pounding.plot.save_figure`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any, NamedTuple

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Polygon, Rectangle

from pounding.plot.layout import (
    LEGEND_SIZE,
    MM,
    TITLE_SIZE,
    Scale,
    axes_grid,
    plain_ticks,
    titled_figure,
)
from pounding.result import BridgePeaks, Result

__all__ = ["BridgeLayout", "bridge_layout", "force_scale", "plot_bridge_elements",
           "plot_bridge_elevation"]

SCHEMATIC_FRAME_LENGTH = 1.0
"""A frame's length on the drawing where its spans are not known (not to scale)."""

MAX_ELEMENT_COLUMNS = 4
"""Panels per frame in the element figure (its piers and bearings of largest peak force)."""


class BridgeLayout(NamedTuple):
    """Where the parts of a bridge stand along its axis (the elevation's x)."""

    to_scale: bool
    """True if every frame's spans are known (x in m); else a schematic, every frame
    :data:`SCHEMATIC_FRAME_LENGTH` long."""
    frame_ends: tuple[tuple[float, float], ...]
    """Each frame's deck from its left end to its right end."""
    piers: tuple[tuple[float, ...], ...]
    """Each frame's piers, left to right."""
    seats: tuple[float, ...]
    """Every seat of :attr:`pounding.result.bridge_peaks.BridgePeaks.seats`' positions:
    0 the left abutment, ``j`` the joint after frame ``j``, ``n`` the right abutment."""


def _bridge_of(result: Result) -> BridgePeaks:
    """The bridge of ``result``; a ``ValueError`` for a model of buildings."""
    bridge = result.bridge
    if bridge is None:
        raise ValueError("bridge figure: the model is not a bridge (every building a "
                         "BridgeFrame)")
    return bridge


def bridge_layout(result: Result,
                  spans: Sequence[Sequence[float] | None] | None = None) -> BridgeLayout:
    """The elevation's geometry of the bridge of ``result``.

    Parameters
    ----------
    result : Result
        A bridge run (:attr:`~pounding.result.Result.bridge` not None).
    spans : sequence of (sequence of float or None), optional
        Span lengths [m] per frame; default each frame's ``spans`` where it carries them
        (:attr:`~pounding.result.bridge_peaks.FramePeaks.spans`).

    Returns
    -------
    BridgeLayout
        To scale if every frame's spans are known: a frame as long as its spans, its piers
        at the supports between them when it has one pier fewer than spans, else spread
        evenly; joints at the frames' ends (their gaps are drawn as marks, not to scale).
    """
    bridge = _bridge_of(result)
    frames = bridge.frames
    given = list(spans) if spans is not None else [f.spans for f in frames]
    if len(given) != len(frames):
        raise ValueError(f"spans: need one entry per frame ({len(frames)}; got {len(given)})")
    to_scale = all(s is not None and len(s) > 0 for s in given)
    x = 0.0
    ends, piers = [], []
    for f, s in zip(frames, given):
        n_p = len(f.piers)
        if to_scale:
            lengths = [float(v) for v in s]  # type: ignore[union-attr]
            length = sum(lengths)
            if n_p == len(lengths) - 1:  # a pier at every support between spans
                at = tuple(x + float(c) for c in np.cumsum(lengths)[:-1])
            else:
                at = tuple(x + length * (i + 0.5) / n_p for i in range(n_p))
        else:
            length = SCHEMATIC_FRAME_LENGTH
            at = tuple(x + length * (i + 0.5) / n_p for i in range(n_p))
        ends.append((x, x + length))
        piers.append(at)
        x += length
    seats = (ends[0][0], *(e[1] for e in ends[:-1]), ends[-1][1])
    return BridgeLayout(to_scale, tuple(ends), tuple(piers), seats)


def force_scale(peak: float) -> Scale:
    """Forces of a bridge figure: kN, or MN from 100 MN on (as the printed tables)."""
    return Scale(1e-6, "MN") if abs(peak) >= 1e8 else Scale(1e-3, "kN")


def plot_bridge_elevation(result: Result, seat_widths: Mapping[str, float] | None = None,
                          spans: Sequence[Sequence[float] | None] | None = None) -> Figure:
    """The bridge's elevation and, below it, the envelope of the relative displacement at
    every joint and abutment seat.

    Above: the decks on their piers (to scale along the axis where the spans are known,
    :func:`bridge_layout`; heights exaggerated), each joint and abutment marked with its
    gap and its impacts, each pier with its peak drift and shear, each restrainer with its
    peak force. Below: at every seat the largest opening (up) and closing (down) of the run
    [mm] (:attr:`pounding.result.bridge_peaks.SeatPeaks.peak_opening`), the gap drawn
    where the closing stops (past it by the impact's penetration) and the seat width where
    given.

    Parameters
    ----------
    result : Result
        A bridge run.
    seat_widths : mapping of str to float, optional
        Seat width [m] by seat name (``A1``, ``J1``, …, ``A2``), drawn on the opening side;
        default those of the result's seat checks where it has them (a ``seats`` attribute
        of checks with ``seat`` and ``width_m``, as a bridge given seat widths has).
    spans : sequence, optional
        Span lengths [m] per frame (:func:`bridge_layout`).
    """
    bridge = _bridge_of(result)
    layout = bridge_layout(result, spans)
    model = result.model
    if seat_widths is None:  # the run's own seat checks, where it has them
        seat_widths = {str(c.seat): float(c.width_m)
                       for c in (getattr(result, "seats", None) or [])
                       if getattr(c, "width_m", None) is not None}
    widths = {str(k): float(v) for k, v in seat_widths.items()}
    forces = [p.peak_shear for p in bridge.piers] + [r.peak_force for r in bridge.restrainers]
    force = force_scale(max(forces, default=0.0))
    fig, extra = titled_figure(
        model.name, "elevation, and the envelope of the relative displacement at the joints "
        "and abutments" + ("" if layout.to_scale else " (schematic along the axis: no spans "
                                                        "in the model)"), 9.0, 6.7)
    top, bottom = axes_grid(fig, 2, 1, left=0.85, right=0.25, top=0.55 + extra, bottom=0.9,
                            hspace=0.35, height_ratios=[1.15, 1.0], sharex=True)[:, 0]
    _draw_elevation(top, result, layout, force)
    _draw_envelope(bottom, result, layout, widths)
    total = layout.frame_ends[-1][1] - layout.frame_ends[0][0]
    bottom.set_xlim(layout.frame_ends[0][0] - 0.08 * total, layout.frame_ends[-1][1]
                    + 0.08 * total)
    if layout.to_scale:
        bottom.set_xlabel("along the bridge [m]")
    else:
        bottom.set_xlabel("along the bridge (schematic: frames drawn alike)")
        bottom.set_xticks([])
    return plain_ticks(fig)


def _seat_label(seat: Any) -> str:
    hit = f"{seat.impacts} impact{'s' if seat.impacts != 1 else ''}"
    gap = "" if not math.isfinite(seat.gap) else f"gap {seat.gap * MM.factor:.4g} mm, "
    return f"{seat.name}: {gap}{hit}"


def _draw_elevation(ax: Any, result: Result, layout: BridgeLayout, force: Any) -> None:
    bridge = _bridge_of(result)
    z_deck = max(f.deck_elevation for f in bridge.frames)
    depth = 0.12 * z_deck
    total = layout.frame_ends[-1][1] - layout.frame_ends[0][0]
    notch = 0.004 * total  # the joints drawn open (not to scale)
    ax.axhline(0.0, color="0.45", lw=1.0)
    for f, (x0, x1), piers in zip(bridge.frames, layout.frame_ends, layout.piers):
        left = x0 + (notch if f.frame > 0 else 0.0)
        right = x1 - (notch if f.frame < len(bridge.frames) - 1 else 0.0)
        ax.add_patch(Rectangle((left, f.deck_elevation), right - left, depth,
                               facecolor="0.82", edgecolor="0.25", lw=0.8))
        ax.text((x0 + x1) / 2, f.deck_elevation + 1.9 * depth,
                f"{f.label}: T1 {f.periods[0]:.2f} s, deck "
                f"{f.peak_deck_displacement * MM.factor:.3g} mm",
                ha="center", va="bottom", fontsize=LEGEND_SIZE)
        for x, p in zip(piers, f.piers):
            ax.plot([x, x], [0.0, p.height], color="0.35", lw=3.5, solid_capstyle="butt")
            ax.plot([x, x], [p.height, f.deck_elevation], color="0.2", lw=0.8)
            ax.plot([x], [f.deck_elevation], marker="s", ms=4, color="k", ls="none")
            ax.text(x + 0.01 * total, 0.45 * p.height,
                    f"{p.label}\n{p.peak_drift * MM.factor:.3g} mm\n"
                    f"{p.peak_shear * force.factor:.4g} {force.unit}",
                    ha="left", va="center", fontsize=LEGEND_SIZE - 0.5, color="0.15")
    for seat in bridge.seats:
        x = layout.seats[seat.position]
        if seat.kind == "abutment":
            side = -1.0 if seat.position == 0 else 1.0
            w = 0.05 * total
            ax.add_patch(Polygon([(x, 0.0), (x, z_deck + depth), (x + side * 0.35 * w,
                                  z_deck + depth), (x + side * 0.35 * w, z_deck),
                                  (x + side * w, z_deck), (x + side * w, 0.0)],
                                 closed=True, facecolor="0.65", edgecolor="0.25", lw=0.8))
        else:
            ax.plot([x, x], [z_deck - 0.3 * depth, z_deck + 1.3 * depth], color="tab:red",
                    lw=1.0)
        ax.text(x, z_deck + 1.35 * depth if seat.kind == "joint" else z_deck + 1.1 * depth,
                _seat_label(seat).replace(": ", "\n", 1), ha="center", va="bottom",
                fontsize=LEGEND_SIZE - 0.5, color="tab:red" if seat.impacts else "0.3")
    for r in bridge.restrainers:
        j = int(r.joint.removeprefix("J"))
        x = layout.seats[j]
        ax.plot([x - 2.5 * notch, x + 2.5 * notch], [z_deck + 0.5 * depth] * 2,
                color="tab:purple", lw=2.0)
        ax.text(x, z_deck - 0.45 * depth, f"{r.name} {r.peak_force * force.factor:.4g} "
                f"{force.unit}" + (" (yielded)" if r.yielded else ""), ha="center", va="top",
                fontsize=LEGEND_SIZE - 0.5, color="tab:purple")
    ax.set_ylim(0.0 - 0.05 * z_deck, z_deck + 4.0 * depth)
    ax.set_ylabel("elevation [m]")
    ax.set_title("piers: peak drift and shear; joints and abutments: gap and impacts",
                 fontsize=TITLE_SIZE, loc="left")
    ax.grid(False)


def _draw_envelope(ax: Any, result: Result, layout: BridgeLayout,
                   widths: Mapping[str, float]) -> None:
    bridge = _bridge_of(result)
    total = layout.frame_ends[-1][1] - layout.frame_ends[0][0]
    tick = 0.025 * total
    ax.axhline(0.0, color="0.6", lw=0.6)
    opening_drawn = closing_drawn = gap_drawn = width_drawn = False
    highest, lowest = [0.0], [0.0]  # above and below zero [mm]
    for seat in bridge.seats:
        x = layout.seats[seat.position]
        up, down = seat.peak_opening * MM.factor, seat.peak_closing * MM.factor
        ax.plot([x, x], [0.0, up], color="tab:blue", lw=5, solid_capstyle="butt",
                label=None if opening_drawn else "largest opening")
        ax.plot([x, x], [0.0, -down], color="tab:orange", lw=5, solid_capstyle="butt",
                label=None if closing_drawn else "largest closing")
        opening_drawn = closing_drawn = True
        ax.text(x + 0.6 * tick, up, f"{up:.3g}", fontsize=LEGEND_SIZE, va="center")
        ax.text(x + 0.6 * tick, -down, f"−{down:.3g}", fontsize=LEGEND_SIZE, va="center")
        highest.append(up)
        lowest.append(down)
        if math.isfinite(seat.gap):
            g = seat.gap * MM.factor
            ax.plot([x - tick, x + tick], [-g, -g], color="tab:red", lw=1.4, ls="--",
                    label=None if gap_drawn else "gap (closing past it: impact)")
            gap_drawn = True
            lowest.append(g)
        width = widths.get(seat.name)
        if width is not None:
            w = width * MM.factor
            ax.plot([x - tick, x + tick], [w, w], color="k", lw=1.4,
                    label=None if width_drawn else "seat width")
            width_drawn = True
            highest.append(w)
            if seat.peak_opening > width:
                ax.text(x - 1.2 * tick, w, "unseated", color="tab:red", fontsize=LEGEND_SIZE,
                        ha="right", va="center", fontweight="bold")
        ax.text(x, 0.97, seat.name, fontsize=LEGEND_SIZE + 1, ha="center", va="top",
                color="0.2", transform=ax.get_xaxis_transform())
    top, bottom = 1.4 * max(highest), 1.25 * max(lowest)  # (the seats' names on top)
    ax.set_ylim(-bottom if bottom > 0 else -1.0, top if top > 0 else 1.0)
    ax.set_ylabel(f"relative displacement [{MM.unit}]\n(+ opening, − closing)")
    ax.grid(True, axis="y", alpha=0.3)
    # under the axis label, in the page's bottom margin: never over a bar
    ax.legend(fontsize=LEGEND_SIZE, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=4,
              frameon=False)


def plot_bridge_elements(result: Result) -> Figure:
    """Force against deformation of the bridge's elements: each frame's piers (shear
    [kN or MN] against drift [mm]) and bearings (force against displacement), at most
    :data:`MAX_ELEMENT_COLUMNS` a frame (those of largest peak force), one row per frame;
    the restrainers (force against the joint's opening) in a last row. A yielding
    element's yield force is dashed."""
    from pounding.result.storey_peaks import bridge_element_histories

    bridge = _bridge_of(result)
    histories = {label: (d, f) for _, label, d, f in bridge_element_histories(result)}
    rows: list[list[tuple[str, Any]]] = []
    for fr in bridge.frames:
        items: list[tuple[str, Any]] = ([("pier", p) for p in fr.piers]
                                        + [("bearing", b) for b in fr.bearings])
        items.sort(key=lambda it: -(it[1].peak_shear if it[0] == "pier" else it[1].peak_force))
        chosen = items[:MAX_ELEMENT_COLUMNS]
        chosen.sort(key=lambda it: (it[0] != "pier", it[1].label))
        rows.append(chosen)
    links = result.model.links
    if bridge.restrainers:
        rows.append([("restrainer", r) for r in bridge.restrainers[:MAX_ELEMENT_COLUMNS]])
    ncol = max(len(r) for r in rows)
    nrow = len(rows)
    peak = max([p.peak_shear for p in bridge.piers] + [b.peak_force for b in bridge.bearings]
               + [r.peak_force for r in bridge.restrainers])
    force = force_scale(peak)
    fig, extra = titled_figure(result.model.name, "pier shear against drift, bearing force "
                               "against displacement, restrainer force against the joint's "
                               "opening (dashed: yield force)",
                               0.8 + ncol * 2.6 + (ncol - 1) * 0.8 + 0.25,
                               0.9 + nrow * 2.1 + (nrow - 1) * 0.9 + 0.55)
    axes = axes_grid(fig, nrow, ncol, left=0.8, right=0.25, top=0.9 + extra, bottom=0.55,
                     wspace=0.8, hspace=0.9)
    for ax_row, items in zip(axes, rows):
        for ax, (what, e) in zip(ax_row, items):
            if what == "restrainer":
                i = [lk.name for lk in links].index(e.name)
                d = result.link_displacement[:, i]
                f = (result.link_force[:, i] if result.link_force is not None
                     else np.zeros_like(d))
                fy = e.yield_force
                title = (f"{e.name} across {e.joint}: peak {e.peak_force * force.factor:.4g} "
                         f"{force.unit}" + ("\nyielded" if e.yielded else ""))
                xlabel = f"joint opening [{MM.unit}]"
            else:
                d, f = histories[e.label]
                fy = e.yield_force
                if what == "pier":
                    title = (f"{e.label}: drift {e.peak_drift * MM.factor:.3g} mm\n"
                             f"shear {e.peak_shear * force.factor:.4g} {force.unit}")
                    xlabel = f"pier drift [{MM.unit}]"
                else:
                    title = (f"{e.label} ({e.kind}): {e.peak_displacement * MM.factor:.3g} mm"
                             f"\nforce {e.peak_force * force.factor:.4g} {force.unit}")
                    xlabel = f"bearing displacement [{MM.unit}]"
            ax.plot(d * MM.factor, f * force.factor, lw=0.7, color="tab:blue")
            if math.isfinite(fy):
                for sgn in ((1.0,) if what == "restrainer" else (1.0, -1.0)):
                    ax.axhline(sgn * fy * force.factor, color="0.5", lw=0.6, ls="--")
            ax.axhline(0.0, color="0.7", lw=0.4)
            ax.axvline(0.0, color="0.7", lw=0.4)
            ax.set_title(title, fontsize=TITLE_SIZE - 1)
            ax.set_xlabel(xlabel)
            ax.grid(True, alpha=0.3)
        ax_row[0].set_ylabel(f"force [{force.unit}]")
        for ax in ax_row[len(items):]:
            ax.set_axis_off()
    return plain_ticks(fig)

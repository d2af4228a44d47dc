"""A legend with no free place inside its axes goes beside them, and on a page of fixed
margins (no layout engine: the run figures) it still ends inside the page — the axes are
narrowed for it (issue 28's note: it could be pushed off the page)."""

from __future__ import annotations

import numpy as np

from pounding.plot import new_figure
from pounding.plot.layout import place_legend


def _crowded(fig, layout_box):
    ax = fig.add_axes(layout_box)
    t = np.linspace(0.0, 1.0, 400)
    for i in range(12):  # lines everywhere: no inside corner is free
        ax.plot(t, np.sin(20.0 * t + i) + 0.1 * i, label=f"a rather long label number {i}")
    ax.set_xlim(0.0, 1.0)
    return ax


def test_a_legend_beside_the_axes_ends_inside_a_fixed_page():
    fig = new_figure(6.0, 4.0)
    ax = _crowded(fig, (0.1, 0.1, 0.85, 0.8))
    legend = place_legend(ax)
    fig.draw_without_rendering()
    box = legend.get_window_extent()
    assert box.x0 > ax.get_window_extent().x1  # beside the axes, not over the lines
    assert box.x1 <= fig.bbox.x1 and box.y1 <= fig.bbox.y1
    assert ax.get_position().x0 == 0.1 and ax.get_position().width < 0.85


def test_a_legend_that_fits_leaves_the_axes_alone():
    fig = new_figure(6.0, 4.0)
    ax = fig.add_axes((0.1, 0.1, 0.85, 0.8))
    ax.plot([0.0, 1.0], [0.0, 0.1], label="low line")
    ax.set_ylim(0.0, 1.0)
    legend = place_legend(ax)
    fig.draw_without_rendering()
    assert ax.bbox.contains(*legend.get_window_extent().p0)  # inside the axes
    assert tuple(ax.get_position().bounds) == (0.1, 0.1, 0.85, 0.8)

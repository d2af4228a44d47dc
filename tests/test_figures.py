"""The figures: those of a run draw the result's numbers (every peak exact through the
display decimation), in readable units without offset notation, with no text overlapping
or off the page, titles wrapped to fit any model name; the storey hysteresis figure only
where storeys yield; the figure registry light enough to import without matplotlib. The
sweep figures name each quantity with its unit in a readable multiple; the legends of the
contact-core, ellipse, spectrum and sweep figures cover no drawn line."""

from __future__ import annotations

import re
import struct
import subprocess
import sys
import tomllib
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.text import Text

from pounding.config import load_config, parse_config
from pounding.integrate import simulate
from pounding.plot import new_figure, save_figure
from pounding.plot.contact import plot_audit, plot_damping_formulas
from pounding.plot.decimate import envelope_indices, union_indices
from pounding.plot.ellipse import plot_hysteresis_ellipse
from pounding.plot.envelope import plot_envelopes
from pounding.plot.layout import axes_grid, fit_text, history, scale_for, text_width
from pounding.plot.loops import plot_hysteresis, plot_storey_hysteresis
from pounding.plot.registry import RUN_FIGURES, figures_for
from pounding.plot.response import plot_contact_forces, plot_displacements, plot_energy
from pounding.plot.spectrum import plot_spectra
from pounding.plot.sweep import plot_sweep
from pounding.result import Result
from pounding.units import G, column_name, format_value
from pounding.units import unit_of as column_unit

ROOT = Path(__file__).resolve().parents[1]
UNIT_FACTOR = {"N": 1.0, "kN": 1e-3, "MN": 1e-6, "GN": 1e-9, "J": 1.0, "kJ": 1e-3,
               "MJ": 1e-6, "mm": 1e3, "%": 100.0, "g": 1.0 / G}
"""SI value × factor = the value in the unit (written out here, independent of the code)."""


def simulate_file(path: Path, duration: float) -> Result:
    cfg = load_config(path)
    model, motion, solver = cfg.build()
    return simulate(model, motion, **{**solver, "duration": duration})


@pytest.fixture(scope="module")
def demo() -> Result:
    """`pounding demo`'s two 10-storey buildings, the first 16 s (impacts from 2.5 s on;
    16,001 samples a history, more than the figures draw)."""
    return simulate_file(Path(str(resources.files("pounding") / "examples" / "two_10_storey.toml")), 16.0)


@pytest.fixture(scope="module")
def yielding() -> Result:
    """The yielding 5-storey pair (bilinear | Bouc–Wen), the first 6 s."""
    return simulate_file(ROOT / "examples" / "inelastic_5_storey.toml", 6.0)


LONG_NAME = ("a pair of single-storey buildings whose model name goes on and on, much longer "
             "than any page is wide, so that every title has to wrap and the longest be cut")


@pytest.fixture(scope="module")
def narrow() -> Result:
    """The seed SDOF pair, the narrowest figures (one contact, one storey a building), with
    yielding storeys (all six figures), a long model name and long building names, the
    first 4 s."""
    data = tomllib.loads((ROOT / "examples" / "seed_sdof_pair.toml").read_text(encoding="utf-8"))
    data["name"] = LONG_NAME
    data["record"]["duration"] = 4.0
    for b in data["building"]:
        b["name"] += " building, named at such length that no legend column is wide enough"
        b["storey_law"] = {"type": "bilinear", "yield_force": 8e5, "hardening": 0.05}
    model, motion, solver = parse_config(data).build()
    return simulate(model, motion, **solver)


def unit_of(label: str) -> str:
    """The unit in the brackets that end an axis label."""
    m = re.search(r"\[([^\]]+)\]$", label)
    assert m, f"no unit in {label!r}"
    return m.group(1)


def line(ax: Axes, label: str) -> Any:
    found = [ln for ln in ax.get_lines() if ln.get_label() == label]
    assert len(found) == 1, (label, [ln.get_label() for ln in ax.get_lines()])
    return found[0]


# ------------------------------------------------------------------------ decimation
def test_envelope_indices_keep_first_last_min_and_max_of_every_bucket() -> None:
    rng = np.random.default_rng(7)
    n, buckets = 40_000, 700
    y = np.cumsum(rng.normal(size=n))
    y[[5, 12_345, 39_998]] += [400.0, -500.0, 300.0]  # isolated one-sample spikes
    idx = envelope_indices(y, buckets)
    assert np.all(np.diff(idx) > 0) and idx[0] == 0 and idx[-1] == n - 1
    assert idx.size <= 4 * buckets + 4 and idx.size < n / 10
    kept = set(idx.tolist())
    size = -(-n // buckets)
    for start in range(0, n, size):  # every bucket, by a plain loop
        chunk = y[start:start + size]
        for k in (0, len(chunk) - 1, int(np.argmin(chunk)), int(np.argmax(chunk))):
            assert start + k in kept, (start, k)
    assert {5, 12_345, 39_998} <= kept
    assert y[idx].max() == y.max() and y[idx].min() == y.min()
    # short histories are drawn whole; NaN samples are never the extremes
    np.testing.assert_array_equal(envelope_indices(y[:100], 700), np.arange(100))
    z = y.copy()
    z[1000:1100] = np.nan
    iz = envelope_indices(z, buckets)
    assert np.nanmax(z[iz]) == np.nanmax(z) and np.nanmin(z[iz]) == np.nanmin(z)
    # several curves on shared abscissae: every curve keeps its extremes
    cols = np.column_stack([y, -2.0 * y[::-1]])
    iu = union_indices(cols, buckets)
    for j in range(2):
        assert cols[iu, j].max() == cols[:, j].max() and cols[iu, j].min() == cols[:, j].min()


def test_decimated_line_covers_the_same_pixels() -> None:
    """A 40,000-sample history with a one-sample spike, drawn decimated and whole at
    150 dpi: the same pixel columns are inked, each over the same rows within 2 pixels
    (antialiasing shades the ends of the strokes a little differently)."""
    t = np.arange(40_000) * 1e-3
    y = (np.sin(2 * np.pi * 0.9 * t) + 0.3 * np.sin(2 * np.pi * 7.3 * t)) * np.exp(-t / 15)
    y[20_000] += 1.5

    def render(decimated: bool) -> tuple[np.ndarray, int]:
        fig = new_figure(10.0, 3.0)
        ax = axes_grid(fig, 1, 1)[0, 0]
        ln = (history(ax, t, y, color="k", lw=0.8) if decimated
              else ax.plot(t, y, color="k", lw=0.8)[0])
        ax.set_xlim(0.0, t[-1])
        ax.set_ylim(-2.0, 3.0)
        ax.set_axis_off()
        fig.set_dpi(150)
        fig.canvas.draw()
        return np.asarray(fig.canvas.buffer_rgba())[..., 0] < 128, len(ln.get_xdata())

    def column_extents(ink: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        inked = ink.any(axis=0)
        top = ink.argmax(axis=0)
        bottom = ink.shape[0] - 1 - ink[::-1].argmax(axis=0)
        return inked, top, bottom

    whole, n_whole = render(False)
    part, n_part = render(True)
    assert n_whole == 40_000 and n_part < 8_000
    inked_w, top_w, bottom_w = column_extents(whole)
    inked_p, top_p, bottom_p = column_extents(part)
    np.testing.assert_array_equal(inked_w, inked_p)
    assert inked_w.sum() > 1000
    assert np.abs(top_w - top_p)[inked_w].max() <= 2
    assert np.abs(bottom_w - bottom_p)[inked_w].max() <= 2
    spike = top_w[inked_w].min()  # the spike is the highest ink, drawn in both
    assert top_p[inked_p].min() == spike


# ------------------------------------------------------------------------ units
@pytest.mark.parametrize(("peak", "unit", "factor", "name"), [
    (7.8e6, "N", 1e-6, "MN"), (999.0e3, "N", 1e-3, "kN"), (1.0e3, "N", 1e-3, "kN"),
    (12.0, "N", 1.0, "N"), (1.75e-4, "J", 1e6, "µJ"), (0.0, "N", 1.0, "N"),
    (float("nan"), "J", 1.0, "J"), (-2.0e9, "N", 1e-9, "GN")])
def test_scale_for_reads_between_1_and_1000(peak: float, unit: str, factor: float,
                                            name: str) -> None:
    s = scale_for(peak, unit)
    assert s.unit == name and s.factor == pytest.approx(factor, rel=1e-15)
    if np.isfinite(peak) and peak != 0.0:
        assert 1.0 <= abs(peak) * s.factor < 1000.0


@pytest.mark.parametrize(("column", "name", "unit"), [
    ("contact.gap", "gap", "m"), ("contact.e", "coefficient of restitution e", "-"),
    ("contact.k_h", "Hertz stiffness k_h", "N/m^n"), ("record.scale", "record scale factor", "-"),
    ("record.duration", "record duration", "s"), ("solver.duration", "duration simulated", "s"),
    ("building.1.period", "B2 period T1", "s"), ("building.*.mass", "floor mass (every "
                                                                    "building)", "kg"),
    ("peak_contact_force_N", "peak contact force", "N"), ("n_impacts", "impacts", "-"),
    ("contact_dissipated_J", "energy dissipated in contacts", "J"),
    ("peak_drift_m_B2F1", "peak drift B2F1", "m"), ("record_pga_g", "record PGA", "g"),
    ("peak_abs_accel_m_s2_B1F3", "peak absolute acceleration B1F3", "m/s²"),
    ("wall_time_s", "wall time", "s"), ("some_new_measure", "some new measure", None)])
def test_column_names_and_units(column: str, name: str, unit: str | None) -> None:
    assert column_name(column) == name and column_unit(column) == unit


@pytest.mark.parametrize(("value", "unit", "text"), [
    (2.75e9, "N/m^1.5", "2.75e9 N/m^1.5"), (0.3728356652600535, "-", "0.373"),
    (239999.99999999997, "kg", "2.40e5 kg"), (0.05, "", "0.05"), (1500.0, "s", "1500 s"),
    (0.0, "m", "0 m"), (-4.2e-7, "m", "-4.20e-7 m")])
def test_format_value(value: float, unit: str, text: str) -> None:
    assert format_value(value, unit) == text


# ------------------------------------------------------------------------ what is drawn
def test_envelope_figure_draws_the_peaks_of_the_histories(demo: Result) -> None:
    # the envelopes are the result's peaks, located inside solver steps (checked against the
    # SciPy reference in tests/integrate/test_peaks_and_limits.py): they equal the result's
    # properties, and bound the peaks of the sampled histories from above by at most 1e-4
    fig = plot_envelopes(demo)
    ax_u, ax_d, ax_v = fig.axes[:3]
    assert [unit_of(ax.get_xlabel()) for ax in (ax_u, ax_d)] == ["mm", "%"]
    assert unit_of(ax_v.get_xlabel()) == "MN"  # storey shears of 5-18 MN
    assert unit_of(ax_u.get_ylabel()) == "m"
    u = demo.displacement
    for b, (bl, off) in enumerate(zip(demo.model.buildings, demo.model.system.offsets)):
        label = f"B{b + 1} {bl.name}"
        floors = u[:, off:off + bl.n]
        drift = np.diff(np.column_stack([np.zeros(len(u)), floors]), axis=1)  # u_j − u_{j−1}
        shear = drift * bl.stiffnesses  # linear storeys: V = k d
        sampled = (np.abs(floors).max(axis=0), np.abs(drift).max(axis=0) / bl.heights,
                   np.abs(shear).max(axis=0))
        located = (demo.peak_displacement[off:off + bl.n],
                   demo.peak_drift_ratio[off:off + bl.n],
                   demo.peak_storey_shear[off:off + bl.n])
        for s_, l_ in zip(sampled, located):
            assert np.all(l_ >= s_) and np.all(l_ <= s_ * (1 + 1e-4))
        peak_u, peak_ratio, peak_v = located
        levels = np.cumsum(bl.heights)
        ln = line(ax_u, label)  # from 0 at the ground through each floor
        np.testing.assert_allclose(ln.get_xdata(), np.r_[0.0, peak_u] * 1e3, rtol=1e-12)
        np.testing.assert_allclose(ln.get_ydata(), np.r_[0.0, levels], rtol=1e-12)
        for ax, peak, factor in ((ax_d, peak_ratio, 100.0), (ax_v, peak_v, 1e-6)):
            ln = line(ax, label)  # steps: each storey's value from its floor below to above
            np.testing.assert_allclose(ln.get_xdata(), np.repeat(peak, 2) * factor, rtol=1e-9)
            np.testing.assert_allclose(ln.get_ydata(),
                                       np.column_stack([np.r_[0.0, levels[:-1]], levels]).ravel())
    # the contact elevations: filled triangles where the floors hit, hollow where not
    hit = demo.peak_contact_force > 0.0
    marks = [ln for ln in ax_u.get_lines() if ln.get_marker() == "<"]
    filled = [ln for ln in marks if ln.get_markerfacecolor() != "none"]
    assert sum(len(ln.get_ydata()) for ln in filled) == hit.sum() > 0
    assert sum(len(ln.get_ydata()) for ln in marks) == len(demo.model.contacts)


def test_time_history_figures_draw_exact_peaks_and_the_ground_below(demo: Result) -> None:
    nt = demo.time.size
    fig = plot_displacements(demo)
    *panels, ground = fig.axes
    assert len(panels) == 2 and unit_of(ground.get_ylabel()) == "g"
    for ax in panels:
        assert ax.get_shared_x_axes().joined(ax, ground)  # the ground shares the time axis
    for ax, bl, off in zip(panels, demo.model.buildings, demo.model.system.offsets):
        assert unit_of(ax.get_ylabel()) == "mm"
        roof = line(ax, f"F{bl.n} (roof, {bl.total_height:g} m)")
        y = roof.get_ydata()
        u = demo.displacement[:, off + bl.n - 1] * 1e3
        assert len(y) < nt / 2  # decimated for display ...
        assert y.max() == u.max() and y.min() == u.min()  # ... with the peaks exact
    ag = max((ln for ln in ground.get_lines()), key=lambda ln: len(ln.get_ydata()))
    assert np.abs(ag.get_ydata()).max() == pytest.approx(np.abs(demo.ground).max() / G,
                                                         rel=1e-14)

    fig = plot_contact_forces(demo)
    ax, ground = fig.axes
    unit = unit_of(ax.get_ylabel())
    assert unit == "MN" and unit_of(ground.get_ylabel()) == "g"
    drawn = 0
    for c in demo.model.contacts:
        f = demo.contact_force[:, c.index]
        if demo.peak_contact_force[c.index] == 0.0:
            continue
        y = line(ax, f"{c.label} ({c.elevation:g} m)").get_ydata()
        assert y.max() == pytest.approx(f.max() * UNIT_FACTOR[unit], rel=1e-14)
        drawn += 1
    assert drawn == (demo.peak_contact_force > 0).sum() > 0
    # the dots: each impact's peak force of the impact table, at its time
    dots = [ln for ln in ax.get_lines() if ln.get_marker() == "o"]
    ys = np.concatenate([ln.get_ydata() for ln in dots])
    xs = np.concatenate([ln.get_xdata() for ln in dots])
    np.testing.assert_allclose(np.sort(ys), np.sort(demo.impacts["peak_force"].to_numpy())
                               * UNIT_FACTOR[unit], rtol=1e-12)
    np.testing.assert_allclose(np.sort(xs), np.sort(demo.impacts["peak_force_time"].to_numpy()),
                               rtol=1e-12)


def test_energy_figure_stacks_the_terms_up_to_the_input(demo: Result) -> None:
    fig = plot_energy(demo)
    ax, ax_r = fig.axes
    unit = unit_of(ax.get_ylabel())
    assert unit == "MJ"
    inp = line(ax, "input").get_ydata()
    assert inp.max() == pytest.approx(demo.energy[:, 0].max() * 1e-6, rel=1e-14)
    closure = ax_r.get_lines()[0].get_ydata()
    e = demo.energy  # input − (kinetic + strain + damping + contact work): linear storeys
    worst = np.abs(e[:, 0] - e[:, 1] - e[:, 2] - e[:, 3] - e[:, 4]).max()
    factor = {"J": 1.0, "mJ": 1e3, "µJ": 1e6, "nJ": 1e9}[unit_of(ax_r.get_ylabel())]
    assert 1.0 <= worst * factor < 1000.0
    rounding = 8 * np.finfo(float).eps * e[:, 0].max()  # the stack is summed in another order
    assert np.abs(closure).max() == pytest.approx(worst * factor, abs=rounding * factor)


def test_storey_figure_only_where_storeys_yield(demo: Result, yielding: Result) -> None:
    buildings = [k for k, f in RUN_FIGURES.items() if f.bridge is not True]
    assert list(figures_for(demo)) == [k for k in buildings if k != "storey_figure"]
    assert list(figures_for(yielding)) == buildings
    assert figures_for(demo.model) == figures_for(demo)
    files = [f.file for f in RUN_FIGURES.values()]
    assert len(set(files)) == len(files) and all(f.endswith(".png") for f in files)
    # the yielding pair: one row per building, dashed lines at the yield shears ±F_y
    fig = plot_storey_hysteresis(yielding)
    unit = unit_of(fig.axes[0].get_ylabel())
    for b, bl in enumerate(yielding.model.buildings):
        ax = fig.axes[3 * b]
        dashed = sorted(ln.get_ydata()[0] for ln in ax.get_lines() if ln.get_linestyle() == "--")
        title = ax.get_title()
        j = int(re.match(rf"B{b + 1} storey (\d+)", title).group(1)) - 1  # type: ignore[union-attr]
        np.testing.assert_allclose(dashed, np.array([-1.0, 1.0]) * bl.yield_forces[j]
                                   * UNIT_FACTOR[unit], rtol=1e-12)
        assert "ductility" in title and "residual" in title


def test_hysteresis_loops_in_mm_and_force_units(demo: Result) -> None:
    fig = plot_hysteresis(demo)
    unit = unit_of(fig.axes[0].get_ylabel())
    pen = np.concatenate([seg[:, 0] for ax in fig.axes for coll in ax.collections
                          for seg in coll.get_segments()])
    force = np.concatenate([seg[:, 1] for ax in fig.axes for coll in ax.collections
                            for seg in coll.get_segments()])
    closed = demo.penetration > 0
    assert pen.max() == pytest.approx(demo.penetration[closed].max() * 1e3, rel=1e-14)
    assert force.max() == pytest.approx(demo.contact_force[closed].max() * UNIT_FACTOR[unit],
                                        rel=1e-14)


# ------------------------------------------------------------------------ the page
def all_run_figures(*runs: tuple[str, Result]) -> list[tuple[str, Figure]]:
    return [(f"{key} ({name})", fig.make(r)) for name, r in runs
            for key, fig in figures_for(r).items()]


def visible_texts(fig: Figure) -> list[Text]:
    """The texts drawn on the page: tick labels only of ticks inside the axis limits."""
    ticks: set[int] = set()
    shown: list[Text] = []
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            lo, hi = sorted(axis.get_view_interval())
            tol = 1e-9 * (hi - lo)
            for loc, label in zip(axis.get_majorticklocs(), axis.get_majorticklabels()):
                ticks.add(id(label))
                if ax.get_visible() and axis.get_visible() and lo - tol <= loc <= hi + tol:
                    shown.append(label)
    off = {id(a.label) for ax in fig.axes if not ax.axison for a in (ax.xaxis, ax.yaxis)}
    shown += [t for t in fig.findobj(Text) if id(t) not in ticks | off
              and (t.axes is None or t.axes.get_visible())]
    return [t for t in shown if t.get_visible() and t.get_text().strip()]


def assert_plain_axes(name: str, fig: Figure) -> None:
    """Every linear axis of the drawn ``fig`` reads without offset or scientific notation,
    its tick labels plain numbers; every axis label (colour bars too) ends with its unit."""
    number = re.compile(r"^[−-]?\d+(\.\d+)?$")
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            assert axis.get_offset_text().get_text() == "", (name, axis)
            if axis.get_scale() != "linear" or axis.get_ticklocs().size == 0:
                continue
            for tick in axis.get_ticklabels():
                if tick.get_visible() and tick.get_text() and axis.get_major_locator() \
                        .__class__.__name__ != "FixedLocator":  # (a heat map's categories)
                    assert number.match(tick.get_text()), (name, tick.get_text())
        for label in (ax.get_xlabel(), ax.get_ylabel()):
            if label:
                unit_of(label)  # every axis label ends with its unit


def test_no_offset_or_scientific_notation_and_no_text_overlaps(demo: Result,
                                                               yielding: Result,
                                                               narrow: Result) -> None:
    for name, fig in all_run_figures(("demo", demo), ("yielding", yielding),
                                     ("narrow", narrow)):
        fig.set_dpi(100)
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        page = fig.bbox
        assert_plain_axes(name, fig)
        boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in visible_texts(fig)]
        for text, box in boxes:
            assert (box.x0 >= page.x0 - 0.5 and box.y0 >= page.y0 - 0.5
                    and box.x1 <= page.x1 + 0.5 and box.y1 <= page.y1 + 0.5), \
                f"{name}: {text!r} is off the page"
        for i, (t1, b1) in enumerate(boxes):
            for t2, b2 in boxes[i + 1:]:
                overlap = min(b1.x1, b2.x1) - max(b1.x0, b2.x0), min(b1.y1, b2.y1) - max(
                    b1.y0, b2.y0)
                assert min(overlap) <= 0.5, f"{name}: {t1!r} overlaps {t2!r}"


def test_titles_fit_the_page_for_any_model_name(narrow: Result) -> None:
    """The page title of every run figure of the narrow model fits its page, wrapped at word
    boundaries into at most three lines: the model's name, cut short ("…") where it would
    need more, then what the figure shows, whole; the long building names of the panel
    titles and the legend are cut to fit, ending in "…" (the page test above checks that
    nothing is off the page or overlaps)."""
    words = LONG_NAME.split()
    for name, fig in all_run_figures(("narrow", narrow)):
        fig.canvas.draw()
        title = fig.get_suptitle()
        assert title, name
        lines = title.split("\n")
        assert 1 <= len(lines) <= 3
        flat = " ".join(title.split())
        assert flat.split()[:5] == words[:5], (name, title)
        assert flat.startswith(LONG_NAME + ": ") or "…: " in flat, (name, title)
        assert not flat.endswith("…"), (name, title)  # the subject is whole
        width = fig.get_figwidth()
        for line_ in lines:
            assert text_width(line_, fig._suptitle.get_fontsize()) <= width - 0.2 + 1e-9
        box = fig._suptitle.get_window_extent()
        assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1 and box.y1 <= fig.bbox.y1
    env = plot_envelopes(narrow)
    names = [t.get_text() for t in env.legends[0].get_texts()][:2]
    assert all(n.startswith(f"B{i + 1} ") and n.endswith("…") for i, n in enumerate(names))


def test_fit_text_wraps_at_spaces_and_cuts_what_does_not_fit() -> None:
    text = "one two three four five six seven eight nine ten eleven twelve"
    assert fit_text(text, 20.0, 10) == text  # fits: unchanged
    lines = fit_text(text, 1.2, 10).split("\n")
    assert len(lines) == 3 and all(text_width(ln, 10) <= 1.2 for ln in lines)
    assert lines[-1].endswith("…")  # more than three lines' worth: the last one cut
    assert " ".join(lines[:2]).split() == text.split()[:len(" ".join(lines[:2]).split())]
    two = fit_text("abc def", text_width("abc", 10) + 0.01, 10)
    assert two == "abc\ndef"
    word = fit_text("x" * 200, 2.0, 10, max_lines=1)  # one word wider than the room
    assert word.endswith("…") and text_width(word, 10) <= 2.0 and "\n" not in word


# ------------------------------------------------------------------------ sweep figures
@pytest.fixture(scope="module")
def sweep_table(tmp_path_factory: pytest.TempPathFactory) -> pd.DataFrame:
    """A real sweep of the seed SDOF pair, in this process: gap × e × record scale, 4 s."""
    from pounding.studies.sweep import load_results, load_sweep, run_sweep

    folder = tmp_path_factory.mktemp("sweep")
    path = folder / "sweep.toml"
    path.write_text(f'base = "{(ROOT / "examples" / "seed_sdof_pair.toml").as_posix()}"\n'
                    'name = "gap_e"\nout = "out"\n[grid]\n'
                    '"contact.gap" = [0.0, 0.01, 0.04]\n"contact.e" = [0.4, 0.8]\n'
                    '"record.scale" = [1.0, 1.5]\n"record.duration" = [4.0]\n',
                    encoding="utf-8")
    sweep = load_sweep(path)
    run_sweep(sweep, scheduler="synchronous")
    return load_results(sweep.out / "results.parquet")


def test_sweep_figures_name_quantities_in_readable_units(sweep_table: pd.DataFrame) -> None:
    df = sweep_table
    ok = df[df["status"] == "ok"]
    assert len(ok) == 12 and ok["peak_contact_force_N"].max() > 1e6  # forces of MN
    # the heat map of the peak force: gap [mm] × e [-], the colour bar in MN
    fig, _, _ = plot_sweep(df, "contact.gap", "contact.e")
    fig.canvas.draw()
    ax, bar = fig.axes
    assert ax.get_xlabel() == "gap [mm]"
    assert ax.get_ylabel() == "coefficient of restitution e [-]"
    assert bar.get_ylabel() == "peak contact force [MN]"
    assert [t.get_text() for t in ax.get_xticklabels()] == ["0", "10", "40"]
    assert [t.get_text() for t in ax.get_yticklabels()] == ["0.4", "0.8"]
    mean = ok.pivot_table(index="contact.e", columns="contact.gap",
                          values="peak_contact_force_N", aggfunc="mean")
    np.testing.assert_allclose(ax.get_images()[0].get_array(), mean.to_numpy() * 1e-6,
                               rtol=1e-12)
    assert "record scale factor" in ax.get_title()
    assert_plain_axes("heat map", fig)
    # one line per e: the impacts [-] against the gap [mm]
    fig, _, _ = plot_sweep(df, "contact.gap", "contact.e", measure="n_impacts", kind="lines")
    fig.canvas.draw()
    ax = fig.axes[0]
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("gap [mm]", "impacts [-]")
    assert [t.get_text() for t in ax.get_legend().get_texts()] == [
        "coefficient of restitution e = 0.4", "coefficient of restitution e = 0.8"]
    for ln in ax.get_lines():
        np.testing.assert_allclose(ln.get_xdata(), [0.0, 10.0, 40.0])
    assert_plain_axes("lines", fig)
    assert_legends_clear("lines", fig)
    # a line of the mean over the other parameters, per e in its legend with no unit and
    # per gap in mm
    fig, _, _ = plot_sweep(df, "contact.gap")
    fig.canvas.draw()
    ax = fig.axes[0]
    assert ax.get_ylabel() == "peak contact force [MN]"
    np.testing.assert_allclose(ax.get_lines()[0].get_ydata(), ok.groupby("contact.gap")[
        "peak_contact_force_N"].mean().to_numpy() * 1e-6, rtol=1e-12)
    assert_plain_axes("line", fig)
    fig, _, _ = plot_sweep(df, "contact.e", "contact.gap", kind="lines")
    assert [t.get_text() for t in fig.axes[0].get_legend().get_texts()] == [
        "gap = 0 mm", "gap = 10 mm", "gap = 40 mm"]


# ------------------------------------------------------------------------ legends
def drawn_points(ax: Axes) -> np.ndarray:
    """Display coordinates of every line of ``ax`` inside the axes: its markers, and for a
    drawn line its stroke, 16 points a segment."""
    out = [np.empty((0, 2))]
    for ln in ax.get_lines():
        if not ln.get_visible() or not len(ln.get_xydata()):
            continue
        xy = ln.get_transform().transform(np.asarray(ln.get_xydata(), dtype=float))
        xy = xy[np.isfinite(xy).all(axis=1)]
        if ln.get_linestyle() not in ("None", "", " ", "none") and len(xy) > 1:
            f = np.linspace(0.0, 1.0, 16)[:, None, None]
            xy = (xy[:-1] + f * (xy[1:] - xy[:-1])).reshape(-1, 2)
        box = ax.bbox
        out.append(xy[(xy[:, 0] >= box.x0) & (xy[:, 0] <= box.x1) & (xy[:, 1] >= box.y0)
                      & (xy[:, 1] <= box.y1)])
    return np.concatenate(out)


def assert_legends_clear(name: str, fig: Figure) -> None:
    """No point of a drawn line or marker of ``fig`` lies under one of its legends."""
    fig.canvas.draw()
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend()] + list(fig.legends)
    assert legends, name
    points = np.concatenate([drawn_points(ax) for ax in fig.axes])
    for legend in legends:
        box = legend.get_window_extent().padded(-1.0)
        under = ((points[:, 0] > box.x0) & (points[:, 0] < box.x1) & (points[:, 1] > box.y0)
                 & (points[:, 1] < box.y1))
        assert not under.any(), f"{name}: the legend covers {under.sum()} drawn points"


AUDIT = {  # achieved e of `pounding audit` (docs/audit.md) at e = 0.1 … 0.9, to 3 decimals
    ("anagnostopoulos", "kelvin-voigt (tension)", True): np.arange(1, 10) / 10,
    ("anagnostopoulos", "kelvin-voigt (no tension)", False): [
        0.253, 0.325, 0.397, 0.472, 0.55, 0.632, 0.718, 0.808, 0.902],
    ("schwager-poschel", "kelvin-voigt (no tension)", True): np.arange(1, 10) / 10,
    ("anagnostopoulos", "modified-kelvin-voigt", False): [
        0.503, 0.57, 0.63, 0.687, 0.742, 0.795, 0.847, 0.899, 0.95],
    ("mahmoud", "modified-kelvin-voigt", True): [
        0.102, 0.205, 0.307, 0.407, 0.506, 0.605, 0.703, 0.801, 0.9],
    ("mahmoud", "nonlinear-viscoelastic", False): [
        0.114, 0.225, 0.333, 0.436, 0.535, 0.632, 0.726, 0.819, 0.91],
    ("jankowski", "nonlinear-viscoelastic", True): [
        0.093, 0.191, 0.292, 0.393, 0.495, 0.596, 0.698, 0.799, 0.9],
    ("naderpour", "nonlinear-viscoelastic", True): [
        0.002, 0.007, 0.017, 0.034, 0.063, 0.115, 0.217, 0.421, 0.769],
    ("naderpour", "kelvin-voigt (tension)", False): [0.0] * 7 + [0.001, 0.511],
    ("hunt-crossley", "hunt-crossley", True): [
        0.516, 0.547, 0.581, 0.62, 0.663, 0.712, 0.768, 0.833, 0.909],
    ("lankarani-nikravesh", "hunt-crossley", True): [
        0.665, 0.672, 0.684, 0.702, 0.725, 0.756, 0.796, 0.847, 0.913],
    ("flores", "hunt-crossley", True): [
        0.069, 0.156, 0.256, 0.363, 0.47, 0.577, 0.683, 0.789, 0.894],
    ("gonthier", "hunt-crossley", True): [
        0.101, 0.205, 0.304, 0.398, 0.488, 0.577, 0.67, 0.768, 0.876],
    ("muthukumar (energy-equivalent)", "bilinear-impact", True): [
        0.609, 0.619, 0.636, 0.66, 0.692, 0.734, 0.784, 0.845, 0.917],
}


def audit_table() -> pd.DataFrame:
    target = np.arange(1, 10) / 10
    return pd.DataFrame([{"formula": f, "law": law, "intended": intended, "target_e": t,
                          "achieved_e": a, "error": a - t}
                         for (f, law, intended), achieved in AUDIT.items()
                         for t, a in zip(target, achieved)])


def test_legends_cover_no_data() -> None:
    """The seed's Fig 4 (its eq-39 curve and Table 1 points reach the upper left), the
    restitution audit (its naderpour curves run through the lower left of the error
    panel), the link-element loop, thin and fat, spectra that fill their axes, and a sweep's
    lines: every legend is where no line or marker is, inside the axes or beside them."""
    periods = np.geomspace(0.02, 5.0, 160)
    names = [f"record_{k}_of_a_suite_RSN{1000 + k}.AT2, ζ=5%" for k in range(9)]
    peaks = np.geomspace(0.03, 4.0, 9)
    curves = [(n, 0.3 + 3.0 * np.exp(-np.log(periods / p) ** 2 / 0.4))
              for n, p in zip(names, peaks)]
    figures = [("Fig 4", plot_damping_formulas()), ("audit", plot_audit(audit_table())),
               ("ellipse", plot_hysteresis_ellipse(1e8, 1e6, 10.0, 0.01)),
               ("fat ellipse", plot_hysteresis_ellipse(1e8, 4e7, 10.0, 0.01)),
               ("spectra", plot_spectra(periods, curves))]
    for name, fig in figures:
        assert_legends_clear(name, fig)
    # Fig 4 keeps all of its curves and Table 1 in view, with the legend beside them
    ax_z = plot_damping_formulas().axes[0]
    assert len(ax_z.get_lines()) == 6


def test_saved_page_is_the_figure_as_laid_out(demo: Result, tmp_path: Path) -> None:
    fig = plot_envelopes(demo)
    out = save_figure(fig, tmp_path / "envelopes.png", dpi=120)
    head = out.read_bytes()[:24]
    assert head[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", head[16:24])
    w_in, h_in = fig.get_size_inches()
    assert (width, height) == (round(w_in * 120), round(h_in * 120))  # not cropped
    assert [p.name for p in tmp_path.iterdir()] == ["envelopes.png"]


def test_single_building_and_no_impact_figures(tmp_path: Path) -> None:
    one = parse_config({"record": {"bundled": "el_centro", "duration": 2.0},
                        "building": [{"n_storeys": 3, "mass": 1e5, "period": 0.4}]})
    model, motion, solver = one.build()
    r = simulate(model, motion, **solver)
    for key, fig in figures_for(r).items():
        f = fig.make(r)
        assert isinstance(f, Figure), key
        f.canvas.draw()
    env = plot_envelopes(r)
    assert not [ln for ln in env.axes[0].get_lines() if ln.get_marker() == "<"]


def test_figure_registry_does_not_import_matplotlib() -> None:
    code = ("import sys, pounding.plot, pounding.plot.registry as r; "
            "assert r.RUN_FIGURES and r.figures_for; "
            "print('matplotlib' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "False"

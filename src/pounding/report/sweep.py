"""The sweep page: overview, parameter grid, results, the main measure against each swept
parameter, and the sweep's metadata."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pounding.report.format import (Block, Figure, Note, Pre, PageSection, Table, kv_table, num,
                                    png_bytes, unit_of)
from pounding.report.page import render_page
from pounding.report.sweep_folder import SweepFolder, is_numeric, read_sweep

__all__ = ["MAX_SWEEP_PLOTS", "MAX_SWEEP_ROWS", "render_sweep"]

MAX_SWEEP_ROWS = 50
"""At most this many cases of a sweep are listed (all of them are in ``results.parquet``)."""

MAX_SWEEP_PLOTS = 8
"""At most this many swept parameters get a plot."""

_TEXT_COLUMNS = ("case_id", "status", "error", "contact.law", "law", "record.file",
                 "record.bundled", "formula")
"""Text columns of a sweep: no unit is expected."""


def render_sweep(folder: Path, code_check: Any = None) -> str:
    """The HTML text of the report of the sweep folder ``folder`` (with a "Code check"
    section for ``code_check``, a :class:`~pounding.report.code_check.CodeCheckFile`).

    Raises
    ------
    ValueError
        ``results.parquet`` is unreadable (:func:`pounding.report.sweep_folder.read_sweep`).
    """
    sw = read_sweep(folder)
    n = len(sw.df)
    names = [sw.meta.get("name")] + [v.get("name") for v in sw.meta.values()
                                      if isinstance(v, dict)]
    title = str(next((x for x in names if x), folder.resolve().name))
    sections = [
        PageSection("overview", "Overview", _overview_section(sw)),
        PageSection("grid", "Parameter grid", _grid_section(sw)),
        PageSection("results", "Results", _results_section(sw)),
        PageSection("plots", "Main measure against each parameter", _plots_section(sw)),
    ]
    if code_check is not None:
        from pounding.report.code_check import code_check_section

        sections.append(code_check_section(code_check))
    if sw.meta:
        sections.append(PageSection("metadata", "Sweep metadata",
                                [Pre(json.dumps(sw.meta, indent=2, default=str))]))
    return render_page(f"{title}: pounding sweep report",
                       f"Sweep report — {n} case(s), {len(sw.parameters)} swept parameter(s); "
                       f"folder {folder.resolve().name}", sections, folder)


def _overview_section(sw: SweepFolder) -> list[Block]:
    df = sw.df
    failed = (df[df["status"].astype(str) != "ok"] if "status" in df.columns
              else df.iloc[:0])
    overview = [("cases", len(df)), ("cases failed (status not ok)", len(failed)),
                ("swept parameters", ", ".join(sw.parameters) or "–"),
                ("measures", ", ".join(sw.measures) or "–"),
                ("main measure (plotted)", sw.label(sw.main) if sw.main else "–"),
                ("how parameters were recognised", sw.how)]
    out: list[Block] = [kv_table(overview)]
    if len(failed):
        ft = Table(("#", "case", "error"), caption="Failed cases (their measures are empty)")
        for i, (_, row) in enumerate(failed.head(MAX_SWEEP_ROWS).iterrows()):
            case = ", ".join(f"{p} = {num(row[p])}" for p in sw.parameters)
            ft.add(int(row["case_index"]) if "case_index" in df.columns else i + 1, case,
                   str(row.get("error") or "–"))
        out += [Note(f"{len(failed)} case(s) failed.", "warn"), ft]
    return out


def _grid_section(sw: SweepFolder) -> list[Block]:
    df = sw.df
    if not sw.parameters:
        return [Note("No parameter column recognised.")]
    grid = Table(("parameter", "values", "distinct values", "min", "max"),
                 caption="Parameter grid (values found in results.parquet)")
    for p in sw.parameters:
        vals = np.asarray(pd.unique(df[p].dropna()))
        try:
            vals = np.sort(vals)
        except TypeError:
            pass
        shown = ", ".join(num(v) for v in vals[:20]) + (" …" if len(vals) > 20 else "")
        numeric = pd.api.types.is_numeric_dtype(df[p]) and not pd.api.types.is_bool_dtype(df[p])
        grid.add(sw.label(p), shown, len(vals),
                 float(df[p].min()) if numeric else "–", float(df[p].max()) if numeric else "–")
    n = len(df)
    product = int(np.prod([df[p].nunique(dropna=False) for p in sw.parameters]))
    return [grid, Note(f"{n} case(s); the full grid of these values has {product} "
                       + ("(a full grid)." if product == n else
                          "(not a full grid: some combinations are absent or repeated)."))]


def _results_section(sw: SweepFolder) -> list[Block]:
    df = sw.df
    n = len(df)
    stats = Table(("measure", "count", "mean", "std", "min", "median", "max"),
                  caption="Summary statistics over all cases")
    for m in sw.measures:
        if not is_numeric(df[m]):
            continue
        v = df[m].astype(float)
        stats.add(sw.label(m), int(v.notna().sum()), v.mean(), v.std(), v.min(), v.median(),
                  v.max())
    cols = list(df.columns)
    head = Table(["#"] + [sw.label(c) for c in cols],
                 caption=f"First {min(n, MAX_SWEEP_ROWS)} of {n} case(s)", scroll=True)
    for i, (_, row) in enumerate(df.head(MAX_SWEEP_ROWS).iterrows()):
        head.add(i + 1, *[row[c] for c in cols])
    out: list[Block] = [stats, head]
    unknown = [c for c in cols if unit_of(c, sw.units) is None and c not in _TEXT_COLUMNS]
    if unknown:
        out.append(Note("Columns shown without a unit: results.parquet does not state one ("
                        + ", ".join(unknown) + ")."))
    return out


def _plots_section(sw: SweepFolder) -> list[Block]:
    df = sw.df
    if sw.main is None:
        return [Note("No numeric measure to plot.")]
    plots: list[Block] = []
    for p in sw.parameters[:MAX_SWEEP_PLOTS]:
        if df[p].nunique(dropna=True) < 2:
            plots.append(Note(f"{p}: one value only ({num(df[p].iloc[0])}), not plotted."))
            continue
        plots.append(Figure(_sweep_plot(sw, sw.main, p), f"{sw.main} against {p}",
                            f"{sw.label(sw.main)} against {sw.label(p)}: grey dots each case, "
                            "line the mean over the other parameters."))
    if len(sw.parameters) > MAX_SWEEP_PLOTS:
        plots.append(Note(f"{len(sw.parameters) - MAX_SWEEP_PLOTS} more parameter(s) not "
                          "plotted."))
    if not sw.parameters:
        plots.append(Note("No parameter to plot against."))
    return plots


def _sweep_plot(sw: SweepFolder, measure: str, param: str) -> bytes:
    """``measure`` against ``param``: each case, and the mean with its min … max band over
    the other parameters; axes named with their units in readable multiples
    (:func:`pounding.plot.sweep.axis_label`), no offset notation, the legend where it hides
    no data."""
    from matplotlib.figure import Figure as MplFigure

    from pounding.plot.layout import place_legend, plain_ticks
    from pounding.plot.sweep import axis_label
    from pounding.units import column_name

    df = sw.df
    y_label, y_scale = axis_label(measure, df[measure])
    y = df[measure].astype(float) * y_scale.factor
    x_raw = df[param]
    numeric_x = pd.api.types.is_numeric_dtype(x_raw) and not pd.api.types.is_bool_dtype(x_raw)
    fig = MplFigure(figsize=(7.5, 3.6))
    ax = fig.subplots()
    if numeric_x:
        x_label, x_scale = axis_label(param, x_raw)
        x = x_raw.astype(float) * x_scale.factor
        ticks = None
    else:
        x_label = column_name(param)
        cats = sorted(x_raw.astype(str).unique())
        x = x_raw.astype(str).map({c: i for i, c in enumerate(cats)}).astype(float)
        ticks = cats
    ax.plot(x, y, "o", ms=3.5, color="0.55", alpha=0.6, label="each case", zorder=2)
    g = pd.DataFrame({"x": x, "y": y}).groupby("x")["y"]
    stats = g.agg(["mean", "min", "max"]).sort_index()
    if len(stats) > 1:
        ax.fill_between(stats.index, stats["min"], stats["max"], color="C0", alpha=0.15,
                        label="min … max over the other parameters", zorder=1)
    ax.plot(stats.index, stats["mean"], "-o", color="C0", ms=4, lw=1.5, label="mean", zorder=3)
    if ticks is not None:
        ax.set_xticks(range(len(ticks)))
        ax.set_xticklabels(ticks, rotation=30 if len(ticks) > 4 else 0, fontsize=8)
    ax.set_xlabel(x_label)
    ax.set_ylabel(y_label)
    ax.grid(True, alpha=0.3)
    ax.set_title(f"{column_name(measure)} against {column_name(param)}", fontsize=9,
                 loc="left")
    fig.tight_layout()
    place_legend(ax, fontsize=7)
    plain_ticks(fig)
    return png_bytes(fig)

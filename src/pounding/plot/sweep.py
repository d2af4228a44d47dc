"""Figures of a parameter sweep: a measure against one or two swept parameters."""

from __future__ import annotations

import re
from typing import Any, Literal

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from pounding.plot import new_figure
from pounding.plot.layout import Scale, display_scale, place_legend, plain_ticks
from pounding.units import column_name, unit_of

__all__ = ["axis_label", "default_figure_name", "plot_sweep", "swept_parameters"]

_REDUCERS: dict[str, Literal["mean", "max", "min", "median"]] = {
    "mean": "mean", "max": "max", "min": "min", "median": "median"}
"""How cases with equal parameters shown are combined: by name, pandas' aggregation."""


def swept_parameters(df: pd.DataFrame) -> list[str]:
    """The parameter columns of a results table (between ``case_id`` and ``status``)."""
    cols = list(df.columns)
    if "case_id" not in cols or "status" not in cols:
        raise ValueError("not a sweep results table (no case_id/status columns)")
    return cols[cols.index("case_id") + 1: cols.index("status")]


def default_figure_name(measure: str, x: str, y: str | None) -> str:
    """``<measure>_vs_<x>[_<y>].png`` with file-safe names."""
    def safe(s: str) -> str:
        return re.sub(r"[^A-Za-z0-9_.-]+", "_", s)
    return f"{safe(measure)}_vs_{safe(x)}" + (f"_{safe(y)}" if y else "") + ".png"


def axis_label(column: str, values: Any) -> tuple[str, Scale]:
    """The label of a column's axis and the unit it is drawn in.

    Parameters
    ----------
    column : str
        A parameter path or measure column (``contact.gap``, ``peak_contact_force_N``).
    values : array_like
        What is drawn: numbers pick the multiple of the unit (N → kN or MN, m → mm,
        :func:`pounding.plot.layout.display_scale`); anything else is drawn as it is.

    Returns
    -------
    tuple of (str, Scale)
        ``"gap [mm]"``, ``"coefficient of restitution e [-]"``, ``"peak contact force
        [MN]"``, with the scale to multiply the SI values by; the name alone when the unit
        is not known.
    """
    unit = unit_of(column)
    v = pd.to_numeric(pd.Series(np.asarray(values, dtype=object).ravel()), errors="coerce")
    peak = float(v.abs().max()) if v.notna().any() else 0.0
    scale = display_scale(unit, peak) if unit else Scale(1.0, "")
    name = column_name(column)
    return (f"{name} [{scale.unit}]" if unit else name), scale


def plot_sweep(df: pd.DataFrame, x: str | None = None, y: str | None = None,
               measure: str = "peak_contact_force_N", kind: str = "heatmap",
               reduce: str = "mean") -> tuple[Figure, str, str | None]:
    """A measure against parameter ``x`` (a line), or ``x`` and ``y``: a heat map
    (``kind="heatmap"``) or one line per value of ``y`` (``kind="lines"``).

    Cases with equal ``x`` (and ``y``) — other parameters varied too — are combined with
    ``reduce``. Failed cases are left out. Axes and colour bar name the quantity and its
    unit (:func:`axis_label`: "gap [mm]", "peak contact force [MN]"), without offset or
    scientific notation. Returns ``(figure, x, y)``.
    """
    params = swept_parameters(df)
    x = x or params[0]
    for name, what in ((x, "--x"), (y, "--y")):
        if name is not None and name not in params:
            raise ValueError(f"{what}: {name!r} is not a swept parameter; swept: "
                             f"{', '.join(params)}")
    if measure not in df.columns:
        numeric = [c for c in df.columns if c not in params
                   and pd.api.types.is_numeric_dtype(df[c]) and c != "case_index"]
        raise ValueError(f"--measure: no column {measure!r}; choose one of "
                         f"{', '.join(numeric)}")
    how = _REDUCERS.get(reduce)
    if how is None:
        raise ValueError(f"--reduce: one of {', '.join(_REDUCERS)} (got {reduce!r})")
    if kind not in ("heatmap", "lines"):
        raise ValueError(f"--kind: heatmap or lines (got {kind!r})")
    if x == y:
        raise ValueError("--y: give a parameter other than --x")
    ok = df[df["status"] == "ok"]
    if ok.empty:
        raise ValueError("no successful cases to plot")
    vals = pd.to_numeric(ok[measure], errors="coerce").astype(float)
    frame = ok[[x] + ([y] if y else [])].copy()
    frame["_v"] = vals.to_numpy()
    fig = new_figure(6.4, 4.8, laid_out=False)
    ax = fig.add_subplot()
    others = [p for p in params if p not in (x, y)]
    note = f" ({reduce} over {', '.join(column_name(p) for p in others)})" if others else ""
    x_label, xs = axis_label(x, frame[x])
    if y is None:
        g = frame.groupby(x, sort=True)["_v"].agg(how)
        m_label, ms = axis_label(measure, g.to_numpy())
        ax.plot(_axis(g.index, xs), g.to_numpy() * ms.factor, marker="o")
        _ticks(ax, g.index)
    elif kind == "lines":
        groups = [(yv, sub.groupby(x, sort=True)["_v"].agg(how))
                  for yv, sub in frame.groupby(y, sort=True)]
        m_label, ms = axis_label(measure, np.concatenate([g.to_numpy() for _, g in groups]))
        _, ys = axis_label(y, frame[y])
        for yv, g in groups:
            ax.plot(_axis(g.index, xs), g.to_numpy() * ms.factor, marker="o",
                    label=f"{column_name(y)} = {_fmt(yv, ys, with_unit=True)}")
        _ticks(ax, pd.Index(sorted(frame[x].unique())))
    else:
        table = frame.pivot_table(index=y, columns=x, values="_v", aggfunc=how,
                                  sort=True)
        m_label, ms = axis_label(measure, table.to_numpy(dtype=float))
        y_label, ys = axis_label(y, frame[y])
        im = ax.imshow(table.to_numpy(dtype=float) * ms.factor, origin="lower", aspect="auto",
                       cmap="viridis")
        ax.set_xticks(np.arange(table.shape[1]), [_fmt(v, xs) for v in table.columns],
                      rotation=45 if table.shape[1] > 8 else 0)
        ax.set_yticks(np.arange(table.shape[0]), [_fmt(v, ys) for v in table.index])
        fig.colorbar(im, ax=ax, label=m_label)
        ax.set_ylabel(y_label)
    ax.set_xlabel(x_label)
    ax.set_title(f"{column_name(measure)}{note}", fontsize="medium")
    plain_ticks(fig)
    if y is None or kind == "lines":
        ax.set_ylabel(m_label)
        ax.grid(True, alpha=0.3)
    if kind == "lines" and y is not None:
        place_legend(ax, fontsize="small")
    return fig, x, y


def _numeric(index: pd.Index) -> bool:
    return pd.api.types.is_numeric_dtype(index) and not pd.api.types.is_bool_dtype(index)


def _axis(index: pd.Index, scale: Scale) -> Any:
    """Positions along x: the values in the axis unit, or 0, 1, … for labels."""
    return (index.to_numpy(dtype=float) * scale.factor if _numeric(index)
            else np.arange(len(index)))


def _ticks(ax: Any, index: pd.Index) -> None:
    """Tick labels along x for a parameter that is not a number."""
    if not _numeric(index):
        ax.set_xticks(np.arange(len(index)), [_fmt(v, Scale(1.0, "")) for v in index])


def _fmt(v: Any, scale: Scale, with_unit: bool = False) -> str:
    """A value of a parameter as a tick or legend label, in the axis unit (written after
    it with ``with_unit``, unless dimensionless)."""
    if isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, bool):
        unit = f" {scale.unit}" if with_unit and scale.unit not in ("", "-") else ""
        return f"{float(v) * scale.factor:g}{unit}"
    text = str(v)
    return text if len(text) <= 24 else "…" + text[-23:]

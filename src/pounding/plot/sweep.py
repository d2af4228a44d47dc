"""Figures of a parameter sweep: a measure against one or two swept parameters."""

from __future__ import annotations

import re
from typing import Any

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from pounding.plot import new_figure

__all__ = ["default_figure_name", "plot_sweep", "swept_parameters"]

_REDUCERS = ("mean", "max", "min", "median")


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


def plot_sweep(df: pd.DataFrame, x: str | None = None, y: str | None = None,
               measure: str = "peak_contact_force_N", kind: str = "heatmap",
               reduce: str = "mean") -> tuple[Figure, str, str | None]:
    """A measure against parameter ``x`` (a line), or ``x`` and ``y``: a heat map
    (``kind="heatmap"``) or one line per value of ``y`` (``kind="lines"``).

    Cases with equal ``x`` (and ``y``) — other parameters varied too — are combined with
    ``reduce``. Failed cases are left out. Returns ``(figure, x, y)``.
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
    if reduce not in _REDUCERS:
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
    note = f" ({reduce} over {', '.join(others)})" if others else ""
    if y is None:
        g = frame.groupby(x, sort=True)["_v"].agg(reduce)
        ax.plot(_axis(g.index), g.to_numpy(), marker="o")
        _ticks(ax, g.index, "x")
    elif kind == "lines":
        for yv, sub in frame.groupby(y, sort=True):
            g = sub.groupby(x, sort=True)["_v"].agg(reduce)
            ax.plot(_axis(g.index), g.to_numpy(), marker="o", label=f"{y} = {_fmt(yv)}")
        _ticks(ax, pd.Index(sorted(frame[x].unique())), "x")
        ax.legend(fontsize="small")
    else:
        table = frame.pivot_table(index=y, columns=x, values="_v", aggfunc=reduce,
                                  sort=True)
        im = ax.imshow(table.to_numpy(dtype=float), origin="lower", aspect="auto",
                       cmap="viridis")
        ax.set_xticks(np.arange(table.shape[1]), [_fmt(v) for v in table.columns],
                      rotation=45 if table.shape[1] > 8 else 0)
        ax.set_yticks(np.arange(table.shape[0]), [_fmt(v) for v in table.index])
        fig.colorbar(im, ax=ax, label=measure)
        ax.set_ylabel(y)
    ax.set_xlabel(x)
    if y is None or kind == "lines":
        ax.set_ylabel(measure)
        ax.grid(True, alpha=0.3)
    ax.set_title(f"{measure}{note}", fontsize="medium")
    return fig, x, y


def _numeric(index: pd.Index) -> bool:
    return pd.api.types.is_numeric_dtype(index) and not pd.api.types.is_bool_dtype(index)


def _axis(index: pd.Index) -> Any:
    return index.to_numpy(dtype=float) if _numeric(index) else np.arange(len(index))


def _ticks(ax: Any, index: pd.Index, which: str) -> None:
    if not _numeric(index):
        ax.set_xticks(np.arange(len(index)), [_fmt(v) for v in index])


def _fmt(v: Any) -> str:
    if isinstance(v, (float, np.floating)):
        return f"{v:g}"
    text = str(v)
    return text if len(text) <= 24 else "…" + text[-23:]

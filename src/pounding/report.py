"""One self-contained HTML page for a run folder or a sweep folder (``pounding report``).

:func:`write_report` reads what ``pounding run`` or ``pounding sweep`` wrote and writes a
single HTML file: inline CSS, every figure embedded as a base64 PNG (``data:`` URI), no
script, no external link — it opens the same offline, from a mail attachment or an archive.
Every text taken from the files is HTML-escaped; every quantity carries its unit.

* A **run** folder holds ``summary.json`` and ``timehistories.nc`` (and normally
  ``impacts.csv``, ``model.toml`` and the PNG figures). The page shows the model, the record,
  the headline numbers, the figures (the PNGs of the folder, or regenerated from the NetCDF
  when the model file can be rebuilt), the impact table, the energy balance and a gap check.
* A **sweep** folder holds ``results.parquet`` (one row per case: parameters and measures).
  The page shows the parameter grid, the first rows of the results with summary statistics,
  and the main measure plotted against each swept parameter.

The report only reads the folder; it writes nothing there but the report itself (written
atomically, :func:`pounding.io.write_text`). See ``docs/report.md``.
"""

from __future__ import annotations

import base64
import datetime as _dt
import html
import io
import json
import math
import os
import re
import tomllib
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pounding.io import write_text
from pounding.result import ENERGY_NAMES, peak_abs

__all__ = ["DEFAULT_NAME", "MAX_IMPACT_ROWS", "MAX_SWEEP_ROWS", "RUN_FILES", "SWEEP_FILE",
           "detect_kind", "render_report", "write_report"]

DEFAULT_NAME = "report.html"
"""File name of the report inside the results folder when no ``out`` is given."""

RUN_FILES: tuple[str, ...] = ("summary.json", "timehistories.nc")
"""Files that make a folder a run output."""

SWEEP_FILE = "results.parquet"
"""The file that makes a folder a sweep output."""

MAX_IMPACT_ROWS = 500
"""At most this many impacts are listed (all of them are in ``impacts.csv``)."""

MAX_SWEEP_ROWS = 50
"""At most this many cases of a sweep are listed (all of them are in ``results.parquet``)."""

MAX_SWEEP_PLOTS = 8
"""At most this many swept parameters get a plot."""

ENERGY_DESCRIPTIONS: dict[str, str] = {
    "input": "input energy −∫u̇ᵀMr·a_g dt",
    "kinetic": "kinetic energy ½u̇ᵀMu̇ (relative to the ground)",
    "strain": "elastic strain energy ½uᵀKu (plus the recoverable energy of yielding storeys)",
    "damping": "dissipated by structural (viscous) damping ∫u̇ᵀCu̇ dt",
    "contact_work": "work of the contact forces ∫ΣF·δ̇ dt",
    "contact_stored": "elastic energy still stored in closed contacts",
    "hysteretic": "hysteretic energy of yielding storeys (their work less what they would give "
                  "back)",
}

CONTACT_UNITS: dict[str, str] = {
    "k": "N/m", "k_h": "N/m^n", "e": "-", "c": "N·s/m", "zeta": "-", "chi": "-", "n": "-",
    "delta_m": "m", "a": "-", "gap": "m", "gaps": "m", "formula": "", "tension": "",
    "law": "",
}
"""Units of the keys of ``[contact]`` (``docs/running.md``)."""

# column-name suffix → unit, longest first (sweep results and summaries name their unit)
_SUFFIX_UNITS: tuple[tuple[str, str], ...] = (
    ("_m_s2", "m/s²"), ("_m_s", "m/s"), ("_N_m", "N/m"), ("_kg", "kg"), ("_Hz", "Hz"),
    ("_pct", "%"), ("_N", "N"), ("_J", "J"), ("_m", "m"), ("_s", "s"), ("_g", "g"),
)
_NAME_UNITS: dict[str, str] = {
    "gap": "m", "gaps": "m", "k": "N/m", "k_h": "N/m^n", "e": "-", "zeta": "-", "chi": "-",
    "n": "-", "delta_m": "m", "mass": "kg", "period": "s", "stiffness": "N/m", "height": "m",
    "pga_g": "g", "scale": "-", "duration": "s", "dt": "s", "rtol": "-", "n_impacts": "-",
    "impacts": "-", "energy_balance_error": "-", "restitution": "-", "drift_ratio": "-",
    "case": "-", "touched": "-", "pounding": "-", "peak_drift_ratio": "-",
    "impact_overflow": "-", "case_index": "-",
}
_TEXT_COLUMNS = ("case_id", "status", "error", "contact.law", "law", "record.file",
                 "record.bundled", "formula")
"""Text columns of a sweep: no unit is expected."""


# =============================================================================== detection
def detect_kind(results_dir: str | os.PathLike[str]) -> str:
    """``"run"`` or ``"sweep"``: what ``results_dir`` holds.

    Raises
    ------
    ValueError
        The folder does not exist, or is neither a run output (``summary.json`` and
        ``timehistories.nc``) nor a sweep output (``results.parquet``); the message names
        the folder and the files missing.
    """
    folder = Path(results_dir)
    if not folder.is_dir():
        what = "does not exist" if not folder.exists() else "is not a folder"
        raise ValueError(f"report: {folder} {what}; give the output folder of "
                         "`pounding run` or `pounding sweep`")
    run_missing = [f for f in RUN_FILES if not (folder / f).is_file()]
    if not run_missing:
        return "run"
    if (folder / SWEEP_FILE).is_file():
        return "sweep"
    raise ValueError(
        f"report: {folder} is neither a run output (missing {', '.join(run_missing)}) nor a "
        f"sweep output (missing {SWEEP_FILE}); give the output folder of `pounding run` or "
        "`pounding sweep`")


def write_report(results_dir: str | os.PathLike[str],
                 out: str | os.PathLike[str] | None = None) -> Path:
    """Write the HTML report of a run or sweep folder and return its path.

    Parameters
    ----------
    results_dir : path-like
        The output folder of ``pounding run`` or ``pounding sweep`` (:func:`detect_kind`).
    out : path-like, optional
        The HTML file to write; default ``results_dir/report.html``. Written atomically.

    Raises
    ------
    ValueError
        ``results_dir`` is neither a run nor a sweep output, or a file in it is unreadable.
    """
    folder = Path(results_dir)
    text = render_report(folder)
    target = Path(out) if out is not None else folder / DEFAULT_NAME
    if target.is_dir():
        raise ValueError(f"report: --out {target} is a folder; give a file name such as "
                         f"{target / DEFAULT_NAME}")
    return write_text(target, text)


def render_report(results_dir: str | os.PathLike[str]) -> str:
    """The HTML text of the report of ``results_dir`` (see :func:`write_report`)."""
    folder = Path(results_dir)
    kind = detect_kind(folder)
    return _render_run(folder) if kind == "run" else _render_sweep(folder)


# =============================================================================== HTML helpers
def _e(x: Any) -> str:
    return html.escape(str(x), quote=True)


def _num(v: Any, digits: int = 4) -> str:
    """A number for a table cell (plain text, not escaped)."""
    if v is None:
        return "–"
    if isinstance(v, (bool, np.bool_)):
        return "yes" if v else "no"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        f = float(v)
        if math.isnan(f):
            return "–"
        if math.isinf(f):
            return "∞" if f > 0 else "−∞"
        if f == 0.0:
            return "0"
        if f.is_integer() and abs(f) < 1e6:
            return str(int(f))
        return f"{f:.{digits}g}"
    return str(v)


def _with_unit(label: str, unit: str | None) -> str:
    return f"{label} [{unit}]" if unit else label


@dataclass
class _Table:
    headers: Sequence[str]
    rows: list[Sequence[Any]] = field(default_factory=list)
    caption: str = ""
    cls: str = ""

    def add(self, *cells: Any) -> None:
        self.rows.append(cells)

    def html(self) -> str:
        out = [f'<table class="{_e(self.cls)}">' if self.cls else "<table>"]
        if self.caption:
            out.append(f"<caption>{_e(self.caption)}</caption>")
        out.append("<thead><tr>" + "".join(f"<th>{_e(h)}</th>" for h in self.headers)
                   + "</tr></thead><tbody>")
        for row in self.rows:
            cells = []
            for v in row:
                # numbers right-aligned, text (labels, notes, "–") left-aligned
                text = _num(v) if not isinstance(v, str) else v
                attr = ' class="n"' if not isinstance(v, str) else ""
                cells.append(f"<td{attr}>{_e(text)}</td>")
            out.append("<tr>" + "".join(cells) + "</tr>")
        out.append("</tbody></table>")
        return "".join(out)


def _kv_table(items: Iterable[tuple[str, Any]], caption: str = "") -> str:
    t = _Table(("quantity", "value"), caption=caption, cls="kv")
    for k, v in items:
        t.add(k, v)
    return t.html()


def _png_bytes(fig: Any, dpi: int = 110) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi, bbox_inches="tight")
    return buf.getvalue()


def _img(png: bytes, alt: str, caption: str) -> str:
    data = base64.b64encode(png).decode("ascii")
    return (f'<figure><img src="data:image/png;base64,{data}" alt="{_e(alt)}">'
            f"<figcaption>{_e(caption)}</figcaption></figure>")


def _note(text: str, cls: str = "note") -> str:
    return f'<p class="{cls}">{_e(text)}</p>'


CSS = """
:root { --fg:#1d2330; --muted:#5b6475; --line:#d5dae3; --accent:#1f5fa8; --bg:#ffffff;
        --soft:#f3f5f9; --warn:#9a3b00; }
* { box-sizing: border-box; }
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif;
       color: var(--fg); background: var(--bg); margin: 0; line-height: 1.45; }
main { max-width: 1100px; margin: 0 auto; padding: 24px 28px 60px; }
h1 { font-size: 1.7em; margin: 0.2em 0 0.1em; color: var(--accent); }
h2 { font-size: 1.25em; margin: 1.8em 0 0.5em; padding-bottom: 4px;
     border-bottom: 2px solid var(--line); }
h3 { font-size: 1.05em; margin: 1.2em 0 0.4em; }
p.sub { color: var(--muted); margin: 0 0 1em; }
p.note { color: var(--muted); font-size: 0.92em; }
p.warn { color: var(--warn); font-weight: 600; }
nav { background: var(--soft); border: 1px solid var(--line); border-radius: 6px;
      padding: 8px 14px; font-size: 0.92em; }
nav a { color: var(--accent); text-decoration: none; margin-right: 14px; }
table { border-collapse: collapse; margin: 0.6em 0 1em; font-size: 0.9em; }
caption { text-align: left; font-weight: 600; padding: 4px 0; }
th, td { border: 1px solid var(--line); padding: 3px 8px; vertical-align: top; }
th { background: var(--soft); text-align: left; font-weight: 600; }
td.n { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
table.impacts td { white-space: nowrap; }
table.kv td:first-child { color: var(--muted); }
.cards { display: flex; flex-wrap: wrap; gap: 10px; margin: 0.8em 0; }
.card { border: 1px solid var(--line); border-radius: 6px; padding: 8px 12px; min-width: 170px;
        background: var(--soft); }
.card .v { font-size: 1.3em; font-weight: 650; }
.card .k { color: var(--muted); font-size: 0.85em; }
figure { margin: 1em 0 1.6em; }
figure img { max-width: 100%; height: auto; border: 1px solid var(--line); }
figcaption { color: var(--muted); font-size: 0.9em; }
pre { background: var(--soft); border: 1px solid var(--line); padding: 10px; overflow-x: auto;
      font-size: 0.85em; }
.scroll { overflow-x: auto; }
footer { color: var(--muted); font-size: 0.85em; margin-top: 3em; border-top: 1px solid
         var(--line); padding-top: 8px; }
"""


def _page(title: str, subtitle: str, sections: list[tuple[str, str, str]],
          folder: Path) -> str:
    """The whole page: ``sections`` is a list of (id, heading, inner html)."""
    from pounding import __version__

    nav = "".join(f'<a href="#{_e(sid)}">{_e(head)}</a>' for sid, head, _ in sections)
    body = "".join(f'<section id="{_e(sid)}"><h2>{_e(head)}</h2>{inner}</section>'
                   for sid, head, inner in sections)
    stamp = _dt.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z")
    return (
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
        f"<meta name=\"generator\" content=\"pounding {_e(__version__)}\">"
        f"<title>{_e(title)}</title><style>{CSS}</style></head><body><main>"
        f"<h1>{_e(title)}</h1><p class=\"sub\">{_e(subtitle)}</p>"
        f"<nav>{nav}</nav>{body}"
        f"<footer>Written by pounding {_e(__version__)} on {_e(stamp)} from "
        f"{_e(folder.resolve())}. Units: SI (m, kg, s, N, J) unless stated.</footer>"
        "</main></body></html>\n")


def _cards(items: Iterable[tuple[str, str]]) -> str:
    return '<div class="cards">' + "".join(
        f'<div class="card"><div class="v">{_e(v)}</div><div class="k">{_e(k)}</div></div>'
        for k, v in items) + "</div>"


# =============================================================================== run folder
@dataclass
class _Run:
    folder: Path
    summary: dict[str, Any]
    ds: Any  # xarray.Dataset, loaded into memory
    impacts: pd.DataFrame
    impacts_units: str
    toml_text: str | None
    toml: dict[str, Any]
    built: Any = None  # pounding.config.Built or None
    build_error: str | None = None


def _read_run(folder: Path) -> _Run:
    import xarray as xr

    try:
        summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as exc:
        raise ValueError(f"report: {folder / 'summary.json'}: unreadable ({exc})") from None
    if not isinstance(summary, dict):
        raise ValueError(f"report: {folder / 'summary.json'}: not a JSON object")
    try:
        with xr.open_dataset(folder / "timehistories.nc", engine="h5netcdf") as ds:
            ds = ds.load()
    except (OSError, ValueError) as exc:
        raise ValueError(f"report: {folder / 'timehistories.nc'}: unreadable ({exc})") from None

    impacts = pd.DataFrame()
    units = ""
    csv = folder / "impacts.csv"
    if csv.is_file():
        with csv.open(encoding="utf-8") as fh:
            first = fh.readline()
        skip = 1 if first.startswith("#") else 0
        units = first.lstrip("#").strip() if skip else ""
        try:
            impacts = pd.read_csv(csv, skiprows=skip)
        except pd.errors.EmptyDataError:
            impacts = pd.DataFrame()
    toml_text = None
    toml: dict[str, Any] = {}
    built = None
    build_error = None
    mt = folder / "model.toml"
    if mt.is_file():
        toml_text = mt.read_text(encoding="utf-8")
        try:
            toml = tomllib.loads(toml_text)
        except tomllib.TOMLDecodeError as exc:
            build_error = f"model.toml is not valid TOML ({exc})"
        if build_error is None:
            from pounding.config import load_config

            try:
                built = load_config(mt).build()
            except (ValueError, OSError) as exc:
                build_error = f"model.toml could not be rebuilt ({exc})"
    else:
        build_error = "no model.toml in the folder"
    return _Run(folder, summary, ds, impacts, units, toml_text, toml, built, build_error)


def _building_of(label: str) -> int:
    m = re.match(r"B(\d+)F(\d+)$", label)
    return int(m.group(1)) - 1 if m else 0


def _damping_text(d: Any) -> str:
    name = type(d).__name__
    fields = getattr(d, "__dataclass_fields__", {})
    values = {k: getattr(d, k) for k in fields}
    args = ", ".join(f"{k}={_num(v) if isinstance(v, float) else v}" for k, v in values.items())
    return f"{name}({args})"


def _range_text(values: Sequence[float], unit: str) -> str:
    v = np.asarray(values, dtype=float)
    if v.size == 0:
        return "–"
    if np.allclose(v, v[0]):
        return f"{_num(v[0])} {unit}" + (f" × {v.size}" if v.size > 1 else "")
    return f"{_num(v.min())} … {_num(v.max())} {unit}"


def _model_section(r: _Run) -> str:
    parts = []
    desc = r.toml.get("description") or ""
    name = r.toml.get("name") or r.summary.get("model", "")
    parts.append(_kv_table([("model name", str(name)), ("description", str(desc) or "–")]))
    if r.built is not None:
        model = r.built.model
        t = _Table(("building", "name", "storeys", "height [m]", "total mass [kg]",
                    "floor masses [kg]", "storey stiffnesses [N/m]", "T1 [s]",
                    "first periods [s]", "damping"),
                   caption="Buildings, left to right")
        for b, bl in enumerate(model.buildings):
            try:
                periods = ", ".join(_num(p) for p in bl.modes().periods[:3])
            except Exception:  # noqa: BLE001  (a display nicety only)
                periods = "–"
            t.add(f"B{b + 1}", bl.name or "–", bl.n, float(bl.total_height),
                  float(bl.total_mass), _range_text(bl.masses, "kg"),
                  _range_text(bl.stiffnesses, "N/m"), float(bl.fundamental_period), periods,
                  _damping_text(bl.damping))
        parts.append(t.html())
    else:
        builds = r.toml.get("building", [])
        if builds:
            t = _Table(("building", "as given in model.toml"),
                       caption="Buildings, left to right (model.toml, not rebuilt)")
            for b, entry in enumerate(builds):
                t.add(f"B{b + 1}", ", ".join(f"{k} = {v}" for k, v in entry.items()))
            parts.append(t.html())
        parts.append(_note(f"The model could not be rebuilt: {r.build_error}. Periods and "
                           "derived quantities are not shown.", "warn"))
    contact = r.toml.get("contact")
    if isinstance(contact, dict) and contact:
        items = [(_with_unit(k, CONTACT_UNITS.get(k)), v if not isinstance(v, list)
                  else ", ".join(_num(x) for x in v)) for k, v in contact.items()]
        parts.append(_kv_table(items, caption="Contact law ([contact] of model.toml)"))
    if r.built is not None and r.built.model.contacts:
        t = _Table(("contact", "elevation [m]", "gap [m]", "law"), caption="Contact elements")
        for c in r.built.model.contacts:
            t.add(c.label, c.elevation, c.gap, repr(c.law))
        parts.append(t.html())
    solver = r.toml.get("solver")
    if isinstance(solver, dict) and solver:
        su = {"dt": "s", "duration": "s", "rtol": "-", "h_max": "s"}
        parts.append(_kv_table([(_with_unit(k, su.get(k)), v) for k, v in solver.items()],
                               caption="Solver options ([solver] of model.toml)"))
    if r.toml_text is not None:
        parts.append("<details><summary>model.toml (as run)</summary>"
                     f"<pre>{_e(r.toml_text)}</pre></details>")
    return "".join(parts)


def _record_section(r: _Run) -> str:
    ds = r.ds
    s = r.summary
    t = np.asarray(ds["time"].values, dtype=float)
    ag = np.asarray(ds["ground_acceleration"].values, dtype=float)
    items: list[tuple[str, Any]] = [("record", str(s.get("record", ds.attrs.get("record", ""))))]
    if r.built is not None:
        gm = r.built.motion
        items += [("source", gm.source or "–"), ("units of the source", gm.units_read),
                  ("record step [s]", gm.dt), ("record duration [s]", gm.duration),
                  ("PGA [g]", gm.pga_g), ("PGA [m/s²]", gm.pga)]
    else:
        items += [("PGA [g]", s.get("record_pga_g"))]
    items += [("simulated duration [s]", float(t[-1]) if t.size else None),
              ("output step [s]", s.get("output_step_s")),
              ("largest |ground acceleration| at output samples [m/s²]",
               float(np.abs(ag).max()) if ag.size else None)]
    rec = r.toml.get("record", {})
    for key, unit in (("duration", "s"), ("scale", "-"), ("pga_g", "g")):
        if isinstance(rec, dict) and key in rec:
            items.append((f"record.{key} in model.toml [{unit}]", rec[key]))
    out = _kv_table(items)
    if t.size:
        from matplotlib.figure import Figure

        fig = Figure(figsize=(10, 2.4))
        ax = fig.subplots()
        ax.plot(t, ag, color="0.2", lw=0.6)
        ax.set_xlabel("time [s]")
        ax.set_ylabel("ground acceleration [m/s²]")
        ax.grid(True, alpha=0.3)
        ax.set_title(f"{s.get('record', '')}: ground acceleration over the simulated time",
                     fontsize=9, loc="left")
        fig.tight_layout()
        out += _img(_png_bytes(fig), "ground acceleration", "Ground acceleration [m/s²] "
                    "against time [s], at the output samples.")
    return out


def _response_table(r: _Run) -> str:
    ds = r.ds
    labels = [str(x) for x in ds["floor"].values]
    disp = peak_abs(ds["displacement"].values)
    drift = peak_abs(ds["drift"].values)
    acc = (peak_abs(ds["absolute_acceleration"].values)
           if "absolute_acceleration" in ds else np.full(len(labels), np.nan))
    elev = (np.asarray(ds["floor_elevation"].values, dtype=float)
            if "floor_elevation" in ds.coords else np.full(len(labels), np.nan))
    inelastic = "ductility" in ds
    cols = ("building", "storeys", "peak roof displacement [m]", "peak storey drift [m]",
            "at storey", "peak drift ratio [%]", "peak absolute floor acceleration [m/s²]")
    if inelastic:
        cols += ("peak storey ductility [-]", "largest residual drift [m]")
    t = _Table(cols, caption="Peak response of each building (absolute values over the run)"
               + ("; ductility = peak drift / yield drift (NaN: linear storeys), residual "
                  "drift after elastic unloading" if inelastic else ""))
    groups: dict[int, list[int]] = {}
    for i, lb in enumerate(labels):
        groups.setdefault(_building_of(lb), []).append(i)
    for b, idx in sorted(groups.items()):
        d = drift[idx]
        j = int(np.argmax(d))
        below = elev[idx[j] - 1] if j > 0 else 0.0
        h = elev[idx[j]] - below
        ratio = 100.0 * d[j] / h if h > 0 else float("nan")
        name = ""
        if r.built is not None and b < len(r.built.model.buildings):
            name = r.built.model.buildings[b].name
        row = [f"B{b + 1}" + (f" ({name})" if name else ""), len(idx), float(disp[idx[-1]]),
               float(d[j]), j + 1, ratio, float(acc[idx].max())]
        if inelastic:
            mu = np.asarray(ds["ductility"].values, dtype=float)[idx]
            res = np.asarray(ds["residual_drift"].values, dtype=float)[idx]
            row += [float(np.nanmax(mu)) if np.isfinite(mu).any() else float("nan"),
                    float(res[int(np.argmax(np.abs(res)))])]
        t.add(*row)
    return t.html()


def _headline_section(r: _Run) -> str:
    s = r.summary
    solver = s.get("solver", {}) or {}
    e_err = s.get("energy_balance_error")
    pdisp = s.get("peak_displacement_m", {}) or {}
    cards = [
        ("impacts", _num(s.get("n_impacts"))),
        ("peak contact force [N]", _num(s.get("peak_contact_force_N"))),
        ("largest floor displacement [m]", _num(max(pdisp.values())) if pdisp else "–"),
        ("dissipated in contacts [J]", _num(s.get("contact_dissipated_J"))),
        ("energy-balance error [of peak input]", f"{e_err:.2e}" if isinstance(e_err, float)
         else "–"),
    ]
    out = _cards(cards)
    pcf = s.get("peak_contact_force_by_contact_N", {}) or {}
    if pcf:
        t = _Table(("contact", "impacts", "peak contact force [N]", "dissipated [J]"),
                   caption="Per contact")
        for label, f in pcf.items():
            rows = (r.impacts[r.impacts["contact"] == label]
                    if len(r.impacts) and "contact" in r.impacts else pd.DataFrame())
            n = len(rows)
            diss = float(np.nansum(rows["energy_dissipated"])) if n else 0.0
            t.add(label, n, f, diss)
        out += t.html()
    out += _response_table(r)
    items = [("solver", solver.get("name")), ("relative tolerance rtol [-]", solver.get("rtol")),
             ("adaptive steps through contacts", solver.get("rk_steps")),
             ("rejected steps", solver.get("rejected")),
             ("contact events (closings and openings)", solver.get("events")),
             ("impact table overflowed", solver.get("impact_table_overflow")),
             ("integration wall time [s]", solver.get("wall_time_s"))]
    out += _kv_table([(k, v) for k, v in items if v is not None],
                     caption="Solver statistics")
    if solver.get("impact_table_overflow"):
        out += _note("The impact table overflowed: some impacts are not listed.", "warn")
    return out


def _result_from(r: _Run) -> Any:
    """A :class:`pounding.result.Result` rebuilt from the folder (for missing figures)."""
    from pounding.result import IMPACT_COLUMNS, Result, SolverStats

    model, motion = r.built.model, r.built.motion
    ds = r.ds
    labels = [c.label for c in model.contacts]
    n_imp = len(r.impacts)
    arr = np.zeros((n_imp, len(IMPACT_COLUMNS)))
    if n_imp:
        arr[:, 0] = [labels.index(str(lb)) for lb in r.impacts["contact"]]
        for j, col in enumerate(IMPACT_COLUMNS[1:], start=1):
            arr[:, j] = r.impacts[col].to_numpy(dtype=float)
    sv = r.summary.get("solver", {}) or {}
    stats = SolverStats(solver=str(sv.get("name", "?")), rtol=float(sv.get("rtol") or 0.0),
                        rk_steps=int(sv.get("rk_steps") or 0),
                        rejected=int(sv.get("rejected") or 0),
                        events=int(sv.get("events") or 0),
                        impact_overflow=bool(sv.get("impact_table_overflow")),
                        wall_time=float(sv.get("wall_time_s") or 0.0))
    t = np.asarray(ds["time"].values, dtype=float)
    dt = float(r.summary.get("output_step_s") or (t[1] - t[0] if t.size > 1 else 1.0))

    def a(name: str) -> np.ndarray:
        return np.asarray(ds[name].values, dtype=float)

    energy = a("energy")
    if energy.shape[1] < len(ENERGY_NAMES):  # runs saved before the hysteretic column
        energy = np.pad(energy, ((0, 0), (0, len(ENERGY_NAMES) - energy.shape[1])))
    yielding = None
    if model.is_inelastic:
        offsets = model.system.offsets
        cols = [offsets[p] + j for p, j in model.yielding_storeys]
        yielding = a("storey_shear")[:, cols]
    return Result(model=model, motion=motion, dt=dt, ground=a("ground_acceleration"),
                  displacement=a("displacement"), velocity=a("velocity"),
                  abs_acceleration=a("absolute_acceleration"), penetration=a("penetration"),
                  contact_force=a("contact_force"), energy=energy, impact_array=arr,
                  stats=stats, yielding_shear=yielding)


def _figures_section(r: _Run) -> str:
    from pounding.plot.registry import RUN_FIGURES, figures_for

    parts = []
    result = None
    why_not = ""
    # the figures a run of this model has (no storey hysteresis without yielding storeys);
    # model unknown: those in the folder and those every run has
    wanted = (figures_for(r.built.model) if r.built is not None else
              {k: f for k, f in RUN_FIGURES.items()
               if not f.yielding_only or (r.folder / f.file).is_file()})
    for fig in wanted.values():
        name, caption = fig.file, fig.caption
        path = r.folder / name
        if path.is_file():
            parts.append(_img(path.read_bytes(), caption, f"{caption} ({name} of the run)."))
            continue
        if result is None and not why_not:
            if r.built is None:
                why_not = r.build_error or "the model is unknown"
            else:
                try:
                    result = _result_from(r)
                except (ValueError, KeyError) as exc:
                    why_not = f"the results could not be reloaded ({exc})"
        if result is not None:
            parts.append(_img(_png_bytes(fig.make(result)), caption,
                              f"{caption} (regenerated from timehistories.nc: {name} is not "
                              "in the folder)."))
        else:
            parts.append(_note(f"{caption}: {name} is not in the folder and could not be "
                               f"regenerated: {why_not}.", "warn"))
    return "".join(parts)


IMPACT_HEADERS: dict[str, str] = {
    "contact": "contact", "elevation": "elevation [m]", "start": "start [s]", "end": "end [s]",
    "v0": "impact velocity v0 [m/s]", "peak_force": "peak force [N]",
    "max_penetration": "max penetration [m]", "restitution": "restitution [-]",
    "energy_dissipated": "energy dissipated [J]",
}


def _impacts_section(r: _Run) -> str:
    imp = r.impacts
    if not len(imp):
        why = ("no impacts.csv in the folder" if not (r.folder / "impacts.csv").is_file()
               else "no impact: the gap never closed")
        return _note(f"No impacts listed ({why}).")
    cols = list(imp.columns)
    headers = ["#"] + [IMPACT_HEADERS.get(c, c) for c in cols]
    t = _Table(headers, cls="impacts")
    for i, (_, row) in enumerate(imp.head(MAX_IMPACT_ROWS).iterrows()):
        t.add(i + 1, *[row[c] if c == "contact" else row[c] for c in cols])
    out = []
    if len(imp) > MAX_IMPACT_ROWS:
        out.append(_note(f"First {MAX_IMPACT_ROWS} of {len(imp)} impacts; all are in "
                         "impacts.csv."))
    else:
        out.append(_note(f"{len(imp)} impact(s), in time order per the solver's impact table "
                         "(impacts.csv). Restitution is −δ̇ at separation / v0; an impact "
                         "still open at the end has no end, restitution or energy (–)."))
    out.append(f'<div class="scroll">{t.html()}</div>')
    if r.impacts_units:
        out.append(_note(f"Units as stated in impacts.csv: {r.impacts_units}"))
    return "".join(out)


def _energy_section(r: _Run) -> str:
    ds = r.ds
    e = np.asarray(ds["energy"].values, dtype=float)
    names = [str(x) for x in ds["energy_term"].values]
    col = {n: e[:, i] for i, n in enumerate(names)}
    t = _Table(("term", "final value [J]", "largest |value| during the run [J]", "meaning"),
               caption="Energy balance: cumulative energies at the end of the run")
    for n in names:
        t.add(n, float(col[n][-1]), float(np.abs(col[n]).max()), ENERGY_DESCRIPTIONS.get(n, ""))
    out = [t.html()]
    needed = ("input", "kinetic", "strain", "damping", "contact_work")
    if all(k in col for k in needed):
        closure = col["input"] - (col["kinetic"] + col["strain"] + col["damping"]
                                  + col["contact_work"])
        scale = max(float(np.abs(col["input"]).max()), 1e-300)
        diss = col["contact_work"] - col.get("contact_stored", 0.0)
        items = [
            ("dissipated in contacts = contact_work − contact_stored, final [J]",
             float(diss[-1])),
            ("kinetic + strain + damping + contact_work, final [J]",
             float(col["input"][-1] - closure[-1])),
            ("closure input − (kinetic + strain + damping + contact_work), final [J]",
             float(closure[-1])),
            ("largest |closure| during the run [J]", float(np.abs(closure).max())),
            ("largest |closure| / largest |input| [-]", float(np.abs(closure).max() / scale)),
            ("energy_balance_error in summary.json [-]", r.summary.get("energy_balance_error")),
        ]
        if col["input"][-1] > 0:
            share = [("structural damping", col["damping"][-1]), ("contacts", diss[-1]),
                     ("kinetic + strain (still in motion)",
                      col["kinetic"][-1] + col["strain"][-1])]
            items += [(f"share of the final input: {k} [%]", 100.0 * float(v) / col["input"][-1])
                      for k, v in share]
        out.append(_kv_table(items, caption="Closure"))
    return "".join(out)


def _gap_check_section(r: _Run) -> str:
    ds = r.ds
    if "contact" not in ds.dims or ds.sizes["contact"] == 0:
        return _note("No contacts: a single building, nothing to check.")
    floors = [str(x) for x in ds["floor"].values]
    u = np.asarray(ds["displacement"].values, dtype=float)
    pen = np.asarray(ds["penetration"].values, dtype=float)
    contacts = [str(x) for x in ds["contact"].values]
    elev = (np.asarray(ds["contact_elevation"].values, dtype=float)
            if "contact_elevation" in ds.coords else np.full(len(contacts), np.nan))
    gaps_model = {}
    if r.built is not None:
        gaps_model = {c.label: c.gap for c in r.built.model.contacts}
    t = _Table(("contact", "elevation [m]", "gap [m]", "touched", "impacts",
                "peak penetration [m]", "max(u_left − u_right) in this run [m]",
                "gap − max(u_left − u_right) [m]", "critical gap (no contact) [m]"),
               caption="Gap check, one row per contact element")
    for i, label in enumerate(contacts):
        left, _, right = label.partition("-")
        if left in floors and right in floors:
            rel = u[:, floors.index(left)] - u[:, floors.index(right)]
            gap_from_nc = float(np.median(rel - pen[:, i]))
        else:  # labels not parseable: penetration + gap with the model's gap
            rel = None
            gap_from_nc = float("nan")
        gap = gaps_model.get(label, gap_from_nc)
        if rel is None:
            rel = pen[:, i] + gap
        rows = (r.impacts[r.impacts["contact"] == label]
                if len(r.impacts) and "contact" in r.impacts else pd.DataFrame())
        n = len(rows)
        peak_pen = float(pen[:, i].max())
        if n:
            peak_pen = max(peak_pen, float(np.nanmax(rows["max_penetration"])))
        touched = n > 0 or peak_pen > 0
        max_rel = float(rel.max())
        t.add(label, float(elev[i]), gap, "yes" if touched else "no", n,
              peak_pen if touched else "– (never closed)", max_rel, gap - max_rel,
              max_rel if not touched else "– (see note)")
    return "".join([
        t.html(),
        _note("Displacements are positive to the right, so the gap between a floor of the "
              "left building and the floor of its right neighbour closes when "
              "u_left − u_right reaches the gap; the penetration is "
              "δ = u_left − u_right − gap (timehistories.nc). max(u_left − u_right) is "
              "taken over the output samples; "
              "the peak penetration also uses the impact table (resolved between samples)."),
        _note("Critical gap: the smallest gap that avoids contact under this record is "
              "max(u_left − u_right) of a run in which the buildings never touch. It is "
              "shown only for contacts that never closed (then this run is such a run). Where "
              "the buildings touched, max(u_left − u_right) = gap + peak penetration is "
              "bounded by the impacts and is NOT the critical gap: the buildings rebound "
              "instead of moving freely; use the gap study (pounding gap) for that."),
    ])


def _render_run(folder: Path) -> str:
    r = _read_run(folder)
    name = str(r.summary.get("model") or r.toml.get("name") or folder.name)
    record = str(r.summary.get("record") or "")
    pga = r.summary.get("record_pga_g")
    sub = (f"Run report — record {record}"
           + (f", PGA {pga:.3f} g" if isinstance(pga, (int, float)) else "")
           + f"; folder {folder.resolve().name}")
    sections = [
        ("summary", "Headline numbers", _headline_section(r)),
        ("model", "Model", _model_section(r)),
        ("record", "Record", _record_section(r)),
        ("figures", "Figures", _figures_section(r)),
        ("impacts", "Impact table", _impacts_section(r)),
        ("energy", "Energy balance", _energy_section(r)),
        ("gap-check", "Gap check", _gap_check_section(r)),
    ]
    return _page(f"{name}: pounding run report", sub, sections, folder)


# =============================================================================== sweep folder
MEASURE_PREFERENCE: tuple[str, ...] = (
    "peak_contact_force_N", "peak_force_N", "peak_contact_force", "n_impacts",
    "contact_dissipated_J", "peak_displacement_m", "peak_drift_m",
)
"""The main measure of a sweep is the first of these present (else the first measure)."""

_MEASURE_HINTS = ("peak", "n_impacts", "impacts", "dissipated", "energy", "error", "drift",
                  "displacement", "force", "penetration", "wall_time", "critical", "touched",
                  "status", "ok", "error_message", "max_", "min_", "mean_", "rk_steps",
                  "rejected", "events", "overflow")


@dataclass
class _Sweep:
    df: pd.DataFrame
    parameters: list[str]
    measures: list[str]
    main: str | None
    units: dict[str, str]
    meta: dict[str, Any]
    how: str


def _parquet_meta(path: Path) -> dict[str, Any]:
    """JSON metadata stored in the Parquet schema by the writer (pandas' own excluded)."""
    try:
        import pyarrow.parquet as pq

        raw = pq.read_schema(path).metadata or {}
    except Exception:  # noqa: BLE001  (metadata is optional)
        return {}
    out: dict[str, Any] = {}
    for k, v in raw.items():
        key = k.decode("utf-8", "replace")
        if key in ("pandas", "ARROW:schema"):
            continue
        text = v.decode("utf-8", "replace")
        try:
            out[key] = json.loads(text)
        except json.JSONDecodeError:
            out[key] = text
    return out


def _side_meta(folder: Path) -> dict[str, Any]:
    """A JSON description of the sweep beside the results, if the sweep wrote one."""
    for name in ("sweep.json", "meta.json", "metadata.json", "grid.json", "study.json"):
        p = folder / name
        if p.is_file():
            try:
                data = json.loads(p.read_text(encoding="utf-8"))
            except (OSError, json.JSONDecodeError):
                continue
            if isinstance(data, dict):
                return {"_file": name, **data}
    return {}


def _find_list(meta: dict[str, Any], keys: Sequence[str]) -> list[str] | None:
    """The first list (or dict keys) under one of ``keys``, searched one level deep too."""
    for where in [meta, *[v for v in meta.values() if isinstance(v, dict)]]:
        for k in keys:
            v = where.get(k)
            if isinstance(v, dict) and v:
                return [str(x) for x in v]
            if isinstance(v, list) and v and all(isinstance(x, str) for x in v):
                return [str(x) for x in v]
    return None


def _find_units(meta: dict[str, Any]) -> dict[str, str]:
    for where in [meta, *[v for v in meta.values() if isinstance(v, dict)]]:
        v = where.get("units")
        if isinstance(v, dict):
            return {str(k): str(u) for k, u in v.items()}
    return {}


def unit_of(column: str, units: dict[str, str] | None = None) -> str | None:
    """The unit of a results column: stated in the metadata, else from its name
    (``peak_contact_force_N`` → N, ``gap`` → m); None if not known."""
    if units and column in units:
        return units[column]
    base = column.split(".")[-1]
    base = re.sub(r"_B\d+F\d+$", "", base)  # per-floor columns: <measure>_B1F2
    if base in _NAME_UNITS:
        return _NAME_UNITS[base]
    m = re.search(r"\[([^\]]+)\]\s*$", column)
    if m:
        return None  # the name already carries its unit
    for suffix, unit in _SUFFIX_UNITS:
        if base.endswith(suffix):
            return unit
    return None


def _label(column: str, units: dict[str, str]) -> str:
    return _with_unit(column, unit_of(column, units))


def _classify(df: pd.DataFrame, meta: dict[str, Any]) -> tuple[list[str], list[str], str]:
    cols = [str(c) for c in df.columns]
    params = _find_list(meta, ("parameters", "params", "grid", "swept", "axes"))
    measures = _find_list(meta, ("measures", "outputs", "metrics"))
    if params:
        params = [p for p in params if p in cols]
    if measures:
        measures = [m for m in measures if m in cols]
    book = {"case_index", "case_id", "status", "error", "case", "index", "id"}
    if params:
        rest = [c for c in cols if c not in params and c not in book]
        return params, measures or [c for c in rest if _is_numeric(df[c])], \
            "parameters as stated in the sweep's metadata"
    if measures:
        return [c for c in cols if c not in measures and c not in book], measures, \
            "measures as stated in the sweep's metadata; the other columns taken as parameters"
    # heuristics: prefixed parameter columns, else columns not named like a measure
    pref = [c for c in cols if c.startswith(("param.", "param_", "p.", "parameter."))]
    if pref:
        return pref, [c for c in cols if c not in pref and _is_numeric(df[c])], \
            "parameters: the columns prefixed param"
    ignore = book | {"run", "folder", "path", "out_dir", "seed"}
    params, measures = [], []
    for c in cols:
        low = c.lower()
        if low in ignore:
            continue
        if any(h in low for h in _MEASURE_HINTS) or re.search(r"_(N|J)$", c):
            if _is_numeric(df[c]):
                measures.append(c)
            continue
        if df[c].nunique(dropna=False) <= max(1, min(len(df), 50)):
            params.append(c)
    return params, measures, ("parameters and measures told apart by their names (the "
                              "results file does not list them)")


def _is_numeric(s: pd.Series) -> bool:
    """Numbers or booleans (shown right-aligned, summarised)."""
    return bool(pd.api.types.is_numeric_dtype(s) or pd.api.types.is_bool_dtype(s))


def _read_sweep(folder: Path) -> _Sweep:
    path = folder / SWEEP_FILE
    try:
        df = pd.read_parquet(path)
    except Exception as exc:  # noqa: BLE001  (pyarrow raises many kinds)
        raise ValueError(f"report: {path}: unreadable Parquet file ({exc})") from None
    df.columns = [str(c) for c in df.columns]
    meta = {**_side_meta(folder), **_parquet_meta(path)}
    params, measures, how = _classify(df, meta)
    units = _find_units(meta)
    numeric = [m for m in measures if _is_numeric(df[m]) and not pd.api.types.is_bool_dtype(df[m])]
    main = next((m for m in MEASURE_PREFERENCE if m in numeric), numeric[0] if numeric else None)
    return _Sweep(df, params, measures, main, units, meta, how)


def _sweep_plot(sw: _Sweep, param: str) -> bytes:
    from matplotlib.figure import Figure

    df = sw.df
    y = df[sw.main].astype(float)
    x_raw = df[param]
    numeric_x = pd.api.types.is_numeric_dtype(x_raw) and not pd.api.types.is_bool_dtype(x_raw)
    fig = Figure(figsize=(7.5, 3.6))
    ax = fig.subplots()
    if numeric_x:
        x = x_raw.astype(float)
        ticks = None
    else:
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
    ax.set_xlabel(_label(param, sw.units))
    ax.set_ylabel(_label(sw.main, sw.units))  # type: ignore[arg-type]
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    ax.set_title(f"{sw.main} against {param}", fontsize=9, loc="left")
    fig.tight_layout()
    return _png_bytes(fig)


def _render_sweep(folder: Path) -> str:
    sw = _read_sweep(folder)
    df = sw.df
    n = len(df)
    names = [sw.meta.get("name")] + [v.get("name") for v in sw.meta.values()
                                      if isinstance(v, dict)]
    title = str(next((x for x in names if x), folder.resolve().name))
    failed = (df[df["status"].astype(str) != "ok"] if "status" in df.columns
              else df.iloc[:0])
    sections = []

    overview = [("cases", n), ("cases failed (status not ok)", len(failed)),
                ("swept parameters", ", ".join(sw.parameters) or "–"),
                ("measures", ", ".join(sw.measures) or "–"),
                ("main measure (plotted)", _label(sw.main, sw.units) if sw.main else "–"),
                ("how parameters were recognised", sw.how)]
    over = _kv_table(overview)
    if len(failed):
        ft = _Table(("#", "case", "error"), caption="Failed cases (their measures are empty)")
        for i, (_, row) in enumerate(failed.head(MAX_SWEEP_ROWS).iterrows()):
            case = ", ".join(f"{p} = {_num(row[p])}" for p in sw.parameters)
            ft.add(int(row["case_index"]) if "case_index" in df.columns else i + 1, case,
                   str(row.get("error") or "–"))
        over += _note(f"{len(failed)} case(s) failed.", "warn") + ft.html()
    sections.append(("overview", "Overview", over))

    grid = _Table(("parameter", "values", "distinct values", "min", "max"),
                  caption="Parameter grid (values found in results.parquet)")
    for p in sw.parameters:
        vals = pd.unique(df[p].dropna())
        try:
            vals = np.sort(vals)
        except TypeError:
            pass
        shown = ", ".join(_num(v) for v in vals[:20]) + (" …" if len(vals) > 20 else "")
        num = pd.api.types.is_numeric_dtype(df[p]) and not pd.api.types.is_bool_dtype(df[p])
        grid.add(_label(p, sw.units), shown, len(vals),
                 float(df[p].min()) if num else "–", float(df[p].max()) if num else "–")
    grid_html = grid.html() if sw.parameters else _note("No parameter column recognised.")
    product = int(np.prod([df[p].nunique(dropna=False) for p in sw.parameters])) \
        if sw.parameters else 0
    if sw.parameters:
        grid_html += _note(f"{n} case(s); the full grid of these values has {product} "
                           + ("(a full grid)." if product == n else
                              "(not a full grid: some combinations are absent or repeated)."))
    sections.append(("grid", "Parameter grid", grid_html))

    stats_t = _Table(("measure", "count", "mean", "std", "min", "median", "max"),
                     caption="Summary statistics over all cases")
    for m in sw.measures:
        if not _is_numeric(df[m]):
            continue
        v = df[m].astype(float)
        stats_t.add(_label(m, sw.units), int(v.notna().sum()), v.mean(), v.std(), v.min(),
                    v.median(), v.max())
    cols = [c for c in df.columns]
    head = _Table(["#"] + [_label(c, sw.units) for c in cols],
                  caption=f"First {min(n, MAX_SWEEP_ROWS)} of {n} case(s)")
    for i, (_, row) in enumerate(df.head(MAX_SWEEP_ROWS).iterrows()):
        head.add(i + 1, *[row[c] if not isinstance(row[c], str) else row[c] for c in cols])
    unknown = [c for c in cols if unit_of(c, sw.units) is None and c not in _TEXT_COLUMNS]
    body = stats_t.html() + f'<div class="scroll">{head.html()}</div>'
    if unknown:
        body += _note("Columns shown without a unit: results.parquet does not state one ("
                      + ", ".join(unknown) + ").")
    sections.append(("results", "Results", body))

    plots = []
    if sw.main is None:
        plots.append(_note("No numeric measure to plot."))
    else:
        for p in sw.parameters[:MAX_SWEEP_PLOTS]:
            if df[p].nunique(dropna=True) < 2:
                plots.append(_note(f"{p}: one value only ({_num(df[p].iloc[0])}), not "
                                   "plotted."))
                continue
            plots.append(_img(_sweep_plot(sw, p), f"{sw.main} against {p}",
                              f"{_label(sw.main, sw.units)} against {_label(p, sw.units)}: "
                              "grey dots each case, line the mean over the other parameters."))
        if len(sw.parameters) > MAX_SWEEP_PLOTS:
            plots.append(_note(f"{len(sw.parameters) - MAX_SWEEP_PLOTS} more parameter(s) not "
                               "plotted."))
        if not sw.parameters:
            plots.append(_note("No parameter to plot against."))
    sections.append(("plots", "Main measure against each parameter", "".join(plots)))
    if sw.meta:
        sections.append(("metadata", "Sweep metadata",
                         f"<pre>{_e(json.dumps(sw.meta, indent=2, default=str))}</pre>"))
    return _page(f"{title}: pounding sweep report",
                 f"Sweep report — {n} case(s), {len(sw.parameters)} swept parameter(s); "
                 f"folder {folder.resolve().name}", sections, folder)

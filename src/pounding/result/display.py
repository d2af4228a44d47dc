"""A run as Jupyter shows it: a compact HTML summary with its key figure
(:meth:`pounding.result.Result._repr_html_`).

The table holds the headline numbers of :func:`pounding.result.summary.summarize` (the
same numbers as ``summary.json``), each with its unit, in readable units (mm, kN, kJ, %);
the figure is the top floor's displacement of every building [mm] and the contact forces
[kN] against time [s], as an inline PNG (``data:`` URI). Nothing is written to disk.
matplotlib is imported only when the figure is drawn, with its object-oriented API
(``matplotlib.figure.Figure``: no pyplot, no global figure state).
"""

from __future__ import annotations

import base64
import html
import io
import math
import re
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from pounding.result.summary import summarize
from pounding.result.variables import history_variables

if TYPE_CHECKING:
    from pounding.result.response import Response

__all__ = ["MAX_CURVE_POINTS", "figure_png", "html_table", "peaks_kept", "png_uri",
           "result_html", "significant"]

MAX_CURVE_POINTS = 2000
"""At most this many points a curve of the figure (every peak kept: :func:`peaks_kept`)."""


def significant(x: Any, digits: int = 4) -> str:
    """``x`` to ``digits`` significant figures (``–`` for None or NaN)."""
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "–"
    if isinstance(x, bool | str):
        return str(x)
    return f"{float(x):.{digits}g}"


def html_table(rows: Iterable[Sequence[Any]], headers: Sequence[str] = (),
               caption: str = "") -> str:
    """A small HTML table; every cell escaped, numbers right-aligned."""
    out = ['<table style="border-collapse:collapse;margin:4px 0">']
    if caption:
        out.append(f'<caption style="text-align:left;font-weight:600">{html.escape(caption)}'
                   "</caption>")
    cell = 'style="border:1px solid #d5dae3;padding:2px 6px;{}"'
    if headers:
        out.append("<tr>" + "".join(f"<th {cell.format('text-align:left')}>{html.escape(h)}</th>"
                                    for h in headers) + "</tr>")
    for row in rows:
        out.append("<tr>" + "".join(
            f"<td {cell.format('text-align:right' if _is_number(v) else 'text-align:left')}>"
            f"{html.escape(v if isinstance(v, str) else significant(v))}</td>" for v in row)
            + "</tr>")
    out.append("</table>")
    return "".join(out)


def _is_number(v: Any) -> bool:
    return not isinstance(v, str) or bool(re.fullmatch(r"[-+0-9.eE]+", v))


def peaks_kept(values: NDArray[np.float64], n: int = MAX_CURVE_POINTS) -> NDArray[np.int64]:
    """Indices of at most about ``n`` samples keeping the smallest and largest of every
    bucket of ``len(values) / (n / 2)`` samples (so every peak is drawn), in order."""
    m = values.shape[0]
    if m <= n:
        return np.arange(m)
    buckets = np.array_split(np.arange(m), n // 2)
    keep: set[int] = set()
    for b in buckets:
        seg = values[b]
        keep.update((int(b[np.nanargmin(seg)]), int(b[np.nanargmax(seg)])))
    return np.array(sorted(keep), dtype=np.int64)


def figure_png(draw: Any, width: float = 6.4, height: float = 3.6, dpi: int = 80) -> str:
    """``draw(figure)`` on a new matplotlib figure (Agg, no pyplot), returned as a
    ``data:image/png;base64`` URI."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), dpi=dpi, layout="constrained")
    FigureCanvasAgg(fig)
    draw(fig)
    return png_uri(fig, dpi)


def png_uri(fig: Any, dpi: int = 80) -> str:
    """A matplotlib figure as a ``data:image/png;base64`` URI (in memory: no file)."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi)
    return "data:image/png;base64," + base64.b64encode(buf.getvalue()).decode("ascii")


def _top_floors(result: Response) -> list[tuple[str, int, float]]:
    """(building, column, elevation [m]) of every building's highest translation DOF."""
    hv = history_variables(result)
    owner = [str(b) for b in hv.coords["building"].values]
    unit = ([str(u) for u in hv.coords["dof_unit"].values] if "dof_unit" in hv.coords
            else ["m"] * len(owner))
    elev = np.asarray(hv.coords["floor_elevation"].values, dtype=float)
    tops: dict[str, tuple[int, float]] = {}
    for j, (b, u) in enumerate(zip(owner, unit, strict=True)):
        if u == "m" and math.isfinite(elev[j]) and (b not in tops or elev[j] > tops[b][1]):
            tops[b] = (j, float(elev[j]))
    return [(b, j, z) for b, (j, z) in tops.items()]


def _building_peaks(summary: dict[str, Any]) -> list[tuple[str, float | None, float | None]]:
    """(building, largest floor displacement [m], largest drift ratio [-]) from the
    summary's per-floor peaks (translations only: keys ending in θ or a footing's are
    left out)."""
    out: dict[str, list[float | None]] = {}
    for key, column in (("peak_displacement_m", 0), ("peak_drift_ratio", 1)):
        for label, value in (summary.get(key) or {}).items():
            m = re.match(r"(B\d+)", str(label))
            if not m or "θ" in label or "Fdn" in label or value is None:
                continue
            row = out.setdefault(m.group(1), [None, None])
            row[column] = max(row[column] or 0.0, float(value))
    return [(b, v[0], v[1]) for b, v in out.items()]


def result_html(result: Response) -> str:
    """The HTML summary of a run: headline numbers with units, per building and per
    contact, and the key figure (module docstring)."""
    s = summarize(result)
    pga = s.get("record_pga_g")
    force = s.get("peak_contact_force_N")
    head = [
        ("model", str(s.get("model", ""))),
        ("record", f"{s.get('record', '')}" + (f", PGA {significant(pga)} g" if pga else "")),
        ("simulated duration [s]", s.get("duration_s")),
        ("impacts", s.get("n_impacts")),
        ("peak contact force [kN]", None if force is None else force / 1e3),
        ("at t [s]", s.get("peak_contact_force_time_s")),
        ("energy dissipated in the contacts [kJ]",
         None if s.get("contact_dissipated_J") is None else s["contact_dissipated_J"] / 1e3),
        ("energy-balance error [-]", s.get("energy_balance_error")),
    ]
    buildings = [(b, None if d is None else d * 1e3, None if r is None else r * 100)
                 for b, d, r in _building_peaks(s)]
    impacts = s.get("impacts_by_contact") or {}
    peaks = s.get("peak_contact_force_by_contact_N") or {}
    contacts = [(c, impacts.get(c), None if peaks.get(c) is None else peaks[c] / 1e3)
                for c in impacts]
    parts = ['<div class="pounding-result"><strong>pounding Result</strong>',
             html_table(head, ("quantity", "value")),
             html_table(buildings, ("building", "peak floor displacement [mm]",
                                    "peak drift ratio [%]"))]
    if contacts:
        shown = contacts[:12]
        parts.append(html_table(shown, ("contact", "impacts", "peak force [kN]"),
                                caption="" if len(shown) == len(contacts)
                                else f"first 12 of {len(contacts)} contacts"))
    parts.append(f'<img alt="top-floor displacements [mm] and contact forces [kN] against '
                 f'time [s]" src="{figure_png(lambda fig: _draw(fig, result))}">')
    parts.append("</div>")
    return "".join(parts)


def _draw(fig: Any, result: Response) -> None:
    """Top floors' displacements [mm] above, contact forces [kN] below, against time [s]."""
    t = np.asarray(result.time, dtype=float)
    forces = np.asarray(result.contact_force, dtype=float).reshape(t.size, -1)
    ax_u, ax_f = fig.subplots(2, 1, sharex=True, height_ratios=[3, 2])
    for b, j, z in _top_floors(result):
        u = result.displacement[:, j] * 1e3
        k = peaks_kept(u)
        ax_u.plot(t[k], u[k], lw=0.8, label=f"{b} at {z:g} m")
    ax_u.set_ylabel("top floor [mm]")
    ax_u.legend(fontsize=7, loc="upper right")
    labels = [c.label for c in result.model.contacts]
    for c in range(forces.shape[1]):
        f = np.nan_to_num(forces[:, c]) / 1e3
        k = peaks_kept(f)
        ax_f.plot(t[k], f[k], lw=0.8, label=labels[c] if c < len(labels) else None)
    ax_f.set_ylabel("contact force [kN]")
    ax_f.set_xlabel("time [s]")

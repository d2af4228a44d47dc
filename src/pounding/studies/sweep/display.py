"""A sweep as Jupyter shows it (:meth:`pounding.studies.sweep.SweepOutcome._repr_html_`):
the counts and times of the sweep, the peak contact force over its successful cases, and
its figure (``pounding plot``'s default: the peak contact force against the first swept
parameter, :func:`pounding.plot.sweep.plot_sweep`) as an inline PNG. ``results.parquet``
is read; nothing is written. pandas and matplotlib are imported only when it is shown."""

from __future__ import annotations

import html
from typing import Any

from pounding.result.display import html_table, png_uri

__all__ = ["sweep_html"]


def sweep_html(outcome: Any) -> str:
    """The HTML summary of a :class:`~pounding.studies.sweep.SweepOutcome`."""
    import numpy as np

    from pounding.studies.sweep.table import load_results

    rows: list[tuple[str, Any]] = [
        ("folder", str(outcome.out_dir)),
        ("cases", outcome.n_cases), ("run this time", outcome.n_run),
        ("failed cases", outcome.n_errors), ("wall time [s]", outcome.wall_time),
        ("cases run a second [1/s]", outcome.rate), ("workers", outcome.n_workers)]
    figure = ""
    try:
        df = load_results(outcome.results)
    except (OSError, ValueError) as exc:  # the table moved or unreadable: the counts only
        rows.append(("results.parquet", f"not read: {exc}"))
        df = None
    if df is not None:
        ok = df[df["status"] == "ok"]
        if "peak_contact_force_N" in ok and len(ok):
            f = ok["peak_contact_force_N"].to_numpy(dtype=float) / 1e3
            rows += [("peak contact force, least over the cases [kN]", float(np.nanmin(f))),
                     ("peak contact force, mean over the cases [kN]", float(np.nanmean(f))),
                     ("peak contact force, largest over the cases [kN]", float(np.nanmax(f)))]
        if "n_impacts" in ok and len(ok):
            rows.append(("cases with an impact", int((ok["n_impacts"] > 0).sum())))
        try:
            from pounding.plot.sweep import plot_sweep

            fig, _, _ = plot_sweep(df)
            figure = (f'<img alt="peak contact force against the swept parameter" '
                      f'src="{png_uri(fig)}">')
        except (ValueError, IndexError) as exc:  # no successful case, nothing swept
            figure = f"<p>no figure: {html.escape(str(exc))}</p>"
    return ('<div class="pounding-sweep"><strong>pounding sweep</strong>'
            + html_table(rows, ("quantity", "value")) + figure + "</div>")

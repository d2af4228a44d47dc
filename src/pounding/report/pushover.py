"""The page of a pushover's folder (``pounding pushover``): the frame and the options, the
capacity curve's headline numbers, the curve event by event, the hinges, and its figure."""

from __future__ import annotations

import csv
import json
from pathlib import Path
from pounding.report.format import Block, Cards, Figure, Note, PageSection, Pre, Table, kv_table
from pounding.report.page import render_page

__all__ = ["PUSHOVER_FILE", "render_pushover"]

PUSHOVER_FILE = "pushover.csv"
"""The file that makes a folder a pushover's output (beside its ``summary.json``)."""

MAX_CURVE_ROWS = 200
"""Events listed on the page (all of them are in ``pushover.csv``)."""


def _read_csv(path: Path) -> list[dict[str, str]]:
    try:
        with open(path, newline="", encoding="utf-8") as f:
            return list(csv.DictReader(f))
    except (OSError, csv.Error, UnicodeDecodeError) as exc:
        raise ValueError(f"report: {path}: unreadable ({exc})") from None


def render_pushover(folder: Path) -> str:
    """The HTML text of the report of the pushover folder ``folder``.

    Raises
    ------
    ValueError
        ``summary.json``, ``pushover.csv`` or ``hinges.csv`` is unreadable.
    """
    path = folder / "summary.json"
    try:
        s = json.loads(path.read_text(encoding="utf-8"))
        peak = float(s["peak_base_shear_N"])
    except (OSError, json.JSONDecodeError, KeyError, TypeError, ValueError) as exc:
        raise ValueError(f"report: {path}: unreadable as a pushover summary ({exc})") from None
    curve = _read_csv(folder / PUSHOVER_FILE)
    hinges = _read_csv(folder / "hinges.csv") if (folder / "hinges.csv").is_file() else []
    first = s.get("first_yield")
    cards = Cards([
        ("peak base shear", f"{peak / 1e3:.4g} kN"),
        ("at roof displacement", f"{1e3 * float(s['roof_displacement_at_peak_m']):.4g} mm"),
        ("first yield", "none" if not first else
         f"{first['base_shear_N'] / 1e3:.4g} kN at {1e3 * first['roof_displacement_m']:.4g} mm"),
        ("ended", str(s["stopped"]))])
    overview: list[Block] = [cards, kv_table([
        ("frame", s["frame"]), ("load pattern", s["pattern"]),
        ("target roof displacement [m]", s["target_roof_displacement_m"]),
        ("final roof drift ratio [%]", 100 * float(s["final_roof_drift_ratio"])),
        ("initial stiffness [kN/m]", "–" if s.get("initial_stiffness_N_per_m") is None
         else float(s["initial_stiffness_N_per_m"]) / 1e3),
        ("events", s["events"]), ("model file", s["source"])])]
    t = Table(("roof displacement [mm]", "base shear [kN]"),
              caption=f"The capacity curve, one row per event (straight between rows)"
                      + (f"; the first {MAX_CURVE_ROWS} of {len(curve)}"
                         if len(curve) > MAX_CURVE_ROWS else ""), scroll=True)
    for row in curve[:MAX_CURVE_ROWS]:
        t.add(1e3 * float(row["roof_displacement_m"]), float(row["base_shear_N"]) / 1e3)
    h = Table(("hinge", "member", "x [m]", "y [m]", "law", "peak rotation [mrad]",
               "final moment [kN·m]", "yielded"), caption="Hinges", scroll=True)
    for row in hinges:
        h.add(row["hinge"], row["member"], float(row["x_m"]), float(row["y_m"]), row["law"],
              1e3 * float(row["peak_rotation_rad"]), float(row["final_moment_Nm"]) / 1e3,
              row["yielded"])
    figure: list[Block] = ([Figure((folder / "pushover.png").read_bytes(), "Capacity curve",
                                   "Base shear against roof displacement, every event marked; "
                                   "storey drift ratios at the end of the push.")]
                           if (folder / "pushover.png").is_file() else
                           [Note("No figure in the folder (the pushover ran with "
                                 "--no-figures).")])
    sections = [PageSection("overview", "Pushover", overview),
                PageSection("curve", "Capacity curve", [*figure, t]),
                PageSection("hinges", "Hinges", [h] if hinges else [Note("No hinges.")]),
                PageSection("metadata", "summary.json", [Pre(json.dumps(s, indent=2),
                                                            "the whole file")])]
    return render_page(f"{s.get('name', 'pushover')}: pushover report",
                       f"{s['pattern']} pattern; folder {folder.resolve().name}", sections,
                       folder)


def is_pushover(folder: Path) -> bool:
    """True if ``folder`` holds a pushover's output."""
    return (folder / PUSHOVER_FILE).is_file() and (folder / "summary.json").is_file()

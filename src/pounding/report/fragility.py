"""The page of a fragility study's folder (``pounding fragility``): the study, the
fragility of each limit state with its intervals, the probability of pounding against the
gap beside the code gaps, the counts at every stripe, and the figures the study drew."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from pounding.report.format import Block, Cards, Figure, Note, Pre, PageSection, Table, kv_table
from pounding.report.page import render_page

__all__ = ["FRAGILITY_FILE", "render_fragility"]

FRAGILITY_FILE = "fragility.json"
"""The file that makes a folder a fragility study's output."""

_FIGURES = (("fragility.png", "Fragility curves",
             "Observed fraction of runs exceeding each limit state at each level (markers), "
             "the maximum-likelihood fit to the stripes (Baker 2015; solid) with its bootstrap "
             "band, and the lognormal fit to the records' IDA capacities (dashed)."),
            ("ida.png", "IDA curves",
             "Each record's demand against the intensity it is scaled to (grey), and the "
             "16 / 50 / 84 % fractiles over the records at each level (Vamvatsikos & Cornell "
             "2002)."),
            ("pounding_vs_gap.png", "Probability of pounding against the gap",
             "At the gap level: the fraction of records whose needed gap is larger (steps), "
             "the lognormal fit and its bootstrap band, the gap for the target probability, "
             "and the ABS / SRSS / DDC gaps from the records' mean peak displacements."),
            ("pounding_surface.png", "Probability of pounding over gap and intensity",
             "Lognormal fit at each level (colours); the records' fractions of 10, 50 and "
             "90 % (dashed white lines); the gap level (dotted)."))


def _f(v: Any) -> Any:
    """A JSON number back to a float ("inf" → inf, null → NaN)."""
    if v is None:
        return float("nan")
    if v in ("inf", "-inf"):
        return float(v)
    return v


def render_fragility(folder: Path, code_check: Any = None) -> str:
    """The HTML text of the report of the fragility folder ``folder`` (with a "Code check"
    section for ``code_check``, a :class:`~pounding.report.code_check.CodeCheckFile`).

    Raises
    ------
    ValueError
        ``fragility.json`` is unreadable.
    """
    path = folder / FRAGILITY_FILE
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as exc:
        raise ValueError(f"report: {path}: unreadable ({exc})") from None
    im = data["intensity"]["label"]
    gap = data["gap"]
    sections = [PageSection("overview", "Study", _overview(data)),
                PageSection("fragility", "Fragility of each limit state", _fragility(data, im)),
                PageSection("gap", "Probability of pounding and the gap", _gap(data, im)),
                PageSection("counts", "Counts at every stripe", _counts(data)),
                PageSection("figures", "Figures", _figures(folder))]
    if data["runs"].get("collapsed"):
        sections.insert(1, PageSection("collapses", "Runs that collapsed", [
            Note(f"{data['runs']['collapsed']} run(s) collapsed: a frame lost its strength "
                 "(its hinges' moments dropped to zero and the run stopped), or a storey drifted "
                 "by more than its own height (sidesway collapse); they count as collapses and "
                 "as exceeding every drift and plastic-rotation limit state, their forces and "
                 "accelerations are left out."),
            Pre("\n".join(data["runs"]["collapses"]))]))
    if data["runs"]["failed"]:
        sections.insert(1, PageSection("failures", "Failed runs", [
            Note(f"{data['runs']['failed']} run(s) failed; they are left out of the counts "
                 "and the fits.", "warn"), Pre("\n".join(data["runs"]["failures"]))]))
    if code_check is not None:
        from pounding.report.code_check import code_check_section

        sections.append(code_check_section(code_check))
    sections.append(PageSection("metadata", "fragility.json",
                            [Pre(json.dumps(data, indent=2), "the whole file")]))
    return render_page(f"{data['name']}: pounding fragility report",
                       f"{len(data['records'])} records × {len(data['levels_g'])} levels of "
                       f"{im}; gap analysis at {gap['at_g']:g} g; folder "
                       f"{folder.resolve().name}", sections, folder)


def _overview(d: dict[str, Any]) -> list[Block]:
    it = d["intensity"]
    g = d["gap"]
    cards = Cards([
        ("runs", f"{d['runs']['n']} ({d['runs']['failed']} failed)"),
        ("intensity measure", it["label"]),
        (f"gap for P(pounding) = {g['target_probability']:g} at {g['at_g']:g} g",
         f"{1000 * _f(g['gap_for_target_lognormal_m']):.0f} mm"),
    ])
    scaling = it["scaling"]
    rows = [("description", d.get("description") or "–"), ("base model", d["base"]),
            ("records", ", ".join(d["records"])),
            ("levels [g]", ", ".join(f"{x:.4g}" for x in d["levels_g"])),
            ("scaling", scaling if isinstance(scaling, str) else json.dumps(scaling)),
            ("gaps run [m]", ", ".join("base model's" if x is None else f"{x:g}"
                                       for x in d["gaps_m"])),
            ("building periods T1 [s]", ", ".join(f"{t:.4g}" for t in d["building_periods_s"])),
            ("bootstrap", f"{d['bootstrap']['n']} resamples of the records, seed "
                          f"{d['bootstrap']['seed']}, {100 * d['bootstrap']['confidence']:g} % "
                          "percentile intervals")]
    return [cards, kv_table(rows)]


def _fragility(d: dict[str, Any], im: str) -> list[Block]:
    t = Table(("limit state", "gap [m]", "method", "median [g]", "median interval [g]", "β",
               "β interval", "records exceeding", "fit"),
              caption=f"Lognormal fragility functions, median in {im}")
    for ls in d["limit_states"]:
        n_exc = sum(1 for c in ls["censored"] if not c)
        for key, name in (("msa_mle", "stripes, MLE (Baker 2015 eq. 11)"),
                          ("ida", "IDA capacities")):
            e = ls[key]
            t.add(ls["name"], "base" if ls["gap_m"] is None else float(ls["gap_m"]), name,
                  _f(e["median_g"]), f"{_f(e['median_ci_g'][0]):.4g} – "
                                     f"{_f(e['median_ci_g'][1]):.4g}", _f(e["beta"]),
                  f"{_f(e['beta_ci'][0]):.3g} – {_f(e['beta_ci'][1]):.3g}",
                  f"{n_exc} of {len(ls['censored'])}", e["status"])
    return [t, Note("P(exceeded | IM = x) = Φ(ln(x / median) / β). Intervals: percentiles "
                    "of the fits to bootstrap resamples of the records (Efron 1979).")]


def _gap(d: dict[str, Any], im: str) -> list[Block]:
    g = d["gap"]
    t = Table(("gap", "[mm]"), caption=f"At {im.replace(' [g]', '')} = {g['at_g']:g} g")
    lo, hi = (_f(v) for v in g["gap_for_target_lognormal_ci_m"])
    p = g["target_probability"]
    t.add(f"P(pounding) = {p:g}: lognormal fit over records", 1000 * _f(
        g["gap_for_target_lognormal_m"]))
    t.add("  its bootstrap interval", f"{1000 * lo:.1f} – {1000 * hi:.1f}")
    t.add(f"P(pounding) = {p:g}: records (inverted empirical CDF)",
          1000 * _f(g["gap_for_target_records_m"]))
    for k, v in g["code_gaps_m"].items():
        t.add(f"{k} (mean simulated peak displacements)", 1000 * _f(v))
    per = Table(("record", "needed gap [mm]"), caption="The gap each record needs")
    for name, v in g["needed_m"].items():
        per.add(name, 1000 * _f(v))
    out: list[Block] = [t, per]
    for c in g["check"].values():
        out.append(Note(f"Check with gap {c['gap_m']:g} m: of {c['runs']} runs with contact, "
                        f"{c['pounded']} pounded, and {c['agree']} agree with 'the needed gap "
                        "exceeds the gap'."))
    return out


def _counts(d: dict[str, Any]) -> list[Block]:
    t = Table(["level [g]"] + [f"{ls['name']}" + ("" if ls["gap_m"] is None else
                                                  f" (gap {ls['gap_m']:g} m)")
                               for ls in d["limit_states"]],
              caption="Runs exceeding each limit state / runs, at each level", scroll=True)
    for j, x in enumerate(d["levels_g"]):
        t.add(x, *[f"{ls['n_exceed'][j]} / {ls['n_runs'][j]}" for ls in d["limit_states"]])
    return [t]


def _figures(folder: Path) -> list[Block]:
    out: list[Block] = []
    for name, alt, caption in _FIGURES:
        p = folder / name
        if p.is_file():
            out.append(Figure(p.read_bytes(), alt, caption))
    return out or [Note("No figure in the folder (the study ran with --no-figures).")]

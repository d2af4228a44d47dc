"""The "Code check" section of the run, sweep and fragility pages: the separation a seismic
code asks for, level by level, from a folder ``pounding code-check --out DIR`` wrote
(``code_check.json``), and for a run the run's own peak closing beside it
(``docs/report.md``).

A code check reaches a page two ways: ``pounding run/sweep/fragility ... --code-check DIR``
keeps a copy in the output folder (:func:`attach_code_check`, recorded in the folder's
manifest), which ``pounding report`` then shows; or ``pounding report FOLDER --code-check
DIR`` shows DIR's check on that page. Either way the file is read only if pounding wrote
it, unchanged since (its folder's manifest), and its content is checked before it is used
(:func:`read_code_check`): anything else is one line naming the folder or the field.
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from pounding.report.format import Block, Note, PageSection, Table, kv_table

__all__ = ["CODE_CHECK_FILE", "CodeCheckFile", "attach_code_check", "code_check_section",
           "folder_code_check", "other_model", "parameters_text", "read_code_check"]

CODE_CHECK_FILE = "code_check.json"
"""The file of a code check (:data:`pounding.studies.codes.CODE_CHECK_FILE`)."""

_LEVEL_KEYS: dict[str, type | tuple[type, ...]] = {
    "pair": str, "contact": str, "elevation_m": (int, float), "left_mm": (int, float),
    "right_mm": (int, float), "required_mm": (int, float), "gap_mm": (int, float),
    "ok": bool, "clause": str}
"""The fields of a level of ``code_check.json`` and their JSON types."""


@dataclass(frozen=True)
class CodeCheckFile:
    """A ``code_check.json`` read and checked: its data, its text as written (copied as is
    into an output folder) and where it came from."""

    data: dict[str, Any]
    text: str
    source: Path


def _checked(text: str, where: str) -> dict[str, Any]:
    """The data of a ``code_check.json``, or one line naming the field at fault."""
    try:
        data = json.loads(text)
    except ValueError as exc:
        raise ValueError(f"{where}: not JSON ({exc})") from None
    if not isinstance(data, dict):
        raise ValueError(f"{where}: not a code check (a JSON object with code, title and "
                         "levels)")
    for key in ("code", "title"):
        if not isinstance(data.get(key), str):
            raise ValueError(f"{where}: {key}: a text expected (got {data.get(key)!r:.60})")
    levels = data.get("levels")
    if not isinstance(levels, list) or not levels:
        raise ValueError(f"{where}: levels: a list of the check's levels expected")
    for i, level in enumerate(levels):
        if not isinstance(level, dict):
            raise ValueError(f"{where}: levels[{i}]: an object expected")
        for key, kind in _LEVEL_KEYS.items():
            value = level.get(key)
            ok = isinstance(value, kind) and not (kind != bool and isinstance(value, bool))
            if ok and isinstance(value, float) and not math.isfinite(value):
                ok = False
            if not ok:
                raise ValueError(f"{where}: levels[{i}].{key}: got {value!r:.60}")
    th = data.get("time_history")
    if th is not None and not (isinstance(th, dict)
                               and isinstance(th.get("verdicts"), list)
                               and isinstance(th.get("records"), list)):
        raise ValueError(f"{where}: time_history: not the block pounding writes")
    return data


def read_code_check(folder: str | os.PathLike[str],
                    option: str = "--code-check") -> CodeCheckFile:
    """The check ``pounding code-check --out`` wrote into ``folder``.

    Raises
    ------
    ValueError
        One line naming ``option`` and the folder: not a folder, not written by
        ``pounding code-check`` (its manifest), ``code_check.json`` missing or changed since,
        or not a code check.
    """
    from pounding.io.manifest import Manifest

    where = Path(folder)
    if not where.is_dir():
        raise ValueError(f"{option}: {where} is not a folder (give the --out DIR of "
                         "`pounding code-check`)")
    manifest = Manifest(where)
    if not manifest.exists() or manifest.kind() != "code-check":
        raise ValueError(f"{option}: {where} is not a folder `pounding code-check --out` "
                         "wrote (no code-check manifest)")
    path = where / CODE_CHECK_FILE
    if not manifest.is_ours(path):
        raise ValueError(f"{option}: {path} is missing or changed since pounding wrote it; "
                         "run `pounding code-check --out` again")
    text = path.read_text(encoding="utf-8")
    return CodeCheckFile(_checked(text, f"{option}: {path}"), text, path)


def folder_code_check(results_dir: str | os.PathLike[str]) -> CodeCheckFile | None:
    """The code check kept in an output folder (:func:`attach_code_check`), None without
    one.

    Raises
    ------
    ValueError
        ``code_check.json`` is there but pounding did not write it there (or it changed
        since), or it is not a code check: one line.
    """
    from pounding.io.manifest import Manifest

    folder = Path(results_dir)
    path = folder / CODE_CHECK_FILE
    if not path.exists() and not path.is_symlink():
        return None
    if not Manifest(folder).is_ours(path):
        raise ValueError(f"report: {path} is not the code check pounding kept there (or it "
                         "changed since); move it away, or give --code-check DIR")
    text = path.read_text(encoding="utf-8")
    return CodeCheckFile(_checked(text, f"report: {path}"), text, path)


def attach_code_check(results_dir: str | os.PathLike[str], check: CodeCheckFile) -> Path:
    """Keep ``check`` in the output folder ``results_dir`` as ``code_check.json``, recorded
    in its manifest (written atomically; a file of that name pounding did not write is not
    replaced). Returns the path written."""
    from pounding.io.manifest import Manifest

    folder = Path(results_dir)
    return Manifest(folder).write_text(folder / CODE_CHECK_FILE, check.text)


def other_model(check: CodeCheckFile, model: Any, gaps: bool = True) -> str | None:
    """Why ``check`` is not a check of ``model`` (a
    :class:`~pounding.model.PoundingModel`), or None: a level whose contact the model does
    not have, or has at another elevation or (with ``gaps``) with another gap (to 1 µm).
    Labels alone prove little — ``B1F1-B2F1`` is in almost every model. A study's base model
    is compared without its gaps (a sweep may vary them)."""
    contacts = {c.label: c for c in model.contacts}
    for level in check.data["levels"]:
        label = str(level["contact"])
        c = contacts.get(label)
        if c is None:
            return f"its level {label} is not a contact of this model"
        here = (float(c.elevation), 1e3 * float(c.gap))
        there = (float(level["elevation_m"]), float(level["gap_mm"]))
        if abs(here[0] - there[0]) > 1e-6 or (gaps and abs(here[1] - there[1]) > 1e-3):
            return (f"its level {label} is at {there[0]:.4g} m with a gap of {there[1]:.4g} "
                    f"mm, this model's at {here[0]:.4g} m with {here[1]:.4g} mm")
    return None


def _run_closing(run: Any, contacts: list[str]) -> dict[str, tuple[float, float, bool]]:
    """Each contact of the run: its gap [m], its peak closing ``max(u_left − u_right)``
    [m] (``gap + max δ``) and whether it touched."""
    ds = run.ds
    if "contact" not in ds.dims or ds.sizes["contact"] == 0:
        return {}
    labels = [str(x) for x in ds["contact"].values]
    pen = np.asarray(ds["penetration"].values, dtype=float)
    gaps: dict[str, float] = {}
    if run.built is not None:
        gaps = {c.label: float(c.gap) for c in run.built.model.contacts}
    out = {}
    for label in contacts:
        if label not in labels or label not in gaps:
            continue
        i = labels.index(label)
        hits = run.impacts_of(label)
        touched = len(hits) > 0 or float(pen[:, i].max()) > 0.0
        out[label] = (gaps[label], gaps[label] + float(pen[:, i].max()), touched)
    return out


def parameters_text(params: dict[str, Any]) -> str:
    """The check's parameters as one readable line: numbers to 4 significant digits (whole
    ones from 10,000 up, and every integer, with thousands separators), a
    building's own values (ASCE 7-22's ELF: T, C_s, …) in brackets after its name, unset
    ones (None) left out: ``sds_g = 1, …, office (T_s = 0.95, C_s = 0.07895, …)``."""
    def value(v: Any) -> str:
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            return str(v)
        if isinstance(v, int):
            return f"{v:,}"
        return f"{v:,.0f}" if abs(v) >= 1e4 else f"{v:.4g}"

    parts = []
    for k, v in params.items():
        if v is None:
            continue
        if isinstance(v, dict):
            parts += [f"{name} ({parameters_text(inner)})" if isinstance(inner, dict)
                      else f"{name} = {value(inner)}" for name, inner in v.items()]
        else:
            parts.append(f"{k} = {value(v)}")
    return ", ".join(parts)


def code_check_section(check: CodeCheckFile, run: Any = None) -> PageSection:
    """The "Code check" section: the check's head (code, parameters, assumptions), its table
    level by level (required beside the gap, the clause), for a run (a
    :class:`~pounding.report.run_folder.RunFolder`) the run's gap and peak closing beside
    it, and the check's time histories if it has them."""
    d = check.data
    levels = d["levels"]
    params: dict[str, Any] = d["parameters"] if isinstance(d.get("parameters"), dict) else {}
    head = [("code", d["title"]), ("displacement", str(d.get("displacement", "")))]
    if params:
        head.append(("parameters", parameters_text(params)))
    if isinstance(d.get("model"), str):
        head.append(("model checked", d["model"]))
    head += [("assumes", str(a)) for a in d.get("assumptions", []) or []]
    head.append(("from", str(check.source)))
    blocks: list[Block] = [kv_table(head, caption="What the check is (pounding code-check)")]
    if run is not None and getattr(run, "built", None) is not None:
        why = other_model(check, run.built.model)
        if why is not None:
            raise ValueError(f"--code-check: {check.source} is a check of another model "
                             f"({why}); check this run's model with pounding code-check")
    closing = _run_closing(run, [lv["contact"] for lv in levels]) if run is not None else {}
    clauses: dict[str, Any] = d["clauses"] if isinstance(d.get("clauses"), dict) else {}
    caption = "; ".join(f"{k}: {v}" for k, v in clauses.items())
    for pair in dict.fromkeys(lv["pair"] for lv in levels):
        cols = ["floor", "elevation [m]", "left building [mm]", "right building [mm]",
                "required [mm]", "gap [mm]", "check", "clause"]
        if run is not None:
            cols += ["gap in this run [mm]", "peak closing in this run [mm]",
                     "touched in this run"]
        t = Table(cols, caption=f"{pair}: separation by {d['title']} (left and right: "
                                f"{d.get('displacement', 'each building')})", scroll=True)
        for lv in levels:
            if lv["pair"] != pair:
                continue
            row: list[Any] = [lv["contact"], lv["elevation_m"], lv["left_mm"], lv["right_mm"],
                              lv["required_mm"], lv["gap_mm"], "OK" if lv["ok"] else "not OK",
                              lv["clause"]]
            if run is not None:
                got = closing.get(lv["contact"])
                row += (["–", "– (not a contact of this run)", "–"] if got is None else
                        [1e3 * got[0], 1e3 * got[1], "yes" if got[2] else "no"])
            t.add(*row)
        blocks.append(t)
    if caption:
        blocks.append(Note(f"Clauses: {caption}."))
    bad = [lv for lv in levels if not lv["ok"]]
    blocks.append(Note(f"{len(levels) - len(bad)} of {len(levels)} level(s) meet "
                       f"{d['title']}" + (f"; largest shortfall "
                       f"{max(lv['required_mm'] - lv['gap_mm'] for lv in bad):.1f} mm."
                       if bad else "."), "warn" if bad else "note"))
    if run is not None:
        missing = [lv["contact"] for lv in levels if lv["contact"] not in closing]
        if missing:
            blocks.append(Note(f"Level(s) {', '.join(missing)} of the check are not contacts "
                               "of this run's model (or its model.toml could not be "
                               "rebuilt): is the check of another model?", "warn"))
        blocks.append(Note(
            "Peak closing in this run: the largest u_left − u_right at the output samples, "
            "gap + the largest penetration δ (timehistories.nc). Where the run touched it is "
            "bounded by the impacts, so it is not the smallest gap that would have prevented "
            "pounding: that is the critical gap of the Gap check section (the buildings "
            "apart). The check is linear on the code's spectrum; the run is this record."))
    blocks += _time_history_blocks(d.get("time_history"))
    return PageSection("code-check", "Code check", blocks)


def _time_history_blocks(th: Any) -> list[Block]:
    """The check's time histories (``pounding code-check --time-history``), if it has them."""
    if not isinstance(th, dict):
        return []
    out: list[Block] = [Note(str(v)) for v in th.get("verdicts", [])]
    t = Table(("record", "scale factor", "pounded (own gap)", "impacts (own gap)",
               "peak force (own gap) [kN]", "pounded (code gap)", "impacts (code gap)",
               "peak force (code gap) [kN]"),
              caption=f"Time histories beside the check: the suite scaled to "
                      f"{th.get('target', '–')} ({th.get('scaling', '–')}); own gap: the "
                      "model's, code gap: every pair's gap at the code's separation",
              scroll=True)
    for rec in th.get("records", []):
        if not isinstance(rec, dict):
            continue
        own = rec.get("own_gap") or {}
        code = rec.get("code_gap") or {}
        t.add(str(rec.get("record")), _number(rec.get("factor")),
              "yes" if own.get("pounded") else "no", _number(own.get("impacts")),
              _number(own.get("peak_force_kN")), "yes" if code.get("pounded") else "no",
              _number(code.get("impacts")), _number(code.get("peak_force_kN")))
    out.append(t)
    lt = Table(("floor", "required [mm]", "mean peak closing [mm]",
                "records closing past the required separation"),
               caption="Peak closing (the smallest gap that prevents pounding under a record: "
                       "max(u_left − u_right) with the buildings apart) beside the code's "
                       "separation")
    for lv in th.get("levels", []):
        if isinstance(lv, dict):
            lt.add(str(lv.get("contact")), _number(lv.get("required_mm")),
                   _number(lv.get("mean_peak_closing_mm")),
                   _number(lv.get("records_closing_past_required")))
    out.append(lt)
    return out


def _number(v: Any) -> Any:
    """A JSON number for a cell (anything else: "–")."""
    return v if isinstance(v, (int, float)) and not isinstance(v, bool) else "–"

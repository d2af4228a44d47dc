"""Messages of bad model and study files, found systematically, and the numbers that were
accepted silently.

Every key of a model file, a fragility study file and a mitigation study file (documents
below that together hold every key) is given a value of the wrong kind and values out of
range. Each message must be one line naming the key path and the value, with none of the
validation library's internals (its names for union members, a class repr, a file name run
into a key); every number must have a finite physical range, stated in the message.
"""

from __future__ import annotations

import copy
import re
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from pounding.cli import main
from pounding.config import dump_toml, load_config, parse_config
from pounding.config.base import Section, fmt
from pounding.ground_motion import GroundMotion
from pounding.ground_motion.incidence import at_incidence
from pounding.hysteresis.isolators import FrictionPendulum
from pounding.plausibility import PlausibilityWarning
from pounding.structure.plan import LateralElement, PlanBuilding
from pounding.studies.fragility.study import parse_study
from pounding.studies.mitigation import load_mitigation

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"

PAIR = [{"name": "a", "mass": 2e5, "period": 0.5, "height": 3.0, "damping": {"ratio": 0.05}},
        {"name": "b", "mass": 3e5, "stiffness": 1.2e7, "height": 3.0}]
PLAN_ELEMENTS = [
    {"name": "x0", "x": 10.0, "y": 0.0, "direction": "x", "stiffnesses": [1.8e8, 1.5e8]},
    {"x": 10.0, "y": 12.0, "direction": 0.0, "stiffnesses": 1.5e8},
    {"x": 0.0, "y": 6.0, "direction": "y", "stiffnesses": [1.8e8, 1.5e8]},
    {"x": 20.0, "y": 6.0, "direction": 90.0, "stiffnesses": [1.8e8, 1.5e8]}]

MODEL_DOCS: dict[str, dict[str, Any]] = {
    "sdof": {
        "name": "pair", "description": "d",
        "record": {"bundled": "el_centro", "duration": 3.0, "scale": 1.0},
        "building": PAIR,
        "contact": {"law": "nonlinear-viscoelastic", "k_h": 2.75e9, "e": 0.65, "gap": 0.02},
        "solver": {"dt": 0.002, "duration": 3.0, "rtol": 1e-8, "h_max": 0.002},
        "output": {"figures": False, "dpi": 100},
    },
    "storeys": {
        "record": {"bundled": "el_centro", "duration": 2.0, "pga_g": 0.3},
        "building": [
            {"n_storeys": 3, "mass": 2e5, "stiffness": 2e8, "height": 3.0,
             "damping": {"rayleigh": [0.05, 0.04], "modes": [1, 3]},
             "storey_law": {"type": "bilinear", "yield_force": 2e6, "hardening": 0.05}},
            {"masses": [2e5, 2e5, 1.5e5], "stiffnesses": [2e8, 1.8e8, 1.5e8],
             "heights": [3.5, 3.0, 3.0], "period": 0.6,
             "damping": {"rayleigh": [0.05], "periods": [0.6, 0.2]},
             "storey_law": {"type": "bouc-wen", "yield_drift_ratio": [0.005, 0.005, 0.006],
                            "alpha": 0.05, "n": 2.0, "beta": 0.5, "gamma": 0.5}},
            {"masses": [2e5, 2e5], "stiffnesses": [2e8, 2e8], "height": 3.0,
             "storey_law": {"type": "bilinear", "yield_drift": [0.01, 0.01]}}],
        "contact": {"law": "hertz", "k_h": 2.75e9, "n": 1.5, "gaps": [0.02, 0.03]},
    },
    "isolated": {
        "record": {"bundled": "el_centro", "duration": 2.0, "sa_g": 0.5, "sa_period": 1.0,
                   "sa_damping": 0.05},
        "building": [{"n_storeys": 2, "mass": 4e5, "period": 0.4, "height": 3.2,
                      "isolator": {"law": "friction-pendulum", "radius": 2.0, "mu": 0.05,
                                   "base_mass": 5e5, "base_height": 1.0, "damping": 1e5,
                                   "weight": 1.2e7, "yield_displacement": 5e-4, "n": 2.0,
                                   "beta": 0.5, "gamma": 0.5}}],
        "wall": [{"side": "left", "height": 1.0, "gap": 0.15, "name": "W1"},
                 {"side": "right", "height": 1.0, "gap": 0.15}],
        "contact": {"law": "kelvin-voigt", "k": 2e9, "e": 0.5},
    },
    "bilinear isolator": {
        "record": {"bundled": "el_centro", "duration": 2.0, "saavg_g": 0.4,
                   "saavg_periods": [0.2, 2.0], "saavg_n": 5},
        "building": [{"n_storeys": 2, "mass": 4e5, "period": 0.4,
                      "isolator": {"law": "bilinear", "pre_yield_stiffness": 1.2e8,
                                   "post_yield_stiffness": 1.2e7,
                                   "characteristic_strength": 5e5, "base_mass": 5e5}},
                     {"n_storeys": 2, "mass": 4e5, "period": 0.4,
                      "isolator": {"law": "bilinear", "pre_yield_stiffness": 1.2e8,
                                   "post_yield_stiffness": 1.2e7, "yield_force": 6e5,
                                   "base_mass": 5e5}}],
        "contact": {"law": "hunt-crossley", "k_h": 2.75e9, "e": 0.6, "n": 1.5, "gap": 0.05},
    },
    "devices": {
        "record": {"bundled": "el_centro", "duration": 2.0},
        "building": [{"n_storeys": 2, "mass": 2e5, "period": 0.3},
                     {"n_storeys": 2, "mass": 2e5, "period": 0.5}],
        "contact": {"law": "kelvin-voigt", "k": 9.3e8, "e": 0.65,
                    "formula": "anagnostopoulos", "gap": 0.02, "floor_to_column": True,
                    "level_tolerance": 0.1},
        "device": [{"type": "viscous", "floors": ["B1F1", "B2F1"], "c": 1e6, "alpha": 0.5},
                   {"type": "kelvin", "floors": ["B1F2", "B2F2"], "c": 1e6, "k": 1e7},
                   {"type": "maxwell", "floors": "all", "c": 1e6, "k": 1e8, "alpha": 1.0},
                   {"type": "bumper", "floors": "all", "thickness": 0.01,
                    "compression_limit": 0.7,
                    "rubber": {"law": "bilinear-impact", "k_h": 2e8, "e": 0.5,
                               "delta_m": 0.002, "n": 1.5, "a": 0.1}}],
    },
    "kelvin-voigt c": {
        "record": {"bundled": "el_centro", "duration": 2.0},
        "building": [{"mass": 2e5, "period": 0.5}, {"mass": 2e5, "period": 0.6}],
        "contact": {"law": "kelvin-voigt", "k": 9.3e8, "c": 1e5, "tension": False,
                    "gap": 0.02},
    },
    "kelvin-voigt zeta": {
        "record": {"bundled": "el_centro", "duration": 2.0},
        "building": [{"mass": 2e5, "period": 0.5}, {"mass": 2e5, "period": 0.6}],
        "contact": {"law": "kelvin-voigt", "k": 9.3e8, "zeta": 0.1, "gap": 0.02},
    },
    "hunt-crossley chi": {
        "record": {"bundled": "el_centro", "duration": 2.0},
        "building": [{"mass": 2e5, "period": 0.5}, {"mass": 2e5, "period": 0.6}],
        "contact": {"law": "hunt-crossley", "k_h": 2.75e9, "chi": 0.5, "gap": 0.02},
    },
    "matrices": {
        "record": {"bundled": "el_centro", "duration": 2.0},
        "building": [{"matrices": {"M": "matrix_building_M.csv", "K": "matrix_building_K.csv"},
                      "elevations": [3.2 * (i + 1) for i in range(10)],
                      "labels": [f"L{i + 1}" for i in range(10)], "r": [1.0] * 10,
                      "damping": {"rayleigh": [0.05, 0.05], "modes": [1, 2]}},
                     {"n_storeys": 10, "mass": 4e5, "stiffness": 1.2e9, "height": 3.2}],
        "contact": {"law": "linear-spring", "k": 1e9, "gap": 0.04},
    },
    "plan": {
        "record": {"bundled": "kocaeli_1999_duzce_180_RSN1158",
                   "second": "kocaeli_1999_duzce_270_RSN1158", "incidence": 60.0,
                   "duration": 2.0},
        "building": [
            {"name": "s", "plan": {"width": 20.0, "depth": 12.0, "site_y": 0.0,
                                   "mass_centres": [10.0, 6.0], "inertias": 1.2e7},
             "masses": [2.5e5, 2.5e5], "heights": [3.0, 3.0], "elements": PLAN_ELEMENTS},
            {"plan": {"width": 16.0, "depth": 12.0, "site_y": 6.0,
                      "mass_centres": [[8.0, 6.0], [8.0, 7.0]], "inertias": [8e6, 8e6]},
             "masses": [2e5, 2e5], "height": 3.0,
             "damping": {"rayleigh": [0.05, 0.05], "modes": [1, 3]},
             "elements": [
                 {"x": 8.0, "y": 0.0, "direction": "x", "stiffnesses": [0.4e8, 0.3e8]},
                 {"x": 8.0, "y": 12.0, "direction": "x", "stiffnesses": [1.6e8, 1.3e8]},
                 {"x": 0.0, "y": 6.0, "direction": "y", "stiffnesses": [1.0e8, 0.8e8]},
                 {"x": 16.0, "y": 6.0, "direction": "y", "stiffnesses": [1.0e8, 0.8e8]}]}],
        "contact": {"law": "kelvin-voigt", "k": 9.3e8, "e": 0.65, "gap": 0.02},
    },
}
"""Model files that together hold every key of a model file (each valid as it stands)."""

FRAGILITY_DOCS: dict[str, dict[str, Any]] = {
    "sa": {"name": "f", "description": "d", "base": "two_10_storey.toml",
           "suite": {"bundled": True, "duration": 30.0},
           "intensity": {"measure": "sa", "period": 1.15, "damping": 0.05,
                         "levels": {"start": 0.02, "stop": 1.0, "n": 5, "spacing": "log"}},
           "limit_state": [{"demand": "pounding"},
                           {"demand": "impact_force", "limit": 10.0, "name": "F"},
                           {"demand": "drift", "limit": 0.5}],
           "gap": {"at": 0.4, "target": 0.1, "values": [0.02, 0.04]},
           "bootstrap": {"n": 100, "seed": 1, "confidence": 0.9},
           "run": {"workers": 1, "batch_size": 4, "histories": False}},
    "saavg": {"base": "two_10_storey.toml",
              "suite": {"files": ["a.at2"], "dt": 0.01, "units": "g",
                        "scaling": {"target": "t.csv", "period": 1.0, "method": "code",
                                    "code": "asce7"}},
              "intensity": {"measure": "saavg", "periods": [0.2, 2.0], "n_periods": 5,
                            "levels": [0.1, 0.2, 0.4]},
              "run": {"scheduler": "synchronous"}},
    "pga": {"base": "two_10_storey.toml", "suite": {"folder": "records"},
            "intensity": {"measure": "pga", "levels": [0.1, 0.2]}},
}
"""Fragility study files that together hold every key."""

MITIGATION_DOCS: dict[str, dict[str, Any]] = {
    "options": {"name": "m", "base": "two_10_storey.toml", "records": ["el_centro"],
                "option": [{"name": "bare"},
                           {"name": "pads", "device": [
                               {"type": "bumper", "floors": "all", "thickness": 0.01,
                                "compression_limit": 0.7,
                                "rubber": {"law": "hertzdamp", "k_h": 2e8, "e": 0.5}}]},
                           {"name": "dash", "device": [{"type": "viscous", "floors": "all",
                                                        "c": 2e6, "alpha": 0.5}]}]},
}
"""A mitigation study file with every key."""

INTERNALS = re.compile(
    r"list\[|literal\[|dict\[|union\[|function-(after|before|wrap|plain)|constrained-|"
    r"strict-|tagged-union|nullable|json-or-python|is_instance|Input should|instance of|"
    r"Value error|Assertion failed|pydantic|\.toml[A-Za-z_\[]|\b\w+(Config|Spec|Range)\(")
"""What the validation library shows of itself: its names for union members, its
messages, a class repr; and a file name run into a key (``study.tomloption[0]``)."""

BOUND = re.compile(r"[\[(]-?[\d.e+]+, -?[\d.e+]+[\])]|[<>]=? -?[\d.]|must not be 0")
"""A range or a bound in a message: ``(0, 1000]``, ``> 0``, ``<= 1``."""

CROSS_FIELD = {
    ("devices", "contact.gap", 0.0): "device[3].thickness",
}
"""Values refused because of another key, which the message names instead."""


def _sections() -> set[str]:
    found, todo = set(), [Section]
    while todo:
        cls = todo.pop()
        for sub in cls.__subclasses__():
            found.add(sub.__name__)
            todo.append(sub)
    return found


def _key_text(path: tuple[Any, ...]) -> str:
    out = ""
    for p in path:
        out += f"[{p}]" if isinstance(p, int) else ("." if out else "") + str(p)
    return out


def _paths(doc: Any, path: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    """Every key path of ``doc``: tables, lists, values; of a list, its first and last
    items."""
    out: list[tuple[Any, ...]] = []
    items = (list(doc.items()) if isinstance(doc, dict) else
             sorted({0: doc[0], len(doc) - 1: doc[-1]}.items()) if isinstance(doc, list) and doc
             else [])
    for k, v in items:
        out.append(path + (k,))
        out += _paths(v, path + (k,))
    return out


def _get(doc: Any, path: tuple[Any, ...]) -> Any:
    for p in path:
        doc = doc[p]
    return doc


def _replaced(doc: dict[str, Any], path: tuple[Any, ...], value: Any) -> dict[str, Any]:
    new = copy.deepcopy(doc)
    _get(new, path[:-1])[path[-1]] = value
    return new


def _wrong_kind(value: Any) -> list[Any]:
    if isinstance(value, bool):
        return ["yes"]
    if isinstance(value, (int, float)):
        return ["abc"]
    if isinstance(value, str):
        return [True]
    if isinstance(value, list):
        return ["abc"]
    return [5]


def _out_of_range(value: Any) -> list[Any]:
    if isinstance(value, bool):
        return []
    if isinstance(value, int):
        return [-1, 0, 10**18]
    if isinstance(value, float):
        return [-1e300, -1.0, 0.0, 1e300]
    if isinstance(value, list):
        return [[]]
    return []


def _model_message(doc: dict[str, Any], tmp: Path) -> str | None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PlausibilityWarning)
        try:
            parse_config(doc, base_dir=EXAMPLES, where="m.toml")
        except ValueError as exc:
            return str(exc)
    return None


def _fragility_message(doc: dict[str, Any], tmp: Path) -> str | None:
    try:
        parse_study(doc, where="s.toml")
    except ValueError as exc:
        return str(exc)
    return None


def _mitigation_message(doc: dict[str, Any], tmp: Path) -> str | None:
    f = tmp / "s.toml"
    f.write_text(dump_toml(doc), encoding="utf-8")
    try:
        load_mitigation(f)
    except ValueError as exc:
        return str(exc).replace(str(f), "s.toml")
    return None


KINDS = {"model file": (MODEL_DOCS, _model_message, "m.toml: "),
         "fragility study": (FRAGILITY_DOCS, _fragility_message, "s.toml: "),
         "mitigation study": (MITIGATION_DOCS, _mitigation_message, "s.toml: ")}


def _problems(name: str, path: tuple[Any, ...], bad: Any, message: str, prefix: str,
              out_of_range: bool) -> list[str]:
    key = _key_text(path)
    parent = _key_text(path[:-1]) if isinstance(path[-1], int) else key
    named = CROSS_FIELD.get((name, key, bad)) if isinstance(bad, float) else None
    problems = []
    if "\n" in message:
        problems.append("more than one line")
    if not message.startswith(prefix) or message.startswith(prefix + " "):
        problems.append("not prefixed with the file")
    if INTERNALS.search(message) or re.search(
            r"\b(" + "|".join(sorted(_sections())) + r")\b", message):
        problems.append("validation internals")
    if not any(f"{p}:" in message or f"{p}[" in message or f"{p}." in message
               for p in ([named] if named else [key, parent])):
        problems.append("the key path is not named")
    values = [fmt(bad)] + ([fmt(bad[0])] if isinstance(bad, list) and bad else [])
    if not any(v in message for v in values):
        problems.append("the value is not named")
    if out_of_range and not named and not isinstance(bad, list) and not BOUND.search(message):
        problems.append("no range in the message")
    return problems


@pytest.mark.parametrize("kind", list(KINDS))
def test_every_key_with_a_bad_value_is_one_line_naming_key_and_value(kind: str,
                                                                     tmp_path: Path) -> None:
    """Every key, a value of the wrong kind and values out of range: one clean line each;
    and no number is accepted at ±1e300 (every number has a physical range)."""
    docs, message_of, prefix = KINDS[kind]
    failures = []
    tried = 0
    for name, doc in docs.items():
        assert message_of(doc, tmp_path) is None, f"{name} must be valid as it stands"
        for path in _paths(doc):
            value = _get(doc, path)
            for bad, ranged in ([(v, False) for v in _wrong_kind(value)]
                                + [(v, True) for v in _out_of_range(value)]):
                tried += 1
                message = message_of(_replaced(doc, path, bad), tmp_path)
                if message is None:
                    if isinstance(bad, float) and abs(bad) == 1e300:
                        failures.append(f"{name}: {_key_text(path)} = {fmt(bad)}: accepted")
                    continue
                for problem in _problems(name, path, bad, message, prefix, ranged):
                    failures.append(f"{name}: {_key_text(path)} = {fmt(bad)}: {problem}: "
                                    f"{message!r}")
    assert tried > {"model file": 1000, "fragility study": 150, "mitigation study": 20}[kind]
    assert not failures, "\n".join(failures)


# ----------------------------------------------------------- the messages of the issue
@pytest.mark.parametrize("doc, path, value, expected", [
    ("fragility", ("intensity", "levels", 0), "a",
     "s.toml: intensity.levels[0]: must be a number (got 'a')"),
    ("fragility", ("intensity", "levels"), {"start": 1.0, "stop": 0.5, "n": 3},
     "s.toml: intensity.levels.stop: must be above start = 1 (got 0.5)"),
    ("fragility", ("intensity", "levels"), "many",
     "s.toml: intensity.levels: must be a list of numbers [ ... ] or a table (got 'many')"),
    ("fragility", ("intensity", "levels"), {"start": 0.1, "stop": 1.0, "n": 3, "x": 1},
     "s.toml: intensity.levels.x: unknown key (got 1) (keys here: n, spacing, start, stop)"),
    ("devices", ("device", 2, "floors"), "al",
     "m.toml: device[2].floors: must be a list of strings [ ... ] or \"all\" (got 'al')"),
    ("storeys", ("building", 0, "storey_law", "yield_force"), -1.0,
     "m.toml: building[0].storey_law.yield_force: must be in (0, 1e+13] N (got -1)"),
])
def test_the_messages_of_the_issue_name_the_key_as_written(doc: str, path: tuple[Any, ...],
                                                          value: Any, expected: str) -> None:
    """``intensity.levels.list[constrained-float]``, ``function-after[_order(),
    LevelRange]``, ``floors.literal['all']`` and a union reported once per member before."""
    if doc == "fragility":
        with pytest.raises(ValueError) as info:
            parse_study(_replaced(FRAGILITY_DOCS["pga"] if path[-1] == 0 else
                                  FRAGILITY_DOCS["sa"], path, value), where="s.toml")
    else:
        with pytest.raises(ValueError) as info:
            parse_config(_replaced(MODEL_DOCS[doc], path, value), EXAMPLES, where="m.toml")
    assert str(info.value) == expected


@pytest.mark.parametrize("doc, path, value, expected", [
    ("matrices", ("building", 0, "floors"), [-1],
     "m.toml: building[0].floors[0]: must be a label or an index in [0, 9] (got -1)"),
    ("matrices", ("building", 0, "labels", 3), "L1",
     "m.toml: building[0].labels[3]: repeats labels[0]: each degree of freedom needs its own "
     "label (got 'L1')"),
    ("storeys", ("building", 0, "damping", "modes"), [2, 2],
     "m.toml: building[0].damping.modes[1]: must differ from modes[0]: Rayleigh damping is "
     "anchored at two modes (got 2)"),
    ("storeys", ("building", 1, "storey_law", "yield_drift_ratio"), [0.005, 0.005],
     "m.toml: building[1].storey_law.yield_drift_ratio: need one value or 3, one per storey "
     "(got 2: [0.005, 0.005])"),
    ("storeys", ("building", 1, "storey_law", "gamma"), -1.0,
     "m.toml: building[1].storey_law.gamma: beta + gamma must be > 0, or the hysteretic "
     "variable grows without bound (got beta = 0.5, gamma = -1)"),
])
def test_what_the_library_refused_is_named_by_the_files_key(
        doc: str, path: tuple[Any, ...], value: Any, expected: str) -> None:
    """Refusals that came from the library's constructors, with their names
    (``building[0]: building 'B1': floors[0] = -1 …``, ``mode_i and mode_j must differ``,
    ``storey_law: beta, gamma: …``), are found in the file and named by its keys."""
    with pytest.raises(ValueError) as info:
        parse_config(_replaced(MODEL_DOCS[doc], path, value), EXAMPLES, where="m.toml")
    assert str(info.value) == expected


def test_a_storey_law_in_a_message_is_written_as_in_the_file() -> None:
    """Not its ``StoreyLawConfig(...)`` repr."""
    doc = copy.deepcopy(MODEL_DOCS["matrices"])
    doc["building"][0]["storey_law"] = {"type": "bilinear", "yield_force": 2e6}
    with pytest.raises(ValueError) as info:
        parse_config(doc, EXAMPLES, where="m.toml")
    assert str(info.value) == (
        "m.toml: building[0].storey_law: not a key of a building given as matrices (a matrix "
        "building is linear: storey yielding is the shear building's) (got { type = "
        "\"bilinear\", yield_force = 2e+06 })")


def test_a_mitigation_file_name_is_not_run_into_the_key(tmp_path: Path) -> None:
    doc = copy.deepcopy(MITIGATION_DOCS["options"])
    doc["option"][2]["device"][0]["c"] = -1.0
    f = tmp_path / "study.toml"
    f.write_text(dump_toml(doc), encoding="utf-8")
    with pytest.raises(ValueError) as info:
        load_mitigation(f)
    assert str(info.value) == (f"{f}: option[2].device[0].c: must be in (0, 1e+15] "
                               "N·(s/m)^α (got -1)")


def test_an_isolator_radius_is_named_not_the_law_it_makes() -> None:
    """A radius of 1e-300 m was reported as ``alpha: must be in [0, 1) (got 1.0)``."""
    doc = _replaced(MODEL_DOCS["isolated"], ("building", 0, "isolator", "radius"), 1e-300)
    with pytest.raises(ValueError) as info:
        parse_config(doc, EXAMPLES, where="m.toml")
    assert str(info.value).startswith(
        "m.toml: building[0].isolator: radius must be > yield_displacement / mu = 0.01 m "
        "(got 1e-300)")
    with pytest.raises(ValueError, match=r"radius must be > yield_displacement / mu"):
        FrictionPendulum(radius=0.005, mu=0.05)


def test_a_device_of_every_shared_floor_is_named_by_its_table() -> None:
    """The model's devices[4] (two maxwell links made by ``floors = "all"`` before it) is
    the file's device[3]."""
    doc = _replaced(MODEL_DOCS["devices"], ("contact", "gap"), 0.0)
    with pytest.raises(ValueError) as info:
        parse_config(doc, EXAMPLES, where="m.toml")
    assert str(info.value).startswith("m.toml: device[3].thickness: ")


# ----------------------------------------------------------- numbers accepted silently before
@pytest.mark.parametrize("doc, path, value, expected", [
    ("isolated", ("building", 0, "isolator", "mu"), 2.0,
     "m.toml: building[0].isolator.mu: must be in (0, 1) (got 2)"),
    ("plan", ("record", "incidence"), 1e300,
     "m.toml: record.incidence: must be in [-360, 360] degrees (got 1e+300)"),
    ("plan", ("building", 0, "elements", 1, "direction"), 1e308,
     "m.toml: building[0].elements[1].direction: must be in [-360, 360] degrees (got 1e+308)"),
    ("sdof", ("record", "scale"), 0.0,
     "m.toml: record.scale: must not be 0: the record would not shake anything (a factor in "
     "[-1000, 1000]; negative flips the record's polarity) (got 0)"),
    ("sdof", ("building", 0, "height"), 1e300,
     "m.toml: building[0].height: must be in (0, 1000] m (got 1e+300)"),
    ("isolated", ("record", "sa_period"), 1e300,
     "m.toml: record.sa_period: must be in (0, 100] s (got 1e+300)"),
    ("devices", ("device", 3, "rubber", "delta_m"), 1e300,
     "m.toml: device[3].rubber.delta_m: must be in (0, 1000] m (got 1e+300)"),
    ("plan", ("building", 0, "plan", "mass_centres"), [30.0, 6.0],
     "m.toml: building[0].plan.mass_centres: must lie inside the plan, x in [0, 20] and y in "
     "[0, 12] m (got [30, 6])"),
    ("plan", ("building", 0, "plan", "inertias"), 1e9,
     "m.toml: building[0].plan.inertias: must be in (0, 3.4e+07] kg·m² for floor 1 (mass "
     "250000 kg, its farthest corner 11.6619 m from its centre of mass) (got 1e+09)"),
    ("plan", ("building", 0, "elements", 0, "y"), 13.0,
     "m.toml: building[0].elements[0].y: must lie inside the plan, in [0, 12] m (the plan's "
     "depth) (got 13)"),
])
def test_numbers_accepted_silently_before_are_refused_with_their_range(
        doc: str, path: tuple[Any, ...], value: Any, expected: str) -> None:
    with pytest.raises(ValueError) as info:
        parse_config(_replaced(MODEL_DOCS[doc], path, value), EXAMPLES, where="m.toml")
    assert str(info.value) == expected


def test_a_negative_scale_flips_the_record() -> None:
    """Decided: a negative scale factor is the record with its polarity reversed (a usual
    way to double a suite), not an error."""
    up = parse_config(MODEL_DOCS["sdof"], EXAMPLES).build().motion
    down = parse_config(_replaced(MODEL_DOCS["sdof"], ("record", "scale"), -1.0),
                        EXAMPLES).build().motion
    np.testing.assert_array_equal(down.accel, -up.accel)


def test_study_numbers_accepted_silently_before(tmp_path: Path) -> None:
    doc = _replaced(MITIGATION_DOCS["options"], ("records",), [])
    f = tmp_path / "s.toml"
    f.write_text(dump_toml(doc), encoding="utf-8")
    with pytest.raises(ValueError) as info:
        load_mitigation(f)
    assert str(info.value) == f"{f}: records: must hold at least 1 value(s) (got 0: [])"
    with pytest.raises(ValueError) as info:
        parse_study(_replaced(FRAGILITY_DOCS["sa"], ("bootstrap", "seed"), -1), where="s.toml")
    assert str(info.value) == "s.toml: bootstrap.seed: must be >= 0 (got -1)"


def test_the_library_refuses_the_same_angles_and_plans() -> None:
    a = GroundMotion(0.01, np.sin(np.linspace(0.0, 6.0, 101)))
    with pytest.raises(ValueError, match=r"angle must be a number of degrees in \[-360, 360\]"):
        at_incidence(a, None, 1e300)
    with pytest.raises(ValueError, match=r"an angle in \[-360, 360\] degrees \(got 1e\+308\)"):
        LateralElement(0.0, 0.0, 1e308, 1e8)
    frames = [LateralElement(0.0, 0.0, "x", 5e7), LateralElement(0.0, 10.0, "x", 5e7),
              LateralElement(0.0, 5.0, "y", 5e7), LateralElement(20.0, 5.0, "y", 1e8)]
    kw = {"masses": [4e5], "heights": [3.5], "width": 20.0, "depth": 10.0}
    with pytest.raises(ValueError, match=r"mass_centres\[0\] must lie inside the plan"):
        PlanBuilding(**kw, elements=frames, mass_centres=[1e6, 5.0])
    # all the mass at the farthest corner: m ρ² = 4e5 (10² + 5²) kg·m², and no more
    PlanBuilding(**kw, elements=frames, inertias=[4e5 * 125.0])
    with pytest.raises(ValueError, match=r"inertias\[0\] must be in \(0, 5e\+07\] kg·m²"):
        PlanBuilding(**kw, elements=frames, inertias=[4e5 * 125.0 * 1.001])
    with pytest.raises(ValueError, match=r"elements\[3\].x must lie inside the plan"):
        PlanBuilding(**kw, elements=[*frames[:3], LateralElement(25.0, 5.0, "y", 5e7)])


# ----------------------------------------------------------- plausibility warnings
PLAUSIBLE = MODEL_DOCS["sdof"]


@pytest.mark.parametrize("path, value, expected", [
    (("contact", "gap"), 40.0, "m.toml: contact.gap: 40 m is wider than 2 m, more than any "
                               "separation of buildings; is it in mm or cm?"),
    (("building", 0, "mass"), 600.0, "m.toml: building[0].mass: 600 kg is lighter than 1000 "
                                     "kg, less than any floor of a building; is it in tonnes?"),
    (("building", 1, "stiffness"), 1.2e12, "m.toml: building[1]: fundamental period T1 = "
                                           "0.003142 s is below 0.05 s, outside the range of "
                                           "buildings; is a mass in tonnes rather than kg?"),
    (("building", 1, "stiffness"), 1e3, "m.toml: building[1]: fundamental period T1 = 108.8 s "
                                        "is above 10 s, outside the range of buildings; is a "
                                        "stiffness in kN/m rather than N/m?"),
    (("record", "scale"), 10.0, "m.toml: record: peak ground acceleration 3.13 g after scale = "
                                "10 is above 3 g, more than any record; is the scaling meant?"),
])
def test_inputs_probably_in_the_wrong_unit_are_warned_of_once(path: tuple[Any, ...],
                                                              value: Any, expected: str) -> None:
    with pytest.warns(PlausibilityWarning) as caught:
        cfg = parse_config(_replaced(PLAUSIBLE, path, value), EXAMPLES, where="m.toml")
    assert [str(w.message) for w in caught] == [expected]
    assert cfg.plausibility == (expected,)


def test_a_friction_coefficient_above_0_3_is_warned_of() -> None:
    doc = _replaced(MODEL_DOCS["isolated"], ("building", 0, "isolator", "mu"), 0.5)
    with pytest.warns(PlausibilityWarning, match=r"building\[0\].isolator.mu: 0.5 is above 0.3"):
        parse_config(doc, EXAMPLES, where="m.toml")


def test_plausible_models_and_the_examples_warn_of_nothing() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", PlausibilityWarning)
        for doc in MODEL_DOCS.values():
            assert parse_config(doc, EXAMPLES).plausibility == ()
        for path in sorted(EXAMPLES.glob("*.toml")):
            if not path.name.startswith(("sweep_", "fragility_", "mitigation_", "spectrum_")):
                assert load_config(path).plausibility == (), path.name


def test_the_command_line_prints_a_warning_line_and_runs(tmp_path: Path,
                                                         capsys: pytest.CaptureFixture[str]
                                                         ) -> None:
    doc = _replaced(_replaced(PLAUSIBLE, ("contact", "gap"), 40.0), ("record", "duration"), 0.5)
    doc["solver"]["duration"] = 0.5
    model = tmp_path / "model.toml"
    model.write_text(dump_toml(doc), encoding="utf-8")
    capsys.readouterr()
    assert main(["run", str(model), "--out", str(tmp_path / "out"), "--no-figures"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert err == [f"warning: {model}: contact.gap: 40 m is wider than 2 m, more than any "
                   "separation of buildings; is it in mm or cm?"]
    assert (tmp_path / "out" / "summary.json").is_file()


@pytest.mark.parametrize("command, text, expected", [
    ("fragility", 'base = "{base}"\n[suite]\nbundled = true\n[intensity]\nmeasure = "pga"\n'
                  'levels = ["a", 0.2]\n',
     "intensity.levels[0]: must be a number (got 'a')"),
    ("fragility", 'base = "{base}"\n[suite]\nbundled = true\n[intensity]\nmeasure = "pga"\n'
                  'levels = [0.1, 0.2]\n[bootstrap]\nseed = -5\n',
     "bootstrap.seed: must be >= 0 (got -5)"),
    ("sweep", 'base = "{base}"\n[random]\nn = 2\nseed = -1\n"contact.gap" = [0.0, 0.05]\n',
     "random.seed: required, an integer >= 0 (got -1)"),
    ("mitigate", 'base = "{base}"\nrecords = []\n[[option]]\nname = "bare"\n',
     "records: must hold at least 1 value(s) (got 0: [])"),
])
def test_the_command_line_refuses_bad_study_files_in_one_line(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], command: str, text: str,
        expected: str) -> None:
    study = tmp_path / "study.toml"
    study.write_text(text.format(base=EXAMPLES / "seed_sdof_pair.toml"), encoding="utf-8")
    capsys.readouterr()
    assert main([command, str(study), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"error: {study}: {expected}"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["study.toml"]


def test_a_sweep_value_out_of_range_of_a_union_fails_in_its_row_not_as_a_wrong_type(
        tmp_path: Path) -> None:
    """``yield_force = -1`` is a number out of range (its case fails in its row, the sweep
    goes on), not "must be a list" (which refused the whole sweep as a wrong type)."""
    from pydantic import ValidationError

    from pounding.config import RunConfig, format_validation_error
    from pounding.studies.sweep import apply_overrides, load_sweep

    base = tmp_path / "model.toml"
    base.write_text(dump_toml(MODEL_DOCS["storeys"]), encoding="utf-8")
    sweep_file = tmp_path / "sweep.toml"
    sweep_file.write_text('base = "model.toml"\n[grid]\n'
                          '"building.0.storey_law.yield_force" = [-1.0, 3e6]\n')
    sweep = load_sweep(sweep_file)
    assert len(sweep.cases) == 2
    data = apply_overrides(sweep.base, sweep.params, sweep.cases[0].values)
    with pytest.raises(ValidationError) as info:
        RunConfig.model_validate(data, context={"base_dir": sweep.base_dir})
    assert format_validation_error(info.value) == (
        "building[0].storey_law.yield_force: must be in (0, 1e+13] N (got -1)")

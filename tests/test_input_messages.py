"""Messages of bad model and study files, found systematically, and the numbers that were
accepted silently.

Every key of a model file, a fragility study file and a mitigation study file (the
documents of ``model_documents.py``, which together hold every key) is given a value of the wrong kind and values out of
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
from pounding.config import dump_toml, parse_config
from pounding.config.base import Section, fmt
from pounding.ground_motion import GroundMotion
from pounding.ground_motion.incidence import at_incidence
from pounding.hysteresis.isolators import FrictionPendulum
from pounding.plausibility import PlausibilityWarning
from pounding.structure.plan import LateralElement, PlanBuilding
from pounding.studies.fragility.study import parse_study
from pounding.studies.mitigation import load_mitigation

from model_documents import (
    EXAMPLES,
    FRAGILITY_DOCS,
    MITIGATION_DOCS,
    MODEL_DOCS,
    get,
    key_text,
    replaced,
)


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
    key = key_text(path)
    parent = key_text(path[:-1]) if isinstance(path[-1], int) else key
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
            value = get(doc, path)
            for bad, ranged in ([(v, False) for v in _wrong_kind(value)]
                                + [(v, True) for v in _out_of_range(value)]):
                tried += 1
                message = message_of(replaced(doc, path, bad), tmp_path)
                if message is None:
                    if isinstance(bad, float) and abs(bad) == 1e300:
                        failures.append(f"{name}: {key_text(path)} = {fmt(bad)}: accepted")
                    continue
                for problem in _problems(name, path, bad, message, prefix, ranged):
                    failures.append(f"{name}: {key_text(path)} = {fmt(bad)}: {problem}: "
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
            parse_study(replaced(FRAGILITY_DOCS["pga"] if path[-1] == 0 else
                                  FRAGILITY_DOCS["sa"], path, value), where="s.toml")
    else:
        with pytest.raises(ValueError) as info:
            parse_config(replaced(MODEL_DOCS[doc], path, value), EXAMPLES, where="m.toml")
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
        parse_config(replaced(MODEL_DOCS[doc], path, value), EXAMPLES, where="m.toml")
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
    doc = replaced(MODEL_DOCS["isolated"], ("building", 0, "isolator", "radius"), 1e-300)
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
    doc = replaced(MODEL_DOCS["devices"], ("contact", "gap"), 0.0)
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
        parse_config(replaced(MODEL_DOCS[doc], path, value), EXAMPLES, where="m.toml")
    assert str(info.value) == expected


def test_a_negative_scale_flips_the_record() -> None:
    """Decided: a negative scale factor is the record with its polarity reversed (a usual
    way to double a suite), not an error."""
    up = parse_config(MODEL_DOCS["sdof"], EXAMPLES).build().motion
    down = parse_config(replaced(MODEL_DOCS["sdof"], ("record", "scale"), -1.0),
                        EXAMPLES).build().motion
    np.testing.assert_array_equal(down.accel, -up.accel)


def test_study_numbers_accepted_silently_before(tmp_path: Path) -> None:
    doc = replaced(MITIGATION_DOCS["options"], ("records",), [])
    f = tmp_path / "s.toml"
    f.write_text(dump_toml(doc), encoding="utf-8")
    with pytest.raises(ValueError) as info:
        load_mitigation(f)
    assert str(info.value) == f"{f}: records: must hold at least 1 value(s) (got 0: [])"
    with pytest.raises(ValueError) as info:
        parse_study(replaced(FRAGILITY_DOCS["sa"], ("bootstrap", "seed"), -1), where="s.toml")
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


@pytest.mark.parametrize("command, text, expected", [
    ("fragility", 'base = "{base}"\n[suite]\nbundled = true\n[intensity]\nmeasure = "pga"\n'
                  'levels = ["a", 0.2]\n',
     "intensity.levels[0]: must be a number (got 'a')"),
    ("fragility", 'base = "{base}"\n[suite]\nbundled = true\n[intensity]\nmeasure = "pga"\n'
                  'levels = [0.1, 0.2]\n[bootstrap]\nseed = -5\n',
     "bootstrap.seed: must be >= 0 (got -5)"),
    ("sweep", 'base = "{base}"\n[random]\nn = 2\nseed = -1\n"contact.gap" = [0.0, 0.05]\n',
     "random.seed: must be >= 0 (got -1)"),
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
    assert format_validation_error(info.value, root=RunConfig) == (
        "building[0].storey_law.yield_force: must be in (0, 1e+13] N (got -1)")

"""Warnings of inputs that are valid but probably in the wrong unit (a gap of 40 m, a floor
of 600 kg, T1 below 0.05 s or above 10 s, a PGA above 3 g, a friction coefficient above
0.3): a :class:`~pounding.plausibility.PlausibilityWarning` in Python, kept in
``RunConfig.plausibility``, and one ``warning:`` line on the command line, which goes on;
none for the examples and plausible models."""

from __future__ import annotations

import json
import warnings
from pathlib import Path
from typing import Any

import pytest

from pounding.cli import main
from pounding.config import dump_toml, load_config, parse_config
from pounding.example_files import example_kind
from pounding.plausibility import PlausibilityWarning

from model_documents import EXAMPLES, MODEL_DOCS, replaced

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
        cfg = parse_config(replaced(PLAUSIBLE, path, value), EXAMPLES, where="m.toml")
    assert [str(w.message) for w in caught] == [expected]
    assert cfg.plausibility == (expected,)


def test_a_friction_coefficient_above_0_3_is_warned_of() -> None:
    doc = replaced(MODEL_DOCS["isolated"], ("building", 0, "isolator", "mu"), 0.5)
    with pytest.warns(PlausibilityWarning, match=r"building\[0\].isolator.mu: 0.5 is above 0.3"):
        parse_config(doc, EXAMPLES, where="m.toml")


def test_plausible_models_and_the_examples_warn_of_nothing() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", PlausibilityWarning)
        for doc in MODEL_DOCS.values():
            assert parse_config(doc, EXAMPLES).plausibility == ()
        for path in sorted(EXAMPLES.glob("*.toml")):
            if example_kind(path.name) == "model":
                assert load_config(path).plausibility == (), path.name


def test_the_command_line_prints_a_warning_line_and_runs(tmp_path: Path,
                                                         capsys: pytest.CaptureFixture[str]
                                                         ) -> None:
    doc = replaced(replaced(PLAUSIBLE, ("contact", "gap"), 40.0), ("record", "duration"), 0.5)
    doc["solver"]["duration"] = 0.5
    model = tmp_path / "model.toml"
    model.write_text(dump_toml(doc), encoding="utf-8")
    capsys.readouterr()
    assert main(["run", str(model), "--out", str(tmp_path / "out"), "--no-figures"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert err == [f"warning: {model}: contact.gap: 40 m is wider than 2 m, more than any "
                   "separation of buildings; is it in mm or cm?"]
    summary = json.loads((tmp_path / "out" / "summary.json").read_text(encoding="utf-8"))
    assert summary["warnings"] == [err[0].removeprefix("warning: ")]


@pytest.mark.parametrize("path, value, expected", [
    (("bridge", "joint", 0, "seat_width"), 600.0,
     "m.toml: bridge.joint[0].seat_width: 600 m is wider than 3 m, more than any seat of a "
     "bridge; is it in mm or cm?"),
    (("bridge", "abutment_seat_widths"), [0.75, 75.0],
     "m.toml: bridge.abutment_seat_widths[1]: 75 m is wider than 3 m, more than any seat of a "
     "bridge; is it in mm or cm?"),
    (("bridge", "joint", 0, "gap"), 25.0,
     "m.toml: bridge.joint[0].gap: 25 m is wider than 2 m, more than any joint of a bridge; "
     "is it in mm or cm?"),
    (("bridge", "abutment_gaps"), [50.0, 0.05],
     "m.toml: bridge.abutment_gaps[0]: 50 m is wider than 2 m, more than any joint of a "
     "bridge; is it in mm or cm?"),
])
def test_a_bridge_gap_or_seat_in_the_wrong_unit_is_warned_of(path: tuple[Any, ...], value: Any,
                                                             expected: str) -> None:
    """A bridge's joint and abutment gaps and its seat widths in mm or cm written as m (the
    gaps were not checked before: no warning)."""
    import tomllib

    doc = tomllib.loads((EXAMPLES / "bridge_two_frames.toml").read_text(encoding="utf-8"))
    with pytest.warns(PlausibilityWarning) as caught:
        cfg = parse_config(replaced(doc, path, value), EXAMPLES, where="m.toml")
    assert [str(w.message) for w in caught] == [expected]
    assert cfg.plausibility == (expected,)

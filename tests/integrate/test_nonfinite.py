"""No run ends with NaN where a number belongs: inputs far outside any building (a storey
stiffness of 1e300 N/m, a record of 1e200 g, a floor's centre of mass far outside its plan,
a link spring of 1e300 N/m) are refused before the run in one line naming them, and a state
that overflows during a run ends it with one line naming the likely input — in the library
(a ``ValueError``), and exit status 2 with nothing written from every command that
simulates (``run``, ``gap``, ``fragility``, ``mitigate``; a sweep records the line in the
case's error column). Before, each of these exited 0 with NaN energies and "0 impacts"."""

from __future__ import annotations

import dataclasses
import math
import warnings
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pounding import PoundingModel, simulate
from pounding.cli import main
from pounding.devices import Link
from pounding.ground_motion import GroundMotion, el_centro
from pounding.hysteresis import BoucWen
from pounding.integrate import IntegrationError
from pounding.model import ContactSpec
from pounding.structure import ShearBuilding
from pounding.structure.plan import LateralElement, PlanBuilding

KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)
SHORT = el_centro().trimmed(2.0)


def _pair(left: ShearBuilding, **kw) -> PoundingModel:
    return PoundingModel([left, ShearBuilding.uniform(3, 3e5, 3e8)], [0.02], KV, **kw)


def test_a_storey_stiffness_far_outside_any_building_is_refused_in_one_line():
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # (no overflow warning from the damping matrix)
        model = _pair(ShearBuilding.uniform(3, 2e5, 1e300))
        period = 2 * math.pi / math.sqrt(4e300 / 2e5)  # ~ the highest mode, Gershgorin
        with pytest.raises(ValueError, match=r"^building B1: a storey stiffness of 1e\+300 N/m "
                                             r"\(storey 1\) and a floor mass of 2e\+05 kg .* "
                                             r"period of 1\.\d+e-147 s, below 1e-06 of the "
                                             r"0\.001 s output step") as info:
            simulate(model, SHORT)
    # the period shown is the undamped one of the stiffest DOF (its matrices overflow)
    shown = float(str(info.value).split("period of ")[1].split(" s")[0])
    assert period <= shown <= 2 * period


def test_a_link_spring_far_outside_any_building_is_refused_in_one_line():
    model = _pair(ShearBuilding.uniform(3, 2e5, 2e8),
                  devices=[Link(("B1F3", "B2F3"), "kelvin", k=1e300, c=1.0)])
    with pytest.raises(ValueError, match=r"^link B1F3-B2F3: a spring of 1e\+300 N/m between "
                                         r"floor masses of 2e\+05 kg and 3e\+05 kg rings with "
                                         r"a period of .* s, below 1e-06"):
        simulate(model, SHORT)


def test_a_floor_centre_of_mass_outside_its_plan_is_refused():
    k = [1e8, 1e8]
    with pytest.raises(ValueError, match=r"^mass_centres\[0\] must lie inside the plan, x in "
                                         r"\[0, 12\] and y in \[0, 10\] m \(got \[1e\+06, 5\]\)"):
        PlanBuilding(masses=[2e5, 2e5], heights=[3.0, 3.0], width=12.0, depth=10.0,
                     mass_centres=[1e6, 5.0],
                     elements=[LateralElement(6.0, 0.0, "x", k), LateralElement(6.0, 10.0, "x", k),
                               LateralElement(0.0, 5.0, "y", k), LateralElement(12.0, 5.0, "y", k)])


def _overflowing_record(start: float) -> GroundMotion:
    """El Centro's first 2 s with samples of 1e200 g from ``start`` [s] on."""
    accel = SHORT.accel.copy()
    accel[int(round(start / SHORT.dt)):] = 1e200 * 9.80665
    return GroundMotion(SHORT.dt, accel, name="overflowing")


@pytest.mark.parametrize("stepping", ["exact", "rk"])
def test_a_state_that_overflows_ends_the_run_with_one_line(stepping):
    # exact steps check the viscous work (which sums every entry of the state and the
    # input) once a step; adaptive steps every energy once a grid step, and a step whose
    # error is not a finite number however short
    model = _pair(ShearBuilding.uniform(3, 2e5, 2e8))
    with pytest.raises(IntegrationError, match=r"^solver: the state stopped being finite "
                                               r"numbers \(an overflow\) at t = [01]\.\d{4} s: "
                                               r"check the stiffness, mass, damping and record "
                                               r"values \(the record's PGA is 9\.81e\+200 m/s² "
                                               r"\(1e\+200 g\); the fastest DOF") as info:
        simulate(model, _overflowing_record(1.0), free_stepping=stepping)
    t = float(str(info.value).split("at t = ")[1].split(" s")[0])
    assert 0.98 <= t <= 1.02
    assert "\n" not in str(info.value)


def test_a_yielding_model_that_overflows_ends_the_run_with_one_line():
    yielding = dataclasses.replace(ShearBuilding.uniform(3, 2e5, 2e8),
                                   storey_law=BoucWen(yield_force=2e5))
    with pytest.raises(IntegrationError, match=r"^solver: the state stopped being finite"):
        simulate(_pair(yielding), _overflowing_record(0.5))


MODEL = """[record]
{record}
[[building]]
n_storeys = 3
mass = 2e5
stiffness = {k}
[[building]]
n_storeys = 3
mass = 3e5
stiffness = 3e8
[contact]
law = "kelvin-voigt"
k = 9.3e8
e = 0.65
gap = 0.02
[solver]
duration = 2.0
"""


def _at2(path: Path, value: float) -> Path:
    path.write_text("PEER\nmade up\nUNITS OF G\nNPTS=   200, DT= .01000 SEC\n"
                    + "\n".join(" ".join([f"{value:.6E}"] * 5) for _ in range(40)) + "\n")
    return path


@pytest.fixture()
def bad_models(tmp_path: Path) -> dict[str, Path]:
    _at2(tmp_path / "big.AT2", 1e200)
    _at2(tmp_path / "big2.AT2", -1e200)
    files = {"stiffness": MODEL.format(record='bundled = "el_centro"', k="1e300"),
             "record": MODEL.format(record='file = "big.AT2"', k="2e8")}
    out = {}
    for name, text in files.items():
        out[name] = tmp_path / f"{name}.toml"
        out[name].write_text(text)
    return out


def _one_error_line(capsys) -> str:
    """The one error line on stderr (after any plausibility ``warning:`` lines: a record
    of 1e200 g is warned of as well)."""
    err = [line for line in capsys.readouterr().err.strip().splitlines()
           if not line.startswith("warning: ")]
    assert len(err) == 1, err
    return err[0]


@pytest.mark.parametrize("which, expect", [
    # a model file's stiffness is refused by its range before anything is built
    ("stiffness", "error: {folder}/stiffness.toml: building[0].stiffness: must be in (0, "
                  "1e+15] N/m (got 1e+300)"),
    ("record", "error: solver: the state stopped being finite numbers"),
])
def test_run_and_gap_exit_2_with_one_line_and_write_nothing(which, expect, bad_models, capsys):
    folder = bad_models[which].parent
    before = sorted(p.name for p in folder.iterdir())
    capsys.readouterr()
    assert main(["run", str(bad_models[which]), "--out", str(folder / "out"),
                 "--no-figures"]) == 2
    expect = expect.format(folder=folder)
    assert _one_error_line(capsys).startswith(expect)
    assert main(["gap", str(bad_models[which])]) == 2
    assert _one_error_line(capsys).startswith(expect)
    assert sorted(p.name for p in folder.iterdir()) == before


def test_mitigate_and_fragility_exit_2_with_one_line_and_write_nothing(bad_models, capsys):
    folder = bad_models["stiffness"].parent
    (folder / "mit.toml").write_text('name = "m"\nbase = "stiffness.toml"\n'
                                     'records = ["el_centro"]\n[[option]]\nname = "bare"\n')
    (folder / "frag.toml").write_text(
        'name = "f"\nbase = "stiffness.toml"\n[suite]\nfiles = ["big.AT2", "big2.AT2"]\n'
        '[intensity]\nmeasure = "pga"\nlevels = [0.1, 0.2]\n[[limit_state]]\n'
        'demand = "pounding"\n[run]\nscheduler = "synchronous"\n')
    before = sorted(p.name for p in folder.iterdir())
    capsys.readouterr()
    assert main(["mitigate", str(folder / "mit.toml"), "--out", str(folder / "m-out")]) == 2
    assert "building[0].stiffness: must be in (0, 1e+15] N/m (got 1e+300)" in _one_error_line(
        capsys)
    assert main(["fragility", str(folder / "frag.toml"), "--out", str(folder / "f-out")]) == 2
    assert "building[0].stiffness: must be in (0, 1e+15] N/m (got 1e+300)" in _one_error_line(
        capsys)
    assert sorted(p.name for p in folder.iterdir()) == before


def test_a_sweep_records_the_line_in_the_error_column(bad_models, capsys):
    folder = bad_models["stiffness"].parent
    (folder / "good.toml").write_text(MODEL.format(record='bundled = "el_centro"', k="2e8"))
    (folder / "sweep.toml").write_text('name = "s"\nbase = "good.toml"\n[grid]\n'
                                       '"building.0.stiffness" = [2e8, 1e300]\n')
    assert main(["sweep", str(folder / "sweep.toml"), "--out", str(folder / "s-out"),
                 "--scheduler", "synchronous"]) == 0
    table = pd.read_parquet(folder / "s-out" / "results.parquet")
    assert list(table["status"]) == ["ok", "error"]
    assert table["error"].iloc[1].startswith("building[0].stiffness: must be in (0, 1e+15] N/m "
                                             "(got 1e+300)")
    # the case that ran has finite numbers everywhere a number belongs
    numbers = table.iloc[0].drop(["status", "error"])
    numeric = pd.to_numeric(numbers, errors="coerce").dropna()
    assert len(numeric) > 5 and np.all(np.isfinite(numeric.to_numpy(dtype=float)))


def test_an_exact_step_that_overflows_is_refused_before_the_run(monkeypatch):
    # the matrix exponential of a building stiff enough to overflow it, yet not refused by
    # its period: stood in for by a propagator with an infinity in it
    import pounding.integrate as integrate
    from pounding.integrate.propagator import free_step

    def overflowing(*args):
        fs = free_step(*args)
        ops = fs.ops.copy()
        ops[0, 0] = np.inf
        return fs._replace(ops=ops)

    monkeypatch.setattr(integrate, "free_step", overflowing)
    model = _pair(ShearBuilding.uniform(3, 2.1e5, 2e8))  # (a model no other test has run)
    with pytest.raises(IntegrationError, match=r"^solver: the exact step over 0\.001 s "
                                               r"overflowed \(its matrix exponential is not "
                                               r"finite\): check the stiffness"):
        simulate(model, SHORT)

"""Model files with a flexible base (``foundation = {...}``): the example builds what the file
says, a matrix building and a rectangle take one too, and bad input is one line naming the
key."""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from pounding.config import parse_config
from pounding.config.load import load_config
from pounding.structure.foundation import FlexibleBaseBuilding, Footing, Soil

ROOT = Path(__file__).resolve().parents[1]


def on_soil() -> dict[str, Any]:
    return {
        "name": "ssi",
        "record": {"bundled": "el_centro"},
        "building": [{"n_storeys": 3, "mass": 3e5, "period": 0.4, "height": 3.0,
                      "foundation": {"length": 12.0, "width": 8.0, "mass": 5e5,
                                     "inertia": 6e6,
                                     "soil": {"vs": 200.0, "density": 1900.0,
                                              "poisson": 0.4, "shaking": 0.15}}},
                     {"mass": 3e5, "period": 0.6, "height": 3.0}],
        "contact": {"law": "kelvin-voigt", "k": 1e9, "e": 0.5, "gap": 0.02},
    }


def error_of(data: dict[str, Any]) -> str:
    with pytest.raises(ValueError) as info:
        parse_config(data, where="m.toml").build()
    return str(info.value)


def test_the_example_and_a_rectangle_build_what_the_file_says() -> None:
    model, _, _ = load_config(ROOT / "examples" / "ssi_sdof.toml").build()
    a = model.buildings[0]
    assert isinstance(a, FlexibleBaseBuilding)
    assert a.foundation.footing == Footing(radius=5.0)
    assert a.foundation.soil == Soil(150.0, 1800.0, 0.33)
    model, _, _ = parse_config(on_soil(), where="m.toml").build()
    a = model.buildings[0]
    assert isinstance(a, FlexibleBaseBuilding) and a.n == 5
    assert a.labels == ("F1", "F2", "F3", "Fdn", "Fdn_r")
    assert a.foundation.soil.modulus_ratio == pytest.approx(0.65)
    assert np.array_equal(np.diag(a.mass_matrix())[3:], [5e5, 6e6])
    # contacts only between the floors, never at the footing
    assert {c.label for c in model.contacts} == {"B1F1-B2F1"}


def test_a_matrix_building_takes_a_flexible_base(tmp_path: Path) -> None:
    np.savetxt(tmp_path / "M.csv", np.diag([2e5, 2e5]), delimiter=",")
    np.savetxt(tmp_path / "K.csv", [[6e7, -2e7], [-2e7, 2e7]], delimiter=",")
    data = on_soil()
    data["building"][0] = {"matrices": {"M": str(tmp_path / "M.csv"),
                                        "K": str(tmp_path / "K.csv")},
                           "elevations": [3.0, 6.0],
                           "foundation": {"radius": 4.0,
                                          "soil": {"vs": 200.0, "density": 1900.0,
                                                   "poisson": 0.3}}}
    model, _, _ = parse_config(data, where="m.toml").build()
    # the same building given storey by storey on the same footing: the same matrices
    same = {"masses": [2e5, 2e5], "stiffnesses": [4e7, 2e7], "heights": [3.0, 3.0],
            "foundation": data["building"][0]["foundation"]}
    shear, _, _ = parse_config({**data, "building": [same, data["building"][1]]},
                               where="m.toml").build()
    a, b = model.buildings[0], shear.buildings[0]
    assert isinstance(a, FlexibleBaseBuilding) and isinstance(b, FlexibleBaseBuilding)
    for x, y in ((a.mass_matrix(), b.mass_matrix()), (a.stiffness_matrix(),
                                                      b.stiffness_matrix()),
                 (a.damping_matrix(), b.damping_matrix())):
        assert np.allclose(x, y, rtol=1e-12, atol=1e-9 * np.abs(y).max())
    assert a.foundation.storey_stiffnesses == pytest.approx([4e7, 2e7], rel=1e-12)


@pytest.mark.parametrize("change, expected", [
    (("radius", 3.0), "building[0].foundation.length: give radius (a circle) or length and "
                      "width (a rectangle), not both"),
    (("width", None), "building[0].foundation.width: required"),
    (("soil", {"vs": 200.0, "density": 1900.0, "poisson": 0.5}),
     "building[0].foundation.soil.poisson: must be in [0, 0.5) (got 0.5)"),
    (("soil", {"vs": 200.0, "density": 1900.0, "poisson": 0.3, "shaking": 0.05}),
     "building[0].foundation.soil.shaking: must be in [0.1, 0.3] (got 0.05)"),
    (("mass", -1.0), "building[0].foundation.mass: must be in [0, 1e+12] kg (got -1)"),
])
def test_bad_foundations_are_one_line(change: tuple[str, Any], expected: str) -> None:
    data = copy.deepcopy(on_soil())
    key, value = change
    if value is None:
        del data["building"][0]["foundation"][key]
    else:
        data["building"][0]["foundation"][key] = value
    message = error_of(data)
    assert expected in message and "\n" not in message


def test_a_yielding_building_needs_a_footing_with_mass_and_inertia() -> None:
    """A yielding building's footing must be a degree of freedom (no static condensation of
    a nonlinear building): without its mass, or its inertia, one line names the key."""
    data = on_soil()
    data["building"][0]["storey_law"] = {"type": "bilinear", "yield_force": 1e6}
    model, _, _ = parse_config(data, where="m.toml").build()  # (with both: it builds)
    assert model.buildings[0].yielding == (0, 1, 2)
    del data["building"][0]["foundation"]["mass"]
    message = error_of(data)
    assert "building[0].foundation.mass: a yielding building's footing needs its mass" in \
        message and "\n" not in message
    data["building"][0]["foundation"]["mass"] = 2e5
    del data["building"][0]["foundation"]["inertia"]
    assert "building[0].foundation.inertia: a yielding building's footing needs its " \
           "inertia" in error_of(data)
    data["building"][0]["isolator"] = {"law": "friction-pendulum", "radius": 2.0,
                                       "mu": 0.05, "base_mass": 1e5}
    data["building"][0].pop("storey_law")
    assert "building[0].foundation: not under a base-isolated building" in error_of(data)

"""Model files with base isolation (``isolator``) and moat walls (``[[wall]]``): the example
builds what the file says, and bad input is one line naming the key."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from pounding.config import parse_config
from pounding.config.load import load_config
from pounding.hysteresis import BoucWen
from pounding.hysteresis.isolators import GRAVITY
from pounding.structure.isolation import SuperstructureDamping

ROOT = Path(__file__).resolve().parents[1]


def isolated() -> dict[str, Any]:
    return {
        "name": "iso",
        "record": {"bundled": "el_centro"},
        "building": [{"n_storeys": 3, "mass": 3e5, "period": 0.4, "height": 3.0,
                      "isolator": {"law": "friction-pendulum", "radius": 2.0, "mu": 0.05,
                                   "base_mass": 4e5}}],
        "wall": [{"height": 1.0, "gap": 0.1}],
        "contact": {"law": "kelvin-voigt", "k": 1e9, "e": 0.5},
    }


def error_of(data: dict[str, Any]) -> str:
    with pytest.raises(ValueError) as info:
        parse_config(data, where="m.toml")
    return str(info.value)


def test_the_example_builds_an_isolated_building_between_two_walls():
    model, motion, _ = load_config(ROOT / "examples" / "isolated_moat_wall.toml").build()
    (b,) = model.buildings
    assert b.n == 6 and b.yielding == (0,) and isinstance(b.storey_law, BoucWen)
    assert isinstance(b.damping, SuperstructureDamping)
    # the friction pendulum carries the whole building: mu W = (1 - alpha) F_y
    W = GRAVITY * b.total_mass
    assert (1 - b.storey_law.alpha) * b.storey_law.yield_force == pytest.approx(0.05 * W)
    assert b.storey_law.alpha * b.stiffnesses[0] == pytest.approx(W / 2.0)
    # the superstructure's fixed-base period is the file's 0.5 s
    from pounding.structure.modal import eigenmodes
    omega, _ = eigenmodes(b.mass_matrix()[1:, 1:], b.stiffness_matrix()[1:, 1:])
    assert 2 * np.pi / omega[0] == pytest.approx(0.5, rel=1e-9)
    assert [c.label for c in model.contacts] == ["W-B1F1", "B1F1-W"]
    assert [c.gap for c in model.contacts] == [0.15, 0.15]
    assert motion.pga_g == pytest.approx(0.8)


def test_bilinear_isolator_from_a_file():
    data = isolated()
    data["building"][0]["isolator"] = {"law": "bilinear", "pre_yield_stiffness": 1.2e8,
                                       "post_yield_stiffness": 1.2e7,
                                       "characteristic_strength": 5e5, "base_mass": 4e5,
                                       "base_height": 1.2, "damping": 1e4}
    model, _, _ = parse_config(data).build()
    b = model.buildings[0]
    assert b.stiffnesses[0] == 1.2e8 and b.storey_law.hardening == pytest.approx(0.1)
    assert b.yield_forces[0] == pytest.approx(5e5 / 0.9)
    assert b.floor_levels[0] == pytest.approx(1.2)
    assert b.damping_matrix()[0] @ np.ones(b.n) == pytest.approx(1e4)


@pytest.mark.parametrize("change, message", [
    (lambda d: d["building"][0].update(storey_law={"type": "bilinear", "yield_force": 1e5}),
     "building[0].isolator: a base-isolated building's superstructure stays linear"),
    (lambda d: d["building"][0]["isolator"].pop("radius"),
     "building[0].isolator.radius: required for the friction-pendulum isolator"),
    (lambda d: d["building"][0]["isolator"].update(hardening=0.1),
     "building[0].isolator.hardening"),
    (lambda d: d["building"][0]["isolator"].update(characteristic_strength=1e5),
     "building[0].isolator.characteristic_strength: not a constant of the friction-pendulum"),
    (lambda d: d["building"][0]["isolator"].update(mu=1.5),
     "building[0].isolator.mu"),
    (lambda d: d.pop("contact"), "contact: required with a [[wall]]"),
    (lambda d: (d["wall"][0].update(height=0.5), d["contact"].update(floor_to_column=False)),
     "wall[0]: no floor of B1 at or below"),
    (lambda d: d["wall"][0].update(side="up"), "wall[0].side"),
    (lambda d: d["wall"].append({"height": 1.0, "gap": 0.1}),
     "wall[1]: a second wall on the right"),
])
def test_bad_isolation_input_names_the_key(change, message):
    data = isolated()
    change(data)
    text = error_of(data) if "wall[0]: no" not in message and "second" not in message \
        else _build_error(data)
    assert message in text
    assert "\n" not in text.strip() or text.count("\n") <= 2


def _build_error(data: dict[str, Any]) -> str:
    with pytest.raises(ValueError) as info:
        parse_config(data, where="m.toml").build()
    return str(info.value)

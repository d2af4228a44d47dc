"""Model and study files that together hold every key of their kind (each valid as it
stands), and helpers to change one key: the documents of ``test_input_messages.py`` and
``test_plausibility.py``."""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
"""Where relative paths of the documents start (the example matrix files are there)."""

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
                                    "code": "asce7-22"}},
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



def key_text(path: tuple[Any, ...]) -> str:
    """``("building", 0, "mass")`` as the file names it: ``building[0].mass``."""
    out = ""
    for p in path:
        out += f"[{p}]" if isinstance(p, int) else ("." if out else "") + str(p)
    return out


def get(doc: Any, path: tuple[Any, ...]) -> Any:
    """The value at ``path``."""
    for p in path:
        doc = doc[p]
    return doc


def replaced(doc: dict[str, Any], path: tuple[Any, ...], value: Any) -> dict[str, Any]:
    """A copy of ``doc`` with ``value`` at ``path``."""
    new = copy.deepcopy(doc)
    get(new, path[:-1])[path[-1]] = value
    return new


def two_storey_pair(ka: float = 4.0e7, kb: float = 8.0e7, mass: float = 1.0e5,
                    gap: float = 0.05, extra: str = "") -> str:
    """The code checks' worked-example model file (docs/codes.md): two 2-storey shear
    buildings A and B, every floor ``mass`` [kg], storeys ``ka``/``kb`` [N/m] of 3 m, 5 %
    Rayleigh damping, a linear spring contact ``gap`` [m] apart; ``extra``: TOML appended
    (a ``[solver]`` section, say)."""
    building = """[[building]]
name = "{name}"
n_storeys = 2
mass = {mass!r}
stiffness = {k!r}
height = 3.0
damping = {{ rayleigh = [0.05, 0.05], modes = [1, 2] }}
"""
    return ('name = "two 2-storey buildings"\n[record]\nbundled = "el_centro"\n'
            + building.format(name="A", mass=mass, k=ka)
            + building.format(name="B", mass=mass, k=kb)
            + f'[contact]\nlaw = "linear-spring"\nk = 1.0e9\ngap = {gap!r}\n' + extra)

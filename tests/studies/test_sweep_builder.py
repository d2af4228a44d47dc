"""The cases of a sweep put together from what earlier cases built (CaseBuilder): the same
model, motion and solver options as a case validated and built alone, the same errors,
and parts shared only between cases with equal values (of the same types)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from pydantic import ValidationError

from pounding.config import RunConfig
from pounding.integrate import simulate
from pounding.studies.sweep import apply_overrides, parse_sweep
from pounding.studies.sweep.builder import CaseBuilder, case_builder
from pounding.studies.sweep.measures import result_row

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "examples" / "seed_sdof_pair.toml"
PARAMS = ("contact.gap", "contact.e", "record.scale", "record.duration", "solver.rtol")


def _alone(sweep, values):
    """The case validated and built on its own, as before any sharing."""
    data = apply_overrides(sweep.base, sweep.params, values)
    return RunConfig.model_validate(data, context={"base_dir": sweep.base_dir}).build()


def _sweep():
    return parse_sweep({"base": str(BASE), "grid": {p: [1.0e-8 if p == "solver.rtol" else 1.0]
                                                    for p in PARAMS}})


def test_shared_parts_give_the_case_built_alone() -> None:
    sweep = _sweep()
    builder = CaseBuilder(sweep.base, sweep.base_dir, sweep.params)
    cases = [(0.01, 0.5, 1.0, 2.0, 1e-8), (0.01, 0.5, 2.0, 2.0, 1e-8),  # record changes
             (0.02, 0.5, 2.0, 2.0, 1e-8),  # model changes, record seen
             (0.01, 0.5, 1.0, 2.0, 1e-7),  # solver changes
             (0.01, 0.5, 1.0, 2.0, 1e-8)]  # every part seen
    built = [builder.build(v) for v in cases]
    assert built[1].model is built[0].model and built[4].model is built[0].model
    assert built[2].model is not built[0].model
    assert built[4].motion is built[0].motion and built[2].motion is built[1].motion
    for values, b in zip(cases, built):
        model, motion, solver = _alone(sweep, values)
        assert solver == b.solver
        assert np.array_equal(motion.accel, b.motion.accel) and motion.dt == b.motion.dt
        assert model.gaps == b.model.gaps and model.contact == b.model.contact
        assert (result_row(simulate(model, motion, **solver))
                == result_row(simulate(b.model, b.motion, **b.solver)))


def test_a_bad_value_fails_as_it_would_alone() -> None:
    sweep = _sweep()
    builder = CaseBuilder(sweep.base, sweep.base_dir, sweep.params)
    builder.build((0.01, 0.5, 1.0, 2.0, 1e-8))
    for bad in ((0.01, 0.5, 1.0, -2.0, 1e-8),  # the model seen, the record bad
                (0.01, 1.5, 1.0, 2.0, 1e-8),  # the record seen, the model bad
                (0.01, 0.5, 1.0, 2.0, 2.0)):  # the solver bad
        with pytest.raises(ValidationError) as shared:
            builder.build(bad)
        with pytest.raises(ValidationError) as alone:
            _alone(sweep, bad)
        assert str(shared.value) == str(alone.value)
    # a failed case leaves nothing behind: the good case still builds from its parts
    assert builder.build((0.01, 0.5, 1.0, 2.0, 1e-8)).model is not None


def test_values_of_other_types_are_other_keys(tmp_path: Path) -> None:
    """1 and 1.0 (and 0.0 and -0.0) are equal in Python, not in a model file: an integer
    key refuses 2.0, so a case of 2.0 must not reuse the model of 2."""
    sweep = parse_sweep({"base": {"record": {"bundled": "el_centro", "duration": 1.0},
                                  "building": [{"n_storeys": 2, "mass": 1e5, "period": 0.4},
                                               {"mass": 1e5, "period": 0.8}],
                                  "contact": {"law": "linear-spring", "k": 1e8, "gap": 0.01}},
                         "list": {"building.0.n_storeys": [2, 3]}}, base_dir=tmp_path)
    builder = CaseBuilder(sweep.base, sweep.base_dir, sweep.params)
    assert builder.build((2,)).model.n_dof == 3
    with pytest.raises(ValidationError, match="n_storeys"):
        builder.build((2.0,))


def test_one_builder_per_sweep_with_its_own_copy_of_the_base() -> None:
    sweep = _sweep()
    base = apply_overrides(sweep.base, (), ())
    b1 = case_builder(base, sweep.base_dir, sweep.params)
    assert case_builder(base, str(sweep.base_dir), list(sweep.params)) is b1
    base["contact"]["k_h"] = 1.0e9  # another base: another builder, the first unchanged
    assert case_builder(base, sweep.base_dir, sweep.params) is not b1
    assert b1.base["contact"]["k_h"] == sweep.base["contact"]["k_h"]

"""What the cases of a sweep share in one process: the bounded memo, and that each memo is
keyed on everything that decides its value (no stale building, record, law or system when
a case changes a parameter)."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from pounding.config import parse_config
from pounding.config.building import BuildingConfig
from pounding.config.record import RecordConfig
from pounding.integrate import kernel_model, simulate
from pounding.memo import Memo
from pounding.model import ContactSpec, PoundingModel

ROOT = Path(__file__).resolve().parents[1]


def test_memo_keeps_the_most_recent_within_its_bounds():
    memo = Memo(max_items=2, max_bytes=100)
    made = []

    def make(v):
        made.append(v)
        return v

    assert memo.get("a", lambda: make(1), size=lambda v: 10) == 1
    assert memo.get("a", lambda: make(99)) == 1  # remembered
    memo.get("b", lambda: make(2), size=lambda v: 10)
    memo.get("a", lambda: make(99))  # "a" is now the most recent
    memo.get("c", lambda: make(3), size=lambda v: 10)  # a third: "b" goes
    assert memo.get("b", lambda: make(4)) == 4
    assert made == [1, 2, 3, 4] and len(memo) == 2
    # bytes: a large value evicts the least recent until the rest fit ("c", 10 bytes; "b"
    # counts none); one larger than the bound is not kept
    memo.get("big", lambda: 5, size=lambda v: 95)
    assert memo.nbytes == 95 and memo.get("c", lambda: 9) == 9
    assert memo.get("huge", lambda: 6, size=lambda v: 101) == 6
    assert memo.get("huge", lambda: 7, size=lambda v: 101) == 7
    # a failure is not remembered
    with pytest.raises(ZeroDivisionError):
        memo.get("bad", lambda: 1 / 0)
    assert memo.get("bad", lambda: 8) == 8
    # find: the value if remembered (now the most recent), else None; nothing is made
    assert memo.find("nothing") is None and "nothing" not in memo._entries
    assert memo.find("bad") == 8 and list(memo._entries)[-1] == "bad"
    memo.clear()
    assert len(memo) == 0 and memo.nbytes == 0


def test_a_building_is_shared_by_equal_configurations_only():
    a = BuildingConfig(mass=2.0e5, period=0.5).build("B1")
    assert BuildingConfig(mass=2.0e5, period=0.5).build("B1") is a
    assert BuildingConfig(mass=2.0e5, period=0.5).build("B2").name == "B2"
    other = BuildingConfig(mass=2.0e5, period=0.5 + 1e-15).build("B1")
    assert other is not a and other.stiffnesses[0] != a.stiffnesses[0]
    damped = BuildingConfig(mass=2.0e5, period=0.5, damping={"ratio": 0.02}).build("B1")
    assert not np.array_equal(damped.damping_matrix(), a.damping_matrix())


def test_a_contact_law_is_shared_by_equal_specs_and_masses_only():
    spec = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)
    law = spec.build(1.0e5, 2.0e5)
    assert ContactSpec("kelvin-voigt", k=9.3e8, e=0.65).build(1.0e5, 2.0e5) is law
    assert spec.build(1.0e5, 3.0e5).params()[1] != law.params()[1]
    assert ContactSpec("kelvin-voigt", k=9.3e8, e=0.6).build(1.0e5, 2.0e5) is not law
    # 0.0 and -0.0 compare equal but are different inputs: different entries
    zero = ContactSpec("kelvin-voigt", k=9.3e8, c=0.0).build(1.0, 1.0)
    assert ContactSpec("kelvin-voigt", k=9.3e8, c=-0.0).build(1.0, 1.0) is not zero


def test_a_record_is_shared_by_equal_configurations_and_reread_when_its_file_changes(
        tmp_path):
    base = RecordConfig(bundled="el_centro", duration=5.0, scale=1.5)
    gm = base.load()
    assert RecordConfig(bundled="el_centro", duration=5.0, scale=1.5).load() is gm
    assert RecordConfig(bundled="el_centro", duration=5.0, scale=1.25).load().pga != gm.pga
    assert RecordConfig(bundled="el_centro", duration=4.0, scale=1.5).load().npts != gm.npts

    rec = tmp_path / "rec.txt"
    rec.write_text("0.0\n1.0\n2.0\n", encoding="utf-8")
    cfg = RecordConfig.model_validate({"file": "rec.txt", "dt": 0.01, "units": "m/s2"},
                                      context={"base_dir": tmp_path})
    first = cfg.load()
    assert cfg.load() is first
    rec.write_text("0.0\n3.0\n2.0\n1.0\n", encoding="utf-8")
    st = rec.stat()
    os.utime(rec, ns=(st.st_atime_ns, st.st_mtime_ns + 10**9))
    again = cfg.load()
    assert again is not first and again.npts == 4 and again.pga == 3.0
    # the same relative name in another folder is another file
    other = tmp_path / "other"
    other.mkdir()
    (other / "rec.txt").write_text("0.0\n5.0\n", encoding="utf-8")
    cfg2 = RecordConfig.model_validate({"file": "rec.txt", "dt": 0.01, "units": "m/s2"},
                                       context={"base_dir": other})
    assert cfg2.load().pga == 5.0


def test_models_of_the_same_buildings_share_their_system_and_kernel_structure():
    data = {"record": {"bundled": "el_centro", "duration": 2.0},
            "building": [{"mass": 2.0e5, "period": 0.5}, {"mass": 3.0e5, "period": 1.0}],
            "contact": {"law": "kelvin-voigt", "k": 9.3e8, "e": 0.65, "gap": 0.01}}
    m1, gm, kw = parse_config(data).build()
    data["contact"]["gap"] = 0.02
    m2, _, _ = parse_config(data).build()
    assert m1 is not m2 and m1.system is m2.system
    assert not m1.system.M.flags.writeable
    k1, k2 = kernel_model(m1), kernel_model(m2)
    assert k1.floors.k_band is k2.floors.k_band and k1.free_steps is k2.free_steps
    assert (k1.contacts.gap[0], k2.contacts.gap[0]) == (0.01, 0.02)
    # another building: its own system, and its own run
    data["building"][1]["period"] = 0.8
    m3, _, _ = parse_config(data).build()
    assert m3.system is not m1.system
    assert not np.array_equal(kernel_model(m3).floors.k_band, k1.floors.k_band)
    r2, r3 = simulate(m2, gm, **kw), simulate(m3, gm, **kw)
    assert not np.array_equal(r2.displacement, r3.displacement)


def test_a_model_run_after_others_is_bit_identical_to_a_fresh_one():
    """The memos change no result: a model built and run after others that share parts
    of it gives the same arrays as a model whose parts are all new."""
    from pounding.config.building import BUILDINGS
    from pounding.config.record import RECORDS
    from pounding.integrate.kernel_model import STRUCTURES
    from pounding.model import CONTACT_LAWS, SYSTEMS

    data = {"record": {"bundled": "el_centro", "duration": 3.0, "scale": 2.0},
            "building": [{"mass": 2.0e5, "period": 0.5}, {"mass": 3.0e5, "period": 1.0}],
            "contact": {"law": "nonlinear-viscoelastic", "k_h": 2.75e9, "e": 0.65,
                        "gap": 0.0}}
    for scale in (1.0, 2.0):
        data["record"]["scale"] = scale
        model, gm, kw = parse_config(data).build()
        shared = simulate(model, gm, **kw)
    for memo in (BUILDINGS, RECORDS, STRUCTURES, CONTACT_LAWS, SYSTEMS):
        memo.clear()
    model, gm, kw = parse_config(data).build()
    fresh = simulate(model, gm, **kw)
    for name in ("displacement", "velocity", "abs_acceleration", "contact_force", "energy",
                 "impact_array", "located_peaks"):
        assert np.array_equal(getattr(shared, name), getattr(fresh, name), equal_nan=True), name

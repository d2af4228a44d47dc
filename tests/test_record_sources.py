"""``[record] stochastic = {…}`` and ``[record] match = {…}`` in a model file: the motion is
the generator's / the matching's, called directly; a copy of the model written with its
paths resolved reads back from another folder; bad values are one line naming the key."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from pounding.config import load_config, parse_config
from pounding.ground_motion import el_centro
from pounding.ground_motion.rezaeian2010 import Scenario, stochastic_motion
from pounding.spectra import DesignSpectrum
from pounding.spectra.matching import match_record

ROOT = Path(__file__).resolve().parents[1]
TARGET = ROOT / "src" / "pounding" / "examples" / "spectrum_asce7_site.toml"

MODEL = '''[[building]]
mass = 2.0e5
period = 0.5
[[building]]
mass = 3.0e5
period = 1.0
[contact]
law = "linear-spring"
k = 1e9
gap = 0.02
[record]
'''


def test_a_stochastic_record_is_the_generators(tmp_path):
    f = tmp_path / "m.toml"
    f.write_text(MODEL + 'stochastic = { magnitude = 6.0, distance = 30.0, vs30 = 600.0, '
                         'seed = 5, index = 2, dt = 0.02 }\npga_g = 0.3\n')
    gm = load_config(f).record.load()
    own = stochastic_motion(Scenario(6.0, 30.0, 600.0), 5, 2, dt=0.02)
    np.testing.assert_allclose(gm.accel, own.accel * 0.3 / own.pga_g, rtol=1e-12, atol=1e-14)


def test_a_matched_record_is_match_records_and_its_copy_reads_from_elsewhere(tmp_path):
    shutil.copy(TARGET, tmp_path / "site.toml")
    f = tmp_path / "m.toml"
    f.write_text(MODEL + 'bundled = "el_centro"\nduration = 8.0\n'
                         'match = { target = "site.toml", range = [0.1, 2.0] }\n')
    cfg = load_config(f)
    own = match_record(el_centro().trimmed(8.0), DesignSpectrum.from_file(TARGET), (0.1, 2.0))
    np.testing.assert_allclose(cfg.record.load().accel, own.motion.accel, rtol=1e-12,
                               atol=1e-14)
    data = cfg.to_dict(resolve_paths=True)
    assert Path(data["record"]["match"]["target"]) == (tmp_path / "site.toml").resolve()
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    assert parse_config(data, base_dir=elsewhere).record.match is not None


@pytest.mark.parametrize(("record", "message"), [
    ('stochastic = { magnitude = 6.0, distance = 30.0, vs30 = 600.0 }\nbundled = "el_centro"',
     "give exactly one of bundled"),
    ('stochastic = { magnitude = 6.0, distance = 30.0, vs30 = 600.0 }\ndt = 0.01',
     "record.dt: not with stochastic"),
    ('stochastic = { magnitude = 6.0, distance = 30.0, vs30 = 60.0 }', "record.stochastic.vs30"),
    ('stochastic = { magnitude = 6.0, distance = 30.0, vs30 = 600.0, mechanism = "normal" }',
     "record.stochastic.mechanism"),
    ('bundled = "el_centro"\nmatch = { target = "none.toml" }', "record.match.target: no such"),
    ('bundled = "el_centro"\nmatch = { target = "m.toml", range = [3.0, 1.0] }',
     "record.match.range"),
])
def test_bad_record_source_is_one_line(tmp_path, record, message):
    f = tmp_path / "m.toml"
    f.write_text(MODEL + record + "\n")
    with pytest.raises(ValueError) as info:
        load_config(f)
    text = str(info.value)
    assert message in text and "\n" not in text.strip(), text

"""One spelling of the seismic codes across pounding (issue 29): ``asce7-22`` and
``en1998-1`` for ``pounding suite --code``, ``pounding code-check --code``, the scaling
library and a fragility study's ``[suite.scaling] code``; the spelling before it
(``asce7``, ``ec8``) is refused in one line that names the new key."""

from __future__ import annotations

from pathlib import Path

import pytest

from pounding.cli import main
from pounding.cli import options as opt
from pounding.ground_motion import el_centro
from pounding.spectra import DesignSpectrum, scale_suite
from pounding.studies.codes import CODES

ROOT = Path(__file__).resolve().parents[2]
TARGET = ROOT / "examples" / "spectrum_asce7_site.toml"
SEED = ROOT / "examples" / "seed_sdof_pair.toml"


def test_one_list_of_codes_for_every_code_option():
    from pounding.spectra.scaling import CODES as SCALING_CODES
    from pounding.spectra.scaling import RENAMED_CODES

    assert [c.value for c in opt.Code] == list(CODES)
    assert set(SCALING_CODES) <= set(CODES)
    assert opt.RENAMED_CODES == RENAMED_CODES


@pytest.mark.parametrize(("old", "new"), [("asce7", "asce7-22"), ("ec8", "en1998-1")])
def test_the_old_spelling_is_refused_naming_the_new_one(old, new, tmp_path, capsys):
    motion = el_centro().trimmed(2.0)
    with pytest.raises(ValueError, match=rf"^code: '{old}' is now spelled '{new}'"):
        scale_suite([motion], DesignSpectrum.asce7(1.0, 0.6), 1.0, code=old)
    capsys.readouterr()
    for argv in (["suite", "--design", str(TARGET), "--t1", "1"],
                 ["code-check", str(SEED), "--agr", "0.3", "--ground-type", "C",
                  "--spectrum-type", "1", "--q", "3"]):
        assert main([*argv, "--code", old]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and f"'{old}' is now spelled '{new}'" in err[0], err
        assert "--code" in err[0]

    from pounding.studies.fragility.study import parse_study

    study = {"base": str(SEED), "suite": {"bundled": True, "scaling": {
        "target": str(TARGET), "period": 1.0, "code": old}},
        "intensity": {"measure": "pga", "levels": [0.1, 0.2]}}
    with pytest.raises(ValueError, match=rf"code.*'{old}' is now spelled '{new}'"):
        parse_study(study)
    study["suite"]["scaling"]["code"] = new  # type: ignore[index]
    assert parse_study(study).suite.scaling.code == new  # type: ignore[union-attr]


def test_the_new_spelling_scales_as_the_old_did():
    """en1998-1 keeps the mean PGA at the target's (EN 1998-1 §3.2.3.1.2(4)b): the factor is
    at least a_g S over the mean PGA; asce7-22 has no PGA rule."""
    motion = el_centro().trimmed(5.0)
    ec8 = DesignSpectrum.eurocode8(0.3, "C", 1)
    by_ec8 = scale_suite([motion], ec8, 0.5, code="en1998-1", n_periods=20).factors[0]
    by_asce = scale_suite([motion], ec8, 0.5, code="asce7-22", n_periods=20).factors[0]
    pga_rule = float(ec8.sa_g(0.0)) / (motion.pga / 9.80665)
    assert by_ec8 == pytest.approx(max(by_asce, pga_rule), rel=1e-9)


@pytest.mark.parametrize("code", ["nzs1170.5", "nbcc2020", "is1893"])
def test_a_code_without_a_suite_rule_is_refused_by_suite_naming_the_option(code, capsys):
    """The codes code-check knows but pounding has no suite-scaling rule for: one line
    naming ``--code`` and the value, exit 2 (it said ``code:``, the library's field)."""
    capsys.readouterr()
    assert main(["suite", "--design", str(TARGET), "--t1", "1", "--code", code]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: --code:") and repr(code) in err[0], err

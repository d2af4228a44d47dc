"""The time histories beside a code check (issue 29, docs/codes.md "Beside a time
history"): each record's outcome against a separate ``simulate`` of the model with its gap
changed by hand, the peak-closing criterion by rerunning just above and just below it, the
suite's factor against ``scale_suite`` on the code's spectrum written out by hand, and the
command line (``--time-history``, ``--suite``, the ``time_history`` block, bad input)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from model_documents import two_storey_pair

from pounding.cli import main
from pounding.config import load_config
from pounding.ground_motion import bundled_suite
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.spectra import DesignSpectrum, scale_suite
from pounding.studies.codes import code_check
from pounding.studies.codes.time_history import code_spectrum, time_history_check

MODEL = two_storey_pair()
ASCE = ["--code", "asce7-22", "--sds", "1.0", "--sd1", "0.6", "--tl", "8", "--cd", "5.5",
        "--r", "8", "--ie", "1.25", "--combination", "srss"]
SECONDS = 6.0


@pytest.fixture(scope="module")
def case(tmp_path_factory):
    path = tmp_path_factory.mktemp("th") / "model.toml"
    path.write_text(MODEL, encoding="utf-8")
    model, _, solver = load_config(path).build()
    check = code_check(model, "asce7-22", sds=1.0, sd1=0.6, tl=8.0, cd=5.5, r=8.0, ie=1.25,
                       combination="srss")
    motions = [m.trimmed(SECONDS) for m in list(bundled_suite())[:4]]
    th = time_history_check(model, check, motions, solver=solver)
    return path, model, check, motions, th


def _with_gap(model, gap):
    return PoundingModel(model.buildings, [gap], model.contact, name=model.name)


def test_the_target_is_the_codes_spectrum_and_the_factor_its_rule():
    """ASCE 7-22 §11.4.6 written out here; the factor that of scale_suite with it."""
    from pounding.studies.codes.common import CodeCheck

    check = CodeCheck("asce7-22", "", "", (), {"sds_g": 1.0, "sd1_g": 0.6, "tl_s": 8.0}, (),
                      {}, {})
    spectrum = code_spectrum(check)
    for t, sa in ((0.0, 0.4), (0.06, 0.4 + 0.6 * 0.06 / 0.12), (0.3, 1.0), (1.5, 0.6 / 1.5),
                  (9.0, 0.6 * 8.0 / 81.0)):
        assert float(spectrum.sa_g(t)) == pytest.approx(sa, rel=1e-12)
    ec8 = CodeCheck("en1998-1", "", "", (), {"agr_g": 0.3, "importance": 1.2, "ag_g": 0.36,
                                             "ground_type": "C", "spectrum_type": 1}, (), {},
                    {})
    # EN 1998-1 eq. 3.3 (elastic, no q): 2.5 a_g S on the plateau, S = 1.15 (ground C)
    assert float(code_spectrum(ec8).sa_g(0.4)) == pytest.approx(2.5 * 0.36 * 1.15, rel=1e-12)


def test_factor_and_runs_are_those_of_separate_simulations(case):
    """Each record's outcome at the model's gap and at the code's equals a separate
    simulate of the record scaled by scale_suite's factor, the gap set by hand."""
    _, model, check, motions, th = case
    t1 = max(p[0] for p in check.periods.values())
    t_short = min(p[0] for p in check.periods.values())
    factors = scale_suite(motions, DesignSpectrum.asce7(1.0, 0.6, 8.0), t1,
                          code="asce7-22", period_range=(0.2 * t_short, 2 * t1)).factors
    assert list(th.factors) == pytest.approx(list(factors), rel=1e-12)
    code_gap = max(row.required for row in check.rows)
    assert code_gap == pytest.approx(0.05778, abs=1e-5)  # docs/codes.md's worked example
    assert th.code_gap("B1-B2") == pytest.approx(code_gap, rel=1e-15)
    for r, motion in enumerate(motions):
        for gap, outcome in ((0.05, th.own), (code_gap, th.at_code)):
            res = simulate(_with_gap(model, gap), motion.scaled(float(factors[r])))
            assert list(outcome.impacts[r]) == list(res.impacts_per_contact)
            assert outcome.peak_force[r] == pytest.approx(res.peak_contact_force, rel=1e-9)
    assert th.own.pounded().any() and not th.at_code.pounded().all()  # both outcomes met


def test_the_peak_closing_is_the_smallest_gap_that_prevents_pounding(case):
    """Rerun every record with the gap just above its peak closing (no impact) and just
    below (an impact, at that level)."""
    _, model, _, motions, th = case
    for r, motion in enumerate(motions):
        scaled = motion.scaled(float(th.factors[r]))
        closing = th.closing_of_pair("B1-B2")[r]
        level = int(np.argmax(th.peak_closing[r]))
        above = simulate(_with_gap(model, closing * 1.001 + 1e-6), scaled)
        below = simulate(_with_gap(model, closing * 0.999), scaled)
        assert above.n_impacts == 0, (r, closing)
        assert below.impacts_per_contact[level] > 0, (r, closing)
    # a record that does not pound at the code's gap has its peak closing below it
    pounded = th.at_code.pounded()
    closing = th.closing_of_pair("B1-B2")
    assert np.array_equal(pounded, closing > th.code_gap("B1-B2"))


def test_the_verdict_says_it_in_one_line(case):
    *_, th = case
    kept = int((~th.at_code.pounded()).sum())
    mean = 1e3 * th.closing_of_pair("B1-B2").mean()
    assert th.verdicts() == [
        (f"B1-B2: the code's 57.8 mm gap prevented pounding in {kept} of 4 records; the "
         f"records' mean peak closing {mean:.1f} mm (largest "
         f"{1e3 * th.closing_of_pair('B1-B2').max():.1f} mm)")]
    data = th.to_dict()
    assert data["pairs"][0]["records_pounding_at_code_gap"] == 4 - kept
    assert [lv["contact"] for lv in data["levels"]] == ["B1F1-B2F1", "B1F2-B2F2"]
    assert math.isclose(data["levels"][1]["required_mm"], 57.7766, rel_tol=1e-4)


def test_the_duration_suggested_is_one_that_passes():
    """The start of a record's strong shaking rounded up, not to 3 digits (13.2418 s was
    suggested as 13.2 s, then refused)."""
    from pounding.ground_motion import GroundMotion
    from pounding.studies.codes.time_history import check_duration

    t = np.arange(0.0, 30.0, 0.01)
    record = GroundMotion(0.01, np.where(t > 12.25, np.sin(2 * np.pi * t), 0.0), name="late")
    start = record.arias_time(0.05)
    with pytest.raises(ValueError, match="give at least") as refused:
        check_duration(10.0, [record])
    suggested = float(str(refused.value).split("give at least ")[1].split(" s")[0])
    assert start <= suggested < start + 0.01
    assert check_duration(suggested, [record]) == suggested


def test_factors_outside_the_suites_limits_are_flagged(case):
    """A factor outside 0.25–4 (pounding suite's flag, spectra.scaling.DEFAULT_LIMITS) adds
    one caution line and marks the record in the JSON; inside, nothing is said."""
    import dataclasses

    th = case[-1]
    far = dataclasses.replace(th, factors=np.array([7.2, 1.0, 0.2, 1.0]))
    assert list(far.factors_flagged) == [True, False, True, False]
    assert far.verdicts()[-1].startswith("caution: scale factor 0.2, 7.2 outside 0.25–4 "
                                        "for 2 of 4 records")
    assert [r["factor_flagged"] for r in far.to_dict()["records"]] == [True, False, True,
                                                                        False]
    near = dataclasses.replace(th, factors=np.array([0.25, 4.0, 1.0, 1.0]))
    assert not near.factors_flagged.any()
    assert not any(v.startswith("caution") for v in near.verdicts())


def test_cli_writes_the_time_history_block_only_with_out(case, tmp_path, capsys):
    path = case[0]
    records = tmp_path / "records"
    records.mkdir()
    bundled = Path(__file__).resolve().parents[2] / "src" / "pounding" / "data" / "records"
    for name in ("elcentro_1940_IV_ELC9_180_PEER.AT2",
                 "northridge_1994_newhall_360_RSN1044.AT2"):
        (records / name).write_bytes((bundled / name).read_bytes())
    out = tmp_path / "check"
    capsys.readouterr()
    assert main(["code-check", str(path), *ASCE, "--suite", str(records), "--duration",
                 str(SECONDS), "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "the code's 57.8 mm gap prevented pounding in" in text
    data = json.loads((out / "code_check.json").read_text(encoding="utf-8"))
    block = data["time_history"]
    assert [r["record"] for r in block["records"]] == [
        "elcentro_1940_IV_ELC9_180_PEER", "northridge_1994_newhall_360_RSN1044"]
    assert block["verdicts"][0].startswith("B1-B2: the code's 57.8 mm gap prevented")
    assert block["duration_s"] == SECONDS
    # 6 s stops before El Centro's strong shaking ends (95 % of Arias at 26.1 s): said
    ends = [m.arias_time(0.95) for m in list(bundled_suite())[:2]]
    assert block["strong_shaking_end_s"] == pytest.approx(max(ends), rel=1e-12)
    assert any(v.startswith("caution: the runs stop at 6 s") for v in block["verdicts"])
    assert "caution: the runs stop at 6 s" in text
    # --duration is the time simulated: the runs equal simulate(..., duration=SECONDS)
    model = case[1]
    for r, motion in enumerate(list(bundled_suite())[:2]):  # the two records copied
        res = simulate(_with_gap(model, 0.05), motion.scaled(block["records"][r]["factor"]),
                       duration=SECONDS)
        assert block["records"][r]["own_gap"]["impacts"] == res.n_impacts
        assert block["records"][r]["own_gap"]["peak_force_kN"] == pytest.approx(
            1e-3 * res.peak_contact_force.max(), rel=1e-9)
    assert data["levels"][1]["required_mm"] == pytest.approx(57.7766, rel=1e-4)
    # without --out nothing is written
    before = sorted(p.name for p in tmp_path.iterdir())
    assert main(["code-check", str(path), *ASCE, "--suite", str(records), "--duration",
                 "4"]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == before


@pytest.mark.parametrize(("extra", "message"), [
    (["--design", "x.toml"], "--design: the target of the suite's scaling"),
    (["--duration", "3"], "--duration: the time simulated"),
    (["--time-history", "--duration", "0"], "--duration"),
    # before the bundled Chi-Chi record's strong shaking begins (5 % of Arias at 32 s)
    (["--time-history", "--duration", "0.001"],
     "--duration: 0.001 s ends before the strong shaking of chichi_1999_TCU052_N_PEER begins"),
    (["--suite", "missing-folder"], "missing-folder"),
])
def test_bad_input_is_one_line_and_writes_nothing(case, tmp_path, capsys, extra, message):
    path = case[0]
    out = tmp_path / "check"
    capsys.readouterr()
    assert main(["code-check", str(path), *ASCE, *extra, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0], err
    assert not out.exists()


def test_a_code_without_a_suite_rule_borrows_asce7s_and_says_so(case):
    """A code pounding has no suite-scaling rule for (NZS 1170.5 §5.5 has its own): the
    suite is scaled by ASCE 7-22 §16.2.3's, and the scaling text says so; a code whose
    spectrum is not known here needs the target given."""
    import dataclasses

    _, model, check, motions, _ = case
    unknown = dataclasses.replace(check, code="some-code")
    with pytest.raises(ValueError, match=r"^design: no spectrum of some-code"):
        time_history_check(model, unknown, motions[:1])
    other = code_check(model, "nzs1170.5", z=0.4, ru=1.0, site_class="C", mu=4.0)
    got = time_history_check(model, other, motions[:1],
                             target=DesignSpectrum.asce7(1.0, 0.6, 8.0))
    assert "ASCE 7-22 §16.2.3; nzs1170.5's own rule for a suite is not in pounding" in (
        got.scaling)


def test_the_other_codes_targets_are_their_elastic_spectra(case):
    """NZS 1170.5: C(T) = C_h(T) Z R (§3.1, N = 1); NBCC 2020: S(T) read off the table at
    its own periods; IS 1893: (Z/2) I Sa/g (§6.4, soil II: 2.5 to 0.55 s, 1.36/T beyond),
    by hand."""
    from pounding.spectra.code_spectra import nzs_spectral_shape

    model = case[1]
    nzs = code_spectrum(code_check(model, "nzs1170.5", z=0.4, ru=1.3, site_class="C", mu=4.0))
    t = np.array([0.3, 1.0, 2.5])
    np.testing.assert_allclose(nzs.sa_g(t), 0.4 * 1.3 * nzs_spectral_shape(t, "C"), rtol=1e-12)
    table = [0.85, 0.75, 0.42, 0.26, 0.085, 0.03]     # g at 0.2, 0.5, 1, 2, 5, 10 s
    nbcc = code_spectrum(code_check(model, "nbcc2020", s_table=",".join(map(str, table)),
                                    rd=5.0, ro=1.5, ie=1.0))
    np.testing.assert_allclose(nbcc.sa_g(np.array([0.5, 1.0, 2.0, 5.0])), table[1:5],
                               rtol=1e-12)
    ind = code_spectrum(code_check(model, "is1893", z=0.36, importance=1.2, r=5.0,
                                   soil_type="II"))
    np.testing.assert_allclose(ind.sa_g(np.array([0.3, 1.0, 2.0])),
                               [0.18 * 1.2 * 2.5, 0.18 * 1.2 * 1.36, 0.18 * 1.2 * 0.68],
                               rtol=1e-9)


def test_a_linked_model_is_refused_before_any_table(case, tmp_path, capsys):
    """The peak closing needs the buildings apart: a model with a link between them is one
    line, exit 2, before the check's tables are printed (they were printed first)."""
    linked = tmp_path / "linked.toml"
    linked.write_text(case[0].read_text(encoding="utf-8") + """
[[device]]
type = "viscous"
floors = "all"
c = 1.0e6
""", encoding="utf-8")
    capsys.readouterr()
    assert main(["code-check", str(linked), *ASCE, "--time-history"]) == 2
    captured = capsys.readouterr()
    err = captured.err.strip().splitlines()
    assert len(err) == 1 and "link(s) tie them together" in err[0], err
    assert "separation by" not in captured.out

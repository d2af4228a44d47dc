"""`pounding fragility` on a bridge with cable restrainers: P(unseating | IM) for a seat
width and P(pounding | IM) at its joint against counts made from runs simulated here apart
from the study, the fits against SciPy, the gap the joint needs against those runs, and
the one-line refusals of a bridge's limit states."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy import optimize, stats

from pounding.cli import main
from pounding.config import RunConfig
from pounding.integrate import simulate
from pounding.studies.fragility import run_study
from pounding.studies.sweep import apply_overrides

LEVELS = [0.15, 0.3, 0.6, 1.2]
AT = 0.45  # the gap analysis' level: none of the study's, so run apart
WIDTH = 0.05  # m: the seat width of the unseating limit states
TARGET = 0.2

BASE = '''name = "two one-span frames"
[record]
bundled = "el_centro"
duration = 3.0
[contact]
law = "kelvin-voigt"
k = 1.0e9
e = 0.6
[bridge]
abutment_gaps = [0.03, 0.03]
[[bridge.frame]]
spans = [30.0]
deck_mass = 4.5e5
bearing = { type = "elastomeric", stiffness = 2.0e7, damping = 1.0e5 }
[[bridge.frame.pier]]
height = 8.0
stiffness = 4.0e7
mass = 5.0e4
[[bridge.frame]]
spans = [30.0]
deck_mass = 4.5e5
bearing = { type = "elastomeric", stiffness = 2.0e7, damping = 1.0e5 }
[[bridge.frame.pier]]
height = 8.0
stiffness = 1.5e8
mass = 5.0e4
[[bridge.joint]]
gap = 0.02
restrainer = { kind = "restrainer", k = 1.76e7, slack = 0.0127, yield_force = 1.76e6 }
'''

STUDY = f'''name = "bridge"
base = "bridge.toml"
[suite]
bundled = true
duration = 3.0
[intensity]
measure = "pga"
levels = {LEVELS}
[[limit_state]]
demand = "seat_opening"
limit = {WIDTH}
[[limit_state]]
demand = "pounding"
joint = "J1"
[[limit_state]]
demand = "seat_opening"
joint = "J1"
limit = {WIDTH}
[gap]
at = {AT}
target = {TARGET}
[bootstrap]
n = 200
[run]
scheduler = "synchronous"
'''


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    folder = tmp_path_factory.mktemp("bridge-study")
    (folder / "bridge.toml").write_text(BASE)
    (folder / "study.toml").write_text(STUDY)
    return folder, run_study(folder / "study.toml", folder / "out", figures=False)


@pytest.fixture(scope="module")
def apart(study):
    """Every record at every level run here, from the model file, without the study: the
    decks' displacements read by hand. Per record and level: the largest opening of any
    seat, the joint's opening, its impacts; and, with the joint out of reach, its largest
    closing at the output steps (at the levels and at AT)."""
    import tomllib

    folder, out = study
    base = tomllib.loads(BASE)
    records = out.cases.records
    seat = np.zeros((len(records), len(LEVELS)))
    joint = np.zeros_like(seat)
    impacts = np.zeros_like(seat)
    closing = np.zeros((len(records), len(LEVELS) + 1))
    for r, name in enumerate(records):
        for li, x in enumerate([*LEVELS, AT]):
            for far in (False, True):
                if li == len(LEVELS) and not far:
                    continue
                data = apply_overrides(base, ["record.bundled", "record.pga_g"], [name, x])
                if far:
                    data["bridge"]["joint"][0]["gap"] = 1000.0
                model, motion, solver = RunConfig.model_validate(
                    data, context={"base_dir": folder}).build()
                res = simulate(model, motion, **solver)
                u1, u2 = res.displacement[:, 0], res.displacement[:, 2]  # B1F1, B2F1
                if far:
                    closing[r, li] = (u1 - u2).max()
                    continue
                joint[r, li] = max((u2 - u1).max(), 0.0)
                seat[r, li] = max(u1.max(), joint[r, li], (-u2).max())
                labels = [c.label for c in model.contacts]
                struck = res.impact_array[:, 0].astype(int)
                impacts[r, li] = np.sum(struck == labels.index("B1F1-B2F1"))
    return seat, joint, impacts, closing


def test_the_counts_are_those_of_the_runs_made_apart(study, apart) -> None:
    """Each limit state's exceedances at every level equal those counted from the runs
    simulated here: any seat opening beyond 50 mm, the joint's; the decks striking at the
    joint (the bridge has cable restrainers: the study runs them, no longer refused)."""
    seat, joint, impacts, _ = apart
    _, out = study
    by = {r.spec.label: r for r in out.analysis.limit_states}
    assert list(by) == ["peak seat opening > 0.05 m", "pounding at J1",
                        "peak seat opening at J1 > 0.05 m"]
    for label, exceeded in (("peak seat opening > 0.05 m", seat > WIDTH),
                            ("pounding at J1", impacts > 0),
                            ("peak seat opening at J1 > 0.05 m", joint > WIDTH)):
        assert by[label].n_runs.tolist() == [9] * len(LEVELS)
        assert by[label].n_exceed.tolist() == exceeded.sum(axis=0).tolist(), label
    # the IDA demand itself, run by run (read at the same output steps)
    np.testing.assert_allclose(out.analysis.demands["seat_opening"][0], seat, rtol=1e-12)
    assert 0 < (seat > WIDTH).sum() < seat.size and 0 < (impacts > 0).sum() < impacts.size


def _binomial_mle(levels, n, z):
    """The lognormal fragility by maximum likelihood on the stripes, written with SciPy:
    Nelder–Mead on −Σ log binom.pmf(z_j; n_j, Φ(ln(x_j/θ)/β))."""
    x = np.asarray(levels)

    def nll(p):
        theta, beta = math.exp(p[0]), math.exp(p[1])
        q = np.clip(stats.norm.cdf(np.log(x / theta) / beta), 1e-300, 1 - 1e-16)
        return -np.sum(stats.binom.logpmf(z, n, q))

    best = optimize.minimize(nll, [math.log(0.5), math.log(0.5)], method="Nelder-Mead",
                             options={"xatol": 1e-10, "fatol": 1e-12, "maxiter": 20000})
    return math.exp(best.x[0]), math.exp(best.x[1])


def test_the_fragility_fits_are_scipys(study, apart) -> None:
    """P(unseating | PGA) for a 50 mm seat and P(pounding at the joint | PGA): the stripe
    fit equals SciPy's maximisation of the binomial likelihood of the counts made apart."""
    seat, _, impacts, _ = apart
    _, out = study
    by = {r.spec.label: r for r in out.analysis.limit_states}
    for label, exceeded in (("peak seat opening > 0.05 m", seat > WIDTH),
                            ("pounding at J1", impacts > 0)):
        theta, beta = _binomial_mle(LEVELS, [9] * len(LEVELS), exceeded.sum(axis=0))
        assert by[label].msa.median == pytest.approx(theta, rel=1e-5)
        assert by[label].msa.beta == pytest.approx(beta, rel=1e-5)


def test_the_seat_width_for_a_probability_of_unseating(study, apart) -> None:
    """At every level the records' largest seat openings fitted by SciPy's lognormal
    (``lognorm.fit`` with the location at 0: its σ is the moments' with n, not n − 1) and
    the width for P(unseating) = 0.2 its 0.8 fractile; from the records, the 8th smallest
    opening of 9 (at most one record, ⌊0.2 × 9⌋, opens beyond it)."""
    seat, *_ = apart
    _, out = study
    s = out.analysis.seats
    for j in range(len(LEVELS)):
        shape, loc, scale = stats.lognorm.fit(seat[:, j], floc=0.0)
        assert loc == 0.0
        assert s.median[j] == pytest.approx(scale, rel=1e-9)
        assert s.beta[j] * math.sqrt(8 / 9) == pytest.approx(shape, rel=1e-9)
        width = stats.lognorm(s.beta[j], scale=scale).ppf(1.0 - TARGET)
        assert s.width_fit[j] == pytest.approx(width, rel=1e-9)
        assert s.width_records[j] == np.sort(seat[:, j])[7]
        assert np.sum(seat[:, j] > s.width_records[j]) <= 1
        assert s.width_fit_ci[0, j] < s.width_fit[j] < s.width_fit_ci[1, j]
    assert (out.out_dir / "seat_widths.csv").is_file()


def test_the_gap_the_joint_needs(study, apart) -> None:
    """The needed joint gap of every record at every level (and at the gap level, none of
    the study's) is the largest closing of the joint with no joint contact, as sampled by
    hand or up to 0.1 mm more (located between output steps); and every run with contact
    (the 20 mm joint) pounded at the joint exactly when its needed gap exceeds 20 mm."""
    *_, impacts, closing = apart
    _, out = study
    ng = out.analysis.gap.needed
    assert not ng.scaled and ng.at == AT
    for found, sampled in ((ng.needed, closing[:, :len(LEVELS)]), (ng.needed_at, closing[:, -1])):
        assert np.all(found >= sampled) and np.all(found - sampled < 1e-4)
    assert np.array_equal(ng.needed > 0.02, impacts > 0)
    check = out.analysis.gap.check["0.02"]
    assert check["runs"] == check["agree"] == 9 * len(LEVELS)
    assert set(ng.code) == {"ABS", "SRSS", "DDC"} and ng.code["ABS"] >= ng.code["SRSS"] > 0


@pytest.mark.parametrize(("limit_state", "message"), [
    ('demand = "seat_opening"\njoint = "J2"\nlimit = 0.3',
     "limit_state[0].joint: the bridge of bridge.toml has 1 expansion joint(s), J1 … J1 "
     "(got 'J2')"),
    ('demand = "drift"\njoint = "J1"\nlimit = 1.0',
     "limit_state[0].joint: only for a bridge's demands pounding, impacts, impact_force, "
     "seat_opening (got 'J1' with demand \"drift\")"),
    ('demand = "seat_opening"\njoint = "B1"\nlimit = 0.3', "limit_state[0].joint: an "
     "expansion joint"),
    ('demand = "seat_opening"', 'limit_state[0].limit: required for demand "seat_opening"'),
])
def test_a_bad_bridge_limit_state_is_one_line(tmp_path: Path, capsys, limit_state: str,
                                              message: str) -> None:
    (tmp_path / "bridge.toml").write_text(BASE)
    text = STUDY.split("[[limit_state]]")[0] + f"[[limit_state]]\n{limit_state}\n"
    (tmp_path / "study.toml").write_text(text)
    capsys.readouterr()
    assert main(["fragility", str(tmp_path / "study.toml"), "--out",
                 str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0], err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bridge.toml", "study.toml"]


def test_a_seat_opening_of_buildings_is_refused(tmp_path: Path) -> None:
    """A seat is a bridge's: a study of buildings refuses the demand in one line."""
    from pounding.studies.fragility import study_cases

    seed = Path(__file__).resolve().parents[2] / "examples" / "seed_sdof_pair.toml"
    text = STUDY.replace('base = "bridge.toml"', f'base = "{seed}"')
    (tmp_path / "study.toml").write_text(text)
    with pytest.raises(ValueError, match=r"limit_state\[0\]\.demand: a bridge's joints and "
                                         r"seats, and .* is no bridge"):
        study_cases(tmp_path / "study.toml")

"""Conventions a user can guess (issue 25).

* every command's ``--help``: no ``<str>``, no ``<bool>``, help text shown as written (no
  ``[s]`` eaten as markup, no double space), the choices of an option shown;
* an option means the same in every command that has it: same type, same metavar, the
  same first sentence of help;
* the runners (``run``, ``run_sweep``, ``run_study``, ``run_mitigation``) take the same
  first arguments in the same order, report progress the same way and write by default
  into ``<input stem>-results`` in the current folder;
* no two public classes of pounding share a name;
* every CSV pounding writes reads with plain ``pandas.read_csv(path)``, numbers as numbers;
* at 80 columns no printed table cuts a number.
"""

from __future__ import annotations

import ast
import inspect
import re
from collections import defaultdict
from pathlib import Path
from typing import Any

import pandas as pd
import pytest

from pounding.cli import app, main
from pounding.cli import options as opt

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src" / "pounding"
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
ASCE = ROOT / "examples" / "spectrum_asce7_site.toml"
RECORDS = ROOT / "src" / "pounding" / "data" / "records"
ELC = RECORDS / "elcentro_1940_IV_ELC9_180_PEER.AT2"
NWH = RECORDS / "northridge_1994_newhall_360_RSN1044.AT2"


def _commands() -> dict[str, Any]:
    from typer.main import get_command

    return dict(get_command(app).commands)  # type: ignore[attr-defined]


def _help_text(capsys: pytest.CaptureFixture[str], *argv: str) -> str:
    capsys.readouterr()
    assert main([*argv, "--help"]) == 0
    return capsys.readouterr().out


# ============================================================================ --help
def test_no_bare_type_in_any_help(capsys: pytest.CaptureFixture[str]) -> None:
    """Every option shows what it takes (a metavar, its choices) or nothing (a flag)."""
    for argv in [[], *([name] for name in _commands())]:
        text = _help_text(capsys, *argv)
        assert "<str>" not in text and "<bool>" not in text, (argv, text)


def test_help_text_is_shown_as_written() -> None:
    """No ``[s]``, ``[record]``, ``[output]`` read as rich markup (it would vanish and leave
    a double space), no double space of the text's own."""
    from rich.text import Text

    for name, command in _commands().items():
        texts = [(param.name, param.help or "") for param in command.params]
        for what, raw in [("(command)", command.help or ""), *texts]:
            shown = Text.from_markup(raw).plain
            assert shown == raw.replace("\\[", "["), (name, what, raw, shown)
            for line in shown.splitlines():  # (the command's examples are indented)
                assert "  " not in line.strip(), (name, what, line)


def _first_sentence(text: str) -> str:
    """Up to the first ". " (an option's meaning)."""
    return re.split(r"(?<=\.) ", text.replace("\\[", "["), maxsplit=1)[0]


def test_an_option_means_the_same_in_every_command() -> None:
    """Options of one name: one type (and choices), one metavar, one first sentence."""
    seen: dict[str, list[tuple[str, tuple[Any, ...]]]] = defaultdict(list)
    for name, command in _commands().items():
        for param in command.params:
            if param.param_type_name != "option":
                continue
            for flag in param.opts:
                if flag.startswith("--"):
                    kind = (param.type_descriptor.annotation if hasattr(param, "type_descriptor")
                            else getattr(param, "type", None))
                    kind = getattr(kind, "__args__", (kind,))
                    # a command may take the option repeated (list[Path]): the same meaning
                    kind = tuple(getattr(k, "__args__", (k,))[0] for k in kind
                                 if k is not type(None))
                    seen[flag].append((name, (kind, param.metavar,
                                              _first_sentence(param.help or ""))))
    shared = {flag: uses for flag, uses in seen.items() if len(uses) > 1}
    assert {"--out", "--overwrite", "--figures", "--workers", "--scheduler", "--plot",
            "--csv", "--design", "--dt", "--units", "--e", "--law", "--damping",
            "--m1", "--k"} <= set(shared)
    assert "--code" in shared  # suite's and code-check's: one list of codes (issue 29)
    for flag, uses in shared.items():
        if flag == "--out":  # `pounding match --out FILE.AT2` writes one file, not a folder
            uses = [u for u in uses if u[0] != "match"]
        meanings = {what for _, what in uses}
        assert len(meanings) == 1, (flag, uses)


def test_the_names_of_every_choice_are_the_librarys() -> None:
    from pounding.contact.bilinear import BILINEAR_FORMULAS
    from pounding.contact.calibration import FIT_LAWS
    from pounding.contact.factory import IMPACT_LAW_NAMES, LAW_NAMES
    from pounding.contact.restitution import FORMULAS
    from pounding.spectra.scaling import METHODS
    from pounding.studies.sweep import HISTORY_FORMATS
    from pounding.units import ACCELERATION_UNITS, acceleration_factor

    assert [law.value for law in opt.Law] == list(IMPACT_LAW_NAMES)
    assert set(FIT_LAWS) <= set(LAW_NAMES)
    assert {f.value for f in opt.Formula} == {"exact", *FORMULAS, *BILINEAR_FORMULAS}
    assert {u.value for u in opt.Units} <= set(ACCELERATION_UNITS)
    assert {acceleration_factor(u.value) for u in opt.Units} == set(ACCELERATION_UNITS.values())
    assert [m.value for m in opt.Method] == list(METHODS)
    assert {h.value for h in opt.Histories} == {*HISTORY_FORMATS, "none"}


def test_every_choice_is_in_the_help(capsys: pytest.CaptureFixture[str]) -> None:
    for argv, choices in ((["collide"], opt.Law), (["fit"], opt.Law),
                          (["collide"], opt.Formula), (["gap"], opt.Units),
                          (["spectrum"], opt.Units), (["plot"], opt.PlotKind),
                          (["plot"], opt.Reduce), (["suite"], opt.Method),
                          (["suite"], opt.Code), (["sweep"], opt.Histories)):
        text = " ".join(_help_text(capsys, *argv).replace("│", " ").split())
        missing = [c.value for c in choices if c.value not in text]
        if argv == ["fit"]:  # only the laws with something to fit
            from pounding.contact.calibration import FIT_LAWS

            missing = [m for m in missing if m in FIT_LAWS]
        assert not missing, (argv, missing)


def test_the_command_line_starts_without_numpy() -> None:
    """Command modules import only typer, rich and the CLI's helpers: ``pounding --help``
    does not wait for NumPy (``pounding ellipse`` imported it at module level)."""
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-c", "import sys, pounding.cli; "
                          "print('numpy' in sys.modules)"], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "False"


# ============================================================================ runners
RUNNERS = ("pounding.run_file:run", "pounding.studies.sweep:run_sweep",
           "pounding.studies.fragility:run_study",
           "pounding.studies.mitigation:run_mitigation")


def test_the_runners_take_the_same_first_arguments() -> None:
    import importlib

    from pounding.progress import Progress

    for spec in RUNNERS:
        module, name = spec.split(":")
        fn = getattr(importlib.import_module(module), name)
        sig = inspect.signature(fn, eval_str=True)
        params = list(sig.parameters.values())
        assert [p.name for p in params[:5]] == ["input", "out", "overwrite", "figures",
                                                "progress"], spec
        assert params[1].default is None and params[2].default is False, spec
        assert params[3].default is None, spec
        assert sig.parameters["progress"].annotation == Progress | None, spec


def test_no_two_public_classes_share_a_name() -> None:
    where: dict[str, list[str]] = defaultdict(list)
    for path in SRC.rglob("*.py"):
        for node in ast.parse(path.read_text(encoding="utf-8")).body:
            if isinstance(node, ast.ClassDef) and not node.name.startswith("_"):
                where[node.name].append(str(path.relative_to(SRC)))
    twice = {name: files for name, files in where.items() if len(files) > 1}
    assert not twice, twice


MITIGATION = f"""
base = "{SEED}"
[[option]]
name = "bare gap"
[[option]]
name = "dashpot"
[[option.device]]
type = "viscous"
floors = "all"
c = 1.0e6
"""


def _short_seed(folder: Path, name: str = "pair", duration: float = 3.0) -> Path:
    text = SEED.read_text(encoding="utf-8")
    path = folder / f"{name}.toml"
    path.write_text(text.replace("[record]", f"[record]\nduration = {duration}", 1),
                    encoding="utf-8")
    return path


def test_every_runner_writes_into_input_stem_results_in_the_current_folder(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The one default: ``<input file stem>-results`` in the current folder, never beside
    the input file (a bundled example is only read)."""
    from pounding import run
    from pounding.studies.fragility import study_cases
    from pounding.studies.mitigation import run_mitigation
    from pounding.studies.sweep import load_sweep

    inputs, here = tmp_path / "inputs", tmp_path / "here"
    inputs.mkdir()
    here.mkdir()
    monkeypatch.chdir(here)
    model = _short_seed(inputs, "pair")
    assert run(model, figures=False).out_dir == Path("pair-results")
    assert (here / "pair-results" / "impacts.csv").is_file()

    (inputs / "gaps.toml").write_text(f'name = "other"\nbase = "{model}"\n'
                                      '[grid]\n"contact.gap" = [0.01, 0.02]\n')
    assert load_sweep(inputs / "gaps.toml").out == Path("gaps-results")

    (inputs / "retrofit.toml").write_text(MITIGATION.replace(str(SEED), str(model)))
    res = run_mitigation(inputs / "retrofit.toml", figures=False)
    assert res.out_dir == Path("retrofit-results") and (here / "retrofit-results").is_dir()

    (inputs / "frag.toml").write_text(f'name = "x"\nbase = "{model}"\n'
                                      f'[suite]\nfiles = ["{ELC}", "{NWH}"]\n'
                                      '[intensity]\nmeasure = "pga"\nlevels = [0.1, 0.2]\n')
    assert study_cases(inputs / "frag.toml").out == Path("frag-results")
    assert sorted(p.name for p in inputs.iterdir()) == ["frag.toml", "gaps.toml", "pair.toml",
                                                       "retrofit.toml"]


def test_progress_is_done_of_total_in_every_runner(tmp_path: Path) -> None:
    from pounding.studies.mitigation import run_mitigation
    from pounding.studies.sweep import load_sweep, run_sweep

    model = _short_seed(tmp_path)
    sweep = tmp_path / "s.toml"
    sweep.write_text(f'base = "{model}"\nout = "o"\n[grid]\n"contact.gap" = [0.01, 0.02, 0.03]\n')
    calls: list[tuple[float, float]] = []
    run_sweep(load_sweep(sweep), progress=lambda d, t: calls.append((d, t)),
              scheduler="synchronous")
    assert calls[0] == (0, 3) and calls[-1] == (3, 3)
    study = tmp_path / "m.toml"
    study.write_text(MITIGATION.replace(str(SEED), str(model)))
    calls.clear()
    run_mitigation(study, tmp_path / "m-out", figures=False,
                   progress=lambda d, t: calls.append((d, t)))
    assert calls == [(0, 2), (1, 2), (2, 2)]


def test_a_sweep_draws_its_figure_when_asked(tmp_path: Path) -> None:
    from pounding.io.manifest import Manifest
    from pounding.studies.sweep import load_sweep, run_sweep

    model = _short_seed(tmp_path)
    sweep = tmp_path / "s.toml"
    sweep.write_text(f'base = "{model}"\nout = "o"\n[grid]\n"contact.gap" = [0.01, 0.03]\n')
    res = run_sweep(load_sweep(sweep), figures=True, scheduler="synchronous")
    assert res.figure == tmp_path / "o" / "peak_contact_force_N_vs_contact.gap.png"
    assert res.figure.read_bytes()[:4] == b"\x89PNG" and Manifest(res.out_dir).is_ours(
        res.figure)


# ============================================================================ CSV
@pytest.fixture
def quick_audit(monkeypatch: pytest.MonkeyPatch) -> None:
    """`pounding audit` over three of its formula–law pairs (the whole audit takes ~9 s an
    e; the point here is its table and CSV, not the audit)."""
    import pounding.contact.audit as audit

    real = audit.restitution_audit
    monkeypatch.setattr(audit, "restitution_audit", lambda e, case: real(
        e, case, pairings=audit.PAIRINGS[:3]))


def _numeric_except(path: Path, text: set[str]) -> pd.DataFrame:
    df = pd.read_csv(path)
    assert len(df) > 0 and not any(str(c).startswith("#") for c in df.columns), path
    for column in df.columns:
        if column not in text:
            assert pd.api.types.is_numeric_dtype(df[column]), (path.name, column,
                                                                df[column].head())
    return df


def test_every_csv_reads_with_plain_read_csv(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                             quick_audit: None) -> None:
    """No comment line: pandas (and Excel, R's read.csv) read the header and the numbers."""
    from pounding.result import IMPACTS_CSV_COLUMNS

    model = _short_seed(tmp_path, duration=4.0)
    assert main(["run", str(model), "--out", str(tmp_path / "r"), "--no-figures"]) == 0
    imp = _numeric_except(tmp_path / "r" / "impacts.csv", {"contact"})
    assert list(imp.columns) == list(IMPACTS_CSV_COLUMNS.values())
    assert main(["gap", str(model), "--csv", str(tmp_path / "g.csv")]) == 0
    _numeric_except(tmp_path / "g.csv", {"pair", "contact"})
    assert main(["spectrum", str(ELC), "--periods", "0.2,1", "--csv",
                 str(tmp_path / "s.csv")]) == 0
    _numeric_except(tmp_path / "s.csv", {"record"})
    assert main(["spectrum", str(ELC), str(ELC), "--rotd", "--periods", "0.2,1", "--csv",
                 str(tmp_path / "rotd.csv")]) == 0
    _numeric_except(tmp_path / "rotd.csv", {"record", "measure"})
    assert main(["suite", str(ELC), str(NWH), "--design", str(ASCE), "--t1", "1", "--csv",
                 str(tmp_path / "f.csv")]) == 0
    _numeric_except(tmp_path / "f.csv", {"record"})
    assert main(["audit", "--e", "0.5", "--csv", str(tmp_path / "a.csv")]) == 0
    _numeric_except(tmp_path / "a.csv", {"formula", "law"})
    study = tmp_path / "m.toml"
    study.write_text(MITIGATION.replace(str(SEED), str(model)))
    assert main(["mitigate", str(study), "--out", str(tmp_path / "m"), "--no-figures"]) == 0
    _numeric_except(tmp_path / "m" / "runs.csv", {"option", "record"})
    _numeric_except(tmp_path / "m" / "summary.csv", {"option"})


# ============================================================================ 80 columns
NUMBER = re.compile(r"(?<![\w.])[-+−]?\d+(?:\.\d+)?(?:e[-+]\d+)?(?![\w.])")


def _printed(argv: list[str], width: int, capsys: pytest.CaptureFixture[str],
             monkeypatch: pytest.MonkeyPatch) -> str:
    from pounding.cli.app import console

    monkeypatch.setattr(console, "width", width)
    capsys.readouterr()
    assert main(argv) == 0, capsys.readouterr().err
    return capsys.readouterr().out


def test_no_table_cuts_a_number_at_80_columns(tmp_path: Path,
                                             capsys: pytest.CaptureFixture[str],
                                             monkeypatch: pytest.MonkeyPatch,
                                             quick_audit: None) -> None:
    """Every number printed 200 columns wide is printed whole at 80 (a table too wide is
    split into parts, each repeating its key columns), no line is wider than 80, nothing
    is elided ("…")."""
    model = _short_seed(tmp_path, duration=3.0)
    study = tmp_path / "m.toml"
    study.write_text(MITIGATION.replace(str(SEED), str(model)))
    commands = [
        ["zeta"],
        ["audit", "--e", "0.3,0.5,0.7,0.9"],
        ["collide", "--law", "hunt-crossley", "--e", "0.3,0.6,0.9"],
        ["ellipse"],
        ["examples"],
        ["gap", str(model)],
        ["spectrum", str(ELC), "--damping", "0.02,0.05,0.1", "--periods", "0.2,1"],
        ["record", str(ELC), str(NWH)],
        ["suite", str(ELC), str(NWH), "--design", str(ASCE), "--t1", "1"],
        ["mitigate", str(study), "--out", "{out}", "--no-figures", "--overwrite"],
    ]
    for k, argv in enumerate(commands):
        argv = [a.replace("{out}", str(tmp_path / f"o{k}")) for a in argv]
        wide = _printed(argv, 200, capsys, monkeypatch)
        narrow = _printed(argv, 80, capsys, monkeypatch)
        assert max(len(line) for line in narrow.splitlines()) <= 80, argv[0]
        assert "…" not in narrow, argv[0]
        lost = set(NUMBER.findall(wide)) - set(NUMBER.findall(narrow))
        assert not lost, (argv[0], sorted(lost)[:10], narrow)


def test_forces_and_energies_read_in_one_unit_without_exponents(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    """collide, fit's residual, mitigate: every force of a table in kN (or MN), every
    energy in kJ (or MJ), no ``7.858e+06 N``; durations in ms, penetrations in mm."""
    model = _short_seed(tmp_path, duration=3.0)
    study = tmp_path / "m.toml"
    study.write_text(MITIGATION.replace(str(SEED), str(model)))
    exponent = re.compile(r"\d[eE][-+]?\d")
    for argv, units in (
            (["collide", "--law", "hunt-crossley", "--e", "0.5"],
             ("contact duration [ms]", "max penetration [mm]", "peak force [kN]",
              "energy dissipated ∫F dδ [kJ]")),
            (["mitigate", str(study), "--out", str(tmp_path / "o"), "--no-figures"],
             ("[kN]|[MN]", "[kJ]|[MJ]"))):
        text = _printed(argv, 200, capsys, monkeypatch)
        rows = [line for line in text.splitlines() if "│" in line]
        assert rows and not any(exponent.search(line) for line in rows), (argv[0], rows)
        flat = " ".join(text.split())
        for unit in units:
            assert any(u in flat for u in unit.split("|")), (argv[0], unit)
        assert "[N]" not in text and "[J]" not in text, argv[0]
        # one unit per quantity on the screen
        assert not ("[kN]" in text and "[MN]" in text), argv[0]
        assert not ("[kJ]" in text and "[MJ]" in text), argv[0]


def test_many_runs_go_where_workers_and_scheduler_say() -> None:
    """mitigate and gap run their runs through run_tasks: in this process by default, on a
    local Dask cluster with n_workers (the sweep's client), results in the order of the
    tasks and progress as each finishes."""
    import operator

    from pounding.studies.sweep.tasks import run_tasks

    tasks = [(3, 4), (5, 12), (8, 15)]
    calls: list[tuple[float, float]] = []
    assert run_tasks(operator.mul, tasks) == [12, 60, 120]
    assert run_tasks(operator.mul, tasks, scheduler="synchronous",
                     progress=lambda d, t: calls.append((d, t))) == [12, 60, 120]
    assert calls == [(0, 3), (1, 3), (2, 3), (3, 3)]
    calls.clear()
    assert run_tasks(operator.mul, tasks, n_workers=1,
                     progress=lambda d, t: calls.append((d, t))) == [12, 60, 120]
    assert calls[0] == (0, 3) and calls[-1] == (3, 3) and len(calls) == 4

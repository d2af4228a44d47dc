"""Never lose what is not ours, never write where not asked: ``--overwrite`` replaces only
the files an output folder's manifest lists; a full disk is one line and leaves earlier
results as they were; what a killed process left is removed only when it is pounding's and
that process is gone; a study's name is a label and its ``out`` stays in its folder.

Every refusal: one line, exit status 2, no traceback, the user's files byte-identical.
"""

from __future__ import annotations

import errno
import json
import os
import resource
import signal
import subprocess
import sys
from pathlib import Path

import pytest

import pounding.run_file as run_mod
from pounding.cli import main
from pounding.config import dump_toml
from pounding.io.manifest import MANIFEST_FILE, Manifest
from pounding.run_file import run

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src"
TWO_10 = ROOT / "examples" / "two_10_storey.toml"


def short_model(folder: Path, duration: float = 3.0) -> Path:
    """The seed pair for 3 s: its timehistories.nc is about 0.5 MB."""
    path = folder / "short.toml"
    path.write_text(dump_toml({
        "name": "short pair", "record": {"bundled": "el_centro"},
        "building": [{"mass": 2e5, "period": 0.5}, {"mass": 3e5, "period": 1.0}],
        "contact": {"law": "nonlinear-viscoelastic", "k_h": 2.75e9, "e": 0.65, "gap": 0.02},
        "solver": {"duration": duration}}), encoding="utf-8")
    return path


def snapshot(folder: Path) -> dict[str, bytes | None]:
    """Every entry under ``folder`` with its bytes (None: a folder)."""
    return {p.relative_to(folder).as_posix(): (p.read_bytes() if p.is_file() else None)
            for p in sorted(folder.rglob("*"))}


def hidden(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.startswith("."))


def cli(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    capsys.readouterr()
    code = main(list(argv))
    return code, capsys.readouterr().err.strip().splitlines()


def dead_pid() -> int:
    """The pid of a process that has ended."""
    p = subprocess.Popen([sys.executable, "-c", "pass"])
    p.wait()
    return p.pid


def limited(argv: list[str], limit: int, cwd: Path) -> subprocess.CompletedProcess[str]:
    """``python -m pounding ARGV`` with files limited to ``limit`` bytes (RLIMIT_FSIZE: a
    write past it fails with EFBIG, as on a full disk; works for root too)."""
    def preexec() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    env = dict(os.environ, PYTHONPATH=str(SRC), POUNDING_SKIP_BROWSER="1")
    return subprocess.run([sys.executable, "-m", "pounding", *argv], cwd=cwd, env=env,
                          preexec_fn=preexec, capture_output=True, text=True, timeout=300)


# ------------------------------------------------------------------ --overwrite: runs
def test_overwrite_never_deletes_a_folder_for_holding_a_summary_json(tmp_path, capsys):
    x = tmp_path / "x"
    x.mkdir()
    (x / "a").write_text("hi\n")
    (x / "summary.json").write_text("{}\n")
    before = snapshot(x)
    code, err = cli(capsys, "run", str(short_model(tmp_path)), "--out", str(x), "--overwrite",
                    "--no-figures")
    assert code == 2 and err == [
        f"error: out: not replacing it: {x} has no manifest of pounding's files "
        f"({MANIFEST_FILE}); remove it yourself or choose another --out"]
    assert snapshot(x) == before and hidden(tmp_path) == []


@pytest.fixture(scope="module")
def earlier_run(tmp_path_factory) -> tuple[Path, Path]:
    """A model file and a run of it (no figures), to copy."""
    folder = tmp_path_factory.mktemp("earlier")
    model = short_model(folder)
    run(model, folder / "out", figures=False)
    return model, folder / "out"


def copy_of(out: Path, to: Path) -> Path:
    import shutil

    shutil.copytree(out, to)
    return to


@pytest.mark.parametrize("change, named", [
    (lambda o: (o / "notes.txt").write_text("mine"), "notes.txt (not a file pounding wrote)"),
    (lambda o: (o / "mine").mkdir(), "mine/ (a folder pounding did not make)"),
    (lambda o: (o / "summary.json").write_text('{"edited": 1}'),
     "summary.json (changed since pounding wrote it)"),
    (lambda o: (o / "deep" / "er").mkdir(parents=True) or (o / "deep" / "er" / "f").write_text(
        "x"), "deep/ (a folder pounding did not make)"),
])
def test_overwrite_refuses_an_earlier_run_holding_anything_else(tmp_path, capsys, earlier_run,
                                                                change, named):
    model, earlier = earlier_run
    out = copy_of(earlier, tmp_path / "out")
    change(out)
    before = snapshot(out)
    code, err = cli(capsys, "run", str(model), "--out", str(out), "--overwrite", "--no-figures")
    assert code == 2 and err == [f"error: out: not replacing {out}: it holds {named}; move it "
                                 "away or choose another --out"]
    assert snapshot(out) == before and hidden(tmp_path) == []


def test_overwrite_replaces_its_own_output_with_the_report_written_into_it(tmp_path, capsys,
                                                                          earlier_run,
                                                                          monkeypatch):
    import pounding.report as report

    monkeypatch.setattr(report, "render_report", lambda folder: "<html>the report</html>")
    model, earlier = earlier_run
    out = copy_of(earlier, tmp_path / "out")
    (out / "report.html").write_text("not pounding's")
    code, err = cli(capsys, "report", str(out))
    assert code == 2 and err == [f"error: out: not replacing {out / 'report.html'}: pounding "
                                 "did not write it (or it changed since); move it away or "
                                 "choose another --out"]
    assert (out / "report.html").read_text() == "not pounding's"
    (out / "report.html").unlink()
    assert cli(capsys, "report", str(out))[0] == 0
    assert "report.html" in Manifest(out).entries()
    assert cli(capsys, "run", str(model), "--out", str(out), "--overwrite",
               "--no-figures")[0] == 0
    assert not (out / "report.html").exists() and (out / MANIFEST_FILE).is_file()
    assert hidden(tmp_path) == []


def test_the_demo_replaces_its_own_output_when_run_again(tmp_path, capsys):
    out = tmp_path / "demo"
    assert cli(capsys, "demo", "--out", str(out), "--no-figures")[0] == 0
    first = json.loads((out / "summary.json").read_text())
    assert cli(capsys, "demo", "--out", str(out), "--no-figures")[0] == 0
    assert json.loads((out / "summary.json").read_text())["n_impacts"] == first["n_impacts"]
    assert hidden(tmp_path) == []


# ------------------------------------------------------------------ a full disk
def test_a_full_disk_is_one_line_and_keeps_the_earlier_run(tmp_path, earlier_run):
    model, earlier = earlier_run
    out = copy_of(earlier, tmp_path / "out")
    before = snapshot(out)
    proc = limited(["run", str(model), "--out", str(out), "--overwrite", "--no-figures"],
                   100_000, tmp_path)
    assert proc.returncode == 2, proc.stderr[-2000:]
    assert proc.stderr.strip().splitlines() == [
        f"error: cannot write {out / 'timehistories.nc'}: file too large"]
    assert snapshot(out) == before and hidden(tmp_path) == []


def test_a_figure_that_cannot_be_written_is_one_line_naming_it(tmp_path, capsys, monkeypatch,
                                                               earlier_run):
    from matplotlib.figure import Figure

    model, earlier = earlier_run
    out = copy_of(earlier, tmp_path / "out")
    before = snapshot(out)

    def full(self, fname, **kw):
        Path(fname).write_bytes(b"\x89PNG half")
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(Figure, "savefig", full)
    code, err = cli(capsys, "run", str(model), "--out", str(out), "--overwrite", "--figures")
    assert code == 2 and len(err) == 1, err
    assert err[0].startswith(f"error: cannot write {out}/") and err[0].endswith(
        ".png: no space left on device")
    assert snapshot(out) == before and hidden(tmp_path) == []


def sweep_file(folder: Path, body: str, name: str = "sweep.toml", head: str | None = None
               ) -> Path:
    p = folder / name
    p.write_text((head if head is not None else 'name = "s"\nout = "out"\n')
                 + f'base = "{short_model(folder, 2.0)}"\n' + body, encoding="utf-8")
    return p


def test_a_full_disk_in_a_sweep_with_histories_is_one_line(tmp_path):
    path = sweep_file(tmp_path, '[grid]\n"contact.gap" = [0.01, 0.02]\n')
    proc = limited(["sweep", str(path), "--scheduler", "synchronous", "--histories", "netcdf",
                    "--batch-size", "1"], 100_000, tmp_path)
    assert proc.returncode == 2, proc.stderr[-2000:]
    [line] = proc.stderr.strip().splitlines()
    hist = tmp_path / "out" / "histories"
    assert line.startswith(f"error: cannot write {hist}/") and (
        ".nc: file too large; no case was saved, leaving" in line)
    # nothing half-written, and the folder it made is gone again
    assert sorted(p.name for p in tmp_path.iterdir()) == ["short.toml", "sweep.toml"]


def mitigation_file(folder: Path, head: str = 'name = "m"\n') -> Path:
    p = folder / "m.toml"
    p.write_text(head + f'base = "{TWO_10}"\nrecords = ["el_centro"]\n'
                 '[[option]]\nname = "bare gap"\n', encoding="utf-8")
    return p


def test_mitigate_on_a_full_disk_keeps_the_earlier_study_whole(tmp_path, capsys, monkeypatch):
    study = mitigation_file(tmp_path)
    out = tmp_path / "o"
    assert cli(capsys, "mitigate", str(study), "--out", str(out))[0] == 0
    before = snapshot(out)
    from matplotlib.figure import Figure

    def full(self, fname, **kw):
        Path(fname).write_bytes(b"\x89PNG half")
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(Figure, "savefig", full)
    code, err = cli(capsys, "mitigate", str(study), "--out", str(out), "--overwrite")
    assert code == 2 and err == [f"error: cannot write {out / 'mitigation.png'}: no space left "
                                 "on device"]
    assert snapshot(out) == before and hidden(tmp_path) == []
    # and a folder holding a file of the user's is never replaced
    (out / "notes.txt").write_text("mine")
    monkeypatch.undo()
    before = snapshot(out)
    code, err = cli(capsys, "mitigate", str(study), "--out", str(out), "--overwrite")
    assert code == 2 and err == [f"error: out: not replacing {out}: it holds notes.txt (not a "
                                 "file pounding wrote); move it away or choose another --out"]
    assert snapshot(out) == before


# ------------------------------------------------------------------ a process killed outright
KILL_WHEN = """
import os, signal, sys
import pounding.run_file as run_mod
real = os.replace
def replace(src, dst):
    if os.path.basename(str(src)).startswith(".out.tmp-"):
        os.kill(os.getpid(), signal.SIGKILL)  # the old output moved aside, the new not in
    return real(src, dst)
os.replace = replace
run_mod.run(sys.argv[1], sys.argv[2], overwrite=True, figures=False)
"""


def test_a_run_killed_while_replacing_is_put_back_and_cleaned_by_the_next(tmp_path,
                                                                          earlier_run):
    model, earlier = earlier_run
    out = copy_of(earlier, tmp_path / "out")
    before = snapshot(out)
    # a folder of the user's that only looks like a temporary of a dead process
    mine = tmp_path / f".out.tmp-{dead_pid()}-abcdefgh"
    mine.mkdir()
    (mine / "summary.json").write_text("mine")
    env = dict(os.environ, PYTHONPATH=str(SRC))
    proc = subprocess.run([sys.executable, "-c", KILL_WHEN, str(model), str(out)], env=env,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == -signal.SIGKILL, proc.stderr[-2000:]
    assert not out.exists()
    left = [n for n in hidden(tmp_path) if n != mine.name]
    assert {n.split("-")[0] for n in left} == {".out.old", ".out.tmp"}, left
    run_mod._remove_stale(out)  # what the next run does first
    assert snapshot(out) == before
    assert hidden(tmp_path) == [mine.name] and (mine / "summary.json").read_text() == "mine"


KILL_CONSOLIDATING = """
import os, signal, sys
import pyarrow.parquet as pq
real = pq.write_table
def write_table(table, where, *a, **kw):
    real(table, where, *a, **kw)
    if os.path.basename(str(where)).startswith(".results.parquet.part-"):
        os.kill(os.getpid(), signal.SIGKILL)
pq.write_table = write_table
from pounding.studies.sweep import run_sweep
run_sweep(sys.argv[1], scheduler="synchronous")
"""


def test_resume_removes_what_a_sweep_killed_while_consolidating_left(tmp_path, capsys):
    path = sweep_file(tmp_path, '[grid]\n"contact.gap" = [0.01, 0.02]\n')
    env = dict(os.environ, PYTHONPATH=str(SRC))
    proc = subprocess.run([sys.executable, "-c", KILL_CONSOLIDATING, str(path)], env=env,
                          capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert proc.returncode == -signal.SIGKILL, proc.stderr[-2000:]
    out = tmp_path / "out"
    assert [p.name.split("-")[0] for p in out.glob(".results.parquet.part-*")] == [
        ".results.parquet.part"]
    # the user's hidden files, and a temporary of a process still running, stay
    (out / "parts" / ".mine").write_text("mine")
    live = out / f".sweep.json.part-{os.getpid()}-abcdefgh.json"
    live.write_text("{}")
    assert cli(capsys, "sweep", str(path), "--scheduler", "synchronous")[0] == 0
    assert sorted(p.name for p in out.rglob(".*")) == sorted([
        MANIFEST_FILE, ".mine", live.name])
    live.unlink()
    # --overwrite: refused while the user's file is in parts/, then done
    before = snapshot(out)
    code, err = cli(capsys, "sweep", str(path), "--scheduler", "synchronous", "--overwrite")
    assert code == 2 and err == [f"error: out: not replacing {out}: it holds parts/.mine (not "
                                 "a file pounding wrote); move it away or choose another --out"]
    assert snapshot(out) == before
    (out / "parts" / ".mine").unlink()
    # the figure pounding plot puts beside the table is pounding's: listed, and replaced
    assert cli(capsys, "plot", str(out), "--x", "contact.gap")[0] == 0
    [figure] = list(out.glob("*.png"))
    assert figure.name in Manifest(out).entries()
    assert cli(capsys, "sweep", str(path), "--scheduler", "synchronous", "--overwrite")[0] == 0
    assert sorted(Manifest(out).entries()) == sorted(
        ["sweep.json", "results.parquet",
         *(f"parts/{p.name}" for p in (out / "parts").glob("part-*.parquet"))])
    assert not figure.exists()
    # a run never replaces a sweep's folder, even with --overwrite
    before = snapshot(out)
    code, err = cli(capsys, "run", str(tmp_path / "short.toml"), "--out", str(out),
                    "--overwrite")
    assert code == 2 and err == [f"error: out: not replacing {out}: it holds the output of a "
                                 "sweep, not of a run; choose another --out"]
    assert snapshot(out) == before


def test_a_sweep_folder_written_before_manifests_is_not_replaced(tmp_path, capsys):
    path = sweep_file(tmp_path, '[grid]\n"contact.gap" = [0.01]\n')
    out = tmp_path / "out"
    (out / "parts").mkdir(parents=True)
    (out / "sweep.json").write_text('{"fingerprint": "old"}')
    (out / "parts" / "my-notes.txt").write_text("mine")
    before = snapshot(out)
    code, err = cli(capsys, "sweep", str(path), "--scheduler", "synchronous", "--overwrite")
    assert code == 2 and err == [
        f"error: out: not replacing it: {out} has no manifest of pounding's files "
        f"({MANIFEST_FILE}); remove it yourself or choose another --out"]
    assert snapshot(out) == before


# ------------------------------------------------------------------ names and out of studies
# Run from tmp_path/a/b, so that even a name or out that escaped would stay in tmp_path.
BAD_NAMES = [  # (as written in TOML, the value)
    ("../../escaped", "../../escaped"), ("{tmp}/abs", "{tmp}/abs"), ("a/b", "a/b"),
    (".hidden", ".hidden"), ("a\\\\b", "a\\b"), ("a\\u0000b", "a\0b")]


@pytest.fixture
def work(tmp_path, monkeypatch) -> Path:
    folder = tmp_path / "a" / "b"
    folder.mkdir(parents=True)
    monkeypatch.chdir(folder)
    return folder


@pytest.mark.parametrize("written, value", BAD_NAMES)
def test_a_sweep_name_is_a_label_not_a_path(tmp_path, work, capsys, written, value):
    written, value = written.format(tmp=tmp_path), value.format(tmp=tmp_path)
    path = sweep_file(work, '[grid]\n"contact.gap" = [0.01]\n', head=f'name = "{written}"\n')
    before = snapshot(tmp_path)
    code, err = cli(capsys, "sweep", str(path), "--scheduler", "synchronous")
    assert code == 2 and err == [f"error: {path}: name: a label, not a path: no '/', '\\', NUL "
                                 f"or leading '.' (got {value!r})"]
    assert snapshot(tmp_path) == before


@pytest.mark.parametrize("written, value", BAD_NAMES[:2])
def test_a_mitigation_name_is_a_label_not_a_path(tmp_path, work, capsys, written, value):
    written, value = written.format(tmp=tmp_path), value.format(tmp=tmp_path)
    study = mitigation_file(work, head=f'name = "{written}"\n')
    before = snapshot(tmp_path)
    code, err = cli(capsys, "mitigate", str(study))
    assert code == 2 and len(err) == 1 and "name: a label, not a path" in err[0]
    assert f"(got {value!r})" in err[0] and snapshot(tmp_path) == before


@pytest.mark.parametrize("out", ["../x", "{tmp}/elsewhere", ".", "sub/../../x"])
def test_out_of_a_study_file_stays_in_its_folder(tmp_path, work, capsys, out):
    out = out.format(tmp=tmp_path)
    sweep = sweep_file(work, '[grid]\n"contact.gap" = [0.01]\n', head=f'out = "{out}"\n')
    mitigation = mitigation_file(work, head=f'out = "{out}"\n')
    before = snapshot(tmp_path)
    for argv in (["sweep", str(sweep), "--scheduler", "synchronous"],
                 ["mitigate", str(mitigation)]):
        code, err = cli(capsys, *argv)
        assert code == 2 and err == [
            f"error: {argv[1]}: out: {out!r} is not a folder inside the study file's folder "
            f"{work}; give the output folder on the command line (--out) to write there"], err
    assert snapshot(tmp_path) == before


def test_an_out_outside_is_fine_when_given_on_the_command_line(tmp_path, work, capsys):
    study = mitigation_file(work, head='name = "m"\nout = "../x"\n')
    code, err = cli(capsys, "mitigate", str(study), "--out", str(tmp_path / "x"),
                    "--no-figures")
    assert code == 0, err
    assert (tmp_path / "x" / "runs.csv").is_file()



def test_a_file_written_by_a_killed_process_leaves_no_temporary_after_the_next_write(tmp_path):
    """``pounding report --html page.html`` killed outright (SIGKILL) while writing leaves
    ``.page.html.part-<pid>-XXXXXXXX.html``; the next write of page.html removes it — only
    that name, only of a dead process."""
    from pounding.io.files import write_text

    dead, alive = dead_pid(), os.getppid()
    stale = tmp_path / f".page.html.part-{dead}-abcd1234.html"
    live = tmp_path / f".page.html.part-{alive}-abcd1234.html"
    other = tmp_path / f".other.html.part-{dead}-abcd1234.html"
    users = tmp_path / f".page.html.part-{dead}-notours.html"
    for p in (stale, live, other, users):
        p.write_text("half")
    write_text(tmp_path / "page.html", "<html></html>")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        ["page.html", live.name, other.name, users.name])


def test_every_kind_of_output_folder_has_a_name_in_the_messages() -> None:
    """Every kind a command writes an output folder as (``new_output_folder``,
    ``check_out_folder``) is named in ``_KIND_TEXT``: a missing one made ``--overwrite`` onto
    another kind's folder a KeyError traceback (``synthesize``, ``code-check``)."""
    import re

    from pounding.io.manifest import _KIND_TEXT

    src = Path(__file__).resolve().parents[1] / "src" / "pounding"
    kinds = set()
    for path in src.rglob("*.py"):
        text = path.read_text(encoding="utf-8")
        kinds |= set(re.findall(r"(?:new_output_folder|check_out_folder)\([^,]+,\s*(?:\w+,\s*)?"
                                r"\"([\w-]+)\"", text))
    assert {"run", "mitigation", "pushover", "code-check", "synthesize"} <= kinds, kinds
    assert kinds <= set(_KIND_TEXT), kinds - set(_KIND_TEXT)


@pytest.mark.parametrize("argv", [
    ["synthesize", "-m", "7", "-r", "25", "--vs30", "750", "-n", "1"],
    ["code-check", str(Path(__file__).resolve().parents[1] / "examples" / "seed_sdof_pair.toml"),
     "--code", "asce7-22", "--sds", "1", "--sd1", "0.6", "--tl", "8", "--cd", "5.5", "--r", "8",
     "--ie", "1"]], ids=["synthesize", "code-check"])
def test_overwrite_onto_a_run_of_another_command_is_one_line(tmp_path, capsys, earlier_run,
                                                             argv):
    out = copy_of(earlier_run[1], tmp_path / "out")
    before = sorted(p.name for p in out.iterdir())
    capsys.readouterr()
    assert main([*argv, "--out", str(out), "--overwrite"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "it holds the output of a run" in err[0], err
    assert sorted(p.name for p in out.iterdir()) == before

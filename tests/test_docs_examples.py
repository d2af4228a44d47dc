"""Every Python block of the README and of docs/ runs, and what it says it prints is what it
prints.

Each ```python (or ```py) block runs in a fresh namespace, in a temporary working folder
that holds a link to ``examples/`` (so a block may read ``examples/two_10_storey.toml`` and
writes nothing into the repository). A block that is deliberately not run is listed in
:data:`NOT_RUN` with the reason: the list is empty, and a block that cannot run is a
failure.

What a block says it prints is checked against what it prints:

* an expression statement or a ``print(...)`` whose line ends in a comment that starts with
  a value (a number, or a ``[``, ``(``, ``{`` or quote that opens a literal), for example
  ``gm.npts, gm.dt, gm.duration   # 2000, 0.02 s, 39.98 s``: the comment up to the first
  ``: `` (prose after it) is the value shown. A Python literal is compared element by
  element, numbers to one unit in their last shown digit (the doc rounds or cuts); other
  text by its numbers, in order, to the same tolerance (units and words between them are
  the doc's);
* a ```text block right after a Python block (only blank lines between) is that block's
  whole printed output, compared line by line the same way (numbers as above, every other
  character exactly, runs of spaces as one).

A comment that starts with a value but is not output is listed in :data:`NOT_OUTPUT`;
:data:`CHECKS` adds checks a comment cannot state (prose numbers, objects without a
literal form).
"""

from __future__ import annotations

import ast
import contextlib
import io
import math
import re
import tokenize
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
FENCE = re.compile(r"^```(?:python|py)[ \t]*\n(.*?)^```[ \t]*\n(?:[ \t]*\n)*"
                   r"(?:```text[ \t]*\n(.*?)^```[ \t]*$)?", re.DOTALL | re.MULTILINE)
NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?…?(?![\w.])")


def _blocks() -> list[tuple[str, str, str | None]]:
    out = []
    for page in PAGES:
        text = page.read_text(encoding="utf-8")
        for m in FENCE.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            out.append((f"{page.relative_to(ROOT)}:{line}", m.group(1), m.group(2)))
    return out


BLOCKS = _blocks()

NOT_RUN: dict[str, str] = {}
"""Block id ("page:line") → why it is not run. Empty: every block runs."""

NOT_OUTPUT: set[str] = set()
"""Source lines whose trailing comment starts like a value but describes, not shows."""

CHECKS: dict[str, Callable[[dict[str, Any], str], None]] = {}
"""Block id → a check of its namespace and printed output beyond what comments state."""


def check(page: str, line: str) -> Callable[[Callable[[dict[str, Any], str], None]],
                                             Callable[[dict[str, Any], str], None]]:
    """Register a check for the one block of ``page`` that has the line ``line``."""
    def register(fn: Callable[[dict[str, Any], str], None]
                 ) -> Callable[[dict[str, Any], str], None]:
        ids = [i for i, code, _ in BLOCKS
               if i.startswith(page + ":") and line in code.splitlines()]
        assert len(ids) == 1, (page, line, ids)
        CHECKS[ids[0]] = fn
        return fn
    return register


# ------------------------------------------------------------------ comparing values
def _tolerance(shown: str) -> float:
    """Half a unit in the last digit shown (the doc rounds): '0.590' → 5e-4, '7.15e5' → 500,
    '2000' → 0.5; a whole unit where the doc cuts the number short ('31582734.08…')."""
    cut = shown.endswith("…")
    mantissa, _, exponent = shown.rstrip("…").lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return (1.0 if cut else 0.5) * 10.0 ** (int(exponent or 0) - decimals)


def _numbers(text: str) -> list[str]:
    return NUMBER.findall(text)


def _same_number(value: float, shown: str, where: str) -> None:
    expected = float(shown.rstrip("…"))
    assert math.isfinite(value), f"{where}: got {value}, the doc shows {shown}"
    assert abs(value - expected) <= _tolerance(shown) * (1 + 1e-9), (
        f"{where}: got {value!r}, the doc shows {shown}")


def _flatten(value: Any) -> list[Any]:
    if isinstance(value, np.ndarray):
        return [x for v in value.tolist() for x in _flatten(v)] if value.ndim else [value.item()]
    if isinstance(value, (list, tuple)):
        return [x for v in value for x in _flatten(v)]
    if isinstance(value, dict):
        return [x for k, v in value.items() for x in (*_flatten(k), *_flatten(v))]
    if isinstance(value, np.generic):
        return [value.item()]
    return [value]


def _compare_literal(value: Any, literal: Any, shown: str, where: str) -> None:
    got, want = _flatten(value), _flatten(literal)
    assert len(got) == len(want), f"{where}: got {value!r}, the doc shows {shown}"
    # the digits of a quoted name ('station (column 2)') are compared with the string
    shown_numbers = iter(_numbers(re.sub(r"'[^']*'|\"[^\"]*\"", "''", shown)))
    for g, w in zip(got, want):
        if isinstance(w, bool) or not isinstance(w, (int, float)):
            assert g == w, f"{where}: got {value!r}, the doc shows {shown}"
        else:
            _same_number(float(g), next(shown_numbers), where)


def _compare_text(printed: str, shown: str, where: str) -> None:
    got, want = _numbers(printed), _numbers(shown)
    assert len(got) == len(want), f"{where}: printed {printed!r}, the doc shows {shown!r}"
    for g, w in zip(got, want):
        _same_number(float(g), w, where)


def _compare_output(printed: str, shown: str, where: str) -> None:
    """A whole printed output against a ```text block: numbers to their last shown digit,
    everything else exactly (runs of spaces as one)."""
    got, want = printed.rstrip("\n").splitlines(), shown.rstrip("\n").splitlines()
    assert len(got) == len(want), f"{where}: printed\n{printed}\nthe doc shows\n{shown}"
    for g, w in zip(got, want):
        assert " ".join(NUMBER.sub("#", g).split()) == " ".join(NUMBER.sub("#", w).split()), (
            f"{where}: printed {g!r}, the doc shows {w!r}")
        _compare_text(g, w, where)


def _shown_value(comment: str) -> str | None:
    """The value a trailing comment shows, or None if it starts with prose."""
    text = comment.lstrip("#").strip()
    if text.split(" ")[0].rstrip(",") in ("True", "False", "None"):
        return text.split(" ")[0].rstrip(",")
    if not text or not (text[0].isdigit() or text[0] in "-+.[({'\""):
        return None
    shown = text.split(": ", 1)[0].strip()
    try:
        ast.literal_eval(shown)
    except (ValueError, SyntaxError):
        if not _numbers(shown):
            return None  # "(n_damping, n_periods)", "[N] per storey": words, not a value
    return shown


# ------------------------------------------------------------------ running a block
def run_block(code: str, where: str) -> tuple[dict[str, Any], str, list[str]]:
    """Run ``code`` statement by statement; return its namespace, everything it printed,
    and the value comments it checked (their source lines)."""
    tree = ast.parse(code, filename=where)
    comments = {tok.start[0]: tok.string for tok in
                tokenize.generate_tokens(io.StringIO(code).readline)
                if tok.type == tokenize.COMMENT}
    lines = code.splitlines()
    namespace: dict[str, Any] = {"__name__": "__docs_example__"}
    printed = io.StringIO()
    checked = []
    for stmt in tree.body:
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            if isinstance(stmt, ast.Expr):
                value = eval(compile(ast.Expression(stmt.value), where, "eval"),  # noqa: S307
                             namespace)
            else:
                exec(compile(ast.Module([stmt], []), where, "exec"), namespace)  # noqa: S102
                value = None
        printed.write(out.getvalue())
        end = stmt.end_lineno or stmt.lineno
        comment = comments.get(end)
        source = lines[end - 1].split("#")[0].strip()
        if not isinstance(stmt, ast.Expr) or comment is None or source in NOT_OUTPUT:
            continue
        shown = _shown_value(comment)
        if shown is None:
            continue
        here = f"{where}, line {end} ({source})"
        is_print = (isinstance(stmt.value, ast.Call) and isinstance(stmt.value.func, ast.Name)
                    and stmt.value.func.id == "print")
        if is_print:
            _compare_text(out.getvalue(), shown, here)
        else:
            try:
                literal = ast.literal_eval(shown)
            except (ValueError, SyntaxError):
                _compare_text(repr(value) if not isinstance(value, tuple) else
                              " ".join(repr(v) for v in _flatten(value)), shown, here)
            else:
                _compare_literal(value, literal, shown, here)
        checked.append(source)
    return namespace, printed.getvalue(), checked


@pytest.fixture
def in_a_scratch_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    (tmp_path / "examples").symlink_to(ROOT / "examples", target_is_directory=True)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_blocks_are_found_on_every_page_that_has_them() -> None:
    pages = {where.split(":")[0] for where, _, _ in BLOCKS}
    assert {"README.md", "docs/engine.md", "docs/gap.md", "docs/mitigation.md",
            "docs/ground_motion.md", "docs/walls.md", "docs/storey_laws.md",
            "docs/spectra.md", "docs/structures.md", "docs/buildings.md",
            "docs/collision.md"} <= pages
    assert len(BLOCKS) >= 46
    assert set(NOT_RUN) <= {where for where, _, _ in BLOCKS}


@pytest.mark.parametrize(("where", "code", "output"), BLOCKS,
                         ids=[where for where, _, _ in BLOCKS])
def test_doc_block_runs_and_prints_what_it_says(where: str, code: str, output: str | None,
                                                in_a_scratch_folder: Path,
                                                request: pytest.FixtureRequest) -> None:
    if where in NOT_RUN:
        pytest.skip(NOT_RUN[where])
    if "openseespy" in code:
        request.getfixturevalue("opensees")  # the peers extra (conftest.py): skip, or fail in CI
    namespace, printed, _ = run_block(code, where)
    if output is not None:
        _compare_output(printed, output, where)
    if where in CHECKS:
        CHECKS[where](namespace, printed)


# ------------------------------------------------------------------ checks of prose numbers
@check("README.md", "result = simulate(model, el_centro())")
def _readme(ns: dict[str, Any], printed: str) -> None:
    peaks = ns["result"].contact_peaks
    assert list(peaks) == ["B1F1-B2F1"] and peaks["B1F1-B2F1"].impacts == 26


NOT_OUTPUT.add("result.contact_peaks")  # a ContactPeak has no literal form: _readme


@check("docs/engine.md", "res = simulate(model, el_centro())")
def _engine(ns: dict[str, Any], printed: str) -> None:
    # the first line printed: impacts, peak force [N], energy balance error (round-off)
    impacts, force, error = _numbers(printed.splitlines()[0])
    assert int(impacts) == ns["res"].n_impacts == 26
    assert float(force) == pytest.approx(5.2738193e6, rel=1e-6) and float(error) < 1e-8


@check("docs/buildings.md", "print(right.labels, [c.label for c in model.contacts][:2])")
def _buildings_matrix(ns: dict[str, Any], printed: str) -> None:
    assert printed == "('F1', 'F2', 'F3', 'F4') ['B1F1-B2F1', 'B1F2-B2F2']\n"


def test_the_comparisons_catch_a_wrong_number() -> None:
    """The checker itself: a value off by more than its last shown digit fails, one within
    it passes, and a comment of prose is not read as a value."""
    ns, _, checked = run_block("x = 0.5904\nx  # 0.590 g\n", "t")
    assert checked == ["x"]
    with pytest.raises(AssertionError, match="the doc shows 0.592"):
        run_block("x = 0.5904\nx  # 0.592 g\n", "t")
    with pytest.raises(AssertionError, match="the doc shows"):
        run_block("print(3, [4.0, 7.0])  # 3 [ 4.  8.]\n", "t")
    run_block("print(3, [4.0, 7.0])  # 3 [ 4.  7.]\n", "t")
    with pytest.raises(AssertionError):
        run_block("['a', 'b']  # ['a', 'c']\n", "t")
    assert run_block("x = 1\nx  # the first\n", "t")[2] == []
    with pytest.raises(AssertionError, match="the doc shows 0.66"):
        _compare_output("e = 0.65\n", "e = 0.66\n", "t")  # (a wrong number)
    _compare_output("e = 0.6512  t = 2\n", "e = 0.651 t = 2\n", "t")

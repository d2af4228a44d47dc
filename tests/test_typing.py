"""The package type-checks: mypy, with the project's configuration (``[tool.mypy]`` in
pyproject.toml: the whole of ``src/pounding``, ``check_untyped_defs``, unused ignores
reported), finds no error.

mypy runs as ``python -m mypy`` from the repository root, so what it checks is what a
developer's ``mypy`` checks. Its incremental cache lives in the system's temporary folder,
one per checkout (never in the working folder): the first run on a machine analyses
NumPy, pandas, matplotlib, xarray, … as well, about 21 s of CPU (31–38 s on a loaded
2-core machine, 2026-12); later runs re-check only what changed (0.4 s with nothing
changed, about 4 s of CPU after every module of the package changed).
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import re
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _cache_dir() -> Path:
    """mypy's incremental cache for this checkout, in the temporary folder."""
    key = hashlib.sha256(str(ROOT).encode()).hexdigest()[:12]
    return Path(tempfile.gettempdir()) / f"pounding-mypy-cache-{key}"


def test_mypy_finds_no_error() -> None:
    if importlib.util.find_spec("mypy") is None:
        reason = 'mypy is not installed (pip install -e ".[test]")'
        if os.environ.get("CI"):
            pytest.fail(f"{reason} [CI type-checks the package]", pytrace=False)
        pytest.skip(reason)
    run = subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(_cache_dir())],
                         cwd=ROOT, capture_output=True, text=True, timeout=600, check=False)
    errors = [ln for ln in run.stdout.splitlines() if ": error: " in ln]
    by_file = Counter(ln.split(":", 1)[0] for ln in errors)
    summary = "\n".join(f"{n:4d}  {path}" for path, n in by_file.most_common())
    assert run.returncode == 0 and not errors, (
        f"mypy exit status {run.returncode}, {len(errors)} error(s):\n{summary}\n\n"
        + "\n".join(errors[:60]) + f"\n{run.stderr[-2000:]}")
    assert re.search(r"^Success: no issues found in \d+ source files", run.stdout, re.M), \
        run.stdout[-2000:]

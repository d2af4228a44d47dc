"""The package's metadata: one version string, a licence file and a PEP 639 licence."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pounding

ROOT = Path(__file__).resolve().parents[1]


def _pyproject() -> dict:
    return tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))


def test_the_version_is_written_once_in_pounding_init() -> None:
    data = _pyproject()
    assert "version" not in data["project"], "pyproject.toml must not repeat the version"
    assert "version" in data["project"]["dynamic"]
    assert data["tool"]["setuptools"]["dynamic"]["version"] == {"attr": "pounding.__version__"}
    # setuptools reads the attribute without importing pounding when it is a literal
    init = (ROOT / "src" / "pounding" / "__init__.py").read_text(encoding="utf-8")
    literal = re.findall(r'^__version__ = "([^"]+)"$', init, flags=re.MULTILINE)
    assert literal == [pounding.__version__]


def test_the_licence_is_mit_with_its_file_and_a_backend_that_reads_it() -> None:
    data = _pyproject()
    project = data["project"]
    assert project["license"] == "MIT"
    assert project["license-files"] == ["LICENSE"]
    # a PEP 639 licence expression and no licence classifier beside it
    assert not any(c.startswith("License ::") for c in project.get("classifiers", []))
    requires = data["build-system"]["requires"]
    found = [r for r in requires if r.replace(" ", "").startswith("setuptools")]
    assert found, requires
    m = re.fullmatch(r"setuptools>=(\d+)(\.\d+)*", found[0].replace(" ", ""))
    assert m and int(m.group(1)) >= 77, "license = \"MIT\" (PEP 639) needs setuptools >= 77"
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("MIT License")
    assert "Copyright (c) 2026 The pounding developers" in text

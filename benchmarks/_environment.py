"""What every comparison benchmark prints first and parses the same way: the machine, the
versions and the load (timings on a shared machine mean little without them), and the
``--sections`` list."""

from __future__ import annotations

import argparse
import datetime as _dt
import os
import platform
import subprocess
from collections.abc import Sequence
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def load() -> str:
    """The machine's load averages (1, 5, 15 min), as a phrase."""
    try:
        return "load average " + " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:
        return "load average unknown"


def print_environment(kept_memory: bool) -> None:
    """Date and commit, where pounding was imported from, the versions of Python, OpenSeesPy
    and NumPy, the CPUs, the load, and whether freed memory is kept (``_memory.py``)."""
    from importlib.metadata import PackageNotFoundError, version

    import numpy as np

    import pounding

    try:
        ops_version = version("openseespy")
    except PackageNotFoundError:
        ops_version = "not installed"
    try:
        commit = subprocess.run(["git", "-C", str(ROOT), "log", "-1", "--format=%h %cs"],
                                capture_output=True, text=True).stdout.strip()
    except OSError:
        commit = "?"
    print(f"{_dt.date.today()}, commit {commit or '?'}; pounding from {pounding.__file__}")
    print(f"python {platform.python_version()}, openseespy {ops_version}, "
          f"numpy {np.__version__}, {os.cpu_count()} CPUs "
          f"({platform.processor() or platform.machine()}); {load()}")
    print("malloc: freed memory kept for reuse (mallopt)" if kept_memory else
          "malloc: as configured")


def parse_list(ap: argparse.ArgumentParser, text: str, allowed: Sequence[str],
               what: str = "section") -> list[str]:
    """A comma-separated option as a list, each item one of ``allowed`` (else a usage
    error naming the unknown ones)."""
    items = [s.strip() for s in text.split(",") if s.strip()]
    bad = [s for s in items if s not in allowed]
    if bad:
        ap.error(f"unknown {what}(s) {bad}; choose from {list(allowed)}")
    return items

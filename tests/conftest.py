"""Fixtures shared by the test files."""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

import pytest


@pytest.fixture
def read_only_folder(tmp_path: Path) -> Iterator[Path]:
    """A folder nobody running the tests can write in.

    For a user: a folder of ``tmp_path`` made read-only (mode 0555, restored afterwards).
    Root writes in any folder whatever its mode, so as root (CI containers run as root):
    ``/proc/sys``, read-only for root too in a container. Skipped, saying why, only where
    neither holds (root on a host whose /proc/sys root may write).
    """
    if os.geteuid() != 0:
        ro = tmp_path / "ro"
        ro.mkdir()
        ro.chmod(0o555)
        try:
            yield ro
        finally:
            ro.chmod(0o755)
        return
    if Path("/proc/sys").is_dir() and not os.access("/proc/sys", os.W_OK):
        yield Path("/proc/sys")
        return
    pytest.skip("root may write in a read-only folder, and /proc/sys is writable here")

"""Files pounding writes get the permissions an ordinary write would (0666 less the
umask), and reading the umask never sets it: ``os.umask`` is never called, even where
``/proc`` cannot tell it (the umask is one for every thread of the process)."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

import pounding.io.files as pio


@pytest.fixture
def umask_027():
    old = os.umask(0o027)  # (the test's own setting, put back after it)
    try:
        yield
    finally:
        os.umask(old)


def _forbid_umask(monkeypatch: pytest.MonkeyPatch) -> None:
    def refuse(mask: int) -> int:
        raise AssertionError(f"os.umask({mask:#o}) called: it sets the umask of every thread")

    monkeypatch.setattr(os, "umask", refuse)


@pytest.mark.parametrize("proc", [True, False], ids=["with /proc", "without /proc"])
def test_the_umask_is_read_without_setting_it(umask_027, monkeypatch, tmp_path, proc):
    if not proc:  # as on macOS: no /proc/self/status
        real = Path.read_text

        def no_proc(self: Path, *args, **kwargs):
            if str(self).startswith("/proc/"):
                raise FileNotFoundError(self)
            return real(self, *args, **kwargs)

        monkeypatch.setattr(Path, "read_text", no_proc)
    _forbid_umask(monkeypatch)
    assert pio.umask() == 0o027
    target = pio.write_text(tmp_path / "a.txt", "text")
    assert stat.S_IMODE(target.stat().st_mode) == 0o640

"""Fixtures shared by the test files."""

from __future__ import annotations

import importlib
import os
from collections.abc import Iterator
from pathlib import Path
from typing import Any

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


# ------------------------------------------------------------------ peer tools
PEERS_INSTALL = 'pip install -e ".[test,peers]"'


def import_peer(module: str) -> Any:
    """Import a peer tool the tests compare against (OpenSeesPy, ObsPy; the ``peers`` extra).

    Where it cannot be imported the test is skipped, saying why and what to install — but
    under CI (``CI`` set, as ``.ci/run`` runs) it fails: every comparison runs there.
    """
    try:
        return importlib.import_module(module)
    except ModuleNotFoundError as exc:
        reason = f"{module}: {exc.name} is not installed ({PEERS_INSTALL})"
    except (ImportError, RuntimeError, OSError) as exc:
        # openseespy installed but its compiled library does not load: on Linux it needs
        # the system's BLAS and LAPACK (libblas.so.3, liblapack.so.3)
        root: BaseException = exc
        while root.__context__ is not None:  # openseespy re-raises: show the first error
            root = root.__context__
        detail = str(exc) if root is exc else f"{exc} ({root})"
        reason = (f"{module} is installed but does not load: {detail}; install the system "
                  "BLAS/LAPACK it links to (Debian/Ubuntu: bash ci/install_peers.sh, which "
                  "runs apt-get install libblas3 liblapack3)")
    if os.environ.get("CI"):
        pytest.fail(f"{reason} [CI runs every peer comparison]", pytrace=False)
    pytest.skip(reason)


@pytest.fixture
def opensees() -> Iterator[Any]:
    """``openseespy.opensees``, its model domain wiped before and after the test."""
    ops = import_peer("openseespy.opensees")
    ops.wipe()
    yield ops
    ops.wipe()


@pytest.fixture
def obspy() -> Any:
    """The ``obspy`` package."""
    return import_peer("obspy")

"""Every module whose compiled functions the kernel's entry point pulls in is listed in
``kernel_cache.KERNEL_MODULES``: a change to an unlisted one would leave a stale compiled
kernel in numba's cache (exact_maxwell was missing when it joined the kernel)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

SRC = Path(__file__).resolve().parents[2] / "src"

CODE = """
import sys
import pounding.integrate.kernel
from numba.core.registry import CPUDispatcher
from pounding.integrate.kernel_cache import KERNEL_MODULES
compiled = sorted(n for n, m in list(sys.modules.items()) if n.startswith("pounding.")
                  and any(isinstance(o, CPUDispatcher) and o.__module__ == n
                          for o in vars(m).values()))
print(len(compiled), [n for n in compiled if n not in KERNEL_MODULES])
"""


def test_every_compiled_module_of_the_kernel_is_stamped() -> None:
    # a fresh interpreter: only what importing the kernel loads
    out = subprocess.run([sys.executable, "-c", CODE], capture_output=True, text=True,
                         check=True, env={"PYTHONPATH": str(SRC), "PATH": ""}).stdout.split(" ", 1)
    assert int(out[0]) >= 15  # the kernel's own and the laws' modules were found
    assert out[1].strip() == "[]"

"""pounding keeps freed memory for reuse between simulations (:mod:`pounding.allocator`), and
``POUNDING_KEEP_FREED_MEMORY=0`` leaves glibc alone.

Checked by what the setting is for, counted by the kernel rather than by pounding: the minor
page faults (``getrusage``) of later ``simulate`` calls of the two 10-storey buildings in a
fresh process. A call that reuses the memory the last one freed faults in a few new pages;
one handed fresh ``mmap`` pages for its outputs faults on each (measured: ~2,445 pages a call,
about 10 MB, every call — glibc's own dynamic threshold stops at 32 MB and does not cover
them; the seed pair's smaller outputs it does cover after two calls).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
CODE = """
import json, resource
from pounding.config import load_config
from pounding.example_files import example_path
from pounding.integrate import simulate
from pounding.allocator import keep_freed_memory
m, g, s = load_config(example_path("two_10_storey.toml")).build()
simulate(m, g, **s)
faults = []
for _ in range(3):
    before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    simulate(m, g, **s)
    faults.append(resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before)
print(json.dumps({"kept": keep_freed_memory(), "faults": min(faults)}))
"""


def _run(env_value: str | None) -> dict:
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    env.pop("POUNDING_KEEP_FREED_MEMORY", None)
    if env_value is not None:
        env["POUNDING_KEEP_FREED_MEMORY"] = env_value
    out = subprocess.run([sys.executable, "-c", CODE], env=env, capture_output=True, text=True,
                         timeout=600, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="glibc's mallopt")
def test_a_second_simulation_reuses_freed_memory_unless_told_not_to() -> None:
    kept = _run(None)
    left_alone = _run("0")
    assert kept["kept"] is True and left_alone["kept"] is False
    # ~2,445 fresh pages a call without the setting; about one with it
    assert left_alone["faults"] > 1000, left_alone
    assert kept["faults"] < left_alone["faults"] / 5, (kept, left_alone)

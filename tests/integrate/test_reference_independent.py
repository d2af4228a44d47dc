"""The SciPy reference shares no code with the compiled kernel, so a kernel-versus-reference
test can catch an error in either: its modules import nothing from the kernel's side of
``pounding.integrate`` (the kernel, its model arrays, right-hand side, events, commits, output
grid, ground interpolation, starting state …) nor the compiled law dispatchers, and call no
compiled law trial. Before, the reference took ``contact_trial``, ``ground_on_grid``,
``grid_step`` and ``initial_state`` from the kernel's side. Its own pieces are checked here
against closed forms."""

from __future__ import annotations

import ast
import importlib.util
import math
import pkgutil
from pathlib import Path

import numpy as np
import pytest

import pounding.integrate
from pounding.contact import (
    BilinearImpact,
    Hertz,
    HuntCrossley,
    KelvinVoigt,
    LinearSpring,
    ModifiedKelvinVoigt,
    NonlinearViscoelastic,
)
from pounding.ground_motion import GroundMotion, GroundMotionComponents
from pounding.integrate.reference_inputs import (
    ground_at,
    knots,
    output_step,
    output_times,
)
from pounding.integrate.reference_laws import contact_force, stored_energy

REFERENCE = ("pounding.integrate.reference", "pounding.integrate.reference_laws",
             "pounding.integrate.reference_inputs")
COMPILED_LAWS = ("pounding.contact.dispatch", "pounding.contact.kernels",
                 "pounding.hysteresis.dispatch", "pounding.devices.laws")


def _imports(module: str) -> list[tuple[str, str]]:
    """Every ``(module, name)`` the module's source imports, anywhere in it (also inside
    functions and under TYPE_CHECKING); ``name`` is empty for ``import module``."""
    path = Path(importlib.util.find_spec(module).origin)
    package = module.rsplit(".", 1)[0]
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out += [(alias.name, "") for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package.split(".")
                base = ".".join(parts[: len(parts) - node.level + 1] + ([base] if base else []))
            out += [(base, alias.name) for alias in node.names]
    return out


def test_the_reference_imports_nothing_from_the_kernel_side():
    kernel_side = {f"pounding.integrate.{m.name}"
                   for m in pkgutil.iter_modules(pounding.integrate.__path__)} - set(REFERENCE)
    assert {"pounding.integrate.kernel", "pounding.integrate.rhs", "pounding.integrate.grid",
            "pounding.integrate.start", "pounding.integrate.kernel_model"} <= kernel_side
    for module in REFERENCE:
        for source, name in _imports(module):
            full = f"{source}.{name}" if name else source
            assert source not in kernel_side and full not in kernel_side, (module, full)
            # the package itself: its names are the kernel's (simulate, grid_step, …)
            assert source != "pounding.integrate" or full in REFERENCE, (module, full)
            assert source not in COMPILED_LAWS, (module, full)
            assert not name.endswith("_trial") and name != "respond_path", (module, full)


@pytest.mark.parametrize("law, delta, rate, v0, expected", [
    (LinearSpring(k=1e8), 1e-3, 0.5, 0.5, 1e5),
    (KelvinVoigt(k=1e8, c=1e5), 1e-3, 0.5, 0.5, 1e5 + 5e4),
    (KelvinVoigt(k=1e8, c=1e5), 1e-3, -2.0, 0.5, 0.0),  # clipped
    (KelvinVoigt(k=1e8, c=1e5, tension=True), 1e-3, -2.0, 0.5, 1e5 - 2e5),
    (ModifiedKelvinVoigt(k=1e8, c=1e5), 1e-3, 0.5, 0.5, 1.5e5),
    (ModifiedKelvinVoigt(k=1e8, c=1e5), 1e-3, -0.5, 0.5, 1e5),
    (Hertz(k_h=1e10), 1e-2, 0.3, 0.5, 1e10 * 1e-3),
    (HuntCrossley(k_h=1e10, chi=0.4), 1e-2, 0.25, 0.5, 1e7 * 1.2),
    (NonlinearViscoelastic(k_h=1e10, zeta=0.3, m_eff=1e5), 1e-2, 0.5,
     0.5, 1e7 + 2 * 0.3 * math.sqrt(1e10 * 0.1 * 1e5) * 0.5),
    (NonlinearViscoelastic(k_h=1e10, zeta=0.3, m_eff=1e5), 1e-2, -0.5, 0.5, 1e7),
])
def test_reference_contact_forces_are_the_published_equations(law, delta, rate, v0, expected):
    assert contact_force(law, delta, rate, v0, 0.0)[0] == pytest.approx(expected, rel=1e-12)


def test_reference_bilinear_element_traces_its_parallelogram():
    """Muthukumar's element (K1 = 3e8, K2 = 1e8, δy = 1 mm) loaded to 3 mm and unloaded:
    K1 to δy, then K2; back down along K1 from (3 mm, 5e5 N) to the line K2 δ, then along
    it; the energy stored at the top is ½ K2 δ² + ½ (K1 − K2) δy²."""
    law = BilinearImpact(K1=3e8, K2=1e8, delta_y=1e-3)
    slip = 0.0
    up = {}
    for d in np.linspace(1e-4, 3e-3, 30):
        up[round(d, 6)], slip = contact_force(law, d, 1.0, 1.0, slip)
    assert up[0.0005] == pytest.approx(3e8 * 5e-4)
    assert up[0.003] == pytest.approx(3e8 * 1e-3 + 1e8 * 2e-3)
    assert stored_energy(law, 3e-3, slip) == pytest.approx(0.5 * 1e8 * 9e-6 + 0.5 * 2e8 * 1e-6)
    f, slip = contact_force(law, 2.5e-3, -1.0, 1.0, slip)
    assert f == pytest.approx(5e5 - 3e8 * 5e-4)
    f, slip = contact_force(law, 1e-3, -1.0, 1.0, slip)
    assert f == pytest.approx(1e8 * 1e-3)  # on the line K2 δ below δ = 2 mm


def test_reference_ground_is_linear_between_samples_and_returns_to_zero_after_the_record():
    gm = GroundMotion(0.02, np.array([0.0, 1.0, -2.0]), name="three samples")
    assert output_step(0.02, 0.007) == pytest.approx(0.02 / 3)
    t = output_times(0.005, 0.1)
    assert t[-1] == pytest.approx(0.1) and t.size == 21
    dt, values = knots(gm, 0.1)
    a = ground_at(t, dt, values)[:, 0]
    expected = np.interp(t, [0.0, 0.02, 0.04, 0.06], [0.0, 1.0, -2.0, 0.0], right=0.0)
    np.testing.assert_allclose(a, expected, atol=1e-15)
    two = GroundMotionComponents.of(gm, GroundMotion(0.02, np.array([3.0]), name="one"))
    dt, values = knots(two, 0.1)
    np.testing.assert_allclose(ground_at(np.array([0.01]), dt, values), [[0.5, 1.5]])

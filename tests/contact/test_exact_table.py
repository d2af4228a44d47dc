"""The tabulated exact inverses (:mod:`pounding.contact.exact_table`) are what their solvers
give: a model file's ``e`` of two decimals reads its damping from the table, so the table
must hold the solution, not a stale or rounded copy of it."""

from __future__ import annotations

import math

import pytest

from pounding.contact import exact_restitution as ex
from pounding.contact import exact_table


@pytest.mark.parametrize("name", ["ZETA_KELVIN_VOIGT_CLIPPED", "ZETA_MODIFIED_KELVIN_VOIGT",
                                  "CHI_HUNT_CROSSLEY"])
def test_every_tabulated_value_is_its_solution(name: str) -> None:
    """The closed-form inverses (Brent's method on a closed form, ms each): every entry
    solved again, to round-off (1e-14 relative: the solvers stop at 8.9e-16)."""
    table = getattr(exact_table, name)
    assert tuple(table) == ex.TABULATED_E
    solve = ex._SOLVERS[name]
    for e, value in table.items():
        assert value == pytest.approx(solve(e), rel=1e-14, abs=0.0), (name, e)


@pytest.mark.parametrize("e", [0.05, 0.5, 0.65, 0.9])
def test_tabulated_nonlinear_viscoelastic_zeta_achieves_its_e(e: float) -> None:
    """Jankowski's law (a dozen integrations an e, so a sample): the tabulated ζ is the
    solver's to its documented 1e-13 relative, and the law with it achieves e (the
    approach integrated independently of the table, to the solver's tolerance)."""
    zeta = exact_table.ZETA_NONLINEAR_VISCOELASTIC[e]
    assert zeta == pytest.approx(ex._zeta_nonlinear_viscoelastic_exact(e), rel=1e-12)
    assert ex.restitution_nonlinear_viscoelastic(zeta) == pytest.approx(e, rel=1e-10)


def test_a_tabulated_e_needs_no_scipy_and_any_other_e_is_solved() -> None:
    """A model file's e = 0.65 takes every exact inverse from the table, without SciPy's
    root finder (checked in a fresh interpreter); an e off the table (0.655) is solved, and
    lies between its neighbours' (each inverse falls with e)."""
    import subprocess
    import sys

    code = ("import sys\nfrom pounding.contact import exact_restitution as ex\n"
            "for f in (ex.zeta_kelvin_voigt_clipped, ex.zeta_modified_kelvin_voigt_exact,\n"
            "          ex.chi_hunt_crossley_exact, ex.zeta_nonlinear_viscoelastic_exact):\n"
            "    f(0.65)\n"
            "print('scipy.optimize' in sys.modules, 'scipy.integrate' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, timeout=120).stdout.split()
    assert out == ["False", "False"]
    for f, name in ((ex.zeta_kelvin_voigt_clipped, "ZETA_KELVIN_VOIGT_CLIPPED"),
                    (ex.chi_hunt_crossley_exact, "CHI_HUNT_CROSSLEY")):
        table = getattr(exact_table, name)
        assert table[0.66] < f(0.655) < table[0.65]
    assert ex.zeta_kelvin_voigt_clipped(1.0) == 0.0
    assert math.isclose(float(ex.zeta_kelvin_voigt_clipped([0.65])[0]),
                        exact_table.ZETA_KELVIN_VOIGT_CLIPPED[0.65])

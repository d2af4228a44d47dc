"""The code rule's one factor holds the suite's mean at ≥ 90 % of the target at *every*
period of the range — checked on a dense grid of its own (3000 periods and the target's
corners), not on the grid the factor was found on (the spectra there by the exact kernel,
itself checked against the plain reference and SciPy in ``test_response_spectrum.py``). A grid alone let the mean dip below 90 % between its periods and at the target's
corners (0.2 % on the bundled suite with 100 periods)."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.ground_motion import bundled_suite
from pounding.spectra import DesignSpectrum, scale_suite
from pounding.spectra.response import response_spectrum


def _mean_psa_g(suite, periods, factor):
    return factor * np.mean([response_spectrum(m, periods, 0.05).psa_g[0] for m in suite],
                            axis=0)


@pytest.mark.parametrize("target, t1, code", [
    (DesignSpectrum.asce7(1.0, 0.6), 1.0, "asce7-22"),       # T_S = 0.6 s inside 0.2–2 s
    (DesignSpectrum.eurocode8(0.3, "C", 1), 0.8, "en1998-1"),     # T_B 0.2, T_C 0.6 s inside
    (DesignSpectrum([0.0, 0.3, 0.45, 0.7, 1.5, 4.0], [0.4, 1.0, 0.8, 1.1, 0.5, 0.1]),
     1.2, "asce7-22"),                                          # a table: every period a corner
])
def test_the_mean_is_at_least_90_percent_of_the_target_at_every_period(target, t1, code):
    suite = [m.trimmed(8.0) for m in list(bundled_suite())[:3]]
    r = scale_suite(suite, target, t1, method="code", code=code, n_periods=20)
    lo, hi = r.period_range
    corners = target.corners[(target.corners >= lo) & (target.corners <= hi)]
    dense = np.unique(np.r_[np.geomspace(lo, hi, 3000), corners])
    ratio = _mean_psa_g(suite, dense, r.factors[0]) / np.asarray(target.sa_g(dense))
    # the refinement resolves the ratio's peak to far better than 1e-6
    assert ratio.min() >= 0.9 * (1 - 1e-6)
    if code == "asce7-22":  # the factor binds somewhere: the mean touches 90 % (to 1e-3)
        assert ratio.min() == pytest.approx(0.9, rel=1e-3)


def test_the_targets_corners():
    asce = DesignSpectrum.asce7(1.0, 0.6, tl=8.0)
    assert asce.corners == pytest.approx([0.12, 0.6, 8.0])
    ec8 = DesignSpectrum.eurocode8(0.3, "C", 1)  # Table 3.2, Type 1, C: 0.2, 0.6, 2.0 s
    assert ec8.corners == pytest.approx([0.2, 0.6, 2.0])
    table = DesignSpectrum([0.0, 0.5, 1.0], [0.3, 0.9, 0.4])
    assert list(table.corners) == [0.0, 0.5, 1.0]

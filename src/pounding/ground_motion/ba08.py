"""The median of the NGA-West1 ground-motion model of Boore & Atkinson (2008): 5 %-damped
pseudo-spectral acceleration (GMRotI50) and PGA from ``M``, ``R_JB``, ``Vs30`` and the
mechanism. The yardstick of the stochastic motions' spectra (``docs/records.md``).

Boore, D. M. & Atkinson, G. M. (2008), "Ground-motion prediction equations for the average
horizontal component of PGA, PGV, and 5 %-damped PSA at spectral periods between 0.01 s and
10.0 s", *Earthquake Spectra* 24(1), 99–138, doi:10.1193/1.2830434: eq. (1) without its
error term, ``ln Y = F_M(M) + F_D(R_JB, M) + F_S(Vs30, R_JB, M)`` with eqs (3)–(13), the
coefficients of its Tables 3, 6 and 7 and the erratum of 27 August 2008 (``R_ref = 1 km``
for ``pga4nl`` too). The coefficients were read from OpenQuake's hazardlib
(``openquake/hazardlib/gsim/boore_atkinson_2008.py``, which cites the same tables); the
median is checked against hazardlib's verification table (``BA08_MEDIAN_SS.csv``) in the
tests. Periods between those of the table: ln Y interpolated linearly in ln T.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.validation import in_range

__all__ = ["ba08_median"]

# T [s] (0 = PGA), c1, c2, c3, h, e1 (unspecified), e2 (SS), e3 (NS), e4 (RS), e5, e6, e7,
# Mh, blin, b1, b2
_TABLE = np.array([
    [0.0, -0.66050, 0.11970, -0.01151, 1.35, -0.53804, -0.50350, -0.75472, -0.50970,
     0.28805, -0.10164, 0.00000, 6.75, -0.36, -0.64, -0.14],
    [0.01, -0.66220, 0.12000, -0.01151, 1.35, -0.52883, -0.49429, -0.74551, -0.49966,
     0.28897, -0.10019, 0.00000, 6.75, -0.36, -0.64, -0.14],
    [0.02, -0.66600, 0.12280, -0.01151, 1.35, -0.52192, -0.48508, -0.73906, -0.48895,
     0.25144, -0.11006, 0.00000, 6.75, -0.34, -0.63, -0.12],
    [0.03, -0.69010, 0.12830, -0.01151, 1.35, -0.45285, -0.41831, -0.66722, -0.42229,
     0.17976, -0.12858, 0.00000, 6.75, -0.33, -0.62, -0.11],
    [0.05, -0.71700, 0.13170, -0.01151, 1.35, -0.28476, -0.25022, -0.48462, -0.26092,
     0.06369, -0.15752, 0.00000, 6.75, -0.29, -0.64, -0.11],
    [0.075, -0.72050, 0.12370, -0.01151, 1.55, 0.00767, 0.04912, -0.20578, 0.02706,
     0.01170, -0.17051, 0.00000, 6.75, -0.23, -0.64, -0.11],
    [0.10, -0.70810, 0.11170, -0.01151, 1.68, 0.20109, 0.23102, 0.03058, 0.22193,
     0.04697, -0.15948, 0.00000, 6.75, -0.25, -0.60, -0.13],
    [0.15, -0.69610, 0.09884, -0.01113, 1.86, 0.46128, 0.48661, 0.30185, 0.49328,
     0.17990, -0.14539, 0.00000, 6.75, -0.28, -0.53, -0.18],
    [0.20, -0.58300, 0.04273, -0.00952, 1.98, 0.57180, 0.59253, 0.40860, 0.61472,
     0.52729, -0.12964, 0.00102, 6.75, -0.31, -0.52, -0.19],
    [0.25, -0.57260, 0.02977, -0.00837, 2.07, 0.51884, 0.53496, 0.33880, 0.57747,
     0.60880, -0.13843, 0.08607, 6.75, -0.39, -0.52, -0.16],
    [0.30, -0.55430, 0.01955, -0.00750, 2.14, 0.43825, 0.44516, 0.25356, 0.51990,
     0.64472, -0.15694, 0.10601, 6.75, -0.44, -0.52, -0.14],
    [0.40, -0.64430, 0.04394, -0.00626, 2.24, 0.39220, 0.40602, 0.21398, 0.46080,
     0.78610, -0.07843, 0.02262, 6.75, -0.50, -0.51, -0.10],
    [0.50, -0.69140, 0.06080, -0.00540, 2.32, 0.18957, 0.19878, 0.00967, 0.26337,
     0.76837, -0.09054, 0.00000, 6.75, -0.60, -0.50, -0.06],
    [0.75, -0.74080, 0.07518, -0.00409, 2.46, -0.21338, -0.19496, -0.49176, -0.10813,
     0.75179, -0.14053, 0.10302, 6.75, -0.69, -0.47, 0.00],
    [1.0, -0.81830, 0.10270, -0.00334, 2.54, -0.46896, -0.43443, -0.78465, -0.39330,
     0.67880, -0.18257, 0.05393, 6.75, -0.70, -0.44, 0.00],
    [1.5, -0.83030, 0.09793, -0.00255, 2.66, -0.86271, -0.79593, -1.20902, -0.88085,
     0.70689, -0.25950, 0.19082, 6.75, -0.72, -0.40, 0.00],
    [2.0, -0.82850, 0.09432, -0.00217, 2.73, -1.22652, -1.15514, -1.57697, -1.27669,
     0.77989, -0.29657, 0.29888, 6.75, -0.73, -0.38, 0.00],
    [3.0, -0.78440, 0.07282, -0.00191, 2.83, -1.82979, -1.74690, -2.22584, -1.91814,
     0.77966, -0.45384, 0.67466, 6.75, -0.74, -0.34, 0.00],
    [4.0, -0.68540, 0.03758, -0.00191, 2.89, -2.24656, -2.15906, -2.58228, -2.38168,
     1.24961, -0.35874, 0.79508, 6.75, -0.75, -0.31, 0.00],
    [5.0, -0.50960, -0.02391, -0.00191, 2.93, -1.28408, -1.21270, -1.50904, -1.41093,
     0.14271, -0.39006, 0.00000, 8.50, -0.75, -0.291, 0.00],
    [7.5, -0.37240, -0.06568, -0.00191, 3.00, -1.43145, -1.31632, -1.81022, -1.59217,
     0.52407, -0.37578, 0.00000, 8.50, -0.692, -0.247, 0.00],
    [10.0, -0.09824, -0.13800, -0.00191, 3.04, -2.15446, -2.16137, -2.53323, -2.14635,
     0.40387, -0.48492, 0.00000, 8.50, -0.650, -0.215, 0.00],
])
_MECH = {"unspecified": 5, "strike-slip": 6, "normal": 7, "reverse": 8}
_M_REF, _R_REF, _V_REF = 4.5, 1.0, 760.0


def _ln_rock(row: NDArray[np.float64], m: float, r_jb: float, mech: int) -> float:
    """``F_M + F_D`` (eqs 3–5): ln Y [g] on the reference rock, without the site term."""
    c1, c2, c3, h = row[1:5]
    e5, e6, e7, mh = row[9:13]
    fm = row[mech] + (e5 * (m - mh) + e6 * (m - mh) ** 2 if m <= mh else e7 * (m - mh))
    r = math.hypot(r_jb, h)
    return float(fm + (c1 + c2 * (m - _M_REF)) * math.log(r / _R_REF) + c3 * (r - _R_REF))


def _site(row: NDArray[np.float64], vs30: float, pga4nl: float) -> float:
    """``F_S = F_LIN + F_NL`` (eqs 6–13)."""
    blin, b1, b2 = row[13:16]
    v1, v2 = 180.0, 300.0
    if vs30 <= v1:
        bnl = b1
    elif vs30 <= v2:
        bnl = (b1 - b2) * math.log(vs30 / v2) / math.log(v1 / v2) + b2
    elif vs30 < _V_REF:
        bnl = b2 * math.log(vs30 / _V_REF) / math.log(v2 / _V_REF)
    else:
        bnl = 0.0
    a1, a2, pga_low = 0.03, 0.09, 0.06
    if pga4nl <= a1:
        fnl = bnl * math.log(pga_low / 0.1)
    elif pga4nl <= a2:
        dx = math.log(a2 / a1)
        dy = bnl * math.log(a2 / pga_low)
        c = (3.0 * dy - bnl * dx) / dx ** 2
        d = -(2.0 * dy - bnl * dx) / dx ** 3
        x = math.log(pga4nl / a1)
        fnl = bnl * math.log(pga_low / 0.1) + c * x ** 2 + d * x ** 3
    else:
        fnl = bnl * math.log(pga4nl / 0.1)
    return float(blin * math.log(vs30 / _V_REF) + fnl)


def ba08_median(periods: ArrayLike, magnitude: float, r_jb: float, vs30: float,
                mechanism: str = "strike-slip") -> NDArray[np.float64]:
    """Median PSA [g] at ``periods`` [s] (0 for PGA; 0.01–10 s).

    Parameters
    ----------
    periods : array_like
        Periods [s]: 0 (PGA) or within 0.01–10 s.
    magnitude : float
        Moment magnitude (the model's range 5–8).
    r_jb : float
        Joyner–Boore distance [km] (0–200).
    vs30 : float
        [m/s] (180–1300).
    mechanism : str
        ``"strike-slip"``, ``"reverse"``, ``"normal"`` or ``"unspecified"``.
    """
    t = np.atleast_1d(np.asarray(periods, dtype=float))
    m = in_range("magnitude", magnitude, 3.0, 9.0)
    r = in_range("r_jb [km]", r_jb, 0.0, 400.0)
    v = in_range("vs30 [m/s]", vs30, 100.0, 3000.0)
    if mechanism not in _MECH:
        raise ValueError(f"mechanism must be one of {', '.join(_MECH)} (got {mechanism!r})")
    if np.any((t != 0.0) & ((t < 0.01) | (t > 10.0))):
        raise ValueError("periods: 0 (PGA) or within 0.01-10 s")
    mech = _MECH[mechanism]
    pga4nl = math.exp(_ln_rock(_TABLE[0], m, r, mech))
    ln_y = np.array([_ln_rock(row, m, r, mech) + _site(row, v, pga4nl) for row in _TABLE])
    out = np.empty(t.size)
    table_t = _TABLE[1:, 0]
    for i, ti in enumerate(t):
        out[i] = ln_y[0] if ti == 0.0 else np.interp(math.log(ti), np.log(table_t),
                                                      ln_y[1:])
    return np.exp(out)

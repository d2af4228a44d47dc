"""Design spectra: :class:`DesignSpectrum`, a code's elastic design response spectrum as a
table of periods and values, linearly interpolated: the ASCE 7-16 §11.4.6 spectrum built
from ``S_DS``, ``S_D1`` and ``T_L`` (:meth:`DesignSpectrum.asce7`), the Eurocode 8
elastic spectrum of EN 1998-1:2004 §3.2.2.2 (:meth:`DesignSpectrum.eurocode8`), the
spectra of the code checks of NZS 1170.5, NBCC 2020 and IS 1893
(:meth:`DesignSpectrum.nzs1170_5`, :meth:`DesignSpectrum.nbcc2020`,
:meth:`DesignSpectrum.is1893`, formulas in :mod:`pounding.spectra.code_spectra`), and a
user's table; spectrum files in TOML or CSV (:meth:`DesignSpectrum.from_file`). See
``docs/spectra.md`` and ``docs/gap.md``.

Units: periods in s, Sa in any acceleration unit of :mod:`pounding.units` (m/s² internally),
Sd in m.
"""

from __future__ import annotations

import functools
import os
import re
import tomllib
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.units import G, acceleration_factor
from pounding.validation import in_range, positive

__all__ = ["EC8_GROUND_TYPES", "DesignSpectrum"]

FloatArray = NDArray[np.float64]

EC8_GROUND_TYPES: dict[int, dict[str, tuple[float, float, float, float]]] = {
    1: {"A": (1.0, 0.15, 0.4, 2.0), "B": (1.2, 0.15, 0.5, 2.0), "C": (1.15, 0.20, 0.6, 2.0),
        "D": (1.35, 0.20, 0.8, 2.0), "E": (1.4, 0.15, 0.5, 2.0)},
    2: {"A": (1.0, 0.05, 0.25, 1.2), "B": (1.35, 0.05, 0.25, 1.2), "C": (1.5, 0.10, 0.25, 1.2),
        "D": (1.8, 0.10, 0.30, 1.2), "E": (1.6, 0.05, 0.25, 1.2)},
}
"""EN 1998-1:2004 Table 3.2 (Type 1) and Table 3.3 (Type 2), the recommended values: for
each ground type A–E, ``(S, T_B [s], T_C [s], T_D [s])``. A National Annex may choose
others (give them as a table)."""


@dataclass(frozen=True, eq=False, init=False)
class DesignSpectrum:
    """A design spectrum given as a table, linearly interpolated in the period.

    Parameters
    ----------
    periods : array_like
        Periods [s], strictly increasing, ≥ 0.
    values : array_like
        Spectral displacement Sd [m] (``kind="Sd"``) or pseudo-acceleration Sa
        (``kind="Sa"``) in ``units``, one per period, ≥ 0.
    kind : {"Sd", "Sa"}
        What ``values`` are. ``Sd = Sa (T/2π)²`` (pseudo-spectral relation, Chopra §6.6).
    units : str
        For ``Sa``: an acceleration unit of :mod:`pounding.units` (``"g"``, ``"m/s2"``, …);
        for ``Sd``: ``"m"``.
    name : str
        Label.
    formula : callable, optional
        ``Sa(T)`` in ``units`` for an array of periods, where the spectrum is a code's
        closed form (:meth:`asce7`, :meth:`eurocode8`): then :meth:`sd` evaluates it
        exactly instead of interpolating the table (which is kept for plots and files).
    corner_periods : array_like, optional
        The periods [s] where the spectrum changes branch (a code's ``T0, T_S, T_L`` or
        ``T_B, T_C, T_D``), given with a ``formula``. Default: every period of the table,
        where a linearly interpolated table bends. See :attr:`corners`.

    Notes
    -----
    No extrapolation: asking for a period outside the table is an error. The spectrum is
    used as given — a code spectrum is usually for 5 % damping; no damping correction is
    applied for buildings with another damping ratio.
    """

    periods: FloatArray
    values: FloatArray
    kind: str
    units: str
    name: str
    formula: Callable[[FloatArray], FloatArray] | None = field(repr=False)
    corner_periods: FloatArray | None = field(repr=False)
    _sd: FloatArray = field(init=False, repr=False)

    def __init__(self, periods: ArrayLike, values: ArrayLike, kind: str = "Sa",
                 units: str = "g", name: str = "design spectrum",
                 formula: Callable[[FloatArray], FloatArray] | None = None,
                 corner_periods: ArrayLike | None = None) -> None:
        t = np.asarray(periods, dtype=float).ravel()
        v = np.asarray(values, dtype=float).ravel()
        if t.size < 2 or t.size != v.size:
            raise ValueError(f"spectrum {name!r}: need at least 2 periods and as many "
                             f"values (got {t.size} periods, {v.size} values)")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(v))):
            raise ValueError(f"spectrum {name!r}: periods and values must be finite")
        if t[0] < 0 or np.any(np.diff(t) <= 0):
            raise ValueError(f"spectrum {name!r}: periods must be >= 0 and strictly "
                             f"increasing (got {t.tolist()})")
        if np.any(v < 0):
            raise ValueError(f"spectrum {name!r}: values must be >= 0 (got {v.tolist()})")
        spelled = {"sd": "Sd", "sa": "Sa"}.get(str(kind).lower())
        if spelled is None:
            raise ValueError(f"spectrum {name!r}: kind must be 'Sd' or 'Sa' "
                             f"(got {kind!r})")
        if spelled == "Sd":
            if units != "m":
                raise ValueError(f"spectrum {name!r}: Sd values are in m (got units="
                                 f"{units!r})")
            sd = v
        else:
            sa = v * acceleration_factor(units)
            sd = sa * (t / (2.0 * np.pi)) ** 2
        frozen_set = object.__setattr__  # the attributes of a frozen dataclass
        frozen_set(self, "periods", t)
        frozen_set(self, "values", v)
        frozen_set(self, "kind", spelled)
        frozen_set(self, "units", units)
        frozen_set(self, "name", name)
        frozen_set(self, "formula", formula)
        frozen_set(self, "_sd", sd)
        corners = None
        if corner_periods is not None:
            c = np.asarray(corner_periods, dtype=float).ravel()
            corners = np.unique(c[(c >= t[0]) & (c <= t[-1])])
        frozen_set(self, "corner_periods", corners)

    @property
    def corners(self) -> FloatArray:
        """Periods [s] where the spectrum is not smooth: the corner periods of a code's
        closed form, else every period of the table (linear interpolation bends there). A
        minimum of a ratio to the spectrum can sit exactly there, between any two periods of
        a grid that misses them."""
        return self.periods if self.corner_periods is None else self.corner_periods

    def sd(self, period: ArrayLike) -> FloatArray | float:
        """Spectral displacement [m] at ``period`` [s].

        Sd is interpolated linearly in T when given; for an Sa table, Sa is interpolated
        (or, for a code's spectrum, evaluated by its formula) and converted
        (``Sd = Sa (T/2π)²``).
        """
        t = self._inside(period)
        if self.kind == "Sd":
            out = np.interp(t, self.periods, self.values)
        else:
            out = self._sa_si(t) * (t / (2.0 * np.pi)) ** 2
        return float(out) if out.ndim == 0 else out

    def sa_g(self, period: ArrayLike) -> FloatArray | float:
        """Pseudo-acceleration [g] at ``period`` [s]: Sa in g, or ``Sd (2π/T)²/g`` for an
        Sd table (T > 0)."""
        t = self._inside(period)
        if self.kind == "Sd":
            with np.errstate(divide="ignore", invalid="ignore"):
                out = np.interp(t, self.periods, self.values) * (2.0 * np.pi / t) ** 2 / G
        else:
            out = self._sa_si(t) / G
        return float(out) if out.ndim == 0 else out

    def _inside(self, period: ArrayLike) -> FloatArray:
        t = np.asarray(period, dtype=float)
        lo, hi = self.periods[0], self.periods[-1]
        if np.any(t < lo - 1e-12) or np.any(t > hi + 1e-12):
            raise ValueError(f"spectrum {self.name!r}: period {t.tolist()} s outside the "
                             f"table [{lo:g}, {hi:g}] s (no extrapolation)")
        return t

    def _sa_si(self, t: FloatArray) -> FloatArray:
        """Sa [m/s²] of an Sa spectrum: its formula, else the table interpolated."""
        sa = self.formula(t) if self.formula is not None else np.interp(t, self.periods,
                                                                          self.values)
        return np.asarray(sa, dtype=float) * acceleration_factor(self.units)

    @classmethod
    def asce7(cls, sds: float, sd1: float, tl: float = 8.0, t_max: float | None = None,
              n: int = 400, name: str | None = None) -> DesignSpectrum:
        """The ASCE 7-16 §11.4.6 design response spectrum (Sa in g, 5 % damping).

        ``Sa = S_DS (0.4 + 0.6 T/T0)`` for ``T < T0``; ``S_DS`` up to ``T_S``; ``S_D1/T``
        up to ``T_L``; ``S_D1 T_L/T²`` beyond; ``T0 = 0.2 S_D1/S_DS``, ``T_S = S_D1/S_DS``.
        Tabulated on ``n`` periods from 0 to ``t_max`` (default ``max(2 T_L, 10 s)``), plus
        the corner periods.
        """
        sds = positive("sds", sds)
        sd1 = positive("sd1", sd1)
        tl = positive("tl", tl)
        t0, ts = 0.2 * sd1 / sds, sd1 / sds
        top = max(2.0 * tl, 10.0) if t_max is None else positive("t_max", t_max)
        t = np.unique(np.concatenate([np.linspace(0.0, top, n), [t0, ts, tl]]))
        t = t[t <= top]
        formula = functools.partial(_asce7_sa, sds=sds, sd1=sd1, tl=tl)
        return cls(t, formula(t), kind="Sa", units="g", formula=formula,
                   corner_periods=np.array([t0, ts, tl]),
                   name=name or f"ASCE 7-16 (SDS={sds:g} g, SD1={sd1:g} g, TL={tl:g} s)")

    @classmethod
    def eurocode8(cls, agr: float, ground_type: str = "B", spectrum_type: int = 1,
                  importance: float = 1.0, damping: float = 0.05, t_max: float = 4.0,
                  n: int = 400, name: str | None = None) -> DesignSpectrum:
        """The Eurocode 8 horizontal elastic response spectrum, EN 1998-1:2004 §3.2.2.2
        (Sa in g).

        With ``a_g = γ_I a_gR`` (§3.2.1(3)) and ``S, T_B, T_C, T_D`` from Table 3.2
        (Type 1) or Table 3.3 (Type 2) for the ground type (:data:`EC8_GROUND_TYPES`):

        * eq. 3.2, ``0 ≤ T ≤ T_B``: ``Se = a_g S (1 + T/T_B (2.5 η − 1))``;
        * eq. 3.3, ``T_B ≤ T ≤ T_C``: ``Se = 2.5 a_g S η``;
        * eq. 3.4, ``T_C ≤ T ≤ T_D``: ``Se = 2.5 a_g S η T_C/T``;
        * eq. 3.5, ``T_D ≤ T ≤ 4 s``: ``Se = 2.5 a_g S η T_C T_D/T²``;

        with the damping correction ``η = sqrt(10/(5 + ξ)) ≥ 0.55``, ξ in % (eq. 3.6).
        Tabulated on ``n`` periods from 0 to ``t_max`` (≤ 4 s, where eq. 3.5 ends), plus the
        corner periods.

        Parameters
        ----------
        agr : float
            Reference peak ground acceleration on type A ground a_gR [g], > 0.
        ground_type : {"A", "B", "C", "D", "E"}
            Ground type of Table 3.1 (S1 and S2 need special studies: not covered).
        spectrum_type : {1, 2}
            Type 1 (surface-wave magnitude above 5.5) or Type 2 (§3.2.2.2(2)).
        importance : float
            Importance factor γ_I [-] (§4.2.5: 0.8, 1.0, 1.2, 1.4 recommended), > 0.
        damping : float
            Viscous damping ratio ζ [-] (0.05 = 5 %, η = 1), in [0, 1).
        """
        agr = positive("agr", agr)
        gi = positive("importance", importance)
        zeta = in_range("damping", damping, 0.0, 1.0, high_open=True)
        kind = {1: 1, 2: 2, "1": 1, "2": 2}.get(spectrum_type)
        if kind is None:
            raise ValueError(f"spectrum_type: must be 1 or 2 (EN 1998-1 §3.2.2.2(2)) "
                             f"(got {spectrum_type!r})")
        ground = str(ground_type).strip().upper()
        if ground not in EC8_GROUND_TYPES[kind]:
            raise ValueError(f"ground_type: must be one of A, B, C, D, E (EN 1998-1 Table "
                             f"3.1) (got {ground_type!r})")
        top = positive("t_max", t_max)
        if top > 4.0:
            raise ValueError(f"t_max: EN 1998-1 eq. 3.5 ends at 4 s (longer periods: its "
                             f"Annex A, not covered) (got {top:g})")
        soil, tb, tc, td = EC8_GROUND_TYPES[kind][ground]
        eta = max(float(np.sqrt(10.0 / (5.0 + 100.0 * zeta))), 0.55)
        t = np.unique(np.concatenate([np.linspace(0.0, top, n), [tb, tc, td]]))
        t = t[t <= top]
        formula = functools.partial(_ec8_sa, ag=gi * agr, soil=soil, tb=tb, tc=tc, td=td,
                                    eta=eta)
        return cls(t, formula(t), kind="Sa", units="g", formula=formula,
                   corner_periods=np.array([tb, tc, td]),
                   name=name or f"EN 1998-1 Type {kind}, ground {ground} (agR={agr:g} g, "
                                f"γI={gi:g}, ζ={100 * zeta:g} %)")

    @classmethod
    def nzs1170_5(cls, z: float, return_factor: float, site_class: str,
                  t_max: float = 10.0, n: int = 400, name: str | None = None
                  ) -> DesignSpectrum:
        """The NZS 1170.5:2004 §3.1 elastic site spectrum ``C(T) = C_h(T) Z R N(T, D)`` [g]
        for the modal method, ``Z R ≤ 0.7``, near-fault factor ``N = 1``; ``C_h(T)`` of
        Table 3.1 for site class A–E (:func:`pounding.spectra.code_spectra.nzs1170_5`).
        Tabulated on ``n`` periods from 0 to ``t_max`` plus the corner periods.

        Parameters
        ----------
        z : float
            Hazard factor Z, > 0.
        return_factor : float
            Return period factor R_u or R_s, > 0.
        site_class : {"A", "B", "C", "D", "E"}
            Site subsoil class.
        """
        from pounding.spectra import code_spectra

        return cls._closed_form(*code_spectra.nzs1170_5(z, return_factor, site_class),
                                t_max, n, name)

    @classmethod
    def nbcc2020(cls, values: ArrayLike, t_max: float = 10.0, n: int = 400,
                 name: str | None = None) -> DesignSpectrum:
        """The NBCC 2020 design spectral acceleration S(T) [g] (Sentence 4.1.8.4) from the
        site's six values at 0.2, 0.5, 1.0, 2.0, 5.0 and 10 s (each ≥ 0, the first > 0):
        S(0.2) below 0.2 s, linear between, S(10) beyond
        (:func:`pounding.spectra.code_spectra.nbcc2020`)."""
        from pounding.spectra import code_spectra

        return cls._closed_form(*code_spectra.nbcc2020(values), t_max, n, name)

    @classmethod
    def is1893(cls, z: float, importance: float, r: float, soil_type: str,
               n: int = 400, name: str | None = None) -> DesignSpectrum:
        """The IS 1893 (Part 1):2016 §6.4 design acceleration coefficient
        ``A_h = (Z/2) (I/R) (Sa/g)`` [g], 5 % damping, on 0–4 s: ``Sa/g`` = ``1 + 15 T``
        to 0.1 s, 2.5 to T_c, ``c/T`` to 4 s, with ``T_c`` = 0.40, 0.55, 0.67 s and
        ``c`` = 1.00, 1.36, 1.67 for soil types I, II, III (also 1, 2, 3)
        (:func:`pounding.spectra.code_spectra.is1893`). ``r = importance = 1`` gives the
        elastic ``(Z/2) Sa/g``.
        """
        from pounding.spectra import code_spectra

        return cls._closed_form(*code_spectra.is1893(z, importance, r, soil_type), 4.0, n,
                                name)

    @classmethod
    def _closed_form(cls, formula: Callable[[FloatArray], FloatArray], corners: FloatArray,
                     label: str, t_max: float, n: int, name: str | None) -> DesignSpectrum:
        """A code's spectrum [g] from its formula, tabulated on ``n`` periods from 0 to
        ``t_max`` plus its corner periods."""
        top = positive("t_max", t_max)
        t = np.unique(np.concatenate([np.linspace(0.0, top, n), corners]))
        t = t[t <= top]
        return cls(t, formula(t), kind="Sa", units="g", formula=formula,
                   corner_periods=corners, name=name or label)

    @classmethod
    def from_file(cls, path: str | os.PathLike[str]) -> DesignSpectrum:
        """Read a spectrum file: CSV (suffix ``.csv``) or TOML (any other suffix).

        A CSV file is a user's table: ``#`` lines are comments, the first other line names
        the columns ``period_s`` and one of ``sa_g``, ``sa_m_s2`` or ``sd_m``; the name is
        the file's stem. A TOML file is either a table::

            name = "site spectrum"
            kind = "Sa"            # or "Sd"
            units = "g"            # Sa: g, m/s2, cm/s2, ...; Sd: m
            periods = [0.0, 0.2, 1.0, 4.0]
            values  = [0.4, 1.0, 0.6, 0.15]

        or a code's parameters: ``asce7 = { sds = 1.0, sd1 = 0.6, tl = 8.0 }`` (ASCE 7-16
        §11.4.6, :meth:`asce7`) or ``eurocode8 = { agr = 0.25, ground_type = "C",
        type = 1, importance = 1.0, damping = 0.05 }`` (EN 1998-1 §3.2.2.2,
        :meth:`eurocode8`).
        """
        p = Path(path)
        if not p.is_file():
            raise ValueError(f"{p}: is a directory, not a spectrum file" if p.is_dir() else
                             f"{p}: no such spectrum file")
        if p.suffix.lower() == ".csv":
            return cls._from_csv(p)
        try:
            data = tomllib.loads(p.read_text(encoding="utf-8"))
        except UnicodeDecodeError:
            raise ValueError(f"{p}: not a TOML spectrum file (not UTF-8 text)") from None
        except tomllib.TOMLDecodeError as exc:  # its message may quote the file: not shown
            at = re.search(r"\((at line \d+, column \d+|at end of document)\)\s*$", str(exc))
            raise ValueError(f"{p}: not a valid TOML spectrum file"
                             + (f" ({at.group(1)})" if at else "")) from None
        if not set(data) & {"asce7", "eurocode8", "kind", "periods", "values"}:
            # none of the keys of a spectrum file: not one (its keys are not listed)
            raise ValueError(f"{p}: not a spectrum file: it has none of the keys asce7, "
                             "eurocode8 or kind, periods and values")
        name = str(data.get("name", p.stem))
        try:
            codes = [k for k in ("asce7", "eurocode8") if k in data]
            if len(codes) > 1:
                raise ValueError("give one of asce7 and eurocode8, not both")
            if codes:
                code = codes[0]
                extra = sorted(set(data) - {code, "name"})
                if extra:
                    raise ValueError(f"unknown key(s) beside {code}: {', '.join(extra)}")
                par = dict(data[code])
                if code == "asce7":
                    unknown = sorted(set(par) - {"sds", "sd1", "tl"})
                    if unknown or "sds" not in par or "sd1" not in par:
                        raise ValueError("asce7 needs sds and sd1 [g] and optionally tl [s] "
                                         f"(got {sorted(par)})")
                    return cls.asce7(float(par["sds"]), float(par["sd1"]),
                                     float(par.get("tl", 8.0)), name=name)
                keys = {"agr", "ground_type", "type", "importance", "damping"}
                if set(par) - keys or "agr" not in par:
                    raise ValueError("eurocode8 needs agr [g] and optionally ground_type "
                                     "(A-E), type (1 or 2), importance, damping (got "
                                     f"{sorted(par)})")
                return cls.eurocode8(float(par["agr"]), str(par.get("ground_type", "B")),
                                     par.get("type", 1), float(par.get("importance", 1.0)),
                                     float(par.get("damping", 0.05)),
                                     name=str(data["name"]) if "name" in data else None)
            extra = sorted(set(data) - {"name", "kind", "units", "periods", "values"})
            if extra:
                raise ValueError(f"unknown key(s): {', '.join(extra)}")
            for key in ("kind", "periods", "values"):
                if key not in data:
                    raise ValueError(f"{key}: required (kind = \"Sa\" or \"Sd\", periods [s], "
                                     "values)")
            kind = str(data["kind"])
            units = str(data.get("units", "m" if kind.lower() == "sd" else "g"))
            return cls(np.asarray(data["periods"], dtype=float),
                       np.asarray(data["values"], dtype=float), kind=kind, units=units,
                       name=name)
        except (ValueError, TypeError) as exc:
            raise ValueError(f"{p}: {exc}") from None

    @classmethod
    def _from_csv(cls, p: Path) -> DesignSpectrum:
        """A user's table in CSV: columns ``period_s`` and ``sa_g``, ``sa_m_s2`` or
        ``sd_m`` (see :meth:`from_file`)."""
        import csv

        columns = {"sa_g": ("Sa", "g"), "sa_m_s2": ("Sa", "m/s2"), "sd_m": ("Sd", "m")}
        try:
            lines = [ln for ln in p.read_text(encoding="utf-8").splitlines()
                     if ln.strip() and not ln.lstrip().startswith("#")]
        except UnicodeDecodeError as exc:
            raise ValueError(f"{p}: not a UTF-8 text file ({exc.reason})") from None
        rows = list(csv.reader(lines))
        if not rows:
            raise ValueError(f"{p}: no header line (columns period_s and one of "
                             f"{', '.join(columns)})")
        head = [h.strip().lower() for h in rows[0]]
        found = [c for c in columns if c in head]
        if "period_s" not in head or len(found) != 1:  # the line itself is not shown
            raise ValueError(f"{p}: the header (line {_first_line(p)}) must name the columns "
                             f"period_s and one of {', '.join(columns)}")
        it, iv = head.index("period_s"), head.index(found[0])
        t, v = [], []
        for k, row in enumerate(rows[1:], start=2):
            try:
                t.append(float(row[it]))
                v.append(float(row[iv]))
            except (ValueError, IndexError):
                raise ValueError(f"{p}: data line {k - 1}: period_s and {found[0]} must be "
                                 "numbers") from None
        kind, units = columns[found[0]]
        try:
            return cls(np.asarray(t), np.asarray(v), kind=kind, units=units, name=p.stem)
        except ValueError as exc:
            raise ValueError(f"{p}: {exc}") from None


def _first_line(p: Path) -> int:
    """The number of the first line of ``p`` that is neither blank nor a ``#`` comment."""
    with p.open(encoding="utf-8") as f:
        for number, line in enumerate(f, start=1):
            if line.strip() and not line.lstrip().startswith("#"):
                return number
    return 1


def _asce7_sa(t: FloatArray, *, sds: float, sd1: float, tl: float) -> FloatArray:
    """ASCE 7-16 §11.4.6 Sa [g] at periods ``t`` [s] (eqs. 11.4-5 to 11.4-8)."""
    t = np.asarray(t, dtype=float)
    t0, ts = 0.2 * sd1 / sds, sd1 / sds
    tt = np.where(t > 0.0, t, 1.0)  # the branches beyond T_S never use it at T = 0
    return np.where(t < t0, sds * (0.4 + 0.6 * t / t0),
                    np.where(t <= ts, sds,
                             np.where(t <= tl, sd1 / tt, sd1 * tl / tt ** 2)))


def _ec8_sa(t: FloatArray, *, ag: float, soil: float, tb: float, tc: float, td: float,
            eta: float) -> FloatArray:
    """EN 1998-1 §3.2.2.2 Se [g] at periods ``t`` [s] (eqs. 3.2 to 3.5)."""
    t = np.asarray(t, dtype=float)
    tt = np.where(t > 0.0, t, 1.0)  # the branches beyond T_C never use it at T = 0
    plateau = 2.5 * ag * soil * eta
    return np.where(t <= tb, ag * soil * (1.0 + t / tb * (2.5 * eta - 1.0)),
                    np.where(t <= tc, plateau,
                             np.where(t <= td, plateau * tc / tt,
                                      plateau * tc * td / tt ** 2)))


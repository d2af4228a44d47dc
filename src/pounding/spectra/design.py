"""Design spectra: :class:`DesignSpectrum`, a code's elastic design response spectrum as a
table of periods and values, with the ASCE 7-16 §11.4.6 spectrum built from ``S_DS``,
``S_D1`` and ``T_L`` (:meth:`DesignSpectrum.asce7`) and spectrum files in TOML
(:meth:`DesignSpectrum.from_file`). See ``docs/gap.md``.

Units: periods in s, Sa in any acceleration unit of :mod:`pounding.units` (m/s² internally),
Sd in m.
"""

from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.units import acceleration_factor
from pounding.validation import positive

__all__ = ["DesignSpectrum"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
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

    Notes
    -----
    No extrapolation: asking for a period outside the table is an error. The spectrum is
    used as given — a code spectrum is usually for 5 % damping; no damping correction is
    applied for buildings with another damping ratio.
    """

    periods: FloatArray
    values: FloatArray
    kind: str = "Sa"
    units: str = "g"
    name: str = "design spectrum"
    _sd: FloatArray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        t = np.asarray(self.periods, dtype=float).ravel()
        v = np.asarray(self.values, dtype=float).ravel()
        if t.size < 2 or t.size != v.size:
            raise ValueError(f"spectrum {self.name!r}: need at least 2 periods and as many "
                             f"values (got {t.size} periods, {v.size} values)")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(v))):
            raise ValueError(f"spectrum {self.name!r}: periods and values must be finite")
        if t[0] < 0 or np.any(np.diff(t) <= 0):
            raise ValueError(f"spectrum {self.name!r}: periods must be >= 0 and strictly "
                             f"increasing (got {t.tolist()})")
        if np.any(v < 0):
            raise ValueError(f"spectrum {self.name!r}: values must be >= 0 (got {v.tolist()})")
        kind = {"sd": "Sd", "sa": "Sa"}.get(str(self.kind).lower())
        if kind is None:
            raise ValueError(f"spectrum {self.name!r}: kind must be 'Sd' or 'Sa' "
                             f"(got {self.kind!r})")
        if kind == "Sd":
            if self.units != "m":
                raise ValueError(f"spectrum {self.name!r}: Sd values are in m (got units="
                                 f"{self.units!r})")
            sd = v
        else:
            sa = v * acceleration_factor(self.units)
            sd = sa * (t / (2.0 * np.pi)) ** 2
        object.__setattr__(self, "periods", t)
        object.__setattr__(self, "values", v)
        object.__setattr__(self, "kind", kind)
        object.__setattr__(self, "_sd", sd)

    def sd(self, period: ArrayLike) -> FloatArray | float:
        """Spectral displacement [m] at ``period`` [s].

        Sd is interpolated linearly in T when given; for an Sa table, Sa is interpolated
        and converted (``Sd = Sa (T/2π)²``).
        """
        t = np.asarray(period, dtype=float)
        lo, hi = self.periods[0], self.periods[-1]
        if np.any(t < lo - 1e-12) or np.any(t > hi + 1e-12):
            raise ValueError(f"spectrum {self.name!r}: period {t.tolist()} s outside the "
                             f"table [{lo:g}, {hi:g}] s (no extrapolation)")
        if self.kind == "Sd":
            out = np.interp(t, self.periods, self.values)
        else:
            sa = np.interp(t, self.periods, self.values) * acceleration_factor(self.units)
            out = sa * (t / (2.0 * np.pi)) ** 2
        return float(out) if out.ndim == 0 else out

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
        tt = np.where(t > 0.0, t, 1.0)  # the branches below T_S never use it at T = 0
        sa = np.where(t < t0, sds * (0.4 + 0.6 * t / t0),
                      np.where(t <= ts, sds,
                               np.where(t <= tl, sd1 / tt, sd1 * tl / tt ** 2)))
        return cls(t, sa, kind="Sa", units="g",
                   name=name or f"ASCE 7-16 (SDS={sds:g} g, SD1={sd1:g} g, TL={tl:g} s)")

    @classmethod
    def from_file(cls, path: str | os.PathLike[str]) -> DesignSpectrum:
        """Read a spectrum file (TOML). Either a table::

            name = "site spectrum"
            kind = "Sa"            # or "Sd"
            units = "g"            # Sa: g, m/s2, cm/s2, ...; Sd: m
            periods = [0.0, 0.2, 1.0, 4.0]
            values  = [0.4, 1.0, 0.6, 0.15]

        or the ASCE 7-16 parameters: ``asce7 = { sds = 1.0, sd1 = 0.6, tl = 8.0 }``.
        """
        p = Path(path)
        if not p.is_file():
            raise ValueError(f"{p}: is a directory, not a spectrum file" if p.is_dir() else
                             f"{p}: no such spectrum file")
        try:
            data = tomllib.loads(p.read_text(encoding="utf-8"))
        except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
            raise ValueError(f"{p}: not a valid TOML spectrum file: {exc}") from None
        name = str(data.get("name", p.stem))
        try:
            if "asce7" in data:
                extra = sorted(set(data) - {"asce7", "name"})
                if extra:
                    raise ValueError(f"unknown key(s) beside asce7: {', '.join(extra)}")
                par = dict(data["asce7"])
                unknown = sorted(set(par) - {"sds", "sd1", "tl"})
                if unknown or "sds" not in par or "sd1" not in par:
                    raise ValueError("asce7 needs sds and sd1 [g] and optionally tl [s] "
                                     f"(got {sorted(par)})")
                return cls.asce7(float(par["sds"]), float(par["sd1"]),
                                 float(par.get("tl", 8.0)), name=name)
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

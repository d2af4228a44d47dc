"""The record sources of ``[record]`` that are made, not read: ``stochastic = {…}`` (a
record of the stochastic model of Rezaeian & Der Kiureghian 2010 for an earthquake scenario
and a seed) and ``match = {…}`` (the record made spectrum-compatible with a target by
:func:`pounding.spectra.matching.match_record`). See ``docs/records.md``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Literal

from pydantic import Field, PrivateAttr, ValidationInfo, model_validator

from pounding.config.base import Section, field_error
from pounding.config.quantities import Duration, Period
from pounding.ground_motion import GroundMotion
from pounding.memo import Memo

__all__ = ["MatchSpec", "StochasticRecord"]

MATCHED = Memo(max_items=32, max_bytes=64 << 20)
"""Matched records, by seed motion and matching settings: the runs of a study that share a
seed record match it once per process."""
SIMULATED = Memo(max_items=64, max_bytes=64 << 20)
"""Stochastic records, by their fields."""


class StochasticRecord(Section):
    """``stochastic = { magnitude, distance, vs30, mechanism, seed, index, dt }``: record
    ``index`` (from 0) of the suite of ``seed`` for moment magnitude ``magnitude``, rupture
    distance ``distance`` [km], ``vs30`` [m/s] and ``mechanism`` (``"strike-slip"`` or
    ``"reverse"``), sampled every ``dt`` [s] (default 0.01, at most 0.02); its length is
    the time 99.9 % of its Arias intensity has arrived, plus 5 s, unless ``length`` [s]
    (:func:`pounding.ground_motion.rezaeian2010.stochastic_motion`)."""

    magnitude: Annotated[float, Field(ge=4.0, le=9.0)]
    distance: Annotated[float, Field(gt=0.0, le=500.0)]
    vs30: Annotated[float, Field(ge=100.0, le=3000.0)]
    mechanism: Literal["strike-slip", "reverse"] = "strike-slip"
    seed: Annotated[int, Field(ge=0, le=2**63 - 1, strict=True)] = 0
    index: Annotated[int, Field(ge=0, le=10**9, strict=True)] = 0
    dt: Annotated[float, Field(gt=0.0, le=0.02)] = 0.01
    length: Duration | None = None

    def motion(self) -> GroundMotion:
        """The record [m/s²] (remembered: the runs of a study that share it make it once per
        process)."""
        return SIMULATED.get(repr(self.__dict__), self._simulate,
                             size=lambda gm: gm.accel.nbytes)

    def _simulate(self) -> GroundMotion:
        from pounding.ground_motion.rezaeian2010 import Scenario, stochastic_motion

        scenario = Scenario(self.magnitude, self.distance, self.vs30, self.mechanism)
        return stochastic_motion(scenario, self.seed, self.index, dt=self.dt,
                                 duration=self.length)


class MatchSpec(Section):
    """``match = { target, range, tolerance, damping, iterations }``: the record (after
    ``duration``, before its scaling) is made spectrum-compatible with the spectrum file
    ``target`` (relative to the model file) over ``range = [lo, hi]`` [s] (default 0.05–4)
    within ``tolerance`` (default 0.10) at ``damping`` (default 0.05), in at most
    ``iterations`` (default 30); a record that does not get within the tolerance is refused."""

    target: str
    range: Annotated[list[Period], Field(min_length=2, max_length=2)] = [0.05, 4.0]
    tolerance: Annotated[float, Field(gt=0.0, lt=1.0)] = 0.10
    damping: Annotated[float, Field(gt=0.0, lt=1.0)] = 0.05
    iterations: Annotated[int, Field(ge=1, le=1000, strict=True)] = 30

    _path: Path | None = PrivateAttr(default=None)

    @model_validator(mode="after")
    def _check(self, info: ValidationInfo) -> MatchSpec:
        if not self.range[0] < self.range[1]:
            raise field_error("range", f"the lower period must be below the upper (got "
                                       f"{self.range})")
        base = Path((info.context or {}).get("base_dir", "."))
        path = (base / Path(self.target).expanduser()).resolve()
        if not path.is_file():
            raise field_error("target", f"no such spectrum file {str(path)!r} (got "
                                        f"{self.target!r}; relative paths start at the model "
                                        "file's folder)")
        self._path = path
        return self

    @property
    def path(self) -> Path:
        """The target's file, resolved."""
        if self._path is None:
            self._path = Path(self.target).expanduser().resolve()
        return self._path

    def apply(self, motion: GroundMotion) -> GroundMotion:
        """``motion`` matched to the target.

        Raises
        ------
        ValueError
            One line: a target that cannot be read or does not cover the range, or a match
            not within the tolerance after the iterations.
        """
        import hashlib

        path = self.path
        stat = path.stat()
        key = (hashlib.sha256(motion.accel.tobytes()).hexdigest(), motion.dt, motion.name,
               str(path), stat.st_mtime_ns, stat.st_size, tuple(self.range), self.tolerance,
               self.damping, self.iterations)
        return MATCHED.get(key, lambda: self._match(motion), size=lambda gm: gm.accel.nbytes)

    def _match(self, motion: GroundMotion) -> GroundMotion:
        from pounding.spectra import DesignSpectrum
        from pounding.spectra.matching import match_record

        try:
            spectrum = DesignSpectrum.from_file(self.path)
        except ValueError as exc:
            raise ValueError(f"match.target: {exc}") from None
        try:
            result = match_record(motion, spectrum, (self.range[0], self.range[1]),
                                  damping=self.damping, tolerance=self.tolerance,
                                  iterations=self.iterations)
        except ValueError as exc:
            raise ValueError(f"match.{exc}") from None
        if not result.converged:
            raise ValueError(f"match: {motion.name} is within {100 * result.max_misfit:.1f} % "
                             f"of {spectrum.name} after {result.iterations} iterations, not "
                             f"the {100 * self.tolerance:g} % asked (raise iterations, "
                             "narrow range or choose another record)")
        return result.motion

"""Links between floors of neighbouring buildings: dampers and springs that act at all times,
and cable restrainers that tie a bridge's deck segments across an expansion joint.

A :class:`Link` joins floor ``floors[0]`` of one building to floor ``floors[1]`` of another
(labels ``"B1F3"``: building 1, floor 3, counted from 1 as in every output). Its law is one of
:mod:`pounding.devices.laws`. A linear law without internal variable (``kelvin``, ``viscous``
with α = 1) joins the structure's stiffness and damping, which the kernel steps exactly
between impacts (:func:`pounding.integrate.kernel_model.fold_linear_links`); the kernel
integrates any other as an element row beside the yielding storeys: a linear Maxwell link
(α = 1) stepped exactly between impacts with its spring's deformation in the exact step's
state (:mod:`pounding.integrate.exact_maxwell`), a restrainer stepped exactly while it is
slack, a fluid damper or a Maxwell link with α ≠ 1 adaptively throughout.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from pounding.devices.laws import KELVIN, MAXWELL, RESTRAINER, VISCOUS
from pounding.units import format_value

__all__ = ["LINK_KINDS", "Link", "parse_floor"]

LINK_KINDS: dict[str, int] = {"viscous": VISCOUS, "kelvin": KELVIN, "maxwell": MAXWELL,
                              "restrainer": RESTRAINER}
"""Link laws by name: ``viscous`` (linear or fluid viscous dashpot, ``F = c |ḋ|^α sgn ḋ``),
``kelvin`` (spring ∥ dashpot), ``maxwell`` (spring in series with a dashpot) and
``restrainer`` (a cable: tension only, slack, elastic then yielding)."""

_FLOOR = re.compile(r"^B(\d+)F(\d+)$")


def parse_floor(label: str, field_name: str = "floors") -> tuple[int, int]:
    """``"B2F3"`` → ``(1, 2)``: 0-based building and floor indices.

    Raises
    ------
    ValueError
        Not of the form ``B<building>F<floor>`` with both numbers from 1.
    """
    m = _FLOOR.match(str(label).strip().upper())
    if m is None or int(m.group(1)) < 1 or int(m.group(2)) < 1:
        raise ValueError(f"{field_name}: {label!r} is not a floor label like 'B1F3' "
                         "(building and floor numbers from 1)")
    return int(m.group(1)) - 1, int(m.group(2)) - 1


@dataclass(frozen=True)
class Link:
    """A damper, spring or cable restrainer between two floors of different buildings.

    Parameters
    ----------
    floors : (str, str)
        The two floors it joins, e.g. ``("B1F3", "B2F3")``.
    kind : {"viscous", "kelvin", "maxwell", "restrainer"}
        ``viscous``: ``F = c |ḋ|^α sgn ḋ`` (a linear dashpot with α = 1, a fluid viscous
        damper with α < 1); ``kelvin``: ``F = k d + c ḋ``; ``maxwell``: spring ``k`` in series
        with the dashpot ``c, α`` (the damper's brace or its own flexibility and the fluid);
        ``restrainer``: a cable restrainer across a joint (DesRoches & Fenves 2000), tension
        only: no force until the opening ``d`` exceeds the ``slack``, then ``k`` per metre up
        to ``yield_force``, then ``hardening · k``; it unloads elastically and a yielded cable
        is longer by its plastic elongation (its slack grows by it;
        :data:`pounding.devices.laws.RESTRAINER`). ``d`` is the relative displacement of the
        right building's floor to the left one's (a joint's opening: the right deck's
        displacement less the left one's).
    c : float, optional
        Dashpot coefficient [N·(s/m)^α] (N·s/m for α = 1) of ``viscous``, ``kelvin`` and
        ``maxwell`` links (not of a restrainer).
    alpha : float
        Velocity exponent α of the dashpot, 0 < α ≤ 2 (1: linear; fluid viscous dampers are
        built with 0.2–1). Kelvin links are linear (α = 1).
    k : float, optional
        Spring stiffness [N/m] of ``kelvin`` and ``maxwell`` links (not of ``viscous``); a
        restrainer's axial stiffness ``n E A / L`` (all its cables together).
    name : str
        A label for outputs (default ``"B1F3-B2F3"``).
    slack : float, optional
        A restrainer's initial slack [m], ≥ 0: the opening at which the cable goes taut
        (Caltrans practice: ~13 mm beyond the joint's expected thermal opening).
    yield_force : float, optional
        A restrainer's yield force [N] (all cables: ``n F_y`` of one), > 0; None: it stays
        elastic.
    hardening : float
        A restrainer's post-yield stiffness as a fraction of ``k``, 0 ≤ b < 1 (default 0:
        elastic–perfectly plastic).

    Examples
    --------
    >>> Link(("B1F1", "B2F1"), "viscous", c=2e5).readable()
    'viscous link B1F1-B2F1: c = 2.00e5 N·s/m'
    >>> Link(("B1F1", "B2F1"), "restrainer", k=2e8, slack=0.013, yield_force=1.2e6,
    ...      hardening=0.02).readable()
    'restrainer link B1F1-B2F1: k = 2.00e8 N/m, slack = 13 mm, F_y = 1.20e6 N, b = 0.02'
    """

    floors: tuple[str, str]
    kind: str
    c: float | None = None
    alpha: float = 1.0
    k: float | None = None
    name: str = field(default="")
    slack: float | None = None
    yield_force: float | None = None
    hardening: float = 0.0

    def __post_init__(self) -> None:
        if not isinstance(self.floors, (tuple, list)) or len(self.floors) != 2:
            raise ValueError(f"floors: give two floor labels, e.g. ['B1F3', 'B2F3'] "
                             f"(got {self.floors!r})")
        a, b = (parse_floor(f) for f in self.floors)
        if a[0] == b[0]:
            raise ValueError(f"floors: {self.floors[0]} and {self.floors[1]} are in one "
                             "building; a link joins two buildings")
        kind = str(self.kind).strip().lower()
        if kind not in LINK_KINDS:
            raise ValueError(f"kind: {self.kind!r} is not a link law (one of "
                             f"{', '.join(LINK_KINDS)})")
        object.__setattr__(self, "kind", kind)
        object.__setattr__(self, "floors", tuple(str(f).strip().upper() for f in self.floors))
        if kind == "restrainer":
            self._check_restrainer()
        else:
            self._check_dashpot(kind)
        # left floor first: d = u_right − u_left
        if a[0] > b[0]:
            object.__setattr__(self, "floors", (self.floors[1], self.floors[0]))
        if not self.name:
            object.__setattr__(self, "name", f"{self.floors[0]}-{self.floors[1]}")

    def _check_restrainer(self) -> None:
        if self.c is not None:
            raise ValueError(f"c: a restrainer has no dashpot (got {self.c!r})")
        if self.alpha != 1.0:
            raise ValueError(f"alpha: a restrainer has no dashpot (got {self.alpha!r})")
        if self.k is None or not (math.isfinite(self.k) and self.k > 0):
            raise ValueError(f"k: a restrainer needs its axial stiffness, finite and > 0 "
                             f"[N/m] (got {self.k!r})")
        if self.slack is None or not (math.isfinite(self.slack) and self.slack >= 0):
            raise ValueError(f"slack: a restrainer needs its slack, finite and ≥ 0 [m] "
                             f"(got {self.slack!r})")
        if self.yield_force is not None and not (math.isfinite(self.yield_force)
                                                 and self.yield_force > 0):
            raise ValueError(f"yield_force: must be finite and > 0 [N] (got "
                             f"{self.yield_force!r})")
        if not (math.isfinite(self.hardening) and 0.0 <= self.hardening < 1.0):
            raise ValueError(f"hardening: the post-yield stiffness ratio must be in [0, 1) "
                             f"(got {self.hardening!r})")

    def _check_dashpot(self, kind: str) -> None:
        for key in ("slack", "yield_force"):
            if getattr(self, key) is not None:
                raise ValueError(f"{key}: only a restrainer has a {key} (this is a {kind} "
                                 "link)")
        if self.hardening != 0.0:
            raise ValueError(f"hardening: only a restrainer has a hardening (this is a {kind} "
                             "link)")
        if self.c is None or not (math.isfinite(self.c) and self.c > 0):
            raise ValueError(f"c: must be finite and > 0 [N·(s/m)^α] (got {self.c!r})")
        if not (math.isfinite(self.alpha) and 0.0 < self.alpha <= 2.0):
            raise ValueError(f"alpha: must be in (0, 2] (got {self.alpha!r})")
        if kind == "kelvin" and self.alpha != 1.0:
            raise ValueError(f"alpha: a kelvin link is linear (α = 1; got {self.alpha!r}); "
                             "use a maxwell link for a nonlinear dashpot with a spring")
        if kind == "viscous":
            if self.k is not None:
                raise ValueError("k: a viscous link has no spring (use kind = 'kelvin' or "
                                 "'maxwell')")
        elif self.k is None or not (math.isfinite(self.k) and self.k > 0):
            raise ValueError(f"k: a {kind} link needs a spring stiffness, finite and > 0 "
                             f"[N/m] (got {self.k!r})")

    @property
    def code(self) -> int:
        """Law code for the compiled kernel (:mod:`pounding.devices.laws`)."""
        return LINK_KINDS[self.kind]

    @property
    def has_internal_variable(self) -> bool:
        """True for a Maxwell link (its spring's deformation is integrated with the motion)
        and a restrainer (its plastic elongation)."""
        return self.kind in ("maxwell", "restrainer")

    @property
    def ends(self) -> tuple[tuple[int, int], tuple[int, int]]:
        """0-based (building, floor) of the left and the right end."""
        return parse_floor(self.floors[0]), parse_floor(self.floors[1])

    def params(self, width: int) -> NDArray[np.float64]:
        """The constants ``[p0, p1, p2(, p3)]`` of the compiled law, zero-padded to
        ``width``: a restrainer's ``[k, slack, F_y (inf: elastic), b]``."""
        p = np.zeros(width)
        if self.kind == "restrainer":
            p[:4] = (self.k, self.slack,
                     math.inf if self.yield_force is None else self.yield_force,
                     self.hardening)
        elif self.kind == "viscous":
            p[:2] = (self.c, self.alpha)
        elif self.kind == "kelvin":
            p[:2] = (self.k, self.c)
        else:
            p[:3] = (self.k, self.c, self.alpha)
        return p

    def force(self, d: NDArray[np.float64] | float, rate: NDArray[np.float64] | float,
              z: NDArray[np.float64] | float = 0.0) -> NDArray[np.float64]:
        """Force [N] at relative displacement ``d`` [m] and rate ``ḋ`` [m/s] (Maxwell: at
        spring deformation ``z`` [m]; a restrainer: at plastic elongation ``z`` [m], the
        cable's force ``clip(k (d − slack − z), 0, F_y + H z)``, ``H = b k/(1 − b)``),
        written out in NumPy (independent of the kernel's compiled law: tests check the
        kernel's link forces against it)."""
        d, rate, z = (np.asarray(x, dtype=float) for x in (d, rate, z))
        if self.kind == "restrainer":
            k = float(self.k)  # type: ignore[arg-type]
            cap = (math.inf if self.yield_force is None
                   else self.yield_force + self.hardening * k / (1.0 - self.hardening) * z)
            return np.clip(k * (d - self.slack - z), 0.0, cap)  # type: ignore[operator]
        if self.kind == "viscous":
            return self.c * np.sign(rate) * np.abs(rate) ** self.alpha
        if self.kind == "kelvin":
            return self.k * d + self.c * rate  # type: ignore[operator]
        return self.k * z  # type: ignore[operator]

    @property
    def yield_elongation(self) -> float:
        """A restrainer's opening at first yield [m]: ``slack + F_y / k`` (inf if elastic)."""
        if self.kind != "restrainer" or self.yield_force is None:
            return math.inf
        return float(self.slack) + self.yield_force / float(self.k)  # type: ignore[arg-type]

    def spring_rate(self, rate: float, z: float) -> float:
        """``ż`` of a Maxwell link [m/s]: ``ḋ`` less the dashpot's rate
        ``sgn F (|F| / c)^(1/α)`` with ``F = k z``."""
        f = float(self.k) * z  # type: ignore[arg-type]
        return rate - math.copysign((abs(f) / self.c) ** (1.0 / self.alpha),  # type: ignore[operator]
                                    f)

    def describe(self) -> str:
        """One line with the exact values (for keys and logs)."""
        if self.kind == "restrainer":
            return (f"Link(floors={self.floors!r}, kind='restrainer', k={self.k!r}, "
                    f"slack={self.slack!r}, yield_force={self.yield_force!r}, "
                    f"hardening={self.hardening!r})")
        return (f"Link(floors={self.floors!r}, kind={self.kind!r}, c={self.c!r}, "
                f"alpha={self.alpha!r}, k={self.k!r})")

    def readable(self) -> str:
        """One line for people, three significant digits and units."""
        if self.kind == "restrainer":
            parts = [f"k = {format_value(float(self.k), 'N/m')}",  # type: ignore[arg-type]
                     f"slack = {float(self.slack) * 1e3:.3g} mm"]  # type: ignore[arg-type]
            parts.append("elastic" if self.yield_force is None
                         else f"F_y = {format_value(float(self.yield_force), 'N')}")
            if self.hardening:
                parts.append(f"b = {self.hardening:g}")
            return f"restrainer link {self.name}: {', '.join(parts)}"
        unit = "N·s/m" if self.alpha == 1.0 else f"N·(s/m)^{self.alpha:g}"
        parts = []
        if self.k is not None:
            parts.append(f"k = {format_value(self.k, 'N/m')}")
        parts.append(f"c = {format_value(float(self.c), unit)}")  # type: ignore[arg-type]
        if self.alpha != 1.0:
            parts.append(f"α = {self.alpha:g}")
        return f"{self.kind} link {self.name}: {', '.join(parts)}"

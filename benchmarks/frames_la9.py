"""An LA9-type frame: the SAC Los Angeles 9-storey steel moment frame as a pounding ``Frame``.

:func:`la9_frame` builds a planar, concentrated-plasticity model of one north–south perimeter
moment frame of the SAC Los Angeles 9-storey building (pre-Northridge design, UBC 1994), of
the type used by Gupta & Krawinkler (1999), *Seismic demands for performance evaluation of
steel moment resisting frame structures*, SAC/BD-99/01 (Blume Center report 132), and in
FEMA P695-style studies. It is a benchmark model ("LA9-type"), not a reproduction of any one
published model: what it keeps and what it leaves out is said below.

Geometry
--------
5 bays of 9.15 m (30 ft); storey heights 5.49 m (18 ft, ground storey) and 3.96 m (13 ft) for
storeys 2–9; total height 37.17 m. The building's one-level basement is **omitted**: the
columns are fixed at the ground level (the published models carry the basement, 3.65 m, with
the ground floor restrained horizontally; fixing at ground makes this model a little stiffer).
Centre-line model: no panel zones, no rigid end offsets, no splices (one section per storey:
where a column splice falls inside a storey, 1.83 m above floors 2, 4, 6 and 8, the lighter
section above the splice is used for the whole storey), no gravity-frame columns or shear-tab
connections, no composite slab action, all columns bending about their strong axis.

Sections (the LA 9-storey pre-Northridge design of Gupta & Krawinkler 1999; the table as
given by Ohtori, Christenson, Spencer & Dyke 2004, *Benchmark control problems for
seismically excited nonlinear buildings*, J. Eng. Mech. 130(4):366–385, and the public
OpenSees model of Ribeiro, Barbosa & Kameshwar 2018, github.com/arbarbosa/OpenSees_SAC_Models,
``9story_M2A.tcl``, against which this table was checked section by section; that model
turns the column at one end about its weak axis in some storeys, this one does not)::

    storey  height   exterior col.  interior col.   beam above (floor)
      1     5.49 m   W14x370        W14x500         W36x160 (2)
      2     3.96 m   W14x370        W14x455         W36x160 (3)
      3     3.96 m   W14x370        W14x455         W36x135 (4)
      4     3.96 m   W14x283        W14x370         W36x135 (5)
      5     3.96 m   W14x283        W14x370         W36x135 (6)
      6     3.96 m   W14x257        W14x283         W36x135 (7)
      7     3.96 m   W14x257        W14x283         W30x99  (8)
      8     3.96 m   W14x233        W14x257         W27x84  (9)
      9     3.96 m   W14x233        W14x257         W24x68  (roof)

Section properties from the AISC *Steel Construction Manual* shapes table, as tabulated in
OpenSees' Tcl library ``SteelWSection.tcl`` (columns "A d bf tw tf Ix Iy Zx Sx rx Zy Sy ry
J"), in inches (converted to SI with 1 in = 25.4 mm)::

    shape     A in²   d in   bf in   tw in   tf in   Ix in⁴   Zx in³   ry in
    W14x500   147     19.6   17.0    2.19    3.50    8210     1050     4.43
    W14x455   134     19.0   16.8    2.02    3.21    7190      936     4.38
    W14x370   109     17.9   16.5    1.66    2.66    5440      736     4.27
    W14x283   83.3    16.7   16.1    1.29    2.07    3840      542     4.17
    W14x257   75.6    16.4   16.0    1.18    1.89    3400      487     4.13
    W14x233   68.5    16.0   15.9    1.07    1.72    3010      436     4.10
    W36x160   47.0    36.0   12.0    0.650   1.02    9760      624     2.50
    W36x135   39.9    35.6   12.0    0.600   0.790   7800      509     2.38
    W30x99    29.0    29.7   10.5    0.520   0.670   3990      312     2.10
    W27x84    24.7    26.7   10.0    0.460   0.640   2850      244     2.07
    W24x68    20.1    23.7   8.97    0.415   0.585   1830      177     1.87

Material: E = 200 GPa; expected yield stress ``F_y,exp`` = 1.1 × 345 MPa = 380 MPa for every
member (the published models use the SAC expected strengths, 339 MPa for the A36 beams and
397 MPa for the Grade 50 columns — Ribeiro et al.'s model above — so these beams are 12 %
stronger and these columns 4 % weaker than theirs); plastic moment ``M_p = Z_x F_y,exp``.

Masses and gravity
------------------
Seismic masses of the half building tributary to one frame (the building has two perimeter
frames in each direction): half of Ohtori et al. (2004)'s whole-structure values — floor 2:
1.01e6 kg, floors 3–9: 9.89e5 kg, roof: 1.07e6 kg; 9.00e6 kg above ground — i.e.
5.05e5, 4.945e5 (×7) and 5.35e5 kg, 4.5015e6 kg in all (FEMA-355C, Appendix B: 69.04,
67.86 and 73.10 kip·s²/ft for the whole structure, the same within 0.3 %; Ribeiro et al.'s
model, read through the search tool, has 5048.8, 4962.5 and 5346.0 kN of weight per frame,
about 2 % more at g = 9.81 m/s²). Each floor's mass is shared equally by its six joints
(rigid floors: only the sum matters).

Gravity load = the seismic weight ``m g`` (g = 9.81 m/s²) of each floor of the half building
(dead load; no live load). The frame's beams carry their tributary strip, half a bay
(4.575 m) of the 22.875 m-deep half-building plan: 20 % of it, as a uniform load on the
floor's beams; the remaining 80 % stands on the leaning column (``leaning=True``), which
adds its P-Delta (``−P/h`` per storey) and nothing else; the frame's own columns take their
P-Delta through ``geometry="p-delta"`` (the chord's ``N/L``, OpenSees' ``PDelta``). Rigid
floors. Damping 2 % Rayleigh at modes 1 and 3 (used by time histories only).

Hinges
------
Every member end has a rotational spring (two per member) in series with an elastic member.
The springs' elastic stiffness follows Ibarra & Krawinkler (2005), *Global collapse of frame
structures under seismic excitations*, Blume Center report 152, Appendix B, and Zareian &
Medina (2010), *A practical method for proper modeling of structural damping in inelastic
plane structural systems*, Comput. Struct. 88:45–53: with a member in double curvature the
member's end stiffness is ``6EI/L``; making the spring ``n`` times stiffer than the elastic
element (n = 10) and the element's ``EI`` larger by ``(n+1)/n`` keeps the member's elastic
stiffness exactly ``6EI/L`` (spring and element in series), so::

    EI_element = (n + 1)/n · E I_x
    k0         = n · 6 EI_element / L  = (n + 1) · 6 E I_x / L

and the member's post-yield stiffness ratio ``α`` becomes the spring's
``α_s = α / (1 + n (1 − α))`` (their Appendix B; used for the bilinear springs). The spring's
``θ_y = M_y/k0`` is 1/11 of the member's.

``hinges="imk-bilinear"`` (default): **beams** get the modified IMK law with bilinear
hysteresis (:class:`pounding.hysteresis.imk.IMKBilinear`, OpenSees ``IMKBilin``), ``M_y = M_p``,
``M_c/M_y = 1.11``, ``κ = 0.4``, ``θ_u = 0.2`` rad, ``c = 1``, ``D = 1`` (the values FM-2D's
``Spring_IMK.tcl`` gives a bare other-than-RBS beam), and ``θ_p``, ``θ_pc``
and ``Λ`` from the Lignos & Krawinkler (2011) regressions for **other-than-RBS** beams of
depth ``d ≥ 533 mm`` (21 in; every beam here is 602–914 mm deep; the pre-Northridge welded
connections of LA9 are not RBS) — Lignos & Krawinkler (2011), *Deterioration modeling of
steel components in support of collapse prediction of steel moment frames under earthquake
loading*, J. Struct. Eng. 137(11):1291–1302::

    θ_p  = 0.318 (h/t_w)^-0.550 (b_f/2t_f)^-0.345 (L_b/r_y)^-0.023 (L/d)^0.090
                 (d/533)^-0.330 (F_y/355)^-0.130
    θ_pc = 7.50  (h/t_w)^-0.610 (b_f/2t_f)^-0.710 (L_b/r_y)^-0.110 (d/533)^-0.161
                 (F_y/355)^-0.320
    Λ    = 536   (h/t_w)^-1.26  (b_f/2t_f)^-0.525 (L_b/r_y)^-0.130 (F_y/355)^-0.291

(d in mm, F_y in MPa; Λ in rad, E_t = Λ M_y). The paper itself could not be reached through
the search tool; the coefficients are those of two public implementations by the papers'
authors' group that agree with each other: Elkady's ``Spring_IMK.tcl`` in FM-2D
(github.com/amaelkady/FM-2D, ``src/Spring_IMK.tcl``, "other-than-RBS equations", branch
``d > 21 in``) and, for the d < 21 in and RBS sets it also carries, Lignos's
``SteelWSectionMR`` in OpenSees' ``SteelWSection.tcl``. Inputs used here: ``h = d − 2 t_f``
(the clear web depth without fillets: ``h/t_w`` 52–57, a little above the AISC tabulated
values), ``L`` = the shear span = half the centre-line span (4.575 m), ``L_b`` = 4.575 m
(the unbraced length taken from the hinge to the inflection point, the definition of
``SteelWSection.tcl``), ``F_y`` = 380 MPa. The resulting constants are in
:data:`BEAM_IMK`::

    beam      h/t_w  b_f/2t_f  M_p MN·m  θ_p     θ_pc    Λ rad
    W36x160   52.2   5.88      3.881     0.0170  0.107   0.814
    W36x135   56.7   7.59      3.165     0.0150  0.0846  0.638
    W30x99    54.5   7.84      1.940     0.0163  0.0860  0.648
    W27x84    55.3   7.81      1.517     0.0169  0.0869  0.637
    W24x68    54.3   7.67      1.101     0.0180  0.0897  0.650

Lignos & Krawinkler's effective yield moment (1.17 M_p for other-than-RBS beams, as FM-2D applies it)
is not applied: ``M_y = M_p`` as for the other hinge types, so that the three variants have
the same strength.

**Columns** (every ``hinges`` choice but ``"elastic-plastic"``): bilinear with kinematic
hardening (:class:`~pounding.hysteresis.hinges.BilinearHinge`, OpenSees ``Steel01``), ``M_y =
M_p``, member hardening 3 % (``α_s`` as above), no deterioration and no axial–moment
interaction. The IMK regressions are not applied to the columns: these stocky W14s
(``h/t_w`` 5.8–11.7, ``b_f/2t_f`` 2.4–4.6) lie outside the beam data the regressions were
fitted to. Their gravity axial load is below 10 % of ``A F_y`` (tested), so leaving out
P–M interaction matters little before a column yields; a column that would lose strength
does not here (not conservative for collapse: a column hinge never deteriorates).

``hinges="bilinear"``: every hinge bilinear as the columns above. ``hinges="elastic-plastic"``: every hinge elastic–perfectly plastic at ``M_p`` (hand
checks: plastic mechanisms).

Period
------
Published first periods of LA9 models lie about 2.2–2.4 s (Ohtori et al. 2004: 0.443 Hz,
i.e. 2.26 s, a model with the basement). This model gives T1 = 2.117 s with the leaning
column and 2.082 s without it, 6 % below 2.26 s; nothing was tuned. The basement accounts for most of the difference: the same frame
with it (the ground level restrained horizontally, storey 1's columns continued 3.65 m down
to a fixed base; a throw-away script, 2026-11-27) gives 2.205 s (2.164 s without the
leaning column). ``tests/structure/test_frames_la9.py`` checks T1 within ±10 % of 2.26 s
and pins this model's values.

Sources
-------
Ribeiro et al.'s model, FM-2D's ``Spring_IMK.tcl`` and OpenSees' ``SteelWSection.tcl``
(with its AISC table) were read through the project's search tool; Ohtori et al. (2004),
FEMA-355C, Gupta & Krawinkler (1999) and Lignos & Krawinkler (2011) were not (their
abstracts or first pages only), and the values quoted from them here are as remembered,
each cross-checked against one of the files that were read (sections and masses against
Ribeiro et al.'s model, the regressions against the two Tcl implementations).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic, HingeLaw
from pounding.hysteresis.imk import IMKBilinear
from pounding.structure.damping import RayleighDamping
from pounding.structure.frame import Frame, FrameHinge

__all__ = [
    "BAYS",
    "BEAMS",
    "BEAM_IMK",
    "COLUMNS",
    "FLOOR_MASSES",
    "FY_EXPECTED",
    "HINGE_TYPES",
    "N_STIFF",
    "SECTIONS",
    "STOREY_HEIGHTS",
    "BeamIMK",
    "E",
    "G",
    "WSection",
    "beam_imk",
    "la9_frame",
    "lignos_krawinkler_2011",
    "total_height",
]

INCH = 0.0254  # m
E = 200e9  # Pa
FY_EXPECTED = 1.1 * 345e6  # Pa: 379.5 MPa, "380 MPa"
G = 9.81  # m/s²
N_STIFF = 10.0  # spring / element stiffness ratio n (Ibarra & Krawinkler 2005, App. B)
MEMBER_HARDENING = 0.03  # α of the bilinear members
MC_MY = 1.11  # Lignos & Krawinkler (2011), other-than-RBS (as FM-2D's Spring_IMK.tcl)
KAPPA = 0.4
THETA_U = 0.2  # rad
TRIBUTARY_FRACTION = 4.575 / 22.875  # the frame's strip of the half-building plan: 0.2

BAYS: tuple[float, ...] = (9.15,) * 5  # m
STOREY_HEIGHTS: tuple[float, ...] = (5.49,) + (3.96,) * 8  # m, ground storey first
FLOOR_MASSES: tuple[float, ...] = (5.05e5,) + (4.945e5,) * 7 + (5.35e5,)  # kg, floor 2 … roof

HINGE_TYPES: tuple[str, ...] = ("imk-bilinear", "bilinear", "elastic-plastic")


@dataclass(frozen=True)
class WSection:
    """A wide-flange shape, AISC shapes table values in inches (see the module docstring)."""

    name: str
    A_in2: float
    d_in: float
    bf_in: float
    tw_in: float
    tf_in: float
    Ix_in4: float
    Zx_in3: float
    ry_in: float

    @property
    def A(self) -> float:
        """Area [m²]."""
        return self.A_in2 * INCH**2

    @property
    def d(self) -> float:
        """Depth [m]."""
        return self.d_in * INCH

    @property
    def Ix(self) -> float:
        """Strong-axis second moment of area [m⁴]."""
        return self.Ix_in4 * INCH**4

    @property
    def Zx(self) -> float:
        """Strong-axis plastic modulus [m³]."""
        return self.Zx_in3 * INCH**3

    @property
    def ry(self) -> float:
        """Weak-axis radius of gyration [m]."""
        return self.ry_in * INCH

    @property
    def h_tw(self) -> float:
        """Web slenderness ``(d − 2 t_f)/t_w`` [-]."""
        return (self.d_in - 2.0 * self.tf_in) / self.tw_in

    @property
    def bf_2tf(self) -> float:
        """Flange slenderness ``b_f/(2 t_f)`` [-]."""
        return self.bf_in / (2.0 * self.tf_in)

    @property
    def Mp(self) -> float:
        """Plastic moment at the expected yield stress, ``Z_x F_y,exp`` [N·m]."""
        return self.Zx * FY_EXPECTED


def _w(name: str, *values: float) -> WSection:
    return WSection(name, *values)


SECTIONS: dict[str, WSection] = {s.name: s for s in (
    _w("W14x500", 147, 19.6, 17.0, 2.19, 3.50, 8210, 1050, 4.43),
    _w("W14x455", 134, 19.0, 16.8, 2.02, 3.21, 7190, 936, 4.38),
    _w("W14x370", 109, 17.9, 16.5, 1.66, 2.66, 5440, 736, 4.27),
    _w("W14x283", 83.3, 16.7, 16.1, 1.29, 2.07, 3840, 542, 4.17),
    _w("W14x257", 75.6, 16.4, 16.0, 1.18, 1.89, 3400, 487, 4.13),
    _w("W14x233", 68.5, 16.0, 15.9, 1.07, 1.72, 3010, 436, 4.10),
    _w("W36x160", 47.0, 36.0, 12.0, 0.650, 1.02, 9760, 624, 2.50),
    _w("W36x135", 39.9, 35.6, 12.0, 0.600, 0.790, 7800, 509, 2.38),
    _w("W30x99", 29.0, 29.7, 10.5, 0.520, 0.670, 3990, 312, 2.10),
    _w("W27x84", 24.7, 26.7, 10.0, 0.460, 0.640, 2850, 244, 2.07),
    _w("W24x68", 20.1, 23.7, 8.97, 0.415, 0.585, 1830, 177, 1.87),
)}

COLUMNS: tuple[tuple[str, str], ...] = (  # (exterior, interior), storey 1 … 9
    ("W14x370", "W14x500"), ("W14x370", "W14x455"), ("W14x370", "W14x455"),
    ("W14x283", "W14x370"), ("W14x283", "W14x370"), ("W14x257", "W14x283"),
    ("W14x257", "W14x283"), ("W14x233", "W14x257"), ("W14x233", "W14x257"))
BEAMS: tuple[str, ...] = ("W36x160", "W36x160", "W36x135", "W36x135", "W36x135", "W36x135",
                          "W30x99", "W27x84", "W24x68")  # floor 2 … roof


def lignos_krawinkler_2011(section: WSection, shear_span: float, unbraced: float,
                           fy: float = FY_EXPECTED) -> tuple[float, float, float]:
    """``(θ_p, θ_pc, Λ)`` [rad] of an other-than-RBS beam by Lignos & Krawinkler (2011)'s
    regressions (module docstring): the ``d ≥ 533 mm`` set, or the ``d < 533 mm`` set
    (no ``L_b/r_y`` term) for shallower beams::

        θ_p  = 0.0865 (h/t_w)^-0.365 (b_f/2t_f)^-0.140 (L/d)^0.340 (d/533)^-0.721 (F_y/355)^-0.230
        θ_pc = 5.63   (h/t_w)^-0.565 (b_f/2t_f)^-0.800 (d/533)^-0.280 (F_y/355)^-0.430
        Λ    = 495    (h/t_w)^-1.34  (b_f/2t_f)^-0.595 (F_y/355)^-0.360

    ``shear_span`` L and ``unbraced`` L_b in m, ``fy`` in Pa."""
    htw, bftf = section.h_tw, section.bf_2tf
    d_mm, fy_355 = section.d * 1e3, fy / 1e6 / 355.0
    l_d = shear_span / section.d
    if d_mm >= 533.0:
        lb_ry = unbraced / section.ry
        theta_p = (0.318 * htw**-0.550 * bftf**-0.345 * lb_ry**-0.023 * l_d**0.090
                   * (d_mm / 533.0)**-0.330 * fy_355**-0.130)
        theta_pc = (7.50 * htw**-0.610 * bftf**-0.710 * lb_ry**-0.110
                    * (d_mm / 533.0)**-0.161 * fy_355**-0.320)
        lam = 536.0 * htw**-1.26 * bftf**-0.525 * lb_ry**-0.130 * fy_355**-0.291
    else:
        theta_p = (0.0865 * htw**-0.365 * bftf**-0.140 * l_d**0.340 * (d_mm / 533.0)**-0.721
                   * fy_355**-0.230)
        theta_pc = 5.63 * htw**-0.565 * bftf**-0.800 * (d_mm / 533.0)**-0.280 * fy_355**-0.430
        lam = 495.0 * htw**-1.34 * bftf**-0.595 * fy_355**-0.360
    return theta_p, theta_pc, lam


@dataclass(frozen=True)
class BeamIMK:
    """The IMK constants of one beam section (:func:`beam_imk`)."""

    section: str
    m_y: float  #: N·m
    theta_p: float  #: rad
    theta_pc: float  #: rad
    lambda_: float  #: rad


def beam_imk(name: str) -> BeamIMK:
    """The IMK constants of beam section ``name`` in this frame (span 9.15 m)."""
    s = SECTIONS[name]
    half = BAYS[0] / 2.0
    tp, tpc, lam = lignos_krawinkler_2011(s, shear_span=half, unbraced=half)
    return BeamIMK(name, s.Mp, tp, tpc, lam)


BEAM_IMK: dict[str, BeamIMK] = {name: beam_imk(name) for name in dict.fromkeys(BEAMS)}
"""The IMK constants of the frame's beam sections."""


def _spring_stiffness(section: WSection, length: float) -> float:
    """``k0 = n · 6 EI_element / L`` with ``EI_element = (n+1)/n E I_x``."""
    return N_STIFF * 6.0 * (N_STIFF + 1.0) / N_STIFF * E * section.Ix / length


def _bilinear(section: WSection, length: float) -> BilinearHinge:
    a = MEMBER_HARDENING
    return BilinearHinge(k0=_spring_stiffness(section, length), m_y=section.Mp,
                         hardening=a / (1.0 + N_STIFF * (1.0 - a)))


def _hinge(kind: str, member: Literal["beam", "column"], section: WSection,
           length: float) -> HingeLaw:
    k0 = _spring_stiffness(section, length)
    if kind == "elastic-plastic":
        return ElasticPlastic(k0=k0, m_y=section.Mp)
    if kind == "bilinear" or member == "column":
        return _bilinear(section, length)
    c = BEAM_IMK[section.name]
    return IMKBilinear(k0=k0, m_y=c.m_y, theta_p=c.theta_p, theta_pc=c.theta_pc,
                       theta_u=THETA_U, mc_my=MC_MY, kappa=KAPPA, lambda_=c.lambda_)


def la9_frame(*, hinges: str = "imk-bilinear", leaning: bool = True,
              name: str = "LA9") -> Frame:
    """The LA9-type frame (module docstring): 9 storeys, 5 bays, fixed at the ground.

    Parameters
    ----------
    hinges : str
        ``"imk-bilinear"`` (beams IMK, columns bilinear), ``"bilinear"`` or
        ``"elastic-plastic"``.
    leaning : bool
        Put 80 % of each floor's gravity load on a leaning column (its P-Delta); without it
        the frame carries only its own 20 % strip.
    name : str
        The frame's label.

    Returns
    -------
    Frame
        60 nodes (6 fixed at the base), 99 elements (54 columns then 45 beams, storey by
        storey, left to right), 198 hinges, geometry ``"p-delta"``, rigid floors.
    """
    if hinges not in HINGE_TYPES:
        raise ValueError(f"hinges: must be one of {', '.join(HINGE_TYPES)} (got {hinges!r})")
    xs = np.concatenate([[0.0], np.cumsum(BAYS)])
    ys = np.concatenate([[0.0], np.cumsum(STOREY_HEIGHTS)])
    ncol, ns = xs.size, len(STOREY_HEIGHTS)
    nodes = np.array([(x, y) for y in ys for x in xs])
    elements: list[tuple[int, int]] = []
    EA: list[float] = []
    EI: list[float] = []
    w: list[float] = []
    laws: list[tuple[HingeLaw, HingeLaw]] = []
    scale = (N_STIFF + 1.0) / N_STIFF
    for s in range(ns):
        h = STOREY_HEIGHTS[s]
        for line in range(ncol):
            sec = SECTIONS[COLUMNS[s][0 if line in (0, ncol - 1) else 1]]
            elements.append((s * ncol + line, (s + 1) * ncol + line))
            EA.append(E * sec.A)
            EI.append(scale * E * sec.Ix)
            w.append(0.0)
            law = _hinge(hinges, "column", sec, h)
            laws.append((law, law))
    for s in range(ns):
        sec = SECTIONS[BEAMS[s]]
        floor_weight = FLOOR_MASSES[s] * G
        load = TRIBUTARY_FRACTION * floor_weight / float(np.sum(BAYS))
        for b, span in enumerate(BAYS):
            elements.append(((s + 1) * ncol + b, (s + 1) * ncol + b + 1))
            EA.append(E * sec.A)
            EI.append(scale * E * sec.Ix)
            w.append(load)
            law = _hinge(hinges, "beam", sec, span)
            laws.append((law, law))
    frame_hinges = tuple(FrameHinge(e, end, laws[e][end]) for e in range(len(elements))
                         for end in (0, 1))
    supports = np.zeros((nodes.shape[0], 3), dtype=bool)
    supports[:ncol] = True
    masses = np.zeros((nodes.shape[0], 3))
    for s in range(ns):
        masses[(s + 1) * ncol:(s + 2) * ncol, 0] = FLOOR_MASSES[s] / ncol
    lean = (np.array(FLOOR_MASSES) * G * (1.0 - TRIBUTARY_FRACTION) if leaning
            else np.zeros(ns))
    return Frame(nodes=nodes, elements=np.array(elements, dtype=np.int64), EA=np.array(EA),
                 EI=np.array(EI), supports=supports, hinges=frame_hinges, masses=masses,
                 member_loads=np.array(w), diaphragm=True, leaning_loads=lean,
                 geometry="p-delta", damping=RayleighDamping(0.02, 0.02, mode_i=1, mode_j=3),
                 name=name)


def total_height() -> float:
    """Height of the roof above the ground [m]."""
    return float(math.fsum(STOREY_HEIGHTS))

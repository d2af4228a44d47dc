"""Links between buildings (issue 17): pounding against OpenSeesPy on the same models, in one
process, with dampers at every shared floor level, with and without contact.

Run from the repository root, in a virtualenv holding both ``pounding`` and ``openseespy``
(see ``benchmarks/README.md``)::

    python benchmarks/bench_devices.py                     # everything, ~3 min
    python benchmarks/bench_devices.py --repeat 5 --sections sdof,cost
    python benchmarks/bench_devices.py --kinds viscous,fvd --no-reference
    python benchmarks/bench_devices.py --sections cost --kinds viscous,maxwell --no-reference \
        --json /tmp/devices.json          # the links' price as figures (benchmarks/run_all.py)

Models (El Centro 1940 as bundled, 39.99 s at 0.01 s, output / analysis step 1 ms):

sdof    ``examples/seed_sdof_pair.toml``: 2e5 kg, T = 0.5 s and 3e5 kg, T = 1.0 s, 5 % damping
        (c = 2ζmω each), Jankowski's nonlinear viscoelastic contact (k_h 2.75e9 N/m^1.5,
        e 0.65), gap 20 mm; one link, B1F1–B2F1.
shear   ``examples/two_10_storey.toml``: 10 + 10 storeys (6e5 kg, 8e8 N/m and 4e5 kg,
        1.2e9 N/m per floor / storey), Rayleigh 5 % in modes 1 and 2, the same contact law at
        every floor, gap 40 mm; ten links, B1Fi–B2Fi.

Links, one law per case (``--kinds``), on every shared floor level:

viscous   linear dashpot, ``F = c ḋ`` — OpenSees ``uniaxialMaterial Viscous c 1``;
fvd       fluid viscous damper, ``F = c_α |ḋ|^α sgn ḋ``, α = ``--alpha`` (0.5), with
          ``c_α = c v_ref^(1−α)`` (the linear dashpot's force at v_ref = 0.25 m/s) —
          OpenSees ``Viscous c_α α``;
maxwell   spring k in series with the linear dashpot c, ``k = c / τ`` (relaxation time τ =
          ``--tau``, 0.02 s) — OpenSees ``ViscousDamper k c 1`` (Akcelyan & Lignos: the
          same ODE, ``Ḟ = k (ḋ − sgn F (|F|/c)^(1/α))``, integrated inside each step by
          Dormand–Prince 5(4) at RelTol 1e-6 with the rate linear over the step). For the SDOF
          pair the same link is also run with OpenSees' ``Maxwell k c 1 1`` material (a
          second-order exponential update of the linear model), to show which one matches;
maxwell-fvd (not by default) the same spring with the dashpot of ``fvd`` —
          ``ViscousDamper k c_α α``.

with ``c`` = ``--c-sdof`` (2e5 N·s/m: 4 % of critical for the left oscillator) or
``--c-shear`` (1e6 N·s/m per link). In OpenSees every link is a ``zeroLength`` element from
the left floor to the right one in direction 1 (deformation ``u_right − u_left``, as
``pounding.devices.Link``), without Rayleigh damping; the buildings and the contact elements
are ``opensees_models.run_opensees_building_pair``'s (Elastic storeys with ``a1 k`` as their
viscous part, ``region -rayleigh a0``, ``JankowskiImpact`` with pounding's k_h, ξ, m_eff,
Newmark average acceleration, Newton, ``NormDispIncr`` 1e-10, retries).

"Without contact": pounding's gap is set to 10 m (its contact elements are kept but never
close: a PoundingModel of two buildings always has them); OpenSees gets no contact elements
at all (the cheaper model for it).

Sections:

model   The two models in both tools: masses, stiffnesses, damping coefficients (checked
        against pounding's assembled C), contact law constants, the link materials.
sdof    The SDOF pair, every link law, with and without contact: whole runs timed (best of
        ``--repeat``, the worst in brackets; pounding at least ``--repeat`` times and as many
        more as fit in ``--pounding-window`` s, as the other benches), the ratio
        OpenSees / pounding, and each tool's peak displacements, peak link force, link
        energy, impacts and peak contact force against ``simulate_reference`` (SciPy DOP853
        at rtol 1e-10, located events; ~10 s a case, α = 0.5 on the whole record).
shear   The same for the two 10-storey buildings, comparing the two tools with each other
        (``--shear-reference`` adds the SciPy reference, minutes a case).
cost    pounding's own price of the links: the same models without links (stepped exactly
        between contacts) against the runs with links (linear dashpots folded into K and C
        and linear Maxwell links, their springs' deformations in the exact step's state,
        stepped exactly between contacts too; fluid dampers and Maxwell links with a fluid
        dashpot stepped adaptively throughout), and OpenSees' with and without links beside
        it. With ``--json PATH`` its figures (link / no link, goal ≤ 1.5× for the linear
        links) are written as one JSON object (the convention of ``benchmarks/run_all.py``).

"Whole run" is, for both tools, everything from plain numbers to the compared measures:
pounding builds its ShearBuildings, Links and PoundingModel afresh, runs ``simulate`` and
reads the peaks; OpenSees builds its domain, runs the ``analyze(1, dt)`` loop reading every
floor's displacement, every contact's and every link's force each step, and the same peaks
from those histories. The record is given to both. Numba compilation (or its loading from
the cache) is kept out by an untimed warm-up run. Not a test: nothing is asserted; the
machine's load average is printed at the start and the end, and every timing with its spread.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

import _figures
from _memory import keep_freed_memory  # noqa: E402
import opensees_models as osm  # noqa: E402
from _environment import load, parse_list, print_environment  # noqa: E402
from bench_opensees import header, pct, table  # noqa: E402

from pounding import PoundingModel, ShearBuilding, load_config, simulate  # noqa: E402
from pounding.devices import Link  # noqa: E402
from pounding.integrate.reference import simulate_reference  # noqa: E402

MODELS = {"sdof": ROOT / "examples" / "seed_sdof_pair.toml",
          "shear": ROOT / "examples" / "two_10_storey.toml"}
KINDS = ("viscous", "fvd", "maxwell", "maxwell-fvd")
DEFAULT_KINDS = ("viscous", "fvd", "maxwell")
NO_CONTACT_GAP = 10.0
"""pounding's gap [m] for the runs without contact (nothing comes near it)."""
V_REF = 0.25
"""Velocity [m/s] at which a fluid damper gives the linear dashpot's force."""
MIN_TIMED_WINDOW = 0.5
MAX_REPEAT = 100


# ===================================================================== printing
# (header, table and pct: bench_opensees.py's, imported above)


def spread(values: list[float], scale: float = 1.0, fmt: str = ".3f") -> str:
    """``best (worst) xN`` of timing repeats."""
    return f"{min(values) * scale:{fmt}} ({max(values) * scale:{fmt}}) x{len(values)}"


# ===================================================================== the models
@dataclass
class Base:
    """A model file's buildings and contact, and what OpenSees needs of them."""

    key: str
    model: Any
    motion: Any
    rtol: float
    os_kwargs: dict[str, Any]
    rows: list[list[str]]
    floors: list[tuple[int, int]]
    """Shared floor levels (left floor, right floor), 0-based: where the links go."""


def opensees_building_args(model: Any) -> tuple[dict[str, Any], list[list[str]]]:
    """``run_opensees_building_pair`` arguments for pounding's two linear shear buildings
    with floor-to-floor contacts and Jankowski's law, checked (and reported) against
    pounding's assembled damping matrix and contact laws."""
    if len(model.buildings) != 2 or any(b.is_inelastic for b in model.buildings):
        raise ValueError("needs two linear shear buildings")
    spec = model.contact
    if spec.law != "nonlinear-viscoelastic":
        raise ValueError(f"contact law {spec.law!r}: only Jankowski's (JankowskiImpact) here")
    bl, br = model.buildings
    ray, blocks = [], []
    for b in (bl, br):
        M, K = osm.shear_matrices(b.masses, b.stiffnesses)
        if hasattr(b.damping, "coefficients"):  # Rayleigh
            a0, a1 = (float(x) for x in b.damping.coefficients(M, K))
        elif b.n == 1:  # one mode: c = 2 ζ m ω as a stiffness-proportional term
            a0, a1 = 0.0, float(b.damping_matrix()[0, 0] / K[0, 0])
        else:
            raise ValueError(f"{b.name}: damping {type(b.damping).__name__} is not a0 M + a1 K")
        ray.append((a0, a1))
        blocks.append(a0 * M + a1 * K)
    C = np.asarray(model.system.C)
    C_os = np.zeros_like(C)
    C_os[:bl.n, :bl.n], C_os[bl.n:, bl.n:] = blocks
    worst_c = float(np.max(np.abs(C - C_os)) / np.max(np.abs(C)))
    cdof, cw = model.contact_kinematics()
    pairs = []
    for c, d, w in zip(model.contacts, cdof, cw):
        if not (d[0] == d[1] and d[2] == d[3] and w[0] == 1.0 and w[2] == -1.0
                and w[1] == 0.0 and w[3] == 0.0 and d[0] < bl.n <= d[2]):
            raise ValueError(f"contact {c.index} is not floor to floor")
        pairs.append((int(d[0]), int(d[2]) - bl.n))
    e = float(spec.e)
    worst_law = 0.0
    for c, (i, j) in zip(model.contacts, pairs):
        ours = (c.law.k_h, c.law.zeta, c.law.m_eff)
        theirs = (spec.k_h, osm.zeta_jankowski(e), osm.m_effective(bl.masses[i], br.masses[j]))
        worst_law = max(worst_law, max(abs(pct(a, b)) for a, b in zip(theirs, ours)))
    c0 = model.contacts[0].law
    rows = [["contact law", f"nonlinear-viscoelastic k_h {c0.k_h:.4g} N/m^1.5, ζ {c0.zeta:.6f}, "
             f"m_eff {c0.m_eff:.6g} kg", f"JankowskiImpact Kh {spec.k_h:.4g}, ξ "
             f"{osm.zeta_jankowski(e):.6f}, mEff {osm.m_effective(bl.masses[0], br.masses[0]):.6g}"
             f", n {spec.n:g}; largest difference {worst_law:.1e} %"],
            ["contacts", f"{len(pairs)}, floor i to floor i, gap {1e3 * model.gaps[0]:g} mm "
             f"(no contact: {NO_CONTACT_GAP:g} m)", f"{len(pairs)} zeroLength, gap "
             f"{-1e3 * model.gaps[0]:g} mm (no contact: no element)"]]
    for name, b, (a0, a1) in (("left", bl, ray[0]), ("right", br, ray[1])):
        rows.append([f"{name}: {b.name}", f"{b.n} floor(s), m {b.masses[0]:.4g} kg, k "
                     f"{b.stiffnesses[0]:.4g} N/m, {type(b.damping).__name__}",
                     f"a0 {a0:.6g} 1/s (region -rayleigh), a1 {a1:.6e} s (Elastic eta)"])
    rows.append(["damping matrix", "model.system.C",
                 f"a0 M + a1 K: max diff {worst_c:.1e} of max |C|"])
    kwargs = dict(left=(bl.masses, bl.stiffnesses), right=(br.masses, br.stiffnesses),
                  rayleigh=ray, contacts=pairs, gap=float(model.gaps[0]), e=e,
                  law="jankowski", k_h=float(spec.k_h), n_exp=float(spec.n),
                  numberer="Plain" if bl.n + br.n <= 2 else "RCM")
    return kwargs, rows


def load_base(key: str) -> Base:
    cfg = load_config(MODELS[key])
    model, motion, solver = cfg.build()
    kwargs, rows = opensees_building_args(model)
    return Base(key, model, motion, float(solver.get("rtol") or 1e-8), kwargs, rows,
                list(kwargs["contacts"]))


@dataclass(frozen=True)
class Kind:
    """One link law of the benchmark, with its constants for a model."""

    name: str
    c: float
    alpha: float
    tau: float

    @property
    def c_alpha(self) -> float:
        return self.c * V_REF ** (1.0 - self.alpha)

    def links(self, floors: list[tuple[int, int]]) -> list[Link]:
        out = []
        for i, j in floors:
            fl = (f"B1F{i + 1}", f"B2F{j + 1}")
            if self.name == "viscous":
                out.append(Link(fl, "viscous", c=self.c))
            elif self.name == "fvd":
                out.append(Link(fl, "viscous", c=self.c_alpha, alpha=self.alpha))
            elif self.name == "maxwell":
                out.append(Link(fl, "maxwell", c=self.c, k=self.c / self.tau))
            elif self.name == "maxwell-fvd":
                out.append(Link(fl, "maxwell", c=self.c_alpha, alpha=self.alpha,
                                k=self.c / self.tau))
            else:
                raise ValueError(self.name)
        return out


def opensees_material(link: Link, maxwell_material: bool = False) -> tuple[Any, ...]:
    """The OpenSees uniaxialMaterial (without its tag) of one of pounding's links."""
    if link.kind == "viscous":
        return ("Viscous", link.c, link.alpha)
    if link.kind == "maxwell":
        if maxwell_material:
            if link.alpha != 1.0:
                raise ValueError("OpenSees' Maxwell material is linear (α only scales C)")
            return ("Maxwell", float(link.k), link.c, 1.0, 1.0)
        return ("ViscousDamper", float(link.k), link.c, link.alpha)
    raise ValueError(f"no OpenSees material here for a {link.kind} link")


def link_rows(kinds: list[Kind], floors: list[tuple[int, int]]) -> list[list[str]]:
    rows = []
    for k in kinds:
        lk = k.links(floors)[0]
        mat = opensees_material(lk)
        rows.append([k.name, lk.readable().split(":", 1)[1].strip() + f" (x{len(floors)})",
                     f"{mat[0]} " + " ".join(f"{x:.6g}" for x in mat[1:])])
        if k.name == "maxwell":
            mm = opensees_material(lk, maxwell_material=True)
            rows.append(["", "(also, SDOF pair only)",
                         f"{mm[0]} " + " ".join(f"{x:.6g}" for x in mm[1:])])
    return rows


# ===================================================================== runs
@dataclass
class Measures:
    n_impacts: int
    f_contact: float
    """Largest contact force [N] (pounding / reference: located; OpenSees: output steps)."""
    u_left: np.ndarray
    u_right: np.ndarray
    """Peak |u| of every floor [m]."""
    f_link: np.ndarray
    """Peak |F| of every link at the output steps [N]."""
    e_link: float
    """Energy dissipated by the links [J] (pounding / reference: the solver's column;
    OpenSees: ∫F dd by the trapezoidal rule on the output steps, less the Maxwell springs'
    energy at the end)."""
    u: np.ndarray
    """Floor displacement history (nt, N) [m]."""
    f_hist: np.ndarray | None = None
    stats: str = ""


def measures_pounding(res: Any, n_left: int) -> Measures:
    u = res.displacement
    links = res.model.links
    return Measures(int(res.n_impacts),
                    float(res.peak_contact_force.max()) if res.peak_contact_force.size else 0.0,
                    np.abs(u[:, :n_left]).max(axis=0), np.abs(u[:, n_left:]).max(axis=0),
                    res.link_peak_force if links else np.zeros(0),
                    float(res.energy[-1, 7]) if links else 0.0, u,
                    res.link_force if links else None,
                    f"{res.stats.rk_steps} RK steps, {res.stats.rejected} rejected, "
                    f"{res.stats.events} events" if res.stats.solver == "kernel" else "")


def measures_opensees(r: dict[str, Any], links: list[Link], pairs: list[tuple[int, int]]
                      ) -> Measures:
    fl = r.get("link_force")
    e = 0.0
    if fl is not None:
        for q, (lk, (i, j)) in enumerate(zip(links, pairs)):
            d = r["u_right"][:, j] - r["u_left"][:, i]
            f = fl[:, q]
            e += float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(d)))
            if lk.kind == "maxwell":
                e -= 0.5 * f[-1] ** 2 / float(lk.k)
    pf = r["peak_force"]
    return Measures(int(r["n_impacts"]), float(pf.max()) if np.size(pf) else 0.0,
                    r["peak_u_left"], r["peak_u_right"],
                    r["peak_link_force"] if fl is not None else np.zeros(0), e,
                    np.hstack([r["u_left"], r["u_right"]]), fl,
                    f"retried {r['retried']}, failed {r['failed']}")


@dataclass
class Case:
    """One model x link law x contact, both tools."""

    base: Base
    kind: Kind | None
    contact: bool
    label: str
    links: list[Link] = field(default_factory=list)
    ours: list[float] = field(default_factory=list)
    theirs: list[float] = field(default_factory=list)
    m_ours: Measures | None = None
    m_theirs: Measures | None = None
    m_ref: Measures | None = None
    ref_wall: float = math.nan
    extra: dict[str, Any] = field(default_factory=dict)


def run_pounding(base: Base, links: list[Link], contact: bool, dt: float,
                 duration: float | None, free_stepping: str = "auto") -> tuple[Measures, Any]:
    """A whole pounding run from plain numbers: buildings, links, model, simulate, peaks."""
    m0 = base.model
    blds = [ShearBuilding(masses=b.masses, stiffnesses=b.stiffnesses, heights=b.heights,
                          damping=b.damping, name=b.name) for b in m0.buildings]
    devices = [Link(lk.floors, lk.kind, c=lk.c, alpha=lk.alpha, k=lk.k) for lk in links]
    model = PoundingModel(blds, [m0.gaps[0] if contact else NO_CONTACT_GAP], m0.contact,
                          name=m0.name, devices=devices)
    res = simulate(model, base.motion, dt=dt, duration=duration, rtol=base.rtol,
                   free_stepping=free_stepping)
    return measures_pounding(res, blds[0].n), res


def run_reference(base: Base, links: list[Link], contact: bool, dt: float,
                  duration: float | None) -> Measures:
    m0 = base.model
    model = PoundingModel(m0.buildings, [m0.gaps[0] if contact else NO_CONTACT_GAP],
                          m0.contact, name=m0.name, devices=links)
    res = simulate_reference(model, base.motion, dt=dt, duration=duration)
    return measures_pounding(res, m0.buildings[0].n)


def run_opensees(base: Base, links: list[Link], contact: bool, dt: float,
                 duration: float | None, maxwell_material: bool = False) -> Measures:
    """A whole OpenSees run: domain, analysis with per-step reads, peaks."""
    kw = dict(base.os_kwargs)
    if not contact:
        kw["contacts"] = []
    pairs = [(lk.ends[0][1], lk.ends[1][1]) for lk in links]
    mats = [(i, j, opensees_material(lk, maxwell_material)) for lk, (i, j) in zip(links, pairs)]
    r = osm.run_opensees_building_pair(base.motion.accel, base.motion.dt, dt, duration=duration,
                                       links=mats, **kw)
    if r["failed"]:
        print(f"  !! OpenSees stopped at a step it could not do ({r['failed']} failed)")
    return measures_opensees(r, links, pairs)


def timed_pounding(case: Case, ctx: "Ctx", free_stepping: str = "auto") -> None:
    # at least --repeat runs, and as many more as fit in the window (a best of three runs
    # of 20 ms is at the mercy of one burst of other work; OpenSees' three span a second)
    run_pounding(case.base, case.links, case.contact, ctx.dt, 0.5, free_stepping)  # warm-up
    t_start = time.perf_counter()
    while (len(case.ours) < ctx.repeat or (time.perf_counter() - t_start < ctx.window
                                           and len(case.ours) < MAX_REPEAT)):
        t0 = time.perf_counter()
        m, _ = run_pounding(case.base, case.links, case.contact, ctx.dt, ctx.duration,
                            free_stepping)
        case.ours.append(time.perf_counter() - t0)
    case.m_ours = m


def timed_opensees(case: Case, ctx: "Ctx", maxwell_material: bool = False) -> tuple[list[float],
                                                                                   Measures]:
    walls = []
    m = None
    for _ in range(ctx.repeat):
        t0 = time.perf_counter()
        m = run_opensees(case.base, case.links, case.contact, ctx.dt, ctx.duration,
                         maxwell_material)
        walls.append(time.perf_counter() - t0)
    assert m is not None
    return walls, m


# ===================================================================== sections
@dataclass
class Ctx:
    bases: dict[str, Base]
    kinds: dict[str, list[Kind]]
    repeat: int
    window: float
    dt: float
    duration: float | None
    reference: bool
    shear_reference: bool
    n_steps: int
    cases: dict[tuple[str, str, bool], Case] = field(default_factory=dict)


def get_case(ctx: Ctx, key: str, kind: Kind | None, contact: bool) -> Case:
    """The case, run by both tools (once: the cost section reuses the others' runs)."""
    name = kind.name if kind else "no links"
    ck = (key, name, contact)
    if ck not in ctx.cases:
        base = ctx.bases[key]
        label = f"{name}, {'contact' if contact else 'no contact'}"
        case = Case(base, kind, contact, label, kind.links(base.floors) if kind else [])
        timed_pounding(case, ctx)
        case.theirs, case.m_theirs = timed_opensees(case, ctx)
        ctx.cases[ck] = case
    return ctx.cases[ck]


def section_model(ctx: Ctx) -> None:
    for key, base in ctx.bases.items():
        header(f"The model in both tools: {MODELS[key].name}")
        table(base.rows + link_rows(ctx.kinds[key], base.floors),
              ["", "pounding", "OpenSees"])


def _compare_rows(case: Case, ref: Measures | None, tool_rows: list[tuple[str, Measures,
                  list[float] | None]], n_steps: int, ratio: str) -> list[list[str]]:
    """One row per tool: timing, and its measures against ``ref`` (the reference, or
    pounding when there is none)."""
    rows = []
    for tool, m, walls in tool_rows:
        base = ref if ref is not None else case.m_ours
        assert base is not None
        is_base = m is base
        du = np.abs(m.u - base.u).max() / np.abs(base.u).max()
        dfl = (max(abs(pct(a, b)) for a, b in zip(m.f_link, base.f_link))
               if m.f_link.size else math.nan)

        def d(x: float, y: float, f: str = "+.4f") -> str:
            return "-" if is_base else (f"{pct(x, y):{f}}" if y else "-")

        rows.append([
            case.label if tool == tool_rows[0][0] else "", tool,
            spread(walls) if walls else "-",
            f"{1e6 * min(walls) / n_steps:.2f}" if walls else "-",
            ratio if tool == "pounding" else "",
            f"{m.n_impacts}" + (f" ({ref.n_impacts})" if ref is not None and not is_base else ""),
            f"{m.f_contact / 1e6:.5g}" if is_base else d(m.f_contact, base.f_contact, "+.3f"),
            f"{1e3 * m.u_left.max():.4f}" if is_base else d(m.u_left.max(), base.u_left.max()),
            f"{1e3 * m.u_right.max():.4f}" if is_base else d(m.u_right.max(),
                                                               base.u_right.max()),
            f"{m.f_link.max() / 1e3:.5g}" if is_base else d(m.f_link.max(), base.f_link.max()),
            "-" if is_base else f"{dfl:.4f}",
            f"{m.e_link / 1e3:.5g}" if is_base else d(m.e_link, base.e_link, "+.3f"),
            "-" if is_base else f"{100 * du:.4f}",
            m.stats])
    return rows


HEAD = ["case", "tool", "whole run s best (worst) xN", "µs/step", "ratio OS/ours",
        "impacts (ref)", "Fc MN | Δ%", "max|u| L mm | Δ%", "max|u| R mm | Δ%",
        "max|F_link| kN | Δ%", "worst link Δ%", "E_link kJ | Δ%", "Δu(t) %", "notes"]


def _ratio(case: Case) -> tuple[float, float, str]:
    best = min(case.theirs) / min(case.ours)
    med = float(np.median(case.theirs) / np.median(case.ours))
    return best, med, f"{best:.1f} ({med:.1f})"


def _section_model_cases(ctx: Ctx, key: str, title: str, with_ref: bool) -> None:
    base = ctx.bases[key]
    header(title)
    rows = []
    ratios = []
    worst = {"u": 0.0, "f_link": 0.0, "e": 0.0, "fc": 0.0, "du": 0.0}
    worst_ours = dict(worst)
    for contact in (True, False):
        for kind in ctx.kinds[key]:
            case = get_case(ctx, key, kind, contact)
            ref = None
            if with_ref:
                t0 = time.perf_counter()
                case.m_ref = run_reference(base, case.links, contact, ctx.dt, ctx.duration)
                case.ref_wall = time.perf_counter() - t0
                ref = case.m_ref
            tools: list[tuple[str, Measures, list[float] | None]] = [
                ("OpenSees", case.m_theirs, case.theirs), ("pounding", case.m_ours, case.ours)]
            if kind.name == "maxwell" and key == "sdof":
                walls, m = timed_opensees(case, ctx, maxwell_material=True)
                case.extra["maxwell_material"] = (walls, m)
                tools.insert(1, ("OpenSees Maxwell mat.", m, walls))
            if ref is not None:
                tools.append(("reference", ref, None))
            best, med, txt = _ratio(case)
            ratios.append((case.label, best, med))
            _figures.figure(f"{MODELS[key].stem}, {case.label}: whole run", min(case.ours),
                            _figures.opensees_name(), min(case.theirs),
                            ratio_meaning="OpenSees / pounding",
                            spread=f"best of {len(case.ours)} / {len(case.theirs)}; medians "
                                   f"{med:.1f}x")
            rows += _compare_rows(case, ref, tools, ctx.n_steps, txt)
            # worst agreement, OpenSees (ViscousDamper / Viscous) and pounding, against the
            # reference if there is one, else OpenSees against pounding
            pairs = [(worst, case.m_theirs)] + ([(worst_ours, case.m_ours)] if ref else [])
            against = ref if ref is not None else case.m_ours
            for w, m in pairs:
                w["u"] = max(w["u"], abs(pct(m.u_left.max(), against.u_left.max())),
                             abs(pct(m.u_right.max(), against.u_right.max())))
                w["f_link"] = max(w["f_link"], max(abs(pct(a, b)) for a, b in
                                                   zip(m.f_link, against.f_link)))
                w["e"] = max(w["e"], abs(pct(m.e_link, against.e_link)))
                if against.f_contact > 0:
                    w["fc"] = max(w["fc"], abs(pct(m.f_contact, against.f_contact)))
                w["du"] = max(w["du"], 100 * np.abs(m.u - against.u).max()
                              / np.abs(against.u).max())
            print(f"  {case.label}: pounding {min(case.ours):.4f} s, OpenSees "
                  f"{min(case.theirs):.3f} s"
                  + (f", reference {case.ref_wall:.1f} s" if ref is not None else ""),
                  flush=True)
    table(rows, HEAD)
    vs = "the reference" if with_ref else "pounding"
    print(f"Δ columns: the tool less {vs}, % of {vs}'s value ('worst link': the largest "
          f"|Δ| over the links' peak forces; Δu(t): the largest |Δu| over all floors and "
          f"output steps, % of {vs}'s largest |u|). Fc: pounding / reference locate the peak, "
          f"OpenSees reads it at the output steps; impacts: pounding's count, OpenSees' "
          f"runs of nonzero force. Peak link forces are |F| at the output steps for every "
          f"tool. E_link: pounding / reference the solver's dissipated-by-links energy, "
          f"OpenSees ∫F dd by the trapezoid on the output steps less the Maxwell springs' "
          f"energy. ratio = OpenSees / pounding, bests (medians).")
    print(f"ratio OpenSees / pounding, whole runs: {min(r[1] for r in ratios):.1f}–"
          f"{max(r[1] for r in ratios):.1f}x on the bests, {min(r[2] for r in ratios):.1f}–"
          f"{max(r[2] for r in ratios):.1f}x on the medians")
    print(f"OpenSees against {vs}, worst over the cases: peak |u| {worst['u']:.4f} %, peak "
          f"link force {worst['f_link']:.4f} %, link energy {worst['e']:.3f} %, peak contact "
          f"force {worst['fc']:.3f} %, displacement history {worst['du']:.4f} % of max |u|")
    if with_ref:
        print(f"pounding against the reference, worst: peak |u| {worst_ours['u']:.5f} %, "
              f"peak link force {worst_ours['f_link']:.5f} %, link energy "
              f"{worst_ours['e']:.5f} %, peak contact force {worst_ours['fc']:.5f} %, history "
              f"{worst_ours['du']:.5f} %")
        same = sum(c.m_ours.n_impacts == c.m_ref.n_impacts == c.m_theirs.n_impacts
                   for k, c in ctx.cases.items() if k[0] == key and c.m_ref is not None)
        n = sum(1 for k, c in ctx.cases.items() if k[0] == key and c.m_ref is not None)
        print(f"impacts: the same in all three in {same} of {n} cases")
    else:
        same = sum(c.m_ours.n_impacts == c.m_theirs.n_impacts
                   for k, c in ctx.cases.items() if k[0] == key and c.kind is not None)
        n = sum(1 for k, c in ctx.cases.items() if k[0] == key and c.kind is not None)
        print(f"impacts: the same in both tools in {same} of {n} cases")


def section_sdof(ctx: Ctx) -> None:
    _section_model_cases(ctx, "sdof", f"SDOF pair ({MODELS['sdof'].name}), one link B1F1-B2F1 "
                         f"(best of {ctx.repeat}; pounding of at least {ctx.repeat} over "
                         f"{ctx.window:g} s)", ctx.reference)


def section_shear(ctx: Ctx) -> None:
    _section_model_cases(ctx, "shear", f"Two 10-storey buildings ({MODELS['shear'].name}), ten "
                         f"links B1Fi-B2Fi (best of {ctx.repeat}; pounding of at least "
                         f"{ctx.repeat} over {ctx.window:g} s)", ctx.shear_reference)


def section_cost(ctx: Ctx) -> None:
    header("The price of the links: the same models without links (pounding: exact steps "
           "between contacts) and with them (linear dashpots and linear Maxwell links: exact "
           "steps between contacts; fluid dampers: adaptive steps throughout)")
    rows = []
    for key in ctx.bases:
        for contact in (True, False):
            plain = get_case(ctx, key, None, contact)
            p_ours, p_os = min(plain.ours), min(plain.theirs)
            rows.append([MODELS[key].stem, "contact" if contact else "no contact", "no links",
                         spread(plain.ours, 1e3, ".2f"), f"{1e6 * p_ours / ctx.n_steps:.3f}",
                         "1", spread(plain.theirs, 1.0, ".3f"),
                         f"{1e6 * p_os / ctx.n_steps:.2f}", "1", f"{p_os / p_ours:.1f}",
                         f"{plain.m_ours.n_impacts}/{plain.m_theirs.n_impacts}",
                         plain.m_ours.stats or "exact steps"])
            # the same model stepped as a model with links is (RK throughout, no links):
            # what the stepper costs, apart from the links' own rows and events
            rk = Case(ctx.bases[key], None, contact, "no links, RK")
            timed_pounding(rk, ctx, free_stepping="rk")
            o = min(rk.ours)
            rows.append(["", "", "no links, RK", spread(rk.ours, 1e3, ".2f"),
                         f"{1e6 * o / ctx.n_steps:.3f}", f"{o / p_ours:.1f}", "", "", "", "",
                         f"{rk.m_ours.n_impacts}/-", rk.m_ours.stats])
            for kind in ctx.kinds[key]:
                c = get_case(ctx, key, kind, contact)
                o, t = min(c.ours), min(c.theirs)
                rows.append(["", "", kind.name, spread(c.ours, 1e3, ".2f"),
                             f"{1e6 * o / ctx.n_steps:.3f}", f"{o / p_ours:.1f}",
                             spread(c.theirs, 1.0, ".3f"), f"{1e6 * t / ctx.n_steps:.2f}",
                             f"{t / p_os:.2f}", f"{t / o:.1f}",
                             f"{c.m_ours.n_impacts}/{c.m_theirs.n_impacts}", c.m_ours.stats])
                linear = kind.name in LINEAR_KINDS
                where = f"{MODELS[key].stem}, {'contact' if contact else 'no contact'}"
                _figures.figure(f"{where}: {kind.name} links, the price of the links", o,
                                "the same model without links", p_ours,
                                ratio_meaning="pounding / peer",
                                goal="<= 1.5x" if linear else None,
                                spread=f"best of {len(c.ours)} / {len(plain.ours)}")
                _figures.figure(f"{where}: {kind.name} links, whole run", o,
                                _figures.opensees_name(), t, ratio_meaning="OpenSees / pounding",
                                spread=f"best of {len(c.ours)} / {len(c.theirs)}; OpenSees "
                                       f"pays {t / p_os:.2f}x for the same links")
    table(rows, ["model", "contact", "links", "pounding ms best (worst) xN", "µs/step",
                 "x no links", "OpenSees s best (worst) xN", "µs/step", "x no links",
                 "OS/ours", "impacts ours/OS", "pounding's steps"])
    print("x no links = the run with links / the same model without, bests; OS/ours = "
          "OpenSees / pounding, bests. Without links pounding takes exact steps (a matrix "
          "exponential propagator) between contacts and RK steps only through them; so it does "
          "with linear dashpot links, folded into K and C (their linked buildings one block of "
          "the propagator, the links' dissipated energy one more exact quadratic form a step), "
          "and with linear Maxwell links (their springs' deformations in the block's state); "
          "with fluid dampers it takes RK steps everywhere (at least one "
          "Dormand–Prince step per output step; each link a row of the element loop; a fluid "
          "damper's rate reversal located as an event, where a step ends; its force is not "
          "smooth at ḋ = 0, hence its rejected steps). 'no links, RK': the model without links, stepped by RK "
          "throughout (free_stepping='rk'): the stepper's share of the price.")


LINEAR_KINDS = ("viscous", "maxwell")
"""The link kinds whose law is linear (the dashpot α = 1): the issue's goal, a price ≤ 1.5×."""


SECTIONS: dict[str, Callable[[Ctx], None]] = {
    "model": section_model, "sdof": section_sdof, "shear": section_shear, "cost": section_cost}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sections", default=",".join(SECTIONS),
                    help=f"comma-separated, from {', '.join(SECTIONS)} (default: all)")
    ap.add_argument("--kinds", default=",".join(DEFAULT_KINDS),
                    help=f"link laws, from {', '.join(KINDS)} (default: "
                         f"{','.join(DEFAULT_KINDS)})")
    ap.add_argument("--repeat", type=int, default=3, help="timing repeats, best kept (3)")
    ap.add_argument("--pounding-window", type=float, default=MIN_TIMED_WINDOW,
                    help="pounding repeats a run at least --repeat times and as many more as "
                         f"fit in this many seconds ({MIN_TIMED_WINDOW:g}; 0: --repeat times)")
    ap.add_argument("--dt", type=float, default=1e-3, help="output / analysis step [s] (1e-3)")
    ap.add_argument("--duration", type=float, default=None,
                    help="seconds of El Centro (default: the whole record, 39.99 s)")
    ap.add_argument("--c-sdof", type=float, default=2e5,
                    help="dashpot c of the SDOF pair's link [N·s/m] (2e5)")
    ap.add_argument("--c-shear", type=float, default=1e6,
                    help="dashpot c of each 10-storey link [N·s/m] (1e6)")
    ap.add_argument("--alpha", type=float, default=0.5,
                    help="velocity exponent of the fluid dampers (0.5)")
    ap.add_argument("--tau", type=float, default=0.02,
                    help="Maxwell relaxation time c/k [s] (0.02)")
    ap.add_argument("--no-reference", action="store_true",
                    help="skip simulate_reference for the SDOF pair (~10 s a case)")
    ap.add_argument("--shear-reference", action="store_true",
                    help="also simulate_reference for the 10-storey pair (minutes a case)")
    ap.add_argument("--fresh-memory", action="store_true",
                    help="leave glibc's malloc as it is (default: keep freed memory for reuse, "
                         "see benchmarks/_memory.py)")
    _figures.add_json_option(ap)
    args = ap.parse_args(argv)
    _figures.start("bench_devices", "Links between buildings")
    wanted = parse_list(ap, args.sections, SECTIONS)
    kinds = parse_list(ap, args.kinds, KINDS, "link kind")

    kept = keep_freed_memory(args.fresh_memory)
    print_environment(kept)

    bases = {key: load_base(key) for key in MODELS}
    motion = bases["sdof"].motion
    t_end = motion.duration if args.duration is None else args.duration
    n_steps = int(round(t_end / args.dt))
    print(f"record: {motion.name}, {motion.npts} samples at {motion.dt} s, {t_end:g} s used; "
          f"step {1e3 * args.dt:g} ms ({n_steps:,} steps); links: {', '.join(kinds)}; c "
          f"{args.c_sdof:.3g} (SDOF) / {args.c_shear:.3g} N·s/m (10-storey, each), fluid "
          f"dampers α {args.alpha:g} with c_α = c ({V_REF:g} m/s)^(1−α), Maxwell k = c / "
          f"{args.tau:g} s")
    kind_sets = {"sdof": [Kind(k, args.c_sdof, args.alpha, args.tau) for k in kinds],
                 "shear": [Kind(k, args.c_shear, args.alpha, args.tau) for k in kinds]}
    ctx = Ctx(bases, kind_sets, args.repeat, args.pounding_window, args.dt, args.duration,
              not args.no_reference, args.shear_reference, n_steps)
    # warm-up, untimed: numba's kernel (compiled, or loaded from its cache)
    t0 = time.perf_counter()
    run_pounding(bases["sdof"], kind_sets["sdof"][0].links(bases["sdof"].floors), True,
                 args.dt, 0.5)
    t1 = time.perf_counter()
    run_opensees(bases["sdof"], kind_sets["sdof"][0].links(bases["sdof"].floors), True,
                 args.dt, 0.5)
    print(f"(warm-up, untimed: pounding's first run {t1 - t0:.2f} s, OpenSees' "
          f"{time.perf_counter() - t1:.2f} s)")

    for s in wanted:
        SECTIONS[s](ctx)
    print()
    print(f"at the end: {load()}")
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

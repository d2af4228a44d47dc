"""Where the kernel's time goes on the SDOF pair: a profile, not a comparison.

Times, for the SDOF pair of ``bench_opensees.py`` under El Centro at 1 ms:

* the whole kernel with a 10 m gap (exact steps only) and with the real 20 mm gap;
* one adaptive Dormand–Prince step (``dormand_prince.rk_step``), one right-hand side
  (``rhs.deriv``, contact closed, contact open, no contact) and one event search
  (``events.find_event``), each called in a compiled loop, so the figures are the
  kernel's own cost per call.

The kernel's private functions are called with the very arrays ``simulate`` hands to the
kernel (caught on their way in), so this measures the shipped code, not a copy. Run::

    python benchmarks/profile_kernel.py            # both laws
    python benchmarks/profile_kernel.py --law jankowski --calls 200000

Timings on a shared machine move by about ±10 %; take the best of a few runs. Freed
memory is kept for reuse (``benchmarks/_memory.py``); ``--fresh-memory`` leaves glibc's
malloc alone, and the whole-kernel figures then include first-touch page faults of the
output arrays on some calls.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np
from numba import njit

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_opensees as bench  # noqa: E402
from _memory import keep_freed_memory  # noqa: E402

import pounding.integrate as integrate  # noqa: E402
from pounding.contact.codes import V0  # noqa: E402
from pounding.ground_motion import el_centro  # noqa: E402
from pounding.integrate import dormand_prince, events, layout, rhs  # noqa: E402

_LOOP = dict(cache=False, error_model="numpy", fastmath={"contract"}, _nrt=False)


def kernel_arguments(model: Any, duration: float = 2.0) -> dict[str, Any]:
    """The arguments ``simulate`` passes to ``kernel.integrate_chunk`` for model, by name
    (``run``, ``km``, ``fs``, ``st``, ``out``, ``sc``: the named tuples of
    :mod:`pounding.integrate.workspace` and :mod:`pounding.integrate.kernel_model`)."""
    caught: dict[str, Any] = {}
    real = integrate.integrate_chunk
    names = real.py_func.__code__.co_varnames[:real.py_func.__code__.co_argcount]

    def catch(*args: Any) -> None:
        caught.update(zip(names, args))
        real(*args)

    integrate.integrate_chunk = catch
    try:
        integrate.simulate(model, el_centro(), dt=1e-3, duration=duration)
    finally:
        integrate.integrate_chunk = real
    return caught


@njit(**_LOOP)
def _loop_rk_step(calls, y, kx, px, gnd, fl, ct, el, committed, sstate, lin, ks, ps, ytmp, y1,
                  atol, rtol):
    total = 0.0
    for i in range(calls):
        h = 1e-4 * (1.0 + 1e-9 * i)  # not loop-invariant: nothing can be hoisted
        total += dormand_prince.rk_step(y, kx, px, h, gnd, 0.0, fl, ct, el, committed, sstate,
                                        lin, ks, ps, ytmp, y1, atol, rtol)
    return total


@njit(**_LOOP)
def _loop_deriv(calls, y, gnd, fl, ct, el, committed, sstate, lin, ks, ps):
    total = 0.0
    n = fl.m_diag.shape[0]
    for _ in range(calls):
        y[0] += 1e-12
        rhs.deriv(y, y, gnd, fl, ct, el, committed, sstate, lin, ks, ps, 1)
        total += ks[1, n]
    return total


@njit(**_LOOP)
def _loop_find_event(calls, y0, ks, y1, n, ct, el, hg, committed, grazed):
    total = 0.0
    for i in range(calls):
        te, _, _ = events.find_event(y0, ks, y1, ks, 1e-4 * (1.0 + 1e-9 * i), n, ct, el, hg,
                                     committed, -1, 0, 2e-10, grazed)
        total += te
    return total


def per_call_ns(fn: Any, calls: int, *args: Any) -> float:
    """Best of three timings of ``fn(calls, *args)``, in ns per call (compiled first)."""
    fn(10, *args)
    best = np.inf
    for _ in range(3):
        t0 = time.perf_counter()
        fn(calls, *args)
        best = min(best, time.perf_counter() - t0)
    return best / calls * 1e9


def profile(law: str, calls: int, repeat: int) -> list[tuple[str, str]]:
    """Rows (what, figure) for one contact law."""
    motion = el_centro()
    rows = []
    for label, gap in (("kernel, 10 m gap (exact steps only)", 10.0),
                       ("kernel, 20 mm gap", 0.02)):
        model = bench.sdof_pair_model(law, gap=gap)
        integrate.simulate(model, motion, dt=1e-3)
        res = min((integrate.simulate(model, motion, dt=1e-3) for _ in range(repeat)),
                  key=lambda r: r.wall_time)
        st = res.stats
        rows.append((label, f"{res.wall_time * 1e3:.2f} ms ({res.time.size - 1} steps, "
                            f"{st.rk_steps} RK steps, {st.rejected} rejected, "
                            f"{res.n_impacts} impacts)"))
    a = kernel_arguments(bench.sdof_pair_model(law))
    fl, ct, el, hg = a["km"]
    st, run = a["st"], a["run"]
    n = fl.m_diag.shape[0]
    m = st.x.shape[0]
    npw = layout.P_CONTACT + ct.gap.shape[0]
    closed = st.committed.copy()
    closed[0, V0] = 0.3  # a contact closing at 0.3 m/s
    y = np.zeros(m)
    y[0], y[n], y[n + 1] = 0.021, 0.2, -0.1  # 1 mm into the 20 mm gap, closing
    ks, ps = np.zeros((7, m)), np.zeros((7, npw))
    kx, px = np.zeros((1, m)), np.zeros((1, npw))
    lin = np.zeros((2, n))
    gnd = np.full((rhs.G_ROWS, fl.r.shape[1]), 0.1)
    sstate = st.storeys
    rhs.deriv(y, y, gnd, fl, ct, el, closed, sstate, lin, kx, px, 0)
    rk = per_call_ns(_loop_rk_step, calls, y, kx, px, gnd, fl, ct, el, closed, sstate, lin,
                     ks, ps, np.zeros(m), np.zeros(m), run.atol, run.rtol)
    rows.append(("one Dormand–Prince step (contact closed)", f"{rk:.0f} ns"))
    for label, state in (("one right-hand side, contact closed", closed),
                         ("one right-hand side, contact open", np.zeros_like(closed))):
        ns = per_call_ns(_loop_deriv, calls * 5, y, gnd, fl, ct, el, state, sstate, lin, ks,
                         ps)
        rows.append((label, f"{ns:.1f} ns"))
    none = type(ct)(*(np.ascontiguousarray(c[:0]) for c in ct))
    ns = per_call_ns(_loop_deriv, calls * 5, y, gnd, fl, none, el, closed[:0], sstate, lin,
                     ks, ps)
    rows.append(("one right-hand side, no contact element", f"{ns:.1f} ns"))
    ns = per_call_ns(_loop_find_event, calls * 5, y, ks, y + 1e-6, n, ct, el, hg, closed,
                     np.zeros(ct.gap.shape[0]))
    rows.append(("one event search (contact closed)", f"{ns:.1f} ns"))
    return rows


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--law", choices=("kelvin-voigt", "jankowski", "both"), default="both")
    p.add_argument("--calls", type=int, default=100_000, help="calls per timed loop")
    p.add_argument("--repeat", type=int, default=20, help="whole-kernel timings, best kept")
    p.add_argument("--fresh-memory", action="store_true",
                   help="leave glibc's malloc as it is (see benchmarks/_memory.py)")
    args = p.parse_args(argv)
    keep_freed_memory(args.fresh_memory)
    laws = ("kelvin-voigt", "jankowski") if args.law == "both" else (args.law,)
    for law in laws:
        print(f"SDOF pair, {law} (El Centro, 1 ms)")
        for what, figure in profile(law, args.calls, args.repeat):
            print(f"  {what:<42} {figure}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""A cheap test, inlined in the adaptive loop, that an accepted step holds no event: where it
passes, :func:`pounding.integrate.events.find_event` would return "none", and is not called.

Called, the search passes the model's contact, element and hinge rows as some hundred and
fifty flattened values, a fifth of a yielding SDOF's whole RK step (2026-11-28). The test
decides only whether to call it, never what it finds: it passes only where every row is
one the search would certainly pass over —

* an open contact whose gap stays, with the cubic's bound, farther than ``graze_tol`` from
  closing (:func:`find_event`'s first test, here with a margin of 10⁻⁹ of its value, so
  that no rounding of the same sum can turn it);
* an element row whose drift rate keeps its sign over the step (``r0 > 0, r1 ≤ 0`` or
  ``r0 < 0, r1 ≥ 0`` is a reversal, :func:`pounding.integrate.events.rate_event`), or a
  link with no event at a reversal;

and fails for any closed contact, cable restrainer, storey over a rocking footing or hinge
row (their events are left to the search).
"""

from __future__ import annotations

from numba import njit

from pounding.contact.codes import V0
from pounding.devices.laws import DEVICE_MIN, RESTRAINER, has_rate_cusp
from pounding.integrate.layout import EL_ROCK, ROW_BLOCK
from pounding.integrate.rhs import INLINE, gap_row


@njit(**INLINE)
def no_event_possible(y0, k0, y1, k1, h, n, ct, el, hg, committed, graze_tol):
    """True if :func:`pounding.integrate.events.find_event` with nothing to skip would find
    no event in the step from ``y0`` to ``y1`` of length h (``k0`` row 0: f(y0); ``k1``
    row 6: f(y1)); False if it might (then it is called)."""
    if hg.dof.shape[0] > 0:
        return False
    cdof, cw, cgap, _, _ = ct
    for c in range(cgap.shape[0]):
        if committed[c, V0] != 0.0:
            return False
        ds0, r0 = gap_row(c, y0, n, cdof, cw)
        ds1, r1 = gap_row(c, y1, n, cdof, cw)
        d0 = ds0 - cgap[c]
        d1 = ds1 - cgap[c]
        acc0 = 0.0
        acc1 = 0.0
        for q0 in range(0, cdof.shape[1], ROW_BLOCK):
            for q in range(q0, q0 + ROW_BLOCK):
                acc0 += cw[c, q] * k0[0, n + cdof[c, q]]
                acc1 += cw[c, q] * k1[6, n + cdof[c, q]]
        reach = (max(d0, d1) + 0.25 * h * (abs(r0) + abs(r1))
                 + 0.125 * h * h * (abs(acc0) + abs(acc1)))
        if not reach + 1e-9 * abs(reach) <= -graze_tol:
            return False
    s_lo, s_hi, s_code, s_par = el.lo, el.hi, el.code, el.params
    for s in range(s_lo.shape[0]):
        code = s_code[s]
        if code == RESTRAINER:
            return False
        if code >= DEVICE_MIN and not has_rate_cusp(code, s_par[s, 1]):
            continue
        if s_par[s, EL_ROCK] >= 0.0:
            return False  # (a storey over a rocking footing: left to the search)
        # the drift rate as :func:`pounding.integrate.rhs.element_drift` has it (one
        # difference), here where the compiler does not inline a call
        hi = s_hi[s]
        lo = s_lo[s]
        r0 = y0[n + hi] - y0[n + lo] if lo >= 0 else y0[n + hi]
        r1 = y1[n + hi] - y1[n + lo] if lo >= 0 else y1[n + hi]
        if (r0 > 0.0 and r1 <= 0.0) or (r0 < 0.0 and r1 >= 0.0):
            return False
    return True

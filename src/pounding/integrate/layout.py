"""The kernel's data layout: columns of its output tables, its workspace slots, event kinds
and tolerances — the numbers every part of the compiled time stepper
(:mod:`pounding.integrate.kernel`) and its Python caller (:func:`pounding.integrate.simulate`)
agree on.
"""

from __future__ import annotations

import numpy as np

# ---------------------------------------------------------------- impact table (one row per impact)
(IMP_CONTACT, IMP_START, IMP_END, IMP_V0, IMP_PEAK, IMP_PEAK_TIME, IMP_DMAX, IMP_E,
 IMP_ENERGY) = range(9)
IMP_COLUMNS = 9
"""Contact index, start and end [s], closing velocity v0 [m/s], peak force [N] and its time
[s], largest penetration [m], restitution, energy dissipated [J]."""

# ---------------------------------------------------------------- energy history columns
(E_INPUT, E_KINETIC, E_STRAIN, E_DAMPING, E_CONTACT_WORK, E_CONTACT_STORED,
 E_HYSTERETIC, E_DEVICE) = range(8)
ENERGY_COLUMNS = 8
"""Cumulative energies [J]: input by the ground, kinetic, strain (storeys, and the springs
of yielding storeys and links), viscous damping, contact work, energy stored in the
contacts, hysteretic (yielding storeys) and dissipated by the links between buildings."""

# ---------------------------------------------------------------- power rows of a step's stages
# input, viscous, yielding storeys, links, then one per contact
P_INPUT, P_DAMP, P_STOREY, P_DEVICE = range(4)
P_CONTACT = 4

# ---------------------------------------------------------------- event kinds
# Event kinds and peak columns, which the compiled functions pass as arguments, are NumPy
# integers, not Python ints: numba types a Python int constant as a literal and compiles a
# called function once more for every literal value it is given (locate, event_value,
# is_upward and event_tolerance for EV_ONSET, update_quintic for each peak column), which
# cost a first compile several seconds.
EV_ONSET, EV_SEPARATION, EV_MAX_COMPRESSION, EV_RELOADING = (np.int64(k) for k in (1, 2, 3, 4))
EV_DRIFT_MAX, EV_DRIFT_MIN = np.int64(5), np.int64(6)
EV_GRAZE = np.int64(7)
"""An open gap whose penetration peaks within the event tolerance of zero inside a step:
the peak is located on real steps to decide whether the gap closes there."""
EV_RELEASE, EV_REENGAGE = np.int64(8), np.int64(9)
"""A closed contact whose law clips its force at zero (Kelvin–Voigt without tension,
:func:`pounding.contact.dispatch.law_releases`): the unclipped force ``k δ + c δ̇`` turning
negative (the bodies released with the spring still compressed) or positive again before
δ = 0 (engaged again)."""
EV_HINGE_HI, EV_HINGE_LO = np.int64(10), np.int64(11)
"""A plastic hinge of a yielding frame reaching the upper / lower end of the branch it is on
(its rotation θ crossing ``HS_HI`` upward / ``HS_LO`` downward): yield, capping, the elastic
branch's other bound (:mod:`pounding.hysteresis.hinges`)."""
EV_HINGE_TURN_DOWN, EV_HINGE_TURN_UP = np.int64(12), np.int64(13)
"""A hinge on a branch that holds for one direction only (``HS_DIR`` +1 / −1) reversing: its
rotation rate θ̇ turning negative / positive."""
EV_TAUT, EV_SLACK, EV_YIELD = np.int64(14), np.int64(15), np.int64(16)
"""A cable restrainer's corners (:func:`pounding.devices.laws.restrainer_kinks`): its elastic
elongation ``e`` turning positive (the slack taken up) / back to ≤ 0 (slack again), its
margin to yield turning positive (it yields). Element-row events, like ``EV_DRIFT_*``."""
EV_FRACTURE = np.int64(17)
"""A closed shear key's penetration reaching its fracture deformation (``δ − δ_u`` turning
positive, :func:`pounding.contact.dispatch.fracture_value`): it breaks off, its force drops
to zero there. A contact event."""

# ---------------------------------------------------------------- workspace scalars / counters
(W_H, W_E_INPUT, W_E_DAMP, W_E_STOREY, W_ERR_OLD, W_PEAK_MARGIN, W_E_DEVICE,
 W_RESUME_S) = range(8)
WS_F_SIZE = 8
"""Workspace scalars: proposed RK step [s], cumulative input, viscous and storey work [J],
last error norm, and the margin by which an acceleration peak between two exact-step
samples can exceed the larger sample (relative; :func:`pounding.integrate.peak_margin`),
the links' cumulative work [J], and the local time [s] inside grid step ``I_REACHED`` at
which the next call resumes (0: at the grid point; set where a call returned at a hinge
event, :data:`I_STOP`)."""
(I_MODE, I_NIMP, I_OVERFLOW, I_NSTEPS, I_NREJECT, I_NEVENTS, I_FAILED, I_FAIL_STEP,
 I_STEP_BUDGET, I_ONSET_C, I_CALL_STEPS, I_REACHED, I_FAIL_ROW, I_STOP, I_STOP_ROW) = range(15)
WS_I_SIZE = 15
"""Counters: mode (0 exact, 1 adaptive), impacts, table overflow, RK steps, rejected steps,
events, failure kind (:data:`FAIL_UNDERFLOW`, :data:`FAIL_BUDGET`, :data:`FAIL_NONFINITE`,
:data:`FAIL_UNKNOWN_LAW`), the grid step it happened in, the largest number of RK steps
allowed in all, the contact whose onset ended the last accepted step (−1: none), the count
of RK steps after which a call returns at the next grid point (so that a call holds Python
— and with it Ctrl-C and SIGTERM — for a bounded time), the grid point a call reached, the
row a failure names (a contact c, or an element row n_c + s), why a call returned before
its last grid point (0: it did not, or the step count; :data:`STOP_HINGE`: at a hinge
event, for Python to move the hinges and give the frame its next configuration) and the
hinge row of that event."""

STOP_HINGE = 1
"""``ws_i[I_STOP]``: the call returned at a located hinge event (the step to it accepted,
``ws_f[W_RESUME_S]`` the local time in grid step ``ws_i[I_REACHED]``)."""

# ---------------------------------------------------------------- element rows
EL_ROCK, EL_LEVER, EL_FOLDED = 6, 7, 8
ELEMENT_PARAMS = 9
"""Columns of an element row's constants (``ElementRows.params``, :meth:`pounding.model.
PoundingModel.storey_arrays`): its law's constants first (at most 6 of them,
:data:`pounding.hysteresis.base.PARAMS_SIZE`), then a third DOF its drift takes and that
DOF's lever [m]: ``d = u[hi] − u[lo] − lever · u[rock]`` — a storey of a building on a
flexible base, whose footing rocks by ``u[rock]`` [rad] under it
(:mod:`pounding.structure.foundation.flexible_base`); −1 (as a float): none, and the lever
is 0; then ``EL_FOLDED``: 1 for a link whose law is linear and has no internal state
(Kelvin; a viscous dashpot with α = 1), whose spring and dashpot are in the kernel's K and C
(:func:`pounding.integrate.kernel_model.fold_linear_links`) — the right-hand side does not
apply its force again, and its row stays for its outputs (its force from the state, its
dashpot's work as the links' energy) — 0 otherwise. In the constants' array, not arrays of
their own: every array of a group is passed to every call that takes the group."""

# ---------------------------------------------------------------- hinge rows (yielding frames)
(HS_A0, HS_LO, HS_HI, HS_DIR, HS_KT, HS_Q, HS_THETA_C, HS_M_C, HS_WORK_C, HS_K_UNLOAD,
 HS_REC0, HS_WABS, HS_TH0, HS_R0, HS_TH1, HS_R1) = range(16)
HS_COLUMNS = 16
"""Columns of a hinge row's state (``HingeRows.state``), set by Python at every
configuration of its frame: the offset ``a0`` of its rotation ``θ = Σ w u + a0`` [rad]
(u the floors' displacements from the gravity state), the lower and upper end of the
branch it is on [rad] (±inf: none), the direction that branch holds for (0: both ways;
±1: one way, its reversal an event), the branch's tangent ``k_t`` [N·m/rad] and offset
``q`` (the moment ``M = k_t θ + q`` [N·m]), the rotation and moment where the hinge was last
committed, its work ``∫ M dθ`` up to there [J], its unloading stiffness [N·m/rad] (the
recoverable energy is ``M²/(2 k_unload)``), its recoverable energy at the start [J], and
``Σ |w|`` [rad/m] (the tolerance of θ from the displacements'); then the kernel's own
scratch: the rotation and its rate at the start of the step being searched for events
(``HS_TH0``, ``HS_R0``) and at the end it was last searched to (``HS_TH1``, ``HS_R1``) —
an accepted step's end is the next step's start, so each step computes the hinges'
rotations once, not twice (:func:`pounding.integrate.events.find_event`)."""

STATION_MASS: float = 1e-30
"""The mass [kg] of a ground station's DOF (spatially varying ground,
:mod:`pounding.integrate.stations`): its kinetic energy and the input energy of its own
record vanish; :func:`pounding.integrate.rhs.deriv` knows a station by it, takes back what
the contacts push on it (its motion is its record's) and counts the work its motion does
through them as input."""

FAIL_UNDERFLOW, FAIL_BUDGET, FAIL_NONFINITE, FAIL_UNKNOWN_LAW = 1, 2, 3, 4
"""Why an integration stopped: the adaptive step fell below 10⁻¹⁴ of the grid step, the
run used up its budget of adaptive steps, the state (or an energy, which sums every
entry of it) stopped being a finite number, or a contact or element row has a law code
that no compiled law implements (its trial is the failure value NaN; the row is
``ws_i[I_FAIL_ROW]``)."""

# ---------------------------------------------------------------- located peaks, per floor
PK_U, PK_U_T, PK_D, PK_D_T, PK_A, PK_A_T = (np.int64(k) for k in range(6))
PK_COLUMNS = 6
"""Largest |displacement| [m], |storey drift| [m] (the storey below each floor) and
|absolute acceleration| [m/s²] of every floor, each with its time [s]."""

# ---------------------------------------------------------------- contact rows
ROW_BLOCK: int = 4
"""The kernel reads a contact row (its DOFs and weights, :meth:`pounding.model.PoundingModel.
contact_kinematics`) in blocks of this many entries, each a loop of constant length that the
compiler unrolls; rows are padded with zero weights to a multiple of it
(:func:`pounding.integrate.kernel_model.padded_rows`). Read as one loop of the row's width
W, the same loops cost the exact steps of the SDOF pair 25 % of their time."""

# ---------------------------------------------------------------- tolerances
EVENT_TOL: float = 1000.0
"""An event is located once its function (δ, δ̇ or a drift rate) is within this many
absolute tolerances of zero on an actual RK step: 2×10⁻¹⁰ m of penetration for the default
rtol and a 20 mm gap, far below anything that moves a contact force or an impact's start;
tighter only costs RK steps (measured: about 5 % of them for the SDOF pair)."""

DELTA_EPS: float = 1e-300
"""Penetration at which a closed contact is evaluated when δ ≤ 0 inside a step [m]."""

RATE_SIDE: float = 1e-300
"""A closing rate [m/s] just above zero: where a law is evaluated on its approach branch
at δ̇ = 0 (see :func:`pounding.integrate.rhs.deriv`)."""

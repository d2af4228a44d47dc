"""A flat sliding bearing's stick–slip against its closed form: a deck launched along its
slider on a rigid pier.

The slider is the Bouc–Wen law with ``α = 0``, ``n = 2``, ``β = γ = ½`` (Constantinou et
al. 1990): while the deck moves forward from rest, ``dz/dx = (1 − z²)/Y`` so ``z = tanh(x/Y)``
and the friction force ``μW tanh(x/Y)`` (the stick phase is the first few ``Y``). The
deck's kinetic energy goes into friction work until it stops:

    ½ m v₀² = ∫₀^x_max μW tanh(x/Y) dx = μW Y ln cosh(x_max/Y)
    ⇒ x_max = Y arccosh(exp(v₀² / (2 μ g Y)))  ≈  v₀²/(2μg) + Y ln 2,

Coulomb's slide ``v₀²/(2μg)`` plus ``Y ln 2`` for the stick phase. After it stops, the deck
springs back elastically (``ż = ẋ/Y`` while ``ẋ < 0 < z``) — the "stick" of the next cycle.
"""

from __future__ import annotations

import math

import numpy as np

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import GroundMotion
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure.bridge import Bearing, Bridge, BridgeFrame, Pier

G = 9.80665


def test_a_deck_launched_on_its_slider_stops_where_the_closed_form_says() -> None:
    m, mu, y, v0 = 2.0e6, 0.06, 5e-4, 0.5
    frame = BridgeFrame(m, [Pier(8.0, 1.0e12, 1.0e5)], Bearing.sliding(mu, m * G, y),
                        zeta=0.0)
    model = PoundingModel.from_bridge(Bridge([frame], []),
                                      ContactSpec("kelvin-voigt", k=1e9, e=0.6))
    at_rest = GroundMotion(0.01, np.zeros(201), "no shaking")
    res = simulate(model, at_rest, duration=2.0, initial_velocity=np.array([v0, 0.0]),
                   rtol=1e-10)
    deck = res.displacement[:, 0] - res.displacement[:, 1]  # (the slide, over the cap)
    x_max = y * math.acosh(math.exp(v0 ** 2 / (2 * mu * G * y)))
    coulomb = v0 ** 2 / (2 * mu * G)
    assert abs(x_max - (coulomb + y * math.log(2.0))) < 1e-9  # (the expansion)
    # the deck's peak, located inside the solver's steps: the slide plus the cap's
    # deflection, at most twice μW/k_pier under the friction force (1.2e-6 m here; the
    # stick phase's Y ln 2 that tells the law from Coulomb's is 3.5e-4 m)
    cap = 2 * mu * m * G / 1.0e12
    peak = float(res.peak_displacement[0])
    assert abs(peak - x_max) < cap, (peak, x_max)
    assert abs(float(deck.max()) - x_max) < 1e-3 * x_max  # (at the 0.01 s output steps)
    # it stops near Coulomb's time v0/(μg) (the stick phase shifts it by O(Y/v0))
    t_stop = float(res.time[np.argmax(deck)])
    assert abs(t_stop - v0 / (mu * G)) < 0.02
    # and springs back by less than the stick displacement's couple: the slide is kept
    assert x_max - 3 * y < deck[-1] < x_max
    # the energy balance: the kinetic energy went into the slider's hysteresis
    assert res.energy_balance_error < 1e-8

"""No silent wrong path: a law whose code no compiled law implements is refused — by the law
object before it computes, where a model is built (one line naming the law's class and its
code), and by the kernel (its dispatchers return the failure value NaN, which stops the run
with an ``IntegrationError``). Before, every dispatcher ran some other law for an unknown
code: a contact law with code 99 and k = 1e8 N/m gave 0 N at 1 mm (the bilinear element's
branch) instead of 100 kN, an unknown storey code the elastic storey, an unknown link code
the Maxwell link."""

from __future__ import annotations

import dataclasses
import math
from typing import ClassVar

import numpy as np
import pytest

from pounding import PoundingModel, simulate
from pounding.contact import LinearSpring
from pounding.contact.dispatch import CONTACT_LAW_CODES, law_trial, stored_energy
from pounding.devices import Link
from pounding.devices.laws import (
    DEVICE_CODES,
    device_rate_terms,
    device_stored,
    device_trial,
)
from pounding.ground_motion import el_centro
from pounding.hysteresis import Bilinear
from pounding.hysteresis.dispatch import (
    STOREY_LAW_CODES,
    storey_recoverable,
    storey_trial,
)
from pounding.integrate import IntegrationError
from pounding.integrate.kernel_model import kernel_model
from pounding.model import ContactSpec
from pounding.structure import ShearBuilding

KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)


@dataclasses.dataclass(frozen=True)
class Stiff99(LinearSpring):
    """A linear spring that claims a code of its own."""

    code: ClassVar[int] = 99


@dataclasses.dataclass(frozen=True)
class Spec99(ContactSpec):
    """A contact spec that builds :class:`Stiff99`."""

    def build(self, m1: float, m2: float) -> LinearSpring:  # type: ignore[override]
        return Stiff99(k=1e8)


@dataclasses.dataclass(frozen=True)
class Bilinear99(Bilinear):
    code: ClassVar[int] = 99  # type: ignore[misc]


def test_a_contact_law_with_an_unknown_code_is_refused_naming_its_class_and_code():
    law = Stiff99(k=1e8)
    for call in (lambda: law.trial(1e-3, 0.0), lambda: law.respond([1e-3], [0.0])):
        with pytest.raises(ValueError, match=r"Stiff99 has code 99, which no compiled") as exc:
            call()
        assert "\n" not in str(exc.value)
    # a subclass that keeps its parent's code is its parent's law: 100 kN at 1 mm
    @dataclasses.dataclass(frozen=True)
    class Spring(LinearSpring):
        pass

    assert Spring(k=1e8).trial(1e-3, 0.0).force == pytest.approx(1e5, rel=1e-12)


def test_the_compiled_dispatchers_return_nan_for_an_unknown_code_and_a_number_for_every_known():
    for code in CONTACT_LAW_CODES:
        f = law_trial(code, 1.0, 1.0, 1.0, 1e-3, 0.1, 0.1, 0.0, 1e-3)
        assert all(math.isfinite(v) for v in f), code
        assert math.isfinite(stored_energy(code, 1.0, 0.5, 1.0, 1e-3, 0.0))
    assert math.isnan(law_trial(99, 1e8, 0.0, 0.0, 1e-3, 0.0, 0.0, 0.0, 0.0)[0])
    assert math.isnan(stored_energy(99, 1e8, 0.0, 0.0, 1e-3, 0.0))
    sp = np.array([[1e7, 1e5, 0.1, 1.0, 0.5, 0.5]])
    for code in [*STOREY_LAW_CODES, *DEVICE_CODES]:
        assert all(math.isfinite(v) for v in storey_trial(code, sp, 0, 1e-3, 0.1, 0.2, 0.0, 0.0))
        assert math.isfinite(storey_recoverable(code, sp, 0, 1e-3, 0.2, 1e4))
    for code in (3, 9, 99):  # neither a storey law nor a link
        assert math.isnan(storey_trial(code, sp, 0, 1e-3, 0.1, 0.0, 0.0, 0.0)[0])
        assert math.isnan(storey_recoverable(code, sp, 0, 1e-3, 0.0, 1e4))
    for fn in (lambda c: device_trial(c, 1e7, 1e5, 1.0, 0.0, 1e-3, 0.1, 0.0)[0],
               lambda c: device_rate_terms(c, 1e7, 1e5, 1.0, 0.1)[0],
               lambda c: device_stored(c, 1e7, 1e5, 1.0, 0.0, 1e-3, 0.0)):
        assert all(math.isfinite(fn(code)) for code in DEVICE_CODES)
        assert math.isnan(fn(14))


def test_a_model_with_a_law_of_unknown_code_is_refused_where_it_is_built():
    a, b = ShearBuilding.sdof(2e5, period=0.5), ShearBuilding.sdof(3e5, period=1.0)
    with pytest.raises(ValueError, match=r"^contact: contact law Stiff99 has code 99"):
        PoundingModel([a, b], [0.02], Spec99("linear-spring", k=1e8))
    yielding = ShearBuilding([2e5], [8e6], [3.0], storey_law=Bilinear99(yield_drift=0.01))
    with pytest.raises(ValueError, match=r"^buildings\[1\]\.storey_law: storey law Bilinear99 "
                                         r"has code 99"):
        PoundingModel([a, yielding], [0.02], KV)


@pytest.mark.parametrize("row", ["contact", "storey", "link"])
def test_the_kernel_stops_at_a_law_code_it_does_not_implement(row):
    """The kernel's own check, past the model's (an array tampered with after the check):
    an IntegrationError naming the row and the code, not a run with another law."""
    a = ShearBuilding([2e5], [3.2e7], [3.0], storey_law=Bilinear(yield_drift=0.01))
    b = ShearBuilding.sdof(3e5, period=1.0)
    link = Link(("B1F1", "B2F1"), "viscous", c=2e5)
    model = PoundingModel([a, b], [0.02], KV, devices=[link])
    km = kernel_model(model)
    array, i, where = {"contact": (km.contacts.code, 0, "contact B1F1-B2F1"),
                       "storey": (km.elements.code, 0, "yielding storey 1"),
                       "link": (km.elements.code, 1, "link B1F1-B2F1")}[row]
    kept = array[i]
    array[i] = 99 if row == "contact" else 14
    try:
        with pytest.raises(IntegrationError, match=rf"^solver: {where} has law code "
                                                   rf"{array[i]}, which no compiled law"):
            simulate(model, el_centro().trimmed(0.5))
    finally:
        array[i] = kept

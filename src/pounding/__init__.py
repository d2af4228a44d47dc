"""pounding: seismic pounding of adjacent buildings.

The public API, by concept (each lives in its own module, and each name below can be
imported from ``pounding`` itself)::

    >>> from pounding import ContactSpec, PoundingModel, ShearBuilding, el_centro, simulate
    >>> model = PoundingModel([ShearBuilding.sdof(2e5, period=0.5),
    ...                        ShearBuilding.sdof(3e5, period=1.0)], gaps=[0.02],
    ...                       contact=ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))
    >>> result = simulate(model, el_centro())
    >>> result.n_impacts > 0
    True

* the problem: buildings (:class:`ShearBuilding`, damping models), the pair or row of them with
  their gaps and contact law (:class:`PoundingModel`, :class:`ContactSpec`) —
  :mod:`pounding.structure`, :mod:`pounding.model`
* frames with plastic hinges: :class:`Frame`, :func:`regular_frame`, hinge laws
  (:class:`ElasticPlastic`, :class:`BilinearHinge`) and the event-to-event :func:`pushover`
  — :mod:`pounding.structure.frame`, :mod:`pounding.structure.frame_analysis`
* the excitation: :class:`GroundMotion`, record readers, the bundled El Centro 1940 record —
  :mod:`pounding.ground_motion`
* the solver: :func:`simulate` (:mod:`pounding.integrate`); the answer: :class:`Result`
* a model file run end to end: :func:`run`, :func:`load_config`
* contact laws and damping formulas — :mod:`pounding.contact`; one collision of two bodies:
  :func:`simulate_collision`, calibration and fitting
* the seed paper's link-element relations — :mod:`pounding.contact.link_element`

Names are imported on first use (PEP 562), so ``import pounding`` is quick and pulls in
numba, SciPy or xarray only when something that needs them is used.

Units are SI throughout: m, kg, s, N, J.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from pounding.lazy import lazy_exports

__version__ = "0.1.0"

_EXPORTS: dict[str, str] = {
    # problem
    "PoundingModel": "pounding.model",
    "ContactSpec": "pounding.model",
    "ShearBuilding": "pounding.structure",
    "RayleighDamping": "pounding.structure",
    "ModalDamping": "pounding.structure",
    "modes": "pounding.structure",
    "Bilinear": "pounding.hysteresis",
    "BoucWen": "pounding.hysteresis",
    "Frame": "pounding.structure.frame",
    "FrameHinge": "pounding.structure.frame",
    "regular_frame": "pounding.structure.frame",
    "ElasticPlastic": "pounding.hysteresis.hinges",
    "BilinearHinge": "pounding.hysteresis.hinges",
    "pushover": "pounding.structure.frame_analysis",
    "PushoverResult": "pounding.structure.frame_analysis",
    # excitation
    "GroundMotion": "pounding.ground_motion",
    "el_centro": "pounding.ground_motion",
    "read_at2": "pounding.ground_motion",
    "read_record": "pounding.ground_motion",
    "read_text": "pounding.ground_motion",
    # solver and result
    "simulate": "pounding.integrate",
    "Result": "pounding.result",
    "SolverStats": "pounding.result",
    # model files
    "run": "pounding.run_file",
    "RunOutput": "pounding.run_file",
    "load_config": "pounding.config",
    "PlausibilityWarning": "pounding.plausibility",
    # contact laws and damping
    "FORMULAS": "pounding.contact",
    "LAWS": "pounding.contact",
    "BilinearImpact": "pounding.contact",
    "ContactLaw": "pounding.contact",
    "Hertz": "pounding.contact",
    "HuntCrossley": "pounding.contact",
    "KelvinVoigt": "pounding.contact",
    "LinearSpring": "pounding.contact",
    "ModifiedKelvinVoigt": "pounding.contact",
    "NonlinearViscoelastic": "pounding.contact",
    "hertzdamp": "pounding.contact",
    "m_effective": "pounding.contact",
    "naderpour_2015": "pounding.contact",
    "make_law": "pounding.contact.factory",
    "restitution_audit": "pounding.contact.audit",
    "calibrate": "pounding.contact.calibration",
    "calibrate_bilinear": "pounding.contact.calibration",
    "fit_impact": "pounding.contact.calibration",
    "CollisionResult": "pounding.contact.collision",
    "simulate_collision": "pounding.contact.collision",
}
"""Public name → the module that defines it."""

__all__ = sorted(_EXPORTS) + ["__version__"]


__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)


if TYPE_CHECKING:  # what type checkers and IDEs see: the same names, imported eagerly
    from pounding.config import load_config
    from pounding.contact import (
        FORMULAS,
        LAWS,
        BilinearImpact,
        ContactLaw,
        Hertz,
        HuntCrossley,
        KelvinVoigt,
        LinearSpring,
        ModifiedKelvinVoigt,
        NonlinearViscoelastic,
        hertzdamp,
        m_effective,
        naderpour_2015,
    )
    from pounding.contact.audit import restitution_audit
    from pounding.contact.calibration import calibrate, calibrate_bilinear, fit_impact
    from pounding.contact.collision import CollisionResult, simulate_collision
    from pounding.contact.factory import make_law
    from pounding.ground_motion import GroundMotion, el_centro, read_at2, read_record, read_text
    from pounding.hysteresis import Bilinear, BoucWen
    from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic
    from pounding.integrate import simulate
    from pounding.model import ContactSpec, PoundingModel
    from pounding.plausibility import PlausibilityWarning
    from pounding.result import Result, SolverStats
    from pounding.run_file import RunOutput, run
    from pounding.structure import ModalDamping, RayleighDamping, ShearBuilding, modes
    from pounding.structure.frame import Frame, FrameHinge, regular_frame
    from pounding.structure.frame_analysis import PushoverResult, pushover

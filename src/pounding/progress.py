"""The progress callback every runner takes: ``progress(done, total)``.

:func:`pounding.run`, :func:`pounding.studies.sweep.run_sweep`,
:func:`pounding.studies.fragility.run_study` and
:func:`pounding.studies.mitigation.run_mitigation` call it as their work advances, with
how much is done and how much there is in all, in the runner's own unit:

=====================  ==================================================
runner                 ``done`` and ``total``
=====================  ==================================================
``run``                seconds of ground motion simulated, and in all [s]
``run_sweep``          cases finished (by this run or before), and in all
``run_study``          runs finished (by this run or before), and in all
``run_mitigation``     runs finished, and in all
=====================  ==================================================

``done / total`` is the fraction done; the last call has ``done == total``.
"""

from __future__ import annotations

from typing import Protocol

__all__ = ["Progress"]


class Progress(Protocol):
    """``progress(done, total)``: how much of the work is done, and how much there is (in
    the runner's unit, module docstring). Any callable of two positional numbers is one:
    ``lambda done, total: print(f"{100 * done / total:.0f} %")``."""

    def __call__(self, done: float, total: float, /) -> None: ...

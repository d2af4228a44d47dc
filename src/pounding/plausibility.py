"""Warnings of inputs that are valid but probably in the wrong unit.

A gap of 40 m, a floor of 600 kg or a record whose peak is 30 g can all be simulated, and
each is almost surely a number in another unit (millimetres, tonnes, cm/s²). Such inputs
are not refused; pounding says what it noticed in one line and goes on. The checks of a
model file are in :mod:`pounding.config.plausibility`.

In Python they are :class:`PlausibilityWarning` warnings (a :class:`UserWarning`), which
the ``warnings`` module shows once per place and lets you filter::

    import warnings
    from pounding import PlausibilityWarning
    warnings.simplefilter("ignore", PlausibilityWarning)   # or "error" to stop on one

The command line prints each on standard error as a line starting ``warning:``.

This module imports nothing heavy: the command line imports it at start-up.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterable

__all__ = ["PlausibilityWarning", "warn_plausibility"]


class PlausibilityWarning(UserWarning):
    """An input that pounding accepts but that is probably in the wrong unit (a gap of
    40 m, a floor mass of 600 kg, a fundamental period of 0.006 s, a PGA of 30 g)."""


def warn_plausibility(messages: Iterable[str], stacklevel: int = 2) -> None:
    """Issue each message as a :class:`PlausibilityWarning` (``stacklevel`` as
    :func:`warnings.warn`'s, counted from the caller of this function)."""
    for message in messages:
        warnings.warn(message, PlausibilityWarning, stacklevel=stacklevel + 1)

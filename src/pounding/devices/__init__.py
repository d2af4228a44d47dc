"""Mitigation devices: links (dampers, springs) between buildings, and bumpers in the gap.

* :class:`Link` — a damper or spring joining two floors of different buildings, acting at
  all times (:mod:`pounding.devices.laws` for the force laws);
* :class:`Bumper` — an elastomeric pad in the gap of a contact;
* :mod:`pounding.devices.optimal` — the optimal coefficient of a damper linking two
  oscillators (closed form under white noise; the search on a record is the study
  :mod:`pounding.studies.optimal_link`).

Give them to :class:`pounding.PoundingModel` as ``devices=[…]`` or in a model file as
``[[device]]`` tables (docs/mitigation.md).
"""

from pounding.devices.bumper import Bumper
from pounding.devices.link import LINK_KINDS, Link, parse_floor

__all__ = ["Bumper", "LINK_KINDS", "Link", "parse_floor"]

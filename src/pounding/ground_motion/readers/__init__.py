"""Record file readers, one module a format, each converting the file's units to SI on
reading (:func:`pounding.units.acceleration_factor`):

* :mod:`~pounding.ground_motion.readers.at2` -- PEER strong-motion ``.AT2`` files
  (:func:`read_at2`, every header variant in common use);
* :mod:`~pounding.ground_motion.readers.knet` -- NIED's K-NET and KiK-net ASCII files
  (:func:`read_knet`: counts times the scale factor, less the record's mean);
* :mod:`~pounding.ground_motion.readers.cosmos` -- COSMOS Volume 1 and 2 files, format
  v1.20 (:func:`read_cosmos`);
* :mod:`~pounding.ground_motion.readers.text` -- plain one-column (with ``dt``),
  two-column time/acceleration or several-column text with the acceleration's ``column``
  chosen (:func:`read_text`), which states no unit: ``units``
  is required (:class:`UnitsRequired` otherwise; :func:`needs_units` tells such a file);
* :mod:`~pounding.ground_motion.readers.dispatch` -- :func:`read_record`, any of the
  above, chosen by suffix and content; any other file is refused in one line naming the
  formats read.

What the formats share: :mod:`~pounding.ground_motion.readers.files` (opening the file and
splitting its lines), :mod:`~pounding.ground_motion.readers.numbers` (the numbers on a data
line), :mod:`~pounding.ground_motion.readers.units` (the unit a header states, against the
one given) and :mod:`~pounding.ground_motion.readers.step` (the time step likewise).
Every reader raises :class:`ValueError` naming the file, the line and the bad value.
"""

from pounding.ground_motion.readers.at2 import read_at2
from pounding.ground_motion.readers.cosmos import read_cosmos
from pounding.ground_motion.readers.dispatch import (
    FORMATS,
    SUPPORTED,
    RecordFormat,
    needs_units,
    read_record,
)
from pounding.ground_motion.readers.knet import read_knet
from pounding.ground_motion.readers.units import ASSUMED, UNIT_NAMES, UnitsRequired
from pounding.ground_motion.readers.text import read_text

__all__ = ["ASSUMED", "FORMATS", "SUPPORTED", "UNIT_NAMES", "RecordFormat", "UnitsRequired",
           "needs_units", "read_at2", "read_cosmos", "read_knet", "read_record", "read_text"]

"""Record file readers, one module a format, each converting the file's units to SI on
reading (:func:`pounding.units.acceleration_factor`):

* :mod:`~pounding.ground_motion.readers.at2` -- PEER strong-motion ``.AT2`` files
  (:func:`read_at2`, every header variant in common use);
* :mod:`~pounding.ground_motion.readers.text` -- plain one-column (with ``dt``) or
  two-column time/acceleration text (:func:`read_text`);
* :mod:`~pounding.ground_motion.readers.dispatch` -- :func:`read_record`, any of the
  above, chosen by suffix and content.

What the formats share: :mod:`~pounding.ground_motion.readers.files` (opening the file and
splitting its lines), :mod:`~pounding.ground_motion.readers.numbers` (the numbers on a data
line) and :mod:`~pounding.ground_motion.readers.units` (the unit a header states).
Every reader raises :class:`ValueError` naming the file, the line and the bad value.
"""

from pounding.ground_motion.readers.at2 import read_at2
from pounding.ground_motion.readers.dispatch import FORMATS, RecordFormat, read_record
from pounding.ground_motion.readers.units import ASSUMED
from pounding.ground_motion.readers.text import read_text

__all__ = ["ASSUMED", "FORMATS", "RecordFormat", "read_at2", "read_record", "read_text"]

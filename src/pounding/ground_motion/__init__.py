"""Ground motions: acceleration records, their readers and synthetic inputs.

A :class:`GroundMotion` is a uniformly sampled horizontal ground acceleration in m/s² whose
first sample is at ``t = 0``. It is built by a reader, which converts the file's units to SI
on reading (:func:`pounding.units.acceleration_factor`), or by a synthetic generator. One
concept a module:

* :mod:`~pounding.ground_motion.motion` -- :class:`GroundMotion`: peaks, velocity and
  displacement, scaled and trimmed copies;
* :mod:`~pounding.ground_motion.components` -- :class:`GroundMotionComponents`: G records
  of one step applied together along the columns of a model's influence matrix (two
  horizontal components of a record, say);
* :mod:`~pounding.ground_motion.readers` -- the file readers, one module a format:
  :func:`read_at2` (PEER strong-motion ``.AT2`` files, every header variant in common use),
  :func:`read_knet` (NIED's K-NET and KiK-net ASCII files), :func:`read_cosmos` (COSMOS
  Volume 1 and 2 files), :func:`read_text` (plain one-column, with ``dt``, two-column
  time/acceleration, or several-column text read for its ``column``, which states no unit:
  ``units`` is required) and
  :func:`read_record` (any of the above, chosen by suffix and content; any other file is
  refused in one line naming it, its size and the formats read);
* :mod:`~pounding.ground_motion.bundled` -- :func:`el_centro`, :func:`load_bundled`,
  :func:`bundled_files`, :func:`bundled_records`, :func:`bundled_companion`: the twelve
  records shipped in ``pounding/data/records``, nine of them the bundled suite (nine
  stations, eight earthquakes), a second digitisation of El Centro N–S kept out of it, and
  two a pair of orthogonal horizontal components of one station (see its ``SOURCES.md`` for
  their provenance);
* :mod:`~pounding.ground_motion.suite` -- :class:`RecordSuite`, an ordered, named
  collection of records (from a folder, a list of files or :func:`bundled_suite`), and
  :func:`read_suite`;
* :mod:`~pounding.ground_motion.synthetic` -- :func:`harmonic`, :func:`sine_pulse`,
  :func:`ricker`: closed-form inputs for tests;
* :mod:`~pounding.ground_motion.stochastic` -- the stochastic model of Rezaeian & Der
  Kiureghian (2008) simulated from its six parameters, and
  :mod:`~pounding.ground_motion.rezaeian2010` -- their predictive equations (2010) from
  magnitude, distance, Vs30 and mechanism, and seeded suites (``docs/records.md``);
* :mod:`~pounding.ground_motion.ba08` -- the median of Boore & Atkinson's (2008) NGA
  ground-motion model, the yardstick of the stochastic suites' spectra.

The last three are not imported here (they import SciPy and numba when used).

Every reader raises :class:`ValueError` naming the file, the line and the problem, never
showing the file's text (a file given as a record may be anything). See
``docs/ground_motion.md``.
"""

from pounding.ground_motion.bundled import (
    bundled_companion,
    bundled_files,
    bundled_records,
    el_centro,
    load_bundled,
)
from pounding.ground_motion.components import GroundMotionComponents
from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.readers import (  # noqa: F401
    ASSUMED,
    read_at2,
    read_cosmos,
    read_knet,
    read_record,
    read_text,
)
from pounding.ground_motion.suite import RecordSuite, bundled_suite, read_suite
from pounding.ground_motion.synthetic import harmonic, ricker, sine_pulse

__all__ = [
    "GroundMotion",
    "GroundMotionComponents",
    "RecordSuite",
    "bundled_companion",
    "bundled_files",
    "bundled_records",
    "bundled_suite",
    "el_centro",
    "harmonic",
    "load_bundled",
    "read_at2",
    "read_cosmos",
    "read_knet",
    "read_record",
    "read_suite",
    "read_text",
    "ricker",
    "sine_pulse",
]

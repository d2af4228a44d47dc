"""The foundations every output shares: files written loss-free, and the output folders.

* :mod:`pounding.io.files` — atomic writes (a temporary name beside the target, moved into
  place when complete; :class:`~pounding.io.files.WriteFailed` otherwise), reading TOML,
  the checks of an output path and of a label;
* :mod:`pounding.io.manifest` — what pounding wrote in a folder, and so may replace or
  remove (``.pounding-manifest.jsonl``);
* :mod:`pounding.io.output_folder` — a run's or a study's folder: the default name, built in
  a temporary folder and published whole, stale leftovers of a killed process removed.

Import the module you need (``from pounding.io.files import write_text``); the package
itself imports nothing, and none of its modules imports NumPy.
"""

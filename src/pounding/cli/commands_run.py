"""`pounding run` and `pounding demo`."""

from pounding.cli.app import app, console  # noqa: F401

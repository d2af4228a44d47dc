"""`pounding gap`."""

from pounding.cli.app import app, console  # noqa: F401

"""`pounding report`."""

from pounding.cli.app import app, console  # noqa: F401

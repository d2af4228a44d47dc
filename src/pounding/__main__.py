"""``python -m pounding``: the command line, as the ``pounding`` script runs it."""

from pounding.cli import main

main()

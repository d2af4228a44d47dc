"""The Typer application object every command module registers on.

Command modules (one per subcommand, in this package) only parse arguments, call the
public API and print; they hold no computation.
"""

from __future__ import annotations

import sys
from typing import Annotated, Any

import typer
from rich.console import Console
from typer.core import TyperCommand, TyperGroup


def _flags_without_type(command: Any, ctx: Any) -> None:
    """Show no type for an on/off flag (``--overwrite``, ``--help``): typer would print
    ``<bool>`` beside it, though a flag takes no value."""
    for param in command.get_params(ctx):
        if getattr(param, "is_flag", False) and param.metavar is None:
            param.metavar = ""


class PoundingCommand(TyperCommand):
    """A command of pounding: its ``--help`` shows no ``<bool>`` beside a flag."""

    def format_help(self, ctx: Any, formatter: Any) -> None:
        _flags_without_type(self, ctx)
        super().format_help(ctx, formatter)


class PoundingGroup(TyperGroup):
    """The ``pounding`` group: its ``--help`` shows no ``<bool>`` beside a flag."""

    def format_help(self, ctx: Any, formatter: Any) -> None:
        _flags_without_type(self, ctx)
        super().format_help(ctx, formatter)


app = typer.Typer(
    name="pounding",
    help="Seismic pounding of adjacent buildings: impact laws, restitution, time histories.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    cls=PoundingGroup,
)


def use_pounding_commands() -> None:
    """Make every command registered on :data:`app` a :class:`PoundingCommand` (called once
    the command modules are imported, :mod:`pounding.cli`)."""
    for info in app.registered_commands:
        if info.cls is None or info.cls is TyperCommand:
            info.cls = PoundingCommand


def _print_version(value: bool) -> None:
    if value:
        from pounding import __version__

        typer.echo(f"pounding {__version__}")
        raise typer.Exit()


@app.callback()
def _root(version: Annotated[bool, typer.Option(
        "--version", callback=_print_version, is_eager=True,
        help="Print the version and exit.")] = False) -> None:
    """Seismic pounding of adjacent buildings: impact laws, restitution, time histories."""
    from pounding.compiled_cache import tell_compiling_to

    tell_compiling_to(_say_compiling)


def compiling_text(seconds: float, what: str = "the solver") -> str:
    """The note while ``what`` compiles (the first run on a machine)."""
    return f"compiling {what} once (about {seconds:.0f} s; cached after) …"


def _say_compiling(what: str, seconds: float) -> None:
    """One dim line on standard error before a kernel other than the solver's compiles
    (the response spectra's, a few seconds, once a machine)."""
    from rich.text import Text

    err_console.print(Text(compiling_text(seconds, what), style="dim"))


console = Console(width=None if sys.stdout.isatty() else 160, markup=False, emoji=False,
                  highlight=False)
"""Where tables and messages go (standard output); 160 columns wide when not a terminal, so
tables written to a file or a pipe are never squeezed. It prints text literally: no rich
markup (a name with ``[bold]`` or ``[link=…]`` in it prints as typed), no emoji codes
(``:x:``), no highlighting; styles are given as :class:`rich.text.Text` styles."""

err_console = Console(stderr=True, emoji=False, highlight=False)
"""Where errors go (standard error); :func:`pounding.cli.error_line` escapes the message's
markup, and emoji codes are never replaced."""

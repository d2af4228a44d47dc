"""The page around the sections: ``templates/page.html.j2`` rendered with Jinja2.

Jinja2 is imported on the first page rendered, not with this module (the command line starts
without it). Autoescape is on and every value goes through :func:`_escape` first, so a text
from the files is escaped exactly as :func:`html.escape` does it (``&quot;``, ``&#x27;``);
what a macro wrote (markup) is left as it is. An undefined name in a template is an error.
"""

from __future__ import annotations

import datetime as _dt
import functools
import html
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pounding.report.format import PageSection, num

if TYPE_CHECKING:
    import jinja2

__all__ = ["render_page"]


def _escape(value: Any) -> Any:
    """``value`` as HTML-escaped markup, unless it is markup already (a macro's output)."""
    if hasattr(value, "__html__"):
        return value
    from markupsafe import Markup

    return Markup(html.escape(str(value), quote=True))


@functools.cache
def _environment() -> jinja2.Environment:
    """The templates of this package, loaded from the installed package (they ship in it)."""
    import jinja2

    env = jinja2.Environment(loader=jinja2.PackageLoader("pounding.report", "templates"),
                             autoescape=True, undefined=jinja2.StrictUndefined,
                             finalize=_escape, keep_trailing_newline=True)
    env.filters["num"] = num
    return env


def render_page(title: str, subtitle: str, sections: Sequence[PageSection], folder: Path) -> str:
    """The whole page: heading, a link to each section, the sections, and a footer.

    Parameters
    ----------
    title, subtitle : str
        The page's title (also its heading) and the line under it.
    sections : sequence of PageSection
        The sections in order, each with its anchor, heading and blocks.
    folder : Path
        The results folder the page describes (named in the footer).

    Returns
    -------
    str
        The HTML text of the page.
    """
    from pounding import __version__

    stamp = _dt.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z")
    return _environment().get_template("page.html.j2").render(
        title=title, subtitle=subtitle, sections=sections, version=__version__, stamp=stamp,
        folder=str(folder.resolve()))

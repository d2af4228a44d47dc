"""The options of more than one command, declared once, and the choices of every option
that takes one of a few names.

An option means the same in every command that has it: the first sentence of its help
says what it is (the same words everywhere: ``tests/test_cli_conventions.py`` checks it);
a command may add a sentence of its own (its default, what it draws). Names of what an
option takes are shown in ``--help`` (``<heatmap|lines>``, ``FILE``, ``DIR``), never a
bare ``<str>``.

Conventions:

* ``--out DIR`` is an output folder; a single file written is named by its kind:
  ``--plot FILE`` (a figure), ``--csv FILE`` (a table), ``--html FILE`` (a report page).
* ``--design FILE`` is a design spectrum (``pounding gap``, ``spectrum``, ``suite``).
* ``--law LAW`` is a contact law, ``--e LIST`` coefficients of restitution
  (comma-separated; one value or several), ``--damping LIST`` damping ratios.
* ``--workers N`` / ``--scheduler ADDRESS``: where the many runs of ``sweep``,
  ``fragility``, ``mitigate`` and ``gap`` go (:func:`pounding.studies.sweep.run_sweep`,
  :func:`pounding.studies.sweep.tasks.run_tasks`).
* ``--dt`` and ``--units`` complete record files that do not give their step or unit.

This module imports only typer (``pounding --help`` starts at once): the names of the
choices are written here, and a test checks them against the library's.
"""

from __future__ import annotations

from enum import StrEnum
from pathlib import Path
from typing import Annotated

import typer

__all__ = ["Code", "Formula", "Histories", "Law", "Method", "PlotKind", "Reduce", "Units",
           "escape", "split_floats"]


def escape(text: str) -> str:
    """Help text as written: ``[s]``, ``[record]`` are not rich markup (typer reads help
    as rich markup, which would drop them)."""
    return text.replace("[", "\\[")


def split_floats(text: str | None, option: str) -> list[float] | None:
    """The numbers of a comma-separated list (``0.3,0.5,0.7``); None for None.

    Raises
    ------
    ValueError
        One line naming the option and the text, if an item is not a number or the list
        is empty.
    """
    if text is None:
        return None
    items = [x.strip() for x in text.split(",") if x.strip()]
    try:
        values = [float(x) for x in items]
    except ValueError:
        raise ValueError(f"{option}: expected comma-separated numbers (got {text!r})") from None
    if not values:
        raise ValueError(f"{option}: expected comma-separated numbers (got {text!r})")
    return values


# ============================================================================ choices


class Law(StrEnum):
    """Contact laws (:data:`pounding.contact.factory.LAW_NAMES`)."""

    linear_spring = "linear-spring"
    kelvin_voigt = "kelvin-voigt"
    modified_kelvin_voigt = "modified-kelvin-voigt"
    hertz = "hertz"
    hunt_crossley = "hunt-crossley"
    hertzdamp = "hertzdamp"
    nonlinear_viscoelastic = "nonlinear-viscoelastic"
    naderpour = "naderpour"
    bilinear_impact = "bilinear-impact"


class Formula(StrEnum):
    """Damping formulas for e: ``exact`` (the law's own), the published ones and the exact
    inverses (:data:`pounding.contact.restitution.FORMULAS`), and the bilinear element's
    (:data:`pounding.contact.bilinear.BILINEAR_FORMULAS`)."""

    exact = "exact"
    anagnostopoulos = "anagnostopoulos"
    schwager_poschel = "schwager-poschel"
    jankowski = "jankowski"
    mahmoud = "mahmoud"
    naderpour = "naderpour"
    hunt_crossley = "hunt-crossley"
    lankarani_nikravesh = "lankarani-nikravesh"
    flores = "flores"
    gonthier = "gonthier"
    exact_modified_kelvin_voigt = "exact-modified-kelvin-voigt"
    exact_hunt_crossley = "exact-hunt-crossley"
    exact_nonlinear_viscoelastic = "exact-nonlinear-viscoelastic"
    exact_bilinear = "exact-bilinear"
    muthukumar = "muthukumar"


class Units(StrEnum):
    """Acceleration units of a record file (:data:`pounding.units.ACCELERATION_UNITS`, one
    spelling each)."""

    g = "g"
    m_s2 = "m/s2"
    cm_s2 = "cm/s2"
    gal = "gal"
    mm_s2 = "mm/s2"
    in_s2 = "in/s2"
    ft_s2 = "ft/s2"


class Histories(StrEnum):
    """How a sweep writes each case's time histories."""

    netcdf = "netcdf"
    zarr = "zarr"
    none = "none"


class PlotKind(StrEnum):
    """A sweep figure over two parameters."""

    heatmap = "heatmap"
    lines = "lines"


class Reduce(StrEnum):
    """How cases with equal parameters on the axes are combined."""

    mean = "mean"
    max = "max"
    min = "min"
    median = "median"


class Method(StrEnum):
    """How a suite is scaled (:func:`pounding.spectra.scaling.scale_suite`)."""

    code = "code"
    sa = "sa"
    pga = "pga"
    lsq = "lsq"


class Code(StrEnum):
    """The seismic codes, by standard and edition: ``--code`` of ``code-check`` (its
    separation rule) and ``suite`` (its rule for scaling a suite), one spelling for both
    (:data:`pounding.studies.codes.CODES`; ``asce7``/``ec8`` before issue 29)."""

    asce7_22 = "asce7-22"
    en1998_1 = "en1998-1"
    nzs1170_5 = "nzs1170.5"
    nbcc2020 = "nbcc2020"
    is1893 = "is1893"


CODE_HELP = "The seismic code, by standard and edition (docs/codes.md)."
"""The meaning of ``--code`` (first sentence of its help)."""

RENAMED_CODES: dict[str, str] = {"asce7": "asce7-22", "ec8": "en1998-1"}
"""``--code`` values before issue 29, and the value now
(:data:`pounding.spectra.scaling.RENAMED_CODES`)."""


def _refuse_renamed_code(token: str) -> str:
    """A choice as typed, unless it is a renamed code: then one line naming the new value
    (click calls it on option names and choices, not on arguments)."""
    if token in RENAMED_CODES:
        raise ValueError(f"{token!r} is now spelled {RENAMED_CODES[token]!r}")
    return token


CODE_CONTEXT = {"token_normalize_func": _refuse_renamed_code}
"""``context_settings`` of the commands with ``--code``: ``--code ec8`` is refused naming
``en1998-1``."""


# ============================================================================ output
CODE_CHECK_HELP = "A folder written by `pounding code-check --out`."
"""The meaning of ``--code-check`` (first sentence of its help)."""

CodeCheckDir = Annotated[Path | None, typer.Option(
    "--code-check", metavar="DIR", help=f"{CODE_CHECK_HELP} Its check is kept in the output "
    "folder (code_check.json), and the report (pounding report) shows it as its Code check "
    "section.", show_default=False)]
"""``--code-check DIR`` of ``run``, ``sweep``, ``fragility`` (issue 29)."""

OUT_HELP = "Output folder."
"""The meaning of ``--out`` (first sentence of its help)."""

OUT_RULE = escape("Default: `out` of the input file if it names one (relative to the file), "
                  "else INPUT-STEM-results in the current folder.")
"""Where every command that reads an input file writes without ``--out``
(:func:`pounding.io.output_folder.default_out_dir`)."""

Out = Annotated[Path | None, typer.Option(
    "--out", "-o", metavar="DIR", help=f"{OUT_HELP} {OUT_RULE}", show_default=False)]
"""``--out DIR`` of ``run``, ``sweep``, ``fragility``, ``mitigate``."""

DemoOut = Annotated[Path, typer.Option(
    "--out", "-o", metavar="DIR", help=f"{OUT_HELP} Default: pounding-demo in the current "
                                       "folder.", show_default=False)]
"""``--out DIR`` of ``demo`` (which reads no input file of the user's)."""

OVERWRITE_HELP = "Replace an earlier output."
"""The meaning of ``--overwrite`` (first sentence of its help)."""

_FOLDER_OVERWRITE = (" Only an empty output folder, or one holding nothing but the files of "
                     "its manifest (pounding's, unchanged), is replaced")

Overwrite = Annotated[bool, typer.Option(
    "--overwrite", help=OVERWRITE_HELP + _FOLDER_OVERWRITE + ", file by file once the new "
                        "output is complete.")]
"""``--overwrite`` of ``run`` and ``mitigate``."""

OverwriteStudy = Annotated[bool, typer.Option(
    "--overwrite", help=OVERWRITE_HELP + _FOLDER_OVERWRITE + ": the runs saved there are "
                        "discarded and the study starts afresh (without it, it resumes).")]
"""``--overwrite`` of ``sweep`` and ``fragility`` (resumable)."""

OverwriteDemo = Annotated[bool, typer.Option(
    "--overwrite/--no-overwrite", help=OVERWRITE_HELP + _FOLDER_OVERWRITE + ". Default: yes, "
                                       "so the demo can be run again.", show_default=False)]
"""``--overwrite`` of ``demo``."""

OverwriteCopy = Annotated[bool, typer.Option(
    "--overwrite", help=OVERWRITE_HELP + " With --copy: the files of the same names in "
                                         "DIR.")]
"""``--overwrite`` of ``examples``."""

FIGURES_HELP = "Draw the figures (PNG) into the output folder."
"""The meaning of ``--figures`` (first sentence of its help)."""

Figures = Annotated[bool | None, typer.Option(
    "--figures/--no-figures", help=FIGURES_HELP + escape(
        " Default: [output] figures of the model file, else yes."), show_default=False)]
"""``--figures`` of ``run`` and ``demo``."""

FiguresStudy = Annotated[bool | None, typer.Option(
    "--figures/--no-figures", help=FIGURES_HELP + " Default: yes.", show_default=False)]
"""``--figures`` of ``fragility`` and ``mitigate``."""

FiguresSweep = Annotated[bool | None, typer.Option(
    "--figures/--no-figures", help=FIGURES_HELP + " A sweep: peak_contact_force_N against "
    "the first swept parameter, as `pounding plot` draws it. Default: no.",
    show_default=False)]
"""``--figures`` of ``sweep``."""

PLOT_HELP = "Draw the figure to FILE (.png, .svg or .pdf, by its suffix)."
"""The meaning of ``--plot`` (first sentence of its help)."""

CSV_HELP = "Write the table to FILE (CSV: one header row, units in the column names)."
"""The meaning of ``--csv`` (first sentence of its help)."""


# ============================================================================ where runs go
WORKERS_HELP = "Run on a local Dask cluster of N worker processes."
"""The meaning of ``--workers`` (first sentence of its help)."""

SCHEDULER_HELP = ("Run on the Dask scheduler at ADDRESS (tcp://host:8786), or in this "
                  "process with 'synchronous'.")
"""The meaning of ``--scheduler`` (first sentence of its help)."""

Workers = Annotated[int | None, typer.Option(
    "--workers", "-j", min=1, metavar="N", help=WORKERS_HELP + " Default: the CPU count.",
    show_default=False)]
"""``--workers`` of ``sweep``."""

WorkersStudy = Annotated[int | None, typer.Option(
    "--workers", "-j", min=1, metavar="N", help=WORKERS_HELP + " Default: run.workers of the "
    "study file, else the CPU count.", show_default=False)]
"""``--workers`` of ``fragility``."""

WorkersFew = Annotated[int | None, typer.Option(
    "--workers", "-j", min=1, metavar="N", help=WORKERS_HELP + " Default: the runs go one "
    "after another in this process (quicker than starting a cluster for a few dozen).",
    show_default=False)]
"""``--workers`` of ``mitigate`` and ``gap``."""

Scheduler = Annotated[str | None, typer.Option(
    "--scheduler", metavar="ADDRESS", help=SCHEDULER_HELP + " Default: a local cluster "
    "(--workers).", show_default=False)]
"""``--scheduler`` of ``sweep``."""

SchedulerStudy = Annotated[str | None, typer.Option(
    "--scheduler", metavar="ADDRESS", help=SCHEDULER_HELP + " Default: run.scheduler of the "
    "study file, else a local cluster (--workers).", show_default=False)]
"""``--scheduler`` of ``fragility``."""

SchedulerFew = Annotated[str | None, typer.Option(
    "--scheduler", metavar="ADDRESS", help=SCHEDULER_HELP + " Default: this process, or a "
    "local cluster with --workers.", show_default=False)]
"""``--scheduler`` of ``mitigate`` and ``gap``."""


# ============================================================================ records
Dt = Annotated[float | None, typer.Option(
    "--dt", metavar="SECONDS", help=escape("Time step [s] of record files that do not give "
                                           "one."), show_default=False)]
"""``--dt`` of every command that reads record files."""

RecordUnits = Annotated[Units | None, typer.Option(
    "--units", metavar="UNIT", case_sensitive=False, help="Acceleration unit of record files "
    "that do not state one: " + ", ".join(u.value for u in Units) + "; required for text "
    "files, which state none. An AT2 file stating another is refused.", show_default=False)]
"""``--units`` of every command that reads record files."""

Column = Annotated[int | None, typer.Option(
    "--column", min=1, help="Text record files of several columns (t, NS, EW, V): the "
    "acceleration's column, from 1.", show_default=False)]
"""``--column`` of every command that reads record files."""

TimeColumn = Annotated[int | None, typer.Option(
    "--time-column", min=0, help="Text record files: the time's column, from 1; 0 for none "
    "(then give --dt). Default: 1 with --column 2 or more.", show_default=False)]
"""``--time-column`` of every command that reads record files."""

Channel = Annotated[int | None, typer.Option(
    "--channel", min=1, help="COSMOS record files of several channels: the acceleration "
    "channel to read, from 1.", show_default=False)]
"""``--channel`` of every command that reads record files."""

DESIGN_HELP = escape("Design spectrum FILE: TOML (asce7 = {sds, sd1, tl}; eurocode8 = {agr, "
                     "ground_type, type, importance, damping}; or a table: kind, units, "
                     "periods, values) or CSV (period_s and sa_g, sa_m_s2 or sd_m); see "
                     "docs/spectra.md.")
"""The meaning of ``--design`` (first sentence of its help)."""

DAMPING_HELP = escape("Damping ratios of the response spectra, fractions of critical in "
                      "[0, 1), comma-separated (0.05,0.02).")
"""The meaning of ``--damping`` (first sentence of its help)."""


# ============================================================================ contact
LAW_HELP = "Contact law."
"""The meaning of ``--law`` (first sentence of its help)."""

E_HELP = "Coefficients of restitution e, comma-separated (0.3,0.5,0.7)."
"""The meaning of ``--e`` (first sentence of its help)."""

ETable = Annotated[str | None, typer.Option(
    "--e", metavar="LIST", help=E_HELP + " Default: the seed's Table 1, 0.1 … 0.9.",
    show_default=False)]
"""``--e`` of ``zeta`` and ``audit``."""

Mass1 = Annotated[float, typer.Option("--m1", metavar="KG", help=escape(
    "Mass of body 1 [kg]."))]
Mass2 = Annotated[float, typer.Option("--m2", metavar="KG", help=escape(
    "Mass of body 2 [kg]."))]
ImpactVelocity = Annotated[float, typer.Option("--v0", metavar="M/S", help=escape(
    "Impact velocity [m/s]."))]
HertzStiffness = Annotated[float, typer.Option("--k-h", metavar="N/M^1.5", help=escape(
    "Hertz stiffness k_h [N/m^1.5] of the nonlinear laws."))]

K_HELP = escape("Linear stiffness k [N/m].")
"""The meaning of ``--k`` (first sentence of its help)."""

LinearStiffness = Annotated[float, typer.Option("--k", metavar="N/M", help=K_HELP + (
    " Of the linear laws: linear-spring, kelvin-voigt, modified-kelvin-voigt."))]
"""``--k`` of the impact commands."""

Tension = Annotated[bool, typer.Option(
    "--tension/--no-tension",
    help="Kelvin-Voigt: may the dashpot pull before separation. Model-file key tension; "
         "default no: the force is clipped at zero, as buildings cannot pull each other; "
         "--tension is OpenSees' ViscoelasticGap.", show_default=False)]
"""``--tension`` of ``collide`` and ``calibrate``."""

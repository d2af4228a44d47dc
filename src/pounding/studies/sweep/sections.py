"""The sweep file's keys and tables, validated as model and study files are.

Each table is a :class:`~pounding.config.base.Section` (no unknown keys, no strings for
numbers, no NaN or infinity), and a bad file is one line per problem naming the key path
and the value (:func:`~pounding.config.errors.format_validation_error`)::

    sweep.toml: batch_size: must be >= 1 (got 0)
    sweep.toml: random.seed: must be >= 0 (got -1)
    sweep.toml: grid.contact.gap: must hold at least 1 value(s) (got 0: [])
    sweep.toml: random.contact.e.unifrom: unknown key (got [0.5, 0.9]); did you mean 'uniform'? ...

What depends on the base model — that a parameter path names a key of a model file, that a
value has the type that key needs — is checked by :mod:`~pounding.studies.sweep.checks`, with
each case's own model validation.

(No ``from __future__ import annotations`` here: the tables have keys called ``list`` and
``int``, and their annotations are read where they stand.)
"""

import difflib
import math
from typing import Annotated, Any, Literal, NamedTuple

from pydantic import AfterValidator, ConfigDict, Field, model_validator

from pounding.config.base import Section, field_error, fmt

__all__ = ["CASE_TABLES", "Draw", "RandomTable", "SweepFile"]

CASE_TABLES = ("grid", "list", "random")
"""The tables that give a sweep's cases: exactly one of them (as
``pounding.config.SWEEP_CASE_TABLES``, by which a model file is told from a sweep file)."""


def _finite(value: Any) -> bool:
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, dict):
        return all(_finite(v) for v in value.values())
    if isinstance(value, list):
        return all(_finite(v) for v in value)
    return True


def _finite_values(values: list[Any]) -> list[Any]:
    """Every value (and every number inside a table or list value) finite."""
    for v in values:
        if not _finite(v):
            raise ValueError(f"values must be finite (got {fmt(v)})")
    return values


Values = Annotated[list[Any], Field(min_length=1), AfterValidator(_finite_values)]
"""A parameter's values: a non-empty list of values of the model-file key it names."""


def _some_parameter(table: dict[str, Any]) -> dict[str, Any]:
    if not table:
        raise ValueError('give at least one parameter, e.g. "contact.gap" = [0.01, 0.02]')
    return table


CaseValues = Annotated[dict[str, Values], AfterValidator(_some_parameter)]
"""``[grid]`` or ``[list]``: each key a parameter (a dotted path into the model file), each
value its list of values."""


DISTRIBUTIONS = ("uniform", "log", "int", "choice")
"""The distributions of a ``[random]`` parameter."""


class Draw(NamedTuple):
    """A parameter of ``[random]``: how its values are drawn (``uniform``, ``log``, ``int``
    or ``choice``) and from what (``[low, high]``, or the values to choose from)."""

    kind: str
    argument: list[Any]


def _is_number(x: Any) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def _draw(spec: Any) -> Draw:
    """A ``[random]`` parameter's distribution: ``[low, high]`` (uniform), or one of
    ``{ uniform = [low, high] }``, ``{ log = [low, high] }`` (log-uniform, low > 0),
    ``{ int = [low, high] }`` (integers, both ends included), ``{ choice = [...] }``."""
    if isinstance(spec, list):
        spec = {"uniform": spec}
    if not isinstance(spec, dict):
        raise ValueError("give [low, high] (uniform) or one of { uniform = [a, b] }, "
                         "{ log = [a, b] }, { int = [a, b] }, { choice = [...] } "
                         f"(got {fmt(spec)})")
    unknown = [k for k in spec if k not in DISTRIBUTIONS]
    if unknown:
        close = difflib.get_close_matches(unknown[0], DISTRIBUTIONS, n=1, cutoff=0.7)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        raise field_error(unknown[0], f"unknown distribution (got {fmt(spec[unknown[0]])})"
                                      f"{hint} (distributions: {', '.join(DISTRIBUTIONS)})")
    if len(spec) != 1:
        raise ValueError(f"give one distribution: {', '.join(DISTRIBUTIONS)} (got "
                         f"{', '.join(spec) or 'none'})")
    (kind, arg), = spec.items()
    if kind == "choice":
        if not isinstance(arg, list) or not arg:
            raise field_error(kind, f"must be a non-empty list of values (got {fmt(arg)})")
        _finite_values(arg)
        return Draw(kind, arg)
    integers = kind == "int"
    ok = (isinstance(arg, list) and len(arg) == 2
          and all((isinstance(x, int) and not isinstance(x, bool)) if integers
                  else _is_number(x) for x in arg))
    if not ok or not arg[0] < arg[1]:
        raise field_error(kind, f"must be [low, high], two {'integers' if integers else 'numbers'}"
                                f" with low < high (got {fmt(arg)})")
    if kind == "log" and not arg[0] > 0:
        raise field_error(kind, f"needs low > 0 (got {fmt(arg)})")
    return Draw(kind, list(arg))


Distribution = Annotated[Any, AfterValidator(_draw)]
"""A parameter of ``[random]`` and its distribution (:func:`_draw`), as a :class:`Draw`."""


class RandomTable(Section):
    """``[random]``: ``n`` samples drawn with ``seed`` (NumPy's PCG64); every other key is
    a parameter and its :class:`Distribution`."""

    model_config = ConfigDict(extra="allow", strict=True, allow_inf_nan=False, frozen=True)
    __pydantic_extra__: dict[str, Distribution]

    n: Annotated[int, Field(ge=1)]
    seed: Annotated[int, Field(ge=0)]

    @model_validator(mode="after")
    def _some_parameter(self) -> "RandomTable":
        if not self.parameters:
            raise ValueError('give at least one parameter, e.g. "contact.gap" = [0.0, 0.05]')
        return self

    @property
    def parameters(self) -> dict[str, Draw]:
        """Each parameter (a dotted path into the model file) and its distribution."""
        return dict(self.__pydantic_extra__ or {})


def _folder_name(text: str) -> str:
    if "\0" in text:
        raise ValueError(f"a folder name (got {text!r})")
    return text


def _model(base: Any) -> str | dict[str, Any]:
    if isinstance(base, str) and base or isinstance(base, dict):
        return base
    raise ValueError('the model file (base = "model.toml", relative to the sweep file) or an '
                     f"inline [base] table (got {fmt(base)})")


class SweepFile(Section):
    """A whole sweep file (``docs/sweep.md``): its ``name``, the ``base`` model (a model
    file, relative to the sweep file, or an inline ``[base]`` table), the output folder
    ``out``, ``histories`` and ``batch_size``, and exactly one table of cases."""

    name: str = "sweep"
    base: Annotated[Any, AfterValidator(_model)]
    out: Annotated[str, Field(min_length=1), AfterValidator(_folder_name)] | None = None
    histories: Literal[False, "netcdf", "zarr", "none"] = False
    batch_size: Annotated[int, Field(ge=1)] | None = None
    grid: CaseValues | None = None
    random: RandomTable | None = None
    list: CaseValues | None = None

    @model_validator(mode="after")
    def _one_table(self) -> "SweepFile":
        given = [k for k in CASE_TABLES if getattr(self, k) is not None]
        if len(given) != 1:
            raise field_error(given[1] if given else "grid", "give exactly one of [grid], "
                              f"[list] and [random] (got {', '.join(given) or 'none'})")
        return self

    @property
    def kind(self) -> str:
        """The table of cases: ``grid``, ``list`` or ``random``."""
        return next(k for k in CASE_TABLES if getattr(self, k) is not None)

    @property
    def history_format(self) -> str | None:
        """``netcdf``, ``zarr``, or None (no histories)."""
        return None if self.histories in (False, "none") else str(self.histories)

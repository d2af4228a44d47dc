"""What every section of a model file shares: strict validation, errors located at a key,
and errors of the library re-raised with the path of the section at fault."""

from __future__ import annotations

import re
from typing import Annotated, Any

from pydantic import BaseModel, ConfigDict, Field, ValidationError
from pydantic_core import PydanticCustomError

Pos = Annotated[float, Field(gt=0)]
NonNeg = Annotated[float, Field(ge=0)]
Ratio = Annotated[float, Field(ge=0, le=1)]


class Section(BaseModel):
    """A table of a model file. Strict: no unknown keys, no strings for numbers, no
    inf/nan."""

    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)


def field_error(field: str | tuple[str | int, ...], message: str) -> PydanticCustomError:
    """An error about ``field`` of the section being validated (located by the formatter,
    :func:`pounding.config.errors.format_validation_error`)."""
    return PydanticCustomError("config_field", "{message}",
                               {"field": field, "message": message})


def check_bouc_wen_shape(beta: float | None, gamma: float | None) -> None:
    """Refuse Bouc–Wen shape constants with ``beta + gamma <= 0`` (defaults 0.5 each), under
    which the hysteretic variable grows without bound; the error names the key given."""
    b = 0.5 if beta is None else beta
    g = 0.5 if gamma is None else gamma
    if not b + g > 0.0:
        raise field_error("gamma" if gamma is not None else "beta",
                          f"beta + gamma must be > 0, or the hysteretic variable grows "
                          f"without bound (got beta = {fmt(b)}, gamma = {fmt(g)})")


def fmt(value: Any) -> str:
    """A value as an error message quotes it (numbers short, true/false and a table as the
    file writes them, long texts cut)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return f"{value:g}"
    text = _inline(value) if isinstance(value, BaseModel) else repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


def _inline(section: BaseModel) -> str:
    """A section as a TOML inline table of the keys it was given (``{ type = "bilinear",
    yield_force = 2e+06 }``), not the repr of its class."""
    def value(v: Any) -> str:
        if isinstance(v, BaseModel):
            return _inline(v)
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, str):
            return '"' + v + '"'
        if isinstance(v, list):
            return "[" + ", ".join(value(x) for x in v) + "]"
        return fmt(v)

    keys = [k for k in type(section).model_fields if k in section.model_fields_set]
    return "{ " + ", ".join(f"{k} = {value(getattr(section, k))}" for k in keys) + " }"


class prefixed:
    """Context manager: re-raise a ValueError as ``ValueError("<where>: <message>")``, or
    as ``"<where>.<message>"`` when the message starts with one of ``keys`` (the keys of
    the section at ``where``): ``building[0]`` and ``storey_law: …`` make
    ``building[0].storey_law: …``, one key path."""

    def __init__(self, where: str, keys: Any = ()) -> None:
        self.where = where
        self.keys = frozenset(keys)

    def __enter__(self) -> None:
        return None

    def __exit__(self, typ: type | None, exc: BaseException | None, tb: Any) -> None:
        if isinstance(exc, ValueError) and not isinstance(exc, ValidationError):
            text = str(exc)
            found = _KEY_PATH.match(text)
            sep = "." if found and found[1] in self.keys else ": "
            raise ValueError(f"{self.where}{sep}{text}") from exc


_KEY_PATH = re.compile(r"([A-Za-z_]\w*)(\[\d+\])*(\.[A-Za-z_]\w*(\[\d+\])*)*: ")
"""A message that starts with a key path (``storey_law: …``, ``elements[2].x: …``)."""

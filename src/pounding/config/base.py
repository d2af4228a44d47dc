"""What every section of a model file shares: strict validation, errors located at a key,
and errors of the library re-raised with the path of the section at fault."""

from __future__ import annotations

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


def fmt(value: Any) -> str:
    """A value as an error message quotes it (numbers short, long texts cut)."""
    if isinstance(value, float):
        return f"{value:g}"
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


class prefixed:
    """Context manager: re-raise a ValueError as ``ValueError("<where>: <message>")``."""

    def __init__(self, where: str) -> None:
        self.where = where

    def __enter__(self) -> None:
        return None

    def __exit__(self, typ: type | None, exc: BaseException | None, tb: Any) -> bool:
        if isinstance(exc, ValueError) and not isinstance(exc, ValidationError):
            raise ValueError(f"{self.where}: {exc}") from exc
        return False

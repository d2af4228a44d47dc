"""Validation errors as one line per problem: ``<key path>: <problem> (got <value>)``."""

from __future__ import annotations

import difflib
import types
import typing
from typing import Any

from pydantic import BaseModel, ValidationError

from pounding.config.base import fmt

_TYPE_WORDS = {
    "float_type": "must be a number",
    "float_parsing": "must be a number",
    "int_type": "must be an integer",
    "int_from_float": "must be an integer",
    "int_parsing": "must be an integer",
    "string_type": "must be a string (in quotes)",
    "bool_type": "must be true or false",
    "list_type": "must be a list [ ... ]",
    "model_type": "must be a table",
    "dict_type": "must be a table",
    "finite_number": "must be a finite number",
    "missing": "required",
}


def _loc_text(loc: tuple[Any, ...]) -> str:
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += ("." if out else "") + str(part)
    return out


def _section_model(loc: tuple[Any, ...], root: type[BaseModel] | None = None
                   ) -> type[BaseModel] | None:
    """The pydantic model class at ``loc`` inside ``root`` (default :class:`RunConfig`),
    for key suggestions."""
    from pounding.config.run import RunConfig

    model: Any = RunConfig if root is None else root
    for part in loc:
        if isinstance(part, int):
            continue
        if not (isinstance(model, type) and issubclass(model, BaseModel)):
            return None
        field = model.model_fields.get(part)
        if field is None:
            return None
        model = _inner_model(field.annotation)
    return model if isinstance(model, type) and issubclass(model, BaseModel) else None


def _inner_model(tp: Any) -> Any:
    """Unwrap ``X | None``, ``list[X]``, ``Annotated[X, ...]`` down to a model class."""
    for _ in range(6):
        if isinstance(tp, type) and issubclass(tp, BaseModel):
            return tp
        origin = typing.get_origin(tp)
        args = [a for a in typing.get_args(tp) if a is not type(None)]
        if origin in (typing.Union, types.UnionType, list, typing.Annotated) and args:
            tp = args[0]
        else:
            return None
    return None


def _one_error(err: dict[str, Any], root: type[BaseModel] | None = None) -> str:
    loc = tuple(err.get("loc", ()))
    typ = err.get("type", "")
    ctx = err.get("ctx") or {}
    inp = err.get("input")
    if typ == "config_field":
        field = ctx["field"]
        loc = loc + (tuple(field) if isinstance(field, (tuple, list)) else (field,))
        return f"{_loc_text(loc)}: {ctx['message']}"
    where = _loc_text(loc) or "(top level)"
    if typ == "value_error":
        msg = str(err.get("msg", "")).removeprefix("Value error, ")
        return f"{where}: {msg}"
    if typ == "extra_forbidden":
        key = str(loc[-1]) if loc else "?"
        model = _section_model(loc[:-1], root)
        allowed = sorted(model.model_fields) if model is not None else []
        close = difflib.get_close_matches(key, allowed, n=1)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        keys = f" (keys here: {', '.join(allowed)})" if allowed else ""
        return f"{where}: unknown key (got {fmt(inp)}){hint}{keys}"
    if typ == "missing":
        return f"{where}: required"
    if typ in ("greater_than", "greater_than_equal", "less_than", "less_than_equal"):
        op = {"greater_than": ">", "greater_than_equal": ">=", "less_than": "<",
              "less_than_equal": "<="}[typ]
        bound = next(iter(ctx.values()))
        return f"{where}: must be {op} {fmt(bound)} (got {fmt(inp)})"
    if typ in ("too_short", "too_long"):
        lo = ctx.get("min_length")
        hi = ctx.get("max_length")
        want = (f"{lo} value(s)" if lo == hi else
                f"at least {lo} value(s)" if typ == "too_short" else f"at most {hi} value(s)")
        return f"{where}: must hold {want} (got {ctx.get('actual_length')}: {fmt(inp)})"
    words = _TYPE_WORDS.get(typ, str(err.get("msg", "invalid")))
    return f"{where}: {words} (got {fmt(inp)})"


def format_validation_error(exc: ValidationError, prefix: str = "",
                            root: type[BaseModel] | None = None) -> str:
    """One line per problem: ``<prefix><key path>: <problem> (got <value>)``; ``root`` is
    the file's model (default :class:`~pounding.config.RunConfig`), for the keys an unknown
    key is compared with."""
    lines = []
    for err in exc.errors(include_url=False):
        line = prefix + _one_error(dict(err), root)
        if line not in lines:
            lines.append(line)
    return "\n".join(lines)

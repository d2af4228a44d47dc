"""Checks of a sweep before anything runs: parameter paths name keys of a model file, and
the cases pass the key check."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from pounding.studies.sweep.overrides import apply_overrides

if TYPE_CHECKING:
    from pounding.studies.sweep.plan import Sweep


def _check_path(path: str, base: dict[str, Any], where: str) -> None:
    """Fail fast on a parameter path that names no key of a model file."""
    from pydantic import BaseModel

    from pounding.config import RunConfig

    model: Any = RunConfig
    node: Any = base
    parts = path.split(".")
    for i, part in enumerate(parts):
        at = ".".join(parts[: i + 1])
        if isinstance(node, list):
            if part == "*":
                node = node[0] if node else None
                continue
            if not part.isdigit() or int(part) >= len(node):
                raise ValueError(f"{where}: {path}: {at}: need an index 0 … {len(node) - 1} "
                                 "or * (every one)")
            node = node[int(part)]
            continue
        if not (isinstance(model, type) and issubclass(model, BaseModel)):
            raise ValueError(f"{where}: {path}: {'.'.join(parts[:i])} has no keys")
        fields = model.model_fields
        if part not in fields:
            import difflib
            close = difflib.get_close_matches(part, list(fields), n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            raise ValueError(f"{where}: {path}: unknown key {part!r}{hint} (keys here: "
                             f"{', '.join(sorted(fields))})")
        model = _unwrap(fields[part].annotation)
        node = node.get(part) if isinstance(node, dict) else None
        if isinstance(node, list) and i == len(parts) - 1:
            continue
        if node is None and i < len(parts) - 1 and isinstance(model, list):
            raise ValueError(f"{where}: {path}: the base model has no {at}")
        if isinstance(model, list):
            model = model[0]
            if i < len(parts) - 1 and not isinstance(node, list):
                node = [node]


def _unwrap(tp: Any) -> Any:
    """``X | None``, ``Annotated[X, ...]`` → X; ``list[X]`` → ``[X]``."""
    import types
    import typing

    for _ in range(8):
        origin = typing.get_origin(tp)
        args = [a for a in typing.get_args(tp) if a is not type(None)]
        if origin in (typing.Union, types.UnionType, typing.Annotated) and args:
            tp = args[0]
        elif origin is list and args:
            return [_unwrap(args[0])]
        else:
            return tp
    return tp


def _check_first_case(sweep: Sweep, where: str) -> None:
    """The first case must at least pass the key check (catches misspelt paths early)."""
    from pydantic import ValidationError

    from pounding.config import RunConfig, format_validation_error

    if not sweep.cases:
        raise ValueError(f"{where}: the sweep has no cases")
    data = apply_overrides(sweep.base, sweep.params, sweep.cases[0].values)
    try:
        RunConfig.model_validate(data, context={"base_dir": sweep.base_dir})
    except ValidationError as exc:
        unknown = [e for e in exc.errors(include_url=False) if e.get("type") == "extra_forbidden"]
        if unknown:
            raise ValueError(f"{where}: case 0: "
                             + format_validation_error(exc).replace("\n", "; ")) from None


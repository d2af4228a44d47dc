"""Checks of a sweep before anything runs: parameter paths name keys of a model file, every
value of every parameter has the right type, and no case is too large for memory."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from pounding.studies.sweep.cases import Case, _canon
from pounding.studies.sweep.overrides import apply_overrides


def _check_path(path: str, base: dict[str, Any], where: str, table: str = "") -> None:
    """Fail fast on a parameter path that names no key of a model file (the message names
    it under its ``table``: ``grid.contact.gapp: unknown key 'gapp'; …``)."""
    from pydantic import BaseModel

    from pounding.config import RunConfig

    named = f"{table}.{path}" if table else path

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
                raise ValueError(f"{where}: {named}: {at}: need an index 0 … {len(node) - 1} "
                                 "or * (every one)")
            node = node[int(part)]
            continue
        if not (isinstance(model, type) and issubclass(model, BaseModel)):
            raise ValueError(f"{where}: {named}: {'.'.join(parts[:i])} has no keys")
        fields = model.model_fields
        if part not in fields:
            import difflib
            close = difflib.get_close_matches(part, list(fields), n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            raise ValueError(f"{where}: {named}: unknown key {part!r}{hint} (keys here: "
                             f"{', '.join(sorted(fields))})")
        model = _unwrap(fields[part].annotation)
        node = node.get(part) if isinstance(node, dict) else None
        if isinstance(node, list) and i == len(parts) - 1:
            continue
        if node is None and i < len(parts) - 1 and isinstance(model, list):
            raise ValueError(f"{where}: {named}: the base model has no {at}")
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


def _is_type_error(err: dict[str, Any]) -> bool:
    """A validation error that no value of the right type would give: a wrong type, or a
    key the model file does not have (not a value out of range, checked per case)."""
    typ = str(err.get("type", ""))
    return typ.endswith(("_type", "_parsing")) or typ in ("int_from_float", "extra_forbidden")


def _under(loc: tuple[Any, ...], path: str) -> bool:
    """Whether a validation error at ``loc`` lies under the dotted parameter ``path``."""
    parts = path.split(".")
    if len(loc) < len(parts):
        return False
    for at, part in zip(loc, parts):
        if part == "*" or part.isdigit():
            if not isinstance(at, int) or (part.isdigit() and at != int(part)):
                return False
        elif at != part:
            return False
    return True


def _errors_text(exc: Any, errors: list[Any]) -> str:
    """The chosen errors of a ValidationError as one line (``; ``-separated)."""
    from pydantic import ValidationError
    from pydantic_core import InitErrorDetails

    from pounding.config import RunConfig, format_validation_error

    keep: list[InitErrorDetails] = []
    for e in errors:  # (the entries of ValidationError.errors(): type, loc, input, ctx)
        detail = InitErrorDetails(type=e["type"], loc=e["loc"], input=e["input"])
        if "ctx" in e:
            detail["ctx"] = e["ctx"]
        keep.append(detail)
    sub = ValidationError.from_exception_data(exc.title, keep)
    return format_validation_error(sub, root=RunConfig).replace("\n", "; ")


def _validate(base: dict[str, Any], base_dir: Path, params: Sequence[str],
              values: tuple[Any, ...]) -> tuple[Any, Any]:
    """``(config, None)`` for a case that validates, else ``(None, the ValidationError)``."""
    from pydantic import ValidationError

    from pounding.config import RunConfig

    data = apply_overrides(base, params, values)
    try:
        return RunConfig.model_validate(data, context={"base_dir": base_dir}), None
    except ValidationError as exc:
        return None, exc


def _size_key(cfg: Any) -> str:
    """What decides the memory of a run: structure (buildings or a bridge), record, output
    step and duration (not the contact law, its gaps, the record's scale, or the
    tolerances)."""
    data = cfg.model_dump(mode="json", exclude_none=True)
    contact = data.get("contact") or {}
    record = {k: v for k, v in data["record"].items() if k not in ("scale", "pga_g")}
    return _canon({"building": data["building"], "bridge": data.get("bridge"),
                   "record": record,
                   "solver": [data["solver"].get("dt"), data["solver"].get("duration")],
                   "contact": [contact.get("floor_to_column"), contact.get("level_tolerance")]})


def _check_size(cfg: Any, label: str, seen: set[str]) -> None:
    """Refuse a case whose run would not fit in memory: the check of ``pounding run``
    (:func:`pounding.integrate.check_history_size`), once per structure, record and grid."""
    from pounding.integrate import check_history_size, grid_step

    key = _size_key(cfg)
    if key in seen:
        return
    seen.add(key)
    try:
        model, motion, solver = cfg.build()
    except Exception:  # noqa: BLE001  (such a case fails when it runs, in its row)
        return
    step = grid_step(motion.dt, solver["dt"])
    t_end = motion.duration if solver["duration"] is None else solver["duration"]
    try:
        check_history_size(model, t_end, step)
    except ValueError as exc:
        raise ValueError(f"{label}: {exc}") from None


def check_cases(base: dict[str, Any], base_dir: Path, params: Sequence[str],
                cases: Sequence[Case], samples: list[list[Any]], where: str,
                kind: str) -> None:
    """Check the cases of a sweep before any runs, without making every case.

    Every value of every parameter (``samples``, see :func:`.cases.case_rows`) is put,
    alone, into the first case and validated: a value of the wrong type (``"abc"`` for a
    number) or with unknown keys refuses the sweep; and the first case must pass the key
    check (catches misspelt keys early). A value out of range is not refused here: its cases
    fail in their rows and the sweep goes on. Each such case (and the first) that builds
    must also fit in memory, as ``pounding run`` requires (checked once per structure,
    record and output grid); combinations of values are checked when they run.

    Parameters
    ----------
    base : dict
        The base model configuration as plain data (validated).
    base_dir : Path
        Where relative paths of the base model start.
    params : sequence of str
        The swept parameters (dotted paths).
    cases : sequence of Case
        The cases, in order.
    samples : list of list
        Per parameter, the values to check.
    where : str
        Prefix of error messages (the sweep file).
    kind : str
        The case table (``grid``, ``list``, ``random``), named in the messages.

    Raises
    ------
    ValueError
        One line naming the table, the parameter, the value and the problem.
    """
    from pounding.config import RunConfig, format_validation_error

    if not cases:
        raise ValueError(f"{where}: the sweep has no cases")
    first = cases[0].values
    sized: set[str] = set()
    for j, p in enumerate(params):
        done: set[str] = set()
        for v in samples[j]:
            key = _canon(v)
            if key in done:
                continue
            done.add(key)
            cfg, exc = _validate(base, base_dir, params, first[:j] + (v,) + first[j + 1:])
            label = f"{where}: {kind}.{p} = {_canon(v)}"
            if exc is not None:
                from pounding.config.errors import meant_elsewhere

                # a member of a union that the value was not meant for does not count
                # (yield_force = -1 is a number out of range, not a list of the wrong kind)
                bad = [e for e, aside in zip(exc.errors(include_url=False),
                                             meant_elsewhere(exc, RunConfig))
                       if _is_type_error(e) and not aside and _under(tuple(e["loc"]), p)]
                if bad:
                    raise ValueError(f"{label}: {_errors_text(exc, bad)}")
            else:
                _check_size(cfg, label, sized)
    _, exc = _validate(base, base_dir, params, first)  # unknown keys not under a parameter
    if exc is not None and any(e.get("type") == "extra_forbidden"
                               for e in exc.errors(include_url=False)):
        raise ValueError(f"{where}: case 0: "
                         + format_validation_error(exc, root=RunConfig).replace("\n", "; ")) from None

"""Validation errors as one line per problem: ``<key path>: <problem> (got <value>)``.

Pydantic locates an error by a path that mixes the user's keys with its own names for the
members of a union (``levels.list[constrained-float][0]``,
``levels.function-after[_order(), LevelRange].stop``, ``floors.literal['all']``), and it
reports a value that fits no member of a union once per member. Here each error's path is
walked along the file's model: the keys and indices the user wrote are kept, the member
names are dropped, and of the members of a union the one the value was meant for is
reported (the one whose problem lies deeper than "wrong kind of value"; a value of no
member's kind is one line naming every kind accepted). The range of a number out of range
is read from its field, with its unit (:mod:`pounding.config.quantities`).
"""

from __future__ import annotations

import difflib
import re
import types
import typing
from dataclasses import dataclass, field
from typing import Any, Literal

from pydantic import BaseModel, ValidationError
from pydantic.fields import FieldInfo

from pounding.config.base import fmt
from pounding.config.quantities import Unit

_TYPE_WORDS = {
    "float_type": "must be a number",
    "float_parsing": "must be a number",
    "int_type": "must be an integer",
    "int_from_float": "must be an integer",
    "int_parsing": "must be an integer",
    "string_type": "must be a string (in quotes)",
    "bool_type": "must be true or false",
    "bool_parsing": "must be true or false",
    "list_type": "must be a list [ ... ]",
    "model_type": "must be a table",
    "model_attributes_type": "must be a table",
    "dict_type": "must be a table",
    "finite_number": "must be a finite number",
    "string_too_short": "must not be empty",
    "missing": "required",
}
"""Words for the errors of a value of the wrong kind (or missing)."""

_SHAPE_ERRORS = frozenset({"float_type", "float_parsing", "int_type", "int_parsing",
                           "int_from_float", "string_type", "bool_type", "bool_parsing",
                           "list_type", "model_type", "model_attributes_type", "dict_type",
                           "literal_error", "is_instance_of", "tuple_type", "set_type"})
"""Errors that say the value is not of a member's kind (so the member was not meant)."""

_BOUND_ERRORS = {"greater_than": ">", "greater_than_equal": ">=", "less_than": "<",
                 "less_than_equal": "<="}

_SCALAR_WORDS: dict[Any, str] = {bool: "true or false", int: "an integer", float: "a number",
                                 str: "a string (in quotes)"}


# ------------------------------------------------------------------ walking a type
def _is_model(tp: Any) -> bool:
    return isinstance(tp, type) and issubclass(tp, BaseModel)


def _members(tp: Any) -> list[Any] | None:
    """The members other than None of a union type (None if ``tp`` is no union)."""
    if typing.get_origin(tp) in (typing.Union, types.UnionType):
        return [a for a in typing.get_args(tp) if a is not type(None)]
    return None


def _metadata(items: Any) -> list[Any]:
    out: list[Any] = []
    for m in items:
        out.extend(m.metadata if isinstance(m, FieldInfo) else [m])
    return out


def _strip(tp: Any) -> tuple[Any, list[Any]]:
    """``tp`` without ``Annotated`` and ``| None`` layers, and the metadata they held."""
    meta: list[Any] = []
    for _ in range(10):
        if typing.get_origin(tp) is typing.Annotated:
            args = typing.get_args(tp)
            meta += _metadata(args[1:])
            tp = args[0]
            continue
        members = _members(tp)
        if members is not None and len(members) == 1:
            tp = members[0]
            continue
        break
    return tp, meta


def _list_depth(tp: Any) -> int:
    depth = 0
    tp, _ = _strip(tp)
    while typing.get_origin(tp) is list:
        depth += 1
        tp, _ = _strip(typing.get_args(tp)[0])
    return depth


def _member_for_tag(tag: str, members: list[Any]) -> Any:
    """The member of a union that pydantic calls ``tag`` (None if not found)."""
    for m in members:
        base, _ = _strip(m)
        if _is_model(base) and re.search(rf"\b{re.escape(base.__name__)}\b", tag):
            return m
        if typing.get_origin(base) is list and tag.count("list[") == _list_depth(base):
            return m
        if typing.get_origin(base) is Literal and tag.startswith("literal["):
            return m
        if base in _SCALAR_WORDS and tag.rsplit("-", 1)[-1] == base.__name__:
            return m
    return None


_TAG_LIKE = re.compile(r"[\[\](),]|^(constrained-|strict-|lax-)?(str|int|float|bool|none)$")


@dataclass
class _Located:
    """An error's path walked along the model: the user's keys, the unions passed (where
    in the keys, which member), and the type and metadata of the field at the end."""

    parts: list[Any]
    unions: list[tuple[int, str, Any]] = field(default_factory=list)
    tp: Any = None
    meta: list[Any] = field(default_factory=list)
    table: Any = None
    """The model class of the table holding the last key (for an unknown key)."""


def _locate(loc: tuple[Any, ...], root: Any) -> _Located:
    tp, meta = _strip(root)
    out = _Located(parts=[])
    known = True
    for part in loc:
        members = _members(tp) if known else None
        if members is not None:
            member = _member_for_tag(str(part), members)
            out.unions.append((len(out.parts), str(part), member))
            if member is None:
                known = False
            else:
                tp, more = _strip(member)
                meta = meta + more
            continue
        if not known:
            if isinstance(part, str) and _TAG_LIKE.search(part):
                out.unions.append((len(out.parts), part, None))
            else:
                out.parts.append(part)
            continue
        out.parts.append(part)
        if _is_model(tp):
            out.table = tp
        if isinstance(part, int) and typing.get_origin(tp) is list:
            tp, meta = _strip(typing.get_args(tp)[0])
        elif isinstance(part, str) and _is_model(tp) and part in tp.model_fields:
            info = tp.model_fields[part]
            tp, meta = _strip(info.annotation)
            meta = _metadata([info]) + meta
        else:
            known = False
    out.tp, out.meta = (tp, meta) if known else (None, [])
    return out


def _loc_text(loc: list[Any] | tuple[Any, ...]) -> str:
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += ("." if out else "") + str(part)
    return out


def _toml_literal(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return f'"{value}"'
    return fmt(value)


def _kind_pieces(tp: Any) -> list[str]:
    """The kinds of value ``tp`` accepts, in words (a literal's values one by one)."""
    base, meta = _strip(tp)
    members = _members(base)
    if members is not None:
        return list(dict.fromkeys(p for m in members for p in _kind_pieces(m)))
    if typing.get_origin(base) is Literal:
        return [_toml_literal(v) for v in typing.get_args(base)]
    if typing.get_origin(base) is list:
        inner = _kind_pieces(typing.get_args(base)[0])
        word = {"a number": "numbers", "an integer": "integers",
                "a string (in quotes)": "strings"}.get(inner[0].split(" in ")[0], "")
        if len(inner) == 1 and inner[0].startswith("a list"):
            return ["a list of lists [ [ ... ], ... ]"]
        return [f"a list of {word} [ ... ]" if len(inner) == 1 and word else "a list [ ... ]"]
    if _is_model(base):
        return ["a table"]
    word = _SCALAR_WORDS.get(base, "a value of another kind")
    rng = _range_text(meta) if base in (int, float) else None
    if rng is not None and rng.startswith("in "):
        word += f" {rng}"
    return [word]


def _kind_words(tp: Any) -> str:
    """What a value of type ``tp`` looks like, in words."""
    return _or(_kind_pieces(tp))


def _or(pieces: list[str]) -> str:
    return pieces[0] if len(pieces) == 1 else ", ".join(pieces[:-1]) + " or " + pieces[-1]


def _range_text(meta: list[Any]) -> str | None:
    """``"in (0, 1000] m"``, ``"> 0 kg"``, … from a field's constraints (None: none)."""
    lo = hi = None
    lo_open = hi_open = False
    unit = ""
    for m in meta:
        if getattr(m, "gt", None) is not None:
            lo, lo_open = m.gt, True
        if getattr(m, "ge", None) is not None:
            lo, lo_open = m.ge, False
        if getattr(m, "lt", None) is not None:
            hi, hi_open = m.lt, True
        if getattr(m, "le", None) is not None:
            hi, hi_open = m.le, False
        if isinstance(m, Unit):
            unit = f" {m.symbol}"
    if lo is None and hi is None:
        return None
    if lo is not None and hi is not None:
        return f"in {'(' if lo_open else '['}{fmt(lo)}, {fmt(hi)}{')' if hi_open else ']'}{unit}"
    if lo is not None:
        return f"{'>' if lo_open else '>='} {fmt(lo)}{unit}"
    return f"{'<' if hi_open else '<='} {fmt(hi)}{unit}"


def _got(value: Any, typ: str) -> str:
    """The value as the message quotes it (a float given for an integer keeps its point)."""
    if typ in ("int_type", "int_from_float") and isinstance(value, float):
        return repr(value)
    return fmt(value)


# ------------------------------------------------------------------ one error
def _section_model(parts: list[Any], root: Any) -> Any:
    """The model class at ``parts`` inside ``root`` (for the keys an unknown key is compared
    with), or None."""
    where = _locate(tuple(parts), root)
    base, _ = _strip(where.tp) if where.tp is not None else (None, [])
    return base if _is_model(base) else None


def _one_error(err: dict[str, Any], where: _Located, root: Any) -> str:
    typ = err.get("type", "")
    ctx = err.get("ctx") or {}
    inp = err.get("input")
    parts = list(where.parts)
    if typ == "config_field":
        fld = ctx["field"]
        parts += list(fld) if isinstance(fld, (tuple, list)) else [fld]
        return f"{_loc_text(parts)}: {ctx['message']}"
    at = _loc_text(parts) or "(top level)"
    if typ in ("value_error", "assertion_error"):
        msg = str(err.get("msg", "")).removeprefix("Value error, ")
        msg = msg.removeprefix("Assertion failed, ")
        return f"{at}: {msg}"
    if typ == "extra_forbidden":
        key = str(parts[-1]) if parts else "?"
        model = where.table if where.table is not None else _section_model(parts[:-1], root)
        allowed = sorted(model.model_fields) if model is not None else []
        close = difflib.get_close_matches(key, allowed, n=1)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        keys = f" (keys here: {', '.join(allowed)})" if allowed else ""
        return f"{at}: unknown key (got {fmt(inp)}){hint}{keys}"
    if typ == "missing":
        return f"{at}: required"
    if typ in _BOUND_ERRORS:
        rng = _range_text(where.meta)
        if rng is None:
            rng = f"{_BOUND_ERRORS[typ]} {fmt(next(iter(ctx.values())))}"
        return f"{at}: must be {rng} (got {fmt(inp)})"
    if typ in ("too_short", "too_long"):
        lo = ctx.get("min_length")
        hi = ctx.get("max_length")
        want = (f"{lo} value(s)" if lo == hi else
                f"at least {lo} value(s)" if typ == "too_short" else f"at most {hi} value(s)")
        return f"{at}: must hold {want} (got {ctx.get('actual_length')}: {fmt(inp)})"
    if typ in _SHAPE_ERRORS and where.tp is not None:
        return f"{at}: must be {_kind_words(where.tp)} (got {_got(inp, typ)})"
    words = _TYPE_WORDS.get(typ)
    if words is None:  # a pydantic message: never its internals, always the value
        words = "invalid value"
    return f"{at}: {words} (got {_got(inp, typ)})"


# ------------------------------------------------------------------ unions
def _is_shape_only(items: list[tuple[dict[str, Any], _Located]], pos: int) -> bool:
    """True if every error of a union member says the value is not of its kind (at the
    union itself): the value was not meant for that member."""
    return all(len(w.parts) == pos and e.get("type") in _SHAPE_ERRORS for e, w in items)


def _resolve(items: list[tuple[dict[str, Any], _Located]], root: Any) -> list[str]:
    """Lines for ``items``: errors outside unions as they are; of the errors of a union's
    members, those of the member meant (or one line naming every kind accepted)."""
    lines: list[str] = []
    groups: dict[tuple[Any, ...], list[tuple[dict[str, Any], _Located]]] = {}
    order: list[Any] = []
    for item in items:
        e, w = item
        if not w.unions:
            order.append(("line", _one_error(e, w, root)))
            continue
        pos = w.unions[0][0]
        key = tuple(w.parts[:pos])
        if key not in groups:
            groups[key] = []
            order.append(("group", key))
        groups[key].append(item)
    for kind, value in order:
        if kind == "line":
            lines.append(value)
            continue
        group = groups[value]
        pos = len(value)
        branches: dict[str, list[tuple[dict[str, Any], _Located]]] = {}
        for e, w in group:
            branches.setdefault(w.unions[0][1], []).append((e, w))
        meant = {tag: br for tag, br in branches.items() if not _is_shape_only(br, pos)}
        if meant:
            tag, chosen = max(meant.items(), key=lambda kv: (
                max(len(w.parts) for _, w in kv[1]), -len(kv[1])))
            rest = [(e, _Located(w.parts, w.unions[1:], w.tp, w.meta, w.table))
                    for e, w in chosen]
            lines += _resolve(rest, root)
            continue
        e0, w0 = group[0]
        members = [w.unions[0][2] for _, w in (br[0] for br in branches.values())]
        if any(m is None for m in members):
            words = "a value of another kind"
        else:
            words = _or(list(dict.fromkeys(p for m in members for p in _kind_pieces(m))))
        lines.append(f"{_loc_text(value) or '(top level)'}: must be {words} (got "
                     f"{fmt(e0.get('input'))})")
    return lines


def meant_elsewhere(exc: ValidationError, root: type[BaseModel]) -> list[bool]:
    """For each error of ``exc`` (in order): True if it is the error of a union member the
    value was not meant for, because another member of the same union took the value's
    kind and failed otherwise (``yield_force = -1``: the list member's "must be a list" is
    beside the point, the number member's "must be > 0" is the problem). ``root`` is the
    model ``exc`` came from (e.g. :class:`~pounding.config.RunConfig`)."""
    located = [(dict(e), _locate(tuple(e.get("loc", ())), root))
               for e in exc.errors(include_url=False)]
    groups: dict[tuple[Any, ...], dict[str, list[tuple[dict[str, Any], _Located]]]] = {}
    for e, w in located:
        if w.unions:
            pos, tag, _ = w.unions[0]
            groups.setdefault(tuple(w.parts[:pos]), {}).setdefault(tag, []).append((e, w))
    out = []
    for e, w in located:
        if not w.unions:
            out.append(False)
            continue
        pos, tag, _ = w.unions[0]
        branches = groups[tuple(w.parts[:pos])]
        out.append(_is_shape_only(branches[tag], pos) and any(
            not _is_shape_only(br, pos) for br in branches.values()))
    return out


def format_validation_error(exc: ValidationError, prefix: str = "", *,
                            root: type[BaseModel]) -> str:
    """One line per problem: ``<prefix><key path>: <problem> (got <value>)``; ``root`` is
    the model ``exc`` came from, the file's model (:class:`~pounding.config.RunConfig` for
    a model file): the key paths and ranges are read along it, and an unknown key is
    compared with the keys of its table."""
    items = [(dict(e), _locate(tuple(e.get("loc", ())), root))
             for e in exc.errors(include_url=False)]
    lines: list[str] = []
    for line in _resolve(items, root):
        line = prefix + " ".join(line.split())
        if line not in lines:
            lines.append(line)
    return "\n".join(lines)

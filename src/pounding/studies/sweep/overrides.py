"""A case's values applied to the base model: dotted paths set, alternatives removed."""

from __future__ import annotations

import copy
from collections.abc import Iterator, Sequence
from typing import Any

__all__ = ["apply_overrides"]

_INTENSITY: dict[str, tuple[str, ...]] = {
    "scale": ("scale",),
    "pga_g": ("pga_g",),
    "sa_g": ("sa_g", "sa_period", "sa_damping"),
    "saavg_g": ("saavg_g", "saavg_periods", "saavg_n"),
}
"""The ways a model file scales its record, each with the keys that go with it."""
_INTENSITY_KEYS = tuple(k for keys in _INTENSITY.values() for k in keys)

_EXCLUSIVE: dict[tuple[str, str], tuple[str, ...]] = {
    ("contact", "gap"): ("gaps",),
    ("contact", "gaps"): ("gap",),
    **{("record", key): tuple(k for k in _INTENSITY_KEYS if k not in _INTENSITY[key])
       for key in _INTENSITY},
    ("record", "file"): ("bundled", "stochastic"),
    ("record", "bundled"): ("file", "dt", "units", "stochastic"),
    ("record", "stochastic"): ("file", "bundled", "dt", "units"),
    ("building", "period"): ("stiffness",),
    ("building", "stiffness"): ("period",),
    # a bridge's pier: its lateral stiffness, or its columns' EI with fixity and columns;
    # a frame's deck: its whole mass, or its mass per length
    ("bridge", "stiffness"): ("EI", "fixity", "columns"),
    ("bridge", "EI"): ("stiffness",),
    ("bridge", "deck_mass"): ("deck_mass_per_length",),
    ("bridge", "deck_mass_per_length"): ("deck_mass",),
}
"""Setting the key on the left removes the keys on the right from the base (they are
alternatives in a model file: setting ``record.scale`` replaces a base ``pga_g``, or a base
``sa_g`` with its ``sa_period`` and ``sa_damping``)."""


def apply_overrides(base: dict[str, Any], params: Sequence[str],
                    values: Sequence[Any]) -> dict[str, Any]:
    """A copy of the base configuration with each dotted path set to its value.

    Alternatives of a key are removed (:data:`_EXCLUSIVE`); a new ``contact.law`` drops the
    base's contact keys that law does not read (those set by the case are kept, so a
    mismatch is reported).

    Parameters
    ----------
    base : dict
        The base model configuration as plain data (left unchanged).
    params : sequence of str
        Dotted paths (``"contact.gap"``, ``"building.*.period"``, …).
    values : sequence
        One value per path. A path may end in an item of a list
        (``"bridge.abutment_gaps.0"``, ``"contact.gaps.*"``): that item is set.

    Returns
    -------
    dict
        The case's configuration, ready for validation.
    """
    from pounding.config import LAW_FIELDS

    data = _copy(base)
    set_contact: set[str] = set()
    for path, value in zip(params, values):
        parts = path.split(".")
        key = parts[-1]
        for node in _parents(data, parts[:-1]):
            if isinstance(node, list):  # an item of a list: "bridge.abutment_gaps.0"
                for i in (range(len(node)) if key == "*" else [int(key)]):
                    node[i] = _copy(value)
                continue
            for other in _EXCLUSIVE.get((parts[0], key), ()):
                node.pop(other, None)
            node[key] = _copy(value)
        if parts[0] == "contact" and len(parts) == 2:
            set_contact.add(parts[1])
    contact = data.get("contact")
    if "law" in set_contact and isinstance(contact, dict) and isinstance(contact.get("law"), str):
        used = LAW_FIELDS.get(contact["law"].strip().lower())
        if used is not None:
            for key in list(contact):
                if key not in used | {"law", "gap", "gaps"} | set_contact:
                    del contact[key]
    return data


def _copy(data: Any) -> Any:
    """A deep copy of plain data (tables, arrays, values): what ``copy.deepcopy`` gives,
    without its bookkeeping (TOML data has no shared or cyclic parts)."""
    if isinstance(data, dict):
        return {k: _copy(v) for k, v in data.items()}
    if isinstance(data, list):
        return [_copy(v) for v in data]
    if isinstance(data, (str, int, float, bool, type(None))):
        return data
    return copy.deepcopy(data)


def _parents(data: Any, parts: list[str]) -> Iterator[dict[str, Any]]:
    """The tables that hold the last key of a dotted path (several with ``*``)."""
    if not parts:
        yield data
        return
    head, rest = parts[0], parts[1:]
    if isinstance(data, list):
        items = data if head == "*" else [data[int(head)]]
        for item in items:
            yield from _parents(item, rest)
    else:
        yield from _parents(data.setdefault(head, {}), rest)

"""Writing a model file back as TOML (what ``pounding run`` echoes into its output).

The text is written by `tomli-w <https://github.com/hukkin/tomli-w>`_, the writer that
pairs with the standard library's reader (:mod:`tomllib`): keys are quoted and strings
escaped as the TOML 1.0 specification requires (a non-ASCII key, a quote or a newline in a
value), so what is written reads back equal. Here only what TOML cannot hold is refused,
with the key path: a non-finite number (``nan``, ``inf`` are TOML, but no model-file value
may be one), an integer outside TOML's 64-bit range, a missing value (None), a key that is
not a string.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

__all__ = ["dump_toml"]

_INT64 = (-(2**63), 2**63 - 1)
"""TOML's integers are 64-bit signed (TOML 1.0, "Integer")."""


def _key_text(path: str, key: object) -> str:
    return f"{path}.{key}" if path else str(key)


def _plain(value: Any, path: str) -> Any:
    """``value`` as the plain data tomli-w writes (NumPy scalars made Python numbers,
    tuples made lists), or ValueError/TypeError naming the key path of what TOML cannot
    hold."""
    if isinstance(value, Mapping):
        out: dict[str, Any] = {}
        for k, v in value.items():
            if not isinstance(k, str):
                raise TypeError(f"cannot write {_key_text(path, k)!s} to TOML: a key must be "
                                f"a string (got {type(k).__name__})")
            out[k] = _plain(v, _key_text(path, k))
        return out
    if isinstance(value, (list, tuple)):
        return [_plain(v, f"{path}[{i}]") for i, v in enumerate(value)]
    if type(value).__module__ == "numpy" and hasattr(value, "item"):
        value = value.item()
    if isinstance(value, bool) or isinstance(value, str):
        return value
    if isinstance(value, int):
        if not _INT64[0] <= value <= _INT64[1]:
            raise ValueError(f"cannot write {path} = {value} to TOML: integers are 64-bit")
        return value
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"cannot write {path} = {value!r} to TOML: not a finite number")
        return float(value)
    raise TypeError(f"cannot write {path} to TOML: a {type(value).__name__} "
                    f"({value!r:.60})")


def dump_toml(data: Mapping[str, Any], header: str = "") -> str:
    """``data`` as TOML text that :func:`tomllib.loads` reads back equal.

    Keys keep their order within each table: a table's values first, then its sub-tables
    and arrays of tables (as TOML requires). Short tables inside arrays are written inline.

    Parameters
    ----------
    data : mapping
        Tables (dicts), arrays (lists, tuples) and values (str, int, float, bool; NumPy
        scalars are taken as Python numbers).
    header : str
        Lines written first, each as a ``#`` comment.

    Raises
    ------
    ValueError
        A value TOML cannot hold: NaN or infinity, an integer outside 64 bits (the message
        names its key path).
    TypeError
        A value of no TOML type (None, an object) or a key that is not a string.
    """
    import tomli_w

    plain = _plain(data, "")
    head = "".join(f"# {line}\n" if line else "#\n" for line in header.splitlines())
    return head + tomli_w.dumps(plain)

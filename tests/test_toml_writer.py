"""The TOML writer (:func:`pounding.config.dump_toml`): whatever it writes, the standard
library's reader reads back equal — every example file, and keys and values that a hand-made
writer gets wrong (non-ASCII and quoted keys, quotes and newlines in strings, extreme
floats); what TOML cannot hold (NaN, infinity, an integer beyond 64 bits) is refused with
its key path."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pounding.config import dump_toml, load_config
from pounding.example_files import example_kind

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE_FILES = sorted((ROOT / "examples").glob("*.toml"))


def same(a: Any, b: Any) -> bool:
    """Equal, with floats compared by their bits (so -0.0 is not 0.0). (The order of keys
    is TOML's: a table's values before its sub-tables.)"""
    if isinstance(a, dict):
        return isinstance(b, dict) and set(a) == set(b) and all(same(a[k], b[k]) for k in a)
    if isinstance(a, list):
        return isinstance(b, list) and len(a) == len(b) and all(map(same, a, b))
    if isinstance(a, float):
        return isinstance(b, float) and a.hex() == b.hex()
    return type(a) is type(b) and a == b


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.name)
def test_every_example_file_reads_back_equal(path: Path) -> None:
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    text = dump_toml(data, header="a copy\n\nof an example")
    assert text.startswith("# a copy\n#\n# of an example\n")
    assert same(tomllib.loads(text), data)


def test_a_run_s_model_toml_reads_back_to_the_same_model() -> None:
    """What ``pounding run`` writes (every default written out) is the same configuration."""
    for path in EXAMPLE_FILES:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        if example_kind(path.name) != "model":
            continue  # a sweep, study, spectrum or pushover file
        cfg = load_config(path)
        text = cfg.to_toml(resolve_paths=True, defaults=True, header="copy")
        assert same(tomllib.loads(text), cfg.with_defaults(resolve_paths=True)), path.name
        # the header first, then the tables in the order of a model file
        assert text.startswith("# copy\n")
        order = [k for k, v in cfg.with_defaults().items()
                 if isinstance(v, dict) or (isinstance(v, list) and v
                                            and all(isinstance(x, dict) for x in v))]
        heads = [line.strip("[]") for line in text.splitlines()
                 if line.startswith("[") and "." not in line]
        assert list(dict.fromkeys(heads)) == [k for k in order if k in heads], path.name
        assert "record" in heads


ADVERSARIAL: dict[str, Any] = {
    "ünïcödé": 1,
    "名前": "値",
    "a key with spaces": True,
    "": "the empty key",
    'quo"te': 'a "quoted" value',
    "back\\slash": "C:\\records\\el centro.AT2",
    "new\nline": "two\nlines\r\nand a tab\t and a bell \x07 and DEL \x7f",
    "dotted.key": "not a sub-table",
    "floats": [1e300, -1e300, 5e-324, 1.7976931348623157e308, -0.0, 0.1, 1e-05, 1e16, 3.0],
    "ints": [-(2**63), 2**63 - 1, 0, -1],
    "mixed": [1, "a", 2.5, [True, []], {"x": 1}],
    "emoji 🌍": {"😀": "😀", "nested ü": {"deeper": [{"k": "v"}, {"k": "w"}]}},
    "table": {"ß": -0.0, "list of tables": [{"a": 1}, {"ä": [1, 2]}]},
    "empty": {"list": [], "table": {}},
}


def test_adversarial_keys_and_values_read_back_equal() -> None:
    text = dump_toml(ADVERSARIAL)
    back = tomllib.loads(text)
    assert same(back, ADVERSARIAL)
    assert math.copysign(1.0, back["floats"][4]) == -1.0  # -0.0 keeps its sign


@pytest.mark.parametrize("data, words", [
    ({"contact": {"e": math.nan}}, "contact.e = nan to TOML: not a finite number"),
    ({"building": [{"mass": 1.0}, {"mass": math.inf}]},
     "building[1].mass = inf to TOML: not a finite number"),
    ({"solver": {"rtol": [-math.inf]}}, "solver.rtol[0] = -inf"),
    ({"n": 2**63}, "n = 9223372036854775808 to TOML: integers are 64-bit"),
])
def test_what_toml_cannot_hold_is_refused_with_its_key_path(data: dict[str, Any],
                                                             words: str) -> None:
    with pytest.raises(ValueError, match="cannot write ") as info:
        dump_toml(data)
    assert words in str(info.value)


def test_none_is_refused_with_its_key_path() -> None:
    with pytest.raises(TypeError, match=r"cannot write record.file to TOML: a NoneType"):
        dump_toml({"record": {"file": None}})


def test_numpy_scalars_are_written_as_numbers() -> None:
    np = pytest.importorskip("numpy")
    back = tomllib.loads(dump_toml({"a": np.float64(0.1), "b": np.int64(3),
                                    "c": [np.float32(0.5)]}))
    assert back == {"a": 0.1, "b": 3, "c": [0.5]}


# any TOML document: string keys, 64-bit integers, finite floats, strings, booleans,
# arrays and tables nested
_values = st.recursive(
    st.integers(-(2**63), 2**63 - 1) | st.floats(allow_nan=False, allow_infinity=False)
    | st.text() | st.booleans(),
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(), inner, max_size=4),
    max_leaves=20)


@settings(max_examples=100, deadline=None)
@given(st.dictionaries(st.text(), _values, max_size=6))
def test_any_toml_document_reads_back_equal(data: dict[str, Any]) -> None:
    assert same(tomllib.loads(dump_toml(data)), data)

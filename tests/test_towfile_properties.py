"""Property-based tests of tow files (hypothesis): random edits of the built-in Barge 2a tow
file. Every invalid edit is refused at load with the file, the line and the key; every valid
one loads and round-trips through ``jaxtow tow show`` (the shown file loads back to the same
resolved tow)."""

from __future__ import annotations

import math
import re

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

import jaxtow as jt
from jaxtow.tow import TowFileError
from jaxtow.tow._schema import SCHEMA

BASE = jt.tow.builtin_text("barge2a")
SOURCE = "random.toml"
SETTINGS = settings(
    max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow], derandomize=True
)

# the scalar keys of the built-in file: (section, key) -> the rule of the schema
EDITABLE = {
    ("tow", "speed"): "positive",
    ("towline", "l0"): "positive",
    ("towline", "xp"): "finite",
    ("towline", "EA_N"): "positive",
    ("tug", "bollard_pull_t"): "positive",
    ("tug", "free_speed"): "positive",
    ("tug", "efficiency"): "unit",
    ("route", "length_nm"): "positive",
    ("study", "t1"): "positive",
}
# valid values that keep the tow one jaxtow can build (plausible ranges of each key)
VALID = {
    ("tow", "speed"): st.floats(0.5, 4.0),
    ("towline", "l0"): st.floats(0.8, 4.0),
    ("towline", "xp"): st.floats(0.3, 0.6),
    ("towline", "EA_N"): st.floats(5e7, 1e9),
    ("tug", "bollard_pull_t"): st.floats(10.0, 200.0),
    ("tug", "free_speed"): st.floats(4.0, 9.0),
    ("tug", "efficiency"): st.floats(0.3, 1.0),
    ("route", "length_nm"): st.floats(10.0, 3000.0),
    ("study", "t1"): st.floats(10.0, 800.0),
}


def _set(text: str, section: str, key: str, value: str) -> str:
    """The file with ``key = value`` in ``[section]`` (replacing its line, comment and all)."""
    head = re.search(rf"^\[{section}\][^\n]*\n", text, flags=re.M)
    assert head, section
    end = re.search(r"^\[", text[head.end() :], flags=re.M)
    stop = head.end() + (end.start() if end else len(text) - head.end())
    body = text[head.end() : stop]
    line = re.compile(rf"^{key}\s*=.*$", flags=re.M)
    new = f"{key} = {value}"
    body = line.sub(new, body, count=1) if line.search(body) else new + "\n" + body
    return text[: head.end()] + body + text[stop:]


def _line_of(text: str, section: str, key: str) -> int:
    head = text.index(f"[{section}]")
    start = text.index(f"\n{key} = ", head) + 1
    return text.count("\n", 0, start) + 1


def _invalid_values(rule: str):
    bad_numbers = st.sampled_from(
        {
            "positive": ["-1.0", "0.0", "nan", "inf"],
            "unit": ["0.0", "1.5", "-0.2", "nan"],
            "finite": ["nan", "inf", "-inf"],
        }[rule]
    )
    return st.one_of(bad_numbers, st.sampled_from(['"fast"', "true", "[1.0, 2.0]"]))


@st.composite
def invalid_edits(draw):
    section, key = draw(st.sampled_from(sorted(EDITABLE)))
    kind = draw(st.sampled_from(["value", "unknown key"]))
    if kind == "unknown key":
        name = draw(st.sampled_from(["lenght", "l_0", "speeed", "colour", "EA_nd"]))
        return section, name, draw(st.sampled_from(["1.0", '"x"']))
    return section, key, draw(_invalid_values(EDITABLE[(section, key)]))


@SETTINGS
@given(invalid_edits())
def test_every_invalid_tow_file_is_refused_with_file_line_and_key(edit):
    section, key, value = edit
    text = _set(BASE, section, key, value)
    with pytest.raises(TowFileError) as info:
        jt.tow.loads(text, source=SOURCE)
    e = info.value
    assert e.source == SOURCE
    assert e.line == _line_of(text, section, key), str(e)
    assert e.key == f"{section}.{key}", str(e)
    assert str(e).startswith(f"tow file {SOURCE}, line {e.line}, key {section}.{key}: ")


@st.composite
def valid_edits(draw):
    keys = draw(st.lists(st.sampled_from(sorted(VALID)), min_size=1, max_size=4, unique=True))
    return [(s, k, draw(VALID[(s, k)])) for s, k in keys]


@SETTINGS
@given(valid_edits())
def test_every_valid_tow_file_loads_and_round_trips_through_show(edits):
    text = BASE
    for section, key, value in edits:
        text = _set(text, section, key, repr(float(value)))
    tow = jt.tow.loads(text, source=SOURCE)
    for section, key, value in edits:
        assert math.isclose(float(tow.resolved[section][key]), value, rel_tol=1e-15)
    again = jt.tow.loads(tow.show(), source="shown")
    assert again.resolved == tow.resolved
    assert float(again.towline.EA) == float(tow.towline.EA)
    assert float(again.scales.u_tug) == float(tow.scales.u_tug)


def test_the_edited_keys_are_in_the_schema():
    for section, key in EDITABLE:
        assert key in SCHEMA[section], (section, key)
        assert SCHEMA[section][key].rule == EDITABLE[(section, key)]

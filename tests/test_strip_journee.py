"""The comparison with Journée's (1992) Wigley experiments in docs/strip.md is what
`benchmarks/strip_journee.py` computes: rows of its committed table recomputed."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from helpers import benchmark_script

ROOT = Path(__file__).resolve().parents[1]


def load_script():
    return benchmark_script("strip_journee")


@pytest.mark.slow
def test_the_committed_comparison_is_what_the_script_computes():
    """Forced heave and zero-speed motions recomputed equal the committed table; every
    measured value in the table is the stored measurement (the table holds no edits)."""
    mod = load_script()
    data = json.loads(mod.MEASURED.read_text())
    committed = json.loads(mod.OUT.read_text())
    for key, fn in (("heave_coefficients", mod.heave_coefficients), ("zero_speed", mod.zero_speed)):
        for new, old in zip(fn(data), committed[key], strict=True):
            assert new.keys() == old.keys()
            for k, v in old.items():
                assert new[k] == (pytest.approx(v, rel=1e-6) if isinstance(v, float) else v), k
    measured = {(r[0], r[1]): r[2] for r in data["added_resistance_peaks"]["rows"]}
    for r in committed["added_resistance_peaks"]:
        assert r["measured"] == measured[(r["model"], r["froude"])]
    doc = (ROOT / "docs" / "strip.md").read_text()
    assert mod.tables(committed) in doc

"""A vessel from its particulars: Clarke, Gedling & Hine's linear derivatives, and what they
give for Barge 2a/2b against the measured Table 3.7."""

import math

import numpy as np
import pytest

import jaxtow as jt

P = jt.presets


def test_clarke_regressions_by_hand_on_barge2():
    """The four regressions evaluated by hand (S = π(T/L)², Clarke's ½ρL²U scales) and
    converted to the Hong et al. scales by L/T."""
    L, B, T, cb = 76.2, 24.4, 5.0, 0.928
    S = math.pi * (T / L) ** 2
    d = P.clarke_linear_derivatives(L, B, T, cb)
    assert d["Yv"] == pytest.approx(-S * (1 + 0.40 * 0.928 * 4.88) * 15.24, rel=1e-12)
    assert d["Yr"] == pytest.approx(
        -S * (-0.5 + 2.2 * 24.4 / 76.2 - 0.08 * 4.88) * 15.24, rel=1e-12
    )
    assert d["Nv"] == pytest.approx(-S * (0.5 + 2.4 * 5 / 76.2) * 15.24, rel=1e-12)
    assert d["Nr"] == pytest.approx(
        -S * (0.25 + 0.039 * 4.88 - 0.56 * 24.4 / 76.2) * 15.24, rel=1e-12
    )
    assert d["lb_in_range"]
    assert not P.clarke_linear_derivatives(200.0, 10.0, 5.0, 0.7)["lb_in_range"]


@pytest.mark.slow
def test_clarke_against_table_3_7_and_the_verdicts():
    """The documented comparison (docs/estimates.md): the regressions give c = -0.044 for
    both hulls (course unstable: they know no skegs), so Barge 2b's straight-behind
    equilibrium turns unstable on them, while 2a stays unstable."""
    cb = P.block_coefficient_from_mass(0.5943, P.BARGE2_LENGTH, P.BARGE2_BREADTH)
    d = P.clarke_linear_derivatives(P.BARGE2_LENGTH, P.BARGE2_BREADTH, 5.0, cb)
    out = {}
    for version in ("2a", "2b"):
        table = P.VESSELS[f"barge_{version}"]()
        vals = {k: float(getattr(table, k)) for k in jt.VESSEL_PARAMETERS}
        derivs = "\n".join(f"{k} = {vals[k]!r}" for k in vals if k not in ("Yv", "Yr", "Nv", "Nr"))
        tow = jt.tow.loads(
            f"""[tow]
name = "est{version}"
[vessel]
length = 76.2
breadth = 24.4
draft = 5.0
block_coefficient = {cb!r}
[vessel.derivatives]
{derivs}
[towline]
l0 = 2.5
xp = 0.5
EA = 2.6e8
""",
            source="particulars",
        )
        for k in ("Yv", "Yr", "Nv", "Nr"):
            assert float(getattr(tow.vessel, k)) == pytest.approx(d[k], rel=1e-12)
            assert "Clarke" in dict(tow.assumed)[k]
        c = float(tow.vessel.stability_coefficient())
        st = jt.stability(tow.model(), jt.equilibria(tow.model()).state)
        out[version] = (c, np.asarray(st.max_real))
    assert out["2a"][0] == pytest.approx(-0.0442, abs=5e-4)
    assert out["2b"][0] == pytest.approx(out["2a"][0], rel=0.02)
    assert out["2b"][1][1] > 0  # 2b's straight-behind equilibrium: unstable on the regression
    assert float(P.barge_2b().stability_coefficient()) > 0  # ... stable on the measured table

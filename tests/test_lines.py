"""The towline catalogue against its sources, and composite lines in series: limits, an
independent SciPy solve, derivatives and the tow model on a wire with a chain pennant."""

import math

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from helpers import barge2_on_lines
from scipy.optimize import root

import jaxtow as jt
from jaxtow import lines

G = 9.80665


# ------------------------------------------------------------------ catalogue
#: Published values at catalogue diameters, worked by hand from each source's own laws
#: (d in m): OrcaFlex line-type wizard for wire and chain mass and EA, IACS UR W22 for chain
#: MBL (c d_mm² (44 − 0.08 d_mm) kN), NREL MoorPy for fibre ropes.
SOURCE_TABLE = [
    # (line, d [m], kw, mass [kg/m], EA [N], MBL [N])
    ("wire", 0.076, {}, 3989.7 * 0.076**2, 4.04e10 * 0.076**2, 633.358e6 * 0.076**2),
    ("wire", 0.052, {}, 10.788, 1.0924e8, 1.71260e6),
    ("wire-fc", 0.040, {}, 5.7774, 5.872e7, 0.93468e6),
    ("wire-spiral", 0.076, {}, 30.572, 5.6085e8, 5.9031e6),
    ("chain", 0.076, {"grade": "R3"}, 114.94, 4.9327e8, 4884.3e3),
    ("chain", 0.102, {"grade": "R4"}, 207.04, 8.8850e8, 0.0274 * 102**2 * (44 - 8.16) * 1e3),
    ("chain-studlink", 0.076, {"grade": "R3"}, 126.49, 5.8338e8, 4884.3e3),
    ("polyester", 0.16, {}, 17.376, 14 * 308.2e6 * 0.16**2, 308.2e6 * 0.16**2),
    ("nylon", 0.10, {}, 5.8515, 5 * 2.30029e6, 2.30029e6),
]


@pytest.mark.parametrize("name,d,kw,mass,EA,mbl", SOURCE_TABLE)
def test_catalogue_against_its_sources(name, d, kw, mass, EA, mbl):
    lt = lines.line(name, d, **kw)
    assert lt.mass == pytest.approx(mass, rel=1e-3)
    assert lt.EA == pytest.approx(EA, rel=1e-3)
    assert lt.mbl == pytest.approx(mbl, rel=1e-3)
    assert 0 < lt.weight < lt.mass * G


def test_chain_against_a_second_source():
    """R4 studless chain against NREL MoorPy's coefficients (taken by MoorPy from DNV-OS-E301
    and maker's catalogues): mass and EA within 1 %, MBL equal (the same IACS law)."""
    for d in (0.05, 0.076, 0.102, 0.152):
        c = lines.chain(d, "R4")
        assert c.mass == pytest.approx(20.01e3 * d**2, rel=0.01)
        assert c.EA == pytest.approx(85.61e9 * d**2 - 3.927e7 * d**3, rel=0.01)
        assert c.mbl == pytest.approx(-2.192e9 * d**3 + 1.206e9 * d**2 + 9.107e2 * d, rel=1e-3)
    # steel in sea water keeps 1 − 1025/7850 of its weight
    assert lines.chain(0.076).weight == pytest.approx(114.94 * G * 0.8694, rel=1e-3)


def test_catalogue_refuses_what_it_does_not_cover():
    with pytest.raises(ValueError, match="diameter.*give metres"):
        lines.wire_rope(76.0)
    with pytest.raises(ValueError, match="grade"):
        lines.chain(0.076, "R7")
    with pytest.raises(ValueError, match="line must be one of"):
        lines.line("rope", 0.05)
    with pytest.raises(ValueError, match="material"):
        lines.fibre_rope(0.1, "hemp")
    with pytest.raises(ValueError, match="EA"):
        lines.wire_rope(0.05).with_values(EA=-1.0)


def test_a_certificate_replaces_the_catalogue_values():
    w = lines.wire_rope(0.076).with_values(EA=2.6e8)
    assert w.EA == 2.6e8 and "EA given" in w.source


def test_power_law_fit_recovers_its_law():
    e = np.linspace(0.01, 0.2, 12)
    Sb, q = lines.fit_power_law(e, 3.0e7 * e**1.6)
    assert Sb == pytest.approx(3.0e7, rel=1e-10) and q == pytest.approx(1.6, rel=1e-12)
    with pytest.raises(ValueError, match="strain"):
        lines.fit_power_law([0.0, 0.1], [1.0, 2.0])


def test_catalogue_line_in_the_tow_model():
    sc = jt.presets.barge2_scales()
    w = lines.wire_rope(0.076)
    cat = w.towline(600.0, scales=sc, xp=0.5)
    el = w.towline(600.0, scales=sc, xp=0.5, catenary=False)
    assert float(cat.w) == pytest.approx(w.weight * sc.length / sc.force)
    assert float(el.EA) == pytest.approx(float(cat.EA)) and float(el.l0) == float(cat.l0)


# ------------------------------------------------------------------ composite lines
def _two(share=(0.3, 0.7), EA=(333.0, 100.0), w=(0.05, 0.2), l0=2.5):
    return jt.CompositeTowline(
        l0=l0, xp=0.5, share=jnp.array(share), EA=jnp.array(EA), w=jnp.array(w)
    )


def test_weightless_composite_is_the_series_elastic_line():
    c = _two(w=(0.0, 0.0))
    EA_series = 2.5 / (0.75 / 333.0 + 1.75 / 100.0)
    el = jt.Towline(l0=2.5, xp=0.5, EA=EA_series)
    ls = jnp.array([2.4, 2.5001, 2.55, 2.7, 3.0])
    got = jax.jit(jax.vmap(c.tension))(ls)
    np.testing.assert_allclose(got, jax.vmap(el.tension)(ls), rtol=1e-10)
    assert float(got[0]) == 0.0


def test_uniform_composite_is_the_catenary():
    c = _two(EA=(333.0, 333.0), w=(0.05, 0.05))
    cat = jt.CatenaryTowline(l0=2.5, xp=0.5, EA=333.0, w=0.05)
    ls = jnp.array([1.5, 2.3, 2.5, 2.55])

    def values(line):
        return jax.jit(
            jax.vmap(lambda l: jnp.stack([line.tension(l), line.sag(l), line.end_tension(l)]))
        )(ls)

    np.testing.assert_allclose(values(c), values(cat), rtol=1e-10)


def _scipy_composite(X, lengths, EA, w):
    """The same segment equations (Irvine's elastic catenary per segment) written with the
    plain differences and solved for (H, V0) by SciPy's hybrid Powell root."""

    def geom(H, V0):
        xs, zs, Vs = [], [], V0
        for L, ea, ww in zip(lengths, EA, w):
            Ve = Vs - ww * L
            xs.append(H * L / ea + H / ww * (math.asinh(Vs / H) - math.asinh(Ve / H)))
            zs.append(
                -(Vs**2 - Ve**2) / (2 * ww * ea) - (math.hypot(H, Vs) - math.hypot(H, Ve)) / ww
            )
            Vs = Ve
        return np.array(xs), np.array(zs)

    def F(p):
        H, V0 = math.exp(p[0]), p[1]
        xs, zs = geom(H, V0)
        return [xs.sum() - X, zs.sum()]

    sol = root(F, [0.0, 0.5 * sum(a * b for a, b in zip(lengths, w))], tol=1e-14)
    assert np.max(np.abs(F(sol.x))) < 1e-12, sol  # converged (xtol may stop it first)
    H, V0 = math.exp(sol.x[0]), sol.x[1]
    Wt = sum(a * b for a, b in zip(lengths, w))
    return dict(H=H, hawser=math.hypot(H, V0), tug=math.hypot(H, V0 - Wt))


def test_composite_against_an_independent_scipy_solve():
    c = _two()
    Xs = jnp.array([1.6, 2.2, 2.45, 2.5, 2.52])

    @jax.jit
    @jax.vmap
    def ours(X):
        H = c.tension(X)
        return jnp.stack([H, *c.end_tensions(X), c.length_at_tension(H)])

    got = np.asarray(ours(Xs))
    for X, row in zip(np.asarray(Xs), got):
        ref = _scipy_composite(float(X), [0.75, 1.75], [333.0, 100.0], [0.05, 0.2])
        np.testing.assert_allclose(row[:3], [ref["H"], ref["hawser"], ref["tug"]], rtol=1e-8)
        assert row[3] == pytest.approx(X, rel=1e-10)


def test_composite_gradients_against_finite_differences():
    @jax.jit
    def H(p):
        l, l0, ea1, w2 = p
        return _two(EA=jnp.stack([ea1, 100.0]), w=jnp.stack([0.05, w2]), l0=l0).tension(l)

    p = jnp.array([2.4, 2.5, 333.0, 0.2])
    g = np.asarray(jax.grad(H)(p))
    h = np.array([1e-6, 1e-6, 1e-3, 1e-6])
    fd = [
        (float(H(p.at[i].add(h[i]))) - float(H(p.at[i].add(-h[i])))) / (2 * h[i]) for i in range(4)
    ]
    np.testing.assert_allclose(g, fd, rtol=1e-5)
    c = _two()
    Ts = jax.jit(jax.vmap(c.tension))(jnp.linspace(1.0, 2.5, 6))
    assert np.all(np.diff(np.asarray(Ts)) > 0)


def test_composite_checks_its_segments():
    with pytest.raises(ValueError, match="share must sum to 1"):
        _two(share=(0.3, 0.6))
    with pytest.raises(ValueError, match="one length"):
        jt.CompositeTowline(
            l0=2.5,
            xp=0.5,
            share=jnp.array([0.5, 0.5]),
            EA=jnp.array([1.0]),
            w=jnp.array([0.1, 0.1]),
        )
    with pytest.raises(ValueError, match="EA"):
        _two(EA=(333.0, -1.0))


def test_a_heavy_pennant_carries_its_weight_at_the_hawser():
    """A chain pennant at the hawser: the hawser carries more of the weight than the tug, the
    two ends' vertical tensions add up to the line's weight, and the lowest point lies below
    both ends by less than half the line."""
    c = _two(share=(0.1, 0.9), EA=(500.0, 333.0), w=(0.5, 0.05))
    H, hawser, tug, sag = (
        float(x) for x in jax.jit(lambda l: (c.tension(l), *c.end_tensions(l), c.sag(l)))(2.3)
    )
    assert hawser > tug
    weight = 0.5 * 0.25 + 0.05 * 2.25
    assert math.sqrt(hawser**2 - H**2) + math.sqrt(tug**2 - H**2) == pytest.approx(
        weight, rel=1e-12
    )
    assert 0.0 < sag < 0.5 * 2.5


@pytest.mark.heavy  # minutes on 2 cores: pytest -m heavy
@pytest.mark.slow
def test_barge2_on_wire_with_a_chain_pennant():
    """600 m of 76 mm IWRC wire with 50 m of 76 mm R3 chain at the hawser, against the same
    wire alone: the equilibria keep their headings (a symmetric tow), the pennant shortens
    the calm span by its sag and leaves the verdicts (2a unstable, 2b stable)."""
    sc = jt.presets.barge2_scales()
    wire, ch = lines.wire_rope(0.076), lines.chain(0.076)
    comp = lines.composite([(ch, 50.0), (wire, 600.0)], scales=sc, xp=0.5)
    alone = wire.towline(650.0, scales=sc, xp=0.5)
    out = barge2_on_lines({"pennant": comp, "wire": alone}, sc)
    for v in ("barge_2a", "barge_2b"):
        np.testing.assert_allclose(
            np.sort(out[v, "pennant"][0]), np.sort(out[v, "wire"][0]), atol=1e-6
        )
        assert out[v, "pennant"][2] < out[v, "wire"][2]
    assert out["barge_2a", "pennant"][1] > 0 and out["barge_2a", "wire"][1] > 0
    assert out["barge_2b", "pennant"][1] < 0 and out["barge_2b", "wire"][1] < 0
    # the numbers in docs/model.md
    assert out["barge_2a", "pennant"][1] == pytest.approx(0.310, abs=1e-3)
    assert out["barge_2a", "wire"][1] == pytest.approx(0.312, abs=1e-3)
    assert out["barge_2b", "pennant"][1] == pytest.approx(-0.120, abs=1e-3)
    l = out["barge_2a", "pennant"][2]
    hawser = float(comp.end_tensions(l)[0]) * sc.force
    wire_end = float(alone.end_tension(out["barge_2a", "wire"][2])) * sc.force
    assert hawser / 1e3 == pytest.approx(116.1, abs=0.5) and wire_end / 1e3 == pytest.approx(
        83.9, abs=0.5
    )
    assert l * sc.length == pytest.approx(548.3, abs=0.5)
    assert float(comp.sag(l)) * sc.length == pytest.approx(152.0, abs=0.5)

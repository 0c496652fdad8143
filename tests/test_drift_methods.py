"""Waterline drift methods: geometry, short-wave limits, symmetry, gradients, K1."""

import math

import jax
import jax.numpy as jnp
import numpy as np
import pytest
import scipy.special as sp
from helpers import assert_png_has_content, central_derivative

import jaxtow as jt
from jaxtow._special import k1, r_function
from jaxtow._units import RHO_SEA, G
from jaxtow.drift import (
    WATERLINE_METHODS,
    dnv2014,
    faltinsen,
    fujii_takahashi,
    kashiwagi,
    kuroda,
)
from jaxtow.presets import barge2_waterline, box_waterline

RG = RHO_SEA * G
B = 24.4


@pytest.fixture(scope="module")
def box():
    return box_waterline(length=76.2, breadth=B)


@pytest.fixture(scope="module")
def barge2():
    return barge2_waterline()


# ---------------------------------------------------------------- special functions


def test_k1_matches_scipy_and_its_derivative_identity():
    x = np.geomspace(1e-3, 50.0, 400)
    np.testing.assert_allclose(np.asarray(k1(x)), sp.k1(x), rtol=1e-13)
    d = np.asarray(jax.vmap(jax.grad(k1))(jnp.asarray(x)))
    np.testing.assert_allclose(d, -sp.k0(x) - sp.k1(x) / x, rtol=1e-12)  # K1' = -K0 - K1/x


def test_r_function_limits_and_formula():
    x = np.geomspace(1e-2, 20.0, 50)
    ref = np.pi**2 * sp.i1(x) ** 2 / (np.pi**2 * sp.i1(x) ** 2 + sp.k1(x) ** 2)
    np.testing.assert_allclose(np.asarray(r_function(x)), ref, rtol=1e-12)
    assert float(r_function(0.0)) == 0.0 and float(jax.grad(r_function)(0.0)) == 0.0
    assert float(r_function(400.0)) == 1.0  # no overflow for short waves


# ---------------------------------------------------------------- geometry


def test_box_geometry(box):
    assert float(box.length) == pytest.approx(76.2) and float(box.breadth) == pytest.approx(B)
    assert float(box.area) == pytest.approx(76.2 * B)
    assert box.convex and float(box.block_coefficient) == 1.0
    n = np.asarray(box.normals)
    th = np.asarray(box.theta)
    np.testing.assert_allclose(np.stack([np.sin(th), np.cos(th)], -1), n, atol=1e-15)  # eq. 2.60
    assert float(box.bow_length_to_95_breadth()) == 0.0


def test_barge2_rake_is_consistent_with_published_mass(barge2):
    r = jt.presets.barge2_rake()
    # the rake's volume loss a·B·T reproduces C_B = m' L / (2B) of Table 3.7
    assert 1.0 - r.extent / 76.2 == pytest.approx(0.5943 * 76.2 / (2 * B))
    assert math.degrees(r.flare) == pytest.approx(47.66, abs=0.01)
    fl = np.degrees(np.asarray(barge2.flare))
    assert sorted(np.round(fl, 2)) == [0.0, 0.0, 47.66, 47.66, 47.66, 47.66]


def test_read_write_waterline_round_trip(tmp_path, barge2):
    f = tmp_path / "wl.txt"
    f.write_text("# half waterline\n38.1 0 0 5\n38.1 12.2 0 5\n-38.1 12.2 0 5\n-38.1 0\n")
    wl = jt.io.read_waterline(f, draft=5.0)
    np.testing.assert_allclose(
        np.asarray(wl.points), np.asarray(box_waterline().points), atol=1e-12
    )
    g = tmp_path / "b2.txt"
    jt.io.write_waterline(g, barge2)
    back = jt.io.read_waterline(g, draft=5.0, block_coefficient=float(barge2.block_coefficient))
    np.testing.assert_allclose(np.asarray(back.points), np.asarray(barge2.points), atol=1e-12)
    np.testing.assert_allclose(np.asarray(back.flare), np.asarray(barge2.flare), atol=1e-12)


def test_clockwise_input_is_reoriented(box):
    p = np.asarray(box.points)
    cw = np.concatenate([p[::-1], p[-1:]], axis=0)
    wl = jt.drift.waterline(cw, draft=5.0)
    np.testing.assert_allclose(
        float(faltinsen(wl, 1.0, 0.3).fy), float(faltinsen(box, 1.0, 0.3).fy)
    )


@pytest.mark.parametrize(
    "points, message",
    [
        ([(38, 0), (38, 12), (-38, 12), (-38, -12), (38, -12)], "not closed"),
        ([(38, 12), (-38, -12), (-38, 12), (38, -12), (38, 12)], "self-intersects"),
        ([(38, 0), (0, 0), (-38, 0), (38, 0)], "zero breadth"),
        ([(38, 0), (38, 0), (-38, 12), (38, 0)], "zero breadth|repeated"),
    ],
)
def test_bad_waterlines_raise_clear_errors(points, message):
    with pytest.raises(ValueError, match=message):
        jt.drift.waterline(points, draft=5.0)


def test_half_waterline_off_centreline_is_not_closed(tmp_path):
    f = tmp_path / "bad.txt"
    f.write_text("38.1 1.0\n38.1 12.2\n-38.1 12.2\n-38.1 0\n")
    with pytest.raises(ValueError, match="not closed"):
        jt.io.read_waterline(f, draft=5.0)


# ---------------------------------------------------------------- limits and symmetry


def test_wall_sided_box_head_seas_short_wave_limits(box):
    w, u = 0.8, 1.5
    assert float(faltinsen(box, w, 0.0).fx) == pytest.approx(-0.5 * RG * B, rel=1e-13)
    assert float(dnv2014(box, w, 0.0).fx) == pytest.approx(-RG * B, rel=1e-13)
    assert float(faltinsen(box, w, 0.0, u).fx) == pytest.approx(
        -0.5 * RG * B * (1 + 2 * w * u / G), rel=1e-13
    )
    f4 = faltinsen(box, w, 0.0, u, speed_factor=(4.0, 2.0))
    assert float(f4.fx) == pytest.approx(-0.5 * RG * B * (1 + 4 * w * u / G), rel=1e-13)
    # oblique: the lit bow and side give ½ρgζa² (B cos²β, L sin²β) along -k̂-ish directions
    b = 0.4
    f = faltinsen(box, w, b)
    assert float(f.fx) == pytest.approx(-0.5 * RG * B * math.cos(b) ** 2, rel=1e-13)
    assert float(f.fy) == pytest.approx(-0.5 * RG * 76.2 * math.sin(b) ** 2, rel=1e-13)


@pytest.mark.parametrize("name", list(WATERLINE_METHODS))
@pytest.mark.parametrize("hull", ["box", "barge2"])
def test_heading_symmetry(name, hull, box, barge2):
    wl = box if hull == "box" else barge2
    fn = WATERLINE_METHODS[name]
    w = jnp.array([0.4, 0.9, 1.7, 3.0])
    for b, u, v in [(0.25, 0.0, 0.0), (0.6, 1.2, 0.0), (1.1, 0.8, 0.4)]:
        p, m = fn(wl, w, b, u, v), fn(wl, w, -b, u, -v)
        np.testing.assert_allclose(np.asarray(p.fx), np.asarray(m.fx), rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(np.asarray(p.fy), -np.asarray(m.fy), rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(np.asarray(p.nz), -np.asarray(m.nz), rtol=1e-12, atol=1e-6)
    head = fn(wl, w, 0.0, 1.0, 0.0)
    np.testing.assert_allclose(np.asarray(head.fy), 0.0, atol=1e-9)
    np.testing.assert_allclose(np.asarray(head.nz), 0.0, atol=1e-6)


def test_fujii_takahashi_family_stationary_equal_and_tend_to_faltinsen(box, barge2):
    for wl in (box, barge2):
        w = jnp.linspace(0.3, 2.5, 23)
        for b in (0.0, 0.26, -0.6):
            ft, ku, ka = (m(wl, w, b) for m in (fujii_takahashi, kuroda, kashiwagi))
            np.testing.assert_allclose(
                np.asarray(ku.force), np.asarray(ft.force), rtol=1e-14, atol=1e-9
            )
            np.testing.assert_allclose(
                np.asarray(ka.force), np.asarray(ft.force), rtol=1e-14, atol=1e-9
            )
            # short waves: k d >> 1, R(kd) -> 1, Faltinsen's limit
            short = jnp.array([6.0, 10.0])
            for m in (fujii_takahashi, kuroda, kashiwagi):
                np.testing.assert_allclose(
                    np.asarray(m(wl, short, b).force),
                    np.asarray(faltinsen(wl, short, b).force),
                    rtol=1e-9,
                    atol=1e-9,
                )
            # long waves: reflection vanishes
            assert abs(float(ft.fx[0])) < 0.01 * abs(float(faltinsen(wl, 0.3, b).fx))


def test_speed_raises_the_family_and_kashiwagi_is_one_at_rest(box):
    w = 1.2
    ft0, ft1 = fujii_takahashi(box, w, 0.0), fujii_takahashi(box, w, 0.0, 2.0)
    fn = 2.0 / math.sqrt(G * 76.2)
    assert float(ft1.fx / ft0.fx) == pytest.approx(1 + 5 * math.sqrt(fn), rel=1e-12)
    ku0, ku1 = kuroda(box, w, 0.0), kuroda(box, w, 0.0, 2.0)
    assert abs(float(ku1.fx)) > abs(float(ku0.fx))
    assert float(jt.drift._methods.kashiwagi_speed_factor(0.0, 0.5)) == 1.0


def test_vmap_over_all_four_inputs(barge2):
    key = np.random.default_rng(0)
    w, b, u, v = (
        jnp.asarray(key.uniform(lo, hi, 7))
        for lo, hi in [(0.3, 2.5), (-1.0, 1.0), (0.0, 3.0), (-1.0, 1.0)]
    )
    for name in ("liu", "kuroda", "faltinsen"):
        fn = WATERLINE_METHODS[name]
        batched = jax.vmap(lambda *a: fn(barge2, *a).force)(w, b, u, v)
        loop = np.stack([np.asarray(fn(barge2, *a).force) for a in zip(w, b, u, v)])
        np.testing.assert_allclose(np.asarray(batched), loop, rtol=1e-13, atol=1e-9)


@pytest.mark.parametrize(
    "name",
    [
        "faltinsen",
        "liu",
        "kuroda",
        pytest.param("fujii_takahashi", marks=pytest.mark.slow),
        pytest.param("kashiwagi", marks=pytest.mark.slow),
    ],
)
def test_gradients_match_finite_differences(name, barge2):
    fn = WATERLINE_METHODS[name]
    x0 = dict(w=1.1, b=0.3, u=1.4, v=0.35)

    def f(**kw):
        a = {**x0, **kw}
        return fn(barge2, a["w"], a["b"], a["u"], a["v"]).force @ jnp.array([1.0, 3.0, 0.02])

    for key in ("w", "b", "u", "v"):
        ad = float(jax.grad(lambda x: f(**{key: x}))(x0[key]))
        fd = central_derivative(lambda x: f(**{key: x}), x0[key], h=1e-5)
        assert ad == pytest.approx(fd, rel=1e-6, abs=1e-6 * abs(float(f()))), key
    # the waterline coordinates, on a hull without ties in its extreme x and y (L and B are
    # maxima over vertices, which have kinks where two vertices tie, as on a box)
    pts, fl, _ = jt.drift.mirror_half(
        [(40, 0), (36, 10), (-30, 12.2), (-37.5, 5), (-38.1, 0)], flare=[0.3, 0.0, 0.0, 0.2]
    )
    wl = jt.drift.waterline(pts, draft=5.0, flare=fl, block_coefficient=0.9)
    g = jax.grad(lambda wl: f_wl(fn, wl, x0))(wl).points
    h = 1e-5
    for i, j in [(0, 0), (1, 0), (1, 1), (2, 1), (5, 1)]:
        e = np.zeros(wl.points.shape)
        e[i, j] = h
        fp = f_wl(fn, jt.drift.Waterline(**{**_fields(wl), "points": wl.points + e}), x0)
        fm = f_wl(fn, jt.drift.Waterline(**{**_fields(wl), "points": wl.points - e}), x0)
        assert float(g[i, j]) == pytest.approx(float(fp - fm) / (2 * h), rel=1e-6, abs=1e-3)


def f_wl(fn, wl, x0):
    return fn(wl, x0["w"], x0["b"], x0["u"], x0["v"]).force @ jnp.array([1.0, 3.0, 0.02])


def _fields(wl):
    return dict(
        points=wl.points,
        flare=wl.flare,
        local_draft=wl.local_draft,
        draft=wl.draft,
        block_coefficient=wl.block_coefficient,
        convex=wl.convex,
        name=wl.name,
    )


# ---------------------------------------------------------------- flags and comparisons


def test_validity_flags(box, barge2):
    fast = faltinsen(box, 1.0, 0.0, u=0.16 * math.sqrt(G * 76.2))
    assert not bool(fast.flags["froude"]) and not bool(fast.valid)
    slow = faltinsen(box, 2.0, 0.0, u=1.0)
    assert bool(slow.valid) and int(slow.zone) == 2
    assert int(faltinsen(box, 0.5, 0.0).zone) == 0
    assert not bool(faltinsen(barge2, 2.0, 0.0).flags["wall_sided"])  # raked faces
    assert not bool(jt.drift.imo(box, 1.0, 0.0).flags["bow_length"])  # box: L_b = 0
    assert not bool(dnv2014(box, 1.0, 0.5).flags["heading"])
    with pytest.raises(ValueError, match="'omega'"):
        faltinsen(box, -1.0, 0.0)


def test_relative_mse_and_zones(box):
    w = jnp.linspace(0.3, 3.0, 60)
    base = faltinsen(box, w, 0.0).fx
    assert jt.drift.relative_mse(base, base) == 0.0
    assert jt.drift.relative_mse(0 * base, base) == 1.0
    z = jt.drift.relative_mse_by_zone(fujii_takahashi(box, w, 0.0).fx, base, w, 76.2)
    assert set(z) == {"motion", "transition", "reflection"}
    assert z["reflection"] < z["transition"] < z["motion"]  # the SW family converges in short waves
    with pytest.raises(ValueError, match="no points"):
        jt.drift.relative_mse(base, base, mask=np.zeros(60, bool))


def test_irregular_short_wave_limit_and_tp_gradient(box):
    # a frequency-independent QTF gives F * Hs^2/8 (eq. 2.32)
    hs, tp = 2.4, 7.0
    F = jt.drift.irregular_drift("dnv2014", box, hs, tp, 0.0)
    assert float(F[0]) == pytest.approx(-RG * B * hs**2 / 8, rel=2e-3)
    f = jax.jit(lambda t: jt.drift.irregular_drift("fujii_takahashi", box, hs, t, 0.0)[0])
    assert float(jax.grad(f)(tp)) == pytest.approx(central_derivative(f, tp, h=1e-4), rel=1e-6)
    tps = jnp.linspace(5.6, 8.5, 4)
    Fv = jax.vmap(lambda t: jt.drift.irregular_drift("liu", box, hs, t, 0.0))(tps)
    assert Fv.shape == (4, 3) and np.all(
        np.diff(np.asarray(Fv[:, 0])) > 0
    )  # less drift in longer seas


@pytest.mark.slow
def test_cli_drift_writes_figures_datasets_and_summary(tmp_path):
    import json

    from jaxtow.cli import main
    from jaxtow.io import load_dataset

    assert (
        main(
            [
                "drift",
                "--tow",
                "barge2a",
                "--out",
                str(tmp_path),
                "--n-omega",
                "40",
                "--speeds",
                "0",
                "2",
            ]
        )
        == 0
    )
    for f in (
        "fig4_3_stationary_surge.png",
        "fig4_4_stationary_sway.png",
        "fig4_5_irregular_surge.png",
        "fig4_6_irregular_sway.png",
        "fig5_6_sailing_surge.png",
        "fig5_7_sailing_sway.png",
    ):
        assert_png_has_content(tmp_path / f)
    ds = load_dataset(tmp_path / "stationary_head_seas.nc")
    assert set(ds.method.values) == set(WATERLINE_METHODS) and ds["valid"].dtype == bool
    s = json.loads((tmp_path / "summary.json").read_text())
    assert s["waterline"] == "barge2" and s["physical_tp_range"][0] == pytest.approx(8.06, abs=0.01)
    assert s["regular_relative_mse_by_zone"]["surge"]["fujii_takahashi"]["reflection"] < 0.05

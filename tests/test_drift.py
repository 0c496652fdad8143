"""QTF database, wave-drift damping, sailing drift and the tow-model wave force (thesis
eqs 2.35-2.49, 5.1, 6.14-6.23)."""

import math

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from helpers import model

import jaxtow as jt
from jaxtow._units import G
from jaxtow.drift import encounter_frequency, sailing_drift
from jaxtow.forces import WaveDriftForce

W = np.linspace(0.2, 2.0, 19)
B = np.radians(np.arange(0.0, 181.0, 15.0))


def _table(w=W, b=B):
    Wg, Bg = np.meshgrid(w, b, indexing="ij")
    return dict(
        fx=-1000 * np.cos(Bg) * (1 + 0.3 * Wg),
        fy=-800 * np.sin(Bg) * Wg,
        nz=5000 * np.sin(2 * Bg) * Wg**2,
    )


def test_constant_qtf_gives_b11_4_omega_f_over_g():
    Wg, Bg = np.meshgrid(W, np.radians(np.arange(-90.0, 91.0, 15.0)), indexing="ij")
    F = -1234.0
    q = jt.drift.QTF(
        omega=W, beta=Bg[0], fx=np.full(Wg.shape, F), fy=np.zeros(Wg.shape), nz=np.zeros(Wg.shape)
    )
    for w in (0.5, 1.0, 1.7):
        Bm = jt.drift.wave_drift_damping(q, w, 0.0)
        assert float(Bm[0, 0]) == pytest.approx(4 * w * F / G, rel=1e-12)
        # speed-corrected short-wave limit, head seas: F (1 + 4 ω u / g)
        u = 1.5
        assert float(sailing_drift(q, w, 0.0, 0.0)[0]) == pytest.approx(F, rel=1e-12)
        Fu = float((q(w, 0.0) + Bm @ jnp.array([u, 0.0, 0.0]))[0])
        assert Fu == pytest.approx(F * (1 + 4 * w * u / G), rel=1e-12)


def test_autodiff_damping_equals_finite_differences_of_table():
    """At interior nodes the interpolant's derivatives are the three-point differences of
    the table, so Aranha's B from autodiff equals B from finite differences of the data."""
    t = _table()
    q = jt.drift.QTF.symmetric(omega=W, beta=B, **t)
    bfull = np.asarray(q.beta)
    vals = np.asarray(q.values)
    for i, j in ((5, 14), (10, 16), (12, 13)):
        w, b = W[i], bfull[j]
        F = vals[:, i, j]
        dFw = (vals[:, i + 1, j] - vals[:, i - 1, j]) / (W[i + 1] - W[i - 1])
        dFb = (vals[:, i, j + 1] - vals[:, i, j - 1]) / (bfull[j + 1] - bfull[j - 1])
        c, s = math.cos(b), math.sin(b)
        col_u = w / G * (w * c * dFw - 2 * s * dFb + 4 * c * F)
        col_v = w / G * (w * s * dFw + 2 * c * dFb + 4 * s * F)
        Bm = np.asarray(jt.drift.wave_drift_damping(q, w, b))
        np.testing.assert_allclose(Bm[:, 0], col_u, rtol=1e-10, atol=1e-9)
        np.testing.assert_allclose(Bm[:, 1], col_v, rtol=1e-10, atol=1e-9)
        np.testing.assert_array_equal(
            Bm[:, 2], 0.0
        )  # documented fallback without sectional moments


def test_interpolant_is_c1_and_reproduces_nodes():
    q = jt.drift.QTF.symmetric(omega=W, beta=B, **_table())
    vals = np.asarray(q.values)
    for i, j in ((3, 13), (18, 20), (0, 12)):
        np.testing.assert_allclose(q(W[i], float(q.beta[j])), vals[:, i, j], rtol=1e-13, atol=1e-9)
    # derivatives continuous across a node (ω = W[7], β = B node)
    d = jax.jacfwd(lambda x: q(x[0], x[1]))
    for eps in (1e-7,):
        left = np.asarray(d(jnp.array([W[7] - eps, 0.3])))
        right = np.asarray(d(jnp.array([W[7] + eps, 0.3])))
        np.testing.assert_allclose(left, right, rtol=1e-4, atol=1e-3)
    # extrapolation: zero at ω = 0, constant beyond ω_max
    np.testing.assert_array_equal(q(0.0, 0.4), 0.0)
    np.testing.assert_allclose(q(5.0, 0.4), q(float(W[-1]), 0.4), rtol=1e-14)
    assert np.all(np.asarray(jax.grad(lambda w: q(w, 0.4)[0])(5.0)) == 0.0)


def test_symmetry_of_forces_and_damping():
    q = jt.drift.QTF.symmetric(omega=W, beta=B, **_table())
    for w, b in ((0.7, 0.4), (1.3, 1.1)):
        Fp, Fm = np.asarray(q(w, b)), np.asarray(q(w, -b))
        np.testing.assert_allclose(Fm, Fp * np.array([1, -1, -1]), rtol=1e-12)
        Bp, Bm = (
            np.asarray(jt.drift.wave_drift_damping(q, w, b)),
            np.asarray(jt.drift.wave_drift_damping(q, w, -b)),
        )
        # B11, B22 even about head seas; B12, B21 mirrored (odd)
        assert Bm[0, 0] == pytest.approx(Bp[0, 0], rel=1e-10)
        assert Bm[1, 1] == pytest.approx(Bp[1, 1], rel=1e-10)
        assert Bm[0, 1] == pytest.approx(-Bp[0, 1], rel=1e-10)
        assert Bm[1, 0] == pytest.approx(-Bp[1, 0], rel=1e-10)
    # head seas: no sway force or yaw moment on a symmetric hull
    np.testing.assert_allclose(np.asarray(q(0.9, 0.0))[1:], 0.0, atol=1e-9)


def test_partial_table_flags_heading():
    Wg, Bg = np.meshgrid(W, np.radians(np.arange(-45.0, 46.0, 15.0)), indexing="ij")
    q = jt.drift.QTF(omega=W, beta=Bg[0], fx=-np.cos(Bg), fy=np.sin(Bg), nz=np.zeros_like(Bg))
    assert bool(q.in_table(0.5)) and not bool(q.in_table(1.0))
    np.testing.assert_allclose(q(1.0, 1.0), q(1.0, math.radians(45.0)))  # clamped, flagged


def test_encounter_frequency():
    assert float(encounter_frequency(1.0, 0.0, 2.0)) == pytest.approx(1.0 + 2.0 / G)
    assert float(encounter_frequency(1.0, math.pi, 2.0)) == pytest.approx(1.0 - 2.0 / G)
    # swaying towards waves from port (travelling along -y) raises the encounter frequency
    assert float(encounter_frequency(1.0, math.pi / 2, 0.0, v=1.0)) == pytest.approx(1.0 + 1.0 / G)
    # tow model: beta = -psi, (u, v) = (cos psi, -sin psi): waves from ahead of the tug, any heading
    for psi in (0.0, 0.3, -1.1):
        assert float(
            encounter_frequency(0.7, -psi, 2 * math.cos(psi), 2 * -math.sin(psi))
        ) == pytest.approx(0.7 + 0.49 * 2 / G)


def test_wamit_fixture_reads_back(tmp_path):
    """A file written by hand from the documented layout reads back to the same numbers."""
    ulen, rho, g = 10.0, 1025.0, 9.80665
    lines = ["  PER   BETA1 BETA2  I  MOD  PHA  RE  IM"]
    per = [12.0, 6.0]
    heads_w = [135.0, 180.0, 225.0]  # WAMIT travel-to headings: 180 = head seas
    nd = {1: -0.4, 2: 0.05, 6: -0.02}
    for p in per:
        for h in heads_w:
            for mode, v in nd.items():
                sgn = 1.0 if h >= 180 else -1.0
                val = v * (1.0 if mode == 1 else sgn * (h != 180.0))
                lines.append(f"{p} {h} {h} {mode} {abs(val)} {0 if val >= 0 else 180} {val} 0.0")
    f = tmp_path / "barge.8"
    f.write_text("\n".join(lines) + "\n")
    q = jt.io.read_wamit_drift(f, ulen=ulen, rho=rho, g=g)
    np.testing.assert_allclose(np.asarray(q.omega), sorted(2 * math.pi / np.array(per)))
    np.testing.assert_allclose(np.degrees(np.asarray(q.beta)), [-45.0, 0.0, 45.0])
    np.testing.assert_allclose(np.asarray(q.values[0]), -0.4 * rho * g * ulen)
    np.testing.assert_allclose(np.asarray(q.values[1])[:, 1], 0.0)
    np.testing.assert_allclose(np.asarray(q.values[1])[:, 2], 0.05 * rho * g * ulen)
    np.testing.assert_allclose(np.asarray(q.values[2])[:, 0], 0.02 * rho * g * ulen**2)
    # write → read round trip
    jt.io.write_wamit_drift(q, tmp_path / "again.9", ulen=ulen, rho=rho, g=g)
    q2 = jt.io.read_wamit_drift(tmp_path / "again.9", ulen=ulen, rho=rho, g=g)
    np.testing.assert_allclose(np.asarray(q2.values), np.asarray(q.values), rtol=1e-15)
    np.testing.assert_allclose(np.asarray(q2.omega), np.asarray(q.omega), rtol=1e-15)


@pytest.mark.parametrize("suffix", [".nc", ".csv"])
def test_own_format_round_trip_is_exact(tmp_path, suffix):
    q = jt.drift.QTF.symmetric(omega=W, beta=B, **_table())
    jt.io.save_qtf(q, tmp_path / f"q{suffix}")
    back = jt.io.load_qtf(tmp_path / f"q{suffix}")
    np.testing.assert_array_equal(np.asarray(back.values), np.asarray(q.values))
    np.testing.assert_array_equal(np.asarray(back.beta), np.asarray(q.beta))
    assert back.periodic == q.periodic


def _wave_model(vessel, zeta_a, omega=1.0, **kw):
    q = jt.drift.QTF.symmetric(omega=W, beta=B, **_table())
    force = WaveDriftForce(qtf=q, omega=omega, zeta_a=zeta_a, scales=jt.presets.barge2_scales())
    return model(vessel, external=force, **kw), force


def test_wave_force_at_zero_speed_is_stationary_qtf(barge_2a):
    m, force = _wave_model(barge_2a, 1.2)
    for psi in (0.0, 0.3, -0.5):
        y = jnp.array([0.0, 0.0, 0.0, 2.5, 0.0, psi])
        np.testing.assert_allclose(
            force.dimensional(y), 1.2**2 * np.asarray(force.qtf(1.0, -psi)), rtol=1e-13
        )
        Fnd = np.asarray(force(0.0, y, m))
        sc = jt.presets.barge2_scales()
        np.testing.assert_allclose(
            Fnd * np.array([sc.force, sc.force, sc.moment]),
            1.2**2 * np.asarray(force.qtf(1.0, -psi)),
            rtol=1e-13,
        )


@pytest.mark.slow
def test_zero_amplitude_reproduces_calm_water(barge_2a):
    # one case with all three equilibria (compiling the wave-force model costs ~15 s a case)
    for v, xp in ((barge_2a, 0.3),):
        calm = jt.equilibria(model(v, xp=xp))
        waves, _ = _wave_model(v, 0.0, xp=xp)
        e = jt.equilibria(waves)
        np.testing.assert_array_equal(np.asarray(e.state), np.asarray(calm.state))
        np.testing.assert_array_equal(
            np.asarray(jt.stability(waves, e.state).max_real),
            np.asarray(jt.stability(model(v, xp=xp), calm.state).max_real),
        )


def test_wave_drift_in_tow_model_equilibria_and_flags(barge_2a):
    m, force = _wave_model(barge_2a, 1.2)
    e = jt.equilibria(m)
    assert np.all(e.residual < 1e-12)
    straight = e.select(e.branch == 0)
    # head-wave drift adds resistance: more tension than in calm water
    calm = jt.equilibria(model(barge_2a)).select(jt.equilibria(model(barge_2a)).branch == 0)
    assert float(straight.tension[0]) > float(calm.tension[0])
    flags = force.validity(straight.state[0])
    assert bool(flags["froude_ok"])  # 2 m/s on 76.2 m: Fn = 0.073
    assert float(flags["froude"]) == pytest.approx(2.0 / math.sqrt(G * 76.2), rel=1e-6)
    # U/(ω ζa) = 2 / (1.0 · 1.2) = 1.67: outside the no-separation limit, and flagged
    assert float(flags["separation_ratio"]) == pytest.approx(2.0 / 1.2, rel=1e-9)
    assert not bool(flags["no_separation"])
    _, short_waves = _wave_model(barge_2a, 1.2, omega=2.0)
    assert bool(short_waves.validity(straight.state[0])["no_separation"])  # 2/(2·1.2) = 0.83


def test_capytaine_layout_reader():
    """Capytaine conventions: travel-to headings (π = head seas), complex values, a
    (omega, wave_direction, wave_direction) QTF of which the diagonal is the mean drift."""
    import xarray as xr

    w = np.array([0.5, 1.0, 1.5])
    wd = np.array([math.pi - 0.5, math.pi, math.pi + 0.5])
    beta_j = wd - math.pi
    fx = -100.0 * np.cos(beta_j)[None, :] * w[:, None]
    full = np.zeros((3, 3, 3), complex)
    for k in range(3):
        full[:, k, k] = fx[:, k] + 0.0j
        full[:, k, (k + 1) % 3] = 99.0  # off-diagonal entries are ignored
    dims = ("omega", "wave_direction", "wave_direction_l")
    coords = {"omega": w, "wave_direction": wd, "wave_direction_l": wd}
    da = xr.DataArray(full, dims=dims, coords=coords)
    zero = xr.DataArray(
        np.zeros((3, 3)),
        dims=("omega", "wave_direction"),
        coords={"omega": w, "wave_direction": wd},
    )
    q = jt.io.qtf_from_capytaine(da, zero, zero)
    np.testing.assert_allclose(np.asarray(q.beta), [-0.5, 0.0, 0.5], atol=1e-15)
    np.testing.assert_allclose(np.asarray(q.values[0]), fx)


def test_irregular_sailing_drift_and_force(barge_2a):
    q = jt.drift.QTF.symmetric(omega=W, beta=B, **_table())
    w = np.linspace(0.3, 3.0, 541)
    sea = jt.waves.Jonswap(hs=2.4, tp=7.0)
    jt.waves.check_frequency_grid(w, 7.0)
    S = sea(w)
    # zero speed: 2 ∫ S F dω of the stationary QTF
    F0 = jt.drift.irregular_sailing_drift(q, w, S, 0.0, 0.0)
    ref = jt.waves.mean_drift(w, S, jax.vmap(lambda x: q(x, 0.0)[0])(jnp.asarray(w)))
    assert float(F0[0]) == pytest.approx(float(ref), rel=1e-12)
    # with speed into head seas the surge drift grows (added resistance rises with speed)
    assert float(jt.drift.irregular_sailing_drift(q, w, S, 0.0, 2.0)[0]) < float(F0[0]) < 0
    f = jt.forces.IrregularWaveDriftForce(
        qtf=q, spectrum=sea, omega=w, scales=jt.presets.barge2_scales()
    )
    m = model(barge_2a, external=f)
    e = jt.equilibria(
        m, n_grid=401
    )  # a 541-point drift integral per residual: a coarser bracket scan
    assert np.all(e.residual < 1e-12)


def _np_slopes(x, y, ends):
    """Node slopes of the whole table along the last axis (plain NumPy reference)."""
    h = np.diff(x)
    h0, h1 = h[:-1], h[1:]
    mid = (h0**2 * y[..., 2:] - h1**2 * y[..., :-2] + (h1**2 - h0**2) * y[..., 1:-1]) / (
        h0 * h1 * (h0 + h1)
    )
    if ends == "periodic":
        a, b = h[-1], h[0]
        first = last = (a**2 * y[..., 1] - b**2 * y[..., -2] + (b**2 - a**2) * y[..., 0]) / (
            a * b * (a + b)
        )
    elif ends == "flat":
        first = last = np.zeros_like(y[..., 0])
    else:
        first, last = (y[..., 1] - y[..., 0]) / h[0], (y[..., -1] - y[..., -2]) / h[-1]
    return np.concatenate([first[..., None], mid, last[..., None]], axis=-1)


def _np_hermite(x, y, xq, ends):
    """Textbook cubic Hermite on the interval of ``xq`` from the full slope table."""
    m = _np_slopes(x, y, ends)
    xq = np.clip(xq, x[0], x[-1])
    i = np.clip(np.searchsorted(x, xq, side="right") - 1, 0, x.size - 2)
    h = x[i + 1] - x[i]
    t = (xq - x[i]) / h
    return (
        (2 * t**3 - 3 * t**2 + 1) * y[..., i]
        + (t**3 - 2 * t**2 + t) * h * m[..., i]
        + (-2 * t**3 + 3 * t**2) * y[..., i + 1]
        + (t**3 - t**2) * h * m[..., i + 1]
    )


def test_hermite_weights_equal_the_full_slope_interpolant():
    """The four-row weight polynomials of `hermite` (tables built in the traced program) and
    of `HermiteAxis` (built with NumPy) give the textbook interpolant built from the whole
    table of slopes, for every end rule, at random points including the end intervals and
    beyond the ends."""
    from jaxtow._interp import ENDS, HermiteAxis, hermite

    rng = np.random.default_rng(5)
    x = np.sort(rng.uniform(-2.0, 3.0, 9))
    y = rng.normal(size=(2, x.size))
    y[:, -1] = y[:, 0]  # a periodic table repeats its first value
    xq = np.concatenate([rng.uniform(-3.0, 4.0, 200), x])
    for ends in ENDS:
        got = np.asarray(
            jax.jit(jax.vmap(lambda q: hermite(jnp.asarray(x), jnp.asarray(y), q, ends)))(xq)
        )
        want = np.stack([_np_hermite(x, y, q, ends) for q in xq])
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-13, err_msg=ends)
        axis = HermiteAxis(x, ends)
        got = np.asarray(jax.jit(jax.vmap(lambda q: axis(jnp.asarray(y), q)))(xq))
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-13, err_msg=ends)
    with pytest.raises(ValueError, match="'ends'"):
        hermite(jnp.asarray(x), jnp.asarray(y), 0.0, "natural")


def test_hermite_is_exact_for_quadratics_and_c1_across_the_periodic_seam():
    from jaxtow._interp import hermite

    x = jnp.asarray(np.sort(np.random.default_rng(1).uniform(0.0, 5.0, 12)))
    quad = 0.3 * x**2 - 1.2 * x + 0.7
    xq = jnp.linspace(x[1], x[-2], 50)  # interior intervals: three-point slopes are exact
    got = jax.jit(jax.vmap(lambda q: hermite(x, quad, q)))(xq)
    np.testing.assert_allclose(got, 0.3 * xq**2 - 1.2 * xq + 0.7, rtol=0, atol=1e-12)
    a = jnp.linspace(-jnp.pi, jnp.pi, 13)
    y = jnp.cos(a) + 0.5 * jnp.sin(2 * a)
    f = jax.jit(jax.vmap(jax.value_and_grad(lambda q: hermite(a, y, q, "periodic"))))
    eps = 1e-7
    (v0, v1), (d0, d1) = f(jnp.array([-jnp.pi + eps, jnp.pi - eps]))
    np.testing.assert_allclose(v0, v1, atol=1e-6)
    np.testing.assert_allclose(d0, d1, atol=1e-5)


def test_local_interpolant_equals_full_slope_tables():
    """QTF.__call__ touches only the entries it needs; it must equal the tensor-product
    Hermite interpolant built from the full slope tables (module docstring), here in plain
    NumPy."""

    def full(q, omega, beta):
        w = np.concatenate([[0.0], np.asarray(q.omega)])
        v = np.moveaxis(np.concatenate([np.zeros_like(q.values[:, :1]), q.values], axis=1), 1, -1)
        a = _np_hermite(w, v, max(omega, 0.0), "flat")  # (3, nβ)
        if q.periodic:
            beta = np.mod(beta + np.pi, 2 * np.pi) - np.pi
        return _np_hermite(np.asarray(q.beta), a, beta, "periodic" if q.periodic else "one_sided")

    rng = np.random.default_rng(3)
    w = np.sort(rng.uniform(0.1, 2.5, 20))
    b = np.radians(np.linspace(0.0, 180.0, 10))
    vals = rng.normal(size=(3, w.size, b.size))
    vals[1:, :, [0, -1]] = 0.0
    W, Bq = rng.uniform(0.0, 3.0, 300), rng.uniform(-4.0, 4.0, 300)
    for q in (
        jt.drift.QTF.symmetric(omega=w, beta=b, fx=vals[0], fy=vals[1], nz=vals[2]),
        jt.drift.QTF(omega=w, beta=b, fx=vals[0], fy=vals[1], nz=vals[2]),
    ):
        np.testing.assert_allclose(
            np.asarray(jax.jit(jax.vmap(q))(W, Bq)),
            np.stack([full(q, x, y) for x, y in zip(W, Bq)]),
            rtol=0,
            atol=1e-13,
        )

"""Wave spectra and irregular seas (thesis eqs 2.29, 2.30, 2.49, 3.1-3.5)."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from helpers import assert_png_has_content

from jaxtow import waves

# log-spaced to 60 rad/s: the ω⁻⁵ tail of m2 beyond 60 rad/s is < 0.01 % of m2
OMEGA = np.geomspace(0.05, 60.0, 40001)


def test_table_3_2_physical_tp_range():
    lo, hi = waves.physical_tp_range(5.0)
    assert (round(float(lo), 2), round(float(hi), 2)) == (8.06, 12.25)
    lo, hi = waves.physical_tp_range(2.4)
    assert (round(float(lo), 2), round(float(hi), 2)) == (5.59, 8.49)


@pytest.mark.parametrize("tp", [6.0, 10.0, 14.0])
def test_tp_t1_t2_relations_gamma_3_3(tp):
    """Tp = 1.199 T1 = 1.287 T2 for γ = 3.3 (thesis eq. 3.4); reached to 0.05 %."""
    p = waves.spectral_periods(OMEGA, waves.jonswap(OMEGA, hs=3.0, tp=tp))
    assert tp / float(p.t1) == pytest.approx(1.199, rel=5e-4)
    assert tp / float(p.t2) == pytest.approx(1.287, rel=5e-4)
    assert float(p.tp) == pytest.approx(tp, rel=1e-3)


def test_normalised_jonswap_hs_exact():
    for gamma in (1.0, 3.3, 7.0):
        S = waves.jonswap(OMEGA, hs=2.4, tp=7.0, gamma=gamma, normalise=True)
        assert 4 * np.sqrt(float(waves.spectral_moment(OMEGA, S, 0))) == pytest.approx(
            2.4, abs=1e-6
        )
    # the thesis (unnormalised) form is close to Hs for γ = 3.3, but with γ = 1 it is not
    # Pierson-Moskowitz (4√m0 = 0.81 Hs); pierson_moskowitz is normalised analytically
    S = waves.jonswap(OMEGA, hs=2.4, tp=7.0)
    assert 4 * np.sqrt(float(waves.spectral_moment(OMEGA, S, 0))) == pytest.approx(2.4, rel=2e-3)
    S = waves.jonswap(OMEGA, hs=2.4, tp=7.0, gamma=1.0)
    assert 4 * np.sqrt(float(waves.spectral_moment(OMEGA, S, 0))) == pytest.approx(
        2.4 * 0.81, rel=1e-2
    )
    S = waves.pierson_moskowitz(OMEGA, hs=2.4, tp=7.0)
    assert 4 * np.sqrt(float(waves.spectral_moment(OMEGA, S, 0))) == pytest.approx(2.4, rel=1e-5)
    assert float(waves.spectral_periods(OMEGA, S).tp) == pytest.approx(7.0, rel=1e-3)


def test_spectrum_modules_match_functions_and_units():
    sea = waves.Jonswap(hs=5.0, tp=10.0)
    np.testing.assert_array_equal(sea(OMEGA), waves.jonswap(OMEGA, hs=5.0, tp=10.0))
    assert float(sea.omega_peak) == pytest.approx(2 * np.pi / 10)
    assert float(waves.hz_to_omega(1.0)) == pytest.approx(2 * np.pi)
    assert float(waves.period_to_omega(10.0)) == pytest.approx(0.2 * np.pi)
    # S(f) df = S(ω) dω
    f = OMEGA / (2 * np.pi)
    Sf = waves.spectrum_per_hz(sea(OMEGA))
    assert float(jnp.trapezoid(Sf, f)) == pytest.approx(
        float(jnp.trapezoid(sea(OMEGA), OMEGA)), rel=1e-12
    )
    assert float(waves.jonswap(jnp.array([0.0, -1.0]), hs=1.0, tp=5.0).sum()) == 0.0


def test_mean_drift_of_constant_qtf_is_p_hs2_over_8():
    S = waves.jonswap(OMEGA, hs=5.0, tp=10.0, normalise=True)
    P = -1234.5 * np.ones_like(OMEGA)
    assert float(waves.mean_drift(OMEGA, S, P)) == pytest.approx(-1234.5 * 5.0**2 / 8, rel=1e-10)
    # damping matrices integrate the same way, per entry
    B = np.ones((OMEGA.size, 3, 3)) * np.arange(9).reshape(3, 3)
    np.testing.assert_allclose(
        waves.mean_drift_damping(OMEGA, S, B), np.arange(9).reshape(3, 3) * 25 / 8, rtol=1e-10
    )


def test_irregular_integrals_differentiable_and_vmappable():
    P = -500.0 * (1 + 0.3 * np.tanh(OMEGA - 0.8))

    def drift(hs, tp):
        return waves.mean_drift(OMEGA, waves.jonswap(OMEGA, hs=hs, tp=tp), P)

    for arg in (0, 1):
        g = float(jax.grad(drift, argnums=arg)(4.0, 9.0))
        h = 1e-5
        args_p, args_m = [4.0, 9.0], [4.0, 9.0]
        args_p[arg] += h
        args_m[arg] -= h
        fd = (float(drift(*args_p)) - float(drift(*args_m))) / (2 * h)
        assert g == pytest.approx(fd, rel=1e-6)
    tps = jnp.linspace(5.0, 15.0, 11)
    vals = jax.vmap(lambda tp: drift(4.0, tp))(tps)
    assert vals.shape == (11,) and np.all(np.isfinite(vals))


def test_slow_drift_spectrum_newman():
    S = waves.jonswap(OMEGA, hs=5.0, tp=10.0)
    P = -800.0 * np.ones_like(OMEGA)
    mu = jnp.array([0.0, 0.05, 0.2])
    SF = waves.slow_drift_force_spectrum(OMEGA, S, P, mu)
    # μ = 0: 8 P² ∫ S² dω; decreasing with μ for a single-peaked spectrum
    assert float(SF[0]) == pytest.approx(8 * 800.0**2 * float(jnp.trapezoid(S**2, OMEGA)), rel=1e-9)
    assert float(SF[0]) > float(SF[1]) > float(SF[2]) > 0


def _uniform_grid(n=2048, wmax=3.0):
    dw = wmax / n
    return dw * np.arange(1, n + 1), dw


def test_synthesised_record_reproduces_m0_and_spectrum():
    w, dw = _uniform_grid()
    S = waves.jonswap(w, hs=4.0, tp=9.0)
    m0 = float(waves.spectral_moment(w, S, 0))
    T = 2 * np.pi / dw  # one full repeat period
    t = np.linspace(
        0, T, 8192, endpoint=False
    )  # exactly one repeat period, Nyquist 2π·8192/T/2 > 3 rad/s
    key = jax.random.PRNGKey(7)
    z1 = np.asarray(waves.synthesise_elevation(key, w, S, t))
    z2 = np.asarray(waves.synthesise_elevation(key, w, S, t))
    np.testing.assert_array_equal(z1, z2)  # reproducible from the seed
    # deterministic amplitudes: exact variance over the repeat period (rectangle rule for m0)
    assert np.var(z1) == pytest.approx(float(np.sum(S) * dw), rel=1e-9)
    assert np.var(z1) == pytest.approx(m0, rel=1e-3)
    # Gaussian sea (Rayleigh amplitudes): band-averaged periodogram within chi² bounds
    z = np.asarray(
        waves.synthesise_elevation(jax.random.PRNGKey(3), w, S, t, random_amplitudes=True)
    )
    X = np.fft.rfft(z) / z.size
    Pw = 2 * np.abs(X[1 : w.size + 1]) ** 2 / dw  # periodogram at ω_i [m² s/rad]
    K = 16  # bins per band → chi² with 2K dof
    band = Pw[: (w.size // K) * K].reshape(-1, K).mean(1)
    target = np.asarray(S)[: (w.size // K) * K].reshape(-1, K).mean(1)
    ok = target > 1e-3 * target.max()
    ratio = band[ok] / target[ok]
    # 99.9 % two-sided bounds of chi²(32)/32 are about 0.42 and 1.85
    assert np.all((ratio > 0.42) & (ratio < 1.85)), ratio
    assert np.var(z) == pytest.approx(m0, rel=0.1)


def test_synthesised_drift_force_mean():
    w, dw = _uniform_grid(1024, 2.5)
    S = waves.jonswap(w, hs=4.0, tp=9.0)
    P = -300.0 - 100.0 * w
    t = np.linspace(0, 2 * np.pi / dw, 4096, endpoint=False)
    F = np.asarray(waves.synthesise_drift_force(jax.random.PRNGKey(1), w, S, P, t))
    target = float(jnp.sum(2 * S * P * dw))  # rectangle rule on the synthesis grid
    assert np.mean(F) == pytest.approx(target, rel=1e-6)
    assert np.all(F <= 0)


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(hs=0.0, tp=8.0), "hs"),
        (dict(hs=-1.0, tp=8.0), "hs"),
        (dict(hs=2.0, tp=0.0), "tp"),
        (dict(hs=2.0, tp=8.0, gamma=0.5), "gamma"),
        (dict(hs=np.nan, tp=8.0), "hs"),
    ],
)
def test_invalid_sea_state(kwargs, name):
    with pytest.raises(ValueError, match=repr(name)):
        waves.Jonswap(**kwargs)
    with pytest.raises(ValueError, match=repr(name)):
        waves.jonswap(OMEGA, **kwargs)


def test_invalid_frequency_grid():
    waves.check_frequency_grid(OMEGA, 10.0)  # fine
    with pytest.raises(ValueError, match="'omega'.*resolve"):
        waves.check_frequency_grid(np.linspace(0.1, 3.0, 20), 10.0)
    with pytest.raises(ValueError, match="'omega'.*cover"):
        waves.check_frequency_grid(np.linspace(0.5, 3.0, 2000), 10.0)
    with pytest.raises(ValueError, match="'omega'"):
        waves.check_frequency_grid(np.array([1.0, 0.5, 2.0]), 10.0)
    with pytest.raises(ValueError, match="'hs'"):
        waves.physical_tp_range(-2.0)


def test_wave_figures(tmp_path):
    from jaxtow.plotting import save
    from jaxtow.plotting.waves import plot_against_tp, plot_spectra

    w = np.linspace(0.1, 2.5, 300)
    spectra = {
        "JONSWAP 3.3": waves.jonswap(w, hs=5, tp=10),
        "PM": waves.pierson_moskowitz(w, hs=5, tp=10),
    }
    ax = plot_spectra(w, spectra)
    lines = ax.get_lines()
    assert [ln.get_label() for ln in lines] == list(spectra)
    for ln, S in zip(lines, spectra.values()):  # the curves drawn are the spectra given
        np.testing.assert_array_equal(ln.get_ydata(), np.asarray(S))
    save(ax, tmp_path / "s.png")
    tps = np.linspace(5, 15, 21)
    vals = jax.vmap(
        lambda tp: waves.mean_drift(
            OMEGA, waves.jonswap(OMEGA, hs=5.0, tp=tp), -500.0 * np.ones_like(OMEGA)
        )
    )(tps)
    ax = plot_against_tp(tps, {"mean surge drift": vals}, hs=5.0, ylabel="N")
    np.testing.assert_array_equal(ax.get_lines()[0].get_ydata(), np.asarray(vals))
    lo, hi = (float(t) for t in waves.physical_tp_range(5.0))  # the shaded band is eq. 3.5's range
    band = ax.patches[0]
    assert band.get_x() == pytest.approx(lo) and band.get_x() + band.get_width() == pytest.approx(
        hi
    )
    save(ax, tmp_path / "t.png")
    assert_png_has_content(tmp_path / "s.png")
    assert_png_has_content(tmp_path / "t.png")

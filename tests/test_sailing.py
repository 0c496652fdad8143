"""Forward speed in the drift: Aranha's finite form, its linearisation (the wave-drift
damping of thesis eqs 2.40-2.41), the yaw-rate column, the tug speed as a model parameter and
the validity flags that travel with the results (docs/model.md section 8)."""

import math

import jax
import jax.numpy as jnp
import numpy as np
import pytest

import jaxtow as jt
from jaxtow._units import G
from jaxtow.drift import QTF, aranha, sailing_drift, wave_drift_damping, yaw_rate_damping

W = np.linspace(0.2, 2.0, 37)
BH = np.radians(np.arange(0.0, 180.1, 7.5))


def analytic(w, b):
    """A smooth analytic zero-speed drift (Fx, Fy, Nz) per ζa² of a symmetric hull."""
    return jnp.stack(
        [
            -1000.0 * jnp.cos(b) * (1 + 0.3 * w) * jnp.tanh(w),
            -800.0 * jnp.sin(b) * w**2 / (1 + w),
            5000.0 * jnp.sin(2 * b) * w**2 * jnp.exp(-0.3 * w),
        ]
    )


def printed_damping(F, dFw, dFb, w, b):
    """Thesis eqs 2.40-2.41 as printed (β measured jaxtow's way, docs/model.md section 8)."""
    c, s = math.cos(b), math.sin(b)
    col_u = w / G * (w * c * dFw - 2 * s * dFb + 4 * c * F)
    col_v = w / G * (w * s * dFw + 2 * c * dFb + 4 * s * F)
    return np.stack([col_u, col_v], axis=-1)


@pytest.mark.parametrize("w,b", [(0.4, 0.0), (0.9, 0.3), (1.3, -0.7), (1.8, 2.5)])
def test_damping_from_finite_form_equals_printed_equations(w, b):
    F = np.asarray(analytic(w, b))
    dFw = np.asarray(jax.jacfwd(analytic, 0)(w, b))
    dFb = np.asarray(jax.jacfwd(analytic, 1)(w, b))
    B = np.asarray(wave_drift_damping(analytic, w, b))
    ref = printed_damping(F, dFw, dFb, w, b)
    np.testing.assert_allclose(B[:, :2], ref, rtol=1e-10, atol=1e-10 * np.max(np.abs(ref)))
    assert np.all(B[:, 2] == 0.0)  # no sectional moments: no yaw-rate column


def test_damping_of_a_table_equals_printed_equations():
    Wg, Bg = np.meshgrid(W, BH, indexing="ij")
    v = np.moveaxis(
        np.asarray(jax.vmap(jax.vmap(analytic))(jnp.asarray(Wg), jnp.asarray(Bg))), -1, 0
    )
    q = QTF.symmetric(omega=W, beta=BH, fx=v[0], fy=v[1], nz=v[2])
    parts = jax.jit(lambda w, b: (q(w, b), jax.jacfwd(q, 0)(w, b), jax.jacfwd(q, 1)(w, b)))
    damping = jax.jit(lambda w, b: wave_drift_damping(q, w, b))
    for w, b in ((0.55, 0.1), (1.21, -0.4), (1.9, 1.0)):
        F, dFw, dFb = (np.asarray(a) for a in parts(w, b))
        ref = printed_damping(F, dFw, dFb, w, b)
        B = np.asarray(damping(w, b))
        np.testing.assert_allclose(B[:, :2], ref, rtol=1e-10, atol=1e-10 * np.max(np.abs(ref)))


def test_constant_short_wave_qtf_gives_exact_speed_factor():
    b = np.radians(np.arange(-90.0, 90.1, 15.0))
    F = -1234.0
    shape = (W.size, b.size)
    q = QTF(omega=W, beta=b, fx=np.full(shape, F), fy=np.zeros(shape), nz=np.zeros(shape))
    for w in (0.6, 1.0, 1.7):
        for u in (0.5, 1.5, 3.0):  # ω_e stays inside the constant part of the table
            got = float(sailing_drift(q, w, 0.0, u)[0])
            assert got == pytest.approx(F * (1 + 4 * w * u / G), rel=1e-13)
            lin = float(sailing_drift(q, w, 0.0, u, form="linear")[0])
            assert lin == pytest.approx(F * (1 + 4 * w * u / G), rel=1e-13)


def test_finite_form_is_linear_form_to_first_order():
    """error(U) = |F_aranha − F_linear| = O(U²): halving U divides it by four."""
    for w, b in ((0.8, 0.2), (1.4, -0.5)):
        errs = []
        for U in (0.1, 0.05, 0.025, 0.0125):
            u, v = U * 0.9, U * 0.3
            fa = np.asarray(aranha(analytic, w, b, u, v))
            B = np.asarray(wave_drift_damping(analytic, w, b))
            fl = np.asarray(analytic(w, b)) + B[:, :2] @ np.array([u, v])
            errs.append(np.max(np.abs(fa - fl)))
        ratios = np.array(errs[:-1]) / np.array(errs[1:])
        np.testing.assert_allclose(ratios, 4.0, rtol=0.05)


def test_thesis_form_counts_the_shift_twice():
    """In head seas on a table linear in ω (F = a ω), the encounter shift δ = ω²u/g enters the
    finite form once, a(ω + δ), and the thesis form twice, a(ω + 2δ) (plus the 4ωu/g factor
    in both, to first order)."""
    a = -700.0
    shape = (W.size, BH.size)
    Wg = np.broadcast_to(W[:, None], shape)
    q = QTF.symmetric(omega=W, beta=BH, fx=a * Wg, fy=np.zeros(shape), nz=np.zeros(shape))
    w, u = 1.0, 0.02
    d = w**2 * u / G
    fa = float(sailing_drift(q, w, 0.0, u)[0])
    ft = float(sailing_drift(q, w, 0.0, u, form="thesis")[0])
    base = a * w * (1 + 4 * w * u / G)
    assert (fa - base) / (a * d) == pytest.approx(1.0, rel=0.05)
    assert (ft - base) / (a * d) == pytest.approx(2.0, rel=0.05)
    with pytest.raises(ValueError, match="'form'"):
        sailing_drift(q, w, 0.0, u, form="double")


def test_overtaken_waves_are_flagged():
    flags = jt.drift.sailing_validity(2.0, math.pi, 5.0)
    assert float(flags["encounter_frequency"]) < 0
    assert not bool(flags["encounter_positive"]) and not bool(flags["tau_ok"])
    ok = jt.drift.sailing_validity(0.8, 0.0, 1.0)
    assert bool(ok["encounter_positive"]) and bool(ok["tau_ok"])


# --- yaw-rate column -----------------------------------------------------------------------

XS, WX = np.polynomial.legendre.leggauss(48)  # sections over the length, x ∈ [−L/2, L/2]
LENGTH = 80.0


def section_density(x, w, b, breadth):
    """Synthetic slender hull: the drift density (f_x, f_y) [N/m per ζa²] of the section at x,
    with a frequency peak that moves along the hull (the moments are not separable), and the
    sectional yaw density −y f_x, of order the half breadth."""
    w0 = 0.8 + 0.5 * x / LENGTH
    shape = jnp.exp(-((w - w0) ** 2) / 0.2) * (1.2 + x / LENGTH)
    fx = -20.0 * jnp.cos(b) * shape
    fy = -15.0 * jnp.sin(b) * shape * (1 + 0.4 * x / LENGTH)
    yaw = -0.5 * breadth * 12.0 * jnp.sin(b) * jnp.cos(b) * shape
    return fx, fy, yaw


WF = np.linspace(0.2, 2.0, 91)
BF = np.radians(np.arange(0.0, 180.1, 2.5))


def hull_tables(breadth):
    """QTF with sectional moments of the synthetic hull, by Gauss quadrature over x, on a
    table fine enough (Δω = 0.02 rad/s, Δβ = 2.5°) for 1e-3 derivatives of its interpolant."""
    x = XS * LENGTH / 2
    wq = WX * LENGTH / 2
    Wg, Bg = np.meshgrid(WF, BF, indexing="ij")
    fx, fy, yaw = (
        np.asarray(a) for a in section_density(x[None, None], Wg[..., None], Bg[..., None], breadth)
    )
    Fx, Fy = fx @ wq, fy @ wq
    Nz = (x * fy + yaw) @ wq
    sec = ((x * fx) @ wq, (x * fy) @ wq, (x**2 * fy) @ wq)
    return QTF.symmetric(omega=WF, beta=BF, fx=Fx, fy=Fy, nz=Nz, sectional=sec)


def turning_drift(w, b, r, breadth):
    """Drift of the synthetic hull turning at yaw rate r: Aranha's finite form applied to each
    section with its own sway velocity r x, integrated over the length."""
    x = XS * LENGTH / 2
    wq = WX * LENGTH / 2

    def one(xi):
        def table(we, be):
            fx, fy, yaw = section_density(xi, we, be, breadth)
            return jnp.stack([fx, fy, xi * fy + yaw])

        return aranha(table, w, b, 0.0, r * xi)

    return jax.vmap(one)(jnp.asarray(x)).T @ wq


def test_yaw_rate_column_matches_a_turning_hull():
    """The slender-body column equals the finite-difference change of the sectional
    finite form with the yaw rate (1e-3: the only approximation is the table interpolant).
    The reference is the dimensional drift [N/m², N m/m²] per unit yaw rate [rad/s] of a
    hull whose sections move at r x [m/s]: equality is also the check of the column's units."""
    breadth = 0.0  # slender limit: the construction's own assumption
    q = hull_tables(breadth)
    for w, b in ((0.7, 0.3), (1.1, -0.6), (0.9, 1.2)):
        col = np.asarray(yaw_rate_damping(q, w, b))
        h = 1e-5
        fd = np.asarray(
            (turning_drift(w, b, h, breadth) - turning_drift(w, b, -h, breadth)) / (2 * h)
        )
        np.testing.assert_allclose(col, fd, rtol=1e-3, atol=1e-3 * np.max(np.abs(fd)))


def test_yaw_rate_column_symmetry_and_slender_limit():
    q = hull_tables(breadth=8.0)
    for w, b in ((0.7, 0.3), (1.2, 0.8)):
        plus = np.asarray(yaw_rate_damping(q, w, b))
        minus = np.asarray(yaw_rate_damping(q, w, -b))
        assert plus[0] == pytest.approx(-minus[0], rel=1e-9)  # B_16 odd about head seas
        assert plus[2] == pytest.approx(minus[2], rel=1e-9)  # B_66 even
    head = np.asarray(yaw_rate_damping(q, 0.9, 0.0))
    assert abs(head[0]) < 1e-9 * np.max(np.abs(np.asarray(q.sectional)))
    # B_26 ≈ B_62: the gap is the −y f_x yaw of the sections, linear in the breadth
    gaps = []
    for breadth in (8.0, 0.8, 0.08):
        qb = hull_tables(breadth)
        B = np.asarray(wave_drift_damping(qb, 0.9, 0.4))
        gaps.append(abs(B[1, 2] - B[2, 1]) / abs(B[1, 2]))
    assert gaps[2] < 1e-2
    np.testing.assert_allclose(np.array(gaps[:-1]) / np.array(gaps[1:]), 10.0, rtol=0.05)


def test_yaw_rate_column_enters_the_drift_linearly_and_can_be_switched_off():
    q = hull_tables(breadth=0.0)
    w, b, r = 0.9, 0.3, 0.01
    with_r = np.asarray(sailing_drift(q, w, b, 1.0, 0.2, r))
    without = np.asarray(sailing_drift(q, w, b, 1.0, 0.2, r, yaw_rate=False))
    np.testing.assert_allclose(
        with_r - without, r * np.asarray(yaw_rate_damping(q, w, b)), rtol=1e-12
    )
    no_table = QTF(omega=WF, beta=q.beta, fx=q.values[0], fy=q.values[1], nz=q.values[2])
    assert not no_table.has_sectional
    assert np.all(np.asarray(yaw_rate_damping(no_table, w, b)) == 0.0)


def test_steady_form_equals_the_force_along_steady_states_and_drops_only_the_yaw_rate_term():
    """The equilibria evaluate the wave force in its `steady` form (no yaw-rate column): at
    r = 0 it equals the full force, and so does its derivative along the heading (what the
    implicit derivative of the bisected root uses); at r != 0 they differ by exactly the
    yaw-rate term."""
    from jaxtow._dynamics import force_breakdown
    from jaxtow._equilibrium import equilibrium_kinematics, hull_forces_at_heading

    q = hull_tables(breadth=8.0)
    m = jt.presets.barge2_wave_model("2a", qtf=q)
    ext = m.external
    assert ext.yaw_rate and not ext.steady().yaw_rate
    comb = jt.forces.CombinedForce((ext, ext))
    assert not any(f.yaw_rate for f in comb.steady().forces)

    def full(psi):  # the hull forces with the force as it is, no steady form
        fb = force_breakdown(0.0, equilibrium_kinematics(psi), m)
        return fb.manoeuvring + fb.coupling + fb.external

    psi = jnp.array([-0.4, 0.1, 0.7])
    steady = jax.jit(
        jax.vmap(lambda p: jax.jvp(lambda q: hull_forces_at_heading(q, m), (p,), (1.0,)))
    )
    whole = jax.jit(jax.vmap(lambda p: jax.jvp(full, (p,), (1.0,))))
    (f_steady, d_steady), (f_full, d_full) = steady(psi), whole(psi)
    np.testing.assert_array_equal(np.asarray(f_steady), np.asarray(f_full))
    np.testing.assert_allclose(np.asarray(d_steady), np.asarray(d_full), rtol=1e-14, atol=0)
    y = jnp.array([0.9, -0.1, 0.05, 2.6, 0.0, 0.1])
    gap = np.asarray(ext(0.0, y, m) - ext.steady()(0.0, y, m))
    U, L = ext.scales.u_tug, ext.scales.length
    r = 0.05 * U / L
    want = ext.scales.nondimensional(ext.zeta_a**2 * r * yaw_rate_damping(q, ext.omega, -0.1))
    assert np.all(gap != 0.0)
    np.testing.assert_allclose(gap, np.asarray(want), rtol=1e-9)


# --- tug speed as a model parameter ---------------------------------------------------------


def calm_model(version="2a", u_tug=2.0, l0=2.5):
    return jt.TowModel(
        vessel=jt.presets.VESSELS[f"barge_{version}"](),
        towline=jt.presets.default_towline(l0=l0, u_tug=u_tug),
        scales=jt.presets.barge2_scales(u_tug),
    )


def test_at_tug_speed_equals_rebuilding_the_model():
    base = calm_model(u_tug=2.0)
    for U in (1.2, 2.9):
        moved, rebuilt = jt.at_tug_speed(base, U), calm_model(u_tug=U)
        assert float(moved.towline.EA) == pytest.approx(float(rebuilt.towline.EA), rel=1e-14)
        assert float(moved.scales.u_tug) == U
    with pytest.raises(ValueError, match="u_tug"):
        jt.at_tug_speed(jt.TowModel(vessel=base.vessel, towline=base.towline), 2.0)
    with pytest.raises(ValueError, match="u_tug"):
        jt.sweep(base, {"u_tug": [1.0, -1.0]})


@pytest.mark.slow  # default-suite time
def test_sweep_over_tug_speed_equals_rebuilt_models_calm():
    base = calm_model("2a", l0=2.5)
    speeds = np.array([1.0, 1.5, 3.0])
    ds = jt.sweep(base, {"u_tug": speeds, "l0": [1.0, 2.5]}, n_grid=401)
    for i, U in enumerate(speeds):
        ref = jt.sweep(calm_model("2a", u_tug=U), {"l0": [1.0, 2.5]}, n_grid=401)
        for k in ("max_real", "psi", "tension"):
            np.testing.assert_allclose(
                ds[k].values[i], ref[k].values, rtol=1e-12, atol=1e-12, equal_nan=True
            )
    assert ds["u_tug"].attrs["units"] == "m s-1"


@pytest.mark.slow
def test_tug_speed_gradient_equals_finite_differences():
    m = jt.presets.barge2_wave_model("2a", l0=2.5, omega=1.3, zeta_a=1.25)
    names, _, grad, _, _ = jt.design.sensitivity_arrays(m, ["u_tug", "external.omega"])
    g = float(grad[0, 0])

    @jax.jit
    def abscissa(U):
        mm = jt.with_parameters(m, u_tug=U)
        return jt.design.spectral_abscissa(mm)

    h = 1e-5
    fd = float((abscissa(2.0 + h) - abscissa(2.0 - h)) / (2 * h))
    assert g == pytest.approx(fd, abs=1e-6 * max(1.0, abs(fd)))
    assert abs(g) > 1e-4  # the speed matters in waves


# --- validity travels with the results ------------------------------------------------------


@pytest.mark.slow
def test_wave_sweep_carries_validity_and_tug_speed_sweep_matches_rebuilt():
    """One wave kernel (chunks of two points) serves both sweeps: the (U_tug, ζa) map crosses
    U/(ω ζa) = 1, and each U_tug row equals the model rebuilt at that speed."""
    opts = dict(n_grid=201, chunk_size=2)
    base = jt.presets.barge2_wave_model("2a", l0=2.5, omega=1.0, zeta_a=1.25)
    speeds, amps = np.array([1.5, 2.5]), np.array([1.0, 2.0])
    ds = jt.sweep(base, {"u_tug": speeds, "external.zeta_a": amps}, **opts)
    for name in ("froude_ok", "no_separation", "tau_ok", "encounter_positive", "line_taut"):
        assert f"validity_{name}" in ds
    assert "physics_valid" in ds
    straight = ds["found"].values & (np.abs(ds["psi"].values) < 1e-6)
    sep = speeds[:, None, None] / (1.0 * amps[None, :, None])  # |U| = U_tug at equilibrium
    got = ds["validity_separation_ratio"].values
    np.testing.assert_allclose(got[straight], np.broadcast_to(sep, got.shape)[straight], rtol=1e-9)
    flag = ds["validity_no_separation"].values[straight]
    assert np.array_equal(flag, (np.broadcast_to(sep, got.shape) < 1.0)[straight])
    assert flag.any() and (~flag).any()  # the map crosses the limit
    for i, U in enumerate(speeds):
        m = jt.presets.barge2_wave_model("2a", l0=2.5, omega=1.0, zeta_a=1.25, u_tug=U)
        ref = jt.sweep(m, {"external.zeta_a": amps}, **opts)
        for k in ("max_real", "psi", "tension"):
            np.testing.assert_allclose(
                ds[k].values[i], ref[k].values, rtol=1e-12, atol=1e-12, equal_nan=True
            )


@pytest.mark.slow
def test_wind_sweep_carries_validity():
    wind = jt.forces.WindForce(
        load=jt.presets.barge2_resistance().wind, speed=10.0, scales=jt.presets.barge2_scales()
    )
    m = jt.TowModel(
        vessel=jt.presets.barge_2b(),
        towline=jt.presets.default_towline(l0=2.5),
        external=wind,
        scales=jt.presets.barge2_scales(),
    )
    ds = jt.sweep(m, {"l0": [2.0, 2.5], "u_tug": [1.0, 2.0]}, n_grid=201)
    assert {"validity_relative_wind_speed", "validity_line_taut", "physics_valid"} <= set(ds)
    straight = ds["found"].values & (np.abs(ds["psi"].values) < 1e-6)
    rel = ds["validity_relative_wind_speed"].values  # head wind plus the tow's own speed
    U = np.broadcast_to(ds["u_tug"].values[None, :, None], rel.shape)
    np.testing.assert_allclose(rel[straight], 10.0 + U[straight], rtol=1e-9)


def test_irregular_and_wind_forces_have_validity():
    m = jt.presets.barge2_irregular_model("2a", hs=2.4, tp=7.0)
    y = jnp.array([1.0, 0.0, 0.0, 2.6, 0.0, 0.0])
    flags = jt.validity(m, y)
    assert (
        bool(flags["line_taut"]) and bool(flags["froude_ok"]) and bool(flags["encounter_positive"])
    )
    assert float(flags["separation_ratio"]) == pytest.approx(
        2.0 / (2 * math.pi / 7.0 * 1.2), rel=1e-12
    )
    assert float(flags["overtaken_energy"]) == 0.0
    wind = jt.forces.WindForce(
        load=jt.presets.barge2_resistance().wind, speed=10.0, scales=jt.presets.barge2_scales()
    )
    both = jt.forces.CombinedForce((m.external, wind))
    f = both.validity(y)
    assert float(f["relative_wind_speed"]) == pytest.approx(12.0, rel=1e-12)
    assert "no_separation" in f
    slack = jt.validity(m, y.at[3].set(2.0))
    assert not bool(slack["line_taut"]) and not bool(jt.all_valid(slack))


@pytest.mark.slow  # default-suite time
def test_simulation_carries_validity():
    m = jt.presets.barge2_wave_model("2a", l0=2.5, omega=1.6, zeta_a=1.25)
    sim = jt.simulate(m, jt.initial_state(m, psi0=0.1), t1=5.0, n_save=11)
    assert sim.validity["physics_valid"].shape == (11,)
    assert bool(np.all(sim.validity["froude_ok"]))


def test_map_figures_hatch_the_invalid_region():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from jaxtow.plotting.waves_report import plot_heading_map, plot_max_real_map

    x, y = np.linspace(1, 3, 5), np.linspace(0.3, 2, 6)
    X, Y = np.meshgrid(x, y, indexing="ij")
    z = 0.1 * (X - 2)
    invalid = X / Y > 2.0  # like U/(ω ζa) > 1

    def hatches(fig):
        return [h for ax in fig.axes for c in ax.collections for h in getattr(c, "hatches", [])]

    fig = plot_max_real_map(x, y, z, invalid=invalid, xlabel="U_tug [m/s]")
    assert "xx" in hatches(fig) and fig.axes[0].get_legend() is not None
    plt.close(fig)
    fig = plot_max_real_map(x, y, z, invalid=np.zeros_like(invalid))
    assert "xx" not in hatches(fig)
    plt.close(fig)
    fig = plot_heading_map(x, y, z, "U_tug [m/s]", invalid=invalid)
    assert "xx" in hatches(fig)
    plt.close(fig)


@pytest.mark.slow  # default-suite time
def test_forms_shift_a_motion_peak_once_or_twice():
    """A QTF with a motion peak at ω0 = 1 rad/s: against the absolute frequency, Aranha's form
    moves the peak down by about δ = ω0² u/g, the thesis's reading by about 2δ, the linear
    form by less than δ (it does not move ω, only tilts the curve)."""
    w = np.linspace(0.05, 2.5, 200)
    shape = (w.size, BH.size)
    fx = -(3e5 * np.exp(-((w - 1.0) ** 2) / 0.05) + 1e5 * w**2 / (1 + w**2))[:, None]
    q = QTF.symmetric(
        omega=w, beta=BH, fx=np.broadcast_to(fx, shape), fy=np.zeros(shape), nz=np.zeros(shape)
    )
    u = 0.3
    r = jt.studies.sailing_forms(
        q, speed=u, omega_peak_grid=np.arange(0.8, 1.1, 0.0002), omega=np.linspace(0.2, 3, 120)
    )
    d = 1.0 * u / G
    assert r["zero_speed"]["peak_omega"] == pytest.approx(1.0, abs=0.005)
    assert r["aranha"]["peak_shift"] == pytest.approx(-d, rel=0.2)
    assert r["thesis"]["peak_shift"] == pytest.approx(-2 * d, rel=0.2)
    assert abs(r["linear"]["peak_shift"]) < d
    assert r["aranha"]["operating_speed"] is None
    table = jt.studies.forms_table({"synthetic": r})
    assert "| synthetic | thesis |" in table


@pytest.mark.heavy  # reproduction scale: `pytest -m heavy` (not in CI's time budget)
def test_forms_comparison_in_the_docs_is_reproducible():
    """docs/data/sailing_forms.json (docs/model.md section 8) equals a fresh run of
    ``python benchmarks/sailing_forms.py`` on the stored panel QTFs."""
    import json

    from helpers import ROOT as root, benchmark_script

    fresh = benchmark_script("sailing_forms").compute()
    stored = json.loads((root / "docs" / "data" / "sailing_forms.json").read_text())
    assert set(fresh) == set(stored)
    for hull, res in stored.items():
        for form, row in res.items():
            for k, v in row.items():
                got = fresh[hull][form][k]
                if v is None:
                    assert got is None
                else:
                    assert got == pytest.approx(v, rel=1e-9, abs=1e-9), (hull, form, k)
    # the thesis's reading counts the shift twice: its peak moves further than Aranha's
    for hull in ("Barge 1 (box), panel", "Barge 2 (raked), panel"):
        assert stored[hull]["thesis"]["peak_shift"] < stored[hull]["aranha"]["peak_shift"] < 0


def test_panel_database_carries_the_yaw_rate_column():
    from pathlib import Path

    path = Path(__file__).resolve().parents[1] / "benchmarks" / "data" / "barge2_raked_far_field.nc"
    q = jt.io.load_qtf(path)
    assert q.has_sectional
    B = np.asarray(wave_drift_damping(q, 1.0, math.radians(15.0)))
    assert np.all(np.isfinite(B)) and np.all(B[:, 2] != 0.0)
    head = np.asarray(yaw_rate_damping(q, 1.0, 0.0))
    assert abs(head[0]) < 1e-9 * np.max(np.abs(np.asarray(q.sectional)))  # B_16 odd
    m = jt.presets.barge2_wave_model("2a", qtf=q)
    assert bool(jt.validity(m, jnp.array([1.0, 0, 0, 2.6, 0, 0]))["yaw_rate_damping"])

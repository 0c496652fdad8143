"""Strip theory as a JAX program end to end: `motions`, `added_resistance` and
`hull_coefficients` under `jax.jit` / `equinox.filter_jit`; gradients with respect to every
offset, the principal dimensions, the speed and the frequencies against central
differences; `jax.vmap` over hull variants; one section table reused across speeds and
headings; bad hulls refused with the parameter named."""

from __future__ import annotations

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
import pytest

import jaxtow as jt
from jaxtow import strip as S

L, B, T = 3.0, 0.3, 0.1875
OMEGA = jnp.array([3.6, 4.3, 5.2])
HEAD = jnp.array([0.0])
U = 0.2 * np.sqrt(9.81 * L)  # Fn 0.2
LOADING = jt.Loading(z_g=0.0, radii=jnp.array([0.35 * B, 0.25 * L, 0.25 * L]))
SMALL = dict(n_stations=11, n_points=8)


def hull(b=B, t=T, alpha=1.0):
    return S.wigley(L, b, t, alpha=alpha, **SMALL)


def heave_energy(h, omega=OMEGA, u=U):
    """A smooth measure of the heave response: Σ |η₃|² over the frequencies, on the
    geometric section grid (``n_frequencies=None``) that a traced call plans too, so that
    the derivative and the differences see the same plan."""
    m = S.motions(h, omega, HEAD, u, loading=LOADING, n_frequencies=None)
    return jnp.sum(jnp.abs(m.rao[:, 0, 1]) ** 2)


def central(f, x, h):
    return (f(x + h) - f(x - h)) / (2 * h)


@pytest.mark.slow
def test_motions_and_resistance_run_under_jit():
    """`eqx.filter_jit(motions)` equals the eager call on the same section grid (the
    geometric plan, ``n_frequencies=None``: traced frequencies have no distinct values to
    plan from); `added_resistance` and `hull_coefficients` compile too."""
    h = hull()
    eager = S.motions(h, OMEGA, HEAD, U, loading=LOADING, n_frequencies=None)
    jitted = eqx.filter_jit(S.motions)(h, OMEGA, HEAD, U, loading=LOADING, n_frequencies=None)
    np.testing.assert_allclose(np.asarray(jitted.rao), np.asarray(eager.rao), rtol=1e-6, atol=1e-9)
    r = eqx.filter_jit(S.added_resistance)(h, OMEGA, HEAD, U, loading=LOADING)
    assert np.all(np.isfinite(np.asarray(r.resistance)))
    c = eqx.filter_jit(S.hull_coefficients)(h, OMEGA, HEAD)
    assert np.all(np.isfinite(np.asarray(c.added_mass)))


@pytest.mark.heavy  # minutes on 2 cores: pytest -m heavy
@pytest.mark.slow
def test_gradient_in_the_beam_under_jit_equals_central_differences():
    """d/dB of the heave response of a Wigley hull built from its dimensions, by
    `jax.jit(jax.grad(...))`, equals central differences; so do d/dT and d/dα."""
    for arg, x0, step in ((0, B, 1e-4), (1, T, 1e-4), (2, 1.0, 1e-4)):

        def f(x, arg=arg):
            dims = [B, T, 1.0]
            dims[arg] = x
            return heave_energy(hull(*dims))

        g = float(jax.jit(jax.grad(f))(x0))
        fd = float(central(f, x0, step))
        assert g == pytest.approx(fd, rel=2e-4, abs=1e-8), (arg, g, fd)


@pytest.mark.slow
def test_gradient_in_every_offset_equals_central_differences():
    """`eqx.filter_grad` over a `Hull`: the derivative in single offsets equals central
    differences of the same offset."""
    h = hull()
    grads = eqx.filter_grad(heave_energy)(h)
    for i, j in ((3, 0), (5, 3), (7, 6)):
        e = jnp.zeros_like(h.y).at[i, j].set(1.0)

        def f(s, e=e):
            return heave_energy(eqx.tree_at(lambda k: k.y, h, h.y + s * e))

        fd = float(central(f, 0.0, 1e-5))
        assert float(grads.y[i, j]) == pytest.approx(fd, rel=2e-4, abs=1e-8), (i, j)


@pytest.mark.slow
def test_gradient_in_the_speed_and_the_frequencies():
    """d/dU and d/dω_i of the heave response equal central differences on one section table
    (what is differentiated is the physics at fixed sections; a plan that moved with U would
    add the interpolation's own change to the differences)."""
    h = hull()
    table = S.section_table(
        h, S.plan_sections(h, jnp.array([3.4, 5.4]), HEAD, [0.9 * U, 1.1 * U], n_frequencies=40)
    )

    def f(omega=OMEGA, u=U):
        m = S.motions(h, omega, HEAD, u, loading=LOADING, sections=table)
        return jnp.sum(jnp.abs(m.rao[:, 0, 1]) ** 2)

    gu = float(jax.grad(lambda u: f(u=u))(U))
    fd = float(central(lambda u: f(u=u), U, 1e-4))
    assert gu == pytest.approx(fd, rel=1e-4), (gu, fd)
    gw = np.asarray(jax.grad(lambda w: f(omega=w))(OMEGA))
    for i in range(3):
        e = jnp.zeros(3).at[i].set(1.0)
        fdi = float(central(lambda s, e=e: f(omega=OMEGA + s * e), 0.0, 1e-4))
        assert gw[i] == pytest.approx(fdi, rel=1e-4, abs=1e-8), (i, gw[i], fdi)


@pytest.mark.slow
def test_vmap_over_hull_variants_equals_one_by_one():
    """`jax.vmap` over the beam of Wigley hulls gives each hull's own RAOs."""
    bs = jnp.array([0.28, 0.3, 0.33])

    def rao(b):
        return S.motions(hull(b), OMEGA, HEAD, U, loading=LOADING, n_frequencies=None).rao

    batched = np.asarray(jax.vmap(rao)(bs))
    for k, b in enumerate(bs):
        np.testing.assert_allclose(batched[k], np.asarray(rao(b)), rtol=1e-6, atol=1e-10)


@pytest.mark.heavy  # minutes on 2 cores: pytest -m heavy
@pytest.mark.slow
def test_one_section_table_serves_three_speeds_and_thirteen_headings(monkeypatch):
    """The section solve is a value: one `SectionTable` planned over 3 speeds × 13 headings
    serves `motions` and `added_resistance` at each (no section is solved again), and
    agrees with each call's own solve within the table's interpolation."""
    h = hull()
    beta = jnp.linspace(0.0, jnp.pi, 13)
    speeds = [0.0, 0.5 * U, U]
    table = S.section_table(h, S.plan_sections(h, OMEGA, beta, speeds, n_frequencies=60))
    own = {u: S.motions(h, OMEGA, beta, u, loading=LOADING, n_frequencies=60).rao for u in speeds}

    def refuse(*a, **k):
        raise AssertionError("a section was solved again")

    monkeypatch.setattr(S._motions, "section_table", refuse)
    for u in speeds:
        reused = S.motions(h, OMEGA, beta, u, loading=LOADING, sections=table).rao
        scale = float(jnp.max(jnp.abs(own[u])))
        np.testing.assert_allclose(np.asarray(reused), np.asarray(own[u]), atol=2e-3 * scale)
        r = S.added_resistance(h, OMEGA, beta, u, loading=LOADING, sections=table)
        assert np.all(np.isfinite(np.asarray(r.resistance)))


@pytest.mark.parametrize(
    "change, parameter",
    [
        (lambda h: eqx.tree_at(lambda k: k.z, h, -h.z), "z"),  # heights positive downwards
        (lambda h: eqx.tree_at(lambda k: (k.y, k.z), h, (h.y[:, ::-1], h.z[:, ::-1])), "y, z"),
    ],
)
def test_bad_hulls_are_refused_with_the_parameter_named(change, parameter):
    """Heights positive downwards and offsets given keel-first (which gave an added mass of
    −11.5 and NaN) are refused by the rules: eagerly, and under jit by `equinox.error_if`."""
    h = change(hull())
    with pytest.raises(jt.ParameterError, match=parameter.split(",")[0]) as e:
        S.Hull(h.x, h.dx, h.y, h.z)
    assert e.value.parameter == parameter
    with pytest.raises(Exception, match="must"):
        eqx.filter_jit(S.motions)(h, OMEGA, HEAD, U, loading=LOADING)

"""Property-based tests (hypothesis) on random valid calm-water tows: symmetries, limits and
residuals that must hold for every model, not only the thesis's barges.

The models are Barge 2a's derivatives scaled by up to ±30 % (each on its own), any
attachment point x_p' in [0, 1], l0' in [0.3, 5] and EA' over three decades. One model
structure: the compiled kernels are shared by every example.
"""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

import jaxtow as jt

hypothesis = pytest.importorskip("hypothesis", reason="the test extra's hypothesis is missing")
from hypothesis import HealthCheck, given, settings, strategies as st  # noqa: E402

SETTINGS = settings(
    max_examples=8,
    deadline=None,
    derandomize=True,  # the same examples on every run: a CI failure reproduces locally
    suppress_health_check=[HealthCheck.too_slow],
)
BASE = jt.presets.barge_2a()
SCALED = ("Yv", "Yr", "Nv", "Nr", "Yvvv", "Nvvv", "R0")


@st.composite
def tows(draw):
    scale = {n: draw(st.floats(0.7, 1.3)) for n in SCALED}
    vessel = jt.presets.barge_2a()
    vessel = jt.with_parameters(
        jt.TowModel(vessel=vessel, towline=jt.presets.default_towline()),
        **{n: float(getattr(BASE, n)) * s for n, s in scale.items()},
    ).vessel
    towline = jt.Towline(
        l0=draw(st.floats(0.3, 5.0)),
        xp=draw(st.floats(0.0, 1.0)),
        EA=10 ** draw(st.floats(1.0, 4.0)),
    )
    return jt.TowModel(vessel=vessel, towline=towline)


@SETTINGS
@given(tows())
def test_equilibria_are_mirror_symmetric_and_solve_the_equations(model):
    """With the towline on the centreline the tow is symmetric port-starboard: the set of
    equilibrium headings is its own mirror image; each found equilibrium is a zero of the
    equations of motion, and its Jacobian is the mirror of its twin's."""
    eqs = jt.equilibria(model)
    psi = np.sort(np.asarray(eqs.psi))
    assert psi.size >= 1
    np.testing.assert_allclose(psi, -psi[::-1], atol=1e-9)
    for y in np.asarray(eqs.state):
        f = jt.vector_field(0.0, jnp.asarray(y), model)
        assert float(jnp.max(jnp.abs(f))) < 1e-8
    lam = [np.sort_complex(np.asarray(jt.eigenvalues(model, y))) for y in eqs.state]
    for a, b in zip(lam, lam[::-1]):  # mirrored equilibria: the same spectrum
        np.testing.assert_allclose(a, b, atol=1e-7 * max(1.0, float(np.max(np.abs(a)))))


@SETTINGS
@given(tows(), st.floats(-1.0, 1.0), st.floats(-0.3, 0.3))
def test_jacobian_by_autodiff_equals_finite_differences(model, psi, v):
    y = jnp.array([np.cos(psi), v, 0.05 * v, float(model.towline.l0) * 1.01, 0.1 * v, psi])
    J = np.asarray(jt.jacobian(model, y))
    h = 1e-6
    fd = np.stack(
        [
            (
                np.asarray(jt.vector_field(0.0, y.at[i].add(h), model))
                - np.asarray(jt.vector_field(0.0, y.at[i].add(-h), model))
            )
            / (2 * h)
            for i in range(6)
        ],
        axis=1,
    )
    np.testing.assert_allclose(J, fd, rtol=1e-5, atol=1e-5 * max(1.0, np.abs(J).max()))


@SETTINGS
@given(tows())
def test_stiff_limit_and_spectral_abscissa(model):
    """The spectral abscissa (the sweeps' kernel) equals LAPACK's largest real part at every
    equilibrium; straight behind in calm water the towline carries the hull's resistance
    (the surge balance at ψ = 0, v = r = 0: T' = R0')."""
    eqs = jt.equilibria(model)
    for y in eqs.state:
        J = jt.jacobian(model, y)
        ref = float(np.max(np.real(np.linalg.eigvals(np.asarray(J)))))
        got = float(jt.spectral_abscissa(J))
        assert abs(got - ref) <= 1e-9 * max(1.0, float(np.max(np.abs(np.asarray(J)))) * 10)
    straight = np.argmin(np.abs(np.asarray(eqs.psi)))
    if abs(float(eqs.psi[straight])) < 1e-9:
        assert float(eqs.tension[straight]) == pytest.approx(float(model.vessel.R0), rel=1e-6)


@SETTINGS
@given(tows(), st.floats(0.3, 5.0))
def test_sweep_point_equals_the_eager_answer(model, l0):
    """A sweep's value at a grid point equals the eager computation on the model with that
    value: `with_parameters` and the vmapped kernel change nothing else."""
    arrays = jt.sweep_arrays(
        model, {"l0": np.array([l0])}, jt.SweepSolver(n_grid=2001, max_roots=8)
    )
    eqs = jt.equilibria(jt.with_parameters(model, l0=l0))
    found = arrays["found"][0]
    np.testing.assert_allclose(
        np.sort(arrays["psi"][0][found]), np.sort(np.asarray(eqs.psi)), atol=1e-10
    )
    assert jax.numpy.isfinite(arrays["max_real"][0][found]).all()

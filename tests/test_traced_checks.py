"""Every public numerical entry point names a bad parameter in every way a user calls it:
eagerly, under `jax.jit`, under `equinox.filter_jit` and under `jax.vmap`; and with
``throw=False`` under a plain `jax.jit`, the result code of `jaxtow.parameter_status` holds
the same sentence (the documented way to see a check from inside `jax.jit`, where XLA puts
its own "CpuCallback error" line above jaxtow's)."""

from __future__ import annotations

import functools

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
import pytest

import jaxtow as jt

Y = jnp.array([1.0, 0.0, 0.0, 1.05, 0.0, 0.0])
W = jnp.linspace(0.2, 2.0, 40)
EA_MESSAGE = "parameter 'EA' must be > 0 and finite"


@functools.cache
def _qtf():
    return jt.tow.load("barge2a").drift.qtf()


@functools.cache
def _resistance_inputs():
    tow = jt.tow.load("barge2a")
    return tow.resistance(), tow.sea_states[0]


def _model():
    return jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.Towline(l0=1.0, EA=50.0, xp=0.5))


def _with_ea(x):
    return eqx.tree_at(lambda m: m.towline.EA, _model(), x)


def _model_case(f):
    """A case varying the model's EA: ``f(model, throw=...)``."""
    return (lambda x, throw=True: f(_with_ea(x), throw=throw)), 50.0, jnp.nan, EA_MESSAGE, True


# (entry point, good EA, bad EA, message, supports throw=False)
CASES = {
    "vector_field": _model_case(lambda m, throw: jt.vector_field(0.0, Y, m, throw=throw)),
    "force_breakdown": _model_case(
        lambda m, throw: jt.force_breakdown(0.0, Y, m, throw=throw).total
    ),
    "validity": _model_case(lambda m, throw: jt.validity(m, Y, throw=throw)["line_taut"]),
    "heading_residual": _model_case(lambda m, throw: jt.heading_residual(0.1, m, throw=throw)),
    "jacobian": _model_case(lambda m, throw: jt.jacobian(m, Y, throw=throw)),
    "eigenvalues": _model_case(lambda m, throw: jt.eigenvalues(m, Y, throw=throw)),
    "max_real_eigenvalue": _model_case(lambda m, throw: jt.max_real_eigenvalue(m, Y, throw=throw)),
    "routh_hurwitz_stable": _model_case(
        lambda m, throw: jt.routh_hurwitz_stable(m, Y, throw=throw)
    ),
    "stability": _model_case(lambda m, throw: jt.stability(m, Y[None], throw=throw).max_real),
    "equilibria_fixed": _model_case(
        lambda m, throw: jt.equilibria_fixed(m, n_grid=101, max_roots=3, throw=throw).psi
    ),
    "analytic_equilibria": _model_case(lambda m, throw: jt.analytic_equilibria(m, throw=throw).psi),
    "simulate": _model_case(
        lambda m, throw: jt.simulate(m, Y, 2.0, n_save=5, solver="tsit5", throw=throw).ys
    ),
    "Jonswap": (
        lambda x, throw=True: jt.waves.Jonswap(hs=2.0, tp=x)(W, throw=throw),
        8.0,
        0.0,
        "parameter 'tp' must be > 0 and finite",
        True,
    ),
    "jonswap": (
        lambda x, throw=True: jt.waves.jonswap(W, hs=x, tp=8.0),
        2.0,
        jnp.nan,
        "parameter 'hs' must be > 0 and finite",
        False,
    ),
    # following seas (beta = pi) at 25 m/s: the vessel outruns the 0.5 rad/s waves
    "sailing_drift": (
        lambda x, throw=True: jt.drift.sailing_drift(_qtf(), 0.5, jnp.pi, x, throw=throw),
        2.0,
        25.0,
        "the vessel overtakes the waves",
        False,
    ),
    "irregular_sailing_drift": (
        lambda x, throw=True: jt.drift.irregular_sailing_drift(
            _qtf(), W, jt.waves.jonswap(W, hs=2.4, tp=8.2), jnp.pi, x, throw=throw
        ),
        2.0,
        6.0,
        "the vessel overtakes the waves",
        False,
    ),
    "resistance (speed)": (
        lambda x, throw=True: (
            jt.resistance.resistance(*_resistance_inputs(), speed=x, throw=throw).resistance
        ),
        1.0,
        jnp.nan,
        "parameter 'speed' must be finite",
        False,
    ),
    "resistance (sea state)": (
        lambda x, throw=True: (
            jt.resistance.resistance(
                _resistance_inputs()[0],
                eqx.tree_at(lambda s: s.hs, _resistance_inputs()[1], x),
                1.0,
                throw=throw,
            ).resistance
        ),
        5.0,
        -1.0,
        "parameter 'hs' must be >= 0 and finite",
        False,
    ),
    "required_pull (sea state)": (
        lambda x, throw=True: (
            jt.resistance.required_pull(
                _resistance_inputs()[0], eqx.tree_at(lambda s: s.hs, _resistance_inputs()[1], x)
            ).bollard_pull
        ),
        5.0,
        jnp.nan,
        "parameter 'hs' must be >= 0 and finite",
        False,
    ),
    "pierson_moskowitz": (
        lambda x, throw=True: jt.waves.pierson_moskowitz(W, hs=2.0, tp=x),
        8.0,
        -1.0,
        "parameter 'tp' must be > 0 and finite",
        False,
    ),
}


def _call(mode: str, f, good, bad):
    if mode == "eager":
        return f(jnp.asarray(bad))
    if mode == "jax.jit":
        return jax.jit(f)(jnp.asarray(bad))
    if mode == "eqx.filter_jit":
        return eqx.filter_jit(f)(jnp.asarray(bad))
    return jax.vmap(f)(jnp.asarray([good, bad]))


MODES = ("eager", "jax.jit", "eqx.filter_jit", "vmap")
#: Under an eager `jax.vmap` these run operation by operation, batched: 6-10 s each on 2
#: cores. Their vmap case runs in the slow suite; their other three stay here, and the other
#: functions' vmap cases too.
HEAVY_VMAP = {
    "irregular_sailing_drift",
    "required_pull (sea state)",
    "resistance (speed)",
    "stability",
}


@pytest.mark.parametrize(
    ("name", "mode"),
    [
        pytest.param(n, m, marks=pytest.mark.slow) if m == "vmap" and n in HEAVY_VMAP else (n, m)
        for n in sorted(CASES)
        for m in MODES
    ],
)
def test_bad_parameter_is_named(name, mode):
    f, good, bad, message, _ = CASES[name]
    with pytest.raises(Exception) as info:
        jax.block_until_ready(_call(mode, f, good, bad))
    text = str(info.value)
    if mode == "eager":  # a ValueError whose first words are jaxtow's sentence
        assert issubclass(info.type, ValueError)  # jaxtow.ParameterError names the parameter
        assert text.startswith(message)
    else:
        assert message in text
    # and the good value runs, so the error is the parameter's, not the harness's
    out = _call(mode, f, good, good)
    assert np.all(np.isfinite(np.asarray(jax.tree_util.tree_leaves(out)[0]) + 0.0))


@pytest.mark.parametrize("name", sorted(n for n in CASES if CASES[n][4] and n != "Jonswap"))
def test_result_code_under_plain_jit(name):
    """``throw=False`` compiles no check; `parameter_status` returned beside the output gives
    the same sentence, eagerly, after the jitted call."""
    f = CASES[name][0]

    @jax.jit
    def run(ea):
        return f(ea, throw=False), jt.parameter_status(_with_ea(ea))

    _, status = run(jnp.asarray(jnp.nan))
    assert not bool(status.ok)
    assert status.message() == EA_MESSAGE
    with pytest.raises(ValueError, match=r"parameter 'EA' must be > 0 and finite"):
        status.raise_if_invalid()
    _, status = run(jnp.asarray(50.0))
    assert bool(status.ok) and status.message() is None


def test_result_code_of_a_spectrum_and_a_batch():
    @jax.jit
    def run(tp):
        s = jt.waves.Jonswap(hs=2.0, tp=tp)
        return s(W, throw=False), jt.parameter_status(s)

    _, status = run(jnp.asarray(0.0))
    assert status.message() == "parameter 'tp' must be > 0 and finite"
    codes = jax.vmap(lambda ea: jt.parameter_status(_with_ea(ea)).code)(
        jnp.array([50.0, -1.0, 50.0])
    )
    assert np.asarray(codes).tolist()[0] == 0 and np.asarray(codes)[1] > 0
    assert np.asarray(codes)[2] == 0


def test_throw_false_adds_no_host_callback():
    """The unchecked program holds no callback (JAX's persistent cache stores it); the checked
    one does."""
    m = _model()
    checked = jax.jit(lambda m: jt.vector_field(0.0, Y, m)).lower(m).as_text()
    unchecked = jax.jit(lambda m: jt.vector_field(0.0, Y, m, throw=False)).lower(m).as_text()
    assert "callback" in checked
    assert "callback" not in unchecked


def test_simulate_auto_solver_of_a_traced_model_is_named():
    with pytest.raises(ValueError, match=r"parameter 'solver': 'auto' chooses"):
        jax.jit(lambda ea: jt.simulate(_with_ea(ea), Y, 1.0).ys)(jnp.asarray(50.0))


def test_overtaken_waves_with_throw_false_are_flagged():
    """``throw=False`` takes the drift of overtaken waves as zero; `sailing_validity` flags
    them, and the resistance budget and its dataset carry the overtaken share."""
    q = _qtf()
    F = jax.jit(lambda u: jt.drift.sailing_drift(q, 0.5, jnp.pi, u, throw=False))(25.0)
    assert np.all(np.asarray(F) == 0.0)
    flags = jt.drift.sailing_validity(0.5, jnp.pi, 25.0, 0.0)
    assert not bool(flags["encounter_positive"])
    assert float(flags["encounter_frequency"]) == pytest.approx(0.5 - 0.25 * 25.0 / 9.80665)
    tow = jt.tow.load("barge2a")
    sea = eqx.tree_at(lambda s: s.wave_angle, tow.sea_states[1], jnp.asarray(jnp.pi))
    speeds, tps = jnp.array([2.0, 6.0]), jnp.array([8.2])
    budget = jt.resistance.resistance_grid(tow.resistance(), sea, speeds, tps)
    ds = jt.io.resistance_dataset(budget, speeds, tps)
    over = ds["overtaken_energy"].values[:, 0]
    assert over[0] == 0.0 and 0.01 < over[1] < 0.1  # 3.7 % of m0 outrun at 6 m/s
    assert ds["waves_complete"].values[:, 0].tolist() == [True, False]

"""The persistent cache of traced programs: a later process reads a program back instead of
tracing it, gets the same numbers, and never reads one that does not fit its call."""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
import pytest

import jaxtow as jt
from jaxtow import _program_cache as pc


@pytest.fixture
def cache(tmp_path):
    pc.set_folder(tmp_path / "programs")
    yield tmp_path / "programs"
    pc.set_folder(None)


def _new_process(monkeypatch):
    """What a new process has: nothing loaded, and nothing may be traced for export."""
    pc._LOADED.clear()

    def refuse(*_):
        raise AssertionError("the program was traced again instead of read back")

    monkeypatch.setattr(pc, "_export", refuse)


def _files(cache, suffix):
    return sorted(p.name for p in cache.rglob(f"*.{suffix}"))


def test_equilibria_are_read_back_equal_in_a_new_process(cache, monkeypatch):
    """The equilibria program (an Equinox module in and out, Equinox's MISSING marker in
    its tree) is stored once and read back, with the same numbers to the bit."""
    model = jt.tow.load("barge2a").model()
    pc.set_folder(None)
    direct = jt.padded_equilibria(model, n_grid=201)  # the cache off: the program as it is
    pc.set_folder(cache)
    first = jt.padded_equilibria(model, n_grid=201)
    assert len(_files(cache, "program")) == 1
    _new_process(monkeypatch)
    again = jt.padded_equilibria(model, n_grid=201)
    for a, b, c in zip(jax.tree.leaves(direct), jax.tree.leaves(first), jax.tree.leaves(again)):
        np.testing.assert_array_equal(np.asarray(a), np.asarray(b))
        np.testing.assert_array_equal(np.asarray(b), np.asarray(c))
    assert type(again) is type(direct)
    assert again.compact().psi.shape == direct.compact().psi.shape  # MISSING came back as it


def test_the_key_holds_the_static_options_and_the_shapes(cache, monkeypatch):
    @pc.persistent
    @eqx.filter_jit
    def f(x, *, power):
        return {"y": x**power}

    x3 = jnp.arange(3.0)
    np.testing.assert_array_equal(f(x3, power=2)["y"], x3**2)
    np.testing.assert_array_equal(f(x3, power=3)["y"], x3**3)  # another static option
    np.testing.assert_array_equal(f(jnp.arange(4.0), power=2)["y"], jnp.arange(4.0) ** 2)
    np.testing.assert_array_equal(f(x3.astype(jnp.float32), power=2)["y"], x3**2)
    assert len(_files(cache, "program")) == 4
    _new_process(monkeypatch)
    np.testing.assert_array_equal(f(x3 + 1, power=3)["y"], (x3 + 1) ** 3)  # read back
    with pytest.raises(AssertionError, match="traced again"):
        f(x3, power=5)  # a call it has not seen is traced (here: refused)


class _Scale(eqx.Module):
    """A user's own model part: defined outside jaxtow, pickled by its name only."""

    factor: float = eqx.field(static=True)


def test_a_users_own_class_in_the_static_part_is_never_keyed(cache):
    """A class from outside jaxtow and the libraries the code digest covers would be keyed
    by its name, so an edited definition would find the old program: such a call is not
    cached at all."""

    @pc.persistent
    @eqx.filter_jit
    def scaled(scale, x):
        return scale.factor * x

    np.testing.assert_array_equal(scaled(_Scale(2.0), jnp.arange(2.0)), [0.0, 2.0])
    assert _files(cache, "program") == [] and _files(cache, "skip") == []
    assert pc._key("f", jt.presets.barge_2b(), None, []) is not None  # jaxtow's own: keyed


def test_a_program_with_a_host_callback_runs_as_it_is(cache):
    """A run-time check (`equinox.error_if`, a host callback) cannot be exported: the call
    runs directly, raises as it should, and a marker keeps later runs from trying again."""

    @pc.persistent
    @eqx.filter_jit
    def checked(x):
        return eqx.error_if(x, x < 0, "x must be >= 0")

    assert float(checked(jnp.asarray(2.0))) == 2.0
    assert len(_files(cache, "skip")) == 1 and _files(cache, "program") == []
    with pytest.raises(Exception, match="x must be >= 0"):
        checked(jnp.asarray(-1.0))


def test_calls_under_a_trace_and_with_the_cache_off_go_straight_to_the_function(tmp_path):
    @pc.persistent
    @eqx.filter_jit
    def square(x):
        return x**2

    assert float(jax.grad(square)(3.0)) == 6.0  # no cache: direct
    pc.set_folder(tmp_path / "programs")
    try:
        assert float(jax.grad(square)(jnp.asarray(3.0))) == 6.0  # traced argument: direct
        assert not list((tmp_path / "programs").rglob("*.program"))
        assert float(square(jnp.asarray(3.0))) == 9.0
        assert len(list((tmp_path / "programs").rglob("*.program"))) == 1
    finally:
        pc.set_folder(None)


def test_a_new_code_digest_starts_an_empty_folder(cache, monkeypatch):
    @pc.persistent
    @eqx.filter_jit
    def double(x):
        return 2 * x

    double(jnp.arange(2.0))
    (old,) = [p for p in cache.iterdir() if p.is_dir()]
    monkeypatch.setattr(pc, "code_digest", lambda: "another")
    double(jnp.arange(2.0))
    assert [p.name for p in cache.iterdir() if p.is_dir()] == ["another"]
    assert not old.exists()


def test_the_compile_cache_switch_turns_it_on_beside_its_folder(tmp_path, monkeypatch):
    monkeypatch.setattr(jax.config, "update", lambda *_: None)  # JAX's own cache stays off
    try:
        jt.enable_compile_cache(tmp_path / "xla")
        assert pc._FOLDER == tmp_path / "xla-programs"
    finally:
        pc.set_folder(None)


def test_the_advice_scans_of_every_parameter_are_one_program(cache):
    """`design.stable_value` scans each parameter with one program whose parameter is an
    index argument: the scans of two parameters store one program, not one each (a Python
    index would be a static part of the key)."""
    from jaxtow import design

    model = jt.tow.load("barge2a").model()
    names = ("l0", "xp")
    design.stable_value(model, "l0", 0.625, 10.0, n=5, among=names)
    design.stable_value(model, "xp", 0.0, 1.0, n=5, among=names)
    assert len(_files(cache, "program")) == 1


def test_the_skeg_advice_runs_the_calm_water_programs(cache):
    """The skeg advice's hulls (the vessel with a skeg span's derivatives) are typed as the
    tow file's vessel, so their equilibria and stability run the calm-water model's two
    programs rather than two of their own."""
    from jaxtow.studies._advice import _with_skegs
    from jaxtow.studies._conditions import equilibria_and_stability

    tow = jt.tow.load("barge2a")
    model = tow.model()
    equilibria_and_stability(model)
    assert len(_files(cache, "program")) == 2
    L, T = tow.scales.length, tow.scales.draft
    skegs = eqx.tree_at(
        lambda m: m.vessel, model, _with_skegs(model.vessel, L, T, 2, 7.6, 3.1, 0.0)
    )
    assert float(skegs.vessel.Yv) != float(model.vessel.Yv)
    equilibria_and_stability(skegs)
    assert len(_files(cache, "program")) == 2


def test_programs_compile_with_the_options_and_without_them_where_xla_refuses(cache, monkeypatch):
    """Programs from the cache are compiled with `COMPILER_OPTIONS`; an option the
    installed XLA does not know makes them compile with XLA's defaults instead (the same
    numbers), and no later program tries it again."""
    model = jt.tow.load("barge2a").model()
    seen = []
    jit = jax.jit

    def spy(fn, **kw):
        seen.append(kw.get("compiler_options"))
        return jit(fn, **kw)

    monkeypatch.setattr(pc.jax, "jit", spy)
    good = jt.padded_equilibria(model, n_grid=201)
    assert pc.COMPILER_OPTIONS and seen[-1] == pc.COMPILER_OPTIONS
    pc._LOADED.clear()
    monkeypatch.setattr(pc, "COMPILER_OPTIONS", {"xla_option_jaxtow_never_heard_of": True})
    monkeypatch.setattr(pc, "_OPTIONS_OK", True)
    fallback = jt.padded_equilibria(model, n_grid=201)
    assert pc._OPTIONS_OK is False
    for a, b in zip(jax.tree.leaves(good), jax.tree.leaves(fallback)):
        np.testing.assert_allclose(np.asarray(a), np.asarray(b), rtol=1e-12, atol=1e-14)
    pc._LOADED.clear()
    again = jt.padded_equilibria(model, n_grid=201)
    assert seen[-1] is None  # the defaults from then on
    np.testing.assert_array_equal(np.asarray(again.psi), np.asarray(fallback.psi))


# ---------------------------------------------------------------- eager calls as one program


def _wave_inputs():
    q = jt.presets.database("barge2")
    w = np.linspace(0.2, 3.0, 120)
    return q, w, jt.waves.Jonswap(hs=2.4, tp=7.0)(w)


def test_an_eager_call_is_one_program_reused_for_new_values():
    """A public function called eagerly compiles one program (its operations one by one
    compiled dozens), and another value of the same shapes compiles nothing."""
    from helpers import count_compiles

    jax.clear_caches()
    model = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.Towline(l0=2.5, xp=0.5, EA=100.0))
    y = np.array([1.0, 0.0, 0.0, 2.5, 0.0, 0.0])
    with count_compiles() as first:
        jt.eigenvalues(model, y)
    with count_compiles() as again:
        jt.eigenvalues(model, y + 0.01)
        jt.eigenvalues(jt.with_parameters(model, xp=0.4), y)
    assert first.compiles == 1, first
    assert again.compiles == 0, again
    with jax.disable_jit(), count_compiles() as op_by_op:  # how it ran before
        before = jt.eigenvalues(model, y + 0.01)
    assert op_by_op.compiles > 20, op_by_op
    np.testing.assert_allclose(jt.eigenvalues(model, y + 0.01), before, rtol=1e-12, atol=1e-12)


@pytest.mark.slow  # the operations one by one: 20 s on 2 cores
def test_eager_programs_equal_the_operations_run_one_by_one():
    """The programs give the numbers the same operations give one by one (to round-off)."""
    model = jt.TowModel(vessel=jt.presets.barge_2b(), towline=jt.Towline(l0=2.5, xp=0.5, EA=100.0))
    eqs = jt.equilibria(model)
    q, w, S = _wave_inputs()
    calls = {
        "vector_field": lambda: jt.vector_field(0.0, eqs.state[1] + 0.01, model),
        "jacobian": lambda: jt.jacobian(model, eqs.state[1]),
        "eigenvalues": lambda: jt.eigenvalues(model, eqs.state[0]),
        "max_real_eigenvalue": lambda: jt.max_real_eigenvalue(model, eqs.state[0], "routh"),
        "stability": lambda: jt.stability(model, eqs.state).max_real,
        "routh_hurwitz_stable": lambda: jt.routh_hurwitz_stable(model, eqs.state[2]),
        "heading_residual": lambda: jt.heading_residual(0.1, model),
        "analytic_equilibria": lambda: jt.analytic_equilibria(model).state,
        "qtf": lambda: q(0.9, 0.3),
        "sailing_drift": lambda: jt.drift.sailing_drift(q, 0.9, 0.2, u=2.0, v=0.3, r=0.01),
        "wave_drift_damping": lambda: jt.drift.wave_drift_damping(q, omega=0.9, beta=0.2),
        "encounter_frequency": lambda: jt.drift.encounter_frequency(w, 0.2, 2.0, 0.3),
        "irregular_sailing_drift": lambda: jt.drift.irregular_sailing_drift(q, w, S, 0.2, 2.0),
        "mean_drift": lambda: jt.waves.mean_drift(w, S, w**2),
        "jonswap": lambda: jt.waves.Jonswap(hs=2.4, tp=7.0, normalise=True)(w),
        "pierson_moskowitz": lambda: jt.waves.pierson_moskowitz(w, hs=2.4, tp=7.0),
    }
    for name, f in calls.items():
        program = np.asarray(f())
        with jax.disable_jit():
            op_by_op = np.asarray(f())
        np.testing.assert_allclose(program, op_by_op, rtol=1e-12, atol=1e-12, err_msg=name)


def test_under_a_trace_the_function_joins_the_callers_program():
    """Under the caller's jit, grad or vmap the function is traced into the caller's program
    (no program of its own inside), and differentiates as before."""
    model = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.Towline(l0=2.5, xp=0.5, EA=100.0))
    y = jnp.array([1.0, 0.0, 0.0, 2.5, 0.0, 0.0])
    jaxpr = jax.make_jaxpr(lambda y: jt.eigenvalues(model, y, throw=False))(y)
    from jaxtow._stability import _eigenvalues

    program = jax.jit(_eigenvalues.__wrapped__, static_argnames=("method",))  # pyright: ignore[reportFunctionMemberAccess]
    nested = jax.make_jaxpr(lambda y: program(model, y, None))(y)
    assert "name=_eigenvalues" in str(nested)  # what a program of its own looks like
    for body in ("_eigenvalues", "_jacobian", "_vector_field"):
        assert f"name={body}" not in str(jaxpr), body
    q, w, S = _wave_inputs()

    def surge(u):
        return jt.drift.irregular_sailing_drift(q, w, S, 0.0, u)[0]

    h = 1e-5
    fd = (surge(2.0 + h) - surge(2.0 - h)) / (2 * h)
    assert float(jax.jit(jax.grad(surge))(2.0)) == pytest.approx(float(fd), rel=1e-6)
    us = jnp.array([1.0, 2.0])
    np.testing.assert_allclose(jax.jit(jax.vmap(surge))(us), [surge(1.0), surge(2.0)], rtol=1e-12)


def test_eager_checks_still_raise_and_non_array_tables_still_work():
    """Bad input raises the same ValueError as before (checked on the host, not in the
    program); a table given as a Python function runs as it did (no program)."""
    q, w, S = _wave_inputs()
    with pytest.raises(ValueError, match="strictly ascending"):
        jt.drift.irregular_sailing_drift(q, w[::-1], S[::-1], 0.0, 2.0)
    with pytest.raises(ValueError, match="strictly ascending"):
        jt.waves.mean_drift(w[::-1], S, w)
    with pytest.raises(ValueError, match="strictly ascending"):
        jt.waves.Jonswap(hs=2.4, tp=7.0, normalise=True)(w[::-1])
    with pytest.raises(ValueError, match="overtakes the waves"):
        jt.drift.sailing_drift(q, 3.0, np.pi, u=5.0)
    bad = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.Towline(l0=2.5, xp=0.5, EA=100.0))
    bad = eqx.tree_at(lambda m: m.towline.l0, bad, -1.0)
    with pytest.raises(ValueError, match="'l0'"):
        jt.eigenvalues(bad, np.array([1.0, 0.0, 0.0, 2.5, 0.0, 0.0]))

    def table(omega, beta):  # a zero-speed table as a plain function
        return jnp.stack([-(omega**2) * jnp.cos(beta), jnp.sin(beta), 0.1 * jnp.sin(2 * beta)])

    B = jt.drift.wave_drift_damping(table, omega=0.9, beta=0.3)
    with jax.disable_jit():
        np.testing.assert_allclose(B, jt.drift.wave_drift_damping(table, omega=0.9, beta=0.3))

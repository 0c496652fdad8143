"""One validation rule per field gives both the eager and the traced check."""

import equinox as eqx
import jax
import jax.numpy as jnp
import pytest

import jaxtow as jt
from jaxtow._rules import guard, rule_of


def _model(**towline):
    return jt.TowModel(
        vessel=jt.presets.barge_2a(),
        towline=jt.Towline(**{"l0": 2.5, "xp": 0.5, "EA": 100.0, **towline}),
    )


def test_changing_one_rule_changes_the_eager_and_the_traced_check(monkeypatch):
    rule = rule_of(_model().towline, "xp")  # the rule of the attachment point x_p'
    assert rule is not None
    eqx.filter_jit(lambda m: jt.equilibria_fixed(m, n_grid=101).psi)(
        _model(xp=0.5)
    )  # valid: x_p' in [0, 1]
    # change that one rule: the eager check at construction and the traced one both follow
    monkeypatch.setattr(rule, "ok", lambda xp, x: xp.isfinite(x) & (x >= 0.0) & (x <= 0.4))
    monkeypatch.setattr(rule, "requirement", "must lie in [0, 0.4]")
    with pytest.raises(ValueError, match=r"'xp' must lie in \[0, 0.4\]"):
        _model(xp=0.5)
    _model(xp=0.3)
    bad = eqx.tree_at(lambda m: m.towline.xp, _model(xp=0.3), jnp.asarray(0.5))  # no eager check
    traced = eqx.filter_jit(
        lambda m: jt.equilibria_fixed(m, n_grid=101).psi
    )  # rules are traced at compile time
    with pytest.raises(Exception, match=r"'xp' must lie in \[0, 0.4\]"):
        traced(bad)


def test_sweep_grids_use_the_same_rule():
    with pytest.raises(ValueError, match="'xp' must lie in"):
        jt.sweep(_model(), {"xp": [0.2, 1.5]})
    with pytest.raises(ValueError, match="'omega' must be > 0"):
        jt.sweep(jt.presets.barge2_wave_model("2a"), {"external.omega": [0.5, -1.0]})


def _raises_under_jit(model):
    """Run the model's traced checks alone under jit (what every guarded entry point does)."""
    return jax.jit(lambda m: guard(jnp.zeros(()), m.checks()))(model)


@pytest.mark.parametrize(
    "path, value, name",
    [
        ("external.omega", -1.0, "omega"),
        ("external.zeta_a", -0.5, "zeta_a"),
        ("EA", float("nan"), "EA"),
    ],
)
def test_traced_checks_cover_the_external_force(path, value, name):
    m0 = jt.presets.barge2_wave_model("2a")
    with pytest.raises(ValueError, match=f"'{name}'"):  # with_parameters checks eagerly
        jt.with_parameters(m0, **{path: value})
    # a model that bypasses the eager checks (eqx.tree_at): only the traced checks see it
    where = {
        "external.omega": lambda mm: mm.external.omega,
        "external.zeta_a": lambda mm: mm.external.zeta_a,
        "EA": lambda mm: mm.towline.EA,
    }[path]
    m = eqx.tree_at(where, m0, jnp.asarray(value))
    failing = [msg for pred, msg in m.checks() if bool(pred)]
    assert failing == [next(msg for msg in failing if f"'{name}'" in msg)]
    with pytest.raises(Exception, match=f"'{name}'"):
        _raises_under_jit(m)


def test_traced_checks_reach_the_spectrum_of_an_irregular_sea():
    m = jt.presets.barge2_irregular_model("2a", hs=2.4, tp=7.0)
    names = " ".join(msg for _, msg in m.checks())
    for field in ("'hs'", "'tp'", "'gamma'", "'omega'", "'EA'", "'m'", "'psi_max'"):
        assert field in names
    _raises_under_jit(m)  # valid: no error
    bad = eqx.tree_at(lambda mm: mm.external.spectrum.gamma, m, jnp.asarray(0.5))
    with pytest.raises(Exception, match="'gamma' must be >= 1"):
        _raises_under_jit(bad)


def test_rules_of_tables_apply_to_sweeps_of_their_parameters():
    """Classes with a custom __init__ (tables) still have their field rules applied by sweeps."""
    tug = jt.presets.illustrative_tug()
    assert rule_of(tug, "efficiency") is not None
    with pytest.raises(ValueError, match="'efficiency'"):
        jt.resistance.Tug(bollard_pull=1e5, free_speed=6.0, efficiency=1.5)


def test_eager_checks_compile_nothing():
    """The checks of a concrete model (`check_now`, an eager `guard`) are evaluated with
    NumPy: no program is compiled for them (each eager `jax.numpy` operation would be one),
    and a bad value is still refused with the parameter named."""
    from helpers import count_compiles

    from jaxtow._rules import check_now

    tow = jt.tow.load("barge2a")
    model = tow.sea_model(tow.sea_states[0])
    bad = eqx.tree_at(lambda m: m.towline.xp, _model(), jnp.asarray(1.5))
    jax.clear_caches()  # no eager operation already compiled in this process
    with count_compiles() as n:
        check_now(model)
        with pytest.raises(ValueError, match="parameter 'xp'"):
            check_now(bad)
    assert n.compiles == 0, n

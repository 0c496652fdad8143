"""float32 (``JAXTOW_ENABLE_X64=0``): the equilibria of the built-in tows are found,
converged and valid, at the float64 headings to float32 accuracy and with the same stability
verdicts. The tolerances of the heading bisection follow the dtype (`bisection_atol`)."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import jax.numpy as jnp
import numpy as np
import pytest

import jaxtow as jt
from jaxtow._equilibrium import bisection_atol

SCRIPT = """
import json, numpy as np, jaxtow as jt
out = {}
for name in ("barge2a", "barge2b"):
    m = jt.tow.load(name).model()
    e = jt.equilibria(m)
    st = jt.stability(m, e.state)
    sim = jt.simulate(m, jt.initial_state(m, psi0=0.1), 50.0, n_save=51)
    ds = jt.sweep(m, {"l0": np.linspace(1.0, 3.0, 3)})
    out[name] = dict(
        dtype=str(e.psi.dtype),
        psi=np.asarray(e.psi, float).tolist(),
        valid=np.asarray(e.valid).tolist(),
        stability=np.asarray(st.stability).tolist(),
        sim_dtype=str(sim.ys.dtype),
        sim_success=bool(sim.success),
        sim_steps=int(sim.n_steps),
        sim_psi_end=float(sim.ys[-1, 5]),
        sweep_dtype=str(ds["psi"].dtype),
        sweep_any_valid=np.asarray(ds["valid"]).any(axis=-1).tolist(),
    )
print(json.dumps(out))
"""


def test_bisection_tolerance_follows_the_dtype():
    # 16 ulp of a heading of order one in either precision (a Newton step's precision there)
    assert bisection_atol(jnp.float64) == 16 * float(jnp.finfo(jnp.float64).eps)  # 3.6e-15
    assert 1e-6 < bisection_atol(jnp.float32) < 1e-5


@pytest.mark.heavy  # minutes on 2 cores: pytest -m heavy
@pytest.mark.slow
def test_builtin_tows_in_float32_match_float64():
    r = subprocess.run(
        [sys.executable, "-c", SCRIPT],
        capture_output=True,
        text=True,
        timeout=600,
        env={**os.environ, "JAXTOW_ENABLE_X64": "0"},
    )
    assert r.returncode == 0, r.stderr[-2000:]
    got = json.loads(r.stdout.strip().splitlines()[-1])
    for name, rec in got.items():
        assert rec["dtype"] == "float32"
        m = jt.tow.load(name).model()
        e = jt.equilibria(m)
        st = jt.stability(m, e.state)
        assert all(rec["valid"]), (name, rec)
        np.testing.assert_allclose(rec["psi"], np.asarray(e.psi), atol=1e-4)
        assert rec["stability"] == np.asarray(st.stability).tolist(), name
        # the time domain and a sweep run in float32 too, with the dtype's own tolerances
        # (1e-5: the float64 1e-8 would take ~24 000 steps over this run)
        assert rec["sim_dtype"] == rec["sweep_dtype"] == "float32"
        assert rec["sim_success"] and rec["sim_steps"] < 2000, rec
        sim = jt.simulate(m, jt.initial_state(m, psi0=0.1), 50.0, n_save=51)
        assert rec["sim_psi_end"] == pytest.approx(float(sim.ys[-1, 5]), abs=1e-3)
        assert all(rec["sweep_any_valid"]), rec


def test_a_tolerance_below_the_float_type_is_refused():
    from jaxtow._simulate import solver_tolerances

    assert solver_tolerances(None, None) == (1e-8, 1e-8)  # float64 in the test process
    with pytest.raises(ValueError, match=r"parameter 'rtol' must be finite and >= 10 eps"):
        solver_tolerances(1e-16, None)

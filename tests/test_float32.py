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

import jaxtow as jt
from jaxtow._equilibrium import bisection_atol

SCRIPT = """
import json, numpy as np, jaxtow as jt
out = {}
for name in ("barge2a", "barge2b"):
    m = jt.tow.load(name).model()
    e = jt.equilibria(m)
    st = jt.stability(m, e.state)
    out[name] = dict(
        dtype=str(e.psi.dtype),
        psi=np.asarray(e.psi, float).tolist(),
        valid=np.asarray(e.valid).tolist(),
        stability=np.asarray(st.stability).tolist(),
    )
print(json.dumps(out))
"""


def test_bisection_tolerance_follows_the_dtype():
    assert bisection_atol(jnp.float64) == 1e-13  # float64: unchanged
    assert 1e-6 < bisection_atol(jnp.float32) < 1e-5


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

"""Benchmark: max Re λ of the tow Jacobians, the pure-JAX spectral abscissa
(`jaxtow.spectral_abscissa`: La Budde characteristic polynomial, bisection on the shift with
a Routh-Hurwitz test) against LAPACK's eigenvalues in JAX (`jnp.linalg.eigvals`) and against
NumPy (`numpy.linalg.eigvals` on the whole stack), in the same run.

The matrices: the Jacobians at every analytic equilibrium of a (x_p', l0') grid of Barge 2a
and 2b, at the thesis's EA' and at 100x it (a stiff towline). Prints µs per matrix (JIT
compile separately), the ratios and the largest difference from NumPy.

    python benchmarks/bench_abscissa.py [--side 120] [--repeat 5] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import time

import jax
import jax.numpy as jnp
import numpy as np

import jaxtow as jt
from jaxtow._equilibrium import analytic_equilibria
from jaxtow._parameters import with_parameters


def jacobians(side: int, ea_factor: float) -> np.ndarray:
    out = []
    for name in ("barge_2a", "barge_2b"):
        m = jt.TowModel(vessel=jt.presets.VESSELS[name](), towline=jt.presets.default_towline())
        ea = float(jt.presets.default_towline().EA) * ea_factor

        def at(xp, l0, m=m, ea=ea):
            mdl = with_parameters(m, xp=xp, l0=l0, EA=ea)
            eqs = analytic_equilibria(mdl, throw=False)
            return jax.vmap(jt.jacobian, in_axes=(None, 0))(mdl, eqs.state)

        xp, l0 = np.meshgrid(np.linspace(0.0, 0.6, side), np.linspace(0.2, 2.5, side))
        J = np.asarray(jax.jit(jax.vmap(at))(jnp.asarray(xp.ravel()), jnp.asarray(l0.ravel())))
        J = J.reshape(-1, 6, 6)
        out.append(J[np.all(np.isfinite(J), axis=(1, 2))])
    return np.concatenate(out)


def timed(fn, x, repeat):
    best = np.inf
    for _ in range(repeat):
        t = time.perf_counter()
        jax.block_until_ready(fn(x))
        best = min(best, time.perf_counter() - t)
    return best


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--side", type=int, default=120, help="grid points per axis")
    ap.add_argument("--repeat", type=int, default=5, help="timed repeats (best is kept)")
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    kernels = {
        "routh": jax.jit(jax.vmap(jt.spectral_abscissa)),
        "lapack": jax.jit(jax.vmap(lambda A: jnp.max(jnp.real(jnp.linalg.eigvals(A))))),
    }
    results = []
    for ea_factor in (1.0, 100.0):
        J = jacobians(args.side, ea_factor)
        Jj = jnp.asarray(J)
        n = J.shape[0]
        ref = np.max(np.linalg.eigvals(J).real, axis=-1)
        t_np = timed(lambda x: np.max(np.linalg.eigvals(x).real, axis=-1), J, args.repeat)
        row = dict(ea_factor=ea_factor, matrices=n, numpy_us=1e6 * t_np / n)
        for name, k in kernels.items():
            t = time.perf_counter()
            k.lower(Jj).compile()
            row[f"{name}_compile_s"] = time.perf_counter() - t
            row[f"{name}_us"] = 1e6 * timed(k, Jj, args.repeat) / n
            row[f"{name}_max_diff"] = float(np.max(np.abs(np.asarray(k(Jj)) - ref)))
        row["lapack_over_routh"] = row["lapack_us"] / row["routh_us"]
        row["numpy_over_routh"] = row["numpy_us"] / row["routh_us"]
        results.append(row)
        print(
            f"EA' x{ea_factor:g}, {n} matrices: routh {row['routh_us']:.2f} µs "
            f"(compile {row['routh_compile_s']:.2f} s, max |diff| {row['routh_max_diff']:.1e}) | "
            f"JAX LAPACK {row['lapack_us']:.2f} µs (compile {row['lapack_compile_s']:.2f} s) | "
            f"NumPy {row['numpy_us']:.2f} µs | LAPACK/routh {row['lapack_over_routh']:.2f}x, "
            f"NumPy/routh {row['numpy_over_routh']:.2f}x"
        )
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=2)
    return results


if __name__ == "__main__":
    main()

"""Pseudo-arclength continuation of a curve G(x) = 0 in the plane (Keller 1977; Allgower & Georg 2003, ch. 2)."""

from __future__ import annotations

from collections.abc import Callable

import jax
import jax.numpy as jnp
import numpy as np

from .._parameters import with_parameters
from .._roots import bisect, newton

NEWTON_ITERATIONS = 12


def parameter_setter(parameter) -> Callable:
    if callable(parameter):
        return parameter
    return lambda model, p: with_parameters(model, **{parameter: p})


# ------------------------------------------------------------------ generic curve following


class Curve:
    """Pseudo-arclength continuation of G(x) = 0, x ∈ R² (jitted pieces, Python driver)."""

    def __init__(self, G: Callable):
        self.G = G
        grad = jax.grad(G)
        self.grad = jax.jit(grad)

        def correct(x_pred, t, x_prev, s):
            # Newton corrector on {G = 0, tᵀ(x − x_prev) = Δs} (`jaxtow._roots.newton`)
            def residual(x, _):
                return jnp.stack([G(x), jnp.dot(t, x - x_prev) - s])

            x, _ = newton(residual, x_pred, rtol=0.0, atol=0.0, max_steps=NEWTON_ITERATIONS)
            return x, jnp.abs(G(x))

        self.correct = jax.jit(correct)

        def locate(x_prev, t_prev, h, test):
            def fn(s, _):
                return test(correct(x_prev + s * t_prev, t_prev, x_prev, s)[0])

            s, _ = bisect(fn, jnp.zeros_like(h), h, max_steps=200)
            return correct(x_prev + s * t_prev, t_prev, x_prev, s)[0]

        self._locate = jax.jit(locate, static_argnums=3)

    def tangent(self, x, previous=None):
        g = np.asarray(self.grad(jnp.asarray(x)))
        t = np.array([-g[1], g[0]]) / np.linalg.norm(g)
        if previous is not None and np.dot(t, previous) < 0:
            t = -t
        return t

    def point(self, x_prev, t_prev, s):
        x, res = self.correct(
            jnp.asarray(x_prev + s * t_prev),
            jnp.asarray(t_prev),
            jnp.asarray(x_prev),
            jnp.asarray(s),
        )
        return np.asarray(x), float(res)

    def follow(self, x0, t0, *, ds, n_max, inside: Callable, ds_min=1e-6, ds_max=None, tol=1e-9):
        """Points, tangents from x0 in direction t0 until ``inside(x)`` fails or n_max."""
        ds_max = ds_max or 10 * ds
        xs, ts = [np.asarray(x0, float)], [np.asarray(t0, float)]
        h = ds
        while len(xs) < n_max:
            x_new, res = self.point(xs[-1], ts[-1], h)
            ok = np.all(np.isfinite(x_new)) and res < tol and np.linalg.norm(x_new - xs[-1]) < 2 * h
            if not ok:
                h *= 0.5
                if h < ds_min:
                    break
                continue
            xs.append(x_new)
            ts.append(self.tangent(x_new, ts[-1]))
            if not inside(x_new):
                break
            h = min(h * 1.3, ds_max)
        return np.array(xs), np.array(ts)

    def locate(self, x_prev, t_prev, h, test: Callable):
        """The point at arclength s ∈ (0, h) where the JAX function ``test(point(s))``
        changes sign (bisection to the floating-point limit, `jaxtow._roots.bisect`)."""
        return np.asarray(
            self._locate(jnp.asarray(x_prev), jnp.asarray(t_prev), jnp.asarray(float(h)), test)
        )

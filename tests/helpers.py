"""Shared test helpers: models, central finite differences, the benchmark scripts."""

import importlib.util
from pathlib import Path

import jax.numpy as jnp
import numpy as np

import jaxtow as jt


def model(vessel, l0=2.5, xp=0.5, **kw):
    return jt.TowModel(vessel=vessel, towline=jt.presets.default_towline(l0=l0, xp=xp), **kw)


def central_jacobian(f, x, h=1e-6):
    x = np.asarray(x, float)
    cols = []
    for i in range(x.size):
        e = np.zeros_like(x)
        e[i] = h
        cols.append((np.asarray(f(x + e)) - np.asarray(f(x - e))) / (2 * h))
    return np.stack(cols, axis=-1)


def central_derivative(f, x, h=1e-6):
    return (float(f(x + h)) - float(f(x - h))) / (2 * h)


def vf_numpy(y, m):
    return np.asarray(jt.vector_field(0.0, jnp.asarray(y), m))


def assert_png_has_content(path, min_ink: float = 0.01):
    """A written figure is a readable PNG with drawn content: more than ``min_ink`` of its
    pixels differ from the background colour."""
    import matplotlib.pyplot as plt

    img = plt.imread(path)[..., :3]
    background = np.median(img.reshape(-1, 3), axis=0)
    ink = np.mean(np.any(np.abs(img - background) > 0.05, axis=-1))
    assert img.shape[0] > 100 and img.shape[1] > 100, f"{path}: {img.shape} is not a figure"
    assert ink > min_ink, f"{path}: only {ink:.3%} of the pixels are drawn"


def barge2_on_lines(lines: dict, scales) -> dict:
    """Barge 2a and 2b on each towline of ``lines`` (name -> towline): for each (vessel,
    name), the equilibrium headings [deg], and the largest real part of the eigenvalues and
    the span of the equilibrium nearest straight behind."""
    out = {}
    for v in ("barge_2a", "barge_2b"):
        for name, line in lines.items():
            m = jt.TowModel(vessel=jt.presets.VESSELS[v](), towline=line, scales=scales)
            e = jt.equilibria(m)
            st = jt.stability(m, e.state)
            k = int(np.argmin(np.abs(np.asarray(e.psi))))
            out[v, name] = (
                np.degrees(np.asarray(e.psi)),
                float(st.max_real[k]),
                float(e.length[k]),
            )
    return out


ROOT = Path(__file__).resolve().parents[1]


def benchmark_script(name: str):
    """``benchmarks/<name>.py`` imported as a module (the scripts are no package), for the
    tests that hold a committed table or data file to what its script computes."""
    spec = importlib.util.spec_from_file_location(name, ROOT / "benchmarks" / f"{name}.py")
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


class count_compiles:
    """Counts JAX's backend compiles and jaxpr traces (and their seconds) inside a
    ``with`` block, through `jax.monitoring`'s duration events."""

    COMPILE = "/jax/core/compile/backend_compile_duration"
    TRACE = "/jax/core/compile/jaxpr_trace_duration"

    def __enter__(self):
        import jax.monitoring

        self.compiles = self.traces = 0
        self.compile_s = self.trace_s = 0.0
        self.on = True

        def listen(event, seconds, **_):
            if not self.on:
                return
            if event == self.COMPILE:
                self.compiles += 1
                self.compile_s += seconds
            elif event == self.TRACE:
                self.traces += 1
                self.trace_s += seconds

        jax.monitoring.register_event_duration_secs_listener(listen)
        return self

    def __exit__(self, *exc):
        self.on = False  # JAX keeps its listeners; this one stops counting

    def __repr__(self):
        return (
            f"{self.compiles} compiles ({self.compile_s:.1f} s), "
            f"{self.traces} traces ({self.trace_s:.1f} s)"
        )

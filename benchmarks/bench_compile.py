"""Benchmark: what the persistent compilation cache saves a user, and what tracing and
compiling the wave-map kernel cost.

1. Commands, each run twice as a user would, in fresh processes sharing one fresh cache
   folder (``JAXTOW_COMPILE_CACHE``): the first run compiles every kernel and stores it, the
   second reads them back. ``jaxtow calm``, ``jaxtow study barge2a`` (the README's main
   job) and ``jaxtow report waves`` on a small grid (``--n 5``, one source and form, no
   attribution or slow-drift runs: the full report takes about an hour on 2 cores).
   Printed: both times and their ratio (target: the second run at least 2x faster).
2. The sweep kernel of the wave study (Barge 2a, regular head waves, the shipped near-field
   database, 401 scan headings, as `jaxtow.studies.WaveStudy` runs it), in a fresh process
   into an empty cache and again from the cache: the time to trace it (Python, every run),
   to lower it and to compile it (XLA; read back from the cache the second time), its
   traced operations and the kernels of the compiled program (the functions XLA generates
   code for: each costs tens of milliseconds to compile on CPU, so their number sets the
   compile time). The same for the kernel on the same model without the wave force (calm
   water): the floor the wave force adds to.

3. With ``--against CHECKOUT`` (another jaxtow source tree, e.g. a ``git worktree`` of an
   earlier commit): only the commands, run as pairs (first, second) alternately from that
   tree and from this one, ``--repeat`` times each, so that both see the same machine load.

    python benchmarks/bench_compile.py [--json out.json] [--skip-commands] [--commands calm]
    python benchmarks/bench_compile.py --against ../old --commands report-waves --repeat 3
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

RUN = "import sys; from jaxtow.cli import main; sys.exit(main())"

COMMANDS = {
    "calm": ["calm"],
    "study": ["study", "barge2a", "--quiet"],
    "report-waves": [  # report waves on a 5-point grid
        "report",
        "waves",
        "--n",
        "5",
        "--n-grid",
        "101",
        "--t1",
        "60",
        "--sources",
        "near_field",
        "--forms",
        "aranha",
        "--no-attribution",
        "--slow-drift-hours",
        "0",
        "--quiet",
    ],
}

KERNEL = r"""
import json, re, sys, time
import jax, jax.numpy as jnp
jax.config.update("jax_enable_x64", True)
import equinox as eqx
from jaxtow import enable_compile_cache
enable_compile_cache(sys.argv[1])
from jaxtow.forces import NoExternalForce
from jaxtow.studies import WaveStudy
from jaxtow._sweep import make_batched_kernel
st = WaveStudy(n=5, n_grid=401, compile_cache=False)
model = st.wave_model("2a")
if sys.argv[2] == "calm":  # the same kernel on the same model without the wave force
    model = eqx.tree_at(lambda m: m.external, model, NoExternalForce())
kernel = make_batched_kernel(method="numerical", n_grid=401, max_roots=4, psi_range=3.141592653589793 / 2,
                             routh_hurwitz=True, eig_method="lapack").jitted
params = {"l0": jnp.linspace(0.5, 2.5, 64), "external.omega": jnp.linspace(0.4, 2.0, 64)}
if sys.argv[2] == "calm":
    params.pop("external.omega")
t0 = time.perf_counter(); traced = kernel.trace(model, params)
t1 = time.perf_counter(); lowered = traced.lower()
t2 = time.perf_counter(); compiled = lowered.compile()
t3 = time.perf_counter(); jax.block_until_ready(compiled(model, params)); t4 = time.perf_counter()
def count(j):  # traced operations, inside sub-programs (loops, calls) too
    from jax.extend.core import ClosedJaxpr, Jaxpr
    n = 0
    for e in j.eqns:
        n += 1
        for p in e.params.values():
            for q in p if isinstance(p, (list, tuple)) else [p]:
                n += count(q.jaxpr if isinstance(q, ClosedJaxpr) else q) if isinstance(q, (ClosedJaxpr, Jaxpr)) else 0
    return n
# the compiled program's kernels: the operations of its non-fused computations (each fusion,
# dot or copy is one function XLA generates code for), constants and tuples aside
kernels = 0
for comp in re.split(r"\n(?=\S)", compiled.as_text()):
    if re.match(r"(ENTRY )?%?(fused_|wrapped_|region_|horizontally|parallel_)", comp):
        continue
    for line in comp.split("\n")[1:]:
        m = re.search(r"= \S+ ([a-z-]+)\(", line)
        if m and m.group(1) not in ("parameter", "constant", "get-tuple-element", "tuple", "bitcast"):
            kernels += 1
print(json.dumps(dict(trace_s=t1 - t0, lower_s=t2 - t1, compile_s=t3 - t2, run_64_points_s=t4 - t3,
                      traced_operations=count(traced.jaxpr.jaxpr), kernels=kernels)))
"""


def _run(args, env, cwd):
    t = time.perf_counter()
    subprocess.run(
        [sys.executable, "-c", RUN, *args], env=env, cwd=cwd, check=True, capture_output=True
    )
    return time.perf_counter() - t


def _pair(cmd, tree, tmp):
    """A first and a second run of ``cmd`` from the source tree ``tree`` into a fresh cache."""
    env = dict(os.environ, JAXTOW_COMPILE_CACHE=str(tmp / "xla"), PYTHONPATH=str(tree))
    return [_run([*cmd, "--out", str(tmp / f"out{i}")], env, tmp) for i in range(2)]


def _compare(args):
    here = Path(__file__).resolve().parents[1]
    trees = {"against": Path(args.against).resolve(), "this": here}
    res: dict = {"against": str(trees["against"]), "runs": []}
    for name in args.commands.split(","):
        for rep in range(args.repeat):
            for label, tree in trees.items():
                with tempfile.TemporaryDirectory() as tmp:
                    first, second = _pair(COMMANDS[name], tree, Path(tmp))
                run = dict(command=name, tree=label, rep=rep, first_s=first, second_s=second)
                res["runs"].append(run | {"ratio": first / second})
                print(
                    f"jaxtow {name} ({label}): {first:.1f} s, then {second:.1f} s "
                    f"({first / second:.2f}x)",
                    flush=True,
                )
    if args.json:
        Path(args.json).write_text(json.dumps(res, indent=2))
    return res


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--json", default=None)
    ap.add_argument("--skip-commands", action="store_true", help="only the kernel timings")
    ap.add_argument(
        "--commands", default=",".join(COMMANDS), help=f"comma-separated, of {list(COMMANDS)}"
    )
    ap.add_argument("--against", default=None, help="another jaxtow source tree to compare")
    ap.add_argument("--repeat", type=int, default=3, help="pairs per tree with --against")
    args = ap.parse_args(argv)
    if args.against:
        return _compare(args)
    res: dict = {"commands": {}, "wave_kernel": {}, "calm_kernel": {}}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        if not args.skip_commands:
            for name in args.commands.split(","):
                cmd = COMMANDS[name]
                cache = tmp / f"xla_{cmd[0]}"
                env = dict(os.environ, JAXTOW_COMPILE_CACHE=str(cache))
                out = tmp / f"out_{cmd[0]}"
                times = [_run([*cmd, "--out", str(out / str(i))], env, tmp) for i in range(2)]
                entries = len(list(cache.glob("*-cache")))
                res["commands"][name] = dict(
                    first_s=times[0], second_s=times[1], ratio=times[0] / times[1], entries=entries
                )
                print(
                    f"jaxtow {name}: first run {times[0]:.1f} s, second {times[1]:.1f} s "
                    f"({times[0] / times[1]:.2f}x; target >= 2x), {entries} cached programs"
                )
        for model in ("waves", "calm"):
            cache = tmp / f"xla_kernel_{model}"
            for label in ("cold", "from cache"):
                out = subprocess.run(
                    [sys.executable, "-c", KERNEL, str(cache), model],
                    check=True,
                    capture_output=True,
                    text=True,
                )
                r = json.loads(out.stdout.strip().splitlines()[-1])
                res["wave_kernel" if model == "waves" else "calm_kernel"][label] = r
                print(
                    f"sweep kernel ({model}), {label}: trace {r['trace_s']:.1f} s, "
                    f"lower {r['lower_s']:.1f} s, compile {r['compile_s']:.1f} s "
                    f"({r['kernels']} kernels); 64 points {r['run_64_points_s']:.2f} s"
                )
        w, c = res["wave_kernel"]["cold"], res["calm_kernel"]["cold"]
        print(
            f"compile time per kernel: waves {w['compile_s'] / w['kernels'] * 1e3:.0f} ms, "
            f"calm {c['compile_s'] / c['kernels'] * 1e3:.0f} ms"
        )
    if args.json:
        Path(args.json).write_text(json.dumps(res, indent=2))
    return res


if __name__ == "__main__":
    main()

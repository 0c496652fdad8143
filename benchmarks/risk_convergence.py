"""Convergence of the irregular-sea Monte Carlo: the fishtail probability, the yaw standard
deviation and the most probable maximum tension of one case against the number of wave
components, the drift's interpolation nodes, the solver tolerance (the adaptive time step)
and the number of runs (the runs of a smaller batch are the first runs of a larger one, so
that column is one batch read at several sizes).

Case: the docs' deck-cargo barge (docs/examples/deck-cargo-barge.toml) in its sailing sea
state with Hs lowered to 1.8 m (``--hs``), one-hour runs. The barge fishtails in calm water
and at Hs 1 m, and the mean drift holds it straight from about 2 m; where no run fishtails the
convergence is read on the yaw standard deviation and the tension's most probable maximum.

    python benchmarks/risk_convergence.py --json benchmarks/data/risk/convergence.json --docs
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import time
from pathlib import Path

import numpy as np

import jaxtow as jt
from jaxtow import risk

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs" / "risk.md"
BEGIN = "<!-- convergence table: python benchmarks/risk_convergence.py --docs -->"
END = "<!-- end of convergence table -->"


def summary(r) -> dict:
    return dict(
        runs=r.n,
        p=r.fishtail_probability,
        low=r.confidence_interval[0],
        high=r.confidence_interval[1],
        yaw_std=float(math.sqrt(np.mean(r.yaw_std[r.completed] ** 2))),
        mpm_kN=r.mpm_tension / 1e3,
    )


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--runs", type=int, default=48)
    ap.add_argument("--hours", type=float, default=1.0)
    ap.add_argument("--hs", type=float, default=1.8)
    ap.add_argument("--json", default=None)
    ap.add_argument("--docs", action="store_true")
    args = ap.parse_args(argv)
    tow = jt.tow.load(ROOT / "docs" / "examples" / "deck-cargo-barge.toml")
    sea = dataclasses.replace(tow.sea_states[1], hs=args.hs)
    base = risk.RiskSettings(chunk_size=args.runs)
    cases = [("default", {})]
    cases += [(f"n_components = {n}", dict(n_components=n)) for n in (64, 128, 512)]
    cases += [(f"nodes = {k}", dict(nodes=k)) for k in (32, 96, None)]
    cases += [(f"rtol = atol = {t:g}", dict(rtol=t, atol=t)) for t in (1e-5, 1e-7)]
    out = dict(
        case=f"{tow.name}, sea state {sea.name} with Hs {args.hs:g} m", hours=args.hours, rows=[]
    )
    t0 = time.perf_counter()
    for label, change in cases:
        s = dataclasses.replace(base, **change)
        t = time.perf_counter()
        r = risk.irregular_sea(tow, sea, n_runs=args.runs, duration=args.hours * 3600.0, settings=s)
        row = dict(label=label, seconds=time.perf_counter() - t, **summary(r))
        out["rows"].append(row)
        print(json.dumps(row), flush=True)
    # the number of runs: one larger batch, read at prefixes
    big = risk.irregular_sea(
        tow,
        sea,
        n_runs=4 * args.runs,
        duration=args.hours * 3600.0,
        settings=dataclasses.replace(base, chunk_size=args.runs),
    )
    for n in (args.runs // 2, args.runs, 2 * args.runs, 4 * args.runs):
        r = dataclasses.replace(
            big,
            settings=dataclasses.replace(big.settings, n_runs=n),
            **{k: getattr(big, k)[:n] for k in ("fishtails", "yaw_amplitude", "max_yaw", "sway_amplitude",
                                                "yaw_std", "sway_std", "max_tension", "min_tension",
                                                "slack_events", "completed")},
        )  # fmt: skip
        row = dict(
            label=f"{n} runs (one batch of {4 * args.runs})", seconds=float("nan"), **summary(r)
        )
        out["rows"].append(row)
        print(json.dumps(row), flush=True)
    out["seconds"] = time.perf_counter() - t0
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=2) + "\n")
    if args.docs:
        write_docs(out)
    return out


def table(out) -> str:
    lines = [
        "| setting | runs | P(fishtail) (95 %) | yaw std deg | MPM tension kN |",
        "| --- | --- | --- | --- | --- |",
    ]
    for r in out["rows"]:
        lines.append(
            f"| {r['label']} | {r['runs']} | {100 * r['p']:.0f} % ({100 * r['low']:.0f}-{100 * r['high']:.0f}) "
            f"| {r['yaw_std']:.2f} | {r['mpm_kN']:.0f} |"
        )
    return "\n".join(lines)


def write_docs(out) -> None:
    from _docs_block import write_block  # beside this script

    write_block(DOCS, BEGIN, END, table(out))


if __name__ == "__main__":
    main()

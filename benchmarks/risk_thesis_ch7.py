"""The thesis's chapter-7 claim re-examined with the irregular-sea Monte Carlo: "in irregular
head seas with Hs = 2.4 m Barge 2a is stable over the physical Tp range for all l0'".

Over a (l0', Tp) grid (Tp over the physical range of Hs 2.4 m, thesis eq. 3.5), for Barge 2a
on the documented towline in the irregular head sea of the wave study (the shipped
near-field panel database, Aranha's forward-speed form, no wind): the linear verdict (max Re
λ of the straight-behind equilibrium under the mean drift) and the Monte Carlo's probability
of fishtailing in a one-hour record (`jaxtow.risk.irregular_sea` on the same model, its mean
drift made the slowly varying drift of the same sea), with its 95 % interval.

    python benchmarks/risk_thesis_ch7.py --json benchmarks/data/risk/thesis_ch7.json --docs
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

import jaxtow as jt
from jaxtow import risk

DOCS = Path(__file__).resolve().parents[1] / "docs" / "risk.md"
BEGIN, END = (
    "<!-- ch7 table: python benchmarks/risk_thesis_ch7.py --docs -->",
    "<!-- end of ch7 table -->",
)


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--l0", type=float, nargs="+", default=[0.5, 1.0, 1.5, 2.0, 2.5, 3.0])
    ap.add_argument("--tp", type=float, nargs="+", default=[5.6, 6.5, 7.5, 8.5])
    ap.add_argument("--runs", type=int, default=32)
    ap.add_argument("--hours", type=float, default=1.0)
    ap.add_argument("--json", default=None)
    ap.add_argument("--docs", action="store_true", help="write the table into docs/risk.md")
    args = ap.parse_args(argv)
    s = risk.RiskSettings(chunk_size=args.runs)
    rows = []
    t0 = time.perf_counter()
    for l0 in args.l0:
        for tp in args.tp:
            model = jt.presets.barge2_irregular_model("2a", l0=l0, tp=tp)
            eqs = jt.equilibria(model)
            mask = np.asarray(jt.straight_behind(np.asarray(eqs.psi), np.asarray(eqs.valid)))
            mr = (
                float(np.asarray(jt.stability(model, eqs.state).max_real)[mask][0])
                if mask.any()
                else float("nan")
            )
            r = risk.irregular_sea(
                model, n_runs=args.runs, duration=args.hours * 3600.0, settings=s
            )
            rows.append(
                dict(
                    l0=l0,
                    tp=tp,
                    max_real=mr,
                    linear="stable" if mr < 0 else "unstable",
                    p=r.fishtail_probability,
                    low=r.confidence_interval[0],
                    high=r.confidence_interval[1],
                    yaw_amplitude_median=float(np.median(r.yaw_amplitude)),
                    runs=r.n,
                )
            )
            print(json.dumps(rows[-1]), flush=True)
    out = dict(runs=args.runs, hours=args.hours, seconds=time.perf_counter() - t0, rows=rows)
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=2) + "\n")
    if args.docs:
        write_docs(out)
    return out


def table(out) -> str:
    tps = sorted({r["tp"] for r in out["rows"]})
    head = "| l0' | " + " | ".join(f"Tp {t:g} s" for t in tps) + " |"
    lines = [head, "|" + " --- |" * (len(tps) + 1)]
    for l0 in sorted({r["l0"] for r in out["rows"]}):
        cells = []
        for t in tps:
            r = next(x for x in out["rows"] if x["l0"] == l0 and x["tp"] == t)
            cells.append(
                f"{r['linear']} ({r['max_real']:+.3f}); P = {100 * r['p']:.0f} % "
                f"({100 * r['low']:.0f}-{100 * r['high']:.0f})"
            )
        lines.append(f"| {l0:g} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def write_docs(out) -> None:
    from _docs_block import write_block  # beside this script

    write_block(DOCS, BEGIN, END, table(out))


if __name__ == "__main__":
    main()

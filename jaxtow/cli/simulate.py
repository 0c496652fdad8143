"""``jaxtow simulate``: time-domain runs from the thesis's initial condition."""

from __future__ import annotations

import json
from pathlib import Path

from ._common import _common, _model, _parse_sets, _time_domain, _time_domain_options


def cmd_simulate(args):
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    summary = {}
    for vname in args.vessels:
        model = _model(args, vname, _parse_sets(args.set))
        summary[vname] = _time_domain(model, vname, args, out) | dict(
            assumed_values=dict(model.assumed)
        )
    (out / "simulate_summary.json").write_text(json.dumps(summary, indent=2, default=float))
    print(f"wrote figures, runs and simulate_summary.json to {out}")


def add_parser(sub):
    s = sub.add_parser("simulate", help="time-domain run(s) from the thesis's initial condition")
    s.add_argument("--vessels", nargs="+", default=["barge_2a", "barge_2b"], help="vessel presets")
    _time_domain_options(s)
    s.add_argument("--out", default="results", help="output folder")
    _common(s)
    s.set_defaults(func=cmd_simulate, vessel=None)

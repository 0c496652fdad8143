"""``jaxtow simulate``: time-domain runs from the thesis's initial condition."""

from __future__ import annotations

import json
from pathlib import Path

from ..io._atomic import write_file
from ._common import (
    model_options,
    parse_sets,
    run_time_domain,
    time_domain_options,
    tow_model,
    tow_names,
    tow_option,
)


def cmd_simulate(args):
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    summary = {}
    for name in tow_names(args, "simulate"):
        model, vname = tow_model(args, name, parse_sets(args.set), "simulate")
        summary[vname] = run_time_domain(model, vname, args, out) | dict(
            assumed_values=dict(model.assumed)
        )
    write_file(out / "simulate_summary.json", json.dumps(summary, indent=2, default=float))
    print(f"wrote figures, runs and simulate_summary.json to {out}")


def add_parser(sub):
    s = sub.add_parser("simulate", help="time-domain run(s) from the thesis's initial condition")
    tow_option(s, multiple=True, default=("barge2a", "barge2b"))
    time_domain_options(s)
    s.add_argument("--out", default="results", help="output folder")
    model_options(s)
    s.set_defaults(func=cmd_simulate)

"""``jaxtow simulate``: time-domain runs from the thesis's initial condition."""

from __future__ import annotations

import json
from pathlib import Path

import msgspec

import jaxtow as jt

from ._common import (
    model_options,
    parse_sets,
    time_domain_options,
    time_domain_settings,
    tow_model,
    tow_names,
    tow_option,
    write_time_domain,
)


def cmd_simulate(args):
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    summary = {}
    for name in tow_names(args, "simulate"):
        model, vname = tow_model(args, name, parse_sets(args.set), "simulate")
        try:
            run = jt.studies.time_domain_run(model, **time_domain_settings(args))
        except ValueError as e:
            raise SystemExit(f"jaxtow simulate: error: {e}") from None
        write_time_domain(model, vname, run, args, out)
        summary[vname] = dict(
            msgspec.to_builtins(run.record),
            n_steps=int(run.simulation.n_steps),
            validity_share=run.validity_share,
            assumed_values=dict(model.assumed),
        )
    jt.io.write_file(out / "simulate_summary.json", json.dumps(summary, indent=2))
    print(f"wrote figures, runs and simulate_summary.json to {out}")


def add_parser(sub):
    s = sub.add_parser("simulate", help="time-domain run(s) from the thesis's initial condition")
    tow_option(s, multiple=True, default=("barge2a", "barge2b"))
    time_domain_options(s)
    s.add_argument("--out", default="results", help="output folder")
    model_options(s)
    s.set_defaults(func=cmd_simulate)

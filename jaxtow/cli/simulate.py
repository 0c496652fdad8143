"""``jaxtow simulate``: time-domain runs from the thesis's initial condition."""

from __future__ import annotations

import json
from pathlib import Path

from ..io._atomic import write_file
from ._common import (
    _common,
    _model,
    _parse_sets,
    _time_domain,
    _time_domain_options,
    _tow_names,
    _tow_option,
)


def cmd_simulate(args):
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    summary = {}
    for name in _tow_names(args, "simulate"):
        model, vname = _model(args, name, _parse_sets(args.set), "simulate")
        summary[vname] = _time_domain(model, vname, args, out) | dict(
            assumed_values=dict(model.assumed)
        )
    write_file(out / "simulate_summary.json", json.dumps(summary, indent=2, default=float))
    print(f"wrote figures, runs and simulate_summary.json to {out}")


def add_parser(sub):
    s = sub.add_parser("simulate", help="time-domain run(s) from the thesis's initial condition")
    _tow_option(s, multiple=True, default=("barge2a", "barge2b"))
    _time_domain_options(s)
    s.add_argument("--out", default="results", help="output folder")
    _common(s)
    s.set_defaults(func=cmd_simulate)

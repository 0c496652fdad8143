"""Compare the outputs of two runs of a command (JSON and NetCDF files of two folders): every
number equal within a relative and absolute tolerance (default 1e-12), wall-clock times
left out. Used to show that a change of the code leaves the built-in tows' results as they
were:

    jaxtow study barge2a --out OLD      # on the earlier commit
    jaxtow study barge2a --out NEW      # on this one
    python benchmarks/compare_outputs.py OLD NEW

Prints each difference and the count of numbers compared; exits 1 on any difference.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np
import xarray as xr

#: Keys whose values are wall-clock times, not results.
TIMES = ("step_times_s", "elapsed_s", "wall_s", "seconds", "created", "started", "finished")


def compare_json(a, b, path: str, tol: float, out: list) -> int:
    if isinstance(a, dict):
        n = 0
        for k in a:
            if k in TIMES:
                continue
            if not isinstance(b, dict) or k not in b:
                out.append(f"{path}/{k}: missing in the second run")
                continue
            n += compare_json(a[k], b[k], f"{path}/{k}", tol, out)
        return n
    if isinstance(a, list):
        if not isinstance(b, list) or len(a) != len(b):
            out.append(f"{path}: lengths differ")
            return 0
        return sum(
            compare_json(x, y, f"{path}[{i}]", tol, out) for i, (x, y) in enumerate(zip(a, b))
        )
    if isinstance(a, float) and isinstance(b, float):
        same = (math.isnan(a) and math.isnan(b)) or math.isclose(a, b, rel_tol=tol, abs_tol=tol)
        if not same:
            out.append(f"{path}: {a!r} != {b!r}")
        return 1
    if a != b and not (isinstance(a, str) and ("/" in a or "\\\\" in a)):  # paths differ
        out.append(f"{path}: {a!r} != {b!r}")
    return 0


def compare_netcdf(a: Path, b: Path, tol: float, out: list) -> int:
    x, y = xr.load_dataset(a), xr.load_dataset(b)
    n = 0
    for v in x.data_vars:
        if v not in y:
            out.append(f"{a.name}/{v}: missing in the second run")
            continue
        xv, yv = np.asarray(x[v].values), np.asarray(y[v].values)
        if xv.dtype.kind in "fc":
            n += xv.size
            if not np.allclose(xv, yv, rtol=tol, atol=tol, equal_nan=True):
                out.append(f"{a.name}/{v}: max difference {np.nanmax(np.abs(xv - yv)):.3g}")
        elif not np.array_equal(xv, yv):
            out.append(f"{a.name}/{v}: values differ")
    return n


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("first", type=Path)
    ap.add_argument("second", type=Path)
    ap.add_argument("--tol", type=float, default=1e-12)
    ap.add_argument(
        "--rename",
        nargs="*",
        default=[],
        metavar="OLD=NEW",
        help="a file of the first run that has another name in the second",
    )
    args = ap.parse_args(argv)
    renamed = dict(r.split("=", 1) for r in args.rename)
    out: list = []
    n = 0
    for f in sorted(args.first.glob("*.json")):
        g = args.second / renamed.get(f.name, f.name)
        if g.is_file():
            n += compare_json(
                json.loads(f.read_text()), json.loads(g.read_text()), f.name, args.tol, out
            )
    for f in sorted(args.first.glob("*.nc")):
        g = args.second / renamed.get(f.name, f.name)
        if g.is_file():
            n += compare_netcdf(f, g, args.tol, out)
    names = [
        {renamed.get(p.name, p.name) for p in args.first.iterdir() if not p.name.startswith(".")},
        {p.name for p in args.second.iterdir() if not p.name.startswith(".")},
    ]
    missing = sorted(names[0] - names[1])  # hidden files (a lock) are not outputs
    out += [f"{m}: missing in the second run" for m in missing]
    print("\n".join(out))
    print(f"compared {n} numbers; differences: {len(out)}")
    return 1 if out else 0


if __name__ == "__main__":
    sys.exit(main())

"""NaN audit: large sweeps over wide parameter ranges, every NaN either absent or flagged.

A calm sweep (default 10⁶ points: x_p' over its whole rule range, l0' from very short to
long, EA' over four decades, so slack lines, headings near ±90° and the pitchfork are all
in it) and a sweep in regular head waves (default 10⁵ points: l0', ω and ζa, the shipped
Barge 2 near-field database with Aranha's forward-speed form). For every floating-point
output it counts the NaN entries and sorts them:

* *masked*: a slot without an equilibrium (``found`` False: NaN by design);
* *flagged*: a found equilibrium outside a flag (``valid``, ``physics_valid`` or a
  stability code of 2, "invalid");
* *unexplained*: NaN at a found, valid equilibrium with every physics flag holding. The
  audit passes when there are none.

Run: ``python benchmarks/nan_audit.py --json benchmarks/data/perf/nan_audit.json``
(``--calm-points``, ``--wave-points``). The counting is `jaxtow.io.nan_audit`; `tests/test_bad_input.py` runs
the same audit on a small calm grid in the default suite.
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np

import jaxtow as jt
from jaxtow.io import nan_audit as audit
from jaxtow.presets import barge2_wave_model


def calm_grid(n: int) -> dict:
    side = max(2, round(n ** (1 / 3)))
    return {
        "xp": np.linspace(0.0, 1.0, side),
        "l0": np.geomspace(0.02, 10.0, side),
        "EA": np.geomspace(1.0, 1e4, side),
    }


def wave_grid(n: int) -> dict:
    side = max(2, round(n ** (1 / 3)))
    return {
        "l0": np.geomspace(0.1, 5.0, side),
        "external.omega": np.linspace(0.2, 2.5, side),
        "external.zeta_a": np.linspace(0.0, 4.0, side),
    }


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--calm-points", type=int, default=1_000_000)
    ap.add_argument("--wave-points", type=int, default=100_000)
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    results = {}
    calm = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.presets.default_towline())
    t = time.perf_counter()
    ds = jt.sweep(calm, calm_grid(args.calm_points), n_grid=401, chunk_size=65536)
    results["calm"] = dict(audit(ds), seconds=time.perf_counter() - t)
    wave = barge2_wave_model("2a", l0=1.0, xp=0.5, omega=1.0, zeta_a=1.25)
    t = time.perf_counter()
    ds = jt.sweep(wave, wave_grid(args.wave_points), n_grid=401, chunk_size=8192, specialise=True)
    results["waves"] = dict(audit(ds), seconds=time.perf_counter() - t)
    for name, r in results.items():
        print(
            f"{name}: {r['points']} points, {r['entries']} slot entries: {r['nan']} NaN = "
            f"{r['masked']} masked (no equilibrium) + {r['flagged']} flagged + "
            f"{r['unexplained']} unexplained {r['unexplained_variables']} ({r['seconds']:.0f} s)"
        )
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=2)
    return results


if __name__ == "__main__":
    main()

"""The three forward-speed forms of the drift compared for Barge 1 and Barge 2.

Run:  python benchmarks/sailing_forms.py [--write]

Panel QTFs: the far-field tables of a coarse `jaxtow bem` run (2 m panels, 30 frequencies
0.05-2.1 rad/s, headings 0-90 deg by 15 deg; not a converged mesh), stored small in
benchmarks/data/ with their provenance. Reproduce them with

    jaxtow bem barge1 --panel-size 2 --n-omega 30 --out bem_barge1
    jaxtow bem barge2a --panel-size 2 --n-omega 30 --out bem_barge2
    python benchmarks/sailing_forms.py --bem bem_barge1 bem_barge2 --write

Prints a Markdown table of the surge QTF peak at 2 m/s (and its shift from zero speed), the
mean surge drift at Hs = 2.4 m, Tp = 7 s and 2 m/s, and the operating speed in the thesis's
sailing sea state with the ILLUSTRATIVE tug, for each form of `jaxtow.drift.sailing_drift`;
``--write`` stores it in docs/data/sailing_forms.md (included in docs/model.md) and the
numbers in docs/data/sailing_forms.json. Drift sources: those panel QTFs, and the documented
Kashiwagi-waterline stand-in (the same for both barges: the rake does not change the
waterline; it has no motion peak). Barge 1 uses Barge 2's
calm-water and wind loads for the operating speed (same main dimensions; the thesis gives
Barge 1 no manoeuvring derivatives).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import jaxtow as jt

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs" / "data"
DATA = ROOT / "benchmarks" / "data"
PANEL = {"Barge 1 (box), panel": "barge1_box", "Barge 2 (raked), panel": "barge2_raked"}


def store_bem(folders) -> None:
    """Far-field QTF (with sectional moments) of each `jaxtow bem` output folder into DATA."""
    import xarray as xr

    from jaxtow import bem

    DATA.mkdir(parents=True, exist_ok=True)
    for folder in folders:
        ds = xr.load_dataset(Path(folder) / "bem.nc")
        q = bem.qtf_from_bem(ds, "far_field", symmetric=True)
        jt.io.save_qtf(
            q, DATA / f"{ds.attrs['mesh_name']}_far_field.nc", bem.qtf_attrs(ds, "far_field")
        )


def compute() -> dict:
    hulls = {
        label: jt.io.load_qtf(DATA / f"{name}_far_field.nc")
        for label, name in PANEL.items()
        if (DATA / f"{name}_far_field.nc").is_file()
    }
    hulls["Barge 1 and 2, waterline stand-in"] = jt.presets.approximate_qtf()
    tug, sea = jt.presets.illustrative_tug(), jt.presets.sea_state("sailing")
    out = {}
    for label, q in hulls.items():
        out[label] = jt.studies.sailing_forms(
            q,
            speed=2.0,
            hs=2.4,
            tp=7.0,
            resistance=lambda form, q=q: jt.presets.barge2_resistance(qtf=q, form=form),
            tug=tug,
            sea=sea,
        )
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--write", action="store_true", help="update docs/data/sailing_forms.*")
    ap.add_argument("--bem", nargs="*", default=[], help="jaxtow bem output folders to store")
    args = ap.parse_args(argv)
    store_bem(args.bem)
    res = compute()
    table = jt.studies.forms_table(res)
    print(table)
    if args.write:
        DOCS.mkdir(parents=True, exist_ok=True)
        (DOCS / "sailing_forms.json").write_text(json.dumps(res, indent=2) + "\n")
        (DOCS / "sailing_forms.md").write_text(
            "<!-- written by: python benchmarks/sailing_forms.py --write -->\n" + table + "\n"
        )


if __name__ == "__main__":
    main()

"""``jaxtow equilibria``: one configuration's equilibria and their stability."""

from __future__ import annotations

import math

import numpy as np

import jaxtow as jt

from ._common import model_options, parse_sets, tow_model, tow_option


def cmd_equilibria(args):
    model, _ = tow_model(args, overrides=parse_sets(args.set))
    eqs = jt.equilibria(model)
    st = jt.stability(model, eqs.state)
    print(
        f"{model.vessel.name}: xp'={float(model.towline.xp)}, l0'={float(model.towline.l0)}, "
        f"EA'={float(model.towline.EA):.2f}"  # pyright: ignore[reportAttributeAccessIssue]
    )
    print(
        f"{'psi [deg]':>10} {'gamma [deg]':>12} {'T_prime':>9} {'l_prime':>8} {'max Re':>10} "
        f"{'verdict':>9} {'R-H':>5} {'valid':>5} {'|f|':>9}"
    )
    for i in range(len(eqs)):
        print(
            f"{math.degrees(eqs.psi[i]):10.4f} {math.degrees(eqs.gamma[i]):12.4f} "
            f"{float(eqs.tension[i]):9.5f} {float(eqs.length[i]):8.4f} {float(st.max_real[i]):+10.5f} "
            f"{jt.STABILITY_LABELS[int(st.stability[i])]:>9} {str(bool(st.routh_hurwitz[i])):>5} "
            f"{str(bool(eqs.valid[i])):>5} {float(eqs.residual[i]):9.1e}"
        )
        if args.eigenvalues:
            lam = np.asarray(st.eigenvalues[i])
            print("      eigenvalues: " + ", ".join(f"{z.real:+.4f}{z.imag:+.4f}j" for z in lam))


def add_parser(sub):
    e = sub.add_parser("equilibria", help="equilibria of one configuration and their stability")
    tow_option(e)
    e.add_argument("--eigenvalues", action="store_true", help="print all eigenvalues")
    model_options(e)
    e.set_defaults(func=cmd_equilibria)

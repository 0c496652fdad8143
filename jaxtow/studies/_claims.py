"""The thesis's claims on towing stability in waves (chapters 6.2-6.3, 7.2.2) as functions.

Each function takes the arrays a study computed (stability maps, equilibrium counts,
time-domain path widths) and returns one ``claims.json`` record: the claim in words, the
numbers measured, whether the claim is reproduced, a note, and the drift forces used. The
stability verdicts use the one rule of `jaxtow.classify` (tolerance `jaxtow.STABILITY_TOL`).
The command ``jaxtow report waves`` computes the arrays and calls these; tests call them on
small arrays directly.
"""

from __future__ import annotations

import numpy as np

from .._stability import STABLE, classify

#: ω below which the thesis says waves do not change the stability of Barge 2a [rad/s].
LOW_OMEGA = 0.65
#: Upper end of the band where the thesis says regular waves stabilise Barge 2a [rad/s].
BAND_OMEGA_MAX = 1.6
#: Wave amplitude below which the thesis says no extra equilibria appear [m].
SMALL_ZETA_A = 0.8
#: Thesis path widths of Barge 2a (l0' = 2.5, ζa = 1.25 m) [L], and the accepted factor.
THESIS_PATH_WIDTHS = {"calm": 2.1, "omega_1.0": 0.5, "omega_1.5": 0.2}
PATH_WIDTH_FACTOR = 1.5


def claim(text: str, measured, reproduced, note: str = "", *, source: str = "") -> dict:
    """One claims.json entry; every entry names the drift forces it was computed with."""
    return dict(
        claim=text, measured=measured, reproduced=bool(reproduced), note=note, drift_source=source
    )


def _stable(max_real) -> np.ndarray:
    return np.asarray(classify(np.asarray(max_real, float))) == STABLE


def _verdict(max_real) -> np.ndarray:
    return np.asarray(classify(np.asarray(max_real, float)))


def low_frequency_waves_keep_calm_verdict(map_2a, calm_2a, omega, *, source: str = "") -> dict:
    """Waves with ω < `LOW_OMEGA` leave the verdict of Barge 2a as in calm water, for every
    l0'. ``map_2a`` (n_l0, n_ω): max Re λ straight behind in waves; ``calm_2a`` (n_l0,)."""
    map_2a, calm_2a, omega = (np.asarray(a, float) for a in (map_2a, calm_2a, omega))
    low = omega < LOW_OMEGA
    same = _verdict(map_2a[:, low]) == _verdict(calm_2a)[:, None]
    dmax = (
        float(np.nanmax(np.abs(map_2a[:, low] - calm_2a[:, None]))) if low.any() else float("nan")
    )
    return claim(
        f"Waves with omega < ~{LOW_OMEGA} rad/s do not change the stability (Barge 2a, all l0')",
        dict(
            fraction_same_verdict=float(np.mean(same)) if same.size else float("nan"),
            max_abs_change_max_real=dmax,
            calm_max_real_range=[float(np.nanmin(calm_2a)), float(np.nanmax(calm_2a))],
        ),
        same.size > 0 and bool(np.all(same)),
        source=source,
    )


def moderate_waves_stabilise_2a(map_2a, omega, *, source: str = "") -> dict:
    """Regular head waves with `LOW_OMEGA` < ω <= `BAND_OMEGA_MAX` make Barge 2a stable at
    most (more than half of the) map points."""
    map_2a, omega = np.asarray(map_2a, float), np.asarray(omega, float)
    band = (omega > LOW_OMEGA) & (omega <= BAND_OMEGA_MAX)
    stable = _stable(map_2a)
    frac = float(np.mean(stable[:, band])) if band.any() else float("nan")
    stab_w = omega[np.any(stable, axis=0)]
    return claim(
        f"Regular head waves with {LOW_OMEGA} < omega <= {BAND_OMEGA_MAX} rad/s make Barge 2a stable "
        "in most cases",
        dict(
            fraction_stable=frac,
            points=int(map_2a[:, band].size),
            lowest_stabilising_omega=float(stab_w.min()) if stab_w.size else None,
        ),
        frac > 0.5,
        source=source,
    )


def barge_2b_stays_stable(map_2b, calm_2b, *, source: str = "") -> dict:
    """Barge 2b is stable at every point of its wave map."""
    frac = float(np.mean(_stable(map_2b)))
    return claim(
        "Barge 2b stays stable in waves",
        dict(fraction_stable=frac, calm_all_stable=bool(np.all(_stable(calm_2b)))),
        frac == 1.0,
        source=source,
    )


def small_waves_add_no_equilibria(counts: dict, *, source: str = "") -> dict:
    """ζa < `SMALL_ZETA_A` creates no equilibria beyond the calm-water ones. ``counts``:
    {version: dict(calm_count=, max_count_below_0_8=, max_count=)}."""
    return claim(
        f"zeta_a < {SMALL_ZETA_A} m creates no extra equilibria",
        counts,
        all(e["max_count_below_0_8"] <= e["calm_count"] for e in counts.values()),
        source=source,
    )


def irregular_sea_keeps_2a_stable(map_2a, hs: float, tp_range, *, source: str = "") -> dict:
    """In irregular head seas of height ``hs`` Barge 2a is stable over the physical Tp range
    for every l0'. ``map_2a`` (n_l0, n_tp)."""
    frac = float(np.mean(_stable(map_2a)))
    lo, hi = (float(t) for t in tp_range)
    return claim(
        f"In irregular head seas with Hs = {hs} m Barge 2a is stable over the physical Tp range for all "
        "l0'",
        dict(fraction_stable=frac, tp_range=[lo, hi], max_real_max=float(np.nanmax(map_2a))),
        frac == 1.0,
        source=source,
    )


def waves_reduce_path_width(widths: dict, *, source: str = "") -> dict:
    """The fishtailing path width of Barge 2a is smaller in waves (ω = 1.0 and 1.5 rad/s)
    than in calm water. ``widths``: {"calm", "omega_1.0", "omega_1.5", ...} in L."""
    return claim(
        "Waves reduce the fishtailing path width of Barge 2a (l0' = 2.5, zeta_a = 1.25 m, omega = 1.0 and "
        "1.5 rad/s)",
        dict(path_width_L=widths),
        widths["calm"] > widths["omega_1.0"] and widths["calm"] > widths["omega_1.5"],
        source=source,
    )


def path_widths_match_thesis(widths: dict, *, source: str = "") -> dict:
    """The path widths are within `PATH_WIDTH_FACTOR` of `THESIS_PATH_WIDTHS`."""
    t, f = THESIS_PATH_WIDTHS, PATH_WIDTH_FACTOR
    return claim(
        f"Path widths {t['calm']} L without waves, {t['omega_1.0']} L at omega = 1.0 and {t['omega_1.5']} L at "
        f"1.5 rad/s (each within a factor {f})",
        dict(path_width_L=widths, thesis_L=t),
        all(t[k] / f <= widths[k] <= f * t[k] for k in t),
        note="0 L means the run converged to the straight-behind equilibrium",
        source=source,
    )


def head_wind_reduces_path_width(
    widths: dict, wind_tag: str, wind_speed: float, *, source: str = ""
) -> dict:
    """A head wind alone reduces the path width of Barge 2a (thesis 7.2.2)."""
    return claim(
        f"A head wind of {wind_speed:g} m/s alone reduces the fishtailing path width of Barge 2a "
        "(thesis 7.2.2: as much as waves at omega = 1.0 rad/s)",
        dict(path_width_L={k: widths[k] for k in ("calm", "omega_1.0", wind_tag)}),
        widths[wind_tag] < widths["calm"],
        note="wind coefficients are the ILLUSTRATIVE Barge 2 table (jaxtow.presets), not the thesis's "
        "unpublished Smit table: the outcome depends on them",
        source=source,
    )


def time_domain_agrees_with_linear(agreement: dict, *, source: str = "") -> dict:
    """Every time-domain run away from the stability boundary ends as the linear verdict
    says. ``agreement``: dict(runs=, agree=, margin=, points=[...])."""
    return claim(
        "Time-domain outcome agrees with the linear prediction away from the stability boundary",
        agreement,
        agreement["agree"] == agreement["runs"],
        source=source,
    )

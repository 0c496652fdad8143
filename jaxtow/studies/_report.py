"""The thesis's wave chapter as one study (``jaxtow report waves``): the primary drift source
and form, every other source × form of the claims table, the attribution of each claim of
the primary study that does not reproduce, and the slowly varying drift in the time domain.
The command line writes what this returns (`WaveReport`); it computes nothing itself."""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable

from ..presets import ASSUMPTIONS, PLAUSIBLE_RANGES, U_TUG_DEFAULT, drift_source
from ._maps import validity_share
from ._waves import WaveStudy, attribute, slow_drift_runs

__all__ = ["WaveReport", "wave_report", "source_key"]


def source_key(spec) -> str:
    """The claims-table key of a drift source spec (a drift-file mapping: its file)."""
    return spec if isinstance(spec, str) else str(spec["file"])


@dataclasses.dataclass(frozen=True)
class WaveReport:
    """What `wave_report` computed: the ``primary`` study (its maps and figures), the
    ``claims`` of every source and form (each tagged ``source_key``; the primary's that do
    not reproduce carry their ``attribution``), the ``summary`` (the drift sources, forms,
    estimates and plausible ranges) and the ``slow_drift`` runs (tag → (model, Simulation,
    metrics, yaw statistics); empty where none were asked for)."""

    primary: WaveStudy
    claims: list
    summary: dict
    slow_drift: dict


def wave_report(
    primary,
    sources: list,
    forms: list,
    *,
    progress: bool = False,
    attribution: bool = False,
    attribution_n: int | None = None,
    panel_variants=None,
    slow_drift_hours: float = 0.0,
    on_progress: Callable[[str, list], None] | None = None,
    **common,
) -> WaveReport:
    """The wave chapter's claims under every drift source of ``sources`` and form of
    ``forms`` (the first of each is the primary study); ``common`` are `WaveStudy`'s options
    (zeta_a, hs, n, n_grid, t1, wind). ``on_progress(message, claims)`` is called as each
    study finishes and as each claim is attributed, with the claims so far (the command
    line keeps them in a partial file: the full report runs for hours on 2 cores)."""
    form = forms[0]
    base = WaveStudy(qtf=primary, form=form, progress=progress, **common)
    summary: dict = dict(
        drift_source=base.source,
        zeta_a=common.get("zeta_a"),
        u_tug=U_TUG_DEFAULT,
        xp=0.5,
        sailing_form=form,
        sources={source_key(s): drift_source(s).describe() for s in sources},
        forms=list(forms),
        assumptions={k: v["note"] for k, v in ASSUMPTIONS.items()},
        plausible_ranges={k: v["note"] for k, v in PLAUSIBLE_RANGES.items()},
    )
    claims: list = []
    t0 = time.perf_counter()
    for s in sources:
        for f in forms:
            first = (s, f) == (primary, form)
            st = base if first else base.variant(qtf=s, form=f, progress=False)
            claims += [dict(c, source_key=source_key(s)) for c in st.claims()]
            if on_progress is not None:
                on_progress(
                    f"claims computed: {source_key(s)}, {f} ({time.perf_counter() - t0:.0f} s)",
                    claims,
                )
    if attribution:
        for c in claims:
            mine = (c["source_key"], c["sailing_form"]) == (source_key(primary), form)
            if mine and not c["reproduced"]:
                a = attribute(base, c["id"], n=attribution_n, panel_variants=panel_variants)
                c["attribution"] = a
                if on_progress is not None:
                    by = a["flipped_by"] or "none of the estimates"
                    on_progress(f"attributed: {c['id']}: flipped by {by}", claims)
    summary["validity_share"] = {
        f"barge_{v}_{tag}": validity_share(maps[v])
        for v in ("2a", "2b")
        for tag, maps in (
            ("map_l0_omega", base.maps_l0_omega),
            ("map_l0_tp", base.maps_l0_tp),
            ("map_utug_omega", base.maps_utug_omega),
        )
    }
    runs = slow_drift_runs(base, hours=slow_drift_hours) if slow_drift_hours > 0 else {}
    if runs:
        summary["slow_drift"] = {k: v[3] for k, v in runs.items()}
    summary["claims"] = claims
    return WaveReport(primary=base, claims=claims, summary=summary, slow_drift=runs)

"""The stability maps of the wave study (thesis figs 6.17-6.19, 6.26) for one drift source and
one forward-speed form, and how two sets of maps differ: the quantities the mesh study of the
stability verdict compares (docs/bem.md, "Shipped databases")."""

from __future__ import annotations

import numpy as np

from .._equilibrium import straight_behind
from .._results import sweep
from .._stability import classify
from ..presets import barge2_irregular_model, barge2_wave_model
from ..waves import physical_tp_range

#: The map axes of the wave study: l0' and ω [rad/s] of the regular-wave maps, and the number
#: of Tp values over the physical range of the irregular-sea maps.
L0_RANGE = (0.3, 3.0)
OMEGA_RANGE = (0.3, 2.0)
MAP_NAMES = ("2a_l0_omega", "2b_l0_omega", "2a_l0_tp", "2b_l0_tp")


#: Points per compiled call of the wave study's maps. Every map of one model structure then
#: shares one compiled kernel (a chunk sized to each map compiled one per map size), and the
#: working memory stays bounded: an irregular-sea point holds the drift integral of every
#: scanned heading batch (with chunks sized to each map the full report reached 18.6 GB;
#: with these it stayed between 1.8 and 6.7 GB in the samples taken).
WAVE_CHUNK = 256


def run_map(
    model, grid: dict, *, n_grid: int = 401, progress: bool = False, specialise: bool = True
):
    """One sweep of the wave study (up to 4 equilibria per point, eigenvalues by LAPACK, the
    kernel specialised to the model's QTF unless ``specialise=False``) as a Dataset, in
    chunks of `WAVE_CHUNK` points."""

    return sweep(
        model,
        grid,
        n_grid=n_grid,
        max_roots=4,
        routh_hurwitz=False,
        progress=progress,
        specialise=specialise,
        chunk_size=WAVE_CHUNK,
    )


def straight(ds, field: str = "max_real"):
    """``field`` of the equilibrium nearest straight behind at every map point (NaN where none)."""

    return nearest_straight({k: ds[k].values for k in ("valid", "psi", field)}, field)


def outside_validity(ds):
    """Where the equilibrium nearest straight behind is outside the physics' validity."""
    return straight(ds, "physics_valid") == 0.0


def validity_share(ds) -> dict:
    """Share of the map points (with a straight-behind equilibrium) that meet each flag."""
    out = {}
    for k in ds.data_vars:
        if (k.startswith("validity_") and ds[k].dtype == bool) or k == "physics_valid":
            v = straight(ds, k)
            has = np.isfinite(v)
            out[k.removeprefix("validity_")] = float(np.mean(v[has] == 1.0)) if has.any() else None
    return out


def map_axes(n: int, hs: float = 2.4) -> dict:
    """The axes of `verdict_maps` for ``n`` points per axis (n // 2, at least 6, Tp values)."""

    lo, hi = (float(t) for t in physical_tp_range(hs))
    return dict(
        l0=np.linspace(*L0_RANGE, n),
        omega=np.linspace(*OMEGA_RANGE, n),
        tp=np.linspace(lo, hi, max(n // 2, 6)),
    )


def verdict_maps(
    qtf,
    *,
    form: str = "aranha",
    n: int = 41,
    zeta_a: float = 1.25,
    hs: float = 2.4,
    n_grid: int = 401,
    progress: bool = False,
    specialise: bool = False,
) -> dict:
    """max Re λ of the equilibrium nearest straight behind on the four maps of the wave study
    (`MAP_NAMES`: Barge 2a and 2b over (l0', ω) in regular head waves of amplitude ``zeta_a``,
    and over (l0', Tp) in a JONSWAP head sea of height ``hs`` over the physical Tp range), for
    the drift source ``qtf`` (any spec of `jaxtow.presets.drift_source`) and ``form``; the
    kernels are compiled once per model structure (``specialise=False``), so tables of one
    shape share them. Returns
    {name: (n_l0, n_y) array, "axes": `map_axes`}."""

    ax = map_axes(n, hs)
    out: dict = {"axes": ax}
    for v in ("2a", "2b"):
        m = barge2_wave_model(v, omega=1.0, zeta_a=zeta_a, qtf=qtf, form=form)
        ds = run_map(
            m,
            {"l0": ax["l0"], "external.omega": ax["omega"]},
            n_grid=n_grid,
            progress=progress,
            specialise=specialise,
        )
        out[f"{v}_l0_omega"] = straight(ds)
        tp0 = float(np.mean(ax["tp"]))
        m = barge2_irregular_model(v, hs=hs, tp=tp0, qtf=qtf, form=form)
        ds = run_map(
            m,
            {"l0": ax["l0"], "external.spectrum.tp": ax["tp"]},
            n_grid=n_grid,
            progress=progress,
            specialise=specialise,
        )
        out[f"{v}_l0_tp"] = straight(ds)
    return out


def verdict_change(a, b) -> dict:
    """How two maps of max Re λ differ: the fraction of points (where both have a
    straight-behind equilibrium) whose verdict (`jaxtow.classify`) differs, the points
    compared, and the largest |Δ max Re λ|."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    both = np.isfinite(a) & np.isfinite(b)
    va, vb = np.asarray(classify(a)), np.asarray(classify(b))
    changed = (va != vb) & both
    exists_changed = np.isfinite(a) != np.isfinite(b)
    return dict(
        fraction_changed=float((changed.sum() + exists_changed.sum()) / max(a.size, 1)),
        points=int(a.size),
        max_abs_change=float(np.max(np.abs(a - b)[both])) if both.any() else float("nan"),
    )


def nearest_straight(arrays: dict, field: str = "max_real"):
    """``field`` of the straight-behind equilibrium (`jaxtow.straight_behind`: the valid one
    nearest ψ = 0, within `jaxtow.STRAIGHT_LIMIT`) at every sweep point, NaN where none: the
    thesis's position 3."""
    mask = straight_behind(np.asarray(arrays["psi"]), np.asarray(arrays["valid"], bool))
    vals = np.where(mask, np.asarray(arrays[field], float), np.nan)
    return np.where(mask.any(axis=-1), np.nansum(np.where(mask, vals, 0.0), axis=-1), np.nan)


def valid_count(arrays: dict):
    """Number of valid equilibria at every sweep point."""
    return np.sum(np.asarray(arrays["valid"]), axis=-1)

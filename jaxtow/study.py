"""Building blocks of the thesis's towing-stability studies in waves and wind (chapters 6-7):
Barge 2 tow models with regular or irregular head-sea drift and wind, and reductions of
sweep results (the equilibrium nearest straight behind).

Drift forces (``qtf=``, any spec of `jaxtow.drift.drift_source`): by default the shipped
Barge 2 near-field panel database (`jaxtow.drift.database`, as the thesis's Delfrac
near-field QTFs); ``"far_field"`` its far-field twin; ``"standin"`` the documented stand-in
`APPROXIMATE_QTF`, a QTF tabulated from a waterline method (`jaxtow.drift.qtf_from_method`,
default Kashiwagi: Fujii-Takahashi diffraction, no motion-induced drift, which matters where
L/λ < 1, ω below about 0.9 rad/s for Barge 2); a `QTF` or a file. Results say which through
``drift_source``.
"""

from __future__ import annotations

import numpy as np

from . import presets
from ._dynamics import TowModel
from .drift._compare import qtf_from_method
from .drift._database import drift_source
from .drift._waterline import barge2_waterline
from .forces import CombinedForce
from .forces._waves import IrregularWaveDriftForce, WaveDriftForce
from .waves import DEFAULT_OMEGA, Jonswap

__all__ = [
    "QTF_OMEGA",
    "QTF_BETA_DEG",
    "APPROXIMATE_QTF",
    "approximate_qtf",
    "barge2_wave_model",
    "barge2_irregular_model",
    "nearest_straight",
    "valid_count",
]

#: Grid of the stand-in QTF (rad/s; headings 0-180 deg completed by symmetry).
QTF_OMEGA = np.linspace(0.1, 2.5, 49)
QTF_BETA_DEG = np.linspace(0.0, 180.0, 19)
APPROXIMATE_QTF = (
    "APPROXIMATE drift forces: QTF tabulated from the Kashiwagi waterline method "
    "(diffraction only, no motion-induced drift) on the estimated Barge 2 rake, "
    "with Aranha's wave-drift damping; the thesis used Delfrac near-field QTFs"
)


def approximate_qtf(method: str = "kashiwagi", draft=None):
    """The documented stand-in QTF of Barge 2 (see the module docstring)."""
    return qtf_from_method(method, barge2_waterline(draft), QTF_OMEGA, np.radians(QTF_BETA_DEG))


def _barge2_tow(version, l0, xp, u_tug, external, draft=None) -> TowModel:
    """Barge 2a/2b on the documented steel towline with an environmental force, carrying its
    reference scales (so ``u_tug`` can be swept, `jaxtow.at_tug_speed`). ``draft`` [m]
    overrides the documented estimate everywhere it enters (added masses, EA', scales)."""
    return TowModel(
        vessel=presets.VESSELS[f"barge_{version}"](draft),
        towline=presets.default_towline(l0=l0, xp=xp, u_tug=u_tug, draft=draft),
        external=external,
        scales=presets.barge2_scales(u_tug, draft),
    )


def barge2_wave_model(
    version: str = "2a",
    *,
    l0: float = 2.5,
    xp: float = 0.5,
    omega: float = 1.0,
    zeta_a: float = 1.25,
    qtf=None,
    u_tug: float = presets.U_TUG_DEFAULT,
    wind=None,
    form: str = "aranha",
    draft: float | None = None,
) -> TowModel:
    """Barge 2a/2b on the documented steel towline in regular head waves (ω [rad/s], ζa [m])
    at tug speed ``u_tug`` (thesis chapter 6.2 base: x_p' = 0.5, ζa = 1.2-1.25 m, 2 m/s);
    ``wind``: an optional `jaxtow.forces.WindForce` added to the waves (thesis 7.2.2).
    Sweep ω and ζa as ``external.omega`` / ``external.zeta_a`` (without wind), the tug speed
    as ``u_tug``. ``form``: the forward-speed form of the drift (`jaxtow.drift.sailing_drift`)."""
    q = drift_source(qtf)[0]
    waves = WaveDriftForce(
        qtf=q, omega=omega, zeta_a=zeta_a, scales=presets.barge2_scales(u_tug, draft), form=form
    )
    ext = waves if wind is None else CombinedForce((waves, wind))
    return _barge2_tow(version, l0, xp, u_tug, ext, draft)


def barge2_irregular_model(
    version: str = "2a",
    *,
    l0: float = 2.5,
    xp: float = 0.5,
    hs: float = 2.4,
    tp: float = 7.0,
    qtf=None,
    u_tug: float = presets.U_TUG_DEFAULT,
    omega=None,
    form: str = "aranha",
    draft: float | None = None,
) -> TowModel:
    """Barge 2a/2b in an irregular head sea (JONSWAP Hs, Tp; mean drift, thesis 6.3); sweep Tp
    as ``external.spectrum.tp``. ``omega``: integration grid (default `jaxtow.waves.DEFAULT_OMEGA`)."""
    q = drift_source(qtf)[0]
    w = np.asarray(DEFAULT_OMEGA if omega is None else omega, float)
    force = IrregularWaveDriftForce(
        qtf=q,
        spectrum=Jonswap(hs=hs, tp=tp),
        omega=w,
        scales=presets.barge2_scales(u_tug, draft),
        form=form,
    )
    return _barge2_tow(version, l0, xp, u_tug, force, draft)


def nearest_straight(arrays: dict, field: str = "max_real"):
    """``field`` of the valid equilibrium nearest ψ = 0 at every sweep point (NaN where none):
    the thesis's position 3 (straight behind) when it exists."""
    psi = np.where(arrays["valid"], np.abs(arrays["psi"]), np.inf)
    k = np.argmin(psi, axis=-1)
    out = np.take_along_axis(np.asarray(arrays[field], float), k[..., None], -1)[..., 0]
    return np.where(np.isfinite(np.min(psi, axis=-1)), out, np.nan)


def valid_count(arrays: dict):
    """Number of valid equilibria at every sweep point."""
    return np.sum(np.asarray(arrays["valid"]), axis=-1)

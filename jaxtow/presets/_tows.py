"""The built-in tows of the thesis's towing-stability studies in waves and wind (chapters
6-7): Barge 2 tow models with regular or irregular head-sea drift and wind.

Drift forces (``qtf=``, any spec of `jaxtow.presets.drift_source`): by default the shipped
Barge 2 near-field panel database (`jaxtow.presets.database`, as the thesis's Delfrac
near-field QTFs); ``"far_field"`` its far-field twin; ``"standin"`` the documented stand-in
`jaxtow.presets.APPROXIMATE_QTF`; a `QTF` or a file. Results say which through
``drift_source``.
"""

from __future__ import annotations

import numpy as np

from .._dynamics import TowModel
from .._values import U_TUG_DEFAULT
from ..forces import CombinedForce, IrregularWaveDriftForce, WaveDriftForce
from ..waves import DEFAULT_OMEGA, Jonswap
from ._barge2 import VESSELS, barge2_scales, default_towline
from ._sources import drift_source


def _barge2_tow(version, l0, xp, u_tug, external, draft=None) -> TowModel:
    """Barge 2a/2b on the documented steel towline with an environmental force, carrying its
    reference scales (so ``u_tug`` can be swept, `jaxtow.at_tug_speed`). ``draft`` [m]
    overrides the documented estimate everywhere it enters (added masses, EA', scales)."""
    return TowModel(
        vessel=VESSELS[f"barge_{version}"](draft),
        towline=default_towline(l0=l0, xp=xp, u_tug=u_tug, draft=draft),
        external=external,
        scales=barge2_scales(u_tug, draft),
    )


def barge2_wave_model(
    version: str = "2a",
    *,
    l0: float = 2.5,
    xp: float = 0.5,
    omega: float = 1.0,
    zeta_a: float = 1.25,
    qtf=None,
    u_tug: float = U_TUG_DEFAULT,
    wind=None,
    form: str = "aranha",
    draft: float | None = None,
) -> TowModel:
    """Barge 2a/2b on the documented steel towline in regular head waves (ω [rad/s], ζa [m])
    at tug speed ``u_tug`` (thesis chapter 6.2 base: x_p' = 0.5, ζa = 1.2-1.25 m, 2 m/s);
    ``wind``: an optional `jaxtow.forces.WindForce` added to the waves (thesis 7.2.2).
    Sweep ω and ζa as ``external.omega`` / ``external.zeta_a`` (without wind), the tug speed
    as ``u_tug``. ``form``: the forward-speed form of the drift (`jaxtow.drift.sailing_drift`)."""
    q = drift_source(qtf).qtf()
    waves = WaveDriftForce(
        qtf=q, omega=omega, zeta_a=zeta_a, scales=barge2_scales(u_tug, draft), form=form
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
    u_tug: float = U_TUG_DEFAULT,
    omega=None,
    form: str = "aranha",
    draft: float | None = None,
) -> TowModel:
    """Barge 2a/2b in an irregular head sea (JONSWAP Hs, Tp; mean drift, thesis 6.3); sweep Tp
    as ``external.spectrum.tp``. ``omega``: integration grid (default `jaxtow.waves.DEFAULT_OMEGA`)."""
    q = drift_source(qtf).qtf()
    w = np.asarray(DEFAULT_OMEGA if omega is None else omega, float)
    force = IrregularWaveDriftForce(
        qtf=q,
        spectrum=Jonswap(hs=hs, tp=tp),
        omega=w,
        scales=barge2_scales(u_tug, draft),
        form=form,
    )
    return _barge2_tow(version, l0, xp, u_tug, force, draft)

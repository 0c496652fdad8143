"""Wave-drift forces: QTF databases, wave-drift damping, sailing drift, tow-model forces."""

from .damping import wave_drift_damping as wave_drift_damping
from .force import IrregularWaveDriftForce as IrregularWaveDriftForce, WaveDriftForce as WaveDriftForce
from .qtf import QTF as QTF
from .sailing import (
    encounter_frequency as encounter_frequency,
    irregular_sailing_drift as irregular_sailing_drift,
    sailing_drift as sailing_drift,
)

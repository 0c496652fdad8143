"""Strip theory in JAX: section coefficients by Frank's close-fit source method (with an
interior lid against irregular frequencies), differentiable in the hull offsets.

Numerics only (no plotting, no files). Modules: `_expint` (the complex exponential integral
of the wave source, with its own derivative rule), `_sections` (the 2-D radiation and
diffraction of a section, `section_coefficients`), `_hull` (hulls by stations, the box and
Wigley hulls, offsets files, and the zero-speed strip integrals, `hull_coefficients`).
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._hull import (
        MODES as MODES,
        Hull as Hull,
        HullCoefficients as HullCoefficients,
        box as box,
        heave_pitch_raos as heave_pitch_raos,
        hull_coefficients as hull_coefficients,
        hydrostatics as hydrostatics,
        offsets_file as offsets_file,
        wigley as wigley,
    )
    from ._sections import (
        LID_FRACTION as LID_FRACTION,
        SectionCoefficients as SectionCoefficients,
        section_coefficients as section_coefficients,
    )

__all__ = [
    "section_coefficients",
    "SectionCoefficients",
    "LID_FRACTION",
    "Hull",
    "box",
    "wigley",
    "offsets_file",
    "hull_coefficients",
    "HullCoefficients",
    "hydrostatics",
    "heave_pitch_raos",
    "MODES",
]

__getattr__, __dir__ = _attach(__name__, __file__)

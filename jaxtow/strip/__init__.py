"""Strip theory in JAX: section coefficients by Frank's close-fit source method (with an
interior lid against irregular frequencies), differentiable in the hull offsets.

Numerics only (no plotting, no files). Modules: `_expint` (the complex exponential integral
of the wave source, with its own derivative rule), `_sections` (the 2-D radiation and
diffraction of a section, `section_coefficients`), `_hull` (hulls by stations, the box and
Wigley hulls, offsets files, and the zero-speed strip integrals, `hull_coefficients`),
`_motions` (Salvesen-Tuck-Faltinsen motions with forward speed, `motions`),
`_resistance` (added resistance by Gerritsma-Beukelman and by the strips' far field in
Maruo's momentum balance, `added_resistance`, and a zero-speed drift table by the
R-function method, `drift_qtf`).
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._hull import (
        MODES as MODES,
        Hull as Hull,
        HullCoefficients as HullCoefficients,
        box as box,
        contour as contour,
        hull_coefficients as hull_coefficients,
        hydrostatics as hydrostatics,
        lewis_hull as lewis_hull,
        lewis_section as lewis_section,
        offsets_file as offsets_file,
        raked_box as raked_box,
        wigley as wigley,
    )
    from ._motions import (
        FROUDE_LIMIT as FROUDE_LIMIT,
        Motions as Motions,
        default_radii as default_radii,
        encounter_frequency as encounter_frequency,
        motions as motions,
        rigid_body_matrices as rigid_body_matrices,
    )
    from ._resistance import (
        METHODS as METHODS,
        AddedResistance as AddedResistance,
        added_resistance as added_resistance,
        drift_qtf as drift_qtf,
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
    "raked_box",
    "lewis_section",
    "lewis_hull",
    "wigley",
    "offsets_file",
    "contour",
    "hull_coefficients",
    "HullCoefficients",
    "hydrostatics",
    "motions",
    "Motions",
    "encounter_frequency",
    "default_radii",
    "rigid_body_matrices",
    "FROUDE_LIMIT",
    "added_resistance",
    "AddedResistance",
    "drift_qtf",
    "METHODS",
    "MODES",
]

__getattr__, __dir__ = _attach(__name__, __file__)

"""Strip theory in JAX: section coefficients by Frank's close-fit source method (with an
interior lid against irregular frequencies), differentiable in the hull offsets.

Numerics only (no plotting, no files: an offsets table is read by
`jaxtow.io.read_offsets`). Modules: `_expint` (the complex exponential integral of the wave
source, with its own derivative rule), `_sections` (the 2-D radiation and diffraction of a
section, `section_coefficients`), `_hull` (hulls by stations: the box, raked box, Wigley and
Lewis-form hulls), `_strips` (the section solve as a reusable value, `SectionTable`, the
strip integrals, the zero-speed `hull_coefficients` and the `hydrostatics`), `_motions`
(Salvesen-Tuck-Faltinsen motions with forward speed, `motions`), `_resistance` (added
resistance by `GerritsmaBeukelman` and by the strips' `FarField` in Maruo's momentum
balance, either with the bow's short-wave reflection (`WithReflection`, on the hull's
waterline: `wigley_waterline`), `added_resistance`, and a zero-speed drift table by the
R-function method, `drift_qtf`). The loading condition is a `jaxtow.Loading` and the water a `jaxtow.Water`,
one value each, shared with the panel method. Everything runs under `jax.jit`,
`jax.grad` and `jax.vmap`.
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._hull import (
        MODES as MODES,
        WATERLINE_TOL as WATERLINE_TOL,
        Hull as Hull,
        box as box,
        lewis_hull as lewis_hull,
        lewis_section as lewis_section,
        raked_box as raked_box,
        resample_contour as resample_contour,
        wigley as wigley,
    )
    from ._motions import (
        FROUDE_LIMIT as FROUDE_LIMIT,
        LOW_FREQUENCY as LOW_FREQUENCY,
        Motions as Motions,
        MotionSolve as MotionSolve,
        motions as motions,
        plan_sections as plan_sections,
        rigid_body_matrices as rigid_body_matrices,
        solve_motions as solve_motions,
    )
    from ._resistance import (
        AbstractAddedResistanceMethod as AbstractAddedResistanceMethod,
        AddedResistance as AddedResistance,
        FarField as FarField,
        GerritsmaBeukelman as GerritsmaBeukelman,
        WithReflection as WithReflection,
        added_resistance as added_resistance,
        drift_qtf as drift_qtf,
    )
    from ._sections import (
        LID_FRACTION as LID_FRACTION,
        SectionCoefficients as SectionCoefficients,
        section_coefficients as section_coefficients,
    )
    from ._strips import (
        HullCoefficients as HullCoefficients,
        Hydrostatics as Hydrostatics,
        SectionTable as SectionTable,
        hull_coefficients as hull_coefficients,
        hydrostatics as hydrostatics,
        section_table as section_table,
        wigley_waterline as wigley_waterline,
    )


__getattr__, __dir__, __all__ = _attach(__name__, __file__)

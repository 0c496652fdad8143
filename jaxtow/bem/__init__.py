"""Panel-method wave drift with Capytaine (optional extra: ``pip install 'jaxtow[bem]'``).

Thesis sections 2.3.1, 4 and 5 and appendix B computed the reference drift forces with the
panel code Delfrac; jaxtow uses the open BEM solver Capytaine. What this package gives:

* parametric hull meshes (NumPy only, no Capytaine needed): `box_barge_mesh` (Barge 1),
  `barge2_mesh` (Barge 2, raked), `raked_barge_mesh`, `vertical_cylinder_mesh`; `read_mesh`
  reads user hulls in the formats Capytaine reads;
* `rigid_body`: mass, CoG (height above the keel, thesis Table B.3), radii of gyration
  (Journée's approximations, documented in `jaxtow.presets.ASSUMPTIONS`), exact hydrostatics;
* `bem_drift`: first-order solution over (ω, β), RAOs, far-field (Capytaine's Kochin-function
  momentum formula) and near-field (Pinkster pressure integration, with its parts I-IV and
  the sectional moments of thesis eqs 2.43-2.48) mean drift, cached per frequency to NetCDF;
* `qtf_from_bem` / `box_barge_drift`: jaxtow `QTF` databases for the tow models;
* `mesh_hull`: the stations of strip theory (`jaxtow.strip.Hull`) cut from a mesh, so
  that both methods run on the same hull;
* `mesh_convergence` (thesis appendix B.1) and `reference.cylinder_drift`, the exact mean
  drift on a bottom-mounted vertical cylinder (MacCamy & Fuchs) for validation;
* command line: ``jaxtow bem CONFIG|barge1|barge2 --out DIR``.

Everything that needs Capytaine imports it on first use and, when it is missing, raises an
ImportError that says how to install it; the rest of jaxtow never imports it.
This is a NumPy pre-processor: it produces tables; the differentiable JAX models consume them.
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from . import (
        body as body,
        capytaine_mesh as capytaine_mesh,
        convergence as convergence,
        database as database,
        offsets as offsets,
        reference as reference,
        solve as solve,
        summary as summary,
    )
    from .body import RigidBody as RigidBody, rigid_body as rigid_body
    from .capytaine_mesh import (
        INSTALL_HINT as INSTALL_HINT,
        available as available,
        read_mesh as read_mesh,
        require_capytaine as require_capytaine,
        symmetric_capytaine_mesh as symmetric_capytaine_mesh,
    )
    from .convergence import mesh_convergence as mesh_convergence
    from .database import (
        BEMDrift as BEMDrift,
        bem_drift as bem_drift,
        box_barge_drift as box_barge_drift,
        qtf_attrs as qtf_attrs,
        qtf_from_bem as qtf_from_bem,
        rao as rao,
    )
    from .meshes import (
        HullMesh as HullMesh,
        barge2_mesh as barge2_mesh,
        box_barge_mesh as box_barge_mesh,
        raked_barge_mesh as raked_barge_mesh,
        vertical_cylinder_mesh as vertical_cylinder_mesh,
    )
    from .offsets import mesh_hull as mesh_hull
    from .solve import far_field_drift as far_field_drift, solve_frequency as solve_frequency
    from .source import MeshDriftSource as MeshDriftSource


__getattr__, __dir__, __all__ = _attach(__name__, __file__)

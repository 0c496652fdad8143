"""File formats and labelled results, one module a format: `dataset` (sweep results as
NetCDF), `qtf_files` (jaxtow's QTF files and `read_qtf`, any drift file by its content),
`wamit`, `capytaine`, `resistance` (coefficient tables, resistance budgets), `design`,
`drift_methods`, `waterline`, `offsets` (a hull's offsets table for strip theory), `checkpoint` (a sweep's chunks), `study_steps` (a study's
finished steps). Numerical modules never
import this."""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

# loaded on first use (`jaxtow._lazy`): the atomic file writes of `jaxtow.io._atomic` do not
# load xarray
if TYPE_CHECKING:
    from ._atomic import (
        atomic_path as atomic_path,
        save_netcdf as save_netcdf,
        write_file as write_file,
    )
    from ._fingerprint import Fingerprint as Fingerprint, fingerprint as fingerprint
    from ._tables import complete_table as complete_table
    from .capytaine import (
        qtf_from_capytaine as qtf_from_capytaine,
        read_capytaine_drift as read_capytaine_drift,
    )
    from .checkpoint import Checkpoint as Checkpoint
    from .dataset import (
        load_dataset as load_dataset,
        nan_audit as nan_audit,
        save_dataset as save_dataset,
        sweep_dataset as sweep_dataset,
    )
    from .design import design_dataset as design_dataset, sensitivity_dataset as sensitivity_dataset
    from .drift_methods import drift_methods_dataset as drift_methods_dataset
    from .offsets import read_offsets as read_offsets
    from .qtf_files import load_qtf as load_qtf, read_qtf as read_qtf, save_qtf as save_qtf
    from .resistance import (
        read_coefficient_table as read_coefficient_table,
        resistance_dataset as resistance_dataset,
    )
    from .study_steps import StepStore as StepStore
    from .wamit import (
        read_drift_file as read_drift_file,
        read_wamit_drift as read_wamit_drift,
        read_wamit_qtf as read_wamit_qtf,
        write_wamit_drift as write_wamit_drift,
        write_wamit_qtf as write_wamit_qtf,
    )
    from .waterline import read_waterline as read_waterline, write_waterline as write_waterline


__getattr__, __dir__, __all__ = _attach(__name__, __file__)

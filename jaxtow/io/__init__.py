"""File formats and labelled results (xarray / NetCDF). Numerical modules never import this."""

from .dataset import (
    load_dataset as load_dataset,
    save_dataset as save_dataset,
    sweep_dataset as sweep_dataset,
)
from .design import design_dataset as design_dataset, sensitivity_dataset as sensitivity_dataset
from .drift_methods import drift_methods_dataset as drift_methods_dataset
from .resistance import resistance_dataset as resistance_dataset
from .wamit import (
    load_qtf as load_qtf,
    qtf_from_capytaine as qtf_from_capytaine,
    read_wamit_drift as read_wamit_drift,
    save_qtf as save_qtf,
    write_wamit_drift as write_wamit_drift,
)

__all__ = [
    "load_dataset",
    "save_dataset",
    "sweep_dataset",
    "design_dataset",
    "sensitivity_dataset",
    "drift_methods_dataset",
    "resistance_dataset",
    "load_qtf",
    "qtf_from_capytaine",
    "read_wamit_drift",
    "save_qtf",
    "write_wamit_drift",
]

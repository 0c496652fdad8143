"""File formats and labelled results (xarray / NetCDF). Numerical modules never import this."""

from .dataset import load_dataset as load_dataset, save_dataset as save_dataset, sweep_dataset as sweep_dataset

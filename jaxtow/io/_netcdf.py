"""Reading NetCDF files with errors that name the file and what was expected: a file that is
not NetCDF, a missing variable, a variable over the wrong dimensions. A variable stored with
its dimensions in another order is read by their names (xarray's labelled dimensions), not
refused."""

from __future__ import annotations

from pathlib import Path

import xarray as xr

__all__ = ["read_netcdf", "table_variables"]


def read_netcdf(path, what: str) -> xr.Dataset:
    """The dataset in ``path`` (loaded into memory); ``what`` says what the file should be."""
    path = Path(path)
    if not path.exists():
        raise ValueError(f"{path}: no such file")
    try:
        return xr.load_dataset(path)
    except (ValueError, OSError) as e:
        raise ValueError(
            f"{path}: not a NetCDF file that xarray can read ({type(e).__name__}); expected {what}"
        ) from None


def table_variables(ds: xr.Dataset, path, names, dims: tuple[str, ...]) -> dict:
    """name → numpy array over ``dims`` (in that order) for each of ``names``: a missing
    variable or one over other dimensions is an error naming the file and the variable."""
    out = {}
    for n in names:
        if n not in ds:
            raise ValueError(
                f"{path}: no variable {n!r} (the file holds {sorted(map(str, ds.data_vars))}; "
                f"expected {', '.join(names)} over {dims})"
            )
        v = ds[n]
        if set(v.dims) != set(dims):
            raise ValueError(
                f"{path}: variable {n!r} has dimensions {v.dims}, expected {dims} (in any order)"
            )
        out[n] = v.transpose(*dims).values
    return out

"""Wave-drift sources: one typed value a kind of source, each with `qtf` and `describe`, and
`drift_source`, the one way a spec (a name, a path, a mapping or a QTF) becomes one.

A tow evaluates its wave drift through exactly one source object: the resistance budget, the
stability model and the report's drift table all call the same ``source.qtf()`` (computed
once, cached on the object) and apply the forward speed by the tow's sailing form
(`jaxtow.drift.sailing_drift`), so that the three agree at every speed. A waterline method
is therefore tabulated as a zero-speed QTF on the grid `QTF_OMEGA` × `QTF_BETA_DEG` like the
others: its own forward-speed factor is not used where a tow is assessed (the
method-comparison study, `jaxtow.drift.compare_methods`, still evaluates the methods
themselves).

The panel solve of a user's mesh is `jaxtow.bem.MeshDriftSource` (above this layer: it needs
Capytaine); it subclasses `AbstractDriftSource` like the rest.
"""

from __future__ import annotations

import abc
import dataclasses
from collections.abc import Mapping
from functools import cached_property
from os import PathLike
from pathlib import Path

import numpy as np

from .. import strip
from .._body import Loading
from ..drift import QTF, WATERLINE_METHODS, Waterline, qtf_from_method
from ..io import read_qtf
from ._barge2 import barge2_waterline
from ._databases import (
    APPROXIMATE_QTF,
    DATABASE_METHODS,
    DATABASES,
    DEFAULT_METHOD,
    QTF_BETA_DEG,
    QTF_OMEGA,
    STANDIN,
    approximate_qtf,
    database,
    describe_database,
)

__all__ = [
    "AbstractDriftSource",
    "DatabaseSource",
    "StandInSource",
    "FileSource",
    "WaterlineSource",
    "StripSource",
    "GivenQTF",
    "FILE_OPTIONS",
    "drift_source",
    "describe_file",
]


class AbstractDriftSource(abc.ABC):
    """Where a tow's wave drift comes from. ``qtf()`` is the zero-speed mean-drift `QTF`
    (SI per ζa², β = 0 head seas), computed on first use and kept; ``describe()`` one line
    naming it for tables and figures; ``caveat()`` what the results that use it depend on
    (an estimate or a limit of the method), for the list of estimates; ``spec`` the tow-file
    value that names it."""

    @abc.abstractmethod
    def _compute(self) -> QTF: ...

    @abc.abstractmethod
    def describe(self) -> str: ...

    @property
    @abc.abstractmethod
    def spec(self) -> object: ...

    def caveat(self) -> str:
        return self.describe()

    @cached_property
    def _qtf(self) -> QTF:
        return self._compute()

    def qtf(self) -> QTF:
        """The source's zero-speed QTF (computed once per source object)."""
        return self._qtf


@dataclasses.dataclass(frozen=True, eq=False)
class DatabaseSource(AbstractDriftSource):
    """A panel-method database shipped with jaxtow (`database`): ``hull`` in `DATABASES`,
    ``method`` in `DATABASE_METHODS`."""

    hull: str = "barge2"
    method: str = DEFAULT_METHOD

    def __post_init__(self):
        if self.hull not in DATABASES:
            raise ValueError(
                f"parameter 'hull': shipped databases are {DATABASES}, got {self.hull!r}"
            )
        if self.method not in DATABASE_METHODS:
            raise ValueError(f"parameter 'method': one of {DATABASE_METHODS}, got {self.method!r}")

    def _compute(self) -> QTF:
        return database(self.hull, self.method)

    def describe(self) -> str:
        return describe_database(self.hull, self.method)

    @property
    def spec(self) -> str:
        return f"{self.hull}:{self.method}"


@dataclasses.dataclass(frozen=True, eq=False)
class StandInSource(AbstractDriftSource):
    """The documented stand-in: the Kashiwagi waterline QTF of Barge 2 (`approximate_qtf`)."""

    def _compute(self) -> QTF:
        return approximate_qtf()

    def describe(self) -> str:
        return APPROXIMATE_QTF

    @property
    def spec(self) -> str:
        return STANDIN


#: The options of a drift-file spec, those of `jaxtow.io.read_drift_file`.
FILE_OPTIONS = ("ulen", "rho", "g", "symmetry", "symmetry_tol", "reference_point", "moment_set")


def describe_file(info: dict) -> str:
    """One line saying how a drift file was read (from a reader's ``info``)."""
    parts = [info.get("format", "drift file")]
    for k in ("ulen", "rho", "g"):
        if k in info:
            v, where = info[k]
            parts.append(f"{k} = {v:g} ({where})")
    if "reference_point" in info:
        _, note = info["reference_point"]
        parts.append(f"yaw about {note}")
    if "symmetry" in info:
        parts.append(str(info["symmetry"]))
    if info.get("moment_set", 6) != 6:
        parts.append(f"moment set I = {info['moment_set']}")
    return f"QTF file {info['file']} (" + "; ".join(parts) + ")"


@dataclasses.dataclass(frozen=True, eq=False)
class FileSource(AbstractDriftSource):
    """A drift file (`jaxtow.io.read_qtf`: jaxtow .nc/.csv, a Capytaine drift NetCDF, WAMIT
    .8/.9) read with the reader's ``options`` (`FILE_OPTIONS`)."""

    path: str
    options: tuple = ()

    def __post_init__(self):
        bad = sorted(set(dict(self.options)) - set(FILE_OPTIONS) - {"length"})
        if bad:
            raise ValueError(
                f"drift file {self.path}: unknown options {bad}; choose from {FILE_OPTIONS}"
            )

    @cached_property
    def _read(self):
        return read_qtf(self.path, **dict(self.options))

    def _compute(self) -> QTF:
        return self._read[0]

    def describe(self) -> str:
        return describe_file(self._read[1])

    @property
    def spec(self):
        return {"file": self.path, **dict(self.options)} if self.options else self.path


@dataclasses.dataclass(frozen=True, eq=False)
class WaterlineSource(AbstractDriftSource):
    """A waterline method of `jaxtow.drift.WATERLINE_METHODS` on ``waterline``, tabulated as a
    zero-speed QTF on `QTF_OMEGA` × `QTF_BETA_DEG` (`jaxtow.drift.qtf_from_method`). It has
    diffraction only: no motion-induced drift, which matters where the waves are longer than
    the hull (L/λ < 1)."""

    method: str
    waterline: Waterline

    def __post_init__(self):
        if self.method not in WATERLINE_METHODS:
            raise ValueError(
                f"parameter 'method': unknown waterline method {self.method!r}; choose from "
                f"{', '.join(WATERLINE_METHODS)}"
            )

    def _compute(self) -> QTF:
        return qtf_from_method(self.method, self.waterline, QTF_OMEGA, np.radians(QTF_BETA_DEG))

    def describe(self) -> str:
        return (
            f"waterline method {self.method!r} on the {self.waterline.name} waterline "
            "(diffraction only, no motion-induced drift), tabulated at zero speed"
        )

    def caveat(self) -> str:
        return (
            f"waterline method {self.method!r} (misses the motion-induced drift where L/lambda < 1)"
        )

    @property
    def spec(self) -> str:
        return self.method


@dataclasses.dataclass(frozen=True, eq=False)
class StripSource(AbstractDriftSource):
    """Strip theory of ``hull`` (`jaxtow.strip.drift_qtf`): Gerritsma-Beukelman added
    resistance plus the R-function short-wave part on ``waterline``, at zero speed, with the
    body's loading.
    ``name`` is the tow-file value (box, barge2 or an offsets file); ``loading`` a
    `jaxtow.Loading` (None: the documented estimate)."""

    hull: strip.Hull
    waterline: Waterline
    name: str
    loading: Loading | None = None

    def _compute(self) -> QTF:
        return strip.drift_qtf(
            self.hull,
            self.waterline,
            QTF_OMEGA,
            np.radians(QTF_BETA_DEG),
            loading=self.loading,
        )

    def describe(self) -> str:
        return (
            f"strip theory of the {self.hull.name} hull ({self.hull.x.shape[0]} sections): "
            f"Gerritsma-Beukelman added resistance plus the R-function short-wave part on the "
            f"{self.waterline.name} waterline; CoG height, radii of gyration and roll damping: "
            "the documented estimates; zero-speed table"
        )

    def caveat(self) -> str:
        return (
            f"strip theory of the {self.name} hull at zero speed (Gerritsma-Beukelman plus "
            "the R-function short-wave part; no lateral motion-induced drift; on a barge it "
            "over-predicts the panel method's surge drift in waves longer than the hull, see "
            "docs/strip.md; CoG height, radii of gyration and roll damping: the documented "
            "estimates)"
        )

    @property
    def spec(self):
        return "strip" if self.name in ("box", "barge2") else {"strip": self.name}


@dataclasses.dataclass(frozen=True, eq=False)
class GivenQTF(AbstractDriftSource):
    """A `QTF` given as a value (``label`` names it)."""

    table: QTF
    label: str = "user QTF"

    def _compute(self) -> QTF:
        return self.table

    def describe(self) -> str:
        return self.label

    @property
    def spec(self) -> str:
        return self.label


def drift_source(spec=None, *, hull: str = "barge2", waterline=None) -> AbstractDriftSource:
    """The `AbstractDriftSource` a spec names, the one way every study and command names its
    drift forces:

    * None or ``"near_field"`` / ``"far_field"``: the shipped database of ``hull`` by that
      method (None: `DEFAULT_METHOD`);
    * ``"barge1:far_field"`` etc.: a shipped database by hull and method;
    * ``"standin"``: the documented stand-in (`StandInSource`);
    * a waterline method of `jaxtow.drift.WATERLINE_METHODS` (``"kashiwagi"``, ...): that
      method on ``waterline`` (default the Barge 2 waterline; `WaterlineSource`);
    * a `QTF`: used as given (`GivenQTF`); an `AbstractDriftSource`: itself;
    * any other string: a drift file (`FileSource`, read with the default options);
    * a mapping {"file": PATH, **options}: the same file with the reader's options (ULEN,
      ρ, g, reference_point, symmetry, symmetry_tol, moment_set; `jaxtow.io.read_drift_file`).

    The description of a file says how it was read (its format, ULEN/ρ/g and where they came
    from, the yaw moment's reference point, the symmetry completion)."""
    if isinstance(spec, AbstractDriftSource):
        return spec
    if isinstance(spec, QTF):
        return GivenQTF(spec)
    if spec is None:
        spec = DEFAULT_METHOD
    if isinstance(spec, Mapping):
        opts = dict(spec)
        path = opts.pop("file", None)
        if not isinstance(path, (str, PathLike)):
            raise ValueError(
                f"parameter 'spec': a drift-file mapping needs 'file' = PATH, got {sorted(spec)}"
            )
        return FileSource(str(path), tuple(sorted(opts.items())))
    if not isinstance(spec, str):
        raise TypeError(
            f"parameter 'spec': a name, a path, a {{'file': ...}} mapping or a QTF, got "
            f"{type(spec).__name__}"
        )
    if spec == STANDIN:
        return StandInSource()
    if spec in WATERLINE_METHODS:
        return WaterlineSource(spec, barge2_waterline() if waterline is None else waterline)
    name, _, method = spec.rpartition(":") if ":" in spec else (hull, "", spec)
    if name in DATABASES and method in DATABASE_METHODS:
        return DatabaseSource(name, method)
    if spec in DATABASES:
        return DatabaseSource(spec, DEFAULT_METHOD)
    if not Path(spec).exists():
        raise ValueError(
            f"drift source {spec!r}: not a shipped database ({', '.join(DATABASE_METHODS)}, "
            f"'hull:method' with hull in {DATABASES}), not {STANDIN!r} and no such file"
        )
    return FileSource(spec)

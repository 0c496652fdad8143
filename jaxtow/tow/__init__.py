"""A tow described in one file (TOML): the vessel, the hull for wave drift, the towline, the
tug, the route, the sea states and what `jaxtow study` runs. The schema is documented in
docs/towfile.md and printed, commented, by ``jaxtow tow new``.

```python
import jaxtow as jt

tow = jt.tow.load("barge2a")            # a built-in (barge1, barge2a, barge2b) or a file path
model = tow.model()                     # the calm-water TowModel, with its scales
res = tow.resistance()                  # the TowResistance of jaxtow.resistance
sea = tow.sea_states[0]; m = tow.sea_model(sea)   # drift, wind and current on the tow
print(tow.drift.describe())             # the one drift source every result uses
print(tow.show())                       # the resolved file, every default and estimate
```

The package is split by section: `_vessel` ([vessel]), `_hull` ([hull]: waterline, drift
source, wind), `_towline` ([towline]: the line, its bridle and its make), `_sections`
([tug], [route], [[sea_state]], [criteria], [study]), `_findings` (plausibility at load),
`_schema` (every key, its type, rule, enum and default; the typed structs that read them)
and `_tow` (the `Tow` and the order the sections resolve in).

Errors are `TowFileError` (a `ValueError`) naming the file, the line and the key; values
outside the physics' range (a Tp outside the physical range of its Hs) and deprecated keys
warn with `TowFileWarning`; values that do not fit together are `Finding`s of the tow.
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._findings import Finding as Finding
    from ._schema import (
        SCHEMA as SCHEMA,
        SUBTABLES as SUBTABLES,
        TowFileError as TowFileError,
        TowFileWarning as TowFileWarning,
        schema_markdown as schema_markdown,
    )
    from ._sections import StudyOptions as StudyOptions
    from ._tow import (
        BUILTIN_TOWS as BUILTIN_TOWS,
        CHANGES as CHANGES,
        DEPRECATED_NAMES as DEPRECATED_NAMES,
        Tow as Tow,
        builtin_text as builtin_text,
        canonical_name as canonical_name,
        load as load,
        loads as loads,
        show as show,
        template as template,
        with_changes as with_changes,
    )
    from ._towline import LineSegment as LineSegment, TowlineMake as TowlineMake

__getattr__, __dir__, __all__ = _attach(__name__, __file__)

"""A tow described in one file (TOML): the vessel, the hull for wave drift, the towline, the
tug, the route, the sea states and what `jaxtow study` runs. The schema is documented in
docs/towfile.md and printed, commented, by ``jaxtow tow new``.

```python
import jaxtow as jt

tow = jt.tow.load("barge2a")            # a built-in (barge1, barge2a, barge2b) or a file path
model = tow.model()                     # the calm-water TowModel, with its scales
res = tow.resistance()                  # the TowResistance of jaxtow.resistance
sea = tow.sea_states[0]; m = tow.sea_model(sea)   # irregular-sea drift and wind on the tow
print(tow.show())                       # the resolved file, every default and estimate
```

Errors are `TowFileError` (a `ValueError`) naming the file, the line and the key; values
outside the physics' range (a Tp outside the physical range of its Hs) warn with
`TowFileWarning`.
"""

from ._schema import (
    SCHEMA as SCHEMA,
    TowFileError as TowFileError,
    TowFileWarning as TowFileWarning,
    schema_markdown as schema_markdown,
)
from ._tow import (
    BUILTIN_TOWS as BUILTIN_TOWS,
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

__all__ = [
    "SCHEMA",
    "TowFileError",
    "TowFileWarning",
    "BUILTIN_TOWS",
    "DEPRECATED_NAMES",
    "Tow",
    "builtin_text",
    "canonical_name",
    "load",
    "loads",
    "show",
    "template",
    "with_changes",
    "schema_markdown",
]

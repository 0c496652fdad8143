"""What a study looks like to a reader: the self-contained HTML report of a tow's assessment
(`tow_report_html`, from jinja2 templates) and the text of the thesis claims
(`claims_markdown`, `claims_table`, `attribution_text`). The numbers come from
`jaxtow.studies`; nothing here computes."""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._claims import (
        SOURCE_NAMES as SOURCE_NAMES,
        SOURCES as SOURCES,
        attribution_text as attribution_text,
        claims_markdown as claims_markdown,
        claims_table as claims_table,
    )
    from ._html import (
        REPORT_SECTIONS as REPORT_SECTIONS,
        criteria_lines as criteria_lines,
        tow_report_html as tow_report_html,
    )


__getattr__, __dir__, __all__ = _attach(__name__, __file__)

"""The one writer of the benchmark scripts' tables into the docs: the text between a begin and
an end marker (HTML comments naming the command that writes it) is replaced, or the marked
block appended where the page has none yet."""

from __future__ import annotations

from pathlib import Path


def write_block(page: Path, begin: str, end: str, text: str) -> None:
    """Put ``text`` between the markers ``begin`` and ``end`` of ``page``."""
    doc = page.read_text(encoding="utf-8")
    block = f"{begin}\n\n{text}\n\n{end}"
    if begin in doc:
        a, b = doc.index(begin), doc.index(end) + len(end)
        doc = doc[:a] + block + doc[b:]
    else:
        doc = doc.rstrip() + "\n\n" + block + "\n"
    page.write_text(doc, encoding="utf-8")

"""The thesis claims as text: the claims table of ``claims.md``, the attribution of each
claim that does not reproduce, and the page ``jaxtow report waves`` writes (from the records
of `jaxtow.studies.WaveStudy`)."""

from __future__ import annotations

#: The drift sources of the claims table, and their short names.
SOURCES = ("near_field", "far_field", "standin")
SOURCE_NAMES = {
    "near_field": "panel near field",
    "far_field": "panel far field",
    "standin": "stand-in",
}


def claims_table(claims: list) -> str:
    """The readable claims table: one row per claim, one column per (source, form)."""
    cols = sorted(
        {(c["source_key"], c["sailing_form"]) for c in claims},
        key=lambda k: (SOURCES.index(k[0]) if k[0] in SOURCES else 9, k[1]),
    )
    ids = list(dict.fromkeys(c["id"] for c in claims))
    by = {(c["id"], c["source_key"], c["sailing_form"]): c for c in claims}
    text = {c["id"]: c["claim"] for c in claims}
    head = "| claim | " + " | ".join(f"{SOURCE_NAMES.get(s, s)}, {f}" for s, f in cols) + " |"
    lines = [head, "|---" * (len(cols) + 1) + "|"]
    for i in ids:
        cells = []
        for s, f in cols:
            c = by.get((i, s, f))
            cells.append("-" if c is None else ("yes" if c["reproduced"] else "NO"))
        lines.append(f"| {text[i]} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def _brief(measured, limit: int = 4) -> str:
    """A few of a claim's measured numbers, for a table cell."""
    items = []

    def walk(prefix, v):
        if isinstance(v, dict):
            for k, x in v.items():
                walk(f"{prefix}{k}" if not prefix else f"{prefix}.{k}", x)
        elif isinstance(v, bool):
            items.append(f"{prefix} {'yes' if v else 'no'}")
        elif isinstance(v, (int, float)):
            items.append(f"{prefix} {float(v):.3g}")
        elif (
            isinstance(v, (list, tuple))
            and v
            and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in v)
        ):
            items.append(f"{prefix} " + "/".join(f"{float(x):.3g}" for x in v))

    walk("", measured)
    return "; ".join(items[:limit]) + (" …" if len(items) > limit else "")


def attribution_text(claims: list) -> str:
    """The attribution of each claim that carries one (`jaxtow.studies.attribute`), as
    markdown: the claim re-run at both ends of each estimate's plausible range, the panel
    variants, the gradient at the deciding point and what flips it."""
    out = []
    for c in claims:
        a = c.get("attribution")
        if not a:
            continue
        yes = "reproduced" if a["reproduced_at_attribution_grid"] else "not reproduced"
        out += [
            f"### {c['id']}",
            "",
            f"{c['claim']}. At the attribution grid ({a['grid_points_per_axis']} points per "
            f"axis) the claim is {yes}.",
            "",
            "| estimate | low end of the range | high end of the range |",
            "|---|---|---|",
        ]
        rows = dict(a["estimates"])
        pan = a.get("panel_estimates", {})
        rows.update(
            {f"{k} (panel variant)": v for k, v in pan.items() if k != "base_at_variant_mesh"}
        )
        for name, ends in rows.items():
            if not isinstance(ends, dict):
                out.append(f"| {name} | {ends} | |")
                continue
            cells = []
            for end in ("low", "high"):
                r = ends.get(end)
                if not isinstance(r, dict):
                    cells.append(str(r))
                    continue
                verdict = "reproduced" if r["reproduced"] else "not reproduced"
                cells.append(f"{r['value']}: {verdict} ({_brief(r['measured'], 2)})")
            out.append(f"| {name} | " + " | ".join(cells) + " |")
        if "base_at_variant_mesh" in pan:
            base = "reproduced" if pan["base_at_variant_mesh"] else "not reproduced"
            out += ["", f"Base database at the panel variants' mesh: {base}."]
        g = a.get("gradient")
        if isinstance(g, dict):
            parts = [
                f"{k} {v['relative_change_to_flip'] * 100:+.0f} %"
                for k, v in g["parameters"].items()
            ]
            out += [
                "",
                f"Deciding point {g['point']}: max Re λ {g['max_real']:.4g}; the linear change "
                f"of each estimate that would make it {g['wanted']}: " + ", ".join(parts) + ".",
            ]
        elif g:
            out += ["", f"Gradient: {g}."]
        flips = a.get("flipped_by") or []
        out += [
            "",
            "Flipped by: " + (", ".join(flips) if flips else "none of the estimates") + ".",
            "",
        ]
    return "\n".join(out)


def claims_markdown(claims: list, sources: dict) -> str:
    """``claims.md``: the claims table, the drift sources ({key: description}) and, where
    claims carry one, the readable attribution."""
    attributed = any(c.get("attribution") for c in claims)
    return (
        "# Thesis claims by drift source and sailing-drift form\n\n"
        + claims_table(claims)
        + "\nDrift sources:\n\n"
        + "".join(f"* {SOURCE_NAMES.get(k, k)}: {v}\n" for k, v in sources.items())
        + (
            "\n## Attribution of the claims that do not reproduce (primary source and form)\n\n"
            + attribution_text(claims)
            + "\nThe numbers behind each row are in claims.json, key 'attribution'.\n"
            if attributed
            else ""
        )
    )

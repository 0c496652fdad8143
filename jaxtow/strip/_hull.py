"""Hulls for strip theory: stations of half offsets and the built-in box, raked box, Wigley
and Lewis-form hulls (geometry only; the strip integrals are in `jaxtow.strip._strips`, an
offsets table file is read by `jaxtow.io.read_offsets`).

Axes: x forward from midships, y to port, z up from the waterline; pitch is positive bow
down and yaw bow to port. Every station has the same number of offsets (so that the section
solve is vmapped over them), from the waterline (y = B(x)/2, z = 0) to the keel on the
centreline. Strips are the midpoint rule: station i stands for the strip of length
``dx[i]`` around ``x[i]``; stations at the very ends of a fine hull, where the breadth is
zero, carry no section and are left out.

Every constructor is a JAX function of its dimensions (jit, grad and vmap over L, B, T, the
rakes and α); the checks of a hull's values are `jaxtow.Rule` checks, eager on numbers and
`equinox.error_if` under tracing (`Hull.checks`).
"""

from __future__ import annotations

import equinox as eqx
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Float

from .._rules import POSITIVE, Checked, ParameterError, Rule, is_concrete, rule_field

#: The zero-speed radiation modes of a hull: sway, heave, roll, pitch, yaw (ship modes 2-6).
MODES = ("sway", "heave", "roll", "pitch", "yaw")

#: How far above the still waterline an offset may lie and still count as on it [m] (the
#: rounding of offsets read from a file or cut from a mesh).
WATERLINE_TOL = 1e-9

_HALF_BREADTH = Rule(
    "must be half-breadths >= 0 (y to port of the centreline)",
    lambda xp, x: xp.isfinite(x) & (x >= 0),
)
_BELOW = Rule(
    f"must be heights <= 0 (z up from the waterline, negative below it; {WATERLINE_TOL:g} m "
    "of rounding allowed): are the heights given positive downwards?",
    lambda xp, x: xp.isfinite(x) & (x <= WATERLINE_TOL),
)
_STRIP = Rule("must be finite", lambda xp, x: xp.isfinite(x))


def _order(xp, y, z):
    """True per station where the offsets run from the waterline down to the keel: the first
    offset is the highest, the last on the centreline, and the last is the deepest."""
    top = z[:, 0] >= xp.max(z, axis=1) - WATERLINE_TOL
    keel = z[:, -1] <= z[:, 0]
    return top & keel


class Hull(Checked):
    """A hull by its stations: ``x`` (n,) [m], strip lengths ``dx`` (n,) [m], half offsets
    ``y``, ``z`` (n, m) [m] from the waterline (y = B/2, z = 0) down to the keel on the
    centreline (y = 0). Offsets given keel-first, or heights positive downwards, are refused
    with the parameter named (eagerly, or by `checks` under tracing)."""

    x: Float[Array, " n"] = rule_field(rule=_STRIP)
    dx: Float[Array, " n"] = rule_field(rule=POSITIVE)
    y: Float[Array, "n m"] = rule_field(rule=_HALF_BREADTH)
    z: Float[Array, "n m"] = rule_field(rule=_BELOW)
    name: str = eqx.field(static=True, default="hull")
    #: whether the hull ends aft in a transom (the aftmost station's section, not a point):
    #: the forward-speed end terms of Salvesen, Tuck & Faltinsen act there
    transom: bool = eqx.field(static=True, default=False)

    def __check_init__(self):
        shape = jnp.shape(self.y)
        if len(shape) != 2 or jnp.shape(self.z) != shape or shape[1] < 3:
            raise ValueError(
                f"parameters 'y' and 'z' must be (stations, offsets) arrays of one shape with at "
                f"least 3 offsets, got {jnp.shape(self.y)} and {jnp.shape(self.z)}"
            )
        if jnp.shape(self.x) != shape[:1] or jnp.shape(self.dx) != shape[:1]:
            raise ValueError(
                f"parameters 'x' and 'dx' must have one value per station ({shape[0]})"
            )
        super().__check_init__()
        if is_concrete(self.z) and is_concrete(self.y) and is_concrete(self.x):
            ok = np.asarray(_order(np, np.asarray(self.y), np.asarray(self.z)))
            if not ok.all():
                i = int(np.flatnonzero(~ok)[0])
                raise ParameterError(
                    "y, z", _ORDER_MESSAGE + f" (station {i} at x = {float(self.x[i]):g} m)"
                )

    def checks(self) -> list:
        return super().checks() + [(~jnp.all(_order(jnp, self.y, self.z)), _ORDER_MESSAGE)]

    @property
    def length(self):
        """The strips' total length [m]."""
        return jnp.sum(self.dx)

    @property
    def breadth(self):
        """The largest breadth at the waterline [m]."""
        return 2.0 * jnp.max(self.y[:, 0])

    @property
    def draft(self):
        """The deepest keel [m]."""
        return -jnp.min(self.z)


_ORDER_MESSAGE = (
    "parameters 'y', 'z': each station's offsets must run from the waterline (y = B/2, z = 0) "
    "down to the keel on the centreline (y = 0); these run keel-first or upwards"
)


def _check_positive(**values) -> None:
    for name, v in values.items():
        POSITIVE.check(name, v)


def _strips(length, n_stations: int):
    """Station positions and strip lengths of ``n_stations`` equal strips over ``length``."""
    if n_stations < 2:
        raise ValueError(f"parameter 'n_stations' must be >= 2, got {n_stations!r}")
    dx = jnp.asarray(length, float) / n_stations
    x = -0.5 * length + dx * (jnp.arange(n_stations) + 0.5)
    return x, jnp.full(n_stations, dx)


def box(
    length,
    breadth,
    draft,
    *,
    n_stations: int = 21,
    n_side: int = 6,
    n_bottom: int = 6,
) -> Hull:
    """A wall-sided box (Barge 1 of the thesis): rectangular sections B x T."""
    _check_positive(length=length, breadth=breadth, draft=draft)
    x, dx = _strips(length, n_stations)
    half = 0.5 * jnp.asarray(breadth, float)
    s_side = jnp.linspace(0.0, 1.0, n_side + 1)
    s_bottom = jnp.linspace(1.0, 0.0, n_bottom + 1)[1:]
    ys = jnp.concatenate([jnp.full(n_side + 1, 1.0) * half, s_bottom * half])
    zs = jnp.concatenate([-s_side * draft, jnp.full(n_bottom, 1.0) * -draft])
    n = x.shape[0]
    return Hull(x, dx, jnp.tile(ys, (n, 1)), jnp.tile(zs, (n, 1)), "box", True)


def raked_box(
    length,
    breadth,
    draft,
    rake,
    *,
    bow_rake=None,
    n_stations: int = 21,
    n_side: int = 6,
    n_bottom: int = 6,
) -> Hull:
    """A barge with a rectangular L × B waterline whose stern and bow faces run straight from
    the waterline (x = ∓L/2) down to the keel at x = ∓(L/2 − rake): rectangular sections
    B × d(x), d = T min(1, (L/2 + x)/rake, (L/2 − x)/bow_rake) (``bow_rake`` defaults to
    ``rake``; the hull of `jaxtow.bem.meshes.raked_barge_mesh`; Barge 2 with
    `jaxtow.presets.barge2_hull`). The raked ends close at the waterline, so the hull has no
    transom (``rake = 0`` at both ends is `box`, which has). Differentiable in the rakes."""
    bow_rake = rake if bow_rake is None else bow_rake
    if is_concrete(rake) and is_concrete(bow_rake) and float(rake) == float(bow_rake) == 0:
        return box(length, breadth, draft, n_stations=n_stations, n_side=n_side, n_bottom=n_bottom)
    for name, v in (("rake", rake), ("bow_rake", bow_rake)):
        if is_concrete(v) and is_concrete(length) and not (0 < float(v) < float(length)):
            raise ValueError(f"parameter {name!r} must lie in (0, length), got {float(v)!r}")
    hull = box(length, breadth, draft, n_stations=n_stations, n_side=n_side, n_bottom=n_bottom)
    x = hull.x
    depth = draft * jnp.minimum(
        1.0, jnp.minimum((0.5 * length + x) / rake, (0.5 * length - x) / bow_rake)
    )
    z = hull.z * (depth / draft)[:, None]
    return Hull(hull.x, hull.dx, hull.y, z, "raked_box", False)


def lewis_section(breadth, draft, sigma, *, n_points: int = 12):
    """Half offsets (y, z) of a Lewis-form section (Lewis 1929): the conformal map
    y = M((1 + a₁) sin θ − a₃ sin 3θ), z = −M((1 − a₁) cos θ + a₃ cos 3θ), θ from π/2 (the
    waterline, y = B/2) to 0 (the keel), whose three coefficients give the beam ``breadth``,
    the draft ``draft`` and the area coefficient ``sigma`` = A/(BT) exactly (the form of
    Journée & Adegeest, "Theoretical manual of strip theory program SEAWAY", TU Delft report
    1370). The cheap hull description of three numbers per station; the section is then
    solved by the close-fit method like any other. Points are cosine-spaced in θ.
    Differentiable in the three numbers. Raises ValueError naming ``sigma`` where no Lewis
    form has that area coefficient at that B/2T (the map would loop)."""
    h0 = breadth / (2.0 * draft)
    c1 = (3.0 + 4.0 * sigma / jnp.pi) + (1.0 - 4.0 * sigma / jnp.pi) * (
        (h0 - 1.0) / (h0 + 1.0)
    ) ** 2
    disc = 9.0 - 2.0 * c1
    if is_concrete(disc) and not (float(disc) >= 0 and float(breadth) > 0 and float(draft) > 0):
        raise ValueError(
            f"parameter 'sigma' = {float(sigma):g}: no Lewis form has that area coefficient "
            f"at B/2T = {float(h0):g} (and breadth, draft must be > 0)"
        )
    a3 = (-c1 + 3.0 + jnp.sqrt(jnp.maximum(disc, 0.0))) / c1
    a1 = (h0 - 1.0) * (a3 + 1.0) / (h0 + 1.0)
    scale = 0.5 * breadth / (1.0 + a1 + a3)
    theta = 0.25 * jnp.pi * (1.0 + jnp.cos(jnp.linspace(0.0, jnp.pi, n_points)))  # π/2 → 0
    y = scale * ((1.0 + a1) * jnp.sin(theta) - a3 * jnp.sin(3.0 * theta))
    z = -scale * ((1.0 - a1) * jnp.cos(theta) + a3 * jnp.cos(3.0 * theta))
    if is_concrete(y) and np.any(np.asarray(y) < -1e-9 * float(breadth)):
        raise ValueError(
            f"parameter 'sigma' = {float(sigma):g}: the Lewis form at B/2T = {float(h0):g} "
            "crosses the centreline"
        )
    return y.at[-1].set(0.0), z


def lewis_hull(x, dx, breadth, draft, sigma, *, n_points: int = 12, name: str = "lewis") -> Hull:
    """A hull of Lewis-form sections (`lewis_section`) from its sectional particulars:
    station x and strip length dx [m], breadth and draft [m] and area coefficient of each
    station (arrays of one length, or scalars broadcast); no transom."""
    x, dx, breadth, draft, sigma = jnp.broadcast_arrays(
        *(jnp.asarray(v, dtype=float) for v in (x, dx, breadth, draft, sigma))
    )
    secs = [
        lewis_section(b, t, s, n_points=n_points)
        for b, t, s in zip(breadth, draft, sigma, strict=True)
    ]
    return Hull(x, dx, jnp.stack([y for y, _ in secs]), jnp.stack([z for _, z in secs]), name)


def wigley(
    length,
    breadth,
    draft,
    *,
    alpha=None,
    n_stations: int = 21,
    n_points: int = 12,
) -> Hull:
    """The Wigley hull y = (B/2)(1 − ξ²)(1 − ζ²), ξ = 2x/L, ζ = z/T, the mathematical hull of
    many seakeeping experiments; with ``alpha``, the fuller form of Journée's (1992, Delft
    report 909) four models, y = (B/2)[(1 − ζ²)(1 − ξ²)(1 + 0.2ξ²) + α ζ²(1 − ζ⁸)(1 − ξ²)⁴]
    (α = 1: models I and II, midship coefficient 0.909; α = 0: III and IV, 0.667; all at
    L = 3 m, T = 0.1875 m, B = 0.3 m (I, III) or 0.6 m (II, IV)). Offsets at n_points depths,
    cosine-spaced towards the waterline and the keel. Differentiable in L, B, T and α."""
    _check_positive(length=length, breadth=breadth, draft=draft)
    if alpha is not None and is_concrete(alpha) and not (np.isfinite(alpha) and alpha >= 0):
        raise ValueError(f"parameter 'alpha' must be None or a finite number >= 0, got {alpha!r}")
    x, dx = _strips(length, n_stations)
    s = 0.5 * (1.0 - jnp.cos(jnp.linspace(0.0, jnp.pi, n_points)))
    zs = -draft * s
    ys = 0.5 * breadth * wigley_form((2.0 * x / length)[:, None] ** 2, (s**2)[None, :], alpha)
    return Hull(x, dx, ys, jnp.tile(zs, (x.shape[0], 1)), "wigley")


def wigley_form(xi2, zeta2, alpha=None):
    """The half-breadth of `wigley` over B/2 at ξ² = (2x/L)² and ζ² = (z/T)² (NumPy or JAX
    arrays): (1 − ξ²)(1 − ζ²), or with ``alpha`` Journée's form."""
    if alpha is None:
        return (1.0 - xi2) * (1.0 - zeta2)
    eta = (1.0 - zeta2) * (1.0 - xi2) * (1.0 + 0.2 * xi2)
    return eta + alpha * zeta2 * (1.0 - zeta2**4) * (1.0 - xi2) ** 4


def resample_contour(y, z, n_points: int):
    """``n_points`` half offsets along the section contour through the points (y, z) [m],
    from the waterline down to the keel, then closed to the centreline at the keel: the
    panels follow the contour's arc length, the corners (turns over 20°) are kept as panel
    ends, and each straight piece gets panels in proportion to its length (at least one),
    cosine-spaced towards its ends. Points below where the contour first reaches the
    centreline are dropped. NumPy (for files and meshes; not differentiable)."""
    y, z = np.asarray(y, float), np.asarray(z, float)
    on_axis = np.flatnonzero(y <= 1e-12 * max(np.max(y), 1e-300))
    stop = on_axis[0] + 1 if on_axis.size else y.size
    y, z = y[:stop], z[:stop]
    if y[-1] > 0:  # close to the centreline along the keel
        y, z = np.r_[y, 0.0], np.r_[z, z[-1]]
    p = np.stack([y, z], axis=1)
    keep = np.r_[True, np.linalg.norm(np.diff(p, axis=0), axis=1) > 1e-12 * np.ptp(p)]
    p = p[keep]
    d = np.diff(p, axis=0)
    heading = np.arctan2(d[:, 1], d[:, 0])
    turn = np.abs((np.diff(heading) + np.pi) % (2 * np.pi) - np.pi)
    corners = np.r_[0, np.flatnonzero(turn > np.radians(20.0)) + 1, len(p) - 1]
    arc = np.r_[0.0, np.cumsum(np.linalg.norm(d, axis=1))]
    pieces = np.diff(arc[corners])
    n_panels = n_points - 1
    if n_panels < len(pieces):
        raise ValueError(
            f"parameter 'n_points' = {n_points}: the contour has {len(pieces)} straight pieces, "
            f"so it needs at least {len(pieces) + 1} points"
        )
    share = np.maximum(1, np.floor(pieces / pieces.sum() * n_panels).astype(int))
    while share.sum() < n_panels:
        share[np.argmax(pieces / share)] += 1
    while share.sum() > n_panels:
        share[np.argmax(np.where(share > 1, share / pieces, -1))] -= 1
    s = [arc[corners[0] : corners[0] + 1]]
    for k, m in enumerate(share):
        a0, a1 = arc[corners[k]], arc[corners[k + 1]]
        t = 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, m + 1)[1:]))
        s.append(a0 + t * (a1 - a0))
    s = np.concatenate(s)
    return np.interp(s, arc, p[:, 0]), np.interp(s, arc, p[:, 1])

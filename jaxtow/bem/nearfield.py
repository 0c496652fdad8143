"""Near-field (pressure-integration) mean drift force, Pinkster (1980); thesis section 2.3.1.

NumPy only: the first-order fields come from any source (Capytaine in
`jaxtow.bem.solve`, the analytic MacCamy-Fuchs solution in `jaxtow.bem.reference`).

Conventions: complex amplitudes with time dependence e^{−iωt} (Capytaine's), per unit
incident wave amplitude; the mean of a product of two first-order quantities is
⟨Re(a e^{−iωt}) Re(b e^{−iωt})⟩ = ½ Re(a b*). Normals n point out of the hull into the
water; the force on the hull is −∬ p n dS.

With the first-order velocity potential Φ, the relative wave elevation
ζ_r = ζ − X_z at the waterline (ζ = −Φ_t/g at z = 0), the first-order displacement of a hull
point X = ξ + α × (x − x_G) (ξ: translation of the CoG, α: rotation) and the hull mass M, the
mean second-order force in the earth-fixed frame is the sum of (thesis fig. 2.11, parts I-IV)

    I   −½ρg ∮_WL ⟨ζ_r²⟩ n / √(1 − n_z²) dl      relative wave elevation
    II  +½ρ ∬_S0 ⟨|∇Φ|²⟩ n dS                     velocity squared (Bernoulli)
    III +ρ  ∬_S0 ⟨(X·∇)Φ_t⟩ n dS                  pressure gradient along the motion
    IV  +⟨α × M ẍ_G⟩                              rotation of the first-order inertia force

and the yaw moment about the vertical axis through the CoG is the same sum with
(x − x_G) dF_y − (y − y_G) dF_x per element, and IV = ⟨α × I_G α̈⟩_z =
−½ω²(I_yy − I_xx) Re(α_x α_y*). The second-order potential contributes nothing to the mean
force in regular waves. The factor 1/√(1 − n_z²) in I turns the waterline element into the
strip of hull surface between the mean and the instantaneous waterline; its horizontal part
is the unit horizontal normal, so flare does not change the horizontal force.

Sectional moments (thesis eqs 2.43-2.48): with dF the per-element horizontal force of parts
I-III (the pressure part; part IV is a rigid-body term and is not distributed, as in the
thesis), M_x,j = Σ x_c^j dF_x and M_y,j = Σ x_c^j dF_y, j = 0, 1, 2, x_c measured from the CoG.
"""

from __future__ import annotations

import dataclasses

import numpy as np


def _mean(a, b):
    """⟨a b⟩ for complex amplitudes (elementwise; sums over a trailing vector axis if given)."""
    return 0.5 * np.real(a * np.conj(b))


def displacement(points, motion, cog):
    """First-order displacement X = ξ + α × (x − x_G) at ``points`` (n, 3) for ``motion``
    (..., 6) = (ξ1, ξ2, ξ3, α1, α2, α3) about ``cog``; returns (..., n, 3) complex."""
    r = np.asarray(points, float) - np.asarray(cog, float)
    xi = motion[..., None, :3]
    al = motion[..., None, 3:]
    return xi + np.cross(al, r)


@dataclasses.dataclass(frozen=True)
class NearFieldDrift:
    """`near_field_drift`'s answer per heading: the mean drift ``force`` (fx, fy, nz), its
    ``parts`` I-IV, and the ``sectional`` moments for the yaw-rate drift damping."""

    force: np.ndarray
    parts: np.ndarray
    sectional: np.ndarray


def near_field_drift(*, omega, rho, g, panels, waterline, mass, inertia, cog, motion=None):
    """Mean drift (Fx, Fy, Nz) per ζa² by pressure integration, with its parts and sectional moments.

    ``panels``: dict with ``centres`` (n, 3), ``normals`` (n, 3, into the water),
    ``areas`` (n,) and ``velocity`` (..., n, 3) complex: the total first-order fluid velocity
    ∇φ (incident + diffracted + radiated) at the panel centres, per unit wave amplitude.
    ``waterline``: dict with ``points`` (m, 3) midpoints, ``normals`` (m, 3) (the owning
    panels' normals), ``lengths`` (m,) and ``potential`` (..., m) complex: the total φ there.
    ``motion``: (..., 6) complex RAO about ``cog`` (None: fixed body). ``inertia``: (3, 3)
    about the CoG. Leading axes (e.g. wave headings) broadcast.

    Returns a dict of arrays over the leading axes: ``force`` (..., 3) = (Fx, Fy, Nz),
    ``parts`` (..., 4, 3) for parts I-IV, ``sectional`` (..., 2, 3) = (M_x,j, M_y,j) for
    j = 0, 1, 2.
    """
    omega = float(omega)
    c, n, a = (np.asarray(panels[k], float) for k in ("centres", "normals", "areas"))
    u = np.asarray(panels["velocity"])
    wp, wn, wl = (np.asarray(waterline[k], float) for k in ("points", "normals", "lengths"))
    phi = np.asarray(waterline["potential"])
    lead = u.shape[:-2]
    if motion is None:
        motion = np.zeros(lead + (6,), complex)
    motion = np.asarray(motion)
    cog = np.asarray(cog, float)

    # I: relative wave elevation on the waterline
    zeta = 1j * omega / g * phi
    zr = zeta - displacement(wp, motion, cog)[..., 2]
    nh = wn[:, :2] / np.linalg.norm(wn[:, :2], axis=1, keepdims=True)
    dF1 = (-0.5 * rho * g * _mean(zr, zr) * wl)[..., None] * nh  # (..., m, 2)

    # II: velocity squared; III: motion along the pressure gradient (∇Φ_t = −iω ∇φ)
    u2 = np.sum(_mean(u, u), axis=-1)
    dF2 = (0.5 * rho * u2 * a)[..., None] * n[:, :2]
    X = displacement(c, motion, cog)
    xgp = np.sum(_mean(X, -1j * omega * u), axis=-1)
    dF3 = (rho * xgp * a)[..., None] * n[:, :2]

    def totals(dF, pts):
        r = pts[:, :2] - cog[:2]
        nz = np.sum(r[:, 0] * dF[..., 1] - r[:, 1] * dF[..., 0], axis=-1)
        return np.concatenate([np.sum(dF, axis=-2), nz[..., None]], axis=-1)

    p1, p2, p3 = totals(dF1, wp), totals(dF2, c), totals(dF3, c)
    # IV: rotation of the first-order inertia force / moment
    xi, al = motion[..., :3], motion[..., 3:]
    f4 = -0.5 * mass * omega**2 * np.real(np.cross(al, np.conj(xi)))
    iyy_ixx = inertia[1, 1] - inertia[0, 0]
    n4 = -0.5 * omega**2 * iyy_ixx * np.real(al[..., 0] * np.conj(al[..., 1]))
    p4 = np.concatenate([f4[..., :2], n4[..., None]], axis=-1)
    parts = np.stack([p1, p2, p3, p4], axis=-2)

    xs = np.concatenate([wp[:, 0], c[:, 0]]) - cog[0]
    dF = np.concatenate([dF1, dF2 + dF3], axis=-2)
    sectional = np.stack(
        [np.sum(xs[:, None] ** j * dF, axis=-2) for j in range(3)], axis=-1
    )  # (..., 2, 3)
    return NearFieldDrift(force=parts.sum(axis=-2), parts=parts, sectional=sectional)


def surface_gradient_operator(
    vertices, faces, centres, normals, wl_points=None, wl_owner=None, *, coplanar: float = 0.9
):
    """Sparse operator for the tangential gradient of a function known at the panel centres
    (and optionally at waterline points), by a local least-squares quadratic fit.

    A constant-panel source method gives the potential at the collocation points to second
    order but its surface velocity (the source gradient) only to first order, which
    underestimates the velocity near the free surface where it varies as e^{kz}. Fitting
    φ(s, t) = φ_i + a s + b t + c s² + d st + e t² in the panel's tangent plane to the values at
    the panels that share a vertex with it on the same face (normals within 26°:
    ``coplanar`` = cos of the angle; the hull's sharp edges are excluded), plus the waterline
    points of those panels, gives (a, b) to second order
    in the interior and, with the waterline values, also in the top row of panels.

    Returns (index (n, k) into the data vector [centres..., waterline points...], padded with
    the panel's own index, weights (n, k, 3)): ∇_t f_i = Σ_k weights[i, k] (f[index[i, k]] − f_i).
    """
    n = len(faces)
    vf: dict[int, set] = {}
    for i, f in enumerate(faces):
        for v in set(int(x) for x in f):
            vf.setdefault(v, set()).add(i)
    wl_by_panel: dict[int, list] = {}
    if wl_points is not None:
        for j, o in enumerate(wl_owner):
            wl_by_panel.setdefault(int(o), []).append(n + j)
    pts = centres if wl_points is None else np.concatenate([centres, wl_points])
    rows, wts = [], []
    for i in range(n):
        nb = set()
        for v in set(int(x) for x in faces[i]):
            nb |= vf[v]
        nb = sorted(j for j in nb if j != i and normals[j] @ normals[i] > coplanar)
        data = list(nb)
        for j in [i] + nb:
            data += wl_by_panel.get(j, [])
        e1 = vertices[faces[i][2]] - vertices[faces[i][0]]  # a diagonal: never degenerate
        e1 = e1 - (e1 @ normals[i]) * normals[i]
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(normals[i], e1)
        d = pts[data] - centres[i]
        s, t = d @ e1, d @ e2
        h = max(np.sqrt(np.mean(s * s + t * t)), 1e-12)
        s, t = s / h, t / h
        A = np.stack([s, t, s * s, s * t, t * t], axis=1)
        if len(data) < 5 or np.linalg.matrix_rank(A, tol=1e-6) < 5:
            A = A[:, :2]
        if len(data) < 2 or np.linalg.matrix_rank(A, tol=1e-6) < 2:
            raise ValueError(
                f"panel {i} has too few neighbours on its face for a surface gradient; refine the mesh"
            )
        P = np.linalg.pinv(A)[:2] / h  # (2, k): rows give a, b
        rows.append(data)
        wts.append(P[0][:, None] * e1 + P[1][:, None] * e2)
    k = max(len(r) for r in rows)
    index = np.array([r + [i] * (k - len(r)) for i, r in enumerate(rows)])
    weights = np.zeros((n, k, 3))
    for i, w in enumerate(wts):
        weights[i, : len(w)] = w
    return index, weights


def apply_gradient(index, weights, f):
    """Tangential gradient (n, ..., 3) of data ``f`` (n_data, ...) with `surface_gradient_operator`."""
    n = index.shape[0]
    diff = f[index] - f[:n][:, None]  # (n, k, ...)
    return np.einsum("nk...,nkc->n...c", diff, weights)

"""Hulls for strip theory: the strip integrals against their closed forms on a box, the
Wigley hull, an offsets file, gradients, and the committed comparison with the panel
method (benchmarks/strip_vs_capytaine.py)."""

import json
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np
import pytest

import jaxtow as jt
import jaxtow.strip as S

ROOT = Path(__file__).parents[1]


@pytest.mark.slow
def test_box_strip_integrals_are_the_section_times_the_lever_moments():
    """Uniform sections: A33 = L a33, A35 = 0, A55 = a33 Σ x² dx = a33 L³/12 (1 − 1/n²),
    A66 = a22 L³/12 (1 − 1/n²), A26 = 0, and sway-roll as the section's."""
    L, n = 76.2, 21
    hull = S.box(L, 24.4, 5.0, n_stations=n)
    om = np.array([0.5, 0.9])
    c = S.hull_coefficients(hull, om)
    sec = S.section_coefficients(hull.y[0], hull.z[0], om)
    lever = L**3 / 12 * (1 - 1 / n**2)
    a, s = np.asarray(c.added_mass), np.asarray(sec.added_mass)
    assert np.allclose(a[:, 1, 1], L * s[:, 1, 1], rtol=1e-10)
    assert np.allclose(a[:, 3, 3], lever * s[:, 1, 1], rtol=1e-10)
    assert np.allclose(a[:, 4, 4], lever * s[:, 0, 0], rtol=1e-10)
    assert np.allclose(a[:, 0, 2], L * s[:, 0, 2], rtol=1e-10)
    assert np.max(np.abs(a[:, 1, 3])) < 1e-9 * np.max(a[:, 1, 1]) * L
    assert np.max(np.abs(a[:, 0, 4])) < 1e-9 * np.max(a[:, 0, 0]) * L
    b = np.asarray(c.damping)
    assert np.all(b[:, 1, 1] > 0) and np.all(b[:, 3, 3] > 0)


@pytest.mark.slow
def test_wigley_hull_is_symmetric_and_positive():
    hull = S.wigley(3.0, 0.3, 0.1875, n_stations=20)
    c = S.hull_coefficients(hull, np.array([4.0, 6.0]))
    a = np.asarray(c.added_mass)
    assert np.all(a[:, 1, 1] > 0) and np.all(a[:, 3, 3] > 0)
    assert np.max(np.abs(a[:, 1, 3])) < 1e-8 * a[0, 1, 1] * 3.0  # fore-aft symmetric
    assert np.all(np.asarray(c.damping)[:, 1, 1] > 0)
    # the sections follow y = (B/2)(1 − (2x/L)²)(1 − (z/T)²)
    x = np.asarray(hull.x)
    assert np.allclose(np.asarray(hull.y)[:, 0], 0.15 * (1 - (2 * x / 3.0) ** 2))
    assert np.allclose(np.asarray(hull.y)[:, -1], 0.0) and np.allclose(
        np.asarray(hull.z)[:, -1], -0.1875
    )


@pytest.mark.parametrize("alpha, cm", [(1.0, 0.909), (0.0, 2.0 / 3.0)])
def test_journee_wigley_forms_have_their_midship_coefficients(alpha, cm):
    """Journée's (1992) Wigley forms: the midship section's area over B T is 0.909 for
    models I and II (α = 1) and 2/3 for III and IV (α = 0); the waterline is the classic
    form times (1 + 0.2ξ²); a negative α is refused by name."""
    hull = S.wigley(3.0, 0.3, 0.1875, alpha=alpha, n_stations=21, n_points=201)
    y, z = np.asarray(hull.y)[10], np.asarray(hull.z)[10]
    assert np.asarray(hull.x)[10] == pytest.approx(0.0, abs=1e-12)
    area = 2 * np.trapezoid(y[::-1], z[::-1])
    assert area / (0.3 * 0.1875) == pytest.approx(cm, rel=2e-4)
    xi = 2 * np.asarray(hull.x) / 3.0
    assert np.allclose(np.asarray(hull.y)[:, 0], 0.15 * (1 - xi**2) * (1 + 0.2 * xi**2))
    with pytest.raises(ValueError, match="'alpha'"):
        S.wigley(3.0, 0.3, 0.1875, alpha=-1.0)


def test_offsets_file_reads_a_box(tmp_path):
    path = tmp_path / "box.csv"
    xs = np.linspace(-38.1, 38.1, 22)
    lines = ["# a box barge, half-breadths at the waterline heights", "x,0,-2.5,-5"]
    lines += [f"{x},12.2,12.2,12.2" for x in xs]
    path.write_text("\n".join(lines) + "\n")
    hull = jt.io.read_offsets(path, n_points=10)
    assert hull.name == "box" and hull.y.shape == (22, 10)
    assert float(jnp.sum(hull.dx)) == pytest.approx(76.2)
    assert np.allclose(np.asarray(hull.x), xs)
    # each station: the side at half-breadth 12.2 m from the waterline to the bilge, then
    # the bottom at 5 m to the centreline, with the bilge corner kept as a panel end
    _assert_box_sections(hull, 12.2, 5.0)


def _assert_box_sections(hull, half, draft):
    y, z = np.asarray(hull.y), np.asarray(hull.z)
    side = np.isclose(y, half)
    bottom = np.isclose(z, -draft)
    assert np.all(side | bottom)  # every offset on the side or the bottom
    assert np.all(np.any(side & bottom, axis=1))  # the corner in every section
    assert np.allclose(z[:, 0], 0.0) and np.allclose(y[:, -1], 0.0)
    assert np.all(np.diff(z, axis=1) <= 0) and np.all(np.diff(y, axis=1) <= 0)


@pytest.mark.parametrize(
    "text, match",
    [
        ("x,0,-1\n0,1,1\n", "at least two stations"),
        ("x,-0.5,-1\n0,1,1\n1,1,1\n", "include 0"),
        ("x,0,-1\n0,1\n1,1,1\n", "half-breadths"),
        ("x,0,-1\n1,1,1\n0,1,1\n", "increase"),
        ("x,0,-1\n0,1,a\n1,1,1\n", "row 2 of the table is not all numbers"),
    ],
)
def test_bad_offsets_files_are_named(tmp_path, text, match):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(ValueError, match=match) as e:
        jt.io.read_offsets(path)
    assert "bad.csv" in str(e.value)


@pytest.mark.slow
def test_hull_gradient_in_the_breadth_equals_finite_differences():
    def a33(breadth):
        hull = S.wigley(3.0, breadth, 0.1875, n_stations=6, n_points=6)
        return S.hull_coefficients(hull, jnp.array([5.0])).added_mass[0, 1, 1]

    g = float(jax.grad(a33)(0.3))
    h = 1e-6
    fd = (float(a33(0.3 + h)) - float(a33(0.3 - h))) / (2 * h)
    assert g == pytest.approx(fd, rel=1e-5)


@pytest.mark.slow
def test_committed_panel_comparison_matches_the_strip_side():
    """benchmarks/data/strip/box_zero_speed.json: the strip values recomputed here equal the
    file's (so the table in docs/strip.md is what the code gives); the panel side is
    Capytaine's, reproduced by the benchmark's command."""
    data = json.loads((ROOT / "benchmarks" / "data" / "strip" / "box_zero_speed.json").read_text())
    hull = S.box(76.2, 24.4, 5.0, **data["strip"])
    c = S.hull_coefficients(hull, np.array(data["omega"]))
    modes = list(S.MODES)
    for r in data["rows"]:
        i, k = data["omega"].index(r["omega"]), modes.index(r["mode"])
        assert float(c.added_mass[i, k, k]) == pytest.approx(r["strip_a"], rel=1e-8)
        assert float(c.damping[i, k, k]) == pytest.approx(r["strip_b"], rel=1e-8)
    om = np.array([r["omega"] for r in data["head_sea_raos"]])
    raos = np.asarray(S.motions(hull, om, [0.0], loading=jt.Loading(z_g=data["z_g"])).rao)[:, 0][
        :, [1, 3]
    ]
    for i, r in enumerate(data["head_sea_raos"]):
        assert abs(raos[i, 0]) == pytest.approx(r["strip_heave"], rel=1e-8)
        assert abs(raos[i, 1]) == pytest.approx(r["strip_pitch"], rel=1e-8)
    # strip theory and the panel method agree where the waves are long against the hull
    long = [r for r in data["head_sea_raos"] if r["omega"] <= 0.6]
    assert all(abs(r["strip_heave"] / r["panel_heave"] - 1) < 0.04 for r in long)
    assert all(abs(r["strip_pitch"] / r["panel_pitch"] - 1) < 0.03 for r in long)


@pytest.mark.slow
def test_strip_wave_force_at_beam_seas_is_the_direct_diffraction_force():
    """The Haskind form of strip theory (Froude-Krylov plus the radiation potentials) at
    sin χ = 1 is the 2-D beam-sea problem, which the section solve also answers directly by
    its diffraction potential: the two agree within the panels' error (0.3 %)."""
    from jaxtow.strip._strips import section_wave_forces

    ys = np.r_[np.full(13, 1.0), np.linspace(1.0, 0.0, 13)[1:]]
    zs = np.r_[np.linspace(0.0, -1.0, 13), np.full(12, -1.0)]
    om = jnp.array([1.0, 2.0, 3.0])
    c = S.section_coefficients(ys, zs, om)
    fk, dif = section_wave_forces(
        jnp.asarray(ys), jnp.asarray(zs), c.potentials, om, jnp.ones(3), jt.SEA_WATER
    )
    x = np.asarray(fk + dif)
    ref = np.asarray(c.exciting)
    assert np.max(np.abs(x - ref) / np.abs(ref).max(axis=0)) < 3e-3


@pytest.mark.slow
def test_box_hydrostatics_and_long_wave_raos():
    """Barge 1: ∇ = LBT, z_B = −T/2; in long head waves the box rides the wave: heave RAO → 1
    and pitch RAO → k (the wave slope), to 0.1 % at ω = 0.1 rad/s."""
    hull = S.box(76.2, 24.4, 5.0, n_stations=11)
    hs = S.hydrostatics(hull)
    assert float(hs.volume) == pytest.approx(76.2 * 24.4 * 5.0)
    assert float(hs.z_b) == pytest.approx(-2.5)
    assert float(hs.area) == pytest.approx(76.2 * 24.4)
    om = np.array([0.1, 0.15])
    # with G at B the strips' pitch restoring is the waterplane's alone, as their exciting
    # moment (strip theory has no surge force to lever)
    m = S.motions(hull, om, np.array([0.0, np.pi / 2]), loading=jt.Loading(z_g=-2.5))
    r = np.asarray(m.rao)
    k = om**2 / 9.80665
    assert np.allclose(np.abs(r[:, 0, 1]), 1.0, rtol=2e-3)
    assert np.allclose(np.abs(r[:, 0, 3]), k, rtol=5e-3)
    # beam seas: no pitch on a fore-aft symmetric hull; head seas: no sway, roll or yaw
    assert np.max(np.abs(r[:, 1, 3])) < 1e-10 * np.max(k)
    assert np.max(np.abs(r[:, 0, [0, 2, 4]])) < 1e-10
    # long beam waves: the box heaves with the wave and rolls with its slope
    assert np.allclose(np.abs(r[:, 1, 1]), 1.0, rtol=2e-3)
    assert np.allclose(np.abs(r[:, 1, 2]), k, rtol=0.05)


def test_lewis_sections_have_their_particulars():
    """A Lewis form has the beam, draft and area coefficient it was asked for; σ = π/4 at
    B/2T = 1 is the semicircle; an impossible σ is refused by name."""
    y, z = S.lewis_section(2.0, 1.0, np.pi / 4, n_points=9)
    assert np.allclose(np.hypot(np.asarray(y), np.asarray(z)), 1.0, atol=1e-12)
    for h0, sigma in [(2.0, 0.9), (1.0, 0.95), (0.5, 0.6), (3.0, 0.7)]:
        y, z = (np.asarray(v) for v in S.lewis_section(2 * h0, 1.0, sigma, n_points=201))
        assert y[0] == pytest.approx(h0) and z[-1] == pytest.approx(-1.0) and y[-1] == 0.0
        area = abs(np.sum(y[:-1] * z[1:] - y[1:] * z[:-1]))  # both halves by the shoelace
        assert area / (2 * h0) == pytest.approx(sigma, rel=2e-4)
    with pytest.raises(ValueError, match="sigma"):
        S.lewis_section(2.0, 1.0, 1.2)
    hull = S.lewis_hull([-1.0, 0.0, 1.0], 1.0, [1.0, 2.0, 1.0], 1.0, [0.8, 0.9, 0.8], n_points=7)
    assert hull.y.shape == (3, 7) and float(hull.y[1, 0]) == pytest.approx(1.0)


@pytest.mark.slow
def test_lewis_semicircle_coefficients_are_the_circle_s():
    """The Lewis semicircle solved by the close-fit method gives the circle's coefficients
    (the same contour, its points spaced alike in angle)."""
    om = np.array([0.8, 1.5])
    t = np.linspace(0.5 * np.pi, 0.0, 17)
    circle = S.section_coefficients(np.sin(t), -np.cos(t), om)
    y, z = S.lewis_section(2.0, 1.0, np.pi / 4, n_points=17)
    lewis = S.section_coefficients(y, z, om)
    assert np.allclose(lewis.added_mass, circle.added_mass, rtol=0.02, atol=1.0)


def test_mesh_hull_cuts_the_panel_meshes_into_the_strip_hulls():
    """The mesh → offsets path: the box mesh gives the box's sections (B/2 at every height,
    draft T, a transom), the Barge 2 mesh the raked hull of `presets.barge2_hull` (same
    stations, depths and volume, no transom)."""
    from jaxtow import presets
    from jaxtow.bem import barge2_mesh, box_barge_mesh, mesh_hull

    box = mesh_hull(box_barge_mesh(76.2, 24.4, 5.0, panel_size=2.0))
    assert box.transom and box.y.shape == (21, 12)
    _assert_box_sections(box, 12.2, 5.0)
    assert float(S.hydrostatics(box).volume) == pytest.approx(76.2 * 24.4 * 5.0, rel=1e-9)
    raked, ref = mesh_hull(barge2_mesh(5.0)), presets.barge2_hull(5.0)
    assert not raked.transom
    assert np.allclose(np.asarray(raked.x), np.asarray(ref.x))
    assert np.allclose(np.asarray(raked.z)[:, -1], np.asarray(ref.z)[:, -1], rtol=1e-6)
    assert float(S.hydrostatics(raked).volume) == pytest.approx(
        float(S.hydrostatics(ref).volume), rel=1e-9
    )
    with pytest.raises(ValueError, match="n_stations"):
        mesh_hull(box_barge_mesh(76.2, 24.4, 5.0), n_stations=1)


def test_mesh_and_offsets_file_give_the_same_sections(tmp_path):
    """The two roads from a hull description to the strips meet: the box read from its panel
    mesh and from an offsets table has the same offsets (`contour` on both)."""
    from jaxtow.bem import box_barge_mesh, mesh_hull

    mesh = mesh_hull(box_barge_mesh(76.2, 24.4, 5.0), n_stations=5)
    path = tmp_path / "box.csv"
    rows = ["x,0,-2.5,-5"] + [f"{x},12.2,12.2,12.2" for x in np.asarray(mesh.x)]
    path.write_text("\n".join(rows) + "\n")
    table = jt.io.read_offsets(path)
    assert np.allclose(np.asarray(mesh.y), np.asarray(table.y), atol=1e-9)
    assert np.allclose(np.asarray(mesh.z), np.asarray(table.z), atol=1e-9)

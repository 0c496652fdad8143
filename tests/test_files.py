"""Drift files as users have them: WAMIT .8/.9/.12d and Capytaine outputs from public
repositories (read from the shared external-data folder; skipped, with the reason, where it
is absent), and the synthetic cases of each finding of the readers."""

import gzip
import math
import re
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np
import pytest

import jaxtow as jt
from jaxtow.drift import FullQTF

EXTERNAL = Path(__file__).resolve().parents[2] / "shared" / "external"
needs_external = pytest.mark.skipif(
    not EXTERNAL.is_dir(),
    reason="the external WAMIT/Capytaine files are not in this checkout (../shared/external)",
)
WAMIT_MEAN = [
    "mss/tanker.9",
    "mss/fpso.9",
    "mss/semisub.9",
    "mss/cylinder.9",
    "mcmodels/csad.8",
    "mcmodels/enterprise.8",
    "mcmodels/ma1.8",
    "mcmodels/voyager.8",
]
ASYMMETRIC = {"mcmodels/ma1.8", "mcmodels/voyager.8"}
SYMMETRIC = [f for f in WAMIT_MEAN if f not in ASYMMETRIC]


def _listing_drift(path: Path):
    """The mean-drift tables printed in a WAMIT .out listing: {(period, heading, mode): value}
    (value = Mod·cos(Pha), the non-dimensional drift), the pressure-integration block for a
    .9 file and the momentum block for a .8 file (with I = -|I| for a .9's second set)."""
    want = "Pressure Integration" if path.suffix == ".9" else "Momentum Conservation"
    text = gzip.decompress(path.with_suffix(".out.gz").read_bytes()).decode(errors="replace")
    out, per, block, head = {}, None, False, None
    for line in text.splitlines():
        m = re.match(r"\s*Wave period \(sec\) =\s*([0-9.Ee+-]+)", line)
        if m:
            per, block = float(m.group(1)), False
            continue
        if "DRIFT FORCES" in line:
            block = want in line
            continue
        if not block or per is None:
            continue
        m = re.match(r"\s*Wave Heading \(deg\) :\s*([-0-9.]+)\s+([-0-9.]+)", line)
        if m:
            head = float(m.group(1)) if float(m.group(1)) == float(m.group(2)) else None
            continue
        parts = line.split()
        if head is not None and len(parts) in (3, 5) and parts[0].isdigit():
            i = int(parts[0])
            out[(per, head, i)] = float(parts[1]) * math.cos(math.radians(float(parts[2])))
            if len(parts) == 5:
                out[(per, head, -i)] = float(parts[3]) * math.cos(math.radians(float(parts[4])))
        elif parts and not parts[0].isdigit() and parts[0] not in ("I",):
            if "RAO" in line or "EXCITING" in line.upper():
                block = False
    return out


def _value(table, per, head_w, comp):
    """The value of a (omega, beta_deg, values) numpy table at a listed period and heading."""
    w, b, v = table
    i = int(np.argmin(np.abs(w - 2 * math.pi / per)))
    j = int(np.argmin(np.abs(b - (head_w - 180.0))))
    assert abs(w[i] * per / (2 * math.pi) - 1) < 1e-6 and abs(b[j] - (head_w - 180.0)) < 1e-6
    return float(v[comp, i, j])


# --------------------------------------------------------------------------- the real files


@needs_external
@pytest.mark.parametrize("name", WAMIT_MEAN)
def test_every_wamit_file_reads_and_equals_its_listing(name):
    """Every real mean-drift file reads (the two asymmetric hulls as half tables), ULEN, ρ, g
    come from the listing next to it, and every value equals the .out listing's table to its
    six printed digits."""
    path = EXTERNAL / name
    sym = "none" if name in ASYMMETRIC else "auto"
    q, info = jt.io.read_drift_file(path, symmetry=sym, reference_point="origin")
    L, rho, g = info["ulen"][0], info["rho"][0], info["g"][0]
    assert info["g"][1].startswith("from") and info["ulen"][1].startswith("from")
    listed = _listing_drift(path)
    table = (np.asarray(q.omega), np.degrees(np.asarray(q.beta)), np.asarray(q.values))
    checked = 0
    big = max(abs(x) for x in listed.values())
    for (per, head, mode), v in listed.items():
        if mode not in (1, 2, 6):
            continue
        k = 1 if mode <= 3 else 2
        got = _value(table, per, head, {1: 0, 2: 1, 6: 2}[mode]) / (rho * g * L**k)
        # the listing prints 6 significant digits; values printed as zero are round-off
        assert abs(got - v) <= 6e-6 * abs(v) + 1e-5 * big, (per, head, mode)
        checked += 1
    assert checked >= 3 * 19 * 20


@needs_external
@pytest.mark.parametrize("name", SYMMETRIC)
def test_half_tables_are_completed_by_symmetry(name):
    """Finding 1: WAMIT's 0-180 deg is jaxtow's -180..0 deg; beta > 0 now gives the mirrored
    values (it returned the beta = 0 values), and the completed table satisfies the symmetry
    relations."""
    q, info = jt.io.read_drift_file(EXTERNAL / name)
    assert q.periodic and "completed by port-starboard symmetry" in info["symmetry"]
    v = np.asarray(q.values)
    np.testing.assert_allclose(v[0], v[0][:, ::-1], atol=1e-12 * np.max(np.abs(v[0])))
    np.testing.assert_allclose(v[1:], -v[1:, :, ::-1], atol=1e-12 * np.max(np.abs(v)))
    half = jt.io.read_wamit_drift(EXTERNAL / name, symmetry="none")  # beta <= 0 as in the file
    np.testing.assert_allclose(
        v[..., : half.beta.shape[0]][:, :, 1:-1], np.asarray(half.values)[:, :, 1:-1]
    )
    if name == "mss/tanker.9":  # the interpolant between headings, on one file
        w = np.asarray(q.omega)[len(q.omega) // 2]
        at = jax.jit(jax.vmap(q, in_axes=(None, 0)))
        bs = jnp.array([0.2, 0.7, 1.9, 3.0])
        scale = np.max(np.abs(v), axis=(1, 2))
        for fp, fm in zip(np.asarray(at(w, bs)), np.asarray(at(w, -bs))):
            for c, sign in ((0, 1.0), (1, -1.0), (2, -1.0)):
                assert fp[c] == pytest.approx(sign * fm[c], abs=1e-12 * scale[c])
            assert abs(fp[1]) > 1e-5 * scale[1]  # not the head-sea zero (1e-7) of the old clamp


@needs_external
def test_readme_example_damping_at_positive_heading():
    """Finding 1 as the README's example meets it: on csad.8 at omega = 2 pi rad/s, B_yu at
    beta = 0.2 was -7.7e-4 (the beta = 0 column) against 2196 at beta = -0.2; now it is the
    exact mirror."""
    q = jt.io.read_wamit_drift(EXTERNAL / "mcmodels/csad.8")
    w = 2 * math.pi / 1.0
    B = jax.jit(jax.vmap(lambda b: jt.drift.wave_drift_damping(q, w, b)))(jnp.array([0.2, -0.2]))
    Bp, Bm = np.asarray(B)
    assert abs(Bp[1, 0]) > 1e3
    np.testing.assert_allclose(Bp[1, 0], -Bm[1, 0], rtol=1e-9)
    np.testing.assert_allclose(Bp[0, 0], Bm[0, 0], rtol=1e-9)


@needs_external
@pytest.mark.parametrize("name", sorted(ASYMMETRIC))
def test_asymmetric_half_tables_are_refused_with_a_message(name):
    """Finding 2's other side: the genuinely asymmetric hulls are not completed."""
    with pytest.raises(ValueError, match="not port-starboard symmetric.*symmetry='none'"):
        jt.io.read_wamit_drift(EXTERNAL / name)
    q = jt.io.read_wamit_drift(EXTERNAL / name, symmetry="none")
    assert not q.periodic and not bool(q.in_table(0.3)) and bool(q.in_table(-0.3))


@needs_external
@pytest.mark.parametrize("name", SYMMETRIC)
def test_symmetric_accepts_real_round_off(name):
    """Finding 2: `QTF.symmetric` refused every real symmetric table (head-sea |Fy|, |Nz| of
    1e-8 to 1e-6 of the scale against a 1e-9 test); the documented tolerance accepts them."""
    q = jt.io.read_wamit_drift(EXTERNAL / name, symmetry="none")
    half = np.asarray(q.beta) <= 1e-12
    b = -np.asarray(q.beta)[half][::-1]
    v = np.asarray(q.values)[:, :, half][:, :, ::-1] * np.array([1, -1, -1])[:, None, None]
    res = jt.drift.symmetry_residual(b, *v)
    assert 1e-10 < res < jt.drift.SYMMETRY_TOL
    full = jt.drift.QTF.symmetric(omega=q.omega, beta=b, fx=v[0], fy=v[1], nz=v[2])
    assert full.periodic
    with pytest.raises(ValueError, match="not a port-starboard symmetric hull"):
        jt.drift.QTF.symmetric(omega=q.omega, beta=b, fx=v[0], fy=v[1], nz=v[2], tol=res / 2)


@needs_external
def test_capytaine3_drift_output_reads_and_equals_its_own_wamit_export():
    """Finding 3: Capytaine 3's far_field_mean_drift_force layout (omega, wave_direction_k,
    wave_direction_l), with the re/im axis it is stored with, reads; it equals Capytaine's
    own WAMIT .8 export of the same result (written with ULEN = 1 and 10 m)."""
    d = EXTERNAL / "capytaine3_generated"
    q = jt.io.read_capytaine_drift(d / "sphere_capytaine3_drift.nc", symmetry="none")
    assert np.degrees(np.asarray(q.beta)).tolist() == pytest.approx([-180.0, -90.0, 0.0])
    for f, L in (("sphere_capytaine3.8", 1.0), ("sphere_capytaine3_L10.8", 10.0)):
        w8 = jt.io.read_wamit_drift(
            d / f, ulen=L, rho=1025.0, g=9.81, symmetry="none", reference_point="origin"
        )
        np.testing.assert_allclose(np.asarray(w8.omega), np.asarray(q.omega), rtol=1e-6)
        np.testing.assert_allclose(
            np.asarray(w8.values), np.asarray(q.values), rtol=2e-6, atol=1e-6 * 3.1e4
        )
    # the coarse sphere mesh is not symmetric to the tolerance: refused by default, clearly
    with pytest.raises(ValueError, match="not port-starboard symmetric"):
        jt.io.read_capytaine_drift(d / "sphere_capytaine3_drift.nc")


@needs_external
def test_capytaine2_dataset_without_drift_is_refused_clearly():
    with pytest.raises(ValueError, match="no Capytaine drift variables"):
        jt.io.read_capytaine_drift(EXTERNAL / "wecsim_capytaine/sphere_hydrodynamics.nc")


@needs_external
@pytest.mark.parametrize("name", SYMMETRIC)
def test_round_trip_of_a_real_table_is_exact(name, tmp_path):
    """Finding 5: write then read returned another grid (-180 became +180.0000..., head
    seas were written as -180); now read -> write -> read is exact."""
    q, info = jt.io.read_drift_file(EXTERNAL / name)
    L, rho, g = info["ulen"][0], info["rho"][0], info["g"][0]
    jt.io.write_wamit_drift(q, tmp_path / "again.8", ulen=L, rho=rho, g=g)
    heads = {float(line.split()[1]) for line in (tmp_path / "again.8").read_text().splitlines()}
    assert 180.0 in heads and min(heads) == 0.0 and max(heads) < 360.0  # head seas at 180
    back = jt.io.read_wamit_drift(tmp_path / "again.8", ulen=L, rho=rho, g=g)
    np.testing.assert_array_equal(np.asarray(back.beta), np.asarray(q.beta))
    np.testing.assert_array_equal(np.asarray(back.omega), np.asarray(q.omega))
    np.testing.assert_allclose(np.asarray(back.values), np.asarray(q.values), rtol=1e-15, atol=0)
    assert back.periodic


@needs_external
def test_12d_is_named_as_such_and_reads_as_a_full_qtf():
    """Finding 6: a .12d file gave an omega-grid error; now the mean-drift reader says what
    it is, and `read_wamit_qtf` reads it, Hermitian, its diagonal real."""
    f = EXTERNAL / "iea15/IEA-15-240-RWT-UMaineSemi.12d"
    with pytest.raises(ValueError, match=r"line 1: 9 columns.*difference-frequency QTF"):
        jt.io.read_wamit_drift(f)
    Q, info = jt.io.read_wamit_qtf(f, ulen=1.0, rho=1025.0, g=9.80665, reference_point="origin")
    assert Q.values.shape == (3, 46, 46, 1)
    v = np.asarray(Q.values)
    # Hermitian to the file's round-off (its diagonal's imaginary parts are ~1e-8 of the scale)
    np.testing.assert_allclose(
        v, np.conj(np.swapaxes(v, 1, 2)), rtol=0, atol=1e-6 * np.max(np.abs(v))
    )
    # the first record: PER 25.133 s, the diagonal surge 4.01132e-1 (x rho g ULEN)
    i = int(np.argmin(np.abs(np.asarray(Q.omega) - 2 * math.pi / 25.133)))
    assert Q.diagonal()[0, i, 0] == pytest.approx(4.01132e-1 * 1025.0 * 9.80665, rel=1e-5)
    assert np.degrees(float(Q.beta[0])) == pytest.approx(-180.0)  # WAMIT 0 deg: following seas


@needs_external
def test_reference_point_moves_the_yaw_moment_to_the_cog():
    """Finding 7: the tanker's yaw moment about its CoG (x = 3.93 m from the WAMIT origin,
    read from the listing) differs from the one about the origin by x_G·Fy."""
    f = EXTERNAL / "mss/tanker.9"
    q, info = jt.io.read_drift_file(f)
    q0 = jt.io.read_wamit_drift(f, reference_point="origin")
    assert info["reference_point"][0] == (3.93, 0.0) and "CoG" in info["reference_point"][1]
    v, v0 = np.asarray(q.values), np.asarray(q0.values)
    np.testing.assert_allclose(v[2], v0[2] - 3.93 * v0[1], rtol=1e-12, atol=1e-9)
    np.testing.assert_array_equal(v[:2], v0[:2])
    rel = np.max(np.abs(v[2] - v0[2])) / np.max(np.abs(v0[2]))
    assert 0.01 < rel < 0.2  # a few per cent on the tanker


@needs_external
def test_pressure_moment_sets_are_a_named_choice():
    """Finding 7: a .9 file's I = 6 and I = -6 moment sets were chosen silently."""
    f = EXTERNAL / "mss/tanker.9"
    q6, i6 = jt.io.read_drift_file(f, moment_set=6, reference_point="origin")
    qm, im = jt.io.read_drift_file(f, moment_set=-6, reference_point="origin")
    assert i6["moment_set"] == 6 and im["moment_set"] == -6
    np.testing.assert_array_equal(np.asarray(q6.values[:2]), np.asarray(qm.values[:2]))
    with pytest.raises(ValueError, match="no records of mode I = -6"):
        jt.io.read_wamit_drift(EXTERNAL / "mcmodels/csad.8", moment_set=-6)
    with pytest.raises(ValueError, match="parameter 'moment_set'"):
        jt.io.read_wamit_drift(f, moment_set=5)


# --------------------------------------------------------------------------- synthetic cases


def _mean_lines(rows):
    return "\n".join(" ".join(str(x) for x in r) for r in rows) + "\n"


def _records(pers=(12.0, 6.0), heads=(0.0, 90.0, 180.0)):
    rows = []
    for p in pers:
        for h in heads:
            for mode in (1, 2, 6):
                v = {
                    1: -0.4,
                    2: 0.05 * math.sin(math.radians(h)),
                    6: -0.02 * math.sin(math.radians(2 * h)),
                }[mode]
                rows.append([p, h, h, mode, abs(v), 0.0 if v >= 0 else 180.0, v, 0.0])
    return rows


def test_fortran_exponents_and_header_read(tmp_path):
    """Finding 6: Fortran D exponents gave 'no mean-drift records'."""
    rows = _records()
    lines = []
    for r in rows:
        lines.append(" ".join(f"{x:.6E}".replace("E", "D") for x in r))
    (tmp_path / "d.8").write_text("header line\n" + "\n".join(lines) + "\n")
    q = jt.io.read_wamit_drift(tmp_path / "d.8", ulen=1.0, rho=1000.0, g=10.0)
    assert float(q.values[0, 0, 0]) == pytest.approx(-0.4 * 1000.0 * 10.0)


def test_unreadable_lines_cut_records_and_duplicates_name_the_line(tmp_path):
    """Finding 6 and the file faults: an unparsable line was skipped silently, a record cut
    mid-line read as a table over half the frequencies, duplicates overwrote."""
    rows = _records()
    body = _mean_lines(rows).splitlines()
    f = tmp_path / "x.8"
    f.write_text("\n".join(body[:4] + ["this is not a record"] + body[4:]) + "\n")
    with pytest.raises(ValueError, match=r"x\.8, line 5: not a WAMIT numeric record"):
        jt.io.read_wamit_drift(f, ulen=1.0)
    f.write_text("\n".join(body[:-1] + [" ".join(body[-1].split()[:5])]) + "\n")
    with pytest.raises(ValueError, match=r"line 18: record cut short .*5 of 8"):
        jt.io.read_wamit_drift(f, ulen=1.0)
    f.write_text("\n".join(body[:-4]) + "\n")  # cut at a record boundary: incomplete table
    with pytest.raises(ValueError, match="incomplete table.*cut short"):
        jt.io.read_wamit_drift(f, ulen=1.0)
    f.write_text("\n".join(body + [body[3]]) + "\n")
    with pytest.raises(ValueError, match=r"line 19: duplicate record .* of line 4"):
        jt.io.read_wamit_drift(f, ulen=1.0)
    # a table listing both 0 and 360 deg (the same heading, the same values) is not a duplicate
    q = jt.io.read_wamit_drift(
        _write(tmp_path, _records(heads=(0.0, 90.0, 180.0, 270.0)), "a.8"), ulen=1.0
    )
    both = _records(heads=(0.0, 90.0, 180.0, 270.0)) + _records(heads=(360.0,))
    q2 = jt.io.read_wamit_drift(_write(tmp_path, both, "b.8"), ulen=1.0)
    np.testing.assert_array_equal(np.asarray(q2.values), np.asarray(q.values))


@pytest.mark.parametrize("bad", [0.0, -1.0, float("nan")])
@pytest.mark.parametrize("name", ["ulen", "rho", "g"])
def test_scales_must_be_positive(tmp_path, name, bad):
    """ulen = 0 gave zeros and ulen = -1 flipped signs."""
    f = tmp_path / "x.8"
    f.write_text(_mean_lines(_records()))
    with pytest.raises(ValueError, match=f"parameter '{name}'"):
        jt.io.read_wamit_drift(f, **{name: bad})
    q = jt.io.read_wamit_drift(f, ulen=1.0)
    with pytest.raises(ValueError, match=f"parameter '{name}'"):
        jt.io.write_wamit_drift(q, tmp_path / "y.8", **{name: bad})


def test_assumed_scales_are_said(tmp_path):
    f = tmp_path / "x.8"
    f.write_text(_mean_lines(_records()))
    _, info = jt.io.read_drift_file(f)
    assert info["ulen"] == (1.0, "ASSUMED (not given, not in a WAMIT listing next to the file)")
    assert "no CoG next to the file" in info["reference_point"][1]


def test_capytaine_complex_axis_with_two_headings(tmp_path):
    """Finding 4: a Capytaine NetCDF opened as stored, with its complex (re/im) dimension and
    exactly two headings, took the re/im axis for a second heading."""
    import xarray as xr

    w = np.array([0.5, 1.0, 1.5])
    wd = np.array([math.pi - 0.4, math.pi + 0.4])  # two headings, jaxtow -0.4 and 0.4
    re_ = np.stack([-100.0 * w, -90.0 * w], axis=1)
    im_ = np.full_like(re_, 7.0)  # the imaginary parts must not be read
    da = xr.DataArray(
        np.stack([re_, im_]),
        dims=("complex", "omega", "wave_direction"),
        coords={"complex": ["re", "im"], "omega": w, "wave_direction": wd},
    )
    zero = da * 0.0
    q = jt.io.qtf_from_capytaine(da, zero, zero, symmetry="none")
    np.testing.assert_allclose(np.asarray(q.beta), [-0.4, 0.4], atol=1e-12)
    np.testing.assert_allclose(np.asarray(q.values[0]), re_)
    ds = xr.Dataset({"drift_force_surge": da, "drift_force_sway": zero, "drift_force_yaw": zero})
    ds.to_netcdf(tmp_path / "c.nc")
    q2 = jt.io.read_capytaine_drift(tmp_path / "c.nc", symmetry="none")
    np.testing.assert_allclose(np.asarray(q2.values), np.asarray(q.values))
    bad = da.assign_coords(complex=["a", "b"])
    with pytest.raises(ValueError, match="labels \\['re', 'im'\\]"):
        jt.io.qtf_from_capytaine(bad, zero, zero)


def test_csv_rows_in_any_order(tmp_path):
    """A CSV QTF with rows in another order was scrambled (reshaped by row order)."""
    q = jt.io.read_wamit_drift(_write(tmp_path, _records()), ulen=1.0)
    jt.io.save_qtf(q, tmp_path / "q.csv")
    lines = (tmp_path / "q.csv").read_text().splitlines()
    head = [x for x in lines if x.startswith("#")]
    body = [x for x in lines if not x.startswith("#")]
    rng = np.random.default_rng(0)
    (tmp_path / "s.csv").write_text("\n".join(head + list(rng.permutation(body))) + "\n")
    back = jt.io.load_qtf(tmp_path / "s.csv")
    np.testing.assert_array_equal(np.asarray(back.values), np.asarray(q.values))
    (tmp_path / "d.csv").write_text("\n".join(head + body + body[:1]) + "\n")
    with pytest.raises(ValueError, match="exactly once"):
        jt.io.load_qtf(tmp_path / "d.csv")


def _write(tmp_path, rows, name="x.8"):
    f = tmp_path / name
    f.write_text(_mean_lines(rows))
    return f


def test_round_trip_keeps_the_full_circle(tmp_path):
    """Write -> read of a jaxtow full-circle table returns its grid (the +-180 column was
    dropped or moved)."""
    q = jt.presets.database("barge2", "far_field")
    jt.io.write_wamit_drift(q, tmp_path / "b.8", ulen=1.0)
    back = jt.io.read_wamit_drift(tmp_path / "b.8", ulen=1.0)
    assert back.periodic and back.beta.shape == q.beta.shape
    np.testing.assert_allclose(np.asarray(back.beta), np.asarray(q.beta), rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.asarray(back.values), np.asarray(q.values), rtol=1e-14, atol=1e-9)


@pytest.mark.parametrize("side", ["0..180", "-180..0", "0..90", "90..180"])
def test_round_trip_keeps_a_half_table_grid(side, tmp_path):
    """Write -> read of a table on one side returns its grid: the following-sea column at
    +180 deg (written at WAMIT's 0 deg) reads back as +180, not as a -180 column beside it."""
    q = jt.presets.database("barge2", "far_field")
    b, w, v = np.asarray(q.beta), np.asarray(q.omega), np.asarray(q.values)
    lo, hi = (np.radians(float(x)) for x in side.split(".."))
    keep = (b >= lo - 1e-9) & (b <= hi + 1e-9)
    half = jt.drift.QTF(omega=w, beta=b[keep], fx=v[0][:, keep], fy=v[1][:, keep], nz=v[2][:, keep])
    jt.io.write_wamit_drift(half, tmp_path / "h.8")
    back = jt.io.read_wamit_drift(tmp_path / "h.8", symmetry="none")
    assert back.beta.shape == half.beta.shape
    np.testing.assert_allclose(np.asarray(back.beta), np.asarray(half.beta), rtol=0, atol=1e-12)
    np.testing.assert_allclose(
        np.asarray(back.values), np.asarray(half.values), rtol=1e-13, atol=1e-9
    )


# --------------------------------------------------------------------------- the full QTF


def _full_from_mean(q: jt.drift.QTF, extra=0.0):
    """A FullQTF whose diagonal is q's mean drift and whose off-diagonal terms are Newman's
    (T_i + T_j)/2, plus extra·i(ω_i − ω_j) (Hermitian)."""
    w = np.asarray(q.omega)
    v = np.asarray(q.values)  # (3, nw, nb)
    T = 0.5 * (v[:, :, None, :] + v[:, None, :, :]) + 0j
    T = T + 1j * extra * (w[:, None] - w[None, :])[None, :, :, None]
    return FullQTF(omega=w, beta=q.beta, values=T)


def test_12d_diagonal_is_the_mean_drift_written_both_ways(tmp_path):
    """A synthetic case written as .8 (mean drift) and .12d (full QTF, diagonal = mean
    drift): the full QTF's diagonal read back equals the mean drift read back."""
    q = jt.io.read_wamit_drift(
        _write(tmp_path, _records(heads=(0.0, 90.0, 180.0, 270.0))), ulen=2.0
    )
    Q = _full_from_mean(q, extra=300.0)
    jt.io.write_wamit_drift(q, tmp_path / "m.8", ulen=2.0)
    jt.io.write_wamit_qtf(Q, tmp_path / "m.12d", ulen=2.0)
    m = jt.io.read_wamit_drift(tmp_path / "m.8", ulen=2.0)
    F, info = jt.io.read_wamit_qtf(tmp_path / "m.12d", ulen=2.0)
    np.testing.assert_allclose(F.diagonal(), np.asarray(m.values)[:, :, :-1], rtol=1e-13, atol=1e-9)
    np.testing.assert_allclose(
        np.asarray(F.values), np.asarray(Q.values)[..., :-1], rtol=1e-13, atol=1e-9
    )
    with pytest.raises(ValueError, match="Hermitian"):
        FullQTF(omega=Q.omega, beta=Q.beta, values=np.asarray(Q.values) + 1j)


def test_slow_drift_with_the_full_qtf():
    """The full QTF drives the slowly varying drift: with Newman's off-diagonal terms it is
    Newman's force exactly; with others the difference is the double sum of the difference
    terms, computed here directly."""
    from jaxtow.forces import SlowDriftForce

    q = jt.presets.database("barge2", "near_field")
    sea = jt.waves.Jonswap(hs=2.4, tp=7.0)
    sc = jt.presets.barge2_scales()
    kw = dict(seed=1, n=64, form="linear", yaw_rate=False)  # the cheapest to compile
    newman = SlowDriftForce.seeded(q, sea, sc, **kw)
    same = SlowDriftForce.seeded(q, sea, sc, full_qtf=_full_from_mean(q), **kw)
    other = SlowDriftForce.seeded(q, sea, sc, full_qtf=_full_from_mean(q, 2e4), **kw)
    w = np.asarray(newman.omega)
    a2 = np.asarray(newman.amplitudes()) ** 2
    inside = w <= float(q.omega[-1])
    assert float(other.full_qtf_energy) == pytest.approx(a2[inside].sum() / a2.sum(), rel=1e-9)
    import equinox as eqx

    force = eqx.filter_jit(lambda f, t, y: f.dimensional(jnp.asarray(t), y))
    for psi in (0.0, 0.25):
        y = jnp.array([1.0, 0.05, 0.01, 2.5, 0.1, psi])
        for t in map(jnp.asarray, (0.0, 3.7, 41.0)):
            f0 = np.asarray(force(newman, t, y))
            np.testing.assert_allclose(
                np.asarray(force(same, t, y)), f0, rtol=1e-9, atol=1e-6 * np.max(np.abs(f0))
            )
            # the difference term by hand: Re sum z_i z_j* 2e4 i (w_i - w_j) (surge, sway, yaw alike)
            U, L = sc.u_tug, sc.length
            w = np.asarray(newman.omega)
            z = np.asarray(newman.amplitudes()) * np.exp(
                1j * ((w + w**2 * U / jt.G) * t * L / U + np.asarray(newman.phase))
            )
            both = inside[:, None] & inside[None, :]  # Newman outside the full QTF's range
            d = np.real(
                np.sum(
                    np.where(
                        both,
                        z[:, None] * np.conj(z)[None, :] * 2e4j * (w[:, None] - w[None, :]),
                        0.0,
                    )
                )
            )
            np.testing.assert_allclose(
                np.asarray(force(other, t, y)) - f0, d, rtol=1e-7, atol=1e-6 * abs(d)
            )


# --------------------------------------------------------------------------- every consumer


def test_drift_source_takes_a_file_with_its_options(tmp_path):
    """Study builders, `jaxtow report waves --qtf` and `jaxtow resistance` name a file with its
    reader options (ULEN, rho, g, reference point, symmetry) through `drift_source`."""
    from jaxtow.presets import drift_source

    f = _write(tmp_path, _records(heads=(0.0, 45.0, 90.0, 135.0, 180.0)))
    src = drift_source(
        {"file": str(f), "ulen": 2.0, "rho": 1000.0, "g": 10.0, "reference_point": [1.5, 0.0]}
    )
    q, desc = src.qtf(), src.describe()
    assert (
        "ulen = 2 (given)" in desc and "rho = 1000 (given)" in desc and "(1.5, 0) m given" in desc
    )
    assert "completed by port-starboard symmetry" in desc and q.periodic
    q0, desc0 = drift_source(str(f)).qtf(), drift_source(str(f)).describe()
    assert "ASSUMED" in desc0
    np.testing.assert_allclose(
        np.asarray(q.values[0]),
        np.asarray(q0.values[0]) * 2.0 * 1000.0 * 10.0 / (jt.RHO_SEA * jt.G),
    )
    with pytest.raises(ValueError, match=r"unknown options \['ulem'\]"):
        drift_source({"file": str(f), "ulem": 2.0})
    with pytest.raises(ValueError, match="needs 'file'"):
        drift_source({"ulen": 2.0})
    m = jt.presets.barge2_wave_model("2a", qtf={"file": str(f), "ulen": 2.0})
    np.testing.assert_allclose(
        np.asarray(m.external.qtf.values),
        np.asarray(drift_source({"file": str(f), "ulen": 2.0}).qtf().values),
    )


def test_report_and_resistance_accept_file_options(tmp_path):
    from jaxtow.cli import build_parser
    from jaxtow.cli.report import plan
    from jaxtow.cli.resistance import build, read_config

    f = _write(tmp_path, _records(heads=(0.0, 45.0, 90.0, 135.0, 180.0)))
    args = build_parser().parse_args(
        [
            "report",
            "waves",
            "--qtf",
            str(f),
            "--qtf-option",
            "ulen=2",
            "--qtf-option",
            "reference_point=1.5,0",
        ]
    )
    primary, sources, _ = plan(args)
    assert primary == {"file": str(f), "ulen": 2.0, "reference_point": [1.5, 0.0]}
    assert sources[1:] == ["near_field", "far_field", "standin"]
    bad = build_parser().parse_args(["report", "waves", "--qtf", str(f), "--qtf-option", "ulen"])
    with pytest.raises(SystemExit, match="KEY=VALUE"):
        plan(bad)
    cfg = read_config("barge2")
    cfg = dict(cfg, tow=dict(cfg["tow"], wave_drift={"file": str(f), "ulen": 2.0, "rho": 1000.0}))
    tow, *_ = build(cfg)
    note = dict(tow.assumed)["wave_drift"]
    assert "ulen = 2 (given)" in note and "rho = 1000 (given)" in note
